//! LAW12 (/MAT/LAW12, /MAT/3D_COMP): orthotropic solid composite (reference
//! guide /MAT/LAW12; research note `docs/notes/law12_research.md` §1.3).
//! The element hands the law its stress and strain increment in the
//! material frame (directions 1, 2, 3 of the /PROP/TYPE6 section); per
//! step:
//!
//! 1. Elastic trial: T_ii += Σ_j D_ij Δε_j (D = C⁻¹ of E_ii, ν_ij), shears
//!    T_ij += G_ij Δγ_ij, uncoupled.
//! 2. Tension damage per direction: past (1 − d_i)σ_ti the normal stress
//!    is held there, the others lose D_ji Δε_i d_i, and d_i grows by
//!    DELTA (to 1); an open crack (its strain EPC_i > 0) carries no
//!    compression.
//! 3. Tsai-Wu F(T) = Σ F_i T_i + Σ F_ii T_i² + 2F12 T1T2 + 2F13 T1T3 +
//!    2F23 T2T3 (shears quadratic only) against σ_y = 1 + B·Wpⁿ (capped at
//!    fmax): one plastic correction λ along ∂F/∂T at the old stress, Wp
//!    the plastic work over Wplaref.
//! 4. The point fails when σ_y reaches fmax (the reference fades the
//!    element out over about ten cycles; here it is deleted at once).
//!
//! The strain-rate term (c ≠ 0) is refused by name.

use super::law::{ElasticConstants, Law};
use crate::model::{Composite3d, MaterialLaw, MaterialSpec};
use serde::{Deserialize, Serialize};

/// The reference's "infinite" strength: a yield at or above it never acts.
const INF: f64 = 1e20;

/// LAW12 parameters, resolved.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Law12 {
    elastic: ElasticConstants,
    d: [[f64; 3]; 3],
    /// C = D⁻¹, for the elastic strain where a crack opens.
    compliance: [[f64; 3]; 3],
    g: [f64; 3],
    sig_t: [f64; 3],
    delta: f64,
    b: f64,
    n: f64,
    fmax: f64,
    wplaref: f64,
    /// Tsai-Wu: linear F1-F3, quadratic F11, F22, F33, F44, F55, F66, and
    /// the couplings F12, F23, F13.
    f_lin: [f64; 3],
    f_sq: [f64; 6],
    f_12_23_13: [f64; 3],
    plastic: bool,
    rate: bool,
}

/// What one LAW12 point keeps beyond its stress and plastic work.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Law12Point {
    /// Tension damage d_i and crack strain EPC_i per direction.
    pub dam: [f64; 3],
    pub crack: [f64; 3],
}

impl Law for Law12 {
    const NUMBER: u32 = 12;
    const NAME: &'static str = "orthotropic composite solid (Tsai-Wu)";
    const HISTORY: &'static [&'static str] = &["Wp (plastic work over Wplaref)"];

    fn from_spec(c: &MaterialSpec) -> Option<Law12> {
        let MaterialLaw::Composite3d(p) = &c.law else {
            return None;
        };
        Some(Law12::new(p, ElasticConstants::from_spec(c)))
    }

    fn elastic(&self) -> &ElasticConstants {
        &self.elastic
    }

    fn check_supported(&self) -> Result<(), String> {
        if self.rate {
            return Err(
                "/MAT/LAW12 with a strain-rate coefficient c ≠ 0 is not computed yet".into(),
            );
        }
        Ok(())
    }

    fn is_plastic(&self) -> bool {
        self.plastic
    }

    fn shell_refusal(&self) -> Option<String> {
        Some(
            "/MAT/LAW12 is a solid law: expected solid elements with /PROP/TYPE6 (SOL_ORTH)".into(),
        )
    }

    /// σ_y reached fmax: the point fails (Wp in the plastic-strain slot).
    #[inline]
    fn has_failed(&self, wp: f64) -> bool {
        self.b > 0.0 && 1.0 + self.b * wp.powf(self.n) >= self.fmax
    }

    /// c = √(max D_ii / ρ₀) (note §1.2).
    #[inline]
    fn sound_speed(&self) -> f64 {
        (self.elastic.e / self.elastic.rho_ref).sqrt()
    }
}

impl Law12 {
    pub fn new(p: &Composite3d, elastic: ElasticConstants) -> Law12 {
        let d = p.stiffness().unwrap_or([[0.0; 3]; 3]);
        let (yt, yc) = (p.yt, p.yc);
        let f_lin = std::array::from_fn(|i| 1.0 / yt[i] - 1.0 / yc[i]);
        let f_sq = std::array::from_fn(|i| 1.0 / (yt[i] * yc[i]));
        let coupling = |i: usize, j: usize| -0.5 / (yt[i] * yc[i] * yt[j] * yc[j]).sqrt();
        Law12 {
            elastic,
            d,
            compliance: p.compliance(),
            g: p.g,
            sig_t: p.sig_t,
            delta: p.delta,
            b: p.b,
            n: p.n,
            fmax: p.fmax,
            wplaref: p.wplaref,
            f_lin,
            f_sq,
            f_12_23_13: [coupling(0, 1), coupling(1, 2), coupling(0, 2)],
            plastic: yt.iter().chain(&yc).any(|&y| y < INF),
            rate: p.c != 0.0,
        }
    }

    /// The Tsai-Wu function F(T) and its gradient ∂F/∂T (shears: ∂F/∂T_ij).
    fn tsai_wu(&self, t: &[f64; 6]) -> (f64, [f64; 6]) {
        let (fl, fs, [f12, f23, f13]) = (&self.f_lin, &self.f_sq, self.f_12_23_13);
        let mut f = 0.0;
        for i in 0..3 {
            f += fl[i] * t[i];
        }
        for i in 0..6 {
            f += fs[i] * t[i] * t[i];
        }
        f += 2.0 * (f12 * t[0] * t[1] + f13 * t[0] * t[2] + f23 * t[1] * t[2]);
        let g = [
            fl[0] + 2.0 * (fs[0] * t[0] + f12 * t[1] + f13 * t[2]),
            fl[1] + 2.0 * (fs[1] * t[1] + f12 * t[0] + f23 * t[2]),
            fl[2] + 2.0 * (fs[2] * t[2] + f13 * t[0] + f23 * t[1]),
            2.0 * fs[3] * t[3],
            2.0 * fs[4] * t[4],
            2.0 * fs[5] * t[5],
        ];
        (f, g)
    }

    /// One step in the material frame: stress `t` [T11 T22 T33 T12 T23 T31],
    /// plastic work `wp` (over Wplaref), the point's damage, the increment
    /// `de` (engineering shears). Returns the plastic work per unit volume.
    pub fn update(&self, t: &mut [f64; 6], wp: &mut f64, pt: &mut Law12Point, de: [f64; 6]) -> f64 {
        let old = *t;
        let d = &self.d;
        // Elastic strain before the step (for the crack's opening strain).
        let c = &self.compliance;
        let elastic: [f64; 3] = std::array::from_fn(|i| (0..3).map(|j| c[i][j] * old[j]).sum());
        for i in 0..3 {
            t[i] += (0..3).map(|j| d[i][j] * de[j]).sum::<f64>();
            t[3 + i] += self.g[i] * de[3 + i];
        }
        self.tension_damage(t, pt, de, elastic);
        if !self.plastic {
            return 0.0;
        }
        let sig_y = (1.0 + self.b * wp.powf(self.n)).min(self.fmax);
        let (f, _) = self.tsai_wu(t);
        if f <= sig_y {
            return 0.0;
        }
        let (_, g) = self.tsai_wu(&old);
        let num: f64 = (0..6).map(|k| g[k] * (t[k] - old[k])).sum();
        let dg: f64 = (0..3)
            .map(|i| g[i] * (0..3).map(|j| d[i][j] * g[j]).sum::<f64>())
            .sum::<f64>()
            + 2.0 * (0..3).map(|k| self.g[k] * g[3 + k] * g[3 + k]).sum::<f64>();
        let tg: f64 = (0..6)
            .map(|k| if k < 3 { 1.0 } else { 2.0 } * old[k] * g[k])
            .sum();
        let slope = self.n
            * self.b
            * if *wp > 0.0 {
                wp.powf(self.n - 1.0)
            } else {
                1.0
            };
        let den = dg + tg * slope;
        if !(den > 0.0) {
            return 0.0;
        }
        let lambda = (num / den).max(0.0);
        let dep: [f64; 6] = std::array::from_fn(|k| lambda * g[k]);
        for i in 0..3 {
            t[i] -= (0..3).map(|j| d[i][j] * dep[j]).sum::<f64>();
            t[3 + i] -= 2.0 * self.g[i] * dep[3 + i];
        }
        let w: f64 = (0..6)
            .map(|k| if k < 3 { 0.5 } else { 1.0 } * dep[k] * (t[k] + old[k]))
            .sum::<f64>()
            .max(0.0);
        *wp += w / self.wplaref;
        w
    }

    /// Step 2 of the module doc, per direction.
    fn tension_damage(
        &self,
        t: &mut [f64; 6],
        pt: &mut Law12Point,
        de: [f64; 6],
        elastic: [f64; 3],
    ) {
        for i in 0..3 {
            let limit = (1.0 - pt.dam[i]) * self.sig_t[i];
            if t[i] > limit {
                t[i] = limit;
                for j in (0..3).filter(|&j| j != i) {
                    t[j] -= self.d[j][i] * de[i] * pt.dam[i];
                }
                pt.dam[i] = (pt.dam[i] + self.delta).min(1.0);
                if pt.crack[i] <= 0.0 {
                    pt.crack[i] = elastic[i].max(0.0);
                }
            }
            if pt.crack[i] > 0.0 {
                pt.crack[i] = (pt.crack[i] + de[i]).max(0.0);
                if t[i] < 0.0 && pt.crack[i] > 0.0 {
                    t[i] = 0.0;
                }
            }
        }
    }
}

#[cfg(test)]
#[path = "law12_tests.rs"]
pub(crate) mod tests;
