//! /INTER/TYPE19 options: general contact of two surfaces (or one surface
//! with itself), which Radioss computes as TYPE7 node-to-surface contact in
//! both directions plus TYPE11 edge-to-edge contact of the surfaces' edges
//! (reference card /INTER/TYPE19: "combination of two symmetric TYPE7
//! interfaces and one TYPE11 interface"). The reader keeps the card; the
//! model builder expands it into those interfaces (`deck::to_model`).

use super::{Type11, Type7};
use crate::model::Id;
use serde::{Deserialize, Serialize};

/// /INTER/TYPE19 (format 2021-2024). Card 1: surf_IDs (1-10), surf_IDm
/// (11-20), Istf, Ithe, Igap, Iedge (51-60), Ibag, Idel, Icurv; card 2:
/// Fscalegap, Gapmax, Edge_scale_gap (41-60); the other cards as TYPE7's
/// (Stmin ... Irem_i2; Stfac, Fric, Gapmin, Tstart, Tstop; IBC, Inacti,
/// VISs, VISF, Bumult; Ifric, Ifiltr, Xfreq, Iform, sens_ID, fric_ID (91-100);
/// friction and thermal cards).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Type19 {
    /// surf_IDs, surf_IDm: either may be 0 (then both are the other: self-contact).
    pub surf_ids: Id,
    pub surf_idm: Id,
    /// Igap as the card gives it: 0 → 1000 constant; 1, 2, 3 variable as in
    /// TYPE7; 4: variable (2) with Irem_gap 2 for the nodes, constant for the edges.
    pub igap: i64,
    /// Iedge: 0 → 2 every edge of the surfaces; 1 only their free edges.
    pub iedge: i64,
    /// Edge_scale_gap: the edge part's Gapmin is Gapmin times it (0: not scaled).
    pub edge_scale_gap: f64,
    /// The node-to-surface options (the TYPE7 layout of the card).
    pub nodes: Type7,
}

impl Type19 {
    /// The two surfaces, (secondary, main); one of them 0 means the other.
    pub fn surfaces(&self) -> (Id, Id) {
        match (self.surf_ids, self.surf_idm) {
            (0, m) => (m, m),
            (s, 0) => (s, s),
            (s, m) => (s, m),
        }
    }

    /// The options of the node-to-surface parts (secondary nodes given by
    /// the builder, not by the card's ids).
    pub fn node_part(&self) -> Type7 {
        Type7 {
            grnod_ids: 0,
            ists: 0,
            ..self.nodes.clone()
        }
    }

    /// The options of the edge-to-edge part, as Radioss passes them (card
    /// Igap 2 → 1, 4 → constant; Istf 1000 → 5; Gapmin × Edge_scale_gap;
    /// no Ifric law, Fscalegap, Gapmax, Ibag, Icurv).
    pub fn edge_part(&self) -> Type11 {
        let t = &self.nodes;
        let (s, m) = self.surfaces();
        let thermal = t.thermal.as_ref().map(|h| super::Type11Thermal {
            kthe: h.kthe,
            fct_idk: h.fct_idk,
            ascalek: h.ascalek,
            tint: h.tint,
            ithe_form: h.ithe_form,
            frad: h.frad,
            drad: h.drad,
        });
        Type11 {
            line_ids: s,
            line_idm: m,
            istf: if t.istf == 1000 || t.istf == 0 {
                5
            } else {
                t.istf
            },
            ithe: t.ithe,
            igap: match self.igap {
                1 | 2 => 1,
                3 => 3,
                _ => 1000,
            },
            irem_gap: if t.irem_gap == 2 && self.igap != 4 {
                2
            } else {
                1
            },
            idel: t.idel,
            stmin: t.stmin,
            stmax: t.stmax,
            mesh_size_pct: t.mesh_size_pct,
            dtmin: t.dtmin,
            iform: t.iform,
            sens_id: t.sens_id,
            stfac: t.stfac,
            fric: t.fric,
            gapmin: if self.edge_scale_gap != 0.0 {
                t.gapmin * self.edge_scale_gap
            } else {
                t.gapmin
            },
            tstart: t.tstart,
            tstop: t.tstop,
            ibc: t.ibc,
            inacti: t.inacti,
            viss: t.viss,
            visf: t.visf,
            bumult: t.bumult,
            fric_id: t.fric_id,
            thermal,
            dyna: t.dyna,
            penalty25: None,
        }
    }
}
