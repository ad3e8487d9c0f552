//! The failure-model registry: one variant of [`Failure`] per model, one file
//! per model (`fail_johnson.rs`, `fail_tab.rs`). A material carries at most one model today;
//! the element sections hold it and call it per integration point after the
//! material update (the damage lives in the element state).

use super::fail_johnson::FailJohnson;
use super::fail_tab::{FailAt, FailTab};
use crate::model::{FailureModel, FailureSpec};
use serde::{Deserialize, Serialize};

/// A failure model with its parameters.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum Failure {
    /// /FAIL/JOHNSON.
    Johnson(FailJohnson),
    /// /FAIL/TAB.
    Tab(FailTab),
    /// /FAIL/HASHIN with Ifail_so 0 on solids: the reference reports the
    /// criteria and changes nothing in the solution (research note
    /// `docs/notes/law12_research.md` §3.3); its relaxation and deletion
    /// (Ifail_so 1, 2) and shells are refused by name.
    Hashin(crate::model::HashinFailure),
}

impl Failure {
    /// The failure model of a material's cards (`None` without one); more
    /// than one model on one material is refused by name.
    pub fn of_material(specs: &[FailureSpec]) -> Result<Option<Failure>, String> {
        match specs {
            [] => Ok(None),
            [one] => match &one.model {
                FailureModel::Johnson(j) => Ok(Some(Failure::Johnson(FailJohnson::new(j)?))),
                FailureModel::Tab(t) => Ok(Some(Failure::Tab(FailTab::new(t)?))),
                FailureModel::Hashin(h) => Ok(Some(Failure::Hashin(h.clone()))),
            },
            _ => Err(format!(
                "{} failure models on one material: only one /FAIL card per material is computed",
                specs.len()
            )),
        }
    }

    /// One solid point after its material update (see [`FailJohnson::solid`],
    /// [`FailTab::solid`]): true when the element is to be deleted. Solids
    /// do not keep their initial length: `at.len0` is not used, and a
    /// /FAIL/TAB with an element-size function is refused on solids
    /// ([`Failure::solid_refusal`]).
    #[inline]
    pub fn solid(&self, sig: &mut [f64; 6], dmg: &mut f64, dep: f64, at: &FailAt) -> bool {
        match self {
            Failure::Johnson(f) => f.solid(sig, dmg, dep, at.rate, at.tstar),
            Failure::Tab(f) => f.solid(sig, dmg, dep, at),
            Failure::Hashin(_) => false,
        }
    }

    /// What the engine cannot compute of this model on solids, by name.
    pub fn solid_refusal(&self) -> Option<String> {
        match self {
            Failure::Tab(f) if f.has_size_function() => Some(
                "/FAIL/TAB with an element-size function (fct_IDel, Fscale_el) on solids is not computed yet (shells only)".into(),
            ),
            Failure::Hashin(h) if h.ifail_so != 0 => Some(format!(
                "/FAIL/HASHIN with Ifail_so = {}: the stress relaxation and deletion after failure are not computed yet (Ifail_so = 0, which reports the criteria only, is)",
                h.ifail_so
            )),
            _ => None,
        }
    }

    /// The model on shells: `None` where shells refuse it (by name, from
    /// [`Failure::shell_refusal`]).
    pub fn shell(&self) -> Option<&FailTab> {
        match self {
            Failure::Tab(f) => Some(f),
            Failure::Johnson(_) | Failure::Hashin(_) => None,
        }
    }

    /// What the engine cannot compute of this model on shells, by name.
    pub fn shell_refusal(&self) -> Option<String> {
        match self {
            Failure::Johnson(_) => Some(
                "/FAIL/JOHNSON on shell elements is not computed yet (solids only; /FAIL/TAB works on both)".into(),
            ),
            Failure::Hashin(_) => {
                Some("/FAIL/HASHIN on shell elements is not computed yet".into())
            }
            Failure::Tab(_) => None,
        }
    }
}
