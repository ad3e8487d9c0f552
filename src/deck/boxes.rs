//! Boxes for selecting entities: /BOX/RECTA, /BOX/SPHER and /BOX/CYLIN
//! (reference guide, Starter, "Boxes"). Read here; resolved on the initial
//! geometry by [`resolve_boxes`] into [`SelectionBox`]es, which the groups
//! that select by box (/GRSHEL/BOX, /GRSHEL/BOX2) test their nodes against.
//!
//! Cards (title line first):
//! * RECTA: N1 N2 (1-20) skew_ID (21-30); P1 = Xp1 Yp1 Zp1; P2 = Xp2 Yp2 Zp2
//!   (three 20-column reals per line): the box with opposite corners P1, P2;
//! * SPHER: N1 (1-10) Diameter (41-60); P1: the sphere of that diameter
//!   centred at P1;
//! * CYLIN: N1 N2 (1-20) Diameter (41-60); P1; P2: the cylinder of that
//!   diameter on the axis P1→P2, between its end planes.
//!
//! A point given by a node (N1, N2 > 0) is that node's initial position; the
//! coordinates are read otherwise. A point on the surface is inside (guide,
//! /GRSHEL/BOX: "all nodes inside the box or on its surface").

use super::fields::Cards;
use super::id_index::IdIndex;
use super::source::Block;
use super::{header_id, header_id_opt, Deck};
use crate::model::{Id, InputError, InputResult, Loc};
use crate::vec3::{dot, sub};
use serde::{Deserialize, Serialize};

/// The shape of a box card.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum BoxShape {
    Rectangle,
    Sphere,
    Cylinder,
}

/// A box card before its nodes are resolved.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct BoxCard {
    pub id: Id,
    pub title: String,
    pub shape: BoxShape,
    /// N1, N2 (0: the point's coordinates are given).
    pub nodes: [Id; 2],
    /// P1, P2 as written (P2 unused by a sphere).
    pub points: [[f64; 3]; 2],
    pub diameter: f64,
    pub skew_id: Id,
    pub loc: Loc,
}

/// A resolved box, in the global frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SelectionBox {
    /// Axis-aligned: the lowest and highest corner.
    Rectangle {
        lo: [f64; 3],
        hi: [f64; 3],
    },
    Sphere {
        centre: [f64; 3],
        radius: f64,
    },
    Cylinder {
        p1: [f64; 3],
        p2: [f64; 3],
        radius: f64,
    },
}

impl SelectionBox {
    /// The point is inside the box or on its surface.
    pub fn contains(&self, p: [f64; 3]) -> bool {
        match *self {
            SelectionBox::Rectangle { lo, hi } => (0..3).all(|k| lo[k] <= p[k] && p[k] <= hi[k]),
            SelectionBox::Sphere { centre, radius } => {
                let d = sub(p, centre);
                dot(d, d) <= radius * radius
            }
            SelectionBox::Cylinder { p1, p2, radius } => {
                let axis = sub(p2, p1);
                let d = sub(p, p1);
                let len2 = dot(axis, axis);
                let along = dot(d, axis);
                if along < 0.0 || along > len2 {
                    return false;
                }
                // Squared distance to the axis: |d|² − (d·a)²/|a|².
                dot(d, d) - along * along / len2 <= radius * radius
            }
        }
    }
}

/// Reads /BOX/RECTA, /BOX/SPHER and /BOX/CYLIN; false for another box type.
pub(super) fn parse_box(block: &Block, deck: &mut Deck) -> InputResult<bool> {
    let shape = match block.parts.get(1).map(String::as_str).unwrap_or("") {
        "RECTA" => BoxShape::Rectangle,
        "SPHER" => BoxShape::Sphere,
        "CYLIN" => BoxShape::Cylinder,
        _ => return Ok(false),
    };
    let id = header_id(block, 2, "box_ID")?;
    header_id_opt(block, 3, "unit_ID")?;
    let mut cards = Cards::new(block);
    let title = cards.title();
    let c = cards.next("the card with the nodes and the size")?;
    let n1 = c.id_opt(1, "N1")?;
    let (n2, skew_id, diameter) = match shape {
        BoxShape::Rectangle => (c.id_opt(11, "N2")?, c.id_opt(21, "skew_ID")?, 0.0),
        BoxShape::Sphere => (0, 0, c.real(41, "Diameter", 0.0)?),
        BoxShape::Cylinder => (c.id_opt(11, "N2")?, 0, c.real(41, "Diameter", 0.0)?),
    };
    if shape != BoxShape::Rectangle && !(diameter > 0.0) {
        return Err(c.err(
            "Diameter",
            format!("{diameter}: expected a positive diameter"),
        ));
    }
    let npoints = if shape == BoxShape::Sphere { 1 } else { 2 };
    let mut points = [[0.0; 3]; 2];
    for (k, p) in points.iter_mut().take(npoints).enumerate() {
        let what = format!("P{}", k + 1);
        let c = cards.next(&format!("the card with Xp{0}, Yp{0}, Zp{0}", k + 1))?;
        for (j, x) in p.iter_mut().enumerate() {
            *x = c.real(1 + 20 * j, &what, 0.0)?;
        }
    }
    super::warn_surplus(&cards, "the last card of the box", &mut deck.warnings);
    deck.boxes.push(BoxCard {
        id,
        title,
        shape,
        nodes: [n1, n2],
        points,
        diameter,
        skew_id,
        loc: block.loc.clone(),
    });
    Ok(true)
}

/// The deck's boxes on the initial geometry `x` (ids unique, nodes defined);
/// with the index of their ids.
pub(super) fn resolve_boxes(
    deck: &Deck,
    nodes: &IdIndex,
    x: &[[f64; 3]],
) -> Result<(Vec<SelectionBox>, IdIndex), InputError> {
    let index = IdIndex::build(
        "box",
        deck.boxes.iter().map(|b| (b.id, b.loc.clone())),
        "/BOX",
    )?;
    let mut out = Vec::with_capacity(deck.boxes.len());
    for c in &deck.boxes {
        let kw = format!("/BOX/{}/{}", shape_name(c.shape), c.id);
        let mut p = c.points;
        for k in 0..2 {
            if c.nodes[k] != 0 {
                let field = format!("N{}", k + 1);
                p[k] = x[nodes.resolve(c.nodes[k], &c.loc, &kw, &field)? as usize];
            }
        }
        let radius = 0.5 * c.diameter;
        out.push(match c.shape {
            BoxShape::Rectangle => {
                if c.skew_id != 0 {
                    return Err(InputError::new(
                        c.loc.clone(),
                        &kw,
                        "skew_ID",
                        format!(
                            "{}: a box in a skew frame is not computed yet (give its corners in the global frame)",
                            c.skew_id
                        ),
                    ));
                }
                SelectionBox::Rectangle {
                    lo: std::array::from_fn(|k| p[0][k].min(p[1][k])),
                    hi: std::array::from_fn(|k| p[0][k].max(p[1][k])),
                }
            }
            BoxShape::Sphere => SelectionBox::Sphere {
                centre: p[0],
                radius,
            },
            BoxShape::Cylinder => {
                if p[0] == p[1] {
                    return Err(InputError::new(
                        c.loc.clone(),
                        &kw,
                        "P1, P2",
                        "the two ends of the cylinder's axis coincide: expected distinct points",
                    ));
                }
                SelectionBox::Cylinder {
                    p1: p[0],
                    p2: p[1],
                    radius,
                }
            }
        });
    }
    Ok((out, index))
}

fn shape_name(s: BoxShape) -> &'static str {
    match s {
        BoxShape::Rectangle => "RECTA",
        BoxShape::Sphere => "SPHER",
        BoxShape::Cylinder => "CYLIN",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_point_on_the_surface_is_inside() {
        let s = SelectionBox::Sphere {
            centre: [1.0, 0.0, 0.0],
            radius: 2.0,
        };
        assert!(s.contains([3.0, 0.0, 0.0]));
        assert!(!s.contains([3.0 + 1e-9, 0.0, 0.0]));
        let r = SelectionBox::Rectangle {
            lo: [0.0; 3],
            hi: [1.0, 2.0, 3.0],
        };
        assert!(r.contains([1.0, 2.0, 3.0]) && r.contains([0.5, 0.0, 1.0]));
        assert!(!r.contains([0.5, 2.1, 1.0]));
    }

    #[test]
    fn a_cylinder_ends_at_its_planes() {
        let c = SelectionBox::Cylinder {
            p1: [0.0, 1.0, 1.0],
            p2: [10.0, 1.0, 1.0],
            radius: 0.5,
        };
        assert!(c.contains([0.0, 1.5, 1.0]));
        assert!(c.contains([10.0, 1.0, 0.5]));
        assert!(c.contains([5.0, 1.3, 1.3]));
        assert!(!c.contains([5.0, 1.4, 1.4])); // 0.566 from the axis
        assert!(!c.contains([-0.01, 1.0, 1.0]));
        assert!(!c.contains([10.01, 1.0, 1.0]));
    }
}
