//! /FAIL/TAB: tabulated failure (reference guide /FAIL/TAB; research note
//! `docs/notes/fail_tab_research.md` §3).
//!
//! At every integration point, after the material update, with the new stress:
//! * triaxiality η = p/σ_vm (tension positive; plane stress on shells, the
//!   transverse shear left out);
//! * ε_f = interp_ε̇(Fscale_i·f_i(η) at ε̇_i)·Fscale_el·g(L₀/EI_ref)·FscaleT·h(T*):
//!   each f_i piecewise linear in η, the rate interpolation linear in ε̇; both
//!   extrapolate from their end segments (not clamped), as the reference
//!   engine's table interpolation does; L₀ is the element's initial
//!   characteristic (time-step) length, T* the homologous temperature (0 for a
//!   law without temperature);
//! * while D < Dcrit and ε_f > 0: D ← D + w·Δε_p/ε_f with w = 1 at D = 0 and
//!   n·D^(1−1/n) after (§3.3); the point fails at D ≥ Dcrit (Dcrit may
//!   exceed 1). ε_f ≤ 0 adds nothing. No stress softening: the parameter D
//!   is read and, as in the reference engine for this card, not applied (§3.4).
//!
//! Shells (Ifail_sh): 1 the element is deleted at its first failed point;
//! 2 a failed point carries no stress, the element is deleted when all have
//! failed; 3 a failed point keeps its stress, the element is deleted when the
//! failed points' share of the thickness (membrane weights) reaches
//! P_thickfail (blank: all of it; negative: |P_thickfail| as a share of the
//! points' count). Solids (Ifail_so): 1 the element is deleted; 2 the
//! deviatoric stress vanishes (σ = p I) from then on.

use super::tabulated_flow::Curve;
use crate::model::{ScaleCurve, TabFailure};
use serde::{Deserialize, Serialize};

/// A shell deletes at the first failed point above this failed share.
const FIRST_POINT: f64 = 1e-6;
/// A shell deletes when every point has failed: this failed share.
const ALL_POINTS: f64 = 1.0 - 1e-6;

/// /FAIL/TAB with its curves scaled, ready for the points.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct FailTab {
    pub ifail_sh: i64,
    pub ifail_so: i64,
    /// Failed share of a shell's thickness that deletes it (negative: of its
    /// points' count).
    pub share: f64,
    pub dcrit: f64,
    pub n: f64,
    /// Fscale_i·f_i(η) at ε̇_i, by increasing rate.
    rates: Vec<Curve>,
    size: Option<Curve>,
    el_ref: f64,
    temperature: Option<Curve>,
}

/// A scale function as a curve (its ordinates times Fscale), `None` for the
/// constant 1 (no function and Fscale 1).
fn scale_curve(c: &ScaleCurve) -> Option<Curve> {
    if c.fct == 0 {
        return (c.fscale != 1.0).then(|| Curve {
            eps_dot: 0.0,
            x: vec![0.0],
            y: vec![c.fscale],
        });
    }
    Some(Curve {
        eps_dot: 0.0,
        x: c.x.clone(),
        y: c.y.iter().map(|y| y * c.fscale).collect(),
    })
}

impl FailTab {
    pub fn new(t: &TabFailure) -> Result<FailTab, String> {
        for r in &t.rates {
            if r.x.windows(2).any(|w| w[1] <= w[0]) {
                return Err(format!(
                    "/FAIL/TAB: function {}: the triaxiality abscissae must increase",
                    r.fct
                ));
            }
        }
        let share = match t.ifail_sh {
            1 => FIRST_POINT,
            2 => ALL_POINTS,
            _ if t.p_thickfail == 0.0 => ALL_POINTS,
            _ => t.p_thickfail.clamp(-ALL_POINTS, ALL_POINTS),
        };
        Ok(FailTab {
            ifail_sh: t.ifail_sh,
            ifail_so: t.ifail_so,
            share,
            dcrit: t.dcrit,
            n: t.n,
            rates: t
                .rates
                .iter()
                .map(|r| Curve {
                    eps_dot: r.eps_dot,
                    x: r.x.clone(),
                    y: r.y.iter().map(|y| y * r.fscale).collect(),
                })
                .collect(),
            size: scale_curve(&t.size),
            el_ref: t.el_ref,
            temperature: scale_curve(&t.temperature),
        })
    }

    /// The failure strain depends on the element size.
    pub fn has_size_function(&self) -> bool {
        self.size.is_some()
    }

    /// ε_f at triaxiality `eta`, strain rate `rate`, initial element length
    /// `len0` and homologous temperature `tstar`.
    pub fn failure_strain(&self, eta: f64, rate: f64, len0: f64, tstar: f64) -> f64 {
        let r = &self.rates;
        let mut ef = if r.len() == 1 {
            r[0].at(eta).0
        } else {
            // The bracketing pair of rates, end pairs extended.
            let i = r[1..r.len() - 1].partition_point(|c| c.eps_dot <= rate);
            let (lo, hi) = (&r[i], &r[i + 1]);
            let s = (rate - lo.eps_dot) / (hi.eps_dot - lo.eps_dot);
            let (a, b) = (lo.at(eta).0, hi.at(eta).0);
            a + s * (b - a)
        };
        if let Some(g) = &self.size {
            ef *= g.at(len0 / self.el_ref).0;
        }
        if let Some(h) = &self.temperature {
            ef *= h.at(tstar).0;
        }
        ef
    }

    /// Adds the damage of a plastic increment `dep` with failure strain `ef`;
    /// true when the point has failed (D ≥ Dcrit).
    pub fn accumulate(&self, dmg: &mut f64, dep: f64, ef: f64) -> bool {
        if *dmg < self.dcrit && dep > 0.0 && ef > 0.0 {
            let w = if *dmg == 0.0 || self.n == 1.0 {
                1.0
            } else {
                self.n * dmg.powf(1.0 - 1.0 / self.n)
            };
            *dmg += w * dep / ef;
        }
        self.has_failed(*dmg)
    }

    #[inline]
    pub fn has_failed(&self, dmg: f64) -> bool {
        dmg >= self.dcrit
    }

    /// A failed shell point carries no stress (Ifail_sh 1, 2).
    #[inline]
    pub fn zeroes_shell_point(&self) -> bool {
        self.ifail_sh != 3
    }

    /// One shell point after its material update: its damage from the
    /// plastic increment `dep` at the plane stress `s`; true when it has
    /// failed.
    pub fn shell(&self, s: &[f64; 3], dmg: &mut f64, dep: f64, at: &FailAt) -> bool {
        let ef = self.failure_strain(shell_triaxiality(s), at.rate, at.len0, at.tstar);
        self.accumulate(dmg, dep, ef)
    }

    /// A shell with `failed` of its `n` points failed, their membrane weights
    /// summing to `w_failed`, is deleted.
    pub fn deletes_shell(&self, w_failed: f64, failed: usize, n: usize) -> bool {
        if self.share < 0.0 {
            failed as f64 >= -self.share * n as f64
        } else {
            failed > 0 && w_failed >= self.share
        }
    }

    /// One solid point after its material update: damage, then the Ifail_so
    /// action on a failed point; true when the element is to be deleted.
    pub fn solid(&self, sig: &mut [f64; 6], dmg: &mut f64, dep: f64, at: &FailAt) -> bool {
        let eta = super::fail_johnson::solid_triaxiality(sig);
        let ef = self.failure_strain(eta, at.rate, at.len0, at.tstar);
        if !self.accumulate(dmg, dep, ef) {
            return false;
        }
        if self.ifail_so == 1 {
            return true;
        }
        let p = (sig[0] + sig[1] + sig[2]) / 3.0;
        *sig = [p, p, p, 0.0, 0.0, 0.0];
        false
    }
}

/// Where a point's failure strain is taken: the element's strain rate, its
/// initial characteristic length and the homologous temperature.
#[derive(Clone, Copy, Debug, Default)]
pub struct FailAt {
    pub rate: f64,
    pub len0: f64,
    pub tstar: f64,
}

/// η = p/σ_vm of a plane stress [σxx, σyy, σxy] (0 for zero stress).
pub fn shell_triaxiality(s: &[f64; 3]) -> f64 {
    let p = (s[0] + s[1]) / 3.0;
    let vm = (s[0] * s[0] + s[1] * s[1] - s[0] * s[1] + 3.0 * s[2] * s[2]).sqrt();
    p / vm.max(1e-20)
}

#[cfg(test)]
#[path = "fail_tab_tests.rs"]
mod tests;
