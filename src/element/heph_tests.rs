//! HEPH against its formulation: the patch test (a linear field makes no
//! hourglass force and the one-point stress), rigid rotation makes no
//! force, hourglass modes are elastic (their energy comes back), and a
//! pure bending mode stores the beam's energy within 2% (the physical
//! stabilization with the Icpre 0 coefficients is exact in bending for ν = 0).

use super::*;
use crate::element::hex8::tests::{mat, resolved};
use crate::material::Material;

/// Natural coordinates of the nodes (Radioss order).
const NAT: [[f64; 3]; 8] = [
    [-1.0, -1.0, -1.0],
    [1.0, -1.0, -1.0],
    [1.0, 1.0, -1.0],
    [-1.0, 1.0, -1.0],
    [-1.0, -1.0, 1.0],
    [1.0, -1.0, 1.0],
    [1.0, 1.0, 1.0],
    [-1.0, 1.0, 1.0],
];

fn sec(nu: f64, icpre: i64) -> SolidSection {
    let mut m = mat();
    if let Material::Elastic(l) = &mut m {
        l.0.nu = nu;
        l.0.g = l.0.e / (2.0 * (1.0 + nu));
    }
    let mut r = resolved(24, 0.0, 0.0, 0.0);
    r.icpre = icpre;
    let mut s = heph_section(&r, &m).unwrap();
    s.h = 0.0; // no hourglass viscosity: the elastic part alone
    s
}

fn boxed(l: [f64; 3]) -> [[f64; 3]; 8] {
    std::array::from_fn(|a| std::array::from_fn(|i| 0.5 * l[i] * NAT[a][i]))
}

fn step(
    s: &SolidSection,
    x: &[[f64; 3]; 8],
    v: &[[f64; 3]; 8],
    dt: f64,
    st: &mut HephState,
) -> Hex8Out {
    let xn: [[f64; 3]; 8] =
        std::array::from_fn(|a| std::array::from_fn(|i| x[a][i] + dt * v[a][i]));
    heph_step(s, &xn, v, dt, st)
}

/// A linear velocity field: no hourglass rate, no hourglass force; the
/// forces are the one-point stress's and balance.
#[test]
fn patch_test_linear_field_has_no_hourglass() {
    let s = sec(0.3, 0);
    let x = boxed([2.0, 1.0, 1.5]);
    let mut st = heph_init(&s, &x);
    let l = [[1e-4, 2e-5, 0.0], [0.0, -3e-5, 1e-5], [2e-5, 0.0, 5e-5]];
    let v: [[f64; 3]; 8] =
        std::array::from_fn(|a| std::array::from_fn(|i| (0..3).map(|j| l[i][j] * x[a][j]).sum()));
    let o = step(&s, &x, &v, 1.0, &mut st);
    assert!(
        st.fh.iter().flatten().all(|f| f.abs() < 1e-18),
        "{:?}",
        st.fh
    );
    assert!(st.ehg.abs() < 1e-30, "{}", st.ehg);
    let total: [f64; 3] = std::array::from_fn(|i| o.f.iter().map(|f| f[i]).sum());
    assert!(total.iter().all(|t| t.abs() < 1e-12), "{total:?}");
    let e = s.material.young();
    assert!(
        st.sig_l[0].abs() > 1e-3 * e * 1e-4,
        "the stress is the strain's"
    );
}

/// A rigid rotation about z: no strain, no hourglass stress, no force.
#[test]
fn rigid_rotation_makes_no_force() {
    let s = sec(0.3, 0);
    let x0 = boxed([2.0, 1.0, 1.5]);
    let mut st = heph_init(&s, &x0);
    let (w, dt): (f64, f64) = (0.5, 1e-3);
    let mut x = x0;
    let mut fmax: f64 = 0.0;
    for _ in 0..1000 {
        let v: [[f64; 3]; 8] = std::array::from_fn(|a| {
            let (c, sn) = ((w * dt).cos(), (w * dt).sin());
            let p = x[a];
            let q = [c * p[0] - sn * p[1], sn * p[0] + c * p[1], p[2]];
            std::array::from_fn(|i| (q[i] - p[i]) / dt)
        });
        let o = step(&s, &x, &v, dt, &mut st);
        x = std::array::from_fn(|a| std::array::from_fn(|i| x[a][i] + dt * v[a][i]));
        fmax = o.f.iter().flatten().fold(fmax, |m, f| m.max(f.abs()));
    }
    assert!(fmax < 1e-9 * s.material.young(), "largest force {fmax}");
}

/// Pure bending (u = −κxz, ν = 0): the one-point part sees no strain, the
/// hourglass stiffness alone carries the beam's energy ½EIκ²l within 2%.
#[test]
fn pure_bending_stores_the_beam_energy() {
    for (l, icpre) in [([4.0, 1.0, 0.5], 0), ([1.0, 1.0, 1.0], 0)] {
        let s = sec(0.0, icpre);
        let x = boxed(l);
        let mut st = heph_init(&s, &x);
        let (kappa, dt) = (1e-6, 1.0);
        let v: [[f64; 3]; 8] = std::array::from_fn(|a| [-kappa * x[a][2] * x[a][0] / dt, 0.0, 0.0]);
        step(&s, &x, &v, dt, &mut st);
        let e = s.material.young();
        let beam = 0.5 * e * kappa * kappa * l[0] * l[1] * l[2].powi(3) / 12.0;
        let stored = st.ehg;
        assert!(
            (stored - beam).abs() < 0.02 * beam,
            "l {l:?}: {stored} vs {beam}"
        );
    }
}

/// An hourglass mode pushed and brought back returns its energy (elastic).
#[test]
fn hourglass_mode_is_elastic() {
    let s = sec(0.3, 1);
    let x0 = boxed([1.0, 1.0, 1.0]);
    let mut st = heph_init(&s, &x0);
    // The ξηζ mode in x.
    let mode: [f64; 8] = std::array::from_fn(|a| NAT[a][0] * NAT[a][1] * NAT[a][2]);
    let dt = 1e-4;
    let mut x = x0;
    let mut peak = 0.0;
    for k in 0..200 {
        let sgn = if k < 100 { 1.0 } else { -1.0 };
        let v: [[f64; 3]; 8] = std::array::from_fn(|a| [sgn * 1e-3 * mode[a], 0.0, 0.0]);
        step(&s, &x, &v, dt, &mut st);
        x = std::array::from_fn(|a| std::array::from_fn(|i| x[a][i] + dt * v[a][i]));
        if k == 99 {
            peak = st.ehg;
        }
    }
    assert!(peak > 0.0);
    assert!(st.ehg.abs() < 1e-6 * peak, "{} of {peak} left", st.ehg);
}

#[test]
fn plastic_laws_and_icpre_2_are_refused_by_name() {
    let mut r = resolved(24, 0.0, 0.0, 0.0);
    r.icpre = 2;
    let e = heph_section(&r, &mat()).unwrap_err();
    assert!(e.contains("Icpre = 2"), "{e}");
}
