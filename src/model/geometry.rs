//! Element measures used by the model (areas, volumes, edge lengths).
//! Pure functions of coordinates.

pub use crate::vec3::{cross, dot, norm, sub, V3};

/// Area of a 4-node shell as Radioss takes it for mass: half the norm of the
/// cross product of the diagonals, A = ½‖(x3 − x1) × (x4 − x2)‖ (exact for a
/// flat quadrilateral, the projected area for a warped one).
pub fn quad_area(x: [V3; 4]) -> f64 {
    0.5 * norm(cross(sub(x[2], x[0]), sub(x[3], x[1])))
}

/// Area of a triangle, ½‖(x2 − x1) × (x3 − x1)‖.
pub fn triangle_area(x: [V3; 3]) -> f64 {
    0.5 * norm(cross(sub(x[1], x[0]), sub(x[2], x[0])))
}

/// Signed volume of a 4-node tetrahedron, (x2−x1)·((x3−x1)×(x4−x1))/6
/// (positive for the Radioss node order: 1-2-3 counter-clockwise seen from 4).
pub fn tetra_volume(x: [V3; 4]) -> f64 {
    dot(sub(x[1], x[0]), cross(sub(x[2], x[0]), sub(x[3], x[0]))) / 6.0
}

/// Faces of an 8-node brick (Radioss numbering: 1-2-3-4 bottom, 5-6-7-8 top),
/// each oriented outward for a positive-volume element.
pub const HEXA_FACES: [[usize; 4]; 6] = [
    [0, 3, 2, 1],
    [4, 5, 6, 7],
    [0, 1, 5, 4],
    [1, 2, 6, 5],
    [2, 3, 7, 6],
    [3, 0, 4, 7],
];

/// Volume of an 8-node brick by the divergence theorem: each face is split
/// into four triangles about its centre (the 24-tetrahedron decomposition),
/// so the result is exact for planar faces and consistent for warped ones.
/// Degenerate bricks (repeated nodes: prisms, pyramids, tetrahedra) work as is.
pub fn hexa_volume(x: [V3; 8]) -> f64 {
    let mut v = 0.0;
    for f in HEXA_FACES {
        let c = [
            0.25 * (x[f[0]][0] + x[f[1]][0] + x[f[2]][0] + x[f[3]][0]),
            0.25 * (x[f[0]][1] + x[f[1]][1] + x[f[2]][1] + x[f[3]][1]),
            0.25 * (x[f[0]][2] + x[f[1]][2] + x[f[2]][2] + x[f[3]][2]),
        ];
        for k in 0..4 {
            let a = x[f[k]];
            let b = x[f[(k + 1) % 4]];
            // Flux of position through triangle (c, a, b): (c · (a × b)) / 6 summed = volume.
            v += dot(c, cross(a, b)) / 6.0;
        }
    }
    v
}

/// Shortest element edge in the model (shells, solids, 1-D elements).
pub fn geometry_edge_min(model: &super::Model) -> f64 {
    use crate::model::ElementKind;
    let x = &model.nodes.x;
    let mut best = f64::INFINITY;
    let mut edge = |a: u32, b: u32| {
        if a != b && a != super::NO_NODE && b != super::NO_NODE {
            let d = norm(sub(x[a as usize], x[b as usize]));
            if d < best {
                best = d;
            }
        }
    };
    for set in &model.elements {
        let pairs: &[(usize, usize)] = match set.kind {
            ElementKind::Shell4 | ElementKind::Tetra4 if set.kind == ElementKind::Shell4 => {
                &[(0, 1), (1, 2), (2, 3), (3, 0)]
            }
            ElementKind::Tetra4 => &[(0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3)],
            ElementKind::Shell3 => &[(0, 1), (1, 2), (2, 0)],
            ElementKind::Brick8 => &[
                (0, 1),
                (1, 2),
                (2, 3),
                (3, 0),
                (4, 5),
                (5, 6),
                (6, 7),
                (7, 4),
                (0, 4),
                (1, 5),
                (2, 6),
                (3, 7),
            ],
            _ => &[(0, 1)],
        };
        for e in 0..set.len() {
            let n = set.nodes_of(e);
            for &(a, b) in pairs {
                edge(n[a], n[b]);
            }
        }
    }
    if best.is_finite() {
        best
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit_cube() -> [V3; 8] {
        [
            [0., 0., 0.],
            [1., 0., 0.],
            [1., 1., 0.],
            [0., 1., 0.],
            [0., 0., 1.],
            [1., 0., 1.],
            [1., 1., 1.],
            [0., 1., 1.],
        ]
    }

    #[test]
    fn cube_and_tetra_volumes() {
        let mut c = unit_cube();
        assert!((hexa_volume(c) - 1.0).abs() < 1e-14);
        for p in c.iter_mut() {
            p[0] *= 2.0;
            p[2] += 0.3 * p[1]; // shear keeps the volume
        }
        assert!((hexa_volume(c) - 2.0).abs() < 1e-14);
        let t = [[0., 0., 0.], [1., 0., 0.], [0., 1., 0.], [0., 0., 1.]];
        assert!((tetra_volume(t) - 1.0 / 6.0).abs() < 1e-15);
        // A tetra written as a degenerate brick: 1 2 3 3 4 4 4 4.
        let d = [t[0], t[1], t[2], t[2], t[3], t[3], t[3], t[3]];
        assert!((hexa_volume(d) - 1.0 / 6.0).abs() < 1e-15);
    }

    #[test]
    fn areas() {
        let q = [[0., 0., 0.], [5., 0., 0.], [5., 5., 0.], [0., 5., 0.]];
        assert_eq!(quad_area(q), 25.0);
        assert_eq!(triangle_area([q[0], q[1], q[2]]), 12.5);
    }
}
