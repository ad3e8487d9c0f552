//! Where something is defined in the input: a file and a line, for error
//! messages (`file:line: error: ...`). Any input format fills it.

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
