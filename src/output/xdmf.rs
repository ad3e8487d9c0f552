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
//! Rank 0 rewrites the whole file in place after each state (a few
//! kilobytes; see `write` for why not through a rename or a truncation).

use crate::deck::ElementKind;
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

/// The XDMF text for the states `(index, time)`.
pub fn render(m: &XdmfModel, states: &[(usize, f64)]) -> String {
    let h5 = &m.h5_name;
    let n = m.n_nodes;
    let mut s = String::new();
    s.push_str("<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n  <Domain>\n");
    let _ = writeln!(
        s,
        "    <Grid Name=\"{}\" GridType=\"Collection\" CollectionType=\"Temporal\">",
        xml(&m.name)
    );
    let spatial = m.kinds.len() > 1;
    for &(idx, time) in states {
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
            let kn = super::runfile::kind_name(kind);
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
            item(
                &mut s,
                &format!("{ind}    "),
                &format!("{ne} {nn}"),
                "Int",
                8,
                h5,
                &format!("/mesh/{kn}/connectivity"),
            );
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
    s.push_str("    </Grid>\n  </Domain>\n</Xdmf>\n");
    s
}

fn xml(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// Writes the description (rank 0 only). The file is overwritten from its
/// start and then cut to length, not truncated first: ext4 flushes a file
/// that was truncated to zero and rewritten when it is closed (its
/// `auto_da_alloc` safeguard), half a millisecond per state here.
pub fn write(path: &Path, m: &XdmfModel, states: &[(usize, f64)]) -> Result<(), String> {
    use std::io::Write;
    let text = render(m, states);
    let e = |e: std::io::Error| format!("{}: cannot write the XDMF file: {e}", path.display());
    let mut f = std::fs::OpenOptions::new()
        .write(true)
        .create(true)
        .truncate(false)
        .open(path)
        .map_err(e)?;
    f.write_all(text.as_bytes()).map_err(e)?;
    f.set_len(text.len() as u64).map_err(e)
}
