//! LAW44 (/MAT/LAW44, /MAT/COWPER): Cowper-Symonds elasto-plastic law
//! (reference guide /MAT/LAW44; research notes
//! `docs/notes/fail_johnson_law44_research.md` §B,
//! `docs/notes/law44_isolid12_research.md` §1):
//!
//! σ_y = (a + b·ε_p^n)·R,  R = 1 + (ε̇/c)^(1/p)  (R = 1 without c),
//!
//! capped at SIG_max0·R (ICC 1) or SIG_max0 (ICC 2): the Johnson-Cook flow
//! curve of `super::johnson_cook` with the Cowper-Symonds factor. The strain
//! rate is the norm of the total strain-rate tensor (VP 2, the default) or
//! the deviatoric equivalent (VP 3), filtered with α = min(1, 2πF_cut Δt)
//! when Fsmooth or F_cut asks.
//!
//! Chard: the reference engine ignores it on solids (isotropic hardening,
//! research note §1.6) and so does this law there; shells with Chard > 0
//! (kinematic hardening) are refused by name. Refused by name too: the
//! plastic strain rate (VP 1), the yield curve fct_IDy, the tension damage
//! εt1/εt2.

use super::hardening::Hardening;
use super::johnson_cook::Flow;
use super::law::{ElasticConstants, Law};
use crate::model::{CowperSymonds, MaterialLaw, MaterialSpec, NO_LIMIT};
use serde::{Deserialize, Serialize};

/// LAW44 parameters after default resolution.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Law44 {
    pub elastic: ElasticConstants,
    pub p: CowperSymonds,
}

impl Law44 {
    /// The Cowper-Symonds factor R = 1 + (ε̇/c)^(1/p).
    pub fn rate_factor(&self, eps_dot: f64) -> f64 {
        let p = &self.p;
        if p.c > 0.0 && eps_dot > 0.0 {
            1.0 + (eps_dot / p.c).powf(1.0 / p.p)
        } else {
            1.0
        }
    }
}

impl Law for Law44 {
    const NUMBER: u32 = 44;
    const NAME: &'static str = "Cowper-Symonds";
    const HISTORY: &'static [&'static str] = &["equivalent plastic strain"];

    fn from_spec(c: &MaterialSpec) -> Option<Law44> {
        let MaterialLaw::CowperSymonds(p) = &c.law else {
            return None;
        };
        Some(Law44 {
            elastic: ElasticConstants::from_spec(c),
            p: p.clone(),
        })
    }

    #[inline]
    fn elastic(&self) -> &ElasticConstants {
        &self.elastic
    }

    fn check_supported(&self) -> Result<(), String> {
        let p = &self.p;
        let refused = [
            (p.vp == 1, "VP = 1 (the plastic strain rate)".to_string()),
            (
                p.fct_idy != 0,
                format!("fct_IDy = {} (a yield curve)", p.fct_idy),
            ),
            (
                p.eps_t1 < NO_LIMIT || p.eps_t2 < NO_LIMIT,
                "the tension damage εt1, εt2".to_string(),
            ),
        ];
        match refused.into_iter().find(|(r, _)| *r) {
            Some((_, what)) => Err(format!("/MAT/LAW44 {what} is not supported yet")),
            None => Ok(()),
        }
    }

    fn shell_refusal(&self) -> Option<String> {
        (self.p.chard != 0.0).then(|| {
            format!(
                "/MAT/LAW44 Chard = {}: kinematic hardening on shells is not supported yet",
                self.p.chard
            )
        })
    }

    fn is_plastic(&self) -> bool {
        true
    }

    fn is_rate_dependent(&self) -> bool {
        self.p.c > 0.0
    }

    /// VP 2: √(D:D) of the total rate; VP 3: √(⅔ D′:D′).
    fn solid_strain_rate(&self, d: &[f64; 6]) -> f64 {
        if self.p.vp == 3 {
            return super::law::deviatoric_rate(d);
        }
        let diag = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        (diag + 2.0 * (d[3] * d[3] + d[4] * d[4] + d[5] * d[5])).sqrt()
    }

    #[inline]
    fn filter_strain_rate(&self, prev: f64, raw: f64, dt: f64) -> f64 {
        if self.p.f_cut <= 0.0 || dt <= 0.0 {
            return raw;
        }
        let a = (2.0 * std::f64::consts::PI * self.p.f_cut * dt).min(1.0);
        a * raw + (1.0 - a) * prev
    }

    #[inline]
    fn failure_strain(&self) -> f64 {
        self.p.eps_p_max
    }

    #[inline]
    fn has_failed(&self, eps_p: f64) -> bool {
        eps_p >= self.p.eps_p_max
    }

    #[inline]
    fn hardening(&self, eps_dot: f64, _temp: f64) -> Option<Hardening<'_>> {
        let p = &self.p;
        Some(Hardening::JohnsonCook(Flow::new(
            p.a,
            p.b,
            p.n,
            p.sig_max0,
            p.icc,
            self.rate_factor(eps_dot),
        )))
    }
}

#[cfg(test)]
#[path = "law44_tests.rs"]
mod tests;
