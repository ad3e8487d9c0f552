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

use super::setup::{Ctx, State};
use crate::error::RunError;
use crate::parallel::exact_sum::{sum_over_ranks, ExactSum};

/// The reference's margin on the added mass.
const MARGIN: f64 = 1.00001;

/// This rank's smallest nodal step (after the added mass) and its node id,
/// or `None` without /DT/NODA/CST; the added mass is updated (collective:
/// every rank calls it at the same cycle).
pub(super) fn nodal_steps(cx: &Ctx, s: &mut State) -> Result<Option<(f64, u64)>, RunError> {
    let Some((scale, min)) = cx.g.engine.nodal_cst else {
        return Ok(None);
    };
    if s.kcontrib.len() != s.contrib.len() {
        s.kcontrib = vec![[0.0; crate::element::SLOT]; s.contrib.len()];
        s.knode = vec![[0.0; crate::element::SLOT]; cx.n];
        s.added = vec![0.0; cx.n];
    }
    for (i, b) in s.blocks.iter().enumerate() {
        let slots = &mut s.kcontrib[cx.offsets[i]..cx.offsets[i + 1]];
        if !b.nodal_stiffness(&s.x, slots) {
            return Err(RunError::Input(format!(
                "/DT/NODA/CST: the nodal stiffness of {} elements is not computed yet (4-node shells only); the deck cannot run with the nodal time step",
                b.kind().listing_name()
            )));
        }
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
    let mut sums = [added];
    sum_over_ranks(cx.world, &mut sums);
    s.mass_added = sums[0].value();
    Ok(Some(best))
}
