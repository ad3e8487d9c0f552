//! Contact interfaces: /INTER/TYPE2 (tied), /INTER/TYPE3 (surface to surface,
//! symmetric), /INTER/TYPE5 (node to surface), /INTER/TYPE7 (general node to
//! surface penalty contact) and /INTER/TYPE11 (edge to edge).
//!
//! Layouts follow the Starter's reader definitions (`inter_typeN.cfg`, newest
//! format) and the reference guide; columns are 1-based and inclusive. A blank
//! field and an explicit 0 are the same thing, and unlike /PART or /PROP the
//! values here are stored *after* default resolution (`0 → default`), as the
//! Starter listing (`_0000.out`) prints them. `/DEFAULT/INTER/TYPEn` is not
//! supported: a 0 always takes the built-in default.
//!
//! The "1000" convention: several flags (Istf, Igap, Ibag, Idel, Inacti, Ignore,
//! Idel2) use 0 for "take /DEFAULT/INTER or the built-in default", and the
//! built-in default is 1000, meaning the historic/"off" behaviour. Those flags
//! are stored as 1000, as the listing prints them.

use super::fields::{Card, Cards};
use super::source::Block;
use super::{header_id, header_id_opt, Deck};
use crate::model::contact::*;
use crate::model::{Id, InputResult, Warning};

// ---------------------------------------------------------------------------
// TYPE2
// ---------------------------------------------------------------------------

const SPOTFLAGS: &[i64] = &[0, 1, 2, 3, 4, 5, 10, 11, 12, 20, 21, 22, 25, 26, 27, 28, 30];

fn read_type2(cards: &mut Cards) -> InputResult<Type2> {
    let c1 = cards.next(
        "the card with grnd_IDs, surf_IDm, Ignore, Spotflag, Level, Isearch, Idel2, dsearch",
    )?;
    let grnod_ids = c1.id(1, "grnd_IDs")?;
    let surf_idm = c1.id(11, "surf_IDm")?;
    let ignore = flag(&c1, 21, "Ignore", &[0, 1, 2, 3, 1000], 1000)?;
    let spotflag = flag(&c1, 31, "Spotflag", SPOTFLAGS, 5)?;
    let mut level = c1.int(41, "Level", 0)?;
    if level < 0 {
        return Err(c1.err(
            "Level",
            format!("{level} in columns 41-50: expected a hierarchy level >= 0"),
        ));
    }
    let penalty_flag = (25..=28).contains(&spotflag);
    if penalty_flag {
        level = 0;
    }
    let isearch = flag(&c1, 51, "Isearch", &[0, 1, 2], 2)?;
    let mut idel2 = flag(&c1, 61, "Idel2", &[0, 1, 2, 1000], 1000)?;
    if !matches!(spotflag, 1 | 5 | 25..=28) {
        idel2 = 1000;
    }
    let surf_ids = c1.id_opt(71, "surf_IDs")?;
    let dsearch = real_ge0(&c1, 81, "dsearch", 0.0, "the search distance")?;

    let rupture = if matches!(spotflag, 20..=22) {
        let r1 = cards.next(
            "the rupture card with Rupt, Ifiltr, fct_IDsr, fct_IDsn, fct_IDst (Spotflag 20-22)",
        )?;
        let r2 = cards.next("the rupture card with Fscalestress, Fscalestr_rate, Fscaledist, Alpha, Area (Spotflag 20-22)")?;
        let ifiltr = flag(&r1, 11, "Ifiltr", &[0, 1], 0)?;
        let mut alpha = r2.real(61, "Alpha", 0.0)?;
        if ifiltr == 1 {
            if alpha == 0.0 {
                alpha = 1.0;
            }
            alpha = alpha.clamp(0.0, 1.0);
        }
        Some(Type2Rupture {
            rupt: flag(&r1, 1, "Rupt", &[0, 1, 2], 2)?,
            ifiltr,
            fct_idsr: r1.id_opt(21, "fct_IDsr")?,
            fct_idsn: r1.id(31, "fct_IDsn")?,
            fct_idst: r1.id(41, "fct_IDst")?,
            isym: flag(&r1, 51, "Isym", &[0, 1], 0)?,
            max_n_dist: real_ge0(&r1, 61, "Max_N_Dist", EP20, "the maximum normal distance")?,
            max_t_dist: real_ge0(
                &r1,
                81,
                "Max_T_Dist",
                EP20,
                "the maximum tangential distance",
            )?,
            fscale_stress: real_ge0(&r2, 1, "Fscalestress", 1.0, "a scale factor")?,
            fscale_str_rate: real_ge0(&r2, 21, "Fscalestr_rate", 1.0, "a scale factor")?,
            fscale_dist: real_ge0(&r2, 41, "Fscaledist", 1.0, "a scale factor")?,
            alpha,
            area: real_ge0(&r2, 81, "Area", 0.0, "the area")?,
        })
    } else {
        None
    };

    let penalty = if penalty_flag {
        let p = cards.next("the penalty card with Stfac, Visc, Istf (Spotflag 25-28)")?;
        Some(Type2Penalty {
            stfac: real_ge0(&p, 1, "Stfac", 1.0, "the stiffness factor")?,
            visc: real_ge0(&p, 21, "Visc", 0.05, "the critical damping")?,
            istf: flag(&p, 61, "Istf", &[0, 1, 2, 3, 4, 5], 2)?,
        })
    } else {
        None
    };

    let thermal = match cards.next_opt() {
        Some(t) if !t.is_blank() => {
            let has_iproj = !matches!(spotflag, 1 | 28 | 30);
            Some(Type2Thermal {
                ithe: flag(&t, 1, "Ithe", &[0, 1], 0)?,
                kthe: real_ge0(&t, 11, "Kthe", 0.0, "the heat exchange coefficient")?,
                iproj: if has_iproj {
                    flag(&t, 91, "Iproj", &[0, 1, 2], 1)?
                } else {
                    1
                },
            })
        }
        _ => None,
    };

    Ok(Type2 {
        grnod_ids,
        surf_idm,
        ignore,
        spotflag,
        level,
        isearch,
        idel2,
        surf_ids,
        dsearch,
        rupture,
        penalty,
        thermal,
        project: false,
    })
}

// ---------------------------------------------------------------------------
// TYPE3
// ---------------------------------------------------------------------------

fn read_type3(cards: &mut Cards) -> InputResult<Type3> {
    let c1 = cards.next("the card with surf_ID1, surf_ID2, Idel")?;
    let c2 = cards.next("the card with Stfac, Fric, Gap, Tstart, Tstop")?;
    let c3 = cards.next("the card with IBC, IRS, IRM")?;
    let c4 = cards.next_opt();
    let (tstart, tstop) = times(&c2)?;
    Ok(Type3 {
        surf_id1: c1.id(1, "surf_ID1")?,
        surf_id2: c1.id(11, "surf_ID2")?,
        idel: flag(&c1, 71, "Idel", &[-2, -1, 0, 1, 2], 0)?,
        stfac: real_ge0(&c2, 1, "Stfac", 0.2, "the stiffness factor")?,
        fric: real_ge0(&c2, 21, "Fric", 0.0, "the friction coefficient")?,
        gap: real_ge0(&c2, 41, "Gap", 0.0, "the gap")?,
        tstart,
        tstop,
        ibc: read_ibc(&c3)?,
        irs: flag(&c3, 11, "IRS", &[0, 1, 2], 0)?,
        irm: flag(&c3, 21, "IRM", &[0, 1, 2], 0)?,
        ptlim: match c4 {
            Some(c) => real_ge0(&c, 61, "Ptlim", EP30, "the tangential pressure limit")?,
            None => EP30,
        },
    })
}

// ---------------------------------------------------------------------------
// TYPE5
// ---------------------------------------------------------------------------

fn read_type5(cards: &mut Cards) -> InputResult<Type5> {
    let c1 = cards.next("the card with grnd_IDs, surf_IDm, Ibag, Idel")?;
    let c2 = cards.next("the card with Stfac, Fric, Gap, Tstart, Tstop")?;
    let c3 = cards.next("the card with IBC, IRM, Inacti")?;
    // Card 4 is absent from the oldest formats: then every field takes its default.
    let c4 = cards.next_opt();
    let (tstart, tstop) = times(&c2)?;
    let (ifric, ifiltr, xfreq, sens_id, ptlim) = match &c4 {
        Some(c) => {
            let ifric = flag(c, 1, "Ifric", &[0, 1, 2, 3], 0)?;
            let (ifiltr, xfreq) = filter(c)?;
            (
                ifric,
                ifiltr,
                xfreq,
                c.id_opt(51, "sens_ID")?,
                real_ge0(c, 61, "Ptlim", EP30, "the tangential pressure limit")?,
            )
        }
        None => (0, 0, 0.0, 0, EP30),
    };
    let fric_coefs = friction_coefs(cards, ifric)?;
    Ok(Type5 {
        grnod_ids: c1.id(1, "grnd_IDs")?,
        surf_idm: c1.id(11, "surf_IDm")?,
        ibag: flag(&c1, 61, "Ibag", &[0, 1], 0)?,
        idel: flag(&c1, 71, "Idel", &[-2, -1, 0, 1, 2], 0)?,
        stfac: real_ge0(&c2, 1, "Stfac", 0.2, "the stiffness factor")?,
        fric: real_ge0(&c2, 21, "Fric", 0.0, "the friction coefficient")?,
        gap: real_ge0(&c2, 41, "Gap", 0.0, "the gap")?,
        tstart,
        tstop,
        ibc: read_ibc(&c3)?,
        irm: flag(&c3, 21, "IRM", &[0, 1, 2], 0)?,
        inacti: flag(&c3, 31, "Inacti", &[0, 3, 4], 0)?,
        ifric,
        ifiltr,
        xfreq,
        sens_id,
        ptlim,
        fric_coefs,
    })
}

// ---------------------------------------------------------------------------
// TYPE7
// ---------------------------------------------------------------------------

fn read_type7(cards: &mut Cards) -> InputResult<Type7> {
    read_type7_card(cards, false)
}

/// The TYPE7 card, or (`type19`) the TYPE7 options of a /INTER/TYPE19 card,
/// which has the same layout but for: surf_IDs, surf_IDm (either may be 0),
/// Igap 4, Iedge in columns 51-60 of card 1, Edge_scale_gap where TYPE7
/// has Fpenmax (card 2, no Itied, Ists), no Iadm, fct_IDF or AscaleF.
fn read_type7_card(cards: &mut Cards, type19: bool) -> InputResult<Type7> {
    let c1 = cards
        .next("the card with grnd_IDs, surf_IDm, Istf, Ithe, Igap, Ibag, Idel, Icurv, Iadm")?;
    let grnod_ids = c1.id_opt(1, "grnd_IDs")?;
    let surf_idm = if type19 {
        c1.id_opt(11, "surf_IDm")?
    } else {
        c1.id(11, "surf_IDm")?
    };
    let istf = flag(&c1, 21, "Istf", &[0, 1, 2, 3, 4, 5, 1000], 1000)?;
    let ithe = flag(&c1, 31, "Ithe", &[0, 1], 0)?;
    let igap = if type19 {
        // TYPE19 Igap 4: variable gap (2) for the nodes, constant for the edges.
        match flag(&c1, 41, "Igap", &[0, 1, 2, 3, 4, 1000], 1000)? {
            4 => 2,
            g => g,
        }
    } else {
        flag(&c1, 41, "Igap", &[0, 1, 2, 3, 1000], 1000)?
    };
    let ibag = flag(&c1, 61, "Ibag", &[0, 1, 2, 1000], 1000)?;
    let idel = flag(&c1, 71, "Idel", &[-2, -1, 0, 1, 2, 1000], 1000)?;
    let icurv = flag(&c1, 81, "Icurv", &[0, 1, 2, 3], 0)?;
    let iadm = if type19 {
        0
    } else {
        flag(&c1, 91, "Iadm", &[0, 1, 2], 0)?
    };
    if iadm != 0 && icurv != 0 {
        return Err(c1.err(
            "Iadm",
            format!("Iadm = {iadm} with Icurv = {icurv}: adaptive meshing (Iadm) cannot be combined with a curvature gap (Icurv); set one of them to 0"),
        ));
    }

    let c2 = cards.next("the card with Fscalegap, Gapmax, Fpenmax, Itied")?;
    let fscalegap = real_ge0(&c2, 1, "Fscalegap", 1.0, "the gap scale factor")?;
    let gapmax = real_ge0(&c2, 21, "Gapmax", EP30, "the maximum gap")?;
    let (fpenmax, itied, ists) = if type19 {
        (0.0, 0, 0)
    } else {
        (
            real_ge0(&c2, 41, "Fpenmax", 0.0, "the maximum penetration fraction")?,
            flag(&c2, 81, "Itied", &[0, 1, 2], 0)?,
            flag(&c2, 91, "Ists", &[0, 1, 2], 0)?,
        )
    };

    let c3 = cards.next("the card with Stmin, Stmax, %mesh_size, dtmin, Irem_gap, Irem_i2")?;
    let stmin = real_ge0(&c3, 1, "Stmin", 0.0, "the minimum stiffness")?;
    let stmax = real_ge0(&c3, 21, "Stmax", EP30, "the maximum stiffness")?;
    if stmax < stmin {
        return Err(c3.err(
            "Stmax",
            format!("{stmax} in columns 21-40 is below Stmin = {stmin}: expected Stmax >= Stmin"),
        ));
    }
    let mesh_size_pct = real_ge0(&c3, 41, "%mesh_size", 0.4, "the mesh size fraction")?;
    let dtmin = real_ge0(&c3, 61, "dtmin", 0.0, "the minimum time step")?;
    let irem_gap = flag(&c3, 81, "Irem_gap", &[0, 1, 2], 1)?;
    let irem_i2 = flag(&c3, 91, "Irem_i2", &[0, 1, 3], 3)?;

    let curv_nodes = if icurv == 1 || icurv == 2 {
        let n = cards.next("the card with node_ID1, node_ID2 (Icurv = 1 or 2)")?;
        let n1 = n.id(1, "node_ID1")?;
        let n2 = if icurv == 2 {
            n.id(11, "node_ID2")?
        } else {
            n.id_opt(11, "node_ID2")?
        };
        Some([n1, n2])
    } else {
        None
    };

    let c4 = cards.next("the card with Stfac, Fric, Gapmin, Tstart, Tstop")?;
    let stfac = real_ge0(&c4, 1, "Stfac", 1.0, "the stiffness factor")?;
    let fric_in = real_ge0(&c4, 21, "Fric", 0.0, "the friction coefficient")?;
    let gapmin = real_ge0(&c4, 41, "Gapmin", 0.0, "the minimum gap")?;
    let (tstart, tstop) = times(&c4)?;

    let c5 = cards.next("the card with IBC, Inacti, VISs, VISF, Bumult")?;
    let ibc = read_ibc(&c5)?;
    let inacti = flag(&c5, 31, "Inacti", &[0, 1, 2, 3, 5, 6, 1000], 1000)?;
    let viss = real_ge0(&c5, 41, "VISs", 0.05, "the critical damping")?;
    let visf = real_ge0(&c5, 61, "VISF", 1.0, "the friction critical damping")?;
    let bumult = real_ge0(&c5, 81, "Bumult", 0.2, "the sorting factor")?;

    let c6 = cards
        .next("the card with Ifric, Ifiltr, Xfreq, Iform, sens_ID, fct_IDF, AscaleF, fric_ID")?;
    let ifric = flag(&c6, 1, "Ifric", &[0, 1, 2, 3, 4], 0)?;
    let (ifiltr, xfreq) = filter(&c6)?;
    let iform = flag(&c6, 41, "Iform", &[0, 1, 2], 1)?;
    let sens_id = c6.id_opt(51, "sens_ID")?;
    let (fct_idf, ascalef) = if type19 {
        (0, 1.0)
    } else {
        (
            c6.id_opt(61, "fct_IDF")?,
            real_ge0(&c6, 71, "AscaleF", 1.0, "the abscissa scale factor")?,
        )
    };
    let fric_id = c6.id_opt(91, "fric_ID")?;
    let fric = if fric_in == 0.0 && fct_idf != 0 {
        1.0
    } else {
        fric_in
    };

    let fric_coefs = friction_coefs(cards, ifric)?;

    let adm = if iadm == 2 {
        let a = cards.next("the card with NRadm, Padm, Angladm (Iadm = 2)")?;
        let nradm = a.int(1, "NRadm", 0)?;
        if nradm < 0 {
            return Err(a.err(
                "NRadm",
                format!("{nradm} in columns 1-10: expected a number of elements >= 0 (0 = 3)"),
            ));
        }
        Some(Type7Adm {
            nradm: if nradm == 0 { 3 } else { nradm },
            padm: real_ge0(&a, 11, "Padm", 1.0, "the penetration criterion")?,
            angladm: real_ge0(&a, 31, "Angladm", 0.0, "the angle criterion")?,
        })
    } else {
        None
    };

    let thermal = read_type7_thermal(cards, ithe)?;

    Ok(Type7 {
        grnod_ids,
        surf_idm,
        istf,
        ithe,
        igap,
        ibag,
        idel,
        icurv,
        iadm,
        fscalegap,
        gapmax,
        fpenmax,
        itied,
        ists,
        stmin,
        stmax,
        mesh_size_pct,
        dtmin,
        irem_gap,
        irem_i2,
        curv_nodes,
        stfac,
        fric,
        gapmin,
        tstart,
        tstop,
        ibc,
        inacti,
        viss,
        visf,
        bumult,
        ifric,
        ifiltr,
        xfreq,
        iform,
        sens_id,
        fct_idf,
        ascalef,
        fric_id,
        fric_coefs,
        adm,
        thermal,
        dyna: None,
    })
}

/// The two thermal cards of /INTER/TYPE7 (Ithe = 1): Kthe, fct_IDK, Tint,
/// Ithe_form, AscaleK; Frad, Drad, Fheats, Fheatm.
fn read_type7_thermal(cards: &mut Cards, ithe: i64) -> InputResult<Option<Type7Thermal>> {
    Ok(if ithe == 1 {
        let t1 = cards
            .next("the thermal card with Kthe, fct_IDK, Tint, Ithe_form, AscaleK (Ithe = 1)")?;
        let t2 = cards.next("the thermal card with Frad, Drad, Fheats, Fheatm (Ithe = 1)")?;
        let fct_idk = t1.id_opt(21, "fct_IDK")?;
        let kthe = real_ge0(&t1, 1, "Kthe", 0.0, "the heat exchange coefficient")?;
        Some(Type7Thermal {
            kthe: if kthe == 0.0 && fct_idk != 0 {
                1.0
            } else {
                kthe
            },
            fct_idk,
            tint: t1.real(41, "Tint", 0.0)?,
            ithe_form: flag(&t1, 61, "Ithe_form", &[0, 1], 0)?,
            ascalek: real_ge0(&t1, 71, "AscaleK", 1.0, "the abscissa scale factor")?,
            frad: real_ge0(&t2, 1, "Frad", 0.0, "the radiation factor")?,
            drad: real_ge0(&t2, 21, "Drad", 0.0, "the radiation distance")?,
            fheats: real_ge0(&t2, 41, "Fheats", 0.0, "the frictional heating factor")?,
            fheatm: real_ge0(&t2, 61, "Fheatm", 0.0, "the frictional heating factor")?,
        })
    } else {
        None
    })
}

// ---------------------------------------------------------------------------
// TYPE11
// ---------------------------------------------------------------------------

/// Card 2 of the TYPE11 layouts from 2017: Stmin, Stmax, %mesh_size,
/// dtmin, Iform, sens_ID.
fn type11_card2(cards: &mut Cards) -> InputResult<(f64, f64, f64, f64, i64, crate::model::Id)> {
    let c2 = cards.next("the card with Stmin, Stmax, %mesh_size, dtmin, Iform, sens_ID")?;
    let stmin = real_ge0(&c2, 1, "Stmin", 0.0, "the minimum stiffness")?;
    let stmax = real_ge0(&c2, 21, "Stmax", EP30, "the maximum stiffness")?;
    if stmax < stmin {
        return Err(c2.err(
            "Stmax",
            format!("{stmax} in columns 21-40 is below Stmin = {stmin}: expected Stmax >= Stmin"),
        ));
    }
    let mesh_size_pct = real_ge0(&c2, 41, "%mesh_size", 0.4, "the mesh size fraction")?;
    let dtmin = real_ge0(&c2, 61, "dtmin", 0.0, "the minimum time step")?;
    let iform = flag(&c2, 81, "Iform", &[0, 1, 2], 1)?;
    let sens_id = c2.id_opt(91, "sens_ID")?;
    Ok((stmin, stmax, mesh_size_pct, dtmin, iform, sens_id))
}

/// /INTER/TYPE11. `old_layout`: a deck of version below 110 (/BEGIN
/// invers), whose TYPE11 has three cards (line_IDs line_IDm Istf _ Igap
/// Multimp _ Idel; Stfac Fric Gap Tstart Tstop; IBC Inacti VISs VISF
/// Bumult): no Stmin card, no Ithe nor Irem_gap (their columns are blank
/// or Multimp, ignored).
fn read_type11(cards: &mut Cards, old_layout: bool) -> InputResult<Type11> {
    let c1 = cards.next("the card with line_IDs, line_IDm, Istf, Ithe, Igap, Irem_gap, Idel")?;
    let line_ids = c1.id(1, "line_IDs")?;
    let line_idm = c1.id_opt(11, "line_IDm")?;
    let mut istf = flag(&c1, 21, "Istf", &[0, 1, 2, 3, 4, 5], 5)?;
    let ithe = flag(&c1, 31, "Ithe", &[0, 1, 2], 0)?;
    let igap = c1.int(41, "Igap", 0)?;
    if igap == 2 {
        return Err(c1.err(
            "Igap",
            "2 in columns 41-50: Igap = 2 is not available for TYPE11; expected 0, 1, 3 or 1000",
        ));
    }
    let igap = flag(&c1, 41, "Igap", &[0, 1, 3, 1000], 1000)?;
    let mut irem_gap = flag(&c1, 61, "Irem_gap", &[0, 1, 2], 1)?;
    if igap == 3 {
        irem_gap = 1;
    }
    let idel = flag(&c1, 71, "Idel", &[-2, -1, 0, 1, 2, 1000], 1000)?;

    let (stmin, stmax, mesh_size_pct, dtmin, iform, sens_id) = if old_layout {
        (0.0, EP30, 0.4, 0.0, 1, 0)
    } else {
        type11_card2(cards)?
    };

    let c3 = cards.next("the card with Stfac, Fric, Gapmin, Tstart, Tstop")?;
    // A negative Stfac is the old way of giving the stiffness itself (Istf = 1).
    let mut stfac = c3.real(1, "Stfac", 0.0)?;
    if stfac < 0.0 {
        istf = 1;
        stfac = -stfac;
    } else if stfac == 0.0 {
        stfac = 1.0;
    }
    let fric = real_ge0(&c3, 21, "Fric", 0.0, "the friction coefficient")?;
    let gapmin = real_ge0(&c3, 41, "Gapmin", 0.0, "the minimum gap")?;
    let (tstart, tstop) = times(&c3)?;

    let c4 = cards.next("the card with IBC, Inacti, VISs, VISF, Bumult")?;
    let ibc = read_ibc(&c4)?;
    let inacti = flag(&c4, 31, "Inacti", &[0, 1, 2, 3, 5, 6, 1000], 1000)?;
    let viss = real_ge0(&c4, 41, "VISs", 0.05, "the critical damping")?;
    let visf = real_ge0(&c4, 61, "VISF", 1.0, "the friction critical damping")?;
    let bumult = real_ge0(&c4, 81, "Bumult", 0.2, "the sorting factor")?;

    // Card 5 (fric_ID) exists from format 2018; older decks end after card 4,
    // which is harmless unless the thermal cards must follow it.
    let c5 = if ithe > 0 {
        Some(cards.next("the card with fric_ID (columns 91-100)")?)
    } else {
        cards.next_opt()
    };
    let fric_id = match &c5 {
        Some(c) => c.id_opt(91, "fric_ID")?,
        None => 0,
    };

    let thermal = if ithe > 0 {
        let t1 = cards
            .next("the thermal card with Kthe, fct_IDK, AscaleK, Tint, Ithe_form (Ithe > 0)")?;
        let t2 = cards.next("the thermal card with Frad, Drad (Ithe > 0)")?;
        let fct_idk = t1.id_opt(21, "fct_IDK")?;
        let kthe = real_ge0(&t1, 1, "Kthe", 0.0, "the heat exchange coefficient")?;
        Some(Type11Thermal {
            kthe: if kthe == 0.0 && fct_idk != 0 {
                1.0
            } else {
                kthe
            },
            fct_idk,
            ascalek: real_ge0(&t1, 31, "AscaleK", 1.0, "the abscissa scale factor")?,
            tint: t1.real(51, "Tint", 0.0)?,
            ithe_form: flag(&t1, 71, "Ithe_form", &[0, 1], 0)?,
            frad: real_ge0(&t2, 1, "Frad", 0.0, "the radiation factor")?,
            drad: real_ge0(&t2, 21, "Drad", 0.0, "the radiation distance")?,
        })
    } else {
        None
    };

    Ok(Type11 {
        line_ids,
        line_idm,
        istf,
        ithe,
        igap,
        irem_gap,
        idel,
        stmin,
        stmax,
        mesh_size_pct,
        dtmin,
        iform,
        sens_id,
        stfac,
        fric,
        gapmin,
        tstart,
        tstop,
        ibc,
        inacti,
        viss,
        visf,
        bumult,
        fric_id,
        thermal,
        dyna: None,
        penalty25: None,
    })
}

// ---------------------------------------------------------------------------
// Dispatch and shared field readers
// ---------------------------------------------------------------------------

// ---------------------------------------------------------------------------
// TYPE19
// ---------------------------------------------------------------------------

/// /INTER/TYPE19 (format 2021-2024): the TYPE7 options, plus Iedge and
/// Edge_scale_gap for the edge-to-edge part.
fn read_type19(cards: &mut Cards) -> InputResult<Type19> {
    let mut peek = cards.clone();
    let c1 =
        peek.next("the card with surf_IDs, surf_IDm, Istf, Ithe, Igap, Iedge, Ibag, Idel, Icurv")?;
    let c2 = peek.next("the card with Fscalegap, Gapmax, Edge_scale_gap")?;
    let surf_ids = c1.id_opt(1, "surf_IDs")?;
    let surf_idm = c1.id_opt(11, "surf_IDm")?;
    if surf_ids == 0 && surf_idm == 0 {
        return Err(c1.err(
            "surf_IDs",
            "surf_IDs and surf_IDm are both 0: expected at least one surface",
        ));
    }
    let igap = flag(&c1, 41, "Igap", &[0, 1, 2, 3, 4, 1000], 1000)?;
    let iedge = flag(&c1, 51, "Iedge", &[0, 1, 2], 2)?;
    let edge_scale_gap = real_ge0(&c2, 41, "Edge_scale_gap", 0.0, "the edge gap scale factor")?;
    let mut nodes = read_type7_card(cards, true)?;
    nodes.irem_gap = if igap == 4 { 2 } else { nodes.irem_gap };
    Ok(Type19 {
        surf_ids,
        surf_idm,
        igap,
        iedge,
        edge_scale_gap,
        nodes,
    })
}

// ---------------------------------------------------------------------------
// TYPE6
// ---------------------------------------------------------------------------

/// /INTER/TYPE6 (format 2017 and later; cards 5 and 6 may be absent), with
/// the Starter's rules: Iform > 0 without fct_IDul becomes 2, then Iform > 0
/// with Stiff = 0 becomes 0; Icor is 0 with Iform = 0; Stiff 0 → 1e30.
fn read_type6(cards: &mut Cards) -> InputResult<Type6> {
    let c1 = cards.next("the card with surf_ID1, surf_ID2")?;
    let c2 = cards.next("the card with Sfric, Fric, Gap, Tstart, Tstop")?;
    let c3 = cards.next("the card with IRS, IRm, Inacti, fct_IDff, fct_IDfv, Ascalef, Ascalev")?;
    let c4 = cards.next("the card with fct_IDld, Iform, Ascalex, FscaleId, Icor")?;
    let c5 = cards.next_opt();
    let c6 = cards.next_opt();
    let (tstart, tstop) = times(&c2)?;
    let fct_id_ld = c4.id_opt(1, "fct_IDld")?;
    if fct_id_ld == 0 {
        return Err(c4.err(
            "fct_IDld",
            "0 in columns 1-10: expected the id of the loading force vs penetration /FUNCT (required)",
        ));
    }
    let (fct_id_ul, stiff_raw, fscale_ul) = match &c5 {
        Some(c) => (
            c.id_opt(1, "fct_IDul")?,
            real_ge0(c, 21, "Stiff", 0.0, "the transition stiffness")?,
            real_ge0(c, 41, "Fscaleul", 1.0, "the unloading ordinate scale")?,
        ),
        None => (0, 0.0, 1.0),
    };
    let (visc, fct_id_dv, fct_id_df, fscalev) = match &c6 {
        Some(c) => (
            real_ge0(c, 1, "Visc", 0.0, "the damping coefficient")?,
            c.id_opt(21, "fct_IDdv")?,
            c.id_opt(31, "fct_IDdf")?,
            real_ge0(c, 41, "Fscalev", 1.0, "the damping ordinate scale")?,
        ),
        None => (0.0, 0, 0, 1.0),
    };
    let mut iform = flag(&c4, 11, "Iform", &[0, 1, 2], 0)?;
    if iform > 0 && fct_id_ul == 0 {
        iform = 2;
    }
    if iform > 0 && stiff_raw == 0.0 {
        iform = 0;
    }
    let icor = flag(&c4, 61, "Icor", &[0, 1], 0)?;
    Ok(Type6 {
        surf_id1: c1.id(1, "surf_ID1")?,
        surf_id2: c1.id(11, "surf_ID2")?,
        sfric: real_ge0(&c2, 1, "Sfric", 0.0, "the static friction force")?,
        fric: real_ge0(&c2, 21, "Fric", 0.0, "the friction coefficient")?,
        gap: real_ge0(&c2, 41, "Gap", 0.0, "the gap")?,
        tstart,
        tstop,
        irs: flag(&c3, 11, "IRS", &[0, 1, 2], 0)?,
        irm: flag(&c3, 21, "IRm", &[0, 1, 2], 0)?,
        inacti: flag(&c3, 31, "Inacti", &[0, 5], 0)?,
        fct_id_ff: c3.id_opt(41, "fct_IDff")?,
        fct_id_fv: c3.id_opt(51, "fct_IDfv")?,
        ascalef: real_ge0(&c3, 61, "Ascalef", 1.0, "the abscissa scale")?,
        ascalev: real_ge0(&c3, 81, "Ascalev", 1.0, "the abscissa scale")?,
        fct_id_ld,
        iform,
        ascalex: real_ge0(&c4, 21, "Ascalex", 1.0, "the penetration scale")?,
        fscale_ld: real_ge0(&c4, 41, "FscaleId", 1.0, "the loading ordinate scale")?,
        icor: if iform == 0 { 0 } else { icor },
        fct_id_ul,
        stiff: if stiff_raw == 0.0 { EP30 } else { stiff_raw },
        fscale_ul,
        visc,
        fct_id_dv,
        fct_id_df,
        fscalev,
    })
}

// ---------------------------------------------------------------------------
// TYPE14
// ---------------------------------------------------------------------------

fn read_type14(cards: &mut Cards) -> InputResult<Type14> {
    let c1 =
        cards.next("the card with grnd_IDs, surf_IDm, fct_IDld, fct_IDf, fct_IDd1, fct_IDd2")?;
    let c2 = cards.next("the card with Stif, Fric, Visc, Gap")?;
    Ok(Type14 {
        grnd_ids: c1.id(1, "grnd_IDs")?,
        surf_idm: c1.id(11, "surf_IDm")?,
        fct_id_ld: c1.id_opt(21, "fct_IDld")?,
        fct_id_f: c1.id_opt(31, "fct_IDf")?,
        fct_id_d1: c1.id_opt(41, "fct_IDd1")?,
        fct_id_d2: c1.id_opt(51, "fct_IDd2")?,
        stif: real_ge0(&c2, 1, "Stif", 0.0, "the stiffness")?,
        fric: real_ge0(&c2, 21, "Fric", 0.0, "the friction coefficient")?,
        visc: real_ge0(&c2, 41, "Visc", 0.0, "the viscosity")?,
        gap: real_ge0(&c2, 61, "Gap", 0.0, "the gap")?,
    })
}

// ---------------------------------------------------------------------------
// TYPE15
// ---------------------------------------------------------------------------

/// /INTER/TYPE15: Stif and Fric have no default (reference guide): a blank
/// Stif is an error, a blank Fric no friction.
fn read_type15(cards: &mut Cards) -> InputResult<Type15> {
    let c1 = cards.next("the card with surf_IDs, surf_IDm")?;
    let c2 = cards.next("the card with Stif, Fric")?;
    let stif = real_ge0(&c2, 1, "Stif", 0.0, "the stiffness")?;
    if stif <= 0.0 {
        return Err(c2.err(
            "Stif",
            "blank or 0 in columns 1-20: expected the stiffness > 0 (it has no default)",
        ));
    }
    Ok(Type15 {
        surf_ids: c1.id(1, "surf_IDs")?,
        surf_idm: c1.id(11, "surf_IDm")?,
        stif,
        fric: real_ge0(&c2, 21, "Fric", 0.0, "the friction coefficient")?,
    })
}

// ---------------------------------------------------------------------------
// TYPE25
// ---------------------------------------------------------------------------

/// /INTER/TYPE25 (formats 2021-2022; 2021 has no Tpressfit, read as 0).
fn read_type25(cards: &mut Cards) -> InputResult<Type25> {
    let c1 =
        cards.next("the card with surf_ID1, surf_ID2, Istf, Ithe, Igap, Irem_i2, Idel, Iedge")?;
    let surf_id1 = c1.id_opt(1, "surf_ID1")?;
    let surf_id2 = c1.id_opt(11, "surf_ID2")?;
    let istf = flag(&c1, 21, "Istf", &[0, 2, 3, 4, 5, 1000], 1000)?;
    let ithe = flag(&c1, 31, "Ithe", &[0, 1], 0)?;
    let igap = flag(&c1, 41, "Igap", &[0, 1, 2, 3, 5], 1)?;
    let irem_i2 = flag(&c1, 51, "Irem_i2", &[0, 1, 3], 1)?;
    let idel = flag(&c1, 71, "Idel", &[-2, -1, 0, 1, 2, 1000], 1000)?;
    let iedge = flag(&c1, 81, "Iedge", &[0, 1, 11, 13, 22, 1000], 1000)?;
    let c2 = cards.next("the card with grnd_IDs, Gap_scale, %mesh_size, Gap_max_s, Gap_max_m")?;
    let grnd_ids = c2.id_opt(1, "grnd_IDs")?;
    penalty_sides(&c1, surf_id1, surf_id2, grnd_ids)?;
    let c3 = cards.next("the card with Stmin, Stmax, Igap0, Ishape, Edge_angle")?;
    let (stmin, stmax) = stiffness_bounds(&c3)?;
    let c4 = cards.next("the card with Stfac, Fric, Tpressfit, Tstart, Tstop")?;
    let (tstart, tstop) = times(&c4)?;
    let c5 = cards.next("the card with IBC, IVIS2, Inacti, VISs, Ithick, Pmax")?;
    let ivis2 = flag(&c5, 21, "IVIS2", &[-1, 0, 1, 2, 3, 4, 5, 6], 1)?;
    let inacti = penalty_inacti(&c5)?;
    let c6 = cards.next("the card with Ifric, Ifiltr, Xfreq, sens_ID, fric_ID")?;
    let ifric = flag(&c6, 1, "Ifric", &[0, 1, 2, 3, 4], 0)?;
    let (ifiltr, xfreq) = filter(&c6)?;
    Ok(Type25 {
        surf_id1,
        surf_id2,
        istf,
        ithe,
        igap,
        irem_i2,
        idel,
        iedge,
        grnd_ids,
        gap_scale: real_ge0(&c2, 21, "Gap_scale", 1.0, "the gap scale factor")?,
        mesh_size_pct: real_ge0(&c2, 41, "%mesh_size", 0.4, "the mesh size fraction")?,
        gap_max_s: real_ge0(&c2, 61, "Gap_max_s", EP30, "the maximum secondary gap")?,
        gap_max_m: real_ge0(&c2, 81, "Gap_max_m", EP30, "the maximum main gap")?,
        stmin,
        stmax,
        igap0: flag(&c3, 41, "Igap0", &[0, 1, 1000], 1000)?,
        ishape: flag(&c3, 51, "Ishape", &[0, 1, 2], 1)?,
        edge_angle: real_ge0(&c3, 61, "Edge_angle", 135.0, "the edge angle")?,
        stfac: real_ge0(&c4, 1, "Stfac", 1.0, "the stiffness factor")?,
        fric: real_ge0(&c4, 21, "Fric", 0.0, "the friction coefficient")?,
        tpressfit: real_ge0(&c4, 41, "Tpressfit", 0.0, "the press-fit time")?,
        tstart,
        tstop,
        ibc: read_ibc(&c5)?,
        ivis2,
        inacti,
        viss: real_ge0(
            &c5,
            41,
            "VISs",
            if ivis2 == 5 { 1.0 } else { 0.05 },
            "the critical damping",
        )?,
        ithick: flag(&c5, 61, "Ithick", &[0, 1], 0)?,
        pmax: real_ge0(&c5, 81, "Pmax", EP30, "the maximum pressure")?,
        ifric,
        ifiltr,
        xfreq,
        sens_id: c6.id_opt(51, "sens_ID")?,
        fric_id: c6.id_opt(91, "fric_ID")?,
        fric_coefs: friction_coefs(cards, ifric)?,
        ipstif: flag(&c1, 91, "IPSTIF", &[0, 1], 0)?,
        stfac_mdt: real_ge0(
            &c3,
            81,
            "Stfac_mdt",
            0.1,
            "the mass and time-step stiffness factor",
        )?,
        dtstif: real_ge0(&c6, 61, "DTstif", 0.0, "the stiffness time step")?,
    })
}

/// TYPE24 and TYPE25: surf_ID1 (self-contact, or with surf_ID2), or
/// grnd_IDs with surf_ID2 (nodes to surface).
fn penalty_sides(c1: &Card, surf_id1: Id, surf_id2: Id, grnd_ids: Id) -> InputResult<()> {
    if surf_id1 == 0 && (surf_id2 == 0 || grnd_ids == 0) {
        return Err(c1.err(
            "surf_ID1",
            "0: expected surf_ID1 (self-contact, or with surf_ID2), or grnd_IDs and surf_ID2 (nodes to surface)",
        ));
    }
    Ok(())
}

/// Stmin (1-20, 0 → 0) and Stmax (21-40, 0 → 1e30, at least Stmin) of
/// TYPE24 and TYPE25.
fn stiffness_bounds(c: &Card) -> InputResult<(f64, f64)> {
    let stmin = real_ge0(c, 1, "Stmin", 0.0, "the minimum stiffness")?;
    let stmax = real_ge0(c, 21, "Stmax", EP30, "the maximum stiffness")?;
    Ok((stmin, stmax.max(stmin)))
}

/// Inacti of TYPE24 and TYPE25 (columns 31-40): 0 → 1000; −1, 1, 3, 5; 6
/// read as 5, as the Starter does.
fn penalty_inacti(c: &Card) -> InputResult<i64> {
    match c.int(31, "Inacti", 0)? {
        0 => Ok(1000),
        6 => Ok(5),
        v @ (-1 | 1 | 3 | 5 | 1000) => Ok(v),
        v => Err(c.err(
            "Inacti",
            format!("{v} in columns 31-40: expected 0, -1, 1, 3, 5 or 6"),
        )),
    }
}

// ---------------------------------------------------------------------------
// TYPE24
// ---------------------------------------------------------------------------

/// /INTER/TYPE24 (formats 2021-2023; 2021 has no IPSTIF, Stfac_mdt, DTstif,
/// Tpressfit, read as 0).
fn read_type24(cards: &mut Cards) -> InputResult<Type24> {
    let c1 = cards.next("the card with surf_ID1, surf_ID2, Istf, Irem_i2, Idel, IPSTIF")?;
    let surf_id1 = c1.id_opt(1, "surf_ID1")?;
    let surf_id2 = c1.id_opt(11, "surf_ID2")?;
    let istf = flag(
        &c1,
        21,
        "Istf",
        &[0, 1, 2, 3, 4, 5, 6, 7, 12, 13, 14, 1000],
        1000,
    )?;
    let c2 = cards.next("the card with grnd_IDs, Iedge, Edge_angle, Gap_max_s, Gap_max_m")?;
    let grnd_ids = c2.id_opt(1, "grnd_IDs")?;
    penalty_sides(&c1, surf_id1, surf_id2, grnd_ids)?;
    let c3 = cards.next("the card with Stmin, Stmax, Igap0, Ipen0, Ipen_max, Stfac_mdt")?;
    let (stmin, stmax) = stiffness_bounds(&c3)?;
    let c4 = cards.next("the card with Stfac, Fric, Tstart, Tstop")?;
    let (tstart, tstop) = times(&c4)?;
    let c5 = cards.next("the card with IBC, Inacti, VISs, Tpressfit")?;
    let c6 = cards.next("the card with Ifric, Ifiltr, Xfreq, sens_ID, DTstif, fric_ID")?;
    let ifric = flag(&c6, 1, "Ifric", &[0, 1, 2, 3, 4], 0)?;
    let (ifiltr, xfreq) = filter(&c6)?;
    Ok(Type24 {
        surf_id1,
        surf_id2,
        istf,
        irem_i2: flag(&c1, 51, "Irem_i2", &[0, 1, 3], 1)?,
        idel: flag(&c1, 71, "Idel", &[-2, -1, 0, 1, 2, 1000], 1000)?,
        ipstif: flag(&c1, 91, "IPSTIF", &[0, 1], 0)?,
        grnd_ids,
        iedge: match c2.int(31, "Iedge", 0)? {
            0 => 1000,
            v if v > 0 => v,
            v => {
                return Err(c2.err(
                    "Iedge",
                    format!("{v} in columns 31-40: expected 0 or a positive flag"),
                ))
            }
        },
        edge_angle: real_ge0(&c2, 41, "Edge_angle", 135.0, "the edge angle")?,
        gap_max_s: real_ge0(&c2, 61, "Gap_max_s", EP30, "the maximum secondary gap")?,
        gap_max_m: real_ge0(&c2, 81, "Gap_max_m", EP30, "the maximum main gap")?,
        stmin,
        stmax,
        igap0: flag(&c3, 41, "Igap0", &[0, 1, 1000], 1000)?,
        ipen0: flag(&c3, 51, "Ipen0", &[0, 1, 1000], 1000)?,
        ipen_max: real_ge0(&c3, 61, "Ipen_max", 0.0, "the largest initial penetration")?,
        stfac_mdt: real_ge0(
            &c3,
            81,
            "Stfac_mdt",
            0.1,
            "the mass and time-step stiffness factor",
        )?,
        stfac: real_ge0(&c4, 1, "Stfac", 1.0, "the stiffness factor")?,
        fric: real_ge0(&c4, 21, "Fric", 0.0, "the friction coefficient")?,
        tstart,
        tstop,
        ibc: read_ibc(&c5)?,
        inacti: penalty_inacti(&c5)?,
        viss: real_ge0(&c5, 41, "VISs", 0.05, "the critical damping")?,
        tpressfit: real_ge0(&c5, 81, "Tpressfit", 0.0, "the press-fit time")?,
        ifric,
        ifiltr,
        xfreq,
        sens_id: c6.id_opt(51, "sens_ID")?,
        dtstif: real_ge0(&c6, 61, "DTstif", 0.0, "the stiffness time step")?,
        fric_id: c6.id_opt(91, "fric_ID")?,
        fric_coefs: friction_coefs(cards, ifric)?,
    })
}

/// Reads one /INTER block. Returns false for an interface type this reader
/// does not support (the caller warns, or fails with --strict).
pub(super) fn parse_interface(block: &Block, deck: &mut Deck) -> InputResult<bool> {
    let ty = block.parts.get(1).map(String::as_str).unwrap_or("");
    let which = match ty {
        "TYPE2" => 2,
        "TYPE3" => 3,
        "TYPE5" => 5,
        "TYPE6" => 6,
        "TYPE7" => 7,
        "TYPE11" => 11,
        "TYPE14" => 14,
        "TYPE15" => 15,
        "TYPE19" => 19,
        "TYPE24" => 24,
        "TYPE25" => 25,
        _ => return Ok(false),
    };
    let id = header_id(block, 2, "inter_ID")?;
    let unit_id = header_id_opt(block, 3, "unit_ID")?;
    let mut cards = Cards::new(block);
    let title = cards.title();
    let kind = match which {
        2 => InterfaceKind::Type2(read_type2(&mut cards)?),
        3 => InterfaceKind::Type3(read_type3(&mut cards)?),
        5 => InterfaceKind::Type5(read_type5(&mut cards)?),
        6 => InterfaceKind::Type6(read_type6(&mut cards)?),
        7 => InterfaceKind::Type7(read_type7(&mut cards)?),
        11 => {
            let invers = deck.begin.as_ref().map_or(0, |b| b.invers);
            InterfaceKind::Type11(read_type11(&mut cards, invers > 0 && invers < 110)?)
        }
        14 => InterfaceKind::Type14(read_type14(&mut cards)?),
        15 => InterfaceKind::Type15(read_type15(&mut cards)?),
        19 => InterfaceKind::Type19(read_type19(&mut cards)?),
        24 => InterfaceKind::Type24(read_type24(&mut cards)?),
        _ => InterfaceKind::Type25(read_type25(&mut cards)?),
    };
    let extra: Vec<_> = cards
        .remaining()
        .iter()
        .filter(|l| !l.text.trim().is_empty())
        .collect();
    if let Some(first) = extra.first() {
        deck.warnings.push(Warning {
            loc: first.loc.clone(),
            keyword: block.header.clone(),
            message: format!(
                "{} line(s) after the last card this /INTER/{ty} expects are ignored \
                 (check the flags that announce optional cards, e.g. Ifric, Icurv, Iadm, Ithe)",
                extra.len()
            ),
        });
    }
    deck.interfaces.push(InterfaceSpec {
        id,
        unit_id,
        title,
        kind,
        loc: block.loc.clone(),
        ids_loc: block
            .lines
            .get(1)
            .map_or_else(|| block.loc.clone(), |l| l.loc.clone()),
    });
    Ok(true)
}

/// A 10-column integer flag at `col` that must be one of `allowed`; 0 (or
/// blank) becomes `zero`.
fn flag(c: &Card, col: usize, name: &str, allowed: &[i64], zero: i64) -> InputResult<i64> {
    let width = 10;
    let v = c.int_opt(col, width, name)?.unwrap_or(0);
    if !allowed.contains(&v) {
        return Err(c.err(
            name,
            format!(
                "{v} in columns {col}-{}: expected one of {allowed:?} (0 = default {zero})",
                col + width - 1
            ),
        ));
    }
    Ok(if v == 0 { zero } else { v })
}

/// A 20-column real at `col` that must be >= 0; 0 (or blank) becomes `zero`.
fn real_ge0(c: &Card, col: usize, name: &str, zero: f64, what: &str) -> InputResult<f64> {
    let width = 20;
    let v = c.real_opt(col, width, name)?.unwrap_or(0.0);
    if v < 0.0 {
        return Err(c.err(
            name,
            format!(
                "{v} in columns {col}-{}: {what} must be >= 0 (0 = default {zero})",
                col + width - 1
            ),
        ));
    }
    Ok(if v == 0.0 { zero } else { v })
}

/// Tstart (61-80, default 0) and Tstop (81-100, 0 → 1e30) of a card.
fn times(c: &Card) -> InputResult<(f64, f64)> {
    let tstart = real_ge0(c, 61, "Tstart", 0.0, "the start time")?;
    let tstop = real_ge0(c, 81, "Tstop", EP30, "the stop time")?;
    if tstop < tstart {
        return Err(c.err(
            "Tstop",
            format!("{tstop} in columns 81-100 is before Tstart = {tstart}: expected Tstop >= Tstart (0 = never stop)"),
        ));
    }
    Ok((tstart, tstop))
}

/// IBC: three one-column 0/1 flags IBCX, IBCY, IBCZ in columns 8, 9, 10
/// (written e.g. `       000`); columns 1-7 are blank.
fn read_ibc(c: &Card) -> InputResult<[bool; 3]> {
    let lead = c.text(1, 7);
    if !lead.is_empty() {
        return Err(c.err(
            "IBC",
            format!("'{lead}' in columns 1-7: expected blanks; IBC is three one-column 0/1 flags IBCX IBCY IBCZ in columns 8, 9, 10 (e.g. '       001')"),
        ));
    }
    let mut out = [false; 3];
    for (i, name) in ["IBCX", "IBCY", "IBCZ"].iter().enumerate() {
        let col = 8 + i;
        match c.text(col, 1) {
            "" | "0" => {}
            "1" => out[i] = true,
            t => return Err(c.err(name, format!("'{t}' in column {col}: expected 0 or 1"))),
        }
    }
    Ok(out)
}

/// Ifiltr (11-20) and Xfreq (21-40) of a friction card, with the Starter's
/// rules: Ifiltr is forced to 0 when Xfreq = 0; with Ifiltr = 1, Xfreq is the
/// filter coefficient α in (0, 1]; with Ifiltr = 2 it is the number of steps
/// per period (α = 2π/Xfreq must be <= 1).
fn filter(c: &Card) -> InputResult<(i64, f64)> {
    let ifiltr = flag(c, 11, "Ifiltr", &[0, 1, 2, 3], 0)?;
    let xfreq = real_ge0(c, 21, "Xfreq", 0.0, "the filtering coefficient")?;
    if xfreq == 0.0 {
        return Ok((0, 0.0));
    }
    match ifiltr {
        1 if xfreq > 1.0 => Err(c.err(
            "Xfreq",
            format!("{xfreq} in columns 21-40: with Ifiltr = 1 the filter coefficient must be in (0, 1]"),
        )),
        2 if xfreq < 2.0 * std::f64::consts::PI => Err(c.err(
            "Xfreq",
            format!("{xfreq} in columns 21-40: with Ifiltr = 2 Xfreq is the number of steps per filtering period and must be >= 2π (6.2832)"),
        )),
        _ => Ok((ifiltr, xfreq)),
    }
}

/// C1..C5 (when Ifric > 0) and C6 (when Ifric > 1), 20 columns each.
fn friction_coefs(cards: &mut Cards, ifric: i64) -> InputResult<Option<[f64; 6]>> {
    if ifric <= 0 {
        return Ok(None);
    }
    let mut cs = [0.0; 6];
    let c = cards.next("the card with friction coefficients C1, C2, C3, C4, C5 (Ifric > 0)")?;
    for (i, name) in ["C1", "C2", "C3", "C4", "C5"].iter().enumerate() {
        cs[i] = c.real(1 + 20 * i, name, 0.0)?;
    }
    if ifric > 1 {
        let c = cards.next("the card with friction coefficient C6 (Ifric > 1)")?;
        cs[5] = c.real(1, "C6", 0.0)?;
    }
    Ok(Some(cs))
}

#[cfg(test)]
mod tests {
    use super::super::source::Line;
    use super::*;
    use crate::model::Loc;

    /// A block as the source reader makes it (comment lines already removed).
    fn block(header: &str, lines: &[&str]) -> Block {
        let parts = header[1..]
            .split('/')
            .map(|p| p.trim().to_ascii_uppercase())
            .collect();
        Block {
            header: header.to_string(),
            parts,
            loc: Loc {
                file: "t.rad".into(),
                line: 1,
            },
            lines: lines
                .iter()
                .enumerate()
                .map(|(i, t)| Line {
                    text: t.to_string(),
                    loc: Loc {
                        file: "t.rad".into(),
                        line: i + 2,
                    },
                })
                .collect(),
        }
    }

    fn parse(header: &str, lines: &[&str]) -> InputResult<(InterfaceSpec, Deck)> {
        let mut deck = Deck::default();
        let ok = parse_interface(&block(header, lines), &mut deck)?;
        assert!(ok, "{header} should be supported");
        Ok((deck.interfaces[0].clone(), deck))
    }

    // INT357 (OpenRadioss QA), with the listing's values in the assertions.
    const INT357_TYPE3: &[&str] = &[
        "interface_3",
        "         9        10                                                           0",
        "                   0                  .2                   0                   0                   0",
        "       000         0         0",
    ];
    const INT357_TYPE5: &[&str] = &[
        "interface_5",
        "        11        12                                                 0         0",
        "                   0                  .2                   0                   0                   0",
        "       000                   0         0",
        "         0         0                   0                   0                   0",
    ];
    const INT357_TYPE7: &[&str] = &[
        "interface_7",
        "        13        14         0         0         0                   0         0         0         0",
        "                   0                   0                   0",
        "                   0                   0                   0                   0         0         0",
        "                   0                  .2                   0                   0                   0",
        "       000                             0                   0                   0                   0",
        "         0         0                   0         0         0         0                   0         0",
    ];

    #[test]
    fn int357_type3() {
        let (card, _) = parse("/INTER/TYPE3/3", INT357_TYPE3).unwrap();
        assert_eq!(card.id, 3);
        assert_eq!(card.title, "interface_3");
        assert_eq!(card.type_number(), 3);
        assert_eq!(card.secondary_side(), Side::Surface(9));
        assert_eq!(card.main_side(), Side::Surface(10));
        let InterfaceKind::Type3(t) = &card.kind else {
            panic!()
        };
        assert_eq!(t.stfac, 0.2);
        assert_eq!(t.fric, 0.2);
        assert_eq!(t.gap, 0.0);
        assert_eq!(t.tstop, 1e30);
        assert_eq!(t.ptlim, 1e30, "card 4 absent → 1e30");
        assert_eq!(t.ibc, [false; 3]);
        assert_eq!((t.irs, t.irm, t.idel), (0, 0, 0));
    }

    #[test]
    fn int357_type5() {
        let (card, deck) = parse("/INTER/TYPE5/6", INT357_TYPE5).unwrap();
        assert!(deck.warnings.is_empty());
        assert_eq!(card.secondary_side(), Side::NodeGroup(11));
        assert_eq!(card.main_side(), Side::Surface(12));
        let InterfaceKind::Type5(t) = &card.kind else {
            panic!()
        };
        assert_eq!(t.stfac, 0.2);
        assert_eq!(t.fric, 0.2);
        assert_eq!(t.tstop, 1e30);
        assert_eq!(t.ptlim, 1e30);
        assert_eq!((t.inacti, t.ifric, t.ifiltr, t.xfreq), (0, 0, 0, 0.0));
        assert_eq!(t.fric_coefs, None);
    }

    #[test]
    fn int357_type7_defaults() {
        let (card, deck) = parse("/INTER/TYPE7/10", INT357_TYPE7).unwrap();
        assert!(deck.warnings.is_empty());
        assert_eq!(card.type_number(), 7);
        assert_eq!(card.secondary_side(), Side::NodeGroup(13));
        assert_eq!(card.main_side(), Side::Surface(14));
        let InterfaceKind::Type7(t) = &card.kind else {
            panic!()
        };
        assert_eq!(t.stfac, 1.0);
        assert_eq!(t.fric, 0.2);
        assert_eq!(t.istf, 1000);
        assert_eq!(t.igap, 1000);
        assert_eq!(t.inacti, 1000);
        assert_eq!(t.idel, 1000);
        assert_eq!(t.ibag, 1000);
        assert_eq!(t.irem_gap, 1);
        assert_eq!(t.irem_i2, 3);
        assert_eq!(t.iform, 1);
        assert_eq!(t.viss, 0.05);
        assert_eq!(t.visf, 1.0);
        assert_eq!(t.bumult, 0.2);
        assert_eq!(t.tstop, 1e30);
        assert_eq!(t.stmax, 1e30);
        assert_eq!(t.gapmax, 1e30);
        assert_eq!(t.fscalegap, 1.0);
        assert_eq!(t.ascalef, 1.0);
        assert_eq!(t.gapmin, 0.0);
        assert_eq!(t.ibc, [false; 3]);
        assert_eq!((t.ifric, t.ifiltr, t.fric_id, t.sens_id), (0, 0, 0, 0));
        assert!(t.fric_coefs.is_none() && t.adm.is_none() && t.thermal.is_none());
        assert!(t.curv_nodes.is_none());
    }

    #[test]
    fn type7_self_contact_and_ibc() {
        let mut lines = INT357_TYPE7.to_vec();
        lines[1] = "         0        14";
        lines[5] = "       101";
        let (card, _) = parse("/INTER/TYPE7/10/2", &lines).unwrap();
        assert_eq!(card.unit_id, 2);
        assert_eq!(card.secondary_side(), Side::SameAsOther);
        let InterfaceKind::Type7(t) = &card.kind else {
            panic!()
        };
        assert_eq!(t.ibc, [true, false, true]);
    }

    /// Right-aligned fixed-width fields: `(width, text)`.
    fn row(fields: &[(usize, &str)]) -> String {
        fields
            .iter()
            .map(|(w, t)| format!("{t:>w$}", w = *w))
            .collect()
    }

    #[test]
    fn type7_friction_law_cards() {
        let c15 = row(&[(20, ".1"), (20, ".2"), (20, ".3"), (20, ".4"), (20, ".5")]);
        let mut lines = INT357_TYPE7.to_vec();
        lines[6] = "         1";
        lines.push(&c15);
        let (card, deck) = parse("/INTER/TYPE7/10", &lines).unwrap();
        assert!(deck.warnings.is_empty());
        let InterfaceKind::Type7(t) = &card.kind else {
            panic!()
        };
        assert_eq!(t.ifric, 1);
        assert_eq!(t.fric_coefs, Some([0.1, 0.2, 0.3, 0.4, 0.5, 0.0]));

        // Ifric = 3 (Renard) also reads C6; then the Iadm and thermal cards follow.
        let c1 = row(&[
            (10, "13"),
            (10, "14"),
            (10, "0"),
            (10, "1"),
            (10, "0"),
            (10, ""),
            (10, "0"),
            (10, "0"),
            (10, "0"),
            (10, "2"),
        ]);
        let c6 = row(&[(20, ".6")]);
        let adm = row(&[(10, "0"), (20, "0"), (20, "30")]);
        let th1 = row(&[(20, "10"), (10, "7"), (10, ""), (20, "293"), (10, "1")]);
        let th2 = row(&[(20, "0"), (20, "0"), (20, ".5"), (20, ".5")]);
        let mut lines = INT357_TYPE7.to_vec();
        lines[1] = &c1;
        lines[6] = "         3";
        lines.extend([c15.as_str(), &c6, &adm, &th1, &th2]);
        let (card, deck) = parse("/INTER/TYPE7/10", &lines).unwrap();
        assert!(deck.warnings.is_empty());
        let InterfaceKind::Type7(t) = &card.kind else {
            panic!()
        };
        assert_eq!((t.ithe, t.iadm), (1, 2));
        assert_eq!(t.fric_coefs, Some([0.1, 0.2, 0.3, 0.4, 0.5, 0.6]));
        assert_eq!(
            t.adm,
            Some(Type7Adm {
                nradm: 3,
                padm: 1.0,
                angladm: 30.0
            })
        );
        let th = t.thermal.as_ref().unwrap();
        assert_eq!(
            (th.kthe, th.fct_idk, th.tint, th.ithe_form),
            (10.0, 7, 293.0, 1)
        );
        assert_eq!(th.ascalek, 1.0);
        assert_eq!((th.fheats, th.fheatm), (0.5, 0.5));
    }

    #[test]
    fn type7_curvature_nodes() {
        let mut lines = INT357_TYPE7.to_vec();
        lines[1] = "        13        14         0         0         0                   0         0         2";
        lines.insert(4, "       101       102");
        let (card, _) = parse("/INTER/TYPE7/10", &lines).unwrap();
        let InterfaceKind::Type7(t) = &card.kind else {
            panic!()
        };
        assert_eq!(t.curv_nodes, Some([101, 102]));

        lines[4] = "       101";
        let e = parse("/INTER/TYPE7/10", &lines).unwrap_err();
        assert_eq!(e.field, "node_ID2");
    }

    #[test]
    fn type7_bad_flag_names_the_field() {
        let mut lines = INT357_TYPE7.to_vec();
        lines[1] = "        13        14         7";
        let e = parse("/INTER/TYPE7/10", &lines).unwrap_err();
        assert_eq!(e.field, "Istf");
        assert!(e.message.contains("columns 21-30"), "{}", e.message);
        assert_eq!(e.loc.line, 3);

        let mut lines = INT357_TYPE7.to_vec();
        lines[4] = "                -1.0";
        let e = parse("/INTER/TYPE7/10", &lines).unwrap_err();
        assert_eq!(e.field, "Stfac");
        assert!(e.message.contains(">= 0"), "{}", e.message);

        let mut lines = INT357_TYPE7.to_vec();
        lines[5] = "       0x0";
        let e = parse("/INTER/TYPE7/10", &lines).unwrap_err();
        assert_eq!(e.field, "IBCY");

        let mut lines = INT357_TYPE7.to_vec();
        lines[1] = "         0         0";
        let e = parse("/INTER/TYPE7/10", &lines).unwrap_err();
        assert_eq!(e.field, "surf_IDm");
    }

    #[test]
    fn type7_truncated_card() {
        let lines = &INT357_TYPE7[..6];
        let e = parse("/INTER/TYPE7/10", lines).unwrap_err();
        assert!(e.message.contains("card missing"), "{}", e.message);
        assert!(e.message.contains("Ifric"), "{}", e.message);

        // Ifric = 2 announces C1..C5 and C6: a missing C6 card is an error too.
        let mut lines = INT357_TYPE7.to_vec();
        lines[6] = "         2";
        lines.push("                  .1");
        let e = parse("/INTER/TYPE7/10", &lines).unwrap_err();
        assert!(
            e.message.contains("card missing") && e.message.contains("C6"),
            "{}",
            e.message
        );
    }

    #[test]
    fn extra_lines_warn() {
        let mut lines = INT357_TYPE7.to_vec();
        lines.push("                  .1                  .2");
        let (_, deck) = parse("/INTER/TYPE7/10", &lines).unwrap();
        assert_eq!(deck.warnings.len(), 1);
        assert_eq!(deck.warnings[0].loc.line, 9);
    }

    #[test]
    fn type3_with_ptlim() {
        let mut lines = INT357_TYPE3.to_vec();
        lines.push("                                                                       5000.");
        let (card, _) = parse("/INTER/TYPE3/3", &lines).unwrap();
        let InterfaceKind::Type3(t) = &card.kind else {
            panic!()
        };
        assert_eq!(t.ptlim, 5000.0);
    }

    #[test]
    fn type2_kinematic_and_penalty() {
        let (card, _) = parse("/INTER/TYPE2/4", &["tied", "         3         4"]).unwrap();
        assert_eq!(card.secondary_side(), Side::NodeGroup(3));
        assert_eq!(card.main_side(), Side::Surface(4));
        let InterfaceKind::Type2(t) = &card.kind else {
            panic!()
        };
        assert_eq!(
            (t.ignore, t.spotflag, t.isearch, t.idel2),
            (1000, 5, 2, 1000)
        );
        assert!(t.penalty.is_none() && t.rupture.is_none() && t.thermal.is_none());

        let (card, _) = parse(
            "/INTER/TYPE2/4",
            &[
                "tied",
                "         3         4                  25         2",
                "",
                "         1                   3",
            ],
        )
        .unwrap();
        let InterfaceKind::Type2(t) = &card.kind else {
            panic!()
        };
        assert_eq!(t.level, 0, "forced to 0 for Spotflag 25");
        assert_eq!(
            t.penalty,
            Some(Type2Penalty {
                stfac: 1.0,
                visc: 0.05,
                istf: 2
            })
        );
        let th = t.thermal.as_ref().unwrap();
        assert_eq!((th.ithe, th.kthe, th.iproj), (1, 3.0, 1));

        let e = parse(
            "/INTER/TYPE2/4",
            &["tied", "         3         4                   6"],
        )
        .unwrap_err();
        assert_eq!(e.field, "Spotflag");
    }

    #[test]
    fn type11_self_contact_and_negative_stfac() {
        let (card, _) = parse(
            "/INTER/TYPE11/8",
            &["edges", "         5", "", "              -1000.", ""],
        )
        .unwrap();
        assert_eq!(card.secondary_side(), Side::Line(5));
        assert_eq!(card.main_side(), Side::SameAsOther);
        let InterfaceKind::Type11(t) = &card.kind else {
            panic!()
        };
        assert_eq!((t.istf, t.stfac), (1, 1000.0));
        assert_eq!(
            (t.igap, t.idel, t.inacti, t.iform, t.irem_gap),
            (1000, 1000, 1000, 1, 1)
        );
        assert_eq!(
            (t.viss, t.bumult, t.tstop, t.stmax),
            (0.05, 0.2, 1e30, 1e30)
        );
        assert_eq!(t.fric_id, 0);

        let e = parse(
            "/INTER/TYPE11/8",
            &[
                "edges",
                "         5         6         0         0         2",
            ],
        )
        .unwrap_err();
        assert_eq!(e.field, "Igap");
    }

    #[test]
    fn unsupported_type() {
        let mut deck = Deck::default();
        let b = block("/INTER/TYPE23/1", &["t", "1 2"]);
        assert!(!parse_interface(&b, &mut deck).unwrap());
        assert!(deck.interfaces.is_empty());
    }

    /// The three-card TYPE11 of a version-100 deck (OpenRadioss QA
    /// SUBMODEL_update_v_100_PLOAD): no Stmin card; Multimp ignored.
    #[test]
    fn type11_of_a_version_100_deck() {
        let lines = [
            "edge to edge",
            "         1         1         0                   0         0                   0",
            "                   1                   0                   0                   0                   0",
            "       000                             0                   0                   0                   0",
        ];
        let mut deck = Deck {
            begin: Some(crate::model::Begin {
                run_name: "OLD".into(),
                invers: 100,
                irun: 0,
                input_units: Default::default(),
                work_units: Default::default(),
                loc: Default::default(),
            }),
            ..Default::default()
        };
        assert!(parse_interface(&block("/INTER/TYPE11/1", &lines), &mut deck).unwrap());
        let InterfaceKind::Type11(t) = &deck.interfaces[0].kind else {
            panic!("a TYPE11")
        };
        assert_eq!(
            (t.line_ids, t.line_idm, t.istf, t.igap, t.idel),
            (1, 1, 5, 1000, 1000)
        );
        assert_eq!((t.stfac, t.stmax, t.viss, t.bumult), (1.0, EP30, 0.05, 0.2));
        // The same lines in a current deck miss the IBC card.
        assert!(parse("/INTER/TYPE11/1", &lines).is_err());
    }
}
