//! The yield curve of a tabulated law at one strain rate: two piecewise
//! linear curves σ_y(ε_p) bracketing the rate, mixed with weight r (LAW36,
//! `super::law36`; research note `docs/notes/law36_research.md` §2–4). Its own
//! module so that `super::hardening` and the law both use it without a cycle.

use serde::{Deserialize, Serialize};

/// One yield curve, its ordinates scaled by Fscale_i.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Curve {
    pub eps_dot: f64,
    pub x: Vec<f64>,
    pub y: Vec<f64>,
}

impl Curve {
    /// The segment holding `ep` (end segments extended): its index.
    #[inline]
    pub(super) fn segment(&self, ep: f64) -> usize {
        let n = self.x.len();
        if n < 2 {
            return 0;
        }
        self.x[1..n - 1].partition_point(|&x| x <= ep)
    }

    /// (f(ε_p), f′(ε_p)).
    #[inline]
    pub(super) fn at(&self, ep: f64) -> (f64, f64) {
        if self.x.len() < 2 {
            return (self.y.first().copied().unwrap_or(0.0), 0.0);
        }
        let i = self.segment(ep);
        let (x0, x1, y0, y1) = (self.x[i], self.x[i + 1], self.y[i], self.y[i + 1]);
        let s = if x1 > x0 { (y1 - y0) / (x1 - x0) } else { 0.0 };
        (y0 + s * (ep - x0), s)
    }
}

/// The curves at one strain rate: σ_y(ε_p) = (1 − r)·lo(ε_p) + r·hi(ε_p).
#[derive(Clone, Copy, Debug)]
pub struct TabFlow<'a> {
    pub(super) lo: &'a Curve,
    pub(super) hi: &'a Curve,
    pub(super) r: f64,
    pub(super) y_min: f64,
    /// The tension damage factor F_dmg of the point (1 without it): it
    /// scales σ_y and its slope (research note eq. 4, 9).
    pub(super) scale: f64,
}

impl TabFlow<'_> {
    #[inline]
    pub fn sig_y(&self, ep: f64) -> f64 {
        let (a, b) = (self.lo.at(ep).0, self.hi.at(ep).0);
        (self.scale * ((1.0 - self.r) * a + self.r * b)).max(1e-20)
    }

    #[inline]
    pub fn slope(&self, ep: f64) -> f64 {
        self.scale * ((1.0 - self.r) * self.lo.at(ep).1 + self.r * self.hi.at(ep).1)
    }

    /// A lower bound of σ_y when the rate weight lies in [0, 1] and the
    /// curves do not fall (their least ordinate); none otherwise.
    #[inline]
    pub fn lower_bound(&self) -> Option<f64> {
        ((0.0..=1.0).contains(&self.r) && self.y_min > 0.0).then_some(self.scale * self.y_min)
    }

    /// The curve with σ_y and its slope scaled by `f` (tension damage).
    #[inline]
    pub fn scaled(self, f: f64) -> Self {
        TabFlow { scale: f, ..self }
    }
}
