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
//!
//! Large rotations: the offset d⃗ is not a constant of the initial
//! configuration but follows the segment: each cycle it is turned by the
//! rotation the segment makes over the step, d⃗ⁿ⁺¹ = R(Δt ω_p) d⃗ⁿ (Rodrigues'
//! formula, exact rotation: |d⃗| is kept to round-off). Within a cycle both
//! maps use the same d⃗ⁿ, so they stay exact transposes; after the position
//! update the secondary node is placed at Σ Φ_i x_iⁿ⁺¹ + d⃗ⁿ⁺¹ (the
//! difference from xₛ + Δt vₛ is the centripetal term, O((ωΔt)²)|d|, a
//! position correction that does no work to first order).
//!
//! Main nodes without rotational degrees of freedom (brick faces): the
//! manual's optimized spotweld formulation (Spotflag 1, "based on element mean
//! rigid motion", recommended "for connecting beam, spring, and shell
//! secondary nodes to brick main segments") ties the secondary node to the
//! segment's mean rigid motion. Here the rotation of the segment is its
//! least-squares rigid spin from the corner velocities (`SpinMap`),
//!   ω_seg = J⁻¹ Σ_i r⃗_i × v⃗_i,  r⃗_i = x⃗_i − c⃗,  J = Σ_i (|r⃗_i|² I − r⃗_i r⃗_iᵀ),
//! (c⃗ the corners' centroid; exact for a rigid motion of the corners), and
//! the secondary node follows it: v_s = Σ Φ_i v_i + ω_seg × d⃗, ω_s = ω_seg.
//! Its transpose turns the moment about the projected point,
//! M_p = M_s + d⃗ × F_s, into a couple of corner forces in the segment,
//!   F_i = Φ_i F_s + a⃗ × r⃗_i,  a⃗ = J⁻¹ M_p,
//! whose resultant is zero (Σ r⃗_i = 0) and whose moment is J a⃗ = M_p. The
//! secondary node's own rotational inertia (and m_s d²) has no place on
//! translation-only main nodes (diagonal masses): it is left out of the
//! dynamics and of the kinetic energy alike.
//!
//! Spotflag 4 (reference guide /INTER/TYPE2: "Rotational DOF are not
//! transmitted"; LS-DYNA's tied nodes and surfaces, which tie translations
//! only): `Turn::Fixed`. v_s = Σ Φ_i v_i and F_i = Φ_i F_s; the offset d⃗
//! keeps its direction, and the secondary node's moment, rotational inertia
//! and rotation stay its own. With d⃗ = 0 (nodes moved onto the surface) the
//! tie keeps momentum and angular momentum exactly; with an offset, the
//! moment d⃗ × F_s is not passed (as the reference formulation).

use crate::contact::geometry::{add, cross, dot, scale, sub, V3};

/// One tie's share on corner i: force and moment (6 components).
pub type Share = [f64; 6];

/// The least-squares rigid spin of a segment from its corner velocities
/// (main nodes without rotational DOFs): ω = J⁻¹ Σ r_i × v_i.
#[derive(Clone, Copy, Debug)]
pub struct SpinMap {
    /// r_i = x_i − c (zero for a triangle's repeated corner).
    pub r: [V3; 4],
    /// J⁻¹ (symmetric).
    pub jinv: [[f64; 3]; 3],
}

impl SpinMap {
    /// From the corners' current positions; None for a degenerate segment.
    pub fn new(x: &[V3; 4], tri: bool) -> Option<SpinMap> {
        let k = if tri { 3 } else { 4 };
        let mut c = [0.0; 3];
        for xi in &x[..k] {
            c = add(c, *xi);
        }
        c = scale(c, 1.0 / k as f64);
        let mut r = [[0.0; 3]; 4];
        let mut j = [[0.0; 3]; 3];
        for i in 0..k {
            r[i] = sub(x[i], c);
            let r2 = dot(r[i], r[i]);
            for a in 0..3 {
                for b in 0..3 {
                    j[a][b] -= r[i][a] * r[i][b];
                }
                j[a][a] += r2;
            }
        }
        let det = j[0][0] * (j[1][1] * j[2][2] - j[1][2] * j[2][1])
            - j[0][1] * (j[1][0] * j[2][2] - j[1][2] * j[2][0])
            + j[0][2] * (j[1][0] * j[2][1] - j[1][1] * j[2][0]);
        let tr = j[0][0] + j[1][1] + j[2][2];
        // Collinear or coincident corners (or NaN): no spin.
        if det.is_nan() || det.abs() <= 1e-12 * tr * tr * tr {
            return None;
        }
        // J⁻¹ = cofactor matrix (transposed) / det.
        let jinv = [0, 1, 2].map(|a| {
            [0, 1, 2].map(|b| {
                let (a1, a2) = ((b + 1) % 3, (b + 2) % 3);
                let (b1, b2) = ((a + 1) % 3, (a + 2) % 3);
                (j[a1][b1] * j[a2][b2] - j[a1][b2] * j[a2][b1]) / det
            })
        });
        Some(SpinMap { r, jinv })
    }

    fn apply(&self, m: V3) -> V3 {
        let j = &self.jinv;
        [0, 1, 2].map(|a| j[a][0] * m[0] + j[a][1] * m[1] + j[a][2] * m[2])
    }

    /// ω_seg from the corner velocities.
    pub fn spin(&self, v: &[V3; 4]) -> V3 {
        let mut h = [0.0; 3];
        for (r, vi) in self.r.iter().zip(v) {
            h = add(h, cross(*r, *vi));
        }
        self.apply(h)
    }

    /// The corner forces equivalent to a moment m (the transpose of `spin`).
    pub fn couple(&self, m: V3) -> [V3; 4] {
        let a = self.apply(m);
        self.r.map(|r| cross(a, r))
    }
}

/// How the segment turns: its nodes' rotational velocities (shells), or its
/// rigid spin from the nodes' velocities (bricks: `None` when degenerate).
/// `Fixed`: Spotflag 4, the rotations are not transmitted (reference guide
/// /INTER/TYPE2: "Rotational DOF are not transmitted"): the offset keeps
/// its direction, the secondary node's moment stays with it and its
/// rotation is its own.
#[derive(Clone, Copy, Debug)]
pub enum Turn {
    Nodal,
    Spin(Option<SpinMap>),
    Fixed,
}

/// Force F and moment M of the secondary node spread over the segment's corners.
pub fn spread(shape: &[f64; 4], f: V3, m: V3, d: V3, turn: &Turn) -> [Share; 4] {
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
            if let Turn::Nodal = turn {
                out[i][3 + k] = s * mp[k];
            }
        }
    }
    if let Turn::Spin(Some(map)) = turn {
        let c = map.couple(mp);
        for i in 0..4 {
            for k in 0..3 {
                out[i][k] += c[i][k];
            }
        }
    }
    out
}

/// Velocity and rotational velocity of the secondary node (the transpose of
/// `spread`) from its main nodes' velocities `v` and rotational velocities `w`.
pub fn recover(shape: &[f64; 4], v: &[V3; 4], w: &[V3; 4], d: V3, turn: &Turn) -> (V3, V3) {
    let mut vp = [0.0; 3];
    let mut wp = [0.0; 3];
    for i in 0..4 {
        let s = shape[i];
        if s == 0.0 {
            continue;
        }
        for k in 0..3 {
            vp[k] += s * v[i][k];
            if let Turn::Nodal = turn {
                wp[k] += s * w[i][k];
            }
        }
    }
    if let Turn::Spin(Some(map)) = turn {
        wp = map.spin(v);
    }
    (add(vp, cross(wp, d)), wp)
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
    use crate::vec3::rotate;

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
        let x = [
            [0.0, 0.0, 0.0],
            [2.0, 0.1, 0.0],
            [2.2, 1.9, 0.1],
            [-0.1, 2.0, 0.0],
        ];
        let p: V3 = [0, 1, 2].map(|k| (0..4).map(|i| shape[i] * x[i][k]).sum());
        for turn in [Turn::Nodal, Turn::Spin(SpinMap::new(&x, false))] {
            let sh = spread(&shape, f, m, d, &turn);
            let (vs, ws) = recover(&shape, &v, &w, d, &turn);
            let p_sec = dot(f, vs) + dot(m, ws);
            let p_main: f64 = (0..4).map(|i| dot6(&sh[i], v[i], w[i])).sum();
            assert!((p_sec - p_main).abs() < 1e-14, "{p_sec} vs {p_main}");
            // Resultant force and moment (about the origin) are kept.
            let mut mo = [0.0; 3];
            for i in 0..4 {
                let fi = [sh[i][0], sh[i][1], sh[i][2]];
                mo = add(add(mo, cross(x[i], fi)), [sh[i][3], sh[i][4], sh[i][5]]);
            }
            let want = add(m, cross(add(p, d), f));
            for k in 0..3 {
                let s: f64 = sh.iter().map(|x| x[k]).sum();
                assert!((s - f[k]).abs() < 1e-14);
                assert!((mo[k] - want[k]).abs() < 1e-13, "{mo:?} vs {want:?}");
            }
        }
        // The spin of a rigid motion is its rotational velocity.
        let om = [0.3, -0.2, 0.7];
        let vr = x.map(|xi| add([1.0, 2.0, 3.0], cross(om, xi)));
        let s = SpinMap::new(&x, false).unwrap().spin(&vr);
        for k in 0..3 {
            assert!((s[k] - om[k]).abs() < 1e-14);
        }
        // Rodrigues keeps the length and turns by the angle.
        let r = rotate(
            [1.0, 0.0, 0.5],
            [0.0, 0.0, 2.0],
            std::f64::consts::FRAC_PI_4,
        );
        assert!((r[0]).abs() < 1e-15 && (r[1] - 1.0).abs() < 1e-15 && r[2] == 0.5);
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
