//! /PLOAD on this rank: each segment is computed by the rank holding the
//! element under it (`model::PressureLoad::carriers`), at t^n on the
//! current positions (`kinematics::pressure`), and its corner forces are
//! summed into the external forces with their own assembly plan, keyed by
//! (segment, corner) in one global order: every rank holding a node gets
//! the same total, in the same summation order for any partition.
//! A segment whose element was deleted takes no load (Idel 1), unless its
//! card keeps it (Idel 2).

use super::super::assembly::{AssemblyPlan, SlotKey, SLOT};
use crate::domain::Subdomain;
use crate::element::blocks::Block;
use crate::global::GlobalData;
use crate::kinematics::{function, pressure::segment_forces};
use crate::parallel::World;
use std::collections::HashMap;

/// The key kind of pressure slots (past every element kind).
const PRESSURE_KEY: usize = 255;

struct LocalSegment {
    load: u32,
    nodes: [u32; 4],
    triangle: bool,
    block: u32,
    element: u32,
    /// Its first slot in `contrib`.
    slot: u32,
}

pub(super) struct PressureState {
    segments: Vec<LocalSegment>,
    plan: AssemblyPlan,
    contrib: Vec<[f64; SLOT]>,
    sum: Vec<[f64; SLOT]>,
}

/// The segments this rank carries and their assembly (None without /PLOAD,
/// on every rank alike: the plan's exchange is collective); `local_of`:
/// the local index of each global node on this rank.
pub(super) fn build(
    world: &World,
    sd: &Subdomain,
    g: &GlobalData,
    local_of: &HashMap<u32, u32>,
    blocks: &[Box<dyn Block>],
) -> Option<PressureState> {
    if g.pressure_loads.is_empty() {
        return None;
    }
    let mut here: HashMap<(u8, u32), (u32, u32)> = HashMap::new();
    for (bi, b) in blocks.iter().enumerate() {
        let ki = b.kind().index() as u8;
        for (e, &ge) in b.local().global.iter().enumerate() {
            here.insert((ki, ge), (bi as u32, e as u32));
        }
    }
    let mut segments = Vec::new();
    let mut slots: Vec<(u32, SlotKey)> = Vec::new();
    let mut key = 0u32;
    for (li, load) in g.pressure_loads.iter().enumerate() {
        for (seg, carrier) in load.segments.iter().zip(&load.carriers) {
            if let Some(&(block, element)) = here.get(carrier) {
                let nodes = seg.map(|gn| local_of[&gn]);
                let triangle = seg[3] == seg[2];
                let slot = slots.len() as u32;
                let corners = if triangle { 3 } else { 4 };
                for (c, &l) in nodes.iter().take(corners).enumerate() {
                    slots.push((l, SlotKey::new(PRESSURE_KEY, key, c)));
                }
                segments.push(LocalSegment {
                    load: li as u32,
                    nodes,
                    triangle,
                    block,
                    element,
                    slot,
                });
            }
            key += 1;
        }
    }
    let plan = AssemblyPlan::build(world, sd, &slots);
    Some(PressureState {
        segments,
        plan,
        contrib: vec![[0.0; SLOT]; slots.len()],
        sum: vec![[0.0; SLOT]; sd.node_global.len()],
    })
}

/// Where the pressures are evaluated: the run's data, its function index
/// (function id → index) and this rank's communicator.
pub(super) struct Loads<'a> {
    pub world: &'a World,
    pub g: &'a GlobalData,
    pub fct_index: &'a HashMap<u64, usize>,
}

/// Adds the pressures at time t on positions x to the external forces.
pub(super) fn add(
    on: &Loads,
    p: &mut PressureState,
    blocks: &[Box<dyn Block>],
    x: &[[f64; 3]],
    t: f64,
    fext: &mut [[f64; SLOT]],
) {
    let g = on.g;
    let values: Vec<f64> = g
        .pressure_loads
        .iter()
        .map(|l| {
            let f = &g.functions[on.fct_index[&l.card.fct]];
            function::scaled(f, t, l.card.ascale_x, l.card.fscale_y)
        })
        .collect();
    for s in &p.segments {
        let load = &g.pressure_loads[s.load as usize];
        let loaded =
            load.card.keep_after_deletion || blocks[s.block as usize].alive(s.element as usize);
        let pressure = if loaded { values[s.load as usize] } else { 0.0 };
        let f = segment_forces(s.nodes.map(|l| x[l as usize]), s.triangle, pressure);
        let corners = if s.triangle { 3 } else { 4 };
        for (c, fc) in f.iter().take(corners).enumerate() {
            let slot = &mut p.contrib[s.slot as usize + c];
            slot[..3].copy_from_slice(fc);
        }
    }
    p.plan.assemble(on.world, &p.contrib, &mut p.sum);
    for (fe, ps) in fext.iter_mut().zip(&p.sum) {
        for k in 0..3 {
            fe[k] += ps[k];
        }
    }
}
