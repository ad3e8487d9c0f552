//! `crashsim check`: what a deck holds, as a table or one JSON object.

use crate::model::{geometry_edge_min, Model};
use crate::model::{ElementKind, Id};
use serde::Serialize;
use std::collections::BTreeMap;

#[derive(Serialize)]
pub struct InterfaceSummary {
    pub id: Id,
    #[serde(rename = "type")]
    pub type_: u32,
    pub title: String,
    pub secondary_nodes: usize,
    pub main_segments: usize,
    /// Edge-to-edge interfaces (TYPE11): the edges of each side.
    pub secondary_edges: usize,
    pub main_edges: usize,
}

#[derive(Serialize)]
pub struct PartDetail {
    pub id: Id,
    pub title: String,
    pub mass: f64,
    pub center: [f64; 3],
    pub inertia: [f64; 6],
}

#[derive(Serialize)]
pub struct RigidBodyDetail {
    pub id: Id,
    pub main_node: Id,
    pub secondary_nodes: usize,
    pub mass: f64,
    pub center: [f64; 3],
    pub inertia: [f64; 6],
}

#[derive(Serialize)]
pub struct Summary {
    pub deck: String,
    pub title: String,
    pub units: [String; 3],
    pub nodes: usize,
    pub shells4: usize,
    pub shells3: usize,
    pub solids: usize,
    pub bricks: usize,
    pub tetras: usize,
    pub springs: usize,
    pub trusses: usize,
    pub beams: usize,
    pub parts: usize,
    pub materials: usize,
    pub properties: usize,
    pub functions: usize,
    pub interfaces: Vec<InterfaceSummary>,
    pub rigid_walls: usize,
    pub rigid_bodies: usize,
    pub total_mass: f64,
    pub added_mass: f64,
    pub center_of_mass: [f64; 3],
    pub part_masses: BTreeMap<Id, f64>,
    /// Per part: mass, centre and inertia about the centre (xx, yy, zz, xy, yz, xz).
    pub part_details: Vec<PartDetail>,
    /// Per rigid body: id, main node id, number of secondary nodes, mass
    /// (MASS + nodal masses), centre and inertia about the centre.
    pub rigid_body_details: Vec<RigidBodyDetail>,
    pub bounding_box: [[f64; 3]; 2],
    pub shortest_edge: f64,
    pub end_time: Option<f64>,
    pub warnings: Vec<String>,
}

impl Summary {
    pub fn of(model: &Model) -> Summary {
        let n = |k| model.elements_of(k).len();
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        for x in &model.nodes.x {
            for k in 0..3 {
                lo[k] = lo[k].min(x[k]);
                hi[k] = hi[k].max(x[k]);
            }
        }
        Summary {
            deck: model.name.clone(),
            title: model.title.clone(),
            units: [
                model.begin.work_units.mass.clone(),
                model.begin.work_units.length.clone(),
                model.begin.work_units.time.clone(),
            ],
            nodes: model.nodes.len(),
            shells4: n(ElementKind::Shell4),
            shells3: n(ElementKind::Shell3),
            solids: n(ElementKind::Brick8) + n(ElementKind::Tetra4),
            bricks: n(ElementKind::Brick8),
            tetras: n(ElementKind::Tetra4),
            springs: n(ElementKind::Spring),
            trusses: n(ElementKind::Truss),
            beams: n(ElementKind::Beam),
            parts: model.parts.len(),
            materials: model.materials.len(),
            properties: model.properties.len(),
            functions: model.functions.len(),
            interfaces: model
                .interfaces
                .iter()
                .map(|i| InterfaceSummary {
                    id: i.card.id,
                    type_: i.card.type_number(),
                    title: i.card.title.clone(),
                    secondary_nodes: i.secondary_nodes.len(),
                    main_segments: i.main_segments.len(),
                    secondary_edges: i.secondary_edges.len(),
                    main_edges: i.main_edges.len(),
                })
                .collect(),
            rigid_walls: model.rigid_walls.len(),
            rigid_bodies: model.rigid_bodies.len(),
            total_mass: model.mass.total,
            added_mass: model.mass.added_total,
            center_of_mass: model.mass.center,
            part_masses: model
                .parts
                .iter()
                .zip(&model.mass.per_part)
                .map(|(p, m)| (p.id, m.mass))
                .collect(),
            part_details: model
                .parts
                .iter()
                .zip(&model.mass.per_part)
                .map(|(p, m)| PartDetail {
                    id: p.id,
                    title: p.title.clone(),
                    mass: m.mass,
                    center: m.center,
                    inertia: m.inertia,
                })
                .collect(),
            rigid_body_details: model
                .rigid_bodies
                .iter()
                .map(|r| RigidBodyDetail {
                    id: r.card.id,
                    main_node: model.nodes.ids[r.main_node as usize],
                    secondary_nodes: r.secondary_nodes.len(),
                    mass: r.mass,
                    center: r.center,
                    inertia: r.inertia,
                })
                .collect(),
            bounding_box: [lo, hi],
            shortest_edge: geometry_edge_min(model),
            end_time: model
                .engine
                .as_ref()
                .and_then(|e| e.run.as_ref().map(|r| r.tstop)),
            warnings: model.warnings.iter().map(|w| w.to_string()).collect(),
        }
    }

    /// The human-readable table.
    pub fn text(&self) -> String {
        use std::fmt::Write;
        let mut s = String::new();
        let _ = writeln!(s, "deck        {}  ({})", self.deck, self.title);
        let _ = writeln!(
            s,
            "units       {} {} {}",
            self.units[0], self.units[1], self.units[2]
        );
        let rows = [
            ("nodes", self.nodes),
            ("shells (4 nodes)", self.shells4),
            ("shells (3 nodes)", self.shells3),
            ("solids", self.solids),
            ("springs", self.springs),
            ("trusses", self.trusses),
            ("beams", self.beams),
            ("parts", self.parts),
            ("materials", self.materials),
            ("property sets", self.properties),
            ("functions", self.functions),
            ("interfaces", self.interfaces.len()),
            ("rigid walls", self.rigid_walls),
            ("rigid bodies", self.rigid_bodies),
        ];
        for (k, v) in rows {
            let _ = writeln!(s, "{k:<18}{v:>10}");
        }
        for i in &self.interfaces {
            let (sec, n_sec, main, n_main) = if i.secondary_edges + i.main_edges > 0 {
                ("edges", i.secondary_edges, "edges   ", i.main_edges)
            } else {
                ("nodes", i.secondary_nodes, "segments", i.main_segments)
            };
            let _ = writeln!(
                s,
                "  interface {:>8}  TYPE{:<3} secondary {sec} {n_sec:>8}  main {main} {n_main:>8}  {}",
                i.id, i.type_, i.title
            );
        }
        let _ = writeln!(
            s,
            "total mass        {:.10e}   (added {:.6e})",
            self.total_mass, self.added_mass
        );
        let c = self.center_of_mass;
        let _ = writeln!(
            s,
            "centre of mass    {:.6e} {:.6e} {:.6e}",
            c[0], c[1], c[2]
        );
        for p in &self.part_details {
            let _ = writeln!(
                s,
                "  part {:>10}  mass {:.10e}  centre {:.6e} {:.6e} {:.6e}  Ixx Iyy Izz {:.6e} {:.6e} {:.6e}",
                p.id, p.mass, p.center[0], p.center[1], p.center[2], p.inertia[0], p.inertia[1], p.inertia[2]
            );
        }
        let [lo, hi] = self.bounding_box;
        let _ = writeln!(
            s,
            "bounding box      [{:.4e}, {:.4e}] x [{:.4e}, {:.4e}] x [{:.4e}, {:.4e}]",
            lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]
        );
        let _ = writeln!(s, "shortest edge     {:.6e}", self.shortest_edge);
        if let Some(t) = self.end_time {
            let _ = writeln!(s, "end time          {t:e}");
        }
        let _ = writeln!(s, "warnings          {}", self.warnings.len());
        for w in &self.warnings {
            let _ = writeln!(s, "  {w}");
        }
        s
    }
}
