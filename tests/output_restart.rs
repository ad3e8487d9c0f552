//! Restart files on BOX1BL: a run stopped in the middle and restarted ends
//! byte-identical to the run that never stopped, on the same or another
//! number of ranks; a stop signal on one rank stops every rank at the same
//! cycle; a rank killed mid-run ends the job quickly and leaves a readable
//! run file.

mod common;
use common::*;
use std::path::{Path, PathBuf};
use std::process::Output;

/// `crashsim run BOX1BL` on `np` ranks into `dir` with `extra` arguments and environment.
fn run(np: u32, dir: &Path, extra: &[&str], env: &[(&str, &str)]) -> Output {
    let deck = qa_deck("BOX1BL");
    let mut args = vec![
        "run",
        deck.to_str().unwrap(),
        "--out",
        dir.to_str().unwrap(),
    ];
    args.extend_from_slice(extra);
    run_env(np, &args, env)
}

/// The uninterrupted run's final state (and its directory).
fn reference(tag: &str) -> (Vec<u8>, PathBuf) {
    let dir = scratch(tag);
    let fs = dir.join("final.csv");
    ok(
        &run(0, &dir, &["--final-state", fs.to_str().unwrap()], &[]),
        "reference run",
    );
    (std::fs::read(fs).unwrap(), dir)
}

/// Restarts from DIR/BOX1BL_rst.h5 on `np` ranks; returns the final state.
fn restart(np: u32, dir: &Path) -> Vec<u8> {
    let rst = dir.join("BOX1BL_rst.h5");
    let fs = dir.join("final.csv");
    let out = run(
        np,
        dir,
        &[
            "--restart",
            rst.to_str().unwrap(),
            "--final-state",
            fs.to_str().unwrap(),
        ],
        &[],
    );
    ok(&out, &format!("restart on {np} rank(s)"));
    std::fs::read(fs).unwrap()
}

#[test]
fn stopped_at_cycle_500_and_restarted_on_1_and_2_ranks_ends_byte_identical() {
    let (full, full_dir) = reference("rst-full");
    let stopped = scratch("rst-stop1");
    let out = run(0, &stopped, &["--stop-after-cycle", "500"], &[]);
    ok(&out, "run stopped at cycle 500");
    let listing = String::from_utf8_lossy(&out.stdout);
    assert!(listing.contains("STOPPED AT CYCLE 500"), "{listing}");
    assert!(stopped.join("BOX1BL_rst.h5").is_file());
    // The restart file describes itself.
    let info = crashsim(&["info", stopped.join("BOX1BL_rst.h5").to_str().unwrap()]);
    ok(&info, "info on the restart file");
    let text = String::from_utf8_lossy(&info.stdout);
    assert!(
        text.contains("elements.shell4") && text.contains("nodes.fint"),
        "{text}"
    );

    let a = copy_run(&stopped, "rst-a");
    assert!(
        restart(0, &a) == full,
        "restart on 1 rank differs from the run that never stopped"
    );
    let b = copy_run(&stopped, "rst-b");
    assert!(
        restart(2, &b) == full,
        "restart on 2 ranks differs from the run that never stopped"
    );
    // The run file continued by the restart is the uninterrupted run's.
    python_check(
        "compare_runs.py",
        &[
            full_dir.join("BOX1BL.h5").as_os_str(),
            a.join("BOX1BL.h5").as_os_str(),
            a.join("BOX1BL.out").as_os_str(),
            "same-ranks".as_ref(),
        ],
    );
}

#[test]
fn stopped_on_2_ranks_and_restarted_on_1_ends_byte_identical() {
    let (full, _) = reference("rst-full2");
    let stopped = scratch("rst-stop2");
    ok(
        &run(2, &stopped, &["--stop-after-cycle", "333"], &[]),
        "2-rank run stopped at 333",
    );
    assert!(restart(0, &stopped) == full, "2 → 1 rank restart differs");
}

#[test]
fn a_signal_on_one_rank_stops_every_rank_at_the_same_cycle_with_a_restart_file() {
    let (full, _) = reference("rst-full3");
    let dir = scratch("rst-signal");
    // Rank 1 sends itself SIGTERM at cycle 400 (the real handler path); the
    // ranks' vote completes one cycle later.
    let out = run(2, &dir, &[], &[("CRASHSIM_SIGNAL_AT", "1:400")]);
    ok(&out, "run stopped by SIGTERM");
    let listing = String::from_utf8_lossy(&out.stdout);
    assert!(
        listing.contains("STOPPED AT CYCLE 401 on a stop signal"),
        "{listing}"
    );
    assert!(restart(2, &dir) == full, "restart after the signal differs");
}

/// Kills `rank` of a run on `np` ranks (0: one process, no mpirun) at
/// cycle 600 by SIGKILL; the job ends (within 60 s: a hang is what this catches) and its run file reads
/// up to the last complete state.
fn killed_at_cycle_600_leaves_a_readable_run_file(np: u32, rank: u32, tag: &str) {
    let dir = scratch(tag);
    let started = std::time::Instant::now();
    let at = format!("{rank}:600");
    let out = run(np, &dir, &[], &[("CRASHSIM_KILL_AT", &at)]);
    let secs = started.elapsed().as_secs_f64();
    assert!(
        !out.status.success(),
        "the job must fail when a rank is killed"
    );
    // A hang detector, not a speed bound: the run to cycle 600 itself takes
    // seconds, more when the suite loads both cores.
    assert!(secs < 60.0, "the job took {secs:.1} s to end after SIGKILL");
    // States 0..5 (up to cycle 532) were complete before cycle 600.
    let script = r#"
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], "r")
states = sorted(f["states"])
assert states == [f"{i:04d}" for i in range(6)], states
for s in states:
    g = f["states"][s]
    for k in ("coordinates", "displacement", "velocity", "contact_force"):
        assert g[k].shape == (155, 3) and np.isfinite(g[k][()]).all(), (s, k)
    assert g["shell4/von_mises"].shape == (140,)
th = f["th/rows"][()]
assert th.shape[0] >= 50 and th["global"].shape == (th.shape[0], 10), th.shape
assert np.isfinite(th["global"]).all() and (np.diff(th["time"]) > 0).all()
print("readable:", len(states), "states,", th.shape[0], "history rows")
"#;
    let py = dir.join("read.py");
    std::fs::write(&py, script).unwrap();
    let o = std::process::Command::new(python())
        .arg(&py)
        .arg(dir.join("BOX1BL.h5"))
        .output()
        .unwrap();
    assert!(
        o.status.success(),
        "the run file of the killed job ({np} ranks) does not read:\n{}",
        String::from_utf8_lossy(&o.stderr)
    );
}

/// Two ranks share the file through MPI-IO.
#[test]
fn a_rank_killed_mid_run_ends_the_job_and_leaves_a_readable_run_file() {
    killed_at_cycle_600_leaves_a_readable_run_file(2, 1, "rst-kill");
}

/// One process writes it as a plain file, flushed after each state.
#[test]
fn a_single_process_killed_mid_run_leaves_a_readable_run_file() {
    killed_at_cycle_600_leaves_a_readable_run_file(0, 0, "rst-kill1");
}

#[test]
fn a_bad_restart_file_is_an_input_error_naming_it() {
    let dir = scratch("rst-bad");
    let listing = dir.join("not_a_restart.h5");
    std::fs::write(&listing, "plain text").unwrap();
    for (file, want) in [
        (dir.join("missing_rst.h5"), "no such restart file"),
        (listing.clone(), "not an HDF5 file"),
    ] {
        let out = run(0, &dir, &["--restart", file.to_str().unwrap()], &[]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{err}");
        assert!(
            err.contains(file.to_str().unwrap()) && err.contains(want),
            "{err}"
        );
    }
    // A run file is not a restart file.
    ok(&run(0, &dir, &[], &[]), "run");
    let h5 = dir.join("BOX1BL.h5");
    let out = run(0, &dir, &["--restart", h5.to_str().unwrap()], &[]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("expected a crashsim restart file"), "{err}");
}

/// /RFILE/1 with Ncycle 300: restart files at cycles 300, 600 and 900; the
/// last one continues to the same final state.
#[test]
fn rfile_writes_a_restart_file_every_n_cycles() {
    let (full, _) = reference("rst-full4");
    let dir = scratch("rst-rfile");
    let engine = dir.join("BOX1BL_0001.rad");
    let mut text =
        std::fs::read_to_string(shared_dir().join("decks/openradioss-qa/BOX1BL/BOX1BL_0001.rad"))
            .unwrap();
    text.push_str("/RFILE/1\n300\n");
    std::fs::write(&engine, text).unwrap();
    ok(
        &run(2, &dir, &["--engine", engine.to_str().unwrap()], &[]),
        "run with /RFILE",
    );
    let rst = dir.join("BOX1BL_rst.h5");
    let fs = dir.join("final.csv");
    let out = run(
        0,
        &dir,
        &[
            "--engine",
            engine.to_str().unwrap(),
            "--restart",
            rst.to_str().unwrap(),
            "--final-state",
            fs.to_str().unwrap(),
        ],
        &[],
    );
    ok(&out, "restart from the /RFILE file");
    let listing = String::from_utf8_lossy(&out.stdout);
    assert!(listing.contains("at cycle 900,"), "{listing}");
    assert!(
        std::fs::read(fs).unwrap() == full,
        "restart from cycle 900 differs"
    );
}
