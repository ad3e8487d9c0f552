//! What a material law is to the engine: the [`Law`] trait each law file
//! (`law1.rs`, `law2.rs`, …) implements, and the elastic constants every law
//! has.
//!
//! Units are the deck's; nothing here assumes SI.

use super::hardening::Hardening;
use crate::model::MaterialSpec;

/// Density and isotropic elasticity of a material, in deck units.
///
/// `rho` is RHO_I (initial density, used for masses); `rho_ref` is RHO_0 (or
/// RHO_I when blank), the density Radioss uses for the sound speed and the
/// hourglass viscosity. `g` = E/(2(1+ν)).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct ElasticConstants {
    pub rho: f64,
    pub rho_ref: f64,
    pub e: f64,
    pub nu: f64,
    pub g: f64,
}

impl ElasticConstants {
    /// RHO_I, RHO_0 (RHO_I when blank), E, ν and G = E/(2(1+ν)) of a material card.
    pub fn from_spec(c: &MaterialSpec) -> ElasticConstants {
        let rho = c.rho;
        let rho_ref = if c.rho_ref > 0.0 { c.rho_ref } else { c.rho };
        let (e, nu) = (c.e, c.nu);
        let g = e / (2.0 * (1.0 + nu));
        ElasticConstants {
            rho,
            rho_ref,
            e,
            nu,
            g,
        }
    }
}

/// A material law: its parameters (the implementing struct, built once from
/// the model's [`MaterialSpec`]) and what the element kernels ask of it.
///
/// The kernels never see a law directly: they call `super::Material`, the
/// registry, which dispatches to the law of the part by `match` (no dynamic
/// call per integration point). Per element and step, [`Law::hardening`]
/// prepares the flow-stress curve once; every integration point is then
/// updated by `super::PointLaw` (elastic trial, return map on that curve,
/// failure).
///
/// Defaults describe an elastic, rate- and temperature-independent law
/// without failure; a law overrides what it has.
pub trait Law: Sized {
    /// The Radioss law number (/MAT/LAWn).
    const NUMBER: u32;
    /// The law's name in messages ("elastic", "Johnson-Cook").
    const NAME: &'static str;
    /// The state the law keeps per integration point beyond the stress, one
    /// name per f64 (LAW2: the equivalent plastic strain ε_p). The kernels
    /// store it today as one `eps_p` per point; a law with more history
    /// declares it here.
    const HISTORY: &'static [&'static str];

    /// The law's parameters from a material card; `None` when the card is of
    /// another law.
    fn from_spec(c: &MaterialSpec) -> Option<Self>;

    /// Density and elastic constants.
    fn elastic(&self) -> &ElasticConstants;

    /// What the engine cannot compute with these parameters, by name.
    fn check_supported(&self) -> Result<(), String> {
        Ok(())
    }

    /// The law has a yield stress (it supplies a [`Hardening`]).
    fn is_plastic(&self) -> bool {
        false
    }

    /// The flow stress depends on the strain rate.
    fn is_rate_dependent(&self) -> bool {
        false
    }

    /// The flow stress depends on the temperature.
    fn is_thermal(&self) -> bool {
        false
    }

    /// What the engine cannot compute on shells with these parameters, by
    /// name (LAW44's kinematic hardening); `None` when shells are fine.
    fn shell_refusal(&self) -> Option<String> {
        None
    }

    /// What the engine cannot compute on solids with this law (a shell-only
    /// law), by name; `None` when solids are fine.
    fn solid_refusal(&self) -> Option<String> {
        None
    }

    /// The law computes its stress from the total deformation (LAW62: from
    /// B = FFᵀ), not from strain increments: only the total-strain brick
    /// (Ismstr = 10) computes it.
    fn total_strain(&self) -> bool {
        false
    }

    /// A solid's raw strain rate from its rate of deformation
    /// d = [Dxx Dyy Dzz Dxy Dyz Dzx] (tensor shears): the deviatoric
    /// equivalent √(⅔ D′:D′) unless the law says otherwise.
    #[inline]
    fn solid_strain_rate(&self, d: &[f64; 6]) -> f64 {
        deviatoric_rate(d)
    }

    /// The element strain rate the law uses this step, from the previous
    /// (filtered) rate and this step's raw rate.
    #[inline]
    fn filter_strain_rate(&self, _prev: f64, raw: f64, _dt: f64) -> f64 {
        raw
    }

    /// Reference temperature (0 for a law without temperature).
    #[inline]
    fn reference_temperature(&self) -> f64 {
        0.0
    }

    /// Homologous temperature T* = (T − T_r)/(T_melt − T_r) (0 for a law
    /// without temperature), for the failure models' temperature terms.
    #[inline]
    fn homologous_temperature(&self, _temp: f64) -> f64 {
        0.0
    }

    /// Temperature from the internal energy per unit volume.
    #[inline]
    fn temperature(&self, _eint_per_volume: f64) -> f64 {
        self.reference_temperature()
    }

    /// The equivalent plastic strain at which a point fails (∞: never).
    #[inline]
    fn failure_strain(&self) -> f64 {
        f64::INFINITY
    }

    /// Tension damage and deletion on the largest principal strain
    /// [Eps_t, Eps_m, Eps_f] (LAW36), when the card gives them.
    fn tension_damage(&self) -> Option<[f64; 3]> {
        None
    }

    /// One failed point deletes a multi-point element (LAW36); otherwise
    /// all its points must fail (LAW2's EPS_p_max on shells).
    fn deletes_at_first_failed_point(&self) -> bool {
        false
    }

    /// True when a point with this plastic strain has failed.
    #[inline]
    fn has_failed(&self, _eps_p: f64) -> bool {
        false
    }

    /// The flow-stress curve at the element's (filtered) strain rate and
    /// temperature, prepared once per element and step; `None` for an
    /// elastic law.
    #[inline]
    fn hardening(&self, _eps_dot: f64, _temp: f64) -> Option<Hardening<'_>> {
        None
    }

    /// The law updates a solid point itself (its pressure from the volume,
    /// its own return): the stress, plastic strain, its extra history `hist`
    /// (one f64 per point, kept by the one-point solids) and the strain
    /// increment, with `v0_over_v` = V₀/V of the point now; the plastic work
    /// per unit volume. `None` for the laws `PointLaw` updates.
    #[inline]
    fn solid_own(
        &self,
        _sig: &mut [f64; 6],
        _eps_p: &mut f64,
        _hist: &mut f64,
        _deps: [f64; 6],
        _v0_over_v: f64,
    ) -> Option<f64> {
        None
    }

    /// The law needs the point's volume and its extra history
    /// ([`Law::solid_own`]): only the one-point solids (Isolid 1, 2 and the
    /// tetrahedron) keep them.
    fn volumetric(&self) -> bool {
        false
    }

    /// Wave speed for element time steps: c = √(E/ρ₀), what the Radioss
    /// starter stores for LAW1 and LAW2 (material parameter "SSP" =
    /// SQRT(E/RHO)) and the shell time step divides the characteristic length
    /// by (checked against the BOX1BL listing: first time step 0.9753E-04 at
    /// scale 0.1 on 5×5 squares).
    #[inline]
    fn sound_speed(&self) -> f64 {
        let el = self.elastic();
        (el.e / el.rho_ref).sqrt()
    }
}

/// The deviatoric equivalent strain rate √(⅔ D′:D′) of
/// d = [Dxx Dyy Dzz Dxy Dyz Dzx] (tensor shears).
#[inline]
pub fn deviatoric_rate(d: &[f64; 6]) -> f64 {
    let m = (d[0] + d[1] + d[2]) / 3.0;
    let (a, b, c) = (d[0] - m, d[1] - m, d[2] - m);
    let dd = a * a + b * b + c * c + 2.0 * (d[3] * d[3] + d[4] * d[4] + d[5] * d[5]);
    (2.0 / 3.0 * dd).sqrt()
}
