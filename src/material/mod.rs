//! Constitutive laws: LAW1 (elastic) and LAW2 (Johnson-Cook), with the
//! plane-stress update used by shells, the global (resultant, Ilyushin)
//! update of shell sections computed with N = 0, and the 3-D update used by solids.

mod ilyushin;
mod johnson_cook;
mod law;

pub use ilyushin::ilyushin_equivalent;
pub use law::*;
