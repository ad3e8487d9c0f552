//! Reading an input into the [`Model`], whatever its format: the one place
//! that knows which reader reads which file. Everything after input (the
//! solver, `check`, `partition`) calls [`load`] or [`Input`] and sees only
//! the model; the readers (`deck` for Radioss today; an LS-DYNA reader would
//! be a sibling folder and one more [`Format`] arm) are never imported
//! elsewhere (`tests/architecture.rs` checks it).

use crate::deck::{self, Deck, EngineFile, ReadOptions};
use crate::keyword;
use crate::model::{Id, InputError, Loc, Model};
use std::path::{Path, PathBuf};

/// How to read an input.
#[derive(Clone, Debug, Default)]
pub struct InputOptions {
    /// The run-controls file (Radioss: the engine file `NAME_0001.rad`);
    /// `None`: the one beside the input, if it exists.
    pub controls: Option<PathBuf>,
    /// Unsupported keywords are errors instead of warnings.
    pub strict: bool,
}

/// The input formats there are readers for.
enum Format {
    /// Radioss block format: starter `NAME_0000.rad` (+ engine `NAME_0001.rad`).
    Radioss(Box<Deck>),
    /// LS-DYNA keyword deck (`*KEYWORD`): translated into the Radioss
    /// reader's card records (see `keyword`), run controls included.
    Keyword(Box<Deck>),
}

/// An input as read from its files: builds the model, and builds it again
/// from moved node positions (the start-up depenetration of contact).
pub struct Input {
    format: Format,
}

impl Input {
    /// Reads the input at `path`: a keyword deck when its name ends in
    /// `.k`, `.key`, `.dyn` or `.kw` or its first line is `*KEYWORD`, else a
    /// Radioss starter deck.
    pub fn read(path: &Path, opts: &InputOptions) -> Result<Input, InputError> {
        if is_keyword_path(path) {
            return read_keyword(path, opts);
        }
        let engine = match &opts.controls {
            Some(p) => EngineFile::Given(p.clone()),
            None => EngineFile::Auto,
        };
        let d = deck::read_deck(
            path,
            engine,
            ReadOptions {
                strict: opts.strict,
            },
        )?;
        Ok(Input {
            format: Format::Radioss(Box::new(d)),
        })
    }

    /// Validates the input and builds the model.
    pub fn model(&self) -> Result<Model, InputError> {
        match &self.format {
            Format::Radioss(d) | Format::Keyword(d) => deck::build_model(d),
        }
    }

    /// The model built again with the nodes `ids` (global ids, ascending, as
    /// `Model::nodes.ids`) at positions `x`; other nodes keep the input's.
    pub fn model_with_node_positions(
        &self,
        ids: &[Id],
        x: &[[f64; 3]],
    ) -> Result<Model, InputError> {
        match &self.format {
            Format::Radioss(d) | Format::Keyword(d) => {
                let mut d2 = Deck::clone(d);
                for nc in d2.nodes.iter_mut() {
                    if let Ok(i) = ids.binary_search(&nc.id) {
                        nc.x = x[i];
                    }
                }
                deck::build_model(&d2)
            }
        }
    }
}

/// Whether `path` names a keyword deck (by its extension, else by its
/// first line).
pub fn is_keyword_path(path: &Path) -> bool {
    let ext = path
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase())
        .unwrap_or_default();
    matches!(ext.as_str(), "k" | "key" | "dyn" | "kw") || keyword::is_keyword_deck(path)
}

/// A keyword deck: it carries its run controls (no separate controls
/// file); `strict` makes its first unsupported keyword an error.
fn read_keyword(path: &Path, opts: &InputOptions) -> Result<Input, InputError> {
    if let Some(c) = &opts.controls {
        return Err(InputError::new(
            Loc {
                file: c.clone(),
                line: 0,
            },
            "",
            "",
            "a keyword deck carries its run controls (*CONTROL_TERMINATION ...): expected no separate controls file",
        ));
    }
    let d = keyword::read(path)?;
    if opts.strict {
        if let Some(u) = d.unsupported.first() {
            return Err(InputError::new(
                u.loc.clone(),
                &u.keyword,
                "",
                u.message.clone(),
            ));
        }
    }
    Ok(Input {
        format: Format::Keyword(Box::new(d)),
    })
}

/// Reads the input at `path` and builds the model.
pub fn load(path: &Path, opts: &InputOptions) -> Result<Model, InputError> {
    Input::read(path, opts)?.model()
}

/// Where the run controls of the input at `path` are looked for when
/// [`InputOptions::controls`] is not given (Radioss: `dir/NAME_0001.rad` for
/// `dir/NAME_0000.rad`).
pub fn controls_beside(path: &Path) -> Option<PathBuf> {
    if is_keyword_path(path) {
        return None;
    }
    deck::engine_beside(path)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn free_plate() -> PathBuf {
        Path::new(env!("CARGO_MANIFEST_DIR")).join("decks/free_plate/free_plate_0000.rad")
    }

    /// The engine file beside the starter is found and read into the model's
    /// run controls; an explicit one that does not exist is an input error.
    #[test]
    fn reads_the_run_controls_beside_the_input() {
        let m = load(&free_plate(), &InputOptions::default()).unwrap();
        assert!(m.engine.as_ref().is_some_and(|e| e.run.is_some()));
        assert_eq!(
            controls_beside(&free_plate()).unwrap(),
            free_plate().with_file_name("free_plate_0001.rad")
        );
        let missing = InputOptions {
            controls: Some(free_plate().with_file_name("missing_0001.rad")),
            strict: false,
        };
        let e = load(&free_plate(), &missing).unwrap_err();
        assert!(e.loc.file.ends_with("missing_0001.rad"), "{e}");
    }

    /// Rebuilding with moved nodes moves exactly those nodes and recomputes
    /// what depends on positions (masses); the same positions give the same
    /// model bit for bit.
    #[test]
    fn rebuilds_the_model_with_moved_nodes() {
        let input = Input::read(&free_plate(), &InputOptions::default()).unwrap();
        let m = input.model().unwrap();
        let same = input
            .model_with_node_positions(&m.nodes.ids, &m.nodes.x)
            .unwrap();
        assert_eq!(same.nodes.x, m.nodes.x);
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&same.nodal_mass), bits(&m.nodal_mass));

        let mut x = m.nodes.x.clone();
        x[0][0] -= 5.0; // stretches the elements at node 0: more area, more mass
        let moved = input.model_with_node_positions(&m.nodes.ids, &x).unwrap();
        assert_eq!(moved.nodes.x[0], x[0]);
        assert_eq!(moved.nodes.x[1..], m.nodes.x[1..]);
        assert!(moved.nodal_mass[0] > m.nodal_mass[0]);
        // Only the first node is given: the others keep the input's positions.
        let first = input
            .model_with_node_positions(&m.nodes.ids[..1], &x[..1])
            .unwrap();
        assert_eq!(first.nodes.x, moved.nodes.x);
    }
}

/// What the readers do with each keyword, as a Markdown table (`crashsim
/// keywords`, the README's "What is supported").
pub fn supported_keywords() -> String {
    crate::deck::supported::markdown()
}
