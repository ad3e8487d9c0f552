//! The keyword policy (issue "never a silent wrong answer"): every keyword of
//! a starter or engine file is either computed (a family parser reads it),
//! *safe to skip* (it changes nothing in the solution: the list below, each
//! with why), or *unsupported*: recorded by name so that `run` refuses the
//! deck before any cycle, `check` lists it, and `run --skip-unsupported`
//! runs anyway and says what it skipped. A keyword this reader does not know
//! is unsupported.

use super::source::Block;
use crate::model::Warning;

/// Keywords read by no parser that change nothing in the solution, with why.
/// (Output requests, memory sizing and the like; never anything that moves,
/// loads, constrains or defines a material, property or element.)
pub const SAFE_TO_SKIP: &[(&str, &str)] = &[
    (
        "MEMORY",
        "memory sizing of the reference solver's starter; it changes nothing in the solution",
    ),
    (
        "ACCEL",
        "an accelerometer: an output request, it changes nothing in the solution",
    ),
    (
        "OUTP",
        "a state-file output request (/OUTP/...): it changes nothing in the solution",
    ),
    (
        "ALE/BCS",
        "boundary conditions of the ALE grid: they act on the nodes of ALE or Euler elements only, and a deck that makes any element ALE or Euler (/ALE/MAT, /EULER/MAT) is refused by name, so on Lagrangian nodes they change nothing",
    ),
    (
        "TH/VERS",
        "the format version of the reference solver's time-history file: it changes nothing in the solution",
    ),
];

/// Why a keyword that no parser reads may be skipped, or `None` when it is
/// unsupported. An entry names the keyword's first word, or its first words
/// joined by '/' (`TH/VERS`).
pub fn safe_to_skip(block: &Block) -> Option<&'static str> {
    let words = |n: usize| block.parts.get(..n).map(|p| p.join("/"));
    SAFE_TO_SKIP
        .iter()
        .find(|(k, _)| words(k.split('/').count()).as_deref() == Some(*k))
        .map(|(_, why)| *why)
}

/// A keyword that no parser reads: a warning when it is safe to skip; when
/// it is unsupported, a warning and an entry in `unsupported` (what `run` stops on).
pub fn not_read(
    block: &Block,
    file_kind: &str,
    warnings: &mut Vec<Warning>,
    unsupported: &mut Vec<Warning>,
) {
    let w = |message: String| Warning {
        loc: block.loc.clone(),
        keyword: block.header.clone(),
        message,
    };
    match safe_to_skip(block) {
        Some(why) => warnings.push(w(format!(
            "keyword skipped ({} line(s)): {why}",
            block.lines.len()
        ))),
        None => {
            let u = w(format!(
                "keyword not supported in the {file_kind} file; `run` stops on it (`run --skip-unsupported` skips its {} line(s))",
                block.lines.len()
            ));
            warnings.push(u.clone());
            unsupported.push(u);
        }
    }
}
