//! crashsim: a distributed explicit crash solver for Radioss block-format decks.
//!
//! Data flow (see docs/ARCHITECTURE.md): `input` (picks the reader: `deck`
//! for Radioss, text → cards → model) → `model` (validated, resolved, masses;
//! the only thing later stages read) → `partition` (METIS) → `domain` (one
//! rank's share) and `global` (what every rank gets) → `solver` (state plus
//! phases over `element`, `material`, `kinematics`, `contact`) → `output`.
//! Ranks talk only through `parallel::Comm` (MPI in `parallel::MpiWorld`).

pub mod contact;
pub mod deck;
pub mod domain;
pub mod element;
pub mod error;
pub mod global;
pub mod input;
pub mod keyword;
pub mod kinematics;
pub mod material;
pub mod model;
pub mod output;
pub mod parallel;
pub mod solver;
pub mod summary;
pub mod vec3;
