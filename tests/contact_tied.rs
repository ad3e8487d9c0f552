//! /INTER/TYPE2 (tied interface, standard kinematic formulation) on the decks
//! of decks/make_tied.py: a steel strip L = 100, W = 10, t = 1 (kg, mm, ms)
//! made of two non-matching shell meshes (10 x 3 and 10 x 2) tied along
//! x = 50, against the same strip meshed continuously (20 x 2):
//!
//! * bending (clamped, tip load, first peak at T1/2): the tip deflection of
//!   the tied strip is the continuous one's within 2 %, and far from the
//!   hinge a tie without rotations would make;
//! * pulling (ramped load, held): tip displacement within 2 % of the
//!   continuous strip and 5 % of P L / (E A);
//! * both: the tied nodes stay on their main segments to round-off;
//! * free flight with a tip load: momentum M v0 + P (t − Δt/2) to round-off,
//!   energy balance as closed as the continuous strip's, the same bytes on
//!   1, 2 and 4 ranks with the secondary and main nodes on different ranks;
//! * a shell plate tied onto a brick block (brick main nodes have no
//!   rotation: moments as force couples, rotation = the face's spin):
//!   momentum and energy in flight, 1 = 2 ranks;
//! * every option the engine does not compute exits 2 naming its field;
//! * large rotations (tied_spin, tied_spin_block): offset strips, and a plate
//!   0.5 above a brick block, spinning freely through 115°: the offsets turn
//!   with their segments, angular momentum about the centre of mass (with the
//!   masses the solver integrates) and energy kept, 1 = 2 ranks;
//! * a shell cantilever tied onto a brick block's face bends as a clamped one
//!   (tied_cant_block vs cont_bend), not as a hinge;
//! * Ignore = 1000: a secondary node out of dsearch is left free and named in
//!   a listing warning (tied_ignore = tied_free to the byte).

#[path = "contact_common/mod.rs"]
mod cc;
mod common;

use cc::*;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

const E: f64 = 210.0;
const RHO: f64 = 7.85e-6;

/// Secondary nodes (fine edge at x = 50, y = 0, 10/3, 20/3, 10) and the
/// coarse edge's main nodes (y = 0, 5, 10).
const SEC: [u64; 4] = [11, 22, 33, 44];
const MAIN: [u64; 3] = [1001, 1012, 1023];
const TIP_TIED: u64 = 1022;
const TIP_CONT: u64 = 42;

fn state(name: &str, tag: &str, a: &RunArgs) -> (Run, BTreeMap<u64, [f64; 6]>) {
    let dir = scratch(&format!("tied-{tag}"));
    let r = run(&deck(name), &dir, a);
    let s = r.final_state();
    (r, s)
}

/// Each secondary node lies where its shape functions put it on the main edge:
/// x_s = (1 − η) x_a + η x_b, η its initial fraction along the edge.
fn assert_on_segments(s: &BTreeMap<u64, [f64; 6]>) {
    for (j, &n) in SEC.iter().enumerate() {
        let y0 = 10.0 * j as f64 / 3.0;
        let (a, b, eta) = if y0 <= 5.0 {
            (MAIN[0], MAIN[1], y0 / 5.0)
        } else {
            (MAIN[1], MAIN[2], (y0 - 5.0) / 5.0)
        };
        for k in 0..3 {
            let want = (1.0 - eta) * s[&a][k] + eta * s[&b][k];
            let got = s[&n][k];
            assert!(
                (got - want).abs() < 1e-11 * (1.0 + want.abs()),
                "node {n} component {k}: {got} off its segment ({want})"
            );
            // Velocities too.
            let want_v = (1.0 - eta) * s[&a][3 + k] + eta * s[&b][3 + k];
            assert!((s[&n][3 + k] - want_v).abs() < 1e-12 * (1.0 + want_v.abs()));
        }
    }
}

#[test]
fn a_tied_bent_strip_deflects_as_the_continuous_one_not_as_a_hinge() {
    let (r, tied) = state("tied_bend", "bend", &RunArgs::default());
    let (_, cont) = state("cont_bend", "bend-c", &RunArgs::default());
    let wt = tied[&TIP_TIED][2];
    let wc = cont[&TIP_CONT][2];
    let ratio = wt / wc;
    eprintln!("bending: tip w tied {wt:.6e}, continuous {wc:.6e}, ratio {ratio:.5}");
    assert!((ratio - 1.0).abs() < 0.02, "ratio {ratio}");
    // A tie without rotations is a hinge at x = 50: the outer half (mass m2,
    // length a) turns about it under P, w_tip ≈ ½·(3P/m2)·t² at t = 5.984.
    let m2 = RHO * 1.0 * 10.0 * 50.0;
    let hinge = 0.5 * 3.0 * 5.25e-5 / m2 * 5.984f64.powi(2);
    eprintln!(
        "bending: a hinge would give ~{hinge:.4} mm ({:.1} x)",
        hinge / wc
    );
    assert!(hinge > 3.0 * wt);
    // The statics: first peak ~2x the static P L³/(3EI) = 0.1 mm.
    assert!(wt > 0.17 && wt < 0.22, "{wt}");
    assert_on_segments(&tied);
    // The joint rotates with the main edge: secondary rotations interpolated.
    let txt = std::fs::read_to_string(r.dir.join("final_state.csv")).unwrap();
    let rows: BTreeMap<u64, Vec<f64>> = txt
        .lines()
        .skip(1)
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
            (v[0] as u64, v[7..10].to_vec())
        })
        .collect();
    let wy = (rows[&MAIN[0]][1] + rows[&MAIN[1]][1]) / 2.0;
    assert!(wy.abs() > 0.0);
    let w22 = rows[&22][1];
    let want = rows[&MAIN[0]][1] / 3.0 + 2.0 * rows[&MAIN[1]][1] / 3.0;
    assert!(
        (w22 - want).abs() < 1e-12 * (1.0 + want.abs()),
        "{w22} vs {want}"
    );
    // The listing names the interface.
    assert!(r
        .listing
        .text
        .contains("/INTER/TYPE2/1: 4 secondary nodes tied"));
    assert!(r
        .listing
        .text
        .contains("INTER        1 TYPE2  TIED NODES      4"));
    // The run file lists the tie with the interfaces, and its time history
    // carries the force and moment resultants the listing prints (last line
    // and last sample: the final cycle).
    let f = hdf5::File::open(r.dir.join("tied_bend.h5")).unwrap();
    let ty = f
        .dataset("mesh/interfaces/type")
        .unwrap()
        .read_raw::<u32>()
        .unwrap();
    let id = f
        .dataset("mesh/interfaces/id")
        .unwrap()
        .read_raw::<u64>()
        .unwrap();
    assert_eq!((ty, id), (vec![2], vec![1]));
    let (sh, v) = crashsim::output::runfile::read_th(&f, "interfaces").unwrap();
    assert_eq!(sh[1..], [1, 13]);
    let last = &v[13 * (sh[0] - 1)..13 * sh[0]];
    let line = r
        .listing
        .text
        .lines()
        .rfind(|l| l.contains("TYPE2  TIED NODES"))
        .unwrap();
    let w: Vec<&str> = line.split_whitespace().collect();
    let num = |k: &str, j: usize| -> f64 {
        let i = w.iter().position(|x| *x == k).unwrap();
        w[i + 1 + j].parse().unwrap()
    };
    eprintln!("bending: last tied force/moment sample {:?}", &last[7..13]);
    assert!(last[..7].iter().all(|&x| x == 0.0), "{last:?}");
    for (c, want) in [(9, num("FORCE", 2)), (11, num("MOMENT", 1))] {
        assert!(
            (last[c] - want).abs() <= 1e-5 * want.abs() && want != 0.0,
            "column {c}: {} vs listing {want}",
            last[c]
        );
    }
}

#[test]
fn a_tied_pulled_strip_stretches_as_the_continuous_one() {
    let (_, tied) = state("tied_pull", "pull", &RunArgs::default());
    let (_, cont) = state("cont_pull", "pull-c", &RunArgs::default());
    let ut = tied[&TIP_TIED][0] - 100.0;
    let uc = cont[&TIP_CONT][0] - 100.0;
    let stat = 0.21 * 100.0 / (E * 10.0);
    eprintln!(
        "pull: tip u tied {ut:.6e}, continuous {uc:.6e}, ratio {:.5}, static {stat:.4e}",
        ut / uc
    );
    assert!((ut / uc - 1.0).abs() < 0.02);
    assert!((ut / stat - 1.0).abs() < 0.05);
    assert_on_segments(&tied);
}

/// Σ m v with the lumped masses of the deck (the secondary nodes' own masses).
fn momentum(deck: &Path, s: &BTreeMap<u64, [f64; 6]>) -> ([f64; 3], f64) {
    let m = shell_masses(&read_mesh(deck), RHO, 1.0, &[]);
    let mut p = [0.0; 3];
    let mut total = 0.0;
    for (id, mi) in &m {
        total += mi;
        for k in 0..3 {
            p[k] += mi * s[id][3 + k];
        }
    }
    (p, total)
}

#[test]
fn a_flying_tied_strip_keeps_momentum_and_energy_and_bytes_on_1_2_4_ranks() {
    let d = deck("tied_free");
    let a = RunArgs {
        energies: true,
        ..Default::default()
    };
    let (r1, s1) = state("tied_free", "free1", &a);
    // Momentum: M v0 + P (t_N − Δt_N/2) (the last half step), to round-off.
    let (_, rows) = r1.energies();
    let n = rows.len();
    let t_end = rows[n - 1][0];
    let dt_last = rows[n - 1][0] - rows[n - 2][0];
    let (p, mtot) = momentum(&d, &s1);
    let want = [
        mtot * 1.0,
        0.0,
        mtot * 0.5 + 5.25e-3 * (t_end - 0.5 * dt_last),
    ];
    let err = (0..3)
        .map(|k| (p[k] - want[k]).abs())
        .fold(0.0f64, f64::max)
        / (mtot * 1.0);
    eprintln!(
        "free flight: momentum {p:?}, expected {want:?}, error {err:.2e} (relative to M·|v0x|)"
    );
    assert!(err < 1e-12, "momentum error {err}");
    // Energy balance: internal + hourglass + kinetic − initial kinetic − external work,
    // against the continuous strip in the same flight.
    let balance = |rows: &Vec<Vec<f64>>| {
        let l = rows.last().unwrap();
        let ke0 = 0.5 * mtot * (1.0 + 0.25);
        (l[3] + l[8] + l[4] + l[5] - ke0 - l[6]) / l[6]
    };
    let bt = balance(&rows);
    let (rc, _) = state("cont_free", "free-c", &a);
    let bc = balance(&rc.energies().1);
    eprintln!(
        "free flight: energy balance tied {bt:.3e}, continuous {bc:.3e} (of the external work)"
    );
    assert!(bt.abs() < 1e-3 && bt.abs() <= 2.0 * bc.abs() + 1e-5);
    // The partition puts the secondary and main nodes on different ranks.
    let part = common::crashsim_json(&["partition", d.to_str().unwrap(), "--np", "2", "--json"]);
    let it = &part["interfaces"][0];
    assert_eq!(it["type"], 2);
    assert_ne!(it["main_ranks"], it["secondary_ranks"], "{it}");
    let b1 = r1.final_state_bytes();
    for np in [2u32, 4] {
        let rn = run(
            &d,
            &scratch(&format!("tied-free{np}")),
            &RunArgs {
                ranks: np,
                ..Default::default()
            },
        );
        assert!(rn.final_state_bytes() == b1, "{np} ranks differ from 1");
    }
}

/// A copy of tied_bend with its starter text changed by `edit`.
fn variant(tag: &str, edit: &dyn Fn(String) -> String) -> PathBuf {
    let src = deck("tied_bend");
    let dir = scratch(&format!("tied-refuse-{tag}"));
    let text = std::fs::read_to_string(&src).unwrap();
    let new = edit(text.clone());
    assert_ne!(new, text, "{tag}: the edit changed nothing");
    let p = dir.join("tied_bend_0000.rad");
    std::fs::write(&p, new).unwrap();
    std::fs::copy(
        src.with_file_name("tied_bend_0001.rad"),
        dir.join("tied_bend_0001.rad"),
    )
    .unwrap();
    p
}

const CARD: &str = "        10        20         0         0         0         0         0         0                   0";

fn card(ignore: i64, spot: i64, level: i64, isearch: i64, idel2: i64) -> String {
    format!(
        "{:>10}{:>10}{ignore:>10}{spot:>10}{level:>10}{isearch:>10}{idel2:>10}{:>10}{:>20}",
        10, 20, 0, 0
    )
}

fn refused(deck: &Path, expect: &[&str]) {
    let out = common::crashsim(&[
        "run",
        deck.to_str().unwrap(),
        "--out",
        deck.parent().unwrap().join("out").to_str().unwrap(),
    ]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{expect:?}: stderr {err}");
    for e in expect {
        assert!(err.contains(e), "stderr lacks '{e}': {err}");
    }
    assert!(!err.contains("panicked"));
}

/// Spotflag 4 (rotations not transmitted, LS-DYNA's tied nodes and
/// surfaces): the same bent strip is a hinge at x = 50. The tied nodes
/// follow their segments' translations to round-off; the tip goes several
/// times as far as the continuous strip's, as far as the hinge
/// estimate of the bending test (the rigid outer half turning about the
/// hinge) within 2 %.
#[test]
fn spotflag_4_ties_translations_only_and_the_strip_hinges() {
    let d = variant("spot4-hinge", &|t: String| {
        t.replace(CARD, &card(0, 4, 0, 0, 0))
    });
    let r = run(&d, &d.parent().unwrap().join("out"), &RunArgs::default());
    let tied = r.final_state();
    let (_, cont) = state("cont_bend", "bend-c4", &RunArgs::default());
    let (wt, wc) = (tied[&TIP_TIED][2], cont[&TIP_CONT][2]);
    let m2 = RHO * 1.0 * 10.0 * 50.0;
    let hinge = 0.5 * 3.0 * 5.25e-5 / m2 * 5.984f64.powi(2);
    eprintln!("Spotflag 4: tip w {wt:.5}, continuous {wc:.5}, hinge estimate {hinge:.5}");
    assert!(wt > 3.0 * wc, "a hinge: {wt} vs continuous {wc}");
    assert!(
        (wt / hinge - 1.0).abs() < 0.25,
        "{wt} vs the hinge estimate {hinge}"
    );
    assert_on_segments(&tied);
}

#[test]
fn type2_options_the_engine_does_not_compute_are_refused_by_field() {
    let with = |c: String| move |t: String| t.replace(CARD, &c);
    for (tag, c, field) in [
        ("spot1", card(0, 1, 0, 0, 0), "Spotflag = 1"),
        ("spot2", card(0, 2, 0, 0, 0), "Spotflag = 2"),
        ("spot3", card(0, 3, 0, 0, 0), "Spotflag = 3"),
        ("spot30", card(0, 30, 0, 0, 0), "Spotflag = 30"),
        ("level", card(0, 0, 1, 0, 0), "field Level"),
        ("isearch", card(0, 0, 0, 1, 0), "field Isearch"),
        ("idel2", card(0, 0, 0, 0, 2), "field Idel2"),
        ("ignore2", card(2, 0, 0, 0, 0), "field Ignore"),
    ] {
        let d = variant(tag, &with(c));
        refused(
            &d,
            &[
                "tied_bend_0000.rad:",
                "/INTER/TYPE2/1",
                field,
                "not supported by the engine yet",
            ],
        );
    }
    // The penalty formulation (with its card) and heat transfer.
    let d = variant("spot25", &|t: String| {
        t.replace(
            CARD,
            &(card(0, 25, 0, 0, 0)
                + "\n                   0                   0                             0"),
        )
    });
    refused(
        &d,
        &["/INTER/TYPE2/1", "field Spotflag", "Spotflag = 25 (penalty"],
    );
    let d = variant("ithe", &|t: String| {
        t.replace(CARD, &format!("{CARD}\n         1                   1"))
    });
    refused(&d, &["/INTER/TYPE2/1", "field Ithe", "heat transfer"]);
    // Conflicting kinematic conditions on a secondary node.
    let d = variant("bcs", &|t: String| {
        t.replace("/END", "/BCS/9\nconflict\n#  Tra rot   skew_ID  grnod_ID\n   100 000         0        10\n/END")
    });
    refused(
        &d,
        &["/INTER/TYPE2/1", "grnd_IDs", "secondary node 11", "/BCS/9"],
    );
    // A node tied twice.
    let d = variant("twice", &|t: String| {
        t.replace("/END", "/INTER/TYPE2/2\nagain\n        10        20\n/END")
    });
    refused(
        &d,
        &[
            "/INTER/TYPE2/2",
            "grnd_IDs",
            "already a secondary node of /INTER/TYPE2/1",
        ],
    );
    // A secondary node on its own main surface.
    let d = variant("self", &|t: String| {
        t.replace(
            "/END",
            "/GRNOD/NODE/16\nmain node\n      1001\n/INTER/TYPE2/3\nself\n        16        20\n/END",
        )
    });
    refused(
        &d,
        &[
            "/INTER/TYPE2/3",
            "grnd_IDs",
            "node 1001 is both a secondary node",
        ],
    );
}

#[test]
fn a_shell_plate_tied_onto_a_brick_block_flies_with_its_momentum_and_energy() {
    // Main nodes on bricks carry no rotation: only the translation is tied,
    // the plate nodes keep their own rotations.
    let d = deck("tied_plate_block");
    let a = RunArgs {
        energies: true,
        ..Default::default()
    };
    let (r1, s1) = state("tied_plate_block", "pb1", &a);
    assert!(r1.listing.text.contains(
        "28 secondary nodes tied (Spotflag 5, standard kinematic formulation), 0 with rotations"
    ));
    let (_, rows) = r1.energies();
    let n = rows.len();
    let t_end = rows[n - 1][0];
    let dt_last = rows[n - 1][0] - rows[n - 2][0];
    let mesh = read_mesh(&d);
    let mut m = shell_masses(&mesh, RHO, 1.0, &[1]);
    for (id, mi) in brick_masses(&mesh, RHO, &[2]) {
        *m.entry(id).or_insert(0.0) += mi;
    }
    let mut p = [0.0; 3];
    let mut mtot = 0.0;
    for (id, mi) in &m {
        mtot += mi;
        for k in 0..3 {
            p[k] += mi * s1[id][3 + k];
        }
    }
    let want = [mtot, 0.0, 0.5 * mtot + 5.25e-3 * (t_end - 0.5 * dt_last)];
    let err = (0..3)
        .map(|k| (p[k] - want[k]).abs())
        .fold(0.0f64, f64::max)
        / mtot;
    eprintln!("plate on block: momentum error {err:.2e}");
    assert!(err < 1e-12, "momentum error {err}");
    let l = rows.last().unwrap();
    let bal = (l[3] + l[8] + l[4] + l[5] - 0.5 * mtot * 1.25 - l[6]) / l[6];
    eprintln!("plate on block: energy balance {bal:.3e} of the external work");
    assert!(bal.abs() < 2e-3, "{bal}");
    // Secondary (plate) and main (block) nodes partly on different ranks.
    assert_same_final_state_on_2_ranks(&d, "tied-pb2", &r1);
}

type V3 = [f64; 3];

/// Final state with rotational velocities: id → [x, v, ω].
fn full_state(r: &Run) -> BTreeMap<u64, [V3; 3]> {
    let (h, rows) = read_csv(&r.dir.join("final_state.csv"));
    assert_eq!(h[7], "vrx");
    rows.iter()
        .map(|r| {
            (
                r[0] as u64,
                [[r[1], r[2], r[3]], [r[4], r[5], r[6]], [r[7], r[8], r[9]]],
            )
        })
        .collect()
}

/// Nodal rotational inertias of 4-node shells (Ishell < 11): dm·(A/9 + t²/12)
/// (src/model/mass.rs).
fn shell_inertias(m: &cc::Mesh, rho: f64, t: f64) -> BTreeMap<u64, f64> {
    let mut out = BTreeMap::new();
    for (_, _, n) in &m.shells {
        let x = n.map(|i| m.nodes[&i]);
        let a = 0.5 * norm(cross(sub(x[2], x[0]), sub(x[3], x[1])));
        let dm = rho * a * t / 4.0;
        for i in n {
            *out.entry(*i).or_insert(0.0) += dm * (a / 9.0 + t * t / 12.0);
        }
    }
    out
}

/// One tie as the test sees it: secondary node, main nodes with Φ_i.
struct TieT {
    sec: u64,
    main: Vec<(u64, f64)>,
    /// Three main nodes of its segment: origin, along, across.
    frame: [u64; 3],
}

/// The masses and inertias the solver integrates: each secondary node's mass
/// on its main nodes by Φ_i, its inertia Φ_i (I_s + m_s d²) where the main
/// nodes rotate (`rot`), the secondary nodes themselves left out.
fn solver_masses(
    m: &BTreeMap<u64, f64>,
    inr: &BTreeMap<u64, f64>,
    ties: &[TieT],
    d: f64,
    rot: bool,
) -> BTreeMap<u64, (f64, f64)> {
    let mut out: BTreeMap<u64, (f64, f64)> = m
        .iter()
        .map(|(&id, &mi)| (id, (mi, *inr.get(&id).unwrap_or(&0.0))))
        .collect();
    for t in ties {
        let (ms, is) = out.remove(&t.sec).unwrap();
        for &(q, phi) in &t.main {
            let e = out.get_mut(&q).unwrap();
            e.0 += phi * ms;
            if rot {
                e.1 += phi * (is + ms * d * d);
            }
        }
    }
    out
}

/// Angular momentum about the centre of mass: Σ m (x − c) × (v − v_c) + Σ I ω.
fn angular_momentum(mi: &BTreeMap<u64, (f64, f64)>, s: &BTreeMap<u64, [V3; 3]>) -> V3 {
    let mt: f64 = mi.values().map(|x| x.0).sum();
    let mut c = [0.0; 3];
    let mut vc = [0.0; 3];
    for (id, &(m, _)) in mi {
        for k in 0..3 {
            c[k] += m * s[id][0][k] / mt;
            vc[k] += m * s[id][1][k] / mt;
        }
    }
    let mut h = [0.0; 3];
    for (id, &(m, i)) in mi {
        let hc = cross(sub(s[id][0], c), sub(s[id][1], vc));
        for k in 0..3 {
            h[k] += m * hc[k] + i * s[id][2][k];
        }
    }
    h
}

/// The deck's initial state of a spin ω0 = (1, 0, 0) about the centre of the
/// own nodal masses `m` (decks/make_tied.py spin_velocities).
fn spin_initial(mesh: &cc::Mesh, m: &BTreeMap<u64, f64>) -> BTreeMap<u64, [V3; 3]> {
    let mt: f64 = m.values().sum();
    let c = [0, 1, 2].map(|k| m.iter().map(|(id, mi)| mi * mesh.nodes[id][k]).sum::<f64>() / mt);
    let w = [1.0, 0.0, 0.0];
    mesh.nodes
        .iter()
        .map(|(&id, &x)| (id, [x, cross(w, sub(x, c)), w]))
        .collect()
}

/// Components of r in the frame (b − a, normal) of three main nodes.
fn local(a: V3, b: V3, c: V3, r: V3) -> V3 {
    let unit = |v: V3| {
        let n = norm(v);
        [v[0] / n, v[1] / n, v[2] / n]
    };
    let e1 = unit(sub(b, a));
    let n = unit(cross(e1, sub(c, a)));
    let e2 = cross(n, e1);
    [dot(r, e1), dot(r, e2), dot(r, n)]
}

/// Secondary node placement checks: |x_s − p| = |d0| and the offset's
/// components in the segment's chord frame (a, b, c) as at t = 0; returns the
/// worst relative changes (of |d0|) of the distance, of the components, and
/// of the components' mean over the ties.
fn placement(
    mesh: &cc::Mesh,
    s: &BTreeMap<u64, [V3; 3]>,
    ties: &[TieT],
    d0: f64,
) -> (f64, f64, f64) {
    let (mut ed, mut el) = (0.0f64, 0.0f64);
    let mut mean = [0.0; 3];
    for t in ties {
        let p = |pos: &dyn Fn(u64) -> V3| {
            let mut p = [0.0; 3];
            for &(q, phi) in &t.main {
                for (pk, xk) in p.iter_mut().zip(pos(q)) {
                    *pk += phi * xk;
                }
            }
            p
        };
        let now = |q: u64| s[&q][0];
        let then = |q: u64| mesh.nodes[&q];
        let d1 = sub(s[&t.sec][0], p(&now));
        ed = ed.max((norm(d1) - d0).abs() / d0);
        let [a, b, c] = t.frame;
        let l1 = local(now(a), now(b), now(c), d1);
        let l0 = local(then(a), then(b), then(c), sub(then(t.sec), p(&then)));
        el = el.max(norm(sub(l1, l0)) / d0);
        for k in 0..3 {
            mean[k] += (l1[k] - l0[k]) / d0 / ties.len() as f64;
        }
    }
    (ed, el, norm(mean))
}

/// Energy balance of a free flight (no external work): change of
/// internal + kinetic + rotational kinetic energy, relative to the kinetic.
fn free_balance(r: &Run) -> f64 {
    let (_, rows) = r.energies();
    let (a, b) = (&rows[0], rows.last().unwrap());
    assert_eq!(b[6], 0.0);
    ((b[3] + b[4] + b[5]) - (a[3] + a[4] + a[5])) / (a[4] + a[5])
}

#[test]
fn a_spinning_offset_tie_turns_with_its_segment_and_keeps_angular_momentum() {
    // Strip 2 (z = 0.4) tied by its nodes at x = 45, 50 (y = 0, 10/3, 20/3, 10)
    // onto the edges x = 45, 50 of strip 1 (y = 0, 5, 10): Φ linear along y.
    let d = deck("tied_spin");
    let mesh = read_mesh(&d);
    let main = |i: u64, j: u64| 1 + i + 11 * j;
    let mut ties = Vec::new();
    for i in 0..2u64 {
        for j in 0..4u64 {
            let y = 10.0 * j as f64 / 3.0;
            let (lo, eta) = if y <= 5.0 {
                (0, y / 5.0)
            } else {
                (1, (y - 5.0) / 5.0)
            };
            ties.push(TieT {
                sec: 1001 + i + 12 * j,
                main: vec![(main(9 + i, lo), 1.0 - eta), (main(9 + i, lo + 1), eta)],
                frame: [main(9, lo), main(10, lo), main(9, lo + 1)],
            });
        }
    }
    let a = RunArgs {
        energies: true,
        ..Default::default()
    };
    let (r1, _) = state("tied_spin", "spin1", &a);
    let s1 = full_state(&r1);
    // It turned by more than 90° about x.
    let e = sub(s1[&main(0, 2)][0], s1[&main(0, 0)][0]);
    let angle = e[2].atan2(e[1]);
    // Placement: distance to the projection and local coordinates.
    let (ed, el, em) = placement(&mesh, &s1, &ties, 0.4);
    // A d kept in the global frame would have moved the node by 2|d| sin(θ/2).
    eprintln!(
        "spin: turned {:.1}°, |x_s − p| off by {ed:.2e} of |d|, offset in the segment's chord frame off by {el:.2e} of |d| (max), {em:.2e} (mean over the ties); a fixed global d: {:.2}",
        angle.to_degrees(),
        2.0 * (angle / 2.0).sin()
    );
    assert!(angle > std::f64::consts::FRAC_PI_2, "{angle}");
    // d turns with the main nodes' rotations (eq. (5)); the chord frame of the
    // segment differs from them by the strip's elastic bending, ±4e-6 rad with
    // opposite signs at x = 45 and x = 50 (the max), which cancels in the mean.
    assert!(ed < 1e-6 && em < 1e-6 && el < 1e-5, "{ed} {em} {el}");
    // Angular momentum about the centre of mass, with the masses the solver integrates.
    let m = shell_masses(&mesh, RHO, 1.0, &[]);
    let inr = shell_inertias(&mesh, RHO, 1.0);
    let mi = solver_masses(&m, &inr, &ties, 0.4, true);
    let h0 = angular_momentum(&mi, &spin_initial(&mesh, &m));
    let h1 = angular_momentum(&mi, &s1);
    let eh = norm(sub(h1, h0)) / norm(h0);
    let eb = free_balance(&r1);
    eprintln!(
        "spin: H0 {h0:?}, H {h1:?}, error {eh:.2e}; energy balance {eb:.2e} of the kinetic energy"
    );
    assert!(eh < 1e-6, "angular momentum error {eh}");
    assert!(eb.abs() < 1e-5, "energy balance {eb}");
    // The turned offsets are state: the same bytes on 2 ranks.
    assert_same_final_state_on_2_ranks(&d, "tied-spin2", &r1);
}

/// The plate nodes of tied_spin_block, (2.5 i, 2.5 j, 5.5), on the block's top
/// face (nodes every 5): Φ bilinear at s, t ∈ {−1, 0, 1}.
fn plate_block_ties() -> Vec<TieT> {
    let bnode = |i: u64, j: u64| 1 + i + 5 * (j + 3);
    let mut ties = Vec::new();
    for j in 0..5u64 {
        for i in 0..9u64 {
            let (ci, cj) = ((i / 2).min(3), (j / 2).min(1));
            let s = (i - 2 * ci) as f64 - 1.0;
            let t = (j - 2 * cj) as f64 - 1.0;
            let sh = [
                0.25 * (1.0 - s) * (1.0 - t),
                0.25 * (1.0 + s) * (1.0 - t),
                0.25 * (1.0 + s) * (1.0 + t),
                0.25 * (1.0 - s) * (1.0 + t),
            ];
            let q = [
                bnode(ci, cj),
                bnode(ci + 1, cj),
                bnode(ci + 1, cj + 1),
                bnode(ci, cj + 1),
            ];
            ties.push(TieT {
                sec: 1001 + i + 9 * j,
                main: (0..4)
                    .filter(|&k| sh[k] != 0.0)
                    .map(|k| (q[k], sh[k]))
                    .collect(),
                frame: [q[0], q[1], q[3]],
            });
        }
    }
    ties
}

#[test]
fn a_plate_tied_with_an_offset_onto_a_spinning_brick_block_keeps_angular_momentum() {
    // Brick main nodes have no rotations: the plate nodes' moments reach the
    // block as force couples and their rotation is the face's spin.
    let d = deck("tied_spin_block");
    let mesh = read_mesh(&d);
    let ties = plate_block_ties();
    let a = RunArgs {
        energies: true,
        ..Default::default()
    };
    let (r1, _) = state("tied_spin_block", "spinb1", &a);
    assert!(r1.listing.text.contains(
        "45 secondary nodes tied (Spotflag 5, standard kinematic formulation), 0 with rotations, 45 on segments without rotational DOFs"
    ));
    let s1 = full_state(&r1);
    let bnode = |i: u64, j: u64| 1 + i + 5 * (j + 3);
    let e = sub(s1[&bnode(0, 2)][0], s1[&bnode(0, 0)][0]);
    let angle = e[2].atan2(e[1]);
    let (ed, el, em) = placement(&mesh, &s1, &ties, 0.5);
    eprintln!(
        "spin on block: turned {:.1}°, |x_s − p| off by {ed:.2e} of |d|, offset in the face's chord frame off by {el:.2e} of |d| (max), {em:.2e} (mean)",
        angle.to_degrees()
    );
    assert!(angle > std::f64::consts::FRAC_PI_2);
    assert!(ed < 1e-6 && el < 2e-6 && em < 1e-6, "{ed} {el} {em}");
    // The plate's rotations follow the face's spin (≈ ω0 = (1, 0, 0) here).
    let w = s1[&1001][2];
    assert!(
        (w[0] - 1.0).abs() < 1e-2 && w[1].abs() < 1e-2 && w[2].abs() < 1e-2,
        "{w:?}"
    );
    let mut m = shell_masses(&mesh, RHO, 1.0, &[1]);
    for (id, mi) in brick_masses(&mesh, RHO, &[2]) {
        *m.entry(id).or_insert(0.0) += mi;
    }
    let inr = shell_inertias(&mesh, RHO, 1.0);
    let mi = solver_masses(&m, &inr, &ties, 0.5, false);
    let h0 = angular_momentum(&mi, &spin_initial(&mesh, &m));
    let h1 = angular_momentum(&mi, &s1);
    let eh = norm(sub(h1, h0)) / norm(h0);
    let eb = free_balance(&r1);
    eprintln!("spin on block: H0 {h0:?}, H {h1:?}, error {eh:.2e}; energy balance {eb:.2e}");
    assert!(eh < 1e-6, "angular momentum error {eh}");
    assert!(eb.abs() < 1e-4, "energy balance {eb}");
    assert_same_final_state_on_2_ranks(&d, "tied-spinb2", &r1);
}

#[test]
fn a_shell_cantilever_tied_onto_a_brick_face_bends_as_a_clamped_one() {
    // The strip's x = 0 edge on the face of a brick block clamped at its back:
    // without the moment (translation only) the joint is a hinge.
    let (r, tied) = state("tied_cant_block", "cantb", &RunArgs::default());
    let (_, cont) = state("cont_bend", "cantb-c", &RunArgs::default());
    let wt = tied[&(1001 + 20 + 21)][2];
    let wc = cont[&TIP_CONT][2];
    // Hinge at x = 0: the whole strip (mass m, length L) turns about it under
    // P: w_tip ≈ ½ (3P/m) t² at t = 5.984.
    let m = RHO * 1.0 * 10.0 * 100.0;
    let hinge = 0.5 * 3.0 * 5.25e-5 / m * 5.984f64.powi(2);
    eprintln!(
        "cantilever on block: tip w {wt:.6e}, clamped {wc:.6e}, ratio {:.4}; a hinge ~{hinge:.3} ({:.1} x)",
        wt / wc,
        hinge / wc
    );
    assert!((wt / wc - 1.0).abs() < 0.03, "ratio {}", wt / wc);
    assert!(hinge > 1.5 * wt);
    assert!(r
        .listing
        .text
        .contains("3 secondary nodes tied (Spotflag 5, standard kinematic formulation), 0 with rotations, 3 on segments"));
}

#[test]
fn ignore_1000_leaves_a_node_out_of_dsearch_free_and_warns() {
    // tied_free with node 6 (x = 25, 25 from the coarse half, dsearch 5) in the
    // secondary group and Ignore = 1000: node 6 is not tied and moves with its
    // own mesh, so the run is the same bytes as tied_free.
    let (ri, si) = state("tied_ignore", "ign", &RunArgs::default());
    let (rf, _) = state("tied_free", "ign-ref", &RunArgs::default());
    assert!(ri.listing.text.contains(
        "WARNING /INTER/TYPE2/1: 1 secondary nodes have no main segment within dsearch and are left free (Ignore = 1000): 6"
    ), "{}", ri.listing.text);
    assert!(ri
        .listing
        .text
        .contains("/INTER/TYPE2/1: 4 secondary nodes tied"));
    assert!(ri.final_state_bytes() == rf.final_state_bytes());
    // It did move (flight at v0 = (1, 0, 0.5) for 1 ms).
    let x0 = read_mesh(&deck("tied_ignore")).nodes[&6];
    assert!((si[&6][0] - x0[0] - 1.0).abs() < 0.05, "{:?}", si[&6]);
}
