//! The HDF5 run file and its XDMF description on BOX1BL: the same file for
//! 1 and 2 ranks, energies equal to the listing, an XDMF that points at
//! what is there and renders, `info` and `plot`.

mod common;
use common::*;
use std::path::{Path, PathBuf};

/// Runs BOX1BL on `np` ranks (0: without mpirun) into a fresh directory.
fn box1bl(tag: &str, np: u32) -> PathBuf {
    let dir = scratch(tag);
    let deck = qa_deck("BOX1BL");
    let out = run_env(
        np,
        &[
            "run",
            deck.to_str().unwrap(),
            "--out",
            dir.to_str().unwrap(),
        ],
        &[],
    );
    ok(&out, &format!("run -n {np}"));
    dir
}

#[test]
fn run_file_is_the_same_on_1_2_and_4_ranks_and_its_energies_are_the_listings() {
    let one = box1bl("h5-np1", 0);
    for np in [2, 4] {
        let other = box1bl(&format!("h5-np{np}"), np);
        let report = python_check(
            "compare_runs.py",
            &[
                one.join("BOX1BL.h5").as_os_str(),
                other.join("BOX1BL.h5").as_os_str(),
                one.join("BOX1BL.out").as_os_str(),
            ],
        );
        assert!(
            report.contains("history samples equal the listing"),
            "{np} ranks: {report}"
        );
    }
}

#[test]
fn xdmf_points_at_datasets_of_the_declared_shape_and_renders_the_last_state() {
    let dir = box1bl("xdmf", 2);
    let xdmf = dir.join("BOX1BL.xdmf");
    let report = python_check("check_xdmf.py", &[xdmf.as_os_str()]);
    assert!(report.contains("11 states"), "{report}");
    let png = dir.join("last_state.png");
    python_check("render_state.py", &[xdmf.as_os_str(), png.as_os_str()]);
    let bytes = std::fs::read(&png).unwrap();
    assert!(bytes.starts_with(b"\x89PNG"), "a PNG was written");
    assert!(
        bytes.len() > 20_000,
        "the picture has content ({} bytes)",
        bytes.len()
    );
}

/// ParaView itself opens the XDMF description: Debian's pvpython
/// (python3-paraview) under xvfb-run, both installed by ci/setup, reads the 11
/// states with their point and cell arrays, goes to the last one and renders
/// the deformed box beam coloured by von Mises stress
/// (tests/py/paraview_render.py; docs/paraview_box1bl.png is one such picture).
#[test]
fn paraview_opens_the_xdmf_and_renders_the_last_state() {
    let dir = box1bl("paraview", 0);
    let xdmf = dir.join("BOX1BL.xdmf");
    let png = dir.join("paraview_last_state.png");
    let script = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/py/paraview_render.py");
    // Xvfb now and then refuses the connection ("bad X server connection",
    // seen in CI rehearsals with both cores loaded, three times in a row
    // once): that is the X server starting, not ParaView reading the file,
    // so it is tried again, waiting longer each time.
    let mut out = None;
    for attempt in 0..6u64 {
        if attempt > 0 {
            std::thread::sleep(std::time::Duration::from_secs(2 * attempt));
        }
        let o = std::process::Command::new("xvfb-run")
            .args(["-a", "pvpython"])
            .arg(&script)
            .arg(&xdmf)
            .arg(&png)
            .output()
            .expect("xvfb-run and pvpython: ci/setup installs xvfb, xauth and python3-paraview");
        let x_refused = String::from_utf8_lossy(&o.stderr).contains("bad X server connection");
        out = Some(o);
        if !x_refused {
            break;
        }
    }
    let out = out.unwrap();
    let text = String::from_utf8_lossy(&out.stdout).to_string();
    assert!(
        out.status.success(),
        "pvpython failed:\n{text}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let line = |key: &str| -> String {
        text.lines()
            .find_map(|l| l.strip_prefix(&format!("{key} ")))
            .unwrap_or_else(|| panic!("ParaView printed no '{key}':\n{text}"))
            .to_string()
    };
    assert!(line("timesteps").starts_with("11 "), "{text}");
    assert_eq!(line("points"), "155 cells 140", "{text}");
    for a in ["contact_force", "displacement", "velocity"] {
        assert!(
            line("point_arrays").split(',').any(|x| x == a),
            "{a}: {text}"
        );
    }
    for a in ["von_mises", "plastic_strain", "thickness", "deleted"] {
        assert!(
            line("cell_arrays").split(',').any(|x| x == a),
            "{a}: {text}"
        );
    }
    let vm: Vec<f64> = line("von_mises_range")
        .split(' ')
        .map(|v| v.parse().unwrap())
        .collect();
    assert!(vm[1] > vm[0] && vm[0] >= 0.0, "{text}");
    let covered: f64 = line("covered").parse().unwrap();
    assert!(covered > 0.05, "the model covers {covered} of the picture");
    let bytes = std::fs::read(&png).unwrap();
    assert!(bytes.starts_with(b"\x89PNG"), "a PNG was written");
}

fn crashsim_in(dir: &Path, args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_crashsim"))
        .current_dir(dir)
        .args(args)
        .output()
        .unwrap()
}

#[test]
fn info_and_plot_read_the_run_file() {
    let dir = box1bl("plot", 0);
    let h5 = dir.join("BOX1BL.h5");
    let out = crashsim(&["info", h5.to_str().unwrap()]);
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    for want in [
        "deck:   BOX1BL",
        "units:  mass kg, length m, time s",
        "on 1 rank(s)",
        "155 nodes",
        "140 shell4",
        "states: 11",
        "/states/0010   t = 1.000559e-1 s",
        "time histories: 101 samples",
        "nodes [14, 9]: 14 nodes",
    ] {
        assert!(text.contains(want), "info lacks '{want}':\n{text}");
    }
    // Part histories at t = 0: the starter listing's PART MASS table
    // (element mass 4.0950001470000E-02, kinetic energy 1.310400047040).
    let f = hdf5::File::open(&h5).unwrap();
    let (shape, v) = crashsim::output::runfile::read_th(&f, "parts").unwrap();
    assert_eq!(shape, [101, 1, 3]);
    assert!(
        (v[2] - 4.0950001470000e-2).abs() <= 1e-12 * 4.1e-2,
        "part mass {}",
        v[2]
    );
    assert!(
        (v[1] - 1.310400047040).abs() <= 1e-11,
        "part kinetic energy {}",
        v[1]
    );
    drop(f);
    for what in ["energies", "interfaces", "parts", "node:6"] {
        let png = dir.join(format!("{}.png", what.replace(':', "_")));
        let out = crashsim(&[
            "plot",
            h5.to_str().unwrap(),
            "--out",
            png.to_str().unwrap(),
            "--what",
            what,
        ]);
        assert!(
            out.status.success(),
            "plot --what {what}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let bytes = std::fs::read(&png).unwrap();
        assert!(
            bytes.starts_with(b"\x89PNG") && bytes.len() > 10_000,
            "{what}: a PNG with content"
        );
    }
    // Bad input: exit 2 and one line naming the file and what was expected.
    let cases: [(&[&str], &str); 5] = [
        (&["info", "nowhere.h5"], "nowhere.h5: no such file"),
        (&["info", "BOX1BL.out"], "BOX1BL.out: not an HDF5 file"),
        (
            &["plot", "BOX1BL.h5", "--out", "x.png", "--what", "speed"],
            "expected energies, interfaces, parts, node:ID (a /TH/NODE node id), mesh",
        ),
        (
            &["plot", "BOX1BL.h5", "--out", "x.png", "--what", "node:7"],
            "node 7 has no time history",
        ),
        (
            &["plot", "BOX1BL.out", "--out", "x.png"],
            "BOX1BL.out: not an HDF5 file",
        ),
    ];
    for (args, want) in cases {
        let out = crashsim_in(&dir, args);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(want), "{args:?}: '{err}' lacks '{want}'");
        assert!(!err.contains("panicked"), "{args:?} panicked");
    }
}

/// The progress line goes to stderr on a terminal only, and --quiet turns it
/// off; the listing on stdout is the same either way.
#[test]
fn progress_line_on_a_terminal_only() {
    let dir = scratch("progress");
    let deck = qa_deck("BOX1BL");
    let bin = env!("CARGO_BIN_EXE_crashsim");
    // Not a terminal: nothing but errors on stderr.
    let out = crashsim(&[
        "run",
        deck.to_str().unwrap(),
        "--out",
        dir.to_str().unwrap(),
    ]);
    assert!(out.status.success());
    assert!(
        out.stderr.is_empty(),
        "stderr: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    // A terminal (script gives the process a pty); stdout goes to a file.
    let term = |quiet: &str| {
        let cmd = format!(
            "{bin} run {} --out {} {quiet} > {}/listing.txt",
            deck.display(),
            dir.display(),
            dir.display()
        );
        let o = std::process::Command::new("script")
            .args(["-qec", &cmd, "/dev/null"])
            .output()
            .expect("script (util-linux) runs");
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        String::from_utf8_lossy(&o.stdout).into_owned()
    };
    let shown = term("");
    assert!(
        shown.contains("cycles/s") && shown.contains("left"),
        "no progress line on the terminal: {shown:?}"
    );
    let listing = std::fs::read_to_string(dir.join("listing.txt")).unwrap();
    assert!(
        !listing.contains("cycles/s"),
        "the progress line leaked into stdout"
    );
    assert!(listing.contains("NORMAL TERMINATION"));
    let quiet = term("--quiet");
    assert!(
        !quiet.contains("cycles/s"),
        "--quiet still shows progress: {quiet:?}"
    );
}

/// Bricks (Hexahedron topology) on 2 ranks: the XDMF points at what is
/// there, and the last state's von Mises stress is the impact stress ρ·c·v
/// of decks/brick_bar (uniaxial: von Mises = |σxx|) where the wave has passed.
#[test]
fn brick_bar_states_carry_the_impact_stress() {
    let dir = scratch("h5-bricks");
    let deck = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("decks/brick_bar/brick_bar_0000.rad");
    let out = run_env(
        2,
        &[
            "run",
            deck.to_str().unwrap(),
            "--out",
            dir.to_str().unwrap(),
        ],
        &[],
    );
    ok(&out, "run brick_bar");
    let xdmf = dir.join("brick_bar.xdmf");
    python_check("check_xdmf.py", &[xdmf.as_os_str()]);
    assert!(std::fs::read_to_string(&xdmf)
        .unwrap()
        .contains("TopologyType=\"Hexahedron\""));
    let script = r#"
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], "r")
last = f["states"][sorted(f["states"])[-1]]
vm = last["brick8/von_mises"][()]
sigma = 7.85e-6 * (210 / 7.85e-6) ** 0.5 * 5.0
behind = vm[vm > 0.5 * sigma]
assert 0.1 * len(vm) < len(behind) < len(vm), len(behind)
assert abs(np.median(behind) / sigma - 1) < 0.1, (np.median(behind), sigma)
assert last["brick8/deleted"][()].sum() == 0 and "thickness" not in last["brick8"]
print("von Mises behind the front", np.median(behind), "vs", sigma)
"#;
    let py = dir.join("check.py");
    std::fs::write(&py, script).unwrap();
    let o = std::process::Command::new(python())
        .arg(&py)
        .arg(dir.join("brick_bar.h5"))
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}
