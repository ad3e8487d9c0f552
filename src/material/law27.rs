//! LAW27 (/MAT/LAW27, /MAT/PLAS_BRIT): Johnson-Cook plasticity with brittle
//! tension damage, for shells (research note `docs/notes/law27_research.md`
//! §2; the reference engine's sigeps27c, m27elas, m27plas and m27crak, whose
//! formulas a point integration reproduces to 0.1% of the QA deck's energy).
//!
//! One shell point, in the frame of its damage direction D (stress and
//! strain increment turned into it; D = x until the point cracks):
//! * elastic with damage: e₁ = 1 − d₁ where the old σ₁ ≥ 0 (an open crack),
//!   else 1; the old elastic strains come back from the old stress through
//!   these factors, take the increment, and give σ₁ = A′₁₁ε₁ + A′₁₂ε₂,
//!   σ₂ = A′₁₂ε₁ + A′₂₂ε₂, σ₁₂ = e₁e₂Gγ₁₂ with A′₁₁ = Ee₁/(1 − ν²s),
//!   A′₂₂ = Ee₂/(1 − ν²s), A′₁₂ = νsA′₁₁ and s = 1 only while undamaged (no
//!   Poisson coupling across a crack); a started damage grows with the
//!   crack strain k₁ (Σ Δε₁ since onset): d₁ = min(max(d₁, k₁/(ε_m − ε_t)),
//!   d_max), never decreasing;
//! * plasticity on the damaged stress: σ_y = min((a + b ε̄pⁿ)·q, σ_max), q = 1
//!   + c ln(max(ε̇, ε̇₀)/ε̇₀) with ε̇ the largest of |Δε₁|, |Δε₂|, ½|Δγ₁₂| over
//!   Δt, σ_max = SIG_max0·q (ICC 1) or SIG_max0 (ICC 2); the plane-stress
//!   return of Iplas 1 (three Newton passes on Δλ, the reference's), the
//!   thickness strain Δε_zz = (−ν(Δε₁ + Δε₂) − (1 − 2ν)Δε^p_kk)/(1 − ν);
//! * cracking on the point's largest principal total strain e₁ (membrane
//!   plus ζt·curvature, kept by the element): at e₁ ≥ EPS_t1 the point's D
//!   turns to that principal direction and d₁ = min((e₁ − EPS_t1)/(EPS_m1 −
//!   EPS_t1), d_max1); at e₁ > EPS_f1 the whole element is deleted.
//!
//! As in the reference engine, direction 2 never starts (EPS_t2 … EPS_f2
//! are read and kept, nothing sets d₂) and the transverse shears stay
//! elastic and undamaged here (the reference scales them by the damage
//! factors: a difference where cracked shells carry transverse shear).
//! Iplas 2 (radial return) is refused by name.

use super::law::{ElasticConstants, Law};
use crate::model::{BrittlePlastic, MaterialLaw, MaterialSpec};
use serde::{Deserialize, Serialize};

/// LAW27 parameters.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Law27 {
    pub elastic: ElasticConstants,
    pub p: BrittlePlastic,
}

/// What one point update reports.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BrittlePoint {
    /// Plastic work per unit volume.
    pub d_wplas: f64,
    /// Thickness strain increment (Ithick 1).
    pub d_ezz: f64,
    /// The point cracked in this step (its direction and damage were set).
    pub cracked: bool,
    /// e₁ > EPS_f1: the element is deleted.
    pub torn: bool,
}

/// Plane tensor (xx, yy, xy) components in the frame turned by θ (cos c, sin s).
fn into_frame(a: [f64; 3], c: f64, s: f64) -> [f64; 3] {
    let (cc, ss, cs) = (c * c, s * s, c * s);
    [
        cc * a[0] + ss * a[1] + 2.0 * cs * a[2],
        ss * a[0] + cc * a[1] - 2.0 * cs * a[2],
        cs * (a[1] - a[0]) + (cc - ss) * a[2],
    ]
}

/// The inverse of [`into_frame`].
fn out_of_frame(a: [f64; 3], c: f64, s: f64) -> [f64; 3] {
    into_frame(a, c, -s)
}

impl Law27 {
    /// The damage factor of direction 1 with the old stress σ₁.
    fn factor(d1: f64, s1: f64) -> f64 {
        if s1 >= 0.0 {
            1.0 - d1
        } else {
            1.0
        }
    }

    /// Updates one shell point: `sig` = [σxx, σyy, σxy] (element frame),
    /// `hist` = [d₁, k₁, θ of D], the increment `de` (engineering shear)
    /// over `dt`, and `total`, the point's total strain after it.
    pub fn shell_point(
        &self,
        sig: &mut [f64; 3],
        eps_p: &mut f64,
        hist: &mut [f64; 3],
        de: [f64; 3],
        dt: f64,
        total: [f64; 3],
    ) -> BrittlePoint {
        let ElasticConstants { e, nu, g, .. } = self.elastic;
        let p = &self.p;
        let [et, em, dmax, ef] = p.crack[0];
        let (c, s) = (hist[2].cos(), hist[2].sin());
        let old = into_frame(*sig, c, s);
        let inc = into_frame([de[0], de[1], 0.5 * de[2]], c, s);
        let inc = [inc[0], inc[1], 2.0 * inc[2]];
        // Elastic part with the damage factors of the old stress sign.
        let mut e1 = Self::factor(hist[0], old[0]);
        let coupled = |e1: f64| if e1 == 1.0 { 1.0 } else { 0.0 };
        let mut sc = coupled(e1);
        let eps1 = (old[0] / e1 - nu * sc * old[1]) / e + inc[0];
        let eps2 = (old[1] - nu * sc * old[0]) / e + inc[1];
        let gam = old[2] / (e1 * g) + inc[2];
        if hist[0] != 0.0 {
            hist[1] += inc[0];
            hist[0] = hist[0].max(hist[1] / (em - et)).min(dmax);
        }
        e1 = Self::factor(hist[0], old[0]);
        sc = coupled(e1);
        let a11 = e * e1 / (1.0 - nu * nu * sc);
        let a22 = e / (1.0 - nu * nu * sc);
        let a12 = nu * sc * a11;
        let mut st = [
            a11 * eps1 + a12 * eps2,
            a12 * eps1 + a22 * eps2,
            e1 * g * gam,
        ];
        let (d_wplas, zp) = self.plastic(&mut st, eps_p, inc, dt);
        *sig = out_of_frame(st, c, s);
        let d_ezz = (-nu * (de[0] + de[1]) - (1.0 - 2.0 * nu) * zp) / (1.0 - nu);
        // Cracking on the largest principal total strain.
        let (xx, yy, xy) = (total[0], total[1], 0.5 * total[2]);
        let e_max = 0.5 * (xx + yy) + (0.25 * (xx - yy).powi(2) + xy * xy).sqrt();
        let cracked = e_max >= et && hist[0] <= 0.0;
        if cracked {
            let (vx, vy) = (xy, e_max - xx);
            let norm = vx.hypot(vy);
            hist[2] = if norm < 1e-8 { 0.0 } else { vy.atan2(vx) };
            hist[0] = ((e_max - et) / (em - et)).min(dmax);
        }
        BrittlePoint {
            d_wplas,
            d_ezz,
            cracked,
            torn: e_max > ef,
        }
    }

    /// The Iplas 1 plane-stress return (m27plas: three Newton passes, the
    /// third pass's Δλ, P and Q kept) on `st` (damage frame); returns the
    /// plastic work per unit volume and Δε^p_xx + Δε^p_yy.
    fn plastic(&self, st: &mut [f64; 3], eps_p: &mut f64, inc: [f64; 3], dt: f64) -> (f64, f64) {
        let ElasticConstants { e, nu, g, .. } = self.elastic;
        let p = &self.p;
        let rate = if dt > 0.0 {
            inc[0].abs().max(inc[1].abs()).max(0.5 * inc[2].abs()) / dt
        } else {
            0.0
        };
        let q = if p.c != 0.0 {
            1.0 + p.c * (rate.max(p.eps_dot0) / p.eps_dot0).ln()
        } else {
            1.0
        };
        let smax = if p.icc == 1 {
            p.sig_max0 * q
        } else {
            p.sig_max0
        };
        let flow = |ep: f64| ((p.a + p.b * ep.powf(p.n)) * q).min(smax);
        let y0 = flow(*eps_p);
        let vm2 = st[0] * st[0] + st[1] * st[1] - st[0] * st[1] + 3.0 * st[2] * st[2];
        let vm = vm2.sqrt();
        if vm <= y0 {
            return (0.0, 0.0);
        }
        let h = if y0 >= smax {
            0.0
        } else {
            p.n * p.b * q * (*eps_p + 1e-7).powf(p.n - 1.0)
        };
        let a = 0.25 * (st[0] + st[1]).powi(2);
        let b = 0.75 * (st[0] - st[1]).powi(2) + 3.0 * st[2] * st[2];
        let mut next = (vm - y0) / (3.0 * g + h);
        let (mut dl, mut pp, mut qq, mut yi, mut r) = (0.0, 1.0, 1.0, y0, 0.0);
        for _ in 0..3 {
            dl = next;
            yi = flow(*eps_p + dl);
            r = 0.5 * e * dl / yi;
            pp = 1.0 / (1.0 + r / (1.0 - nu));
            qq = 1.0 / (1.0 + 3.0 * r / (1.0 + nu));
            let f = a * pp * pp + b * qq * qq - yi * yi;
            let df = -(a * pp.powi(3) / (1.0 - nu) + 3.0 * b * qq.powi(3) / (1.0 + nu))
                * (e - 2.0 * r * h)
                / yi
                - 2.0 * h * yi;
            next = if dl > 0.0 {
                (dl - f / df).max(0.0)
            } else {
                0.0
            };
        }
        *eps_p += dl;
        let s1 = (st[0] + st[1]) * pp;
        let s2 = (st[0] - st[1]) * qq;
        *st = [0.5 * (s1 + s2), 0.5 * (s1 - s2), st[2] * qq];
        (yi * dl, r * s1 / e)
    }
}

impl Law for Law27 {
    const NUMBER: u32 = 27;
    const NAME: &'static str = "brittle plastic (PLAS_BRIT)";
    const HISTORY: &'static [&'static str] = &[
        "plastic strain",
        "damage d1",
        "crack strain k1",
        "damage direction angle",
    ];

    fn from_spec(c: &MaterialSpec) -> Option<Law27> {
        let MaterialLaw::BrittlePlastic(p) = &c.law else {
            return None;
        };
        Some(Law27 {
            elastic: ElasticConstants::from_spec(c),
            p: p.clone(),
        })
    }

    #[inline]
    fn elastic(&self) -> &ElasticConstants {
        &self.elastic
    }

    fn solid_refusal(&self) -> Option<String> {
        Some("/MAT/LAW27 (PLAS_BRIT) is a shell law: on solids it is not computed".into())
    }

    fn is_plastic(&self) -> bool {
        true
    }

    fn is_rate_dependent(&self) -> bool {
        self.p.c != 0.0
    }

    fn deletes_at_first_failed_point(&self) -> bool {
        true
    }
}

#[cfg(test)]
#[path = "law27_tests.rs"]
mod tests;
