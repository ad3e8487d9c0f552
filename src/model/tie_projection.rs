//! Where a tied secondary node lies on its main surface: the search
//! distance of /INTER/TYPE2 and the nearest main segment, used by the
//! set-up of the ties (`contact::tied`) and, before masses and element
//! geometry, to move the secondary nodes of LS-DYNA's ties without an
//! offset option onto the surface (`Type2::project`).

use super::segment_geometry::{self as geo, V3};
use super::{InterfaceKind, Model};

/// dsearch: the card's, or 0 → the mean edge length of the main segments
/// (reference guide, /INTER/TYPE2 dsearch).
pub fn search_distance(t: &super::contact::Type2, segs: &[[u32; 4]], x: &[V3]) -> f64 {
    if t.dsearch > 0.0 {
        return t.dsearch;
    }
    let (mut sum, mut n) = (0.0, 0usize);
    for s in segs {
        let x = s.map(|q| x[q as usize]);
        let k = if s[3] == s[2] { 3 } else { 4 };
        for e in 0..k {
            sum += geo::norm(geo::sub(x[(e + 1) % k], x[e]));
            n += 1;
        }
    }
    sum / n as f64
}

/// The main segment nearest to `xs` (the first of equals): its distance,
/// index and the projection on it. `segs` is not empty.
pub fn nearest_segment(xs: V3, segs: &[[u32; 4]], x: &[V3]) -> (f64, usize, geo::Projection) {
    let mut best: Option<(f64, usize, geo::Projection)> = None;
    for (k, seg) in segs.iter().enumerate() {
        let xm = seg.map(|q| x[q as usize]);
        let pr = geo::project(xs, &xm, seg[3] == seg[2]);
        if best.as_ref().is_none_or(|b| pr.dist < b.0) {
            best = Some((pr.dist, k, pr));
        }
    }
    best.expect("segments")
}

/// LS-DYNA's tied options without `_OFFSET` (`Type2::project`): each
/// secondary node within dsearch of the main surface is moved onto its
/// nearest segment, before masses and element geometry are computed (the
/// nodes of every such interface in card order, each from the positions
/// the earlier moves left). Returns how many nodes moved.
pub fn project_secondary_nodes(m: &mut Model) -> usize {
    let mut moved = 0;
    for i in 0..m.interfaces.len() {
        let it = &m.interfaces[i];
        let InterfaceKind::Type2(t) = &it.card.kind else {
            continue;
        };
        if !t.project || it.main_segments.is_empty() {
            continue;
        }
        let dsearch = search_distance(t, &it.main_segments, &m.nodes.x);
        let mut to: Vec<(u32, V3)> = Vec::new();
        for &s in &it.secondary_nodes {
            let xs = m.nodes.x[s as usize];
            let (dist, k, pr) = nearest_segment(xs, &it.main_segments, &m.nodes.x);
            if dist <= dsearch {
                let seg = it.main_segments[k];
                to.push((
                    s,
                    geo::interpolate(&pr.shape, &seg.map(|q| m.nodes.x[q as usize])),
                ));
            }
        }
        moved += to.len();
        for (s, p) in to {
            m.nodes.x[s as usize] = p;
        }
    }
    moved
}
