//! The truss against uniaxial answers: elastic stretch, linear hardening,
//! rigid rotation, energy and time step.

use super::*;
use crate::element::hex8::tests::mat;
use crate::model::{JohnsonCook, MaterialLaw, MaterialSpec};

fn card(e: f64, law: MaterialLaw) -> Material {
    Material::from_card(&MaterialSpec {
        id: 1,
        unit_id: 0,
        title: String::new(),
        rho: 8e-10,
        rho_ref: 0.0,
        e,
        nu: 0.0,
        law,
        failures: Vec::new(),
        loc: Default::default(),
    })
}

fn plastic() -> Material {
    card(
        210000.0,
        MaterialLaw::JohnsonCook(JohnsonCook::hardening(20.0, 210.0, 1.0)),
    )
}

/// Stretches a bar of length 200 along y at `speed` for `steps` steps.
fn stretch(sec: &TrussSection, speed: f64, steps: usize, dt: f64) -> (TrussState, TrussOut, f64) {
    let mut st = truss_init(sec);
    let mut x = [[0.0, 0.0, 0.0], [0.0, 200.0, 0.0]];
    let v = [[0.0; 3], [0.0, speed, 0.0]];
    let mut out = TrussOut::default();
    for _ in 0..steps {
        x[1][1] += speed * dt;
        out = truss_step(sec, &x, &v, dt, &mut st);
    }
    (st, out, x[1][1])
}

#[test]
fn an_elastic_bar_carries_ea_times_its_log_strain() {
    let m = card(210.0, MaterialLaw::Elastic);
    let sec = TrussSection::new(4.0, 0.0, &m).unwrap();
    let (st, out, l) = stretch(&sec, 1.0, 1000, 0.01);
    let eps = (l / 200.0).ln();
    let n = 210.0 * 4.0 * eps;
    assert!(
        (st.sig * st.area - n).abs() < 1e-6 * n,
        "{} vs {n}",
        st.sig * st.area
    );
    // Equilibrium and direction: node 2 is pulled back along −y.
    assert!((out.f[1][1] - n).abs() < 1e-6 * n && (out.f[0][1] + out.f[1][1]).abs() < 1e-12);
    // The work ∫EA·ln(l/l₀) dl = EA·l₀·(e^ε(ε − 1) + 1).
    let w = 210.0 * 4.0 * 200.0 * (eps.exp() * (eps - 1.0) + 1.0);
    assert!((st.eint - w).abs() < 1e-5 * w, "{} vs {w}", st.eint);
    assert!((out.dt - l / (210.0f64 / m.rho_ref()).sqrt()).abs() < 1e-12 * out.dt);
}

#[test]
fn a_plastic_bar_follows_its_hardening_line() {
    let m = plastic();
    let sec = TrussSection::new(400.0, 0.0, &m).unwrap();
    let (st, _, l) = stretch(&sec, 1000.0, 1000, 5e-6);
    let eps = (l / 200.0).ln();
    // σ = a + b ε_p with ε_p = ε − σ/E: σ = (a + b ε)/(1 + b/E).
    let sig = (20.0 + 210.0 * eps) / (1.0 + 210.0 / 210000.0);
    assert!((st.sig - sig).abs() < 1e-4 * sig, "{} vs {sig}", st.sig);
    assert!((st.eps_p - (eps - sig / 210000.0)).abs() < 1e-6);
    assert!(st.eplas > 0.0 && st.eplas < st.eint);
}

#[test]
fn a_rigid_rotation_keeps_the_force_and_turns_it() {
    let sec = TrussSection::new(4.0, 0.0, &mat()).unwrap();
    let (mut st, _, _) = stretch(&sec, 1.0, 10, 0.01);
    let n = st.sig * st.area;
    let l = 200.1;
    let th = 0.3f64;
    let x = [[0.0; 3], [-l * th.sin(), l * th.cos(), 0.0]];
    // The rotation over one step: the mid-step chord is normal to the
    // relative velocity, so no strain.
    let dt = 1e-3;
    let v = [[0.0; 3], [-l * th.sin() / dt, (l * th.cos() - l) / dt, 0.0]];
    let out = truss_step(&sec, &x, &v, dt, &mut st);
    assert!((st.sig * st.area - n).abs() < 1e-9 * n.abs());
    let f = out.f[1];
    assert!((f[0] + n * th.sin()).abs() < 1e-9 * n && (f[1] - n * th.cos()).abs() < 1e-9 * n);
}

#[test]
fn a_gap_and_other_laws_are_refused_by_name() {
    let e = TrussSection::new(4.0, 1.0, &mat()).unwrap_err();
    assert!(e.contains("Gap = 1"), "{e}");
}

/// A lone truss's node steps at √(2m/K) = l/c, the element step (m = ρAl/2).
#[test]
fn the_nodal_stiffness_gives_the_element_step() {
    let m = card(210000.0, MaterialLaw::Elastic);
    let sec = TrussSection::new(400.0, 0.0, &m).unwrap();
    let st = truss_init(&sec);
    let x = [[0.0; 3], [0.0, 200.0, 0.0]];
    let k = truss_nodal_stiffness(&sec, &st, &x);
    let mass = 0.5 * 8e-10 * 400.0 * 200.0;
    let out = truss_step(&sec, &x, &[[0.0; 3]; 2], 0.0, &mut truss_init(&sec));
    assert!(((2.0 * mass / k).sqrt() - out.dt).abs() < 1e-12 * out.dt);
}
