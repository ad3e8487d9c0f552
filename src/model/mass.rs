//! Lumped masses: element mass to its nodes, part masses, centres and
//! inertias, the model total.
//!
//! - 4-node shell: m = ρ·t·A with A = ½‖(x3−x1)×(x4−x2)‖, ¼ to each node;
//! - 3-node shell: m = ρ·t·A, to each node the share of its corner angle,
//!   α/π (OpenRadioss QA COQUES3N_ct3a: the starter's NODAL MASSES table to
//!   2e-13 relative, where ⅓ each is 33% off at some nodes);
//! - brick: ρ·V, ⅛ to each of its 8 node slots; tetra: ρ·V, ¼ to each node;
//! - spring (/PROP/TYPE4, TYPE13): the property's Mass, ½ to each node;
//! - truss and beam: ρ·A·L, ½ to each node; beam nodes also get the
//!   rotational inertia of `beam_inertia`;
//! - /ADMAS type 0: MASS on each node of the group; type 1: MASS shared
//!   equally by the group's nodes;
//! - /RBODY MASS: carried by the rigid body (on its main node), counted once.
//!
//! - shell nodes also get a rotational inertia (isotropic, for the
//!   rotational degrees of freedom): ρ·t·A/4 · (A/9 + t²/12) per node, with
//!   A/12 instead of A/9 for Ishell ≥ 11 (QBAT, QEPH) and A/4.5 for 3-node
//!   shells (the reference's C3INMAS); it counts in the part
//!   inertia as Radioss reports it.
//!
//! This is how the Radioss starter distributes mass (its NODAL MASSES,
//! PART MASS and TOTAL MASS tables agree with these rules on the QA decks).

use super::geometry::{hexa_volume, quad_area, tetra_volume, triangle_area};
use super::{ElementSet, Model, NO_NODE};
use crate::model::{ElementKind, InputError, Loc};
use serde::{Deserialize, Serialize};

#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub struct PartMass {
    pub mass: f64,
    pub center: [f64; 3],
    /// About the centre: xx, yy, zz, xy, yz, xz (products with the sign
    /// convention I_xy = −Σ m·x·y).
    pub inertia: [f64; 6],
}

#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub struct MassSummary {
    pub per_part: Vec<PartMass>,
    /// Elements + added + rigid-body masses.
    pub total: f64,
    pub center: [f64; 3],
    pub added_total: f64,
}

/// Element masses for one element set, with an error for a non-positive measure.
pub fn element_masses(
    model: &Model,
    set: &ElementSet,
    locs: &[Loc],
) -> Result<Vec<f64>, InputError> {
    let x = &model.nodes.x;
    let mut out = Vec::with_capacity(set.len());
    for e in 0..set.len() {
        let n = set.nodes_of(e);
        let part = &model.parts[set.part[e] as usize];
        let rho = part
            .mat
            .map(|m| model.materials[m as usize].rho)
            .unwrap_or(0.0);
        let (measure, what) = match set.kind {
            ElementKind::Shell4 => (
                quad_area([
                    x[n[0] as usize],
                    x[n[1] as usize],
                    x[n[2] as usize],
                    x[n[3] as usize],
                ]),
                "area",
            ),
            ElementKind::Shell3 => (
                triangle_area([x[n[0] as usize], x[n[1] as usize], x[n[2] as usize]]),
                "area",
            ),
            ElementKind::Brick8 => {
                let mut p = [[0.0; 3]; 8];
                for k in 0..8 {
                    p[k] = x[n[k] as usize];
                }
                (hexa_volume(p), "volume")
            }
            ElementKind::Tetra4 => (
                tetra_volume([
                    x[n[0] as usize],
                    x[n[1] as usize],
                    x[n[2] as usize],
                    x[n[3] as usize],
                ]),
                "volume",
            ),
            ElementKind::Truss | ElementKind::Beam => {
                let (area, l, _) = line_section(model, set, e);
                (area * l, "length")
            }
            ElementKind::Spring => (1.0, ""),
        };
        if (measure.is_nan() || measure <= 0.0) && !what.is_empty() {
            return Err(InputError::new(
                locs[e].clone(),
                set.kind.keyword(),
                "",
                format!("element {} has {what} {measure:e}: expected > 0 (degenerate or inverted element; check its node order)", set.ids[e]),
            ));
        }
        let m = match set.kind {
            ElementKind::Shell4 | ElementKind::Shell3 => rho * set.thick[e] * measure,
            ElementKind::Brick8 | ElementKind::Tetra4 | ElementKind::Truss | ElementKind::Beam => {
                rho * measure
            }
            ElementKind::Spring => spring_mass(model, set, e).0,
        };
        out.push(m);
    }
    Ok(out)
}

/// A spring element's mass and rotational inertia (its property's; 0 for
/// the other elements).
fn spring_mass(model: &Model, set: &ElementSet, e: usize) -> (f64, f64) {
    if set.kind != ElementKind::Spring {
        return (0.0, 0.0);
    }
    let n = set.nodes_of(e);
    let x = |k: usize| model.nodes.x[n[k] as usize];
    let l0 = crate::vec3::norm(crate::vec3::sub(x(1), x(0)));
    model.parts[set.part[e] as usize]
        .prop
        .and_then(|p| model.properties[p as usize].card.kind.spring_mass(l0))
        .unwrap_or((0.0, 0.0))
}

/// A truss's or beam's cross-section area, initial length and (beams) its
/// property; (1, 0, None) where the part has no such property (the model
/// builder refuses it before masses are needed).
fn line_section<'a>(
    model: &'a Model,
    set: &ElementSet,
    e: usize,
) -> (f64, f64, Option<&'a super::BeamProperty>) {
    let n = set.nodes_of(e);
    let x = |k: usize| model.nodes.x[n[k] as usize];
    let l = crate::vec3::norm(crate::vec3::sub(x(1), x(0)));
    match model.parts[set.part[e] as usize]
        .prop
        .map(|p| &model.properties[p as usize].card.kind)
    {
        Some(super::PropertyKind::Truss(t)) => (t.area, l, None),
        Some(super::PropertyKind::Beam(b)) => (b.area, l, Some(b)),
        _ => (1.0, 0.0, None),
    }
}

/// The rotational inertia each node of a beam takes (isotropic), as the
/// reference starter lumps it (QA LOIS_LOI2_BESH's part inertia to the
/// printed digits): max(m·L²/12 + ρ·(L/2)·max(Iyy, Izz), ρ·L·Ixx/2) with
/// m = ρAL/2 the node's mass; 0 for other elements.
fn beam_inertia(model: &Model, set: &ElementSet, e: usize) -> f64 {
    if set.kind != ElementKind::Beam {
        return 0.0;
    }
    let (area, l, Some(b)) = line_section(model, set, e) else {
        return 0.0;
    };
    let rho = model.parts[set.part[e] as usize]
        .mat
        .map_or(0.0, |m| model.materials[m as usize].rho);
    let m = 0.5 * rho * area * l;
    (m * l * l / 12.0 + rho * 0.5 * l * b.iyy.max(b.izz)).max(0.5 * rho * l * b.ixx)
}

/// Share of an element's mass each node slot gets.
fn share(kind: ElementKind) -> f64 {
    match kind {
        ElementKind::Shell4 | ElementKind::Tetra4 => 0.25,
        ElementKind::Shell3 => 1.0 / 3.0,
        ElementKind::Brick8 => 0.125,
        ElementKind::Spring | ElementKind::Truss | ElementKind::Beam => 0.5,
    }
}

/// Adds the element masses to the nodes (in element order: deterministic) and
/// accumulates part mass, first moment and second moments.
pub fn lump(model: &mut Model, masses: &[Vec<f64>]) {
    let nparts = model.parts.len();
    let mut rot = vec![0.0; nparts]; // Σ nodal rotational inertia of the part's shells
    let mut m = vec![0.0; nparts];
    let mut s1 = vec![[0.0; 3]; nparts];
    let mut s2 = vec![[0.0; 6]; nparts]; // Σm x², y², z², xy, yz, xz
    for (set, em) in model.elements.iter().zip(masses) {
        let f = share(set.kind);
        for e in 0..set.len() {
            let p = set.part[e] as usize;
            let slots = match set.kind {
                ElementKind::Beam => &set.nodes_of(e)[..2],
                _ => set.nodes_of(e),
            };
            let rot_per_mass = shell_rotational_factor(model, set, e);
            let spring_inertia = 0.5 * spring_mass(model, set, e).1 + beam_inertia(model, set, e);
            let corners = (set.kind == ElementKind::Shell3).then(|| corner_shares(model, slots));
            for (i, &n) in slots.iter().enumerate() {
                if n == NO_NODE {
                    continue;
                }
                let dm = em[e] * corners.map_or(f, |c| c[i]);
                model.nodal_mass[n as usize] += dm;
                if rot_per_mass > 0.0 {
                    model.nodal_inertia[n as usize] += dm * rot_per_mass;
                    rot[p] += dm * rot_per_mass;
                }
                if spring_inertia > 0.0 {
                    model.nodal_inertia[n as usize] += spring_inertia;
                    rot[p] += spring_inertia;
                }
                let x = model.nodes.x[n as usize];
                m[p] += dm;
                for k in 0..3 {
                    s1[p][k] += dm * x[k];
                }
                s2[p][0] += dm * x[0] * x[0];
                s2[p][1] += dm * x[1] * x[1];
                s2[p][2] += dm * x[2] * x[2];
                s2[p][3] += dm * x[0] * x[1];
                s2[p][4] += dm * x[1] * x[2];
                s2[p][5] += dm * x[0] * x[2];
            }
        }
    }
    model.mass.per_part = (0..nparts)
        .map(|p| {
            if m[p] == 0.0 {
                return PartMass::default();
            }
            let c = [s1[p][0] / m[p], s1[p][1] / m[p], s1[p][2] / m[p]];
            // Central second moments: Σm x_i x_j − M c_i c_j.
            let xx = s2[p][0] - m[p] * c[0] * c[0];
            let yy = s2[p][1] - m[p] * c[1] * c[1];
            let zz = s2[p][2] - m[p] * c[2] * c[2];
            let xy = s2[p][3] - m[p] * c[0] * c[1];
            let yz = s2[p][4] - m[p] * c[1] * c[2];
            let xz = s2[p][5] - m[p] * c[0] * c[2];
            PartMass {
                mass: m[p],
                center: c,
                inertia: [
                    yy + zz + rot[p],
                    xx + zz + rot[p],
                    xx + yy + rot[p],
                    -xy,
                    -yz,
                    -xz,
                ],
            }
        })
        .collect();
}

/// A triangle's corner angles over π: the share of its mass each node takes
/// (they add up to 1).
fn corner_shares(model: &Model, n: &[u32]) -> [f64; 3] {
    let x = |k: usize| model.nodes.x[n[k % 3] as usize];
    std::array::from_fn(|k| {
        let (a, b, c) = (x(k), x(k + 1), x(k + 2));
        let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
        let v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
        let dot = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
        let cross = [
            u[1] * v[2] - u[2] * v[1],
            u[2] * v[0] - u[0] * v[2],
            u[0] * v[1] - u[1] * v[0],
        ];
        let sin = (cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]).sqrt();
        sin.atan2(dot) / std::f64::consts::PI
    })
}

/// Rotational inertia per unit nodal mass of a shell's nodes, A/9 + t²/12
/// (A/12 + t²/12 for Ishell ≥ 11, A/4.5 + t²/12 for triangles); 0 for
/// other elements.
fn shell_rotational_factor(model: &Model, set: &ElementSet, e: usize) -> f64 {
    if !matches!(set.kind, ElementKind::Shell4 | ElementKind::Shell3) {
        return 0.0;
    }
    let x = &model.nodes.x;
    let n = set.nodes_of(e);
    let area = if set.kind == ElementKind::Shell4 {
        quad_area([
            x[n[0] as usize],
            x[n[1] as usize],
            x[n[2] as usize],
            x[n[3] as usize],
        ])
    } else {
        triangle_area([x[n[0] as usize], x[n[1] as usize], x[n[2] as usize]])
    };
    let part = &model.parts[set.part[e] as usize];
    let ishell = part
        .prop
        .and_then(|p| {
            model.properties[p as usize]
                .shell
                .as_ref()
                .map(|s| s.ishell)
        })
        .unwrap_or(1);
    let t = set.thick[e];
    // Triangles: A/4.5 (the reference starter's C3INMAS, its share by
    // corner angle as the mass; QA COQUES3N_ct3a's part Iyy 6.452).
    let divisor = match (set.kind, ishell >= 11) {
        (ElementKind::Shell3, _) => 4.5,
        (_, true) => 12.0,
        (_, false) => 9.0,
    };
    area / divisor + t * t / 12.0
}

/// Total mass and centre: nodal masses (elements + /ADMAS) plus rigid-body MASS on main nodes.
pub fn totals(model: &mut Model) {
    let mut total = 0.0;
    let mut s = [0.0; 3];
    for (i, &mi) in model.nodal_mass.iter().enumerate() {
        total += mi;
        for k in 0..3 {
            s[k] += mi * model.nodes.x[i][k];
        }
    }
    for rb in &model.rigid_bodies {
        total += rb.card.mass;
        for k in 0..3 {
            s[k] += rb.card.mass * model.nodes.x[rb.main_node as usize][k];
        }
    }
    model.mass.total = total;
    model.mass.center = if total > 0.0 {
        [s[0] / total, s[1] / total, s[2] / total]
    } else {
        [0.0; 3]
    };
    model.mass.added_total = model.added_mass.iter().sum();
}
