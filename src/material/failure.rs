//! The failure-model registry: one variant of [`Failure`] per model, one file
//! per model (`fail_johnson.rs`). A material carries at most one model today;
//! the element sections hold it and call it per integration point after the
//! material update (the damage lives in the element state).

use super::fail_johnson::FailJohnson;
use crate::model::{FailureModel, FailureSpec};
use serde::{Deserialize, Serialize};

/// A failure model with its parameters.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum Failure {
    /// /FAIL/JOHNSON.
    Johnson(FailJohnson),
}

impl Failure {
    /// The failure model of a material's cards (`None` without one); more
    /// than one model on one material is refused by name.
    pub fn of_material(specs: &[FailureSpec]) -> Result<Option<Failure>, String> {
        match specs {
            [] => Ok(None),
            [one] => match &one.model {
                FailureModel::Johnson(j) => Ok(Some(Failure::Johnson(FailJohnson::new(j)?))),
            },
            _ => Err(format!(
                "{} failure models on one material: only one /FAIL card per material is computed",
                specs.len()
            )),
        }
    }

    /// One solid point after its material update (see [`FailJohnson::solid`]):
    /// true when the element is to be deleted.
    #[inline]
    pub fn solid(
        &self,
        sig: &mut [f64; 6],
        dmg: &mut f64,
        dep: f64,
        rate: f64,
        tstar: f64,
    ) -> bool {
        match self {
            Failure::Johnson(f) => f.solid(sig, dmg, dep, rate, tstar),
        }
    }
}
