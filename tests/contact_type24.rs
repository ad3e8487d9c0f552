//! TYPE24 penalty node-to-surface contact on decks/make_type24.py's decks.
//!
//! - type24_plate: a block driven at 1 mm/ms onto a fixed 1 mm shell plate
//!   from 0.8 mm over its mid-plane. The gap is the plate's half thickness,
//!   0.5 mm, unscaled (TYPE24 forces Igap 1): no force before 0.3 ms, then
//!   F = 16 · ½K · v · (t − 0.3), K = E·t (Istf default: the main side's),
//!   the full stiffness from the impact on; with Gap_max_m = 0.2 the force
//!   starts at 0.6 ms. Byte-identical on 1, 2 and 4 ranks with the
//!   interface cut and on 2 threads.
//! - type24_block: a block starting 0.1 mm inside a fixed block. By default
//!   the reference flags such a node and gives it no force while it stays
//!   penetrated (i24pen3.F): no force. With Inacti = 5 the penetration is
//!   the baseline and only the further one pushes, F = 16 · ½K · v · t,
//!   K = B·A²/V.
//! - Options the engine does not compute are refused by name.

mod common;
#[path = "contact_common/mod.rs"]
mod contact_common;
use contact_common::*;
use std::path::PathBuf;

const NODES: f64 = 16.0;

/// ½K of a block node on the plate: E·t/2.
const HALF_K_PLATE: f64 = 0.5 * 210.0 * 1.0;

/// The variant of `name` whose card line `k` lines below the TYPE24 header
/// gets `text` in columns [a, b).
fn variant(name: &str, tag: &str, k: usize, a: usize, b: usize, text: &str) -> PathBuf {
    common::deck_variant(name, &scratch(tag), |i, lines| {
        (i >= k && lines[i - k].starts_with("/INTER/TYPE24/")).then(|| {
            format!(
                "{}{:>w$}{}",
                &lines[i][..a],
                text,
                &lines[i][b..],
                w = b - a
            )
        })
    })
}

/// Each printed force against 16·½K·v·(t − onset), within 1% plus a quarter
/// step's approach; none before the onset.
fn assert_plate_force(r: &Run, onset: f64) {
    assert_plate_force_at(r, onset, NODES * HALF_K_PLATE * 1.0);
}

/// Each printed force against slope·(t − onset), within 1% plus a quarter
/// step's approach; none before the onset.
fn assert_plate_force_at(r: &Run, onset: f64, slope: f64) {
    assert!(r.listing.normal_termination());
    let lines = r.listing.of(1);
    assert!(lines.len() >= 6, "INTER lines: {}", lines.len());
    let slack = slope * 1e-4;
    let mut touched = 0;
    for l in &lines {
        let expect = slope * (l.t - onset).max(0.0);
        let f = l.normal[2];
        assert!(
            (f - expect).abs() < 0.01 * expect + slack,
            "onset {onset}, t = {}: force {f}, expected {expect}",
            l.t
        );
        if l.t > onset + 1e-3 {
            assert_eq!(l.pairs, 16, "t = {}", l.t);
            touched += 1;
        } else if l.t < onset - 1e-3 {
            assert_eq!(l.pairs, 0, "t = {}", l.t);
        }
    }
    assert!(touched >= 2, "{touched} lines after the onset");
}

#[test]
fn a_block_meets_a_shell_plate_at_its_half_thickness_with_the_full_stiffness() {
    let r = run(
        &deck("type24_plate"),
        &scratch("type24_plate_1"),
        &RunArgs::default(),
    );
    assert_plate_force(&r, 0.3);
}

#[test]
fn gap_max_m_caps_the_plate_gap() {
    // Gap_max_m: columns 81-100 of card 2 (after the title, a comment,
    // card 1 and a comment: line 5 below the header).
    let d = variant(
        "type24_plate",
        "type24_plate_gapmax_deck",
        5,
        80,
        100,
        "0.2",
    );
    let r = run(&d, &scratch("type24_plate_gapmax"), &RunArgs::default());
    assert_plate_force(&r, 0.6);
}

#[test]
fn an_initial_penetration_pushes_only_with_inacti_5_and_then_only_beyond_it() {
    let half_k = {
        let b = 210.0 / (3.0 * (1.0 - 2.0 * 0.3));
        0.5 * b * 25.0 * 25.0 / 125.0
    };
    let r = run(
        &deck("type24_block"),
        &scratch("type24_block_1"),
        &RunArgs::default(),
    );
    assert!(r.listing.normal_termination());
    let lines = r.listing.of(1);
    assert!(lines.len() >= 4);
    assert!(lines.iter().all(|l| l.normal[2] == 0.0 && l.pairs == 0));
    // Inacti: columns 31-40 of card 5 (line 11 below the header).
    let d = variant("type24_block", "type24_block_inacti5_deck", 11, 30, 40, "5");
    let r = run(&d, &scratch("type24_block_inacti5"), &RunArgs::default());
    let lines = r.listing.of(1);
    assert!(lines.len() >= 4);
    for l in &lines {
        let expect = NODES * half_k * 0.01 * l.t;
        let f = l.normal[2];
        assert!(
            (f - expect).abs() < 0.01 * expect,
            "Inacti 5, t = {}: force {f}, expected {expect}",
            l.t
        );
        assert_eq!(l.pairs, 16);
    }
}

#[test]
fn type24_is_identical_on_1_2_4_ranks_and_2_threads_with_a_cut_interface() {
    let d = deck("type24_plate");
    for np in [2, 4] {
        let (sec, main) = interface_ranks(&d, np, 0);
        assert!(
            sec.iter().any(|r| !main.contains(r)),
            "{np} ranks: the interface is not cut: {sec:?} {main:?}"
        );
    }
    let one = run(&d, &scratch("type24_ranks_1"), &RunArgs::default());
    assert_same_final_state_on_ranks_and_2_threads(&d, "type24_ranks", &one, &[2, 4]);
}

#[test]
fn type24_options_the_engine_does_not_compute_are_refused_by_name() {
    // Iedge: columns 31-40 of card 2; Ipen_max: columns 61-80 of card 3.
    for (k, a, b, text, name) in [(5, 30, 40, "1", "Iedge"), (7, 60, 80, "0.5", "Ipen_max")] {
        let d = variant(
            "type24_plate",
            &format!("type24_refused_{name}"),
            k,
            a,
            b,
            text,
        );
        let out = common::crashsim(&[
            "run",
            d.to_str().unwrap(),
            "--out",
            d.parent().unwrap().to_str().unwrap(),
            "--quiet",
        ]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{name}: {err}");
        assert!(
            err.contains("/INTER/TYPE24/1") && err.contains(name) && err.contains("not supported"),
            "{name}: {err}"
        );
    }
}

/// Istf = 5 (type24_plate with the card's Istf rewritten): each pair's K is
/// the series of the plate's E·t and the block node's stiffness, which with
/// Istf > 1 is the reference starter's assembled nodal value
/// B·(2·V_n)^(1/3) (i24stslav.F I24STSECND; V_n the node's share of its
/// bricks, V/8 each): the block's corner, edge and inner bottom nodes (1, 2,
/// 4 bricks of 2.5 mm) get 276, 347 and 438. The force grows from 0.3 ms as
/// Σ ½K·v·(t − 0.3), within 1% plus a quarter step's approach, none before.
#[test]
fn istf_5_pairs_the_plate_with_the_assembled_node_stiffness() {
    let d = variant("type24_plate", "type24_plate_istf5_deck", 3, 20, 30, "5");
    let r = run(&d, &scratch("type24_plate_istf5"), &RunArgs::default());
    let b = 210.0 / (3.0 * (1.0 - 2.0 * 0.3));
    let km = 2.0 * HALF_K_PLATE;
    let ks = |bricks: f64| b * (2.0 * bricks * 2.5f64.powi(3) / 8.0).cbrt();
    let series = |k: f64| km * k / (km + k);
    let slope = 0.5 * (4.0 * series(ks(1.0)) + 8.0 * series(ks(2.0)) + 4.0 * series(ks(4.0)));
    assert_plate_force_at(&r, 0.3, slope);
}
