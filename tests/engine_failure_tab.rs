//! /FAIL/TAB on shells through the engine, on OpenRadioss's own QA deck
//! RUPTURE_FAIL_TAB_ELEM_SAMP (two QEPH shells of LAW36 pulled in uniaxial
//! tension, η = 1/3, research note `docs/notes/fail_tab_research.md` §4):
//! element 1 fails when Σ Δε_p/ε_f reaches Dcrit = 1.1, at t = 1.4795 in the
//! reference listing (cycle 2045 → 2046); element 9, pulled at a constant
//! true strain rate 0.1, at ε_p = 1.1·0.216 (t = 2.425, hand check and
//! reference). Each deletion is immediate (Ifail_sh 3 with P_thickfail read
//! as 0 in the version-100 layout: all five points fail together), its
//! energy stays in I-ENERGY, and the step then climbs 10% a cycle.

mod common;
use common::*;
use std::path::PathBuf;

fn deck() -> PathBuf {
    shared_dir()
        .join("decks/openradioss-qa/RUPTURE_FAIL_TAB_ELEM_SAMP")
        .join("1ELEM_SAMP_0000.rad")
}

/// (time, step, element id, I-ENERGY) of every row of our cycle table.
fn rows(text: &str) -> Vec<(f64, f64, u64, f64)> {
    text.lines()
        .filter_map(|l| {
            let t: Vec<&str> = l.split_whitespace().collect();
            if t.len() < 9 || t[0].parse::<u64>().is_err() || !t[5].ends_with('%') {
                return None;
            }
            Some((
                t[1].parse().ok()?,
                t[2].parse().ok()?,
                t[4].parse().ok()?,
                t[6].parse().ok()?,
            ))
        })
        .collect()
}

#[test]
fn tabulated_failure_deletes_both_shells_when_the_reference_does() {
    let dir = scratch("fail-tab");
    let d = deck();
    let out = crashsim(&["run", d.to_str().unwrap(), "--out", dir.to_str().unwrap()]);
    ok(&out, "RUPTURE_FAIL_TAB_ELEM_SAMP");
    let text = String::from_utf8_lossy(&out.stdout);
    let r = rows(&text);
    assert!(r.len() > 2000, "{} rows", r.len());
    // Element 1 governs the step until it fails; the step then grows ×1.1 a cycle.
    let k = r
        .iter()
        .position(|x| x.2 == 9)
        .expect("element 9 takes over the step");
    let t1 = r[k].0;
    assert!(
        (t1 - 1.4795).abs() < 0.005,
        "element 1 deleted at {t1}, reference 1.4795"
    );
    assert!(
        (r[k].1 / r[k - 1].1 - 1.1).abs() < 1e-3,
        "the step grows 10%: {:?} -> {:?}",
        r[k - 1],
        r[k]
    );
    // Element 9 fails near 2.425: the internal energy stops there.
    let ie_end = r.last().unwrap().3;
    let frozen = r
        .iter()
        .position(|x| (x.3 - ie_end).abs() <= 1e-4 * ie_end)
        .unwrap();
    let t9 = r[frozen].0;
    assert!(
        (t9 - 2.425).abs() < 0.005,
        "element 9 deleted at {t9}, reference 2.425"
    );
    // The deleted elements' energy stays counted: 28.02 in the reference.
    assert!(
        (ie_end - 28.02).abs() < 0.01 * 28.02,
        "final I-ENERGY {ie_end}, reference 28.02"
    );
    // The version-100 layout: the 0.4 of columns 41-60 is not P_thickfail, and it says so.
    let check = crashsim(&["check", d.to_str().unwrap()]);
    ok(&check, "check");
    let listing = String::from_utf8_lossy(&check.stdout);
    assert!(
        listing.contains("not a field of the 110 layout"),
        "{listing}"
    );
}
