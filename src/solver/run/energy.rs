//! Global energies as the listing counts them (collective sums).

use super::setup::{Ctx, State};
use crate::kinematics::rigid_body::RigidBodyState;

/// Translational and rotational kinetic energy (owned nodes, rigid-body
/// main masses once; rigid-body main nodes and tied secondary nodes skip
/// the translational energy), with the free moving rigid walls' own kinetic
/// energy in the translational one, as the Radioss listing counts it.
pub(super) fn kinetic(
    cx: &Ctx,
    v: &[[f64; 3]],
    vr: &[[f64; 3]],
    bodies: &[RigidBodyState],
    wall_v: &[[f64; 3]],
) -> (f64, f64) {
    let (mass, inertia, owned, skip) = (&cx.mass, &cx.inertia_ke, &cx.owned, &cx.ke_skip);
    let mut e = [0.0f64; 2];
    for l in 0..v.len() {
        if owned[l] && !skip[l] {
            e[0] += 0.5 * mass[l] * (v[l][0] * v[l][0] + v[l][1] * v[l][1] + v[l][2] * v[l][2]);
        }
        if owned[l] {
            e[1] += 0.5
                * inertia[l]
                * (vr[l][0] * vr[l][0] + vr[l][1] * vr[l][1] + vr[l][2] * vr[l][2]);
        }
    }
    for (b, lb) in cx.local_bodies.iter().enumerate() {
        if lb.main_local.is_some() {
            let vb = bodies[b].v;
            e[0] += 0.5 * lb.main_mass * (vb[0] * vb[0] + vb[1] * vb[1] + vb[2] * vb[2]);
        }
    }
    if cx.world.rank() == 0 {
        // The walls' state is replicated: counted once, on rank 0.
        for &(w, m) in &cx.free_walls {
            let u = wall_v[w];
            e[0] += 0.5 * m * (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
        }
    }
    cx.world.sum_f64(&mut e);
    (e[0], e[1])
}

/// The kinetic energies at t^n: from `State::at_n` when the cycle has
/// them, else (t = 0) from the velocities as they are.
fn kinetic_at_n(cx: &Ctx, s: &State) -> (f64, f64) {
    match &s.at_n {
        Some(a) => kinetic(cx, &a.v, &a.vr, &a.bodies, &a.wall_v),
        None => kinetic(cx, &s.v, &s.vr, &s.bodies, &s.walls.v),
    }
}

/// The energies of one listing row or `--energies` CSV row.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Energies {
    /// Internal energy with the hourglass energy.
    pub internal: f64,
    pub hourglass: f64,
    pub external_work: f64,
    pub contact: f64,
    pub kinetic: f64,
    pub rotational: f64,
}

/// The global energies now (one all-reduce and the kinetic sums).
pub(super) fn global(cx: &Ctx, s: &State) -> Energies {
    let mut e = [
        s.blocks.iter().map(|b| b.energy()).sum::<f64>(),
        s.blocks.iter().map(|b| b.energy_parts().0).sum::<f64>(),
        s.w_ext,
        s.e_contact,
    ];
    cx.world.sum_f64(&mut e);
    let (kinetic, rotational) = kinetic_at_n(cx, s);
    Energies {
        internal: e[0],
        hourglass: e[1],
        external_work: e[2],
        contact: e[3],
        kinetic,
        rotational,
    }
}

/// The end-of-run breakdown: internal (hourglass and plastic work
/// included), kinetic, rotational, external work, rigid-wall work, contact
/// energy (collective: every rank takes part, even after a stop).
pub(super) fn final_breakdown(cx: &Ctx, s: &State) -> [f64; 8] {
    let mut e = [0.0f64; 6];
    for b in &s.blocks {
        let (hg, pl) = b.energy_parts();
        e[0] += b.energy();
        e[1] += hg;
        e[2] += pl;
    }
    e[3] = s.w_ext;
    e[4] = s.wall_work;
    e[5] = s.e_contact;
    cx.world.sum_f64(&mut e);
    let (ke, ker) = kinetic_at_n(cx, s);
    [e[0], e[1], e[2], ke, ker, e[3], e[4], e[5]]
}
