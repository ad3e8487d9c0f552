//! /FUNCT evaluation: piecewise linear through the points, extrapolated
//! linearly from the first and last segments (as Radioss does).

use crate::model::Function;

/// y(x) of a /FUNCT.
pub fn eval(f: &Function, x: f64) -> f64 {
    let n = f.x.len();
    if n == 1 {
        return f.y[0];
    }
    // Segment index: the last i with x_i <= x, clamped to [0, n-2] (extrapolation).
    let i = match f.x.partition_point(|&xi| xi <= x) {
        0 => 0,
        k => (k - 1).min(n - 2),
    };
    let (x0, x1, y0, y1) = (f.x[i], f.x[i + 1], f.y[i], f.y[i + 1]);
    y0 + (y1 - y0) * (x - x0) / (x1 - x0)
}

/// dy/dx of a /FUNCT at x: the slope of the segment `eval` interpolates
/// on (the first or last one beyond the ends; 0 for a single point).
pub fn slope(f: &Function, x: f64) -> f64 {
    let n = f.x.len();
    if n < 2 {
        return 0.0;
    }
    let i = match f.x.partition_point(|&xi| xi <= x) {
        0 => 0,
        k => (k - 1).min(n - 2),
    };
    (f.y[i + 1] - f.y[i]) / (f.x[i + 1] - f.x[i])
}

/// Fscale·f(x/Ascale) and its slope in x, Fscale/Ascale·f′(x/Ascale).
pub fn scaled_with_slope(f: &Function, x: f64, ascale_x: f64, fscale_y: f64) -> (f64, f64) {
    let u = x / ascale_x;
    (fscale_y * eval(f, u), fscale_y / ascale_x * slope(f, u))
}

/// Fscale · f(t / Ascale), the value of a load or imposed motion at time t.
pub fn scaled(f: &Function, t: f64, ascale_x: f64, fscale_y: f64) -> f64 {
    fscale_y * eval(f, t / ascale_x)
}

/// The value of an /IMPVEL or /IMPDISP at time t, or `None` outside [Tstart, Tstop].
pub fn imposed_value(f: &Function, card: &crate::model::ImposedMotionSpec, t: f64) -> Option<f64> {
    (t >= card.tstart && t <= card.tstop).then(|| scaled(f, t, card.ascale_x, card.fscale_y))
}

/// The displacement an /IMPDISP imposes at the end of the step from t to
/// t + Δt: Fscale·f((t + Δt)/Ascale) when t lies in [Tstart, Tstop] (the
/// reference engine tests the window at the step's start, so the step that
/// crosses Tstop still ends on the curve, extrapolated past its last point
/// as `eval` does), `None` otherwise.
pub fn imposed_displacement(
    f: &Function,
    card: &crate::model::ImposedMotionSpec,
    t: f64,
    dt: f64,
) -> Option<f64> {
    (t >= card.tstart && t <= card.tstop).then(|| scaled(f, t + dt, card.ascale_x, card.fscale_y))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn f() -> Function {
        Function {
            id: 1,
            title: String::new(),
            x: vec![0.0, 1.0, 3.0],
            y: vec![0.0, 10.0, 20.0],
            loc: Default::default(),
        }
    }

    #[test]
    fn interpolates_and_extrapolates() {
        let f = f();
        assert_eq!(eval(&f, 0.5), 5.0);
        assert_eq!(eval(&f, 2.0), 15.0);
        assert_eq!(eval(&f, 5.0), 30.0);
        assert_eq!(eval(&f, -1.0), -10.0);
        assert_eq!(scaled(&f, 1.0, 2.0, 3.0), 15.0);
    }
}
