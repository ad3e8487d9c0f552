//! QBAT: membrane and bending patch tests on a distorted element (the
//! energy of a uniform strain or curvature exactly), rigid motion of a
//! warped element, the time step of a rectangle.

use super::*;
use crate::model::{MaterialLaw, MaterialSpec};

const E: f64 = 29e6;
const NU: f64 = 0.22;
const T: f64 = 0.32;

fn section() -> QbatSection {
    let m = Material::from_card(&MaterialSpec {
        id: 1,
        unit_id: 0,
        title: String::new(),
        rho: 7.34e-4,
        rho_ref: 0.0,
        e: E,
        nu: NU,
        law: MaterialLaw::Elastic,
        failures: Vec::new(),
        loc: Default::default(),
    });
    QbatSection::new(T, 5.0 / 6.0, 0.0, &m).unwrap()
}

/// A distorted flat quadrilateral in the plane z = 0.
fn distorted() -> [[f64; 3]; 4] {
    [
        [0.0, 0.0, 0.0],
        [2.2, 0.3, 0.0],
        [2.0, 1.7, 0.0],
        [-0.3, 1.2, 0.0],
    ]
}

fn area(x: &[[f64; 3]; 4]) -> f64 {
    0.5 * norm(cross(sub(x[2], x[0]), sub(x[3], x[1])))
}

/// The in-plane velocity gradient of the membrane tests (Δt = 1).
const H: [[f64; 2]; 2] = [[2e-6, 1e-6], [-0.5e-6, 1.5e-6]];

/// v = H·x at the corners.
fn stretch(x: &[[f64; 3]; 4]) -> [[f64; 3]; 4] {
    x.map(|p| {
        [
            H[0][0] * p[0] + H[0][1] * p[1],
            H[1][0] * p[0] + H[1][1] * p[1],
            0.0,
        ]
    })
}

/// The plane-stress energy of the uniform strain sym(H) over `area`.
fn stretch_energy(area: f64) -> f64 {
    let (exx, eyy, gxy) = (H[0][0], H[1][1], H[0][1] + H[1][0]);
    let a11 = E / (1.0 - NU * NU);
    let g = E / (2.0 * (1.0 + NU));
    0.5 * T * area * (a11 * (exx * exx + eyy * eyy + 2.0 * NU * exx * eyy) + g * gxy * gxy)
}

#[test]
fn a_uniform_membrane_strain_stores_its_exact_energy() {
    let sec = section();
    let x = distorted();
    let v = stretch(&x);
    let mut st = QbatState::default();
    let out = qbat_step(&sec, &x, &v, &[[0.0; 3]; 4], 1.0, &mut st);
    let w = stretch_energy(area(&x));
    // The membrane shear is taken in the element frame and the normal
    // strains in each point's frame (E11, W5), which differ by a little more
    // than a right angle on a distorted element: 1e-4 of the energy.
    assert!((out.d_eint - w).abs() < 1e-4 * w, "{} vs {w}", out.d_eint);
    // The corner forces balance (and so do their moments about the origin).
    for k in 0..3 {
        let s: f64 = out.f.iter().map(|f| f[k]).sum();
        assert!(s.abs() < 1e-9 * out.f.iter().map(|f| f[k].abs()).sum::<f64>().max(1e-30));
    }
}

/// θ_y = κx with w = −½κx²: constant curvature κ_xx and no transverse shear;
/// the energy is ½·D·κ²·A (D = Et³/12(1−ν²)).
#[test]
fn a_uniform_curvature_stores_the_plate_bending_energy() {
    let sec = section();
    let x = distorted();
    let kappa = 1e-6;
    let v = x.map(|p| [0.0, 0.0, -0.5 * kappa * p[0] * p[0]]);
    let w = x.map(|p| [0.0, kappa * p[0], 0.0]);
    let mut st = QbatState::default();
    let out = qbat_step(&sec, &x, &v, &w, 1.0, &mut st);
    let d = E * T * T * T / (12.0 * (1.0 - NU * NU));
    let want = 0.5 * d * kappa * kappa * area(&x);
    assert!(
        (out.d_eint - want).abs() < 1e-6 * want,
        "{} vs {want}",
        out.d_eint
    );
    for r in &st.res {
        assert!(
            r[2].abs() < 1e-9 * d * kappa && r[3].abs() < 1e-9 * d * kappa,
            "no shear: {r:?}"
        );
    }
}

/// A warped element moved rigidly (translation and spin) strains nothing.
#[test]
fn a_warped_element_moved_rigidly_strains_nothing() {
    let sec = section();
    let mut x = distorted();
    x[0][2] = 0.15;
    x[2][2] = 0.1;
    x[1][2] = -0.12;
    let om = [0.3, -0.7, 0.5];
    let v = x.map(|p| add([0.1, 0.2, -0.3], cross(om, p)));
    let mut st = QbatState::default();
    let out = qbat_step(&sec, &x, &v, &[om; 4], 1e-3, &mut st);
    let big = st.res.iter().flatten().fold(0.0f64, |m, r| m.max(r.abs()));
    assert!(big < 1e-9, "{:?}", st.res);
    assert!(
        out.f.iter().flatten().all(|f| f.abs() < 1e-6),
        "{:?}",
        out.f
    );
}

/// A rectangle a × b (a ≥ b): L_c = ab/√(F(a² + b²)/3), F = 2(1 + min(½, (a/b − 1)/4))
/// (note E24–E27; f₂ = 1 up to 3e-4 for a rectangle), Δt = L_c/c₀ with dn = 0.
#[test]
fn the_time_step_of_a_rectangle() {
    let sec = section();
    let (a, b) = (0.5, 0.27);
    let x = [[0.0, 0.0, 0.0], [a, 0.0, 0.0], [a, b, 0.0], [0.0, b, 0.0]];
    let mut st = QbatState::default();
    let out = qbat_step(&sec, &x, &[[0.0; 3]; 4], &[[0.0; 3]; 4], 0.0, &mut st);
    let f1: f64 = 1.0 + (0.25 * (a / b - 1.0)).min(0.5);
    let f2 = 0.78 + 0.22 * (3.413f64 * (1.0 - 0.7071)).powi(3);
    let lc = a * b / (2.0 * f1 * f2 * (a * a + b * b) / 3.0).sqrt();
    let c0 = (E / 7.34e-4f64).sqrt();
    assert!(
        (out.dt - lc / c0).abs() < 1e-12 * out.dt,
        "{} vs {}",
        out.dt,
        lc / c0
    );
}

#[test]
fn plastic_laws_are_refused_by_name() {
    let m = Material::from_card(&MaterialSpec {
        id: 1,
        unit_id: 0,
        title: String::new(),
        rho: 7.8e-9,
        rho_ref: 0.0,
        e: 210000.0,
        nu: 0.3,
        law: MaterialLaw::JohnsonCook(crate::model::JohnsonCook::hardening(200.0, 400.0, 0.5)),
        failures: Vec::new(),
        loc: Default::default(),
    });
    let e = QbatSection::new(1.0, 0.0, 0.0, &m).unwrap_err();
    assert!(e.contains("QBAT") && e.contains("LAW2"), "{e}");
}

/// Patch test: a 2×2 patch of parallelograms, then one around a moved
/// interior node, under v = H·x (as above): the energy of the uniform
/// membrane strain over the patch within 1e-4 and no force on the interior
/// node — 1e-9 of the largest on parallelograms; 1% on the distorted patch
/// (0.8% there: the normal strains taken in each point's frame, as above).
#[test]
fn a_patch_around_a_moved_node_passes_the_patch_test() {
    let parallelograms: [[f64; 3]; 9] = std::array::from_fn(|n| {
        let (i, j) = ((n % 3) as f64, (n / 3) as f64);
        [5.0 * i + 1.5 * j, 0.5 * i + 4.5 * j, 0.0]
    });
    let distorted = [
        [0.0, 0.0, 0.0],
        [4.0, 0.3, 0.0],
        [9.0, 0.0, 0.0],
        [-0.4, 4.5, 0.0],
        [5.1, 3.6, 0.0],
        [10.0, 5.0, 0.0],
        [0.0, 10.0, 0.0],
        [4.2, 9.6, 0.0],
        [9.5, 10.3, 0.0],
    ];
    for (nodes, bound) in [(parallelograms, 1e-9), (distorted, 1e-2)] {
        patch(&nodes, bound);
    }
}

fn patch(nodes: &[[f64; 3]; 9], bound: f64) {
    let sec = section();
    let conn = [[0, 1, 4, 3], [1, 2, 5, 4], [3, 4, 7, 6], [4, 5, 8, 7]];
    let (mut f, mut energy, mut a) = ([[0.0; 3]; 9], 0.0, 0.0);
    for c in conn {
        let x = c.map(|n| nodes[n]);
        let mut st = QbatState::default();
        let out = qbat_step(&sec, &x, &stretch(&x), &[[0.0; 3]; 4], 1.0, &mut st);
        energy += out.d_eint;
        a += area(&x);
        for (k, &n) in c.iter().enumerate() {
            for j in 0..3 {
                f[n][j] += out.f[k][j];
            }
        }
    }
    let w = stretch_energy(a);
    assert!((energy - w).abs() < 1e-4 * w, "{energy} vs {w}");
    let fmax = f.iter().flatten().fold(0.0f64, |m, b| m.max(b.abs()));
    assert!(
        f[4].iter().all(|c| c.abs() < bound * fmax),
        "bound {bound}: interior {:?} (max {fmax})",
        f[4]
    );
}
