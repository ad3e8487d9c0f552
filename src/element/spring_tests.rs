//! The three spring kernels against their formulas: forces, energies,
//! failure, time steps, objectivity and equilibrium.

use super::*;
use crate::element::spring_beam::SpringBeam;
use crate::element::spring_general::GeneralSpring;
use crate::model::{GeneralSpringProperty, Loc, SpringBeamProperty, SpringDof};
use crate::vec3::{add, cross, dot};

fn axial(k: f64, c: f64, mass: f64) -> SpringProperty {
    SpringProperty {
        mass,
        sens_id: 0,
        isflag: 0,
        ileng: 0,
        dof: SpringDof::linear(k, c),
    }
}

fn func(x: Vec<f64>, y: Vec<f64>) -> Function {
    Function {
        id: 7,
        title: String::new(),
        x,
        y,
        loc: Loc::default(),
    }
}

/// Spring along (1, 2, 2)/3 from the origin, stretched to length l.
fn geom(l: f64) -> ([[f64; 3]; 2], [f64; 3]) {
    let n = [1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0];
    ([[0.0; 3], scale(n, l)], n)
}

fn run_axial(s: &AxialSpring, st: &mut SpringState, l: f64, l0: f64, dt: f64) -> SpringOut {
    let (x, _) = geom(l);
    s.step(&x, &[[0.0; 3]; 2], l0, dt, [1.0, 1.0], st)
}

#[test]
fn linear_spring_stores_half_k_delta_squared_and_pulls_its_nodes_together() {
    let s = AxialSpring::new(&axial(100.0, 0.0, 2.0), &[]).unwrap();
    let l0 = 2.0;
    let mut st = AxialSpring::init(&geom(l0).0);
    let mut o = SpringOut::default();
    for i in 1..=300 {
        o = run_axial(&s, &mut st, l0 + 1e-3 * i as f64, l0, 1e-3);
    }
    assert!((st.force() - 30.0).abs() < 1e-9);
    assert!((st.eint - 0.5 * 100.0 * 0.09).abs() < 1e-9, "{}", st.eint);
    let n = geom(1.0).1;
    assert!((o.f[1][1] - 30.0 * n[1]).abs() < 1e-9 && (o.f[0][1] + 30.0 * n[1]).abs() < 1e-9);
    // Element step M/(√(C² + MK) + C) = √(M/K).
    assert!((o.dt - (2.0f64 / 100.0).sqrt()).abs() < 1e-15);
}

#[test]
fn damper_dissipates_and_ignores_transverse_motion() {
    let s = AxialSpring::new(&axial(0.0, 5.0, 1.0), &[]).unwrap();
    let (l0, dt, vel) = (1.0, 1e-3, -2.0);
    let mut st = AxialSpring::init(&geom(l0).0);
    let mut e = 0.0;
    for i in 1..=10 {
        let o = run_axial(&s, &mut st, l0 + vel * dt * i as f64, l0, dt);
        assert!((st.force() - 5.0 * vel).abs() < 1e-9, "{}", st.force());
        e += o.d_eint;
    }
    assert!(e > 0.0 && (e - 5.0 * vel * vel * 10.0 * dt).abs() < 0.06 * e);
    // M/(√(C² + MK) + C) with K = 0: M/(2C).
    let o = run_axial(&s, &mut st, l0 + vel * dt * 11.0, l0, dt);
    assert!((o.dt - 1.0 / 10.0).abs() < 1e-15);
    let mut st = AxialSpring::init(&geom(l0).0);
    let vt = [[0.0; 3], [2.0, -1.0, 0.0]]; // ⟂ (1, 2, 2)
    let o = s.step(&geom(l0).0, &vt, l0, dt, [1.0; 2], &mut st);
    assert!(o.f[1][0].abs() < 1e-15);
}

#[test]
fn function_force_with_scales_and_per_unit_length() {
    let mut p = axial(10.0, 0.0, 1.0);
    p.dof.fct_id1 = 7;
    p.dof.a = 2.0;
    p.dof.ascale = 0.5;
    let f = func(vec![-1.0, 0.0, 1.0, 2.0], vec![-50.0, 0.0, 10.0, 40.0]);
    let s = AxialSpring::new(&p, std::slice::from_ref(&f)).unwrap();
    let mut st = AxialSpring::init(&geom(1.0).0);
    // δ = 0.75 → f(δ/Ascale = 1.5) = 25, F = A·25 = 50; K raised to 2·50/0.5.
    run_axial(&s, &mut st, 1.75, 1.0, 1e-3);
    assert!((st.force() - 50.0).abs() < 1e-12, "{}", st.force());
    assert_eq!(s.law.k_dt(), 200.0);
    // Ileng = 1: δ/l₀ with l₀ = 2; the mass is per unit length.
    let mut p = axial(10.0, 0.0, 1.0);
    p.ileng = 1;
    let s = AxialSpring::new(&p, &[]).unwrap();
    let mut st = AxialSpring::init(&geom(2.0).0);
    let o = run_axial(&s, &mut st, 2.5, 2.0, 1e-3);
    assert!((st.force() - 10.0 * 0.25).abs() < 1e-12);
    assert!((o.dt - (2.0f64 / 5.0).sqrt()).abs() < 1e-15);
}

#[test]
fn failure_adds_the_last_half_increment_then_nothing() {
    let mut p = axial(100.0, 0.0, 1.0);
    p.dof.delta_max = 0.2;
    let s = AxialSpring::new(&p, &[]).unwrap();
    let mut st = AxialSpring::init(&geom(1.0).0);
    assert!(!run_axial(&s, &mut st, 1.1, 1.0, 1e-3).failed);
    let e1 = st.eint;
    let o = run_axial(&s, &mut st, 1.3, 1.0, 1e-3);
    assert!(o.failed && st.force() == 0.0 && o.f == [[0.0; 6]; 2]);
    assert!((st.eint - e1 - 0.5 * 10.0 * 0.2).abs() < 1e-12);
    let o = run_axial(&s, &mut st, 1.1, 1.0, 1e-3);
    assert!(o.failed && o.d_eint == 0.0);
}

#[test]
fn zero_length_spring_uses_the_relative_velocity() {
    let s = AxialSpring::new(&axial(100.0, 1.0, 1.0), &[]).unwrap();
    let x = [[1.0, 1.0, 1.0]; 2];
    let mut st = AxialSpring::init(&x);
    let v = [[0.0; 3], [0.0, 0.0, 2.0]];
    let o = s.step(&x, &v, 0.0, 1e-3, [1.0; 2], &mut st);
    assert_eq!(st.dir, [0.0, 0.0, 1.0]);
    assert_eq!(o.f[1][2], 0.0); // δ and δ̇ (finite difference) are zero
}

fn general(k: [f64; 6], ifail: i64, dmax: f64) -> GeneralSpringProperty {
    GeneralSpringProperty {
        mass: 5.0,
        inertia: 1.0,
        skew_id: 0,
        sens_id: 0,
        isflag: 0,
        ifail,
        ifail2: 0,
        iequil: 0,
        dofs: std::array::from_fn(|i| SpringDof {
            delta_max: dmax,
            ..SpringDof::linear(k[i], 0.0)
        }),
        fsmooth: 0,
        fcut: 0.0,
    }
}

/// Six directions driven at unit rate (RESSORT_couple's case): energy
/// ½ΣKᵢt², the multi-directional failure 6t² > 1, then one half increment.
#[test]
fn general_spring_six_directions_and_multi_directional_failure() {
    let k = [1e3, 1e5, 100.0, 10.0, 10.0, 10.0];
    let s = GeneralSpring::new(&general(k, 1, 1.0), &[]).unwrap();
    let x0 = [[0.0; 3], [0.0, 1.0, 0.0]];
    let mut st = GeneralSpring::init(&x0);
    let (dt, w) = (1e-3, [[0.0; 3], [1.0; 3]]);
    let mut broke_at = 0;
    for i in 1..=600 {
        let t = i as f64 * dt;
        let x = [[0.0; 3], [t, 1.0 + t, t]];
        let e_before = st.eint;
        let f_before = st.dofs.map(|d| d.force);
        let o = s.step(&x, &w, dt, &mut st);
        if i < 400 {
            assert!((st.eint - 0.5 * k.iter().sum::<f64>() * t * t).abs() < 1e-6 * st.eint);
            for j in 0..6 {
                assert!(
                    (o.f[1][j] - k[j] * t).abs() < 1e-9 * k[j],
                    "{j}: {:?}",
                    o.f[1]
                );
            }
            assert!((o.dt - (5.0f64 / 1e5).sqrt()).abs() < 1e-15);
        }
        if o.failed && broke_at == 0 {
            broke_at = i;
            assert!(6.0 * t * t > 1.0 && 6.0 * (t - dt).powi(2) <= 1.0);
            assert!(o.f[1][1] > 0.0, "the breaking step still carries its force");
        } else if broke_at > 0 && i == broke_at + 1 {
            let half: f64 = f_before.iter().map(|f| 0.5 * f * dt).sum();
            assert!((st.eint - e_before - half).abs() < 1e-9 && o.f == [[0.0; 6]; 2]);
        } else if broke_at > 0 {
            assert_eq!(st.eint, e_before);
        }
    }
    assert_eq!(broke_at, 409);
}

fn beam(ks: [f64; 6]) -> SpringBeamProperty {
    SpringBeamProperty {
        mass: 4.0,
        inertia: 30.0,
        skew_id: 0,
        sens_id: 0,
        isflag: 0,
        ifail: 0,
        ileng: 0,
        ifail2: 0,
        dofs: std::array::from_fn(|i| SpringDof::linear(ks[i], 0.0)),
        v0: 0.0,
        omega0: 0.0,
        fail: [[0.0, 1.0, 1.0, 2.0]; 6],
    }
}

fn rotate_z(p: [f64; 3], a: f64) -> [f64; 3] {
    [
        a.cos() * p[0] - a.sin() * p[1],
        a.sin() * p[0] + a.cos() * p[1],
        p[2],
    ]
}

/// A spring beam turning rigidly about z (nodes and their rotations) keeps
/// no force: the shear is measured net of the rigid rotation.
#[test]
fn spring_beam_rigid_rotation_makes_no_force() {
    let s = SpringBeam::new(&beam([500.0, 300.0, 300.0, 50.0, 40.0, 40.0]), &[]).unwrap();
    let x0 = [[0.0; 3], [2.0, 0.5, 0.0]];
    let mut st = SpringBeam::init(&x0);
    let (w, dt) = (0.7, 1e-4);
    let mut fmax: f64 = 0.0;
    for i in 1..=20000 {
        let a = w * dt * i as f64;
        let x = [x0[0], rotate_z(x0[1], a)];
        let am = w * dt * (i as f64 - 0.5);
        let v = [[0.0; 3], scale(rotate_z([-x0[1][1], x0[1][0], 0.0], am), w)];
        let o = s.step(&x, &v, &[[0.0, 0.0, w]; 2], 2.0615528128088303, dt, &mut st);
        fmax = fmax.max(o.f[1].iter().fold(0.0, |m, f| m.max(f.abs())));
    }
    assert!(fmax < 1e-5, "largest force or moment {fmax}");
}

/// A transverse shift of node 2 with no rotation: the shear force K_s δ and
/// the end moments ±l F/2 are in equilibrium; the time step falls with l².
#[test]
fn spring_beam_shear_is_balanced_by_end_moments() {
    let s = SpringBeam::new(&beam([500.0, 300.0, 300.0, 0.0, 0.0, 0.0]), &[]).unwrap();
    let l = 3.0;
    let x0 = [[0.0; 3], [l, 0.0, 0.0]];
    let mut st = SpringBeam::init(&x0);
    let (dt, vy) = (1e-3, 0.2);
    let mut o = SpringOut::default();
    for i in 1..=100 {
        let y = vy * dt * i as f64;
        let x = [[0.0; 3], [l, y, 0.0]];
        o = s.step(
            &x,
            &[[0.0; 3], [0.0, vy, 0.0]],
            &[[0.0; 3]; 2],
            l,
            dt,
            &mut st,
        );
    }
    let x21 = [l, 0.02, 0.0];
    let lc = crate::vec3::norm(x21);
    let e = scale(x21, 1.0 / lc);
    let ey = [-e[1], e[0], 0.0];
    let fy = dot([o.f[1][0], o.f[1][1], o.f[1][2]], ey);
    assert!((fy - 300.0 * 0.02 * e[0]).abs() < 1e-3 * fy, "{fy}");
    // Σ moments of the internal loads about node 1 vanish.
    let m = add(
        add(
            [o.f[0][3], o.f[0][4], o.f[0][5]],
            [o.f[1][3], o.f[1][4], o.f[1][5]],
        ),
        cross(x21, [o.f[1][0], o.f[1][1], o.f[1][2]]),
    );
    assert!(crate::vec3::norm(m) < 1e-9, "{m:?}");
    // K_r = K_s l² bounds the step: I/√(I K_s l²).
    let want = (4.0f64 / 500.0)
        .sqrt()
        .min(30.0 / (30.0 * 300.0 * lc * lc).sqrt());
    assert!((o.dt - want).abs() < 1e-12, "{} vs {want}", o.dt);
}

#[test]
fn options_not_computed_are_refused_by_name() {
    let mut g = general([1.0; 6], 0, 0.0);
    g.skew_id = 3;
    assert!(GeneralSpring::new(&g, &[]).unwrap_err().contains("skew_ID"));
    let mut b = beam([1.0; 6]);
    b.ifail2 = 1;
    assert!(SpringBeam::new(&b, &[]).unwrap_err().contains("Ifail2"));
    let mut p = axial(1.0, 0.0, 1.0);
    p.sens_id = 4;
    assert!(AxialSpring::new(&p, &[])
        .unwrap_err()
        .contains("sens_ID = 4"));
    p.sens_id = 0;
    p.dof.fct_id1 = 9;
    assert!(AxialSpring::new(&p, &[])
        .unwrap_err()
        .contains("fct_ID1 = 9"));
}

#[test]
fn a_damper_alone_bounds_the_step_by_2_mu_over_c() {
    // μ = 0.5: the bound 2μ/c, the limit of the spring's bound as k → 0.
    assert_eq!(two_mass_dt([1.0, 1.0], 0.0, 0.5), 2.0);
    assert!((two_mass_dt([1.0, 1.0], 1e-12, 0.5) - 2.0).abs() < 1e-6);
    assert_eq!(two_mass_dt([1.0, 1.0], 0.0, 0.0), f64::INFINITY);
}
