//! BOULE1V4 and INT357 — the OpenRadioss QA decks with contact — on 1, 2 and
//! 4 ranks: internal and kinetic energies against the listings OpenRadioss
//! wrote, the same final state whatever the number of ranks, and a partition
//! that really cuts through the interfaces.

mod common;
use common::*;
use std::path::PathBuf;
use std::process::Command;

fn out_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("crashsim-contact-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Runs a QA deck on `np` ranks (0 = without mpirun); returns the output dir
/// holding final.csv and energies.csv.
fn run(deck: &str, np: u32) -> PathBuf {
    let dir = out_dir(&format!("{deck}-{np}"));
    let fs = dir.join("final.csv");
    let en = dir.join("energies.csv");
    let d = qa_deck(deck);
    let args = [
        "run",
        d.to_str().unwrap(),
        "--out",
        dir.to_str().unwrap(),
        "--final-state",
        fs.to_str().unwrap(),
        "--energies",
        en.to_str().unwrap(),
    ];
    let out = if np == 0 {
        Command::new(env!("CARGO_BIN_EXE_crashsim"))
            .args(args)
            .output()
            .unwrap()
    } else {
        mpirun(np, &args)
    };
    assert!(
        out.status.success(),
        "{deck} on {np} ranks failed:\n{}\n{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    dir
}

/// (time, I-energy, K-energy T) rows of the reference listing's cycle table.
fn reference_rows(deck: &str) -> Vec<[f64; 3]> {
    let p = shared_dir()
        .join("decks/openradioss-qa")
        .join(deck)
        .join(format!("{deck}_0001.out"));
    let text = std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
    let mut rows = Vec::new();
    for l in text.lines() {
        let t: Vec<&str> = l.split_whitespace().collect();
        if t.len() >= 9 && t[0].parse::<u64>().is_ok() && t[5].ends_with('%') {
            let p = |s: &str| s.parse::<f64>().unwrap();
            rows.push([p(t[1]), p(t[6]), p(t[7])]);
        }
    }
    assert!(rows.len() > 10, "{deck}: reference table not found");
    rows
}

/// (time, internal, kinetic) of our run, every cycle.
fn our_rows(dir: &std::path::Path) -> Vec<[f64; 3]> {
    let text = std::fs::read_to_string(dir.join("energies.csv")).unwrap();
    text.lines()
        .skip(1)
        .map(|l| {
            let c: Vec<f64> = l.split(',').map(|s| s.parse().unwrap()).collect();
            [c[0], c[3], c[4]]
        })
        .collect()
}

fn at(rows: &[[f64; 3]], t: f64, col: usize) -> f64 {
    let i = rows.partition_point(|r| r[0] < t);
    if i == 0 {
        return rows[0][col];
    }
    if i >= rows.len() {
        return rows[rows.len() - 1][col];
    }
    let (a, b) = (rows[i - 1], rows[i]);
    let w = if b[0] > a[0] {
        (t - a[0]) / (b[0] - a[0])
    } else {
        0.0
    };
    a[col] * (1.0 - w) + b[col] * w
}

/// Every printed reference row: our energy at the same time within 10% of the
/// column's largest reference value. A column whose largest value is below
/// 0.1% of the run's energy scale (INT357's I-ENERGY, at most 1.4e-3 J in a
/// 72 J run: the plastic work at SIG_y = 0.003 Pa is round-off) is held to
/// 10% of that floor instead of to 10% of its own noise.
///
/// `limits`: (fraction, last time checked) per column, I-ENERGY then K-ENERGY T.
fn check_energies(deck: &str, dir: &std::path::Path, limits: [(f64, f64); 2]) -> Vec<String> {
    let reference = reference_rows(deck);
    let ours = our_rows(dir);
    let scale = reference
        .iter()
        .map(|r| r[1].abs().max(r[2].abs()))
        .fold(0.0, f64::max);
    let mut report = Vec::new();
    let mut fails = Vec::new();
    for (col, name) in [(1, "I-ENERGY"), (2, "K-ENERGY T")] {
        let (frac, t_last) = limits[col - 1];
        let max = reference.iter().map(|r| r[col].abs()).fold(0.0, f64::max);
        let tol = frac * max.max(1e-3 * scale);
        let mut worst = 0.0f64;
        for r in reference.iter().filter(|r| r[0] <= t_last) {
            let o = at(&ours, r[0], col);
            let d = (o - r[col]).abs();
            worst = worst.max(100.0 * d / max.max(1e-3 * scale));
            if d > tol {
                fails.push(format!("{deck} {name} at t = {:e}: ours {o:.5e}, OpenRadioss {:.5e} (tolerance {tol:.3e})", r[0], r[col]));
            }
        }
        report.push(format!(
            "{deck} {name}: worst deviation {worst:.2}% of the column's largest value"
        ));
    }
    assert!(
        fails.is_empty(),
        "{}\n{}",
        fails.join("\n"),
        report.join("\n")
    );
    report
}

fn final_state(dir: &std::path::Path) -> Vec<u8> {
    std::fs::read(dir.join("final.csv")).unwrap()
}

/// INT357's EXT-WORK (the CLOADs' work, the rigid wall's impulses on the
/// plates pressed onto it) at every printed row's time within 5% of the
/// row's value (issue 13: it was 13.09 against 6.985 at cycle 300).
fn check_external_work(dir: &std::path::Path) {
    let p = shared_dir().join("decks/openradioss-qa/INT357/INT357_0001.out");
    let text = std::fs::read_to_string(p).unwrap();
    let reference: Vec<[f64; 2]> = text
        .lines()
        .map(|l| l.split_whitespace().collect::<Vec<_>>())
        .filter(|t| t.len() > 9 && t[0].parse::<u64>().is_ok() && t[5].ends_with('%'))
        .map(|t| [t[1].parse().unwrap(), t[9].parse().unwrap()])
        .collect();
    let (_, csv) = read_csv(&dir.join("energies.csv"));
    let ours: Vec<[f64; 3]> = csv.iter().map(|r| [r[0], r[6], 0.0]).collect();
    assert!(reference.len() > 15);
    for r in reference.iter().filter(|r| r[1] > 0.0) {
        let w = at(&ours, r[0], 1);
        assert!(
            (w / r[1] - 1.0).abs() < 0.05,
            "INT357 EXT-WORK at t = {:e}: ours {w:.4e}, OpenRadioss {:.4e}",
            r[0],
            r[1]
        );
    }
}

#[test]
fn int357_energies_on_1_2_and_4_ranks_follow_openradioss() {
    let mut states = Vec::new();
    let mut energies = Vec::new();
    for np in [0, 2, 4] {
        let dir = run("INT357", np);
        for line in check_energies("INT357", &dir, [(0.1, 1.0), (0.1, 1.0)]) {
            eprintln!("{np} ranks: {line}");
        }
        check_external_work(&dir);
        states.push(final_state(&dir));
        energies.push(std::fs::read(dir.join("energies.csv")).unwrap());
    }
    assert!(
        states[0] == states[1] && states[0] == states[2],
        "INT357 final state differs between 1, 2 and 4 ranks"
    );
    // The energies are exact sums: the same bits on any number of ranks.
    assert!(
        energies[0] == energies[1] && energies[0] == energies[2],
        "INT357 energies differ between 1, 2 and 4 ranks"
    );
}

#[test]
fn boule1v4_energies_on_1_2_and_4_ranks_follow_openradioss_and_final_state_is_byte_identical() {
    let mut states = Vec::new();
    for np in [0, 2, 4] {
        let dir = run("BOULE1V4", np);
        // I-ENERGY (without the hourglass energy, as the Radioss listing)
        // and K-ENERGY T at every printed cycle: the issue asks 10% of the
        // column's largest value; measured 0.4% and 0.8% (the shells'
        // hourglass with the reference engine's factors), held to 5% here so
        // that a regression shows long before the 10%.
        for line in check_energies("BOULE1V4", &dir, [(0.05, 1.0), (0.05, 1.0)]) {
            eprintln!("{np} ranks: {line}");
        }
        states.push(final_state(&dir));
    }
    assert!(!states[0].is_empty());
    assert!(
        states[0] == states[1],
        "BOULE1V4 final state differs between 1 and 2 ranks"
    );
    assert!(
        states[0] == states[2],
        "BOULE1V4 final state differs between 1 and 4 ranks"
    );
}

#[test]
fn boule1v4_four_rank_partition_cuts_through_both_interfaces() {
    let d = qa_deck("BOULE1V4");
    let v = crashsim_json(&["partition", d.to_str().unwrap(), "--np", "4", "--json"]);
    let inter = v["interfaces"].as_array().unwrap();
    assert_eq!(inter.len(), 2);
    for i in inter {
        let mut ranks: Vec<u64> = i["secondary_ranks"]
            .as_array()
            .unwrap()
            .iter()
            .chain(i["main_ranks"].as_array().unwrap())
            .map(|r| r.as_u64().unwrap())
            .collect();
        ranks.sort_unstable();
        ranks.dedup();
        assert!(
            ranks.len() > 1,
            "interface {} lies on one rank: {i}",
            i["id"]
        );
    }
    // And on 2 ranks the plate interface already crosses: ball on one side, plate split.
    let v2 = crashsim_json(&["partition", d.to_str().unwrap(), "--np", "2", "--json"]);
    let i1 = &v2["interfaces"][0];
    assert!(
        i1["main_ranks"].as_array().unwrap().len()
            + i1["secondary_ranks"].as_array().unwrap().len()
            > 2
    );
}
