//! One rank without MPI: every collective is the identity on this rank's
//! values. Runs on one rank use MPI as usual (`MpiWorld`); this
//! communicator is for unit tests of the code that takes a `&World`
//! (contact, exchanges, solver phases) without mpirun.

use super::{plain_file_access, Comm, H5Access, StopVote};

/// The communicator of a single rank, in-process.
#[derive(Clone, Copy, Debug, Default)]
pub struct Serial;

impl Comm for Serial {
    fn rank(&self) -> u32 {
        0
    }
    fn size(&self) -> u32 {
        1
    }
    fn abort(&self, code: i32) -> ! {
        std::process::exit(code)
    }
    fn scatter_bytes(&self, per_rank: Option<Vec<Vec<u8>>>) -> Result<Vec<u8>, String> {
        per_rank
            .and_then(|mut p| (!p.is_empty()).then(|| p.swap_remove(0)))
            .ok_or_else(|| "rank 0 has nothing to scatter".to_string())
    }
    fn broadcast_bytes(&self, bytes: Option<Vec<u8>>) -> Vec<u8> {
        bytes.unwrap_or_default()
    }
    /// A single rank has no neighbours: nothing is sent, nothing comes back.
    fn exchange_with_neighbours(&self, ranks: &[u32], _send: &[Vec<u64>]) -> Vec<Vec<u64>> {
        assert!(ranks.is_empty(), "a single rank has no neighbours");
        Vec::new()
    }
    fn gather_strings(&self, s: &str) -> Option<Vec<String>> {
        Some(vec![s.to_string()])
    }
    fn barrier(&self) {}
    fn allgather_bytes(&self, mine: &[u8]) -> Vec<Vec<u8>> {
        vec![mine.to_vec()]
    }
    fn allgather_u64(&self, mine: &[u64]) -> Vec<u64> {
        mine.to_vec()
    }
    fn sum_f64(&self, _v: &mut [f64]) {}
    fn max_u64(&self, v: u64) -> u64 {
        v
    }
    fn max_f64(&self, _v: &mut [f64]) {}
    fn any(&self, flag: bool) -> bool {
        flag
    }
    fn exchange_f64(&self, ranks: &[u32], _send: &[Vec<f64>], _recv: &mut [Vec<f64>]) {
        assert!(ranks.is_empty(), "a single rank has no neighbours");
    }
    /// What rank 0 sends itself.
    fn alltoallv_u64(&self, send: &[Vec<u64>]) -> Vec<Vec<u64>> {
        assert_eq!(send.len(), 1, "one buffer per rank");
        send.to_vec()
    }
    fn hdf5_access(&self) -> Result<H5Access, String> {
        plain_file_access()
    }
    fn stop_vote(&self) -> Box<dyn StopVote> {
        Box::new(SerialVote::default())
    }
}

/// One rank's vote: the flag cast the cycle before.
#[derive(Default)]
struct SerialVote {
    pending: Option<bool>,
}

impl StopVote for SerialVote {
    fn cast(&mut self, flag: bool) -> bool {
        self.pending.replace(flag).unwrap_or(false)
    }
    fn complete(&mut self) -> bool {
        self.pending.take().unwrap_or(false)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::parallel::World;

    #[test]
    fn typed_messages_come_back_as_sent() {
        let w: &World = &Serial;
        assert_eq!(
            w.allgather(&(1u32, "a".to_string())),
            vec![(1, "a".to_string())]
        );
        assert_eq!(
            w.broadcast(Some(&vec![1.5f64, 2.0])).unwrap(),
            vec![1.5, 2.0]
        );
        assert!(w.broadcast::<u8>(None).is_err());
        let mut v = [1.0, -2.0];
        w.sum_f64(&mut v);
        assert_eq!(v, [1.0, -2.0]);
        assert_eq!(w.alltoallv_u64(&[vec![3, 4]]), vec![vec![3, 4]]);
    }

    #[test]
    fn the_stop_vote_answers_one_cycle_late() {
        let mut v = Serial.stop_vote();
        assert!(!v.cast(true));
        assert!(v.cast(false));
        assert!(!v.cast(false));
        assert!(!v.complete());
    }
}
