//! TYPE24 penalty node-to-surface contact (reference card /INTER/TYPE24;
//! docs/notes/type24_type25_research.md §1.2, §2.5, §4 and
//! docs/notes/type24_reference_answers.md). Its kernel is TYPE25's
//! (`type25`): the same stiffness (EQ. 8.5.3.2/8.5.3.3 with Istf), ½·K·p
//! with the no-force-jump secant, the VISs damper on the harmonic mean of
//! the masses (the reference fixes IVIS2 = 1), incremental Coulomb friction
//! with the full K, one segment per node, Idel, dormant faces between two
//! solids. What differs:
//!
//! - a new impact (`type25::Impact::Full`): no baseline, the full stiffness
//!   at once (the secant applies from the next cycle in contact); a node
//!   found penetrated before the first step feels nothing until it leaves
//!   that contact (the reference flags it, i24pen3.F). With Inacti 5 the
//!   penetration at each new impact is the baseline, as TYPE25's;
//! - the gap is the shells' half thickness unscaled (Igap 1 is forced, no
//!   Gap_scale), each side capped by Gap_max_s, Gap_max_m;
//! - Istf 7: no standard stiffness, only the mass and time-step stiffness
//!   Stfac_mdt·m*/Δt² (IPSTIF forced to 1);
//! - the reference detects a new impact by the node's crossing during the
//!   step (i24dst3.F); here, as for TYPE25, by the closest point.
//!
//! Refused by name: Istf 1, 6 and 12-14 (a constant stiffness, the implicit
//! adjustment, Nitsche), Iedge (edges as fictitious nodes), Inacti −1, 1, 3
//! (press-fit and the starter's treatments), Ipen_max, Ipen0 = 1, friction
//! laws and filters, /FRICTION, sensors.

use super::layout::{Interface, Pass};
use super::type25::{penalty_common, Impact, Type25 as Kernel};
use crate::model::contact::Penalty25;
use super::{
    CandidateKind, CandidateSearch, CardCommon, InterfaceType, NodeState, PairContext, PairForce,
    PairOutcome, PairState, SurfaceSizes,
};
use crate::contact::gap::{GapRule, InitialPenetration};
use crate::contact::geometry::V3;
use crate::model::{self, InterfaceKind};
use serde::{Deserialize, Serialize};

/// TYPE24's options: TYPE25's kernel with TYPE24's card.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Type24 {
    kernel: Kernel,
}

impl InterfaceType for Type24 {
    fn type_number(&self) -> u32 {
        24
    }

    fn unsupported(kind: &InterfaceKind) -> Option<&'static str> {
        let InterfaceKind::Type24(t) = kind else {
            return None;
        };
        let refused = [
            (t.istf == 1, "a constant stiffness (Istf = 1)"),
            (t.istf == 6, "the implicit stiffness adjustment (Istf = 6)"),
            (matches!(t.istf, 12..=14), "the Nitsche method (Istf 12-14)"),
            (t.iedge != 1000, "edge contact through fictitious nodes (Iedge)"),
            (
                !matches!(t.inacti, 5 | 1000),
                "an initial-penetration treatment other than the baseline (Inacti -1, 1, 3)",
            ),
            (t.ipen0 == 1, "initial penetrations within a part (Ipen0 = 1)"),
            (t.ipen_max > 0.0, "a largest initial penetration (Ipen_max)"),
            (t.sens_id != 0, "an activation sensor (sens_ID)"),
            (t.fric_id != 0, "friction from /FRICTION (fric_ID)"),
            (t.ifric != 0 || t.ifiltr != 0, "a friction law or filter (Ifric, Ifiltr)"),
        ];
        refused.into_iter().find(|r| r.0).map(|r| r.1)
    }

    fn candidate_kind(&self) -> CandidateKind {
        CandidateKind::NodeToSegment
    }

    fn search(&self) -> CandidateSearch {
        CandidateSearch::Sort
    }

    fn from_card(kind: &InterfaceKind) -> Option<(Self, CardCommon)> {
        let InterfaceKind::Type24(t) = kind else {
            return None;
        };
        let common = penalty_common(t.stfac, t.fric, (t.tstart, t.tstop), t.ibc, t.inacti, t.idel);
        let mass_stiffness = t.ipstif == 1 || t.istf == 7;
        let kernel = Kernel {
            law: Penalty25 {
                istf: t.istf,
                stmin: t.stmin,
                stmax: t.stmax,
                viss: t.viss,
                ivis2: 1,
                gap_scale: 1.0,
                gap_max_s: t.gap_max_s,
                gap_max_m: t.gap_max_m,
            },
            mass_stiffness: mass_stiffness.then_some((t.stfac_mdt, t.dtstif)),
            igap0: t.igap0 == 1,
            impact: if t.inacti == 5 {
                Impact::Baseline
            } else {
                Impact::Full
            },
            // TYPE24 removes no neighbours by distance (its Irem_i2 is the
            // tied nodes of TYPE2: docs/notes/irem_gap2_research.md Q5).
            remove_close: false,
            mesh_gap: None,
        };
        Some((Type24 { kernel }, common))
    }

    fn passes<'a>(&self, i: &'a model::Interface) -> Vec<super::PassSides<'a>> {
        self.kernel.passes(i)
    }

    fn gap_rule(&self, common: &CardCommon, sizes: &SurfaceSizes) -> GapRule {
        self.kernel.gap_rule(common, sizes)
    }

    fn sorting_margin(&self) -> f64 {
        self.kernel.sorting_margin()
    }

    fn zero_gap_on_free_shell_edges(&self) -> bool {
        self.kernel.zero_gap_on_free_shell_edges()
    }

    fn inner_solid_faces_as_segments(&self) -> bool {
        self.kernel.inner_solid_faces_as_segments()
    }

    fn solid_segment_stiffness(&self, bulk: f64, area: f64, volume: f64) -> f64 {
        self.kernel.solid_segment_stiffness(bulk, area, volume)
    }

    fn pair_stiffness(&self, it: &Interface, p: &Pass, k: usize, m: usize) -> f64 {
        self.kernel.pair_stiffness(it, p, k, m)
    }

    fn one_segment_per_node(&self) -> bool {
        self.kernel.one_segment_per_node()
    }

    /// As TYPE25: with Istf > 1 the reference starter gives each secondary
    /// node Stfac·STIFINT, its assembled stiffness (ININTR1 → I24STSECND,
    /// i24stslav.F); Istf 0, 1, 1000 never read it, Istf 7 takes the mass
    /// and time-step stiffness alone.
    fn assembled_node_stiffness(&self) -> bool {
        true
    }

    fn nearness(&self, c: &PairContext, side: i8) -> Option<(f64, i8)> {
        self.kernel.nearness(c, side)
    }

    #[inline]
    fn pair(&self, c: &PairContext, ns: &mut NodeState, st: &mut PairState) -> PairOutcome {
        self.kernel.pair(c, ns, st)
    }

    fn kinematic_step(&self, f: &PairForce) -> Option<f64> {
        self.kernel.kinematic_step(f)
    }

    fn initial_penetration(
        &self,
        it: &Interface,
        xs: V3,
        xm: &[V3; 4],
        tri: bool,
        g: f64,
    ) -> (InitialPenetration, f64) {
        self.kernel.initial_penetration(it, xs, xm, tri, g)
    }
}
