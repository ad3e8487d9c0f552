use super::*;
use crate::model::{Loc, RateCurve};

/// A curve through (0, 0) and (1, s), at strain rate `rate`.
fn line(s: f64, rate: f64) -> RateCurve {
    RateCurve {
        fct: 1,
        fscale: 1.0,
        eps_dot: rate,
        x: vec![0.0, 1.0],
        y: vec![0.0, s],
    }
}

fn foam(loading: Vec<RateCurve>, nu: f64, iflag: i64) -> Law70 {
    let spec = MaterialSpec {
        id: 1,
        unit_id: 0,
        title: "foam".into(),
        rho: 1e-3,
        rho_ref: 0.0,
        e: 0.5,
        nu,
        law: MaterialLaw::FoamTab(FoamTab {
            e_max: 10.0,
            eps_max: 0.8,
            f_cut: 0.0,
            israte: 0,
            iflag,
            shape: 2.0,
            hys: 0.0,
            itens: 0,
            loading,
            unloading: vec![],
        }),
        failures: vec![],
        loc: Loc::default(),
    };
    Law70::from_spec(&spec).expect("a LAW70 card")
}

/// Uniaxial strain εxx from 0 to `to` in `n` equal steps at the rate ε̇.
fn stretch(l: &Law70, pt: &mut Law70Point, to: f64, n: usize, rate: f64) -> [f64; 6] {
    let d = (to - pt.eps[0]) / n as f64;
    let mut sig = [0.0; 6];
    for _ in 0..n {
        sig = l.update(pt, &[d, 0.0, 0.0, 0.0, 0.0, 0.0], rate);
    }
    sig
}

#[test]
fn the_stress_follows_the_curve_of_the_strain_rate() {
    // Curves 1·ε at rate 0, 2·ε at 1, 4·ε at 2; ε = 0.5 (compression).
    let l = foam(vec![line(1.0, 0.0), line(2.0, 1.0), line(4.0, 2.0)], 0.0, 4);
    for (rate, want) in [(0.0, 0.5), (0.5, 0.75), (1.5, 1.5), (3.0, 3.0)] {
        let mut pt = Law70Point::default();
        let s = stretch(&l, &mut pt, -0.5, 10, rate);
        assert!((s[0] + want).abs() < 1e-12, "rate {rate}: {s:?}");
        assert!(s[1].abs() < 1e-15 && s[3].abs() < 1e-15, "ν = 0: uniaxial");
    }
}

#[test]
fn past_eps_max_the_curve_goes_on_with_e_max() {
    let l = foam(vec![line(1.0, 0.0)], 0.0, 4);
    let mut pt = Law70Point::default();
    let s = stretch(&l, &mut pt, -0.9, 9, 0.0);
    // f(0.8) + E_max·(0.9 − 0.8) = 0.8 + 1.0.
    assert!((s[0] + 1.8).abs() < 1e-12, "{s:?}");
}

#[test]
fn unloading_scales_by_the_work_ratio() {
    // Hys = 0, Shape = 2: R = (W/W_max)²; along f = ε the trapezoid is exact.
    let l = foam(vec![line(1.0, 0.0)], 0.0, 4);
    let mut pt = Law70Point::default();
    stretch(&l, &mut pt, 0.4, 8, 0.0);
    assert!((pt.w_max - 0.08).abs() < 1e-12, "{}", pt.w_max);
    let s = stretch(&l, &mut pt, 0.2, 4, 0.0);
    assert!((pt.w - 0.02).abs() < 1e-12, "{}", pt.w);
    let r: f64 = (0.02f64 / 0.08).powi(2);
    assert!((s[0] - 0.2 * r).abs() < 1e-12, "{s:?}");
    // Reloading follows the curve again.
    let s = stretch(&l, &mut pt, 0.3, 1, 0.0);
    assert!((s[0] - 0.3).abs() < 1e-12, "{s:?}");
}

#[test]
fn iflag_3_keeps_the_pressure_on_unloading() {
    let l = foam(vec![line(1.0, 0.0)], 0.3, 3);
    let mut pt = Law70Point::default();
    stretch(&l, &mut pt, 0.4, 8, 0.0);
    let s = stretch(&l, &mut pt, 0.2, 4, 0.0);
    let loaded = l.radial(&pt, l.curve_values(0.2, 0.0).0);
    let p = (loaded[0] + loaded[1] + loaded[2]) / 3.0;
    assert!(((s[0] + s[1] + s[2]) / 3.0 - p).abs() < 1e-12);
    let r: f64 = (pt.w / pt.w_max).powi(2);
    assert!((s[0] - p - r * (loaded[0] - p)).abs() < 1e-12);
}

#[test]
fn shear_has_the_curve_value_as_its_tensor_norm() {
    // γ = 0.2: ε_t = γ/√2, |σ| = √2·τ = f(ε_t).
    let l = foam(vec![line(1.0, 0.0)], 0.2, 4);
    let mut pt = Law70Point::default();
    let s = l.update(&mut pt, &[0.0, 0.0, 0.0, 0.2, 0.0, 0.0], 0.0);
    let et = 0.2 / 2f64.sqrt();
    assert!((s[3] * 2f64.sqrt() - et).abs() < 1e-12, "{s:?}");
    assert!(s[0].abs() < 1e-15);
}

#[test]
fn the_secant_modulus_grows_and_sets_the_wave_speed() {
    // A curve softer than E0 past ε = 0.2 (ε_s > 0): E grows by
    // (E_max − E0)/eps_max per unit of ε_s, capped at E_max.
    let mut c = line(1.0, 0.0);
    c.x = vec![0.0, 0.2, 1.0];
    c.y = vec![0.0, 0.1, 0.14];
    let l = foam(vec![c], 0.0, 4);
    let mut pt = Law70Point::default();
    assert!((l.point_sound_speed(&pt) - (0.5f64 / 1e-3).sqrt()).abs() < 1e-9);
    stretch(&l, &mut pt, 0.6, 60, 0.0);
    assert!(pt.e > 0.5 && pt.e <= 10.0, "{}", pt.e);
    assert!((l.point_sound_speed(&pt) - (pt.e / 1e-3).sqrt()).abs() < 1e-9);
    // The stress is the curve's whatever E.
    let s = stretch(&l, &mut pt, 0.61, 1, 0.0);
    assert!((s[0] - (0.1 + 0.04 * 0.41 / 0.8)).abs() < 1e-12, "{s:?}");
}

#[test]
fn the_unloading_curves_rules_are_refused_by_name() {
    let l = foam(vec![line(1.0, 0.0)], 0.0, 0);
    assert!(l.check_supported().unwrap_err().contains("Iflag = 0"));
    assert!(foam(vec![line(1.0, 0.0)], 0.0, 4).check_supported().is_ok());
}

#[test]
fn the_total_strain_rate_is_filtered_at_f_cut() {
    let mut l = foam(vec![line(1.0, 0.0)], 0.0, 4);
    let d = [1.0, 0.0, 0.0, 0.5, 0.0, 0.0];
    assert!((l.solid_strain_rate(&d) - 1.5f64.sqrt()).abs() < 1e-15);
    assert_eq!(l.filter_strain_rate(2.0, 1.0, 0.01), 1.0);
    l.p.israte = 1;
    l.p.f_cut = 0.1;
    let a = 2.0 * std::f64::consts::PI * 0.1 * 0.01;
    assert!((l.filter_strain_rate(2.0, 1.0, 0.01) - (a + (1.0 - a) * 2.0)).abs() < 1e-15);
}
