//! Interface stiffness: segment and node stiffness from the elements under
//! them, the TYPE7 Istf combinations, and the non-linear TYPE7 reaction.
//!
//! Sources: Radioss theory manual ch. 8 (EQ. 8.5.3.1–3, 8.8.9.1–2, 8.8.11.1–2)
//! and the /INTER/TYPE7 reference card, comment 3 (equations (1)–(7)).

/// Shell segment stiffness K = 0.5·E·t (EQ. 8.5.3.2; TYPE7 card eq. (4) and
/// (6)): it does not depend on the shell size. The scale factor is applied by
/// the caller.
pub fn shell(e: f64, t: f64) -> f64 {
    0.5 * e * t
}

/// Brick segment stiffness for TYPE3/TYPE5: K = 0.5·B·A²/V (EQ. 8.5.3.3).
pub fn brick_type3(bulk: f64, area: f64, volume: f64) -> f64 {
    0.5 * bulk * area * area / volume
}

/// Brick main segment stiffness for TYPE7: Km = B·S²/V (card eq. (5)).
pub fn brick_type7(bulk: f64, area: f64, volume: f64) -> f64 {
    bulk * area * area / volume
}

/// Secondary node stiffness of a node on a solid: Ks = B·V^(1/3) (card eq. (7)).
pub fn solid_node(bulk: f64, volume: f64) -> f64 {
    bulk * volume.cbrt()
}

/// Two springs in series: K1·K2/(K1+K2) (EQ. 8.5.3.1 without its scale factor).
pub fn series(k1: f64, k2: f64) -> f64 {
    if k1 + k2 > 0.0 {
        k1 * k2 / (k1 + k2)
    } else {
        0.0
    }
}

/// Stiffness from the masses and a time step (the TYPE24/25 IPSTIF option,
/// LS-DYNA's SOFT = 1/2 contact stiffness): K = s·m1·m2/(m1 + m2)/Δt², the
/// spring that two masses m1, m2 joined by it keep stable at step Δt for s
/// small enough (seed 003: k = 0.5·SLSFAC·SFS·m1·m2/(m1+m2)/Δt_c², the 0.5
/// being the force's half of K in the Radioss types). 0 when Δt or a mass is 0.
pub fn mass_time_step(s: f64, m1: f64, m2: f64, dt: f64) -> f64 {
    if dt <= 0.0 || m1 + m2 <= 0.0 {
        return 0.0;
    }
    s * m1 * m2 / (m1 + m2) / (dt * dt)
}

/// TYPE7 stiffness of a node–segment pair from the Istf flag (card eq. (1)–(3)):
/// - Istf = 1: K = Stfac (the card's stiffness value);
/// - Istf = 2, 3, 4, 5: Kn = mean, max, min or series of Km and Ks, then
///   K = max(Stmin, min(Stmax, Kn));
/// - Istf = 0 / 1000: K = Km (main side only).
///
/// `km` already carries Stfac (card eq. (4), (5)).
pub fn type7_pair(istf: i64, stfac: f64, km: f64, ks: f64, stmin: f64, stmax: f64) -> f64 {
    let kn = match istf {
        1 => return stfac,
        2 => 0.5 * (km + ks),
        3 => km.max(ks),
        4 => km.min(ks),
        5 => series(km, ks),
        _ => return km,
    };
    stmin.max(stmax.min(kn))
}

/// What a type's own stiffness rule reads of the element under a contact
/// face or around a contact node.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ElementSize {
    /// Bulk modulus of its material.
    pub bulk: f64,
    /// A shell (else a solid).
    pub shell: bool,
    /// The face's area (a solid's node: V^(2/3)) and, on a shell, its
    /// longest diagonal (a triangle: its longest edge).
    pub area: f64,
    pub dmax: f64,
    /// The solid's volume.
    pub volume: f64,
    /// The element's mass (a shell's ρ·A·t, a solid's ρ·V).
    pub mass: f64,
}

/// LS-DYNA's SOFT = 0 penalty stiffness (`model::contact::DynaPenalty`):
/// f·K·A/d_max on a shell, f·K·A²/V on a solid, f = SLSFAC·SFS or
/// SLSFAC·SFM.
pub fn dyna_soft0(f: f64, el: &ElementSize) -> f64 {
    if el.shell {
        if el.dmax > 0.0 {
            f * el.bulk * el.area / el.dmax
        } else {
            0.0
        }
    } else if el.volume > 0.0 {
        f * el.bulk * el.area * el.area / el.volume
    } else {
        0.0
    }
}

/// LS-DYNA's soft constraint stiffness (SOFT = 1; theory manual "Soft
/// Constraint Penalty Formulation"): k = 0.5·SOFSCL·m*/Δt², the spring that
/// keeps the mass m* stable at the step Δt with a margin (its own step
/// √(2m*/k) = Δt·√(4/SOFSCL)); 0 before the first step.
pub fn soft_constraint(sofscl: f64, m: f64, dt: f64) -> f64 {
    if dt <= 0.0 {
        return 0.0;
    }
    0.5 * sofscl * m / (dt * dt)
}

/// TYPE7 elastic reaction and tangent stiffness at penetration `p` in gap `g`:
/// F = K0·P·Gap/(Gap − P) (EQ. 8.8.9.1, 8.8.11.1), Kt = K0·Gap²/(Gap − P)² (EQ. 8.8.9.2).
/// `p` must be below `g` (the caller deactivates a node at the mid-plane).
pub fn type7_reaction(k0: f64, g: f64, p: f64) -> (f64, f64) {
    let r = g / (g - p);
    (k0 * p * r, k0 * r * r)
}

/// Elastic energy stored at penetration p: CE = K0·g·(−p − g·ln((g − p)/g)) (EQ. 8.8.11.2).
pub fn type7_energy(k0: f64, g: f64, p: f64) -> f64 {
    k0 * g * (-p - g * ((g - p) / g).ln())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ls_dynas_soft0_stiffness_of_a_shell_and_a_solid_face() {
        // A 5 × 5 shell square: f·K·A/d_max; a 5 mm cube's face: f·K·A²/V.
        let shell = ElementSize {
            bulk: 175.0,
            shell: true,
            area: 25.0,
            dmax: 50f64.sqrt(),
            volume: 0.0,
            mass: 0.0,
        };
        assert!((dyna_soft0(0.1, &shell) - 0.1 * 175.0 * 25.0 / 50f64.sqrt()).abs() < 1e-12);
        let solid = ElementSize {
            shell: false,
            dmax: 0.0,
            volume: 125.0,
            ..shell
        };
        assert!((dyna_soft0(0.1, &solid) - 0.1 * 175.0 * 5.0).abs() < 1e-12);
        assert_eq!(
            dyna_soft0(
                0.1,
                &ElementSize {
                    volume: 0.0,
                    ..solid
                }
            ),
            0.0
        );
    }

    #[test]
    fn the_mass_time_step_stiffness_keeps_two_masses_stable() {
        // Two masses m1, m2 on a spring K oscillate at ω² = K/m*, m* the
        // reduced mass: with K = s·m*/Δt², ω·Δt = √s (stable for s < 4).
        let (m1, m2, dt) = (2.0, 6.0, 1e-3);
        let k = mass_time_step(0.1, m1, m2, dt);
        let m_red = m1 * m2 / (m1 + m2);
        assert!(((k / m_red).sqrt() * dt - 0.1f64.sqrt()).abs() < 1e-12);
        assert_eq!(mass_time_step(0.1, m1, m2, 0.0), 0.0);
    }

    #[test]
    fn istf_options() {
        let (km, ks) = (3.0, 1.0);
        assert_eq!(type7_pair(1000, 1.0, km, ks, 0.0, 1e30), 3.0);
        assert_eq!(type7_pair(1, 7.0, km, ks, 0.0, 1e30), 7.0);
        assert_eq!(type7_pair(2, 1.0, km, ks, 0.0, 1e30), 2.0);
        assert_eq!(type7_pair(3, 1.0, km, ks, 0.0, 1e30), 3.0);
        assert_eq!(type7_pair(4, 1.0, km, ks, 0.0, 1e30), 1.0);
        assert_eq!(type7_pair(5, 1.0, km, ks, 0.0, 1e30), 0.75);
        assert_eq!(type7_pair(4, 1.0, km, ks, 1.5, 1e30), 1.5);
        assert_eq!(type7_pair(3, 1.0, km, ks, 0.0, 2.0), 2.0);
    }

    #[test]
    fn reaction_is_the_derivative_of_the_energy_and_tangent_of_the_force() {
        let (k0, g) = (2.0e5, 0.01);
        for p in [1e-4, 3e-3, 8e-3] {
            let h = 1e-9;
            let (f, kt) = type7_reaction(k0, g, p);
            let de = (type7_energy(k0, g, p + h) - type7_energy(k0, g, p - h)) / (2.0 * h);
            assert!((de - f).abs() < 1e-5 * f, "{de} {f}");
            let df = (type7_reaction(k0, g, p + h).0 - type7_reaction(k0, g, p - h).0) / (2.0 * h);
            assert!((df - kt).abs() < 1e-5 * kt);
        }
        // Small penetration: linear spring K0.
        let (f, kt) = type7_reaction(k0, g, 1e-9);
        assert!((f / 1e-9 - k0).abs() < 1e-3 * k0 && (kt - k0).abs() < 1e-3 * k0);
    }
}
