//! Global id → dense index maps, with the error every unknown reference gets.

use crate::model::{Id, InputError, Loc};
use std::collections::HashMap;

/// Maps deck ids of one entity kind to dense indices 0..n.
#[derive(Clone, Debug, Default)]
pub struct IdIndex {
    map: HashMap<Id, u32>,
    what: &'static str,
}

impl IdIndex {
    /// Builds the map; a repeated id is an error naming both places.
    pub fn build(
        what: &'static str,
        ids: impl Iterator<Item = (Id, Loc)>,
        keyword: &str,
    ) -> Result<Self, InputError> {
        let mut map = HashMap::new();
        let mut first: HashMap<Id, Loc> = HashMap::new();
        for (i, (id, loc)) in ids.enumerate() {
            if let Some(prev) = first.get(&id) {
                return Err(InputError::new(
                    loc,
                    keyword,
                    "",
                    format!(
                        "duplicate {what} id {id} (first defined at {prev}); ids must be unique"
                    ),
                ));
            }
            first.insert(id, loc);
            map.insert(id, i as u32);
        }
        Ok(IdIndex { map, what })
    }

    pub fn get(&self, id: Id) -> Option<u32> {
        self.map.get(&id).copied()
    }

    /// The index of `id`, or an error at `loc` saying that `keyword`'s `field` names an unknown id
    /// ("WHAT ID is not defined in the deck": `to_model` adds the unsupported keyword that
    /// would define it, reading that wording).
    pub fn resolve(
        &self,
        id: Id,
        loc: &Loc,
        keyword: &str,
        field: &str,
    ) -> Result<u32, InputError> {
        self.get(id).ok_or_else(|| {
            InputError::new(
                loc.clone(),
                keyword,
                field,
                format!("{} {id} is not defined in the deck", self.what),
            )
        })
    }
}
