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
    GeneralSpring(GeneralSpringProperty),
    SpringBeam(SpringBeamProperty),
    /// /PROP/TYPE2 (/PROP/TRUSS).
    Truss(TrussProperty),
    /// /PROP/TYPE3 (/PROP/BEAM).
    Beam(BeamProperty),
    /// /PROP/TYPE45 (/PROP/KJOINT2): a penalty joint between two rigid bodies.
    Joint(JointProperty),
}

/// /PROP/TYPE45 (/PROP/KJOINT2), defaults resolved as the reference
/// starter (research note `docs/notes/kjoint2_research.md` §2): Cr 0 →
/// 0.05, ScF 0 → 1 (Kn = 0, automatic) or 10 (Kn given).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct JointProperty {
    /// 1 spherical, 2 revolute, 3 cylindrical, 4 planar, 5 universal,
    /// 6 translational, 7 Oldham, 8 rigid, 9 free.
    pub joint_type: i64,
    /// Stiffness of the blocked degrees of freedom (0: automatic).
    pub kn: f64,
    pub scf: f64,
    /// Critical damping factor of the blocked degrees of freedom.
    pub cr: f64,
    pub sens_id: super::Id,
    pub skew_ids: [super::Id; 2],
    /// The free degrees of freedom of the type, in the order Tx, Ty, Tz,
    /// Rx, Ry, Rz: (which, its cards).
    pub free: Vec<(usize, JointDof)>,
}

/// The three cards of one free degree of freedom of a KJOINT2.
#[derive(Clone, Debug, Default, Serialize, Deserialize, PartialEq)]
pub struct JointDof {
    /// Stiffness (the scale on `fct_k` when given).
    pub k: f64,
    pub fct_k: super::Id,
    /// Stops: the displacement or angle below S− and above S+ (0: none).
    pub stop_minus: f64,
    pub stop_plus: f64,
    /// Combined stops (input versions after 2017; 0: none).
    pub icomb: i64,
    /// Damping (the scale on `fct_c` when given).
    pub c: f64,
    pub fct_c: super::Id,
    /// Friction stiffness, force or moment and its function.
    pub kf: f64,
    pub friction: f64,
    pub fct_f: super::Id,
}

impl JointProperty {
    /// Kn asks for the automatic stiffness: the reference tests the nearest
    /// integer of Kn against 0.
    pub fn automatic(kn: f64) -> bool {
        kn.round() == 0.0
    }

    /// The free degrees of freedom of a joint type (0-2 translations, 3-5
    /// rotations), research note §2: None for a type that does not exist.
    pub fn free_dofs(joint_type: i64) -> Option<&'static [usize]> {
        Some(match joint_type {
            1 => &[3, 4, 5],
            2 => &[3],
            3 => &[0, 3],
            4 => &[1, 2, 3],
            5 => &[4, 5],
            6 => &[0],
            7 => &[1, 2],
            8 => &[],
            9 => &[0, 1, 2, 3, 4, 5],
            _ => return None,
        })
    }
}

/// /PROP/TYPE2 (/PROP/TRUSS): the cross-section and the initial gap.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct TrussProperty {
    pub area: f64,
    /// The truss carries no force until it has shortened by Gap (0: none).
    pub gap: f64,
}

/// /PROP/TYPE3 (/PROP/BEAM), defaults resolved as the reference starter:
/// df 0 → 0.01.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct BeamProperty {
    pub ismstr: i64,
    /// Membrane and flexural damping.
    pub dm: f64,
    pub df: f64,
    pub area: f64,
    /// Bending moments of area about the local y and z axes, torsion constant.
    pub iyy: f64,
    pub izz: f64,
    pub ixx: f64,
    /// Rotations released (ωx, ωy, ωz at node 1, then at node 2).
    pub released: [bool; 6],
    /// 0: Timoshenko (shear deformation included); 1: without.
    pub ishear: i64,
}

impl PropertyKind {
    /// A spring's mass and rotational inertia (each node takes half); with
    /// Ileng = 1 they are per unit of the initial length `l0`. None for the
    /// other properties.
    pub fn spring_mass(&self, l0: f64) -> Option<(f64, f64)> {
        let per = |ileng: i64| if ileng == 1 { l0 } else { 1.0 };
        match self {
            PropertyKind::Spring(s) => Some((s.mass * per(s.ileng), 0.0)),
            PropertyKind::GeneralSpring(s) => Some((s.mass, s.inertia)),
            PropertyKind::SpringBeam(s) => Some((s.mass * per(s.ileng), s.inertia * per(s.ileng))),
            _ => None,
        }
    }
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
    /// qa and qb were both 0 or blank on the card: LAW70 then has no bulk
    /// viscosity (the reference engine's FACQ0 = 0 for it).
    #[serde(default)]
    pub q_blank: bool,
    /// Hourglass coefficient (0 → 0.1).
    pub h: f64,
    pub lambda_v: f64,
    pub mu_v: f64,
    pub dtmin: f64,
    pub istrain: i64,
    /// /PROP/TYPE6 (SOL_ORTH): the orthotropic directions (None: TYPE14).
    #[serde(default)]
    pub ortho: Option<SolidOrtho>,
}

/// One degree of freedom of a spring property: the three cards
/// `K C A B D` / `fct_ID1 H fct_ID2 fct_ID3 fct_ID4 δmin δmax` /
/// `F E Ascale Hscale` shared by /PROP/TYPE4, TYPE8 and TYPE13 (reference
/// guide /PROP/TYPE4; research note `docs/notes/springs_research.md` §1.1),
/// with the reader's defaults applied: A, D, F, E, Ascale, Hscale 0 → 1;
/// without fct_ID1 A = 1, B = 0, E = 0; a δ bound 0 → none (±∞).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct SpringDof {
    pub k: f64,
    pub c: f64,
    pub a: f64,
    pub b: f64,
    pub d: f64,
    /// Force (or moment) versus displacement: loading curve.
    pub fct_id1: Id,
    /// Hardening flag H (0 elastic, 1 isotropic, 2 uncoupled, 4 kinematic,
    /// 5 nonlinear unloading, 6 isotropic with nonlinear unloading, 7
    /// elastic hysteresis, 8 function of the length).
    pub h: i64,
    /// g(δ̇/F), scaled by E.
    pub fct_id2: Id,
    /// Unloading, lower yield or residual-displacement curve (H = 4-7).
    pub fct_id3: Id,
    /// h(δ̇/F), scaled by Hscale.
    pub fct_id4: Id,
    pub delta_min: f64,
    pub delta_max: f64,
    /// Velocity scale F of g and h.
    pub fscale: f64,
    pub e: f64,
    pub ascale: f64,
    pub hscale: f64,
}

impl SpringDof {
    /// A linear spring and dashpot with no function and no failure.
    pub fn linear(k: f64, c: f64) -> Self {
        SpringDof {
            k,
            c,
            a: 1.0,
            b: 0.0,
            d: 1.0,
            fct_id1: 0,
            h: 0,
            fct_id2: 0,
            fct_id3: 0,
            fct_id4: 0,
            delta_min: f64::NEG_INFINITY,
            delta_max: f64::INFINITY,
            fscale: 1.0,
            e: 0.0,
            ascale: 1.0,
            hscale: 1.0,
        }
    }

    /// The functions it names: (field, id), ids 0 left out.
    pub fn functions(&self) -> impl Iterator<Item = (&'static str, Id)> {
        [
            ("fct_ID1", self.fct_id1),
            ("fct_ID2", self.fct_id2),
            ("fct_ID3", self.fct_id3),
            ("fct_ID4", self.fct_id4),
        ]
        .into_iter()
        .filter(|(_, id)| *id != 0)
    }
}

/// /PROP/TYPE4 (/PROP/SPRING): axial spring, one degree of freedom.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct SpringProperty {
    pub mass: f64,
    pub sens_id: Id,
    pub isflag: i64,
    pub ileng: i64,
    pub dof: SpringDof,
}

/// /PROP/TYPE8 (/PROP/SPR_GENE): general spring, six degrees of freedom
/// (X, Y, Z, RX, RY, RZ of its skew) each with its own [`SpringDof`].
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct GeneralSpringProperty {
    pub mass: f64,
    pub inertia: f64,
    pub skew_id: Id,
    pub sens_id: Id,
    pub isflag: i64,
    /// 0: uni-directional failure; 1: multi-directional Σ(δ/δlim)² > 1.
    pub ifail: i64,
    /// What the failure bounds limit: 0 displacement, 1 force, 2 energy.
    pub ifail2: i64,
    pub iequil: i64,
    pub dofs: [SpringDof; 6],
    /// Filter of the multi-directional criterion (Fsmooth ≠ 0: on, Fcut).
    pub fsmooth: i64,
    pub fcut: f64,
}

/// /PROP/TYPE13 (/PROP/SPR_BEAM): spring beam, six degrees of freedom in a
/// frame that follows the element (tension, shear XY, shear XZ, torsion,
/// bending Y, bending Z).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct SpringBeamProperty {
    pub mass: f64,
    pub inertia: f64,
    pub skew_id: Id,
    pub sens_id: Id,
    pub isflag: i64,
    pub ifail: i64,
    pub ileng: i64,
    pub ifail2: i64,
    pub dofs: [SpringDof; 6],
    /// Reference velocities of the velocity-dependent failure (Ifail2 = 1).
    pub v0: f64,
    pub omega0: f64,
    /// Per direction: c, n, α, β of the failure criterion.
    pub fail: [[f64; 4]; 6],
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

/// The orthotropic directions of a /PROP/TYPE6 (/PROP/SOL_ORTH) solid
/// (research note `docs/notes/law28_sol_orth_research.md` §2): Ip 1, 2, 3
/// put direction 1 at φ in the element's (1,2), (2,3) or (3,1) plane; Ip 0
/// takes the skew's X and Y axes.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct SolidOrtho {
    pub v: [f64; 3],
    pub skew_id: super::Id,
    pub ip: i64,
    pub iorth: i64,
    /// φ in degrees.
    pub phi: f64,
}
