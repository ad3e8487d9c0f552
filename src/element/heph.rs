//! 8-node brick, one point with physical hourglass stabilization: Radioss
//! HEPH (/PROP/SOLID Isolid = 24), the solid counterpart of the QEPH shell.
//!
//! # Formulation (research note `docs/notes/solid_formulations_research.md`
//! §2 and §5; Belytschko & Bindeman 1993)
//! * **Frame**: co-rotational, the element frame of the centre Jacobian
//!   (as HA8, `super::ha8`); stress and hourglass stresses are kept in it.
//! * **One point**: D = sym(Σ_I v_I ⊗ b_I) on the mid-step configuration,
//!   the material once per element, f_I = V (σ − qI)·b_I on x^{n+1}
//!   (constant pressure: Icpre changes only the hourglass coefficients).
//! * **Hourglass** (note eq. 18–26): rates q̇_iα = Σ_I γ_Iα v_iI with
//!   γ_Iα = ⅛(Γ_αI − h_α·b_I); J_i the diagonal of the centre Jacobian
//!   columns; G_h = ½ρ₀c²(1 − 2ν)/(1 − ν) (the shear modulus of an elastic
//!   law); twelve stored hourglass stresses F_iα += (G_h Δt/3) q̇_iα / J_i;
//!   F̂_iα = F_iα J_i + c_v q̇_iα with c_v = (dn/4) ρ V^⅓ c / 150;
//!   generalized forces Q_iα of eq. 24 with the coefficients N₁, N₂, N₃ of
//!   Icpre (0: 2/(1−ν), 2ν/(1−ν), ⅔(1+ν); 1: 4/3, −2/3, 4/9); nodal forces
//!   f_iI += Σ_α γ_Iα Q_iα; their work Σ Q_iα q̇_iα Δt (trapezoid on the
//!   stored stresses) is internal energy, as the reference engine counts it
//!   (`ehg` records its share).
//! * **Time step**: Δx = V / largest face area, as the one-point brick.
//!
//! Not computed yet, refused by name: elasto-plastic laws (the plasticity
//! cut of the hourglass stiffness, note §5.4), Icpre 2, failure models.

use super::ha8::{centre_columns, element_frame, geometry, mat_vec, to_frame, vel_to_frame};
use super::hex8::{hex_max_face_area, solid_time_step, Hex8Out, SolidSection};
use crate::material::Material;
use crate::model::ResolvedSolid;
use serde::{Deserialize, Serialize};

/// Section of a HEPH part: Icpre 0/3 (−1 → 0) or 1; dn (0 → 0.1) is kept
/// in `h`, the hourglass viscous coefficient.
pub fn heph_section(r: &ResolvedSolid, m: &Material) -> Result<SolidSection, String> {
    if m.is_plastic() {
        return Err("Isolid = 24 (HEPH) with an elasto-plastic law: the plasticity cut of the hourglass stiffness is not computed yet".into());
    }
    let icpre = match r.icpre {
        -1 | 0 | 3 => 0,
        1 => 1,
        v => {
            return Err(format!(
                "Isolid = 24 with Icpre = {v}: expected -1, 0, 1 or 3"
            ))
        }
    };
    super::hex8::refuse_small_and_foam(r, m, "Isolid = 24 (HEPH)")?;
    let mut plain = r.clone();
    plain.isolid = 1;
    plain.iframe = 1;
    let mut sec = SolidSection::new(&plain, m)?;
    if sec.failure.is_some() {
        return Err("Isolid = 24 (HEPH) with a failure model (/FAIL) is not computed yet".into());
    }
    sec.isolid = 24;
    sec.icpre = icpre;
    sec.h = if r.dn == 0.0 { 0.1 } else { r.dn };
    Ok(sec)
}

/// Per-element state: stress and hourglass stresses in the element frame.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct HephState {
    /// Cauchy stress [σxx σyy σzz σxy σyz σzx] (element frame).
    pub sig_l: [f64; 6],
    /// The same in the global frame, for output.
    pub sig: [f64; 6],
    /// Hourglass stresses F_iα (element frame).
    pub fh: [[f64; 4]; 3],
    pub eps_p: f64,
    /// Internal energy: stress, bulk viscosity and hourglass work.
    pub eint: f64,
    /// The hourglass stabilization's share of `eint`.
    pub ehg: f64,
    pub eplas: f64,
    pub vol0: f64,
    pub vol: f64,
    pub eps_dot: f64,
    /// /PROP/TYPE6 sections: the directions in the element frame (constant:
    /// the frame is co-rotational) and the law's point state.
    #[serde(default)]
    pub ortho: super::ortho::OrthoState,
}

pub fn heph_init(sec: &SolidSection, x: &[[f64; 3]; 8]) -> HephState {
    let vol = volume(x).unwrap_or(0.0);
    let mut ortho = super::ortho::OrthoState::default();
    if let Some(o) = &sec.ortho {
        // The directions at t = 0 (element axes as Isolid 1), then in this
        // element's co-rotational frame.
        let e = super::ortho::element_axes(x);
        let d = super::ortho::material_axes(&super::ortho::initial_gama(o, &e), &e);
        let r = element_frame(x);
        let (d1, d2) = (mat_vec(&r, d[0]), mat_vec(&r, d[1]));
        ortho.gama = [d1[0], d1[1], d1[2], d2[0], d2[1], d2[2]];
    }
    HephState {
        vol0: vol,
        vol,
        ortho,
        ..Default::default()
    }
}

/// The material axes of a /PROP/TYPE6 element in its co-rotational frame.
const LOCAL: [[f64; 3]; 3] = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

/// The centre volume V = j_ξ·(j_η × j_ζ)/64 (exact for a parallelepiped).
fn volume(x: &[[f64; 3]; 8]) -> Option<f64> {
    let [jx, jy, jz] = centre_columns(x);
    let v = crate::vec3::dot(jx, crate::vec3::cross(jy, jz)) / 64.0;
    (v > 0.0).then_some(v)
}

/// N₁, N₂, N₃ of Icpre (note §5.3).
fn coefficients(icpre: i64, nu: f64) -> [f64; 3] {
    if icpre == 1 {
        [4.0 / 3.0, -2.0 / 3.0, 4.0 / 9.0]
    } else {
        [
            2.0 / (1.0 - nu),
            2.0 * nu / (1.0 - nu),
            2.0 / 3.0 * (1.0 + nu),
        ]
    }
}

/// The generalized hourglass forces Q_iα of F̂ (note eq. 23–24).
fn generalized_forces(fh: &[[f64; 4]; 3], j: [f64; 3], n: [f64; 3]) -> [[f64; 4]; 3] {
    let h11 = j[1] * j[2] / j[0];
    let h22 = j[0] * j[2] / j[1];
    let h33 = j[0] * j[1] / j[2];
    let (h12, h13, h23) = (j[2], j[1], j[0]);
    let [x, y, z] = *fh;
    let mut q = [[0.0; 4]; 3];
    // Modes 1-3 (ηζ, ζξ, ξη): index 0..3.
    q[0][0] = (h22 + h33) * x[0] + h12 * y[1] + h13 * z[2];
    q[1][1] = (h11 + h33) * y[1] + h12 * x[0] + h23 * z[2];
    q[2][2] = (h11 + h22) * z[2] + h13 * x[0] + h23 * y[1];
    q[0][1] = n[0] * h11 * x[1] + n[1] * h12 * y[0];
    q[1][0] = n[0] * h22 * y[0] + n[1] * h12 * x[1];
    q[0][2] = n[0] * h11 * x[2] + n[1] * h13 * z[0];
    q[2][0] = n[0] * h33 * z[0] + n[1] * h13 * x[2];
    q[1][2] = n[0] * h22 * y[2] + n[1] * h23 * z[1];
    q[2][1] = n[0] * h33 * z[1] + n[1] * h23 * y[2];
    let hii = [h11, h22, h33];
    for i in 0..3 {
        q[i][3] = n[2] * hii[i] * fh[i][3];
    }
    q
}

/// One explicit step of one HEPH brick (see the module doc). With `dt = 0`
/// only the forces of the current stresses and the time step.
pub fn heph_step(
    sec: &SolidSection,
    x: &[[f64; 3]; 8],
    v: &[[f64; 3]; 8],
    dt: f64,
    st: &mut HephState,
) -> Hex8Out {
    let mut out = Hex8Out {
        dt: f64::INFINITY,
        ..Default::default()
    };
    let r1 = element_frame(x);
    let xl = to_frame(&r1, x);
    let (Some(g1), Some(vol)) = (geometry(&xl), volume(&xl)) else {
        out.bad_volume = true;
        return out;
    };
    let mat = &sec.material;
    let mut compress = 0.0;
    let vl = vel_to_frame(&r1, v);
    let [jx, jy, jz] = centre_columns(&xl);
    let j = [jx[0], jy[1], jz[2]];
    // Hourglass rates of the mode functions, in the element frame.
    let qd: [[f64; 4]; 3] = std::array::from_fn(|i| {
        std::array::from_fn(|al| (0..8).map(|a| g1.gam[al][a] * vl[a][i]).sum())
    });
    let fh_old = st.fh;
    if dt > 0.0 {
        let xm: [[f64; 3]; 8] =
            std::array::from_fn(|a| std::array::from_fn(|k| x[a][k] - 0.5 * dt * v[a][k]));
        let rm = element_frame(&xm);
        let Some(gm) = geometry(&to_frame(&rm, &xm)) else {
            out.bad_volume = true;
            return out;
        };
        let vm = vel_to_frame(&rm, v);
        let mut d = [0.0; 6];
        for a in 0..8 {
            let (b, w) = (gm.b[a], vm[a]);
            d[0] += w[0] * b[0];
            d[1] += w[1] * b[1];
            d[2] += w[2] * b[2];
            d[3] += 0.5 * (w[0] * b[1] + w[1] * b[0]);
            d[4] += 0.5 * (w[1] * b[2] + w[2] * b[1]);
            d[5] += 0.5 * (w[2] * b[0] + w[0] * b[2]);
        }
        st.eps_dot = mat.filter_strain_rate(st.eps_dot, mat.solid_strain_rate(&d), dt);
        let temp = mat.temperature(st.eint / vol);
        let deps = [d[0], d[1], d[2], 2.0 * d[3], 2.0 * d[4], 2.0 * d[5]].map(|e| e * dt);
        let old = st.sig_l;
        let wp = match (&sec.ortho, mat.composite3d()) {
            (Some(_), Some(law)) => {
                let axes = super::ortho::material_axes(&st.ortho.gama, &LOCAL);
                super::ortho::update(
                    law,
                    &axes,
                    &mut st.sig_l,
                    &mut st.eps_p,
                    &mut st.ortho,
                    deps,
                )
            }
            _ => mat.solid_update_at(&mut st.sig_l, &mut st.eps_p, deps, st.eps_dot, temp),
        };
        let w: f64 = (0..6).map(|k| 0.5 * (old[k] + st.sig_l[k]) * deps[k]).sum();
        let vm_vol: f64 = gm.vol_p.iter().sum();
        out.d_eint = w * vm_vol;
        out.d_eplas = wp * vm_vol;
        compress = (-(d[0] + d[1] + d[2])).max(0.0);
        // Hourglass stresses: F += (G_h Δt / 3) q̇ / J (note eq. 21).
        let nu = mat.poisson();
        let rho_c2 = mat.rho_ref() * sec.c * sec.c;
        let gh = 0.5 * rho_c2 * (1.0 - 2.0 * nu) / (1.0 - nu);
        for i in 0..3 {
            for al in 0..4 {
                st.fh[i][al] += gh * dt / 3.0 * qd[i][al] / j[i];
            }
        }
    }
    // Bulk viscosity from the centre dilatation (as the one-point brick).
    let mut q = 0.0;
    if compress > 0.0 {
        q = super::hex8::bulk_viscosity(sec, st.vol0, vol, compress);
        // LAW12 books the law's work only (as `super::hex8`).
        if mat.composite3d().is_none() {
            out.d_eint += q * compress * vol * dt;
        }
    }
    // Hourglass forces: F̂ = F J + c_v q̇ (note eq. 22), Q of eq. 24.
    let rho = mat.rho() * st.vol0 / vol;
    let cv = sec.h / 4.0 * rho * vol.cbrt() * sec.c / 150.0;
    let fhat: [[f64; 4]; 3] =
        std::array::from_fn(|i| std::array::from_fn(|al| st.fh[i][al] * j[i] + cv * qd[i][al]));
    let qg = generalized_forces(&fhat, j, coefficients(sec.icpre, mat.poisson()));
    let mut fl = [[0.0; 3]; 8];
    let mut s = st.sig_l;
    for k in 0..3 {
        s[k] -= q;
    }
    for a in 0..8 {
        let b = g1.b[a];
        fl[a][0] = vol * (s[0] * b[0] + s[3] * b[1] + s[5] * b[2]);
        fl[a][1] = vol * (s[3] * b[0] + s[1] * b[1] + s[4] * b[2]);
        fl[a][2] = vol * (s[5] * b[0] + s[4] * b[1] + s[2] * b[2]);
        for i in 0..3 {
            fl[a][i] += (0..4).map(|al| g1.gam[al][a] * qg[i][al]).sum::<f64>();
        }
    }
    if dt > 0.0 {
        // The work of the hourglass forces over the step: the elastic part
        // at the mean of the old and new hourglass stresses (trapezoid, as
        // the stress work), the viscous part at this step's rate.
        let mid: [[f64; 4]; 3] = std::array::from_fn(|i| {
            std::array::from_fn(|al| 0.5 * (fh_old[i][al] + st.fh[i][al]) * j[i] + cv * qd[i][al])
        });
        let qm = generalized_forces(&mid, j, coefficients(sec.icpre, mat.poisson()));
        let power: f64 = (0..3)
            .flat_map(|i| (0..4).map(move |al| (i, al)))
            .map(|(i, al)| qm[i][al] * qd[i][al])
            .sum();
        // Physical stabilization: its energy is internal energy (note eq.
        // 26), as the reference engine lists it; `ehg` keeps its share.
        st.ehg += power * dt;
        out.d_eint += power * dt;
    }
    st.eint += out.d_eint;
    st.eplas += out.d_eplas;
    st.vol = vol;
    let rt = crate::kinematics::rigid_body::transpose(&r1);
    for a in 0..8 {
        out.f[a] = mat_vec(&rt, fl[a]);
    }
    st.sig = super::hex8::rotate_voigt(&rt, &st.sig_l);
    out.dt = solid_time_step(sec, vol / hex_max_face_area(x), compress);
    out
}

#[cfg(test)]
#[path = "heph_tests.rs"]
mod tests;
