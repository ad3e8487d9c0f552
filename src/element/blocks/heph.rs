//! 8-node bricks, one point with physical hourglass stabilization: HEPH
//! (Radioss Isolid = 24; kernel in `crate::element::heph`).

use super::common::{
    decode_state, gather, hourglass_of, settle_common, von_mises_3d, HourglassEnergy,
};
use super::sections::solid_sections;
use super::solid_block::solid_block;
use super::{Block, BlockInput, ElemOut, ElemRow, ElemStep};
use crate::domain::LocalElements;
use crate::element::heph::{self, HephState};
use crate::element::hex8::SolidSection;
use crate::element::SLOT;
use crate::model::{ElementKind, Part, Property};
use rayon::prelude::*;

solid_block!(
    HephBlock,
    ElementKind::Brick8,
    8,
    HephState,
    heph::heph_init,
    heph::heph_step,
    heph::heph_section
);

/// The registry's builder for this formulation.
pub(super) fn build(input: BlockInput) -> Result<Box<dyn Block>, String> {
    Ok(Box::new(HephBlock::new(
        input.le,
        input.x,
        input.parts,
        input.props,
        input.mats,
    )?))
}
