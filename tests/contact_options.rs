//! Every /INTER/TYPE7 option changes the result the way the card says, on
//! tiny decks written here (units kg, mm, ms, GPa):
//!
//! * a "probe": a 10 x 10 shell plate held at a distance d above a fixed
//!   40 x 40 shell plate (all nodes fixed): the first cycle's INTER line gives
//!   the force of 4 identical pairs, F = K·P·G/(G − P) with P = G − d, from
//!   which the stiffness K (Istf, Stfac, Stmin, Stmax) or the gap G (Igap,
//!   Gapmin, Fscalegap, Gapmax, %mesh_size) is read back; Inacti, Fpenmax,
//!   Tstart/Tstop switch it off;
//! * a lone node with an added mass over a fixed plate: falling (VISs, dtmin
//!   and ITIED), sliding at an imposed speed (Ifric, Ifiltr/Xfreq, Iform),
//!   flying into a wall with a fixed DOF (IBC), driven along a plate (Inacti);
//! * a flat strip of small shells in self-contact (Irem_gap);
//! * the ball drop deck with another Bumult (same bytes, other sort count).

#[path = "contact_common/mod.rs"]
mod cc;
mod common;

use cc::*;
use std::path::{Path, PathBuf};

const RHO: f64 = 7.85e-6;

fn i10(v: i64) -> String {
    format!("{v:>10}")
}

fn r20(v: f64) -> String {
    let s = format!("{v}");
    let s = if s.len() > 20 { format!("{v:.12e}") } else { s };
    format!("{s:>20}")
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// /INTER/TYPE7 fields (0 = the card's default, as in the deck).
#[derive(Clone, Debug, Default)]
struct T7 {
    istf: i64,
    igap: i64,
    fscalegap: f64,
    gapmax: f64,
    fpenmax: f64,
    itied: i64,
    stmin: f64,
    stmax: f64,
    mesh_pct: f64,
    dtmin: f64,
    irem_gap: i64,
    stfac: f64,
    fric: f64,
    gapmin: f64,
    tstart: f64,
    tstop: f64,
    ibc: &'static str,
    inacti: i64,
    viss: f64,
    visf: f64,
    bumult: f64,
    ifric: i64,
    ifiltr: i64,
    xfreq: f64,
    iform: i64,
    coefs: [f64; 6],
}

impl T7 {
    fn card(&self, id: u64, sec: u64, main: u64) -> Vec<String> {
        let mut l = vec![
            format!("/INTER/TYPE7/{id}"),
            "option test".into(),
            format!(
                "{}{}{}{}{}{}{}{}{}{}",
                i10(sec as i64),
                i10(main as i64),
                i10(self.istf),
                i10(0),
                i10(self.igap),
                " ".repeat(10),
                i10(0),
                i10(0),
                i10(0),
                i10(0)
            ),
            format!(
                "{}{}{}{}{}{}",
                r20(self.fscalegap),
                r20(self.gapmax),
                r20(self.fpenmax),
                " ".repeat(20),
                i10(self.itied),
                i10(0)
            ),
            format!(
                "{}{}{}{}{}{}",
                r20(self.stmin),
                r20(self.stmax),
                r20(self.mesh_pct),
                r20(self.dtmin),
                i10(self.irem_gap),
                i10(0)
            ),
            format!(
                "{}{}{}{}{}",
                r20(self.stfac),
                r20(self.fric),
                r20(self.gapmin),
                r20(self.tstart),
                r20(self.tstop)
            ),
            format!(
                "{:>10}{}{}{}{}{}",
                if self.ibc.is_empty() { "000" } else { self.ibc },
                " ".repeat(20),
                i10(self.inacti),
                r20(self.viss),
                r20(self.visf),
                r20(self.bumult)
            ),
            format!(
                "{}{}{}{}{}{}{}{}",
                i10(self.ifric),
                i10(self.ifiltr),
                r20(self.xfreq),
                i10(self.iform),
                i10(0),
                i10(0),
                r20(0.0),
                i10(0)
            ),
        ];
        if self.ifric > 0 {
            l.push(self.coefs[..5].iter().map(|&c| r20(c)).collect());
            if self.ifric > 1 {
                l.push(r20(self.coefs[5]));
            }
        }
        l
    }
}

/// A starter deck under construction.
struct Deck {
    l: Vec<String>,
}

impl Deck {
    fn new(name: &str) -> Deck {
        let u = format!("{:>20}{:>20}{:>20}", "kg", "mm", "ms");
        Deck {
            l: vec![
                "/BEGIN".into(),
                name.into(),
                i10(2019) + &i10(0),
                u.clone(),
                u,
            ],
        }
    }
    fn law1(&mut self, id: u64, rho: f64, e: f64, nu: f64) {
        self.l.extend([
            format!("/MAT/LAW1/{id}"),
            "elastic".into(),
            r20(rho),
            r20(e) + &r20(nu),
        ]);
    }
    fn shell_prop(&mut self, id: u64, t: f64) {
        self.l.extend([
            format!("/PROP/SHELL/{id}"),
            "shell".into(),
            i10(1) + &i10(2) + &i10(2) + &i10(0),
            r20(0.01) + &r20(0.01) + &r20(0.01) + &r20(0.0) + &r20(0.0),
            i10(1) + &i10(1) + &r20(t) + &r20(0.0) + &" ".repeat(10) + &i10(0) + &i10(1),
        ]);
    }
    fn part(&mut self, id: u64, prop: u64, mat: u64) {
        self.l.extend([
            format!("/PART/{id}"),
            "part".into(),
            i10(prop as i64) + &i10(mat as i64) + &i10(0),
        ]);
    }
    fn nodes(&mut self, n: &[(u64, [f64; 3])]) {
        self.l.push("/NODE".into());
        for (id, x) in n {
            self.l
                .push(i10(*id as i64) + &r20(x[0]) + &r20(x[1]) + &r20(x[2]));
        }
    }
    fn shells(&mut self, part: u64, s: &[(u64, [u64; 4])]) {
        self.l.push(format!("/SHELL/{part}"));
        for (id, n) in s {
            self.l
                .push(i10(*id as i64) + &n.iter().map(|&v| i10(v as i64)).collect::<String>());
        }
    }
    fn grnod(&mut self, id: u64, nodes: &[u64]) {
        self.l.push(format!("/GRNOD/NODE/{id}"));
        self.l.push("group".into());
        for c in nodes.chunks(10) {
            self.l
                .push(c.iter().map(|&v| i10(v as i64)).collect::<String>());
        }
    }
    fn grnod_part(&mut self, id: u64, part: u64) {
        self.l.extend([
            format!("/GRNOD/PART/{id}"),
            "part nodes".into(),
            i10(part as i64),
        ]);
    }
    fn surf_part(&mut self, id: u64, part: u64) {
        self.l.extend([
            format!("/SURF/PART/{id}"),
            "surface".into(),
            i10(part as i64),
        ]);
    }
    fn bcs(&mut self, id: u64, code: &str, grnod: u64) {
        self.l.extend([
            format!("/BCS/{id}"),
            "bcs".into(),
            format!("{code:>10}") + &i10(0) + &i10(grnod as i64),
        ]);
    }
    fn admas(&mut self, id: u64, mass: f64, grnod: u64) {
        self.l.extend([
            format!("/ADMAS/0/{id}"),
            "added mass".into(),
            r20(mass) + &i10(grnod as i64),
        ]);
    }
    fn grav(&mut self, id: u64, dir: &str, g: f64, grnod: u64) {
        self.l.extend([
            format!("/GRAV/{id}"),
            "gravity".into(),
            i10(0)
                + &format!("{dir:>10}")
                + &i10(0)
                + &i10(0)
                + &i10(grnod as i64)
                + &" ".repeat(10)
                + &r20(1.0)
                + &r20(g),
        ]);
    }
    fn inivel(&mut self, id: u64, v: [f64; 3], grnod: u64) {
        self.l.extend([
            format!("/INIVEL/TRA/{id}"),
            "initial velocity".into(),
            r20(v[0]) + &r20(v[1]) + &r20(v[2]) + &i10(grnod as i64) + &i10(0),
        ]);
    }
    fn funct(&mut self, id: u64, pts: &[(f64, f64)]) {
        self.l.push(format!("/FUNCT/{id}"));
        self.l.push("function".into());
        for (x, y) in pts {
            self.l.push(r20(*x) + &r20(*y));
        }
    }
    fn impvel(&mut self, id: u64, fct: u64, dir: &str, grnod: u64, scale: f64) {
        self.l.extend([
            format!("/IMPVEL/{id}"),
            "imposed velocity".into(),
            i10(fct as i64)
                + &format!("{dir:>10}")
                + &i10(0)
                + &i10(0)
                + &i10(grnod as i64)
                + &i10(0)
                + &i10(0),
            r20(1.0) + &r20(scale) + &r20(0.0) + &r20(0.0),
        ]);
    }
    fn inter(&mut self, id: u64, sec: u64, main: u64, t: &T7) {
        self.l.extend(t.card(id, sec, main));
    }
    /// Writes DIR/NAME_0000.rad and NAME_0001.rad; returns the starter's path.
    fn write(&self, dir: &Path, name: &str, tend: f64, print: i64, dt_scale: f64) -> PathBuf {
        std::fs::create_dir_all(dir).unwrap();
        let mut l = self.l.clone();
        l.push("/END".into());
        let s = dir.join(format!("{name}_0000.rad"));
        std::fs::write(&s, l.join("\n") + "\n").unwrap();
        let e = [
            format!("/RUN/{name}/1"),
            format!("{tend}"),
            "/DT".into(),
            format!("{dt_scale} 0.0"),
            format!("/PRINT/{print}/55"),
        ];
        std::fs::write(dir.join(format!("{name}_0001.rad")), e.join("\n") + "\n").unwrap();
        s
    }
}

/// A fixed shell plate of `n` x 1 shells (nodes 1001.., shells 1001..) on
/// [x0, x0 + n·w] x [−h/2, h/2] at z = 0: part 1 (steel, thickness t), its
/// surface 1001, its node group 1001 held fixed.
fn main_plate(d: &mut Deck, t: f64, x0: f64, w: f64, h: f64, n: usize) {
    d.law1(1, RHO, 210.0, 0.3);
    d.shell_prop(1, t);
    d.part(1, 1, 1);
    let mut nodes = Vec::new();
    for j in 0..2 {
        for i in 0..=n {
            nodes.push((
                1001 + (i + (n + 1) * j) as u64,
                [x0 + w * i as f64, -0.5 * h + h * j as f64, 0.0],
            ));
        }
    }
    d.nodes(&nodes);
    let s: Vec<(u64, [u64; 4])> = (0..n as u64)
        .map(|i| {
            (
                1001 + i,
                [
                    1001 + i,
                    1002 + i,
                    1002 + i + n as u64 + 1,
                    1001 + i + n as u64 + 1,
                ],
            )
        })
        .collect();
    d.shells(1, &s);
    d.grnod_part(1001, 1);
    d.surf_part(1001, 1);
    d.bcs(1001, "111 111", 1001);
}

// ---------------------------------------------------------------------------
// The probe: a fixed 10 x 10 plate (E_s, t_s) at height d over the main plate.

const KM: f64 = 0.5 * 210.0 * 1.0; // main shell stiffness 0.5·E·t (t = 1)

struct Probe {
    run: Run,
    /// First printed INTER line (cycle 1): forces with the initial positions.
    first: InterLine,
}

fn probe(tag: &str, t7: &T7, d: f64, e_s: f64, t_s: f64, tend: f64) -> Probe {
    let dir = scratch(&format!("opt-{tag}"));
    let mut k = Deck::new("probe");
    main_plate(&mut k, 1.0, -20.0, 40.0, 40.0, 1);
    k.law1(2, RHO, e_s, 0.3);
    k.shell_prop(2, t_s);
    k.part(2, 2, 2);
    k.nodes(&[
        (1, [-5.0, -5.0, d]),
        (2, [5.0, -5.0, d]),
        (3, [5.0, 5.0, d]),
        (4, [-5.0, 5.0, d]),
    ]);
    k.shells(2, &[(1, [1, 2, 3, 4])]);
    k.grnod(1, &[1, 2, 3, 4]);
    k.bcs(1, "111 111", 1);
    k.inter(1, 1, 1001, t7);
    let deck = k.write(&dir.join("deck"), "probe", tend, -1, 0.9);
    let run = run(&deck, &dir, &RunArgs::default());
    assert!(run.listing.normal_termination(), "{tag}: run failed");
    let first = run.listing.of(1)[0];
    Probe { run, first }
}

/// Per-pair stiffness K from the total force of the 4 pairs at distance d in gap g.
fn stiffness_of(f: f64, d: f64, g: f64) -> f64 {
    let p = g - d;
    f / 4.0 * (g - p) / (p * g)
}

/// The gap G from the per-pair force F = K (G − d) G / d.
fn gap_of(f: f64, d: f64, k: f64) -> f64 {
    let fp = f / 4.0;
    (k * d + (k * k * d * d + 4.0 * k * fp * d).sqrt()) / (2.0 * k)
}

/// Istf, Stfac, Stmin, Stmax (card comment 3): Km = Stfac·0.5·E_m·t_m = 105
/// (main shell), Ks = 0.5·E_s·t_s = 17.5 (the secondary plate: E 70, t 0.5).
/// Istf 1000: Km; 1: Stfac itself; 2, 3, 4, 5: mean, max, min, series of Km
/// and Ks, clamped to [Stmin, Stmax] — which Istf 1 and 1000 ignore. Read back
/// from the force at P = 0.2 in the default gap 1 (min(t_m, l_min/2)).
#[test]
fn istf_stfac_stmin_stmax_set_the_stiffness() {
    let (d, ks) = (0.8, 0.5 * 70.0 * 0.5);
    let cases: Vec<(&str, T7, f64)> = vec![
        ("default (Km)", T7::default(), KM),
        (
            "Stfac 2 (2 Km)",
            T7 {
                stfac: 2.0,
                ..T7::default()
            },
            2.0 * KM,
        ),
        (
            "Istf 1, Stfac 40",
            T7 {
                istf: 1,
                stfac: 40.0,
                ..T7::default()
            },
            40.0,
        ),
        (
            "Istf 2 mean",
            T7 {
                istf: 2,
                ..T7::default()
            },
            0.5 * (KM + ks),
        ),
        (
            "Istf 3 max",
            T7 {
                istf: 3,
                ..T7::default()
            },
            KM,
        ),
        (
            "Istf 4 min",
            T7 {
                istf: 4,
                ..T7::default()
            },
            ks,
        ),
        (
            "Istf 5 series",
            T7 {
                istf: 5,
                ..T7::default()
            },
            KM * ks / (KM + ks),
        ),
        (
            "Istf 4, Stfac 0.1: min(10.5, Ks)",
            T7 {
                istf: 4,
                stfac: 0.1,
                ..T7::default()
            },
            10.5,
        ),
        (
            "Istf 4, Stmin 30",
            T7 {
                istf: 4,
                stmin: 30.0,
                ..T7::default()
            },
            30.0,
        ),
        (
            "Istf 3, Stmax 50",
            T7 {
                istf: 3,
                stmax: 50.0,
                ..T7::default()
            },
            50.0,
        ),
        (
            "Istf 1000 ignores Stmin",
            T7 {
                stmin: 200.0,
                ..T7::default()
            },
            KM,
        ),
        (
            "Istf 1 ignores Stmax",
            T7 {
                istf: 1,
                stfac: 40.0,
                stmax: 20.0,
                ..T7::default()
            },
            40.0,
        ),
    ];
    for (i, (what, t7, want)) in cases.iter().enumerate() {
        let p = probe(&format!("istf{i}"), t7, d, 70.0, 0.5, 0.01);
        assert_eq!(p.first.pairs, 4, "{what}");
        let k = stiffness_of(p.first.normal[2], d, 1.0);
        eprintln!("{what}: K = {k:.6} (expected {want})");
        assert!(rel(k, *want) < 1e-6, "{what}: K = {k}, expected {want}");
    }
}

/// Igap, Gapmin, Fscalegap, Gapmax, %mesh_size (card comments 9–11): a 3 mm
/// secondary shell (g_s = 1.5) over the 1 mm main plate (g_m = 0.5), Gapmin
/// 0.2: Igap 0 keeps Gapmin; Igap 1 takes g_s + g_m = 2; Igap 2 scales it by
/// Fscalegap and caps it at Gapmax; Igap 3 also caps it at %mesh_size times
/// the smallest edges (10 + 40). Contact starts at a larger distance with the
/// thick shell: at d = 1.5 Igap 0 sees nothing, Igap 1 pushes.
#[test]
fn igap_gapmin_fscalegap_gapmax_set_the_gap() {
    let d = 0.5;
    let base = T7 {
        gapmin: 0.2,
        ..T7::default()
    };
    let cases: Vec<(&str, T7, f64)> = vec![
        (
            "Igap 0, Gapmin 0.7",
            T7 {
                gapmin: 0.7,
                ..T7::default()
            },
            0.7,
        ),
        ("Igap 0, Gapmin 0: min(t_m, l_min/2)", T7::default(), 1.0),
        (
            "Igap 1: g_s + g_m",
            T7 {
                igap: 1,
                ..base.clone()
            },
            2.0,
        ),
        (
            "Igap 1, Gapmin 2.4 > g_s + g_m",
            T7 {
                igap: 1,
                gapmin: 2.4,
                ..T7::default()
            },
            2.4,
        ),
        (
            "Igap 2, Fscalegap 0.5",
            T7 {
                igap: 2,
                fscalegap: 0.5,
                ..base.clone()
            },
            1.0,
        ),
        (
            "Igap 2, Gapmax 1.2",
            T7 {
                igap: 2,
                gapmax: 1.2,
                ..base.clone()
            },
            1.2,
        ),
        (
            "Igap 3, %mesh_size 0.02: 0.02 (10 + 40)",
            T7 {
                igap: 3,
                mesh_pct: 0.02,
                ..base.clone()
            },
            1.0,
        ),
        (
            "Igap 3, default %mesh_size 0.4",
            T7 {
                igap: 3,
                ..base.clone()
            },
            2.0,
        ),
    ];
    for (i, (what, t7, want)) in cases.iter().enumerate() {
        let p = probe(&format!("igap{i}"), t7, d, 210.0, 3.0, 0.01);
        assert_eq!(p.first.pairs, 4, "{what}");
        let g = gap_of(p.first.normal[2], d, KM);
        eprintln!("{what}: gap = {g:.6} (expected {want})");
        assert!(rel(g, *want) < 1e-6, "{what}: gap {g}, expected {want}");
    }
    // Farther than the constant gap, inside the variable one.
    let far = probe("igap-far0", &base, 1.5, 210.0, 3.0, 0.01);
    assert_eq!(far.first.pairs, 0);
    assert_eq!(far.first.normal[2], 0.0);
    let far1 = probe("igap-far1", &T7 { igap: 1, ..base }, 1.5, 210.0, 3.0, 0.01);
    assert_eq!(far1.first.pairs, 4);
    assert!(far1.first.normal[2] > 0.0);
}

/// Inacti 1, 2, 5, 6 and Fpenmax on an initially penetrated node (P0 = 0.2 in
/// the gap 1): the default pushes it with the full reaction; Inacti 1 (node
/// stiffness off), 2 (that segment off for it), 5 and 6 (gap reduced to the
/// initial distance, or 5% less) give it no force; Fpenmax 0.15 deactivates it
/// (P0 ≥ 0.15 G) whatever Inacti, Fpenmax 0.25 does not.
#[test]
fn inacti_and_fpenmax_on_initial_penetrations() {
    let d = 0.8;
    let full = KM * 0.2 / 0.8 * 4.0;
    let cases: Vec<(&str, T7, f64)> = vec![
        ("default", T7::default(), full),
        (
            "Inacti 1",
            T7 {
                inacti: 1,
                ..T7::default()
            },
            0.0,
        ),
        (
            "Inacti 2",
            T7 {
                inacti: 2,
                ..T7::default()
            },
            0.0,
        ),
        (
            "Inacti 5",
            T7 {
                inacti: 5,
                ..T7::default()
            },
            0.0,
        ),
        (
            "Inacti 6",
            T7 {
                inacti: 6,
                ..T7::default()
            },
            0.0,
        ),
        (
            "Fpenmax 0.15",
            T7 {
                fpenmax: 0.15,
                ..T7::default()
            },
            0.0,
        ),
        (
            "Fpenmax 0.15, Inacti 5",
            T7 {
                fpenmax: 0.15,
                inacti: 5,
                ..T7::default()
            },
            0.0,
        ),
        (
            "Fpenmax 0.25",
            T7 {
                fpenmax: 0.25,
                ..T7::default()
            },
            full,
        ),
    ];
    for (i, (what, t7, want)) in cases.iter().enumerate() {
        let p = probe(&format!("inacti{i}"), t7, d, 70.0, 0.5, 0.01);
        let f = p.first.normal[2];
        eprintln!(
            "{what}: F = {f:.6} (expected {want}), pairs {}",
            p.first.pairs
        );
        assert!(
            (f - want).abs() <= 1e-9 * full,
            "{what}: F = {f}, expected {want}"
        );
        // Held there, it stays so.
        let l = p.run.listing.last(1);
        assert!(
            (l.normal[2] - want).abs() <= 1e-9 * full,
            "{what}: at the end F = {}",
            l.normal[2]
        );
    }
}

/// Tstart, Tstop: no contact force outside [Tstart, Tstop], the full one inside.
#[test]
fn tstart_tstop_bound_the_contact_in_time() {
    let d = 0.8;
    let full = KM * 0.2 / 0.8 * 4.0;
    let t7 = T7 {
        tstart: 0.01,
        tstop: 0.02,
        ..T7::default()
    };
    let p = probe("tstart", &t7, d, 70.0, 0.5, 0.03);
    let lines = p.run.listing.of(1);
    assert!(lines.len() > 6);
    let (mut before, mut inside, mut after) = (0, 0, 0);
    for l in &lines {
        if l.t < 0.01 || l.t > 0.02 {
            assert_eq!(l.normal[2], 0.0, "t = {}: force outside the window", l.t);
            assert_eq!(l.pairs, 0);
            if l.t < 0.01 {
                before += 1
            } else {
                after += 1
            }
        } else {
            assert!(
                rel(l.normal[2], full) < 1e-9,
                "t = {}: F = {}",
                l.t,
                l.normal[2]
            );
            inside += 1;
        }
    }
    eprintln!("Tstart/Tstop: {before} prints before, {inside} inside, {after} after");
    assert!(before > 0 && inside > 0 && after > 0);
}

// ---------------------------------------------------------------------------
// A lone node (added mass) over the main plate.

struct NodeCase {
    mass: f64,
    x0: [f64; 3],
    v0: [f64; 3],
    /// /BCS code on the node ("" = free).
    bcs: &'static str,
    /// Gravity along -z on the node (0 = none).
    g: f64,
    /// Imposed velocity: (dir, function points, scale).
    impvel: Vec<(&'static str, Vec<(f64, f64)>, f64)>,
    /// Main plate: shells of width w along x starting at x0, and their count.
    plate: (f64, f64, usize),
    /// Vertical plate (normal +x through x = 0) instead of the horizontal one.
    wall: bool,
    tend: f64,
    print: i64,
    dt_scale: f64,
}

impl Default for NodeCase {
    fn default() -> Self {
        NodeCase {
            mass: 1.0,
            x0: [0.0, 0.0, 1.2],
            v0: [0.0; 3],
            bcs: "",
            g: 0.0,
            impvel: Vec::new(),
            plate: (-20.0, 40.0, 1),
            wall: false,
            tend: 3.0,
            print: -50,
            dt_scale: 0.9,
        }
    }
}

fn node_run(tag: &str, c: &NodeCase, t7: &T7) -> (Run, [f64; 6]) {
    let dir = scratch(&format!("opt-{tag}"));
    let mut k = Deck::new("node");
    main_plate(&mut k, 1.0, c.plate.0, c.plate.1, 40.0, c.plate.2);
    if c.wall {
        // Turn the plate upright: rewrite z = 0 as x = 0 (y and the old x as z).
        for line in k.l.iter_mut() {
            if line.len() == 70 && line.starts_with("      10") {
                let x: f64 = line[10..30].trim().parse().unwrap();
                let y: f64 = line[30..50].trim().parse().unwrap();
                *line = line[..10].to_string() + &r20(0.0) + &r20(y) + &r20(x);
            }
        }
    }
    k.nodes(&[(1, c.x0)]);
    k.grnod(1, &[1]);
    k.admas(1, c.mass, 1);
    if !c.bcs.is_empty() {
        k.bcs(1, c.bcs, 1);
    }
    if c.v0 != [0.0; 3] {
        k.inivel(1, c.v0, 1);
    }
    if c.g != 0.0 {
        k.grav(1, "Z", -c.g, 1);
    }
    for (i, (dir, f, s)) in c.impvel.iter().enumerate() {
        k.funct(10 + i as u64, f);
        k.impvel(10 + i as u64, 10 + i as u64, dir, 1, *s);
    }
    k.inter(1, 1, 1001, t7);
    let deck = k.write(&dir.join("deck"), "node", c.tend, c.print, c.dt_scale);
    let r = run(&deck, &dir, &RunArgs::default());
    assert!(r.listing.normal_termination(), "{tag}: run failed");
    let s = r.final_state()[&1];
    (r, s)
}

/// VISs: critical damping of the contact spring. A 1 kg node dropped at 0.5
/// mm/ms on the plate (K0 = 105, P ≪ gap: a linear spring) bounces back with
/// e = exp(−πξ/√(1 − ξ²)), ξ = VISs/√2 (C = VISs·√(2KM)), less about 1% for
/// the quadratic damper 0.4²·2M·(dP/dt)/(Gap − P) that acts whatever VISs
/// while the node closes in: no damping, e ≈ 0.99; VISs 0.05 (default),
/// e ≈ 0.887; the damper also pulls on the way out, so e follows the linear
/// value up to critical damping.
#[test]
fn viss_damps_the_rebound() {
    let c = NodeCase {
        v0: [0.0, 0.0, -0.5],
        ..NodeCase::default()
    };
    let mut last = f64::INFINITY;
    for (viss, lo, hi) in [
        (1e-30, 0.98, 0.995),
        (0.0, 0.875, 0.895), // the default, 0.05
        (0.2, 0.6, 0.66),
        (0.5, 0.28, 0.33),
        (1.0, 0.02, 0.06),
    ] {
        let (_, s) = node_run(
            &format!("viss{viss}"),
            &c,
            &T7 {
                viss,
                ..T7::default()
            },
        );
        let e = s[5] / 0.5;
        let v = if viss == 0.0 { 0.05 } else { viss };
        let xi = v / 2f64.sqrt();
        let lin = (-std::f64::consts::PI * xi / (1.0 - xi * xi).sqrt()).exp();
        eprintln!("VISs {v}: restitution {e:.5} (linear spring-damper {lin:.5})");
        assert!(e > lo && e < hi, "VISs {v}: e = {e}");
        assert!(e < last, "VISs {v}: more damping, less rebound");
        assert!((e - lin).abs() < 0.015, "VISs {v}: e = {e}, linear {lin}");
        last = e;
    }
}

/// dtmin with ITIED 0, 1, 2: the node (1 kg at 0.5 mm/ms) meets the plate with a
/// pair time step √(2M/K) ≈ 0.138 ms, below dtmin = 0.2: ITIED 0 removes it
/// from the interface (it goes through the plate); ITIED 2 ties it where it
/// is (it stays there, at rest); ITIED 1 ties it but lets go when the tie
/// pulls (it rebounds). With dtmin = 0 it bounces as usual.
#[test]
fn dtmin_and_itied() {
    let c = NodeCase {
        v0: [0.0, 0.0, -0.5],
        ..NodeCase::default()
    };
    let (_, free) = node_run("dtmin-none", &c, &T7::default());
    let (r0, gone) = node_run(
        "dtmin-0",
        &c,
        &T7 {
            dtmin: 0.2,
            ..T7::default()
        },
    );
    let t_end = r0.listing.cycles.last().unwrap().t;
    let (r2, tied) = node_run(
        "dtmin-2",
        &c,
        &T7 {
            dtmin: 0.2,
            itied: 2,
            ..T7::default()
        },
    );
    let (_, rebound) = node_run(
        "dtmin-1",
        &c,
        &T7 {
            dtmin: 0.2,
            itied: 1,
            ..T7::default()
        },
    );
    eprintln!(
        "dtmin: none z {:.4} vz {:.4}; ITIED 0 z {:.4} vz {:.4}; ITIED 2 z {:.4} vz {:.2e}; ITIED 1 z {:.4} vz {:.4}",
        free[2], free[5], gone[2], gone[5], tied[2], tied[5], rebound[2], rebound[5]
    );
    assert!(free[5] > 0.4 && free[2] > 1.0, "no dtmin: bounces");
    // Removed: passes through at the same speed, far below the plate.
    assert_eq!(gone[5], -0.5);
    assert!(
        (gone[2] - (1.2 - 0.5 * t_end)).abs() < 1e-4,
        "z = {}",
        gone[2]
    );
    assert!(
        r0.listing.inter.iter().all(|l| l.pairs == 0),
        "ITIED 0: never in contact"
    );
    // Tied without rebound: held in the gap (tied at ~its entry, 1 mm up),
    // ringing down on the tie spring.
    assert!(tied[2] > 0.9 && tied[2] < 1.0, "tied at z = {}", tied[2]);
    assert!(tied[5].abs() < 0.01, "tied node moves at {}", tied[5]);
    assert!(r2.listing.last(1).pairs == 1);
    // Tied with rebound: leaves the plate upwards.
    assert!(
        rebound[5] > 0.1 && rebound[2] > 1.0,
        "ITIED 1: z {} vz {}",
        rebound[2],
        rebound[5]
    );
}

/// Ifric 0, 1, 2, 3 (card eq. (11), (14), (15), (16)): the node, pressed by
/// gravity (1 kg, g = 0.01: N = 0.01 kN) and driven along x at V = 2 mm/ms, is
/// held back by T = μ(p, V)·N, p = N / (main segment area 1600).
#[test]
fn ifric_selects_the_friction_law() {
    let (m, g, v) = (1.0, 0.01, 2.0);
    let n = m * g;
    let gap = 1.0;
    let pen = n * gap / (KM * gap + n); // the resting penetration
    let c = NodeCase {
        mass: m,
        x0: [-10.0, 0.0, gap - pen],
        v0: [v, 0.0, 0.0],
        g,
        impvel: vec![("X", vec![(0.0, 1.0), (100.0, 1.0)], v)],
        tend: 0.5,
        ..NodeCase::default()
    };
    let p = n / 1600.0;
    let renard = [0.3, 0.2, 0.5, 0.1, 1.0, 3.0];
    let cases: Vec<(&str, T7, f64)> = vec![
        (
            "Ifric 0 (Coulomb 0.25)",
            T7 {
                fric: 0.25,
                ..T7::default()
            },
            0.25,
        ),
        (
            "Ifric 1 (generalized viscous)",
            T7 {
                ifric: 1,
                fric: 0.05,
                coefs: [2e4, 0.02, 1e4, 1e9, 0.01, 0.0],
                ..T7::default()
            },
            0.05 + 2e4 * p + 0.02 * v + 1e4 * p * v + 1e9 * p * p + 0.01 * v * v,
        ),
        (
            "Ifric 2 (Darmstad)",
            T7 {
                ifric: 2,
                fric: 0.05,
                coefs: [1e9, -0.1, 2e4, -0.2, 0.1, -0.3],
                ..T7::default()
            },
            0.05 + 1e9 * (-0.2f64).exp() * p * p
                + 2e4 * (-0.4f64).exp() * p
                + 0.1 * (-0.6f64).exp(),
        ),
        (
            "Ifric 3 (Renard, Vcr1 < V < Vcr2)",
            T7 {
                ifric: 3,
                coefs: renard,
                ..T7::default()
            },
            0.5 - 0.4 * 0.25 * (3.0 - 1.0),
        ),
    ];
    for (i, (what, t7, mu)) in cases.iter().enumerate() {
        let (r, _) = node_run(&format!("ifric{i}"), &c, t7);
        let l = r.listing.last(1);
        let ratio = -l.tangent[0] / l.normal[2];
        eprintln!(
            "{what}: T/N = {ratio:.7} (mu = {mu:.7}), N = {:.6}",
            l.normal[2]
        );
        assert!(rel(l.normal[2], n) < 1e-3, "{what}: N = {}", l.normal[2]);
        assert!(rel(ratio, *mu) < 1e-3, "{what}: T/N = {ratio}, mu = {mu}");
    }
}

/// The friction case above (Coulomb 0.3) printed every cycle: the tangential
/// force of each cycle's computation (cycle 0 included).
fn friction_history(tag: &str, t7: &T7, v: f64) -> (Vec<f64>, Vec<f64>, f64) {
    let (m, g) = (1.0, 0.01);
    let n = m * g;
    let pen = n / (KM + n);
    let c = NodeCase {
        mass: m,
        x0: [-10.0, 0.0, 1.0 - pen],
        v0: [v, 0.0, 0.0],
        g,
        impvel: vec![("X", vec![(0.0, 1.0), (100.0, 1.0)], v)],
        tend: 0.3,
        print: -1,
        ..NodeCase::default()
    };
    let (r, _) = node_run(tag, &c, t7);
    let t: Vec<f64> = r.listing.of(1).iter().map(|l| -l.tangent[0]).collect();
    let dts: Vec<f64> = r.listing.cycles.iter().map(|c| c.dt).collect();
    (t, dts, n)
}

/// Ifiltr 1, 2, 3 with Xfreq (card eq. (19)): the friction force is filtered,
/// F_f = α·F + (1 − α)·F_f(previous), so the sudden slide's μN is reached
/// gradually, as 1 − Π(1 − α): Ifiltr 1, α = Xfreq = 0.2; Ifiltr 2, α =
/// 2π/Xfreq (Xfreq = 20 steps per period: 0.314); Ifiltr 3, α = 2π·Xfreq·dt
/// (cut-off Xfreq = 5 /ms). Without a filter μN from the first cycle.
#[test]
fn ifiltr_filters_the_friction_force() {
    let (mu, v) = (0.3, 2.0);
    let (raw, dts, n) = friction_history(
        "ifiltr0",
        &T7 {
            fric: mu,
            ..T7::default()
        },
        v,
    );
    assert!(
        rel(raw[0], mu * n) < 1e-9,
        "unfiltered: {} at the first print",
        raw[0]
    );
    for (ifiltr, xfreq) in [(1, 0.2), (2, 20.0), (3, 5.0)] {
        let t7 = T7 {
            fric: mu,
            ifiltr,
            xfreq,
            ..T7::default()
        };
        let (f, dts2, _) = friction_history(&format!("ifiltr{ifiltr}"), &t7, v);
        assert_eq!(dts, dts2);
        // Expected: the filter runs at every computation: cycle 0 (dt = 0), then
        // each cycle with the step just taken (the previous line's dt).
        let alpha = |dt: f64| -> f64 {
            match ifiltr {
                1 => xfreq,
                2 => 2.0 * std::f64::consts::PI / xfreq,
                _ => 2.0 * std::f64::consts::PI * xfreq * dt,
            }
        };
        let mut ff = alpha(0.0) * mu * n;
        let mut shown = Vec::new();
        for k in 0..f.len().min(12) {
            ff = alpha(dts[k]) * mu * n + (1.0 - alpha(dts[k])) * ff;
            shown.push(format!("{:.4}", f[k] / (mu * n)));
            assert!(
                (f[k] - ff).abs() < 1e-4 * mu * n,
                "Ifiltr {ifiltr}, print {}: T = {} expected {ff}",
                k + 1,
                f[k]
            );
        }
        eprintln!(
            "Ifiltr {ifiltr}, Xfreq {xfreq}: T/(mu N) = {}",
            shown.join(" ")
        );
        assert!(f[0] < 0.8 * mu * n, "Ifiltr {ifiltr}: filtered");
        assert!(
            rel(*f.last().unwrap(), mu * n) < 1e-3,
            "Ifiltr {ifiltr}: reaches mu N"
        );
    }
}

/// Iform 1 (viscous, the default) and 2 (stiffness) at a slow slide V = 1e-4:
/// Iform 1 gives the adhesion force C·V, C = VISF·√(2·Kt·M) (card eq. (21)),
/// at once (1.4493e-3 < μN = 3e-3, halved with VISF 0.5); Iform 2 accumulates
/// K·V·dt = 7.3e-5 per cycle (eq. (22)) and reaches μN after 42 cycles.
#[test]
fn iform_viscous_or_stiffness_friction() {
    let (mu, v) = (0.3, 1e-4);
    let (f1, _, n) = friction_history(
        "iform1",
        &T7 {
            fric: mu,
            ..T7::default()
        },
        v,
    );
    let pen = n / (KM + n);
    let kt = KM / (1.0 - pen).powi(2);
    let c = (2.0 * kt * 1.0f64).sqrt();
    eprintln!(
        "Iform 1: T = {:.6e}, C V = {:.6e}, mu N = {:.3e}",
        f1[0],
        c * v,
        mu * n
    );
    assert!(c * v < mu * n);
    for t in &f1 {
        assert!(rel(*t, c * v) < 1e-5, "Iform 1: T = {t}, C V = {}", c * v);
    }
    let (f1b, _, _) = friction_history(
        "iform1-visf",
        &T7 {
            fric: mu,
            visf: 0.5,
            ..T7::default()
        },
        v,
    );
    assert!(rel(f1b[0], 0.5 * c * v) < 1e-5, "VISF 0.5: T = {}", f1b[0]);
    let (f2, dts, _) = friction_history(
        "iform2",
        &T7 {
            fric: mu,
            iform: 2,
            ..T7::default()
        },
        v,
    );
    let mut acc = 0.0f64;
    let mut reached = None;
    for k in 0..f2.len() {
        acc = (acc + KM * v * dts[k]).min(mu * n);
        assert!(
            (f2[k] - acc).abs() < 1e-4 * mu * n,
            "Iform 2, print {}: T = {} expected {acc}",
            k + 1,
            f2[k]
        );
        if reached.is_none() && acc >= mu * n {
            reached = Some(k + 1);
        }
    }
    eprintln!(
        "Iform 2: T grows by K V dt = {:.3e} per cycle, mu N reached at print {reached:?}",
        KM * v * dts[0]
    );
    assert!(
        reached.is_some() && reached.unwrap() > 3,
        "Iform 2 builds up over cycles"
    );
}

/// IBC (card 5, IBCX IBCY IBCZ): the node flies along −x into an upright plate
/// (x = 0) held along z by /BCS under a gravity along −z. With IBCZ = 1 the
/// impact releases its z condition and it falls (vz = −g·(t_end − t_impact));
/// without, it keeps vz = 0.
#[test]
fn ibc_releases_the_boundary_condition_at_impact() {
    let g = 0.1;
    let c = NodeCase {
        x0: [1.5, 0.0, 0.0],
        v0: [-1.0, 0.0, 0.0],
        bcs: "001 000",
        g,
        wall: true,
        plate: (-20.0, 40.0, 1),
        tend: 2.0,
        ..NodeCase::default()
    };
    let (r0, held) = node_run("ibc0", &c, &T7::default());
    let (r1, released) = node_run(
        "ibc1",
        &c,
        &T7 {
            ibc: "001",
            ..T7::default()
        },
    );
    // The impact starts when the node enters the gap: x = 1 at t = 0.5.
    let hit = |r: &Run| r.listing.inter.iter().find(|l| l.pairs > 0).map(|l| l.t);
    eprintln!(
        "IBC: without vz = {:.4}, with IBCZ vz = {:.4} (g (tend - 0.5) = {}), impact seen at {:?}",
        held[5],
        released[5],
        g * 1.5,
        hit(&r1)
    );
    assert!(hit(&r0).is_some() && hit(&r1).is_some());
    assert_eq!(held[5], 0.0);
    assert_eq!(held[2], 0.0);
    assert!(
        rel(released[5], -g * 1.5) < 0.02,
        "released: vz = {}",
        released[5]
    );
    // Both bounced back along x.
    assert!(held[3] > 0.5 && released[3] > 0.5);
}

/// Inacti 2 versus 1: the node starts 0.8 above segment A (in its gap) and is
/// driven along x (z held) over to segment B. Inacti 1 switches the node off:
/// no force anywhere; Inacti 2 switches off only segment A for it: B pushes
/// it as soon as it is in B's gap, with the full force K·P·G/(G − P) over B.
#[test]
fn inacti_2_keeps_the_other_segments() {
    let c = NodeCase {
        x0: [-10.0, 0.0, 0.8],
        v0: [10.0, 0.0, 0.0],
        bcs: "001 000",
        impvel: vec![("X", vec![(0.0, 1.0), (100.0, 1.0)], 10.0)],
        plate: (-20.0, 20.0, 2),
        tend: 2.0,
        print: -5,
        ..NodeCase::default()
    };
    let full = KM * 0.2 / 0.8;
    let (r0, _) = node_run("inacti2-0", &c, &T7::default());
    let (r1, _) = node_run(
        "inacti2-1",
        &c,
        &T7 {
            inacti: 1,
            ..T7::default()
        },
    );
    let (r2, _) = node_run(
        "inacti2-2",
        &c,
        &T7 {
            inacti: 2,
            ..T7::default()
        },
    );
    // x(t) = −10 + 10 t: over A until t = 1 (x = 0), over B after.
    for l in r0.listing.of(1) {
        assert!(l.normal[2] > 0.0, "default: force everywhere (t = {})", l.t);
    }
    for l in r1.listing.of(1) {
        assert_eq!(l.normal[2], 0.0, "Inacti 1: no force (t = {})", l.t);
    }
    let mut over_b = 0;
    for l in r2.listing.of(1) {
        let x = -10.0 + 10.0 * l.t;
        if x < -0.7 {
            assert_eq!(l.normal[2], 0.0, "Inacti 2 over A (x = {x})");
        }
        if x > 0.1 {
            assert!(
                rel(l.normal[2], full) < 1e-9,
                "Inacti 2 over B (x = {x}): {}",
                l.normal[2]
            );
            over_b += 1;
        }
    }
    eprintln!("Inacti 2: full force {full} over B at {over_b} prints, none over A");
    assert!(over_b > 5);
}

/// Inacti 5 and 6: the initially penetrated node (P0 = 0.2 in gap 1) keeps a
/// reduced gap, 0.8 (Inacti 5) or 0.95 × 0.8 (Inacti 6). Free, it is not
/// kicked out (the default throws it off at 2.09 mm/ms); driven down at 0.1
/// mm/ms it is pushed as soon as it moves (5: first force at z = 0.7986) or
/// after 0.04 mm (6: at z = 0.7596); driven back up past the nominal gap and
/// down again, the gap is nominal again.
#[test]
fn inacti_5_6_reduce_the_gap() {
    let free = NodeCase {
        x0: [0.0, 0.0, 0.8],
        tend: 1.0,
        ..NodeCase::default()
    };
    let (_, kicked) = node_run("inacti56-free0", &free, &T7::default());
    let (_, s5) = node_run(
        "inacti56-free5",
        &free,
        &T7 {
            inacti: 5,
            ..T7::default()
        },
    );
    let (_, s6) = node_run(
        "inacti56-free6",
        &free,
        &T7 {
            inacti: 6,
            ..T7::default()
        },
    );
    eprintln!(
        "free node at P0 = 0.2: default vz {:.4}, Inacti 5 vz {}, Inacti 6 vz {}",
        kicked[5], s5[5], s6[5]
    );
    assert!(kicked[5] > 0.1, "the default kicks it out");
    assert!(s5[5] == 0.0 && s5[2] == 0.8 && s6[5] == 0.0 && s6[2] == 0.8);
    // Driven down at 0.1 mm/ms for 1 ms (to z = 0.7), then up at 0.5 for 1 ms
    // (to z = 1.2, out of the nominal gap), then down at 0.5 for 1 ms (to 0.7).
    // No linear damping (VISs ~ 0): the force is the elastic reaction and,
    // while the node closes in at v, the quadratic damper 0.4²·2·M·v²/(Gap − P)
    // (1 kg node: 0.11 at 0.5 mm/ms and 0.7 mm off the plate).
    let driven = NodeCase {
        x0: [0.0, 0.0, 0.8],
        v0: [0.0, 0.0, -0.1],
        impvel: vec![(
            "Z",
            vec![
                (0.0, -0.1),
                (1.0, -0.1),
                (1.0001, 0.5),
                (2.0, 0.5),
                (2.0001, -0.5),
                (3.0, -0.5),
                (10.0, -0.5),
            ],
            1.0,
        )],
        tend: 3.0,
        print: -2,
        ..NodeCase::default()
    };
    for (inacti, g0) in [(5, 0.8), (6, 0.95 * 0.8)] {
        let t7 = T7 {
            inacti,
            viss: 1e-30,
            ..T7::default()
        };
        let (r, s) = node_run(&format!("inacti56-drive{inacti}"), &driven, &t7);
        let first = r
            .listing
            .of(1)
            .into_iter()
            .find(|l| l.normal[2] > 0.0)
            .unwrap();
        let z_first = 0.8 - 0.1 * first.t;
        eprintln!(
            "Inacti {inacti}: first force at t = {:.4} (z = {z_first:.4}, reduced gap {g0})",
            first.t
        );
        // The first force appears once z < the reduced gap (within one print).
        assert!(
            z_first < g0 && z_first > g0 - 0.01,
            "Inacti {inacti}: first force at z = {z_first}"
        );
        // Down to z = 0.7 at t = 1: the force of the reduced gap.
        let at1 = r
            .listing
            .of(1)
            .into_iter()
            .filter(|l| l.t <= 1.0)
            .last()
            .unwrap();
        let z1 = 0.8 - 0.1 * at1.t;
        let want = KM * (g0 - z1) * g0 / z1;
        assert!(
            rel(at1.normal[2], want) < 1e-3,
            "Inacti {inacti}: F = {} expected {want}",
            at1.normal[2]
        );
        // Back at z = 0.7 after leaving the gap: the nominal gap's force.
        assert!((s[2] - 0.7).abs() < 0.01, "z = {}", s[2]);
        let end = r.listing.last(1);
        let nominal = KM * (1.0 - s[2]) / s[2] + 0.16 * 2.0 * 0.5 * 0.5 / s[2];
        assert!(
            rel(end.normal[2], nominal) < 1e-3,
            "Inacti {inacti}: at the end F = {} expected {nominal}",
            end.normal[2]
        );
    }
}

// ---------------------------------------------------------------------------

/// Irem_gap = 2 (card comment 14): in self-contact, a segment ignores the
/// secondary nodes within √2·gap of it along the surface, initially (the
/// reference starter's lists, `contact::close_neighbours`). A flat strip of
/// 0.25 mm shells in self-contact with a 1 mm gap: every node is within the
/// gap of its neighbours' neighbours, and the default (Irem_gap 1) pushes
/// them apart from the first cycle; with Irem_gap = 2 nothing happens.
#[test]
fn irem_gap_2_ignores_close_segments_in_self_contact() {
    let run_strip = |tag: &str, irem_gap: i64| -> Run {
        let dir = scratch(&format!("opt-{tag}"));
        let mut k = Deck::new("strip");
        k.law1(1, RHO, 210.0, 0.3);
        k.shell_prop(1, 0.1);
        k.part(1, 1, 1);
        let n = 12u64;
        let mut nodes = Vec::new();
        for j in 0..2u64 {
            for i in 0..=n {
                nodes.push((1 + i + (n + 1) * j, [0.25 * i as f64, 0.25 * j as f64, 0.0]));
            }
        }
        k.nodes(&nodes);
        let s: Vec<(u64, [u64; 4])> = (0..n)
            .map(|i| (1 + i, [1 + i, 2 + i, 2 + i + n + 1, 1 + i + n + 1]))
            .collect();
        k.shells(1, &s);
        k.grnod_part(1, 1);
        k.surf_part(1, 1);
        k.bcs(1, "001 111", 1);
        k.inter(
            1,
            0,
            1,
            &T7 {
                gapmin: 1.0,
                irem_gap,
                ..T7::default()
            },
        );
        // A few cycles: with the default the strip blows apart soon after.
        let deck = k.write(&dir.join("deck"), "strip", 2e-5, -1, 0.9);
        let r = run(&deck, &dir, &RunArgs::default());
        assert!(r.listing.normal_termination());
        r
    };
    let r1 = run_strip("irem1", 0);
    let r2 = run_strip("irem2", 2);
    let l1 = r1.listing.of(1)[0];
    let l2 = r2.listing.of(1)[0];
    eprintln!(
        "Irem_gap 1: {} pairs at the first cycle, |F| sum per axis {:?}; Irem_gap 2: {} pairs",
        l1.pairs, l1.normal, l2.pairs
    );
    assert!(l1.pairs > 10, "default: close segments push");
    assert_eq!(l2.pairs, 0, "Irem_gap 2: no pair");
    let s1 = r1.final_state();
    let s2 = r2.final_state();
    let moved = |s: &std::collections::BTreeMap<u64, [f64; 6]>| {
        s.values()
            .map(|v| v[3].abs() + v[4].abs())
            .fold(0.0, f64::max)
    };
    assert!(moved(&s1) > 1e-3, "default: the strip is pushed apart");
    assert_eq!(moved(&s2), 0.0, "Irem_gap 2: at rest");
}

/// Irem_gap = 2 on decks/tube_fine (`make_tube.py OUT tube_fine 1 500
/// 0.01`: 50 × 0.4 mm shells under the 1.2 mm gap of the two half
/// thicknesses, flying free for 0.01 ms): a node lies exactly 3 × 0.4 mm =
/// one gap from the segments three rows away, so a rule on the straight
/// distance at the gap lets round-off decide which of them touch (hundreds
/// of pairs with forces of 1e-12, and the contact sets the step); along the
/// surface they are within √2·gap and no pair forms: no force, no internal
/// energy, the shells' step at every row, the same bytes on 2 ranks. With
/// Irem_gap = 0 the neighbours push the mesh apart and the energy error
/// stops the run.
#[test]
fn irem_gap_2_leaves_out_the_neighbours_at_the_gap_of_a_fine_mesh() {
    let d = deck("tube_fine");
    let r = run(&d, &scratch("tube_fine"), &RunArgs::default());
    assert!(r.listing.normal_termination());
    assert!(!r.listing.inter.is_empty());
    for l in &r.listing.inter {
        assert_eq!(l.pairs, 0, "no pair at t = {}", l.t);
        assert_eq!(l.normal, [0.0; 3]);
    }
    assert!(!r.listing.cycles.is_empty());
    for c in &r.listing.cycles {
        assert_eq!(
            c.what, "SHELL",
            "the shells set the step at cycle {}",
            c.cycle
        );
    }
    assert!(
        r.listing
            .text
            .contains("internal 0.000000E0 (hourglass 0.000000E0 included"),
        "{}",
        r.listing.text
    );
    assert_same_final_state_on_2_ranks(&d, "tube_fine_2", &r);
    let dir = scratch("tube_fine_irem0");
    let d0 = common::deck_variant("tube_fine", &dir, |i, lines| {
        (i >= 1 && lines[i - 1].contains("Irem_gap")).then(|| common::set_cols(lines[i], 80, 90, 0))
    });
    let out = common::crashsim(&[
        "run",
        d0.to_str().unwrap(),
        "--out",
        dir.join("out").to_str().unwrap(),
    ]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(3), "{err}");
    assert!(err.contains("ENERGY ERROR LIMIT"), "{err}");
}

/// Bumult only sets the sorting margin: the ball drop with Bumult 0.02 and 2
/// (default 0.2) ends with the same bytes, but sorts more often with the
/// smaller margin.
#[test]
fn bumult_changes_the_sorts_not_the_result() {
    let d = deck("ball_drop");
    let text = std::fs::read_to_string(&d).unwrap();
    let mut finals = Vec::new();
    let mut sorts = Vec::new();
    for bumult in [0.02, 0.2, 2.0] {
        let dir = scratch(&format!("opt-bumult{bumult}"));
        // Card 5 (IBC, Inacti, VISs, VISF, Bumult) of the TYPE7: Bumult in columns 81-100.
        let mut lines: Vec<String> = text.lines().map(String::from).collect();
        let i = lines
            .iter()
            .position(|l| l.starts_with("#      IBC"))
            .unwrap()
            + 1;
        lines[i] = format!("{}{}", &lines[i][..80], r20(bumult));
        let nd = dir.join("deck").join("ball_drop_0000.rad");
        std::fs::create_dir_all(nd.parent().unwrap()).unwrap();
        std::fs::write(&nd, lines.join("\n") + "\n").unwrap();
        std::fs::copy(
            d.with_file_name("ball_drop_0001.rad"),
            nd.with_file_name("ball_drop_0001.rad"),
        )
        .unwrap();
        let r = run(&nd, &dir, &RunArgs::default());
        let n: u64 = r
            .listing
            .text
            .lines()
            .find(|l| l.contains("CONTACT SORTS"))
            .and_then(|l| l.split(':').nth(1))
            .map(|s| s.trim().parse().unwrap())
            .expect("CONTACT SORTS line");
        eprintln!("Bumult {bumult}: {n} sorts");
        sorts.push(n);
        finals.push(r.final_state_bytes());
    }
    assert!(
        finals[0] == finals[1] && finals[1] == finals[2],
        "Bumult changed the result"
    );
    assert!(
        sorts[0] > sorts[1] && sorts[1] > sorts[2],
        "sorts {sorts:?}"
    );
    assert!(sorts[2] >= 1);
}

/// Inacti 3 deck: the fixed 40 x 40 main plate (gap 1) and a free secondary
/// shell (E 70, t 0.5, nodes 1-4) whose node 1 is 0.5 above the plate (P 0.5),
/// node 2 0.3 beyond the plate's edge x = 20 and 0.2 above it (distance 0.36
/// to the edge, P 0.64), nodes 3 and 4 at 1.5 (out of the gap).
fn inacti3_run(tag: &str, inacti: i64, tend: f64, print: i64, ranks: u32) -> Run {
    inacti3_run_with(
        tag,
        &T7 {
            inacti,
            ..T7::default()
        },
        tend,
        print,
        ranks,
    )
}

fn inacti3_run_with(tag: &str, t7: &T7, tend: f64, print: i64, ranks: u32) -> Run {
    let dir = scratch(&format!("opt-inacti3-{tag}"));
    let mut k = Deck::new("inacti3");
    main_plate(&mut k, 1.0, -20.0, 40.0, 40.0, 1);
    k.law1(2, RHO, 70.0, 0.3);
    k.shell_prop(2, 0.5);
    k.part(2, 2, 2);
    k.nodes(&[
        (1, [15.0, -5.0, 0.5]),
        (2, [20.3, -5.0, 0.2]),
        (3, [20.3, 5.0, 1.5]),
        (4, [15.0, 5.0, 1.5]),
    ]);
    k.shells(2, &[(1, [1, 2, 3, 4])]);
    k.grnod(1, &[1, 2, 3, 4]);
    k.inter(1, 1, 1001, t7);
    let deck = k.write(&dir.join("deck"), "inacti3", tend, print, 0.9);
    let r = run(
        &deck,
        &dir,
        &RunArgs {
            ranks,
            ..RunArgs::default()
        },
    );
    assert!(r.listing.normal_termination(), "{tag}: run failed");
    r
}

/// Distance from a point to the main plate [−20, 20]² at z = 0.
fn plate_distance(x: [f64; 3]) -> f64 {
    let c = [x[0].clamp(-20.0, 20.0), x[1].clamp(-20.0, 20.0), 0.0];
    norm(sub(x, c))
}

/// Inacti 3: the starter step moves the penetrated secondary nodes out to the
/// gap along the contact direction — node 1 along the plate normal to z = 1,
/// node 2 radially from the plate's edge to distance 1 — and leaves the
/// others; the listing says which and how far. The run then starts at rest:
/// no contact force, no motion (the moved shell is the reference geometry),
/// where Inacti 0 kicks the nodes out and Inacti 5 keeps them in place with
/// reduced gaps. Same bytes on 1 and 2 ranks.
#[test]
fn inacti_3_moves_the_penetrated_nodes_to_the_gap() {
    // Initial state: a run of one tiny step.
    let r0 = inacti3_run("t0", 3, 1e-9, 1, 1);
    let s0 = r0.final_state();
    let x = |s: &std::collections::BTreeMap<u64, [f64; 6]>, id: u64| {
        let v = s[&id];
        [v[0], v[1], v[2]]
    };
    // Node 1 straight up to the gap.
    let x1 = x(&s0, 1);
    assert!(
        (x1[0] - 15.0).abs() < 1e-12 && (x1[1] + 5.0).abs() < 1e-12 && (x1[2] - 1.0).abs() < 1e-12,
        "node 1 at {x1:?}"
    );
    // Node 2 radially from the edge (20, −5, 0): along (0.3, 0, 0.2)/0.36.
    let d2 = (0.3f64 * 0.3 + 0.2 * 0.2).sqrt();
    let want2 = [20.0 + 0.3 / d2, -5.0, 0.2 / d2];
    let x2 = x(&s0, 2);
    assert!(
        norm(sub(x2, want2)) < 1e-12,
        "node 2 at {x2:?}, expected {want2:?}"
    );
    // Nodes out of the gap and the main plate's nodes untouched (bitwise).
    assert_eq!(x(&s0, 3), [20.3, 5.0, 1.5]);
    assert_eq!(x(&s0, 4), [15.0, 5.0, 1.5]);
    assert_eq!(x(&s0, 1001), [-20.0, -20.0, 0.0]);
    assert_eq!(x(&s0, 1004), [20.0, 20.0, 0.0]);
    for id in 1..=4 {
        let d = plate_distance(x(&s0, id));
        eprintln!("node {id}: distance {d:.15} to the main plate");
        assert!(d >= 1.0 - 1e-12, "node {id} still in the gap: {d}");
    }
    // The listing note: 2 nodes, largest move 1 − 0.36 at node 2.
    let note = r0
        .listing
        .text
        .lines()
        .find(|l| l.contains("Inacti = 3"))
        .expect("an Inacti = 3 note");
    eprintln!("{note}");
    assert!(note.contains("/INTER/TYPE7/1"), "{note}");
    assert!(note.contains("2 secondary nodes moved"), "{note}");
    assert!(note.contains("moved: 1, 2"), "{note}");
    assert!(
        note.contains(&format!("largest move {:.6e} (node 2)", 1.0 - d2)),
        "{note}"
    );

    // The first cycles: no force, no motion with Inacti 3.
    let r3 = inacti3_run("run3", 3, 0.05, 1, 1);
    let f3 = r3
        .listing
        .of(1)
        .iter()
        .map(|l| norm(l.normal))
        .fold(0.0, f64::max);
    let s3 = r3.final_state();
    let v3 = (1..=4)
        .map(|id| norm([s3[&id][3], s3[&id][4], s3[&id][5]]))
        .fold(0.0, f64::max);
    // Inacti 0: the full reaction throws the nodes out.
    let r0 = inacti3_run("run0", 0, 0.05, 1, 1);
    let f0 = norm(r0.listing.of(1)[0].normal);
    let s0r = r0.final_state();
    let v0 = (1..=4)
        .map(|id| norm([s0r[&id][3], s0r[&id][4], s0r[&id][5]]))
        .fold(0.0, f64::max);
    // Inacti 5: no force either, the nodes stay where they were.
    let r5 = inacti3_run("run5", 5, 0.05, 1, 1);
    let f5 = r5
        .listing
        .of(1)
        .iter()
        .map(|l| norm(l.normal))
        .fold(0.0, f64::max);
    let s5 = r5.final_state();
    eprintln!(
        "Inacti 3: max |F| {f3:e}, max |v| {v3:e}; Inacti 0: first |F| {f0:.4}, max |v| {v0:.4}; Inacti 5: max |F| {f5:e}, node 1 z {}",
        s5[&1][2]
    );
    assert!(f0 > 1.0 && v0 > 1e-2, "Inacti 0 pushes the nodes out");
    assert!(f3 <= 1e-9 * f0, "Inacti 3: contact force {f3}");
    assert!(v3 <= 1e-9 * v0, "Inacti 3: the nodes move ({v3})");
    assert!(f5 <= 1e-9 * f0);
    assert_eq!(s5[&1][2], 0.5, "Inacti 5 leaves the node in place");

    // 1 and 2 ranks: the same bytes.
    let r3b = inacti3_run("run3-np2", 3, 0.05, 1, 2);
    assert_eq!(
        r3.final_state_bytes(),
        r3b.final_state_bytes(),
        "Inacti 3: 1 and 2 ranks differ"
    );
    assert!(r3b.listing.text.contains("2 secondary nodes moved"));
}

/// Inacti 3 with Fpenmax 0.55: node 1 (P 0.5 < 0.55·Gap) is moved, node 2
/// (P 0.64) is not — its stiffness is deactivated whatever Inacti (card
/// comment 13) — and nothing pushes either.
#[test]
fn inacti_3_leaves_fpenmax_nodes_to_the_deactivation() {
    let t7 = T7 {
        inacti: 3,
        fpenmax: 0.55,
        ..T7::default()
    };
    let r = inacti3_run_with("fpen", &t7, 0.05, 1, 1);
    let s = r.final_state();
    let note = r
        .listing
        .text
        .lines()
        .find(|l| l.contains("Inacti = 3"))
        .expect("an Inacti = 3 note");
    eprintln!("{note}");
    assert!(note.contains("1 secondary nodes moved"), "{note}");
    assert!(note.contains("moved: 1;"), "{note}");
    assert!(
        note.contains("Fpenmax*Gap not moved (their stiffness is deactivated): 2"),
        "{note}"
    );
    assert!((s[&1][2] - 1.0).abs() < 1e-9, "node 1 z {}", s[&1][2]);
    assert!((s[&2][0] - 20.3).abs() < 1e-9 && (s[&2][2] - 0.2).abs() < 1e-9);
    let f = r
        .listing
        .of(1)
        .iter()
        .map(|l| norm(l.normal))
        .fold(0.0, f64::max);
    assert!(f < 1e-9, "no force: {f}");
}

/// Inacti 3 in a concave corner (floor z = 0 and wall x = 0, gap 1): the node
/// at (0.5, 0, 0.3) is first moved out of the floor (the deeper, P 0.7) to
/// z = 1, which leaves it in the wall's gap; the next pass moves it to x = 1:
/// it ends at (1, 0, 1), at the gap of both.
#[test]
fn inacti_3_frees_a_node_from_two_segments() {
    let dir = scratch("opt-inacti3-corner");
    let mut k = Deck::new("corner");
    k.law1(1, RHO, 210.0, 0.3);
    k.shell_prop(1, 1.0);
    k.part(1, 1, 1);
    k.nodes(&[
        (1001, [0.0, -5.0, 0.0]),
        (1002, [10.0, -5.0, 0.0]),
        (1003, [10.0, 5.0, 0.0]),
        (1004, [0.0, 5.0, 0.0]),
        (1005, [0.0, 5.0, 10.0]),
        (1006, [0.0, -5.0, 10.0]),
        (1, [0.5, 0.0, 0.3]),
    ]);
    k.shells(
        1,
        &[
            (1001, [1001, 1002, 1003, 1004]),
            (1002, [1001, 1004, 1005, 1006]),
        ],
    );
    k.grnod_part(1001, 1);
    k.surf_part(1001, 1);
    k.bcs(1001, "111 111", 1001);
    k.grnod(1, &[1]);
    k.admas(1, 1.0, 1);
    k.inter(
        1,
        1,
        1001,
        &T7 {
            inacti: 3,
            gapmin: 1.0,
            ..T7::default()
        },
    );
    let deck = k.write(&dir.join("deck"), "corner", 0.05, 1, 0.9);
    let r = run(&deck, &dir, &RunArgs::default());
    assert!(r.listing.normal_termination());
    let s = r.final_state()[&1];
    eprintln!("corner node at ({}, {}, {})", s[0], s[1], s[2]);
    assert!((s[0] - 1.0).abs() < 1e-12 && s[1] == 0.0 && (s[2] - 1.0).abs() < 1e-12);
    let note = r
        .listing
        .text
        .lines()
        .find(|l| l.contains("Inacti = 3"))
        .unwrap();
    let want = (0.5f64 * 0.5 + 0.7 * 0.7).sqrt();
    assert!(
        note.contains(&format!("largest move {want:.6e} (node 1)")),
        "{note}"
    );
    assert!(!note.contains("still penetrated"), "{note}");
    let f = r
        .listing
        .of(1)
        .iter()
        .map(|l| norm(l.normal))
        .fold(0.0, f64::max);
    assert!(f < 1e-9, "no force: {f}");
}

/// `decks/free_plate` (10 mm LAW1 steel shells, ν = 0.3) with Ishell
/// `ishell` and a TYPE7 self-contact on it from `tstart` (no pair ever
/// forms: its gap is under the mesh size). Returns what set the first
/// step (the listing) and the step (the energies file, every digit).
fn plate_step(tag: &str, ishell: i64, tstart: Option<f64>) -> (String, f64) {
    let dir = common::scratch(&format!("t7-nodal-step-{tag}"));
    let deck = common::deck_variant("free_plate", &dir, |i, lines| {
        if i >= 2 && lines[i - 2].starts_with("/PROP/SHELL/") {
            return Some(common::set_cols(lines[i], 0, 10, ishell));
        }
        let tstart = tstart?;
        (lines[i] == "/NODE").then(|| {
            [
                "/GRNOD/PART/7".to_string(),
                "plate nodes".into(),
                i10(1),
                "/SURF/PART/8".into(),
                "plate".into(),
                i10(1),
                "/INTER/TYPE7/1".into(),
                "self-contact".into(),
                i10(7) + &i10(8) + &i10(0).repeat(7),
                r20(0.0).repeat(3),
                r20(0.0).repeat(4) + &i10(0).repeat(2),
                r20(0.0).repeat(3) + &r20(tstart) + &r20(0.0),
                format!("{:>10}", "000") + &" ".repeat(20) + &i10(0) + &r20(0.0).repeat(3),
                i10(0).repeat(2) + &r20(0.0) + &i10(0).repeat(3) + &r20(0.0) + &i10(0),
                "/NODE".into(),
            ]
            .join("\n")
        })
    });
    let args = RunArgs {
        energies: true,
        ..Default::default()
    };
    let r = run(&deck, &dir.join("out"), &args);
    assert!(r.listing.normal_termination(), "{tag}");
    (r.listing.cycles[0].what.clone(), r.energies().1[0][2])
}

/// With a TYPE7 active the step is also every node's own √(2M/(K_el + K_c))
/// (the reference's dtnoda with I7KGLO; `solver::run::interface_nodal_step`).
/// A QEPH node gets ½·V0·A11/L² from each of its shells: its step is
/// √(1 − ν²) times the shell step and sets the first cycle (NODE), as
/// INTERF_INT_25_hexa8's first row does in the reference listing; a
/// Belytschko-Tsay node gets 0.81·½·V0·E/L², a step 1/0.9 of the shell's,
/// which keeps the shell's; before Tstart neither applies.
#[test]
fn an_active_type7_makes_every_node_a_time_step_candidate() {
    let alone = plate_step("qeph-alone", 24, None);
    let qeph = plate_step("qeph", 24, Some(0.0));
    let later = plate_step("qeph-later", 24, Some(1.0));
    let bt = plate_step("bt", 1, Some(0.0));
    let bt_alone = plate_step("bt-alone", 1, None);
    assert_eq!(alone.0, "SHELL");
    assert_eq!(qeph.0, "NODE");
    let want = alone.1 * (1.0f64 - 0.3 * 0.3).sqrt();
    assert!(
        rel(qeph.1, want) < 1e-12,
        "QEPH with TYPE7: {} against {want}",
        qeph.1
    );
    assert_eq!(later, alone, "Tstart after the end");
    assert_eq!(bt, bt_alone, "BT with TYPE7");
}
