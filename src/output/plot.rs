//! `crashsim plot RUN.h5 --out FILE.png --what energies|interfaces|parts|node:ID`:
//! curves from the time histories, drawn with plotters into a PNG, axes
//! labelled with the deck's units.
//!
//! Text is drawn with the font `text` registers.

use super::h5::attr;
use super::info::open;
use super::text::{register_font, tick};
use hdf5::File;
use plotters::prelude::*;
use std::path::Path;

/// What to draw.
#[derive(Clone, Debug, PartialEq)]
pub enum What {
    Energies,
    Interfaces,
    Parts,
    Node(u64),
    /// The deformed mesh coloured by an element value (`mesh_view`).
    Mesh(super::mesh_view::Field),
}

impl std::str::FromStr for What {
    type Err = String;
    fn from_str(s: &str) -> Result<What, String> {
        match s {
            "energies" => Ok(What::Energies),
            "interfaces" => Ok(What::Interfaces),
            "parts" => Ok(What::Parts),
            "mesh" | "mesh:plastic_strain" => Ok(What::Mesh(super::mesh_view::Field::PlasticStrain)),
            "mesh:von_mises" => Ok(What::Mesh(super::mesh_view::Field::VonMises)),
            _ => match s.strip_prefix("node:").map(|n| n.trim().parse::<u64>()) {
                Some(Ok(id)) => Ok(What::Node(id)),
                _ => Err(format!(
                    "'{s}': expected energies, interfaces, parts, node:ID (a /TH/NODE node id), mesh, mesh:plastic_strain or mesh:von_mises"
                )),
            },
        }
    }
}

/// One curve.
struct Curve {
    label: String,
    y: Vec<f64>,
}

/// One chart: title, y label and curves over the common time axis.
struct Panel {
    title: String,
    ylabel: String,
    curves: Vec<Curve>,
}

/// Member `name` of the run file's `/th/rows`, as `[T, dims...]` and values.
fn read(f: &File, name: &str, file: &Path) -> Result<(Vec<usize>, Vec<f64>), String> {
    super::runfile::read_th(f, name).map_err(|e| format!("{}: {name}: {e}", file.display()))
}

fn ids(f: &File, path: &str) -> Vec<u64> {
    f.dataset(path)
        .and_then(|d| d.read_raw::<u64>())
        .unwrap_or_default()
}

/// Object `c` of a [T, n, w] table as a curve over T: column `cols.start`,
/// or the magnitude of columns `cols` when there are several.
fn column(shape: &[usize], v: &[f64], c: usize, cols: std::ops::Range<usize>) -> Vec<f64> {
    let t = shape[0];
    let n = shape.get(1).copied().unwrap_or(1);
    let w = shape.get(2).copied().unwrap_or(1);
    (0..t)
        .map(|i| {
            // A file whose shapes do not fit gives NaN (not drawn), not a panic.
            let Some(row) = v.get((i * n + c) * w..(i * n + c + 1) * w) else {
                return f64::NAN;
            };
            match row.get(cols.clone()) {
                Some([a]) => *a,
                Some(xs) => xs.iter().map(|a| a * a).sum::<f64>().sqrt(),
                None => f64::NAN,
            }
        })
        .collect()
}

/// Column `name` of the `global` member of `/th/rows`.
fn global(shape: &[usize], v: &[f64], name: &str) -> Vec<f64> {
    let k = super::history::GLOBAL_COLUMNS
        .iter()
        .position(|&c| c == name)
        .expect("a global time-history column");
    let w = shape.get(1).copied().unwrap_or(0);
    (0..shape[0])
        .map(|i| {
            if k < w {
                v.get(i * w + k).copied().unwrap_or(f64::NAN)
            } else {
                f64::NAN
            }
        })
        .collect()
}

/// Draws `what` from `input` into `out` (PNG).
pub fn plot(input: &Path, out: &Path, what: &What) -> Result<(), String> {
    if let What::Mesh(field) = what {
        return super::mesh_view::render(input, out, *field, None, Default::default()).map(|_| ());
    }
    let (f, fmt) = open(input)?;
    if fmt != super::runfile::FORMAT {
        return Err(format!(
            "{}: a restart file: expected a run file DIR/NAME.h5 (the one beside NAME.xdmf)",
            input.display()
        ));
    }
    let (um, ul, ut) = (
        attr(&f, "units_mass"),
        attr(&f, "units_length"),
        attr(&f, "units_time"),
    );
    let energy = format!("energy [{um}·{ul}²/{ut}²]");
    let force = format!("force [{um}·{ul}/{ut}²]");
    let (_, time) = read(&f, "time", input)?;
    if time.is_empty() {
        return Err(format!(
            "{}: no time-history samples to plot",
            input.display()
        ));
    }
    let deck = attr(&f, "deck");
    let mut panels = Vec::new();
    match what {
        // Drawn before the time histories are read (`plot` opens with it).
        What::Mesh(_) => unreachable!("the mesh view returns at the top of plot"),
        What::Energies => {
            let (gs, gv) = read(&f, "global", input)?;
            let mut curves = Vec::new();
            for (name, label) in [
                ("internal_energy", "internal"),
                ("kinetic_energy", "kinetic"),
                ("rotational_kinetic_energy", "rotational kinetic"),
                ("external_work", "external work"),
                ("hourglass_energy", "hourglass"),
                ("plastic_work", "plastic work"),
                ("rigid_wall_work", "rigid-wall work"),
                ("contact_energy", "contact"),
            ] {
                curves.push(Curve {
                    label: label.into(),
                    y: global(&gs, &gv, name),
                });
            }
            let total: Vec<f64> = (0..time.len())
                .map(|i| curves[0].y[i] + curves[1].y[i] + curves[2].y[i])
                .collect();
            curves.insert(
                0,
                Curve {
                    label: "internal + kinetic".into(),
                    y: total,
                },
            );
            // Curves that stay zero are named in the title instead of drawn.
            let (zero, curves): (Vec<Curve>, Vec<Curve>) = curves
                .into_iter()
                .partition(|c| c.y.iter().all(|&v| v == 0.0));
            let zero: Vec<String> = zero.into_iter().map(|c| c.label).collect();
            let note = if zero.is_empty() {
                String::new()
            } else {
                format!(" (zero throughout: {})", zero.join(", "))
            };
            panels.push(Panel {
                title: format!("{deck}: energies{note}"),
                ylabel: energy,
                curves,
            });
        }
        What::Parts => {
            let pid = ids(&f, "th/parts/id");
            let (shape, v) = read(&f, "parts", input)?;
            for (k, label) in [(0, "internal energy"), (1, "kinetic energy")] {
                let curves = (0..pid.len())
                    .map(|p| Curve {
                        label: format!("part {}", pid[p]),
                        y: column(&shape, &v, p, k..k + 1),
                    })
                    .collect();
                panels.push(Panel {
                    title: format!("{deck}: {label} per part"),
                    ylabel: energy.clone(),
                    curves,
                });
            }
        }
        What::Interfaces => {
            let iid = ids(&f, "th/interfaces/id");
            let (sh, vals) = read(&f, "interfaces", input)?;
            let mut curves = Vec::new();
            for (i, id) in iid.iter().enumerate() {
                curves.push(Curve {
                    label: format!("{id} normal"),
                    y: column(&sh, &vals, i, 0..3),
                });
                curves.push(Curve {
                    label: format!("{id} tangential"),
                    y: column(&sh, &vals, i, 3..6),
                });
            }
            let none = if iid.is_empty() {
                " (no interfaces)"
            } else {
                ""
            };
            panels.push(Panel {
                title: format!("{deck}: interface force resultants{none}"),
                ylabel: force,
                curves,
            });
            panels.push(Panel {
                title: format!("{deck}: contact energy{none}"),
                ylabel: energy,
                curves: iid
                    .iter()
                    .enumerate()
                    .map(|(i, id)| Curve {
                        label: format!("interface {id}"),
                        y: column(&sh, &vals, i, 6..7),
                    })
                    .collect(),
            });
        }
        What::Node(id) => {
            let nid = ids(&f, "th/nodes/id");
            let Some(i) = nid.iter().position(|n| n == id) else {
                return Err(format!(
                    "{}: node {id} has no time history: expected one of the /TH/NODE nodes{}",
                    input.display(),
                    if nid.is_empty() {
                        " (the deck asks for none)".to_string()
                    } else {
                        format!(
                            " ({})",
                            nid.iter()
                                .map(|n| n.to_string())
                                .collect::<Vec<_>>()
                                .join(", ")
                        )
                    }
                ));
            };
            let (shape, v) = read(&f, "nodes", input)?;
            for (o, label, unit) in [
                (0, "displacement", ul.clone()),
                (3, "velocity", format!("{ul}/{ut}")),
                (6, "acceleration", format!("{ul}/{ut}²")),
            ] {
                let curves = ["x", "y", "z"]
                    .iter()
                    .enumerate()
                    .map(|(k, c)| Curve {
                        label: (*c).into(),
                        y: column(&shape, &v, i, o + k..o + k + 1),
                    })
                    .collect();
                panels.push(Panel {
                    title: format!("{deck}: node {id} {label}"),
                    ylabel: format!("{label} [{unit}]"),
                    curves,
                });
            }
        }
    }
    draw(out, &time, &format!("time [{ut}]"), &panels)
}

fn draw(out: &Path, time: &[f64], xlabel: &str, panels: &[Panel]) -> Result<(), String> {
    register_font()?;
    let e = |err: &dyn std::fmt::Display| format!("{}: cannot draw the plot: {err}", out.display());
    let height = 420 * panels.len() as u32;
    let root = BitMapBackend::new(out, (1000, height)).into_drawing_area();
    root.fill(&WHITE).map_err(|x| e(&x))?;
    let areas = root.split_evenly((panels.len(), 1));
    let (t0, t1) = (time[0], *time.last().unwrap());
    let t1 = if t1 > t0 { t1 } else { t0 + 1.0 };
    for (area, p) in areas.iter().zip(panels) {
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for c in &p.curves {
            for &y in c.y.iter().filter(|y| y.is_finite()) {
                lo = lo.min(y);
                hi = hi.max(y);
            }
        }
        if !lo.is_finite() {
            (lo, hi) = (0.0, 1.0);
        }
        if hi - lo <= 1e-300f64.max(1e-12 * hi.abs()) {
            let pad = if hi == 0.0 { 1.0 } else { 0.1 * hi.abs() };
            (lo, hi) = (lo - pad, hi + pad);
        }
        let pad = 0.05 * (hi - lo);
        let mut chart = ChartBuilder::on(area)
            .caption(&p.title, ("sans-serif", 22))
            .margin(12)
            .margin_right(30)
            .x_label_area_size(45)
            .y_label_area_size(90)
            .build_cartesian_2d(t0..t1, (lo - pad)..(hi + pad))
            .map_err(|x| e(&x))?;
        chart
            .configure_mesh()
            .x_desc(xlabel)
            .y_desc(p.ylabel.as_str())
            .x_label_formatter(&tick)
            .y_label_formatter(&tick)
            .label_style(("sans-serif", 14))
            .axis_desc_style(("sans-serif", 16))
            .draw()
            .map_err(|x| e(&x))?;
        for (i, c) in p.curves.iter().enumerate() {
            let color = Palette99::pick(i).to_rgba();
            chart
                .draw_series(LineSeries::new(
                    time.iter()
                        .copied()
                        .zip(c.y.iter().copied())
                        .filter(|(_, y)| y.is_finite()),
                    color.stroke_width(2),
                ))
                .map_err(|x| e(&x))?
                .label(c.label.as_str())
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
                });
        }
        if !p.curves.is_empty() {
            chart
                .configure_series_labels()
                .position(SeriesLabelPosition::MiddleRight)
                .label_font(("sans-serif", 14))
                .background_style(WHITE.mix(0.85))
                .border_style(BLACK)
                .draw()
                .map_err(|x| e(&x))?;
        }
    }
    root.present().map_err(|x| e(&x))?;
    Ok(())
}
