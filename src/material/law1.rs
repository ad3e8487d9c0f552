//! LAW1 (/MAT/LAW1, /MAT/ELAST): linear elastic, isotropic (Hooke's law;
//! reference guide /MAT/LAW1). No history, no failure, no rate or
//! temperature: every default of [`Law`].

use super::law::{ElasticConstants, Law};
use crate::model::{MaterialLaw, MaterialSpec};
use serde::{Deserialize, Serialize};

/// LAW1 parameters: the elastic constants alone.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Law1(pub ElasticConstants);

impl Law for Law1 {
    const NUMBER: u32 = 1;
    const NAME: &'static str = "elastic";
    const HISTORY: &'static [&'static str] = &[];

    fn from_spec(c: &MaterialSpec) -> Option<Law1> {
        matches!(c.law, MaterialLaw::Elastic).then(|| Law1(ElasticConstants::from_spec(c)))
    }

    #[inline]
    fn elastic(&self) -> &ElasticConstants {
        &self.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::material::Material;
    use crate::model::Loc;

    fn card() -> MaterialSpec {
        MaterialSpec {
            id: 1,
            unit_id: 0,
            title: "steel".into(),
            rho: 7.8e-6,
            rho_ref: 0.0,
            e: 210.0,
            nu: 0.3,
            law: MaterialLaw::Elastic,
            failures: vec![],
            loc: Loc::default(),
        }
    }

    /// One 3-D strain increment from zero stress gives Hooke's stress
    /// σ = λ tr(Δε) I + 2G Δε (engineering shears: τ = G γ), whatever the
    /// plastic strain (LAW1 has no yield), with no plastic work.
    #[test]
    fn one_point_increment_is_hooke() {
        let law = Law1::from_spec(&card()).expect("a LAW1 card");
        let el = *law.elastic();
        assert_eq!(
            (el.rho, el.rho_ref, el.e, el.nu),
            (7.8e-6, 7.8e-6, 210.0, 0.3)
        );
        assert_eq!(el.g, 210.0 / 2.6);
        let m = Material::from_card(&card());
        let p = m.at(1e3, 0.0);
        let d = [1e-3, -2e-4, 5e-4, 2e-3, -1e-3, 4e-4];
        let mut sig = [0.0; 6];
        let mut ep = 0.0;
        let w = p.solid(&mut sig, &mut ep, d);
        let lam = 210.0 * 0.3 / (1.3 * 0.4);
        let tr = d[0] + d[1] + d[2];
        for k in 0..3 {
            let want = lam * tr + 2.0 * el.g * d[k];
            assert!((sig[k] - want).abs() < 1e-14, "σ{k} {} vs {want}", sig[k]);
            assert!((sig[k + 3] - el.g * d[k + 3]).abs() < 1e-14);
        }
        assert_eq!((w, ep), (0.0, 0.0));
        assert_eq!(p.yield_stress(1.0), f64::INFINITY);
        assert!(!law.is_plastic() && !law.has_failed(1e30) && Law1::HISTORY.is_empty());
        assert_eq!(law.sound_speed(), (210.0f64 / 7.8e-6).sqrt());
    }

    #[test]
    fn a_johnson_cook_card_is_not_law1() {
        let mut c = card();
        c.law = MaterialLaw::JohnsonCook(crate::model::JohnsonCook::hardening(0.2, 0.3, 0.5));
        assert!(Law1::from_spec(&c).is_none());
    }
}
