//! BOX1BL through the engine: energies against the OpenRadioss listing, and
//! the same final state whatever the number of ranks and threads.

mod common;
use common::*;
use std::path::PathBuf;
use std::process::Command;

fn out_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("crashsim-box1bl-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Runs BOX1BL on `np` ranks with `threads` rayon threads; returns the output dir.
fn run_box1bl(np: u32, threads: u32) -> PathBuf {
    let dir = out_dir(&format!("{np}x{threads}"));
    let fs = dir.join("final.csv");
    let deck = qa_deck("BOX1BL");
    let args = [
        "run",
        deck.to_str().unwrap(),
        "--out",
        dir.to_str().unwrap(),
        "--final-state",
        fs.to_str().unwrap(),
    ];
    let out = if np == 0 {
        Command::new(env!("CARGO_BIN_EXE_crashsim"))
            .args(args)
            .env("RAYON_NUM_THREADS", threads.to_string())
            .output()
            .unwrap()
    } else {
        let mut c = Command::new("mpirun");
        c.env("OMPI_ALLOW_RUN_AS_ROOT", "1")
            .env("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
            .env("OMPI_MCA_hwloc_base_binding_policy", "none")
            .env("OMPI_MCA_btl_vader_single_copy_mechanism", "none")
            .args(["-x", "RAYON_NUM_THREADS", "-n", &np.to_string()]);
        if np > 2 {
            c.arg("--oversubscribe");
        }
        c.env("RAYON_NUM_THREADS", threads.to_string())
            .arg(env!("CARGO_BIN_EXE_crashsim"))
            .args(args)
            .output()
            .unwrap()
    };
    assert!(
        out.status.success(),
        "run -n {np} failed:\n{}\n{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    dir
}

/// (cycle, time, error %, I-energy, K-energy T) rows of a listing's cycle table.
fn table(text: &str) -> Vec<[f64; 5]> {
    let mut rows = Vec::new();
    let mut on = false;
    for l in text.lines() {
        if l.trim_start().starts_with("CYCLE") && l.contains("I-ENERGY") {
            on = true;
            continue;
        }
        if !on {
            continue;
        }
        let t: Vec<&str> = l.split_whitespace().collect();
        // CYCLE TIME TIME-STEP KIND ID ERROR% IE KE KER EXT MASERR MASS ADDED
        if t.len() >= 9 && t[0].parse::<u64>().is_ok() && t[5].ends_with('%') {
            let p = |s: &str| s.trim_end_matches('%').parse::<f64>().unwrap();
            rows.push([p(t[0]), p(t[1]), p(t[5]), p(t[6]), p(t[7])]);
        }
    }
    rows
}

/// Linear interpolation of column `c` of the reference rows at time `t`.
fn at(reference: &[[f64; 5]], t: f64, c: usize) -> f64 {
    let i = reference
        .partition_point(|r| r[1] <= t)
        .clamp(1, reference.len() - 1);
    let (a, b) = (reference[i - 1], reference[i]);
    if b[1] == a[1] {
        return a[c];
    }
    a[c] + (b[c] - a[c]) * (t - a[1]) / (b[1] - a[1])
}

#[test]
fn box1bl_energies_follow_the_reference_listing() {
    let dir = run_box1bl(0, 2);
    let ours = table(&std::fs::read_to_string(dir.join("BOX1BL.out")).unwrap());
    let reference = table(
        &std::fs::read_to_string(shared_dir().join("decks/openradioss-qa/BOX1BL/BOX1BL_0001.out"))
            .unwrap(),
    );
    assert!(
        reference.len() > 1000,
        "reference table parsed ({} rows)",
        reference.len()
    );
    assert!(ours.len() > 10, "our table has rows");
    let t_end = reference.last().unwrap()[1];
    assert!(ours.last().unwrap()[1] >= 0.1, "ran to the end time");
    let max_ie = reference.iter().map(|r| r[3]).fold(0.0, f64::max);
    let max_ke = reference.iter().map(|r| r[4]).fold(0.0, f64::max);
    for r in &ours {
        if r[1] > t_end {
            continue;
        }
        let (ie, ke) = (at(&reference, r[1], 3), at(&reference, r[1], 4));
        assert!(
            (r[3] - ie).abs() <= 0.10 * max_ie,
            "cycle {} t={}: I-ENERGY {} vs reference {ie} (max {max_ie})",
            r[0],
            r[1],
            r[3]
        );
        assert!(
            (r[4] - ke).abs() <= 0.10 * max_ke,
            "cycle {} t={}: K-ENERGY {} vs reference {ke}",
            r[0],
            r[1],
            r[4]
        );
        assert!(
            r[2].abs() <= 2.0,
            "cycle {}: energy error {}% beyond ±2%",
            r[0],
            r[2]
        );
    }
}

#[test]
fn box1bl_final_state_is_identical_for_1_2_4_ranks_and_1_2_threads() {
    let reference = std::fs::read(run_box1bl(1, 1).join("final.csv")).unwrap();
    assert!(reference.len() > 155 * 50, "final state has a row per node");
    for (np, threads) in [(1, 2), (2, 1), (2, 2), (4, 1)] {
        let other = std::fs::read(run_box1bl(np, threads).join("final.csv")).unwrap();
        assert!(
            other == reference,
            "final state differs for {np} ranks x {threads} threads"
        );
    }
}

/// A rank that dies mid-run takes the whole job down quickly (no hang), and
/// the listing written so far is kept.
#[test]
fn a_dying_rank_takes_the_job_down() {
    let dir = out_dir("fault");
    let deck = qa_deck("BOX1BL");
    let started = std::time::Instant::now();
    let mut c = Command::new("mpirun");
    c.env("OMPI_ALLOW_RUN_AS_ROOT", "1")
        .env("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
        .env("OMPI_MCA_hwloc_base_binding_policy", "none")
        .env("OMPI_MCA_btl_vader_single_copy_mechanism", "none")
        .env("CRASHSIM_FAULT", "1:300")
        .args([
            "-x",
            "CRASHSIM_FAULT",
            "-n",
            "2",
            env!("CARGO_BIN_EXE_crashsim"),
            "run",
            deck.to_str().unwrap(),
            "--out",
            dir.to_str().unwrap(),
        ]);
    let out = c.output().unwrap();
    let secs = started.elapsed().as_secs_f64();
    assert!(!out.status.success(), "the job must fail when a rank dies");
    assert!(
        secs < 30.0,
        "the job took {secs} s to end after a rank died"
    );
    let listing = std::fs::read_to_string(dir.join("BOX1BL.out")).unwrap();
    assert!(
        listing.lines().any(|l| l.trim_start().starts_with("299 ")),
        "the listing up to the fault is kept"
    );
}
