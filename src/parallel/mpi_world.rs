//! The MPI communicator: the one file that calls MPI (rsmpi). Start-up,
//! the point-to-point exchanges, the collectives and the MPI-IO handle that
//! parallel HDF5 (`crate::output`) opens its files with.

use super::{Comm, H5Access, StopVote};
use mpi::topology::SimpleCommunicator;
use mpi::traits::*;

/// The MPI world for this process (one rank when run without mpirun).
pub struct MpiWorld {
    _universe: mpi::environment::Universe,
    comm: SimpleCommunicator,
}

impl MpiWorld {
    /// Initialises MPI; `None` if it was already initialised.
    pub fn init() -> Option<MpiWorld> {
        // MPI-IO through ROMIO, not Open MPI's default OMPIO: on BOX1BL with
        // 2 ranks, once OMPIO had the run file open every later cycle was
        // slower (cycle loop 4.3 s against 0.6 s with ROMIO and 0.14 s with
        // no file, best of 7 on a loaded 2-core machine), far beyond the
        // time spent writing. A user's own OMPI_MCA_io is kept.
        if std::env::var_os("OMPI_MCA_io").is_none() {
            std::env::set_var("OMPI_MCA_io", "romio321");
        }
        let universe = mpi::initialize()?;
        let comm = universe.world();
        Some(MpiWorld {
            _universe: universe,
            comm,
        })
    }

    /// How many ranks of this job run on this rank's node (those that can
    /// share memory with it: MPI_Comm_split_type SHARED); threads per rank
    /// are chosen from it (`threads_per_rank`).
    pub fn ranks_on_this_node(&self) -> usize {
        self.comm.split_shared(self.comm.rank()).size().max(1) as usize
    }

    /// Every rank's values concatenated in rank order, on every rank (an
    /// MPI_Allgatherv after an MPI_Allgather of the counts), with each rank's
    /// count and offset.
    fn allgather_var<T: mpi::datatype::Equivalence + Default + Clone>(
        &self,
        mine: &[T],
    ) -> (Vec<T>, Vec<i32>, Vec<i32>) {
        use mpi::datatype::PartitionMut;
        let n = self.size() as usize;
        let len = mine.len() as i32;
        let mut lens = vec![0i32; n];
        self.comm.all_gather_into(&len, &mut lens[..]);
        let displs: Vec<i32> = lens
            .iter()
            .scan(0, |acc, &l| {
                let d = *acc;
                *acc += l;
                Some(d)
            })
            .collect();
        let total: i32 = lens.iter().sum();
        let mut buf = vec![T::default(); total as usize];
        {
            let mut part = PartitionMut::new(&mut buf[..], &lens[..], &displs[..]);
            self.comm.all_gather_varcount_into(mine, &mut part);
        }
        (buf, lens, displs)
    }
}

impl Comm for MpiWorld {
    fn rank(&self) -> u32 {
        self.comm.rank() as u32
    }
    fn size(&self) -> u32 {
        self.comm.size() as u32
    }

    /// Takes the job down (all ranks) with an exit code: a rank that fails must not leave the others hanging.
    fn abort(&self, code: i32) -> ! {
        self.comm.abort(code)
    }

    fn scatter_bytes(&self, per_rank: Option<Vec<Vec<u8>>>) -> Result<Vec<u8>, String> {
        const TAG: i32 = 11;
        if self.rank() == 0 {
            let mut parts = per_rank.ok_or("rank 0 has nothing to scatter")?;
            for (r, bytes) in parts.iter().enumerate().skip(1) {
                self.comm
                    .process_at_rank(r as i32)
                    .send_with_tag(&bytes[..], TAG);
            }
            Ok(std::mem::take(&mut parts[0]))
        } else {
            Ok(self
                .comm
                .process_at_rank(0)
                .receive_vec_with_tag::<u8>(TAG)
                .0)
        }
    }

    fn broadcast_bytes(&self, bytes: Option<Vec<u8>>) -> Vec<u8> {
        let root = self.comm.process_at_rank(0);
        let mut bytes = bytes.unwrap_or_default();
        let mut len = bytes.len() as u64;
        root.broadcast_into(&mut len);
        bytes.resize(len as usize, 0);
        root.broadcast_into(&mut bytes[..]);
        bytes
    }

    /// Sends `send[i]` to neighbour `ranks[i]` and returns what each sent back.
    /// Pairs are served in ascending neighbour order, the lower rank sending
    /// first, so blocking sends cannot deadlock.
    fn exchange_with_neighbours(&self, ranks: &[u32], send: &[Vec<u64>]) -> Vec<Vec<u64>> {
        const TAG: i32 = 12;
        let me = self.rank();
        ranks
            .iter()
            .zip(send)
            .map(|(&nb, out)| {
                let p = self.comm.process_at_rank(nb as i32);
                if me < nb {
                    p.send_with_tag(&out[..], TAG);
                    p.receive_vec_with_tag::<u64>(TAG).0
                } else {
                    let got = p.receive_vec_with_tag::<u64>(TAG).0;
                    p.send_with_tag(&out[..], TAG);
                    got
                }
            })
            .collect()
    }

    /// Gathers one string per rank on rank 0 (in rank order).
    fn gather_strings(&self, s: &str) -> Option<Vec<String>> {
        const TAG: i32 = 13;
        if self.rank() == 0 {
            let mut out = vec![s.to_string()];
            for r in 1..self.size() {
                let (b, _) = self
                    .comm
                    .process_at_rank(r as i32)
                    .receive_vec_with_tag::<u8>(TAG);
                out.push(String::from_utf8_lossy(&b).into_owned());
            }
            Some(out)
        } else {
            self.comm
                .process_at_rank(0)
                .send_with_tag(s.as_bytes(), TAG);
            None
        }
    }

    fn barrier(&self) {
        self.comm.barrier();
    }

    /// Every rank's bytes, in rank order, on every rank.
    fn allgather_bytes(&self, mine: &[u8]) -> Vec<Vec<u8>> {
        let (buf, lens, displs) = self.allgather_var(mine);
        (0..lens.len())
            .map(|r| buf[displs[r] as usize..(displs[r] + lens[r]) as usize].to_vec())
            .collect()
    }

    /// Every rank's u64 values concatenated in rank order, on every rank.
    /// Contact's Idel uses it for the element ids deleted in a cycle, only at
    /// the cycles where some rank deleted one.
    fn allgather_u64(&self, mine: &[u64]) -> Vec<u64> {
        self.allgather_var(mine).0
    }

    /// Sum over ranks of each entry (diagnostics: not bitwise independent of the rank count).
    fn sum_f64(&self, v: &mut [f64]) {
        use mpi::collective::SystemOperation;
        let send = v.to_vec();
        self.comm
            .all_reduce_into(&send[..], v, SystemOperation::sum());
    }

    /// Largest value over ranks.
    fn max_u64(&self, v: u64) -> u64 {
        use mpi::collective::SystemOperation;
        let mut out = 0u64;
        self.comm
            .all_reduce_into(&v, &mut out, SystemOperation::max());
        out
    }

    /// How this world opens the run's HDF5 files. Several ranks share a
    /// file through MPI-IO (HDF5's `mpio` driver on a duplicate of the world
    /// communicator; every rank opens it together). A single rank opens it
    /// as a plain POSIX file (the `sec2` driver): no MPI-IO layer between
    /// HDF5 and the file, and `H5Fflush` writes the metadata out without the
    /// fsync that `mpio` ends every flush with. File locking is off as it is
    /// under `mpio`, so a file being written can be read meanwhile. The file
    /// is the same either way. This is the one place the output code gets
    /// at MPI.
    fn hdf5_access(&self) -> Result<H5Access, String> {
        use mpi::raw::AsRaw;
        if self.size() == 1 {
            return super::plain_file_access();
        }
        let mut b = hdf5::plist::FileAccess::build();
        b.mpio(self.comm.as_raw(), None);
        let fapl = b.finish().map_err(|e| e.to_string())?;
        Ok(H5Access { fapl, mpio: true })
    }

    /// A stop vote whose all-reduce overlaps the next cycle (see `StopVote`).
    fn stop_vote(&self) -> Box<dyn StopVote> {
        use mpi::raw::AsRaw;
        Box::new(MpiVote {
            comm: self.comm.as_raw(),
            send: Box::new(0),
            recv: Box::new(0),
            req: None,
        })
    }

    /// Logical OR over ranks.
    fn any(&self, flag: bool) -> bool {
        use mpi::collective::SystemOperation;
        let mut out = 0i32;
        self.comm
            .all_reduce_into(&(flag as i32), &mut out, SystemOperation::max());
        out != 0
    }

    /// Sends `send[i]` (f64 values) to neighbour `ranks[i]` and receives its values into `recv[i]`,
    /// whose lengths are known in advance. Non-blocking, so any neighbour order is safe.
    fn exchange_f64(&self, ranks: &[u32], send: &[Vec<f64>], recv: &mut [Vec<f64>]) {
        const TAG: i32 = 21;
        mpi::request::scope(|scope| {
            let mut reqs = Vec::with_capacity(ranks.len() * 2);
            for (i, &nb) in ranks.iter().enumerate() {
                reqs.push(
                    self.comm
                        .process_at_rank(nb as i32)
                        .immediate_send_with_tag(scope, &send[i][..], TAG),
                );
            }
            for (i, r) in recv.iter_mut().enumerate() {
                reqs.push(
                    self.comm
                        .process_at_rank(ranks[i] as i32)
                        .immediate_receive_into_with_tag(scope, &mut r[..], TAG),
                );
            }
            for q in reqs {
                q.wait();
            }
        });
    }

    /// Maximum over ranks of each entry.
    fn max_f64(&self, v: &mut [f64]) {
        use mpi::collective::SystemOperation;
        let send = v.to_vec();
        self.comm
            .all_reduce_into(&send[..], v, SystemOperation::max());
    }

    /// Sends `send[r]` to every rank r (itself included) and returns what each
    /// rank sent here, in rank order (an all-to-all with variable counts).
    fn alltoallv_u64(&self, send: &[Vec<u64>]) -> Vec<Vec<u64>> {
        use mpi::datatype::{Partition, PartitionMut};
        let n = self.size() as usize;
        assert_eq!(send.len(), n);
        let counts: Vec<i32> = send.iter().map(|s| s.len() as i32).collect();
        let mut rcounts = vec![0i32; n];
        self.comm.all_to_all_into(&counts[..], &mut rcounts[..]);
        let displs = |c: &[i32]| -> Vec<i32> {
            c.iter()
                .scan(0, |a, &x| {
                    let d = *a;
                    *a += x;
                    Some(d)
                })
                .collect()
        };
        let sd = displs(&counts);
        let rd = displs(&rcounts);
        let flat: Vec<u64> = send.iter().flatten().copied().collect();
        let total: i32 = rcounts.iter().sum();
        let mut buf = vec![0u64; total as usize];
        {
            let sp = Partition::new(&flat[..], &counts[..], &sd[..]);
            let mut rp = PartitionMut::new(&mut buf[..], &rcounts[..], &rd[..]);
            self.comm.all_to_all_varcount_into(&sp, &mut rp);
        }
        (0..n)
            .map(|r| buf[rd[r] as usize..(rd[r] + rcounts[r]) as usize].to_vec())
            .collect()
    }
}

/// A logical OR over ranks taken once per cycle without a blocking
/// collective: each cycle completes the all-reduce started the cycle before
/// and starts the next one (MPI_Iallreduce), so the vote costs no extra
/// synchronisation point. Every rank gets the result of the same reduction
/// at the same cycle, one cycle after the votes were cast.
struct MpiVote {
    /// The world communicator (it outlives every vote: `MpiWorld` lives
    /// for the whole process).
    comm: mpi::ffi::MPI_Comm,
    send: Box<i32>,
    recv: Box<i32>,
    req: Option<mpi::ffi::MPI_Request>,
}

impl StopVote for MpiVote {
    /// Completes the previous vote (false if none) and casts `flag` for the next.
    fn cast(&mut self, flag: bool) -> bool {
        let result = self.complete();
        *self.send = flag as i32;
        let mut req = std::mem::MaybeUninit::<mpi::ffi::MPI_Request>::uninit();
        // SAFETY: the buffers are boxed (stable addresses) and live in self
        // until the request completes (`complete`, also on drop).
        unsafe {
            mpi::ffi::MPI_Iallreduce(
                (&*self.send as *const i32).cast(),
                (&mut *self.recv as *mut i32).cast(),
                1,
                mpi::ffi::RSMPI_INT32_T,
                mpi::ffi::RSMPI_MAX,
                self.comm,
                req.as_mut_ptr(),
            );
            self.req = Some(req.assume_init());
        }
        result
    }

    /// Waits for the outstanding vote; its result (false if none).
    fn complete(&mut self) -> bool {
        match self.req.take() {
            Some(mut r) => {
                unsafe {
                    mpi::ffi::MPI_Wait(&mut r, mpi::ffi::RSMPI_STATUS_IGNORE);
                }
                *self.recv != 0
            }
            None => false,
        }
    }
}

impl Drop for MpiVote {
    fn drop(&mut self) {
        if self.req.is_some() {
            let mut finalized = 0;
            unsafe {
                mpi::ffi::MPI_Finalized(&mut finalized);
            }
            if finalized == 0 {
                self.complete();
            }
        }
    }
}
