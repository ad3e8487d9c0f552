//! The force phases of a cycle at the current positions: element forces
//! and their assembly, external loads, contact (with the element deletions
//! the interfaces learn of).

use super::super::assembly::SLOT;
use super::setup::{Ctx, State};
use super::time_step::Found;
use crate::contact::{ContactStep, ContactSystem};
use crate::element::blocks::Block;
use crate::kinematics::function;
use crate::model::{Dof, ElementKind};
use std::collections::HashMap;

/// Element, external and contact forces at the state's positions; `dt` is
/// the step that led there (0 at cycle 0).
pub(super) fn all_forces(cx: &Ctx, s: &mut State, dt: f64) -> Found {
    // Idel: the elements deleted in the last cycle leave the interfaces
    // now, before this cycle's contact, as the reference engine removes
    // them after its element forces and computes contact before them
    // (docs/notes/idel_release_timing_research.md, Q1 and Q3).
    let dead = newly_deleted(s);
    let element = compute_all(
        &mut s.blocks,
        &cx.offsets,
        &s.x,
        &s.v,
        &s.vr,
        dt,
        &mut s.contrib,
    );
    s.plan.assemble(cx.world, &s.contrib, &mut s.fint);
    external_forces(cx, s.t, &mut s.fext);
    if let Some(p) = s.pressure.as_mut() {
        let on = super::pressure::Loads {
            world: cx.world,
            g: cx.g,
            fct_index: &cx.fct_index,
        };
        super::pressure::add(&on, p, &s.blocks, &s.x, s.t, &mut s.fext);
    }
    let contact = contact_forces(cx, s, dt, &dead);
    Found {
        element,
        node: None,
        contact,
        nodal: None,
        interface_nodal: None,
    }
}

/// Runs every block; returns the first stopping problem (kind, global element index, what).
fn compute_all(
    blocks: &mut [Box<dyn Block>],
    offsets: &[usize],
    x: &[[f64; 3]],
    v: &[[f64; 3]],
    vr: &[[f64; 3]],
    dt: f64,
    contrib: &mut [[f64; SLOT]],
) -> Option<(ElementKind, u32, &'static str)> {
    let mut problem = None;
    for (i, b) in blocks.iter_mut().enumerate() {
        b.compute(x, v, vr, dt, &mut contrib[offsets[i]..offsets[i + 1]]);
        if let Some((ge, what)) = b.settle() {
            problem.get_or_insert((b.kind(), ge, what));
        }
    }
    problem
}

/// Concentrated loads and gravity at time t, per local node (force, moment).
fn external_forces(cx: &Ctx, t: f64, fext: &mut [[f64; SLOT]]) {
    for f in fext.iter_mut() {
        *f = [0.0; SLOT];
    }
    concentrated_loads(cx, t, fext);
    gravity(cx, t, fext);
}

fn concentrated_loads(cx: &Ctx, t: f64, fext: &mut [[f64; SLOT]]) {
    let fct: &HashMap<u64, usize> = &cx.fct_index;
    for (nodes, c) in &cx.cloads {
        let val = function::scaled(
            &cx.g.functions[fct[&c.card.fct]],
            t,
            c.card.ascale_x,
            c.card.fscale_y,
        );
        let d = c.card.dir.index();
        for &l in nodes {
            fext[l as usize][d] += val;
        }
    }
}

/// Gravity acts on each node's own mass (not the tied masses moved to main nodes).
fn gravity(cx: &Ctx, t: f64, fext: &mut [[f64; SLOT]]) {
    let mass = &cx.sd.mass;
    for (nodes, c) in &cx.gravity {
        let acc = if c.card.fct == 0 {
            c.card.fscale_y
        } else {
            function::scaled(
                &cx.g.functions[cx.fct_index[&c.card.fct]],
                t,
                c.card.ascale_x,
                c.card.fscale_y,
            )
        };
        let d = match c.card.dir {
            Dof::X | Dof::Xx => 0,
            Dof::Y | Dof::Yy => 1,
            Dof::Z | Dof::Zz => 2,
        };
        for &l in nodes {
            fext[l as usize][d] += mass[l as usize] * acc;
        }
    }
}

/// Idel: the elements of this rank deleted since the last look, as (kind index, element).
pub(super) fn newly_deleted(s: &mut State) -> Vec<(u8, u32)> {
    let mut out = Vec::new();
    if !s.contact.tracks_deletion() {
        return out;
    }
    for (b, w) in s.blocks.iter().zip(s.was_alive.iter_mut()) {
        let ki = b.kind().index() as u8;
        for (e, a) in w.iter_mut().enumerate() {
            if *a && !b.alive(e) {
                *a = false;
                out.push((ki, b.local().global[e]));
            }
        }
    }
    out
}

/// Contact forces and stiffness per local node at time t; an impact
/// releases the secondary node's boundary conditions (IBC).
fn contact_forces(cx: &Ctx, s: &mut State, dt: f64, deleted: &[(u8, u32)]) -> Option<ContactStep> {
    s.fcont.iter_mut().for_each(|f| *f = [0.0; 3]);
    s.kcont.iter_mut().for_each(|k| *k = 0.0);
    s.release.clear();
    let contact: &mut ContactSystem = &mut s.contact;
    let step = contact.compute(
        cx.world,
        &s.x,
        &s.v,
        &cx.mass.read().unwrap(),
        s.t,
        dt,
        &mut s.fcont,
        &mut s.kcont,
        &mut s.release,
        deleted,
        &s.bodies,
    );
    for &(l, bits) in &s.release {
        for k in 0..3 {
            if bits >> k & 1 == 1 {
                s.fixed[l as usize][k] = false;
            }
        }
    }
    step
}
