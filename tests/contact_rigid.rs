//! Rigid body contact (theory manual §8.7, TYPE6) on decks/make_rigid.py's
//! type6_rest: a rigid shell block (1 kg) pushed by W = 0.012 kN on a rigid
//! ground through /INTER/TYPE6 with a nonlinear loading curve f, FscaleId =
//! 2 and Ascalex = 0.5, damped by Visc on each penetrated node.
//!
//! - The block comes to rest at the penetration p* where the total force
//!   FscaleId·f(p*/Ascalex) balances W (EQ. 8.7.6.1: the interface's force
//!   is the curve's at its largest penetration, whatever the number of
//!   penetrated nodes), within 1% (it lands within 1e-6);
//! - the energy closes: the contact energy (elastic and damping) equals the
//!   load's work;
//! - the final state is byte-identical on 1, 2 and 4 ranks with the two
//!   surfaces on different ranks and on 1 and 2 threads (p_max and the
//!   resultant are reduced exactly over the ranks); a run stopped on 2 ranks
//!   and restarted on 1 ends identically;
//! - a surface not on a rigid body, and the options not computed, stop the
//!   run by name.

mod common;
#[path = "contact_common/mod.rs"]
mod contact_common;
use contact_common::*;

const W: f64 = 0.012;
const CURVE: [(f64, f64); 4] = [(0.0, 0.0), (0.01, 0.005), (0.02, 0.02), (0.05, 0.2)];
const FSCALE: f64 = 2.0;
const ASCALE: f64 = 0.5;

/// p* with FSCALE·f(p*/ASCALE) = W (f piecewise linear).
fn rest_penetration() -> f64 {
    let target = W / FSCALE;
    for s in CURVE.windows(2) {
        let ((x0, y0), (x1, y1)) = (s[0], s[1]);
        if (y0..=y1).contains(&target) {
            return ASCALE * (x0 + (x1 - x0) * (target - y0) / (y1 - y0));
        }
    }
    unreachable!("W is within the curve")
}

#[test]
fn a_type6_block_rests_where_the_load_curve_balances_its_load() {
    let r = run(
        &deck("type6_rest"),
        &scratch("type6_rest_1"),
        &RunArgs::default(),
    );
    assert!(r.listing.normal_termination());
    let p_star = rest_penetration();
    assert!((p_star - 0.0053333).abs() < 1e-6);
    let state = r.final_state();
    let block: Vec<&[f64; 6]> = (101..=109).map(|n| &state[&n]).collect();
    for s in &block {
        let p = -s[2];
        assert!(
            (p - p_star).abs() < 0.01 * p_star,
            "penetration {p}, expected {p_star}"
        );
        assert!(
            s[5].abs() < 1e-6 * p_star,
            "the block still moves: {}",
            s[5]
        );
    }
    // 9 block nodes on the ground, 4 ground nodes under the block.
    assert_eq!(r.listing.last(1).pairs, 13);
    let out = std::fs::read_to_string(r.dir.join("type6_rest.out")).unwrap();
    let closes = out
        .lines()
        .find(|l| l.contains("ENERGY BALANCE"))
        .and_then(|l| l.split("closes to ").nth(1))
        .and_then(|t| t.trim().trim_end_matches('%').parse::<f64>().ok())
        .expect("ENERGY BALANCE line");
    assert!(closes.abs() < 1.0, "energy closes to {closes}%");
}

#[test]
fn type6_is_identical_on_1_2_4_ranks_and_2_threads_with_a_cut_interface() {
    let d = deck("type6_rest");
    for np in [2, 4] {
        let v = common::crashsim_json(&[
            "partition",
            d.to_str().unwrap(),
            "--np",
            &np.to_string(),
            "--json",
        ]);
        let i = &v["interfaces"][0];
        let ranks = |k: &str| -> Vec<u64> {
            i[k].as_array()
                .unwrap()
                .iter()
                .map(|r| r.as_u64().unwrap())
                .collect()
        };
        let (sec, main) = (ranks("secondary_ranks"), ranks("main_ranks"));
        assert!(
            main.iter().any(|r| !sec.contains(r)) || sec.iter().any(|r| !main.contains(r)),
            "{np} ranks: the interface is not cut: {sec:?} {main:?}"
        );
    }
    let one = run(&d, &scratch("type6_ranks_1"), &RunArgs::default());
    assert_same_final_state_on_ranks_and_2_threads(&d, "type6_ranks", &one, &[2, 4]);
}

#[test]
fn a_type6_run_restarted_on_another_rank_count_ends_identically() {
    let d = deck("type6_rest");
    let whole = run(&d, &scratch("type6_restart_whole"), &RunArgs::default());
    assert_restart_2_to_1_ends_as(&d, "type6_restart_stop", 2000, &whole);
}

/// Runs a variant of type6_rest and returns (exit code, stderr).
fn run_variant(tag: &str, edit: impl Fn(usize, &[&str]) -> Option<String>) -> (i32, String) {
    let dir = scratch(tag);
    let d = common::deck_variant("type6_rest", &dir, edit);
    let out = common::crashsim(&[
        "run",
        d.to_str().unwrap(),
        "--out",
        dir.join("out").to_str().unwrap(),
    ]);
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn a_type6_surface_off_any_rigid_body_stops_the_run_by_name() {
    // The block's /RBODY (its 7 lines) left out: the block is a deformable shell.
    let (code, err) = run_variant("type6_no_body", |i, lines| {
        (0..7)
            .any(|k| i >= k && lines[i - k] == "/RBODY/2")
            .then(|| "#".to_string())
    });
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("/INTER/TYPE6/1") && err.contains("surf_ID1") && err.contains("/RBODY"),
        "{err}"
    );
}

#[test]
fn type6_options_it_does_not_compute_stop_the_run_by_name() {
    // Iform = 1 with an unloading curve and a transition stiffness.
    let (code, err) = run_variant("type6_iform", |i, lines| {
        if i >= 1 && lines[i - 1].starts_with("# fct_IDld") {
            Some(common::set_cols(lines[i], 10, 20, 1))
        } else if i >= 1 && lines[i - 1].starts_with("# fct_IDul") {
            Some(format!("{:>10}{:>10}{:>20}{:>20}", 2, "", "1.0", "1.0"))
        } else {
            None
        }
    });
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("/INTER/TYPE6/1") && err.contains("Iform"),
        "{err}"
    );
}
