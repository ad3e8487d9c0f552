//! The velocity phases of a cycle, in their order: tied forces to main
//! nodes, accelerations to v^{n+½}, rigid bodies, imposed velocities and
//! displacements, rigid walls, boundary conditions, then the tied secondary
//! nodes follow their main nodes.

use super::setup::{Ctx, State};
use crate::element::lanes::F4;
use crate::element::SLOT;
use crate::kinematics::rigid_body::NodeLoad;
use crate::kinematics::rigid_wall::{stays_off, wall_velocity};
use crate::output;
use rayon::prelude::*;

/// Every velocity phase of one cycle, with the velocity step `dt_v` =
/// ½(Δt^{n−½}+Δt^{n+½}). Returns, on this rank, the lowest (node id, wall
/// id) of a rigid body's node whose velocity a rigid wall changed (see
/// [`wall_nodes`]).
pub(super) fn velocities(cx: &Ctx, s: &mut State, dt_v: f64) -> Option<(u64, u64)> {
    tied_transfer(cx, s);
    // The rigid walls' nodes at v^{n−½}: the walls' work is taken with them.
    let before: Vec<Vec<[f64; 3]>> = cx
        .walls
        .iter()
        .map(|(nodes, _)| nodes.iter().map(|&l| s.v[l as usize]).collect())
        .collect();
    let prior = imposed_prior(cx, s);
    let prior_fgeo = fgeo_prior(cx, s);
    accelerate(cx, s, dt_v);
    rigid_bodies(cx, s, dt_v);
    imposed_motion(cx, s, &prior);
    final_geometry(cx, s, &prior_fgeo);
    let on_body = rigid_walls(cx, s, &before);
    boundary_conditions(s);
    // Tied secondary nodes follow their main nodes (after every other condition).
    if !s.ties.is_empty() {
        s.ties.recover(cx.world, &s.x, &mut s.v, &mut s.vr, s.dt);
    }
    on_body
}

/// Tied interfaces: the secondary nodes' forces and moments go to their
/// main nodes (contact::interfaces::type2), summed in key order.
fn tied_transfer(cx: &Ctx, s: &mut State) {
    if s.ties.is_empty() {
        return;
    }
    let (fext, fint, fcont) = (&s.fext, &s.fint, &s.fcont);
    let f_of = |l: usize| {
        let mut f = [0.0; 6];
        for k in 0..3 {
            f[k] = fext[l][k] - fint[l][k] + fcont[l][k];
            f[3 + k] = fext[l][3 + k] - fint[l][3 + k];
        }
        f
    };
    s.ties.transfer(cx.world, &s.x, &f_of, &mut s.ftie);
    let n_contact = s.contact.sums.len();
    for (smp, su) in s.interface_samples[n_contact..]
        .iter_mut()
        .zip(&s.ties.sums)
    {
        *smp = output::InterfaceSample {
            tied_force: su.force,
            tied_moment: su.moment,
            ..Default::default()
        };
    }
}

/// Nodes per chunk of the nodal loops a rank's threads share: large enough
/// that a chunk costs far more than handing it to a thread.
pub(super) const NODE_CHUNK: usize = 2048;

/// What moves the nodes: forces of every kind, masses, inertias, fixities.
#[derive(Clone, Copy)]
struct Movers<'a> {
    fext: &'a [[f64; SLOT]],
    fint: &'a [[f64; SLOT]],
    fcont: &'a [[f64; 3]],
    ftie: &'a [[f64; 6]],
    fixed: &'a [[bool; 6]],
    mass: &'a [f64],
    inertia: &'a [f64],
    is_main: &'a [bool],
    tied_tr: &'a [bool],
    tied_rot: &'a [bool],
}

/// The forces' and masses' fields of the state, borrowed one by one (so
/// that the velocities can be borrowed beside them).
macro_rules! movers {
    ($cx:expr, $s:expr, $mass:expr, $inertia:expr) => {
        Movers {
            fext: &$s.fext,
            fint: &$s.fint,
            fcont: &$s.fcont,
            ftie: &$s.ftie,
            fixed: &$s.fixed,
            mass: &$mass,
            inertia: &$inertia,
            is_main: &$cx.is_main,
            tied_tr: &$cx.tied_tr,
            tied_rot: &$cx.tied_rot,
        }
    };
}

/// Accelerations (damped where a /DAMP asks) and velocities at n+½: node
/// by node, in chunks over the rank's threads (each node's update is its
/// own, so the bits do not depend on the chunks); a model with /DAMP keeps
/// one loop (its damping state and work go node by node).
fn accelerate(cx: &Ctx, s: &mut State, dt_v: f64) {
    let (mass, inertia) = (cx.mass.read().unwrap(), cx.inertia.read().unwrap());
    if cx.damp_of.iter().any(Option::is_some) {
        for l in 0..cx.n {
            if cx.is_main[l] {
                continue;
            }
            let (m, mut a) = node_acceleration(&movers!(cx, s, mass, inertia), l);
            if cx.damp_of[l].is_some() && !cx.in_body[l] {
                let (v, w) = (s.v[l], s.vr[l]);
                let v6 = [v[0], v[1], v[2], w[0], w[1], w[2]];
                super::damping::damp(cx, s, l, &mut a, v6, m, dt_v);
            }
            advance_node(&mut s.v[l], &mut s.vr[l], m, a, dt_v);
        }
        return;
    }
    let mv = movers!(cx, s, mass, inertia);
    s.v.par_chunks_mut(NODE_CHUNK)
        .zip(s.vr.par_chunks_mut(NODE_CHUNK))
        .enumerate()
        .for_each(|(c, (v, vr))| {
            for (i, (v, vr)) in v.iter_mut().zip(vr).enumerate() {
                let l = c * NODE_CHUNK + i;
                if !mv.is_main[l] {
                    let (m, a) = node_acceleration(&mv, l);
                    advance_node(v, vr, m, a, dt_v);
                }
            }
        });
}

/// Three quotients n_k / m as one vector division: IEEE division lane by
/// lane, the bits of the three scalar divisions (the nodal loops' time went
/// largely to their divisions).
#[inline(always)]
pub(super) fn divided(n: [f64; 3], m: f64) -> [f64; 3] {
    let q = (F4::new([n[0], n[1], n[2], 0.0]) / F4::new([m; 4])).to_array();
    [q[0], q[1], q[2]]
}

/// Per degree of freedom of local node `l`: the mass that moves it (0: it
/// does not move) and its undamped acceleration.
#[inline(always)]
fn node_acceleration(mv: &Movers, l: usize) -> ([f64; 6], [f64; 6]) {
    let (mass, inertia) = (mv.mass[l], mv.inertia[l]);
    let (fe, fi, fc, ft) = (&mv.fext[l], &mv.fint[l], &mv.fcont[l], &mv.ftie[l]);
    let tr = divided([0, 1, 2].map(|k| fe[k] - fi[k] + fc[k] + ft[k]), mass);
    let rot = divided([3, 4, 5].map(|k| fe[k] - fi[k] + ft[k]), inertia);
    let mut m = [0.0; 6];
    let mut a = [0.0; 6];
    for k in 0..3 {
        if mass > 0.0 && !mv.tied_tr[l] && !mv.fixed[l][k] {
            m[k] = mass;
            a[k] = tr[k];
        }
        if inertia > 0.0 && !mv.tied_rot[l] && !mv.fixed[l][3 + k] {
            m[3 + k] = inertia;
            a[3 + k] = rot[k];
        }
    }
    (m, a)
}

/// v^{n+½} = v^{n−½} + a·Δt for the degrees of freedom that move.
fn advance_node(v: &mut [f64; 3], vr: &mut [f64; 3], m: [f64; 6], a: [f64; 6], dt_v: f64) {
    for k in 0..3 {
        if m[k] > 0.0 {
            v[k] += a[k] * dt_v;
        }
        if m[3 + k] > 0.0 {
            vr[k] += a[3 + k] * dt_v;
        }
    }
}

/// This rank's owned loads of each rigid body: its members', then its main
/// node's (a load on the main node acts on the body, as in Radioss; the main
/// node sits at the centre, so its force adds no moment), then the
/// reactions of the contacts on its analytic surfaces (TYPE14, TYPE15),
/// keyed by their secondary node (a TYPE15 facet's: its first node); the
/// body sorts them by key and value, so the order the ranks gather them
/// in does not matter.
fn rigid_body_loads(cx: &Ctx, s: &State) -> Vec<Vec<NodeLoad>> {
    let mut loads = own_body_loads(cx, s);
    for &(b, l) in &s.contact.body_loads {
        loads[b].push(l);
    }
    loads
}

/// The members' and main node's loads of each rigid body.
fn own_body_loads(cx: &Ctx, s: &State) -> Vec<Vec<NodeLoad>> {
    cx.local_bodies
        .iter()
        .map(|lb| {
            let main = lb.main_local.map(|l| (l, cx.sd.node_global[l as usize]));
            lb.members
                .iter()
                .chain(main.iter())
                .filter(|(l, _)| cx.owned[*l as usize])
                .map(|&(l, gl)| {
                    let l = l as usize;
                    let f = [0, 1, 2].map(|k| s.fext[l][k] - s.fint[l][k] + s.fcont[l][k]);
                    let m = [0, 1, 2].map(|k| s.fext[l][3 + k] - s.fint[l][3 + k]);
                    NodeLoad {
                        node: gl,
                        f,
                        m,
                        x: s.x[l],
                    }
                })
                .collect()
        })
        .collect()
}

/// Rigid bodies: resultant of their nodes, gathered in global node order;
/// the members take the body's velocity field.
fn rigid_bodies(cx: &Ctx, s: &mut State, dt_v: f64) {
    if cx.local_bodies.is_empty() {
        return;
    }
    s.bodies_v_before = s.bodies.iter().map(|b| (b.v, b.omega)).collect();
    let all = cx.world.allgather(&rigid_body_loads(cx, s));
    for (b, lb) in cx.local_bodies.iter().enumerate() {
        let mut loads: Vec<NodeLoad> = all.iter().flat_map(|r| r[b].iter().copied()).collect();
        let c_before = s.bodies[b].center;
        s.bodies[b].accelerate(&mut loads, [0.0; 3], dt_v);
        constrain_body(cx, s, b);
        s.bodies[b].move_by(s.dt);
        for &(l, _) in &lb.members {
            let l = l as usize;
            s.v[l] = s.bodies[b].velocity_at(s.x[l], c_before);
            if cx.inertia.read().unwrap()[l] > 0.0 {
                s.vr[l] = s.bodies[b].omega;
            }
        }
        if let Some(l) = lb.main_local {
            s.v[l as usize] = s.bodies[b].v;
            s.vr[l as usize] = s.bodies[b].omega;
        }
    }
}

/// The /BCS and /IMPVEL of a rigid body's main node act on the body (as in
/// Radioss): its velocity (translations) or spin (rotations, global frame)
/// in those directions is zero or imposed at t + ½Δt. The reaction's work
/// on the translations (`reaction_work`, as for nodes) is external work, counted once, on the rank that owns
/// the main node; an imposed spin does the work of the rotational energy it
/// changes.
fn constrain_body(cx: &Ctx, s: &mut State, b: usize) {
    let lb = &cx.local_bodies[b];
    let mut imposed: [Option<f64>; 6] = lb.main_fixed.map(|f| f.then_some(0.0));
    let th = s.t + 0.5 * s.dt;
    for &i in &lb.main_impvel {
        let c = &cx.g.imposed_velocities[i];
        if let Some(val) = cx.imposed(c, th) {
            imposed[c.card.dir.index()] = Some(val);
        }
    }
    // /IMPDISP on the main node: the velocity that takes the body's centre
    // to u(t + Δt) from where it is.
    for &i in &lb.main_impdisp {
        let c = &cx.g.imposed_displacements[i];
        if let Some(u) = cx.imposed_displacement(c, s.t, s.dt) {
            let d = c.card.dir.index();
            let body = &s.bodies[b];
            imposed[d] = Some((u - (body.center[d] - body.center0[d])) / s.dt);
        }
    }
    let counts = lb.main_local.is_some_and(|l| cx.owned[l as usize]);
    let (v_prior, w_prior) = s.bodies_v_before[b];
    let body = &mut s.bodies[b];
    let w_free = body.omega;
    for (k, val) in imposed.iter().enumerate() {
        let Some(val) = *val else {
            continue;
        };
        if k < 3 {
            if counts {
                s.w_ext
                    .add(reaction_work(body.mass, v_prior[k], body.v[k], val));
            }
            body.v[k] = val;
        } else {
            body.omega[k - 3] = val;
        }
    }
    // An imposed spin: the reaction's angular impulse J(ω − ω_free) times
    // the mean spin ½(ω^{n−½} + ω^{n+½}), as for the translations (a body
    // held still does no work).
    if counts && imposed[3..].iter().any(Option::is_some) {
        let w = body.omega;
        let dl = body.inertia_times(crate::vec3::sub(w, w_free));
        s.w_ext.add(
            (0..3)
                .map(|k| dl[k] * 0.5 * (w_prior[k] + w[k]))
                .sum::<f64>(),
        );
    }
}

/// The velocity of every imposed degree of freedom before this step's
/// acceleration (v^{n−½}), in the order `imposed_motion` visits them.
fn imposed_prior(cx: &Ctx, s: &State) -> Vec<f64> {
    let of = |l: u32, d: usize| {
        let l = l as usize;
        if d < 3 {
            s.v[l][d]
        } else {
            s.vr[l][d - 3]
        }
    };
    cx.impvel
        .iter()
        .chain(&cx.impdisp)
        .flat_map(|(nodes, c)| nodes.iter().map(move |&l| of(l, c.card.dir.index())))
        .collect()
}

/// Imposed velocities at t + ½Δt; imposed displacements: the velocity that
/// reaches u(t + Δt) at the end of the step. The reaction that imposes
/// them does work, counted as external work (EXT-WORK, `reaction_work`):
/// a jump from v₀ to v₁ does ½m(v₁² − v₀²), the kinetic energy it gives,
/// as Radioss counts it (`prior`: the velocities before the step, from
/// `imposed_prior`).
fn imposed_motion(cx: &Ctx, s: &mut State, prior: &[f64]) {
    let (t, dt) = (s.t, s.dt);
    let th = t + 0.5 * dt;
    let mut i = 0;
    for (nodes, c) in &cx.impvel {
        let val = cx.imposed(c, th);
        let d = c.card.dir.index();
        for &l in nodes {
            if let Some(val) = val {
                impose(cx, s, l as usize, d, val, prior[i]);
            }
            i += 1;
        }
    }
    for (nodes, c) in &cx.impdisp {
        let u = cx.imposed_displacement(c, t, dt);
        let d = c.card.dir.index();
        for &l in nodes {
            let l = l as usize;
            // A rigid body's main node moves with its body (`constrain_body`).
            if let Some(u) = u.filter(|_| d >= 3 || !cx.is_main[l]) {
                impose(
                    cx,
                    s,
                    l,
                    d,
                    (u - (s.x[l][d] - cx.sd.x[l][d])) / dt,
                    prior[i],
                );
            }
            i += 1;
        }
    }
}

/// The velocities v^{n−½} of the /IMPDISP/FGEO nodes, in `final_geometry`'s order.
fn fgeo_prior(cx: &Ctx, s: &State) -> Vec<[f64; 3]> {
    cx.fgeo
        .iter()
        .flat_map(|(on, _)| on.iter().map(|&(l, _)| s.v[l as usize]))
        .collect()
}

/// /IMPDISP/FGEO between Tstart and Tstop (research note
/// `docs/notes/impdisp_fgeo_research.md` §2): along e = (X_f − X₀)/|X_f − X₀|
/// the velocity that brings the node to f(Ascale·(t+Δt))·|X_f − X₀| of its
/// path at the end of the step; across e the velocity of n−½ is kept (no
/// acceleration: a node that starts on its line stays on it); a node whose
/// final position is its initial one is held. Rotations stay free. The
/// reaction's work is external work, as for /IMPDISP (`impose`).
fn final_geometry(cx: &Ctx, s: &mut State, prior: &[[f64; 3]]) {
    let (t, dt) = (s.t, s.dt);
    let mut i = 0;
    for (on, c) in &cx.fgeo {
        let active = t >= c.tstart && t <= c.tstop && dt > 0.0;
        let f = &cx.g.functions[cx.fct_index[&c.fct]];
        let frac = crate::kinematics::function::eval(f, c.ascale * (t + dt));
        for &(l, k) in on {
            let l = l as usize;
            let before = prior[i];
            i += 1;
            if !active {
                continue;
            }
            let x0 = cx.sd.x[l];
            let d = crate::vec3::sub(c.target[k], x0);
            let dist = crate::vec3::dot(d, d).sqrt();
            let mut v = [0.0; 3];
            if dist > 0.0 {
                let e = crate::vec3::scale(d, 1.0 / dist);
                let along = crate::vec3::dot(e, crate::vec3::sub(s.x[l], x0));
                let v_axis = (dist * frac - along) / dt;
                let v_across = crate::vec3::dot(e, before);
                for q in 0..3 {
                    v[q] = before[q] - v_across * e[q] + v_axis * e[q];
                }
            }
            for q in 0..3 {
                impose(cx, s, l, q, v[q], before[q]);
            }
        }
    }
}

/// Sets a node's velocity (d < 3) or rotational velocity (d − 3) to
/// `val` (it was `before` at n−½); the reaction's work joins this rank's
/// external work (owned nodes).
fn impose(cx: &Ctx, s: &mut State, l: usize, d: usize, val: f64, before: f64) {
    let (slot, m) = if d < 3 {
        (&mut s.v[l][d], cx.mass.read().unwrap()[l])
    } else {
        (&mut s.vr[l][d - 3], cx.inertia.read().unwrap()[l])
    };
    if cx.owned[l] {
        s.w_ext.add(reaction_work(m, before, *slot, val));
    }
    *slot = val;
    if d < 3 {
        s.imposed_before.push((l as u32, d as u8, before));
    }
}

/// The work of the reaction that sets a velocity to `val` (it was `before`
/// at n−½ and `free` after this step's forces): its impulse m(val − free)
/// times the mean velocity ½(before + val) over the step. It is the kinetic
/// energy a jump gives, ½m(val² − before²), plus the work of the forces the
/// reaction balances, f·½(before + val)·Δt — the velocity at t^n, so that
/// summed over the steps it is the work the elements' trapezoidal internal
/// energy takes, also where the imposed motion reverses (a load peak: QA
/// LOIS_LOI62's simple shear closes to 0.0% as in the reference listing).
fn reaction_work(m: f64, before: f64, free: f64, val: f64) -> f64 {
    m * (val - free) * 0.5 * (val + before)
}

/// Rigid walls: each stops its nodes; a moving wall follows its node's
/// /IMPVEL, or (free, with a mass) takes the momentum its nodes lost.
fn rigid_walls(cx: &Ctx, s: &mut State, before: &[Vec<[f64; 3]>]) -> Option<(u64, u64)> {
    let (dt, th) = (s.dt, s.t + 0.5 * s.dt);
    let mut on_body: Option<(u64, u64)> = None;
    for (w, (nodes, wall)) in cx.walls.iter().enumerate() {
        s.walls.force[w] = Default::default();
        for c in &cx.wall_driver[w] {
            if let Some(val) = cx.imposed(c, th) {
                let d = c.card.dir.index();
                // The driver's work on the wall's own mass, ½M(v² − v_prior²)
                // (an imposed motion's work, `imposed_motion`, with no other
                // force on that mass); the walls are replicated: rank 0 counts it.
                if cx.world.rank() == 0 {
                    let prior = s.walls.v[w][d];
                    s.w_ext
                        .add(0.5 * wall.card.mass * (val * val - prior * prior));
                }
                s.walls.v[w][d] = val;
            }
        }
        let (push, hit) = wall_nodes(cx, s, w, (nodes, &before[w]));
        if let Some(n) = hit {
            let id = (n, wall.card.id);
            on_body = Some(on_body.map_or(id, |b| b.min(id)));
        }
        if wall.node.is_some() && cx.wall_driver[w].is_empty() && wall.card.mass > 0.0 {
            // Free moving wall: its mass takes the momentum the nodes lost.
            let mut all: Vec<(u32, [f64; 3])> =
                cx.world.allgather(&push).into_iter().flatten().collect();
            all.sort_by_key(|p| p.0);
            let mut f = [0.0; 3];
            for (_, fi) in &all {
                for k in 0..3 {
                    f[k] += fi[k];
                }
            }
            for k in 0..3 {
                s.walls.v[w][k] += f[k] / wall.card.mass * dt;
            }
        }
        for k in 0..3 {
            s.walls.p[w][k] += s.walls.v[w][k] * dt;
        }
        if let Some(nd) = wall.node {
            if let Some(&l) = cx.local_of.get(&nd) {
                s.v[l as usize] = s.walls.v[w];
            }
        }
    }
    on_body
}

/// One wall's nodes on this rank (with their velocities at n−½): their
/// velocities after the wall, the wall's work and force; returns the owned
/// nodes' forces (global node, force), and the lowest id of a rigid body's
/// node whose velocity the wall changed: the wall's impulse is not passed
/// to the body (its node would leave the body's motion), so the run stops
/// on it (`cycle`) rather than go on wrong.
fn wall_nodes(
    cx: &Ctx,
    s: &mut State,
    w: usize,
    (nodes, before): (&[u32], &[[f64; 3]]),
) -> (Vec<(u32, [f64; 3])>, Option<u64>) {
    let wall = cx.walls[w].1;
    // A free wall (its own mass) is part of the system, its kinetic energy
    // counted: what its impacts take stays inside (a negative ERROR, as a
    // contact's loss); a fixed or driven wall is outside: the work of its
    // impulses is external work (EXT-WORK), as Radioss counts it.
    let mass = cx.mass.read().unwrap();
    let free = wall.node.is_some() && cx.wall_driver[w].is_empty() && wall.card.mass > 0.0;
    let (x, v, dt, tied) = (&s.x, &s.v, s.dt, &s.walls.tied[w]);
    let (p, vw) = (s.walls.p[w], s.walls.v[w]);
    let mass_of = &mass[..];
    // The nodes the wall acts on (most nodes, most cycles: none), found
    // over the rank's threads, then applied in the list's order.
    let acted: Vec<(usize, [f64; 3], bool, [f64; 3])> = nodes
        .par_iter()
        .with_min_len(NODE_CHUNK)
        .enumerate()
        .filter_map(|(i, &l)| {
            let l = l as usize;
            if !tied[i] && stays_off(x[l], v[l], dt, p, wall.normal, vw) {
                return None;
            }
            let (nv, now_tied, f) = wall_velocity(
                x[l],
                v[l],
                mass_of[l],
                dt,
                p,
                wall.normal,
                vw,
                wall.card.slide,
                wall.card.fric,
                tied[i],
            );
            // The same bits (a zero keeps its sign; NaN != NaN: a
            // non-finite velocity is kept as acted on).
            let same = nv == v[l]
                && nv.map(f64::to_bits) == v[l].map(f64::to_bits)
                && now_tied == tied[i]
                && f == [0.0; 3];
            (!same).then_some((i, nv, now_tied, f))
        })
        .collect();
    let mut push: Vec<(u32, [f64; 3])> = Vec::new();
    let mut hit: Option<u64> = None;
    for (i, nv, now_tied, f) in acted {
        let l = nodes[i] as usize;
        let v = s.v[l];
        if cx.owned[l] && !free {
            s.wall_work.add(impulse_work(mass[l], (before[i], v), nv));
        }
        if nv != v && cx.in_body[l] {
            let id = cx.g.node_ids[cx.sd.node_global[l] as usize];
            hit = Some(hit.map_or(id, |h| h.min(id)));
        }
        s.v[l] = nv;
        s.walls.tied[w][i] = now_tied;
        if cx.owned[l] && f != [0.0; 3] {
            push.push((cx.sd.node_global[l], f));
            for k in 0..3 {
                s.walls.force[w][k].add(f[k]);
            }
        }
    }
    (push, hit)
}

/// The work of a rigid wall's impulse on a node over the step: the impulse
/// m (v_after − v_free) times the node's mean velocity over the step,
/// ½ (v^{n−½} + v_after). A node resting on a fixed wall takes none (its
/// velocity is zero before and after, whatever the forces pressing it); a
/// node landing on it loses its whole approach kinetic energy over the
/// steps it needs to land; friction takes what it slows; a driven wall's
/// push gives F·v_wall Δt. Radioss counts these in EXT-WORK (its normal
/// term −½ DV·I_N, with DV the velocity at n−½, and friction term): INT357's
/// plates pressed onto its wall lose 6.0 there, as in the reference listing.
fn impulse_work(m: f64, (v_half, v_free): ([f64; 3], [f64; 3]), v_after: [f64; 3]) -> f64 {
    0.5 * m
        * (0..3)
            .map(|k| (v_after[k] - v_free[k]) * (v_after[k] + v_half[k]))
            .sum::<f64>()
}

/// Boundary conditions have the last word.
fn boundary_conditions(s: &mut State) {
    for (l, fixed) in s.fixed.iter().enumerate() {
        for k in 0..3 {
            if fixed[k] {
                s.v[l][k] = 0.0;
            }
            if fixed[3 + k] {
                s.vr[l][k] = 0.0;
            }
        }
    }
}

/// The velocities at t^n, the time of this cycle's positions, forces and
/// internal energy: v^n = v^{n−½} + ½Δt^{n−½} a^n, a^n with every condition
/// of the velocity phases (boundary conditions, rigid bodies and walls,
/// imposed motion, ties). The next cycle's velocity phases run and are
/// undone (collective: every rank asks at the same cycles), and v^n is read
/// between v^{n−½} and v^{n+½}. At cycle 0 (and wherever no step was taken
/// yet) the velocities are those of t^n already.
pub(super) fn at_n(cx: &Ctx, s: &mut State) -> output::VelocitiesAtN {
    let now = |s: &State| output::VelocitiesAtN {
        v: s.v.clone(),
        vr: s.vr.clone(),
        bodies: s.bodies.clone(),
        wall_v: s.walls.v.clone(),
        ahead: Default::default(),
        ahead_weight: 0.0,
    };
    if s.cycle == 0 || s.dt_prev <= 0.0 {
        return now(s);
    }
    let before = now(s);
    let kept = (
        s.ftie.clone(),
        s.walls.clone(),
        (s.wall_work, s.w_ext),
        s.interface_samples.clone(),
        s.ties.clone(),
    );
    // The coming update's work, summed apart.
    (s.wall_work, s.w_ext) = Default::default();
    velocities(cx, s, 0.5 * (s.dt_prev + s.dt));
    let ahead = [s.w_ext, s.wall_work];
    let w = s.dt_prev / (s.dt_prev + s.dt);
    let lerp = |a: &[[f64; 3]], b: &[[f64; 3]]| -> Vec<[f64; 3]> {
        a.iter()
            .zip(b)
            .map(|(p, q)| [0, 1, 2].map(|k| p[k] + w * (q[k] - p[k])))
            .collect()
    };
    let mut bodies = before.bodies.clone();
    for (b, after) in bodies.iter_mut().zip(&s.bodies) {
        b.v = lerp(&[b.v], &[after.v])[0];
        b.omega = lerp(&[b.omega], &[after.omega])[0];
    }
    let at = output::VelocitiesAtN {
        v: lerp(&before.v, &s.v),
        vr: lerp(&before.vr, &s.vr),
        bodies,
        wall_v: lerp(&before.wall_v, &s.walls.v),
        ahead,
        ahead_weight: w,
    };
    // Undo: the state is again that of the cycle's end.
    (s.v, s.vr, s.bodies) = (before.v, before.vr, before.bodies);
    (
        s.ftie,
        s.walls,
        (s.wall_work, s.w_ext),
        s.interface_samples,
        s.ties,
    ) = kept;
    at
}
