//! The orientation of one-sided contact surfaces: IRS and IRM of
//! /INTER/TYPE3, IRM of /INTER/TYPE5, IRS and IRm of /INTER/TYPE6
//! (reference guide, "Flag for renumbering the segments" of each surface).
//! These types measure penetration on one side of a main segment only, the
//! side its normal (n = (x3 − x1) × (x4 − x2), right-hand rule on the node
//! order) points to, so a surface given the wrong way round is a surface
//! nothing can touch:
//!
//! - 0: a segment on the face of a solid element whose normal points into
//!   that solid is reversed (a solid's contact face looks out of it);
//!   shell segments stay as given;
//! - 1: every segment of the surface is reversed;
//! - 2: every segment stays as given.
//!
//! Reversing keeps the first node: [a, b, c, d] → [a, d, c, b], and a
//! triangle [a, b, c, c] → [a, c, b, b].

use super::{ElementKind, InterfaceKind, Model, Warning};
use crate::vec3::{dot, scale, sub, V3};
use std::collections::HashMap;

/// The rule of one surface's flag.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Renumbering {
    /// 0: solid faces look out of their solid.
    OutOfSolids,
    /// 1: every segment reversed.
    Reverse,
    /// 2: as given.
    AsGiven,
}

impl Renumbering {
    fn of(flag: i64) -> Self {
        match flag {
            1 => Renumbering::Reverse,
            2 => Renumbering::AsGiven,
            _ => Renumbering::OutOfSolids,
        }
    }
}

/// (secondary surface, main surface) rules of a card, each with its field
/// name; `None` for a side whose orientation no kernel reads.
fn rules(kind: &InterfaceKind) -> [Option<(Renumbering, &'static str)>; 2] {
    let r = |f: i64, name| Some((Renumbering::of(f), name));
    match kind {
        InterfaceKind::Type3(t) => [r(t.irs, "IRS"), r(t.irm, "IRM")],
        InterfaceKind::Type5(t) => [None, r(t.irm, "IRM")],
        InterfaceKind::Type6(t) => [r(t.irs, "IRS"), r(t.irm, "IRm")],
        _ => [None, None],
    }
}

/// The segment with its normal reversed, its first node kept.
pub fn reversed(s: [u32; 4]) -> [u32; 4] {
    if s[3] == s[2] {
        [s[0], s[2], s[1], s[1]]
    } else {
        [s[0], s[3], s[2], s[1]]
    }
}

/// The segment's unit normal (`segment_geometry::segment_normal`).
fn normal(x: &[V3], s: &[u32; 4]) -> V3 {
    super::segment_geometry::segment_normal(&s.map(|n| x[n as usize]), s[3] == s[2])
}

fn mean(x: &[V3], nodes: &[u32]) -> V3 {
    let sum = nodes
        .iter()
        .fold([0.0; 3], |a, &n| crate::vec3::add(a, x[n as usize]));
    scale(sum, 1.0 / nodes.len().max(1) as f64)
}

/// The solid elements around each node of `segs`: (set, element) pairs.
fn solids_at(m: &Model, segs: &[[u32; 4]]) -> HashMap<u32, Vec<(usize, usize)>> {
    let mut at: HashMap<u32, Vec<(usize, usize)>> =
        segs.iter().flatten().map(|&n| (n, Vec::new())).collect();
    for (ki, set) in m.elements.iter().enumerate() {
        if !matches!(set.kind, ElementKind::Brick8 | ElementKind::Tetra4) {
            continue;
        }
        for e in 0..set.len() {
            let mut nodes = set.nodes_of(e).to_vec();
            nodes.sort_unstable();
            nodes.dedup();
            for n in nodes {
                if let Some(v) = at.get_mut(&n) {
                    v.push((ki, e));
                }
            }
        }
    }
    at
}

/// Whether the segment lies on exactly one solid and its normal points
/// into it (from the face's centre towards the solid's centre).
fn points_into_its_solid(m: &Model, at: &HashMap<u32, Vec<(usize, usize)>>, s: &[u32; 4]) -> bool {
    let holds_all = |&&(ki, e): &&(usize, usize)| {
        let nodes = m.elements[ki].nodes_of(e);
        s.iter().all(|n| nodes.contains(n))
    };
    let mut solids = at[&s[0]].iter().filter(holds_all);
    let (Some(&(ki, e)), None) = (solids.next(), solids.next()) else {
        return false;
    };
    let x = &m.nodes.x;
    let mut distinct = m.elements[ki].nodes_of(e).to_vec();
    distinct.sort_unstable();
    distinct.dedup();
    let face: Vec<u32> = if s[3] == s[2] {
        s[..3].to_vec()
    } else {
        s.to_vec()
    };
    dot(normal(x, s), sub(mean(x, &distinct), mean(x, &face))) > 0.0
}

/// Applies a rule to a surface's segments; returns how many it reversed.
pub fn apply(m: &Model, rule: Renumbering, segs: &mut [[u32; 4]]) -> usize {
    let flip: Vec<bool> = match rule {
        Renumbering::AsGiven => return 0,
        Renumbering::Reverse => vec![true; segs.len()],
        Renumbering::OutOfSolids => {
            let at = solids_at(m, segs);
            segs.iter()
                .map(|s| points_into_its_solid(m, &at, s))
                .collect()
        }
    };
    for (s, _) in segs.iter_mut().zip(&flip).filter(|(_, &f)| f) {
        *s = reversed(*s);
    }
    flip.iter().filter(|&&f| f).count()
}

/// Orients the surfaces of every TYPE3, TYPE5 and TYPE6 interface by its
/// flags; rule 0 says in a note how many solid faces it turned.
pub fn orient_interfaces(m: &mut Model) -> Vec<Warning> {
    let mut warnings = Vec::new();
    for i in 0..m.interfaces.len() {
        let [sec, main] = rules(&m.interfaces[i].card.kind);
        let mut segs = [
            std::mem::take(&mut m.interfaces[i].secondary_segments),
            std::mem::take(&mut m.interfaces[i].main_segments),
        ];
        for (rule, s) in [sec, main].into_iter().zip(segs.iter_mut()) {
            let Some((rule, field)) = rule else {
                continue;
            };
            let n = apply(m, rule, s);
            if rule == Renumbering::OutOfSolids && n > 0 {
                let c = &m.interfaces[i].card;
                warnings.push(Warning {
                    loc: c.loc.clone(),
                    keyword: format!("/INTER/TYPE{}/{}", c.type_number(), c.id),
                    message: format!(
                        "{n} segment(s) of the surface of {field} pointed into their solid element and were reversed ({field} = 0; 2 keeps them as given)"
                    ),
                });
            }
        }
        let [s, mn] = segs;
        m.interfaces[i].secondary_segments = s;
        m.interfaces[i].main_segments = mn;
    }
    warnings
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::contact as card;

    /// TYPE3's IRS is its surface 1 (the secondary side), IRM surface 2.
    #[test]
    fn type3_irs_is_the_secondary_surface_irm_the_main() {
        let t3 = InterfaceKind::Type3(card::Type3 {
            surf_id1: 1,
            surf_id2: 2,
            idel: 0,
            stfac: 0.2,
            fric: 0.0,
            gap: 0.0,
            tstart: 0.0,
            tstop: 1e30,
            ibc: [false; 3],
            irs: 1,
            irm: 2,
            ptlim: 1e30,
        });
        assert_eq!(
            rules(&t3),
            [
                Some((Renumbering::Reverse, "IRS")),
                Some((Renumbering::AsGiven, "IRM"))
            ]
        );
    }

    #[test]
    fn reversing_keeps_the_first_node_and_flips_the_normal() {
        let x = vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
        ];
        for s in [[0, 1, 2, 3], [0, 1, 2, 2]] {
            let r = reversed(s);
            assert_eq!(r[0], s[0]);
            assert_eq!(reversed(r), s);
            let (n, nr) = (normal(&x, &s), normal(&x, &r));
            assert!(n[2] > 0.0 && nr[2] < 0.0, "{n:?} {nr:?}");
            assert!((n[2] + nr[2]).abs() < 1e-15);
        }
    }
}
