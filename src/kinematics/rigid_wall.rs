//! /RWALL/PLANE (fixed or moving infinite plane), kinematic treatment: a
//! secondary node that would cross the wall in this step is put on it; the
//! wall then acts on its velocity — sliding (normal part removed), tied (the
//! node sticks to the wall from then on) or Coulomb friction (tangential
//! change limited by fric × the normal change). The wall force is the
//! momentum the wall took, m·Δv/dt.

type V3 = [f64; 3];

use crate::vec3::dot;

/// Whether a node not tied to the wall stays on its side over the step
/// (the gap at the end of the step, at the relative velocity, is not
/// negative): the wall leaves it as it is.
#[inline]
pub fn stays_off(x: V3, v: V3, dt: f64, p: V3, n: V3, vw: V3) -> bool {
    approach(x, v, dt, p, n, vw).2 >= 0.0
}

/// A node's velocity relative to the wall, its gap now and its gap at the
/// end of the step at that velocity.
#[inline]
fn approach(x: V3, v: V3, dt: f64, p: V3, n: V3, vw: V3) -> (V3, f64, f64) {
    let rel = [v[0] - vw[0], v[1] - vw[1], v[2] - vw[2]];
    let gap = dot([x[0] - p[0], x[1] - p[1], x[2] - p[2]], n);
    (rel, gap, gap + dot(rel, n) * dt)
}

/// The velocity a node leaves the step with and the wall force it exerted.
/// `x`: position at the start of the step, `v`: velocity after the
/// unconstrained update, `p`, `n`: a point of the wall and its unit normal
/// (the allowed side), `vw`: wall velocity, `tied`: the node stuck earlier.
/// Returns (new velocity, now tied, force on the wall).
#[allow(clippy::too_many_arguments)]
pub fn wall_velocity(
    x: V3,
    v: V3,
    m: f64,
    dt: f64,
    p: V3,
    n: V3,
    vw: V3,
    slide: i64,
    fric: f64,
    tied: bool,
) -> (V3, bool, V3) {
    if tied {
        let f = [0, 1, 2].map(|k| m * (v[k] - vw[k]) / dt);
        return (vw, true, f);
    }
    let (rel, gap, gap_next) = approach(x, v, dt, p, n, vw);
    if gap_next >= 0.0 {
        return (v, false, [0.0; 3]);
    }
    // Normal velocity that lands the node on the wall at the end of the step.
    let vn_new = -gap.max(0.0) / dt;
    let vn = dot(rel, n);
    let dvn = vn_new - vn; // > 0
    let mut new_rel = [
        rel[0] + dvn * n[0],
        rel[1] + dvn * n[1],
        rel[2] + dvn * n[2],
    ];
    let mut now_tied = false;
    match slide {
        1 => {
            // Tied: the tangential motion stops too.
            new_rel = [vn_new * n[0], vn_new * n[1], vn_new * n[2]];
            now_tied = true;
        }
        2 if fric > 0.0 => {
            let vt = [
                new_rel[0] - vn_new * n[0],
                new_rel[1] - vn_new * n[1],
                new_rel[2] - vn_new * n[2],
            ];
            let vt_norm = dot(vt, vt).sqrt();
            if vt_norm > 0.0 {
                let reduce = (fric * dvn).min(vt_norm) / vt_norm;
                for k in 0..3 {
                    new_rel[k] -= reduce * vt[k];
                }
            }
        }
        _ => {}
    }
    let new_v = [new_rel[0] + vw[0], new_rel[1] + vw[1], new_rel[2] + vw[2]];
    let f = [0, 1, 2].map(|k| m * (v[k] - new_v[k]) / dt);
    (new_v, now_tied, f)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn node_landing_on_a_sliding_wall_keeps_its_tangential_speed() {
        let (v, tied, f) = wall_velocity(
            [0.5, 0.0, 1.0],
            [-1.0, 0.0, 2.0],
            2.0,
            1.0,
            [0.0; 3],
            [1.0, 0.0, 0.0],
            [0.0; 3],
            0,
            0.0,
            false,
        );
        assert_eq!(v, [-0.5, 0.0, 2.0]);
        assert!(!tied);
        assert_eq!(f, [-1.0, 0.0, 0.0]);
    }

    #[test]
    fn tied_wall_stops_the_node() {
        let (v, tied, _) = wall_velocity(
            [0.0, 0.0, 1.0],
            [-1.0, 0.0, 2.0],
            1.0,
            1.0,
            [0.0; 3],
            [1.0, 0.0, 0.0],
            [0.0; 3],
            1,
            0.0,
            false,
        );
        assert_eq!(v, [0.0, 0.0, 0.0]);
        assert!(tied);
    }

    #[test]
    fn friction_limits_the_tangential_change() {
        let (v, _, _) = wall_velocity(
            [0.0; 3],
            [-1.0, 5.0, 0.0],
            1.0,
            1.0,
            [0.0; 3],
            [1.0, 0.0, 0.0],
            [0.0; 3],
            2,
            0.3,
            false,
        );
        assert_eq!(v[0], 0.0);
        assert!((v[1] - 4.7).abs() < 1e-15);
    }

    #[test]
    fn node_moving_away_is_free() {
        let (v, _, f) = wall_velocity(
            [1.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            1.0,
            1.0,
            [0.0; 3],
            [1.0, 0.0, 0.0],
            [0.0; 3],
            0,
            0.0,
            false,
        );
        assert_eq!(v, [1.0, 0.0, 0.0]);
        assert_eq!(f, [0.0; 3]);
    }
}
