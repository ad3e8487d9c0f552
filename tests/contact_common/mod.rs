//! Helpers shared by the contact tests (tests/contact_analytic.rs,
//! tests/contact_options.rs): running a deck, reading the listing's cycle and
//! INTER lines, CSV outputs and fixed-format starter meshes.
#![allow(dead_code)]

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

pub type V3 = [f64; 3];

// The helpers every integration test shares (every test that includes this
// module also includes `common`).
#[allow(unused_imports)]
pub use crate::common::{deck, ok, read_csv, scratch};

/// The ranks `partition --np NP --json` puts interface `i`'s sides on:
/// (secondary ranks, main ranks).
pub fn interface_ranks(deck: &Path, np: u32, i: usize) -> (Vec<u64>, Vec<u64>) {
    let v = crate::common::crashsim_json(&[
        "partition",
        deck.to_str().unwrap(),
        "--np",
        &np.to_string(),
        "--json",
    ]);
    let it = &v["interfaces"][i];
    let ranks = |k: &str| -> Vec<u64> {
        it[k]
            .as_array()
            .unwrap()
            .iter()
            .map(|r| r.as_u64().unwrap())
            .collect()
    };
    (ranks("secondary_ranks"), ranks("main_ranks"))
}

/// Runs `deck` again on 2 ranks (in scratch `tag`) and asserts that its final
/// state is byte-identical to `one`'s.
pub fn assert_same_final_state_on_2_ranks(deck: &Path, tag: &str, one: &Run) {
    let two = run(
        deck,
        &scratch(tag),
        &RunArgs {
            ranks: 2,
            ..Default::default()
        },
    );
    assert!(
        two.final_state_bytes() == one.final_state_bytes(),
        "{}: the final state on 2 ranks differs from 1 rank",
        deck.display()
    );
}

/// Runs `deck` on each of `ranks` and on 1 rank with 2 threads (scratch
/// `tag`-...) and asserts that each final state is byte-identical to `one`'s.
pub fn assert_same_final_state_on_ranks_and_2_threads(
    deck: &Path,
    tag: &str,
    one: &Run,
    ranks: &[u32],
) {
    for &np in ranks {
        let r = run(
            deck,
            &scratch(&format!("{tag}-{np}ranks")),
            &RunArgs {
                ranks: np,
                ..Default::default()
            },
        );
        assert!(
            r.final_state_bytes() == one.final_state_bytes(),
            "{}: the final state on {np} ranks differs from 1 rank",
            deck.display()
        );
    }
    let dir = scratch(&format!("{tag}-2threads"));
    let fs = dir.join("final_state.csv");
    let s = |p: &Path| p.to_str().unwrap().to_string();
    let args = [
        "run",
        &s(deck),
        "--out",
        &s(&dir),
        "--quiet",
        "--threads",
        "2",
        "--final-state",
        &s(&fs),
    ];
    ok(&crate::common::run_env(0, &args, &[]), "2 threads");
    assert!(
        std::fs::read(fs).unwrap() == one.final_state_bytes(),
        "{}: the final state on 2 threads differs from 1",
        deck.display()
    );
}

/// Stops `deck` on 2 ranks after `cycle` (scratch `tag`), restarts it on 1
/// rank from its restart file and asserts that the final state is
/// byte-identical to `whole`'s, the run that never stopped.
pub fn assert_restart_2_to_1_ends_as(deck: &Path, tag: &str, cycle: u64, whole: &Run) {
    let dir = scratch(tag);
    let s = |p: &Path| p.to_str().unwrap().to_string();
    let c = cycle.to_string();
    let args = [
        "run",
        &s(deck),
        "--out",
        &s(&dir),
        "--quiet",
        "--stop-after-cycle",
        &c,
    ];
    let out = crate::common::run_env(2, &args, &[]);
    ok(&out, &format!("run stopped at cycle {cycle} on 2 ranks"));
    assert!(String::from_utf8_lossy(&out.stdout).contains(&format!("STOPPED AT CYCLE {cycle}")));
    let name = deck
        .file_name()
        .unwrap()
        .to_str()
        .unwrap()
        .trim_end_matches("_0000.rad");
    let rst = dir.join(format!("{name}_rst.h5"));
    let fs = dir.join("final_state.csv");
    let args = [
        "run",
        &s(deck),
        "--out",
        &s(&dir),
        "--quiet",
        "--restart",
        &s(&rst),
        "--final-state",
        &s(&fs),
    ];
    ok(&crate::common::run_env(0, &args, &[]), "restart on 1 rank");
    assert!(
        std::fs::read(fs).unwrap() == whole.final_state_bytes(),
        "{}: stopped at cycle {cycle} on 2 ranks and restarted on 1, the final state differs",
        deck.display()
    );
}

/// What a run wrote.
pub struct Run {
    pub dir: PathBuf,
    pub listing: Listing,
}

impl Run {
    pub fn final_state(&self) -> BTreeMap<u64, [f64; 6]> {
        read_state(&self.dir.join("final_state.csv"))
    }
    pub fn final_state_bytes(&self) -> Vec<u8> {
        std::fs::read(self.dir.join("final_state.csv")).unwrap()
    }
    pub fn elements(&self) -> BTreeMap<u64, Vec<f64>> {
        let (_, rows) = read_csv(&self.dir.join("final_elements.csv"));
        rows.into_iter()
            .map(|r| (r[1] as u64, r[2..].to_vec()))
            .collect()
    }
    pub fn energies(&self) -> (Vec<String>, Vec<Vec<f64>>) {
        read_csv(&self.dir.join("energies.csv"))
    }
    pub fn history(&self) -> (Vec<String>, Vec<Vec<f64>>) {
        read_csv(&self.dir.join("history.csv"))
    }
}

/// Options of one run.
#[derive(Default, Clone)]
pub struct RunArgs {
    pub engine: Option<PathBuf>,
    pub elements: bool,
    pub energies: bool,
    pub history: bool,
    /// Run under `mpirun -n ranks` when > 1.
    pub ranks: u32,
}

/// Runs `crashsim run DECK --out DIR --final-state DIR/final_state.csv ...`
/// and reads the listing DIR/<name>.out.
pub fn run(deck: &Path, dir: &Path, a: &RunArgs) -> Run {
    std::fs::create_dir_all(dir).unwrap();
    let s = |p: PathBuf| p.to_str().unwrap().to_string();
    let mut args = vec![
        "run".to_string(),
        s(deck.to_path_buf()),
        "--out".into(),
        s(dir.to_path_buf()),
        "--final-state".into(),
        s(dir.join("final_state.csv")),
    ];
    if let Some(e) = &a.engine {
        args.push("--engine".into());
        args.push(s(e.clone()));
    }
    if a.elements {
        args.push("--final-elements".into());
        args.push(s(dir.join("final_elements.csv")));
    }
    if a.energies {
        args.push("--energies".into());
        args.push(s(dir.join("energies.csv")));
    }
    if a.history {
        args.push("--history".into());
        args.push(s(dir.join("history.csv")));
    }
    let argv: Vec<&str> = args.iter().map(String::as_str).collect();
    let out = if a.ranks > 1 {
        super::common::mpirun(a.ranks, &argv)
    } else {
        super::common::crashsim(&argv)
    };
    ok(&out, &format!("crashsim {argv:?}"));
    let name = listing_name(dir);
    Run {
        dir: dir.to_path_buf(),
        listing: Listing::read(&dir.join(name)),
    }
}

fn listing_name(dir: &Path) -> String {
    std::fs::read_dir(dir)
        .unwrap()
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().to_string())
        .find(|n| n.ends_with(".out"))
        .expect("a listing NAME.out")
}

/// One `INTER id TYPEn NORMAL FORCE fx fy fz TANGENT tx ty tz PAIRS n` line.
#[derive(Clone, Copy, Debug)]
pub struct InterLine {
    /// Time of the cycle line it follows.
    pub t: f64,
    pub id: u64,
    pub normal: V3,
    pub tangent: V3,
    pub pairs: u64,
}

/// One cycle line of the listing.
#[derive(Clone, Debug)]
pub struct CycleLine {
    pub cycle: u64,
    pub t: f64,
    pub dt: f64,
    /// What set the time step (BRICK, SHELL, NODE, INTER, ...) and its id.
    pub what: String,
    pub id: u64,
}

pub struct Listing {
    pub text: String,
    pub cycles: Vec<CycleLine>,
    pub inter: Vec<InterLine>,
}

impl Listing {
    pub fn read(path: &Path) -> Listing {
        let text = std::fs::read_to_string(path)
            .unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
        let mut cycles = Vec::new();
        let mut inter = Vec::new();
        let mut t = 0.0;
        for l in text.lines() {
            let f: Vec<&str> = l.split_whitespace().collect();
            if f.len() >= 6 && f[0] == "INTER" && f[3] == "NORMAL" {
                let p = |i: usize| f[i].parse::<f64>().unwrap();
                inter.push(InterLine {
                    t,
                    id: f[1].parse().unwrap(),
                    normal: [p(5), p(6), p(7)],
                    tangent: [p(9), p(10), p(11)],
                    pairs: f[13].parse().unwrap(),
                });
            } else if f.len() >= 6 {
                if let (Ok(c), Ok(tt), Ok(dt)) = (
                    f[0].parse::<u64>(),
                    f[1].parse::<f64>(),
                    f[2].parse::<f64>(),
                ) {
                    t = tt;
                    cycles.push(CycleLine {
                        cycle: c,
                        t: tt,
                        dt,
                        what: f[3].to_string(),
                        id: f[4].parse().unwrap_or(0),
                    });
                }
            }
        }
        Listing {
            text,
            cycles,
            inter,
        }
    }

    /// INTER lines of interface `id`, in time order.
    pub fn of(&self, id: u64) -> Vec<InterLine> {
        self.inter.iter().filter(|l| l.id == id).copied().collect()
    }

    /// The last INTER line of interface `id`.
    pub fn last(&self, id: u64) -> InterLine {
        *self
            .inter
            .iter()
            .rev()
            .find(|l| l.id == id)
            .unwrap_or_else(|| panic!("no INTER line for interface {id}"))
    }

    /// "FINAL contact energy" etc.: the energies at the end.
    pub fn normal_termination(&self) -> bool {
        self.text.contains("NORMAL TERMINATION")
    }
}

// The solver's own vector algebra (not every test binary uses all of it).
#[allow(unused_imports)]
pub use crashsim::model::geometry::{cross, dot, norm, sub};

/// Final state CSV: id → [x, y, z, vx, vy, vz].
pub fn read_state(path: &Path) -> BTreeMap<u64, [f64; 6]> {
    let (h, rows) = read_csv(path);
    assert_eq!(&h[..7], &["id", "x", "y", "z", "vx", "vy", "vz"]);
    rows.iter()
        .map(|r| (r[0] as u64, [r[1], r[2], r[3], r[4], r[5], r[6]]))
        .collect()
}

/// Nodes and elements of a fixed-format starter deck (ids 10 wide, reals 20 wide).
#[derive(Default)]
pub struct Mesh {
    pub nodes: BTreeMap<u64, V3>,
    /// (element id, part id, node ids).
    pub bricks: Vec<(u64, u64, [u64; 8])>,
    pub shells: Vec<(u64, u64, [u64; 4])>,
}

pub fn read_mesh(path: &Path) -> Mesh {
    let text = std::fs::read_to_string(path).unwrap();
    let field = |l: &str, a: usize, b: usize| -> String {
        l.get(a..b.min(l.len())).unwrap_or("").trim().to_string()
    };
    let mut m = Mesh::default();
    let mut block = String::new();
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
            m.nodes.insert(id, c);
        } else if let Some(p) = block.strip_prefix("/BRICK/") {
            let v: Vec<u64> = (0..9)
                .map(|k| field(l, 10 * k, 10 * k + 10).parse().unwrap())
                .collect();
            m.bricks.push((
                v[0],
                p.parse().unwrap(),
                [v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8]],
            ));
        } else if let Some(p) = block.strip_prefix("/SHELL/") {
            let v: Vec<u64> = (0..5)
                .map(|k| field(l, 10 * k, 10 * k + 10).parse().unwrap())
                .collect();
            m.shells
                .push((v[0], p.parse().unwrap(), [v[1], v[2], v[3], v[4]]));
        }
    }
    m
}

/// Lumped nodal masses ρ·V/8 of the bricks of `parts` (all parts if empty).
pub fn brick_masses(m: &Mesh, rho: f64, parts: &[u64]) -> BTreeMap<u64, f64> {
    let mut out = BTreeMap::new();
    for (_, p, n) in &m.bricks {
        if !parts.is_empty() && !parts.contains(p) {
            continue;
        }
        let x = n.map(|i| m.nodes[&i]);
        let v = crashsim::model::geometry::hexa_volume(x).abs();
        for i in n {
            *out.entry(*i).or_insert(0.0) += rho * v / 8.0;
        }
    }
    out
}

/// Lumped nodal masses ρ·A·t/4 of the 4-node shells of `parts`.
pub fn shell_masses(m: &Mesh, rho: f64, t: f64, parts: &[u64]) -> BTreeMap<u64, f64> {
    let mut out = BTreeMap::new();
    for (_, p, n) in &m.shells {
        if !parts.is_empty() && !parts.contains(p) {
            continue;
        }
        let x = n.map(|i| m.nodes[&i]);
        let a = crashsim::model::geometry::quad_area(x);
        for i in n {
            *out.entry(*i).or_insert(0.0) += rho * a * t / 4.0;
        }
    }
    out
}

/// Writes a copy of an engine file with `/PRINT/...` replaced (and optionally
/// the end time): returns its path.
pub fn engine_variant(deck: &Path, dir: &Path, print_every: i64, tend: Option<f64>) -> PathBuf {
    let name = deck
        .file_name()
        .unwrap()
        .to_str()
        .unwrap()
        .replace("_0000.rad", "");
    let src = deck.with_file_name(format!("{name}_0001.rad"));
    let text = std::fs::read_to_string(&src).unwrap();
    let mut out = Vec::new();
    let mut after_run = false;
    for l in text.lines() {
        if l.starts_with("/PRINT/") {
            out.push(format!("/PRINT/{print_every}/55"));
            continue;
        }
        if after_run && !l.starts_with('#') {
            after_run = false;
            if let Some(t) = tend {
                out.push(format!("{t}"));
                continue;
            }
        }
        if l.starts_with("/RUN/") {
            after_run = true;
        }
        out.push(l.to_string());
    }
    std::fs::create_dir_all(dir).unwrap();
    let p = dir.join(format!("{name}_0001.rad"));
    std::fs::write(&p, out.join("\n") + "\n").unwrap();
    p
}

/// Least-squares fit of y = c0 + c1·t + c2·t².
pub fn quadratic_fit(t: &[f64], y: &[f64]) -> [f64; 3] {
    let mut a = [[0.0f64; 4]; 3];
    for (&ti, &yi) in t.iter().zip(y) {
        let f = [1.0, ti, ti * ti];
        for r in 0..3 {
            for c in 0..3 {
                a[r][c] += f[r] * f[c];
            }
            a[r][3] += f[r] * yi;
        }
    }
    for p in 0..3 {
        let d = a[p][p];
        for c in p..4 {
            a[p][c] /= d;
        }
        for r in 0..3 {
            if r != p {
                let f = a[r][p];
                for c in p..4 {
                    a[r][c] -= f * a[p][c];
                }
            }
        }
    }
    [a[0][3], a[1][3], a[2][3]]
}

/// The listing's final ENERGY BALANCE line of run `r` (listing NAME.out):
/// (the Radioss-style ERROR %, and how far the balance with the contact
/// energy included closes, %).
pub fn energy_balance(r: &Run, name: &str) -> (f64, f64) {
    let out = std::fs::read_to_string(r.dir.join(format!("{name}.out"))).unwrap();
    let line = out
        .lines()
        .find(|l| l.contains("ENERGY BALANCE"))
        .expect("ENERGY BALANCE line");
    let number = |after: &str| -> f64 {
        line.split(after)
            .nth(1)
            .and_then(|t| t.split('%').next())
            .and_then(|t| t.trim().parse().ok())
            .unwrap_or_else(|| panic!("{after} in {line}"))
    };
    (number("ERROR"), number("closes to "))
}
