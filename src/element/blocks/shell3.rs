//! C0 3-node shells (Radioss Ish3n = 1, 2; kernel in `crate::element::shell3`).

use super::common::{
    decode_state, gather, hourglass_of, settle_common, von_mises_shell, HourglassEnergy,
};
use super::sections::shell_sections;
use super::shell_block::{corner_slots, shell_block, BatchFn, NodalStiffnessFn};
use super::{Block, BlockInput, ElemOut, ElemRow, ElemStep};
use crate::domain::LocalElements;
use crate::element::shell3::{self, Shell3State};
use crate::element::shell4::{PointHistory, ShellSection};
use crate::element::SLOT;
use crate::model::{ElementKind, Part, Property};
use rayon::prelude::*;

shell_block!(
    Shell3Block,
    ElementKind::Shell3,
    3,
    Shell3State,
    shell3::shell3_init,
    shell3::shell3_step,
    shell3::shell3_section,
    None,
    None
);

/// The registry's builder for this formulation.
pub(super) fn build(input: BlockInput) -> Result<Box<dyn Block>, String> {
    Ok(Box::new(Shell3Block::new(
        input.le,
        input.x,
        input.parts,
        input.props,
        input.mats,
    )?))
}
