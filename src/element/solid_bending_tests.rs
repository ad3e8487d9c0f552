//! Every brick and tetrahedron formulation in pure bending against the
//! beam's energy ½·E·I·κ²·L (Euler-Bernoulli) within 2%.
//!
//! A beam of unit cubes, 8 long, 8 deep and 1 wide (tetrahedra: each cube
//! in 6, Kuhn's split), takes in one step the displacement of linear
//! elasticity's exact pure bending,
//! u = −κxz, v = νκyz, w = ½κ(x² + ν(z² − y²)):
//! σxx = −Eκz is its only stress, so the energy is ½EIκ²L whatever ν.
//! Measured: one-point bricks (Isolid 1, 2; Ismstr 1, 4, 10) see each
//! element's mean strain and miss 1/n² of it, −1.5625% with n = 8 through
//! the depth; HA8 and HEPH are exact; S8 +0.84% and H8C +0.21% (their
//! parasitic shear, (G/E)(l/t)²-small on cubes); tetrahedra +1.7% with 16
//! cubes through the depth (+6.7% with 8: the linear tetrahedron's own
//! strain is uniform).

use super::ha8::{ha8_init, ha8_section, ha8_step};
use super::heph::{heph_init, heph_section, heph_step};
use super::hex8::tests::{mat, resolved};
use super::hex8::{hex8_init, hex8_step, SolidSection};
use super::hex8_total::{hex8_total_init, hex8_total_step, total_section};
use super::tet4::{tet4_init, tet4_step};
use crate::material::Material;
use crate::model::{MaterialLaw, MaterialSpec, ViscoHyperelastic};

/// Cubes through the depth and along the length (tetrahedra: twice as many).
const N: usize = 8;
const KAPPA: f64 = 1e-6;

/// The bending displacement at x (beam axis x, depth z from −N/2 to N/2).
fn bending(p: [f64; 3], nu: f64) -> [f64; 3] {
    let [x, y, z] = p;
    [
        -KAPPA * x * z,
        nu * KAPPA * y * z,
        0.5 * KAPPA * (x * x + nu * (z * z - y * y)),
    ]
}

/// The beam's cubes as 8 corners each (Radioss order), x from 0 to N, y
/// from −½ to ½, z from −N/2 to N/2.
fn cubes(n: usize) -> Vec<[[f64; 3]; 8]> {
    const C: [[f64; 3]; 8] = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
        [1.0, 0.0, 1.0],
        [1.0, 1.0, 1.0],
        [0.0, 1.0, 1.0],
    ];
    let h = n as f64 / 2.0;
    let mut out = Vec::new();
    for i in 0..n {
        for k in 0..n {
            out.push(C.map(|c| [i as f64 + c[0], c[1] - 0.5, k as f64 - h + c[2]]));
        }
    }
    out
}

/// Kuhn's split of a unit cube into 6 tetrahedra along its main diagonal
/// (conforming between neighbours), each positively oriented.
fn tetrahedra(c: &[[f64; 3]; 8]) -> Vec<[[f64; 3]; 4]> {
    // The corner at offsets b (0 or 1 along each axis) of a unit cube.
    let corner = |b: [usize; 3]| -> [f64; 3] { std::array::from_fn(|k| c[0][k] + b[k] as f64) };
    let mut out = Vec::new();
    for p in [
        [0, 1, 2],
        [0, 2, 1],
        [1, 0, 2],
        [1, 2, 0],
        [2, 0, 1],
        [2, 1, 0],
    ] {
        let mut b = [0usize; 3];
        let mut t = [corner(b); 4];
        for (q, &axis) in p.iter().enumerate() {
            b[axis] = 1;
            t[q + 1] = corner(b);
        }
        let d = |a: [f64; 3], o: [f64; 3]| [a[0] - o[0], a[1] - o[1], a[2] - o[2]];
        let (a, bb, cc) = (d(t[1], t[0]), d(t[2], t[0]), d(t[3], t[0]));
        let vol = a[0] * (bb[1] * cc[2] - bb[2] * cc[1]) - a[1] * (bb[0] * cc[2] - bb[2] * cc[0])
            + a[2] * (bb[0] * cc[1] - bb[1] * cc[0]);
        if vol < 0.0 {
            t.swap(2, 3);
        }
        out.push(t);
    }
    out
}

/// ½EIκ²L of the beam (I = b·t³/12, b = 1, t = L = n).
fn beam_energy(e: f64, n: usize) -> f64 {
    let t = n as f64;
    0.5 * e * KAPPA * KAPPA * t.powi(3) / 12.0 * t
}

/// One step's velocity (Δt = 1) and the moved corners.
fn step_of<const M: usize>(x: &[[f64; 3]; M], nu: f64) -> ([[f64; 3]; M], [[f64; 3]; M]) {
    let v = x.map(|p| bending(p, nu));
    let xn = std::array::from_fn(|a| std::array::from_fn(|k| x[a][k] + v[a][k]));
    (xn, v)
}

fn check(what: &str, energy: f64, e: f64, n: usize) {
    let want = beam_energy(e, n);
    let rel = (energy - want) / want;
    assert!(
        rel.abs() < 0.02,
        "{what}: {energy} vs ½EIκ²L = {want} ({rel:+.4})"
    );
}

/// The brick formulations with a linear elastic law (ν = 0.3).
#[test]
fn every_brick_formulation_bends_with_the_beam_energy() {
    let m = mat();
    let (e, nu) = (m.young(), m.poisson());
    type Step = Box<dyn Fn(&[[f64; 3]; 8]) -> f64>;
    let one_point = |isolid: i64, ismstr: i64| -> Step {
        let mut r = resolved(isolid, 0.0, 0.0, 0.1);
        r.ismstr = ismstr;
        let s = SolidSection::new(&r, &mat()).unwrap();
        Box::new(move |x| {
            let mut st = hex8_init(&s, x);
            let (xn, v) = step_of(x, nu);
            hex8_step(&s, &xn, &v, 1.0, &mut st).d_eint
        })
    };
    let full = |isolid: i64, icpre: i64| -> Step {
        let mut r = resolved(isolid, 0.0, 0.0, 0.0);
        r.icpre = icpre;
        let s = ha8_section(&r, &mat()).unwrap();
        Box::new(move |x| {
            let mut st = ha8_init(&s, x);
            let (xn, v) = step_of(x, nu);
            ha8_step(&s, &xn, &v, 1.0, &mut st);
            st.eint
        })
    };
    let heph: Step = {
        let s = heph_section(&resolved(24, 0.0, 0.0, 0.0), &mat()).unwrap();
        Box::new(move |x| {
            let mut st = heph_init(&s, x);
            let (xn, v) = step_of(x, nu);
            heph_step(&s, &xn, &v, 1.0, &mut st).d_eint
        })
    };
    let cases: Vec<(&str, Step)> = vec![
        ("Isolid 1", one_point(1, 4)),
        ("Isolid 2", one_point(2, 4)),
        ("Isolid 1 Ismstr 1", one_point(1, 1)),
        ("Isolid 12 (S8)", full(12, 0)),
        ("Isolid 14 (HA8)", full(14, 0)),
        ("Isolid 17 (H8C)", full(17, 1)),
        ("Isolid 24 (HEPH)", heph),
    ];
    for (what, f) in cases {
        let energy: f64 = cubes(N).iter().map(|x| f(x)).sum();
        check(what, energy, e, N);
    }
}

/// Tetrahedra (each cube in 6), ν = 0.3: a linear tetrahedron's own strain
/// is uniform and stiffens bending by the mesh's (h/t)² — 6.7% with 8
/// cubes through the depth, so 16 here.
#[test]
fn tetrahedra_bend_with_the_beam_energy() {
    let m = mat();
    let (e, nu) = (m.young(), m.poisson());
    let s = SolidSection::for_tetra(&resolved(1, 0.0, 0.0, 0.0), &m).unwrap();
    let mut energy = 0.0;
    for c in cubes(2 * N) {
        for x in tetrahedra(&c) {
            let mut st = tet4_init(&s, &x);
            let (xn, v) = step_of(&x, nu);
            energy += tet4_step(&s, &xn, &v, 1.0, &mut st).d_eint;
        }
    }
    check("Tet4", energy, e, 2 * N);
}

/// Total strain (Ismstr 10) with LAW62's Ogden terms (the reference's
/// W = Σ 2μᵢ/αᵢ² (λ₁^αᵢ + λ₂^αᵢ + λ₃^αᵢ − 3)), which at small strain is
/// Hooke's law with μ = Σμᵢ and the card's ν.
#[test]
fn total_strain_bricks_bend_with_the_beam_energy() {
    let nu = 0.2;
    let (mu_i, alpha) = (vec![0.069119e-3, 12.0126e-8], vec![30.4979, -3.6961]);
    let mu: f64 = mu_i.iter().sum();
    let m = Material::from_card(&MaterialSpec {
        id: 1,
        unit_id: 0,
        title: String::new(),
        rho: 5.5e-8,
        rho_ref: 0.0,
        e: 2.0 * mu * (1.0 + nu),
        nu,
        law: MaterialLaw::ViscoHyperelastic(ViscoHyperelastic {
            mu: mu_i,
            alpha,
            gamma: vec![],
            tau: vec![],
            mu_max: 1e20,
            flag_visc: 0,
        }),
        failures: Vec::new(),
        loc: Default::default(),
    });
    let mut r = resolved(1, 0.0, 0.0, 0.1);
    r.ismstr = 10;
    let s = total_section(&r, &m).unwrap();
    let mut energy = 0.0;
    for x in cubes(N) {
        let mut st = hex8_total_init(&s, &x);
        let (xn, v) = step_of(&x, nu);
        hex8_total_step(&s, &xn, &v, 1.0, &mut st);
        energy += st.eint;
    }
    check(
        "Isolid 1 Ismstr 10 (LAW62)",
        energy,
        2.0 * mu * (1.0 + nu),
        N,
    );
}
