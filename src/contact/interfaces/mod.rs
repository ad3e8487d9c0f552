//! Interface types as compositions of geometry, stiffness, gap and friction:
//! each file turns one measured node–segment pair into the force on the
//! secondary node (the segment nodes take −N_i times it, EQ. 8.6.6.4–6).

pub mod type2;
pub mod type5;
pub mod type7;

use super::geometry::V3;

/// What one pair gives.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PairForce {
    /// Force on the secondary node.
    pub fs: V3,
    /// Shape functions of the contact point on the segment nodes.
    pub shape: [f64; 4],
    /// Tangent stiffness (for the nodal time step, EQ. 8.8.5.2).
    pub kt: f64,
    /// Kinematic time step 0.5·(Gap − p)/(dp/dt) (EQ. 8.8.5.1), ∞ if not closing.
    pub dt_kin: f64,
    /// Normal force magnitude and tangential force.
    pub f_n: f64,
    pub f_t: V3,
    /// Penetration and the direction the normal force pushes the secondary node.
    pub pen: f64,
    pub dir: V3,
    /// The contact point.
    pub point: V3,
}

/// Friction and tie memory of one node–segment pair.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct PairState {
    /// Tangential force of the last cycle (incremental form).
    pub ft: V3,
    /// Filtered tangential force (Ifiltr).
    pub ff: V3,
    /// ITIED: the node is tied to this point of the segment (shape, offset).
    pub tie: Option<([f64; 4], V3)>,
    /// Side of the segment (sign of the normal distance) at the last cycle in contact; 0 = none.
    pub side: i8,
}
