//! LAW2 (/MAT/LAW2, /MAT/PLAS_JOHNS): Johnson-Cook elasto-plastic law with
//! isotropic hardening, strain-rate and thermal factors, a flow-stress cap
//! and failure at a plastic strain (reference guide /MAT/LAW2, theory manual
//! "Johnson-Cook plasticity model"; the flow stress is `super::johnson_cook`).

use super::hardening::Hardening;
use super::johnson_cook::{self as jc, Flow};
use super::law::{ElasticConstants, Law};
use crate::model::{MaterialLaw, MaterialSpec, NO_LIMIT};
use serde::{Deserialize, Serialize};

/// LAW2 parameters after default resolution (`chard` is kept so that the
/// engine can refuse Chard ≠ 0 by name).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Law2 {
    pub elastic: ElasticConstants,
    pub a: f64,
    pub b: f64,
    pub n: f64,
    pub eps_p_max: f64,
    pub sig_max0: f64,
    pub c: f64,
    pub eps_dot_0: f64,
    pub icc: i64,
    pub fsmooth: i64,
    pub f_cut: f64,
    pub m: f64,
    pub t_melt: f64,
    pub rho_cp: f64,
    pub t_r: f64,
    pub chard: f64,
}

impl Law for Law2 {
    const NUMBER: u32 = 2;
    const NAME: &'static str = "Johnson-Cook";
    const HISTORY: &'static [&'static str] = &["equivalent plastic strain"];

    fn from_spec(c: &MaterialSpec) -> Option<Law2> {
        let MaterialLaw::JohnsonCook(j) = &c.law else {
            return None;
        };
        Some(Law2 {
            elastic: ElasticConstants::from_spec(c),
            a: j.a,
            b: j.b,
            n: j.n,
            eps_p_max: j.eps_p_max,
            sig_max0: j.sig_max0,
            c: j.c,
            eps_dot_0: j.eps_dot_0,
            icc: j.icc,
            fsmooth: j.fsmooth,
            f_cut: j.f_cut,
            m: j.m,
            t_melt: j.t_melt,
            rho_cp: j.rho_cp,
            t_r: j.t_r,
            chard: j.chard,
        })
    }

    #[inline]
    fn elastic(&self) -> &ElasticConstants {
        &self.elastic
    }

    fn check_supported(&self) -> Result<(), String> {
        if self.chard != 0.0 {
            return Err(format!(
                "/MAT/LAW2 Chard = {}: kinematic or mixed hardening is not supported yet (isotropic hardening only, Chard = 0)",
                self.chard
            ));
        }
        Ok(())
    }

    fn is_plastic(&self) -> bool {
        true
    }

    /// c ≠ 0.
    fn is_rate_dependent(&self) -> bool {
        self.c != 0.0
    }

    /// ρC_p given.
    fn is_thermal(&self) -> bool {
        self.rho_cp < NO_LIMIT
    }

    /// Fsmooth/F_cut strain-rate filter: ε̇ ← α ε̇_raw + (1−α) ε̇_prev with
    /// α = min(1, 2π F_cut Δt). Radioss turns filtering on whenever c ≠ 0 (the
    /// BOX1BL starter listing prints SMOOTH STRAIN RATE OPTION = 1 for Fsmooth = 0);
    /// with the default F_cut = 1e20 the filter passes the raw rate through.
    #[inline]
    fn filter_strain_rate(&self, prev: f64, raw: f64, dt: f64) -> f64 {
        if self.c != 0.0 {
            let alpha = (2.0 * std::f64::consts::PI * self.f_cut * dt).min(1.0);
            alpha * raw + (1.0 - alpha) * prev
        } else {
            raw
        }
    }

    #[inline]
    fn reference_temperature(&self) -> f64 {
        self.t_r
    }

    /// T* = (T − T_r)/(T_melt − T_r) when the law is thermal (ρC_p given).
    #[inline]
    fn homologous_temperature(&self, temp: f64) -> f64 {
        if self.is_thermal() && self.t_melt < NO_LIMIT {
            (temp - self.t_r) / (self.t_melt - self.t_r)
        } else {
            0.0
        }
    }

    /// Adiabatic heating, T = T_r + e/ρC_p, as Radioss does for LAW2 shells;
    /// T_r when ρC_p is not given.
    #[inline]
    fn temperature(&self, eint_per_volume: f64) -> f64 {
        if self.rho_cp < NO_LIMIT {
            self.t_r + eint_per_volume.max(0.0) / self.rho_cp
        } else {
            self.t_r
        }
    }

    #[inline]
    fn failure_strain(&self) -> f64 {
        self.eps_p_max
    }

    /// ε_p ≥ EPS_p_max.
    #[inline]
    fn has_failed(&self, eps_p: f64) -> bool {
        eps_p >= self.eps_p_max
    }

    /// σ_y = (a + b·ε_p^n)·q, capped, with q = rate factor × thermal factor
    /// (at least 1e-20) evaluated once for the element's rate and temperature.
    #[inline]
    fn hardening(&self, eps_dot: f64, temp: f64) -> Option<Hardening<'_>> {
        let q = (jc::rate_factor(self.c, self.eps_dot_0, eps_dot)
            * jc::thermal_factor(self.rho_cp, self.t_r, self.t_melt, self.m, temp))
        .max(1e-20);
        Some(Hardening::JohnsonCook(Flow::new(
            self.a,
            self.b,
            self.n,
            self.sig_max0,
            self.icc,
            q,
        )))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::material::Material;
    use crate::model::{JohnsonCook, Loc};

    fn card(a: f64, b: f64, n: f64) -> MaterialSpec {
        MaterialSpec {
            id: 2,
            unit_id: 0,
            title: "jc".into(),
            rho: 7.8e-6,
            rho_ref: 0.0,
            e: 210.0,
            nu: 0.3,
            law: MaterialLaw::JohnsonCook(JohnsonCook::hardening(a, b, n)),
            failures: vec![],
            loc: Loc::default(),
        }
    }

    /// σ_y = a + b·ε_p^n without rate, temperature or cap.
    #[test]
    fn yield_stress_is_a_plus_b_eps_p_to_the_n() {
        let law = Law2::from_spec(&card(0.25, 0.35, 0.52)).expect("a LAW2 card");
        let h = law.hardening(0.0, law.reference_temperature()).unwrap();
        for ep in [0.0f64, 1e-3, 0.05, 0.2, 1.0] {
            let want = 0.25 + 0.35 * if ep > 0.0 { ep.powf(0.52) } else { 0.0 };
            assert_eq!(h.sig_y(ep), want, "ε_p {ep}");
        }
        assert_eq!(Law2::HISTORY.len(), 1);
        assert!(law.is_plastic() && !law.is_rate_dependent() && !law.is_thermal());
    }

    /// A uniaxial stress path (3-D radial return, lateral strains of the
    /// elastic-plastic uniaxial state): the point stays elastic, σ = E ε, up
    /// to the yield stress a; one increment past it returns onto the yield
    /// surface of the updated ε_p, σ_vm = a + b·ε_p^n, with Δε_p from the
    /// consistency σ_trial,vm − 3GΔε_p = σ_y(Δε_p).
    #[test]
    fn radial_return_of_a_uniaxial_path_reaching_yield() {
        let (a, b, n, e, nu) = (0.25, 0.35, 0.52, 210.0, 0.3);
        let m = Material::from_card(&card(a, b, n));
        let p = m.at(0.0, 298.0);
        let eps_y = a / e;
        let uni = |d: f64| [d, -nu * d, -nu * d, 0.0, 0.0, 0.0];
        let mut sig = [0.0; 6];
        let mut ep = 0.0;
        // Elastic to 0.9 of the yield strain.
        assert_eq!(p.solid(&mut sig, &mut ep, uni(0.9 * eps_y)), 0.0);
        assert!((sig[0] - 0.9 * a).abs() < 1e-14 && sig[1].abs() < 1e-15 && ep == 0.0);
        // Past the yield surface: the deviatoric trial is returned radially.
        let w = p.solid(&mut sig, &mut ep, uni(0.2 * eps_y));
        assert!(ep > 0.0 && w > 0.0);
        let pr = (sig[0] + sig[1] + sig[2]) / 3.0;
        let svm = 1.5 * ((sig[0] - pr).powi(2) + (sig[1] - pr).powi(2) + (sig[2] - pr).powi(2));
        let svm = svm.sqrt();
        let y = a + b * ep.powf(n);
        assert!((svm - y).abs() < 1e-12 * y, "σ_vm {svm} vs σ_y {y}");
        let g = e / (2.0 * (1.0 + nu));
        let trial_vm = 1.1 * a; // uniaxial stress state: trial σ_vm = E·1.1 ε_y
        assert!((trial_vm - 3.0 * g * ep - y).abs() < 1e-12, "consistency");
        assert_eq!(w, y * ep);
    }

    #[test]
    fn an_elastic_card_is_not_law2() {
        let mut c = card(0.25, 0.35, 0.52);
        c.law = MaterialLaw::Elastic;
        assert!(Law2::from_spec(&c).is_none());
    }
}
