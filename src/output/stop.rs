//! Stop requests: SIGTERM and SIGINT set a flag (nothing else happens in
//! the handler, as signal-hook does it); the loop reads it once per cycle
//! and the ranks agree with an all-reduce (non-blocking, completed the next
//! cycle: `parallel::StopVote`), so that every rank stops at the same cycle
//! — the one after the signal — and writes the restart file together. A second signal ends
//! the process at once (exit 128 + signal), for a run stuck elsewhere.
//!
//! Test hooks (environment, read once): `CRASHSIM_SIGNAL_AT=RANK:CYCLE`
//! makes that rank raise SIGTERM on itself at that cycle (the real handler
//! path); `CRASHSIM_KILL_AT=RANK:CYCLE` makes it die by SIGKILL there.

use std::sync::atomic::{AtomicU32, Ordering};

/// Number of stop signals received.
static SIGNALS: AtomicU32 = AtomicU32::new(0);
/// The last signal number received.
static LAST: AtomicU32 = AtomicU32::new(0);

extern "C" fn on_signal(sig: libc::c_int) {
    LAST.store(sig as u32, Ordering::SeqCst);
    if SIGNALS.fetch_add(1, Ordering::SeqCst) >= 1 {
        // Second request: leave now (async-signal-safe).
        unsafe { libc::_exit(128 + sig) };
    }
}

/// Installs the SIGTERM and SIGINT handlers.
pub fn install() {
    unsafe {
        let h = on_signal as extern "C" fn(libc::c_int) as libc::sighandler_t;
        libc::signal(libc::SIGTERM, h);
        libc::signal(libc::SIGINT, h);
    }
}

/// Whether this process got a stop signal, and its name.
pub fn requested() -> Option<&'static str> {
    if SIGNALS.load(Ordering::SeqCst) == 0 {
        return None;
    }
    Some(match LAST.load(Ordering::SeqCst) as i32 {
        libc::SIGINT => "SIGINT",
        libc::SIGTERM => "SIGTERM",
        _ => "a signal",
    })
}

fn rank_cycle(var: &str) -> Option<(u32, u64)> {
    let v = std::env::var(var).ok()?;
    let (r, c) = v.split_once(':')?;
    Some((r.trim().parse().ok()?, c.trim().parse().ok()?))
}

/// The test hooks in effect for this process.
pub struct TestHooks {
    signal_at: Option<(u32, u64)>,
    kill_at: Option<(u32, u64)>,
}

impl TestHooks {
    pub fn from_env() -> TestHooks {
        TestHooks {
            signal_at: rank_cycle("CRASHSIM_SIGNAL_AT"),
            kill_at: rank_cycle("CRASHSIM_KILL_AT"),
        }
    }
    /// Fires what is due on this rank at this cycle.
    pub fn fire(&self, rank: u32, cycle: u64) {
        if self.signal_at == Some((rank, cycle)) {
            unsafe {
                libc::raise(libc::SIGTERM);
            }
        }
        if self.kill_at == Some((rank, cycle)) {
            eprintln!("crashsim: rank {rank}: CRASHSIM_KILL_AT: SIGKILL at cycle {cycle}");
            unsafe {
                libc::raise(libc::SIGKILL);
            }
        }
    }
}
