//! Node ↔ segment geometry for the contact code: the pure functions live in
//! `model::segment_geometry`, below the deck reader too (which moves the
//! secondary nodes of LS-DYNA's ties onto their surface).

pub use crate::model::segment_geometry::*;
