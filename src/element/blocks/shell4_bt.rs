//! Belytschko-Tsay 4-node shells (Radioss Ishell = 1, 2, 3, 4; kernel in
//! `crate::element::shell4`).

use super::common::{
    decode_state, gather, hourglass_of, settle_common, von_mises_shell, HourglassEnergy,
};
use super::sections::shell_sections;
use super::shell_block::{corner_slots, shell_block, BatchFn, NodalStiffnessFn};
use super::{Block, BlockInput, ElemOut, ElemRow, ElemStep};
use crate::domain::LocalElements;
use crate::element::shell4::{self, Shell4State};
use crate::element::shell4::{PointHistory, ShellSection};
use crate::element::SLOT;
use crate::model::{ElementKind, Part, Property};
use rayon::prelude::*;

shell_block!(
    Shell4Block,
    ElementKind::Shell4,
    4,
    Shell4State,
    shell4::shell4_init,
    shell4::shell4_step,
    ShellSection::new,
    Some(shell4::nodal_stiffness),
    Some(shell4::shell4_step4)
);

/// The registry's builder for this formulation.
pub(super) fn build(input: BlockInput) -> Result<Box<dyn Block>, String> {
    Ok(Box::new(Shell4Block::new(
        input.le,
        input.x,
        input.parts,
        input.props,
        input.mats,
    )?))
}
