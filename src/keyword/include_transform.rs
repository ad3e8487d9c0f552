//! `*INCLUDE_TRANSFORM`: what it does to the cards of the file it includes
//! (keyword manual volume I, "*INCLUDE_TRANSFORM"; cards 2-5: IDNOFF IDEOFF
//! IDPOFF IDMOFF IDSOFF IDFOFF IDDOFF; IDROFF, PREFIX, SUFFIX; FCTMAS
//! FCTTIM FCTLEN FCTTEM INCOUT1; TRANID).
//!
//! - **Id offsets.** Every id the included cards write, defined there or
//!   referenced, is offset by its kind's offset: nodes IDNOFF, elements
//!   IDEOFF, parts (and nodal rigid bodies, rigid walls) IDPOFF, materials
//!   IDMOFF, sets IDSOFF, curves IDFOFF, other `*DEFINE` ids (vectors,
//!   coordinate systems, transformations) IDDOFF, the rest (sections,
//!   hourglass controls, contacts) IDROFF. 0 (none) and negative values
//!   are kept. Which kind a field is comes from its name in the card (the
//!   tables below); a field the tables do not know, in a file with an
//!   offset, is an error naming it rather than a guess. Set ids whose kind
//!   a type field gives (a contact's SSID with SSTYP) are offset by the
//!   keyword once it has read the type (`Card::offset_by_type`).
//! - **Unit factors.** The included file's values are in units FCTMAS,
//!   FCTTIM, FCTLEN times the deck's ("FCTMAS = 1000 when the include is in
//!   tonnes and the deck in kg"): a value of dimension M^a·T^b·L^c is
//!   multiplied by FCTMAS^a·FCTTIM^b·FCTLEN^c (density a, b, c = 1, 0, −3;
//!   stress 1, −2, −1; ...). A real field the tables do not know, in a file
//!   with a factor other than 1, is an error naming it. Curves
//!   (`*DEFINE_CURVE`) are refused there: their dimensions depend on what
//!   uses them. FCTTEM (temperature conversion) is refused.
//! - **TRANID** (`define_transformation`): the included nodes are moved by
//!   the transformation once the deck is read, after the unit factors (its
//!   rows are in the deck's units).
//!
//! Nested includes compose: offsets add, factors multiply, the inner file's
//! transformation applies first. PREFIX and SUFFIX change titles only.

use crate::model::{Id, Loc};

/// The kinds of ids an offset applies to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum IdKind {
    Node,
    Element,
    Part,
    Material,
    Set,
    Function,
    /// `*DEFINE_` ids other than curves (IDDOFF).
    Define,
    /// Every other id (IDROFF).
    Other,
}

/// One `*INCLUDE_TRANSFORM` (composed with the ones around it).
#[derive(Clone, Debug, PartialEq)]
pub struct Transform {
    /// IDNOFF IDEOFF IDPOFF IDMOFF IDSOFF IDFOFF IDDOFF IDROFF, in
    /// `IdKind` order.
    pub offsets: [i64; 8],
    /// FCTMAS, FCTTIM, FCTLEN (1 when blank or 0).
    pub factors: [f64; 3],
    /// TRANIDs, the innermost file's first, with the card naming each.
    pub tranids: Vec<(Id, Loc)>,
}

impl Transform {
    pub fn identity() -> Transform {
        Transform {
            offsets: [0; 8],
            factors: [1.0; 3],
            tranids: Vec::new(),
        }
    }

    /// This include's transform inside `outer`'s.
    pub fn within(&self, outer: &Transform) -> Transform {
        let mut t = self.clone();
        for k in 0..8 {
            t.offsets[k] += outer.offsets[k];
        }
        for k in 0..3 {
            t.factors[k] *= outer.factors[k];
        }
        t.tranids.extend(outer.tranids.iter().cloned());
        t
    }

    pub fn offset(&self, kind: IdKind) -> i64 {
        self.offsets[kind as usize]
    }

    fn has_offsets(&self) -> bool {
        self.offsets.iter().any(|&o| o != 0)
    }

    fn has_factors(&self) -> bool {
        self.factors.iter().any(|&f| f != 1.0)
    }

    /// An integer field `name` of `keyword` as written (`v`) → as the deck
    /// reads it; Err: what to say about the field.
    pub fn int(&self, keyword: &str, name: &str, v: i64) -> Result<i64, String> {
        if !self.has_offsets() {
            return Ok(v);
        }
        match int_field(keyword, name) {
            Some(IntField::Id(k)) if v > 0 => Ok(v + self.offset(k)),
            Some(_) => Ok(v),
            None => Err(format!(
                "{v}: an id offset of *INCLUDE_TRANSFORM applies to this file, and whether this field is an id (and of which kind) is not known to the reader"
            )),
        }
    }

    /// A real field `name` of `keyword` as written → in the deck's units.
    pub fn real(&self, keyword: &str, name: &str, v: f64) -> Result<f64, String> {
        if !self.has_factors() {
            return Ok(v);
        }
        match dimension(keyword, name) {
            Some([a, b, c]) => Ok(v
                * self.factors[0].powi(a)
                * self.factors[1].powi(b)
                * self.factors[2].powi(c)),
            None => Err(format!(
                "{v}: unit factors of *INCLUDE_TRANSFORM apply to this file, and this field's dimension is not known to the reader (a curve's depends on its use)"
            )),
        }
    }
}

/// The kind of a contact's SSID/MSID by its set type (SSTYP/MSTYP): 3 a
/// part, 5 every part (no id), the others sets.
pub fn contact_set_kind(styp: i64) -> Option<IdKind> {
    match styp {
        3 => Some(IdKind::Part),
        5 => None,
        _ => Some(IdKind::Set),
    }
}

/// What an integer field is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum IntField {
    Id(IdKind),
    /// A flag, count or formulation number: never offset.
    Flag,
    /// An id whose kind a type field gives (`Card::offset_by_type`).
    ByType,
}

/// The kind of integer field `name` in `keyword` (its base name).
pub fn int_field(keyword: &str, name: &str) -> Option<IntField> {
    use IdKind::*;
    use IntField::*;
    let id = |k| Some(Id(k));
    match (keyword, name) {
        // The rigid body's own id is a part's (IDPOFF covers nodal rigid
        // bodies); its CID a coordinate system.
        ("CONSTRAINED_NODAL_RIGID_BODY" | "CONSTRAINED_NODAL_RIGID_BODY_SPC", "CID") => id(Define),
        ("INITIAL_VELOCITY_GENERATION", "ID") => Some(ByType),
        (k, "CID") if k.starts_with("CONTACT_") => id(Other),
        (k, "PID") if k.starts_with("SET_PART") => id(Part),
        (_, "NID" | "N1" | "N2" | "N3" | "N4" | "N5" | "N6" | "N7" | "N8" | "PNODE") => id(Node),
        (_, "EID") => id(Element),
        (_, "PID" | "RWID") => id(Part),
        (_, "MID") => id(Material),
        (_, "SID" | "NSID" | "NSIDEX" | "PSID") => id(Set),
        (_, "LCID" | "LCSS" | "LCSR" | "LCIDAB" | "LCIDDR") => id(Function),
        (_, "CID" | "VID" | "ICID" | "TRANID") => id(Define),
        (_, "SECID" | "HGID") => id(Other),
        (_, "SSID" | "MSID") => Some(ByType),
        (
            _,
            "TC" | "RC" | "ELFORM" | "NIP" | "IHQ" | "ICOMP" | "SOFT" | "SBOPT" | "DEPTH"
            | "FRCFRQ" | "IGNORE" | "SSTYP" | "MSTYP" | "STYP" | "DOF" | "VAD" | "DATTYP" | "AET"
            | "SIDR" | "IRIGID" | "DOFX" | "DOFY" | "DOFZ" | "DOFRX" | "DOFRY" | "DOFRZ" | "CMO"
            | "CON1" | "CON2" | "SBOXID" | "MBOXID",
        ) => Some(Flag),
        _ => None,
    }
}

/// Dimension of real field `name` in `keyword` as exponents of mass, time
/// and length; None when not known (curves).
pub fn dimension(keyword: &str, name: &str) -> Option<[i32; 3]> {
    const ONE: [i32; 3] = [0, 0, 0];
    const LENGTH: [i32; 3] = [0, 0, 1];
    const TIME: [i32; 3] = [0, 1, 0];
    const MASS: [i32; 3] = [1, 0, 0];
    const RATE: [i32; 3] = [0, -1, 0];
    const SPEED: [i32; 3] = [0, -1, 1];
    const STRESS: [i32; 3] = [1, -2, -1];
    const DENSITY: [i32; 3] = [1, 0, -3];
    match (keyword, name) {
        ("DEFINE_CURVE", _) => None,
        // Cowper-Symonds C is a strain rate; Johnson-Cook's C is a number.
        ("MAT_PIECEWISE_LINEAR_PLASTICITY" | "MAT_024", "C") => Some(RATE),
        ("MAT_JOHNSON_COOK" | "MAT_015", "C") => Some(ONE),
        // Specific heat: energy per mass per kelvin.
        (_, "CP") => Some([0, -2, 2]),
        (
            _,
            "X" | "Y" | "Z" | "T1" | "T2" | "T3" | "T4" | "XT" | "YT" | "ZT" | "XH" | "YH" | "ZH",
        ) => Some(LENGTH),
        (_, "RO") => Some(DENSITY),
        (_, "E" | "G" | "SIGY" | "ETAN" | "A" | "B" | "ES") => Some(STRESS),
        (_, "SRC" | "EPSO" | "VXR" | "VYR" | "VZR" | "OMEGA") => Some(RATE),
        (_, "VX" | "VY" | "VZ" | "V0" | "WVEL") => Some(SPEED),
        (_, "MASS") => Some(MASS),
        // Spring stiffness (force per length) and damping (force per speed).
        (_, "K") => Some([1, -2, 0]),
        (_, "DC") => Some([1, -1, 0]),
        (_, "DT" | "BT" | "DTINIT" | "ENDTIM" | "BIRTH" | "DEATH" | "TDEL") => Some(TIME),
        // Temperatures (FCTTEM is refused) and pure numbers.
        (
            _,
            "TM" | "TR" | "PR" | "N" | "M" | "P" | "SRP" | "BETA" | "FAIL" | "FS" | "EPS" | "VP"
            | "SHRF" | "Q1" | "Q2" | "QB" | "QH" | "QM" | "QW" | "S" | "FRIC" | "RWKSF" | "SFS"
            | "SFM" | "SLSFAC" | "SOFSCL" | "VDC" | "RWPNAL" | "XPENE" | "TSSFAC",
        ) => Some(ONE),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn offsets_follow_the_field_kind_and_skip_none() {
        let mut t = Transform::identity();
        t.offsets = [1000, 2000, 30, 40, 50, 60, 70, 80];
        assert_eq!(t.int("NODE", "NID", 5), Ok(1005));
        assert_eq!(t.int("ELEMENT_SHELL", "N3", 7), Ok(1007));
        assert_eq!(t.int("ELEMENT_SHELL", "EID", 7), Ok(2007));
        assert_eq!(t.int("SET_PART_LIST", "PID", 2), Ok(32));
        assert_eq!(t.int("PART", "SECID", 2), Ok(82));
        assert_eq!(t.int("PART", "MID", 2), Ok(42));
        assert_eq!(t.int("LOAD_NODE_POINT", "LCID", 0), Ok(0));
        assert_eq!(t.int("SECTION_SHELL", "ELFORM", 2), Ok(2));
        assert_eq!(t.int("CONTACT_AUTOMATIC_GENERAL", "SSID", 3), Ok(3));
        assert!(t.int("SOMETHING", "XYZID", 3).is_err());
    }

    #[test]
    fn unit_factors_scale_by_dimension() {
        // Include in t, ms, mm; deck in kg, s, m: FCTMAS 1000, FCTTIM 1e-3, FCTLEN 1e-3.
        let mut t = Transform::identity();
        t.factors = [1000.0, 1e-3, 1e-3];
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b.abs();
        // 7.85e-9 t/mm³ = 7850 kg/m³; 210000 MPa (t, ms, mm: 210000 GPa) ...
        assert!(close(t.real("MAT_ELASTIC", "RO", 7.85e-9).unwrap(), 7850.0));
        assert!(close(t.real("NODE", "X", 25.0).unwrap(), 0.025));
        assert!(close(t.real("INITIAL_VELOCITY", "VX", 10.0).unwrap(), 10.0));
        assert!(close(
            t.real("CONTROL_TERMINATION", "ENDTIM", 5.0).unwrap(),
            5e-3
        ));
        assert!(close(t.real("MAT_024", "C", 40.0).unwrap(), 40e3));
        assert!(close(t.real("MAT_015", "C", 0.01).unwrap(), 0.01));
        assert!(t.real("DEFINE_CURVE", "A", 1.0).is_err());
        // t·ms⁻²·mm⁻¹ = 1000 kg / (1e-6 s² · 1e-3 m) = 1e12 Pa.
        assert!(close(t.real("MAT_ELASTIC", "E", 0.21).unwrap(), 0.21e12));
    }

    #[test]
    fn nested_transforms_compose() {
        let mut a = Transform::identity();
        a.offsets[0] = 100;
        a.factors[2] = 10.0;
        let mut b = Transform::identity();
        b.offsets[0] = 5;
        b.factors[2] = 0.5;
        let c = b.within(&a);
        assert_eq!(c.offsets[0], 105);
        assert_eq!(c.factors[2], 5.0);
    }
}
