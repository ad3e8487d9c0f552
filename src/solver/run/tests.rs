//! The loop's phases on the serial communicator (one rank, no mpirun):
//! rank 0's preparation of a project deck, the per-rank set-up, then
//! cycle 0 and single cycles, checked against physics.

use super::setup::{self, Ctx, State};
use super::{cycle, cycle_zero, prepare, report::Report, RunOptions};
use crate::contact::tied::TiedSystem;
use crate::global::GlobalData;
use crate::parallel::{run_ranks, Serial, World};
use std::path::PathBuf;

fn options(deck: &str) -> RunOptions {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    RunOptions {
        deck: root.join(format!("decks/{deck}/{deck}_0000.rad")),
        engine: None,
        out_dir: std::env::temp_dir().join(format!("crashsim-phase-{deck}-{}", std::process::id())),
        final_state: None,
        final_elements: None,
        history: None,
        energies: None,
        strict: false,
        skip_unsupported: false,
        energy_error_limit: 100.0,
        output: Default::default(),
    }
}

/// What rank 0 prepares for one rank, and the options it was prepared with.
fn prepared(
    deck: &str,
) -> (
    RunOptions,
    GlobalData,
    crate::domain::Subdomain,
    Vec<crate::kinematics::rigid_body::RigidBodyState>,
) {
    let opts = options(deck);
    let (g, mut sds, bodies, _) = prepare::prepare(&opts, 1).unwrap();
    assert_eq!(sds.len(), 1);
    (opts, g, sds.remove(0), bodies)
}

/// Runs `f` on the context and the state after cycle 0 (no listing).
fn after_cycle_zero(deck: &str, f: impl FnOnce(&Ctx, &mut State, &mut Report)) {
    let (opts, g, sd, bodies) = prepared(deck);
    on_rank(&Serial, &opts, &g, sd, bodies, f);
}

/// One rank's set-up and cycle 0 on `world`, then `f`.
fn on_rank<T>(
    world: &World,
    opts: &RunOptions,
    g: &GlobalData,
    sd: crate::domain::Subdomain,
    bodies: Vec<crate::kinematics::rigid_body::RigidBodyState>,
    f: impl FnOnce(&Ctx, &mut State, &mut Report) -> T,
) -> T {
    let mut ties = TiedSystem::new(g.tied.clone(), &sd);
    let mut cx = setup::context(world, opts, g, &sd, &mut ties);
    let mut s = setup::initial_state(&mut cx, ties, bodies).unwrap();
    let mut report = Report { listing: None };
    cycle_zero(&cx, &mut s, &mut report).unwrap();
    f(&cx, &mut s, &mut report)
}

/// Σ m·v over the nodes (translational momentum).
fn momentum(cx: &Ctx, s: &State) -> [f64; 3] {
    let mut p = [0.0; 3];
    for l in 0..cx.n {
        for k in 0..3 {
            p[k] += cx.mass.read().unwrap()[l] * s.v[l][k];
        }
    }
    p
}

#[test]
fn cycle_zero_takes_the_smallest_element_step_times_the_dt_scale() {
    after_cycle_zero("free_plate", |cx, s, _| {
        let smallest = s
            .blocks
            .iter()
            .flat_map(|b| b.steps().iter().map(|st| st.dt).collect::<Vec<_>>())
            .fold(f64::INFINITY, f64::min);
        assert!(smallest.is_finite() && smallest > 0.0);
        assert_eq!(s.dt, smallest * cx.g.engine.dt_scale);
        assert_eq!(s.step.what, "SHELL");
        // The balance starts from the initial kinetic energy: ½ m v² of the launched half.
        let ke: f64 = (0..cx.n)
            .map(|l| 0.5 * cx.mass.read().unwrap()[l] * s.v[l].iter().map(|c| c * c).sum::<f64>())
            .sum();
        assert!(
            (s.e0 - ke).abs() <= 1e-12 * ke,
            "e0 {} against ½mv² {ke}",
            s.e0
        );
    });
}

#[test]
fn free_plate_cycles_keep_momentum() {
    after_cycle_zero("free_plate", |cx, s, report| {
        let p0 = momentum(cx, s);
        let e0 = s.e0;
        let mut dog = super::watchdog::Watchdog::new(cx, &s.blocks);
        for _ in 0..200 {
            cycle(cx, s, report, &mut dog).unwrap();
        }
        assert_eq!(s.cycle, 200);
        let p = momentum(cx, s);
        let scale = p0.iter().map(|c| c.abs()).fold(0.0, f64::max);
        for k in 0..3 {
            assert!(
                (p[k] - p0[k]).abs() <= 1e-10 * scale,
                "momentum {p:?} against {p0:?}"
            );
        }
        // The launched half strained the plate: energy went into the elements.
        let e = super::energy::global(cx, s);
        assert!(
            e.internal > 0.01 * e0,
            "the plate was not strained: {}",
            e.internal
        );
    });
}

#[test]
fn contact_forces_on_the_serial_communicator_balance() {
    // Two brick blocks pressed together through two TYPE7 interfaces:
    // contact is internal, so its nodal forces sum to zero.
    after_cycle_zero("contact_patch", |cx, s, report| {
        let mut pressed = 0;
        let mut dog = super::watchdog::Watchdog::new(cx, &s.blocks);
        for _ in 0..400 {
            cycle(cx, s, report, &mut dog).unwrap();
            let mut sum = [0.0f64; 3];
            let mut size = 0.0f64;
            for f in &s.fcont {
                for k in 0..3 {
                    sum[k] += f[k];
                    size += f[k].abs();
                }
            }
            if size > 0.0 {
                pressed += 1;
                for c in sum {
                    assert!(
                        c.abs() <= 1e-9 * size,
                        "contact forces sum to {sum:?} (size {size})"
                    );
                }
            }
        }
        assert!(pressed > 100, "contact acted on {pressed} cycles only");
        assert!(!s.contact.is_empty());
    });
}

/// (global node, position, velocity bits) of the owned nodes after `cycles`
/// cycles on `n` in-process ranks, and the contact ghosts the ranks held.
fn final_nodes(deck: &str, n: usize, cycles: u64) -> (Vec<(u32, [u64; 6])>, usize) {
    let opts = options(deck);
    let (g, sds, bodies, _) = prepare::prepare(&opts, n).unwrap();
    let per_rank = run_ranks(n, |w| {
        let sd = sds[w.rank() as usize].clone();
        on_rank(w, &opts, &g, sd, bodies.clone(), |cx, s, report| {
            let mut dog = super::watchdog::Watchdog::new(cx, &s.blocks);
            while s.cycle < cycles {
                cycle(cx, s, report, &mut dog).unwrap();
            }
            let nodes = (0..cx.n)
                .filter(|&l| cx.owned[l])
                .map(|l| {
                    let (x, v) = (s.x[l], s.v[l]);
                    let bits = [x[0], x[1], x[2], v[0], v[1], v[2]].map(f64::to_bits);
                    (cx.sd.node_global[l], bits)
                })
                .collect::<Vec<_>>();
            (nodes, s.contact.ghost_count())
        })
    });
    let ghosts = per_rank.iter().map(|r| r.1).sum();
    let mut all: Vec<(u32, [u64; 6])> = per_rank.into_iter().flat_map(|r| r.0).collect();
    all.sort_unstable();
    (all, ghosts)
}

#[test]
fn contact_cycles_on_two_in_process_ranks_match_one_rank_bit_for_bit() {
    // Elements, assembly, contact ghosts and force routing across a partition boundary.
    let (one, _) = final_nodes("contact_patch", 1, 150);
    let (two, ghosts) = final_nodes("contact_patch", 2, 150);
    assert!(ghosts > 0, "no contact node crossed the partition boundary");
    assert_eq!(one.len(), two.len());
    assert!(one == two, "the final states differ between 1 and 2 ranks");
}

#[test]
fn the_nodal_loops_vector_division_gives_the_bits_of_three_scalar_ones() {
    use super::kinematics::divided;
    // Ordinary forces and masses, a denormal quotient, a huge one, a zero
    // mass (infinite and NaN quotients): lane by lane as the scalar `/`.
    let cases: [([f64; 3], f64); 5] = [
        ([1.234_567_89e3, -9.876e-4, 3.0], 7.3e-6),
        ([1e-300, -2.5e-310, 0.0], 3.0e7),
        ([1e300, -1e300, 1.0], 1e-10),
        ([1.0, -1.0, 0.0], 0.0),
        ([f64::NAN, f64::INFINITY, -0.0], 2.0),
    ];
    for (n, m) in cases {
        let q = divided(n, m);
        for k in 0..3 {
            assert_eq!(q[k].to_bits(), (n[k] / m).to_bits(), "{n:?} / {m}");
        }
    }
}
