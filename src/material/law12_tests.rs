use super::*;
use crate::model::Loc;

/// An elastic composite (no yield, no damage), stiff along 1.
pub(crate) fn params() -> Composite3d {
    Composite3d {
        e: [100.0, 10.0, 5.0],
        nu: [0.3, 0.2, 0.01],
        g: [4.0, 3.0, 2.0],
        sig_t: [1e30; 3],
        delta: 0.05,
        b: 0.0,
        n: 1.0,
        fmax: 1e10,
        wplaref: 1.0,
        yt: [INF; 6],
        yc: [INF; 6],
        c: 0.0,
        eps_rate0: 1.0,
        icc: 1,
    }
}

pub(crate) fn law(p: &Composite3d) -> Law12 {
    let spec = MaterialSpec {
        id: 1,
        unit_id: 0,
        title: "composite".into(),
        rho: 1e-3,
        rho_ref: 0.0,
        e: 100.0,
        nu: 0.0,
        law: MaterialLaw::Composite3d(p.clone()),
        failures: vec![],
        loc: Loc::default(),
    };
    Law12::from_spec(&spec).expect("a LAW12 card")
}

/// A uniaxial stress along direction 1 (the increments the compliance
/// gives: Δε = C·(Δσ, 0, 0)) is E11 times its strain, and the shears
/// are G_ij γ_ij, uncoupled.
#[test]
fn elastic_stress_is_the_orthotropic_hooke_law() {
    let p = params();
    let l = law(&p);
    let s = 1.0;
    // C·(s, 0, 0): ε1 = s/E11, ε2 = −ν12 s/E11, ε3 = −ν31 s/E33.
    let de = [
        s / 100.0,
        -0.3 * s / 100.0,
        -0.01 * s / 5.0,
        0.01,
        0.02,
        0.03,
    ];
    let (mut t, mut wp, mut pt) = ([0.0; 6], 0.0, Law12Point::default());
    assert_eq!(l.update(&mut t, &mut wp, &mut pt, de), 0.0);
    assert!(
        (t[0] - s).abs() < 1e-12 && t[1].abs() < 1e-12 && t[2].abs() < 1e-12,
        "{t:?}"
    );
    assert!(
        (t[3] - 0.04).abs() < 1e-15 && (t[4] - 0.06).abs() < 1e-15 && (t[5] - 0.06).abs() < 1e-15
    );
    assert_eq!(wp, 0.0);
    assert!(!l.is_plastic());
}

/// Tsai-Wu with equal yields Y in tension and compression along 1 and no
/// hardening: F = T1²/Y², so the stress of a strain driven uniaxially
/// stops near Y (one correction per step, as the reference), and the
/// plastic work grows by the stress times the plastic strain. The one
/// correction along the gradient at the old stress leaves the stress
/// within one elastic increment of Y.
#[test]
fn tsai_wu_caps_the_fibre_stress_at_its_yield() {
    let mut p = params();
    p.nu = [0.0; 3];
    p.yt = [2.0, INF, INF, INF, INF, INF];
    p.yc = [2.0, INF, INF, INF, INF, INF];
    let l = law(&p);
    assert!(l.is_plastic());
    let (mut t, mut wp, mut pt) = ([0.0; 6], 0.0, Law12Point::default());
    let mut work = 0.0;
    for _ in 0..1000 {
        work += l.update(&mut t, &mut wp, &mut pt, [1e-4, 0.0, 0.0, 0.0, 0.0, 0.0]);
    }
    // Elastic up to ε = 0.02 (T = 2), then held at Y: plastic strain 0.08.
    assert!((t[0] - 2.0).abs() < 0.02, "T1 = {}", t[0]);
    assert!((work - 2.0 * 0.08).abs() < 0.01, "plastic work {work}");
    assert!((wp - work).abs() < 1e-12);
    // Compression is capped at −Y the same way.
    let (mut t, mut wp) = ([0.0; 6], 0.0);
    for _ in 0..1000 {
        l.update(&mut t, &mut wp, &mut pt, [-1e-4, 0.0, 0.0, 0.0, 0.0, 0.0]);
    }
    assert!((t[0] + 2.0).abs() < 0.02, "T1 = {}", t[0]);
}

/// Past σ_t the normal stress is held at (1 − d)σ_t and d grows by DELTA;
/// the open crack then carries no compression.
#[test]
fn tension_damage_holds_the_stress_and_the_crack_carries_no_compression() {
    let mut p = params();
    p.nu = [0.0; 3];
    p.sig_t = [1.0, 1e30, 1e30];
    let l = law(&p);
    let (mut t, mut wp, mut pt) = ([0.0; 6], 0.0, Law12Point::default());
    for _ in 0..15 {
        l.update(&mut t, &mut wp, &mut pt, [0.001, 0.0, 0.0, 0.0, 0.0, 0.0]);
    }
    // Elastic to 1.0 at ε = 0.01; five more steps past it, each adding DELTA.
    assert!((pt.dam[0] - 0.25).abs() < 1e-12, "d = {}", pt.dam[0]);
    assert!((t[0] - 0.8).abs() < 1e-12, "T1 = {}", t[0]);
    for _ in 0..30 {
        l.update(&mut t, &mut wp, &mut pt, [-0.001, 0.0, 0.0, 0.0, 0.0, 0.0]);
        assert!(
            t[0] >= 0.0 || pt.crack[0] == 0.0,
            "compression through an open crack"
        );
    }
}

/// σ_y = 1 + B·Wpⁿ reaching fmax fails the point.
#[test]
fn the_point_fails_when_the_limit_reaches_fmax() {
    let mut p = params();
    p.b = 2.0;
    p.n = 0.5;
    p.fmax = 3.0;
    let l = law(&p);
    assert!(!l.has_failed(0.9));
    assert!(l.has_failed(1.0));
}

/// The wave speed is √(max D_ii/ρ₀) (the card's E is that maximum).
#[test]
fn sound_speed_is_the_largest_normal_stiffness() {
    let p = params();
    let l = law(&p);
    let d = p.stiffness().unwrap();
    assert!(d[0][0] > 100.0);
    // The reader stores max D_ii as E; this card gives 100 as E.
    assert!((l.sound_speed() - (100.0f64 / 1e-3).sqrt()).abs() < 1e-9);
}

/// Work hardening: along a uniaxial path in direction 1 (Y = 2 in tension
/// and compression, so F = T₁²/Y²), the stress follows the grown limit
/// T₁ = Y·√(1 + B·Wpⁿ) (B = 0.5, n = 0.5) within 1% once yielding, Wp the
/// plastic work per volume; no failure below fmax.
#[test]
fn the_yield_limit_grows_with_the_plastic_work() {
    let mut p = params();
    p.nu = [0.0; 3];
    p.yt = [2.0, INF, INF, INF, INF, INF];
    p.yc = [2.0, INF, INF, INF, INF, INF];
    p.b = 0.5;
    p.n = 0.5;
    let l = law(&p);
    let (mut t, mut wp, mut pt) = ([0.0; 6], 0.0, Law12Point::default());
    let (mut work, mut checked) = (0.0, 0);
    for _ in 0..2000 {
        work += l.update(&mut t, &mut wp, &mut pt, [1e-4, 0.0, 0.0, 0.0, 0.0, 0.0]);
        if wp > 0.01 {
            let want = 2.0 * (1.0 + 0.5 * wp.sqrt()).sqrt();
            assert!(
                (t[0] - want).abs() < 0.01 * want,
                "Wp {wp}: T1 {} vs {want}",
                t[0]
            );
            checked += 1;
        }
    }
    assert!(checked > 1000, "{checked} plastic steps");
    assert!((wp - work).abs() < 1e-12 && !l.has_failed(wp));
}

/// The strain-rate term (c ≠ 0) is refused by name.
#[test]
fn a_strain_rate_term_is_refused_by_name() {
    let mut p = params();
    p.c = 0.02;
    let e = law(&p).check_supported().unwrap_err();
    assert!(e.contains("/MAT/LAW12") && e.contains("strain-rate"), "{e}");
}
