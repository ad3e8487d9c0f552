//! QBAT: the Batoz fully integrated 4-node shell (Radioss Ishell = 12;
//! theory manual "Fully-integrated Shell Element QBAT"; research note
//! `docs/notes/qbat_research.md` §5, equations E1–E28, W1–W8).
//!
//! * Element frame (E1): R = x₃+x₄−x₁−x₂, S = x₄+x₁−x₂−x₃, e₃ = R×S/|R×S|,
//!   e₁ = unit(R/|R| + S×e₃/|S|), e₂ = e₃×e₁; corners p_I centred on their
//!   mean, warp z_I = ±z_l (E2).
//! * Rigid-mode projection (W4): Ω = D⁻¹(Σ p×v + Σ ω) with
//!   D = Σ(|p|²𝟙 − p pᵀ) + 4·𝟙; v ← v − v̄ − Ω×p, ω ← ω − Ω. Forces take the
//!   transposed projection (W7).
//! * 2×2 Gauss points (E5) on the bilinear surface through p_I (W1), each
//!   with its frame t₁ (bisector of the ξ and η lines), t₂, n and the
//!   contravariant g¹, g² (W3); nodal frames from the surface at the nodes,
//!   director rates ṅ_I = (t₂·ω)t₁ − (t₁·ω)t₂ (W2, W4).
//! * Strain rates (W5, W6): membrane ε̇₁₁, ε̇₂₂ and curvatures with the warp
//!   terms at each point; transverse shear MITC4 from the four mid-side tying
//!   points; the membrane shear γ̇₁₂ constant over the element, from the
//!   centre gradients (E11).
//! * Elastic resultants per point, incremental in the co-rotational frames
//!   (E16–E17): N = t·A(ε), Q = k·G·t·γ (k = Ashear), M = D(κ),
//!   D = Et³/12(1−ν²); the membrane-shear force from the points' mean N₁₂
//!   (E21). Numerical damping dn (E19) as viscous resultants on the forces.
//! * Forces by virtual power, each point weighted by its area J_g (E20).
//! * Δt = L_c(√(1+dn²) − dn)/c₀ with the characteristic length of E24–E25
//!   and c₀ = √(E/ρ) (E26–E27: TWISBEAM's 1.1914171e-6 to all digits).
//!
//! Elastic laws only (N = 0 or any N: resultants are exact for them);
//! plastic laws on QBAT are refused by name.

use crate::material::Material;
use crate::vec3::{add, cross, dot, norm, scale, sub};
use serde::{Deserialize, Serialize};

type V3 = [f64; 3];

/// Per-point generalized strains/stresses: [ε₁₁, ε₂₂, γ₁z, γ₂z, κ₁₁, κ₂₂, κ₁₂].
const NS: usize = 7;
const PG: f64 = 0.577_350_269_189_625_8;
const XI: [f64; 4] = [-1.0, 1.0, 1.0, -1.0];
const ETA: [f64; 4] = [-1.0, -1.0, 1.0, 1.0];
const GAUSS: [(f64, f64); 4] = [(-PG, -PG), (PG, -PG), (PG, PG), (-PG, PG)];

/// A QBAT part's constants.
#[derive(Clone, Debug)]
pub struct QbatSection {
    pub thick: f64,
    pub ashear: f64,
    pub dn: f64,
    pub material: Material,
}

impl QbatSection {
    pub fn new(thick: f64, ashear: f64, dn: f64, m: &Material) -> Result<QbatSection, String> {
        if m.is_plastic() || m.law_number() != 1 {
            return Err(format!(
                "Ishell = 12 (QBAT) with /MAT/LAW{}: only elastic laws (LAW1) are computed on QBAT yet",
                m.law_number()
            ));
        }
        m.check_supported()?;
        Ok(QbatSection {
            thick,
            ashear: if ashear > 0.0 { ashear } else { 5.0 / 6.0 },
            dn,
            material: m.clone(),
        })
    }

    /// [A11·t, A12·t, k·G·t, D, ν·D, D(1−ν)/2, G·t] of the section.
    fn stiffness(&self) -> [f64; 7] {
        let (e, nu) = (self.material.young(), self.material.poisson());
        let t = self.thick;
        let a11 = e / (1.0 - nu * nu);
        let g = e / (2.0 * (1.0 + nu));
        let d = a11 * t * t * t / 12.0;
        [
            a11 * t,
            nu * a11 * t,
            self.ashear * g * t,
            d,
            nu * d,
            0.5 * (1.0 - nu) * d,
            g * t,
        ]
    }
}

/// Per-element state: the resultants of each Gauss point and the
/// membrane shear N₁₂ (element constant), energies.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct QbatState {
    pub res: [[f64; NS]; 4],
    pub n12: f64,
    pub eint: f64,
}

/// What one step returns: internal forces and moments per corner.
#[derive(Clone, Copy, Debug, Default)]
pub struct QbatOut {
    pub f: [[f64; 6]; 4],
    pub dt: f64,
    pub d_eint: f64,
}

fn unit(a: V3) -> V3 {
    scale(a, 1.0 / norm(a))
}

/// The element frame and the corners in it (E1, E2), and A = |R×S|/4.
fn frame(x: &[[f64; 3]; 4]) -> ([V3; 3], [V3; 4], f64) {
    let r = sub(add(x[2], x[3]), add(x[0], x[1]));
    let s = sub(add(x[3], x[0]), add(x[1], x[2]));
    let rs = cross(r, s);
    let e3 = unit(rs);
    let e1 = unit(add(
        scale(r, 1.0 / norm(r)),
        scale(cross(s, e3), 1.0 / norm(s)),
    ));
    let e = [e1, cross(e3, e1), e3];
    let c = scale(add(add(x[0], x[1]), add(x[2], x[3])), 0.25);
    let p = x.map(|xi| {
        let d = sub(xi, c);
        [dot(e[0], d), dot(e[1], d), dot(e[2], d)]
    });
    (e, p, 0.25 * norm(rs))
}

fn dxi(eta: f64) -> [f64; 4] {
    std::array::from_fn(|i| 0.25 * XI[i] * (1.0 + eta * ETA[i]))
}
fn deta(xi: f64) -> [f64; 4] {
    std::array::from_fn(|i| 0.25 * ETA[i] * (1.0 + xi * XI[i]))
}
fn comb(w: &[f64; 4], p: &[V3; 4]) -> V3 {
    std::array::from_fn(|k| (0..4).map(|i| w[i] * p[i][k]).sum())
}

/// The projection's D⁻¹ (W4).
fn projector(p: &[V3; 4]) -> nalgebra::Matrix3<f64> {
    let mut d = nalgebra::Matrix3::identity() * 4.0;
    for q in p {
        let pp = dot(*q, *q);
        for i in 0..3 {
            for j in 0..3 {
                d[(i, j)] += if i == j { pp } else { 0.0 } - q[i] * q[j];
            }
        }
    }
    d.try_inverse().unwrap_or_else(nalgebra::Matrix3::zeros)
}

fn apply(m: &nalgebra::Matrix3<f64>, a: V3) -> V3 {
    std::array::from_fn(|i| (0..3).map(|j| m[(i, j)] * a[j]).sum())
}

/// Linear forms of the strain rates on the projected local dofs: per node,
/// a row on v_I and a row on ω_I.
type Form = [[V3; 2]; 4];

/// The generalized strain forms of the 4 Gauss points and the membrane
/// shear form (E11), the points' areas J_g, and A_w = ΣJ_g.
struct Kinematics {
    b: [[Form; NS]; 4],
    shear: Form,
    jac: [f64; 4],
}

/// The coefficient of ω_I in t·ṅ_I: (t·t₁)t₂ − (t·t₂)t₁ (W2).
fn ndot_form(t: V3, t1: V3, t2: V3) -> V3 {
    sub(scale(t2, dot(t, t1)), scale(t1, dot(t, t2)))
}

fn kinematics(p: &[V3; 4], area: f64) -> Kinematics {
    // Nodal frames (W2).
    let mut t1n = [[0.0; 3]; 4];
    let mut t2n = [[0.0; 3]; 4];
    let mut nn = [[0.0; 3]; 4];
    for i in 0..4 {
        let g1 = comb(&dxi(ETA[i]), p);
        let g2 = comb(&deta(XI[i]), p);
        nn[i] = unit(cross(g1, g2));
        t1n[i] = unit(g1);
        t2n[i] = cross(nn[i], t1n[i]);
    }
    let zero: Form = [[[0.0; 3]; 2]; 4];
    // Membrane shear at the centre (E11), element-frame x, y components.
    let (x13, y13) = (0.5 * (p[0][0] - p[2][0]), 0.5 * (p[0][1] - p[2][1]));
    let (x24, y24) = (0.5 * (p[1][0] - p[3][0]), 0.5 * (p[1][1] - p[3][1]));
    let mut shear = zero;
    for (i, s) in [(0, 1.0), (2, -1.0)] {
        shear[i][0] = [-x24 * s / area, y24 * s / area, 0.0];
    }
    for (i, s) in [(1, 1.0), (3, -1.0)] {
        shear[i][0] = [x13 * s / area, -y13 * s / area, 0.0];
    }
    // Tying points (W6): (a, b, tangent).
    let ties = [
        (0, 1, comb(&dxi(-1.0), p)),
        (3, 2, comb(&dxi(1.0), p)),
        (0, 3, comb(&deta(-1.0), p)),
        (1, 2, comb(&deta(1.0), p)),
    ];
    let tie_form = |(a, b, g): (usize, usize, V3)| -> Form {
        let nm = unit(add(nn[a], nn[b]));
        let mut f = zero;
        f[a][0] = scale(nm, -0.5);
        f[b][0] = scale(nm, 0.5);
        f[a][1] = scale(ndot_form(g, t1n[a], t2n[a]), 0.5);
        f[b][1] = scale(ndot_form(g, t1n[b], t2n[b]), 0.5);
        f
    };
    let tied = ties.map(tie_form);
    let mut out = Kinematics {
        b: [[zero; NS]; 4],
        shear,
        jac: [0.0; 4],
    };
    for (g, &(xi, eta)) in GAUSS.iter().enumerate() {
        let (dx, de) = (dxi(eta), deta(xi));
        let (g1, g2) = (comb(&dx, p), comb(&de, p));
        let c = cross(g1, g2);
        let j = norm(c);
        let n = scale(c, 1.0 / j);
        let t1 = unit(add(scale(g1, norm(g2)), scale(cross(g2, n), norm(g1))));
        let t2 = cross(n, t1);
        let (gc1, gc2) = (scale(cross(g2, n), 1.0 / j), scale(cross(n, g1), 1.0 / j));
        let (nxi, neta) = (comb(&dx, &nn), comb(&de, &nn));
        let (k11, k12, k21, k22) = (dot(gc1, nxi), dot(gc1, neta), dot(gc2, nxi), dot(gc2, neta));
        let h = -(k11 + k22);
        let tc = [[dot(gc1, t1), dot(gc1, t2)], [dot(gc2, t1), dot(gc2, t2)]];
        let tbi = [[k22, -k12], [-k21, k11]];
        let tbc: [[f64; 2]; 2] = std::array::from_fn(|r| {
            std::array::from_fn(|q| tbi[r][0] * tc[0][q] + tbi[r][1] * tc[1][q])
        });
        let b = &mut out.b[g];
        for i in 0..4 {
            let c1 = dx[i] * tc[0][0] + de[i] * tc[1][0];
            let c2 = dx[i] * tc[0][1] + de[i] * tc[1][1];
            let b1 = dx[i] * tbc[0][0] + de[i] * tbc[1][0];
            let b2 = dx[i] * tbc[0][1] + de[i] * tbc[1][1];
            let (k1, k2) = (ndot_form(t1, t1n[i], t2n[i]), ndot_form(t2, t1n[i], t2n[i]));
            b[0][i][0] = scale(t1, c1);
            b[1][i][0] = scale(t2, c2);
            b[4][i] = [add(scale(t1, b1), scale(t1, h * c1)), scale(k1, c1)];
            b[5][i] = [add(scale(t2, b2), scale(t2, h * c2)), scale(k2, c2)];
            b[6][i] = [
                add(add(scale(t2, b1), scale(t1, b2)), scale(shear[i][0], h)),
                add(scale(k2, c1), scale(k1, c2)),
            ];
        }
        // Transverse shear: γ_ξ, γ_η interpolated (E14), then to t₁, t₂.
        let w = [
            0.5 * (1.0 - eta),
            0.5 * (1.0 + eta),
            0.5 * (1.0 - xi),
            0.5 * (1.0 + xi),
        ];
        for i in 0..4 {
            for r in 0..2 {
                let gx = add(scale(tied[0][i][r], w[0]), scale(tied[1][i][r], w[1]));
                let ge = add(scale(tied[2][i][r], w[2]), scale(tied[3][i][r], w[3]));
                b[2][i][r] = add(scale(gx, tc[0][0]), scale(ge, tc[1][0]));
                b[3][i][r] = add(scale(gx, tc[0][1]), scale(ge, tc[1][1]));
            }
        }
        out.jac[g] = j;
    }
    out
}

fn eval(f: &Form, v: &[V3; 4], w: &[V3; 4]) -> f64 {
    (0..4)
        .map(|i| dot(f[i][0], v[i]) + dot(f[i][1], w[i]))
        .sum()
}

fn accumulate(f: &Form, s: f64, fv: &mut [V3; 4], fw: &mut [V3; 4]) {
    for i in 0..4 {
        fv[i] = add(fv[i], scale(f[i][0], s));
        fw[i] = add(fw[i], scale(f[i][1], s));
    }
}

/// The characteristic length of the element step (E24, E25).
fn char_length(p: &[V3; 4], area: f64, area_w: f64) -> f64 {
    let d = |a: usize, b: usize, c: usize, e: usize| {
        let v = [
            p[a][0] + p[b][0] - p[c][0] - p[e][0],
            p[a][1] + p[b][1] - p[c][1] - p[e][1],
        ];
        (v[0] * v[0] + v[1] * v[1]).sqrt()
    };
    let (c1, c2) = (d(1, 2, 0, 3), d(2, 3, 0, 1));
    let s = 0.25 * (c1.max(c2) / c1.min(c2) - 1.0);
    let f1 = 1.0 + s.min(0.5);
    let f2 = 0.78 + 0.22 * (3.413 * (4.0 * area_w / (c1 * c2) - 0.7071).max(0.0)).powi(3);
    let lm = (p[1][0] * p[3][1] - p[1][1] * p[3][0])
        .abs()
        .max((p[0][0] * p[2][1] - p[0][1] * p[2][0]).abs());
    let half = |a: usize, b: usize| {
        let (x, y) = (0.5 * (p[a][0] - p[b][0]), 0.5 * (p[a][1] - p[b][1]));
        x * x + y * y
    };
    let lmax2 = half(0, 2).max(half(1, 3));
    area_w / (2.0 * f1 * f2 * (4.0 / 3.0 + lm / area) * lmax2).sqrt()
}

/// One explicit step of one QBAT shell from x^{n+1}, v^{n+½}, ω^{n+½}.
pub fn qbat_step(
    sec: &QbatSection,
    x: &[[f64; 3]; 4],
    v: &[[f64; 3]; 4],
    w: &[[f64; 3]; 4],
    dt: f64,
    st: &mut QbatState,
) -> QbatOut {
    let (e, p, area) = frame(x);
    let kin = kinematics(&p, area);
    let area_w: f64 = kin.jac.iter().sum();
    let m = &sec.material;
    let c0 = (m.young() / m.rho()).sqrt();
    let mu = sec.dn;
    let mut out = QbatOut {
        dt: char_length(&p, area, area_w) * ((1.0 + mu * mu).sqrt() - mu) / c0,
        ..Default::default()
    };
    let loc = |a: V3| [dot(e[0], a), dot(e[1], a), dot(e[2], a)];
    let mut vl = v.map(loc);
    let mut wl = w.map(loc);
    // Rigid-mode projection (W4).
    let dinv = projector(&p);
    let vbar = scale(add(add(vl[0], vl[1]), add(vl[2], vl[3])), 0.25);
    let mut a = [0.0; 3];
    for i in 0..4 {
        a = add(add(a, cross(p[i], vl[i])), wl[i]);
    }
    let om = apply(&dinv, a);
    for i in 0..4 {
        vl[i] = sub(sub(vl[i], vbar), cross(om, p[i]));
        wl[i] = sub(wl[i], om);
    }
    let k = sec.stiffness();
    let cv = 1.414 * sec.dn * m.rho() * c0;
    let (t, nu) = (sec.thick, m.poisson());
    let mut fv = [[0.0; 3]; 4];
    let mut fw = [[0.0; 3]; 4];
    let mut de = 0.0;
    let g12 = eval(&kin.shear, &vl, &wl);
    let mut n12_visc = 0.0;
    for g in 0..4 {
        let rate: [f64; NS] = std::array::from_fn(|s| eval(&kin.b[g][s], &vl, &wl));
        let old = st.res[g];
        if dt > 0.0 {
            let d: [f64; NS] = rate.map(|r| r * dt);
            let r = &mut st.res[g];
            r[0] += k[0] * d[0] + k[1] * d[1];
            r[1] += k[1] * d[0] + k[0] * d[1];
            r[2] += k[2] * d[2];
            r[3] += k[2] * d[3];
            r[4] += k[3] * d[4] + k[4] * d[5];
            r[5] += k[4] * d[4] + k[3] * d[5];
            r[6] += k[5] * d[6];
            for s in 0..NS {
                de += kin.jac[g] * 0.5 * (old[s] + r[s]) * d[s];
            }
        }
        // Numerical damping (E19): viscous resultants on the forces.
        let c = cv * kin.jac[g].sqrt();
        let visc = [
            c * t * (rate[0] + nu * rate[1]),
            c * t * (rate[1] + nu * rate[0]),
            0.0,
            0.0,
            0.3 * t * t * t * c * (rate[4] + nu * rate[5]),
            0.3 * t * t * t * c * (rate[5] + nu * rate[4]),
            0.3 * t * t * t * c * rate[6] / (2.0 * (1.0 + nu)),
        ];
        n12_visc += 0.25 * c * t * g12 / (2.0 * (1.0 + nu));
        // The damping's work dissipates into the internal energy.
        for s in 0..NS {
            de += kin.jac[g] * visc[s] * rate[s] * dt;
        }
        for s in 0..NS {
            accumulate(
                &kin.b[g][s],
                kin.jac[g] * (st.res[g][s] + visc[s]),
                &mut fv,
                &mut fw,
            );
        }
    }
    if dt > 0.0 {
        let n12_old = st.n12;
        st.n12 += k[6] * g12 * dt;
        de += area_w * (0.5 * (n12_old + st.n12) + n12_visc) * g12 * dt;
    }
    accumulate(&kin.shear, area_w * (st.n12 + n12_visc), &mut fv, &mut fw);
    // The transposed projection (W7): the forces on the unprojected dofs.
    let fbar = scale(add(add(fv[0], fv[1]), add(fv[2], fv[3])), 0.25);
    let mut af = [0.0; 3];
    for i in 0..4 {
        af = add(add(af, cross(p[i], fv[i])), fw[i]);
    }
    let omf = apply(&dinv, af);
    for i in 0..4 {
        let f = sub(sub(fv[i], fbar), cross(omf, p[i]));
        let mm = sub(fw[i], omf);
        let glob = |a: V3| add(add(scale(e[0], a[0]), scale(e[1], a[1])), scale(e[2], a[2]));
        let (fg, mg) = (glob(f), glob(mm));
        out.f[i] = [fg[0], fg[1], fg[2], mg[0], mg[1], mg[2]];
    }
    out.d_eint = de;
    st.eint += de;
    out
}

/// Von Mises of the mean membrane stress (N/t) of an element.
pub fn membrane_von_mises(st: &QbatState, thick: f64) -> f64 {
    let n = |s: usize| st.res.iter().map(|r| r[s]).sum::<f64>() / (4.0 * thick);
    let (a, b, c) = (n(0), n(1), st.n12 / thick);
    (a * a + b * b - a * b + 3.0 * c * c).max(0.0).sqrt()
}

#[cfg(test)]
#[path = "shell4_qbat_tests.rs"]
mod tests;
