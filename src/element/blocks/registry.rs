//! The element-formulation registry: which block computes the elements of a
//! kind whose part's property asks for a given formulation number (Ishell for
//! 4-node shells, Ish3n for triangles, Isolid for bricks, Itetra4 for
//! tetrahedra, the property type for springs), in one table
//! ([`FORMULATIONS`]). [`make_block`] groups a rank's elements of one kind by
//! the formulation their parts ask for and builds one block per group; a
//! number no line lists is refused by name ([`refusal`]).
//!
//! Adding a formulation (say DKT18, Ish3n 30): its block file in this folder
//! and one line in [`FORMULATIONS`] (`Shell3`, `&[30]`, `dkt18::build`), and
//! its number out of [`refusal`]'s list of known-but-missing formulations.

use super::sections::{part_material, shell_property, solid_property};
use super::sections::{SHELL_WITHOUT_MATERIAL, SOLID_WITHOUT_MATERIAL};
use super::{
    ha8, heph, hex8, hex8_total, joint, line, shell3, shell4_bt, shell4_qbat, spring, tet4,
};
use super::{Block, BlockContext, BlockInput, BuildBlock};
use crate::domain::LocalElements;
use crate::model::{ElementKind, Function, MaterialSpec, Part, Property, PropertyKind};
use std::collections::HashMap;

/// One formulation the engine computes: the element kind, the property's
/// formulation numbers that select it, and its block builder.
pub struct Formulation {
    pub kind: ElementKind,
    /// What the numbers are (the property field), for messages and tests.
    pub flag: &'static str,
    pub numbers: &'static [i64],
    /// The solid strain options (Ismstr) the line computes; empty: any (the
    /// block's sections check them).
    pub ismstr: &'static [i64],
    pub name: &'static str,
    pub build: BuildBlock,
}

/// Every formulation the engine computes, one line each.
pub const FORMULATIONS: &[Formulation] = &[
    Formulation {
        kind: ElementKind::Shell4,
        flag: "Ishell",
        numbers: &[1, 2, 3, 4],
        ismstr: &[],
        name: "Belytschko-Tsay",
        build: shell4_bt::build,
    },
    Formulation {
        kind: ElementKind::Shell4,
        flag: "Ishell",
        numbers: &[24],
        ismstr: &[],
        name: "QEPH (Belytschko-Tsay with physical hourglass stabilization)",
        build: shell4_bt::build,
    },
    Formulation {
        kind: ElementKind::Shell4,
        flag: "Ishell",
        numbers: &[12],
        ismstr: &[],
        name: "QBAT (Batoz, 2×2 points, MITC4 shear; elastic laws)",
        build: shell4_qbat::build,
    },
    Formulation {
        kind: ElementKind::Shell3,
        flag: "Ish3n",
        numbers: &[1, 2],
        ismstr: &[],
        name: "C0 triangle",
        build: shell3::build,
    },
    Formulation {
        kind: ElementKind::Brick8,
        flag: "Isolid",
        numbers: &[1, 2],
        ismstr: &[10],
        name: "one-point brick, total strain (Ismstr 10: LAW62)",
        build: hex8_total::build,
    },
    Formulation {
        kind: ElementKind::Brick8,
        flag: "Isolid",
        numbers: &[1, 2],
        ismstr: &[],
        name: "one-point brick, viscous hourglass",
        build: hex8::build,
    },
    Formulation {
        kind: ElementKind::Brick8,
        flag: "Isolid",
        numbers: &[14],
        ismstr: &[],
        name: "HA8 fully integrated brick (2×2×2, assumed strain)",
        build: ha8::build,
    },
    Formulation {
        kind: ElementKind::Brick8,
        flag: "Isolid",
        numbers: &[12, 17],
        ismstr: &[],
        name: "S8 / H8C fully integrated brick (2×2×2; H8C with constant pressure)",
        build: ha8::build,
    },
    Formulation {
        kind: ElementKind::Brick8,
        flag: "Isolid",
        numbers: &[24],
        ismstr: &[],
        name: "HEPH one-point brick with physical hourglass stabilization",
        build: heph::build,
    },
    Formulation {
        kind: ElementKind::Tetra4,
        flag: "Itetra4",
        numbers: &[0, 1000],
        ismstr: &[],
        name: "standard 4-node tetrahedron",
        build: tet4::build,
    },
    Formulation {
        kind: ElementKind::Spring,
        flag: "/PROP/TYPE",
        numbers: &[4],
        ismstr: &[],
        name: "axial spring",
        build: spring::build_axial,
    },
    Formulation {
        kind: ElementKind::Spring,
        flag: "/PROP/TYPE",
        numbers: &[8],
        ismstr: &[],
        name: "general spring (six degrees of freedom)",
        build: spring::build_general,
    },
    Formulation {
        kind: ElementKind::Spring,
        flag: "/PROP/TYPE",
        numbers: &[13],
        ismstr: &[],
        name: "spring beam",
        build: spring::build_beam,
    },
    Formulation {
        kind: ElementKind::Spring,
        flag: "/PROP/TYPE",
        numbers: &[45],
        ismstr: &[],
        name: "KJOINT2 joint between rigid bodies",
        build: joint::build,
    },
    Formulation {
        kind: ElementKind::Truss,
        flag: "/PROP/TYPE",
        numbers: &[2],
        ismstr: &[],
        name: "truss (axial bar)",
        build: line::build_truss,
    },
    Formulation {
        kind: ElementKind::Beam,
        flag: "/PROP/TYPE",
        numbers: &[3],
        ismstr: &[],
        name: "beam (Timoshenko, section resultants)",
        build: line::build_beam,
    },
];

/// Why the engine does not compute formulation `n` of `kind` (today's
/// messages of the sections' own checks, byte for byte).
pub fn refusal(kind: ElementKind, n: i64) -> String {
    match (kind, n) {
        (ElementKind::Shell4, v) => format!("Ishell = {v}: expected 1, 2, 3, 4 (Belytschko-Tsay), 12 (QBAT) or 24 (QEPH)"),
        (ElementKind::Shell3, 30) => "Ish3n = 30 (DKT18) is not supported: the engine computes the C0 triangle (Ish3n = 1, 2)".into(),
        (ElementKind::Shell3, 31) => "Ish3n = 31 (DKT_S3) is not supported: the engine computes the C0 triangle (Ish3n = 1, 2)".into(),
        (ElementKind::Shell3, v) => format!("Ish3n = {v}: expected 1 or 2 (C0 triangle)"),
        (ElementKind::Brick8, v) => format!(
            "Isolid = {v} is not supported: the engine computes bricks with Isolid = 1 (Belytschko viscous hourglass), 2 (Hallquist viscous hourglass), 12 (S8), 14 (HA8), 17 (H8C, fully integrated) or 24 (HEPH)"
        ),
        (ElementKind::Tetra4, v) => format!(
            "Itetra4 = {v}: only the standard 4-node tetrahedron (Itetra4 = 0 or 1000) is supported"
        ),
        (k, _) => format!("{} elements are not computed by the engine yet", k.keyword()),
    }
}

/// The line of [`FORMULATIONS`] computing formulation `n` of `kind` with
/// the strain option `ismstr` (solids; 0 elsewhere), or the refusal naming it.
pub fn lookup(kind: ElementKind, n: i64, ismstr: i64) -> Result<usize, String> {
    FORMULATIONS
        .iter()
        .position(|f| {
            f.kind == kind
                && f.numbers.contains(&n)
                && (f.ismstr.is_empty() || f.ismstr.contains(&ismstr))
        })
        .ok_or_else(|| refusal(kind, n))
}

/// The formulation number a part's property asks for and its solid strain
/// option (0 for other kinds), read after the same property and material
/// look-ups (and refusals, in the same order) as the block's sections.
fn formulation_number(
    kind: ElementKind,
    part: &Part,
    props: &[Property],
    mats: &[MaterialSpec],
) -> Result<(i64, i64), String> {
    match kind {
        ElementKind::Shell4 | ElementKind::Shell3 => {
            let prop = shell_property(part, props)?;
            part_material(part, mats, SHELL_WITHOUT_MATERIAL)?;
            Ok((
                if kind == ElementKind::Shell4 {
                    prop.ishell
                } else {
                    prop.ish3n
                },
                0,
            ))
        }
        ElementKind::Brick8 | ElementKind::Tetra4 => {
            let prop = solid_property(part, props)?;
            part_material(part, mats, SOLID_WITHOUT_MATERIAL)?;
            Ok((
                if kind == ElementKind::Brick8 {
                    prop.isolid
                } else {
                    prop.itetra4
                },
                prop.ismstr,
            ))
        }
        ElementKind::Spring => {
            let prop = &props[part.prop.ok_or("spring part without property")? as usize];
            match prop.card.kind {
                PropertyKind::Spring(_) => Ok((4, 0)),
                PropertyKind::GeneralSpring(_) => Ok((8, 0)),
                PropertyKind::SpringBeam(_) => Ok((13, 0)),
                PropertyKind::Joint(_) => Ok((45, 0)),
                _ => Err(format!(
                    "/PROP/{}: a spring part needs a spring property (/PROP/TYPE4, TYPE8, TYPE13 or TYPE45)",
                    prop.card.id
                )),
            }
        }
        ElementKind::Truss | ElementKind::Beam => {
            let prop = &props[part.prop.ok_or("truss or beam part without property")? as usize];
            match prop.card.kind {
                PropertyKind::Truss(_) => Ok((2, 0)),
                PropertyKind::Beam(_) => Ok((3, 0)),
                _ => Err(format!(
                    "/PROP/{}: a truss part needs /PROP/TRUSS (TYPE2), a beam part /PROP/BEAM (TYPE3)",
                    prop.card.id
                )),
            }
        }
    }
}

/// The formulation (line of [`FORMULATIONS`]) of every element of `le`,
/// looked up once per part in the order the parts first appear.
fn formulations_of(
    le: &LocalElements,
    parts: &[Part],
    props: &[Property],
    mats: &[MaterialSpec],
) -> Result<Vec<usize>, String> {
    let mut of_part: HashMap<u32, usize> = HashMap::new();
    let mut out = Vec::with_capacity(le.part.len());
    for &p in &le.part {
        let f = match of_part.get(&p) {
            Some(&f) => f,
            None => {
                let (n, ismstr) = formulation_number(le.kind, &parts[p as usize], props, mats)?;
                let f = lookup(le.kind, n, ismstr)?;
                of_part.insert(p, f);
                f
            }
        };
        out.push(f);
    }
    Ok(out)
}

/// Groups element positions by their label: one group per label, in the
/// order the labels first appear, each group's positions ascending (so a
/// block keeps the global order of its elements).
pub fn group_in_order(labels: &[usize]) -> Vec<(usize, Vec<usize>)> {
    let mut groups: Vec<(usize, Vec<usize>)> = Vec::new();
    for (e, &l) in labels.iter().enumerate() {
        match groups.iter_mut().find(|(g, _)| *g == l) {
            Some((_, members)) => members.push(e),
            None => groups.push((l, vec![e])),
        }
    }
    groups
}

/// The elements of `le` at positions `members` (ascending), as their own set.
fn subset(le: &LocalElements, members: &[usize]) -> LocalElements {
    if members.len() == le.global.len() {
        return le.clone();
    }
    let n = le.kind.nodes();
    LocalElements {
        kind: le.kind,
        global: members.iter().map(|&e| le.global[e]).collect(),
        part: members.iter().map(|&e| le.part[e]).collect(),
        nodes: members
            .iter()
            .flat_map(|&e| le.nodes[n * e..n * (e + 1)].iter().copied())
            .collect(),
        thick: members.iter().map(|&e| le.thick[e]).collect(),
    }
}

/// The blocks of one kind of local elements: one per formulation its parts
/// ask for, in the order the formulations first appear (empty kinds get none).
pub fn make_block(
    le: &LocalElements,
    x: &[[f64; 3]],
    mass: &[f64],
    parts: &[Part],
    props: &[Property],
    mats: &[MaterialSpec],
    functions: &[Function],
    ctx: BlockContext,
) -> Result<Vec<Box<dyn Block>>, String> {
    if le.global.is_empty() {
        return Ok(Vec::new());
    }
    let formulations = formulations_of(le, parts, props, mats)?;
    let mut blocks = Vec::new();
    for (f, members) in group_in_order(&formulations) {
        blocks.push((FORMULATIONS[f].build)(BlockInput {
            le: subset(le, &members),
            x,
            mass,
            parts,
            props,
            mats,
            functions,
            ctx,
        })?);
    }
    Ok(blocks)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::{load, InputOptions};
    use crate::model::Model;

    fn model(deck: &str) -> Model {
        let root = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"));
        let path = root.join(format!("decks/{deck}/{deck}_0000.rad"));
        let opts = InputOptions {
            controls: None,
            strict: false,
        };
        load(&path, &opts).unwrap()
    }

    /// The whole element set of `kind` as one rank's elements.
    fn all_of(m: &Model, kind: ElementKind) -> LocalElements {
        let set = m.elements.iter().find(|s| s.kind == kind).unwrap();
        LocalElements {
            kind,
            global: (0..set.len() as u32).collect(),
            part: set.part.clone(),
            nodes: set.nodes.clone(),
            thick: set.thick.clone(),
        }
    }

    fn blocks(m: &Model, le: &LocalElements) -> Result<Vec<Box<dyn Block>>, String> {
        make_block(
            le,
            &m.nodes.x,
            &m.nodal_mass,
            &m.parts,
            &m.properties,
            &m.materials,
            &m.functions,
            BlockContext {
                rigid_bodies: &m.rigid_bodies,
                node_global: &[],
                dt_max: m.engine.as_ref().map_or(0.0, |e| e.dtix.1),
            },
        )
    }

    #[test]
    fn every_line_is_found_by_its_numbers_and_others_are_refused_by_name() {
        for (i, f) in FORMULATIONS.iter().enumerate() {
            for &n in f.numbers {
                let ismstr = f.ismstr.first().copied().unwrap_or(0);
                assert_eq!(
                    lookup(f.kind, n, ismstr),
                    Ok(i),
                    "{} {} = {n}",
                    f.name,
                    f.flag
                );
            }
        }
        let refused = [
            (ElementKind::Shell4, 7, "Ishell = 7: expected 1, 2, 3, 4 (Belytschko-Tsay), 12 (QBAT) or 24 (QEPH)"),
            (ElementKind::Shell3, 30, "Ish3n = 30 (DKT18) is not supported: the engine computes the C0 triangle (Ish3n = 1, 2)"),
            (ElementKind::Brick8, 18, "Isolid = 18 is not supported: the engine computes bricks with Isolid = 1 (Belytschko viscous hourglass), 2 (Hallquist viscous hourglass), 12 (S8), 14 (HA8), 17 (H8C, fully integrated) or 24 (HEPH)"),
            (ElementKind::Tetra4, 3, "Itetra4 = 3: only the standard 4-node tetrahedron (Itetra4 = 0 or 1000) is supported"),
        ];
        for (kind, n, message) in refused {
            assert_eq!(lookup(kind, n, 0), Err(message.to_string()));
        }
    }

    #[test]
    fn each_kind_gets_its_block_and_an_unknown_formulation_is_refused() {
        let mut m = model("idel_layers");
        for kind in [ElementKind::Shell4, ElementKind::Brick8] {
            let le = all_of(&m, kind);
            let b = blocks(&m, &le).unwrap();
            assert_eq!(b.len(), 1, "{kind:?}: one formulation, one block");
            assert_eq!(b[0].kind(), kind);
            assert_eq!(b[0].corners(), kind.nodes());
            assert_eq!(b[0].local().global, le.global);
            assert_eq!(b[0].local().nodes, le.nodes);
        }
        let le = all_of(&m, ElementKind::Shell4);
        let prop = m.parts[le.part[0] as usize].prop.unwrap() as usize;
        m.properties[prop].shell.as_mut().unwrap().ishell = 7;
        assert_eq!(
            blocks(&m, &le).err().unwrap(),
            "Ishell = 7: expected 1, 2, 3, 4 (Belytschko-Tsay), 12 (QBAT) or 24 (QEPH)"
        );
        let le = all_of(&m, ElementKind::Brick8);
        let prop = m.parts[le.part[0] as usize].prop.unwrap() as usize;
        m.properties[prop].solid.as_mut().unwrap().isolid = 18;
        assert!(blocks(&m, &le)
            .err()
            .unwrap()
            .starts_with("Isolid = 18 is not supported"));
    }

    #[test]
    fn two_formulations_of_one_kind_get_their_elements_in_global_order() {
        // Elements 0..6 of a kind whose parts ask for formulations 3, 1, 3, 1, 1, 0.
        let groups = group_in_order(&[3, 1, 3, 1, 1, 0]);
        assert_eq!(
            groups,
            vec![(3, vec![0, 2]), (1, vec![1, 3, 4]), (0, vec![5])]
        );
        let le = LocalElements {
            kind: ElementKind::Shell3,
            global: vec![10, 11, 12, 13, 14, 15],
            part: vec![0, 1, 0, 1, 1, 2],
            nodes: (0..18).collect(),
            thick: vec![1.0, 1.1, 1.2, 1.3, 1.4, 1.5],
        };
        let second = subset(&le, &groups[1].1);
        assert_eq!(second.kind, ElementKind::Shell3);
        assert_eq!(second.global, vec![11, 13, 14]);
        assert_eq!(second.part, vec![1, 1, 1]);
        assert_eq!(second.nodes, vec![3, 4, 5, 9, 10, 11, 12, 13, 14]);
        assert_eq!(second.thick, vec![1.1, 1.3, 1.4]);
        // One group is the set itself, untouched.
        assert_eq!(subset(&le, &[0, 1, 2, 3, 4, 5]), le);
    }

    /// The elements of a kind split over two blocks compute the same corner
    /// forces, to the bit, as the kind in one block: a block's result per
    /// element does not depend on which other elements share it.
    #[test]
    fn a_kind_split_over_two_blocks_computes_the_same_forces() {
        let m = model("idel_layers");
        let le = all_of(&m, ElementKind::Shell4);
        let first = le.part[0];
        let labels: Vec<usize> = le.part.iter().map(|&p| usize::from(p != first)).collect();
        let groups = group_in_order(&labels);
        assert_eq!(groups.len(), 2, "idel_layers has several shell parts");
        let x = &m.nodes.x;
        let v: Vec<[f64; 3]> = (0..x.len())
            .map(|i| {
                [
                    1e-3 * (i % 7) as f64,
                    -2e-3 * (i % 5) as f64,
                    1e-3 * (i % 3) as f64,
                ]
            })
            .collect();
        let vr = vec![[0.0; 3]; x.len()];
        let build = |le: LocalElements| {
            (FORMULATIONS[0].build)(BlockInput {
                le,
                x,
                mass: &m.nodal_mass,
                parts: &m.parts,
                props: &m.properties,
                mats: &m.materials,
                functions: &m.functions,
                ctx: BlockContext::default(),
            })
            .unwrap()
        };
        let run = |b: &mut Box<dyn Block>| {
            let mut c = vec![[0.0; crate::element::SLOT]; b.local().global.len() * 4];
            b.compute(x, &v, &vr, 1e-4, &mut c);
            c
        };
        let whole = run(&mut build(le.clone()));
        assert!(
            whole.iter().flatten().any(|&f| f != 0.0),
            "the step loads the shells"
        );
        for (_, members) in &groups {
            let part = run(&mut build(subset(&le, members)));
            for (k, &e) in members.iter().enumerate() {
                assert_eq!(
                    part[4 * k..4 * k + 4],
                    whole[4 * e..4 * e + 4],
                    "element {e}"
                );
            }
        }
    }
}
