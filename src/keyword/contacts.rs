//! `*CONTACT_AUTOMATIC_SINGLE_SURFACE`, `*CONTACT_AUTOMATIC_NODES_TO_SURFACE`
//! and `*CONTACT_AUTOMATIC_GENERAL(_INTERIOR)`
//! with SOFT = 0 or 1, and `*CONTROL_CONTACT`'s SLSFAC (keyword manual volume I,
//! "*CONTACT", "*CONTROL_CONTACT").
//!
//! They run on the TYPE7 kernel (node to segment, both sides of a shell,
//! edges and corners, its search; the reference guide maps these keywords
//! to a Radioss penalty interface too) with LS-DYNA's own penalty:
//! - stiffness (`model::contact::DynaPenalty`): SLSFAC·SFS or SFM times
//!   K·A/d_max on shells, K·A²/V on solids, the smaller of the pair's two;
//!   SOFT = 1 takes the larger of that and the soft constraint
//!   0.5·SOFSCL·m*/Δt² (m* the smaller of the pair's node masses, Δt the
//!   solution step; seed 003 and the theory manual's soft constraint);
//! - force F = K·P, linear to and through the surface (no TYPE7 stiffening
//!   toward the gap, no quadratic damper), and the damper VDC % of
//!   critical, VDC/100·2·√(K·M);
//! - contact thickness half the shell thickness on each side (TYPE7's
//!   variable gap, Igap 1); Coulomb friction FS (DC 0).
//!
//! SOFT = 2 on `*CONTACT_AUTOMATIC_SINGLE_SURFACE` and
//! `*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE` is LS-DYNA's segment-based
//! contact (`contact::interfaces::dyna_segment`: segment pairs, the
//! initial penetration as baseline, k from the segment masses and the
//! time step, DEPTH 5 edge-to-edge); the keyword gives it as a TYPE7 card
//! (with the surface-to-surface form's SSID surface as its secondary
//! surface) whose `DynaPenalty` says SOFT 2, and that type takes it.
//!
//! `*CONTACT_AUTOMATIC_SURFACE_TO_SURFACE` with SOFT 0/1 is two node-to-
//! surface TYPE7s, each surface's nodes on the other's segments (the second
//! with SFS and SFM swapped), as a Radioss deck writes a symmetric contact.
//!
//! `*CONTACT_AUTOMATIC_GENERAL` (SOFT 0/1) is a TYPE19 self-contact of the
//! SSID surface, which Radioss computes as TYPE7 nodes to surface plus
//! TYPE11 edge to edge: LS-DYNA checks "beams and exterior (unshared)
//! shell edges" along their whole length besides the nodes, so the edge
//! part takes the surface's free edges (Iedge 1), and every edge with
//! `_INTERIOR` (Iedge 2); both parts run LS-DYNA's penalty
//! (`contact::interfaces::type11`, linear law). (OpenRadioss's reader maps
//! the keyword to a TYPE25 without edges unless SOFT is −19.)
//!
//! Other SOFT values (and SOFT 2 nodes to surface), SBOPT other than 2, DEPTH other than 2 or 5 on SOFT 2,
//! FRCFRQ > 1, SST/MST, SFST/SFMT, DC, VC, box and set types not read are
//! refused by name.

use super::card::{Card, Cards};
use super::include_transform::contact_set_kind;
use super::source::Block;
use super::{base_name, Ctx};
use crate::deck::{NodeGroupKind, SurfaceCard, SurfaceDef};
use crate::model::contact::{DynaPenalty, Type19, Type7, EP30};
use crate::model::{Id, InputResult, InterfaceKind, InterfaceSpec, Loc};

/// `*CONTROL_CONTACT` card 1: SLSFAC RWPNAL ISLCHK SHLTHK PENOPT THKCHG
/// ORIEN ENMASS. SLSFAC (0 → 0.1) scales every contact's stiffness.
pub fn control(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let kw = format!("*{}", b.name);
    let std = cards.standard();
    let c = cards.next(
        std,
        "the card SLSFAC RWPNAL ISLCHK SHLTHK PENOPT THKCHG ORIEN ENMASS",
    )?;
    let s = c.real(0, "SLSFAC", 0.0)?;
    if s < 0.0 {
        return Err(c.err(
            "SLSFAC",
            format!("{s}: expected a scale factor >= 0 (0: 0.1)"),
        ));
    }
    ctx.slsfac = if s == 0.0 { 0.1 } else { s };
    // SHLTHK 0/1 (thickness considered), PENOPT 0/1 (the minimum of the
    // pair's stiffnesses), THKCHG 0 (the initial thickness) are what runs.
    for (i, name, most) in [(3, "SHLTHK", 1), (4, "PENOPT", 1), (5, "THKCHG", 0)] {
        if !(0..=most).contains(&c.int(i, name, 0)?) {
            ctx.refuse(&c.loc(), &kw, format!("field {name}"));
        }
    }
    ctx.refuse_given(&c, &kw, &[(7, "ENMASS")], "", true)?;
    // RWPNAL > 0 or < 0 treats rigid-wall nodes by penalty; ours are the
    // constraint method (0): refused once the deck is read if it has a wall.
    ctx.rwpnal = Some((c.real(1, "RWPNAL", 0.0)?, c.loc()));
    optional_controls(cards, ctx, &kw)
}

/// `*CONTROL_CONTACT` cards 2-6 (each optional). What runs: card 2's NSBCS
/// and INTERM (how often LS-DYNA searches: ours sorts whenever the motion
/// since the last sort passes half the margin, every pair in reach found)
/// and XPENE 0 or 4 (its default); card 4's IGNORE (0; 1 and 2: initial
/// penetrations kept as the gap's baseline, TYPE7 Inacti 5), FRCENG,
/// SKIPRWG, OUTSEG (output only). Every other field given and not 0 is
/// refused by name (card 3's default friction and scale factors, card 5's
/// symmetry and rigid-wall gaps, card 6's edge shape and stiffness option).
fn optional_controls(cards: &mut Cards, ctx: &mut Ctx, kw: &str) -> InputResult<()> {
    const REFUSED: [&[(usize, &str)]; 5] = [
        &[
            (0, "USRSTR"),
            (1, "USRFRC"),
            (5, "SSTHK"),
            (6, "ECDT"),
            (7, "TIEDPRJ"),
        ],
        &[
            (0, "SFRIC"),
            (1, "DFRIC"),
            (2, "EDC"),
            (3, "VFC"),
            (4, "TH"),
            (5, "TH_SF"),
            (6, "PEN_SF"),
            (7, "PTSCL"),
        ],
        &[
            (4, "SPOTSTP"),
            (5, "SPOTDEL"),
            (6, "SPOTHIN"),
            (7, "DIR_TIE"),
        ],
        &[
            (0, "ISYM"),
            (1, "NSEROD"),
            (2, "RWGAPS"),
            (3, "RWGDTH"),
            (4, "RWKSF"),
            (5, "ICOV"),
            (6, "SWRADF"),
            (7, "ITHOFF"),
        ],
        &[
            (0, "SHLEDG"),
            (1, "PSTIFF"),
            (2, "ITHCNT"),
            (3, "TDCNOF"),
            (4, "FTALL"),
            (6, "SHLTRW"),
            (7, "IGACTC"),
        ],
    ];
    for (n, fields) in REFUSED.iter().enumerate() {
        let std = cards.standard();
        let Some(c) = cards.next_opt(std) else {
            return Ok(());
        };
        ctx.refuse_given(&c, kw, fields, "", false)?;
        match n {
            0 => {
                let xpene = c.real(4, "XPENE", 0.0)?;
                if xpene != 0.0 && xpene != 4.0 {
                    ctx.refuse(&c.loc(), kw, "field XPENE (0 or 4 runs)");
                }
            }
            2 => {
                let ignore = c.int(0, "IGNORE", 0)?;
                if !(0..=2).contains(&ignore) {
                    return Err(c.err("IGNORE", format!("{ignore}: expected 0, 1 or 2")));
                }
                ctx.ignore_penetrations = ignore > 0;
            }
            _ => {}
        }
    }
    Ok(())
}

/// Which contact keyword.
#[derive(Clone, Copy, PartialEq)]
enum Form {
    SingleSurface,
    NodesToSurface,
    SurfaceToSurface,
    /// `*CONTACT_AUTOMATIC_GENERAL`; `_INTERIOR`: every edge, not only the
    /// free ones.
    General {
        interior: bool,
    },
}

pub fn general(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    let interior = base_name(&b.name).0.ends_with("_INTERIOR");
    contact(b, cards, ctx, Form::General { interior })
}

pub fn single_surface(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    contact(b, cards, ctx, Form::SingleSurface)
}

pub fn nodes_to_surface(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    contact(b, cards, ctx, Form::NodesToSurface)
}

pub fn surface_to_surface(b: &Block, cards: &mut Cards, ctx: &mut Ctx) -> InputResult<()> {
    contact(b, cards, ctx, Form::SurfaceToSurface)
}

/// The `_ID`/`_TITLE` card of a *CONTACT keyword: (CID, HEADING), (0, "")
/// without it.
pub(super) fn heading(b: &Block, cards: &mut Cards) -> InputResult<(Id, String)> {
    let (_, titled, with_id) = base_name(&b.name);
    if !(titled || with_id) {
        return Ok((0, String::new()));
    }
    let c = cards.next(vec![10, 70], "the card CID HEADING")?;
    Ok((c.id_opt(0, "CID")?, c.raw(1).to_string()))
}

fn contact(b: &Block, cards: &mut Cards, ctx: &mut Ctx, form: Form) -> InputResult<()> {
    let kw = format!("*{}", b.name);
    let std = cards.standard();
    let (mut id, title) = heading(b, cards)?;
    let c1 = cards.next(
        std.clone(),
        "card 1: SSID MSID SSTYP MSTYP SBOXID MBOXID SPR MPR",
    )?;
    let loc = c1.loc();
    let ((ssid, sstyp), (msid, mstyp)) = set_ids(&c1)?;
    ctx.refuse_given(&c1, &kw, &[(4, "SBOXID"), (5, "MBOXID")], "", true)?;
    let c2 = cards.next(std.clone(), "card 2: FS FD DC VC VDC PENCHK BT DT")?;
    let fs = c2.real(0, "FS", 0.0)?;
    let vdc = c2.real(4, "VDC", 0.0)?;
    ctx.refuse_given(&c2, &kw, &[(2, "DC"), (3, "VC"), (5, "PENCHK")], "", false)?;
    let bt = c2.real(6, "BT", 0.0)?;
    let dt = c2.real(7, "DT", 0.0)?;
    let c3 = cards.next(std.clone(), "card 3: SFS SFM SST MST SFST SFMT FSF VSF")?;
    let one = |v: f64| if v == 0.0 { 1.0 } else { v };
    let sfs = one(c3.real(0, "SFS", 1.0)?);
    let sfm = one(c3.real(1, "SFM", 1.0)?);
    for (i, name, free) in [
        (2, "SST", 0.0),
        (3, "MST", 0.0),
        (4, "SFST", 1.0),
        (5, "SFMT", 1.0),
        (6, "FSF", 1.0),
        (7, "VSF", 1.0),
    ] {
        let v = c3.real(i, name, free)?;
        if v != free && v != 0.0 {
            ctx.refuse(&c3.loc(), &kw, format!("field {name}"));
        }
    }
    let (soft, sofscl, depth) = optional_cards(cards, ctx, &kw)?;
    if soft == 2 && matches!(form, Form::NodesToSurface | Form::General { .. }) {
        ctx.refuse(
            &loc,
            &kw,
            "SOFT 2 on a nodes-to-surface or general contact (segment-based contact is for single-surface and surface-to-surface contacts)",
        );
    }
    if id == 0 {
        id = ctx.deck.interfaces.len() as Id + 1;
    }
    let penalty = DynaPenalty {
        slsfac: ctx.slsfac,
        sfs,
        sfm,
        soft,
        sofscl,
        depth,
    };
    let side = |ctx: &mut Ctx, sid: Id, styp: i64, field: &str| -> InputResult<(Id, Id)> {
        Ok((
            secondary_nodes(ctx, sid, styp, &loc, &kw, field)?,
            parts_surface(ctx, sid, styp, &loc, &kw, field)?,
        ))
    };
    let one = |grnod, surf, dyna| type7(grnod, surf, fs, vdc, bt, dt, dyna);
    let spec_of = |id, title: String, kind| InterfaceSpec {
        id,
        unit_id: 0,
        title,
        kind,
        loc: loc.clone(),
        ids_loc: loc.clone(),
    };
    let spec = |id, title: String, t: Type7| spec_of(id, title, InterfaceKind::Type7(t));
    let specs = match form {
        Form::General { interior } => {
            // TYPE19 self-contact: nodes to surface (the node part) and the
            // shell edges against each other (the edge part), both with
            // LS-DYNA's penalty; free edges, or every edge with _INTERIOR.
            let surf = parts_surface(ctx, ssid, sstyp, &loc, &kw, "SSID")?;
            let t = Type19 {
                surf_ids: surf,
                surf_idm: 0,
                igap: 1,
                iedge: if interior { 2 } else { 1 },
                edge_scale_gap: 0.0,
                nodes: one(0, surf, penalty),
            };
            vec![spec_of(id, title, InterfaceKind::Type19(t))]
        }
        Form::SingleSurface => {
            let surf = parts_surface(ctx, ssid, sstyp, &loc, &kw, "SSID")?;
            vec![spec(id, title, one(0, surf, penalty))]
        }
        Form::NodesToSurface => {
            let surf = parts_surface(ctx, msid, mstyp, &loc, &kw, "MSID")?;
            let grnod = secondary_nodes(ctx, ssid, sstyp, &loc, &kw, "SSID")?;
            vec![spec(id, title, one(grnod, surf, penalty))]
        }
        Form::SurfaceToSurface if soft == 2 => {
            // Segment-based: the SSID surface's segments against MSID's.
            let surf = parts_surface(ctx, msid, mstyp, &loc, &kw, "MSID")?;
            let sec = parts_surface(ctx, ssid, sstyp, &loc, &kw, "SSID")?;
            let mut t = one(sec, surf, penalty);
            t.ists = 1;
            vec![spec(id, title, t)]
        }
        Form::SurfaceToSurface => {
            // Two-way node to surface: SSID's nodes on MSID's segments
            // (SFS on the nodes, SFM on the segments), and MSID's nodes on
            // SSID's segments (the factors swapped), as two interfaces, the
            // second with an id of the reader's own.
            let (s_nodes, s_surf) = side(ctx, ssid, sstyp, "SSID")?;
            let (m_nodes, m_surf) = side(ctx, msid, mstyp, "MSID")?;
            let back = DynaPenalty {
                sfs: sfm,
                sfm: sfs,
                ..penalty
            };
            let back_id = ctx.own_id();
            vec![
                spec(id, title.clone(), one(s_nodes, m_surf, penalty)),
                spec(
                    back_id,
                    format!("{title} (MSID on SSID)"),
                    one(m_nodes, s_surf, back),
                ),
            ]
        }
    };
    for s in specs {
        ctx.deck.interfaces.push(s);
        ctx.contacts.push(ctx.deck.interfaces.len() - 1);
    }
    Ok(())
}

/// Optional cards A (SOFT SOFSCL LCIDAB MAXPAR SBOPT DEPTH BSORT FRCFRQ)
/// and B (PENMAX THKOPT SHLTHK SNLOG ISYM I2D3D SLDTHK SLDSTF): SOFT 0, 1
/// and 2 are computed; the options that change their answer are refused.
/// (SOFT, SOFSCL, DEPTH).
fn optional_cards(cards: &mut Cards, ctx: &mut Ctx, kw: &str) -> InputResult<(i64, f64, i64)> {
    let std = cards.standard();
    let mut soft = (0, 0.1, 2);
    if let Some(a) = cards.next_opt(std.clone()) {
        soft.0 = a.int(0, "SOFT", 0)?;
        if !(0..=2).contains(&soft.0) {
            ctx.refuse(
                &a.loc(),
                kw,
                format!("SOFT {} (SOFT 0, 1 and 2 are computed)", soft.0),
            );
        }
        segment_options(&a, ctx, kw, soft.0, &mut soft.2)?;
        let s = a.real(1, "SOFSCL", 0.0)?;
        if s < 0.0 {
            return Err(a.err(
                "SOFSCL",
                format!("{s}: expected a scale factor >= 0 (0: 0.1)"),
            ));
        }
        if s > 0.0 {
            soft.1 = s;
        }
        if a.int(2, "LCIDAB", 0)? != 0 {
            ctx.refuse(&a.loc(), kw, "field LCIDAB");
        }
    }
    if let Some(b) = cards.next_opt(std) {
        let fields = [
            (0, "PENMAX"),
            (1, "THKOPT"),
            (2, "SHLTHK"),
            (6, "SLDTHK"),
            (7, "SLDSTF"),
        ];
        ctx.refuse_given(&b, kw, &fields, "", false)?;
    }
    if cards.remaining() > 0 {
        let c = cards.next_opt(cards.standard()).unwrap();
        ctx.refuse(&c.loc(), kw, "optional cards C and beyond");
    }
    Ok(soft)
}

/// Optional card A's SBOPT (0 → 2: planar segments), DEPTH (0 → 2: surface
/// penetration; 5: and edge-to-edge crossings) for SOFT 2, and FRCFRQ
/// (0, 1: forces every cycle) for any SOFT.
fn segment_options(
    a: &super::card::Card,
    ctx: &mut Ctx,
    kw: &str,
    soft: i64,
    depth: &mut i64,
) -> InputResult<()> {
    if a.int(7, "FRCFRQ", 0)? > 1 {
        ctx.refuse(&a.loc(), kw, "FRCFRQ > 1 (forces updated every cycle)");
    }
    if soft != 2 {
        return Ok(());
    }
    let sbopt = a.int(4, "SBOPT", 0)?;
    if !matches!(sbopt, 0 | 2) {
        ctx.refuse(
            &a.loc(),
            kw,
            format!("SBOPT {sbopt} (SBOPT 2, planar segments, is computed)"),
        );
    }
    *depth = match a.int(5, "DEPTH", 0)? {
        0 | 2 => 2,
        5 => 5,
        d => {
            ctx.refuse(
                &a.loc(),
                kw,
                format!("DEPTH {d} on SOFT 2 (2 surface, 5 surface and edge to edge are computed)"),
            );
            2
        }
    };
    Ok(())
}

/// The TYPE7 options of a SOFT = 0 contact: variable gap (half thicknesses),
/// LS-DYNA's stiffness, Coulomb FS, damping VDC % of critical, BT/DT.
fn type7(grnod: Id, surf: Id, fs: f64, vdc: f64, bt: f64, dt: f64, dyna: DynaPenalty) -> Type7 {
    Type7 {
        grnod_ids: grnod,
        surf_idm: surf,
        istf: 4,
        ithe: 0,
        igap: 1,
        ibag: 0,
        idel: 0,
        icurv: 0,
        iadm: 0,
        fscalegap: 1.0,
        gapmax: EP30,
        fpenmax: 0.0,
        itied: 0,
        ists: 0,
        stmin: 0.0,
        stmax: EP30,
        mesh_size_pct: 0.4,
        dtmin: 0.0,
        irem_gap: 1,
        irem_i2: 3,
        curv_nodes: None,
        stfac: 1.0,
        fric: fs,
        gapmin: 0.0,
        tstart: bt,
        tstop: if dt == 0.0 { EP30 } else { dt },
        ibc: [false; 3],
        inacti: 1000,
        viss: vdc / 100.0,
        visf: if fs != 0.0 { 1.0 } else { 0.0 },
        bumult: 0.2,
        ifric: 0,
        ifiltr: 0,
        xfreq: 0.0,
        iform: 1,
        sens_id: 0,
        fct_idf: 0,
        ascalef: 1.0,
        fric_id: 0,
        fric_coefs: None,
        adm: None,
        thermal: None,
        dyna: Some(dyna),
    }
}

/// Card 1's (SSID, SSTYP) and (MSID, MSTYP) of every *CONTACT, the ids
/// offset by an *INCLUDE_TRANSFORM as their set type says.
pub(super) type SetId = (Id, i64);
pub(super) fn set_ids(c1: &Card) -> InputResult<(SetId, SetId)> {
    let (sstyp, mstyp) = (c1.int(2, "SSTYP", 0)?, c1.int(3, "MSTYP", 0)?);
    let ssid = c1.offset_by_type(c1.id_opt(0, "SSID")?, contact_set_kind(sstyp));
    let msid = c1.offset_by_type(c1.id_opt(1, "MSID")?, contact_set_kind(mstyp));
    Ok(((ssid, sstyp), (msid, mstyp)))
}

/// The main surface a set names: type 0 (segment set), 1 (shell set), 2
/// (part set), 3 (part) or 5 (every part); shell and part sets and every
/// part are filled once the deck is read.
pub(super) fn parts_surface(
    ctx: &mut Ctx,
    sid: Id,
    styp: i64,
    loc: &Loc,
    kw: &str,
    field: &str,
) -> InputResult<Id> {
    if styp == 0 {
        // A *SET_SEGMENT: the surface of its id (checked once the deck is read).
        ctx.segment_sets_used
            .push((sid, loc.clone(), kw.to_string(), field.to_string()));
        return Ok(sid);
    }
    if styp == 1 {
        // A *SET_SHELL: its shells' faces, once the deck is read.
        return Ok(ctx.shell_set_surface(sid, loc, kw, field));
    }
    let parts: Vec<i64> = match styp {
        3 => vec![sid as i64],
        // Filled once the deck is read (`Ctx::resolve_part_sets`).
        2 | 5 => Vec::new(),
        _ => {
            ctx.refuse(
                loc,
                kw,
                format!("set type {styp} for {field} (0 segment set, 1 shell set, 2 part set, 3 part and 5 all are read)"),
            );
            Vec::new()
        }
    };
    let id = ctx.own_id();
    if styp == 5 {
        ctx.all_parts_surfaces.push(ctx.deck.surfaces.len());
    }
    if styp == 2 {
        let target = super::PartSetTarget::Surface(ctx.deck.surfaces.len());
        ctx.part_sets_used
            .push((sid, target, loc.clone(), kw.into(), field.into()));
    }
    ctx.deck.surfaces.push(SurfaceCard {
        id,
        title: format!("{kw} {field} {sid}"),
        def: SurfaceDef::Parts(parts),
        item_locs: vec![(0, loc.clone())],
        loc: loc.clone(),
    });
    Ok(id)
}

/// The secondary nodes of a nodes-to-surface contact: a node set (4), or
/// the nodes of a part (3) or part set (2).
pub(super) fn secondary_nodes(
    ctx: &mut Ctx,
    sid: Id,
    styp: i64,
    loc: &Loc,
    kw: &str,
    field: &str,
) -> InputResult<Id> {
    match styp {
        4 => Ok(sid),
        0 => {
            ctx.segment_sets_used
                .push((sid, loc.clone(), kw.to_string(), field.to_string()));
            Ok(ctx.own_group(
                NodeGroupKind::Surf,
                vec![sid as i64],
                format!("{kw} segment set {sid}"),
                loc,
            ))
        }
        1 => {
            let surf = ctx.shell_set_surface(sid, loc, kw, field);
            Ok(ctx.own_group(
                NodeGroupKind::Surf,
                vec![surf as i64],
                format!("{kw} shell set {sid}"),
                loc,
            ))
        }
        3 => Ok(ctx.own_group(
            NodeGroupKind::Part,
            vec![sid as i64],
            format!("{kw} part {sid}"),
            loc,
        )),
        2 => Ok(ctx.part_set_group(sid, format!("{kw} part set {sid}"), loc, kw, field)),
        _ => {
            ctx.refuse(
                loc,
                kw,
                format!("set type {styp} for {field} (0 segment set, 1 shell set, 2 part set, 3 part and 4 node set are read)"),
            );
            Ok(ctx.own_group(NodeGroupKind::Node, Vec::new(), kw.to_string(), loc))
        }
    }
}

/// After the last keyword: SSTYP 5 surfaces and NSID 0 rigid walls take
/// every part, and every
/// contact takes the deck's SLSFAC (a *CONTROL_CONTACT may come after it).
pub fn finish(ctx: &mut Ctx) {
    let all: Vec<i64> = ctx.deck.parts.iter().map(|p| p.id as i64).collect();
    for &i in &ctx.all_parts_surfaces {
        ctx.deck.surfaces[i].def = SurfaceDef::Parts(all.clone());
    }
    for &i in &ctx.all_parts_groups {
        ctx.deck.node_groups[i].items = all.clone();
    }
    for &i in &ctx.contacts {
        let t = match &mut ctx.deck.interfaces[i].kind {
            InterfaceKind::Type7(t) => Some(t),
            InterfaceKind::Type19(t) => Some(&mut t.nodes),
            _ => None,
        };
        if let Some(t) = t {
            if let Some(d) = &mut t.dyna {
                d.slsfac = ctx.slsfac;
            }
            if ctx.ignore_penetrations {
                // IGNORE 1/2: initial penetrations kept, the gap reduced
                // to them and following the node back out (Inacti 5).
                t.inacti = 5;
            }
        }
    }
    if let Some((rwpnal, loc)) = ctx.rwpnal.clone() {
        if rwpnal != 0.0 && !ctx.deck.rigid_walls.is_empty() {
            ctx.refuse(
                &loc,
                "*CONTROL_CONTACT",
                "field RWPNAL with a *RIGIDWALL (0, the constraint method, is computed)",
            );
        }
    }
}
