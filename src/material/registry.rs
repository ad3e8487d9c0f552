//! The material registry: one line per law, in the `registry!` table at the
//! bottom of this file. [`Material`] is the material of a part, built once
//! from its model card; its methods dispatch to the law's [`Law`]
//! implementation by `match` (enum dispatch: no dynamic call on the hot path).
//!
//! Adding a law: write `src/material/lawN.rs` (its parameter struct
//! implementing [`Law`]), declare it in `mod.rs`, and add its line to the
//! table (variant, type, name). A plastic law with a new flow-stress curve adds
//! its variant to `super::Hardening`.
//!
//! Units are the deck's; nothing here assumes SI.

use super::law::{ElasticConstants, Law};
use super::law1::Law1;
use super::law12::Law12;
use super::law2::Law2;
use super::law21::Law21;
use super::law27::Law27;
use super::law36::Law36;
use super::law44::Law44;
use super::law62::Law62;
use super::law70::Law70;
use super::point::{PlaneStressResult, PointLaw};
use crate::model::MaterialSpec;
use serde::{Deserialize, Serialize};

/// Defines [`Material`] (one variant per law), its builder from a card, the
/// table of law numbers, and `each_law!`, the match that dispatches to the
/// law. `$d` is the `$` token, so the generated macro can have parameters.
macro_rules! registry {
    ($d:tt $($(#[$doc:meta])* $variant:ident($law:ty),)*) => {
        /// The material of a part: one variant per law, holding that law's
        /// parameters (built from a model [`MaterialSpec`], values in deck
        /// units).
        #[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
        pub enum Material {
            $($(#[$doc])* $variant($law),)*
        }

        /// Every law of the registry: (Radioss law number, name).
        pub const LAWS: &[(u32, &str)] = &[$((<$law as Law>::NUMBER, <$law as Law>::NAME),)*];

        impl Material {
            /// The material of a card: the law whose `from_spec` accepts it.
            pub fn from_card(c: &MaterialSpec) -> Material {
                $(if let Some(l) = <$law as Law>::from_spec(c) {
                    return Material::$variant(l);
                })*
                panic!(
                    "/MAT {} ({:?}): no law of the material registry accepts this card",
                    c.id, c.law
                )
            }
        }

        /// `each_law!(material, law => expression)`: the expression with
        /// `law` bound to the material's law parameters, whatever the law.
        macro_rules! each_law {
            ($d m:expr, $d l:ident => $d e:expr) => {
                match $d m {
                    $(Material::$variant($d l) => $d e,)*
                }
            };
        }
    };
}

registry! {
    $
    /// LAW1: linear elastic.
    Elastic(Law1),
    /// LAW2: Johnson-Cook elasto-plastic.
    JohnsonCook(Law2),
    /// LAW36: tabulated elasto-plastic.
    Tabulated(Law36),
    /// LAW44: Cowper-Symonds elasto-plastic.
    CowperSymonds(Law44),
    DruckerPrager(Law21),
    /// LAW27: Johnson-Cook plasticity with brittle tension damage (shells).
    BrittlePlastic(Law27),
    /// LAW62: hyper-visco-elastic (Ogden-type with a Prony series; bricks).
    ViscoHyperelastic(Law62),
    /// LAW12: orthotropic composite solid (Tsai-Wu; /PROP/TYPE6 bricks).
    Composite3d(Law12),
    /// LAW70: tabulated visco-elastic foam (one-point bricks).
    FoamTab(Law70),
}

/// The name of law number `number` when the registry has it; otherwise the
/// refusal, naming the law and the ones the engine computes.
pub fn law_name(number: u32) -> Result<&'static str, String> {
    match LAWS.iter().find(|(n, _)| *n == number) {
        Some((_, name)) => Ok(name),
        None => Err(format!(
            "/MAT/LAW{number}: this material law is not supported yet (the engine computes {})",
            LAWS.iter()
                .map(|(n, name)| format!("LAW{n} {name}"))
                .collect::<Vec<_>>()
                .join(", ")
        )),
    }
}

impl Material {
    /// The Radioss law number of this material.
    pub fn law_number(&self) -> u32 {
        fn number<L: Law>(_: &L) -> u32 {
            L::NUMBER
        }
        each_law!(self, l => number(l))
    }

    /// The names of the state the law keeps per integration point beyond the
    /// stress (see [`Law::HISTORY`]).
    pub fn history(&self) -> &'static [&'static str] {
        fn history<L: Law>(_: &L) -> &'static [&'static str] {
            L::HISTORY
        }
        each_law!(self, l => history(l))
    }

    /// What the engine cannot compute with this material, by name.
    pub fn check_supported(&self) -> Result<(), String> {
        each_law!(self, l => l.check_supported())
    }

    /// The law has a yield stress (LAW2); LAW1 is elastic.
    #[inline]
    pub fn is_plastic(&self) -> bool {
        each_law!(self, l => l.is_plastic())
    }

    /// The flow stress depends on the strain rate (LAW2 with c ≠ 0).
    #[inline]
    pub fn is_rate_dependent(&self) -> bool {
        each_law!(self, l => l.is_rate_dependent())
    }

    /// The flow stress depends on the temperature (LAW2 with ρC_p given).
    #[inline]
    pub fn is_thermal(&self) -> bool {
        each_law!(self, l => l.is_thermal())
    }

    /// Density and elastic constants.
    #[inline]
    pub fn elastic(&self) -> &ElasticConstants {
        each_law!(self, l => l.elastic())
    }

    /// Initial density RHO_I.
    #[inline]
    pub fn rho(&self) -> f64 {
        self.elastic().rho
    }

    /// Reference density RHO_0 (RHO_I when blank).
    #[inline]
    pub fn rho_ref(&self) -> f64 {
        self.elastic().rho_ref
    }

    #[inline]
    pub fn young(&self) -> f64 {
        self.elastic().e
    }

    #[inline]
    pub fn poisson(&self) -> f64 {
        self.elastic().nu
    }

    #[inline]
    pub fn shear_modulus(&self) -> f64 {
        self.elastic().g
    }

    /// Elastic plane-stress modulus E/(1−ν²).
    #[inline]
    pub fn a11(&self) -> f64 {
        let nu = self.poisson();
        self.young() / (1.0 - nu * nu)
    }

    /// Wave speed for element time steps (see [`Law::sound_speed`]).
    #[inline]
    pub fn sound_speed(&self) -> f64 {
        each_law!(self, l => l.sound_speed())
    }

    /// The strain rate the law uses this step (LAW2: the Fsmooth/F_cut filter,
    /// see [`Law::filter_strain_rate`]).
    #[inline]
    pub fn filter_strain_rate(&self, prev: f64, raw: f64, dt: f64) -> f64 {
        each_law!(self, l => l.filter_strain_rate(prev, raw, dt))
    }

    /// Temperature from the internal energy per unit volume (LAW2: adiabatic
    /// heating, T = T_r + e/ρC_p; T_r when ρC_p is not given; 0 for LAW1).
    #[inline]
    pub fn temperature(&self, eint_per_volume: f64) -> f64 {
        each_law!(self, l => l.temperature(eint_per_volume))
    }

    /// Homologous temperature T* at temperature `temp` (see [`Law::homologous_temperature`]).
    #[inline]
    pub fn homologous_temperature(&self, temp: f64) -> f64 {
        each_law!(self, l => l.homologous_temperature(temp))
    }

    /// Reference temperature T_r (0 for elastic materials).
    #[inline]
    pub fn reference_temperature(&self) -> f64 {
        each_law!(self, l => l.reference_temperature())
    }

    /// What the engine cannot compute on shells (see [`Law::shell_refusal`]).
    pub fn shell_refusal(&self) -> Option<String> {
        each_law!(self, l => l.shell_refusal())
    }

    /// What the engine cannot compute on solids with this material (see
    /// [`Law::solid_refusal`]).
    pub fn solid_refusal(&self) -> Option<String> {
        each_law!(self, l => l.solid_refusal())
    }

    /// LAW27's brittle shell update, which the shells call instead of the
    /// return map (`None` for every other law).
    #[inline]
    pub fn brittle(&self) -> Option<&Law27> {
        match self {
            Material::BrittlePlastic(l) => Some(l),
            _ => None,
        }
    }

    /// The law computes its stress from the total deformation (see
    /// [`Law::total_strain`]).
    pub fn total_strain(&self) -> bool {
        each_law!(self, l => l.total_strain())
    }

    /// LAW12's parameters when this is LAW12.
    pub fn composite3d(&self) -> Option<&Law12> {
        match self {
            Material::Composite3d(l) => Some(l),
            _ => None,
        }
    }

    /// LAW70's parameters when this is LAW70.
    pub fn foam_tab(&self) -> Option<&Law70> {
        match self {
            Material::FoamTab(l) => Some(l),
            _ => None,
        }
    }

    /// LAW62's parameters when this is LAW62.
    pub fn visco_hyperelastic(&self) -> Option<&Law62> {
        match self {
            Material::ViscoHyperelastic(l) => Some(l),
            _ => None,
        }
    }

    /// The raw strain rate of a solid (see [`Law::solid_strain_rate`]).
    #[inline]
    pub fn solid_strain_rate(&self, d: &[f64; 6]) -> f64 {
        each_law!(self, l => l.solid_strain_rate(d))
    }

    /// [Eps_t, Eps_m, Eps_f] of a law with tension damage (see [`Law::tension_damage`]).
    #[inline]
    pub fn tension_damage(&self) -> Option<[f64; 3]> {
        each_law!(self, l => l.tension_damage())
    }

    /// One failed point deletes a multi-point element (see [`Law::deletes_at_first_failed_point`]).
    #[inline]
    pub fn deletes_at_first_failed_point(&self) -> bool {
        each_law!(self, l => l.deletes_at_first_failed_point())
    }

    /// True when a point with this plastic strain has failed (LAW2: ε_p ≥ EPS_p_max).
    #[inline]
    pub fn has_failed(&self, eps_p: f64) -> bool {
        each_law!(self, l => l.has_failed(eps_p))
    }

    /// The material at the given (filtered) strain rate and temperature,
    /// prepared for the integration points of one element and step.
    #[inline]
    pub fn at(&self, eps_dot: f64, temp: f64) -> PointLaw<'_> {
        let (e, nu, g) = (self.young(), self.poisson(), self.shear_modulus());
        each_law!(self, l => PointLaw {
            e,
            nu,
            g,
            eps_p_max: l.failure_strain(),
            hardening: l.hardening(eps_dot, temp),
        })
    }

    /// Current yield stress (∞ for an elastic material).
    #[inline]
    pub fn yield_stress(&self, eps_p: f64, eps_dot: f64, temp: f64) -> f64 {
        self.at(eps_dot, temp).yield_stress(eps_p)
    }

    /// Plane-stress update at one integration point (shells) at the reference
    /// temperature (no thermal softening); see [`PointLaw::plane_stress`].
    #[inline]
    pub fn plane_stress_update(
        &self,
        sig: &mut [f64; 3],
        eps_p: &mut f64,
        deps: [f64; 3],
        eps_dot: f64,
        iplas: i64,
    ) -> PlaneStressResult {
        self.plane_stress_update_at(
            sig,
            eps_p,
            deps,
            eps_dot,
            self.reference_temperature(),
            iplas,
        )
    }

    /// Plane-stress update at temperature `temp`; see [`PointLaw::plane_stress`].
    #[inline]
    pub fn plane_stress_update_at(
        &self,
        sig: &mut [f64; 3],
        eps_p: &mut f64,
        deps: [f64; 3],
        eps_dot: f64,
        temp: f64,
        iplas: i64,
    ) -> PlaneStressResult {
        self.at(eps_dot, temp).plane_stress(sig, eps_p, deps, iplas)
    }

    /// 3-D update (solids; radial return) at the reference temperature; see [`PointLaw::solid`].
    #[inline]
    pub fn solid_update(
        &self,
        sig: &mut [f64; 6],
        eps_p: &mut f64,
        deps: [f64; 6],
        eps_dot: f64,
    ) -> f64 {
        self.solid_update_at(sig, eps_p, deps, eps_dot, self.reference_temperature())
    }

    /// The law needs the point's volume and its own history (LAW21).
    #[inline]
    pub fn volumetric(&self) -> bool {
        each_law!(self, l => l.volumetric())
    }

    /// 3-D update of a point of a one-point solid: the law's own update
    /// ([`Law::solid_own`], with V₀/V and the extra history `hist`) or
    /// [`Material::solid_update_at`].
    #[inline]
    #[allow(clippy::too_many_arguments)]
    pub fn solid_update_volumetric(
        &self,
        sig: &mut [f64; 6],
        eps_p: &mut f64,
        hist: &mut f64,
        deps: [f64; 6],
        eps_dot: f64,
        temp: f64,
        v0_over_v: f64,
    ) -> f64 {
        match each_law!(self, l => l.solid_own(sig, eps_p, hist, deps, v0_over_v)) {
            Some(wp) => wp,
            None => self.solid_update_at(sig, eps_p, deps, eps_dot, temp),
        }
    }

    /// 3-D update at temperature `temp`; see [`PointLaw::solid`].
    #[inline]
    pub fn solid_update_at(
        &self,
        sig: &mut [f64; 6],
        eps_p: &mut f64,
        deps: [f64; 6],
        eps_dot: f64,
        temp: f64,
    ) -> f64 {
        self.at(eps_dot, temp).solid(sig, eps_p, deps)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::MaterialLaw;
    use crate::model::{JohnsonCook, Loc};

    /// The BOX1BL material (OpenRadioss QA deck), with overrides.
    fn box1bl_card(law: Option<JohnsonCook>) -> MaterialSpec {
        let jc = JohnsonCook::hardening(0.25, 0.349999994, 0.519999981);
        MaterialSpec {
            id: 1,
            unit_id: 0,
            title: "test".into(),
            rho: 7.80000028e-6,
            rho_ref: 0.0,
            e: 205.0,
            nu: 0.300000012,
            law: MaterialLaw::JohnsonCook(law.unwrap_or(jc)),
            failures: vec![],
            loc: Loc::default(),
        }
    }

    fn jc_with(f: impl FnOnce(&mut JohnsonCook)) -> Material {
        let mut c = box1bl_card(None);
        if let MaterialLaw::JohnsonCook(j) = &mut c.law {
            f(j);
        }
        Material::from_card(&c)
    }

    /// Uniaxial plane stress driven by Δεxx steps: the lateral strain increment
    /// is iterated (secant) so that σyy = 0 after each update.
    fn uniaxial(
        m: &Material,
        iplas: i64,
        de: f64,
        steps: usize,
        eps_dot: f64,
        mut each: impl FnMut(f64, f64, f64, bool),
    ) {
        let mut sig = [0.0; 3];
        let mut ep = 0.0;
        let mut lat = -m.poisson() * de;
        for _ in 0..steps {
            let try_lat = |l: f64| {
                let (mut s, mut e) = (sig, ep);
                let r = m.plane_stress_update(&mut s, &mut e, [de, l, 0.0], eps_dot, iplas);
                (s, e, r)
            };
            let (mut l0, mut l1) = (lat, lat - 0.5 * de);
            let (mut f0, mut f1) = (try_lat(l0).0[1], try_lat(l1).0[1]);
            for _ in 0..60 {
                if f1 == f0 || f1.abs() < 1e-15 {
                    break;
                }
                let l2 = l1 - f1 * (l1 - l0) / (f1 - f0);
                l0 = l1;
                f0 = f1;
                l1 = l2;
                f1 = try_lat(l1).0[1];
            }
            lat = l1;
            let (s, e, r) = try_lat(lat);
            sig = s;
            ep = e;
            each(sig[0], sig[1], ep, r.failed);
        }
    }

    #[test]
    fn jc_uniaxial_follows_hardening_curve_all_iplas() {
        let m = jc_with(|_| {});
        let (a, b, n) = (0.25, 0.349999994, 0.519999981);
        for iplas in [0, 1, 2] {
            let mut checked = 0;
            uniaxial(&m, iplas, 2e-5, 20_000, 0.0, |sxx, syy, ep, _| {
                assert!(syy.abs() < 1e-9, "σyy = {syy}");
                if (0.01..=0.3).contains(&ep) {
                    let want = a + b * ep.powf(n);
                    assert!(
                        (sxx - want).abs() / want < 0.01,
                        "Iplas {iplas}: ε_p {ep}: σ {sxx} vs {want}"
                    );
                    checked += 1;
                }
            });
            assert!(
                checked > 1000,
                "Iplas {iplas}: ε_p range not covered ({checked})"
            );
        }
    }

    #[test]
    fn jc_newton_is_exact_on_the_yield_surface() {
        // Iplas = 1: after a large biaxial + shear step the stress lies on the
        // yield surface of the updated ε_p, and the plastic strain increment is
        // normal to it (Δε^p ∝ P σ, checked through elastic strain consistency).
        let m = jc_with(|_| {});
        let mut sig = [0.1, -0.05, 0.02];
        let mut ep = 0.02;
        let deps = [3e-3, 1e-3, 2e-3];
        let old = sig;
        m.plane_stress_update(&mut sig, &mut ep, deps, 0.0, 1);
        let svm =
            (sig[0] * sig[0] + sig[1] * sig[1] - sig[0] * sig[1] + 3.0 * sig[2] * sig[2]).sqrt();
        let y = m.yield_stress(ep, 0.0, 298.0);
        assert!((svm - y).abs() < 1e-12 * y, "σ_vm {svm} vs σ_y {y}");
        // Plastic strain increment = Δε − C⁻¹Δσ must be parallel to Pσ with |·| giving Δε_p.
        let (e, nu) = (m.young(), m.poisson());
        let ds = [sig[0] - old[0], sig[1] - old[1], sig[2] - old[2]];
        let dee = [
            (ds[0] - nu * ds[1]) / e,
            (ds[1] - nu * ds[0]) / e,
            ds[2] * 2.0 * (1.0 + nu) / e,
        ];
        let dp = [deps[0] - dee[0], deps[1] - dee[1], deps[2] - dee[2]];
        let ps = [
            (2.0 * sig[0] - sig[1]) / 3.0,
            (2.0 * sig[1] - sig[0]) / 3.0,
            2.0 * sig[2],
        ];
        let lam = dp[0] / ps[0];
        for k in 0..3 {
            assert!(
                (dp[k] - lam * ps[k]).abs() < 1e-10,
                "component {k}: {} vs {}",
                dp[k],
                lam * ps[k]
            );
        }
        // Δε_p = (2/3) Δλ σ_vm.
        assert!(((ep - 0.02) - 2.0 / 3.0 * lam * svm).abs() < 1e-10);
    }

    #[test]
    fn jc_elastic_unloading_slope_is_e() {
        let m = jc_with(|_| {});
        for iplas in [0, 1] {
            let mut last = (0.0, 0.0);
            uniaxial(&m, iplas, 1e-4, 500, 0.0, |s, _, ep, _| last = (s, ep));
            let (s0, ep0) = last;
            let mut first = None;
            // Unload by Δε = −1e-4 steps (uniaxial, lateral iterated).
            let m2 = m.clone();
            let mut sig = [s0, 0.0, 0.0];
            let mut ep = ep0;
            let de = -1e-4;
            let lat = -m2.poisson() * de;
            let r = m2.plane_stress_update(&mut sig, &mut ep, [de, lat, 0.0], 0.0, iplas);
            first.get_or_insert(sig[0]);
            assert_eq!(ep, ep0, "unloading must stay elastic");
            assert!(r.d_wplas == 0.0);
            let slope = (sig[0] - s0) / de;
            assert!(
                (slope - m.young()).abs() < 1e-9 * m.young(),
                "slope {slope}"
            );
            assert!(sig[1].abs() < 1e-15);
        }
    }

    /// The flow stress along a path at three strain rates, 10, 10³ and 10⁵
    /// times ε̇₀: (a + b ε_p^n)(1 + c ln(ε̇/ε̇₀)) within 1% (shells: plane
    /// stress uniaxial) and to round-off (solids: uniaxial strain, the Mises
    /// stress after the radial return); below ε̇₀ no rate effect.
    #[test]
    fn jc_rate_term_scales_the_flow_stress() {
        let c = 0.0494999997;
        let e0 = 4.82999985e-6;
        let m = jc_with(|j| {
            j.c = c;
            j.eps_dot_0 = e0;
        });
        let (a, b, n) = (0.25, 0.349999994, 0.519999981);
        for ratio in [10.0f64, 1e3, 1e5] {
            let rate = ratio * e0;
            let q = 1.0 + c * ratio.ln();
            let mut checked = 0;
            uniaxial(&m, 1, 5e-5, 3000, rate, |s, _, ep, _| {
                if ep > 0.02 {
                    let want = q * (a + b * ep.powf(n));
                    assert!(
                        (s - want).abs() / want < 0.01,
                        "ε̇/ε̇₀ {ratio}, ε_p {ep}: {s} vs {want}"
                    );
                    checked += 1;
                }
            });
            assert!(checked > 100);
            let (mut sig, mut ep) = ([0.0; 6], 0.0);
            let mut solid = 0;
            for _ in 0..3000 {
                m.solid_update_at(
                    &mut sig,
                    &mut ep,
                    [5e-5, 0.0, 0.0, 0.0, 0.0, 0.0],
                    rate,
                    298.0,
                );
                if ep > 0.01 {
                    let p = (sig[0] + sig[1] + sig[2]) / 3.0;
                    let s2: f64 = (0..3).map(|k| (sig[k] - p).powi(2)).sum();
                    let vm = (1.5 * s2).sqrt();
                    let want = q * (a + b * ep.powf(n));
                    assert!(
                        (vm - want).abs() < 1e-9 * want,
                        "solid ε̇/ε̇₀ {ratio}, ε_p {ep}: {vm} vs {want}"
                    );
                    solid += 1;
                }
            }
            assert!(solid > 1000, "{solid} plastic solid steps");
        }
        // Below the reference rate: no rate effect.
        assert_eq!(m.yield_stress(0.1, 0.5 * e0, 298.0), a + b * 0.1f64.powf(n));
    }

    #[test]
    fn jc_sig_max_cap_with_and_without_rate() {
        let e0 = 1e-3;
        for icc in [1, 2] {
            let m = jc_with(|j| {
                j.sig_max0 = 0.379999995;
                j.c = 0.05;
                j.eps_dot_0 = e0;
                j.icc = icc;
            });
            let q = 1.0 + 0.05 * (100f64).ln();
            let cap = if icc == 1 {
                0.379999995 * q
            } else {
                0.379999995
            };
            let mut last = 0.0;
            uniaxial(&m, 1, 1e-4, 4000, 100.0 * e0, |s, _, _, _| last = s);
            assert!((last - cap).abs() < 1e-9, "ICC {icc}: {last} vs cap {cap}");
            assert_eq!(m.yield_stress(0.35, 100.0 * e0, 298.0), cap);
        }
    }

    #[test]
    fn jc_failure_at_eps_p_max() {
        let m = jc_with(|j| j.eps_p_max = 0.1);
        let mut failed_at = None;
        let mut after = Vec::new();
        uniaxial(&m, 0, 1e-4, 2000, 0.0, |s, _, ep, failed| {
            if failed {
                failed_at.get_or_insert(ep);
                after.push(s);
            }
        });
        let ep = failed_at.expect("the point must fail");
        assert!((0.1..0.1 + 2e-4).contains(&ep), "failed at ε_p = {ep}");
        assert!(after.iter().all(|&s| s == 0.0));
    }

    #[test]
    fn jc_thermal_softening() {
        let m = jc_with(|j| {
            j.rho_cp = 4.0e-3;
            j.t_melt = 1800.0;
            j.m = 1.0;
        });
        let t = m.temperature(4.0e-3 * 751.0); // T = 298 + 751 = 1049 → T* = 0.5
        assert!((t - 1049.0).abs() < 1e-9);
        let y = m.yield_stress(0.0, 0.0, t);
        assert!((y - 0.5 * 0.25).abs() < 1e-12);
    }

    #[test]
    fn law1_plane_stress_is_hooke() {
        let mut c = box1bl_card(None);
        c.law = MaterialLaw::Elastic;
        let m = Material::from_card(&c);
        let (e, nu) = (205.0, 0.300000012);
        let mut sig = [0.0; 3];
        let mut ep = 0.0;
        let (ex, ey, gxy) = (2e-3, -5e-4, 1e-3);
        for _ in 0..10 {
            let r = m.plane_stress_update(
                &mut sig,
                &mut ep,
                [ex / 10.0, ey / 10.0, gxy / 10.0],
                0.0,
                0,
            );
            assert!((r.d_ezz - (-nu / (1.0 - nu) * (ex + ey) / 10.0)).abs() < 1e-18);
        }
        let a11 = e / (1.0 - nu * nu);
        assert!((sig[0] - a11 * (ex + nu * ey)).abs() < 1e-13);
        assert!((sig[1] - a11 * (ey + nu * ex)).abs() < 1e-13);
        assert!((sig[2] - e / (2.0 * (1.0 + nu)) * gxy).abs() < 1e-13);
        assert_eq!(ep, 0.0);
    }

    #[test]
    fn thickness_strain_is_incompressible_in_plastic_flow() {
        // Iplas = 1, deep in plastic flow under equibiaxial stretch: Δεxx+Δεyy+Δεzz ≈ elastic volume change only.
        let m = jc_with(|j| j.b = 0.0);
        let mut sig = [0.0; 3];
        let mut ep = 0.0;
        let d = 1e-4;
        let mut r = PlaneStressResult::default();
        for _ in 0..200 {
            r = m.plane_stress_update(&mut sig, &mut ep, [d, d, 0.0], 0.0, 1);
        }
        // Perfect plasticity, stress constant: the whole increment is plastic → Δεzz = −2d.
        assert!((r.d_ezz + 2.0 * d).abs() < 1e-12, "Δεzz {}", r.d_ezz);
    }

    #[test]
    fn solid_radial_return_consistency() {
        let m = jc_with(|_| {});
        let mut sig = [0.0; 6];
        let mut ep = 0.0;
        let mut wsum = 0.0;
        // Uniaxial strain path with shear.
        for _ in 0..400 {
            wsum += m.solid_update(&mut sig, &mut ep, [1e-4, 0.0, 0.0, 5e-5, 0.0, 0.0], 0.0);
        }
        let p = (sig[0] + sig[1] + sig[2]) / 3.0;
        let e = m.young();
        let nu = m.poisson();
        let k = e / (3.0 * (1.0 - 2.0 * nu));
        assert!(
            (p - k * 400.0 * 1e-4).abs() < 1e-10,
            "pressure must stay elastic: {p}"
        );
        let d = [sig[0] - p, sig[1] - p, sig[2] - p];
        let svm = (1.5 * (d[0] * d[0] + d[1] * d[1] + d[2] * d[2])
            + 3.0 * (sig[3] * sig[3] + sig[4] * sig[4] + sig[5] * sig[5]))
            .sqrt();
        let y = m.yield_stress(ep, 0.0, 298.0);
        assert!(ep > 0.0 && (svm - y).abs() < 1e-12 * y);
        assert!(wsum > 0.0);
    }

    #[test]
    fn chard_is_refused_by_name() {
        let m = jc_with(|j| j.chard = 0.5);
        let e = m.check_supported().unwrap_err();
        assert!(e.contains("Chard"), "{e}");
        assert!(jc_with(|_| {}).check_supported().is_ok());
    }
    /// Each law number maps to its implementation, each card to its variant,
    /// and a law the registry does not have is refused by its number.
    #[test]
    fn registry_maps_law_numbers_and_refuses_others_by_name() {
        assert_eq!(law_name(1), Ok("elastic"));
        assert_eq!(law_name(2), Ok("Johnson-Cook"));
        assert_eq!(law_name(36), Ok("tabulated plasticity"));
        assert_eq!(law_name(44), Ok("Cowper-Symonds"));
        assert_eq!(law_name(27), Ok("brittle plastic (PLAS_BRIT)"));
        let e = law_name(25).unwrap_err();
        assert!(
            e.contains("/MAT/LAW25")
                && e.contains("LAW1 elastic")
                && e.contains("LAW2 Johnson-Cook"),
            "{e}"
        );
        let mut c = box1bl_card(None);
        let jc = Material::from_card(&c);
        assert!(matches!(jc, Material::JohnsonCook(_)));
        assert_eq!((jc.law_number(), jc.history().len()), (2, 1));
        c.law = MaterialLaw::Elastic;
        let el = Material::from_card(&c);
        assert!(matches!(el, Material::Elastic(_)));
        assert_eq!((el.law_number(), el.history().len()), (1, 0));
        // The elastic constants are the card's, G = E/(2(1+ν)), RHO_0 = RHO_I when blank.
        assert_eq!(el.elastic(), jc.elastic());
        assert_eq!(el.rho_ref(), 7.80000028e-6);
        assert_eq!(el.shear_modulus(), 205.0 / (2.0 * (1.0 + 0.300000012)));
    }
}
