//! Hyper-ellipsoid to segment contact (theory manual §8.10, /INTER/TYPE15)
//! on decks/make_rigid.py's type15_drop and type15_roll: a rigid sphere
//! (/SURF/ELLIPS, R = 50 mm, on a 1 kg /RBODY) against a fixed plate of
//! 400 mm shells, over the middle of one of a quad's four triangles with no
//! node near.
//!
//! - Dropped at v0 = 5 mm/ms (type15_drop): the force
//!   F(p) = Stif·[R/(R − p)]²·p stops it at the depth p* where
//!   ∫₀^p* F = ½Mv0², the largest force is F(p*) within 1%; the same law
//!   unloads, so it rebounds at v0 within 1%, and the energy closes.
//! - TYPE14 (nodes) on the same plate misses it: the sphere falls through
//!   between the nodes (the case TYPE15 exists for).
//! - Pressed by W on the plate and sliding at v0 without spin, Fric μ
//!   (type15_roll): while it slides the friction is μ·W (the ball's
//!   reaction turns it), and it ends rolling at 5/7·v0, its rim speed ω·R
//!   equal to its speed, within 1%; the energy lost to friction is the
//!   2/7 of the kinetic energy the law predicts.
//! - Identical on 1, 2 and 4 ranks (the plate's segments on several ranks)
//!   and on 2 threads; a run stopped on 2 ranks in the middle of the
//!   contact and restarted on 1 ends identically.
//! - A blank Stif and an ellipsoid as surf_IDs are deck errors at their line.

mod common;
#[path = "contact_common/mod.rs"]
mod contact_common;
use contact_common::*;

const R: f64 = 50.0;
const M: f64 = 1.0;

/// F(p) = Stif·[R/(R − p)]²·p (§8.10, D = R on a sphere).
fn force(stif: f64, p: f64) -> f64 {
    stif * (R / (R - p)).powi(2) * p
}

/// ∫₀^p F = Stif·R²·[p/(R − p) + ln((R − p)/R)].
fn work(stif: f64, p: f64) -> f64 {
    stif * R * R * (p / (R - p) + ((R - p) / R).ln())
}

/// The depth where the work of F is `e` (bisection: the work grows with p).
fn depth_of(stif: f64, e: f64) -> f64 {
    let (mut lo, mut hi) = (0.0, R);
    for _ in 0..200 {
        let p = 0.5 * (lo + hi);
        if work(stif, p) < e {
            lo = p;
        } else {
            hi = p;
        }
    }
    0.5 * (lo + hi)
}

#[test]
fn a_type15_sphere_stops_where_the_stiffening_law_takes_its_energy_and_rebounds() {
    let (stif, v0) = (0.05, 5.0);
    let r = run(
        &deck("type15_drop"),
        &scratch("type15_drop_1"),
        &RunArgs::default(),
    );
    assert!(r.listing.normal_termination());
    let p = depth_of(stif, 0.5 * M * v0 * v0);
    // The law stiffens: the depth is well below the linear spring's.
    let linear = (M * v0 * v0 / stif).sqrt();
    assert!(p < 0.8 * linear, "{p} against {linear}");
    let expect = force(stif, p);
    let lines = r.listing.of(1);
    let peak = lines.iter().map(|l| -l.normal[2]).fold(0.0, f64::max);
    assert!(
        (peak - expect).abs() < 0.01 * expect,
        "peak force {peak}, expected {expect} at the depth {p}"
    );
    // One facet at a time: the contact stayed inside one triangle.
    assert!(lines.iter().all(|l| l.pairs <= 1));
    let v = r.final_state()[&1000][5];
    assert!((v - v0).abs() < 0.01 * v0, "rebound {v}, expected {v0}");
    assert_eq!(lines.last().unwrap().pairs, 0, "the sphere left the plate");
    let closes = energy_balance(&r, "type15_drop").1;
    assert!(closes.abs() < 1.0, "energy closes to {closes}%");
}

#[test]
fn type14_on_the_same_plate_lets_the_sphere_fall_between_the_nodes() {
    let dir = scratch("type15_as_type14");
    // The TYPE15 block (header, title, two comment/data pairs) as a TYPE14
    // of the plate's nodes (group 1) with the same stiffness.
    let d = common::deck_variant("type15_drop", &dir, |i, lines| {
        let at = lines.iter().position(|l| l.starts_with("/INTER/TYPE15"))?;
        match i.checked_sub(at)? {
            0 => Some("/INTER/TYPE14/1".into()),
            3 => Some(format!("{:>10}{:>10}{:>10}", 1, 10, 0)),
            5 => Some(format!("{:>20}", "0.05")),
            _ => None,
        }
    });
    let r = run(&d, &dir.join("run"), &RunArgs::default());
    assert!(r.listing.normal_termination());
    assert!(r.listing.of(1).iter().all(|l| l.pairs == 0));
    let z = r.final_state()[&1000][2];
    assert!(
        z < -R,
        "the sphere's centre at z = {z}: it fell through the plate"
    );
}

#[test]
fn a_sliding_sphere_is_turned_by_type15_friction_until_it_rolls_at_five_sevenths() {
    let (w, mu, v0) = (0.05, 0.5, 1.0);
    let r = run(
        &deck("type15_roll"),
        &scratch("type15_roll_1"),
        &RunArgs::default(),
    );
    assert!(r.listing.normal_termination());
    // Sliding until t* = 2·v0/(7·μ·g): the friction is μ·W.
    let t_roll = 2.0 * v0 / (7.0 * mu * w / M);
    let sliding: Vec<_> = r
        .listing
        .of(1)
        .into_iter()
        .filter(|l| l.t > 0.5 && l.t < 0.9 * t_roll)
        .collect();
    assert!(sliding.len() > 5);
    for l in &sliding {
        assert!(
            (l.tangent[0] - mu * w).abs() < 0.01 * mu * w && (-l.normal[2] - w).abs() < 0.01 * w,
            "t = {}: friction {:?}, normal {:?}",
            l.t,
            l.tangent,
            l.normal
        );
    }
    let s = r.final_state();
    let (v, spin) = (s[&1000][3], r_spin(&r));
    let rolling = 5.0 / 7.0 * v0;
    assert!(
        (v - rolling).abs() < 0.01 * rolling,
        "v = {v}, expected {rolling}"
    );
    assert!(
        (spin * R - rolling).abs() < 0.01 * rolling,
        "rim speed {}, expected {rolling}",
        spin * R
    );
    // Friction took 2/7 of the kinetic energy: the Radioss-style balance
    // lists it as the error, the balance with contact energy closes.
    let (error, closes) = energy_balance(&r, "type15_roll");
    assert!((error + 100.0 * 2.0 / 7.0).abs() < 0.5, "ERROR {error}%");
    assert!(closes.abs() < 0.5, "closes to {closes}%");
}

/// The sphere's spin about y at the end (its main node's rotational
/// velocity, from the final-state CSV's vry column).
fn r_spin(r: &Run) -> f64 {
    let (head, rows) = read_csv(&r.dir.join("final_state.csv"));
    let id = head.iter().position(|h| h == "id").unwrap();
    let vry = head.iter().position(|h| h == "vry").unwrap();
    rows.iter().find(|row| row[id] == 1000.0).unwrap()[vry]
}

/// A light sphere (0.05 kg, J scaled with it, the same W: it starts at its
/// rest penetration and rolls from 0.57 ms) on the plate without the
/// small pad that set the step: its contact stiffness
/// then sets the step (the body's √(2M/K) and √(2J/K_r), reported as the
/// interface's), the run stays stable where the plate's step alone let it
/// blow up (650% energy error by cycle 20), and it still ends rolling at
/// 5/7·v0 (within the elastic friction's oscillation, a few % for so light
/// a body).
#[test]
fn a_light_sphere_s_contact_stiffness_sets_the_time_step() {
    let dir = scratch("type15_roll_light");
    let pad = |l: &str| l.starts_with("/SHELL/2") || l.starts_with("/PART/2");
    let d = common::deck_variant("type15_roll", &dir, |i, lines| {
        let back = |k: usize| i.checked_sub(k).map_or("", |j| lines[j]);
        let l = lines[i];
        if pad(l) || pad(back(1)) || pad(back(2)) {
            Some("#".into())
        } else if back(1).starts_with("#  node_ID   sens_ID") {
            Some(format!("{}{:>20}{}", &l[..40], "0.05", &l[60..]))
        } else if back(1).starts_with("#                Jxx") {
            Some(format!("{:>20}{:>20}{:>20}", "50", "50", "50"))
        } else {
            None
        }
    });
    let r = run(&d, &dir.join("run"), &RunArgs::default());
    assert!(r.listing.normal_termination());
    let first = &r.listing.cycles[0];
    assert!(
        first.what == "INTER" && first.id == 1,
        "step set by {} {}",
        first.what,
        first.id
    );
    let v = r.final_state()[&1000][3];
    let rolling = 5.0 / 7.0;
    assert!((v - rolling).abs() < 0.05 * rolling, "v = {v}");
    let (error, closes) = energy_balance(&r, "type15_roll");
    assert!((error + 100.0 * 2.0 / 7.0).abs() < 1.0, "ERROR {error}%");
    // About four steps per period of the friction spring on so light a
    // body: the balance closes to a few %, where the run without the
    // body's step left it at 650% by cycle 20.
    assert!(closes.abs() < 5.0, "closes to {closes}%");
}

/// type15_drop with its sphere an oblate ellipsoid (semi-axis 25 along z,
/// 50 across): given directly, or as (25, 50, 50) in a /SKEW/FIX whose X′
/// is the global z, the same run; a skew that is not defined is an error
/// naming the ellipsoid.
fn drop_variant(tag: &str, skew: u64, axes: [&str; 3]) -> std::path::PathBuf {
    let dir = scratch(tag);
    common::deck_variant("type15_drop", &dir, |i, lines| {
        let at = lines.iter().position(|l| l.starts_with("/SURF/ELLIPS"))?;
        match i.checked_sub(at)? {
            3 => Some(format!("{skew:>10}{:>10}", 2)),
            6 => Some(format!("{:>20}{:>20}{:>20}", axes[0], axes[1], axes[2])),
            _ if lines[i] == "/END" => Some(
                [
                    "/SKEW/FIX/7\nX' along z",
                    &format!("{:>20}{:>20}{:>20}", 0, 0, 0),
                    &format!("{:>20}{:>20}{:>20}", 0, 1, 0),
                    &format!("{:>20}{:>20}{:>20}", -1, 0, 0),
                    "/END",
                ]
                .join("\n"),
            ),
            _ => None,
        }
    })
}

#[test]
fn an_ellipsoid_s_skew_sets_its_axes() {
    let plain = drop_variant("type15_oblate", 0, ["50", "50", "25"]);
    let skewed = drop_variant("type15_oblate_skew", 7, ["25", "50", "50"]);
    let a = run(
        &plain,
        &plain.parent().unwrap().join("run"),
        &RunArgs::default(),
    );
    let b = run(
        &skewed,
        &skewed.parent().unwrap().join("run"),
        &RunArgs::default(),
    );
    let peak = |r: &Run| {
        r.listing
            .of(1)
            .iter()
            .map(|l| -l.normal[2])
            .fold(0.0, f64::max)
    };
    assert!(
        peak(&a) > 0.5,
        "the oblate sphere hit the plate: {}",
        peak(&a)
    );
    assert!(
        (peak(&a) - peak(&b)).abs() <= 1e-9 * peak(&a),
        "{} {}",
        peak(&a),
        peak(&b)
    );
    let (sa, sb) = (a.final_state(), b.final_state());
    for k in [2, 5] {
        assert!(
            (sa[&1000][k] - sb[&1000][k]).abs() <= 1e-9 * sa[&1000][k].abs(),
            "{k}"
        );
    }
    let bad = drop_variant("type15_bad_skew", 8, ["25", "50", "50"]);
    let out = common::crashsim(&[
        "run",
        bad.to_str().unwrap(),
        "--out",
        bad.parent().unwrap().to_str().unwrap(),
    ]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("skew_ID 8") && err.contains("/SURF/ELLIPS/10"),
        "{err}"
    );
}

#[test]
fn type15_is_identical_on_1_2_4_ranks_and_2_threads_with_the_plate_on_several_ranks() {
    let d = deck("type15_drop");
    for np in [2, 4] {
        let sec = interface_ranks(&d, np, 0).0.len();
        assert!(
            sec >= 2,
            "{np} ranks: the plate's segments on {sec} rank(s)"
        );
    }
    let one = run(&d, &scratch("type15_ranks_1"), &RunArgs::default());
    assert_same_final_state_on_ranks_and_2_threads(&d, "type15_ranks", &one, &[2, 4]);
}

#[test]
fn a_type15_run_restarted_on_another_rank_count_ends_identically() {
    let d = deck("type15_roll");
    let whole = run(&d, &scratch("type15_restart_whole"), &RunArgs::default());
    // Cycle 200 is in the middle of the sliding (its friction memory travels).
    assert_restart_2_to_1_ends_as(&d, "type15_restart_stop", 200, &whole);
}

#[test]
fn a_blank_stiffness_and_an_ellipsoid_of_secondary_segments_are_deck_errors() {
    let dir = scratch("type15_bad_stif");
    let d = common::deck_variant("type15_drop", &dir, |i, lines| {
        let at = lines.iter().position(|l| l.starts_with("/INTER/TYPE15"))?;
        (i == at + 5).then(String::new)
    });
    let out = common::crashsim(&["check", d.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("type15_drop_0000.rad:") && err.contains("Stif") && err.contains("> 0"),
        "{err}"
    );
    let dir = scratch("type15_bad_side");
    let d = common::deck_variant("type15_drop", &dir, |i, lines| {
        let at = lines.iter().position(|l| l.starts_with("/INTER/TYPE15"))?;
        (i == at + 3).then(|| format!("{:>10}{:>10}", 10, 10))
    });
    let out = common::crashsim(&["check", d.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("type15_drop_0000.rad:")
            && err.contains("surf_IDs")
            && err.contains("hyper-ellipsoid"),
        "{err}"
    );
}
