//! LAW44 against its formulas: the Cowper-Symonds yield at three strain
//! rates along a uniaxial stress path, the cap (ICC), the strain-rate
//! measures (VP) and the refusals.

use super::*;
use crate::material::Material;
use crate::model::Loc;

fn card(c: f64, p: f64, icc: i64, vp: i64) -> MaterialSpec {
    MaterialSpec {
        id: 2,
        unit_id: 0,
        title: "cowper".into(),
        rho: 7.8e-3,
        rho_ref: 0.0,
        e: 2.05e5,
        nu: 0.3,
        law: MaterialLaw::CowperSymonds(CowperSymonds {
            a: 180.0,
            b: 450.0,
            n: 0.5,
            chard: 0.0,
            sig_max0: 300.0,
            c,
            p,
            icc,
            fsmooth: 0,
            f_cut: 0.0,
            vp,
            eps_p_max: NO_LIMIT,
            eps_t1: NO_LIMIT,
            eps_t2: NO_LIMIT,
            fct_idy: 0,
            fscale_y: 0.0,
        }),
        failures: vec![],
        loc: Loc::default(),
    }
}

/// Uniaxial stress (lateral strains of the incompressible plastic flow)
/// past yield at three strain rates: σ_vm = min((a + b ε_p^n)·R, cap·R)
/// with R = 1 + (ε̇/c)^(1/p) at every plastic step of the path.
#[test]
fn yield_follows_cowper_symonds_at_three_strain_rates() {
    let m = Material::from_card(&card(400.0, 5.0, 1, 2));
    let law = Law44::from_spec(&card(400.0, 5.0, 1, 2)).unwrap();
    for rate in [0.0, 4.0, 400.0] {
        let r = 1.0
            + if rate > 0.0 {
                (rate / 400.0f64).powf(0.2)
            } else {
                0.0
            };
        assert_eq!(law.rate_factor(rate), r);
        let p = m.at(rate, 0.0);
        let (mut sig, mut ep) = ([0.0; 6], 0.0);
        let mut checked = 0;
        for _ in 0..400 {
            let d = 5e-5;
            p.solid(&mut sig, &mut ep, [d, -0.5 * d, -0.5 * d, 0.0, 0.0, 0.0]);
            if ep == 0.0 {
                continue;
            }
            // Every plastic step of the path, not only its end.
            let pr = (sig[0] + sig[1] + sig[2]) / 3.0;
            let svm = (1.5 * (0..3).map(|i| (sig[i] - pr).powi(2)).sum::<f64>()).sqrt();
            let want = ((180.0 + 450.0 * ep.sqrt()) * r).min(300.0 * r);
            assert!(
                (svm - want).abs() < 1e-9 * want,
                "rate {rate}, ε_p {ep}: σ_vm {svm} vs {want}"
            );
            checked += 1;
        }
        assert!(ep > 0.005 && checked > 100, "rate {rate}: plastic");
    }
    // ICC = 2: the cap does not scale with the rate.
    let law = Law44::from_spec(&card(400.0, 5.0, 2, 2)).unwrap();
    assert_eq!(law.hardening(400.0, 0.0).unwrap().sig_y(10.0), 300.0);
}

/// VP 2 is the norm of the total strain-rate tensor; VP 3 the deviatoric
/// equivalent; the filter follows F_cut.
#[test]
fn strain_rate_measures_and_filter() {
    let d = [-1.0, 0.5, 0.5, 0.0, 0.0, 0.0];
    let total = Law44::from_spec(&card(400.0, 5.0, 1, 2)).unwrap();
    let dev = Law44::from_spec(&card(400.0, 5.0, 1, 3)).unwrap();
    assert!((total.solid_strain_rate(&d) - 1.5f64.sqrt()).abs() < 1e-15);
    assert!((dev.solid_strain_rate(&d) - 1.0).abs() < 1e-15);
    assert_eq!(total.filter_strain_rate(3.0, 5.0, 1e-3), 5.0);
    let mut f = total.clone();
    f.p.f_cut = 10.0;
    let a = 2.0 * std::f64::consts::PI * 10.0 * 1e-3;
    assert!((f.filter_strain_rate(3.0, 5.0, 1e-3) - (a * 5.0 + (1.0 - a) * 3.0)).abs() < 1e-15);
}

#[test]
fn options_not_computed_are_refused_by_name() {
    let law = |f: &dyn Fn(&mut CowperSymonds)| {
        let mut c = card(400.0, 5.0, 1, 2);
        if let MaterialLaw::CowperSymonds(p) = &mut c.law {
            f(p);
        }
        Law44::from_spec(&c).unwrap()
    };
    assert!(law(&|p| p.vp = 1)
        .check_supported()
        .unwrap_err()
        .contains("VP = 1"));
    assert!(law(&|p| p.fct_idy = 3)
        .check_supported()
        .unwrap_err()
        .contains("fct_IDy"));
    assert!(law(&|p| p.eps_t1 = 0.2)
        .check_supported()
        .unwrap_err()
        .contains("εt1"));
    // Chard: ignored on solids as the reference engine does, refused on shells.
    let k = law(&|p| p.chard = 1.0);
    assert!(k.check_supported().is_ok());
    assert!(k.shell_refusal().unwrap().contains("Chard"));
}
