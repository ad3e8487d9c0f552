//! Restart files of decks with interfaces: a run stopped (`--stop-after-cycle`)
//! while pairs are active and restarted on 1 or 2 ranks (also 2 → 1) ends
//! with a `--final-state` byte-identical to the run that never stopped; the
//! state measured is the pair memory (friction, Inacti 5 corrected gaps),
//! the candidate lists kept between sorts, the sort positions (the sort
//! decision), the Idel tables (mid-way through the deletions), TYPE5's
//! walk, TYPE2's turning offsets. A restart file without the contact
//! sections (an older crashsim) or of another deck is refused (exit 2).

mod common;
use common::*;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn run(np: u32, deck: &Path, dir: &Path, extra: &[&str]) -> Output {
    let mut args = vec![
        "run",
        deck.to_str().unwrap(),
        "--out",
        dir.to_str().unwrap(),
        "--quiet",
    ];
    args.extend_from_slice(extra);
    run_env(np, &args, &[])
}

struct Case {
    deck: PathBuf,
    name: String,
    /// `--stop-after-cycle` of the reference (None: to the end).
    end: Option<u64>,
}

impl Case {
    fn new(deck: PathBuf, end: Option<u64>) -> Case {
        let name = deck
            .file_name()
            .unwrap()
            .to_str()
            .unwrap()
            .trim_end_matches("_0000.rad")
            .to_string();
        Case { deck, name, end }
    }

    fn end_args(&self) -> Vec<String> {
        match self.end {
            Some(c) => vec!["--stop-after-cycle".into(), c.to_string()],
            None => Vec::new(),
        }
    }

    /// The uninterrupted run's final state, and its listing.
    fn reference(&self, tag: &str) -> (Vec<u8>, String) {
        let dir = scratch(tag);
        let fs = dir.join("final.csv");
        let mut extra = vec!["--final-state".to_string(), fs.to_str().unwrap().into()];
        extra.extend(self.end_args());
        let extra: Vec<&str> = extra.iter().map(|s| s.as_str()).collect();
        let out = run(0, &self.deck, &dir, &extra);
        ok(&out, "reference run");
        (
            std::fs::read(fs).unwrap(),
            String::from_utf8_lossy(&out.stdout).into_owned(),
        )
    }

    /// A run on `np` ranks stopped after `cycle`: its directory.
    fn stop(&self, np: u32, cycle: u64, tag: &str) -> PathBuf {
        let dir = scratch(tag);
        let out = run(
            np,
            &self.deck,
            &dir,
            &["--stop-after-cycle", &cycle.to_string()],
        );
        ok(
            &out,
            &format!("run stopped at cycle {cycle} on {np} rank(s)"),
        );
        assert!(
            String::from_utf8_lossy(&out.stdout).contains(&format!("STOPPED AT CYCLE {cycle}")),
            "no stop at {cycle}"
        );
        dir
    }

    /// Restarts a copy of `stopped` on `np` ranks: final state and listing.
    fn restart(&self, np: u32, stopped: &Path, tag: &str) -> (Vec<u8>, String) {
        let dir = copy_run(stopped, tag);
        let rst = dir.join(format!("{}_rst.h5", self.name));
        let fs = dir.join("final.csv");
        let mut extra = vec![
            "--restart".to_string(),
            rst.to_str().unwrap().into(),
            "--final-state".into(),
            fs.to_str().unwrap().into(),
        ];
        extra.extend(self.end_args());
        let extra: Vec<&str> = extra.iter().map(|s| s.as_str()).collect();
        let out = run(np, &self.deck, &dir, &extra);
        ok(&out, &format!("restart on {np} rank(s)"));
        (
            std::fs::read(fs).unwrap(),
            String::from_utf8_lossy(&out.stdout).into_owned(),
        )
    }
}

fn rows(csv: &[u8]) -> usize {
    csv.iter().filter(|&&c| c == b'\n').count()
}

/// Stops at `cycle` on `from` ranks, restarts on each of `to`: identical bytes.
fn check(case: &Case, cycle: u64, from: u32, to: &[u32], full: &[u8], tag: &str) {
    let stopped = case.stop(from, cycle, &format!("{tag}-stop{from}"));
    for &np in to {
        let (got, _) = case.restart(np, &stopped, &format!("{tag}-{from}to{np}"));
        assert!(rows(&got) == rows(full) && rows(full) > 1);
        assert!(
            got == full,
            "{}: stopped at cycle {cycle} on {from} rank(s), restarted on {np}: the final state differs from the run that never stopped",
            case.name
        );
    }
}

/// Sliding block (TYPE7, Coulomb) with Iform = 2 (incremental: the
/// tangential force of the last cycle is the pair's memory; with that
/// memory zeroed at the restart the final state differs), 9 pairs in
/// contact from the first cycle to the end, one sort: stopped mid-slide at
/// 1300 of 2633 cycles.
#[test]
fn sliding_block_friction_memory_restart_1_2_and_2_to_1() {
    let dir = scratch("crst-slide-deck");
    // Iform: columns 41-50 of the line below "#    Ifric".
    let d = deck_variant("sliding_block", &dir, |i, lines| {
        (i >= 1 && lines[i - 1].starts_with("#    Ifric")).then(|| set_cols(lines[i], 40, 50, 2))
    });
    let case = Case::new(d, None);
    let (full, _) = case.reference("crst-slide-full");
    check(&case, 1300, 0, &[0, 2], &full, "crst-slide");
    check(&case, 1300, 2, &[0], &full, "crst-slide");
}

/// The sliding block with Inacti = 5: it starts inside the gap, so every
/// pair keeps a corrected gap that relaxes cycle by cycle.
#[test]
fn inacti_5_corrected_gaps_restart_1_to_2() {
    let dir = scratch("crst-inacti5-deck");
    // Inacti: columns 31-40 of the line below "#      IBC ... Inacti".
    let d = deck_variant("sliding_block", &dir, |i, lines| {
        (i >= 1 && lines[i - 1].starts_with("#      IBC") && lines[i - 1].contains("Inacti"))
            .then(|| set_cols(lines[i], 30, 40, 5))
    });
    let text = std::fs::read_to_string(&d).unwrap();
    assert!(
        text.contains("       000                             5"),
        "Inacti 5 not set"
    );
    let case = Case::new(d, None);
    let (full, _) = case.reference("crst-inacti5-full");
    // Inacti 5 changes the run (else this would measure nothing new).
    let (plain, _) = Case::new(deck("sliding_block"), None).reference("crst-inacti5-plain");
    assert!(full != plain, "Inacti 5 has no effect on the sliding block");
    check(&case, 1300, 0, &[2], &full, "crst-inacti5");
}

/// Ball drop (TYPE7, a sphere bouncing on a plate, pairs from cycle 550 to
/// 750): stopped during the impact.
#[test]
fn ball_drop_mid_impact_restart_1_2_and_2_to_1() {
    let case = Case::new(deck("ball_drop"), Some(1000));
    let (full, _) = case.reference("crst-ball-full");
    check(&case, 650, 0, &[0, 2], &full, "crst-ball");
    check(&case, 650, 2, &[0], &full, "crst-ball");
}

/// Tube crush (TYPE7 self-contact, pairs from cycle 2213, a sort every few
/// dozen cycles): stopped at 2450, compared at 2650 (several sorts after
/// the restart, each rebuilding the ghost plan of the new layout).
#[test]
fn tube_crush_self_contact_restart_1_to_2_and_2_to_1() {
    let case = Case::new(deck("tube_crush"), Some(2650));
    let (full, listing) = case.reference("crst-tube-full");
    assert!(listing.contains("PAIRS"));
    check(&case, 2450, 0, &[2], &full, "crst-tube");
    check(&case, 2450, 2, &[0], &full, "crst-tube");
}

/// The `IDEL INTER` lines of a listing after `cycle`.
fn idel_after(listing: &str, cycle: u64) -> Vec<String> {
    listing
        .lines()
        .filter(|l| l.contains("IDEL INTER"))
        .filter(|l| {
            let w: Vec<&str> = l.split_whitespace().collect();
            let c = w.iter().position(|&x| x == "CYCLE").unwrap();
            w[c + 1].parse::<u64>().unwrap() > cycle
        })
        .map(|l| l.to_string())
        .collect()
}

/// idel_gap with Idel = -1 (decks/make_idel.py: the band's segments are
/// removed as its shells fail, at cycles 145–152; the middle-line nodes stay
/// and stop the cube, pairs at cycles 757–763): stopped in the middle of the
/// deletions (148) and in the middle of the impact (760).
#[test]
fn idel_restart_mid_deletion_and_mid_impact() {
    let dir = scratch("crst-idel-deck");
    // Idel: columns 71-80 of the first data line of every interface.
    let d = deck_variant("idel_gap", &dir, |i, lines| {
        inter_line(i, lines, 3).then(|| set_cols(lines[i], 70, 80, -1))
    });
    let case = Case::new(d, None);
    let (full, listing) = case.reference("crst-idel-full");
    let later = idel_after(&listing, 148);
    assert!(!later.is_empty() && idel_after(&listing, 0).len() > later.len());
    let stopped = case.stop(0, 148, "crst-idel-stop148");
    let (got, restarted) = case.restart(2, &stopped, "crst-idel-148to2");
    assert!(got == full, "Idel: restart at 148 on 2 ranks differs");
    // The removals after the restart are the same, with the same totals.
    assert_eq!(idel_after(&restarted, 148), later);
    check(&case, 760, 2, &[0], &full, "crst-idel760");
}

/// idel_gap_t5 (TYPE5: the walk's last segment and its pair per node;
/// Idel = 2): stopped in the middle of the deletions.
#[test]
fn type5_idel_restart_1_to_2() {
    let case = Case::new(deck("idel_gap_t5"), None);
    let (full, listing) = case.reference("crst-t5-full");
    let later = idel_after(&listing, 148);
    assert!(!later.is_empty());
    let stopped = case.stop(0, 148, "crst-t5-stop");
    let (got, restarted) = case.restart(2, &stopped, "crst-t5-1to2");
    assert!(got == full, "TYPE5: restart at 148 on 2 ranks differs");
    assert_eq!(idel_after(&restarted, 148), later);
}

/// TYPE2: spinning strips (offsets turned every cycle) and a plate tied
/// onto a block.
#[test]
fn tied_restart_1_to_2_and_2_to_1() {
    let spin = Case::new(deck("tied_spin"), None);
    let (full, _) = spin.reference("crst-spin-full");
    check(&spin, 1731, 0, &[2], &full, "crst-spin");
    check(&spin, 1731, 2, &[0], &full, "crst-spin");
    let block = Case::new(deck("tied_plate_block"), None);
    let (full, _) = block.reference("crst-tpb-full");
    check(&block, 438, 2, &[0, 2], &full, "crst-tpb");
}

/// A restart file without the contact sections (as crashsim wrote them
/// before they existed) and one of a deck whose interfaces differ are
/// refused with exit code 2 and a message naming what is wrong.
#[test]
fn restart_files_without_contact_state_or_of_another_deck_are_refused() {
    let case = Case::new(deck("sliding_block"), None);
    let stopped = case.stop(0, 100, "crst-refuse-stop");
    // Older layout: the contact sections removed.
    let old = copy_run(&stopped, "crst-refuse-old");
    let rst = old.join("sliding_block_rst.h5");
    let py = Command::new(python())
        .args([
            "-c",
            "import h5py, sys\nwith h5py.File(sys.argv[1], 'a') as f:\n    for s in ['contact', 'contact.pairs', 'contact.x_sort', 'nodes.fcont', 'nodes.fixed']:\n        del f['sections/' + s]",
            rst.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    ok(&py, "h5py removing the contact sections");
    let out = run(0, &case.deck, &old, &["--restart", rst.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2), "old restart file accepted");
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("no section 'contact'") && err.contains("contact interfaces"),
        "{err}"
    );
    // Another deck of the same name and size: the interface id differs.
    let dir = scratch("crst-refuse-deck");
    let other = deck_variant("sliding_block", &dir, |i, lines| {
        lines[i]
            .starts_with("/INTER/TYPE7/1")
            .then(|| "/INTER/TYPE7/7".to_string())
    });
    let moved = copy_run(&stopped, "crst-refuse-other");
    let rst = moved.join("sliding_block_rst.h5");
    let out = run(0, &other, &moved, &["--restart", rst.to_str().unwrap()]);
    assert_eq!(
        out.status.code(),
        Some(2),
        "restart of another deck accepted"
    );
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("/INTER/TYPE7/1")
            && err.contains("/INTER/TYPE7/7")
            && err.contains("expected a restart file of this deck"),
        "{err}"
    );
}
