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
