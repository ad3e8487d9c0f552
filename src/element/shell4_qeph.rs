//! QEPH (Radioss Ishell = 24): the Belytschko-Tsay constant part of
//! `shell4` plus a physical hourglass stabilization, after the research
//! note `docs/notes/qeph_research.md` (Radioss theory manual "Advanced
//! Elasto-plastic Hourglass Control"; Belytschko & Leviathan 1994, "Physical
//! stabilization of the 4-node shell element with one point quadrature",
//! CMAME 113; Zeng & Combescure 1998). Equation numbers are the note's.
//!
//! * Six hourglass rates (eq. 5–10): membrane q̇₁, q̇₂ (with the warp term
//!   w b·v_z), bending q̇₃, q̇₄ and two transverse-shear rates q̇₅, q̇₆.
//! * Twelve hourglass stresses S_k in the element frame (eq. 11–13), the
//!   η and ξ parts of a linear stress field without in-plane shear; no user
//!   coefficient (hm, hf, hr are not used): the stiffness is the material's
//!   plane-stress A11 = E/(1−ν²), A12 = νA11 and G·k_s/64.
//! * Plasticity (eq. 14–15): once a point of the section yields, the
//!   loading membrane increment is scaled by the mean E_t/E and the bending
//!   one frozen (×0.001); an elastic section whose stress plus 0.85 of the
//!   hourglass field passes the yield surface has its membrane increment cut.
//! * Damping dn (eq. 16, default 0.015) on the rates, its work counted as
//!   hourglass energy; the elastic hourglass work is internal energy.
//! * Generalized forces (eq. 17) and their nodal transposes (eq. 18–20):
//!   force and moment equilibrium hold and the power is exact.
//! * Time step (eq. 21–22): its own characteristic length (aspect, skew
//!   and taper factors; 0.894a on a square of side a) times √(1+dn²) − dn.
//!
//! Not computed (documented differences from the reference engine, both
//! vanishing on flat parallelograms): the Belytschko-Leviathan projection of
//! the rotation rates of warped elements with N > 1, and the transverse-shear
//! correction of non-parallelograms (eq. 4).

use super::{Geom, ShellSection};

/// Radioss's local quantities of a configuration (eq. 1–2): the mid-sides
/// MX13 = h·x̄/4, MX23 = ∂x/∂ξ, MX34 = ∂x/∂η (and y), the inverse-Jacobian
/// factors and the warp w (z_I = w·h_I).
#[derive(Clone, Copy, Debug)]
struct Sides {
    mx13: f64,
    mx23: f64,
    mx34: f64,
    my13: f64,
    my23: f64,
    my34: f64,
    hx: f64,
    hy: f64,
    kx: f64,
    ky: f64,
    w: f64,
}

fn sides(g: &Geom) -> Sides {
    let (x, y) = (&g.x, &g.y);
    let m = |a: &[f64; 4], i: usize, j: usize| 0.5 * (a[i] + a[j]);
    let (mx34, my34, mx23, my23) = (m(x, 2, 3), m(y, 2, 3), m(x, 1, 2), m(y, 1, 2));
    let r = 4.0 / g.area;
    Sides {
        mx13: m(x, 0, 2),
        my13: m(y, 0, 2),
        mx23,
        my23,
        mx34,
        my34,
        hx: r * my34,
        hy: r * mx34,
        kx: r * my23,
        ky: r * mx23,
        w: 0.25 * g.gz,
    }
}

const H: [f64; 4] = [1.0, -1.0, 1.0, -1.0];
const S: [f64; 4] = [1.0, 1.0, -1.0, -1.0];
const SP: [f64; 4] = [1.0, -1.0, -1.0, 1.0];

/// Nodal velocities and rotation rates in the frame of `g`:
/// (v_x, v_y, v_z) and (θ_x, θ_y) per node.
pub(super) fn local(
    g: &Geom,
    v: &[[f64; 3]; 4],
    vr: &[[f64; 3]; 4],
) -> ([[f64; 3]; 4], [[f64; 2]; 4]) {
    let d = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let [e1, e2, e3] = g.e;
    (
        std::array::from_fn(|i| [d(e1, v[i]), d(e2, v[i]), d(e3, v[i])]),
        std::array::from_fn(|i| [d(e1, vr[i]), d(e2, vr[i])]),
    )
}

/// Hourglass rates q̇₁..q̇₆ (eq. 5–10).
fn rates(g: &Geom, s: &Sides, vl: &[[f64; 3]; 4], th: &[[f64; 2]; 4]) -> [f64; 6] {
    let sum = |w: &[f64; 4], f: &dyn Fn(usize) -> f64| (0..4).map(|i| w[i] * f(i)).sum::<f64>();
    let one = [1.0; 4];
    let bxvz = sum(&g.bx, &|i| vl[i][2]);
    let byvz = sum(&g.by, &|i| vl[i][2]);
    let hvz = sum(&H, &|i| vl[i][2]);
    let (sx, sy) = (sum(&one, &|i| th[i][0]), sum(&one, &|i| th[i][1]));
    let shear = |mx: f64, my: f64, w: &[f64; 4]| {
        4.0 * (hvz - s.my13 * sx + my * sum(w, &|i| th[i][0]) - mx * sum(w, &|i| th[i][1])
            + s.mx13 * sy)
    };
    [
        0.25 * sum(&g.gam, &|i| vl[i][0]) + s.w * bxvz,
        0.25 * sum(&g.gam, &|i| vl[i][1]) + s.w * byvz,
        0.25 * sum(&g.gam, &|i| th[i][1]),
        -0.25 * sum(&g.gam, &|i| th[i][0]),
        shear(s.mx23, s.my23, &S),
        shear(s.mx34, s.my34, &SP),
    ]
}

/// Elastic increments of the twelve hourglass stresses (eq. 11–13);
/// index k of the note is `k − 1` here.
fn increments(sec: &ShellSection, s: &Sides, dq: &[f64; 6]) -> [f64; 12] {
    let (e, nu) = (sec.material.young(), sec.material.poisson());
    let a11 = e / (1.0 - nu * nu);
    let a12 = nu * a11;
    let c = sec.material.shear_modulus() * sec.ashear / 64.0;
    let pair = |q1: f64, q2: f64, h: (f64, f64)| {
        (
            a11 * h.0 * q1 - a12 * h.1 * q2,
            a11 * h.1 * q2 - a12 * h.0 * q1,
        )
    };
    let (m1, m2) = pair(dq[0], dq[1], (s.hx, s.hy));
    let (m7, m8) = pair(dq[0], dq[1], (s.kx, s.ky));
    let (b3, b4) = pair(dq[2], dq[3], (s.hx, s.hy));
    let (b9, b10) = pair(dq[2], dq[3], (s.kx, s.ky));
    [
        m1,
        m2,
        b3,
        b4,
        c * s.hx * dq[4],
        c * s.hy * dq[4],
        m7,
        m8,
        b9,
        b10,
        c * s.kx * dq[5],
        c * s.ky * dq[5],
    ]
}

/// The plastic state of the section this step (eq. 14): mean and least
/// E_t/E of the points (1 for a point that did not yield) and the mean
/// current yield stress (∞ for an elastic law).
#[derive(Clone, Copy, Debug)]
pub(super) struct Plastic {
    pub phi_avg: f64,
    pub phi_min: f64,
    pub sig_y: f64,
}

/// Von Mises-like sum of a stress pair and the hourglass field (eq. 15a).
fn j2(s: [f64; 3], a: [f64; 4]) -> f64 {
    let [a1, a2, a7, a8] = a;
    s[0] * s[0] + s[1] * s[1] - s[0] * s[1]
        + 3.0 * s[2] * s[2]
        + (a1 * a1 + a2 * a2 - a1 * a2)
        + (a7 * a7 + a8 * a8 - a7 * a8)
        + (a1 * (2.0 * a7 - a8) + a2 * (2.0 * a8 - a7)).abs()
}

/// The plasticity cut of this step's increments (eq. 15a–b): returns the
/// fractions (e₁, e₂) of the membrane and bending increments taken back.
#[allow(clippy::too_many_arguments)]
fn plastic_cut(
    sec: &ShellSection,
    s: &Sides,
    hg: &[f64; 12],
    dq: &[f64; 6],
    t: f64,
    pl: Plastic,
    nbar: [f64; 3],
    mbar: [f64; 3],
) -> (f64, f64) {
    if !(pl.sig_y < 0.9e30) {
        return (0.0, 0.0);
    }
    let sy2 = pl.sig_y * pl.sig_y;
    let elastic = (pl.phi_avg.min(pl.phi_min) - 1.0).abs() < 1e-18;
    let (jm, f) = if elastic {
        let a = [0.85 * hg[0], 0.85 * hg[1], 0.85 * hg[6], 0.85 * hg[7]];
        let b = [hg[2], hg[3], hg[8], hg[9]].map(|v| 0.85 * t / 16.0 * v);
        let jm = j2(nbar, a);
        let cb = if sec.global { 16.0 } else { 25.0 };
        (jm, jm + cb * j2(mbar, b))
    } else {
        (0.0, 0.0)
    };
    if elastic && f <= sy2 {
        return (0.0, 0.0);
    }
    let esx = (s.my34 * hg[0] + s.my23 * hg[6]) * dq[0] + (s.mx23 * hg[7] + s.mx34 * hg[1]) * dq[1];
    let emx = (s.my34 * hg[2] + s.my23 * hg[8]) * dq[2] + (s.mx23 * hg[9] + s.mx34 * hg[3]) * dq[3];
    let e1 = if esx < 0.0 {
        0.0
    } else {
        (0.999 * (jm / sy2).min(1.0)).max(1.0 - pl.phi_avg)
    };
    let e2 = if emx < 0.0 {
        0.0
    } else {
        0.999f64.max(1.0 - pl.phi_min)
    };
    (e1, e2)
}

/// Generalized hourglass forces (eq. 17) of the stresses `hg` on the
/// configuration `s`: [P1, P2, B1, B2, T5, T6] (elastic part).
fn generalized(s: &Sides, hg: &[f64; 12], t: f64) -> [f64; 6] {
    let k = 4.0 / 3.0;
    [
        k * (s.my34 * hg[0] + s.my23 * hg[6]),
        k * (s.mx23 * hg[7] + s.mx34 * hg[1]),
        k * (s.my34 * hg[2] + s.my23 * hg[8]),
        -k * (s.mx23 * hg[9] + s.mx34 * hg[3]),
        k * t * (s.my34 * hg[4] + s.mx34 * hg[5]),
        k * t * (s.my23 * hg[10] + s.mx23 * hg[11]),
    ]
}

/// The dampers of the rates (eq. 16), same order as [`generalized`].
fn damping(sec: &ShellSection, g: &Geom, s: &Sides, qd: &[f64; 6], t: f64) -> [f64; 6] {
    let m = &sec.material;
    let (e, nu, rho) = (m.young(), m.poisson(), m.rho_ref());
    let a11 = e / (1.0 - nu * nu);
    let (s11, s12) = (a11.sqrt(), (nu * a11).max(0.0).sqrt());
    let mu = sec.dn;
    let ra = (rho * g.area).sqrt();
    let v = mu * ra / g.area;
    let cyy = s.my34 * s.my34 + s.my23 * s.my23;
    let cxx = s.mx23 * s.mx23 + s.mx34 * s.mx34;
    let cxy = s.my34 * s.mx34 + s.my23 * s.mx23;
    let k = 16.0 / 3.0 * v;
    let bend = if sec.n_ip > 1 || sec.global {
        12.0f64.sqrt() * k
    } else {
        0.0
    };
    let l5 = s.my34 * s.my34 + s.mx34 * s.mx34;
    let l6 = s.my23 * s.my23 + s.mx23 * s.mx23;
    let g_mod = m.shear_modulus();
    let sh = if sec.n_ip > 1 || sec.global {
        mu * ra * (g_mod * sec.ashear / 12.0).sqrt() * t / g.area
    } else {
        25.0 * mu * (g_mod * rho * g.area / 12.0).sqrt() * t / g.area
    };
    [
        k * (s11 * cyy * qd[0] - s12 * cxy * qd[1]),
        k * (s11 * cxx * qd[1] - s12 * cxy * qd[0]),
        bend * (s11 * cyy * qd[2] - s12 * cxy * qd[3]),
        bend * (-s11 * cxx * qd[3] + s12 * cxy * qd[2]),
        sh * l5 * qd[4],
        sh * l6 * qd[5],
    ]
}

/// Power of generalized forces `p` on rates `q`:
/// t(P1q1 + P2q2) + (t³/12)(B1q3 − B2q4) + ¼(T5q5 + T6q6).
fn power(p: &[f64; 6], q: &[f64; 6], t: f64, bending: bool) -> f64 {
    let tb = if bending { t * t * t / 12.0 } else { 0.0 };
    t * (p[0] * q[0] + p[1] * q[1])
        + tb * (p[2] * q[2] - p[3] * q[3])
        + 0.25 * (p[4] * q[4] + p[5] * q[5])
}

/// What the QEPH hourglass adds to one element step: local corner forces
/// and moments (frame of the end configuration) and the energies.
pub(super) struct QephStep {
    pub f: [[f64; 3]; 4],
    pub m: [[f64; 2]; 4],
    pub d_eint: f64,
    pub d_ehg: f64,
}

/// One step of the stabilization: rates on the mid-step configuration
/// `gm`, stresses `hg` updated (elastic, cut by plasticity), forces on the
/// end configuration `ge`. `nbar`, `mbar`: the section's N/t and M/t².
#[allow(clippy::too_many_arguments)]
pub(super) fn step(
    sec: &ShellSection,
    gm: &Geom,
    ge: &Geom,
    v: &[[f64; 3]; 4],
    vr: &[[f64; 3]; 4],
    dt: f64,
    t: f64,
    hg: &mut [f64; 12],
    pl: Plastic,
    nbar: [f64; 3],
    mbar: [f64; 3],
) -> QephStep {
    let bending = sec.n_ip > 1 || sec.global;
    let sm = sides(gm);
    let (vl, th) = local(gm, v, vr);
    let qd = rates(gm, &sm, &vl, &th);
    let dq = qd.map(|q| q * dt);
    let old = *hg;
    let mut inc = increments(sec, &sm, &dq);
    if !bending {
        for k in [2, 3, 4, 5, 8, 9, 10, 11] {
            inc[k] = 0.0;
        }
    }
    let (e1, e2) = plastic_cut(sec, &sm, hg, &dq, t, pl, nbar, mbar);
    for k in 0..12 {
        let cut = match k {
            0 | 1 | 6 | 7 => e1,
            2 | 3 | 8 | 9 => e2,
            _ => 0.0,
        };
        hg[k] += (1.0 - cut) * inc[k];
    }
    let se = sides(ge);
    let p_old = generalized(&se, &old, t);
    let p_el = generalized(&se, hg, t);
    let p_v = damping(sec, ge, &se, &qd, t);
    let mid: [f64; 6] = std::array::from_fn(|k| 0.5 * (p_old[k] + p_el[k]));
    let p: [f64; 6] = std::array::from_fn(|k| p_el[k] + p_v[k]);
    let (f, m) = nodal(ge, &se, &p, t, bending);
    QephStep {
        f,
        m,
        d_eint: power(&mid, &dq, t, bending),
        d_ehg: power(&p_v, &dq, t, bending),
    }
}

/// Nodal forces and moments of generalized forces `p` (eq. 18–20), local frame.
fn nodal(
    g: &Geom,
    s: &Sides,
    p: &[f64; 6],
    t: f64,
    bending: bool,
) -> ([[f64; 3]; 4], [[f64; 2]; 4]) {
    let [p1, p2, b1, b2, t5, t6] = *p;
    let tb = if bending { t * t * t / 12.0 } else { 0.0 };
    let mut f = [[0.0; 3]; 4];
    let mut m = [[0.0; 2]; 4];
    for i in 0..4 {
        let gi = 0.25 * g.gam[i];
        f[i] = [
            t * p1 * gi,
            t * p2 * gi,
            H[i] * (t5 + t6) + s.w * t * (p1 * g.bx[i] + p2 * g.by[i]),
        ];
        m[i] = [
            tb * b2 * gi + t5 * (s.my23 * S[i] - s.my13) + t6 * (s.my34 * SP[i] - s.my13),
            tb * b1 * gi + t5 * (s.mx13 - s.mx23 * S[i]) + t6 * (s.mx13 - s.mx34 * SP[i]),
        ];
    }
    (f, m)
}

/// The QEPH characteristic length (eq. 21) times √(1+dn²) − dn (eq. 22):
/// the element step is this over the sound speed.
pub(super) fn char_length(sec: &ShellSection, g: &Geom) -> f64 {
    let (x, y) = (&g.x, &g.y);
    let r = [x[1] + x[2] - x[3] - x[0], y[1] + y[2] - y[3] - y[0]];
    let q = [x[2] + x[3] - x[0] - x[1], y[2] + y[3] - y[0] - y[1]];
    let (c1, c2) = (
        (r[0] * r[0] + r[1] * r[1]).sqrt(),
        (q[0] * q[0] + q[1] * q[1]).sqrt(),
    );
    let f1 = 1.0 + (0.25 * (c1.max(c2) / c1.min(c2) - 1.0)).min(0.5);
    let f2 = 3.413 * (4.0 * g.area / (c1 * c2) - 0.7071).max(0.0);
    let f2 = 0.78 + 0.22 * f2 * f2 * f2;
    let hs = (x[1] * y[3] - y[1] * x[3])
        .abs()
        .max((x[0] * y[2] - y[0] * x[2]).abs())
        / g.area;
    let h = |i: usize, j: usize| 0.25 * ((x[i] - x[j]).powi(2) + (y[i] - y[j]).powi(2));
    let l2 = h(0, 2).max(h(1, 3));
    let l = g.area / (2.0 * f1 * f2 * (1.25 + hs) * l2).sqrt();
    l * ((1.0 + sec.dn * sec.dn).sqrt() - sec.dn)
}

/// The section's plastic state this step (eq. 14) from its points' plastic
/// strains before (`ep0`) and after the update: a point that yielded has
/// E_t/E = H/(H + E), H the slope of its flow-stress curve.
pub(super) fn plastic_state(
    sec: &ShellSection,
    law: &crate::material::PointLaw,
    ep0: &[f64],
    eps_p: &[f64],
) -> Plastic {
    let e = sec.material.young();
    let (mut avg, mut min, mut sig_y) = (0.0, 1.0f64, 0.0);
    for (k, (&a, &b)) in ep0.iter().zip(eps_p).enumerate() {
        let w = sec.w_mem[k];
        let sy = law.yield_stress(b);
        sig_y += w * sy;
        let phi = if b > a {
            let d = 1e-6 * b.max(1e-3);
            let h = ((law.yield_stress(b + d) - sy) / d).max(0.0);
            h / (h + e)
        } else {
            1.0
        };
        avg += w * phi;
        min = min.min(phi);
    }
    Plastic {
        phi_avg: avg,
        phi_min: min,
        sig_y,
    }
}
