//! General spring (/SPRING with /PROP/TYPE8, /PROP/SPR_GENE): six
//! independent degrees of freedom X, Y, Z, RX, RY, RZ in the global frame,
//! each with the law of [`super::spring_law`] (reference guide /PROP/TYPE8;
//! research note `docs/notes/springs_research.md` §2).
//!
//! * Translations are total: δᵢ = (x₂ − x₁)ᵢ − (x₂ − x₁)⁰ᵢ; rotations are
//!   incremental: θᵢ += (ω₂ − ω₁)ᵢ Δt. TYPE8 is meant for (nearly)
//!   coincident nodes: its translations are not objective.
//! * Internal forces f₁ = −Σ Fᵢ eᵢ, f₂ = +Σ Fᵢ eᵢ, and the same for the
//!   moments; energy Σ ½(Fᵢⁿ + Fᵢⁿ⁺¹)Δδᵢ.
//! * Failure (Ifail 0): one direction past its bound, D = δ/δ_max (δ > 0)
//!   or δ/δ_min, > 1; (Ifail 1) Σ D² > 1, low-pass filtered with
//!   α = 2πF_cutΔt/(1 + 2πF_cutΔt) when Fsmooth ≠ 0. Ifail2 = 1 measures
//!   forces instead of displacements. The step that breaks it still carries
//!   its force; the next adds ½Fⁿ·Δδ and nothing more.
//! * Time step min(M/(√(C_m² + M K_m) + C_m), I/(√(C_r² + I K_r) + C_r)),
//!   K_m, C_m the largest translational stiffness and damping, K_r, C_r the
//!   rotational ones.

use super::spring::{check_sensor, element_dt, finder, SpringOut, SpringState};
use super::spring_law::DofLaw;
use crate::model::{Function, GeneralSpringProperty};
use crate::vec3::sub;

/// A /PROP/TYPE8 spring ready to run.
#[derive(Clone, Debug)]
pub struct GeneralSpring {
    pub mass: f64,
    pub inertia: f64,
    multi: bool,
    by_force: bool,
    /// Filter weight 2πF_cut (0: none).
    filter: f64,
    pub laws: Vec<DofLaw>,
}

/// Damage of one direction: its value over the bound on its side.
pub(super) fn ratio(value: f64, lo: f64, hi: f64) -> f64 {
    if value > 0.0 {
        value / hi
    } else {
        value / lo
    }
}

impl GeneralSpring {
    pub fn new(p: &GeneralSpringProperty, functions: &[Function]) -> Result<Self, String> {
        check_sensor(p.sens_id)?;
        let refuse = [
            (p.skew_id != 0, "skew_ID ≠ 0: a spring in a skew frame"),
            (
                p.iequil != 0,
                "Iequil = 1: the incremental objective formulation",
            ),
            (p.ifail2 == 2, "Ifail2 = 2: failure on the energy"),
            (
                p.dofs.iter().any(|d| d.h == 8),
                "H = 8 (a function of the length) on a general spring",
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
        Ok(GeneralSpring {
            mass: p.mass,
            inertia: p.inertia.max(1e-20),
            multi: p.ifail == 1,
            by_force: p.ifail2 == 1,
            filter: if p.fsmooth != 0 {
                2.0 * std::f64::consts::PI * p.fcut
            } else {
                0.0
            },
            laws,
        })
    }

    /// State at t = 0.
    pub fn init(x: &[[f64; 3]; 2]) -> SpringState {
        SpringState {
            origin: sub(x[1], x[0]),
            ..Default::default()
        }
    }

    /// One explicit step from x^{n+1}, v^{n+½}, ω^{n+½}.
    pub fn step(
        &self,
        x: &[[f64; 3]; 2],
        vr: &[[f64; 3]; 2],
        dt: f64,
        st: &mut SpringState,
    ) -> SpringOut {
        let mut out = SpringOut {
            dt: f64::INFINITY,
            ..Default::default()
        };
        let d = sub(x[1], x[0]);
        let w = sub(vr[1], vr[0]);
        let mut delta = [0.0; 6];
        for i in 0..3 {
            delta[i] = d[i] - st.origin[i];
            delta[i + 3] = st.dofs[i + 3].delta + w[i] * dt;
        }
        if st.broken {
            out.d_eint = finish(st, &delta);
            out.failed = true;
            return out;
        }
        let mut de = 0.0;
        let mut force = [0.0; 6];
        for (i, law) in self.laws.iter().enumerate() {
            let s = &mut st.dofs[i];
            let (old, f_old) = (s.delta, s.force);
            let rate = if dt > 0.0 { (delta[i] - old) / dt } else { 0.0 };
            force[i] = law.step(s, delta[i], rate, 0.0);
            de += 0.5 * (f_old + force[i]) * (delta[i] - old);
        }
        for i in 0..6 {
            out.f[0][i] = -force[i];
            out.f[1][i] = force[i];
        }
        out.d_eint = de;
        st.eint += de;
        st.broken = self.fails(&delta, &force, dt, &mut st.crit);
        out.failed = st.broken;
        out.dt = self.time_step();
        out
    }

    /// The failure criterion of this step (the filtered one kept in `crit`).
    fn fails(&self, delta: &[f64; 6], force: &[f64; 6], dt: f64, crit: &mut f64) -> bool {
        let d: Vec<f64> = self
            .laws
            .iter()
            .enumerate()
            .map(|(i, l)| {
                let v = if self.by_force { force[i] } else { delta[i] };
                ratio(v, l.p.delta_min, l.p.delta_max)
            })
            .collect();
        if !self.multi {
            return d.iter().any(|&r| r > 1.0);
        }
        let now: f64 = d.iter().map(|r| r * r).sum();
        *crit = if self.filter > 0.0 {
            let a = self.filter * dt / (1.0 + self.filter * dt);
            a * now + (1.0 - a) * *crit
        } else {
            now
        };
        *crit > 1.0
    }

    fn time_step(&self) -> f64 {
        let group = |r: std::ops::Range<usize>| {
            let k = self.laws[r.clone()]
                .iter()
                .map(DofLaw::k_dt)
                .fold(0.0, f64::max);
            let c = self.laws[r].iter().map(DofLaw::c_dt).fold(0.0, f64::max);
            (k, c)
        };
        let (km, cm) = group(0..3);
        let (kr, cr) = group(3..6);
        element_dt(self.mass, km, cm).min(element_dt(self.inertia, kr, cr))
    }
}

/// The step after a spring broke: the half increment ½Fⁿ·Δδ once, then
/// nothing; every force is zero.
pub(super) fn finish(st: &mut SpringState, delta: &[f64; 6]) -> f64 {
    let mut de = 0.0;
    for (s, &d) in st.dofs.iter_mut().zip(delta) {
        de += 0.5 * s.force * (d - s.delta);
        s.force = 0.0;
        s.delta = d;
    }
    st.eint += de;
    de
}
