//! 8-node brick, one-point integration (Radioss /BRICK with /PROP/SOLID
//! Isolid = 1 or 2).
//!
//! # Formulation
//! * **Gradient** (Flanagan & Belytschko 1981, "A uniform strain hexahedron and
//!   quadrilateral with orthogonal hourglass control", IJNME 17, eq. 79): the
//!   uniform-gradient vectors b_a = ∂V/∂x_a = ∫ ∂N_a/∂x dV, written in closed
//!   form with the node permutation table of that paper; V = Σ_a x_a b_a^x.
//!   The mean velocity gradient is L = (1/V) Σ_a v_a ⊗ b_a. (Radioss evaluates
//!   ∂N/∂x at the element centre instead; both coincide for parallelepipeds and
//!   pass the patch test.)
//! * **Configurations** (as in `shell4`): the rate of deformation D and spin W
//!   are taken on the mid-step geometry x^{n+½} = x^{n+1} − ½Δt v^{n+½}. For a
//!   rigid rotation the velocity field is then exactly skew on it (Cayley
//!   transform), so rigid rotations give no strain at any step size. Internal
//!   forces use b and V of x^{n+1}.
//! * **Stress rotation**: Jaumann rate, integrated with the Hughes-Winget
//!   (1980) incrementally objective rule σ ← Q σ Qᵀ, Q = (I − ½ΔtW)⁻¹(I + ½ΔtW).
//!   With the mid-step W this rotates the stress exactly by R for a rigid
//!   rotation R (Radioss applies the first-order Jaumann update σ += (Wσ − σW)Δt).
//! * **Strain measure** (Ismstr, reference guide /PROP/SOLID): 4 = full
//!   geometric non-linearity, the rate form above (default); 2 = the same
//!   (Radioss switches such an element to small strain only under /DT/BRICK/CST,
//!   which this engine does not have); −1 (automatic) → 4; 1 = small strain
//!   from t = 0 on the reference shape (`super::hex8_small`). Ismstr = 3, 11,
//!   12 are refused by name (10: `super::hex8_total`).
//! * **Material**: `Material::solid_update_at` with Δε = D Δt (engineering
//!   shears), the filtered equivalent rate √(⅔ D′:D′) for Johnson-Cook, and the
//!   adiabatic temperature from the element's internal energy per volume.
//!   One point: when it fails (ε_p ≥ EPS_p_max) the element is deleted.
//! * **Internal forces** f_a = (σ − q I) b_a (internal: the solver does
//!   M a = f_ext − f_int).
//! * **Bulk viscosity** (reference engine MQVISCB; theory manual "Stability"):
//!   q = ρ l (qa² l ḋ + qb c) ḋ with ḋ = max(0, −tr D), l = V^{1/3}, ρ the
//!   current density ρ_I V₀/V; q is added to the pressure (σ − q I).
//! * **Hourglass** (reference engine SHVIS3, theory manual "Hourglass Modes"):
//!   base vectors h₁ = ξη, h₂ = ηζ, h₃ = ζξ, h₄ = ξηζ (entries ±1, Radioss node
//!   order: 1-4 bottom face, 5-8 top). Isolid 1 (Belytschko, "orthogonal and
//!   rigid deformation modes compensation") uses the Flanagan-Belytschko vectors
//!   γ_α = h_α − (1/V)(h_α·x_i) b_i, orthogonal to every linear velocity field;
//!   Isolid 2 (Hallquist, "without orthogonality") uses h_α itself. Mode rates
//!   q_α = Σ_a Γ_αa v_a (3 components), generalized forces
//!   Q_α = q_α (C_l + |q_α| C_q), C_l = (h/4) ρ c V^{2/3}, C_q = (h/4)² 100 ρ V^{2/3},
//!   corner forces f_a += Σ_α Γ_αa Q_α, dissipated power Σ_α Q_α·q_α.
//!   (Isolid 2 does not conserve angular momentum on distorted bricks, as in Radioss.)
//! * **Time step** (theory manual "Stability", reference engine SDLEN3/SLEN and
//!   MQVISCB): l_c = V / A_max, A_face = ½|d₁₃ × d₂₄| (largest of the six faces;
//!   for a parallelepiped the smallest distance between opposite faces);
//!   Δt = l_c / (Q + √(Q² + c²)), Q = qb c + l_c qa² ḋ, c = √((λ + 2μ)/ρ₀)
//!   ("c = √(K/ρ + 4μ/3ρ) = √((λ+2μ)/ρ) for a solid elastic material"), ρ₀ = RHO_0.
//!   Unscaled (the solver applies the /DT scale factor). With qa = qb = 0 a unit
//!   cube gives exactly 1/c; with the default qb = 0.05 it gives 1/(1.0513 c).
//!
//! No heap allocation: everything is fixed-size on the stack.

use super::hex8_small::SmallStrainRef;
use crate::material::{FailAt, Failure, Law70Point, Material};
use crate::model::ResolvedSolid;
pub(crate) use crate::vec3::rotate_voigt;
use crate::vec3::spin_rotation;
use serde::{Deserialize, Serialize};

/// Resolved section data for one solid part (from [`ResolvedSolid`] + the part's [`Material`]).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct SolidSection {
    /// 1 (Flanagan-Belytschko orthogonal hourglass) or 2 (Hallquist); 0 for tetrahedra.
    pub isolid: i64,
    /// Strain formulation actually used (4: rate form).
    pub ismstr: i64,
    /// Quadratic and linear bulk viscosity.
    pub qa: f64,
    pub qb: f64,
    /// Hourglass viscosity coefficient.
    pub h: f64,
    pub material: Material,
    /// Dilatational wave speed √((λ+2μ)/ρ₀).
    pub c: f64,
    /// The material's failure model (/FAIL), if any.
    pub failure: Option<Failure>,
    /// Icpre as the formulation uses it (HA8: 0, 1 or 2; 0 elsewhere).
    pub icpre: i64,
    /// /PROP/TYPE6: the orthotropic directions (`super::ortho`).
    pub ortho: Option<crate::model::SolidOrtho>,
}

fn check_ismstr(r: &ResolvedSolid) -> Result<i64, String> {
    match r.ismstr {
        1 if r.isolid == 1 || r.isolid == 2 => Ok(1),
        -1 => Ok(4),
        2 | 4 => Ok(r.ismstr),
        v => Err(format!(
            "Ismstr = {v} is not supported here: the engine computes solids with Ismstr = 2 or 4 (full geometric non-linearity, rate form), and Ismstr = 1 (small strain from t = 0) on the one-point bricks Isolid 1 and 2"
        )),
    }
}

/// LAW36's tension damage needs the points' total strain, which the solids
/// do not keep yet.
fn refuse_tension_damage(m: &Material) -> Result<(), String> {
    match m.tension_damage() {
        Some(_) => Err(
            "/MAT/LAW36: the tension damage (Eps_t, Eps_m, Eps_f) is not computed on solids yet"
                .into(),
        ),
        None => Ok(()),
    }
}

/// A total-strain law (LAW62) is computed by the total-strain brick only
/// (`super::hex8_total`, Ismstr = 10).
fn refuse_total_strain(m: &Material) -> Result<(), String> {
    if m.total_strain() {
        return Err(format!(
            "/MAT/LAW{} computes its stress from the total deformation: expected a one-point brick (Isolid 1 or 2) with Ismstr = 10",
            m.law_number()
        ));
    }
    Ok(())
}

/// Ismstr = 1 (small strain, `super::hex8_small`) and LAW70 are computed
/// on the one-point bricks (Isolid 1, 2) only: `what` refuses them by name.
pub(crate) fn refuse_small_and_foam(
    r: &ResolvedSolid,
    m: &Material,
    what: &str,
) -> Result<(), String> {
    if r.ismstr == 1 {
        return Err(format!(
            "Ismstr = 1 (small strain) on {what}: the engine computes it on the one-point bricks (Isolid 1, 2) only"
        ));
    }
    if m.foam_tab().is_some() {
        return Err(format!(
            "/MAT/LAW70 on {what}: the engine computes it on the one-point bricks (Isolid 1, 2) only"
        ));
    }
    Ok(())
}

/// /PROP/TYPE6 on a formulation that does not compute its directions.
pub(crate) fn refuse_ortho(r: &ResolvedSolid, what: &str) -> Result<(), String> {
    if r.ortho.is_some() {
        return Err(format!(
            "/PROP/TYPE6 (SOL_ORTH) on {what}: the orthotropic directions are computed on the one-point bricks (Isolid 1, 2) and HEPH (Isolid 24) only"
        ));
    }
    Ok(())
}

fn dilatational_speed(m: &Material) -> f64 {
    let (e, nu) = (m.young(), m.poisson());
    let lam_2mu = e * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));
    (lam_2mu / m.rho_ref()).sqrt()
}

impl SolidSection {
    /// Section of an 8-node brick part: Isolid 1 or 2, Iframe 1, Ismstr 2/4.
    pub fn new(r: &ResolvedSolid, m: &Material) -> Result<SolidSection, String> {
        match r.isolid {
            1 | 2 => {}
            v => {
                return Err(format!(
                    "Isolid = {v} is not supported: the engine computes bricks with Isolid = 1 (Belytschko viscous hourglass), 2 (Hallquist viscous hourglass) or 14 (HA8, fully integrated)"
                ))
            }
        }
        if r.iframe != 1 {
            return Err(format!(
                "Iframe = {}: only Iframe = 1 (non-corotational) is supported for Isolid = 1, 2",
                r.iframe
            ));
        }
        let ismstr = check_ismstr(r)?;
        m.check_supported()?;
        refuse_tension_damage(m)?;
        refuse_total_strain(m)?;
        if let Some(why) = r.ortho.as_ref().and_then(super::ortho::refusal) {
            return Err(why);
        }
        // LAW70 with qa and qb blank has no bulk viscosity: the reference
        // engine sets FACQ0 = 0 for it (research note law70_research.md §3).
        let no_q = r.q_blank && m.foam_tab().is_some();
        Ok(SolidSection {
            isolid: r.isolid,
            ismstr,
            qa: if no_q { 0.0 } else { r.qa },
            qb: if no_q { 0.0 } else { r.qb },
            h: r.h,
            material: m.clone(),
            c: dilatational_speed(m),
            failure: None,
            icpre: 0,
            ortho: r.ortho.clone(),
        })
    }

    /// Section of a 4-node tetrahedron part (the same /PROP/SOLID; Isolid and h
    /// do not apply). Itetra4 0 or 1000 (standard formulation) only.
    pub fn for_tetra(r: &ResolvedSolid, m: &Material) -> Result<SolidSection, String> {
        if r.itetra4 != 0 && r.itetra4 != 1000 {
            return Err(format!(
                "Itetra4 = {}: only the standard 4-node tetrahedron (Itetra4 = 0 or 1000) is supported",
                r.itetra4
            ));
        }
        refuse_small_and_foam(r, m, "tetrahedra")?;
        let ismstr = check_ismstr(r)?;
        m.check_supported()?;
        refuse_tension_damage(m)?;
        refuse_total_strain(m)?;
        refuse_ortho(r, "tetrahedra")?;
        Ok(SolidSection {
            isolid: 0,
            ismstr,
            qa: r.qa,
            qb: r.qb,
            h: 0.0,
            material: m.clone(),
            c: dilatational_speed(m),
            failure: None,
            icpre: 0,
            ortho: None,
        })
    }
}

/// Per-element state kept by the solver (fixed size; what only some
/// sections need is boxed).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Hex8State {
    /// Cauchy stress [σxx σyy σzz σxy σyz σzx] (global frame), without bulk viscosity.
    pub sig: [f64; 6],
    /// Equivalent plastic strain.
    pub eps_p: f64,
    /// Damage of the failure model (/FAIL; 1 = failed).
    pub dmg: f64,
    /// The law's extra history (LAW21: the volumetric strain μ of the last step).
    #[serde(default)]
    pub hist: f64,
    /// Last hourglass generalized forces Q_α (4 modes × 3 components), for output.
    pub hg: [[f64; 3]; 4],
    /// Cumulative internal energy (stress and bulk viscosity work, without hourglass).
    pub eint: f64,
    /// Cumulative hourglass energy.
    pub ehg: f64,
    /// Cumulative plastic work.
    pub eplas: f64,
    /// Initial volume.
    pub vol0: f64,
    /// Volume at the last step.
    pub vol: f64,
    /// Filtered equivalent strain rate (Johnson-Cook rate term).
    pub eps_dot: f64,
    /// The integration point failed: the element is deleted.
    pub deleted: bool,
    /// /PROP/TYPE6 sections: the directions and the law's point state.
    #[serde(default)]
    pub ortho: super::ortho::OrthoState,
    /// Ismstr = 1: the reference shape (`super::hex8_small`).
    #[serde(default)]
    pub small: Option<Box<SmallStrainRef>>,
    /// LAW70: the point's total strain and history.
    #[serde(default)]
    pub foam: Option<Box<Law70Point>>,
}

/// What one element step returns.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Hex8Out {
    /// Internal corner forces; the solver subtracts them (M a = f_ext − f).
    pub f: [[f64; 3]; 8],
    /// Critical (unscaled) time step; ∞ for a deleted or inverted element.
    pub dt: f64,
    /// Internal energy increment (stress + bulk viscosity work, excluding hourglass).
    pub d_eint: f64,
    /// Hourglass energy increment.
    pub d_ehg: f64,
    /// Plastic work increment (included in `d_eint`).
    pub d_eplas: f64,
    /// The element is deleted (its point failed).
    pub failed: bool,
    /// Zero or negative volume at x^{n+1} or mid-step: the solver stops.
    pub bad_volume: bool,
}

// ---- small 3-vector / 3×3 helpers (shared with tet4) ---------------------------

pub(crate) use crate::vec3::{cross, dot, sub};

/// Permutation table of Flanagan & Belytschko (1981) for the closed-form
/// uniform gradient: row a lists the nodes playing the roles 1..8 for node a.
const FB_PERM: [[usize; 8]; 8] = [
    [0, 1, 2, 3, 4, 5, 6, 7],
    [1, 2, 3, 0, 5, 6, 7, 4],
    [2, 3, 0, 1, 6, 7, 4, 5],
    [3, 0, 1, 2, 7, 4, 5, 6],
    [4, 7, 6, 5, 0, 3, 2, 1],
    [5, 4, 7, 6, 1, 0, 3, 2],
    [6, 5, 4, 7, 2, 1, 0, 3],
    [7, 6, 5, 4, 3, 2, 1, 0],
];

/// One Cartesian component of the uniform-gradient vectors (FB 1981 eq. 79):
/// b^x from (y, z), b^y from (z, x), b^z from (x, y).
#[inline]
fn fb_component(y: &[f64; 8], z: &[f64; 8]) -> [f64; 8] {
    let mut b = [0.0; 8];
    for (a, p) in FB_PERM.iter().enumerate() {
        let (y2, y3, y4, y5, y6, y8) = (y[p[1]], y[p[2]], y[p[3]], y[p[4]], y[p[5]], y[p[7]]);
        let (z2, z3, z4, z5, z6, z8) = (z[p[1]], z[p[2]], z[p[3]], z[p[4]], z[p[5]], z[p[7]]);
        b[a] = (y2 * ((z6 - z3) - (z4 - z5))
            + y3 * (z2 - z4)
            + y4 * ((z3 - z8) - (z5 - z2))
            + y5 * ((z8 - z6) - (z2 - z4))
            + y6 * (z5 - z2)
            + y8 * (z4 - z5))
            / 12.0;
    }
    b
}

/// Uniform-gradient vectors b_a = ∂V/∂x_a and the volume V of a hexahedron.
#[inline]
pub(crate) fn hex_gradient(x: &[[f64; 3]; 8]) -> ([[f64; 3]; 8], f64) {
    let mut cx = [0.0; 8];
    let mut cy = [0.0; 8];
    let mut cz = [0.0; 8];
    for a in 0..8 {
        cx[a] = x[a][0];
        cy[a] = x[a][1];
        cz[a] = x[a][2];
    }
    let bx = fb_component(&cy, &cz);
    let by = fb_component(&cz, &cx);
    let bz = fb_component(&cx, &cy);
    let mut b = [[0.0; 3]; 8];
    let mut vol = 0.0;
    for a in 0..8 {
        b[a] = [bx[a], by[a], bz[a]];
        vol += cx[a] * bx[a];
    }
    (b, vol)
}

/// Hourglass base vectors h₁ = ξη, h₂ = ηζ, h₃ = ζξ, h₄ = ξηζ (up to sign),
/// Radioss node order (reference engine SHVIS3).
pub(crate) const HG_BASE: [[f64; 8]; 4] = [
    [1.0, -1.0, 1.0, -1.0, 1.0, -1.0, 1.0, -1.0],
    [1.0, 1.0, -1.0, -1.0, -1.0, -1.0, 1.0, 1.0],
    [1.0, -1.0, -1.0, 1.0, -1.0, 1.0, 1.0, -1.0],
    [1.0, -1.0, 1.0, -1.0, -1.0, 1.0, -1.0, 1.0],
];

/// Largest face area of a hexahedron, ½|d₁₃ × d₂₄| per face (reference engine SLEN).
#[inline]
pub(crate) fn hex_max_face_area(x: &[[f64; 3]; 8]) -> f64 {
    const FACES: [[usize; 4]; 6] = [
        [0, 1, 2, 3],
        [4, 5, 6, 7],
        [0, 1, 5, 4],
        [1, 2, 6, 5],
        [2, 3, 7, 6],
        [3, 0, 4, 7],
    ];
    let mut amax: f64 = 0.0;
    for f in FACES {
        let n = cross(sub(x[f[2]], x[f[0]]), sub(x[f[3]], x[f[1]]));
        amax = amax.max(dot(n, n));
    }
    0.5 * amax.sqrt()
}

/// Velocity gradient L_ij = ∂v_i/∂x_j = (1/V) Σ_a v_ai b_aj.
#[inline]
pub(crate) fn velocity_gradient<const N: usize>(
    v: &[[f64; 3]; N],
    b: &[[f64; 3]; N],
    vol: f64,
) -> [[f64; 3]; 3] {
    let mut l = [[0.0; 3]; 3];
    for a in 0..N {
        for i in 0..3 {
            for j in 0..3 {
                l[i][j] += v[a][i] * b[a][j];
            }
        }
    }
    let r = 1.0 / vol;
    for row in l.iter_mut() {
        for e in row.iter_mut() {
            *e *= r;
        }
    }
    l
}

/// Hughes-Winget rotation of a Voigt stress by the spin increment W Δt:
/// σ ← Q σ Qᵀ (`crate::vec3::spin_rotation`).
#[inline]
pub(crate) fn rotate_stress(s: &mut [f64; 6], w: &[[f64; 3]; 3], dt: f64) {
    let Some(q) = spin_rotation(w, dt) else {
        return;
    };
    let sm = [[s[0], s[3], s[5]], [s[3], s[1], s[4]], [s[5], s[4], s[2]]];
    let mut qs = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            qs[i][j] = q[i][0] * sm[0][j] + q[i][1] * sm[1][j] + q[i][2] * sm[2][j];
        }
    }
    let r = |i: usize, j: usize| qs[i][0] * q[j][0] + qs[i][1] * q[j][1] + qs[i][2] * q[j][2];
    *s = [r(0, 0), r(1, 1), r(2, 2), r(0, 1), r(1, 2), r(2, 0)];
}

/// A strain with engineering shears turned as a stress ([`rotate_stress`]).
#[inline]
fn rotate_strain(e: &mut [f64; 6], w: &[[f64; 3]; 3], dt: f64) {
    let mut t = [e[0], e[1], e[2], 0.5 * e[3], 0.5 * e[4], 0.5 * e[5]];
    rotate_stress(&mut t, w, dt);
    *e = [t[0], t[1], t[2], 2.0 * t[3], 2.0 * t[4], 2.0 * t[5]];
}

/// Result of the shared one-point stress update of a solid.
pub(crate) struct SolidPoint {
    /// Stress used for the forces: σ − q I.
    pub sig_f: [f64; 6],
    pub d_eint: f64,
    pub d_eplas: f64,
    pub failed: bool,
    /// max(0, −tr D), for the time step.
    pub compress: f64,
    /// The wave speed after the update (the section's, or LAW70's of the
    /// point's secant modulus).
    pub c: f64,
}

/// Stress update of a one-point solid from the mid-step velocity gradient:
/// objective rotation, material update, bulk viscosity, energies.
/// `vol_mid`: mid-step volume (energy), `vol`: volume at x^{n+1} (density, q).
#[allow(clippy::too_many_arguments)]
pub(crate) fn solid_point_update(
    sec: &SolidSection,
    l: &[[f64; 3]; 3],
    vol_mid: f64,
    vol: f64,
    vol0: f64,
    dt: f64,
    sig: &mut [f64; 6],
    eps_p: &mut f64,
    dmg: &mut f64,
    hist: &mut f64,
    eps_dot: &mut f64,
    eint: f64,
    ortho: Option<(&[[f64; 3]; 3], &mut super::ortho::OrthoState)>,
    mut foam: Option<&mut Law70Point>,
) -> SolidPoint {
    let mat = &sec.material;
    let d = [
        l[0][0],
        l[1][1],
        l[2][2],
        0.5 * (l[0][1] + l[1][0]),
        0.5 * (l[1][2] + l[2][1]),
        0.5 * (l[2][0] + l[0][2]),
    ];
    let tr = d[0] + d[1] + d[2];
    let compress = (-tr).max(0.0);
    let mut out = SolidPoint {
        sig_f: [0.0; 6],
        d_eint: 0.0,
        d_eplas: 0.0,
        failed: false,
        compress,
        c: sec.c,
    };
    if dt > 0.0 {
        let w = crate::vec3::spin(l);
        rotate_stress(sig, &w, dt);
        let old = *sig;
        // The law's strain rate (the deviatoric equivalent √(⅔ D′:D′) for most).
        let raw = mat.solid_strain_rate(&d);
        *eps_dot = mat.filter_strain_rate(*eps_dot, raw, dt);
        let temp = mat.temperature(eint / vol_mid);
        let deps = [
            d[0] * dt,
            d[1] * dt,
            d[2] * dt,
            2.0 * d[3] * dt,
            2.0 * d[4] * dt,
            2.0 * d[5] * dt,
        ];
        let ep0 = *eps_p;
        let law12 = mat.composite3d();
        let wp = if let (Some(pt), Some(law)) = (foam.as_deref_mut(), mat.foam_tab()) {
            // LAW70 on its total strain, turned as the stress is.
            rotate_strain(&mut pt.eps, &w, dt);
            *sig = law.update(pt, &deps, *eps_dot);
            0.0
        } else {
            match (ortho, law12) {
                // The orthotropic law in its material axes (`super::ortho`).
                (Some((axes, os)), Some(law)) => {
                    super::ortho::update(law, axes, sig, eps_p, os, deps)
                }
                _ => {
                    mat.solid_update_volumetric(sig, eps_p, hist, deps, *eps_dot, temp, vol0 / vol)
                }
            }
        };
        out.failed = mat.has_failed(*eps_p);
        if let (Some(f), false) = (&sec.failure, out.failed) {
            let tstar = mat.homologous_temperature(temp);
            let at = FailAt {
                rate: *eps_dot,
                tstar,
                ..Default::default()
            };
            out.failed = f.solid(sig, dmg, *eps_p - ep0, &at);
        }
        if out.failed {
            *sig = [0.0; 6];
        }
        let mut p = 0.0;
        for k in 0..6 {
            let wk = if k < 3 { 1.0 } else { 2.0 };
            p += wk * 0.5 * (old[k] + sig[k]) * d[k];
        }
        out.d_eint = p * vol_mid * dt;
        out.d_eplas = wp * vol_mid;
    }
    if let (Some(pt), Some(law)) = (foam.as_deref(), mat.foam_tab()) {
        out.c = law.point_sound_speed(pt);
    }
    let mut q = 0.0;
    if compress > 0.0 && !out.failed {
        q = bulk_viscosity_c(sec, out.c, vol0, vol, compress);
        // LAW12 books the law's work only: its bulk viscosity's work is
        // outside the internal energy, as the reference's (note
        // law12_research.md §1.3, step 10).
        if sec.material.composite3d().is_none() {
            out.d_eint += q * compress * vol_mid * dt;
        }
    }
    out.sig_f = *sig;
    for k in 0..3 {
        out.sig_f[k] -= q;
    }
    out
}

/// Δt = l_c / (Q + √(Q² + c²)), Q = qb c + l_c qa² ḋ (reference engine MQVISCB).
#[inline]
pub(crate) fn solid_time_step(sec: &SolidSection, lc: f64, compress: f64) -> f64 {
    solid_time_step_c(sec, sec.c, lc, compress)
}

/// [`solid_time_step`] with the wave speed `c` of the point.
#[inline]
pub(crate) fn solid_time_step_c(sec: &SolidSection, c: f64, lc: f64, compress: f64) -> f64 {
    let q = sec.qb * c + lc * sec.qa * sec.qa * compress;
    lc / (q + (q * q + c * c).sqrt())
}

/// Von Mises stress of a Voigt stress.
pub(crate) fn von_mises(s: &[f64; 6]) -> f64 {
    let d = (s[0] - s[1]).powi(2) + (s[1] - s[2]).powi(2) + (s[2] - s[0]).powi(2);
    (0.5 * d + 3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]))
        .max(0.0)
        .sqrt()
}

/// Internal force of a constant stress on the gradient vector b: σ b.
#[inline]
pub(crate) fn stress_force(s: &[f64; 6], b: [f64; 3]) -> [f64; 3] {
    [
        s[0] * b[0] + s[3] * b[1] + s[5] * b[2],
        s[3] * b[0] + s[1] * b[1] + s[4] * b[2],
        s[5] * b[0] + s[4] * b[1] + s[2] * b[2],
    ]
}

/// Element state at t = 0 (stress-free; a /PROP/TYPE6 section's
/// directions in the element axes).
pub fn hex8_init(sec: &SolidSection, x: &[[f64; 3]; 8]) -> Hex8State {
    let (_, vol) = hex_gradient(x);
    let mut ortho = super::ortho::OrthoState::default();
    if let Some(o) = &sec.ortho {
        ortho.gama = super::ortho::initial_gama(o, &super::ortho::element_axes(x));
    }
    Hex8State {
        vol0: vol,
        vol,
        ortho,
        small: (sec.ismstr == 1).then(|| Box::new(SmallStrainRef::new(x))),
        foam: sec.material.foam_tab().map(|_| Box::default()),
        ..Default::default()
    }
}

/// Bulk viscosity (MQVISCB) of a brick compressing at the rate `compress`
/// (> 0): q = ρ l ḋ (qa² l ḋ + qb c), l = V^{1/3}, ρ = ρ_I V₀/V. Shared by
/// every brick formulation (`super::ha8`, `super::heph`).
pub(crate) fn bulk_viscosity(sec: &SolidSection, vol0: f64, vol: f64, compress: f64) -> f64 {
    bulk_viscosity_c(sec, sec.c, vol0, vol, compress)
}

/// [`bulk_viscosity`] with the wave speed `c` of the point.
fn bulk_viscosity_c(sec: &SolidSection, c: f64, vol0: f64, vol: f64, compress: f64) -> f64 {
    let rho = sec.material.rho() * vol0 / vol;
    let al = vol.cbrt();
    rho * al * compress * (sec.qa * sec.qa * al * compress + sec.qb * c)
}

/// The viscous hourglass of a one-point brick (Isolid 1: Flanagan-Belytschko
/// orthogonal modes; 2: the Hallquist base vectors), added to the corner
/// forces `f`; `rho` is the current density and `c` the wave speed. Keeps
/// the generalized forces Q_α in `hg` and returns the hourglass energy of
/// the step. Shared by every one-point brick (`super::hex8_total`).
#[allow(clippy::too_many_arguments)]
#[inline]
pub(crate) fn viscous_hourglass(
    sec: &SolidSection,
    x: &[[f64; 3]; 8],
    v: &[[f64; 3]; 8],
    b: &[[f64; 3]; 8],
    vol: f64,
    rho: f64,
    c: f64,
    dt: f64,
    f: &mut [[f64; 3]; 8],
    hg: &mut [[f64; 3]; 4],
) -> f64 {
    let mut gam = HG_BASE;
    if sec.isolid == 1 {
        let r = 1.0 / vol;
        for (g, h) in gam.iter_mut().zip(HG_BASE.iter()) {
            let mut hx = [0.0; 3];
            for a in 0..8 {
                for k in 0..3 {
                    hx[k] += h[a] * x[a][k];
                }
            }
            for a in 0..8 {
                g[a] -= r * dot(hx, b[a]);
            }
        }
    }
    let caq = 0.25 * sec.h;
    let base = caq * rho * vol.powf(2.0 / 3.0);
    let (cl, cq) = (base * c, base * caq * 100.0);
    let mut power = 0.0;
    for (m, g) in gam.iter().enumerate() {
        let mut qv = [0.0; 3];
        for a in 0..8 {
            for k in 0..3 {
                qv[k] += g[a] * v[a][k];
            }
        }
        let mut qf = [0.0; 3];
        for k in 0..3 {
            qf[k] = qv[k] * (cl + qv[k].abs() * cq);
            power += qf[k] * qv[k];
        }
        hg[m] = qf;
        for a in 0..8 {
            for k in 0..3 {
                f[a][k] += g[a] * qf[k];
            }
        }
    }
    power * dt
}

/// The uniform gradient and volume of the mid-step geometry
/// x^{n+½} = x^{n+1} − ½Δt v^{n+½} (shared with `super::hex8_total`).
#[inline]
pub(crate) fn mid_step_gradient(
    x: &[[f64; 3]; 8],
    v: &[[f64; 3]; 8],
    dt: f64,
) -> ([[f64; 3]; 8], f64) {
    let mut xm = *x;
    for a in 0..8 {
        for k in 0..3 {
            xm[a][k] -= 0.5 * dt * v[a][k];
        }
    }
    hex_gradient(&xm)
}

/// The unscaled time step of a one-point brick of shape `x` at rest (no
/// compression term) with the wave speed `c`.
pub(crate) fn brick_rest_step(sec: &SolidSection, c: f64, x: &[[f64; 3]; 8]) -> f64 {
    let (_, vol) = hex_gradient(x);
    solid_time_step_c(sec, c, vol / hex_max_face_area(x), 0.0)
}

impl Hex8State {
    /// [`brick_rest_step`] of the element in the shape `x`: the reference
    /// shape under small strain, LAW70's wave speed of the point's secant
    /// modulus.
    pub fn rest_time_step(&self, sec: &SolidSection, x: &[[f64; 3]; 8]) -> f64 {
        let x = self.small.as_deref().map_or(*x, SmallStrainRef::corners);
        let c = match (self.foam.as_deref(), sec.material.foam_tab()) {
            (Some(pt), Some(law)) => law.point_sound_speed(pt),
            _ => sec.c,
        };
        brick_rest_step(sec, c, &x)
    }
}

/// The geometry a step of one brick uses: gradient vectors and volume for
/// the strain rate (mid-step) and for the forces, and the corners of the
/// hourglass and the time step. Ismstr = 1 takes the reference shape for
/// all of them (`super::hex8_small`); otherwise x^{n+½} and x^{n+1}.
struct StepGeometry {
    bm: [[f64; 3]; 8],
    volm: f64,
    b: [[f64; 3]; 8],
    vol: f64,
    x: [[f64; 3]; 8],
}

fn step_geometry(
    x: &[[f64; 3]; 8],
    v: &[[f64; 3]; 8],
    dt: f64,
    small: Option<&mut SmallStrainRef>,
) -> Option<StepGeometry> {
    if let Some(r) = small {
        return small_strain_geometry(r, v, dt);
    }
    let (b, vol) = hex_gradient(x);
    if !(vol > 0.0) {
        return None;
    }
    let (bm, volm) = if dt > 0.0 {
        mid_step_gradient(x, v, dt)
    } else {
        (b, vol)
    };
    (volm > 0.0).then_some(StepGeometry {
        bm,
        volm,
        b,
        vol,
        x: *x,
    })
}

/// Ismstr = 1: the strain rate on the reference shape turned by half the
/// step's spin (the spin of the shape at the step's start first), the
/// forces on the shape turned by the whole step, which `r` keeps: a rigid
/// turn gives a strain of the third order in the step's angle.
fn small_strain_geometry(
    r: &mut SmallStrainRef,
    v: &[[f64; 3]; 8],
    dt: f64,
) -> Option<StepGeometry> {
    let x0 = r.corners();
    let (b0, vol0) = hex_gradient(&x0);
    if !(vol0 > 0.0) {
        return None;
    }
    if !(dt > 0.0) {
        return Some(StepGeometry {
            bm: b0,
            volm: vol0,
            b: b0,
            vol: vol0,
            x: x0,
        });
    }
    let mut half = *r;
    half.turn(&velocity_gradient(v, &b0, vol0), 0.5 * dt);
    let (bm, volm) = hex_gradient(&half.corners());
    half.turn(&velocity_gradient(v, &bm, volm), 0.5 * dt);
    r.x = half.x;
    let x = r.corners();
    let (b, vol) = hex_gradient(&x);
    Some(StepGeometry {
        bm,
        volm,
        b,
        vol,
        x,
    })
}

/// One explicit step of one brick: stress from x^{n+1} and v^{n+½}, internal
/// corner forces at x^{n+1}, energies and the element time step.
/// With `dt = 0` only the forces of the current stress and the time step are computed.
pub fn hex8_step(
    sec: &SolidSection,
    x: &[[f64; 3]; 8],
    v: &[[f64; 3]; 8],
    dt: f64,
    st: &mut Hex8State,
) -> Hex8Out {
    let mut out = Hex8Out {
        dt: f64::INFINITY,
        ..Default::default()
    };
    if st.deleted {
        out.failed = true;
        return out;
    }
    let Some(g) = step_geometry(x, v, dt, st.small.as_deref_mut()) else {
        out.bad_volume = true;
        return out;
    };
    let l = velocity_gradient(v, &g.bm, g.volm);
    // The volume the density follows: V₀ρ₀/ρ under small strain.
    let vol_rho = match st.small.as_deref_mut() {
        Some(r) => {
            r.advance_density(l[0][0] + l[1][1] + l[2][2], st.vol0, g.volm, dt);
            st.vol0 / r.rho_ratio
        }
        None => g.vol,
    };
    // /PROP/TYPE6: the material axes follow the element axes (Iframe 1).
    let axes = sec
        .ortho
        .as_ref()
        .map(|_| super::ortho::material_axes(&st.ortho.gama, &super::ortho::element_axes(x)));
    let p = solid_point_update(
        sec,
        &l,
        g.volm,
        vol_rho,
        st.vol0,
        dt,
        &mut st.sig,
        &mut st.eps_p,
        &mut st.dmg,
        &mut st.hist,
        &mut st.eps_dot,
        st.eint,
        axes.as_ref().map(|a| (a, &mut st.ortho)),
        st.foam.as_deref_mut(),
    );
    st.vol = vol_rho;
    st.eint += p.d_eint;
    st.eplas += p.d_eplas;
    out.d_eint = p.d_eint;
    out.d_eplas = p.d_eplas;
    if p.failed {
        st.deleted = true;
        out.failed = true;
        return out;
    }
    for a in 0..8 {
        out.f[a] = stress_force(&p.sig_f, g.b[a]);
    }

    if sec.h > 0.0 {
        // Small strain: ρ₀ and V_ref (research note solid_ismstr1_research.md §4).
        let rho = match st.small {
            Some(_) => sec.material.rho(),
            None => sec.material.rho() * st.vol0 / g.vol,
        };
        out.d_ehg = viscous_hourglass(
            sec, &g.x, v, &g.b, g.vol, rho, p.c, dt, &mut out.f, &mut st.hg,
        );
        st.ehg += out.d_ehg;
    }

    let lc = g.vol / hex_max_face_area(&g.x);
    out.dt = solid_time_step_c(sec, p.c, lc, p.compress);
    out
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    pub(crate) fn mat() -> Material {
        let (e, nu) = (210.0, 0.3);
        Material::Elastic(crate::material::Law1(crate::material::ElasticConstants {
            rho: 7.8e-6,
            rho_ref: 7.8e-6,
            e,
            nu,
            g: e / (2.0 * (1.0 + nu)),
        }))
    }

    pub(crate) fn resolved(isolid: i64, qa: f64, qb: f64, h: f64) -> ResolvedSolid {
        ResolvedSolid {
            isolid,
            ismstr: 4,
            iframe: 1,
            itetra4: 1000,
            icpre: 0,
            inpts: 0,
            qa,
            qb,
            q_blank: false,
            h,
            dtmin: 0.0,
            dn: 0.0,
            ortho: None,
        }
    }

    fn sec(isolid: i64, qa: f64, qb: f64, h: f64) -> SolidSection {
        SolidSection::new(&resolved(isolid, qa, qb, h), &mat()).unwrap()
    }

    pub(crate) fn lame(m: &Material) -> (f64, f64) {
        let (e, nu) = (m.young(), m.poisson());
        (
            e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)),
            e / (2.0 * (1.0 + nu)),
        )
    }

    const NAT: [[f64; 3]; 8] = [
        [-1.0, -1.0, -1.0],
        [1.0, -1.0, -1.0],
        [1.0, 1.0, -1.0],
        [-1.0, 1.0, -1.0],
        [-1.0, -1.0, 1.0],
        [1.0, -1.0, 1.0],
        [1.0, 1.0, 1.0],
        [-1.0, 1.0, 1.0],
    ];

    /// A fixed sequence of numbers in [−½, ½) (a 64-bit LCG from `seed`).
    fn lcg(mut seed: u64) -> impl FnMut() -> f64 {
        move || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((seed >> 11) as f64 / (1u64 << 53) as f64) - 0.5
        }
    }

    /// The 27 nodes of a 2×2×2 patch of a sheared, stretched box (node
    /// (i, j, k) near the affine image of (i, j, k)), every node moved by up
    /// to ±amp/2 (a fixed sequence), and its 8 bricks (Radioss corner order).
    pub(crate) fn distorted_patch(amp: f64) -> (Vec<[f64; 3]>, Vec<[usize; 8]>) {
        let id = |i: usize, j: usize, k: usize| i + 3 * j + 9 * k;
        let mut rnd = lcg(12345);
        let mut p = vec![[0.0; 3]; 27];
        for k in 0..3 {
            for j in 0..3 {
                for i in 0..3 {
                    let (x, y, z) = (i as f64, j as f64, k as f64);
                    // A sheared, stretched box (affine), then each node moved.
                    p[id(i, j, k)] = [
                        x + 0.3 * y + 0.2 * z + amp * rnd(),
                        1.2 * y - 0.25 * z + amp * rnd(),
                        0.9 * z + 0.15 * x + amp * rnd(),
                    ];
                }
            }
        }
        let mut bricks = Vec::new();
        for k in 0..2 {
            for j in 0..2 {
                for i in 0..2 {
                    bricks.push([
                        id(i, j, k),
                        id(i + 1, j, k),
                        id(i + 1, j + 1, k),
                        id(i, j + 1, k),
                        id(i, j, k + 1),
                        id(i + 1, j, k + 1),
                        id(i + 1, j + 1, k + 1),
                        id(i, j + 1, k + 1),
                    ]);
                }
            }
        }
        (p, bricks)
    }

    pub(crate) fn unit_cube() -> [[f64; 3]; 8] {
        let mut x = [[0.0; 3]; 8];
        for a in 0..8 {
            for k in 0..3 {
                x[a][k] = 0.5 * (NAT[a][k] + 1.0);
            }
        }
        x
    }

    fn distorted() -> [[f64; 3]; 8] {
        let d = [
            [0.05, -0.02, 0.03],
            [0.10, 0.04, -0.05],
            [-0.07, 0.12, 0.02],
            [0.03, -0.06, 0.08],
            [-0.04, 0.09, -0.03],
            [0.06, -0.08, 0.11],
            [0.15, 0.05, -0.09],
            [-0.02, 0.07, 0.04],
        ];
        let mut x = unit_cube();
        for a in 0..8 {
            x[a][0] = 1.3 * x[a][0] + d[a][0];
            x[a][1] = 0.9 * x[a][1] + 0.2 * x[a][2] + d[a][1];
            x[a][2] = 1.1 * x[a][2] + d[a][2];
        }
        x
    }

    fn maxabs(f: &[[f64; 3]]) -> f64 {
        f.iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()))
    }

    fn sum_f(f: &[[f64; 3]]) -> [f64; 3] {
        let mut s = [0.0; 3];
        for fa in f {
            for k in 0..3 {
                s[k] += fa[k];
            }
        }
        s
    }

    fn rotation(axis: [f64; 3], th: f64) -> [[f64; 3]; 3] {
        let n = dot(axis, axis).sqrt();
        let (x, y, z) = (axis[0] / n, axis[1] / n, axis[2] / n);
        let (c, s) = (th.cos(), th.sin());
        let t = 1.0 - c;
        [
            [c + x * x * t, x * y * t - z * s, x * z * t + y * s],
            [y * x * t + z * s, c + y * y * t, y * z * t - x * s],
            [z * x * t - y * s, z * y * t + x * s, c + z * z * t],
        ]
    }

    fn apply(r: &[[f64; 3]; 3], p: [f64; 3]) -> [f64; 3] {
        [dot(r[0], p), dot(r[1], p), dot(r[2], p)]
    }

    /// R σ Rᵀ of a Voigt stress.
    pub(crate) fn rotated(r: &[[f64; 3]; 3], s: &[f64; 6]) -> [f64; 6] {
        rotate_voigt(r, s)
    }

    #[test]
    fn uniform_gradient_matches_exact_integration() {
        // b_a = ∫ ∂N_a/∂x dV is integrated exactly by 2×2×2 Gauss points
        // (the integrand has degree ≤ 2 in each natural coordinate).
        let x = distorted();
        let (b, vol) = hex_gradient(&x);
        let g = 1.0 / 3.0f64.sqrt();
        let mut bg = [[0.0; 3]; 8];
        let mut vg = 0.0;
        for p in NAT {
            let xi = [p[0] * g, p[1] * g, p[2] * g];
            let mut dn = [[0.0; 3]; 8];
            for a in 0..8 {
                let n = NAT[a];
                let f = |k: usize| 1.0 + n[k] * xi[k];
                dn[a] = [
                    0.125 * n[0] * f(1) * f(2),
                    0.125 * n[1] * f(0) * f(2),
                    0.125 * n[2] * f(0) * f(1),
                ];
            }
            let mut j = [[0.0; 3]; 3]; // j[i][k] = ∂x_i/∂ξ_k
            for a in 0..8 {
                for i in 0..3 {
                    for k in 0..3 {
                        j[i][k] += x[a][i] * dn[a][k];
                    }
                }
            }
            let det = dot(j.map(|r| r[0]), cross(j.map(|r| r[1]), j.map(|r| r[2])));
            // cofactors: ∂ξ_k/∂x_i · det = (cof J)_{ik}
            let c0 = cross(j.map(|r| r[1]), j.map(|r| r[2]));
            let c1 = cross(j.map(|r| r[2]), j.map(|r| r[0]));
            let c2 = cross(j.map(|r| r[0]), j.map(|r| r[1]));
            vg += det;
            for a in 0..8 {
                for i in 0..3 {
                    bg[a][i] += dn[a][0] * c0[i] + dn[a][1] * c1[i] + dn[a][2] * c2[i];
                }
            }
        }
        assert!((vol - vg).abs() < 1e-14 * vg, "{vol} vs {vg}");
        for a in 0..8 {
            for i in 0..3 {
                assert!(
                    (b[a][i] - bg[a][i]).abs() < 1e-14,
                    "b[{a}][{i}] = {} vs {}",
                    b[a][i],
                    bg[a][i]
                );
            }
        }
        // Σ_a x_ai b_aj = V δ_ij
        for i in 0..3 {
            for j in 0..3 {
                let s: f64 = (0..8).map(|a| x[a][i] * b[a][j]).sum();
                let e = if i == j { vol } else { 0.0 };
                assert!((s - e).abs() < 1e-14, "{i}{j}: {s}");
            }
        }
    }

    #[test]
    fn rigid_translation_gives_no_force() {
        for isolid in [1, 2] {
            let s = sec(isolid, 1.1, 0.05, 0.1);
            let mut x = distorted();
            let mut st = hex8_init(&s, &x);
            let v = [[3.0, -2.0, 1.5]; 8];
            let dt = 1e-3;
            for _ in 0..10 {
                for a in 0..8 {
                    for k in 0..3 {
                        x[a][k] += dt * v[a][k];
                    }
                }
                let o = hex8_step(&s, &x, &v, dt, &mut st);
                assert!(maxabs(&o.f) < 1e-12, "isolid {isolid}: {:?}", o.f);
                assert!(o.d_eint.abs() < 1e-18 && o.d_ehg.abs() < 1e-18);
            }
            assert!(st.sig.iter().all(|s| s.abs() < 1e-10));
        }
    }

    #[test]
    fn rigid_rotation_rotates_stress_exactly() {
        let s = sec(1, 1.1, 0.05, 0.1);
        let x0 = distorted();
        let r = rotation([1.0, 2.0, 3.0], 0.3);
        let c = [0.4, -0.2, 0.7];
        let mut x1 = [[0.0; 3]; 8];
        for a in 0..8 {
            let p = apply(&r, sub(x0[a], c));
            x1[a] = [p[0] + c[0] + 0.5, p[1] + c[1], p[2] + c[2] - 0.1];
        }
        let dt = 0.01;
        let mut v = [[0.0; 3]; 8];
        for a in 0..8 {
            for k in 0..3 {
                v[a][k] = (x1[a][k] - x0[a][k]) / dt;
            }
        }
        // Stress-free: no force, no energy.
        let mut st = hex8_init(&s, &x0);
        let o = hex8_step(&s, &x1, &v, dt, &mut st);
        assert!(maxabs(&o.f) < 1e-12, "{:?}", o.f);
        assert!(o.d_ehg.abs() < 1e-20 && o.d_eint.abs() < 1e-16);
        // Pre-stressed: the stress turns with the body, the forces are those of Rσ₀Rᵀ.
        let sig0 = [0.3, -0.1, 0.2, 0.05, -0.07, 0.11];
        let mut st = hex8_init(&s, &x0);
        st.sig = sig0;
        let o = hex8_step(&s, &x1, &v, dt, &mut st);
        let want = rotated(&r, &sig0);
        for k in 0..6 {
            // Round-off of v = (x¹ − x⁰)/Δt times E: ~1e-13 of σ.
            assert!(
                (st.sig[k] - want[k]).abs() < 1e-12,
                "{:?} vs {want:?}",
                st.sig
            );
        }
        let (b, _) = hex_gradient(&x1);
        for a in 0..8 {
            let f = stress_force(&want, b[a]);
            for k in 0..3 {
                assert!(
                    (o.f[a][k] - f[k]).abs() < 1e-12,
                    "{a}: {:?} vs {f:?}",
                    o.f[a]
                );
            }
        }
        assert!(o.d_eint.abs() < 1e-14);
    }

    #[test]
    fn uniaxial_strain_is_exact() {
        let s = sec(1, 1.1, 0.05, 0.1);
        let (lam, mu) = lame(&s.material);
        let x0 = unit_cube();
        let (v0, dt) = (1.0, 1e-4);
        let mut v = [[0.0; 3]; 8];
        for a in 4..8 {
            v[a][2] = v0;
        }
        let mut x1 = x0;
        for a in 0..8 {
            x1[a][2] += dt * v[a][2];
        }
        let mut st = hex8_init(&s, &x0);
        let o = hex8_step(&s, &x1, &v, dt, &mut st);
        let hm = 1.0 + 0.5 * dt * v0;
        let eps = dt * v0 / hm;
        let want = [lam * eps, lam * eps, (lam + 2.0 * mu) * eps, 0.0, 0.0, 0.0];
        for k in 0..6 {
            assert!(
                (st.sig[k] - want[k]).abs() <= 1e-9 * want[2],
                "{:?} vs {want:?}",
                st.sig
            );
        }
        for k in 0..3 {
            assert!((st.sig[k] - want[k]).abs() <= 1e-12 * want[k].abs());
        }
        // Corner forces: ±σzz/4 on the top/bottom, ±σxx h/4 on the sides.
        let h1 = 1.0 + dt * v0;
        for a in 0..8 {
            let n = NAT[a];
            let f = [
                0.25 * n[0] * want[0] * h1,
                0.25 * n[1] * want[1] * h1,
                0.25 * n[2] * want[2],
            ];
            for k in 0..3 {
                assert!(
                    (o.f[a][k] - f[k]).abs() < 1e-12 * want[2],
                    "{a}: {:?} vs {f:?}",
                    o.f[a]
                );
            }
        }
        assert!((o.d_eint - 0.5 * want[2] * eps * hm).abs() < 1e-12 * o.d_eint);
        assert_eq!(o.d_ehg, 0.0);
    }

    #[test]
    fn bulk_viscosity_adds_pressure_in_compression() {
        let s = sec(1, 1.1, 0.05, 0.1);
        let (lam, mu) = lame(&s.material);
        let x0 = unit_cube();
        let (v0, dt) = (-5.0, 1e-4);
        let mut v = [[0.0; 3]; 8];
        for a in 4..8 {
            v[a][2] = v0;
        }
        let mut x1 = x0;
        for a in 4..8 {
            x1[a][2] += dt * v0;
        }
        let mut st = hex8_init(&s, &x0);
        let o = hex8_step(&s, &x1, &v, dt, &mut st);
        let hm = 1.0 + 0.5 * dt * v0;
        let h1 = 1.0 + dt * v0;
        let rate = -v0 / hm;
        let eps = -rate * dt;
        assert!((st.sig[2] - (lam + 2.0 * mu) * eps).abs() < 1e-12 * st.sig[2].abs());
        let rho = s.material.rho() / h1;
        let l = h1.cbrt();
        let q = rho * l * rate * (1.1 * 1.1 * l * rate + 0.05 * s.c);
        assert!(q > 0.0);
        // Top nodes: f_z = (σzz − q) A/4 with A = 1.
        for a in 4..8 {
            let want = 0.25 * (st.sig[2] - q);
            assert!(
                (o.f[a][2] - want).abs() < 1e-12 * want.abs(),
                "{} vs {want}",
                o.f[a][2]
            );
        }
        // Energy: ½σ̄:Δε V + q ḋ V Δt (both positive in compression).
        let want = (0.5 * st.sig[2] * eps + q * rate * dt) * hm;
        assert!(
            (o.d_eint - want).abs() < 1e-12 * want,
            "{} vs {want}",
            o.d_eint
        );
        // Time step: Q = qb c + l_c qa² ḋ.
        let qx = 0.05 * s.c + h1 * 1.1 * 1.1 * rate;
        let want_dt = h1 / (qx + (qx * qx + s.c * s.c).sqrt());
        assert!((o.dt - want_dt).abs() < 1e-14 * want_dt);
    }

    #[test]
    fn patch_test_on_a_distorted_mesh() {
        // 2×2×2 bricks of a sheared box, every node moved; linear velocity field v = G x + v₀.
        let (p, bricks) = distorted_patch(0.3);
        let g = [[0.3, -0.2, 0.5], [0.1, -0.4, 0.25], [-0.35, 0.15, 0.2]];
        let v0 = [1.0, 2.0, -0.5];
        let vel = |x: [f64; 3]| {
            [
                dot(g[0], x) + v0[0],
                dot(g[1], x) + v0[1],
                dot(g[2], x) + v0[2],
            ]
        };
        let dt = 1e-3;
        let s = sec(1, 1.1, 0.05, 0.1);
        let mut fnode = [[0.0; 3]; 27];
        let mut sig_ref: Option<[f64; 6]> = None;
        let mut fmax: f64 = 0.0;
        for nodes in &bricks {
            let x = nodes.map(|n| p[n]);
            let v = x.map(vel);
            let mut st = hex8_init(&s, &x);
            let o = hex8_step(&s, &x, &v, dt, &mut st);
            assert!(
                o.d_ehg.abs() < 1e-14 * o.d_eint.abs(),
                "hourglass energy {}",
                o.d_ehg
            );
            assert!(st.hg.iter().flatten().all(|q| q.abs() < 1e-14));
            match sig_ref {
                None => sig_ref = Some(st.sig),
                Some(r) => {
                    for c in 0..6 {
                        assert!((st.sig[c] - r[c]).abs() < 1e-12, "{:?} vs {r:?}", st.sig);
                    }
                }
            }
            for (a, &n) in nodes.iter().enumerate() {
                for c in 0..3 {
                    fnode[n][c] += o.f[a][c];
                }
            }
            fmax = fmax.max(maxabs(&o.f));
        }
        // The interior node is in equilibrium under a uniform stress.
        let fc = fnode[13];
        assert!(maxabs(&[fc]) < 1e-12 * fmax, "{fc:?} (max {fmax})");
        // The stress is Hooke's law of Δε = sym(L)Δt with L = G (I − ½ΔtG)⁻¹.
        let a = [
            [
                1.0 - 0.5 * dt * g[0][0],
                -0.5 * dt * g[0][1],
                -0.5 * dt * g[0][2],
            ],
            [
                -0.5 * dt * g[1][0],
                1.0 - 0.5 * dt * g[1][1],
                -0.5 * dt * g[1][2],
            ],
            [
                -0.5 * dt * g[2][0],
                -0.5 * dt * g[2][1],
                1.0 - 0.5 * dt * g[2][2],
            ],
        ];
        let det = dot(a[0], cross(a[1], a[2]));
        let cols = [cross(a[1], a[2]), cross(a[2], a[0]), cross(a[0], a[1])];
        let mut ainv = [[0.0; 3]; 3];
        for i in 0..3 {
            for j in 0..3 {
                ainv[i][j] = cols[j][i] / det;
            }
        }
        let mut l = [[0.0; 3]; 3];
        for i in 0..3 {
            for j in 0..3 {
                for m in 0..3 {
                    l[i][j] += g[i][m] * ainv[m][j];
                }
            }
        }
        let (lam, mu) = lame(&s.material);
        let e = |i: usize, j: usize| 0.5 * (l[i][j] + l[j][i]) * dt;
        let tr = e(0, 0) + e(1, 1) + e(2, 2);
        let want = [
            lam * tr + 2.0 * mu * e(0, 0),
            lam * tr + 2.0 * mu * e(1, 1),
            lam * tr + 2.0 * mu * e(2, 2),
            2.0 * mu * e(0, 1),
            2.0 * mu * e(1, 2),
            2.0 * mu * e(2, 0),
        ];
        let r = sig_ref.unwrap();
        for c in 0..6 {
            assert!(
                (r[c] - want[c]).abs() < 1e-9 * want[0].abs(),
                "{r:?} vs {want:?}"
            );
        }
    }

    #[test]
    fn hourglass_modes_are_resisted() {
        let x = unit_cube();
        for isolid in [1, 2] {
            let s = sec(isolid, 1.1, 0.05, 0.1);
            for (m, h) in HG_BASE.iter().enumerate() {
                for dir in 0..3 {
                    let amp = 0.01;
                    let mut v = [[0.0; 3]; 8];
                    for a in 0..8 {
                        v[a][dir] = amp * h[a];
                    }
                    let dt = 1e-6;
                    let mut st = hex8_init(&s, &x);
                    let o = hex8_step(&s, &x, &v, dt, &mut st);
                    // No strain: the mode is invisible to the one-point gradient.
                    assert!(st.sig.iter().all(|s| s.abs() < 1e-15), "{:?}", st.sig);
                    // Exact viscous force Q = q(C_l + |q| C_q), q = 8 amp, f_a = h_a Q.
                    let q = 8.0 * amp;
                    let base = 0.025 * s.material.rho();
                    let qf = q * (base * s.c + q * base * 0.025 * 100.0);
                    for a in 0..8 {
                        assert!(
                            (o.f[a][dir] - h[a] * qf).abs() < 1e-12 * qf,
                            "mode {m} dir {dir}"
                        );
                    }
                    let power: f64 = (0..8).map(|a| dot(o.f[a], v[a])).sum();
                    assert!(power > 0.0);
                    assert!((o.d_ehg - power * dt).abs() < 1e-12 * o.d_ehg);
                    assert!(maxabs(&[sum_f(&o.f)]) < 1e-15);
                }
            }
        }
    }

    #[test]
    fn forces_are_in_equilibrium() {
        let mut rnd = lcg(99);
        for isolid in [1, 2] {
            let s = sec(isolid, 1.1, 0.05, 0.1);
            let mut x = distorted();
            let mut st = hex8_init(&s, &x);
            let mut v = [[0.0; 3]; 8];
            for a in 0..8 {
                v[a] = [rnd(), rnd(), rnd()];
            }
            let dt = 1e-3;
            for _ in 0..20 {
                for a in 0..8 {
                    for k in 0..3 {
                        x[a][k] += dt * v[a][k];
                    }
                }
                let o = hex8_step(&s, &x, &v, dt, &mut st);
                assert!(!o.bad_volume);
                let fm = maxabs(&o.f);
                assert!(fm > 0.0);
                assert!(
                    maxabs(&[sum_f(&o.f)]) < 1e-13 * fm,
                    "Σf = {:?}",
                    sum_f(&o.f)
                );
                if isolid == 1 {
                    let mut mo = [0.0; 3];
                    for a in 0..8 {
                        let c = cross(x[a], o.f[a]);
                        for k in 0..3 {
                            mo[k] += c[k];
                        }
                    }
                    assert!(maxabs(&[mo]) < 1e-12 * fm, "Σx×f = {mo:?}");
                }
                assert!(o.d_ehg >= 0.0);
            }
        }
    }

    #[test]
    fn internal_energy_equals_the_work_of_the_forces() {
        // Σ ½(fⁿ + fⁿ⁺¹)·v^{n+½} Δt = E_int + E_hg (second order in Δt).
        let s = sec(1, 1.1, 0.05, 0.1);
        let mut x = distorted();
        let mut st = hex8_init(&s, &x);
        let mut v = [[0.0; 3]; 8];
        for a in 0..8 {
            v[a] = [
                -0.8 * x[a][0] + 0.2 * x[a][1],
                0.3 * x[a][2],
                0.5 * x[a][2] - 0.1 * x[a][0],
            ];
            for k in 0..3 {
                v[a][k] += 0.05 * HG_BASE[k][a];
            }
        }
        let dt = 1e-4;
        let mut f_old = [[0.0; 3]; 8];
        let mut work = 0.0;
        for _ in 0..300 {
            for a in 0..8 {
                for k in 0..3 {
                    x[a][k] += dt * v[a][k];
                }
            }
            let o = hex8_step(&s, &x, &v, dt, &mut st);
            for a in 0..8 {
                for k in 0..3 {
                    work += 0.5 * (f_old[a][k] + o.f[a][k]) * v[a][k] * dt;
                }
            }
            f_old = o.f;
        }
        let e = st.eint + st.ehg;
        assert!(st.ehg > 0.0 && st.eint > 0.0);
        assert!((work - e).abs() < 1e-3 * e, "work {work} vs energy {e}");
    }

    #[test]
    fn time_step_of_a_unit_cube() {
        let m = mat();
        let (lam, mu) = lame(&m);
        let c = ((lam + 2.0 * mu) / m.rho_ref()).sqrt();
        let x = unit_cube();
        let s = sec(1, 0.0, 0.0, 0.1);
        assert!((s.c - c).abs() < 1e-12 * c);
        let mut st = hex8_init(&s, &x);
        let o = hex8_step(&s, &x, &[[0.0; 3]; 8], 0.0, &mut st);
        assert!((o.dt * c - 1.0).abs() < 1e-12, "{}", o.dt * c);
        // Default qb = 0.05: Δt = 1/(c (qb + √(1 + qb²))).
        let s = sec(1, 1.1, 0.05, 0.1);
        let o = hex8_step(&s, &x, &[[0.0; 3]; 8], 0.0, &mut st);
        let want = 1.0 / (c * (0.05 + (1.0f64 + 0.0025).sqrt()));
        assert!((o.dt - want).abs() < 1e-12 * want);
        assert!((o.dt * c - 1.0).abs() < 0.06);
        // A 2 × 1 × 0.5 box: V / A_max = 0.5, the smallest dimension.
        let mut b = x;
        for p in b.iter_mut() {
            p[0] *= 2.0;
            p[2] *= 0.5;
        }
        let s = sec(1, 0.0, 0.0, 0.1);
        let o = hex8_step(&s, &b, &[[0.0; 3]; 8], 0.0, &mut hex8_init(&s, &b));
        assert!((o.dt * c - 0.5).abs() < 1e-12);
    }

    #[test]
    fn negative_volume_is_reported() {
        let s = sec(1, 1.1, 0.05, 0.1);
        let x = unit_cube();
        let mut st = hex8_init(&s, &x);
        // Top face pushed through the bottom one.
        let mut xi = x;
        for a in 4..8 {
            xi[a][2] = -0.5;
        }
        let o = hex8_step(&s, &xi, &[[0.0; 3]; 8], 1e-6, &mut st);
        assert!(o.bad_volume);
        // Mirrored numbering.
        let mut xm = x;
        xm.swap(1, 3);
        xm.swap(5, 7);
        assert!(hex8_step(&s, &xm, &[[0.0; 3]; 8], 0.0, &mut st).bad_volume);
    }

    #[test]
    fn sections_refuse_what_is_not_computed() {
        let m = mat();
        let e = SolidSection::new(&resolved(17, 1.1, 0.05, 0.1), &m).unwrap_err();
        assert!(e.contains("Isolid = 17"), "{e}");
        let e = SolidSection::new(&resolved(24, 1.1, 0.05, 0.1), &m).unwrap_err();
        assert!(e.contains("Isolid = 24"), "{e}");
        let mut r = resolved(1, 1.1, 0.05, 0.1);
        r.ismstr = 3;
        assert!(SolidSection::new(&r, &m)
            .unwrap_err()
            .contains("Ismstr = 3"));
        r.ismstr = 1;
        assert_eq!(SolidSection::new(&r, &m).unwrap().ismstr, 1);
        assert!(SolidSection::for_tetra(&r, &m)
            .unwrap_err()
            .contains("Ismstr = 1 (small strain) on tetrahedra"));
        let mut r = resolved(2, 1.1, 0.05, 0.1);
        r.iframe = 2;
        assert!(SolidSection::new(&r, &m)
            .unwrap_err()
            .contains("Iframe = 2"));
        let mut r = resolved(1, 1.1, 0.05, 0.1);
        r.itetra4 = 3;
        assert!(SolidSection::for_tetra(&r, &m)
            .unwrap_err()
            .contains("Itetra4 = 3"));
        r.itetra4 = 1000;
        r.isolid = 14;
        assert_eq!(SolidSection::for_tetra(&r, &m).unwrap().isolid, 0);
    }

    /// A Johnson-Cook aluminium (E 70, ν 0.3; a 0.15, b 0.2, n 0.6).
    pub(crate) fn jc_aluminium() -> Material {
        Material::from_card(&crate::model::MaterialSpec {
            id: 1,
            unit_id: 0,
            title: String::new(),
            rho: 2.7e-6,
            rho_ref: 0.0,
            e: 70.0,
            nu: 0.3,
            law: crate::model::MaterialLaw::JohnsonCook(crate::model::JohnsonCook::hardening(
                0.15, 0.2, 0.6,
            )),
            failures: vec![],
            loc: Default::default(),
        })
    }

    /// /FAIL/JOHNSON D1 = D2 = 0.1, D3 = 0 (ε_f = 0.2 whatever the
    /// triaxiality), Ifail_so 1.
    pub(crate) fn jc_failure_at_0_2() -> Failure {
        let jc = crate::model::JohnsonFailure {
            d: [0.1, 0.1, 0.0, 0.0, 0.0],
            eps_dot_0: 1.0,
            ifail_sh: 1,
            ifail_so: 1,
            epsf_min: 0.0,
            ixfem: 0,
        };
        Failure::Johnson(crate::material::FailJohnson::new(&jc).unwrap())
    }

    /// /FAIL/JOHNSON on a brick in pure shear, D3 = 0: ε_f = D1 + D2 whatever
    /// the small pressure of the (not exactly isochoric) prescribed motion;
    /// the damage is ε_p/ε_f all along and the element is deleted in the
    /// step where its plastic strain passes ε_f, not before.
    #[test]
    fn johnson_cook_failure_deletes_at_the_failure_strain() {
        let mut s = SolidSection::new(&resolved(1, 0.0, 0.0, 0.0), &jc_aluminium()).unwrap();
        s.failure = Some(jc_failure_at_0_2());
        let mut x = unit_cube();
        let mut st = hex8_init(&s, &x);
        let (rate, dt) = (1.0, 1e-4);
        let mut v = [[0.0; 3]; 8];
        for a in 0..8 {
            v[a] = [
                0.5 * rate * (x[a][1] - 0.5),
                0.5 * rate * (x[a][0] - 0.5),
                0.0,
            ];
        }
        let mut last = 0.0;
        for _ in 0..100_000 {
            for a in 0..8 {
                for k in 0..3 {
                    x[a][k] += dt * v[a][k];
                }
                v[a] = [
                    0.5 * rate * (x[a][1] - 0.5),
                    0.5 * rate * (x[a][0] - 0.5),
                    0.0,
                ];
            }
            let before = st.eps_p;
            let o = hex8_step(&s, &x, &v, dt, &mut st);
            if o.failed {
                assert!(
                    before < 0.2 && st.eps_p >= 0.2 - 1e-12,
                    "{before} {}",
                    st.eps_p
                );
                assert_eq!(st.dmg, 1.0);
                return;
            }
            assert!(
                (st.dmg - st.eps_p / 0.2).abs() <= 1e-12,
                "{} {}",
                st.dmg,
                st.eps_p
            );
            last = st.eps_p;
        }
        panic!("not deleted; eps_p = {last}");
    }

    /// LAW36 on a brick in pure shear at three strain rates: once yielding,
    /// the von Mises stress is the tabulated curve at the point's ε_p, mixed
    /// between the rate curves linearly in the equivalent rate ε̇ = γ̇/√3
    /// (curves at 0 and 200 /ms; runs at ε̇ = 50, 100 and 300 /ms weigh the
    /// second ¼, ½ and 1.5: extrapolated past the last rate).
    #[test]
    fn law36_yield_follows_the_curves_at_three_strain_rates() {
        use crate::model::{MaterialLaw, RateCurve, TabulatedPlasticity, NO_LIMIT};
        let curve = |fscale: f64, eps_dot: f64| RateCurve {
            fct: 1,
            fscale,
            eps_dot,
            x: vec![0.0, 0.05, 0.5],
            y: vec![0.2, 0.3, 0.4],
        };
        let card = crate::model::MaterialSpec {
            id: 1,
            unit_id: 0,
            title: String::new(),
            rho: 7.8e-6,
            rho_ref: 0.0,
            e: 210.0,
            nu: 0.3,
            law: MaterialLaw::Tabulated(TabulatedPlasticity {
                eps_p_max: NO_LIMIT,
                eps_t: NO_LIMIT,
                eps_m: NO_LIMIT,
                eps_f: NO_LIMIT,
                fsmooth: 0,
                chard: 0.0,
                f_cut: 0.0,
                vp: 0,
                fct_p: 0,
                fscale_p: 1.0,
                fct_e: 0,
                e_inf: 0.0,
                ce: 0.0,
                curves: vec![curve(1.0, 0.0), curve(2.0, 200.0)],
            }),
            failures: vec![],
            loc: Default::default(),
        };
        let m = Material::from_card(&card);
        let s = SolidSection::new(&resolved(1, 0.0, 0.0, 0.0), &m).unwrap();
        let tab = |ep: f64| {
            if ep < 0.05 {
                0.2 + 2.0 * ep
            } else {
                0.3 + 0.1 / 0.45 * (ep - 0.05)
            }
        };
        for (rate, w) in [(50.0, 0.25), (100.0, 0.5), (300.0, 1.5)] {
            let mut x = unit_cube();
            let mut st = hex8_init(&s, &x);
            let (dt, gdot) = (1e-6, 3.0f64.sqrt() * rate);
            for _ in 0..2000 {
                let v: [[f64; 3]; 8] = std::array::from_fn(|a| {
                    [
                        0.5 * gdot * (x[a][1] - 0.5),
                        0.5 * gdot * (x[a][0] - 0.5),
                        0.0,
                    ]
                });
                for a in 0..8 {
                    for k in 0..3 {
                        x[a][k] += dt * v[a][k];
                    }
                }
                hex8_step(&s, &x, &v, dt, &mut st);
                // Every plastic step of the path, both curve segments.
                if st.eps_p > 1e-3 {
                    let expect = (1.0 - w) * tab(st.eps_p) + w * 2.0 * tab(st.eps_p);
                    let vm = von_mises(&st.sig);
                    assert!(
                        (vm - expect).abs() < 2e-3 * expect,
                        "rate {rate}, ε_p {}: σ_vm {vm} vs {expect}",
                        st.eps_p
                    );
                }
            }
            assert!(
                st.eps_p > 0.05,
                "yielded past the first segment: {}",
                st.eps_p
            );
        }
    }
}

#[cfg(test)]
#[path = "hex8_small_tests.rs"]
mod small_tests;
