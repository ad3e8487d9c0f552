//! The code's shape, checked on the sources (issue "architecture for
//! breadth"): every function in `src/` is under 200 lines, and the modules
//! import each other without cycles — neither between the crate's top-level
//! modules (`deck`, `model`, `contact`, `output`, `solver`, ...) nor between
//! the files of one module folder.
//!
//! How: a small lexer drops comments, strings and character literals; a
//! function runs from its `fn` line to the brace that closes its body; a
//! file's imports are its `crate::a::b` and `super::` paths, resolved to the
//! longest module path that exists under `src/`.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

const MAX_FN_LINES: usize = 200;
const MAX_CLOSURE_PARAMS: usize = 4;

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|e| e == "rs") {
            out.push(p);
        }
    }
}

/// The source with comments blanked and string and char literals filled
/// with `x` (newlines kept).
fn code_only(src: &str) -> String {
    let c: Vec<char> = src.chars().collect();
    let mut out = String::with_capacity(src.len());
    let mut i = 0;
    let keep_newlines = |s: &[char], out: &mut String| {
        let fill = if s[0] == '/' { ' ' } else { 'x' };
        for &ch in s {
            out.push(if ch == '\n' { '\n' } else { fill });
        }
    };
    while i < c.len() {
        let rest = &c[i..];
        let end = if rest.starts_with(&['/', '/']) {
            rest.iter().position(|&ch| ch == '\n').unwrap_or(rest.len())
        } else if rest.starts_with(&['/', '*']) {
            block_comment_len(rest)
        } else if rest[0] == '"' {
            string_len(rest, 0)
        } else if rest[0] == 'r' && (rest.get(1) == Some(&'"') || rest.get(1) == Some(&'#')) {
            raw_string_len(rest).unwrap_or(0)
        } else if rest[0] == '\'' {
            char_literal_len(rest)
        } else {
            0
        };
        if end == 0 {
            out.push(c[i]);
            i += 1;
        } else {
            keep_newlines(&rest[..end], &mut out);
            i += end;
        }
    }
    out
}

fn block_comment_len(s: &[char]) -> usize {
    let (mut depth, mut i) = (0usize, 0usize);
    while i + 1 < s.len() {
        if s[i] == '/' && s[i + 1] == '*' {
            depth += 1;
            i += 2;
        } else if s[i] == '*' && s[i + 1] == '/' {
            depth -= 1;
            i += 2;
            if depth == 0 {
                return i;
            }
        } else {
            i += 1;
        }
    }
    s.len()
}

/// Length of the string literal opening at `s[start]` (a `"`).
fn string_len(s: &[char], start: usize) -> usize {
    let mut i = start + 1;
    while i < s.len() {
        match s[i] {
            '\\' => i += 2,
            '"' => return i + 1,
            _ => i += 1,
        }
    }
    s.len()
}

fn raw_string_len(s: &[char]) -> Option<usize> {
    let hashes = s[1..].iter().take_while(|&&c| c == '#').count();
    if s.get(1 + hashes) != Some(&'"') {
        return None;
    }
    let mut i = 2 + hashes;
    while i < s.len() {
        if s[i] == '"'
            && s[i + 1..]
                .iter()
                .take(hashes)
                .filter(|&&c| c == '#')
                .count()
                == hashes
        {
            return Some(i + 1 + hashes);
        }
        i += 1;
    }
    Some(s.len())
}

/// A char literal ('x', '\n', '\u{..}') or 0 for a lifetime.
fn char_literal_len(s: &[char]) -> usize {
    if s.get(1) == Some(&'\\') {
        return s[2..].iter().position(|&c| c == '\'').map_or(0, |p| p + 3);
    }
    if s.get(2) == Some(&'\'') {
        return 3;
    }
    0
}

/// The name of the function declared on this (code-only) line, if any.
fn fn_name(line: &str) -> Option<String> {
    let words: Vec<&str> = line.split_whitespace().collect();
    let at = words.iter().position(|w| *w == "fn")?;
    let before_ok = words[..at].iter().all(|w| {
        matches!(
            *w,
            "pub" | "const" | "unsafe" | "async" | "extern" | "default"
        ) || w.starts_with("pub(")
    });
    let name = words.get(at + 1)?;
    let name: String = name
        .chars()
        .take_while(|c| c.is_alphanumeric() || *c == '_')
        .collect();
    (before_ok && !name.is_empty()).then_some(name)
}

/// (name, first line, number of lines) of every function with a body.
fn functions(code: &str) -> Vec<(String, usize, usize)> {
    let lines: Vec<&str> = code.lines().collect();
    let mut out = Vec::new();
    for (i, line) in lines.iter().enumerate() {
        let Some(name) = fn_name(line) else { continue };
        let mut depth = 0i64;
        let mut opened = false;
        'scan: for (j, l) in lines.iter().enumerate().skip(i) {
            for ch in l.chars() {
                match ch {
                    ';' if !opened && depth == 0 => break 'scan,
                    '{' => {
                        depth += 1;
                        opened = true;
                    }
                    '}' => depth -= 1,
                    _ => {}
                }
                if opened && depth == 0 {
                    out.push((name.clone(), i + 1, j - i + 1));
                    break 'scan;
                }
            }
        }
    }
    out
}

fn src_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

#[test]
fn every_function_in_src_is_under_200_lines() {
    let mut files = Vec::new();
    rust_files(&src_root(), &mut files);
    let mut long = Vec::new();
    let mut count = 0;
    for f in &files {
        let code = code_only(&std::fs::read_to_string(f).unwrap());
        for (name, line, n) in functions(&code) {
            count += 1;
            if n >= MAX_FN_LINES {
                long.push(format!("{}:{line}: fn {name} has {n} lines", f.display()));
            }
        }
    }
    assert!(count > 500, "the scanner found only {count} functions");
    assert!(
        long.is_empty(),
        "functions of {MAX_FN_LINES} lines or more:\n{}",
        long.join("\n")
    );
}

/// (line, parameter count) of every closure: a `|…|` parameter list opened
/// after `=`, `(`, `,` or `move`.
fn closures(code: &str) -> Vec<(usize, usize)> {
    let c: Vec<char> = code.chars().collect();
    let mut out = Vec::new();
    let mut after = 0;
    for i in 0..c.len() {
        if i < after || c[i] != '|' || c.get(i + 1) == Some(&'|') || (i > 0 && c[i - 1] == '|') {
            continue;
        }
        let before: String = c[..i]
            .iter()
            .rev()
            .skip_while(|ch| ch.is_whitespace())
            .take(4)
            .collect();
        let opens = matches!(before.chars().next(), Some('=' | '(' | ','))
            && !before.starts_with("=>")
            && !before.starts_with("==")
            || before.starts_with("evom");
        if !opens {
            continue;
        }
        let (mut depth, mut commas, mut j, mut any) = (0i32, 0usize, i + 1, false);
        while j < c.len() && !(c[j] == '|' && depth == 0) {
            match c[j] {
                '(' | '[' | '<' => depth += 1,
                ')' | ']' | '>' => depth -= 1,
                ',' if depth == 0 => commas += 1,
                ch if !ch.is_whitespace() => any = true,
                _ => {}
            }
            j += 1;
        }
        after = j + 1;
        let trailing = c[i + 1..j].iter().rev().find(|ch| !ch.is_whitespace()) == Some(&',');
        let n = if any {
            commas + 1 - trailing as usize
        } else {
            0
        };
        out.push((
            code[..].chars().take(i).filter(|&ch| ch == '\n').count() + 1,
            n,
        ));
    }
    out
}

#[test]
fn no_closure_takes_more_than_four_parameters() {
    let mut files = Vec::new();
    rust_files(&src_root(), &mut files);
    let mut wide = Vec::new();
    let mut count = 0;
    for f in &files {
        let code = code_only(&std::fs::read_to_string(f).unwrap());
        for (line, n) in closures(&code) {
            count += 1;
            if n > MAX_CLOSURE_PARAMS {
                wide.push(format!(
                    "{}:{line}: a closure of {n} parameters",
                    f.display()
                ));
            }
        }
    }
    assert!(count > 100, "the scanner found only {count} closures");
    assert!(
        wide.is_empty(),
        "closures over {MAX_CLOSURE_PARAMS} parameters:\n{}",
        wide.join("\n")
    );
}

/// The module path of a source file: src/output/runfile.rs → ["output", "runfile"].
fn module_of(file: &Path) -> Vec<String> {
    let rel = file.strip_prefix(src_root()).unwrap();
    let mut parts: Vec<String> = rel
        .iter()
        .map(|p| p.to_string_lossy().trim_end_matches(".rs").to_string())
        .collect();
    if matches!(
        parts.last().map(String::as_str),
        Some("mod" | "lib" | "main")
    ) {
        parts.pop();
    }
    parts
}

/// The module paths a file refers to: its `use` trees and the inline
/// `crate::a::b…` and `super::…` paths, cut to the longest module that exists.
fn references(code: &str, me: &[String], modules: &BTreeSet<Vec<String>>) -> BTreeSet<Vec<String>> {
    let mut paths: Vec<String> = Vec::new();
    for stmt in code.split(';') {
        let stmt = stmt.trim_start();
        let body = stmt
            .strip_prefix("use ")
            .or_else(|| stmt.split_once(" use ").map(|(_, b)| b));
        if let Some(body) = body {
            let tree: String = body.chars().filter(|c| !c.is_whitespace()).collect();
            expand("", &tree, &mut paths);
        }
    }
    paths.extend(
        code.split(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':'))
            .filter(|t| t.starts_with("crate::") || t.starts_with("super::"))
            .map(str::to_string),
    );
    let mut out = BTreeSet::new();
    for path in paths {
        let segs: Vec<&str> = path.split("::").filter(|s| !s.is_empty()).collect();
        let abs: Vec<String> = match segs.first() {
            Some(&"crate") => segs[1..].iter().map(|s| s.to_string()).collect(),
            Some(&"super") => {
                let ups = segs.iter().take_while(|s| **s == "super").count();
                let mut base = me.to_vec();
                for _ in 0..ups {
                    base.pop();
                }
                base.extend(segs[ups..].iter().map(|s| s.to_string()));
                base
            }
            _ => continue,
        };
        if let Some(m) = (1..=abs.len())
            .rev()
            .map(|k| abs[..k].to_vec())
            .find(|p| modules.contains(p))
        {
            out.insert(m);
        }
    }
    out
}

/// A `use` tree without whitespace → its paths: `crate::{a,b::{c,d}}` →
/// `crate::a`, `crate::b::c`, `crate::b::d`.
fn expand(prefix: &str, tree: &str, out: &mut Vec<String>) {
    let mut depth = 0;
    let mut start = 0;
    let mut items = Vec::new();
    for (i, ch) in tree.char_indices() {
        match ch {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                items.push(&tree[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    items.push(&tree[start..]);
    for item in items.into_iter().filter(|s| !s.is_empty()) {
        match (item.find('{'), item.rfind('}')) {
            (Some(a), Some(b)) => expand(&format!("{prefix}{}", &item[..a]), &item[a + 1..b], out),
            _ => out.push(format!("{prefix}{item}")),
        }
    }
}

/// A cycle in a directed graph, if any (depth-first search).
fn find_cycle(graph: &BTreeMap<String, BTreeSet<String>>) -> Option<Vec<String>> {
    fn visit(
        n: &str,
        g: &BTreeMap<String, BTreeSet<String>>,
        state: &mut BTreeMap<String, u8>,
        stack: &mut Vec<String>,
    ) -> Option<Vec<String>> {
        state.insert(n.to_string(), 1);
        stack.push(n.to_string());
        for m in g.get(n).into_iter().flatten() {
            match state.get(m.as_str()).copied().unwrap_or(0) {
                1 => {
                    let from = stack.iter().position(|s| s == m).unwrap();
                    let mut cyc = stack[from..].to_vec();
                    cyc.push(m.clone());
                    return Some(cyc);
                }
                0 => {
                    if let Some(c) = visit(m, g, state, stack) {
                        return Some(c);
                    }
                }
                _ => {}
            }
        }
        stack.pop();
        state.insert(n.to_string(), 2);
        None
    }
    let mut state = BTreeMap::new();
    for n in graph.keys() {
        if state.get(n.as_str()).copied().unwrap_or(0) == 0 {
            if let Some(c) = visit(n, graph, &mut state, &mut Vec::new()) {
                return Some(c);
            }
        }
    }
    None
}

/// Edges between the modules at one level: top-level modules (the crate's
/// children) or the files of one folder (a module's children); a module's
/// references to its own descendants or ancestors do not count.
fn module_graph(files: &[PathBuf]) -> Vec<(String, BTreeMap<String, BTreeSet<String>>)> {
    let modules: BTreeSet<Vec<String>> = files.iter().map(|f| module_of(f)).collect();
    let mut levels: BTreeMap<Vec<String>, BTreeMap<String, BTreeSet<String>>> = BTreeMap::new();
    for f in files {
        let me = module_of(f);
        if me.is_empty() {
            continue;
        }
        let code = code_only(&std::fs::read_to_string(f).unwrap());
        for r in references(&code, &me, &modules) {
            // The deepest common parent: the level where `me` and `r` are siblings.
            let common = me.iter().zip(&r).take_while(|(a, b)| a == b).count();
            if common == me.len() || common == r.len() {
                continue;
            }
            levels
                .entry(me[..common].to_vec())
                .or_default()
                .entry(me[common].clone())
                .or_default()
                .insert(r[common].clone());
        }
    }
    levels
        .into_iter()
        .map(|(parent, g)| (format!("crate::{}", parent.join("::")), g))
        .collect()
}

#[test]
fn no_import_cycle_between_modules() {
    let mut files = Vec::new();
    rust_files(&src_root(), &mut files);
    let graphs = module_graph(&files);
    let top = graphs.iter().find(|(p, _)| p == "crate::").map(|(_, g)| g);
    assert!(
        top.is_some_and(|g| g.get("solver").is_some_and(|d| d.contains("contact"))),
        "the scanner did not see solver's imports of contact"
    );
    let cycles: Vec<String> = graphs
        .iter()
        .filter_map(|(parent, g)| find_cycle(g).map(|c| format!("in {parent}: {}", c.join(" -> "))))
        .collect();
    assert!(cycles.is_empty(), "import cycles:\n{}", cycles.join("\n"));
}

#[test]
fn the_scanner_reads_functions_and_paths() {
    let code = code_only(
        "fn a() {\n let s = \"}\"; let c = '{';\n // }\n}\npub(crate) fn b<'x>(v: &'x u8) -> u8 { *v }\nfn c();\n",
    );
    let f = functions(&code);
    assert_eq!(f, vec![("a".into(), 1, 4), ("b".into(), 5, 1)]);
    let cl = closures("let f = |a: u8, b: (u8, u8)| a;\nx.map(move |q| q || r);\nmatch v { A | B => 0 }\ng(|a, b, c, d, e,| 0);");
    assert_eq!(cl, vec![(1, 2), (2, 1), (4, 5)]);
    let mut paths = Vec::new();
    expand("", "crate::{model::{Model,build},deck}", &mut paths);
    assert_eq!(
        paths,
        vec!["crate::model::Model", "crate::model::build", "crate::deck"]
    );
    let mut g = BTreeMap::new();
    g.insert("a".to_string(), BTreeSet::from(["b".to_string()]));
    g.insert("b".to_string(), BTreeSet::from(["a".to_string()]));
    assert_eq!(
        find_cycle(&g),
        Some(vec!["a".into(), "b".into(), "a".into()])
    );
}
