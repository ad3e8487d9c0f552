//! /PLOAD/pload_ID/unit_ID: a pressure on the segments of a surface
//! (reference guide /PLOAD; research note
//! `docs/notes/submodel_pload_random_research.md` §2).
//!
//! Card 1 is the title; card 2's layout follows the input version:
//! - before 51: surf_ID (1-8), fct_IDT (9-16), sens_ID (17-24), Fscale_y (33-48);
//! - 51 to 2019: surf_ID (1-10), fct_IDT (11-20), sens_ID (21-30),
//!   Ascale_x (61-80), Fscale_y (81-100);
//! - 2020 adds Ipinch (31-40), 2021 Idel (41-50), 2023 Itypfun (51-60).
//!
//! Ascale_x and Fscale_y blank or 0 are 1. Refused by name: a sensor
//! (sensors are not computed), Ipinch 1 (the pinching pressure of QBAT
//! shells) and Itypfun 2/3 (a function of the segment's displacement or
//! velocity instead of time).

use super::fields::{one_if_zero, Cards};
use super::source::Block;
use super::{header_id, header_id_opt, Deck};
use crate::model::{ElementSet, InputError, InputResult, PressureLoad, PressureLoadSpec, Surface};
use std::collections::HashMap;

/// Reads one /PLOAD.
pub(super) fn parse_pload(block: &Block, deck: &mut Deck) -> InputResult<bool> {
    let id = header_id(block, 1, "pload_ID")?;
    let unit_id = header_id_opt(block, 2, "unit_ID")?;
    let invers = deck.begin.as_ref().map_or(0, |b| b.invers);
    let latest = |v: i64| invers == 0 || invers >= v;
    let mut cards = Cards::new(block);
    let title = cards.title();
    let c = cards.next("the card with surf_ID, fct_IDT, sens_ID, Ascale_x, Fscale_y")?;
    let old = invers > 0 && invers < 51;
    let (surf, fct, sens, ascale_x, fscale_y) = if old {
        (
            c.int(1, "surf_ID", 0)?,
            c.int(9, "fct_IDT", 0)?,
            c.int(17, "sens_ID", 0)?,
            0.0,
            c.real_opt(33, 16, "Fscale_y")?.unwrap_or(0.0),
        )
    } else {
        (
            c.int(1, "surf_ID", 0)?,
            c.int(11, "fct_IDT", 0)?,
            c.int(21, "sens_ID", 0)?,
            c.real(61, "Ascale_x", 0.0)?,
            c.real(81, "Fscale_y", 0.0)?,
        )
    };
    if surf <= 0 {
        return Err(c.err("surf_ID", format!("{surf}: expected the id of a /SURF")));
    }
    if fct <= 0 {
        return Err(c.err("fct_IDT", format!("{fct}: expected the id of a /FUNCT")));
    }
    if sens != 0 {
        return Err(c.err(
            "sens_ID",
            "a sensor-started /PLOAD is not supported yet (sensors are not computed)",
        ));
    }
    if ascale_x < 0.0 {
        return Err(c.err(
            "Ascale_x",
            format!("{ascale_x}: the time scale must be > 0 (blank: 1)"),
        ));
    }
    let ipinch = if latest(2020) {
        c.int(31, "Ipinch", 0)?
    } else {
        0
    };
    if ipinch != 0 {
        return Err(c.err(
            "Ipinch",
            format!("{ipinch}: the pinching pressure of QBAT shells is not supported; expected 0"),
        ));
    }
    let idel = if latest(2021) {
        c.int(41, "Idel", 0)?
    } else {
        0
    };
    let itypfun = if latest(2023) {
        c.int(51, "Itypfun", 0)?
    } else {
        0
    };
    if !(0..=1).contains(&itypfun) {
        return Err(c.err(
            "Itypfun",
            format!("{itypfun}: a pressure function of the segment's displacement or velocity is not supported; expected 0 or 1 (time)"),
        ));
    }
    super::warn_surplus(&cards, "the card with surf_ID", &mut deck.warnings);
    deck.pressure_loads.push(PressureLoadSpec {
        id,
        unit_id,
        title,
        surf: surf as u64,
        fct: fct as u64,
        ascale_x: one_if_zero(ascale_x),
        fscale_y: one_if_zero(fscale_y),
        keep_after_deletion: idel == 2,
        loc: c.loc(),
    });
    Ok(true)
}

/// Each /PLOAD with its surface's segments and the element carrying each
/// segment: the first shell whose nodes are the segment's, or solid with
/// the segment as a face (kinds in `ElementKind::ALL` order, elements in
/// id order). `surface`: the index of surface `id`, named by the card.
pub(super) fn resolve(
    cards: &[PressureLoadSpec],
    surfaces: &[Surface],
    surface: impl Fn(&PressureLoadSpec) -> Result<usize, InputError>,
    elements: &[ElementSet],
) -> Result<Vec<PressureLoad>, InputError> {
    let mut out = Vec::with_capacity(cards.len());
    for c in cards {
        let s = &surfaces[surface(c)?];
        if s.segments.is_empty() {
            return Err(InputError::new(
                c.loc.clone(),
                &format!("/PLOAD/{}", c.id),
                "surf_ID",
                format!(
                    "surface {} has no segments; expected a surface of element faces",
                    c.surf
                ),
            ));
        }
        let carriers = carriers(&s.segments, elements).map_err(|seg| {
            InputError::new(
                c.loc.clone(),
                &format!("/PLOAD/{}", c.id),
                "surf_ID",
                format!(
                    "segment {} of surface {} (dense nodes {:?}) is no face of a shell or solid; \
                     a pressure needs the element under it",
                    seg + 1,
                    c.surf,
                    s.segments[seg]
                ),
            )
        })?;
        out.push(PressureLoad {
            card: c.clone(),
            segments: s.segments.clone(),
            carriers,
        });
    }
    Ok(out)
}

/// The carrier of each segment, or the index of the first segment without one.
fn carriers(segments: &[[u32; 4]], elements: &[ElementSet]) -> Result<Vec<(u8, u32)>, usize> {
    let mut around: HashMap<u32, Vec<(u8, u32)>> =
        segments.iter().map(|s| (s[0], Vec::new())).collect();
    for set in elements.iter().filter(|s| {
        use crate::model::ElementKind::*;
        matches!(s.kind, Shell4 | Shell3 | Brick8 | Tetra4)
    }) {
        let ki = set.kind.index() as u8;
        for e in 0..set.len() {
            for n in set.nodes_of(e) {
                if let Some(list) = around.get_mut(n) {
                    if list.last() != Some(&(ki, e as u32)) {
                        list.push((ki, e as u32));
                    }
                }
            }
        }
    }
    let contains = |(k, e): (u8, u32), seg: &[u32; 4]| {
        let set = &elements[k as usize];
        let nodes = set.nodes_of(e as usize);
        seg.iter().all(|n| nodes.contains(n))
    };
    segments
        .iter()
        .enumerate()
        .map(|(i, seg)| {
            around[&seg[0]]
                .iter()
                .copied()
                .find(|&c| contains(c, seg))
                .ok_or(i)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::ElementKind;

    fn set(kind: ElementKind, nodes: Vec<u32>) -> ElementSet {
        let n = nodes.len() / kind.nodes();
        ElementSet {
            kind,
            ids: (1..=n as u64).collect(),
            part: vec![0; n],
            nodes,
            thick: vec![0.0; n],
        }
    }

    #[test]
    fn a_segment_is_carried_by_its_shell_or_the_solid_it_bounds() {
        let mut sets: Vec<ElementSet> = ElementKind::ALL
            .iter()
            .map(|&k| set(k, Vec::new()))
            .collect();
        sets[0] = set(ElementKind::Shell4, vec![0, 1, 2, 3, 4, 5, 6, 7]);
        sets[2] = set(ElementKind::Brick8, vec![10, 11, 12, 13, 14, 15, 16, 17]);
        let segs = [[4, 5, 6, 7], [14, 15, 16, 17], [3, 2, 1, 0]];
        assert_eq!(carriers(&segs, &sets), Ok(vec![(0, 1), (2, 0), (0, 0)]));
        assert_eq!(carriers(&[[0, 1, 5, 4]], &sets), Err(0));
    }
}
