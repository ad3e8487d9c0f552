//! Interface types as compositions of geometry, stiffness, gap and friction,
//! one file per type, behind one trait ([`InterfaceType`]) and one registry
//! ([`TypeOptions`], the `registry!` table at the end of this file).
//!
//! A type says what its pairs are made of ([`CandidateKind`]), how their
//! candidates are found ([`CandidateSearch`]: a box sort of the whole main
//! side, or a walk from the last closest segment), what one pair's force is
//! (its kernel: stiffness, gap, friction), what it adds to the time step, and
//! how it treats a pair found penetrated at the first sort. `ContactSystem`
//! (the runtime, `contact/mod.rs` and `contact/pairs.rs`) dispatches through
//! the trait and never names a type.
//!
//! Adding a type: one file here implementing [`InterfaceType`] on the
//! type's own options struct, and one line in `registry!`
//! (`11 => type11::Type11`). The runtime lays out node-to-segment pairs and
//! edge-to-edge pairs (`contact::pairs`, `setup::Pass`, `contact::edge_setup`);
//! the first type of another [`CandidateKind`] also teaches it that kind's
//! sides once.
//!
//! Restart: a type's pair memory lives in the records `contact::restart`
//! writes for every type (`NodeState`, the candidates' `PairState`, the walk
//! pair); none of today's types has state of its own beyond them.
//!
//! TYPE2 (`type2.rs`, run by `contact::tied`) is not in the registry: it is
//! a kinematic condition, not a penalty force. It has no candidates and no
//! search (each secondary node is tied once, at set-up, to one segment), and
//! it acts in other phases of the cycle than the contact forces: it adds
//! masses and inertias before the first cycle, moves the secondary nodes'
//! forces and moments to the main nodes after all forces are known, and
//! recovers the secondary nodes' velocities after the velocity update and
//! their positions after the position update. Its table also tracks
//! rotational degrees of freedom, which contact nodes do not have.
//!
//! Each kernel turns one measured pair into the force on the secondary side;
//! the main side takes −N_i times it (EQ. 8.6.6.4–6).

pub mod edge_pair;
pub mod ellipsoid;
pub mod layout;
pub mod type2;

use super::friction::FrictionLaw;
use super::gap::{GapRule, InitialPenetration};
use super::geometry::V3;
use crate::model;
use crate::model::InterfaceKind;
use layout::{Interface, Pass};
use serde::{Deserialize, Serialize};
use std::borrow::Cow;

/// What a pair is made of: the entity on each side.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CandidateKind {
    /// A secondary node against a main segment (TYPE3, 5, 7).
    NodeToSegment,
    /// An edge against an edge (TYPE11, TYPE25 edges).
    EdgeToEdge,
    /// A segment against a segment (LS-DYNA's SOFT = 2).
    SegmentToSegment,
    /// A node against an ellipsoid (TYPE14).
    NodeToEllipsoid,
    /// A segment's triangle against an ellipsoid (TYPE15).
    SegmentToEllipsoid,
}

/// How a type finds the candidates of its secondary nodes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CandidateSearch {
    /// Every main segment within gap + sorting margin (box search), rebuilt
    /// when the motion since the last sort passes half the margin.
    Sort,
    /// One segment per node, walked to from the last cycle's closest segment
    /// ([`InterfaceType::walk`]).
    Walk,
    /// No segments: every secondary node against the type's analytic main
    /// surface (TYPE14's ellipsoid), which moves with a rigid body; the
    /// kernel screens the node itself.
    Analytic,
}

/// The most nodes on one side of a pair (a quadrilateral segment).
pub const SIDE_NODES: usize = 4;

/// The nodes (cnodes) of one side of a pair: a node (1), an edge (2), a
/// triangle (3) or a quadrilateral (4).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Side {
    pub nodes: [u32; SIDE_NODES],
    pub count: u8,
}

impl Side {
    pub fn node(c: u32) -> Side {
        Side {
            nodes: [c, c, c, c],
            count: 1,
        }
    }
    /// An edge (2 nodes; the second repeats itself).
    pub fn edge(e: [u32; 2]) -> Side {
        Side {
            nodes: [e[0], e[1], e[1], e[1]],
            count: 2,
        }
    }
    /// A main entity as `Pass::segs` stores it: a quadrilateral, a triangle
    /// (its third node repeated: 3 nodes) or an edge (its second node
    /// repeated: 2 nodes).
    pub fn segment(seg: &[u32; 4]) -> Side {
        let count = if seg[3] != seg[2] {
            4
        } else if seg[2] != seg[1] {
            3
        } else {
            2
        };
        Side { nodes: *seg, count }
    }
    pub fn nodes(&self) -> &[u32] {
        &self.nodes[..self.count as usize]
    }
}

/// The two sides of one pair.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PairNodes {
    pub sec: Side,
    pub main: Side,
}

/// Weights of a lone secondary node (node-to-segment, node-to-ellipsoid).
pub const NODE_SHAPE: [f64; SIDE_NODES] = [1.0, 0.0, 0.0, 0.0];

/// What one pair gives.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PairForce {
    /// Force on the secondary side.
    pub fs: V3,
    /// Weights of the secondary side's nodes: node j takes +w_j·fs
    /// ([`NODE_SHAPE`] for a node).
    pub sec_shape: [f64; SIDE_NODES],
    /// Shape functions of the contact point on the main side's nodes: node i
    /// takes −N_i·fs.
    pub shape: [f64; SIDE_NODES],
    /// Tangent stiffness (for the nodal time step, EQ. 8.8.5.2).
    pub kt: f64,
    /// Kinematic time step 0.5·(Gap − p)/(dp/dt) (EQ. 8.8.5.1), ∞ if not closing.
    pub dt_kin: f64,
    /// Normal force magnitude and tangential force.
    pub f_n: f64,
    pub f_t: V3,
    /// Penetration and the direction the normal force pushes the secondary node.
    pub pen: f64,
    pub dir: V3,
    /// The contact point.
    pub point: V3,
}

/// Friction and tie memory of one node–segment pair.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct PairState {
    /// Tangential force of the last cycle (incremental form).
    pub ft: V3,
    /// Filtered tangential force (Ifiltr).
    pub ff: V3,
    /// ITIED: the node is tied to this point of the segment (shape, offset).
    pub tie: Option<([f64; 4], V3)>,
    /// Side of the segment (sign of the normal distance) at the last cycle in contact; 0 = none.
    pub side: i8,
    /// Penetration-based types (TYPE25): the penetration at the impact
    /// (the baseline only further penetration pushes against), and the
    /// penetration and stiffness of the last cycle.
    pub pen_memory: [f64; 3],
}

/// Per secondary node memory (owned secondary nodes of a pass).
#[derive(Clone, Debug, Default, serde::Serialize, serde::Deserialize)]
pub struct NodeState {
    /// Removed from the interface (Inacti = 1, Fpenmax, dtmin with ITIED = 0).
    pub off: bool,
    /// Walk types: the closest segment at the last cycle.
    pub last_seg: u32,
    /// Inacti = 2: segments deactivated for this node.
    pub off_segs: Vec<u32>,
    /// Inacti = 5, 6: (segment, corrected gap, clearance the node keeps below
    /// it: 0 with Inacti = 5, 5% of the initial distance with 6).
    pub gap0: Vec<(u32, f64, f64)>,
}

/// The options every type reads from its card, kept on `setup::Interface`.
#[derive(Clone, Debug, PartialEq)]
pub struct CardCommon {
    pub stfac: f64,
    pub friction: FrictionLaw,
    /// The card's gap (Gapmin on TYPE7, Gap on TYPE3, 5).
    pub gap_card: f64,
    pub tstart: f64,
    pub tstop: f64,
    pub ibc: [bool; 3],
    pub inacti: i64,
    pub idel: i64,
}

/// Sizes of an interface's main segments (all passes), for the default gap.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceSizes {
    /// Shell segments: their number, summed and smallest thickness.
    pub n_shell: usize,
    pub thick_sum: f64,
    pub thick_min: f64,
    /// Smallest edge (0 when there is none).
    pub l_min: f64,
    /// Edge-to-edge interfaces: the default Gapmin of their edges (0 otherwise).
    pub edge_gapmin: f64,
}

/// One pass's sides on the model: secondary nodes (global, ascending), the
/// segments whose element stiffness the secondary nodes take (TYPE3's own
/// surface; `None`: from the nodes' elements), and the main segments; or,
/// for an edge-to-edge pass, the secondary and main edges.
pub struct PassSides<'a> {
    pub sec: Vec<u32>,
    pub own: Option<&'a [[u32; 4]]>,
    pub main: &'a [[u32; 4]],
    /// Edge-to-edge passes (empty otherwise): global node indices.
    pub sec_edges: &'a [[u32; 2]],
    pub main_edges: &'a [[u32; 2]],
    /// Segment-to-segment passes (empty otherwise): the secondary segments
    /// (global node indices) against `main`.
    pub sec_segs: Cow<'a, [[u32; 4]]>,
    /// Both sides are the same edges (self-contact): each pair of edges is
    /// computed once.
    pub self_contact: bool,
}

/// One measured pair, as the kernel sees it.
pub struct PairContext<'a> {
    pub it: &'a Interface,
    pub p: &'a Pass,
    /// Secondary entity (index into `p.sec` or `p.sec_edges`) and main
    /// entity (index into `p.segs`).
    pub k: usize,
    pub m: u32,
    /// The secondary side's first node: position, velocity, nodal mass.
    pub xs: V3,
    pub vs: V3,
    pub ms: f64,
    /// Every node of the secondary side (a node repeats itself, an edge its
    /// second node: see [`Side`]).
    pub xs_side: &'a [V3; SIDE_NODES],
    pub vs_side: &'a [V3; SIDE_NODES],
    /// The pair's two sides as cnodes.
    pub sec: Side,
    pub main: Side,
    /// Initial nodal mass of every contact node (the same on every rank,
    /// for the dampers of pairs whose main nodes may be ghosts).
    pub cnode_mass: &'a [f64],
    pub xm: &'a [V3; 4],
    pub vm: &'a [V3; 4],
    pub dt: f64,
    /// The rigid bodies at the start of the step (replicated on every rank):
    /// analytic main surfaces move with them.
    pub bodies: &'a [crate::kinematics::rigid_body::RigidBodyState],
    /// Total-force types ([`InterfaceType::total_force`]): `None` while the
    /// runtime measures the pairs (the kernel gives the penetration vector
    /// p·n as `fs`, `pen` = p, and leaves the pair memory as it is);
    /// `Some(fac)` when it computes the forces, fac being the interface's
    /// normal force per unit penetration this cycle. `None` for other types.
    pub scale: Option<f64>,
    /// The interface's memory this cycle ([`InterfaceType::advance_memory`]),
    /// the same on every rank.
    pub memory: [f64; 2],
}

/// What a kernel decides for one pair.
pub enum PairOutcome {
    /// No force (out of the gap, beyond the segment).
    Free,
    Force(PairForce),
    /// The secondary node leaves the interface now (dtmin with ITIED = 0):
    /// none of its pairs of this cycle counts.
    NodeOff,
}

/// An interface type: its options are the struct that implements it.
pub trait InterfaceType: Sync {
    /// The /INTER/TYPEn number.
    fn type_number(&self) -> u32;

    /// What its pairs are made of.
    fn candidate_kind(&self) -> CandidateKind;

    /// How its candidates are found.
    fn search(&self) -> CandidateSearch;

    /// Its options and the common ones from the deck's card, `None` when the
    /// card is of another type.
    fn from_card(kind: &InterfaceKind) -> Option<(Self, CardCommon)>
    where
        Self: Sized;

    /// The first option of the deck's card (of this type) that the engine
    /// does not compute, named for the refusal; `None` when it computes them all.
    fn unsupported(_kind: &InterfaceKind) -> Option<&'static str>
    where
        Self: Sized,
    {
        None
    }

    /// Its passes: by default one, the secondary nodes against the main segments.
    fn passes<'a>(&self, i: &'a model::Interface) -> Vec<PassSides<'a>> {
        vec![PassSides {
            sec: i.secondary_nodes.clone(),
            own: None,
            main: &i.main_segments,
            sec_edges: &[],
            main_edges: &[],
            sec_segs: Cow::Borrowed(&[]),
            self_contact: false,
        }]
    }

    /// Igap as the card gives it (0 when the type has no gap flag): the
    /// edge set-up's default Gapmin depends on it.
    fn igap(&self) -> i64 {
        0
    }

    /// Its gap rule (constant, variable, default from the surface sizes).
    fn gap_rule(&self, common: &CardCommon, sizes: &SurfaceSizes) -> GapRule;

    /// Bumult: the sorting margin as a fraction of the mean segment edge.
    fn sorting_margin(&self) -> f64;

    /// Stiffness of a main segment on a solid of bulk modulus `bulk`, with
    /// the segment's `area` and the element's `volume`.
    fn solid_segment_stiffness(&self, bulk: f64, area: f64, volume: f64) -> f64;

    /// A type's own penalty stiffness of the element under a main segment
    /// (`main`) or around a secondary node, replacing the Radioss rules
    /// (shells 0.5·E·t, solids [`Self::solid_segment_stiffness`] and
    /// B·V^(1/3)); `None` keeps them.
    fn element_stiffness(
        &self,
        _el: &crate::contact::stiffness::ElementSize,
        _main: bool,
    ) -> Option<f64> {
        None
    }

    /// The stiffness of pair (secondary k, segment m).
    fn pair_stiffness(&self, it: &Interface, p: &Pass, k: usize, m: usize) -> f64;

    /// Walk types: the node's segment this cycle from the last one `s0`
    /// (`x_of`: a cnode's position, `None` when not on this rank; `seg_on`:
    /// false for segments removed by Idel).
    fn walk(
        &self,
        _it: &Interface,
        _p: &Pass,
        _s0: u32,
        _xs: V3,
        _x_of: &dyn Fn(u32) -> Option<V3>,
        _seg_on: &dyn Fn(u32) -> bool,
    ) -> Option<u32> {
        None
    }

    /// How much farther than gap + 2·margin + segment size the ghost boxes
    /// reach (a walk reads the segments around the nodes it passes).
    fn walk_reach(&self, _max_diag: f64) -> f64 {
        0.0
    }

    /// Whether a face between two solids may be a main segment from the
    /// start (TYPE7, 3, 5: yes; TYPE25 keeps such a face dormant until one
    /// of its solids is deleted, `contact::inner_faces`).
    fn inner_solid_faces_as_segments(&self) -> bool {
        true
    }

    /// Whether the secondary nodes' stiffness is the reference starter's
    /// assembled nodal stiffness (solids' B̄·(2·V_n)^(1/3) plus the shells'
    /// mean E·t, `element_data::assembled_node_stiffness`) instead of the
    /// largest of TYPE7's per-element rules.
    fn assembled_node_stiffness(&self) -> bool {
        false
    }

    /// Whether a secondary node takes the force of one main segment only,
    /// the nearest of its candidates in contact ([`Self::nearness`]), with
    /// one pair memory per node (TYPE25: the reference engine keeps one
    /// candidate per node), rather than the sum over its candidates.
    fn one_segment_per_node(&self) -> bool {
        false
    }

    /// One-segment types: how near the node is to the segment (larger is
    /// chosen) and the side of the segment it is on, given the side it was
    /// on (0: none yet); `None` when out of contact. Nothing changes.
    fn nearness(&self, _c: &PairContext, _side: i8) -> Option<(f64, i8)> {
        None
    }

    /// Igap0 = 1 (TYPE25): secondary nodes on a free edge of the shells take
    /// no gap of their own.
    fn zero_gap_on_free_shell_edges(&self) -> bool {
        false
    }

    /// Irem_gap = 2: the sort leaves out main segments with a node closer
    /// than 2·Gapmin to the secondary node in the initial configuration.
    fn removes_initially_close(&self) -> bool {
        false
    }

    /// Resolves what the type takes from the model beyond its card (the
    /// rigid bodies of TYPE6's surfaces, load curves), `kw` naming the card
    /// in messages; an inconsistent deck is an error.
    fn bind(&mut self, _m: &model::Model, _i: &model::Interface, _kw: &str) -> Result<(), String> {
        Ok(())
    }

    /// Whether the interface's total normal force is a function of its
    /// largest penetration (TYPE6, EQ. 8.7.6.1): then each cycle the runtime
    /// first measures every pair (kernel with `PairContext::scale` = `None`),
    /// reduces the largest penetration p_max and the resultant penetration
    /// vector R = Σ_pass sign·Σ p_i·n_i over all ranks (exactly, so on any
    /// number of ranks the same bits), and then computes the forces with
    /// fac = F(p_max)/|R| (`scale` = `Some(fac)`), so the resultant normal
    /// force is F(p_max).
    fn is_total_force(&self) -> bool {
        false
    }

    /// Total-force types: the sign of pass `pass`'s penetration vectors in
    /// the resultant R (each pass's secondary side's vectors, counted on
    /// the first side).
    fn resultant_sign(&self, _pass: usize) -> f64 {
        1.0
    }

    /// Total-force types: the total normal force at the largest penetration
    /// `p_max` (0 when nothing penetrates), and the interface's time step
    /// (∞ when it sets none). `memory` is the interface's from the last
    /// cycle (zeros at the start), the same on every rank; the type keeps
    /// what it needs there (TYPE6 Iform 1/2: the last p_max and force).
    fn total_force(&self, _p_max: f64, _memory: &mut [f64; 2]) -> (f64, f64) {
        (0.0, f64::INFINITY)
    }

    /// Types that are not total-force ones: the interface's memory from
    /// cycle to cycle (zeros at the start, the same on every rank), advanced
    /// once per cycle before the pairs with this cycle's step `dt` (0 before
    /// the first step); the kernels read it as `PairContext::memory`.
    fn advance_memory(&self, _memory: &mut [f64; 2], _dt: f64) {}

    /// Analytic main surfaces on a rigid body: the body (index into the
    /// model's rigid bodies) that takes each pair's reaction, −F at the
    /// contact point (`PairForce::point`).
    fn reaction_body(&self) -> Option<usize> {
        None
    }

    /// The pair kernel: the force of one pair, and its memory.
    fn pair(&self, c: &PairContext, ns: &mut NodeState, st: &mut PairState) -> PairOutcome;

    /// A reach beyond which pair (k, m) of a secondary node is free whatever
    /// the velocities: a node at least this far from segment `m` (from its
    /// closest point, `segment_geometry::project`, and so also one farther
    /// than it from the ball holding the segment's nodes) makes
    /// [`Self::pair`] return `Free`, having done to the pair's memory only
    /// [`Self::when_free`]. The pass then skips the pair without gathering
    /// its velocities, or even its positions while the distance at the last
    /// sort less twice the motion since exceeds the reach (most candidates
    /// of a sort are out of reach at a given cycle). `None`: every pair goes
    /// to the kernel.
    fn free_beyond(
        &self,
        _it: &Interface,
        _p: &Pass,
        _k: usize,
        _m: usize,
        _ns: &NodeState,
        _st: &PairState,
    ) -> Option<f64> {
        None
    }

    /// What [`Self::pair`] does to the memory of a pair beyond
    /// [`Self::free_beyond`]'s reach.
    fn when_free(&self, _st: &mut PairState) {}

    /// Its time step contribution: the kinematic step of a pair (EQ.
    /// 8.8.5.1), `None` when the type does not limit it. (Every pair limits
    /// the nodal step through its tangent stiffness `PairForce::kt`.)
    fn kinematic_step(&self, _f: &PairForce) -> Option<f64> {
        None
    }

    /// Its initial-penetration rule: what happens to a pair of gap `g` found
    /// penetrated at the first sort, and the penetration it measured. By
    /// default the pair is kept as it is: types whose pairs take the
    /// initial penetration as a baseline (TYPE25, LS-DYNA's SOFT 2), whose
    /// edge pairs the runtime decides (`contact::edge_initial_penetrations`),
    /// whose nodes meet an analytic surface (TYPE14), or whose total force
    /// counts an initial intersection in p_max (TYPE6, Icor = 0).
    fn initial_penetration(
        &self,
        _it: &Interface,
        _xs: V3,
        _xm: &[V3; 4],
        _tri: bool,
        _g: f64,
    ) -> (InitialPenetration, f64) {
        (InitialPenetration::Keep, 0.0)
    }
}

/// The /FUNCT a card's field names, for a type's `bind`; an error naming
/// the card (`kw`) and the field when it is not defined.
pub fn bound_curve(
    m: &model::Model,
    id: model::Id,
    kw: &str,
    field: &str,
) -> Result<model::Function, String> {
    m.function(id)
        .cloned()
        .ok_or_else(|| format!("{kw}, field {field}: /FUNCT/{id} is not defined"))
}

/// [`bound_curve`] for an optional field: id 0 names no curve.
pub fn optional_curve(
    m: &model::Model,
    id: model::Id,
    kw: &str,
    field: &str,
) -> Result<Option<model::Function>, String> {
    match id {
        0 => Ok(None),
        id => bound_curve(m, id, kw, field).map(Some),
    }
}

/// An optional curve's value at x over its abscissa scale, `none` without
/// a curve (a factor's 1, a term's 0).
pub fn curve_at(f: &Option<model::Function>, x: f64, ascale: f64, none: f64) -> f64 {
    f.as_ref().map_or(none, |f| {
        crate::kinematics::function::scaled(f, x, ascale, 1.0)
    })
}

/// Work done on a type known at compile time ([`TypeOptions::visit`]).
pub trait TypeVisitor {
    type Out;
    fn visit<T: InterfaceType>(self, t: &T) -> Self::Out;
}

/// The registry: one line per interface type, `number => file::Type`.
/// It declares the type's file (module), and makes [`TypeOptions`] (a
/// serialisable enum with one variant per type, holding the type's options),
/// its dispatch to the type's [`InterfaceType`], the look-up by type number
/// and the conversion from the deck's card.
macro_rules! registry {
    ($($number:literal => $file:ident :: $variant:ident),* $(,)?) => {
        $(pub mod $file;)*

        /// The options of one registered interface type.
        #[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
        pub enum TypeOptions {
            $($variant($file::$variant)),*
        }

        impl TypeOptions {
            /// The type's implementation.
            pub fn implementation(&self) -> &dyn InterfaceType {
                match self {
                    $(TypeOptions::$variant(t) => t),*
                }
            }

            /// The type's implementation, to bind it to the model.
            pub fn implementation_mut(&mut self) -> &mut dyn InterfaceType {
                match self {
                    $(TypeOptions::$variant(t) => t),*
                }
            }

            /// `v.visit(t)` on the type `t`, statically dispatched (the
            /// per-pair loops are compiled for each type, so its kernel
            /// inlines).
            pub fn visit<V: TypeVisitor>(&self, v: V) -> V::Out {
                match self {
                    $(TypeOptions::$variant(t) => v.visit(t)),*
                }
            }

            /// The type of number `n` with its default options.
            pub fn by_number(n: u32) -> Option<TypeOptions> {
                match n {
                    $($number => Some(TypeOptions::$variant(<$file::$variant>::default())),)*
                    _ => None,
                }
            }

            /// The type numbers the engine computes.
            pub const NUMBERS: &'static [u32] = &[$($number),*];

            /// Whether the engine computes the deck's card: `Err(None)` for a
            /// type it does not register, `Err(Some(option))` for an option of
            /// a registered type it does not compute.
            pub fn check_card(kind: &InterfaceKind) -> Result<(), Option<&'static str>> {
                $(if <$file::$variant as InterfaceType>::from_card(kind).is_some() {
                    return match <$file::$variant as InterfaceType>::unsupported(kind) {
                        None => Ok(()),
                        Some(what) => Err(Some(what)),
                    };
                })*
                Err(None)
            }

            /// The type of the deck's card, with the common options; `None`
            /// for a card of a type the engine does not compute.
            pub fn from_card(kind: &InterfaceKind) -> Option<(TypeOptions, CardCommon)> {
                $(if let Some((t, c)) = <$file::$variant as InterfaceType>::from_card(kind) {
                    return Some((TypeOptions::$variant(t), c));
                })*
                None
            }
        }
    };
}

registry! {
    3 => type3::Type3,
    5 => type5::Type5,
    6 => type6::Type6,
    7 => type7::Type7,
    11 => type11::Type11,
    14 => type14::Type14,
    15 => type15::Type15,
    24 => type24::Type24,
    25 => type25::Type25,
    // LS-DYNA's segment-based contact (SOFT = 2): keyword decks only, no
    // Radioss number (`dyna_segment::DYNA_SEGMENT`).
    1002 => dyna_segment::DynaSegment,
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The interface cards of a project deck, read through the format-neutral entry.
    fn cards(deck: &str) -> Vec<InterfaceKind> {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join(format!("decks/{deck}/{deck}_0000.rad"));
        let m = crate::input::load(&path, &Default::default()).unwrap();
        m.interfaces.into_iter().map(|i| i.card.kind).collect()
    }

    #[test]
    fn each_registered_type_refuses_the_options_it_does_not_compute_by_name() {
        let mut t7 = cards("contact_patch").remove(0);
        assert_eq!(TypeOptions::check_card(&t7), Ok(()));
        let InterfaceKind::Type7(t) = &mut t7 else {
            panic!("contact_patch has a TYPE7 first")
        };
        t.ithe = 1;
        assert_eq!(
            TypeOptions::check_card(&t7),
            Err(Some("heat transfer (Ithe = 1)"))
        );
        let mut t5 = cards("idel_gap_t5").remove(0);
        assert_eq!(TypeOptions::check_card(&t5), Ok(()));
        let InterfaceKind::Type5(t) = &mut t5 else {
            panic!("idel_gap_t5 has a TYPE5 first")
        };
        t.ptlim = 1.0;
        assert_eq!(
            TypeOptions::check_card(&t5),
            Err(Some("a tangential pressure limit (Ptlim)"))
        );
        // TYPE2 is a kinematic condition (contact::tied), not a registered contact type.
        let t2 = cards("tied_bend").remove(0);
        assert_eq!(TypeOptions::check_card(&t2), Err(None));
    }

    #[test]
    fn every_registered_number_resolves_to_its_type_and_candidate_kind() {
        assert_eq!(
            TypeOptions::NUMBERS,
            &[3, 5, 6, 7, 11, 14, 15, 24, 25, 1002]
        );
        let expect = [
            (3, CandidateKind::NodeToSegment, CandidateSearch::Walk),
            (5, CandidateKind::NodeToSegment, CandidateSearch::Walk),
            (6, CandidateKind::NodeToSegment, CandidateSearch::Walk),
            (7, CandidateKind::NodeToSegment, CandidateSearch::Sort),
            (11, CandidateKind::EdgeToEdge, CandidateSearch::Sort),
            (
                14,
                CandidateKind::NodeToEllipsoid,
                CandidateSearch::Analytic,
            ),
            (
                15,
                CandidateKind::SegmentToEllipsoid,
                CandidateSearch::Analytic,
            ),
            (24, CandidateKind::NodeToSegment, CandidateSearch::Sort),
            (25, CandidateKind::NodeToSegment, CandidateSearch::Sort),
            (1002, CandidateKind::SegmentToSegment, CandidateSearch::Sort),
        ];
        for (n, kind, search) in expect {
            let t = TypeOptions::by_number(n).unwrap_or_else(|| panic!("TYPE{n} registered"));
            let imp = t.implementation();
            assert_eq!(imp.type_number(), n);
            assert_eq!(imp.candidate_kind(), kind, "TYPE{n}");
            assert_eq!(imp.search(), search, "TYPE{n}");
        }
        assert!(matches!(
            TypeOptions::by_number(3),
            Some(TypeOptions::Type3(_))
        ));
        assert!(matches!(
            TypeOptions::by_number(5),
            Some(TypeOptions::Type5(_))
        ));
        assert!(matches!(
            TypeOptions::by_number(7),
            Some(TypeOptions::Type7(_))
        ));
        assert!(matches!(
            TypeOptions::by_number(11),
            Some(TypeOptions::Type11(_))
        ));
        // TYPE2 is the tied interface (contact::tied), not a registered type.
        assert!(TypeOptions::by_number(2).is_none());
    }

    #[test]
    fn a_side_holds_its_nodes() {
        assert_eq!(Side::node(9).nodes(), &[9]);
        assert_eq!(Side::segment(&[1, 2, 3, 3]).nodes(), &[1, 2, 3]);
        assert_eq!(Side::segment(&[1, 2, 3, 4]).nodes(), &[1, 2, 3, 4]);
        assert_eq!(Side::segment(&[1, 2, 2, 2]).nodes(), &[1, 2]);
        assert_eq!(Side::edge([5, 6]), Side::segment(&[5, 6, 6, 6]));
    }
}
