//! LAW62 point tests against its formulas (research note
//! `docs/notes/law62_research.md` §2, §4.3).

use super::*;
use crate::model::{MaterialLaw, MaterialSpec, ViscoHyperelastic};

fn law(nu: f64, mu: &[f64], alpha: &[f64], gamma: &[f64], tau: &[f64], flag: i64) -> Law62 {
    let g: f64 = mu.iter().sum();
    let spec = MaterialSpec {
        id: 1,
        unit_id: 0,
        title: String::new(),
        rho: 5.5e-8,
        rho_ref: 0.0,
        e: 2.0 * g * (1.0 + nu),
        nu,
        law: MaterialLaw::ViscoHyperelastic(ViscoHyperelastic {
            mu: mu.to_vec(),
            alpha: alpha.to_vec(),
            gamma: gamma.to_vec(),
            tau: tau.to_vec(),
            mu_max: 1e20,
            flag_visc: flag,
        }),
        failures: Vec::new(),
        loc: Default::default(),
    };
    Law62::from_spec(&spec).unwrap()
}

/// The QA deck's two Ogden terms (LOIS_LOI62_cisaillement).
const MU: [f64; 2] = [0.069119e-3, 12.0126e-8];
const ALPHA: [f64; 2] = [30.4979, -3.6961];

/// e = B − I of the simple shear F = I + γ e_x⊗e_z.
fn shear(g: f64) -> [f64; 6] {
    [g * g, 0.0, 0.0, 0.0, 0.0, g]
}

#[test]
fn elastic_simple_shear_follows_the_principal_stretches() {
    let l = law(0.0, &MU, &ALPHA, &[], &[], 0);
    assert_eq!(l.history_len(), 0);
    for g in [0.01, 0.1, 0.2, 0.285] {
        let s = l.stress(&shear(g), 1.0, &mut []).sig;
        // Note §4.3: λ₁,₂ = √(1 + γ²/4) ± γ/2, λ₃ = 1, J = 1;
        // σ_j = Σ(2μ_i/α_i)(λ_j^α_i − 1), σ_xz = (σ₁ − σ₂)/√(4 + γ²).
        let r = (1.0 + g * g / 4.0).sqrt();
        let sj = |lam: f64| -> f64 {
            MU.iter()
                .zip(&ALPHA)
                .map(|(m, a)| 2.0 * m / a * (lam.powf(*a) - 1.0))
                .sum()
        };
        let (s1, s2) = (sj(r + g / 2.0), sj(r - g / 2.0));
        let xz = (s1 - s2) / (4.0 + g * g).sqrt();
        assert!(
            (s[5] - xz).abs() <= 1e-9 * xz.abs(),
            "γ {g}: {} vs {xz}",
            s[5]
        );
        assert!(s[1].abs() <= 1e-12 * xz.abs(), "σ_yy stays 0 at ν = 0");
        assert!((s[0] + s[2] - s1 - s2).abs() <= 1e-9 * xz.abs());
    }
    // The listing's row near the peak (note §4.3): σ_xz(0.2857) = 1.725e-4.
    let s = l.stress(&shear(20.0 / 70.0), 1.0, &mut []).sig;
    assert!((s[5] - 1.725e-4).abs() < 0.001e-4, "{}", s[5]);
}

/// Small-strain shear at a constant rate r: the linear viscoelastic answer
/// σ_xz(t) = G·r·[γ∞·t + Σγ_i τ_i (1 − e^(−t/τ_i))], at three rates.
#[test]
fn shear_at_three_rates_follows_the_prony_series() {
    let (gamma, tau) = ([0.3, 0.2], [1.0, 10.0]);
    for flag in [0, 1] {
        let l = law(0.0, &[1.0], &[2.0], &gamma, &tau, flag);
        assert_eq!(l.history_len(), 18);
        for t_end in [0.1, 3.0, 100.0] {
            let (g_end, steps) = (1e-6, 4000);
            let (rate, dt) = (g_end / t_end, t_end / steps as f64);
            let mut h = vec![0.0; l.history_len()];
            let mut s = [0.0; 6];
            for k in 1..=steps {
                s = l.stress(&shear(rate * dt * k as f64), dt, &mut h).sig;
            }
            let mut expect = (1.0 - 0.5) * t_end;
            for (g, t) in gamma.iter().zip(&tau) {
                expect += g * t * (1.0 - (-t_end / t).exp());
            }
            expect *= rate;
            let err = (s[5] - expect).abs() / expect;
            assert!(
                err < 2e-4,
                "Flag_Visc {flag}, t {t_end}: {} vs {expect}",
                s[5]
            );
        }
    }
    // The instantaneous and the long-term limits.
    let l = law(0.0, &[1.0], &[2.0], &gamma, &tau, 0);
    let mut h = vec![0.0; l.history_len()];
    let fast = l.stress(&shear(1e-6), 1e-9, &mut h).sig[5];
    assert!((fast - 1e-6).abs() < 1e-12, "{fast}");
    let slow = l.stress(&shear(1e-6), 1e6, &mut h).sig[5];
    assert!((slow - 0.5e-6).abs() < 1e-12, "{slow}");
}

#[test]
fn wave_modulus_at_rest_is_k_plus_four_thirds_g() {
    for nu in [0.0, 0.3, 0.45] {
        let plain = law(nu, &[2.0, 1.0], &[2.0, -2.0], &[], &[], 0);
        let g = 3.0;
        let k = 2.0 / 3.0 * g * (1.0 + nu) / (1.0 - 2.0 * nu);
        let want = k + 4.0 / 3.0 * g;
        assert!((plain.rest_rho_c2() - want).abs() < 1e-12 * want, "ν {nu}");
        // With viscosity the reference adds (2/3)·2G (note §2.5).
        let visc = law(nu, &[2.0, 1.0], &[2.0, -2.0], &[0.5], &[1.0], 0);
        let want = want + 4.0 / 3.0 * g;
        assert!((visc.rest_rho_c2() - want).abs() < 1e-12 * want, "ν {nu}");
    }
    // The deck: ρc² = (10/3)G and Δt = 70/c = 1.080598 (the starter's solid step).
    let l = law(
        0.0,
        &MU,
        &ALPHA,
        &[0.34391, 0.10785, 0.070763, 0.077511],
        &[46.2, 1.4e4, 2e5, 8.6e6],
        0,
    );
    let dt = 70.0 / l.sound_speed();
    assert!((dt - 1.080598).abs() < 1e-6, "{dt}");
}

/// A rotated deformation gives the rotated stress (B → R B Rᵀ), with and
/// without viscosity.
#[test]
fn stress_is_objective() {
    let (c, s) = (0.6f64, 0.8f64);
    let r = [[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]];
    // R T Rᵀ of a symmetric tensor [xx yy zz xy yz zx].
    let rot = |t: &[f64; 6]| {
        let m = [[t[0], t[3], t[5]], [t[3], t[1], t[4]], [t[5], t[4], t[2]]];
        let o = |i: usize, j: usize| -> f64 {
            (0..3)
                .flat_map(|k| (0..3).map(move |l| (k, l)))
                .map(|(k, l)| r[i][k] * m[k][l] * r[j][l])
                .sum()
        };
        [o(0, 0), o(1, 1), o(2, 2), o(0, 1), o(1, 2), o(2, 0)]
    };
    let e = [0.02, -0.01, 0.03, 0.015, -0.005, 0.01];
    for flag in [0, 1] {
        let l = law(0.25, &MU, &ALPHA, &[0.3], &[2.0], flag);
        let (mut h1, mut h2) = (vec![0.0; 12], vec![0.0; 12]);
        for step in 1..=3 {
            let f = step as f64 / 3.0;
            let ek: [f64; 6] = std::array::from_fn(|k| f * e[k]);
            let a = rot(&l.stress(&ek, 0.5, &mut h1).sig);
            let b = l.stress(&rot(&ek), 0.5, &mut h2).sig;
            for k in 0..6 {
                assert!(
                    (a[k] - b[k]).abs() < 1e-13,
                    "Flag_Visc {flag}: {a:?} vs {b:?}"
                );
            }
        }
    }
}
