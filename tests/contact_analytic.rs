//! Analytic and physical checks of the TYPE7 contact, each on its own deck
//! (decks/<name>/, written by decks/make_contact.py; units kg, mm, ms, GPa):
//!
//! * `contact_patch*`: two non-matching brick blocks (2x2 and 3x3 bricks in
//!   plan) pressed together by a smoothly ramped uniform pressure — the
//!   contact transmits p·A and the stress in the coarse block is uniform.
//! * `sliding_block`: a block sliding on a plate under gravity with Coulomb
//!   friction decelerates at μ·g and stops at v0²/(2μg).
//! * `sliding_laws`: blocks driven at constant speeds — T/N of each
//!   interface is the Renard / Darmstad / generalized viscous μ(p, V).
//! * `ball_drop`: an elastic shell ball bounces on a plate; the energy balance
//!   (contact energy included) closes within 1% through the impact.
//! * `bars_head_on`: two equal elastic bars exchange their velocities and
//!   conserve momentum to round-off.
//! * `tube_crush`: a square tube folds under a moving rigid wall, and with
//!   TYPE7 self-contact no tube segment ends up crossing another.
//!
//! The ball and the bars also run on 2 MPI ranks: the final state must be
//! byte-identical to the 1-rank run.

#[path = "contact_common/mod.rs"]
mod cc;
mod common;

use cc::*;
use std::collections::BTreeMap;

const RHO: f64 = 7.85e-6;

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

// ---------------------------------------------------------------------------
// Patch test

/// The contact resultant through the interface(s) at every print of the hold
/// phase: interface 1's secondary nodes are the upper block's, interface 2's
/// the lower block's, so the force on the upper block is F1x − F2x.
fn patch_resultants(r: &Run, t_from: f64) -> Vec<f64> {
    let l = &r.listing;
    let f1 = l.of(1);
    let f2 = l.of(2);
    let mut out = Vec::new();
    let times: Vec<f64> = if f1.is_empty() {
        f2.iter().map(|x| x.t).collect()
    } else {
        f1.iter().map(|x| x.t).collect()
    };
    for t in times {
        if t < t_from {
            continue;
        }
        let a = f1.iter().find(|x| x.t == t).map_or(0.0, |x| x.normal[0]);
        let b = f2.iter().find(|x| x.t == t).map_or(0.0, |x| x.normal[0]);
        out.push(a - b);
    }
    out
}

struct PatchResult {
    f_mean: f64,
    f_min: f64,
    f_max: f64,
    /// Lower block σxx: mean, (max − min)/|mean|, largest |σyy|, |σxy|.
    low_mean: f64,
    low_spread: f64,
    low_lateral: f64,
    up_spread: f64,
}

fn patch(name: &str) -> PatchResult {
    let (p, a) = (0.01, 100.0);
    let d = deck(name);
    let dir = scratch(name);
    let eng = engine_variant(&d, &dir.join("engine"), -10, None);
    let r = run(
        &d,
        &dir,
        &RunArgs {
            engine: Some(eng),
            elements: true,
            ..Default::default()
        },
    );
    assert!(r.listing.normal_termination());
    // Hold phase: the ramp ends at 0.4 ms, the run at 0.5 ms.
    let f = patch_resultants(&r, 0.42);
    assert!(f.len() > 20, "{} prints in the hold phase", f.len());
    let f_mean = f.iter().sum::<f64>() / f.len() as f64 / (p * a);
    let f_min = f.iter().copied().fold(f64::INFINITY, f64::min) / (p * a);
    let f_max = f.iter().copied().fold(f64::NEG_INFINITY, f64::max) / (p * a);
    let el = r.elements();
    let low: Vec<&Vec<f64>> = el
        .iter()
        .filter(|(id, _)| **id < 1000)
        .map(|e| e.1)
        .collect();
    let up: Vec<f64> = el
        .iter()
        .filter(|(id, _)| **id > 1000)
        .map(|e| e.1[0])
        .collect();
    assert_eq!(low.len(), 8);
    let sxx: Vec<f64> = low.iter().map(|s| s[0]).collect();
    let mean = sxx.iter().sum::<f64>() / sxx.len() as f64;
    let spread = (sxx.iter().copied().fold(f64::NEG_INFINITY, f64::max)
        - sxx.iter().copied().fold(f64::INFINITY, f64::min))
        / mean.abs();
    let lateral = low
        .iter()
        .map(|s| s[1].abs().max(s[2].abs()))
        .fold(0.0, f64::max);
    let up_mean = up.iter().sum::<f64>() / up.len() as f64;
    let up_spread = (up.iter().copied().fold(f64::NEG_INFINITY, f64::max)
        - up.iter().copied().fold(f64::INFINITY, f64::min))
        / up_mean.abs();
    let res = PatchResult {
        f_mean,
        f_min,
        f_max,
        low_mean: mean / -p,
        low_spread: spread,
        low_lateral: lateral / p,
        up_spread,
    };
    eprintln!(
        "{name}: resultant / pA: mean {:.5} (min {:.5}, max {:.5}) over the hold; lower block \
         sxx/(-p) mean {:.5}, spread {:.4}, |syy|,|sxy| <= {:.4} p; upper block sxx spread {:.3}",
        res.f_mean,
        res.f_min,
        res.f_max,
        res.low_mean,
        res.low_spread,
        res.low_lateral,
        res.up_spread
    );
    res
}

fn assert_resultant(name: &str, r: &PatchResult) {
    assert!(
        (r.f_mean - 1.0).abs() < 0.01,
        "{name}: mean resultant {} p·A",
        r.f_mean
    );
    assert!(
        (r.f_min - 1.0).abs() < 0.01 && (r.f_max - 1.0).abs() < 0.01,
        "{name}: resultant between {} and {} p·A during the hold",
        r.f_min,
        r.f_max
    );
}

/// Two passes (each block's contact-face nodes secondary on the other block's
/// face): the contact transmits p·A (hold phase: mean 1.0001, within ±0.5%)
/// and the coarse lower block carries σxx = −p uniformly (spread 0.14%).
/// The fine upper block's first layer is not uniform (spread ~70%): its face
/// is loaded at the coarse block's nodes — a node-to-segment limitation.
#[test]
fn contact_patch_two_pass_transmits_a_uniform_pressure() {
    let r = patch("contact_patch");
    assert_resultant("contact_patch", &r);
    assert!(
        (r.low_mean - 1.0).abs() < 0.01,
        "lower sxx mean {} (-p)",
        r.low_mean
    );
    assert!(r.low_spread < 0.01, "lower sxx spread {}", r.low_spread);
    assert!(
        r.low_lateral < 0.01,
        "lower block lateral stress {} p",
        r.low_lateral
    );
}

/// One pass with the coarse block's nodes secondary on the fine block's face:
/// also uniform within 1% (spread 0.5%).
#[test]
fn contact_patch_one_pass_coarse_nodes_on_fine_face() {
    let r = patch("contact_patch_1p_coarse");
    assert_resultant("contact_patch_1p_coarse", &r);
    assert!(
        (r.low_mean - 1.0).abs() < 0.01,
        "lower sxx mean {} (-p)",
        r.low_mean
    );
    assert!(r.low_spread < 0.01, "lower sxx spread {}", r.low_spread);
}

/// One pass with the fine block's nodes secondary on the coarse block's face:
/// the resultant is right but the coarse block's stress is NOT uniform within
/// 1% (spread 1.3%: 16 penalty springs of equal stiffness, whatever their
/// tributary areas, press on 4 segments). Kept as a measured limitation: the
/// bound below is 2%.
#[test]
fn contact_patch_one_pass_fine_nodes_on_coarse_face() {
    let r = patch("contact_patch_1p");
    assert_resultant("contact_patch_1p", &r);
    assert!(
        (r.low_mean - 1.0).abs() < 0.01,
        "lower sxx mean {} (-p)",
        r.low_mean
    );
    assert!(r.low_spread < 0.02, "lower sxx spread {}", r.low_spread);
}

// ---------------------------------------------------------------------------
// Friction

/// A 10 mm steel cube (2x2x2 bricks) at v0 = 4 mm/ms on a plate, g = 10
/// mm/ms², Coulomb μ = 0.3: its centre of mass follows x = v0·t − ½μg·t² until
/// t_stop = v0/(μg) = 1.333 ms, then rests at v0²/(2μg) = 2.667 mm.
/// Measured: deceleration 3.0000 (μg = 3), within 1e-6.
#[test]
fn sliding_block_decelerates_at_mu_g() {
    let (v0, g, mu) = (4.0, 10.0, 0.3);
    let d = deck("sliding_block");
    let mesh = read_mesh(&d);
    let mass = brick_masses(&mesh, RHO, &[1]);
    let m: f64 = mass.values().sum();
    assert!(rel(m, RHO * 1000.0) < 1e-12);
    let r = run(
        &d,
        &scratch("sliding_block"),
        &RunArgs {
            history: true,
            ..Default::default()
        },
    );
    let (h, rows) = r.history();
    // Columns dx_ID, dy_ID, dz_ID: the centre of mass's x displacement.
    let cols: Vec<(usize, f64)> = h
        .iter()
        .enumerate()
        .filter_map(|(i, c)| {
            let id: u64 = c.strip_prefix("dx_")?.parse().ok()?;
            Some((i, mass[&id]))
        })
        .collect();
    assert_eq!(cols.len(), mass.len());
    let t: Vec<f64> = rows.iter().map(|r| r[0]).collect();
    let x: Vec<f64> = rows
        .iter()
        .map(|r| cols.iter().map(|&(i, w)| w * r[i]).sum::<f64>() / m)
        .collect();
    let t_stop = v0 / (mu * g);
    let (ts, xs): (Vec<f64>, Vec<f64>) = t
        .iter()
        .zip(&x)
        .filter(|(&ti, _)| ti > 0.05 * t_stop && ti < 0.9 * t_stop)
        .map(|(a, b)| (*a, *b))
        .unzip();
    assert!(ts.len() > 100);
    let c = quadratic_fit(&ts, &xs);
    let (v_fit, a_fit) = (c[1], -2.0 * c[2]);
    eprintln!(
        "sliding_block: v0 {v_fit:.6} (4), deceleration {a_fit:.6} (mu g = {})",
        mu * g
    );
    assert!(
        rel(a_fit, mu * g) < 0.01,
        "deceleration {a_fit} vs {}",
        mu * g
    );
    assert!(rel(v_fit, v0) < 0.01, "initial speed {v_fit}");
    // Linear decrease: the velocity by finite differences stays on v0 − μg·t.
    for k in 1..t.len() - 1 {
        if t[k] > 0.05 * t_stop && t[k] < 0.95 * t_stop {
            let v = (x[k + 1] - x[k - 1]) / (t[k + 1] - t[k - 1]);
            let want = v0 - mu * g * t[k];
            assert!(
                (v - want).abs() < 0.01 * v0,
                "t = {}: v = {v}, expected {want}",
                t[k]
            );
        }
    }
    // Stopped: at rest at v0²/(2μg).
    let stop = v0 * v0 / (2.0 * mu * g);
    let last = *x.last().unwrap();
    assert!(*t.last().unwrap() > 1.2 * t_stop);
    assert!(rel(last, stop) < 0.01, "final distance {last} vs {stop}");
    let n = x.len();
    let v_end = (x[n - 1] - x[n - 11]) / (t[n - 1] - t[n - 11]);
    assert!(
        v_end.abs() < 0.01 * v0,
        "still moving at {v_end} after the stop"
    );
    // While sliding, the INTER line's T/N is μ.
    for l in r
        .listing
        .of(1)
        .iter()
        .filter(|l| l.t < 0.9 * t_stop && l.t > 0.1)
    {
        let ratio = norm(l.tangent) / norm(l.normal);
        assert!(rel(ratio, mu) < 0.01, "t = {}: T/N = {ratio}", l.t);
        assert!(l.tangent[0] < 0.0, "friction opposes the sliding");
    }
}

fn renard(c: &[f64; 6], v: f64) -> f64 {
    let (mus, mud, mumax, mumin, v1, v2) = (c[0], c[1], c[2], c[3], c[4], c[5]);
    if v <= v1 {
        let r = v / v1;
        mus + (mumax - mus) * r * (2.0 - r)
    } else if v <= v2 {
        let r = (v - v1) / (v2 - v1);
        mumax - (mumax - mumin) * r * r * (3.0 - 2.0 * r)
    } else {
        let d = v - v2;
        mud - 1.0 / (1.0 / (mud - mumin) + d * d)
    }
}

/// Blocks driven at constant speed V (/IMPVEL) on a plate, one TYPE7 each:
/// the tangential/normal resultant of each interface is μ(p, V) of its law,
/// p the pair's normal force over the main segment's area (4 equal pairs per
/// block). Measured: within 5e-6 of the formulas.
///
/// Renard above Vcr2 follows the card's eq. (18), μd − 1/(1/(μd − μmin) +
/// (V − Vcr2)²); the theory manual's EQ. 8.6.4.2 has (V − Vcr2) not squared
/// (0.1167 instead of 0.1286 at V = 5).
#[test]
fn sliding_laws_give_mu_of_the_formulas() {
    let renard_c = [0.3, 0.2, 0.5, 0.1, 1.0, 3.0];
    let darm = [5.0e11, -0.1, 3.0e5, -0.2, 0.1, -0.3];
    let visc = [1.0e5, 0.02, 1.0e5, 1.0e11, 0.005];
    let area = 300.0 * 240.0;
    let r = run(
        &deck("sliding_laws"),
        &scratch("sliding_laws"),
        &RunArgs::default(),
    );
    assert!(r.listing.normal_termination());
    let cases: [(&str, f64, Box<dyn Fn(f64) -> f64>); 6] = [
        ("Renard V < Vcr1", 0.5, Box::new(|_| renard(&renard_c, 0.5))),
        (
            "Renard Vcr1 < V < Vcr2",
            2.0,
            Box::new(|_| renard(&renard_c, 2.0)),
        ),
        ("Renard V > Vcr2", 5.0, Box::new(|_| renard(&renard_c, 5.0))),
        (
            "Darmstad V = 0.5",
            0.5,
            Box::new(move |p| {
                let v = 0.5f64;
                0.05 + darm[0] * (darm[1] * v).exp() * p * p
                    + darm[2] * (darm[3] * v).exp() * p
                    + darm[4] * (darm[5] * v).exp()
            }),
        ),
        (
            "Darmstad V = 2",
            2.0,
            Box::new(move |p| {
                let v = 2.0f64;
                0.05 + darm[0] * (darm[1] * v).exp() * p * p
                    + darm[2] * (darm[3] * v).exp() * p
                    + darm[4] * (darm[5] * v).exp()
            }),
        ),
        (
            "generalized viscous V = 1",
            1.0,
            Box::new(move |p| {
                let v = 1.0f64;
                0.05 + visc[0] * p
                    + visc[1] * v
                    + visc[2] * p * v
                    + visc[3] * p * p
                    + visc[4] * v * v
            }),
        ),
    ];
    for (i, (what, _v, mu)) in cases.iter().enumerate() {
        let l = r.listing.last(i as u64 + 1);
        assert_eq!(l.pairs, 4, "{what}: the block's 4 bottom nodes in contact");
        let n = norm(l.normal);
        // Normal force ≈ the block's weight m g = 7.85e-3 · 10.
        assert!(rel(n, RHO * 1000.0 * 10.0) < 0.05, "{what}: N = {n}");
        let p = n / 4.0 / area;
        let ratio = norm(l.tangent) / n;
        let want = mu(p);
        eprintln!("{what}: T/N = {ratio:.7}, mu = {want:.7}");
        assert!(
            rel(ratio, want) < 0.01,
            "{what}: T/N = {ratio}, mu = {want}"
        );
        assert!(l.tangent[0] < 0.0, "{what}: friction opposes the sliding");
    }
    // The pressure terms matter: without them the Darmstad μ would differ.
    let l = r.listing.last(4);
    let ratio = norm(l.tangent) / norm(l.normal);
    assert!((ratio - (0.05 + 0.1 * (-0.15f64).exp())).abs() > 0.05);
    // EQ. 8.6.4.2's linear third branch is not what the engine computes.
    let l = r.listing.last(3);
    let ratio = norm(l.tangent) / norm(l.normal);
    assert!((ratio - (0.2 - 1.0 / (10.0 + 2.0))).abs() > 0.005);
}

// ---------------------------------------------------------------------------
// Impacts

/// Mean velocity of a set of nodes weighted by their masses.
fn mean_velocity(state: &BTreeMap<u64, [f64; 6]>, mass: &BTreeMap<u64, f64>) -> [f64; 3] {
    let mut p = [0.0; 3];
    let mut m = 0.0;
    for (id, w) in mass {
        let s = state[id];
        for k in 0..3 {
            p[k] += w * s[3 + k];
        }
        m += w;
    }
    p.map(|c| c / m)
}

/// A LAW1 steel shell ball (R = 10, t = 1) falls at 3 mm/ms under gravity on a
/// fixed plate: kinetic + rotational + internal + contact energy − work of
/// gravity stays at the initial kinetic energy within 1% through the impact
/// (measured: +0.74% / −0.55% at worst, +0.15% at the end), and the ball
/// bounces back (mean vz +2.88 mm/ms at the end). The same deck on 2 ranks
/// gives a byte-identical final state.
#[test]
fn ball_drop_conserves_energy_and_bounces() {
    let d = deck("ball_drop");
    let mesh = read_mesh(&d);
    let r = run(
        &d,
        &scratch("ball_drop"),
        &RunArgs {
            energies: true,
            ..Default::default()
        },
    );
    assert!(r.listing.normal_termination());
    let (h, rows) = r.energies();
    assert_eq!(
        h,
        [
            "time",
            "cycle",
            "dt",
            "internal",
            "kinetic",
            "rotational",
            "external_work",
            "contact",
            "hourglass"
        ]
    );
    let e0 = rows[0][4] + rows[0][5] + rows[0][3] + rows[0][8] + rows[0][7] - rows[0][6];
    let mut worst = (0.0f64, 0.0);
    let mut max_contact_ie = 0.0f64;
    for row in &rows {
        let e = row[3] + row[8] + row[4] + row[5] + row[7] - row[6];
        let err = (e - e0) / e0;
        if err.abs() > worst.0.abs() {
            worst = (err, row[0]);
        }
        max_contact_ie = max_contact_ie.max(row[3] + row[8]);
    }
    eprintln!(
        "ball_drop: worst energy error {:.4}% at t = {:.4}",
        100.0 * worst.0,
        worst.1
    );
    assert!(
        worst.0.abs() < 0.01,
        "energy off by {} at t = {}",
        worst.0,
        worst.1
    );
    // The impact happened: pairs in contact, the ball deformed.
    assert!(r.listing.of(1).iter().any(|l| l.pairs > 0));
    assert!(max_contact_ie > 0.01 * e0);
    // Rebound: the ball's mean vertical velocity is upwards at the end.
    let mass = shell_masses(&mesh, RHO, 1.0, &[1]);
    let v = mean_velocity(&r.final_state(), &mass);
    eprintln!("ball_drop: mean velocity at the end {v:?}");
    assert!(v[2] > 0.5 * 3.0, "no rebound: vz = {}", v[2]);
    // 2 ranks: the same bytes.
    assert_same_final_state_on_2_ranks(&d, "ball_drop_np2", &r);
}

/// Two equal elastic bars (ν = 0) at ±2 mm/ms meet end to end through a TYPE7:
/// after 2L/c they separate with their velocities exchanged (measured ∓1.941,
/// 2.9% short: the rest rings in the bars and went into the contact damping),
/// and the total momentum stays 0 to round-off. 2 ranks: identical bytes.
#[test]
fn bars_head_on_exchange_velocities() {
    let v0 = 2.0;
    let d = deck("bars_head_on");
    let mesh = read_mesh(&d);
    let ma = brick_masses(&mesh, RHO, &[1]);
    let mb = brick_masses(&mesh, RHO, &[2]);
    let r = run(&d, &scratch("bars_head_on"), &RunArgs::default());
    assert!(r.listing.normal_termination());
    assert!(r.listing.of(1).iter().any(|l| l.pairs > 0), "the bars met");
    let s = r.final_state();
    let va = mean_velocity(&s, &ma);
    let vb = mean_velocity(&s, &mb);
    eprintln!("bars_head_on: bar A {va:?}, bar B {vb:?}");
    assert!(
        rel(va[0], -v0) < 0.05,
        "bar A at {} (expected -{v0})",
        va[0]
    );
    assert!(rel(vb[0], v0) < 0.05, "bar B at {} (expected {v0})", vb[0]);
    // Separated: the contact is over.
    assert_eq!(r.listing.last(1).pairs, 0);
    // Momentum: Σ m v = 0 (exact initially: the bars mirror each other).
    let m: f64 = ma.values().chain(mb.values()).sum();
    let mut p = [0.0f64; 3];
    let mut scale = 0.0f64;
    for (id, w) in ma.iter().chain(mb.iter()) {
        for k in 0..3 {
            p[k] += w * s[id][3 + k];
        }
        scale += w * s[id][3].abs();
    }
    eprintln!("bars_head_on: total momentum {p:?} (m v = {})", m * v0);
    for k in 0..3 {
        assert!(p[k].abs() < 1e-12 * m * v0, "momentum {p:?}");
    }
    assert!(scale > 0.9 * m * v0);
    assert_same_final_state_on_2_ranks(&d, "bars_head_on_np2", &r);
}

/// A copy of decks/NAME with `edit` applied to the starter's text, in `dir`.
fn deck_variant(
    name: &str,
    dir: &std::path::Path,
    edit: &dyn Fn(&str) -> String,
) -> std::path::PathBuf {
    let d = deck(name);
    let nd = dir.join("deck").join(format!("{name}_0000.rad"));
    std::fs::create_dir_all(nd.parent().unwrap()).unwrap();
    std::fs::write(&nd, edit(&std::fs::read_to_string(&d).unwrap())).unwrap();
    std::fs::copy(
        d.with_file_name(format!("{name}_0001.rad")),
        nd.with_file_name(format!("{name}_0001.rad")),
    )
    .unwrap();
    nd
}

/// The sliding block's internal energy after it has stopped (t > 1.05 t_stop),
/// at its largest, with the friction form Iform.
fn internal_energy_after_the_stop(iform: i64) -> (f64, f64) {
    let dir = scratch(&format!("sliding_block_iform{iform}"));
    let d = deck_variant("sliding_block", &dir, &|t| {
        // Card 6 of the TYPE7: Iform in columns 41-50.
        let mut lines: Vec<String> = t.lines().map(String::from).collect();
        let i = lines
            .iter()
            .position(|l| l.starts_with("#    Ifric"))
            .unwrap()
            + 1;
        lines[i] = format!("{}{:>10}{}", &lines[i][..40], iform, &lines[i][50..]);
        lines.join("\n") + "\n"
    });
    let r = run(
        &d,
        &dir,
        &RunArgs {
            energies: true,
            ..Default::default()
        },
    );
    let (_, rows) = r.energies();
    let t_stop = 4.0 / 3.0;
    let before = rows
        .iter()
        .filter(|r| r[0] < 0.9 * t_stop)
        .map(|r| r[3] + r[8])
        .fold(0.0, f64::max);
    let after = rows
        .iter()
        .filter(|r| r[0] > 1.05 * t_stop)
        .map(|r| r[3] + r[8])
        .fold(0.0, f64::max);
    eprintln!("sliding_block, Iform {iform}: internal energy while sliding <= {before:.3e}, after the stop <= {after:.3e} (initial kinetic 6.28e-2)");
    (before, after)
}

/// Once stopped, the block rests: with the incremental friction (Iform 2) its
/// internal energy stays at the elastic energy of its weight (~1e-5).
#[test]
fn sliding_block_rests_quietly_with_iform_2() {
    let (before, after) = internal_energy_after_the_stop(2);
    assert!(
        after < 2.0 * before.max(1e-5),
        "internal energy {after} after the stop"
    );
}

/// With the viscous friction (Iform 1, VISF 1) the stopped block rests too.
/// The damper C = VISF·√(2·K·M) acts on the previous velocity; with only the
/// cap C ≤ M/Δt (C·Δt/m ≈ 0.9 on the corner nodes) it was unstable on top of
/// the bricks' own stiffness: a period-2 oscillation along x whose internal
/// energy grew from 9e-6 to 2.5e-3 after the stop. It is now capped at
/// 2·(1 − s²)·M/Δt (s the /DT scale), the stability limit of the central
/// difference update with a lagged damper at the critical node.
#[test]
fn sliding_block_rests_quietly_with_iform_1() {
    let (before, after) = internal_energy_after_the_stop(1);
    assert!(
        after < 2.0 * before.max(1e-5),
        "internal energy {after} after the stop"
    );
}

/// KNOWN BUG: the bars_head_on deck with the default stiffness (Stfac 1, Km =
/// B·S²/V, as stiff as the bricks) at /DT 0.9: the contact chatters (on one
/// cycle in three) and blows up: the bars leave at ±2.43 mm/ms instead of
/// ±2, with 23 times the initial energy. The nodal contact step √(2M/K) uses
/// the contact stiffness alone; EQ. 8.8.5.2 sums the elements' stiffness K_el
/// with it. The committed deck uses Stfac 0.1.
#[test]
fn bars_head_on_with_the_default_stiffness_stay_stable() {
    let dir = scratch("bars_head_on_stfac1");
    let d = deck_variant("bars_head_on", &dir, &|t| {
        // Card 4 of the TYPE7: Stfac in columns 1-20 (0 = 1).
        let mut lines: Vec<String> = t.lines().map(String::from).collect();
        let i = lines
            .iter()
            .position(|l| l.starts_with("#              Stfac"))
            .unwrap()
            + 1;
        lines[i] = format!("{:>20}{}", 0, &lines[i][20..]);
        lines.join("\n") + "\n"
    });
    let r = run(&d, &dir, &RunArgs::default());
    let mesh = read_mesh(&d);
    let va = mean_velocity(&r.final_state(), &brick_masses(&mesh, RHO, &[1]));
    eprintln!("bars_head_on, Stfac 1: bar A at {:.4}", va[0]);
    assert!(rel(va[0], -2.0) < 0.05, "bar A at {}", va[0]);
}

// ---------------------------------------------------------------------------
// Tube crush

fn tri_bbox(t: &[V3; 3]) -> ([f64; 3], [f64; 3]) {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for p in t {
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    (lo, hi)
}

/// Whether segment p→q crosses triangle t (Möller–Trumbore, both ends included).
fn segment_crosses(p: V3, q: V3, t: &[V3; 3]) -> bool {
    let d = sub(q, p);
    let e1 = sub(t[1], t[0]);
    let e2 = sub(t[2], t[0]);
    let h = cross(d, e2);
    let a = dot(e1, h);
    if a.abs() < 1e-14 * norm(d) * norm(e1) * norm(e2) {
        return false; // parallel (coplanar contacts are not crossings)
    }
    let f = 1.0 / a;
    let s = sub(p, t[0]);
    let u = f * dot(s, h);
    if !(0.0..=1.0).contains(&u) {
        return false;
    }
    let qv = cross(s, e1);
    let v = f * dot(d, qv);
    if v < 0.0 || u + v > 1.0 {
        return false;
    }
    let w = f * dot(e2, qv);
    (0.0..=1.0).contains(&w)
}

fn triangles_intersect(a: &[V3; 3], b: &[V3; 3]) -> bool {
    (0..3).any(|i| segment_crosses(a[i], a[(i + 1) % 3], b))
        || (0..3).any(|i| segment_crosses(b[i], b[(i + 1) % 3], a))
}

/// Distance from p to triangle t.
fn point_triangle_distance(p: V3, t: &[V3; 3]) -> f64 {
    // Inside the prism: distance to the plane; else to the closest edge.
    let n = cross(sub(t[1], t[0]), sub(t[2], t[0]));
    let nn = norm(n);
    let inside = (0..3).all(|i| {
        let e = sub(t[(i + 1) % 3], t[i]);
        dot(cross(e, sub(p, t[i])), n) >= 0.0
    });
    if inside && nn > 0.0 {
        return dot(sub(p, t[0]), n).abs() / nn;
    }
    (0..3)
        .map(|i| {
            let a = t[i];
            let b = t[(i + 1) % 3];
            let ab = sub(b, a);
            let s = (dot(sub(p, a), ab) / dot(ab, ab)).clamp(0.0, 1.0);
            norm(sub(
                p,
                [a[0] + s * ab[0], a[1] + s * ab[1], a[2] + s * ab[2]],
            ))
        })
        .fold(f64::INFINITY, f64::min)
}

/// The four triangles of a 4-node segment around its centre (as the engine splits it).
fn split(x: &[V3; 4]) -> [[V3; 3]; 4] {
    let c = [0, 1, 2].map(|k| (x[0][k] + x[1][k] + x[2][k] + x[3][k]) / 4.0);
    [0, 1, 2, 3].map(|i| [c, x[i], x[(i + 1) % 4]])
}

type Segs = Vec<([u64; 4], [[V3; 3]; 4])>;
type Boxes = Vec<([f64; 3], [f64; 3])>;

/// Every tube segment's four triangles at the positions `x`, and its box.
fn segments(mesh: &Mesh, x: &dyn Fn(u64) -> V3) -> (Segs, Boxes) {
    let segs: Segs = mesh
        .shells
        .iter()
        .map(|(_, _, n)| (*n, split(&n.map(x))))
        .collect();
    let boxes: Boxes = segs
        .iter()
        .map(|(_, t)| {
            let mut lo = [f64::INFINITY; 3];
            let mut hi = [f64::NEG_INFINITY; 3];
            for tri in t {
                let (a, b) = tri_bbox(tri);
                for k in 0..3 {
                    lo[k] = lo[k].min(a[k]);
                    hi[k] = hi[k].max(b[k]);
                }
            }
            (lo, hi)
        })
        .collect();
    (segs, boxes)
}

/// Pairs of segments with no common node that intersect.
fn crossing_pairs(mesh: &Mesh, segs: &Segs, boxes: &Boxes) -> Vec<(u64, u64)> {
    let near = |i: usize, j: usize| {
        (0..3).all(|k| boxes[i].0[k] <= boxes[j].1[k] && boxes[j].0[k] <= boxes[i].1[k])
    };
    let mut crossings = Vec::new();
    for i in 0..segs.len() {
        for j in i + 1..segs.len() {
            if segs[i].0.iter().any(|n| segs[j].0.contains(n)) || !near(i, j) {
                continue;
            }
            if segs[i]
                .1
                .iter()
                .any(|a| segs[j].1.iter().any(|b| triangles_intersect(a, b)))
            {
                crossings.push((mesh.shells[i].0, mesh.shells[j].0));
            }
        }
    }
    crossings
}

/// A square steel tube (40 x 40 x 120 mm, t = 1, 6 x 18 shells per side and
/// length, Johnson-Cook) crushed 35 mm by a rigid wall at 10 mm/ms, TYPE7
/// self-contact (gap t = 1): it folds into lobes (the mid-line of each side
/// swings in and out along the axis, several mm), and in the final state no
/// two tube segments that share no node intersect — no node went through the
/// tube's wall. Measured: final length 85 mm, deviations up to ±8.7 mm, 0
/// crossing pairs, closest node–segment distance 0.97 (gap 1); the same crush
/// without the TYPE7 ends with 72 crossing pairs (checked here too).
#[test]
fn tube_crush_folds_without_crossing_itself() {
    let (w, nw, nl, gap) = (40.0, 6usize, 18usize, 1.0);
    let d = deck("tube_crush");
    let mesh = read_mesh(&d);
    let r = run(&d, &scratch("tube_crush"), &RunArgs::default());
    assert!(r.listing.normal_termination());
    assert!(
        r.listing.inter.iter().any(|l| l.pairs > 0),
        "self-contact happened"
    );
    let s = r.final_state();
    let x = |id: u64| -> V3 { [s[&id][0], s[&id][1], s[&id][2]] };
    // Length: crushed by the wall's travel.
    let xs: Vec<f64> = mesh
        .nodes
        .keys()
        .filter(|&&id| id < 99999)
        .map(|&id| x(id)[0])
        .collect();
    let len = xs.iter().copied().fold(f64::NEG_INFINITY, f64::max)
        - xs.iter().copied().fold(f64::INFINITY, f64::min);
    eprintln!("tube_crush: length 120 -> {len:.3}");
    assert!((len - 85.0).abs() < 1.0, "final length {len}");
    // Lobes: on each side's mid-line, count the swings beyond ±1.5 mm.
    let nr = 4 * nw;
    for side in 0..4 {
        let k = side * nw + nw / 2;
        let (ax, sign) = [(2, -1.0), (1, 1.0), (2, 1.0), (1, -1.0)][side];
        let mut swings = 0;
        let mut last = 0.0f64;
        let mut devs = Vec::new();
        for j in 0..=nl {
            let p = x((j * nr + k + 1) as u64);
            let dev = sign * p[ax] - w / 2.0;
            devs.push((dev * 10.0).round() / 10.0);
            if dev.abs() > 1.5 {
                if last != 0.0 && dev.signum() != last.signum() {
                    swings += 1;
                }
                last = dev;
            }
        }
        eprintln!("tube_crush: side {side} mid-line deviations {devs:?}");
        assert!(swings >= 2, "side {side}: {swings} in/out swings: {devs:?}");
    }
    let (segs, boxes) = segments(&mesh, &x);
    let crossings = crossing_pairs(&mesh, &segs, &boxes);
    // The closest approach of a node to a segment it is not on.
    let mut dmin = (f64::INFINITY, 0u64, 0u64);
    for (&id, _) in mesh.nodes.iter().filter(|(&id, _)| id < 99999) {
        let p = x(id);
        for (i, (n, tris)) in segs.iter().enumerate() {
            if n.contains(&id) {
                continue;
            }
            let (lo, hi) = boxes[i];
            if (0..3).any(|k| p[k] < lo[k] - 2.0 * gap || p[k] > hi[k] + 2.0 * gap) {
                continue;
            }
            let dd = tris
                .iter()
                .map(|t| point_triangle_distance(p, t))
                .fold(f64::INFINITY, f64::min);
            if dd < dmin.0 {
                dmin = (dd, id, mesh.shells[i].0);
            }
        }
    }
    eprintln!(
        "tube_crush: {} crossing segment pairs; closest node-segment distance {:.4} (gap {gap}) \
         node {} segment {}",
        crossings.len(),
        dmin.0,
        dmin.1,
        dmin.2
    );
    assert!(
        crossings.is_empty(),
        "segments crossing each other: {crossings:?}"
    );
    assert!(dmin.0 > 0.0 && dmin.0 < gap, "closest approach {}", dmin.0);

    // The same crush without the TYPE7: the check does see the walls go through each other.
    let dir = scratch("tube_crush_nocontact");
    let text = std::fs::read_to_string(&d).unwrap();
    let (head, rest) = text.split_once("/INTER/TYPE7/1").unwrap();
    let tail = &rest[rest.find("/END").unwrap()..];
    let nd = dir.join("deck").join("tube_crush_0000.rad");
    std::fs::create_dir_all(nd.parent().unwrap()).unwrap();
    std::fs::write(&nd, format!("{head}{tail}")).unwrap();
    std::fs::copy(
        d.with_file_name("tube_crush_0001.rad"),
        nd.with_file_name("tube_crush_0001.rad"),
    )
    .unwrap();
    let r0 = run(&nd, &dir, &RunArgs::default());
    assert!(r0.listing.normal_termination());
    let s0 = r0.final_state();
    let x0 = |id: u64| -> V3 { [s0[&id][0], s0[&id][1], s0[&id][2]] };
    let (segs0, boxes0) = segments(&mesh, &x0);
    let c0 = crossing_pairs(&mesh, &segs0, &boxes0);
    eprintln!(
        "tube_crush without contact: {} crossing segment pairs",
        c0.len()
    );
    assert!(
        c0.len() > 10,
        "without contact the walls cross: {} pairs",
        c0.len()
    );
}
