//! `*CONTACT_TIED_SHELL_EDGE_TO_SURFACE_CONSTRAINED_OFFSET` → /INTER/TYPE2
//! Spotflag 5 (keyword manual volume I "*CONTACT", the tied options; the
//! reference guide's TYPE2).
//!
//! The secondary nodes (SSID: a node set, part, part set or segment set)
//! are tied kinematically to the main surface (MSID) at set-up: each
//! follows the point of the segment it projects on, with its offset kept
//! as a rigid arm (the `_CONSTRAINED_OFFSET` option: nodes are not moved
//! onto the surface), and its rotations follow the segment's (a shell
//! edge's rotations are tied too: Spotflag 5 passes the moments to the
//! main nodes). Nodes that find no segment within the search distance
//! stay free, with a warning (Ignore 1000, dsearch from the element sizes).
//!
//! Not registered (they stop `run` by name): the plain option, which moves
//! the nodes onto the surface; `_OFFSET` and `_BEAM_OFFSET` (penalty ties);
//! `_NODES_TO_SURFACE` and `_SURFACE_TO_SURFACE`, which tie translations
//! only. Refused by name here: SBOXID, MBOXID, a birth or death time,
//! SST/MST, and optional cards.

use super::card::Cards;
use super::contacts::{parts_surface, secondary_nodes};
use super::source::Block;
use super::Ctx;
use crate::model::contact::Type2;
use crate::model::{Id, InputResult, InterfaceKind, InterfaceSpec};

/// Cards 1-3 of *CONTACT (the title card with `_ID`/`_TITLE`).
pub fn shell_edge(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let kw = format!("*{}", b.name);
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
    let (ssid, sstyp) = (c1.id_opt(0, "SSID")?, c1.int(2, "SSTYP", 0)?);
    let (msid, mstyp) = (c1.id_opt(1, "MSID")?, c1.int(3, "MSTYP", 0)?);
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
            spotflag: 5,
            level: 0,
            isearch: 2,
            idel2: 1000,
            surf_ids: 0,
            dsearch: 0.0,
            rupture: None,
            penalty: None,
            thermal: None,
        }),
        loc: loc.clone(),
        ids_loc: loc,
    });
    Ok(())
}
