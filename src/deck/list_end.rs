//! Where an id list ends before the next keyword. Blocks whose data lines
//! are lists of ids (/TH objects, /GRNOD, /GRSHEL, /SURF/PART, /SUBSET)
//! run to the next keyword; a line there that holds text where the first id
//! belongs (columns 1-10 start with a letter, which no integer does) ends the
//! list, and it and the non-blank lines after it are ignored with one warning.
//!
//! Why: the OpenRadioss QA decks `#include qadiags.inc`, 23 `Copyright>`
//! lines, right after a block's last line (/TH/PART/4 in AMS_boxbeam,
//! /TH/INTER/7 in INTERF_INT_7_fpenmax, /TH/RBODY/3, /TH/SHEL/3, /PART/3,
//! /TITLE), and OpenRadioss reads them without error or warning, its starter
//! listings showing the ids above those lines only. Lines of text hold no id,
//! and a 0 in these lists names nothing, so nothing is lost; a mistyped
//! number (`1O`, `1.5`) starts with a digit and stays an error.

use super::fields::{Card, Cards};
use crate::model::Warning;

/// Whether `c` holds text where the first id of a list belongs.
pub(super) fn holds_text(c: &Card) -> bool {
    c.text(1, 10)
        .chars()
        .next()
        .is_some_and(|ch| ch.is_ascii_alphabetic())
}

/// The warning for a list that `c` ends (`what` names the list's items, e.g.
/// "object id"): `c` and the non-blank lines after it, up to the next
/// keyword, are ignored.
pub(super) fn ended_by_text(c: &Card, cards: &Cards, what: &str, warnings: &mut Vec<Warning>) {
    let more = cards
        .remaining()
        .iter()
        .filter(|l| !l.text.trim().is_empty())
        .count();
    warnings.push(Warning {
        loc: c.loc(),
        keyword: c.kw.to_string(),
        message: format!(
            "'{}' in columns 1-10 is text, not a {what}: the list ends here and {} line(s) up to the next keyword are ignored",
            c.text(1, 10),
            1 + more
        ),
    });
}
