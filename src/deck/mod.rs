//! Radioss block-format reader (starter `NAME_0000.rad`, engine `NAME_0001.rad`).
//!
//! `source` turns files into keyword blocks, `fields` reads fixed-column
//! fields, and one file per keyword family turns blocks into typed cards that
//! keep their file:line; what the model holds as is (materials, properties,
//! functions, conditions, interfaces, controls) is read straight into the
//! model's types (`crate::model`). `to_model` then resolves every id and
//! builds the [`Model`](crate::model::Model): it is the only step that reads
//! a [`Deck`], so nothing outside this folder knows the Radioss cards.

pub mod fields;
pub mod source;

mod beam_props;
mod boxes;
mod conditions;
mod controls;
pub(crate) mod engine;
mod failure_tab;
mod failures;
mod id_index;
mod impdisp_fgeo;
mod interfaces;
mod joint_props;
pub mod keyword_policy;
mod lines;
mod list_end;
mod material_law12;
mod material_law21;
mod material_law27;
mod material_law36;
mod material_law44;
mod material_law62;
mod material_law70;
mod material_opening;
mod materials;
mod mesh;
mod move_funct;
mod parts;
mod pressure_load;
mod random_noise;
mod resolve_sets;
mod sets;
mod skews;
mod spring_props;
mod submodel;
pub mod supported;
mod to_model;

pub use controls::*;
pub use lines::{LineCard, LineDef, LineSegmentCard};
pub use mesh::*;
pub use parts::*;
pub use sets::*;
pub use to_model::build_model;

use crate::model::{
    AnimationSpec, Begin, BoundarySpec, ConcentratedLoadSpec, CrossSectionSpec, DefShell, DefSolid,
    Engine, Function, GravitySpec, Id, ImposedMotionSpec, InitialVelocitySpec, InputError,
    InputResult, InterfaceSpec, Loc, MaterialSpec, PropertySpec, RigidBodySpec, RigidWallSpec,
    TimeHistorySpec, Warning,
};

use fields::Cards;
use serde::{Deserialize, Serialize};
use source::Block;
use std::path::{Path, PathBuf};

/// Everything read from a starter deck (and its engine file, if any).
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub struct Deck {
    pub path: PathBuf,
    pub begin: Option<Begin>,
    pub title: String,
    pub controls: Controls,
    pub nodes: Vec<NodeCard>,
    pub elements: Elements,
    pub parts: Vec<PartCard>,
    pub materials: Vec<MaterialSpec>,
    /// Failure cards (/FAIL/...), attached to their materials by the model builder.
    pub failures: Vec<failures::FailureCard>,
    pub properties: Vec<PropertySpec>,
    pub def_shell: Option<DefShell>,
    pub def_solid: Option<DefSolid>,
    pub functions: Vec<Function>,
    pub added_masses: Vec<AddedMassCard>,
    pub node_groups: Vec<NodeGroupCard>,
    pub shell_groups: Vec<ShellGroupCard>,
    pub surfaces: Vec<SurfaceCard>,
    pub lines: Vec<LineCard>,
    pub subsets: Vec<SubsetCard>,
    pub bcs: Vec<BoundarySpec>,
    pub imposed_velocities: Vec<ImposedMotionSpec>,
    pub imposed_displacements: Vec<ImposedMotionSpec>,
    pub initial_velocities: Vec<InitialVelocitySpec>,
    pub concentrated_loads: Vec<ConcentratedLoadSpec>,
    pub gravity: Vec<GravitySpec>,
    pub dampings: Vec<crate::model::DampingSpec>,
    pub rigid_walls: Vec<RigidWallSpec>,
    pub rigid_bodies: Vec<RigidBodySpec>,
    pub sections: Vec<CrossSectionSpec>,
    pub interfaces: Vec<InterfaceSpec>,
    pub time_histories: Vec<TimeHistorySpec>,
    pub skews: Vec<skews::SkewCard>,
    pub boxes: Vec<boxes::BoxCard>,
    pub final_geometries: Vec<impdisp_fgeo::FgeoCard>,
    pub move_functs: Vec<move_funct::MoveFunct>,
    pub animations: Vec<AnimationSpec>,
    pub engine: Option<Engine>,
    pub warnings: Vec<Warning>,
    /// Keywords no parser reads and the policy does not let through (`run` stops on them).
    pub unsupported: Vec<Warning>,
    /// /PLOAD cards.
    #[serde(default)]
    pub pressure_loads: Vec<crate::model::PressureLoadSpec>,
    /// /RANDOM cards, in deck order.
    #[serde(default)]
    pub random_noises: Vec<random_noise::RandomCard>,
    /// //SUBMODEL blocks not yet closed by //ENDSUB (while reading).
    #[serde(default)]
    pub open_submodels: Vec<Loc>,
}

/// Reading options.
#[derive(Clone, Copy, Debug, Default)]
pub struct ReadOptions {
    /// Unknown keywords are errors instead of warnings.
    pub strict: bool,
}

/// Reads a starter deck, and the engine file `NAME_0001.rad` beside it when
/// `engine` is `Auto` and it exists (or the given file).
pub fn read_deck(starter: &Path, engine: EngineFile, opts: ReadOptions) -> InputResult<Deck> {
    let src = source::read(starter)?;
    let mut deck = Deck {
        path: starter.to_path_buf(),
        ..Default::default()
    };
    for block in &src.blocks {
        parse_starter_block(block, &mut deck, opts)?;
    }
    submodel::check_closed(&deck)?;
    move_funct::apply(&mut deck)?;
    if src.end.is_none() {
        let loc = src
            .blocks
            .last()
            .map(|b| {
                b.lines
                    .last()
                    .map(|l| l.loc.clone())
                    .unwrap_or(b.loc.clone())
            })
            .unwrap_or(Loc {
                file: starter.to_path_buf(),
                line: 0,
            });
        return Err(InputError::new(
            loc,
            "/END",
            "",
            "the starter deck ends without /END (truncated file?); expected /END as its last keyword",
        ));
    }
    if deck.begin.is_none() {
        return Err(InputError::new(
            Loc {
                file: starter.to_path_buf(),
                line: src.blocks.first().map(|b| b.loc.line).unwrap_or(1),
            },
            "/BEGIN",
            "",
            "no /BEGIN block; a starter deck opens with /BEGIN (title, version, units)",
        ));
    }
    let engine_path = match engine {
        EngineFile::None => None,
        EngineFile::Given(p) => Some(p),
        EngineFile::Auto => engine_beside(starter).filter(|p| p.is_file()),
    };
    if let Some(p) = engine_path {
        deck.engine = Some(read_engine(
            &p,
            &mut deck.warnings,
            &mut deck.unsupported,
            opts,
        )?);
    }
    Ok(deck)
}

/// Which engine file to read with the starter.
#[derive(Clone, Debug)]
pub enum EngineFile {
    /// `NAME_0001.rad` beside `NAME_0000.rad`, if present.
    Auto,
    None,
    Given(PathBuf),
}

/// `dir/NAME_0001.rad` for `dir/NAME_0000.rad`.
pub fn engine_beside(starter: &Path) -> Option<PathBuf> {
    let name = starter.file_name()?.to_str()?;
    let stem = name
        .strip_suffix("_0000.rad")
        .or_else(|| name.strip_suffix("_0000.RAD"))?;
    Some(starter.with_file_name(format!("{stem}_0001.rad")))
}

/// Reads an engine file (`NAME_0001.rad`).
pub fn read_engine(
    path: &Path,
    warnings: &mut Vec<Warning>,
    unsupported: &mut Vec<Warning>,
    opts: ReadOptions,
) -> InputResult<Engine> {
    let src = source::read_as(path, source::LineFormat::Free)?;
    let mut eng = Engine::default();
    for block in &src.blocks {
        if !engine::parse_engine_block(block, &mut eng)? {
            unknown_keyword(block, warnings, unsupported, opts, "engine")?;
        }
    }
    Ok(eng)
}

fn unknown_keyword(
    block: &Block,
    warnings: &mut Vec<Warning>,
    unsupported: &mut Vec<Warning>,
    opts: ReadOptions,
    file_kind: &str,
) -> InputResult<()> {
    if opts.strict && keyword_policy::safe_to_skip(block).is_none() {
        return Err(InputError::new(
            block.loc.clone(),
            &block.header,
            "",
            format!("keyword not supported in the {file_kind} file (--strict)"),
        ));
    }
    keyword_policy::not_read(block, file_kind, warnings, unsupported);
    Ok(())
}

/// Reads one starter block; a keyword no family reads (or a variant of one
/// that its family does not know) goes to the keyword policy.
fn parse_starter_block(block: &Block, deck: &mut Deck, opts: ReadOptions) -> InputResult<()> {
    let handled = match read_starter_block(block, deck) {
        Err(e) if e.variant_not_read => false,
        r => r?,
    };
    if !handled {
        unknown_keyword(
            block,
            &mut deck.warnings,
            &mut deck.unsupported,
            opts,
            "starter",
        )?;
    }
    Ok(())
}

/// Dispatches one starter block to its family's parser; false when none reads it.
pub(crate) fn read_starter_block(block: &Block, deck: &mut Deck) -> InputResult<bool> {
    let p: Vec<&str> = block.parts.iter().map(String::as_str).collect();
    Ok(match p[0] {
        "BEGIN" => {
            submodel::refuse_begin_inside(block, deck)?;
            controls::parse_begin(block, deck).map(|_| true)?
        }
        "/SUBMODEL" | "/ENDSUB" => submodel::parse_submodel(block, deck)?,
        "TITLE" => {
            let mut cards = Cards::new(block);
            deck.title = cards.title();
            warn_surplus(&cards, "the title", &mut deck.warnings);
            true
        }
        "ANALY" | "SPMD" | "IOFLAG" | "SHFRA" => controls::parse_control(block, deck)?,
        "TH" => controls::parse_th(block, deck)?,
        "ANIM" => controls::parse_anim(block, deck)?,
        "NODE" => mesh::parse_nodes(block, deck).map(|_| true)?,
        "SHELL" | "SH3N" | "BRICK" | "TETRA4" | "SPRING" | "TRUSS" | "BEAM" => {
            mesh::parse_elements(block, deck).map(|_| true)?
        }
        "PART" => parts::parse_part(block, deck).map(|_| true)?,
        "MAT" => materials::parse_material(block, deck)?,
        "FAIL" => failures::parse_failure(block, deck)?,
        "PROP" => parts::parse_property(block, deck)?,
        "DEF_SHELL" | "DEF_SOLID" => parts::parse_defaults(block, deck).map(|_| true)?,
        "FUNCT" => parts::parse_function(block, deck).map(|_| true)?,
        "ADMAS" => parts::parse_admas(block, deck)?,
        "GRNOD" | "GRSHEL" | "SURF" | "SUBSET" => sets::parse_set(block, deck)?,
        "LINE" => lines::parse_line(block, deck)?,
        "RANDOM" => random_noise::parse_random(block, deck)?,
        "PLOAD" => pressure_load::parse_pload(block, deck)?,
        "SKEW" => skews::parse_skew(block, deck)?,
        "BOX" => boxes::parse_box(block, deck)?,
        "IMPDISP" if block.parts.get(1).is_some_and(|p| p == "FGEO") => {
            impdisp_fgeo::parse_fgeo(block, deck)?
        }
        "MOVE_FUNCT" => move_funct::parse_move_funct(block, deck)?,
        "BCS" | "IMPVEL" | "IMPDISP" | "INIVEL" | "CLOAD" | "GRAV" | "DAMP" | "RWALL" | "RBODY"
        | "SECT" => conditions::parse_condition(block, deck)?,
        "INTER" => interfaces::parse_interface(block, deck)?,
        _ => false,
    })
}

/// One warning when a fixed-card block has non-blank lines after its last
/// card (`what` names that card, e.g. "the title"): they are ignored.
pub(crate) fn warn_surplus(cards: &Cards, what: &str, warnings: &mut Vec<Warning>) {
    let mut extra = cards
        .remaining()
        .iter()
        .filter(|l| !l.text.trim().is_empty());
    if let Some(first) = extra.next() {
        warnings.push(Warning {
            loc: first.loc.clone(),
            keyword: cards.block.header.clone(),
            message: format!(
                "{} line(s) after {what} are ignored; expected the next keyword here",
                1 + extra.count()
            ),
        });
    }
}

/// The id that follows the keyword name in the header (`/PART/12` → 12),
/// at position `idx` of the header parts. Must be a positive integer.
pub(crate) fn header_id(block: &Block, idx: usize, name: &str) -> InputResult<Id> {
    let t = block.parts.get(idx).map(String::as_str).unwrap_or("");
    if t.is_empty() {
        return Err(InputError::new(
            block.loc.clone(),
            &block.header,
            name,
            format!(
                "missing {name} in the keyword line; expected e.g. {}/1",
                block.header
            ),
        ));
    }
    match fields::parse_int(t) {
        Ok(v) if v > 0 => Ok(v as Id),
        _ => {
            let mut e = InputError::new(
                block.loc.clone(),
                &block.header,
                name,
                format!("'{t}' in the keyword line: expected a positive integer id"),
            );
            // A word where the id belongs names a variant of the keyword
            // (`/IMPDISP/FGEO/10`, `/SURF/PART/FOO/1`) that this family's
            // reader does not know: unsupported by name, not a syntax error.
            e.variant_not_read = t.starts_with(|c: char| c.is_ascii_alphabetic());
            Err(e)
        }
    }
}

/// An optional id in the header (unit_ID etc.): 0 when absent.
pub(crate) fn header_id_opt(block: &Block, idx: usize, name: &str) -> InputResult<Id> {
    match block.parts.get(idx).map(|s| s.trim()) {
        None | Some("") => Ok(0),
        Some(t) => match fields::parse_int(t) {
            Ok(v) if v >= 0 => Ok(v as Id),
            _ => Err(InputError::new(
                block.loc.clone(),
                &block.header,
                name,
                format!("'{t}' in the keyword line: expected a non-negative integer"),
            )),
        },
    }
}

impl<'a> fields::Card<'a> {
    /// A 10-column id field that must be given and positive.
    pub fn id(&self, col: usize, name: &str) -> InputResult<Id> {
        match self.int_opt(col, 10, name)? {
            Some(v) if v > 0 => Ok(v as Id),
            Some(v) => Err(self.err(name, format!("{v}: expected a positive id"))),
            None => Err(self.err(name, "blank: expected a positive id")),
        }
    }

    /// A 10-column optional id field: 0 (or blank) means none.
    pub fn id_opt(&self, col: usize, name: &str) -> InputResult<Id> {
        match self.int_opt(col, 10, name)? {
            None | Some(0) => Ok(0),
            Some(v) if v > 0 => Ok(v as Id),
            Some(v) => Err(self.err(name, format!("{v}: expected a positive id or 0"))),
        }
    }

    /// A 10-column flag that must be one of `allowed` (blank → `default`).
    pub fn flag(&self, col: usize, name: &str, default: i64, allowed: &[i64]) -> InputResult<i64> {
        let v = self.int(col, name, default)?;
        if allowed.contains(&v) {
            Ok(v)
        } else {
            Err(self.err(name, format!("{v}: expected one of {allowed:?}")))
        }
    }

    /// A 20-column real that must be > 0 (`what` says what it is).
    pub fn positive_real(&self, col: usize, name: &str, what: &str) -> InputResult<f64> {
        let v = self.real(col, name, 0.0)?;
        if v > 0.0 {
            Ok(v)
        } else {
            Err(self.err(name, format!("{v}: {what} must be > 0")))
        }
    }
}
