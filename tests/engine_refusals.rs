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
fn contact_interfaces_are_refused_until_contact_lands() {
    let deck =
        std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("decks/demo/demo_0000.rad");
    run_refused(
        &deck,
        &[
            "demo_0000.rad:",
            "/INTER/TYPE7",
            "not computed by the engine yet",
        ],
    );
}
