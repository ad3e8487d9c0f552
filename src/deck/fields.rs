//! Fixed-column fields of the block format: 10-character integer and text
//! fields, 20-character real fields (1-based column numbers, as in the
//! reference guide's column rulers). A blank field takes the default.
//!
//! Engine-file cards (e.g. `/DT` then `0.9 0.0`) are read list-directed: the
//! values are separated by blanks or commas, as Radioss reads them.

use super::source::{Block, Line};
use crate::model::{InputError, InputResult, Loc};

/// Reads the cards of one block in order.
#[derive(Clone)]
pub struct Cards<'a> {
    pub block: &'a Block,
    pos: usize,
}

impl<'a> Cards<'a> {
    pub fn new(block: &'a Block) -> Self {
        Cards { block, pos: 0 }
    }

    /// The next card, which must exist: `what` names it for the error message
    /// (e.g. "the card with RHO_I").
    pub fn next(&mut self, what: &str) -> InputResult<Card<'a>> {
        match self.block.lines.get(self.pos) {
            Some(line) => {
                self.pos += 1;
                Ok(Card {
                    line,
                    kw: &self.block.header,
                })
            }
            None => {
                let loc = self
                    .block
                    .lines
                    .last()
                    .map(|l| l.loc.clone())
                    .unwrap_or_else(|| self.block.loc.clone());
                Err(InputError::new(
                    loc,
                    &self.block.header,
                    "",
                    format!(
                        "card missing: expected {what} (the block ends here — truncated card?)"
                    ),
                ))
            }
        }
    }

    /// The next card if there is one (optional cards at the end of a block).
    pub fn next_opt(&mut self) -> Option<Card<'a>> {
        let line = self.block.lines.get(self.pos)?;
        self.pos += 1;
        Some(Card {
            line,
            kw: &self.block.header,
        })
    }

    /// The next non-blank card, for list blocks (/NODE, /SHELL, group lists)
    /// where blank lines carry nothing.
    pub fn next_nonblank(&mut self) -> Option<Card<'a>> {
        while let Some(line) = self.block.lines.get(self.pos) {
            self.pos += 1;
            if !line.text.trim().is_empty() {
                return Some(Card {
                    line,
                    kw: &self.block.header,
                });
            }
        }
        None
    }

    /// Lines not read yet.
    pub fn remaining(&self) -> &'a [Line] {
        &self.block.lines[self.pos.min(self.block.lines.len())..]
    }

    /// The title line (first line after the header); empty if the block has none.
    pub fn title(&mut self) -> String {
        self.next_opt()
            .map(|c| c.line.text.trim().to_string())
            .unwrap_or_default()
    }
}

/// One input line read as fields.
#[derive(Clone, Copy)]
pub struct Card<'a> {
    pub line: &'a Line,
    pub kw: &'a str,
}

impl<'a> Card<'a> {
    pub fn loc(&self) -> Loc {
        self.line.loc.clone()
    }

    pub fn err(&self, field: &str, message: impl Into<String>) -> InputError {
        InputError::new(self.loc(), self.kw, field, message)
    }

    pub fn is_blank(&self) -> bool {
        self.line.text.trim().is_empty()
    }

    /// Raw text of columns `col .. col+width` (1-based), blanks trimmed.
    pub fn text(&self, col: usize, width: usize) -> &'a str {
        field_slice(&self.line.text, col, width).trim()
    }

    /// The field as written, blanks kept (for fields read by column, like Trarot).
    pub fn raw(&self, col: usize, width: usize) -> &'a str {
        field_slice(&self.line.text, col, width)
    }

    /// Integer field; `None` when blank.
    pub fn int_opt(&self, col: usize, width: usize, name: &str) -> InputResult<Option<i64>> {
        let t = self.text(col, width);
        if t.is_empty() {
            return Ok(None);
        }
        parse_int(t).map(Some).map_err(|m| {
            self.err(
                name,
                format!("'{t}' in columns {}-{}: {m}", col, col + width - 1),
            )
        })
    }

    /// 10-column integer field with a default for blank.
    pub fn int(&self, col: usize, name: &str, default: i64) -> InputResult<i64> {
        Ok(self.int_opt(col, 10, name)?.unwrap_or(default))
    }

    /// Real field; `None` when blank. A field holding several numbers
    /// separated by blanks (a neighbour's digits run into it, cut at the
    /// column) is read as its first, as the reference reader's `%20lg` does;
    /// the others must start as numbers do (digit, sign or point).
    pub fn real_opt(&self, col: usize, width: usize, name: &str) -> InputResult<Option<f64>> {
        let t = self.text(col, width);
        if t.is_empty() {
            return Ok(None);
        }
        let mut words = t.split_whitespace();
        let first = words.next().unwrap_or(t);
        let spill_ok = parse_real(first).is_ok()
            && words.all(|w| w.starts_with(|c: char| c.is_ascii_digit() || "+-.".contains(c)));
        let t = if spill_ok { first } else { t };
        parse_real(t).map(Some).map_err(|m| {
            self.err(
                name,
                format!("'{t}' in columns {}-{}: {m}", col, col + width - 1),
            )
        })
    }

    /// 20-column real field with a default for blank.
    pub fn real(&self, col: usize, name: &str, default: f64) -> InputResult<f64> {
        Ok(self.real_opt(col, 20, name)?.unwrap_or(default))
    }

    /// Whitespace/comma separated values of a list-directed (engine) card.
    pub fn tokens(&self) -> Vec<&'a str> {
        self.line
            .text
            .split(|c: char| c.is_whitespace() || c == ',')
            .filter(|s| !s.is_empty())
            .collect()
    }

    /// The i-th list-directed value as a real (`None` if absent).
    pub fn tok_real(&self, i: usize, name: &str) -> InputResult<Option<f64>> {
        match self.tokens().get(i) {
            None => Ok(None),
            Some(t) => parse_real(t)
                .map(Some)
                .map_err(|m| self.err(name, format!("'{t}' (value {}): {m}", i + 1))),
        }
    }

    /// The i-th list-directed value as an integer (`None` if absent).
    pub fn tok_int(&self, i: usize, name: &str) -> InputResult<Option<i64>> {
        match self.tokens().get(i) {
            None => Ok(None),
            Some(t) => parse_int(t)
                .map(Some)
                .map_err(|m| self.err(name, format!("'{t}' (value {}): {m}", i + 1))),
        }
    }
}

/// The Radioss convention for most fields: a value of 0 (or blank) means
/// "use the default".
pub fn zero_default(v: f64, default: f64) -> f64 {
    if v == 0.0 {
        default
    } else {
        v
    }
}

/// Scale factors: 0 (or blank) means 1.
pub fn one_if_zero(v: f64) -> f64 {
    zero_default(v, 1.0)
}

/// Columns `col..col+width` (1-based) of a line; shorter lines give what they have.
fn field_slice(s: &str, col: usize, width: usize) -> &str {
    let start = col.saturating_sub(1);
    if s.is_ascii() {
        let a = start.min(s.len());
        let b = (start + width).min(s.len());
        return &s[a..b];
    }
    let mut idx = s
        .char_indices()
        .map(|(i, _)| i)
        .chain(std::iter::once(s.len()));
    let a = idx.nth(start).unwrap_or(s.len());
    let mut idx = s
        .char_indices()
        .map(|(i, _)| i)
        .chain(std::iter::once(s.len()));
    let b = idx.nth(start + width).unwrap_or(s.len());
    &s[a..b.max(a)]
}

/// An integer as Fortran writes it: optional sign and digits.
pub fn parse_int(t: &str) -> Result<i64, String> {
    let digits = t.strip_prefix(['+', '-']).unwrap_or(t);
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return Err("expected an integer".into());
    }
    t.parse::<i64>()
        .map_err(|_| "integer out of range".to_string())
}

/// A real as Fortran writes it: `1`, `-1.5`, `.3`, `7.8E-6`, `2.1D+05`, or the
/// exponent-without-letter form `1.5-3` (= 1.5E-3). NaN and infinities are
/// refused: they are never meaningful input.
pub fn parse_real(t: &str) -> Result<f64, String> {
    let lower = t.to_ascii_lowercase();
    let bare = lower.trim_start_matches(['+', '-']);
    if bare.starts_with("nan") || bare.starts_with("inf") {
        return Err("expected a finite real number, found NaN or infinity".into());
    }
    let b = lower.as_bytes();
    let mut i = 0;
    if i < b.len() && (b[i] == b'+' || b[i] == b'-') {
        i += 1;
    }
    let mant_start = i;
    let mut ndig = 0;
    while i < b.len() && b[i].is_ascii_digit() {
        i += 1;
        ndig += 1;
    }
    if i < b.len() && b[i] == b'.' {
        i += 1;
        while i < b.len() && b[i].is_ascii_digit() {
            i += 1;
            ndig += 1;
        }
    }
    if ndig == 0 {
        return Err("expected a real number".into());
    }
    let mantissa = &lower[..i];
    let _ = mant_start;
    let exponent: &str = if i == b.len() {
        ""
    } else {
        let mut j = i;
        if b[j] == b'e' || b[j] == b'd' {
            j += 1;
        } else if b[j] != b'+' && b[j] != b'-' {
            return Err("expected a real number".into());
        }
        let exp = &lower[j..];
        let ed = exp.strip_prefix(['+', '-']).unwrap_or(exp);
        if ed.is_empty() || !ed.bytes().all(|c| c.is_ascii_digit()) {
            return Err("expected a real number (bad exponent)".into());
        }
        exp
    };
    let text = if exponent.is_empty() {
        mantissa.to_string()
    } else {
        format!("{mantissa}e{exponent}")
    };
    let v: f64 = text
        .parse()
        .map_err(|_| "expected a real number".to_string())?;
    if !v.is_finite() {
        return Err("real number out of range (overflows to infinity)".into());
    }
    Ok(v)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fortran_reals() {
        assert_eq!(parse_real("7.80000028E-6").unwrap(), 7.80000028e-6);
        assert_eq!(parse_real(".3").unwrap(), 0.3);
        assert_eq!(parse_real("-5").unwrap(), -5.0);
        assert_eq!(parse_real("2.1D+05").unwrap(), 2.1e5);
        assert_eq!(parse_real("1.5-3").unwrap(), 1.5e-3);
        assert_eq!(parse_real("1.").unwrap(), 1.0);
        assert!(parse_real("NaN").is_err());
        assert!(parse_real("-Infinity").is_err());
        assert!(parse_real("1e999").is_err());
        assert!(parse_real("abc").is_err());
        assert!(parse_real("1.2.3").is_err());
        assert!(parse_real(".").is_err());
    }

    #[test]
    fn fortran_ints() {
        assert_eq!(parse_int("155").unwrap(), 155);
        assert_eq!(parse_int("-1").unwrap(), -1);
        assert!(parse_int("1.0").is_err());
        assert!(parse_int("x").is_err());
        assert!(parse_int("99999999999999999999").is_err());
    }

    #[test]
    fn columns() {
        assert_eq!(field_slice("         1         2", 11, 10).trim(), "2");
        assert_eq!(field_slice("ab", 11, 10), "");
        assert_eq!(field_slice("é123456789x", 11, 10), "x");
    }
}
