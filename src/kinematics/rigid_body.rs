//! /RBODY: a rigid body made of a node group and a main node. Its state is
//! replicated on every rank and advanced identically from the resultant of
//! its nodes' forces, gathered over ranks and summed in global node order.
//!
//! Newton-Euler in the global frame: M·a = F, J·ω̇ = T − ω×(J·ω) with
//! J = R·J₀·Rᵀ; then every node of the body moves as v = v_G + ω×(x − x_G)
//! and, for shell nodes, turns at ω.

use serde::{Deserialize, Serialize};

type V3 = [f64; 3];

/// One node's share of a rigid body's resultant: global node index, force,
/// moment (shell nodes) and position.
#[derive(Clone, Copy, Debug, Serialize, Deserialize)]
pub struct NodeLoad {
    pub node: u32,
    pub f: V3,
    pub m: V3,
    pub x: V3,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct RigidBodyState {
    pub id: u64,
    pub mass: f64,
    /// Inertia about the centre at t = 0 (xx, yy, zz, xy, yz, xz), body axes = global at t = 0.
    pub j0: [f64; 6],
    pub center: V3,
    /// Centre at t = 0 (the body's displacement, for /IMPDISP on its main node).
    pub center0: V3,
    pub v: V3,
    pub omega: V3,
    /// Rotation from the initial orientation (row-major 3×3).
    pub rot: [[f64; 3]; 3],
}

impl RigidBodyState {
    /// The smallest principal moment of inertia (the eigenvalues of j0:
    /// the body's turning does not change them).
    pub fn smallest_inertia(&self) -> f64 {
        let j = sym(&self.j0);
        nalgebra::Matrix3::from_fn(|r, c| j[r][c])
            .symmetric_eigenvalues()
            .min()
    }

    /// ½ ωᵀ J ω with J the body's inertia turned to its orientation.
    pub fn rotational_energy(&self) -> f64 {
        let (w, r) = (self.omega, &self.rot);
        // ω in the body's initial axes: Rᵀω.
        let wb: V3 = [0, 1, 2].map(|i| r[0][i] * w[0] + r[1][i] * w[1] + r[2][i] * w[2]);
        let jw = mat_vec(&sym(&self.j0), wb);
        0.5 * (wb[0] * jw[0] + wb[1] * jw[1] + wb[2] * jw[2])
    }

    /// J w with J the body's inertia turned to its orientation (R J₀ Rᵀ w):
    /// the angular momentum of spin w.
    pub fn inertia_times(&self, w: V3) -> V3 {
        let r = &self.rot;
        let wb: V3 = [0, 1, 2].map(|i| r[0][i] * w[0] + r[1][i] * w[1] + r[2][i] * w[2]);
        mat_vec(r, mat_vec(&sym(&self.j0), wb))
    }
}

fn sym(j: &[f64; 6]) -> [[f64; 3]; 3] {
    [[j[0], j[3], j[5]], [j[3], j[1], j[4]], [j[5], j[4], j[2]]]
}
/// a·v.
pub fn mat_vec(a: &[[f64; 3]; 3], v: V3) -> V3 {
    [0, 1, 2].map(|i| a[i][0] * v[0] + a[i][1] * v[1] + a[i][2] * v[2])
}
/// The product a·b of two 3×3 matrices (row-major).
pub fn mat_mul(a: &[[f64; 3]; 3], b: &[[f64; 3]; 3]) -> [[f64; 3]; 3] {
    let mut c = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            c[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
        }
    }
    c
}
/// aᵀ.
pub fn transpose(a: &[[f64; 3]; 3]) -> [[f64; 3]; 3] {
    [0, 1, 2].map(|i| [a[0][i], a[1][i], a[2][i]])
}
pub use crate::vec3::cross;

/// Solves the 3×3 system A·x = b (Cramer); the inertia is positive definite
/// for a real body. A singular (flat or line-like) body gets no rotation about
/// the singular direction.
fn solve3(a: &[[f64; 3]; 3], b: V3) -> V3 {
    let det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
        - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
        + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    if det.abs() <= f64::MIN_POSITIVE {
        return [0.0; 3];
    }
    let mut x = [0.0; 3];
    for k in 0..3 {
        let mut m = *a;
        for i in 0..3 {
            m[i][k] = b[i];
        }
        x[k] = (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))
            / det;
    }
    x
}

/// Rotation matrix of the rotation vector θ (Rodrigues).
fn rotation(theta: V3) -> [[f64; 3]; 3] {
    let a = (theta[0] * theta[0] + theta[1] * theta[1] + theta[2] * theta[2]).sqrt();
    if a == 0.0 {
        return [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    }
    let k = [theta[0] / a, theta[1] / a, theta[2] / a];
    let (s, c) = a.sin_cos();
    let kx = [[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]];
    let mut r = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            let kk = kx[i][0] * kx[0][j] + kx[i][1] * kx[1][j] + kx[i][2] * kx[2][j];
            r[i][j] = if i == j { 1.0 } else { 0.0 } + s * kx[i][j] + (1.0 - c) * kk;
        }
    }
    r
}

impl RigidBodyState {
    /// The spin ω = J⁻¹L of a body of inertia `inertia` (Jxx, Jyy, Jzz, Jxy,
    /// Jyz, Jxz about its centre) with angular momentum `l` (0 about a
    /// singular direction).
    pub fn spin_of(inertia: &[f64; 6], l: V3) -> V3 {
        solve3(&sym(inertia), l)
    }

    pub fn new(id: u64, mass: f64, center: V3, inertia: [f64; 6], v: V3, omega: V3) -> Self {
        RigidBodyState {
            id,
            mass,
            j0: inertia,
            center,
            center0: center,
            v,
            omega,
            rot: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
        }
    }

    /// Advances the body over one step from the gathered node loads (any
    /// order: they are sorted here, by node and then by value), the main-node external force
    /// `f_main` (e.g. gravity on the added MASS), the velocity step `dt_v`
    /// (from v^{n−1/2} to v^{n+1/2}) and the position step `dt_x`.
    pub fn advance(
        &mut self,
        loads: &mut [NodeLoad],
        f_main: V3,
        dt_v: f64,
        dt_x: f64,
    ) -> (V3, V3) {
        let ft = self.accelerate(loads, f_main, dt_v);
        self.move_by(dt_x);
        ft
    }

    /// The velocities at n+½ from the loads (see [`advance`](Self::advance));
    /// returns the resultant force and moment.
    pub fn accelerate(&mut self, loads: &mut [NodeLoad], f_main: V3, dt_v: f64) -> (V3, V3) {
        // By node, then (loads keyed by the same node: the contact reactions
        // of a node's several facets) by their bits: one order whatever
        // order the ranks gathered them in.
        let bits = |l: &NodeLoad| [l.x, l.f, l.m].map(|v| v.map(f64::to_bits));
        loads.sort_by(|a, b| a.node.cmp(&b.node).then_with(|| bits(a).cmp(&bits(b))));
        let mut f = f_main;
        let mut t = [0.0; 3];
        for l in loads.iter() {
            let r = [
                l.x[0] - self.center[0],
                l.x[1] - self.center[1],
                l.x[2] - self.center[2],
            ];
            let rf = cross(r, l.f);
            for k in 0..3 {
                f[k] += l.f[k];
                t[k] += rf[k] + l.m[k];
            }
        }
        let j = mat_mul(&mat_mul(&self.rot, &sym(&self.j0)), &transpose(&self.rot));
        let jw = mat_vec(&j, self.omega);
        let gyro = cross(self.omega, jw);
        let alpha = solve3(&j, [t[0] - gyro[0], t[1] - gyro[1], t[2] - gyro[2]]);
        for k in 0..3 {
            self.v[k] += f[k] / self.mass * dt_v;
            self.omega[k] += alpha[k] * dt_v;
        }
        (f, t)
    }

    /// The centre and orientation at n+1 with the velocities at n+½.
    pub fn move_by(&mut self, dt_x: f64) {
        for k in 0..3 {
            self.center[k] += self.v[k] * dt_x;
        }
        self.rot = mat_mul(
            &rotation([
                self.omega[0] * dt_x,
                self.omega[1] * dt_x,
                self.omega[2] * dt_x,
            ]),
            &self.rot,
        );
    }

    /// Velocity of a point of the body at position x (at the start of the step).
    pub fn velocity_at(&self, x: V3, center_before: V3) -> V3 {
        let r = [
            x[0] - center_before[0],
            x[1] - center_before[1],
            x[2] - center_before[2],
        ];
        let w = cross(self.omega, r);
        [self.v[0] + w[0], self.v[1] + w[1], self.v[2] + w[2]]
    }

    pub fn kinetic_energy(&self) -> (f64, f64) {
        let t = 0.5
            * self.mass
            * (self.v[0] * self.v[0] + self.v[1] * self.v[1] + self.v[2] * self.v[2]);
        let j = mat_mul(&mat_mul(&self.rot, &sym(&self.j0)), &transpose(&self.rot));
        let jw = mat_vec(&j, self.omega);
        let r = 0.5 * (self.omega[0] * jw[0] + self.omega[1] * jw[1] + self.omega[2] * jw[2]);
        (t, r)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn free_body_keeps_momentum_and_spins_steadily() {
        let mut b = RigidBodyState::new(
            1,
            2.0,
            [0.0; 3],
            [1.0, 2.0, 3.0, 0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 0.0, 0.5],
        );
        for _ in 0..1000 {
            b.advance(&mut [], [0.0; 3], 1e-3, 1e-3);
        }
        assert!((b.v[0] - 1.0).abs() < 1e-15);
        assert!((b.center[0] - 1.0).abs() < 1e-12);
        // Spin about a principal axis stays constant.
        assert!((b.omega[2] - 0.5).abs() < 1e-12 && b.omega[0].abs() < 1e-15);
    }

    #[test]
    fn force_accelerates_and_offset_force_turns() {
        let mut b = RigidBodyState::new(
            1,
            4.0,
            [0.0; 3],
            [1.0, 1.0, 1.0, 0.0, 0.0, 0.0],
            [0.0; 3],
            [0.0; 3],
        );
        let mut loads = [NodeLoad {
            node: 3,
            f: [0.0, 2.0, 0.0],
            m: [0.0; 3],
            x: [1.0, 0.0, 0.0],
        }];
        let (f, t) = b.advance(&mut loads, [0.0; 3], 0.5, 0.5);
        assert_eq!(f, [0.0, 2.0, 0.0]);
        assert_eq!(t, [0.0, 0.0, 2.0]);
        assert!((b.v[1] - 0.25).abs() < 1e-15);
        assert!((b.omega[2] - 1.0).abs() < 1e-15);
    }
}
