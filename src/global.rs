//! What every rank needs besides its own mesh share: parts, materials,
//! properties, functions, conditions (with global node lists), the engine
//! controls. Rank 0 builds it from the model and broadcasts it.

use crate::model::{
    Bcs, ConcentratedLoad, Damping, Gravity, ImposedMotion, InitialVelocity, Model, Part, Property,
    RigidBody, RigidWall,
};
use crate::model::{Engine, Function, Id, MaterialSpec, Units};
use serde::{Deserialize, Serialize};

#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct GlobalData {
    pub name: String,
    pub title: String,
    pub units: Units,
    pub engine: Engine,
    pub parts: Vec<Part>,
    pub materials: Vec<MaterialSpec>,
    pub properties: Vec<Property>,
    pub functions: Vec<Function>,
    pub bcs: Vec<Bcs>,
    pub imposed_velocities: Vec<ImposedMotion>,
    pub imposed_displacements: Vec<ImposedMotion>,
    pub final_geometries: Vec<crate::model::FinalGeometry>,
    pub pressure_loads: Vec<crate::model::PressureLoad>,
    pub initial_velocities: Vec<InitialVelocity>,
    pub concentrated_loads: Vec<ConcentratedLoad>,
    pub gravity: Vec<Gravity>,
    /// /DAMP, with the engine file's coefficients where it gives them.
    pub dampings: Vec<Damping>,
    pub rigid_walls: Vec<RigidWall>,
    pub rigid_bodies: Vec<RigidBody>,
    /// Global ids of the nodes and of each element kind's elements.
    pub node_ids: Vec<Id>,
    pub element_ids: Vec<Vec<Id>>,
    pub total_mass: f64,
    pub added_mass: f64,
    /// Global indices of the /TH/NODE nodes, in the order the deck lists them.
    pub th_nodes: Vec<u32>,
    /// Keywords the run skips (`--skip-unsupported`), as "file:line: /KEYWORD".
    pub skipped_keywords: Vec<String>,
    /// Contact interfaces, resolved (empty without /INTER).
    pub contact: crate::contact::setup::ContactSetup,
    /// Tied interfaces (/INTER/TYPE2), resolved.
    pub tied: crate::contact::tied::TiedSetup,
}

impl GlobalData {
    pub fn from_model(m: &Model, engine: Engine) -> GlobalData {
        let dampings = with_engine_coefficients(&m.dampings, &engine);
        GlobalData {
            name: m.name.clone(),
            title: m.title.clone(),
            units: m.begin.work_units.clone(),
            engine,
            parts: m.parts.clone(),
            materials: m.materials.clone(),
            properties: m.properties.clone(),
            functions: m.functions.clone(),
            bcs: m.bcs.clone(),
            imposed_velocities: m.imposed_velocities.clone(),
            imposed_displacements: m.imposed_displacements.clone(),
            final_geometries: m.final_geometries.clone(),
            pressure_loads: m.pressure_loads.clone(),
            initial_velocities: m.initial_velocities.clone(),
            concentrated_loads: m.concentrated_loads.clone(),
            gravity: m.gravity.clone(),
            dampings,
            rigid_walls: m.rigid_walls.clone(),
            rigid_bodies: m.rigid_bodies.clone(),
            node_ids: m.nodes.ids.clone(),
            element_ids: m.elements.iter().map(|s| s.ids.clone()).collect(),
            total_mass: m.mass.total,
            added_mass: m.mass.added_total,
            th_nodes: Vec::new(),
            skipped_keywords: Vec::new(),
            contact: Default::default(),
            tied: Default::default(),
        }
    }
}

/// The /DAMP cards with the engine file's coefficients for the ids it names
/// (an id the starter does not define is refused at `run`'s checks).
fn with_engine_coefficients(d: &[Damping], engine: &Engine) -> Vec<Damping> {
    let mut out = d.to_vec();
    for o in &engine.dampings {
        for c in out.iter_mut().filter(|c| c.card.id == o.id) {
            c.card.alpha = o.alpha;
            c.card.beta = o.beta;
        }
    }
    out
}
