//! Communication between ranks, behind one trait: [`Comm`] has the MPI
//! implementation ([`MpiWorld`], the only code that calls MPI) and a serial
//! one ([`Serial`], one rank, no MPI at all), and in-process ranks on
//! threads ([`run_ranks`]), with which contact, the exchanges between ranks
//! and the solver phases are unit-tested without mpirun.
//!
//! The rest of the crate takes a `&World` (= `&dyn Comm`). Typed messages
//! (`broadcast`, `allgather`, `scatter`) are bincode-encoded on top of the
//! trait's byte and number primitives.

pub mod exact_sum;
pub mod keep_awake;
mod mpi_world;
mod serial;
mod threads;
pub mod threads_per_rank;

pub use exact_sum::ExactSum;
pub use mpi_world::MpiWorld;
pub use serial::Serial;
pub use threads::{run_ranks, ThreadRank};

use crate::domain::Subdomain;
use serde::{de::DeserializeOwned, Serialize};

/// The ranks of one run, as the solver sees them.
pub type World = dyn Comm;

/// What the solver asks of its communicator. Collective calls must be made
/// by every rank in the same order; results come in rank order.
pub trait Comm {
    fn rank(&self) -> u32;
    fn size(&self) -> u32;
    /// Takes the job down (all ranks) with an exit code: a rank that fails
    /// must not leave the others hanging.
    fn abort(&self, code: i32) -> !;
    /// Rank 0 passes one buffer per rank (index = rank); each rank gets its own.
    fn scatter_bytes(&self, per_rank: Option<Vec<Vec<u8>>>) -> Result<Vec<u8>, String>;
    /// Rank 0's bytes on every rank (the others pass `None`).
    fn broadcast_bytes(&self, bytes: Option<Vec<u8>>) -> Vec<u8>;
    /// Sends `send[i]` to neighbour `ranks[i]` and returns what each sent back.
    /// Pairs are served in ascending neighbour order, the lower rank sending
    /// first, so blocking sends cannot deadlock.
    fn exchange_with_neighbours(&self, ranks: &[u32], send: &[Vec<u64>]) -> Vec<Vec<u64>>;
    /// Gathers one string per rank on rank 0 (in rank order).
    fn gather_strings(&self, s: &str) -> Option<Vec<String>>;
    fn barrier(&self);
    /// Every rank's bytes, in rank order, on every rank.
    fn allgather_bytes(&self, mine: &[u8]) -> Vec<Vec<u8>>;
    /// Every rank's u64 values concatenated in rank order, on every rank.
    /// Contact's Idel uses it for the element ids deleted in a cycle, only at
    /// the cycles where some rank deleted one.
    fn allgather_u64(&self, mine: &[u64]) -> Vec<u64>;
    /// Sum over ranks of each entry (diagnostics: not bitwise independent of the rank count).
    fn sum_f64(&self, v: &mut [f64]);
    /// Largest value over ranks.
    fn max_u64(&self, v: u64) -> u64;
    /// Maximum over ranks of each entry.
    fn max_f64(&self, v: &mut [f64]);
    /// Logical OR over ranks.
    fn any(&self, flag: bool) -> bool;
    /// Sends `send[i]` (f64 values) to neighbour `ranks[i]` and receives its
    /// values into `recv[i]`, whose lengths are known in advance.
    /// Non-blocking, so any neighbour order is safe.
    fn exchange_f64(&self, ranks: &[u32], send: &[Vec<f64>], recv: &mut [Vec<f64>]);
    /// Sends `send[r]` to every rank r (itself included) and returns what each
    /// rank sent here, in rank order (an all-to-all with variable counts).
    fn alltoallv_u64(&self, send: &[Vec<u64>]) -> Vec<Vec<u64>>;
    /// How this world opens the run's HDF5 files. Several ranks share a
    /// file through MPI-IO (HDF5's `mpio` driver on a duplicate of the world
    /// communicator; every rank opens it together). A single rank opens it
    /// as a plain POSIX file (the `sec2` driver): no MPI-IO layer between
    /// HDF5 and the file, and `H5Fflush` writes the metadata out without the
    /// fsync that `mpio` ends every flush with. File locking is off as it is
    /// under `mpio`, so a file being written can be read meanwhile. The file
    /// is the same either way. This is the one place the output code gets
    /// at MPI.
    fn hdf5_access(&self) -> Result<H5Access, String>;
    /// A stop vote whose reduction overlaps the next cycle (see [`StopVote`]).
    fn stop_vote(&self) -> Box<dyn StopVote>;
}

/// A logical OR over ranks taken once per cycle without a blocking
/// collective: each cycle completes the reduction started the cycle before
/// and starts the next one, so the vote costs no extra synchronisation
/// point. Every rank gets the result of the same reduction at the same
/// cycle, one cycle after the votes were cast.
pub trait StopVote {
    /// Completes the previous vote (false if none) and casts `flag` for the next.
    fn cast(&mut self, flag: bool) -> bool;
    /// Waits for the outstanding vote; its result (false if none).
    fn complete(&mut self) -> bool;
}

/// A file-access property list for the run's HDF5 files (see
/// `Comm::hdf5_access`) and whether it goes through MPI-IO: transfers are
/// then collective or independent, and a flush ends with an fsync.
pub struct H5Access {
    pub fapl: hdf5::plist::FileAccess,
    pub mpio: bool,
}

/// The plain-file (sec2) access of a single rank, file locking off.
fn plain_file_access() -> Result<H5Access, String> {
    let mut b = hdf5::plist::FileAccess::build();
    b.sec2().file_locking(false);
    let fapl = b.finish().map_err(|e| e.to_string())?;
    Ok(H5Access { fapl, mpio: false })
}

/// Typed messages over any communicator (bincode).
impl dyn Comm {
    /// Broadcasts a value from rank 0 (the others pass `None`).
    pub fn broadcast<T: Serialize + DeserializeOwned>(
        &self,
        value: Option<&T>,
    ) -> Result<T, String> {
        let mut bytes = None;
        if self.rank() == 0 {
            let v = value.ok_or("rank 0 has nothing to broadcast")?;
            bytes = Some(bincode::serialize(v).map_err(|e| e.to_string())?);
        }
        let got = self.broadcast_bytes(bytes);
        bincode::deserialize(&got).map_err(|e| e.to_string())
    }

    /// Every rank's values, in rank order, on every rank (a typed allgather).
    pub fn allgather<T: Serialize + DeserializeOwned>(&self, mine: &T) -> Vec<T> {
        let bytes = bincode::serialize(mine).expect("serializable");
        self.allgather_bytes(&bytes)
            .iter()
            .map(|b| bincode::deserialize(b).expect("same type on every rank"))
            .collect()
    }

    /// Rank 0 passes one Subdomain per rank; every rank gets its own back.
    pub fn scatter(&self, parts: Option<Vec<Subdomain>>) -> Result<Subdomain, String> {
        let per_rank = match (self.rank(), parts) {
            (0, None) => return Err("rank 0 has no subdomains to scatter".into()),
            (0, Some(parts)) => {
                let mut out = vec![Vec::new(); self.size() as usize];
                let mut mine = false;
                for sd in &parts {
                    mine |= sd.rank == 0;
                    out[sd.rank as usize] = bincode::serialize(sd).map_err(|e| e.to_string())?;
                }
                if !mine {
                    return Err("no subdomain for rank 0".into());
                }
                Some(out)
            }
            _ => None,
        };
        let bytes = self.scatter_bytes(per_rank)?;
        bincode::deserialize(&bytes).map_err(|e| e.to_string())
    }
}
