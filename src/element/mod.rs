//! Element kernels: pure functions from nodal kinematics and element state to
//! corner forces, moments, energy increments and the element's stable time step.
//! No element writes into nodal arrays: the solver assembles the corner
//! contributions in a fixed global order (see `solver::assembly`).

/// Values per corner slot: force (3) and moment (3).
pub const SLOT: usize = 6;

pub mod beam;
pub mod blocks;
pub mod ha8;
pub mod heph;
pub mod hex8;
pub mod hex8_small;
pub mod hex8_total;
pub mod joint;
pub mod lanes;
pub mod ortho;
pub mod shell3;
pub mod shell4;
pub mod shell4_qbat;
#[cfg(test)]
mod solid_analytic_tests;
pub mod spring;
pub mod spring_beam;
pub mod spring_general;
pub mod spring_law;
pub mod step_stiffness;
pub mod tet4;
pub mod truss;
