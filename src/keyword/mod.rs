//! The LS-DYNA keyword reader (`*KEYWORD` decks: `.k`, `.key`, `.dyn`).
//!
//! Each keyword it computes is translated into the same card records the
//! Radioss reader gives for the Radioss card that means the same thing
//! (`*SECTION_SHELL` ELFORM 2 → /PROP/SHELL Ishell 1, `*MAT_ELASTIC` →
//! /MAT/LAW1, `*SET_NODE_LIST` → /GRNOD/NODE, ...), and the one model
//! builder (`deck::build_model`) turns them into the model. So a keyword
//! deck and its Radioss twin build the same model bit for bit, and every
//! later stage is shared. References are checked here in keyword terms
//! first (which part names a missing section), so errors name the keyword
//! deck's file:line, keyword and field.
//!
//! The keyword policy is the Radioss reader's: a keyword is computed (a
//! translator below), safe to skip (an output request: noted, not fatal),
//! or unsupported: recorded by name so that `run` refuses the deck. An
//! option of a computed keyword that nothing computes (a non-zero EOSID,
//! a mass-scaling DT2MS) is refused the same way, by keyword and field.
//!
//! Keywords come in any order, as LS-DYNA reads them: what depends on
//! keywords read later is completed once the whole deck is read — the
//! groups and surfaces of part sets and shell sets
//! (`Ctx::resolve_part_sets`, `Ctx::resolve_shell_sets`), every-part
//! surfaces and SLSFAC (`contacts::finish`), discrete parts' spring
//! properties (`discrete::finish`), hourglass definitions
//! (`hourglass::finish`), rigid bodies and their new
//! main nodes (`rigid::finish`), moving walls' nodes (`walls_masses::finish`)
//! — before the references are checked (`references::check`).

mod card;
mod conditions;
mod contacts;
mod controls;
mod define_transformation;
mod discrete;
mod hourglass;
pub mod include_transform;
mod loads;
mod materials;
mod mesh;
mod references;
mod rigid;
mod sections;
pub mod source;
mod tied;
mod walls_masses;

use crate::deck::Deck;
use crate::model::{Begin, Id, InputError, InputResult, Loc, Units, Warning};
use card::{Cards, Parameters};
use source::Block;
use std::path::Path;

pub use source::is_keyword_deck;

/// The translation in progress: the records, and what keywords refer to
/// across the deck.
pub(crate) struct Ctx<'a> {
    pub deck: Deck,
    pub params: &'a Parameters,
    /// `*SET_PART_LIST` parts by set id.
    pub part_sets: Vec<(Id, Vec<i64>)>,
    /// SLSFAC of `*CONTROL_CONTACT` (0.1 without it), its RWPNAL (checked
    /// against the rigid walls once the deck is read) and IGNORE ≥ 1.
    pub slsfac: f64,
    pub rwpnal: Option<(f64, Loc)>,
    pub ignore_penetrations: bool,
    /// The interfaces the contact keywords made, and the surfaces that take
    /// every part (SSTYP 5), completed once the deck is read.
    pub contacts: Vec<usize>,
    pub all_parts_surfaces: Vec<usize>,
    /// Node groups that take every part's nodes (a rigid wall's NSID 0).
    pub all_parts_groups: Vec<usize>,
    /// Segment sets contacts name (id, where, keyword, field), checked once
    /// the deck is read.
    pub segment_sets_used: Vec<(Id, Loc, String, String)>,
    /// Node sets keywords name (id, where, keyword, field) where the
    /// reader makes its own group of them, checked once the deck is read.
    pub node_sets_used: Vec<(Id, Loc, String, String)>,
    /// `*SET_SHELL` sets (id, shell ids, where), and the surfaces made of
    /// one (set, surface index, where, keyword, field), filled once the deck
    /// is read.
    pub shell_sets: Vec<(Id, Vec<Id>, Loc)>,
    pub shell_sets_used: Vec<(Id, usize, Loc, String, String)>,
    /// Groups and surfaces made of a part set (set, which, where, keyword,
    /// field), filled once the deck is read.
    pub part_sets_used: Vec<(Id, PartSetTarget, Loc, String, String)>,
    /// `*HOURGLASS` definitions, `*CONTROL_HOURGLASS`'s, and the parts
    /// with an HGID (index, HGID, where) or without: applied once the deck
    /// is read (`hourglass::finish`).
    pub hourglasses: Vec<(Id, hourglass::Hourglass)>,
    pub control_hourglass: Option<hourglass::Hourglass>,
    pub part_hgid: Vec<(usize, Id, Loc)>,
    pub parts_without_hgid: Vec<usize>,
    /// `*SECTION_DISCRETE` ids and the spring and damper materials (id,
    /// their law), joined per part once the deck is read (`discrete::finish`).
    pub discrete_sections: Vec<Id>,
    pub discrete_materials: Vec<(Id, crate::model::SpringDof)>,
    /// Rigid bodies made once the deck is read (`rigid::finish`), and the
    /// moving walls (indices) whose node is made then.
    pub rigid: Vec<rigid::PendingBody>,
    pub moving_walls: Vec<usize>,
    /// `*DEFINE_TRANSFORMATION`s (TRANID, rows, where), the nodes read from
    /// a file with a TRANID (index), and the keywords with directions read
    /// there: completed once the deck is read (`define_transformation`).
    pub transformations: Vec<(Id, Vec<define_transformation::Row>, Loc)>,
    pub transformed_nodes: Vec<(usize, std::sync::Arc<include_transform::Transform>)>,
    pub directed_in_transform: Vec<(Loc, String, std::sync::Arc<include_transform::Transform>)>,
    /// Next id of a node group made for a keyword that names nodes or
    /// parts directly (above every id a deck writes).
    next_group: Id,
}

/// What a part set fills once the deck is read: a node group or a
/// surface (indices in the deck's records).
pub(crate) enum PartSetTarget {
    Group(usize),
    Surface(usize),
}

/// First id of the node groups the reader makes itself.
const OWN_GROUPS: Id = 1 << 40;

impl Ctx<'_> {
    /// An option of a computed keyword that nothing computes: `run`
    /// refuses the deck by keyword and field.
    pub fn refuse(&mut self, loc: &Loc, keyword: &str, what: impl Into<String>) {
        let w = Warning {
            loc: loc.clone(),
            keyword: format!("{keyword}, {}", what.into()),
            message: "not computed; `run` stops on it (`run --skip-unsupported` ignores it)".into(),
        };
        self.deck.warnings.push(w.clone());
        self.deck.unsupported.push(w);
    }

    /// Refuses by name each of `fields` (index, name) of card `c` that is
    /// given and not 0 (see [`Card::given`]); `whose` follows the field's
    /// name in the message (" (material 3)").
    pub fn refuse_given(
        &mut self,
        c: &card::Card,
        kw: &str,
        fields: &[(usize, &str)],
        whose: &str,
        integer: bool,
    ) -> InputResult<()> {
        for &(i, name) in fields {
            if c.given(i, name, integer)? {
                self.refuse(&c.loc(), kw, format!("field {name}{whose}"));
            }
        }
        Ok(())
    }

    /// The nodes a card's first field names: a node (`set` false: a group
    /// of its own) or a node set.
    pub fn card_nodes(&mut self, c: &card::Card, set: bool, kw: &str) -> InputResult<Id> {
        let id = c.id(0, if set { "NSID" } else { "NID" })?;
        Ok(if set {
            id
        } else {
            let title = format!("{kw} node {id}");
            self.own_group(
                crate::deck::NodeGroupKind::Node,
                vec![id as i64],
                title,
                &c.loc(),
            )
        })
    }

    /// A new node at `x` (the next free node id), for a body or a wall the
    /// reader makes once the deck is read.
    pub fn add_node(&mut self, x: [f64; 3], loc: &Loc) -> Id {
        let id = self.deck.nodes.iter().map(|n| n.id).max().unwrap_or(0) + 1;
        self.deck.nodes.push(crate::deck::NodeCard {
            id,
            x,
            loc: loc.clone(),
        });
        id
    }

    /// An id for a group or surface the reader makes itself.
    pub fn own_id(&mut self) -> Id {
        self.next_group += 1;
        self.next_group - 1
    }

    /// A node group of the parts of `*SET_PART` `sid`, filled once the deck
    /// is read (keywords come in any order; [`Self::resolve_part_sets`]).
    pub fn part_set_group(
        &mut self,
        sid: Id,
        title: String,
        loc: &Loc,
        kw: &str,
        field: &str,
    ) -> Id {
        let g = self.own_group(crate::deck::NodeGroupKind::Part, Vec::new(), title, loc);
        let target = PartSetTarget::Group(self.deck.node_groups.len() - 1);
        self.part_sets_used
            .push((sid, target, loc.clone(), kw.into(), field.into()));
        g
    }

    /// Fills every group and surface made of a part set; an undefined set is
    /// an error naming the keyword and field that name it.
    pub fn resolve_part_sets(&mut self) -> InputResult<()> {
        for (sid, target, loc, kw, field) in std::mem::take(&mut self.part_sets_used) {
            let parts = self.part_set(sid).ok_or_else(|| {
                InputError::new(
                    loc,
                    &kw,
                    &field,
                    format!("part set {sid} is not defined (expected a *SET_PART)"),
                )
            })?;
            match target {
                PartSetTarget::Group(i) => self.deck.node_groups[i].items = parts,
                PartSetTarget::Surface(i) => {
                    self.deck.surfaces[i].def = crate::deck::SurfaceDef::Parts(parts)
                }
            }
        }
        Ok(())
    }

    /// A surface of the faces of `*SET_SHELL` `sid`'s shells, filled once
    /// the deck is read ([`Self::resolve_shell_sets`]).
    pub fn shell_set_surface(&mut self, sid: Id, loc: &Loc, kw: &str, field: &str) -> Id {
        let id = self.own_id();
        self.shell_sets_used.push((
            sid,
            self.deck.surfaces.len(),
            loc.clone(),
            kw.into(),
            field.into(),
        ));
        self.deck.surfaces.push(crate::deck::SurfaceCard {
            id,
            title: format!("{kw} {field} shell set {sid}"),
            def: crate::deck::SurfaceDef::Segments(Vec::new()),
            item_locs: vec![(0, loc.clone())],
            loc: loc.clone(),
        });
        id
    }

    /// Fills every surface made of a shell set with its shells' faces (a
    /// triangle's fourth node its third); an undefined set or shell is an
    /// error naming the keyword and field.
    pub fn resolve_shell_sets(&mut self) -> InputResult<()> {
        let used = std::mem::take(&mut self.shell_sets_used);
        if used.is_empty() {
            return Ok(());
        }
        let e = &self.deck.elements;
        let shells: std::collections::HashMap<Id, [Id; 4]> = e
            .shell4
            .iter()
            .map(|c| (c.id, [c.nodes[0], c.nodes[1], c.nodes[2], c.nodes[3]]))
            .chain(
                e.shell3
                    .iter()
                    .map(|c| (c.id, [c.nodes[0], c.nodes[1], c.nodes[2], c.nodes[2]])),
            )
            .collect();
        for (sid, si, loc, kw, field) in used {
            let Some((_, ids, set_loc)) = self.shell_sets.iter().find(|s| s.0 == sid) else {
                return Err(InputError::new(
                    loc,
                    &kw,
                    &field,
                    format!("shell set {sid} is not defined (expected a *SET_SHELL)"),
                ));
            };
            let mut segs = Vec::with_capacity(ids.len());
            for &eid in ids {
                let nodes = *shells.get(&eid).ok_or_else(|| {
                    InputError::new(
                        set_loc.clone(),
                        "*SET_SHELL",
                        "EID",
                        format!(
                            "shell {eid} of set {sid} is not defined (no *ELEMENT_SHELL gives it)"
                        ),
                    )
                })?;
                segs.push(crate::deck::SegmentCard {
                    id: segs.len() as Id + 1,
                    nodes,
                    loc: set_loc.clone(),
                });
            }
            self.deck.surfaces[si].def = crate::deck::SurfaceDef::Segments(segs);
        }
        Ok(())
    }

    /// The parts of `*SET_PART` `id`.
    pub fn part_set(&self, id: Id) -> Option<Vec<i64>> {
        self.part_sets
            .iter()
            .find(|(s, _)| *s == id)
            .map(|(_, p)| p.clone())
    }

    /// A node group of its own for `kind` over `items` (nodes or parts).
    pub fn own_group(
        &mut self,
        kind: crate::deck::NodeGroupKind,
        items: Vec<i64>,
        title: String,
        loc: &Loc,
    ) -> Id {
        let id = self.own_id();
        self.deck.node_groups.push(crate::deck::NodeGroupCard {
            id,
            title,
            kind,
            items,
            item_locs: vec![(0, loc.clone())],
            loc: loc.clone(),
        });
        id
    }
}

/// A translator: reads one keyword block into the records.
type Translate = fn(&Block, &mut Cards, &mut Ctx) -> InputResult<()>;

/// The keywords computed, by name (options `_TITLE`/`_ID` removed, see
/// [`base_name`]).
const TRANSLATORS: &[(&str, Translate)] = &[
    ("NODE", mesh::node),
    ("ELEMENT_SHELL", mesh::shell),
    ("ELEMENT_SOLID", mesh::solid),
    ("PART", mesh::part),
    ("SECTION_SHELL", sections::shell),
    ("SECTION_SOLID", sections::solid),
    ("MAT_ELASTIC", materials::elastic),
    ("MAT_001", materials::elastic),
    ("MAT_PLASTIC_KINEMATIC", materials::plastic_kinematic),
    ("MAT_003", materials::plastic_kinematic),
    ("MAT_JOHNSON_COOK", materials::johnson_cook),
    ("MAT_015", materials::johnson_cook),
    (
        "MAT_PIECEWISE_LINEAR_PLASTICITY",
        materials::piecewise_linear,
    ),
    ("MAT_024", materials::piecewise_linear),
    ("MAT_SPRING_ELASTIC", discrete::spring),
    ("MAT_S01", discrete::spring),
    ("MAT_DAMPER_VISCOUS", discrete::damper),
    ("MAT_S02", discrete::damper),
    ("SECTION_DISCRETE", discrete::section),
    ("ELEMENT_DISCRETE", discrete::element),
    ("MAT_RIGID", rigid::material),
    ("MAT_020", rigid::material),
    ("CONSTRAINED_NODAL_RIGID_BODY", rigid::nodal_body),
    ("CONSTRAINED_NODAL_RIGID_BODY_SPC", rigid::nodal_body),
    ("SET_NODE_LIST", conditions::node_set),
    ("SET_NODE", conditions::node_set),
    ("SET_PART_LIST", conditions::part_set),
    ("SET_SEGMENT", conditions::segment_set),
    ("SET_PART", conditions::part_set),
    ("SET_SHELL_LIST", conditions::shell_set),
    ("SET_SHELL", conditions::shell_set),
    ("BOUNDARY_SPC_NODE", conditions::spc_node),
    ("BOUNDARY_SPC_SET", conditions::spc_set),
    (
        "INITIAL_VELOCITY_GENERATION",
        conditions::velocity_generation,
    ),
    ("INITIAL_VELOCITY", conditions::velocity_set),
    ("INITIAL_VELOCITY_NODE", conditions::velocity_node),
    ("DEFINE_CURVE", conditions::curve),
    ("DEFINE_TRANSFORMATION", define_transformation::define),
    ("CONTACT_AUTOMATIC_SINGLE_SURFACE", contacts::single_surface),
    (
        "CONTACT_AUTOMATIC_NODES_TO_SURFACE",
        contacts::nodes_to_surface,
    ),
    (
        "CONTACT_AUTOMATIC_SURFACE_TO_SURFACE",
        contacts::surface_to_surface,
    ),
    ("CONTACT_TIED_NODES_TO_SURFACE", tied::tied),
    (
        "CONTACT_TIED_NODES_TO_SURFACE_CONSTRAINED_OFFSET",
        tied::tied,
    ),
    ("CONTACT_TIED_SURFACE_TO_SURFACE", tied::tied),
    (
        "CONTACT_TIED_SURFACE_TO_SURFACE_CONSTRAINED_OFFSET",
        tied::tied,
    ),
    ("CONTACT_TIED_NODES_TO_SURFACE_OFFSET", tied::tied),
    ("CONTACT_TIED_SURFACE_TO_SURFACE_OFFSET", tied::tied),
    ("CONTACT_TIED_SHELL_EDGE_TO_SURFACE_OFFSET", tied::tied),
    ("CONTACT_TIED_SHELL_EDGE_TO_SURFACE_BEAM_OFFSET", tied::tied),
    ("CONTACT_TIED_SHELL_EDGE_TO_SURFACE", tied::tied),
    (
        "CONTACT_TIED_SHELL_EDGE_TO_SURFACE_CONSTRAINED_OFFSET",
        tied::tied,
    ),
    ("CONTACT_AUTOMATIC_GENERAL", contacts::general),
    ("CONTACT_AUTOMATIC_GENERAL_INTERIOR", contacts::general),
    ("CONTROL_CONTACT", contacts::control),
    ("HOURGLASS", hourglass::hourglass),
    ("CONTROL_HOURGLASS", hourglass::control),
    ("RIGIDWALL_PLANAR", walls_masses::planar),
    ("RIGIDWALL_PLANAR_ORTHO", walls_masses::planar),
    ("RIGIDWALL_PLANAR_MOVING", walls_masses::planar),
    ("RIGIDWALL_PLANAR_MOVING_ID", walls_masses::planar),
    ("RIGIDWALL_PLANAR_FINITE", walls_masses::planar),
    ("ELEMENT_MASS", walls_masses::mass),
    ("BOUNDARY_PRESCRIBED_MOTION_NODE", loads::prescribed_motion),
    ("BOUNDARY_PRESCRIBED_MOTION_SET", loads::prescribed_motion),
    ("LOAD_NODE_POINT", loads::node_load),
    ("LOAD_NODE_SET", loads::node_load),
    ("LOAD_BODY_X", loads::body_load),
    ("LOAD_BODY_Y", loads::body_load),
    ("LOAD_BODY_Z", loads::body_load),
    ("CONTROL_TERMINATION", controls::termination),
    ("CONTROL_TIMESTEP", controls::timestep),
    ("DATABASE_BINARY_D3PLOT", controls::d3plot),
    ("TITLE", controls::title),
];

/// Keywords read by no translator that change nothing in the solution
/// (output requests), with why: noted, not fatal.
const SAFE_TO_SKIP: &[(&str, &str)] = &[
    (
        "DATABASE_",
        "an output request: it changes nothing in the solution",
    ),
    (
        "CONTROL_OUTPUT",
        "listing options: they change nothing in the solution",
    ),
    (
        "CONTROL_UNITS",
        "the units' names for output only: LS-DYNA converts no value of the deck with it, nor do we",
    ),
    (
        "CONTROL_ENERGY",
        "which energies are computed for output: it changes nothing in the solution",
    ),
];

/// The keyword without its `_TITLE` / `_ID` option, and whether it has them.
pub(crate) fn base_name(name: &str) -> (&str, bool, bool) {
    let (n, title) = match name.strip_suffix("_TITLE") {
        Some(n) => (n, true),
        None => (name, false),
    };
    match n.strip_suffix("_ID") {
        Some(b) => (b, title, true),
        None => (n, title, false),
    }
}

/// Reads the keyword deck at `path` into the Radioss reader's records.
pub fn read(path: &Path) -> InputResult<Deck> {
    let src = source::read(path)?;
    if !src.has_keyword_header {
        let at = src.blocks.first().map(|b| b.loc.clone()).unwrap_or(Loc {
            file: path.to_path_buf(),
            line: 1,
        });
        return Err(InputError::new(
            at,
            "*KEYWORD",
            "",
            "a keyword deck starts with *KEYWORD",
        ));
    }
    let params = parameters(&src.blocks)?;
    let mut ctx = Ctx {
        deck: Deck {
            path: path.to_path_buf(),
            begin: Some(begin(path, &src.blocks[0].loc)),
            ..Default::default()
        },
        params: &params,
        part_sets: Vec::new(),
        slsfac: 0.1,
        rwpnal: None,
        ignore_penetrations: false,
        contacts: Vec::new(),
        all_parts_surfaces: Vec::new(),
        all_parts_groups: Vec::new(),
        segment_sets_used: Vec::new(),
        node_sets_used: Vec::new(),
        part_sets_used: Vec::new(),
        shell_sets: Vec::new(),
        shell_sets_used: Vec::new(),
        discrete_sections: Vec::new(),
        discrete_materials: Vec::new(),
        hourglasses: Vec::new(),
        control_hourglass: None,
        part_hgid: Vec::new(),
        parts_without_hgid: Vec::new(),
        rigid: Vec::new(),
        moving_walls: Vec::new(),
        transformations: Vec::new(),
        transformed_nodes: Vec::new(),
        directed_in_transform: Vec::new(),
        next_group: OWN_GROUPS,
    };
    for b in &src.blocks {
        translate(b, &mut ctx)?;
    }
    define_transformation::finish(&mut ctx)?;
    ctx.resolve_part_sets()?;
    ctx.resolve_shell_sets()?;
    discrete::finish(&mut ctx)?;
    hourglass::finish(&mut ctx)?;
    contacts::finish(&mut ctx);
    rigid::finish(&mut ctx);
    walls_masses::finish(&mut ctx);
    references::check(&ctx)?;
    Ok(ctx.deck)
}

fn translate(b: &Block, ctx: &mut Ctx) -> InputResult<()> {
    let (base, _, _) = base_name(&b.name);
    if matches!(base, "KEYWORD" | "PARAMETER") {
        // The header, and the parameters (read before every other keyword).
        return Ok(());
    }
    let params = ctx.params;
    if let Some((_, f)) = TRANSLATORS.iter().find(|(n, _)| *n == base) {
        if define_transformation::has_directions(base) {
            define_transformation::note(ctx, b, None);
        }
        let mut cards = Cards::new(b, params);
        return f(b, &mut cards, ctx);
    }
    let w = |message: String| Warning {
        loc: b.loc.clone(),
        keyword: format!("*{}", b.name),
        message,
    };
    match SAFE_TO_SKIP.iter().find(|(k, _)| b.name.starts_with(k)) {
        Some((_, why)) => ctx.deck.warnings.push(w(format!(
            "keyword skipped ({} line(s)): {why}",
            b.lines.len()
        ))),
        None => {
            let u = w(format!(
                "keyword not supported; `run` stops on it (`run --skip-unsupported` skips its {} line(s))",
                b.lines.len()
            ));
            ctx.deck.warnings.push(u.clone());
            ctx.deck.unsupported.push(u);
        }
    }
    Ok(())
}

/// `*PARAMETER` cards: pairs of fields "Tname" (T the type: R, I or C)
/// and value, four pairs on a line.
fn parameters(blocks: &[Block]) -> InputResult<Parameters> {
    let mut out = Parameters::new();
    let none = Parameters::new();
    for b in blocks.iter().filter(|b| b.name == "PARAMETER") {
        let mut cards = Cards::new(b, &none);
        while let Some(c) = cards.next_opt(card::standard(b.long)) {
            for pair in 0..4 {
                let name = c.raw(2 * pair);
                if name.is_empty() {
                    continue;
                }
                let mut chars = name.chars();
                let ty = chars.next().unwrap_or(' ').to_ascii_uppercase();
                let rest = chars.as_str().trim();
                if !matches!(ty, 'R' | 'I' | 'C') || rest.is_empty() {
                    return Err(c.err(
                        "PRMR",
                        format!("'{name}': expected a type letter R, I or C followed by the name"),
                    ));
                }
                out.insert(rest.to_ascii_uppercase(), c.raw(2 * pair + 1).to_string());
            }
        }
    }
    Ok(out)
}

/// The run's header: its name is the deck's file stem; a keyword deck
/// carries no units (they are the deck's own, consistent).
fn begin(path: &Path, loc: &Loc) -> Begin {
    let stem = path
        .file_stem()
        .map(|s| s.to_string_lossy().to_string())
        .unwrap_or_else(|| "keyword".into());
    let units = Units {
        mass: "(deck)".into(),
        length: "(deck)".into(),
        time: "(deck)".into(),
        ..Units::default()
    };
    Begin {
        run_name: stem,
        invers: 0,
        irun: 0,
        input_units: units.clone(),
        work_units: units,
        loc: loc.clone(),
    }
}
