//! Keeps a rank's other pool threads awake through the cycle loop.
//!
//! A cycle runs a dozen parallel loops of 100-200 µs (the nodal loops, the
//! time step's scan) between stretches of serial work and MPI. Between two
//! loops rayon's idle workers fall asleep, and waking one takes about as
//! long as such a loop: the 10k tube's nodal loops hardly gained from a
//! second thread (README, "Speed"). While a [`KeepAwake`] lives, every pool
//! thread but the rank's own (the main thread, in the pool) runs a job that
//! asks rayon for work (`yield_now`) and spins when there is none, so the
//! next loop's chunks are taken at once. It costs those cores while the
//! rank waits; results do not change (sums keep their order).

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Arc;

/// The spinning jobs stop when this is dropped.
pub struct KeepAwake {
    stop: Arc<AtomicBool>,
    /// Spinning jobs running now.
    live: Arc<AtomicUsize>,
}

impl KeepAwake {
    /// Starts the spinning jobs; `None` (nothing started) on a single
    /// thread, or when the caller is no pool thread (in-process test
    /// ranks share one pool, and none of them may hold its threads).
    pub fn start() -> Option<KeepAwake> {
        let me = rayon::current_thread_index()?;
        if rayon::current_num_threads() < 2 {
            return None;
        }
        let stop = Arc::new(AtomicBool::new(false));
        let live = Arc::new(AtomicUsize::new(0));
        let (flag, count) = (Arc::clone(&stop), Arc::clone(&live));
        rayon::spawn_broadcast(move |ctx| {
            if ctx.index() == me {
                return;
            }
            count.fetch_add(1, Ordering::SeqCst);
            while !flag.load(Ordering::SeqCst) {
                if rayon::yield_now() != Some(rayon::Yield::Executed) {
                    std::hint::spin_loop();
                }
            }
            count.fetch_sub(1, Ordering::SeqCst);
        });
        Some(KeepAwake { stop, live })
    }

    /// How many threads spin now.
    pub fn spinning(&self) -> usize {
        self.live.load(Ordering::SeqCst)
    }
}

impl Drop for KeepAwake {
    /// Stops the spinning jobs and waits until they have let their threads go.
    fn drop(&mut self) {
        self.stop.store(true, Ordering::SeqCst);
        while self.live.load(Ordering::SeqCst) > 0 {
            std::hint::spin_loop();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rayon::prelude::*;

    /// On a pool thread of a 2-thread pool the other thread spins while the
    /// guard lives, parallel work still comes out right (an exact integer
    /// sum), and dropping the guard lets the thread go; on a thread outside
    /// any pool and on a 1-thread pool nothing starts.
    #[test]
    fn the_other_threads_spin_while_it_lives() {
        assert!(
            KeepAwake::start().is_none(),
            "the test thread is no pool thread"
        );
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(2)
            .build()
            .unwrap();
        let left = pool.install(|| {
            let awake = KeepAwake::start().expect("a pool thread of 2");
            let t0 = std::time::Instant::now();
            while awake.spinning() == 0 {
                assert!(t0.elapsed().as_secs() < 10, "the other thread never spun");
                std::hint::spin_loop();
            }
            let s: u64 = (0..100_000u64).into_par_iter().map(|i| i * i).sum();
            assert_eq!(s, (0..100_000u64).map(|i| i * i).sum::<u64>());
            let live = Arc::clone(&awake.live);
            drop(awake);
            live.load(Ordering::SeqCst)
        });
        assert_eq!(left, 0);
        let one = rayon::ThreadPoolBuilder::new()
            .num_threads(1)
            .build()
            .unwrap();
        assert!(one.install(KeepAwake::start).is_none());
    }
}
