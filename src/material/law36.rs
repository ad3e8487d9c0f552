//! LAW36 (/MAT/LAW36, /MAT/PLAS_TAB): elasto-plastic law with tabulated
//! yield curves σ_y = Fscale_i·f_i(ε_p) at strain rates ε̇_i (reference guide
//! /MAT/LAW36; research note `docs/notes/law36_research.md` §2–4).
//!
//! * Each curve is piecewise linear in ε_p and extrapolated with its end
//!   segments' slopes.
//! * At the element's (filtered) strain rate ε̇, the curves j, j+1 bracketing
//!   it are mixed: σ_y = (1 − r)·σ_j + r·σ_{j+1}, r linear in ε̇ (F_smooth 0,
//!   1) or in ln ε̇ (F_smooth 2); below the first rate the first curve (the
//!   starter inserts a copy of it at ε̇ = 0), above the last rate r is not
//!   clamped (linear extrapolation, as the reference engine).
//! * Strain-rate filter α = min(1, 2π F_cut Δt) (F_cut 10 kHz by default
//!   with several curves).
//! * Failure: a point whose ε_p passes Eps_p_max has failed.
//!
//! Refused by name (not computed yet): kinematic hardening (C_hard > 0), the
//! plastic strain rate (VP = 1), the pressure-dependent yield factor
//! (fct_IDp), Young's modulus evolution (Fct_IDE, CE), and the tension
//! damage and deletion on the principal strain (Eps_t, Eps_m, Eps_f).

use super::hardening::Hardening;
use super::law::{ElasticConstants, Law};
pub use super::tabulated_flow::{Curve, TabFlow};
use crate::model::{MaterialLaw, MaterialSpec, NO_LIMIT};
use serde::{Deserialize, Serialize};

/// LAW36 parameters after default resolution.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Law36 {
    pub elastic: ElasticConstants,
    /// By increasing rate; the first at ε̇ = 0 when there are several.
    pub curves: Vec<Curve>,
    pub log_rate: bool,
    pub f_cut: f64,
    pub eps_p_max: f64,
    /// Kept so that the options not computed are refused by name.
    refused: Option<String>,
    /// Tension damage and deletion (Eps_t, Eps_m, Eps_f), when given.
    pub tension: Option<[f64; 3]>,
    /// The smallest ordinate of every curve (elastic pre-test).
    y_min: f64,
}

/// Tension damage (research note eq. 9): F = clamp((Eps_m − ε₁)/(Eps_m −
/// Eps_t), 1e-20, 1) of the largest principal strain ε₁.
#[inline]
pub fn tension_factor(eps_t: f64, eps_m: f64, e1: f64) -> f64 {
    ((eps_m - e1) / (eps_m - eps_t)).clamp(1e-20, 1.0)
}

fn refusal(t: &crate::model::TabulatedPlasticity) -> Option<&'static str> {
    let refused = [
        (t.chard != 0.0, "kinematic hardening (C_hard > 0)"),
        (t.vp == 1, "the plastic strain rate (VP = 1)"),
        (t.fct_p != 0, "a pressure-dependent yield factor (fct_IDp)"),
        (
            t.fct_e != 0 || t.ce != 0.0,
            "Young's modulus evolution (Fct_IDE, EInf, CE)",
        ),
    ];
    refused.into_iter().find(|r| r.0).map(|r| r.1)
}

impl Law for Law36 {
    const NUMBER: u32 = 36;
    const NAME: &'static str = "tabulated plasticity";
    const HISTORY: &'static [&'static str] = &["equivalent plastic strain"];

    fn from_spec(c: &MaterialSpec) -> Option<Law36> {
        let MaterialLaw::Tabulated(t) = &c.law else {
            return None;
        };
        let mut curves: Vec<Curve> = t
            .curves
            .iter()
            .map(|rc| Curve {
                eps_dot: rc.eps_dot,
                x: rc.x.clone(),
                y: rc.y.iter().map(|y| y * rc.fscale).collect(),
            })
            .collect();
        // Several curves: the starter inserts a copy of the first at ε̇ = 0.
        if curves.len() > 1 && curves[0].eps_dot != 0.0 {
            let first = Curve {
                eps_dot: 0.0,
                ..curves[0].clone()
            };
            curves.insert(0, first);
        }
        let y_min = curves
            .iter()
            .flat_map(|c| c.y.iter())
            .fold(f64::INFINITY, |m, &y| m.min(y));
        Some(Law36 {
            elastic: ElasticConstants::from_spec(c),
            curves,
            log_rate: t.fsmooth == 2,
            f_cut: t.f_cut,
            eps_p_max: t.eps_p_max,
            refused: refusal(t).map(String::from),
            tension: (t.eps_t < NO_LIMIT || t.eps_m < NO_LIMIT || t.eps_f < NO_LIMIT)
                .then_some([t.eps_t, t.eps_m, t.eps_f]),
            y_min,
        })
    }

    fn elastic(&self) -> &ElasticConstants {
        &self.elastic
    }

    fn check_supported(&self) -> Result<(), String> {
        match &self.refused {
            Some(what) => Err(format!("/MAT/LAW36: {what} is not computed yet")),
            None => Ok(()),
        }
    }

    fn is_plastic(&self) -> bool {
        true
    }

    fn is_rate_dependent(&self) -> bool {
        self.curves.len() > 1
    }

    /// ε̇ ← α ε̇_raw + (1 − α) ε̇_prev, α = min(1, 2π F_cut Δt) (no filter
    /// when F_cut = 0).
    #[inline]
    fn filter_strain_rate(&self, prev: f64, raw: f64, dt: f64) -> f64 {
        if self.f_cut <= 0.0 || dt <= 0.0 {
            return raw;
        }
        let a = (2.0 * std::f64::consts::PI * self.f_cut * dt).min(1.0);
        a * raw + (1.0 - a) * prev
    }

    /// Plane-stress wave speed √(E/((1 − ν²)ρ₀)): the ACCELEROMETRES
    /// listing's first step (0.8767E-03 at /DT 0.9) is √(1 − ν²) = 0.912
    /// of the √(E/ρ₀) one with ν = 0.41.
    fn sound_speed(&self) -> f64 {
        let el = &self.elastic;
        (el.e / ((1.0 - el.nu * el.nu) * el.rho_ref)).sqrt()
    }

    fn tension_damage(&self) -> Option<[f64; 3]> {
        self.tension
    }

    /// The reference engine deletes the element at the first point past
    /// Eps_p_max (research note §4).
    fn deletes_at_first_failed_point(&self) -> bool {
        true
    }

    #[inline]
    fn failure_strain(&self) -> f64 {
        self.eps_p_max
    }

    #[inline]
    fn has_failed(&self, eps_p: f64) -> bool {
        eps_p >= self.eps_p_max
    }

    fn hardening(&self, eps_dot: f64, _temp: f64) -> Option<Hardening<'_>> {
        let c = &self.curves;
        if c.len() == 1 {
            return Some(Hardening::Tabulated(TabFlow {
                lo: &c[0],
                hi: &c[0],
                r: 0.0,
                y_min: self.y_min,
                scale: 1.0,
            }));
        }
        let j = c[1..c.len() - 1].partition_point(|k| k.eps_dot <= eps_dot);
        let (a, b) = (c[j].eps_dot, c[j + 1].eps_dot);
        let r = if self.log_rate {
            let lo = a.max(1e-20);
            (eps_dot.max(1e-20) / lo).ln() / (b / lo).ln()
        } else {
            (eps_dot - a) / (b - a)
        };
        Some(Hardening::Tabulated(TabFlow {
            lo: &c[j],
            hi: &c[j + 1],
            r: r.max(0.0),
            y_min: self.y_min,
            scale: 1.0,
        }))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{Loc, RateCurve, TabulatedPlasticity};

    fn card(curves: Vec<RateCurve>, fsmooth: i64) -> MaterialSpec {
        MaterialSpec {
            id: 1,
            unit_id: 0,
            title: String::new(),
            rho: 7.8e-6,
            rho_ref: 0.0,
            e: 210.0,
            nu: 0.3,
            law: MaterialLaw::Tabulated(TabulatedPlasticity {
                eps_p_max: NO_LIMIT,
                eps_t: NO_LIMIT,
                eps_m: NO_LIMIT,
                eps_f: NO_LIMIT,
                fsmooth,
                chard: 0.0,
                f_cut: 0.0,
                vp: 0,
                fct_p: 0,
                fscale_p: 1.0,
                fct_e: 0,
                e_inf: 0.0,
                ce: 0.0,
                curves,
            }),
            failures: vec![],
            loc: Loc::default(),
        }
    }

    fn curve(fscale: f64, eps_dot: f64) -> RateCurve {
        RateCurve {
            fct: 1,
            fscale,
            eps_dot,
            x: vec![0.0, 0.1, 0.3],
            y: vec![0.2, 0.3, 0.35],
        }
    }

    /// Piecewise-linear curve, end segments extended, Fscale applied.
    #[test]
    fn one_curve_is_interpolated_and_extrapolated() {
        let l = Law36::from_spec(&card(vec![curve(2.0, 0.0)], 0)).unwrap();
        let h = l.hardening(0.0, 0.0).unwrap();
        assert!((h.sig_y(0.05) - 2.0 * 0.25).abs() < 1e-15);
        assert!((h.slope(0.05) - 2.0).abs() < 1e-12);
        assert!(
            (h.sig_y(0.5) - 2.0 * (0.35 + 0.25 * 0.2)).abs() < 1e-14,
            "last slope 0.25"
        );
        assert!((h.sig_y(0.2) - 2.0 * 0.325).abs() < 1e-14);
    }

    /// Two rates: below the first (given at ε̇ = 10, a copy is put at 0) the
    /// first curve, between them linear in ε̇ (or ln ε̇), above extrapolated.
    #[test]
    fn curves_are_mixed_by_strain_rate() {
        let l = Law36::from_spec(&card(vec![curve(1.0, 10.0), curve(2.0, 100.0)], 0)).unwrap();
        assert_eq!(l.curves.len(), 3);
        let y = |r: f64| l.hardening(r, 0.0).unwrap().sig_y(0.0);
        assert!((y(5.0) - 0.2).abs() < 1e-15);
        assert!((y(55.0) - 0.3).abs() < 1e-15, "halfway: 0.2 → 0.4");
        assert!(
            (y(190.0) - 0.6).abs() < 1e-12,
            "extrapolated past the last rate"
        );
        let g = Law36::from_spec(&card(vec![curve(1.0, 10.0), curve(2.0, 1000.0)], 2)).unwrap();
        let y = g.hardening(100.0, 0.0).unwrap().sig_y(0.0);
        assert!((y - 0.3).abs() < 1e-12, "halfway in ln ε̇: {y}");
    }

    /// The options not computed are refused by name.
    #[test]
    fn options_not_computed_are_refused() {
        let mut c = card(vec![curve(1.0, 0.0)], 0);
        if let MaterialLaw::Tabulated(t) = &mut c.law {
            t.chard = 0.5;
        }
        let e = Law36::from_spec(&c).unwrap().check_supported().unwrap_err();
        assert!(e.contains("C_hard"), "{e}");
    }

    /// Tension damage: 1 below Eps_t, linear to 0 (1e-20) at Eps_m, and it
    /// scales the yield stress and its slope.
    #[test]
    fn tension_damage_scales_the_yield() {
        assert_eq!(tension_factor(0.01, 0.02, 0.005), 1.0);
        assert!((tension_factor(0.01, 0.02, 0.0125) - 0.75).abs() < 1e-14);
        assert_eq!(tension_factor(0.01, 0.02, 0.03), 1e-20);
        let l = Law36::from_spec(&card(vec![curve(1.0, 0.0)], 0)).unwrap();
        let Some(Hardening::Tabulated(f)) = l.hardening(0.0, 0.0) else {
            panic!()
        };
        let g = f.scaled(0.5);
        assert!((g.sig_y(0.05) - 0.125).abs() < 1e-15 && (g.slope(0.05) - 0.5).abs() < 1e-12);
    }
}
