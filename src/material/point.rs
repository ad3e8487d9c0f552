//! The hot-path object of the material update: a law prepared for one
//! element and step ([`PointLaw`]), updating one integration point at a time
//! — elastic trial, return map on the law's [`Hardening`] curve, failure.

use super::hardening::Hardening;
use super::return_map as rm;

/// What one plane-stress point update reports.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PlaneStressResult {
    /// Plastic work increment per unit volume (σ_vm·Δε_p at the end of the step).
    pub d_wplas: f64,
    /// Thickness strain increment Δε_zz: elastic plane-stress part plus the
    /// incompressible plastic part (used when Ithick = 1).
    pub d_ezz: f64,
    /// The point has failed (ε_p ≥ EPS_p_max): its stress is zero from now on.
    pub failed: bool,
}

/// A material prepared for one element and step (`Material::at`): the law's
/// flow-stress curve is prepared once (its strain-rate and thermal factors
/// depend on the element's strain rate and temperature), then every
/// integration point is updated with
/// [`PointLaw::plane_stress`] or [`PointLaw::solid`] (or, for a section
/// computed with global integration, `PointLaw::section_global`).
#[derive(Clone, Copy, Debug)]
pub struct PointLaw<'a> {
    pub(super) e: f64,
    pub(super) nu: f64,
    pub(super) g: f64,
    pub(super) eps_p_max: f64,
    pub(super) hardening: Option<Hardening<'a>>,
}

impl PointLaw<'_> {
    /// The law with its yield stress and hardening slope scaled by `f`
    /// (LAW36 tension damage; other laws unchanged).
    #[inline]
    pub fn with_yield_scale(&self, f: f64) -> Self {
        let mut p = *self;
        if let Some(Hardening::Tabulated(t)) = p.hardening {
            p.hardening = Some(Hardening::Tabulated(t.scaled(f)));
        }
        p
    }

    /// True when a point with this plastic strain has failed (ε_p ≥ EPS_p_max).
    #[inline]
    pub fn has_failed(&self, eps_p: f64) -> bool {
        eps_p >= self.eps_p_max
    }

    /// Current yield stress (∞ for an elastic material).
    #[inline]
    pub fn yield_stress(&self, eps_p: f64) -> f64 {
        self.hardening.map_or(f64::INFINITY, |f| f.sig_y(eps_p))
    }

    /// Plane-stress update at one integration point: `sig` = [σxx, σyy, σxy] in
    /// the element's local frame, updated in place from the strain increment
    /// `deps` = [Δεxx, Δεyy, Δγxy] (engineering shear); `eps_p` is the
    /// equivalent plastic strain.
    /// Iplas: 0 radial return, 1 exact (Newton) plane-stress projection,
    /// 2 approximate normal + radial (see the johnson_cook module doc).
    ///
    /// Elastic trial: σ += C Δε with C the plane-stress Hooke matrix
    /// (E/(1−ν²)·`[[1,ν,0],[ν,1,0],[0,0,(1−ν)/2]]`). Thickness strain:
    /// Δε_zz = [−ν(Δεxx+Δεyy) + (1−2ν)Δε^p_zz]/(1−ν) (elastic plane stress plus
    /// incompressible plastic flow).
    /// A point whose ε_p reaches EPS_p_max fails: its stress is set to zero and
    /// stays zero (`failed` is then true on every later call).
    #[inline]
    pub fn plane_stress(
        &self,
        sig: &mut [f64; 3],
        eps_p: &mut f64,
        deps: [f64; 3],
        iplas: i64,
    ) -> PlaneStressResult {
        if self.has_failed(*eps_p) {
            *sig = [0.0; 3];
            return PlaneStressResult {
                failed: true,
                ..Default::default()
            };
        }
        let (e, nu, g) = (self.e, self.nu, self.g);
        let a11 = e / (1.0 - nu * nu);
        sig[0] += a11 * (deps[0] + nu * deps[1]);
        sig[1] += a11 * (nu * deps[0] + deps[1]);
        sig[2] += g * deps[2];
        let ezz_el = -nu * (deps[0] + deps[1]);
        self.plane_stress_after_trial(sig, eps_p, ezz_el, iplas)
    }

    /// E, ν and G of the elastic trial (for kernels that form the trial
    /// σ += C Δε of [`PointLaw::plane_stress`] for several elements at once).
    #[inline]
    pub fn elastic_constants(&self) -> (f64, f64, f64) {
        (self.e, self.nu, self.g)
    }

    /// Whether a trial stress of von Mises square `svm2` is certainly
    /// elastic without evaluating the flow curve: an elastic law, or below
    /// the curve's lower bound (what [`PointLaw::plane_stress_after_trial`]
    /// tests first).
    #[inline]
    pub fn surely_elastic(&self, svm2: f64) -> bool {
        match self.hardening {
            None => true,
            Some(flow) => flow.elastic_bound().is_some_and(|y| svm2 <= y * y),
        }
    }

    /// The rest of [`PointLaw::plane_stress`] once the elastic trial is in
    /// `sig` (`ezz_el` = −ν(Δεxx + Δεyy), the point not failed): the return
    /// map, the plastic work, Δε_zz and failure.
    #[inline]
    pub fn plane_stress_after_trial(
        &self,
        sig: &mut [f64; 3],
        eps_p: &mut f64,
        ezz_el: f64,
        iplas: i64,
    ) -> PlaneStressResult {
        let (e, nu, g) = (self.e, self.nu, self.g);
        let Some(flow) = self.hardening else {
            return PlaneStressResult {
                d_ezz: ezz_el / (1.0 - nu),
                ..Default::default()
            };
        };
        // Fast elastic exit below a lower bound of σ_y (Johnson-Cook: the
        // initial yield stress when b ≥ 0): no power of ε_p and no call.
        let svm2 = sig[0] * sig[0] + sig[1] * sig[1] - sig[0] * sig[1] + 3.0 * sig[2] * sig[2];
        if let Some(y_low) = flow.elastic_bound() {
            if svm2 <= y_low * y_low {
                return PlaneStressResult {
                    d_ezz: ezz_el / (1.0 - nu),
                    ..Default::default()
                };
            }
        }
        let (dep, ezz_p) = rm::plane_stress_return(sig, *eps_p, &flow, e, nu, g, iplas);
        if dep == 0.0 {
            return PlaneStressResult {
                d_ezz: ezz_el / (1.0 - nu),
                ..Default::default()
            };
        }
        *eps_p += dep;
        let svm =
            (sig[0] * sig[0] + sig[1] * sig[1] - sig[0] * sig[1] + 3.0 * sig[2] * sig[2]).sqrt();
        let mut r = PlaneStressResult {
            d_wplas: svm * dep,
            d_ezz: (ezz_el + (1.0 - 2.0 * nu) * ezz_p) / (1.0 - nu),
            failed: false,
        };
        if self.has_failed(*eps_p) {
            *sig = [0.0; 3];
            r.failed = true;
        }
        r
    }

    /// 3-D update: `sig` = [σxx σyy σzz σxy σyz σzx], `deps` likewise with
    /// engineering shears. Hooke's law for the trial, radial return (exact
    /// consistency, Newton on Δε_p) for a plastic law. Returns the plastic work per unit
    /// volume. A failed point (ε_p ≥ EPS_p_max) keeps zero stress.
    pub fn solid(&self, sig: &mut [f64; 6], eps_p: &mut f64, deps: [f64; 6]) -> f64 {
        if self.has_failed(*eps_p) {
            *sig = [0.0; 6];
            return 0.0;
        }
        let (e, nu, g) = (self.e, self.nu, self.g);
        let lam = e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
        let tr = deps[0] + deps[1] + deps[2];
        for k in 0..3 {
            sig[k] += lam * tr + 2.0 * g * deps[k];
            sig[k + 3] += g * deps[k + 3];
        }
        let Some(flow) = self.hardening else {
            return 0.0;
        };
        let dep = rm::radial_return_3d(sig, *eps_p, &flow, g);
        if dep == 0.0 {
            return 0.0;
        }
        *eps_p += dep;
        let w = flow.sig_y(*eps_p) * dep;
        if self.has_failed(*eps_p) {
            *sig = [0.0; 6];
        }
        w
    }
}
