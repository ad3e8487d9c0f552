//! The one-degree-of-freedom spring law against its formulas, flag by flag.

use super::*;
use crate::model::Loc;

fn func(id: crate::model::Id, x: &[f64], y: &[f64]) -> Function {
    Function {
        id,
        title: String::new(),
        x: x.to_vec(),
        y: y.to_vec(),
        loc: Loc::default(),
    }
}

/// Odd bilinear yield curve: slope 100 up to (1, 100), then 10.
fn f_yield() -> Function {
    func(
        1,
        &[-11.0, -1.0, 0.0, 1.0, 11.0],
        &[-200.0, -100.0, 0.0, 100.0, 200.0],
    )
}

fn law(h: i64, k: f64, fct3: Option<Function>) -> DofLaw {
    let mut d = SpringDof::linear(k, 0.0);
    d.fct_id1 = 1;
    d.h = h;
    d.fct_id3 = fct3.as_ref().map_or(0, |f| f.id);
    let fs = [Some(f_yield()), fct3];
    DofLaw::new(&d, |id| fs.iter().flatten().find(|f| f.id == id).cloned()).unwrap()
}

/// Drives the law along displacements `path` in steps of at most `h`;
/// returns the force at each path point.
fn drive(l: &DofLaw, path: &[f64]) -> Vec<f64> {
    let mut st = DofState::default();
    let mut out = Vec::new();
    let mut x = 0.0;
    for &target in path {
        let n = ((target - x).abs() / 1e-3).ceil().max(1.0) as usize;
        let (x0, mut f) = (x, 0.0);
        for i in 1..=n {
            x = x0 + (target - x0) * i as f64 / n as f64;
            f = l.step(&mut st, x, 0.0, 1.0);
        }
        out.push(f);
    }
    out
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * b.abs().max(1.0)
}

#[test]
fn linear_spring_with_damper_and_raised_stiffness() {
    let mut d = SpringDof::linear(50.0, 3.0);
    let l = DofLaw::new(&d, |_| None).unwrap();
    let mut st = DofState::default();
    assert_eq!(l.step(&mut st, 0.2, 4.0, 1.0), 50.0 * 0.2 + 3.0 * 4.0);
    assert_eq!((l.k_dt(), l.c_dt()), (50.0, 3.0));
    // A curve steeper than K raises K to A·max slope/Ascale.
    d.k = 10.0;
    d.fct_id1 = 1;
    d.a = 2.0;
    d.ascale = 4.0;
    let f = f_yield();
    let l = DofLaw::new(&d, |_| Some(f.clone())).unwrap();
    assert_eq!(l.k_dt(), 2.0 * 100.0 / 4.0);
}

#[test]
fn nonlinear_elastic_follows_the_curve_both_ways() {
    let l = law(0, 10.0, None);
    let f = drive(&l, &[3.0, 0.5, -2.0]);
    assert!(close(f[0], 120.0, 1e-9) && close(f[1], 50.0, 1e-9) && close(f[2], -110.0, 1e-9));
}

/// H = 1: yields on f1, unloads with K, yields in compression when the force
/// reaches the largest tensile force (isotropic: at δ = 2.5 − 190/K), then
/// hardens on f1 of the cumulated displacement (X = −3 − 1.6 at δ = −1).
#[test]
fn isotropic_hardening_yields_at_the_largest_force_in_compression() {
    let l = law(1, 100.0, None);
    let f = drive(&l, &[3.0, 2.5, 0.6, -1.0]);
    assert!(close(f[0], 120.0, 2e-3), "{f:?}");
    assert!(close(f[1], 70.0, 2e-3), "{f:?}");
    assert!(close(f[2], -120.0, 2e-3), "{f:?}");
    assert!(close(f[3], -136.0, 2e-3), "{f:?}");
}

/// H = 2: tension and compression apart, no force between the offsets.
#[test]
fn uncoupled_hardening_has_a_slack_band() {
    let l = law(2, 100.0, None);
    let f = drive(&l, &[3.0, 2.0, 1.0, -0.5, -3.0]);
    assert!(close(f[0], 120.0, 2e-3), "{f:?}");
    assert!(close(f[1], 20.0, 1e-2), "{f:?}");
    assert_eq!((f[2], f[3]), (0.0, -50.0));
    assert!(close(f[4], -120.0, 2e-3), "{f:?}");
}

/// H = 4: kinematic hardening between the upper curve f1 and the lower f3.
#[test]
fn kinematic_hardening_stays_between_the_two_curves() {
    let lower = func(3, &[-10.0, 10.0], &[-250.0, -50.0]);
    let l = law(4, 100.0, Some(lower));
    let f = drive(&l, &[3.0, 0.0, -1.0]);
    assert!(close(f[0], 120.0, 2e-3), "{f:?}");
    // Unloading by 3 at K = 100 would reach −180; the lower curve gives −150 at 0.
    assert!(close(f[1], -150.0, 1e-6), "{f:?}");
    assert!(close(f[2], -160.0, 1e-6), "{f:?}");
}

/// H = 5: unloading on F_m((δ−δ_r)/(δ_m−δ_r))^b down to δ_r = f3(δ_m).
#[test]
fn nonlinear_unloading_reaches_the_residual_displacement() {
    let residual = func(3, &[0.0, 10.0], &[0.0, 5.0]);
    let l = law(5, 200.0, Some(residual));
    let f = drive(&l, &[4.0, 3.0, 2.0, 1.5]);
    assert!(close(f[0], 130.0, 1e-9), "{f:?}");
    // δ_m = 4, δ_r = 2, F_m = 130, b = K(δ_m − δ_r)/F_m.
    let b: f64 = 200.0 * 2.0 / 130.0;
    assert!(
        close(f[1], 130.0 * 0.5f64.powf(b), 1e-2),
        "{f:?} vs {}",
        130.0 * 0.5f64.powf(b)
    );
    assert_eq!((f[2], f[3]), (0.0, 0.0));
}

/// H = 7: loading with K up to f1, unloading with K down to f3, no residual
/// deformation: the loop closes at the origin.
#[test]
fn elastic_hysteresis_loads_on_f1_unloads_on_f3() {
    let unload = func(3, &[-11.0, 0.0, 11.0], &[-110.0, 0.0, 110.0]);
    let l = law(7, 1000.0, Some(unload));
    let f = drive(&l, &[3.0, 2.0, 0.0, 3.0]);
    assert!(close(f[0], 120.0, 1e-3), "{f:?}");
    assert!(close(f[1], 20.0, 1e-3), "{f:?}");
    assert!(f[2].abs() < 1e-9, "{f:?}");
    assert!(close(f[3], 120.0, 1e-3), "{f:?}");
}

/// H = 6: first loading on f1, unloading with the slope of f3 at the force.
#[test]
fn isotropic_hardening_with_nonlinear_unloading_uses_the_slope_of_f3() {
    let unload = func(3, &[0.0, 1.0, 2.0], &[0.0, 50.0, 250.0]);
    let l = law(6, 100.0, Some(unload));
    let f = drive(&l, &[3.0, 2.9]);
    assert!(close(f[0], 120.0, 1e-3), "{f:?}");
    // At 120 the f3 segment holding the force has slope 200: 120 − 200·0.1.
    assert!(close(f[1], 100.0, 1e-3), "{f:?}");
}

/// The rate factor A + B ln(max(1,|δ̇/D|)) + E g(δ̇/F) and the h term, at
/// three rates.
#[test]
fn rate_terms_at_three_rates() {
    let mut d = SpringDof::linear(10.0, 0.0);
    d.fct_id1 = 1;
    d.b = 0.5;
    d.d = 2.0;
    d.fct_id2 = 2;
    d.e = 3.0;
    d.fscale = 4.0;
    d.fct_id4 = 4;
    d.hscale = 7.0;
    let fs = [
        f_yield(),
        func(2, &[0.0, 100.0], &[0.0, 1.0]),
        func(4, &[-100.0, 100.0], &[-200.0, 200.0]),
    ];
    let l = DofLaw::new(&d, |id| fs.iter().find(|f| f.id == id).cloned()).unwrap();
    for rate in [0.5, 20.0, 200.0] {
        let mut st = DofState::default();
        let got = l.step(&mut st, 0.5, rate, 1.0);
        let fac = 1.0 + 0.5 * (rate / 2.0f64).max(1.0).ln() + 3.0 * (rate / 4.0) / 100.0;
        let want = fac * 50.0 + 7.0 * 2.0 * (rate / 4.0);
        assert!(close(got, want, 1e-12), "rate {rate}: {got} vs {want}");
    }
    assert_eq!(l.c_dt(), 7.0 * 2.0 / 4.0);
}

#[test]
fn a_missing_function_is_named() {
    let mut d = SpringDof::linear(1.0, 0.0);
    d.fct_id3 = 9;
    let e = DofLaw::new(&d, |_| None).unwrap_err();
    assert!(e.contains("fct_ID3 = 9"), "{e}");
}
