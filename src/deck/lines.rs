//! /LINE: sets of 2-node segments (edges) for edge-to-edge contact (TYPE11).
//! Reference guide, "Lines" overview: a line is a set of 2-node segments
//! defined explicitly (/LINE/SEG), by parts (/LINE/PART: their trusses and
//! beams), by surfaces (/LINE/SURF: every line of the surfaces) or by the
//! edges of surfaces (/LINE/EDGE: the free edges, those that bound one
//! segment only). The other variants (/LINE/BOX, /LINE/PROP, /LINE/MAT,
//! /LINE/GRBEAM, /LINE/LINE, ...) are not read and stop `run` by name.

use super::fields::Cards;
use super::id_index::IdIndex;
use super::resolve_sets::SetContext;
use super::sets::{id_list, item_loc, ItemLocs};
use super::source::Block;
use super::{header_id, Deck, Id};
use crate::model::{ElementKind, InputError, InputResult, Line, Loc, Surface};
use serde::{Deserialize, Serialize};
use std::collections::HashMap;

/// What a /LINE block lists.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub enum LineDef {
    /// /LINE/SEG: seg_ID (1-10), node_ID1 (11-20), node_ID2 (21-30) a line.
    Segments(Vec<LineSegmentCard>),
    /// /LINE/PART: the trusses and beams of the parts.
    Parts(Vec<i64>),
    /// /LINE/SURF: every distinct edge of the surfaces' segments.
    Surfaces(Vec<i64>),
    /// /LINE/EDGE: the edges that bound exactly one segment of the surfaces.
    SurfaceEdges(Vec<i64>),
}

#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct LineSegmentCard {
    pub id: Id,
    pub nodes: [Id; 2],
    pub loc: Loc,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct LineCard {
    pub id: Id,
    pub title: String,
    pub def: LineDef,
    #[serde(default)]
    pub item_locs: ItemLocs,
    pub loc: Loc,
}

impl LineCard {
    /// The keyword as the deck writes it (`/LINE/SURF/3`), for messages.
    pub fn keyword(&self) -> String {
        let v = match self.def {
            LineDef::Segments(_) => "SEG",
            LineDef::Parts(_) => "PART",
            LineDef::Surfaces(_) => "SURF",
            LineDef::SurfaceEdges(_) => "EDGE",
        };
        format!("/LINE/{v}/{}", self.id)
    }
}

/// Reads a /LINE block; false for a variant this reader does not know.
pub(super) fn parse_line(block: &Block, deck: &mut Deck) -> InputResult<bool> {
    let variant = block.parts.get(1).map(String::as_str).unwrap_or("");
    if !matches!(variant, "SEG" | "PART" | "SURF" | "EDGE") {
        return Ok(false);
    }
    let id = header_id(block, 2, "line_ID")?;
    let mut cards = Cards::new(block);
    let title = cards.title();
    let mut item_locs = Vec::new();
    let def = if variant == "SEG" {
        let mut segs = Vec::new();
        while let Some(c) = cards.next_nonblank() {
            segs.push(LineSegmentCard {
                id: c.id_opt(1, "seg_ID")?,
                nodes: [c.id(11, "node_ID1")?, c.id(21, "node_ID2")?],
                loc: c.loc(),
            });
        }
        LineDef::Segments(segs)
    } else {
        let (items, locs) = id_list(&mut cards, "item_ID", &mut deck.warnings)?;
        item_locs = locs;
        match variant {
            "PART" => LineDef::Parts(items),
            "SURF" => LineDef::Surfaces(items),
            _ => LineDef::SurfaceEdges(items),
        }
    };
    deck.lines.push(LineCard {
        id,
        title,
        def,
        item_locs,
        loc: block.loc.clone(),
    });
    Ok(true)
}

/// Resolves every /LINE to its edges (dense node indices, each edge once,
/// in the order the definition first meets it). A line with no edge, or a
/// /LINE/SEG segment whose two nodes are the same, is an error.
pub fn resolve_lines(
    cards: &[LineCard],
    surfaces: &[Surface],
    surf_index: &IdIndex,
    ctx: &SetContext,
) -> Result<Vec<Line>, InputError> {
    IdIndex::build("line", cards.iter().map(|c| (c.id, c.loc.clone())), "/LINE")?;
    let mut out = Vec::with_capacity(cards.len());
    for c in cards {
        let kw = c.keyword();
        let edges = match &c.def {
            LineDef::Segments(segs) => explicit_edges(segs, ctx, &kw)?,
            LineDef::Parts(items) => part_edges(c, items, ctx, &kw)?,
            LineDef::Surfaces(items) | LineDef::SurfaceEdges(items) => {
                let mut segments = Vec::new();
                for (k, &item) in items.iter().enumerate() {
                    let loc = item_loc(&c.item_locs, k, &c.loc);
                    let s = surf_index.resolve(item.unsigned_abs(), loc, &kw, "surf_ID")?;
                    segments.extend_from_slice(&surfaces[s as usize].segments);
                }
                let free_only = matches!(c.def, LineDef::SurfaceEdges(_));
                segment_edges(&segments, free_only)
            }
        };
        if edges.is_empty() {
            return Err(InputError::new(
                c.loc.clone(),
                &kw,
                "",
                "the line has no edge; expected at least one 2-node segment",
            ));
        }
        out.push(Line {
            id: c.id,
            title: c.title.clone(),
            edges,
        });
    }
    Ok(out)
}

/// /LINE/SEG: the listed segments, repeated ones once.
fn explicit_edges(
    segs: &[LineSegmentCard],
    ctx: &SetContext,
    kw: &str,
) -> Result<Vec<[u32; 2]>, InputError> {
    let mut edges = Vec::with_capacity(segs.len());
    for s in segs {
        let a = ctx.nodes.resolve(s.nodes[0], &s.loc, kw, "node_ID1")?;
        let b = ctx.nodes.resolve(s.nodes[1], &s.loc, kw, "node_ID2")?;
        if a == b {
            return Err(InputError::new(
                s.loc.clone(),
                kw,
                "node_ID2",
                format!(
                    "{}: the segment's two nodes are the same; expected two different nodes",
                    s.nodes[1]
                ),
            ));
        }
        edges.push([a, b]);
    }
    Ok(unique_edges(edges))
}

/// /LINE/PART: the trusses and beams of the parts (their first two nodes).
fn part_edges(
    c: &LineCard,
    items: &[i64],
    ctx: &SetContext,
    kw: &str,
) -> Result<Vec<[u32; 2]>, InputError> {
    let mut edges = Vec::new();
    for (k, &item) in items.iter().enumerate() {
        let loc = item_loc(&c.item_locs, k, &c.loc);
        let p = ctx.parts.resolve(item.unsigned_abs(), loc, kw, "part_ID")?;
        for set in ctx.elements {
            if matches!(set.kind, ElementKind::Truss | ElementKind::Beam) {
                for e in (0..set.len()).filter(|&e| set.part[e] == p) {
                    let n = set.nodes_of(e);
                    edges.push([n[0], n[1]]);
                }
            }
        }
    }
    Ok(unique_edges(edges))
}

/// The edges of the segments (n4 = n3 triangles have three), each once;
/// with `free_only`, only those that bound a single segment.
pub fn segment_edges(segments: &[[u32; 4]], free_only: bool) -> Vec<[u32; 2]> {
    let mut all = Vec::with_capacity(4 * segments.len());
    for s in segments {
        for k in 0..4 {
            let (a, b) = (s[k], s[(k + 1) % 4]);
            if a != b {
                all.push([a, b]);
            }
        }
    }
    if !free_only {
        return unique_edges(all);
    }
    let mut count: HashMap<[u32; 2], u32> = HashMap::new();
    for e in &all {
        *count.entry(sorted(*e)).or_default() += 1;
    }
    all.into_iter()
        .filter(|e| count[&sorted(*e)] == 1)
        .collect()
}

/// Each edge once (whichever direction), in the order of first appearance.
fn unique_edges(edges: Vec<[u32; 2]>) -> Vec<[u32; 2]> {
    let mut seen = std::collections::HashSet::with_capacity(edges.len());
    edges
        .into_iter()
        .filter(|e| seen.insert(sorted(*e)))
        .collect()
}

fn sorted(e: [u32; 2]) -> [u32; 2] {
    [e[0].min(e[1]), e[0].max(e[1])]
}

#[cfg(test)]
mod tests {
    use super::segment_edges;

    #[test]
    fn surface_lines_and_free_edges_of_two_quads_and_a_triangle() {
        // Quads 0-1-4-3 and 1-2-5-4 share edge 1-4; triangle 4-5-6 shares 4-5.
        let segs = [[0, 1, 4, 3], [1, 2, 5, 4], [4, 5, 6, 6]];
        let all = segment_edges(&segs, false);
        assert_eq!(all.len(), 4 + 3 + 2, "{all:?}"); // 1-4 and 4-5 shared
        assert!(all.contains(&[1, 4]) && !all.contains(&[4, 1]));
        let free = segment_edges(&segs, true);
        assert_eq!(free.len(), 9 - 2, "{free:?}");
        assert!(!free.iter().any(|e| *e == [1, 4] || *e == [4, 1]));
        assert!(!free.iter().any(|e| *e == [4, 5] || *e == [5, 4]));
        assert!(free.contains(&[5, 6]) && free.contains(&[6, 4]));
    }
}
