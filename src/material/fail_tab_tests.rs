use super::*;
use crate::model::RateCurve;

/// ε_f(η) = 0.3 + 0.2η on [−1, 1] (two points: extrapolated beyond).
fn rate(fscale: f64, eps_dot: f64) -> RateCurve {
    RateCurve {
        fct: 20,
        fscale,
        eps_dot,
        x: vec![-1.0, 1.0],
        y: vec![0.1, 0.5],
    }
}

fn none() -> ScaleCurve {
    ScaleCurve {
        fct: 0,
        fscale: 1.0,
        x: vec![],
        y: vec![],
    }
}

fn card(ifail_sh: i64, p_thickfail: f64, dcrit: f64, n: f64) -> TabFailure {
    TabFailure {
        ifail_sh,
        ifail_so: 2,
        p_thickfail,
        dcrit,
        d: 0.999,
        n,
        rates: vec![rate(0.5, 1e-5), rate(1.0, 0.5)],
        size: none(),
        el_ref: 1.0,
        temperature: none(),
    }
}

/// Plane-stress triaxiality: uniaxial 1/3, equibiaxial 2/3, shear 0,
/// uniaxial compression −1/3.
#[test]
fn shell_triaxiality_of_simple_states() {
    let t = |s: [f64; 3]| shell_triaxiality(&s);
    assert!((t([2.0, 0.0, 0.0]) - 1.0 / 3.0).abs() < 1e-15);
    assert!((t([1.0, 1.0, 0.0]) - 2.0 / 3.0).abs() < 1e-15);
    assert!(t([0.0, 0.0, 1.0]).abs() < 1e-15);
    assert!((t([0.0, -3.0, 0.0]) + 1.0 / 3.0).abs() < 1e-15);
    assert_eq!(t([0.0; 3]), 0.0);
}

/// ε_f is linear in ε̇ between the rates and extrapolated (not clamped)
/// outside them; each curve is linear in η and extrapolated too.
#[test]
fn failure_strain_interpolates_and_extrapolates_in_rate_and_triaxiality() {
    let f = FailTab::new(&card(3, 0.0, 1.1, 1.0)).unwrap();
    let base = |eta: f64| 0.3 + 0.2 * eta;
    let eta = 1.0 / 3.0;
    let lo = 0.5 * base(eta);
    let hi = base(eta);
    let at = |r: f64| lo + (hi - lo) * (r - 1e-5) / (0.5 - 1e-5);
    for r in [1e-5, 0.1, 0.25, 0.5] {
        assert!(
            (f.failure_strain(eta, r, 1.0, 0.0) - at(r)).abs() < 1e-15,
            "rate {r}"
        );
    }
    // Past the last rate and below the first: the end pair's line.
    assert!((f.failure_strain(eta, 1.0, 1.0, 0.0) - at(1.0)).abs() < 1e-15);
    assert!(f.failure_strain(eta, 1.0, 1.0, 0.0) > hi);
    assert!((f.failure_strain(eta, 0.0, 1.0, 0.0) - at(0.0)).abs() < 1e-15);
    // η beyond the curve's last abscissa: extrapolated from its end segment.
    assert!((f.failure_strain(2.0, 0.5, 1.0, 0.0) - base(2.0)).abs() < 1e-15);
}

/// The element-size and temperature functions scale ε_f by Fscale·g(L₀/EI_ref)
/// and FscaleT·h(T*).
#[test]
fn size_and_temperature_factors_scale_the_failure_strain() {
    let mut c = card(3, 0.0, 1.0, 1.0);
    c.size = ScaleCurve {
        fct: 21,
        fscale: 2.0,
        x: vec![0.0, 10.0],
        y: vec![1.0, 0.5],
    };
    c.el_ref = 2.0;
    c.temperature = ScaleCurve {
        fct: 0,
        fscale: 0.8,
        x: vec![],
        y: vec![],
    };
    let f = FailTab::new(&c).unwrap();
    let plain = FailTab::new(&card(3, 0.0, 1.0, 1.0)).unwrap();
    let e0 = plain.failure_strain(0.0, 0.5, 4.0, 0.0);
    // g(4/2) = 1 − 0.05·2 = 0.9, times 2; h = 0.8.
    let e = f.failure_strain(0.0, 0.5, 4.0, 0.0);
    assert!((e - e0 * 2.0 * 0.9 * 0.8).abs() < 1e-14);
    assert!(f.has_size_function());
}

/// With n = 1 the point fails when Σ Δε_p/ε_f reaches Dcrit (1.1 here, not 1):
/// after 1.1·ε_f of plastic strain at constant ε_f.
#[test]
fn damage_reaches_dcrit_after_dcrit_times_the_failure_strain() {
    let f = FailTab::new(&card(3, 0.0, 1.1, 1.0)).unwrap();
    let ef = 0.25;
    let (mut d, mut steps) = (0.0, 0);
    while !f.accumulate(&mut d, 1.0 / 1024.0, ef) {
        steps += 1;
        assert!(steps < 1000);
    }
    // Each increment adds exactly 1/256: the first D ≥ 1.1 is at 282 (281.6).
    assert_eq!(steps + 1, 282, "1.1 × 0.25 × 1024 increments, rounded up");
    // Failed: no more growth; ε_f ≤ 0 freezes the damage.
    let d1 = d;
    assert!(f.accumulate(&mut d, 0.01, ef));
    assert_eq!(d, d1);
    let mut d2 = 0.5;
    assert!(!f.accumulate(&mut d2, 0.01, -0.1));
    assert_eq!(d2, 0.5);
}

/// n = 2: dD = 2√D dε/ε_f, D = (ε/ε_f)²: the point fails at ε = ε_f·√Dcrit.
/// (The first increment, w = 1 at D = 0, starts the square law ahead by
/// ε_f·√(Δε/ε_f): 1.7e-4 of ε_f with these increments.)
#[test]
fn damage_exponent_two_follows_the_square_law() {
    let f = FailTab::new(&card(3, 0.0, 1.0, 2.0)).unwrap();
    let (ef, de) = (0.3, 1e-7);
    let (mut d, mut eps) = (0.0, 0.0);
    while !f.accumulate(&mut d, de, ef) {
        eps += de;
    }
    eps += de;
    assert!(
        (eps - ef).abs() < 2e-3 * ef,
        "failed at {eps}, expected {ef}"
    );
    let mut d = 0.0;
    let mut e = 0.0;
    while e < 0.5 * ef {
        f.accumulate(&mut d, de, ef);
        e += de;
    }
    assert!((d - 0.25).abs() < 1e-3, "D = {d} at ε_f/2, expected 0.25");
}

/// Ifail_sh 1 deletes at the first failed point, 2 when all have, 3 at the
/// P_thickfail share of the thickness (blank: all; negative: of the count).
#[test]
fn shell_deletion_rules_follow_ifail_sh() {
    let w = [0.125, 0.25, 0.25, 0.25, 0.125]; // 5-point membrane weights
    let share = |idx: &[usize]| idx.iter().map(|&k| w[k]).sum::<f64>();
    let first = FailTab::new(&card(1, 0.0, 1.0, 1.0)).unwrap();
    assert!(first.deletes_shell(share(&[0]), 1, 5));
    assert!(!first.deletes_shell(0.0, 0, 5));
    let all = FailTab::new(&card(2, 0.4, 1.0, 1.0)).unwrap();
    assert!(!all.deletes_shell(share(&[0, 1, 2, 3]), 4, 5));
    assert!(all.deletes_shell(share(&[0, 1, 2, 3, 4]), 5, 5));
    assert!(all.zeroes_shell_point());
    let part = FailTab::new(&card(3, 0.4, 1.0, 1.0)).unwrap();
    assert!(!part.zeroes_shell_point());
    assert!(!part.deletes_shell(share(&[0, 1]), 2, 5), "0.375 < 0.4");
    assert!(part.deletes_shell(share(&[0, 1, 2]), 3, 5), "0.625 >= 0.4");
    let blank = FailTab::new(&card(3, 0.0, 1.0, 1.0)).unwrap();
    assert!(!blank.deletes_shell(share(&[0, 1, 2, 3]), 4, 5));
    assert!(blank.deletes_shell(1.0, 5, 5));
    let count = FailTab::new(&card(3, -0.6, 1.0, 1.0)).unwrap();
    assert!(!count.deletes_shell(share(&[1, 2]), 2, 5));
    assert!(
        count.deletes_shell(share(&[0, 4, 1]), 3, 5),
        "3 of 5 points >= 0.6"
    );
}

/// Solids: Ifail_so 2 leaves σ = p I at a failed point; 1 deletes.
#[test]
fn solid_options_release_the_stress_or_delete() {
    let at = FailAt {
        rate: 0.5,
        len0: 1.0,
        tstar: 0.0,
    };
    let f = FailTab::new(&card(1, 0.0, 1.0, 1.0)).unwrap();
    let mut s = [3.0, 0.0, 0.0, 0.0, 0.0, 0.0];
    let mut d = 0.99;
    assert!(!f.solid(&mut s, &mut d, 0.1, &at));
    assert_eq!(s, [1.0, 1.0, 1.0, 0.0, 0.0, 0.0]);
    let mut c = card(1, 0.0, 1.0, 1.0);
    c.ifail_so = 1;
    let g = FailTab::new(&c).unwrap();
    let (mut s, mut d) = ([3.0, 0.0, 0.0, 0.0, 0.0, 0.0], 0.99);
    assert!(g.solid(&mut s, &mut d, 0.1, &at));
}

/// A uniaxial tension path on a solid point (η = 1/3) at three strain rates:
/// the point fails after Dcrit·ε_f(η, ε̇) of plastic strain (n = 1), ε_f
/// interpolated between the two rate curves, to one increment.
#[test]
fn a_tension_path_fails_at_the_strain_of_its_rate() {
    let mut c = card(1, 0.0, 1.1, 1.0);
    c.ifail_so = 1;
    let f = FailTab::new(&c).unwrap();
    let eta = 1.0 / 3.0;
    let base = 0.3 + 0.2 * eta;
    let dep = 1e-5;
    for r in [1e-5, 0.25, 0.5] {
        let ef = 0.5 * base + 0.5 * base * (r - 1e-5) / (0.5 - 1e-5);
        let at = FailAt {
            rate: r,
            len0: 1.0,
            tstar: 0.0,
        };
        let (mut s, mut d, mut ep) = ([3.0, 0.0, 0.0, 0.0, 0.0, 0.0], 0.0, 0.0);
        loop {
            ep += dep;
            if f.solid(&mut s, &mut d, dep, &at) {
                break;
            }
            assert!(ep < 10.0 * ef, "rate {r}: no failure by {ep}");
        }
        let want = 1.1 * ef;
        assert!(
            (ep - want).abs() <= 1.01 * dep,
            "rate {r}: fails at {ep}, Dcrit·ε_f {want}"
        );
    }
}
