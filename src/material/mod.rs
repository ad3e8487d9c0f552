//! Constitutive laws: LAW1 (elastic) and LAW2 (Johnson-Cook), with the
//! plane-stress update used by shells and the 3-D update used by solids.

mod johnson_cook;
mod law;

pub use law::*;
