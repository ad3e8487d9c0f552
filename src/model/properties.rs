//! Property defaults that depend on other cards: a 0 in /PROP/SHELL takes the
//! /DEF_SHELL value, and a 0 there takes the built-in default (reference
//! guide, confirmed against the OpenRadioss starter listings).

use crate::model::{DefShell, DefSolid, ShellProperty, SolidProperty};
use serde::{Deserialize, Serialize};

/// /PROP/SHELL with every default resolved.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct ResolvedShell {
    /// Formulation: 1..4 Belytschko-Tsay family with hourglass options, 12 QBAT, 24 QEPH.
    pub ishell: i64,
    pub ismstr: i64,
    pub ish3n: i64,
    pub idrill: i64,
    pub hm: f64,
    pub hf: f64,
    pub hr: f64,
    pub dm: f64,
    pub dn: f64,
    /// Integration points through the thickness; 0 = global (resultant) plasticity.
    pub n: i64,
    pub istrain: i64,
    pub thick: f64,
    pub ashear: f64,
    pub ithick: i64,
    pub iplas: i64,
    pub p_thick_fail: f64,
}

fn pick(own: i64, global: Option<i64>, builtin: i64) -> i64 {
    if own != 0 {
        own
    } else {
        match global {
            Some(g) if g != 0 => g,
            _ => builtin,
        }
    }
}

/// Ishell 0 → /DEF_SHELL → 1; Ismstr → 2; Ish3n → 2; Idrill → 2 (none);
/// Istrain → 1; Ithick, Iplas → 0; hm, hf, hr 0 → 0.01 (0.1 for Ishell 3);
/// Ashear 0 → 5/6; dn 0 → 0.001 for QBAT (12), 0.015 for QEPH (24).
pub fn resolve_shell(p: &ShellProperty, d: Option<&DefShell>) -> ResolvedShell {
    let ishell = pick(p.ishell, d.map(|d| d.ishell), 1);
    let hdef = if ishell == 3 { 0.1 } else { 0.01 };
    let h = |v: f64| if v == 0.0 { hdef } else { v };
    let dn = if p.dn != 0.0 {
        p.dn
    } else {
        match ishell {
            12 => 0.001,
            24 => 0.015,
            _ => 0.0,
        }
    };
    ResolvedShell {
        ishell,
        ismstr: pick(p.ismstr, d.map(|d| d.ismstr), 2),
        ish3n: pick(p.ish3n, d.map(|d| d.ish3n), 2),
        idrill: pick(p.idrill, d.map(|d| d.idrill), 2),
        hm: h(p.hm),
        hf: h(p.hf),
        hr: h(p.hr),
        dm: p.dm,
        dn,
        n: p.n,
        istrain: pick(p.istrain, d.map(|d| d.istrain), 1),
        thick: p.thick,
        ashear: if p.ashear == 0.0 { 5.0 / 6.0 } else { p.ashear },
        ithick: pick(p.ithick, d.map(|d| d.ithick), 0),
        iplas: pick(p.iplas, d.map(|d| d.iplas), 0),
        p_thick_fail: p.p_thick_fail,
    }
}

/// /PROP/SOLID with every default resolved.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct ResolvedSolid {
    pub isolid: i64,
    pub ismstr: i64,
    pub iframe: i64,
    pub itetra4: i64,
    /// Icpre as given (0 blank, −1 automatic); the formulation resolves it.
    #[serde(default)]
    pub icpre: i64,
    /// Inpts as given (0 blank).
    #[serde(default)]
    pub inpts: i64,
    pub qa: f64,
    pub qb: f64,
    /// qa and qb both blank on the card (see `SolidProperty::q_blank`).
    #[serde(default)]
    pub q_blank: bool,
    pub h: f64,
    pub dtmin: f64,
    /// Hourglass viscous coefficient of HEPH (Isolid 24) as given (0 blank).
    #[serde(default)]
    pub dn: f64,
    /// The orthotropic directions of a /PROP/TYPE6 section.
    #[serde(default)]
    pub ortho: Option<super::SolidOrtho>,
}

/// Isolid 0 → /DEF_SOLID → 1; Ismstr → 4; Iframe → 1; Itetra4 → 1000;
/// qa, qb, h defaults were applied by the reader.
pub fn resolve_solid(p: &SolidProperty, d: Option<&DefSolid>) -> ResolvedSolid {
    ResolvedSolid {
        isolid: pick(p.isolid, d.map(|d| d.isolid), 1),
        ismstr: pick(p.ismstr, d.map(|d| d.ismstr), 4),
        iframe: pick(p.iframe, d.map(|d| d.iframe), 1),
        itetra4: pick(p.itetra4, None, 1000),
        icpre: p.icpre,
        inpts: p.inpts,
        qa: p.qa,
        qb: p.qb,
        q_blank: p.q_blank,
        h: p.h,
        dtmin: p.dtmin,
        dn: p.dn,
        ortho: p.ortho.clone(),
    }
}
