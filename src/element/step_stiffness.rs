//! Each shell formulation's part in its nodes' stiffness for the nodal time
//! step taken while a TYPE7-family interface is active
//! (`solver::run::interface_nodal_step`): the factor c such that every
//! corner gets c·2·(m_e/corners)/Δt_e², with Δt_e the element's own
//! unscaled step L/√(E/ρ). Solids take 1 (`Block::nodal_step_factor`).
//! From the reference engine's element step routines with NODADT = 0
//! (`docs/notes/contact_time_step_research.md` §3,
//! `docs/notes/type25_nodal_step_research.md` §1-§2), read, not copied.

use super::shell4::ShellSection;
use crate::model::ElementKind;

/// Belytschko-Tsay (Ishell 1-4; cdt3.F): STI = 0.81·½·V0·E/L² to each of the
/// four nodes; with the corner mass ¼ρV0 that is 0.81·2·(m_e/4)/Δt_e².
pub const BELYTSCHKO_TSAY: f64 = 0.81;

/// C0 triangle (Ish3n 1, 2; c3dt3.F): 0.81²·A·t·A11/L² to each of the three
/// nodes, no ½: over 2·(ρAt/3)/Δt_e² that is 0.6561·(3/2)/(1 − ν²).
const C0_TRIANGLE: f64 = 0.6561 * 1.5;

/// QEPH (Ishell 24) and QBAT (Ishell 12) (cndt3.F): ½·V0·A11/L² times the
/// node's FACN, with A11 = E/(1 − ν²) and no 0.81: 1/(1 − ν²) over
/// 2·(m_e/4)/Δt_e². FACN (√ of the other half-diagonal's square over the
/// larger one) is 1 on a rectangle and taken as 1: a distorted quad's
/// nodes are counted a little stiffer, so their step is never larger.
pub fn quad_physical_factor(nu: f64) -> f64 {
    1.0 / (1.0 - nu * nu)
}

/// c for a shell of kind `kind` and section `sec`.
pub fn shell_factor(kind: ElementKind, sec: &ShellSection) -> f64 {
    let nu = sec.material.poisson();
    match (kind, sec.ishell) {
        (ElementKind::Shell3, _) => C0_TRIANGLE / (1.0 - nu * nu),
        (ElementKind::Shell4, 24) => quad_physical_factor(nu),
        _ => BELYTSCHKO_TSAY,
    }
}
