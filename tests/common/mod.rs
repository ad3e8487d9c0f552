//! Helpers shared by the integration tests.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// `../shared` beside the checkout (CI puts it there), or $CRASHSIM_SHARED.
pub fn shared_dir() -> PathBuf {
    let p = std::env::var_os("CRASHSIM_SHARED")
        .map(PathBuf::from)
        .unwrap_or_else(|| {
            PathBuf::from(env!("CARGO_MANIFEST_DIR"))
                .join("..")
                .join("shared")
        });
    assert!(
        p.join("decks/openradioss-qa").is_dir(),
        "the shared reference decks are not at {} (set CRASHSIM_SHARED)",
        p.display()
    );
    p
}

/// The starter deck of a QA reference case, read in place.
pub fn qa_deck(name: &str) -> PathBuf {
    shared_dir()
        .join("decks/openradioss-qa")
        .join(name)
        .join(format!("{name}_0000.rad"))
}

pub fn qa_listing(name: &str) -> String {
    let p = shared_dir()
        .join("decks/openradioss-qa")
        .join(name)
        .join(format!("{name}_0000.out"));
    std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("cannot read {}: {e}", p.display()))
}

pub fn crashsim(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_crashsim"))
        .args(args)
        .output()
        .expect("crashsim runs")
}

/// Runs crashsim and parses its stdout as JSON, asserting success.
pub fn crashsim_json(args: &[&str]) -> serde_json::Value {
    let out = crashsim(args);
    assert!(
        out.status.success(),
        "crashsim {args:?} failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("JSON output")
}

/// `mpirun -n N [--oversubscribe] crashsim ARGS`, working as root.
pub fn mpirun(n: u32, args: &[&str]) -> Output {
    let mut c = Command::new("mpirun");
    c.env("OMPI_ALLOW_RUN_AS_ROOT", "1")
        .env("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
        .env("OMPI_MCA_btl_vader_single_copy_mechanism", "none")
        .env("OMPI_MCA_hwloc_base_binding_policy", "none")
        .arg("-n")
        .arg(n.to_string());
    if n > 2 {
        c.arg("--oversubscribe");
    }
    c.arg(env!("CARGO_BIN_EXE_crashsim"))
        .args(args)
        .output()
        .expect("mpirun runs (is openmpi-bin installed? run ci/setup)")
}

/// A Python 3 that has h5py and matplotlib (Debian's python3-h5py and
/// python3-matplotlib, which ci/setup installs, live under /usr/bin/python3
/// when another python3 comes first on PATH).
pub fn python() -> PathBuf {
    for p in ["python3", "/usr/bin/python3"] {
        let ok = Command::new(p)
            .args(["-c", "import h5py, matplotlib, numpy"])
            .output()
            .map(|o| o.status.success())
            .unwrap_or(false);
        if ok {
            return PathBuf::from(p);
        }
    }
    panic!("no python3 with h5py and matplotlib: run ci/setup (python3-h5py python3-matplotlib)");
}

/// Runs tests/py/SCRIPT with ARGS, asserting success; returns its stdout.
pub fn python_check(script: &str, args: &[&std::ffi::OsStr]) -> String {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/py")
        .join(script);
    let out = Command::new(python())
        .arg(&path)
        .args(args)
        .output()
        .expect("python runs");
    assert!(
        out.status.success(),
        "{script} failed:\n{}\n{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// Asserts that the command `what` succeeded, showing its output otherwise.
pub fn ok(out: &Output, what: &str) {
    assert!(
        out.status.success(),
        "{what} failed ({:?}):\n{}\n{}",
        out.status.code(),
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
}

/// Copies the files of a (stopped) run's directory into a fresh scratch
/// directory `tag`.
pub fn copy_run(from: &Path, tag: &str) -> PathBuf {
    let to = scratch(tag);
    for e in std::fs::read_dir(from).unwrap() {
        let p = e.unwrap().path();
        std::fs::copy(&p, to.join(p.file_name().unwrap())).unwrap();
    }
    to
}

/// A fresh scratch directory under the system temp dir.
pub fn scratch(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("crashsim-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// `[mpirun -n NP] crashsim ARGS` with extra environment (passed on to every
/// rank); `np` 0 runs crashsim alone.
pub fn run_env(np: u32, args: &[&str], env: &[(&str, &str)]) -> Output {
    let mut c;
    if np == 0 {
        c = Command::new(env!("CARGO_BIN_EXE_crashsim"));
        c.args(args);
    } else {
        c = Command::new("mpirun");
        c.env("OMPI_ALLOW_RUN_AS_ROOT", "1")
            .env("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
            .env("OMPI_MCA_btl_vader_single_copy_mechanism", "none")
            .env("OMPI_MCA_hwloc_base_binding_policy", "none");
        for (k, _) in env {
            c.args(["-x", k]);
        }
        c.arg("-n").arg(np.to_string());
        if np > 2 {
            c.arg("--oversubscribe");
        }
        c.arg(env!("CARGO_BIN_EXE_crashsim")).args(args);
    }
    for (k, v) in env {
        c.env(k, v);
    }
    c.output().expect("crashsim runs")
}

/// decks/NAME/NAME_0000.rad in the checkout.
pub fn deck(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("decks")
        .join(name)
        .join(format!("{name}_0000.rad"))
}

/// A copy of decks/NAME in `dir` with `edit` applied to the starter's lines.
pub fn deck_variant(
    name: &str,
    dir: &Path,
    edit: impl Fn(usize, &[&str]) -> Option<String>,
) -> PathBuf {
    let src = deck(name);
    let text = std::fs::read_to_string(&src).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    let out: Vec<String> = (0..lines.len())
        .map(|i| edit(i, &lines).unwrap_or_else(|| lines[i].to_string()))
        .collect();
    std::fs::create_dir_all(dir).unwrap();
    let d = dir.join(format!("{name}_0000.rad"));
    std::fs::write(&d, out.join("\n") + "\n").unwrap();
    std::fs::copy(
        src.with_file_name(format!("{name}_0001.rad")),
        dir.join(format!("{name}_0001.rad")),
    )
    .unwrap();
    d
}

/// The line `k` data lines below an /INTER/TYPE7 or TYPE5 header (comments
/// and the title counted as in the decks: title, then comment/data pairs).
pub fn inter_line(i: usize, lines: &[&str], k: usize) -> bool {
    i >= k
        && ["/INTER/TYPE7/", "/INTER/TYPE5/", "/INTER/TYPE25/"]
            .iter()
            .any(|t| lines[i - k].starts_with(t))
}

/// Replaces columns [a, b) (0-based) of a line by `v` right-aligned.
pub fn set_cols(l: &str, a: usize, b: usize, v: i64) -> String {
    assert!(l.len() >= b, "short card line: {l}");
    format!("{}{:>w$}{}", &l[..a], v, &l[b..], w = b - a)
}

/// Line `i` of a deck written the other way round when it is a 4-node
/// shell of a /SHELL block (node2 and node4 swapped: the shell's normal,
/// and its contact segment's, reversed); `None` for any other line.
pub fn shell_reversed(i: usize, lines: &[&str]) -> Option<String> {
    let block = lines[..i].iter().rev().find(|l| l.starts_with('/'))?;
    let f: Vec<&str> = lines[i].split_whitespace().collect();
    (block.starts_with("/SHELL/") && f.len() == 5 && !lines[i].starts_with('#')).then(|| {
        format!(
            "{:>10}{:>10}{:>10}{:>10}{:>10}",
            f[0], f[1], f[4], f[3], f[2]
        )
    })
}

/// CSV rows as numbers (a non-numeric field such as `kind` reads as NaN),
/// with the header.
pub fn read_csv(path: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let text = std::fs::read_to_string(path)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
    let mut lines = text.lines();
    let header = lines.next().unwrap().split(',').map(String::from).collect();
    let rows = lines
        .filter(|l| !l.is_empty())
        .map(|l| {
            l.split(',')
                .map(|s| s.parse().unwrap_or(f64::NAN))
                .collect()
        })
        .collect();
    (header, rows)
}

/// The rows of a listing's cycle table, split into their fields: CYCLE,
/// TIME, TIME-STEP, ELEMENT (kind, id), ERROR %, I-ENERGY, K-ENERGY T,
/// K-ENERGY R, EXT-WORK, MAS.ERR, TOTAL MASS, MASS ADDED.
pub fn cycle_table(text: &str) -> Vec<Vec<&str>> {
    text.lines()
        .map(|l| l.split_whitespace().collect::<Vec<&str>>())
        .filter(|t| t.len() >= 13 && t[0].parse::<u64>().is_ok() && t[5].ends_with('%'))
        .collect()
}

/// A number of the listing (panics with the field when it is none).
pub fn num(field: &str) -> f64 {
    field
        .parse()
        .unwrap_or_else(|_| panic!("'{field}' is no number"))
}
