//! `build_model`: Deck → Model. Resolves every id (an unknown one is an
//! error at the card that names it), applies defaults, computes masses.
//! The steps run in a fixed order (nodes, parts, elements, groups,
//! conditions, rigid walls, interfaces, masses, rigid bodies): the first
//! error met is the one reported.

use super::id_index::IdIndex;
use super::resolve_sets::{node_groups, shell_groups, surfaces, SetContext};
use super::{Deck, ElementCard, Elements};
use crate::model::contact::{Type19, Type25};
use crate::model::*;

/// Builds the model from a deck.
pub fn build_model(deck: &Deck) -> Result<Model, InputError> {
    build(deck).map_err(|e| name_unsupported_definition(e, deck))
}

/// An id that no card defines ([`IdIndex::resolve`]: "WHAT ID is not defined
/// in the deck") but a keyword of its family that is not supported would
/// (`/GRNOD/GRSHEL/5` for node group 5): the error names that keyword, so
/// that the deck is refused by the feature's name, not by a dangling id.
fn name_unsupported_definition(mut e: InputError, deck: &Deck) -> InputError {
    // "node group" before "node": the first matching prefix decides.
    const FAMILIES: &[(&str, &str)] = &[
        ("node group", "/GRNOD"),
        ("shell group", "/GRSHEL"),
        ("surface", "/SURF"),
        ("function", "/FUNCT"),
        ("material", "/MAT"),
        ("property", "/PROP"),
        ("part", "/PART"),
        ("interface", "/INTER"),
        ("node", "/NODE"),
    ];
    if e.message.contains("defines it") {
        return e;
    }
    let found = FAMILIES.iter().find_map(|(what, family)| {
        let id = e
            .message
            .strip_prefix(what)?
            .strip_suffix(" is not defined in the deck")?
            .trim();
        Some((*family, id.to_string()))
    });
    if let Some((family, id)) = found {
        let defines = |w: &&Warning| {
            w.keyword.starts_with(family)
                && w.keyword.rsplit('/').next().map(str::trim) == Some(id.as_str())
        };
        if let Some(w) = deck.unsupported.iter().find(defines) {
            e.message = format!(
                "{}; {} at {} defines it but that keyword is not supported",
                e.message, w.keyword, w.loc
            );
        }
    }
    e
}

fn build(deck: &Deck) -> Result<Model, InputError> {
    let begin = deck.begin.clone().ok_or_else(|| {
        InputError::new(
            Loc {
                file: deck.path.clone(),
                line: 0,
            },
            "/BEGIN",
            "",
            "no /BEGIN block",
        )
    })?;
    let mut warnings = deck.warnings.clone();
    let (mut nodes, node_index) = read_nodes(deck, &begin)?;
    let (part_index, properties, parts) = read_parts(deck)?;
    let (elements, element_locs, shell4_index) =
        read_elements(deck, &node_index, &part_index, &parts, &properties)?;

    // Sets.
    // Groups select by box on the positions as read (before /RANDOM).
    let x_read = nodes.x.clone();
    let (boxes, box_index) = super::boxes::resolve_boxes(deck, &node_index, &x_read)?;
    let ctx = SetContext {
        x: &x_read,
        boxes: (&boxes, &box_index),
        nodes: &node_index,
        parts: &part_index,
        shells4: &shell4_index,
        elements: &elements,
        surfaces: None,
        shell_groups: None,
    };
    let shell_groups = shell_groups(&deck.shell_groups, &ctx)?;
    let surfaces = surfaces(&deck.surfaces, &shell_groups, &deck.shell_groups, &ctx)?;
    let surf_index = IdIndex::build(
        "surface",
        deck.surfaces.iter().map(|s| (s.id, s.loc.clone())),
        "/SURF",
    )?;
    let grshel_index = IdIndex::build(
        "shell group",
        deck.shell_groups.iter().map(|g| (g.id, g.loc.clone())),
        "/GRSHEL",
    )?;
    let ctx = SetContext {
        surfaces: Some((&surfaces, &surf_index)),
        shell_groups: Some((&shell_groups, &grshel_index)),
        ..ctx
    };
    let node_groups = node_groups(&deck.node_groups, &ctx)?;
    let refs = Refs {
        node_groups: &node_groups,
        grnod_index: IdIndex::build(
            "node group",
            deck.node_groups.iter().map(|g| (g.id, g.loc.clone())),
            "/GRNOD",
        )?,
        surf_index: IdIndex::build(
            "surface",
            deck.surfaces.iter().map(|s| (s.id, s.loc.clone())),
            "/SURF",
        )?,
        fct_index: IdIndex::build(
            "function",
            deck.functions.iter().map(|f| (f.id, f.loc.clone())),
            "/FUNCT",
        )?,
    };

    let reading_order: Vec<u32> = deck
        .nodes
        .iter()
        .filter_map(|n| node_index.get(n.id))
        .collect();
    super::random_noise::perturb(
        &deck.random_noises,
        &reading_order,
        |id, loc| refs.group(id, loc, "/RANDOM/GRNOD", "grnd_ID"),
        &mut nodes.x,
    )?;
    let conditions = read_conditions(deck, &refs, nodes.len())?;
    refs.check_spring_functions(&properties)?;
    for c in &deck.interfaces {
        let kw = format!("/INTER/TYPE{}/{}", c.type_number(), c.id);
        for (f, field) in c.functions() {
            refs.check_fct(f, &c.loc, &kw, field)?;
        }
    }
    let rigid_walls = read_rigid_walls(deck, &refs, &nodes, &node_index, &mut warnings)?;
    let lines = super::lines::resolve_lines(&deck.lines, &surfaces, &refs.surf_index, &ctx)?;
    let interfaces = read_interfaces(deck, &refs, &surfaces, &lines, &mut warnings)?;

    let mut materials = super::failures::materials_with_failures(deck)?;
    super::material_law36::resolve_curves(
        &mut materials,
        &deck.functions,
        begin.work_units.time_si,
    )?;

    let skews = super::skews::resolve_skews(deck, &node_index, &nodes.x)?;
    let final_geometries = super::impdisp_fgeo::resolve(deck, &node_index, |f, l, k, fld| {
        refs.check_fct(f, l, k, fld)
    })?;

    let pressure_loads = super::pressure_load::resolve(
        &deck.pressure_loads,
        &surfaces,
        |c| {
            let kw = format!("/PLOAD/{}", c.id);
            refs.check_fct(c.fct, &c.loc, &kw, "fct_IDT")?;
            Ok(refs.surf_index.resolve(c.surf, &c.loc, &kw, "surf_ID")? as usize)
        },
        &elements,
    )?;

    // Masses.
    let mut model = Model {
        name: begin.run_name.clone(),
        title: deck.title.clone(),
        begin,
        nodal_mass: vec![0.0; nodes.len()],
        added_mass: vec![0.0; nodes.len()],
        nodal_inertia: vec![0.0; nodes.len()],
        nodes,
        elements,
        parts,
        materials,
        properties,
        functions: deck.functions.clone(),
        node_groups: node_groups.clone(),
        shell_groups,
        surfaces,
        bcs: conditions.bcs,
        imposed_velocities: conditions.imposed_velocities,
        imposed_displacements: conditions.imposed_displacements,
        initial_velocities: conditions.initial_velocities,
        concentrated_loads: conditions.concentrated_loads,
        gravity: conditions.gravity,
        dampings: conditions.dampings,
        rigid_walls,
        rigid_bodies: Vec::new(),
        interfaces,
        sections: deck.sections.clone(),
        time_histories: deck.time_histories.clone(),
        skews,
        final_geometries,
        pressure_loads,
        mass: MassSummary::default(),
        engine: deck.engine.clone(),
        warnings: Vec::new(),
        notes: Vec::new(),
        unsupported: deck.unsupported.clone(),
    };
    // LS-DYNA's tied options without _OFFSET move their secondary nodes onto
    // the main surface before masses and element geometry are computed.
    crate::model::tie_projection::project_secondary_nodes(&mut model);
    // IRS / IRM: the one-sided types' surfaces face the way their flags say.
    model.notes = crate::model::segment_orientation::orient_interfaces(&mut model);
    warnings.extend(model.notes.iter().cloned());
    let mut masses = Vec::new();
    for (set, locs) in model.elements.iter().zip(&element_locs) {
        masses.push(element_masses(&model, set, locs)?);
    }
    lump(&mut model, &masses);
    add_masses(&mut model, deck, &refs, &mut warnings)?;
    // Rigid bodies (after masses: their mass and inertia come from their nodes).
    add_rigid_bodies(&mut model, deck, &refs, &node_index)?;
    totals(&mut model);
    model.warnings = warnings;
    Ok(model)
}

/// Nodes, sorted by id, and their index.
fn read_nodes(deck: &Deck, begin: &Begin) -> Result<(Nodes, IdIndex), InputError> {
    let mut order: Vec<usize> = (0..deck.nodes.len()).collect();
    order.sort_by_key(|&i| deck.nodes[i].id);
    let nodes = Nodes {
        ids: order.iter().map(|&i| deck.nodes[i].id).collect(),
        x: order.iter().map(|&i| deck.nodes[i].x).collect(),
    };
    let node_index = IdIndex::build(
        "node",
        order
            .iter()
            .map(|&i| (deck.nodes[i].id, deck.nodes[i].loc.clone())),
        "/NODE",
    )?;
    if nodes.is_empty() {
        return Err(InputError::new(
            begin.loc.clone(),
            "/NODE",
            "",
            "the deck defines no node; expected a /NODE block",
        ));
    }
    Ok((nodes, node_index))
}

/// Materials, properties (their defaults resolved) and parts: the part index,
/// the properties and the parts with their property and material resolved.
fn read_parts(deck: &Deck) -> Result<(IdIndex, Vec<Property>, Vec<Part>), InputError> {
    let mat_index = IdIndex::build(
        "material",
        deck.materials.iter().map(|m| (m.id, m.loc.clone())),
        "/MAT",
    )?;
    let prop_index = IdIndex::build(
        "property",
        deck.properties.iter().map(|p| (p.id, p.loc.clone())),
        "/PROP",
    )?;
    let part_index = IdIndex::build(
        "part",
        deck.parts.iter().map(|p| (p.id, p.loc.clone())),
        "/PART",
    )?;
    let properties: Vec<Property> = deck
        .properties
        .iter()
        .map(|p| Property {
            card: p.clone(),
            shell: match &p.kind {
                PropertyKind::Shell(s) => Some(resolve_shell(s, deck.def_shell.as_ref())),
                _ => None,
            },
            solid: match &p.kind {
                PropertyKind::Solid(s) => Some(resolve_solid(s, deck.def_solid.as_ref())),
                _ => None,
            },
        })
        .collect();
    let mut parts = Vec::with_capacity(deck.parts.len());
    for p in &deck.parts {
        let kw = format!("/PART/{}", p.id);
        let prop = if p.prop == 0 {
            None
        } else {
            Some(resolve_skipped(
                &prop_index,
                p.prop,
                &p.loc,
                &kw,
                "prop_ID",
                "/PROP",
                deck,
            )?)
        };
        let mat = if p.mat == 0 {
            None
        } else {
            Some(resolve_skipped(
                &mat_index, p.mat, &p.loc, &kw, "mat_ID", "/MAT", deck,
            )?)
        };
        parts.push(Part {
            id: p.id,
            title: p.title.clone(),
            prop,
            mat,
            subset: p.subset,
            thick: p.thick,
        });
    }
    Ok((part_index, properties, parts))
}

/// The element sets, each kind sorted by id, in `ElementKind::ALL` order;
/// with each element's card location and the /SHELL index.
type ReadElements = (Vec<ElementSet>, Vec<Vec<Loc>>, IdIndex);

fn read_elements(
    deck: &Deck,
    node_index: &IdIndex,
    part_index: &IdIndex,
    parts: &[Part],
    properties: &[Property],
) -> Result<ReadElements, InputError> {
    let mut elements = Vec::new();
    let mut element_locs: Vec<Vec<Loc>> = Vec::new();
    let mut shell4_index = IdIndex::default();
    for kind in Elements::KINDS {
        let cards = deck.elements.of_kind(kind);
        let mut order: Vec<usize> = (0..cards.len()).collect();
        order.sort_by_key(|&i| cards[i].id);
        let index = IdIndex::build(
            "element",
            order.iter().map(|&i| (cards[i].id, cards[i].loc.clone())),
            kind.keyword(),
        )?;
        let mut set = ElementSet {
            kind,
            ids: Vec::with_capacity(cards.len()),
            part: Vec::with_capacity(cards.len()),
            nodes: Vec::with_capacity(cards.len() * kind.nodes()),
            thick: Vec::with_capacity(cards.len()),
        };
        let mut locs = Vec::with_capacity(cards.len());
        for &i in &order {
            let c = &cards[i];
            add_element(
                &mut set,
                c,
                kind,
                node_index,
                part_index,
                parts,
                properties,
                &deck.materials,
            )?;
            locs.push(c.loc.clone());
        }
        if kind == ElementKind::Shell4 {
            shell4_index = index;
        }
        elements.push(set);
        element_locs.push(locs);
    }
    Ok((elements, element_locs, shell4_index))
}

/// What conditions, walls, interfaces and rigid bodies refer to by id: node
/// groups, surfaces and functions.
struct Refs<'a> {
    node_groups: &'a [NodeGroup],
    grnod_index: IdIndex,
    surf_index: IdIndex,
    fct_index: IdIndex,
}

impl Refs<'_> {
    /// The nodes of node group `id`, named by field `field` of `kw` at `loc`.
    fn group(&self, id: Id, loc: &Loc, kw: &str, field: &str) -> Result<Vec<u32>, InputError> {
        Ok(
            self.node_groups[self.grnod_index.resolve(id, loc, kw, field)? as usize]
                .nodes
                .clone(),
        )
    }

    /// Function `id` (0 = none) must be defined.
    fn check_fct(&self, id: Id, loc: &Loc, kw: &str, field: &str) -> Result<(), InputError> {
        if id != 0 {
            self.fct_index.resolve(id, loc, kw, field)?;
        }
        Ok(())
    }

    /// The functions and skews a spring property names must be defined.
    fn check_spring_functions(&self, properties: &[Property]) -> Result<(), InputError> {
        for p in properties {
            let (kw, dofs): (&str, &[SpringDof]) = match &p.card.kind {
                PropertyKind::Spring(s) => ("SPRING", std::slice::from_ref(&s.dof)),
                PropertyKind::GeneralSpring(s) => ("SPR_GENE", &s.dofs),
                PropertyKind::SpringBeam(s) => ("SPR_BEAM", &s.dofs),
                PropertyKind::Joint(j) => {
                    let kw = format!("/PROP/KJOINT2/{}", p.card.id);
                    for (_, d) in &j.free {
                        for (name, f) in
                            [("fct_K", d.fct_k), ("fct_C", d.fct_c), ("fct_F", d.fct_f)]
                        {
                            self.check_fct(f, &p.card.loc, &kw, name)?;
                        }
                    }
                    continue;
                }
                _ => continue,
            };
            let kw = format!("/PROP/{kw}/{}", p.card.id);
            for d in dofs {
                for (name, f) in d.functions() {
                    self.check_fct(f, &p.card.loc, &kw, name)?;
                }
            }
        }
        Ok(())
    }

    /// Imposed velocities or displacements (`kw` /IMPVEL or /IMPDISP).
    fn motions(
        &self,
        cards: &[ImposedMotionSpec],
        kw: &str,
    ) -> Result<Vec<ImposedMotion>, InputError> {
        let mut out = Vec::new();
        for c in cards {
            let k = format!("{kw}/{}", c.id);
            self.check_fct(c.fct, &c.loc, &k, "fct_IDT")?;
            out.push(OnNodes {
                nodes: self.group(c.grnod, &c.loc, &k, "grnod_ID")?,
                card: c.clone(),
            });
        }
        Ok(out)
    }
}

/// Boundary and initial conditions and loads with their nodes.
struct Conditions {
    bcs: Vec<Bcs>,
    imposed_velocities: Vec<ImposedMotion>,
    imposed_displacements: Vec<ImposedMotion>,
    initial_velocities: Vec<InitialVelocity>,
    concentrated_loads: Vec<ConcentratedLoad>,
    gravity: Vec<Gravity>,
    dampings: Vec<Damping>,
}

fn read_conditions(deck: &Deck, refs: &Refs, n_nodes: usize) -> Result<Conditions, InputError> {
    let mut bcs = Vec::new();
    for c in &deck.bcs {
        bcs.push(OnNodes {
            nodes: refs.group(c.grnod, &c.loc, &format!("/BCS/{}", c.id), "grnod_ID")?,
            card: c.clone(),
        });
    }
    let imposed_velocities = refs.motions(&deck.imposed_velocities, "/IMPVEL")?;
    let imposed_displacements = refs.motions(&deck.imposed_displacements, "/IMPDISP")?;
    let mut initial_velocities = Vec::new();
    for c in &deck.initial_velocities {
        initial_velocities.push(OnNodes {
            nodes: refs.group(c.grnod, &c.loc, &format!("/INIVEL/{}", c.id), "grnod_ID")?,
            card: c.clone(),
        });
    }
    let mut concentrated_loads = Vec::new();
    for c in &deck.concentrated_loads {
        let k = format!("/CLOAD/{}", c.id);
        refs.check_fct(c.fct, &c.loc, &k, "fct_IDT")?;
        concentrated_loads.push(OnNodes {
            nodes: refs.group(c.grnod, &c.loc, &k, "grnod_ID")?,
            card: c.clone(),
        });
    }
    let mut gravity = Vec::new();
    for c in &deck.gravity {
        let k = format!("/GRAV/{}", c.id);
        refs.check_fct(c.fct, &c.loc, &k, "fct_IDT")?;
        let nodes = if c.grnod == 0 {
            (0..n_nodes as u32).collect()
        } else {
            refs.group(c.grnod, &c.loc, &k, "grnod_ID")?
        };
        gravity.push(OnNodes {
            nodes,
            card: c.clone(),
        });
    }
    let mut dampings = Vec::new();
    for c in &deck.dampings {
        let nodes = if c.grnod == 0 {
            (0..n_nodes as u32).collect()
        } else {
            refs.group(c.grnod, &c.loc, &format!("/DAMP/{}", c.id), "grnod_ID")?
        };
        dampings.push(OnNodes {
            nodes,
            card: c.clone(),
        });
    }
    Ok(Conditions {
        bcs,
        dampings,
        imposed_velocities,
        imposed_displacements,
        initial_velocities,
        concentrated_loads,
        gravity,
    })
}

/// Rigid walls: the plane, and the secondary nodes (group 1, plus the nodes
/// within the search distance in front of the wall, minus group 2).
fn read_rigid_walls(
    deck: &Deck,
    refs: &Refs,
    nodes: &Nodes,
    node_index: &IdIndex,
    warnings: &mut Vec<Warning>,
) -> Result<Vec<RigidWall>, InputError> {
    let mut rigid_walls = Vec::new();
    for c in &deck.rigid_walls {
        let kw = format!("/RWALL/PLANE/{}", c.id);
        let node = if c.node_id == 0 {
            None
        } else {
            Some(node_index.resolve(c.node_id, &c.loc, &kw, "node_ID")?)
        };
        let point = node.map(|n| nodes.x[n as usize]).unwrap_or(c.m);
        let d = [c.m1[0] - point[0], c.m1[1] - point[1], c.m1[2] - point[2]];
        let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        if len.is_nan() || len <= 0.0 {
            return Err(InputError::new(
                c.loc.clone(),
                &kw,
                "X_M1",
                "M1 coincides with M: the wall normal M→M1 is undefined",
            ));
        }
        let normal = [d[0] / len, d[1] / len, d[2] / len];
        let mut sec: std::collections::BTreeSet<u32> = std::collections::BTreeSet::new();
        if c.grnod1 != 0 {
            sec.extend(refs.group(c.grnod1, &c.loc, &kw, "grnod_ID1")?);
        }
        if c.d_search > 0.0 {
            for (i, x) in nodes.x.iter().enumerate() {
                let dist = (x[0] - point[0]) * normal[0]
                    + (x[1] - point[1]) * normal[1]
                    + (x[2] - point[2]) * normal[2];
                if dist >= 0.0 && dist <= c.d_search && Some(i as u32) != node {
                    sec.insert(i as u32);
                }
            }
        }
        if c.grnod2 != 0 {
            for n in refs.group(c.grnod2, &c.loc, &kw, "grnod_ID2")? {
                sec.remove(&n);
            }
        }
        if sec.is_empty() {
            warnings.push(Warning {
                loc: c.loc.clone(),
                keyword: kw.clone(),
                message: "the rigid wall has no secondary node".into(),
            });
        }
        rigid_walls.push(RigidWall {
            card: c.clone(),
            node,
            point,
            normal,
            secondary_nodes: sec.into_iter().collect(),
        });
    }
    Ok(rigid_walls)
}

/// One side of an interface resolved: its nodes, segments and edges.
#[derive(Clone, Default)]
struct ResolvedSide {
    nodes: Vec<u32>,
    segments: Vec<[u32; 4]>,
    edges: Vec<[u32; 2]>,
}

/// Contact interfaces with their sides resolved to nodes, segments and edges.
fn read_interfaces(
    deck: &Deck,
    refs: &Refs,
    surfaces: &[Surface],
    lines: &[Line],
    warnings: &mut Vec<Warning>,
) -> Result<Vec<Interface>, InputError> {
    let mut interfaces = Vec::new();
    // Ids for the interfaces a TYPE19 card adds, after every id of the deck.
    let mut next_id = deck.interfaces.iter().map(|i| i.id).max().unwrap_or(0) + 1;
    IdIndex::build(
        "interface",
        deck.interfaces.iter().map(|i| (i.id, i.loc.clone())),
        "/INTER",
    )?;
    let line_index = IdIndex::build(
        "line",
        deck.lines.iter().map(|l| (l.id, l.loc.clone())),
        "/LINE",
    )?;
    for c in &deck.interfaces {
        let kw = format!("/INTER/TYPE{}/{}", c.type_number(), c.id);
        let loc = if c.ids_loc.line == 0 {
            &c.loc
        } else {
            &c.ids_loc
        };
        if let InterfaceKind::Type19(t) = &c.kind {
            let sides = Type19Sides::resolve(t, refs, surfaces, loc, &kw)?;
            interfaces.extend(expand_type19(c, t, &sides, &mut next_id, warnings));
            continue;
        }
        let side = |s: Side, field: &str| -> Result<Option<ResolvedSide>, InputError> {
            Ok(match s {
                Side::NodeGroup(g) => Some(ResolvedSide {
                    nodes: refs.group(g, loc, &kw, field)?,
                    ..Default::default()
                }),
                Side::Surface(sid) => {
                    let s = &surfaces[refs.surf_index.resolve(sid, loc, &kw, field)? as usize];
                    let ellipsoid_side = matches!(c.type_number(), 14 | 15) && field == "surf_IDm";
                    if s.ellipsoid.is_some() != ellipsoid_side {
                        let msg = if ellipsoid_side {
                            format!("/SURF/{sid} is not a /SURF/ELLIPS: expected a hyper-ellipsoid surface")
                        } else {
                            format!("/SURF/ELLIPS/{sid} is a hyper-ellipsoid: expected a surface of segments (an ellipsoid is only the main side of /INTER/TYPE14 and /INTER/TYPE15)")
                        };
                        return Err(InputError::new(loc.clone(), &kw, field, msg));
                    }
                    Some(ResolvedSide {
                        nodes: s.nodes(),
                        segments: s.segments.clone(),
                        ..Default::default()
                    })
                }
                Side::Line(lid) => {
                    let l = &lines[line_index.resolve(lid, loc, &kw, field)? as usize];
                    let nodes = distinct_nodes(l.edges.iter().flatten().copied());
                    Some(ResolvedSide {
                        nodes,
                        edges: l.edges.clone(),
                        ..Default::default()
                    })
                }
                Side::SameAsOther | Side::None => None,
            })
        };
        let (sec_field, main_field) = c.side_fields();
        let main = side(c.main_side(), main_field)?;
        let sec = side(c.secondary_side(), sec_field)?;
        // Self-contact: the side given twice (TYPE7 grnd_IDs = 0: the main
        // surface's nodes; TYPE11 line_IDm = 0: the secondary line's edges).
        let (main, sec) = match (main, sec) {
            (Some(m), Some(s)) => (m, s),
            (Some(m), None) if c.secondary_side() == Side::SameAsOther => {
                let s = ResolvedSide {
                    nodes: m.nodes.clone(),
                    edges: m.edges.clone(),
                    ..Default::default()
                };
                (m, s)
            }
            (None, Some(s)) if c.main_side() == Side::SameAsOther => {
                let m = ResolvedSide {
                    nodes: s.nodes.clone(),
                    edges: s.edges.clone(),
                    ..Default::default()
                };
                (m, s)
            }
            (m, s) => (m.unwrap_or_default(), s.unwrap_or_default()),
        };
        interfaces.push(Interface {
            card: c.clone(),
            secondary_nodes: sec.nodes,
            main_segments: main.segments,
            secondary_segments: sec.segments,
            secondary_edges: sec.edges,
            main_edges: main.edges,
        });
        if let InterfaceKind::Type25(t) = &c.kind {
            let nodes_part = interfaces.last().unwrap();
            if let Some(e) = type25_edge_part(c, t, nodes_part, &mut next_id, warnings) {
                interfaces.push(e);
            }
        }
    }
    Ok(interfaces)
}

/// The edge-to-edge part of a /INTER/TYPE25 with Iedge = 1 (reference card:
/// "shell external border edges"): the free edges of surf_ID1 against
/// those of surf_ID2 (of surf_ID1 itself in self-contact), as an interface
/// with an id after the deck's largest running TYPE25's penalty on edge
/// pairs (`Type25::edge_part`). A side with no free edge, or a node group as
/// the secondary side, leaves the edge part out, with a warning. Other
/// Iedge values are the engine's to refuse by name.
fn type25_edge_part(
    c: &InterfaceSpec,
    t: &Type25,
    nodes_part: &Interface,
    next_id: &mut Id,
    warnings: &mut Vec<Warning>,
) -> Option<Interface> {
    if t.iedge != 1 {
        return None;
    }
    let kw = format!("/INTER/TYPE25/{}", c.id);
    let main_edges = super::lines::segment_edges(&nodes_part.main_segments, true);
    let self_contact = t.surf_id2 == 0 || t.surf_id2 == t.surf_id1;
    let sec_edges = if self_contact {
        main_edges.clone()
    } else {
        super::lines::segment_edges(&nodes_part.secondary_segments, true)
    };
    if t.surf_id1 == 0 || sec_edges.is_empty() || main_edges.is_empty() {
        warnings.push(Warning {
            loc: c.loc.clone(),
            keyword: kw,
            message: "Iedge = 1: a side has no free shell edge (or is a node group): \
                      the edge-to-edge part is left out"
                .into(),
        });
        return None;
    }
    let id = *next_id;
    *next_id += 1;
    // The surfaces' ids as the lines' (as TYPE19's edge part): the same
    // on both sides, or 0, is self-contact.
    let mut card = t.edge_part();
    card.line_ids = t.surf_id1;
    card.line_idm = if self_contact { 0 } else { t.surf_id2 };
    Some(Interface {
        card: InterfaceSpec {
            id,
            title: format!("{} ({kw}: edge to edge)", c.title),
            kind: InterfaceKind::Type11(card),
            ..c.clone()
        },
        secondary_nodes: distinct_nodes(sec_edges.iter().flatten().copied()),
        main_segments: Vec::new(),
        secondary_segments: Vec::new(),
        secondary_edges: sec_edges,
        main_edges,
    })
}

/// The two surfaces of a /INTER/TYPE19 card.
struct Type19Sides<'a> {
    sec: &'a Surface,
    main: &'a Surface,
    same: bool,
}

impl<'a> Type19Sides<'a> {
    fn resolve(
        t: &Type19,
        refs: &Refs,
        surfaces: &'a [Surface],
        loc: &Loc,
        kw: &str,
    ) -> Result<Type19Sides<'a>, InputError> {
        let (s, m) = t.surfaces();
        let field = |given: Id| if given == 0 { "surf_IDm" } else { "surf_IDs" };
        let sec = &surfaces[refs.surf_index.resolve(s, loc, kw, field(t.surf_ids))? as usize];
        let main = &surfaces[refs.surf_index.resolve(m, loc, kw, "surf_IDm")? as usize];
        Ok(Type19Sides {
            sec,
            main,
            same: s == m,
        })
    }
}

/// /INTER/TYPE19 as Radioss computes it (reference card /INTER/TYPE19):
/// a TYPE7 with the secondary surface's nodes on the main surface (the
/// card's id), a second TYPE7 the other way round when the surfaces differ,
/// and a TYPE11 between the surfaces' edges (Iedge 2: all, 1: the free
/// ones; the surface with itself when they are the same). The added
/// interfaces take ids after the deck's largest; a surface with no edge of
/// the kind asked leaves the edge part out, with a warning.
fn expand_type19(
    c: &InterfaceSpec,
    t: &Type19,
    sides: &Type19Sides,
    next_id: &mut Id,
    warnings: &mut Vec<Warning>,
) -> Vec<Interface> {
    let kw = format!("/INTER/TYPE19/{}", c.id);
    let mut take_id = || {
        let id = *next_id;
        *next_id += 1;
        id
    };
    let spec = |id: Id, what: &str, kind: InterfaceKind| InterfaceSpec {
        id,
        title: format!("{} ({kw}: {what})", c.title),
        kind,
        ..c.clone()
    };
    let node_part = |id: Id, what: &str, sec: &Surface, main: &Surface| Interface {
        card: spec(id, what, InterfaceKind::Type7(t.node_part())),
        secondary_nodes: sec.nodes(),
        main_segments: main.segments.clone(),
        secondary_segments: Vec::new(),
        secondary_edges: Vec::new(),
        main_edges: Vec::new(),
    };
    let mut out = vec![node_part(c.id, "nodes to surface", sides.sec, sides.main)];
    if !sides.same {
        let id = take_id();
        out.push(node_part(
            id,
            "main surface nodes to secondary surface",
            sides.main,
            sides.sec,
        ));
    }
    let free = t.iedge == 1;
    let sec_edges = super::lines::segment_edges(&sides.sec.segments, free);
    let main_edges = if sides.same {
        sec_edges.clone()
    } else {
        super::lines::segment_edges(&sides.main.segments, free)
    };
    if sec_edges.is_empty() || main_edges.is_empty() {
        warnings.push(Warning {
            loc: c.loc.clone(),
            keyword: kw.clone(),
            message: "a surface has no free edge (Iedge = 1): the edge-to-edge part is left out"
                .into(),
        });
        return out;
    }
    let id = take_id();
    let edge_nodes = distinct_nodes(sec_edges.iter().flatten().copied());
    out.push(Interface {
        card: spec(id, "edge to edge", InterfaceKind::Type11(t.edge_part())),
        secondary_nodes: edge_nodes,
        main_segments: Vec::new(),
        secondary_segments: Vec::new(),
        secondary_edges: sec_edges,
        main_edges,
    });
    out
}

/// /ADMAS: mass added to the nodes of a group (each, or shared).
fn add_masses(
    model: &mut Model,
    deck: &Deck,
    refs: &Refs,
    warnings: &mut Vec<Warning>,
) -> Result<(), InputError> {
    for a in &deck.added_masses {
        let kw = format!("/ADMAS/{}/{}", a.kind, a.id);
        let g = refs.group(a.target, &a.loc, &kw, "grnd_ID")?;
        if g.is_empty() {
            warnings.push(Warning {
                loc: a.loc.clone(),
                keyword: kw.clone(),
                message: "the node group is empty: no mass added".into(),
            });
            continue;
        }
        let each = if a.kind == 0 {
            a.mass
        } else {
            a.mass / g.len() as f64
        };
        for n in g {
            model.added_mass[n as usize] += each;
            model.nodal_mass[n as usize] += each;
        }
    }
    Ok(())
}

/// Rigid bodies: main node, secondary nodes, and the body's mass, centre
/// and inertia about the centre from its nodes' masses.
fn add_rigid_bodies(
    model: &mut Model,
    deck: &Deck,
    refs: &Refs,
    node_index: &IdIndex,
) -> Result<(), InputError> {
    for c in &deck.rigid_bodies {
        let kw = format!("/RBODY/{}", c.id);
        let main_node = node_index.resolve(c.main_node, &c.loc, &kw, "RBID")?;
        let secondary_nodes: Vec<u32> = refs
            .group(c.grnod, &c.loc, &kw, "Gnod_id")?
            .into_iter()
            .filter(|&n| n != main_node)
            .collect();
        if secondary_nodes.is_empty() {
            return Err(InputError::new(c.loc.clone(), &kw, "Gnod_id", "the rigid body's node group is empty (or holds only the main node); expected its secondary nodes"));
        }
        let xm = model.nodes.x[main_node as usize];
        let mut m = c.mass + model.nodal_mass[main_node as usize];
        let mut s = [xm[0] * m, xm[1] * m, xm[2] * m];
        for &n in &secondary_nodes {
            let mn = model.nodal_mass[n as usize];
            m += mn;
            for k in 0..3 {
                s[k] += mn * model.nodes.x[n as usize][k];
            }
        }
        // ICOG 0/1: the centre of mass of the main and secondary nodes;
        // 3: the main node, the inertia taken about it (the reference
        // starter's "NEW X,Y,Z" and "NEW INERTIA", QA RESSORT_kjoint2).
        let center = match c.icog {
            0 | 1 if m > 0.0 => [s[0] / m, s[1] / m, s[2] / m],
            0 | 1 | 3 => xm,
            v => {
                return Err(InputError::new(
                    c.loc.clone(),
                    &kw,
                    "ICOG",
                    format!("{v}: this centre-of-mass option is not computed; expected 0 or 1 (the centre of mass) or 3 (the main node)"),
                ))
            }
        };
        let mut inertia = c.inertia;
        // Point masses, plus the shells' nodal rotational inertia (isotropic).
        let mut add = |mn: f64, x: [f64; 3], rot: f64| {
            let r = [x[0] - center[0], x[1] - center[1], x[2] - center[2]];
            inertia[0] += mn * (r[1] * r[1] + r[2] * r[2]) + rot;
            inertia[1] += mn * (r[0] * r[0] + r[2] * r[2]) + rot;
            inertia[2] += mn * (r[0] * r[0] + r[1] * r[1]) + rot;
            inertia[3] -= mn * r[0] * r[1];
            inertia[4] -= mn * r[1] * r[2];
            inertia[5] -= mn * r[0] * r[2];
        };
        add(
            c.mass + model.nodal_mass[main_node as usize],
            xm,
            model.nodal_inertia[main_node as usize],
        );
        for &n in &secondary_nodes {
            add(
                model.nodal_mass[n as usize],
                model.nodes.x[n as usize],
                model.nodal_inertia[n as usize],
            );
        }
        // ISPHER 1: a spherical inertia, the trace of the tensor over 3
        // (QA RESSORT_kjoint2's rb2: 31200, 990600, 990600 → 670800).
        if c.ispher == 1 {
            let j = (inertia[0] + inertia[1] + inertia[2]) / 3.0;
            inertia = [j, j, j, 0.0, 0.0, 0.0];
        }
        // A body of massless nodes (a deck of rigid bodies and no element)
        // or of collinear point masses: a negligible mass and principal
        // inertia where there is none, as the reference engine (its listing
        // gives such a model a TOTAL MASS of 1e-19), so that no motion
        // divides by zero.
        const NEGLIGIBLE: f64 = 1e-20;
        for j in inertia.iter_mut().take(3) {
            if *j <= 0.0 {
                *j = NEGLIGIBLE;
            }
        }
        model.rigid_bodies.push(RigidBody {
            card: c.clone(),
            main_node,
            secondary_nodes,
            mass: if m > 0.0 { m } else { NEGLIGIBLE },
            center,
            inertia,
        });
    }
    Ok(())
}

/// Resolves an id, mentioning in the error when the card that would define it was skipped as unsupported.
fn resolve_skipped(
    index: &IdIndex,
    id: Id,
    loc: &Loc,
    kw: &str,
    field: &str,
    family: &str,
    deck: &Deck,
) -> Result<u32, InputError> {
    index.resolve(id, loc, kw, field).map_err(|mut e| {
        let id_s = id.to_string();
        if let Some(w) = deck.warnings.iter().find(|w| {
            w.keyword.starts_with(family)
                && w.keyword.rsplit('/').next().map(str::trim) == Some(id_s.as_str())
        }) {
            e.message = format!(
                "{}; {} at {} defines it but that keyword is not supported",
                e.message, w.keyword, w.loc
            );
        }
        e
    })
}

#[allow(clippy::too_many_arguments)]
fn add_element(
    set: &mut ElementSet,
    c: &ElementCard,
    kind: ElementKind,
    node_index: &IdIndex,
    part_index: &IdIndex,
    parts: &[Part],
    properties: &[Property],
    materials: &[MaterialSpec],
) -> Result<(), InputError> {
    let kw = format!("{}/{}", kind.keyword(), c.part);
    let p = part_index.resolve(c.part, &c.loc, &kw, "part_ID")?;
    let part = &parts[p as usize];
    let prop = part.prop.map(|i| &properties[i as usize]);
    // The part's property must suit the element kind, and a material is needed for continua.
    let ok = match (kind, prop.map(|p| &p.card.kind)) {
        (ElementKind::Shell4 | ElementKind::Shell3, Some(PropertyKind::Shell(_))) => true,
        (ElementKind::Brick8 | ElementKind::Tetra4, Some(PropertyKind::Solid(_))) => true,
        (
            ElementKind::Spring,
            Some(
                PropertyKind::Spring(_)
                | PropertyKind::GeneralSpring(_)
                | PropertyKind::SpringBeam(_)
                | PropertyKind::Joint(_),
            ),
        ) => true,
        (ElementKind::Truss, Some(PropertyKind::Truss(_))) => true,
        (ElementKind::Beam, Some(PropertyKind::Beam(_))) => true,
        _ => false,
    };
    if !ok {
        let what = match prop {
            None => "no property".to_string(),
            Some(p) => format!("property {} of another kind", p.card.id),
        };
        return Err(InputError::new(
            c.loc.clone(),
            &kw,
            "part_ID",
            format!(
                "element {} belongs to part {} which has {what}; expected a {} property",
                c.id,
                c.part,
                match kind {
                    ElementKind::Shell4 | ElementKind::Shell3 => "/PROP/SHELL (TYPE1)",
                    ElementKind::Brick8 | ElementKind::Tetra4 => "/PROP/SOLID (TYPE14)",
                    ElementKind::Truss => "/PROP/TRUSS (TYPE2)",
                    ElementKind::Beam => "/PROP/BEAM (TYPE3)",
                    _ => "/PROP/SPRING (TYPE4), /PROP/SPR_GENE (TYPE8), /PROP/SPR_BEAM (TYPE13) or /PROP/KJOINT2 (TYPE45)",
                }
            ),
        ));
    }
    if matches!(
        kind,
        ElementKind::Shell4
            | ElementKind::Shell3
            | ElementKind::Brick8
            | ElementKind::Tetra4
            | ElementKind::Truss
            | ElementKind::Beam
    ) {
        match part.mat {
            None => {
                return Err(InputError::new(
                    c.loc.clone(),
                    &kw,
                    "mat_ID",
                    format!(
                        "element {} belongs to part {} which has no material (mat_ID = 0)",
                        c.id, c.part
                    ),
                ))
            }
            Some(m) => {
                // Every material the reader keeps is a law the solver has (LAW1, LAW2).
                debug_assert!(matches!(
                    materials[m as usize].law,
                    MaterialLaw::Elastic | MaterialLaw::JohnsonCook(_)
                ));
            }
        }
    }
    set.ids.push(c.id);
    set.part.push(p);
    let names = [
        "node_ID1", "node_ID2", "node_ID3", "node_ID4", "node_ID5", "node_ID6", "node_ID7",
        "node_ID8",
    ];
    for (k, &n) in c.nodes.iter().enumerate() {
        if n == 0 {
            set.nodes.push(NO_NODE);
        } else {
            let loc = &c.loc;
            set.nodes
                .push(node_index.resolve(n, loc, &kw, names[k]).map_err(|mut e| {
                    e.message = format!("element {}: {}", c.id, e.message);
                    e
                })?);
        }
    }
    let t = if c.thick > 0.0 {
        c.thick
    } else {
        prop.and_then(|p| p.shell.as_ref().map(|s| s.thick))
            .unwrap_or(0.0)
    };
    set.thick.push(t);
    Ok(())
}
