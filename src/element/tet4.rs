//! 4-node constant-strain tetrahedron (Radioss /TETRA4 with /PROP/SOLID,
//! Itetra4 = 0/1000: the standard element).
//!
//! # Formulation
//! * **Gradient**: b_a = ∂V/∂x_a = ∫ ∂N_a/∂x dV, exact for the linear
//!   tetrahedron: b₂ = ⅙ x₃₁ × x₄₁, b₃ = ⅙ x₄₁ × x₂₁, b₄ = ⅙ x₂₁ × x₃₁,
//!   b₁ = −(b₂ + b₃ + b₄); V = x₂₁·b₂ (positive for the right-hand ordering
//!   where node 4 lies on the side of x₂₁ × x₃₁, as Radioss /TETRA4).
//! * Everything else is the one-point solid of [`super::hex8`]: mid-step
//!   velocity gradient, Hughes-Winget (Jaumann) stress rotation, Ismstr 2/4
//!   rate form, `Material::solid_update_at`, bulk viscosity (reference engine
//!   MQVISCB), internal forces f_a = (σ − q I) b_a. No hourglass modes.
//! * **Time step**: l_c = 3V / A_max (the smallest height: the reference engine
//!   takes DELTAX = 6V/|2A|_max; the user guide "Solid Elements" gives
//!   L = a√(2/3) = 0.816a for a regular tetrahedron of edge a), then
//!   Δt = l_c / (Q + √(Q² + c²)), Q = qb c + l_c qa² ḋ, c = √((λ+2μ)/ρ₀). Unscaled.
//!
//! No heap allocation: everything is fixed-size on the stack.

use super::hex8::{
    cross, dot, solid_point_update, solid_time_step, stress_force, sub, velocity_gradient,
    SolidSection,
};
use serde::{Deserialize, Serialize};

/// Per-element state kept by the solver (small, `Copy`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Tet4State {
    /// Cauchy stress [σxx σyy σzz σxy σyz σzx] (global frame), without bulk viscosity.
    pub sig: [f64; 6],
    /// Equivalent plastic strain.
    pub eps_p: f64,
    /// Damage of the failure model (/FAIL; 1 = failed).
    pub dmg: f64,
    /// The law's extra history (LAW21: the volumetric strain μ of the last step).
    #[serde(default)]
    pub hist: f64,
    /// Cumulative internal energy (stress and bulk viscosity work).
    pub eint: f64,
    /// Cumulative plastic work.
    pub eplas: f64,
    /// Initial volume.
    pub vol0: f64,
    /// Volume at the last step.
    pub vol: f64,
    /// Filtered equivalent strain rate (Johnson-Cook rate term).
    pub eps_dot: f64,
    /// The integration point failed: the element is deleted.
    pub deleted: bool,
}

/// What one element step returns.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Tet4Out {
    /// Internal corner forces; the solver subtracts them (M a = f_ext − f).
    pub f: [[f64; 3]; 4],
    /// Critical (unscaled) time step; ∞ for a deleted or inverted element.
    pub dt: f64,
    /// Internal energy increment (stress + bulk viscosity work).
    pub d_eint: f64,
    /// Plastic work increment (included in `d_eint`).
    pub d_eplas: f64,
    /// The element is deleted (its point failed).
    pub failed: bool,
    /// Zero or negative volume at x^{n+1} or mid-step: the solver stops.
    pub bad_volume: bool,
}

/// Gradient vectors b_a = ∂V/∂x_a and the volume of a tetrahedron.
#[inline]
pub(crate) fn tet_gradient(x: &[[f64; 3]; 4]) -> ([[f64; 3]; 4], f64) {
    let (x21, x31, x41) = (sub(x[1], x[0]), sub(x[2], x[0]), sub(x[3], x[0]));
    let s = 1.0 / 6.0;
    let c2 = cross(x31, x41);
    let c3 = cross(x41, x21);
    let c4 = cross(x21, x31);
    let b2 = [s * c2[0], s * c2[1], s * c2[2]];
    let b3 = [s * c3[0], s * c3[1], s * c3[2]];
    let b4 = [s * c4[0], s * c4[1], s * c4[2]];
    let b1 = [
        -(b2[0] + b3[0] + b4[0]),
        -(b2[1] + b3[1] + b4[1]),
        -(b2[2] + b3[2] + b4[2]),
    ];
    let vol = dot(x21, b2);
    ([b1, b2, b3, b4], vol)
}

/// Largest face area of a tetrahedron.
#[inline]
fn tet_max_face_area(x: &[[f64; 3]; 4]) -> f64 {
    const FACES: [[usize; 3]; 4] = [[1, 2, 3], [0, 2, 3], [0, 1, 3], [0, 1, 2]];
    let mut amax: f64 = 0.0;
    for f in FACES {
        let n = cross(sub(x[f[1]], x[f[0]]), sub(x[f[2]], x[f[0]]));
        amax = amax.max(dot(n, n));
    }
    0.5 * amax.sqrt()
}

/// Element state at t = 0 (stress-free).
pub fn tet4_init(_sec: &SolidSection, x: &[[f64; 3]; 4]) -> Tet4State {
    let (_, vol) = tet_gradient(x);
    Tet4State {
        vol0: vol,
        vol,
        ..Default::default()
    }
}

/// One explicit step of one tetrahedron: stress from x^{n+1} and v^{n+½},
/// internal corner forces at x^{n+1}, energies and the element time step.
/// With `dt = 0` only the forces of the current stress and the time step are computed.
pub fn tet4_step(
    sec: &SolidSection,
    x: &[[f64; 3]; 4],
    v: &[[f64; 3]; 4],
    dt: f64,
    st: &mut Tet4State,
) -> Tet4Out {
    let mut out = Tet4Out {
        dt: f64::INFINITY,
        ..Default::default()
    };
    if st.deleted {
        out.failed = true;
        return out;
    }
    let (b, vol) = tet_gradient(x);
    if !(vol > 0.0) {
        out.bad_volume = true;
        return out;
    }
    let (bm, volm) = if dt > 0.0 {
        let mut xm = *x;
        for a in 0..4 {
            for k in 0..3 {
                xm[a][k] -= 0.5 * dt * v[a][k];
            }
        }
        tet_gradient(&xm)
    } else {
        (b, vol)
    };
    if !(volm > 0.0) {
        out.bad_volume = true;
        return out;
    }
    let l = velocity_gradient(v, &bm, volm);
    let p = solid_point_update(
        sec,
        &l,
        volm,
        vol,
        st.vol0,
        dt,
        &mut st.sig,
        &mut st.eps_p,
        &mut st.dmg,
        &mut st.hist,
        &mut st.eps_dot,
        st.eint,
        None,
        None,
    );
    st.vol = vol;
    st.eint += p.d_eint;
    st.eplas += p.d_eplas;
    out.d_eint = p.d_eint;
    out.d_eplas = p.d_eplas;
    if p.failed {
        st.deleted = true;
        out.failed = true;
        return out;
    }
    for a in 0..4 {
        out.f[a] = stress_force(&p.sig_f, b[a]);
    }
    let lc = 3.0 * vol / tet_max_face_area(x);
    out.dt = solid_time_step(sec, lc, p.compress);
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::element::hex8::tests::{lame, mat, resolved, rotated};

    fn sec(qa: f64, qb: f64) -> SolidSection {
        SolidSection::for_tetra(&resolved(1, qa, qb, 0.1), &mat()).unwrap()
    }

    fn distorted() -> [[f64; 3]; 4] {
        [
            [0.1, -0.05, 0.02],
            [1.3, 0.1, -0.1],
            [0.2, 1.1, 0.15],
            [0.05, 0.3, 0.9],
        ]
    }

    fn maxabs(f: &[[f64; 3]]) -> f64 {
        f.iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()))
    }

    fn rotation(axis: [f64; 3], th: f64) -> [[f64; 3]; 3] {
        let n = dot(axis, axis).sqrt();
        let (x, y, z) = (axis[0] / n, axis[1] / n, axis[2] / n);
        let (c, s) = (th.cos(), th.sin());
        let t = 1.0 - c;
        [
            [c + x * x * t, x * y * t - z * s, x * z * t + y * s],
            [y * x * t + z * s, c + y * y * t, y * z * t - x * s],
            [z * x * t - y * s, z * y * t + x * s, c + z * z * t],
        ]
    }

    #[test]
    fn gradient_and_volume() {
        let x = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
        ];
        let (b, v) = tet_gradient(&x);
        assert!((v - 1.0 / 6.0).abs() < 1e-15);
        // ∂N/∂x = b/V: N₂ = x, N₃ = y, N₄ = z.
        assert_eq!(b[1].map(|c| c / v), [1.0, 0.0, 0.0]);
        assert_eq!(b[2].map(|c| c / v), [0.0, 1.0, 0.0]);
        assert_eq!(b[3].map(|c| c / v), [0.0, 0.0, 1.0]);
        let x = distorted();
        let (b, v) = tet_gradient(&x);
        for i in 0..3 {
            for j in 0..3 {
                let s: f64 = (0..4).map(|a| x[a][i] * b[a][j]).sum();
                assert!((s - if i == j { v } else { 0.0 }).abs() < 1e-15);
            }
        }
    }

    #[test]
    fn rigid_motion_gives_no_force_and_rotates_stress() {
        let s = sec(1.1, 0.05);
        let x0 = distorted();
        // Translation.
        let mut st = tet4_init(&s, &x0);
        let v = [[2.0, -1.0, 0.5]; 4];
        let mut x1 = x0;
        for a in 0..4 {
            for k in 0..3 {
                x1[a][k] += 1e-3 * v[a][k];
            }
        }
        let o = tet4_step(&s, &x1, &v, 1e-3, &mut st);
        assert!(maxabs(&o.f) < 1e-13 && o.d_eint.abs() < 1e-18);
        // Finite rotation of a pre-stressed element.
        let r = rotation([-1.0, 0.5, 2.0], 0.4);
        let dt = 0.01;
        let mut v = [[0.0; 3]; 4];
        for a in 0..4 {
            x1[a] = [dot(r[0], x0[a]), dot(r[1], x0[a]), dot(r[2], x0[a])];
            for k in 0..3 {
                v[a][k] = (x1[a][k] - x0[a][k]) / dt;
            }
        }
        let mut st = tet4_init(&s, &x0);
        let o = tet4_step(&s, &x1, &v, dt, &mut st);
        assert!(maxabs(&o.f) < 1e-12, "{:?}", o.f);
        let sig0 = [0.3, -0.1, 0.2, 0.05, -0.07, 0.11];
        let mut st = tet4_init(&s, &x0);
        st.sig = sig0;
        let o = tet4_step(&s, &x1, &v, dt, &mut st);
        let want = rotated(&r, &sig0);
        for k in 0..6 {
            assert!(
                (st.sig[k] - want[k]).abs() < 1e-12,
                "{:?} vs {want:?}",
                st.sig
            );
        }
        assert!(o.d_eint.abs() < 1e-14);
    }

    #[test]
    fn uniaxial_strain_is_exact() {
        let s = sec(1.1, 0.05);
        let (lam, mu) = lame(&s.material);
        let x0 = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
        ];
        let (v0, dt) = (1.0, 1e-4);
        let mut v = [[0.0; 3]; 4];
        v[3][2] = v0;
        let mut x1 = x0;
        x1[3][2] += dt * v0;
        let mut st = tet4_init(&s, &x0);
        let o = tet4_step(&s, &x1, &v, dt, &mut st);
        let eps = dt * v0 / (1.0 + 0.5 * dt * v0);
        let want = [lam * eps, lam * eps, (lam + 2.0 * mu) * eps, 0.0, 0.0, 0.0];
        for k in 0..6 {
            assert!(
                (st.sig[k] - want[k]).abs() <= 1e-9 * want[2],
                "{:?} vs {want:?}",
                st.sig
            );
        }
        // Node 4 carries σzz b₄ = σzz A/3 (A = ½, the opposite face).
        assert!((o.f[3][2] - want[2] / 6.0).abs() < 1e-12 * want[2]);
        let sum: f64 = (0..4).map(|a| o.f[a][2]).sum();
        assert!(sum.abs() < 1e-15);
    }

    #[test]
    fn patch_test_cube_of_six_tetrahedra() {
        // A distorted hexahedron cut into 6 tetrahedra around the diagonal 1-7;
        // a linear velocity field gives the same stress in all of them and
        // no force on a node shared by all (node 1 and 7 are shared by all six).
        let p = [
            [0.0, 0.0, 0.0],
            [1.1, 0.05, -0.1],
            [1.0, 1.2, 0.1],
            [-0.1, 0.9, 0.05],
            [0.1, -0.05, 1.0],
            [1.05, 0.1, 1.1],
            [0.9, 1.0, 0.95],
            [0.05, 1.1, 1.2],
        ];
        let tets = [
            [0, 1, 2, 6],
            [0, 2, 3, 6],
            [0, 3, 7, 6],
            [0, 7, 4, 6],
            [0, 4, 5, 6],
            [0, 5, 1, 6],
        ];
        let g = [[0.3, -0.2, 0.5], [0.1, -0.4, 0.25], [-0.35, 0.15, 0.2]];
        let vel = |x: [f64; 3]| [dot(g[0], x) + 1.0, dot(g[1], x), dot(g[2], x) - 2.0];
        let s = sec(1.1, 0.05);
        let mut sref: Option<[f64; 6]> = None;
        let mut fsum = [[0.0; 3]; 8];
        let mut vsum = 0.0;
        for t in tets {
            let x = t.map(|n| p[n]);
            let (_, v0) = tet_gradient(&x);
            assert!(v0 > 0.0);
            vsum += v0;
            let v = x.map(vel);
            let mut st = tet4_init(&s, &x);
            let o = tet4_step(&s, &x, &v, 1e-3, &mut st);
            match sref {
                None => sref = Some(st.sig),
                Some(r) => {
                    for k in 0..6 {
                        assert!((st.sig[k] - r[k]).abs() < 1e-12, "{:?} vs {r:?}", st.sig);
                    }
                }
            }
            for (a, &n) in t.iter().enumerate() {
                for k in 0..3 {
                    fsum[n][k] += o.f[a][k];
                }
            }
        }
        assert!(vsum > 0.9);
        // Assembled forces of a uniform stress: σ times the outward area vector
        // of the boundary around each node, in equilibrium overall.
        let mut tot = [0.0; 3];
        for f in &fsum {
            for k in 0..3 {
                tot[k] += f[k];
            }
        }
        assert!(maxabs(&[tot]) < 1e-13 * maxabs(&fsum));
    }

    #[test]
    fn forces_are_in_equilibrium() {
        let s = sec(1.1, 0.05);
        let mut x = distorted();
        let mut st = tet4_init(&s, &x);
        let v = [
            [0.3, -0.2, 0.1],
            [-0.4, 0.1, 0.2],
            [0.2, 0.3, -0.5],
            [0.1, -0.3, 0.05],
        ];
        for _ in 0..20 {
            for a in 0..4 {
                for k in 0..3 {
                    x[a][k] += 1e-3 * v[a][k];
                }
            }
            let o = tet4_step(&s, &x, &v, 1e-3, &mut st);
            let fm = maxabs(&o.f);
            let mut sf = [0.0; 3];
            let mut mo = [0.0; 3];
            for a in 0..4 {
                let c = cross(x[a], o.f[a]);
                for k in 0..3 {
                    sf[k] += o.f[a][k];
                    mo[k] += c[k];
                }
            }
            assert!(
                maxabs(&[sf]) < 1e-13 * fm && maxabs(&[mo]) < 1e-12 * fm,
                "{sf:?} {mo:?}"
            );
        }
    }

    #[test]
    fn time_step_is_the_smallest_height() {
        let m = mat();
        let (lam, mu) = lame(&m);
        let c = ((lam + 2.0 * mu) / m.rho_ref()).sqrt();
        // Regular tetrahedron of edge a: l_c = a √(2/3).
        let a = 2.0;
        let x = [
            [0.0, 0.0, 0.0],
            [a, 0.0, 0.0],
            [0.5 * a, 0.5 * a * 3.0f64.sqrt(), 0.0],
            [
                0.5 * a,
                a / (2.0 * 3.0f64.sqrt()),
                a * (2.0f64 / 3.0).sqrt(),
            ],
        ];
        let s = sec(0.0, 0.0);
        let mut st = tet4_init(&s, &x);
        let o = tet4_step(&s, &x, &[[0.0; 3]; 4], 0.0, &mut st);
        let want = a * (2.0f64 / 3.0).sqrt() / c;
        assert!((o.dt - want).abs() < 1e-12 * want, "{} vs {want}", o.dt);
        let s = sec(1.1, 0.05);
        let o = tet4_step(&s, &x, &[[0.0; 3]; 4], 0.0, &mut st);
        assert!((o.dt - want / (0.05 + 1.0025f64.sqrt())).abs() < 1e-12 * want);
    }

    #[test]
    fn negative_volume_is_reported() {
        let s = sec(1.1, 0.05);
        let x = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
        ];
        let mut st = tet4_init(&s, &x);
        let mut xi = x;
        xi[3][2] = -0.2;
        assert!(tet4_step(&s, &xi, &[[0.0; 3]; 4], 0.0, &mut st).bad_volume);
        // Inverted during the step (mid-step volume ≤ 0).
        let v = [[0.0; 3], [0.0; 3], [0.0; 3], [0.0, 0.0, 3.0]];
        let mut x1 = x;
        x1[3][2] = 0.1;
        assert!(tet4_step(&s, &x1, &v, 0.1, &mut st).bad_volume);
    }
}
