//! Tabulated functions y = f(x) (load curves, spring force curves).

use super::{Id, Loc};
use serde::{Deserialize, Serialize};

/// /FUNCT/fct_ID: title, then (X, Y) pairs (X 1-20, Y 21-40), X strictly increasing.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Function {
    pub id: Id,
    pub title: String,
    pub x: Vec<f64>,
    pub y: Vec<f64>,
    pub loc: Loc,
}
