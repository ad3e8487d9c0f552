//! The global time step: the smallest scaled element step over every rank
//! (ties: smallest kind, then id), combined with the contact nodal and
//! kinematic steps, and the collective stop when any rank met a problem.

use super::setup::{Ctx, State, Step};
use crate::contact::ContactStep;
use crate::element::blocks::Block;
use crate::error::RunError;
use crate::model::ElementKind;
use rayon::prelude::*;

/// Largest growth of the step from one cycle to the next.
const GROWTH: f64 = 1.1;

/// What this rank found at the end of a cycle's forces.
#[derive(Default)]
pub(super) struct Found {
    /// The first element that cannot go on: (kind, global element index, what).
    pub element: Option<(ElementKind, u32, &'static str)>,
    /// A node with a non-finite position or velocity (its message).
    pub node: Option<String>,
    /// This rank's contact time step terms.
    pub contact: Option<ContactStep>,
    /// /DT/NODA/CST: this rank's smallest nodal step and its node id
    /// (the element steps are then not used).
    pub nodal: Option<(f64, u64)>,
    /// While a TYPE7-family interface is active: this rank's smallest
    /// unscaled nodal step over every node and its node id
    /// (`super::interface_nodal_step`); the contact's own nodal term is
    /// then in it.
    pub interface_nodal: Option<(f64, u64)>,
}

/// The kind index that names a node (NODE) in the step's candidates.
const NODE: usize = usize::MAX - 1;

/// A step candidate: (dt, kind index, element or node id).
type Candidate = (f64, usize, u64);

/// The smaller candidate; ties: smallest kind, then id.
fn smaller(a: Candidate, b: Candidate) -> Candidate {
    if b.0 < a.0 || (b.0 == a.0 && (b.1, b.2) < (a.1, a.2)) {
        b
    } else {
        a
    }
}

/// This rank's smallest element time step, and apart that of the elements
/// inside a rigid body (`in_body`): the reference deactivates them, so they
/// set the step only in a model with no other element.
fn smallest_element_step(
    cx: &Ctx,
    blocks: &[Box<dyn Block>],
    in_body: &[Vec<bool>],
) -> (Candidate, Candidate) {
    let none = (f64::INFINITY, usize::MAX, u64::MAX);
    let (mut free, mut body) = (none, none);
    for (b, inside) in blocks.iter().zip(in_body) {
        let ki = b.kind().index();
        let (global, ids) = (&b.local().global, &cx.g.element_ids[ki]);
        // Over the rank's threads: `smaller` is a total order on the
        // candidates (a NaN step never enters a fold started at `none`),
        // so the chunks' minima give the one loop's.
        let (f, bo) = b
            .steps()
            .par_iter()
            .enumerate()
            .with_min_len(4096)
            .filter(|(e, _)| b.alive(*e))
            .fold(
                || (none, none),
                |(f, bo), (e, st)| {
                    let c = (st.dt, ki, ids[global[e] as usize]);
                    if inside[e] {
                        (f, smaller(bo, c))
                    } else {
                        (smaller(f, c), bo)
                    }
                },
            )
            .reduce(
                || (none, none),
                |a, c| (smaller(a.0, c.0), smaller(a.1, c.1)),
            );
        free = smaller(free, f);
        body = smaller(body, bo);
    }
    (free, body)
}

/// Global minimum of the scaled element time steps and the contact steps
/// (collective); a problem found on any rank stops every rank.
pub(super) fn global_step(cx: &Ctx, s: &State, found: Found) -> Result<Step, RunError> {
    let (cycle, t) = (s.cycle, s.t);
    // The nodal step carries its own scale (ΔTsca): undo the /DT one applied below.
    let none = (f64::INFINITY, usize::MAX, u64::MAX);
    let (mut best, body) = match found.nodal {
        Some((d, id)) => ((d / cx.g.engine.dt_scale, NODE, id), none),
        None => smallest_element_step(cx, &s.blocks, &s.in_body),
    };
    if let Some((d, id)) = found.interface_nodal {
        best = smaller(best, (d, NODE, id));
    }
    let prob = found.element.map(|(k, ge, m)| {
        format!(
            "{} {} {m} at cycle {cycle}, time {t:e}",
            k.listing_name(),
            cx.g.element_ids[k.index()][ge as usize]
        )
    });
    let prob = found.node.or(prob);
    let mut cs = found.contact.unwrap_or(ContactStep {
        kin_dt: f64::INFINITY,
        ..Default::default()
    });
    if found.interface_nodal.is_some() {
        // Already in the nodal step over every node.
        cs.nodal_q = 0.0;
    }
    let all: Vec<(Candidate, Candidate, Option<String>, ContactStep)> =
        cx.world.allgather(&(best, body, prob, cs));
    if let Some(m) = all.iter().find_map(|(_, _, p, _)| p.clone()) {
        return Err(RunError::Physics(m));
    }
    let free = all.iter().fold(none, |acc, a| smaller(acc, a.0));
    let (d, ki, id) = if free.0.is_finite() {
        free
    } else {
        all.iter().fold(none, |acc, a| smaller(acc, a.1))
    };
    let contacts: Vec<ContactStep> = all.into_iter().map(|a| a.3).collect();
    let step = if d.is_finite() {
        Step {
            dt: d,
            what: if ki == NODE {
                "NODE"
            } else {
                crate::model::ElementKind::ALL[ki].listing_name()
            },
            id,
        }
    } else if cx.g.engine.dtix.1 > 0.0 {
        // No element (a model of rigid bodies): /DTIX's largest step.
        Step {
            dt: cx.g.engine.dtix.1 / cx.g.engine.dt_scale,
            what: "FIXED",
            id: 0,
        }
    } else if s.step.dt > 0.0 {
        // Every element has failed: the step grows by 10% a cycle from the
        // last one, as the reference engine's does (the nodes fly on).
        Step {
            dt: s.step.dt * GROWTH / cx.g.engine.dt_scale,
            ..s.step
        }
    } else {
        return Err(RunError::Physics(format!(
            "no element left to set the time step at cycle {cycle}, time {t:e}"
        )));
    };
    let mut step = with_contact(step, &contacts, cx.g.engine.dt_scale);
    step.dt *= cx.g.engine.dt_scale;
    step.dt *= super::damping::step_factor(cx, s.t, step.dt);
    // /DTIX: the first step at most ΔT_ini, every step at most ΔT_max.
    let (ini, max) = cx.g.engine.dtix;
    if s.cycle == 0 && ini > 0.0 {
        step.dt = step.dt.min(ini);
    }
    if max > 0.0 {
        step.dt = step.dt.min(max);
    }
    // The step grows by at most 10% a cycle, as the reference engine's does
    // (after an element is deleted its listing climbs ×1.1 per cycle to the
    // next element's step: RUPTURE_FAIL_TAB_ELEM_SAMP, RESSORT_couple).
    if s.step.dt > 0.0 && step.dt > GROWTH * s.step.dt {
        step.dt = GROWTH * s.step.dt;
    }
    Ok(step)
}

/// The element part of a contact node's stiffness, over 2M/Δt_el²: the
/// Belytschko-Tsay shell's CDT3 factor (`element::step_stiffness`, research
/// note `docs/notes/contact_time_step_research.md` §3): 0.81·2M/Δt_el², a
/// node alone has the step Δt_el/0.9.
const ELEMENT_PART: f64 = crate::element::step_stiffness::BELYTSCHKO_TSAY;

/// Contact (EQ. 8.8.5.1–2; note `contact_time_step_research.md` §6): with
/// a TYPE7-family interface active every node's own step is already a
/// candidate (`super::interface_nodal_step`, `nodal_q` is then 0); with the
/// other types alone a
/// contact node's step √(2M/(K_el + K_c)) = 1/√(0.81/Δt_el² + K_c/(2M)),
/// with Δt_el the smallest element step (no node's own is larger: the
/// step is never overestimated), a candidate beside the element step, not
/// added to it; then the kinematic step 0.5·(Gap − P)/(dP/dt), which the
/// /DT scale does not reduce (`scale`). Ties: the smallest node /
/// interface id.
fn with_contact(mut step: Step, all: &[ContactStep], scale: f64) -> Step {
    let d = step.dt;
    let (mut q, mut qid) = (0.0f64, 0u64);
    let (mut kin, mut kid) = (f64::INFINITY, 0u64);
    for c in all {
        if c.nodal_q > q || (c.nodal_q == q && q > 0.0 && c.node_id < qid) {
            q = c.nodal_q;
            qid = c.node_id;
        }
        if c.kin_dt < kin || (c.kin_dt == kin && c.inter_id < kid) {
            kin = c.kin_dt;
            kid = c.inter_id;
        }
    }
    if q > 0.0 {
        let nodal = 1.0 / (ELEMENT_PART / (d * d) + q).sqrt();
        if nodal < d {
            step = Step {
                dt: nodal,
                what: "NODE",
                id: qid,
            };
        }
    }
    // Compared before the caller scales the step: the kinematic step is
    // taken whole.
    if kin / scale < step.dt {
        step = Step {
            dt: kin / scale,
            what: "INTER",
            id: kid,
        };
    }
    step
}
