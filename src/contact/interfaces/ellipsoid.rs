//! The rigid hyper-ellipsoid of /SURF/ELLIPS, |ξ/a|^n + |η/b|^n + |ζ/c|^n = 1,
//! as TYPE14 (nodes) and TYPE15 (segments) meet it: its geometry as pure
//! functions of the local coordinates ξ (theory manual §8.9–8.10; docs/notes/
//! type6_type14_type15_research.md §2.2–2.3), and where the rigid body
//! that carries it (/RBODY surf_ID) has moved it; its local axes are those
//! of its skew_ID at t = 0 (reference guide /SURF/ELLIPS: the skew gives
//! the initial orientation), then turn with the body.

use super::{CardCommon, PairState};
use crate::contact::friction::{self, FrictionLaw};
use crate::contact::geometry::{self as geo, V3};
use crate::kinematics::rigid_body::{mat_mul, mat_vec, transpose, RigidBodyState};
use crate::model::{self, Ellipsoid};
use serde::{Deserialize, Serialize};

/// F(ξ) = Σ|ξ_k/a_k|^n.
pub fn shape_value(xi: V3, axes: V3, n: u32) -> f64 {
    (0..3).map(|k| (xi[k] / axes[k]).abs().powi(n as i32)).sum()
}

/// ∇F/n = (sgn ξ_k·|ξ_k|^{n−1}/a_k^n)_k.
pub fn shape_gradient(xi: V3, axes: V3, n: u32) -> V3 {
    [0, 1, 2].map(|k| xi[k].signum() * xi[k].abs().powi(n as i32 - 1) / axes[k].powi(n as i32))
}

/// The signed distance of ξ (local) to the ellipsoid, d = (s − 1)·h with
/// s = F^{1/n} and h = 1/|∇F(ξ/s)/n| (the distance from the centre to the
/// tangent plane at ξ/s; Euler's identity ∇F·ξ = n·F), and the outward
/// unit normal at ξ. `None` at the centre.
pub fn distance(xi: V3, axes: V3, n: u32) -> Option<(f64, V3)> {
    let f = shape_value(xi, axes, n);
    if f <= 0.0 {
        return None;
    }
    let s = f.powf(1.0 / n as f64);
    let on = geo::scale(xi, 1.0 / s);
    let h = 1.0 / geo::norm(shape_gradient(on, axes, n));
    let g = shape_gradient(xi, axes, n);
    let gn = geo::norm(g);
    if gn == 0.0 {
        return None;
    }
    Some(((s - 1.0) * h, geo::scale(g, 1.0 / gn)))
}

/// ξ moved along its ray from the centre onto the surface, ξ/F(ξ)^{1/n}
/// (`None` at the centre).
pub fn onto_surface(xi: V3, axes: V3, n: u32) -> Option<V3> {
    let f = shape_value(xi, axes, n);
    (f > 0.0).then(|| geo::scale(xi, f.powf(-1.0 / n as f64)))
}

/// The point of the surface whose outward normal is the unit vector `m`
/// (the support point in direction m): ∇F ∥ m gives
/// ξ_k = sgn m_k·(|m_k|·a_k^n)^{1/(n−1)}, scaled onto F = 1.
pub fn support(m: V3, axes: V3, n: u32) -> V3 {
    let e = 1.0 / (n as f64 - 1.0);
    let u = [0, 1, 2].map(|k| m[k].signum() * (m[k].abs() * axes[k].powi(n as i32)).powf(e));
    onto_surface(u, axes, n).unwrap_or([0.0; 3])
}

/// Where the ellipsoid is: its centre and the rotation from its axes to
/// the global ones (row-major).
pub struct Pose {
    pub center: V3,
    pub rot: [[f64; 3]; 3],
}

impl Pose {
    /// Global x in the ellipsoid's axes.
    pub fn local(&self, x: V3) -> V3 {
        mat_vec(&transpose(&self.rot), geo::sub(x, self.center))
    }
    /// A local vector in global axes.
    pub fn turn(&self, v: V3) -> V3 {
        mat_vec(&self.rot, v)
    }
    /// A local point in global coordinates.
    pub fn global(&self, xi: V3) -> V3 {
        geo::add(self.center, self.turn(xi))
    }
}

/// The ellipsoid of an interface's main side and the rigid body carrying it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Carried {
    pub ellipsoid: Ellipsoid,
    /// The /RBODY whose surf_ID names the ellipsoid (index; `None`: it stays
    /// where it is), its mass, and the ellipsoid's centre relative to the
    /// body's centre at t = 0.
    pub body: Option<usize>,
    pub body_mass: f64,
    pub offset: V3,
    /// The ellipsoid's axes at t = 0 (its skew_ID's, as columns; `None`:
    /// the global axes).
    pub axes0: Option<[[f64; 3]; 3]>,
}

/// The /SURF/ELLIPS `surf_idm` of card `kw` and its body; a surface of
/// another kind, or a skew that is not defined or degenerate, is an error
/// naming the field.
pub fn bind(m: &model::Model, surf_idm: model::Id, kw: &str) -> Result<Carried, String> {
    let e = m
        .surfaces
        .iter()
        .find(|s| s.id == surf_idm)
        .and_then(|s| s.ellipsoid.clone())
        .ok_or_else(|| format!("{kw}, field surf_IDm: /SURF/{surf_idm} is not a /SURF/ELLIPS"))?;
    let axes0 = match e.skew_id {
        0 => None,
        id => {
            let rows = m
                .skews
                .iter()
                .find(|s| s.id == id)
                .and_then(|s| s.axes(&m.nodes.x))
                .ok_or_else(|| {
                    format!(
                        "{kw}, field surf_IDm: /SURF/ELLIPS/{surf_idm} names skew_ID {id}, \
                         which is not a defined /SKEW with independent axes"
                    )
                })?;
            Some(transpose(&rows))
        }
    };
    let body = m
        .rigid_bodies
        .iter()
        .position(|b| b.card.surf_id == surf_idm);
    let (body_mass, offset) = match body.map(|b| &m.rigid_bodies[b]) {
        Some(b) => (b.mass, geo::sub(e.center, b.center)),
        None => (0.0, [0.0; 3]),
    };
    Ok(Carried {
        ellipsoid: e,
        body,
        body_mass,
        offset,
        axes0,
    })
}

impl Carried {
    /// The ellipsoid's pose now: its axes those of its skew at t = 0
    /// (`axes0`), carried by its body (centre = body centre + the turned
    /// offset, axes turned with it) or where the deck put it.
    pub fn pose(&self, bodies: &[RigidBodyState]) -> Pose {
        const I: [[f64; 3]; 3] = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        let a0 = self.axes0.as_ref().unwrap_or(&I);
        match self.body.and_then(|b| bodies.get(b)) {
            Some(b) => Pose {
                center: geo::add(b.center, mat_vec(&b.rot, self.offset)),
                rot: mat_mul(&b.rot, a0),
            },
            None => Pose {
                center: self.ellipsoid.center,
                rot: *a0,
            },
        }
    }

    /// The velocity of the surface at global point x: the body's motion
    /// there (a fixed ellipsoid's is 0).
    pub fn surface_velocity(&self, bodies: &[RigidBodyState], x: V3) -> V3 {
        match self.body.and_then(|b| bodies.get(b)) {
            Some(b) => geo::add(b.v, geo::cross(b.omega, geo::sub(x, b.center))),
            None => [0.0; 3],
        }
    }
}

/// The options every ellipsoid card shares: Coulomb friction Fric
/// (incremental), the gap, active from 0 to the end (Tstart and Tstop are
/// not on the cards), no IBC, Inacti or Idel.
pub fn card_common(fric: f64, gap: f64) -> CardCommon {
    CardCommon {
        stfac: 1.0,
        friction: FrictionLaw {
            fric,
            iform: 2,
            ..FrictionLaw::none()
        },
        gap_card: gap,
        tstart: 0.0,
        tstop: model::contact::EP30,
        ibc: [false; 3],
        inacti: 0,
        idel: 0,
    }
}

/// Coulomb friction of one contact on the ellipsoid (§8.9: "a local
/// friction coefficient is computed at each impacted node"; §8.10: F_t ≤
/// μ·F_n for each penetrated element; the reference engine's form, docs/
/// notes/type6_type14_type15_research.md §2.2–2.3): an elastic tangential
/// spring of the contact's normal stiffness `k` on its slip `v_rel`
/// relative to the surface, capped at μ·max(F_n, 0); only for a contact
/// already made at the last cycle (the impact's cycle takes none). `law`
/// is the interface's (Fric, incremental); `st.ft` keeps the force,
/// `st.side` marks the contact.
#[allow(clippy::too_many_arguments)]
pub fn friction(
    law: &FrictionLaw,
    mu: f64,
    k: f64,
    f_n: f64,
    v_rel: V3,
    n: V3,
    dt: f64,
    st: &mut PairState,
) -> V3 {
    let impacted_before = st.side != 0;
    st.side = 1;
    if !law.active() || !impacted_before {
        return [0.0; 3];
    }
    let vt = friction::tangential(v_rel, n);
    friction::tangential_force(law, mu, f_n.max(0.0), vt, n, k, 0.0, dt, &mut st.ft)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_distance_is_exact_on_a_sphere_and_on_the_axes_of_an_ellipsoid() {
        let (d, n) = distance([3.0, 4.0, 0.0], [2.0; 3], 2).unwrap();
        assert!((d - 3.0).abs() < 1e-14);
        assert!((n[0] - 0.6).abs() < 1e-14 && (n[1] - 0.8).abs() < 1e-14);
        let (d, n) = distance([0.0, 0.0, 1.5], [3.0, 2.0, 1.0], 2).unwrap();
        assert!((d - 0.5).abs() < 1e-14, "{d}");
        assert_eq!(n, [0.0, 0.0, 1.0]);
        let (d, _) = distance([0.0, -1.0, 0.0], [3.0, 2.0, 1.0], 4).unwrap();
        assert!((d + 1.0).abs() < 1e-14, "{d}");
        assert!(distance([0.0; 3], [1.0; 3], 2).is_none());
    }

    #[test]
    fn the_support_point_lies_on_the_surface_with_the_normal_asked() {
        // Sphere: r·m.
        let s = support([0.0, 0.6, -0.8], [5.0; 3], 2);
        assert!(geo::norm(geo::sub(s, [0.0, 3.0, -4.0])) < 1e-12, "{s:?}");
        // Ellipsoid and hyper-ellipsoid: on F = 1, the normal there is m.
        for (axes, n) in [([3.0, 2.0, 1.0], 2), ([3.0, 2.0, 1.0], 4)] {
            let m = geo::scale([1.0, -2.0, 0.5], 1.0 / geo::norm([1.0, -2.0, 0.5]));
            let s = support(m, axes, n);
            assert!((shape_value(s, axes, n) - 1.0).abs() < 1e-12);
            let g = shape_gradient(s, axes, n);
            let g = geo::scale(g, 1.0 / geo::norm(g));
            assert!(geo::norm(geo::sub(g, m)) < 1e-12, "{g:?} {m:?}");
        }
        // On an axis: the semi-axis.
        let s = support([0.0, 0.0, 1.0], [3.0, 2.0, 1.0], 2);
        assert!(geo::norm(geo::sub(s, [0.0, 0.0, 1.0])) < 1e-14);
    }
}
