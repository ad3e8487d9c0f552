//! The explicit solver: central differences with lumped mass, one global
//! time step per cycle, deterministic assembly (see `assembly`).
//!
//! One cycle (velocities live at half steps):
//!   a^n = (f_ext^n − f_int^n)/m → v^{n+½} = v^{n−½} + a^n·½(Δt^{n−½}+Δt^{n+½})
//!   → rigid bodies, imposed velocities, rigid walls, boundary conditions act on v^{n+½}
//!   → x^{n+1} = x^n + Δt^{n+½}·v^{n+½} → element forces at x^{n+1} → assembly
//!   → global minimum of the element time steps × /DT scale.

pub mod assembly;
pub mod listing;
pub mod run;

pub use crate::error::RunError;
pub use run::{run, RunOptions};
