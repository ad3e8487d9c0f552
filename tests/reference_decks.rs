//! `crashsim check --json` against the OpenRadioss starter listings of the QA
//! decks: entity counts exactly, total and part masses within 1e-6 relative.

mod common;
use common::*;

/// The integer at the end of the first listing line containing `label`.
fn listed_count(listing: &str, label: &str) -> u64 {
    let line = listing
        .lines()
        .find(|l| l.contains(label))
        .unwrap_or_else(|| panic!("listing has no line '{label}'"));
    line.split_whitespace()
        .last()
        .unwrap()
        .parse()
        .unwrap_or_else(|_| panic!("no count on '{line}'"))
}

/// TOTAL MASS from the "TOTAL MASS AND MASS CENTER" table.
fn listed_total_mass(listing: &str) -> f64 {
    let mut it = listing
        .lines()
        .skip_while(|l| !l.contains("TOTAL MASS AND MASS CENTER"));
    it.find(|l| {
        l.split_whitespace()
            .next()
            .is_some_and(|t| t.parse::<f64>().is_ok())
    })
    .and_then(|l| l.split_whitespace().next().unwrap().parse().ok())
    .expect("total mass in the listing")
}

/// One part of the listing's "PART MASS & INERTIA" section.
struct ListedPart {
    id: u64,
    /// Mass, Ixx, Iyy, Izz, Ixy, Iyz, Izx.
    mass_inertia: Vec<f64>,
    center: Vec<f64>,
}

fn numbers(line: &str) -> Vec<f64> {
    // Fortran may glue a negative number to the previous one ("1.8E-18-5.3E-18").
    let spaced = line
        .replace("E-", "e~")
        .replace('-', " -")
        .replace("e~", "E-");
    spaced
        .split_whitespace()
        .filter_map(|t| t.parse().ok())
        .collect()
}

fn listed_parts(listing: &str) -> Vec<ListedPart> {
    let lines: Vec<&str> = listing.lines().collect();
    let mut out = Vec::new();
    let mut part = None;
    for (i, l) in lines.iter().enumerate() {
        if let Some(rest) = l.strip_prefix("PART :") {
            let digits: String = rest
                .trim_start()
                .chars()
                .take_while(|c| c.is_ascii_digit())
                .collect();
            part = digits.parse().ok();
        }
        if l.trim_start().starts_with("Mass ") && l.contains("Ixx") {
            if let Some(id) = part.take() {
                out.push(ListedPart {
                    id,
                    mass_inertia: numbers(lines[i + 1]),
                    center: numbers(lines[i + 3]),
                });
            }
        }
    }
    out
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(f64::MIN_POSITIVE)
}

fn check_against_listing(name: &str) {
    let listing = qa_listing(name);
    let deck = qa_deck(name);
    let s = crashsim_json(&["check", "--json", deck.to_str().unwrap()]);
    let pairs = [
        ("nodes", "NUMNOD: NUMBER OF NODAL POINTS"),
        ("shells4", "NUMELC: NUMBER OF 3D SHELL ELEMENTS (4-NODES)"),
        ("shells3", "NUMELT3 : NUMBER OF 2D TRIA ELEMENTS"),
        ("solids", "NUMELS: NUMBER OF 3D SOLID ELEMENTS"),
        ("parts", "NPART:   NUMBER OF PARTS"),
        ("materials", "NUMMAT: NUMBER OF MATERIALS"),
        ("properties", "NUMGEO: NUMBER OF PROPERTY SETS"),
        ("rigid_walls", "NRWALL: NUMBER OF RIGID WALLS"),
        ("rigid_bodies", "NRBODY: NUMBER OF RIGID BODIES"),
    ];
    for (key, label) in pairs {
        let want = if key == "shells3" {
            // 3-node shells are listed as NUMELTG (3D); NUMELT3 is the 2-D count.
            listed_count(&listing, "NUMELTG: NUMBER OF 3D SHELL ELEMENTS (3-NODES)")
        } else {
            listed_count(&listing, label)
        };
        assert_eq!(
            s[key].as_u64(),
            Some(want),
            "{name}: {key} (listing: {label})"
        );
    }
    assert_eq!(
        s["interfaces"].as_array().unwrap().len() as u64,
        listed_count(&listing, "NINTER: NUMBER OF INTERFACES"),
        "{name}: interfaces"
    );
    let total = s["total_mass"].as_f64().unwrap();
    let want = listed_total_mass(&listing);
    assert!(
        rel(total, want) < 1e-6,
        "{name}: total mass {total} vs listing {want}"
    );
    let parts = listed_parts(&listing);
    assert_eq!(
        parts.len() as u64,
        s["parts"].as_u64().unwrap(),
        "{name}: one listed mass per part"
    );
    for p in parts {
        let id = p.id;
        let got = s["part_masses"][id.to_string()]
            .as_f64()
            .unwrap_or_else(|| panic!("{name}: part {id} missing"));
        let m = p.mass_inertia[0];
        assert!(
            rel(got, m) < 1e-6,
            "{name}: part {id} mass {got} vs listing {m}"
        );
        // Centre and inertia (about the centre, nodal rotational inertia of
        // shells included) as the listing gives them.
        let d = s["part_details"]
            .as_array()
            .unwrap()
            .iter()
            .find(|d| d["id"].as_u64() == Some(id))
            .unwrap();
        let scale_x = p
            .center
            .iter()
            .fold(0.0f64, |a, v| a.max(v.abs()))
            .max(1e-30);
        for k in 0..3 {
            let c = d["center"][k].as_f64().unwrap();
            assert!(
                (c - p.center[k]).abs() <= 1e-6 * scale_x,
                "{name}: part {id} centre {k}: {c} vs {}",
                p.center[k]
            );
        }
        let scale_i = p.mass_inertia[1..4]
            .iter()
            .fold(0.0f64, |a, v| a.max(v.abs()));
        for k in 0..6 {
            let i = d["inertia"][k].as_f64().unwrap();
            let want = p.mass_inertia[1 + k];
            assert!(
                (i - want).abs() <= 1e-6 * scale_i,
                "{name}: part {id} inertia component {k}: {i} vs listing {want}"
            );
        }
    }
}

#[test]
fn box1bl_matches_listing() {
    check_against_listing("BOX1BL");
}

#[test]
fn boule1v4_matches_listing() {
    check_against_listing("BOULE1V4");
}

#[test]
fn int357_matches_listing() {
    check_against_listing("INT357");
}

#[test]
fn twisbeam_matches_listing() {
    check_against_listing("TWISBEAM");
}

/// BOX1BL's listing also gives the centre of mass and the rigid body's mass.
#[test]
fn box1bl_centre_of_mass_and_rigid_body() {
    let s = crashsim_json(&["check", "--json", qa_deck("BOX1BL").to_str().unwrap()]);
    let c = &s["center_of_mass"];
    let want = [33.33191170085, 5.834044149576, 2.917022074788];
    for k in 0..3 {
        assert!(rel(c[k].as_f64().unwrap(), want[k]) < 1e-9, "centre {k}");
    }
    assert!(
        rel(s["added_mass"].as_f64().unwrap(), 100.0) < 1e-12,
        "TOTAL ADDED MASS = 100"
    );
}

/// The interfaces of INT357 and BOULE1V4: sizes as the listing's node and
/// segment lists give them (INT357: 4 nodes and 1 segment each; BOULE1V4:
/// TYPE7 #1 40 nodes / 81 segments, #2 40 nodes / 32 segments).
/// (id, type, secondary nodes, main segments) of every interface of a QA deck.
fn interface_sizes_of(name: &str) -> Vec<(u64, u64, u64, u64)> {
    let s = crashsim_json(&["check", "--json", qa_deck(name).to_str().unwrap()]);
    s["interfaces"]
        .as_array()
        .unwrap()
        .iter()
        .map(|i| {
            let n = |k: &str| i[k].as_u64().unwrap();
            (n("id"), n("type"), n("secondary_nodes"), n("main_segments"))
        })
        .collect()
}

#[test]
fn interface_sizes() {
    assert_eq!(
        interface_sizes_of("INT357"),
        vec![(3, 3, 4, 1), (6, 5, 4, 1), (10, 7, 4, 1)]
    );
    assert_eq!(
        interface_sizes_of("BOULE1V4"),
        vec![(1, 7, 40, 81), (2, 7, 40, 32)]
    );
}
