//! Input errors: every problem with a deck is reported with where it is
//! (file:line), which keyword and field, and what was expected.

use std::fmt;
use std::path::PathBuf;

/// A place in the input: a file and a 1-based line number (0 = whole file).
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize, Default)]
pub struct Loc {
    pub file: PathBuf,
    pub line: usize,
}

impl fmt::Display for Loc {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.line == 0 {
            write!(f, "{}", self.file.display())
        } else {
            write!(f, "{}:{}", self.file.display(), self.line)
        }
    }
}

/// One bad-input error. `Display` gives the one-line message the user sees.
#[derive(Clone, Debug, PartialEq)]
pub struct DeckError {
    pub loc: Loc,
    /// The keyword (e.g. `/MAT/PLAS_JOHNS/1`), empty when the problem is outside a block.
    pub keyword: String,
    /// The field name as the reference guide spells it (e.g. `RHO_I`), empty if none.
    pub field: String,
    /// What was found and what was expected.
    pub message: String,
}

impl DeckError {
    pub fn new(loc: Loc, keyword: &str, field: &str, message: impl Into<String>) -> Self {
        DeckError {
            loc,
            keyword: keyword.to_string(),
            field: field.to_string(),
            message: message.into(),
        }
    }
}

impl fmt::Display for DeckError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: error", self.loc)?;
        if !self.keyword.is_empty() {
            write!(f, ": {}", self.keyword)?;
        }
        if !self.field.is_empty() {
            write!(f, ", field {}", self.field)?;
        }
        write!(f, ": {}", self.message)
    }
}

impl std::error::Error for DeckError {}

pub type DeckResult<T> = Result<T, DeckError>;

/// A non-fatal remark about the input (unknown keyword skipped, ignored field ...).
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Warning {
    pub loc: Loc,
    pub keyword: String,
    pub message: String,
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: warning", self.loc)?;
        if !self.keyword.is_empty() {
            write!(f, ": {}", self.keyword)?;
        }
        write!(f, ": {}", self.message)
    }
}
