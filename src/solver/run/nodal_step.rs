//! /DT/NODA/CST: the time step from the nodes, with added mass (reference
//! guide /DT/NODA/Keyword3/Iflag, Engine, and "Nodal Time Step"; research
//! note `docs/notes/impdisp_fgeo_research.md` §4).
//!
//! After each cycle's forces, every node's stiffness K (and K_rot) is
//! summed from its elements (`Block::nodal_stiffness`, assembled over the
//! ranks as the forces are); its step is Δt_n = ΔTsca·√(2m/K). A node under
//! ΔTmin gets the mass m = ½K(ΔTmin/ΔTsca)²·1.00001 (the reference's CST2),
//! and its inertia likewise from K_rot: masses only grow, the velocities
//! are kept (the kinetic energy grows with the mass, and MASS ADDED and
//! MAS.ERR say by how much). The element steps are not used: the cycle's
//! step is the smallest nodal step, named after its node.
//!
//! A rigid body steps at its main node (the reference engine's rgbodfp
//! and dtnoda): K = Σ K_s over its secondary nodes, K_rot = Σ (K_rot,s +
//! d²·K_s) with d the arm from the body's centre, and the step
//! ΔTsca·min(√(2M/K), √(2·I_min/K_rot)), I_min its smallest principal
//! inertia (Ispher 1: their mean; values under 10⁻³·I_max raised by
//! 0.1·I_max, as the reference does). Elements whose nodes all belong to one
//! body are inactive in the reference (its starter's "deactivated
//! elements") and give no stiffness. Under ΔTmin the body takes mass, and
//! its principal inertias are raised to the inertia its step needs.

use super::setup::{Ctx, State};
use crate::error::RunError;
use crate::parallel::exact_sum::{sum_over_ranks, ExactSum};

/// The reference's margin on the added mass.
const MARGIN: f64 = 1.00001;

/// This rank's smallest nodal step (after the added mass) and its node id,
/// or `None` without /DT/NODA (/CST); the added mass is updated (collective:
/// every rank calls it at the same cycle).
pub(super) fn nodal_steps(cx: &Ctx, s: &mut State) -> Result<Option<(f64, u64)>, RunError> {
    // /DT/NODA/CST adds mass under ΔTmin; plain /DT/NODA adds none (its
    // ΔTmin taken as 0: no node needs mass).
    let (scale, min) = match (cx.g.engine.nodal_cst, cx.g.engine.nodal) {
        (Some(cst), _) => cst,
        (None, Some(scale)) => (scale, 0.0),
        (None, None) => return Ok(None),
    };
    if s.kcontrib.len() != s.contrib.len() {
        s.kcontrib = vec![[0.0; crate::element::SLOT]; s.contrib.len()];
        s.knode = vec![[0.0; crate::element::SLOT]; cx.n];
        s.added = vec![0.0; cx.n];
        s.kinactive = inside_bodies(cx, s);
    }
    for (i, b) in s.blocks.iter().enumerate() {
        let slots = &mut s.kcontrib[cx.offsets[i]..cx.offsets[i + 1]];
        if !b.nodal_stiffness(&s.x, slots) {
            return Err(RunError::Input(format!(
                "/DT/NODA/CST: the nodal stiffness of {} elements is not computed yet (4-node shells, trusses and beams have it); the deck cannot run with the nodal time step",
                b.kind().listing_name()
            )));
        }
    }
    for &slot in &s.kinactive {
        s.kcontrib[slot as usize] = [0.0; crate::element::SLOT];
    }
    s.plan.assemble(cx.world, &s.kcontrib, &mut s.knode);
    let f = 0.5 * (min / scale) * (min / scale) * MARGIN;
    let mut mass = cx.mass.write().unwrap();
    let mut inertia = cx.inertia.write().unwrap();
    let mut inertia_ke = cx.inertia_ke.write().unwrap();
    let mut best = (f64::INFINITY, u64::MAX);
    let mut added = ExactSum::default();
    for l in 0..cx.n {
        if cx.in_body[l] || cx.tied_tr[l] || mass[l] <= 0.0 {
            continue;
        }
        let (k, kr) = (s.knode[l][0], s.knode[l][3]);
        let mut dt_l = f64::INFINITY;
        if k > 0.0 {
            let need = f * k;
            if mass[l] < need {
                s.added[l] += need - mass[l];
                mass[l] = need;
            }
            dt_l = scale * (2.0 * mass[l] / k).sqrt();
        }
        if kr > 0.0 && inertia[l] > 0.0 && !cx.tied_rot[l] {
            let need = f * kr;
            if inertia[l] < need {
                if inertia_ke[l] > 0.0 {
                    inertia_ke[l] += need - inertia[l];
                }
                inertia[l] = need;
            }
            dt_l = dt_l.min(scale * (2.0 * inertia[l] / kr).sqrt());
        }
        if cx.owned[l] {
            added.add(s.added[l]);
            let id = cx.g.node_ids[cx.sd.node_global[l] as usize];
            if dt_l < best.0 || (dt_l == best.0 && id < best.1) {
                best = (dt_l, id);
            }
        }
    }
    drop((mass, inertia, inertia_ke));
    let (body_best, body_added) = body_steps(cx, s, scale, f);
    if body_best.0 < best.0 || (body_best.0 == best.0 && body_best.1 < best.1) {
        best = body_best;
    }
    added.add(body_added);
    let mut sums = [added];
    sum_over_ranks(cx.world, &mut sums);
    s.mass_added = sums[0].value();
    Ok(Some(best))
}

/// The stiffness slots of elements whose nodes all belong to one rigid body.
fn inside_bodies(cx: &Ctx, s: &State) -> Vec<u32> {
    let mut out = Vec::new();
    for (i, blk) in s.blocks.iter().enumerate() {
        let nc = blk.corners();
        for (e, _) in s.in_body[i]
            .iter()
            .enumerate()
            .filter(|(_, &inside)| inside)
        {
            let first = cx.offsets[i] + e * nc;
            out.extend((first..first + nc).map(|k| k as u32));
        }
    }
    out
}

/// Each rigid body's step at its main node (summed exactly over the ranks,
/// so every rank finds the same), the mass and inertia ΔTmin asks of it;
/// returns the smallest step with its main node's id, and the mass added
/// this cycle on this rank's share (the rank owning the main node).
fn body_steps(cx: &Ctx, s: &mut State, scale: f64, f: f64) -> ((f64, u64), f64) {
    let nb = cx.local_bodies.len();
    if nb == 0 {
        return ((f64::INFINITY, u64::MAX), 0.0);
    }
    let mut sums = vec![ExactSum::default(); 2 * nb];
    for (b, lb) in cx.local_bodies.iter().enumerate() {
        let c = s.bodies[b].center;
        let main = lb.main_local.map(|l| (l, 0));
        for &(l, _) in lb.members.iter().chain(main.iter()) {
            let l = l as usize;
            if !cx.owned[l] {
                continue;
            }
            let (k, kr) = (s.knode[l][0], s.knode[l][3]);
            let d2: f64 = (0..3).map(|i| (s.x[l][i] - c[i]).powi(2)).sum();
            sums[2 * b].add(k);
            sums[2 * b + 1].add(kr + d2 * k);
        }
    }
    sum_over_ranks(cx.world, &mut sums);
    let mut best = (f64::INFINITY, u64::MAX);
    let mut added = 0.0;
    for (b, rb) in cx.g.rigid_bodies.iter().enumerate() {
        let (k, kr) = (sums[2 * b].value(), sums[2 * b + 1].value());
        let body = &mut s.bodies[b];
        let mut dt = f64::INFINITY;
        if k > 0.0 {
            let need = f * k;
            if body.mass < need {
                if cx.local_bodies[b]
                    .main_local
                    .is_some_and(|l| cx.owned[l as usize])
                {
                    added += need - body.mass;
                }
                body.mass = need;
            }
            dt = scale * (2.0 * body.mass / k).sqrt();
        }
        if kr > 0.0 {
            let need = f * kr;
            let mut i_min = smallest_inertia(&body.j0, rb.card.ispher);
            if i_min < need {
                raise_inertia(&mut body.j0, need);
                i_min = smallest_inertia(&body.j0, rb.card.ispher);
            }
            dt = dt.min(scale * (2.0 * i_min / kr).sqrt());
        }
        let id = cx.g.node_ids[rb.main_node as usize];
        if dt < best.0 || (dt == best.0 && id < best.1) {
            best = (dt, id);
        }
    }
    (best, added)
}

fn principal(j: &[f64; 6]) -> nalgebra::SymmetricEigen<f64, nalgebra::U3> {
    nalgebra::Matrix3::new(j[0], j[3], j[5], j[3], j[1], j[4], j[5], j[4], j[2]).symmetric_eigen()
}

/// The inertia the step sees: the smallest principal value, as the
/// reference's main node carries it (Ispher 1: the mean of the three).
fn smallest_inertia(j: &[f64; 6], ispher: i64) -> f64 {
    let ev = principal(j).eigenvalues;
    if ispher == 1 {
        return (ev[0] + ev[1] + ev[2]) / 3.0;
    }
    let max = ev.max();
    ev.iter()
        .map(|&e| if e < 1e-3 * max { e + 0.1 * max } else { e })
        .fold(f64::INFINITY, f64::min)
}

/// Raises every principal inertia below `need` to it (axes kept).
fn raise_inertia(j: &mut [f64; 6], need: f64) {
    let e = principal(j);
    let d = nalgebra::Matrix3::from_diagonal(&e.eigenvalues.map(|v| v.max(need)));
    let m = e.eigenvectors * d * e.eigenvectors.transpose();
    *j = [
        m[(0, 0)],
        m[(1, 1)],
        m[(2, 2)],
        m[(0, 1)],
        m[(1, 2)],
        m[(0, 2)],
    ];
}
