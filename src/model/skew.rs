//! Skew frames (/SKEW/FIX, /SKEW/MOV, /SKEW/MOV2): local coordinate systems
//! that conditions and outputs may be expressed in (reference guide
//! /SKEW/FIX and /SKEW/MOV, Starter).

use super::{Id, Loc};
use serde::{Deserialize, Serialize};

/// A skew as the model holds it (nodes as dense indices).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Skew {
    pub id: Id,
    pub title: String,
    pub kind: SkewKind,
    pub loc: Loc,
}

/// How a skew's axes are found.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub enum SkewKind {
    /// /SKEW/FIX: origin, Y′ and Z′ given; X = Y′ × Z′, Y = Z′ × X.
    Fixed {
        origin: [f64; 3],
        y: [f64; 3],
        z: [f64; 3],
    },
    /// /SKEW/MOV (Dir X, Y, Z; blank X) and /SKEW/MOV2 (X): axes from the
    /// current positions of three nodes. N1→N2 is the Dir axis; N1→N3 lies
    /// in the plane of the Dir axis and the next one (cyclically: X′Y′ for
    /// X, Y′Z′ for Y, Z′X′ for Z), on its positive side; the third axis
    /// completes a right-handed frame. For Dir X this is the guide's
    /// Z′ = X′ × Y″, Y′ = Z′ × X′; for Y and Z the guide's page renders the
    /// products ambiguously, and the cyclic form is taken (UNCONFIRMED).
    Moving { nodes: [u32; 3], dir: u8 },
}

fn unit(a: [f64; 3]) -> Option<[f64; 3]> {
    let n = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
    (n > 0.0 && n.is_finite()).then(|| [a[0] / n, a[1] / n, a[2] / n])
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

impl Skew {
    /// The skew's unit axes [X′, Y′, Z′] (rows) with the nodes at `x`;
    /// `None` when they are degenerate (coincident or aligned nodes, zero or
    /// parallel vectors).
    pub fn axes(&self, x: &[[f64; 3]]) -> Option<[[f64; 3]; 3]> {
        match &self.kind {
            SkewKind::Fixed { y, z, .. } => {
                let z = unit(*z)?;
                let xa = unit(cross(*y, z))?;
                Some([xa, cross(z, xa), z])
            }
            SkewKind::Moving { nodes, dir } => {
                let p = |k: usize| x[nodes[k] as usize];
                let a = unit(sub(p(1), p(0)))?;
                let b = sub(p(2), p(0));
                match dir {
                    b'Y' => {
                        let xa = unit(cross(a, b))?;
                        Some([xa, a, cross(xa, a)])
                    }
                    b'Z' => {
                        let ya = unit(cross(a, b))?;
                        Some([cross(ya, a), ya, a])
                    }
                    _ => {
                        let za = unit(cross(a, b))?;
                        Some([a, cross(za, a), za])
                    }
                }
            }
        }
    }

    /// The components of a global vector in the skew's axes.
    pub fn to_local(axes: &[[f64; 3]; 3], v: [f64; 3]) -> [f64; 3] {
        axes.map(|e| e[0] * v[0] + e[1] * v[1] + e[2] * v[2])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn moving(dir: u8) -> Skew {
        Skew {
            id: 1,
            title: String::new(),
            kind: SkewKind::Moving {
                nodes: [0, 1, 2],
                dir,
            },
            loc: Loc::default(),
        }
    }

    fn det(a: &[[f64; 3]; 3]) -> f64 {
        let c = cross(a[0], a[1]);
        c[0] * a[2][0] + c[1] * a[2][1] + c[2] * a[2][2]
    }

    /// Dir X, Y, Z put N1→N2 on X′, Y′, Z′ and N1→N3 in the plane the guide
    /// names; every frame is right-handed and orthonormal.
    #[test]
    fn moving_skews_follow_the_guide_and_are_right_handed() {
        let x = [[1.0, 1.0, 1.0], [3.0, 1.0, 1.0], [1.0, 4.0, 1.0]];
        let ax = moving(b'X').axes(&x).unwrap();
        assert_eq!(ax, [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]);
        let ay = moving(b'Y').axes(&x).unwrap();
        assert_eq!(ay[1], [1.0, 0.0, 0.0]);
        assert_eq!(ay[2], [0.0, 1.0, 0.0], "N1→N3 spans Y′Z′");
        let az = moving(b'Z').axes(&x).unwrap();
        assert_eq!(az[2], [1.0, 0.0, 0.0]);
        assert_eq!(az[0], [0.0, 1.0, 0.0], "N1→N3 spans Z′X′");
        for a in [ax, ay, az] {
            assert!((det(&a) - 1.0).abs() < 1e-14);
        }
        // Aligned nodes: no frame.
        let line = [[0.0; 3], [1.0, 0.0, 0.0], [2.0, 0.0, 0.0]];
        assert!(moving(b'X').axes(&line).is_none());
    }

    /// /SKEW/FIX: X = Y′ × Z′, Y = Z′ × X from vectors of any length.
    #[test]
    fn fixed_skew_is_orthonormalised_from_y_and_z() {
        let s = Skew {
            id: 2,
            title: String::new(),
            kind: SkewKind::Fixed {
                origin: [0.0; 3],
                y: [0.0, 2.0, 0.5],
                z: [0.0, 0.0, 3.0],
            },
            loc: Loc::default(),
        };
        let a = s.axes(&[]).unwrap();
        assert_eq!(a, [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]);
        assert_eq!(Skew::to_local(&a, [1.0, 2.0, 3.0]), [1.0, 2.0, 3.0]);
    }
}
