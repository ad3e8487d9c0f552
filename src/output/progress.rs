//! The progress line: on a terminal, rank 0 keeps one line on stderr with
//! the simulated time, the cycle, the time step, cycles per second and the
//! estimated time left (from the simulated-time rate so far). Off when
//! stderr is not a terminal or with `--quiet`, on with `--progress` even
//! when it is not one (under mpirun, which forwards the ranks' pipes to the
//! terminal); the listing on stdout is untouched. The line is redrawn at most four times a second and ends with
//! a carriage return, so the next listing row overwrites it.

use std::io::{IsTerminal, Write};
use std::time::{Duration, Instant};

/// When the line is drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Mode {
    /// Never (`--quiet`).
    Off,
    /// When stderr is a terminal (the default).
    Terminal,
    /// Always (`--progress`).
    Always,
}

impl Mode {
    pub fn of(o: &super::OutputOptions) -> Mode {
        if o.quiet {
            Mode::Off
        } else if o.progress {
            Mode::Always
        } else {
            Mode::Terminal
        }
    }
}

pub struct Progress {
    on: bool,
    started: Instant,
    last: Instant,
    t0: f64,
    cycle0: u64,
    tstop: f64,
    drawn: bool,
}

impl Progress {
    /// `t0`, `cycle0`: where the loop starts (not 0 after a restart).
    pub fn new(rank: u32, mode: Mode, t0: f64, cycle0: u64, tstop: f64) -> Progress {
        let now = Instant::now();
        let shown = match mode {
            Mode::Off => false,
            Mode::Terminal => std::io::stderr().is_terminal(),
            Mode::Always => true,
        };
        Progress {
            on: rank == 0 && shown,
            started: now,
            // The first update draws at once.
            last: now.checked_sub(Duration::from_secs(1)).unwrap_or(now),
            t0,
            cycle0,
            tstop,
            drawn: false,
        }
    }

    /// The line for the given state (public for tests).
    pub fn line(&self, t: f64, cycle: u64, dt: f64, elapsed: f64) -> String {
        let cycles = cycle.saturating_sub(self.cycle0) as f64;
        let rate = if elapsed > 0.0 { cycles / elapsed } else { 0.0 };
        let done = t - self.t0;
        let left = if done > 0.0 {
            format!("{:.0} s", elapsed * (self.tstop - t).max(0.0) / done)
        } else {
            "?".into()
        };
        format!(
            "t = {t:.4e} / {:.4e}  cycle {cycle}  dt {dt:.3e}  {rate:.0} cycles/s  left {left}",
            self.tstop
        )
    }

    pub fn update(&mut self, t: f64, cycle: u64, dt: f64) {
        if !self.on {
            return;
        }
        let now = Instant::now();
        if now.duration_since(self.last) < Duration::from_millis(250) {
            return;
        }
        self.last = now;
        let l = self.line(t, cycle, dt, now.duration_since(self.started).as_secs_f64());
        let mut e = std::io::stderr();
        let _ = write!(e, "\x1b[2K{l}\r");
        let _ = e.flush();
        self.drawn = true;
    }

    /// Clears the line at the end.
    pub fn finish(&mut self) {
        if self.on && self.drawn {
            let mut e = std::io::stderr();
            let _ = write!(e, "\x1b[2K\r");
            let _ = e.flush();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_line_names_time_cycle_step_rate_and_time_left() {
        let p = Progress::new(1, Mode::Always, 0.0, 0, 0.1);
        assert!(!p.on, "only rank 0 draws");
        // A quarter of the run in 2 s: 6 s left; 500 cycles in 2 s.
        let l = p.line(0.025, 500, 1e-4, 2.0);
        assert_eq!(
            l,
            "t = 2.5000e-2 / 1.0000e-1  cycle 500  dt 1.000e-4  250 cycles/s  left 6 s"
        );
        // After a restart the rate counts from where the run started.
        let p = Progress::new(0, Mode::Off, 0.05, 500, 0.1);
        assert!(!p.on, "--quiet turns it off");
        assert!(p
            .line(0.075, 600, 1e-4, 1.0)
            .contains("100 cycles/s  left 1 s"));
    }
}
