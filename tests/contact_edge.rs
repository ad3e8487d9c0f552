//! Edge-to-edge contact (/INTER/TYPE11) on the crossing-plates decks of
//! decks/make_edge.py: two shell plates whose edges cross, no node of
//! either ever near the other's surface.
//!
//! - TYPE11 stops the pushed plate where the edge pair's force balances the
//!   load: its edge rests inside the sum of the two edges' gaps (half a
//!   thickness each, Igap = 1) at the penetration p that solves
//!   ½·K·g'·p/(g' − p) = load (g' = 0.9·g; K the two edges' stiffnesses
//!   E·t in series), and the interface's normal force is the load;
//! - self-contact on both plates' edges gives the same answer (each pair once);
//! - node-to-surface contact (TYPE7) alone lets the edges pass through, the
//!   case TYPE11 exists for (Theory Manual §8.4.2.1);
//! - TYPE25 with Iedge = 1 (self-contact of both plates, edge_cross_t25)
//!   stops the edges with its edge penalty: ½·K·(p − P0) balances the load
//!   (K the main edge's E·t, Istf 1000; P0 the penetration at the impact,
//!   under 1e-3 here), identical on 1, 2 and 4 ranks and 2 threads; without
//!   Iedge it lets them pass; Iedge 11 is refused by name;
//! - the final state is byte-identical on 1, 2 and 4 ranks, with partitions
//!   that put the two edges of the crossing pair on different ranks, and on
//!   1 and 2 threads; a restart on another rank count continues it exactly.

mod common;
#[path = "contact_common/mod.rs"]
mod contact_common;
use contact_common::*;

const E: f64 = 210.0;
const T: f64 = 1.0;
const LOAD: f64 = 10.0;

/// The pair stiffness (Istf 5: the edges' E·t in series, Stfac 1), the
/// pair gap (Igap 1: the sum of the half thicknesses) and the law's gap.
fn law() -> (f64, f64, f64) {
    let k = (E * T) * (E * T) / (E * T + E * T);
    let g = 0.5 * T + 0.5 * T;
    (k, g, 0.9 * g)
}

fn edge_force(p: f64) -> f64 {
    let (k, _, gl) = law();
    0.5 * k * gl * p / (gl - p)
}

/// The crossing pair's secondary edge is A's bottom middle edge, nodes 2, 3.
fn edge_height(r: &Run) -> f64 {
    let s = r.final_state();
    0.5 * (s[&2][2] + s[&3][2])
}

#[test]
fn crossing_edges_stop_where_the_edge_force_balances_the_load() {
    let r = run(
        &deck("edge_cross"),
        &scratch("edge_cross_1"),
        &RunArgs::default(),
    );
    assert!(r.listing.normal_termination());
    let (_, g, gl) = law();
    // B's top edge is fixed at z = 0: A's edge rests at distance d = g − p.
    let d = edge_height(&r);
    let p = g - d;
    assert!(p > 0.0 && p < gl, "the edge rests inside the gap: d = {d}");
    // The penetration where the law balances the load: p = load·g'/(½K·g' + load).
    let (k, _, _) = law();
    let p_expect = LOAD * gl / (0.5 * k * gl + LOAD);
    assert!(
        (p - p_expect).abs() < 0.01 * p_expect,
        "p = {p}, expected {p_expect}"
    );
    // The interface's force is the load, and the law's force at the measured p.
    let f = r.listing.last(1).normal[2];
    assert!((f - LOAD).abs() < 0.01 * LOAD, "normal force {f}");
    assert!(
        (f - edge_force(p)).abs() < 0.01 * f,
        "{f} against {}",
        edge_force(p)
    );
    assert_eq!(r.listing.last(1).pairs, 1);
    // A comes to rest.
    let s = r.final_state();
    assert!(s[&2][5].abs() < 0.01, "vz {}", s[&2][5]);
    // The run file's interface history has the pair's force and energy.
    let h5 = r.dir.join("edge_cross.h5");
    let got = common::python_check("interface_history.py", &[h5.as_os_str(), "1".as_ref()]);
    let v: Vec<f64> = got.split_whitespace().map(|w| w.parse().unwrap()).collect();
    assert_eq!((v[0], v[1]), (11.0, 1.0), "{got}");
    assert!((v[2] - LOAD).abs() < 0.01 * LOAD && v[3] > 0.0, "{got}");
}

#[test]
fn edge_self_contact_finds_the_crossing_pair_once() {
    let one = run(
        &deck("edge_cross"),
        &scratch("edge_cross_ref"),
        &RunArgs::default(),
    );
    let own = run(
        &deck("edge_cross_self"),
        &scratch("edge_cross_self"),
        &RunArgs::default(),
    );
    assert_eq!(own.listing.last(1).pairs, 1);
    let f = own.listing.last(1).normal[2];
    assert!((f - LOAD).abs() < 0.01 * LOAD, "normal force {f}");
    assert_eq!(edge_height(&own), edge_height(&one));
}

#[test]
fn type19_is_type7_both_ways_and_type11_and_stops_the_edges_as_type11_does() {
    let t11 = run(
        &deck("edge_cross"),
        &scratch("edge_cross_t11_ref"),
        &RunArgs::default(),
    );
    let t19 = run(
        &deck("edge_cross_t19"),
        &scratch("edge_cross_t19"),
        &RunArgs::default(),
    );
    // The card's id is the first TYPE7 (A's nodes on B); the second TYPE7
    // (B's nodes on A) and the TYPE11 take the next ids.
    let text = &t19.listing.text;
    for (id, ty) in [(1, "TYPE7 "), (2, "TYPE7 "), (3, "TYPE11")] {
        assert!(
            text.contains(&format!("INTER        {id} {ty}")),
            "interface {id} {ty}"
        );
    }
    assert!(t19
        .listing
        .of(1)
        .iter()
        .chain(t19.listing.of(2).iter())
        .all(|l| l.pairs == 0));
    assert_eq!(t19.listing.last(3).pairs, 1);
    // The default gap of the edge part (Igap 0: the default Gapmin, the mean
    // thickness 1 mm) is the sum of the half thicknesses: the same run.
    assert!(t19.final_state_bytes() == t11.final_state_bytes());
    assert_same_final_state_on_2_ranks(&deck("edge_cross_t19"), "edge_cross_t19_2", &t19);
}

/// Idel on TYPE11 (edge_cross_idel): B's shell under the crossing yields and
/// is deleted at about 0.12 ms while its neighbours still hold its top edge.
/// With Idel = 2 the edge leaves with its only shell (the listing says so)
/// and A falls through; with Idel = 0 the edge stays and A rests on it.
#[test]
fn an_edge_whose_shell_is_deleted_leaves_the_interface_with_idel() {
    let with = run(
        &deck("edge_cross_idel"),
        &scratch("edge_idel_2"),
        &RunArgs::default(),
    );
    assert!(with.listing.normal_termination());
    assert!(
        with.listing.text.contains("IDEL INTER        1 TYPE11")
            && with.listing.text.contains("REMOVED      4 MAIN EDGES"),
        "no Idel line in the listing"
    );
    assert!(
        edge_height(&with) < -3.0,
        "A fell through: {}",
        edge_height(&with)
    );
    let dir = scratch("edge_idel_0_deck");
    // Idel: columns 71-80 of the line below the "# line_IDs" comment.
    let d = common::deck_variant("edge_cross_idel", &dir, |i, lines| {
        (i >= 1 && lines[i - 1].starts_with("# line_IDs"))
            .then(|| common::set_cols(lines[i], 70, 80, 0))
    });
    let without = run(&d, &scratch("edge_idel_0"), &RunArgs::default());
    assert!(!without.listing.text.contains("IDEL INTER"));
    let h = edge_height(&without);
    assert!(
        h > 0.5 && h < 1.0,
        "A rests on B's edge inside the gap: {h}"
    );
    assert!((without.listing.last(1).normal[2] - LOAD).abs() < 0.02 * LOAD);
}

/// Inacti on TYPE11 (edge_cross_inacti: the crossing pair starts 0.05 mm
/// inside its 1 mm gap): 1 switches the secondary edge off, 2 the main edge
/// for it, and A falls through either way until its top edge (3 mm up)
/// crosses B's top edge and rests there, where the law balances the load.
/// (With 0 the pair pushes out with the energy stored in the initial
/// penetration, which the energy check reports.)
#[test]
fn inacti_switches_an_initially_penetrated_edge_pair_off() {
    for inacti in [1, 2] {
        let dir = scratch(&format!("edge_inacti_{inacti}_deck"));
        // Inacti: columns 31-40 of the line below the "#      IBC" comment.
        let d = common::deck_variant("edge_cross_inacti", &dir, |i, lines| {
            (i >= 1 && lines[i - 1].starts_with("#      IBC"))
                .then(|| common::set_cols(lines[i], 30, 40, inacti))
        });
        let r = run(
            &d,
            &scratch(&format!("edge_inacti_{inacti}")),
            &RunArgs::default(),
        );
        let h = edge_height(&r);
        assert!(
            h < -2.0,
            "Inacti {inacti}: A's bottom edge falls through: {h}"
        );
        assert!((r.listing.last(1).normal[2] - LOAD).abs() < 0.02 * LOAD);
    }
}

#[test]
fn node_to_surface_contact_alone_lets_the_edges_pass_through() {
    let r = run(
        &deck("edge_cross_t7"),
        &scratch("edge_cross_t7"),
        &RunArgs::default(),
    );
    assert!(r.listing.normal_termination());
    assert!(
        r.listing.of(1).iter().all(|l| l.pairs == 0),
        "TYPE7 found a pair"
    );
    let d = edge_height(&r);
    assert!(
        d < -3.0,
        "A's edge went through B (below B's bottom at z = -3): {d}"
    );
}

#[test]
fn type25_with_free_edges_stops_crossing_edges_with_its_edge_penalty() {
    let d = deck("edge_cross_t25");
    let r = run(&d, &scratch("edge_cross_t25_1"), &RunArgs::default());
    assert!(r.listing.normal_termination());
    // The edge part is interface 2, after the deck's ids.
    let last = r.listing.last(2);
    assert_eq!(last.pairs, 1);
    assert!(
        (last.normal[2] - LOAD).abs() < 0.01 * LOAD,
        "{:?}",
        last.normal
    );
    assert!(
        r.listing.of(1).iter().all(|l| l.pairs == 0),
        "the node part"
    );
    let p = 0.5 * T + 0.5 * T - edge_height(&r);
    let expect = 2.0 * LOAD / (E * T);
    assert!(
        (p - expect).abs() < 0.01 * expect,
        "p = {p}, expected {expect}"
    );
    assert_same_final_state_on_ranks_and_2_threads(&d, "edge_t25_ranks", &r, &[2, 4]);
    // Without Iedge the node part alone lets A through; Iedge 11 is refused.
    for (iedge, tag) in [(0, "edge_t25_off"), (11, "edge_t25_11")] {
        let dir = scratch(tag);
        let v = common::deck_variant("edge_cross_t25", &dir, |i, lines| {
            let at = lines.iter().position(|l| l.starts_with("/INTER/TYPE25"))?;
            (i == at + 3).then(|| format!("{}{iedge:>10}{}", &lines[i][..80], &lines[i][90..]))
        });
        if iedge == 0 {
            let r = run(&v, &dir.join("run"), &RunArgs::default());
            assert!(edge_height(&r) < -3.0, "A went through B");
        } else {
            let out =
                common::crashsim(&["run", v.to_str().unwrap(), "--out", dir.to_str().unwrap()]);
            let err = String::from_utf8_lossy(&out.stderr);
            assert_eq!(out.status.code(), Some(2), "{err}");
            assert!(err.contains("Iedge 11, 13, 22"), "{err}");
        }
    }
}

/// Ranks of the crossing pair's two shells (A's middle shell 2 and B's
/// middle shell 102, elements 1 and 4 in deck order) under `crashsim
/// partition --np N`.
fn pair_ranks(np: u32) -> (u64, u64) {
    let d = deck("edge_cross");
    let v = common::crashsim_json(&[
        "partition",
        d.to_str().unwrap(),
        "--np",
        &np.to_string(),
        "--json",
    ]);
    let part = v["part"].as_array().expect("part");
    (part[1].as_u64().unwrap(), part[4].as_u64().unwrap())
}

#[test]
fn edge_contact_is_identical_on_1_2_4_ranks_and_1_2_threads_with_a_cut_pair() {
    for np in [2, 4] {
        let (a, b) = pair_ranks(np);
        assert_ne!(
            a, b,
            "{np} ranks: the crossing edges must lie on different ranks"
        );
    }
    let d = deck("edge_cross");
    let one = run(&d, &scratch("edge_ranks_1"), &RunArgs::default());
    let f = one.listing.last(1).normal[2];
    assert!((f - LOAD).abs() < 0.01 * LOAD);
    assert_same_final_state_on_ranks_and_2_threads(&d, "edge_ranks", &one, &[2, 4]);
}

#[test]
fn an_edge_contact_run_restarted_on_another_rank_count_ends_identically() {
    let d = deck("edge_cross");
    let whole = run(&d, &scratch("edge_restart_whole"), &RunArgs::default());
    // Stopped on 2 ranks mid-load (pairs active), restarted on 1.
    assert_restart_2_to_1_ends_as(&d, "edge_restart_stop", 1500, &whole);
}
