//! Reading deck text: files, `#include`, comment lines, line hygiene, and the
//! split into keyword blocks. Nothing here knows what a keyword means.
//!
//! Rules (Radioss block format):
//! - a line whose first character is `#` or `$` is a comment, except `#include FILE`,
//!   which is replaced by the lines of FILE (a path relative to the including
//!   file's folder); `#enddata` ends the input like `/END`;
//! - a line whose first character is `/` starts a keyword block;
//! - every other line belongs to the block above it (blank lines too: in a
//!   fixed-card block a blank line is a card whose fields all take defaults);
//! - tab characters: see [`LineFormat`].

use crate::model::{InputError, InputResult, Loc};
use std::path::{Path, PathBuf};

/// Longest line accepted. Block-format cards use 100 columns (titles a few more);
/// anything this long is not a deck line.
pub const MAX_LINE_BYTES: usize = 4096;
/// Deepest `#include` nesting accepted.
pub const MAX_INCLUDE_DEPTH: usize = 32;
/// Largest input file accepted.
pub const MAX_FILE_BYTES: u64 = 4 << 30;

/// One physical input line with where it came from.
#[derive(Clone, Debug)]
pub struct Line {
    pub text: String,
    pub loc: Loc,
}

/// A keyword and the lines under it.
#[derive(Clone, Debug)]
pub struct Block {
    /// The keyword line as written, trailing blanks removed (e.g. `/MAT/PLAS_JOHNS/1`).
    pub header: String,
    /// The header split at `/`, upper-cased, e.g. `["MAT", "PLAS_JOHNS", "1"]`.
    pub parts: Vec<String>,
    pub loc: Loc,
    pub lines: Vec<Line>,
}

impl Block {
    /// The keyword name without trailing numeric ids, e.g. `/MAT/PLAS_JOHNS`.
    pub fn name(&self) -> String {
        let mut n = String::new();
        for p in &self.parts {
            if !p.is_empty() && p.bytes().all(|b| b.is_ascii_digit() || b == b'-') {
                break;
            }
            n.push('/');
            n.push_str(p);
        }
        n
    }
}

/// The result of reading one top-level file with its includes.
#[derive(Debug)]
pub struct Source {
    pub blocks: Vec<Block>,
    /// Where `/END` (or `#enddata`) was met, if it was.
    pub end: Option<Loc>,
    /// Every file that was read, top-level first.
    pub files: Vec<PathBuf>,
}

/// How the data lines of a file are laid out, which decides what a tab is.
///
/// The reference guide does not mention tabs. Its "Starter Keywords Syntax"
/// page says the starter's block content "is entered in fixed format": each
/// field owns fixed columns, and a tab owns no column, so a tab followed by
/// data on a starter line would put the data in no known field. Its "Engine
/// Keywords Syntax" page says engine data "are read in free format ... separated
/// by at least one blank", where a tab is one more blank. Hence:
/// - [`LineFormat::Fixed`] (starter files): a tab with only blanks or tabs
///   after it ends the line (trailing white space, as OpenRadioss QA's
///   SUBMODEL deck has after its /BEGIN unit line); a tab before data is an
///   error naming its column;
/// - [`LineFormat::Free`] (engine files): a tab separates values like a blank.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LineFormat {
    Fixed,
    Free,
}

/// Reads `path` (a starter file: fixed format) and everything it includes,
/// and splits it into blocks. Whether `/END` was met is in [`Source::end`]; the caller decides if it is required
/// (after the blocks are parsed, so that a truncated card is reported as such).
pub fn read(path: &Path) -> InputResult<Source> {
    read_as(path, LineFormat::Fixed)
}

/// [`read`] with the tab rule of `format` (engine files: [`LineFormat::Free`]).
pub fn read_as(path: &Path, format: LineFormat) -> InputResult<Source> {
    let mut lines = Vec::new();
    let mut files = Vec::new();
    let mut stack = Vec::new();
    let mut end = None;
    read_file(
        path, None, format, &mut stack, &mut lines, &mut files, &mut end,
    )?;
    let blocks = split_blocks(lines)?;
    Ok(Source { blocks, end, files })
}

fn read_file(
    path: &Path,
    included_from: Option<&Loc>,
    format: LineFormat,
    stack: &mut Vec<PathBuf>,
    out: &mut Vec<Line>,
    files: &mut Vec<PathBuf>,
    end: &mut Option<Loc>,
) -> InputResult<()> {
    let here = Loc {
        file: path.to_path_buf(),
        line: 0,
    };
    let (err_loc, kw) = match included_from {
        Some(l) => (l.clone(), "#include"),
        None => (here.clone(), ""),
    };
    let canon = std::fs::canonicalize(path).map_err(|e| {
        InputError::new(
            err_loc.clone(),
            kw,
            "",
            format!("cannot open '{}': {}", path.display(), io_reason(&e)),
        )
    })?;
    if stack.contains(&canon) {
        let chain: Vec<String> = stack
            .iter()
            .chain(std::iter::once(&canon))
            .map(|p| p.display().to_string())
            .collect();
        return Err(InputError::new(
            err_loc,
            kw,
            "",
            format!("#include cycle: {}", chain.join(" -> ")),
        ));
    }
    if stack.len() >= MAX_INCLUDE_DEPTH {
        return Err(InputError::new(
            err_loc,
            kw,
            "",
            format!("#include nested deeper than {MAX_INCLUDE_DEPTH} files"),
        ));
    }
    let meta = std::fs::metadata(&canon).map_err(|e| {
        InputError::new(
            err_loc.clone(),
            kw,
            "",
            format!("cannot read '{}': {}", path.display(), io_reason(&e)),
        )
    })?;
    if meta.is_dir() {
        return Err(InputError::new(
            err_loc,
            kw,
            "",
            format!("'{}' is a directory, expected a deck file", path.display()),
        ));
    }
    if !meta.is_file() {
        // A device, FIFO or socket (`#include /dev/zero`, `/dev/stdin`): reading
        // it would never end or block; its size says nothing.
        return Err(InputError::new(
            err_loc,
            kw,
            "",
            format!(
                "'{}' is not a regular file (device, pipe or socket), expected a deck file",
                path.display()
            ),
        ));
    }
    if meta.len() > MAX_FILE_BYTES {
        return Err(InputError::new(
            err_loc,
            kw,
            "",
            format!(
                "'{}' is {} bytes, larger than the {} accepted",
                path.display(),
                meta.len(),
                MAX_FILE_BYTES
            ),
        ));
    }
    let bytes = std::fs::read(&canon).map_err(|e| {
        InputError::new(
            err_loc.clone(),
            kw,
            "",
            format!("cannot read '{}': {}", path.display(), io_reason(&e)),
        )
    })?;
    stack.push(canon);
    files.push(path.to_path_buf());
    let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
    // A final newline ends the last line; it does not start an empty one.
    let body = bytes.strip_suffix(b"\n").unwrap_or(&bytes);
    for (i, raw) in body.split(|&b| b == b'\n').enumerate() {
        if end.is_some() {
            break;
        }
        let loc = Loc {
            file: path.to_path_buf(),
            line: i + 1,
        };
        let raw = raw.strip_suffix(b"\r").unwrap_or(raw);
        if raw.first() == Some(&b'$') {
            continue; // old-style comment line
        }
        if raw.first() == Some(&b'#') {
            let text = decode_line(raw, &loc).map_err(|e| in_block(e, out))?;
            if let Some(target) = include_target(&text) {
                let target = target.ok_or_else(|| {
                    InputError::new(
                        loc.clone(),
                        "#include",
                        "FILE",
                        "expected a file name after #include",
                    )
                })?;
                read_file(
                    &dir.join(target),
                    Some(&loc),
                    format,
                    stack,
                    out,
                    files,
                    end,
                )?;
            } else if text.trim_end().eq_ignore_ascii_case("#enddata") {
                *end = Some(loc);
            }
            continue;
        }
        let text = decode_line(raw, &loc).map_err(|e| in_block(e, out))?;
        let t = tabs(&text, format, &loc).map_err(|e| in_block(e, out))?;
        if t.eq_ignore_ascii_case("/END") {
            *end = Some(loc);
            break;
        }
        out.push(Line {
            text: t.to_string(),
            loc,
        });
    }
    stack.pop();
    Ok(())
}

/// Names the keyword block a bad line falls in (the last keyword line read so far).
fn in_block(mut e: InputError, out: &[Line]) -> InputError {
    if e.keyword.is_empty() {
        if let Some(h) = out.iter().rev().find(|l| l.text.starts_with('/')) {
            e.keyword = h.text.trim_end().to_string();
        }
    }
    e
}

fn io_reason(e: &std::io::Error) -> String {
    match e.kind() {
        std::io::ErrorKind::NotFound => "no such file".into(),
        std::io::ErrorKind::PermissionDenied => "permission denied".into(),
        _ => e.to_string(),
    }
}

/// `Some(Some(file))` for `#include file`, `Some(None)` for a bare `#include`,
/// `None` for any other comment.
fn include_target(text: &str) -> Option<Option<&str>> {
    let rest = text.strip_prefix('#')?;
    let kw = rest.get(..7)?;
    if !kw.eq_ignore_ascii_case("include") {
        return None;
    }
    let tail = &rest[7..];
    if !tail.is_empty() && !tail.starts_with([' ', '\t']) {
        return None; // e.g. "#included by ..." is an ordinary comment
    }
    let name = tail.trim();
    let name = name.trim_matches('"');
    Some(if name.is_empty() { None } else { Some(name) })
}

/// Checks a raw line and turns it into text. Control bytes mean the file is not
/// text; bytes that are not UTF-8 are taken as Latin-1 (older decks carry
/// accented titles). Tabs are left to [`tabs`].
fn decode_line(raw: &[u8], loc: &Loc) -> InputResult<String> {
    if raw.len() > MAX_LINE_BYTES {
        return Err(InputError::new(
            loc.clone(),
            "",
            "",
            format!(
                "line is {} bytes long; deck lines are at most 100 columns (limit {} bytes) — is this a deck file?",
                raw.len(),
                MAX_LINE_BYTES
            ),
        ));
    }
    if let Some(pos) = raw
        .iter()
        .position(|&b| (b < 0x20 && b != b'\t') || b == 0x7f)
    {
        return Err(InputError::new(
            loc.clone(),
            "",
            "",
            format!(
                "binary data (byte 0x{:02x} at column {}); expected text in Radioss block format",
                raw[pos],
                pos + 1
            ),
        ));
    }
    Ok(match std::str::from_utf8(raw) {
        Ok(s) => s.to_string(),
        Err(_) => raw.iter().map(|&b| b as char).collect(),
    })
}

/// A data line without its trailing white space, under the tab rule of
/// [`LineFormat`]: in a fixed-format line a tab before data is an error (it
/// has no column); in a free-format line a tab is a blank.
fn tabs(text: &str, format: LineFormat, loc: &Loc) -> InputResult<String> {
    let t = text.trim_end();
    match (format, t.find('\t')) {
        (_, None) => Ok(t.to_string()),
        (LineFormat::Free, Some(_)) => Ok(t.replace('\t', " ")),
        (LineFormat::Fixed, Some(pos)) => Err(InputError::new(
            loc.clone(),
            "",
            "",
            format!(
                "tab character at column {} before data; block-format fields are positional (fixed columns), use spaces",
                t[..pos].chars().count() + 1
            ),
        )),
    }
}

/// A keyword line split at '/', upper-cased: `/MAT/LAW1/1` → ["MAT",
/// "LAW1", "1"]; `//SUBMODEL/1` → ["/SUBMODEL", "1"].
pub(crate) fn header_parts(header: &str) -> Vec<String> {
    let double = header.starts_with("//");
    let mut parts: Vec<String> = header[if double { 2 } else { 1 }..]
        .split('/')
        .map(|p| p.trim().to_ascii_uppercase())
        .collect();
    if double {
        parts[0].insert(0, '/');
    }
    parts
}

fn split_blocks(lines: Vec<Line>) -> InputResult<Vec<Block>> {
    let mut blocks: Vec<Block> = Vec::new();
    for line in lines {
        if line.text.starts_with('/') {
            let header = line.text.trim_end().to_string();
            // `//SUBMODEL/1` ... `//ENDSUB` (the reference guide's submodel
            // keywords) are keywords whose name keeps its leading '/':
            // parts ["/SUBMODEL", "1"] (read by `super::submodel`).
            let parts = header_parts(&header);
            if parts.first().is_none_or(|p| p.is_empty() || p == "/") {
                return Err(InputError::new(
                    line.loc,
                    &header,
                    "",
                    "expected a keyword name after '/'",
                ));
            }
            blocks.push(Block {
                header,
                parts,
                loc: line.loc,
                lines: Vec::new(),
            });
        } else if let Some(b) = blocks.last_mut() {
            b.lines.push(line);
        } else if !line.text.trim().is_empty() {
            return Err(InputError::new(
                line.loc,
                "",
                "",
                "data line before the first keyword; expected a line starting with '/' (e.g. /BEGIN)",
            ));
        }
    }
    Ok(blocks)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `#include /dev/zero` used to be read to the end (never, until out of
    /// memory): its metadata length is 0 and it is not a directory.
    #[cfg(unix)]
    #[test]
    fn include_of_a_device_is_an_error() {
        let dir = std::env::temp_dir().join(format!("crashsim-src-dev-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let deck = dir.join("dev_0000.rad");
        std::fs::write(&deck, "/BEGIN\n#include /dev/zero\n/END\n").unwrap();
        let e = read(&deck).unwrap_err();
        assert!(e.message.contains("not a regular file"), "{}", e.message);
        let _ = std::fs::remove_dir_all(&dir);
    }
}
