//! The force law of one spring degree of freedom, shared by /PROP/TYPE4,
//! TYPE8 and TYPE13 (reference guide /PROP/TYPE4 "H"; user guide "Spring
//! Hardening"; research note `docs/notes/springs_research.md` §1.3):
//!
//! F = [A + B·ln(max(1, |δ̇/D|)) + E·g(δ̇/F)]·F_s + C·δ̇ + Hscale·h(δ̇/F)
//!
//! with F_s the static force of the hardening flag H on the curves f1
//! (loading, fct_ID1) and f3 (unloading, lower yield or residual
//! displacement, fct_ID3) at x = δ/Ascale. The elastic slope K is raised to
//! A·max slope(f1)/Ascale (the reference Starter's rule); the static law
//! runs with K/A since the rate factor multiplies F_s.

use crate::kinematics::function::eval;
use crate::model::{Function, Id, SpringDof};
use serde::{Deserialize, Serialize};

/// What one degree of freedom keeps between steps.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct DofState {
    /// Displacement (or rotation) at the last step.
    pub delta: f64,
    /// Static force F_s of the last step (before the rate terms).
    pub f_ep: f64,
    /// Total force of the last step.
    pub force: f64,
    /// Plastic offset (H 1, 2, 4, 7), largest displacement (H 5).
    pub dp: f64,
    /// Compression offset (H 2), smallest displacement (H 5).
    pub dp2: f64,
    /// Current yield force (H 6).
    pub yield_force: f64,
    /// Cumulated plastic displacement (H 6).
    pub x_plastic: f64,
}

/// One degree of freedom with its functions resolved.
#[derive(Clone, Debug)]
pub struct DofLaw {
    pub p: SpringDof,
    f1: Option<Function>,
    f2: Option<Function>,
    f3: Option<Function>,
    f4: Option<Function>,
    /// Raised stiffness K (the unloading slope times A).
    k: f64,
    /// Largest slope of h in δ̇ (for the time step).
    h_slope: f64,
}

/// Largest |slope| of a function's segments (0 for a single point).
pub fn max_slope(f: &Function) -> f64 {
    (1..f.x.len())
        .map(|i| ((f.y[i] - f.y[i - 1]) / (f.x[i] - f.x[i - 1])).abs())
        .fold(0.0, f64::max)
}

/// The slope of the segment of `f` whose ordinates hold `y` (the first or
/// last segment beyond the ends): the unloading slope of H = 6.
fn slope_at_ordinate(f: &Function, y: f64) -> f64 {
    let n = f.x.len();
    if n < 2 {
        return 0.0;
    }
    let i = (0..n - 1).find(|&i| y <= f.y[i + 1]).unwrap_or(n - 2);
    (f.y[i + 1] - f.y[i]) / (f.x[i + 1] - f.x[i])
}

impl DofLaw {
    /// The law of `p`; `find` looks a function up by id (None: not defined).
    pub fn new(p: &SpringDof, find: impl Fn(Id) -> Option<Function>) -> Result<Self, String> {
        let get = |id: Id, name: &str| -> Result<Option<Function>, String> {
            if id == 0 {
                return Ok(None);
            }
            find(id)
                .map(Some)
                .ok_or(format!("{name} = {id}: function not found"))
        };
        let f1 = get(p.fct_id1, "fct_ID1")?;
        let f4 = get(p.fct_id4, "fct_ID4")?;
        let k = match &f1 {
            Some(f) => p.k.max(p.a * max_slope(f) / p.ascale),
            None => p.k,
        };
        let h_slope = f4
            .as_ref()
            .map_or(0.0, |f| p.hscale * max_slope(f) / p.fscale);
        Ok(DofLaw {
            f1,
            f2: get(p.fct_id2, "fct_ID2")?,
            f3: get(p.fct_id3, "fct_ID3")?,
            f4,
            k,
            h_slope,
            p: p.clone(),
        })
    }

    /// The stiffness for the time step (K raised, times A).
    pub fn k_dt(&self) -> f64 {
        self.k
    }

    /// The damping for the time step: C plus the largest slope of h.
    pub fn c_dt(&self) -> f64 {
        self.p.c + self.h_slope
    }

    /// The rate factor A + B·ln(max(1, |δ̇/D|)) + E·g(δ̇/F).
    pub fn rate_factor(&self, rate: f64) -> f64 {
        let p = &self.p;
        let mut f = p.a;
        if p.b != 0.0 {
            f += p.b * (rate / p.d).abs().max(1.0).ln();
        }
        if let Some(g) = &self.f2 {
            f += p.e * eval(g, rate / p.fscale);
        }
        f
    }

    /// One step to displacement `delta` at rate `rate` (`length`: the
    /// current length, H = 8): the total force; `st` moves on.
    pub fn step(&self, st: &mut DofState, delta: f64, rate: f64, length: f64) -> f64 {
        let fs = self.static_force(st, delta, length);
        st.f_ep = fs;
        st.delta = delta;
        let p = &self.p;
        let h = self
            .f4
            .as_ref()
            .map_or(0.0, |h| p.hscale * eval(h, rate / p.fscale));
        let f = self.rate_factor(rate) * fs + p.c * rate + h;
        st.force = f;
        f
    }

    /// The static force F_s of the hardening flag (research note §1.3 step 1).
    fn static_force(&self, st: &mut DofState, delta: f64, length: f64) -> f64 {
        let k = self.k / self.p.a;
        let Some(f1) = &self.f1 else {
            return k * delta;
        };
        let x = delta / self.p.ascale;
        let f3 = self.f3.as_ref();
        if k <= 0.0 {
            return eval(f1, x);
        }
        match (self.p.h, f3) {
            (1, _) => isotropic(st, delta, k, |x| eval(f1, x / self.p.ascale)),
            (2, _) => uncoupled(st, delta, k, eval(f1, x)),
            (4, Some(f3)) => {
                let ft = st.f_ep + k * (delta - st.delta);
                let fs = ft.min(eval(f1, x)).max(eval(f3, x));
                st.dp = delta - fs / k;
                fs
            }
            (5, Some(f3)) => self.residual(st, delta, k, f1, f3),
            (6, Some(f3)) => isotropic_unloading(st, delta, f3, |x| eval(f1, x / self.p.ascale)),
            (7, Some(f3)) => {
                let ft = st.f_ep + k * (delta - st.delta);
                let (up, pos) = (delta >= st.delta, delta >= 0.0);
                let fs = match (up, pos) {
                    (true, true) => ft.min(eval(f1, x)),
                    (false, true) => ft.max(eval(f3, x)),
                    (true, false) => ft.min(eval(f3, x)),
                    (false, false) => ft.max(eval(f1, x)),
                };
                st.dp = delta - fs / k;
                fs
            }
            (8, _) => eval(f1, length / self.p.ascale),
            _ => eval(f1, x),
        }
    }

    /// H = 5: loading on f1, unloading on the power curve
    /// F = F_m((δ − δ_r)/(δ_m − δ_r))^b, b = K(δ_m − δ_r)/F_m, down to the
    /// residual displacement δ_r = f3(δ_m) (user guide "Spring Hardening").
    fn residual(&self, st: &mut DofState, delta: f64, k: f64, f1: &Function, f3: &Function) -> f64 {
        let a = self.p.ascale;
        if delta > st.dp || delta < st.dp2 {
            if delta > st.dp {
                st.dp = delta;
            } else {
                st.dp2 = delta;
            }
            return eval(f1, delta / a);
        }
        let ft = st.f_ep + k * (delta - st.delta);
        let (dm, s) = if delta > 0.0 {
            (st.dp, 1.0)
        } else if delta < 0.0 {
            (st.dp2, -1.0)
        } else {
            return 0.0;
        };
        // In the mirrored frame (s = −1 for compression) everything is positive.
        let fm = s * eval(f1, dm / a);
        let mut dr = (s * eval(f3, dm / a)).max(0.0);
        let (d, m) = (s * delta, s * dm);
        if d <= dr || fm <= 0.0 {
            return 0.0;
        }
        dr = dr.min(m - fm / k);
        let t = (d - dr) / (m - dr);
        let b = (m - dr) * k / fm;
        let lo = (fm * t.powf(b)).max(0.0);
        let hi = (fm * t).min(s * eval(f1, delta / a));
        s * (s * ft).max(lo).min(hi)
    }
}

/// H = 1: isotropic hardening; the yield force y(X) is f1 at the plastic
/// displacement plus the elastic one, in the direction of the force.
fn isotropic(st: &mut DofState, delta: f64, k: f64, f1: impl Fn(f64) -> f64) -> f64 {
    let ft = st.f_ep + k * (delta - st.delta);
    let xe = if ft >= 0.0 {
        st.dp + ft / k
    } else {
        -st.dp + ft / k
    };
    let y = f1(xe);
    if ft >= 0.0 && ft > y {
        st.dp += (ft - y) / k;
        y
    } else if ft < 0.0 && ft < y {
        st.dp += (y - ft) / k;
        y
    } else {
        ft
    }
}

/// H = 2: tension and compression yield apart; between the two plastic
/// offsets the spring carries nothing.
fn uncoupled(st: &mut DofState, delta: f64, k: f64, y: f64) -> f64 {
    if delta > st.dp {
        let fs = (k * (delta - st.dp)).min(y);
        st.dp = delta - fs / k;
        fs
    } else if delta < st.dp2 {
        let fs = (k * (delta - st.dp2)).max(y);
        st.dp2 = delta - fs / k;
        fs
    } else {
        0.0
    }
}

/// H = 6: isotropic hardening on f1 of the cumulated plastic displacement,
/// elastic unloading with the slope of f3 at the current force.
fn isotropic_unloading(
    st: &mut DofState,
    delta: f64,
    f3: &Function,
    f1: impl Fn(f64) -> f64,
) -> f64 {
    let dd = delta - st.delta;
    let k3 = slope_at_ordinate(f3, st.f_ep);
    let ft = st.f_ep + k3 * dd;
    let x = if ft >= 0.0 {
        st.x_plastic
    } else {
        -st.x_plastic
    } + dd;
    let y = f1(x);
    if (ft >= 0.0 && ft > st.yield_force) || (ft < 0.0 && ft < -st.yield_force) {
        if k3 > 0.0 {
            st.dp += (ft - y) / k3;
        }
        st.yield_force = y.abs();
        st.x_plastic += dd.abs();
        y
    } else {
        ft
    }
}

#[cfg(test)]
#[path = "spring_law_tests.rs"]
mod tests;
