//! `crashsim info FILE.h5`: what a run file (or a restart file) holds.
//! Read serially (no MPI); bad files are input errors naming the file.

use super::h5::attr;
use hdf5::File;
use std::fmt::Write as _;
use std::path::Path;

/// Opens an HDF5 file written by crashsim, with a clear error otherwise.
/// A state group's `time` and `cycle` attributes (NaN and 0 when absent).
pub fn state_time_cycle(g: &hdf5::Group) -> (f64, u64) {
    let t = g
        .attr("time")
        .and_then(|a| a.read_scalar::<f64>())
        .unwrap_or(f64::NAN);
    let c = g
        .attr("cycle")
        .and_then(|a| a.read_scalar::<u64>())
        .unwrap_or(0);
    (t, c)
}

pub fn open(path: &Path) -> Result<(File, String), String> {
    if !path.is_file() {
        return Err(format!(
            "{}: no such file: expected a run file DIR/NAME.h5 written by crashsim run",
            path.display()
        ));
    }
    let f = File::open(path).map_err(|_| {
        format!(
            "{}: not an HDF5 file: expected a run file DIR/NAME.h5 written by crashsim run",
            path.display()
        )
    })?;
    let fmt = attr(&f, "format");
    if fmt == "crashsim-run 1" {
        return Err(format!(
            "{}: a run file of format 'crashsim-run 1', written by an older crashsim: expected format '{}' (run the deck again)",
            path.display(),
            super::runfile::FORMAT
        ));
    }
    if fmt != super::runfile::FORMAT && fmt != super::restart::FORMAT {
        return Err(format!(
            "{}: an HDF5 file without crashsim's 'format' attribute (found '{fmt}'): expected a run file DIR/NAME.h5 written by crashsim run",
            path.display()
        ));
    }
    Ok((f, fmt))
}

/// Length of a 1-D dataset (0 when absent).
fn len(f: &File, path: &str) -> usize {
    f.dataset(path)
        .map(|d| d.shape().first().copied().unwrap_or(0))
        .unwrap_or(0)
}

fn ids(f: &File, path: &str) -> Vec<u64> {
    f.dataset(path)
        .and_then(|d| d.read_raw::<u64>())
        .unwrap_or_default()
}

fn id_list(v: &[u64]) -> String {
    if v.is_empty() {
        return String::new();
    }
    let shown: Vec<String> = v.iter().take(12).map(|i| i.to_string()).collect();
    let more = if v.len() > 12 {
        format!(", … ({} in all)", v.len())
    } else {
        String::new()
    };
    format!(" (ids {}{more})", shown.join(", "))
}

/// The report for a file.
pub fn report(path: &Path) -> Result<String, String> {
    let (f, fmt) = open(path)?;
    let mut s = String::new();
    if fmt == super::restart::FORMAT {
        let _ = writeln!(s, "{}: crashsim restart file ({fmt})", path.display());
        let sec = f.group("sections").map_err(|e| e.to_string())?;
        let mut names = sec.member_names().unwrap_or_default();
        names.sort();
        let _ = writeln!(s, "sections:");
        for n in names {
            let kind = sec.group(&n).map(|g| attr(&g, "kind")).unwrap_or_default();
            let _ = writeln!(s, "  {n:<20} {kind}");
        }
        return Ok(s);
    }
    let ranks = f
        .attr("ranks")
        .and_then(|a| a.read_scalar::<u32>())
        .unwrap_or(0);
    let _ = writeln!(
        s,
        "{}: crashsim run file ({fmt}), written by crashsim {} on {ranks} rank(s)",
        path.display(),
        attr(&f, "crashsim_version")
    );
    let _ = writeln!(s, "deck:   {} — {}", attr(&f, "deck"), attr(&f, "title"));
    let (um, ul, ut) = (
        attr(&f, "units_mass"),
        attr(&f, "units_length"),
        attr(&f, "units_time"),
    );
    let _ = writeln!(s, "units:  mass {um}, length {ul}, time {ut}");
    let skipped = attr(&f, "skipped_keywords");
    for k in skipped.lines() {
        let _ = writeln!(s, "skipped (--skip-unsupported): {k}");
    }
    let mut kinds = Vec::new();
    if let Ok(mesh) = f.group("mesh") {
        let mut names = mesh.member_names().unwrap_or_default();
        names.sort();
        for k in names {
            if let Ok(d) = f.dataset(&format!("mesh/{k}/ids")) {
                kinds.push(format!("{} {k}", d.shape()[0]));
            }
        }
    }
    let _ = writeln!(
        s,
        "mesh:   {} nodes; elements: {}; {} parts, {} materials, {} interfaces, {} rigid walls",
        len(&f, "mesh/node_ids"),
        if kinds.is_empty() {
            "none".to_string()
        } else {
            kinds.join(", ")
        },
        len(&f, "mesh/parts/id"),
        len(&f, "mesh/materials/id"),
        len(&f, "mesh/interfaces/id"),
        len(&f, "mesh/rigid_walls/id"),
    );
    let mut states: Vec<(String, f64, u64)> = Vec::new();
    if let Ok(g) = f.group("states") {
        let mut names = g.member_names().unwrap_or_default();
        names.sort();
        for n in names {
            if let Ok(st) = g.group(&n) {
                let (t, c) = state_time_cycle(&st);
                states.push((n, t, c));
            }
        }
    }
    let _ = writeln!(
        s,
        "states: {} (coordinates, displacement, velocity, contact_force; per element von_mises, plastic_strain, thickness, internal_energy, deleted)",
        states.len()
    );
    for (n, t, c) in &states {
        let _ = writeln!(s, "  /states/{n}   t = {t:.6e} {ut}   cycle {c}");
    }
    let times = super::runfile::read_th(&f, "time")
        .map(|(_, v)| v)
        .unwrap_or_default();
    match (times.first(), times.last()) {
        (Some(a), Some(b)) => {
            let _ = writeln!(
                s,
                "time histories: {} samples, t = {a:.4e} … {b:.4e} {ut}",
                times.len()
            );
        }
        _ => {
            let _ = writeln!(s, "time histories: none");
        }
    }
    use super::history::{
        GLOBAL_COLUMNS, INTERFACE_COLUMNS, NODE_COLUMNS, PART_COLUMNS, WALL_COLUMNS,
    };
    let _ = writeln!(s, "  /th/rows [T] records, member by member:");
    let _ = writeln!(s, "    time, cycle");
    let _ = writeln!(
        s,
        "    global [{}]: {}",
        GLOBAL_COLUMNS.len(),
        GLOBAL_COLUMNS.join(", ")
    );
    for (name, what, cols) in [
        ("parts", "parts", &PART_COLUMNS[..]),
        ("interfaces", "interfaces", &INTERFACE_COLUMNS[..]),
        ("rigid_walls", "walls", &WALL_COLUMNS[..]),
        ("nodes", "nodes", &NODE_COLUMNS[..]),
    ] {
        let id = ids(&f, &format!("th/{name}/id"));
        if id.is_empty() {
            let _ = writeln!(s, "    {name}: none (no {what})");
            continue;
        }
        let _ = writeln!(
            s,
            "    {name} [{}, {}]: {} {what}{} — {}",
            id.len(),
            cols.len(),
            id.len(),
            id_list(&id),
            cols.join(", ")
        );
    }
    Ok(s)
}
