//! Resolving groups and surfaces to dense indices. Group references may point
//! forward in the deck and nest (/GRNOD/GRNOD); cycles are errors.

use super::id_index::IdIndex;
use super::{item_loc, NodeGroupCard, NodeGroupKind, ShellGroupCard, SurfaceCard, SurfaceDef};
use crate::model::{ElementSet, Id, InputError, NodeGroup, ShellGroup, Surface};
use std::collections::{BTreeSet, HashMap};

/// Deepest /GRNOD/GRNOD nesting accepted. Resolution recurses once per level,
/// so an unbounded chain (one group naming the next, thousands deep) would
/// overflow the stack; real decks nest a few levels.
pub const MAX_GROUP_NESTING: usize = 256;

pub struct SetContext<'a> {
    pub nodes: &'a IdIndex,
    pub parts: &'a IdIndex,
    pub shells4: &'a IdIndex,
    /// Element sets in `Elements::KINDS` order.
    pub elements: &'a [ElementSet],
    /// The resolved surfaces and their ids (/GRNOD/SURF), once known.
    pub surfaces: Option<(&'a [Surface], &'a IdIndex)>,
    /// The initial node positions and the resolved boxes with their ids
    /// (/GRSHEL/BOX).
    pub x: &'a [[f64; 3]],
    pub boxes: (&'a [super::boxes::SelectionBox], &'a IdIndex),
    /// The resolved shell groups and their ids (/GRNOD/GRSHEL), once known.
    pub shell_groups: Option<(&'a [ShellGroup], &'a IdIndex)>,
}

/// Resolves every node group (in deck order).
pub fn node_groups(
    cards: &[NodeGroupCard],
    ctx: &SetContext,
) -> Result<Vec<NodeGroup>, InputError> {
    let index = IdIndex::build(
        "node group",
        cards.iter().map(|c| (c.id, c.loc.clone())),
        "/GRNOD",
    )?;
    let mut done: HashMap<usize, Vec<u32>> = HashMap::new();
    let mut out = Vec::with_capacity(cards.len());
    for i in 0..cards.len() {
        let mut stack = Vec::new();
        let nodes = resolve_group(i, cards, &index, ctx, &mut done, &mut stack)?;
        out.push(NodeGroup {
            id: cards[i].id,
            title: cards[i].title.clone(),
            nodes,
        });
    }
    Ok(out)
}

fn resolve_group(
    i: usize,
    cards: &[NodeGroupCard],
    index: &IdIndex,
    ctx: &SetContext,
    done: &mut HashMap<usize, Vec<u32>>,
    stack: &mut Vec<usize>,
) -> Result<Vec<u32>, InputError> {
    if let Some(n) = done.get(&i) {
        return Ok(n.clone());
    }
    let card = &cards[i];
    let kw = format!("/GRNOD/{:?}/{}", card.kind, card.id).to_uppercase();
    if stack.contains(&i) {
        let chain: Vec<String> = stack
            .iter()
            .chain(std::iter::once(&i))
            .map(|&k| cards[k].id.to_string())
            .collect();
        return Err(InputError::new(
            card.loc.clone(),
            &kw,
            "grnd_ID",
            format!(
                "node groups refer to each other in a cycle: {}",
                chain.join(" -> ")
            ),
        ));
    }
    if stack.len() >= MAX_GROUP_NESTING {
        return Err(InputError::new(
            card.loc.clone(),
            &kw,
            "grnd_ID",
            format!(
                "node groups nest deeper than {MAX_GROUP_NESTING} levels (/GRNOD/GRNOD {} -> ... -> {}); expected a shallower nesting",
                cards[stack[0]].id, card.id
            ),
        ));
    }
    stack.push(i);
    let mut add = BTreeSet::new();
    let mut remove = BTreeSet::new();
    for (k, &item) in card.items.iter().enumerate() {
        let loc = item_loc(&card.item_locs, k, &card.loc);
        let id = item.unsigned_abs() as Id;
        let target = if item > 0 { &mut add } else { &mut remove };
        match card.kind {
            NodeGroupKind::Node => {
                target.insert(ctx.nodes.resolve(id, loc, &kw, "node_ID")?);
            }
            NodeGroupKind::Part => {
                let p = ctx.parts.resolve(id, loc, &kw, "part_ID")?;
                for set in ctx.elements {
                    for e in 0..set.len() {
                        if set.part[e] == p {
                            target.extend(
                                set.nodes_of(e)
                                    .iter()
                                    .copied()
                                    .filter(|&n| n != crate::model::NO_NODE),
                            );
                        }
                    }
                }
            }
            NodeGroupKind::Box => {
                let (boxes, index) = ctx.boxes;
                let b = &boxes[index.resolve(id, loc, &kw, "box_ID")? as usize];
                let inside = ctx.x.iter().enumerate().filter(|(_, p)| b.contains(**p));
                target.extend(inside.map(|(n, _)| n as u32));
            }
            NodeGroupKind::Grshel => {
                let (groups, index) = ctx
                    .shell_groups
                    .expect("shell groups resolved before node groups");
                let g = index.resolve(id, loc, &kw, "grshel_ID")? as usize;
                let shells = &ctx.elements[0];
                for &e in &groups[g].shells {
                    target.extend(shells.nodes_of(e as usize).iter().copied());
                }
            }
            NodeGroupKind::Surf => {
                let (surfaces, surf_index) =
                    ctx.surfaces.expect("surfaces resolved before node groups");
                let s = surf_index.resolve(id, loc, &kw, "surf_ID")? as usize;
                target.extend(surfaces[s].nodes());
            }
            NodeGroupKind::Grnod => {
                let g = index.resolve(id, loc, &kw, "grnd_ID")? as usize;
                let nodes = resolve_group(g, cards, index, ctx, done, stack)?;
                target.extend(nodes);
            }
        }
    }
    stack.pop();
    let nodes: Vec<u32> = add.difference(&remove).copied().collect();
    done.insert(i, nodes.clone());
    Ok(nodes)
}

/// Resolves the shell groups.
pub fn shell_groups(
    cards: &[ShellGroupCard],
    ctx: &SetContext,
) -> Result<Vec<ShellGroup>, InputError> {
    IdIndex::build(
        "shell group",
        cards.iter().map(|c| (c.id, c.loc.clone())),
        "/GRSHEL",
    )?;
    let mut out = Vec::new();
    for c in cards {
        if let Some((box_id, all)) = c.by_box {
            out.push(shells_in_box(c, box_id, all, ctx)?);
            continue;
        }
        let kw = format!("/GRSHEL/SHEL/{}", c.id);
        let mut add = BTreeSet::new();
        let mut remove = BTreeSet::new();
        for (k, &item) in c.items.iter().enumerate() {
            let loc = item_loc(&c.item_locs, k, &c.loc);
            let e = ctx
                .shells4
                .resolve(item.unsigned_abs(), loc, &kw, "shell_ID")?;
            if item > 0 {
                add.insert(e);
            } else {
                remove.insert(e);
            }
        }
        out.push(ShellGroup {
            id: c.id,
            title: c.title.clone(),
            shells: add.difference(&remove).copied().collect(),
        });
    }
    Ok(out)
}

/// /GRSHEL/BOX (`all`: every node of the shell in the box) and /GRSHEL/BOX2
/// (at least one node), on the initial geometry (guide, /GRSHEL/BOX).
fn shells_in_box(
    c: &ShellGroupCard,
    box_id: Id,
    all: bool,
    ctx: &SetContext,
) -> Result<ShellGroup, InputError> {
    let kw = format!("/GRSHEL/{}/{}", if all { "BOX" } else { "BOX2" }, c.id);
    let (boxes, index) = ctx.boxes;
    let b = &boxes[index.resolve(box_id, &c.loc, &kw, "box_ID")? as usize];
    let shells = &ctx.elements[0];
    let inside = |e: usize| {
        let mut nodes = shells.nodes_of(e).iter().map(|&n| ctx.x[n as usize]);
        if all {
            nodes.all(|p| b.contains(p))
        } else {
            nodes.any(|p| b.contains(p))
        }
    };
    Ok(ShellGroup {
        id: c.id,
        title: c.title.clone(),
        shells: (0..shells.len())
            .filter(|&e| inside(e))
            .map(|e| e as u32)
            .collect(),
    })
}

/// Segment of a shell, reversed if `flip` (n1 n4 n3 n2 keeps n4 = n3 triangles valid as n1 n3 n2 n2).
fn shell_segment(nodes: &[u32], flip: bool) -> [u32; 4] {
    let s = if nodes.len() == 3 {
        [nodes[0], nodes[1], nodes[2], nodes[2]]
    } else {
        [nodes[0], nodes[1], nodes[2], nodes[3]]
    };
    if !flip {
        s
    } else if s[2] == s[3] {
        [s[0], s[2], s[1], s[1]]
    } else {
        [s[0], s[3], s[2], s[1]]
    }
}

/// Which faces of a part's solids a surface takes.
#[derive(Clone, Copy, PartialEq, Eq)]
enum SolidFaces {
    /// Faces not shared by two of its solids (/SURF/PART, /SURF/PART/EXT).
    External,
    /// Every face, each solid's own, outward from it (/SURF/PART/ALL).
    All,
}

/// The faces of the solids of part `p` that `which` selects, outward (inward if `flip`).
fn solid_faces(ctx: &SetContext, p: u32, which: SolidFaces, flip: bool, out: &mut Vec<[u32; 4]>) {
    use crate::model::ElementKind;
    let mut faces: Vec<[u32; 4]> = Vec::new();
    for set in ctx.elements {
        let local: &[[usize; 4]] = match set.kind {
            ElementKind::Brick8 => &crate::model::geometry::HEXA_FACES,
            ElementKind::Tetra4 => &[[0, 2, 1, 1], [0, 1, 3, 3], [1, 2, 3, 3], [2, 0, 3, 3]],
            _ => continue,
        };
        for e in 0..set.len() {
            if set.part[e] != p {
                continue;
            }
            let n = set.nodes_of(e);
            for f in local {
                let face = [n[f[0]], n[f[1]], n[f[2]], n[f[3]]];
                let mut distinct: Vec<u32> = face.to_vec();
                distinct.sort_unstable();
                distinct.dedup();
                if distinct.len() >= 3 {
                    faces.push(face);
                }
            }
        }
    }
    let flipped = |f: [u32; 4]| if flip { [f[0], f[3], f[2], f[1]] } else { f };
    if which == SolidFaces::All {
        out.extend(faces.into_iter().map(flipped));
        return;
    }
    let key = |f: &[u32; 4]| {
        let mut k = *f;
        k.sort_unstable();
        k
    };
    let mut count: HashMap<[u32; 4], u32> = HashMap::new();
    for f in &faces {
        *count.entry(key(f)).or_default() += 1;
    }
    for f in faces {
        if count[&key(&f)] == 1 {
            out.push(flipped(f));
        }
    }
}

/// Resolves the surfaces; a surface with no segment is an error.
pub fn surfaces(
    cards: &[SurfaceCard],
    shell_groups: &[ShellGroup],
    grshel_cards: &[ShellGroupCard],
    ctx: &SetContext,
) -> Result<Vec<Surface>, InputError> {
    use crate::model::ElementKind;
    IdIndex::build(
        "surface",
        cards.iter().map(|c| (c.id, c.loc.clone())),
        "/SURF",
    )?;
    let grshel_index = IdIndex::build(
        "shell group",
        grshel_cards.iter().map(|c| (c.id, c.loc.clone())),
        "/GRSHEL",
    )?;
    let mut out = Vec::new();
    for c in cards {
        let mut segments = Vec::new();
        let kw;
        if let SurfaceDef::Ellipsoid(e) = &c.def {
            out.push(Surface {
                id: c.id,
                title: c.title.clone(),
                segments,
                ellipsoid: Some(e.clone()),
            });
            continue;
        }
        match &c.def {
            SurfaceDef::Parts(items) | SurfaceDef::PartsAllFaces(items) => {
                let which = match &c.def {
                    SurfaceDef::PartsAllFaces(_) => SolidFaces::All,
                    _ => SolidFaces::External,
                };
                kw = match which {
                    SolidFaces::All => format!("/SURF/PART/ALL/{}", c.id),
                    SolidFaces::External => format!("/SURF/PART/{}", c.id),
                };
                for (k, &item) in items.iter().enumerate() {
                    let loc = item_loc(&c.item_locs, k, &c.loc);
                    let p = ctx
                        .parts
                        .resolve(item.unsigned_abs(), loc, &kw, "part_ID")?;
                    let flip = item < 0;
                    for set in ctx.elements {
                        if matches!(set.kind, ElementKind::Shell4 | ElementKind::Shell3) {
                            for e in 0..set.len() {
                                if set.part[e] == p {
                                    segments.push(shell_segment(set.nodes_of(e), flip));
                                }
                            }
                        }
                    }
                    solid_faces(ctx, p, which, flip, &mut segments);
                }
            }
            SurfaceDef::ShellGroups(items) => {
                kw = format!("/SURF/GRSHEL/{}", c.id);
                let shells = &ctx.elements[0];
                for (k, &item) in items.iter().enumerate() {
                    let loc = item_loc(&c.item_locs, k, &c.loc);
                    let g = grshel_index.resolve(item.unsigned_abs(), loc, &kw, "grshel_ID")?;
                    for &e in &shell_groups[g as usize].shells {
                        segments.push(shell_segment(shells.nodes_of(e as usize), item < 0));
                    }
                }
            }
            SurfaceDef::Segments(segs) => {
                kw = format!("/SURF/SEG/{}", c.id);
                for s in segs {
                    let mut n = [0u32; 4];
                    for (k, name) in ["node_ID1", "node_ID2", "node_ID3", "node_ID4"]
                        .iter()
                        .enumerate()
                    {
                        n[k] = ctx.nodes.resolve(s.nodes[k], &s.loc, &kw, name)?;
                    }
                    segments.push(n);
                }
            }
            SurfaceDef::Ellipsoid(_) => unreachable!("taken above"),
        }
        if segments.is_empty() {
            return Err(InputError::new(c.loc.clone(), &kw, "", "the surface has no segments (its parts or groups hold no shell or solid face); expected at least one"));
        }
        out.push(Surface {
            id: c.id,
            title: c.title.clone(),
            segments,
            ellipsoid: None,
        });
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use crate::deck::{read_deck, EngineFile, ReadOptions};

    /// A chain of /GRNOD/GRNOD groups, each naming the next, `n` deep.
    fn chain_deck(n: usize) -> String {
        let mut s = String::from("/BEGIN\nchain\n      2022         0\n/NODE\n");
        s += "         1                   0                   0                   0\n";
        for i in 1..n {
            s += &format!("/GRNOD/GRNOD/{i}\ng{i}\n{:>10}\n", i + 1);
        }
        s += &format!("/GRNOD/NODE/{n}\nlast\n         1\n/END\n");
        s
    }

    fn build_text(name: &str, text: &str) -> Result<crate::model::Model, crate::model::InputError> {
        let dir = std::env::temp_dir().join(format!("crashsim-sets-{name}-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("chain_0000.rad");
        std::fs::write(&path, text).unwrap();
        let deck = read_deck(&path, EngineFile::None, ReadOptions::default());
        let _ = std::fs::remove_dir_all(&dir);
        crate::deck::build_model(&deck?)
    }

    /// Found reviewing the reader for fuzzing: a long /GRNOD/GRNOD chain overflowed the stack
    /// (one recursion per level); it is now an error past MAX_GROUP_NESTING.
    #[test]
    fn deep_group_nesting_is_an_error_not_a_stack_overflow() {
        let e = build_text("deep", &chain_deck(20_000)).unwrap_err();
        assert!(e.message.contains("nest deeper than"), "{}", e.message);
        let m = build_text("shallow", &chain_deck(super::MAX_GROUP_NESTING)).unwrap();
        assert!(m.node_groups.iter().all(|g| g.nodes == [0]));
    }
}
