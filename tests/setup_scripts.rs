//! What the README's two commands install: `ci/demo` only what the solver
//! needs to build, run and plot; `ci/test` that and what only the tests use
//! (issue 18).

use std::process::Command;

fn root() -> std::path::PathBuf {
    std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The packages `ci/setup ARGS --list` would check and install.
fn packages(args: &[&str]) -> Vec<String> {
    let out = Command::new("bash")
        .arg(root().join("ci/setup"))
        .args(args)
        .arg("--list")
        .output()
        .expect("bash runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout)
        .lines()
        .map(str::to_string)
        .collect()
}

/// Lines of a script that run ci/setup (comments left out).
fn setup_calls(script: &str) -> Vec<String> {
    std::fs::read_to_string(root().join(script))
        .unwrap()
        .lines()
        .map(str::trim)
        .filter(|l| !l.starts_with('#') && l.contains("ci/setup"))
        .map(str::to_string)
        .collect()
}

#[test]
fn the_demo_installs_no_package_that_only_the_tests_use() {
    let solver = packages(&[]);
    let all = packages(&["--tests"]);
    for p in [
        "python3-h5py",
        "python3-matplotlib",
        "python3-paraview",
        "xvfb",
        "xauth",
        "libgl1-mesa-dri",
    ] {
        assert!(
            !solver.iter().any(|s| s == p),
            "ci/setup installs {p} for the demo"
        );
        assert!(
            all.iter().any(|s| s == p),
            "ci/setup --tests leaves {p} out"
        );
    }
    for p in [
        "libopenmpi-dev",
        "libhdf5-openmpi-dev",
        "libmetis-dev",
        "fonts-dejavu-core",
    ] {
        assert!(solver.iter().any(|s| s == p), "the solver needs {p}");
    }
    assert!(
        solver.iter().all(|p| all.contains(p)),
        "the tests need the solver too"
    );
    let demo = setup_calls("ci/demo");
    assert!(
        !demo.is_empty() && demo.iter().all(|l| !l.contains("--tests")),
        "{demo:?}"
    );
    let test = setup_calls("ci/test");
    assert!(
        !test.is_empty() && test.iter().all(|l| l.contains("--tests")),
        "{test:?}"
    );
}
