//! `crashsim run`: set-up on rank 0, scatter, the explicit cycle on every rank.

use super::assembly::{key, AssemblyPlan, SLOT};
use super::blocks::{make_block, Block};
use super::global::GlobalData;
use super::listing::{format_row, Listing, Row, HEADER};
use crate::contact::{ContactStep, ContactSystem};
use crate::domain::{self, Subdomain};
use crate::input::{self, Input, InputOptions};
use crate::kinematics::function;
use crate::kinematics::rigid_body::{NodeLoad, RigidBodyState};
use crate::kinematics::rigid_wall::wall_velocity;
use crate::model::{self, Dof, ElementKind, Model};
use crate::output;
use crate::parallel::World;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::time::Instant;

pub struct RunOptions {
    pub deck: PathBuf,
    pub engine: Option<PathBuf>,
    pub out_dir: PathBuf,
    pub final_state: Option<PathBuf>,
    /// Per-element final state (stress, plastic strain, thickness, energy).
    pub final_elements: Option<PathBuf>,
    /// Displacements of the /TH/NODE nodes every /TFILE period.
    pub history: Option<PathBuf>,
    /// Energies at every cycle (CSV; costs reductions every cycle).
    pub energies: Option<PathBuf>,
    pub strict: bool,
    /// HDF5 run file, restart, progress (src/output).
    pub output: crate::output::OutputOptions,
}

/// Why a run stopped early.
#[derive(Debug)]
pub enum RunError {
    /// Bad or unsupported input (exit code 2).
    Input(String),
    /// Physics went wrong at run time (exit code 3).
    Physics(String),
}

impl RunError {
    pub fn exit_code(&self) -> u8 {
        match self {
            RunError::Input(_) => 2,
            RunError::Physics(_) => 3,
        }
    }
    pub fn message(&self) -> &str {
        match self {
            RunError::Input(m) | RunError::Physics(m) => m,
        }
    }
}

/// What rank 0 prepares: the shared data and one subdomain per rank.
type Prepared = (GlobalData, Vec<Subdomain>, Vec<RigidBodyState>, Vec<String>);

fn prepare(opts: &RunOptions, nranks: usize) -> Result<Prepared, String> {
    let d = Input::read(
        &opts.deck,
        &InputOptions {
            controls: opts.engine.clone(),
            strict: opts.strict,
        },
    )
    .map_err(|e| e.to_string())?;
    let m = d.model().map_err(|e| e.to_string())?;
    let starter = opts.deck.display();
    let eng = m.engine.clone().ok_or_else(|| {
        format!(
            "{starter}: no engine file: expected {} beside the starter, or --engine FILE",
            input::controls_beside(&opts.deck)
                .map(|p| p.display().to_string())
                .unwrap_or_else(|| "NAME_0001.rad".into())
        )
    })?;
    if eng.run.is_none() {
        return Err(format!(
            "{starter}: the engine file has no /RUN card: expected /RUN/NAME/1 and its end time"
        ));
    }
    check_supported(&m)?;
    // /INTER/TYPE7 Inacti = 3: a starter step — the penetrated secondary nodes
    // get new coordinates, and the model is built again from them so that
    // every rank's elements, masses, gaps and the output mesh start there.
    let (moved, inacti3) = crate::contact::inacti3::depenetrate(&m)?;
    let m = match moved {
        Some(x) => d
            .model_with_node_positions(&m.nodes.ids, &x)
            .map_err(|e| e.to_string())?,
        None => m,
    };
    let (p, _) =
        domain::partition(&m, nranks).map_err(|e| format!("{starter}: cannot partition: {e}"))?;
    let sds = domain::split(&m, &p.part, nranks);
    let rbs = initial_rigid_bodies(&m);
    let mut g = GlobalData::from_model(&m, eng);
    // Contact: which ranks hold each node, then the interfaces' static data.
    let mut holders: Vec<Vec<u32>> = vec![Vec::new(); m.nodes.ids.len()];
    for sd in &sds {
        for &gn in &sd.node_global {
            holders[gn as usize].push(sd.rank);
        }
    }
    g.contact = crate::contact::setup::build(&m, &holders)?;
    g.tied = crate::contact::tied::build(&m, &holders)?;
    for th in m.time_histories.iter().filter(|t| t.kind == "NODE") {
        for &id in &th.objects {
            let i = m.nodes.ids.binary_search(&id).map_err(|_| {
                format!(
                    "{}: /TH/NODE/{}, field NODid: node {id} is not defined in the deck",
                    th.loc, th.id
                )
            })?;
            g.th_nodes.push(i as u32);
        }
    }
    // Where the engine computes a card's option another way, the listing says so.
    let mut notes = Vec::new();
    for r in &inacti3 {
        if let Some(i) = m
            .interfaces
            .iter()
            .find(|i| i.card.id == r.interface_id && i.card.type_number() == 7)
        {
            notes.push(r.note(&i.card.loc.to_string()));
        }
    }
    for p in &m.properties {
        if let Some(s) = &p.shell {
            if s.ismstr == 1 {
                notes.push(format!("{}: /PROP/{}: Ismstr = 1 (small strain) is computed from the initial geometry on 4-node shells, with the large-strain corotational rate form on 3-node shells", p.card.loc, p.card.id));
            }
        }
    }
    notes.extend(g.tied.notes());
    // N = 0 with a law the reference engine does not integrate globally.
    let mut seen = std::collections::BTreeSet::new();
    for part in &m.parts {
        let (Some(ip), Some(im)) = (part.prop, part.mat) else {
            continue;
        };
        let p = &m.properties[ip as usize];
        if p.shell.as_ref().is_none_or(|s| s.n != 0) {
            continue;
        }
        let mat = crate::material::Material::from_card(&m.materials[im as usize]);
        if let crate::element::shell4::N0Rule::Points(n) = crate::element::shell4::n0_rule(&mat) {
            if seen.insert((ip, im)) {
                notes.push(format!("{}: /PROP/{}: N = 0 (global integration) with /MAT/{} (LAW2) is computed with N = {n} integration points, as the reference engine does (its starter WARNING 1912)", p.card.loc, p.card.id, m.materials[im as usize].id));
            }
        }
    }
    Ok((g, sds, rbs, notes))
}

/// The engine refuses what it does not compute yet, by name — never a silent substitute.
fn check_supported(m: &Model) -> Result<(), String> {
    // Every kind's sections are built once over the whole model: what the
    // engine cannot compute is refused here, on rank 0, with its card.
    for set in &m.elements {
        // One element of each part is enough to build (and so check) its section.
        let mut seen = std::collections::BTreeSet::new();
        for e in 0..set.len() {
            if !seen.insert(set.part[e]) {
                continue;
            }
            let n = set.kind.nodes();
            let le = domain::LocalElements {
                kind: set.kind,
                global: vec![e as u32],
                part: vec![set.part[e]],
                nodes: set.nodes[n * e..n * (e + 1)].to_vec(),
                thick: vec![set.thick[e]],
            };
            super::blocks::make_block(
                &le,
                &m.nodes.x,
                &m.nodal_mass,
                &m.parts,
                &m.properties,
                &m.materials,
                &m.functions,
            )
            .map_err(|err| {
                let part = &m.parts[set.part[e] as usize];
                match part.prop.map(|i| &m.properties[i as usize].card) {
                    Some(c) => format!(
                        "{}: /PROP/{} (part {}, {} elements): {err}",
                        c.loc,
                        c.id,
                        part.id,
                        set.kind.keyword()
                    ),
                    None => format!("part {} ({} elements): {err}", part.id, set.kind.keyword()),
                }
            })?;
        }
    }
    let unsupported = |what: &str, loc: &model::Loc| {
        Err(format!("{loc}: {what} is not supported by the engine yet"))
    };
    for c in &m.bcs {
        if c.card.skew_id != 0 {
            return unsupported("/BCS with a skew system", &c.card.loc);
        }
    }
    for c in &m.imposed_velocities {
        if c.card.skew_id != 0 || c.card.sens_id != 0 || c.card.frame_id != 0 || c.card.icoor != 0 {
            return unsupported(
                "/IMPVEL with a skew, sensor, frame or cylindrical coordinates",
                &c.card.loc,
            );
        }
    }
    for c in &m.imposed_displacements {
        if c.card.skew_id != 0
            || c.card.sens_id != 0
            || c.card.icoor != 0
            || c.card.dir.index() >= 3
        {
            return unsupported(
                "/IMPDISP with a skew, sensor, cylindrical coordinates or a rotation",
                &c.card.loc,
            );
        }
    }
    for c in &m.initial_velocities {
        if c.card.skew_id != 0 {
            return unsupported("/INIVEL with a skew system", &c.card.loc);
        }
    }
    for c in &m.concentrated_loads {
        if c.card.skew_id != 0 || c.card.sens_id != 0 {
            return unsupported("/CLOAD with a skew system or sensor", &c.card.loc);
        }
    }
    for c in &m.gravity {
        if c.card.skew_id != 0 || c.card.sens_id != 0 {
            return unsupported("/GRAV with a skew system or sensor", &c.card.loc);
        }
    }
    for r in &m.rigid_bodies {
        if r.card.sens_id != 0 || r.card.skew_id != 0 || r.card.ikrem != 0 || r.card.surf_id != 0 {
            return unsupported("/RBODY with a sensor, skew, IKREM or surface", &r.card.loc);
        }
    }
    for i in &m.interfaces {
        check_interface(&i.card)?;
    }
    Ok(())
}

/// Interface options the engine does not compute are refused by name.
fn check_interface(c: &model::InterfaceSpec) -> Result<(), String> {
    use model::InterfaceKind as K;
    let kw = format!("{}: /INTER/TYPE{}/{}", c.loc, c.type_number(), c.id);
    let no = |what: &str| Err(format!("{kw}: {what} is not supported by the engine yet"));
    match &c.kind {
        K::Type2(t) => {
            // Spotflag 0 reads as 5 (deck::interfaces::read_type2): the standard
            // kinematic formulation is the one computed (contact::interfaces::type2).
            let fo = |field: &str, what: &str| {
                Err(format!(
                    "{kw}, field {field}: {what} is not supported by the engine yet"
                ))
            };
            match t.spotflag {
                5 => {}
                1 => {
                    return fo(
                        "Spotflag",
                        "Spotflag = 1 (optimized spotweld formulation, element mean rigid motion)",
                    )
                }
                2 => {
                    return fo(
                        "Spotflag",
                        "Spotflag = 2 (formulation for hierarchy levels)",
                    )
                }
                3 => return fo("Spotflag", "Spotflag = 3"),
                4 => return fo("Spotflag", "Spotflag = 4 (rotations not transmitted)"),
                10..=12 => {
                    return fo(
                        "Spotflag",
                        &format!(
                            "Spotflag = {} (formulation with rotations of bricks)",
                            t.spotflag
                        ),
                    )
                }
                20..=22 => {
                    return fo(
                        "Spotflag",
                        &format!(
                            "Spotflag = {} (formulation with failure, rupture cards)",
                            t.spotflag
                        ),
                    )
                }
                25..=28 => {
                    return fo(
                        "Spotflag",
                        &format!(
                            "Spotflag = {} (penalty formulation, penalty card)",
                            t.spotflag
                        ),
                    )
                }
                30 => return fo("Spotflag", "Spotflag = 30"),
                other => return fo("Spotflag", &format!("Spotflag = {other}")),
            }
            if t.level != 0 {
                return fo("Level", "a hierarchy level (Level > 0)");
            }
            if t.isearch == 1 {
                return fo("Isearch", "Isearch = 1 (old search)");
            }
            if t.idel2 != 1000 {
                return fo(
                    "Idel2",
                    "Idel2 (releasing nodes when main elements are deleted)",
                );
            }
            if matches!(t.ignore, 2 | 3) && t.dsearch == 0.0 {
                return fo(
                    "Ignore",
                    "Ignore = 2 or 3 with dsearch = 0 (recomputed search distance)",
                );
            }
            if t.rupture.is_some() {
                return fo("Rupt", "the rupture cards");
            }
            if t.penalty.is_some() {
                return fo("Stfac", "the penalty card");
            }
            if let Some(th) = &t.thermal {
                if th.ithe != 0 {
                    return fo("Ithe", "heat transfer (Ithe = 1)");
                }
            }
            Ok(())
        }
        K::Type11(_) => no("TYPE11 (edge to edge)"),
        K::Type3(_) => Ok(()),
        K::Type5(t) => {
            if t.sens_id != 0 {
                return no("an activation sensor (sens_ID)");
            }
            if t.inacti != 0 {
                return no("Inacti (moving nodes out of initial penetrations)");
            }
            if t.ptlim < 1e29 {
                return no("a tangential pressure limit (Ptlim)");
            }
            Ok(())
        }
        K::Type7(t) => {
            if t.sens_id != 0 {
                return no("an activation sensor (sens_ID)");
            }
            if t.ithe != 0 {
                return no("heat transfer (Ithe = 1)");
            }
            if t.icurv != 0 {
                return no("a curved gap envelope (Icurv)");
            }
            if t.iadm != 0 {
                return no("adaptive meshing (Iadm)");
            }
            if t.ists != 0 {
                return no("surface-to-surface contact (Ists)");
            }
            if t.fct_idf != 0 || t.fric_id != 0 {
                return no("friction from a function or /FRICTION (fct_IDF, fric_ID)");
            }
            if t.ibag == 1 {
                return no("airbag vent closure (Ibag = 1)");
            }
            if t.ifric == 4 {
                return no("Ifric = 4 (exponential decay law)");
            }
            Ok(())
        }
    }
}

/// Rigid bodies at t = 0: mass, centre, inertia from the model; velocity the
/// mass-weighted mean of its nodes' initial velocities (all /INIVEL/TRA).
fn initial_rigid_bodies(m: &Model) -> Vec<RigidBodyState> {
    let mut v0 = vec![[0.0; 3]; m.nodes.len()];
    for iv in &m.initial_velocities {
        if !iv.card.rotational {
            for &n in &iv.nodes {
                v0[n as usize] = iv.card.v;
            }
        }
    }
    m.rigid_bodies
        .iter()
        .map(|rb| {
            let mut p = [0.0; 3];
            let main_m = rb.card.mass + m.nodal_mass[rb.main_node as usize];
            for k in 0..3 {
                p[k] += main_m * v0[rb.main_node as usize][k];
            }
            for &n in &rb.secondary_nodes {
                for k in 0..3 {
                    p[k] += m.nodal_mass[n as usize] * v0[n as usize][k];
                }
            }
            let v = if rb.mass > 0.0 {
                [p[0] / rb.mass, p[1] / rb.mass, p[2] / rb.mass]
            } else {
                [0.0; 3]
            };
            RigidBodyState::new(rb.card.id, rb.mass, rb.center, rb.inertia, v, [0.0; 3])
        })
        .collect()
}

/// One rank's rigid body membership.
struct LocalBody {
    /// (local node, global node) of the members this rank holds (main node included).
    members: Vec<(u32, u32)>,
    main_local: Option<u32>,
    main_global: u32,
    /// Card MASS + main node's own mass: what the main node carries.
    main_mass: f64,
}

pub fn run(world: &World, opts: &RunOptions) -> Result<(), RunError> {
    let rank = world.rank();
    let nranks = world.size();
    let started = Instant::now();
    // Rank 0 prepares; a failure there is broadcast so every rank stops together.
    let prepared: Option<Result<Prepared, String>> = if rank == 0 {
        Some(prepare(opts, nranks as usize))
    } else {
        None
    };
    let status: Result<(), String> = match &prepared {
        Some(Err(e)) => Err(e.clone()),
        _ => Ok(()),
    };
    world
        .broadcast(if rank == 0 { Some(&status) } else { None })
        .map_err(RunError::Input)?
        .map_err(RunError::Input)?;
    let (g, sds, rbs, notes) = match prepared {
        Some(Ok((g, s, r, n))) => (Some(g), Some(s), Some(r), n),
        _ => (None, None, None, Vec::new()),
    };
    let g: GlobalData = world.broadcast(g.as_ref()).map_err(RunError::Input)?;
    let mut bodies: Vec<RigidBodyState> = world.broadcast(rbs.as_ref()).map_err(RunError::Input)?;
    let sd = world.scatter(sds).map_err(RunError::Input)?;
    let engine = &g.engine;
    let run_card = engine.run.as_ref().expect("checked on rank 0");
    let tstop = run_card.tstop;

    // ---- local set-up ---------------------------------------------------
    let n = sd.node_global.len();
    let local_of: HashMap<u32, u32> = sd
        .node_global
        .iter()
        .enumerate()
        .map(|(l, &gl)| (gl, l as u32))
        .collect();
    let locals = |nodes: &[u32]| -> Vec<u32> {
        nodes
            .iter()
            .filter_map(|gn| local_of.get(gn).copied())
            .collect()
    };
    let owned: Vec<bool> = (0..n as u32).map(|l| sd.owns(l)).collect();
    let mut x = sd.x.clone();
    let mut v = vec![[0.0f64; 3]; n];
    let mut vr = vec![[0.0f64; 3]; n];
    // Gravity acts on each node's own mass; the dynamics use the masses with
    // the tied secondary nodes' masses and inertias moved to their main nodes
    // (/INTER/TYPE2, contact::tied).
    let grav_mass = sd.mass.clone();
    let mut mass = sd.mass.clone();
    let mut inertia = sd.inertia.clone();
    let mut ties = crate::contact::tied::TiedSystem::new(g.tied.clone(), &sd);
    ties.add_masses(&mut mass, &mut inertia);
    let (mass, inertia) = (mass, inertia);
    // Tied secondary nodes: translation (and rotation) follow their main segment.
    let (tied_tr, tied_rot) = ties.masks(n);
    let mut ftie = vec![[0.0f64; 6]; n];
    let mut fixed = vec![[false; 6]; n];
    for c in &g.bcs {
        for l in locals(&c.nodes) {
            for k in 0..6 {
                fixed[l as usize][k] |= c.card.fixed[k];
            }
        }
    }
    for iv in &g.initial_velocities {
        for l in locals(&iv.nodes) {
            if iv.card.rotational {
                vr[l as usize] = iv.card.v;
            } else {
                v[l as usize] = iv.card.v;
            }
        }
    }
    let mut local_bodies = Vec::new();
    let mut is_main = vec![false; n];
    for (b, rb) in g.rigid_bodies.iter().enumerate() {
        let mut members: Vec<(u32, u32)> = rb
            .secondary_nodes
            .iter()
            .filter_map(|gn| local_of.get(gn).map(|&l| (l, *gn)))
            .collect();
        let main_local = local_of.get(&rb.main_node).copied();
        if let Some(l) = main_local {
            is_main[l as usize] = true;
            x[l as usize] = bodies[b].center;
            v[l as usize] = bodies[b].v;
        }
        members.sort_by_key(|m| m.1);
        local_bodies.push(LocalBody {
            members,
            main_local,
            main_global: rb.main_node,
            main_mass: rb.card.mass + main_node_mass(&sd, main_local),
        });
    }
    // Kinetic energy: rigid-body main nodes are counted by their body, tied
    // secondary nodes by their main nodes (which carry their mass).
    let ke_skip: Vec<bool> = (0..n).map(|l| is_main[l] || tied_tr[l]).collect();
    // Rotational: a tied secondary node's inertia is its main nodes' (or, on
    // main nodes without rotations, left out of the dynamics: contact::interfaces::type2).
    let inertia_ke: Vec<f64> = (0..n)
        .map(|l| {
            if is_main[l] || tied_rot[l] {
                0.0
            } else {
                inertia[l]
            }
        })
        .collect();
    let walls: Vec<(Vec<u32>, &model::RigidWall)> = g
        .rigid_walls
        .iter()
        .map(|w| (locals(&w.secondary_nodes), w))
        .collect();
    let mut tied: Vec<Vec<bool>> = walls.iter().map(|(l, _)| vec![false; l.len()]).collect();
    // Wall motion, replicated on every rank: point, velocity. A moving wall
    // follows its node: that node's /IMPVEL if it has one, else its own mass
    // pushed back by the nodes it stops (forces summed in global node order).
    let mut wall_p: Vec<[f64; 3]> = g.rigid_walls.iter().map(|w| w.point).collect();
    // Force the nodes put on each wall in the last cycle (this rank's owned nodes), for the time histories.
    let mut wall_force = vec![[0.0f64; 3]; g.rigid_walls.len()];
    let mut wall_v: Vec<[f64; 3]> = g
        .rigid_walls
        .iter()
        .map(|w| {
            if w.node.is_some() {
                w.card.v0
            } else {
                [0.0; 3]
            }
        })
        .collect();
    // Every translational /IMPVEL on a moving wall's node drives that direction.
    let wall_driver: Vec<Vec<&model::ImposedMotion>> = g
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
    let impdisp: Vec<(Vec<u32>, &model::ImposedMotion)> = g
        .imposed_displacements
        .iter()
        .map(|c| (locals(&c.nodes), c))
        .collect();
    let impvel: Vec<(Vec<u32>, &model::ImposedMotion)> = g
        .imposed_velocities
        .iter()
        .map(|c| (locals(&c.nodes), c))
        .collect();
    let cloads: Vec<(Vec<u32>, &model::ConcentratedLoad)> = g
        .concentrated_loads
        .iter()
        .map(|c| (locals(&c.nodes), c))
        .collect();
    let gravity: Vec<(Vec<u32>, &model::Gravity)> =
        g.gravity.iter().map(|c| (locals(&c.nodes), c)).collect();
    let fct_index: HashMap<u64, usize> = g
        .functions
        .iter()
        .enumerate()
        .map(|(i, f)| (f.id, i))
        .collect();

    // Element blocks, one per kind present; each element corner owns a slot
    // keyed by (kind, global element, corner).
    let mut blocks: Vec<Box<dyn Block>> = Vec::new();
    for le in &sd.elements {
        if let Some(b) = make_block(
            le,
            &x,
            &sd.mass,
            &g.parts,
            &g.properties,
            &g.materials,
            &g.functions,
        )
        .map_err(RunError::Input)?
        {
            blocks.push(b);
        }
    }
    let kind_index = |k: ElementKind| {
        crate::model::ElementKind::ALL
            .iter()
            .position(|&q| q == k)
            .unwrap()
    };
    let mut slot_meta: Vec<(u32, u64)> = Vec::new();
    let mut offsets = Vec::new();
    for b in &blocks {
        offsets.push(slot_meta.len());
        let le = b.local();
        let nc = b.corners();
        let ki = kind_index(b.kind());
        let stride = b.kind().nodes();
        for e in 0..le.global.len() {
            for c in 0..nc {
                slot_meta.push((le.nodes[stride * e + c], key(ki, le.global[e], c)));
            }
        }
    }
    offsets.push(slot_meta.len());
    let mut plan = AssemblyPlan::build(world, &sd, &slot_meta);
    let mut contrib = vec![[0.0f64; SLOT]; slot_meta.len()];
    let mut fint = vec![[0.0f64; SLOT]; n];
    let mut fext = vec![[0.0f64; SLOT]; n];
    // Contact: forces and stiffness per local node, summed in a fixed global order.
    let mut contact = ContactSystem::new(g.contact.clone(), &sd, &g.node_ids);
    contact.set_time_step_scale(engine.dt_scale);
    contact.always_sort = std::env::var_os("CRASHSIM_SORT_EVERY_CYCLE").is_some();
    let mut fcont = vec![[0.0f64; 3]; n];
    let mut kcont = vec![0.0f64; n];
    let mut release: Vec<(u32, u8)> = Vec::new();
    let mut contact_forces = |contact: &mut ContactSystem,
                              x: &[[f64; 3]],
                              v: &[[f64; 3]],
                              t: f64,
                              dt: f64,
                              fcont: &mut [[f64; 3]],
                              fixed: &mut [[bool; 6]],
                              deleted: &[(u8, u32)]|
     -> Option<ContactStep> {
        fcont.iter_mut().for_each(|f| *f = [0.0; 3]);
        kcont.iter_mut().for_each(|k| *k = 0.0);
        release.clear();
        let s = contact.compute(
            world,
            x,
            v,
            &mass,
            t,
            dt,
            fcont,
            &mut kcont,
            &mut release,
            deleted,
        );
        // IBC: an impact releases the secondary node's boundary conditions.
        for &(l, bits) in &release {
            for k in 0..3 {
                if bits >> k & 1 == 1 {
                    fixed[l as usize][k] = false;
                }
            }
        }
        s
    };
    let mut e_contact = 0.0f64;
    // Idel: which of this rank's elements were alive at the last look (all
    // at the start; after a restart, those the restart file brings back).
    let mut was_alive: Vec<Vec<bool>> = blocks
        .iter()
        .map(|b| vec![true; b.local().global.len()])
        .collect();
    let mut newly_deleted =
        |blocks: &[Box<dyn Block>], contact: &ContactSystem| -> Vec<(u8, u32)> {
            let mut out = Vec::new();
            if !contact.tracks_deletion() {
                return out;
            }
            for (b, w) in blocks.iter().zip(was_alive.iter_mut()) {
                let ki = crate::model::ElementKind::ALL
                    .iter()
                    .position(|&q| q == b.kind())
                    .unwrap() as u8;
                for (e, a) in w.iter_mut().enumerate() {
                    if *a && !b.alive(e) {
                        *a = false;
                        out.push((ki, b.local().global[e]));
                    }
                }
            }
            out
        };

    // ---- listing ----------------------------------------------------------
    let mut listing = if rank == 0 {
        std::fs::create_dir_all(&opts.out_dir).map_err(|e| {
            RunError::Input(format!(
                "{}: cannot create the output directory: {e}",
                opts.out_dir.display()
            ))
        })?;
        let path = opts.out_dir.join(format!("{}.out", g.name));
        // After a restart the listing goes on in the same file.
        let listing = match opts.output.restart {
            Some(_) => Listing::append(&path),
            None => Listing::new(Some(&path)),
        };
        Some(listing.map_err(|e| {
            RunError::Input(format!("{}: cannot write the listing: {e}", path.display()))
        })?)
    } else {
        None
    };
    if let Some(l) = &mut listing {
        l.line(&format!(
            " crashsim {} — {} ({}), {} rank(s), {} thread(s) per rank",
            env!("CARGO_PKG_VERSION"),
            g.name,
            g.title,
            nranks,
            rayon::current_num_threads()
        ));
        l.line(&format!(
            " units: {} {} {}   end time {:e}   /DT scale {}",
            g.units.mass, g.units.length, g.units.time, tstop, engine.dt_scale
        ));
        l.line("");
        for n in &notes {
            l.line(&format!(" note: {n}"));
        }
        if !notes.is_empty() {
            l.line("");
        }
        l.line(HEADER);
    }
    let print_every = engine.print_every.unsigned_abs().max(1);

    // ---- cycle 0: forces and time step at t = 0 -------------------------
    let mut t = 0.0f64;
    let mut cycle: u64 = 0;
    let mut w_ext = 0.0f64;
    let mut wall_work = 0.0f64;
    // Tied secondary nodes start with their main segment's motion.
    if !ties.is_empty() {
        ties.recover(world, &x, &mut v, &mut vr, 0.0);
    }
    let stop = compute_all(&mut blocks, &offsets, &x, &v, &vr, 0.0, &mut contrib);
    plan.assemble(world, &contrib, &mut fint);
    external_forces(&g, &fct_index, &cloads, &gravity, &grav_mass, t, &mut fext);
    let dead = newly_deleted(&blocks, &contact);
    let cstep = contact_forces(&mut contact, &x, &v, t, 0.0, &mut fcont, &mut fixed, &dead);
    let mut step = global_step(
        world,
        &g,
        &blocks,
        engine.dt_scale,
        stop,
        None,
        cstep,
        cycle,
        t,
    )?;
    let mut dt = step.dt;
    let (ke0, ker0) = kinetic(
        world,
        &v,
        &vr,
        &mass,
        &inertia_ke,
        &owned,
        &ke_skip,
        &bodies,
        &local_bodies,
    );
    let e0 = ke0 + ker0;
    let emit = |listing: &mut Option<Listing>,
                cycle: u64,
                t: f64,
                dt: f64,
                step: &Step,
                ie: f64,
                hg: f64,
                ke: f64,
                ker: f64,
                w: f64,
                ec: f64| {
        if let Some(l) = listing {
            // The I-ENERGY column leaves the hourglass energy out, as the
            // Radioss listing does (its time histories carry it apart: on
            // BOULE1V4 I-ENERGY + HOURGLASS + kinetic + contact energies
            // equal the rigid wall's work); the balance counts both, and
            // the energy contact took (ec).
            let err = if e0 + w != 0.0 {
                100.0 * (ie + hg + ec + ke + ker - e0 - w) / (e0 + w).abs()
            } else {
                0.0
            };
            l.line(&format_row(&Row {
                cycle,
                time: t,
                dt,
                what: step.what,
                id: step.id,
                error_pct: err,
                ie,
                ke,
                ker,
                ext_work: w,
                mas_err: 0.0,
                total_mass: g.total_mass,
                mass_added: 0.0,
            }));
        }
    };
    if opts.output.restart.is_none() {
        emit(
            &mut listing,
            cycle,
            t,
            dt,
            &step,
            0.0,
            0.0,
            ke0,
            ker0,
            0.0,
            0.0,
        );
    }
    let mut dt_prev = 0.0f64;
    let th_period = engine.th_period.unwrap_or(f64::INFINITY);
    let th_local: Vec<(usize, u32)> = g
        .th_nodes
        .iter()
        .enumerate()
        .filter_map(|(i, gn)| {
            local_of
                .get(gn)
                .filter(|&&l| owned[l as usize])
                .map(|&l| (i, l))
        })
        .collect();
    let mut history: Vec<(f64, Vec<[f64; 3]>)> = Vec::new();
    let mut next_th = 0.0f64;
    let sample = |t: f64, x: &[[f64; 3]], history: &mut Vec<(f64, Vec<[f64; 3]>)>| {
        if opts.history.is_none() || g.th_nodes.is_empty() {
            return;
        }
        let mine: Vec<(usize, [f64; 3])> = th_local
            .iter()
            .map(|&(i, l)| (i, [0, 1, 2].map(|k| x[l as usize][k] - sd.x[l as usize][k])))
            .collect();
        let all = world.allgather(&mine);
        let mut d = vec![[0.0; 3]; g.th_nodes.len()];
        for (i, u) in all.into_iter().flatten() {
            d[i] = u;
        }
        history.push((t, d));
    };
    sample(0.0, &x, &mut history);
    next_th += th_period;
    // CRASHSIM_FAULT=RANK:CYCLE makes that rank abort at that cycle (tests only).
    let fault: Option<(u32, u64)> = std::env::var("CRASHSIM_FAULT").ok().and_then(|v| {
        let (r, c) = v.split_once(':')?;
        Some((r.parse().ok()?, c.parse().ok()?))
    });

    // ---- output hooks (src/output): restart, HDF5 run file, time histories, progress ----
    // Contact forces per node and per-interface samples (refreshed every cycle).
    let mut contact_force = fcont.clone();
    // The interface tables: the contact interfaces, then the tied ones (TYPE2).
    let n_contact = contact.sums.len();
    let mut interface_samples: Vec<output::InterfaceSample> =
        vec![output::InterfaceSample::default(); n_contact + ties.sums.len()];
    let iface_info: Vec<output::InterfaceInfo> = contact
        .setup
        .interfaces
        .iter()
        .map(|i| output::InterfaceInfo {
            id: i.id,
            type_number: i.type_number,
            title: i.title.clone(),
        })
        .chain(ties.setup.interfaces.iter().map(|i| output::InterfaceInfo {
            id: i.id,
            type_number: 2,
            title: i.title.clone(),
        }))
        .collect();
    let octx = output::Context {
        world,
        g: &g,
        sd: &sd,
        out_dir: &opts.out_dir,
        opts: &opts.output,
        interfaces: &iface_info,
    };
    let ke_of = |v: &[[f64; 3]], vr: &[[f64; 3]], b: &[RigidBodyState]| {
        kinetic(
            world,
            v,
            vr,
            &mass,
            &inertia_ke,
            &owned,
            &ke_skip,
            b,
            &local_bodies,
        )
    };
    // The loop's state by reference, for the output hooks.
    macro_rules! loop_state {
        () => {
            output::LoopState {
                t: &mut t,
                cycle: &mut cycle,
                dt: &mut dt,
                dt_prev: &mut dt_prev,
                step_what: &mut step.what,
                step_id: &mut step.id,
                x: &mut x,
                v: &mut v,
                vr: &mut vr,
                fint: &mut fint,
                fext: &mut fext,
                blocks: &mut blocks,
                bodies: &mut bodies,
                wall_p: &mut wall_p,
                wall_v: &mut wall_v,
                tied: &mut tied,
                w_ext: &mut w_ext,
                wall_work: &mut wall_work,
                next_th: &mut next_th,
                history: &mut history,
                contact: &mut contact,
                ties: &mut ties,
                fcont: &mut fcont,
                e_contact: &mut e_contact,
                fixed: &mut fixed,
                e0,
                wall_force: &wall_force,
                contact_force: &contact_force,
                interfaces: &interface_samples,
                kinetic: &ke_of,
            }
        };
    }
    let mut out = output::Output::start(&octx, &mut loop_state!())?;
    if opts.output.restart.is_some() {
        // The interfaces' Idel state came with the restart file: the
        // elements it brings back deleted are known to them already.
        let _ = newly_deleted(&blocks, &contact);
        contact_force.clone_from(&fcont);
    }
    if let (Some(l), Some(p)) = (&mut listing, &opts.output.restart) {
        l.line(&format!(
            " restarted from {} at cycle {cycle}, time {t:e}",
            p.display()
        ));
    }
    let mut stopped: Option<String> = None;
    let loop_started = Instant::now();
    let mut energy_rows: Vec<[f64; 9]> = Vec::new();

    // ---- the cycle ----------------------------------------------------------
    let result: Result<(), RunError> = loop {
        if t >= tstop {
            break Ok(());
        }
        let dt_v = if cycle == 0 {
            0.5 * dt
        } else {
            0.5 * (dt_prev + dt)
        };
        // Tied interfaces: the secondary nodes' forces and moments go to their
        // main nodes (contact::interfaces::type2), summed in key order.
        if !ties.is_empty() {
            let f_of = |l: usize| {
                let mut f = [0.0; 6];
                for k in 0..3 {
                    f[k] = fext[l][k] - fint[l][k] + fcont[l][k];
                    f[3 + k] = fext[l][3 + k] - fint[l][3 + k];
                }
                f
            };
            ties.transfer(world, &x, &f_of, &mut ftie);
            for (smp, su) in interface_samples[n_contact..].iter_mut().zip(&ties.sums) {
                *smp = output::InterfaceSample {
                    tied_force: su.force,
                    tied_moment: su.moment,
                    ..Default::default()
                };
            }
        }
        // Accelerations and velocities at n+½.
        for l in 0..n {
            if is_main[l] {
                continue;
            }
            if mass[l] > 0.0 && !tied_tr[l] {
                for k in 0..3 {
                    if !fixed[l][k] {
                        v[l][k] +=
                            (fext[l][k] - fint[l][k] + fcont[l][k] + ftie[l][k]) / mass[l] * dt_v;
                    }
                }
            }
            if inertia[l] > 0.0 && !tied_rot[l] {
                for k in 0..3 {
                    if !fixed[l][3 + k] {
                        vr[l][k] +=
                            (fext[l][3 + k] - fint[l][3 + k] + ftie[l][3 + k]) / inertia[l] * dt_v;
                    }
                }
            }
        }
        // Rigid bodies: resultant of their nodes, gathered in global node order.
        if !local_bodies.is_empty() {
            let mine: Vec<Vec<NodeLoad>> = local_bodies
                .iter()
                .map(|lb| {
                    lb.members
                        .iter()
                        .filter(|(l, _)| owned[*l as usize])
                        .map(|&(l, gl)| {
                            let l = l as usize;
                            let f = [0, 1, 2].map(|k| fext[l][k] - fint[l][k] + fcont[l][k]);
                            let m = [0, 1, 2].map(|k| fext[l][3 + k] - fint[l][3 + k]);
                            NodeLoad {
                                node: gl,
                                f,
                                m,
                                x: x[l],
                            }
                        })
                        .collect()
                })
                .collect();
            let all = world.allgather(&mine);
            for (b, lb) in local_bodies.iter().enumerate() {
                let mut loads: Vec<NodeLoad> =
                    all.iter().flat_map(|r| r[b].iter().copied()).collect();
                let c_before = bodies[b].center;
                bodies[b].advance(&mut loads, [0.0; 3], dt_v, dt);
                for &(l, _) in &lb.members {
                    let l = l as usize;
                    v[l] = bodies[b].velocity_at(x[l], c_before);
                    if inertia[l] > 0.0 {
                        vr[l] = bodies[b].omega;
                    }
                }
                if let Some(l) = lb.main_local {
                    v[l as usize] = bodies[b].v;
                    vr[l as usize] = bodies[b].omega;
                }
                let _ = (lb.main_global, lb.main_mass);
            }
        }
        // Imposed velocities at t + ½Δt.
        let th = t + 0.5 * dt;
        let imposed = |c: &model::ImposedMotion, t: f64| {
            function::imposed_value(&g.functions[fct_index[&c.card.fct]], &c.card, t)
        };
        for (nodes, c) in &impvel {
            let Some(val) = imposed(c, th) else { continue };
            let d = c.card.dir.index();
            for &l in nodes {
                if d < 3 {
                    v[l as usize][d] = val;
                } else {
                    vr[l as usize][d - 3] = val;
                }
            }
        }
        // Imposed displacements: the velocity that reaches u(t + Δt) at the end of the step.
        for (nodes, c) in &impdisp {
            let Some(u) = imposed(c, t + dt) else {
                continue;
            };
            let d = c.card.dir.index();
            for &l in nodes {
                let l = l as usize;
                v[l][d] = (u - (x[l][d] - sd.x[l][d])) / dt;
            }
        }
        // Rigid walls.
        for (w, (nodes, wall)) in walls.iter().enumerate() {
            wall_force[w] = [0.0; 3];
            for c in &wall_driver[w] {
                if let Some(val) = imposed(c, th) {
                    wall_v[w][c.card.dir.index()] = val;
                }
            }
            let mut push: Vec<(u32, [f64; 3])> = Vec::new();
            for (i, &l) in nodes.iter().enumerate() {
                let l = l as usize;
                let (nv, now_tied, f) = wall_velocity(
                    x[l],
                    v[l],
                    mass[l],
                    dt,
                    wall_p[w],
                    wall.normal,
                    wall_v[w],
                    wall.card.slide,
                    wall.card.fric,
                    tied[w][i],
                );
                if owned[l] {
                    // Work of the wall's force on the node over the step,
                    // f·v·dt with f = m(v_after − v_before)/dt: zero for a fixed wall.
                    wall_work += mass[l]
                        * ((nv[0] - v[l][0]) * nv[0]
                            + (nv[1] - v[l][1]) * nv[1]
                            + (nv[2] - v[l][2]) * nv[2]);
                }
                v[l] = nv;
                tied[w][i] = now_tied;
                if owned[l] && f != [0.0; 3] {
                    push.push((sd.node_global[l], f));
                    for k in 0..3 {
                        wall_force[w][k] += f[k];
                    }
                }
            }
            if wall.node.is_some() && wall_driver[w].is_empty() && wall.card.mass > 0.0 {
                // Free moving wall: its mass takes the momentum the nodes lost.
                let mut all: Vec<(u32, [f64; 3])> =
                    world.allgather(&push).into_iter().flatten().collect();
                all.sort_by_key(|p| p.0);
                let mut f = [0.0; 3];
                for (_, fi) in &all {
                    for k in 0..3 {
                        f[k] += fi[k];
                    }
                }
                for k in 0..3 {
                    wall_v[w][k] += f[k] / wall.card.mass * dt;
                }
            }
            for k in 0..3 {
                wall_p[w][k] += wall_v[w][k] * dt;
            }
            if let Some(nd) = wall.node {
                if let Some(&l) = local_of.get(&nd) {
                    v[l as usize] = wall_v[w];
                }
            }
        }
        // Boundary conditions have the last word.
        for l in 0..n {
            for k in 0..3 {
                if fixed[l][k] {
                    v[l][k] = 0.0;
                }
                if fixed[l][3 + k] {
                    vr[l][k] = 0.0;
                }
            }
        }
        // Tied secondary nodes follow their main nodes (after every other condition).
        if !ties.is_empty() {
            ties.recover(world, &x, &mut v, &mut vr, dt);
        }
        // External work over the step, with the forces at n.
        for l in 0..n {
            if owned[l] {
                for k in 0..3 {
                    w_ext += fext[l][k] * v[l][k] * dt_v;
                    w_ext += fext[l][3 + k] * vr[l][k] * dt_v;
                    // Energy the contact forces take (elastic, damping, friction),
                    // with the mean of the velocities before and after the step:
                    // f·v_after alone overstates the work by (f·Δt)²/2M, which
                    // adds up when friction forces are large and their work small.
                    let dv = if fixed[l][k] || mass[l] <= 0.0 || tied_tr[l] {
                        0.0
                    } else {
                        (fext[l][k] - fint[l][k] + fcont[l][k] + ftie[l][k]) / mass[l] * dt_v
                    };
                    e_contact -= fcont[l][k] * (v[l][k] - 0.5 * dv) * dt_v;
                }
            }
        }
        // Positions at n+1.
        for l in 0..n {
            if is_main[l] {
                continue;
            }
            for k in 0..3 {
                x[l][k] += dt * v[l][k];
            }
        }
        for (b, lb) in local_bodies.iter().enumerate() {
            if let Some(l) = lb.main_local {
                x[l as usize] = bodies[b].center;
            }
        }
        // Tied secondary nodes: at their place on the moved segment.
        if !ties.is_empty() {
            ties.place(&mut x);
        }
        t += dt;
        cycle += 1;
        dt_prev = dt;
        if fault.is_some_and(|(r, c)| r == rank && c == cycle) {
            // Fault injection for the resilience tests: this rank dies abruptly.
            eprintln!("crashsim: rank {rank}: CRASHSIM_FAULT: aborting at cycle {cycle}");
            std::process::abort();
        }
        // Non-finite state: name the node (reported with the element problems,
        // collectively, so that every rank stops at the same cycle).
        let nan_msg = (0..n)
            .find(|&l| {
                !(x[l]
                    .iter()
                    .chain(&v[l])
                    .chain(&vr[l])
                    .all(|c| c.is_finite()))
            })
            .map(|l| {
                format!(
                    "node {} has a non-finite position or velocity at cycle {cycle}, time {t:e}",
                    g.node_ids[sd.node_global[l] as usize]
                )
            });
        // Forces at n+1.
        let stop = compute_all(&mut blocks, &offsets, &x, &v, &vr, dt, &mut contrib);
        plan.assemble(world, &contrib, &mut fint);
        external_forces(&g, &fct_index, &cloads, &gravity, &grav_mass, t, &mut fext);
        let dead = newly_deleted(&blocks, &contact);
        let cstep = contact_forces(&mut contact, &x, &v, t, dt, &mut fcont, &mut fixed, &dead);
        // Idel: segments and nodes the interfaces removed at this cycle.
        if let Some(l) = &mut listing {
            for r in contact.removed() {
                l.line(&format!(
                    "     IDEL INTER {:>8} TYPE{:<2} CYCLE {:>8} TIME {:>12.5E}  REMOVED {:>6} MAIN SEGMENTS {:>6} SECONDARY NODES  (TOTAL {} SEGMENTS {} NODES, Idel = {})",
                    r.inter_id, r.type_number, cycle, t, r.segments, r.nodes, r.segments_total, r.nodes_total, r.idel
                ));
            }
        }
        if !contact.is_empty() {
            contact_force.clone_from(&fcont);
            for (smp, su) in interface_samples.iter_mut().zip(&contact.sums) {
                *smp = output::InterfaceSample {
                    normal: su.f_normal,
                    tangential: su.f_tangent,
                    energy: su.energy,
                    ..Default::default()
                };
            }
        }
        step = match global_step(
            world,
            &g,
            &blocks,
            engine.dt_scale,
            stop,
            nan_msg,
            cstep,
            cycle,
            t,
        ) {
            Ok(s) => s,
            Err(e) => break Err(e),
        };
        dt = step.dt;
        if t >= next_th {
            sample(t, &x, &mut history);
            while next_th <= t {
                next_th += th_period;
            }
        }
        if engine.dt_min > 0.0 && dt < engine.dt_min {
            break Err(RunError::Physics(format!(
                "time step {dt:e} set by {} {} is below the /DT minimum {:e} at cycle {cycle}, time {t:e}",
                step.what, step.id, engine.dt_min
            )));
        }
        // The global energies (one all-reduce), at the cycles the --energies
        // CSV or the listing wants them.
        let print_now = cycle % print_every == 0 || t >= tstop;
        let energies_now = (opts.energies.is_some() || print_now).then(|| {
            let mut e = [
                blocks.iter().map(|b| b.energy()).sum::<f64>(),
                blocks.iter().map(|b| b.energy_parts().0).sum::<f64>(),
                w_ext,
                e_contact,
            ];
            world.sum_f64(&mut e);
            let (ke, ker) = kinetic(
                world,
                &v,
                &vr,
                &mass,
                &inertia_ke,
                &owned,
                &ke_skip,
                &bodies,
                &local_bodies,
            );
            (e, ke, ker)
        });
        if let (Some(_), Some((e, ke, ker))) = (&opts.energies, energies_now) {
            energy_rows.push([t, cycle as f64, dt, e[0] - e[1], ke, ker, e[2], e[3], e[1]]);
        }
        if let (true, Some((e, ke, ker))) = (print_now, energies_now) {
            emit(
                &mut listing,
                cycle,
                t,
                dt,
                &step,
                e[0] - e[1],
                e[1],
                ke,
                ker,
                e[2],
                e[3],
            );
            // Contact force resultants per interface (secondary side).
            if !contact.is_empty() {
                let mut r: Vec<f64> = contact
                    .sums
                    .iter()
                    .flat_map(|s| {
                        [
                            s.f_normal[0],
                            s.f_normal[1],
                            s.f_normal[2],
                            s.f_tangent[0],
                            s.f_tangent[1],
                            s.f_tangent[2],
                            s.pairs as f64,
                        ]
                    })
                    .collect();
                world.sum_f64(&mut r);
                if let Some(l) = &mut listing {
                    for (i, it) in contact.setup.interfaces.iter().enumerate() {
                        let q = &r[7 * i..7 * i + 7];
                        l.line(&format!(
                            "     INTER {:>8} TYPE{:<2} NORMAL FORCE {:>12.5E} {:>12.5E} {:>12.5E}  TANGENT {:>12.5E} {:>12.5E} {:>12.5E}  PAIRS {:>6}",
                            it.id, it.type_number, q[0], q[1], q[2], q[3], q[4], q[5], q[6] as u64
                        ));
                    }
                }
            }
        }
        // Tied interfaces: what the secondary nodes passed to their main nodes.
        if !ties.is_empty() && print_now {
            let mut r: Vec<f64> = ties
                .sums
                .iter()
                .flat_map(|s| {
                    [
                        s.tied as f64,
                        s.force[0],
                        s.force[1],
                        s.force[2],
                        s.moment[0],
                        s.moment[1],
                        s.moment[2],
                    ]
                })
                .collect();
            world.sum_f64(&mut r);
            if let Some(l) = &mut listing {
                for (i, it) in ties.setup.interfaces.iter().enumerate() {
                    let q = &r[7 * i..7 * i + 7];
                    l.line(&format!(
                        "     INTER {:>8} TYPE2  TIED NODES {:>6}  FORCE {:>12.5E} {:>12.5E} {:>12.5E}  MOMENT {:>12.5E} {:>12.5E} {:>12.5E}",
                        it.id, q[0] as u64, q[1], q[2], q[3], q[4], q[5], q[6]
                    ));
                }
            }
        }
        // Output hook: histories, states, restart files, progress, stop requests.
        match out.after_cycle(&octx, &mut loop_state!()) {
            Ok(None) => {}
            Ok(Some(msg)) => {
                stopped = Some(msg);
                break Ok(());
            }
            Err(e) => break Err(e),
        }
    };
    // Output hook: last state and samples, XDMF (collective, also after a stop).
    let result = match (result, out.finish(&octx, &mut loop_state!())) {
        (Ok(()), Err(e)) => Err(e),
        (r, _) => r,
    };
    let elapsed = started.elapsed().as_secs_f64();
    let looped = loop_started.elapsed().as_secs_f64();
    // Energy breakdown (collective: every rank takes part, even after a stop).
    let final_energies = {
        let mut e = [0.0f64; 6];
        for b in &blocks {
            let (hg, pl) = b.energy_parts();
            e[0] += b.energy();
            e[1] += hg;
            e[2] += pl;
        }
        e[3] = w_ext;
        e[4] = wall_work;
        e[5] = e_contact;
        world.sum_f64(&mut e);
        let (ke, ker) = kinetic(
            world,
            &v,
            &vr,
            &mass,
            &inertia_ke,
            &owned,
            &ke_skip,
            &bodies,
            &local_bodies,
        );
        Some([e[0], e[1], e[2], ke, ker, e[3], e[4], e[5]])
    };
    // Contact timers of rank 0 per secondary node-cycle (all ranks' secondary nodes).
    let contact_timing = if contact.is_empty() {
        None
    } else {
        let mut nsec = [contact.owned_secondary() as f64];
        world.sum_f64(&mut nsec);
        let tm = contact.timers;
        let per = |s: f64| 1e6 * s / (cycle.max(1) as f64 * nsec[0].max(1.0));
        Some((
            tm.sorts,
            nsec[0] as u64,
            per(tm.search_s),
            per(tm.force_s),
            per(tm.exchange_s),
        ))
    };
    if let Some(l) = &mut listing {
        l.line("");
        match &result {
            Ok(()) => l.line(stopped.as_deref().unwrap_or("     NORMAL TERMINATION")),
            Err(e) => l.line(&format!("     ERROR TERMINATION: {}", e.message())),
        }
        l.line(&format!("     TOTAL NUMBER OF CYCLES  : {cycle:>10}"));
        if !contact.is_empty() {
            // The sort decision is collective: every rank sorts as often.
            l.line(&format!(
                "     CONTACT SORTS           : {:>10}",
                contact.timers.sorts
            ));
        }
        if let Some(e) = &final_energies {
            l.line(&format!("     ENERGIES AT THE END     : internal {:.6E} (hourglass {:.6E} included, plastic work {:.6E}), kinetic {:.6E} + rotational {:.6E}", e[0], e[1], e[2], e[3], e[4]));
            l.line(&format!(
                "                               external work {:.6E}, rigid-wall work {:.6E}, contact energy {:.6E}",
                e[5], e[6], e[7]
            ));
        }
        if let Some(c) = &contact_timing {
            l.line(&format!(
                "     CONTACT                 : {} sorts, {} secondary nodes, {:.4} µs search + {:.4} µs forces + {:.4} µs exchange per secondary node-cycle (rank 0)",
                c.0, c.1, c.2, c.3, c.4
            ));
        }
        l.line(&format!("     ELAPSED TIME            : {elapsed:>10.3} s   (set-up {:.3} s, cycles {looped:.3} s)", elapsed - looped));
        l.line(&format!("     OUTPUT TIME             : {:>10.3} s   (HDF5 run file, time histories, restart files; rank 0; CPU {:.4} s)", out.seconds(), out.cpu_seconds()));
        let elems = g.element_ids.iter().map(|e| e.len()).sum::<usize>().max(1);
        l.line(&format!(
            "     TIME PER CYCLE          : {:>10.3} µs   ({:.4} µs per element-cycle)",
            1e6 * looped / cycle.max(1) as f64,
            1e6 * looped / (cycle.max(1) as f64 * elems as f64)
        ));
        l.flush();
    }
    if let Some(path) = &opts.final_state {
        write_final_state(world, &g, &sd, &owned, &x, &v, &vr, path)?;
    }
    if let Some(path) = &opts.final_elements {
        write_final_elements(world, &g, &blocks, path)?;
    }
    if let (Some(path), 0) = (&opts.energies, rank) {
        let mut s = String::from(
            "time,cycle,dt,internal,kinetic,rotational,external_work,contact,hourglass\n",
        );
        for r in &energy_rows {
            s.push_str(&format!(
                "{:.16e},{},{:.16e},{:.16e},{:.16e},{:.16e},{:.16e},{:.16e},{:.16e}\n",
                r[0], r[1] as u64, r[2], r[3], r[4], r[5], r[6], r[7], r[8]
            ));
        }
        std::fs::write(path, s).map_err(|e| {
            RunError::Input(format!(
                "{}: cannot write the energies: {e}",
                path.display()
            ))
        })?;
    }
    if let (Some(path), 0) = (&opts.history, rank) {
        let mut s = String::from("time");
        for &gn in &g.th_nodes {
            let id = g.node_ids[gn as usize];
            s.push_str(&format!(",dx_{id},dy_{id},dz_{id}"));
        }
        s.push('\n');
        for (t, d) in &history {
            s.push_str(&format!("{t:.16e}"));
            for u in d {
                s.push_str(&format!(",{:.16e},{:.16e},{:.16e}", u[0], u[1], u[2]));
            }
            s.push('\n');
        }
        std::fs::write(path, s).map_err(|e| {
            RunError::Input(format!("{}: cannot write the history: {e}", path.display()))
        })?;
    }
    result
}

fn main_node_mass(sd: &Subdomain, main_local: Option<u32>) -> f64 {
    main_local.map(|l| sd.mass[l as usize]).unwrap_or(0.0)
}

/// Runs every block; returns the first stopping problem (kind, global element index, what).
fn compute_all(
    blocks: &mut [Box<dyn Block>],
    offsets: &[usize],
    x: &[[f64; 3]],
    v: &[[f64; 3]],
    vr: &[[f64; 3]],
    dt: f64,
    contrib: &mut [[f64; SLOT]],
) -> Option<(ElementKind, u32, &'static str)> {
    let mut problem = None;
    for (i, b) in blocks.iter_mut().enumerate() {
        b.compute(x, v, vr, dt, &mut contrib[offsets[i]..offsets[i + 1]]);
        if let Some((ge, what)) = b.settle() {
            problem.get_or_insert((b.kind(), ge, what));
        }
    }
    problem
}

/// The listing's name of an element kind.
fn kind_name(k: ElementKind) -> &'static str {
    match k {
        ElementKind::Shell4 => "SHELL",
        ElementKind::Shell3 => "SH3N",
        ElementKind::Brick8 => "BRICK",
        ElementKind::Tetra4 => "TETRA4",
        ElementKind::Spring => "SPRING",
        ElementKind::Truss => "TRUSS",
        ElementKind::Beam => "BEAM",
    }
}

/// The global time step and what set it.
struct Step {
    dt: f64,
    what: &'static str,
    id: u64,
}

/// Global minimum of the scaled element time steps (ties: smallest kind, then id),
/// and a collective stop if any rank met a problem.
#[allow(clippy::too_many_arguments)]
fn global_step(
    world: &World,
    g: &GlobalData,
    blocks: &[Box<dyn Block>],
    scale: f64,
    problem: Option<(ElementKind, u32, &'static str)>,
    node_problem: Option<String>,
    contact: Option<ContactStep>,
    cycle: u64,
    t: f64,
) -> Result<Step, RunError> {
    let kind_index = |k: ElementKind| {
        crate::model::ElementKind::ALL
            .iter()
            .position(|&q| q == k)
            .unwrap()
    };
    let mut best = (f64::INFINITY, usize::MAX, u64::MAX);
    for b in blocks {
        let ki = kind_index(b.kind());
        let le = b.local();
        for (e, st) in b.steps().iter().enumerate() {
            if b.alive(e) {
                let id = g.element_ids[ki][le.global[e] as usize];
                let cand = (st.dt, ki, id);
                if cand.0 < best.0 || (cand.0 == best.0 && (cand.1, cand.2) < (best.1, best.2)) {
                    best = cand;
                }
            }
        }
    }
    let prob = problem.map(|(k, ge, m)| {
        format!(
            "{} {} {m} at cycle {cycle}, time {t:e}",
            kind_name(k),
            g.element_ids[kind_index(k)][ge as usize]
        )
    });
    let prob = node_problem.or(prob);
    let cs = contact.unwrap_or(ContactStep {
        kin_dt: f64::INFINITY,
        ..Default::default()
    });
    let all: Vec<(f64, usize, u64, Option<String>, ContactStep)> =
        world.allgather(&(best.0, best.1, best.2, prob, cs));
    if let Some(m) = all.iter().find_map(|(_, _, _, p, _)| p.clone()) {
        return Err(RunError::Physics(m));
    }
    let (d, ki, id) = all.iter().fold(
        (f64::INFINITY, usize::MAX, u64::MAX),
        |acc, &(d, k, id, _, _)| {
            if d < acc.0 || (d == acc.0 && (k, id) < (acc.1, acc.2)) {
                (d, k, id)
            } else {
                acc
            }
        },
    );
    if !d.is_finite() {
        return Err(RunError::Physics(format!(
            "no element left to set the time step at cycle {cycle}, time {t:e}"
        )));
    }
    // Contact (EQ. 8.8.5.1–2): nodes held by their elements and contact springs
    // together, Δt = 1/√(1/Δt_el² + max K/(2M)); then the kinematic step.
    // Ties: the smallest node / interface id.
    let (mut q, mut qid) = (0.0f64, 0u64);
    let (mut kin, mut kid) = (f64::INFINITY, 0u64);
    for (_, _, _, _, c) in &all {
        if c.nodal_q > q || (c.nodal_q == q && q > 0.0 && c.node_id < qid) {
            q = c.nodal_q;
            qid = c.node_id;
        }
        if c.kin_dt < kin || (c.kin_dt == kin && c.inter_id < kid) {
            kin = c.kin_dt;
            kid = c.inter_id;
        }
    }
    let mut step = Step {
        dt: d,
        what: kind_name(crate::model::ElementKind::ALL[ki]),
        id,
    };
    if q > 0.0 {
        let combined = 1.0 / (1.0 / (d * d) + q).sqrt();
        // Named after the node once contact costs more than 1% of the step.
        if combined < 0.99 * d {
            step = Step {
                dt: combined,
                what: "NODE",
                id: qid,
            };
        } else {
            step.dt = combined;
        }
    }
    if kin < step.dt {
        step = Step {
            dt: kin,
            what: "INTER",
            id: kid,
        };
    }
    step.dt *= scale;
    Ok(step)
}

/// Concentrated loads and gravity at time t, per local node (force, moment).
fn external_forces(
    g: &GlobalData,
    fct: &HashMap<u64, usize>,
    cloads: &[(Vec<u32>, &model::ConcentratedLoad)],
    gravity: &[(Vec<u32>, &model::Gravity)],
    mass: &[f64],
    t: f64,
    fext: &mut [[f64; SLOT]],
) {
    for f in fext.iter_mut() {
        *f = [0.0; SLOT];
    }
    for (nodes, c) in cloads {
        let val = function::scaled(
            &g.functions[fct[&c.card.fct]],
            t,
            c.card.ascale_x,
            c.card.fscale_y,
        );
        let d = c.card.dir.index();
        for &l in nodes {
            fext[l as usize][d] += val;
        }
    }
    for (nodes, c) in gravity {
        let acc = if c.card.fct == 0 {
            c.card.fscale_y
        } else {
            function::scaled(
                &g.functions[fct[&c.card.fct]],
                t,
                c.card.ascale_x,
                c.card.fscale_y,
            )
        };
        let d = match c.card.dir {
            Dof::X | Dof::Xx => 0,
            Dof::Y | Dof::Yy => 1,
            Dof::Z | Dof::Zz => 2,
        };
        for &l in nodes {
            fext[l as usize][d] += mass[l as usize] * acc;
        }
    }
}

/// Translational and rotational kinetic energy (owned nodes, rigid-body main masses once).
#[allow(clippy::too_many_arguments)]
fn kinetic(
    world: &World,
    v: &[[f64; 3]],
    vr: &[[f64; 3]],
    mass: &[f64],
    inertia: &[f64],
    owned: &[bool],
    is_main: &[bool], // skip the translational energy (rigid-body main nodes, tied secondary nodes)
    bodies: &[RigidBodyState],
    local: &[LocalBody],
) -> (f64, f64) {
    let mut e = [0.0f64; 2];
    for l in 0..v.len() {
        if owned[l] && !is_main[l] {
            e[0] += 0.5 * mass[l] * (v[l][0] * v[l][0] + v[l][1] * v[l][1] + v[l][2] * v[l][2]);
        }
        if owned[l] {
            e[1] += 0.5
                * inertia[l]
                * (vr[l][0] * vr[l][0] + vr[l][1] * vr[l][1] + vr[l][2] * vr[l][2]);
        }
    }
    for (b, lb) in local.iter().enumerate() {
        if lb.main_local.is_some() {
            let vb = bodies[b].v;
            e[0] += 0.5 * lb.main_mass * (vb[0] * vb[0] + vb[1] * vb[1] + vb[2] * vb[2]);
        }
    }
    world.sum_f64(&mut e);
    (e[0], e[1])
}

/// One CSV row per node in global id order: id, x, y, z, vx, vy, vz, vrx, vry, vrz (17 significant digits).
#[allow(clippy::too_many_arguments)]
fn write_final_state(
    world: &World,
    g: &GlobalData,
    sd: &Subdomain,
    owned: &[bool],
    x: &[[f64; 3]],
    v: &[[f64; 3]],
    vr: &[[f64; 3]],
    path: &Path,
) -> Result<(), RunError> {
    let mine: Vec<(u32, [f64; 9])> = (0..x.len())
        .filter(|&l| owned[l])
        .map(|l| {
            (
                sd.node_global[l],
                [
                    x[l][0], x[l][1], x[l][2], v[l][0], v[l][1], v[l][2], vr[l][0], vr[l][1],
                    vr[l][2],
                ],
            )
        })
        .collect();
    let all = world.allgather(&mine);
    if world.rank() != 0 {
        return Ok(());
    }
    let mut rows: Vec<(u32, [f64; 9])> = all.into_iter().flatten().collect();
    rows.sort_by_key(|r| r.0);
    let mut s = String::from("id,x,y,z,vx,vy,vz,vrx,vry,vrz\n");
    for (gn, vals) in rows {
        s.push_str(&g.node_ids[gn as usize].to_string());
        for val in vals {
            s.push_str(&format!(",{val:.16e}"));
        }
        s.push('\n');
    }
    std::fs::write(path, s).map_err(|e| {
        RunError::Input(format!(
            "{}: cannot write the final state: {e}",
            path.display()
        ))
    })
}

/// One CSV row per element in global order (kind, then id): mean membrane
/// stress over the integration points (shells: local frame sxx, syy, sxy;
/// solids: sxx, syy, sxy; springs: the force in sxx), largest plastic strain,
/// thickness, internal energy (with hourglass), deleted flag.
fn write_final_elements(
    world: &World,
    g: &GlobalData,
    blocks: &[Box<dyn Block>],
    path: &Path,
) -> Result<(), RunError> {
    let kind_index = |k: ElementKind| {
        crate::model::ElementKind::ALL
            .iter()
            .position(|&q| q == k)
            .unwrap()
    };
    let mine: Vec<(usize, u32, [f64; 7])> = blocks
        .iter()
        .flat_map(|b| {
            let ki = kind_index(b.kind());
            b.rows().into_iter().map(move |(ge, v)| (ki, ge, v))
        })
        .collect();
    let all = world.allgather(&mine);
    if world.rank() != 0 {
        return Ok(());
    }
    let mut rows: Vec<(usize, u32, [f64; 7])> = all.into_iter().flatten().collect();
    rows.sort_by_key(|r| (r.0, r.1));
    let mut s = String::from("kind,id,sxx,syy,sxy,eps_p,thick,eint,deleted\n");
    for (ki, ge, v) in rows {
        s.push_str(&format!(
            "{},{}",
            kind_name(crate::model::ElementKind::ALL[ki]),
            g.element_ids[ki][ge as usize]
        ));
        for val in &v[..6] {
            s.push_str(&format!(",{val:.16e}"));
        }
        s.push_str(&format!(",{}\n", v[6] as u8));
    }
    std::fs::write(path, s).map_err(|e| {
        RunError::Input(format!(
            "{}: cannot write the element state: {e}",
            path.display()
        ))
    })
}
