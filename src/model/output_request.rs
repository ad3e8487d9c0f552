//! What the input asks to be written: cross sections (force through a cut),
//! time histories and animation variables.

use super::{Id, Loc};
use serde::{Deserialize, Serialize};

/// /SECT: a cut through the model for force output.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct CrossSectionSpec {
    pub id: Id,
    pub title: String,
    pub nodes: [Id; 3],
    pub grnod: Id,
    pub isave: i64,
    pub frame_id: Id,
    pub dt: f64,
    pub alpha: f64,
    pub file_name: String,
    pub grbric: Id,
    pub grshel: Id,
    pub grtrus: Id,
    pub grbeam: Id,
    pub grsprg: Id,
    pub grtria: Id,
    pub iframe: i64,
    pub interfaces: Vec<Id>,
    pub loc: Loc,
}

/// /TH/type/th_ID: what to record in time histories.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct TimeHistorySpec {
    pub id: Id,
    /// The object type as written (NODE, PART, SHELL, RWALL, RBODY, INTER, SECTIO, ...).
    pub kind: String,
    pub title: String,
    /// Variable names (DEF, DX, VX, ...).
    pub variables: Vec<String>,
    /// Object ids.
    pub objects: Vec<Id>,
    pub loc: Loc,
}

/// An /ANIM request (starter /ANIM/VERS or engine /ANIM/ELEM/..., /ANIM/VECT/...).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct AnimationSpec {
    /// Header parts after ANIM, e.g. ["VECT", "DISP"].
    pub what: Vec<String>,
    pub loc: Loc,
}
