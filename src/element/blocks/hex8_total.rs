//! 8-node bricks with one integration point and viscous hourglass (Radioss
//! Isolid = 1, 2 with Ismstr = 10: total strain, for LAW62; kernel in
//! `crate::element::hex8_total`).

use super::common::{
    decode_state, gather, hourglass_of, settle_common, von_mises_3d, HourglassEnergy,
};
use super::sections::solid_sections;
use super::solid_block::solid_block;
use super::{Block, BlockInput, ElemOut, ElemRow, ElemStep};
use crate::domain::LocalElements;
use crate::element::hex8::SolidSection;
use crate::element::hex8_total::{self, Hex8TotalState};
use crate::element::SLOT;
use crate::model::{ElementKind, Part, Property};
use rayon::prelude::*;

solid_block!(
    Hex8TotalBlock,
    ElementKind::Brick8,
    8,
    Hex8TotalState,
    hex8_total::hex8_total_init,
    hex8_total::hex8_total_step,
    hex8_total::total_section
);

/// The registry's builder for this formulation.
pub(super) fn build(input: BlockInput) -> Result<Box<dyn Block>, String> {
    Ok(Box::new(Hex8TotalBlock::new(
        input.le,
        input.x,
        input.parts,
        input.props,
        input.mats,
    )?))
}
