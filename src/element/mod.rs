//! Element kernels: pure functions from nodal kinematics and element state to
//! corner forces, moments, energy increments and the element's stable time step.
//! No element writes into nodal arrays: the solver assembles the corner
//! contributions in a fixed global order (see `solver::assembly`).

pub mod hex8;
pub mod shell3;
pub mod shell4;
pub mod spring;
pub mod tet4;
