//! Constitutive laws behind one trait ([`Law`]), one file per law, and the
//! registry ([`Material`], `registry.rs`) the element kernels call: LAW1
//! (elastic, `law1.rs`) and LAW2 (Johnson-Cook, `law2.rs`, its flow stress in
//! `johnson_cook.rs`). A plastic law supplies its flow-stress curve as a
//! [`Hardening`]; [`PointLaw`] updates the integration points with the
//! return maps of `return_map.rs` (plane stress for shells, 3-D for solids)
//! or, for shell sections computed with N = 0, the global (resultant,
//! Ilyushin) update of `ilyushin.rs`.

mod fail_johnson;
mod fail_tab;
mod failure;
mod hardening;
mod ilyushin;
mod johnson_cook;
mod law;
mod law1;
pub(crate) mod law12;
mod law2;
mod law21;
mod law27;
mod law36;
mod law44;
mod law62;
mod law70;
mod point;
mod registry;
mod return_map;
mod tabulated_flow;

pub use fail_johnson::FailJohnson;
pub use fail_tab::{shell_triaxiality, FailAt, FailTab};
pub use failure::Failure;
pub use hardening::Hardening;
pub use ilyushin::ilyushin_equivalent;
pub use law::{ElasticConstants, Law};
pub use law1::Law1;
pub use law12::{Law12, Law12Point};
pub use law2::Law2;
pub use law21::Law21;
pub use law27::{BrittlePoint, Law27};
pub use law36::{tension_factor, Law36};
pub use law44::Law44;
pub use law62::{HyperStress, Law62};
pub use law70::{Law70, Law70Point};
pub use point::{PlaneStressResult, PointLaw};
pub use registry::{law_name, Material, LAWS};
