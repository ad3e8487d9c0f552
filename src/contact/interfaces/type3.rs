//! TYPE3 surface-to-surface contact (theory manual §8.5): two passes, the
//! nodes of each surface against the segments of the other, each pass
//! computed as TYPE5 (`type5.rs`: the closest-segment walk, one-sided
//! penetration, a linear spring) with the stiffness of the two surfaces in
//! series, K = s·K1·K2/(K1 + K2) (EQ. 8.5.3.1), K1 the stiffness of the
//! secondary node's own surface and K2 the main segment's.

use std::borrow::Cow;
use super::type5;
use super::{
    CandidateKind, CandidateSearch, CardCommon, InterfaceType, NodeState, PairContext, PairOutcome,
    PairState, PassSides, SurfaceSizes,
};
use crate::contact::friction::FrictionLaw;
use crate::contact::gap::{GapRule, InitialPenetration};
use crate::contact::geometry::V3;
use super::layout::{Interface, Pass};
use crate::contact::stiffness;
use crate::model::InterfaceKind;
use crate::model;
use serde::{Deserialize, Serialize};

/// TYPE3 has no options of its own beyond the common ones (Stfac, Fric,
/// Gap, Tstart/Tstop, IBC, Idel; no Inacti: 0).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Type3 {}

/// The nodes of `segs`, ascending.
pub(super) fn nodes_of(segs: &[[u32; 4]]) -> Vec<u32> {
    crate::model::distinct_nodes(segs.iter().flatten().copied())
}

impl InterfaceType for Type3 {
    fn type_number(&self) -> u32 {
        3
    }

    fn candidate_kind(&self) -> CandidateKind {
        CandidateKind::NodeToSegment
    }

    fn search(&self) -> CandidateSearch {
        CandidateSearch::Walk
    }

    fn from_card(kind: &InterfaceKind) -> Option<(Self, CardCommon)> {
        let InterfaceKind::Type3(t) = kind else {
            return None;
        };
        let common = CardCommon {
            stfac: t.stfac,
            friction: FrictionLaw {
                fric: t.fric,
                ..FrictionLaw::none()
            },
            gap_card: t.gap,
            tstart: t.tstart,
            tstop: t.tstop,
            ibc: t.ibc,
            inacti: 0,
            idel: t.idel,
        };
        Some((Type3 {}, common))
    }

    /// Surface 1's nodes against surface 2, then surface 2's against surface 1;
    /// each node's stiffness is its own surface's.
    fn passes<'a>(&self, i: &'a model::Interface) -> Vec<PassSides<'a>> {
        vec![
            PassSides {
                sec: nodes_of(&i.secondary_segments),
                own: Some(&i.secondary_segments),
                main: &i.main_segments,
                sec_edges: &[],
                main_edges: &[],
                sec_segs: Cow::Borrowed(&[]),
                self_contact: false,
            },
            PassSides {
                sec: nodes_of(&i.main_segments),
                own: Some(&i.main_segments),
                main: &i.secondary_segments,
                sec_edges: &[],
                main_edges: &[],
                sec_segs: Cow::Borrowed(&[]),
                self_contact: false,
            },
        ]
    }

    fn gap_rule(&self, common: &CardCommon, _sizes: &SurfaceSizes) -> GapRule {
        type5::constant_gap(common.gap_card)
    }

    fn sorting_margin(&self) -> f64 {
        type5::DEFAULT_BUMULT
    }

    /// EQ. 8.5.3.3.
    fn solid_segment_stiffness(&self, bulk: f64, area: f64, volume: f64) -> f64 {
        stiffness::brick_type3(bulk, area, volume)
    }

    /// s·K1·K2/(K1 + K2) (EQ. 8.5.3.1).
    fn pair_stiffness(&self, it: &Interface, p: &Pass, k: usize, m: usize) -> f64 {
        it.stfac * stiffness::series(p.sec_k[k], p.seg_k[m])
    }

    fn walk(
        &self,
        it: &Interface,
        p: &Pass,
        s0: u32,
        xs: V3,
        x_of: &dyn Fn(u32) -> Option<V3>,
        seg_on: &dyn Fn(u32) -> bool,
    ) -> Option<u32> {
        type5::walk(p, s0, xs, type5::walk_reach(it, p), x_of, seg_on)
    }

    fn walk_reach(&self, max_diag: f64) -> f64 {
        2.0 * max_diag
    }

    #[inline]
    fn pair(&self, c: &PairContext, _ns: &mut NodeState, st: &mut PairState) -> PairOutcome {
        let k = self.pair_stiffness(c.it, c.p, c.k, c.m as usize);
        type5::kernel(c, k, st)
    }

    fn initial_penetration(
        &self,
        it: &Interface,
        xs: V3,
        xm: &[V3; 4],
        tri: bool,
        g: f64,
    ) -> (InitialPenetration, f64) {
        type5::initial_penetration(it, xs, xm, tri, g)
    }
}
