//! /INTER/TYPE2, the tied interface, standard kinematic formulation
//! (Spotflag 5, the card's default without /CAA): a secondary node is held at
//! a fixed place of its main segment. Theory manual chapter 8, §8.3, refers to
//! the "Kinematic Constraints" chapter, "Tied Interface (TYPE2)", default
//! spotweld formulation:
//!
//! - masses: m̄_main,i = m_main,i + m_secondary·Φ_i(p) (its eq. (1)), Φ_i the
//!   shape functions of the secondary node's projection p on the segment;
//!   inertia: Ī_main,i = I_main,i + Φ_i(p)·(I_secondary + m_secondary·d²),
//!   d the distance between the node and the surface (its eq. (2));
//! - forces and moments of the secondary node go to the main nodes,
//!   F_i = Φ_i F_s, M_i = Φ_i (M_s + d⃗ × F_s) (its figure 3: "forces and
//!   moments transfer from secondary to main nodes");
//! - after the main nodes' velocities are updated, the velocity of the
//!   projected point and then of the secondary node are recovered from them
//!   (its eqs. (4)–(5)): v_s = Σ Φ_i v_i + ω_p × d⃗, ω_s = ω_p = Σ Φ_i ω_i.
//!
//! The force map is the transpose of the velocity map, so the constraint does
//! no work: F_s·v_s + M_s·ω_s = Σ_i (F_i·v_i + M_i·ω_i) exactly (see the test).
//! The offset d⃗ = x_s − p is the one of the initial configuration, kept in the
//! global frame (small rotations of the joint).
//!
//! Where the main nodes carry no rotational degree of freedom (brick faces),
//! only the translation is tied (`rot == false`): v_s = Σ Φ_i v_i and
//! F_i = Φ_i F_s; a shell secondary node then keeps its own rotation.

use crate::contact::geometry::{add, cross, V3};

/// One tie's share on corner i: force and moment (6 components).
pub type Share = [f64; 6];

/// Force F and moment M of the secondary node spread over the segment's corners.
pub fn spread(shape: &[f64; 4], f: V3, m: V3, d: V3, rot: bool) -> [Share; 4] {
    let mut out = [[0.0; 6]; 4];
    // Moment about the projected point: M_s + d × F_s.
    let mp = add(m, cross(d, f));
    for i in 0..4 {
        let s = shape[i];
        if s == 0.0 {
            continue;
        }
        for k in 0..3 {
            out[i][k] = s * f[k];
            if rot {
                out[i][3 + k] = s * mp[k];
            }
        }
    }
    out
}

/// Velocity (and, with rotations, rotational velocity) of the secondary node
/// from its main nodes' velocities `v` and rotational velocities `w`.
pub fn recover(shape: &[f64; 4], v: &[V3; 4], w: &[V3; 4], d: V3, rot: bool) -> (V3, Option<V3>) {
    let mut vp = [0.0; 3];
    let mut wp = [0.0; 3];
    for i in 0..4 {
        let s = shape[i];
        if s == 0.0 {
            continue;
        }
        for k in 0..3 {
            vp[k] += s * v[i][k];
            wp[k] += s * w[i][k];
        }
    }
    if rot {
        (add(vp, cross(wp, d)), Some(wp))
    } else {
        (vp, None)
    }
}

/// Mass and rotational inertia added to corner i (set-up, once).
pub fn mass_share(shape: &[f64; 4], ms: f64, is: f64, d: V3, rot: bool) -> [(f64, f64); 4] {
    let d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    let mut out = [(0.0, 0.0); 4];
    for i in 0..4 {
        let s = shape[i];
        if s == 0.0 {
            continue;
        }
        out[i] = (s * ms, if rot { s * (is + ms * d2) } else { 0.0 });
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::geometry::dot;

    fn dot6(a: &Share, v: V3, w: V3) -> f64 {
        a[0] * v[0] + a[1] * v[1] + a[2] * v[2] + a[3] * w[0] + a[4] * w[1] + a[5] * w[2]
    }

    #[test]
    fn the_tie_does_no_work_and_keeps_force_and_moment() {
        let shape = [0.1, 0.4, 0.3, 0.2];
        let f = [1.0, -2.0, 0.5];
        let m = [0.3, 0.1, -0.7];
        let d = [0.05, -0.02, 0.4];
        let v = [
            [1.0, 2.0, 3.0],
            [-1.0, 0.5, 0.2],
            [0.3, -0.4, 1.1],
            [2.0, 0.0, -1.0],
        ];
        let w = [
            [0.1, 0.2, 0.3],
            [-0.5, 0.4, 0.0],
            [0.2, 0.2, -0.1],
            [0.0, 1.0, 0.5],
        ];
        let sh = spread(&shape, f, m, d, true);
        let (vs, ws) = recover(&shape, &v, &w, d, true);
        let ws = ws.unwrap();
        let p_sec = dot(f, vs) + dot(m, ws);
        let p_main: f64 = (0..4).map(|i| dot6(&sh[i], v[i], w[i])).sum();
        assert!((p_sec - p_main).abs() < 1e-14, "{p_sec} vs {p_main}");
        // Resultant force is kept.
        for k in 0..3 {
            let s: f64 = sh.iter().map(|x| x[k]).sum();
            assert!((s - f[k]).abs() < 1e-15);
        }
        // Translation only: still no work.
        let sh = spread(&shape, f, m, d, false);
        let (vs, ws) = recover(&shape, &v, &w, d, false);
        assert!(ws.is_none());
        let p_main: f64 = (0..4).map(|i| dot6(&sh[i], v[i], w[i])).sum();
        assert!((dot(f, vs) - p_main).abs() < 1e-14);
    }

    #[test]
    fn masses_are_kept() {
        let shape = [0.25, 0.25, 0.5, 0.0];
        let s = mass_share(&shape, 2.0, 0.1, [0.0, 0.0, 0.5], true);
        let m: f64 = s.iter().map(|x| x.0).sum();
        let i: f64 = s.iter().map(|x| x.1).sum();
        assert_eq!(m, 2.0);
        assert!((i - (0.1 + 2.0 * 0.25)).abs() < 1e-15);
    }
}
