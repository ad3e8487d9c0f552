//! Physics going wrong at run time stops the run with a message naming what
//! and where (node or element id, cycle, time), exit code 3, and the listing
//! written so far kept. Gravity accelerates a free body at g exactly.

mod common;
use std::path::{Path, PathBuf};

fn free_plate() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("decks/free_plate/free_plate_0000.rad")
}

fn tmp(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("crashsim-stop-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn run_with_engine(deck: &Path, dir: &Path, engine: &str) -> std::process::Output {
    run_with_engine_and(deck, dir, engine, &[])
}

/// `run DECK --engine ENGINE --out DIR` with `extra` arguments.
fn run_with_engine_and(
    deck: &Path,
    dir: &Path,
    engine: &str,
    extra: &[&str],
) -> std::process::Output {
    let eng = dir.join("engine_0001.rad");
    std::fs::write(&eng, engine).unwrap();
    let mut args = vec![
        "run",
        deck.to_str().unwrap(),
        "--engine",
        eng.to_str().unwrap(),
        "--out",
        dir.to_str().unwrap(),
    ];
    args.extend_from_slice(extra);
    common::crashsim(&args)
}

#[test]
fn time_step_below_the_dt_minimum_stops_the_run() {
    let dir = tmp("dtmin");
    let out = run_with_engine(
        &free_plate(),
        &dir,
        "/RUN/free_plate/1\n0.5\n/DT\n0.9 0.01\n/PRINT/-1/55\n",
    );
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(3), "stderr: {err}");
    assert!(
        err.contains("below the /DT minimum")
            && err.contains("SHELL")
            && err.contains("cycle 1")
            && err.contains("time"),
        "{err}"
    );
    let listing = std::fs::read_to_string(dir.join("free_plate.out")).unwrap();
    assert!(
        listing.contains("ERROR TERMINATION"),
        "the listing is kept and says why"
    );
}

#[test]
fn an_unstable_run_stops_naming_the_element_or_node() {
    // A time-step scale of 3 breaks the stability limit: the plate blows up.
    let dir = tmp("unstable");
    let out = run_with_engine(
        &free_plate(),
        &dir,
        "/RUN/free_plate/1\n0.5\n/DT\n3.0 0.0\n/PRINT/-1/55\n",
    );
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(3), "stderr: {err}");
    // The element or node check, or the energy watchdog (it names the part).
    assert!(
        (err.contains("SHELL ") || err.contains("node ") || err.contains("PART 1"))
            && err.contains("at cycle")
            && err.contains("time"),
        "{err}"
    );
    assert!(!err.contains("panicked"));
    let listing = std::fs::read_to_string(dir.join("free_plate.out")).unwrap();
    assert!(
        listing
            .lines()
            .filter(|l| l.trim_start().starts_with(|c: char| c.is_ascii_digit()))
            .count()
            >= 2,
        "rows before the stop are kept"
    );
}

#[test]
fn gravity_accelerates_a_free_plate_at_g() {
    // The free plate with /GRAV (g = -9.81e-3 mm/ms^2 on z, constant) and no initial velocity.
    let dir = tmp("grav");
    let text = std::fs::read_to_string(free_plate()).unwrap();
    let start = text.find("/INIVEL/TRA/1").unwrap();
    let end = text.find("/END").unwrap();
    let deck = format!(
        "{}/GRAV/1\ngravity\n{:>10}{:>10}{:>10}{:>10}{:>10}{:>10}{:>20}{:>20}\n/GRNOD/PART/7\nall\n{:>10}\n/END\n",
        &text[..start],
        0,
        "Z",
        0,
        0,
        7,
        "",
        0,
        -9.81e-3,
        1
    );
    let _ = end;
    let path = dir.join("grav_0000.rad");
    std::fs::write(&path, deck).unwrap();
    std::fs::write(
        dir.join("grav_0001.rad"),
        "/RUN/grav/1\n0.2\n/DT\n0.9 0.0\n/PRINT/-1/55\n",
    )
    .unwrap();
    let fs = dir.join("final.csv");
    let out = common::crashsim(&[
        "run",
        path.to_str().unwrap(),
        "--out",
        dir.to_str().unwrap(),
        "--final-state",
        fs.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let listing = std::fs::read_to_string(dir.join("free_plate.out")).unwrap(); // named after the /BEGIN run name
    let t_end: f64 = listing
        .lines()
        .filter_map(|l| {
            let t: Vec<&str> = l.split_whitespace().collect();
            (t.len() > 5 && t[0].parse::<u64>().is_ok() && t[5].ends_with('%'))
                .then(|| t[1].parse::<f64>().unwrap())
        })
        .last()
        .unwrap();
    for line in std::fs::read_to_string(&fs).unwrap().lines().skip(1) {
        let c: Vec<f64> = line.split(',').map(|s| s.parse().unwrap()).collect();
        // v_z = g t at the last half step; the listing prints t to 5 digits.
        assert!(
            (c[6] - (-9.81e-3) * t_end).abs() <= 9.81e-3 * t_end * 1e-2,
            "node {}: vz = {} vs g t = {}",
            c[0],
            c[6],
            -9.81e-3 * t_end
        );
        assert!(
            c[4].abs() < 1e-12 && c[5].abs() < 1e-12,
            "no lateral motion"
        );
    }
    // External work equals the kinetic energy gained (energy error ~ 0).
    let last = listing
        .lines()
        .filter(|l| l.contains('%') && l.trim_start().starts_with(|c: char| c.is_ascii_digit()))
        .last()
        .unwrap();
    let err: f64 = last
        .split_whitespace()
        .nth(5)
        .unwrap()
        .trim_end_matches('%')
        .parse()
        .unwrap();
    assert!(err.abs() <= 1.0, "energy error {err}% with gravity work");
}

/// decks/bars_head_on made to blow up: contact stiffness ×1e6 (Stfac 0.1 →
/// 1e5) and a /DT scale of 2, with `engine` as its engine file and `extra`
/// arguments to `run`.
fn blown_bars(tag: &str, engine: &str, extra: &[&str]) -> (PathBuf, std::process::Output) {
    let dir = tmp(tag);
    let deck = common::deck_variant("bars_head_on", &dir, |i, lines| {
        (i >= 9 && lines[i - 9].starts_with("/INTER/TYPE7/"))
            .then(|| lines[i].replacen("                 0.1", "                 1e5", 1))
    });
    assert!(std::fs::read_to_string(&deck).unwrap().contains("1e5"));
    let out = run_with_engine_and(&deck, &dir, engine, extra);
    (dir, out)
}

const BLOWN_ENGINE: &str = "/RUN/bars_head_on/1\n0.055998\n/DT\n2.0 0.0\n/PRINT/-1/55\n";

#[test]
fn a_blow_up_stops_on_the_energy_watchdog_naming_cycle_time_and_part() {
    let (dir, out) = blown_bars("watchdog", BLOWN_ENGINE, &[]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(3), "stderr: {err}");
    assert!(
        err.contains("ENERGY ERROR LIMIT REACHED")
            && err.contains("the default limit 100%")
            && err.contains("at cycle")
            && err.contains("time")
            && err.contains("PART "),
        "{err}"
    );
    let listing = std::fs::read_to_string(dir.join("bars_head_on.out")).unwrap();
    assert!(listing.contains("ERROR TERMINATION: ENERGY ERROR LIMIT REACHED"));
    assert!(
        dir.join("bars_head_on.h5").is_file(),
        "the run file is kept"
    );
}

#[test]
fn stop_emax_with_nth_checks_every_cycle() {
    // Rows every 100 cycles only: /STOP's NTH = 1 makes the check run every
    // cycle, and its Emax (a fraction: 0.5 = 50%) is the limit.
    let (_, out) = blown_bars(
        "stop-emax",
        "/RUN/bars_head_on/1\n0.055998\n/DT\n2.0 0.0\n/PRINT/-100/55\n/STOP\n0.5 0 0 1 0 0\n",
        &[],
    );
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(3), "stderr: {err}");
    assert!(
        err.contains("ENERGY ERROR LIMIT REACHED") && err.contains("/STOP Emax 0.5"),
        "{err}"
    );
}

#[test]
fn no_energy_limit_leaves_the_blow_up_to_the_element_checks() {
    let (_, out) = blown_bars("no-limit", BLOWN_ENGINE, &["--energy-error-limit", "0"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(3), "stderr: {err}");
    assert!(
        !err.contains("ENERGY ERROR LIMIT") && err.contains("BRICK "),
        "{err}"
    );
}
