//! `crashsim plot RUN.h5 --what mesh[:plastic_strain|von_mises] [--state N]
//! [--view iso|x|y|z|-x|-y|-z|X,Y,Z]`: the deformed mesh of one state of
//! the run file (default the last), its shells and the outer faces of its
//! bricks and tetrahedra, coloured by an element value on a rainbow scale
//! from the smallest to the largest value of the elements drawn, seen from
//! a direction in orthographic projection. Deleted elements are left out.
//! Rendered by `raster` (z-buffer), text by plotters: no ParaView or X.

use super::h5::attr;
use super::raster::{rainbow, shaded, Canvas, ScreenPoint};
use crate::vec3::{cross, dot, norm, sub};
use hdf5::{File, Group};
use plotters::prelude::*;
use std::collections::HashMap;
use std::path::Path;

/// The element value the mesh is coloured by.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Field {
    PlasticStrain,
    VonMises,
}

impl Field {
    /// The dataset name in a state's element groups.
    pub fn dataset(self) -> &'static str {
        match self {
            Field::PlasticStrain => "plastic_strain",
            Field::VonMises => "von_mises",
        }
    }
    fn label(self, stress_unit: &str) -> String {
        match self {
            Field::PlasticStrain => "plastic strain".into(),
            Field::VonMises => format!("von Mises stress [{stress_unit}]"),
        }
    }
}

/// Where the mesh is seen from: a direction towards the viewer.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct View(pub [f64; 3]);

impl Default for View {
    /// The isometric view, from (1, 1, 1).
    fn default() -> View {
        View([1.0, 1.0, 1.0])
    }
}

impl std::str::FromStr for View {
    type Err = String;
    fn from_str(s: &str) -> Result<View, String> {
        let d = match s.trim() {
            "iso" => [1.0, 1.0, 1.0],
            "x" => [1.0, 0.0, 0.0],
            "-x" => [-1.0, 0.0, 0.0],
            "y" => [0.0, 1.0, 0.0],
            "-y" => [0.0, -1.0, 0.0],
            "z" => [0.0, 0.0, 1.0],
            "-z" => [0.0, 0.0, -1.0],
            t => {
                let v: Vec<f64> = t.split(',').filter_map(|c| c.trim().parse().ok()).collect();
                match v[..] {
                    [a, b, c] if norm([a, b, c]) > 0.0 && norm([a, b, c]).is_finite() => [a, b, c],
                    _ => return Err(format!(
                        "'{s}': expected iso, x, y, z, -x, -y, -z or a direction X,Y,Z towards the viewer"
                    )),
                }
            }
        };
        Ok(View(d))
    }
}

/// What was drawn: the state, the scale and where the colour bar is.
#[derive(Clone, Debug)]
pub struct MeshView {
    pub state: String,
    pub time: f64,
    pub cycle: u64,
    pub field: Field,
    /// The scale's ends: the smallest and largest value of the elements drawn.
    pub lo: f64,
    pub hi: f64,
    pub faces: usize,
    /// Pixels the mesh covers.
    pub mesh_pixels: usize,
    /// The colour bar: x0, y0 (top, = `hi`), x1, y1 (bottom, = `lo`), in pixels.
    pub bar: [u32; 4],
    pub size: (u32, u32),
}

/// One polygon to draw: node indices and the element's value.
struct Face {
    nodes: Vec<usize>,
    value: f64,
}

const SIZE: (u32, u32) = (1200, 800);
const MESH_BOX: [f64; 4] = [20.0, 70.0, 1000.0, 780.0];
const BAR: [u32; 4] = [1030, 110, 1060, 710];
const BACKGROUND: [u8; 3] = [255, 255, 255];

/// Draws state `state` (default the last) of `input` into `out`.
pub fn render(
    input: &Path,
    out: &Path,
    field: Field,
    state: Option<usize>,
    view: View,
) -> Result<MeshView, String> {
    let (f, _) = super::info::open(input)?;
    let e = |m: String| format!("{}: {m}", input.display());
    let (name, g) = pick_state(&f, state).map_err(e)?;
    let x = read_f64(&g, "coordinates").map_err(e)?;
    let faces = read_faces(&f, &g, field).map_err(e)?;
    if faces.is_empty() {
        return Err(e(format!(
            "state {name}: no shell, brick or tetrahedron left to draw"
        )));
    }
    let (lo, hi) = faces
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), fc| {
            (a.min(fc.value), b.max(fc.value))
        });
    let canvas = rasterise(&x, &faces, view, lo, hi);
    let (time, cycle) = super::info::state_time_cycle(&g);
    let (um, ul, ut) = (
        attr(&f, "units_mass"),
        attr(&f, "units_length"),
        attr(&f, "units_time"),
    );
    let title = format!(
        "{}: {} at t = {} {ut} (cycle {cycle}, state {name})",
        attr(&f, "deck"),
        field.label(&format!("{um}/({ul}·{ut}²)")),
        super::text::tick(&time)
    );
    let mv = MeshView {
        state: name,
        time,
        cycle,
        field,
        lo,
        hi,
        faces: faces.len(),
        mesh_pixels: canvas.covered_count(),
        bar: BAR,
        size: SIZE,
    };
    draw(out, &canvas, &title, &mv)?;
    Ok(mv)
}

/// The state group to draw: `states/NNNN` numbered `state`, else the last.
fn pick_state(f: &File, state: Option<usize>) -> Result<(String, Group), String> {
    let states = f
        .group("states")
        .map_err(|_| "no /states: expected a run file".to_string())?;
    let mut names = states.member_names().map_err(|e| e.to_string())?;
    names.sort();
    let name = match state {
        Some(k) => names
            .iter()
            .find(|n| n.parse::<usize>().ok() == Some(k))
            .cloned()
            .ok_or_else(|| {
                format!(
                    "no state {k}: expected one of 0..{}",
                    names.len().saturating_sub(1)
                )
            })?,
        None => names.last().cloned().ok_or("no state written")?,
    };
    let g = states.group(&name).map_err(|e| e.to_string())?;
    Ok((name, g))
}

fn read_f64(g: &Group, name: &str) -> Result<Vec<f64>, String> {
    g.dataset(name)
        .and_then(|d| d.read_raw::<f64>())
        .map_err(|_| format!("no dataset {name} in {}", g.name()))
}

/// Shells and the outer faces of bricks and tetrahedra, with their element's value.
fn read_faces(f: &File, g: &Group, field: Field) -> Result<Vec<Face>, String> {
    let mut faces = Vec::new();
    let mut solid_faces: HashMap<Vec<usize>, (usize, Face)> = HashMap::new();
    for kind in ["shell4", "shell3", "brick8", "tetra4"] {
        let Ok(mesh) = f.group(&format!("mesh/{kind}")) else {
            continue;
        };
        let conn = mesh.dataset("connectivity").map_err(|e| e.to_string())?;
        let n = conn.shape().get(1).copied().unwrap_or(0);
        let conn = conn.read_raw::<i64>().map_err(|e| e.to_string())?;
        let sub = g
            .group(kind)
            .map_err(|_| format!("no {kind} group in {}", g.name()))?;
        let vals = read_f64(&sub, field.dataset())?;
        let deleted = sub
            .dataset("deleted")
            .and_then(|d| d.read_raw::<u8>())
            .unwrap_or_default();
        for (k, row) in conn.chunks(n.max(1)).enumerate() {
            if deleted.get(k).copied().unwrap_or(0) != 0 || row.iter().any(|&i| i < -1) {
                continue;
            }
            let value = vals.get(k).copied().unwrap_or(f64::NAN);
            if !value.is_finite() {
                continue;
            }
            let node = |i: usize| row.get(i).copied().filter(|&v| v >= 0).map(|v| v as usize);
            for local in element_faces(kind) {
                let mut nodes: Vec<usize> = local.iter().filter_map(|&i| node(i)).collect();
                nodes.dedup();
                if nodes.len() > 1 && nodes.first() == nodes.last() {
                    nodes.pop();
                }
                if nodes.len() < 3 {
                    continue;
                }
                if kind.starts_with("shell") {
                    faces.push(Face { nodes, value });
                } else {
                    let mut key = nodes.clone();
                    key.sort_unstable();
                    let entry = solid_faces.entry(key).or_insert((0, Face { nodes, value }));
                    entry.0 += 1;
                }
            }
        }
    }
    // A face that two solids share is inside: only those met once are drawn.
    let mut outer: Vec<(Vec<usize>, Face)> = solid_faces
        .into_iter()
        .filter(|(_, (count, _))| *count == 1)
        .map(|(k, (_, face))| (k, face))
        .collect();
    outer.sort_by(|a, b| a.0.cmp(&b.0));
    faces.extend(outer.into_iter().map(|(_, face)| face));
    Ok(faces)
}

/// The faces of an element kind as local node numbers (Radioss order:
/// bricks 1-4 one end, 5-8 the other; tetrahedra 1-4).
fn element_faces(kind: &str) -> &'static [&'static [usize]] {
    match kind {
        "shell4" => &[&[0, 1, 2, 3]],
        "shell3" => &[&[0, 1, 2]],
        "brick8" => &[
            &[0, 3, 2, 1],
            &[4, 5, 6, 7],
            &[0, 1, 5, 4],
            &[1, 2, 6, 5],
            &[2, 3, 7, 6],
            &[3, 0, 4, 7],
        ],
        _ => &[&[0, 2, 1], &[0, 1, 3], &[1, 2, 3], &[0, 3, 2]],
    }
}

/// The screen basis for a view direction: right, up, towards the viewer.
fn basis(view: View) -> [[f64; 3]; 3] {
    let w = crate::vec3::scale(view.0, 1.0 / norm(view.0));
    let up = if cross([0.0, 0.0, 1.0], w).iter().any(|c| c.abs() > 1e-6) {
        [0.0, 0.0, 1.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    let u = cross(up, w);
    let u = crate::vec3::scale(u, 1.0 / norm(u));
    [u, cross(w, u), w]
}

/// The faces drawn into a canvas the size of the picture, fitted to MESH_BOX.
fn rasterise(x: &[f64], faces: &[Face], view: View, lo: f64, hi: f64) -> Canvas {
    let [u, v, w] = basis(view);
    let p = |i: usize| [x[3 * i], x[3 * i + 1], x[3 * i + 2]];
    let used: Vec<usize> = faces
        .iter()
        .flat_map(|fc| fc.nodes.iter().copied())
        .collect();
    let (mut a, mut b) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for &i in &used {
        let q = [dot(p(i), u), dot(p(i), v)];
        for k in 0..2 {
            a[k] = a[k].min(q[k]);
            b[k] = b[k].max(q[k]);
        }
    }
    let [bx0, by0, bx1, by1] = MESH_BOX;
    let span = [(b[0] - a[0]).max(1e-300), (b[1] - a[1]).max(1e-300)];
    let s = 0.95 * ((bx1 - bx0) / span[0]).min((by1 - by0) / span[1]);
    let (cx, cy) = (0.5 * (bx0 + bx1), 0.5 * (by0 + by1));
    let (mx, my) = (0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]));
    let screen = |q: [f64; 3]| -> ScreenPoint {
        [
            cx + s * (dot(q, u) - mx),
            cy - s * (dot(q, v) - my),
            dot(q, w),
        ]
    };
    // Edges where the elements are big enough on the screen to show them.
    let mean_edge = faces
        .iter()
        .map(|fc| s * norm(sub(p(fc.nodes[1]), p(fc.nodes[0]))))
        .sum::<f64>()
        / faces.len() as f64;
    let mut c = Canvas::new(SIZE.0 as usize, SIZE.1 as usize, BACKGROUND);
    for fc in faces {
        let pts: Vec<ScreenPoint> = fc.nodes.iter().map(|&i| screen(p(i))).collect();
        let n = cross(
            sub(p(fc.nodes[2]), p(fc.nodes[0])),
            sub(p(fc.nodes[fc.nodes.len() - 1]), p(fc.nodes[1])),
        );
        let facing = if norm(n) > 0.0 {
            dot(n, w).abs() / norm(n)
        } else {
            1.0
        };
        let colour = shaded(rainbow(scale_of(fc.value, lo, hi)), 0.45 + 0.55 * facing);
        let edge = (mean_edge > 6.0).then(|| (shaded(colour, 0.55), 0.6));
        c.polygon(&pts, colour, edge);
    }
    c
}

/// Where `v` sits on the scale lo..hi, in [0, 1] (the middle when lo = hi).
pub fn scale_of(v: f64, lo: f64, hi: f64) -> f64 {
    if hi > lo {
        ((v - lo) / (hi - lo)).clamp(0.0, 1.0)
    } else {
        0.5
    }
}

/// The picture: the canvas, the title, the colour bar and its labels.
fn draw(out: &Path, c: &Canvas, title: &str, mv: &MeshView) -> Result<(), String> {
    super::text::register_font()?;
    let e = |err: &dyn std::fmt::Display| {
        format!("{}: cannot draw the mesh view: {err}", out.display())
    };
    let root = BitMapBackend::new(out, mv.size).into_drawing_area();
    root.fill(&WHITE).map_err(|x| e(&x))?;
    for (i, px) in c.rgb.iter().enumerate() {
        if c.is_covered(i) {
            let (x, y) = ((i % c.width) as i32, (i / c.width) as i32);
            root.draw_pixel((x, y), &RGBColor(px[0], px[1], px[2]))
                .map_err(|x| e(&x))?;
        }
    }
    root.draw(&Text::new(
        title.to_string(),
        (20, 20),
        ("sans-serif", 22).into_font(),
    ))
    .map_err(|x| e(&x))?;
    let [x0, y0, x1, y1] = mv.bar.map(|v| v as i32);
    for y in y0..=y1 {
        let t = 1.0 - (y - y0) as f64 / (y1 - y0) as f64;
        let [r, g, b] = rainbow(t);
        root.draw(&Rectangle::new(
            [(x0, y), (x1, y + 1)],
            RGBColor(r, g, b).filled(),
        ))
        .map_err(|x| e(&x))?;
    }
    root.draw(&Rectangle::new(
        [(x0 - 1, y0 - 1), (x1 + 1, y1 + 1)],
        BLACK.stroke_width(1),
    ))
    .map_err(|x| e(&x))?;
    for k in 0..=5 {
        let value = mv.lo + (mv.hi - mv.lo) * k as f64 / 5.0;
        let y = y1 - ((y1 - y0) as f64 * k as f64 / 5.0).round() as i32;
        let label = super::text::tick(&value);
        root.draw(&Text::new(
            label,
            (x1 + 8, y - 8),
            ("sans-serif", 16).into_font(),
        ))
        .map_err(|x| e(&x))?;
    }
    root.present().map_err(|x| e(&x))?;
    Ok(())
}
