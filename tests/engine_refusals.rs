//! What the engine does not compute yet is refused by name, at the card that
//! asks for it, with exit code 2 — never a silent substitute.

mod common;
use common::*;

fn run_refused(deck: &std::path::Path, expect: &[&str]) {
    let dir = std::env::temp_dir().join(format!("crashsim-refusal-{}", std::process::id()));
    let out = crashsim(&[
        "run",
        deck.to_str().unwrap(),
        "--out",
        dir.to_str().unwrap(),
    ]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "stderr: {err}");
    for e in expect {
        assert!(err.contains(e), "stderr lacks '{e}': {err}");
    }
    assert!(!err.contains("panicked"));
}

#[test]
fn qbat_shells_with_a_plastic_law_are_refused_at_their_property() {
    // TWISBEAM's elastic material made Johnson-Cook: QBAT computes elastic laws only.
    let src = qa_deck("TWISBEAM");
    let text = std::fs::read_to_string(&src).unwrap();
    let old = "/MAT/ELAST/1\nmaterial number _      1\n#        Init. dens.          Ref. dens.\n             7.34E-4                   0\n#                  E                  nu\n            29000000           .22000001\n";
    assert!(text.contains(old));
    let new = "/MAT/PLAS_JOHNS/1\nmaterial number _      1\n             7.34E-4                   0\n            29000000           .22000001\n               30000                1000                 0.5\n                   0                   0\n";
    let dir = std::env::temp_dir().join(format!("crashsim-refusal-qbat-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("TWISBEAM_0000.rad"), text.replace(old, new)).unwrap();
    for f in ["TWISBEAM_0001.rad", "TWISBEAMD0B"] {
        std::fs::copy(src.with_file_name(f), dir.join(f)).unwrap();
    }
    run_refused(
        &dir.join("TWISBEAM_0000.rad"),
        &[
            "TWISBEAM_0000.rad:",
            "Ishell = 12 (QBAT) with /MAT/LAW2",
            "only elastic laws",
        ],
    );
}

#[test]
fn contact_options_the_engine_does_not_compute_are_refused_at_the_interface() {
    // The demo tube's TYPE7 with Icurv = 3 (curved gap envelope), not computed yet.
    let src = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("decks/demo/demo_0000.rad");
    let text = std::fs::read_to_string(&src).unwrap();
    let old = "         0         5         4         0         1                   0         0         0         0";
    assert!(text.contains(old));
    let new = "         0         5         4         0         1                   0         0         3         0";
    let dir = std::env::temp_dir().join(format!("crashsim-refusal-icurv-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let deck = dir.join("demo_0000.rad");
    std::fs::write(&deck, text.replace(old, new)).unwrap();
    std::fs::copy(
        src.with_file_name("demo_0001.rad"),
        dir.join("demo_0001.rad"),
    )
    .unwrap();
    run_refused(
        &deck,
        &[
            "demo_0000.rad:889",
            "/INTER/TYPE7/1",
            "Icurv",
            "not supported by the engine yet",
        ],
    );
}

/// free_plate with a starter keyword and an engine keyword the engine does
/// not compute, and one the keyword policy lets through (/MEMORY).
fn free_plate_with_unsupported(tag: &str) -> std::path::PathBuf {
    let src = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("decks/free_plate");
    let dir = std::env::temp_dir().join(format!("crashsim-policy-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let starter = std::fs::read_to_string(src.join("free_plate_0000.rad")).unwrap();
    let (head, tail) = starter.split_once("/END").unwrap();
    let extra = "/MEMORY\n   1000000\n/TRANSFORM/TRA/1\nmove the plate\n         0       0.0       0.0      10.0\n";
    std::fs::write(
        dir.join("free_plate_0000.rad"),
        format!("{head}{extra}/END{tail}"),
    )
    .unwrap();
    let engine = std::fs::read_to_string(src.join("free_plate_0001.rad")).unwrap();
    std::fs::write(
        dir.join("free_plate_0001.rad"),
        format!("{engine}/DT/SHELL/CST\n0.9 1e-6\n"),
    )
    .unwrap();
    dir.join("free_plate_0000.rad")
}

#[test]
fn a_keyword_the_engine_does_not_compute_stops_the_run_naming_every_one() {
    let deck = free_plate_with_unsupported("refused");
    let head = std::fs::read_to_string(&deck).unwrap();
    let line = 1 + head
        .lines()
        .position(|l| l.starts_with("/TRANSFORM"))
        .unwrap();
    run_refused(
        &deck,
        &[
            &format!("free_plate_0000.rad:{line}: /TRANSFORM/TRA/1"),
            "free_plate_0001.rad:6: /DT/SHELL/CST",
            "2 keyword(s)",
            "--skip-unsupported",
        ],
    );
    // `check` lists them as warnings, and the safe one as skipped.
    let out = crashsim(&["check", deck.to_str().unwrap()]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{text}");
    assert!(
        text.contains("/TRANSFORM/TRA/1: keyword not supported"),
        "{text}"
    );
    assert!(text.contains("/MEMORY: keyword skipped"), "{text}");
}

#[test]
fn skip_unsupported_runs_and_says_what_it_skipped() {
    let deck = free_plate_with_unsupported("skipped");
    let dir = deck.with_file_name("out");
    let out = crashsim(&[
        "run",
        deck.to_str().unwrap(),
        "--out",
        dir.to_str().unwrap(),
        "--quiet",
        "--skip-unsupported",
    ]);
    ok(&out, "run --skip-unsupported");
    let listing = std::fs::read_to_string(dir.join("free_plate.out")).unwrap();
    for k in ["/TRANSFORM/TRA/1", "free_plate_0001.rad:6: /DT/SHELL/CST"] {
        let note = listing
            .lines()
            .find(|l| l.contains("skipped (--skip-unsupported)") && l.contains(k));
        assert!(note.is_some(), "the listing does not name {k}:\n{listing}");
    }
    assert!(
        !listing.contains("/MEMORY"),
        "a safe keyword is not a skipped one"
    );
    let info = crashsim(&["info", dir.join("free_plate.h5").to_str().unwrap()]);
    let info = String::from_utf8_lossy(&info.stdout);
    assert!(
        info.contains("skipped (--skip-unsupported)") && info.contains("/DT/SHELL/CST"),
        "{info}"
    );
}

/// /RANDOM moves the nodes (`engine_pressure_noise_submodel` checks by how
/// much): a noise in a unit system of its own, or on an undefined group,
/// stops the deck at its line.
#[test]
fn a_random_noise_in_its_own_units_or_on_no_group_is_refused() {
    let src = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("decks/free_plate");
    let starter = std::fs::read_to_string(src.join("free_plate_0000.rad")).unwrap();
    let (head, tail) = starter.split_once("/END").unwrap();
    for (header, expect) in [
        ("/RANDOM/7", ["free_plate_0000.rad:144", "unit_ID"]),
        ("/RANDOM/GRNOD/99", ["free_plate_0000.rad:145", "grnd_ID"]),
    ] {
        let dir = scratch(&format!("random-{}", header.len()));
        let extra = format!("{header}\n{:>20}{:>20}\n", 0.01, 0.5);
        std::fs::write(
            dir.join("free_plate_0000.rad"),
            format!("{head}{extra}/END{tail}"),
        )
        .unwrap();
        std::fs::copy(
            src.join("free_plate_0001.rad"),
            dir.join("free_plate_0001.rad"),
        )
        .unwrap();
        run_refused(&dir.join("free_plate_0000.rad"), &expect);
    }
}

/// /DT/BRICK/CST is accepted where it changes nothing (no solids,
/// `engine_final_geometry`); on a model with bricks it stops the run by name.
#[test]
fn brick_mass_scaling_on_bricks_is_refused_by_name() {
    let src = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("decks/brick_bar");
    let dir = scratch("brick-cst");
    std::fs::copy(
        src.join("brick_bar_0000.rad"),
        dir.join("brick_bar_0000.rad"),
    )
    .unwrap();
    let engine = std::fs::read_to_string(src.join("brick_bar_0001.rad")).unwrap();
    std::fs::write(
        dir.join("brick_bar_0001.rad"),
        format!("{engine}/DT/BRICK/CST/0\n0.67 4e-4\n"),
    )
    .unwrap();
    run_refused(
        &dir.join("brick_bar_0000.rad"),
        &[
            "brick_bar_0001.rad:6",
            "/DT/BRICK/CST",
            "solid elements is not computed",
        ],
    );
}

/// LOI12 (LAW12 on /PROP/TYPE6 with /FAIL/HASHIN Ifail_so 0) runs; the
/// Hashin relaxation and deletion (Ifail_so 1) and an isotropic law on an
/// orthotropic section are refused by name.
#[test]
fn hashin_relaxation_and_isotropic_laws_on_sol_orth_are_refused_by_name() {
    let src = qa_deck("LOIS_LOI12_test1").with_file_name("LOI12_0000.rad");
    let text = std::fs::read_to_string(&src).unwrap();
    let hashin = "/FAIL/HASHIN/1\n#---1----|----2----|----3----|----4----|----5----|----6----|----7----|----8----|----9----|---10----|\n         1         2     \n";
    assert!(text.contains(hashin));
    let relaxing = hashin.replace(
        "         1         2     \n",
        "         1         2         1\n",
    );
    let mat = "/MAT/LAW12/1\ntest des directions d_orthotropie\n";
    assert!(text.contains(mat));
    for (tag, deck, expect) in [
        ("hashin", text.replace(hashin, &relaxing), "Ifail_so = 1"),
        (
            "iso",
            // The material block made an elastic LAW1.
            {
                let (a, b) = (
                    text.find(mat).unwrap(),
                    text.find("/FAIL/HASHIN/1").unwrap(),
                );
                let elastic = format!(
                    "/MAT/ELAST/1\nisotropic\n{:>20}\n{:>20}{:>20}\n",
                    0.0078, 10.0, 0.3
                );
                format!("{}{elastic}{}", &text[..a], &text[b..])
            },
            "on /PROP/TYPE6 (SOL_ORTH)",
        ),
    ] {
        let dir = scratch(&format!("refusal-loi12-{tag}"));
        std::fs::write(dir.join("LOI12_0000.rad"), deck).unwrap();
        for f in ["LOI12_0001.rad", "qadiags.inc"] {
            std::fs::copy(src.with_file_name(f), dir.join(f)).unwrap();
        }
        run_refused(&dir.join("LOI12_0000.rad"), &[expect]);
    }
}
