//! Fuzz target for the Radioss deck reader: arbitrary bytes as a starter deck,
//! read with `deck::read_deck` and, when that succeeds, built with
//! `deck::build_model`. Neither may panic, overflow, hang or run out of memory;
//! any `Err` is fine.
//!
//! The reader works on files (it resolves `#include` relative to the deck's
//! folder), so each input is written to one file in a per-process temp dir,
//! reused every iteration.
#![no_main]

use crashsim::deck::{read_deck, EngineFile, ReadOptions};
use libfuzzer_sys::fuzz_target;
use std::path::PathBuf;
use std::sync::OnceLock;

fn deck_path() -> &'static PathBuf {
    static PATH: OnceLock<PathBuf> = OnceLock::new();
    PATH.get_or_init(|| {
        let dir = std::env::temp_dir().join(format!("crashsim-fuzz-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("create fuzz temp dir");
        dir.join("deck_0000.rad")
    })
}

fuzz_target!(|data: &[u8]| {
    let path = deck_path();
    std::fs::write(path, data).expect("write fuzz deck");
    if let Ok(deck) = read_deck(path, EngineFile::None, ReadOptions::default()) {
        let _ = crashsim::deck::build_model(&deck);
    }
});
