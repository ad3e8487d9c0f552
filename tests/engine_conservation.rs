//! Momentum conservation: a free plate (no boundary conditions, no contact)
//! with half its nodes launched deforms, but its total momentum Σ m·v stays
//! what it was at t = 0, to round-off.

mod common;
use std::path::PathBuf;

#[test]
fn free_plate_conserves_momentum() {
    let deck =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("decks/free_plate/free_plate_0000.rad");
    let dir = std::env::temp_dir().join(format!("crashsim-momentum-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let fs = dir.join("final.csv");
    let out = common::crashsim(&[
        "run",
        deck.to_str().unwrap(),
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
    // Nodal masses of the regular 8 x 6 grid: rho*t*A/4 per element corner.
    let (nx, ny) = (8usize, 6usize);
    let m_corner = 7.85e-6 * 1.0 * 100.0 / 4.0;
    let mass = |id: usize| {
        let (i, j) = ((id - 1) % (nx + 1), (id - 1) / (nx + 1));
        let cx = if i == 0 || i == nx { 1.0 } else { 2.0 };
        let cy = if j == 0 || j == ny { 1.0 } else { 2.0 };
        cx * cy * m_corner
    };
    // Initial momentum: the left half (i <= nx/2) at (1, 0, 0.5).
    let mut p0 = [0.0f64; 3];
    for id in 1..=(nx + 1) * (ny + 1) {
        if (id - 1) % (nx + 1) <= nx / 2 {
            p0[0] += mass(id);
            p0[2] += 0.5 * mass(id);
        }
    }
    let text = std::fs::read_to_string(&fs).unwrap();
    let mut p = [0.0f64; 3];
    let mut moved = 0.0f64;
    for line in text.lines().skip(1) {
        let c: Vec<f64> = line.split(',').map(|s| s.parse().unwrap()).collect();
        let id = c[0] as usize;
        for k in 0..3 {
            p[k] += mass(id) * c[4 + k];
        }
        moved = moved.max(
            (c[4]
                - if (id - 1) % (nx + 1) <= nx / 2 {
                    1.0
                } else {
                    0.0
                })
            .abs(),
        );
    }
    assert!(
        moved > 1e-3,
        "the plate deformed (velocities changed by {moved})"
    );
    for k in 0..3 {
        assert!(
            (p[k] - p0[k]).abs() <= 1e-12 * p0[0].abs(),
            "momentum component {k}: {} vs {}",
            p[k],
            p0[k]
        );
    }
}

/// `decks/free_plate` printed every 8 cycles, as OpenRadioss ran it (issue
/// 13): I-ENERGY and K-ENERGY T within 1% of OpenRadioss's listing at cycles
/// 32, 64, 160 and 280. The kinetic energy is that of the velocities at
/// t^n (v^{n−½} + ½Δt a^n, as Radioss counts it); with the loop's v^{n−½}
/// it was 7–11% high while the plate rings.
#[test]
fn free_plate_listing_energies_match_openradioss() {
    let dir = common::scratch("free-plate-print8");
    let src = common::deck("free_plate");
    std::fs::copy(&src, dir.join("free_plate_0000.rad")).unwrap();
    let engine = std::fs::read_to_string(src.with_file_name("free_plate_0001.rad")).unwrap();
    assert!(engine.contains("/PRINT/-100/55"));
    std::fs::write(
        dir.join("free_plate_0001.rad"),
        engine.replace("/PRINT/-100/55", "/PRINT/-8/55"),
    )
    .unwrap();
    let out = common::crashsim(&[
        "run",
        dir.join("free_plate_0000.rad").to_str().unwrap(),
        "--out",
        dir.to_str().unwrap(),
    ]);
    common::ok(&out, "free_plate /PRINT/-8");
    let listing = std::fs::read_to_string(dir.join("free_plate.out")).unwrap();
    // OpenRadioss: cycle, I-ENERGY, K-ENERGY T.
    let reference = [
        (32u64, 3.974e-3, 1.014e-2),
        (64, 3.343e-3, 1.081e-2),
        (160, 1.668e-3, 1.215e-2),
        (280, 3.840e-3, 9.903e-3),
    ];
    for (cycle, ie, ke) in reference {
        let row: Vec<&str> = listing
            .lines()
            .map(|l| l.split_whitespace().collect::<Vec<_>>())
            .find(|c| c.len() > 8 && c[0] == cycle.to_string())
            .unwrap_or_else(|| panic!("no listing row for cycle {cycle}:\n{listing}"));
        let (our_ie, our_ke): (f64, f64) = (row[6].parse().unwrap(), row[7].parse().unwrap());
        for (what, ours, theirs) in [("I-ENERGY", our_ie, ie), ("K-ENERGY T", our_ke, ke)] {
            assert!(
                (ours / theirs - 1.0).abs() < 0.01,
                "cycle {cycle}: {what} {ours:e} against OpenRadioss {theirs:e}"
            );
        }
    }
}

/// decks/pushed_block: a block pushed from rest by a constant load along a
/// TYPE7 surface (Fric 0.2, outside the gap): the listing's ERROR within ±1%
/// at every printed cycle from cycle 3 on (issue 13: it was −26% at cycle 3,
/// the kinetic energy taken at the half step and the first step's work
/// halved), and K-ENERGY T + I-ENERGY = EXT-WORK at the end.
#[test]
fn pushed_block_balances_its_external_work_at_every_row() {
    let dir = common::scratch("pushed-block");
    let out = common::crashsim(&[
        "run",
        common::deck("pushed_block").to_str().unwrap(),
        "--out",
        dir.to_str().unwrap(),
    ]);
    common::ok(&out, "pushed_block");
    let listing = std::fs::read_to_string(dir.join("pushed_block.out")).unwrap();
    let rows: Vec<Vec<String>> = listing
        .lines()
        .map(|l| l.split_whitespace().map(String::from).collect::<Vec<_>>())
        .filter(|c| c.len() > 10 && c[0].parse::<u64>().is_ok() && c[5].ends_with('%'))
        .collect();
    assert!(rows.len() > 100, "{} rows", rows.len());
    for r in &rows {
        let err: f64 = r[5].trim_end_matches('%').parse().unwrap();
        assert!(err.abs() <= 1.0, "ERROR {err}% at cycle {}", r[0]);
    }
    let last = rows.last().unwrap();
    let num = |k: usize| last[k].parse::<f64>().unwrap();
    let (ie, ke, w) = (num(6), num(7), num(9));
    assert!(w > 0.3, "the block was pushed: EXT-WORK {w}");
    assert!(
        ((ie + ke) / w - 1.0).abs() < 1e-3,
        "I {ie} + K {ke} against W {w}"
    );
}
