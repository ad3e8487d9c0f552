//! Input errors and warnings: every problem with an input is reported with
//! where it is (file:line), which keyword and field, and what was expected.
//! The readers and the model's validation both return them.

use super::Loc;
use std::fmt;

/// One bad-input error. `Display` gives the one-line message the user sees.
#[derive(Clone, Debug, PartialEq)]
pub struct InputError {
    pub loc: Loc,
    /// The keyword (e.g. `/MAT/PLAS_JOHNS/1`), empty when the problem is outside a block.
    pub keyword: String,
    /// The field name as the reference guide spells it (e.g. `RHO_I`), empty if none.
    pub field: String,
    /// What was found and what was expected.
    pub message: String,
    /// The keyword line names a variant that no reader computes (a word where
    /// the id belongs, e.g. `/IMPDISP/FGEO/10`): the reader records the keyword
    /// as unsupported, by name, instead of stopping on it.
    pub variant_not_read: bool,
}

impl InputError {
    pub fn new(loc: Loc, keyword: &str, field: &str, message: impl Into<String>) -> Self {
        InputError {
            loc,
            keyword: keyword.to_string(),
            field: field.to_string(),
            message: message.into(),
            variant_not_read: false,
        }
    }
}

impl std::error::Error for InputError {}

pub type InputResult<T> = Result<T, InputError>;

/// A non-fatal remark about the input (unknown keyword skipped, ignored field ...).
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Warning {
    pub loc: Loc,
    pub keyword: String,
    pub message: String,
}

impl fmt::Display for InputError {
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

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: warning", self.loc)?;
        if !self.keyword.is_empty() {
            write!(f, ": {}", self.keyword)?;
        }
        write!(f, ": {}", self.message)
    }
}
