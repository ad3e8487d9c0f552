//! Element properties (the section and formulation choices of a part):
//! shell, solid, spring and spring-beam options as the input gives them
//! (0 = default), and the global shell/solid defaults. `properties` resolves
//! the defaults.

use super::{Id, Loc};
use serde::{Deserialize, Serialize};

/// A property: the section and formulation choices of the parts that name it (Radioss: /PROP).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct PropertySpec {
    pub id: Id,
    pub unit_id: Id,
    pub title: String,
    pub kind: PropertyKind,
    pub loc: Loc,
}

/// Which element family the property is for, with its options.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub enum PropertyKind {
    Shell(ShellProperty),
    Solid(SolidProperty),
    Spring(SpringProperty),
    SpringBeam(SpringBeamProperty),
}

/// /PROP/TYPE1 (/PROP/SHELL), as written (0 = default).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct ShellProperty {
    pub ishell: i64,
    pub ismstr: i64,
    pub ish3n: i64,
    pub idrill: i64,
    pub p_thick_fail: f64,
    pub hm: f64,
    pub hf: f64,
    pub hr: f64,
    pub dm: f64,
    pub dn: f64,
    /// Integration points through the thickness (0 = global/default).
    pub n: i64,
    pub istrain: i64,
    pub thick: f64,
    pub ashear: f64,
    pub ithick: i64,
    pub iplas: i64,
}

/// /PROP/TYPE14 (/PROP/SOLID), as written (0 = default).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct SolidProperty {
    pub isolid: i64,
    pub ismstr: i64,
    pub icpre: i64,
    pub itetra10: i64,
    /// Integration points, packed ijk (Isolid 14/16).
    pub inpts: i64,
    pub itetra4: i64,
    pub iframe: i64,
    pub dn: f64,
    /// Quadratic bulk viscosity (0 → 1.1).
    pub qa: f64,
    /// Linear bulk viscosity (0 → 0.05).
    pub qb: f64,
    /// Hourglass coefficient (0 → 0.1).
    pub h: f64,
    pub lambda_v: f64,
    pub mu_v: f64,
    pub dtmin: f64,
    pub istrain: i64,
}

/// /PROP/TYPE4 (/PROP/SPRING): axial spring, linear or through functions.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct SpringProperty {
    pub mass: f64,
    pub sens_id: Id,
    pub isflag: i64,
    pub ileng: i64,
    pub k: f64,
    pub c: f64,
    pub a: f64,
    pub b: f64,
    pub d: f64,
    pub fct_id1: Id,
    pub h: i64,
    pub fct_id2: Id,
    pub fct_id3: Id,
    /// Failure elongations (0 → none).
    pub delta_min: f64,
    pub delta_max: f64,
    pub fscale: f64,
    pub e: f64,
    pub ascale: f64,
}

/// /PROP/TYPE13 (/PROP/SPR_BEAM): six-degree-of-freedom spring beam.
/// Read: mass, inertia and per-direction K, C (six blocks of three cards:
/// K C A B D / fct_ID1 H fct_ID2 fct_ID3 fct_ID4 δmin δmax / F E Ascale Hscale).
/// The function and scale cards are not interpreted yet.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct SpringBeamProperty {
    pub mass: f64,
    pub inertia: f64,
    pub skew_id: Id,
    pub sens_id: Id,
    pub isflag: i64,
    pub ifail: i64,
    pub ileng: i64,
    /// Stiffness per direction (tension, shear s, shear t, torsion, bending y, bending z).
    pub k: [f64; 6],
    /// Damping per direction.
    pub c: [f64; 6],
}

/// /DEF_SHELL: global shell defaults (used where a /PROP/SHELL field is 0).
#[derive(Clone, Debug, Serialize, Deserialize, Default, PartialEq)]
pub struct DefShell {
    pub ishell: i64,
    pub ismstr: i64,
    pub ithick: i64,
    pub iplas: i64,
    pub istrain: i64,
    pub ish3n: i64,
    pub idrill: i64,
}

/// /DEF_SOLID: global solid defaults.
#[derive(Clone, Debug, Serialize, Deserialize, Default, PartialEq)]
pub struct DefSolid {
    pub isolid: i64,
    pub ismstr: i64,
    pub istrain: i64,
    pub iframe: i64,
}
