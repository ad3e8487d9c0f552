//! Axial spring (Radioss /SPRING with /PROP/TYPE4, /PROP/SPRING): one
//! translational degree of freedom along the line of its two nodes.
//!
//! # Formulation (reference guide /PROP/TYPE4; user guide "Stiffness
//! Formulation", Force and Moment, eq. 1)
//! * Elongation δ = l − l₀ (l = |x₂ − x₁|, l₀ the initial length given by the
//!   solver), rate δ̇ = (v₂ − v₁)·n with n = (x₂ − x₁)/l. With Ileng = 1 the input
//!   is per unit length: δ and δ̇ are replaced by δ/l₀ and δ̇/l₀ (forces are not
//!   scaled).
//! * fct_ID1 = 0: linear spring and dashpot F = K δ + C δ̇.
//! * fct_ID1 ≠ 0, H = 0 (non-linear elastic):
//!   F = f(δ/Ascale)·[A + B ln(max(1, |δ̇/D|))] + C δ̇,
//!   f the /FUNCT (force versus elongation, linear interpolation and
//!   extrapolation). The E·g(δ̇/F) and Hscale·h(δ̇/F) terms need fct_ID2/fct_ID3,
//!   which [`spring_check`] refuses, as it refuses H ≠ 0 (elasto-plastic and
//!   hysteretic unloading).
//! * Failure: when δ (δ/l₀ with Ileng = 1) leaves [δ_min, δ_max] (a 0 bound is
//!   "none") the spring breaks and carries no force from then on.
//! * Internal forces (the solver does M a = f_ext − f): f₁ = −F n, f₂ = +F n;
//!   a stretched spring (F > 0) pulls its nodes together.
//! * Energy: d_eint = ½(F^n + F^{n+1})(l^{n+1} − l^n) (trapezoidal, includes the
//!   damper's work).
//! * Stability data for the solver's nodal time step: `k_eff` (K, or for a
//!   function the largest segment slope times the current rate factor, whichever
//!   is larger, divided by Ascale; /l₀ with Ileng = 1) and `c_eff` (C, /l₀ with
//!   Ileng = 1). For a node of mass m: Δt = √(2m/k_eff) without damping; with
//!   damping the central-difference bound Δt = (2/ω)(√(1 + ξ²) − ξ),
//!   ω² = 2k_eff/m, ξ = c_eff/√(2 k_eff m) applies.
//! * A zero-length spring (coincident nodes) keeps the last direction it had;
//!   before it ever had one it takes the direction of the relative velocity.
//!
//! No heap allocation.

use crate::kinematics::function::eval;
use crate::model::{Function, SpringProperty};
use serde::{Deserialize, Serialize};

/// Per-spring state kept by the solver.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct SpringState {
    /// Axial force F (positive in tension).
    pub force: f64,
    /// Length at the last step.
    pub len: f64,
    /// Last unit direction x₂ − x₁ (zero while undefined).
    pub dir: [f64; 3],
    /// Cumulative internal energy.
    pub eint: f64,
    /// The spring broke (δ left [δ_min, δ_max]).
    pub broken: bool,
}

/// What one spring step returns.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SpringOut {
    /// Internal nodal forces; the solver subtracts them.
    pub f: [[f64; 3]; 2],
    /// Axial force F (positive in tension).
    pub force: f64,
    /// Stiffness for the nodal time step √(2m/k).
    pub k_eff: f64,
    /// Damping coefficient for the nodal time step (see the module doc).
    pub c_eff: f64,
    /// Internal energy increment.
    pub d_eint: f64,
    /// The spring broke during this step (or earlier).
    pub failed: bool,
}

/// What the engine cannot compute for this spring property, by name.
/// `f1` is the resolved fct_ID1 function (None when fct_ID1 = 0 or missing).
pub fn spring_check(p: &SpringProperty, f1: Option<&Function>) -> Result<(), String> {
    if p.h != 0 {
        return Err(format!(
            "H = {}: only non-linear elastic springs (H = 0) are supported, not elasto-plastic or hysteretic unloading",
            p.h
        ));
    }
    if p.fct_id2 != 0 {
        return Err(format!(
            "fct_ID2 = {}: the velocity function g (E·g(δ̇/F) term) is not supported",
            p.fct_id2
        ));
    }
    if p.fct_id3 != 0 {
        return Err(format!(
            "fct_ID3 = {}: the velocity function h (Hscale·h(δ̇/F) term) is not supported",
            p.fct_id3
        ));
    }
    if p.fct_id1 != 0 && f1.is_none() {
        return Err(format!("fct_ID1 = {}: function not found", p.fct_id1));
    }
    if !(0..=1).contains(&p.ileng) {
        return Err(format!("Ileng = {}: expected 0 or 1", p.ileng));
    }
    if p.fct_id1 != 0 && p.b != 0.0 && p.d <= 0.0 {
        return Err(format!(
            "D = {}: the rate scale must be > 0 when B ≠ 0",
            p.d
        ));
    }
    Ok(())
}

/// State at t = 0 (no force).
pub fn spring_init(x: &[[f64; 3]; 2]) -> SpringState {
    let d = [x[1][0] - x[0][0], x[1][1] - x[0][1], x[1][2] - x[0][2]];
    let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    SpringState {
        len: l,
        dir: if l > 0.0 {
            [d[0] / l, d[1] / l, d[2] / l]
        } else {
            [0.0; 3]
        },
        ..Default::default()
    }
}

/// Largest |slope| of a function's segments (0 for a single point).
fn max_slope(f: &Function) -> f64 {
    let mut s: f64 = 0.0;
    for i in 1..f.x.len() {
        s = s.max(((f.y[i] - f.y[i - 1]) / (f.x[i] - f.x[i - 1])).abs());
    }
    s
}

/// One explicit step of one spring from x^{n+1}, v^{n+½} (see the module doc).
/// `f1`: the fct_ID1 function (ignored when fct_ID1 = 0); `l0`: initial length.
pub fn spring_step(
    p: &SpringProperty,
    f1: Option<&Function>,
    x: &[[f64; 3]; 2],
    v: &[[f64; 3]; 2],
    l0: f64,
    dt: f64,
    st: &mut SpringState,
) -> SpringOut {
    let _ = dt;
    let mut out = SpringOut::default();
    let d = [x[1][0] - x[0][0], x[1][1] - x[0][1], x[1][2] - x[0][2]];
    let dv = [v[1][0] - v[0][0], v[1][1] - v[0][1], v[1][2] - v[0][2]];
    let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    let tiny = 1e-12 * l0.max(st.len);
    if l > tiny && l > 0.0 {
        st.dir = [d[0] / l, d[1] / l, d[2] / l];
    } else if st.dir == [0.0; 3] {
        let s = (dv[0] * dv[0] + dv[1] * dv[1] + dv[2] * dv[2]).sqrt();
        if s > 0.0 {
            st.dir = [dv[0] / s, dv[1] / s, dv[2] / s];
        }
    }
    let n = st.dir;
    let scale = if p.ileng == 1 {
        if l0 > 0.0 {
            1.0 / l0
        } else {
            0.0
        }
    } else {
        1.0
    };
    let delta = (l - l0) * scale;
    let rate = (dv[0] * n[0] + dv[1] * n[1] + dv[2] * n[2]) * scale;
    out.c_eff = p.c * scale;

    let broken_now =
        (p.delta_max > 0.0 && delta > p.delta_max) || (p.delta_min < 0.0 && delta < p.delta_min);
    if st.broken || broken_now || (p.ileng == 1 && l0 <= 0.0) {
        st.broken = st.broken || broken_now;
        let dl = l - st.len;
        out.d_eint = 0.5 * st.force * dl;
        st.eint += out.d_eint;
        st.force = 0.0;
        st.len = l;
        out.failed = st.broken;
        return out;
    }

    let (force, k_eff) = match f1 {
        Some(f) if p.fct_id1 != 0 => {
            let rf = p.a
                + if p.b != 0.0 {
                    p.b * (rate / p.d).abs().max(1.0).ln()
                } else {
                    0.0
                };
            let fv = eval(f, delta / p.ascale) * rf;
            let k = (max_slope(f) * rf.abs() / p.ascale).max(p.k);
            (fv + p.c * rate, k * scale)
        }
        _ => (p.k * delta + p.c * rate, p.k * scale),
    };
    out.k_eff = k_eff;
    out.force = force;
    out.f = [
        [-force * n[0], -force * n[1], -force * n[2]],
        [force * n[0], force * n[1], force * n[2]],
    ];
    out.d_eint = 0.5 * (st.force + force) * (l - st.len);
    st.eint += out.d_eint;
    st.force = force;
    st.len = l;
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Loc;

    fn prop(k: f64, c: f64) -> SpringProperty {
        SpringProperty {
            mass: 0.0,
            sens_id: 0,
            isflag: 0,
            ileng: 0,
            k,
            c,
            a: 1.0,
            b: 0.0,
            d: 1.0,
            fct_id1: 0,
            h: 0,
            fct_id2: 0,
            fct_id3: 0,
            delta_min: 0.0,
            delta_max: 0.0,
            fscale: 1.0,
            e: 0.0,
            ascale: 1.0,
        }
    }

    fn func(x: Vec<f64>, y: Vec<f64>) -> Function {
        Function {
            id: 7,
            title: String::new(),
            x,
            y,
            loc: Loc::default(),
        }
    }

    /// Spring along (1, 2, 2)/3 from the origin, stretched to length l.
    fn geom(l: f64) -> ([[f64; 3]; 2], [f64; 3]) {
        let n = [1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0];
        ([[0.0; 3], [l * n[0], l * n[1], l * n[2]]], n)
    }

    #[test]
    fn linear_spring_force_and_energy() {
        let p = prop(100.0, 0.0);
        let l0 = 2.0;
        let (x0, n) = geom(l0);
        let mut st = spring_init(&x0);
        // Stretch quasi-statically to δ = 0.3 in 300 steps.
        let dt = 1e-3;
        let vel = 1.0; // δ̇
        let mut o = SpringOut::default();
        for i in 1..=300 {
            let (x, _) = geom(l0 + vel * dt * i as f64);
            let v = [[0.0; 3], [vel * n[0], vel * n[1], vel * n[2]]];
            o = spring_step(&p, None, &x, &v, l0, dt, &mut st);
        }
        let delta = 0.3;
        assert!((o.force - 100.0 * delta).abs() < 1e-9);
        for k in 0..3 {
            assert!((o.f[1][k] - 100.0 * delta * n[k]).abs() < 1e-9);
            assert!((o.f[0][k] + o.f[1][k]).abs() < 1e-15);
        }
        // ½ K δ², exact for the trapezoidal rule on a linear law.
        assert!(
            (st.eint - 0.5 * 100.0 * delta * delta).abs() < 1e-9,
            "{}",
            st.eint
        );
        assert_eq!(o.k_eff, 100.0);
        // Compression pushes the nodes apart: internal force on node 2 along −n.
        let (x, _) = geom(l0 - 0.1);
        let o = spring_step(&p, None, &x, &[[0.0; 3]; 2], l0, dt, &mut st);
        assert!((o.force + 10.0).abs() < 1e-12 && o.f[1][0] < 0.0);
    }

    #[test]
    fn damping_force_and_dissipation() {
        let p = prop(0.0, 5.0);
        let l0 = 1.0;
        let (x0, n) = geom(l0);
        let mut st = spring_init(&x0);
        let vel = -2.0;
        let dt = 1e-3;
        let v = [
            [0.3 * n[0], 0.3 * n[1], 0.3 * n[2]],
            [(0.3 + vel) * n[0], (0.3 + vel) * n[1], (0.3 + vel) * n[2]],
        ];
        let mut e = 0.0;
        for i in 1..=10 {
            let (x, _) = geom(l0 + vel * dt * i as f64);
            let o = spring_step(&p, None, &x, &v, l0, dt, &mut st);
            assert!((o.force - 5.0 * vel).abs() < 1e-12, "{}", o.force);
            assert_eq!(o.c_eff, 5.0);
            e += o.d_eint;
        }
        // Power C δ̇² > 0 (first step ramps up from F = 0).
        assert!(e > 0.0);
        assert!((e - 5.0 * vel * vel * 10.0 * dt).abs() < 0.06 * e);
        // A transverse velocity produces no axial force.
        let mut st = spring_init(&x0);
        let vt = [[0.0; 3], [2.0, -1.0, 0.0]]; // (2,−1,0)·(1,2,2) = 0
        let o = spring_step(&p, None, &x0, &vt, l0, dt, &mut st);
        assert!(o.force.abs() < 1e-15);
    }

    #[test]
    fn function_defined_force() {
        let mut p = prop(10.0, 0.0);
        p.fct_id1 = 7;
        p.a = 2.0;
        p.ascale = 0.5;
        let f = func(vec![-1.0, 0.0, 1.0, 2.0], vec![-50.0, 0.0, 10.0, 40.0]);
        spring_check(&p, Some(&f)).unwrap();
        let l0 = 1.0;
        let (x0, _) = geom(l0);
        let mut st = spring_init(&x0);
        // δ = 0.75 → f(δ/Ascale = 1.5) = 25, F = A·25 = 50.
        let (x, n) = geom(l0 + 0.75);
        let o = spring_step(&p, Some(&f), &x, &[[0.0; 3]; 2], l0, 1e-3, &mut st);
        assert!((o.force - 50.0).abs() < 1e-12, "{}", o.force);
        assert!((o.f[1][1] - 50.0 * n[1]).abs() < 1e-12);
        // Largest slope 50/1 × A / Ascale = 200 (> K).
        assert!((o.k_eff - 200.0).abs() < 1e-12);
        // Log rate effect: B ln(|δ̇|/D) with δ̇ = e·D → factor A + B.
        p.b = 1.0;
        p.d = 0.1;
        let vel = 0.1 * std::f64::consts::E;
        let v = [[0.0; 3], [vel * n[0], vel * n[1], vel * n[2]]];
        let o = spring_step(&p, Some(&f), &x, &v, l0, 1e-3, &mut st);
        assert!((o.force - 25.0 * 3.0).abs() < 1e-9, "{}", o.force);
        // Ileng = 1: per unit length, δ/l₀ with l₀ = 2.
        let mut p = prop(10.0, 0.0);
        p.ileng = 1;
        let (x0, _) = geom(2.0);
        let mut st = spring_init(&x0);
        let (x, _) = geom(2.5);
        let o = spring_step(&p, None, &x, &[[0.0; 3]; 2], 2.0, 1e-3, &mut st);
        assert!((o.force - 10.0 * 0.25).abs() < 1e-12);
        assert!((o.k_eff - 5.0).abs() < 1e-12);
    }

    #[test]
    fn failure_and_check() {
        let mut p = prop(100.0, 0.0);
        p.delta_max = 0.2;
        let (x0, _) = geom(1.0);
        let mut st = spring_init(&x0);
        let (x, _) = geom(1.1);
        assert!(!spring_step(&p, None, &x, &[[0.0; 3]; 2], 1.0, 1e-3, &mut st).failed);
        let (x, _) = geom(1.3);
        let o = spring_step(&p, None, &x, &[[0.0; 3]; 2], 1.0, 1e-3, &mut st);
        assert!(o.failed && o.force == 0.0 && o.f == [[0.0; 3]; 2]);
        let (x, _) = geom(1.1);
        assert!(spring_step(&p, None, &x, &[[0.0; 3]; 2], 1.0, 1e-3, &mut st).failed);

        let mut p = prop(1.0, 0.0);
        p.h = 4;
        assert!(spring_check(&p, None).unwrap_err().contains("H = 4"));
        let mut p = prop(1.0, 0.0);
        p.fct_id2 = 3;
        assert!(spring_check(&p, None).unwrap_err().contains("fct_ID2 = 3"));
        let mut p = prop(1.0, 0.0);
        p.fct_id1 = 9;
        assert!(spring_check(&p, None).unwrap_err().contains("fct_ID1 = 9"));
    }

    #[test]
    fn zero_length_spring_uses_the_relative_velocity() {
        let p = prop(100.0, 1.0);
        let x = [[1.0, 1.0, 1.0]; 2];
        let mut st = spring_init(&x);
        let v = [[0.0; 3], [0.0, 0.0, 2.0]];
        let o = spring_step(&p, None, &x, &v, 0.0, 1e-3, &mut st);
        assert_eq!(o.f[1], [0.0, 0.0, 2.0]);
        assert_eq!(st.dir, [0.0, 0.0, 1.0]);
    }
}
