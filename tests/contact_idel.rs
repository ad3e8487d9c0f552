//! Contact node and segment deletion (Idel of /INTER/TYPE7) on the decks of
//! decks/make_idel.py (units kg, mm, ms, GPa):
//!
//! * idel_gap: a membrane plate held in z is torn open along a failing band of
//!   8 shells (deleted at about 0.1 ms); a steel cube moving at (5, 0, -2)
//!   reaches the plate's plane over the gap at about 0.5 ms. Interface 1: cube
//!   nodes on the plate; interface 2: plate nodes on the cube's bottom face.
//!   The 5 nodes of the band's middle line belong to band shells only.
//! * idel_layers: the same band doubled by a weak shell layer that never
//!   fails (not in the surface), interface 1 only.
//! * idel_gap_t5: idel_gap with interface 1 a TYPE5 (its card's Idel, 0 = no
//!   deletion), no interface 2.
//!
//! What shows each option: whether the cube goes through (its final velocity
//! is still exactly (5, 0, -2), its bottom below the plate) or is stopped (it
//! bounces: vz > 0), and the IDEL lines of the listing (segments and nodes
//! removed per interface).

#[path = "contact_common/mod.rs"]
mod cc;
mod common;

use cc::*;
use common::{deck_variant, inter_line, set_cols};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Cube nodes: 1001-1004 bottom (z0 = 1.2), 1005-1008 top.
const CUBE: [u64; 8] = [1001, 1002, 1003, 1004, 1005, 1006, 1007, 1008];
/// The band's shells (columns 3 and 4 of the 8 x 4 plate).
const BAND: [u64; 8] = [104, 105, 112, 113, 120, 121, 128, 129];

/// decks/NAME with the Idel column (71-80) of every /INTER/TYPE7, TYPE5 and TYPE25 set to `idel`.
fn variant(name: &str, idel: i64, dir: &Path) -> PathBuf {
    deck_variant(name, dir, |i, lines| {
        inter_line(i, lines, 3).then(|| set_cols(lines[i], 70, 80, idel))
    })
}

/// One listing IDEL line: (interface, segments, nodes, total segments, total nodes).
fn idel_lines(l: &Listing) -> Vec<(u64, u64, u64, u64, u64)> {
    l.text
        .lines()
        .filter(|s| s.trim_start().starts_with("IDEL INTER"))
        .map(|s| {
            let f: Vec<&str> = s.split_whitespace().collect();
            let n = |i: usize| f[i].parse::<u64>().unwrap();
            // IDEL INTER id TYPE7 CYCLE c TIME t REMOVED s MAIN SEGMENTS n SECONDARY NODES (TOTAL S SEGMENTS N NODES, ...
            assert_eq!(
                (f[8], f[10], f[13], f[15]),
                ("REMOVED", "MAIN", "SECONDARY", "(TOTAL"),
                "{s}"
            );
            (n(2), n(9), n(12), n(16), n(18))
        })
        .collect()
}

/// Total (segments, nodes) an interface removed.
fn removed(l: &Listing, iface: u64) -> (u64, u64) {
    idel_lines(l)
        .iter()
        .filter(|r| r.0 == iface)
        .map(|r| (r.3, r.4))
        .next_back()
        .unwrap_or((0, 0))
}

struct Cube {
    /// Lowest z of the cube's nodes and its mean velocity.
    z_min: f64,
    v: V3,
}

fn cube(state: &BTreeMap<u64, [f64; 6]>) -> Cube {
    let mut z_min = f64::INFINITY;
    let mut v = [0.0; 3];
    for id in CUBE {
        let s = state[&id];
        z_min = z_min.min(s[2]);
        for k in 0..3 {
            v[k] += s[3 + k] / 8.0;
        }
    }
    Cube { z_min, v }
}

fn run_idel(name: &str, idel: i64, tag: &str, ranks: u32) -> Run {
    let dir = scratch(&format!("idel-{tag}"));
    let d = variant(name, idel, &dir);
    let r = run(
        &d,
        &dir.join("out"),
        &RunArgs {
            elements: true,
            ranks,
            ..Default::default()
        },
    );
    assert!(r.listing.normal_termination(), "{}", r.listing.text);
    r
}

/// The band's 8 shells failed and were deleted, whatever Idel.
fn band_deleted(r: &Run) {
    let e = r.elements();
    for id in BAND {
        assert_eq!(*e[&id].last().unwrap(), 1.0, "band shell {id} is deleted");
    }
    assert_eq!(*e[&101].last().unwrap(), 0.0, "the steel shells live");
}

fn through(c: &Cube, what: &str) {
    // Nothing touched it: the initial velocity, to round-off.
    assert!(
        (c.v[2] + 2.0).abs() < 1e-9 && (c.v[0] - 5.0).abs() < 1e-9 && c.v[1].abs() < 1e-9,
        "{what}: the cube flies through untouched, v = {:?}",
        c.v
    );
    // Bottom at 1.2 - 2·t_end (t_end = 1.0 and the last step's overshoot): below the plate.
    assert!((c.z_min + 0.8).abs() < 5e-3, "{what}: z_min {}", c.z_min);
}

fn stopped(c: &Cube, what: &str) {
    assert!(
        c.v[2] > 1.0 && c.z_min > 0.5,
        "{what}: the cube bounced back off the plate, vz = {}, z_min = {}",
        c.v[2],
        c.z_min
    );
}

#[test]
fn idel_2_and_1_open_the_gap_idel_1000_keeps_stopping_the_cube() {
    // No deletion: the deleted band's segments stay, spanned between nodes
    // held in z, and stop the cube (it bounces at about 1.78 mm/ms).
    let r = run_idel("idel_gap", 1000, "gap-1000", 1);
    band_deleted(&r);
    assert!(idel_lines(&r.listing).is_empty());
    stopped(&cube(&r.final_state()), "Idel = 1000");

    for idel in [2, 1] {
        let r = run_idel("idel_gap", idel, &format!("gap-{idel}"), 1);
        band_deleted(&r);
        // Interface 1 loses the 8 band segments (each has one element), interface 2
        // the 5 middle-line nodes, once both their band shells are gone.
        assert_eq!(removed(&r.listing, 1), (8, 0), "Idel = {idel}");
        assert_eq!(removed(&r.listing, 2), (0, 5), "Idel = {idel}");
        // Removed when the shells are deleted, i.e. at about 0.1 ms, before the cube arrives.
        through(&cube(&r.final_state()), &format!("Idel = {idel}"));
    }
}

#[test]
fn idel_1_keeps_a_segment_while_one_of_its_elements_lives_idel_2_does_not() {
    // Each band segment is the face of a failing band shell and of a weak
    // shell that never fails.
    let r1 = run_idel("idel_layers", 1, "layers-1", 1);
    band_deleted(&r1);
    let weak = r1.elements();
    for id in 1..=8u64 {
        assert_eq!(*weak[&id].last().unwrap(), 0.0, "weak shell {id} lives");
    }
    assert!(
        idel_lines(&r1.listing).is_empty(),
        "Idel = 1 removes nothing"
    );
    stopped(
        &cube(&r1.final_state()),
        "Idel = 1, two elements per segment",
    );
    // Nothing removed: the run is Idel = 1000's, to the bit.
    let r0 = run_idel("idel_layers", 1000, "layers-1000", 1);
    assert_eq!(r1.final_state_bytes(), r0.final_state_bytes());

    let r2 = run_idel("idel_layers", 2, "layers-2", 1);
    band_deleted(&r2);
    assert_eq!(removed(&r2.listing, 1), (8, 0));
    through(
        &cube(&r2.final_state()),
        "Idel = 2, two elements per segment",
    );
}

#[test]
fn idel_minus_1_keeps_non_connected_secondary_nodes_idel_1_removes_them() {
    let r = run_idel("idel_gap", -1, "gap-m1", 1);
    band_deleted(&r);
    assert_eq!(removed(&r.listing, 1), (8, 0));
    // The middle-line nodes stay secondary nodes of interface 2, though none of
    // their elements lives, and stop the cube (held in z, they cannot yield).
    assert_eq!(removed(&r.listing, 2), (0, 0));
    // The band's segments are gone from interface 1: only those nodes can have stopped it.
    stopped(&cube(&r.final_state()), "Idel = -1");
    // One element per segment: -2 is -1.
    let r2 = run_idel("idel_gap", -2, "gap-m2", 1);
    assert_eq!(r.final_state_bytes(), r2.final_state_bytes());
    // Idel = 1 (removing them) lets the cube through: see the first test.
}

/// The element → rank map of `crashsim partition --np n` (shells 101-132 then the brick).
fn partition(n: u32) -> Vec<u64> {
    let j = common::crashsim_json(&[
        "partition",
        deck("idel_gap").to_str().unwrap(),
        "--np",
        &n.to_string(),
        "--json",
    ]);
    j["part"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_u64().unwrap())
        .collect()
}

#[test]
fn deletion_is_bitwise_identical_on_1_2_4_ranks_and_any_thread_count() {
    // The deleted shells do not all sit on the cube's rank: their deletion
    // must reach the cube's rank at the same cycle.
    for n in [2, 4] {
        let part = partition(n);
        assert_eq!(part.len(), 33);
        let cube_rank = part[32];
        let band_ranks: Vec<u64> = BAND.iter().map(|&id| part[(id - 101) as usize]).collect();
        assert!(
            band_ranks.iter().any(|&r| r != cube_rank),
            "{n} ranks: band on {band_ranks:?}, cube on {cube_rank}"
        );
    }
    // Idel = 2 (the cube flies through) and -2 (it is stopped by the kept nodes after the deletion).
    for idel in [2, -2] {
        let one = run_idel("idel_gap", idel, &format!("det{idel}-1"), 1);
        let reference = one.final_state_bytes();
        let lines = idel_lines(&one.listing);
        assert!(!lines.is_empty());
        // One thread.
        let dir = scratch(&format!("idel-det{idel}-t1"));
        let d = variant("idel_gap", idel, &dir);
        let fs = dir.join("fs.csv");
        let out = common::run_env(
            0,
            &[
                "run",
                d.to_str().unwrap(),
                "--out",
                dir.join("out").to_str().unwrap(),
                "--final-state",
                fs.to_str().unwrap(),
            ],
            &[("RAYON_NUM_THREADS", "1")],
        );
        ok(&out, "one thread");
        assert!(
            std::fs::read(&fs).unwrap() == reference,
            "Idel = {idel}: 1 thread"
        );
        for n in [2, 4] {
            let r = run_idel("idel_gap", idel, &format!("det{idel}-{n}"), n);
            assert!(
                r.final_state_bytes() == reference,
                "Idel = {idel}: {n} ranks differ from 1"
            );
            assert_eq!(
                idel_lines(&r.listing),
                lines,
                "Idel = {idel}: {n} ranks' IDEL lines"
            );
        }
    }
}

#[test]
fn type5_idel_2_removes_the_segments_idel_0_keeps_them() {
    let r0 = run_idel("idel_gap_t5", 0, "t5-0", 1);
    band_deleted(&r0);
    assert!(idel_lines(&r0.listing).is_empty());
    stopped(&cube(&r0.final_state()), "TYPE5, Idel = 0");
    let r2 = run_idel("idel_gap_t5", 2, "t5-2", 1);
    assert_eq!(removed(&r2.listing, 1), (8, 0));
    through(&cube(&r2.final_state()), "TYPE5, Idel = 2");
    // The TYPE5 walk skips removed segments the same way on 2 ranks.
    let r2b = run_idel("idel_gap_t5", 2, "t5-2-np2", 2);
    assert!(r2b.final_state_bytes() == r2.final_state_bytes());
    let r0b = run_idel("idel_gap_t5", 0, "t5-0-np2", 2);
    assert!(r0b.final_state_bytes() == r0.final_state_bytes());
}

/// idel_gap_t5 (Idel 0) with `edit` applied to its lines as well.
fn t5_run(tag: &str, edit: impl Fn(usize, &[&str]) -> Option<String>) -> Run {
    let dir = scratch(&format!("idel-t5-{tag}"));
    let d = deck_variant("idel_gap_t5", &dir, |i, lines| {
        let line = edit(i, lines);
        if inter_line(i, lines, 3) {
            return Some(set_cols(line.as_deref().unwrap_or(lines[i]), 70, 80, 0));
        }
        line
    });
    let out = dir.join("out");
    std::fs::create_dir_all(&out).unwrap();
    let fin = out.join("final_state.csv");
    let o = common::crashsim(&[
        "run",
        d.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--final-state",
        fin.to_str().unwrap(),
    ]);
    let code = o.status.code();
    assert!(
        code == Some(0) || code == Some(3),
        "{tag}: {code:?} {}",
        String::from_utf8_lossy(&o.stderr)
    );
    Run {
        dir: out.clone(),
        listing: Listing::read(&out.join("idel_gap_t5.out")),
    }
}

/// The TYPE5 card line that holds IRM, with IRM = `irm`.
fn irm(i: usize, lines: &[&str], v: i64) -> Option<String> {
    (i >= 1 && lines[i - 1].starts_with("#      IBC                 IRM"))
        .then(|| set_cols(lines[i], 20, 30, v))
}

/// IRM = 1 turns the main normals round. A plate written facing away from
/// the cube (its shells, /SHELL/1 and /SHELL/2, node2 and node4 swapped) stops it again under IRM = 1 as the plate facing it does under
/// IRM = 0 (the shells' own frames differ, so to round-off), while under
/// IRM = 0 the cube meets the plate's back, which TYPE5 does not see; IRM =
/// 2 keeps shell segments as given, the same bits as 0.
#[test]
fn type5_irm_1_reverses_the_main_normals_2_keeps_them() {
    let base = t5_run("irm0", |_, _| None);
    assert!(base.listing.normal_termination());
    let c0 = cube(&base.final_state());
    stopped(&c0, "TYPE5, IRM = 0, plate facing the cube");
    let flipped = t5_run("irm1-rev", |i, l| {
        irm(i, l, 1).or_else(|| common::shell_reversed(i, l))
    });
    let c1 = cube(&flipped.final_state());
    stopped(&c1, "TYPE5, IRM = 1, plate facing away");
    for k in 0..3 {
        assert!(
            (c1.v[k] - c0.v[k]).abs() < 1e-6 * (1.0 + c0.v[k].abs()),
            "IRM = 1 on the reversed plate against IRM = 0: {:?} vs {:?}",
            c1.v,
            c0.v
        );
    }
    // The cube's nodes lie behind the plate's segments, deeper than the
    // gap, from the start: TYPE5 takes that as a penetration and the
    // energy error stops the run.
    let back = t5_run("irm0-rev", common::shell_reversed);
    assert!(
        !back.listing.normal_termination() && back.listing.text.contains("ENERGY ERROR LIMIT"),
        "IRM = 0 on the plate facing away: {}",
        back.listing.text
    );
    let two = t5_run("irm2", |i, l| irm(i, l, 2));
    assert!(two.final_state_bytes() == base.final_state_bytes());
}

/// The cube's bottom face as TYPE5's main surface under the plate's nodes
/// (held in z, so they stop the cube): /SURF/SEG/6 written pointing into
/// the cube is turned out of it by IRM = 0 (a warning says so), the same
/// bits as the face written pointing out; IRM = 2 keeps it pointing in,
/// the same bits as the outward face reversed by IRM = 1.
#[test]
fn type5_irm_0_turns_a_solid_face_out_of_its_solid() {
    let on_face = |i: usize, l: &[&str], inward: bool, flag: i64| {
        if i >= 1 && l[i - 1].starts_with("#  grnd_IDs  surf_IDm") {
            return Some(set_cols(&set_cols(l[i], 0, 10, 1), 10, 20, 6));
        }
        if inward
            && l[i].split_whitespace().collect::<Vec<_>>() == ["1", "1001", "1003", "1004", "1002"]
        {
            return Some(format!(
                "{:>10}{:>10}{:>10}{:>10}{:>10}",
                1, 1001, 1002, 1004, 1003
            ));
        }
        irm(i, l, flag)
    };
    let out0 = t5_run("face-out-0", |i, l| on_face(i, l, false, 0));
    assert!(!out0.listing.text.contains("were reversed"));
    stopped(
        &cube(&out0.final_state()),
        "TYPE5 on the cube's face, IRM = 0",
    );
    let in0 = t5_run("face-in-0", |i, l| on_face(i, l, true, 0));
    assert!(
        in0.listing.text.contains(
            "1 segment(s) of the surface of IRM pointed into their solid element and were reversed"
        ),
        "{}",
        in0.listing.text
    );
    assert!(in0.final_state_bytes() == out0.final_state_bytes());
    let in2 = t5_run("face-in-2", |i, l| on_face(i, l, true, 2));
    let c2 = cube(&in2.final_state());
    assert!(
        (c2.v[2] - cube(&out0.final_state()).v[2]).abs() > 0.1,
        "IRM = 2 keeps the face pointing into the cube: {:?}",
        c2.v
    );
    let out1 = t5_run("face-out-1", |i, l| on_face(i, l, false, 1));
    assert!(out1.final_state_bytes() == in2.final_state_bytes());
}

#[test]
fn type25_idel_2_removes_the_segments_idel_0_keeps_them() {
    let r0 = run_idel("idel_gap_t25", 0, "t25-0", 1);
    band_deleted(&r0);
    assert!(idel_lines(&r0.listing).is_empty());
    stopped(&cube(&r0.final_state()), "TYPE25, Idel = 0");
    let r2 = run_idel("idel_gap_t25", 2, "t25-2", 1);
    assert_eq!(removed(&r2.listing, 1), (8, 0));
    through(&cube(&r2.final_state()), "TYPE25, Idel = 2");
    let r2b = run_idel("idel_gap_t25", 2, "t25-2-np2", 2);
    assert!(r2b.final_state_bytes() == r2.final_state_bytes());
}
