//! LAW70 (/MAT/LAW70, /MAT/FOAM_TAB): tabulated visco-elastic foam, solids
//! only (reference guide /MAT/LAW70; research note
//! `docs/notes/law70_research.md` §1.2-1.3, the reference engine's sigeps70
//! read for its formulas). Per point and step, on the total small strain ε
//! (engineering shears) the element keeps in [`Law70Point`]:
//!
//! 1. The strain measure ε_t = √(εxx² + εyy² + εzz² + ½(γxy² + γyz² + γzx²))
//!    and its change δ = ε_t − ε_t,old: loading when δ ≥ 0.
//! 2. The curve value Y at (ε_t, ε̇): the loading curves j, j+1 bracketing
//!    the (filtered) total strain rate, linear in ε̇ and extrapolated past
//!    the last rate; past eps_max the curves continue with slope E_max.
//!    Y_s, the first (static) curve, feeds the hysteresis work.
//! 3. The secant modulus E (E0 to E_max, grows by (E_max − E0)/eps_max per
//!    unit of ε_s = max(0, ε_t − Y/E) on loading, shrinks on unloading, is
//!    kept at a turn), for the direction of the stress and the wave speed.
//! 4. The stress: the elastic stress of E, ν on the total strain, scaled
//!    to the norm Y: σ = σ_e·Y/|σ_e| with |σ|² = Σσ_ii² + 2Στ_ij².
//! 5. Unloading (Iflag 3, 4), with W the work along the static curve and
//!    W_max its largest value: R = 1 − (1 − Hys)(1 − (W/W_max)^Shape)
//!    scales the stress (Iflag 4) or its deviator (Iflag 3).
//!
//! Wave speed √(A1/ρ₀), A1 = E(1 − ν)/((1 + ν)(1 − 2ν)) of the current E.
//! Refused by name: Iflag 0, 1, 2 (the unloading curves' rules), unloading
//! curves (NuL > 0) and Itens > 0.

use super::law::{ElasticConstants, Law};
use super::tabulated_flow::Curve;
use crate::model::{FoamTab, MaterialLaw, MaterialSpec};
use serde::{Deserialize, Serialize};

/// LAW70 parameters with the loading curves, ordinates scaled.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Law70 {
    elastic: ElasticConstants,
    p: FoamTab,
    curves: Vec<Curve>,
    /// (E_max − E0)/eps_max, the secant modulus' growth per unit strain.
    aa: f64,
}

/// What one LAW70 point keeps (the reference's UVAR 1-9).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Law70Point {
    /// Total small strain [εxx εyy εzz γxy γyz γzx].
    pub eps: [f64; 6],
    /// Secant modulus (0 before the first step: E0).
    pub e: f64,
    /// ε_s of the secant update, ε_t of the last step.
    pub eps_s: f64,
    pub eps_t: f64,
    /// +1 loading, −1 unloading, 0 before the first step.
    pub dir: f64,
    /// Work along the static curve, its largest value, and the static curve
    /// value of the last step.
    pub w: f64,
    pub w_max: f64,
    pub y_static: f64,
}

impl Law for Law70 {
    const NUMBER: u32 = 70;
    const NAME: &'static str = "tabulated visco-elastic foam";
    const HISTORY: &'static [&'static str] = &[];

    fn from_spec(c: &MaterialSpec) -> Option<Law70> {
        let MaterialLaw::FoamTab(p) = &c.law else {
            return None;
        };
        let curves = p
            .loading
            .iter()
            .map(|r| Curve {
                eps_dot: r.eps_dot,
                x: r.x.clone(),
                y: r.y.iter().map(|y| y * r.fscale).collect(),
            })
            .collect();
        Some(Law70 {
            elastic: ElasticConstants::from_spec(c),
            aa: (p.e_max - c.e) / p.eps_max,
            p: p.clone(),
            curves,
        })
    }

    fn elastic(&self) -> &ElasticConstants {
        &self.elastic
    }

    fn check_supported(&self) -> Result<(), String> {
        let p = &self.p;
        if p.iflag < 3 {
            return Err(format!(
                "/MAT/LAW70 with Iflag = {}: the engine computes the hysteresis unloading of Iflag 3 and 4 only",
                p.iflag
            ));
        }
        if !p.unloading.is_empty() {
            return Err("/MAT/LAW70 with unloading curves (NuL > 0) is not computed yet".into());
        }
        if p.itens > 0 {
            return Err(format!(
                "/MAT/LAW70 with Itens = {}: the tension behaviour is not computed yet",
                p.itens
            ));
        }
        Ok(())
    }

    fn shell_refusal(&self) -> Option<String> {
        Some("/MAT/LAW70 is a law for solids (reference guide): not on shells".into())
    }

    fn is_rate_dependent(&self) -> bool {
        self.curves.len() > 1
    }

    /// The total strain rate √(D:D) (the reference's MSTRAIN_RATE, IDEV 0).
    #[inline]
    fn solid_strain_rate(&self, d: &[f64; 6]) -> f64 {
        (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] + 2.0 * (d[3] * d[3] + d[4] * d[4] + d[5] * d[5]))
            .sqrt()
    }

    /// ε̇ ← α ε̇_raw + (1 − α) ε̇, α = min(1, 2π F_cut Δt), with Fsmooth > 0
    /// and F_cut > 0.
    #[inline]
    fn filter_strain_rate(&self, prev: f64, raw: f64, dt: f64) -> f64 {
        if self.p.israte <= 0 || self.p.f_cut <= 0.0 || dt <= 0.0 {
            return raw;
        }
        let a = (2.0 * std::f64::consts::PI * self.p.f_cut * dt).min(1.0);
        a * raw + (1.0 - a) * prev
    }
}

/// ε_t of a total strain (engineering shears).
#[inline]
pub fn strain_norm(e: &[f64; 6]) -> f64 {
    (e[0] * e[0] + e[1] * e[1] + e[2] * e[2] + 0.5 * (e[3] * e[3] + e[4] * e[4] + e[5] * e[5]))
        .sqrt()
}

impl Law70 {
    /// E of a point (E0 before its first step).
    #[inline]
    fn modulus(&self, pt: &Law70Point) -> f64 {
        pt.e.max(self.elastic.e)
    }

    /// The dilatational wave speed √(A1/ρ₀) of the point's secant modulus.
    pub fn point_sound_speed(&self, pt: &Law70Point) -> f64 {
        let nu = self.elastic.nu;
        let a1 = self.modulus(pt) * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));
        (a1 / self.elastic.rho_ref).sqrt()
    }

    /// The curve values at ε_t: the rate-interpolated Y and the static Y_s.
    pub fn curve_values(&self, eps_t: f64, eps_dot: f64) -> (f64, f64) {
        let (x, tail) = if eps_t < self.p.eps_max {
            (eps_t, 0.0)
        } else {
            (self.p.eps_max, self.p.e_max * (eps_t - self.p.eps_max))
        };
        let c = &self.curves;
        let y_static = c[0].at(x).0 + tail;
        if c.len() == 1 {
            return (y_static.max(1e-20), y_static);
        }
        let j = (1..c.len() - 1)
            .rev()
            .find(|&j| eps_dot >= c[j].eps_dot)
            .unwrap_or(0);
        let (y1, y2) = (c[j].at(x).0, c[j + 1].at(x).0);
        let r = (eps_dot - c[j].eps_dot) / (c[j + 1].eps_dot - c[j].eps_dot);
        ((y1 + r * (y2 - y1) + tail).max(1e-20), y_static)
    }

    /// One point: the strain increment `deps` (engineering shears) at the
    /// filtered total strain rate `eps_dot`; returns the stress.
    pub fn update(&self, pt: &mut Law70Point, deps: &[f64; 6], eps_dot: f64) -> [f64; 6] {
        for k in 0..6 {
            pt.eps[k] += deps[k];
        }
        let eps_t = strain_norm(&pt.eps);
        let delta = eps_t - pt.eps_t;
        let dir = if delta >= 0.0 { 1.0 } else { -1.0 };
        let (y, y_static) = self.curve_values(eps_t, eps_dot);
        self.secant_update(pt, eps_t, y, dir);
        // The work along the static curve (trapezoid), never below 0.
        pt.w = (pt.w + 0.5 * (y_static + pt.y_static) * delta).max(0.0);
        pt.w_max = pt.w_max.max(pt.w);
        pt.y_static = y_static;
        let mut sig = self.radial(pt, y);
        if dir < 0.0 && pt.w_max > 0.0 {
            let r = 1.0 - (1.0 - self.p.hys) * (1.0 - (pt.w / pt.w_max).powf(self.p.shape));
            scale_unloading(&mut sig, r, self.p.iflag == 3);
        }
        pt.eps_t = eps_t;
        pt.dir = dir;
        sig
    }

    /// Step 3: the secant modulus follows ε_s = max(0, ε_t − Y/E) up on
    /// loading and down on unloading, unchanged at a turn, within [E0, E_max].
    fn secant_update(&self, pt: &mut Law70Point, eps_t: f64, y: f64, dir: f64) {
        let e_old = self.modulus(pt);
        let eps_s = (eps_t - y / e_old).max(0.0);
        let de = self.aa * (eps_s - pt.eps_s);
        let mut e = e_old;
        if dir > 0.0 {
            if pt.dir >= 0.0 {
                e += de.max(0.0);
            }
            pt.eps_s = pt.eps_s.max(eps_s);
        } else {
            if pt.dir < 0.0 {
                e += de.min(0.0);
            }
            pt.eps_s = pt.eps_s.min(eps_s);
        }
        pt.e = e.clamp(self.elastic.e, self.p.e_max.max(self.elastic.e));
    }

    /// Step 4: the elastic stress of E, ν on the total strain, scaled to the
    /// norm `y`.
    fn radial(&self, pt: &Law70Point, y: f64) -> [f64; 6] {
        let (e, nu) = (pt.e, self.elastic.nu);
        let a1 = e * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));
        let a2 = a1 * nu / (1.0 - nu);
        let g = e / (2.0 * (1.0 + nu));
        let s = &pt.eps;
        let mut sig = [
            a1 * s[0] + a2 * (s[1] + s[2]),
            a1 * s[1] + a2 * (s[2] + s[0]),
            a1 * s[2] + a2 * (s[0] + s[1]),
            g * s[3],
            g * s[4],
            g * s[5],
        ];
        let norm = (sig[0] * sig[0]
            + sig[1] * sig[1]
            + sig[2] * sig[2]
            + 2.0 * (sig[3] * sig[3] + sig[4] * sig[4] + sig[5] * sig[5]))
            .sqrt();
        let f = y / norm.max(1e-20);
        for v in sig.iter_mut() {
            *v *= f;
        }
        sig
    }
}

/// Scales the stress by `r` (Iflag 4), or only its deviator (Iflag 3).
fn scale_unloading(sig: &mut [f64; 6], r: f64, deviator_only: bool) {
    let p = if deviator_only {
        (sig[0] + sig[1] + sig[2]) / 3.0
    } else {
        0.0
    };
    for (k, v) in sig.iter_mut().enumerate() {
        let iso = if k < 3 { p } else { 0.0 };
        *v = iso + r * (*v - iso);
    }
}

#[cfg(test)]
#[path = "law70_tests.rs"]
mod tests;
