//! Every owned pair's force, for any interface type: per secondary node,
//! the candidates its type's search gives (the sorted list, or the segment
//! its walk reaches), the type's pair kernel on each, and each pair's
//! contributions to its nodes, keyed for the fixed summation order
//! (`key::SumKey`). Nodes are computed in parallel and gathered in order.
//! The loops are compiled for each registered type
//! (`interfaces::TypeOptions::visit`), so the type's kernel inlines.

use super::exchange::Contribution;
use super::geometry::{self as geo, V3};
use super::interfaces::{
    CandidateSearch, InterfaceType, NodeState, PairContext, PairForce, PairNodes, PairOutcome,
    PairState, Side, TypeVisitor,
};
use super::key::{SumKey, SECONDARY_CORNER};
use super::setup::{Interface, Pass, NONE};
use super::{seg_values, ContactSystem, InterfaceSums, PassRun, Removal};
use crate::kinematics::rigid_body::{NodeLoad, RigidBodyState};
use crate::parallel::exact_sum::{sum_over_ranks, ExactSum};
use crate::parallel::World;
use rayon::prelude::*;

/// One node's pairs: their contributions, the smallest kinematic step (with
/// the interface id), and their sums.
#[derive(Default)]
struct NodeOut {
    contribs: Vec<Contribution>,
    step: Option<(f64, u64)>,
    sums: InterfaceSums,
    /// The largest penetration of its pairs.
    pen_max: f64,
    /// Reactions on rigid bodies (analytic main surfaces), and the sums of
    /// their pairs' tangent stiffnesses k and of k·r² (r the contact point's
    /// distance to the body's centre).
    body_loads: Vec<(usize, NodeLoad)>,
    body_k: [f64; 2],
}

impl NodeOut {
    /// Nothing to hand on: no contribution, reaction, step or penetration,
    /// and zero sums. The pass drops such nodes (most nodes, most cycles):
    /// adding a zero to a sum that starts at +0 changes no bit of it.
    fn is_nothing(&self) -> bool {
        let su = &self.sums;
        self.contribs.is_empty()
            && self.body_loads.is_empty()
            && self.step.is_none()
            && self.pen_max == 0.0
            && self.pen_max.is_sign_positive()
            && su.pairs == 0
            && su.energy == 0.0
            && su.f_normal.iter().chain(&su.f_tangent).all(|&f| f == 0.0)
    }
}

/// What every node of one pass reads.
struct PassView<'a> {
    it: &'a Interface,
    p: &'a Pass,
    ii: usize,
    pi: usize,
    cx: &'a [V3],
    cv: &'a [V3],
    avail: &'a [bool],
    local: &'a [u32],
    mass: &'a [f64],
    /// Global node index of each cnode.
    nodes_g: &'a [u32],
    /// Initial nodal mass of each cnode.
    cnode_mass: &'a [f64],
    /// IBC bits to release on an impacting secondary node.
    ibc: u8,
    dt: f64,
    bodies: &'a [RigidBodyState],
    /// Total-force types: see `PairContext::scale`.
    scale: Option<f64>,
    /// The interface's memory this cycle (`PairContext::memory`).
    memory: [f64; 2],
    /// The largest motion of a contact node since the last sort, less a
    /// common translation.
    motion: f64,
}

/// One owned secondary node's memory.
struct NodeMemory<'a> {
    ns: &'a mut NodeState,
    /// Sorting types: the pair memory of its candidates.
    pairs: &'a mut [PairState],
    /// Walk types: its current pair.
    walk_pair: &'a mut (u32, PairState),
}

impl ContactSystem {
    /// Every owned pair's force, as contributions, and the smallest kinematic step.
    pub(super) fn pairs(
        &mut self,
        world: &World,
        mass: &[f64],
        t: f64,
        dt: f64,
        bodies: &[RigidBodyState],
    ) -> (Vec<Contribution>, Option<(f64, u64)>) {
        let mut out: Vec<Contribution> = Vec::new();
        self.body_loads.clear();
        let mut best: Option<(f64, u64)> = None;
        for s in self.sums.iter_mut() {
            *s = InterfaceSums {
                energy: s.energy,
                ..Default::default()
            };
        }
        for ii in 0..self.setup.interfaces.len() {
            let it = &self.setup.interfaces[ii];
            if t < it.tstart || t > it.tstop {
                continue;
            }
            let mut scale = None;
            if !it.ty().is_total_force() {
                it.ty().advance_memory(&mut self.total_memory[ii], dt);
            }
            if it.ty().is_total_force() {
                let (fac, step) = self.total_scale(world, ii, mass, dt, bodies);
                scale = Some(fac);
                if step < best.map_or(f64::INFINITY, |b| b.0) {
                    best = Some((step, self.setup.interfaces[ii].id));
                }
            }
            let mut body_k = [ExactSum::default(); 2];
            for pi in 0..self.setup.interfaces[ii].passes.len() {
                let results = self.run_pass(ii, pi, mass, dt, bodies, scale);
                let acc = &mut self.sums[ii];
                for r in results {
                    body_k[0].add(r.body_k[0]);
                    body_k[1].add(r.body_k[1]);
                    out.extend(r.contribs);
                    self.body_loads.extend(r.body_loads);
                    if let Some(st) = r.step {
                        if best.is_none_or(|b| st < b) {
                            best = Some(st);
                        }
                    }
                    for k in 0..3 {
                        acc.f_normal[k] += r.sums.f_normal[k];
                        acc.f_tangent[k] += r.sums.f_tangent[k];
                    }
                    acc.pairs += r.sums.pairs;
                    acc.energy += r.sums.energy * dt;
                }
            }
            let it = &self.setup.interfaces[ii];
            if let (false, Some(b)) = (it.ty().is_total_force(), it.ty().reaction_body()) {
                let step = bodies
                    .get(b)
                    .map_or(f64::INFINITY, |b| body_step(world, body_k, b));
                if step < best.map_or(f64::INFINITY, |b| b.0) {
                    best = Some((step, it.id));
                }
            }
        }
        (out, best)
    }

    /// The pairs of pass `pi` of interface `ii` this rank owns, in node
    /// order (`scale`: see `PairContext::scale`).
    fn run_pass(
        &mut self,
        ii: usize,
        pi: usize,
        mass: &[f64],
        dt: f64,
        bodies: &[RigidBodyState],
        scale: Option<f64>,
    ) -> Vec<NodeOut> {
        let it = &self.setup.interfaces[ii];
        let ibc = (it.ibc[0] as u8) | ((it.ibc[1] as u8) << 1) | ((it.ibc[2] as u8) << 2);
        let view = PassView {
            it,
            p: &it.passes[pi],
            ii,
            pi,
            cx: &self.cx,
            cv: &self.cv,
            avail: &self.avail,
            local: &self.local,
            mass,
            nodes_g: &self.setup.nodes,
            cnode_mass: &self.setup.mass,
            ibc,
            dt,
            bodies,
            scale,
            memory: self.total_memory[ii],
            motion: self.motion,
        };
        it.options.visit(PassPairs {
            v: &view,
            run: &mut self.runs[ii][pi],
        })
    }

    /// A total-force interface (`InterfaceType::is_total_force`): measures
    /// its pairs, reduces the largest penetration and the resultant
    /// penetration vector over all ranks (exact sums: the same bits on any
    /// number of ranks), and returns its normal force per unit penetration
    /// F(p_max)/|R| and its time step. Collective.
    fn total_scale(
        &mut self,
        world: &World,
        ii: usize,
        mass: &[f64],
        dt: f64,
        bodies: &[RigidBodyState],
    ) -> (f64, f64) {
        let mut p_max = [0.0f64];
        let mut r = [ExactSum::default(); 3];
        for pi in 0..self.setup.interfaces[ii].passes.len() {
            let sign = self.setup.interfaces[ii].ty().resultant_sign(pi);
            for n in self.run_pass(ii, pi, mass, dt, bodies, None) {
                p_max[0] = p_max[0].max(n.pen_max);
                for k in 0..3 {
                    r[k].add(sign * n.sums.f_normal[k]);
                }
            }
        }
        world.max_f64(&mut p_max);
        sum_over_ranks(world, &mut r);
        let resultant = geo::norm([r[0].value(), r[1].value(), r[2].value()]);
        let memory = &mut self.total_memory[ii];
        let (f, step) = self.setup.interfaces[ii].ty().total_force(p_max[0], memory);
        let fac = if resultant > 0.0 { f / resultant } else { 0.0 };
        (fac, step)
    }
}

/// The stable step of a rigid body carrying an analytic surface: the
/// smaller of √(2M/K) and √(2J/K_r), K the sum over every rank of its
/// pairs' tangent stiffnesses, K_r = Σ k·r² their rotational stiffness
/// about its centre, J its smallest principal inertia (the reference adds
/// them to the body's main node, STIFN and STIFR: its nodal step, EQ.
/// 8.8.5.2); ∞ without contact. Collective.
fn body_step(world: &World, mut k: [ExactSum; 2], body: &RigidBodyState) -> f64 {
    sum_over_ranks(world, &mut k);
    let step = |m: f64, k: f64| {
        if k > 0.0 && m > 0.0 {
            (2.0 * m / k).sqrt()
        } else {
            f64::INFINITY
        }
    };
    step(body.mass, k[0].value()).min(step(body.smallest_inertia(), k[1].value()))
}

/// One pass's pairs, for the pass's interface type.
struct PassPairs<'a, 'b> {
    v: &'b PassView<'a>,
    run: &'b mut PassRun,
}

impl TypeVisitor for PassPairs<'_, '_> {
    type Out = Vec<NodeOut>;
    fn visit<T: InterfaceType>(self, ty: &T) -> Vec<NodeOut> {
        pass_pairs(ty, self.v, self.run)
    }
}

/// The pairs of every node this rank owns in one pass, in node order (nodes
/// with nothing to hand on left out).
fn pass_pairs<T: InterfaceType>(ty: &T, v: &PassView, run: &mut PassRun) -> Vec<NodeOut> {
    let PassRun {
        mine,
        nodes,
        cand,
        state,
        dist_sort,
        walk_pair,
        removal,
    } = run;
    // Split the pair memory by node so each node owns its slice.
    let mut slices: Vec<&mut [PairState]> = Vec::with_capacity(mine.len());
    let mut rest: &mut [PairState] = state;
    for j in 0..mine.len() {
        let (a, b) = rest.split_at_mut(cand.ptr[j + 1] - cand.ptr[j]);
        slices.push(a);
        rest = b;
    }
    let cand = &*cand;
    let removal = &*removal;
    let dist_sort = &dist_sort[..];
    mine.par_iter()
        .zip(nodes.par_iter_mut())
        .zip(slices.into_par_iter())
        .zip(walk_pair.par_iter_mut())
        .enumerate()
        .map(|(j, (((&k, ns), pairs), walk_pair))| {
            let mem = NodeMemory {
                ns,
                pairs,
                walk_pair,
            };
            let r = cand.ptr[j]..cand.ptr[j + 1];
            let dist = dist_sort.get(r.clone()).unwrap_or(&[]);
            node_pairs(ty, v, removal, k as usize, &cand.segs[r], dist, mem)
        })
        .filter(|o| !o.is_nothing())
        .collect()
}

/// The pairs of secondary node k (index into the pass's `sec`): its sorted
/// candidates `segs` (with their distances at the sort, `dist`, or none),
/// or the segment its walk reaches.
fn node_pairs<T: InterfaceType>(
    ty: &T,
    v: &PassView,
    removal: &Removal,
    k: usize,
    segs: &[u32],
    dist: &[f64],
    mem: NodeMemory,
) -> NodeOut {
    let mut out = NodeOut::default();
    let ns = mem.ns;
    if ns.off {
        return out;
    }
    match ty.search() {
        CandidateSearch::Sort if ty.one_segment_per_node() => {
            // One pair per node, its memory the node's (kept when the node
            // slides onto another segment, dropped when it leaves contact).
            let wp = mem.walk_pair;
            let Some((m, side)) = nearest(ty, v, k, segs, &ns.off_segs, (wp.0, wp.1.side)) else {
                *wp = (NONE, PairState::default());
                return out;
            };
            if wp.0 != m && wp.1.side != 0 {
                wp.1.side = side;
            }
            wp.0 = m;
            if !one_pair(ty, v, k, m, f64::NEG_INFINITY, ns, &mut wp.1, &mut out) {
                return NodeOut::default();
            }
        }
        CandidateSearch::Sort => {
            for (q, &m) in segs.iter().enumerate() {
                let d = dist.get(q).copied().unwrap_or(f64::NEG_INFINITY);
                if !one_pair(ty, v, k, m, d, ns, &mut mem.pairs[q], &mut out) {
                    return NodeOut::default();
                }
            }
        }
        CandidateSearch::Analytic => {
            // One pair per node, against main entity 0 (the analytic surface).
            if !one_pair(
                ty,
                v,
                k,
                0,
                f64::NEG_INFINITY,
                ns,
                &mut mem.walk_pair.1,
                &mut out,
            ) {
                return NodeOut::default();
            }
        }
        CandidateSearch::Walk => {
            let node_off = removal.sec_off.get(k).copied().unwrap_or(false);
            if node_off || ns.last_seg == NONE {
                return out;
            }
            let xs = v.cx[v.p.sec[k] as usize];
            let x_of = |c: u32| {
                if v.avail[c as usize] {
                    Some(v.cx[c as usize])
                } else {
                    None
                }
            };
            let seg_on = |m: u32| !removal.seg_off.get(m as usize).copied().unwrap_or(false);
            let Some(m) = ty.walk(v.it, v.p, ns.last_seg, xs, &x_of, &seg_on) else {
                return out;
            };
            ns.last_seg = m;
            let wp = mem.walk_pair;
            if wp.0 != m {
                *wp = (m, PairState::default());
            }
            if !one_pair(ty, v, k, m, f64::NEG_INFINITY, ns, &mut wp.1, &mut out) {
                return NodeOut::default();
            }
        }
    }
    out
}

/// The positions and velocities one pair reads: its main segment's and its
/// secondary side's nodes (a node repeats itself, an edge its second node).
struct PairValues {
    xm: [V3; 4],
    vm: [V3; 4],
    xs: [V3; 4],
    vs: [V3; 4],
}

/// An analytic main surface has no segment: no main nodes.
const NO_SEGMENT: [u32; 4] = [NONE; 4];

/// Pair (k, m)'s values; None when one of its nodes is not on this rank.
fn pair_values(v: &PassView, k: usize, m: u32) -> Option<PairValues> {
    let (xm, vm) = if v.p.segs.is_empty() {
        ([[0.0; 3]; 4], [[0.0; 3]; 4])
    } else {
        let seg = &v.p.segs[m as usize];
        (
            seg_values(seg, v.avail, v.cx)?,
            seg_values(seg, v.avail, v.cv)?,
        )
    };
    let sec = v.p.sec_side(k);
    let s = sec.nodes[0] as usize;
    let (xs, vs) = if sec.count == 1 {
        ([v.cx[s]; 4], [v.cv[s]; 4])
    } else {
        // An edge's owner holds both its nodes.
        (
            seg_values(&sec.nodes, v.avail, v.cx)?,
            seg_values(&sec.nodes, v.avail, v.cv)?,
        )
    };
    Some(PairValues { xm, vm, xs, vs })
}

/// The kernel's view of pair (k, m).
fn context<'a>(v: &'a PassView, k: usize, m: u32, pv: &'a PairValues) -> PairContext<'a> {
    let sec = v.p.sec_side(k);
    let main = if v.p.segs.is_empty() {
        Side {
            nodes: NO_SEGMENT,
            count: 0,
        }
    } else {
        Side::segment(&v.p.segs[m as usize])
    };
    PairContext {
        it: v.it,
        p: v.p,
        k,
        m,
        xs: pv.xs[0],
        vs: pv.vs[0],
        ms: v.mass[v.local[sec.nodes[0] as usize] as usize],
        xs_side: &pv.xs,
        vs_side: &pv.vs,
        sec,
        main,
        cnode_mass: v.cnode_mass,
        xm: &pv.xm,
        vm: &pv.vm,
        dt: v.dt,
        bodies: v.bodies,
        scale: v.scale,
        memory: v.memory,
    }
}

/// Types with one segment per node: the nearest candidate in contact (the
/// first of equals, in candidate order; `off`, sorted, left out) and the
/// side the node is on.
/// The node's current segment keeps its side; another takes the side whose
/// normal points as the current one's pushes (`None` side 0: a new impact).
fn nearest<T: InterfaceType>(
    ty: &T,
    v: &PassView,
    k: usize,
    segs: &[u32],
    off: &[u32],
    current: (u32, i8),
) -> Option<(u32, i8)> {
    let normal = |m: u32, pv: &PairValues| geo::segment_normal(&pv.xm, v.p.is_tri(m as usize));
    let push = (current.1 != 0)
        .then(|| pair_values(v, k, current.0))
        .flatten()
        .map(|pv| geo::scale(normal(current.0, &pv), f64::from(current.1)));
    let mut best: Option<(f64, u32, i8)> = None;
    for &m in segs {
        if off.binary_search(&m).is_ok() {
            continue;
        }
        let Some(pv) = pair_values(v, k, m) else {
            continue;
        };
        let side = match push {
            _ if m == current.0 => current.1,
            Some(d) if geo::dot(normal(m, &pv), d) < 0.0 => -1,
            Some(_) => 1,
            None => 0,
        };
        if let Some((d, side)) = ty.nearness(&context(v, k, m, &pv), side) {
            if best.is_none_or(|b| d > b.0) {
                best = Some((d, m, side));
            }
        }
    }
    best.map(|b| (b.1, b.2))
}

/// Pair (secondary entity k, main entity m) through the type's kernel, its
/// contributions added to `out`; false when the entity leaves the interface.
/// `d_sort`: the pair's distance at the last sort (`sort_distance`), −∞
/// when not measured.
#[allow(clippy::too_many_arguments)]
fn one_pair<T: InterfaceType>(
    ty: &T,
    v: &PassView,
    k: usize,
    m: u32,
    d_sort: f64,
    ns: &mut NodeState,
    st: &mut PairState,
    out: &mut NodeOut,
) -> bool {
    if ns.off_segs.binary_search(&m).is_ok() {
        return true;
    }
    if surely_free(ty, v, k, m, d_sort, ns, st) {
        return true;
    }
    let Some(pv) = pair_values(v, k, m) else {
        return true;
    };
    let c = context(v, k, m, &pv);
    let (sec, s) = (c.sec, c.sec.nodes[0]);
    let f = match ty.pair(&c, ns, st) {
        PairOutcome::Free => return true,
        PairOutcome::NodeOff => return false,
        PairOutcome::Force(f) => f,
    };
    let nodes = PairNodes { sec, main: c.main };
    let key = SumKey::pair(v.ii, v.pi, v.p.sec_key(k, v.nodes_g), m);
    let vs = if sec.count == 1 {
        c.vs
    } else {
        geo::interpolate(&f.sec_shape, &pv.vs)
    };
    let vrel = geo::sub(vs, geo::interpolate(&f.shape, &pv.vm));
    emit(out, key, &nodes, &f, v.ibc, vrel);
    if let Some(b) = ty.reaction_body() {
        let r = v
            .bodies
            .get(b)
            .map_or([0.0; 3], |b| geo::sub(f.point, b.center));
        out.body_k[0] += f.kt;
        out.body_k[1] += f.kt * geo::dot(r, r);
        out.body_loads.push((
            b,
            NodeLoad {
                node: v.nodes_g[s as usize],
                f: geo::scale(f.fs, -1.0),
                m: [0.0; 3],
                x: f.point,
            },
        ));
    }
    if let Some(d) = ty.kinematic_step(&f) {
        if d < out.step.map_or(f64::INFINITY, |b| b.0) {
            out.step = Some((d, v.it.id));
        }
    }
    true
}

/// Whether pair (k, m) of a secondary node is beyond its type's reach
/// ([`InterfaceType::free_beyond`]): its memory then takes
/// [`InterfaceType::when_free`], as the kernel would do. First by its
/// distance at the sort alone, `d_sort`, reading nothing: apart from a
/// common translation, which no distance sees, no node has moved more than
/// `v.motion` since, and every point of a segment is a convex combination
/// of its nodes, so the distance now is at least d_sort − 2·motion. Then
/// from the positions (outside the ball of the segment's nodes, else by the
/// distance to its closest point, the kernel's own). A pair whose nodes are
/// not all on this rank is left to `pair_values`, which skips it the same
/// way.
fn surely_free<T: InterfaceType>(
    ty: &T,
    v: &PassView,
    k: usize,
    m: u32,
    d_sort: f64,
    ns: &NodeState,
    st: &mut PairState,
) -> bool {
    let sec = v.p.sec_side(k);
    if sec.count != 1 || v.p.segs.is_empty() {
        return false;
    }
    let Some(reach) = ty.free_beyond(v.it, v.p, k, m as usize, ns, st) else {
        return false;
    };
    if d_sort - 2.0 * v.motion < reach {
        let s = sec.nodes[0] as usize;
        let Some(xm) = seg_values(&v.p.segs[m as usize], v.avail, v.cx) else {
            return false;
        };
        let tri = v.p.is_tri(m as usize);
        if !geo::beyond_reach(v.cx[s], &xm, tri, reach)
            && geo::project(v.cx[s], &xm, tri).dist < reach
        {
            return false;
        }
    }
    ty.when_free(st);
    true
}

/// A node's distance to a segment as the sort measures it for the motion
/// bound of [`surely_free`]: the distance to the segment's closest point
/// (`segment_geometry::project`), less an allowance for the round-off of
/// this and of the kernel's own distance (10⁻⁹ of the largest coordinate,
/// far above it, far below any gap).
pub(super) fn sort_distance(xs: V3, xm: &[V3; 4], tri: bool) -> f64 {
    let n = if tri { 3 } else { 4 };
    let scale = xm[..n]
        .iter()
        .chain(std::iter::once(&xs))
        .flat_map(|x| x.iter())
        .fold(0.0f64, |a, &c| a.max(c.abs()));
    geo::project(xs, xm, tri).dist - 1e-9 * scale
}

/// Contributions of one pair: +w_j·F on the secondary side's nodes, −N_i·F
/// on the main side's (EQ. 8.6.6.4–6), and its tangent stiffness on each
/// in the same proportions; nodes of zero weight take nothing.
fn emit(out: &mut NodeOut, key: SumKey, nodes: &PairNodes, f: &PairForce, ibc: u8, vrel: V3) {
    for (j, &c) in nodes.sec.nodes().iter().enumerate() {
        let w = f.sec_shape[j];
        if w == 0.0 {
            continue;
        }
        out.contribs.push(Contribution {
            c,
            key: key.at(SECONDARY_CORNER + j as u8),
            f: geo::scale(f.fs, w),
            k: f.kt * w,
            ibc: if f.f_n > 0.0 { ibc } else { 0 },
        });
    }
    for (i, &c) in nodes.main.nodes().iter().enumerate() {
        if f.shape[i] == 0.0 {
            continue;
        }
        out.contribs.push(Contribution {
            c,
            key: key.at(i as u8),
            f: geo::scale(f.fs, -f.shape[i]),
            k: f.kt * f.shape[i],
            ibc: 0,
        });
    }
    let sums = &mut out.sums;
    for k in 0..3 {
        sums.f_normal[k] += f.dir[k] * f.f_n;
        sums.f_tangent[k] += f.f_t[k];
    }
    sums.pairs += 1;
    sums.energy -= geo::dot(f.fs, vrel);
    out.pen_max = out.pen_max.max(f.pen);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::interfaces::NODE_SHAPE;

    #[test]
    fn a_node_to_segment_pair_gives_one_plus_four_keyed_contributions() {
        let f = PairForce {
            fs: [0.0, 0.0, 8.0],
            sec_shape: NODE_SHAPE,
            shape: [0.5, 0.25, 0.25, 0.0],
            kt: 100.0,
            f_n: 8.0,
            dir: [0.0, 0.0, 1.0],
            ..Default::default()
        };
        let nodes = PairNodes {
            sec: Side::node(9),
            main: Side::segment(&[1, 2, 3, 4]),
        };
        let key = SumKey::pair(2, 1, 900, 17);
        let mut out = NodeOut::default();
        emit(&mut out, key, &nodes, &f, 5, [0.0, 0.0, -1.0]);
        let got: Vec<(u32, u8, f64, f64, u8)> = out
            .contribs
            .iter()
            .map(|c| (c.c, c.key.corner, c.f[2], c.k, c.ibc))
            .collect();
        // The secondary node at corner 4 (+F), the segment's nodes of
        // non-zero shape at corners 0..2 (−N_i·F); node 4 has N = 0.
        assert_eq!(
            got,
            vec![
                (9, 4, 8.0, 100.0, 5),
                (1, 0, -4.0, 50.0, 0),
                (2, 1, -2.0, 25.0, 0),
                (3, 2, -2.0, 25.0, 0),
            ]
        );
        assert!(out.contribs.iter().all(|c| c.key == key.at(c.key.corner)));
        assert_eq!(out.sums.pairs, 1);
        assert_eq!(out.sums.f_normal, [0.0, 0.0, 8.0]);
        assert_eq!(out.sums.energy, 8.0);
    }

    /// xorshift numbers in [−1, 1).
    struct Rng(u64);
    impl Rng {
        fn next(&mut self) -> f64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            (self.0 >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        }
        fn v3(&mut self, s: f64) -> V3 {
            [s * self.next(), s * self.next(), s * self.next()]
        }
    }

    /// The motion bound of `surely_free`: after any motion of the node and
    /// the segment's nodes that differs from a common translation by at
    /// most `motion` (`relative_motion` of their displacements), the
    /// kernel's distance is at least the sort's distance less 2·motion, for
    /// quads and triangles, near and far, large coordinates included.
    #[test]
    fn the_distance_at_the_sort_less_twice_the_motion_bounds_the_distance_now() {
        let mut r = Rng(0x2545_f491_4f6c_dd1d);
        for case in 0..20000 {
            let base = r.v3(if case % 2 == 0 { 1.0 } else { 1e4 });
            let tri = case % 3 == 0;
            let mut xm = [[0.0; 3]; 4];
            for x in xm.iter_mut() {
                *x = geo::add(base, r.v3(1.0));
            }
            let xs = geo::add(base, r.v3(1.5));
            let d = sort_distance(xs, &xm, tri);
            // Displacements: a translation t plus at most m each.
            let t = r.v3(3.0);
            let m = 0.2 * r.next().abs();
            let mut ext = [f64::NEG_INFINITY; 8];
            ext[0] = 0.0;
            let mut moved = |x: V3, r: &mut Rng| {
                let u = r.v3(1.0);
                let u = geo::scale(u, m * r.next().abs() / geo::norm(u).max(1e-300));
                let dx = geo::add(t, u);
                ext[0] = ext[0].max(geo::norm(dx));
                for k in 0..3 {
                    ext[2 + k] = ext[2 + k].max(dx[k]);
                    ext[5 + k] = ext[5 + k].max(-dx[k]);
                }
                geo::add(x, dx)
            };
            let xs2 = moved(xs, &mut r);
            let mut xm2 = xm;
            for x in xm2.iter_mut() {
                *x = moved(*x, &mut r);
            }
            let motion = super::super::relative_motion(&ext);
            assert!(motion <= 0.2 * 3f64.sqrt() + 1e-12, "case {case}: {motion}");
            let now = geo::project(xs2, &xm2, tri).dist;
            assert!(
                now >= d - 2.0 * motion,
                "case {case}: {now} < {d} - 2·{motion}"
            );
        }
    }
}
