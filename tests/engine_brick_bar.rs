//! A free elastic bar of bricks (ν = 0) flying into a rigid wall: behind the
//! compressive front the stress is −ρ·c·v with c = √(E/ρ) (decks/brick_bar,
//! written by decks/make_brick_bar.py); ahead of it the bar is unstressed.

mod common;
use std::path::PathBuf;

#[test]
fn brick_bar_impact_stress_is_rho_c_v() {
    let deck = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("decks/brick_bar/brick_bar_0000.rad");
    let dir = std::env::temp_dir().join(format!("crashsim-brick-bar-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let el = dir.join("elements.csv");
    let out = common::crashsim(&[
        "run",
        deck.to_str().unwrap(),
        "--out",
        dir.to_str().unwrap(),
        "--final-elements",
        el.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let (e, rho, v) = (210.0f64, 7.85e-6f64, 5.0f64);
    let sigma = rho * (e / rho).sqrt() * v;
    let nx = 40;
    let mut sum = vec![0.0f64; nx];
    let mut cnt = vec![0usize; nx];
    for line in std::fs::read_to_string(&el).unwrap().lines().skip(1) {
        let c: Vec<&str> = line.split(',').collect();
        assert_eq!(c[0], "BRICK");
        let id: usize = c[1].parse().unwrap();
        let sxx: f64 = c[2].parse().unwrap();
        sum[(id - 1) % nx] += sxx;
        cnt[(id - 1) % nx] += 1;
    }
    let mean = |i: usize| sum[i] / cnt[i] as f64;
    // The front is at mid-bar (t = L/2c): slices 2..15 are behind it, 25.. ahead.
    let behind: f64 = (2..16).map(mean).sum::<f64>() / 14.0;
    assert!(
        (behind + sigma).abs() <= 0.02 * sigma,
        "stress behind the front {behind} vs -rho c v = {}",
        -sigma
    );
    for i in 2..16 {
        assert!(
            (mean(i) + sigma).abs() <= 0.03 * sigma,
            "slice {i}: {} vs {}",
            mean(i),
            -sigma
        );
    }
    for i in 25..nx {
        assert!(
            mean(i).abs() <= 0.05 * sigma,
            "slice {i} ahead of the front is stressed: {}",
            mean(i)
        );
    }
}
