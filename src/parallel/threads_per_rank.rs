//! How many threads each rank's rayon pool gets (issue 18: `mpirun -n 2` on
//! 2 cores must not start 2 threads per rank).
//!
//! In order: `run --threads N`; else `RAYON_NUM_THREADS` (rayon's own
//! variable, kept for scripts that set it); else the cores this process may
//! use divided by the ranks on this node, at least 1. The listing header
//! says which rule chose the number. Results do not depend on it: every sum
//! has a fixed order (see `docs/ARCHITECTURE.md`).

use std::sync::OnceLock;

/// The number of threads per rank and why.
#[derive(Clone, Debug, PartialEq)]
pub struct ThreadChoice {
    pub threads: usize,
    pub why: String,
}

static CHOSEN: OnceLock<ThreadChoice> = OnceLock::new();

/// The rule above, as a pure function: `cli` from `--threads`, `env` the
/// value of `RAYON_NUM_THREADS`, `cores` the cores this process may use,
/// `local_ranks` the ranks on this node.
pub fn choose(
    cli: Option<usize>,
    env: Option<&str>,
    cores: usize,
    local_ranks: usize,
) -> ThreadChoice {
    if let Some(n) = cli.filter(|&n| n > 0) {
        return ThreadChoice {
            threads: n,
            why: "--threads".into(),
        };
    }
    if let Some(n) = env
        .and_then(|s| s.trim().parse::<usize>().ok())
        .filter(|&n| n > 0)
    {
        return ThreadChoice {
            threads: n,
            why: "RAYON_NUM_THREADS".into(),
        };
    }
    let local = local_ranks.max(1);
    let cores = cores.max(1);
    ThreadChoice {
        threads: (cores / local).max(1),
        why: format!(
            "{cores} core(s) / {local} rank(s) on this node{}",
            if cores < local {
                ", oversubscribed"
            } else {
                ""
            }
        ),
    }
}

/// Builds rayon's global pool with `choice.threads` threads and remembers
/// the choice for the listing header. Call once, before any parallel work.
pub fn apply(choice: ThreadChoice) -> Result<(), String> {
    rayon::ThreadPoolBuilder::new()
        .num_threads(choice.threads)
        .use_current_thread()
        .build_global()
        .map_err(|e| format!("cannot start {} thread(s): {e}", choice.threads))?;
    let _ = CHOSEN.set(choice);
    Ok(())
}

/// Threads per rank as the header prints them: the pool's size, and the
/// rule that chose it when `apply` did.
pub fn describe() -> String {
    let n = rayon::current_num_threads();
    match CHOSEN.get() {
        Some(c) if c.threads == n => format!("{n} thread(s) per rank ({})", c.why),
        _ => format!("{n} thread(s) per rank"),
    }
}

/// The cores this process may use (its CPU affinity where the system tells it).
pub fn cores() -> usize {
    std::thread::available_parallelism()
        .map(|n| n.get())
        .unwrap_or(1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_ranks_on_two_cores_get_one_thread_each() {
        let c = choose(None, None, 2, 2);
        assert_eq!(c.threads, 1);
        assert_eq!(c.why, "2 core(s) / 2 rank(s) on this node");
        assert_eq!(choose(None, None, 16, 4).threads, 4);
        assert_eq!(choose(None, None, 2, 1).threads, 2);
        // More ranks than cores: one thread each, and the header says so.
        let o = choose(None, None, 2, 4);
        assert_eq!(o.threads, 1);
        assert!(o.why.ends_with("oversubscribed"), "{}", o.why);
    }

    #[test]
    fn the_option_then_rayons_variable_override_the_default() {
        assert_eq!(choose(Some(3), Some("5"), 2, 2).threads, 3);
        assert_eq!(choose(None, Some("5"), 2, 2).threads, 5);
        assert_eq!(choose(None, Some("5"), 2, 2).why, "RAYON_NUM_THREADS");
        // Zero or junk means "not set".
        assert_eq!(choose(Some(0), Some("x"), 8, 2).threads, 4);
    }
}
