//! The integration phases of a cycle: the external work and the energy
//! contact took over the step, positions at n+1, the clock, and the check
//! that the state stayed finite.

use super::kinematics::{divided, NODE_CHUNK};
use super::setup::{Ctx, State};
use crate::parallel::ExactSum;
use rayon::prelude::*;

/// External work over the step [t^n, t^{n+1}], f^n·v^{n+½}·Δt^{n+½} (the
/// whole step: with the kinetic energy at t^n, a constant load's work is
/// then ½m|v^n|² exactly, as Radioss lists it; a half first step would lose
/// ¼ f a Δt²); the energy the
/// contact forces take (elastic, damping, friction), with the mean of the
/// velocities before and after the step: f·v_after alone overstates the
/// work by (f·Δt)²/2M, which adds up when friction forces are large and
/// their work small. A rigid body's node moves with its body, not by its
/// own force over its own mass: it takes its velocity after the step. An
/// imposed velocity takes the mean of the one before and the one imposed
/// (the forces did not move it: a node driven into a stiff contact would
/// otherwise book f²Δt²/2M a step).
pub(super) fn work(cx: &Ctx, s: &mut State, dt_v: f64) {
    let mass = cx.mass.read().unwrap();
    let imposed = imposed_by_node(&mut s.imposed_before);
    let nodes = WorkNodes {
        st: &*s,
        mass: &mass,
        owned: &cx.owned,
        tied_tr: &cx.tied_tr,
        in_body: &cx.in_body,
        imposed: &imposed,
    };
    // Exact sums: the chunks' sums merge to the bits of one loop's.
    let n = cx.n;
    let sums: Vec<[ExactSum; 2]> = (0..n.div_ceil(NODE_CHUNK))
        .into_par_iter()
        .map(|c| nodes.work(c * NODE_CHUNK..((c + 1) * NODE_CHUNK).min(n), dt_v))
        .collect();
    for [ext, contact] in &sums {
        s.w_ext.merge(ext);
        s.e_contact.merge(contact);
    }
    s.imposed_before = imposed;
    s.imposed_before.clear();
    // The reactions of analytic contact surfaces (TYPE14) on their rigid
    // bodies, at the mean velocity of the body's point over the step.
    for (b, l) in &s.contact.body_loads {
        let body = &s.bodies[*b];
        let after = body.velocity_at(l.x, body.center);
        let (v0, w0) = s.bodies_v_before[*b];
        let r = [0, 1, 2].map(|k| l.x[k] - body.center[k]);
        let spin = crate::vec3::cross(w0, r);
        for k in 0..3 {
            let v = 0.5 * (after[k] + v0[k] + spin[k]);
            s.e_contact.add(-l.f[k] * v * dt_v);
        }
    }
}

/// What the work of a cycle reads, node by node.
struct WorkNodes<'a> {
    st: &'a State,
    mass: &'a [f64],
    owned: &'a [bool],
    tied_tr: &'a [bool],
    in_body: &'a [bool],
    imposed: &'a [(u32, u8, f64)],
}

impl WorkNodes<'_> {
    /// The external work and the contact's energy of the owned nodes of
    /// `range` over the step.
    fn work(&self, range: std::ops::Range<usize>, dt_v: f64) -> [ExactSum; 2] {
        let s = self.st;
        let mut sums = [ExactSum::default(), ExactSum::default()];
        for l in range.filter(|&l| self.owned[l]) {
            let m = self.mass[l];
            let (fe, fi, fc, ft) = (&s.fext[l], &s.fint[l], &s.fcont[l], &s.ftie[l]);
            // Half the accelerations, ½F/m.
            let half_acc = divided([0, 1, 2].map(|k| 0.5 * (fe[k] - fi[k] + fc[k] + ft[k])), m);
            for k in 0..3 {
                sums[0].add(fe[k] * s.v[l][k] * s.dt);
                sums[0].add(fe[3 + k] * s.vr[l][k] * s.dt);
                let v = s.v[l][k];
                let mean = if s.fixed[l][k] || m <= 0.0 || self.tied_tr[l] || self.in_body[l] {
                    v
                } else if let Some(before) = self.imposed_before(l, k) {
                    0.5 * (before + v)
                } else {
                    v - half_acc[k] * dt_v
                };
                sums[1].add(-fc[k] * mean * dt_v);
            }
        }
        sums
    }

    /// The velocity before the step of direction `k` of node `l`, where
    /// this cycle imposed it.
    fn imposed_before(&self, l: usize, k: usize) -> Option<f64> {
        self.imposed
            .binary_search_by_key(&(l as u32, k as u8), |e| (e.0, e.1))
            .ok()
            .map(|i| self.imposed[i].2)
    }
}

/// This cycle's imposed directions sorted by (node, direction); where a
/// direction was imposed twice, the last imposition's velocity before it.
fn imposed_by_node(list: &mut Vec<(u32, u8, f64)>) -> Vec<(u32, u8, f64)> {
    let mut v = std::mem::take(list);
    v.reverse();
    v.sort_by_key(|e| (e.0, e.1));
    v.dedup_by_key(|e| (e.0, e.1));
    v
}

/// Positions at n+1: nodes by their velocity, rigid-body main nodes at
/// their body's centre, tied secondary nodes at their place on the moved segment.
pub(super) fn positions(cx: &Ctx, s: &mut State) {
    let (dt, is_main) = (s.dt, &cx.is_main);
    s.x.par_chunks_mut(NODE_CHUNK)
        .zip(s.v.par_chunks(NODE_CHUNK))
        .enumerate()
        .for_each(|(c, (x, v))| {
            for (i, (x, v)) in x.iter_mut().zip(v).enumerate() {
                if !is_main[c * NODE_CHUNK + i] {
                    for k in 0..3 {
                        x[k] += dt * v[k];
                    }
                }
            }
        });
    for (b, lb) in cx.local_bodies.iter().enumerate() {
        if let Some(l) = lb.main_local {
            s.x[l as usize] = s.bodies[b].center;
        }
    }
    if !s.ties.is_empty() {
        s.ties.place(&mut s.x);
    }
}

/// t += Δt; the fault injection of the resilience tests (CRASHSIM_FAULT)
/// makes its rank die abruptly at its cycle.
pub(super) fn advance_clock(cx: &Ctx, s: &mut State) {
    s.t += s.dt;
    s.cycle += 1;
    s.dt_prev = s.dt;
    let (rank, cycle) = (cx.world.rank(), s.cycle);
    if cx.fault.is_some_and(|(r, c)| r == rank && c == cycle) {
        eprintln!("crashsim: rank {rank}: CRASHSIM_FAULT: aborting at cycle {cycle}");
        std::process::abort();
    }
}

/// Non-finite state: names the node (reported with the element problems,
/// collectively, so that every rank stops at the same cycle).
pub(super) fn non_finite(cx: &Ctx, s: &State) -> Option<String> {
    (0..cx.n)
        .find(|&l| {
            !(s.x[l]
                .iter()
                .chain(&s.v[l])
                .chain(&s.vr[l])
                .all(|c| c.is_finite()))
        })
        .map(|l| {
            format!(
                "node {} has a non-finite position or velocity at cycle {}, time {:e}",
                cx.g.node_ids[cx.sd.node_global[l] as usize], s.cycle, s.t
            )
        })
}
