//! Rigid parts and nodal rigid bodies: `*MAT_RIGID` (`*MAT_020`) and
//! `*CONSTRAINED_NODAL_RIGID_BODY` (`_SPC`) → `/RBODY` (keyword manual
//! volume II "*MAT_RIGID", volume I "*CONSTRAINED_NODAL_RIGID_BODY"; the
//! reference guide maps both to a rigid body the same way).
//!
//! - `*MAT_RIGID`: the material is elastic (/MAT/LAW1 with RO, E, PR, which
//!   give the part its mass and its contact stiffness), and once the deck
//!   is read every part of that material becomes one rigid body over the
//!   part's nodes. Its main node is a new node (the next free id), moved to
//!   the centre of mass (ICOG 1); its mass and inertia are its nodes' lumped
//!   masses; it starts with its nodes' momentum and angular momentum (the
//!   engine's rule when the main node has no initial velocity of its own).
//!   CMO = +1 fixes the body's translations CON1 and rotations CON2
//!   (0 free, 1 x, 2 y, 3 z, 4 xy, 5 yz, 6 zx, 7 all) on the main node;
//!   elements whose nodes all belong to the body are deactivated (no time
//!   step), as LS-DYNA's rigid elements are. Refused by name: N, COUPLE, M
//!   (MADYMO coupling), ALIAS, CMO = −1 (constraints in a local system).
//!   Card 3 (LCO or A1-V3) sets the body's local axes for output only.
//! - `*CONSTRAINED_NODAL_RIGID_BODY`: the node set's nodes (with PNODE)
//!   are one rigid body, its main node new as above; `_SPC`'s card 2
//!   (CMO CON1 CON2) as `*MAT_RIGID`'s. Refused: CID, DRFLAG, RRFLAG (release
//!   of a two-node body's degrees of freedom), `_INERTIA` (not registered:
//!   it stops `run` as a keyword nothing computes).

use super::card::{Card, Cards};
use super::source::Block;
use super::Ctx;
use crate::deck::NodeGroupKind;
use crate::model::{BoundarySpec, Id, InputResult, Loc, MaterialLaw, RigidBodySpec};

/// A rigid body to make once the deck is read: its nodes (a node group),
/// its translational and rotational constraints, its title, where it is
/// defined.
pub struct PendingBody {
    pub nodes: Pending,
    pub fixed: [bool; 6],
    pub title: String,
    pub loc: Loc,
}

/// What a pending body is made of.
pub enum Pending {
    /// Every part of material `MID` (`*MAT_RIGID`).
    Material(Id),
    /// A node group (`*CONSTRAINED_NODAL_RIGID_BODY`'s set, with PNODE).
    Group(Id),
}

/// Card 1: MID RO E PR N COUPLE M ALIAS; card 2: CMO CON1 CON2; card 3:
/// LCO or A1 A2 A3 V1 V2 V3.
pub fn material(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let kw = format!("*{}", b.name);
    while cards.remaining() > 0 {
        let title = super::sections::title(b, cards)?;
        let std = cards.standard();
        let c = cards.next(std.clone(), "the card MID RO E PR N COUPLE M ALIAS")?;
        let (id, rho, e, nu) = super::materials::common(&c)?;
        let whose = format!(" (material {id})");
        ctx.refuse_given(&c, &kw, &[(4, "N"), (5, "COUPLE"), (6, "M")], &whose, false)?;
        if !c.raw(7).trim().is_empty() {
            ctx.refuse(&c.loc(), &kw, format!("field ALIAS{whose}"));
        }
        let c2 = cards.next(std.clone(), "card 2: CMO CON1 CON2")?;
        let fixed = constraints(&c2, ctx, &kw, &whose)?;
        cards.next(std, "card 3: LCO or A1 A2 A3 V1 V2 V3")?;
        ctx.deck.materials.push(super::materials::material(
            id,
            title.clone(),
            rho,
            e,
            nu,
            MaterialLaw::Elastic,
            c.loc(),
        ));
        ctx.rigid.push(PendingBody {
            nodes: Pending::Material(id),
            fixed,
            title: format!("{kw} {id} {title}"),
            loc: c.loc(),
        });
    }
    Ok(())
}

/// CMO CON1 CON2: the fixed degrees of freedom (CMO 0: none; +1: CON1
/// translations, CON2 rotations in the global system; −1 refused).
fn constraints(c: &Card, ctx: &mut Ctx, kw: &str, whose: &str) -> InputResult<[bool; 6]> {
    let cmo = c.real(0, "CMO", 0.0)?;
    if cmo < 0.0 {
        ctx.refuse(
            &c.loc(),
            kw,
            format!("CMO -1 (constraints in a local system){whose}"),
        );
        return Ok([false; 6]);
    }
    if cmo == 0.0 {
        return Ok([false; 6]);
    }
    let mut fixed = [false; 6];
    for (i, name) in [(1, "CON1"), (2, "CON2")] {
        let code = c.real(i, name, 0.0)?;
        let dofs = (code.fract() == 0.0)
            .then(|| super::mesh::constraint(code as i64))
            .flatten()
            .ok_or_else(|| {
                c.err(
                    name,
                    format!(
                        "{code}: expected 0 to 7 (0 free, 1 x, 2 y, 3 z, 4 xy, 5 yz, 6 zx, 7 all)"
                    ),
                )
            })?;
        fixed[3 * (i - 1)..3 * i].copy_from_slice(&dofs);
    }
    Ok(fixed)
}

/// `*CONSTRAINED_NODAL_RIGID_BODY(_SPC)`: card 1 PID CID NSID PNODE IPRT
/// DRFLAG RRFLAG; `_SPC` card 2 CMO CON1 CON2.
pub fn nodal_body(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let kw = format!("*{}", b.name);
    let spc = b.name.contains("_SPC");
    while cards.remaining() > 0 {
        let std = cards.standard();
        let c = cards.next(
            std.clone(),
            "the card PID CID NSID PNODE IPRT DRFLAG RRFLAG",
        )?;
        let pid = c.id_opt(0, "PID")?;
        let whose = format!(" (body {pid})");
        ctx.refuse_given(
            &c,
            &kw,
            &[(1, "CID"), (5, "DRFLAG"), (6, "RRFLAG")],
            &whose,
            true,
        )?;
        let nsid = c.id(2, "NSID")?;
        let pnode = c.id_opt(3, "PNODE")?;
        let fixed = if spc {
            let c2 = cards.next(std, "card 2: CMO CON1 CON2")?;
            constraints(&c2, ctx, &kw, &whose)?
        } else {
            [false; 6]
        };
        ctx.node_sets_used
            .push((nsid, c.loc(), kw.clone(), "NSID".into()));
        let group = if pnode == 0 {
            nsid
        } else {
            let p = ctx.own_group(
                NodeGroupKind::Node,
                vec![pnode as i64],
                format!("{kw} PNODE"),
                &c.loc(),
            );
            ctx.own_group(
                NodeGroupKind::Grnod,
                vec![nsid as i64, p as i64],
                format!("{kw} {pid}"),
                &c.loc(),
            )
        };
        ctx.rigid.push(PendingBody {
            nodes: Pending::Group(group),
            fixed,
            title: format!("{kw} {pid}"),
            loc: c.loc(),
        });
    }
    Ok(())
}

/// Once the deck is read: each pending body's node group (a rigid
/// material's parts), its new main node, the /RBODY and the main node's
/// constraints.
pub fn finish(ctx: &mut Ctx) {
    let bodies = std::mem::take(&mut ctx.rigid);
    for body in bodies {
        let grnod = match body.nodes {
            Pending::Group(g) => g,
            Pending::Material(mid) => {
                let parts: Vec<i64> = ctx
                    .deck
                    .parts
                    .iter()
                    .filter(|p| p.mat == mid)
                    .map(|p| p.id as i64)
                    .collect();
                if parts.is_empty() {
                    // A rigid material no part uses: nothing to make.
                    continue;
                }
                ctx.own_group(NodeGroupKind::Part, parts, body.title.clone(), &body.loc)
            }
        };
        // At the centre of mass once the model is built (ICOG 1).
        let main = ctx.add_node([0.0; 3], &body.loc);
        ctx.deck.rigid_bodies.push(RigidBodySpec {
            id: ctx.deck.rigid_bodies.len() as Id + 1,
            title: body.title.clone(),
            main_node: main,
            sens_id: 0,
            skew_id: 0,
            ispher: 0,
            mass: 0.0,
            grnod,
            ikrem: 0,
            icog: 1,
            surf_id: 0,
            inertia: [0.0; 6],
            ioptoff: 0,
            iexpams: 0,
            loc: body.loc.clone(),
        });
        if body.fixed.iter().any(|&f| f) {
            let on = ctx.own_group(
                NodeGroupKind::Node,
                vec![main as i64],
                body.title.clone(),
                &body.loc,
            );
            ctx.deck.bcs.push(BoundarySpec {
                id: ctx.deck.bcs.len() as Id + 1,
                title: body.title,
                fixed: body.fixed,
                skew_id: 0,
                grnod: on,
                loc: body.loc,
            });
        }
    }
}
