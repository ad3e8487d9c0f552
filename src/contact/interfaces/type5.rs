//! TYPE5 node-to-surface contact (theory manual §8.6), also each pass of
//! TYPE3 (§8.5.2): the node is penetrated when it is on the negative side of
//! its closest main segment (tetrahedron volume sign, §8.6.6.3) or within the
//! gap on the positive side; the reaction is a linear spring F = K·p along
//! the segment normal (EQ. 8.6.6.3) spread by the shape functions of the
//! contact point (EQ. 8.6.6.6); friction is incremental Coulomb with
//! Kt = K/10 (EQ. 8.5.4.1–4) and the Ifric laws and filter of §8.6.4.

use super::{PairForce, PairState};
use crate::contact::friction::{self, FrictionLaw};
use crate::contact::geometry::{self as geo, V3};

pub struct Pair<'a> {
    pub xs: V3,
    pub vs: V3,
    pub xm: &'a [V3; 4],
    pub vm: &'a [V3; 4],
    pub tri: bool,
    /// Interface spring stiffness K (EQ. 8.5.3.1 / 8.6.3.1).
    pub k: f64,
    pub gap: f64,
    pub friction: &'a FrictionLaw,
    pub area: f64,
    pub dt: f64,
}

/// Depth of the node below the segment's gap surface, if it projects inside
/// the segment: `gap − (x − c)·n` (positive when penetrated).
pub fn penetration(xs: V3, xm: &[V3; 4], tri: bool, gap: f64) -> Option<(f64, geo::Projection)> {
    let pr = geo::project(xs, xm, tri);
    let d = geo::sub(xs, pr.point);
    let ds = geo::dot(d, pr.normal);
    // Beyond an edge the closest point leaves the face: not this segment's contact.
    let off = geo::norm(friction::tangential(d, pr.normal));
    let size = geo::segment_area(xm, tri).sqrt();
    if off > 1e-6 * size {
        return None;
    }
    // `ds` has the sign of the tetrahedron (node, segment) volume (§8.6.6.3):
    // negative once the node is through the segment.
    Some((gap - ds, pr))
}

pub fn pair(p: &Pair, st: &mut PairState) -> Option<PairForce> {
    let (pen, pr) = penetration(p.xs, p.xm, p.tri, p.gap)?;
    if pen <= 0.0 {
        st.ft = [0.0; 3];
        st.ff = [0.0; 3];
        return None;
    }
    let n = pr.normal;
    let f_n = p.k * pen;
    let vc = geo::interpolate(&pr.shape, p.vm);
    let vrel = geo::sub(p.vs, vc);
    let mut f_t = [0.0; 3];
    if p.friction.active() {
        let vt = friction::tangential(vrel, n);
        let pressure = if p.area > 0.0 { f_n / p.area } else { 0.0 };
        let mu = p.friction.mu(pressure, geo::norm(vt));
        let raw = friction::tangential_force(
            p.friction,
            mu,
            f_n,
            vt,
            n,
            0.1 * p.k,
            0.0,
            p.dt,
            &mut st.ft,
        );
        let a = p.friction.filter_alpha(p.dt);
        st.ff = geo::add(geo::scale(raw, a), geo::scale(st.ff, 1.0 - a));
        f_t = st.ff;
    }
    let fs = geo::add(geo::scale(n, f_n), f_t);
    Some(PairForce {
        fs,
        shape: pr.shape,
        kt: p.k,
        dt_kin: f64::INFINITY,
        f_n,
        f_t,
        pen,
        dir: n,
        point: pr.point,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_sided_linear_spring() {
        let xm = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
        ];
        let vm = [[0.0; 3]; 4];
        let law = FrictionLaw::none();
        let mut st = PairState::default();
        let mk = |z: f64| Pair {
            xs: [0.3, 0.3, z],
            vs: [0.0; 3],
            xm: &xm,
            vm: &vm,
            tri: false,
            k: 200.0,
            gap: 0.0,
            friction: &law,
            area: 1.0,
            dt: 1e-3,
        };
        assert!(pair(&mk(0.01), &mut st).is_none());
        let f = pair(&mk(-0.01), &mut st).unwrap();
        assert!((f.fs[2] - 2.0).abs() < 1e-12);
        // Beyond the edge: not this segment.
        let mut q = mk(-0.01);
        q.xs = [1.5, 0.3, -0.01];
        assert!(pair(&q, &mut st).is_none());
    }
}
