//! TYPE6 rigid body contact (theory manual §8.7): two surfaces, each on one
//! rigid body, searched as TYPE3 (`type3.rs`: the nodes of each surface
//! against the segments of the other, the closest-segment walk, one-sided
//! penetration), but the interface's total normal force is a user function
//! of the largest penetration, F = FscaleId·f(p_max/Ascalex), shared by the
//! penetrated nodes in proportion to their penetration vectors
//! (EQ. 8.7.6.1):
//!
//!   F_i = p̄_i / ‖Σ p̄_j − Σ q̄_k‖ · F(max p)
//!
//! (p̄ the penetration vectors of surface 1's nodes, q̄ those of surface 2's
//! nodes, counted on surface 1). The runtime measures every pair, reduces
//! p_max and the resultant over all ranks, then computes the forces
//! (`InterfaceType::is_total_force`). On top of the elastic share, each
//! penetrated node takes a normal damper −Visc·v_n (the card's Visc, along
//! the normal, never pulling) and Coulomb friction as TYPE3's (EQ.
//! 8.5.4.1–4: incremental, K_t = K_n/10 with K_n = F/‖R‖ the node's normal
//! force per unit penetration, capped at Fric·F_n).
//!
//! Time step (EQ. 8.7.5.1–2): Δt = 0.1·√(M/K), M the smaller of the two
//! rigid bodies' masses, K the larger of the tangent FscaleId/Ascalex·f′
//! and the secant F/p at the largest penetration (the tangent at 0 while
//! nothing penetrates, so the step is already small at the first impact).
//! The stiffness goes to no node's own step: the nodes move with their
//! bodies.

use super::type3::{nodes_of, Type3};
use super::type5;
use super::{
    CandidateKind, CandidateSearch, CardCommon, InterfaceType, NodeState, PairContext, PairForce,
    PairOutcome, PairState, PassSides, SurfaceSizes, NODE_SHAPE,
};
use super::layout::{Interface, Pass};
use crate::contact::friction::{self, FrictionLaw};
use crate::contact::gap::GapRule;
use crate::contact::geometry::{self as geo, V3};
use crate::kinematics::function;
use crate::model::{self, Function, InterfaceKind};
use serde::{Deserialize, Serialize};

/// TYPE6's own options; the load curve and the body mass are bound from
/// the model (`bind`).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Type6 {
    pub fct_id_ld: model::Id,
    /// The loading curve f(p) (fct_IDld).
    pub load: Option<Function>,
    pub ascalex: f64,
    pub fscale_ld: f64,
    /// Visc: damping force per unit normal velocity, per penetrated node.
    pub visc: f64,
    /// The smaller of the two rigid bodies' masses (EQ. 8.7.5.1).
    pub body_mass: f64,
    /// Iform: 0 elastic (one curve both ways); 1 unloading along Stiff down
    /// to the unloading curve; 2 down to zero.
    #[serde(default)]
    pub iform: i64,
    /// Stiff: the slope of unloading and reloading between the curves.
    #[serde(default)]
    pub stiff: f64,
    pub fct_id_ul: model::Id,
    /// The unloading curve (fct_IDul, Iform 1) and its ordinate scale.
    pub unload: Option<Function>,
    #[serde(default)]
    pub fscale_ul: f64,
    /// The node curves' ids (fct_IDff, fct_IDfv, fct_IDdv, fct_IDdf; 0:
    /// none) and the curves `bind` finds for them.
    #[serde(default)]
    pub node_fct_ids: [model::Id; 4],
    #[serde(default)]
    pub node_curves: NodeCurves,
    /// Ascalef, Ascalev: the abscissa scales of the normal-force and the
    /// velocity arguments; Fscalev: fct_IDdv's ordinate scale.
    #[serde(default)]
    pub ascalef: f64,
    #[serde(default)]
    pub ascalev: f64,
    #[serde(default)]
    pub fscalev: f64,
}

/// TYPE6's curves of a penetrated node's friction and damping (reference
/// guide /INTER/TYPE6; research note type6_type14_type15_research.md §2.1),
/// each of the node's normal force F (its share of the curve's force) over
/// Ascalef or of a speed over Ascalev:
/// μ = Fric·g_ff(F/Ascalef)·g_fv(v_t/Ascalev), and the normal damper
/// −[Visc·v_n + Fscalev·g_dv(v_n/Ascalev)]·g_df(F/Ascalef). A missing
/// factor counts 1, a missing g_dv 0.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct NodeCurves {
    pub friction_of_force: Option<Function>,
    pub friction_of_speed: Option<Function>,
    pub damping_of_speed: Option<Function>,
    pub damping_of_force: Option<Function>,
}

impl Type6 {
    /// FscaleId·f(p/Ascalex) and its slope in p.
    fn curve(&self, p: f64) -> (f64, f64) {
        match &self.load {
            Some(f) => function::scaled_with_slope(f, p, self.ascalex, self.fscale_ld),
            None => (0.0, 0.0),
        }
    }

    /// Iform 1/2 (the reference engine's rule, docs/notes/
    /// type6_type14_type15_research.md §2.1): from the last (p, F), load
    /// along Stiff up to the loading curve, F = min(f_ld(p), F' + Stiff·Δp),
    /// or unload along Stiff down to the unloading curve (Iform 1:
    /// Fscaleul·f_ul(p/Ascalex)) or to zero (Iform 2),
    /// F = max(f_ul(p), F' + Stiff·Δp). The memory is dropped when the
    /// surfaces separate (the reference keeps F', which would make the next
    /// impact start at it). Returns F and whether it is on a Stiff line.
    fn hysteresis(&self, p: f64, f_ld: f64, memory: &mut [f64; 2]) -> (f64, bool) {
        if p <= 0.0 {
            *memory = [0.0; 2];
            return (0.0, false);
        }
        let [p_prev, f_prev] = *memory;
        let along = f_prev + self.stiff * (p - p_prev);
        let f = if p >= p_prev {
            f_ld.min(along)
        } else {
            let f_ul = match (&self.unload, self.iform) {
                (Some(u), 1) => function::scaled(u, p, self.ascalex, self.fscale_ul),
                _ => 0.0,
            };
            f_ul.max(along)
        };
        *memory = [p, f];
        (f, f == along)
    }

    /// The normal damper of a penetrated node of elastic share `f_e` and
    /// normal speed `v_n` (positive leaving): −[Visc·v_n +
    /// Fscalev·g_dv(v_n/Ascalev)]·g_df(f_e/Ascalef), added to f_e.
    fn damper(&self, f_e: f64, v_n: f64) -> f64 {
        let c = &self.node_curves;
        if self.visc == 0.0 && c.damping_of_speed.is_none() {
            return 0.0;
        }
        let of_speed = self.fscalev * super::curve_at(&c.damping_of_speed, v_n, self.ascalev, 0.0);
        let factor = super::curve_at(&c.damping_of_force, f_e, self.ascalef, 1.0);
        -(self.visc * v_n + of_speed) * factor
    }

    /// μ's factor at a node of elastic share `f_e` sliding at `speed`:
    /// g_ff(f_e/Ascalef)·g_fv(speed/Ascalev).
    fn friction_factor(&self, f_e: f64, speed: f64) -> f64 {
        let c = &self.node_curves;
        super::curve_at(&c.friction_of_force, f_e, self.ascalef, 1.0)
            * super::curve_at(&c.friction_of_speed, speed, self.ascalev, 1.0)
    }
}

/// The rigid body that holds every node of `segs`, by index.
fn body_of(m: &model::Model, segs: &[[u32; 4]]) -> Option<usize> {
    let nodes = nodes_of(segs);
    m.rigid_bodies
        .iter()
        .position(|b| nodes.iter().all(|&n| b.holds(n)))
}

impl InterfaceType for Type6 {
    fn type_number(&self) -> u32 {
        6
    }

    fn candidate_kind(&self) -> CandidateKind {
        CandidateKind::NodeToSegment
    }

    fn search(&self) -> CandidateSearch {
        CandidateSearch::Walk
    }

    fn from_card(kind: &InterfaceKind) -> Option<(Self, CardCommon)> {
        let InterfaceKind::Type6(t) = kind else {
            return None;
        };
        let common = CardCommon {
            stfac: 1.0,
            friction: FrictionLaw {
                fric: t.fric,
                ..FrictionLaw::none()
            },
            gap_card: t.gap,
            tstart: t.tstart,
            tstop: t.tstop,
            ibc: [false; 3],
            inacti: 0,
            idel: 0,
        };
        let own = Type6 {
            fct_id_ld: t.fct_id_ld,
            load: None,
            ascalex: t.ascalex,
            fscale_ld: t.fscale_ld,
            visc: t.visc,
            body_mass: 0.0,
            iform: t.iform,
            stiff: t.stiff,
            fct_id_ul: t.fct_id_ul,
            unload: None,
            fscale_ul: t.fscale_ul,
            node_fct_ids: [t.fct_id_ff, t.fct_id_fv, t.fct_id_dv, t.fct_id_df],
            node_curves: NodeCurves::default(),
            ascalef: t.ascalef,
            ascalev: t.ascalev,
            fscalev: t.fscalev,
        };
        Some((own, common))
    }

    fn unsupported(kind: &InterfaceKind) -> Option<&'static str> {
        let InterfaceKind::Type6(t) = kind else {
            return None;
        };
        if t.sfric != 0.0 {
            Some("a static friction force (Sfric)")
        } else if t.icor != 0 {
            Some("the force correction of an initial intersection (Icor = 1)")
        } else if t.inacti != 0 {
            Some("Inacti = 5 (variable gap for initial penetrations)")
        } else {
            None
        }
    }

    /// The load curve, and the two rigid bodies: each surface must lie on
    /// one rigid body (§8.7.1), and not the same one.
    fn bind(&mut self, m: &model::Model, i: &model::Interface, kw: &str) -> Result<(), String> {
        self.load = Some(super::bound_curve(m, self.fct_id_ld, kw, "fct_IDld")?);
        if self.iform == 1 && self.fct_id_ul != 0 {
            self.unload = Some(super::bound_curve(m, self.fct_id_ul, kw, "fct_IDul")?);
        }
        let [ff, fv, dv, df] = self.node_fct_ids;
        let curve = |id: model::Id, field: &str| super::optional_curve(m, id, kw, field);
        self.node_curves = NodeCurves {
            friction_of_force: curve(ff, "fct_IDff")?,
            friction_of_speed: curve(fv, "fct_IDfv")?,
            damping_of_speed: curve(dv, "fct_IDdv")?,
            damping_of_force: curve(df, "fct_IDdf")?,
        };
        let mut bodies = [0usize; 2];
        for (b, (segs, field)) in bodies.iter_mut().zip([
            (&i.secondary_segments, "surf_ID1"),
            (&i.main_segments, "surf_ID2"),
        ]) {
            *b = body_of(m, segs).ok_or_else(|| {
                format!(
                    "{kw}, field {field}: every node of a TYPE6 surface must belong to one \
                     /RBODY (theory manual §8.7.1); this surface's nodes are not all on one"
                )
            })?;
        }
        if bodies[0] == bodies[1] {
            return Err(format!(
                "{kw}, fields surf_ID1 and surf_ID2: both surfaces are on /RBODY/{}: \
                 expected two different rigid bodies (theory manual §8.7.1)",
                m.rigid_bodies[bodies[0]].card.id
            ));
        }
        self.body_mass = bodies
            .iter()
            .map(|&b| m.rigid_bodies[b].mass)
            .fold(f64::INFINITY, f64::min);
        Ok(())
    }

    /// Surface 1's nodes against surface 2, then surface 2's against surface 1.
    fn passes<'a>(&self, i: &'a model::Interface) -> Vec<PassSides<'a>> {
        Type3 {}.passes(i)
    }

    fn gap_rule(&self, common: &CardCommon, _sizes: &SurfaceSizes) -> GapRule {
        type5::constant_gap(common.gap_card)
    }

    fn sorting_margin(&self) -> f64 {
        type5::DEFAULT_BUMULT
    }

    /// Not used: the force is the load curve's.
    fn solid_segment_stiffness(&self, bulk: f64, area: f64, volume: f64) -> f64 {
        crate::contact::stiffness::brick_type3(bulk, area, volume)
    }

    fn pair_stiffness(&self, _it: &Interface, _p: &Pass, _k: usize, _m: usize) -> f64 {
        0.0
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

    fn is_total_force(&self) -> bool {
        true
    }

    /// Pass 2's nodes are surface 2's: their vectors count with the
    /// opposite sign on surface 1 (EQ. 8.7.6.1, −Σ q̄_k).
    fn resultant_sign(&self, pass: usize) -> f64 {
        if pass == 0 {
            1.0
        } else {
            -1.0
        }
    }

    /// F(p_max) and Δt = 0.1·√(M/K) (EQ. 8.7.5.1–2).
    fn total_force(&self, p_max: f64, memory: &mut [f64; 2]) -> (f64, f64) {
        let (f_ld, tangent) = self.curve(p_max.max(0.0));
        let (f, on_stiff) = if self.iform == 0 {
            (if p_max > 0.0 { f_ld.max(0.0) } else { 0.0 }, false)
        } else {
            self.hysteresis(p_max, f_ld.max(0.0), memory)
        };
        let secant = if p_max > 0.0 { f / p_max } else { 0.0 };
        // On a Stiff line the force moves with Stiff: the step must see it
        // (the reference takes the curve's tangent and the secant only).
        let k = tangent.max(secant).max(if on_stiff { self.stiff } else { 0.0 });
        let dt = if k > 0.0 && self.body_mass > 0.0 {
            0.1 * (self.body_mass / k).sqrt()
        } else {
            f64::INFINITY
        };
        (f, dt)
    }

    #[inline]
    fn pair(&self, c: &PairContext, _ns: &mut NodeState, st: &mut PairState) -> PairOutcome {
        let m = c.m as usize;
        let tri = c.p.is_tri(m);
        let Some((pen, pr)) = type5::penetration(c.xs, c.xm, tri, c.it.gap.gapmin) else {
            return PairOutcome::Free;
        };
        if pen <= 0.0 {
            if c.scale.is_some() {
                st.ft = [0.0; 3];
            }
            return PairOutcome::Free;
        }
        let n = pr.normal;
        let Some(fac) = c.scale else {
            // Measuring: the penetration vector.
            return PairOutcome::Force(PairForce {
                fs: geo::scale(n, pen),
                sec_shape: NODE_SHAPE,
                shape: pr.shape,
                dt_kin: f64::INFINITY,
                f_n: pen,
                pen,
                dir: n,
                point: pr.point,
                ..Default::default()
            });
        };
        let vrel = geo::sub(c.vs, geo::interpolate(&pr.shape, c.vm));
        let f_e = fac * pen;
        let f_n = (f_e + self.damper(f_e, geo::dot(vrel, n))).max(0.0);
        let law = &c.it.friction;
        let f_t = if law.active() && f_n > 0.0 {
            let vt = friction::tangential(vrel, n);
            let speed = geo::norm(vt);
            let mu = law.mu(0.0, speed) * self.friction_factor(f_e, speed);
            friction::tangential_force(law, mu, f_n, vt, n, 0.1 * fac, 0.0, c.dt, &mut st.ft)
        } else {
            st.ft = [0.0; 3];
            [0.0; 3]
        };
        PairOutcome::Force(PairForce {
            fs: geo::add(geo::scale(n, f_n), f_t),
            sec_shape: NODE_SHAPE,
            shape: pr.shape,
            kt: 0.0,
            dt_kin: f64::INFINITY,
            f_n,
            f_t,
            pen,
            dir: n,
            point: pr.point,
        })
    }

    // Initial penetration: kept (the trait's default): an initial
    // intersection is simply part of p_max (Icor = 0).
}

#[cfg(test)]
mod tests {
    use super::*;

    fn linear(k: f64) -> Type6 {
        Type6 {
            fct_id_ld: 1,
            load: Some(Function {
                id: 1,
                title: String::new(),
                x: vec![0.0, 1.0],
                y: vec![0.0, k],
                loc: Default::default(),
            }),
            ascalex: 0.5,
            fscale_ld: 2.0,
            visc: 0.0,
            body_mass: 4.0,
            iform: 0,
            stiff: 0.0,
            fct_id_ul: 0,
            unload: None,
            fscale_ul: 1.0,
            node_fct_ids: [0; 4],
            node_curves: NodeCurves::default(),
            ascalef: 1.0,
            ascalev: 1.0,
            fscalev: 1.0,
        }
    }

    /// F = FscaleId·f(p/Ascalex); Δt = 0.1·√(M/K) with K the tangent
    /// FscaleId/Ascalex·f′ (EQ. 8.7.5.1), also before any penetration.
    #[test]
    fn the_total_force_and_step_follow_the_scaled_curve() {
        let t = linear(100.0);
        let mut memory = [0.0; 2];
        let (f, dt) = t.total_force(0.01, &mut memory);
        assert!((f - 2.0 * 100.0 * 0.02).abs() < 1e-12);
        assert!((dt - 0.1 * (4.0f64 / 400.0).sqrt()).abs() < 1e-15);
        let (f0, dt0) = t.total_force(0.0, &mut memory);
        assert_eq!(f0, 0.0);
        assert_eq!(dt0, dt);
        assert_eq!(t.resultant_sign(0), 1.0);
        assert_eq!(t.resultant_sign(1), -1.0);
    }

    /// Iform 2: loading on the curve, unloading along Stiff to zero,
    /// reloading along Stiff back to the curve; Iform 1 stops unloading on
    /// the unloading curve. The memory is dropped at separation.
    #[test]
    fn iform_unloads_and_reloads_along_stiff_between_the_curves() {
        // f_ld = 2·100·(p/0.5) = 400 p; Stiff 4000.
        let mut t = linear(100.0);
        t.iform = 2;
        t.stiff = 4000.0;
        let mut m = [0.0; 2];
        let f = |t: &Type6, p: f64, m: &mut [f64; 2]| t.total_force(p, m).0;
        // Loading from 0: along Stiff until it meets the curve (one step).
        assert!((f(&t, 0.01, &mut m) - 4.0).abs() < 1e-12);
        assert!((f(&t, 0.02, &mut m) - 8.0).abs() < 1e-12);
        // Unloading by 0.001: 8 − 4000·0.001 = 4; the step sees Stiff.
        let (fu, dt) = t.total_force(0.019, &mut m);
        assert!((fu - 4.0).abs() < 1e-12);
        assert!((dt - 0.1 * (4.0f64 / 4000.0).sqrt()).abs() < 1e-15);
        // Further: zero (Iform 2), not negative.
        assert_eq!(f(&t, 0.017, &mut m), 0.0);
        // Reloading from (0.017, 0) along Stiff: 4000·0.001 = 4, below the curve.
        assert!((f(&t, 0.018, &mut m) - 4.0).abs() < 1e-12);
        // Separation drops the memory.
        assert_eq!(f(&t, 0.0, &mut m), 0.0);
        assert_eq!(m, [0.0; 2]);
        // Iform 1 with f_ul = 0.25·f_ld: unloading stops on it.
        t.iform = 1;
        t.unload = t.load.clone();
        t.fscale_ul = 0.5;
        f(&t, 0.02, &mut m);
        assert!((f(&t, 0.015, &mut m) - 0.25 * 400.0 * 0.015).abs() < 1e-12);
    }
}
