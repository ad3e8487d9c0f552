//! The nodal forces of a pressure on one segment (/PLOAD), lumped as the
//! reference engine lumps them (research note
//! `docs/notes/submodel_pload_random_research.md` §2): at the current
//! positions, N = (x3 − x1) × (x4 − x2) for a quadrangle, each of its four
//! nodes taking p·N/8 (together p·N/2 = p·A·n for a flat one); a triangle
//! (fourth node = third) has N = (x2 − x1) × (x3 − x1) and each of its three
//! nodes takes p·N/6. A positive pressure pushes along +N, the right-hand
//! normal of N1N2N3N4 (reference guide /PLOAD, comment 1).

use crate::vec3::{cross, sub};

type V3 = [f64; 3];

/// The force on each corner (the fourth is zero for a triangle) and whether
/// the segment is a triangle.
pub fn segment_forces(x: [V3; 4], triangle: bool, p: f64) -> [V3; 4] {
    if triangle {
        let n = cross(sub(x[1], x[0]), sub(x[2], x[0]));
        let f = n.map(|c| p * c / 6.0);
        [f, f, f, [0.0; 3]]
    } else {
        let n = cross(sub(x[2], x[0]), sub(x[3], x[1]));
        let f = n.map(|c| p * c / 8.0);
        [f, f, f, f]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_flat_quadrangle_takes_pressure_times_area_along_its_normal() {
        let x = [
            [0.0, 0.0, 0.0],
            [2.0, 0.0, 0.0],
            [2.0, 3.0, 0.0],
            [0.0, 3.0, 0.0],
        ];
        let f = segment_forces(x, false, 5.0);
        let total: f64 = f.iter().map(|c| c[2]).sum();
        assert_eq!(total, 5.0 * 6.0);
        assert!(f.iter().all(|c| c[0] == 0.0 && c[1] == 0.0 && c[2] == 7.5));
    }

    #[test]
    fn a_triangle_shares_its_force_in_thirds() {
        let x = [
            [0.0, 0.0, 0.0],
            [0.0, 0.0, 4.0],
            [0.0, 3.0, 0.0],
            [0.0, 3.0, 0.0],
        ];
        let f = segment_forces(x, true, 2.0);
        // N = (0,0,4) × (0,3,0) = (−12, 0, 0): area 6 along −x.
        assert_eq!(f[0], [-4.0, 0.0, 0.0]);
        assert_eq!(f[1], f[0]);
        assert_eq!(f[2], f[0]);
        assert_eq!(f[3], [0.0; 3]);
    }
}
