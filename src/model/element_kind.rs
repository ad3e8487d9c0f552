//! The element kinds the model knows (shell, brick, tetrahedron, spring ...),
//! with their node counts and the fixed order of the model's element sets.

use serde::{Deserialize, Serialize};

/// The element kinds the reader knows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize, PartialOrd, Ord)]
pub enum ElementKind {
    Shell4,
    Shell3,
    Brick8,
    Tetra4,
    Spring,
    Truss,
    Beam,
}

impl ElementKind {
    /// Every kind, in the fixed order of the model's element sets
    /// (`Model::elements`), of partitioning and of the output.
    pub const ALL: [ElementKind; 7] = [
        ElementKind::Shell4,
        ElementKind::Shell3,
        ElementKind::Brick8,
        ElementKind::Tetra4,
        ElementKind::Spring,
        ElementKind::Truss,
        ElementKind::Beam,
    ];

    /// The name messages give the kind: the Radioss keyword that defines
    /// such elements (`/SHELL` ...), which every reader's messages share.
    pub fn keyword(self) -> &'static str {
        match self {
            ElementKind::Shell4 => "/SHELL",
            ElementKind::Shell3 => "/SH3N",
            ElementKind::Brick8 => "/BRICK",
            ElementKind::Tetra4 => "/TETRA4",
            ElementKind::Spring => "/SPRING",
            ElementKind::Truss => "/TRUSS",
            ElementKind::Beam => "/BEAM",
        }
    }

    /// The kind's place in [`ElementKind::ALL`].
    pub fn index(self) -> usize {
        self as usize
    }

    /// The name the engine listing gives the kind (ELEMENT column, messages):
    /// the keyword without its slash (`SHELL`, `SH3N`, `BRICK`, ...).
    pub fn listing_name(self) -> &'static str {
        &self.keyword()[1..]
    }

    /// The name of the kind's group in the HDF5 run and restart files.
    pub fn file_name(self) -> &'static str {
        match self {
            ElementKind::Shell4 => "shell4",
            ElementKind::Shell3 => "shell3",
            ElementKind::Brick8 => "brick8",
            ElementKind::Tetra4 => "tetra4",
            ElementKind::Spring => "spring",
            ElementKind::Truss => "truss",
            ElementKind::Beam => "beam",
        }
    }

    /// Number of nodes that define the element (beams: 2 + orientation node).
    pub fn nodes(self) -> usize {
        match self {
            ElementKind::Shell4 | ElementKind::Tetra4 => 4,
            ElementKind::Shell3 | ElementKind::Beam => 3,
            ElementKind::Brick8 => 8,
            ElementKind::Spring | ElementKind::Truss => 2,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_kind_knows_its_place_and_its_names() {
        for (i, k) in ElementKind::ALL.into_iter().enumerate() {
            assert_eq!(k.index(), i);
            assert_eq!(format!("/{}", k.listing_name()), k.keyword());
        }
        assert_eq!(ElementKind::Shell3.listing_name(), "SH3N");
        assert_eq!(ElementKind::Brick8.file_name(), "brick8");
    }
}
