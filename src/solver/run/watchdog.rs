//! The energy watchdog: a run whose energy balance goes wrong stops (exit
//! 3) instead of ending with a wrong answer at exit 0.
//!
//! The limit is /STOP's Emax when the engine file gives one (Radioss
//! reference guide, /STOP engine keyword: Emax is the relative energy error
//! as a fraction, 0 = no limit; NERR_POSIT = 1 checks the positive error
//! only, else its absolute value), otherwise the run's default
//! `--energy-error-limit` (100%: energy created beyond what the initial
//! kinetic energy and the external work put in, checked on the positive
//! side only, since damping, friction and rigid walls take energy out of
//! the balance legitimately). The error is the listing's ERROR column as a
//! fraction, `energy::error_fraction`: (E_int + E_kin + E_rot + E_contact)
//! / (E_0 + W_ext) − 1.
//!
//! As in Radioss, the check runs on the cycles whose energies are computed
//! anyway (listing rows, `--energies` rows), and on every cycle when /STOP
//! asks for a time history or an animation at the stop (NTH, NANIM ≠ 0).
//! A stop names the cycle, the time and the part or interface whose energy
//! grew the most since the last check. The outputs written so far stay, and
//! the run file and listing get the state of the stop (RunError::Physics).
//! Radioss ends such a run with exit 0 ("USER BREAK"); crashsim exits 3, so
//! that a script cannot take it for a finished run.
//!
//! Mmax and Nmax (mass error limits) cannot be reached: crashsim adds no
//! mass (no mass scaling), its MAS.ERR is 0.

use super::energy::{self, Energies};
use super::setup::{Ctx, State};
use crate::element::blocks::Block;
use crate::error::RunError;
use crate::output::history::{element_masses, part_sums};

/// Cycles before the energy error is held to its limit.
const START_UP_CYCLES: u64 = 10;

/// The limit, where it comes from, and the energies of the last check.
pub(super) struct Watchdog {
    /// Fraction; infinite: no limit.
    limit: f64,
    positive_only: bool,
    origin: String,
    /// Check every cycle (/STOP NTH or NANIM), not only where energies are printed.
    pub every_cycle: bool,
    elem_mass: Vec<Vec<f64>>,
    /// Cycle and energy (internal + kinetic) per part, then per interface, at the last check.
    last: Option<(u64, Vec<f64>)>,
}

impl Watchdog {
    pub fn new(cx: &Ctx, blocks: &[Box<dyn Block>]) -> Watchdog {
        let default_pct = cx.opts.energy_error_limit;
        let (limit, positive_only, origin, every_cycle) = match &cx.g.engine.stop {
            Some(st) if st.emax < 1e29 => (
                st.emax,
                st.nerr_posit == 1,
                format!("the /STOP Emax {} of {}", st.emax, st.loc),
                st.nth != 0 || st.nanim != 0,
            ),
            st => (
                if default_pct > 0.0 {
                    default_pct / 100.0
                } else {
                    f64::INFINITY
                },
                true,
                format!("the default limit {default_pct}% (crashsim run --energy-error-limit)"),
                st.as_ref().is_some_and(|s| s.nth != 0 || s.nanim != 0),
            ),
        };
        Watchdog {
            limit,
            positive_only,
            origin,
            every_cycle,
            elem_mass: blocks
                .iter()
                .map(|b| element_masses(cx.g, &cx.sd.x, b.as_ref()))
                .collect(),
            last: None,
        }
    }

    /// Checks this cycle's energies (collective: every rank calls it at the
    /// same cycles with the same global energies).
    pub fn check(&mut self, cx: &Ctx, s: &State, e: &Energies) -> Result<(), RunError> {
        let now = self.energies_by_owner(cx, s);
        let err = energy::error_fraction(s.e0, e);
        let past = if self.positive_only {
            err > self.limit
        } else {
            err.abs() > self.limit
        };
        let last = self.last.replace((s.cycle, now));
        // The first cycles' balance is the staggered scheme's start-up: the
        // work of the loads and imposed motions lags the internal energy by
        // one step (½FΔu), which is all there is while the energies are a
        // few steps old.
        if !past || s.cycle < START_UP_CYCLES {
            return Ok(());
        }
        let (since, before) = last.unwrap_or((0, Vec::new()));
        let grown = self.largest_growth(cx, s, &before);
        Err(RunError::Physics(format!(
            "ENERGY ERROR LIMIT REACHED: ERROR {:.1}% passes {} at cycle {}, time {:e}; largest energy growth since cycle {since}: {grown}",
            100.0 * err,
            self.origin,
            s.cycle,
            s.t
        )))
    }

    /// Internal + kinetic energy per part, then contact energy per
    /// interface, summed over the ranks.
    fn energies_by_owner(&self, cx: &Ctx, s: &State) -> Vec<f64> {
        let vel = s.at_n.as_ref().map_or(&s.v[..], |a| &a.v);
        let parts = part_sums(&s.blocks, &self.elem_mass, vel, cx.g.parts.len());
        let mut e: Vec<f64> = parts.iter().map(|p| p[0].value() + p[1].value()).collect();
        e.extend(s.contact.sums.iter().map(|su| su.energy));
        cx.world.sum_f64(&mut e);
        e
    }

    /// The part whose energy (internal + kinetic) grew the most since
    /// `before`, and the interface that put the most energy in (its contact
    /// energy, the work it took, fell), where one did.
    fn largest_growth(&self, cx: &Ctx, s: &State, before: &[f64]) -> String {
        let Some((_, now)) = &self.last else {
            return "none".into();
        };
        let np = cx.g.parts.len();
        let was = |i: usize| before.get(i).copied().unwrap_or(0.0);
        let growth = |i: usize| now[i] - was(i);
        let mut said = Vec::new();
        if let Some(i) = (0..np).max_by(|&a, &b| growth(a).total_cmp(&growth(b))) {
            let p = &cx.g.parts[i];
            said.push(format!(
                "PART {} ({}), internal + kinetic energy {:.4e} → {:.4e}",
                p.id,
                p.title.trim(),
                was(i),
                now[i]
            ));
        }
        let put_in = (np..now.len())
            .filter(|&i| growth(i) < 0.0)
            .min_by(|&a, &b| growth(a).total_cmp(&growth(b)));
        if let Some(i) = put_in {
            let inter = &s.contact.setup.interfaces[i - np];
            said.push(format!(
                "INTERFACE {} (TYPE{}) put {:.4e} of energy in (its contact energy {:.4e} → {:.4e})",
                inter.id,
                inter.type_number,
                -growth(i),
                was(i),
                now[i]
            ));
        }
        if said.is_empty() {
            "none".into()
        } else {
            said.join("; ")
        }
    }
}
