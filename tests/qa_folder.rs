//! Walks `../shared/decks/openradioss-qa` (issue 13): every deck runs or is
//! refused by name, every deck that runs is within 10% of its OpenRadioss
//! listing unless `KNOWN_OFF` says why not and holds it to its own bound,
//! and every deck that runs gives byte-identical final states on 1 and 2
//! ranks and takes the reference's number of cycles to its last printed
//! row within 5% (issue 16's time step target).
//! Prints one line per deck: status, worst deviation, seconds, 1 = 2 ranks,
//! cycles over the reference's.
//!
//! The deviation of a run: at every row of the reference engine listing,
//! our I-ENERGY and K-ENERGY T (every cycle, `--energies`, read at the
//! row's time) against the reference, relative to the column's largest
//! reference value (a column under 1% of the run's energy scale — the
//! largest I-ENERGY + K-ENERGY T — is held to 1% of that scale).

mod common;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// (time, I-ENERGY, K-ENERGY T) of every row of an engine listing.
fn reference_rows(listing: &Path) -> Vec<[f64; 3]> {
    let text = std::fs::read_to_string(listing).unwrap_or_default();
    text.lines()
        .filter_map(|l| {
            let t: Vec<&str> = l.split_whitespace().collect();
            if t.len() < 9 || t[0].parse::<u64>().is_err() || !t[5].ends_with('%') {
                return None;
            }
            let p = |s: &str| s.parse::<f64>().ok();
            Some([p(t[1])?, p(t[6])?, p(t[7])?])
        })
        .collect()
}

/// (cycle, time) of an engine listing's last row.
fn reference_last_cycle(listing: &Path) -> Option<(f64, f64)> {
    let text = std::fs::read_to_string(listing).unwrap_or_default();
    let last = common::cycle_table(&text).pop()?;
    Some((common::num(last[0]), common::num(last[1])))
}

/// Our cycles to the reference's last row over its cycles there (`None`
/// under 10 reference cycles): the time step rule's check (issue 16: the
/// same deck takes as many cycles as the reference, within 5%).
fn cycle_ratio(listing: &Path, csv: &Path) -> Option<f64> {
    let (cycle, t) = reference_last_cycle(listing)?;
    let (_, rows) = common::read_csv(csv);
    let i = rows.partition_point(|r| r[0] < t * (1.0 - 1e-4));
    let ours = rows.get(i).or(rows.last())?[1];
    (cycle >= 10.0).then(|| ours / cycle)
}

/// (time, internal, kinetic) of our `--energies` CSV.
fn our_rows(csv: &Path) -> Vec<[f64; 3]> {
    let (_, rows) = common::read_csv(csv);
    rows.iter().map(|r| [r[0], r[3], r[4]]).collect()
}

/// Our value of column `k` at time `t` (linear between cycles; the
/// listing prints 4 digits of time: its last row may lie just past our end).
fn at(ours: &[[f64; 3]], t: f64, k: usize) -> Option<f64> {
    let last = ours.last()?;
    if t > last[0] && t <= last[0] * (1.0 + 1e-3) {
        return Some(last[k]);
    }
    let i = ours.partition_point(|r| r[0] < t);
    if i == 0 {
        return ours.first().map(|r| r[k]);
    }
    let b = ours.get(i)?;
    let a = ours[i - 1];
    let w = if b[0] > a[0] {
        (t - a[0]) / (b[0] - a[0])
    } else {
        1.0
    };
    Some(a[k] + w * (b[k] - a[k]))
}

/// The worst deviation of our run from the reference rows (see the module doc).
fn worst_deviation(reference: &[[f64; 3]], ours: &[[f64; 3]]) -> f64 {
    let scale = reference.iter().map(|r| r[1] + r[2]).fold(0.0f64, f64::max);
    let mut worst = 0.0f64;
    for k in [1, 2] {
        let col = reference.iter().map(|r| r[k].abs()).fold(0.0f64, f64::max);
        let base = col.max(0.01 * scale).max(f64::MIN_POSITIVE);
        for r in reference {
            // Past our end (a run that stopped early): the deviation is total.
            let d = match at(ours, r[0], k) {
                Some(v) => (v - r[k]).abs() / base,
                None => 1.0,
            };
            worst = worst.max(d);
        }
    }
    worst
}

/// Whether a message names a keyword (` /WORD`, as the refusals do).
fn names_a_keyword(msg: &str) -> bool {
    msg.match_indices(" /")
        .any(|(i, _)| msg[i + 2..].starts_with(|c: char| c.is_ascii_uppercase()))
}

/// Decks that ran to their end when this floor was last raised: fewer is a regression.
const MIN_RUNNING: usize = 29;

/// Decks that run but not yet within 10% of their reference (issue 15's
/// bar): the bound each is held to (a regression guard) and why; every
/// other deck that runs is held to 10%.
const KNOWN_OFF: &[(&str, f64, &str)] = &[(
    "INTERF_INT_25_hexa8",
    0.60,
    "I-ENERGY within 3.1% at every row and the time step column as the reference's (NODE 5 at 6.367e-4 at cycle 1000, 0.6569 ms); the Johnson-Cook failure of the HA8 bricks starts about 1.74 ms (the reference has deleted 22 by 1.874), EXT-WORK ends at 364 against 397, and the nodes the deletions free fly off with K-ENERGY T 2.5-3.1 against 6.08 (52%; it moves by 15% with the last bit of the step: chaotic) (issue 14)",
)];

struct Outcome {
    deck: String,
    status: String,
    worst: Option<f64>,
    seconds: f64,
    /// A deck that ran: its final state on 2 ranks is byte-identical to 1 rank's.
    ranks_equal: Option<bool>,
    /// A deck that ran: `cycle_ratio`.
    cycles: Option<f64>,
}

fn run_deck(folder: &Path) -> Outcome {
    let name = |suffix: &str| -> Option<PathBuf> {
        std::fs::read_dir(folder)
            .ok()?
            .filter_map(|e| e.ok().map(|e| e.path()))
            .find(|p| p.to_string_lossy().ends_with(suffix))
    };
    let deck = folder.file_name().unwrap().to_string_lossy().into_owned();
    let (Some(starter), Some(listing)) = (name("_0000.rad"), name("_0001.out")) else {
        return Outcome {
            deck,
            status: "no starter deck or reference listing".into(),
            worst: None,
            seconds: 0.0,
            ranks_equal: None,
            cycles: None,
        };
    };
    let dir = common::scratch(&format!("qa-{deck}"));
    let csv = dir.join("energies.csv");
    let (final1, final2) = (dir.join("final1.csv"), dir.join("final2.csv"));
    let started = Instant::now();
    let out = common::crashsim(&[
        "run",
        starter.to_str().unwrap(),
        "--out",
        dir.to_str().unwrap(),
        "--energies",
        csv.to_str().unwrap(),
        "--final-state",
        final1.to_str().unwrap(),
        "--quiet",
    ]);
    let seconds = started.elapsed().as_secs_f64();
    let err = String::from_utf8_lossy(&out.stderr);
    let first = err.lines().next().unwrap_or("");
    let cycles = (out.status.code() == Some(0))
        .then(|| cycle_ratio(&listing, &csv))
        .flatten();
    let (status, worst) = match out.status.code() {
        Some(0) => {
            let w = worst_deviation(&reference_rows(&listing), &our_rows(&csv));
            ("ran".to_string(), Some(w))
        }
        Some(2) if names_a_keyword(&err) => (format!("refused: {first}"), None),
        Some(2) => (format!("refused without naming a keyword: {first}"), None),
        Some(3) => (format!("stopped: {first}"), None),
        c => (format!("failed ({c:?}): {first}"), None),
    };
    let ranks_equal = worst.map(|_| {
        let two = dir.join("two");
        let out2 = common::mpirun(
            2,
            &[
                "run",
                starter.to_str().unwrap(),
                "--out",
                two.to_str().unwrap(),
                "--final-state",
                final2.to_str().unwrap(),
                "--quiet",
            ],
        );
        out2.status.success()
            && std::fs::read(&final1).ok().is_some()
            && std::fs::read(&final1).ok() == std::fs::read(&final2).ok()
    });
    let _ = std::fs::remove_dir_all(&dir);
    Outcome {
        deck,
        status,
        worst,
        seconds,
        ranks_equal,
        cycles,
    }
}

#[test]
fn every_qa_deck_runs_or_is_refused_by_name_and_none_runs_far_off() {
    let root = common::shared_dir().join("decks/openradioss-qa");
    let mut folders: Vec<PathBuf> = std::fs::read_dir(&root)
        .unwrap()
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.is_dir())
        .collect();
    folders.sort();
    assert!(folders.len() >= 30, "{} decks", folders.len());
    let outcomes: Vec<Outcome> = folders.iter().map(|f| run_deck(f)).collect();
    println!(
        "{:<60} {:>9} {:>8} {:>5} {:>7}  status",
        "deck", "worst", "seconds", "1=2", "cycles"
    );
    for o in &outcomes {
        let worst = o
            .worst
            .map_or("-".to_string(), |w| format!("{:.1}%", 100.0 * w));
        let same = match o.ranks_equal {
            Some(true) => "yes",
            Some(false) => "NO",
            None => "-",
        };
        let status: String = o.status.chars().take(160).collect();
        let cycles = o.cycles.map_or("-".to_string(), |c| format!("{c:.3}"));
        println!(
            "{:<60} {worst:>9} {:>8.1} {same:>5} {cycles:>7}  {status}",
            o.deck, o.seconds
        );
    }
    let ran = outcomes.iter().filter(|o| o.worst.is_some()).count();
    println!("{ran} of {} decks ran to their end", outcomes.len());
    assert!(
        ran >= MIN_RUNNING,
        "{ran} decks ran to their end; {MIN_RUNNING} did before: a deck that ran is refused or fails now"
    );
    for (deck, bound, why) in KNOWN_OFF {
        println!("known: {deck} (held to {:.0}%): {why}", 100.0 * bound);
    }
    let bad: Vec<&Outcome> = outcomes
        .iter()
        .filter(|o| {
            let bound = KNOWN_OFF
                .iter()
                .find(|(d, _, _)| *d == o.deck)
                .map_or(0.1, |k| k.1);
            o.worst.is_some_and(|w| w > bound)
                || o.status.starts_with("failed")
                || o.ranks_equal == Some(false)
                || o.cycles.is_some_and(|c| (c - 1.0).abs() > 0.05)
                || o.status.starts_with("refused without")
        })
        .collect();
    assert!(
        bad.is_empty(),
        "far off (over 10%, or a known deck over its bound), failed, 1 and 2 ranks not byte-identical, cycles more than 5% off the reference's, or refused without naming a keyword: {:?}",
        bad.iter()
            .map(|o| (&o.deck, &o.status, o.worst, o.cycles))
            .collect::<Vec<_>>()
    );
}
