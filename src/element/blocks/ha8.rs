//! 8-node bricks, fully integrated locking-free HA8 (Radioss Isolid = 14;
//! kernel in `crate::element::ha8`).

use super::common::{
    decode_state, gather, hourglass_of, settle_common, von_mises_3d, HourglassEnergy,
};
use super::sections::solid_sections;
use super::solid_block::solid_block;
use super::{Block, BlockInput, ElemOut, ElemRow, ElemStep};
use crate::domain::LocalElements;
use crate::element::ha8::{self, Ha8State};
use crate::element::hex8::SolidSection;
use crate::element::SLOT;
use crate::model::{ElementKind, Part, Property};
use rayon::prelude::*;

solid_block!(
    Ha8Block,
    ElementKind::Brick8,
    8,
    Ha8State,
    ha8::ha8_init,
    ha8::ha8_step,
    ha8::ha8_section
);

/// The registry's builder for this formulation.
pub(super) fn build(input: BlockInput) -> Result<Box<dyn Block>, String> {
    Ok(Box::new(Ha8Block::new(
        input.le,
        input.x,
        input.parts,
        input.props,
        input.mats,
    )?))
}
