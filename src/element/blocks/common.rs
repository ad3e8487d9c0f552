//! What every block shares: gathering an element's nodal values, marking
//! failed elements deleted, decoding restart records, von Mises stresses and
//! the hourglass energy kept by an element state.

use super::ElemStep;
use crate::domain::LocalElements;
use crate::element::hex8::Hex8State;
use crate::element::hex8::SolidSection;
use crate::element::shell3::Shell3State;
use crate::element::shell4::Shell4State;
use crate::element::tet4::Tet4State;

/// Von Mises stress of a shell point [σxx σyy σxy σyz σzx] (σzz = 0).
pub(super) fn von_mises_shell(s: &[f64; 5]) -> f64 {
    (s[0] * s[0] + s[1] * s[1] - s[0] * s[1] + 3.0 * (s[2] * s[2] + s[3] * s[3] + s[4] * s[4]))
        .max(0.0)
        .sqrt()
}

/// Von Mises stress of a 3-D tensor [σxx σyy σzz σxy σyz σzx].
pub(super) fn von_mises_3d(s: &[f64; 6]) -> f64 {
    crate::element::hex8::von_mises(s)
}

/// Decodes one element's restart record, naming what did not fit.
pub(super) fn decode_state<T: serde::de::DeserializeOwned>(
    bytes: &[u8],
    what: &str,
) -> Result<T, String> {
    bincode::deserialize(bytes).map_err(|e| format!("{what} element state does not decode: {e}"))
}

pub(super) fn gather<const N: usize>(
    le: &LocalElements,
    e: usize,
    a: &[[f64; 3]],
) -> [[f64; 3]; N] {
    std::array::from_fn(|k| a[le.nodes[N * e + k] as usize])
}

pub(super) fn settle_common(
    alive: &mut [bool],
    steps: &[ElemStep],
    le: &LocalElements,
    what: &'static str,
) -> Option<(u32, &'static str)> {
    let mut problem = None;
    for e in 0..alive.len() {
        if !alive[e] {
            continue;
        }
        if steps[e].bad && problem.is_none() {
            problem = Some((le.global[e], what));
        }
        if steps[e].failed {
            alive[e] = false;
        }
    }
    problem
}

/// Hourglass energy kept by an element state (0 for elements without
/// hourglass modes), and its plastic work.
pub(super) trait HourglassEnergy {
    fn hourglass_energy(&self) -> f64;
    fn plastic_work(&self) -> f64;
}
impl HourglassEnergy for Shell4State {
    fn hourglass_energy(&self) -> f64 {
        self.ehg
    }
    fn plastic_work(&self) -> f64 {
        self.eplas
    }
}
impl HourglassEnergy for Shell3State {
    fn hourglass_energy(&self) -> f64 {
        0.0
    }
    fn plastic_work(&self) -> f64 {
        self.eplas
    }
}
impl HourglassEnergy for Hex8State {
    fn hourglass_energy(&self) -> f64 {
        self.ehg
    }
    fn plastic_work(&self) -> f64 {
        self.eplas
    }
}
impl HourglassEnergy for crate::element::hex8_total::Hex8TotalState {
    fn hourglass_energy(&self) -> f64 {
        self.ehg
    }
    fn plastic_work(&self) -> f64 {
        self.eplas
    }
}
impl HourglassEnergy for Tet4State {
    fn hourglass_energy(&self) -> f64 {
        0.0
    }
    fn plastic_work(&self) -> f64 {
        self.eplas
    }
}
impl HourglassEnergy for crate::element::ha8::Ha8State {
    fn hourglass_energy(&self) -> f64 {
        0.0
    }
    fn plastic_work(&self) -> f64 {
        self.eplas
    }
}
impl HourglassEnergy for crate::element::heph::HephState {
    /// Its physical stabilization is internal energy (`eint`), not a
    /// numerical hourglass energy.
    fn hourglass_energy(&self) -> f64 {
        0.0
    }
    fn plastic_work(&self) -> f64 {
        self.eplas
    }
}
pub(super) fn hourglass_of<S: HourglassEnergy>(s: &S) -> f64 {
    s.hourglass_energy()
}

/// The nodal stiffness a solid gives each of its corners for /DT/NODA/CST
/// (None: the formulation does not give it and the run refuses the option
/// by name). The one-point bricks: K = ρ₀V₀/(4Δt_e²) with Δt_e their
/// unscaled element step (without the compression term), so that a node of
/// mass ρ₀V₀/8 gets √(2m/K) = Δt_e (research note law12_research.md §2.3,
/// the reference's STI = ρV/Δt² spread as 2·STI/8).
pub(super) trait SolidNodalStiffness {
    fn corner_stiffness(&self, _sec: &SolidSection, _x: &[[f64; 3]]) -> Option<f64> {
        None
    }
}

/// ρ₀V₀/(4Δt_e²) of a one-point brick whose unscaled step at rest is `dt`.
fn one_point_stiffness(sec: &SolidSection, vol0: f64, dt: f64) -> Option<f64> {
    (dt > 0.0).then(|| sec.material.rho() * vol0 / (4.0 * dt * dt))
}

impl SolidNodalStiffness for crate::element::hex8::Hex8State {
    fn corner_stiffness(&self, sec: &SolidSection, x: &[[f64; 3]]) -> Option<f64> {
        one_point_stiffness(sec, self.vol0, self.rest_time_step(sec, x.try_into().ok()?))
    }
}
impl SolidNodalStiffness for crate::element::heph::HephState {
    fn corner_stiffness(&self, sec: &SolidSection, x: &[[f64; 3]]) -> Option<f64> {
        let dt = crate::element::hex8::brick_rest_step(sec, sec.c, x.try_into().ok()?);
        one_point_stiffness(sec, self.vol0, dt)
    }
}
impl SolidNodalStiffness for crate::element::tet4::Tet4State {}
impl SolidNodalStiffness for crate::element::ha8::Ha8State {}
impl SolidNodalStiffness for crate::element::hex8_total::Hex8TotalState {}
