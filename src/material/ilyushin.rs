//! Global (resultant) plasticity of a plane-stress shell section: Ilyushin's
//! approximate yield condition, used for shells computed with N = 0 ("global
//! integration": one point for the whole thickness).
//!
//! # Generalized stresses
//! The section carries the membrane resultant N and the moment M (per unit
//! length). They are handled as two plane stress tensors (xx, yy, xy):
//! * s_m = N/t, the mean stress through the thickness;
//! * s_b = 6M/t², the surface stress of the elastic (linear) distribution
//!   that carries M.
//!
//! Elastic law (the same plate law as a through-thickness integration of a
//! linear stress): Δs_m = C Δε, Δs_b = C (t/2) Δκ, C the plane-stress Hooke
//! matrix. So ΔN = t C Δε and ΔM = (t³/12) C Δκ.
//!
//! # Yield condition
//! Ilyushin's approximate yield condition for a homogeneous plane-stress
//! section of a von Mises material (A. A. Ilyushin, *Plasticité*, Eyrolles,
//! Paris 1956, French translation of the 1948 Russian edition; compared with
//! the exact surface in M. Robinson, "A comparison of yield surfaces for thin
//! shells", Int. J. Mech. Sci. 13, 1971):
//!
//! Q_t + Q_m + |Q_tm|/√3 = 1,
//!
//! with n = N/N₀, m = M/M₀, N₀ = σ_y t (membrane yield force), M₀ = σ_y t²/4
//! (fully plastic moment), and the von Mises forms
//! Q_t = P(n, n), Q_m = P(m, m), Q_tm = P(n, m),
//! P(a, b) = a_xx b_xx + a_yy b_yy − ½(a_xx b_yy + a_yy b_xx) + 3 a_xy b_xy.
//! In the generalized stresses this is σ_eq = σ_y with the section's
//! equivalent stress
//!
//! σ_eq² = P(s_m, s_m) + P(q, q) + |P(s_m, q)|/√3,   q = 4M/t² = ⅔ s_b.
//!
//! Pure membrane: σ_eq is the von Mises stress of N/t. Pure bending: the
//! section yields at once over its whole thickness, at M = σ_y t²/4 under a
//! uniaxial moment (the global model has no gradual plastification from the
//! surfaces inwards).
//!
//! The Radioss documentation reachable from this project does not give the
//! reference engine's own global criterion; this is the classical Ilyushin
//! form named above. (The reference engine does not use its global
//! integration for LAW2 at all: its starter switches N = 0 to N = 3 with
//! WARNING 1912, see `element::shell4::n0_rule`.)
//!
//! # Return
//! σ_eq is homogeneous of degree one in (s_m, s_b), so the return is a radial
//! scaling of the trial (N, M): s ← λ s_trial, λ = σ_y(ε̄_p + Δε̄_p)/σ_eq.
//! The equivalent plastic strain is work-conjugate to σ_y: the plastic work
//! of the return per unit volume, (1/t)(N:Δε^p + M:Δκ^p) with the generalized
//! plastic strains Δε^p = C⁻¹(s_m,trial − s_m) and Δκ^p = (2/t)C⁻¹(s_b,trial − s_b)
//! at the returned resultants, is set equal to σ_y Δε̄_p. With
//! W = s_m:C⁻¹s_m + ⅓ s_b:C⁻¹s_b of the trial state this gives
//!
//! σ_eq − E_w Δε̄_p = σ_y(ε̄_p + Δε̄_p),   E_w = σ_eq²/W,
//!
//! solved by safeguarded Newton (bisection fallback). E_w = E for a uniaxial
//! membrane state (the layered radial return) and ⁴⁄₃E for a uniaxial moment;
//! the Iplas flag is not used.
//!
//! Thickness strain: Δε_zz = [−ν(Δε_xx + Δε_yy) + (1−2ν)Δε^p_zz]/(1−ν) of the
//! mid-surface (bending strains average out over the thickness), with the
//! incompressible membrane plastic strain Δε^p_zz = −(Δε^p_xx + Δε^p_yy)
//! taken along the normal of the yield function F(n, m) = Q_t + Q_m + |Q_tm|/√3
//! (associated flow, as the layered update takes the von Mises normal even
//! for its radial return): Δε^p = Δλ/N₀ ∂F/∂n, Δκ^p = Δλ/M₀ ∂F/∂m, with Δλ
//! from the same plastic work, N:Δε^p + M:Δκ^p = 2Δλ F = σ_y t Δε̄_p. This
//! gives Δε^p_zz = −¼Δε̄_p [2(n_xx + n_yy) + sgn(Q_tm)(m_xx + m_yy)/√3] at the
//! returned state (−½Δε̄_p for a uniaxial membrane, as the layered update).

use super::point::{PlaneStressResult, PointLaw};
use super::return_map::scalar_return;

const INV_SQRT3: f64 = 0.577_350_269_189_625_8; // 1/√3

/// Von Mises bilinear form P(a, b) of two plane tensors (xx, yy, xy).
#[inline(always)]
fn p2(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] - 0.5 * (a[0] * b[1] + a[1] * b[0]) + 3.0 * a[2] * b[2]
}

/// s:C⁻¹s for a plane stress tensor (compliance of plane-stress Hooke).
#[inline(always)]
fn compliance2(s: &[f64; 3], e: f64, nu: f64, g: f64) -> f64 {
    (s[0] * s[0] + s[1] * s[1] - 2.0 * nu * s[0] * s[1]) / e + s[2] * s[2] / g
}

/// Ilyushin equivalent stress of the section (see the module doc): √(P(s_m) + P(q) + |P(s_m, q)|/√3), q = ⅔ s_b.
#[inline]
pub fn ilyushin_equivalent(s_m: &[f64; 3], s_b: &[f64; 3]) -> f64 {
    let q = [2.0 / 3.0 * s_b[0], 2.0 / 3.0 * s_b[1], 2.0 / 3.0 * s_b[2]];
    (p2(s_m, s_m) + p2(&q, &q) + INV_SQRT3 * p2(s_m, &q).abs()).sqrt()
}

impl PointLaw<'_> {
    /// Global (N = 0) update of a section (see the module doc): `s_m` = N/t and
    /// `s_b` = 6M/t² in the local frame, updated in place from the membrane
    /// strain increment `de_m` and the surface bending strain increment
    /// `de_b` = (t/2)Δκ (engineering shears); `eps_p` is the section's
    /// equivalent plastic strain. `d_wplas` is the plastic work per unit
    /// volume, `d_ezz` the mid-surface thickness strain increment. A section
    /// whose ε̄_p reaches EPS_p_max fails (zero resultants from then on).
    pub fn section_global(
        &self,
        s_m: &mut [f64; 3],
        s_b: &mut [f64; 3],
        eps_p: &mut f64,
        de_m: [f64; 3],
        de_b: [f64; 3],
    ) -> PlaneStressResult {
        if self.has_failed(*eps_p) {
            *s_m = [0.0; 3];
            *s_b = [0.0; 3];
            return PlaneStressResult {
                failed: true,
                ..Default::default()
            };
        }
        let (e, nu, g) = (self.e, self.nu, self.g);
        let a11 = e / (1.0 - nu * nu);
        for (s, d) in [(&mut *s_m, de_m), (&mut *s_b, de_b)] {
            s[0] += a11 * (d[0] + nu * d[1]);
            s[1] += a11 * (nu * d[0] + d[1]);
            s[2] += g * d[2];
        }
        let ezz_el = -nu * (de_m[0] + de_m[1]);
        let elastic = PlaneStressResult {
            d_ezz: ezz_el / (1.0 - nu),
            ..Default::default()
        };
        let Some(flow) = self.hardening else {
            return elastic;
        };
        let seq = ilyushin_equivalent(s_m, s_b);
        let y0 = flow.sig_y(*eps_p);
        if seq <= y0 {
            return elastic;
        }
        let w = compliance2(s_m, e, nu, g) + compliance2(s_b, e, nu, g) / 3.0;
        let e_w = seq * seq / w;
        let dep = scalar_return(seq, e_w, *eps_p, &flow);
        let y1 = flow.sig_y(*eps_p + dep);
        let lam = y1 / seq;
        s_m.iter_mut().chain(s_b.iter_mut()).for_each(|c| *c *= lam);
        // Associated flow: Δε^p_zz = −¼Δε̄_p[2 tr n + sgn(Q_tm) tr m/√3],
        // n = s_m/σ_y, m = ⅔s_b/σ_y at the returned state.
        let q = [2.0 / 3.0 * s_b[0], 2.0 / 3.0 * s_b[1], 2.0 / 3.0 * s_b[2]];
        let sgn = match p2(s_m, &q) {
            v if v > 0.0 => 1.0,
            v if v < 0.0 => -1.0,
            _ => 0.0,
        };
        let ezz_p = if y1 > 0.0 {
            -0.25 * dep * (2.0 * (s_m[0] + s_m[1]) + sgn * INV_SQRT3 * (q[0] + q[1])) / y1
        } else {
            0.0
        };
        *eps_p += dep;
        let mut r = PlaneStressResult {
            d_wplas: y1 * dep,
            d_ezz: (ezz_el + (1.0 - 2.0 * nu) * ezz_p) / (1.0 - nu),
            failed: false,
        };
        if self.has_failed(*eps_p) {
            *s_m = [0.0; 3];
            *s_b = [0.0; 3];
            r.failed = true;
        }
        r
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::material::Material;
    use crate::model::{JohnsonCook, Loc, MaterialLaw, MaterialSpec};

    fn jc(b: f64) -> Material {
        Material::from_card(&MaterialSpec {
            id: 1,
            unit_id: 0,
            title: "t".into(),
            rho: 7.8e-6,
            rho_ref: 0.0,
            e: 205.0,
            nu: 0.3,
            law: MaterialLaw::JohnsonCook(JohnsonCook::hardening(0.25, b, 0.52)),
            failures: vec![],
            loc: Loc::default(),
        })
    }

    /// The interaction curve of a uniaxial N and M: n² + m² + |nm|/√3 = 1, with
    /// the ends n = 1 (N = σ_y t) and m = 1 (M = σ_y t²/4).
    #[test]
    fn interaction_curve_of_uniaxial_resultants() {
        let (y, t) = (0.25, 1.5);
        let at = |n: f64, m: f64| {
            let sm = [n * y, 0.0, 0.0];
            let sb = [6.0 * m * y * t * t / 4.0 / (t * t), 0.0, 0.0];
            ilyushin_equivalent(&sm, &sb) / y
        };
        assert!((at(1.0, 0.0) - 1.0).abs() < 1e-15);
        assert!((at(0.0, 1.0) - 1.0).abs() < 1e-15);
        assert!((at(0.0, -1.0) - 1.0).abs() < 1e-15);
        let n: f64 = 0.5;
        let m = (-n * INV_SQRT3 + (n * n / 3.0 - 4.0 * (n * n - 1.0)).sqrt()) / 2.0;
        assert!((at(n, m) - 1.0).abs() < 1e-14 && (at(-n, -m) - 1.0).abs() < 1e-14);
        // Within 2.5 % of the exact rectangular-section curve |m| + n² = 1 at n = ½.
        assert!((m - 0.75).abs() < 0.025 * 0.75, "m = {m}");
    }

    /// A trial beyond yield is scaled radially onto σ_eq = σ_y(ε̄_p) of the
    /// updated plastic strain, and the plastic work equals the work of the
    /// returned resultants on the generalized plastic strains.
    #[test]
    fn return_is_radial_consistent_and_work_conjugate() {
        let (e, nu) = (205.0, 0.3);
        let g = e / (2.0 * (1.0 + nu));
        for b in [0.0, 0.35] {
            let mat = jc(b);
            let law = mat.at(0.0, 298.0);
            for (dm, db) in [
                ([4e-3, 0.0, 0.0], [0.0, 0.0, 0.0]),
                ([0.0, 0.0, 0.0], [3e-3, -1e-3, 0.0]),
                ([2e-3, -1e-3, 1e-3], [-2e-3, 1e-3, 2e-3]),
            ] {
                let (mut sm, mut sb, mut ep) = ([0.01, 0.02, 0.0], [0.0, 0.01, 0.005], 0.01);
                let a11 = e / (1.0 - nu * nu);
                let trial = |s: [f64; 3], d: [f64; 3]| {
                    [
                        s[0] + a11 * (d[0] + nu * d[1]),
                        s[1] + a11 * (nu * d[0] + d[1]),
                        s[2] + g * d[2],
                    ]
                };
                let (tm, tb) = (trial(sm, dm), trial(sb, db));
                let ep0 = ep;
                let r = law.section_global(&mut sm, &mut sb, &mut ep, dm, db);
                assert!(ep > ep0, "b {b}: must yield");
                let y = law.yield_stress(ep);
                let seq = ilyushin_equivalent(&sm, &sb);
                assert!((seq - y).abs() < 1e-12 * y, "b {b}: σ_eq {seq} vs σ_y {y}");
                let lam = sm[0] / tm[0].max(1e-300);
                for k in 0..3 {
                    assert!((sm[k] - lam * tm[k]).abs() < 1e-14);
                    assert!((sb[k] - lam * tb[k]).abs() < 1e-14);
                }
                // (1/t)(N:Δε^p + M:Δκ^p) = s_m:C⁻¹Δs_m + ⅓ s_b:C⁻¹Δs_b.
                let cw = |s: &[f64; 3], d: &[f64; 3]| {
                    (s[0] * d[0] + s[1] * d[1] - nu * (s[0] * d[1] + s[1] * d[0])) / e
                        + s[2] * d[2] / g
                };
                let dsm = [tm[0] - sm[0], tm[1] - sm[1], tm[2] - sm[2]];
                let dsb = [tb[0] - sb[0], tb[1] - sb[1], tb[2] - sb[2]];
                let work = cw(&sm, &dsm) + cw(&sb, &dsb) / 3.0;
                assert!(
                    (r.d_wplas - work).abs() < 1e-12 * work,
                    "b {b}: {} vs {work}",
                    r.d_wplas
                );
            }
        }
    }

    /// Below yield the update is the elastic plate law, for any material.
    #[test]
    fn elastic_below_yield() {
        let mat = jc(0.35);
        let law = mat.at(0.0, 298.0);
        let (mut sm, mut sb, mut ep) = ([0.0; 3], [0.0; 3], 0.0);
        let r = law.section_global(
            &mut sm,
            &mut sb,
            &mut ep,
            [1e-4, 0.0, 0.0],
            [0.0, 2e-4, 0.0],
        );
        let a11 = 205.0 / (1.0 - 0.09);
        assert_eq!(ep, 0.0);
        assert!((sm[0] - a11 * 1e-4).abs() < 1e-15 && (sm[1] - 0.3 * a11 * 1e-4).abs() < 1e-15);
        assert!((sb[1] - a11 * 2e-4).abs() < 1e-15 && (sb[0] - 0.3 * a11 * 2e-4).abs() < 1e-15);
        assert!((r.d_ezz + 0.3 / 0.7 * 1e-4).abs() < 1e-18 && r.d_wplas == 0.0);
    }
}
