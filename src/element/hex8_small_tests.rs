//! Ismstr = 1 (`super::super::hex8_small`) and LAW70 on the one-point brick.

use super::tests::{mat, resolved};
use super::*;
use crate::material::ElasticConstants;

/// LAW1 with ν = 0 (no lateral strain: the bar stays a unit square).
fn bar_material() -> Material {
    Material::Elastic(crate::material::Law1(ElasticConstants {
        rho: 7.8e-6,
        rho_ref: 7.8e-6,
        e: 210.0,
        nu: 0.0,
        g: 105.0,
    }))
}

fn section(ismstr: i64, m: &Material) -> SolidSection {
    let mut r = resolved(1, 0.0, 0.0, 0.0);
    r.ismstr = ismstr;
    let mut s = SolidSection::new(&r, m).unwrap();
    (s.qa, s.qb, s.h) = (0.0, 0.0, 0.0);
    s
}

fn unit_cube() -> [[f64; 3]; 8] {
    std::array::from_fn(|a| {
        let (i, j) = ([0, 1, 1, 0][a % 4], [0, 0, 1, 1][a % 4]);
        [i as f64, j as f64, (a / 4) as f64]
    })
}

/// Stretches the unit cube along z by `dl` in `n` steps of `dt` (top face
/// moving, bottom fixed); the last step's output.
fn stretch(
    s: &SolidSection,
    st: &mut Hex8State,
    x: &mut [[f64; 3]; 8],
    dl: f64,
    n: usize,
) -> Hex8Out {
    let dt = 1e-3;
    let mut v = [[0.0; 3]; 8];
    for a in 4..8 {
        v[a][2] = dl / (n as f64 * dt);
    }
    let mut o = Hex8Out::default();
    for _ in 0..n {
        for a in 4..8 {
            x[a][2] += v[a][2] * dt;
        }
        o = hex8_step(s, x, &v, dt, st);
    }
    o
}

#[test]
fn small_strain_is_the_engineering_strain_on_the_initial_area() {
    // ΔL/L0 = 0.1: σ = E·0.1 = 21 under small strain; ln(1.1)·E under the
    // rate form (Ismstr 4).
    let m = bar_material();
    for (ismstr, want) in [(1, 21.0), (4, 210.0 * 1.1f64.ln())] {
        let s = section(ismstr, &m);
        let mut x = unit_cube();
        let mut st = hex8_init(&s, &x);
        assert_eq!(st.small.is_some(), ismstr == 1);
        let o = stretch(&s, &mut st, &mut x, 0.1, 200);
        let tol = if ismstr == 1 { 1e-12 } else { 1e-4 };
        assert!(
            (st.sig[2] - want).abs() < tol * want,
            "Ismstr {ismstr}: {}",
            st.sig[2]
        );
        let top: f64 = (4..8).map(|a| o.f[a][2]).sum();
        assert!((top - want).abs() < tol * want, "Ismstr {ismstr}: {top}");
        if ismstr == 1 {
            // The time step of the initial shape, the density of the strain.
            assert!((o.dt - 1.0 / (210.0f64 / 7.8e-6).sqrt()).abs() < 1e-15);
            let r = st.small.as_deref().unwrap();
            assert!((r.rho_ratio - 0.9).abs() < 1e-12, "{}", r.rho_ratio);
        }
    }
}

#[test]
fn a_small_strain_brick_turned_rigidly_keeps_its_stress_turned() {
    let m = mat();
    let s = section(1, &m);
    // A stress in the undeformed shape (as an initial stress): a rigid turn
    // of a deformed shape would strain it (small strain is not objective).
    let mut x = unit_cube();
    let mut st = hex8_init(&s, &x);
    let sig0 = [1.2, 1.2, 2.8, 0.0, 0.0, 0.0];
    st.sig = sig0;
    // A quarter turn about x, in 4000 steps, positions exact.
    let x0 = x;
    let (n, dt) = (4000, 1e-4);
    let mut o = Hex8Out::default();
    for i in 1..=n {
        let th = std::f64::consts::FRAC_PI_2 * i as f64 / n as f64;
        let (c, s_) = (th.cos(), th.sin());
        let x1: [[f64; 3]; 8] = std::array::from_fn(|a| {
            let p = x0[a];
            [p[0], c * p[1] - s_ * p[2], s_ * p[1] + c * p[2]]
        });
        let v: [[f64; 3]; 8] =
            std::array::from_fn(|a| std::array::from_fn(|k| (x1[a][k] - x[a][k]) / dt));
        x = x1;
        o = hex8_step(&s, &x, &v, dt, &mut st);
    }
    // z turned onto y: σyy ← σzz, σzz ← σyy (the strain rate taken on the
    // shape turned to mid-step: no strain of the first order in the angle).
    let tol = 1e-5 * sig0[2].abs();
    assert!(
        (st.sig[1] - sig0[2]).abs() < tol,
        "{:?} vs {sig0:?}",
        st.sig
    );
    assert!(
        (st.sig[2] - sig0[1]).abs() < tol,
        "{:?} vs {sig0:?}",
        st.sig
    );
    // The reference shape turned with the body: the forces are σ b(x).
    let (b, _) = hex_gradient(&x);
    for a in 0..8 {
        let f = stress_force(&st.sig, b[a]);
        for k in 0..3 {
            assert!(
                (o.f[a][k] - f[k]).abs() < 1e-2 * tol,
                "{a}: {:?} vs {f:?}",
                o.f[a]
            );
        }
    }
}

/// A LAW70 foam: E0 = 0.01, ν = 0, E_max = 10, eps_max = 0.8, one static
/// curve σ = 0.002·ε + 0.05·ε² (as points), Iflag 4, Shape 2, Hys ~ 0.
fn foam() -> Material {
    use crate::model::{FoamTab, Loc, MaterialLaw, MaterialSpec, RateCurve};
    let xs: Vec<f64> = (0..=100).map(|i| i as f64 * 0.01).collect();
    let ys = xs.iter().map(|e| 0.002 * e + 0.05 * e * e).collect();
    Material::from_card(&MaterialSpec {
        id: 1,
        unit_id: 0,
        title: "foam".into(),
        rho: 5e-8,
        rho_ref: 0.0,
        e: 0.01,
        nu: 0.0,
        law: MaterialLaw::FoamTab(FoamTab {
            e_max: 10.0,
            eps_max: 0.8,
            f_cut: 0.0,
            israte: 0,
            iflag: 4,
            shape: 2.0,
            hys: 1e-20,
            itens: 0,
            loading: vec![RateCurve {
                fct: 1,
                fscale: 1.0,
                eps_dot: 0.0,
                x: xs,
                y: ys,
            }],
            unloading: vec![],
        }),
        failures: vec![],
        loc: Loc::default(),
    })
}

#[test]
fn a_foam_brick_follows_its_curve_and_steps_with_its_secant_modulus() {
    let m = foam();
    let mut r = resolved(1, 1.1, 0.05, 0.1);
    r.ismstr = 1;
    r.q_blank = true;
    let s = SolidSection::new(&r, &m).unwrap();
    // qa = qb = 0 on the card: no bulk viscosity with LAW70 (FACQ0 = 0).
    assert_eq!((s.qa, s.qb), (0.0, 0.0));
    let mut x = unit_cube();
    let mut st = hex8_init(&s, &x);
    // At rest: Δt = L/c, c = √(E0/ρ0) (the QA deck's 0.9·5/447.21).
    let o = hex8_step(&s, &x, &[[0.0; 3]; 8], 0.0, &mut st);
    assert!(
        (o.dt - 1.0 / (0.01f64 / 5e-8).sqrt()).abs() < 1e-15,
        "{}",
        o.dt
    );
    // Compressed by 30 %: |σ| = f(0.3) with the stress along z.
    let o = stretch(&s, &mut st, &mut x, -0.3, 300);
    let want = -(0.002 * 0.3 + 0.05 * 0.09);
    assert!((st.sig[2] - want).abs() < 1e-12, "{:?}", st.sig);
    let pt = st.foam.as_deref().unwrap();
    assert!(pt.e > 0.01, "the secant modulus grew: {}", pt.e);
    let c = (pt.e / 5e-8).sqrt();
    assert!(
        (o.dt - 1.0 / c).abs() < 1e-12 / c,
        "{} vs {}",
        o.dt,
        1.0 / c
    );
    // Unloading halfway back: σ scaled by (W/W_max)².
    let o2 = stretch(&s, &mut st, &mut x, 0.15, 150);
    let pt = st.foam.as_deref().unwrap();
    let r = (pt.w / pt.w_max).powi(2);
    let back = -(0.002 * 0.15 + 0.05 * 0.0225) * r;
    assert!((st.sig[2] - back).abs() < 1e-12, "{} vs {back}", st.sig[2]);
    assert!(r < 0.3 && o2.d_eint < 0.0);
}

#[test]
fn small_strain_and_law70_are_refused_off_the_one_point_bricks() {
    let mut r = resolved(1, 1.1, 0.05, 0.1);
    r.ismstr = 1;
    let e = SolidSection::for_tetra(&resolved(1, 1.1, 0.05, 0.1), &foam()).unwrap_err();
    assert!(e.contains("/MAT/LAW70 on tetrahedra"), "{e}");
    let e = SolidSection::for_tetra(&r, &mat()).unwrap_err();
    assert!(e.contains("Ismstr = 1 (small strain) on tetrahedra"), "{e}");
}
