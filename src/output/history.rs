//! Time histories (`/th` in the run file), sampled every /TFILE period.
//!
//! One row per sample, the same on every rank (partial sums are added with
//! one all-reduce). All of a sample is one record of the extendible table
//! `/th/rows [T]`, whose members h5py and numpy read by name
//! (`f["th/rows"]["parts"]` is a `[T, P, 3]` array), so that appending the
//! rows gathered since the last state is one extension and one write, not
//! one per quantity. The columns of each member are named by the attribute
//! of `/th/rows` with the member's name (comma-separated); the ids of the
//! objects of a per-object member are in `/th/<member>/id`. A member whose
//! table has no objects (no interfaces, say) is left out of the record.
//!
//! - `time`, `cycle`;
//! - `global [10]`: the time step, the listing's columns — internal
//!   energy (without the hourglass energy, as Radioss lists it), translational and rotational kinetic energy,
//!   external work and the energy error in % (as the listing computes
//!   them) — and the hourglass energy, plastic work, rigid-wall work and
//!   contact energy (`GLOBAL_COLUMNS`);
//! - `parts [P, 3]` (ids in `/th/parts/id`): per part, its
//!   elements' internal energy (without hourglass); kinetic energy Σ_e Σ_corners ½·(m_e/n)·|v|²
//!   and mass Σ m_e over its elements not deleted, with the element mass
//!   m_e = ρ·t·A (shells), ρ·V (solids), the property mass (springs) taken
//!   on the initial geometry, as the starter's part masses;
//! - `interfaces [I, 13]`: normal and tangential force
//!   resultants (x, y, z) and contact energy, as the contact code passes
//!   them in (`InterfaceSample`), then for the tied interfaces (/INTER/TYPE2,
//!   after the contact interfaces) the resultants of the forces and of the
//!   moments their secondary nodes passed to the main nodes in the sampled
//!   cycle, Σ F_s and Σ M_s (0 for the other types; the contact columns are 0
//!   for TYPE2, whose energy is 0: the tie does no work);
//! - `rigid_walls [W, 3]`: the force the nodes put on each
//!   wall in the sampled cycle;
//! - `nodes [M, 9]` for the /TH/NODE nodes: displacement
//!   u = x − x0, velocity at the half step, acceleration (f_ext − f_int)/m
//!   at the sample (0 on a fixed degree of freedom).
//!
//! Rows are kept in memory and appended to the file at each state (and at
//! the end), so the file is written a few times per run, not at every sample.

use super::h5::Member;
use super::{Context, LoopState};
use crate::element::blocks::Block;
use crate::global::GlobalData;
use crate::model::geometry::{hexa_volume, quad_area, tetra_volume, triangle_area};
use crate::model::ElementKind;
use crate::parallel::exact_sum::{sum_over_ranks, ExactSum};
use serde::{Deserialize, Serialize};

/// Columns of the `global` member of `/th/rows`.
pub const GLOBAL_COLUMNS: [&str; 10] = [
    "time_step",
    "internal_energy",
    "kinetic_energy",
    "rotational_kinetic_energy",
    "external_work",
    "energy_error_percent",
    "hourglass_energy",
    "plastic_work",
    "rigid_wall_work",
    "contact_energy",
];
/// Columns of the `parts` member.
pub const PART_COLUMNS: [&str; 3] = ["internal_energy", "kinetic_energy", "mass"];
/// Columns of the `interfaces` member.
pub const INTERFACE_COLUMNS: [&str; 13] = [
    "normal_force_x",
    "normal_force_y",
    "normal_force_z",
    "tangential_force_x",
    "tangential_force_y",
    "tangential_force_z",
    "contact_energy",
    "tied_force_x",
    "tied_force_y",
    "tied_force_z",
    "tied_moment_x",
    "tied_moment_y",
    "tied_moment_z",
];
/// Values per interface and sample (`INTERFACE_COLUMNS`).
pub const IW: usize = INTERFACE_COLUMNS.len();
/// Columns of the `rigid_walls` member.
pub const WALL_COLUMNS: [&str; 3] = ["force_x", "force_y", "force_z"];
/// Columns of the `nodes` member.
pub const NODE_COLUMNS: [&str; 9] = [
    "displacement_x",
    "displacement_y",
    "displacement_z",
    "velocity_x",
    "velocity_y",
    "velocity_z",
    "acceleration_x",
    "acceleration_y",
    "acceleration_z",
];

/// Sizes of the per-object histories.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct ThLayout {
    pub parts: usize,
    pub interfaces: usize,
    pub walls: usize,
    pub nodes: usize,
}

impl ThLayout {
    /// Values of one row besides the cycle: time, the globals, then each
    /// per-object table (object-major) in the order of the file.
    pub fn width(&self) -> usize {
        1 + GLOBAL_COLUMNS.len()
            + 3 * self.parts
            + IW * self.interfaces
            + 3 * self.walls
            + 9 * self.nodes
    }

    /// The per-object members of a row: (name, number of objects, their
    /// columns), in the order of the values.
    pub fn tables(&self) -> [(&'static str, usize, &'static [&'static str]); 4] {
        [
            ("parts", self.parts, &PART_COLUMNS),
            ("interfaces", self.interfaces, &INTERFACE_COLUMNS),
            ("rigid_walls", self.walls, &WALL_COLUMNS),
            ("nodes", self.nodes, &NODE_COLUMNS),
        ]
    }

    /// The members of a `/th/rows` record, in the order of the values (the
    /// cycle second): tables without objects are left out.
    pub fn members(&self) -> Vec<(&'static str, Member)> {
        let mut m = vec![
            ("time", Member::F64),
            ("cycle", Member::U64),
            ("global", Member::F64Array(vec![GLOBAL_COLUMNS.len()])),
        ];
        for (name, n, cols) in self.tables() {
            if n > 0 {
                m.push((name, Member::F64Array(vec![n, cols.len()])));
            }
        }
        m
    }
}

/// One sample: the cycle, and the values in the order `ThLayout::width` says.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ThRow {
    pub cycle: u64,
    pub values: Vec<f64>,
}

/// What the contact code reports per interface at a sample, as this rank's
/// partial sums (they are added over ranks): normal and tangential force
/// resultants and the contact energy; for a tied interface the force and
/// moment resultants its secondary nodes passed to their main nodes.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct InterfaceSample {
    pub normal: [f64; 3],
    pub tangential: [f64; 3],
    pub energy: f64,
    pub tied_force: [f64; 3],
    pub tied_moment: [f64; 3],
}

/// The sampler: what it needs precomputed, and its schedule.
pub struct History {
    pub layout: ThLayout,
    /// /TFILE period.
    pub period: f64,
    /// Time of the next sample.
    pub next: f64,
    /// Element masses per block, per local element.
    elem_mass: Vec<Vec<f64>>,
    /// (position among the /TH/NODE nodes, local node) of the ones this rank owns.
    th_local: Vec<(usize, usize)>,
}

/// Mass of each of a block's elements on the initial geometry `x0` (see the module doc).
pub(crate) fn element_masses(g: &GlobalData, x0: &[[f64; 3]], b: &dyn Block) -> Vec<f64> {
    let le = b.local();
    let nn = b.kind().nodes();
    (0..le.global.len())
        .map(|e| {
            let n = &le.nodes[nn * e..nn * (e + 1)];
            let p = |k: usize| x0[n[k] as usize];
            let part = &g.parts[le.part[e] as usize];
            let rho = part.mat.map(|m| g.materials[m as usize].rho).unwrap_or(0.0);
            match b.kind() {
                ElementKind::Shell4 => rho * le.thick[e] * quad_area([p(0), p(1), p(2), p(3)]),
                ElementKind::Shell3 => rho * le.thick[e] * triangle_area([p(0), p(1), p(2)]),
                ElementKind::Brick8 => rho * hexa_volume(std::array::from_fn(p)),
                ElementKind::Tetra4 => rho * tetra_volume([p(0), p(1), p(2), p(3)]),
                _ => part
                    .prop
                    .and_then(|q| {
                        g.properties[q as usize]
                            .card
                            .kind
                            .spring_mass(crate::vec3::norm(crate::vec3::sub(p(1), p(0))))
                    })
                    .map_or(0.0, |(m, _)| m),
            }
        })
        .collect()
}

/// This rank's exact sums per part: internal energy without hourglass (as
/// Radioss's part histories), kinetic energy Σ_e Σ_corners ½·(m_e/n)·|v|²
/// and mass of the live elements.
pub(crate) fn part_sums(
    blocks: &[Box<dyn Block>],
    elem_mass: &[Vec<f64>],
    vel: &[[f64; 3]],
    parts: usize,
) -> Vec<[ExactSum; 3]> {
    let mut sums = vec![[ExactSum::default(); 3]; parts];
    for (bi, b) in blocks.iter().enumerate() {
        let le = b.local();
        let nn = b.kind().nodes();
        for (e, out) in b.outputs().iter().enumerate() {
            let p = &mut sums[le.part[e] as usize];
            p[0].add(out.eint - out.ehg);
            if out.deleted {
                continue;
            }
            let me = elem_mass[bi][e];
            p[2].add(me);
            let mut v2 = 0.0;
            for &n in &le.nodes[nn * e..nn * (e + 1)] {
                if n != crate::model::NO_NODE {
                    let v = vel[n as usize];
                    v2 += v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
                }
            }
            p[1].add(0.5 * me / nn as f64 * v2);
        }
    }
    sums
}

impl History {
    pub fn new(ctx: &Context, blocks: &[Box<dyn Block>], interfaces: usize) -> History {
        let g = ctx.g;
        let sd = ctx.sd;
        let th_local = g
            .th_nodes
            .iter()
            .enumerate()
            .filter_map(|(i, gn)| {
                let l = sd.node_global.binary_search(gn).ok()?;
                sd.owns(l as u32).then_some((i, l))
            })
            .collect();
        let engine = &g.engine;
        let tstop = engine.run.as_ref().map(|r| r.tstop).unwrap_or(0.0);
        // No /TFILE: sample as often as the states are written, else 100 times
        // a run. /TFILE dT_his = 0: every cycle (period 0).
        let period = match engine.th_period {
            Some(p) if p >= 0.0 => p,
            _ => engine
                .anim_period
                .filter(|p| *p > 0.0)
                .unwrap_or(tstop / 100.0)
                .max(f64::MIN_POSITIVE),
        };
        History {
            layout: ThLayout {
                parts: g.parts.len(),
                interfaces,
                walls: g.rigid_walls.len(),
                nodes: g.th_nodes.len(),
            },
            period,
            next: 0.0,
            elem_mass: blocks
                .iter()
                .map(|b| element_masses(ctx.g, &ctx.sd.x, b.as_ref()))
                .collect(),
            th_local,
        }
    }

    /// Whether a sample is due at time `t`.
    pub fn due(&self, t: f64) -> bool {
        t >= self.next
    }

    /// Takes a sample (collective: every rank calls it at the same cycle) and
    /// schedules the next one.
    pub fn sample(&mut self, ctx: &Context, s: &LoopState) -> ThRow {
        let l = self.layout;
        let (np, ni, nw, nm) = (l.parts, l.interfaces, l.walls, l.nodes);
        // Partial sums: [ie, hourglass, plastic, w_ext, wall work, then the
        // tables as the file lays them out: parts [P][3], interfaces [I][IW],
        // walls [W][3], nodes [M][9]].
        let o_parts = 5;
        let o_if = o_parts + 3 * np;
        let o_wall = o_if + IW * ni;
        let o_node = o_wall + 3 * nw;
        // Exact sums, element by element and node by node: the same row
        // for any number of ranks (the interfaces' samples are this rank's
        // sums already).
        // Then the coming velocity update's works (`VelocitiesAtN::ahead`).
        let o_ahead = o_node + 9 * nm;
        let mut exact = vec![ExactSum::default(); o_ahead + 2];
        let mut el = [ExactSum::default(); 3];
        s.blocks.iter().for_each(|b| b.energy_sums(&mut el));
        exact[..3].copy_from_slice(&el);
        (exact[3], exact[4]) = (*s.w_ext, *s.wall_work);
        let weight = s.at_n.map_or(0.0, |a| {
            exact[o_ahead..].copy_from_slice(&a.ahead);
            a.ahead_weight
        });
        let vel: &[[f64; 3]] = s.at_n.map_or(&s.v[..], |a| &a.v);
        let parts = part_sums(s.blocks, &self.elem_mass, vel, np);
        exact[o_parts..o_parts + 3 * np].copy_from_slice(parts.as_flattened());
        for (i, smp) in s.interfaces.iter().enumerate().take(ni) {
            let o = o_if + IW * i;
            let values = [smp.normal, smp.tangential, [smp.energy, 0.0, 0.0]];
            for (j, x) in values.as_flattened()[..7].iter().enumerate() {
                exact[o + j] = ExactSum::of(*x);
            }
            for k in 0..3 {
                exact[o + 7 + k] = ExactSum::of(smp.tied_force[k]);
                exact[o + 10 + k] = ExactSum::of(smp.tied_moment[k]);
            }
        }
        for (w, f) in s.wall_force.iter().enumerate().take(nw) {
            exact[o_wall + 3 * w..o_wall + 3 * w + 3].copy_from_slice(f);
        }
        let mass = &ctx.sd.mass;
        for &(i, l) in &self.th_local {
            let o = o_node + 9 * i;
            for k in 0..3 {
                exact[o + k] = ExactSum::of(s.x[l][k] - ctx.sd.x[l][k]);
                exact[o + 3 + k] = ExactSum::of(vel[l][k]);
                if mass[l] > 0.0 && !s.fixed[l][k] {
                    exact[o + 6 + k] = ExactSum::of((s.fext[l][k] - s.fint[l][k]) / mass[l]);
                }
            }
        }
        sum_over_ranks(ctx.world, &mut exact);
        let mut buf: Vec<f64> = exact.iter().map(|x| x.value()).collect();
        buf[3] += weight * buf[o_ahead];
        buf[4] += weight * buf[o_ahead + 1];
        let (ke, ker) = match s.at_n {
            Some(a) => (s.kinetic)(&a.v, &a.vr, &a.bodies, &a.wall_v),
            None => (s.kinetic)(s.v, s.vr, s.bodies, s.wall_v),
        };
        // The listing's internal energy leaves the hourglass energy out (its
        // own column), as the Radioss listing and time histories do; the
        // external work is the listing's EXT-WORK, the rigid walls' included.
        let (ie, w) = (buf[0] - buf[1], buf[3] + buf[4]);
        // The listing's energy error (Radioss's: hourglass and contact
        // energies outside; solver::run::energy::error_fraction).
        let err = if s.e0 + w != 0.0 {
            100.0 * (ie + ke + ker - s.e0 - w) / (s.e0 + w).abs()
        } else {
            0.0
        };
        let contact: f64 = (0..ni).map(|i| buf[o_if + IW * i + 6]).sum();
        let mut values = Vec::with_capacity(l.width());
        values.extend_from_slice(&[*s.t, *s.dt]);
        values.extend_from_slice(&[ie, ke, ker, w, err, buf[1], buf[2], buf[4], contact]);
        values.extend_from_slice(&buf[o_parts..o_node + 9 * nm]);
        debug_assert_eq!(values.len(), l.width());
        while self.period > 0.0 && self.next <= *s.t {
            self.next += self.period;
        }
        ThRow {
            cycle: *s.cycle,
            values,
        }
    }
}
