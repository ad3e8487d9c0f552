//! Arithmetic on one element or on four side by side.
//!
//! Kernels written over [`Real`] compile twice: for `f64` (one element) and
//! for [`F4`] (four elements of one section, each lane one element). Every
//! operation of `F4` is the `f64` operation applied lane by lane, in the same
//! order the generic source gives, and Rust never fuses a multiply and an add
//! on its own: a lane's result is bitwise the one element's result. A batch
//! therefore changes the speed and never the answer, whichever elements a
//! rank's partition happens to put side by side.
//!
//! `F4` wraps `wide::f64x4` (already in the tree through nalgebra): its
//! `+ − × ÷` and `sqrt` are one AVX instruction each where the build targets
//! AVX (`.cargo/config.toml`), two SSE2 halves otherwise, all IEEE-rounded
//! lane by lane like the scalar operations. `std::simd` would say the same but
//! is not stable; a plain `[f64; 4]` left the vectorising to the compiler,
//! which kept most of the kernel in scalar and 2-wide registers. Negation
//! and `abs` work on the sign bit, as they do on an f64; `min`/`max` go lane
//! by lane through `f64::min`/`max` (their NaN rule is not the instruction's).

use std::ops::{Add, Div, Mul, Neg, Sub};
use wide::f64x4;

/// The arithmetic a kernel written once for one element or four needs.
pub trait Real:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// How many elements one value carries.
    const LANES: usize;
    /// The same value in every lane.
    fn splat(v: f64) -> Self;
    /// Lane `i`.
    fn lane(self, i: usize) -> f64;
    /// A value built lane by lane.
    fn from_fn(f: impl FnMut(usize) -> f64) -> Self;
    fn sqrt(self) -> Self;
    fn abs(self) -> Self;
    /// `f64::min` lane by lane.
    fn min(self, o: Self) -> Self;
    /// `f64::max` lane by lane.
    fn max(self, o: Self) -> Self;
    /// Whether `ok` holds in every lane.
    #[inline(always)]
    fn all(self, ok: impl Fn(f64) -> bool) -> bool {
        (0..Self::LANES).all(|i| ok(self.lane(i)))
    }
}

impl Real for f64 {
    const LANES: usize = 1;
    #[inline(always)]
    fn splat(v: f64) -> f64 {
        v
    }
    #[inline(always)]
    fn lane(self, _: usize) -> f64 {
        self
    }
    #[inline(always)]
    fn from_fn(mut f: impl FnMut(usize) -> f64) -> f64 {
        f(0)
    }
    #[inline(always)]
    fn sqrt(self) -> f64 {
        f64::sqrt(self)
    }
    #[inline(always)]
    fn abs(self) -> f64 {
        f64::abs(self)
    }
    #[inline(always)]
    fn min(self, o: f64) -> f64 {
        f64::min(self, o)
    }
    #[inline(always)]
    fn max(self, o: f64) -> f64 {
        f64::max(self, o)
    }
}

/// Four elements' values, one per lane.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct F4(f64x4);

impl F4 {
    #[inline(always)]
    pub fn new(a: [f64; 4]) -> F4 {
        F4(f64x4::new(a))
    }
    #[inline(always)]
    pub fn to_array(self) -> [f64; 4] {
        self.0.to_array()
    }
}

macro_rules! lane_op {
    ($tr:ident, $f:ident) => {
        impl $tr for F4 {
            type Output = F4;
            #[inline(always)]
            fn $f(self, o: F4) -> F4 {
                F4($tr::$f(self.0, o.0))
            }
        }
    };
}
lane_op!(Add, add);
lane_op!(Sub, sub);
lane_op!(Mul, mul);
lane_op!(Div, div);

impl Neg for F4 {
    type Output = F4;
    /// The sign bit flipped, as `-x` does to an f64 (zeros and NaNs included).
    #[inline(always)]
    fn neg(self) -> F4 {
        F4(self.0 ^ f64x4::splat(-0.0))
    }
}

impl Real for F4 {
    const LANES: usize = 4;
    #[inline(always)]
    fn splat(v: f64) -> F4 {
        F4(f64x4::splat(v))
    }
    #[inline(always)]
    fn lane(self, i: usize) -> f64 {
        self.0.as_array_ref()[i]
    }
    #[inline(always)]
    fn from_fn(mut f: impl FnMut(usize) -> f64) -> F4 {
        F4::new([f(0), f(1), f(2), f(3)])
    }
    #[inline(always)]
    fn sqrt(self) -> F4 {
        F4(self.0.sqrt())
    }
    #[inline(always)]
    fn abs(self) -> F4 {
        // The sign bit cleared, as f64::abs.
        F4(self.0 & f64x4::splat(f64::from_bits(!(1u64 << 63))))
    }
    #[inline(always)]
    fn min(self, o: F4) -> F4 {
        let (a, b) = (self.to_array(), o.to_array());
        F4::new([
            a[0].min(b[0]),
            a[1].min(b[1]),
            a[2].min(b[2]),
            a[3].min(b[3]),
        ])
    }
    #[inline(always)]
    fn max(self, o: F4) -> F4 {
        let (a, b) = (self.to_array(), o.to_array());
        F4::new([
            a[0].max(b[0]),
            a[1].max(b[1]),
            a[2].max(b[2]),
            a[3].max(b[3]),
        ])
    }
}

/// a·b for 3-vectors, summed x + y + z (as `vec3::dot`).
#[inline(always)]
pub fn dot<R: Real>(a: [R; 3], b: [R; 3]) -> R {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// a × b (as `vec3::cross`).
#[inline(always)]
pub fn cross<R: Real>(a: [R; 3], b: [R; 3]) -> [R; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// a − b.
#[inline(always)]
pub fn sub<R: Real>(a: [R; 3], b: [R; 3]) -> [R; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// a·s.
#[inline(always)]
pub fn scale<R: Real>(a: [R; 3], s: R) -> [R; 3] {
    [a[0] * s, a[1] * s, a[2] * s]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every operator of F4 is the f64 operator lane by lane, special values included.
    #[test]
    fn lanes_are_the_scalar_operations() {
        let a = F4::new([1.5, -0.0, f64::INFINITY, 3.0e-310]);
        let b = F4::new([-2.25, 0.0, 7.0, f64::NAN]);
        fn bits(x: F4) -> [u64; 4] {
            x.to_array().map(f64::to_bits)
        }
        fn each(a: F4, b: F4, f: fn(f64, f64) -> f64) -> F4 {
            let (a, b) = (a.to_array(), b.to_array());
            F4::new([f(a[0], b[0]), f(a[1], b[1]), f(a[2], b[2]), f(a[3], b[3])])
        }
        assert_eq!(bits(a + b), bits(each(a, b, |x, y| x + y)));
        assert_eq!(bits(a - b), bits(each(a, b, |x, y| x - y)));
        assert_eq!(bits(a * b), bits(each(a, b, |x, y| x * y)));
        assert_eq!(bits(a / b), bits(each(a, b, |x, y| x / y)));
        assert_eq!(bits(Real::min(a, b)), bits(each(a, b, f64::min)));
        assert_eq!(bits(Real::max(a, b)), bits(each(a, b, f64::max)));
        assert_eq!(bits(-a), a.to_array().map(|x| (-x).to_bits()));
        assert_eq!(bits(-b), b.to_array().map(|x| (-x).to_bits()));
        assert_eq!(
            bits(Real::sqrt(a)),
            a.to_array().map(|x| x.sqrt().to_bits())
        );
        assert_eq!(bits(Real::abs(b)), b.to_array().map(|x| x.abs().to_bits()));
        assert_eq!(bits(Real::abs(a)), a.to_array().map(|x| x.abs().to_bits()));
        assert!(F4::splat(1.0).all(|x| x > 0.0));
        assert!(!a.all(|x| x > 0.0));
    }
}
