//! Rank 0's set-up before the scatter: the deck read and checked, the model
//! built (and built again after /INTER/TYPE7 Inacti = 3), partitioned, the
//! replicated data and the listing's notes.

use super::RunOptions;
use crate::domain::{self, Subdomain};
use crate::global::GlobalData;
use crate::input::{self, Input, InputOptions};
use crate::kinematics::rigid_body::RigidBodyState;
use crate::model::{self, ElementKind, Model};

/// What rank 0 prepares: the shared data and one subdomain per rank.
pub(super) type Prepared = (GlobalData, Vec<Subdomain>, Vec<RigidBodyState>, Vec<String>);

pub(super) fn prepare(opts: &RunOptions, nranks: usize) -> Result<Prepared, String> {
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
    let skipped = unsupported_keywords(&m, opts)?;
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
    g.skipped_keywords = skipped;
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
    let mut notes: Vec<String> = g
        .skipped_keywords
        .iter()
        .map(|k| format!("skipped (--skip-unsupported): {k}"))
        .collect();
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
    notes.extend(
        m.notes
            .iter()
            .map(|w| format!("{}: {}: {}", w.loc, w.keyword, w.message)),
    );
    // N = 0 with a law the reference engine does not integrate globally.
    let mut seen = std::collections::BTreeSet::new();
    for part in &m.parts {
        let (Some(ip), Some(im)) = (part.prop, part.mat) else {
            continue;
        };
        let p = &m.properties[ip as usize];
        let Some(n) = p.shell.as_ref().map(|s| s.n) else {
            continue;
        };
        let mat = crate::material::Material::from_card(&m.materials[im as usize]);
        if n >= 2 && !mat.is_plastic() && seen.insert((ip, im)) {
            notes.push(format!("{}: /PROP/{}: N = {n} with the elastic /MAT/{} is computed with {n} integration points through the thickness; the reference starter switches an elastic section to global integration N = 0 (its WARNING 1084): the same membrane and bending stiffness, to round-off", p.card.loc, p.card.id, m.materials[im as usize].id));
        }
        if n != 0 {
            continue;
        }
        if let crate::element::shell4::N0Rule::Points(n) = crate::element::shell4::n0_rule(&mat) {
            if seen.insert((ip, im)) {
                notes.push(format!("{}: /PROP/{}: N = 0 (global integration) with /MAT/{} (LAW2) is computed with N = {n} integration points, as the reference engine does (its starter WARNING 1912)", p.card.loc, p.card.id, m.materials[im as usize].id));
            }
        }
    }
    Ok((g, sds, rbs, notes))
}

/// The keyword policy (deck::keyword_policy): keywords nothing computes stop
/// the run before any cycle, every one named with its file:line; with
/// `--skip-unsupported` they are skipped and returned, for the listing and the run file.
fn unsupported_keywords(m: &Model, opts: &RunOptions) -> Result<Vec<String>, String> {
    let named: Vec<String> = m
        .unsupported
        .iter()
        .map(|w| format!("{}: {}", w.loc, w.keyword))
        .collect();
    if named.is_empty() || opts.skip_unsupported {
        return Ok(named);
    }
    Err(format!(
        "{}: {} keyword(s) of this input are not computed by the engine, so it does not run (`run --skip-unsupported` runs without them and says so in the listing):\n  {}",
        opts.deck.display(),
        named.len(),
        named.join("\n  ")
    ))
}

/// The engine refuses what it does not compute yet, by name — never a silent substitute.
fn check_supported(m: &Model) -> Result<(), String> {
    if let Some(loc) = m.engine.as_ref().and_then(|e| e.brick_cst.as_ref()) {
        let solids = m
            .elements
            .iter()
            .filter(|s| matches!(s.kind, ElementKind::Brick8 | ElementKind::Tetra4))
            .map(|s| s.len())
            .sum::<usize>();
        if solids > 0 {
            return Err(format!(
                "{loc}: /DT/BRICK/CST: the mass scaling of the model's {solids} solid elements is not computed yet"
            ));
        }
    }
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
            crate::element::blocks::make_block(
                &le,
                &m.nodes.x,
                &m.nodal_mass,
                &m.parts,
                &m.properties,
                &m.materials,
                &m.functions,
                crate::element::blocks::BlockContext {
                    rigid_bodies: &m.rigid_bodies,
                    node_global: &[],
                    dt_max: m.engine.as_ref().map_or(0.0, |e| e.dtix.1),
                },
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
    for c in &m.dampings {
        if c.card.skew_id != 0 {
            return unsupported("/DAMP with a skew system", &c.card.loc);
        }
    }
    for (id, loc) in m.engine.iter().flat_map(|e| &e.rbody_on) {
        if !m.rigid_bodies.iter().any(|r| r.card.id as i64 == *id) {
            return Err(format!(
                "{loc}: /RBODY/ON: rigid body {id} is not defined in the starter deck"
            ));
        }
    }
    for o in m.engine.iter().flat_map(|e| &e.dampings) {
        if !m.dampings.iter().any(|d| d.card.id == o.id) {
            return Err(format!(
                "{}: /DAMP/{}: no starter /DAMP has this id (the engine file changes the coefficients of a starter /DAMP)",
                o.loc, o.id
            ));
        }
    }
    let mut damped = std::collections::HashMap::new();
    for c in &m.dampings {
        for &n in &c.nodes {
            if let Some(first) = damped.insert(n, c.card.id) {
                return Err(format!(
                    "{}: /DAMP/{}: node {} is in /DAMP/{first} too: a node takes one /DAMP",
                    c.card.loc, c.card.id, m.nodes.ids[n as usize]
                ));
            }
        }
    }
    for r in &m.rigid_bodies {
        if r.card.sens_id != 0 || r.card.skew_id != 0 || r.card.ikrem != 0 {
            return unsupported("/RBODY with a sensor, skew or IKREM", &r.card.loc);
        }
        // surf_ID: the hyper-ellipsoid the body carries (TYPE14).
        let ellipsoid = |id| {
            m.surfaces
                .iter()
                .any(|s| s.id == id && s.ellipsoid.is_some())
        };
        if r.card.surf_id != 0 && !ellipsoid(r.card.surf_id) {
            return unsupported(
                "/RBODY with a surface (surf_ID) other than a /SURF/ELLIPS",
                &r.card.loc,
            );
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
            // kinematic formulation and Spotflag 4, translations only, are the
            // ones computed (contact::interfaces::type2).
            let fo = |field: &str, what: &str| {
                Err(format!(
                    "{kw}, field {field}: {what} is not supported by the engine yet"
                ))
            };
            match t.spotflag {
                4 | 5 => {}
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
        // The registered types say which of their options they refuse
        // (contact::interfaces); a type not registered is refused whole.
        _ => match crate::contact::interfaces::TypeOptions::check_card(&c.kind) {
            Ok(()) => Ok(()),
            Err(Some(what)) => no(what),
            Err(None) => no(&format!("TYPE{} ({})", c.type_number(), c.description())),
        },
    }
}

/// Rigid bodies at t = 0: mass, centre, inertia from the model; velocity the
/// mass-weighted mean of its nodes' initial velocities (all /INIVEL/TRA),
/// spin from their angular momentum — unless the main node has its own
/// /INIVEL/TRA or /INIVEL/ROT: the body then takes that velocity or spin,
/// as the reference does (QA RESSORT_kjoint2: a spin on the main node alone
/// gives the body ½·I·ω² of K-ENERGY R with I the body's inertia).
pub(super) fn initial_rigid_bodies(m: &Model) -> Vec<RigidBodyState> {
    let mut v0 = vec![[0.0; 3]; m.nodes.len()];
    let mut w0 = vec![[0.0; 3]; m.nodes.len()];
    let mut given = vec![[false; 2]; m.nodes.len()];
    for iv in &m.initial_velocities {
        let to = if iv.card.rotational { &mut w0 } else { &mut v0 };
        for &n in &iv.nodes {
            to[n as usize] = iv.card.v;
            given[n as usize][usize::from(iv.card.rotational)] = true;
        }
    }
    m.rigid_bodies
        .iter()
        .map(|rb| {
            // The body starts with its nodes' momentum and angular momentum
            // about its centre (the main node carries the card's mass and
            // inertia).
            let (mut p, mut l) = ([0.0; 3], [0.0; 3]);
            let main = rb.main_node as usize;
            let jc = rb.card.inertia;
            let wm = w0[main];
            for k in 0..3 {
                l[k] += jc[k] * wm[k];
            }
            // Off-diagonal card terms (Jxy, Jyz, Jxz) on the main node's spin.
            l[0] += jc[3] * wm[1] + jc[5] * wm[2];
            l[1] += jc[3] * wm[0] + jc[4] * wm[2];
            l[2] += jc[5] * wm[0] + jc[4] * wm[1];
            let nodes = std::iter::once((main, rb.card.mass + m.nodal_mass[main])).chain(
                rb.secondary_nodes
                    .iter()
                    .map(|&n| (n as usize, m.nodal_mass[n as usize])),
            );
            for (n, mn) in nodes {
                let r = crate::vec3::sub(m.nodes.x[n], rb.center);
                let rxv = crate::vec3::cross(r, v0[n]);
                for k in 0..3 {
                    p[k] += mn * v0[n][k];
                    l[k] += mn * rxv[k] + m.nodal_inertia[n] * w0[n][k];
                }
            }
            let v = if given[main][0] {
                v0[main]
            } else if rb.mass > 0.0 {
                [p[0] / rb.mass, p[1] / rb.mass, p[2] / rb.mass]
            } else {
                [0.0; 3]
            };
            let omega = if given[main][1] {
                wm
            } else {
                RigidBodyState::spin_of(&rb.inertia, l)
            };
            RigidBodyState::new(rb.card.id, rb.mass, rb.center, rb.inertia, v, omega)
        })
        .collect()
}
