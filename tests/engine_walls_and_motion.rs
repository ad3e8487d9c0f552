//! Moving rigid walls and imposed displacements.

mod common;
use std::path::PathBuf;

fn tmp(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("crashsim-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// decks/brick_bar_wall: a free wall of 0.01 kg (node 9999) strikes a resting
/// brick bar at 5 mm/ms. The wall slows down, the bar starts moving, and the
/// total momentum stays 0.05 kg·mm/ms to round-off.
#[test]
fn free_moving_wall_conserves_momentum() {
    let deck = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("decks/brick_bar_wall/brick_bar_wall_0000.rad");
    let dir = tmp("wall");
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
    let (n, nx, h, rho) = (4usize, 40usize, 2.5f64, 7.85e-6f64);
    let corner = rho * h * h * h / 8.0;
    let count = |i: usize, m: usize| if i == 0 || i == m { 1.0 } else { 2.0 };
    let (mut p_bar, mut v_wall) = (0.0f64, f64::NAN);
    for line in std::fs::read_to_string(&fs).unwrap().lines().skip(1) {
        let c: Vec<f64> = line.split(',').map(|s| s.parse().unwrap()).collect();
        let id = c[0] as usize;
        if id == 9999 {
            v_wall = c[4];
            continue;
        }
        let k = id - 1;
        let (i, j, kk) = (
            k % (nx + 1),
            (k / (nx + 1)) % (n + 1),
            k / ((nx + 1) * (n + 1)),
        );
        p_bar += corner * count(i, nx) * count(j, n) * count(kk, n) * c[4];
    }
    let p = p_bar + 0.01 * v_wall;
    assert!((p - 0.05).abs() < 1e-12, "total momentum {p} vs 0.05");
    // The listing counts the free wall as Radioss does: its 0.01 kg in TOTAL
    // MASS (bar: 7.85e-6 x 10 x 10 x 100 = 0.0785) and its ½ m v² in K-ENERGY T.
    let listing = std::fs::read_to_string(dir.join("brick_bar_wall.out")).unwrap();
    let rows: Vec<Vec<&str>> = listing
        .lines()
        .map(|l| l.split_whitespace().collect::<Vec<_>>())
        .filter(|t| t.len() == 13 && t[0].parse::<u64>().is_ok() && t[5].ends_with('%'))
        .collect();
    let num = |t: &str| t.parse::<f64>().unwrap();
    assert_eq!(rows[0][0], "0");
    assert!(
        (num(rows[0][7]) - 0.125).abs() < 1e-4,
        "K-ENERGY T at t = 0: {}",
        rows[0][7]
    );
    assert!(
        (num(rows[0][11]) - 0.0885).abs() < 1e-4,
        "TOTAL MASS: {}",
        rows[0][11]
    );
    let last = rows.last().unwrap();
    let err = num(last[5].trim_end_matches('%'));
    assert!(
        err.abs() < 5.0,
        "ERROR {err}% at the end: the wall's energy is in the balance"
    );
    assert!(
        v_wall < 5.0 && v_wall > 0.0,
        "the wall slowed down (v = {v_wall})"
    );
    assert!(p_bar > 0.0, "the bar was set moving");
}

/// /IMPDISP drives its nodes along u(t) = Fscale·f(t/Ascale) exactly.
#[test]
fn imposed_displacement_is_followed_exactly() {
    let dir = tmp("impdisp");
    let i10 = |v: i64| format!("{v:>10}");
    let r20 = |v: f64| format!("{v:>20}");
    let mut d = vec![
        "/BEGIN".to_string(),
        "impdisp".into(),
        i10(2019) + &i10(0),
        format!("{:>20}{:>20}{:>20}", "kg", "mm", "ms"),
        format!("{:>20}{:>20}{:>20}", "kg", "mm", "ms"),
        "/MAT/LAW1/1".into(),
        "steel".into(),
        r20(7.85e-6),
        r20(210.0) + &r20(0.3),
        "/PROP/SHELL/1".into(),
        "1 mm".into(),
        i10(1) + &i10(2),
        r20(0.0),
        i10(3) + &i10(0) + &r20(1.0),
        "/PART/1".into(),
        "plate".into(),
        i10(1) + &i10(1),
        "/NODE".into(),
    ];
    for (id, x, y) in [
        (1, 0.0, 0.0),
        (2, 10.0, 0.0),
        (3, 10.0, 10.0),
        (4, 0.0, 10.0),
    ] {
        d.push(i10(id) + &r20(x) + &r20(y) + &r20(0.0));
    }
    d.extend([
        "/SHELL/1".into(),
        i10(1) + &i10(1) + &i10(2) + &i10(3) + &i10(4),
    ]);
    d.extend([
        "/BCS/1".into(),
        "left".into(),
        format!("{:>10}{}{}", "111 111", i10(0), i10(1)),
        "/GRNOD/NODE/1".into(),
        "left".into(),
        i10(1) + &i10(4),
    ]);
    // u(t) = 0.5 * t^... : a ramp u = 0.02 * t (mm, ms) via f(t) = t, Fscale 0.02.
    d.extend([
        "/FUNCT/1".into(),
        "ramp".into(),
        r20(0.0) + &r20(0.0),
        r20(1.0) + &r20(1.0),
    ]);
    d.extend([
        "/IMPDISP/1".into(),
        "pull".into(),
        i10(1) + &format!("{:>10}", "X") + &i10(0) + &i10(0) + &i10(2),
        r20(0.0) + &r20(0.02) + &r20(0.0) + &r20(0.0),
    ]);
    d.extend([
        "/GRNOD/NODE/2".into(),
        "right".into(),
        i10(2) + &i10(3),
        "/END".into(),
    ]);
    std::fs::write(dir.join("impdisp_0000.rad"), d.join("\n") + "\n").unwrap();
    std::fs::write(
        dir.join("impdisp_0001.rad"),
        "/RUN/impdisp/1\n0.05\n/DT\n0.9 0.0\n",
    )
    .unwrap();
    let fs = dir.join("final.csv");
    let out = common::crashsim(&[
        "run",
        dir.join("impdisp_0000.rad").to_str().unwrap(),
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
    let listing = std::fs::read_to_string(dir.join("impdisp.out")).unwrap();
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
        if c[0] == 2.0 || c[0] == 3.0 {
            let u = c[1] - 10.0;
            // The listing prints time to 5 digits: compare within that.
            assert!(
                (u - 0.02 * t_end).abs() <= 0.02 * t_end * 1e-3,
                "node {}: u = {u}, expected {}",
                c[0],
                0.02 * t_end
            );
        }
        if c[0] == 1.0 || c[0] == 4.0 {
            assert_eq!(c[1], 0.0, "the held side stays put");
        }
    }
}

/// decks/free_plate made one rigid body (/RBODY on all its nodes, main node
/// 1000 at the centre, MASS 0.5, node group 8 = the main node, /FUNCT/3 = 1)
/// with `loads` (cards on the main node) added; runs it and returns the
/// final-state rows (id, x, y, z, vx, vy, vz, ...).
fn rigid_plate_with(tag: &str, loads: &[&str]) -> Vec<Vec<f64>> {
    rigid_plate_inertia(tag, 0.0, loads)
}

/// `rigid_plate_with`, the card giving the body the added inertia Jxx = Jyy
/// = Jzz = `j` (at its main node).
fn rigid_plate_inertia(tag: &str, j: f64, loads: &[&str]) -> Vec<Vec<f64>> {
    rigid_plate_body(tag, j, 0, loads)
}

/// `rigid_plate_inertia` with the card's ISPHER; the run writes its
/// energies to `tmp(tag)/energies.csv`.
fn rigid_plate_body(tag: &str, j: f64, ispher: i64, loads: &[&str]) -> Vec<Vec<f64>> {
    let src = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("decks/free_plate");
    let dir = tmp(tag);
    let inertia = format!("{j:>20}{j:>20}{j:>20}");
    let rbody = format!(
        "      1000         0         0{ispher:>10}                 0.5         7         0         0         0"
    );
    let starter = std::fs::read_to_string(src.join("free_plate_0000.rad")).unwrap();
    let head = &starter[..starter.find("/INIVEL/TRA/1").unwrap()];
    let body: [&str; 17] = [
        "/NODE",
        "      1000                  40                  30                   0",
        "/GRNOD/PART/7",
        "all plate nodes",
        "         1",
        "/RBODY/1",
        "plate as one rigid body",
        &rbody,
        &inertia,
        "                   0                   0                   0",
        "/FUNCT/3",
        "constant",
        "                   0                   1",
        "                  10                   1",
        "/GRNOD/NODE/8",
        "the main node",
        "      1000",
    ];
    let deck = dir.join("rbody_0000.rad");
    let cards = [&body[..], loads, &["/END"]].concat();
    std::fs::write(&deck, format!("{head}{}\n", cards.join("\n"))).unwrap();
    std::fs::copy(src.join("free_plate_0001.rad"), dir.join("rbody_0001.rad")).unwrap();
    let m = common::crashsim_json(&["check", deck.to_str().unwrap(), "--json"])["total_mass"]
        .as_f64()
        .unwrap();
    assert!((m - PLATE_AND_BODY_MASS).abs() < 1e-12, "total mass {m}");
    let fs = dir.join("final.csv");
    let out = common::crashsim(&[
        "run",
        deck.to_str().unwrap(),
        "--out",
        dir.to_str().unwrap(),
        "--quiet",
        "--final-state",
        fs.to_str().unwrap(),
        "--energies",
        dir.join("energies.csv").to_str().unwrap(),
    ]);
    common::ok(&out, "run");
    std::fs::read_to_string(&fs)
        .unwrap()
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|s| s.parse().unwrap()).collect())
        .collect()
}

/// The plate's nodes and the card's MASS.
const PLATE_AND_BODY_MASS: f64 = 0.03768 + 0.5;

/// A constant /CLOAD of 2 along x on the main node only: the load acts on
/// the body, as in Radioss, so every node moves at v = F t / m (m: the
/// plate, its nodes and the card's mass).
#[test]
fn a_load_on_a_rigid_bodys_main_node_accelerates_the_body() {
    let rows = rigid_plate_with(
        "rbody-cload",
        &[
            "/CLOAD/9",
            "pull along x",
            "         3         X         0         0         8                             1                   2",
        ],
    );
    // Velocities live at the half step: the last one is v(t_end - dt/2), dt ~ 1.7e-3 ms.
    let expected = 2.0 / PLATE_AND_BODY_MASS * 0.5;
    for c in rows {
        assert!(
            (c[4] - expected).abs() < 5e-3 * expected,
            "node {}: vx {} against F t / m = {expected}",
            c[0],
            c[4]
        );
        assert!(
            c[5].abs() < 1e-12 * expected && c[6].abs() < 1e-12 * expected,
            "{c:?}"
        );
    }
}

/// The same rigid plate with, on its main node only: a /CLOAD of 2 along x
/// and of 5 along y, a /BCS fixing y and the rotations, and an /IMPVEL of
/// 0.3 along z. They act on the body, as in Radioss: every node moves at
/// vx = F t / m, vy = 0 (the y load is held), vz = 0.3.
#[test]
fn boundary_conditions_and_imposed_velocity_on_a_rigid_bodys_main_node_hold_the_body() {
    let rows = rigid_plate_with(
        "rbody-bcs-impvel",
        &[
            "/CLOAD/9",
            "pull along x",
            "         3         X         0         0         8                             1                   2",
            "/CLOAD/10",
            "pull along y, held by the BCS",
            "         3         Y         0         0         8                             1                   5",
            "/BCS/11",
            "main node: y and the rotations fixed",
            "   010 111         0         8",
            "/IMPVEL/12",
            "main node: z velocity",
            "         3         Z         0         0         8         0         0",
            "                   1                 0.3                   0                   0",
        ],
    );
    let expected = 2.0 / PLATE_AND_BODY_MASS * 0.5;
    for c in rows {
        assert!(
            (c[4] - expected).abs() < 5e-3 * expected,
            "node {}: vx {} against F t / m = {expected}",
            c[0],
            c[4]
        );
        assert!(c[5].abs() < 1e-12, "node {}: vy {} (held)", c[0], c[5]);
        assert!(
            (c[6] - 0.3).abs() < 1e-12,
            "node {}: vz {} (imposed 0.3)",
            c[0],
            c[6]
        );
    }
}

/// The same rigid plate with an /IMPDISP along z on its main node only
/// (u = 0.3 t through a ramp): it moves the body, as in Radioss — every
/// node ends at z = 0.3 t_end with vz = 0.3 (before, the displacement was
/// imposed on the main node alone and the body never followed it).
#[test]
fn imposed_displacement_on_a_rigid_bodys_main_node_moves_the_body() {
    let rows = rigid_plate_with(
        "rbody-impdisp",
        &[
            "/FUNCT/4",
            "ramp",
            "                   0                   0",
            "                  10                  10",
            "/IMPDISP/12",
            "main node: z displacement",
            "         4         Z         0         0         8         0         0",
            "                   1                 0.3                   0                   0",
        ],
    );
    for c in rows {
        assert!(
            (c[6] - 0.3).abs() < 1e-9,
            "node {}: vz {} (0.3)",
            c[0],
            c[6]
        );
        assert!(
            (c[3] - 0.15).abs() < 0.3 * 2e-3, // the run ends within a step (~1.7e-3) past 0.5
            "node {}: z {} (0.3 t_end = 0.15)",
            c[0],
            c[3]
        );
    }
}

/// An initial spin on a rigid body's main node only (/INIVEL/ROT, ω_z =
/// 0.01) spins the body: the main node
/// carries the card's inertia J = 1e6 and its /INIVEL/ROT: the body spins at
/// that ω, every node moving at |v| = ω·|r − c| to 1e-4 (the reference
/// engine starts OPTIONS_frame_or_skew_MOV_frame so: K-ENERGY R ½Jω² at
/// cycle 0, no external work). Without card inertia the body spins at the
/// main node's ω all the same (the reference's RESSORT_kjoint2).
#[test]
fn an_initial_spin_on_a_rigid_bodys_main_node_spins_the_body() {
    let omega = 0.01;
    let spin = [
        "/INIVEL/ROT/9",
        "spin about z",
        "                   0                   0                0.01         8         0",
    ];
    let rows = rigid_plate_inertia("rbody-inivel-rot", 1e6, &spin);
    let mut checked = 0;
    for c in rows {
        let r = ((c[1] - 40.0).powi(2) + (c[2] - 30.0).powi(2)).sqrt();
        let speed = (c[4] * c[4] + c[5] * c[5] + c[6] * c[6]).sqrt();
        if r > 1.0 {
            assert!(
                (speed - omega * r).abs() < 1e-4 * omega * r,
                "node {}: speed {speed} at r = {r}, expected ω r = {}",
                c[0],
                omega * r
            );
            checked += 1;
        }
    }
    assert!(checked > 10, "{checked} nodes checked");
    // Without any card inertia the main node's spin is still the body's, as
    // in the reference (QA RESSORT_kjoint2's rb2, K-ENERGY R = ½·I·ω²).
    for c in rigid_plate_with("rbody-inivel-rot-0", &spin) {
        let r = ((c[1] - 40.0).powi(2) + (c[2] - 30.0).powi(2)).sqrt();
        let speed = (c[4] * c[4] + c[5] * c[5] + c[6] * c[6]).sqrt();
        assert!(
            (speed - omega * r).abs() < 1e-4 * omega * r.max(1.0),
            "node {}",
            c[0]
        );
    }
}

/// A spinning rigid body's kinetic energy is its main node's, as the
/// reference lists it: K-ENERGY T ½Mv² of its centre (0 here) and K-ENERGY R
/// ½ωᵀJω with the inertia its motion uses (ISPHER 1: the trace over 3), its
/// nodes not counted again (QA RESSORT_kjoint2: K-ENERGY R 33.54). Free
/// spin about a principal axis: both stay as they started.
#[test]
fn a_spinning_rigid_bodys_energy_is_its_own_not_its_nodes() {
    let spin = [
        "/INIVEL/ROT/9",
        "spin about z",
        "                   0                   0                0.01         8         0",
    ];
    let tag = "rbody-spin-energy";
    rigid_plate_body(tag, 0.0, 1, &spin);
    let (head, rows) = common::read_csv(&tmp(tag).join("energies.csv"));
    let col = |name: &str| head.iter().position(|h| h == name).unwrap();
    let (kin, rot) = (col("kinetic"), col("rotational"));
    let r0 = rows[0][rot];
    assert!(r0 > 0.0, "rotational energy {r0}");
    for r in &rows {
        assert!(
            r[kin].abs() <= 1e-12 * r0,
            "the nodes' spin counted as translational energy: {r:?}"
        );
        assert!(
            (r[rot] - r0).abs() <= 1e-9 * r0,
            "rotational {} vs {r0}",
            r[rot]
        );
    }
}
