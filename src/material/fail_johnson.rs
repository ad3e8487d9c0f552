//! /FAIL/JOHNSON: Johnson-Cook damage (reference guide /FAIL/JOHNSON; theory
//! after Johnson & Cook 1985, "Fracture characteristics of three metals").
//!
//! At every integration point, after the material update, with the new stress:
//! * triaxiality σ* = p/σ_vm, p = tr σ/3 (tension positive: uniaxial tension
//!   gives +1/3), σ_vm = √(3/2 s:s);
//! * ε_f = [D1 + D2·exp(D3·σ*)]·[1 + D4·ln(max(1, ε̇/ε̇₀))]·[1 + D5·T*],
//!   then ε_f ← max(ε_f, EPSF_MIN) — the rate factor never drops below 1;
//! * while the point flows (Δε_p > 0) and ε_f > 0: D ← min(1, D + Δε_p/ε_f).
//!   A step with ε_f ≤ 0 adds no damage (it freezes, as the reference engine
//!   does; it is not failure).
//!
//! The point fails at D = 1. Solids (Ifail_so): 1 the element is deleted;
//! 2 the deviatoric stress is removed (σ = p I); 3 only compressive pressure
//! is kept (σ = min(p, 0) I); 4 the stress is zero and the element kept.
//! 2–4 hold on every later step.

use crate::model::JohnsonFailure;
use serde::{Deserialize, Serialize};

/// /FAIL/JOHNSON parameters, as the model gives them (defaults resolved).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct FailJohnson {
    pub d: [f64; 5],
    pub eps_dot_0: f64,
    pub ifail_sh: i64,
    pub ifail_so: i64,
    pub epsf_min: f64,
}

impl FailJohnson {
    /// From the card; XFEM cracks (Ixfem) are refused by name.
    pub fn new(j: &JohnsonFailure) -> Result<FailJohnson, String> {
        if j.ixfem != 0 {
            return Err(format!(
                "/FAIL/JOHNSON: Ixfem = {}: XFEM crack propagation is not computed",
                j.ixfem
            ));
        }
        Ok(FailJohnson {
            d: j.d,
            eps_dot_0: j.eps_dot_0,
            ifail_sh: j.ifail_sh,
            ifail_so: j.ifail_so,
            epsf_min: j.epsf_min,
        })
    }

    /// The failure strain at triaxiality `triax`, strain rate `rate` and
    /// homologous temperature `tstar`.
    pub fn failure_strain(&self, triax: f64, rate: f64, tstar: f64) -> f64 {
        let [d1, d2, d3, d4, d5] = self.d;
        let mut ef = d1 + d2 * (d3 * triax).exp();
        if d4 != 0.0 {
            ef *= 1.0 + d4 * (rate / self.eps_dot_0).max(1.0).ln();
        }
        if d5 != 0.0 {
            ef *= 1.0 + d5 * tstar;
        }
        ef.max(self.epsf_min)
    }

    /// Adds the damage of a plastic increment `dep` at triaxiality `triax`.
    pub fn accumulate(&self, dmg: &mut f64, dep: f64, triax: f64, rate: f64, tstar: f64) {
        if dep <= 0.0 || *dmg >= 1.0 {
            return;
        }
        let ef = self.failure_strain(triax, rate, tstar);
        if ef > 0.0 {
            *dmg = (*dmg + dep / ef).min(1.0);
        }
    }

    /// One solid point after its material update: damage from the plastic
    /// increment `dep`, then the Ifail_so action on a failed point. True when
    /// the element is to be deleted (Ifail_so = 1).
    pub fn solid(
        &self,
        sig: &mut [f64; 6],
        dmg: &mut f64,
        dep: f64,
        rate: f64,
        tstar: f64,
    ) -> bool {
        self.accumulate(dmg, dep, solid_triaxiality(sig), rate, tstar);
        if *dmg < 1.0 {
            return false;
        }
        let p = (sig[0] + sig[1] + sig[2]) / 3.0;
        let keep = match self.ifail_so {
            1 => return true,
            2 => p,
            3 => p.min(0.0),
            _ => 0.0,
        };
        *sig = [keep, keep, keep, 0.0, 0.0, 0.0];
        false
    }
}

/// σ* = p/σ_vm of a 3-D stress [σxx σyy σzz σxy σyz σzx] (0 for zero stress).
pub fn solid_triaxiality(s: &[f64; 6]) -> f64 {
    let p = (s[0] + s[1] + s[2]) / 3.0;
    let (a, b, c) = (s[0] - p, s[1] - p, s[2] - p);
    let j2x2 = a * a + b * b + c * c + 2.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]);
    let vm = (1.5 * j2x2).sqrt();
    p / vm.max(1e-20)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn jc(d: [f64; 5], ifail_so: i64) -> FailJohnson {
        FailJohnson {
            d,
            eps_dot_0: 1.0,
            ifail_sh: 1,
            ifail_so,
            epsf_min: 0.0,
        }
    }

    /// Uniaxial tension has σ* = 1/3, pure shear 0, hydrostatic compression −∞ side.
    #[test]
    fn triaxiality_of_simple_states() {
        assert!((solid_triaxiality(&[3.0, 0.0, 0.0, 0.0, 0.0, 0.0]) - 1.0 / 3.0).abs() < 1e-15);
        assert!(solid_triaxiality(&[0.0, 0.0, 0.0, 2.0, 0.0, 0.0]).abs() < 1e-15);
        assert!((solid_triaxiality(&[-2.0, -1.0, -1.0, 0.0, 0.0, 0.0]) + 4.0 / 3.0).abs() < 1e-12);
    }

    /// ε_f of the formula, the rate factor floored at 1 and the EPSF_MIN floor.
    #[test]
    fn failure_strain_follows_the_formula() {
        let f = jc([0.1, 0.1, -0.1, 0.2, 0.5], 1);
        let t = 1.0 / 3.0;
        let base = 0.1 + 0.1 * (-0.1f64 / 3.0).exp();
        assert!((f.failure_strain(t, 0.5, 0.0) - base).abs() < 1e-15);
        let r = base * (1.0 + 0.2 * 100.0f64.ln()) * (1.0 + 0.5 * 0.4);
        assert!((f.failure_strain(t, 100.0, 0.4) - r).abs() < 1e-14);
        let g = FailJohnson { epsf_min: 0.5, ..f };
        assert_eq!(g.failure_strain(t, 0.5, 0.0), 0.5);
    }

    /// Damage grows by Δε_p/ε_f and a point fails after ε_f of plastic strain
    /// at constant triaxiality; ε_f ≤ 0 freezes it.
    #[test]
    fn damage_accumulates_to_failure() {
        let f = jc([0.2, 0.0, 0.0, 0.0, 0.0], 1);
        let mut s = [1.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        let mut d = 0.0;
        let mut n = 0;
        while !f.solid(&mut s, &mut d, 0.01, 0.0, 0.0) {
            n += 1;
            assert!(n < 100);
        }
        assert_eq!(n + 1, 20);
        let frozen = jc([-0.1, 0.0, 0.0, 0.0, 0.0], 1);
        let mut d = 0.3;
        frozen.accumulate(&mut d, 0.5, 0.0, 0.0, 0.0);
        assert_eq!(d, 0.3);
    }

    /// A uniaxial tension path (σ* = 1/3) at three strain rates, 1, 100 and
    /// 10⁴ times ε̇₀: the point fails after ε_f(σ*, ε̇) of plastic strain,
    /// [D1 + D2 e^(D3/3)](1 + D4 ln(ε̇/ε̇₀)), to one increment.
    #[test]
    fn a_tension_path_fails_at_the_strain_of_its_rate() {
        let f = FailJohnson {
            eps_dot_0: 2.0,
            ..jc([0.05, 0.1, -0.5, 0.15, 0.0], 1)
        };
        let dep = 1e-5;
        for ratio in [1.0f64, 100.0, 1e4] {
            let rate = ratio * 2.0;
            let want = (0.05 + 0.1 * (-0.5f64 / 3.0).exp()) * (1.0 + 0.15 * ratio.ln());
            let (mut s, mut d, mut ep) = ([2.0, 0.0, 0.0, 0.0, 0.0, 0.0], 0.0, 0.0);
            loop {
                ep += dep;
                if f.solid(&mut s, &mut d, dep, rate, 0.0) {
                    break;
                }
                assert!(ep < 10.0 * want, "rate {ratio}: no failure by {ep}");
            }
            assert!(
                (ep - want).abs() <= 1.01 * dep,
                "ε̇/ε̇₀ {ratio}: fails at {ep}, ε_f {want}"
            );
        }
    }

    /// Ifail_so 2, 3, 4 keep the element with the stress the option leaves.
    #[test]
    fn ifail_so_options_release_the_stress() {
        let s0 = [3.0, 0.0, 0.0, 1.0, 0.0, 0.0];
        for (opt, keep) in [(2, 1.0), (3, 0.0), (4, 0.0)] {
            let f = jc([0.1, 0.0, 0.0, 0.0, 0.0], opt);
            let (mut s, mut d) = (s0, 0.99);
            assert!(!f.solid(&mut s, &mut d, 0.01, 0.0, 0.0));
            assert_eq!(s, [keep, keep, keep, 0.0, 0.0, 0.0]);
        }
    }
}
