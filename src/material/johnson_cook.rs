//! LAW2 (Johnson-Cook) flow stress and the return maps that use it.
//!
//! Flow stress (reference guide /MAT/LAW2, theory manual "Johnson-Cook plasticity
//! model"):
//!
//! σ_y = (a + b·ε_p^n) · (1 + c·ln(ε̇/ε̇₀)) · (1 − T*^m),  capped at σ_max,
//!
//! with the rate factor only when c ≠ 0 and ε̇ > ε̇₀ (below ε̇₀ the factor is 1),
//! the thermal factor only when ρC_p is given (T* = (T − T_r)/(T_melt − T_r),
//! clamped to [0, 1]), and σ_max = SIG_max0 · (rate · thermal factor) for ICC = 1,
//! SIG_max0 alone for ICC = 2. Hardening is isotropic (Chard = 0); the engine
//! refuses Chard ≠ 0 (see [`super::Material::check_supported`]).
//!
//! The law itself is `super::law2`; the return maps that use this curve are
//! `super::return_map` (through [`super::Hardening::JohnsonCook`]).

/// ε_p floor for the hardening slope b·n·ε_p^(n−1) at ε_p = 0 with n < 1.
const EPS_SMALL: f64 = 1e-10;

/// Flow-stress curve at one update: σ_y(ε_p) = min(a + b·ε_p^n, cap), where
/// a, b and cap already include the rate and thermal factors.
#[derive(Clone, Copy, Debug)]
pub struct Flow {
    pub a: f64,
    pub b: f64,
    pub n: f64,
    pub cap: f64,
}

impl Flow {
    /// `q` = rate factor × thermal factor (≥ 1e-20), `icc` selects whether the cap scales with it.
    #[inline]
    pub fn new(a: f64, b: f64, n: f64, sig_max0: f64, icc: i64, q: f64) -> Flow {
        Flow {
            a: a * q,
            b: b * q,
            n,
            cap: if icc == 2 { sig_max0 } else { sig_max0 * q },
        }
    }

    #[inline]
    pub fn sig_y(&self, ep: f64) -> f64 {
        let s = if ep > 0.0 {
            self.a + self.b * ep.powf(self.n)
        } else {
            self.a
        };
        s.min(self.cap)
    }

    /// dσ_y/dε_p (0 on the cap).
    #[inline]
    pub fn slope(&self, ep: f64) -> f64 {
        if self.sig_y(ep) >= self.cap || self.b == 0.0 {
            0.0
        } else {
            self.b * self.n * ep.max(EPS_SMALL).powf(self.n - 1.0)
        }
    }
}

/// Rate factor 1 + c·ln(ε̇/ε̇₀) for ε̇ > ε̇₀ (else 1).
#[inline]
pub(super) fn rate_factor(c: f64, eps_dot_0: f64, eps_dot: f64) -> f64 {
    if c != 0.0 && eps_dot > eps_dot_0 {
        1.0 + c * (eps_dot / eps_dot_0).ln()
    } else {
        1.0
    }
}

/// Thermal factor 1 − T*^m (1 when ρC_p is not given or T ≤ T_r).
#[inline]
pub(super) fn thermal_factor(rho_cp: f64, t_r: f64, t_melt: f64, m: f64, temp: f64) -> f64 {
    if rho_cp >= crate::model::NO_LIMIT || temp <= t_r || t_melt >= crate::model::NO_LIMIT {
        return 1.0;
    }
    let ts = ((temp - t_r) / (t_melt - t_r)).clamp(0.0, 1.0);
    1.0 - ts.powf(m)
}
