//! Ball arithmetic: a rigorous enclosure [m − r, m + r] of every real number a computation
//! stands for, with the midpoint m in MPFR at p bits and the radius r an f64 rounded upward.
//!
//! Every operation returns a ball that contains the exact result of the operation applied to
//! any points of its operand balls (the inclusion principle), so a value computed through
//! the generic algorithms is *proven* to lie in its ball — not certified by two precisions
//! agreeing. Each operation rounds the midpoint to nearest (MPFR reports whether it was
//! exact) and adds to the propagated radius a bound on that rounding error, one ulp of the
//! result, 2^(e−p) for a result in [2^(e−1), 2^e). The radius arithmetic itself runs in f64
//! round-to-nearest: the four arithmetic operations (and the fused multiply-add) evaluate
//! their whole radius formula to nearest and multiply it once by 1 + 2⁻⁴⁸, which bounds the
//! few roundings inside from above (`bound`); the rarer functions step each intermediate
//! result one double up. |m| is bounded from the midpoint's leading limb, 2^k from its bits,
//! and the midpoint is computed in place: an operation allocates nothing. An f64 radius has
//! ample range for enclosures of numbers between 1e-300 and 1e300.
//!
//! | operation | midpoint | radius (before the rounding bound) |
//! |---|---|---|
//! | a ± b | m_a ± m_b | r_a + r_b |
//! | a·b | m_a·m_b | \|m_a\|r_b + \|m_b\|r_a + r_a r_b |
//! | a/b | m_a/m_b | (r_a + \|m\|r_b)/(\|m_b\| − r_b), ∞ if b contains 0 |
//! | √a | √m_a | r_a/(√(m_a − r_a) + √m_a) |
//! | sin, cos | sin m, cos m | r (Lipschitz 1) |
//! | exp | e^m | e^m·(e^r − 1) |
//! | ln | ln m | r/(m − r) |
//! | atan2(y, x) | atan2(m_y, m_x) | (r_x + r_y)/ρ_min, ∞ across the branch cut |
//!
//! Comparisons are honest: a < b holds only when the balls are disjoint; when they overlap
//! the answer is unknown, so `partial_cmp` returns `None` and the event is counted. A
//! computation that made a branch on an undecided comparison may have taken the wrong branch,
//! so the `run` commands refuse its result. The count belongs to the computation: [`tally`]
//! runs a closure and returns how many undecided comparisons *it* made (work it hands to
//! rayon carries the tally with [`carried`]); outside any tally they add to a process-wide
//! total ([`undecided_comparisons`]). With the environment variable `TRAJVERIFY_BALL_TRACE`
//! set, each undecided comparison prints a backtrace to stderr, to find the branch. Where a
//! branch only chooses between two equal formulas or orders a rounding heuristic (a pivot),
//! the code asks [`Field::decide_lt`], which does not count; where a piecewise function meets
//! a ball that straddles a breakpoint, both pieces are evaluated and joined ([`Field::hull`]).
//! `is_zero` means "exactly zero" (radius 0), as for the other number types; exact zeros
//! propagate (0·x, x − x of one exact value, sin 0, atan2(0, x > 0) are exactly 0).
//!
//! **The printed contract.** A ball is printed ([`Ball::printed`]) as a decimal `value` and a
//! decimal `radius` such that every point of the ball lies in [value − radius, value +
//! radius] *as printed*: `value` carries the digits every point of the ball rounds to (the
//! midpoint to two digits when not even one is proven), and `radius` is measured from that
//! rounded value — |value − mid| + rad, computed exactly and rounded up to two digits — not
//! from the unprinted midpoint. The README's example prints 13/15 at 64 bits as
//! 0.866666666666666667 ± 4.6e-19, which contains it.

use super::certify::format_float_digits;
use super::mpfr::precision;
use super::{BigRational, Field, Real};
use rug::float::{Constant, Round};
use rug::ops::{AddAssignRound, DivAssignRound, MulAssignRound, SubAssignRound};
use rug::{Assign, Float};
use std::cmp::Ordering;
use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};
use std::sync::atomic::{AtomicU64, Ordering as AtomicOrdering};
use std::sync::Arc;

/// A ball as printed (see [`Ball::printed`]): every point of the ball lies within `radius`
/// of `value`, both read as exact decimals.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PrintedBall {
    /// A decimal: the proven digits, or the midpoint to two digits when none is proven.
    pub value: String,
    /// An upper bound of the distance from `value` to every point of the ball, two
    /// significant digits rounded up ("0" for an exact ball printed in full).
    pub radius: String,
    /// How many significant digits of `value` are proven (every point of the ball rounds
    /// to them); 0 when not even the first is.
    pub digits: u32,
}

/// A non-negative rational as a decimal of two significant digits that is not below it
/// ("0" for zero).
fn upper_decimal(x: &rug::Rational) -> String {
    if *x == 0 {
        return "0".into();
    }
    // A 64-bit upper bound, then two decimal digits rounded up from it.
    let (up, _) = Float::with_val_round(64, x, Round::Up);
    let (negative, mantissa, exp) = up.to_sign_string_exp_round(10, Some(2), Round::Up);
    let e = exp.unwrap_or(0) - 1;
    let (lead, rest) = mantissa.split_at(1.min(mantissa.len()));
    format!("{}{lead}.{rest}e{e}", if negative { "-" } else { "" })
}

/// The digits an interval [lo, hi] proves at a working precision of `prec` bits: the largest
/// d (at most what `prec` bits carry) such that every point of the interval rounds to the same
/// d significant decimal digits, with that decimal; 0 and "" when not even the first digit
/// is proven, and every digit of "0" for [0, 0].
pub fn interval_digits(lo: &Float, hi: &Float, prec: u32) -> (u32, String) {
    if !lo.is_finite() || !hi.is_finite() {
        return (0, String::new());
    }
    let cap = super::certify::max_digits(prec);
    if lo.is_zero() && hi.is_zero() {
        return (cap, "0".into());
    }
    // An exact value proves every digit; show as many as the precision holds, not the extra
    // ones of guard bits.
    let mut digits = super::certify::agreeing_digits(lo, hi).min(cap).max(1);
    while digits > 0 {
        let (a, b) = (
            format_float_digits(lo, digits),
            format_float_digits(hi, digits),
        );
        if a == b {
            return (digits, a);
        }
        digits -= 1;
    }
    (0, String::new())
}

/// An interval [lo, hi] printed as a ball ([`Ball::printed`]'s contract), without the f64
/// range of a ball's radius: `value` carries the digits every point rounds to (the midpoint to
/// two digits when none is proven), `radius` bounds max(value − lo, hi − value), rounded up.
/// `None` when an end is not finite.
pub fn printed_interval(lo: &Float, hi: &Float, prec: u32) -> Option<PrintedBall> {
    let (l, h) = (lo.to_rational()?, hi.to_rational()?);
    let mid = Float::with_val(lo.prec().max(hi.prec()) + 1, lo + hi) / 2u32;
    printed_around(interval_digits(lo, hi, prec), &mid, |printed| {
        (printed.clone() - &l).max(h.clone() - printed)
    })
}

/// The printed form of proven `digits` (or of `mid` to two digits when there are none), with
/// the radius `distance(printed value)` rounded up.
fn printed_around(
    (digits, proven): (u32, String),
    mid: &Float,
    distance: impl Fn(&rug::Rational) -> rug::Rational,
) -> Option<PrintedBall> {
    let value = if digits == 0 {
        format_float_digits(mid, 2)
    } else {
        proven
    };
    let printed = super::parse::parse_rational(&value)
        .ok()
        .map(|q| super::mpfr::to_gmp_rational(&q))?;
    Some(PrintedBall {
        radius: upper_decimal(&distance(&printed)),
        value,
        digits,
    })
}

/// A real number known to lie in [mid − rad, mid + rad].
#[derive(Clone, Debug)]
pub struct Ball {
    mid: Float,
    rad: f64,
}

static UNDECIDED: AtomicU64 = AtomicU64::new(0);

thread_local! {
    /// The tally of the computation running on this thread ([`tally`]), if any.
    static CURRENT: std::cell::RefCell<Option<Arc<AtomicU64>>> = const { std::cell::RefCell::new(None) };
}

/// How many ball comparisons could not be decided since the process started, outside any
/// [`tally`] (all threads).
pub fn undecided_comparisons() -> u64 {
    UNDECIDED.load(AtomicOrdering::Relaxed)
}

/// Run `f` and count the undecided comparisons it makes, and only those: the count belongs
/// to this computation, not to the process, so computations on other threads (other
/// commands, other tests) cannot add to it. Work `f` hands to rayon must carry the tally
/// into the worker threads with [`carried`].
pub fn tally<R>(f: impl FnOnce() -> R) -> (R, u64) {
    let counter = Arc::new(AtomicU64::new(0));
    let result = installed(Some(counter.clone()), f);
    (result, counter.load(AtomicOrdering::Relaxed))
}

/// `f` wrapped to count its undecided comparisons in the tally of the thread that wraps it
/// (for closures run on rayon's worker threads: `.map(carried(|k| …))`).
pub fn carried<A, R, F: Fn(A) -> R + Sync + Send>(f: F) -> impl Fn(A) -> R + Sync + Send {
    let counter = CURRENT.with(|c| c.borrow().clone());
    // Every parallel loop of the library goes through here: one checkpoint per item lets a
    // stopped job end within an item (`crate::cancel`).
    move |a| {
        crate::cancel::checkpoint();
        installed(counter.clone(), || f(a))
    }
}

fn installed<R>(counter: Option<Arc<AtomicU64>>, f: impl FnOnce() -> R) -> R {
    let previous = CURRENT.with(|c| c.replace(counter));
    // Restore the previous tally even if `f` unwinds.
    struct Restore(Option<Arc<AtomicU64>>);
    impl Drop for Restore {
        fn drop(&mut self) {
            let previous = self.0.take();
            CURRENT.with(|c| *c.borrow_mut() = previous);
        }
    }
    let _restore = Restore(previous);
    f()
}

fn undecided() {
    let counted = CURRENT.with(|c| {
        c.borrow()
            .as_ref()
            .map(|t| t.fetch_add(1, AtomicOrdering::Relaxed))
            .is_some()
    });
    if !counted {
        UNDECIDED.fetch_add(1, AtomicOrdering::Relaxed);
    }
    if std::env::var_os("TRAJVERIFY_BALL_TRACE").is_some() {
        eprintln!("{}", std::backtrace::Backtrace::force_capture());
    }
}

/// The next double above x (`f64::next_up`, which needs Rust 1.86, spelled out for 1.85).
pub(super) fn next_double(x: f64) -> f64 {
    if x.is_nan() || x == f64::INFINITY {
        x
    } else if x == 0.0 {
        f64::from_bits(1)
    } else if x > 0.0 {
        f64::from_bits(x.to_bits() + 1)
    } else {
        f64::from_bits(x.to_bits() - 1)
    }
}

/// x rounded up to the next double (an upper bound for the exact value x approximates).
fn up(x: f64) -> f64 {
    if x.is_nan() {
        f64::INFINITY
    } else {
        next_double(x)
    }
}

/// An upper bound of a + b for a, b ≥ 0 (exact when one is 0).
fn add_up(a: f64, b: f64) -> f64 {
    if a == 0.0 {
        b
    } else if b == 0.0 {
        a
    } else {
        up(a + b)
    }
}

/// An upper bound of a·b for a, b ≥ 0 (exactly 0 when one is 0, even if the other is ∞).
fn mul_up(a: f64, b: f64) -> f64 {
    if a == 0.0 || b == 0.0 {
        0.0
    } else {
        up(a * b)
    }
}

/// 1 + 2⁻⁴⁸. A sum of products of non-negative doubles computed in round-to-nearest, with
/// k ≤ 30 roundings each of relative error at most u = 2⁻⁵³, is at least (1 − u)ᵏ times the
/// exact value; multiplied by this factor (and rounded once more) it is above the exact
/// value, since (1 − u)³¹(1 + 32u) > 1. One multiplication bounds a whole radius formula
/// instead of stepping every intermediate result one double up.
const SLACK: f64 = 1.0 + 1.0 / 281_474_976_710_656.0;

/// Below 2⁻⁹⁰⁰ the terms of a radius may have underflowed, each losing up to 2⁻¹⁰⁷⁵
/// absolutely: [`bound`] adds eight of the smallest subnormals there.
const UNDERFLOW_ZONE: f64 = f64::from_bits((1023 - 900) << 52);

/// An upper bound of the exact non-negative value that `s`, a sum of products of
/// non-negative doubles rounded to nearest (at most 30 roundings), approximates; `positive`
/// says whether any exact term is positive (otherwise the value is an exact 0 and stays 0).
/// NaN (∞ · 0 inside a radius) becomes ∞.
fn bound(s: f64, positive: bool) -> f64 {
    if !positive {
        0.0
    } else if s >= UNDERFLOW_ZONE {
        s * SLACK
    } else if s.is_nan() {
        f64::INFINITY
    } else {
        s * SLACK + 8.0 * f64::from_bits(1)
    }
}

/// a·b for a, b ≥ 0, exactly 0 when one is 0 even if the other is ∞ (to nearest otherwise;
/// [`bound`] accounts for the rounding).
fn times(a: f64, b: f64) -> f64 {
    if a == 0.0 || b == 0.0 {
        0.0
    } else {
        a * b
    }
}

/// An upper bound of a/b for a ≥ 0, b > 0.
fn div_up(a: f64, b: f64) -> f64 {
    if a == 0.0 {
        0.0
    } else {
        up(a / b)
    }
}

/// x stepped one ulp down (a lower bound).
fn down(x: f64) -> f64 {
    if x.is_nan() {
        0.0
    } else {
        -next_double(-x)
    }
}

/// The top 53 bits of |x| and its exponent e (|x| = 0.b₁b₂… × 2^e with b₁ = 1), read from
/// the limbs without MPFR's conversion: `(mantissa, e, inexact)` with mantissa in
/// [2⁵², 2⁵³) and `inexact` when bits beyond the 53rd are set. `None` for 0, ∞ and NaN.
#[cfg(target_pointer_width = "64")]
fn leading_bits(x: &Float) -> Option<(u64, i64, bool)> {
    if !x.is_normal() {
        return None;
    }
    // SAFETY: a normal MPFR number has ⌈prec/64⌉ limbs at `d`, the most significant last
    // (MPFR's documented representation, the one `Float::get_significand` borrows); they are
    // only read, while `x` is borrowed. Reading them directly avoids the borrowed-integer
    // view and its checks: this runs twice per ball product.
    unsafe {
        let raw = &*x.as_raw();
        let count = usize::try_from((raw.prec - 1) / 64 + 1).ok()?;
        let limbs = std::slice::from_raw_parts(raw.d.as_ptr().cast_const(), count);
        let (&top, rest) = limbs.split_last()?;
        let inexact = top & 0x7ff != 0 || rest.iter().any(|&limb| limb != 0);
        // MPFR's exponent type is a C long: i64 here, i32 on some 64-bit targets.
        #[allow(clippy::useless_conversion)]
        let exp = i64::from(raw.exp);
        Some((top >> 11, exp, inexact))
    }
}

/// The double with 53-bit mantissa `mantissa` ∈ [2⁵², 2⁵³] times 2^(e − 53), when it is a
/// normal double (`None` otherwise: the caller falls back to MPFR's conversion).
fn normal_double(mut mantissa: u64, mut e: i64) -> Option<f64> {
    if mantissa == 1 << 53 {
        mantissa >>= 1;
        e += 1;
    }
    // The value lies in [2^(e−1), 2^e): biased exponent e − 1 + 1023.
    let biased = e - 1 + 1023;
    (1..=2046)
        .contains(&biased)
        .then(|| f64::from_bits(((biased as u64) << 52) | (mantissa & ((1 << 52) - 1))))
}

/// An upper bound for |x| as a double: |x| rounded up to 53 bits (exactly what MPFR's
/// `mpfr_get_d` rounding away from zero gives, read from the limbs on 64-bit targets).
fn abs_up(x: &Float) -> f64 {
    #[cfg(target_pointer_width = "64")]
    if let Some(up) =
        leading_bits(x).and_then(|(m, e, inexact)| normal_double(m + u64::from(inexact), e))
    {
        return up;
    }
    let round = if x.is_sign_negative() {
        Round::Down
    } else {
        Round::Up
    };
    x.to_f64_round(round).abs()
}

/// A lower bound for |x| as a double: |x| truncated to 53 bits.
fn abs_down(x: &Float) -> f64 {
    #[cfg(target_pointer_width = "64")]
    if let Some(down) = leading_bits(x).and_then(|(m, e, _)| normal_double(m, e)) {
        return down;
    }
    x.to_f64_round(Round::Zero).abs()
}

/// 2^k as a double: exact from 2⁻¹⁰⁷⁴ to 2¹⁰²³ (built from its bits, no `powi`), the
/// smallest subnormal below (an upper bound), ∞ above.
fn pow2_up(k: i64) -> f64 {
    if k > 1023 {
        f64::INFINITY
    } else if k >= -1022 {
        f64::from_bits(((k + 1023) as u64) << 52)
    } else if k >= -1074 {
        f64::from_bits(1 << (k + 1074))
    } else {
        f64::from_bits(1)
    }
}

/// A bound on the rounding error of `m`, the nearest p-bit value to an exact result:
/// 0 when MPFR reports the operation exact, otherwise one ulp, 2^(e − p).
fn rounding_error(m: &Float, direction: Ordering) -> f64 {
    if direction == Ordering::Equal {
        return 0.0;
    }
    match m.get_exp() {
        None if m.is_zero() => f64::from_bits(1),
        None => f64::INFINITY,
        Some(e) => pow2_up(i64::from(e) - i64::from(m.prec())),
    }
}

impl Ball {
    /// The ball with this midpoint and radius (the radius is made non-negative; NaN becomes ∞).
    pub fn new(mid: Float, rad: f64) -> Ball {
        let rad = if rad.is_nan() {
            f64::INFINITY
        } else {
            rad.abs()
        };
        Ball { mid, rad }
    }

    /// An exact value (radius 0).
    pub fn exact(mid: Float) -> Ball {
        Ball { mid, rad: 0.0 }
    }

    /// A ball from a nearest-rounded midpoint and MPFR's ternary value, with `rad` added.
    fn rounded((mid, direction): (Float, Ordering), rad: f64) -> Ball {
        let err = rounding_error(&mid, direction);
        Ball::new(mid, add_up(rad, err))
    }

    /// The midpoint.
    pub fn mid(&self) -> &Float {
        &self.mid
    }

    /// The radius.
    pub fn rad(&self) -> f64 {
        self.rad
    }

    /// A lower bound of the ball, m − r rounded down, 64 bits beyond the midpoint's precision
    /// (so the bound is not looser than the radius says by a rounding of its own).
    pub fn lower(&self) -> Float {
        Float::with_val_round(
            self.mid.prec() + 64,
            &self.mid - &Float::with_val(64, self.rad),
            Round::Down,
        )
        .0
    }

    /// An upper bound of the ball, m + r rounded up (at the precision of [`Ball::lower`]).
    pub fn upper(&self) -> Float {
        Float::with_val_round(
            self.mid.prec() + 64,
            &self.mid + &Float::with_val(64, self.rad),
            Round::Up,
        )
        .0
    }

    /// The smallest ball (up to rounding outward) containing [lo, hi], its midpoint at the
    /// larger precision of the two bounds.
    pub fn from_bounds(lo: &Float, hi: &Float) -> Ball {
        Ball::from_bounds_at(lo, hi, lo.prec().max(hi.prec()))
    }

    /// A ball containing [lo, hi] with its midpoint at `prec` bits.
    pub fn from_bounds_at(lo: &Float, hi: &Float, prec: u32) -> Ball {
        let mid = Float::with_val(prec + 2, lo + hi) / 2u32;
        let (mid, _) = Float::with_val_round(prec, &mid, Round::Nearest);
        let above = Float::with_val_round(53, hi - &mid, Round::Up)
            .0
            .to_f64_round(Round::Up);
        let below = Float::with_val_round(53, &mid - lo, Round::Up)
            .0
            .to_f64_round(Round::Up);
        Ball::new(mid, above.max(below))
    }

    /// The digits the enclosure proves: the largest d such that every point of the ball
    /// rounds to the same d significant decimal digits, with that decimal (0 and "" when
    /// not even the first digit is proven). See [`interval_digits`].
    pub fn proven_digits(&self) -> (u32, String) {
        interval_digits(&self.lower(), &self.upper(), self.mid.prec())
    }

    /// The ball as it is printed: a decimal `value` and a decimal `radius` with every point
    /// of the ball inside [value − radius, value + radius] **as printed** (`None` for a ball
    /// that is not finite).
    ///
    /// `value` carries the [`Ball::proven_digits`] (the digits every point of the ball rounds
    /// to); when not even the first digit is proven, it is the midpoint to two significant
    /// digits. Because `value` is rounded, the radius is measured from it, not from the
    /// unprinted midpoint: it bounds |value − mid| + rad, computed exactly in rationals and
    /// rounded *up* to two significant digits. It is "0" only when the ball is exact and
    /// `value` is its midpoint written out in full.
    pub fn printed(&self) -> Option<PrintedBall> {
        if !self.mid.is_finite() || !self.rad.is_finite() {
            return None;
        }
        let mid = self.mid.to_rational()?;
        let rad = rug::Rational::from_f64(self.rad)?;
        printed_around(self.proven_digits(), &self.mid, |printed| {
            rug::Rational::from(printed - &mid).abs() + &rad
        })
    }

    /// An upper bound of |x| over the ball, as a double rounded up (∞ beyond its range).
    pub fn abs_upper(&self) -> f64 {
        add_up(abs_up(&self.mid), self.rad)
    }

    /// The ball with `extra` (≥ 0) added to its radius, rounded up: an enclosure of every
    /// point within `extra` of this ball (a remainder bound added to a Taylor model).
    pub fn widen(self, extra: f64) -> Ball {
        let rad = add_up(self.rad, extra.abs());
        Ball::new(self.mid, rad)
    }

    /// Whether x lies in the ball (for tests of the inclusion principle).
    pub fn contains(&self, x: &Float) -> bool {
        *x >= self.lower() && *x <= self.upper()
    }

    /// |m_a|·r_b + |m_b|·r_a + r_a·r_b rounded to nearest (five roundings, for [`bound`]),
    /// and whether any of its exact terms is positive. |m| is read only for a positive
    /// radius of the other operand (an exact operand's midpoint needs no bound).
    fn product_terms(a: &Ball, b: &Ball) -> (f64, bool) {
        let mut sum = 0.0;
        let mut positive = false;
        if b.rad != 0.0 {
            let m = abs_up(&a.mid);
            sum += times(m, b.rad);
            positive |= m != 0.0;
        }
        if a.rad != 0.0 {
            let m = abs_up(&b.mid);
            sum += times(m, a.rad) + times(a.rad, b.rad);
            positive |= m != 0.0 || b.rad != 0.0;
        }
        (sum, positive)
    }

    /// Whether the ball contains zero (and is not exactly zero).
    fn straddles_zero(&self) -> bool {
        abs_down(&self.mid) <= self.rad && !(self.rad == 0.0 && self.mid.is_zero())
    }
}

impl PartialEq for Ball {
    /// Equal only when both are exact and the same number; two overlapping balls are an
    /// undecided comparison (counted) and answer false.
    fn eq(&self, other: &Ball) -> bool {
        if self.rad == 0.0 && other.rad == 0.0 {
            return self.mid == other.mid;
        }
        if self.partial_cmp_quiet(other).is_none() {
            undecided();
        }
        false
    }
}

impl Ball {
    /// `Some(Less)` / `Some(Greater)` when the balls are disjoint, `Some(Equal)` when both are
    /// the same exact number, `None` otherwise — without counting.
    fn partial_cmp_quiet(&self, other: &Ball) -> Option<Ordering> {
        if self.rad == 0.0 && other.rad == 0.0 {
            return self.mid.partial_cmp(&other.mid);
        }
        let prec = self.mid.prec().max(other.mid.prec()) + 2;
        let gap = Float::with_val(64, add_up(self.rad, other.rad));
        let below = Float::with_val_round(prec, &other.mid - &self.mid, Round::Down).0;
        if below > gap {
            return Some(Ordering::Less);
        }
        let above = Float::with_val_round(prec, &self.mid - &other.mid, Round::Down).0;
        if above > gap {
            return Some(Ordering::Greater);
        }
        None
    }
}

impl PartialOrd for Ball {
    fn partial_cmp(&self, other: &Ball) -> Option<Ordering> {
        let decided = self.partial_cmp_quiet(other);
        if decided.is_none() {
            undecided();
        }
        decided
    }
}

impl Neg for Ball {
    type Output = Ball;
    fn neg(self) -> Ball {
        Ball::new(-self.mid, self.rad)
    }
}

impl Ball {
    /// Set the radius after an operation computed the midpoint in place: `terms` (rounded to
    /// nearest, positive exactly when `positive`) plus the rounding error of the midpoint
    /// (MPFR's ternary value `direction`), bounded from above once ([`bound`]).
    fn set_rounded(&mut self, direction: Ordering, (terms, positive): (f64, bool)) {
        let err = rounding_error(&self.mid, direction);
        self.rad = bound(terms + err, positive || err != 0.0);
    }

    /// `self ← self·mul + add` with one rounding of the midpoint (MPFR's fma), in place: the
    /// Horner step. The radius is that of the product plus `add`'s, plus one rounding.
    pub fn mul_add_mut(&mut self, mul: &Ball, add: &Ball) {
        let (product, positive) = Ball::product_terms(self, mul);
        let terms = (product + add.rad, positive || add.rad != 0.0);
        let direction = self.mid.mul_add_round(&mul.mid, &add.mid, Round::Nearest);
        self.set_rounded(direction, terms);
    }

    /// The radius terms of a sum or difference: r_a + r_b.
    fn sum_terms(a: &Ball, b: &Ball) -> (f64, bool) {
        (a.rad + b.rad, a.rad != 0.0 || b.rad != 0.0)
    }

    /// The radius terms of self ± a·b: r_self + (the product's terms).
    fn fused_terms(&self, a: &Ball, b: &Ball) -> (f64, bool) {
        let (product, positive) = Ball::product_terms(a, b);
        (self.rad + product, positive || self.rad != 0.0)
    }
}

// The arithmetic works on the midpoint in place (MPFR's `*_assign_round`, which returns the
// ternary value), so an operation allocates nothing: the by-value operators reuse the left
// operand's midpoint.
impl AddAssign<&Ball> for Ball {
    fn add_assign(&mut self, b: &Ball) {
        let terms = Ball::sum_terms(self, b);
        let direction = self.mid.add_assign_round(&b.mid, Round::Nearest);
        self.set_rounded(direction, terms);
    }
}

impl SubAssign<&Ball> for Ball {
    fn sub_assign(&mut self, b: &Ball) {
        let terms = Ball::sum_terms(self, b);
        let direction = self.mid.sub_assign_round(&b.mid, Round::Nearest);
        self.set_rounded(direction, terms);
    }
}

impl MulAssign<&Ball> for Ball {
    fn mul_assign(&mut self, b: &Ball) {
        let terms = Ball::product_terms(self, b);
        let direction = self.mid.mul_assign_round(&b.mid, Round::Nearest);
        self.set_rounded(direction, terms);
    }
}

impl DivAssign<&Ball> for Ball {
    fn div_assign(&mut self, b: &Ball) {
        let denominator = down(abs_down(&b.mid) - b.rad);
        if b.mid.is_zero() || denominator <= 0.0 {
            // The divisor may be zero: the quotient is unbounded.
            self.mid.assign(0);
            self.rad = f64::INFINITY;
            return;
        }
        let numerator_rad = self.rad;
        let direction = self.mid.div_assign_round(&b.mid, Round::Nearest);
        let err = rounding_error(&self.mid, direction);
        let quotient = add_up(abs_up(&self.mid), err);
        let rad = div_up(add_up(numerator_rad, mul_up(quotient, b.rad)), denominator);
        self.rad = add_up(rad, err);
        if self.rad.is_nan() {
            self.rad = f64::INFINITY;
        }
    }
}

by_value_from_assign!(Ball);

impl Field for Ball {
    type Ctx = u32;
    const ENCLOSURE: bool = true;

    fn ctx(&self) -> u32 {
        self.mid.prec()
    }
    fn scalar_name(bits: &u32) -> String {
        format!("ball:{bits}")
    }
    fn from_i64(v: i64, bits: &u32) -> Self {
        Ball::rounded(
            Float::with_val_round(precision(*bits), v, Round::Nearest),
            0.0,
        )
    }
    fn from_ratio(n: i64, d: i64, bits: &u32) -> Self {
        if d == 0 {
            // No number: the ball of every number, as for NaN.
            return Ball::new(Float::with_val(precision(*bits), 0), f64::INFINITY);
        }
        Ball::rounded(super::mpfr::ratio_rounded(n, d, precision(*bits)), 0.0)
    }
    fn from_rational(q: &BigRational, bits: &u32) -> Self {
        Self::from_exact(&super::mpfr::to_gmp_rational(q), bits)
    }
    fn from_exact(q: &rug::Rational, bits: &u32) -> Self {
        Ball::rounded(
            Float::with_val_round(precision(*bits), q, Round::Nearest),
            0.0,
        )
    }
    fn from_f64(v: f64, bits: &u32) -> Self {
        // NaN is no number: the ball of every number (not an exact ball around NaN), which
        // `is_finite` reports.
        if v.is_nan() {
            return Ball::new(Float::with_val(precision(*bits), 0), f64::INFINITY);
        }
        Ball::rounded(
            Float::with_val_round(precision(*bits), v, Round::Nearest),
            0.0,
        )
    }
    fn mul_add_assign(&mut self, a: &Self, b: &Self) {
        // self + a·b with one rounding (mpfr_fma), in place.
        let terms = self.fused_terms(a, b);
        let direction = self.mid.add_assign_round(&a.mid * &b.mid, Round::Nearest);
        self.set_rounded(direction, terms);
    }
    fn horner_step(&mut self, x: &Self, c: &Self) {
        if self.mid.prec() == c.mid.prec() {
            // c.rad + product is the same f64 sum as product + c.rad: bit for bit the
            // default's c.mul_add_assign(self, x).
            self.mul_add_mut(x, c);
        } else {
            super::horner_step_into_copy(self, x, c);
        }
    }
    fn mul_sub_assign(&mut self, a: &Self, b: &Self) {
        let terms = self.fused_terms(a, b);
        let direction = self.mid.sub_assign_round(&a.mid * &b.mid, Round::Nearest);
        self.set_rounded(direction, terms);
    }
    fn abs(&self) -> Self {
        // ||x| − |m|| ≤ |x − m|: the same radius encloses every |x|.
        Ball::new(self.mid.clone().abs(), self.rad)
    }
    fn is_zero(&self) -> bool {
        self.rad == 0.0 && self.mid.is_zero()
    }
    fn is_finite(&self) -> bool {
        self.mid.is_finite() && self.rad.is_finite()
    }
    fn magnitude_bounds(&self) -> (f64, f64) {
        let (lo, hi) = (self.lower(), self.upper());
        let lower = if lo > 0 {
            lo.to_f64_round(Round::Down)
        } else if hi < 0 {
            (-hi).to_f64_round(Round::Down)
        } else {
            0.0
        };
        (lower, self.abs_upper())
    }
    fn to_f64(&self) -> f64 {
        self.mid.to_f64()
    }
    /// The midpoint as a fraction (the ball's other points are not represented).
    fn to_rational(&self) -> Option<BigRational> {
        self.mid
            .to_rational()
            .map(|q| super::mpfr::from_gmp_rational(&q))
    }
    fn to_exact(&self) -> Option<rug::Rational> {
        self.mid.to_rational()
    }
    fn to_plain_string(&self) -> String {
        format!("{} ± {:e}", self.mid.to_plain_string(), self.rad)
    }
    fn decide_lt(&self, other: &Self) -> Option<bool> {
        self.partial_cmp_quiet(other).map(|o| o == Ordering::Less)
    }
    fn hull(lo: &Self, hi: &Self) -> Self {
        let lower = lo.lower().min(&hi.lower());
        let upper = lo.upper().max(&hi.upper());
        Ball::from_bounds_at(&lower, &upper, lo.mid.prec())
    }
    fn min_with(&self, other: &Self) -> Self {
        if self.rad == 0.0 && other.rad == 0.0 {
            return if other.mid < self.mid {
                other.clone()
            } else {
                self.clone()
            };
        }
        let lower = self.lower().min(&other.lower());
        let upper = self.upper().min(&other.upper());
        Ball::from_bounds_at(&lower, &upper, self.mid.prec())
    }
    fn max_with(&self, other: &Self) -> Self {
        if self.rad == 0.0 && other.rad == 0.0 {
            return if other.mid > self.mid {
                other.clone()
            } else {
                self.clone()
            };
        }
        let lower = self.lower().max(&other.lower());
        let upper = self.upper().max(&other.upper());
        Ball::from_bounds_at(&lower, &upper, self.mid.prec())
    }
}

impl Real for Ball {
    fn sqrt(&self) -> Self {
        let prec = self.mid.prec();
        if self.mid.is_sign_negative() && !self.straddles_zero() {
            return Ball::new(Float::with_val(prec, 0), f64::INFINITY);
        }
        let lowest = down(self.mid.to_f64_round(Round::Down) - self.rad);
        if lowest <= 0.0 {
            // [0, √(m + r)]: half of it around its midpoint.
            let top = Float::with_val_round(prec, self.upper().sqrt_ref(), Round::Up).0;
            return Ball::from_bounds(&Float::with_val(prec, 0), &top);
        }
        let (mid, direction) = Float::with_val_round(prec, self.mid.sqrt_ref(), Round::Nearest);
        let denominator = down(down(lowest.sqrt()) + abs_down(&mid));
        Ball::rounded((mid, direction), div_up(self.rad, denominator))
    }
    fn sin_cos(&self) -> (Self, Self) {
        let prec = self.mid.prec();
        let mut sin = Float::with_val(prec, &self.mid);
        let mut cos = Float::new(prec);
        let (ds, dc) = sin.sin_cos_round(&mut cos, Round::Nearest);
        // Both are Lipschitz with constant 1: the radius carries over.
        (
            Ball::rounded((sin, ds), self.rad),
            Ball::rounded((cos, dc), self.rad),
        )
    }
    fn sin(&self) -> Self {
        let mid = Float::with_val_round(self.mid.prec(), self.mid.sin_ref(), Round::Nearest);
        Ball::rounded(mid, self.rad)
    }
    fn cos(&self) -> Self {
        let mid = Float::with_val_round(self.mid.prec(), self.mid.cos_ref(), Round::Nearest);
        Ball::rounded(mid, self.rad)
    }
    fn atan2(&self, x: &Self) -> Self {
        let prec = self.mid.prec();
        // Distance from the origin of the nearest point of the box.
        let gap = |b: &Ball| down(abs_down(&b.mid) - b.rad).max(0.0);
        let (gx, gy) = (gap(x), gap(self));
        let rho = down(down(gx * gx + gy * gy).sqrt());
        let crosses_cut = x.mid.is_sign_negative() && gy == 0.0;
        if rho <= 0.0 || crosses_cut {
            return Ball::new(Float::with_val(prec, 0), f64::INFINITY);
        }
        // On the positive x axis the angle is exactly 0, whatever the ball of x: keep the
        // exact zero (a straight Dubins leg, an arc of length 0, stays exactly straight).
        if Field::is_zero(self) && gx > 0.0 {
            return Ball::exact(Float::with_val(prec, 0));
        }
        let mid = Float::with_val_round(prec, self.mid.atan2_ref(&x.mid), Round::Nearest);
        Ball::rounded(mid, div_up(add_up(x.rad, self.rad), rho))
    }
    fn exp(&self) -> Self {
        let prec = self.mid.prec();
        let (mid, direction) = Float::with_val_round(prec, self.mid.exp_ref(), Round::Nearest);
        // e^r − 1 from libm (not correctly rounded), widened by a few ulps.
        let growth = if self.rad == 0.0 {
            0.0
        } else {
            mul_up(up(self.rad.exp_m1()), 1.0 + 8.0 * f64::EPSILON)
        };
        let err = rounding_error(&mid, direction);
        let rad = mul_up(add_up(abs_up(&mid), err), growth);
        Ball::new(mid, add_up(rad, err))
    }
    fn ln(&self) -> Self {
        let prec = self.mid.prec();
        let lowest = down(self.mid.to_f64_round(Round::Down) - self.rad);
        if lowest <= 0.0 {
            return Ball::new(Float::with_val(prec, 0), f64::INFINITY);
        }
        let mid = Float::with_val_round(prec, self.mid.ln_ref(), Round::Nearest);
        Ball::rounded(mid, div_up(self.rad, lowest))
    }
    fn pi(bits: &u32) -> Self {
        Ball::rounded(
            Float::with_val_round(precision(*bits), Constant::Pi, Round::Nearest),
            0.0,
        )
    }
    fn epsilon(bits: &u32) -> Self {
        Ball::exact(Float::with_val(precision(*bits), 1) >> (*bits as i32 - 1))
    }
    fn precision_bits(bits: &u32) -> u32 {
        *bits
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The bounds read from the limbs are exactly MPFR's directed conversions, across
    /// precisions, signs, exponents, and the values just below a power of two (where rounding
    /// up carries into the exponent).
    #[test]
    fn limb_bounds_equal_mpfr_directed_conversions() {
        let mut next = crate::scalar::xorshift(0x9e37_79b9_7f4a_7c15);
        for bits in [24, 53, 54, 64, 65, 128, 256, 1000] {
            for _ in 0..2000 {
                let numerator = Float::with_val(bits, next() as i64);
                let shift = (next() % 2400) as i32 - 1200;
                let x = Float::with_val(bits, &numerator << shift) / 3u32;
                let edge = Float::with_val(bits, 1u32 << 20) - Float::with_val(bits, 1) * 1e-12;
                for y in [x.clone(), -x, edge] {
                    let up = if y.is_sign_negative() {
                        -y.to_f64_round(Round::Down)
                    } else {
                        y.to_f64_round(Round::Up)
                    };
                    assert_eq!(abs_up(&y).to_bits(), up.to_bits(), "{y} at {bits} bits");
                    let down = y.to_f64_round(Round::Zero).abs();
                    assert_eq!(abs_down(&y).to_bits(), down.to_bits(), "{y} at {bits} bits");
                }
            }
        }
        // The single radius bound keeps exact zeros exact and tiny radii positive.
        let zero = Ball::from_i64(0, &64);
        let everything = Ball::new(Float::with_val(64, 0), f64::INFINITY);
        assert!((zero.clone() * &everything).is_zero());
        let three = Ball::from_i64(3, &64) * &Ball::from_i64(5, &64);
        assert_eq!(three.rad(), 0.0);
        let tiny = Ball::new(Float::with_val(64, 0), 1e-200);
        assert!(
            (tiny.clone() * &tiny).rad() > 0.0,
            "an underflowed radius became 0"
        );
        let mut fused = Ball::from_i64(1, &64);
        fused.mul_add_assign(&tiny, &tiny);
        assert!(fused.rad() > 0.0 && fused.contains(&Float::with_val(64, 1)));
        for k in -1100..1100 {
            let expected = if k < -1074 {
                f64::from_bits(1)
            } else {
                Float::with_val(64, Float::i_exp(1, k as i32)).to_f64()
            };
            assert_eq!(pow2_up(k), expected, "2^{k}");
        }
    }
}
