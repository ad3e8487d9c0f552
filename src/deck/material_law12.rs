//! /MAT/LAW12 (/MAT/3D_COMP): orthotropic solid composite with Tsai-Wu
//! plasticity (reference guide /MAT/LAW12; research note
//! `docs/notes/law12_research.md` §1.1-1.2). Cards after the title:
//! 1. RHO_I (1-20), RHO_0 (21-40)
//! 2. E11, E22, E33; 3. ν12, ν23, ν31; 4. G12, G23, G31
//! 5. σ_t1, σ_t2, σ_t3, DELTA; 6. B, n, fmax, Wplaref
//! 7. σ_1yt, σ_2yt, σ_1yc, σ_2yc; 8. σ_12yt, σ_12yc, σ_23yt, σ_23yc
//! 9. σ_3yt, σ_3yc, σ_13yt, σ_13yc; 10. α, E_f, c, ε̇₀ (61-80), ICC (81-90)
//!
//! (20-column fields.) G and ν may be 0 (no shear stiffness, no Poisson
//! coupling), as the reference starter keeps them.

use super::fields::{Card, Cards};
use super::source::Block;
use super::{header_id, header_id_opt, Deck};
use crate::model::{Composite3d, InputResult, MaterialLaw, MaterialSpec};

/// The reference starter's "infinite" strength (single-precision 1e20).
const INF: f64 = 1e20;

fn reals<const N: usize>(c: &Card, names: [&str; N]) -> InputResult<[f64; N]> {
    let mut out = [0.0; N];
    for (k, name) in names.iter().enumerate() {
        out[k] = c.real(1 + 20 * k, name, 0.0)?;
    }
    Ok(out)
}

/// A blank value takes `default`.
fn or(v: f64, default: f64) -> f64 {
    if v == 0.0 {
        default
    } else {
        v
    }
}

/// The yields (tension, compression) in the order 1, 2, 3, 12, 23, 31,
/// blanks resolved as the reference starter (note §1.2).
fn yields(y7: [f64; 4], y8: [f64; 4], y9: [f64; 4]) -> ([f64; 6], [f64; 6]) {
    let [s1t, s2t, s1c, s2c] = y7;
    let [s12t, s12c, s23t, s23c] = y8;
    let [s3t, s3c, s13t, s13c] = y9;
    let s1t = or(s1t, INF);
    let s1c = or(s1c, s1t);
    let s2t = or(s2t, s1t);
    let s2c = or(s2c, s1c);
    let s3t = or(s3t, s2t);
    let s3c = or(s3c, s2c);
    let (s12t, s12c) = (or(s12t, INF), or(s12c, INF));
    let (s23t, s23c) = (or(s23t, INF), or(s23c, INF));
    let (s13t, s13c) = (or(s13t, s12t), or(s13c, s12c));
    (
        [s1t, s2t, s3t, s12t, s23t, s13t],
        [s1c, s2c, s3c, s12c, s23c, s13c],
    )
}

/// Reads /MAT/LAW12 or /MAT/3D_COMP into the deck's materials.
pub(super) fn parse_law12(block: &Block, deck: &mut Deck) -> InputResult<()> {
    let id = header_id(block, 2, "mat_ID")?;
    let unit_id = header_id_opt(block, 3, "unit_ID")?;
    let mut cards = Cards::new(block);
    let title = cards.title();
    let c1 = cards.next("the card with RHO_I (initial density)")?;
    let rho = c1.positive_real(1, "RHO_I", "density")?;
    let rho_ref = c1.real(21, "RHO_0", 0.0)?;
    let c2 = cards.next("the card with E11, E22, E33")?;
    let e = reals(&c2, ["E11", "E22", "E33"])?;
    for (k, v) in e.iter().enumerate() {
        if !(*v > 0.0) {
            let name = ["E11", "E22", "E33"][k];
            return Err(c2.err(name, format!("{v}: expected a Young's modulus > 0")));
        }
    }
    let c3 = cards.next("the card with NU12, NU23, NU31")?;
    let nu = reals(&c3, ["NU12", "NU23", "NU31"])?;
    let c4 = cards.next("the card with G12, G23, G31")?;
    let g = reals(&c4, ["G12", "G23", "G31"])?;
    if let Some(k) = g.iter().position(|v| *v < 0.0) {
        let name = ["G12", "G23", "G31"][k];
        return Err(c4.err(name, format!("{}: expected a shear modulus >= 0", g[k])));
    }
    let c5 = cards.next("the card with SIGMA_T1, SIGMA_T2, SIGMA_T3, DELTA")?;
    let [t1, t2, t3, delta] = reals(&c5, ["SIGMA_T1", "SIGMA_T2", "SIGMA_T3", "DELTA"])?;
    let c6 = cards.next("the card with B, n, fmax, Wplaref")?;
    let [b, n, fmax, wplaref] = reals(&c6, ["B", "n", "fmax", "Wplaref"])?;
    let c7 = cards.next("the card with sigma_1yt, sigma_2yt, sigma_1yc, sigma_2yc")?;
    let y7 = reals(&c7, ["sigma_1yt", "sigma_2yt", "sigma_1yc", "sigma_2yc"])?;
    let c8 = cards.next("the card with sigma_12yt, sigma_12yc, sigma_23yt, sigma_23yc")?;
    let y8 = reals(
        &c8,
        ["sigma_12yt", "sigma_12yc", "sigma_23yt", "sigma_23yc"],
    )?;
    let c9 = cards.next("the card with sigma_33yt, sigma_33yc, sigma_13yt, sigma_13yc")?;
    let y9 = reals(
        &c9,
        ["sigma_33yt", "sigma_33yc", "sigma_13yt", "sigma_13yc"],
    )?;
    let c10 = cards.next("the card with ALPHA, E_f, c, EPS_RATE_0, ICC")?;
    let [_alpha, _e_f, c, eps_rate0] = reals(&c10, ["ALPHA", "E_f", "c", "EPS_RATE_0"])?;
    if c != 0.0 && eps_rate0 == 0.0 {
        return Err(c10.err(
            "EPS_RATE_0",
            "0 with a strain-rate coefficient c ≠ 0: expected a reference strain rate > 0",
        ));
    }
    let icc = c10.flag(81, "ICC", 0, &[0, 1, 2, 3, 4])?;
    let (yt, yc) = yields(y7, y8, y9);
    let t1 = or(t1, 1e30);
    let law = Composite3d {
        e,
        nu,
        g,
        sig_t: [t1, or(t2, t1), or(t3, t1)],
        delta: or(delta, 0.05),
        b,
        n: or(n, 1.0),
        fmax: or(fmax, 1e10).max(1.0001),
        wplaref: or(wplaref, 1.0),
        yt,
        yc,
        c,
        eps_rate0: if c == 0.0 { 1.0 } else { eps_rate0 },
        icc: or(icc as f64, 1.0) as i64,
    };
    let Some(d) = law.stiffness() else {
        return Err(c3.err(
            "NU12",
            "the compliance of E11, E22, E33, NU12, NU23, NU31 is not positive definite",
        ));
    };
    super::warn_surplus(&cards, "the last card of /MAT/LAW12", &mut deck.warnings);
    deck.materials.push(MaterialSpec {
        id,
        unit_id,
        title,
        rho,
        rho_ref,
        // The wave speed √(max Dii/ρ0) of the reference (note §1.2).
        e: d[0][0].max(d[1][1]).max(d[2][2]),
        nu: 0.0,
        law: MaterialLaw::Composite3d(law),
        failures: Vec::new(),
        loc: block.loc.clone(),
    });
    Ok(())
}
