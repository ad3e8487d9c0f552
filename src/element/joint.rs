//! KJOINT2 joint (/SPRING with /PROP/TYPE45): a penalty connection of two
//! nodes of two rigid bodies, six relative degrees of freedom in the
//! joint's frame, those the joint type blocks held by a stiff damped
//! spring, the free ones with the card's stiffness and damping (reference
//! guide /PROP/TYPE45; research note `docs/notes/kjoint2_research.md`).
//!
//! * Frame E (rows e₁, e₂, e₃): global at t = 0, turned each step by the
//!   mean rotation ½(ω₁ + ω₂)Δt of its two nodes (§3).
//! * Relative displacement D = E(x₂ − x₁) − D⁰ (D⁰ its value at t = 0),
//!   relative rotation R += E(ω₂ − ω₁)Δt; rates by backward difference
//!   over the last step (0 on the first).
//! * Law per local component i (§5): Fᵢ = Kᵢ Dᵢ, or Kᵢ f(Dᵢ) with a
//!   function; blocked components add critical damping Cr·√(Kᵢ M̄)·Ḋᵢ with
//!   the harmonic mass M̄ = m₁m₂/(m₁ + m₂) (inertia Ī for rotations), free
//!   ones Cᵢ Ḋᵢ or Cᵢ g(Ḋᵢ).
//! * Energy Σᵢ ½(Dᵢⁿ⁺¹ − Dᵢⁿ)(Fᵢⁿ⁺¹ + Fᵢⁿ), elastic and dissipated.
//! * Node 1 takes Eᵀ F and Eᵀ(M + ½ D×F), node 2 the opposite force and
//!   −Eᵀ(M − ½ D×F) (external sense; the solver's internal forces are their
//!   negatives), so the pair carries no net moment.

use super::spring::SpringOut;
use crate::kinematics::function::eval;
use crate::model::{Function, JointProperty};
use crate::vec3::{cross, dot, rotate, scale, sub, V3};
use serde::{Deserialize, Serialize};

/// Rule of the automatic blocked stiffness (§4): α in k = m/(α Δt²).
const ALPHA: f64 = 4.1;

/// One local component's law.
#[derive(Clone, Debug, Default)]
pub struct Component {
    /// Stiffness, or the scale on `f` when given.
    pub k: f64,
    pub f: Option<Function>,
    /// Free component: damping (scale on `g` when given).
    pub c: f64,
    pub g: Option<Function>,
    /// Blocked component: critical damping factor.
    pub cr: f64,
}

impl Component {
    /// The force of displacement `d` moving at rate `rate`; `mass` the
    /// reduced mass or inertia of the critical damping.
    fn force(&self, d: f64, rate: f64, mass: f64) -> f64 {
        let elastic = match &self.f {
            Some(f) => self.k * eval(f, d),
            None => self.k * d,
        };
        let user = match &self.g {
            Some(g) => self.c * eval(g, rate),
            None => self.c * rate,
        };
        elastic + user + self.cr * (self.k * mass).sqrt() * rate
    }

    /// The tangent stiffness for the time step (the largest slope of f).
    fn tangent(&self) -> f64 {
        match &self.f {
            Some(f) => self.k * super::spring_law::max_slope(f),
            None => self.k,
        }
    }
}

/// One side of a joint: the rigid body its node belongs to.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Side {
    /// The body's mass and the inertia of its main node (smallest
    /// principal moment about the centre; the spherical one with Ispher 1).
    pub mass: f64,
    pub inertia: f64,
    /// The body's mean principal moment (trace/3): its share of the
    /// joint's reduced inertia.
    pub mean_inertia: f64,
    /// Squared distance of the joint's node from the body's centre.
    pub arm2: f64,
}

/// A joint ready to run: its six components (translations, then rotations)
/// and the reduced mass and inertia of its two bodies.
#[derive(Clone, Debug)]
pub struct Joint {
    pub comp: [Component; 6],
    pub mass: f64,
    pub inertia: f64,
    pub sides: [Side; 2],
}

/// Per-joint state kept by the solver.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct JointState {
    /// The joint's frame, one axis per row.
    pub frame: [V3; 3],
    /// E(x₂ − x₁) at t = 0.
    pub origin: V3,
    /// The relative displacements and rotations at the last step.
    pub d: [f64; 6],
    /// The forces and moments at the last step (local components).
    pub f: [f64; 6],
    pub eint: f64,
    /// The last step set the rates (false before the first step).
    pub started: bool,
}

/// The automatic blocked stiffnesses KNN (translations) and KNR
/// (rotations) of a joint with Kn = 0 (§4): from each side's body,
/// k = 2m/(αΔt²) and k_r = I/(αΔt²), with the arm's limit 0.8 k_r/(d² + L²)
/// on the translations; scaled by ScF. `dt` is the first step's bound.
pub fn automatic_stiffness(sides: &[Side; 2], length2: f64, dt: f64, scf: f64) -> (f64, f64) {
    let a = ALPHA * dt * dt;
    let d2 = sides[0].arm2.max(sides[1].arm2) + length2;
    let mut knn = f64::INFINITY;
    let mut knr = f64::INFINITY;
    for s in sides {
        let kr = s.inertia / a;
        knr = knr.min(kr);
        knn = knn.min(2.0 * s.mass / a);
        if d2 > 0.0 && kr > 0.0 {
            knn = knn.min(0.8 * kr / d2);
        }
    }
    (scf * knn, scf * knr)
}

/// m₁m₂/(m₁ + m₂) (0 when either is 0).
fn harmonic(a: f64, b: f64) -> f64 {
    if a > 0.0 && b > 0.0 {
        a * b / (a + b)
    } else {
        0.0
    }
}

impl Joint {
    /// The joint of property `p` between bodies `sides`, its nodes
    /// `length2` apart; `dt_first` bounds the first step (the automatic
    /// stiffness needs it: /DTIX). What it does not compute is refused.
    pub fn new(
        p: &JointProperty,
        sides: [Side; 2],
        length2: f64,
        dt_first: f64,
        find: impl Fn(crate::model::Id) -> Option<Function>,
    ) -> Result<Self, String> {
        let refuse = [
            (p.sens_id != 0, "sens_ID ≠ 0: a joint switched by a sensor"),
            (
                p.skew_ids != [0, 0],
                "Skew_ID1 or Skew_ID2 ≠ 0: a joint frame from skews",
            ),
            (
                (2..=7).contains(&p.joint_type),
                "Type 2 to 7: a joint whose axis comes from skews or a third node",
            ),
            (
                p.free
                    .iter()
                    .any(|(_, d)| d.stop_minus != 0.0 || d.stop_plus != 0.0 || d.icomb != 0),
                "stops S-, S+ (or Icomb) on a free degree of freedom",
            ),
            (
                p.free.iter().any(|(_, d)| d.kf != 0.0 || d.friction != 0.0),
                "friction Kf, FF/FM on a free degree of freedom",
            ),
        ];
        if let Some((_, what)) = refuse.iter().find(|(r, _)| *r) {
            return Err(format!("{what} is not computed yet"));
        }
        let (knn, knr) = if JointProperty::automatic(p.kn) {
            if dt_first <= 0.0 {
                return Err("Kn = 0 (the automatic stiffness) needs the first time step's bound: give /DTIX or Kn".into());
            }
            automatic_stiffness(&sides, length2, dt_first, p.scf)
        } else {
            (p.kn, p.kn * p.scf.max(length2))
        };
        let mut comp: [Component; 6] = Default::default();
        for (i, c) in comp.iter_mut().enumerate() {
            c.k = if i < 3 { knn } else { knr };
            c.cr = p.cr;
        }
        for (i, d) in &p.free {
            let get = |id: crate::model::Id, name: &str| -> Result<Option<Function>, String> {
                if id == 0 {
                    return Ok(None);
                }
                find(id)
                    .map(Some)
                    .ok_or_else(|| format!("{name} = {id}: no such function"))
            };
            comp[*i] = Component {
                k: d.k,
                f: get(d.fct_k, "fct_K")?,
                c: d.c,
                g: get(d.fct_c, "fct_C")?,
                cr: 0.0,
            };
        }
        Ok(Joint {
            comp,
            mass: harmonic(sides[0].mass, sides[1].mass),
            inertia: harmonic(sides[0].mean_inertia, sides[1].mean_inertia),
            sides,
        })
    }

    /// State at t = 0: the global frame.
    pub fn init(x: &[V3; 2]) -> JointState {
        JointState {
            frame: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            origin: sub(x[1], x[0]),
            ..Default::default()
        }
    }

    /// One explicit step from x^{n}, ω^{n−½} and the last step `dt`.
    pub fn step(&self, x: &[V3; 2], w: &[V3; 2], dt: f64, st: &mut JointState) -> SpringOut {
        let mean = scale([0, 1, 2].map(|k| w[0][k] + w[1][k]), 0.5);
        st.frame = st.frame.map(|e| rotate(e, mean, dt));
        let e = st.frame;
        let xl = e.map(|ei| dot(ei, sub(x[1], x[0])));
        let dw = sub(w[1], w[0]);
        let mut d = st.d;
        for i in 0..3 {
            d[i] = xl[i] - st.origin[i];
            d[3 + i] += dot(e[i], dw) * dt;
        }
        let mut f = [0.0; 6];
        let mut d_eint = 0.0;
        for i in 0..6 {
            let rate = if st.started && dt > 0.0 {
                (d[i] - st.d[i]) / dt
            } else {
                0.0
            };
            let m = if i < 3 { self.mass } else { self.inertia };
            f[i] = self.comp[i].force(d[i], rate, m);
            d_eint += 0.5 * (d[i] - st.d[i]) * (f[i] + st.f[i]);
        }
        let global =
            |v: [f64; 3]| [0, 1, 2].map(|k| v[0] * e[0][k] + v[1] * e[1][k] + v[2] * e[2][k]);
        let (ft, mt) = ([f[0], f[1], f[2]], [f[3], f[4], f[5]]);
        let half = scale(cross(xl, ft), 0.5);
        let fg = global(ft);
        let m1 = global([0, 1, 2].map(|k| mt[k] + half[k]));
        let m2 = global([0, 1, 2].map(|k| mt[k] - half[k]));
        let mut out = SpringOut {
            d_eint,
            dt: self.time_step(dot(xl, xl)),
            ..Default::default()
        };
        // Internal forces: the negatives of what the joint applies.
        for k in 0..3 {
            out.f[0][k] = -fg[k];
            out.f[1][k] = fg[k];
            out.f[0][3 + k] = -m1[k];
            out.f[1][3 + k] = m2[k];
        }
        st.d = d;
        st.f = f;
        st.eint += d_eint;
        st.started = true;
        out
    }

    /// The joint's step on its two bodies (§6): the stiffness the joint
    /// puts on each body's main node, K = 2 S and K_r = S_r + S(|D|² + 2d²)
    /// with S = (c + √(c² + k M̄))²/M̄ (c = Cr√(k M̄), k the largest
    /// translational tangent) and S_r likewise, then the smaller of
    /// √(2m/K) and √(2I/K_r) over the two sides (unscaled).
    pub fn time_step(&self, length2: f64) -> f64 {
        let cx = self.comp.iter().map(|c| c.cr).fold(0.0, f64::max);
        let largest = |r: std::ops::Range<usize>| {
            self.comp[r]
                .iter()
                .map(Component::tangent)
                .fold(0.0, f64::max)
        };
        let sti = |k: f64, m: f64| {
            if m <= 0.0 {
                return 0.0;
            }
            let c = cx * (k * m).sqrt();
            (c + (c * c + k * m).sqrt()).powi(2) / m
        };
        let s = sti(largest(0..3), self.mass);
        let sr = sti(largest(3..6), self.inertia);
        let mut dt = f64::INFINITY;
        for side in &self.sides {
            let k = 2.0 * s;
            let kr = sr + s * (length2 + 2.0 * side.arm2);
            if k > 0.0 && side.mass > 0.0 {
                dt = dt.min((2.0 * side.mass / k).sqrt());
            }
            if kr > 0.0 && side.inertia > 0.0 {
                dt = dt.min((2.0 * side.inertia / kr).sqrt());
            }
        }
        dt
    }
}

#[cfg(test)]
#[path = "joint_tests.rs"]
mod tests;
