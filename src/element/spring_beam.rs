//! Spring beam (/SPRING with /PROP/TYPE13, /PROP/SPR_BEAM): six degrees of
//! freedom (tension, shear XY, shear XZ, torsion, bending Y, bending Z) in a
//! frame that follows the element, each with the law of
//! [`super::spring_law`] (reference guide /PROP/TYPE13; user guide "Beam
//! Type Spring"; research note `docs/notes/springs_research.md` §3).
//!
//! * Frame: x along x₂ − x₁; y from global Y (global X when the spring lies
//!   within 60° of Y) at t = 0, turned each step by the mean torsion
//!   ½(ω₁ + ω₂)·x Δt and kept orthogonal to x; z = x × y.
//! * Tension δ = l − l₀ (total); shear increments net of the nodes' rigid
//!   rotation, Δδ_y = (v₂₁·y − l ω̄·z)Δt, Δδ_z = (v₂₁·z + l ω̄·y)Δt; torsion
//!   and bending Δθᵢ = (ω₂ − ω₁)·eᵢ Δt. With Ileng = 1 the laws run on the
//!   displacements over l₀.
//! * Internal forces f₁ = −F, f₂ = +F; moments m₁ = −(Mx, My − lF_z/2,
//!   Mz + lF_y/2), m₂ = +(Mx, My + lF_z/2, Mz − lF_y/2) (in equilibrium).
//! * Failure (Ifail 0): a direction past its bound; (Ifail 1)
//!   Σ αᵢ Dᵢ^βᵢ > 1. Ifail2 = 2 measures forces.
//! * Time step as TYPE8 with the rotational stiffness raised by the shear
//!   one times l²: K_r = max K_rot + max(K_y, K_z)·l², the same for C.

use super::spring::{check_sensor, element_dt, finder, SpringOut, SpringState};
use super::spring_general::{finish, ratio};
use super::spring_law::DofLaw;
use crate::model::{Function, SpringBeamProperty};
use crate::vec3::{add, cross, dot, norm, orthogonal_axis, scale, sub};

/// A /PROP/TYPE13 spring ready to run.
#[derive(Clone, Debug)]
pub struct SpringBeam {
    pub mass: f64,
    pub inertia: f64,
    ileng: bool,
    multi: bool,
    by_force: bool,
    /// α, β of each direction (Ifail = 1).
    exponents: [[f64; 2]; 6],
    pub laws: Vec<DofLaw>,
}

impl SpringBeam {
    pub fn new(p: &SpringBeamProperty, functions: &[Function]) -> Result<Self, String> {
        check_sensor(p.sens_id)?;
        let refuse = [
            (
                p.skew_id != 0,
                "skew_ID ≠ 0: a spring beam oriented by a skew",
            ),
            (
                matches!(p.ifail2, 1 | 3),
                "Ifail2 = 1 or 3: failure on the velocity or the energy",
            ),
            (
                p.dofs.iter().any(|d| d.h == 8),
                "H = 8 (a function of the length) on a spring beam",
            ),
        ];
        if let Some((_, what)) = refuse.iter().find(|(r, _)| *r) {
            return Err(format!("{what} is not computed yet"));
        }
        let laws = p
            .dofs
            .iter()
            .map(|d| DofLaw::new(d, finder(functions)))
            .collect::<Result<Vec<_>, _>>()?;
        let free = p.ifail2 != 0;
        Ok(SpringBeam {
            mass: p.mass,
            inertia: p.inertia.max(1e-20),
            ileng: p.ileng == 1,
            multi: p.ifail == 1,
            by_force: p.ifail2 == 2,
            exponents: std::array::from_fn(|i| {
                if free {
                    [p.fail[i][2], p.fail[i][3]]
                } else {
                    [1.0, 2.0]
                }
            }),
            laws,
        })
    }

    /// State at t = 0: the local y axis.
    pub fn init(x: &[[f64; 3]; 2]) -> SpringState {
        let d = sub(x[1], x[0]);
        let l = norm(d);
        let reference = if d[1].abs() < 0.5 * l {
            [0.0, 1.0, 0.0]
        } else {
            [1.0, 0.0, 0.0]
        };
        let ex = if l > 0.0 {
            scale(d, 1.0 / l)
        } else {
            [1.0, 0.0, 0.0]
        };
        SpringState {
            len: l,
            dir: orthogonal_axis(reference, ex),
            ..Default::default()
        }
    }

    /// One explicit step from x^{n+1}, v^{n+½}, ω^{n+½}.
    #[allow(clippy::too_many_arguments)]
    pub fn step(
        &self,
        x: &[[f64; 3]; 2],
        v: &[[f64; 3]; 2],
        vr: &[[f64; 3]; 2],
        l0: f64,
        dt: f64,
        st: &mut SpringState,
    ) -> SpringOut {
        let mut out = SpringOut {
            dt: f64::INFINITY,
            ..Default::default()
        };
        let d = sub(x[1], x[0]);
        let l = norm(d);
        let ex = if l > 0.0 {
            scale(d, 1.0 / l)
        } else {
            [1.0, 0.0, 0.0]
        };
        let wm = scale(add(vr[0], vr[1]), 0.5);
        let (ey, ez) = self.frame(st, ex, dot(wm, ex) * dt);
        let (v21, w21) = (sub(v[1], v[0]), sub(vr[1], vr[0]));
        let per = if self.ileng && l0 > 0.0 {
            1.0 / l0
        } else {
            1.0
        };
        let inc = [
            0.0,
            (dot(v21, ey) - l * dot(wm, ez)) * dt,
            (dot(v21, ez) + l * dot(wm, ey)) * dt,
            dot(w21, ex) * dt,
            dot(w21, ey) * dt,
            dot(w21, ez) * dt,
        ];
        let mut delta: [f64; 6] = std::array::from_fn(|i| st.dofs[i].delta + inc[i] * per);
        delta[0] = (l - l0) * per;
        st.len = l;
        if st.broken {
            out.d_eint = finish(st, &delta) / per;
            out.failed = true;
            return out;
        }
        let mut f = [0.0; 6];
        let mut de = 0.0;
        for (i, law) in self.laws.iter().enumerate() {
            let s = &mut st.dofs[i];
            let (old, f_old) = (s.delta, s.force);
            let rate = if dt > 0.0 { (delta[i] - old) / dt } else { 0.0 };
            f[i] = law.step(s, delta[i], rate, l);
            de += 0.5 * (f_old + f[i]) * (delta[i] - old) / per;
        }
        self.assemble(&f, [ex, ey, ez], l, &mut out);
        out.d_eint = de;
        st.eint += de;
        st.broken = self.fails(&delta, &f);
        out.failed = st.broken;
        out.dt = self.time_step(l, l0);
        out
    }

    /// The local y and z axes: y turned about x by the torsion angle φ and
    /// made orthogonal to the new x.
    fn frame(&self, st: &mut SpringState, ex: [f64; 3], phi: f64) -> ([f64; 3], [f64; 3]) {
        let y = st.dir;
        let turned = add(scale(y, phi.cos()), scale(cross(ex, y), phi.sin()));
        st.dir = orthogonal_axis(turned, ex);
        (st.dir, cross(ex, st.dir))
    }

    fn assemble(&self, f: &[f64; 6], e: [[f64; 3]; 3], l: f64, out: &mut SpringOut) {
        let on = |c: [f64; 3]| add(add(scale(e[0], c[0]), scale(e[1], c[1])), scale(e[2], c[2]));
        let force = on([f[0], f[1], f[2]]);
        let m1 = on([f[3], f[4] - 0.5 * l * f[2], f[5] + 0.5 * l * f[1]]);
        let m2 = on([f[3], f[4] + 0.5 * l * f[2], f[5] - 0.5 * l * f[1]]);
        for k in 0..3 {
            out.f[0][k] = -force[k];
            out.f[1][k] = force[k];
            out.f[0][k + 3] = -m1[k];
            out.f[1][k + 3] = m2[k];
        }
    }

    fn fails(&self, delta: &[f64; 6], force: &[f64; 6]) -> bool {
        let d = self.laws.iter().enumerate().map(|(i, l)| {
            let v = if self.by_force { force[i] } else { delta[i] };
            ratio(v, l.p.delta_min, l.p.delta_max)
        });
        if self.multi {
            let sum: f64 = d
                .zip(&self.exponents)
                .map(|(r, [a, b])| a * r.max(0.0).powf(*b))
                .sum();
            sum > 1.0
        } else {
            d.into_iter().any(|r| r > 1.0)
        }
    }

    fn time_step(&self, l: f64, l0: f64) -> f64 {
        let per = if self.ileng && l0 > 0.0 {
            1.0 / l0
        } else {
            1.0
        };
        let ls = &self.laws;
        let (km, cm) = (
            largest(&ls[0..3], DofLaw::k_dt),
            largest(&ls[0..3], DofLaw::c_dt),
        );
        let kr = largest(&ls[3..6], DofLaw::k_dt) + largest(&ls[1..3], DofLaw::k_dt) * l * l;
        let cr = largest(&ls[3..6], DofLaw::c_dt) + largest(&ls[1..3], DofLaw::c_dt) * l * l;
        let (m, i) = (self.mass / per, self.inertia / per);
        element_dt(m, km * per, cm * per).min(element_dt(i, kr * per, cr * per))
    }
}

/// The largest `g` of `laws` (0 for none).
fn largest(laws: &[DofLaw], g: fn(&DofLaw) -> f64) -> f64 {
    laws.iter().map(g).fold(0.0, f64::max)
}
