//! Deck syntax that Radioss accepts and the reader must too (issue 13, item 4):
//! tabs as trailing white space (starter) or separators (engine), /SURF/PART/ALL
//! and /SURF/PART/EXT, a node numbered 0, a /TH object list followed by lines
//! that hold no id (the QA decks' `qadiags.inc`), /TFILE with dT_his = 0, a
//! keyword variant written where the id belongs (/IMPVEL/FGEO/10) refused by
//! name, `//SUBMODEL` read in place, /BCS Trarot written with fewer than six
//! codes.
//!
//! Each test writes a small deck in a fresh folder and reads it through the
//! library (`read_deck`, `build_model`).

mod common;

use crashsim::deck::{build_model, read_deck, Deck, EngineFile, ReadOptions};
use crashsim::model::{InputError, Model};
use std::path::PathBuf;

fn i10(v: impl std::fmt::Display) -> String {
    format!("{v:>10}")
}

fn r20(v: impl std::fmt::Display) -> String {
    format!("{v:>20}")
}

fn node(id: u64, x: f64, y: f64, z: f64) -> String {
    i10(id) + &r20(x) + &r20(y) + &r20(z)
}

/// Two unit bricks side by side along x (part 1, nodes 1-12), as a starter
/// deck whose blocks `extra` go before /END.
fn two_bricks(extra: &[&str]) -> String {
    let mut d = vec![
        "#RADIOSS STARTER".to_string(),
        "/BEGIN".into(),
        "syntax".into(),
        i10(2019) + &i10(0),
        r20("kg") + &r20("mm") + &r20("ms"),
        r20("kg") + &r20("mm") + &r20("ms"),
        "/MAT/LAW1/1".into(),
        "steel".into(),
        r20("7.85e-06"),
        r20(210) + &r20("0.3"),
        "/PROP/SOLID/1".into(),
        "brick".into(),
        i10(1) + &i10(4),
        r20(0) + &r20(0) + &r20(0),
        "/PART/1".into(),
        "bricks".into(),
        i10(1) + &i10(1) + &i10(0),
        "/NODE".into(),
    ];
    let mut id = 0;
    for z in [0.0, 1.0] {
        for y in [0.0, 1.0] {
            for x in [0.0, 1.0, 2.0] {
                id += 1;
                d.push(node(id, x, y, z));
            }
        }
    }
    // Node n at (x, y, z) = ((n-1) % 3, (n-1)/3 % 2, (n-1)/6).
    d.push("/BRICK/1".into());
    d.push([1, 1, 2, 5, 4, 7, 8, 11, 10].map(i10).concat());
    d.push([2, 2, 3, 6, 5, 8, 9, 12, 11].map(i10).concat());
    d.extend(extra.iter().map(|s| s.to_string()));
    d.push("/END".into());
    d.join("\n") + "\n"
}

/// A fresh folder with the starter (and engine, if given) written in it.
struct Case {
    dir: PathBuf,
}

impl Case {
    fn new(tag: &str) -> Case {
        Case {
            dir: common::scratch(&format!("syntax-{tag}")),
        }
    }

    fn write(&self, name: &str, text: &str) -> PathBuf {
        let p = self.dir.join(name);
        std::fs::write(&p, text).unwrap();
        p
    }

    fn read(&self, starter: &str, engine: Option<&str>) -> Result<Deck, InputError> {
        let s = self.write("SYN_0000.rad", starter);
        let e = match engine {
            Some(text) => EngineFile::Given(self.write("SYN_0001.rad", text)),
            None => EngineFile::None,
        };
        read_deck(&s, e, ReadOptions::default())
    }

    fn model(&self, starter: &str) -> Model {
        let deck = self.read(starter, None).unwrap_or_else(|e| panic!("{e}"));
        build_model(&deck).unwrap_or_else(|e| panic!("{e}"))
    }
}

impl Drop for Case {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.dir);
    }
}

// ---------------------------------------------------------------------------
// Tabs
// ---------------------------------------------------------------------------

#[test]
fn trailing_tab_on_a_starter_line_is_white_space() {
    // OpenRadioss QA SUBMODEL_update_v_100_PLOAD: a tab after the /BEGIN unit fields.
    let c = Case::new("tab-trailing");
    let deck = two_bricks(&[]).replacen(
        &(r20("kg") + &r20("mm") + &r20("ms")),
        &(r20("kg") + &r20("mm") + &r20("ms") + "      \t  "),
        1,
    );
    assert!(deck.contains('\t'));
    let m = c.model(&deck);
    assert_eq!(m.nodes.len(), 12);
    // The fields before the tab land in their columns.
    let d = c.read(&deck, None).unwrap();
    let b = d.begin.unwrap();
    assert_eq!(b.input_units.length, "mm");
    assert_eq!(b.input_units.time, "ms");
}

#[test]
fn tab_before_data_on_a_starter_line_is_an_error_with_its_column() {
    let c = Case::new("tab-data");
    let deck = two_bricks(&[]).replacen(&node(2, 1.0, 0.0, 0.0), "         2\t1.0\t0\t0", 1);
    let e = c.read(&deck, None).unwrap_err();
    assert_eq!(e.keyword, "/NODE");
    assert!(e.message.contains("tab character at column 11"), "{e}");
}

#[test]
fn tab_separates_values_in_the_engine_file() {
    // The engine file is read in free format (values separated by blanks).
    let c = Case::new("tab-engine");
    let engine = "#RADIOSS ENGINE\n/RUN/SYN/1\n\t0.5\t\n/DT\n0.8\t0.0\n/END\n";
    let d = c.read(&two_bricks(&[]), Some(engine)).unwrap();
    let e = d.engine.unwrap();
    assert_eq!(e.run.unwrap().tstop, 0.5);
    assert_eq!(e.dt_scale, 0.8);
}

// ---------------------------------------------------------------------------
// /SURF/PART/ALL and /SURF/PART/EXT
// ---------------------------------------------------------------------------

#[test]
fn surf_part_all_takes_every_solid_face() {
    // Two bricks: 12 faces in all, 10 external (the shared face counted out).
    let c = Case::new("surf-all");
    let m = c.model(&two_bricks(&[
        "/SURF/PART/ALL/7",
        "every face",
        &i10(1),
        "/SURF/PART/EXT/8",
        "outer faces",
        &i10(1),
        "/SURF/PART/9",
        "plain",
        &i10(1),
    ]));
    let faces = |id: u64| {
        m.surfaces
            .iter()
            .find(|s| s.id == id)
            .unwrap_or_else(|| panic!("surface {id}"))
            .segments
            .len()
    };
    assert_eq!(faces(7), 12);
    assert_eq!(faces(8), 10);
    assert_eq!(faces(9), 10);
}

// ---------------------------------------------------------------------------
// Node id 0
// ---------------------------------------------------------------------------

#[test]
fn node_numbered_zero_is_left_out_with_a_warning() {
    // OpenRadioss QA RESSORT_kjoint2 lists a node 0 that nothing names.
    let c = Case::new("node0");
    let deck = two_bricks(&[]).replacen(
        "/NODE\n",
        &format!("/NODE\n{}\n", node(0, 5.0, 5.0, 5.0)),
        1,
    );
    let d = c.read(&deck, None).unwrap();
    assert_eq!(d.nodes.len(), 12);
    assert!(
        d.warnings
            .iter()
            .any(|w| w.keyword == "/NODE" && w.message.contains("node_ID 0")),
        "{:?}",
        d.warnings
    );
    assert_eq!(build_model(&d).unwrap().nodes.len(), 12);
}

// ---------------------------------------------------------------------------
// /TH object lists followed by lines that hold no id
// ---------------------------------------------------------------------------

#[test]
fn th_object_list_ends_at_a_line_holding_no_id() {
    // The QA decks include qadiags.inc (Copyright> lines) right after a /TH block.
    let c = Case::new("th-copyright");
    c.write(
        "qadiags.inc",
        "Copyright>        OpenRadioss\nCopyright>        Copyright (C) 2026 Someone\nCopyright>\n",
    );
    let deck = two_bricks(&[
        "/TH/NODE/3",
        "nodes",
        "DEF",
        &(i10(1) + &i10(0) + " first"),
        &(i10(0) + &i10(0) + " none"),
        &(i10(12) + &i10(0) + " last"),
        "#include qadiags.inc",
        "/TH/PART/4",
        "parts",
        "DEF",
        &i10(1),
        "#include qadiags.inc",
        "/TH/PART/5",
        "no object yet",
        "DEF",
        "#include qadiags.inc",
    ]);
    let d = c.read(&deck, None).unwrap_or_else(|e| panic!("{e}"));
    let th = |id: u64| d.time_histories.iter().find(|t| t.id == id).unwrap();
    assert_eq!(th(3).objects, vec![1, 12]);
    assert_eq!(th(4).objects, vec![1]);
    // Right after the variables, a Copyright> line is no variable name either.
    assert_eq!(th(5).variables, vec!["DEF"]);
    assert!(th(5).objects.is_empty());
    let w: Vec<_> = d
        .warnings
        .iter()
        .filter(|w| w.message.contains("is text, not a /TH object id"))
        .collect();
    assert_eq!(w.len(), 3, "{:?}", d.warnings);
    assert!(w[0].loc.file.ends_with("qadiags.inc") && w[0].loc.line == 1);
    assert!(w[0].message.contains("3 line(s)"), "{}", w[0].message);
    build_model(&d).unwrap_or_else(|e| panic!("{e}"));
}

#[test]
fn group_and_surface_lists_end_at_a_line_of_text() {
    let c = Case::new("list-copyright");
    c.write("qadiags.inc", "Copyright>        OpenRadioss\nCopyright>\n");
    let deck = two_bricks(&[
        "/GRNOD/NODE/2",
        "corner nodes",
        &(i10(1) + &i10(3)),
        &i10(12),
        "#include qadiags.inc",
        "/SURF/PART/ALL/6",
        "all faces",
        &i10(1),
        "#include qadiags.inc",
    ]);
    let d = c.read(&deck, None).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(d.node_groups[0].items, vec![1, 3, 12]);
    let w: Vec<_> = d
        .warnings
        .iter()
        .filter(|w| w.message.contains("is text, not a"))
        .collect();
    assert_eq!(w.len(), 2, "{:?}", d.warnings);
    assert_eq!(w[0].keyword, "/GRNOD/NODE/2");
    assert!(w[0].message.contains("2 line(s)"), "{}", w[0].message);
    let m = build_model(&d).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(m.surfaces[0].segments.len(), 12);
}

#[test]
fn a_mistyped_number_in_a_list_stays_an_error() {
    // Only text (a letter in column 1 of the field) ends a list.
    let c = Case::new("list-typo");
    let deck = two_bricks(&["/GRNOD/NODE/2", "nodes", &(i10(1) + &i10("1O"))]);
    let e = c.read(&deck, None).unwrap_err();
    assert_eq!(
        (e.keyword.as_str(), e.field.as_str()),
        ("/GRNOD/NODE/2", "item_ID")
    );
}

// ---------------------------------------------------------------------------
// /TFILE dT_his = 0
// ---------------------------------------------------------------------------

#[test]
fn tfile_period_zero_means_every_cycle() {
    let c = Case::new("tfile0");
    let engine = "#RADIOSS ENGINE\n/RUN/SYN/1\n0.5\n/TFILE/4\n0.000000\n/END\n";
    let d = c
        .read(&two_bricks(&[]), Some(engine))
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(d.engine.unwrap().th_period, Some(0.0));
    let engine = "#RADIOSS ENGINE\n/RUN/SYN/1\n0.5\n/TFILE/4\n-1.0\n/END\n";
    let e = c.read(&two_bricks(&[]), Some(engine)).unwrap_err();
    assert_eq!(e.field, "dT_his");
}

#[test]
fn tfile_period_zero_runs_and_samples_every_cycle() {
    // Before dT_his = 0 was read, the sampling loop `next += period` never
    // passed t: the run hung. Now every cycle is sampled: the --history CSV
    // has the t = 0 row and one row per cycle, as the --energies CSV has.
    let c = Case::new("tfile0-run");
    let s = c.write(
        "SYN_0000.rad",
        &two_bricks(&[
            "/INIVEL/TRA/1",
            "push",
            &(r20(1) + &r20(0) + &r20(0) + &i10(1)),
            "/GRNOD/NODE/1",
            "all",
            &(1..=10).map(i10).collect::<String>(),
            &(11..=12).map(i10).collect::<String>(),
            "/TH/NODE/1",
            "tip",
            "DEF",
            &i10(12),
        ]),
    );
    c.write(
        "SYN_0001.rad",
        "#RADIOSS ENGINE\n/RUN/SYN/1\n0.003\n/TFILE/4\n0.0\n/END\n",
    );
    let out = c.dir.join("out");
    std::fs::create_dir_all(&out).unwrap();
    let (hist, energies) = (out.join("hist.csv"), out.join("energies.csv"));
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_crashsim"))
        .args(["run", "--quiet", "--out"])
        .arg(&out)
        .arg("--history")
        .arg(&hist)
        .arg("--energies")
        .arg(&energies)
        .arg(&s)
        .stdout(std::process::Stdio::null())
        .spawn()
        .expect("crashsim runs");
    let t0 = std::time::Instant::now();
    let status = loop {
        if let Some(st) = child.try_wait().unwrap() {
            break st;
        }
        if t0.elapsed().as_secs() > 60 {
            let _ = child.kill();
            panic!("the run with /TFILE dT_his = 0 hangs");
        }
        std::thread::sleep(std::time::Duration::from_millis(50));
    };
    assert!(status.success(), "{status}");
    let rows = |p: &PathBuf| common::read_csv(p).1.len();
    let cycles = rows(&energies);
    assert!(cycles > 10, "{cycles} cycles");
    // Both files hold the t = 0 row and one row per cycle.
    assert_eq!(rows(&hist), cycles);
}

// ---------------------------------------------------------------------------
// Variants and keywords refused by name
// ---------------------------------------------------------------------------

#[test]
fn a_word_where_the_id_belongs_is_an_unsupported_variant_by_name() {
    let c = Case::new("variant");
    let deck = two_bricks(&[
        "/IMPVEL/FGEO/10",
        "geometric",
        &i10(1),
        "/SURF/PART/FOO/3",
        "unknown faces",
        &i10(1),
    ]);
    let d = c.read(&deck, None).unwrap_or_else(|e| panic!("{e}"));
    let names: Vec<&str> = d.unsupported.iter().map(|w| w.keyword.as_str()).collect();
    assert_eq!(names, ["/IMPVEL/FGEO/10", "/SURF/PART/FOO/3"]);
    assert!(d.imposed_velocities.is_empty() && d.surfaces.is_empty());
}

#[test]
fn a_number_that_is_no_id_stays_an_error() {
    let c = Case::new("variant-neg");
    let e = c
        .read(&two_bricks(&["/SURF/PART/-3", "negative", &i10(1)]), None)
        .unwrap_err();
    assert_eq!(e.field, "surf_ID");
    assert!(e.message.contains("positive integer id"), "{e}");
}

#[test]
fn double_slash_submodel_is_read_in_place_and_must_be_closed() {
    let c = Case::new("submodel");
    let deck = two_bricks(&["//SUBMODEL/1", "sub", "", "//ENDSUB"]);
    let d = c.read(&deck, None).unwrap_or_else(|e| panic!("{e}"));
    assert!(d.unsupported.is_empty(), "{:?}", d.unsupported);
    assert!(d.open_submodels.is_empty());
    let e = c.read(&two_bricks(&["//ENDSUB"]), None).unwrap_err();
    assert!(e.message.contains("without an open //SUBMODEL"), "{e}");
    let e = c
        .read(
            &two_bricks(&["//SUBMODEL/1/3", "sub", "", "//ENDSUB"]),
            None,
        )
        .unwrap_err();
    assert_eq!(e.field, "unit_ID", "{e}");
}

// ---------------------------------------------------------------------------
// /BCS Trarot
// ---------------------------------------------------------------------------

#[test]
fn bcs_trarot_short_forms_read_by_column() {
    // Trarot (columns 1-10): TX TY TZ in columns 4-6, rotations in 8-10, as
    // the guide lays it out; '     1' (LOIS_LOI44) fixes TZ, '   111 111' and
    // '111111' (six codes anywhere) fix all six, '   010 101' TY, XX and ZZ.
    let c = Case::new("trarot");
    let bcs = |id: u64, trarot: &str| {
        vec![
            format!("/BCS/{id}"),
            "fix".to_string(),
            format!("{trarot:<10}") + &i10(0) + &i10(1),
        ]
    };
    let mut extra = vec!["/GRNOD/NODE/1".to_string(), "n".into(), i10(1)];
    extra.extend(bcs(1, "     1"));
    extra.extend(bcs(2, "   111 111"));
    extra.extend(bcs(3, "111111"));
    extra.extend(bcs(4, "   010 101"));
    let refs: Vec<&str> = extra.iter().map(String::as_str).collect();
    let d = c
        .read(&two_bricks(&refs), None)
        .unwrap_or_else(|e| panic!("{e}"));
    let fixed: Vec<[bool; 6]> = d.bcs.iter().map(|b| b.fixed).collect();
    assert_eq!(
        fixed,
        [
            [false, false, true, false, false, false],
            [true; 6],
            [true; 6],
            [false, true, false, true, false, true]
        ]
    );
}

#[test]
fn a_dangling_id_names_the_unsupported_keyword_that_would_define_it() {
    // As OpenRadioss QA AMS_boxbeam did before /GRNOD/GRSHEL was read: a
    // condition names node group 5, which /GRNOD/GENE/5 (not supported) defines.
    let c = Case::new("dangling");
    let deck = two_bricks(&[
        "/GRNOD/GENE/5",
        "generated",
        &i10(1),
        "/BCS/1",
        "fix",
        &("   111 111".to_string() + &i10(0) + &i10(5)),
    ]);
    let d = c.read(&deck, None).unwrap_or_else(|e| panic!("{e}"));
    let e = build_model(&d).unwrap_err();
    assert_eq!(e.field, "grnod_ID");
    assert!(
        e.message.contains("node group 5 is not defined")
            && e.message.contains("/GRNOD/GENE/5 at")
            && e.message.contains("not supported"),
        "{e}"
    );
}

/// /SKEW/FIX of an input version before 2017 may give its two axes without
/// the origin line (OPTIONS_NEW_BOX_V11, version 110); from 2017 on the
/// origin line is required.
#[test]
fn skew_fix_of_an_old_version_reads_two_axes_without_origin() {
    let c = Case::new("skew-old");
    let skew = [
        "/SKEW/FIX/1",
        "old layout",
        "                   1                   0                   0",
        "                   1                   0                   1",
    ];
    let old = two_bricks(&skew).replace(&(i10(2019) + &i10(0)), &(i10(110) + &i10(0)));
    let d = c.read(&old, None).unwrap_or_else(|e| panic!("{e}"));
    let m = build_model(&d).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(
        m.skews[0].kind,
        crashsim::model::SkewKind::Fixed {
            origin: [0.0; 3],
            y: [1.0, 0.0, 0.0],
            z: [1.0, 0.0, 1.0],
        }
    );
    let e = c.read(&two_bricks(&skew), None).unwrap_err();
    assert!(e.message.contains("Z′ axis"), "{e}");
}

// ---------------------------------------------------------------------------
// /RBODY centre and inertia options
// ---------------------------------------------------------------------------

/// The two bricks made a rigid body with main node 100 at (−1, 0, 0), with
/// ISPHER and ICOG as given.
fn rigid_bricks(ispher: i64, icog: i64) -> String {
    let rbody =
        i10(100) + &i10(0) + &i10(0) + &i10(ispher) + &r20(0) + &i10(5) + &i10(0) + &i10(icog);
    let node100 = node(100, -1.0, 0.0, 0.0);
    two_bricks(&[
        "/NODE",
        &node100,
        "/GRNOD/NODE/5",
        "the bricks' nodes",
        &(1..=10).map(i10).collect::<String>(),
        &(11..=12).map(i10).collect::<String>(),
        "/RBODY/1",
        "two bricks",
        &rbody,
        &(r20(0) + &r20(0) + &r20(0)),
        &(r20(0) + &r20(0) + &r20(0)),
    ])
}

/// ICOG 0: the centre of mass; ICOG 3: the main node, the inertia about it;
/// ISPHER 1: the inertia made spherical, trace/3 (QA RESSORT_kjoint2's rb2);
/// ICOG 2 is refused by name.
#[test]
fn rbody_icog_and_ispher_set_the_centre_and_the_inertia() {
    let c = Case::new("rbody-icog");
    let m = c.model(&rigid_bricks(0, 0));
    let b = &m.rigid_bodies[0];
    assert!((b.center[0] - 1.0).abs() < 1e-12 && (b.center[1] - 0.5).abs() < 1e-12);
    // About the main node (−1, 0, 0), from the nodal masses.
    let about = |p: [f64; 3]| {
        let mut j = [0.0; 3];
        for n in 0..12 {
            let (x, mn) = (m.nodes.x[n], m.nodal_mass[n]);
            let d = [x[0] - p[0], x[1] - p[1], x[2] - p[2]];
            j[0] += mn * (d[1] * d[1] + d[2] * d[2]);
            j[1] += mn * (d[0] * d[0] + d[2] * d[2]);
            j[2] += mn * (d[0] * d[0] + d[1] * d[1]);
        }
        j
    };
    let m3 = c.model(&rigid_bricks(1, 3));
    let b3 = &m3.rigid_bodies[0];
    assert_eq!(b3.center, [-1.0, 0.0, 0.0]);
    let j = about([-1.0, 0.0, 0.0]);
    let sphere = (j[0] + j[1] + j[2]) / 3.0;
    for k in 0..3 {
        assert!(
            (b3.inertia[k] - sphere).abs() < 1e-12 * sphere,
            "{:?}",
            b3.inertia
        );
        assert_eq!(b3.inertia[3 + k], 0.0);
    }
    assert!((b.inertia[0] - about(b.center)[0]).abs() < 1e-12 * sphere);
    let deck = c.read(&rigid_bricks(0, 2), None).unwrap();
    let e = build_model(&deck).unwrap_err().to_string();
    assert!(
        e.contains("ICOG") && e.contains("2: this centre-of-mass option is not computed"),
        "{e}"
    );
}

/// Two plates on the bricks' bottom face (z = 0, nodes 1-6: shell 11 on
/// x ∈ [0, 1], shell 12 on [1, 2]) and a shell group per box given.
fn plates_in_boxes(boxes: &[&str]) -> String {
    let mut extra = vec![
        "/PROP/SHELL/2".to_string(),
        "plate".into(),
        i10(0) + &i10(0),
        r20(0) + &r20(0) + &r20(0) + &r20(0) + &r20(0),
        i10(1) + &i10(0) + &r20(1),
        "/PART/2".into(),
        "plates".into(),
        i10(2) + &i10(1) + &i10(0),
        "/SHELL/2".into(),
        [11, 1, 2, 5, 4].map(i10).concat(),
        [12, 2, 3, 6, 5].map(i10).concat(),
    ];
    extra.extend(boxes.iter().map(|s| s.to_string()));
    let extra: Vec<&str> = extra.iter().map(String::as_str).collect();
    two_bricks(&extra)
}

/// /GRSHEL/BOX takes the shells with every node in the box (or on its
/// surface), /GRSHEL/BOX2 those with at least one; boxes from nodes or
/// coordinates (reference guide, Boxes and /GRSHEL/BOX).
#[test]
fn shell_groups_by_box_take_the_shells_in_the_box() {
    let c = Case::new("grshel-box");
    let group =
        |kind: &str, id: u64, bx: u64| [format!("/GRSHEL/{kind}/{id}"), "g".into(), i10(bx)];
    let mut lines: Vec<String> = vec![
        // A rectangle around shell 11 only.
        "/BOX/RECTA/1".into(),
        "rect".into(),
        i10(0) + &i10(0) + &i10(0),
        r20(1.1) + &r20(1.5) + &r20(0.5),
        r20(-0.1) + &r20(-0.5) + &r20(-0.5),
        // A sphere of radius 1.1 on node 1: nodes 1, 2, 4.
        "/BOX/SPHER/2".into(),
        "sphere".into(),
        i10(1) + &" ".repeat(30) + &r20(2.2),
        r20(0) + &r20(0) + &r20(0),
        // A cylinder of radius 0.5 along y = 0.5: every node on its surface.
        "/BOX/CYLIN/3".into(),
        "cylinder".into(),
        i10(0) + &i10(0) + &" ".repeat(20) + &r20(1.0),
        r20(0) + &r20(0.5) + &r20(0),
        r20(2) + &r20(0.5) + &r20(0),
    ];
    for (k, (kind, bx)) in [("BOX", 1), ("BOX2", 1), ("BOX", 2), ("BOX2", 2), ("BOX", 3)]
        .iter()
        .enumerate()
    {
        lines.extend(group(kind, 101 + k as u64, *bx));
    }
    let lines: Vec<&str> = lines.iter().map(String::as_str).collect();
    let m = c.model(&plates_in_boxes(&lines));
    let shells: Vec<Vec<u32>> = m.shell_groups.iter().map(|g| g.shells.clone()).collect();
    assert_eq!(
        shells,
        vec![vec![0], vec![0, 1], vec![], vec![0, 1], vec![0, 1]]
    );
}

#[test]
fn a_box_of_an_unknown_node_or_a_flat_cylinder_is_an_error() {
    let c = Case::new("box-errors");
    let deck = plates_in_boxes(&[
        "/BOX/SPHER/2",
        "sphere",
        &(i10(99) + &" ".repeat(30) + &r20(2.2)),
        &(r20(0) + &r20(0) + &r20(0)),
    ]);
    let d = c.read(&deck, None).unwrap_or_else(|e| panic!("{e}"));
    let e = build_model(&d).unwrap_err();
    assert!(e.keyword == "/BOX/SPHER/2" && e.field == "N1", "{e}");
    let deck = plates_in_boxes(&[
        "/BOX/CYLIN/3",
        "cylinder",
        &(i10(0) + &i10(0) + &" ".repeat(20) + &r20(1.0)),
        &(r20(1) + &r20(0.5) + &r20(0)),
        &(r20(1) + &r20(0.5) + &r20(0)),
    ]);
    let d = c.read(&deck, None).unwrap_or_else(|e| panic!("{e}"));
    let e = build_model(&d).unwrap_err();
    assert!(e.message.contains("coincide"), "{e}");
    let deck = plates_in_boxes(&["/GRSHEL/BOX/7", "g", &i10(5)]);
    let d = c.read(&deck, None).unwrap_or_else(|e| panic!("{e}"));
    let e = build_model(&d).unwrap_err();
    assert!(e.keyword == "/GRSHEL/BOX/7" && e.field == "box_ID", "{e}");
}
