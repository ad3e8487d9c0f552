//! Contact interfaces as the input specifies them: which interface type
//! (tied, node-to-surface, surface-to-surface, general penalty contact,
//! edge-to-edge), what each side references (node group, surface, line) and
//! the type's options after default resolution. One file per interface type.

mod type11;
mod type14;
mod type15;
mod type19;
mod type2;
mod type24;
mod type25;
mod type3;
mod type5;
mod type6;
mod type7;

pub use type11::*;
pub use type14::*;
pub use type15::*;
pub use type19::*;
pub use type2::*;
pub use type24::*;
pub use type25::*;
pub use type3::*;
pub use type5::*;
pub use type6::*;
pub use type7::*;

use super::{Id, Loc};
use serde::{Deserialize, Serialize};

/// "No limit" value the Starter substitutes for Tstop, Stmax, Gapmax, Ptlim.
pub const EP30: f64 = 1.0e30;

/// Starter's "infinite" rupture distance for TYPE2 (Max_N_Dist, Max_T_Dist).
pub const EP20: f64 = 1.0e20;

/// One contact interface: its type with the type's options, and where it is
/// defined (Radioss: an `/INTER/TYPEn/inter_ID[/unit_ID]` block).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct InterfaceSpec {
    pub id: Id,
    /// Header unit_ID (0 = none).
    pub unit_id: Id,
    /// inter_title: the line after the header (up to 100 characters).
    pub title: String,
    pub kind: InterfaceKind,
    /// Where the keyword line is.
    pub loc: Loc,
    /// Where card 1 (the ids of both sides) is.
    #[serde(default)]
    pub ids_loc: Loc,
}

// A deck holds few interfaces: the size of the TYPE7 variant does not matter,
// and boxing it would change the public shape `Type7(Type7)`.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub enum InterfaceKind {
    Type2(Type2),
    Type3(Type3),
    Type5(Type5),
    Type6(Type6),
    Type7(Type7),
    Type11(Type11),
    Type14(Type14),
    Type15(Type15),
    Type19(Type19),
    Type24(Type24),
    Type25(Type25),
}

/// What one side of an interface references.
#[derive(Clone, Copy, Debug, Serialize, Deserialize, PartialEq)]
pub enum Side {
    /// A `/GRNOD` node group.
    NodeGroup(Id),
    /// A `/SURF` surface (segments).
    Surface(Id),
    /// A `/LINE` set of 2-node segments.
    Line(Id),
    /// self-contact (TYPE7 grnod=0 / TYPE11 main line 0): same as the other side
    SameAsOther,
    None,
}

impl InterfaceSpec {
    /// 2, 3, 5, 6, 7, 11, 14, 15, 19, 24 or 25.
    pub fn type_number(&self) -> u32 {
        match self.kind {
            InterfaceKind::Type2(_) => 2,
            InterfaceKind::Type3(_) => 3,
            InterfaceKind::Type5(_) => 5,
            InterfaceKind::Type6(_) => 6,
            InterfaceKind::Type7(_) => 7,
            InterfaceKind::Type11(_) => 11,
            InterfaceKind::Type14(_) => 14,
            InterfaceKind::Type15(_) => 15,
            InterfaceKind::Type19(_) => 19,
            InterfaceKind::Type24(_) => 24,
            InterfaceKind::Type25(_) => 25,
        }
    }

    /// What the type does, in a few words (for messages).
    pub fn description(&self) -> &'static str {
        match self.kind {
            InterfaceKind::Type2(_) => "tied",
            InterfaceKind::Type3(_) => "segment to segment, node-to-segment in both directions",
            InterfaceKind::Type5(_) => "node to segment",
            InterfaceKind::Type6(_) => {
                "rigid body to rigid body, total force a function of the penetration"
            }
            InterfaceKind::Type7(_) => "general node to segment",
            InterfaceKind::Type11(_) => "edge to edge",
            InterfaceKind::Type14(_) => "nodes against a rigid hyper-ellipsoid",
            InterfaceKind::Type15(_) => "segments against a rigid hyper-ellipsoid",
            InterfaceKind::Type19(_) => {
                "general contact: node to surface both ways and edge to edge"
            }
            InterfaceKind::Type24(_) => "penalty node to surface",
            InterfaceKind::Type25(_) => "penalty node to surface without activation gap",
        }
    }

    /// What the secondary (slave) side references.
    pub fn secondary_side(&self) -> Side {
        match &self.kind {
            InterfaceKind::Type2(t) => Side::NodeGroup(t.grnod_ids),
            InterfaceKind::Type3(t) => Side::Surface(t.surf_id1),
            InterfaceKind::Type5(t) => Side::NodeGroup(t.grnod_ids),
            InterfaceKind::Type6(t) => Side::Surface(t.surf_id1),
            InterfaceKind::Type7(t) => {
                if t.grnod_ids == 0 {
                    Side::SameAsOther
                } else if t.ists != 0 {
                    Side::Surface(t.grnod_ids)
                } else {
                    Side::NodeGroup(t.grnod_ids)
                }
            }
            InterfaceKind::Type11(t) => Side::Line(t.line_ids),
            InterfaceKind::Type14(t) => Side::NodeGroup(t.grnd_ids),
            InterfaceKind::Type15(t) => Side::Surface(t.surf_ids),
            InterfaceKind::Type19(t) => Side::Surface(t.surfaces().0),
            InterfaceKind::Type24(_) | InterfaceKind::Type25(_) => {
                let (s1, s2, grnd) = self.penalty_ids().unwrap_or_default();
                if s1 == 0 {
                    Side::NodeGroup(grnd)
                } else if s2 == 0 {
                    Side::SameAsOther
                } else {
                    Side::Surface(s1)
                }
            }
        }
    }

    /// The field names of (secondary side, main side) on card 1.
    pub fn side_fields(&self) -> (&'static str, &'static str) {
        match &self.kind {
            InterfaceKind::Type3(_) | InterfaceKind::Type6(_) => ("surf_ID1", "surf_ID2"),
            InterfaceKind::Type11(_) => ("line_IDs", "line_IDm"),
            InterfaceKind::Type15(_) => ("surf_IDs", "surf_IDm"),
            InterfaceKind::Type19(_) => ("surf_IDs", "surf_IDm"),
            InterfaceKind::Type24(_) | InterfaceKind::Type25(_) => {
                match self.penalty_ids().unwrap_or_default() {
                    (0, _, _) => ("grnd_IDs", "surf_ID2"),
                    (_, 0, _) => ("surf_ID1", "surf_ID1"),
                    _ => ("surf_ID1", "surf_ID2"),
                }
            }
            _ => ("grnd_IDs", "surf_IDm"),
        }
    }

    /// The /FUNCT ids the card names (0 = none), with their field names.
    pub fn functions(&self) -> Vec<(Id, &'static str)> {
        match &self.kind {
            InterfaceKind::Type6(t) => vec![
                (t.fct_id_ff, "fct_IDff"),
                (t.fct_id_fv, "fct_IDfv"),
                (t.fct_id_ld, "fct_IDld"),
                (t.fct_id_ul, "fct_IDul"),
                (t.fct_id_dv, "fct_IDdv"),
                (t.fct_id_df, "fct_IDdf"),
            ],
            InterfaceKind::Type14(t) => vec![
                (t.fct_id_ld, "fct_IDld"),
                (t.fct_id_f, "fct_IDf"),
                (t.fct_id_d1, "fct_IDd1"),
                (t.fct_id_d2, "fct_IDd2"),
            ],
            _ => Vec::new(),
        }
    }

    /// What the main (master) side references.
    pub fn main_side(&self) -> Side {
        match &self.kind {
            InterfaceKind::Type2(t) => Side::Surface(t.surf_idm),
            InterfaceKind::Type3(t) => Side::Surface(t.surf_id2),
            InterfaceKind::Type5(t) => Side::Surface(t.surf_idm),
            InterfaceKind::Type6(t) => Side::Surface(t.surf_id2),
            InterfaceKind::Type7(t) => Side::Surface(t.surf_idm),
            InterfaceKind::Type11(t) => {
                if t.line_idm == 0 {
                    Side::SameAsOther
                } else {
                    Side::Line(t.line_idm)
                }
            }
            InterfaceKind::Type14(t) => Side::Surface(t.surf_idm),
            InterfaceKind::Type15(t) => Side::Surface(t.surf_idm),
            InterfaceKind::Type19(t) => Side::Surface(t.surfaces().1),
            InterfaceKind::Type24(_) | InterfaceKind::Type25(_) => {
                let (s1, s2, _) = self.penalty_ids().unwrap_or_default();
                Side::Surface(if s2 == 0 { s1 } else { s2 })
            }
        }
    }

    /// TYPE24 and TYPE25: (surf_ID1, surf_ID2, grnd_IDs). surf_ID1 alone is
    /// self-contact, with surf_ID2 two surfaces, 0 the group's nodes on
    /// surf_ID2.
    fn penalty_ids(&self) -> Option<(Id, Id, Id)> {
        match &self.kind {
            InterfaceKind::Type24(t) => Some((t.surf_id1, t.surf_id2, t.grnd_ids)),
            InterfaceKind::Type25(t) => Some((t.surf_id1, t.surf_id2, t.grnd_ids)),
            _ => None,
        }
    }
}
