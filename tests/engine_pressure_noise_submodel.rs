//! /PLOAD, /RANDOM, //SUBMODEL and the rigid-body nodal step, on
//! `decks/free_plate` (an 80 × 60 steel plate of 10 mm squares, t = 1 mm,
//! ρ = 7.85e-6, in the z = 0 plane, its shells' normals along +z):
//! * a constant pressure p on every shell of the free plate gives every node
//!   the acceleration p/(ρt) along +N (its lumped share of p·A over its
//!   lumped share of ρtA): the plate flies flat at v = p·T/(ρt), the
//!   external work equals the kinetic energy, and 1 and 2 ranks (a cut
//!   through the loaded surface) end byte-identical;
//! * /RANDOM (/RANDOM/0: no unit system of its own) inside a //SUBMODEL moves every node, in reading order, x then
//!   y then z, by Xalea·r with r the reference starter's 16-bit generator;
//!   id offsets and a missing //ENDSUB are errors at their line;
//! * /DT/NODA/CST with a rigid body of the plate's first column of squares:
//!   those squares give no stiffness, the body steps at its main node with
//!   ΔTsca·min(√(2M/ΣK), √(2·I_min/Σ(K_rot + d²K))).

mod common;
use common::*;
use std::path::{Path, PathBuf};

const E: f64 = 210.0;
const NU: f64 = 0.3;
const RHO: f64 = 7.85e-6;
const T: f64 = 1.0;

/// The plate deck without its initial velocity, `cards` added (wrapped in
/// `wrap` before and after), and an engine file ending at `end` with
/// `engine` cards.
fn plate_deck(tag: &str, cards: &[String], end: f64, engine: &[&str]) -> PathBuf {
    let src = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("decks/free_plate");
    let starter = std::fs::read_to_string(src.join("free_plate_0000.rad")).unwrap();
    let head = &starter[..starter.find("/INIVEL/TRA/1").unwrap()];
    let dir = scratch(tag);
    let deck = dir.join("plate_0000.rad");
    std::fs::write(&deck, format!("{head}{}\n/END\n", cards.join("\n"))).unwrap();
    let run = [
        "/RUN/plate/1".to_string(),
        format!("{end:>20}"),
        "/PRINT/-1/55".into(),
    ];
    let engine: Vec<String> = engine.iter().map(|s| s.to_string()).collect();
    std::fs::write(
        dir.join("plate_0001.rad"),
        [&run[..], &engine[..]].concat().join("\n") + "\n",
    )
    .unwrap();
    deck
}

fn run_plate(deck: &Path, ranks: u32, tag: &str) -> (String, Vec<Vec<f64>>) {
    let dir = deck.parent().unwrap().join(format!("r{ranks}"));
    std::fs::create_dir_all(&dir).unwrap();
    let fs = dir.join("final.csv");
    let args = [
        "run",
        deck.to_str().unwrap(),
        "--out",
        dir.to_str().unwrap(),
        "--final-state",
        fs.to_str().unwrap(),
        "--quiet",
    ];
    let out = if ranks == 1 {
        crashsim(&args)
    } else {
        mpirun(ranks, &args)
    };
    ok(&out, tag);
    let (_, state) = read_csv(&fs);
    (String::from_utf8_lossy(&out.stdout).into_owned(), state)
}

/// (time, step, what, id, I-ENERGY, K-ENERGY T, EXT-WORK) rows of the cycle table.
fn rows(text: &str) -> Vec<(f64, f64, String, u64, f64, f64, f64)> {
    cycle_table(text)
        .iter()
        .map(|t| {
            let n = |i: usize| num(t[i]);
            (n(1), n(2), t[3].to_string(), n(4) as u64, n(6), n(7), n(9))
        })
        .collect()
}

#[test]
fn a_pressure_pushes_a_free_plate_at_p_over_rho_t() {
    let p = 1e-3;
    let end = 0.5;
    let cards = [
        "/PLOAD/1".to_string(),
        "pressure on the whole plate".into(),
        format!("{:>10}{:>10}", 7, 8),
        "/SURF/PART/7".into(),
        "plate".into(),
        format!("{:>10}", 1),
        "/FUNCT/8".into(),
        "constant".into(),
        format!("{:>20}{:>20}", 0, p),
        format!("{:>20}{:>20}", 10, p),
    ];
    let deck = plate_deck("pload", &cards, end, &["/DT", "0.9 0.0"]);
    let (text, one) = run_plate(&deck, 1, "pload 1 rank");
    let r = rows(&text);
    let last = r.last().unwrap();
    // Leapfrog under a constant acceleration a = p/(ρt): every node has the
    // same velocity, a·t within the last step of the end time.
    let (t_end, dt) = (last.0, last.1);
    let a = p / (RHO * T);
    let v = one[0][6];
    assert!(
        (v - a * t_end).abs() <= a * dt,
        "v {v} against a·t {}",
        a * t_end
    );
    for n in &one {
        assert!(
            (n[6] - v).abs() < 1e-12 * v && n[4].abs() < 1e-12 * v && n[5].abs() < 1e-12 * v,
            "node {} velocity {:?} against (0, 0, {v})",
            n[0],
            &n[4..7]
        );
    }
    let v = a * t_end;
    // EXT-WORK counts f^n·v^{n+½}Δt: the kinetic energy at t^n plus half a
    // step's share; the internal energy stays nil.
    let ke = 0.5 * RHO * T * 80.0 * 60.0 * v * v;
    assert!(
        (last.5 - ke).abs() < 2e-3 * ke,
        "K-ENERGY T {} against {ke}",
        last.5
    );
    assert!(
        (last.6 - last.5).abs() < 2e-3 * ke,
        "EXT-WORK {} against K-ENERGY T {}",
        last.6,
        last.5
    );
    assert!(last.4.abs() < 1e-9 * ke, "I-ENERGY {}", last.4);
    let (_, two) = run_plate(&deck, 2, "pload 2 ranks");
    assert_eq!(one, two, "1 and 2 ranks differ");
}

/// The reference starter's generator, written again from its definition.
fn noise(count: usize, xalea: f64) -> Vec<f64> {
    let mut i: i64 = 0;
    (0..count)
        .map(|_| {
            i = (25173 * i + 13849) % 65536;
            xalea * (i - 32768) as f64 / 32768.0
        })
        .collect()
}

#[test]
fn random_noise_in_a_submodel_moves_the_nodes_as_the_reference_starter() {
    let xalea = 0.01;
    // The plate's blocks after /BEGIN go inside a submodel; /RANDOM before it.
    let src = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("decks/free_plate");
    let starter = std::fs::read_to_string(src.join("free_plate_0000.rad")).unwrap();
    let start = starter.find("/MAT/LAW1/1").unwrap();
    let stop = starter.find("/INIVEL/TRA/1").unwrap();
    let write = |tag: &str, offsets: &str, close: bool| -> PathBuf {
        let dir = scratch(tag);
        let body = format!(
            "{}/RANDOM/0\n{xalea:>20}\n//SUBMODEL/1\nthe plate\n{offsets}\n{}{}/END\n",
            &starter[..start],
            &starter[start..stop],
            if close { "//ENDSUB\n" } else { "" }
        );
        std::fs::write(dir.join("plate_0000.rad"), body).unwrap();
        std::fs::write(
            dir.join("plate_0001.rad"),
            "/RUN/plate/1\n                1e-9\n/PRINT/-1/55\n",
        )
        .unwrap();
        dir.join("plate_0000.rad")
    };
    let deck = write("random-submodel", "", true);
    let (_, state) = run_plate(&deck, 1, "random noise");
    let ids: Vec<f64> = state.iter().map(|n| n[0]).collect();
    let r = noise(3 * state.len(), xalea);
    // The deck lists its nodes by ascending id: reading order = id order.
    assert!(ids.windows(2).all(|w| w[0] < w[1]));
    for (k, n) in state.iter().enumerate() {
        let id = n[0] as usize - 1;
        let (col, row) = (id % 9, id / 9);
        let x0 = [10.0 * col as f64, 10.0 * row as f64, 0.0];
        for d in 0..3 {
            let want = x0[d] + r[3 * k + d];
            assert!(
                (n[1 + d] - want).abs() < 1e-12,
                "node {} coordinate {d}: {} against {want}",
                n[0],
                n[1 + d]
            );
        }
    }
    // Id offsets would renumber the submodel: refused at their field.
    let bad = write("submodel-offsets", &format!("{:>10}{:>10}", 0, 1000), true);
    let out = crashsim(&["check", bad.to_str().unwrap()]);
    let said = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{said}");
    assert!(
        said.contains("plate_0000.rad:") && said.contains("off_nod"),
        "{said}"
    );
    // A submodel without //ENDSUB: an error at its //SUBMODEL line.
    let open = write("submodel-open", "", false);
    let out = crashsim(&["check", open.to_str().unwrap()]);
    let said = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{said}");
    assert!(said.contains("no //ENDSUB"), "{said}");
}

#[test]
fn a_rigid_body_steps_at_its_main_node_with_its_secondary_stiffness() {
    // The first column of squares (x = 0 and x = 10, 14 nodes) is rigid,
    // main node 100 (moved to the centre of mass, x = 20/3, y = 30).
    let col: Vec<String> = (0..7)
        .flat_map(|row| [9 * row + 1, 9 * row + 2])
        .map(|id| format!("{id:>10}"))
        .collect();
    let cards = [
        "/NODE".to_string(),
        format!("{:>10}{:>20}{:>20}{:>20}", 100, 5, 30, 0),
        "/RBODY/1".into(),
        "first column".into(),
        format!("{:>10}{:>10}{:>10}{:>10}{:>20}{:>10}", 100, 0, 0, 0, 0, 5),
        String::new(),
        String::new(),
        "/GRNOD/NODE/5".into(),
        "first column".into(),
        col[..7].join(""),
        col[7..].join(""),
    ];
    let deck = plate_deck("rbody-noda", &cards, 0.01, &["/DT/NODA/CST/0", "0.9 1e-6"]);
    let info = crashsim_json(&["check", deck.to_str().unwrap(), "--json"]);
    let body = &info["rigid_body_details"][0];
    let mass = body["mass"].as_f64().unwrap();
    let j: Vec<f64> = (0..6)
        .map(|k| body["inertia"][k].as_f64().unwrap())
        .collect();
    // By symmetry the products vanish: the principal inertias are the diagonal.
    assert!(j[3..].iter().all(|p| p.abs() < 1e-12 * j[2]), "{j:?}");
    let i_min = j[0].min(j[1]).min(j[2]);
    let c: Vec<f64> = (0..3)
        .map(|k| body["center"][k].as_f64().unwrap())
        .collect();
    // Active squares give each corner K = E t/(2(1 − ν²)); only the
    // x = 10 nodes touch them (twice inside the edge, once at its ends).
    let k_half = E * T / (1.0 - NU * NU) * 0.5;
    let mut sum_k = 0.0;
    let mut sum_kr = 0.0;
    for row in 0..7 {
        let y = 10.0 * row as f64;
        let k = if row == 0 || row == 6 {
            k_half
        } else {
            2.0 * k_half
        };
        let d2 = (10.0 - c[0]).powi(2) + (y - c[1]).powi(2) + c[2] * c[2];
        sum_k += k;
        sum_kr += k * (T * T / 12.0 + 100.0 / 9.0) + d2 * k;
    }
    let want = 0.9
        * (2.0 * mass / sum_k)
            .sqrt()
            .min((2.0 * i_min / sum_kr).sqrt());
    // The plate's own nodes step at 0.9·√(2ρtA/(E t A/(1 − ν²)))·… = larger.
    let plate = 0.9 * (2.0 * RHO * T * 25.0 / k_half).sqrt();
    assert!(want < plate, "the body must lead: {want} against {plate}");
    let (text, _) = run_plate(&deck, 1, "rigid body nodal step");
    let first = &rows(&text)[0];
    assert_eq!((first.2.as_str(), first.3), ("NODE", 100), "{first:?}");
    assert!(
        (first.1 - want).abs() < 1e-4 * want,
        "step {} against {want}",
        first.1
    );
    // The body's nodes: 25 + 50·5 + 25 and 50 + 100·5 + 50 quarter squares.
    assert!((mass - 900.0 * RHO * T).abs() < 1e-12, "{mass}");
}
