//! LAW27 point tests against its formulas (research note
//! `docs/notes/law27_research.md` §2, §9).

use super::*;
use crate::model::{BrittlePlastic, MaterialLaw, MaterialSpec};

/// The QA deck's material 2: E 16600, ν 0.33, a 220, b 420, n 0.6,
/// SIG_max0 270, cracking 0.07 / 0.08 / 0.999 / 0.081.
fn law(c: f64) -> Law27 {
    let spec = MaterialSpec {
        id: 2,
        unit_id: 0,
        title: String::new(),
        rho: 0.0028,
        rho_ref: 0.0,
        e: 16600.0,
        nu: 0.33,
        law: MaterialLaw::BrittlePlastic(BrittlePlastic {
            a: 220.0,
            b: 420.0,
            n: 0.6,
            sig_max0: 270.0,
            c,
            eps_dot0: 1.0,
            icc: 1,
            crack: [[0.07, 0.08, 0.999, 0.081], [0.07, 0.08, 0.999, 0.081]],
        }),
        failures: Vec::new(),
        loc: Default::default(),
    };
    Law27::from_spec(&spec).unwrap()
}

/// Uniaxial stress along y: each step solves Δε_xx for σ_xx = 0 (secant),
/// returns (σ_yy, ε_p, d₁, torn) after the step.
fn uniaxial(
    l: &Law27,
    sig: &mut [f64; 3],
    ep: &mut f64,
    h: &mut [f64; 3],
    total: &mut [f64; 3],
    dy: f64,
    dt: f64,
) -> BrittlePoint {
    let trial = |dx: f64| {
        let (mut s, mut e, mut hh) = (*sig, *ep, *h);
        let t = [total[0] + dx, total[1] + dy, 0.0];
        l.shell_point(&mut s, &mut e, &mut hh, [dx, dy, 0.0], dt, t);
        s[0]
    };
    let (mut a, mut b) = (0.0, -0.5 * dy);
    let (mut fa, mut fb) = (trial(a), trial(b));
    for _ in 0..60 {
        if fb == fa {
            break;
        }
        let c = b - fb * (b - a) / (fb - fa);
        (a, fa) = (b, fb);
        b = c;
        fb = trial(b);
    }
    *total = [total[0] + b, total[1] + dy, 0.0];
    l.shell_point(sig, ep, h, [b, dy, 0.0], dt, *total)
}

#[test]
fn uniaxial_tension_yields_hardens_caps_cracks_and_tears() {
    let l = law(0.0);
    let (mut sig, mut ep, mut h, mut tot) = ([0.0; 3], 0.0, [0.0; 3], [0.0; 3]);
    let dy = 1e-5;
    let mut cracked_at = None;
    let mut torn_at = None;
    for i in 1..=9000 {
        let r = uniaxial(&l, &mut sig, &mut ep, &mut h, &mut tot, dy, 1e-3);
        let eps = i as f64 * dy;
        assert!(sig[0].abs() < 1e-6, "σxx {}", sig[0]);
        if eps < 220.0 / 16600.0 * 0.999 {
            // Elastic: σ = Eε.
            assert!((sig[1] - 16600.0 * eps).abs() < 1e-6 * 16600.0 * eps);
        } else if h[0] == 0.0 && ep > 0.0 {
            // On the curve (a + b ε_pⁿ) or the cap.
            let y = (220.0 + 420.0 * ep.powf(0.6)).min(270.0);
            assert!(
                (sig[1] - y).abs() < 1e-3 * y,
                "σ {} against {y} at ε_p {ep}",
                sig[1]
            );
        }
        if r.cracked {
            cracked_at.get_or_insert(tot[1]);
        }
        if r.torn {
            torn_at = Some(tot[1]);
            break;
        }
    }
    // The largest principal strain is ε_yy: cracks at 0.07, tears past 0.081.
    let c = cracked_at.expect("the point cracks");
    assert!((c - 0.07).abs() <= dy, "cracked at {c}");
    assert!(
        (h[2] - std::f64::consts::FRAC_PI_2).abs() < 1e-9,
        "direction {}",
        h[2]
    );
    let t = torn_at.expect("the point tears");
    assert!(t > 0.081 && t <= 0.081 + dy, "torn at {t}");
    // Near full damage the stress carried across the crack is nearly gone.
    assert!(sig[1] < 0.05 * 270.0, "σ {}", sig[1]);
    assert!(h[0] > 0.99, "d₁ {}", h[0]);
}

#[test]
fn a_crack_carries_no_tension_but_compression() {
    let l = law(0.0);
    // Cracked along y with d₁ = 0.5 and no stress: a tension increment
    // across the crack meets E(1 − d₁), a compression one the full E.
    let h0 = [0.5, 0.0, std::f64::consts::FRAC_PI_2];
    let mut sig = [0.0, 10.0, 0.0];
    let (mut ep, mut h) = (0.0, h0);
    l.shell_point(&mut sig, &mut ep, &mut h, [0.0, 1e-4, 0.0], 1e-3, [0.0; 3]);
    // Direction 1 is y: no Poisson coupling once damaged; k₁ grows but
    // k₁/(ε_m − ε_t) = 0.01 stays under d₁.
    assert!(
        (sig[1] - (10.0 + 0.5 * 16600.0 * 1e-4)).abs() < 1e-9,
        "{sig:?}"
    );
    assert_eq!(h[0], 0.5);
    assert!((h[1] - 1e-4).abs() < 1e-15);
    // Closed in compression: the undamaged plane-stress modulus, with the
    // Poisson coupling back.
    let mut sig = [0.0, -10.0, 0.0];
    let mut h = h0;
    l.shell_point(&mut sig, &mut ep, &mut h, [0.0, -1e-4, 0.0], 1e-3, [0.0; 3]);
    let a11 = 16600.0 / (1.0 - 0.33 * 0.33);
    assert!((sig[1] - (-10.0 - a11 * 1e-4)).abs() < 1e-9, "{sig:?}");
    assert!((sig[0] - (-0.33 * a11 * 1e-4)).abs() < 1e-9, "{sig:?}");
}

#[test]
fn the_strain_rate_raises_the_yield_stress_and_its_cap() {
    // c = 0.1: σ_y = (a + b ε_pⁿ)(1 + c ln(ε̇/ε̇₀)), capped at SIG_max0 × the same.
    for rate in [1.0, 100.0, 1e4] {
        let l = law(0.1);
        let q = 1.0 + 0.1 * (rate as f64).ln();
        let (mut sig, mut ep, mut h, mut tot) = ([0.0; 3], 0.0, [0.0; 3], [0.0; 3]);
        let dy = 1e-5;
        let (mut hardening, mut capped) = (0, 0);
        for _ in 0..5000 {
            uniaxial(&l, &mut sig, &mut ep, &mut h, &mut tot, dy, dy / rate);
            // Every plastic step of the path: on the curve, then on the cap.
            if ep > 1e-4 {
                let curve = (220.0 + 420.0 * ep.powf(0.6)) * q;
                let y = curve.min(270.0 * q);
                assert!(
                    (sig[1] - y).abs() < 2e-3 * y,
                    "rate {rate}, ε_p {ep}: σ {} against {y}",
                    sig[1]
                );
                if curve < 270.0 * q {
                    hardening += 1;
                } else {
                    capped += 1;
                }
            }
        }
        assert!(
            hardening > 50 && hardening + capped > 1000,
            "rate {rate}: {hardening} on the curve, {capped} on the cap"
        );
    }
}
