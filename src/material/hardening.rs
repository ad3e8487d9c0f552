//! The flow-stress curve a plastic law hands to the return maps for one
//! element and step: σ_y(ε_p), its slope, its cap, and a lower bound of σ_y
//! for the cheap elastic test.
//!
//! A law with another hardening (LAW36's tabulated curve, LAW44's
//! Cowper-Symonds factor on a + b·ε_p^n) adds one variant here and its arms in
//! the four functions below; the return maps (`super::return_map`,
//! `super::ilyushin`) and `super::PointLaw` do not change. A curve that
//! borrows its law's table gives this enum (and `PointLaw`) a lifetime; the
//! kernels, which write `&PointLaw`, do not change.

use super::johnson_cook::Flow;
use super::tabulated_flow::TabFlow;

/// σ_y(ε_p) at one element and step, with the rate and thermal factors of the
/// law already applied.
#[derive(Clone, Copy, Debug)]
pub enum Hardening<'a> {
    /// LAW2: σ_y = min(a + b·ε_p^n, cap) (see `super::johnson_cook`).
    JohnsonCook(Flow),
    /// LAW36: the law's curves at the element's strain rate (`super::law36`).
    Tabulated(TabFlow<'a>),
}

impl Hardening<'_> {
    /// Current yield stress σ_y(ε_p).
    #[inline]
    pub fn sig_y(&self, ep: f64) -> f64 {
        match self {
            Hardening::JohnsonCook(f) => f.sig_y(ep),
            Hardening::Tabulated(f) => f.sig_y(ep),
        }
    }

    /// dσ_y/dε_p (0 on the cap).
    #[inline]
    pub fn slope(&self, ep: f64) -> f64 {
        match self {
            Hardening::JohnsonCook(f) => f.slope(ep),
            Hardening::Tabulated(f) => f.slope(ep),
        }
    }

    /// The maximum flow stress (1e20 when the card gives none).
    #[inline]
    pub fn cap(&self) -> f64 {
        match self {
            Hardening::JohnsonCook(f) => f.cap,
            Hardening::Tabulated(_) => crate::model::NO_LIMIT,
        }
    }

    /// A lower bound of σ_y over every ε_p ≥ 0, when the curve has a cheap one
    /// (Johnson-Cook with b ≥ 0: min(a, cap)): a trial von Mises stress below
    /// it is elastic without evaluating the curve.
    #[inline]
    pub fn elastic_bound(&self) -> Option<f64> {
        match self {
            Hardening::JohnsonCook(f) => {
                let y_low = f.a.min(f.cap);
                (f.b >= 0.0).then_some(y_low)
            }
            Hardening::Tabulated(f) => f.lower_bound(),
        }
    }
}
