//! Bad input gets ONE clear error: `FILE:LINE: error: KEYWORD, field FIELD:
//! what was expected`, exit code 2, nothing on stdout, never a panic.
//!
//! Each test writes a small deck in a fresh temporary folder: one valid
//! minimal deck (`base_deck`) mutated per case.

use std::path::PathBuf;
use std::process::{Command, Output};

// ---------------------------------------------------------------------------
// Harness
// ---------------------------------------------------------------------------

/// A fresh folder `$TMP/crashsim-bad-<test>-<pid>`, removed when dropped.
struct Case {
    dir: PathBuf,
}

impl Case {
    fn new(test: &str) -> Case {
        let dir = std::env::temp_dir().join(format!("crashsim-bad-{test}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).expect("create the test folder");
        Case { dir }
    }

    fn path(&self, name: &str) -> PathBuf {
        self.dir.join(name)
    }

    fn write(&self, name: &str, bytes: &[u8]) -> PathBuf {
        let p = self.path(name);
        std::fs::write(&p, bytes).expect("write a deck file");
        p
    }

    /// Writes `lines` (joined with newlines) as `name`.
    fn write_lines(&self, name: &str, lines: &[String]) -> PathBuf {
        let mut text = lines.join("\n");
        text.push('\n');
        self.write(name, text.as_bytes())
    }

    /// `crashsim ARGS...` with the folder as working directory.
    fn run(&self, args: &[&str]) -> Output {
        Command::new(env!("CARGO_BIN_EXE_crashsim"))
            .args(args)
            .current_dir(&self.dir)
            .output()
            .expect("crashsim runs")
    }

    /// Writes the deck as `DECK_0000.rad` and runs `crashsim check` on it.
    fn check(&self, lines: &[String]) -> Output {
        let p = self.write_lines(DECK, lines);
        self.run(&["check", p.to_str().unwrap()])
    }
}

impl Drop for Case {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.dir);
    }
}

const DECK: &str = "DECK_0000.rad";

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

/// What one error must say. Empty `field` = the error names no field.
struct Expect<'a> {
    file: &'a str,
    /// 0: the message names the file without a line.
    line: usize,
    keyword: &'a str,
    field: &'a str,
    /// Phrases (case-insensitive) saying what was found / expected.
    phrases: &'a [&'a str],
}

/// Asserts exit code 2, empty stdout, no panic and exactly one error line
/// `crashsim: FILE:LINE: error: KEYWORD, field FIELD: ...` holding the phrases.
fn assert_error(out: &Output, e: Expect) -> String {
    let stderr = text(&out.stderr);
    let stdout = text(&out.stdout);
    assert_eq!(
        out.status.code(),
        Some(2),
        "exit code must be 2\nstderr: {stderr}\nstdout: {stdout}"
    );
    assert!(stdout.is_empty(), "stdout must be empty, got: {stdout}");
    assert!(!stderr.contains("panicked"), "panic: {stderr}");
    let errors: Vec<&str> = stderr.lines().filter(|l| l.contains("error")).collect();
    assert_eq!(errors.len(), 1, "expected one error line, got: {stderr}");
    let msg = errors[0];
    assert!(msg.starts_with("crashsim: "), "message prefix: {msg}");
    let place = if e.line == 0 {
        format!("{}: error", e.file)
    } else {
        format!("{}:{}: error", e.file, e.line)
    };
    assert!(msg.contains(&place), "expected place '{place}' in: {msg}");
    if !e.keyword.is_empty() {
        assert!(
            msg.contains(&format!("error: {}", e.keyword)),
            "expected keyword '{}' in: {msg}",
            e.keyword
        );
    }
    if !e.field.is_empty() {
        assert!(
            msg.contains(&format!(", field {}:", e.field)),
            "expected field '{}' in: {msg}",
            e.field
        );
    }
    let lower = msg.to_lowercase();
    for p in e.phrases {
        assert!(
            lower.contains(&p.to_lowercase()),
            "expected '{p}' in: {msg}"
        );
    }
    msg.to_string()
}

fn assert_ok(out: &Output) -> String {
    let stderr = text(&out.stderr);
    assert_eq!(
        out.status.code(),
        Some(0),
        "expected success\nstderr: {stderr}\nstdout: {}",
        text(&out.stdout)
    );
    assert!(!stderr.contains("panicked"), "panic: {stderr}");
    text(&out.stdout)
}

// ---------------------------------------------------------------------------
// Deck text
// ---------------------------------------------------------------------------

/// 10-column integer field.
fn i10(v: impl std::fmt::Display) -> String {
    format!("{v:>10}")
}

/// 20-column real field.
fn r20(v: impl std::fmt::Display) -> String {
    format!("{v:>20}")
}

fn s(v: &str) -> String {
    v.to_string()
}

/// The valid minimal deck: /BEGIN, /TITLE, one /MAT/LAW1, one /PROP/TYPE1,
/// one /PART, four /NODEs, one /SHELL, /END (fixed 10/20-column layout).
fn base_deck() -> Vec<String> {
    vec![
        s("#RADIOSS STARTER"),
        s("#---1----|----2----|----3----|----4----|----5----|----6----|----7----|----8----|----9----|---10----|"),
        s("/BEGIN"),
        s("MINI"),
        i10(2019) + &i10(0),
        r20("kg") + &r20("m") + &r20("s"),
        r20("kg") + &r20("m") + &r20("s"),
        s("/TITLE"),
        s("Minimal deck for bad-input tests"),
        s("/MAT/LAW1/1"),
        s("steel"),
        s("#              RHO_I"),
        r20("7800.0"),
        s("#                  E                  Nu"),
        r20("2.1E+11") + &r20("0.3"),
        s("/PROP/TYPE1/1"),
        s("shell property"),
        s("#   Ishell    Ismstr     Ish3n    Idrill                            P_thick_fail"),
        i10(0) + &i10(0) + &i10(0) + &i10(0) + &" ".repeat(20) + &r20(0),
        s("#                 hm                  hf                  hr                  dm                  dn"),
        r20(0) + &r20(0) + &r20(0) + &r20(0) + &r20(0),
        s("#        N   Istrain               Thick              Ashear              Ithick     Iplas"),
        i10(3) + &i10(0) + &r20("0.001") + &r20(0) + &i10(0) + &i10(0),
        s("/PART/1"),
        s("plate"),
        s("#  prop_ID    mat_ID subset_ID"),
        i10(1) + &i10(1) + &i10(0),
        s("/NODE"),
        node(1, "0", "0", "0"),
        node(2, "1", "0", "0"),
        node(3, "1", "1", "0"),
        node(4, "0", "1", "0"),
        s("/SHELL/1"),
        i10(1) + &i10(1) + &i10(2) + &i10(3) + &i10(4),
        s("/END"),
    ]
}

fn node(id: impl std::fmt::Display, x: &str, y: &str, z: &str) -> String {
    i10(id) + &r20(x) + &r20(y) + &r20(z)
}

/// 1-based number of the first line equal to `exact`.
fn line_no(lines: &[String], exact: &str) -> usize {
    lines
        .iter()
        .position(|l| l == exact)
        .unwrap_or_else(|| panic!("no line '{exact}' in the deck"))
        + 1
}

/// Replaces the line equal to `exact` by `new`; returns its line number.
fn replace(lines: &mut [String], exact: &str, new: String) -> usize {
    let n = line_no(lines, exact);
    lines[n - 1] = new;
    n
}

/// Inserts `extra` before /END; returns the line number of the first inserted line.
fn before_end(lines: &mut Vec<String>, extra: &[String]) -> usize {
    let end = line_no(lines, "/END") - 1;
    for (k, l) in extra.iter().enumerate() {
        lines.insert(end + k, l.clone());
    }
    end + 1
}

fn rho_line() -> String {
    r20("7800.0")
}
fn e_nu_line() -> String {
    r20("2.1E+11") + &r20("0.3")
}
fn prop_thick_line() -> String {
    i10(3) + &i10(0) + &r20("0.001") + &r20(0) + &i10(0) + &i10(0)
}
fn part_line() -> String {
    i10(1) + &i10(1) + &i10(0)
}
fn shell_line() -> String {
    i10(1) + &i10(1) + &i10(2) + &i10(3) + &i10(4)
}

/// A /SURF/PART on part 1 (the shell), for interface tests.
fn surf_part(id: u64, part: i64) -> Vec<String> {
    vec![format!("/SURF/PART/{id}"), s("surface"), i10(part)]
}

/// /INTER/TYPE7 with grnd_IDs and surf_IDm (format 2020+, other fields default).
fn inter_type7(id: u64, grnod: u64, surf: u64) -> Vec<String> {
    vec![
        format!("/INTER/TYPE7/{id}"),
        s("contact"),
        i10(grnod)
            + &i10(surf)
            + &i10(0)
            + &i10(0)
            + &i10(0)
            + &" ".repeat(10)
            + &i10(0)
            + &i10(0)
            + &i10(0),
        r20(0) + &r20(0) + &r20(0),
        r20(0) + &r20(0) + &r20(0) + &r20(0) + &i10(0) + &i10(0),
        r20(0) + &r20(".2") + &r20(0) + &r20(0) + &r20(0),
        i10("000") + &" ".repeat(20) + &i10(0) + &r20(0) + &r20(0) + &r20(0) + &r20(0),
        i10(0) + &i10(0) + &r20(0) + &i10(0) + &i10(0) + &i10(0) + &r20(0) + &i10(0),
    ]
}

// ---------------------------------------------------------------------------
// The valid deck
// ---------------------------------------------------------------------------

#[test]
fn valid_minimal_deck_passes() {
    let c = Case::new("valid");
    let out = c.check(&base_deck());
    let stdout = assert_ok(&out);
    assert!(
        stdout.contains("shells (4 nodes)           1"),
        "one shell expected: {stdout}"
    );
    assert!(text(&out.stderr).is_empty());

    let p = c.path(DECK);
    let out = c.run(&["check", p.to_str().unwrap(), "--json"]);
    let v: serde_json::Value = serde_json::from_str(&assert_ok(&out)).expect("JSON");
    assert_eq!(v["shells4"], 1);
    assert_eq!(v["nodes"], 4);
    assert_eq!(v["warnings"].as_array().map(Vec::len), Some(0));
}

#[test]
fn valid_deck_with_interface_passes() {
    // The interface fixtures below are valid when their ids resolve.
    let c = Case::new("valid-inter");
    let mut d = base_deck();
    let mut extra = surf_part(5, 1);
    extra.extend([s("/GRNOD/NODE/6"), s("nodes"), i10(1) + &i10(2)]);
    extra.extend(inter_type7(10, 6, 5));
    before_end(&mut d, &extra);
    let out = c.check(&d);
    let stdout = assert_ok(&out);
    assert!(stdout.contains("interfaces                 1"), "{stdout}");
}

// ---------------------------------------------------------------------------
// Files and includes
// ---------------------------------------------------------------------------

#[test]
fn missing_file() {
    let c = Case::new("missing-file");
    let p = c.path("NOPE_0000.rad");
    let out = c.run(&["check", p.to_str().unwrap()]);
    assert_error(
        &out,
        Expect {
            file: "NOPE_0000.rad",
            line: 0,
            keyword: "",
            field: "",
            phrases: &["cannot open", "no such file"],
        },
    );
}

/// Found by `ci/fuzz` (deck_reader): a /DAMP header without its id
/// indexed past the header's parts.
#[test]
fn damp_without_its_id() {
    let c = Case::new("damp-no-id");
    let mut d = base_deck();
    let n = before_end(&mut d, &[s("/DAMP"), s("ramp"), r20(0)]);
    let out = c.check(&d);
    assert_error(
        &out,
        Expect {
            file: DECK,
            line: n,
            keyword: "/DAMP",
            field: "damp_ID",
            phrases: &["missing damp_ID", "/DAMP/1"],
        },
    );
}

#[test]
fn missing_include_target() {
    let c = Case::new("missing-include");
    let mut d = base_deck();
    let n = before_end(&mut d, &[s("#include parts/nothere.inc")]);
    let out = c.check(&d);
    assert_error(
        &out,
        Expect {
            file: DECK,
            line: n,
            keyword: "#include",
            field: "",
            phrases: &["cannot open", "nothere.inc", "no such file"],
        },
    );
}

#[test]
fn include_without_file_name() {
    let c = Case::new("bare-include");
    let mut d = base_deck();
    let n = before_end(&mut d, &[s("#include   ")]);
    let out = c.check(&d);
    assert_error(
        &out,
        Expect {
            file: DECK,
            line: n,
            keyword: "#include",
            field: "FILE",
            phrases: &["expected a file name"],
        },
    );
}

#[test]
fn empty_file() {
    let c = Case::new("empty");
    let p = c.write(DECK, b"");
    let out = c.run(&["check", p.to_str().unwrap()]);
    assert_error(
        &out,
        Expect {
            file: DECK,
            line: 0,
            keyword: "/END",
            field: "",
            phrases: &["expected /END"],
        },
    );
}

#[test]
fn negative_node_id() {
    let c = Case::new("neg-node-id");
    let mut d = base_deck();
    let n = replace(&mut d, &node(2, "1", "0", "0"), node(-2, "1", "0", "0"));
    let out = c.check(&d);
    assert_error(
        &out,
        Expect {
            file: DECK,
            line: n,
            keyword: "/NODE",
            field: "node_ID",
            phrases: &["-2", "expected a positive id"],
        },
    );
}

#[test]
fn include_cycle() {
    let c = Case::new("include-cycle");
    c.write("a.inc", b"#include b.inc\n");
    c.write("b.inc", b"# b includes a\n#include a.inc\n");
    let mut d = base_deck();
    before_end(&mut d, &[s("#include a.inc")]);
    let out = c.check(&d);
    let msg = assert_error(
        &out,
        Expect {
            file: "b.inc",
            line: 2,
            keyword: "#include",
            field: "",
            phrases: &["#include cycle", "a.inc -> ", "b.inc -> "],
        },
    );
    assert!(msg.matches("a.inc").count() >= 2, "{msg}");
}

#[test]
fn end_missing() {
    let c = Case::new("end-missing");
    let mut d = base_deck();
    d.pop();
    let last = d.len();
    let out = c.check(&d);
    assert_error(
        &out,
        Expect {
            file: DECK,
            line: last,
            keyword: "/END",
            field: "",
            phrases: &["without /END", "expected /END"],
        },
    );
}

// ---------------------------------------------------------------------------
// Numbers
// ---------------------------------------------------------------------------

fn bad_x(test: &str, x: &str, phrases: &[&str]) {
    let c = Case::new(test);
    let mut d = base_deck();
    let n = replace(&mut d, &node(2, "1", "0", "0"), node(2, x, "0", "0"));
    let out = c.check(&d);
    let msg = assert_error(
        &out,
        Expect {
            file: DECK,
            line: n,
            keyword: "/NODE",
            field: "X",
            phrases,
        },
    );
    assert!(
        msg.contains(&format!("'{x}'")),
        "the bad text is quoted: {msg}"
    );
    assert!(
        msg.contains("columns 11-30"),
        "the columns are named: {msg}"
    );
}

#[test]
fn non_numeric_real() {
    bad_x("abc", "abc", &["expected a real number"]);
}

#[test]
fn nan_real() {
    bad_x("nan", "NaN", &["expected a finite real number"]);
}

#[test]
fn infinite_real_word() {
    bad_x("inf", "Inf", &["expected a finite real number"]);
    bad_x(
        "minus-infinity",
        "-Infinity",
        &["expected a finite real number"],
    );
}

#[test]
fn infinite_real_overflow() {
    bad_x("1e999", "1e999", &["out of range", "infinity"]);
}

#[test]
fn integer_field_holding_a_real() {
    let c = Case::new("int-real");
    let mut d = base_deck();
    let n = replace(&mut d, &node(3, "1", "1", "0"), node("1.5", "1", "1", "0"));
    let out = c.check(&d);
    assert_error(
        &out,
        Expect {
            file: DECK,
            line: n,
            keyword: "/NODE",
            field: "node_ID",
            phrases: &["'1.5'", "columns 1-10", "expected an integer"],
        },
    );
}

#[test]
fn integer_field_holding_a_real_in_a_property() {
    let c = Case::new("int-real-prop");
    let mut d = base_deck();
    let n = replace(
        &mut d,
        &prop_thick_line(),
        i10("1.5") + &i10(0) + &r20("0.001"),
    );
    let out = c.check(&d);
    assert_error(
        &out,
        Expect {
            file: DECK,
            line: n,
            keyword: "/PROP/TYPE1/1",
            field: "N",
            phrases: &["'1.5'", "expected an integer"],
        },
    );
}

// ---------------------------------------------------------------------------
// Physical values
// ---------------------------------------------------------------------------

fn bad_value(test: &str, old: String, new: String, keyword: &str, field: &str, phrases: &[&str]) {
    let c = Case::new(test);
    let mut d = base_deck();
    let n = replace(&mut d, &old, new);
    let out = c.check(&d);
    assert_error(
        &out,
        Expect {
            file: DECK,
            line: n,
            keyword,
            field,
            phrases,
        },
    );
}

#[test]
fn negative_density() {
    bad_value(
        "rho-neg",
        rho_line(),
        r20("-7800.0"),
        "/MAT/LAW1/1",
        "RHO_I",
        &["-7800", "density must be > 0"],
    );
}

#[test]
fn zero_density() {
    bad_value(
        "rho-zero",
        rho_line(),
        r20("0.0"),
        "/MAT/LAW1/1",
        "RHO_I",
        &["density must be > 0"],
    );
}

#[test]
fn blank_density() {
    bad_value(
        "rho-blank",
        rho_line(),
        s(""),
        "/MAT/LAW1/1",
        "RHO_I",
        &["density must be > 0"],
    );
}

#[test]
fn negative_thickness() {
    bad_value(
        "thick-neg",
        prop_thick_line(),
        i10(3) + &i10(0) + &r20("-0.001"),
        "/PROP/TYPE1/1",
        "Thick",
        &["-0.001", "thickness must be > 0"],
    );
}

#[test]
fn zero_thickness() {
    bad_value(
        "thick-zero",
        prop_thick_line(),
        i10(3) + &i10(0) + &r20("0"),
        "/PROP/TYPE1/1",
        "Thick",
        &["thickness must be > 0"],
    );
}

#[test]
fn negative_element_thickness() {
    bad_value(
        "thick-elem-neg",
        shell_line(),
        shell_line() + &r20(0) + &r20("-0.002"),
        "/SHELL/1",
        "Thick",
        &["-0.002", "thickness must be >= 0"],
    );
}

#[test]
fn zero_young_modulus() {
    bad_value(
        "e-zero",
        e_nu_line(),
        r20("0") + &r20("0.3"),
        "/MAT/LAW1/1",
        "E",
        &["young's modulus must be > 0"],
    );
}

#[test]
fn negative_young_modulus() {
    bad_value(
        "e-neg",
        e_nu_line(),
        r20("-2.1E+11") + &r20("0.3"),
        "/MAT/LAW1/1",
        "E",
        &["-210000000000", "young's modulus must be > 0"],
    );
}

#[test]
fn poisson_ratio_out_of_range() {
    bad_value(
        "nu",
        e_nu_line(),
        r20("2.1E+11") + &r20("0.7"),
        "/MAT/LAW1/1",
        "Nu",
        &["0.7", "(-1, 0.5]"],
    );
}

// ---------------------------------------------------------------------------
// References between cards
// ---------------------------------------------------------------------------

#[test]
fn element_names_unknown_node() {
    bad_value(
        "elem-node",
        shell_line(),
        i10(1) + &i10(1) + &i10(2) + &i10(3) + &i10(99),
        "/SHELL/1",
        "node_ID4",
        &["element 1", "node 99 is not defined"],
    );
}

#[test]
fn element_names_unknown_part() {
    let c = Case::new("elem-part");
    let mut d = base_deck();
    replace(&mut d, "/SHELL/1", s("/SHELL/7"));
    let n = line_no(&d, &shell_line());
    let out = c.check(&d);
    assert_error(
        &out,
        Expect {
            file: DECK,
            line: n,
            keyword: "/SHELL/7",
            field: "part_ID",
            phrases: &["part 7 is not defined"],
        },
    );
}

#[test]
fn duplicate_node_id() {
    let c = Case::new("dup-node");
    let mut d = base_deck();
    let first = line_no(&d, &node(3, "1", "1", "0"));
    let n = replace(&mut d, &node(4, "0", "1", "0"), node(3, "0", "1", "0"));
    let out = c.check(&d);
    let msg = assert_error(
        &out,
        Expect {
            file: DECK,
            line: n,
            keyword: "/NODE",
            field: "",
            phrases: &["duplicate node id 3", "ids must be unique"],
        },
    );
    assert!(
        msg.contains(&format!("first defined at {}", c.path(DECK).display()))
            && msg.contains(&format!(":{first})")),
        "the first definition is named: {msg}"
    );
}

#[test]
fn part_names_unknown_property() {
    bad_value(
        "part-prop",
        part_line(),
        i10(9) + &i10(1) + &i10(0),
        "/PART/1",
        "prop_ID",
        &["property 9 is not defined"],
    );
}

#[test]
fn part_names_unknown_material() {
    bad_value(
        "part-mat",
        part_line(),
        i10(1) + &i10(8) + &i10(0),
        "/PART/1",
        "mat_ID",
        &["material 8 is not defined"],
    );
}

#[test]
fn part_names_unsupported_material() {
    // A material the reader skips (unsupported law) is named as such.
    let c = Case::new("part-mat-unsupported");
    let mut d = base_deck();
    let n = replace(&mut d, &part_line(), i10(1) + &i10(8) + &i10(0));
    before_end(&mut d, &[s("/MAT/LAW25/8"), s("brittle"), r20("7800.0")]);
    let out = c.check(&d);
    assert_error(
        &out,
        Expect {
            file: DECK,
            line: n,
            keyword: "/PART/1",
            field: "mat_ID",
            phrases: &["material 8 is not defined", "/MAT/LAW25/8", "not supported"],
        },
    );
}

#[test]
fn node_group_names_unknown_node() {
    let c = Case::new("grnod-node");
    let mut d = base_deck();
    let n = before_end(
        &mut d,
        &[
            s("/GRNOD/NODE/3"),
            s("some nodes"),
            i10(1) + &i10(2) + &i10(3),
            i10(4) + &i10(77),
        ],
    );
    let out = c.check(&d);
    assert_error(
        &out,
        Expect {
            file: DECK,
            line: n + 3,
            keyword: "/GRNOD/NODE/3",
            field: "node_ID",
            phrases: &["node 77 is not defined"],
        },
    );
}

#[test]
fn grnod_grnod_names_unknown_group() {
    let c = Case::new("grnod-grnod");
    let mut d = base_deck();
    let n = before_end(
        &mut d,
        &[
            s("/GRNOD/NODE/3"),
            s("some nodes"),
            i10(1) + &i10(2),
            s("/GRNOD/GRNOD/4"),
            s("union"),
            i10(3) + &i10(12),
        ],
    );
    let out = c.check(&d);
    assert_error(
        &out,
        Expect {
            file: DECK,
            line: n + 5,
            keyword: "/GRNOD/GRNOD/4",
            field: "grnd_ID",
            phrases: &["node group 12 is not defined"],
        },
    );
}

#[test]
fn surface_names_unknown_part() {
    let c = Case::new("surf-part");
    let mut d = base_deck();
    let mut extra = surf_part(5, 1);
    extra.push(i10(-42));
    let n = before_end(&mut d, &extra);
    let out = c.check(&d);
    assert_error(
        &out,
        Expect {
            file: DECK,
            line: n + 3,
            keyword: "/SURF/PART/5",
            field: "part_ID",
            phrases: &["part 42 is not defined"],
        },
    );
}

#[test]
fn interface_names_unknown_surface() {
    let c = Case::new("inter-surf");
    let mut d = base_deck();
    let mut extra = vec![s("/GRNOD/NODE/6"), s("nodes"), i10(1) + &i10(2)];
    extra.extend(inter_type7(10, 6, 55));
    let n = before_end(&mut d, &extra);
    let out = c.check(&d);
    assert_error(
        &out,
        Expect {
            file: DECK,
            line: n + 5,
            keyword: "/INTER/TYPE7/10",
            field: "surf_IDm",
            phrases: &["surface 55 is not defined"],
        },
    );
}

#[test]
fn interface_names_unknown_node_group() {
    let c = Case::new("inter-grnod");
    let mut d = base_deck();
    let mut extra = surf_part(5, 1);
    extra.extend(inter_type7(10, 66, 5));
    let n = before_end(&mut d, &extra);
    let out = c.check(&d);
    assert_error(
        &out,
        Expect {
            file: DECK,
            line: n + 5,
            keyword: "/INTER/TYPE7/10",
            field: "grnd_IDs",
            phrases: &["node group 66 is not defined"],
        },
    );
}

#[test]
fn empty_surface_of_part_without_shells() {
    let c = Case::new("surf-empty-part");
    let mut d = base_deck();
    let mut extra = vec![s("/PART/2"), s("empty part"), i10(1) + &i10(1)];
    extra.extend(surf_part(5, 2));
    let n = before_end(&mut d, &extra);
    let out = c.check(&d);
    assert_error(
        &out,
        Expect {
            file: DECK,
            line: n + 3,
            keyword: "/SURF/PART/5",
            field: "",
            phrases: &["no segments", "expected at least one"],
        },
    );
}

#[test]
fn empty_surface_seg_without_lines() {
    let c = Case::new("surf-empty-seg");
    let mut d = base_deck();
    let n = before_end(&mut d, &[s("/SURF/SEG/5"), s("no segments")]);
    let out = c.check(&d);
    assert_error(
        &out,
        Expect {
            file: DECK,
            line: n,
            keyword: "/SURF/SEG/5",
            field: "",
            phrases: &["no segments", "expected at least one"],
        },
    );
}

// ---------------------------------------------------------------------------
// Damaged text
// ---------------------------------------------------------------------------

#[test]
fn truncated_card_at_end_of_file() {
    // /MAT/PLAS_JOHNS with its title and 2 of its cards, then EOF (no /END):
    // the missing card is what is reported, not the missing /END.
    let c = Case::new("truncated");
    let mut d = base_deck();
    d.pop(); // /END
    d.extend([
        s("/MAT/PLAS_JOHNS/2"),
        s("johnson-cook"),
        r20("7800.0"),
        r20("2.1E+11") + &r20("0.3") + &i10(0),
    ]);
    let last = d.len();
    let out = c.check(&d);
    let msg = assert_error(
        &out,
        Expect {
            file: DECK,
            line: last,
            keyword: "/MAT/PLAS_JOHNS/2",
            field: "",
            phrases: &[
                "card missing",
                "expected the card with a, b, n",
                "truncated",
            ],
        },
    );
    assert!(!msg.contains("/END"), "the truncated card, not /END: {msg}");
}

#[test]
fn truncated_card_then_next_keyword() {
    // A block cut short before the next keyword.
    let c = Case::new("truncated-mid");
    let mut d = base_deck();
    let n = before_end(
        &mut d,
        &[s("/MAT/PLAS_JOHNS/2"), s("johnson-cook"), r20("7800.0")],
    );
    let out = c.check(&d);
    assert_error(
        &out,
        Expect {
            file: DECK,
            line: n + 2,
            keyword: "/MAT/PLAS_JOHNS/2",
            field: "",
            phrases: &["card missing", "expected the card with E"],
        },
    );
}

#[test]
fn binary_garbage_in_node_block() {
    let c = Case::new("binary");
    let d = base_deck();
    let n = line_no(&d, &node(3, "1", "1", "0"));
    let mut bytes = Vec::new();
    for (i, l) in d.iter().enumerate() {
        if i + 1 == n {
            bytes.extend_from_slice(b"         3\x00\x01\x02garbage\x1b[0m\x07\x1f\x10  1.0");
        } else {
            bytes.extend_from_slice(l.as_bytes());
        }
        bytes.push(b'\n');
    }
    let p = c.write(DECK, &bytes);
    let out = c.run(&["check", p.to_str().unwrap()]);
    assert_error(
        &out,
        Expect {
            file: DECK,
            line: n,
            keyword: "/NODE",
            field: "",
            phrases: &["binary data", "byte 0x00 at column 11", "expected text"],
        },
    );
}

#[test]
fn ten_megabyte_line() {
    let c = Case::new("long-line");
    let d = base_deck();
    let n = line_no(&d, &node(3, "1", "1", "0"));
    let mut bytes = Vec::new();
    for (i, l) in d.iter().enumerate() {
        if i + 1 == n {
            bytes.extend_from_slice(l.as_bytes());
            bytes.extend(std::iter::repeat_n(b'7', 10 << 20));
        } else {
            bytes.extend_from_slice(l.as_bytes());
        }
        bytes.push(b'\n');
    }
    let p = c.write(DECK, &bytes);
    let out = c.run(&["check", p.to_str().unwrap()]);
    let msg = assert_error(
        &out,
        Expect {
            file: DECK,
            line: n,
            keyword: "/NODE",
            field: "",
            phrases: &["bytes long", "at most 100 columns"],
        },
    );
    assert!(
        msg.len() < 1000,
        "the line is not echoed: {} bytes",
        msg.len()
    );
}

#[test]
fn tab_in_data_line() {
    let c = Case::new("tab");
    let mut d = base_deck();
    let n = replace(&mut d, &node(2, "1", "0", "0"), s("2\t1.0\t0\t0"));
    let out = c.check(&d);
    assert_error(
        &out,
        Expect {
            file: DECK,
            line: n,
            keyword: "/NODE",
            field: "",
            phrases: &["tab character at column 2", "use spaces"],
        },
    );
}

// ---------------------------------------------------------------------------
// Unsupported keywords, /TITLE surplus lines
// ---------------------------------------------------------------------------

fn with_unsupported() -> (Vec<String>, usize) {
    let mut d = base_deck();
    let n = before_end(
        &mut d,
        &[s("/MONVOL/AIRBAG1/3"), s("bag"), i10(1) + &i10(2)],
    );
    (d, n)
}

#[test]
fn unsupported_keyword_strict_is_an_error() {
    let c = Case::new("strict");
    let (d, n) = with_unsupported();
    let p = c.write_lines(DECK, &d);
    let out = c.run(&["check", "--strict", p.to_str().unwrap()]);
    assert_error(
        &out,
        Expect {
            file: DECK,
            line: n,
            keyword: "/MONVOL/AIRBAG1/3",
            field: "",
            phrases: &["not supported", "--strict"],
        },
    );
}

#[test]
fn unsupported_keyword_is_a_warning() {
    let c = Case::new("unsupported");
    let (d, n) = with_unsupported();
    let out = c.check(&d);
    let stdout = assert_ok(&out);
    assert!(stdout.contains("warnings          1"), "{stdout}");
    let w = format!("{DECK}:{n}: warning: /MONVOL/AIRBAG1/3: keyword not supported");
    assert!(stdout.contains(&w), "expected '{w}' in: {stdout}");
}

#[test]
fn unsupported_keyword_json_lists_the_warning() {
    let c = Case::new("unsupported-json");
    let (d, n) = with_unsupported();
    let p = c.write_lines(DECK, &d);
    let out = c.run(&["check", p.to_str().unwrap(), "--json"]);
    let v: serde_json::Value = serde_json::from_str(&assert_ok(&out)).expect("JSON on stdout");
    let w = v["warnings"].as_array().expect("a warnings list");
    assert_eq!(w.len(), 1, "{w:?}");
    let w = w[0].as_str().expect("a warning is a string");
    assert!(
        w.contains(&format!("{DECK}:{n}: warning: /MONVOL/AIRBAG1/3")),
        "{w}"
    );
    assert!(w.contains("not supported"), "{w}");
    assert_eq!(v["shells4"], 1);
}

#[test]
fn title_surplus_lines_are_a_warning() {
    // An included file's /TITLE followed by Copyright> lines: one warning.
    let c = Case::new("title-surplus");
    c.write(
        "title.inc",
        b"/TITLE\nIncluded title\nCopyright> 2026 Someone\nCopyright> all rights reserved\n\n",
    );
    let mut d = base_deck();
    let t = line_no(&d, "/TITLE");
    d.drain(t - 1..t + 1);
    d.insert(t - 1, s("#include title.inc"));
    let p = c.write_lines(DECK, &d);
    let out = c.run(&["check", p.to_str().unwrap(), "--json"]);
    let v: serde_json::Value = serde_json::from_str(&assert_ok(&out)).expect("JSON");
    assert_eq!(v["title"], "Included title");
    let w = v["warnings"].as_array().expect("warnings");
    assert_eq!(w.len(), 1, "one warning: {w:?}");
    let w = w[0].as_str().unwrap();
    assert!(w.contains("title.inc:3: warning: /TITLE"), "{w}");
    assert!(w.contains("2 line(s)") && w.contains("ignored"), "{w}");
}

#[test]
fn part_surplus_lines_are_a_warning() {
    let c = Case::new("part-surplus");
    let mut d = base_deck();
    let n = line_no(&d, &part_line()) + 1;
    d.insert(n - 1, i10(2) + &i10(2) + &i10(0));
    let p = c.write_lines(DECK, &d);
    let out = c.run(&["check", p.to_str().unwrap(), "--json"]);
    let v: serde_json::Value = serde_json::from_str(&assert_ok(&out)).expect("JSON");
    let w = v["warnings"].as_array().expect("warnings");
    assert_eq!(w.len(), 1, "one warning: {w:?}");
    let w = w[0].as_str().unwrap();
    assert!(w.contains(&format!("{DECK}:{n}: warning: /PART/1")), "{w}");
    assert!(w.contains("1 line(s)") && w.contains("ignored"), "{w}");
}

// ---------------------------------------------------------------------------
// Command line
// ---------------------------------------------------------------------------

#[test]
fn partition_np_zero() {
    let c = Case::new("np0");
    let p = c.write_lines(DECK, &base_deck());
    let out = c.run(&["partition", "--np", "0", p.to_str().unwrap()]);
    let stderr = text(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(out.stdout.is_empty());
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert!(stderr.contains("--np"), "names the argument: {stderr}");
    assert!(stderr.contains("0"), "names the value: {stderr}");
}

#[test]
fn check_without_deck_argument() {
    let c = Case::new("noarg");
    let out = c.run(&["check"]);
    let stderr = text(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(out.stdout.is_empty());
    assert!(
        stderr.contains("DECK") || stderr.contains("<DECK>"),
        "{stderr}"
    );
}

#[test]
fn unknown_option() {
    let c = Case::new("unknown-opt");
    let p = c.write_lines(DECK, &base_deck());
    let out = c.run(&["check", "--frobnicate", p.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    assert!(text(&out.stderr).contains("--frobnicate"));
}

#[test]
fn deck_is_a_directory() {
    let c = Case::new("dir");
    std::fs::create_dir_all(c.path("sub_0000.rad")).unwrap();
    let p = c.path("sub_0000.rad");
    let out = c.run(&["check", p.to_str().unwrap()]);
    assert_error(
        &out,
        Expect {
            file: "sub_0000.rad",
            line: 0,
            keyword: "",
            field: "",
            phrases: &["is a directory", "expected a deck file"],
        },
    );
}

// ---------------------------------------------------------------------------
// /LINE (edge-to-edge sides)
// ---------------------------------------------------------------------------

/// /INTER/TYPE11 with line_IDs and line_IDm (format 2020+, other fields default).
fn inter_type11(id: u64, line_s: u64, line_m: u64) -> Vec<String> {
    vec![
        format!("/INTER/TYPE11/{id}"),
        s("edges"),
        i10(line_s) + &i10(line_m) + &i10(0) + &i10(0) + &i10(0) + &i10(0) + &i10(0) + &i10(0),
        r20(0) + &r20(0) + &r20(0) + &r20(0) + &i10(0) + &i10(0),
        r20(0) + &r20(0) + &r20(0) + &r20(0) + &r20(0),
        i10("000") + &" ".repeat(20) + &i10(0) + &r20(0) + &r20(0) + &r20(0),
        i10(0),
    ]
}

#[test]
fn line_segment_with_unknown_node() {
    let c = Case::new("line-node");
    let mut d = base_deck();
    let at = before_end(
        &mut d,
        &[s("/LINE/SEG/3"), s("edge"), i10(1) + &i10(1) + &i10(99)],
    );
    assert_error(
        &c.check(&d),
        Expect {
            file: DECK,
            line: at + 2,
            keyword: "/LINE/SEG/3",
            field: "node_ID2",
            phrases: &["node 99 is not defined"],
        },
    );
}

#[test]
fn line_segment_with_one_node_twice() {
    let c = Case::new("line-same");
    let mut d = base_deck();
    let at = before_end(
        &mut d,
        &[s("/LINE/SEG/3"), s("edge"), i10(1) + &i10(2) + &i10(2)],
    );
    assert_error(
        &c.check(&d),
        Expect {
            file: DECK,
            line: at + 2,
            keyword: "/LINE/SEG/3",
            field: "node_ID2",
            phrases: &["two nodes are the same", "expected two different nodes"],
        },
    );
}

#[test]
fn line_of_an_unknown_surface() {
    let c = Case::new("line-surf");
    let mut d = base_deck();
    let at = before_end(&mut d, &[s("/LINE/EDGE/3"), s("edges"), i10(8)]);
    assert_error(
        &c.check(&d),
        Expect {
            file: DECK,
            line: at + 2,
            keyword: "/LINE/EDGE/3",
            field: "surf_ID",
            phrases: &["surface 8 is not defined"],
        },
    );
}

#[test]
fn edge_interface_naming_an_unknown_line() {
    let c = Case::new("t11-line");
    let mut d = base_deck();
    let mut extra = vec![s("/LINE/SEG/3"), s("edge"), i10(1) + &i10(1) + &i10(2)];
    extra.extend(inter_type11(4, 3, 7));
    let at = before_end(&mut d, &extra);
    assert_error(
        &c.check(&d),
        Expect {
            file: DECK,
            line: at + 5,
            keyword: "/INTER/TYPE11/4",
            field: "line_IDm",
            phrases: &["line 7 is not defined"],
        },
    );
}

#[test]
fn surface_edges_resolve_to_the_free_edges() {
    // /LINE/EDGE of the one-shell surface: its four edges; /LINE/SURF too.
    let c = Case::new("line-ok");
    let mut d = base_deck();
    let mut extra = surf_part(5, 1);
    extra.extend([s("/LINE/EDGE/3"), s("edges"), i10(5)]);
    extra.extend(inter_type11(4, 3, 0));
    before_end(&mut d, &extra);
    let p = c.write_lines(DECK, &d);
    let out = c.run(&["check", p.to_str().unwrap(), "--json"]);
    let v: serde_json::Value = serde_json::from_str(&assert_ok(&out)).expect("JSON");
    let i = &v["interfaces"][0];
    assert_eq!(
        (
            i["type"].as_u64(),
            i["secondary_edges"].as_u64(),
            i["main_edges"].as_u64()
        ),
        (Some(11), Some(4), Some(4)),
        "{v}"
    );
    let text = assert_ok(&c.check(&d));
    assert!(
        text.contains("TYPE11  secondary edges        4  main edges           4"),
        "{text}"
    );
}

#[test]
fn node_group_of_a_surface_holds_its_nodes() {
    let c = Case::new("grnod-surf");
    let mut d = base_deck();
    let mut extra = surf_part(5, 1);
    extra.extend([s("/GRNOD/SURF/6"), s("surface nodes"), i10(5)]);
    extra.extend(inter_type7(10, 6, 5));
    before_end(&mut d, &extra);
    let p = c.write_lines(DECK, &d);
    let out = c.run(&["check", p.to_str().unwrap(), "--json"]);
    let v: serde_json::Value = serde_json::from_str(&assert_ok(&out)).expect("JSON");
    assert_eq!(v["interfaces"][0]["secondary_nodes"], 4, "{v}");
}

#[test]
fn node_group_of_a_shell_group_holds_its_shells_nodes() {
    let c = Case::new("grnod-grshel");
    let mut d = base_deck();
    let mut extra = surf_part(5, 1);
    extra.extend([s("/GRSHEL/SHEL/3"), s("shells"), i10(1)]);
    extra.extend([s("/GRNOD/GRSHEL/6"), s("shell nodes"), i10(3)]);
    extra.extend(inter_type7(10, 6, 5));
    before_end(&mut d, &extra);
    let p = c.write_lines(DECK, &d);
    let out = c.run(&["check", p.to_str().unwrap(), "--json"]);
    let v: serde_json::Value = serde_json::from_str(&assert_ok(&out)).expect("JSON");
    assert_eq!(v["interfaces"][0]["secondary_nodes"], 4, "{v}");
}

#[test]
fn node_group_of_an_unknown_surface() {
    let c = Case::new("grnod-surf-bad");
    let mut d = base_deck();
    let at = before_end(&mut d, &[s("/GRNOD/SURF/6"), s("surface nodes"), i10(5)]);
    assert_error(
        &c.check(&d),
        Expect {
            file: DECK,
            line: at + 2,
            keyword: "/GRNOD/SURF/6",
            field: "surf_ID",
            phrases: &["surface 5 is not defined"],
        },
    );
}

#[test]
fn failure_card_names_unknown_material_and_bad_flags() {
    // /FAIL/JOHNSON on a material the deck does not define: error at the card.
    let c = Case::new("fail-jc-mat");
    let mut d = base_deck();
    let n = before_end(
        &mut d,
        &[
            s("/FAIL/JOHNSON/9"),
            r20("0.1") + &r20("0.1") + &r20("-0.1"),
            r20("0") + &i10(1) + &i10(1),
        ],
    );
    assert_error(
        &c.check(&d),
        Expect {
            file: DECK,
            line: n,
            keyword: "/FAIL/JOHNSON",
            field: "mat_ID",
            phrases: &["material 9 is not defined"],
        },
    );
    // Ifail_so outside 0-4: error at its line, naming the field.
    let c = Case::new("fail-jc-ifail");
    let mut d = base_deck();
    let n = before_end(
        &mut d,
        &[
            s("/FAIL/JOHNSON/1"),
            r20("0.1") + &r20("0.1") + &r20("-0.1"),
            r20("0") + &i10(1) + &i10(7),
        ],
    );
    assert_error(
        &c.check(&d),
        Expect {
            file: DECK,
            line: n + 2,
            keyword: "/FAIL/JOHNSON/1",
            field: "Ifail_so",
            phrases: &["7: expected one of"],
        },
    );
}

#[test]
fn law36_names_an_undefined_curve_and_bad_rates() {
    let law36 = |rates: &str| {
        vec![
            s("/MAT/LAW36/1"),
            s("tabulated"),
            r20("7.8e-6"),
            r20("210") + &r20("0.3"),
            i10(2) + &i10(0),
            i10(0),
            i10(77) + &i10(77),
            r20("1") + &r20("1"),
            rates.to_string(),
        ]
    };
    // The material card replaces the deck's /MAT/LAW1/1.
    let c = Case::new("law36-fct");
    let mut d = base_deck();
    let at = line_no(&d, "/MAT/LAW1/1") - 1;
    d.drain(at..at + 6);
    for (k, l) in law36(&(r20("0") + &r20("100"))).into_iter().enumerate() {
        d.insert(at + k, l);
    }
    assert_error(
        &c.check(&d),
        Expect {
            file: DECK,
            line: at + 1,
            keyword: "/MAT/LAW36/1",
            field: "func_ID",
            phrases: &["function 77 is not defined"],
        },
    );
    let c = Case::new("law36-rates");
    let mut d = base_deck();
    d.drain(at..at + 6);
    for (k, l) in law36(&(r20("100") + &r20("10"))).into_iter().enumerate() {
        d.insert(at + k, l);
    }
    assert_error(
        &c.check(&d),
        Expect {
            file: DECK,
            line: at + 9,
            keyword: "/MAT/LAW36/1",
            field: "Eps_dot_2",
            phrases: &["must increase strictly"],
        },
    );
}

/// Spring hardening flags name the curves they need; a /DAMP gives one line
/// of coefficients or six.
#[test]
fn spring_hardening_and_damp_coefficients_are_checked_at_their_card() {
    let c = Case::new("spring-h4");
    let mut d = base_deck();
    let at = line_no(&d, "/PART/1") - 1;
    let spring = [
        s("/PROP/SPRING/9"),
        s("spring"),
        r20("1.0"),
        r20("100.0"),
        i10(5) + &i10(4),
    ];
    for (k, l) in spring.into_iter().enumerate() {
        d.insert(at + k, l);
    }
    d.extend([
        s("/FUNCT/5"),
        s("curve"),
        r20(0) + &r20(0),
        r20(1) + &r20(1),
    ]);
    assert_error(
        &c.check(&d),
        Expect {
            file: DECK,
            line: at + 5,
            keyword: "/PROP/SPRING/9",
            field: "H",
            phrases: &["H = 4", "fct_ID3"],
        },
    );
    let c = Case::new("damp-lines");
    let mut d = base_deck();
    let at = line_no(&d, "/PART/1") - 1;
    let damp = [
        s("/DAMP/3"),
        s("damping"),
        r20("1.0") + &r20("0.0") + &i10(0),
        r20("1.0") + &r20("0.0"),
    ];
    for (k, l) in damp.into_iter().enumerate() {
        d.insert(at + k, l);
    }
    assert_error(
        &c.check(&d),
        Expect {
            file: DECK,
            line: at + 3,
            keyword: "/DAMP/3",
            field: "alpha",
            phrases: &["2 lines", "expected 1"],
        },
    );
}

/// /FAIL/TAB names what it needs: at least one failure-strain function
/// (N_rate), and functions the deck defines.
#[test]
fn fail_tab_rates_and_functions_are_checked_at_their_card() {
    let c = Case::new("fail-tab-nrate");
    let mut d = base_deck();
    let at = line_no(&d, "/PART/1") - 1;
    let card = [
        s("/FAIL/TAB/1"),
        i10(1) + &i10(1) + &i10(0),
        r20("1.0") + &r20("0.0") + &r20("1.0"),
    ];
    for (k, l) in card.into_iter().enumerate() {
        d.insert(at + k, l);
    }
    assert_error(
        &c.check(&d),
        Expect {
            file: DECK,
            line: at + 2,
            keyword: "/FAIL/TAB/1",
            field: "N_rate",
            phrases: &["N_rate >= 1"],
        },
    );
    let c = Case::new("fail-tab-fct");
    let mut d = base_deck();
    let at = line_no(&d, "/PART/1") - 1;
    let card = [
        s("/FAIL/TAB/1"),
        i10(1) + &i10(1) + &i10(1),
        r20("1.0") + &r20("0.0") + &r20("1.0"),
        i10(77) + &r20("1.0") + &r20("0.0"),
    ];
    for (k, l) in card.into_iter().enumerate() {
        d.insert(at + k, l);
    }
    assert_error(
        &c.check(&d),
        Expect {
            file: DECK,
            line: at + 1,
            keyword: "/FAIL/TAB/1",
            field: "fct_ID",
            phrases: &["function 77", "/FUNCT"],
        },
    );
}

/// A moving skew names three nodes that span a frame; an unknown Dir is
/// named.
#[test]
fn moving_skews_need_three_independent_nodes_and_a_known_axis() {
    let c = Case::new("skew-aligned");
    let mut d = base_deck();
    let at = line_no(&d, "/PART/1") - 1;
    let skew = [
        s("/SKEW/MOV/4"),
        s("moving frame"),
        i10(1) + &i10(1) + &i10(2),
    ];
    for (k, l) in skew.into_iter().enumerate() {
        d.insert(at + k, l);
    }
    assert_error(
        &c.check(&d),
        Expect {
            file: DECK,
            line: at + 1,
            keyword: "/SKEW/MOV/4",
            field: "axes",
            phrases: &["degenerate", "three independent directions"],
        },
    );
    let c = Case::new("skew-dir");
    let mut d = base_deck();
    let at = line_no(&d, "/PART/1") - 1;
    let skew = [
        s("/SKEW/MOV/4"),
        s("moving frame"),
        i10(1) + &i10(2) + &i10(3) + "         W",
    ];
    for (k, l) in skew.into_iter().enumerate() {
        d.insert(at + k, l);
    }
    assert_error(
        &c.check(&d),
        Expect {
            file: DECK,
            line: at + 3,
            keyword: "/SKEW/MOV/4",
            field: "Dir",
            phrases: &["'W'", "X, Y or Z"],
        },
    );
}

/// /MAT/LAW21 names its pressure curve and a positive tension modulus.
#[test]
fn drucker_prager_needs_its_pressure_curve_and_kt() {
    let c = Case::new("law21-kt");
    let mut d = base_deck();
    let at = line_no(&d, "/PART/1") - 1;
    let card = [
        s("/MAT/LAW21/7"),
        s("rock"),
        r20("2000.0"),
        r20("1e10") + &r20("0.2"),
        r20("0") + &r20("0") + &r20("3"),
        i10(5) + &i10(0) + &r20("0"),
        r20("0"),
    ];
    for (k, l) in card.into_iter().enumerate() {
        d.insert(at + k, l);
    }
    assert_error(
        &c.check(&d),
        Expect {
            file: DECK,
            line: at + 6,
            keyword: "/MAT/LAW21/7",
            field: "Kt",
            phrases: &["tension bulk modulus", "> 0"],
        },
    );
}

/// /MOVE_FUNCT names a function the deck defines; /IMPDISP/FGEO gives each
/// node one final position.
#[test]
fn move_funct_and_final_geometry_are_checked_at_their_cards() {
    let c = Case::new("move-funct");
    let mut d = base_deck();
    let at = line_no(&d, "/PART/1") - 1;
    let card = [s("/MOVE_FUNCT/77"), s("shift"), r20("2.0")];
    for (k, l) in card.into_iter().enumerate() {
        d.insert(at + k, l);
    }
    assert_error(
        &c.check(&d),
        Expect {
            file: DECK,
            line: at + 1,
            keyword: "/MOVE_FUNCT/77",
            field: "fct_ID",
            phrases: &["function 77", "/FUNCT"],
        },
    );
    let c = Case::new("fgeo-twice");
    let mut d = base_deck();
    let at = line_no(&d, "/PART/1") - 1;
    let card = [
        s("/FUNCT/5"),
        s("ramp"),
        r20("0") + &r20("0"),
        r20("1") + &r20("1"),
        s("/IMPDISP/FGEO/3"),
        s("to the end"),
        i10(5),
        r20("1.0"),
        i10(2) + &r20("2.0") + &r20("0.0") + &r20("0.0"),
        i10(2) + &r20("3.0") + &r20("0.0") + &r20("0.0"),
    ];
    for (k, l) in card.into_iter().enumerate() {
        d.insert(at + k, l);
    }
    assert_error(
        &c.check(&d),
        Expect {
            file: DECK,
            line: at + 10,
            keyword: "/IMPDISP/FGEO/3",
            field: "node_ID",
            phrases: &["node 2", "already has a final position"],
        },
    );
}

/// /PROP/KJOINT2: the joint type and the critical damping factor are
/// checked at their card.
#[test]
fn kjoint2_type_and_damping_are_checked_at_their_card() {
    for (tag, ty, cr, field, phrases) in [
        ("kjoint2-cr", 1, "1.5", "Cr", &["1.5", "[0, 1]"][..]),
        ("kjoint2-type", 12, "0.1", "Type", &["12", "1 to 9"][..]),
    ] {
        let c = Case::new(tag);
        let mut d = base_deck();
        let at = line_no(&d, "/PART/1") - 1;
        let joint = [
            s("/PROP/KJOINT2/9"),
            s("joint"),
            i10(ty) + &r20("0.0") + &r20("0.0") + &r20(cr),
        ];
        for (k, l) in joint.into_iter().enumerate() {
            d.insert(at + k, l);
        }
        assert_error(
            &c.check(&d),
            Expect {
                file: DECK,
                line: at + 3,
                keyword: "/PROP/KJOINT2/9",
                field,
                phrases,
            },
        );
    }
}

/// /MAT/LAW70: the number of loading curves and the order of their strain
/// rates are checked at their card.
#[test]
fn law70_curves_are_checked_at_their_card() {
    let curve = |rate: &str| i10(1) + &r20(rate) + &r20("1.0");
    for (tag, nl, rates, line, field, phrases) in [
        ("law70-nl", 0, &[][..], 5, "NL", &["0", "1 to 100"][..]),
        (
            "law70-rates",
            2,
            &["0.1", "0.1"][..],
            7,
            "strain rate",
            &["0.1", "must increase"][..],
        ),
    ] {
        let c = Case::new(tag);
        let mut d = base_deck();
        let at = line_no(&d, "/PART/1") - 1;
        let mut card = vec![
            s("/MAT/LAW70/9"),
            s("foam"),
            r20("5e-8"),
            r20("0.01") + &r20("0") + &r20("10") + &r20("0.8"),
            r20("0") + &i10(0) + &i10(nl) + &i10(0) + &i10(4),
        ];
        card.extend(rates.iter().map(|r| curve(r)));
        for (k, l) in card.into_iter().enumerate() {
            d.insert(at + k, l);
        }
        assert_error(
            &c.check(&d),
            Expect {
                file: DECK,
                line: at + line,
                keyword: "/MAT/LAW70/9",
                field,
                phrases,
            },
        );
    }
}
