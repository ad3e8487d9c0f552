//! The cycle table, with the header line and columns of the Radioss engine
//! listing: CYCLE, TIME, TIME-STEP, ELEMENT, ERROR, I-ENERGY, K-ENERGY T,
//! K-ENERGY R, EXT-WORK, MAS.ERR, TOTAL MASS, MASS ADDED.

use std::io::Write;

pub const HEADER: &str = "   CYCLE    TIME      TIME-STEP  ELEMENT          ERROR  I-ENERGY    K-ENERGY T  K-ENERGY R  EXT-WORK     MAS.ERR     TOTAL MASS  MASS ADDED";

/// One row of the table.
pub struct Row<'a> {
    pub cycle: u64,
    pub time: f64,
    pub dt: f64,
    /// What set the time step: "SHELL", "NODE", ... and its global id.
    pub what: &'a str,
    pub id: u64,
    pub error_pct: f64,
    pub ie: f64,
    pub ke: f64,
    pub ker: f64,
    pub ext_work: f64,
    pub mas_err: f64,
    pub total_mass: f64,
    pub mass_added: f64,
}

/// A number the way the listing prints it: 4 significant digits, exponent form.
fn g(v: f64) -> String {
    format!("{:>11}", format!("{:.4E}", v))
}

pub fn format_row(r: &Row) -> String {
    format!(
        "{:>8} {} {} {:<7} {:>8} {:>6.1}% {} {} {} {} {} {} {}",
        r.cycle,
        g(r.time),
        g(r.dt),
        r.what,
        r.id,
        r.error_pct,
        g(r.ie),
        g(r.ke),
        g(r.ker),
        g(r.ext_work),
        g(r.mas_err),
        g(r.total_mass),
        g(r.mass_added)
    )
}

/// Writes to stdout and to the .out file together.
pub struct Listing {
    file: Option<std::io::BufWriter<std::fs::File>>,
}

impl Listing {
    pub fn new(path: Option<&std::path::Path>) -> std::io::Result<Listing> {
        let file = match path {
            Some(p) => Some(std::io::BufWriter::new(std::fs::File::create(p)?)),
            None => None,
        };
        Ok(Listing { file })
    }
    /// Appends to an existing listing (a restarted run goes on in its file).
    pub fn append(path: &std::path::Path) -> std::io::Result<Listing> {
        let f = std::fs::OpenOptions::new()
            .create(true)
            .append(true)
            .open(path)?;
        Ok(Listing {
            file: Some(std::io::BufWriter::new(f)),
        })
    }
    /// Writes one line to stdout and the file, flushed at once: a run that is
    /// killed keeps every line printed before.
    pub fn line(&mut self, s: &str) {
        println!("{s}");
        if let Some(f) = &mut self.file {
            let _ = writeln!(f, "{s}");
            let _ = f.flush();
        }
    }
    pub fn flush(&mut self) {
        let _ = std::io::stdout().flush();
        if let Some(f) = &mut self.file {
            let _ = f.flush();
        }
    }
}
