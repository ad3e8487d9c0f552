//! Restart files `DIR/NAME_rst.h5`: the full state of the explicit loop, in
//! global order, so that a run can continue from it on any number of ranks
//! and end bitwise where the run that never stopped ends.
//!
//! # Format: named sections
//!
//! The file is a set of named sections under `/sections/NAME` (names are
//! `[a-z0-9_.]`), each with an attribute `kind`:
//!
//! | kind | datasets | what for |
//! | --- | --- | --- |
//! | `replicated` | `bytes [L] u8`: bincode of a serde value | values every rank holds alike (time, cycle, rigid bodies, counters) |
//! | `dense_f64` | `values [N, W] f64` | rows keyed by a dense global index (nodes) |
//! | `dense_bytes` | `bytes [N, L] u8`, `len [N] u32` | one record per dense global index (element states) |
//! | `keyed` | `keys [K] u64`, `bytes [K, L] u8`, `len [K] u32` | sparse records keyed by any u64 built from global ids |
//!
//! Every rank writes the rows it owns (collective MPI-IO, see `h5`); every
//! rank reads back the rows it holds, whatever the partition that wrote them.
//!
//! The solver's sections: `solver` (replicated `LoopScalars`), `output`
//! (replicated `OutputCounters`), `nodes.x`, `nodes.v`, `nodes.vr` `[N,3]`,
//! `nodes.fint`, `nodes.fext` `[N,6]`, `elements.KIND` (one `Block::export_state`
//! record per element), `walls.tied` (keyed: wall index << 32 | global node,
//! present when tied). Decks with interfaces add `contact`, `contact.pairs`,
//! `contact.x_sort`, `nodes.fcont`, `nodes.fixed` and `tied`, `tied.d`,
//! `tied.x_ghost` (`save_interfaces`, `contact::restart`); a deck with
//! interfaces refuses a file without them.
//!
//! **Adding state** (the contact code, for instance per-interface friction
//! history): write one more section with a new name — `keyed` with keys
//! built from global ids (interface index, secondary node, main segment) is
//! made for that — and read it back by name; `RestartReader::has` tells an
//! old file from a new one. Existing sections and readers are unchanged, so
//! the format does not change.
//!
//! A restart file is written to `NAME_rst.h5.tmp` and renamed when complete:
//! a run killed while writing keeps the previous restart file.

use super::h5::{self, Rows, Xfer};
use super::{Context, LoopState};
use crate::kinematics::rigid_body::{NodeLoad, RigidBodyState};
use crate::parallel::exact_sum::{sum_over_ranks, ExactSum};
use crate::parallel::World;
use hdf5::types::VarLenUnicode;
use hdf5::{File, Group};
use serde::{de::DeserializeOwned, Deserialize, Serialize};
use std::path::{Path, PathBuf};

pub const FORMAT: &str = "crashsim-restart 1";

/// Collective writer of a restart file: every rank calls every method, in
/// the same order.
pub struct RestartWriter<'w> {
    world: &'w World,
    file: File,
    sections: Group,
    xfer: Xfer,
    tmp: PathBuf,
    path: PathBuf,
}

fn check_name(name: &str) -> Result<(), String> {
    if name.is_empty()
        || !name
            .bytes()
            .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == b'_' || c == b'.')
    {
        return Err(format!(
            "restart section name '{name}': expected [a-z0-9_.]"
        ));
    }
    Ok(())
}

impl<'w> RestartWriter<'w> {
    pub fn create(world: &'w World, path: &Path) -> Result<RestartWriter<'w>, String> {
        let tmp = PathBuf::from(format!("{}.tmp", path.display()));
        let access = world.hdf5_access()?;
        let file = File::with_options()
            .set_access_plist(&access.fapl)
            .map_err(|e| e.to_string())?
            .create(&tmp)
            .map_err(|e| format!("{}: cannot create the restart file: {e}", tmp.display()))?;
        let v: VarLenUnicode = FORMAT.parse().unwrap_or_default();
        file.new_attr::<VarLenUnicode>()
            .create("format")
            .and_then(|a| a.write_scalar(&v))
            .map_err(|e| e.to_string())?;
        let sections = file.create_group("sections").map_err(|e| e.to_string())?;
        Ok(RestartWriter {
            world,
            file,
            sections,
            xfer: Xfer::collective(access.mpio)?,
            tmp,
            path: path.to_path_buf(),
        })
    }

    fn section(&self, name: &str, kind: &str) -> Result<Group, String> {
        check_name(name)?;
        let g = self
            .sections
            .create_group(name)
            .map_err(|e| format!("restart section {name}: {e}"))?;
        let v: VarLenUnicode = kind.parse().unwrap_or_default();
        g.new_attr::<VarLenUnicode>()
            .create("kind")
            .and_then(|a| a.write_scalar(&v))
            .map_err(|e| e.to_string())?;
        Ok(g)
    }

    /// A value every rank holds alike; rank 0 writes it.
    pub fn replicated<T: Serialize>(&mut self, name: &str, value: &T) -> Result<(), String> {
        let g = self.section(name, "replicated")?;
        let bytes = bincode::serialize(value).map_err(|e| e.to_string())?;
        let ds = g
            .new_dataset::<u8>()
            .shape([bytes.len()])
            .create("bytes")
            .map_err(|e| e.to_string())?;
        let rows = Rows::root(bytes.len(), self.world.rank());
        let data = if rows.is_empty() { &[][..] } else { &bytes[..] };
        h5::write_rows(&ds, &rows, data, &self.xfer)
    }

    /// `total` rows of `width` values keyed by a dense global index; this
    /// rank writes `rows` (packed in `data`).
    pub fn dense_f64(
        &mut self,
        name: &str,
        total: usize,
        width: usize,
        rows: &Rows,
        data: &[f64],
    ) -> Result<(), String> {
        let g = self.section(name, "dense_f64")?;
        let ds = g
            .new_dataset::<f64>()
            .shape([total, width])
            .create("values")
            .map_err(|e| e.to_string())?;
        h5::write_rows(&ds, rows, data, &self.xfer)
    }

    fn records(
        &mut self,
        g: &Group,
        total: usize,
        rows: &Rows,
        records: &[&[u8]],
    ) -> Result<(), String> {
        let local_max = records.iter().map(|r| r.len()).max().unwrap_or(0) as u64;
        let width = self.world.max_u64(local_max).max(1) as usize;
        let mut bytes = vec![0u8; records.len() * width];
        for (i, r) in records.iter().enumerate() {
            bytes[i * width..i * width + r.len()].copy_from_slice(r);
        }
        let lens: Vec<u32> = records.iter().map(|r| r.len() as u32).collect();
        let ds = g
            .new_dataset::<u8>()
            .shape([total, width])
            .create("bytes")
            .map_err(|e| e.to_string())?;
        h5::write_rows(&ds, rows, &bytes, &self.xfer)?;
        let ds = g
            .new_dataset::<u32>()
            .shape([total])
            .create("len")
            .map_err(|e| e.to_string())?;
        h5::write_rows(&ds, rows, &lens, &self.xfer)
    }

    /// One byte record per dense global index; this rank writes `rows`.
    pub fn dense_bytes(
        &mut self,
        name: &str,
        total: usize,
        rows: &Rows,
        records: &[Vec<u8>],
    ) -> Result<(), String> {
        let g = self.section(name, "dense_bytes")?;
        let refs: Vec<&[u8]> = records.iter().map(|r| &r[..]).collect();
        self.records(&g, total, rows, &refs)
    }

    /// Sparse records keyed by any u64 (no key on two ranks). Stored in rank
    /// order; readers get them all and keep what they hold.
    pub fn keyed(&mut self, name: &str, records: &[(u64, Vec<u8>)]) -> Result<(), String> {
        let g = self.section(name, "keyed")?;
        let counts: Vec<u64> = self.world.allgather(&(records.len() as u64));
        let first: u64 = counts[..self.world.rank() as usize].iter().sum();
        let total: u64 = counts.iter().sum();
        let rows = Rows::range(first, records.len() as u64);
        let keys: Vec<u64> = records.iter().map(|r| r.0).collect();
        let ds = g
            .new_dataset::<u64>()
            .shape([total as usize])
            .create("keys")
            .map_err(|e| e.to_string())?;
        h5::write_rows(&ds, &rows, &keys, &self.xfer)?;
        let refs: Vec<&[u8]> = records.iter().map(|r| &r.1[..]).collect();
        self.records(&g, total as usize, &rows, &refs)
    }

    /// Closes the file and puts it in place (collective).
    pub fn finish(self) -> Result<(), String> {
        let RestartWriter {
            world,
            file,
            sections,
            xfer,
            tmp,
            path,
        } = self;
        drop(sections);
        drop(xfer);
        file.close().map_err(|e| e.to_string())?;
        world.barrier();
        if world.rank() == 0 {
            std::fs::rename(&tmp, &path).map_err(|e| {
                format!(
                    "{}: cannot put the restart file in place: {e}",
                    path.display()
                )
            })?;
        }
        world.barrier();
        Ok(())
    }
}

/// Collective reader of a restart file.
pub struct RestartReader {
    file: File,
    xfer: Xfer,
    path: PathBuf,
}

impl RestartReader {
    pub fn open(world: &World, path: &Path) -> Result<RestartReader, String> {
        if !path.is_file() {
            return Err(format!(
                "{}: no such restart file: expected a NAME_rst.h5 written by crashsim run",
                path.display()
            ));
        }
        let access = world.hdf5_access()?;
        let file = File::with_options()
            .set_access_plist(&access.fapl)
            .map_err(|e| e.to_string())?
            .open(path)
            .map_err(|_| {
                format!(
                    "{}: not an HDF5 file: expected a crashsim restart file ({FORMAT})",
                    path.display()
                )
            })?;
        let fmt = file
            .attr("format")
            .and_then(|a| a.read_scalar::<VarLenUnicode>())
            .map(|s| s.to_string())
            .unwrap_or_default();
        if fmt != FORMAT {
            return Err(format!(
                "{}: format '{fmt}': expected a crashsim restart file ({FORMAT})",
                path.display()
            ));
        }
        Ok(RestartReader {
            file,
            xfer: Xfer::collective(access.mpio)?,
            path: path.to_path_buf(),
        })
    }

    fn err(&self, what: impl std::fmt::Display) -> String {
        format!("{}: {what}", self.path.display())
    }

    /// Whether the file has a section (a newer writer may add some).
    pub fn has(&self, name: &str) -> bool {
        self.file.group(&format!("sections/{name}")).is_ok()
    }

    fn group(&self, name: &str, kind: &str) -> Result<Group, String> {
        let g = self
            .file
            .group(&format!("sections/{name}"))
            .map_err(|_| self.err(format!("no section '{name}' in the restart file")))?;
        let k = g
            .attr("kind")
            .and_then(|a| a.read_scalar::<VarLenUnicode>())
            .map(|s| s.to_string())
            .unwrap_or_default();
        if k != kind {
            return Err(self.err(format!("section '{name}' is '{k}', expected '{kind}'")));
        }
        Ok(g)
    }

    pub fn replicated<T: DeserializeOwned>(&self, name: &str) -> Result<T, String> {
        let g = self.group(name, "replicated")?;
        let ds = g.dataset("bytes").map_err(|e| self.err(e))?;
        let n = ds.shape()[0];
        let bytes: Vec<u8> = h5::read_rows(&ds, &Rows::range(0, n as u64), &self.xfer)?;
        bincode::deserialize(&bytes).map_err(|e| self.err(format!("section '{name}': {e}")))
    }

    /// Total rows, width and this rank's `rows` of a dense f64 section.
    pub fn dense_f64(&self, name: &str, rows: &Rows) -> Result<(usize, usize, Vec<f64>), String> {
        let g = self.group(name, "dense_f64")?;
        let ds = g.dataset("values").map_err(|e| self.err(e))?;
        let shape = ds.shape();
        Ok((shape[0], shape[1], h5::read_rows(&ds, rows, &self.xfer)?))
    }

    fn read_records(&self, g: &Group, rows: &Rows) -> Result<(usize, Vec<Vec<u8>>), String> {
        let ds = g.dataset("bytes").map_err(|e| self.err(e))?;
        let shape = ds.shape();
        let width = shape[1];
        let bytes: Vec<u8> = h5::read_rows(&ds, rows, &self.xfer)?;
        let lens: Vec<u32> = h5::read_rows(
            &g.dataset("len").map_err(|e| self.err(e))?,
            rows,
            &self.xfer,
        )?;
        Ok((
            shape[0],
            lens.iter()
                .enumerate()
                .map(|(i, &l)| bytes[i * width..i * width + (l as usize).min(width)].to_vec())
                .collect(),
        ))
    }

    /// Total rows and this rank's records of a dense byte section.
    pub fn dense_bytes(&self, name: &str, rows: &Rows) -> Result<(usize, Vec<Vec<u8>>), String> {
        let g = self.group(name, "dense_bytes")?;
        self.read_records(&g, rows)
    }

    /// Every record of a keyed section (all ranks get all of them).
    pub fn keyed(&self, name: &str) -> Result<Vec<(u64, Vec<u8>)>, String> {
        let g = self.group(name, "keyed")?;
        let ds = g.dataset("keys").map_err(|e| self.err(e))?;
        let all = Rows::range(0, ds.shape()[0] as u64);
        let keys: Vec<u64> = h5::read_rows(&ds, &all, &self.xfer)?;
        let (_, recs) = self.read_records(&g, &all)?;
        Ok(keys.into_iter().zip(recs).collect())
    }
}

/// The explicit loop's scalars and replicated state.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct LoopScalars {
    pub deck: String,
    pub nodes: u64,
    /// Elements per kind (`ElementKind::ALL` order): the deck must match.
    pub elements: Vec<u64>,
    pub t: f64,
    pub cycle: u64,
    pub dt: f64,
    pub dt_prev: f64,
    pub step_what: String,
    pub step_id: u64,
    /// Exact sums over the ranks, as `ExactSum` words (each rank keeps a
    /// partial; rank 0 takes the whole back): external and rigid-wall work.
    pub w_ext: Vec<u64>,
    pub wall_work: Vec<u64>,
    pub next_th: f64,
    pub history: Vec<(f64, Vec<[f64; 3]>)>,
    pub bodies: Vec<RigidBodyState>,
    pub wall_p: Vec<[f64; 3]>,
    pub wall_v: Vec<[f64; 3]>,
    /// The contact reactions on rigid bodies (TYPE14) the next cycle
    /// applies, gathered from every rank in rank order (a node's loads all
    /// come from its owner, so their order survives another rank count).
    #[serde(default)]
    pub body_loads: Vec<(usize, NodeLoad)>,
}

/// Where the output stood (replicated).
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub struct OutputCounters {
    /// (time, cycle) of each state in the run file.
    pub states: Vec<(f64, u64)>,
    /// Time-history rows in the run file, and the next sample time.
    pub th_rows: usize,
    pub next_th: f64,
    /// Next /ANIM/DT time.
    pub next_anim: f64,
}

/// The listing's names of what sets the time step, as `&'static str`.
fn static_name(s: &str) -> &'static str {
    const NAMES: [&str; 8] = [
        "SHELL", "SH3N", "BRICK", "TETRA4", "SPRING", "TRUSS", "BEAM", "NODE",
    ];
    NAMES
        .iter()
        .find(|&&n| n == s)
        .copied()
        .unwrap_or_else(|| Box::leak(s.to_string().into_boxed_str()))
}

/// Owned nodes as rows, and their local indices.
fn owned_rows(ctx: &Context) -> (Rows, Vec<usize>) {
    let sd = ctx.sd;
    let local: Vec<usize> = (0..sd.node_global.len())
        .filter(|&l| sd.owns(l as u32))
        .collect();
    (
        Rows::from_sorted(local.iter().map(|&l| sd.node_global[l] as u64)),
        local,
    )
}

fn pack<const W: usize>(local: &[usize], a: &[[f64; W]]) -> Vec<f64> {
    local.iter().flat_map(|&l| a[l]).collect()
}

/// Writes the restart file (collective).
pub fn save(
    ctx: &Context,
    path: &Path,
    s: &LoopState,
    counters: &OutputCounters,
) -> Result<(), String> {
    let g = ctx.g;
    let n = g.node_ids.len();
    let mut sums = [*s.w_ext, *s.wall_work];
    sum_over_ranks(ctx.world, &mut sums);
    let body_loads: Vec<(usize, NodeLoad)> = ctx
        .world
        .allgather(&s.contact.body_loads)
        .into_iter()
        .flatten()
        .collect();
    let scalars = LoopScalars {
        deck: g.name.clone(),
        nodes: n as u64,
        elements: g.element_ids.iter().map(|e| e.len() as u64).collect(),
        t: *s.t,
        cycle: *s.cycle,
        dt: *s.dt,
        dt_prev: *s.dt_prev,
        step_what: s.step_what.to_string(),
        step_id: *s.step_id,
        w_ext: sums[0].to_words().to_vec(),
        wall_work: sums[1].to_words().to_vec(),
        next_th: *s.next_th,
        history: s.history.clone(),
        bodies: s.bodies.to_vec(),
        wall_p: s.wall_p.to_vec(),
        wall_v: s.wall_v.to_vec(),
        body_loads,
    };
    let mut w = RestartWriter::create(ctx.world, path)?;
    w.replicated("solver", &scalars)?;
    w.replicated("output", counters)?;
    let (rows, local) = owned_rows(ctx);
    w.dense_f64("nodes.x", n, 3, &rows, &pack(&local, s.x))?;
    w.dense_f64("nodes.v", n, 3, &rows, &pack(&local, s.v))?;
    w.dense_f64("nodes.vr", n, 3, &rows, &pack(&local, s.vr))?;
    w.dense_f64("nodes.fint", n, 6, &rows, &pack(&local, s.fint))?;
    w.dense_f64("nodes.fext", n, 6, &rows, &pack(&local, s.fext))?;
    for kr in super::runfile::kind_rows(ctx, s.blocks) {
        let recs: Vec<Vec<u8>> = kr
            .members
            .iter()
            .map(|&(b, e)| s.blocks[b].export_state(e))
            .collect();
        w.dense_bytes(
            &format!("elements.{}", kr.kind.file_name()),
            kr.total,
            &kr.rows,
            &recs,
        )?;
    }
    let mut tied = Vec::new();
    for (wi, nodes) in wall_locals(ctx).iter().enumerate() {
        for (i, &l) in nodes.iter().enumerate() {
            if s.tied[wi][i] && ctx.sd.owns(l as u32) {
                tied.push(((wi as u64) << 32 | ctx.sd.node_global[l] as u64, Vec::new()));
            }
        }
    }
    w.keyed("walls.tied", &tied)?;
    save_interfaces(ctx, &mut w, s, &rows, &local)?;
    w.finish()
}

/// A node's fixed degrees of freedom as a bit mask (bit k: DOF k).
fn fixed_mask(f: &[bool; 6]) -> u8 {
    f.iter()
        .enumerate()
        .fold(0u8, |m, (k, &b)| m | (u8::from(b) << k))
}

/// The contact and tied interfaces' sections (module `contact::restart`),
/// present when the deck has such interfaces:
///
/// - `contact` (replicated `ContactScalars`), `contact.pairs` (keyed:
///   interface << 40 | pass << 32 | secondary global node → the node's
///   memory, candidates and pair memory), `contact.x_sort` `[C,3]` (rows by
///   contact node: positions at the last sort), `nodes.fcont` `[N,3]` (the
///   last cycle's contact forces), `nodes.fixed` (keyed: global node → mask
///   of fixed DOFs, IBC releases some);
/// - `tied` (replicated: (id, ties) per interface), `tied.d` (keyed:
///   interface << 32 | secondary global node → offset), `tied.x_ghost`
///   `[T,3]` (rows by tied node: the position ghosts hold).
fn save_interfaces(
    ctx: &Context,
    w: &mut RestartWriter,
    s: &LoopState,
    rows: &Rows,
    local: &[usize],
) -> Result<(), String> {
    let n = ctx.g.node_ids.len();
    if !s.contact.is_empty() {
        // The whole contact energy on rank 0 (the export sums over ranks).
        let mut e = [*s.e_contact];
        sum_over_ranks(ctx.world, &mut e);
        let mine = if ctx.world.rank() == 0 {
            e[0].value()
        } else {
            0.0
        };
        let ex = s.contact.export(ctx.world, mine)?;
        w.replicated("contact", &ex.scalars)?;
        w.keyed("contact.pairs", &ex.records)?;
        w.dense_f64(
            "contact.x_sort",
            s.contact.node_count(),
            3,
            &Rows::from_sorted(ex.sort_rows.iter().copied()),
            &ex.x_sort,
        )?;
        w.dense_f64("nodes.fcont", n, 3, rows, &pack(local, s.fcont))?;
        let fixed: Vec<(u64, Vec<u8>)> = local
            .iter()
            .filter(|&&l| s.fixed[l].iter().any(|&b| b))
            .map(|&l| (ctx.sd.node_global[l] as u64, vec![fixed_mask(&s.fixed[l])]))
            .collect();
        w.keyed("nodes.fixed", &fixed)?;
    }
    if !s.ties.is_empty() {
        let ex = s.ties.export();
        w.replicated("tied", &ex.shape)?;
        w.keyed("tied.d", &ex.offsets)?;
        w.dense_f64(
            "tied.x_ghost",
            s.ties.node_count(),
            3,
            &Rows::from_sorted(ex.ghost_rows.iter().copied()),
            &ex.x_ghost,
        )?;
    }
    Ok(())
}

/// Reads the interfaces' sections back (see `save_interfaces`).
fn restore_interfaces(
    ctx: &Context,
    r: &RestartReader,
    s: &mut LoopState,
    all: &Rows,
) -> Result<(), String> {
    let n = ctx.g.node_ids.len();
    let old = |what: &str, sec: &str| {
        r.err(format!(
            "no section '{sec}': the deck has {what} but the restart file holds no state for them (written by a crashsim that did not save it, or for another deck): expected a restart file written by this version for this deck"
        ))
    };
    if s.contact.is_empty() {
        if r.has("contact") {
            return Err(r.err(
                "the restart file holds contact interfaces, this deck has none: expected a restart file of this deck",
            ));
        }
    } else {
        for sec in [
            "contact",
            "contact.pairs",
            "contact.x_sort",
            "nodes.fcont",
            "nodes.fixed",
        ] {
            if !r.has(sec) {
                return Err(old("contact interfaces", sec));
            }
        }
        let sc: crate::contact::restart::ContactScalars = r.replicated("contact")?;
        let records = r.keyed("contact.pairs")?;
        let rows = Rows::from_sorted(s.contact.held_rows());
        let (total, width, x_sort) = r.dense_f64("contact.x_sort", &rows)?;
        if total != s.contact.node_count() || width != 3 {
            return Err(r.err(format!(
                "section 'contact.x_sort' is {total}×{width}, expected {}×3 (a restart file of another deck?)",
                s.contact.node_count()
            )));
        }
        s.contact
            .import(ctx.world, &sc, &records, &x_sort)
            .map_err(|m| r.err(m))?;
        *s.e_contact = if ctx.world.rank() == 0 {
            ExactSum::of(sc.e_contact)
        } else {
            ExactSum::default()
        };
        unpack(r, "nodes.fcont", all, n, s.fcont)?;
        let mut fixed: Vec<(u64, u8)> = r
            .keyed("nodes.fixed")?
            .into_iter()
            .map(|(k, b)| (k, b.first().copied().unwrap_or(0)))
            .collect();
        fixed.sort_unstable();
        for (l, f) in s.fixed.iter_mut().enumerate() {
            let gn = ctx.sd.node_global[l] as u64;
            let mask = match fixed.binary_search_by_key(&gn, |e| e.0) {
                Ok(i) => fixed[i].1,
                Err(_) => 0,
            };
            for (k, b) in f.iter_mut().enumerate() {
                *b = mask >> k & 1 == 1;
            }
        }
    }
    if s.ties.is_empty() {
        if r.has("tied") {
            return Err(r.err(
                "the restart file holds tied interfaces (TYPE2), this deck has none: expected a restart file of this deck",
            ));
        }
    } else {
        for sec in ["tied", "tied.d", "tied.x_ghost"] {
            if !r.has(sec) {
                return Err(old("tied interfaces (TYPE2)", sec));
            }
        }
        let shape: Vec<(u64, u64)> = r.replicated("tied")?;
        let offsets = r.keyed("tied.d")?;
        let rows = Rows::from_sorted(s.ties.ghost_rows());
        let (total, width, xg) = r.dense_f64("tied.x_ghost", &rows)?;
        if total != s.ties.node_count() || width != 3 {
            return Err(r.err(format!(
                "section 'tied.x_ghost' is {total}×{width}, expected {}×3 (a restart file of another deck?)",
                s.ties.node_count()
            )));
        }
        s.ties.import(&shape, &offsets, &xg).map_err(|m| r.err(m))?;
    }
    Ok(())
}

/// Each wall's secondary nodes held here, as local indices, in the order
/// the solver keeps its `tied` flags (the wall's global list order).
fn wall_locals(ctx: &Context) -> Vec<Vec<usize>> {
    ctx.g
        .rigid_walls
        .iter()
        .map(|w| {
            w.secondary_nodes
                .iter()
                .filter_map(|gn| ctx.sd.node_global.binary_search(gn).ok())
                .collect()
        })
        .collect()
}

fn unpack<const W: usize>(
    r: &RestartReader,
    name: &str,
    rows: &Rows,
    n: usize,
    out: &mut [[f64; W]],
) -> Result<(), String> {
    let (total, width, vals) = r.dense_f64(name, rows)?;
    if total != n || width != W {
        return Err(r.err(format!(
            "section '{name}' is {total}×{width}, expected {n}×{W} (a restart file of another deck?)"
        )));
    }
    for (i, o) in out.iter_mut().enumerate() {
        o.copy_from_slice(&vals[i * W..(i + 1) * W]);
    }
    Ok(())
}

/// Reads a restart file into the loop state (collective); returns where
/// the output stood.
pub fn restore(ctx: &Context, path: &Path, s: &mut LoopState) -> Result<OutputCounters, String> {
    let r = RestartReader::open(ctx.world, path)?;
    let g = ctx.g;
    let sc: LoopScalars = r.replicated("solver")?;
    let elements: Vec<u64> = g.element_ids.iter().map(|e| e.len() as u64).collect();
    if sc.nodes != g.node_ids.len() as u64 || sc.elements != elements || sc.deck != g.name {
        return Err(r.err(format!(
            "written for deck {} ({} nodes, {:?} elements), this deck is {} ({} nodes, {:?} elements): expected a restart file of this deck",
            sc.deck, sc.nodes, sc.elements, g.name, g.node_ids.len(), elements
        )));
    }
    if sc.bodies.len() != s.bodies.len() || sc.wall_p.len() != s.wall_p.len() {
        return Err(r.err("rigid bodies or walls differ from the deck's"));
    }
    let counters: OutputCounters = r.replicated("output")?;
    let sd = ctx.sd;
    let n = g.node_ids.len();
    let all = Rows::from_sorted(sd.node_global.iter().map(|&gn| gn as u64));
    unpack(&r, "nodes.x", &all, n, s.x)?;
    unpack(&r, "nodes.v", &all, n, s.v)?;
    unpack(&r, "nodes.vr", &all, n, s.vr)?;
    unpack(&r, "nodes.fint", &all, n, s.fint)?;
    unpack(&r, "nodes.fext", &all, n, s.fext)?;
    for kr in super::runfile::kind_rows(ctx, s.blocks) {
        let name = format!("elements.{}", kr.kind.file_name());
        let (total, recs) = r.dense_bytes(&name, &kr.rows)?;
        if total != kr.total {
            return Err(r.err(format!(
                "section '{name}' has {total} elements, expected {}",
                kr.total
            )));
        }
        for (&(b, e), rec) in kr.members.iter().zip(&recs) {
            s.blocks[b]
                .import_state(e, rec)
                .map_err(|m| r.err(format!("section '{name}': {m}")))?;
        }
    }
    let mut tied: Vec<u64> = r.keyed("walls.tied")?.into_iter().map(|(k, _)| k).collect();
    tied.sort_unstable();
    for (wi, nodes) in wall_locals(ctx).iter().enumerate() {
        for (i, &l) in nodes.iter().enumerate() {
            let key = (wi as u64) << 32 | sd.node_global[l] as u64;
            s.tied[wi][i] = tied.binary_search(&key).is_ok();
        }
    }
    restore_interfaces(ctx, &r, s, &all)?;
    *s.t = sc.t;
    *s.cycle = sc.cycle;
    *s.dt = sc.dt;
    *s.dt_prev = sc.dt_prev;
    *s.step_what = static_name(&sc.step_what);
    *s.step_id = sc.step_id;
    // Partial sums: the whole on rank 0.
    let root = ctx.world.rank() == 0;
    let whole = |w: &[u64]| -> Result<ExactSum, String> {
        if w.len() != ExactSum::WORDS {
            return Err(format!(
                "{}: the work sums have {} words, expected {} (a restart file of another version)",
                path.display(),
                w.len(),
                ExactSum::WORDS
            ));
        }
        Ok(if root {
            ExactSum::from_words(w)
        } else {
            ExactSum::default()
        })
    };
    *s.w_ext = whole(&sc.w_ext)?;
    *s.wall_work = whole(&sc.wall_work)?;
    *s.next_th = sc.next_th;
    *s.history = sc.history;
    s.bodies.clone_from_slice(&sc.bodies);
    // The reactions go back on rank 0 alone, in their gathered order.
    s.contact.body_loads = if ctx.world.rank() == 0 {
        sc.body_loads
    } else {
        Vec::new()
    };
    s.wall_p.copy_from_slice(&sc.wall_p);
    s.wall_v.copy_from_slice(&sc.wall_v);
    Ok(counters)
}
