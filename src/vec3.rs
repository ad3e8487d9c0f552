//! 3-vector algebra on plain `[f64; 3]`, the one copy every kernel uses
//! (elements, contact geometry, rigid bodies and walls, model measures).
//! Always inlined: the hot kernels pay nothing for the call, and each
//! expression is written once, so every caller rounds alike.
//!
//! Why not nalgebra's `Vector3` here: the kernels keep their state as plain
//! arrays in structure-of-arrays blocks (serde, MPI buffers, HDF5 rows); a
//! conversion at every call would cost more than these one-line bodies.

/// A 3-vector.
pub type V3 = [f64; 3];

#[inline(always)]
pub fn add(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
#[inline(always)]
pub fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
#[inline(always)]
pub fn scale(a: V3, s: f64) -> V3 {
    [a[0] * s, a[1] * s, a[2] * s]
}
#[inline(always)]
pub fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
#[inline(always)]
pub fn cross(a: V3, b: V3) -> V3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
#[inline(always)]
pub fn norm(a: V3) -> f64 {
    dot(a, a).sqrt()
}

/// The spin W = ½(L − Lᵀ) of a velocity gradient L.
#[inline]
pub fn spin(l: &[[f64; 3]; 3]) -> [[f64; 3]; 3] {
    std::array::from_fn(|i| std::array::from_fn(|j| 0.5 * (l[i][j] - l[j][i])))
}

/// The Hughes-Winget rotation of the spin increment W Δt:
/// Q = (I − ½ΔtW)⁻¹(I + ½ΔtW); `None` without spin.
#[inline]
pub fn spin_rotation(w: &[[f64; 3]; 3], dt: f64) -> Option<[[f64; 3]; 3]> {
    // ω with W = [[0, −ω3, ω2], [ω3, 0, −ω1], [−ω2, ω1, 0]] · (scaled by ½Δt).
    let h = 0.5 * dt;
    let (o1, o2, o3) = (h * w[2][1], h * w[0][2], h * w[1][0]);
    if o1 == 0.0 && o2 == 0.0 && o3 == 0.0 {
        return None;
    }
    // Q = I + 2/(1+|ω|²) (Ω + Ω²), the Cayley transform of Ω = ½ΔtW.
    let om = [[0.0, -o3, o2], [o3, 0.0, -o1], [-o2, o1, 0.0]];
    let k = 2.0 / (1.0 + o1 * o1 + o2 * o2 + o3 * o3);
    let mut q = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            let mut om2 = 0.0;
            for m in 0..3 {
                om2 += om[i][m] * om[m][j];
            }
            q[i][j] = if i == j { 1.0 } else { 0.0 } + k * (om[i][j] + om2);
        }
    }
    Some(q)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_basis_multiplies_as_it_should() {
        let (x, y, z) = ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]);
        assert_eq!(cross(x, y), z);
        assert_eq!(cross(y, x), scale(z, -1.0));
        assert_eq!(dot(add(x, y), sub(x, y)), 0.0);
        assert_eq!(norm([3.0, 4.0, 12.0]), 13.0);
    }
}

/// `a` made orthogonal to the unit `x` and normalised; a global axis (X, or
/// Y when `x` lies near X) made so when `a` is parallel to `x`. The local y
/// axis of the spring beam and the beam.
pub fn orthogonal_axis(a: V3, x: V3) -> V3 {
    let p = sub(a, scale(x, dot(a, x)));
    let n = norm(p);
    if n > 1e-12 {
        return scale(p, 1.0 / n);
    }
    let other = if x[0].abs() < 0.9 {
        [1.0, 0.0, 0.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    orthogonal_axis(other, x)
}

/// d turned by the rotation of rotational velocity w over dt (Rodrigues).
pub fn rotate(d: V3, w: V3, dt: f64) -> V3 {
    let th = norm(w) * dt;
    if th == 0.0 {
        return d;
    }
    let n = scale(w, 1.0 / norm(w));
    let (s, c) = th.sin_cos();
    let nxd = cross(n, d);
    let nd = dot(n, d);
    [0, 1, 2].map(|k| d[k] * c + nxd[k] * s + n[k] * nd * (1.0 - c))
}

/// The inverse of a 3×3 matrix (cofactors over the determinant); None when
/// the determinant is not positive (a compliance or stiffness must be).
pub fn inverse_positive(a: &[[f64; 3]; 3]) -> Option<[[f64; 3]; 3]> {
    let cof = |i: usize, j: usize| {
        let (r0, r1) = ((i + 1) % 3, (i + 2) % 3);
        let (c0, c1) = ((j + 1) % 3, (j + 2) % 3);
        a[r0][c0] * a[r1][c1] - a[r0][c1] * a[r1][c0]
    };
    let det = a[0][0] * cof(0, 0) + a[0][1] * cof(0, 1) + a[0][2] * cof(0, 2);
    if !(det > 0.0) {
        return None;
    }
    Some(std::array::from_fn(|i| {
        std::array::from_fn(|j| cof(j, i) / det)
    }))
}

/// R σ Rᵀ of a Voigt stress [σxx σyy σzz σxy σyz σzx].
pub fn rotate_voigt(r: &[[f64; 3]; 3], s: &[f64; 6]) -> [f64; 6] {
    let m = [[s[0], s[3], s[5]], [s[3], s[1], s[4]], [s[5], s[4], s[2]]];
    let mut o = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            for k in 0..3 {
                for l in 0..3 {
                    o[i][j] += r[i][k] * m[k][l] * r[j][l];
                }
            }
        }
    }
    [o[0][0], o[1][1], o[2][2], o[0][1], o[1][2], o[2][0]]
}
