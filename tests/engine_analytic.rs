//! Analytic checks of the explicit shell engine, each on its own small deck
//! (decks/<name>/, written by decks/make_analytic.py; units kg, mm, ms, GPa):
//!
//! * `bar_impact`: elastic strip (ν = 0) at 5 m/s onto a fixed sliding rigid
//!   wall — behind the front σ = −ρcv and the particles are at rest, ahead of
//!   it nothing has happened yet, the front is at x = c·t.
//! * `cantilever`: clamped strip under a suddenly applied tip load — the tip
//!   oscillates about P L³/(3EI) with the first bending period.
//! * `jc_tension`: Johnson-Cook strip in homogeneous uniaxial tension —
//!   σxx = a + b ε_p^n, σyy = 0, at ε_p ≈ 0.02, 0.08 and 0.2.
//! * `patch_stretch` / `patch_parallelogram`: 3×3 distorted (resp. parallelogram)
//!   patch under v = (ε̇x, 0, 0) — every element carries the same plane-stress
//!   state E/(1−ν²)·ε, ν·σxx, 0.

mod common;
use common::{deck, read_csv, scratch};

use std::collections::HashMap;
use std::path::Path;

const E: f64 = 210.0;
const RHO: f64 = 7.85e-6;

/// Nodes (id → initial x, y, z) and 4-node shells (id → node ids) of a starter
/// deck in the fixed format (ids 10 wide, reals 20 wide).
struct Mesh {
    nodes: HashMap<u64, [f64; 3]>,
    shells: Vec<(u64, [u64; 4])>,
}

fn read_mesh(path: &Path) -> Mesh {
    let text = std::fs::read_to_string(path).unwrap();
    let field =
        |l: &str, a: usize, b: usize| l.get(a..b.min(l.len())).unwrap_or("").trim().to_string();
    let mut block = String::new();
    let mut nodes = HashMap::new();
    let mut shells = Vec::new();
    for l in text.lines() {
        if l.starts_with('#') || l.trim().is_empty() {
            continue;
        }
        if l.starts_with('/') {
            block = l.to_string();
            continue;
        }
        if block == "/NODE" {
            let id: u64 = field(l, 0, 10).parse().unwrap();
            let c = [10, 30, 50].map(|a| field(l, a, a + 20).parse::<f64>().unwrap());
            nodes.insert(id, c);
        } else if block.starts_with("/SHELL/") {
            let v: Vec<u64> = (0..5)
                .map(|k| field(l, 10 * k, 10 * k + 10).parse().unwrap())
                .collect();
            shells.push((v[0], [v[1], v[2], v[3], v[4]]));
        }
    }
    Mesh { nodes, shells }
}

/// The end time of an engine file (the line after /RUN/...).
fn end_time(engine: &Path) -> f64 {
    let text = std::fs::read_to_string(engine).unwrap();
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    while let Some(l) = lines.next() {
        if l.starts_with("/RUN/") {
            return lines.next().unwrap().trim().parse().unwrap();
        }
    }
    panic!("no /RUN in {}", engine.display())
}

struct Results {
    /// id → [x, y, z, vx, vy, vz].
    state: HashMap<u64, [f64; 6]>,
    /// id → [sxx, syy, sxy, eps_p, thick].
    elements: HashMap<u64, [f64; 5]>,
    history: Option<(Vec<String>, Vec<Vec<f64>>)>,
}

/// Runs a deck (with an optional engine file) and reads what it wrote.
fn run(deck: &Path, engine: Option<&Path>, dir: &Path, history: bool) -> Results {
    let fs = dir.join("final_state.csv");
    let fe = dir.join("final_elements.csv");
    let th = dir.join("history.csv");
    let mut args = vec![
        "run".to_string(),
        deck.to_str().unwrap().into(),
        "--out".into(),
        dir.to_str().unwrap().into(),
        "--final-state".into(),
        fs.to_str().unwrap().into(),
        "--final-elements".into(),
        fe.to_str().unwrap().into(),
    ];
    if let Some(e) = engine {
        args.push("--engine".into());
        args.push(e.to_str().unwrap().into());
    }
    if history {
        args.push("--history".into());
        args.push(th.to_str().unwrap().into());
    }
    let a: Vec<&str> = args.iter().map(String::as_str).collect();
    let out = common::crashsim(&a);
    assert!(
        out.status.success(),
        "crashsim {a:?} failed:\n{}\n{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    let (_, rows) = read_csv(&fs);
    let state = rows
        .iter()
        .map(|r| (r[0] as u64, [r[1], r[2], r[3], r[4], r[5], r[6]]))
        .collect();
    let (_, rows) = read_csv(&fe);
    let elements = rows
        .iter()
        .map(|r| {
            assert_eq!(r[8], 0.0, "element {} deleted", r[1]);
            (r[1] as u64, [r[2], r[3], r[4], r[5], r[6]])
        })
        .collect();
    Results {
        state,
        elements,
        history: history.then(|| read_csv(&th)),
    }
}

fn centre(mesh: &Mesh, nodes: &[u64; 4]) -> [f64; 3] {
    let mut c = [0.0; 3];
    for n in nodes {
        for (ck, xk) in c.iter_mut().zip(mesh.nodes[n]) {
            *ck += 0.25 * xk;
        }
    }
    c
}

// ---------------------------------------------------------------------------

/// A free elastic strip (ν = 0: uniaxial stress, c = √(E/ρ)) hits a fixed rigid
/// wall at v = 5 mm/ms. At t = L/(2c) the compressive front is at x = L/2:
/// behind it σxx = −ρcv and vx = 0, ahead σxx = 0 and vx = −v.
#[test]
fn bar_impact_stress_behind_the_front_is_rho_c_v() {
    let d = deck("bar_impact");
    let mesh = read_mesh(&d);
    let t_end = end_time(&d.with_file_name("bar_impact_0001.rad"));
    let r = run(&d, None, &scratch("bar"), false);
    let v = 5.0;
    let c = (E / RHO).sqrt();
    let sig = RHO * c * v; // 0.2030 GPa
    let len = mesh.nodes.values().map(|p| p[0]).fold(0.0, f64::max);
    assert!((len - 200.0).abs() < 1e-9);

    let mut behind = Vec::new();
    let mut ahead_max = 0.0f64;
    let mut front = 0.0f64; // centre of the farthest element with σxx < −σ/2
    for (id, nodes) in &mesh.shells {
        let xc = centre(&mesh, nodes)[0];
        let sxx = r.elements[id][0];
        if (0.1 * len..=0.4 * len).contains(&xc) {
            behind.push(sxx);
        }
        if xc >= 0.6 * len {
            ahead_max = ahead_max.max(sxx.abs());
        }
        if sxx < -0.5 * sig {
            front = front.max(xc);
        }
    }
    let mean = behind.iter().sum::<f64>() / behind.len() as f64;
    println!(
        "bar: rho c v = {sig:.6}, mean sxx (10-40% L) = {mean:.6} ({:+.3}%), max |sxx| ahead = {ahead_max:.3e}, front at {front} (c t = {:.3})",
        100.0 * (mean / -sig - 1.0),
        c * t_end
    );
    assert_eq!(behind.len(), 60);
    assert!(
        (mean + sig).abs() <= 0.02 * sig,
        "mean sxx behind the front {mean} vs -rho c v = {}",
        -sig
    );
    assert!(
        ahead_max < 0.05 * sig,
        "ahead of the front |sxx| reaches {ahead_max} (rho c v = {sig})"
    );
    assert!(
        (front - c * t_end).abs() <= 2.0,
        "the front is at x = {front}, expected c t = {}",
        c * t_end
    );

    // Particle velocities: the jump across the front is v.
    let (mut vb, mut vb_max, mut nb) = (0.0, 0.0f64, 0);
    for (id, p) in &mesh.nodes {
        let vx = r.state[id][3];
        if (0.1 * len..=0.4 * len).contains(&p[0]) {
            vb += vx;
            nb += 1;
            vb_max = vb_max.max(vx.abs());
        }
        if p[0] >= 0.6 * len {
            assert!(
                (vx + v).abs() <= 1e-6 * v,
                "node {id} ahead of the front: vx = {vx}"
            );
        }
    }
    vb /= nb as f64;
    println!("bar: behind the front mean vx = {vb:.3e}, max |vx| = {vb_max:.3}");
    assert!(vb.abs() <= 0.01 * v, "mean vx behind the front {vb}");
    assert!(vb_max <= 0.1 * v, "max |vx| behind the front {vb_max}");
}

/// Clamped strip (L = 100, b = 10, t = 1, ν = 0) with a tip load P applied at
/// t = 0 and held: the tip oscillates about δ = P L³/(3EI) with the period
/// T1 = 1/f1, f1 = 1.8751²/(2πL²)·√(EI/(ρA)).
#[test]
fn cantilever_first_bending_period_and_static_deflection() {
    let d = deck("cantilever");
    let r = run(&d, None, &scratch("cantilever"), true);
    let (l, b, t) = (100.0, 10.0, 1.0);
    let ei = E * b * t * t * t / 12.0;
    let p = 3.0 * ei * 0.1 / (l * l * l); // as the deck: δ_static = 0.1 mm
    let d_static = p * l * l * l / (3.0 * ei);
    let f1 = 1.8751f64.powi(2) / (2.0 * std::f64::consts::PI * l * l)
        * (E * t * t / (12.0 * RHO)).sqrt();
    let t1 = 1.0 / f1;

    let (header, rows) = r.history.unwrap();
    assert_eq!(header[3], "dz_42", "history columns {header:?}");
    let ts: Vec<f64> = rows.iter().map(|r| r[0]).collect();
    let z: Vec<f64> = rows.iter().map(|r| r[3]).collect();
    assert!(
        ts[1] - ts[0] <= t1 / 100.0,
        "history period {}",
        ts[1] - ts[0]
    );
    // Up-crossings of the mean, linearly interpolated; the mean is taken over
    // the whole periods between the first and the last crossing (iterated).
    let crossings = |m: f64| -> Vec<f64> {
        (1..z.len())
            .filter(|&i| z[i - 1] < m && z[i] >= m)
            .map(|i| ts[i - 1] + (m - z[i - 1]) / (z[i] - z[i - 1]) * (ts[i] - ts[i - 1]))
            .collect()
    };
    let mut mean = z.iter().sum::<f64>() / z.len() as f64;
    let mut cr = crossings(mean);
    for _ in 0..3 {
        assert!(cr.len() >= 3, "only {} up-crossings: {cr:?}", cr.len());
        let (a, e) = (cr[0], cr[cr.len() - 1]);
        let mut s = 0.0;
        for i in 1..z.len() {
            let (t0, t1_) = (ts[i - 1].max(a), ts[i].min(e));
            if t1_ > t0 {
                // Trapezoid on the clipped interval (linear interpolation).
                let zi =
                    |tt: f64| z[i - 1] + (z[i] - z[i - 1]) * (tt - ts[i - 1]) / (ts[i] - ts[i - 1]);
                s += 0.5 * (zi(t0) + zi(t1_)) * (t1_ - t0);
            }
        }
        mean = s / (e - a);
        cr = crossings(mean);
    }
    let period = (cr[cr.len() - 1] - cr[0]) / (cr.len() - 1) as f64;
    let zmax = z.iter().cloned().fold(f64::MIN, f64::max);
    println!(
        "cantilever: period {period:.5} ms vs T1 {t1:.5} ({:+.3}%), mean tip deflection {mean:.6} vs P L^3/3EI {d_static:.6} ({:+.3}%), max {zmax:.5}, {} periods",
        100.0 * (period / t1 - 1.0),
        100.0 * (mean / d_static - 1.0),
        cr.len() - 1
    );
    assert!(
        (period / t1 - 1.0).abs() <= 0.01,
        "period {period} vs analytic {t1}"
    );
    assert!(
        (mean / d_static - 1.0).abs() <= 0.01,
        "mean tip deflection {mean} vs static {d_static}"
    );
    // Sudden load, no damping: the peak is about twice the static deflection.
    assert!((zmax / d_static - 2.0).abs() < 0.05, "peak {zmax}");
}

/// Johnson-Cook (a = 0.2, b = 0.5, n = 0.4, c = 0) strip in homogeneous
/// uniaxial tension (linear initial velocity field, right end pulled at
/// 4 mm/ms, lateral contraction free): σxx = a + b ε_p^n, σyy = 0, the same in
/// every element, at ε_p ≈ 0.02, 0.08 and 0.2 (three runs of the same starter).
#[test]
fn jc_tension_follows_the_hardening_curve() {
    let d = deck("jc_tension");
    let (a, b, n) = (0.2, 0.5, 0.4);
    let (len, edot) = (40.0, 0.1); // V / L
    let dir = scratch("jc");
    let committed = d.with_file_name("jc_tension_0001.rad");
    // The committed engine file runs to ε_p ≈ 0.2; the smaller ones are written here.
    let t_committed = end_time(&committed);
    for target in [0.02, 0.08, 0.2] {
        // Log strain ε_p + σ/E reached at t: ln(1 + edot t).
        let sig_t = a + b * f64::powf(target, n);
        let t_end = ((target + sig_t / E).exp() - 1.0) / edot;
        let sub = dir.join(format!("eps{target}"));
        std::fs::create_dir_all(&sub).unwrap();
        let eng = if target == 0.2 {
            assert!(
                (t_committed / t_end - 1.0).abs() < 1e-4,
                "committed end time {t_committed} vs {t_end}"
            );
            committed.clone()
        } else {
            let eng = sub.join("jc_tension_0001.rad");
            std::fs::write(
                &eng,
                format!("/RUN/jc_tension/1\n{t_end:.6}\n/DT\n0.9 0.0\n/PRINT/-1000/55\n"),
            )
            .unwrap();
            eng
        };
        let r = run(&d, Some(&eng), &sub, false);

        let els: Vec<[f64; 5]> = r.elements.values().copied().collect();
        assert_eq!(els.len(), 4);
        let mean = els.iter().map(|e| e[0]).sum::<f64>() / els.len() as f64;
        let spread = els.iter().map(|e| (e[0] - mean).abs()).fold(0.0, f64::max);
        // Kinematic check of ε_p: ln(stretch) = ε_p + σxx/E in uniaxial plane stress.
        let x_right = r.state[&5][0];
        let ep_kin = (x_right / len).ln() - mean / E;
        for (k, e) in els.iter().enumerate() {
            let (sxx, syy, ep) = (e[0], e[1], e[3]);
            let want = a + b * ep.powf(n);
            println!(
                "jc ε_p {target}: element {k}: eps_p {ep:.6} (kinematic {ep_kin:.6}), sxx {sxx:.6} vs a+b eps_p^n {want:.6} ({:+.2e}), syy/sxx {:+.2e}",
                sxx / want - 1.0,
                syy / sxx
            );
            assert!(
                (ep / target - 1.0).abs() < 0.2,
                "eps_p {ep} far from the target {target}"
            );
            assert!(
                (sxx / want - 1.0).abs() <= 1e-3,
                "sxx {sxx} vs a + b eps_p^n = {want} at eps_p = {ep}"
            );
            assert!(syy.abs() <= 1e-3 * sxx, "syy {syy} vs sxx {sxx}");
            assert!(
                (ep - ep_kin).abs() <= 1e-3 * ep,
                "eps_p {ep} vs ln(stretch) - sxx/E = {ep_kin}"
            );
        }
        assert!(
            spread <= 1e-3 * mean,
            "element sxx spread {spread} (mean {mean})"
        );
    }
}

/// Stress (xx, yy, xy) from an element's local frame to the global one. The
/// frame is the engine's (src/element/shell4.rs): e3 ∝ d13 × d24,
/// e1 ∝ g1 + g2 × e3 with g1 = d13 − d24, g2 = d13 + d24 (flat, z = 0 here).
fn to_global(p: &[[f64; 3]; 4], s: [f64; 3]) -> [f64; 3] {
    let d13 = [p[2][0] - p[0][0], p[2][1] - p[0][1]];
    let d24 = [p[3][0] - p[1][0], p[3][1] - p[1][1]];
    assert!(d13[0] * d24[1] - d13[1] * d24[0] > 0.0, "normal along +z");
    let g1 = [d13[0] - d24[0], d13[1] - d24[1]];
    let g2 = [d13[0] + d24[0], d13[1] + d24[1]];
    let e1 = [g1[0] + g2[1], g1[1] - g2[0]];
    let h = (e1[0] * e1[0] + e1[1] * e1[1]).sqrt();
    let (c, sn) = (e1[0] / h, e1[1] / h);
    [
        c * c * s[0] + sn * sn * s[1] - 2.0 * c * sn * s[2],
        sn * sn * s[0] + c * c * s[1] + 2.0 * c * sn * s[2],
        c * sn * (s[0] - s[1]) + (c * c - sn * sn) * s[2],
    ]
}

/// Patch under v = (ε̇x, 0, 0): boundary held to the field, interior free.
/// Every element must carry the same global stress, equal to the plane-stress
/// state with εxx = ε, εyy = 0: σxx = E/(1−ν²)ε, σyy = νσxx, σxy = 0. The
/// engine integrates the rate of deformation on the mid-step geometry, so ε is
/// the logarithmic strain ln(x/X), taken here from the final node positions.
fn patch(name: &str) {
    let nu = 0.3;
    let d = deck(name);
    let mesh = read_mesh(&d);
    let r = run(&d, None, &scratch(name), false);
    let xmax = mesh.nodes.values().map(|p| p[0]).fold(0.0, f64::max);
    // ε from the right-hand boundary nodes (all at the same X).
    let right: Vec<u64> = mesh
        .nodes
        .iter()
        .filter(|(_, p)| p[0] == xmax)
        .map(|(id, _)| *id)
        .collect();
    let eps = (r.state[&right[0]][0] / xmax).ln();
    assert!(eps > 9e-4, "strain reached {eps}");
    // Every node, interior included, still on the linear field x = X·e^ε, y = Y.
    for (id, p) in &mesh.nodes {
        let s = r.state[id];
        assert!(
            (s[0] - p[0] * eps.exp()).abs() <= 1e-9 * xmax && (s[1] - p[1]).abs() <= 1e-9 * xmax,
            "node {id} left the linear field: ({}, {}) from ({}, {})",
            s[0],
            s[1],
            p[0],
            p[1]
        );
    }
    let sxx = E / (1.0 - nu * nu) * eps;
    let want = [sxx, nu * sxx, 0.0];
    let mut g_all = Vec::new();
    let mut local_spread = 0.0f64;
    for (id, nodes) in &mesh.shells {
        let p = nodes.map(|n| [r.state[&n][0], r.state[&n][1], r.state[&n][2]]);
        let s = r.elements[id];
        local_spread = local_spread.max((s[0] - sxx).abs() / sxx);
        g_all.push((*id, to_global(&p, [s[0], s[1], s[2]])));
    }
    let mut dev = [0.0f64; 3];
    let mut err = [0.0f64; 3];
    for (_, g) in &g_all {
        for k in 0..3 {
            dev[k] = dev[k].max((g[k] - g_all[0].1[k]).abs() / sxx);
            err[k] = err[k].max((g[k] - want[k]).abs() / sxx);
        }
    }
    println!(
        "{name}: eps = {eps:.9}, expected (sxx, syy, sxy) = ({:.9}, {:.9}, 0); element 1 global {:?}; max deviation between elements / sxx = [{:.2e}, {:.2e}, {:.2e}], from analytic / sxx = [{:.2e}, {:.2e}, {:.2e}] (local-frame sxx differ by up to {local_spread:.2e})",
        want[0], want[1], g_all[0].1, dev[0], dev[1], dev[2], err[0], err[1], err[2]
    );
    for k in 0..3 {
        assert!(
            dev[k] <= 1e-6,
            "{name}: stress component {k} differs between elements by {:.3e} of sxx: {g_all:?}",
            dev[k]
        );
        assert!(
            err[k] <= 1e-6,
            "{name}: stress component {k} off the analytic value by {:.3e} of sxx: {g_all:?} vs {want:?}",
            err[k]
        );
    }
}

#[test]
fn patch_of_distorted_quads_under_uniform_stretch_is_uniform() {
    patch("patch_stretch");
}

#[test]
fn patch_of_parallelograms_under_uniform_stretch_is_uniform() {
    patch("patch_parallelogram");
}
