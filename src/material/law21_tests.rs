use super::*;
use crate::model::Loc;

/// The QA deck's material (LOIS_LOI21): ρ 1e4, E 3.1e10, ν 0, A2 3,
/// Kt = B = 1e10, f = (0,0) (0.01,1e8) (0.1,2e8) (2,1e10), with overrides.
fn law(f: impl FnOnce(&mut DruckerPrager)) -> Law21 {
    let mut p = DruckerPrager {
        a0: 0.0,
        a1: 0.0,
        a2: 3.0,
        amax: 1e20,
        fct: 1,
        fscale_p: 1.0,
        kt: 1e10,
        p_min: -1e20,
        p_ext: 0.0,
        b: 1e10,
        mu_max: 1e20,
        x: vec![0.0, 0.01, 0.1, 2.0],
        y: vec![0.0, 1e8, 2e8, 1e10],
    };
    f(&mut p);
    let spec = MaterialSpec {
        id: 1,
        unit_id: 0,
        title: "M21".into(),
        rho: 1e4,
        rho_ref: 0.0,
        e: 3.1e10,
        nu: 0.0,
        law: MaterialLaw::DruckerPrager(p),
        failures: vec![],
        loc: Loc::default(),
    };
    Law21::from_spec(&spec).unwrap()
}

fn f_of(l: &Law21, mu: f64) -> f64 {
    l.curve.at(mu).0
}

/// The QA deck's starter step: L/c = 5.7108835e-4 for L = 1 with
/// c = √((1.333 G + B)/ρ₀) (the reference's 1.333, not 4/3).
#[test]
fn sound_speed_uses_the_reference_constants() {
    let l = law(|_| {});
    assert!((1.0 / l.sound_speed() - 5.7108835073269e-4).abs() < 1e-15);
    // A curve steeper than B sets the speed.
    let steep = law(|p| p.y[3] = 1e11);
    let slope: f64 = (1e11 - 2e8) / 1.9;
    assert!((steep.sound_speed() - ((1.333 * 1.55e10 + slope) / 1e4).sqrt()).abs() < 1e-9);
}

/// Uniaxial compression with the sides fixed (ε_yy = ε_zz = 0) at yield from
/// the first step (A2 = 3: J2 ≤ 3P² is |s_yy| ≤ P): σ_yy = σ_zz = 0 and
/// σ_xx = −3 f(μ) along the path, μ = 1/(1 − ε) − 1.
#[test]
fn uniaxial_strain_at_yield_follows_the_pressure_curve() {
    let l = law(|_| {});
    let (mut sig, mut ep, mut mu_old) = ([0.0; 6], 0.0, 0.0);
    let de = 1e-4;
    let mut strain = 0.0;
    for _ in 0..3000 {
        strain += de;
        let v0_over_v = 1.0 / (1.0 - strain);
        let wp = l
            .solid_own(
                &mut sig,
                &mut ep,
                &mut mu_old,
                [-de / (1.0 - strain), 0.0, 0.0, 0.0, 0.0, 0.0],
                v0_over_v,
            )
            .unwrap();
        assert!(wp >= 0.0);
    }
    let mu = 1.0 / (1.0 - strain) - 1.0;
    let p = f_of(&l, mu);
    assert!(
        (sig[0] + 3.0 * p).abs() < 1e-9 * p,
        "σxx {} against −3P = {}",
        sig[0],
        -3.0 * p
    );
    assert!(
        sig[1].abs() < 1e-9 * p && sig[2].abs() < 1e-9 * p,
        "{sig:?}"
    );
    assert!(ep > 0.0 && (mu_old - mu).abs() < 1e-15);
}

/// Unloading from the curve runs along B below it; tension follows Kt; the
/// P_min cut holds the pressure and wipes the shear.
#[test]
fn unloading_tension_and_the_cut_off() {
    let l = law(|p| {
        p.b = 5e10;
        p.a2 = 0.0;
        p.a0 = 1e30;
    });
    let (mut sig, mut ep, mut mu_old) = ([0.0; 6], 0.0, 0.0);
    // Load hydrostatically to μ = 0.05 (on the curve: 5e10 > every slope).
    l.update(&mut sig, &mut ep, &mut mu_old, [0.0; 6], 0.05);
    let p1 = f_of(&l, 0.05);
    assert!((-sig[0] - p1).abs() < 1e-6 * p1);
    // Back to μ = 0.049: P = p1 − B·0.001 (under the curve).
    l.update(&mut sig, &mut ep, &mut mu_old, [0.0; 6], 0.049);
    let p2 = p1 - 5e10 * 0.001;
    assert!((-sig[0] - p2).abs() < 1e-6 * p1, "{} against {p2}", -sig[0]);
    // Tension from rest: the predictor P_old + K_old μ − K_new μ_old takes
    // K_old = B at μ_old = 0 and lies under the curve Kt μ, so the first
    // step follows B; from then on both moduli are Kt (the reference
    // engine's rule, research note §2.1).
    let (mut s, mut mo) = ([0.0; 6], 0.0);
    l.update(&mut s, &mut ep, &mut mo, [0.0; 6], -1e-4);
    assert!((s[0] - 5e10 * 1e-4).abs() < 1e-3, "{s:?}");
    l.update(&mut s, &mut ep, &mut mo, [0.0; 6], -2e-4);
    assert!((s[0] - (5e10 + 1e10) * 1e-4).abs() < 1e-3, "{s:?}");
    // The cut-off: P_min = −1e5 holds the pressure and no shear is carried.
    let cut = law(|p| {
        p.p_min = -1e5;
        p.a0 = 1e30;
    });
    let (mut s, mut mo) = ([0.0, 0.0, 0.0, 1e4, 0.0, 0.0], 0.0);
    cut.update(
        &mut s,
        &mut ep,
        &mut mo,
        [0.0, 0.0, 0.0, 1e-6, 0.0, 0.0],
        -1e-4,
    );
    assert_eq!(s, [1e5, 1e5, 1e5, 0.0, 0.0, 0.0]);
    assert!(
        (mo - (-1e5 - 0.0) / 1e10).abs() < 1e-20,
        "μ_old shifted by (P_min − P_old)/K_old: {mo}"
    );
}

/// The yield limit: the quadratic clipped to [0, Amax], 0 at or below its root.
#[test]
fn yield_limit_is_the_clipped_quadratic() {
    let l = law(|p| {
        p.a0 = -4.0;
        p.a1 = 0.0;
        p.a2 = 1.0;
        p.amax = 12.0;
    });
    assert_eq!(yield_root(-4.0, 0.0, 1.0), 2.0);
    assert_eq!(l.yield_limit(1.0), 0.0);
    assert_eq!(l.yield_limit(2.0), 0.0);
    assert_eq!(l.yield_limit(3.0), 5.0);
    assert_eq!(l.yield_limit(10.0), 12.0);
    assert_eq!(yield_root(1.0, 0.0, 1.0), f64::NEG_INFINITY);
    assert_eq!(yield_root(2.0, -1.0, 0.0), 2.0);
}
