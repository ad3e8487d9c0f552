//! Sets: /GRNOD/NODE, /GRNOD/GRNOD, /GRNOD/PART, /GRNOD/SURF, /GRNOD/GRSHEL, /GRNOD/BOX, /GRSHEL/SHEL (and /GRSHEL/BOX,
//! /GRSHEL/BOX2: the 4-node shells in a box of `boxes.rs`), /SURF/PART
//! (and /SURF/PART/EXT, /SURF/PART/ALL), /SURF/SEG, /SURF/GRSHEL, /SUBSET. Each is a title line then a list of ids,
//! ten 10-column fields a line, until the next keyword (/SURF/SEG: one
//! segment a line). Ids are resolved by `to_model`.

use super::fields::Cards;
use super::list_end;
use super::source::Block;
use super::{header_id, Deck, Id};
use crate::model::{InputError, InputResult, Loc, Warning};
use serde::{Deserialize, Serialize};

/// What the ids of a node group's list name.
#[derive(Clone, Copy, Debug, Serialize, Deserialize, PartialEq, Eq)]
pub enum NodeGroupKind {
    /// /GRNOD/NODE: node ids.
    Node,
    /// /GRNOD/GRNOD: other node groups (union).
    Grnod,
    /// /GRNOD/PART: every node of the parts' elements.
    Part,
    /// /GRNOD/SURF: every node of the surfaces' segments.
    Surf,
    /// /GRNOD/GRSHEL: every node of the shells of the shell groups.
    Grshel,
    /// /GRNOD/BOX: every node in the box (`boxes.rs`; one box id).
    Box,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct NodeGroupCard {
    pub id: Id,
    pub title: String,
    pub kind: NodeGroupKind,
    /// The listed ids; negative = remove that item from the group.
    pub items: Vec<i64>,
    /// Where each list line starts (see [`item_loc`]).
    #[serde(default)]
    pub item_locs: ItemLocs,
    pub loc: Loc,
}

/// /GRSHEL/SHEL: a list of 4-node shell ids; /GRSHEL/BOX and /GRSHEL/BOX2:
/// the 4-node shells in a box.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct ShellGroupCard {
    pub id: Id,
    pub title: String,
    pub items: Vec<i64>,
    /// /GRSHEL/BOX (all nodes in the box: `true`) or /GRSHEL/BOX2 (at least
    /// one node: `false`), with the box id; `items` is then empty.
    #[serde(default)]
    pub by_box: Option<(Id, bool)>,
    #[serde(default)]
    pub item_locs: ItemLocs,
    pub loc: Loc,
}

#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub enum SurfaceDef {
    /// /SURF/PART and /SURF/PART/EXT: the shell faces of the parts and the
    /// external faces of their solids (negative id: normals reversed).
    Parts(Vec<i64>),
    /// /SURF/PART/ALL: the shell faces of the parts and every face of their
    /// solids, inner ones included (reference guide, /SURF/PART/ALL: "a
    /// surface segment is created for every face of a solid element that
    /// belongs to the item_ID listed"; shells are selected as by /SURF/PART).
    PartsAllFaces(Vec<i64>),
    /// /SURF/GRSHEL: the faces of the shells of the groups (negative: reversed).
    ShellGroups(Vec<i64>),
    /// /SURF/SEG: explicit segments (n4 = n3 or 0 for a triangle).
    Segments(Vec<SegmentCard>),
    /// /SURF/ELLIPS: an analytic hyper-ellipsoid.
    Ellipsoid(crate::model::Ellipsoid),
}

#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct SegmentCard {
    pub id: Id,
    pub nodes: [Id; 4],
    pub loc: Loc,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct SurfaceCard {
    pub id: Id,
    pub title: String,
    pub def: SurfaceDef,
    /// Where each line of a /SURF/PART or /SURF/GRSHEL id list starts.
    #[serde(default)]
    pub item_locs: ItemLocs,
    pub loc: Loc,
}

/// For an id list: (index of the first item of a line, that line), in order.
pub type ItemLocs = Vec<(usize, Loc)>;

/// The line that holds item `i` of a list (`fallback` when unknown).
pub fn item_loc<'a>(locs: &'a [(usize, Loc)], i: usize, fallback: &'a Loc) -> &'a Loc {
    match locs.partition_point(|(start, _)| *start <= i) {
        0 => fallback,
        k => &locs[k - 1].1,
    }
}

/// /SUBSET: a title and a list of child subset ids (parts join a subset
/// through their subset_ID field).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct SubsetCard {
    pub id: Id,
    pub title: String,
    pub children: Vec<Id>,
    pub loc: Loc,
}

/// Returns false for a set type this reader does not support.
pub(super) fn parse_set(block: &Block, deck: &mut Deck) -> InputResult<bool> {
    let p0 = block.parts[0].as_str();
    let p1 = block.parts.get(1).map(String::as_str).unwrap_or("");
    match (p0, p1) {
        ("GRNOD", "NODE" | "GRNOD" | "PART" | "SURF" | "GRSHEL") => {
            let kind = match p1 {
                "NODE" => NodeGroupKind::Node,
                "GRNOD" => NodeGroupKind::Grnod,
                "SURF" => NodeGroupKind::Surf,
                "GRSHEL" => NodeGroupKind::Grshel,
                _ => NodeGroupKind::Part,
            };
            let id = header_id(block, 2, "grnd_ID")?;
            let mut cards = Cards::new(block);
            let title = cards.title();
            let (items, item_locs) = id_list(&mut cards, "item_ID", &mut deck.warnings)?;
            deck.node_groups.push(NodeGroupCard {
                id,
                title,
                kind,
                items,
                item_locs,
                loc: block.loc.clone(),
            });
        }
        ("GRNOD", "BOX") => {
            let g = read_box_group(block, "grnd_ID", "nodes", &mut deck.warnings)?;
            deck.node_groups.push(NodeGroupCard {
                id: g.id,
                title: g.title,
                kind: NodeGroupKind::Box,
                items: vec![g.box_id as i64],
                item_locs: vec![(0, g.box_loc)],
                loc: block.loc.clone(),
            });
        }
        ("GRSHEL", "SHEL") => {
            let id = header_id(block, 2, "grshel_ID")?;
            let mut cards = Cards::new(block);
            let title = cards.title();
            let (items, item_locs) = id_list(&mut cards, "shell_ID", &mut deck.warnings)?;
            deck.shell_groups.push(ShellGroupCard {
                id,
                title,
                items,
                item_locs,
                by_box: None,
                loc: block.loc.clone(),
            });
        }
        ("GRSHEL", "BOX" | "BOX2") => {
            let g = read_box_group(block, "grshel_ID", "shells", &mut deck.warnings)?;
            deck.shell_groups.push(ShellGroupCard {
                id: g.id,
                title: g.title,
                items: Vec::new(),
                item_locs: Vec::new(),
                by_box: Some((g.box_id, p1 == "BOX")),
                loc: block.loc.clone(),
            });
        }
        ("SURF", "ELLIPS") => {
            let id = header_id(block, 2, "surf_ID")?;
            let mut cards = Cards::new(block);
            let title = cards.title();
            let def = SurfaceDef::Ellipsoid(read_ellipsoid(&mut cards)?);
            deck.surfaces.push(SurfaceCard {
                id,
                title,
                def,
                item_locs: Vec::new(),
                loc: block.loc.clone(),
            });
        }
        ("SURF", "PART" | "GRSHEL" | "SEG") => {
            // /SURF/PART/EXT/surf_ID and /SURF/PART/ALL/surf_ID: the id one place on.
            let faces = block.parts.get(2).map(String::as_str);
            let faces = faces.filter(|&f| p1 == "PART" && (f == "EXT" || f == "ALL"));
            let id = header_id(block, if faces.is_some() { 3 } else { 2 }, "surf_ID")?;
            let mut cards = Cards::new(block);
            let title = cards.title();
            let mut item_locs = Vec::new();
            let def = match p1 {
                "PART" => {
                    let (items, locs) = id_list(&mut cards, "part_ID", &mut deck.warnings)?;
                    item_locs = locs;
                    if faces == Some("ALL") {
                        SurfaceDef::PartsAllFaces(items)
                    } else {
                        SurfaceDef::Parts(items)
                    }
                }
                "GRSHEL" => {
                    let (items, locs) = id_list(&mut cards, "grshel_ID", &mut deck.warnings)?;
                    item_locs = locs;
                    SurfaceDef::ShellGroups(items)
                }
                _ => {
                    let mut segs = Vec::new();
                    // seg_ID (1-10) node_ID1..4 (11-50)
                    while let Some(c) = cards.next_nonblank() {
                        let sid = c.id_opt(1, "seg_ID")?;
                        let n1 = c.id(11, "node_ID1")?;
                        let n2 = c.id(21, "node_ID2")?;
                        let n3 = c.id(31, "node_ID3")?;
                        let n4 = c.id_opt(41, "node_ID4")?;
                        let n4 = if n4 == 0 { n3 } else { n4 };
                        segs.push(SegmentCard {
                            id: sid,
                            nodes: [n1, n2, n3, n4],
                            loc: c.loc(),
                        });
                    }
                    SurfaceDef::Segments(segs)
                }
            };
            deck.surfaces.push(SurfaceCard {
                id,
                title,
                def,
                item_locs,
                loc: block.loc.clone(),
            });
        }
        ("SUBSET", _) => {
            let id = header_id(block, 1, "subset_ID")?;
            let mut cards = Cards::new(block);
            let title = cards.title();
            let mut children = Vec::new();
            for v in id_list(&mut cards, "subset_ID", &mut deck.warnings)?.0 {
                if v < 0 {
                    return Err(InputError::new(
                        block.loc.clone(),
                        &block.header,
                        "subset_ID",
                        format!("{v}: expected a positive subset id"),
                    ));
                }
                children.push(v as Id);
            }
            deck.subsets.push(SubsetCard {
                id,
                title,
                children,
                loc: block.loc.clone(),
            });
        }
        _ => return Ok(false),
    }
    Ok(true)
}

/// A group by box (/GRNOD/BOX, /GRSHEL/BOX, /GRSHEL/BOX2): its id, title,
/// and the one box it takes, with where that card is.
struct BoxGroup {
    id: Id,
    title: String,
    box_id: Id,
    box_loc: Loc,
}

/// Reads a group by box. The reference reads one box (guide: box_ID,
/// columns 1-10); what follows on the card is not read, and said so
/// (`what` names the group's items).
fn read_box_group(
    block: &Block,
    id_name: &str,
    what: &str,
    warnings: &mut Vec<Warning>,
) -> InputResult<BoxGroup> {
    let id = header_id(block, 2, id_name)?;
    let mut cards = Cards::new(block);
    let title = cards.title();
    let c = cards.next("the card with box_ID")?;
    let box_id = c.id(1, "box_ID")?;
    let rest = c.text(11, 90);
    if !rest.is_empty() {
        warnings.push(Warning {
            loc: c.loc(),
            keyword: block.header.clone(),
            message: format!(
                "'{rest}' after box_ID (columns 11-100) is not read: the group takes the {what} of box {box_id} only, as the reference starter does"
            ),
        });
    }
    super::warn_surplus(&cards, "box_ID", warnings);
    Ok(BoxGroup {
        id,
        title,
        box_id,
        box_loc: c.loc(),
    })
}

/// Ten 10-column ids a line until the block ends (or a line of text ends
/// the list: [`list_end`]); blank and 0 fields are skipped. Also gives where
/// each line's items start.
pub(super) fn id_list(
    cards: &mut Cards,
    name: &str,
    warnings: &mut Vec<Warning>,
) -> InputResult<(Vec<i64>, ItemLocs)> {
    let mut out = Vec::new();
    let mut locs = Vec::new();
    while let Some(c) = cards.next_nonblank() {
        if list_end::holds_text(&c) {
            list_end::ended_by_text(&c, cards, name, warnings);
            break;
        }
        locs.push((out.len(), c.loc()));
        for k in 0..10 {
            if let Some(v) = c.int_opt(1 + 10 * k, 10, name)? {
                if v != 0 {
                    out.push(v);
                }
            }
        }
    }
    Ok((out, locs))
}

/// /SURF/ELLIPS cards: skew_ID (1-10), n (11-20, 0 → 2, >= 2); Xc Yc Zc
/// (1-20, 21-40, 41-60); a b c (the same columns, each > 0).
fn read_ellipsoid(cards: &mut Cards) -> InputResult<crate::model::Ellipsoid> {
    let c1 = cards.next("the card with skew_ID, n")?;
    let c2 = cards.next("the card with Xc, Yc, Zc")?;
    let c3 = cards.next("the card with the semi-axes a, b, c")?;
    let n = match c1.int_opt(11, 10, "n")?.unwrap_or(0) {
        0 => 2,
        v if v >= 2 => v as u32,
        v => {
            return Err(c1.err(
                "n",
                format!("{v} in columns 11-20: expected the degree of the hyper-ellipsoid, an integer >= 2 (0 = 2)"),
            ))
        }
    };
    let mut center = [0.0; 3];
    let mut axes = [0.0; 3];
    for (k, (cn, an)) in [("Xc", "a"), ("Yc", "b"), ("Zc", "c")].iter().enumerate() {
        let col = 1 + 20 * k;
        center[k] = c2.real_opt(col, 20, cn)?.unwrap_or(0.0);
        let a = c3.real_opt(col, 20, an)?.unwrap_or(0.0);
        if a <= 0.0 {
            return Err(c3.err(
                an,
                format!(
                    "{a} in columns {col}-{}: expected a semi-axis length > 0",
                    col + 19
                ),
            ));
        }
        axes[k] = a;
    }
    Ok(crate::model::Ellipsoid {
        skew_id: c1.id_opt(1, "skew_ID")?,
        n,
        center,
        axes,
    })
}
