//! /INTER/TYPE2 (tied interface, standard kinematic formulation) on the decks
//! of decks/make_tied.py: a steel strip L = 100, W = 10, t = 1 (kg, mm, ms)
//! made of two non-matching shell meshes (10 x 3 and 10 x 2) tied along
//! x = 50, against the same strip meshed continuously (20 x 2):
//!
//! * bending (clamped, tip load, first peak at T1/2): the tip deflection of
//!   the tied strip is the continuous one's within 2 %, and far from the
//!   hinge a tie without rotations would make;
//! * pulling (ramped load, held): tip displacement within 2 % of the
//!   continuous strip and 5 % of P L / (E A);
//! * both: the tied nodes stay on their main segments to round-off;
//! * free flight with a tip load: momentum M v0 + P (t − Δt/2) to round-off,
//!   energy balance as closed as the continuous strip's, the same bytes on
//!   1, 2 and 4 ranks with the secondary and main nodes on different ranks;
//! * a shell plate tied onto a brick block (translation only: brick main
//!   nodes have no rotation): momentum and energy in flight, 1 = 2 ranks;
//! * every option the engine does not compute exits 2 naming its field.

#[path = "contact_common/mod.rs"]
mod cc;
mod common;

use cc::*;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

const E: f64 = 210.0;
const RHO: f64 = 7.85e-6;

/// Secondary nodes (fine edge at x = 50, y = 0, 10/3, 20/3, 10) and the
/// coarse edge's main nodes (y = 0, 5, 10).
const SEC: [u64; 4] = [11, 22, 33, 44];
const MAIN: [u64; 3] = [1001, 1012, 1023];
const TIP_TIED: u64 = 1022;
const TIP_CONT: u64 = 42;

fn state(name: &str, tag: &str, a: &RunArgs) -> (Run, BTreeMap<u64, [f64; 6]>) {
    let dir = scratch(&format!("tied-{tag}"));
    let r = run(&deck(name), &dir, a);
    let s = r.final_state();
    (r, s)
}

/// Each secondary node lies where its shape functions put it on the main edge:
/// x_s = (1 − η) x_a + η x_b, η its initial fraction along the edge.
fn assert_on_segments(s: &BTreeMap<u64, [f64; 6]>) {
    for (j, &n) in SEC.iter().enumerate() {
        let y0 = 10.0 * j as f64 / 3.0;
        let (a, b, eta) = if y0 <= 5.0 {
            (MAIN[0], MAIN[1], y0 / 5.0)
        } else {
            (MAIN[1], MAIN[2], (y0 - 5.0) / 5.0)
        };
        for k in 0..3 {
            let want = (1.0 - eta) * s[&a][k] + eta * s[&b][k];
            let got = s[&n][k];
            assert!(
                (got - want).abs() < 1e-11 * (1.0 + want.abs()),
                "node {n} component {k}: {got} off its segment ({want})"
            );
            // Velocities too.
            let want_v = (1.0 - eta) * s[&a][3 + k] + eta * s[&b][3 + k];
            assert!((s[&n][3 + k] - want_v).abs() < 1e-12 * (1.0 + want_v.abs()));
        }
    }
}

#[test]
fn a_tied_bent_strip_deflects_as_the_continuous_one_not_as_a_hinge() {
    let (r, tied) = state("tied_bend", "bend", &RunArgs::default());
    let (_, cont) = state("cont_bend", "bend-c", &RunArgs::default());
    let wt = tied[&TIP_TIED][2];
    let wc = cont[&TIP_CONT][2];
    let ratio = wt / wc;
    eprintln!("bending: tip w tied {wt:.6e}, continuous {wc:.6e}, ratio {ratio:.5}");
    assert!((ratio - 1.0).abs() < 0.02, "ratio {ratio}");
    // A tie without rotations is a hinge at x = 50: the outer half (mass m2,
    // length a) turns about it under P, w_tip ≈ ½·(3P/m2)·t² at t = 5.984.
    let m2 = RHO * 1.0 * 10.0 * 50.0;
    let hinge = 0.5 * 3.0 * 5.25e-5 / m2 * 5.984f64.powi(2);
    eprintln!(
        "bending: a hinge would give ~{hinge:.4} mm ({:.1} x)",
        hinge / wc
    );
    assert!(hinge > 3.0 * wt);
    // The statics: first peak ~2x the static P L³/(3EI) = 0.1 mm.
    assert!(wt > 0.17 && wt < 0.22, "{wt}");
    assert_on_segments(&tied);
    // The joint rotates with the main edge: secondary rotations interpolated.
    let txt = std::fs::read_to_string(r.dir.join("final_state.csv")).unwrap();
    let rows: BTreeMap<u64, Vec<f64>> = txt
        .lines()
        .skip(1)
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
            (v[0] as u64, v[7..10].to_vec())
        })
        .collect();
    let wy = (rows[&MAIN[0]][1] + rows[&MAIN[1]][1]) / 2.0;
    assert!(wy.abs() > 0.0);
    let w22 = rows[&22][1];
    let want = rows[&MAIN[0]][1] / 3.0 + 2.0 * rows[&MAIN[1]][1] / 3.0;
    assert!(
        (w22 - want).abs() < 1e-12 * (1.0 + want.abs()),
        "{w22} vs {want}"
    );
    // The listing names the interface.
    assert!(r
        .listing
        .text
        .contains("/INTER/TYPE2/1: 4 secondary nodes tied"));
    assert!(r
        .listing
        .text
        .contains("INTER        1 TYPE2  TIED NODES      4"));
}

#[test]
fn a_tied_pulled_strip_stretches_as_the_continuous_one() {
    let (_, tied) = state("tied_pull", "pull", &RunArgs::default());
    let (_, cont) = state("cont_pull", "pull-c", &RunArgs::default());
    let ut = tied[&TIP_TIED][0] - 100.0;
    let uc = cont[&TIP_CONT][0] - 100.0;
    let stat = 0.21 * 100.0 / (E * 10.0);
    eprintln!(
        "pull: tip u tied {ut:.6e}, continuous {uc:.6e}, ratio {:.5}, static {stat:.4e}",
        ut / uc
    );
    assert!((ut / uc - 1.0).abs() < 0.02);
    assert!((ut / stat - 1.0).abs() < 0.05);
    assert_on_segments(&tied);
}

/// Σ m v with the lumped masses of the deck (the secondary nodes' own masses).
fn momentum(deck: &Path, s: &BTreeMap<u64, [f64; 6]>) -> ([f64; 3], f64) {
    let m = shell_masses(&read_mesh(deck), RHO, 1.0, &[]);
    let mut p = [0.0; 3];
    let mut total = 0.0;
    for (id, mi) in &m {
        total += mi;
        for k in 0..3 {
            p[k] += mi * s[id][3 + k];
        }
    }
    (p, total)
}

#[test]
fn a_flying_tied_strip_keeps_momentum_and_energy_and_bytes_on_1_2_4_ranks() {
    let d = deck("tied_free");
    let a = RunArgs {
        energies: true,
        ..Default::default()
    };
    let (r1, s1) = state("tied_free", "free1", &a);
    // Momentum: M v0 + P (t_N − Δt_N/2) (the last half step), to round-off.
    let (_, rows) = r1.energies();
    let n = rows.len();
    let t_end = rows[n - 1][0];
    let dt_last = rows[n - 1][0] - rows[n - 2][0];
    let (p, mtot) = momentum(&d, &s1);
    let want = [
        mtot * 1.0,
        0.0,
        mtot * 0.5 + 5.25e-3 * (t_end - 0.5 * dt_last),
    ];
    let err = (0..3)
        .map(|k| (p[k] - want[k]).abs())
        .fold(0.0f64, f64::max)
        / (mtot * 1.0);
    eprintln!(
        "free flight: momentum {p:?}, expected {want:?}, error {err:.2e} (relative to M·|v0x|)"
    );
    assert!(err < 1e-12, "momentum error {err}");
    // Energy balance: internal + hourglass + kinetic − initial kinetic − external work,
    // against the continuous strip in the same flight.
    let balance = |rows: &Vec<Vec<f64>>| {
        let l = rows.last().unwrap();
        let ke0 = 0.5 * mtot * (1.0 + 0.25);
        (l[3] + l[8] + l[4] + l[5] - ke0 - l[6]) / l[6]
    };
    let bt = balance(&rows);
    let (rc, _) = state("cont_free", "free-c", &a);
    let bc = balance(&rc.energies().1);
    eprintln!(
        "free flight: energy balance tied {bt:.3e}, continuous {bc:.3e} (of the external work)"
    );
    assert!(bt.abs() < 1e-3 && bt.abs() <= 2.0 * bc.abs() + 1e-5);
    // The partition puts the secondary and main nodes on different ranks.
    let part = common::crashsim_json(&["partition", d.to_str().unwrap(), "--np", "2", "--json"]);
    let it = &part["interfaces"][0];
    assert_eq!(it["type"], 2);
    assert_ne!(it["main_ranks"], it["secondary_ranks"], "{it}");
    let b1 = r1.final_state_bytes();
    for np in [2u32, 4] {
        let rn = run(
            &d,
            &scratch(&format!("tied-free{np}")),
            &RunArgs {
                ranks: np,
                ..Default::default()
            },
        );
        assert!(rn.final_state_bytes() == b1, "{np} ranks differ from 1");
    }
}

/// A copy of tied_bend with its starter text changed by `edit`.
fn variant(tag: &str, edit: &dyn Fn(String) -> String) -> PathBuf {
    let src = deck("tied_bend");
    let dir = scratch(&format!("tied-refuse-{tag}"));
    let text = std::fs::read_to_string(&src).unwrap();
    let new = edit(text.clone());
    assert_ne!(new, text, "{tag}: the edit changed nothing");
    let p = dir.join("tied_bend_0000.rad");
    std::fs::write(&p, new).unwrap();
    std::fs::copy(
        src.with_file_name("tied_bend_0001.rad"),
        dir.join("tied_bend_0001.rad"),
    )
    .unwrap();
    p
}

const CARD: &str = "        10        20         0         0         0         0         0         0                   0";

fn card(ignore: i64, spot: i64, level: i64, isearch: i64, idel2: i64) -> String {
    format!(
        "{:>10}{:>10}{ignore:>10}{spot:>10}{level:>10}{isearch:>10}{idel2:>10}{:>10}{:>20}",
        10, 20, 0, 0
    )
}

fn refused(deck: &Path, expect: &[&str]) {
    let out = common::crashsim(&[
        "run",
        deck.to_str().unwrap(),
        "--out",
        deck.parent().unwrap().join("out").to_str().unwrap(),
    ]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{expect:?}: stderr {err}");
    for e in expect {
        assert!(err.contains(e), "stderr lacks '{e}': {err}");
    }
    assert!(!err.contains("panicked"));
}

#[test]
fn type2_options_the_engine_does_not_compute_are_refused_by_field() {
    let with = |c: String| move |t: String| t.replace(CARD, &c);
    for (tag, c, field) in [
        ("spot1", card(0, 1, 0, 0, 0), "Spotflag = 1"),
        ("spot2", card(0, 2, 0, 0, 0), "Spotflag = 2"),
        ("spot4", card(0, 4, 0, 0, 0), "Spotflag = 4"),
        ("spot30", card(0, 30, 0, 0, 0), "Spotflag = 30"),
        ("level", card(0, 0, 1, 0, 0), "field Level"),
        ("isearch", card(0, 0, 0, 1, 0), "field Isearch"),
        ("idel2", card(0, 0, 0, 0, 2), "field Idel2"),
        ("ignore2", card(2, 0, 0, 0, 0), "field Ignore"),
    ] {
        let d = variant(tag, &with(c));
        refused(
            &d,
            &[
                "tied_bend_0000.rad:",
                "/INTER/TYPE2/1",
                field,
                "not supported by the engine yet",
            ],
        );
    }
    // The penalty formulation (with its card) and heat transfer.
    let d = variant("spot25", &|t: String| {
        t.replace(
            CARD,
            &(card(0, 25, 0, 0, 0)
                + "\n                   0                   0                             0"),
        )
    });
    refused(
        &d,
        &["/INTER/TYPE2/1", "field Spotflag", "Spotflag = 25 (penalty"],
    );
    let d = variant("ithe", &|t: String| {
        t.replace(CARD, &format!("{CARD}\n         1                   1"))
    });
    refused(&d, &["/INTER/TYPE2/1", "field Ithe", "heat transfer"]);
    // Conflicting kinematic conditions on a secondary node.
    let d = variant("bcs", &|t: String| {
        t.replace("/END", "/BCS/9\nconflict\n#  Tra rot   skew_ID  grnod_ID\n   100 000         0        10\n/END")
    });
    refused(
        &d,
        &["/INTER/TYPE2/1", "grnd_IDs", "secondary node 11", "/BCS/9"],
    );
    // A node tied twice.
    let d = variant("twice", &|t: String| {
        t.replace("/END", "/INTER/TYPE2/2\nagain\n        10        20\n/END")
    });
    refused(
        &d,
        &[
            "/INTER/TYPE2/2",
            "grnd_IDs",
            "already a secondary node of /INTER/TYPE2/1",
        ],
    );
    // A secondary node on its own main surface.
    let d = variant("self", &|t: String| {
        t.replace(
            "/END",
            "/GRNOD/NODE/16\nmain node\n      1001\n/INTER/TYPE2/3\nself\n        16        20\n/END",
        )
    });
    refused(
        &d,
        &[
            "/INTER/TYPE2/3",
            "grnd_IDs",
            "node 1001 is both a secondary node",
        ],
    );
}

#[test]
fn a_shell_plate_tied_onto_a_brick_block_flies_with_its_momentum_and_energy() {
    // Main nodes on bricks carry no rotation: only the translation is tied,
    // the plate nodes keep their own rotations.
    let d = deck("tied_plate_block");
    let a = RunArgs {
        energies: true,
        ..Default::default()
    };
    let (r1, s1) = state("tied_plate_block", "pb1", &a);
    assert!(r1.listing.text.contains(
        "28 secondary nodes tied (Spotflag 5, standard kinematic formulation), 0 with rotations"
    ));
    let (_, rows) = r1.energies();
    let n = rows.len();
    let t_end = rows[n - 1][0];
    let dt_last = rows[n - 1][0] - rows[n - 2][0];
    let mesh = read_mesh(&d);
    let mut m = shell_masses(&mesh, RHO, 1.0, &[1]);
    for (id, mi) in brick_masses(&mesh, RHO, &[2]) {
        *m.entry(id).or_insert(0.0) += mi;
    }
    let mut p = [0.0; 3];
    let mut mtot = 0.0;
    for (id, mi) in &m {
        mtot += mi;
        for k in 0..3 {
            p[k] += mi * s1[id][3 + k];
        }
    }
    let want = [mtot, 0.0, 0.5 * mtot + 5.25e-3 * (t_end - 0.5 * dt_last)];
    let err = (0..3)
        .map(|k| (p[k] - want[k]).abs())
        .fold(0.0f64, f64::max)
        / mtot;
    eprintln!("plate on block: momentum error {err:.2e}");
    assert!(err < 1e-12, "momentum error {err}");
    let l = rows.last().unwrap();
    let bal = (l[3] + l[8] + l[4] + l[5] - 0.5 * mtot * 1.25 - l[6]) / l[6];
    eprintln!("plate on block: energy balance {bal:.3e} of the external work");
    assert!(bal.abs() < 2e-3, "{bal}");
    // Secondary (plate) and main (block) nodes partly on different ranks.
    let r2 = run(
        &d,
        &scratch("tied-pb2"),
        &RunArgs {
            ranks: 2,
            ..Default::default()
        },
    );
    assert!(
        r2.final_state_bytes() == r1.final_state_bytes(),
        "2 ranks differ from 1"
    );
}
