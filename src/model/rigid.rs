//! Rigid walls and rigid bodies as the input defines them.

use super::{Id, Loc};
use serde::{Deserialize, Serialize};

/// /RWALL/PLANE: an infinite plane through M with normal M→M1.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct RigidWallSpec {
    pub id: Id,
    pub title: String,
    /// Node that carries a moving wall (0 = fixed wall).
    pub node_id: Id,
    /// 0 sliding, 1 tied, 2 sliding with friction.
    pub slide: i64,
    /// Secondary nodes added / removed.
    pub grnod1: Id,
    pub grnod2: Id,
    /// Nodes closer than this at t = 0 are secondary too (0 = none by distance).
    pub d_search: f64,
    pub fric: f64,
    pub diameter: f64,
    pub ffac: f64,
    pub ifq: i64,
    /// Point M (fixed wall), or the moving node's position (filled by the model).
    pub m: [f64; 3],
    /// Moving wall: mass and initial velocity.
    pub mass: f64,
    pub v0: [f64; 3],
    /// Point M1: the normal is M→M1.
    pub m1: [f64; 3],
    pub loc: Loc,
}

/// /RBODY: rigid body of a node group with main node RBID.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct RigidBodySpec {
    pub id: Id,
    pub title: String,
    pub main_node: Id,
    pub sens_id: Id,
    pub skew_id: Id,
    pub ispher: i64,
    /// Mass added to the main node.
    pub mass: f64,
    pub grnod: Id,
    pub ikrem: i64,
    pub icog: i64,
    pub surf_id: Id,
    /// Added inertia Jxx, Jyy, Jzz, Jxy, Jyz, Jxz.
    pub inertia: [f64; 6],
    pub ioptoff: i64,
    pub iexpams: i64,
    pub loc: Loc,
}
