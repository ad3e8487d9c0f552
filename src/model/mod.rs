//! The model: what every stage after input reads. It speaks physics, not
//! an input format: materials and their laws, properties (section and
//! formulation choices), functions, loads and boundary conditions, contact
//! interfaces, rigid walls and bodies, output requests and run controls,
//! with every id resolved to a dense index, defaults applied and lumped
//! masses computed. A reader (`deck` for Radioss) fills it; serde
//! serializable so it (or a rank's share of it) can be sent to other ranks.
//!
//! Dense order is global id order: nodes and each element kind are sorted by
//! id, so "the fixed global order" of the determinism rules is index order.

pub mod contact;
mod controls;
mod element_kind;
mod function;
pub mod geometry;
mod input_error;
mod loads;
mod mass;
mod material;
mod output_request;
mod properties;
mod property;
mod rigid;
pub mod segment_geometry;
pub mod segment_orientation;
mod skew;
mod source_location;
pub mod tie_projection;

pub use contact::{InterfaceKind, InterfaceSpec, Side};
pub use controls::*;
pub use element_kind::ElementKind;
pub use function::Function;
pub use geometry::{geometry_edge_min, hexa_volume, quad_area, tetra_volume, triangle_area};
pub use input_error::{InputError, InputResult, Warning};
pub use loads::*;
pub use mass::{element_masses, lump, totals, MassSummary, PartMass};
pub use material::*;
pub use output_request::*;
pub use properties::{resolve_shell, resolve_solid, ResolvedShell, ResolvedSolid};
pub use property::*;
pub use rigid::*;
pub use skew::{Skew, SkewKind};
pub use source_location::Loc;

use serde::{Deserialize, Serialize};

/// An entity id as written in the input (strictly positive).
pub type Id = u64;

/// Node coordinates by dense index (ids ascending).
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub struct Nodes {
    pub ids: Vec<Id>,
    pub x: Vec<[f64; 3]>,
}

impl Nodes {
    pub fn len(&self) -> usize {
        self.ids.len()
    }
    pub fn is_empty(&self) -> bool {
        self.ids.is_empty()
    }
}

/// The elements of one kind (ids ascending), nodes flat with `kind.nodes()` per element.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct ElementSet {
    pub kind: ElementKind,
    pub ids: Vec<Id>,
    /// Part index of each element.
    pub part: Vec<u32>,
    /// Dense node indices, `kind.nodes()` per element; `u32::MAX` = absent
    /// (optional orientation node of a beam or spring).
    pub nodes: Vec<u32>,
    /// Shell thickness actually used (element's, else the property's); 0 for others.
    pub thick: Vec<f64>,
}

impl ElementSet {
    pub fn len(&self) -> usize {
        self.ids.len()
    }
    pub fn is_empty(&self) -> bool {
        self.ids.is_empty()
    }
    pub fn nodes_of(&self, e: usize) -> &[u32] {
        let n = self.kind.nodes();
        &self.nodes[e * n..(e + 1) * n]
    }
}

/// Absent optional node.
pub const NO_NODE: u32 = u32::MAX;

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Part {
    pub id: Id,
    pub title: String,
    /// Property and material indices (None: 0 in the deck, allowed for springs).
    pub prop: Option<u32>,
    pub mat: Option<u32>,
    pub subset: Id,
    pub thick: f64,
}

/// A property with the defaults that depend on /DEF_SHELL, /DEF_SOLID applied.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Property {
    pub card: PropertySpec,
    pub shell: Option<ResolvedShell>,
    pub solid: Option<ResolvedSolid>,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct NodeGroup {
    pub id: Id,
    pub title: String,
    /// Dense node indices, ascending, no repeats.
    pub nodes: Vec<u32>,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct ShellGroup {
    pub id: Id,
    pub title: String,
    /// Indices into the Shell4 element set.
    pub shells: Vec<u32>,
}

/// A contact surface: segments of 4 dense node indices (n4 = n3 for triangles),
/// oriented by the right-hand rule n1→n2→n3.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Surface {
    pub id: Id,
    pub title: String,
    pub segments: Vec<[u32; 4]>,
    /// /SURF/ELLIPS: an analytic hyper-ellipsoid (then no segments).
    #[serde(default)]
    pub ellipsoid: Option<Ellipsoid>,
}

/// /SURF/ELLIPS (reference guide): |(x−xc)/a|^n + |(y−yc)/b|^n + |(z−zc)/c|^n = 1
/// in the axes of skew_ID (0: global), n an integer >= 2 (default 2).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Ellipsoid {
    pub skew_id: Id,
    pub n: u32,
    pub center: [f64; 3],
    pub axes: [f64; 3],
}

impl Surface {
    /// Distinct nodes of the segments, ascending.
    pub fn nodes(&self) -> Vec<u32> {
        distinct_nodes(self.segments.iter().flatten().copied())
    }
}

/// The distinct nodes among `nodes` (of segments, edges ...), ascending.
pub fn distinct_nodes(nodes: impl IntoIterator<Item = u32>) -> Vec<u32> {
    let mut n: Vec<u32> = nodes.into_iter().collect();
    n.sort_unstable();
    n.dedup();
    n
}

/// A /LINE: 2-node segments (edges) of dense node indices, each once.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Line {
    pub id: Id,
    pub title: String,
    pub edges: Vec<[u32; 2]>,
}

/// An interface with its sides resolved.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Interface {
    pub card: InterfaceSpec,
    /// Secondary nodes, ascending dense indices.
    pub secondary_nodes: Vec<u32>,
    /// Main segments.
    pub main_segments: Vec<[u32; 4]>,
    /// Secondary segments, for interfaces that have them (TYPE3).
    pub secondary_segments: Vec<[u32; 4]>,
    /// Secondary and main edges, for edge-to-edge interfaces (TYPE11); in
    /// self-contact both sides hold the same edges.
    #[serde(default)]
    pub secondary_edges: Vec<[u32; 2]>,
    #[serde(default)]
    pub main_edges: Vec<[u32; 2]>,
}

/// A condition that applies to a node group.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct OnNodes<C> {
    pub card: C,
    pub nodes: Vec<u32>,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct RigidWall {
    pub card: RigidWallSpec,
    /// The node carrying a moving wall.
    pub node: Option<u32>,
    /// Point M (the moving node's position for a moving wall) and unit normal.
    pub point: [f64; 3],
    pub normal: [f64; 3],
    pub secondary_nodes: Vec<u32>,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct RigidBody {
    pub card: RigidBodySpec,
    pub main_node: u32,
    pub secondary_nodes: Vec<u32>,
    /// Mass of the body (secondary nodal masses + MASS), centre and inertia
    /// about the centre (xx, yy, zz, xy, yz, xz).
    pub mass: f64,
    pub center: [f64; 3],
    pub inertia: [f64; 6],
}

/// /PLOAD with its segments (dense node indices; a triangle repeats its
/// third node) and the element that carries each: (kind index in
/// `ElementKind::ALL`, element index within its kind). The carrier's rank
/// computes the segment's forces, and its deletion ends them (Idel 1).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct PressureLoad {
    pub card: PressureLoadSpec,
    pub segments: Vec<[u32; 4]>,
    pub carriers: Vec<(u8, u32)>,
}

/// A direction-and-function load or imposed motion, with its nodes.
pub type Bcs = OnNodes<BoundarySpec>;
pub type ImposedMotion = OnNodes<ImposedMotionSpec>;
pub type InitialVelocity = OnNodes<InitialVelocitySpec>;
pub type ConcentratedLoad = OnNodes<ConcentratedLoadSpec>;
pub type Gravity = OnNodes<GravitySpec>;
pub type Damping = OnNodes<DampingSpec>;

/// The model: what every later stage reads.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Model {
    pub name: String,
    pub title: String,
    pub begin: Begin,
    pub nodes: Nodes,
    /// One set per [`ElementKind`], in `ElementKind::ALL` order.
    pub elements: Vec<ElementSet>,
    pub parts: Vec<Part>,
    pub materials: Vec<MaterialSpec>,
    pub properties: Vec<Property>,
    pub functions: Vec<Function>,
    pub node_groups: Vec<NodeGroup>,
    pub shell_groups: Vec<ShellGroup>,
    pub surfaces: Vec<Surface>,
    pub bcs: Vec<Bcs>,
    pub imposed_velocities: Vec<ImposedMotion>,
    pub imposed_displacements: Vec<ImposedMotion>,
    pub initial_velocities: Vec<InitialVelocity>,
    pub concentrated_loads: Vec<ConcentratedLoad>,
    pub gravity: Vec<Gravity>,
    pub dampings: Vec<Damping>,
    pub rigid_walls: Vec<RigidWall>,
    pub rigid_bodies: Vec<RigidBody>,
    pub interfaces: Vec<Interface>,
    pub sections: Vec<CrossSectionSpec>,
    pub time_histories: Vec<TimeHistorySpec>,
    /// Final-geometry motions (/IMPDISP/FGEO).
    #[serde(default)]
    pub final_geometries: Vec<FinalGeometry>,
    /// Pressure loads (/PLOAD) with their segments.
    #[serde(default)]
    pub pressure_loads: Vec<PressureLoad>,
    /// Skew frames (/SKEW/FIX, /SKEW/MOV).
    #[serde(default)]
    pub skews: Vec<Skew>,
    /// Lumped nodal mass: elements + /ADMAS (rigid-body MASS is in `rigid_bodies`).
    pub nodal_mass: Vec<f64>,
    /// Rotational inertia of shell nodes (isotropic), see `mass`.
    pub nodal_inertia: Vec<f64>,
    /// /ADMAS mass per node (already included in `nodal_mass`).
    pub added_mass: Vec<f64>,
    pub mass: MassSummary,
    pub engine: Option<Engine>,
    pub warnings: Vec<Warning>,
    /// What the set-up changed of the input as the reference starter does
    /// (segments it turned round): the run listing prints them as notes,
    /// `check` as warnings.
    #[serde(default)]
    pub notes: Vec<Warning>,
    /// Keywords of the input that nothing computes (the keyword policy):
    /// `run` refuses the input while there are any, unless told to skip them.
    pub unsupported: Vec<Warning>,
}

impl RigidBody {
    /// Whether node `n` (global index) moves with the body: its main node
    /// or one of its (ascending) secondary nodes.
    pub fn holds(&self, n: u32) -> bool {
        n == self.main_node || self.secondary_nodes.binary_search(&n).is_ok()
    }
}

impl Model {
    /// The /FUNCT of id `id`.
    pub fn function(&self, id: Id) -> Option<&Function> {
        self.functions.iter().find(|f| f.id == id)
    }

    pub fn elements_of(&self, kind: ElementKind) -> &ElementSet {
        &self.elements[kind.index()]
    }
    pub fn n_elements(&self) -> usize {
        self.elements.iter().map(|s| s.len()).sum()
    }
}

/// Index of a DOF in a 6-vector (for conditions).
pub fn dof_index(d: Dof) -> usize {
    d.index()
}
