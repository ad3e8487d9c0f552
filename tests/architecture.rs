//! Architecture rules that the compiler does not check.
//!
//! Input → neutral model (issue 12): the Radioss reader (`src/deck/`) reads
//! cards and fills the model (`src/model/`); every later stage reads only the
//! model. So no file under `src/` outside the input layer may name the reader
//! module. The input layer is the reader folders and the format dispatcher
//! `src/input.rs` (the one place that picks a reader for a file); a second
//! format adds its folder to [`INPUT_LAYER`].

use std::path::{Path, PathBuf};

/// Paths under `src/` (relative, `/`-separated) that may name a reader:
/// folders end with `/`.
const INPUT_LAYER: &[&str] = &["deck/", "keyword/", "input.rs"];

/// Every `.rs` file under `dir`, sorted.
fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("read {}: {e}", dir.display()))
        .map(|e| e.expect("directory entry").path())
        .collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// Whether `code` (a line without its `//` comment) names the reader module:
/// a path `deck::…` (`crate::deck::`, `crashsim::deck::`, `super::deck::`, a
/// bare `deck::` after `use crate::deck;`) or an import of the module itself.
fn names_reader(code: &str) -> bool {
    let bytes = code.as_bytes();
    let word_at =
        |i: usize| i == 0 || !(bytes[i - 1].is_ascii_alphanumeric() || bytes[i - 1] == b'_');
    let path_use = code.match_indices("deck::").any(|(i, _)| word_at(i));
    let module_import = ["crate::deck", "crashsim::deck", "super::deck"]
        .iter()
        .any(|p| code.contains(p));
    let grouped_import = (code.contains("crate::{") || code.contains("crashsim::{"))
        && code.match_indices("deck").any(|(i, _)| {
            word_at(i) && !code[i + 4..].starts_with(|c: char| c.is_alphanumeric() || c == '_')
        });
    path_use || module_import || grouped_import
}

/// The code of a line: what comes before a `//` comment.
fn code_of(line: &str) -> &str {
    line.split("//").next().unwrap_or("")
}

#[test]
fn only_the_input_layer_names_the_reader() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    assert!(
        files.len() > 20,
        "found only {} files under {}",
        files.len(),
        src.display()
    );
    let mut offenders = Vec::new();
    for f in &files {
        let rel = f
            .strip_prefix(&src)
            .expect("under src")
            .to_string_lossy()
            .replace('\\', "/");
        if INPUT_LAYER.iter().any(|p| {
            if p.ends_with('/') {
                rel.starts_with(p)
            } else {
                rel == *p
            }
        }) {
            continue;
        }
        let text = std::fs::read_to_string(f).expect("read a source file");
        for (n, line) in text.lines().enumerate() {
            if names_reader(code_of(line)) {
                offenders.push(format!("src/{rel}:{}: {}", n + 1, line.trim()));
            }
        }
    }
    assert!(
        offenders.is_empty(),
        "outside the input layer ({INPUT_LAYER:?} under src/), these lines name the reader \
         module `deck`; read the model's types (crate::model) or call crate::input instead:\n{}",
        offenders.join("\n")
    );
}

#[test]
fn the_check_sees_reader_paths_and_not_lookalikes() {
    // What the scan must catch ...
    for line in [
        "use crate::deck::{ElementKind, Elements};",
        "use crate::deck;",
        "use crashsim::deck::{self, EngineFile};",
        "    mats: &[crate::deck::MaterialCard],",
        "    let d = deck::read_deck(&p, e, o)?;",
        "use crate::{deck, model};",
        "use super::deck::Id;",
    ] {
        assert!(names_reader(code_of(line)), "missed: {line}");
    }
    // ... and what it must let through: words that merely contain "deck",
    // fields named deck, and comments.
    for line in [
        "    pub deck: PathBuf,",
        "    let starter = opts.deck.display();",
        "fn decks_dir() -> PathBuf {",
        "use crate::model::{self, Model}; // built from the deck::Deck",
        "// Spotflag 0 reads as 5 (deck::interfaces::read_type2)",
        "    format!(\"{} is not defined in the deck\", what)",
        "use crate::{mydeck, model};",
    ] {
        assert!(!names_reader(code_of(line)), "false alarm: {line}");
    }
}
