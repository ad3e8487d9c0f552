//! KJOINT2 joints (/SPRING with /PROP/TYPE45) over the kernel
//! `crate::element::joint`: each joint finds the rigid bodies of its two
//! nodes (their masses, inertias and arms set its reduced mass, its
//! automatic stiffness and its step).

use super::common::{decode_state, gather};
use super::{Block, BlockContext, BlockInput, ElemOut, ElemRow, ElemStep};
use crate::domain::LocalElements;
use crate::element::joint::{Joint, JointState, Side};
use crate::element::spring::finder;
use crate::element::SLOT;
use crate::model::{ElementKind, PropertyKind, RigidBody};
use crate::vec3::{dot, sub};
use rayon::prelude::*;
use std::collections::HashMap;

pub struct JointBlock {
    le: LocalElements,
    joints: Vec<Joint>,
    state: Vec<JointState>,
    steps: Vec<ElemStep>,
}

/// Where a node stands in the rigid bodies: the main node of body b, or a
/// secondary node of body b.
#[derive(Clone, Copy)]
enum InBody {
    Main,
    Secondary(usize),
}

/// Every body node's place, built once for the block.
fn body_nodes(bodies: &[RigidBody]) -> HashMap<u32, InBody> {
    let mut map = HashMap::new();
    for (b, body) in bodies.iter().enumerate() {
        for &n in &body.secondary_nodes {
            map.entry(n).or_insert(InBody::Secondary(b));
        }
    }
    for body in bodies {
        map.insert(body.main_node, InBody::Main);
    }
    map
}

/// The side of a joint whose node is `node` (global index) at `x`: the
/// rigid body holding it as a secondary node.
fn side_of(
    bodies: &[RigidBody],
    of_node: &HashMap<u32, InBody>,
    node: u32,
    x: [f64; 3],
) -> Result<Side, String> {
    let b = match of_node.get(&node) {
        Some(InBody::Secondary(b)) => &bodies[*b],
        Some(InBody::Main) => return Err("a joint node is the main node of a rigid body: expected secondary nodes of two rigid bodies".into()),
        None => return Err("a joint node outside a rigid body is not computed yet: expected secondary nodes of two rigid bodies".into()),
    };
    let j = &b.inertia;
    let principal = nalgebra::Matrix3::new(j[0], j[3], j[5], j[3], j[1], j[4], j[5], j[4], j[2])
        .symmetric_eigenvalues();
    let r = sub(x, b.center);
    Ok(Side {
        mass: b.mass,
        inertia: principal.min(),
        mean_inertia: (j[0] + j[1] + j[2]) / 3.0,
        arm2: dot(r, r),
    })
}

impl JointBlock {
    fn new(input: BlockInput) -> Result<Self, String> {
        let BlockInput {
            le,
            x,
            parts,
            props,
            functions,
            ctx,
            ..
        } = input;
        let BlockContext {
            rigid_bodies,
            node_global,
            dt_max,
        } = ctx;
        let global = |n: u32| {
            if node_global.is_empty() {
                n
            } else {
                node_global[n as usize]
            }
        };
        let of_node = body_nodes(rigid_bodies);
        let n = le.global.len();
        let mut joints = Vec::with_capacity(n);
        let mut state = Vec::with_capacity(n);
        for e in 0..n {
            let part = &parts[le.part[e] as usize];
            let prop = &props[part.prop.ok_or("joint part without property")? as usize];
            let PropertyKind::Joint(p) = &prop.card.kind else {
                return Err(format!("/PROP/{}: not a KJOINT2 property", prop.card.id));
            };
            let xe = gather::<2>(&le, e, x);
            let sides =
                [0, 1].map(|k| side_of(rigid_bodies, &of_node, global(le.nodes[2 * e + k]), xe[k]));
            let [s1, s2] = sides;
            let d = sub(xe[1], xe[0]);
            let (s1, s2) = (s1?, s2?);
            let joint = Joint::new(p, [s1, s2], dot(d, d), dt_max, finder(functions))
                .map_err(|err| format!("/PROP/KJOINT2/{}: {err}", prop.card.id))?;
            joints.push(joint);
            state.push(Joint::init(&xe));
        }
        Ok(JointBlock {
            le,
            joints,
            state,
            steps: vec![ElemStep::default(); n],
        })
    }
}

impl Block for JointBlock {
    fn kind(&self) -> ElementKind {
        ElementKind::Spring
    }
    fn local(&self) -> &LocalElements {
        &self.le
    }
    fn corners(&self) -> usize {
        2
    }
    fn compute(
        &mut self,
        x: &[[f64; 3]],
        _v: &[[f64; 3]],
        vr: &[[f64; 3]],
        dt: f64,
        contrib: &mut [[f64; SLOT]],
    ) {
        let (le, joints) = (&self.le, &self.joints);
        contrib
            .par_chunks_mut(2)
            .zip(self.state.par_iter_mut())
            .zip(self.steps.par_iter_mut())
            .enumerate()
            .for_each(|(e, ((c, st), out))| {
                let xe = gather::<2>(le, e, x);
                let we = if vr.is_empty() {
                    [[0.0; 3]; 2]
                } else {
                    gather::<2>(le, e, vr)
                };
                let o = joints[e].step(&xe, &we, dt, st);
                c[0] = o.f[0];
                c[1] = o.f[1];
                *out = ElemStep {
                    dt: o.dt,
                    failed: false,
                    bad: false,
                };
            });
    }
    fn steps(&self) -> &[ElemStep] {
        &self.steps
    }
    /// A joint neither fails nor inverts: nothing to settle.
    fn settle(&mut self) -> Option<(u32, &'static str)> {
        None
    }
    fn alive(&self, _e: usize) -> bool {
        true
    }
    fn rows(&self) -> Vec<ElemRow> {
        (0..self.le.global.len())
            .map(|e| {
                let s = &self.state[e];
                (
                    self.le.global[e],
                    [s.f[0], s.f[1], s.f[2], 0.0, 0.0, s.eint, 0.0],
                )
            })
            .collect()
    }
    fn outputs(&self) -> Vec<ElemOut> {
        self.state
            .iter()
            .map(|s| ElemOut {
                von_mises: (s.f[0] * s.f[0] + s.f[1] * s.f[1] + s.f[2] * s.f[2]).sqrt(),
                eint: s.eint,
                ..Default::default()
            })
            .collect()
    }
    fn export_state(&self, e: usize) -> Vec<u8> {
        bincode::serialize(&self.state[e]).expect("element state serializes")
    }
    fn import_state(&mut self, e: usize, bytes: &[u8]) -> Result<(), String> {
        self.state[e] = decode_state(bytes, "joint")?;
        Ok(())
    }
}

pub(super) fn build(input: BlockInput) -> Result<Box<dyn Block>, String> {
    Ok(Box::new(JointBlock::new(input)?))
}
