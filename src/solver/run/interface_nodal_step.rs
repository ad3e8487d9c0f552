//! The nodal time step the reference engine takes over every node once an
//! interface of the TYPE7 family is active (its dtnoda.F "INTERFACES 7"
//! branch, EQ. 8.8.5.2 of the theory manual; research notes
//! `docs/notes/contact_time_step_research.md` §1-§3 and
//! `docs/notes/type25_nodal_step_research.md` §1-§3):
//!
//! Δt_n = ΔTsca·√(2·M_n / (K_el,n + K_c,n))
//!
//! over every node with mass, without /DT/NODA. K_c,n is the contact
//! stiffness the interfaces put on the node this cycle (`State::kcont`);
//! K_el,n is the sum over the node's elements of what each element's own
//! time step routine gives its nodes: c·2·(m_e/corners)/Δt_e², Δt_e the
//! element's unscaled step, m_e its mass, c its formulation's factor
//! (`Block::nodal_step_factor`: 1 for solids, the reference's
//! ¼·ρV/Δt² per brick node; 0.81 for the Belytschko-Tsay shell, CDT3;
//! 1/(1 − ν²) for QEPH, CNDT3). The step is a candidate beside the element
//! steps and is named after its node (NODE).
//!
//! The reference sets the flag for TYPE7, 10, 11, 17, 18, 20, 23, 24 and 25
//! once t reaches the interface's Tstart (inttri.F, I7KGLO) and never
//! clears it; of those crashsim computes 7, 11 (19 = 7 + 11), 24 and 25.
//! Nodes of rigid bodies are left out (their body steps as one, as in the
//! reference, whose dtnoda skips them), and so are tied secondary nodes.

use super::setup::{Ctx, InterfaceStep, State};
use crate::element::blocks::Block;
use crate::element::SLOT;
use crate::model::ElementKind;
use rayon::prelude::*;

/// The interface types whose activity makes the step nodal (I7KGLO).
const NODAL_TYPES: [u32; 5] = [7, 11, 19, 24, 25];

/// Whether some TYPE7-family interface is active at `t` (t ≥ Tstart), and
/// no /DT/NODA takes the step instead.
fn nodal_rule_on(cx: &Ctx, s: &State) -> bool {
    cx.g.engine.nodal.is_none()
        && cx.g.engine.nodal_cst.is_none()
        && s.contact
            .setup
            .interfaces
            .iter()
            .any(|i| NODAL_TYPES.contains(&i.type_number) && s.t >= i.tstart)
}

/// This rank's smallest nodal step (unscaled: the /DT scale is applied
/// with the element steps') and its node id, or `None` when the rule is
/// off. Collective while it is on (the stiffness is summed over the ranks
/// as the forces are).
///
/// Where every element's c is at most 1 (Belytschko-Tsay shells, solids),
/// a node without contact stiffness steps at least as long as its
/// smallest element (K_el ≤ c·2·M/Δt_e,min², M ≥ its elements' shares),
/// which is already a candidate: only the nodes with contact stiffness are
/// looked at, and only their elements' stiffness is computed.
pub(super) fn interface_nodal_step(cx: &Ctx, s: &mut State) -> Option<(f64, u64)> {
    if !nodal_rule_on(cx, s) {
        return None;
    }
    if !s.interface_step.ready {
        s.interface_step = prepare(cx, s);
    }
    let mass = cx.mass.read().unwrap();
    let (is, blocks, kcont) = (&mut s.interface_step, &s.blocks, &s.kcont);
    let eligible = |l: usize| cx.owned[l] && !cx.in_body[l] && !cx.tied_tr[l] && mass[l] > 0.0;
    let id = |l: usize| cx.g.node_ids[cx.sd.node_global[l] as usize];
    // The largest K/(2M), ties to the smallest node id.
    let mut best = (0.0f64, u64::MAX);
    let mut consider = |l: usize, k_el: f64| {
        let q = (k_el + kcont[l]) / (2.0 * mass[l]);
        if q > best.0 || (q == best.0 && q > 0.0 && id(l) < best.1) {
            best = (q, id(l));
        }
    };
    if is.c_max > 1.0 {
        element_stiffness(blocks, is);
        let (k, elem) = (&is.k, &is.elem_of_slot);
        let value = |slot: usize| k[elem[slot] as usize];
        let remote = s.plan.exchange_scalar(cx.world, value);
        for l in (0..cx.n).filter(|&l| eligible(l)) {
            consider(l, s.plan.node_sum(l, value, &remote));
        }
    } else {
        let value = |slot: usize| slot_stiffness(blocks, is, slot);
        let remote = s.plan.exchange_scalar(cx.world, value);
        for l in (0..cx.n).filter(|&l| kcont[l] > 0.0 && eligible(l)) {
            consider(l, s.plan.node_sum(l, value, &remote));
        }
    }
    if best.0 > 0.0 {
        Some(((1.0 / best.0).sqrt(), best.1))
    } else {
        Some((f64::INFINITY, u64::MAX))
    }
}

/// Each element's constant c·2·m_e/corners (`Block::nodal_step_factor`;
/// masses on the initial geometry), the slots' elements and the largest c
/// over every rank (collective).
fn prepare(cx: &Ctx, s: &State) -> InterfaceStep {
    let (mut coef, mut first, mut c_max) = (Vec::new(), Vec::new(), [0.0f64]);
    let mut elem_of_slot = vec![0u32; s.contrib.len()];
    for (i, (b, inside)) in s.blocks.iter().zip(&s.in_body).enumerate() {
        let nc = b.corners();
        first.push(coef.len());
        let m = element_masses(cx, s, b.as_ref());
        for (e, &m) in m.iter().enumerate() {
            let c = b.nodal_step_factor(e);
            if m > 0.0 && !inside[e] {
                c_max[0] = c_max[0].max(c);
            }
            let slots = cx.offsets[i] + e * nc..cx.offsets[i] + (e + 1) * nc;
            elem_of_slot[slots].fill(coef.len() as u32);
            coef.push(if inside[e] {
                0.0
            } else {
                c * 2.0 * m / nc as f64
            });
        }
    }
    cx.world.max_f64(&mut c_max);
    InterfaceStep {
        k: vec![0.0; coef.len()],
        coef,
        first,
        elem_of_slot,
        c_max: c_max[0],
        ready: true,
    }
}

/// Each element's mass. Trusses and beams, whose mass the output's
/// element masses leave out, take it from their nodal stiffness when the
/// rule first applies (`Block::nodal_stiffness`, EA/l at each end, which
/// gives a lone element's nodes its own step: m_e = K·Δt_e²·corners/2, so
/// c = 1 for them). Left out, a line element's nodes in contact would step
/// as √(2M/(K_s + K_c)) instead of √(2M/(K_s + K_t + K_c)): too long.
fn element_masses(cx: &Ctx, s: &State, b: &dyn Block) -> Vec<f64> {
    let nc = b.corners();
    if matches!(b.kind(), ElementKind::Truss | ElementKind::Beam) {
        let mut k = vec![[0.0; SLOT]; nc * b.local().global.len()];
        if b.nodal_stiffness(&s.x, &mut k) {
            return b
                .steps()
                .iter()
                .enumerate()
                .map(|(e, st)| k[e * nc][0] * st.dt * st.dt * nc as f64 / 2.0)
                .map(|m| if m.is_finite() { m } else { 0.0 })
                .collect();
        }
    }
    crate::output::history::element_masses(cx.g, &cx.sd.x, b)
}

/// Element `e` of `b`: coef/Δt_e², 0 once it is deleted.
fn stiffness(b: &dyn Block, e: usize, coef: f64) -> f64 {
    let dt = b.steps()[e].dt;
    if coef > 0.0 && dt > 0.0 && dt.is_finite() && b.alive(e) {
        coef / (dt * dt)
    } else {
        0.0
    }
}

/// The stiffness of a slot's element, computed on its own.
fn slot_stiffness(blocks: &[Box<dyn Block>], is: &InterfaceStep, slot: usize) -> f64 {
    let f = is.elem_of_slot[slot] as usize;
    let i = is.first.partition_point(|&start| start <= f) - 1;
    stiffness(blocks[i].as_ref(), f - is.first[i], is.coef[f])
}

/// Every element's stiffness this cycle, over the rank's threads.
fn element_stiffness(blocks: &[Box<dyn Block>], is: &mut InterfaceStep) {
    for (i, b) in blocks.iter().enumerate() {
        let start = is.first[i];
        let n = b.local().global.len();
        let coef = &is.coef[start..start + n];
        is.k[start..start + n]
            .par_iter_mut()
            .with_min_len(1024)
            .enumerate()
            .for_each(|(e, k)| *k = stiffness(b.as_ref(), e, coef[e]));
    }
}
