//! LAW21 (/MAT/LAW21, /MAT/DPRAG): Drucker-Prager for rock, concrete and
//! soil (reference guide /MAT/LAW21; research note
//! `docs/notes/law21_research.md` §2–3).
//!
//! Per point and step, with μ = ρ/ρ₀ − 1 (P positive in compression,
//! relative to P_ext):
//! * pressure: the elastic predictor P_el = P_old + K_old·μ − K_new·μ_old
//!   (K = B in compression, Kt in tension) and the loading curve P_c =
//!   FscaleP·f(μ) for μ > 0, Kt·μ otherwise; P = min(P_c, P_el) below Mu_max
//!   (unloading and reloading along B under the curve), P_c above it. Under
//!   P_min the pressure is held at P_min, μ_old shifts by (P_min − P_old)/K_old
//!   and the material carries no shear that step (spall);
//! * yield: J2 ≤ g = A0 + A1·P_t + A2·P_t² with P_t = P + P_ext, g clipped to
//!   [0, Amax] and 0 at or below the root P* of the quadratic (J2 itself, not
//!   √J2: Amax caps J2, as the reference engine computes it);
//! * return: the trial deviator s_old + 2G·Δε′ scaled radially by
//!   r = √(g/J2) when J2 > g; ε_p += (1 − r)·√J2/(3G) (the reference's
//!   measure, 1/√3 of the von Mises equivalent);
//! * stress σ = s − P·I.
//!
//! Sound speed for the time step: √((1.333·G + K)/ρ₀) with the reference
//! engine's 1.333 (not 4/3: it reproduces the QA deck's first step to all
//! digits), K = the largest of B, Kt and the curve's largest (unscaled)
//! slope: the reference takes the slope at the current μ, this never gives a
//! larger step.

use super::law::{ElasticConstants, Law};
use super::tabulated_flow::Curve;
use crate::model::{DruckerPrager, MaterialLaw, MaterialSpec};
use serde::{Deserialize, Serialize};

/// LAW21 parameters after default resolution, with the pressure curve.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Law21 {
    pub elastic: ElasticConstants,
    pub p: DruckerPrager,
    curve: Curve,
    /// The root P* of A0 + A1 P + A2 P² (−∞ without one).
    p_star: f64,
    c: f64,
}

/// The largest root of A0 + A1 P + A2 P² = 0 (research note §1.2).
fn yield_root(a0: f64, a1: f64, a2: f64) -> f64 {
    if a2 == 0.0 {
        return if a1 != 0.0 {
            -a0 / a1
        } else {
            f64::NEG_INFINITY
        };
    }
    let delta = a1 * a1 - 4.0 * a0 * a2;
    if delta < 0.0 {
        f64::NEG_INFINITY
    } else {
        (-a1 + delta.sqrt()) / (2.0 * a2)
    }
}

impl Law21 {
    /// The yield limit of J2 at the total pressure `pt`.
    fn yield_limit(&self, pt: f64) -> f64 {
        let p = &self.p;
        if pt <= self.p_star {
            return 0.0;
        }
        (p.a0 + p.a1 * pt + p.a2 * pt * pt).clamp(0.0, p.amax)
    }

    /// One point: stress `sig` (total, tension positive), plastic strain,
    /// μ of the last step `mu_old`, strain increment `deps` (engineering
    /// shears) and μ now. Returns the plastic work per unit volume.
    pub fn update(
        &self,
        sig: &mut [f64; 6],
        eps_p: &mut f64,
        mu_old: &mut f64,
        deps: [f64; 6],
        mu: f64,
    ) -> f64 {
        let p = &self.p;
        let g = self.elastic.g;
        let p_old = -(sig[0] + sig[1] + sig[2]) / 3.0;
        let k_old = if *mu_old >= 0.0 { p.b } else { p.kt };
        let k_new = if mu >= 0.0 { p.b } else { p.kt };
        let p_el = p_old + k_old * mu - k_new * *mu_old;
        let p_c = if mu > 0.0 {
            p.fscale_p * self.curve.at(mu).0
        } else {
            p.kt * mu
        };
        let mut pr = if mu < p.mu_max { p_c.min(p_el) } else { p_c };
        let spall = pr < p.p_min;
        if spall {
            pr = p.p_min;
            *mu_old += (p.p_min - p_old) / k_old;
        } else {
            *mu_old = mu;
        }
        // Trial deviator.
        let tr = (deps[0] + deps[1] + deps[2]) / 3.0;
        let mut s = [
            sig[0] + p_old + 2.0 * g * (deps[0] - tr),
            sig[1] + p_old + 2.0 * g * (deps[1] - tr),
            sig[2] + p_old + 2.0 * g * (deps[2] - tr),
            sig[3] + g * deps[3],
            sig[4] + g * deps[4],
            sig[5] + g * deps[5],
        ];
        let j2 = 0.5 * (s[0] * s[0] + s[1] * s[1] + s[2] * s[2])
            + s[3] * s[3]
            + s[4] * s[4]
            + s[5] * s[5];
        let lim = if spall {
            0.0
        } else {
            self.yield_limit(pr + p.p_ext)
        };
        let r = if j2 <= lim && lim > 0.0 {
            1.0
        } else {
            (lim / (j2 + 1e-14)).sqrt()
        };
        let mut wp = 0.0;
        if r < 1.0 {
            // Plastic work s_new : Δε_p with Δε_p = (s_trial − s_new)/(2G).
            let f = r * (1.0 - r) / (2.0 * g);
            wp = f * 2.0 * j2;
            *eps_p += (1.0 - r) * j2.sqrt() / (3.0 * g);
            s.iter_mut().for_each(|v| *v *= r);
        }
        *sig = [s[0] - pr, s[1] - pr, s[2] - pr, s[3], s[4], s[5]];
        wp
    }
}

impl Law for Law21 {
    const NUMBER: u32 = 21;
    const NAME: &'static str = "Drucker-Prager";
    const HISTORY: &'static [&'static str] =
        &["plastic strain", "volumetric strain μ of the last step"];

    fn from_spec(c: &MaterialSpec) -> Option<Law21> {
        let MaterialLaw::DruckerPrager(p) = &c.law else {
            return None;
        };
        let elastic = ElasticConstants::from_spec(c);
        let curve = Curve {
            eps_dot: 0.0,
            x: p.x.clone(),
            y: p.y.clone(),
        };
        let slope =
            p.x.windows(2)
                .zip(p.y.windows(2))
                .filter(|(x, _)| x[1] > x[0])
                .map(|(x, y)| (y[1] - y[0]) / (x[1] - x[0]))
                .fold(0.0f64, f64::max);
        let k = p.b.max(p.kt).max(slope);
        Some(Law21 {
            c: ((1.333 * elastic.g + k) / elastic.rho_ref).sqrt(),
            elastic,
            p_star: yield_root(p.a0, p.a1, p.a2),
            curve,
            p: p.clone(),
        })
    }

    #[inline]
    fn elastic(&self) -> &ElasticConstants {
        &self.elastic
    }

    fn shell_refusal(&self) -> Option<String> {
        Some("/MAT/LAW21 (Drucker-Prager) is a solid law: on shells it is not computed".into())
    }

    fn is_plastic(&self) -> bool {
        true
    }

    fn volumetric(&self) -> bool {
        true
    }

    #[inline]
    fn solid_own(
        &self,
        sig: &mut [f64; 6],
        eps_p: &mut f64,
        hist: &mut f64,
        deps: [f64; 6],
        v0_over_v: f64,
    ) -> Option<f64> {
        let mu = self.elastic.rho / self.elastic.rho_ref * v0_over_v - 1.0;
        Some(self.update(sig, eps_p, hist, deps, mu))
    }

    #[inline]
    fn sound_speed(&self) -> f64 {
        self.c
    }
}

#[cfg(test)]
#[path = "law21_tests.rs"]
mod tests;
