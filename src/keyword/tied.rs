//! LS-DYNA's tied contacts → /INTER/TYPE2 (keyword manual volume I
//! "*CONTACT", the tied options; the reference guide's TYPE2):
//!
//! | keyword | ties | Spotflag | nodes moved onto the surface |
//! | --- | --- | --- | --- |
//! | `*CONTACT_TIED_NODES_TO_SURFACE` | translations | 4 | yes |
//! | `*CONTACT_TIED_SURFACE_TO_SURFACE` | translations | 4 | yes |
//! | `*CONTACT_TIED_SHELL_EDGE_TO_SURFACE` | translations and rotations | 5 | yes |
//! | each with `_CONSTRAINED_OFFSET` | the same | the same | no: the offset is a rigid arm |
//! | each with `_OFFSET` (LS-DYNA: penalty) | translations | 4 | no |
//! | `*CONTACT_TIED_SHELL_EDGE_TO_SURFACE_BEAM_OFFSET` (penalty) | translations and rotations | 5 | no |
//!
//! The secondary nodes (SSID: a node set, part, part set, shell set or
//! segment set) are tied kinematically at set-up: each follows the point
//! of the main segment (MSID) it projects on. Without an offset option
//! LS-DYNA "projects the slave nodes to the master surface during
//! initialization" (`Type2::project`: moved before masses and element
//! geometry). Spotflag 4 passes no rotation (reference guide: "Rotational
//! DOF are not transmitted"), as LS-DYNA's nodes and surfaces ties, which
//! constrain translations only; a shell edge's rotations are tied too
//! (Spotflag 5 passes the moments to the main nodes). Nodes that find no
//! segment within the search distance stay free, with a warning (Ignore
//! 1000, dsearch from the element sizes).
//!
//! `_OFFSET` and `_BEAM_OFFSET` are penalty springs in LS-DYNA ("tied
//! contacts whose name holds OFFSET or BEAM_OFFSET are penalty-based",
//! dynasupport "Tied, tied offset and tiebreak contacts"; a plain `_OFFSET`
//! carries no moment of the offset, `_BEAM_OFFSET` does). They run here as
//! the kinematic tie with the offset kept, the stiff limit of that spring,
//! as OpenRadioss's keyword reader maps every tied option (to TYPE2
//! Spotflag 28, kinematic where no other condition conflicts); the listing
//! says so for each (the spring's own compliance is not computed).
//!
//! Not registered (they stop `run` by name): `_FAILURE`, tiebreaks.
//! Refused by name here: SBOXID, MBOXID, a birth or death time, SST/MST,
//! and optional cards.

use super::card::Cards;
use super::contacts::{parts_surface, secondary_nodes};
use super::source::Block;
use super::Ctx;
use crate::model::contact::Type2;
use crate::model::{Id, InputResult, InterfaceKind, InterfaceSpec};

/// Spotflag, whether the nodes move onto the surface, and whether LS-DYNA
/// computes the tie as a penalty spring, by keyword (module table).
fn form(name: &str) -> (i64, bool, bool) {
    let (base, _, _) = super::base_name(name);
    let edge = |b: &str| {
        if b.ends_with("SHELL_EDGE_TO_SURFACE") {
            5
        } else {
            4
        }
    };
    if let Some(b) = base.strip_suffix("_CONSTRAINED_OFFSET") {
        (edge(b), false, false)
    } else if base.ends_with("_BEAM_OFFSET") {
        (5, false, true)
    } else if base.ends_with("_OFFSET") {
        (4, false, true)
    } else {
        (edge(base), true, false)
    }
}

/// Cards 1-3 of *CONTACT (the title card with `_ID`/`_TITLE`).
pub fn tied(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let kw = format!("*{}", b.name);
    let (spotflag, project, penalty) = form(&b.name);
    if penalty {
        ctx.deck.warnings.push(crate::model::Warning {
            loc: b.loc.clone(),
            keyword: kw.clone(),
            message: format!(
                "LS-DYNA's penalty tie is computed as the kinematic tie with its offset kept (TYPE2 Spotflag {spotflag}), the stiff limit of the spring, as OpenRadioss's reader maps it"
            ),
        });
    }
    let std = cards.standard();
    let (mut id, title) = super::contacts::heading(b, cards)?;
    let c1 = cards.next(
        std.clone(),
        "card 1: SSID MSID SSTYP MSTYP SBOXID MBOXID SPR MPR",
    )?;
    let loc = c1.loc();
    ctx.refuse_given(&c1, &kw, &[(4, "SBOXID"), (5, "MBOXID")], "", true)?;
    let c2 = cards.next(std.clone(), "card 2: FS FD DC VC VDC PENCHK BT DT")?;
    ctx.refuse_given(&c2, &kw, &[(6, "BT")], "", false)?;
    let dt = c2.real(7, "DT", 0.0)?;
    if dt != 0.0 && dt < 1e20 {
        ctx.refuse(&c2.loc(), &kw, "field DT (a death time)");
    }
    let c3 = cards.next(std, "card 3: SFS SFM SST MST SFST SFMT FSF VSF")?;
    ctx.refuse_given(&c3, &kw, &[(2, "SST"), (3, "MST")], "", false)?;
    if cards.remaining() > 0 {
        let c = cards.next_opt(cards.standard()).expect("a card");
        ctx.refuse(&c.loc(), &kw, "optional cards A and beyond");
    }
    let ((ssid, sstyp), (msid, mstyp)) = super::contacts::set_ids(&c1)?;
    let grnod_ids = secondary_nodes(ctx, ssid, sstyp, &loc, &kw, "SSID")?;
    let surf_idm = parts_surface(ctx, msid, mstyp, &loc, &kw, "MSID")?;
    if id == 0 {
        id = ctx.deck.interfaces.len() as Id + 1;
    }
    ctx.deck.interfaces.push(InterfaceSpec {
        id,
        unit_id: 0,
        title,
        kind: InterfaceKind::Type2(Type2 {
            grnod_ids,
            surf_idm,
            ignore: 1000,
            spotflag,
            level: 0,
            isearch: 2,
            idel2: 1000,
            surf_ids: 0,
            dsearch: 0.0,
            rupture: None,
            penalty: None,
            thermal: None,
            project,
        }),
        loc: loc.clone(),
        ids_loc: loc,
    });
    Ok(())
}
