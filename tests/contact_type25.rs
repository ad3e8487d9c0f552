//! TYPE25 penalty contact on decks/make_type25.py's type25_block: a block
//! driven at a constant speed into a fixed block it starts 0.1 mm inside of.
//!
//! - The initial penetration is each pair's baseline: no force at the
//!   start, then only the further penetration pushes, F = 16 · ½K · v · t
//!   with K = B·A²/V of the lower block's 5 mm faces (Istf default: the main
//!   side's; EQ. 8.5.3.3 times two, the force taking half), within 1% at
//!   every printed cycle;
//! - the final state is byte-identical on 1, 2 and 4 ranks with the
//!   interface cut (secondary nodes and main segments on different ranks)
//!   and on 1 and 2 threads; a run stopped on 2 ranks and restarted on 1
//!   ends identically (the baselines travel in the restart file).

mod common;
#[path = "contact_common/mod.rs"]
mod contact_common;
use contact_common::*;

const V: f64 = 0.01;
const P0: f64 = 0.1;
const NODES: f64 = 16.0;

/// ½K of one pair: B·A²/V / 2 with B = E/(3(1 − 2ν)), A = 25 mm², V = 125 mm³.
fn half_k() -> f64 {
    let b = 210.0 / (3.0 * (1.0 - 2.0 * 0.3));
    0.5 * b * 25.0 * 25.0 / 125.0
}

/// The interface's normal force at every listed line is `slope`·t within 1%
/// (at least 5 lines).
fn grows_at(lines: &[InterLine], slope: f64) {
    assert!(lines.len() >= 5, "INTER lines: {}", lines.len());
    for l in lines {
        let expect = slope * l.t;
        let f = l.normal[2];
        assert!(
            (f - expect).abs() < 0.01 * expect,
            "t = {}: force {f}, expected {expect}",
            l.t
        );
    }
}

#[test]
fn an_initial_penetration_is_the_baseline_only_further_penetration_pushes() {
    let r = run(
        &deck("type25_block"),
        &scratch("type25_block_1"),
        &RunArgs::default(),
    );
    assert!(r.listing.normal_termination());
    let lines = r.listing.of(1);
    assert!(lines.len() >= 5, "INTER lines: {}", lines.len());
    for l in &lines {
        let expect = NODES * half_k() * V * l.t;
        let f = l.normal[2];
        assert!(
            (f - expect).abs() < 0.01 * expect,
            "t = {}: force {f}, expected {expect}",
            l.t
        );
        assert_eq!(l.pairs, 16);
        // Without the baseline the whole penetration would push, 0.1 mm more:
        // the force would be over 30 times this one.
        assert!(f < 0.05 * NODES * half_k() * (P0 + V * l.t));
    }
}

/// Istf = 5 (type25_block with the card's Istf rewritten): each pair's K
/// is the series of the lower face's B·A²/V and the upper node's stiffness,
/// which with Istf > 1 is the reference starter's assembled nodal value
/// B·(2·V_n)^(1/3), V_n the node's share of its bricks' volumes (V/8 each):
/// the upper block's corner, edge and inner bottom nodes (1, 2, 4 bricks of
/// 2.5 mm) get 276, 347 and 438, not one B·V^(1/3) = 438 for all. The force
/// grows as Σ ½K·v·t within 1%.
#[test]
fn istf_5_pairs_the_face_with_the_assembled_node_stiffness() {
    let dir = scratch("type25_block_istf5_deck");
    let d = common::deck_variant("type25_block", &dir, |i, lines| {
        (i >= 1 && lines[i - 1].starts_with("#  surf_ID1"))
            .then(|| common::set_cols(lines[i], 20, 30, 5))
    });
    let r = run(&d, &scratch("type25_block_istf5"), &RunArgs::default());
    assert!(r.listing.normal_termination());
    let b = 210.0 / (3.0 * (1.0 - 2.0 * 0.3));
    let km = 2.0 * half_k();
    let ks = |bricks: f64| b * (2.0 * bricks * 2.5f64.powi(3) / 8.0).cbrt();
    let series = |k: f64| km * k / (km + k);
    let sum_k = 4.0 * series(ks(1.0)) + 8.0 * series(ks(2.0)) + 4.0 * series(ks(4.0));
    grows_at(&r.listing.of(1), 0.5 * sum_k * V);
}

/// IPSTIF = 1 (type25_mass): each pair's stiffness is Stfac_mdt·m*/DTstif²
/// (the mass and time-step stiffness of LS-DYNA's SOFT = 1/2), m* the reduced
/// mass of the upper node and the lower face's point, which the 1 kg added on
/// each lower node makes the upper node's mass to 1e-4. The 16 upper nodes
/// carry 4.5 brick masses (4 corners 1/8, 8 edges 2/8, 4 inner 4/8).
/// Igap0 (type25_edge: a 1 mm plate's 4 free-edge nodes 0.3 mm over the
/// block, driven down at 1 mm/ms). With Igap0 = 1 they have no gap: the force
/// starts as they reach the face at 0.3 ms, 4·½K·v·(t − 0.3). With Igap0 = 0
/// their gap is half the thickness, 0.5 mm, so they start inside it (the
/// baseline) and the force is 4·½K·v·t. Within 1% plus one step's approach.
#[test]
fn igap0_takes_the_gap_off_free_shell_edges() {
    let slack = 4.0 * half_k() * 1.0 * 1e-3;
    for (igap0, onset) in [(1, 0.3), (0, 0.0)] {
        let dir = scratch(&format!("type25_edge_{igap0}_deck"));
        // Igap0: columns 41-50 of the line below the "#              Stmin" comment.
        let d = common::deck_variant("type25_edge", &dir, |i, lines| {
            (i >= 1 && lines[i - 1].starts_with("#              Stmin"))
                .then(|| common::set_cols(lines[i], 40, 50, igap0))
        });
        let r = run(
            &d,
            &scratch(&format!("type25_edge_{igap0}")),
            &RunArgs::default(),
        );
        let lines = r.listing.of(1);
        assert!(lines.len() >= 4);
        for l in &lines {
            let expect = 4.0 * half_k() * 1.0 * (l.t - onset).max(0.0);
            let f = l.normal[2];
            assert!(
                (f - expect).abs() < 0.01 * expect + slack,
                "Igap0 {igap0}, t = {}: force {f}, expected {expect}",
                l.t
            );
        }
    }
}

/// A face two solids share is no contact face until one of them is
/// deleted (type25_wake, /SURF/PART/ALL of A and B): C crushes B, B fails
/// and its faces leave (Idel = 1); C then falls through where B was and
/// meets A's top face, which B's deletion woke. Its 4 bottom nodes meet it
/// at t = 5.2 mm / 2 mm/ms = 2.6 ms and the force grows as 4·½K·v·(t − 2.6)
/// (K = B·A²/V of A's 5 mm face; A's nodes are fixed), within 1% plus one
/// step's approach. A face that stayed dormant would let C through: no
/// pair, no force. The run is byte-identical on 1, 2 and 4 ranks and 2
/// threads, through the deletion and the wake.
#[test]
fn a_face_between_two_solids_becomes_contact_when_one_of_them_is_deleted() {
    let d = deck("type25_wake");
    let r = run(&d, &scratch("type25_wake_1"), &RunArgs::default());
    assert!(r.listing.normal_termination());
    let out = std::fs::read_to_string(r.dir.join("type25_wake.out")).unwrap();
    assert!(
        out.lines()
            .any(|l| l.contains("IDEL INTER") && l.contains("REMOVED      5 MAIN SEGMENTS")),
        "B's 5 outer faces leave with it"
    );
    let slope = 4.0 * 0.5 * (175.0 * 25.0 * 25.0 / 125.0) * 2.0;
    // The baseline is the approach of one step before the impact: C's
    // brick step, 3.57e-4 ms (the contact's nodal step, 1.5e-4, comes after).
    let slack = slope * 3.6e-4;
    let on_a: Vec<_> = r.listing.of(1).into_iter().filter(|l| l.t > 2.6).collect();
    assert!(on_a.len() >= 10, "{} INTER lines on A", on_a.len());
    for l in &on_a {
        let expect = slope * (l.t - 2.6);
        let f = l.normal[2];
        assert!(
            (f - expect).abs() < 0.01 * expect + slack,
            "t = {}: force {f}, expected {expect}",
            l.t
        );
        assert_eq!(l.pairs, 4);
    }
    // Between B's deletion and A, C is free.
    assert!(r
        .listing
        .of(1)
        .iter()
        .any(|l| l.t > 0.5 && l.t < 2.5 && l.pairs == 0));
    assert_same_final_state_on_ranks_and_2_threads(&d, "type25_wake_ranks", &r, &[2, 4]);
}

#[test]
fn the_run_file_keeps_the_type25_interface_history() {
    let r = run(
        &deck("type25_block"),
        &scratch("type25_block_h5"),
        &RunArgs::default(),
    );
    let h5 = r.dir.join("type25_block.h5");
    let got = common::python_check("interface_history.py", &[h5.as_os_str(), "1".as_ref()]);
    let v: Vec<f64> = got.split_whitespace().map(|w| w.parse().unwrap()).collect();
    assert_eq!((v[0], v[1]), (25.0, 1.0), "{got}");
    let last = r.listing.last(1);
    assert!(
        (v[2] - last.normal[2]).abs() < 1e-3 * last.normal[2],
        "{got}"
    );
}

#[test]
fn the_mass_and_time_step_stiffness_pushes_with_stfac_mdt_m_over_dt_squared() {
    let r = run(
        &deck("type25_mass"),
        &scratch("type25_mass"),
        &RunArgs::default(),
    );
    assert!(r.listing.normal_termination());
    let brick = 2.5f64.powi(3) * 7.85e-6;
    let k_total = 0.2 * 4.5 * brick / (1e-4 * 1e-4);
    grows_at(&r.listing.of(1), 0.5 * k_total * V);
}

#[test]
fn type25_is_identical_on_1_2_4_ranks_and_2_threads_with_a_cut_interface() {
    let d = deck("type25_block");
    for np in [2, 4] {
        let (sec, main) = interface_ranks(&d, np, 0);
        assert!(
            sec.iter().any(|r| !main.contains(r)),
            "{np} ranks: the interface is not cut: {sec:?} {main:?}"
        );
    }
    let one = run(&d, &scratch("type25_ranks_1"), &RunArgs::default());
    assert_same_final_state_on_ranks_and_2_threads(&d, "type25_ranks", &one, &[2, 4]);
}

#[test]
fn a_type25_run_restarted_on_another_rank_count_ends_identically() {
    let d = deck("type25_block");
    let whole = run(&d, &scratch("type25_restart_whole"), &RunArgs::default());
    assert_restart_2_to_1_ends_as(&d, "type25_restart_stop", 1000, &whole);
}

/// decks/tube_fine with its TYPE7 replaced by a TYPE25 self-contact of the
/// tube's surface (/SURF/PART/5), Igap = `igap` (other fields the defaults).
fn tube_fine_type25(igap: i64, tag: &str) -> std::path::PathBuf {
    let i10 = |v: i64| format!("{v:>10}");
    let r20 = |v: f64| format!("{v:>20}");
    let card = [
        "/INTER/TYPE25/1".to_string(),
        "Tube self-contact".to_string(),
        i10(5)
            + &i10(0)
            + &i10(0)
            + &i10(0)
            + &i10(igap)
            + &i10(0)
            + &" ".repeat(10)
            + &i10(0)
            + &i10(0),
        i10(0) + &" ".repeat(10) + &r20(0.0).repeat(4),
        r20(0.0).repeat(2) + &i10(0) + &i10(0) + &r20(0.0),
        r20(0.0).repeat(5),
        format!("{:>10}", "000") + &" ".repeat(10) + &i10(0) + &i10(0) + &r20(0.0),
        i10(0).repeat(2) + &r20(0.0),
    ]
    .join("\n");
    common::deck_variant("tube_fine", &scratch(tag), |i, lines| {
        let start = lines.iter().position(|l| l.starts_with("/INTER/TYPE7/1"))?;
        let end = start + 1 + lines[start + 1..].iter().position(|l| l.starts_with('/'))?;
        if i == start {
            Some(card.clone())
        } else if (start + 1..end).contains(&i) {
            Some("#".to_string())
        } else {
            None
        }
    })
}

/// Igap = 2 (reference: the gap of Igap 1, and the Irem_gap = 2 lists of
/// TYPE7, `contact::close_neighbours`): the fine tube of 50 × 0.4 mm shells
/// under the 1.2 mm gap of its half thicknesses, flying free for 0.01 ms,
/// forms no pair (each node's neighbours within the gap lie within √2·gap
/// along the surface), and the shells set the step at every row; with
/// Igap = 1 the nodes along the tube's corners pair with the segments of
/// the next face within the gap from the first printed cycle.
#[test]
fn igap_2_leaves_out_the_neighbours_within_the_gap_of_a_fine_mesh() {
    let d = tube_fine_type25(2, "tube_fine_t25_igap2");
    let r = run(&d, &d.with_file_name("out"), &RunArgs::default());
    assert!(r.listing.normal_termination(), "{}", r.listing.text);
    assert!(!r.listing.inter.is_empty());
    for l in &r.listing.inter {
        assert_eq!(l.pairs, 0, "Igap 2: no pair at t = {}", l.t);
    }
    for c in &r.listing.cycles {
        assert_eq!(
            c.what, "SHELL",
            "the shells set the step at cycle {}",
            c.cycle
        );
    }
    let d1 = tube_fine_type25(1, "tube_fine_t25_igap1");
    let out = d1.with_file_name("out");
    let o = common::crashsim(&["run", d1.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    let text = String::from_utf8_lossy(&o.stdout);
    let pairs: Vec<u64> = text
        .lines()
        .filter(|l| l.trim_start().starts_with("INTER") && l.contains("PAIRS"))
        .filter_map(|l| l.split_whitespace().last()?.parse().ok())
        .collect();
    assert!(
        pairs.first().is_some_and(|&p| p > 0),
        "Igap 1: the neighbours within the gap pair up: {pairs:?}\n{text}"
    );
}

/// Igap = 3 (type25_edge, Igap0 = 0): each side's gap is at most
/// %mesh_size times its shortest edge. The plate's edge nodes (2.5 mm
/// shells, half thickness 0.5 mm) with %mesh_size 0.08 get 0.2 mm, the
/// block's faces none: starting 0.3 mm over the block they meet the gap at
/// 0.1 ms and the force grows as 4·½K·v·(t − 0.1), within 1% plus one
/// step's approach (with Igap 1 they start inside the 0.5 mm gap).
#[test]
fn igap_3_caps_the_gap_at_a_fraction_of_the_mesh_size() {
    let slack = 4.0 * half_k() * 1.0 * 1e-3;
    let dir = scratch("type25_edge_igap3_deck");
    let d = common::deck_variant("type25_edge", &dir, |i, lines| {
        let below = |c: &str| i >= 1 && lines[i - 1].starts_with(c);
        if below("#  surf_ID1") {
            Some(common::set_cols(lines[i], 40, 50, 3))
        } else if below("#  grnd_IDs") {
            Some(format!(
                "{}{:>20}{}",
                &lines[i][..40],
                "0.08",
                &lines[i][60..]
            ))
        } else if below("#              Stmin") {
            Some(common::set_cols(lines[i], 40, 50, 0))
        } else {
            None
        }
    });
    let r = run(&d, &scratch("type25_edge_igap3"), &RunArgs::default());
    assert!(r.listing.normal_termination(), "{}", r.listing.text);
    let lines = r.listing.of(1);
    assert!(lines.len() >= 4);
    for l in &lines {
        let expect = 4.0 * half_k() * 1.0 * (l.t - 0.1).max(0.0);
        let f = l.normal[2];
        assert!(
            (f - expect).abs() < 0.01 * expect + slack,
            "Igap 3, t = {}: force {f}, expected {expect}",
            l.t
        );
    }
}
