//! `crashsim plot --what mesh`: the demo tube's deformed shells drawn from
//! the run file, coloured by plastic strain on a scale that runs from the
//! smallest to the largest value of the state drawn (issue 18).

mod common;
use common::*;
use crashsim::output::mesh_view::{render, Field, View};
use crashsim::output::raster::rainbow;
use std::path::{Path, PathBuf};

/// The demo tube (decks/demo_tube) for 1 ms on 2 ranks: the wall end has
/// started to fold and yield. Run once for the tests of this file.
fn demo_tube_run() -> PathBuf {
    static RUN: std::sync::OnceLock<PathBuf> = std::sync::OnceLock::new();
    RUN.get_or_init(run_demo_tube).clone()
}

fn run_demo_tube() -> PathBuf {
    let dir = scratch("mesh-view");
    let engine = dir.join("demo_tube_0001.rad");
    std::fs::write(
        &engine,
        "/RUN/demo_tube/1\n1.0\n/DT\n0.9 0.0\n/PRINT/-1000/55\n/ANIM/DT\n0.0 0.5\n/TFILE/4\n0.05\n",
    )
    .unwrap();
    let out = run_env(
        2,
        &[
            "run",
            deck("demo_tube").to_str().unwrap(),
            "--engine",
            engine.to_str().unwrap(),
            "--out",
            dir.to_str().unwrap(),
            "--quiet",
        ],
        &[],
    );
    ok(&out, "the demo tube for 1 ms on 2 ranks");
    // Threads per rank default to the cores over the ranks on this node
    // (2 ranks on 2 cores: 1 each), and the header says so.
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let listing = std::fs::read_to_string(dir.join("demo_tube.out")).unwrap();
    let want = format!(
        "2 rank(s), {} thread(s) per rank ({cores} core(s) / 2 rank(s) on this node",
        (cores / 2).max(1)
    );
    assert!(
        listing.contains(&want),
        "header lacks '{want}':\n{}",
        &listing[..300.min(listing.len())]
    );
    dir
}

/// The last state's shell plastic strains in the run file, read with h5py's
/// C library through the hdf5 crate: (smallest, largest).
fn plastic_strain_range(h5: &Path) -> (f64, f64, String) {
    let f = hdf5::File::open(h5).unwrap();
    let states = f.group("states").unwrap();
    let mut names = states.member_names().unwrap();
    names.sort();
    let last = names.last().unwrap().clone();
    let v = f
        .dataset(&format!("states/{last}/shell4/plastic_strain"))
        .unwrap()
        .read_raw::<f64>()
        .unwrap();
    let lo = v.iter().cloned().fold(f64::INFINITY, f64::min);
    let hi = v.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
    (lo, hi, last)
}

fn near(a: [u8; 3], b: [u8; 3]) -> bool {
    a.iter()
        .zip(b)
        .all(|(x, y)| (*x as i32 - y as i32).abs() <= 2)
}

#[test]
fn the_mesh_view_draws_the_tube_on_the_run_files_scale() {
    let dir = demo_tube_run();
    let h5 = dir.join("demo_tube.h5");
    let png = dir.join("mesh.png");
    let mv = render(&h5, &png, Field::PlasticStrain, None, View::default()).unwrap();
    let (lo, hi, last) = plastic_strain_range(&h5);
    assert_eq!(mv.state, last, "the last state by default");
    assert_eq!(mv.faces, 1600, "every shell drawn");
    assert_eq!(
        (mv.lo, mv.hi),
        (lo, hi),
        "the scale is the state's plastic strain range"
    );
    assert!(hi > lo && hi > 0.01, "the tube has yielded: {lo} .. {hi}");

    let img = image::open(&png).unwrap().to_rgb8();
    assert_eq!(img.dimensions(), mv.size);
    let px = |x: u32, y: u32| img.get_pixel(x, y).0;
    // Not blank: the tube's pixels differ from the white background, in many colours.
    let (w, h) = img.dimensions();
    let mut coloured = 0usize;
    let mut colours = std::collections::HashSet::new();
    for y in 60..h {
        for x in 0..mv.bar[0] - 10 {
            let p = px(x, y);
            if p != [255, 255, 255] {
                coloured += 1;
                colours.insert(p);
            }
        }
    }
    assert!(coloured > (w * h / 20) as usize, "{coloured} mesh pixels");
    assert_eq!(
        coloured, mv.mesh_pixels,
        "every mesh pixel and no other is coloured"
    );
    assert!(colours.len() > 50, "{} colours", colours.len());
    // The colour bar: red at its top (the largest value), blue at its bottom
    // (the smallest), green half-way, as the mesh's colours are computed.
    let [x0, y0, x1, y1] = mv.bar;
    let xm = (x0 + x1) / 2;
    assert!(near(px(xm, y0), rainbow(1.0)), "{:?}", px(xm, y0));
    assert!(near(px(xm, y1), rainbow(0.0)), "{:?}", px(xm, y1));
    assert!(
        near(px(xm, (y0 + y1) / 2), rainbow(0.5)),
        "{:?}",
        px(xm, (y0 + y1) / 2)
    );
    // The brightest (face-on) mesh pixels of the top and bottom colours exist:
    // the elements at both ends of the scale are drawn in them.
    let hue = |p: [u8; 3], c: [u8; 3]| {
        let m = *p.iter().max().unwrap() as f64;
        m > 0.0
            && p.iter()
                .zip(c)
                .all(|(a, b)| ((*a as f64 / m) * 255.0 - b as f64).abs() < 12.0)
    };
    assert!(
        colours.iter().any(|&p| hue(p, rainbow(0.0))),
        "no mesh pixel in the bottom colour"
    );
    assert!(
        colours.iter().any(|&p| hue(p, rainbow(1.0))),
        "no mesh pixel in the top colour"
    );
}

#[test]
fn plot_names_a_missing_state_and_a_bad_view() {
    let dir = demo_tube_run();
    let h5 = dir.join("demo_tube.h5");
    let png = dir.join("errors.png");
    let (h5s, pngs) = (h5.to_str().unwrap(), png.to_str().unwrap());
    let out = crashsim(&[
        "plot", h5s, "--what", "mesh", "--state", "99", "--out", pngs,
    ]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("no state 99"), "{err}");
    let out = crashsim(&["plot", h5s, "--what", "mesh", "--view", "up", "--out", pngs]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--view 'up'"));
    // The first state (t = 0): nothing has yielded; von Mises is drawn too.
    let out = crashsim(&[
        "plot",
        h5s,
        "--what",
        "mesh:von_mises",
        "--state",
        "0",
        "--view",
        "z",
        "--out",
        pngs,
    ]);
    ok(&out, "plot the first state");
    let said = String::from_utf8_lossy(&out.stdout);
    assert!(
        said.contains("state 0000") && said.contains("von_mises"),
        "{said}"
    );
}
