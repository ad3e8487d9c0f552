//! One data line of a keyword as fields: fixed columns (10 wide, 8 on a
//! line; 20 wide in the long format; the keyword's own widths where the
//! manual gives them, as `*NODE`'s 8/16), or free format when the line
//! holds a comma (fields between commas, in order). A field written
//! `&NAME` (or `-&NAME`) takes the value of `*PARAMETER` NAME. Every error
//! names file:line, the keyword, the field and what was expected.

use super::include_transform::{IdKind, Transform};
use super::source::{Block, Line};
use crate::deck::fields::{parse_int, parse_real};
use crate::model::{Id, InputError, InputResult, Loc};
use std::collections::HashMap;

/// `*PARAMETER` values by upper-cased name.
pub type Parameters = HashMap<String, String>;

/// One card: a data line read with a layout.
pub struct Card<'a> {
    line: &'a Line,
    keyword: &'a str,
    /// Field widths in columns (fixed format).
    widths: Vec<usize>,
    params: &'a Parameters,
    /// The `*INCLUDE_TRANSFORM` of the file the card is in.
    transform: Option<&'a Transform>,
}

/// Standard fields: 8 of 10 columns (20 in the long format).
pub fn standard(long: bool) -> Vec<usize> {
    vec![if long { 20 } else { 10 }; 8]
}

impl<'a> Card<'a> {
    pub fn new(
        block: &'a Block,
        line: &'a Line,
        widths: Vec<usize>,
        params: &'a Parameters,
    ) -> Self {
        Card {
            line,
            keyword: &block.name,
            widths,
            params,
            transform: block.transform.as_deref(),
        }
    }

    /// The keyword's base name (no `_TITLE`/`_ID`), as the transform tables know it.
    fn base(&self) -> &str {
        super::base_name(self.keyword).0
    }

    pub fn loc(&self) -> Loc {
        self.line.loc.clone()
    }

    pub fn err(&self, field: &str, message: impl Into<String>) -> InputError {
        InputError::new(self.loc(), &format!("*{}", self.keyword), field, message)
    }

    pub fn is_blank(&self) -> bool {
        self.line.text.trim().is_empty()
    }

    /// Field `i` as written, trimmed ("" when blank or past the line's end).
    pub fn raw(&self, i: usize) -> &'a str {
        let t = self.line.text.as_str();
        if t.contains(',') {
            return t.split(',').nth(i).map(str::trim).unwrap_or("");
        }
        let start: usize = self.widths[..i.min(self.widths.len())].iter().sum();
        let w = self.widths.get(i).copied().unwrap_or(0);
        let chars: Vec<(usize, char)> = t.char_indices().collect();
        let byte = |c: usize| chars.get(c).map(|&(b, _)| b).unwrap_or(t.len());
        t[byte(start)..byte(start + w)].trim()
    }

    /// Field `i` with `*PARAMETER` substitution.
    fn value(&self, i: usize, name: &str) -> InputResult<String> {
        let r = self.raw(i);
        let (neg, body) = match r.strip_prefix('-') {
            Some(b) if b.starts_with('&') => (true, b),
            _ => (false, r),
        };
        let Some(p) = body.strip_prefix('&') else {
            return Ok(r.to_string());
        };
        let v = self.params.get(&p.to_ascii_uppercase()).ok_or_else(|| {
            self.err(
                name,
                format!("parameter '{p}' is not defined: expected a *PARAMETER that defines it before this card"),
            )
        })?;
        Ok(if neg {
            match v.strip_prefix('-') {
                Some(pos) => pos.to_string(),
                None => format!("-{v}"),
            }
        } else {
            v.clone()
        })
    }

    /// An integer field as written (no `*INCLUDE_TRANSFORM` offset).
    fn int_written(&self, i: usize, name: &str, default: i64) -> InputResult<i64> {
        let v = self.value(i, name)?;
        if v.is_empty() {
            return Ok(default);
        }
        // Integer fields written as reals ("1.", "2.0") are common.
        parse_int(&v)
            .or_else(|e| match parse_real(&v) {
                Ok(x) if x.fract() == 0.0 && x.abs() < 9.0e15 => Ok(x as i64),
                _ => Err(e),
            })
            .map_err(|e| self.err(name, format!("'{v}': {e}")))
    }

    /// An integer field; an id offset by the file's `*INCLUDE_TRANSFORM`.
    pub fn int(&self, i: usize, name: &str, default: i64) -> InputResult<i64> {
        let v = self.int_written(i, name, default)?;
        match self.transform {
            Some(t) if !self.raw(i).is_empty() => {
                t.int(self.base(), name, v).map_err(|m| self.err(name, m))
            }
            _ => Ok(v),
        }
    }

    /// A real field as written (no unit factor).
    fn real_written(&self, i: usize, name: &str, default: f64) -> InputResult<f64> {
        let v = self.value(i, name)?;
        if v.is_empty() {
            return Ok(default);
        }
        parse_real(&v).map_err(|e| self.err(name, format!("'{v}': {e}")))
    }

    /// A real field, in the deck's units (the file's `*INCLUDE_TRANSFORM`
    /// unit factors).
    pub fn real(&self, i: usize, name: &str, default: f64) -> InputResult<f64> {
        let v = self.real_written(i, name, default)?;
        match self.transform {
            Some(t) if !self.raw(i).is_empty() => {
                t.real(self.base(), name, v).map_err(|m| self.err(name, m))
            }
            _ => Ok(v),
        }
    }

    /// Set id `id` (read as written: an `IntField::ByType` field) offset as
    /// the kind `kind` says (None: not an id, as SSTYP 5).
    pub fn offset_by_type(&self, id: Id, kind: Option<IdKind>) -> Id {
        match (self.transform, kind) {
            (Some(t), Some(k)) if id > 0 => (id as i64 + t.offset(k)).max(0) as Id,
            _ => id,
        }
    }

    /// A required id (> 0).
    pub fn id(&self, i: usize, name: &str) -> InputResult<Id> {
        match self.int(i, name, 0)? {
            v if v > 0 => Ok(v as Id),
            0 => Err(self.err(name, "blank or 0: expected an id > 0")),
            v => Err(self.err(name, format!("{v}: expected an id > 0"))),
        }
    }

    /// An optional id (blank or 0: none).
    pub fn id_opt(&self, i: usize, name: &str) -> InputResult<Id> {
        match self.int(i, name, 0)? {
            v if v >= 0 => Ok(v as Id),
            v => Err(self.err(name, format!("{v}: expected an id >= 0 (0: none)"))),
        }
    }

    /// Three reals from field `first` on (a vector: VX VY VZ).
    pub fn vec3(&self, first: usize, names: [&str; 3]) -> InputResult<[f64; 3]> {
        Ok([
            self.real(first, names[0], 0.0)?,
            self.real(first + 1, names[1], 0.0)?,
            self.real(first + 2, names[2], 0.0)?,
        ])
    }

    /// Whether field `i` is given and not 0, read as an integer field
    /// (`integer`: "1.5" is an error) or a real one.
    pub fn given(&self, i: usize, name: &str, integer: bool) -> InputResult<bool> {
        Ok(if integer {
            self.int_written(i, name, 0)? != 0
        } else {
            self.real_written(i, name, 0.0)? != 0.0
        })
    }

    /// The whole line as a title.
    pub fn title(&self) -> String {
        self.line.text.trim().to_string()
    }
}

/// The cards of a block, in order, with the keyword's option suffixes.
pub struct Cards<'a> {
    block: &'a Block,
    params: &'a Parameters,
    next: usize,
}

impl<'a> Cards<'a> {
    pub fn new(block: &'a Block, params: &'a Parameters) -> Self {
        Cards {
            block,
            params,
            next: 0,
        }
    }

    /// The next line read with `widths`; an error naming `what` when the
    /// keyword has no more lines.
    pub fn next(&mut self, widths: Vec<usize>, what: &str) -> InputResult<Card<'a>> {
        self.next_opt(widths).ok_or_else(|| {
            let at = self
                .block
                .lines
                .last()
                .map(|l| l.loc.clone())
                .unwrap_or(self.block.loc.clone());
            InputError::new(
                at,
                &format!("*{}", self.block.name),
                "",
                format!("the keyword ends early: expected {what}"),
            )
        })
    }

    /// The next line, `None` at the end.
    pub fn next_opt(&mut self, widths: Vec<usize>) -> Option<Card<'a>> {
        let line = self.block.lines.get(self.next)?;
        self.next += 1;
        Some(Card::new(self.block, line, widths, self.params))
    }

    /// The standard layout of this keyword (10 or 20 columns).
    pub fn standard(&self) -> Vec<usize> {
        standard(self.block.long)
    }

    pub fn long(&self) -> bool {
        self.block.long
    }

    /// Lines not read yet.
    pub fn remaining(&self) -> usize {
        self.block.lines.len() - self.next.min(self.block.lines.len())
    }
}
