//! Fuzz target for the LS-DYNA keyword reader: arbitrary bytes as a `.k`
//! deck, read and built through `crashsim::input::load` (the keyword arm of
//! the format dispatcher). It may not panic, overflow, hang or run out of
//! memory; any `Err` is fine.
//!
//! The reader works on files (it resolves `*INCLUDE` relative to the deck's
//! folder), so each input is written to one file in a per-process temp dir,
//! reused every iteration.
#![no_main]

use libfuzzer_sys::fuzz_target;
use std::path::PathBuf;
use std::sync::OnceLock;

fn deck_path() -> &'static PathBuf {
    static PATH: OnceLock<PathBuf> = OnceLock::new();
    PATH.get_or_init(|| {
        let dir = std::env::temp_dir().join(format!("crashsim-fuzz-k-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("create fuzz temp dir");
        dir.join("deck.k")
    })
}

fuzz_target!(|data: &[u8]| {
    let path = deck_path();
    std::fs::write(path, data).expect("write fuzz deck");
    let _ = crashsim::input::load(path, &Default::default());
});
