//! /IMPDISP/FGEO with /MOVE_FUNCT, and the nodal time step /DT/NODA/CST,
//! on `decks/free_plate` (an 80 × 60 steel plate of 10 mm squares, t = 1):
//! * every node driven to a final geometry stretched 1% along x and lifted
//!   2 mm, by a ramp that /MOVE_FUNCT stretches to 0.25 ms: the nodes end
//!   exactly there, at rest, and the plate stores the membrane energy of
//!   ε_xx = ln 1.01 with ε_yy = 0, ½·E/(1 − ν²)·ε²·t·A;
//! * /DT/NODA/CST with ΔTmin above every node's own step: the step is
//!   ΔTmin, and the mass added is ½·ΣK·(ΔTmin/ΔTsca)²·1.00001 − M, each
//!   node's K the sum of its squares' E t/(2(1 − ν²)) (the half diagonal
//!   rule of a square).

mod common;
use common::*;
use std::path::{Path, PathBuf};

const E: f64 = 210.0;
const NU: f64 = 0.3;
const RHO: f64 = 7.85e-6;

/// (id, x, y, z) of the plate's nodes.
fn plate_nodes(starter: &str) -> Vec<(u64, [f64; 3])> {
    let body = &starter[starter.find("\n/NODE").unwrap()..starter.find("\n/SHELL/").unwrap()];
    body.lines()
        .skip(1)
        .filter_map(|l| {
            let t: Vec<f64> = l
                .split_whitespace()
                .filter_map(|w| w.parse().ok())
                .collect();
            (t.len() == 4).then(|| (t[0] as u64, [t[1], t[2], t[3]]))
        })
        .collect()
}

/// The plate deck without its initial velocity, `cards` added, and an
/// engine file with `engine` cards; returns the starter's path.
fn plate_deck(tag: &str, cards: &[String], engine: &[&str]) -> (PathBuf, Vec<(u64, [f64; 3])>) {
    let src = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("decks/free_plate");
    let starter = std::fs::read_to_string(src.join("free_plate_0000.rad")).unwrap();
    let nodes = plate_nodes(&starter);
    let head = &starter[..starter.find("/INIVEL/TRA/1").unwrap()];
    let dir = scratch(tag);
    let deck = dir.join("plate_0000.rad");
    std::fs::write(&deck, format!("{head}{}\n/END\n", cards.join("\n"))).unwrap();
    let run = [
        "/RUN/plate/1",
        "                 0.5",
        "/DT",
        "0.9 0.0",
        "/PRINT/-1/55",
    ];
    std::fs::write(
        dir.join("plate_0001.rad"),
        [&run[..], engine].concat().join("\n") + "\n",
    )
    .unwrap();
    (deck, nodes)
}

/// (time, step, what, I-ENERGY, K-ENERGY T, EXT-WORK, MASS ADDED) rows of the cycle table.
fn rows(text: &str) -> Vec<(f64, f64, String, f64, f64, f64, f64)> {
    cycle_table(text)
        .iter()
        .map(|t| {
            let n = |i: usize| num(t[i]);
            (n(1), n(2), t[3].to_string(), n(6), n(7), n(9), n(12))
        })
        .collect()
}

fn run(deck: &Path, tag: &str) -> (String, Vec<Vec<f64>>) {
    let dir = deck.parent().unwrap();
    let fs = dir.join("final.csv");
    let out = crashsim(&[
        "run",
        deck.to_str().unwrap(),
        "--out",
        dir.to_str().unwrap(),
        "--final-state",
        fs.to_str().unwrap(),
    ]);
    ok(&out, tag);
    let (_, state) = read_csv(&fs);
    (String::from_utf8_lossy(&out.stdout).into_owned(), state)
}

#[test]
fn nodes_reach_their_final_geometry_along_straight_lines() {
    let src = std::fs::read_to_string(
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("decks/free_plate/free_plate_0000.rad"),
    )
    .unwrap();
    let target = |p: [f64; 3]| [1.01 * p[0], p[1], p[2] + 2.0];
    let mut cards: Vec<String> = vec![
        "/FUNCT/5".into(),
        "ramp, stretched to 0.25 ms by /MOVE_FUNCT".into(),
        format!("{:>20}{:>20}", 0, 0),
        format!("{:>20}{:>20}", 1, 1),
        format!("{:>20}{:>20}", 4, 1),
        "/MOVE_FUNCT/5".into(),
        "time scale".into(),
        format!("{:>20}{:>20}", 0.25, 0),
        "/IMPDISP/FGEO/1".into(),
        "stretch and lift".into(),
        format!("{:>10}{:>10}{:>10}{:>10}", 5, 0, "", 0),
        format!("{:>20}{:>20}{:>20}{:>20}", 1, "", 0, 0),
    ];
    for (id, p) in plate_nodes(&src) {
        let q = target(p);
        cards.push(format!("{id:>10}{:>20}{:>20}{:>20}", q[0], q[1], q[2]));
    }
    let (deck, nodes) = plate_deck("fgeo", &cards, &[]);
    let (text, state) = run(&deck, "fgeo");
    // Final state: id, x, y, z, vx, vy, vz, ...
    assert_eq!(state.len(), nodes.len());
    for (row, (id, p)) in state.iter().zip(&nodes) {
        assert_eq!(row[0] as u64, *id);
        let q = target(*p);
        for k in 0..3 {
            assert!(
                (row[1 + k] - q[k]).abs() < 1e-9,
                "node {id}: {:?} against {q:?}",
                &row[1..4]
            );
            assert!(
                row[4 + k].abs() < 1e-9,
                "node {id} still moves: {:?}",
                &row[4..7]
            );
        }
    }
    let r = rows(&text);
    let last = r.last().unwrap();
    let eps = 1.01f64.ln();
    let expected = 0.5 * E / (1.0 - NU * NU) * eps * eps * 1.0 * 80.0 * 60.0;
    assert!(
        (last.3 - expected).abs() < 0.02 * expected,
        "I-ENERGY {} against {expected}",
        last.3
    );
    // The reactions' work is the energy the plate holds (at rest at the end).
    assert!(
        (last.5 - last.3).abs() < 0.01 * expected,
        "EXT-WORK {} against I-ENERGY {}",
        last.5,
        last.3
    );
}

/// The whole plate launched at (1, 0, 0.5).
fn flying_plate() -> [String; 6] {
    [
        "/INIVEL/TRA/1".to_string(),
        "whole plate".into(),
        format!("{:>20}{:>20}{:>20}{:>10}", 1, 0, 0.5, 1),
        "/GRNOD/PART/1".into(),
        "plate".into(),
        format!("{:>10}", 1),
    ]
}

#[test]
fn nodal_time_step_adds_the_mass_that_brings_every_node_to_the_minimum() {
    let cards = flying_plate();
    let (tmin, scale) = (3e-3, 0.9);
    let (deck, _) = plate_deck("nodal-cst", &cards, &["/DT/NODA/CST/0", "0.9 0.003"]);
    let (text, _) = run(&deck, "nodal-cst");
    let r = rows(&text);
    let a11 = E / (1.0 - NU * NU);
    // 48 squares, each K = A11 t /2 to its 4 corners.
    let sum_k = 48.0 * 4.0 * a11 * 0.5;
    let mass = RHO * 80.0 * 60.0;
    let added = 0.5 * sum_k * (tmin / scale) * (tmin / scale) * 1.00001 - mass;
    for row in &r {
        assert_eq!(row.2, "NODE", "{row:?}");
        assert!(
            (row.1 - tmin).abs() < 1e-5 * tmin,
            "step {} against ΔTmin {tmin}",
            row.1
        );
        assert!(
            (row.6 - added).abs() < 1e-3 * added,
            "MASS ADDED {} against {added}",
            row.6
        );
    }
    // The whole plate flies at its initial velocity: K-ENERGY T with the added mass.
    let ke = 0.5 * (mass + added) * (1.0 + 0.25);
    assert!(
        (r[1].4 - ke).abs() < 1e-3 * ke,
        "K-ENERGY T {} against {ke}",
        r[1].4
    );
}

/// /DT/NODA/0 (no action keyword): the step comes from the nodes, ΔTsca·√(2m/K)
/// (on the plate's squares √(100ρ/A11) at every node), and no mass is added
/// although ΔTmin is above it; /DT/BRICK/CST changes nothing in a model
/// without solids.
#[test]
fn plain_nodal_time_step_adds_no_mass() {
    let cards = flying_plate();
    let (deck, _) = plate_deck(
        "nodal-plain",
        &cards,
        &["/DT/NODA/0", "0.8 0.003", "/DT/BRICK/CST/0", "0.67 4e-4"],
    );
    let (text, _) = run(&deck, "nodal-plain");
    let want = 0.8 * (100.0 * RHO / (E / (1.0 - NU * NU))).sqrt();
    let r = rows(&text);
    assert!(r.len() > 10);
    for row in &r {
        assert_eq!(row.2, "NODE", "{row:?}");
        assert!(
            (row.1 - want).abs() < 5e-5 * want,
            "step {} against {want}",
            row.1
        );
        assert_eq!(row.6, 0.0, "MASS ADDED {}", row.6);
    }
}
