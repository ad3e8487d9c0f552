//! Return maps of J2 (von Mises) plasticity with isotropic hardening, for
//! any flow-stress curve σ_y(ε_p) a law supplies as a [`Hardening`].
//!
//! The plane-stress returns follow the three Radioss options of the shell
//! property's Iplas flag (reference guide /PROP/TYPE1, and the behaviour of the
//! reference engine's LAW2 shell routine):
//! * Iplas = 0: radial return — the trial stress is scaled to the yield stress
//!   of the start of the step, Δε_p = (σ_vm − σ_y)/E;
//! * Iplas = 1: exact plane-stress projection (Simo & Taylor 1986; Simo & Hughes,
//!   *Computational Inelasticity*, §3.4), Newton iterations on Δε_p to machine
//!   precision;
//! * Iplas = 2: one projection along an approximate normal, then radial scaling
//!   to the yield stress updated with the tangent modulus.
//!
//! Solids use the 3-D radial return, N = 0 shell sections the scalar return
//! of `super::ilyushin`.

use super::hardening::Hardening;

#[inline]
fn vm_plane(s: &[f64; 3]) -> f64 {
    (s[0] * s[0] + s[1] * s[1] - s[0] * s[1] + 3.0 * s[2] * s[2]).sqrt()
}

/// Plane-stress return from the trial stress `s` (modified in place).
/// Returns (Δε_p, plastic thickness strain Δε^p_zz); (0, 0) when elastic.
pub(super) fn plane_stress_return(
    s: &mut [f64; 3],
    ep: f64,
    f: &Hardening,
    e: f64,
    nu: f64,
    g: f64,
    iplas: i64,
) -> (f64, f64) {
    let svm2 = s[0] * s[0] + s[1] * s[1] - s[0] * s[1] + 3.0 * s[2] * s[2];
    // Cheap elastic test first: below the initial yield stress (a lower bound of
    // σ_y when b ≥ 0) no power of ε_p is needed.
    if let Some(y_low) = f.elastic_bound() {
        if svm2 <= y_low * y_low {
            return (0.0, 0.0);
        }
    }
    let y0 = f.sig_y(ep);
    if svm2 <= y0 * y0 {
        return (0.0, 0.0);
    }
    let svm = svm2.sqrt();
    let dep = match iplas {
        1 => newton_plane_stress(s, ep, f, e, nu, g),
        2 => {
            // Approximate normal projection, then radial scaling to the
            // yield stress advanced with the tangent modulus.
            let h = f.slope(ep);
            let aa = (svm2 - y0 * y0) / (5.0 * svm2 + 3.0 * (-s[0] * s[1] + s[2] * s[2]));
            let s1 = (1.0 - 2.0 * aa) * s[0] + aa * s[1];
            let s2 = aa * s[0] + (1.0 - 2.0 * aa) * s[1];
            let s3 = (1.0 - 3.0 * aa) * s[2];
            *s = [s1, s2, s3];
            let dep = (svm - y0) / (3.0 * g + h);
            let y1 = (y0 + h * dep).min(f.cap());
            let r = (y1 / vm_plane(s).max(1e-300)).min(1.0);
            s.iter_mut().for_each(|c| *c *= r);
            dep
        }
        _ => {
            // Radial return (Iplas = 0).
            let r = y0 / svm;
            s.iter_mut().for_each(|c| *c *= r);
            (svm - y0) / e
        }
    };
    // Incompressible plastic flow along the normal: Δε^p_zz = −Δε_p (σxx+σyy)/(2σ_y).
    let y = vm_plane(s).max(1e-300);
    (dep, -dep * 0.5 * (s[0] + s[1]) / y)
}

/// Exact plane-stress return: with S1 = σxx+σyy, S2 = σxx−σyy, S3 = σxy of the
/// trial state, the returned stress is S1/(1 + E Δλ/(3(1−ν))), (S2, S3)/(1 + 2GΔλ)
/// with Δλ = 3Δε_p/(2σ_y(ε_p+Δε_p)); Δε_p solves
/// F = ¼S1²P² + (¾S2² + 3S3²)Q² − σ_y² = 0 (F strictly decreasing in Δε_p).
/// Safeguarded Newton (bisection fallback) to relative 1e-14.
fn newton_plane_stress(s: &mut [f64; 3], ep: f64, f: &Hardening, e: f64, nu: f64, g: f64) -> f64 {
    let s1 = s[0] + s[1];
    let s2 = s[0] - s[1];
    let s3 = s[2];
    let a = 0.25 * s1 * s1;
    let b = 0.75 * s2 * s2 + 3.0 * s3 * s3;
    let nu1 = 1.0 / (1.0 - nu);
    let nu2 = 3.0 / (1.0 + nu);
    let eval = |dep: f64| -> (f64, f64, f64, f64) {
        let y = f.sig_y(ep + dep);
        let h = f.slope(ep + dep);
        let dr = 0.5 * e * dep / y;
        let p = 1.0 / (1.0 + dr * nu1);
        let q = 1.0 / (1.0 + dr * nu2);
        let fv = a * p * p + b * q * q - y * y;
        let df =
            -(a * nu1 * p * p * p + b * nu2 * q * q * q) * (e - 2.0 * dr * h) / y - 2.0 * h * y;
        (fv, df, p, q)
    };
    let svm = (a + b).sqrt();
    let y0 = f.sig_y(ep);
    // Bracket: F(0) > 0; find hi with F(hi) ≤ 0.
    let mut lo = 0.0;
    let mut hi = (svm - y0) / (3.0 * g) + 1e-300;
    let mut k = 0;
    while eval(hi).0 > 0.0 && k < 200 {
        lo = hi;
        hi *= 2.0;
        k += 1;
    }
    let mut x = ((svm - y0) / (3.0 * g + f.slope(ep))).clamp(lo, hi);
    let mut pq = (1.0, 1.0);
    for _ in 0..100 {
        let (fv, df, p, q) = eval(x);
        pq = (p, q);
        if fv > 0.0 {
            lo = x;
        } else {
            hi = x;
        }
        let mut xn = if df < 0.0 {
            x - fv / df
        } else {
            0.5 * (lo + hi)
        };
        if !(xn > lo && xn < hi) {
            xn = 0.5 * (lo + hi);
        }
        let done = (xn - x).abs() <= 1e-14 * x.abs().max(1e-300) || hi - lo <= 1e-15 * hi;
        x = xn;
        if done {
            let (_, _, p, q) = eval(x);
            pq = (p, q);
            break;
        }
    }
    let n1 = s1 * pq.0;
    let n2 = s2 * pq.1;
    *s = [0.5 * (n1 + n2), 0.5 * (n1 - n2), s3 * pq.1];
    x
}

/// 3-D radial return (Wilkins; Simo & Hughes Box 3.2) from the trial stress `s`
/// (σxx σyy σzz σxy σyz σzx). Returns Δε_p; Newton on
/// σ_vm − 3GΔε_p − σ_y(ε_p + Δε_p) = 0.
pub(super) fn radial_return_3d(s: &mut [f64; 6], ep: f64, f: &Hardening, g: f64) -> f64 {
    let p = (s[0] + s[1] + s[2]) / 3.0;
    let d = [s[0] - p, s[1] - p, s[2] - p];
    let j2 =
        0.5 * (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) + s[3] * s[3] + s[4] * s[4] + s[5] * s[5];
    let svm = (3.0 * j2).sqrt();
    let y0 = f.sig_y(ep);
    if svm <= y0 {
        return 0.0;
    }
    let x = scalar_return(svm, 3.0 * g, ep, f);
    let k = 1.0 - 3.0 * g * x / svm;
    s[0] = p + k * d[0];
    s[1] = p + k * d[1];
    s[2] = p + k * d[2];
    s[3] *= k;
    s[4] *= k;
    s[5] *= k;
    x
}

/// Δε_p of a radial return: the root of r(x) = σ_eq − k x − σ_y(ε_p + x)
/// (strictly decreasing; r(0) > 0 when called, r(σ_eq/k) ≤ 0), by Newton
/// safeguarded with bisection, to relative 1e-14.
pub(super) fn scalar_return(seq: f64, k: f64, ep: f64, f: &Hardening) -> f64 {
    let (mut lo, mut hi) = (0.0, seq / k);
    let mut x = (seq - f.sig_y(ep)) / (k + f.slope(ep));
    x = x.clamp(lo, hi);
    for _ in 0..100 {
        let r = seq - k * x - f.sig_y(ep + x);
        if r > 0.0 {
            lo = x;
        } else {
            hi = x;
        }
        let dr = -k - f.slope(ep + x);
        let mut xn = x - r / dr;
        if !(xn > lo && xn < hi) {
            xn = 0.5 * (lo + hi);
        }
        let done = (xn - x).abs() <= 1e-14 * x.abs().max(1e-300) || hi - lo <= 1e-15 * hi;
        x = xn;
        if done {
            break;
        }
    }
    x
}
