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
//!
//! Iform 1 and 2 (type6_drop, type6_drop_ul): a block dropped at 1 mm/ms
//! rebounds with the energy of its unloading path (along Stiff down to
//! zero or to the unloading curve).
//!
//! Hyper-ellipsoid contact (§8.9, TYPE14) on type14_sphere: a rigid sphere
//! (/SURF/ELLIPS on a 10 kg /RBODY) dropped at v0 = 2 mm/ms on a fixed plate,
//! the total elastic force a nonlinear curve of the largest penetration:
//!
//! - the largest force is the curve's at the depth δ where its work equals
//!   the sphere's kinetic energy, ∫₀^δ f = ½Mv0², within 2%;
//! - the sphere rebounds with its kinetic energy (one curve loads and
//!   unloads), within 2%, and the energy closes with the contact energy;
//! - identical on 1, 2 and 4 ranks (the plate's nodes, whose reactions the
//!   body gathers, on several ranks) and 2 threads; restart 2 → 1.
//!
//! TYPE14's normal damper (type14_damped): a node bounces off a fixed sphere
//! with the restitution of a spring-dashpot of damping ratio Visc; its
//! friction (type14_slide): a node sliding on the ellipsoid is braked by
//! μ·W; its functions (fct_IDd1, fct_IDd2 set the damper's coefficient,
//! fct_IDf scales μ) on the same decks, against the same analytic answers.
//!
//! TYPE6's friction and damping curves (type6_slide): the products they
//! give, and the sliding block's acceleration (P − μW)/M.

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

/// How far the energy balance, contact energy included, closes (%).
fn energy_closes(r: &Run, name: &str) -> f64 {
    energy_balance(r, name).1
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
    let closes = energy_closes(&r, "type6_rest");
    assert!(closes.abs() < 1.0, "energy closes to {closes}%");
}

#[test]
fn type6_is_identical_on_1_2_4_ranks_and_2_threads_with_a_cut_interface() {
    let d = deck("type6_rest");
    for np in [2, 4] {
        let (sec, main) = interface_ranks(&d, np, 0);
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

/// Runs a variant of decks/NAME and returns (exit code, stderr).
fn run_variant(
    name: &str,
    tag: &str,
    edit: impl Fn(usize, &[&str]) -> Option<String>,
) -> (i32, String) {
    let dir = scratch(tag);
    let d = common::deck_variant(name, &dir, edit);
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
    let (code, err) = run_variant("type6_rest", "type6_no_body", |i, lines| {
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
    // Icor = 1 (columns 61-70 of the fct_IDld card) with Iform 2 and Stiff.
    let (code, err) = run_variant("type6_drop", "type6_icor", |i, lines| {
        (i >= 1 && lines[i - 1].starts_with("# fct_IDld"))
            .then(|| common::set_cols(lines[i], 60, 70, 1))
    });
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("/INTER/TYPE6/1") && err.contains("Icor"),
        "{err}"
    );
}

/// TYPE6's friction and damping curves (type6_slide, decks/make_rigid.py):
/// the block pressed by W and pushed sideways by P = W/2, Fric 0.4 with a
/// friction curve of the node's normal force (0.5) and one of its sliding
/// speed (0.75), and a damper given as Fscalev·g_dv(v_n)·g_df(F) with
/// g_dv(v) = v, g_df = ½, Fscalev = 2·Visc:
///
/// - it runs as the plain card with μ = 0.4·0.5·0.75 = 0.15 and Visc
///   (type6_slide_plain), within round-off;
/// - between 10 and 15 ms (settled, sliding at the cap) it accelerates at
///   (P − μW)/M, within 1%.
#[test]
fn type6_friction_and_damping_curves_act_as_their_factors() {
    let curves = run(
        &deck("type6_slide"),
        &scratch("type6_slide"),
        &RunArgs::default(),
    );
    let plain = run(
        &deck("type6_slide_plain"),
        &scratch("type6_slide_plain"),
        &RunArgs::default(),
    );
    let (a, b) = (curves.final_state(), plain.final_state());
    assert_eq!(a.len(), b.len());
    for (n, sa) in &a {
        for k in 0..6 {
            assert!(
                (sa[k] - b[n][k]).abs() < 1e-9,
                "node {n}, column {k}: {} with curves, {} plain",
                sa[k],
                b[n][k]
            );
        }
    }
    // The same run stopped at 10 ms.
    let dir = scratch("type6_slide_10");
    let engine = engine_variant(&deck("type6_slide"), &dir.join("engine"), -500, Some(10.0));
    let early = run(
        &deck("type6_slide"),
        &dir,
        &RunArgs {
            engine: Some(engine),
            ..Default::default()
        },
    );
    assert!(early.listing.normal_termination());
    let (mu, p, m) = (0.4 * 0.5 * 0.75, 0.5 * W, 1.0 + 7.85e-6 * 400.0);
    let accel = (a[&2000][3] - early.final_state()[&2000][3]) / 5.0;
    let expected = (p - mu * W) / m;
    assert!(
        (accel - expected).abs() < 0.01 * expected,
        "acceleration {accel}, expected (P - mu W)/M = {expected}"
    );
}

/// The block's vertical speed at the end of a run of decks/NAME, after it
/// left the ground (its main node, 2000).
fn rebound_speed(r: &Run) -> f64 {
    r.final_state()[&2000][5]
}

/// Iform 2 (type6_drop): the block hits the ground at v0 = 1 mm/ms, loads
/// on the linear curve K·p (K = 1 kN/mm) to ½Mv0² = ½K·p², unloads along
/// Stiff = 4 kN/mm to zero: it gives back F²/2Stiff = (K/Stiff)·½Mv0² and
/// leaves at v0·√(K/Stiff) = 0.5 mm/ms, within 1%. Iform 1 (type6_drop_ul):
/// along Stiff = 100 down to the unloading curve 0.25·K·p, then on it; the
/// energy given back is the area under that path, the share
/// (1 + q·x)(1 − x) + q·x² of ½K·p² (x = p_i/p, below), so it leaves at
/// 0.5056 mm/ms, within 1%.
/// Both byte-identical on 2 ranks; Iform 2 restarted mid-unloading from 2
/// ranks on 1 ends identically (the interface's memory travels).
#[test]
fn iform_1_and_2_give_back_the_energy_of_the_unloading_path() {
    let d = deck("type6_drop");
    let r = run(&d, &scratch("type6_drop_1"), &RunArgs::default());
    assert!(r.listing.normal_termination());
    let v = rebound_speed(&r);
    assert!(
        (v - 0.5).abs() < 0.005,
        "Iform 2: rebound {v}, expected 0.5"
    );
    assert_same_final_state_on_2_ranks(&d, "type6_drop_2", &r);
    assert_restart_2_to_1_ends_as(&d, "type6_drop_restart", 20, &r);
    // Iform 1: from (p, K·p) along Stiff S to the unloading curve q·K·p at
    // p_i = p·(S − K)/(S − qK), then on it to zero; per unit ½K·p².
    let (k, s, q): (f64, f64, f64) = (1.0, 100.0, 0.25);
    let x = (s - k) / (s - q * k);
    let share = (1.0 + q * x) * (1.0 - x) + q * x * x;
    let r = run(
        &deck("type6_drop_ul"),
        &scratch("type6_drop_ul_1"),
        &RunArgs::default(),
    );
    let v = rebound_speed(&r);
    let expect = share.sqrt();
    assert!(
        (v - expect).abs() < 0.01 * expect,
        "Iform 1: rebound {v}, expected {expect}"
    );
    assert!((v - 0.5).abs() > 0.004, "the Stiff segment counts: {v}");
}

const CURVE14: [(f64, f64); 3] = [(0.0, 0.0), (10.0, 0.5), (30.0, 4.5)];
const M_SPHERE: f64 = 10.0;
const V0_SPHERE: f64 = 2.0;

/// δ with ∫₀^δ f = ½·M·v0² (f piecewise linear, integrated exactly).
fn sphere_depth() -> f64 {
    let mut left = 0.5 * M_SPHERE * V0_SPHERE * V0_SPHERE;
    for s in CURVE14.windows(2) {
        let ((x0, y0), (x1, y1)) = (s[0], s[1]);
        let slope = (y1 - y0) / (x1 - x0);
        let area = 0.5 * (y0 + y1) * (x1 - x0);
        if area >= left {
            // y0·x + ½·slope·x² = left
            let x = (-y0 + (y0 * y0 + 2.0 * slope * left).sqrt()) / slope;
            return x0 + x;
        }
        left -= area;
    }
    unreachable!("the energy is within the curve")
}

fn curve14(p: f64) -> f64 {
    for s in CURVE14.windows(2) {
        let ((x0, y0), (x1, y1)) = (s[0], s[1]);
        if p <= x1 {
            return y0 + (y1 - y0) * (p - x0) / (x1 - x0);
        }
    }
    unreachable!("p is within the curve")
}

#[test]
fn a_type14_sphere_penetrates_as_its_load_curve_says_and_rebounds_with_its_energy() {
    let r = run(
        &deck("type14_sphere"),
        &scratch("type14_sphere_1"),
        &RunArgs::default(),
    );
    assert!(r.listing.normal_termination());
    let depth = sphere_depth();
    assert!((depth - 20.963).abs() < 1e-3, "{depth}");
    let f_peak = r
        .listing
        .of(1)
        .iter()
        .map(|l| -l.normal[2])
        .fold(0.0, f64::max);
    let expect = curve14(depth);
    assert!(
        (f_peak - expect).abs() < 0.02 * expect,
        "peak force {f_peak}, expected {expect} at the depth {depth}"
    );
    let state = r.final_state();
    let v = state[&1000][5];
    assert!(
        (v * v / (V0_SPHERE * V0_SPHERE) - 1.0).abs() < 0.02,
        "rebound speed {v}, expected {V0_SPHERE}"
    );
    assert!(
        r.listing.of(1).last().unwrap().pairs == 0,
        "the sphere left the plate"
    );
    let closes = energy_closes(&r, "type14_sphere");
    assert!(closes.abs() < 1.0, "energy closes to {closes}%");
}

#[test]
fn type14_is_identical_on_1_2_4_ranks_and_2_threads_with_the_nodes_on_several_ranks() {
    let d = deck("type14_sphere");
    for np in [2, 4] {
        let sec = interface_ranks(&d, np, 0).0.len();
        assert!(sec >= 2, "{np} ranks: the plate's nodes on {sec} rank(s)");
    }
    let one = run(&d, &scratch("type14_ranks_1"), &RunArgs::default());
    assert_same_final_state_on_ranks_and_2_threads(&d, "type14_ranks", &one, &[2, 4]);
}

#[test]
fn a_type14_run_restarted_on_another_rank_count_ends_identically() {
    let d = deck("type14_sphere");
    let whole = run(&d, &scratch("type14_restart_whole"), &RunArgs::default());
    // Cycle 300 is in the middle of the contact.
    assert_restart_2_to_1_ends_as(&d, "type14_restart_stop", 300, &whole);
}

/// `name` with TYPE14's function fields of card 1 set (fct_IDf columns
/// 31-40, fct_IDd1 41-50, fct_IDd2 51-60: (first column, id)) and, before
/// /END, constant curves (id, value) over −1e3..1e3; run, its final state.
fn type14_with_functions(
    name: &str,
    tag: &str,
    fields: &[(usize, i64)],
    curves: &[(i64, f64)],
) -> (Run, std::collections::BTreeMap<u64, [f64; 6]>) {
    let dir = scratch(tag);
    let d = common::deck_variant(name, &dir, |i, lines| {
        if i >= 1 && lines[i - 1].starts_with("#  grnd_IDs  surf_IDm") {
            let mut l = lines[i].to_string();
            for &(a, id) in fields {
                l = common::set_cols(&l, a, a + 10, id);
            }
            return Some(l);
        }
        (lines[i] == "/END").then(|| {
            let mut out = String::new();
            for &(id, v) in curves {
                out += &format!(
                    "/FUNCT/{id}\nconstant {v}\n{:>20}{:>20}\n{:>20}{:>20}\n",
                    -1e3, v, 1e3, v
                );
            }
            out + "/END"
        })
    });
    let r = run(&d, &dir.join("out"), &RunArgs::default());
    assert!(r.listing.normal_termination(), "{tag}");
    let s = r.final_state();
    (r, s)
}

/// TYPE14's damping functions (reference guide: fct_IDd1 the damping
/// coefficient against the normal speed, fct_IDd2 against the nodal
/// elastic force; c = Visc·g1·g2): on type14_damped (k = 1, m = 1,
/// Visc 0.1) g1 = 4 gives c = 0.4, ζ = 0.2, and the node comes back at
/// e·v0, e = exp(−ζπ/√(1 − ζ²)) = 0.5266, within 1%; g1 = 2 with g2 = 2
/// gives the same; the energy closes with the damper's work within 0.1%.
#[test]
fn type14_damping_functions_set_the_damper_s_coefficient() {
    let zeta: f64 = 0.2;
    let e = (-zeta * std::f64::consts::PI / (1.0 - zeta * zeta).sqrt()).exp();
    let (r, s) = type14_with_functions("type14_damped", "type14_fd1", &[(40, 7)], &[(7, 4.0)]);
    let v = s[&1][5];
    assert!(
        (v - e).abs() < 0.01 * e,
        "g1 = 4: rebound {v}, expected {e}"
    );
    let closes = energy_closes(&r, "type14_damped");
    assert!(closes.abs() < 0.1, "the energy closes to {closes}%");
    let (_, s2) = type14_with_functions(
        "type14_damped",
        "type14_fd12",
        &[(40, 7), (50, 8)],
        &[(7, 2.0), (8, 2.0)],
    );
    let v2 = s2[&1][5];
    assert!(
        (v2 - e).abs() < 0.01 * e,
        "g1 = g2 = 2: rebound {v2}, expected {e}"
    );
}

/// TYPE14's friction function (fct_IDf, the friction coefficient's factor
/// against the nodal elastic force): on type14_slide (W = 0.3 kN, Fric
/// 0.3) a factor 0.5 halves the Coulomb force to 0.045 kN at every printed
/// cycle while it slides (within 0.1%), and the node brakes as
/// v0 − 0.15·W·t/m within 0.01 mm/ms.
#[test]
fn type14_friction_function_scales_the_friction_coefficient() {
    let (r, s) = type14_with_functions("type14_slide", "type14_ff", &[(30, 7)], &[(7, 0.5)]);
    assert_braked(&r, &s, 0.15, 0.3);
}

/// TYPE14 Visc (type14_damped): a 1 kg node hits a fixed sphere at v0 =
/// 1 mm/ms on a linear spring k = 1 kN/mm with the damper Visc·2·√(k·m),
/// damping ratio ζ = 0.1. A spring-dashpot that lets go when the
/// penetration is back to 0 returns it at e·v0, e = exp(−ζπ/√(1 − ζ²)) =
/// 0.7292, within 1%; the energy closes with the contact energy (the
/// damper's work) within 0.1%.
#[test]
fn a_type14_damper_takes_the_energy_of_a_damped_half_period() {
    let r = run(
        &deck("type14_damped"),
        &scratch("type14_damped"),
        &RunArgs::default(),
    );
    assert!(r.listing.normal_termination());
    let zeta: f64 = 0.1;
    let e = (-zeta * std::f64::consts::PI / (1.0 - zeta * zeta).sqrt()).exp();
    let v = r.final_state()[&1][5];
    assert!((v - e).abs() < 0.01 * e, "rebound {v}, expected {e}");
    let closes = energy_closes(&r, "type14_damped");
    assert!(closes.abs() < 0.1, "the energy closes to {closes}%");
}

/// TYPE14 Fric (type14_slide): a 1 kg node pressed by W = 0.3 kN on a
/// fixed flat ellipsoid slides at 1 mm/ms. While it slides the friction
/// force is μ·W = 0.09 kN against its motion at every printed cycle
/// (within 0.1%), the normal force W, and it brakes as v = v0 − μ·W·t/m,
/// within 0.01 mm/ms at 5 ms (the impact's cycle takes no friction and
/// the tangential spring needs a step to reach μ·W: about 0.1 ms late).
#[test]
fn a_type14_node_sliding_on_the_ellipsoid_is_braked_by_coulomb_friction() {
    let r = run(
        &deck("type14_slide"),
        &scratch("type14_slide"),
        &RunArgs::default(),
    );
    assert!(r.listing.normal_termination());
    let s = r.final_state();
    assert_braked(&r, &s, 0.3, 0.3);
}

/// type14_slide's node, pressed by `w`, slides against friction μ·w at
/// every printed cycle after 0.2 ms (within 0.1%) under the normal force w,
/// and ends at v0 − μ·w·t/m (m = 1) within 0.01 mm/ms.
fn assert_braked(r: &Run, s: &std::collections::BTreeMap<u64, [f64; 6]>, mu: f64, w: f64) {
    let lines = r.listing.of(1);
    assert!(lines.len() >= 5);
    for l in lines.iter().filter(|l| l.t > 0.2) {
        assert!(
            (l.tangent[0] + mu * w).abs() < 1e-3 * mu * w,
            "t = {}: friction {:?}",
            l.t,
            l.tangent
        );
        assert!(
            (l.normal[2] - w).abs() < 1e-3 * w,
            "t = {}: {:?}",
            l.t,
            l.normal
        );
    }
    let t_end = r.listing.cycles.last().unwrap().t;
    let v = s[&1][3];
    let expect = 1.0 - mu * w * t_end;
    assert!(
        (v - expect).abs() < 0.01,
        "v = {v} at {t_end}, expected {expect}"
    );
}

#[test]
fn an_ellipsoid_with_a_zero_semi_axis_is_a_deck_error_at_its_line() {
    let dir = scratch("type14_bad_axis");
    let d = common::deck_variant("type14_sphere", &dir, |i, lines| {
        (i >= 1 && lines[i - 1].starts_with("#                  a"))
            .then(|| format!("{:>20}{:>20}{:>20}", "100", "0", "100"))
    });
    let out = common::crashsim(&["check", d.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("type14_sphere_0000.rad:")
            && err.contains("/SURF/ELLIPS/10")
            && err.contains("semi-axis"),
        "{err}"
    );
}

/// IRS and IRm (type6_drop): both surfaces written the other way round
/// (node2 and node4 of every shell swapped, normals facing away from each
/// other) with IRS = IRm = 1 give the block the rebound of the deck as
/// written, 0.5 mm/ms, to round-off; with IRS = IRm = 0 the ground's
/// segments face away from the block, which then falls through it.
#[test]
fn type6_irs_irm_1_turn_both_surfaces_round() {
    let flags = |v: i64| {
        move |i: usize, lines: &[&str]| {
            if i >= 1 && lines[i - 1].starts_with("#                 IRS") {
                return Some(common::set_cols(
                    &common::set_cols(lines[i], 10, 20, v),
                    20,
                    30,
                    v,
                ));
            }
            common::shell_reversed(i, lines)
        }
    };
    let dir = scratch("type6_irs1");
    let d = common::deck_variant("type6_drop", &dir, flags(1));
    let r = run(&d, &dir.join("out"), &RunArgs::default());
    assert!(r.listing.normal_termination());
    let v = rebound_speed(&r);
    assert!(
        (v - 0.5).abs() < 0.005,
        "IRS = IRm = 1 on the reversed surfaces: rebound {v}"
    );
    let dir0 = scratch("type6_irs0_rev");
    let d0 = common::deck_variant("type6_drop", &dir0, flags(0));
    let r0 = run(&d0, &dir0.join("out"), &RunArgs::default());
    let v0 = rebound_speed(&r0);
    assert!(
        v0 < -0.99,
        "IRS = IRm = 0 on the reversed surfaces: the block falls through, v = {v0}"
    );
}
