//! /INTER/TYPE3 options.

use crate::model::Id;
use serde::{Deserialize, Serialize};

/// /INTER/TYPE3: surface to surface "sliding and voids" (symmetric: the nodes of
/// each surface are checked against the segments of the other).
///
/// Card 1: surf_ID1 (1-10), surf_ID2 (11-20), Idel (71-80).
/// Card 2: Stfac (1-20), Fric (21-40), Gap (41-60), Tstart (61-80), Tstop (81-100).
/// Card 3: IBCX IBCY IBCZ (8, 9, 10), IRS (11-20), IRM (21-30).
/// Card 4 (may be absent): Ptlim (61-80).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Type3 {
    /// surf_ID1 (1-10): the first surface, stored on the *secondary* side
    /// (the Starter listing prints its segments as SECONDARY SURFACE). Required.
    pub surf_id1: Id,
    /// surf_ID2 (11-20): the second surface, the main side. Required.
    pub surf_id2: Id,
    /// Idel (71-80): 0 no deletion; 1 / 2 remove main segments when all / one of
    /// their elements are deleted; -1 / -2 the same keeping non-connected nodes.
    pub idel: i64,
    /// Stfac (card 2, 1-20): stiffness factor, 0 → 0.2 (the Starter listing
    /// prints 0.2). The theory manual recommends <= 1.0; larger values are
    /// accepted.
    pub stfac: f64,
    /// Fric (21-40): Coulomb friction, default 0.
    pub fric: f64,
    /// Gap (41-60): initial gap, default 0 (not computed: the listing prints 0).
    pub gap: f64,
    /// Tstart (61-80), default 0.
    pub tstart: f64,
    /// Tstop (81-100): 0 → 1e30.
    pub tstop: f64,
    /// IBCX, IBCY, IBCZ (card 3, columns 8, 9, 10): deactivate the secondary
    /// nodes' boundary conditions in X, Y, Z at impact.
    pub ibc: [bool; 3],
    /// IRS (11-20): renumbering of surface 1 segments: 0 = reverse a normal that
    /// points into the solid, 1 = always reverse, 2 = never.
    pub irs: i64,
    /// IRM (21-30): the same for surface 2.
    pub irm: i64,
    /// Ptlim (card 4, 61-80): maximum tangential pressure, 0 → 1e30. Card 4 is
    /// often absent (e.g. INT357); the listing still prints 1e30.
    pub ptlim: f64,
}
