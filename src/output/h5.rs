//! Low-level parallel HDF5: which rows of a dataset a rank writes, and the
//! collective (MPI-IO) writes and reads of those rows.
//!
//! Every distributed dataset is laid out in global order along its first
//! dimension (global node index, global element index within its kind), so
//! the file does not depend on the partition. A rank writes the rows it owns.
//! Owned rows are not contiguous in global order: a rank's owned nodes come
//! in runs (METIS parts are compact and the local numbering follows the
//! global one), so a rank's file selection is the union of one hyperslab per
//! run and its memory buffer is the rows packed in that order. One
//! collective `H5Dwrite` per dataset then lets MPI-IO aggregate the pieces
//! (two-phase I/O) into large contiguous file accesses. That is correct for
//! any partition, needs no gather on rank 0 and no reordering communication,
//! and costs one hyperslab per run (a few per thousand rows for compact parts);
//! point selections would cost one coordinate per row and are not aggregated
//! by every HDF5 1.10 release.
//!
//! Replicated data (tables, time-history rows, which every rank holds) are
//! written by rank 0 alone with an independent transfer (the datasets are
//! created and extended collectively, as parallel HDF5 requires; their
//! space is allocated then, so one rank may write into it).
//!
//! The high-level `hdf5` crate creates the files, groups, datasets and
//! attributes (collective metadata operations: every rank calls them alike);
//! the raw transfer calls below only add the collective transfer property and
//! the run selections it does not offer.

use hdf5::{Dataset, Datatype, H5Type};
use hdf5_sys::h5::hsize_t;
use hdf5_sys::h5i::hid_t;
use hdf5_sys::{h5d, h5p, h5s, h5t};
use std::sync::Mutex;

/// Rows of a dataset's first dimension that this rank writes or reads:
/// ascending, as (first row, number of rows) runs.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Rows {
    runs: Vec<(u64, u64)>,
    count: usize,
}

impl Rows {
    /// Rows from ascending global indices (repeats are not allowed).
    pub fn from_sorted(idx: impl IntoIterator<Item = u64>) -> Rows {
        let mut runs: Vec<(u64, u64)> = Vec::new();
        let mut count = 0;
        for i in idx {
            count += 1;
            match runs.last_mut() {
                Some((s, n)) if *s + *n == i => *n += 1,
                Some((s, n)) => {
                    debug_assert!(i > *s + *n, "rows must be ascending");
                    runs.push((i, 1));
                }
                None => runs.push((i, 1)),
            }
        }
        Rows { runs, count }
    }
    /// Rows `first..first+n` (empty when `n` is 0).
    pub fn range(first: u64, n: u64) -> Rows {
        if n == 0 {
            return Rows::default();
        }
        Rows {
            runs: vec![(first, n)],
            count: n as usize,
        }
    }
    /// All `n` rows on rank 0, none elsewhere: replicated data.
    pub fn root(n: usize, rank: u32) -> Rows {
        if rank == 0 {
            Rows::range(0, n as u64)
        } else {
            Rows::default()
        }
    }
    pub fn len(&self) -> usize {
        self.count
    }
    pub fn is_empty(&self) -> bool {
        self.count == 0
    }
    /// Number of contiguous runs (one hyperslab each).
    pub fn n_runs(&self) -> usize {
        self.runs.len()
    }
}

/// A transfer property list (closed on drop): collective or independent
/// MPI-IO on a file opened through MPI-IO, the default transfer on a file
/// one rank opened alone (see `World::hdf5_access`).
pub struct Xfer(hid_t);

impl Xfer {
    /// Every rank takes part in each transfer (MPI-IO two-phase I/O):
    /// distributed rows.
    pub fn collective(mpio: bool) -> Result<Xfer, String> {
        Xfer::new(mpio.then_some(h5p::H5FD_mpio_xfer_t::H5FD_MPIO_COLLECTIVE))
    }
    /// Only the ranks that call transfer: replicated rows written by rank 0
    /// alone (time-history rows, tables), without the collective machinery.
    pub fn independent(mpio: bool) -> Result<Xfer, String> {
        Xfer::new(mpio.then_some(h5p::H5FD_mpio_xfer_t::H5FD_MPIO_INDEPENDENT))
    }
    fn new(mode: Option<h5p::H5FD_mpio_xfer_t>) -> Result<Xfer, String> {
        unsafe {
            let id = h5p::H5Pcreate(*hdf5_sys::h5p::H5P_CLS_DATASET_XFER);
            if id < 0 {
                return Err("HDF5: cannot create a transfer property list".into());
            }
            if let Some(mode) = mode {
                if h5p::H5Pset_dxpl_mpio(id, mode) < 0 {
                    hdf5_sys::h5p::H5Pclose(id);
                    return Err("HDF5: cannot set the MPI-IO transfer mode".into());
                }
            }
            Ok(Xfer(id))
        }
    }
}

impl Drop for Xfer {
    fn drop(&mut self) {
        unsafe {
            h5p::H5Pclose(self.0);
        }
    }
}

/// The creation property list of fixed-size datasets (contiguous, no
/// modification times: the file does not depend on when it was written),
/// made once per file instead of once per dataset as the `hdf5` builders
/// do: creating, copying and closing property lists is a good part of what
/// a dataset costs in HDF5 1.10.
pub struct FixedDcpl(hid_t);

impl FixedDcpl {
    pub fn new() -> Result<FixedDcpl, String> {
        unsafe {
            let id = h5p::H5Pcreate(*h5p::H5P_CLS_DATASET_CREATE);
            if id < 0 {
                return Err("HDF5: cannot create a dataset creation property list".into());
            }
            let pl = FixedDcpl(id);
            if h5p::H5Pset_obj_track_times(id, 0) < 0 {
                return Err("HDF5: cannot turn off modification times".into());
            }
            Ok(pl)
        }
    }

    /// Creates the fixed-size dataset `name` of `T` and `shape` in `loc`
    /// (collective, like every metadata operation in parallel HDF5).
    pub fn create<T: H5Type>(
        &self,
        loc: &hdf5::Location,
        name: &str,
        shape: &[usize],
    ) -> Result<Dataset, String> {
        let dims: Vec<hsize_t> = shape.iter().map(|&d| d as hsize_t).collect();
        let space = Space(unsafe {
            h5s::H5Screate_simple(dims.len() as i32, dims.as_ptr(), std::ptr::null())
        });
        if space.0 < 0 {
            return Err(format!("HDF5: cannot create the dataspace of {name}"));
        }
        let dtype = Datatype::from_type::<T>().map_err(|e| e.to_string())?;
        let cname = std::ffi::CString::new(name).map_err(|e| e.to_string())?;
        let id = unsafe {
            h5d::H5Dcreate2(
                loc.id(),
                cname.as_ptr(),
                dtype.id(),
                space.0,
                h5p::H5P_DEFAULT,
                self.0,
                h5p::H5P_DEFAULT,
            )
        };
        if id < 0 {
            return Err(format!("HDF5: cannot create {name}"));
        }
        // SAFETY: `id` is a new dataset id; the handle takes its reference.
        unsafe { hdf5::from_id::<Dataset>(id) }.map_err(|e| e.to_string())
    }
}

impl Drop for FixedDcpl {
    fn drop(&mut self) {
        unsafe {
            h5p::H5Pclose(self.0);
        }
    }
}

/// An owned dataspace id (closed on drop).
struct Space(hid_t);
impl Drop for Space {
    fn drop(&mut self) {
        unsafe {
            h5s::H5Sclose(self.0);
        }
    }
}

/// The file dataspace of `ds` with `rows` selected (all trailing dimensions),
/// and the number of values one row holds.
fn file_selection(ds: &Dataset, rows: &Rows) -> Result<(Space, usize), String> {
    let space = Space(unsafe { h5d::H5Dget_space(ds.id()) });
    if space.0 < 0 {
        return Err("HDF5: cannot get a dataset's dataspace".into());
    }
    let shape = ds.shape();
    if shape.is_empty() {
        return Err("HDF5: row writes need a dataset with at least one dimension".into());
    }
    let per_row: usize = shape[1..].iter().product();
    let nd = shape.len();
    unsafe {
        if rows.runs.is_empty() {
            h5s::H5Sselect_none(space.0);
        } else {
            let mut start = vec![0 as hsize_t; nd];
            let mut count: Vec<hsize_t> = shape.iter().map(|&d| d as hsize_t).collect();
            for (i, &(s, n)) in rows.runs.iter().enumerate() {
                if s + n > shape[0] as u64 {
                    return Err(format!(
                        "HDF5: rows {s}..{} beyond the dataset's {} rows",
                        s + n,
                        shape[0]
                    ));
                }
                start[0] = s;
                count[0] = n;
                let op = if i == 0 {
                    h5s::H5S_seloper_t::H5S_SELECT_SET
                } else {
                    h5s::H5S_seloper_t::H5S_SELECT_OR
                };
                if h5s::H5Sselect_hyperslab(
                    space.0,
                    op,
                    start.as_ptr(),
                    std::ptr::null(),
                    count.as_ptr(),
                    std::ptr::null(),
                ) < 0
                {
                    return Err("HDF5: cannot select the rows".into());
                }
            }
        }
    }
    Ok((space, per_row))
}

/// A 1-D memory dataspace of `n` values (all selected, or none when `n` is 0).
fn memory_space(n: usize) -> Result<Space, String> {
    let dims = [n as hsize_t];
    let space = Space(unsafe { h5s::H5Screate_simple(1, dims.as_ptr(), std::ptr::null()) });
    if space.0 < 0 {
        return Err("HDF5: cannot create a memory dataspace".into());
    }
    if n == 0 {
        unsafe {
            h5s::H5Sselect_none(space.0);
        }
    }
    Ok(space)
}

/// Writes this rank's `rows` of `ds` collectively (every rank calls it, with
/// its own rows, possibly none). `data` holds the rows packed in `rows`
/// order, all trailing dimensions of each row.
pub fn write_rows<T: H5Type>(
    ds: &Dataset,
    rows: &Rows,
    data: &[T],
    xfer: &Xfer,
) -> Result<(), String> {
    let (fspace, per_row) = file_selection(ds, rows)?;
    if data.len() != rows.len() * per_row {
        return Err(format!(
            "HDF5: {} values for {} rows of {per_row}",
            data.len(),
            rows.len()
        ));
    }
    let mspace = memory_space(data.len())?;
    let dtype = Datatype::from_type::<T>().map_err(|e| e.to_string())?;
    let rc = unsafe {
        h5d::H5Dwrite(
            ds.id(),
            dtype.id(),
            mspace.0,
            fspace.0,
            xfer.0,
            data.as_ptr().cast(),
        )
    };
    if rc < 0 {
        return Err(format!("HDF5: writing {} failed", ds.name()));
    }
    Ok(())
}

/// Reads this rank's `rows` of `ds` collectively, packed in `rows` order.
pub fn read_rows<T: H5Type + Default + Clone>(
    ds: &Dataset,
    rows: &Rows,
    xfer: &Xfer,
) -> Result<Vec<T>, String> {
    let (fspace, per_row) = file_selection(ds, rows)?;
    let mut data = vec![T::default(); rows.len() * per_row];
    let mspace = memory_space(data.len())?;
    let dtype = Datatype::from_type::<T>().map_err(|e| e.to_string())?;
    let rc = unsafe {
        h5d::H5Dread(
            ds.id(),
            dtype.id(),
            mspace.0,
            fspace.0,
            xfer.0,
            data.as_mut_ptr().cast(),
        )
    };
    if rc < 0 {
        return Err(format!("HDF5: reading {} failed", ds.name()));
    }
    Ok(data)
}

/// Fixed-size UTF-8 string for tables (parallel HDF5 cannot write
/// variable-length strings collectively); longer text is cut at a character
/// boundary.
pub type Text = hdf5::types::FixedUnicode<128>;

pub fn text(s: &str) -> Text {
    let mut end = s.len().min(128);
    while !s.is_char_boundary(end) {
        end -= 1;
    }
    s[..end].parse().unwrap_or_default()
}

/// A datatype id made here (closed on drop).
pub struct TypeId(hid_t);

impl TypeId {
    pub fn id(&self) -> hid_t {
        self.0
    }
    /// Size of one value of the type in bytes.
    pub fn size(&self) -> usize {
        unsafe { h5t::H5Tget_size(self.0) }
    }
}

impl Drop for TypeId {
    fn drop(&mut self) {
        unsafe {
            h5t::H5Tclose(self.0);
        }
    }
}

/// A member of a record type: one f64 or u64, or an array of f64 with the
/// given dimensions (every one at least 1).
#[derive(Clone, Debug, PartialEq)]
pub enum Member {
    F64,
    U64,
    F64Array(Vec<usize>),
}

impl Member {
    /// The native type of the member (a new id).
    fn native(&self) -> Result<TypeId, String> {
        let id = unsafe {
            match self {
                Member::F64 => h5t::H5Tcopy(*h5t::H5T_NATIVE_DOUBLE),
                Member::U64 => h5t::H5Tcopy(*h5t::H5T_NATIVE_UINT64),
                Member::F64Array(dims) => {
                    let d: Vec<hsize_t> = dims.iter().map(|&n| n as hsize_t).collect();
                    h5t::H5Tarray_create2(*h5t::H5T_NATIVE_DOUBLE, d.len() as u32, d.as_ptr())
                }
            }
        };
        if id < 0 {
            return Err(format!("HDF5: cannot make the type of a {self:?} member"));
        }
        Ok(TypeId(id))
    }
    /// Size in bytes.
    pub fn size(&self) -> usize {
        match self {
            Member::F64 | Member::U64 => 8,
            Member::F64Array(dims) => 8 * dims.iter().product::<usize>(),
        }
    }
}

/// The packed record (compound) type of `members`, in order: one row of a
/// table whose fields h5py and numpy read by name.
pub fn record_type(members: &[(&str, Member)]) -> Result<TypeId, String> {
    let size: usize = members.iter().map(|(_, m)| m.size()).sum();
    let ty = TypeId(unsafe { h5t::H5Tcreate(h5t::H5T_class_t::H5T_COMPOUND, size) });
    if ty.0 < 0 {
        return Err("HDF5: cannot create a record type".into());
    }
    let mut offset = 0;
    for (name, m) in members {
        let mt = m.native()?;
        let cname = std::ffi::CString::new(*name).map_err(|e| e.to_string())?;
        if unsafe { h5t::H5Tinsert(ty.0, cname.as_ptr(), offset, mt.0) } < 0 {
            return Err(format!(
                "HDF5: cannot add the member {name} to a record type"
            ));
        }
        offset += m.size();
    }
    Ok(ty)
}

/// Creates the extendible 1-D dataset `name` of records `ty` in `loc`, with
/// no rows yet, chunked by `chunk` rows, without fill values (every row is
/// written; in parallel a fill costs a collective write of each new chunk)
/// or modification times. Collective.
pub fn create_record_table(
    loc: &hdf5::Location,
    name: &str,
    ty: &TypeId,
    chunk: usize,
) -> Result<Dataset, String> {
    let dims = [0 as hsize_t];
    let maxdims = [h5s::H5S_UNLIMITED];
    let space = Space(unsafe { h5s::H5Screate_simple(1, dims.as_ptr(), maxdims.as_ptr()) });
    if space.0 < 0 {
        return Err(format!("HDF5: cannot create the dataspace of {name}"));
    }
    let dcpl = FixedDcpl::new()?;
    let chunk = [chunk.max(1) as hsize_t];
    unsafe {
        if h5p::H5Pset_chunk(dcpl.0, 1, chunk.as_ptr()) < 0
            || h5p::H5Pset_fill_time(dcpl.0, h5d::H5D_fill_time_t::H5D_FILL_TIME_NEVER) < 0
        {
            return Err(format!("HDF5: cannot set the layout of {name}"));
        }
    }
    let cname = std::ffi::CString::new(name).map_err(|e| e.to_string())?;
    let id = unsafe {
        h5d::H5Dcreate2(
            loc.id(),
            cname.as_ptr(),
            ty.0,
            space.0,
            h5p::H5P_DEFAULT,
            dcpl.0,
            h5p::H5P_DEFAULT,
        )
    };
    if id < 0 {
        return Err(format!("HDF5: cannot create {name}"));
    }
    // SAFETY: `id` is a new dataset id; the handle takes its reference.
    unsafe { hdf5::from_id::<Dataset>(id) }.map_err(|e| e.to_string())
}

/// Writes this rank's `rows` of the 1-D record dataset `ds`: `bytes` holds
/// the records of `ty`, packed in `rows` order.
pub fn write_records(
    ds: &Dataset,
    rows: &Rows,
    bytes: &[u8],
    ty: &TypeId,
    xfer: &Xfer,
) -> Result<(), String> {
    let (fspace, _) = file_selection(ds, rows)?;
    if bytes.len() != rows.len() * ty.size() {
        return Err(format!(
            "HDF5: {} bytes for {} records of {}",
            bytes.len(),
            rows.len(),
            ty.size()
        ));
    }
    let mspace = memory_space(rows.len())?;
    let rc = unsafe {
        h5d::H5Dwrite(
            ds.id(),
            ty.0,
            mspace.0,
            fspace.0,
            xfer.0,
            bytes.as_ptr().cast(),
        )
    };
    if rc < 0 {
        return Err(format!("HDF5: writing {} failed", ds.name()));
    }
    Ok(())
}

/// The member `name` of every record of the 1-D record dataset `ds` (serial
/// read), as its dimensions (empty for a scalar) and the values, record
/// after record. `None` when the records have no such member.
pub fn read_member<T: H5Type + Default + Clone>(
    ds: &Dataset,
    name: &str,
) -> Result<Option<(Vec<usize>, Vec<T>)>, String> {
    let cname = std::ffi::CString::new(name).map_err(|e| e.to_string())?;
    let ftype = TypeId(unsafe { h5d::H5Dget_type(ds.id()) });
    if ftype.0 < 0 {
        return Err(format!("HDF5: cannot get the type of {}", ds.name()));
    }
    let k = unsafe { h5t::H5Tget_member_index(ftype.0, cname.as_ptr()) };
    if k < 0 {
        return Ok(None);
    }
    let mtype = TypeId(unsafe { h5t::H5Tget_member_type(ftype.0, k as u32) });
    let mut dims: Vec<usize> = Vec::new();
    if unsafe { h5t::H5Tget_class(mtype.0) } == h5t::H5T_class_t::H5T_ARRAY {
        let nd = unsafe { h5t::H5Tget_array_ndims(mtype.0) };
        let mut d = vec![0 as hsize_t; nd.max(0) as usize];
        unsafe { h5t::H5Tget_array_dims2(mtype.0, d.as_mut_ptr()) };
        dims = d.into_iter().map(|n| n as usize).collect();
    }
    let per: usize = dims.iter().product();
    let base = Datatype::from_type::<T>().map_err(|e| e.to_string())?;
    let elem = if dims.is_empty() {
        TypeId(unsafe { h5t::H5Tcopy(base.id()) })
    } else {
        let d: Vec<hsize_t> = dims.iter().map(|&n| n as hsize_t).collect();
        TypeId(unsafe { h5t::H5Tarray_create2(base.id(), d.len() as u32, d.as_ptr()) })
    };
    let size = std::mem::size_of::<T>() * per;
    let mem = TypeId(unsafe { h5t::H5Tcreate(h5t::H5T_class_t::H5T_COMPOUND, size) });
    if elem.0 < 0 || mem.0 < 0 || unsafe { h5t::H5Tinsert(mem.0, cname.as_ptr(), 0, elem.0) } < 0 {
        return Err(format!("HDF5: cannot make the type to read {name}"));
    }
    let n = ds.shape().first().copied().unwrap_or(0);
    let mut out = vec![T::default(); n * per];
    if n > 0 {
        let rc = unsafe {
            h5d::H5Dread(
                ds.id(),
                mem.0,
                h5s::H5S_ALL,
                h5s::H5S_ALL,
                h5p::H5P_DEFAULT,
                out.as_mut_ptr().cast(),
            )
        };
        if rc < 0 {
            return Err(format!("HDF5: reading {name} of {} failed", ds.name()));
        }
    }
    Ok(Some((dims, out)))
}

/// The thread initialising the HDF5 library (see `warm_up`).
static WARM_UP: Mutex<Option<std::thread::JoinHandle<()>>> = Mutex::new(None);

/// Starts initialising the HDF5 library on a thread of its own. HDF5 sets
/// itself up on its first call (its identifier types, drivers and property
/// list classes: about 0.8 ms here); a run asks for it as soon as MPI is up,
/// so that it overlaps reading and partitioning the deck. Every HDF5 call
/// must come after `ready` (the library is not built thread-safe).
pub fn warm_up() {
    let mut w = WARM_UP.lock().unwrap_or_else(|e| e.into_inner());
    if w.is_none() {
        *w = std::thread::Builder::new()
            .name("hdf5-init".into())
            .spawn(|| {
                hdf5::library_version();
            })
            .ok();
    }
}

/// Waits for `warm_up`'s thread, if one was started and still runs.
pub fn ready() {
    let h = WARM_UP.lock().unwrap_or_else(|e| e.into_inner()).take();
    if let Some(h) = h {
        // A panic there leaves the library to set itself up on first use.
        let _ = h.join();
    }
}

/// A string attribute of a group or file ("" when absent).
pub fn attr(f: &hdf5::Location, name: &str) -> String {
    f.attr(name)
        .and_then(|a| a.read_scalar::<hdf5::types::VarLenUnicode>())
        .map(|s| s.to_string())
        .unwrap_or_default()
}
