//! 3-node C0 shell triangle (Radioss /SH3N with /PROP/SHELL Ish3n = 1 or 2).
//!
//! # Formulation
//! * **Element** (reference guide /PROP/SHELL: Ish3n = 1 "standard triangle
//!   (C0)", 2 "standard triangle (C0) with modification for large rotation",
//!   the default; theory manual "3-node shell elements"): constant-strain
//!   membrane and a Mindlin plate with linear rotations, one in-plane point,
//!   corotational local frame. Both Ish3n values are computed by this one
//!   corotational kernel (large rotations are carried by the frame);
//!   Ish3n = 30 (DKT18) and 31 (DKT_S3) are refused by [`check_ish3n`].
//! * **Local frame** (reference engine C3EVEC3/C3DERI3): e1 along the edge
//!   1→2, e3 = x₂₁ × x₃₁ normalised, e2 = e3 × e1; coordinates relative to the
//!   centroid. Gradient vectors b_x,i = (y_j − y_k)/(2A), b_y,i = (x_k − x_j)/(2A),
//!   (i, j, k) cyclic.
//! * **Rates** (as in `shell4`, on the mid-step geometry x^{n+½} = x^{n+1} − ½Δt v):
//!   membrane d = (Σb_x v_x, Σb_y v_y, Σ(b_y v_x + b_x v_y)), curvature
//!   κ = (Σb_x θ_y, −Σb_y θ_x, Σ(b_y θ_y − b_x θ_x)), transverse shear
//!   γ_xz = Σb_x v_z + Σ(c_i θ_x,i + d_i θ_y,i), γ_yz likewise, with the
//!   reference's node-specific weights ([`ShearWeights`]: no shear for any
//!   constant-curvature Kirchhoff state, so no shear locking; a uniform
//!   rotation gives ±θ as the centroid rotation ⅓Σθ did).
//! * **Through the thickness**: the quad's rule ([`ShellSection`]: N points,
//!   trapezoidal membrane weights, exact bending weights for a piecewise-linear
//!   stress; N = 0 as the quad, global integration with Ilyushin's resultant
//!   yield condition or N = 3 for LAW2, see `shell4::n0_rule`), the quad's
//!   in-plane update of the points (`shell4::update_slots`); transverse shear
//!   elastic (k G); Ithick = 1 updates the thickness.
//! * **Corner forces** (internal, power-conjugate, at x^{n+1}; the solver does
//!   M a = f_ext − f): f_x = A(b_x N_xx + b_y N_xy), f_y = A(b_y N_yy + b_x N_xy),
//!   f_z = A(b_x Q_x + b_y Q_y), m_x = −A(b_y M_yy + b_x M_xy) + A(c_zx Q_x + c_yz Q_y),
//!   m_y = A(b_x M_xx + b_y M_xy) + A(d_zx Q_x + d_yz Q_y) (the shear weights'
//!   transpose), m_z = 0 (no drilling stiffness).
//!   No hourglass modes.
//! * **Time step** (reference engine C3DERI3: ALDT = 2A / max edge, the smallest
//!   height): Δt = (2A / l_max) / √(E/ρ₀), unscaled, the same wave speed as the quad.
//! * **Energy**: d_eint = ½AΔt[(N^n + N^{n+1}):d + (M^n + M^{n+1}):κ + (Q^n + Q^{n+1})·γ],
//!   the work of the corner forces (resultants of the point stresses with the
//!   membrane and bending weights), so that it closes the energy balance in
//!   bending too; plastic work Σ w_N Δw_p A t.
//! * **Strain rate** for Johnson-Cook and **failure** as in `shell4`.
//!
//! No heap allocation: everything is fixed-size on the stack.

use super::shell4::{shell4_resultants, update_slots, ShellSection};
use crate::material::{FailAt, Material};
use crate::model::ResolvedShell;

/// Refuses the 3-node formulations this kernel does not compute.
pub fn check_ish3n(r: &ResolvedShell) -> Result<(), String> {
    match r.ish3n {
        1 | 2 => Ok(()),
        30 => Err("Ish3n = 30 (DKT18) is not supported: the engine computes the C0 triangle (Ish3n = 1, 2)".into()),
        31 => Err("Ish3n = 31 (DKT_S3) is not supported: the engine computes the C0 triangle (Ish3n = 1, 2)".into()),
        v => Err(format!("Ish3n = {v}: expected 1 or 2 (C0 triangle)")),
    }
}

/// Section of a triangle part: Ish3n checked, then the quad's section with
/// Ishell taken as 1 (the 4-node formulation and its hourglass coefficients do
/// not apply to triangles, so a QEPH/QBAT part can still hold triangles).
pub fn shell3_section(r: &ResolvedShell, m: &Material) -> Result<ShellSection, String> {
    check_ish3n(r)?;
    if m.brittle().is_some() {
        return Err(
            "/MAT/LAW27: its cracking on the total strain is not computed on 3-node shells yet"
                .into(),
        );
    }
    if m.tension_damage().is_some() {
        return Err("/MAT/LAW36: the tension damage (Eps_t, Eps_m, Eps_f) is not computed on 3-node shells yet".into());
    }
    let mut q = r.clone();
    q.ishell = 1;
    ShellSection::new(&q, m)
}

/// Per-element state kept by the solver (small, `Copy`). Per point the solver
/// keeps `[σxx, σyy, σxy, σyz, σzx]` (local frame) and ε_p, as for the quad.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Shell3State {
    /// Current thickness.
    pub thick: f64,
    /// Initial area.
    pub area0: f64,
    /// Cumulative internal energy (elastic + plastic).
    pub eint: f64,
    /// Cumulative plastic work.
    pub eplas: f64,
    /// Filtered equivalent strain rate (Johnson-Cook rate term).
    pub eps_dot: f64,
    /// All points have failed: the element is deleted.
    pub deleted: bool,
    /// Initial characteristic (time-step) length, for a failure model's
    /// element-size factor.
    pub len0: f64,
}

/// What one element step returns.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Shell3Out {
    /// Internal corner forces (global frame); the solver subtracts them.
    pub f: [[f64; 3]; 3],
    /// Internal corner moments (global frame).
    pub m: [[f64; 3]; 3],
    /// Critical (unscaled) time step; ∞ for a deleted or degenerate element.
    pub dt: f64,
    /// Internal energy increment (elastic + plastic).
    pub d_eint: f64,
    /// Plastic work increment (included in `d_eint`).
    pub d_eplas: f64,
    /// The element is deleted (all its points failed).
    pub failed: bool,
    /// Zero area, or the element turned over during the step: the solver stops.
    pub bad_area: bool,
}

use crate::vec3::{cross, dot, sub};
#[inline]
fn dot3(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The nodal rotations' weights in the transverse shears (reference engine
/// C3CURV3 / C3FINT3; research note `docs/notes/shell3_c0_research.md`,
/// difference 1): γ_zx = Σb_x v_z + Σ(zx[0]_i θx_i + zx[1]_i θy_i), γ_yz
/// likewise; the corner moments take the transpose. Each row sums to the
/// uniform rotation's ±1 (as ⅓Σθ), and every constant-curvature Kirchhoff
/// state (w quadratic, θ = ∇w) gives γ = 0 on any triangle: no shear
/// locking (the centroid rotation ⅓Σθ locks: the QA plate COQUES3N bent
/// about 45 % too stiff).
struct ShearWeights {
    zx: [[f64; 3]; 2],
    yz: [[f64; 3]; 2],
}

/// [`ShearWeights`] in the element frame: x2 = x₂ − x₁ (e1 runs along 1→2),
/// (x3, y3) = node 3 − node 1.
fn shear_weights(g: &Geom) -> ShearWeights {
    let x2 = g.x[1] - g.x[0];
    let (x3, y3) = (g.x[2] - g.x[0], g.y[2] - g.y[0]);
    let (a, b) = (6.0 * x2, 6.0 * x2 * y3);
    ShearWeights {
        zx: [
            [-y3 / a, y3 / a, 0.0],
            [(2.0 * x2 + x3) / a, (3.0 * x2 - x3) / a, 1.0 / 6.0],
        ],
        yz: [
            [-(2.0 * x2 - x3) / a, -(x2 + x3) / a, -0.5],
            [
                (x2 * x2 - x3 * x3) / b,
                -x3 * (2.0 * x2 - x3) / b,
                -(x2 - 2.0 * x3) / (6.0 * y3),
            ],
        ],
    }
}

/// Corotational geometry of one configuration.
#[derive(Clone, Copy, Debug)]
struct Geom {
    /// Rows e1, e2, e3.
    e: [[f64; 3]; 3],
    x: [f64; 3],
    y: [f64; 3],
    area: f64,
    bx: [f64; 3],
    by: [f64; 3],
}

impl Geom {
    #[inline]
    fn new(p: &[[f64; 3]; 3]) -> Option<Geom> {
        let x21 = sub(p[1], p[0]);
        let x31 = sub(p[2], p[0]);
        let n = cross(x21, x31);
        let nn = dot(n, n).sqrt();
        let l21 = dot(x21, x21).sqrt();
        // NaN-safe: a non-finite or vanishing area is refused.
        if !(nn > 1e-12 * (dot(x21, x21) + dot(x31, x31))) || !(l21 > 0.0) {
            return None;
        }
        let e3 = [n[0] / nn, n[1] / nn, n[2] / nn];
        let e1 = [x21[0] / l21, x21[1] / l21, x21[2] / l21];
        let e2 = cross(e3, e1);
        let c = [
            (p[0][0] + p[1][0] + p[2][0]) / 3.0,
            (p[0][1] + p[1][1] + p[2][1]) / 3.0,
            (p[0][2] + p[1][2] + p[2][2]) / 3.0,
        ];
        let mut x = [0.0; 3];
        let mut y = [0.0; 3];
        for i in 0..3 {
            let r = sub(p[i], c);
            x[i] = dot(e1, r);
            y[i] = dot(e2, r);
        }
        let a2 = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
        if !(a2 > 0.0) {
            return None;
        }
        let r = 1.0 / a2;
        let bx = [(y[1] - y[2]) * r, (y[2] - y[0]) * r, (y[0] - y[1]) * r];
        let by = [(x[2] - x[1]) * r, (x[0] - x[2]) * r, (x[1] - x[0]) * r];
        Some(Geom {
            e: [e1, e2, e3],
            x,
            y,
            area: 0.5 * a2,
            bx,
            by,
        })
    }

    #[inline]
    fn to_local(&self, v: [f64; 3]) -> [f64; 3] {
        [dot(self.e[0], v), dot(self.e[1], v), dot(self.e[2], v)]
    }

    #[inline]
    fn to_global(&self, l: [f64; 3]) -> [f64; 3] {
        let e = &self.e;
        [
            e[0][0] * l[0] + e[1][0] * l[1] + e[2][0] * l[2],
            e[0][1] * l[0] + e[1][1] * l[1] + e[2][1] * l[2],
            e[0][2] * l[0] + e[1][2] * l[1] + e[2][2] * l[2],
        ]
    }

    /// Smallest height 2A / max edge (reference engine C3DERI3).
    #[inline]
    fn char_length(&self) -> f64 {
        let d2 = |i: usize, j: usize| {
            let (dx, dy) = (self.x[j] - self.x[i], self.y[j] - self.y[i]);
            dx * dx + dy * dy
        };
        2.0 * self.area / d2(0, 1).max(d2(1, 2)).max(d2(2, 0)).sqrt()
    }
}

/// Element state at t = 0.
pub fn shell3_init(_sec: &ShellSection, x: &[[f64; 3]; 3], thick: f64) -> Shell3State {
    let n = cross(sub(x[1], x[0]), sub(x[2], x[0]));
    Shell3State {
        thick,
        area0: 0.5 * dot(n, n).sqrt(),
        len0: Geom::new(x).map_or(0.0, |g| g.char_length()),
        ..Default::default()
    }
}

/// One explicit step of one triangle: stresses from x^{n+1} and v^{n+½},
/// internal corner forces and moments at x^{n+1}, energies, and the time step.
///
/// `x`: positions at t^{n+1}; `v`: translational velocities v^{n+½}; `vr`:
/// rotational velocities (global frame); `sig`, `eps_p`: this element's `n_ip`
/// points. With `dt = 0` only forces and the time step are computed.
#[allow(clippy::too_many_arguments)]
pub fn shell3_step(
    sec: &ShellSection,
    x: &[[f64; 3]; 3],
    v: &[[f64; 3]; 3],
    vr: &[[f64; 3]; 3],
    dt: f64,
    st: &mut Shell3State,
    sig: &mut [[f64; 5]],
    eps_p: &mut [f64],
    dmg: &mut [super::shell4::PointHistory],
) -> Shell3Out {
    let mut out = Shell3Out {
        dt: f64::INFINITY,
        ..Default::default()
    };
    if st.deleted {
        out.failed = true;
        return out;
    }
    let n_ip = sec.n_ip;
    debug_assert!(sig.len() >= n_ip && eps_p.len() >= n_ip);
    let mat = &sec.material;

    // ---- geometry at x^{n+1} (forces) and x^{n+1/2} (rates) ------------------
    let Some(ge) = Geom::new(x) else {
        out.bad_area = true;
        return out;
    };
    out.dt = ge.char_length() / mat.sound_speed();
    let gm = if dt > 0.0 {
        let mut xm = *x;
        for i in 0..3 {
            for k in 0..3 {
                xm[i][k] -= 0.5 * dt * v[i][k];
            }
        }
        match Geom::new(&xm) {
            Some(g) => g,
            None => {
                out.bad_area = true;
                return out;
            }
        }
    } else {
        ge
    };
    if dot(gm.e[2], ge.e[2]) <= 0.0 {
        out.bad_area = true;
        return out;
    }

    // ---- local velocities and generalized strain rates (mid-step) -----------
    let mut vx = [0.0; 3];
    let mut vy = [0.0; 3];
    let mut vz = [0.0; 3];
    let mut wx = [0.0; 3];
    let mut wy = [0.0; 3];
    for i in 0..3 {
        let l = gm.to_local(v[i]);
        vx[i] = l[0];
        vy[i] = l[1];
        vz[i] = l[2];
        let r = gm.to_local(vr[i]);
        wx[i] = r[0];
        wy[i] = r[1];
    }
    let (bx, by) = (&gm.bx, &gm.by);
    let dxx = dot3(bx, &vx);
    let dyy = dot3(by, &vy);
    let gxy = dot3(by, &vx) + dot3(bx, &vy);
    let kxx = dot3(bx, &wy);
    let kyy = -dot3(by, &wx);
    let kxy = dot3(by, &wy) - dot3(bx, &wx);
    let sw = shear_weights(&gm);
    let gxz = dot3(bx, &vz) + dot3(&sw.zx[0], &wx) + dot3(&sw.zx[1], &wy);
    let gyz = dot3(by, &vz) + dot3(&sw.yz[0], &wx) + dot3(&sw.yz[1], &wy);

    let t = st.thick;
    if dt > 0.0 {
        let em = dxx * dxx + dyy * dyy + dxx * dyy + 0.25 * gxy * gxy;
        let ek = kxx * kxx + kyy * kyy + kxx * kyy + 0.25 * kxy * kxy;
        let raw = (4.0 / 3.0 * em + t * t / 9.0 * ek).sqrt();
        st.eps_dot = mat.filter_strain_rate(st.eps_dot, raw, dt);
    }

    // ---- stress update at the points ------------------------------------------
    let vol = gm.area * t;
    let temp = mat.temperature(st.eint / vol);
    let gs = mat.shear_modulus() * sec.ashear;
    let (dgyz, dgzx) = (gyz * dt, gxz * dt);
    let (dwp, dezz, deleted);
    if dt > 0.0 {
        let (n0, m0, q0) = shell4_resultants(sec, t, sig);
        for s in sig[..n_ip].iter_mut() {
            s[3] += gs * dgyz;
            s[4] += gs * dgzx;
        }
        let law = mat.at(st.eps_dot, temp);
        let at = FailAt {
            rate: st.eps_dot,
            len0: st.len0,
            tstar: mat.homologous_temperature(temp),
        };
        (dwp, dezz, deleted) = update_slots(
            sec,
            &law,
            t,
            &mut sig[..n_ip],
            &mut eps_p[..n_ip],
            &mut dmg[..n_ip],
            &at,
            [dxx, dyy, gxy],
            [kxx, kyy, kxy],
            dt,
            None,
        );
        // Work of the mean resultants on the generalized strain increments:
        // the power of the corner forces, A(N:d + M:κ + Q·γ).
        let (n1, m1, q1) = shell4_resultants(sec, t, sig);
        let h = 0.5 * gm.area * dt;
        out.d_eint = h
            * ((n0[0] + n1[0]) * dxx
                + (n0[1] + n1[1]) * dyy
                + (n0[2] + n1[2]) * gxy
                + (m0[0] + m1[0]) * kxx
                + (m0[1] + m1[1]) * kyy
                + (m0[2] + m1[2]) * kxy
                + (q0[0] + q1[0]) * gxz
                + (q0[1] + q1[1]) * gyz);
    } else {
        (dwp, dezz) = (0.0, 0.0);
        let nfailed = (0..n_ip).filter(|&k| mat.has_failed(eps_p[k])).count();
        deleted = nfailed == n_ip || (nfailed > 0 && mat.deletes_at_first_failed_point());
    }
    out.d_eplas = dwp * vol;
    st.eint += out.d_eint;
    st.eplas += out.d_eplas;
    if deleted {
        st.deleted = true;
        out.failed = true;
        return out;
    }

    // ---- resultants and corner forces at x^{n+1} -----------------------------
    let (nr, mr, q) = shell4_resultants(sec, t, sig);
    let a = ge.area;
    let sw = shear_weights(&ge);
    for i in 0..3 {
        let (bxi, byi) = (ge.bx[i], ge.by[i]);
        let fl = [
            a * (bxi * nr[0] + byi * nr[2]),
            a * (byi * nr[1] + bxi * nr[2]),
            a * (bxi * q[0] + byi * q[1]),
        ];
        let ml = [
            -a * (byi * mr[1] + bxi * mr[2]) + a * (sw.zx[0][i] * q[0] + sw.yz[0][i] * q[1]),
            a * (bxi * mr[0] + byi * mr[2]) + a * (sw.zx[1][i] * q[0] + sw.yz[1][i] * q[1]),
            0.0,
        ];
        out.f[i] = ge.to_global(fl);
        out.m[i] = ge.to_global(ml);
    }

    // ---- thickness ---------------------------------------------------------------
    if sec.ithick == 1 && dt > 0.0 {
        st.thick = t * (1.0 + dezz);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every constant-curvature Kirchhoff state w = a x² + b xy + c y²,
    /// θx = ∂w/∂y, θy = −∂w/∂x (crashsim's sign: γ_zx = ∂w/∂x + θy), gives
    /// no transverse shear on a skewed triangle; a uniform rotation gives
    /// γ = ±θ.
    #[test]
    fn kirchhoff_bending_makes_no_transverse_shear() {
        let g = Geom::new(&[[0.3, -0.2, 0.1], [2.1, 0.4, -0.3], [0.7, 1.9, 0.5]]).unwrap();
        let sw = shear_weights(&g);
        let shear = |vz: [f64; 3], wx: [f64; 3], wy: [f64; 3]| {
            (
                dot3(&g.bx, &vz) + dot3(&sw.zx[0], &wx) + dot3(&sw.zx[1], &wy),
                dot3(&g.by, &vz) + dot3(&sw.yz[0], &wx) + dot3(&sw.yz[1], &wy),
            )
        };
        for (a, b, c) in [
            (1.0, 0.0, 0.0),
            (0.0, 1.0, 0.0),
            (0.0, 0.0, 1.0),
            (0.3, -0.7, 1.1),
        ] {
            let w = |i: usize| a * g.x[i] * g.x[i] + b * g.x[i] * g.y[i] + c * g.y[i] * g.y[i];
            let vz = [w(0), w(1), w(2)];
            let wx: [f64; 3] = std::array::from_fn(|i| b * g.x[i] + 2.0 * c * g.y[i]);
            let wy: [f64; 3] = std::array::from_fn(|i| -(2.0 * a * g.x[i] + b * g.y[i]));
            let (zx, yz) = shear(vz, wx, wy);
            assert!(
                zx.abs() < 1e-13 && yz.abs() < 1e-13,
                "{a} {b} {c}: {zx} {yz}"
            );
        }
        let (zx, yz) = shear([0.0; 3], [0.0; 3], [1.0; 3]);
        assert!((zx - 1.0).abs() < 1e-14 && yz.abs() < 1e-14);
        let (zx, yz) = shear([0.0; 3], [1.0; 3], [0.0; 3]);
        assert!(zx.abs() < 1e-14 && (yz + 1.0).abs() < 1e-14);
    }

    fn mat() -> Material {
        let (e, nu) = (210.0, 0.3);
        Material::Elastic(crate::material::Law1(crate::material::ElasticConstants {
            rho: 7.8e-6,
            rho_ref: 7.8e-6,
            e,
            nu,
            g: e / (2.0 * (1.0 + nu)),
        }))
    }

    fn resolved(n: i64, ish3n: i64) -> ResolvedShell {
        ResolvedShell {
            ishell: 24,
            ismstr: 2,
            ish3n,
            idrill: 2,
            hm: 0.01,
            hf: 0.01,
            hr: 0.01,
            dm: 0.0,
            dn: 0.0,
            n,
            istrain: 1,
            thick: 1.5,
            ashear: 5.0 / 6.0,
            ithick: 0,
            iplas: 0,
            p_thick_fail: 0.0,
        }
    }

    fn section(n: i64) -> ShellSection {
        shell3_section(&resolved(n, 2), &mat()).unwrap()
    }

    struct El {
        st: Shell3State,
        sig: [[f64; 5]; 10],
        ep: [f64; 10],
        dmg: [[f64; 3]; 10],
    }

    impl El {
        fn new(sec: &ShellSection, x: &[[f64; 3]; 3], t: f64) -> El {
            El {
                st: shell3_init(sec, x, t),
                sig: [[0.0; 5]; 10],
                ep: [0.0; 10],
                dmg: [[0.0; 3]; 10],
            }
        }
        fn step(
            &mut self,
            sec: &ShellSection,
            x: &[[f64; 3]; 3],
            v: &[[f64; 3]; 3],
            vr: &[[f64; 3]; 3],
            dt: f64,
        ) -> Shell3Out {
            let (st, sig, ep, dmg) = (&mut self.st, &mut self.sig, &mut self.ep, &mut self.dmg);
            shell3_step(sec, x, v, vr, dt, st, sig, ep, dmg)
        }
    }

    fn rotation(u: [f64; 3], ang: f64) -> [[f64; 3]; 3] {
        let n = dot(u, u).sqrt();
        let u = [u[0] / n, u[1] / n, u[2] / n];
        let (s, c) = ang.sin_cos();
        let k = 1.0 - c;
        [
            [
                c + u[0] * u[0] * k,
                u[0] * u[1] * k - u[2] * s,
                u[0] * u[2] * k + u[1] * s,
            ],
            [
                u[1] * u[0] * k + u[2] * s,
                c + u[1] * u[1] * k,
                u[1] * u[2] * k - u[0] * s,
            ],
            [
                u[2] * u[0] * k - u[1] * s,
                u[2] * u[1] * k + u[0] * s,
                c + u[2] * u[2] * k,
            ],
        ]
    }

    fn maxabs(f: &[[f64; 3]]) -> f64 {
        f.iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()))
    }

    fn tri() -> [[f64; 3]; 3] {
        [[0.2, -0.1, 0.3], [4.1, 0.5, -0.4], [1.3, 3.2, 0.6]]
    }

    #[test]
    fn rigid_motion_gives_no_force() {
        let sec = section(3);
        let x0 = tri();
        // Translation.
        let mut el = El::new(&sec, &x0, 1.5);
        let v = [[1.0, -2.0, 0.5]; 3];
        let mut x = x0;
        for _ in 0..5 {
            for i in 0..3 {
                for k in 0..3 {
                    x[i][k] += 1e-3 * v[i][k];
                }
            }
            let o = el.step(&sec, &x, &v, &[[0.0; 3]; 3], 1e-3);
            assert!(maxabs(&o.f) < 1e-12 && maxabs(&o.m) < 1e-12 && o.d_eint.abs() < 1e-15);
        }
        // Finite rotation θ about u, nodal rotation rate = the Cayley rate
        // 2 tan(θ/2)/Δt (the rate the mid-step geometry sees).
        let (u, th, dt) = ([0.3, -0.5, 0.8], 0.25, 1e-2);
        let r = rotation(u, th);
        let nu = dot(u, u).sqrt();
        let w = 2.0 * (0.5 * th).tan() / dt / nu;
        let vr = [[u[0] * w, u[1] * w, u[2] * w]; 3];
        let mut x1 = [[0.0; 3]; 3];
        let mut v = [[0.0; 3]; 3];
        for i in 0..3 {
            x1[i] = [
                dot(r[0], x0[i]) + 0.3,
                dot(r[1], x0[i]),
                dot(r[2], x0[i]) - 0.2,
            ];
            for k in 0..3 {
                v[i][k] = (x1[i][k] - x0[i][k]) / dt;
            }
        }
        let mut el = El::new(&sec, &x0, 1.5);
        let o = el.step(&sec, &x1, &v, &vr, dt);
        assert!(
            maxabs(&o.f) < 1e-11 && maxabs(&o.m) < 1e-11,
            "{:?} {:?}",
            o.f,
            o.m
        );
        assert!(el.sig[..3].iter().flatten().all(|s| s.abs() < 1e-12));
    }

    #[test]
    fn uniform_membrane_stretch_is_exact() {
        let sec = section(3);
        let m = &sec.material;
        let (e, nu, g) = (m.young(), m.poisson(), m.shear_modulus());
        let x0 = [[0.0, 0.0, 0.0], [3.0, 0.0, 0.0], [1.0, 2.0, 0.0]];
        // v = G x (x^{n+1}) with v_y = 0 on the edge 1-2, so e1 stays on the x-axis.
        let gm = [[0.4, 0.15], [0.0, -0.25]];
        let dt = 1e-3;
        // Solve x1 = x0 + dt G x1 → x1 = (I − dt G)⁻¹ x0.
        let a = [
            [1.0 - dt * gm[0][0], -dt * gm[0][1]],
            [-dt * gm[1][0], 1.0 - dt * gm[1][1]],
        ];
        let det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
        let mut x1 = [[0.0; 3]; 3];
        let mut v = [[0.0; 3]; 3];
        for i in 0..3 {
            let (px, py) = (x0[i][0], x0[i][1]);
            x1[i] = [
                (a[1][1] * px - a[0][1] * py) / det,
                (-a[1][0] * px + a[0][0] * py) / det,
                0.0,
            ];
            v[i] = [
                gm[0][0] * x1[i][0] + gm[0][1] * x1[i][1],
                gm[1][0] * x1[i][0] + gm[1][1] * x1[i][1],
                0.0,
            ];
        }
        let mut el = El::new(&sec, &x0, 1.5);
        let o = el.step(&sec, &x1, &v, &[[0.0; 3]; 3], dt);
        // L = G (I − ½Δt G)⁻¹ on the mid-step geometry.
        let b = [
            [1.0 - 0.5 * dt * gm[0][0], -0.5 * dt * gm[0][1]],
            [-0.5 * dt * gm[1][0], 1.0 - 0.5 * dt * gm[1][1]],
        ];
        let db = b[0][0] * b[1][1] - b[0][1] * b[1][0];
        let bi = [[b[1][1] / db, -b[0][1] / db], [-b[1][0] / db, b[0][0] / db]];
        let l = |i: usize, j: usize| gm[i][0] * bi[0][j] + gm[i][1] * bi[1][j];
        let (exx, eyy, gxy) = (l(0, 0) * dt, l(1, 1) * dt, (l(0, 1) + l(1, 0)) * dt);
        let a11 = e / (1.0 - nu * nu);
        let want = [a11 * (exx + nu * eyy), a11 * (nu * exx + eyy), g * gxy];
        for k in 0..3 {
            for c in 0..3 {
                assert!(
                    (el.sig[k][c] - want[c]).abs() < 1e-9 * want[0].abs(),
                    "{:?} vs {want:?}",
                    el.sig[k]
                );
            }
        }
        // Forces: f = A t (b_x σxx + b_y σxy, b_y σyy + b_x σxy).
        let ge = Geom::new(&x1).unwrap();
        let t = 1.5;
        for i in 0..3 {
            let fx = ge.area * t * (ge.bx[i] * want[0] + ge.by[i] * want[2]);
            let fy = ge.area * t * (ge.by[i] * want[1] + ge.bx[i] * want[2]);
            assert!((o.f[i][0] - fx).abs() < 1e-9 * fx.abs().max(1e-3));
            assert!((o.f[i][1] - fy).abs() < 1e-9 * fy.abs().max(1e-3));
            assert!(o.f[i][2].abs() < 1e-15 && maxabs(&o.m) < 1e-15);
        }
    }

    /// Patch test: 4 triangles around a free, off-centre interior node under
    /// v = G·x for one small step: Hooke's plane-stress energy over the
    /// patch (within 1e-6) and no force on the interior node (1e-6 of the
    /// largest).
    #[test]
    fn a_patch_of_triangles_passes_the_patch_test() {
        let sec = section(3);
        let m = &sec.material;
        let (e, nu, g) = (m.young(), m.poisson(), m.shear_modulus());
        let x0 = [
            [0.0, 0.0, 0.0],
            [4.0, 0.3, 0.0],
            [4.3, 3.7, 0.0],
            [-0.2, 4.1, 0.0],
            [2.6, 1.7, 0.0],
        ];
        let tris = [[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]];
        let gm = [[0.4, 0.15], [-0.1, -0.25]];
        let (dt, t) = (1e-6, 1.5);
        let v: Vec<[f64; 3]> = x0
            .iter()
            .map(|p| {
                let w = |i: usize| gm[i][0] * p[0] + gm[i][1] * p[1];
                [w(0), w(1), 0.0]
            })
            .collect();
        let (mut f, mut energy, mut area) = ([[0.0; 3]; 5], 0.0, 0.0);
        for tri in tris {
            let xe = tri.map(|n| x0[n]);
            let xn = tri.map(|n| std::array::from_fn(|k| x0[n][k] + dt * v[n][k]));
            let mut el = El::new(&sec, &xe, t);
            let o = el.step(&sec, &xn, &tri.map(|n| v[n]), &[[0.0; 3]; 3], dt);
            energy += o.d_eint;
            area += Geom::new(&xe).unwrap().area;
            for (a, &n) in tri.iter().enumerate() {
                for k in 0..3 {
                    f[n][k] += o.f[a][k];
                }
            }
        }
        let (exx, eyy, gxy) = (gm[0][0] * dt, gm[1][1] * dt, (gm[0][1] + gm[1][0]) * dt);
        let a11 = e / (1.0 - nu * nu);
        let want =
            0.5 * (a11 * (exx * exx + eyy * eyy + 2.0 * nu * exx * eyy) + g * gxy * gxy) * area * t;
        assert!((energy - want).abs() < 1e-6 * want, "{energy} vs {want}");
        let fmax = f.iter().flatten().fold(0.0f64, |a, b| a.max(b.abs()));
        assert!(
            f[4].iter().all(|c| c.abs() < 1e-6 * fmax),
            "interior {:?} (max {fmax})",
            f[4]
        );
    }

    #[test]
    fn pure_bending_gives_d_kappa() {
        for n in [3, 5] {
            let sec = section(n);
            let m = &sec.material;
            let (e, nu) = (m.young(), m.poisson());
            let t = 1.5;
            // Centroid at the origin; the Kirchhoff state w = −½κ̇x², θ_y = κ̇ x
            // gives κ_xx = κ̇ and no shear.
            let x = [[-1.0, -1.0, 0.0], [2.0, -1.0, 0.0], [-1.0, 2.0, 0.0]];
            let kd = 0.01;
            let vr = [
                [0.0, kd * x[0][0], 0.0],
                [0.0, kd * x[1][0], 0.0],
                [0.0, kd * x[2][0], 0.0],
            ];
            let v: [[f64; 3]; 3] =
                std::array::from_fn(|i| [0.0, 0.0, -0.5 * kd * x[i][0] * x[i][0]]);
            let dt = 1e-3;
            let mut el = El::new(&sec, &x, t);
            let o = el.step(&sec, &x, &v, &vr, dt);
            let (nr, mr, q) = shell4_resultants(&sec, t, &el.sig);
            let d = e * t * t * t / (12.0 * (1.0 - nu * nu));
            let dk = kd * dt;
            assert!(
                (mr[0] - d * dk).abs() < 0.03 * d * dk,
                "N = {n}: M = {} vs D κ = {}",
                mr[0],
                d * dk
            );
            // The mid-step shape tilts by ½Δt·v_z: 1e-10 of D κ elsewhere.
            let small = 1e-9 * d * dk;
            assert!((mr[0] - d * dk).abs() < small);
            assert!((mr[1] - nu * d * dk).abs() < small);
            // The deflection's second-order membrane strain ½(∂w/∂x)² only.
            assert!(nr.iter().all(|v| v.abs() < 1e-5 * e * t * dk), "{nr:?}");
            assert!(q.iter().all(|v| v.abs() < small), "{q:?}");
            // Corner moments m_y = A b_x M_xx, m_x = −A b_y M_yy; no forces.
            let ge = Geom::new(&x).unwrap();
            for i in 0..3 {
                assert!((o.m[i][1] - ge.area * ge.bx[i] * mr[0]).abs() < small);
                assert!((o.m[i][0] + ge.area * ge.by[i] * mr[1]).abs() < small);
            }
            // Forces: the membrane resultant's, of the same second order.
            assert!(maxabs(&o.f) < 1e-5 * e * t * dk * ge.area, "{:?}", o.f);
            // Energy ½ M κ A.
            assert!(
                (o.d_eint - 0.5 * (mr[0] * dk + mr[1] * 0.0) * ge.area).abs() < 1e-9 * o.d_eint
            );
        }
    }

    #[test]
    fn forces_and_moments_are_in_equilibrium() {
        let sec = section(5);
        let mut x = tri();
        let mut el = El::new(&sec, &x, 1.5);
        let v = [[0.3, -0.2, 0.5], [-0.4, 0.1, -0.2], [0.2, 0.3, 0.1]];
        let vr = [[0.05, -0.02, 0.1], [-0.03, 0.04, 0.0], [0.02, 0.01, -0.05]];
        for _ in 0..20 {
            for i in 0..3 {
                for k in 0..3 {
                    x[i][k] += 1e-2 * v[i][k];
                }
            }
            let o = el.step(&sec, &x, &v, &vr, 1e-2);
            let fm = maxabs(&o.f).max(maxabs(&o.m));
            assert!(fm > 0.0);
            let mut sf = [0.0; 3];
            let mut mo = [0.0; 3];
            for i in 0..3 {
                let c = cross(x[i], o.f[i]);
                for k in 0..3 {
                    sf[k] += o.f[i][k];
                    mo[k] += c[k] + o.m[i][k];
                }
            }
            assert!(
                maxabs(&[sf]) < 1e-12 * fm && maxabs(&[mo]) < 1e-11 * fm,
                "{sf:?} {mo:?}"
            );
        }
    }

    #[test]
    fn time_step_is_the_smallest_height() {
        let sec = section(3);
        let x = [[0.0, 0.0, 0.0], [3.0, 0.0, 0.0], [0.0, 4.0, 0.0]];
        let mut el = El::new(&sec, &x, 1.5);
        let o = el.step(&sec, &x, &[[0.0; 3]; 3], &[[0.0; 3]; 3], 0.0);
        let want = 2.4 / sec.material.sound_speed();
        assert!((o.dt - want).abs() < 1e-14 * want);
    }

    /// Johnson-Cook (BOX1BL's LAW2 without rate term), hardening `b`.
    fn jc(b: f64) -> Material {
        use crate::model::{JohnsonCook, Loc, MaterialLaw, MaterialSpec};
        Material::from_card(&MaterialSpec {
            id: 1,
            unit_id: 0,
            title: "t".into(),
            rho: 7.8e-6,
            rho_ref: 0.0,
            e: 210.0,
            nu: 0.3,
            law: MaterialLaw::JohnsonCook(JohnsonCook::hardening(0.25, b, 0.52)),
            failures: vec![],
            loc: Loc::default(),
        })
    }

    /// N = 0 of an elastic part is global integration, and equals N = 5 to
    /// round-off under arbitrary motion (forces, moments, energy, time step,
    /// thickness with Ithick = 1); a LAW2 part gets N = 3 points.
    #[test]
    fn n0_elastic_equals_n5() {
        let mut r = resolved(0, 2);
        r.ithick = 1;
        let g0 = shell3_section(&r, &mat()).unwrap();
        assert!(g0.global && g0.n_ip == 2);
        r.n = 5;
        let g5 = shell3_section(&r, &mat()).unwrap();
        let j = shell3_section(&resolved(0, 2), &jc(0.3)).unwrap();
        assert!(!j.global && j.n_ip == 3);
        let mut x = tri();
        let (mut e0, mut e5) = (El::new(&g0, &x, 1.5), El::new(&g5, &x, 1.5));
        let v = [[0.3, -0.2, 0.5], [-0.4, 0.1, -0.2], [0.2, 0.3, 0.1]];
        let vr = [[0.05, -0.02, 0.1], [-0.03, 0.04, 0.0], [0.02, 0.01, -0.05]];
        for _ in 0..10 {
            for i in 0..3 {
                for k in 0..3 {
                    x[i][k] += 1e-2 * v[i][k];
                }
            }
            let o0 = e0.step(&g0, &x, &v, &vr, 1e-2);
            let o5 = e5.step(&g5, &x, &v, &vr, 1e-2);
            let fs = maxabs(&o5.f).max(maxabs(&o5.m));
            assert!(fs > 0.0 && o0.dt == o5.dt);
            for i in 0..3 {
                for k in 0..3 {
                    assert!((o0.f[i][k] - o5.f[i][k]).abs() < 1e-11 * fs);
                    assert!((o0.m[i][k] - o5.m[i][k]).abs() < 1e-11 * fs);
                }
            }
        }
        assert!((e0.st.eint - e5.st.eint).abs() < 1e-10 * e5.st.eint.abs());
        assert!((e0.st.thick - e5.st.thick).abs() < 1e-14 && e0.st.thick != 1.5);
    }

    /// Global (Ilyushin) plasticity on the triangle: a uniaxial moment
    /// (κ_xx = κ̇, κ_yy = −νκ̇) of a perfectly plastic section reaches the fully
    /// plastic moment σ_y t²/4 to round-off, a membrane stretch returns onto
    /// σ_y(ε̄_p), and the plastic work is accumulated in the element.
    #[test]
    fn n0_global_plasticity() {
        let t = 1.5;
        let mut q = resolved(0, 2);
        q.ishell = 1;
        let m = jc(0.0);
        let sec = ShellSection::build(&q, &m, crate::element::shell4::N0Rule::Global).unwrap();
        let nu = m.poisson();
        let x = [[-1.0, -1.0, 0.0], [2.0, -1.0, 0.0], [-1.0, 2.0, 0.0]];
        let kd = 0.3;
        let vr: [[f64; 3]; 3] = std::array::from_fn(|i| [nu * kd * x[i][1], kd * x[i][0], 0.0]);
        let mut el = El::new(&sec, &x, t);
        for _ in 0..100 {
            el.step(&sec, &x, &[[0.0; 3]; 3], &vr, 1e-3);
        }
        let (nr, mr, _) = shell4_resultants(&sec, t, &el.sig);
        let m0 = 0.25 * t * t * 0.25;
        assert!(
            el.ep[0] > 0.0 && (mr[0] - m0).abs() < 1e-10 * m0,
            "{mr:?} vs {m0}"
        );
        assert!(mr[1].abs() < 1e-10 * m0 && nr.iter().all(|v| v.abs() < 1e-12));
        assert!(el.st.eplas > 0.0 && el.st.eint > el.st.eplas);
        // Membrane stretch with hardening.
        let m = jc(0.35);
        let sec = ShellSection::build(&q, &m, crate::element::shell4::N0Rule::Global).unwrap();
        let mut x = [[0.0, 0.0, 0.0], [3.0, 0.0, 0.0], [1.0, 2.0, 0.0]];
        let mut el = El::new(&sec, &x, t);
        let mut eplas = 0.0;
        for _ in 0..30 {
            let v: [[f64; 3]; 3] = std::array::from_fn(|i| [2.0 * x[i][0], 0.6 * x[i][1], 0.0]);
            for i in 0..3 {
                x[i][0] += 1e-3 * v[i][0];
                x[i][1] += 1e-3 * v[i][1];
            }
            eplas += el.step(&sec, &x, &v, &[[0.0; 3]; 3], 1e-3).d_eplas;
        }
        let s = el.sig[0];
        let svm = (s[0] * s[0] + s[1] * s[1] - s[0] * s[1] + 3.0 * s[2] * s[2]).sqrt();
        let y = m.yield_stress(el.ep[0], 0.0, 298.0);
        assert!(
            el.ep[0] > 0.01 && (svm - y).abs() < 1e-12 * y,
            "{svm} vs {y}"
        );
        assert_eq!(el.sig[0], el.sig[1]);
        assert!((eplas - el.st.eplas).abs() < 1e-12 * eplas && eplas > 0.0);
    }

    #[test]
    fn bad_area_and_refused_formulations() {
        let sec = section(3);
        let x = [[0.0, 0.0, 0.0], [3.0, 0.0, 0.0], [6.0, 0.0, 0.0]];
        let mut el = El::new(&sec, &x, 1.5);
        assert!(
            el.step(&sec, &x, &[[0.0; 3]; 3], &[[0.0; 3]; 3], 0.0)
                .bad_area
        );
        // Turned over during the step (node 3 through the edge 1-2).
        let x0 = [[0.0, 0.0, 0.0], [3.0, 0.0, 0.0], [1.0, 1.0, 0.0]];
        let x1 = [[0.0, 0.0, 0.0], [3.0, 0.0, 0.0], [1.0, -1.0, 0.0]];
        let dt = 0.1;
        let v = [[0.0; 3], [0.0; 3], [0.0, -2.0 / dt, 0.0]];
        let mut el = El::new(&sec, &x0, 1.5);
        assert!(el.step(&sec, &x1, &v, &[[0.0; 3]; 3], dt).bad_area);
        let e = shell3_section(&resolved(3, 30), &sec.material).unwrap_err();
        assert!(e.contains("Ish3n = 30"), "{e}");
        assert!(check_ish3n(&resolved(3, 31)).is_err());
        assert!(check_ish3n(&resolved(3, 1)).is_ok());
    }
}
