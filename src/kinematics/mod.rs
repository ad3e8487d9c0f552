//! Kinematic conditions and loads: time functions, boundary conditions,
//! imposed velocities, concentrated loads, pressures and gravity, rigid bodies,
//! rigid walls.
//! Each piece works on one rank's nodes; what must be summed over ranks (a
//! rigid body's resultant) arrives already gathered, in global node order.

pub mod function;
pub mod pressure;
pub mod rigid_body;
pub mod rigid_wall;
