//! Beam (/BEAM with /PROP/TYPE3, /PROP/BEAM): a two-node Timoshenko beam on
//! section resultants, one point, corotational, rate form (reference engine
//! PFORC3/PDEFO3/PCURV3/M2LAWP/PDAMP3/PDLEN3; research note
//! `docs/notes/beam_truss_research.md` §2).
//!
//! * Frame: x along x₂ − x₁; y from the orientation node at t = 0 (in the
//!   plane of x and x₃ − x₁), turned each step about x by the mean torsion
//!   ½(ω₁ + ω₂)·x Δt and kept orthogonal to x; z = x × y. Rates are taken
//!   on the mid-step axis.
//! * Generalized strain rates (local): ė = (v₂ − v₁)ₓ/l; κ̇ = (ω₂ − ω₁)/l;
//!   γ̇_xy = (v₂ − v₁)_y/l − ½(ω₁ + ω₂)_z, γ̇_xz = (v₂ − v₁)_z/l + ½(ω₁ + ω₂)_y.
//! * Elastic resultant increments: N += EA ė Δt, M_x += G I_xx κ̇_x Δt,
//!   M_y += E I_yy κ̇_y Δt, M_z += E I_zz κ̇_z Δt; shear Q_y += k_z γ̇_xy Δt,
//!   Q_z += k_y γ̇_xz Δt with S = ⅚GA, B = 12EI/l² and
//!   k = S·B/(S + B) (Ishear 0, Timoshenko) or B (Ishear 1).
//! * Plastic laws: resultant (global) plasticity, σ_eq = √(N² + 3A Σ M_i²/I_i)/A
//!   against σ_y(ε_p, ε̇); N and M scaled back radially onto it; the plastic
//!   strain from the work the scaling removed, Δε_p = (ΔW − ΔW_el)/(σ_y A),
//!   ε̇ the work-equivalent rate |N ė + Σ M κ̇|/(σ_eq,trial A) and the
//!   plastic work divided by the static flow stress (M2LAWP, reproduced: QA
//!   LOIS_LOI2_BESH's beam energy to 0.1%).
//! * Damping (PDAMP3): viscous resultants dm·ė·V√(2Eρ) on N, df·γ̇·V√(2Eρ)
//!   on Q, df·κ̇·I·l·√(2Eρ) on M_y, M_z and df·κ̇_x·I_xx·l·√(2Gρ) on M_x;
//!   they dissipate into the internal energy.
//! * Nodal forces and moments by virtual power: f₂ = −f₁ = (N, Q_y, Q_z);
//!   m₁ = (−M_x, −M_y + ½lQ_z, −M_z − ½lQ_y), m₂ = (M_x, M_y + ½lQ_z, M_z − ½lQ_y).
//! * Δt = (√(1 + δ²) − δ)·l/c, δ = √2·max(dm, df) (PDLEN3).

use super::truss::line_law_refusal;
use crate::material::Material;
use crate::model::BeamProperty;
use crate::vec3::{add, cross, dot, norm, orthogonal_axis, scale, sub};
use serde::{Deserialize, Serialize};

/// A beam part's constants.
#[derive(Clone, Debug)]
pub struct BeamSection {
    pub p: BeamProperty,
    pub material: Material,
}

impl BeamSection {
    pub fn new(p: &BeamProperty, material: &Material) -> Result<BeamSection, String> {
        if p.released.iter().any(|&r| r) {
            return Err("released rotations (OmegaDof) on a beam are not computed yet".into());
        }
        if !matches!(p.ismstr, 0 | 2 | 4) {
            return Err(format!(
                "Ismstr = {}: a small-strain beam is not computed (Ismstr 0, 2, 4 are)",
                p.ismstr
            ));
        }
        line_law_refusal(material)?;
        Ok(BeamSection {
            p: p.clone(),
            material: material.clone(),
        })
    }

    /// √(2Eρ) and √(2Gρ), the damping impedances.
    fn impedances(&self) -> (f64, f64) {
        let m = &self.material;
        let rho = m.rho();
        (
            (2.0 * m.young() * rho).sqrt(),
            (2.0 * m.shear_modulus() * rho).sqrt(),
        )
    }
}

/// Per-element state of a beam: resultants [N, Q_y, Q_z, M_x, M_y, M_z]
/// (without damping), the local y axis, plasticity and energies.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct BeamState {
    pub f: [f64; 6],
    pub ey: [f64; 3],
    pub eps_p: f64,
    pub eint: f64,
    pub eplas: f64,
}

/// What one beam step returns: internal forces and moments on its two nodes.
#[derive(Clone, Copy, Debug, Default)]
pub struct BeamOut {
    pub f: [[f64; 6]; 2],
    pub d_eint: f64,
    pub dt: f64,
    pub failed: bool,
}

/// State at t = 0 from the two nodes and the orientation node (`None`:
/// global Y, or X for a beam along Y).
pub fn beam_init(x: &[[f64; 3]; 2], x3: Option<[f64; 3]>) -> BeamState {
    let d = sub(x[1], x[0]);
    let ex = scale(d, 1.0 / norm(d));
    let reference = match x3 {
        Some(p) => sub(p, x[0]),
        None if ex[1].abs() < 0.9 => [0.0, 1.0, 0.0],
        None => [1.0, 0.0, 0.0],
    };
    BeamState {
        ey: orthogonal_axis(reference, ex),
        ..Default::default()
    }
}

/// The shear stiffnesses (k for Q_y, k for Q_z) at length `l`.
fn shear_stiffness(sec: &BeamSection, l: f64) -> (f64, f64) {
    let (e, g, a) = (
        sec.material.young(),
        sec.material.shear_modulus(),
        sec.p.area,
    );
    let s = 5.0 / 6.0 * g * a;
    let k = |i: f64| {
        let b = 12.0 * e * i / (l * l);
        if sec.p.ishear == 1 {
            b
        } else {
            s * b / (s + b)
        }
    };
    (k(sec.p.izz), k(sec.p.iyy))
}

/// Radial return of the resultants onto the yield surface (plastic laws);
/// returns the plastic work per unit length. `old` are the resultants
/// before the step, `inc` the generalized strain increments.
fn resultant_plasticity(
    sec: &BeamSection,
    st: &mut BeamState,
    old: &[f64; 6],
    inc: &[f64; 6],
    dt: f64,
) -> f64 {
    let m = &sec.material;
    if !m.is_plastic() {
        return 0.0;
    }
    let p = &sec.p;
    let a = p.area;
    let inertia = [p.ixx, p.iyy, p.izz];
    let eq = |f: &[f64; 6]| {
        let bend: f64 = (0..3).map(|i| f[3 + i] * f[3 + i] / inertia[i]).sum();
        (f[0] * f[0] + 3.0 * a * bend).sqrt() / a
    };
    // The work-equivalent strain rate of the step (M2LAWP): the old
    // resultants' work on the increments over the trial σ_eq·A.
    let s = eq(&st.f);
    let rate = if s > 0.0 && dt > 0.0 {
        let w = old[0] * inc[0] + (0..3).map(|i| old[3 + i] * inc[3 + i]).sum::<f64>();
        w.abs() / (s * a) / dt
    } else {
        0.0
    };
    let temp = m.reference_temperature();
    let y = m.yield_stress(st.eps_p, rate, temp);
    if s <= y {
        return 0.0;
    }
    let r = y / s;
    for k in [0, 3, 4, 5] {
        st.f[k] *= r;
    }
    // The work of the step less the change of the elastic energy.
    let (e, g) = (m.young(), m.shear_modulus());
    let stiff = [e * a, g * p.ixx, e * p.iyy, e * p.izz];
    let mut dw = 0.0;
    for (j, k) in [0, 3, 4, 5].into_iter().enumerate() {
        dw += 0.5 * (old[k] + st.f[k]) * inc[k];
        dw -= (st.f[k] * st.f[k] - old[k] * old[k]) / (2.0 * stiff[j]);
    }
    let dw = dw.max(0.0);
    // As the reference engine, the plastic strain takes the plastic work
    // over the static flow stress (the rate factor does not divide it).
    st.eps_p += dw / (m.yield_stress(st.eps_p, 0.0, temp) * a);
    dw
}

/// The nodal stiffness for the nodal time step (/DT/NODA/CST), as the
/// reference's PDLEN3: K = EA/l and K_rot = max(G·I_xx, φ·E·max(I_yy, I_zz))/l
/// with φ = max(1, (4 + Φ)/((1 + Φ)(1 + s))), s = A l²/(12 I), Φ = 1.2(E/G)/s;
/// both divided by the damping factor (√(1+δ²) − δ)² of the element step, so
/// that a lone beam's nodes step as the element does.
pub fn beam_nodal_stiffness(sec: &BeamSection, x: &[[f64; 3]; 2]) -> (f64, f64) {
    let l = norm(sub(x[1], x[0]));
    let (m, p) = (&sec.material, &sec.p);
    let (e, g) = (m.young(), m.shear_modulus());
    let i = p.iyy.max(p.izz);
    let s = p.area * l * l / (12.0 * i);
    let big_phi = 1.2 * (e / g) / s;
    let phi = ((4.0 + big_phi) / ((1.0 + big_phi) * (1.0 + s))).max(1.0);
    let delta = std::f64::consts::SQRT_2 * p.dm.max(p.df);
    let f = (1.0 + delta * delta).sqrt() - delta;
    let k = e * p.area / l / (f * f);
    let kr = (g * p.ixx).max(phi * e * i) / l / (f * f);
    (k, kr)
}

/// One explicit step of one beam from x^{n+1}, v^{n+½}, ω^{n+½}.
pub fn beam_step(
    sec: &BeamSection,
    x: &[[f64; 3]; 2],
    v: &[[f64; 3]; 2],
    w: &[[f64; 3]; 2],
    dt: f64,
    st: &mut BeamState,
) -> BeamOut {
    let d = sub(x[1], x[0]);
    let l = norm(d);
    let ex = scale(d, 1.0 / l);
    let c = sec.material.sound_speed();
    let delta = std::f64::consts::SQRT_2 * sec.p.dm.max(sec.p.df);
    let mut out = BeamOut {
        dt: ((1.0 + delta * delta).sqrt() - delta) * l / c,
        ..Default::default()
    };
    let wm = scale(add(w[0], w[1]), 0.5);
    // The frame turned by the mean torsion and kept orthogonal to x.
    let phi = dot(wm, ex) * dt;
    let y = st.ey;
    st.ey = orthogonal_axis(add(scale(y, phi.cos()), scale(cross(ex, y), phi.sin())), ex);
    let e = [ex, st.ey, cross(ex, st.ey)];
    let mut visc = [0.0; 6];
    if dt > 0.0 {
        let dm = sub(d, scale(sub(v[1], v[0]), 0.5 * dt));
        let lm = norm(dm);
        let em = [
            scale(dm, 1.0 / lm),
            orthogonal_axis(e[1], scale(dm, 1.0 / lm)),
            [0.0; 3],
        ];
        let em = [em[0], em[1], cross(em[0], em[1])];
        let loc = |a: [f64; 3]| [dot(a, em[0]), dot(a, em[1]), dot(a, em[2])];
        let (dv, dw, wl) = (loc(sub(v[1], v[0])), loc(sub(w[1], w[0])), loc(wm));
        // Rates [ė, γ̇_xy, γ̇_xz, κ̇_x, κ̇_y, κ̇_z].
        let rates = [
            dv[0] / lm,
            dv[1] / lm - wl[2],
            dv[2] / lm + wl[1],
            dw[0] / lm,
            dw[1] / lm,
            dw[2] / lm,
        ];
        let inc = rates.map(|r| r * dt);
        let (m, p) = (&sec.material, &sec.p);
        let (ky, kz) = shear_stiffness(sec, lm);
        let stiff = [
            m.young() * p.area,
            ky,
            kz,
            m.shear_modulus() * p.ixx,
            m.young() * p.iyy,
            m.young() * p.izz,
        ];
        let old = st.f;
        for k in 0..6 {
            st.f[k] += stiff[k] * inc[k];
        }
        let wp = resultant_plasticity(sec, st, &old, &inc, dt);
        let (ze, zg) = sec.impedances();
        let vol = p.area * lm;
        visc = [
            p.dm * rates[0] * vol * ze,
            p.df * rates[1] * vol * ze,
            p.df * rates[2] * vol * ze,
            p.df * rates[3] * p.ixx * lm * zg,
            p.df * rates[4] * p.iyy * lm * ze,
            p.df * rates[5] * p.izz * lm * ze,
        ];
        let mut de = 0.0;
        for k in 0..6 {
            de += (0.5 * (old[k] + st.f[k]) + visc[k]) * inc[k] * lm;
        }
        out.d_eint = de;
        st.eint += de;
        st.eplas += wp * lm;
        out.failed = m.has_failed(st.eps_p);
    }
    let r: [f64; 6] = std::array::from_fn(|k| st.f[k] + visc[k]);
    let on = |a: [f64; 3]| add(add(scale(e[0], a[0]), scale(e[1], a[1])), scale(e[2], a[2]));
    let force = on([r[0], r[1], r[2]]);
    let m1 = on([-r[3], -r[4] + 0.5 * l * r[2], -r[5] - 0.5 * l * r[1]]);
    let m2 = on([r[3], r[4] + 0.5 * l * r[2], r[5] - 0.5 * l * r[1]]);
    for k in 0..3 {
        out.f[0][k] = -force[k];
        out.f[1][k] = force[k];
        out.f[0][3 + k] = m1[k];
        out.f[1][3 + k] = m2[k];
    }
    out
}

#[cfg(test)]
#[path = "beam_tests.rs"]
mod tests;
