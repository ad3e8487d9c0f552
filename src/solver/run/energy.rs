//! Global energies as the listing counts them (collective sums, exact:
//! the same bits for any number of ranks and threads, `parallel::exact_sum`).

use super::setup::{Ctx, State};
use crate::kinematics::rigid_body::RigidBodyState;
use crate::parallel::exact_sum::{sum_over_ranks, ExactSum};

/// Translational and rotational kinetic energy (owned nodes; tied secondary
/// nodes skip the translational energy), with the moving rigid walls' own
/// kinetic energy (free or driven) in the translational one, as the Radioss
/// listing counts it. A rigid body counts as its main node does in the
/// reference: ½Mv² of its centre in K-ENERGY T and ½ωᵀJω of its inertia
/// (the one its motion uses: with the card's J, ICOG 3 or ISPHER 1) in
/// K-ENERGY R, its nodes not again (QA RESSORT_kjoint2: K-ENERGY R
/// ½·670800·0.01² of a spinning body of brick nodes).
pub(super) fn kinetic(
    cx: &Ctx,
    v: &[[f64; 3]],
    vr: &[[f64; 3]],
    bodies: &[RigidBodyState],
    wall_v: &[[f64; 3]],
) -> (f64, f64) {
    let (mass, inertia) = (cx.mass.read().unwrap(), cx.inertia_ke.read().unwrap());
    let (owned, skip) = (&cx.owned, &cx.ke_skip);
    let mut e = [ExactSum::default(); 2];
    for l in 0..v.len() {
        if !owned[l] || cx.in_body[l] {
            continue;
        }
        if !skip[l] {
            e[0].add(0.5 * mass[l] * (v[l][0] * v[l][0] + v[l][1] * v[l][1] + v[l][2] * v[l][2]));
        }
        e[1].add(
            0.5 * inertia[l] * (vr[l][0] * vr[l][0] + vr[l][1] * vr[l][1] + vr[l][2] * vr[l][2]),
        );
    }
    for (b, lb) in cx.local_bodies.iter().enumerate() {
        if lb.main_local.is_some() {
            let (vb, m) = (bodies[b].v, bodies[b].mass);
            e[0].add(0.5 * m * (vb[0] * vb[0] + vb[1] * vb[1] + vb[2] * vb[2]));
            e[1].add(bodies[b].rotational_energy());
        }
    }
    if cx.world.rank() == 0 {
        // The walls' state is replicated: counted once, on rank 0.
        for &(w, m) in &cx.wall_masses {
            let u = wall_v[w];
            e[0].add(0.5 * m * (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]));
        }
    }
    sum_over_ranks(cx.world, &mut e);
    (e[0].value(), e[1].value())
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
    /// EXT-WORK: loads, imposed motions' reactions, rigid walls.
    pub external_work: f64,
    pub contact: f64,
    pub kinetic: f64,
    pub rotational: f64,
}

/// The listing's energy error as a fraction, as Radioss defines its ERROR
/// column (100 times it): (E_int + E_kin + E_rot) / (E_0 + W_ext) − 1, with
/// E_int without the hourglass energy, W_ext the work of the loads, of the
/// imposed motions' reactions and of the rigid walls (EXT-WORK), E_0 the
/// energy at t = 0; 0 where nothing put energy in yet. The contact
/// interfaces' energy (elastic, friction, damping) and the hourglass energy
/// stay outside it, as in Radioss (penalty contact shows as a passing
/// negative error, friction as a lasting one): `closed_fraction` counts them.
pub(super) fn error_fraction(e0: f64, e: &Energies) -> f64 {
    balance(e0, e, e.internal - e.hourglass)
}

/// The balance with every energy crashsim accounts for: the hourglass and
/// contact energies on the internal side (the final block's).
pub(super) fn closed_fraction(e0: f64, e: &Energies) -> f64 {
    balance(e0, e, e.internal + e.contact)
}

fn balance(e0: f64, e: &Energies, internal: f64) -> f64 {
    let w = e.external_work;
    if e0 + w != 0.0 {
        (internal + e.kinetic + e.rotational - e0 - w) / (e0 + w).abs()
    } else {
        0.0
    }
}

/// This rank's exact sums, summed over the ranks: internal energy (with
/// hourglass), hourglass energy, plastic work, external work of the loads
/// and imposed motions, rigid-wall work, contact energy.
/// The external and rigid-wall works at t^n include the share of the
/// coming velocity update's work that `State::at_n` says (see
/// `output::VelocitiesAtN::ahead`).
fn global_sums(cx: &Ctx, s: &State) -> [f64; 6] {
    let mut e = [ExactSum::default(); 8];
    let mut el = [ExactSum::default(); 3];
    for b in &s.blocks {
        b.energy_sums(&mut el);
    }
    e[..3].copy_from_slice(&el);
    (e[3], e[4], e[5]) = (s.w_ext, s.wall_work, s.e_contact);
    let weight = s.at_n.as_ref().map_or(0.0, |a| {
        (e[6], e[7]) = (a.ahead[0], a.ahead[1]);
        a.ahead_weight
    });
    sum_over_ranks(cx.world, &mut e);
    let v = e.map(|x| x.value());
    [
        v[0],
        v[1],
        v[2],
        v[3] + weight * v[6],
        v[4] + weight * v[7],
        v[5],
    ]
}

/// The global energies now (one exchange and the kinetic sums).
pub(super) fn global(cx: &Ctx, s: &State) -> Energies {
    let e = global_sums(cx, s);
    let (kinetic, rotational) = kinetic_at_n(cx, s);
    Energies {
        internal: e[0],
        hourglass: e[1],
        external_work: e[3] + e[4],
        contact: e[5],
        kinetic,
        rotational,
    }
}

/// The end-of-run breakdown: internal (hourglass and plastic work
/// included), kinetic, rotational, external work, rigid-wall work, contact
/// energy (collective: every rank takes part, even after a stop).
pub(super) fn final_breakdown(cx: &Ctx, s: &State) -> [f64; 8] {
    let e = global_sums(cx, s);
    let (ke, ker) = kinetic_at_n(cx, s);
    [e[0], e[1], e[2], ke, ker, e[3], e[4], e[5]]
}
