//! `*DEFINE_TRANSFORMATION` and the TRANID of `*INCLUDE_TRANSFORM`
//! (keyword manual volume I, "*DEFINE_TRANSFORMATION"): card 1 TRANID, then
//! rows OPTION A1 ... A7 applied in the order they are written, each to
//! the result of the rows above:
//! - `TRANSL` a1 a2 a3: x + a;
//! - `SCALE` a1 a2 a3: each coordinate times its factor (0: 1);
//! - `ROTATE` a1 a2 a3 a4 a5 a6 a7: by a7 degrees about the axis of
//!   direction (a1, a2, a3) through the point (a4, a5, a6) (right-hand
//!   rule; the form naming two POINTs, a4 to a7 blank, is refused);
//! - `MIRROR`, `POINT`, `POS6P`, `POS6N`, `ROTATE3NA`, `TRANSL2ND` and the
//!   others are refused by name.
//!
//! The nodes of an included file are moved once the deck is read (the
//! transformation may be defined anywhere). Directions and points of other
//! keywords in that file (velocities, load and constraint directions, wall
//! planes) are not transformed: such a keyword in a file whose
//! transformation does more than translate (any, for a rigid wall's
//! points) is refused by name.

use super::card::Cards;
use super::include_transform::Transform;
use super::source::Block;
use super::Ctx;
use crate::model::{Id, InputError, InputResult, Loc};
use std::sync::Arc;

/// One row of a transformation.
#[derive(Clone, Debug, PartialEq)]
pub enum Row {
    Translate([f64; 3]),
    Scale([f64; 3]),
    /// Axis direction (unit), point on it, angle in radians.
    Rotate([f64; 3], [f64; 3], f64),
}

impl Row {
    pub fn apply(&self, x: [f64; 3]) -> [f64; 3] {
        match self {
            Row::Translate(a) => [x[0] + a[0], x[1] + a[1], x[2] + a[2]],
            Row::Scale(s) => [x[0] * s[0], x[1] * s[1], x[2] * s[2]],
            Row::Rotate(n, p, th) => {
                let d = [x[0] - p[0], x[1] - p[1], x[2] - p[2]];
                let r = crate::vec3::rotate(d, *n, *th);
                [p[0] + r[0], p[1] + r[1], p[2] + r[2]]
            }
        }
    }
}

/// `*DEFINE_TRANSFORMATION(_TITLE)`.
pub fn define(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let kw = format!("*{}", b.name);
    let std = cards.standard();
    if super::base_name(&b.name).1 {
        cards.next(std.clone(), "the title card")?;
    }
    let c = cards.next(std.clone(), "the card TRANID")?;
    let id = c.id(0, "TRANID")?;
    if ctx.transformations.iter().any(|t| t.0 == id) {
        return Err(c.err("TRANID", format!("transformation {id} is defined twice")));
    }
    let mut rows = Vec::new();
    while let Some(r) = cards.next_opt(std.clone()) {
        if r.is_blank() {
            continue;
        }
        let option = r.raw(0).to_ascii_uppercase();
        let a: Vec<f64> = (1..8)
            .map(|i| r.real(i, &format!("A{i}"), 0.0))
            .collect::<InputResult<_>>()?;
        let row = match option.as_str() {
            "TRANSL" => Row::Translate([a[0], a[1], a[2]]),
            "SCALE" => Row::Scale([0, 1, 2].map(|k| if a[k] == 0.0 { 1.0 } else { a[k] })),
            "ROTATE" if a[3..7].iter().any(|&v| v != 0.0) => {
                let len = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
                if len == 0.0 {
                    return Err(r.err("A1", "the axis (A1, A2, A3) is zero: expected a direction"));
                }
                let n = [a[0] / len, a[1] / len, a[2] / len];
                Row::Rotate(n, [a[3], a[4], a[5]], a[6].to_radians())
            }
            "ROTATE" => {
                ctx.refuse(&r.loc(), &kw, "ROTATE about two POINTs (A4 to A7 blank)");
                continue;
            }
            "" => return Err(r.err("OPTION", "blank: expected TRANSL, SCALE or ROTATE")),
            other => {
                ctx.refuse(&r.loc(), &kw, format!("option {other}"));
                continue;
            }
        };
        rows.push(row);
    }
    ctx.transformations.push((id, rows, c.loc()));
    Ok(())
}

/// Once the deck is read: the included nodes moved by their files'
/// transformations, and the keywords whose directions or points would need
/// them refused (module comment).
pub fn finish(ctx: &mut Ctx) -> InputResult<()> {
    let moved = std::mem::take(&mut ctx.transformed_nodes);
    // The nodes of one file share its transform: its rows are looked up
    // once per file, not per node.
    let mut last: Option<(&Arc<Transform>, Vec<Row>)> = None;
    for (i, t) in &moved {
        if !last.as_ref().is_some_and(|(l, _)| Arc::ptr_eq(l, t)) {
            last = Some((t, chain(ctx, t)?));
        }
        let rows = &last.as_ref().expect("set above").1;
        let x = &mut ctx.deck.nodes[*i].x;
        *x = rows.iter().fold(*x, |x, r| r.apply(x));
    }
    let directed = std::mem::take(&mut ctx.directed_in_transform);
    for (loc, kw, t) in &directed {
        let rows = chain(ctx, t)?;
        let points = kw.starts_with("*RIGIDWALL");
        if points || !rows.iter().all(|r| matches!(r, Row::Translate(_))) {
            ctx.refuse(
                loc,
                kw,
                "in a file of *INCLUDE_TRANSFORM whose TRANID turns, scales or (a wall's points) moves it: its directions and points are not transformed",
            );
        }
    }
    Ok(())
}

/// The rows of every TRANID of `t`, in the order they apply (the innermost
/// file's first); an undefined TRANID is an error at its card.
fn chain(ctx: &Ctx, t: &Transform) -> InputResult<Vec<Row>> {
    let mut rows = Vec::new();
    for (id, at) in &t.tranids {
        rows.extend(rows_of(ctx, *id, at)?.iter().cloned());
    }
    Ok(rows)
}

fn rows_of<'c>(ctx: &'c Ctx, id: Id, at: &Loc) -> InputResult<&'c [Row]> {
    ctx.transformations
        .iter()
        .find(|d| d.0 == id)
        .map(|d| d.1.as_slice())
        .ok_or_else(|| {
            InputError::new(
                at.clone(),
                "*INCLUDE_TRANSFORM",
                "TRANID",
                format!("transformation {id} is not defined: expected a *DEFINE_TRANSFORMATION with TRANID {id}"),
            )
        })
}

/// Keyword families whose cards hold directions or points.
pub fn has_directions(base: &str) -> bool {
    [
        "INITIAL_VELOCITY",
        "RIGIDWALL",
        "BOUNDARY_SPC",
        "BOUNDARY_PRESCRIBED_MOTION",
        "LOAD_NODE",
        "LOAD_BODY",
    ]
    .iter()
    .any(|f| base.starts_with(f))
}

/// Records a node read from a file with a TRANID, or a keyword with
/// directions there (`finish`).
pub fn note(ctx: &mut Ctx, b: &Block, node: Option<usize>) {
    let Some(t) = b.transform.as_ref().filter(|t| !t.tranids.is_empty()) else {
        return;
    };
    match node {
        Some(i) => ctx.transformed_nodes.push((i, Arc::clone(t))),
        None => {
            ctx.directed_in_transform
                .push((b.loc.clone(), format!("*{}", b.name), Arc::clone(t)))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_translate_scale_and_rotate_about_an_axis_through_a_point() {
        let x = [1.0, 0.0, 0.0];
        assert_eq!(Row::Translate([1.0, 2.0, 3.0]).apply(x), [2.0, 2.0, 3.0]);
        assert_eq!(Row::Scale([2.0, 1.0, 1.0]).apply(x), [2.0, 0.0, 0.0]);
        // 90° about z through (1, 1, 0): (1, 0, 0) → (2, 1, 0).
        let r = Row::Rotate([0.0, 0.0, 1.0], [1.0, 1.0, 0.0], 90f64.to_radians()).apply(x);
        assert!((r[0] - 2.0).abs() < 1e-15 && (r[1] - 1.0).abs() < 1e-15 && r[2] == 0.0);
    }
}
