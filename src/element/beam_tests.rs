//! The beam against the exact stiffness of a beam (Euler-Bernoulli with
//! Ishear 1, Timoshenko with 0), axial and torsion, rigid motions,
//! resultant plasticity and the time step.

use super::*;
use crate::model::{JohnsonCook, MaterialLaw, MaterialSpec};

fn card(law: MaterialLaw) -> Material {
    Material::from_card(&MaterialSpec {
        id: 1,
        unit_id: 0,
        title: String::new(),
        rho: 8e-10,
        rho_ref: 0.0,
        e: 210000.0,
        nu: 0.3,
        law,
        failures: Vec::new(),
        loc: Default::default(),
    })
}

fn prop(ishear: i64, df: f64) -> BeamProperty {
    BeamProperty {
        ismstr: 0,
        dm: 0.0,
        df,
        area: 400.0,
        iyy: 13333.3333,
        izz: 20000.0,
        ixx: 26666.6666,
        released: [false; 6],
        ishear,
    }
}

const L: f64 = 200.0;

/// A beam along x, node 1 at the origin, oriented by a node on y.
fn start() -> ([[f64; 3]; 2], BeamState) {
    let x = [[0.0; 3], [L, 0.0, 0.0]];
    (x, beam_init(&x, Some([0.0, 1.0, 0.0])))
}

/// Node 1 clamped, node 2 turned by θ about z, then about y, in one step: the end moments
/// are the beam's exact 4EI/L (near end, Timoshenko (4+Φ)/(1+Φ)) and
/// 2EI/L (far end, (2−Φ)/(1+Φ)), the shear 6EI/L²·θ/(1+Φ).
#[test]
fn end_rotation_gives_the_exact_beam_stiffness() {
    let m = card(MaterialLaw::Elastic);
    let (e, g) = (m.young(), m.shear_modulus());
    // About z (Izz, shear along y) and about y (Iyy, shear along z).
    for (axis, i, shear_dir) in [(2usize, 20000.0, 1usize), (1, 13333.3333, 2)] {
        for ishear in [1, 0] {
            let sec = BeamSection::new(&prop(ishear, 0.0), &m).unwrap();
            let (x, mut st) = start();
            let th = 1e-4;
            let mut w = [[0.0; 3]; 2];
            w[1][axis] = th;
            let out = beam_step(&sec, &x, &[[0.0; 3]; 2], &w, 1.0, &mut st);
            let phi = if ishear == 1 {
                0.0
            } else {
                12.0 * e * i / (5.0 / 6.0 * g * 400.0 * L * L)
            };
            let near = (4.0 + phi) / (1.0 + phi) * e * i / L * th;
            let far = (2.0 - phi) / (1.0 + phi) * e * i / L * th;
            let shear = 6.0 * e * i / (L * L) * th / (1.0 + phi);
            let close = |a: f64, b: f64| (a - b).abs() < 1e-9 * b.abs();
            let (m1, m0) = (out.f[1][3 + axis], out.f[0][3 + axis]);
            assert!(
                close(m1, near),
                "axis {axis} Ishear {ishear}: {m1} vs {near}"
            );
            assert!(close(m0, far), "axis {axis} Ishear {ishear}: {m0} vs {far}");
            let (s1, s0) = (out.f[1][shear_dir], out.f[0][shear_dir]);
            assert!(
                close(s1.abs(), shear) && close(s0, -s1),
                "axis {axis}: {s0} {s1} vs {shear}"
            );
            // The work of the moment equals the stored energy ½·θ·M.
            assert!((st.eint - 0.5 * th * near).abs() < 1e-9 * st.eint);
        }
    }
}

#[test]
fn axial_and_torsion_stiffness() {
    let m = card(MaterialLaw::Elastic);
    let sec = BeamSection::new(&prop(0, 0.0), &m).unwrap();
    let (x, mut st) = start();
    let (dt, u, th) = (1e-3, 1e-3, 2e-4);
    let x1 = [x[0], [L + u, 0.0, 0.0]];
    let v = [[0.0; 3], [u / dt, 0.0, 0.0]];
    let w = [[0.0; 3], [th / dt, 0.0, 0.0]];
    let out = beam_step(&sec, &x1, &v, &w, dt, &mut st);
    let n = m.young() * 400.0 * u / (L + 0.5 * u);
    assert!((out.f[1][0] - n).abs() < 1e-9 * n, "{} vs {n}", out.f[1][0]);
    let mx = m.shear_modulus() * 26666.6666 * th / (L + 0.5 * u);
    assert!((out.f[1][3] - mx).abs() < 1e-9 * mx && (out.f[0][3] + mx).abs() < 1e-9 * mx);
}

/// A beam carried rigidly (translation and spin about z) keeps its
/// resultants: no strain rate.
#[test]
fn rigid_motion_strains_nothing() {
    let m = card(MaterialLaw::Elastic);
    let sec = BeamSection::new(&prop(0, 0.01), &m).unwrap();
    let (x, mut st) = start();
    let (dt, om) = (1e-4, 2.0f64);
    // Spin about z through the midpoint by θ = 2 atan(ωΔt/2): the midpoint
    // rule's rotation for the nodal spin ω (Cayley transform).
    let th = 2.0 * (0.5 * om * dt).atan();
    let c = [0.5 * L, 0.0, 0.0];
    let turn = |p: [f64; 3], a: f64| {
        let r = sub(p, c);
        add(
            c,
            [
                r[0] * a.cos() - r[1] * a.sin(),
                r[0] * a.sin() + r[1] * a.cos(),
                0.0,
            ],
        )
    };
    let x1 = [turn(x[0], th), turn(x[1], th)];
    let v = [0, 1].map(|k| scale(sub(x1[k], x[k]), 1.0 / dt));
    let w = [[0.0, 0.0, om]; 2];
    let out = beam_step(&sec, &x1, &v, &w, dt, &mut st);
    assert!(st.f.iter().all(|f| f.abs() < 1e-7), "{:?}", st.f);
    assert!(
        out.f.iter().flatten().all(|f| f.abs() < 1e-6),
        "{:?}",
        out.f
    );
}

#[test]
fn plastic_tension_follows_the_hardening_line() {
    let m = card(MaterialLaw::JohnsonCook(JohnsonCook::hardening(
        20.0, 210.0, 1.0,
    )));
    let sec = BeamSection::new(&prop(0, 0.0), &m).unwrap();
    let (mut x, mut st) = start();
    let (dt, speed) = (5e-6, 1000.0);
    let v = [[0.0; 3], [speed, 0.0, 0.0]];
    for _ in 0..1000 {
        x[1][0] += speed * dt;
        beam_step(&sec, &x, &v, &[[0.0; 3]; 2], dt, &mut st);
    }
    let eps = (x[1][0] / L).ln();
    let sig = (20.0 + 210.0 * eps) / (1.0 + 210.0 / 210000.0);
    let n = st.f[0] / 400.0;
    // The radial return lags the hardening by one step's increment.
    assert!((n - sig).abs() < 2e-3 * sig, "{n} vs {sig}");
    assert!((st.eps_p - (eps - sig / 210000.0)).abs() < 2e-3 * eps);
}

#[test]
fn time_step_and_refusals() {
    let m = card(MaterialLaw::Elastic);
    let sec = BeamSection::new(&prop(0, 0.01), &m).unwrap();
    let (x, mut st) = start();
    let out = beam_step(&sec, &x, &[[0.0; 3]; 2], &[[0.0; 3]; 2], 0.0, &mut st);
    let d = std::f64::consts::SQRT_2 * 0.01;
    let want = ((1.0 + d * d).sqrt() - d) * L / (210000.0f64 / 8e-10).sqrt();
    assert!((out.dt - want).abs() < 1e-12 * want);
    let mut p = prop(0, 0.0);
    p.released[4] = true;
    assert!(BeamSection::new(&p, &m)
        .unwrap_err()
        .contains("released rotations"));
}

/// A lone beam's node steps at √(2m/K) as its element step (damping factor
/// included); the rotational stiffness is E·max(I)/l for a slender beam.
#[test]
fn the_nodal_stiffness_gives_the_element_step() {
    let m = card(MaterialLaw::Elastic);
    let sec = BeamSection::new(&prop(0, 0.01), &m).unwrap();
    let (x, mut st) = start();
    let (k, kr) = beam_nodal_stiffness(&sec, &x);
    let mass = 0.5 * 8e-10 * 400.0 * L;
    let out = beam_step(&sec, &x, &[[0.0; 3]; 2], &[[0.0; 3]; 2], 0.0, &mut st);
    assert!(((2.0 * mass / k).sqrt() - out.dt).abs() < 1e-12 * out.dt);
    let d = std::f64::consts::SQRT_2 * 0.01;
    let f = (1.0 + d * d).sqrt() - d;
    let want = 210000.0 * 20000.0 / L / (f * f);
    assert!((kr - want).abs() < 1e-12 * want, "{kr} vs {want}");
}
