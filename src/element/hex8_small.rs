//! Ismstr = 1 on the one-point bricks (Isolid 1, 2): small strain from
//! t = 0 (reference guide /PROP/SOLID; research note
//! `docs/notes/solid_ismstr1_research.md` §1-4). The element keeps its
//! initial shape, node 8 at the origin, and turns it with the element's spin
//! every step; that reference shape, not the current one, gives the
//! gradient vectors, the volume V_ref, the hourglass vectors and the
//! characteristic length of the time step, applied to the current
//! velocities. The density follows dρ = −ρ₀(V₀/V_ref)·tr D·Δt.
//!
//! The reference engine turns the shape to first order (x += Δt W x) and
//! takes the strain rate on the shape of the step's start, which strains a
//! body turned rigidly (½(ωΔt)² a step). Here the Hughes-Winget rotation the
//! stress gets (`crate::vec3::spin_rotation`) turns it, keeping its size,
//! and the strain rate is taken on the shape turned to mid-step
//! (`super::hex8::step_geometry`).

use serde::{Deserialize, Serialize};

/// The reference shape of a small-strain brick and its density ratio.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct SmallStrainRef {
    /// Corners 1-7 relative to corner 8 (corner 8 is the origin).
    pub x: [[f64; 3]; 7],
    /// ρ/ρ₀.
    pub rho_ratio: f64,
}

impl SmallStrainRef {
    /// The reference at t = 0: the initial shape.
    pub fn new(x: &[[f64; 3]; 8]) -> SmallStrainRef {
        SmallStrainRef {
            x: std::array::from_fn(|a| std::array::from_fn(|k| x[a][k] - x[7][k])),
            rho_ratio: 1.0,
        }
    }

    /// The eight corners of the reference shape.
    pub fn corners(&self) -> [[f64; 3]; 8] {
        std::array::from_fn(|a| if a < 7 { self.x[a] } else { [0.0; 3] })
    }

    /// The density after a step of volume rate `tr_d` = tr D:
    /// dρ = −ρ₀(V₀/V_ref)·tr D·Δt.
    pub fn advance_density(&mut self, tr_d: f64, vol0: f64, vref: f64, dt: f64) {
        self.rho_ratio -= vol0 / vref * tr_d * dt;
    }

    /// Turns the shape by the spin of the velocity gradient `l` over Δt (the
    /// rotation the stress gets).
    pub fn turn(&mut self, l: &[[f64; 3]; 3], dt: f64) {
        if let Some(q) = crate::vec3::spin_rotation(&crate::vec3::spin(l), dt) {
            for p in self.x.iter_mut() {
                *p = std::array::from_fn(|i| q[i][0] * p[0] + q[i][1] * p[1] + q[i][2] * p[2]);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_spin_turns_the_shape_rigidly() {
        let x: [[f64; 3]; 8] = std::array::from_fn(|a| {
            [
                (a & 1) as f64 * 2.0,
                ((a >> 1) & 1) as f64,
                ((a >> 2) & 1) as f64 * 3.0,
            ]
        });
        let mut r = SmallStrainRef::new(&x);
        // Spin about z at ω = 1, 100 steps of 0.01: a turn of 1 radian.
        let l = [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 0.0]];
        for _ in 0..100 {
            r.turn(&l, 0.01);
        }
        let (c, s) = (1f64.cos(), 1f64.sin());
        for a in 0..7 {
            let d: [f64; 3] = std::array::from_fn(|k| x[a][k] - x[7][k]);
            let want = [c * d[0] - s * d[1], s * d[0] + c * d[1], d[2]];
            // Each step turns by 2·atan(ω Δt/2) (midpoint rule): 8e-6 rad
            // short after 100 steps; the lengths are exact.
            for k in 0..3 {
                assert!(
                    (r.x[a][k] - want[k]).abs() < 5e-5,
                    "{a}: {:?} vs {want:?}",
                    r.x[a]
                );
            }
            let len = |v: [f64; 3]| (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
            assert!((len(r.x[a]) - len(d)).abs() < 1e-13);
        }
        assert_eq!(r.rho_ratio, 1.0);
    }

    #[test]
    fn the_density_follows_the_volume_rate() {
        let x: [[f64; 3]; 8] =
            std::array::from_fn(|a| [(a & 1) as f64, ((a >> 1) & 1) as f64, (a >> 2) as f64]);
        let mut r = SmallStrainRef::new(&x);
        r.advance_density(-0.5, 1.0, 1.0, 0.1);
        assert!((r.rho_ratio - 1.05).abs() < 1e-15);
    }
}
