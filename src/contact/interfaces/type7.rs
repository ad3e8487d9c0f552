//! TYPE7 node-to-segment penalty contact (theory manual §8.8): both sides,
//! edges and corners; F = Ks·P + C·dP/dt with Ks = K0·Gap/(Gap − P) and
//! C = VISs·√(2·Ks·M) (EQ. 8.8.9.1, 8.8.3.3); friction by Ifric/Iform/Ifiltr
//! (EQ. 8.8.3.4–5).
//!
//! Details as the reference engine applies them (its listing prints them as
//! "QUADRATIC DAMPING FLAG 0" and "FRICTION CRITICAL DAMPING FACTOR"):
//! - while the node closes in, the damper works on the tangent stiffness
//!   Kt = Ks·Gap/(Gap − P) (EQ. 8.8.9.2) rather than Ks, and a quadratic term
//!   0.4²·2·M·(dP/dt)/(Gap − P) is added to C, so that a fast impact is
//!   braked before the node reaches the mid-plane;
//! - the reaction is not cut at zero: on the way out the damper may pull
//!   (EQ. 8.8.9.1 as written), which takes out the energy the damper of the
//!   way in did not;
//! - the friction damper VISF·√(2·K·M) enters the stiffness the nodal time
//!   step sees as VISF·√(2·K·M)/Δt (with Δt the last step): a node sliding
//!   under friction is integrated with a step at which that damper is stable.

use super::{PairForce, PairState};
use crate::contact::friction::{self, FrictionLaw};
use crate::contact::geometry::{self as geo, V3};
use crate::contact::stiffness;

/// A TYPE7 pair's inputs.
pub struct Pair<'a> {
    pub xs: V3,
    pub vs: V3,
    pub ms: f64,
    pub xm: &'a [V3; 4],
    pub vm: &'a [V3; 4],
    pub tri: bool,
    /// Initial stiffness K0 of the pair (Istf).
    pub k0: f64,
    /// The pair's gap (constant, variable, or reduced for an initial penetration).
    pub gap: f64,
    pub viss: f64,
    pub friction: &'a FrictionLaw,
    /// Area of the main segment, for the contact pressure of the friction laws.
    pub area: f64,
    pub dt: f64,
}

/// The pair's force, or `None` when the node is outside the gap (or at the
/// segment's mid-plane, where it is deactivated, §8.8.11.1).
pub fn pair(p: &Pair, st: &mut PairState) -> Option<PairForce> {
    // Most candidates of the sort are out of the gap at a given cycle: a node
    // farther than the gap from the ball holding the segment's nodes is
    // farther than the gap from the segment (exact, so the result is the same
    // as the full projection's).
    if geo::beyond_reach(p.xs, p.xm, p.tri, p.gap) {
        st.ft = [0.0; 3];
        st.ff = [0.0; 3];
        return None;
    }
    let pr = geo::project(p.xs, p.xm, p.tri);
    if pr.dist >= p.gap || pr.dist < 1e-10 * p.gap {
        st.ft = [0.0; 3];
        st.ff = [0.0; 3];
        return None;
    }
    let s = geo::dot(geo::sub(p.xs, pr.point), pr.normal);
    st.side = if s >= 0.0 { 1 } else { -1 };
    let pen = p.gap - pr.dist;
    let (f_el, kt) = stiffness::type7_reaction(p.k0, p.gap, pen);
    let vc = geo::interpolate(&pr.shape, p.vm);
    let vrel = geo::sub(p.vs, vc);
    // Penetration rate: the node closing on the contact point.
    let dpdt = -geo::dot(vrel, pr.dir);
    let c = damping(p.viss, p.k0, p.gap, pen, p.ms, dpdt);
    // Signed: the damper may pull while the node leaves (EQ. 8.8.9.1).
    let f_n = f_el + c * dpdt;
    // The stiffness the dampers see: Kt closing in, Ks going out.
    let kd = if dpdt > 0.0 {
        kt
    } else {
        p.k0 * p.gap / (p.gap - pen)
    };
    let mut f_t = [0.0; 3];
    if p.friction.active() && f_n != 0.0 {
        let vt = friction::tangential(vrel, pr.dir);
        let f_abs = f_n.abs();
        let pressure = if p.area > 0.0 { f_abs / p.area } else { 0.0 };
        let mu = p.friction.mu(pressure, geo::norm(vt));
        let k = if p.friction.iform == 1 { kd } else { p.k0 };
        let raw = friction::tangential_force(
            p.friction, mu, f_abs, vt, pr.dir, k, p.ms, p.dt, &mut st.ft,
        );
        let a = p.friction.filter_alpha(p.dt);
        st.ff = geo::add(geo::scale(raw, a), geo::scale(st.ff, 1.0 - a));
        f_t = st.ff;
    }
    let fs = geo::add(geo::scale(pr.dir, f_n), f_t);
    let dt_kin = if dpdt > 0.0 {
        0.5 * pr.dist / dpdt
    } else {
        f64::INFINITY
    };
    // The stiffness of the nodal time step: Kt, or the friction damper over
    // the last step where that is stiffer.
    let k_step = if p.friction.active() && p.dt > 0.0 {
        kt.max(p.friction.visf * (2.0 * kd * p.ms).sqrt() / p.dt)
    } else {
        kt
    };
    Some(PairForce {
        fs,
        shape: pr.shape,
        kt: k_step,
        dt_kin,
        f_n,
        f_t,
        pen,
        dir: pr.dir,
        point: pr.point,
    })
}

/// Coefficient of the normal damper at penetration `pen` (≥ 0) and
/// penetration rate `dpdt` (> 0 closing): C = VISs·√(2·K·M) with K = Kt while
/// closing and Ks while opening (EQ. 8.8.9.1–2), plus, while closing, the
/// quadratic term 0.4²·2·M·(dP/dt)/(Gap − P).
pub fn damping(viss: f64, k0: f64, gap: f64, pen: f64, m: f64, dpdt: f64) -> f64 {
    let ks = k0 * gap / (gap - pen);
    if dpdt > 0.0 {
        let kt = ks * gap / (gap - pen);
        viss * (2.0 * kt * m).sqrt() + QUAD_DAMPING * QUAD_DAMPING * 2.0 * m * dpdt / (gap - pen)
    } else {
        viss * (2.0 * ks * m).sqrt()
    }
}

/// Coefficient of the quadratic damper (the reference engine's default,
/// "QUADRATIC DAMPING FLAG 0").
const QUAD_DAMPING: f64 = 0.4;

/// A tied pair (ITIED 1, 2): a spring K0 with critical damping VISs holds the
/// node at the point of the segment where it was tied. With ITIED = 1 the tie
/// lets go when the spring pulls the node towards the segment (rebound).
pub fn tied(p: &Pair, st: &mut PairState, itied: i64) -> Option<PairForce> {
    let (shape, offset) = st.tie?;
    let anchor = geo::add(geo::interpolate(&shape, p.xm), offset);
    let vc = geo::interpolate(&shape, p.vm);
    let err = geo::sub(p.xs, anchor);
    let vrel = geo::sub(p.vs, vc);
    let c = p.viss.max(0.05) * (2.0 * p.k0 * p.ms).sqrt();
    let fs = geo::sub(geo::scale(err, -p.k0), geo::scale(vrel, c));
    let ol = geo::norm(offset);
    let dir = if ol > 0.0 {
        geo::scale(offset, 1.0 / ol)
    } else {
        [0.0; 3]
    };
    let f_n = geo::dot(fs, dir);
    if itied == 1 && f_n < 0.0 {
        st.tie = None;
        return None;
    }
    Some(PairForce {
        fs,
        shape,
        kt: p.k0,
        dt_kin: f64::INFINITY,
        f_n: f_n.max(0.0),
        f_t: geo::sub(fs, geo::scale(dir, f_n)),
        pen: 0.0,
        dir,
        point: anchor,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn plate() -> [V3; 4] {
        [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
        ]
    }

    fn input<'a>(
        xs: V3,
        vs: V3,
        xm: &'a [V3; 4],
        vm: &'a [V3; 4],
        law: &'a FrictionLaw,
    ) -> Pair<'a> {
        Pair {
            xs,
            vs,
            ms: 1.0,
            xm,
            vm,
            tri: false,
            k0: 1000.0,
            gap: 0.1,
            viss: 0.0,
            friction: law,
            area: 1.0,
            dt: 1e-3,
        }
    }

    #[test]
    fn both_sides_and_balanced_moments() {
        let xm = plate();
        let vm = [[0.0; 3]; 4];
        let law = FrictionLaw::none();
        let mut st = PairState::default();
        let up = pair(&input([0.25, 0.5, 0.05], [0.0; 3], &xm, &vm, &law), &mut st).unwrap();
        assert!(up.fs[2] > 0.0);
        // F = K0·P·Gap/(Gap − P) with P = 0.05: 1000·0.05·2 = 100.
        assert!((up.fs[2] - 100.0).abs() < 1e-9);
        let down = pair(
            &input([0.25, 0.5, -0.05], [0.0; 3], &xm, &vm, &law),
            &mut st,
        )
        .unwrap();
        assert!((down.fs[2] + 100.0).abs() < 1e-9);
        // Segment forces −N_i·F have the same moment about the node as −F at the contact point.
        let mut m = [0.0; 3];
        for i in 0..4 {
            let f = geo::scale(up.fs, -up.shape[i]);
            m = geo::add(m, geo::cross(xm[i], f));
        }
        let m_ref = geo::cross(up.point, geo::scale(up.fs, -1.0));
        for k in 0..3 {
            assert!((m[k] - m_ref[k]).abs() < 1e-12);
        }
        // Outside the gap: nothing.
        assert!(pair(&input([0.25, 0.5, 0.2], [0.0; 3], &xm, &vm, &law), &mut st).is_none());
    }

    #[test]
    fn closing_speed_gives_damping_and_a_kinematic_step() {
        let xm = plate();
        let vm = [[0.0; 3]; 4];
        let law = FrictionLaw::none();
        let mut st = PairState::default();
        let mut inp = input([0.5, 0.5, 0.05], [0.0, 0.0, -2.0], &xm, &vm, &law);
        inp.viss = 0.05;
        let f = pair(&inp, &mut st).unwrap();
        let kt = 1000.0 * 4.0;
        assert!((f.kt - kt).abs() < 1e-9);
        // Closing at 2: C = VISs·√(2·Kt·M) + 0.4²·2·M·2/(Gap − P).
        let c = 0.05 * (2.0f64 * kt).sqrt() + 0.16 * 2.0 * 2.0 / 0.05;
        let expect = 100.0 + c * 2.0;
        assert!((f.fs[2] - expect).abs() < 1e-9);
        // EQ. 8.8.5.1: 0.5·(Gap − P)/(dP/dt) = 0.5·0.05/2.
        assert!((f.dt_kin - 0.0125).abs() < 1e-15);
    }

    #[test]
    fn opening_damper_works_on_the_secant_stiffness_and_may_pull() {
        let xm = plate();
        let vm = [[0.0; 3]; 4];
        let law = FrictionLaw::none();
        let mut st = PairState::default();
        // Leaving at 2: C = VISs·√(2·Ks·M), Ks = K0·Gap/(Gap − P) = 2000.
        let mut inp = input([0.5, 0.5, 0.05], [0.0, 0.0, 2.0], &xm, &vm, &law);
        inp.viss = 0.05;
        let f = pair(&inp, &mut st).unwrap();
        let expect = 100.0 - 0.05 * (2.0f64 * 2000.0).sqrt() * 2.0;
        assert!((f.fs[2] - expect).abs() < 1e-9);
        // A node leaving fast from a shallow penetration is pulled back.
        let mut inp = input([0.5, 0.5, 0.0999], [0.0, 0.0, 50.0], &xm, &vm, &law);
        inp.viss = 0.05;
        let f = pair(&inp, &mut st).unwrap();
        assert!(f.fs[2] < 0.0 && f.f_n < 0.0, "{:?}", f.fs);
    }

    #[test]
    fn friction_damper_stiffens_the_nodal_step() {
        let xm = plate();
        let vm = [[0.0; 3]; 4];
        let law = FrictionLaw {
            fric: 0.3,
            iform: 1,
            visf: 1.0,
            ..FrictionLaw::none()
        };
        let mut st = PairState::default();
        let mut inp = input([0.5, 0.5, 0.05], [1.0, 0.0, 0.0], &xm, &vm, &law);
        inp.dt = 1e-4;
        let f = pair(&inp, &mut st).unwrap();
        // Not moving along the normal: Ks = 2000; √(2·2000·1)/1e-4 > Kt = 4000.
        let k = (2.0f64 * 2000.0).sqrt() / 1e-4;
        assert!((f.kt - k).abs() < 1e-6 * k);
        // Without friction the step sees Kt only.
        let none = FrictionLaw::none();
        let mut inp = input([0.5, 0.5, 0.05], [1.0, 0.0, 0.0], &xm, &vm, &none);
        inp.dt = 1e-4;
        assert!((pair(&inp, &mut st).unwrap().kt - 4000.0).abs() < 1e-9);
    }

    #[test]
    fn coulomb_friction_opposes_sliding() {
        let xm = plate();
        let vm = [[0.0; 3]; 4];
        let law = FrictionLaw {
            fric: 0.3,
            ..FrictionLaw::none()
        };
        let mut st = PairState::default();
        let inp = input([0.5, 0.5, 0.05], [5.0, 0.0, 0.0], &xm, &vm, &law);
        let mut f = pair(&inp, &mut st).unwrap();
        for _ in 0..1000 {
            f = pair(&inp, &mut st).unwrap();
        }
        assert!((f.fs[0] + 0.3 * 100.0).abs() < 1e-9, "{:?}", f.fs);
    }
}
