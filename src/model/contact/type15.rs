//! /INTER/TYPE15 options: a rigid hyper-ellipsoid against segments (theory
//! manual §8.10).

use crate::model::Id;
use serde::{Deserialize, Serialize};

/// /INTER/TYPE15 (reference guide "/INTER/TYPE15"):
///
/// Card 1: surf_IDs (1-10), surf_IDm (11-20).
/// Card 2: Stif (1-20), Fric (21-40).
///
/// The starter takes no gap, no damping, Tstart 0 and Tstop 1e30.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Type15 {
    /// surf_IDs: the secondary surface, of 3- and 4-node segments.
    pub surf_ids: Id,
    /// surf_IDm: the main surface, a /SURF/ELLIPS.
    pub surf_idm: Id,
    /// Stif: the stiffness at zero penetration (it grows as the segment
    /// nears the ellipsoid's centre, §8.10).
    pub stif: f64,
    /// Fric: Coulomb friction coefficient.
    pub fric: f64,
}
