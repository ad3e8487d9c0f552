//! /MAT/LAW62 (VISC_HYP): hyper-visco-elasticity on the full principal
//! stretches with a Prony series (research note `docs/notes/law62_research.md`
//! §2, the reference engine's sigeps62 read for its formulas).
//!
//! Hyperelastic part (note §2.2), per principal direction j, with the
//! compressibility β = ν/(1 − 2ν) of every term:
//!   Kirchhoff τ_j = Σ_i (2μ_i/α_i)·(λ_j^α_i − J^(−α_i β)),
//! the stress of the energy W = Σ_i (2μ_i/α_i²)[Σ_j λ_j^α_i − 3 + (J^(−α_iβ) − 1)/β].
//! At small strain G = Σμ_i and K = ⅔G(1 + ν)/(1 − 2ν).
//!
//! Viscosity (note §2.4): the convolution of a PK2-type stress A (its
//! deviatoric part for Flag_Visc 0, the whole for 1) with each relaxation
//! kernel, midpoint rule in global components:
//!   h_i ← e^(−Δt/τ_i)·h_i + e^(−Δt/2τ_i)·(A − A_old),
//! projected on the current principal directions (diagonal only) and mixed
//! as γ∞·A + Σγ_i·h_i with γ∞ = 1 − Σγ_i. The card's μ_i are instantaneous.
//!
//! Units are the deck's; nothing here assumes SI.

use super::law::{ElasticConstants, Law};
use crate::model::{MaterialLaw, MaterialSpec};
use serde::{Deserialize, Serialize};

/// LAW62 parameters, built once from the card.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Law62 {
    elastic: ElasticConstants,
    mu: Vec<f64>,
    alpha: Vec<f64>,
    /// β = ν/(1 − 2ν), the same for every term.
    beta: f64,
    gamma: Vec<f64>,
    tau: Vec<f64>,
    /// γ∞ = 1 − Σγ_i.
    gamma_inf: f64,
    /// 0: no viscosity (M = 0); 1: the deviatoric stress relaxes (Flag_Visc
    /// 0); 2: the whole stress relaxes (Flag_Visc 1).
    ivisc: u8,
    /// Initial shear and bulk moduli G = Σμ_i, K = Σ2μ_i(1/3 + β).
    g: f64,
    k: f64,
}

/// The stress of one point and its wave modulus.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HyperStress {
    /// Cauchy stress [σxx σyy σzz σxy σyz σzx], global frame.
    pub sig: [f64; 6],
    /// ρc², the current density times the squared wave speed (note §2.5).
    pub rho_c2: f64,
}

/// Principal values and directions (columns) of a symmetric tensor
/// [xx yy zz xy yz zx].
fn principal(t: &[f64; 6]) -> ([f64; 3], [[f64; 3]; 3]) {
    let m = nalgebra::Matrix3::new(t[0], t[3], t[5], t[3], t[1], t[4], t[5], t[4], t[2]);
    let e = m.symmetric_eigen();
    let n = std::array::from_fn(|j| std::array::from_fn(|k| e.eigenvectors[(k, j)]));
    (std::array::from_fn(|j| e.eigenvalues[j]), n)
}

/// Σ_j s_j n_j⊗n_j as [xx yy zz xy yz zx].
fn assemble(s: &[f64; 3], n: &[[f64; 3]; 3]) -> [f64; 6] {
    let mut o = [0.0; 6];
    for j in 0..3 {
        let v = n[j];
        o[0] += s[j] * v[0] * v[0];
        o[1] += s[j] * v[1] * v[1];
        o[2] += s[j] * v[2] * v[2];
        o[3] += s[j] * v[0] * v[1];
        o[4] += s[j] * v[1] * v[2];
        o[5] += s[j] * v[2] * v[0];
    }
    o
}

/// v·T·v of a symmetric tensor [xx yy zz xy yz zx].
fn project(t: &[f64], v: &[f64; 3]) -> f64 {
    t[0] * v[0] * v[0]
        + t[1] * v[1] * v[1]
        + t[2] * v[2] * v[2]
        + 2.0 * (t[3] * v[0] * v[1] + t[4] * v[1] * v[2] + t[5] * v[2] * v[0])
}

impl Law62 {
    /// The f64 of history one point keeps: the last relaxed stress A and one
    /// tensor h_i per Maxwell term (6 + 6M; none without viscosity).
    pub fn history_len(&self) -> usize {
        if self.ivisc == 0 {
            0
        } else {
            6 * (1 + self.gamma.len())
        }
    }

    /// ρc² at rest: (4/3)G + K, plus (4/3)G with viscosity.
    pub fn rest_rho_c2(&self) -> f64 {
        self.wave_modulus(&[1.0; 3], 1.0)
    }

    /// ρc² at the stretches λ (note §2.5): ⅔G_v + max(max_j D_j/J, (4/3)G + K),
    /// G_v = 2Σμ_i with viscosity,
    /// D_j = Σ_i 2μ_i[(1 − 1/α_i)λ_j^α_i + (β + 1/α_i)J^(−α_iβ)].
    fn wave_modulus(&self, lam: &[f64; 3], j: f64) -> f64 {
        let gv = if self.ivisc > 0 { 2.0 * self.g } else { 0.0 };
        let mut dmax = f64::NEG_INFINITY;
        for l in lam {
            let mut d = 0.0;
            for (m, a) in self.mu.iter().zip(&self.alpha) {
                let jb = j.powf(-a * self.beta);
                d += 2.0 * m * ((1.0 - 1.0 / a) * l.powf(*a) + (self.beta + 1.0 / a) * jb);
            }
            dmax = dmax.max(d / j);
        }
        2.0 / 3.0 * gv + dmax.max(4.0 / 3.0 * self.g + self.k)
    }

    /// The Cauchy stress of the left Cauchy-Green tensor B = I + e, with
    /// e = B − I given as [xx yy zz xy yz zx] (tensor components), after a
    /// step `dt`; `hist` (length [`Law62::history_len`]) is the Prony state,
    /// updated.
    pub fn stress(&self, e: &[f64; 6], dt: f64, hist: &mut [f64]) -> HyperStress {
        let (ev, n) = principal(e);
        let lam: [f64; 3] = std::array::from_fn(|k| (1.0 + ev[k]).max(0.0).sqrt());
        let j = lam[0] * lam[1] * lam[2];
        let mut kirchhoff = [0.0; 3];
        for (m, a) in self.mu.iter().zip(&self.alpha) {
            let jb = j.powf(-a * self.beta);
            for k in 0..3 {
                kirchhoff[k] += 2.0 * m / a * (lam[k].powf(*a) - jb);
            }
        }
        let mut sig: [f64; 3] = std::array::from_fn(|k| kirchhoff[k] / j);
        if self.ivisc > 0 {
            sig = self.relax(&sig, &lam, j, &n, dt, hist);
        }
        HyperStress {
            sig: assemble(&sig, &n),
            rho_c2: self.wave_modulus(&lam, j),
        }
    }

    /// The principal Cauchy stresses after the Prony series (note §2.3–2.4).
    fn relax(
        &self,
        sig: &[f64; 3],
        lam: &[f64; 3],
        j: f64,
        n: &[[f64; 3]; 3],
        dt: f64,
        hist: &mut [f64],
    ) -> [f64; 3] {
        let l2: [f64; 3] = std::array::from_fn(|k| lam[k] * lam[k]);
        let p = (sig[0] + sig[1] + sig[2]) / 3.0;
        let j23 = j.powf(2.0 / 3.0);
        // The PK2-type stress that relaxes: deviatoric (Ŝ) or whole (S).
        let s_rel: [f64; 3] = std::array::from_fn(|k| {
            if self.ivisc == 1 {
                j23 * j * (sig[k] - p) / l2[k]
            } else {
                j * sig[k] / l2[k]
            }
        });
        let a = assemble(&s_rel, n);
        let (old, terms) = hist.split_at_mut(6);
        let mut mixed: [f64; 3] = std::array::from_fn(|k| self.gamma_inf * s_rel[k]);
        for (i, h) in terms.chunks_exact_mut(6).enumerate() {
            let tau = self.tau[i];
            let (decay, half) = ((-dt / tau).exp(), (-0.5 * dt / tau).exp());
            for c in 0..6 {
                h[c] = decay * h[c] + half * (a[c] - old[c]);
            }
            let hj: [f64; 3] = std::array::from_fn(|k| project(h, &n[k]));
            let trace = if self.ivisc == 1 {
                (hj[0] * l2[0] + hj[1] * l2[1] + hj[2] * l2[2]) / 3.0
            } else {
                0.0
            };
            for k in 0..3 {
                mixed[k] += self.gamma[i] * (hj[k] - trace / l2[k]);
            }
        }
        old.copy_from_slice(&a);
        std::array::from_fn(|k| {
            let s = if self.ivisc == 1 {
                j * p / l2[k] + mixed[k] / j23
            } else {
                mixed[k]
            };
            l2[k] * s / j
        })
    }
}

impl Law for Law62 {
    const NUMBER: u32 = 62;
    const NAME: &'static str = "visco-hyperelastic (VISC_HYP)";
    const HISTORY: &'static [&'static str] = &[
        "the last relaxed stress (6)",
        "one convolution tensor per Maxwell term (6 each)",
    ];

    fn from_spec(c: &MaterialSpec) -> Option<Law62> {
        let MaterialLaw::ViscoHyperelastic(p) = &c.law else {
            return None;
        };
        let beta = c.nu / (1.0 - 2.0 * c.nu);
        let g: f64 = p.mu.iter().sum();
        let k = p.mu.iter().map(|m| 2.0 * m * (1.0 / 3.0 + beta)).sum();
        let ivisc = match (p.gamma.is_empty(), p.flag_visc) {
            (true, _) => 0,
            (false, 1) => 2,
            (false, _) => 1,
        };
        Some(Law62 {
            elastic: ElasticConstants::from_spec(c),
            mu: p.mu.clone(),
            alpha: p.alpha.clone(),
            beta,
            gamma: p.gamma.clone(),
            tau: p.tau.clone(),
            gamma_inf: 1.0 - p.gamma.iter().sum::<f64>(),
            ivisc,
            g,
            k,
        })
    }

    #[inline]
    fn elastic(&self) -> &ElasticConstants {
        &self.elastic
    }

    fn shell_refusal(&self) -> Option<String> {
        Some(
            "/MAT/LAW62 (VISC_HYP) on shells is not computed yet (bricks with Ismstr = 10 are)"
                .into(),
        )
    }

    fn total_strain(&self) -> bool {
        true
    }

    /// c = √(ρc²/ρ₀) at rest.
    fn sound_speed(&self) -> f64 {
        (self.rest_rho_c2() / self.elastic.rho_ref).sqrt()
    }
}

#[cfg(test)]
#[path = "law62_tests.rs"]
mod tests;
