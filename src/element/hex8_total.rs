//! 8-node brick, one point, total strain (Radioss /PROP/SOLID Isolid = 1 or
//! 2 with Ismstr = 10), for the laws that compute their stress from the
//! whole deformation (LAW62).
//!
//! # Formulation (research note `docs/notes/law62_research.md` §3)
//! * **Deformation gradient** (reference engine SDERITO3/SDEFOT3): the
//!   element keeps its initial corner coordinates X₀; with the uniform
//!   gradient vectors b⁰ and volume V₀ of X₀ (`hex8::hex_gradient`),
//!   M = ∂u/∂X₀ = (1/V₀) Σ_a u_a ⊗ b⁰_a, F = I + M at the one point.
//! * **Strain passed to the law** (reference engine MULAW, total-strain
//!   block): e = B − I = M + Mᵀ + M Mᵀ, B = F Fᵀ, without the round-off of
//!   forming B first.
//! * **Stress**: the law's Cauchy stress (global frame) from e and the step
//!   Δt (its Prony series), `crate::material::Law62::stress`. Nothing is
//!   rotated: the stress is rebuilt whole each step.
//! * **Internal forces** f_a = (σ − q I) b_a on x^{n+1}, the bulk viscosity
//!   q and the viscous hourglass of `hex8` (with the law's current wave
//!   speed).
//! * **Internal energy** (reference engine MEINT): ΔE = ½Δt V^{n+½}
//!   (σⁿ + σⁿ⁺¹):D^{n+½} + q ḋ V Δt — the work of the stress; the Prony
//!   dissipation stays in it.
//! * **Time step**: Δt = l_c/(Q + √(Q² + c²)), l_c = V/A_max as `hex8`, with
//!   the law's wave speed at the current stretches, c² = (ρc²)/ρ,
//!   ρ = ρ₀V₀/V (note §2.5).

use super::hex8::{
    hex_gradient, hex_max_face_area, mid_step_gradient, stress_force, velocity_gradient,
    viscous_hourglass, Hex8Out, SolidSection,
};
use crate::material::{Law62, Material};
use crate::model::ResolvedSolid;
use serde::{Deserialize, Serialize};

/// Per-element state of the total-strain brick.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Hex8TotalState {
    /// Cauchy stress [σxx σyy σzz σxy σyz σzx] (global frame), without bulk viscosity.
    pub sig: [f64; 6],
    /// Initial corner coordinates X₀.
    pub x0: [[f64; 3]; 8],
    /// The law's history (LAW62: its Prony series).
    pub hist: Vec<f64>,
    /// Last hourglass generalized forces Q_α.
    pub hg: [[f64; 3]; 4],
    /// Cumulative internal energy (stress and bulk viscosity work).
    pub eint: f64,
    /// Cumulative hourglass energy.
    pub ehg: f64,
    /// Always 0: the law has no plastic strain (kept for the outputs).
    pub eps_p: f64,
    pub eplas: f64,
    pub vol0: f64,
    pub vol: f64,
    pub deleted: bool,
}

/// Section of a total-strain brick part: Isolid 1 or 2, Ismstr 10, a
/// total-strain law.
pub fn total_section(r: &ResolvedSolid, m: &Material) -> Result<SolidSection, String> {
    let Some(law) = m.visco_hyperelastic() else {
        return Err(format!(
            "Ismstr = 10 (total strain) with /MAT/LAW{} is not supported: the engine computes Ismstr = 10 for /MAT/LAW62 only",
            m.law_number()
        ));
    };
    if r.isolid != 1 && r.isolid != 2 {
        return Err(format!(
            "Isolid = {} with Ismstr = 10 is not supported: expected Isolid = 1 or 2",
            r.isolid
        ));
    }
    m.check_supported()?;
    super::hex8::refuse_ortho(r, "the total-strain brick (Ismstr 10)")?;
    Ok(SolidSection {
        isolid: r.isolid,
        ismstr: 10,
        qa: r.qa,
        qb: r.qb,
        h: r.h,
        material: m.clone(),
        c: (law.rest_rho_c2() / m.rho_ref()).sqrt(),
        failure: None,
        icpre: 0,
        ortho: None,
    })
}

fn law(sec: &SolidSection) -> &Law62 {
    sec.material
        .visco_hyperelastic()
        .expect("total_section admits LAW62 only")
}

/// Element state at t = 0 (stress-free, at X₀ = x).
pub fn hex8_total_init(sec: &SolidSection, x: &[[f64; 3]; 8]) -> Hex8TotalState {
    let (_, vol) = hex_gradient(x);
    Hex8TotalState {
        x0: *x,
        hist: vec![0.0; law(sec).history_len()],
        vol0: vol,
        vol,
        ..Default::default()
    }
}

/// e = B − I = M + Mᵀ + MMᵀ of M = ∂u/∂X₀, as [xx yy zz xy yz zx].
fn left_strain(x: &[[f64; 3]; 8], x0: &[[f64; 3]; 8]) -> [f64; 6] {
    let (b0, v0) = hex_gradient(x0);
    let mut m = [[0.0; 3]; 3];
    for a in 0..8 {
        for i in 0..3 {
            let u = x[a][i] - x0[a][i];
            for j in 0..3 {
                m[i][j] += u * b0[a][j];
            }
        }
    }
    m.iter_mut().flatten().for_each(|v| *v /= v0);
    let e = |i: usize, j: usize| m[i][j] + m[j][i] + (0..3).map(|k| m[i][k] * m[j][k]).sum::<f64>();
    [e(0, 0), e(1, 1), e(2, 2), e(0, 1), e(1, 2), e(2, 0)]
}

/// One explicit step of one total-strain brick: stress of x^{n+1}, corner
/// forces, energies and the element time step. With `dt = 0` the state is
/// kept and only the forces of the current stress and the time step are
/// computed.
pub fn hex8_total_step(
    sec: &SolidSection,
    x: &[[f64; 3]; 8],
    v: &[[f64; 3]; 8],
    dt: f64,
    st: &mut Hex8TotalState,
) -> Hex8Out {
    let mut out = Hex8Out {
        dt: f64::INFINITY,
        ..Default::default()
    };
    if st.deleted {
        out.failed = true;
        return out;
    }
    let (b, vol) = hex_gradient(x);
    let (bm, volm) = mid_step_gradient(x, v, dt);
    if !(vol > 0.0 && volm > 0.0) {
        out.bad_volume = true;
        return out;
    }
    let e = left_strain(x, &st.x0);
    let hs = if dt > 0.0 {
        law(sec).stress(&e, dt, &mut st.hist)
    } else {
        law(sec).stress(&e, 0.0, &mut st.hist.clone())
    };
    let l = velocity_gradient(v, &bm, volm);
    let d = [
        l[0][0],
        l[1][1],
        l[2][2],
        0.5 * (l[0][1] + l[1][0]),
        0.5 * (l[1][2] + l[2][1]),
        0.5 * (l[2][0] + l[0][2]),
    ];
    let compress = (-(d[0] + d[1] + d[2])).max(0.0);
    let rho = sec.material.rho() * st.vol0 / vol;
    let c = (hs.rho_c2 / rho).sqrt();
    let mut sig_f = hs.sig;
    if dt > 0.0 {
        let mut p = 0.0;
        for k in 0..6 {
            let wk = if k < 3 { 1.0 } else { 2.0 };
            p += wk * 0.5 * (st.sig[k] + hs.sig[k]) * d[k];
        }
        out.d_eint = p * volm * dt;
        st.sig = hs.sig;
        if compress > 0.0 {
            // MQVISCB with the current wave speed.
            let al = vol.cbrt();
            let q = rho * al * compress * (sec.qa * sec.qa * al * compress + sec.qb * c);
            out.d_eint += q * compress * volm * dt;
            (0..3).for_each(|k| sig_f[k] -= q);
        }
        st.eint += out.d_eint;
    }
    st.vol = vol;
    for a in 0..8 {
        out.f[a] = stress_force(&sig_f, b[a]);
    }
    if sec.h > 0.0 {
        out.d_ehg = viscous_hourglass(sec, x, v, &b, vol, rho, c, dt, &mut out.f, &mut st.hg);
        st.ehg += out.d_ehg;
    }
    let lc = vol / hex_max_face_area(x);
    let q = sec.qb * c + lc * sec.qa * sec.qa * compress;
    out.dt = lc / (q + (q * q + c * c).sqrt());
    out
}

#[cfg(test)]
#[path = "hex8_total_tests.rs"]
pub(crate) mod tests;
