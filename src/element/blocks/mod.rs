//! One rank's elements, in blocks. A block holds the local elements of one
//! element kind that share one formulation (BT shell, C0 triangle, brick,
//! tetrahedron, spring): it runs its kernel over its elements (rayon, one
//! element per task, each writing only its own corner slots), reports its
//! smallest time step and its energy, lists its final state and saves it for
//! restart. The solver sees every block through the [`Block`] trait; a kind
//! may be held by several blocks, one per formulation its parts ask for.
//!
//! Adding a formulation (say DKT18, Ish3n 30): one file here with the block
//! (its struct, `Block` impl and builder) over its kernel in `crate::element`,
//! and one line in the table of [`registry`].

mod common;
mod ha8;
mod heph;
mod hex8;
mod hex8_total;
mod joint;
mod line;
pub mod registry;
mod sections;
mod shell3;
mod shell4_bt;
mod shell4_qbat;
mod shell_block;
mod solid_block;
mod spring;
mod tet4;

pub use hex8::Hex8Block;
pub use registry::make_block;
pub use shell3::Shell3Block;
pub use shell4_bt::Shell4Block;
pub use spring::{SpringBlock, SpringKernel};
pub use tet4::Tet4Block;

use super::SLOT;
use crate::domain::LocalElements;
use crate::model::{ElementKind, Function, MaterialSpec, Part, Property, RigidBody};
use crate::parallel::ExactSum;

/// Per-element result the solver needs after a step.
#[derive(Clone, Copy, Debug, Default)]
pub struct ElemStep {
    pub dt: f64,
    pub failed: bool,
    pub bad: bool,
}

/// Final per-element values for --final-elements: sxx, syy, sxy, eps_p, thick, eint, deleted.
pub type ElemRow = (u32, [f64; 7]);

/// Per-element values written to the HDF5 states and time histories
/// (`crate::output`), one per local element in the block's (global) order.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ElemOut {
    /// Von Mises stress: shells the largest over the through-thickness
    /// points (plane stress with the transverse shears), solids from the
    /// full tensor, springs |force|.
    pub von_mises: f64,
    /// Effective plastic strain (shells: largest over the points).
    pub eps_p: f64,
    /// Current thickness (shells; 0 for the others).
    pub thick: f64,
    /// Internal energy with hourglass.
    pub eint: f64,
    /// Hourglass energy (part of `eint`; Radioss reports it apart from the
    /// listing's and the time histories' internal energy).
    pub ehg: f64,
    /// Plastic work (part of `eint`).
    pub eplas: f64,
    pub deleted: bool,
}

pub trait Block: Send + Sync {
    fn kind(&self) -> ElementKind;
    fn local(&self) -> &LocalElements;
    /// Corner slots per element (force + moment each).
    fn corners(&self) -> usize;
    /// Runs every live element; writes `corners()` slots per element into `contrib`.
    fn compute(
        &mut self,
        x: &[[f64; 3]],
        v: &[[f64; 3]],
        vr: &[[f64; 3]],
        dt: f64,
        contrib: &mut [[f64; SLOT]],
    );
    /// Per-element step results of the last `compute`.
    fn steps(&self) -> &[ElemStep];
    /// Marks failed elements deleted; returns the first element with a bad
    /// geometry (global index within the kind, what is wrong).
    fn settle(&mut self) -> Option<(u32, &'static str)>;
    fn alive(&self, e: usize) -> bool;
    fn rows(&self) -> Vec<ElemRow>;
    /// Values for the HDF5 states, one per local element (see `ElemOut`).
    fn outputs(&self) -> Vec<ElemOut>;
    /// Adds the block's energies element by element to exact sums:
    /// internal (with hourglass), hourglass, plastic work — the same totals
    /// for any partition (`parallel::exact_sum`).
    fn energy_sums(&self, acc: &mut [ExactSum; 3]) {
        for o in self.outputs() {
            acc[0].add(o.eint);
            acc[1].add(o.ehg);
            acc[2].add(o.eplas);
        }
    }
    /// The nodal stiffness of every element's corners at the positions `x`
    /// for the nodal time step (/DT/NODA/CST): [K, 0, 0, K_rot, 0, 0] in
    /// each corner slot; `false` when the formulation does not give it (the
    /// run then refuses /DT/NODA/CST by name).
    fn nodal_stiffness(&self, _x: &[[f64; 3]], _contrib: &mut [[f64; SLOT]]) -> bool {
        false
    }
    /// The element's part in its nodes' stiffness for the nodal time step
    /// taken while a TYPE7-family interface is active
    /// (`solver::run::interface_nodal_step`): each corner gets
    /// c·2·(m_e/corners)/Δt_e², Δt_e the element's unscaled step; this is
    /// c. Solids 1: the reference's ρV/Δt² per brick, a quarter to each
    /// node (mqviscb.F, scumu3.F; `docs/notes/type25_nodal_step_research.md` §1).
    fn nodal_step_factor(&self, _e: usize) -> f64 {
        1.0
    }
    /// Everything the element needs to continue after a restart (its state,
    /// integration-point stresses and strains, deleted flag), as bytes; the
    /// restart file keys it by the element's global index (`local().global[e]`).
    fn export_state(&self, e: usize) -> Vec<u8>;
    /// Puts back what `export_state` saved (possibly on another rank count).
    fn import_state(&mut self, e: usize, bytes: &[u8]) -> Result<(), String>;
}

/// What a block builder gets: its elements (one kind, one formulation, in
/// global order) and the model data they refer to.
pub struct BlockInput<'a> {
    pub le: LocalElements,
    pub x: &'a [[f64; 3]],
    pub mass: &'a [f64],
    pub parts: &'a [Part],
    pub props: &'a [Property],
    pub mats: &'a [MaterialSpec],
    pub functions: &'a [Function],
    pub ctx: BlockContext<'a>,
}

/// What a block may need of the model beyond its elements' parts,
/// properties and materials (today: the joints' rigid bodies).
#[derive(Clone, Copy, Debug, Default)]
pub struct BlockContext<'a> {
    /// The rigid bodies (dense global node indices).
    pub rigid_bodies: &'a [RigidBody],
    /// The global index of each local node (empty: local is global).
    pub node_global: &'a [u32],
    /// /DTIX bound of every step (0: none).
    pub dt_max: f64,
}

/// Builds the block of one formulation (a line of [`registry::FORMULATIONS`]).
pub type BuildBlock = fn(BlockInput) -> Result<Box<dyn Block>, String>;
