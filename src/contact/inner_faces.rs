//! Faces between two solids as dormant main segments (TYPE25 with
//! /SURF/PART/ALL): such a face is no contact surface while both its solids
//! live; once one of them is deleted the face is the survivor's outer
//! surface and becomes a segment, outward from the survivor.
//!
//! The reference starter stores an inner face's stiffness negative (dormant)
//! and its engine takes only faces of positive stiffness as candidates,
//! turning a face positive when a neighbour solid is deleted
//! (docs/notes/type24_type25_research.md §2.1, §5.2). Here /SURF/PART/ALL
//! gives an inner face twice, each solid's own face outward from it; the
//! face of solid A shared with solid B belongs to A (its stiffness, its
//! Idel removal when A is deleted) and wakes when B is deleted.

use super::geometry::{self as geo, V3};
use crate::model::{ElementKind, Model};
use std::collections::HashMap;

/// An inner face: the solid it is the face of, and the solid whose deletion
/// exposes it (each as (kind index, element index)).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct InnerFace {
    pub owner: (u8, u32),
    pub waker: (u8, u32),
}

fn is_solid(m: &Model, ki: u8) -> bool {
    matches!(
        m.elements[ki as usize].kind,
        ElementKind::Brick8 | ElementKind::Tetra4
    )
}

/// The mean position of an element's distinct nodes.
fn centroid(m: &Model, (ki, e): (u8, u32)) -> V3 {
    let mut n = m.elements[ki as usize].nodes_of(e as usize).to_vec();
    n.sort_unstable();
    n.dedup();
    let mut c = [0.0; 3];
    for &q in &n {
        c = geo::add(c, m.nodes.x[q as usize]);
    }
    geo::scale(c, 1.0 / n.len() as f64)
}

/// For each main segment, `Some` when it is a face between two solids: the
/// solid it faces outward from is its owner, the other its waker. A face
/// shared by more than two solids is an error (the mesh overlaps).
pub(super) fn classify(
    m: &Model,
    face_elems: &HashMap<[u32; 4], Vec<(u8, u32)>>,
    main: &[[u32; 4]],
    key: impl Fn(&[u32; 4]) -> [u32; 4],
) -> Result<Vec<Option<InnerFace>>, String> {
    let mut out = Vec::with_capacity(main.len());
    for seg in main {
        let solids: Vec<(u8, u32)> = face_elems
            .get(&key(seg))
            .map(|v| v.iter().copied().filter(|e| is_solid(m, e.0)).collect())
            .unwrap_or_default();
        let id = |c: u32| m.nodes.ids[c as usize];
        match solids.len() {
            0 | 1 => out.push(None),
            2 => {
                let x = seg.map(|n| m.nodes.x[n as usize]);
                let tri = seg[3] == seg[2];
                let n = geo::segment_normal(&x, tri);
                let w = if tri { [1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0, 0.0] } else { [0.25; 4] };
                let centre = geo::interpolate(&w, &x);
                // The owner's centroid lies behind its outward face.
                let behind =
                    |e: (u8, u32)| geo::dot(geo::sub(centroid(m, e), centre), n) < 0.0;
                let (owner, waker) = match (behind(solids[0]), behind(solids[1])) {
                    (true, false) => (solids[0], solids[1]),
                    (false, true) => (solids[1], solids[0]),
                    _ => {
                        return Err(format!(
                            "main segment {} {} {} {} lies between two solids but faces outward from neither (or both): expected each solid's face listed outward from it",
                            id(seg[0]), id(seg[1]), id(seg[2]), id(seg[3])
                        ))
                    }
                };
                out.push(Some(InnerFace { owner, waker }));
            }
            _ => {
                return Err(format!(
                    "main segment {} {} {} {} is a face of {} solids: the solids overlap (a face belongs to at most two)",
                    id(seg[0]), id(seg[1]), id(seg[2]), id(seg[3]), solids.len()
                ))
            }
        }
    }
    Ok(out)
}
