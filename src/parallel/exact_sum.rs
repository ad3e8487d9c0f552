//! Sums that do not depend on the order of their terms: the same bits for
//! any partition into ranks and any thread count.
//!
//! A floating-point sum depends on its order; the energies and the time
//! histories sum over elements and nodes that the partition spreads over
//! the ranks. [`ExactSum`] holds its sum as a fixed-point integer of 32-bit
//! limbs (a "long accumulator", as in Kulisch's exact dot product and the
//! ExBLAS reproducible sums): each term is split exactly into limbs, limbs
//! add as integers (associative), and the result is rounded to an f64 once,
//! at the end. Terms are exact from 2^-320 up to 2^320 (each below 2^-320
//! is cut off the same way wherever it is added; one above 2^320 makes the
//! sum infinite, as a NaN makes it NaN).

/// Limbs of 32 bits from 2^LOW on.
const LIMBS: usize = 21;
const LOW: i32 = -320;
/// Carries are propagated after this many additions (each adds less than
/// 2^32 to a limb, which holds an i64).
const RENORMALISE_EVERY: u32 = 1 << 30;

/// An order-independent sum of f64 terms.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ExactSum {
    limbs: [i64; LIMBS],
    adds: u32,
    /// NaN or ±infinity terms (as bits of their f64 sum: NaN, +inf, −inf).
    special: u64,
}

impl Default for ExactSum {
    fn default() -> Self {
        ExactSum {
            limbs: [0; LIMBS],
            adds: 0,
            special: 0f64.to_bits(),
        }
    }
}

impl ExactSum {
    /// Adds one term.
    pub fn add(&mut self, x: f64) {
        if x == 0.0 {
            return;
        }
        if !x.is_finite() || x.abs() >= 2f64.powi(LOW + 32 * LIMBS as i32 - 40) {
            let big = if x.is_nan() {
                f64::NAN
            } else {
                x.signum() * f64::INFINITY
            };
            self.special = (f64::from_bits(self.special) + big).to_bits();
            return;
        }
        let bits = x.abs().to_bits();
        let exp = ((bits >> 52) & 0x7ff) as i32;
        let (mant, e) = if exp == 0 {
            (bits & ((1 << 52) - 1), -1074)
        } else {
            ((bits & ((1 << 52) - 1)) | (1 << 52), exp - 1075)
        };
        // |x| = mant · 2^e; its bit k sits at position e + k − LOW.
        let shift = e - LOW;
        let (mant, shift) = if shift < 0 {
            if shift <= -64 {
                return;
            }
            (mant >> (-shift), 0)
        } else {
            (mant, shift)
        };
        let sign = if x < 0.0 { -1 } else { 1 };
        let (limb, bit) = ((shift / 32) as usize, shift % 32);
        let wide = (mant as u128) << bit;
        for j in 0..3 {
            let part = ((wide >> (32 * j)) & 0xffff_ffff) as i64;
            if part != 0 {
                self.limbs[limb + j] += sign * part;
            }
        }
        self.adds += 1;
        if self.adds >= RENORMALISE_EVERY {
            self.renormalise();
        }
    }

    /// Adds another sum's terms.
    pub fn merge(&mut self, other: &ExactSum) {
        self.renormalise();
        let mut o = *other;
        o.renormalise();
        for (a, b) in self.limbs.iter_mut().zip(&o.limbs) {
            *a += b;
        }
        self.special = (f64::from_bits(self.special) + f64::from_bits(o.special)).to_bits();
        self.renormalise();
    }

    /// Carries: every limb but the last in [0, 2^32).
    fn renormalise(&mut self) {
        for i in 0..LIMBS - 1 {
            let carry = self.limbs[i] >> 32;
            self.limbs[i] -= carry << 32;
            self.limbs[i + 1] += carry;
        }
        self.adds = 0;
    }

    /// The sum, rounded once (the same bits for the same terms in any order).
    pub fn value(&self) -> f64 {
        let special = f64::from_bits(self.special);
        if special != 0.0 {
            // ±infinity or NaN (NaN != 0.0 too).
            return special;
        }
        let mut s = *self;
        s.renormalise();
        // From the top limb down: each step adds a limb far below the
        // running sum's rounding unit once the sum has its leading bits.
        let mut v = 0.0f64;
        for i in (0..LIMBS).rev() {
            if s.limbs[i] != 0 {
                v += s.limbs[i] as f64 * 2f64.powi(LOW + 32 * i as i32);
            }
        }
        v
    }

    /// The state as words (for the ranks' exchange).
    pub fn to_words(&self) -> [u64; LIMBS + 1] {
        let mut s = *self;
        s.renormalise();
        let mut w = [0u64; LIMBS + 1];
        for (o, l) in w.iter_mut().zip(&s.limbs) {
            *o = *l as u64;
        }
        w[LIMBS] = s.special;
        w
    }

    pub fn from_words(w: &[u64]) -> ExactSum {
        let mut s = ExactSum::default();
        for (l, o) in s.limbs.iter_mut().zip(w) {
            *l = *o as i64;
        }
        s.special = w[LIMBS];
        s
    }

    /// Words per sum in [`to_words`](Self::to_words).
    pub const WORDS: usize = LIMBS + 1;

    /// An exact sum of one term.
    pub fn of(x: f64) -> ExactSum {
        let mut s = ExactSum::default();
        s.add(x);
        s
    }
}

/// Sums over the ranks, entry by entry: the same bits on every rank and
/// for any number of ranks (collective).
pub fn sum_over_ranks(world: &super::World, sums: &mut [ExactSum]) {
    if world.size() == 1 {
        return;
    }
    let mine: Vec<u64> = sums.iter().flat_map(|s| s.to_words()).collect();
    let all = world.allgather_u64(&mine);
    let per_rank = mine.len();
    for (i, s) in sums.iter_mut().enumerate() {
        let mut total = ExactSum::default();
        for r in 0..world.size() as usize {
            let o = r * per_rank + i * ExactSum::WORDS;
            total.merge(&ExactSum::from_words(&all[o..o + ExactSum::WORDS]));
        }
        *s = total;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn any_order_and_grouping_gives_the_same_bits() {
        let mut terms: Vec<f64> = (0..2000)
            .map(|i| {
                let x = ((i * 7919) % 1000) as f64 - 500.0;
                x * 10f64.powi((i % 13) as i32 - 6) / 3.0
            })
            .collect();
        terms.push(1e-300);
        terms.push(-2.5e-310);
        let mut a = ExactSum::default();
        terms.iter().for_each(|&t| a.add(t));
        terms.reverse();
        let (mut b, mut c) = (ExactSum::default(), ExactSum::default());
        for (i, &t) in terms.iter().enumerate() {
            if i % 3 == 0 {
                b.add(t)
            } else {
                c.add(t)
            }
        }
        b.merge(&c);
        assert_eq!(a.value().to_bits(), b.value().to_bits());
        // And the value is the correctly summed one to within an ulp.
        let naive: f64 = terms.iter().sum();
        assert!((a.value() - naive).abs() <= 1e-9 * naive.abs().max(1.0));
    }

    #[test]
    fn cancellation_is_exact() {
        let mut s = ExactSum::default();
        for t in [1e20, 1.0, -1e20, 1e-20] {
            s.add(t);
        }
        assert_eq!(s.value(), 1.0 + 1e-20);
        let mut z = ExactSum::of(-0.0);
        z.add(0.0);
        assert_eq!(z.value().to_bits(), 0f64.to_bits());
    }

    #[test]
    fn words_round_trip_and_specials_propagate() {
        let mut s = ExactSum::of(3.25);
        s.add(-1e-5);
        assert_eq!(ExactSum::from_words(&s.to_words()).value(), s.value());
        s.add(f64::NAN);
        assert!(s.value().is_nan());
        let mut i = ExactSum::of(f64::INFINITY);
        i.add(1.0);
        assert_eq!(i.value(), f64::INFINITY);
    }
}
