//! References checked in keyword terms once the whole deck is read (a
//! keyword may name an id defined further down): every element's part and
//! nodes, every part's section and material, every set a condition names.
//! The model builder checks them again; doing it here first makes the
//! error name the keyword deck's keyword and field (`*PART`, `SECID`),
//! and, where the id would come from a keyword that is not computed, that
//! keyword.

use super::Ctx;
use crate::deck::ElementCard;
use crate::model::{Id, InputError, InputResult, Loc, PropertyKind};
use std::collections::HashSet;

pub fn check(ctx: &Ctx) -> InputResult<()> {
    let d = &ctx.deck;
    let nodes: HashSet<Id> = d.nodes.iter().map(|n| n.id).collect();
    let groups: HashSet<Id> = d.node_groups.iter().map(|g| g.id).collect();
    let e = |loc: &Loc, kw: &str, field: &str, msg: String| {
        InputError::new(loc.clone(), kw, field, msg)
    };
    for p in &d.parts {
        let section = d.properties.iter().find(|s| s.id == p.prop);
        if section.is_none() {
            return Err(e(
                &p.loc,
                "*PART",
                "SECID",
                missing(ctx, "section", p.prop, "*SECTION"),
            ));
        }
        let spring = matches!(section.map(|s| &s.kind), Some(PropertyKind::Spring(_)));
        if !spring && !d.materials.iter().any(|m| m.id == p.mat) {
            return Err(e(
                &p.loc,
                "*PART",
                "MID",
                missing(ctx, "material", p.mat, "*MAT"),
            ));
        }
    }
    let kinds = [
        ("*ELEMENT_SHELL", &d.elements.shell4, true),
        ("*ELEMENT_SHELL", &d.elements.shell3, true),
        ("*ELEMENT_SOLID", &d.elements.brick8, false),
        ("*ELEMENT_SOLID", &d.elements.tetra4, false),
    ];
    for (kw, cards, shell) in kinds {
        for c in cards.iter() {
            element(ctx, c, kw, shell, &nodes)?;
        }
    }
    for m in &d.materials {
        let crate::model::MaterialLaw::Tabulated(t) = &m.law else {
            continue;
        };
        for c in &t.curves {
            if !d.functions.iter().any(|f| f.id == c.fct) {
                return Err(e(
                    &m.loc,
                    "*MAT_PIECEWISE_LINEAR_PLASTICITY",
                    "LCSS",
                    missing(ctx, "curve", c.fct, "*DEFINE_CURVE"),
                ));
            }
        }
    }
    for (id, loc, kw, field) in &ctx.segment_sets_used {
        if !d.surfaces.iter().any(|s| s.id == *id) {
            return Err(e(
                loc,
                kw,
                field,
                missing(ctx, "segment set", *id, "*SET_SEGMENT"),
            ));
        }
    }
    for (id, loc, kw, field) in &ctx.node_sets_used {
        if !groups.contains(id) {
            return Err(e(loc, kw, field, format!("node set {id} is not defined")));
        }
    }
    for b in &d.bcs {
        if !groups.contains(&b.grnod) {
            return Err(e(
                &b.loc,
                "*BOUNDARY_SPC_SET",
                "NSID",
                format!("node set {} is not defined", b.grnod),
            ));
        }
    }
    let motions = d.imposed_velocities.iter().chain(&d.imposed_displacements);
    let groups_of = motions
        .map(|m| (m.grnod, m.fct, &m.loc, "*BOUNDARY_PRESCRIBED_MOTION"))
        .chain(
            d.concentrated_loads
                .iter()
                .map(|l| (l.grnod, l.fct, &l.loc, "*LOAD_NODE")),
        )
        .chain(d.gravity.iter().map(|g| (0, g.fct, &g.loc, "*LOAD_BODY")));
    for (g, f, loc, kw) in groups_of {
        if g != 0 && !groups.contains(&g) {
            return Err(e(loc, kw, "NSID", format!("node set {g} is not defined")));
        }
        if !d.functions.iter().any(|c| c.id == f) {
            return Err(e(
                loc,
                kw,
                "LCID",
                missing(ctx, "curve", f, "*DEFINE_CURVE"),
            ));
        }
    }
    for v in &d.initial_velocities {
        if !groups.contains(&v.grnod) {
            return Err(e(
                &v.loc,
                &v.title,
                "NSID",
                format!("node set {} is not defined", v.grnod),
            ));
        }
    }
    Ok(())
}

/// An element's part must exist and carry a section of its family; its
/// nodes must exist.
fn element(
    ctx: &Ctx,
    c: &ElementCard,
    kw: &str,
    shell: bool,
    nodes: &HashSet<Id>,
) -> InputResult<()> {
    let d = &ctx.deck;
    let err = |field: &str, msg: String| InputError::new(c.loc.clone(), kw, field, msg);
    let part = d
        .parts
        .iter()
        .find(|p| p.id == c.part)
        .ok_or_else(|| err("PID", missing(ctx, "part", c.part, "*PART")))?;
    let kind = d
        .properties
        .iter()
        .find(|s| s.id == part.prop)
        .map(|s| &s.kind);
    let fits = match kind {
        Some(PropertyKind::Shell(_)) => shell,
        Some(PropertyKind::Solid(_)) => !shell,
        _ => true,
    };
    if !fits {
        let want = if shell {
            "*SECTION_SHELL"
        } else {
            "*SECTION_SOLID"
        };
        return Err(err(
            "PID",
            format!(
                "part {} has section {}, which is not a {want}",
                part.id, part.prop
            ),
        ));
    }
    for (i, n) in c.nodes.iter().enumerate() {
        if *n != 0 && !nodes.contains(n) {
            return Err(err(
                &format!("N{}", i + 1),
                format!("node {n} is not defined (no *NODE gives it)"),
            ));
        }
    }
    Ok(())
}

/// "WHAT ID is not defined", naming the keywords of `family` the deck has
/// but that are not computed (one of them may have defined it).
fn missing(ctx: &Ctx, what: &str, id: Id, family: &str) -> String {
    let skipped: Vec<String> = ctx
        .deck
        .unsupported
        .iter()
        .filter(|w| w.keyword.starts_with(family))
        .map(|w| format!("{} at {}", w.keyword, w.loc))
        .collect();
    if skipped.is_empty() {
        format!("{what} {id} is not defined (expected a {family}... keyword with id {id})")
    } else {
        format!(
            "{what} {id} is not defined; the deck's {} may define it but is not supported",
            skipped.join(", ")
        )
    }
}
