//! The run's HDF5 file `DIR/NAME.h5`, written by every rank together through
//! MPI-IO (see `h5` for how rows are selected).
//!
//! ```text
//! /                      attributes: deck, title, units_mass, units_length, units_time,
//!                        crashsim_version, ranks, format (`FORMAT`)
//! /mesh/node_ids         [N]      u64   node ids, global (id) order
//! /mesh/coordinates      [N,3]    f64   initial coordinates
//! /mesh/<kind>/          one group per element kind present (shell4, shell3, brick8, tetra4, spring)
//!     connectivity       [E,n]    i64   global node indices (rows of the node arrays; -1 = absent)
//!     ids                [E]      u64   element ids
//!     part_ids           [E]      u64
//! /mesh/parts/           id, title, material_id, property_id          [P]
//! /mesh/materials/       id, title, law, density                      [M]
//! /mesh/interfaces/      id, type, title                              [I]
//! /mesh/rigid_walls/     id, title                                    [W]
//! /states/NNNN/          at t = 0, every /ANIM/DT time and the last cycle; attributes time, cycle
//!     coordinates, displacement, velocity, contact_force   [N,3] f64
//!     <kind>/von_mises, plastic_strain, thickness (shells) [E] f64, deleted [E] u8
//! /th/rows               [T] records: time, cycle, global [10], parts [P,3], interfaces [I,13],
//!                        rigid_walls [W,3], nodes [M,9] (see `history`; the attribute named
//!                        after a member names its columns)
//! /th/<table>/id         ids of the parts, interfaces, rigid walls and /TH/NODE nodes
//! ```
//!
//! Rows are in global order whatever the partition: the file is the same
//! for any number of ranks except the `ranks` attribute. After each state
//! (and the time-history rows gathered since the last one) the file is
//! made complete on disk (`RunFile::checkpoint`), so a run that dies keeps
//! a readable file up to its last complete state.

use super::h5::{self, Rows, Text, Xfer};
use super::history::{ThLayout, ThRow};
use super::{Context, InterfaceInfo, LoopState};
use crate::element::blocks::ElemOut;
use crate::model::NO_NODE;
use crate::model::{ElementKind, MaterialLaw};
use crate::parallel::H5Access;
use hdf5::types::VarLenUnicode;
use hdf5::{Dataset, File, Group, H5Type};

/// The `format` attribute of a run file. Format 1 (before November 2026)
/// had one `/th` dataset per table.
pub const FORMAT: &str = "crashsim-run 2";

/// The time-history member `name` of a run file's `/th/rows` (`time`,
/// `global`, `parts`, ...) as `[T, dims...]` and its values, row after row;
/// `[T, 0]` and no values when the records have no such member (a table
/// without objects).
pub fn read_th(f: &File, name: &str) -> Result<(Vec<usize>, Vec<f64>), String> {
    let ds = f
        .dataset("th/rows")
        .map_err(|_| "no dataset /th/rows: expected a run file with time histories".to_string())?;
    let t = ds.shape().first().copied().unwrap_or(0);
    let read = if name == "cycle" {
        h5::read_member::<u64>(&ds, name)?
            .map(|(d, v)| (d, v.into_iter().map(|c| c as f64).collect()))
    } else {
        h5::read_member::<f64>(&ds, name)?
    };
    Ok(match read {
        Some((dims, v)) => {
            let mut shape = vec![t];
            shape.extend(dims);
            (shape, v)
        }
        None => (vec![t, 0], Vec::new()),
    })
}

/// One element kind present in the model: its global count, the rows this
/// rank writes (its elements' global indices) and where each row's element
/// lives: (block, element in the block), in row order. A kind may be held by
/// several blocks (one per formulation); every one of them is read.
pub struct KindRows {
    pub kind: ElementKind,
    pub total: usize,
    pub rows: Rows,
    pub members: Vec<(usize, usize)>,
}

/// The elements of one kind over every block holding it, in ascending global
/// order: (global indices, (block, element in the block)).
pub fn kind_members(
    kind: ElementKind,
    blocks: &[(ElementKind, &[u32])],
) -> (Vec<u64>, Vec<(usize, usize)>) {
    let mut all: Vec<(u32, usize, usize)> = blocks
        .iter()
        .enumerate()
        .filter(|(_, (k, _))| *k == kind)
        .flat_map(|(b, (_, global))| global.iter().enumerate().map(move |(e, &ge)| (ge, b, e)))
        .collect();
    all.sort_unstable();
    all.into_iter()
        .map(|(ge, b, e)| (ge as u64, (b, e)))
        .unzip()
}

/// Element kinds present in the model (replicated), with this rank's rows.
pub fn kind_rows(
    ctx: &Context,
    blocks: &[Box<dyn crate::element::blocks::Block>],
) -> Vec<KindRows> {
    ElementKind::ALL
        .iter()
        .enumerate()
        .filter(|(ki, _)| !ctx.g.element_ids[*ki].is_empty())
        .map(|(ki, &kind)| {
            let held: Vec<(ElementKind, &[u32])> = blocks
                .iter()
                .map(|b| (b.kind(), &b.local().global[..]))
                .collect();
            let (global, members) = kind_members(kind, &held);
            KindRows {
                kind,
                total: ctx.g.element_ids[ki].len(),
                rows: Rows::from_sorted(global.into_iter()),
                members,
            }
        })
        .collect()
}

fn err(path: &std::path::Path, e: impl std::fmt::Display) -> String {
    format!("{}: {e}", path.display())
}

/// Opens `path` for writing with the access property list `fapl` as it is.
/// (The `hdf5` crate's builder reads every property of a list and sets it
/// again on a new one, duplicating the MPI communicator, a collective, at
/// each of the reopenings after a state.)
fn open_rw(path: &std::path::Path, fapl: &hdf5::plist::FileAccess) -> Result<File, String> {
    let name = path
        .to_str()
        .and_then(|p| std::ffi::CString::new(p).ok())
        .ok_or_else(|| err(path, "a path that is not UTF-8 text"))?;
    let id =
        unsafe { hdf5_sys::h5f::H5Fopen(name.as_ptr(), hdf5_sys::h5f::H5F_ACC_RDWR, fapl.id()) };
    if id < 0 {
        return Err(err(path, "cannot reopen the run file"));
    }
    // SAFETY: `id` is a new file id; the handle takes its reference.
    unsafe { hdf5::from_id::<File>(id) }.map_err(|e| err(path, e))
}

fn attr_str(loc: &hdf5::Location, name: &str, value: &str) -> Result<(), String> {
    let v: VarLenUnicode = value.parse().unwrap_or_default();
    loc.new_attr::<VarLenUnicode>()
        .create(name)
        .and_then(|a| a.write_scalar(&v))
        .map_err(|e| format!("HDF5: attribute {name}: {e}"))
}

fn attr_num<T: H5Type>(loc: &hdf5::Location, name: &str, value: T) -> Result<(), String> {
    loc.new_attr::<T>()
        .create(name)
        .and_then(|a| a.write_scalar(&value))
        .map_err(|e| format!("HDF5: attribute {name}: {e}"))
}

/// The open run file and what each rank writes into it.
pub struct RunFile {
    /// `/th/rows`, open from its first append until the file is next closed
    /// (declared before `file`: dropped first).
    th_ds: Option<Dataset>,
    file: Option<File>,
    /// How the file is (re)opened: MPI-IO on the world communicator, or
    /// as a plain file on a single rank.
    access: H5Access,
    path: std::path::PathBuf,
    xfer: Xfer,
    /// Rank 0's transfers of replicated rows.
    solo: Xfer,
    /// How fixed-size datasets are created.
    dcpl: h5::FixedDcpl,
    rank: u32,
    /// Owned nodes (global indices, ascending) and their local indices.
    node_rows: Rows,
    node_local: Vec<usize>,
    n_nodes: usize,
    kinds: Vec<KindRows>,
    th: ThLayout,
    /// The record type of `/th/rows`.
    th_type: h5::TypeId,
    /// Rows already in `/th/rows`.
    pub th_rows: usize,
}

impl RunFile {
    /// Creates `path` (collective) and writes the attributes, `/mesh` and
    /// the empty `/th` datasets. Not yet complete on disk: the caller
    /// writes the initial state at once (its checkpoint covers the header)
    /// or calls `checkpoint`.
    pub fn create(
        ctx: &Context,
        path: &std::path::Path,
        blocks: &[Box<dyn crate::element::blocks::Block>],
        th: ThLayout,
    ) -> Result<RunFile, String> {
        // A file of an earlier run is removed, not truncated: ext4 flushes a
        // file truncated to zero when it is next closed (`auto_da_alloc`).
        if ctx.world.rank() == 0 && path.is_file() {
            std::fs::remove_file(path).map_err(|e| err(path, format!("cannot replace: {e}")))?;
        }
        ctx.world.barrier();
        let access = ctx.world.hdf5_access()?;
        let file = File::with_options()
            .set_access_plist(&access.fapl)
            .map_err(|e| err(path, e))?
            .create(path)
            .map_err(|e| err(path, format!("cannot create the HDF5 file: {e}")))?;
        let mut rf = RunFile::new(ctx, file, access, path, blocks, th)?;
        rf.write_header(ctx, blocks)?;
        Ok(rf)
    }

    /// Reopens the file of the run being restarted: keeps its first
    /// `n_states` states and `th_rows` history rows (what existed when the
    /// restart file was written) and drops what came after.
    pub fn reopen(
        ctx: &Context,
        path: &std::path::Path,
        blocks: &[Box<dyn crate::element::blocks::Block>],
        th: ThLayout,
        n_states: usize,
        th_rows: usize,
    ) -> Result<RunFile, String> {
        let access = ctx.world.hdf5_access()?;
        let file = open_rw(path, &access.fapl)?;
        let fmt = h5::attr(&file, "format");
        if fmt != FORMAT {
            return Err(err(
                path,
                format!("format '{fmt}': expected a run file of format '{FORMAT}' (written by an older crashsim: run the deck from its start)"),
            ));
        }
        let n = file
            .dataset("mesh/node_ids")
            .map(|d| d.shape())
            .map_err(|e| err(path, format!("not a crashsim run file: {e}")))?;
        if n != [ctx.g.node_ids.len()] {
            return Err(err(
                path,
                format!(
                    "holds {} nodes, the deck {}: expected the run file of this deck",
                    n.first().copied().unwrap_or(0),
                    ctx.g.node_ids.len()
                ),
            ));
        }
        let mut rf = RunFile::new(ctx, file, access, path, blocks, th)?;
        {
            let states = rf.f().group("states").map_err(|e| err(path, e))?;
            let mut names = states.member_names().map_err(|e| err(path, e))?;
            names.sort();
            for name in names {
                if name.parse::<usize>().map_or(true, |i| i >= n_states) {
                    states.unlink(&name).map_err(|e| err(path, e))?;
                }
            }
        }
        rf.truncate_th(th_rows)?;
        rf.th_rows = th_rows;
        rf.checkpoint()?;
        Ok(rf)
    }

    fn new(
        ctx: &Context,
        file: File,
        access: H5Access,
        path: &std::path::Path,
        blocks: &[Box<dyn crate::element::blocks::Block>],
        th: ThLayout,
    ) -> Result<RunFile, String> {
        let sd = ctx.sd;
        let node_local: Vec<usize> = (0..sd.node_global.len())
            .filter(|&l| sd.owns(l as u32))
            .collect();
        let node_rows = Rows::from_sorted(node_local.iter().map(|&l| sd.node_global[l] as u64));
        Ok(RunFile {
            th_ds: None,
            file: Some(file),
            xfer: Xfer::collective(access.mpio)?,
            solo: Xfer::independent(access.mpio)?,
            access,
            path: path.to_path_buf(),
            dcpl: h5::FixedDcpl::new()?,
            rank: ctx.world.rank(),
            node_rows,
            node_local,
            n_nodes: ctx.g.node_ids.len(),
            kinds: kind_rows(ctx, blocks),
            th_type: h5::record_type(&th.members())?,
            th,
            th_rows: 0,
        })
    }

    fn f(&self) -> &File {
        self.file.as_ref().expect("the run file is open")
    }

    /// Puts everything written so far in the file on disk's hands, complete
    /// and readable (collective). A process killed afterwards leaves a file
    /// that reads up to this point (the operating system has the data; only
    /// a machine crash could lose it).
    ///
    /// A file one rank opened alone is flushed (`H5Fflush`: the metadata
    /// cache is written out, the file stays open). Through MPI-IO a flush
    /// ends with `MPI_File_sync`, an fsync on every rank: milliseconds each,
    /// and stalls of tenths of a second while other processes write to the
    /// same disk, with every rank waiting. A file being closed is not
    /// synced, so there the file is closed and opened again instead.
    pub fn checkpoint(&mut self) -> Result<(), String> {
        if !self.access.mpio {
            return self
                .f()
                .flush()
                .map_err(|e| err(&self.path, format!("cannot flush the run file: {e}")));
        }
        self.th_ds = None;
        if let Some(f) = self.file.take() {
            f.close().map_err(|e| err(&self.path, e))?;
        }
        self.file = Some(open_rw(&self.path, &self.access.fapl)?);
        Ok(())
    }

    /// Owned-node values, one row of `W` per owned node in global order.
    fn node_values<const W: usize>(&self, f: impl Fn(usize) -> [f64; W]) -> Vec<f64> {
        let mut out = Vec::with_capacity(self.node_local.len() * W);
        for &l in &self.node_local {
            out.extend_from_slice(&f(l));
        }
        out
    }

    fn write_node_array<const W: usize>(
        &self,
        g: &Group,
        name: &str,
        f: impl Fn(usize) -> [f64; W],
    ) -> Result<(), String> {
        let shape: Vec<usize> = if W == 1 {
            vec![self.n_nodes]
        } else {
            vec![self.n_nodes, W]
        };
        let ds = self.dcpl.create::<f64>(g, name, &shape)?;
        h5::write_rows(&ds, &self.node_rows, &self.node_values(f), &self.xfer)
    }

    /// Replicated values: every rank creates the dataset, rank 0 writes it.
    fn write_table<T: H5Type>(&self, g: &Group, name: &str, values: &[T]) -> Result<(), String> {
        let ds = self.dcpl.create::<T>(g, name, &[values.len()])?;
        if self.rank == 0 && !values.is_empty() {
            h5::write_rows(
                &ds,
                &Rows::range(0, values.len() as u64),
                values,
                &self.solo,
            )?;
        }
        Ok(())
    }

    fn write_header(
        &mut self,
        ctx: &Context,
        blocks: &[Box<dyn crate::element::blocks::Block>],
    ) -> Result<(), String> {
        let g = ctx.g;
        let root: &hdf5::Location = self.f();
        attr_str(root, "format", FORMAT)?;
        attr_str(root, "deck", &g.name)?;
        attr_str(root, "title", &g.title)?;
        attr_str(root, "units_mass", &g.units.mass)?;
        attr_str(root, "units_length", &g.units.length)?;
        attr_str(root, "units_time", &g.units.time)?;
        attr_str(root, "crashsim_version", env!("CARGO_PKG_VERSION"))?;
        if !g.skipped_keywords.is_empty() {
            attr_str(root, "skipped_keywords", &g.skipped_keywords.join("\n"))?;
        }
        attr_num(root, "ranks", ctx.world.size())?;
        let mesh = self.f().create_group("mesh").map_err(|e| e.to_string())?;
        let sd = ctx.sd;
        let ids: Vec<u64> = self
            .node_local
            .iter()
            .map(|&l| g.node_ids[sd.node_global[l] as usize])
            .collect();
        let ds = self
            .dcpl
            .create::<u64>(&mesh, "node_ids", &[self.n_nodes])?;
        h5::write_rows(&ds, &self.node_rows, &ids, &self.xfer)?;
        self.write_node_array(&mesh, "coordinates", |l| sd.x[l])?;
        for kr in &self.kinds {
            let ki = kr.kind.index();
            let nn = kr.kind.nodes();
            let grp = mesh
                .create_group(kr.kind.file_name())
                .map_err(|e| e.to_string())?;
            let (mut conn, mut eids, mut pids) = (Vec::new(), Vec::new(), Vec::new());
            for &(b, e) in &kr.members {
                let le = blocks[b].local();
                for &l in &le.nodes[nn * e..nn * (e + 1)] {
                    conn.push(if l == NO_NODE {
                        -1i64
                    } else {
                        sd.node_global[l as usize] as i64
                    });
                }
                eids.push(g.element_ids[ki][le.global[e] as usize]);
                pids.push(g.parts[le.part[e] as usize].id);
            }
            let ds = self
                .dcpl
                .create::<i64>(&grp, "connectivity", &[kr.total, nn])?;
            h5::write_rows(&ds, &kr.rows, &conn, &self.xfer)?;
            let ds = self.dcpl.create::<u64>(&grp, "ids", &[kr.total])?;
            h5::write_rows(&ds, &kr.rows, &eids, &self.xfer)?;
            let ds = self.dcpl.create::<u64>(&grp, "part_ids", &[kr.total])?;
            h5::write_rows(&ds, &kr.rows, &pids, &self.xfer)?;
        }
        // Tables (replicated: rank 0 writes).
        let parts = mesh.create_group("parts").map_err(|e| e.to_string())?;
        let pid: Vec<u64> = g.parts.iter().map(|p| p.id).collect();
        let ptitle: Vec<Text> = g.parts.iter().map(|p| h5::text(&p.title)).collect();
        let pmat: Vec<u64> = g
            .parts
            .iter()
            .map(|p| p.mat.map(|m| g.materials[m as usize].id).unwrap_or(0))
            .collect();
        let pprop: Vec<u64> = g
            .parts
            .iter()
            .map(|p| {
                p.prop
                    .map(|q| g.properties[q as usize].card.id)
                    .unwrap_or(0)
            })
            .collect();
        self.write_table(&parts, "id", &pid)?;
        self.write_table(&parts, "title", &ptitle)?;
        self.write_table(&parts, "material_id", &pmat)?;
        self.write_table(&parts, "property_id", &pprop)?;
        let mats = mesh.create_group("materials").map_err(|e| e.to_string())?;
        let mid: Vec<u64> = g.materials.iter().map(|m| m.id).collect();
        let mtitle: Vec<Text> = g.materials.iter().map(|m| h5::text(&m.title)).collect();
        let mlaw: Vec<Text> = g
            .materials
            .iter()
            .map(|m| {
                h5::text(match m.law {
                    MaterialLaw::Elastic => "LAW1 elastic",
                    MaterialLaw::JohnsonCook(_) => "LAW2 Johnson-Cook",
                    MaterialLaw::Tabulated(_) => "LAW36 tabulated plasticity",
                    MaterialLaw::CowperSymonds(_) => "LAW44 Cowper-Symonds",
                    MaterialLaw::DruckerPrager(_) => "LAW21 Drucker-Prager",
                    MaterialLaw::BrittlePlastic(_) => "LAW27 brittle plastic",
                    MaterialLaw::ViscoHyperelastic(_) => "LAW62 visco-hyperelastic",
                    MaterialLaw::Composite3d(_) => "LAW12 orthotropic composite (Tsai-Wu)",
                    MaterialLaw::FoamTab(_) => "LAW70 tabulated visco-elastic foam",
                })
            })
            .collect();
        let mrho: Vec<f64> = g.materials.iter().map(|m| m.rho).collect();
        self.write_table(&mats, "id", &mid)?;
        self.write_table(&mats, "title", &mtitle)?;
        self.write_table(&mats, "law", &mlaw)?;
        self.write_table(&mats, "density", &mrho)?;
        let ifs = mesh.create_group("interfaces").map_err(|e| e.to_string())?;
        let iid: Vec<u64> = ctx.interfaces.iter().map(|i| i.id).collect();
        let ityp: Vec<u32> = ctx.interfaces.iter().map(|i| i.type_number).collect();
        let ititle: Vec<Text> = ctx.interfaces.iter().map(|i| h5::text(&i.title)).collect();
        self.write_table(&ifs, "id", &iid)?;
        self.write_table(&ifs, "type", &ityp)?;
        self.write_table(&ifs, "title", &ititle)?;
        let walls = mesh
            .create_group("rigid_walls")
            .map_err(|e| e.to_string())?;
        let wid: Vec<u64> = g.rigid_walls.iter().map(|w| w.card.id).collect();
        let wtitle: Vec<Text> = g
            .rigid_walls
            .iter()
            .map(|w| h5::text(&w.card.title))
            .collect();
        self.write_table(&walls, "id", &wid)?;
        self.write_table(&walls, "title", &wtitle)?;
        self.f().create_group("states").map_err(|e| e.to_string())?;
        self.create_th(ctx)?;
        Ok(())
    }

    /// Writes `/states/NNNN` (collective); `checkpoint` or the close makes
    /// it complete on disk. Every handle into the file is closed when this
    /// returns.
    pub fn write_state(
        &mut self,
        ctx: &Context,
        index: usize,
        s: &LoopState,
        contact_force: &[[f64; 3]],
    ) -> Result<(), String> {
        let sd = ctx.sd;
        let grp = self
            .f()
            .create_group(&format!("states/{index:04}"))
            .map_err(|e| format!("HDF5: state {index}: {e}"))?;
        attr_num(&grp, "time", *s.t)?;
        attr_num(&grp, "cycle", *s.cycle)?;
        let x = &*s.x;
        let v = &*s.v;
        self.write_node_array(&grp, "coordinates", |l| x[l])?;
        self.write_node_array(&grp, "displacement", |l| {
            [0, 1, 2].map(|k| x[l][k] - sd.x[l][k])
        })?;
        self.write_node_array(&grp, "velocity", |l| v[l])?;
        self.write_node_array(&grp, "contact_force", |l| contact_force[l])?;
        for kr in &self.kinds {
            let sub = grp
                .create_group(kr.kind.file_name())
                .map_err(|e| e.to_string())?;
            let mut per_block: Vec<Option<Vec<ElemOut>>> = vec![None; s.blocks.len()];
            let outs: Vec<ElemOut> = kr
                .members
                .iter()
                .map(|&(b, e)| per_block[b].get_or_insert_with(|| s.blocks[b].outputs())[e])
                .collect();
            let col = |f: fn(&ElemOut) -> f64| -> Vec<f64> { outs.iter().map(f).collect() };
            let write = |name: &str, vals: Vec<f64>| -> Result<(), String> {
                let ds = self.dcpl.create::<f64>(&sub, name, &[kr.total])?;
                h5::write_rows(&ds, &kr.rows, &vals, &self.xfer)
            };
            write("von_mises", col(|o| o.von_mises))?;
            write("plastic_strain", col(|o| o.eps_p))?;
            if matches!(kr.kind, ElementKind::Shell4 | ElementKind::Shell3) {
                write("thickness", col(|o| o.thick))?;
            }
            write("internal_energy", col(|o| o.eint))?;
            let del: Vec<u8> = outs.iter().map(|o| o.deleted as u8).collect();
            let ds = self.dcpl.create::<u8>(&sub, "deleted", &[kr.total])?;
            h5::write_rows(&ds, &kr.rows, &del, &self.xfer)?;
        }
        Ok(())
    }

    fn create_th(&self, ctx: &Context) -> Result<(), String> {
        use super::history::GLOBAL_COLUMNS;
        let th = self.f().create_group("th").map_err(|e| e.to_string())?;
        // 256 rows per chunk: a few kilobytes for small models, and few
        // chunks (each one a B-tree entry) for long runs.
        let ds = h5::create_record_table(&th, "rows", &self.th_type, 256)?;
        attr_str(&ds, "global", &GLOBAL_COLUMNS.join(","))?;
        let g = ctx.g;
        let ids: [Vec<u64>; 4] = [
            g.parts.iter().map(|p| p.id).collect(),
            ctx.interfaces.iter().map(|i| i.id).collect(),
            g.rigid_walls.iter().map(|w| w.card.id).collect(),
            g.th_nodes.iter().map(|&n| g.node_ids[n as usize]).collect(),
        ];
        for ((name, _, cols), ids) in self.th.tables().into_iter().zip(ids) {
            attr_str(&ds, name, &cols.join(","))?;
            let grp = th.create_group(name).map_err(|e| e.to_string())?;
            self.write_table(&grp, "id", &ids)?;
        }
        Ok(())
    }

    /// `/th/rows` (a new handle on it), opened once per opening of the file.
    fn th_table(&mut self) -> Result<Dataset, String> {
        if self.th_ds.is_none() {
            let ds = self
                .f()
                .dataset("th/rows")
                .map_err(|e| err(&self.path, format!("th/rows: {e}")))?;
            self.th_ds = Some(ds);
        }
        Ok(self.th_ds.clone().expect("opened above"))
    }

    fn truncate_th(&mut self, rows: usize) -> Result<(), String> {
        self.th_table()?
            .resize([rows])
            .map_err(|e| err(&self.path, e))
    }

    /// Appends time-history rows (replicated on every rank): every rank
    /// extends `/th/rows` (collective), rank 0 alone writes the records.
    pub fn append_th(&mut self, rows: &[ThRow]) -> Result<(), String> {
        let n_new = rows.len();
        // Every rank learns the count the same way: rows are replicated.
        if n_new == 0 {
            return Ok(());
        }
        let first = self.th_rows;
        let ds = self.th_table()?;
        ds.resize([first + n_new]).map_err(|e| err(&self.path, e))?;
        if self.rank == 0 {
            // A record is the time, the cycle, then the other values in the
            // order of the members (`ThLayout::members`).
            let mut bytes = Vec::with_capacity(n_new * self.th_type.size());
            for r in rows {
                bytes.extend_from_slice(&r.values[0].to_ne_bytes());
                bytes.extend_from_slice(&r.cycle.to_ne_bytes());
                for v in &r.values[1..] {
                    bytes.extend_from_slice(&v.to_ne_bytes());
                }
            }
            let sel = Rows::range(first as u64, n_new as u64);
            h5::write_records(&ds, &sel, &bytes, &self.th_type, &self.solo)?;
        }
        self.th_rows = first + n_new;
        Ok(())
    }
}

/// What the caller knows of an interface, for the /mesh and /th tables.
impl InterfaceInfo {
    pub fn new(id: u64, type_number: u32, title: &str) -> InterfaceInfo {
        InterfaceInfo {
            id,
            type_number,
            title: title.to_string(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_block_of_a_kind_is_read_in_global_order() {
        // Two shell blocks (two formulations) interleaved in global order, a brick block between.
        let a: Vec<u32> = vec![0, 3, 4];
        let b: Vec<u32> = vec![7];
        let c: Vec<u32> = vec![1, 2, 6];
        let blocks = [
            (ElementKind::Shell4, &a[..]),
            (ElementKind::Brick8, &b[..]),
            (ElementKind::Shell4, &c[..]),
        ];
        let (global, members) = kind_members(ElementKind::Shell4, &blocks);
        assert_eq!(global, vec![0, 1, 2, 3, 4, 6]);
        assert_eq!(
            members,
            vec![(0, 0), (2, 0), (2, 1), (0, 1), (0, 2), (2, 2)]
        );
        let (global, members) = kind_members(ElementKind::Brick8, &blocks);
        assert_eq!((global, members), (vec![7], vec![(1, 0)]));
        assert_eq!(kind_members(ElementKind::Tetra4, &blocks), (vec![], vec![]));
    }
}
