//! The orthotropic material frame of a /PROP/TYPE6 (SOL_ORTH) brick and the
//! law update in it (research notes `docs/notes/law28_sol_orth_research.md`
//! §2.3-2.4 and `docs/notes/law12_research.md` §2).
//!
//! * Element axes from the corners (Radioss order 1-4 bottom, 5-8 top):
//!   R = (x3+x4+x7+x8) − (x1+x2+x5+x6), S = (x5+x6+x7+x8) − (x1+x2+x3+x4);
//!   e1 = R/|R|, e3 = e1×S/|e1×S|, e2 = e3×e1.
//! * Directions at t = 0 (angle φ): Ip 1: d1 = c e1 + s e2, d2 = −s e1 + c e2;
//!   Ip 2: d1 = c e2 + s e3, d2 = −s e2 + c e3; Ip 3: d1 = s e1 + c e3,
//!   d2 = c e1 − s e3; Ip 0: the global X and Y axes (skew 0). They are
//!   kept as components in the element axes (GAMA) and follow those axes
//!   (Iframe 1: recomputed from the corners each step; the co-rotational
//!   HEPH keeps them in its own frame).
//! * The law sees the stress Tᵀ = Qᵀ σ Q and the strain increment in the
//!   frame Q = [d1 d2 d3] (d3 = d1×d2); its stress goes back as Q T Qᵀ.

use crate::material::{Law12, Law12Point};
use crate::model::SolidOrtho;
use crate::vec3::{cross, dot, norm, scale, sub, V3};
use serde::{Deserialize, Serialize};

/// Per-element orthotropic state: the directions in the element axes and
/// the law's point state.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct OrthoState {
    /// d1 and d2 in the element axes (e1, e2, e3 components).
    pub gama: [f64; 6],
    pub point: Law12Point,
}

/// What the engine cannot compute of a section's directions, by name.
pub fn refusal(o: &SolidOrtho) -> Option<String> {
    if o.skew_id != 0 {
        return Some(format!(
            "/PROP/TYPE6 with skew_ID = {}: directions from a skew are not computed yet",
            o.skew_id
        ));
    }
    if o.iorth != 0 {
        return Some("/PROP/TYPE6 with Iorth = 1 (directions in the element's own non-orthogonal axes) is not computed yet".into());
    }
    if !(0..=3).contains(&o.ip) {
        return Some(format!(
            "/PROP/TYPE6 with Ip = {}: the engine computes Ip 0 (skew axes), 1, 2 and 3 (angle φ in an element plane)",
            o.ip
        ));
    }
    None
}

/// The element axes e1, e2, e3 of the corners (module doc).
pub fn element_axes(x: &[[f64; 3]; 8]) -> [V3; 3] {
    let sum = |ids: [usize; 4]| {
        let mut s = [0.0; 3];
        for i in ids {
            for k in 0..3 {
                s[k] += x[i][k];
            }
        }
        s
    };
    let r = sub(sum([2, 3, 6, 7]), sum([0, 1, 4, 5]));
    let s = sub(sum([4, 5, 6, 7]), sum([0, 1, 2, 3]));
    let e1 = scale(r, 1.0 / norm(r));
    let n = cross(e1, s);
    let e3 = scale(n, 1.0 / norm(n));
    [e1, cross(e3, e1), e3]
}

/// d1, d2 at t = 0 as components in the axes `e` (GAMA).
pub fn initial_gama(o: &SolidOrtho, e: &[V3; 3]) -> [f64; 6] {
    let (s, c) = o.phi.to_radians().sin_cos();
    let (d1, d2): (V3, V3) = match o.ip {
        1 => ([c, s, 0.0], [-s, c, 0.0]),
        2 => ([0.0, c, s], [0.0, -s, c]),
        3 => ([s, 0.0, c], [c, 0.0, -s]),
        _ => {
            let x = [1.0, 0.0, 0.0];
            let y = [0.0, 1.0, 0.0];
            (e.map(|ek| dot(x, ek)), e.map(|ek| dot(y, ek)))
        }
    };
    [d1[0], d1[1], d1[2], d2[0], d2[1], d2[2]]
}

/// The material axes (rows d1, d2, d3) of the directions `gama` in the
/// axes `e` (global components when `e` is global, local when local).
pub fn material_axes(gama: &[f64; 6], e: &[V3; 3]) -> [V3; 3] {
    let comb = |g: &[f64]| [0, 1, 2].map(|k| g[0] * e[0][k] + g[1] * e[1][k] + g[2] * e[2][k]);
    let d1 = comb(&gama[..3]);
    let d2 = comb(&gama[3..]);
    let d3 = cross(d1, d2);
    [d1, d2, d3]
}

/// a σ aᵀ of a Voigt tensor (rows of `a` the new axes).
fn rotate(a: &[V3; 3], s: &[f64; 6]) -> [f64; 6] {
    crate::vec3::rotate_voigt(a, s)
}

/// The law's update in the material axes `a` (rows, in the components of
/// `sig` and `deps`): stress `sig`, plastic work `wp`, engineering strain
/// increment `deps`; returns the plastic work per unit volume.
pub fn update(
    law: &Law12,
    a: &[V3; 3],
    sig: &mut [f64; 6],
    wp: &mut f64,
    st: &mut OrthoState,
    deps: [f64; 6],
) -> f64 {
    let half = |e: [f64; 6]| [e[0], e[1], e[2], 0.5 * e[3], 0.5 * e[4], 0.5 * e[5]];
    let mut t = rotate(a, sig);
    let e = rotate(a, &half(deps));
    let de = [e[0], e[1], e[2], 2.0 * e[3], 2.0 * e[4], 2.0 * e[5]];
    let w = law.update(&mut t, wp, &mut st.point, de);
    let at = [0, 1, 2].map(|i| [a[0][i], a[1][i], a[2][i]]);
    *sig = rotate(&at, &t);
    w
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The unit cube in Radioss order (1-4 bottom, 5-8 top).
    const CUBE: [[f64; 3]; 8] = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
        [1.0, 0.0, 1.0],
        [1.0, 1.0, 1.0],
        [0.0, 1.0, 1.0],
    ];

    fn ortho(ip: i64, phi: f64) -> SolidOrtho {
        SolidOrtho {
            v: [0.0; 3],
            skew_id: 0,
            ip,
            iorth: 0,
            phi,
        }
    }

    fn close(a: V3, b: V3) -> bool {
        (0..3).all(|k| (a[k] - b[k]).abs() < 1e-12)
    }

    /// R (1→4) is +y and S (1→5) +z: e1 = y, e3 = e1×S = x, e2 = z; Ip 1
    /// puts d1 on e1, Ip 2 on e2, Ip 3 on e3 (φ = 0), Ip 0 on global X —
    /// the table of research note law12_research.md §2.1.
    #[test]
    fn directions_follow_ip_in_the_element_axes() {
        let e = element_axes(&CUBE);
        assert!(
            close(e[0], [0.0, 1.0, 0.0])
                && close(e[1], [0.0, 0.0, 1.0])
                && close(e[2], [1.0, 0.0, 0.0])
        );
        let axes = |ip| material_axes(&initial_gama(&ortho(ip, 0.0), &e), &e);
        let a = axes(1);
        assert!(
            close(a[0], [0.0, 1.0, 0.0])
                && close(a[1], [0.0, 0.0, 1.0])
                && close(a[2], [1.0, 0.0, 0.0])
        );
        let a = axes(2);
        assert!(
            close(a[0], [0.0, 0.0, 1.0])
                && close(a[1], [1.0, 0.0, 0.0])
                && close(a[2], [0.0, 1.0, 0.0])
        );
        assert!(close(axes(3)[0], [1.0, 0.0, 0.0]));
        let a = axes(0);
        assert!(close(a[0], [1.0, 0.0, 0.0]) && close(a[1], [0.0, 1.0, 0.0]));
        // φ = 30° turns d1 from e1 towards e2.
        let a = material_axes(&initial_gama(&ortho(1, 30.0), &e), &e);
        let (s, c) = 30f64.to_radians().sin_cos();
        assert!(close(a[0], [0.0, c, s]));
    }

    /// A strain along d1 (at 30° in the global x-y plane) in a composite
    /// stiff along 1 only gives the stress E11·ε along d1 in global
    /// components, and the frame's rotation is undone exactly.
    #[test]
    fn the_law_works_in_the_material_axes() {
        use crate::material::law12::tests::{law, params};
        let mut p = params();
        p.e = [100.0, 1.0, 1.0];
        p.nu = [0.0; 3];
        p.g = [0.0; 3];
        let law = law(&p);
        let (s, c) = 30f64.to_radians().sin_cos();
        let d1 = [c, s, 0.0];
        let axes = [d1, [-s, c, 0.0], [0.0, 0.0, 1.0]];
        let eps = 0.01;
        // ε = eps·d1⊗d1 in engineering Voigt components.
        let deps = [eps * c * c, eps * s * s, 0.0, 2.0 * eps * c * s, 0.0, 0.0];
        let (mut sig, mut wp, mut st) = ([0.0; 6], 0.0, OrthoState::default());
        update(&law, &axes, &mut sig, &mut wp, &mut st, deps);
        let t = 100.0 * eps;
        let want = [t * c * c, t * s * s, 0.0, t * c * s, 0.0, 0.0];
        for k in 0..6 {
            assert!((sig[k] - want[k]).abs() < 1e-12, "{sig:?} vs {want:?}");
        }
    }
}
