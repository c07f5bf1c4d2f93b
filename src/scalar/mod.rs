//! Number types: the [`Field`] and [`Real`] traits and their three instances.
//!
//! Every algorithm in trajverify is written once over these traits and instantiated with
//!
//! | type | context (`Ctx`) | what it delivers |
//! |---|---|---|
//! | `f64` | `()` | IEEE double: fast, 53-bit rounding in every operation |
//! | [`rug::Float`] (MPFR) | precision in bits (`u32`) | correctly rounded operations at any precision |
//! | [`BigRational`] | `()` | exact field arithmetic; no square roots, so it implements only [`Field`] |
//! | [`rug::Rational`] (GMP) | `()` | the same exact values with GMP's integer arithmetic, 20–30× faster where fractions grow (`benches/param.rs`); only [`Field`] |
//! | [`ball::Ball`] | precision in bits (`u32`) | a proven enclosure: MPFR midpoint, f64 radius rounded up |
//! | [`double_interval::DoubleInterval`] | `()` | a proven enclosure with f64 ends: a cheap first try before balls (no `exp`, `ln`) |
//!
//! The context is never a hidden global: a new constant is made with the context of the
//! operands it will meet (`T::from_i64(3, &x.ctx())`), so MPFR precision flows through the
//! computation explicitly. Operators take an owned left and a borrowed right operand
//! (`a * &b`, `a += &b`), the one form all three types provide (rug's `&a + &b` is a lazy
//! expression, not a `Float`).
//!
//! [`parse`] reads decimal and fraction strings exactly; [`certify`] turns two computations at
//! different precisions into a decimal string carrying only the digits on which they agree.

/// `a op b` and `a op &b` for a number type `$t` from its in-place `a op= &b`, which reuses the
/// left operand's storage (balls and double intervals; defined before the modules that use it).
macro_rules! by_value_from_assign {
    ($t:ty) => {
        by_value_from_assign!($t, Add, add, add_assign);
        by_value_from_assign!($t, Sub, sub, sub_assign);
        by_value_from_assign!($t, Mul, mul, mul_assign);
        by_value_from_assign!($t, Div, div, div_assign);
    };
    ($t:ty, $op:ident, $method:ident, $assign_method:ident) => {
        impl $op<&$t> for $t {
            type Output = $t;
            fn $method(mut self, b: &$t) -> $t {
                self.$assign_method(b);
                self
            }
        }
        impl $op<$t> for $t {
            type Output = $t;
            fn $method(mut self, b: $t) -> $t {
                self.$assign_method(&b);
                self
            }
        }
    };
}

pub mod ball;
pub mod certify;
pub mod double_interval;
pub mod dual;
mod float;
mod mpfr;
pub mod parse;
pub mod qsqrt2;
mod rational;

use std::fmt::Debug;
use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};

pub use num_bigint::BigInt;
pub use num_rational::BigRational;
pub use rug::Float;

/// The exact number type `run` reads its input into and computes in for `--scalar rational`:
/// GMP's rationals, 20–30× faster than num-rational's [`BigRational`] where fractions grow
/// (both are a [`Field`] and hold the same values; `docs/benchmarks.md`).
pub type Exact = rug::Rational;

/// The field operations every algorithm needs, with an explicit context for constants.
///
/// Implemented for `f64`, [`rug::Float`], [`rug::Rational`], [`BigRational`], balls and double
/// intervals.
/// Algorithms that need only `+ − × ÷` (Bernstein evaluation, Hermite interpolation,
/// Gaussian elimination) take `T: Field` and therefore also run exactly in rationals.
pub trait Field:
    Clone
    + PartialOrd
    + Debug
    + Send
    + Sync
    + 'static
    + Add<Output = Self>
    + for<'a> Add<&'a Self, Output = Self>
    + Sub<Output = Self>
    + for<'a> Sub<&'a Self, Output = Self>
    + Mul<Output = Self>
    + for<'a> Mul<&'a Self, Output = Self>
    + Div<Output = Self>
    + for<'a> Div<&'a Self, Output = Self>
    + Neg<Output = Self>
    + for<'a> AddAssign<&'a Self>
    + for<'a> SubAssign<&'a Self>
    + for<'a> MulAssign<&'a Self>
    + for<'a> DivAssign<&'a Self>
{
    /// What a constant needs to be made compatible with existing values: `()` for f64 and
    /// rationals, the precision in bits for MPFR.
    type Ctx: Clone + Debug + PartialEq + Send + Sync;

    /// Whether values are rigorous enclosures ([`ball::Ball`]), whose comparisons can be
    /// undecidable. Code that compares only to tidy its output (flushing rounding noise to
    /// 0) skips those comparisons for enclosures: a ball around 0 is already the honest
    /// answer.
    const ENCLOSURE: bool = false;

    /// The context of this value (its precision for MPFR).
    fn ctx(&self) -> Self::Ctx;
    /// A name for the number type in this context: `f64`, `rational`, `mpfr:<bits>`.
    fn scalar_name(ctx: &Self::Ctx) -> String;

    /// Zero in `ctx`.
    fn zero_in(ctx: &Self::Ctx) -> Self {
        Self::from_i64(0, ctx)
    }
    /// One in `ctx`.
    fn one_in(ctx: &Self::Ctx) -> Self {
        Self::from_i64(1, ctx)
    }
    /// The integer `v`, rounded to the context if it is not representable.
    fn from_i64(v: i64, ctx: &Self::Ctx) -> Self;
    /// The fraction `n/d` with one rounding (exact for rationals).
    ///
    /// # Panics
    /// For d = 0 the exact types (rationals, ℚ(√2)) panic, as `i64` division by zero does
    /// and as their `/` operator does; the floating types give ±∞ or NaN (a ball: the ball of
    /// every number). By design: the library calls it with denominators it has checked.
    /// [`Field::try_from_ratio`] is the form for a denominator that may be zero.
    fn from_ratio(n: i64, d: i64, ctx: &Self::Ctx) -> Self;
    /// `n/d`, or `None` for d = 0, in every number type.
    ///
    /// # Examples
    /// ```
    /// use trajverify::scalar::{BigRational, Field};
    /// assert_eq!(BigRational::try_from_ratio(1, 0, &()), None);
    /// assert_eq!(f64::try_from_ratio(3, 4, &()), Some(0.75));
    /// ```
    fn try_from_ratio(n: i64, d: i64, ctx: &Self::Ctx) -> Option<Self> {
        (d != 0).then(|| Self::from_ratio(n, d, ctx))
    }
    /// The fraction `n/d` whose correctly rounded double `nearest` the caller precomputed
    /// (cached constants): f64 returns `nearest` without dividing, every other type
    /// computes `n/d` in its own precision as [`Field::from_ratio`] does.
    fn from_ratio_nearest(n: i64, d: i64, nearest: f64, ctx: &Self::Ctx) -> Self {
        let _ = nearest;
        Self::from_ratio(n, d, ctx)
    }
    /// The rational `q`, correctly rounded to the context (exact for rationals).
    fn from_rational(q: &BigRational, ctx: &Self::Ctx) -> Self;
    /// The GMP rational `q` (how `run` reads its input), correctly rounded to the context:
    /// the same value as [`Field::from_rational`] gives for the same number, without a
    /// num-rational copy for the types that round from GMP directly.
    fn from_exact(q: &rug::Rational, ctx: &Self::Ctx) -> Self {
        Self::from_rational(&mpfr::from_gmp_rational(q), ctx)
    }
    /// The double `v` (exact for rationals and for MPFR with at least 53 bits). `v` must be finite.
    fn from_f64(v: f64, ctx: &Self::Ctx) -> Self;
    /// A shortcut for reading the text of a JSON number (`-12.5e3`, the JSON grammar), when
    /// the type has one that gives exactly `from_exact(parse_exact(text))`; `None` sends the
    /// caller to that exact path. f64 reads short decimals straight to the nearest double.
    fn from_json_number(text: &str, ctx: &Self::Ctx) -> Option<Self> {
        let _ = (text, ctx);
        None
    }

    /// |x|.
    fn abs(&self) -> Self;
    /// Whether x = 0 exactly.
    fn is_zero(&self) -> bool;
    /// False for infinities and NaN (always true for rationals).
    fn is_finite(&self) -> bool;
    /// The nearest double (may overflow to ±∞ or lose everything below 2⁻¹⁰⁷⁴).
    fn to_f64(&self) -> f64;
    /// The exact value of a finite number as a fraction.
    fn to_rational(&self) -> Option<BigRational>;
    /// The exact value of a finite number as a GMP rational (the exact decisions' type): the
    /// same value as [`Field::to_rational`], without a num-rational copy where the number
    /// converts to GMP directly.
    fn to_exact(&self) -> Option<rug::Rational> {
        self.to_rational().map(|q| mpfr::to_gmp_rational(&q))
    }
    /// `self ← a·b`, rounded exactly as `a.clone() * b`, reusing `self`'s storage where the
    /// number type has any (MPFR: no allocation when `self` has `a`'s precision), for loops
    /// that keep a scratch product.
    fn assign_mul(&mut self, a: &Self, b: &Self) {
        *self = a.clone() * b;
    }
    /// `self += a·b`. MPFR fuses it into one rounding without a temporary; the default (used
    /// by f64 and rationals) multiplies, then adds.
    fn mul_add_assign(&mut self, a: &Self, b: &Self) {
        *self += &(a.clone() * b);
    }
    /// `self ← self·x + c`, the Horner step, rounded exactly as `c.mul_add_assign(self, x)`
    /// (one rounding in MPFR and balls, which do it in place without a temporary).
    fn horner_step(&mut self, x: &Self, c: &Self) {
        horner_step_into_copy(self, x, c);
    }
    /// `self −= a·b`, fused in MPFR like [`Field::mul_add_assign`].
    fn mul_sub_assign(&mut self, a: &Self, b: &Self) {
        *self -= &(a.clone() * b);
    }
    /// The unit roundoff of the number type in `ctx` (2⁻⁵³ for f64, 2⁻ᵖ for MPFR at p
    /// bits), for methods that check their own conditioning; `None` where no digit is lost
    /// to rounding unnoticed: exact rationals, and balls, whose radius already says it.
    fn unit_roundoff(ctx: &Self::Ctx) -> Option<f64> {
        let _ = ctx;
        None
    }
    /// Whether `self < other`, when that is decided: always for f64, MPFR and rationals;
    /// for enclosures only when the balls are disjoint (`None` otherwise, without counting an
    /// undecided comparison — the caller handles it, e.g. a bisection that stops there).
    fn decide_lt(&self, other: &Self) -> Option<bool> {
        Some(*self < *other)
    }
    /// A value standing for the whole interval [lo, hi] (lo ≤ hi): its midpoint for
    /// f64, MPFR and rationals, an enclosure of the interval for balls (a bisection's last
    /// bracket is then a proven enclosure of the root).
    fn hull(lo: &Self, hi: &Self) -> Self {
        (lo.clone() + hi) / &Self::from_i64(2, &lo.ctx())
    }
    /// The smaller of `self` and `other`. For enclosures ([`ball::Ball`]) an enclosure of
    /// min(x, y) over every x and y of the two balls: min is continuous, so it needs no
    /// comparison to be decided (and counts none).
    fn min_with(&self, other: &Self) -> Self {
        if *other < *self {
            other.clone()
        } else {
            self.clone()
        }
    }
    /// The larger of `self` and `other` (an enclosure for balls, as [`Field::min_with`]).
    fn max_with(&self, other: &Self) -> Self {
        if *other > *self {
            other.clone()
        } else {
            self.clone()
        }
    }
    /// Bounds (lower, upper) of |x| as doubles. For enclosures ([`ball::Ball`]) they hold
    /// for every point of the ball (rounded outward: a proven residual bound |r| ≤ upper, a
    /// proven separation |d| ≥ lower); for f64, MPFR and rationals both are |x| rounded to
    /// the nearest double, which proves nothing about the rounding that produced x.
    fn magnitude_bounds(&self) -> (f64, f64) {
        let m = self.abs().to_f64();
        (m, m)
    }
    /// All the digits this value carries, uncertified: an exact fraction for rationals,
    /// the shortest round-trip decimal for f64, every significant digit of the precision for
    /// MPFR. Use [`certify`] for digits that two precisions agree on.
    fn to_plain_string(&self) -> String;
    /// [`Field::to_plain_string`] appended to `out` (f64 writes without a string of its own).
    fn write_plain_string(&self, out: &mut String) {
        out.push_str(&self.to_plain_string());
    }
    /// About the length of [`Field::to_plain_string`], without writing it: for reserving an
    /// output's text and deciding whether to print it on two threads (exact fractions run to
    /// thousands of digits; a double to at most 24 characters).
    fn plain_string_len_hint(&self) -> usize {
        24
    }
}

/// `acc ← c + acc·x` through a copy of `c` and [`Field::mul_add_assign`]: the default
/// [`Field::horner_step`], and the fallback of the in-place overrides when the precisions of
/// `acc` and `c` differ.
pub fn horner_step_into_copy<T: Field>(acc: &mut T, x: &T, c: &T) {
    let mut next = c.clone();
    next.mul_add_assign(acc, x);
    *acc = next;
}

/// The operations beyond a field that curves, frames and singular values need.
///
/// Implemented by `f64` and [`rug::Float`] only, so code that takes a square root cannot be
/// instantiated with rationals by mistake. MPFR operations are correctly rounded; the f64
/// transcendental functions come from the platform's libm and may differ in the last bit
/// between platforms.
pub trait Real: Field {
    /// √x.
    fn sqrt(&self) -> Self;
    /// (sin x, cos x).
    fn sin_cos(&self) -> (Self, Self);
    /// sin x, bit for bit the first of [`Real::sin_cos`] (MPFR and balls compute it alone,
    /// correctly rounded as `sin_cos` rounds it).
    fn sin(&self) -> Self {
        self.sin_cos().0
    }
    /// cos x, bit for bit the second of [`Real::sin_cos`].
    fn cos(&self) -> Self {
        self.sin_cos().1
    }
    /// `self.atan2(x)` is the angle of the point (x, self), in (−π, π].
    fn atan2(&self, x: &Self) -> Self;
    /// eˣ.
    fn exp(&self) -> Self;
    /// ln x.
    fn ln(&self) -> Self;
    /// log₂ x (correctly rounded in MPFR; the default divides by ln 2).
    fn log2(&self) -> Self {
        self.ln() / &Self::from_i64(2, &self.ctx()).ln()
    }
    /// π in `ctx`.
    fn pi(ctx: &Self::Ctx) -> Self;
    /// The unit roundoff scale 2^(1−p) of the context (p = 53 for f64).
    fn epsilon(ctx: &Self::Ctx) -> Self;
    /// The precision in bits.
    fn precision_bits(ctx: &Self::Ctx) -> u32;
}

/// `base^e` by repeated squaring, in the field of `base`.
pub fn powi<T: Field>(base: &T, mut e: u32) -> T {
    let mut result = T::one_in(&base.ctx());
    let mut square = base.clone();
    while e > 0 {
        if e & 1 == 1 {
            result *= &square;
        }
        e >>= 1;
        if e > 0 {
            square = square.clone() * &square;
        }
    }
    result
}

/// The larger of two values (the first one when they compare equal or are unordered).
pub fn max_of<T: Field>(a: T, b: T) -> T {
    if b > a {
        b
    } else {
        a
    }
}

/// Which number type a computation runs in, as chosen on the command line.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ScalarKind {
    /// IEEE double precision.
    F64,
    /// Exact rationals.
    Rational,
    /// MPFR with this many bits of precision.
    Mpfr(u32),
    /// Ball arithmetic (a proven enclosure) with an MPFR midpoint of this many bits.
    Ball(u32),
}

/// Smallest and largest MPFR precision accepted from users.
pub const MPFR_BITS_RANGE: (u32, u32) = (16, 1 << 16);

impl std::str::FromStr for ScalarKind {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "f64" => Ok(ScalarKind::F64),
            "rational" => Ok(ScalarKind::Rational),
            _ => {
                let (kind, bits) = if let Some(bits) = s.strip_prefix("mpfr:") {
                    ("mpfr", bits)
                } else if let Some(bits) = s.strip_prefix("ball:") {
                    ("ball", bits)
                } else {
                    return Err(format!(
                        "unknown scalar {s:?}: expected f64, rational, mpfr:<bits> or ball:<bits>"
                    ));
                };
                let bits: u32 = bits.parse().map_err(|_| {
                    format!("{kind} precision {bits:?} is not a whole number of bits")
                })?;
                let (lo, hi) = MPFR_BITS_RANGE;
                if !(lo..=hi).contains(&bits) {
                    return Err(format!(
                        "{kind} precision {bits} is outside {lo}..={hi} bits"
                    ));
                }
                Ok(if kind == "ball" {
                    ScalarKind::Ball(bits)
                } else {
                    ScalarKind::Mpfr(bits)
                })
            }
        }
    }
}

impl std::fmt::Display for ScalarKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ScalarKind::F64 => write!(f, "f64"),
            ScalarKind::Rational => write!(f, "rational"),
            ScalarKind::Mpfr(bits) => write!(f, "mpfr:{bits}"),
            ScalarKind::Ball(bits) => write!(f, "ball:{bits}"),
        }
    }
}

/// A num-rational as a GMP rational, exactly (for MPFR operations with directed rounding).
pub fn mpfr_rational(q: &BigRational) -> rug::Rational {
    mpfr::to_gmp_rational(q)
}

/// A GMP rational ([`Exact`]) as a num-rational, exactly.
pub fn big_rational(q: &Exact) -> BigRational {
    mpfr::from_gmp_rational(q)
}

/// The shortest decimal that reads back as the same double (see `Field::to_plain_string`).
pub fn float_text(x: f64) -> String {
    float::format_f64(x)
}

/// A reproducible stream of 64-bit words (xorshift64) for the tests' random inputs.
#[cfg(test)]
pub(crate) fn xorshift(mut state: u64) -> impl FnMut() -> u64 {
    move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn generic_sum_of_thirds<T: Field>(ctx: &T::Ctx) -> T {
        let third = T::from_ratio(1, 3, ctx);
        third.clone() + &third + &third
    }

    #[test]
    fn one_generic_body_three_number_types() {
        assert_eq!(
            generic_sum_of_thirds::<BigRational>(&()),
            BigRational::from_integer(1.into())
        );
        assert_eq!(generic_sum_of_thirds::<f64>(&()), 1.0);
        let x: Float = generic_sum_of_thirds(&200);
        assert_eq!(x.prec(), 200);
        assert!((x - 1u32).abs() < 1e-59);
    }

    /// Rationals round once to the nearest double, subnormals too (rounding to 53 bits first
    /// and then to a subnormal's fewer bits rounded twice), down to the tie at 2⁻¹⁰⁷⁵.
    #[test]
    fn subnormal_rationals_round_once() {
        for text in [
            "1.6725613558992932035e-308",
            "4.9406564584124654e-324",
            "2.5e-324",
            "2.4703282292062328e-324",
            "1e-330",
        ] {
            let q = parse::parse_rational(text).unwrap();
            assert_eq!(
                BigRational::to_f64(&q),
                text.parse::<f64>().unwrap(),
                "{text}"
            );
        }
        let tie = BigRational::new(1.into(), BigInt::from(1) << 1075usize);
        assert_eq!(BigRational::to_f64(&tie), 0.0);
        assert_eq!(BigRational::to_f64(&-tie.clone()), 0.0);
        let above = tie * BigRational::new(1_000_001.into(), 1_000_000.into());
        assert_eq!(BigRational::to_f64(&above), f64::from_bits(1));
    }

    #[test]
    fn powi_matches_repeated_multiplication() {
        let b = BigRational::new(3.into(), 2.into());
        assert_eq!(powi(&b, 5), BigRational::new(243.into(), 32.into()));
        assert_eq!(powi(&2.0f64, 0), 1.0);
    }

    #[test]
    fn scalar_kind_parses_and_rejects() {
        assert_eq!("mpfr:256".parse::<ScalarKind>(), Ok(ScalarKind::Mpfr(256)));
        assert_eq!("rational".parse::<ScalarKind>(), Ok(ScalarKind::Rational));
        assert!("mpfr:3".parse::<ScalarKind>().is_err());
        assert!("mpfr:x".parse::<ScalarKind>().is_err());
        assert!("f32".parse::<ScalarKind>().is_err());
    }
}
