//! Belytschko-Lin-Tsay 4-node shell (Radioss Ishell = 1, 2, 3, 4).
//!
//! # Formulation
//! * **Kinematics** (Belytschko, Lin & Tsay 1984; Radioss theory manual, "Shell
//!   Elements": bilinear Mindlin plate, one in-plane integration point, rigid
//!   body motion carried by a corotational local frame). Velocities are taken to
//!   the local frame; with the one-point gradient vectors
//!   b_x = (y24, y31, y42, y13)/(2A), b_y = (x42, x13, x24, x31)/(2A):
//!   membrane d = (Σb_x v_x, Σb_y v_y, Σ(b_y v_x + b_x v_y)),
//!   curvature κ = (Σb_x θ_y, −Σb_y θ_x, Σ(b_y θ_y − b_x θ_x)),
//!   transverse shear γ_xz = Σb_x v_z + ¼Σθ_y, γ_yz = Σb_y v_z − ¼Σθ_x.
//! * **Configurations.** The velocity gradient is evaluated on the mid-step
//!   geometry x^{n+½} = x^{n+1} − ½Δt v^{n+½} (frame and b-vectors of that
//!   geometry): for a rigid rotation the nodal velocity field is then exactly
//!   skew on it (Cayley transform), so rigid rotations give no strain at any step
//!   size. This replaces the second-order velocity correction the Radioss engine
//!   applies to BLT membrane rates. Internal forces use the x^{n+1} frame and
//!   b-vectors, so that they are in exact force and moment equilibrium at x^{n+1}.
//! * **Local frame** (one choice for all decks, /SHFRA V4 or V5): e3 = normal of
//!   the diagonals d13 × d24; e1 ∝ g1 + g2 × e3 with the mid-lines
//!   g1 = d13 − d24, g2 = d13 + d24 (g2 turned by −90°); e2 = e3 × e1.
//!   Renumbering the nodes by one turns it by 90°. The frame does not change the
//!   results: the stored stresses are turned each step by the material spin
//!   minus the frame spin (Jaumann rate, see [`shell4_step`]), so the in-plane
//!   frame choice (V4 or V5) does not change our results (Radioss stores its
//!   stresses in its convected frame without this correction).
//! * **Warped elements**: with this frame the nodes sit at z_I = w·(1,−1,1,−1).
//!   The orthogonal hourglass rates (Ishell 1, 3, 4) add the warping term
//!   (γ·z)(b·v_z) — the Belytschko-Wong-Chiang correction Radioss applies for
//!   Ishell = 4 — so that rigid rotations of a warped element excite no
//!   hourglass, and hourglass forces are the exact transposes of their rates
//!   (force and moment equilibrium hold for any geometry). Radioss drops this
//!   term for Ishell = 1 (its source notes the resulting hourglass moment
//!   imbalance); here Ishell 1 and 4 therefore coincide.
//! * **Through the thickness**: N points at ζ_k = −½ + k/(N−1) (k = 0 bottom),
//!   membrane weights of the trapezoidal rule and bending weights exact for a
//!   piecewise-linear stress (theory manual "Forces and Moments Calculation",
//!   table of positions/weights: N = 3 → w_N = ¼ ½ ¼, w_M = ∓1/12 0; N = 5 →
//!   w_N = ⅛ ¼ ¼ ¼ ⅛, w_M = ∓0.0521 ∓0.0625 0). N = 1: membrane only, no
//!   transverse shear (the starter sets Ashear = 0 for N = 1).
//!   Resultants N = tΣw_N σ_k, M = t²Σw_M σ_k, Q = tΣw_N τ_k.
//! * **N = 0** (see [`n0_rule`]): for LAW2 the section is computed with N = 3
//!   points, as the reference engine does (its starter switches global
//!   integration to NPT = 3 for LAW2 with WARNING 1912, printed in the
//!   BOULE1V4 and INT357 reference listings); the run listing notes it.
//!   Otherwise (LAW1) the section is computed with global integration: the
//!   element keeps the resultants, stored as the two surface stresses
//!   s_m ∓ s_b (s_m = N/t, s_b = 6M/t²) at ζ = ∓½ with the N = 2 weights
//!   (w_N = ½ ½, w_M = ∓1/12, exact for the linear elastic distribution), and
//!   updates them with the elastic plate law and, for a material with a yield
//!   stress, Ilyushin's resultant yield condition with a radial return
//!   (`material::ilyushin`; Iplas is not used). Both slots carry the section's
//!   equivalent plastic strain.
//! * **Corner forces** (internal, power-conjugate: Σ f·v + m·ω = A(N:d + M:κ + Q·γ)):
//!   f_x = A(b_x N_xx + b_y N_xy), f_y = A(b_y N_yy + b_x N_xy),
//!   f_z = A(b_x Q_x + b_y Q_y), m_x = −A(b_y M_yy + b_x M_xy) − ¼A Q_y,
//!   m_y = A(b_x M_xx + b_y M_xy) + ¼A Q_x, m_z = 0 (no drilling stiffness).
//!   The solver subtracts them: M a = f_ext − f.
//! * **Hourglass** (theory manual "Hourglass Modes"/"Hourglass Resistance";
//!   coefficients as in the reference engine's shell hourglass routines):
//!   Γ = (1,−1,1,−1); orthogonal vector γ = Γ − (Γ·x)b_x − (Γ·y)b_y
//!   (Belytschko-Bachrach / Flanagan-Belytschko); Ishell 2 uses Γ itself
//!   ("without orthogonality", Hallquist), which does not conserve angular
//!   momentum on non-parallelogram or warped elements (as in Radioss).
//!   Rates q_x, q_y (membrane), q_z (out of plane), q_rx, q_ry (rotations),
//!   all with γ for Ishell 1, 3, 4 — with Γ under small strain (Ismstr = 1),
//!   as the reference engine does — (the reference engine uses Γ for the
//!   rotational modes in every Ishell, which also resists constant curvature on
//!   non-parallelograms; γ keeps the modes orthogonal to it).
//!   - Ishell 1, 2, 4 (visco-elastic, with the reference engine's global
//!     factors: elastic ½, quadratic viscosity ½, linear viscosity 0):
//!     Q = H + C q|q| with elastic resultants integrated in time,
//!     H_m += ⅛h_m E t q_m Δt, H_f += ⅛h_f E k/(3(1+ν)) t³/B q_z Δt,
//!     B = A²(|b_1|² + |b_2|²), and quadratic dampers (¼ρ·100·½·h per mode)
//!     C_m = 12.5ρ h_m t √A, C_f = 12.5ρ h_f √(k/(3(1+ν))) t²,
//!     C_r = 12.5ρ h_r t² A/(8√3) (rotations: damper only). (k = Ashear.)
//!     On BOULE1V4 (thick-shell ball, hm = hf = hr = 0.01) this gives the
//!     reference's energies to < 1% at every printed cycle, hourglass energy
//!     included; the linear sound-speed damper ¼ρc t √(h_m A/2) of the theory
//!     manual's in-plane force, which the engine switches off, left them 15%
//!     (kinetic) to 90% (rotational) off.
//!   - Ishell 3 (elasto-plastic): H_m += ⅛h_m E t q_m Δt capped at ½σ_y t √A h_m,
//!     H_f += ⅛h_f E k/(3(1+ν)) t³/B q_z Δt capped at ¼σ_y t² h_f (σ_y: mean
//!     current yield stress of the points), rotations viscous ¼ρc t² A √h_r/(8√3).
//!
//!   Degenerate quads (node 3 = node 4) get no hourglass forces.
//! * **Time step** (reference engine's shell characteristic length): with the
//!   local edge lengths l_12, l_23, l_34, l_41 and diagonals d_13, d_24,
//!   L² = max(A²/max(d_13², d_24²), min(l², d²)), then
//!   L² ← min(L², ½(min(l², d²) + L²)/max(h_m, h_f)); Δt = L/√(E/ρ₀). On BOX1BL's
//!   5×5 squares (E = 205, ρ = 7.8e-6) this is 5/5126.6 = 9.753e-4, the
//!   listing's first step 0.9753E-04 divided by the /DT scale 0.1.
//! * **Strain measure**: Ismstr 1, 2 and 4 all use this corotational rate form
//!   (Radioss Ismstr = 2 is full geometric nonlinearity unless a /DT…/CST
//!   option switches an element to small strain; Ismstr = 1 — see
//!   `small_strain` — keeps the initial derivatives, area and step; it freezes the
//!   reference geometry of the strain-displacement matrix, which is not done here).
//! * **Thickness**: Ithick = 1 updates t with Σ_k w_N,k Δε_zz,k (global
//!   integration: the mid-surface Δε_zz); Ithick = 0 keeps it.
//! * **Strain rate** for Johnson-Cook: the element's energy-equivalent rate
//!   √(4/3(d_xx²+d_yy²+d_xx d_yy+¼γ_xy²) + t²/9(κ_xx²+κ_yy²+κ_xxκ_yy+¼κ_xy²)),
//!   filtered with F_cut (Radioss's shell strain rate for LAW2).
//! * **Failure**: a point fails when ε_p ≥ EPS_p_max (its stress is zero from
//!   then on); the element is deleted when all its points have failed (with
//!   global integration: when the section's ε̄_p reaches EPS_p_max).
//!
//! No heap allocation: everything is fixed-size on the stack.

use crate::material::{FailAt, Failure, Material, PointLaw};
use crate::model::ResolvedShell;
use serde::{Deserialize, Serialize};

/// Most integration points through the thickness (Radioss allows N ≤ 10).
pub const MAX_IP: usize = 10;
/// Elastic hourglass resultants kept per element: membrane x, y and out of plane.
pub const N_HG: usize = 3;

const GAMMA: [f64; 4] = [1.0, -1.0, 1.0, -1.0];

/// Resolved section data for one shell part (from [`ResolvedShell`] + the part's [`Material`]).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct ShellSection {
    pub ishell: i64,
    pub ismstr: i64,
    pub hm: f64,
    pub hf: f64,
    pub hr: f64,
    /// Membrane damping (only for laws Radioss applies it to; unused for LAW1/LAW2).
    pub dm: f64,
    /// Stress slots per element: the integration points through the
    /// thickness (1..=10), or 2 for global integration.
    pub n_ip: usize,
    /// Global integration (N = 0 computed on the resultants, see [`n0_rule`]):
    /// the two slots are the surface stresses s_m ∓ s_b of the section.
    pub global: bool,
    /// Transverse shear factor actually used (Ashear; 0 when N = 1).
    pub ashear: f64,
    pub ithick: i64,
    pub iplas: i64,
    /// Numerical damping dn (QEPH hourglass dampers and time step).
    pub dn: f64,
    /// LAW36 tension damage and deletion [Eps_t, Eps_m, Eps_f] on the
    /// points' largest in-plane principal strain (the element then keeps
    /// its total strain).
    #[serde(default)]
    pub tension: Option<[f64; 3]>,
    pub material: Material,
    /// The material's failure model (/FAIL/TAB on shells), if any: its
    /// damage per point lives beside the stresses.
    #[serde(default)]
    pub failure: Option<Failure>,
    /// Point positions ζ_k ∈ [−½, ½] (fraction of the thickness, k = 0 at the bottom).
    pub zeta: [f64; MAX_IP],
    /// Membrane weights (N = tΣ w_mem σ_k; they sum to 1).
    pub w_mem: [f64; MAX_IP],
    /// Bending weights (M = t²Σ w_bend σ_k).
    pub w_bend: [f64; MAX_IP],
    /// Constants of the step, derived once from the fields above.
    k: Consts,
}

/// Per-section constants used every step (material moduli, wave speed, hourglass factors).
#[derive(Clone, Copy, Debug, Default, Serialize, Deserialize)]
struct Consts {
    e: f64,
    nu: f64,
    /// Sound speed √(E/ρ₀).
    c: f64,
    /// Transverse shear modulus G·Ashear.
    gs: f64,
    /// ¼ρ₀c.
    rc: f64,
    /// Ashear/(3(1+ν)).
    shfpr3: f64,
    /// √(h_m/2), √(h_f·Ashear/(6(1+ν))), √(h_r/2)/(8√3) (Ishell 1, 2, 4).
    qm: f64,
    qf: f64,
    qr: f64,
    /// √h_r/(8√3) (Ishell 3).
    vr3: f64,
    /// The material has a strain-rate term.
    rate: bool,
    /// The material has a thermal softening term (adiabatic heating).
    thermal: bool,
}

/// Through-thickness rule: equally spaced points, trapezoidal membrane weights,
/// bending weights exact for a piecewise-linear stress (theory manual table).
fn thickness_rule(n: usize) -> ([f64; MAX_IP], [f64; MAX_IP], [f64; MAX_IP]) {
    let mut z = [0.0; MAX_IP];
    let mut wm = [0.0; MAX_IP];
    let mut wb = [0.0; MAX_IP];
    if n == 1 {
        wm[0] = 1.0;
        return (z, wm, wb);
    }
    let h = 1.0 / (n - 1) as f64;
    for k in 0..n {
        z[k] = -0.5 + k as f64 * h;
        wm[k] = h;
        wb[k] = z[k] * h;
    }
    wm[0] = 0.5 * h;
    wm[n - 1] = 0.5 * h;
    // ∫ ζ φ dζ over the half hat of an end point: (½ − h)h/2 + h²/3.
    let end = (0.5 - h) * 0.5 * h + h * h / 3.0;
    wb[0] = -end;
    wb[n - 1] = end;
    (z, wm, wb)
}

/// How a section with N = 0 is computed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum N0Rule {
    /// Global integration on the resultants (elastic plate law, Ilyushin yield).
    Global,
    /// Numerical integration with this many points through the thickness.
    Points(usize),
}

/// N = 0 as the reference engine computes it: its starter does not support
/// global integration for LAW2 and switches to NPT = 3 (WARNING 1912 in the BOULE1V4
/// and INT357 reference listings: "GLOBAL INTEGRATION FORMULATION (NPT = 0) IS
/// NOT SUPPORTED FOR THE FOLLOWING LAWS, SWITCHING AUTOMATICALLY TO NUMERICAL
/// INTEGRATION NPT= 3", LAW TYPE 2). An elastic section (LAW1) is computed
/// with global integration, which equals any N ≥ 2 to round-off.
pub fn n0_rule(m: &Material) -> N0Rule {
    if m.is_plastic() {
        N0Rule::Points(3)
    } else {
        N0Rule::Global
    }
}

impl ShellSection {
    /// The section of a property and material; N = 0 follows [`n0_rule`].
    pub fn new(r: &ResolvedShell, m: &Material) -> Result<ShellSection, String> {
        Self::build(r, m, n0_rule(m))
    }

    /// The section with N = 0 computed by `n0` (any other N as given).
    pub fn build(r: &ResolvedShell, m: &Material, n0: N0Rule) -> Result<ShellSection, String> {
        if let Some(why) = m.shell_refusal() {
            return Err(why);
        }
        match r.ishell {
            1..=4 | 24 => {}
            12 => return Err("Ishell = 12 (QBAT) is computed by its own formulation (element/shell4_qbat.rs), not by the Belytschko-Tsay section".into()),
            v => return Err(format!("Ishell = {v}: expected 1, 2, 3, 4 (Belytschko-Tsay) or 24 (QEPH)")),
        }
        let ismstr = match r.ismstr {
            1 | 2 | 4 => r.ismstr,
            -1 => 2,
            v => return Err(format!("Ismstr = {v} is not supported: the engine computes Ismstr = 1, 2, 4 (corotational rate form)")),
        };
        if !(0..=MAX_IP as i64).contains(&r.n) {
            return Err(format!(
                "N = {}: expected 0 (global integration) or 1..10 integration points through the thickness",
                r.n
            ));
        }
        if !(0..=1).contains(&r.ithick) {
            return Err(format!("Ithick = {}: expected 0 or 1", r.ithick));
        }
        if !(0..=2).contains(&r.iplas) {
            return Err(format!("Iplas = {}: expected 0, 1 or 2", r.iplas));
        }
        m.check_supported()?;
        let (n_ip, global) = match (r.n, n0) {
            (0, N0Rule::Global) => (2, true),
            (0, N0Rule::Points(n)) => (n.clamp(1, MAX_IP), false),
            (n, _) => (n as usize, false),
        };
        if m.brittle().is_some() && (global || r.iplas == 2) {
            return Err(format!(
                "/MAT/LAW27 with {}: not computed; expected N >= 1 points and Iplas 0 or 1",
                if global {
                    "global integration (N = 0)".to_string()
                } else {
                    "Iplas = 2".into()
                }
            ));
        }
        // LAW27's membrane damping defaults to 0.05 (the reference starter's
        // shell group parameters).
        let dm = if m.brittle().is_some() && r.dm == 0.0 {
            0.05
        } else {
            r.dm
        };
        // Global integration stores the surface stresses: the N = 2 rule.
        let (zeta, w_mem, w_bend) = thickness_rule(n_ip);
        Ok(ShellSection {
            ishell: r.ishell,
            ismstr,
            hm: r.hm,
            hf: r.hf,
            hr: r.hr,
            dm,
            n_ip,
            global,
            ashear: if n_ip == 1 { 0.0 } else { r.ashear },
            ithick: r.ithick,
            iplas: r.iplas,
            dn: r.dn,
            tension: m.tension_damage(),
            material: m.clone(),
            failure: None,
            zeta,
            w_mem,
            w_bend,
            k: Consts::default(),
        }
        .with_consts())
    }

    /// The membrane damping the law takes (LAW27: dm, 0.05 when blank;
    /// 0 for every other law, as the reference engine).
    pub fn membrane_damping(&self) -> f64 {
        if self.material.brittle().is_some() {
            self.dm
        } else {
            0.0
        }
    }

    /// The reference's VISCMX = √(1 + dm²) − dm of the membrane damping:
    /// it shortens the element step and stiffens the nodal one.
    pub fn viscmx(&self) -> f64 {
        let dm = self.membrane_damping();
        (1.0 + dm * dm).sqrt() - dm
    }

    fn with_consts(mut self) -> ShellSection {
        const INV_8_SQRT3: f64 = 0.072_168_783_648_703_22; // 1/(8√3)
        let m = &self.material;
        let (e, nu) = (m.young(), m.poisson());
        let c = m.sound_speed();
        self.k = Consts {
            e,
            nu,
            c,
            gs: m.shear_modulus() * self.ashear,
            rc: 0.25 * m.rho_ref() * c,
            shfpr3: self.ashear / (3.0 * (1.0 + nu)),
            // Quadratic hourglass viscosities (Ishell 1, 2, 4): ¼ρ·100·½·h
            // per mode, the flexural one with √(k/(3(1+ν))), the rotational
            // one with 1/(8√3).
            qm: 12.5 * m.rho_ref() * self.hm,
            qf: 12.5 * m.rho_ref() * self.hf * (self.ashear / (3.0 * (1.0 + nu))).sqrt(),
            qr: 12.5 * m.rho_ref() * self.hr * INV_8_SQRT3,
            vr3: self.hr.sqrt() * INV_8_SQRT3,
            rate: m.is_rate_dependent(),
            thermal: m.is_thermal(),
        };
        self
    }
}

/// What a shell point keeps beside its stress and ε_p: the failure model's
/// damage in [0], or LAW27's damage d₁, crack strain k₁ and the angle of its
/// damage direction in the element frame.
pub type PointHistory = [f64; 3];

/// Per-element state kept by the solver (small, `Copy`).
///
/// Per integration point the solver keeps `[σxx, σyy, σxy, σyz, σzx]` (local
/// frame) and ε_p, `n_ip` of each per element, and hands them in as slices.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Shell4State {
    /// Current thickness.
    pub thick: f64,
    /// Initial area (½|d13 × d24|).
    pub area0: f64,
    /// Elastic hourglass resultants (local frame): membrane x, y; out of plane.
    pub hourglass: [f64; N_HG],
    /// Cumulative internal energy (elastic + plastic, without hourglass).
    pub eint: f64,
    /// Cumulative hourglass energy.
    pub ehg: f64,
    /// Cumulative plastic work.
    pub eplas: f64,
    /// Filtered equivalent strain rate (Johnson-Cook rate term).
    pub eps_dot: f64,
    /// Degenerate quad (node 3 = node 4 at initialisation): no hourglass.
    pub tri: bool,
    /// All points have failed: the element is deleted (zero forces from then on).
    pub deleted: bool,
    /// Ismstr = 1 (small strain): the initial geometry, whose derivatives,
    /// area and time step the element keeps (its frame still turns).
    pub geo0: Option<Geom>,
    /// QEPH (Ishell 24): the twelve hourglass stresses (element frame).
    pub qeph: [f64; 12],
    /// Total membrane strain and curvature [ε_xx, ε_yy, γ_xy, κ_xx, κ_yy,
    /// κ_xy] (local frame), kept for LAW36's tension damage.
    pub strain: [f64; 6],
    /// Initial characteristic (time-step) length, for a failure model's
    /// element-size factor.
    pub len0: f64,
}

/// What one element step returns.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Shell4Out {
    /// Internal corner forces (global frame); the solver subtracts them.
    pub f: [[f64; 3]; 4],
    /// Internal corner moments (global frame).
    pub m: [[f64; 3]; 4],
    /// Critical (unscaled) time step; ∞ for a deleted or degenerate element.
    pub dt: f64,
    /// Internal energy increment (elastic + plastic, excluding hourglass).
    pub d_eint: f64,
    /// Hourglass energy increment.
    pub d_ehg: f64,
    /// Plastic work increment.
    pub d_eplas: f64,
    /// The element is deleted (all its points failed).
    pub failed: bool,
    /// Zero area, or the element turned inside out during the step: the solver stops.
    pub bad_area: bool,
}

use super::lanes::{cross, dot, scale, sub, Real, F4};
/// a·p + b·q + c·r for vectors p, q, r.
#[inline(always)]
fn comb3<R: Real>(a: R, p: [R; 3], b: R, q: [R; 3], c: R, r: [R; 3]) -> [R; 3] {
    [
        a * p[0] + b * q[0] + c * r[0],
        a * p[1] + b * q[1] + c * r[1],
        a * p[2] + b * q[2] + c * r[2],
    ]
}
/// Σ_I w_I u_I for four vectors.
#[inline(always)]
fn wsum<R: Real>(w: &[R; 4], u: &[[R; 3]; 4]) -> [R; 3] {
    [
        w[0] * u[0][0] + w[1] * u[1][0] + w[2] * u[2][0] + w[3] * u[3][0],
        w[0] * u[0][1] + w[1] * u[1][1] + w[2] * u[2][1] + w[3] * u[3][1],
        w[0] * u[0][2] + w[1] * u[1][2] + w[2] * u[2][2] + w[3] * u[3][2],
    ]
}

/// Corotational geometry of one configuration.
///
/// With d13 = x3 − x1, d24 = x4 − x2, h = x1 − x2 + x3 − x4 and the centroid c,
/// the corners are x1 − c = ¼(h − 2d13), x2 − c = ¼(−h − 2d24),
/// x3 − c = ¼(h + 2d13), x4 − c = ¼(−h + 2d24); the diagonals are in the plane
/// (e3 ⟂ d13, d24), so the warp is z_I = ¼(e3·h)Γ_I.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Geom<R = f64> {
    /// Rows e1, e2, e3.
    e: [[R; 3]; 3],
    /// Local in-plane coordinates relative to the centroid.
    x: [R; 4],
    y: [R; 4],
    area: R,
    bx: [R; 4],
    by: [R; 4],
    /// Orthogonal hourglass vector γ = Γ − (Γ·x)b_x − (Γ·y)b_y.
    gam: [R; 4],
    /// γ·z = e3·h (warping coupling of the membrane hourglass rates; γ·Γ = 4).
    gz: R,
}

impl Geom {
    #[inline(always)]
    fn new(p: &[[f64; 3]; 4]) -> Option<Geom> {
        let (g, ok) = Geom::build(p);
        ok.then_some(g)
    }
}

impl<R: Real> Geom<R> {
    /// The geometry of corners `p`, and whether every lane has a finite,
    /// non-vanishing and positive area (NaN-safe: anything else is refused).
    #[inline(always)]
    fn build(p: &[[R; 3]; 4]) -> (Geom<R>, bool) {
        let d13 = sub(p[2], p[0]);
        let d24 = sub(p[3], p[1]);
        let n = cross(d13, d24);
        let nn2 = dot(n, n);
        let dd = R::splat(1e-12) * (dot(d13, d13) + dot(d24, d24));
        let sized = (0..R::LANES).all(|i| {
            let (a, d) = (nn2.lane(i), dd.lane(i));
            !(a.is_nan() || a <= d * d)
        });
        let one = R::splat(1.0);
        let e3 = scale(n, one / nn2.sqrt());
        // e1 ∝ g1 + g2 × e3 with the mid-lines g1 = d13 − d24, g2 = d13 + d24
        // (g2 × e3 is g2 turned by −90°; never opposite to g1 since g1 × g2 ∥ +e3).
        let g1 = sub(d13, d24);
        let g2 = [d13[0] + d24[0], d13[1] + d24[1], d13[2] + d24[2]];
        let bt = cross(g2, e3);
        let s = [g1[0] + bt[0], g1[1] + bt[1], g1[2] + bt[2]];
        let e1 = scale(s, one / dot(s, s).sqrt());
        let e2 = cross(e3, e1);
        let h = [
            p[0][0] - p[1][0] + p[2][0] - p[3][0],
            p[0][1] - p[1][1] + p[2][1] - p[3][1],
            p[0][2] - p[1][2] + p[2][2] - p[3][2],
        ];
        let (x13, x24, xh) = (dot(e1, d13), dot(e1, d24), dot(e1, h));
        let (y13, y24, yh) = (dot(e2, d13), dot(e2, d24), dot(e2, h));
        let area = R::splat(0.5) * (x13 * y24 - x24 * y13);
        let ok = sized && area.all(|a| !(a.is_nan() || a <= 0.0));
        let (q, mq, two) = (R::splat(0.25), R::splat(-0.25), R::splat(2.0));
        let x = [
            q * (xh - two * x13),
            mq * (xh + two * x24),
            q * (xh + two * x13),
            q * (two * x24 - xh),
        ];
        let y = [
            q * (yh - two * y13),
            mq * (yh + two * y24),
            q * (yh + two * y13),
            q * (two * y24 - yh),
        ];
        let r2a = R::splat(0.5) / area;
        let bx = [-y24 * r2a, y13 * r2a, y24 * r2a, -y13 * r2a];
        let by = [x24 * r2a, -x13 * r2a, -x24 * r2a, x13 * r2a];
        // Γ·x = xh, Γ·y = yh.
        let gam = [
            one - xh * bx[0] - yh * by[0],
            -one - xh * bx[1] - yh * by[1],
            one - xh * bx[2] - yh * by[2],
            -one - xh * bx[3] - yh * by[3],
        ];
        let g = Geom {
            e: [e1, e2, e3],
            x,
            y,
            area,
            bx,
            by,
            gam,
            gz: dot(e3, h),
        };
        (g, ok)
    }
}

/// Characteristic length of the reference engine's shell time step (see the module doc).
#[inline]
fn char_length<R: Real>(sec: &ShellSection, g: &Geom<R>, tri: bool) -> R {
    let d2 = |i: usize, j: usize| {
        let dx = g.x[j] - g.x[i];
        let dy = g.y[j] - g.y[i];
        dx * dx + dy * dy
    };
    let (l12, l23, l34, l41) = (d2(0, 1), d2(1, 2), d2(2, 3), d2(3, 0));
    let (d13, d24) = (d2(0, 2), d2(1, 3));
    let mut lmin = l12.min(l23).min(l41);
    if !tri {
        lmin = lmin.min(l34).min(d13).min(d24);
    }
    let dyn2 = g.area * g.area / d13.max(d24).max(R::splat(1e-300));
    let mut l2 = dyn2.max(lmin);
    let h = sec.hm.max(sec.hf);
    if h > 0.0 {
        l2 = l2.min(R::splat(0.5) * (lmin + l2) / R::splat(h));
    }
    l2.sqrt()
}

/// The element's nodal stiffness for the nodal time step (/DT/NODA, the
/// reference engine's shell stiffness; research note
/// `docs/notes/impdisp_fgeo_research.md` §4): K = max(B₁, B₂)·t·A₁₁/A, with
/// B_k = ¼|d_k|² the squared half diagonals in the element's plane (the
/// reference's PX² + PY²) and A₁₁ = E/(1 − ν²), given to each corner, and
/// K_rot = K·(t²/12 + A/9), divided by VISCMX² where the law has membrane
/// damping (LAW27, research note `docs/notes/law27_research.md` §4). On a
/// square of side L every node then has the element step L/c as its nodal
/// step √(2m/K). The reference's hourglass term (its viscous hourglass
/// coefficients over Δt) is left out.
pub fn nodal_stiffness(sec: &ShellSection, x: &[[f64; 3]; 4], t: f64) -> (f64, f64) {
    let (d13, d24) = (sub(x[2], x[0]), sub(x[3], x[1]));
    let n = cross(d13, d24);
    let nn = dot(n, n).sqrt();
    if !(nn > 0.0) {
        return (0.0, 0.0);
    }
    let area = 0.5 * nn;
    let e = scale(n, 1.0 / nn);
    let half_sq = |d: [f64; 3]| 0.25 * (dot(d, d) - dot(d, e).powi(2));
    let vm = sec.viscmx();
    let k = half_sq(d13).max(half_sq(d24)) * t * sec.material.a11() / (area * vm * vm);
    (k, k * (t * t / 12.0 + area / 9.0))
}

/// Element state at t = 0.
pub fn shell4_init(sec: &ShellSection, x: &[[f64; 3]; 4], thick: f64) -> Shell4State {
    let n = cross(sub(x[2], x[0]), sub(x[3], x[1]));
    let tri = x[2] == x[3];
    let len0 = match Geom::new(x) {
        Some(g) if sec.ishell == 24 && !tri => qeph::char_length(sec, &g),
        Some(g) => char_length(sec, &g, tri),
        None => 0.0,
    };
    Shell4State {
        thick,
        area0: 0.5 * dot(n, n).sqrt(),
        tri,
        len0,
        geo0: if sec.ismstr == 1 { Geom::new(x) } else { None },
        ..Default::default()
    }
}

/// Ismstr = 1, small strain from t = 0: strain rates and forces use the
/// initial in-plane derivatives, area and hourglass vectors in the current
/// corotational frame, and the time step stays the initial one.
#[inline]
fn small_strain(g: &mut Geom, g0: &Geom) {
    let e = g.e;
    *g = *g0;
    g.e = e;
}

/// Membrane N, bending M and transverse shear Q = (Q_x, Q_y) resultants (local
/// frame, per unit length) of an element's points.
pub fn shell4_resultants(
    sec: &ShellSection,
    thick: f64,
    sig: &[[f64; 5]],
) -> ([f64; 3], [f64; 3], [f64; 2]) {
    let mut nr = [0.0; 3];
    let mut mr = [0.0; 3];
    let mut q = [0.0; 2];
    for (k, s) in sig[..sec.n_ip].iter().enumerate() {
        let (wm, wb) = (sec.w_mem[k] * thick, sec.w_bend[k] * thick * thick);
        for c in 0..3 {
            nr[c] += wm * s[c];
            mr[c] += wb * s[c];
        }
        q[0] += wm * s[4];
        q[1] += wm * s[3];
    }
    (nr, mr, q)
}

/// In-plane update of one element's stress slots over a step, shared by the
/// 4- and 3-node shells. `sig` holds the slots already in this step's frame
/// (transverse shear updated); `d_m`, `d_k`: membrane strain and curvature
/// rates (engineering shears) of the step `dt`, thickness `t`.
/// * Points: each point k gets Δε = (d_m + ζ_k t d_k)Δt through
///   [`PointLaw::plane_stress`] with the section's Iplas.
/// * Global integration: `PointLaw::section_global` on s_m = ½(σ_0 + σ_1),
///   s_b = ½(σ_1 − σ_0) with Δε = d_m Δt and the surface bending strain
///   ½t d_k Δt; the slots become s_m ∓ s_b and both keep the section's ε̄_p.
///
/// A failed slot gets zero stress (transverse shear included). With a
/// failure model (`sec.failure`, /FAIL/TAB) each point's damage `dmg` grows
/// with its plastic increment at the failure strain of `at`; a failed point
/// carries no stress (Ifail_sh 1, 2) or keeps it (3). Returns the plastic
/// work per unit volume Σ w_N Δw_p, the thickness strain increment Σ w_N Δε_zz
/// and whether the element is deleted: all points failed (or the first one,
/// LAW36's EPS_p_max) by the law, or the failure model's deletion rule.
#[allow(clippy::too_many_arguments)]
pub(super) fn update_slots(
    sec: &ShellSection,
    law: &PointLaw,
    t: f64,
    sig: &mut [[f64; 5]],
    eps_p: &mut [f64],
    dmg: &mut [PointHistory],
    at: &FailAt,
    d_m: [f64; 3],
    d_k: [f64; 3],
    dt: f64,
    strain: Option<&[f64; 6]>,
) -> (f64, f64, bool) {
    if sec.global {
        let (lo, hi) = (sig[0], sig[1]);
        let mut s_m = [0.0; 3];
        let mut s_b = [0.0; 3];
        for c in 0..3 {
            s_m[c] = 0.5 * (lo[c] + hi[c]);
            s_b[c] = 0.5 * (hi[c] - lo[c]);
        }
        let de_m = [d_m[0] * dt, d_m[1] * dt, d_m[2] * dt];
        let hb = 0.5 * t * dt;
        let de_b = [d_k[0] * hb, d_k[1] * hb, d_k[2] * hb];
        let mut ep = eps_p[0];
        let r = law.section_global(&mut s_m, &mut s_b, &mut ep, de_m, de_b);
        eps_p[0] = ep;
        eps_p[1] = ep;
        if r.failed {
            sig[0] = [0.0; 5];
            sig[1] = [0.0; 5];
            return (r.d_wplas, r.d_ezz, true);
        }
        for c in 0..3 {
            sig[0][c] = s_m[c] - s_b[c];
            sig[1][c] = s_m[c] + s_b[c];
        }
        return (r.d_wplas, r.d_ezz, false);
    }
    let fail = sec.failure.as_ref().and_then(Failure::shell);
    let (mut dwp, mut dezz, mut nfailed) = (0.0, 0.0, 0);
    let (mut w_broken, mut nbroken) = (0.0, 0);
    for (k, (s, ep)) in sig.iter_mut().zip(eps_p.iter_mut()).enumerate() {
        let wm = sec.w_mem[k];
        if fail.is_some_and(|f| f.has_failed(dmg[k][0]) && f.zeroes_shell_point()) {
            // A failed point of Ifail_sh 1, 2 stays off: no stress, no work.
            *s = [0.0; 5];
            w_broken += wm;
            nbroken += 1;
            continue;
        }
        let z = sec.zeta[k] * t;
        let d = [
            (d_m[0] + z * d_k[0]) * dt,
            (d_m[1] + z * d_k[1]) * dt,
            (d_m[2] + z * d_k[2]) * dt,
        ];
        let mut s3 = [s[0], s[1], s[2]];
        if let Some(l27) = sec.material.brittle() {
            let total = strain.map_or([0.0; 3], |e| {
                [e[0] + z * e[3], e[1] + z * e[4], e[2] + z * e[5]]
            });
            let r = l27.shell_point(&mut s3, ep, &mut dmg[k], d, dt, total);
            s[..3].copy_from_slice(&s3);
            nfailed += r.torn as usize;
            dwp += wm * r.d_wplas;
            dezz += wm * r.d_ezz;
            continue;
        }
        let (lk, torn) = match (sec.tension, strain) {
            (Some([et, em, ef]), Some(e)) => {
                let e1 = principal_in_plane([e[0] + z * e[3], e[1] + z * e[4], e[2] + z * e[5]]);
                let f = crate::material::tension_factor(et, em, e1);
                (law.with_yield_scale(f), e1 > ef)
            }
            _ => (*law, false),
        };
        let ep0 = *ep;
        let r = lk.plane_stress(&mut s3, ep, d, sec.iplas);
        if r.failed || torn {
            *s = [0.0; 5];
            nfailed += 1;
        } else {
            s[..3].copy_from_slice(&s3);
            if let Some(f) = fail {
                if f.shell(&s3, &mut dmg[k][0], *ep - ep0, at) {
                    if f.zeroes_shell_point() {
                        *s = [0.0; 5];
                    }
                    w_broken += wm;
                    nbroken += 1;
                }
            }
        }
        dwp += wm * r.d_wplas;
        dezz += wm * r.d_ezz;
    }
    let n_ip = sig.len();
    let by_law = nfailed == n_ip || (nfailed > 0 && sec.material.deletes_at_first_failed_point());
    let by_model = fail.is_some_and(|f| f.deletes_shell(w_broken, nbroken, n_ip));
    (dwp, dezz, by_law || by_model)
}

/// The largest principal value of an in-plane strain [ε_xx, ε_yy, γ_xy]
/// (engineering shear).
#[inline]
fn principal_in_plane(e: [f64; 3]) -> f64 {
    0.5 * (e[0] + e[1]) + 0.5 * ((e[0] - e[1]).powi(2) + e[2] * e[2]).sqrt()
}

/// Rotation (cos, sin) applied to plane tensors and vectors.
#[derive(Clone, Copy, Debug)]
struct Rot<R = f64> {
    c: R,
    s: R,
}

impl<R: Real> Rot<R> {
    /// The rotation by ψ with tan(ψ/2) = p.
    #[inline(always)]
    fn cayley(p: R) -> Rot<R> {
        let one = R::splat(1.0);
        let d = one / (one + p * p);
        Rot {
            c: (one - p * p) * d,
            s: R::splat(2.0) * p * d,
        }
    }
    /// Components (xx, yy, xy) of the symmetric tensor turned by the angle:
    /// R a Rᵀ with R = [[c, −s], [s, c]].
    #[inline(always)]
    fn stress(self, a: [R; 3]) -> [R; 3] {
        let (c, s) = (self.c, self.s);
        let (cc, ss, cs) = (c * c, s * s, c * s);
        let two = R::splat(2.0);
        [
            cc * a[0] + ss * a[1] - two * cs * a[2],
            ss * a[0] + cc * a[1] + two * cs * a[2],
            cs * (a[0] - a[1]) + (cc - ss) * a[2],
        ]
    }
    /// The same for a strain-like tensor given with its engineering shear (xx, yy, 2xy).
    #[inline(always)]
    fn strain(self, a: [R; 3]) -> [R; 3] {
        let r = self.stress([a[0], a[1], R::splat(0.5) * a[2]]);
        [r[0], r[1], R::splat(2.0) * r[2]]
    }
    /// Components of the in-plane vector turned by the angle.
    #[inline(always)]
    fn vector(self, x: R, y: R) -> (R, R) {
        (self.c * x - self.s * y, self.s * x + self.c * y)
    }
    #[inline(always)]
    fn lane(self, i: usize) -> Rot {
        Rot {
            c: self.c.lane(i),
            s: self.s.lane(i),
        }
    }
}

/// The step's kinematics on the mid-step geometry (see [`shell4_step`]):
/// generalized strain rates turned by half the step's rotation ψ/2, the
/// rotations ψ (stored stresses) and ψ/2, and the hourglass rates.
#[derive(Clone, Copy, Debug)]
struct Rates<R = f64> {
    /// Membrane strain rates (xx, yy, 2xy).
    d_m: [R; 3],
    /// Curvature rates (xx, yy, 2xy).
    d_k: [R; 3],
    /// Transverse shear rates γ_zx, γ_yz.
    gxz: R,
    gyz: R,
    rot_old: Rot<R>,
    rot_inc: Rot<R>,
    /// Hourglass rates q_x, q_y, q_z, q_rx, q_ry.
    hg: [R; 5],
}

impl<R: Real> Rates<R> {
    /// The rates of corners `v`, `vr` on the mid-step geometry `gm`, with the
    /// frame turn from `gm` to the end geometry `ge` (none when `dt` = 0).
    /// `orth`: the orthogonal hourglass vector γ, else Γ.
    #[inline(always)]
    fn new(
        gm: &Geom<R>,
        ge: &Geom<R>,
        v: &[[R; 3]; 4],
        vr: &[[R; 3]; 4],
        dt: f64,
        orth: bool,
    ) -> Rates<R> {
        let [m1, m2, m3] = gm.e;
        let vbx = wsum(&gm.bx, v); // Σ b_x,I v_I
        let vby = wsum(&gm.by, v);
        let wbx = wsum(&gm.bx, vr);
        let wby = wsum(&gm.by, vr);
        let wbar = scale(
            [
                vr[0][0] + vr[1][0] + vr[2][0] + vr[3][0],
                vr[0][1] + vr[1][1] + vr[2][1] + vr[3][1],
                vr[0][2] + vr[1][2] + vr[2][2] + vr[3][2],
            ],
            R::splat(0.25),
        );
        let (bxvy, byvx) = (dot(m2, vbx), dot(m1, vby));
        let d_m = [dot(m1, vbx), dot(m2, vby), byvx + bxvy];
        let d_k = [dot(m2, wbx), -dot(m1, wby), dot(m2, wby) - dot(m1, wbx)];
        let bxvz = dot(m3, vbx);
        let byvz = dot(m3, vby);
        let gxz = bxvz + dot(m2, wbar);
        let gyz = byvz - dot(m1, wbar);
        let one = R::splat(1.0);
        // ---- rotations: material spin minus frame spin ----------------------------
        let (rot_old, rot_inc) = if dt > 0.0 {
            // Frame turn: Rodrigues vector g = tan(β/2)·axis of the rotation taking
            // the mid-step frame to the end frame (components in the mid frame);
            // the whole step's turn about the normal has tan(Θ/2) = 2g_z/(1 − |g|²).
            let (m, e) = (&gm.e, &ge.e);
            let tr = dot(m[0], e[0]) + dot(m[1], e[1]) + dot(m[2], e[2]);
            let inv = one / (one + tr);
            let gx = (dot(m[2], e[1]) - dot(m[1], e[2])) * inv;
            let gy = (dot(m[0], e[2]) - dot(m[2], e[0])) * inv;
            let gz = (dot(m[1], e[0]) - dot(m[0], e[1])) * inv;
            let tf = R::splat(2.0) * gz / (one - (gx * gx + gy * gy + gz * gz));
            // Material turn: tan(φ/2) = ω_z Δt/2 (midpoint rule, exact for a rigid spin).
            let tm = R::splat(0.25) * (bxvy - byvx) * R::splat(dt);
            // ψ = φ − Θ for the stored stress, ψ/2 for the mid-step increments.
            let p = (tm - tf) / (one + tm * tf);
            let ph = p / (one + (one + p * p).sqrt());
            (Rot::cayley(p), Rot::cayley(ph))
        } else {
            (Rot::cayley(R::splat(0.0)), Rot::cayley(R::splat(0.0)))
        };
        // Hourglass rates: orthogonal γ for Ishell 1, 3, 4 (with the warping
        // term), Γ for Ishell 2 and under small strain.
        let (gmv, gzm) = if orth {
            (gm.gam, gm.gz)
        } else {
            (GAMMA.map(R::splat), R::splat(0.0))
        };
        let vg = wsum(&gmv, v);
        let wg = wsum(&gmv, vr);
        let (qx, qy) = rot_inc.vector(dot(m1, vg) + gzm * bxvz, dot(m2, vg) + gzm * byvz);
        let qz = dot(m3, vg);
        let (qrx, qry) = rot_inc.vector(dot(m1, wg), dot(m2, wg));
        let (gxz, gyz) = rot_inc.vector(gxz, gyz);
        Rates {
            d_m: rot_inc.strain(d_m),
            d_k: rot_inc.strain(d_k),
            gxz,
            gyz,
            rot_old,
            rot_inc,
            hg: [qx, qy, qz, qrx, qry],
        }
    }

    #[inline(always)]
    fn lane(&self, i: usize) -> Rates {
        let l = |a: [R; 3]| a.map(|r| r.lane(i));
        Rates {
            d_m: l(self.d_m),
            d_k: l(self.d_k),
            gxz: self.gxz.lane(i),
            gyz: self.gyz.lane(i),
            rot_old: self.rot_old.lane(i),
            rot_inc: self.rot_inc.lane(i),
            hg: self.hg.map(|r| r.lane(i)),
        }
    }
}

/// What an element's points give over the step.
#[derive(Clone, Copy, Debug)]
struct Points<'a> {
    /// Resultants per unit length at x^{n+1}: membrane N, bending M, shear (Q_x, Q_y).
    nr: [f64; 3],
    mr: [f64; 3],
    q: [f64; 2],
    /// Thickness strain increment Σ w_N Δε_zz.
    dezz: f64,
    /// The element is deleted (its points failed).
    deleted: bool,
    d_eint: f64,
    d_eplas: f64,
    /// The points' law at this step's strain rate and temperature, and their ε_p before it.
    law: PointLaw<'a>,
    ep0: [f64; MAX_IP],
}

/// Sums over an element's points per unit thickness: Σ w_N σ (membrane),
/// Σ w_M σ (bending), Σ w_N τ (shear zx, yz).
#[derive(Clone, Copy, Debug)]
struct Sums<R = f64> {
    n: [R; 3],
    m: [R; 3],
    q: [R; 2],
}

impl<R: Real> Sums<R> {
    #[inline(always)]
    fn zero() -> Sums<R> {
        let z = R::splat(0.0);
        Sums {
            n: [z; 3],
            m: [z; 3],
            q: [z; 2],
        }
    }
    /// Adds point k's in-plane stress `s` and shears `zx`, `yz`.
    #[inline(always)]
    fn add(&mut self, sec: &ShellSection, k: usize, s: [R; 3], zx: R, yz: R) {
        let (wm, wb) = (R::splat(sec.w_mem[k]), R::splat(sec.w_bend[k]));
        for c in 0..3 {
            self.n[c] = self.n[c] + wm * s[c];
            self.m[c] = self.m[c] + wb * s[c];
        }
        self.q[0] = self.q[0] + wm * zx;
        self.q[1] = self.q[1] + wm * yz;
    }
}

/// The work of the resultants over the step per unit area,
/// ½Δt(t(N̄:d) + t²(M̄:κ) + t(Q̄·γ)) with the old and new sums (conjugate to
/// the forces).
#[inline(always)]
fn resultant_work<R: Real>(t: R, old: &Sums<R>, new: &Sums<R>, r: &Rates<R>, dt: f64) -> R {
    let (no, nr, mo, mr, qo, qr) = (old.n, new.n, old.m, new.m, old.q, new.q);
    let (d_m, d_k) = (r.d_m, r.d_k);
    R::splat(0.5)
        * R::splat(dt)
        * (t * ((no[0] + nr[0]) * d_m[0] + (no[1] + nr[1]) * d_m[1] + (no[2] + nr[2]) * d_m[2])
            + t * t
                * ((mo[0] + mr[0]) * d_k[0] + (mo[1] + mr[1]) * d_k[1] + (mo[2] + mr[2]) * d_k[2])
            + t * ((qo[0] + qr[0]) * r.gxz + (qo[1] + qr[1]) * r.gyz))
}

/// A stored point stress [σxx, σyy, σxy, σyz, σzx] turned to this step's
/// frame by ψ, with the elastic transverse shear increments `dg_yz`,
/// `dg_zx` (already times G·k); returns the turned old stress and the new slot.
#[inline(always)]
fn turn_slot<R: Real>(s: [R; 5], rot: Rot<R>, dg_yz: R, dg_zx: R) -> ([R; 3], R, R, [R; 5]) {
    let o = rot.stress([s[0], s[1], s[2]]);
    let (ozx, oyz) = rot.vector(s[4], s[3]);
    (o, ozx, oyz, [o[0], o[1], o[2], oyz + dg_yz, ozx + dg_zx])
}

/// The element's filtered strain rate (Johnson-Cook rate term, failure
/// models) and its law at this step's rate and temperature.
fn rate_and_law<'a>(
    sec: &'a ShellSection,
    st: &mut Shell4State,
    r: &Rates,
    dt: f64,
    area_m: f64,
) -> (PointLaw<'a>, f64) {
    let (mat, kc) = (&sec.material, &sec.k);
    let (d_m, d_k) = (r.d_m, r.d_k);
    let t = st.thick;
    if dt > 0.0 && (kc.rate || sec.failure.is_some()) {
        let (a, b, g) = (d_m[0], d_m[1], d_m[2]);
        let em = a * a + b * b + a * b + 0.25 * g * g;
        let (a, b, g) = (d_k[0], d_k[1], d_k[2]);
        let ek = a * a + b * b + a * b + 0.25 * g * g;
        let raw = (4.0 / 3.0 * em + t * t / 9.0 * ek).sqrt();
        st.eps_dot = mat.filter_strain_rate(st.eps_dot, raw, dt);
    }
    let temp = if kc.thermal {
        mat.temperature(st.eint / (area_m * t))
    } else {
        mat.reference_temperature()
    };
    (mat.at(st.eps_dot, temp), temp)
}

/// The points of one element over the step (scalar: laws branch point by
/// point): strain rate filter, old stresses turned by ψ, the laws through
/// [`update_slots`], the work of the resultants and LAW27's membrane
/// viscosity. `area_m`, `area_e`: the mid-step and end areas.
#[allow(clippy::too_many_arguments)]
fn points<'a>(
    sec: &'a ShellSection,
    st: &mut Shell4State,
    sig: &mut [[f64; 5]],
    eps_p: &mut [f64],
    dmg: &mut [PointHistory],
    r: &Rates,
    dt: f64,
    area_m: f64,
    area_e: f64,
) -> Points<'a> {
    let (mat, kc, n_ip) = (&sec.material, &sec.k, sec.n_ip);
    let (d_m, d_k, rot_old) = (r.d_m, r.d_k, r.rot_old);
    let t = st.thick;
    let (law, temp) = rate_and_law(sec, st, r, dt, area_m);

    // ---- stress update at the points ------------------------------------------
    let (dg_zx, dg_yz) = (kc.gs * (r.gxz * dt), kc.gs * (r.gyz * dt));
    let mut old = Sums::zero();
    let mut ep0 = [0.0; MAX_IP];
    let (dwp, dezz, deleted) = if dt > 0.0 {
        // Old stresses turned to this step's frame; transverse shear elastic.
        for (k, s) in sig.iter_mut().enumerate() {
            let (o, ozx, oyz, new) = turn_slot(*s, rot_old, dg_yz, dg_zx);
            old.add(sec, k, o, ozx, oyz);
            *s = new;
        }
        ep0[..n_ip].copy_from_slice(eps_p);
        if sec.material.brittle().is_some() {
            // LAW27's damage directions turn with the stresses.
            let psi = rot_old.s.atan2(rot_old.c);
            dmg[..n_ip].iter_mut().for_each(|h| h[2] += psi);
        }
        let strain = if sec.tension.is_some() || sec.material.brittle().is_some() {
            // The total strain turns with the stresses, then takes this step's increment.
            let e = &mut st.strain;
            let (m, k) = (
                rot_old.strain([e[0], e[1], e[2]]),
                rot_old.strain([e[3], e[4], e[5]]),
            );
            *e = std::array::from_fn(|c| {
                if c < 3 {
                    m[c] + d_m[c] * dt
                } else {
                    k[c - 3] + d_k[c - 3] * dt
                }
            });
            Some(&st.strain)
        } else {
            None
        };
        let at = FailAt {
            rate: st.eps_dot,
            len0: st.len0,
            tstar: mat.homologous_temperature(temp),
        };
        let dmg = &mut dmg[..n_ip];
        update_slots(sec, &law, t, sig, eps_p, dmg, &at, d_m, d_k, dt, strain)
    } else {
        let failed = eps_p.iter().filter(|&&e| law.has_failed(e)).count();
        let deleted = failed == n_ip || (failed > 0 && mat.deletes_at_first_failed_point());
        (0.0, 0.0, deleted)
    };
    let mut new = Sums::zero();
    for (k, s) in sig.iter().enumerate() {
        new.add(sec, k, [s[0], s[1], s[2]], s[4], s[3]);
    }
    let mut out = Points {
        nr: new.n,
        mr: new.m,
        q: new.q,
        dezz,
        deleted,
        d_eint: 0.0,
        d_eplas: 0.0,
        law,
        ep0,
    };
    if dt > 0.0 {
        out.d_eint = resultant_work(t, &old, &new, r, dt) * area_m;
        out.d_eplas = dwp * area_m * t;
        st.eint += out.d_eint;
        st.eplas += out.d_eplas;
    }
    if deleted {
        st.deleted = true;
        return out;
    }
    // LAW27's membrane viscosity (research note `docs/notes/law27_research.md`
    // §2.7): 1.414·dm·ρ·c₀·√A times the membrane strain rates
    // (ε̇xx + ½ε̇yy, ε̇yy + ½ε̇xx, γ̇xy/3) on the mean stresses; its work is
    // internal energy.
    let dm = sec.membrane_damping();
    if dm > 0.0 && dt > 0.0 {
        let f = 1.414 * dm * mat.rho_ref() * mat.sound_speed() * area_e.sqrt();
        let sv = [
            f * (d_m[0] + 0.5 * d_m[1]),
            f * (d_m[1] + 0.5 * d_m[0]),
            f * d_m[2] / 3.0,
        ];
        let dw = (sv[0] * d_m[0] + sv[1] * d_m[1] + sv[2] * d_m[2]) * dt * area_m * t;
        out.d_eint += dw;
        st.eint += dw;
        for c in 0..3 {
            out.nr[c] += sv[c];
        }
    }
    // Resultants per unit length at x^{n+1}.
    out.nr = scale(out.nr, t);
    out.mr = scale(out.mr, t * t);
    out.q = [new.q[0] * t, new.q[1] * t];
    out
}

/// Ishell 1, 2, 4 hourglass (see the module doc): the elastic resultants
/// `hg` turned by ψ and integrated over the step, and the quadratic dampers.
/// Returns the resultants (Q_mx, Q_my, Q_f, M_rx, M_ry), the new elastic
/// resultants and the energy increment: the elastic resultants' mean over the
/// step (the exact change of their stored energy, as the internal energy
/// takes the mean of the old and new resultants) plus the dampers' work.
#[inline(always)]
fn hourglass_visco<R: Real>(
    sec: &ShellSection,
    ge: &Geom<R>,
    t: R,
    r: &Rates<R>,
    hg: [R; N_HG],
    dt: f64,
) -> ([R; 5], [R; N_HG], R) {
    let kc = &sec.k;
    let a = ge.area;
    let [qx, qy, qz, qrx, qry] = r.hg;
    let bsum = a
        * a
        * (ge.bx[0] * ge.bx[0] + ge.by[0] * ge.by[0] + ge.bx[1] * ge.bx[1] + ge.by[1] * ge.by[1]);
    let (h0, h1) = r.rot_old.vector(hg[0], hg[1]);
    // Global factors of the reference engine: elastic ½, quadratic viscosity ½, linear 0.
    let km = R::splat(0.125 * sec.hm * kc.e) * t;
    let kf = R::splat(0.125 * sec.hf * kc.e * kc.shfpr3) * t * t * t / bsum;
    let rdt = R::splat(dt);
    let h2 = hg[2];
    let new = [h0 + km * qx * rdt, h1 + km * qy * rdt, h2 + kf * qz * rdt];
    let cm = R::splat(kc.qm) * t * a.sqrt();
    let cf = R::splat(kc.qf) * t * t;
    let cr = R::splat(kc.qr) * t * t * a;
    let (dmx, dmy, df) = (cm * qx.abs() * qx, cm * qy.abs() * qy, cf * qz.abs() * qz);
    let (mrx, mry) = (cr * qrx.abs() * qrx, cr * qry.abs() * qry);
    let half = R::splat(0.5);
    let d_ehg = rdt
        * ((half * (h0 + new[0]) + dmx) * qx
            + (half * (h1 + new[1]) + dmy) * qy
            + (half * (h2 + new[2]) + df) * qz
            + mrx * qrx
            + mry * qry);
    (
        [new[0] + dmx, new[1] + dmy, new[2] + df, mrx, mry],
        new,
        d_ehg,
    )
}

/// Ishell 3 hourglass (see the module doc): elasto-plastic membrane and
/// flexural resultants capped by the points' mean yield stress, viscous
/// rotations. Returns the resultants and the energy increment; `hg` is updated.
#[allow(clippy::too_many_arguments)]
fn hourglass_plastic(
    sec: &ShellSection,
    ge: &Geom,
    t: f64,
    r: &Rates,
    hg: &mut [f64; N_HG],
    law: &PointLaw,
    eps_p: &[f64],
    dt: f64,
) -> ([f64; 5], f64) {
    let kc = &sec.k;
    let a = ge.area;
    let [qx, qy, qz, qrx, qry] = r.hg;
    let bsum = a
        * a
        * (ge.bx[0] * ge.bx[0] + ge.by[0] * ge.by[0] + ge.bx[1] * ge.bx[1] + ge.by[1] * ge.by[1]);
    let (h0, h1) = r.rot_old.vector(hg[0], hg[1]);
    // Mean current yield stress of the points (∞ for an elastic material).
    let sy_mean: f64 = (0..sec.n_ip)
        .map(|k| sec.w_mem[k] * law.yield_stress(eps_p[k]))
        .sum();
    let km = 0.125 * sec.hm * kc.e * t;
    let kf = 0.125 * sec.hf * kc.e * kc.shfpr3 * t * t * t / bsum;
    let fm_max = 0.5 * sy_mean * t * a.sqrt() * sec.hm;
    let ff_max = 0.25 * sy_mean * t * t * sec.hf;
    let cap = |v: f64, m: f64| if m.is_finite() { v.clamp(-m, m) } else { v };
    hg[0] = cap(h0 + km * qx * dt, fm_max);
    hg[1] = cap(h1 + km * qy * dt, fm_max);
    hg[2] = cap(hg[2] + kf * qz * dt, ff_max);
    let cr = kc.rc * t * t * a * kc.vr3;
    let h = [hg[0], hg[1], hg[2], cr * qrx, cr * qry];
    let d_ehg = dt * (h[0] * qx + h[1] * qy + h[2] * qz + h[3] * qrx + h[4] * qry);
    (h, d_ehg)
}

/// Corner forces and moments at x^{n+1}, global frame, of the resultants
/// per unit length (`nr`, `mr`, `q`) and the hourglass resultants `h`:
/// f_I = b_x,I F_x + b_y,I F_y + γ_I H_f with
/// F_x = A(N_xx e1 + N_xy e2 + Q_x e3) + (γ·z)q_mx e3, F_y likewise, H_f = Q_m,x e1 + Q_m,y e2 + Q_f e3;
/// m_I = b_x,I M_x + b_y,I M_y + M_0 + γ_I H_m with M_x = A(−M_xy e1 + M_xx e2),
/// M_y = A(−M_yy e1 + M_xy e2), M_0 = ¼A(−Q_y e1 + Q_x e2), H_m = M_rx e1 + M_ry e2.
#[inline(always)]
fn corner_forces<R: Real>(
    ge: &Geom<R>,
    orth: bool,
    nr: [R; 3],
    mr: [R; 3],
    q: [R; 2],
    h: [R; 5],
) -> ([[R; 3]; 4], [[R; 3]; 4]) {
    let [e1, e2, e3] = ge.e;
    let a = ge.area;
    let [qmx, qmy, qf, mrx, mry] = h;
    let zero = R::splat(0.0);
    let (gev, gze) = if orth {
        (ge.gam, ge.gz)
    } else {
        (GAMMA.map(R::splat), zero)
    };
    let fx = comb3(a * nr[0], e1, a * nr[2], e2, a * q[0] + gze * qmx, e3);
    let fy = comb3(a * nr[2], e1, a * nr[1], e2, a * q[1] + gze * qmy, e3);
    let hf = comb3(qmx, e1, qmy, e2, qf, e3);
    let mx = comb3(-a * mr[2], e1, a * mr[0], e2, zero, e3);
    let my = comb3(-a * mr[1], e1, a * mr[2], e2, zero, e3);
    let m0 = comb3(
        R::splat(-0.25) * a * q[1],
        e1,
        R::splat(0.25) * a * q[0],
        e2,
        zero,
        e3,
    );
    let hm = comb3(mrx, e1, mry, e2, zero, e3);
    let mut f = [[zero; 3]; 4];
    let mut m = [[zero; 3]; 4];
    for (i, &gi) in gev.iter().enumerate() {
        let (bxi, byi) = (ge.bx[i], ge.by[i]);
        f[i] = comb3(bxi, fx, byi, fy, gi, hf);
        let mm = comb3(bxi, mx, byi, my, gi, hm);
        m[i] = [mm[0] + m0[0], mm[1] + m0[1], mm[2] + m0[2]];
    }
    (f, m)
}

/// One explicit step of one element: stresses from x^{n+1} and v^{n+½}, internal
/// corner forces and moments at x^{n+1}, energies, and the element time step.
///
/// `x`: positions at t^{n+1}; `v`: translational velocities v^{n+½}; `vr`:
/// rotational velocities (global frame); `sig`, `eps_p`: this element's
/// `n_ip` points (stresses in the local frame of x^{n+1} on return).
/// With `dt = 0` only forces and the time step are computed.
///
/// Objectivity: the stored local stresses (and elastic hourglass resultants)
/// are turned by ψ = φ − Θ, the in-plane material rotation of the step minus
/// the frame rotation (midpoint/Hughes-Winget: tan(φ/2) = ω_z Δt/2 with
/// ω_z = ½(∂v_y/∂x − ∂v_x/∂y) on the mid-step geometry; Θ from the Rodrigues
/// vector of the measured frame turn from x^{n+½} to x^{n+1}, doubled); the
/// mid-step strain increments are turned by ψ/2. The stress rate is thus the
/// Jaumann rate whatever the local frame (/SHFRA V4 or V5 alike), and a
/// prestressed element spinning rigidly keeps its stress.
///
/// The local velocity sums are formed in the global frame (Σ b_I v_I, then
/// projected on the frame vectors), and the corner forces are assembled
/// directly in the global frame. [`shell4_step4`] runs four elements of one
/// section through the same source, lane by lane.
#[allow(clippy::too_many_arguments)]
pub fn shell4_step(
    sec: &ShellSection,
    x: &[[f64; 3]; 4],
    v: &[[f64; 3]; 4],
    vr: &[[f64; 3]; 4],
    dt: f64,
    st: &mut Shell4State,
    sig: &mut [[f64; 5]],
    eps_p: &mut [f64],
    dmg: &mut [PointHistory],
) -> Shell4Out {
    let mut out = Shell4Out {
        dt: f64::INFINITY,
        ..Default::default()
    };
    if st.deleted {
        out.failed = true;
        return out;
    }
    let n_ip = sec.n_ip;
    let sig = &mut sig[..n_ip];
    let eps_p = &mut eps_p[..n_ip];
    let kc = &sec.k;

    // ---- geometry at x^{n+1} (forces) and x^{n+1/2} (rates) ------------------
    let Some(mut ge) = Geom::new(x) else {
        out.bad_area = true;
        return out;
    };
    let g_dt = st.geo0.as_ref().unwrap_or(&ge);
    out.dt = if sec.ishell == 24 && !st.tri {
        qeph::char_length(sec, g_dt) / kc.c
    } else {
        char_length(sec, g_dt, st.tri) / kc.c * sec.viscmx()
    };
    let mut gm = if dt > 0.0 {
        match Geom::new(&mid_step(x, v, dt)) {
            Some(g) => g,
            None => {
                out.bad_area = true;
                return out;
            }
        }
    } else {
        ge
    };
    if dot(gm.e[2], ge.e[2]) <= 0.0 {
        out.bad_area = true;
        return out;
    }
    if let Some(g0) = &st.geo0 {
        small_strain(&mut gm, g0);
        small_strain(&mut ge, g0);
    }
    // Hourglass vectors: orthogonal γ for Ishell 1, 3, 4, except under small
    // strain (Ismstr = 1), where the reference engine takes the plain Γ for
    // the membrane and flexural modes as for the rotational ones (its shell
    // hourglass routine switches the orthogonalisation off with Ismstr 1/11).
    let orth = sec.ishell != 2 && sec.ismstr != 1;
    let hourglass = !st.tri && sec.ishell != 24;
    let r = Rates::new(&gm, &ge, v, vr, dt, orth);
    let t = st.thick;
    let p = points(sec, st, sig, eps_p, dmg, &r, dt, gm.area, ge.area);
    out.d_eint = p.d_eint;
    out.d_eplas = p.d_eplas;
    if p.deleted {
        out.failed = true;
        return out;
    }

    // ---- hourglass -------------------------------------------------------------
    let mut h = [0.0; 5];
    if hourglass {
        let (hr, d_ehg) = if sec.ishell == 3 {
            hourglass_plastic(sec, &ge, t, &r, &mut st.hourglass, &p.law, eps_p, dt)
        } else {
            let (hr, new, d_ehg) = hourglass_visco(sec, &ge, t, &r, st.hourglass, dt);
            st.hourglass = new;
            (hr, d_ehg)
        };
        h = hr;
        out.d_ehg = d_ehg;
        st.ehg += d_ehg;
    }
    (out.f, out.m) = corner_forces(&ge, orth, p.nr, p.mr, p.q, h);

    if sec.ishell == 24 && !st.tri {
        let [e1, e2, e3] = ge.e;
        let pl = qeph::plastic_state(sec, &p.law, &p.ep0[..n_ip], eps_p);
        let (nb, mb) = (scale(p.nr, 1.0 / t), scale(p.mr, 1.0 / (t * t)));
        let q = qeph::step(sec, &gm, &ge, v, vr, dt, t, &mut st.qeph, pl, nb, mb);
        for i in 0..4 {
            let (f, m) = (q.f[i], q.m[i]);
            let fg = comb3(f[0], e1, f[1], e2, f[2], e3);
            let mg = comb3(m[0], e1, m[1], e2, 0.0, e3);
            for k in 0..3 {
                out.f[i][k] += fg[k];
                out.m[i][k] += mg[k];
            }
        }
        (out.d_eint, out.d_ehg) = (out.d_eint + q.d_eint, q.d_ehg);
        st.eint += q.d_eint;
        st.ehg += q.d_ehg;
    }

    // ---- thickness ---------------------------------------------------------------
    if sec.ithick == 1 && dt > 0.0 {
        st.thick = t * (1.0 + p.dezz);
    }
    out
}

/// The mid-step corners x^{n+½} = x^{n+1} − ½Δt v^{n+½}.
#[inline(always)]
fn mid_step<R: Real>(x: &[[R; 3]; 4], v: &[[R; 3]; 4], dt: f64) -> [[R; 3]; 4] {
    let h = R::splat(0.5 * dt);
    let mut m = *x;
    for (mi, vi) in m.iter_mut().zip(v) {
        for k in 0..3 {
            mi[k] = mi[k] - h * vi[k];
        }
    }
    m
}

#[path = "shell4_qeph.rs"]
mod qeph;

#[path = "shell4_batch.rs"]
mod batch;
pub use batch::shell4_step4;

#[cfg(test)]
#[path = "shell4_tests.rs"]
mod tests;
