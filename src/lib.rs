//! crashsim: a distributed explicit crash solver for Radioss block-format decks.
//!
//! Data flow (see ARCHITECTURE.md): `deck` (text → cards) → `model` (validated,
//! resolved, masses) → `partition` (METIS) → `domain` (one rank's share) →
//! solver (to come). MPI lives only in `parallel`.

pub mod deck;
pub mod domain;
pub mod model;
pub mod parallel;
pub mod summary;
