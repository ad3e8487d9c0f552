//! Material laws as the input defines them: density, elasticity and the law
//! (linear elastic, Johnson-Cook elasto-plastic) with its parameters after
//! default resolution, in the input's units.

use super::{Id, Loc};
use serde::{Deserialize, Serialize};

/// A material: density, elastic constants and its law (Radioss: /MAT/LAW1, /MAT/LAW2).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct MaterialSpec {
    pub id: Id,
    pub unit_id: Id,
    pub title: String,
    /// Initial density RHO_I.
    pub rho: f64,
    /// Reference density RHO_0 (0 = RHO_I).
    pub rho_ref: f64,
    pub e: f64,
    pub nu: f64,
    pub law: MaterialLaw,
    /// Failure models attached by /FAIL/.../mat_ID (in deck order).
    #[serde(default)]
    pub failures: Vec<FailureSpec>,
    pub loc: Loc,
}

/// A failure model attached to a material (/FAIL/<model>/mat_ID), where its card is.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct FailureSpec {
    pub model: FailureModel,
    pub loc: Loc,
}

/// The failure model and its parameters after default resolution.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub enum FailureModel {
    /// /FAIL/JOHNSON: Johnson-Cook damage D = Σ Δε_p / ε_f(σ*, ε̇, T*).
    Johnson(JohnsonFailure),
    /// /FAIL/TAB: tabulated failure strain ε_f(η, ε̇)·g(L/L_ref)·h(T*),
    /// damage D = Σ w(D)·Δε_p/ε_f, the point fails at Dcrit.
    Tab(TabFailure),
    /// /FAIL/HASHIN: the Hashin criteria of unidirectional (model 1) or
    /// fabric (model 2) composites.
    Hashin(HashinFailure),
}

/// /FAIL/HASHIN, as the card gives it (research note
/// `docs/notes/law12_research.md` §3).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct HashinFailure {
    pub iform: i64,
    pub ifail_sh: i64,
    /// Solids: 0 = the criteria are reported only, 1 or 2 = the stress
    /// relaxes and the element is deleted.
    pub ifail_so: i64,
}

/// /FAIL/TAB parameters (reference guide /FAIL/TAB; research note
/// `docs/notes/fail_tab_research.md` §2), defaults resolved as the starter:
/// Ifail_sh, Ifail_so 0 → 1, Dcrit 0 → 1, D = 1 → 0.999, n 0 → 1,
/// Fscale_el, FscaleT 0 → 1, EI_ref 0 → 1; a blank P_thickfail stays 0 (the
/// deletion rule then asks for every point). The curves' points are copied
/// from their /FUNCT by the model builder.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct TabFailure {
    /// Shells: 1 = deleted when one point fails (its stress zeroed); 2 = the
    /// failed point's stress zeroed, deleted when all have failed; 3 = the
    /// stress kept, deleted when the failed points' thickness fraction
    /// reaches P_thickfail.
    pub ifail_sh: i64,
    /// Solids: 1 = deleted when one point fails; 2 = the deviatoric stress vanishes.
    pub ifail_so: i64,
    /// Fraction of the thickness whose points must fail (Ifail_sh 3; 0 = all).
    pub p_thickfail: f64,
    pub dcrit: f64,
    /// Damage parameter D (read; the old engine applies no softening).
    pub d: f64,
    /// Damage exponent n of w = n·D^(1−1/n).
    pub n: f64,
    /// ε_f(η) = Fscale_i·f_i(η) at strain rate ε̇_i, by increasing rate.
    pub rates: Vec<RateCurve>,
    /// Element-size factor g(L/EI_ref)·Fscale_el (fct 0: 1).
    pub size: ScaleCurve,
    pub el_ref: f64,
    /// Temperature factor h(T*)·FscaleT (fct 0: 1).
    pub temperature: ScaleCurve,
}

/// A scale function Fscale·f(x) of a failure card (fct 0: the constant Fscale).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct ScaleCurve {
    pub fct: Id,
    pub fscale: f64,
    #[serde(default)]
    pub x: Vec<f64>,
    #[serde(default)]
    pub y: Vec<f64>,
}

/// /FAIL/JOHNSON parameters (reference guide /FAIL/JOHNSON; defaults as the
/// Radioss starter resolves them).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct JohnsonFailure {
    /// D1..D5 of ε_f = [D1 + D2·exp(D3·σ*)]·[1 + D4·ln(ε̇/ε̇₀)]·[1 + D5·T*].
    pub d: [f64; 5],
    /// Reference strain rate ε̇₀ (blank → 1e-20, as the starter).
    pub eps_dot_0: f64,
    /// Shells: 1 = deleted when one through-thickness point fails, 2 = when all do (blank → 1).
    pub ifail_sh: i64,
    /// Solids: 1 = deleted when one point fails; 2 = deviatoric stress set to
    /// zero; 3 = only compressive pressure kept; 4 = stress set to zero, element kept (blank → 1).
    pub ifail_so: i64,
    /// Lower bound of ε_f (2024 format; blank → 0).
    pub epsf_min: f64,
    /// XFEM crack flag (0 none).
    pub ixfem: i64,
}

/// The constitutive law and its parameters.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub enum MaterialLaw {
    /// LAW1: linear elastic.
    Elastic,
    /// LAW2: Johnson-Cook elasto-plastic,
    /// σ_y = (a + b·ε_p^n)·(1 + c·ln(ε̇/ε̇₀))·(1 − T*^m), capped at SIG_max0.
    JohnsonCook(JohnsonCook),
    /// LAW36 (/MAT/PLAS_TAB): tabulated yield curves σ_y(ε_p) per strain rate.
    Tabulated(TabulatedPlasticity),
    /// LAW44 (/MAT/COWPER): σ_y = (a + b·ε_p^n)·(1 + (ε̇/c)^(1/p)).
    CowperSymonds(CowperSymonds),
    /// LAW21 (/MAT/DPRAG): Drucker-Prager, J2 ≤ A0 + A1·P + A2·P², with a
    /// tabulated pressure P(μ).
    DruckerPrager(DruckerPrager),
    /// LAW27 (/MAT/PLAS_BRIT): Johnson-Cook plasticity with brittle tension
    /// damage on shells.
    BrittlePlastic(BrittlePlastic),
    /// LAW62 (/MAT/VISC_HYP): Ogden-type (Hill/Storåkers) hyperelasticity
    /// on the full principal stretches with a Prony series.
    ViscoHyperelastic(ViscoHyperelastic),
    /// LAW12 (/MAT/3D_COMP): orthotropic solid composite, Tsai-Wu
    /// plasticity with work hardening, tension damage per direction.
    Composite3d(Composite3d),
    /// LAW70 (/MAT/FOAM_TAB): tabulated visco-elastic foam, loading curves
    /// per strain rate, secant modulus, hysteresis on unloading.
    FoamTab(FoamTab),
}

/// /MAT/LAW70 parameters (reference guide /MAT/LAW70; research note
/// `docs/notes/law70_research.md` §1.1), defaults resolved as the reference
/// starter: eps_max 0 → 1, Shape 0 → 1, Hys 0 → 1, a curve scale 0 → 1,
/// the first loading rate → 0, E_max 0 → the largest slope of the scaled
/// loading curves (not below E0), F_cut 0 → no filter. E0 and ν are the
/// card's `MaterialSpec::e`, `nu`.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct FoamTab {
    pub e_max: f64,
    /// Strain past which the curves are continued with slope E_max.
    pub eps_max: f64,
    /// Strain-rate filter frequency in the deck's time unit (0: none) and
    /// ISRATE (Fsmooth; 0: no filter).
    pub f_cut: f64,
    pub israte: i64,
    /// Unloading model Iflag (0-4), Shape and Hys of the hysteresis.
    pub iflag: i64,
    pub shape: f64,
    pub hys: f64,
    /// Itens: tension handled apart (its pressure-factor curve).
    pub itens: i64,
    /// The loading curves σ = Fscale·f(ε) by increasing strain rate, and
    /// the unloading ones (points filled by the model builder).
    pub loading: Vec<RateCurve>,
    pub unloading: Vec<RateCurve>,
}

/// /MAT/LAW12 parameters in the material frame (directions 1, 2, 3; shears
/// 12, 23, 31), defaults resolved as the reference starter (research note
/// `docs/notes/law12_research.md` §1.2): blank strengths are 1e20, σ_t2,3
/// → σ_t1, DELTA 0 → 0.05, Wplaref 0 → 1, n 0 → 1, fmax 0 → 1e10, ICC 0
/// → 1.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Composite3d {
    pub e: [f64; 3],
    /// ν12, ν23, ν31.
    pub nu: [f64; 3],
    /// G12, G23, G31.
    pub g: [f64; 3],
    /// Tension-damage thresholds and the damage increment.
    pub sig_t: [f64; 3],
    pub delta: f64,
    /// Tsai-Wu limit 1 + B·Wpⁿ (Wp the plastic work over Wplaref), capped
    /// at fmax.
    pub b: f64,
    pub n: f64,
    pub fmax: f64,
    pub wplaref: f64,
    /// Yield stresses in tension and compression: 1, 2, 3, 12, 23, 31.
    pub yt: [f64; 6],
    pub yc: [f64; 6],
    /// Strain-rate term c, reference rate and ICC.
    pub c: f64,
    pub eps_rate0: f64,
    pub icc: i64,
}

impl Composite3d {
    /// The normal compliance C11 = 1/E11, C12 = −ν12/E11, C13 = −ν31/E33,
    /// C23 = −ν23/E22 (symmetric; note §1.2).
    pub fn compliance(&self) -> [[f64; 3]; 3] {
        let [e1, e2, e3] = self.e;
        let [n12, n23, n31] = self.nu;
        [
            [1.0 / e1, -n12 / e1, -n31 / e3],
            [-n12 / e1, 1.0 / e2, -n23 / e2],
            [-n31 / e3, -n23 / e2, 1.0 / e3],
        ]
    }

    /// The normal stiffness D = C⁻¹; None when C is not positive.
    pub fn stiffness(&self) -> Option<[[f64; 3]; 3]> {
        crate::vec3::inverse_positive(&self.compliance())
    }
}

/// /MAT/LAW62 parameters (reference guide /MAT/LAW62; research note
/// `docs/notes/law62_research.md` §1), defaults resolved as the reference
/// starter: ν ≥ 0.5 → 0.499, α_i 0 → 1, τ_i ≤ 0 → 1e20, mu_max 0 → 1e20.
/// `flag_visc` 1 relaxes the whole stress, otherwise the deviatoric part.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct ViscoHyperelastic {
    /// Shear moduli μ_i and exponents α_i of the N Ogden terms.
    pub mu: Vec<f64>,
    pub alpha: Vec<f64>,
    /// Stiffness ratios γ_i and relaxation times τ_i of the M Maxwell terms.
    pub gamma: Vec<f64>,
    pub tau: Vec<f64>,
    pub mu_max: f64,
    pub flag_visc: i64,
}

/// /MAT/LAW27 parameters (research note `docs/notes/law27_research.md` §1),
/// defaults resolved as the reference starter: a 0 → 1e20, n 0 → 1,
/// SIG_max0 0 → 1e20, ICC 0 → 1, EPS_DOT_0 → 1 when c = 0; per direction
/// EPS_t 0 → 1e20, EPS_m 0 → 1.1e20, d_max 0 → 0.999, EPS_f 0 → 1.2e20.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct BrittlePlastic {
    pub a: f64,
    pub b: f64,
    pub n: f64,
    pub sig_max0: f64,
    pub c: f64,
    pub eps_dot0: f64,
    /// 1: the strain-rate factor scales SIG_max too; 2: it does not.
    pub icc: i64,
    /// Directions 1 and 2: [EPS_t, EPS_m, d_max, EPS_f].
    pub crack: [[f64; 4]; 2],
}

/// /MAT/LAW21 parameters (reference guide /MAT/LAW21; research note
/// `docs/notes/law21_research.md` §1), defaults resolved as the starter:
/// B 0 → Kt, Amax and Mu_max 0 → 1e20, P_min 0 → −1e20, FscaleP 0 → 1. The
/// pressure curve's points are copied from its /FUNCT by the model builder.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct DruckerPrager {
    pub a0: f64,
    pub a1: f64,
    pub a2: f64,
    /// Cap on the yield limit of J2 (stress² units, as the reference engine).
    pub amax: f64,
    /// P(μ) in compression: FscaleP·f(μ).
    pub fct: Id,
    pub fscale_p: f64,
    /// Tension bulk modulus (P = Kt·μ for μ ≤ 0).
    pub kt: f64,
    /// Fracture (cut-off) pressure and external pressure.
    pub p_min: f64,
    pub p_ext: f64,
    /// Unloading bulk modulus, and the compression above which the
    /// pressure follows the curve without an unloading branch.
    pub b: f64,
    pub mu_max: f64,
    #[serde(default)]
    pub x: Vec<f64>,
    #[serde(default)]
    pub y: Vec<f64>,
}

/// /MAT/LAW44 parameters (reference guide /MAT/LAW44; research notes
/// `docs/notes/fail_johnson_law44_research.md` §B and
/// `docs/notes/law44_isolid12_research.md` §1), defaults resolved: p 0 → 1,
/// ICC 0 → 1, VP 0 → 2, SIG_max0, EPS_p_max, εt1, εt2 0 → no limit; F_cut
/// with Fsmooth and no F_cut: 10 kHz in the deck's time unit (the model
/// builder resolves it).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct CowperSymonds {
    pub a: f64,
    pub b: f64,
    pub n: f64,
    pub chard: f64,
    pub sig_max0: f64,
    /// Rate scale c (0: no rate effect) and exponent p.
    pub c: f64,
    pub p: f64,
    pub icc: i64,
    pub fsmooth: i64,
    pub f_cut: f64,
    /// Strain rate: 1 plastic, 2 total, 3 deviatoric.
    pub vp: i64,
    pub eps_p_max: f64,
    pub eps_t1: f64,
    pub eps_t2: f64,
    /// Yield curve (0: none) and its scale.
    pub fct_idy: Id,
    pub fscale_y: f64,
}

/// /MAT/LAW36 parameters (reference guide /MAT/LAW36; research note
/// `docs/notes/law36_research.md`), defaults resolved; the curves' points are
/// copied from their /FUNCT by the model builder.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct TabulatedPlasticity {
    /// Plastic strain at failure (blank → ∞: `NO_LIMIT`).
    pub eps_p_max: f64,
    /// Tension damage: stress reduction from Eps_t to Eps_m of the largest
    /// principal strain; deletion at Eps_f (blank → `NO_LIMIT`).
    pub eps_t: f64,
    pub eps_m: f64,
    pub eps_f: f64,
    /// F_smooth: 0, 1 rate interpolation linear in ε̇; 2 linear in ln ε̇.
    pub fsmooth: i64,
    /// Kinematic hardening fraction C_hard.
    pub chard: f64,
    /// Strain-rate filter frequency in the deck's time unit (0: none);
    /// blank with several curves → 10 kHz, as the starter.
    pub f_cut: f64,
    /// VP: 1 = the plastic strain rate; otherwise the total strain rate.
    pub vp: i64,
    /// Yield factor function of the pressure (0 none) and its abscissa scale.
    pub fct_p: Id,
    pub fscale_p: f64,
    /// Young's modulus evolution: its function (0 none), or E_inf and C_E.
    pub fct_e: Id,
    pub e_inf: f64,
    pub ce: f64,
    /// The yield curves, by increasing strain rate.
    pub curves: Vec<RateCurve>,
}

/// One yield curve of LAW36: σ_y = Fscale·f(ε_p) at strain rate ε̇.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct RateCurve {
    pub fct: Id,
    pub fscale: f64,
    pub eps_dot: f64,
    /// The function's points (ε_p, f), filled by the model builder.
    #[serde(default)]
    pub x: Vec<f64>,
    #[serde(default)]
    pub y: Vec<f64>,
}

#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct JohnsonCook {
    /// Iflag as given: 0 = (a, b, n) input, 1 = (σ_y, UTS, ε_UTS) input.
    pub iflag: i64,
    pub a: f64,
    pub b: f64,
    pub n: f64,
    /// Plastic strain at failure (blank/0 → 1e20: no failure).
    pub eps_p_max: f64,
    /// Maximum flow stress (blank/0 → 1e20).
    pub sig_max0: f64,
    /// Strain-rate coefficient c.
    pub c: f64,
    /// Reference strain rate ε̇₀ (required > 0 when c ≠ 0; 1 when c = 0).
    pub eps_dot_0: f64,
    /// 1: the strain-rate term also scales σ_max (default 1); 2: it does not.
    pub icc: i64,
    /// Strain-rate filtering flag (0 off, 1 on).
    pub fsmooth: i64,
    /// Cut-off frequency for strain-rate filtering (blank/0 → 1e20).
    pub f_cut: f64,
    /// Hardening: 0 isotropic … 1 kinematic (mixed between).
    pub chard: f64,
    /// Temperature exponent m (blank/0 → 1).
    pub m: f64,
    /// Melting temperature (blank/0 → 1e20).
    pub t_melt: f64,
    /// ρ·Cp (blank/0 → 1e20: no adiabatic heating).
    pub rho_cp: f64,
    /// Reference (room) temperature (blank/0 → 298).
    pub t_r: f64,
}

impl JohnsonCook {
    /// The (a, b, n) law with every other field at its blank-card default:
    /// no failure, no stress cap, no strain-rate or temperature term,
    /// isotropic hardening.
    pub fn hardening(a: f64, b: f64, n: f64) -> JohnsonCook {
        JohnsonCook {
            iflag: 0,
            a,
            b,
            n,
            eps_p_max: NO_LIMIT,
            sig_max0: NO_LIMIT,
            c: 0.0,
            eps_dot_0: 1.0,
            icc: 1,
            fsmooth: 0,
            f_cut: NO_LIMIT,
            chard: 0.0,
            m: 1.0,
            t_melt: NO_LIMIT,
            rho_cp: NO_LIMIT,
            t_r: 298.0,
        }
    }
}

/// What Radioss puts for "no limit" when a limit field is 0 (the starter listing prints 1E+20).
pub const NO_LIMIT: f64 = 1e20;
