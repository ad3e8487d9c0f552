//! One rank's set-up after the scatter: the fixed context of the loop
//! ([`Ctx`]: node roles, masses, the loads and walls this rank holds) and
//! the loop's mutable [`State`] at t = 0 (nodal arrays, element blocks,
//! assembly plan, contact and tied interfaces, walls, energies).

use super::super::assembly::{AssemblyPlan, SlotKey, SLOT};
use super::RunOptions;
use crate::contact::tied::TiedSystem;
use crate::contact::ContactSystem;
use crate::domain::Subdomain;
use crate::element::blocks::{make_block, Block};
use crate::error::RunError;
use crate::global::GlobalData;
use crate::kinematics::rigid_body::RigidBodyState;
use crate::model;
use crate::output;
use crate::parallel::{ExactSum, World};
use std::collections::HashMap;
use std::sync::RwLock;

/// One rank's rigid body membership.
pub(super) struct LocalBody {
    /// (local node, global node) of the secondary nodes this rank holds (the main node is `main_local`).
    pub members: Vec<(u32, u32)>,
    pub main_local: Option<u32>,
    /// The main node's /BCS (fixed degrees of freedom, global frame) and
    /// /IMPVEL cards (indices into `GlobalData::imposed_velocities`): they
    /// act on the body, as in Radioss.
    pub main_fixed: [bool; 6],
    pub main_impvel: Vec<usize>,
    /// The main node's translational /IMPDISP cards (indices into
    /// `GlobalData::imposed_displacements`): they move the body.
    pub main_impdisp: Vec<usize>,
}

/// Local nodes of a card, with the card.
pub(super) type OnLocal<'a, T> = Vec<(Vec<u32>, &'a T)>;

/// What the loop reads and never changes, on one rank.
pub(super) struct Ctx<'a> {
    pub world: &'a World,
    pub opts: &'a RunOptions,
    pub g: &'a GlobalData,
    pub sd: &'a Subdomain,
    pub n: usize,
    pub local_of: HashMap<u32, u32>,
    pub owned: Vec<bool>,
    /// Masses and inertias with the tied secondary nodes' moved to their
    /// main nodes (/INTER/TYPE2, contact::tied); gravity acts on `sd.mass`.
    /// Behind a lock: /DT/NODA/CST adds mass and inertia between cycles
    /// (`super::nodal_step`); every phase reads them once.
    pub mass: RwLock<Vec<f64>>,
    pub inertia: RwLock<Vec<f64>>,
    /// Rigid-body main nodes (their body moves them).
    pub is_main: Vec<bool>,
    /// Rigid-body main and member nodes (their body's resultant moves them).
    pub in_body: Vec<bool>,
    /// Tied secondary nodes: translation (and rotation) follow their main segment.
    pub tied_tr: Vec<bool>,
    pub tied_rot: Vec<bool>,
    /// Kinetic energy: rigid-body main nodes are counted by their body, tied
    /// secondary nodes by their main nodes (which carry their mass).
    pub ke_skip: Vec<bool>,
    /// Rotational: a tied secondary node's inertia is its main nodes' (or, on
    /// main nodes without rotations, left out of the dynamics: contact::interfaces::type2).
    pub inertia_ke: RwLock<Vec<f64>>,
    pub local_bodies: Vec<LocalBody>,
    pub walls: OnLocal<'a, model::RigidWall>,
    /// Every translational /IMPVEL on a moving wall's node drives that direction.
    pub wall_driver: Vec<Vec<&'a model::ImposedMotion>>,
    /// Moving walls with a mass, free or driven by an /IMPVEL on their
    /// node: (wall, mass). The listing counts their mass in TOTAL MASS and
    /// their kinetic energy in K-ENERGY T, as Radioss does (a driven wall's
    /// driver does the work of its kinetic energy, `kinematics`).
    pub wall_masses: Vec<(usize, f64)>,
    pub impdisp: OnLocal<'a, model::ImposedMotion>,
    /// /IMPDISP/FGEO: each card's local nodes as (local node, index in the card).
    pub fgeo: Vec<(Vec<(u32, usize)>, &'a model::FinalGeometry)>,
    pub impvel: OnLocal<'a, model::ImposedMotion>,
    pub cloads: OnLocal<'a, model::ConcentratedLoad>,
    pub gravity: OnLocal<'a, model::Gravity>,
    /// Which /DAMP damps each local node (`super::damping`).
    pub damp_of: Vec<Option<u16>>,
    pub fct_index: HashMap<u64, usize>,
    /// Each block's first slot in the element contributions (and the end).
    pub offsets: Vec<usize>,
    /// The /TH/NODE nodes this rank owns: (index in the list, local node).
    pub th_local: Vec<(usize, u32)>,
    pub tstop: f64,
    pub print_every: u64,
    pub th_period: f64,
    /// CRASHSIM_FAULT=RANK:CYCLE makes that rank abort at that cycle (tests only).
    pub fault: Option<(u32, u64)>,
}

/// Per-wall state, replicated on every rank: point, velocity; and per rank:
/// the force its owned nodes put on the wall in the last cycle (time
/// histories, summed exactly) and which of its nodes are tied to it.
#[derive(Clone)]
pub(super) struct Walls {
    pub p: Vec<[f64; 3]>,
    pub v: Vec<[f64; 3]>,
    pub force: Vec<[ExactSum; 3]>,
    pub tied: Vec<Vec<bool>>,
}

/// The global time step and what set it (the listing's ELEMENT column).
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Step {
    pub dt: f64,
    pub what: &'static str,
    pub id: u64,
}

/// The explicit loop's mutable state on one rank.
pub(super) struct State {
    pub t: f64,
    pub cycle: u64,
    pub dt: f64,
    pub dt_prev: f64,
    pub step: Step,
    pub x: Vec<[f64; 3]>,
    pub v: Vec<[f64; 3]>,
    pub vr: Vec<[f64; 3]>,
    pub fixed: Vec<[bool; 6]>,
    /// This cycle's imposed velocities (/IMPVEL, /IMPDISP, FGEO), as (local
    /// node, direction, velocity before the step), for the contact energy's
    /// mean velocity (`integrate::work`, which empties it): only the
    /// imposed directions, so the loop over every node writes nothing.
    pub imposed_before: Vec<(u32, u8, f64)>,
    pub ftie: Vec<[f64; 6]>,
    pub fint: Vec<[f64; SLOT]>,
    pub fext: Vec<[f64; SLOT]>,
    /// /DT/NODA/CST (`super::nodal_step`): the corners' and nodes'
    /// stiffness [K, 0, 0, K_rot, 0, 0], the mass each local node was
    /// given, the total added mass (empty without it).
    pub kcontrib: Vec<[f64; SLOT]>,
    pub knode: Vec<[f64; SLOT]>,
    pub added: Vec<f64>,
    pub mass_added: f64,
    /// The stiffness slots of elements inside a rigid body (no stiffness).
    pub kinactive: Vec<u32>,
    /// The nodal step while a TYPE7-family interface is active
    /// (`super::interface_nodal_step`).
    pub interface_step: InterfaceStep,
    /// Per block, the elements inside one rigid body (deactivated: no time
    /// step), `elements_in_bodies`.
    pub in_body: Vec<Vec<bool>>,
    pub contrib: Vec<[f64; SLOT]>,
    /// /PLOAD segments this rank carries (None without /PLOAD).
    pub pressure: Option<super::pressure::PressureState>,
    pub blocks: Vec<Box<dyn Block>>,
    pub plan: AssemblyPlan,
    /// Contact: forces and stiffness per local node, summed in a fixed global order.
    pub contact: ContactSystem,
    pub fcont: Vec<[f64; 3]>,
    pub kcont: Vec<f64>,
    /// IBC: (local node, released directions) of this cycle's impacts.
    pub release: Vec<(u32, u8)>,
    pub ties: TiedSystem,
    pub bodies: Vec<RigidBodyState>,
    /// Each body's velocity and spin before this step's acceleration (the
    /// contact work on analytic surfaces takes the mean with the new ones).
    pub bodies_v_before: Vec<([f64; 3], [f64; 3])>,
    pub walls: Walls,
    /// This rank's partial sums, exact (the same totals for any partition):
    /// external work, rigid-wall work, contact energy.
    pub w_ext: ExactSum,
    pub wall_work: ExactSum,
    pub e_contact: ExactSum,
    /// /DAMP: the last undamped accelerations.
    pub damping: DampState,
    /// Kinetic energy at t = 0 (the energy error's reference).
    pub e0: f64,
    /// Idel: which of this rank's elements were alive at the last look.
    pub was_alive: Vec<Vec<bool>>,
    /// The `--history` CSV samples and schedule.
    pub history: Vec<(f64, Vec<[f64; 3]>)>,
    pub next_th: f64,
    /// Contact forces per node and per-interface samples for the outputs.
    pub contact_force: Vec<[f64; 3]>,
    pub interface_samples: Vec<output::InterfaceSample>,
    /// The `--energies` CSV rows.
    pub energy_rows: Vec<[f64; 9]>,
    /// The velocities at t^n of this cycle, once something asked for them
    /// (the listing's kinetic energy: `kinematics::at_n`).
    pub at_n: Option<output::VelocitiesAtN>,
}

impl<'a> Ctx<'a> {
    /// Local nodes of global nodes this rank holds (others left out).
    pub(super) fn locals(&self, nodes: &[u32]) -> Vec<u32> {
        nodes
            .iter()
            .filter_map(|gn| self.local_of.get(gn).copied())
            .collect()
    }

    /// The value of an imposed motion's function at time t.
    pub fn imposed(&self, c: &model::ImposedMotion, t: f64) -> Option<f64> {
        crate::kinematics::function::imposed_value(
            &self.g.functions[self.fct_index[&c.card.fct]],
            &c.card,
            t,
        )
    }

    /// The displacement an /IMPDISP imposes at t + Δt, when the step from t
    /// starts inside its window (`function::imposed_displacement`).
    pub fn imposed_displacement(&self, c: &model::ImposedMotion, t: f64, dt: f64) -> Option<f64> {
        crate::kinematics::function::imposed_displacement(
            &self.g.functions[self.fct_index[&c.card.fct]],
            &c.card,
            t,
            dt,
        )
    }
}

/// The context of the loop on this rank; `ties` adds the tied secondary
/// nodes' masses and inertias to their main nodes.
pub(super) fn context<'a>(
    world: &'a World,
    opts: &'a RunOptions,
    g: &'a GlobalData,
    sd: &'a Subdomain,
    ties: &mut TiedSystem,
) -> Ctx<'a> {
    let n = sd.node_global.len();
    let local_of: HashMap<u32, u32> = sd
        .node_global
        .iter()
        .enumerate()
        .map(|(l, &gl)| (gl, l as u32))
        .collect();
    let mut mass = sd.mass.clone();
    let mut inertia = sd.inertia.clone();
    ties.add_masses(&mut mass, &mut inertia);
    let (tied_tr, tied_rot) = ties.masks(n);
    let engine = &g.engine;
    let mut cx = Ctx {
        world,
        opts,
        g,
        sd,
        n,
        local_of,
        owned: (0..n as u32).map(|l| sd.owns(l)).collect(),
        mass: RwLock::new(mass),
        inertia: RwLock::new(inertia),
        is_main: vec![false; n],
        in_body: vec![false; n],
        tied_tr,
        tied_rot,
        ke_skip: Vec::new(),
        inertia_ke: RwLock::new(Vec::new()),
        local_bodies: Vec::new(),
        walls: Vec::new(),
        wall_driver: Vec::new(),
        wall_masses: Vec::new(),
        impdisp: Vec::new(),
        fgeo: Vec::new(),
        impvel: Vec::new(),
        cloads: Vec::new(),
        gravity: Vec::new(),
        damp_of: Vec::new(),
        fct_index: g
            .functions
            .iter()
            .enumerate()
            .map(|(i, f)| (f.id, i))
            .collect(),
        offsets: Vec::new(),
        th_local: Vec::new(),
        tstop: engine.run.as_ref().expect("checked on rank 0").tstop,
        print_every: engine.print_every.unsigned_abs().max(1),
        th_period: engine.th_period.unwrap_or(f64::INFINITY),
        fault: std::env::var("CRASHSIM_FAULT").ok().and_then(|v| {
            let (r, c) = v.split_once(':')?;
            Some((r.parse().ok()?, c.parse().ok()?))
        }),
    };
    rigid_body_roles(&mut cx);
    on_local_cards(&mut cx);
    cx.th_local = g
        .th_nodes
        .iter()
        .enumerate()
        .filter_map(|(i, gn)| {
            cx.local_of
                .get(gn)
                .filter(|&&l| cx.owned[l as usize])
                .map(|&l| (i, l))
        })
        .collect();
    cx
}

/// Which local nodes are rigid-body main nodes, the bodies this rank holds,
/// and the kinetic-energy masks that follow.
fn rigid_body_roles(cx: &mut Ctx) {
    let (g, n) = (cx.g, cx.n);
    for rb in &g.rigid_bodies {
        let mut members: Vec<(u32, u32)> = rb
            .secondary_nodes
            .iter()
            .filter_map(|gn| cx.local_of.get(gn).map(|&l| (l, *gn)))
            .collect();
        let main_local = cx.local_of.get(&rb.main_node).copied();
        if let Some(l) = main_local {
            cx.is_main[l as usize] = true;
            cx.in_body[l as usize] = true;
        }
        for &(l, _) in &members {
            cx.in_body[l as usize] = true;
        }
        members.sort_by_key(|m| m.1);
        let mut main_fixed = [false; 6];
        for c in g.bcs.iter().filter(|c| c.nodes.contains(&rb.main_node)) {
            for k in 0..6 {
                main_fixed[k] |= c.card.fixed[k];
            }
        }
        let main_impvel = (0..g.imposed_velocities.len())
            .filter(|&i| g.imposed_velocities[i].nodes.contains(&rb.main_node))
            .collect();
        let main_impdisp = (0..g.imposed_displacements.len())
            .filter(|&i| {
                let c = &g.imposed_displacements[i];
                c.nodes.contains(&rb.main_node) && c.card.dir.index() < 3
            })
            .collect();
        cx.local_bodies.push(LocalBody {
            members,
            main_local,
            main_fixed,
            main_impvel,
            main_impdisp,
        });
    }
    cx.ke_skip = (0..n).map(|l| cx.is_main[l] || cx.tied_tr[l]).collect();
    let inertia = cx.inertia.read().unwrap().clone();
    cx.inertia_ke = RwLock::new(
        (0..n)
            .map(|l| {
                if cx.is_main[l] || cx.tied_rot[l] {
                    0.0
                } else {
                    inertia[l]
                }
            })
            .collect(),
    );
}

/// The walls, imposed motions, loads and gravity with the local nodes they act on.
fn on_local_cards<'a>(cx: &mut Ctx<'a>) {
    let g: &'a GlobalData = cx.g;
    cx.walls = g
        .rigid_walls
        .iter()
        .map(|w| (cx.locals(&w.secondary_nodes), w))
        .collect();
    cx.wall_driver = g
        .rigid_walls
        .iter()
        .map(|w| match w.node {
            Some(nd) => g
                .imposed_velocities
                .iter()
                .filter(|c| c.nodes.binary_search(&nd).is_ok() && c.card.dir.index() < 3)
                .collect(),
            None => Vec::new(),
        })
        .collect();
    cx.wall_masses = g
        .rigid_walls
        .iter()
        .enumerate()
        .filter(|(_, r)| r.node.is_some() && r.card.mass > 0.0)
        .map(|(w, r)| (w, r.card.mass))
        .collect();
    cx.impdisp = g
        .imposed_displacements
        .iter()
        .map(|c| (cx.locals(&c.nodes), c))
        .collect();
    cx.fgeo = g
        .final_geometries
        .iter()
        .map(|c| {
            let on: Vec<(u32, usize)> = c
                .nodes
                .iter()
                .enumerate()
                .filter_map(|(k, gn)| cx.local_of.get(gn).map(|&l| (l, k)))
                .collect();
            (on, c)
        })
        .collect();
    cx.impvel = g
        .imposed_velocities
        .iter()
        .map(|c| (cx.locals(&c.nodes), c))
        .collect();
    cx.cloads = g
        .concentrated_loads
        .iter()
        .map(|c| (cx.locals(&c.nodes), c))
        .collect();
    cx.gravity = g.gravity.iter().map(|c| (cx.locals(&c.nodes), c)).collect();
    // Which /DAMP damps each local node (`super::damping`).
    cx.damp_of = vec![None; cx.n];
    for (i, d) in g.dampings.iter().enumerate() {
        for l in cx.locals(&d.nodes) {
            cx.damp_of[l as usize] = Some(i as u16);
        }
    }
}

/// /DAMP: the last undamped acceleration of each degree of freedom of this
/// rank's nodes (the β term of `super::damping`), once it has one.
#[derive(Default)]
pub(super) struct DampState {
    pub prev: Vec<[f64; 6]>,
    pub primed: Vec<bool>,
}

/// The nodal step while a TYPE7-family interface is active
/// (`super::interface_nodal_step`), built at its first use.
#[derive(Default)]
pub(super) struct InterfaceStep {
    /// Per element (blocks one after the other): c·2·m_e/corners, 0 inside
    /// a rigid body (the reference deactivates those elements).
    pub coef: Vec<f64>,
    /// Each block's first element in `coef`.
    pub first: Vec<usize>,
    /// Each contribution slot's element in `coef`.
    pub elem_of_slot: Vec<u32>,
    /// This cycle's element stiffness coef/Δt_e² (every element: `c_max` > 1).
    pub k: Vec<f64>,
    /// The largest c over every rank's elements.
    pub c_max: f64,
    /// Built (every rank at the same cycle: a rank without elements too).
    pub ready: bool,
}

/// The loop's state at t = 0 before any force: initial velocities, rigid
/// bodies' nodes at their bodies, element blocks and their assembly plan,
/// contact, walls.
pub(super) fn initial_state(
    cx: &mut Ctx,
    ties: TiedSystem,
    bodies: Vec<RigidBodyState>,
) -> Result<State, RunError> {
    let (g, sd, n) = (cx.g, cx.sd, cx.n);
    let mut x = sd.x.clone();
    let mut v = vec![[0.0f64; 3]; n];
    let mut vr = vec![[0.0f64; 3]; n];
    let mut fixed = vec![[false; 6]; n];
    for c in &g.bcs {
        for l in cx.locals(&c.nodes) {
            for k in 0..6 {
                fixed[l as usize][k] |= c.card.fixed[k];
            }
        }
    }
    for iv in &g.initial_velocities {
        for l in cx.locals(&iv.nodes) {
            if iv.card.rotational {
                vr[l as usize] = iv.card.v;
            } else {
                v[l as usize] = iv.card.v;
            }
        }
    }
    for (b, lb) in cx.local_bodies.iter().enumerate() {
        if let Some(l) = lb.main_local {
            x[l as usize] = bodies[b].center;
            v[l as usize] = bodies[b].v;
        }
    }
    let blocks = element_blocks(cx, &x)?;
    let slot_meta = slots(cx, &blocks);
    let plan = AssemblyPlan::build(cx.world, sd, &slot_meta);
    let pressure = super::pressure::build(cx.world, sd, g, &cx.local_of, &blocks);
    let mut contact = ContactSystem::new(g.contact.clone(), sd, &g.node_ids);
    contact.set_time_step_scale(g.engine.dt_scale);
    contact.always_sort = std::env::var_os("CRASHSIM_SORT_EVERY_CYCLE").is_some();
    let n_samples = contact.sums.len() + ties.sums.len();
    Ok(State {
        t: 0.0,
        cycle: 0,
        dt: 0.0,
        dt_prev: 0.0,
        step: Step::default(),
        x,
        v,
        vr,
        imposed_before: Vec::new(),
        fixed,
        ftie: vec![[0.0f64; 6]; n],
        fint: vec![[0.0f64; SLOT]; n],
        fext: vec![[0.0f64; SLOT]; n],
        contrib: vec![[0.0f64; SLOT]; slot_meta.len()],
        pressure,
        kcontrib: Vec::new(),
        knode: Vec::new(),
        added: Vec::new(),
        mass_added: 0.0,
        kinactive: Vec::new(),
        interface_step: Default::default(),
        in_body: elements_in_bodies(&cx, &blocks),
        was_alive: blocks
            .iter()
            .map(|b| vec![true; b.local().global.len()])
            .collect(),
        blocks,
        plan,
        contact,
        fcont: vec![[0.0f64; 3]; n],
        kcont: vec![0.0f64; n],
        release: Vec::new(),
        ties,
        bodies,
        walls: initial_walls(cx),
        w_ext: ExactSum::default(),
        wall_work: ExactSum::default(),
        e_contact: ExactSum::default(),
        damping: Default::default(),
        bodies_v_before: Vec::new(),
        e0: 0.0,
        history: Vec::new(),
        next_th: 0.0,
        contact_force: Vec::new(),
        interface_samples: vec![output::InterfaceSample::default(); n_samples],
        energy_rows: Vec::new(),
        at_n: None,
    })
}

/// Element blocks: per kind present on this rank, one per formulation its
/// parts ask for (`element::blocks::registry`).
fn element_blocks(cx: &Ctx, x: &[[f64; 3]]) -> Result<Vec<Box<dyn Block>>, RunError> {
    let (g, sd) = (cx.g, cx.sd);
    let mut blocks: Vec<Box<dyn Block>> = Vec::new();
    for le in &sd.elements {
        blocks.extend(
            make_block(
                le,
                x,
                &sd.mass,
                &g.parts,
                &g.properties,
                &g.materials,
                &g.functions,
                crate::element::blocks::BlockContext {
                    rigid_bodies: &g.rigid_bodies,
                    node_global: &sd.node_global,
                    dt_max: g.engine.dtix.1,
                },
            )
            .map_err(RunError::Input)?,
        );
    }
    Ok(blocks)
}

/// Each element corner owns a slot keyed by (kind, global element, corner);
/// sets the blocks' first slots (`offsets`) and returns (local node, key) per slot.
fn slots(cx: &mut Ctx, blocks: &[Box<dyn Block>]) -> Vec<(u32, SlotKey)> {
    let mut slot_meta: Vec<(u32, SlotKey)> = Vec::new();
    for b in blocks {
        cx.offsets.push(slot_meta.len());
        let le = b.local();
        let nc = b.corners();
        let ki = b.kind().index();
        let stride = b.kind().nodes();
        for e in 0..le.global.len() {
            for c in 0..nc {
                slot_meta.push((le.nodes[stride * e + c], SlotKey::new(ki, le.global[e], c)));
            }
        }
    }
    cx.offsets.push(slot_meta.len());
    slot_meta
}

/// Wall motion at t = 0: a moving wall starts with its card's velocity.
fn initial_walls(cx: &Ctx) -> Walls {
    let g = cx.g;
    Walls {
        p: g.rigid_walls.iter().map(|w| w.point).collect(),
        v: g.rigid_walls
            .iter()
            .map(|w| {
                if w.node.is_some() {
                    w.card.v0
                } else {
                    [0.0; 3]
                }
            })
            .collect(),
        force: vec![[ExactSum::default(); 3]; g.rigid_walls.len()],
        tied: cx.walls.iter().map(|(l, _)| vec![false; l.len()]).collect(),
    }
}

/// Per block, the elements whose nodes all belong to one rigid body: the
/// reference starter deactivates them (reference guide /RBODY: "all the
/// elements belonging to the rigid body are deactivated"), so they give no
/// time step and no nodal stiffness.
fn elements_in_bodies(
    cx: &Ctx,
    blocks: &[Box<dyn crate::element::blocks::Block>],
) -> Vec<Vec<bool>> {
    let mut body_of = vec![u32::MAX; cx.n];
    for (b, lb) in cx.local_bodies.iter().enumerate() {
        for &(l, _) in &lb.members {
            body_of[l as usize] = b as u32;
        }
    }
    blocks
        .iter()
        .map(|blk| {
            let (le, nc, stride) = (blk.local(), blk.corners(), blk.kind().nodes());
            (0..le.global.len())
                .map(|e| {
                    let nodes = &le.nodes[stride * e..stride * e + nc];
                    let b = body_of[nodes[0] as usize];
                    b != u32::MAX && nodes.iter().all(|&l| body_of[l as usize] == b)
                })
                .collect()
        })
        .collect()
}
