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
fn qbat_shells_are_refused_at_their_property() {
    run_refused(
        &qa_deck("TWISBEAM"),
        &[
            "TWISBEAM_0000.rad:110",
            "/PROP/1",
            "Ishell = 12",
            "not supported yet",
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
