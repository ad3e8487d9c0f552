//! Standard 4-node tetrahedra (Radioss Itetra4 = 0, 1000; kernel in
//! `crate::element::tet4`).

use super::common::{
    decode_state, gather, hourglass_of, settle_common, von_mises_3d, HourglassEnergy,
};
use super::sections::solid_sections;
use super::solid_block::solid_block;
use super::{Block, BlockInput, ElemOut, ElemRow, ElemStep};
use crate::domain::LocalElements;
use crate::element::hex8::SolidSection;
use crate::element::tet4::{self, Tet4State};
use crate::element::SLOT;
use crate::model::{ElementKind, Part, Property};
use rayon::prelude::*;

solid_block!(
    Tet4Block,
    ElementKind::Tetra4,
    4,
    Tet4State,
    tet4::tet4_init,
    tet4::tet4_step,
    SolidSection::for_tetra
);

/// The registry's builder for this formulation.
pub(super) fn build(input: BlockInput) -> Result<Box<dyn Block>, String> {
    Ok(Box::new(Tet4Block::new(
        input.le,
        input.x,
        input.parts,
        input.props,
        input.mats,
    )?))
}
