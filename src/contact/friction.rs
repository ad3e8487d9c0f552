//! Friction: the coefficient laws (Ifric), the filter (Ifiltr, Xfreq) and the
//! two penalty forms of the tangential force (Iform).
//!
//! Sources: theory manual EQ. 8.5.4.1–4 (TYPE3/5 incremental Coulomb with
//! Kt = K/10), EQ. 8.6.4.1–3 (Darmstad, Renard, filter), EQ. 8.8.3.1–5
//! (TYPE7); /INTER/TYPE7 card comments 16–19, equations (11)–(22).

use super::geometry::{dot, norm, scale, sub, V3};
use serde::{Deserialize, Serialize};

/// A friction law with its options, as the interface card gives them.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct FrictionLaw {
    /// Ifric: 0 Coulomb, 1 generalized viscous, 2 Darmstad, 3 Renard.
    pub ifric: i64,
    /// Fric: the Coulomb coefficient (and the constant term of laws 1, 2).
    pub fric: f64,
    /// C1..C6.
    pub c: [f64; 6],
    /// Ifiltr 0..3 and Xfreq.
    pub ifiltr: i64,
    pub xfreq: f64,
    /// Iform: 1 viscous (total), 2 stiffness (incremental).
    pub iform: i64,
    /// VISF: critical damping of the viscous form.
    pub visf: f64,
    /// Largest C·Δt/M of the viscous form's damper (see `tangential_force`):
    /// 2·(1 − s²) with s the /DT scale factor (`with_time_step_scale`).
    pub damper_cap: f64,
}

impl FrictionLaw {
    /// No friction; the fields a card leaves out (Iform 2, no filter, the
    /// damper cap of the default /DT scale 0.9 until `with_time_step_scale`).
    pub fn none() -> FrictionLaw {
        FrictionLaw {
            ifric: 0,
            fric: 0.0,
            c: [0.0; 6],
            ifiltr: 0,
            xfreq: 0.0,
            iform: 2,
            visf: 0.0,
            damper_cap: damper_cap(0.9),
        }
    }

    /// The law on a run whose time step is `scale` times the critical one.
    pub fn with_time_step_scale(mut self, scale: f64) -> FrictionLaw {
        self.damper_cap = damper_cap(scale);
        self
    }

    /// Whether the law can ever give a tangential force.
    pub fn active(&self) -> bool {
        self.ifric != 0 || self.fric != 0.0
    }

    /// The stiffness a pair adds to its nodes' time step
    /// (docs/notes/contact_time_step_research.md §2): the tangent `kt` and
    /// the normal damper `c` over the last step, or the friction damper
    /// VISF·√(2·kd·m)/Δt where that is stiffer; `kt` before the first step.
    pub fn step_stiffness(&self, kt: f64, c: f64, kd: f64, m: f64, dt: f64) -> f64 {
        if dt <= 0.0 {
            return kt;
        }
        let k = kt + c / dt;
        if self.active() {
            k.max(self.visf * (2.0 * kd * m).sqrt() / dt)
        } else {
            k
        }
    }

    /// μ(p, V): p the contact pressure on the main segment, V the sliding speed.
    pub fn mu(&self, p: f64, v: f64) -> f64 {
        let c = &self.c;
        match self.ifric {
            // Generalized viscous law (card eq. (14)).
            1 => self.fric + c[0] * p + c[1] * v + c[2] * p * v + c[3] * p * p + c[4] * v * v,
            // Modified Darmstad law (card eq. (15); EQ. 8.6.4.1 plus Fric).
            2 => {
                self.fric
                    + c[0] * (c[1] * v).exp() * p * p
                    + c[2] * (c[3] * v).exp() * p
                    + c[4] * (c[5] * v).exp()
            }
            // Renard law (EQ. 8.6.4.2, card eq. (16)–(18)):
            // C1 = μs, C2 = μd, C3 = μmax, C4 = μmin, C5 = Vcr1, C6 = Vcr2.
            3 => renard(c, v),
            // Static Coulomb (card eq. (11)).
            _ => self.fric,
        }
        .max(0.0)
    }

    /// Filter coefficient α of F_f = α·F(t) + (1 − α)·F_f(t − dt) (EQ. 8.6.4.3,
    /// card eq. (19)): Ifiltr 1: α = Xfreq; 2: α = 2π/Xfreq (Xfreq = T/dt, the
    /// filtering period in time steps, >= 2π as the reader checks; the card's
    /// "α = 2π·Xfreq with Xfreq = dt/T" is the same α); 3: α = 2π·Xfreq·dt
    /// (Xfreq = cut-off frequency); no filter: α = 1.
    pub fn filter_alpha(&self, dt: f64) -> f64 {
        let a = match self.ifiltr {
            1 => self.xfreq,
            2 if self.xfreq > 0.0 => 2.0 * std::f64::consts::PI / self.xfreq,
            3 => 2.0 * std::f64::consts::PI * self.xfreq * dt,
            _ => 1.0,
        };
        a.clamp(0.0, 1.0)
    }
}

/// Renard's μ(V) (EQ. 8.6.4.2; third branch as card eq. (18)).
pub fn renard(c: &[f64; 6], v: f64) -> f64 {
    let (mus, mud, mumax, mumin, v1, v2) = (c[0], c[1], c[2], c[3], c[4], c[5]);
    if v <= v1 {
        let r = v / v1;
        mus + (mumax - mus) * r * (2.0 - r)
    } else if v <= v2 {
        let r = (v - v1) / (v2 - v1);
        mumax - (mumax - mumin) * r * r * (3.0 - 2.0 * r)
    } else {
        let d = v - v2;
        mud - 1.0 / (1.0 / (mud - mumin) + d * d)
    }
}

/// Largest stable C·Δt/M of a damper acting on the previous half-step
/// velocity of a node that also has a stiffness: the central difference
/// update of m·ẍ + c·ẋ + k·x = 0 with the damper lagged is stable while
/// c·Δt/m ≤ 2 − (ωΔt)²/2, and the critical node runs at ωΔt = 2·s (s the
/// time step scale factor), hence 2·(1 − s²) (0.38 at the default 0.9).
pub fn damper_cap(scale: f64) -> f64 {
    (2.0 * (1.0 - scale * scale)).max(0.0)
}

/// Removes the normal component of a vector.
pub fn tangential(v: V3, n: V3) -> V3 {
    sub(v, scale(n, dot(v, n)))
}

/// Tangential force of one contact (force on the secondary node).
///
/// - Iform 1, viscous (EQ. 8.8.3.1/4, card eq. (20)–(21)):
///   F_t = min(μ·F_n, F_adh), F_adh = C·|V_t|, C = VISF·√(2·K·M), opposed to V_t
///   (C capped at `damper_cap`·M/Δt, the largest damper the explicit step
///   keeps stable on top of the node's own stiffness; M/Δt alone left the
///   stopped sliding block's nodes in a growing period-2 oscillation).
/// - Iform 2, incremental (EQ. 8.8.3.2/5, card eq. (22); EQ. 8.5.4.1/4 for
///   TYPE3/5 with `k` = K/10): F_adh = F_t_old + ΔF_t, ΔF_t = −K·V_t·dt, with
///   the old force turned into the current tangent plane; capped at μ·F_n
///   (sliding) or kept (sticking).
///
/// `state` is the previous tangential force (Iform 2) and is updated.
#[allow(clippy::too_many_arguments)]
pub fn tangential_force(
    law: &FrictionLaw,
    mu: f64,
    f_n: f64,
    vt: V3,
    normal: V3,
    k: f64,
    mass: f64,
    dt: f64,
    state: &mut V3,
) -> V3 {
    let limit = mu * f_n;
    if law.iform == 1 {
        let speed = norm(vt);
        if speed <= 0.0 || limit <= 0.0 {
            *state = [0.0; 3];
            return [0.0; 3];
        }
        // The adhesion damper acts on the previous velocity: beyond
        // C·Δt/M = damper_cap the explicit update (with the elements'
        // stiffness on the same node) overshoots and the friction chatters,
        // feeding energy in instead of taking it out.
        let mut c = law.visf * (2.0 * k * mass).sqrt();
        if dt > 0.0 {
            c = c.min(law.damper_cap * mass / dt);
        }
        let f = limit.min(c * speed);
        let out = scale(vt, -f / speed);
        *state = out;
        return out;
    }
    // Incremental form.
    let old = tangential(*state, normal);
    let old_len = norm(old);
    let prev_len = norm(*state);
    // Keep the magnitude of the previous force when the plane turns.
    let old = if old_len > 0.0 {
        scale(old, prev_len / old_len)
    } else {
        old
    };
    let trial = sub(old, scale(vt, k * dt));
    let l = norm(trial);
    let out = if l > limit && l > 0.0 {
        scale(trial, limit / l)
    } else {
        trial
    };
    *state = out;
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn law(ifric: i64) -> FrictionLaw {
        FrictionLaw {
            ifric,
            fric: 0.1,
            c: [0.3, 0.2, 0.5, 0.05, 1.0, 3.0],
            ifiltr: 0,
            xfreq: 0.0,
            iform: 2,
            visf: 1.0,
            damper_cap: damper_cap(0.9),
        }
    }

    #[test]
    fn renard_law_is_continuous_and_reaches_its_coefficients() {
        let c = [0.3, 0.2, 0.5, 0.05, 1.0, 3.0];
        assert!((renard(&c, 0.0) - 0.3).abs() < 1e-15); // μs at rest
        assert!((renard(&c, 1.0) - 0.5).abs() < 1e-15); // μmax at Vcr1
        assert!((renard(&c, 3.0) - 0.05).abs() < 1e-15); // μmin at Vcr2
        assert!((renard(&c, 1e6) - 0.2).abs() < 1e-9); // μd far away
        for v in [1.0, 3.0] {
            let h = 1e-9;
            assert!((renard(&c, v - h) - renard(&c, v + h)).abs() < 1e-7);
        }
    }

    #[test]
    fn darmstad_and_viscous_laws_follow_their_formulas() {
        let l = law(2);
        let (p, v) = (2.0, 0.5);
        let expect = 0.1
            + 0.3 * (0.2f64 * v).exp() * p * p
            + 0.5 * (0.05f64 * v).exp() * p
            + 1.0 * (3.0f64 * v).exp();
        assert!((l.mu(p, v) - expect).abs() < 1e-14);
        let l1 = law(1);
        let e1 = 0.1 + 0.3 * p + 0.2 * v + 0.5 * p * v + 0.05 * p * p + 1.0 * v * v;
        assert!((l1.mu(p, v) - e1).abs() < 1e-14);
        assert_eq!(law(0).mu(p, v), 0.1);
    }

    #[test]
    fn incremental_friction_sticks_then_slides_at_mu_fn() {
        let l = law(0);
        let mut st = [0.0; 3];
        let n = [0.0, 0.0, 1.0];
        // Small slip: elastic stick force K·v·dt.
        let f = tangential_force(
            &l,
            0.1,
            100.0,
            [1.0, 0.0, 0.0],
            n,
            1000.0,
            1.0,
            1e-3,
            &mut st,
        );
        assert!((f[0] + 1.0).abs() < 1e-12);
        // Keep sliding: capped at μ·Fn = 10.
        for _ in 0..100 {
            tangential_force(
                &l,
                0.1,
                100.0,
                [1.0, 0.0, 0.0],
                n,
                1000.0,
                1.0,
                1e-3,
                &mut st,
            );
        }
        assert!((st[0] + 10.0).abs() < 1e-12);
    }

    #[test]
    fn viscous_friction_is_capped_by_coulomb() {
        let mut l = law(0);
        l.iform = 1;
        let mut st = [0.0; 3];
        let n = [0.0, 0.0, 1.0];
        let f = tangential_force(
            &l,
            0.1,
            100.0,
            [0.0, 2.0, 0.0],
            n,
            1.0e6,
            1.0,
            1e-3,
            &mut st,
        );
        assert!((f[1] + 10.0).abs() < 1e-12);
        let f = tangential_force(
            &l,
            0.1,
            100.0,
            [0.0, 1e-6, 0.0],
            n,
            1.0e6,
            1.0,
            1e-4,
            &mut st,
        );
        let c = (2.0e6f64).sqrt();
        assert!((f[1] + c * 1e-6).abs() < 1e-12);
        // A step longer than M/C: the damper is capped at damper_cap·M/Δt.
        let f = tangential_force(
            &l,
            0.1,
            100.0,
            [0.0, 1e-6, 0.0],
            n,
            1.0e6,
            1.0,
            1e-2,
            &mut st,
        );
        assert!((f[1] + damper_cap(0.9) * 100.0 * 1e-6).abs() < 1e-12);
        assert!((damper_cap(0.9) - 0.38).abs() < 1e-12);
    }

    #[test]
    fn filter_coefficients() {
        let mut l = law(0);
        assert_eq!(l.filter_alpha(1e-3), 1.0);
        l.ifiltr = 1;
        l.xfreq = 0.3;
        assert_eq!(l.filter_alpha(1e-3), 0.3);
        // Ifiltr 2: Xfreq steps per period (the reader asks for >= 2π).
        l.ifiltr = 2;
        l.xfreq = 20.0;
        assert!((l.filter_alpha(1e-3) - 2.0 * std::f64::consts::PI / 20.0).abs() < 1e-15);
        l.ifiltr = 3;
        l.xfreq = 10.0;
        assert!((l.filter_alpha(1e-3) - 2.0 * std::f64::consts::PI * 1e-2).abs() < 1e-15);
    }
}
