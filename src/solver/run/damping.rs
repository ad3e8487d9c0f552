//! /DAMP Rayleigh damping of nodal accelerations (reference guide /DAMP;
//! research note `docs/notes/springs_research.md` §5.3). Per damped degree
//! of freedom, with a the undamped acceleration F/m:
//!
//! a_d = [a − α v^{n−½} + (β*/Δt)(a − a_prev)] / (1 + α Δt/2),  β* = min(β, Δt)
//!
//! the mass term αMv taken at mid-step (implicitly), the stiffness term
//! −βKv as β times the rate of the acceleration. The work of the damping
//! forces, m(a_d − a)(v + a_d Δt/2)Δt, joins the external work (it is
//! negative), as the reference engine counts it. The time step is reduced
//! to Δt(√(1 + b²) − b), b = β*/Δt + αΔt/2 (α, β the largest of the active
//! cards), the central-difference bound of a damped oscillator.

use super::setup::{Ctx, State};
use crate::model::Damping;

fn active(d: &Damping, t: f64) -> bool {
    d.card.tstart <= t && t <= d.card.tstop
}

/// The damped accelerations of local node `l` (`a`: undamped, per degree
/// of freedom; `dofs`: which to damp), its velocity `v` before the step;
/// the damping work over the step joins the external work when the node
/// is owned.
#[allow(clippy::too_many_arguments)]
pub(super) fn damp(
    cx: &Ctx,
    s: &mut State,
    l: usize,
    a: &mut [f64; 6],
    v: [f64; 6],
    m: [f64; 6],
    dt: f64,
) {
    let Some(i) = cx.damp_of[l] else { return };
    let d = &cx.g.dampings[i as usize];
    if !active(d, s.t) || dt <= 0.0 {
        return;
    }
    let ds = &mut s.damping;
    if ds.prev.is_empty() {
        ds.prev = vec![[0.0; 6]; cx.n];
        ds.primed = vec![false; cx.n];
    }
    let primed = std::mem::replace(&mut ds.primed[l], true);
    for k in 0..6 {
        if m[k] <= 0.0 {
            continue;
        }
        let (alpha, beta) = (d.card.alpha[k], d.card.beta[k].min(dt));
        let rate = if primed {
            beta / dt * (a[k] - ds.prev[l][k])
        } else {
            0.0
        };
        ds.prev[l][k] = a[k];
        let ad = (a[k] - alpha * v[k] + rate) / (1.0 + 0.5 * alpha * dt);
        if cx.owned[l] {
            s.w_ext
                .add(m[k] * (ad - a[k]) * (v[k] + 0.5 * ad * dt) * dt);
        }
        a[k] = ad;
    }
}

/// The time step reduced by the active damping (1 without any).
pub(super) fn step_factor(cx: &Ctx, t: f64, dt: f64) -> f64 {
    let (mut alpha, mut beta) = (0.0f64, 0.0f64);
    for d in cx.g.dampings.iter().filter(|d| active(d, t)) {
        alpha = d.card.alpha.iter().fold(alpha, |m, &x| m.max(x));
        beta = d.card.beta.iter().fold(beta, |m, &x| m.max(x));
    }
    if dt <= 0.0 || (alpha == 0.0 && beta == 0.0) {
        return 1.0;
    }
    let b = beta.min(dt) / dt + 0.5 * alpha * dt;
    (1.0 + b * b).sqrt() - b
}
