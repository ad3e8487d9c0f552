//! Truss (/TRUSS with /PROP/TYPE2, /PROP/TRUSS): an axial bar, large
//! displacements (reference engine TFORC3/TDEFO3/M2LAWT/TDLEN3; research
//! note `docs/notes/beam_truss_research.md` §3).
//!
//! * Strain increment Δε = (v₂ − v₁)·e Δt / l on the mid-step geometry
//!   (e, l of x^{n+½}); the force acts along the current axis e of x^{n+1}.
//! * Hypo-elastic stress σ += E Δε; the area follows A ← A(1 − 2ν Δε) as in
//!   the reference engine.
//! * A plastic law: uniaxial return on its yield curve at zero strain rate
//!   (the reference's truss law M2LAWT has no rate term), Newton on
//!   |σ_trial| − E Δε_p = σ_y(ε_p + Δε_p).
//! * Internal energy ½(N_old + N_new) Δε l (the stress power).
//! * Δt = l / c, c the law's wave speed.
//! * Deleted when the law's failure strain is reached.

use crate::material::Material;
use crate::vec3::{dot, norm, scale, sub};
use serde::{Deserialize, Serialize};

/// A truss part's constants.
#[derive(Clone, Debug)]
pub struct TrussSection {
    pub area: f64,
    pub material: Material,
}

impl TrussSection {
    pub fn new(area: f64, gap: f64, material: &Material) -> Result<TrussSection, String> {
        if gap > 0.0 {
            return Err(format!(
                "Gap = {gap}: a truss with an initial gap is not computed yet (Gap = 0 is)"
            ));
        }
        line_law_refusal(material)?;
        Ok(TrussSection {
            area,
            material: material.clone(),
        })
    }
}

/// Trusses and beams compute the elastic laws and the plastic laws that
/// give a yield curve (LAW1, LAW2, LAW36, LAW44); others are refused by name.
pub fn line_law_refusal(m: &Material) -> Result<(), String> {
    match m.law_number() {
        1 | 2 | 36 | 44 => m.check_supported(),
        n => Err(format!(
            "/MAT/LAW{n} on trusses and beams is not computed (LAW1, LAW2, LAW36 and LAW44 are)"
        )),
    }
}

/// Per-element state of a truss.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct TrussState {
    /// Axial stress.
    pub sig: f64,
    pub area: f64,
    pub eps_p: f64,
    pub eint: f64,
    pub eplas: f64,
}

/// What one truss step returns: internal forces on its two nodes, the
/// energy increment and the time step.
#[derive(Clone, Copy, Debug, Default)]
pub struct TrussOut {
    pub f: [[f64; 3]; 2],
    pub d_eint: f64,
    pub dt: f64,
    pub failed: bool,
}

pub fn truss_init(sec: &TrussSection) -> TrussState {
    TrussState {
        area: sec.area,
        ..Default::default()
    }
}

/// The uniaxial stress after a strain increment `de`: the elastic trial
/// returned to the yield curve of a plastic law; the plastic strain grows.
pub fn uniaxial(m: &Material, sig: f64, eps_p: &mut f64, de: f64, eps_dot: f64) -> f64 {
    let e = m.young();
    let trial = sig + e * de;
    if !m.is_plastic() {
        return trial;
    }
    let temp = m.reference_temperature();
    let y0 = m.yield_stress(*eps_p, eps_dot, temp);
    if trial.abs() <= y0 {
        return trial;
    }
    let mut dp = 0.0;
    for _ in 0..20 {
        let y = m.yield_stress(*eps_p + dp, eps_dot, temp);
        let h = 1e-8_f64.max(1e-6 * (*eps_p + dp));
        let slope = (m.yield_stress(*eps_p + dp + h, eps_dot, temp) - y) / h;
        let r = trial.abs() - e * dp - y;
        let step = r / (e + slope.max(0.0));
        dp += step;
        if step.abs() <= 1e-14 * (*eps_p + dp).max(1e-6) {
            break;
        }
    }
    let dp = dp.max(0.0);
    *eps_p += dp;
    trial.signum() * (trial.abs() - e * dp)
}

/// The nodal stiffness for the nodal time step (/DT/NODA/CST): K = EA/l at
/// each end (the reference's truss stiffness), so that a node of a lone
/// truss steps at √(2m/K) = l/c, the element step.
pub fn truss_nodal_stiffness(sec: &TrussSection, st: &TrussState, x: &[[f64; 3]; 2]) -> f64 {
    sec.material.young() * st.area / norm(sub(x[1], x[0]))
}

/// One explicit step of one truss from x^{n+1} and v^{n+½}.
pub fn truss_step(
    sec: &TrussSection,
    x: &[[f64; 3]; 2],
    v: &[[f64; 3]; 2],
    dt: f64,
    st: &mut TrussState,
) -> TrussOut {
    let d = sub(x[1], x[0]);
    let l = norm(d);
    let mut out = TrussOut {
        dt: l / sec.material.sound_speed(),
        ..Default::default()
    };
    if dt > 0.0 {
        let vd = sub(v[1], v[0]);
        let dm = sub(d, scale(vd, 0.5 * dt));
        let lm = norm(dm);
        let de = dot(vd, dm) / (lm * lm) * dt;
        let n_old = st.sig * st.area;
        let ep0 = st.eps_p;
        st.sig = uniaxial(&sec.material, st.sig, &mut st.eps_p, de, 0.0);
        st.area *= 1.0 - 2.0 * sec.material.poisson() * de;
        let n_new = st.sig * st.area;
        out.d_eint = 0.5 * (n_old + n_new) * de * lm;
        st.eint += out.d_eint;
        st.eplas += (st.eps_p - ep0) * st.sig.abs() * st.area * lm;
        out.failed = sec.material.has_failed(st.eps_p);
    }
    let n = st.sig * st.area;
    let e = scale(d, 1.0 / l);
    out.f = [scale(e, -n), scale(e, n)];
    out
}

#[cfg(test)]
#[path = "truss_tests.rs"]
mod tests;
