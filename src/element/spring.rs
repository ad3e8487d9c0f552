//! Axial spring (Radioss /SPRING with /PROP/TYPE4, /PROP/SPRING): one
//! translational degree of freedom along the line of its two nodes, and
//! what every spring kernel shares (state, output, time step).
//!
//! # Formulation (reference guide /PROP/TYPE4; theory manual "One Degree of
//! Freedom Spring Elements"; research note `docs/notes/springs_research.md`
//! §1.2–1.4)
//! * Elongation δ = l − l₀ (l = |x₂ − x₁|), rate δ̇ = (δⁿ⁺¹ − δⁿ)/Δt. With
//!   Ileng = 1 the input is per unit length: the law runs on δ/l₀ and δ̇/l₀,
//!   the mass is Mass·l₀.
//! * The force is the law of one degree of freedom
//!   ([`super::spring_law`]: hardening flags H, rate terms).
//! * Failure: when δ (δ/l₀ with Ileng = 1) leaves [δ_min, δ_max] the spring
//!   breaks and carries no force from then on.
//! * Internal forces (the solver does M a = f_ext − f): f₁ = −F n,
//!   f₂ = +F n; a stretched spring (F > 0) pulls its nodes together.
//! * Energy: ½(Fⁿ + Fⁿ⁺¹)(lⁿ⁺¹ − lⁿ) (trapezoidal, the damper's work and
//!   the hysteresis included); the step that breaks it adds ½Fⁿ(lⁿ⁺¹ − lⁿ).
//! * Time step of the element from the spring's own mass (the reference
//!   engine's rule): Δt = M/(√(C² + M·K) + C) with K the law's stiffness
//!   (times the rate factor) and C its damping; without a mass, the
//!   two-mass step of its nodes.
//! * A zero-length spring keeps the last direction it had; before it ever
//!   had one it takes the direction of the relative velocity.

use super::spring_law::{DofLaw, DofState};
use crate::model::{Function, Id, SpringProperty};
use crate::vec3::{norm, scale, sub};
use serde::{Deserialize, Serialize};

/// Per-spring state kept by the solver (all three spring kinds).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct SpringState {
    /// The law state of each degree of freedom (TYPE4 uses the first).
    pub dofs: [DofState; 6],
    /// Length at the last step.
    pub len: f64,
    /// TYPE4: last unit direction x₂ − x₁ (zero while undefined); TYPE13:
    /// the element's local y axis.
    pub dir: [f64; 3],
    /// TYPE8: x₂ − x₁ at t = 0.
    pub origin: [f64; 3],
    /// Cumulative internal energy.
    pub eint: f64,
    /// The filtered multi-directional failure criterion (TYPE8).
    pub crit: f64,
    /// The spring broke.
    pub broken: bool,
}

impl SpringState {
    /// The force of the first degree of freedom (axial, or X).
    pub fn force(&self) -> f64 {
        self.dofs[0].force
    }
}

/// What one spring step returns.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SpringOut {
    /// Internal nodal forces and moments; the solver subtracts them.
    pub f: [[f64; 6]; 2],
    /// The element's time step (unscaled; ∞ when it sets none).
    pub dt: f64,
    /// Internal energy increment.
    pub d_eint: f64,
    /// The spring broke during this step (or earlier).
    pub failed: bool,
}

/// The time step of a mass `m` on a spring K with damper C:
/// M/(√(C² + M·K) + C); ∞ when there is nothing to bound it.
pub fn element_dt(m: f64, k: f64, c: f64) -> f64 {
    if m <= 0.0 || k + c < 1e-15 {
        return f64::INFINITY;
    }
    m / ((c * c + m * k).sqrt() + c)
}

/// Looks up a function by id.
pub fn finder(functions: &[Function]) -> impl Fn(Id) -> Option<Function> + '_ {
    move |id| functions.iter().find(|f| f.id == id).cloned()
}

/// The sensor, which no spring computes yet, refused by name.
pub fn check_sensor(sens_id: Id) -> Result<(), String> {
    if sens_id != 0 {
        return Err(format!(
            "sens_ID = {sens_id}: springs switched by a sensor are not computed yet"
        ));
    }
    Ok(())
}

/// A /PROP/TYPE4 spring ready to run.
#[derive(Clone, Debug)]
pub struct AxialSpring {
    pub mass: f64,
    pub ileng: bool,
    pub law: DofLaw,
}

impl AxialSpring {
    pub fn new(p: &SpringProperty, functions: &[Function]) -> Result<Self, String> {
        check_sensor(p.sens_id)?;
        if p.dof.h == 8 && p.ileng == 1 {
            return Err(
                "H = 8 with Ileng = 1: the length function per unit length is not computed".into(),
            );
        }
        Ok(AxialSpring {
            mass: p.mass,
            ileng: p.ileng == 1,
            law: DofLaw::new(&p.dof, finder(functions))?,
        })
    }

    /// State at t = 0 (no force).
    pub fn init(x: &[[f64; 3]; 2]) -> SpringState {
        let d = sub(x[1], x[0]);
        let l = norm(d);
        SpringState {
            len: l,
            dir: if l > 0.0 { scale(d, 1.0 / l) } else { [0.0; 3] },
            ..Default::default()
        }
    }

    /// One explicit step from x^{n+1}, v^{n+½} (see the module doc);
    /// `masses`: the two nodal masses (the step without a spring mass).
    pub fn step(
        &self,
        x: &[[f64; 3]; 2],
        v: &[[f64; 3]; 2],
        l0: f64,
        dt: f64,
        masses: [f64; 2],
        st: &mut SpringState,
    ) -> SpringOut {
        let mut out = SpringOut {
            dt: f64::INFINITY,
            ..Default::default()
        };
        let d = sub(x[1], x[0]);
        let l = norm(d);
        if l > 1e-12 * l0.max(st.len) && l > 0.0 {
            st.dir = scale(d, 1.0 / l);
        } else if st.dir == [0.0; 3] {
            let dv = sub(v[1], v[0]);
            let s = norm(dv);
            if s > 0.0 {
                st.dir = scale(dv, 1.0 / s);
            }
        }
        let per = if self.ileng {
            if l0 > 0.0 {
                1.0 / l0
            } else {
                0.0
            }
        } else {
            1.0
        };
        let delta = (l - l0) * per;
        let p = &self.law.p;
        let breaks = delta > p.delta_max || delta < p.delta_min || (self.ileng && l0 <= 0.0);
        let f_old = st.dofs[0].force;
        if st.broken || breaks {
            out.d_eint = if st.broken {
                0.0
            } else {
                0.5 * f_old * (l - st.len)
            };
            st.broken = true;
            st.eint += out.d_eint;
            st.dofs[0].force = 0.0;
            st.len = l;
            out.failed = true;
            return out;
        }
        let rate = if dt > 0.0 {
            (delta - st.dofs[0].delta) / dt
        } else {
            0.0
        };
        let force = self.law.step(&mut st.dofs[0], delta, rate, l);
        let n = st.dir;
        out.f[0][..3].copy_from_slice(&scale(n, -force));
        out.f[1][..3].copy_from_slice(&scale(n, force));
        out.d_eint = 0.5 * (f_old + force) * (l - st.len);
        st.eint += out.d_eint;
        st.len = l;
        let amp = (self.law.rate_factor(rate) / p.a).abs().max(1.0);
        let (k, c) = (self.law.k_dt() * amp * per, self.law.c_dt() * per);
        out.dt = if self.mass > 0.0 {
            let m = if self.ileng {
                self.mass * l0
            } else {
                self.mass
            };
            element_dt(m, k, c)
        } else {
            two_mass_dt(masses, k, c)
        };
        out
    }
}

/// Two nodal masses on a spring: ω² = k(1/m₁ + 1/m₂),
/// Δt = (2/ω)(√(1+ξ²) − ξ), ξ = c/(2√(k μ)); a damper alone (k = 0):
/// that bound's limit 2μ/c (the explicit update of μ·v̇ = −c·v is stable
/// for Δt < 2μ/c).
fn two_mass_dt([m1, m2]: [f64; 2], k: f64, c: f64) -> f64 {
    if m1 <= 0.0 || m2 <= 0.0 {
        return f64::INFINITY;
    }
    let mu = m1 * m2 / (m1 + m2);
    if k <= 0.0 {
        return if c > 0.0 { 2.0 * mu / c } else { f64::INFINITY };
    }
    let w = (k / mu).sqrt();
    let xi = c / (2.0 * (k * mu).sqrt());
    (2.0 / w) * ((1.0 + xi * xi).sqrt() - xi)
}

#[cfg(test)]
#[path = "spring_tests.rs"]
mod tests;
