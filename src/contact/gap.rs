//! Contact gap: the TYPE7 default minimum gap, the variable gap (Igap 1, 2, 3)
//! and the treatments of initial penetrations (Inacti, Fpenmax).
//!
//! Source: /INTER/TYPE7 card, comments 9–11 and 13; theory manual §8.8.6–8.8.8.

/// TYPE7 default Gapmin (card comment 10): with shells on the main side,
/// min(t, l_min/2) where t is the mean main shell thickness (Igap = 0) or the
/// smallest one (Igap = 1, 2, 3); with only solids, l_min/10. `l_min` is the
/// smallest edge of all main segments.
pub fn type7_default_gapmin(shell_thickness: Option<f64>, l_min: f64) -> f64 {
    match shell_thickness {
        Some(t) => t.min(0.5 * l_min),
        None => 0.1 * l_min,
    }
}

/// What decides a pair's gap.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct GapRule {
    /// Igap: 1000 constant; 1, 2, 3 variable.
    pub igap: i64,
    pub gapmin: f64,
    pub fscalegap: f64,
    /// 1e30 = none (Gapmax = 0 on the card).
    pub gapmax: f64,
    pub mesh_size_pct: f64,
}

impl GapRule {
    /// Gap of a pair from the secondary and main element gaps g_s, g_m (half
    /// thicknesses) and their smallest edges g_s_l, g_m_l (card eq. (8)–(10)).
    pub fn pair_gap(&self, gs: f64, gm: f64, gs_l: f64, gm_l: f64) -> f64 {
        match self.igap {
            1 => self.gapmin.max(gs + gm),
            2 => self
                .gapmin
                .max((self.fscalegap * (gs + gm)).min(self.gapmax)),
            3 => self.gapmin.max(
                (self.fscalegap * (gs + gm))
                    .min(self.mesh_size_pct * (gs_l + gm_l))
                    .min(self.gapmax),
            ),
            _ => self.gapmin,
        }
    }

    /// The largest gap any pair can have (for the search reach).
    pub fn max_gap(&self, gs_max: f64, gm_max: f64) -> f64 {
        match self.igap {
            1 => self.gapmin.max(gs_max + gm_max),
            2 | 3 => self
                .gapmin
                .max((self.fscalegap * (gs_max + gm_max)).min(self.gapmax)),
            _ => self.gapmin,
        }
    }
}

/// What happens to a pair found penetrated at the first sort (Inacti, Fpenmax).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum InitialPenetration {
    /// Inacti 0/1000: nothing; the node is pushed out by the full reaction.
    Keep,
    /// Inacti = 1 or Fpenmax exceeded: the node's stiffness is deactivated.
    DeactivateNode,
    /// Inacti = 2: the segment's stiffness is deactivated for this node.
    DeactivateSegment,
    /// Inacti = 3: the node is moved out of the gap before the first cycle.
    MoveNode,
    /// Inacti = 5, 6: the pair gets a reduced gap (see [`initial_gap`]).
    ReduceGap,
}

/// Decision for an initial penetration `p0` in gap `g` (card comment 13:
/// "if Fpenmax ≠ 0, node stiffness is deactivated if P ≥ Fpenmax·Gap whatever Inacti").
pub fn initial_penetration(inacti: i64, fpenmax: f64, p0: f64, g: f64) -> InitialPenetration {
    if p0 <= 0.0 {
        return InitialPenetration::Keep;
    }
    if fpenmax > 0.0 && p0 >= fpenmax * g {
        return InitialPenetration::DeactivateNode;
    }
    match inacti {
        1 => InitialPenetration::DeactivateNode,
        2 => InitialPenetration::DeactivateSegment,
        3 => InitialPenetration::MoveNode,
        5 | 6 => InitialPenetration::ReduceGap,
        _ => InitialPenetration::Keep,
    }
}

/// Reduced gap of an initially penetrated pair (card Inacti):
/// Inacti = 5: gap0 = Gap − P0; Inacti = 6: gap0 = Gap − P0 − 5%·(Gap − P0)
/// (the node is slightly depenetrated, so it starts with no force).
pub fn initial_gap(inacti: i64, g: f64, p0: f64) -> f64 {
    let d0 = g - p0;
    if inacti == 6 {
        d0 - 0.05 * d0
    } else {
        d0
    }
}

/// The corrected gap follows the node back out (§8.8.8: "if the node
/// penetration decreases, the correction is reduced"): it grows with the
/// current distance less the clearance the node was given (0 with Inacti = 5,
/// 5% of its initial distance with Inacti = 6, so that the clearance is not
/// lost at the first cycle), never beyond the nominal gap.
pub fn relax_gap(current: f64, nominal: f64, dist: f64, clearance: f64) -> f64 {
    nominal.min(current.max(dist - clearance))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn default_gapmin_matches_the_qa_starter_listings() {
        // INT357 interface 10: shells t = 0.0045, smallest edge 20 → 4.5e-3.
        assert_eq!(type7_default_gapmin(Some(0.0045), 20.0), 0.0045);
        // BOULE1V4 interface 1: t = 1, smallest edge √0.52 → 0.3605551275.
        let g = type7_default_gapmin(Some(1.0), 0.52f64.sqrt());
        assert!((g - 0.3605551275464).abs() < 1e-9);
        assert_eq!(type7_default_gapmin(None, 2.0), 0.2);
    }

    #[test]
    fn variable_gap_rules() {
        let r = GapRule {
            igap: 1,
            gapmin: 0.1,
            fscalegap: 0.5,
            gapmax: 0.3,
            mesh_size_pct: 0.4,
        };
        assert_eq!(r.pair_gap(0.5, 0.25, 1.0, 1.0), 0.75);
        assert_eq!(r.pair_gap(0.0, 0.0, 1.0, 1.0), 0.1);
        let r2 = GapRule { igap: 2, ..r };
        assert_eq!(r2.pair_gap(0.5, 0.25, 1.0, 1.0), 0.3);
        assert!((r2.pair_gap(0.2, 0.1, 1.0, 1.0) - 0.15).abs() < 1e-15);
        let r3 = GapRule {
            igap: 3,
            gapmax: 1e30,
            ..r
        };
        assert!((r3.pair_gap(0.5, 0.5, 0.2, 0.1) - 0.12).abs() < 1e-15);
        let r0 = GapRule { igap: 1000, ..r };
        assert_eq!(r0.pair_gap(0.5, 0.5, 1.0, 1.0), 0.1);
    }

    #[test]
    fn initial_penetration_options() {
        use InitialPenetration::*;
        assert_eq!(initial_penetration(1000, 0.0, 0.01, 0.1), Keep);
        assert_eq!(initial_penetration(1, 0.0, 0.01, 0.1), DeactivateNode);
        assert_eq!(initial_penetration(2, 0.0, 0.01, 0.1), DeactivateSegment);
        assert_eq!(initial_penetration(3, 0.0, 0.01, 0.1), MoveNode);
        assert_eq!(initial_penetration(5, 0.0, 0.01, 0.1), ReduceGap);
        assert_eq!(initial_penetration(5, 0.5, 0.06, 0.1), DeactivateNode);
        assert_eq!(initial_penetration(5, 0.0, 0.0, 0.1), Keep);
        assert!((initial_gap(5, 0.1, 0.04) - 0.06).abs() < 1e-15);
        assert!((initial_gap(6, 0.1, 0.04) - 0.057).abs() < 1e-15);
        assert_eq!(relax_gap(0.06, 0.1, 0.08, 0.0), 0.08);
        assert_eq!(relax_gap(0.06, 0.1, 0.2, 0.0), 0.1);
        assert_eq!(relax_gap(0.06, 0.1, 0.05, 0.0), 0.06);
        // Inacti = 6 at rest: distance 0.06, gap 0.057, clearance 0.003: unchanged.
        assert!((relax_gap(0.057, 0.1, 0.06, 0.003) - 0.057).abs() < 1e-15);
        assert!((relax_gap(0.057, 0.1, 0.07, 0.003) - 0.067).abs() < 1e-15);
    }
}
