//! Several ranks in one process, one thread each, talking over channels: a
//! communicator for unit tests of the code that exchanges between ranks
//! (contact ghosts and force routing, tied transfers) without mpirun.
//! [`run_ranks`] starts the ranks and returns what each one returned.
//!
//! Messages between two ranks travel in order on their own channel (one for
//! point-to-point exchanges, one for collectives), so as long as every rank
//! makes its calls in the same order, as MPI asks too, each receive gets the
//! message meant for it. No HDF5 through it: the run file needs MPI-IO.

use super::{Comm, H5Access, StopVote, World};
use std::sync::mpsc::{channel, Receiver, Sender};
use std::sync::{Arc, Barrier, Mutex};

/// Bytes from one rank to another.
type Mail = Vec<u8>;

/// One rank of an in-process world.
pub struct ThreadRank {
    rank: u32,
    size: u32,
    barrier: Arc<Barrier>,
    /// The stop votes, one per rank (shared memory).
    votes: Arc<Mutex<Vec<bool>>>,
    /// [lane][to]: lane 0 point-to-point, lane 1 collectives.
    to: [Vec<Sender<Mail>>; 2],
    /// [lane][from].
    from: [Vec<Receiver<Mail>>; 2],
}

/// Runs `f` on `n` in-process ranks (threads) and returns each rank's result, in rank order.
pub fn run_ranks<T: Send>(n: usize, f: impl Fn(&World) -> T + Sync) -> Vec<T> {
    let ranks = world_of(n);
    std::thread::scope(|scope| {
        let f = &f;
        let handles: Vec<_> = ranks
            .into_iter()
            .map(|r| scope.spawn(move || f(&r)))
            .collect();
        handles
            .into_iter()
            .map(|h| h.join().expect("a rank panicked"))
            .collect()
    })
}

/// `n` connected ranks.
fn world_of(n: usize) -> Vec<ThreadRank> {
    let barrier = Arc::new(Barrier::new(n));
    let votes = Arc::new(Mutex::new(vec![false; n]));
    // senders[lane][from][to], receivers[lane][to][from]
    let mut senders: Vec<Vec<Vec<Sender<Mail>>>> = vec![vec![Vec::new(); n]; 2];
    let mut receivers: Vec<Vec<Vec<Option<Receiver<Mail>>>>> = (0..2)
        .map(|_| (0..n).map(|_| (0..n).map(|_| None).collect()).collect())
        .collect();
    for lane in 0..2 {
        for from in 0..n {
            for to in 0..n {
                let (s, r) = channel();
                senders[lane][from].push(s);
                receivers[lane][to][from] = Some(r);
            }
        }
    }
    let mut rx = receivers.into_iter();
    let (mut rx0, mut rx1) = (
        rx.next().unwrap().into_iter(),
        rx.next().unwrap().into_iter(),
    );
    let mut tx = senders.into_iter();
    let (mut tx0, mut tx1) = (
        tx.next().unwrap().into_iter(),
        tx.next().unwrap().into_iter(),
    );
    (0..n)
        .map(|rank| {
            let take = |v: Vec<Option<Receiver<Mail>>>| v.into_iter().map(Option::unwrap).collect();
            ThreadRank {
                rank: rank as u32,
                size: n as u32,
                barrier: barrier.clone(),
                votes: votes.clone(),
                to: [tx0.next().unwrap(), tx1.next().unwrap()],
                from: [take(rx0.next().unwrap()), take(rx1.next().unwrap())],
            }
        })
        .collect()
}

fn u64s_to_bytes(v: &[u64]) -> Mail {
    v.iter().flat_map(|x| x.to_le_bytes()).collect()
}
fn bytes_to_u64s(b: &[u8]) -> Vec<u64> {
    b.chunks_exact(8)
        .map(|c| u64::from_le_bytes(c.try_into().unwrap()))
        .collect()
}
fn f64s_to_bytes(v: &[f64]) -> Mail {
    v.iter().flat_map(|x| x.to_le_bytes()).collect()
}

impl ThreadRank {
    fn send(&self, lane: usize, to: u32, m: Mail) {
        self.to[lane][to as usize].send(m).expect("rank gone");
    }
    fn recv(&self, lane: usize, from: u32) -> Mail {
        self.from[lane][from as usize].recv().expect("rank gone")
    }
    /// Every rank's bytes, in rank order (collective lane).
    fn gather_all(&self, mine: &[u8]) -> Vec<Mail> {
        for r in 0..self.size {
            self.send(1, r, mine.to_vec());
        }
        (0..self.size).map(|r| self.recv(1, r)).collect()
    }
    /// Each entry combined over ranks, in rank order.
    fn reduce(&self, v: &mut [f64], op: fn(f64, f64) -> f64) {
        let all = self.gather_all(&f64s_to_bytes(v));
        for (i, x) in v.iter_mut().enumerate() {
            let vals = all
                .iter()
                .map(|b| f64::from_le_bytes(b[8 * i..8 * i + 8].try_into().unwrap()));
            *x = vals.reduce(op).unwrap();
        }
    }
}

impl Comm for ThreadRank {
    fn rank(&self) -> u32 {
        self.rank
    }
    fn size(&self) -> u32 {
        self.size
    }
    fn abort(&self, code: i32) -> ! {
        panic!("rank {} aborted with code {code}", self.rank)
    }
    fn scatter_bytes(&self, per_rank: Option<Vec<Vec<u8>>>) -> Result<Vec<u8>, String> {
        if self.rank == 0 {
            let mut parts = per_rank.ok_or("rank 0 has nothing to scatter")?;
            for (r, p) in parts.iter().enumerate().skip(1) {
                self.send(1, r as u32, p.clone());
            }
            Ok(std::mem::take(&mut parts[0]))
        } else {
            Ok(self.recv(1, 0))
        }
    }
    fn broadcast_bytes(&self, bytes: Option<Vec<u8>>) -> Vec<u8> {
        if self.rank == 0 {
            let b = bytes.unwrap_or_default();
            for r in 1..self.size {
                self.send(1, r, b.clone());
            }
            b
        } else {
            self.recv(1, 0)
        }
    }
    fn exchange_with_neighbours(&self, ranks: &[u32], send: &[Vec<u64>]) -> Vec<Vec<u64>> {
        for (&nb, out) in ranks.iter().zip(send) {
            self.send(0, nb, u64s_to_bytes(out));
        }
        ranks
            .iter()
            .map(|&nb| bytes_to_u64s(&self.recv(0, nb)))
            .collect()
    }
    fn gather_strings(&self, s: &str) -> Option<Vec<String>> {
        let all = self.gather_all(s.as_bytes());
        (self.rank == 0).then(|| {
            all.iter()
                .map(|b| String::from_utf8_lossy(b).into_owned())
                .collect()
        })
    }
    fn barrier(&self) {
        self.barrier.wait();
    }
    fn allgather_bytes(&self, mine: &[u8]) -> Vec<Vec<u8>> {
        self.gather_all(mine)
    }
    fn allgather_u64(&self, mine: &[u64]) -> Vec<u64> {
        self.gather_all(&u64s_to_bytes(mine))
            .iter()
            .flat_map(|b| bytes_to_u64s(b))
            .collect()
    }
    fn sum_f64(&self, v: &mut [f64]) {
        self.reduce(v, |a, b| a + b);
    }
    fn max_u64(&self, v: u64) -> u64 {
        self.allgather_u64(&[v]).into_iter().max().unwrap()
    }
    fn max_f64(&self, v: &mut [f64]) {
        self.reduce(v, f64::max);
    }
    fn any(&self, flag: bool) -> bool {
        self.max_u64(flag as u64) != 0
    }
    fn exchange_f64(&self, ranks: &[u32], send: &[Vec<f64>], recv: &mut [Vec<f64>]) {
        for (&nb, out) in ranks.iter().zip(send) {
            self.send(0, nb, f64s_to_bytes(out));
        }
        for (&nb, r) in ranks.iter().zip(recv.iter_mut()) {
            let b = self.recv(0, nb);
            assert_eq!(b.len(), 8 * r.len(), "rank {nb} sent another length");
            for (x, c) in r.iter_mut().zip(b.chunks_exact(8)) {
                *x = f64::from_le_bytes(c.try_into().unwrap());
            }
        }
    }
    fn alltoallv_u64(&self, send: &[Vec<u64>]) -> Vec<Vec<u64>> {
        assert_eq!(send.len(), self.size as usize);
        for (r, out) in send.iter().enumerate() {
            self.send(1, r as u32, u64s_to_bytes(out));
        }
        (0..self.size)
            .map(|r| bytes_to_u64s(&self.recv(1, r)))
            .collect()
    }
    fn hdf5_access(&self) -> Result<H5Access, String> {
        Err("in-process ranks cannot share an HDF5 file (MPI-IO needs MPI)".into())
    }
    fn stop_vote(&self) -> Box<dyn StopVote> {
        Box::new(ThreadVote {
            rank: self.rank as usize,
            barrier: self.barrier.clone(),
            votes: self.votes.clone(),
            last: false,
        })
    }
}

/// The vote of in-process ranks: a blocking OR, handed back one cycle late
/// as the MPI vote is.
struct ThreadVote {
    rank: usize,
    barrier: Arc<Barrier>,
    votes: Arc<Mutex<Vec<bool>>>,
    last: bool,
}

impl StopVote for ThreadVote {
    fn cast(&mut self, flag: bool) -> bool {
        self.votes.lock().unwrap()[self.rank] = flag;
        self.barrier.wait();
        let any = self.votes.lock().unwrap().iter().any(|&v| v);
        self.barrier.wait();
        std::mem::replace(&mut self.last, any)
    }
    fn complete(&mut self) -> bool {
        std::mem::take(&mut self.last)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn collectives_and_exchanges_between_three_ranks() {
        let out = run_ranks(3, |w| {
            let me = w.rank() as u64;
            let all = w.allgather(&(me, format!("r{me}")));
            let mut s = [me as f64, 1.0];
            w.sum_f64(&mut s);
            let b: u64 = w
                .broadcast(if me == 0 { Some(&42u64) } else { None })
                .unwrap();
            // Each rank sends its id to every rank (itself included).
            let a2a = w.alltoallv_u64(&vec![vec![me; me as usize + 1]; 3]);
            // A ring: exchange with both neighbours.
            let nbs = [(me as u32 + 2) % 3, (me as u32 + 1) % 3];
            let mut recv = vec![vec![0.0; 1]; 2];
            w.exchange_f64(&nbs, &[vec![me as f64], vec![me as f64]], &mut recv);
            (all, s, b, a2a, recv)
        });
        for (r, (all, s, b, a2a, recv)) in out.into_iter().enumerate() {
            assert_eq!(
                all,
                vec![(0, "r0".into()), (1, "r1".into()), (2, "r2".into())]
            );
            assert_eq!(s, [3.0, 3.0]);
            assert_eq!(b, 42);
            assert_eq!(a2a, vec![vec![0], vec![1, 1], vec![2, 2, 2]]);
            let nb = |d: usize| ((r + d) % 3) as f64;
            assert_eq!(recv, vec![vec![nb(2)], vec![nb(1)]]);
        }
    }
}
