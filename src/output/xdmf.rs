//! `DIR/NAME.xdmf`: an XDMF 3 description of the run file that ParaView
//! (Xdmf3 reader) and VisIt open as a time series of the deforming mesh.
//!
//! A temporal collection with one grid per state. Each state's geometry is
//! its current coordinates (`/states/NNNN/coordinates`); its topology per
//! element kind comes from `/mesh/KIND/connectivity` (Quadrilateral,
//! Triangle, Hexahedron, Tetrahedron, 2-node Polyline for springs); node
//! attributes are displacement, velocity and contact force, cell attributes
//! the element values of the state plus element and part ids. With more than
//! one element kind a state is a spatial collection of one grid per kind
//! sharing the same geometry. Paths point into `NAME.h5` beside it.
//!
//! Rank 0 appends each state's grid as it is written (`XdmfFile`): the
//! closing tags are overwritten by the new grid and written again after it,
//! so the file is complete after every state and a state costs the same
//! whatever the number of states before it.

use crate::model::ElementKind;
use std::fmt::Write as _;
use std::path::Path;

/// What the description needs to know.
pub struct XdmfModel {
    pub name: String,
    /// File name of the HDF5 file, relative to the XDMF file.
    pub h5_name: String,
    pub n_nodes: usize,
    /// (kind, number of elements).
    pub kinds: Vec<(ElementKind, usize)>,
}

fn topology(k: ElementKind) -> (&'static str, usize) {
    match k {
        ElementKind::Shell4 => ("Quadrilateral", 4),
        ElementKind::Shell3 => ("Triangle", 3),
        ElementKind::Brick8 => ("Hexahedron", 8),
        ElementKind::Tetra4 => ("Tetrahedron", 4),
        ElementKind::Spring | ElementKind::Truss | ElementKind::Beam => ("Polyline", 2),
    }
}

fn item(out: &mut String, indent: &str, dims: &str, ty: &str, prec: u32, h5: &str, path: &str) {
    let _ = writeln!(
        out,
        "{indent}<DataItem Dimensions=\"{dims}\" NumberType=\"{ty}\" Precision=\"{prec}\" Format=\"HDF\">{h5}:{path}</DataItem>"
    );
}

#[allow(clippy::too_many_arguments)]
fn attribute(
    out: &mut String,
    indent: &str,
    name: &str,
    center: &str,
    dims: &str,
    ty: &str,
    prec: u32,
    h5: &str,
    path: &str,
) {
    let kind = if dims.contains(' ') {
        "Vector"
    } else {
        "Scalar"
    };
    let _ = writeln!(
        out,
        "{indent}<Attribute Name=\"{name}\" AttributeType=\"{kind}\" Center=\"{center}\">"
    );
    item(out, &format!("{indent}  "), dims, ty, prec, h5, path);
    let _ = writeln!(out, "{indent}</Attribute>");
}

/// The closing tags of the temporal collection and of the document.
const TAIL: &str = "    </Grid>\n  </Domain>\n</Xdmf>\n";

/// The document up to the temporal collection's first grid.
fn head(m: &XdmfModel) -> String {
    let mut s = String::new();
    s.push_str("<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n  <Domain>\n");
    let _ = writeln!(
        s,
        "    <Grid Name=\"{}\" GridType=\"Collection\" CollectionType=\"Temporal\">",
        xml(&m.name)
    );
    s
}

/// The grid of state `idx` at `time`.
fn grid(m: &XdmfModel, idx: usize, time: f64) -> String {
    let h5 = &m.h5_name;
    let n = m.n_nodes;
    let mut s = String::new();
    let spatial = m.kinds.len() > 1;
    {
        let st = format!("/states/{idx:04}");
        let mut ind = "      ".to_string();
        if spatial {
            let _ = writeln!(
                s,
                "{ind}<Grid Name=\"state {idx:04}\" GridType=\"Collection\" CollectionType=\"Spatial\">"
            );
            let _ = writeln!(s, "{ind}  <Time Value=\"{time:.17e}\"/>");
            ind.push_str("  ");
        }
        for &(kind, ne) in &m.kinds {
            let kn = kind.file_name();
            let (topo, nn) = topology(kind);
            let name = if spatial {
                kn.to_string()
            } else {
                format!("state {idx:04}")
            };
            let _ = writeln!(s, "{ind}<Grid Name=\"{name}\" GridType=\"Uniform\">");
            if !spatial {
                let _ = writeln!(s, "{ind}  <Time Value=\"{time:.17e}\"/>");
            }
            let extra = if topo == "Polyline" {
                " NodesPerElement=\"2\""
            } else {
                ""
            };
            let _ = writeln!(
                s,
                "{ind}  <Topology TopologyType=\"{topo}\" NumberOfElements=\"{ne}\"{extra}>"
            );
            let stored = kind.nodes();
            if stored == nn {
                item(
                    &mut s,
                    &format!("{ind}    "),
                    &format!("{ne} {nn}"),
                    "Int",
                    8,
                    h5,
                    &format!("/mesh/{kn}/connectivity"),
                );
            } else {
                // A beam stores its orientation node third: draw the first two.
                let _ = writeln!(
                    s,
                    "{ind}    <DataItem ItemType=\"HyperSlab\" Dimensions=\"{ne} {nn}\" Type=\"HyperSlab\">"
                );
                let _ = writeln!(
                    s,
                    "{ind}      <DataItem Dimensions=\"3 2\" Format=\"XML\">0 0 1 1 {ne} {nn}</DataItem>"
                );
                item(
                    &mut s,
                    &format!("{ind}      "),
                    &format!("{ne} {stored}"),
                    "Int",
                    8,
                    h5,
                    &format!("/mesh/{kn}/connectivity"),
                );
                let _ = writeln!(s, "{ind}    </DataItem>");
            }
            let _ = writeln!(s, "{ind}  </Topology>");
            let _ = writeln!(s, "{ind}  <Geometry GeometryType=\"XYZ\">");
            item(
                &mut s,
                &format!("{ind}    "),
                &format!("{n} 3"),
                "Float",
                8,
                h5,
                &format!("{st}/coordinates"),
            );
            let _ = writeln!(s, "{ind}  </Geometry>");
            let a = format!("{ind}  ");
            for f in ["displacement", "velocity", "contact_force"] {
                attribute(
                    &mut s,
                    &a,
                    f,
                    "Node",
                    &format!("{n} 3"),
                    "Float",
                    8,
                    h5,
                    &format!("{st}/{f}"),
                );
            }
            let mut cell = vec!["von_mises", "plastic_strain"];
            if matches!(kind, ElementKind::Shell4 | ElementKind::Shell3) {
                cell.push("thickness");
            }
            cell.push("internal_energy");
            for f in cell {
                attribute(
                    &mut s,
                    &a,
                    f,
                    "Cell",
                    &ne.to_string(),
                    "Float",
                    8,
                    h5,
                    &format!("{st}/{kn}/{f}"),
                );
            }
            attribute(
                &mut s,
                &a,
                "deleted",
                "Cell",
                &ne.to_string(),
                "UChar",
                1,
                h5,
                &format!("{st}/{kn}/deleted"),
            );
            attribute(
                &mut s,
                &a,
                "element_id",
                "Cell",
                &ne.to_string(),
                "UInt",
                8,
                h5,
                &format!("/mesh/{kn}/ids"),
            );
            attribute(
                &mut s,
                &a,
                "part_id",
                "Cell",
                &ne.to_string(),
                "UInt",
                8,
                h5,
                &format!("/mesh/{kn}/part_ids"),
            );
            let _ = writeln!(s, "{ind}</Grid>");
        }
        if spatial {
            let _ = writeln!(s, "      </Grid>");
        }
    }
    s
}

fn xml(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// The description on disk (rank 0 only), brought up to date state by
/// state. It is written in place, never truncated to zero first: ext4
/// flushes a file that was truncated and rewritten when it is closed (its
/// `auto_da_alloc` safeguard).
pub struct XdmfFile {
    path: std::path::PathBuf,
    file: Option<std::fs::File>,
    /// Where the closing tags start.
    end: u64,
    /// States in the file.
    states: usize,
}

impl XdmfFile {
    pub fn new(path: &Path) -> XdmfFile {
        XdmfFile {
            path: path.to_path_buf(),
            file: None,
            end: 0,
            states: 0,
        }
    }

    /// Makes the file describe `states`: the first call writes the whole
    /// document (a restarted run lists the states it keeps), later ones
    /// append the states that are new.
    pub fn update(&mut self, m: &XdmfModel, states: &[(usize, f64)]) -> Result<(), String> {
        use std::io::{Seek, SeekFrom, Write};
        let e =
            |e: std::io::Error| format!("{}: cannot write the XDMF file: {e}", self.path.display());
        let (text, at) = match &self.file {
            Some(_) if states.len() >= self.states => {
                let mut t = String::new();
                for &(idx, time) in &states[self.states..] {
                    t.push_str(&grid(m, idx, time));
                }
                (t, self.end)
            }
            _ => {
                let f = std::fs::OpenOptions::new()
                    .write(true)
                    .create(true)
                    .truncate(false)
                    .open(&self.path)
                    .map_err(e)?;
                self.file = Some(f);
                let mut t = head(m);
                for &(idx, time) in states {
                    t.push_str(&grid(m, idx, time));
                }
                (t, 0)
            }
        };
        let f = self.file.as_mut().expect("opened above");
        f.seek(SeekFrom::Start(at)).map_err(e)?;
        f.write_all(text.as_bytes()).map_err(e)?;
        f.write_all(TAIL.as_bytes()).map_err(e)?;
        self.end = at + text.len() as u64;
        if at == 0 {
            f.set_len(self.end + TAIL.len() as u64).map_err(e)?;
        }
        self.states = states.len();
        Ok(())
    }
}
