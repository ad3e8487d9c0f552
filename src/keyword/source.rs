//! Reading keyword-deck text: files, `*INCLUDE` and `*INCLUDE_PATH`, `$`
//! comments, `*PARAMETER`, and the split into keyword blocks. Nothing here
//! knows what a keyword means.
//!
//! Rules (LS-DYNA keyword format, "General Card Format" of the keyword
//! manual, volume I):
//! - a line whose first character is `$` is a comment;
//! - a line whose first character is `*` starts a keyword; the keyword is
//!   its first word, upper-cased (`*NODE`, `*MAT_ELASTIC_TITLE`); a ` +`
//!   after it asks for the long format (20-column fields) for that keyword,
//!   ` -` for the standard one, and `*KEYWORD LONG=S` for the whole deck;
//! - `*INCLUDE` is replaced by the lines of the files it names, relative
//!   to the including file's folder or to a folder of `*INCLUDE_PATH`
//!   (`*INCLUDE_PATH_RELATIVE` too); `*END` ends the file it is in;
//!   `*INCLUDE_TRANSFORM` too, its blocks carrying what it does to their
//!   cards (`include_transform::Transform`: id offsets, unit factors, a
//!   TRANID);
//! - `*PARAMETER` defines names that a field of any later card may give as
//!   `&NAME` (or `-&NAME`);
//! - every other line belongs to the keyword above it.

use super::include_transform::Transform;
use crate::model::{InputError, InputResult, Loc};
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// Longest line accepted.
pub const MAX_LINE_BYTES: usize = 4096;
/// Deepest `*INCLUDE` nesting accepted.
pub const MAX_INCLUDE_DEPTH: usize = 32;

/// One data line with where it came from.
#[derive(Clone, Debug)]
pub struct Line {
    pub text: String,
    pub loc: Loc,
}

/// A keyword and its data lines.
#[derive(Clone, Debug)]
pub struct Block {
    /// The keyword, upper-cased, without `*` and options (`ELEMENT_SHELL`).
    pub name: String,
    pub loc: Loc,
    /// 20-column fields (` +` on the keyword line, or `*KEYWORD LONG=S`).
    pub long: bool,
    pub lines: Vec<Line>,
    /// The `*INCLUDE_TRANSFORM` of the file the block is in (composed
    /// with those around it), if any.
    pub transform: Option<Arc<Transform>>,
}

/// A deck read with its includes: its keyword blocks in reading order and
/// the `*PARAMETER` values (by upper-cased name).
#[derive(Debug, Default)]
pub struct Source {
    pub blocks: Vec<Block>,
    pub parameters: HashMap<String, String>,
    pub files: Vec<PathBuf>,
    /// Whether the first keyword is `*KEYWORD`.
    pub has_keyword_header: bool,
}

/// Whether the file at `path` looks like a keyword deck: its first line that
/// is neither blank nor a `$` comment starts with `*KEYWORD`.
pub fn is_keyword_deck(path: &Path) -> bool {
    use std::io::Read;
    // Only the file's start: a Radioss deck of gigabytes is not read twice.
    let mut head = Vec::new();
    let read = std::fs::File::open(path).and_then(|f| f.take(1 << 16).read_to_end(&mut head));
    if read.is_err() {
        return false;
    }
    String::from_utf8_lossy(&head)
        .lines()
        .map(str::trim_end)
        .find(|l| !l.trim().is_empty() && !l.starts_with('$'))
        .is_some_and(|l| l.to_ascii_uppercase().starts_with("*KEYWORD"))
}

/// Reads `path` and everything it includes.
pub fn read(path: &Path) -> InputResult<Source> {
    let mut r = Reader {
        src: Source::default(),
        stack: Vec::new(),
        include_dirs: Vec::new(),
        long_deck: false,
        transform: None,
    };
    r.file(path, None)?;
    r.src.has_keyword_header = r.src.blocks.first().is_some_and(|b| b.name == "KEYWORD");
    Ok(r.src)
}

struct Reader {
    src: Source,
    stack: Vec<PathBuf>,
    include_dirs: Vec<PathBuf>,
    long_deck: bool,
    /// The transform of the file being read.
    transform: Option<Arc<Transform>>,
}

impl Reader {
    /// Reads one file; `from` is the `*INCLUDE` line that named it.
    fn file(&mut self, path: &Path, from: Option<&Loc>) -> InputResult<()> {
        let (err_loc, kw) = match from {
            Some(l) => (l.clone(), "*INCLUDE"),
            None => (loc(path, 0), ""),
        };
        let fail = |why: String| InputError::new(err_loc.clone(), kw, "", why);
        let canon = std::fs::canonicalize(path)
            .map_err(|e| fail(format!("cannot open '{}': {e}", path.display())))?;
        if self.stack.contains(&canon) {
            return Err(fail(format!("'{}' includes itself", path.display())));
        }
        if self.stack.len() >= MAX_INCLUDE_DEPTH {
            return Err(fail(format!(
                "includes nested deeper than {MAX_INCLUDE_DEPTH} files"
            )));
        }
        let bytes = std::fs::read(path)
            .map_err(|e| fail(format!("cannot read '{}': {e}", path.display())))?;
        let text = String::from_utf8(bytes).map_err(|e| {
            let line = 1 + e.as_bytes()[..e.utf8_error().valid_up_to()]
                .iter()
                .filter(|&&b| b == b'\n')
                .count();
            InputError::new(loc(path, line), "", "", "the line is not UTF-8 text")
        })?;
        self.stack.push(canon);
        self.src.files.push(path.to_path_buf());
        let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
        let mut lines = text.lines().enumerate().peekable();
        while let Some((i, raw)) = lines.next() {
            let here = loc(path, i + 1);
            if raw.len() > MAX_LINE_BYTES {
                return Err(InputError::new(
                    here,
                    "",
                    "",
                    format!("line longer than {MAX_LINE_BYTES} bytes"),
                ));
            }
            let text = raw.trim_end().replace('\t', " ");
            if text.starts_with('$') {
                continue;
            }
            if !text.starts_with('*') {
                match self.src.blocks.last_mut() {
                    Some(b) => b.lines.push(Line { text, loc: here }),
                    None if text.trim().is_empty() => {}
                    None => {
                        return Err(InputError::new(
                            here,
                            "",
                            "",
                            "data before the first keyword: expected a line starting with '*'",
                        ))
                    }
                }
                continue;
            }
            let mut words = text[1..].split_whitespace();
            let name = words.next().unwrap_or("").to_ascii_uppercase();
            let rest: Vec<String> = words.map(|w| w.to_ascii_uppercase()).collect();
            match name.as_str() {
                "END" => break,
                "KEYWORD" => {
                    self.long_deck |= rest.iter().any(|w| w == "LONG=S" || w == "LONG=Y");
                }
                "INCLUDE_PATH" | "INCLUDE_PATH_RELATIVE" => {
                    for (_, l) in take_data(&mut lines) {
                        let p = l.trim();
                        if !p.is_empty() {
                            self.include_dirs.push(dir.join(p));
                        }
                    }
                    continue;
                }
                "INCLUDE_TRANSFORM" => {
                    let data = take_data(&mut lines);
                    let Some((j, name)) = data.first() else {
                        return Err(InputError::new(
                            here,
                            "*INCLUDE_TRANSFORM",
                            "FILENAME",
                            "missing: expected the card FILENAME",
                        ));
                    };
                    let t = transform_cards(path, &data[1..])?;
                    let outer = self.transform.clone();
                    let t = match &outer {
                        Some(o) => t.within(o),
                        None => t,
                    };
                    self.transform = Some(Arc::new(t));
                    let target = self.locate(&dir, name.trim());
                    let read = self.file(&target, Some(&loc(path, j + 1)));
                    self.transform = outer;
                    read?;
                    continue;
                }
                "INCLUDE" => {
                    for (j, l) in take_data(&mut lines) {
                        let name = l.trim();
                        if name.is_empty() {
                            continue;
                        }
                        let from = loc(path, j + 1);
                        let target = self.locate(&dir, name);
                        self.file(&target, Some(&from))?;
                    }
                    continue;
                }
                _ => {}
            }
            let long = match rest.first().map(String::as_str) {
                Some("+") => true,
                Some("-") => false,
                _ => self.long_deck,
            };
            self.src.blocks.push(Block {
                name,
                loc: here,
                long,
                lines: Vec::new(),
                transform: self.transform.clone(),
            });
        }
        self.stack.pop();
        Ok(())
    }

    /// An included file: relative to the including file's folder, else to
    /// the first `*INCLUDE_PATH` folder that holds it.
    fn locate(&self, dir: &Path, name: &str) -> PathBuf {
        let p = Path::new(name);
        if p.is_absolute() {
            return p.to_path_buf();
        }
        let here = dir.join(p);
        if here.exists() {
            return here;
        }
        self.include_dirs
            .iter()
            .map(|d| d.join(p))
            .find(|c| c.exists())
            .unwrap_or(here)
    }
}

/// The data lines under a keyword (up to the next keyword), comments dropped.
fn take_data<'a, I>(lines: &mut std::iter::Peekable<I>) -> Vec<(usize, String)>
where
    I: Iterator<Item = (usize, &'a str)>,
{
    let mut out = Vec::new();
    while let Some((_, l)) = lines.peek() {
        if l.starts_with('*') {
            break;
        }
        let (j, l) = lines.next().unwrap();
        if !l.starts_with('$') {
            out.push((j, l.trim_end().to_string()));
        }
    }
    out
}

/// `*INCLUDE_TRANSFORM`'s cards 2-5 (IDNOFF IDEOFF IDPOFF IDMOFF IDSOFF
/// IDFOFF IDDOFF; IDROFF, blank, PREFIX, SUFFIX; FCTMAS FCTTIM FCTLEN FCTTEM
/// INCOUT1; TRANID), fixed 10-column or free format; blank cards and fields
/// are 0 (factors: 0 or blank are 1). FCTTEM is refused by name.
fn transform_cards(path: &Path, cards: &[(usize, String)]) -> InputResult<Transform> {
    const NAMES: [&[&str]; 4] = [
        &[
            "IDNOFF", "IDEOFF", "IDPOFF", "IDMOFF", "IDSOFF", "IDFOFF", "IDDOFF",
        ],
        &["IDROFF", "", "PREFIX", "SUFFIX"],
        &["FCTMAS", "FCTTIM", "FCTLEN", "FCTTEM", "INCOUT1"],
        &["TRANID"],
    ];
    let mut t = Transform::identity();
    for (card, (j, text)) in cards.iter().enumerate().take(NAMES.len()) {
        let fields: Vec<String> = if text.contains(',') {
            text.split(',').map(|f| f.trim().to_string()).collect()
        } else {
            let b = text.as_bytes();
            (0..b.len().div_ceil(10))
                .map(|i| {
                    String::from_utf8_lossy(&b[10 * i..(10 * i + 10).min(b.len())])
                        .trim()
                        .to_string()
                })
                .collect()
        };
        let at = loc(path, j + 1);
        for (f, name) in fields.iter().zip(NAMES[card]) {
            let bad = |what: &str| {
                InputError::new(
                    at.clone(),
                    "*INCLUDE_TRANSFORM",
                    name,
                    format!("'{f}': expected {what}"),
                )
            };
            match (card, *name) {
                (_, "") | (1, "PREFIX" | "SUFFIX") | (2, "INCOUT1") => {}
                _ if f.is_empty() => {}
                (2, "FCTTEM") => return Err(bad("blank: temperature conversion is not computed")),
                (2, _) => {
                    let v: f64 = f.parse().map_err(|_| bad("a unit factor > 0"))?;
                    if !(v >= 0.0 && v.is_finite()) {
                        return Err(bad("a unit factor > 0 (0: 1)"));
                    }
                    let k = NAMES[2].iter().position(|n| n == name).unwrap();
                    t.factors[k] = if v == 0.0 { 1.0 } else { v };
                }
                _ => {
                    let v = crate::deck::fields::parse_int(f)
                        .ok()
                        .filter(|&v| v >= 0)
                        .ok_or_else(|| bad("an integer >= 0"))?;
                    match (card, *name) {
                        (3, _) => {
                            if v > 0 {
                                t.tranids.push((v as u64, at.clone()));
                            }
                        }
                        (1, _) => t.offsets[7] = v,
                        (_, _) => {
                            let k = NAMES[0].iter().position(|n| n == name).unwrap();
                            t.offsets[k] = v;
                        }
                    }
                }
            }
        }
    }
    Ok(t)
}

fn loc(path: &Path, line: usize) -> Loc {
    Loc {
        file: path.to_path_buf(),
        line,
    }
}
