//! A parameter interval [a, b] whose ends are real numbers given exactly: rationals, doubles
//! (each double is a rational) or constant expressions such as `4*pi`
//! ([`ExactReal`]). An end is rounded only when a computation needs it in a number type:
//! to the nearest double in f64, to p bits in MPFR, and *enclosed* in a ball, so a proof
//! run on [a, b] in balls holds for the true interval (the ball of 4π contains 4π).
//!
//! This is how the computations that need an interval in several number types at once take
//! it: a convergence study ([`crate::algo::convergence::study`]), its regularity proof
//! ([`crate::curve::regularity::check`]) and the certified error of a conversion
//! ([`crate::algo::ph::piecewise::certified_error`]). Functions that work in one number type
//! take the ends as two values of that type (`fit(&curve, (&a, &b), ..)`).
//!
//! Whether a < b is decided on the exact ends: by rational comparison when both are
//! rational, otherwise by balls at 64, 256, 1024 and 4096 bits until they are disjoint.
//! Ends that agree to 4096 bits (`pi` and `4*atan(1)`) are refused as undecided rather than
//! ordered by a rounding.

use super::expr::ExactReal;
use crate::scalar::ball::Ball;
use crate::scalar::{BigRational, Field, Float, Real};

/// The precisions at which a < b is tried, in bits.
pub const DECISION_BITS: [u32; 4] = [64, 256, 1024, 4096];

/// Why an interval cannot be made.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum IntervalError {
    /// An end that is not a number or a constant expression (the text and the parser's
    /// message).
    #[error("interval: {end} = {text:?}: {message}")]
    Parse {
        /// "a" or "b".
        end: &'static str,
        /// The text as given.
        text: String,
        /// What is wrong with it.
        message: String,
    },
    /// An end that is not finite (a NaN or infinite double, or an expression such as
    /// `1/0` or `ln(0)`).
    #[error("interval: the end {0} is not a finite number")]
    NotFinite(&'static str),
    /// b ≤ a.
    #[error("interval: need a < b")]
    NotIncreasing,
    /// The ends agree to [`DECISION_BITS`]'s last precision: a < b was not decided.
    #[error(
        "interval: whether a < b is not decided at 4096 bits (the ends agree to that precision)"
    )]
    Undecided,
}

/// A parameter interval [a, b] with exact ends and a < b (decided exactly).
///
/// # Examples
/// ```
/// use trajverify::curve::interval::Interval;
/// use trajverify::scalar::ball::Ball;
///
/// let turns = Interval::parse("0", "4*pi").unwrap();
/// let (a, b): (f64, f64) = turns.ends(&());
/// assert_eq!((a, b), (0.0, 4.0 * std::f64::consts::PI));
/// let (_, b): (Ball, Ball) = turns.ends(&128);
/// assert!(b.lower() < 12.5664 && b.upper() > 12.5663); // a ball encloses 4π
/// assert!(Interval::parse("1", "1").is_err());
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Interval {
    a: ExactReal,
    b: ExactReal,
}

impl Interval {
    /// [a, b] from two exact ends.
    ///
    /// # Errors
    /// [`IntervalError::NotFinite`] for an end whose ball is not finite,
    /// [`IntervalError::NotIncreasing`] unless a < b, [`IntervalError::Undecided`] when the
    /// ends agree to 4096 bits.
    pub fn new(a: impl Into<ExactReal>, b: impl Into<ExactReal>) -> Result<Self, IntervalError> {
        let (a, b) = (a.into(), b.into());
        let increasing = match (&a, &b) {
            (ExactReal::Exact(a), ExactReal::Exact(b)) => a < b,
            _ => decide_less(&a, &b)?,
        };
        if !increasing {
            return Err(IntervalError::NotIncreasing);
        }
        Ok(Interval { a, b })
    }

    /// [0, 1].
    pub fn unit() -> Self {
        Interval {
            a: ExactReal::from(0),
            b: ExactReal::from(1),
        }
    }

    /// [a, b] from two doubles, taken exactly (a double is a rational).
    ///
    /// # Errors
    /// [`IntervalError::NotFinite`] for NaN or ±∞, [`IntervalError::NotIncreasing`] unless
    /// a < b.
    pub fn from_f64(a: f64, b: f64) -> Result<Self, IntervalError> {
        let exact = |x: f64, end| ExactReal::from_f64(x).ok_or(IntervalError::NotFinite(end));
        Interval::new(exact(a, "a")?, exact(b, "b")?)
    }

    /// [a, b] from two texts, each a number (`"0.25"`, `"1/3"`, `"1e-3"`) or a constant
    /// expression in the curve language (`"4*pi"`, `"sqrt(2)/2"`).
    ///
    /// # Errors
    /// [`IntervalError::Parse`] for text that is neither, or an expression in t; then those
    /// of [`Interval::new`].
    pub fn parse(a: &str, b: &str) -> Result<Self, IntervalError> {
        Interval::new(parse_end(a, "a")?, parse_end(b, "b")?)
    }

    /// The left end, exactly.
    pub fn a(&self) -> &ExactReal {
        &self.a
    }

    /// The right end, exactly.
    pub fn b(&self) -> &ExactReal {
        &self.b
    }

    /// Both ends when both are rational.
    pub fn rational_ends(&self) -> Option<(&BigRational, &BigRational)> {
        match (&self.a, &self.b) {
            (ExactReal::Exact(a), ExactReal::Exact(b)) => Some((a, b)),
            _ => None,
        }
    }

    /// The ends in the number type `T`: rounded once for a rational end, each operation of
    /// an expression rounded in `T` (so balls enclose the true ends).
    pub fn ends<T: Real>(&self, ctx: &T::Ctx) -> (T, T) {
        (self.a.eval(ctx), self.b.eval(ctx))
    }

    /// The ends to the nearest double.
    pub fn to_f64(&self) -> (f64, f64) {
        self.ends(&())
    }

    /// Floats `lo ≤ a` and `hi ≥ b` at `bits` (or finer): an interval of floats that contains
    /// [a, b], for proofs that bisect a parameter box.
    pub fn enclosure(&self, bits: u32) -> (Float, Float) {
        let (a, b): (Ball, Ball) = self.ends(&bits);
        (a.lower(), b.upper())
    }
}

/// Decide a < b by balls at increasing precision.
fn decide_less(a: &ExactReal, b: &ExactReal) -> Result<bool, IntervalError> {
    for bits in DECISION_BITS {
        let (x, y): (Ball, Ball) = (a.eval(&bits), b.eval(&bits));
        if !x.is_finite() {
            return Err(IntervalError::NotFinite("a"));
        }
        if !y.is_finite() {
            return Err(IntervalError::NotFinite("b"));
        }
        if let Some(less) = x.decide_lt(&y) {
            // Disjoint balls: either a < b, or b < a (then also not increasing).
            return Ok(less);
        }
    }
    Err(IntervalError::Undecided)
}

/// One end from its text ([`ExactReal::parse`]).
fn parse_end(text: &str, end: &'static str) -> Result<ExactReal, IntervalError> {
    ExactReal::parse(text).map_err(|message| IntervalError::Parse {
        end,
        text: text.to_string(),
        message,
    })
}

impl std::fmt::Display for Interval {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.rational_ends() {
            Some((a, b)) => write!(f, "[{a}, {b}]"),
            None => {
                let (a, b) = self.to_f64();
                write!(f, "[{a}, {b}] (to the nearest double)")
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rational_ends_are_compared_exactly() {
        let third = BigRational::new(1.into(), 3.into());
        let close = BigRational::new(
            num_bigint::BigInt::from(10).pow(3000) + 1,
            num_bigint::BigInt::from(10).pow(3000) * 3,
        );
        // Equal to 1/3 far beyond 4096 bits, still ordered: the comparison is exact.
        assert!(Interval::new(third.clone(), close.clone()).is_ok());
        assert_eq!(
            Interval::new(close, third),
            Err(IntervalError::NotIncreasing)
        );
    }

    #[test]
    fn expressions_are_ordered_by_balls_or_refused() {
        assert!(Interval::parse("3.1415926", "pi").is_ok());
        assert_eq!(
            Interval::parse("pi", "3.1415926"),
            Err(IntervalError::NotIncreasing)
        );
        assert_eq!(
            Interval::parse("pi", "4*atan(1)"),
            Err(IntervalError::Undecided)
        );
        assert_eq!(
            Interval::parse("0", "1/0"),
            Err(IntervalError::NotFinite("b"))
        );
        assert!(matches!(
            Interval::parse("t", "1"),
            Err(IntervalError::Parse { end: "a", .. })
        ));
        assert_eq!(
            Interval::from_f64(f64::NAN, 1.0),
            Err(IntervalError::NotFinite("a"))
        );
    }

    #[test]
    fn the_enclosure_contains_the_ends() {
        let i = Interval::parse("-pi", "4*pi").expect("ordered");
        let (lo, hi) = i.enclosure(64);
        let pi = Float::with_val(512, rug::float::Constant::Pi);
        assert!(lo < Float::with_val(512, -&pi));
        assert!(hi > Float::with_val(512, &pi * 4u32));
    }
}
