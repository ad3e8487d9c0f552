//! The listing `DIR/NAME.out` (rank 0): header, one row per printed cycle
//! with the energy balance, the interfaces' lines, and the final block.

use super::super::listing::{format_row, Listing, Row, HEADER};
use super::energy::Energies;
use super::setup::{Ctx, State};
use super::RunOptions;
use crate::error::RunError;

/// Rank 0's listing (other ranks hold none).
pub(super) struct Report {
    pub listing: Option<Listing>,
}

impl Report {
    /// Creates (or, after a restart, reopens) the listing on rank 0.
    pub fn open(opts: &RunOptions, name: &str, rank: u32) -> Result<Report, RunError> {
        if rank != 0 {
            return Ok(Report { listing: None });
        }
        std::fs::create_dir_all(&opts.out_dir).map_err(|e| {
            RunError::Input(format!(
                "{}: cannot create the output directory: {e}",
                opts.out_dir.display()
            ))
        })?;
        let path = opts.out_dir.join(format!("{name}.out"));
        // After a restart the listing goes on in the same file.
        let listing = match opts.output.restart {
            Some(_) => Listing::append(&path),
            None => Listing::new(Some(&path)),
        };
        let listing = listing.map_err(|e| {
            RunError::Input(format!("{}: cannot write the listing: {e}", path.display()))
        })?;
        Ok(Report {
            listing: Some(listing),
        })
    }

    pub fn line(&mut self, s: &str) {
        if let Some(l) = &mut self.listing {
            l.line(s);
        }
    }

    /// The header: version, deck, ranks and threads, units, notes, column titles.
    pub fn header(&mut self, cx: &Ctx, notes: &[String]) {
        if self.listing.is_none() {
            return;
        }
        let g = cx.g;
        self.line(&format!(
            " crashsim {} — {} ({}), {} rank(s), {}",
            env!("CARGO_PKG_VERSION"),
            g.name,
            g.title,
            cx.world.size(),
            crate::parallel::threads_per_rank::describe()
        ));
        self.line(&format!(
            " units: {} {} {}   end time {:e}   /DT scale {}",
            g.units.mass, g.units.length, g.units.time, cx.tstop, g.engine.dt_scale
        ));
        self.line("");
        for n in notes {
            self.line(&format!(" note: {n}"));
        }
        if !notes.is_empty() {
            self.line("");
        }
        self.line(HEADER);
    }

    /// One cycle row. The I-ENERGY column leaves the hourglass energy out,
    /// as the Radioss listing does (its time histories carry it apart: on
    /// BOULE1V4 I-ENERGY + HOURGLASS + kinetic + contact energies equal the
    /// rigid wall's work); the balance counts both, and the energy contact took.
    pub fn row(&mut self, cx: &Ctx, s: &State, e: &Energies) {
        let Some(l) = &mut self.listing else {
            return;
        };
        let w = e.external_work;
        let ie = e.internal - e.hourglass;
        let err = 100.0 * super::energy::error_fraction(s.e0, e);
        l.line(&format_row(&Row {
            cycle: s.cycle,
            time: s.t,
            dt: s.dt,
            what: s.step.what,
            id: s.step.id,
            error_pct: err,
            ie,
            ke: e.kinetic,
            ker: e.rotational,
            ext_work: w,
            mas_err: s.mass_added / cx.g.total_mass,
            total_mass: cx.g.total_mass
                + cx.wall_masses.iter().map(|w| w.1).sum::<f64>()
                + s.mass_added,
            mass_added: s.mass_added,
        }));
    }

    /// Idel: segments and nodes the interfaces removed at this cycle.
    pub fn removals(&mut self, s: &State) {
        if self.listing.is_none() {
            return;
        }
        for r in s.contact.removed() {
            let (main, sec) = if r.edges {
                ("EDGES", "EDGES")
            } else {
                ("SEGMENTS", "NODES")
            };
            self.line(&format!(
                "     IDEL INTER {:>8} TYPE{:<2} CYCLE {:>8} TIME {:>12.5E}  REMOVED {:>6} MAIN {main} {:>6} SECONDARY {sec}  (TOTAL {} {main} {} {sec}, Idel = {})",
                r.inter_id, r.type_number, s.cycle, s.t, r.segments, r.nodes, r.segments_total, r.nodes_total, r.idel
            ));
        }
    }

    /// Contact force resultants per interface (secondary side; collective).
    pub fn contact_lines(&mut self, cx: &Ctx, s: &State) {
        if s.contact.is_empty() {
            return;
        }
        let mut r: Vec<f64> = s
            .contact
            .sums
            .iter()
            .flat_map(|s| {
                [
                    s.f_normal[0],
                    s.f_normal[1],
                    s.f_normal[2],
                    s.f_tangent[0],
                    s.f_tangent[1],
                    s.f_tangent[2],
                    s.pairs as f64,
                ]
            })
            .collect();
        cx.world.sum_f64(&mut r);
        if self.listing.is_none() {
            return;
        }
        for (i, it) in s.contact.setup.interfaces.iter().enumerate() {
            let q = &r[7 * i..7 * i + 7];
            self.line(&format!(
                "     INTER {:>8} TYPE{:<2} NORMAL FORCE {:>12.5E} {:>12.5E} {:>12.5E}  TANGENT {:>12.5E} {:>12.5E} {:>12.5E}  PAIRS {:>6}",
                it.id, it.type_number, q[0], q[1], q[2], q[3], q[4], q[5], q[6] as u64
            ));
        }
    }

    /// Tied interfaces: what the secondary nodes passed to their main nodes (collective).
    pub fn tied_lines(&mut self, cx: &Ctx, s: &State) {
        if s.ties.is_empty() {
            return;
        }
        let mut r: Vec<f64> = s
            .ties
            .sums
            .iter()
            .flat_map(|s| {
                [
                    s.tied as f64,
                    s.force[0],
                    s.force[1],
                    s.force[2],
                    s.moment[0],
                    s.moment[1],
                    s.moment[2],
                ]
            })
            .collect();
        cx.world.sum_f64(&mut r);
        if self.listing.is_none() {
            return;
        }
        for (i, it) in s.ties.setup.interfaces.iter().enumerate() {
            let q = &r[7 * i..7 * i + 7];
            self.line(&format!(
                "     INTER {:>8} TYPE2  TIED NODES {:>6}  FORCE {:>12.5E} {:>12.5E} {:>12.5E}  MOMENT {:>12.5E} {:>12.5E} {:>12.5E}",
                it.id, q[0] as u64, q[1], q[2], q[3], q[4], q[5], q[6]
            ));
        }
    }
}
