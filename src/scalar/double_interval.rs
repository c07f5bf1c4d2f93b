//! Interval arithmetic on doubles: a proven enclosure [lo, hi] of every real number a
//! computation stands for, with both ends f64. It is the cheap first try of a decision
//! procedure whose answer balls would also give (the Dubins planner decides each leg's word
//! in it first and goes to [`super::ball::Ball`]s only when an interval cannot decide,
//! `algo::gerbs::dubins`): an operation costs a few double operations where a ball's costs
//! an MPFR call (`run dubins` on 1999 legs went from 145 to about 20 ms).
//!
//! **Why the ends are proven.** IEEE 754 rounds each `+ − × ÷ √` of doubles to nearest, so
//! the exact result lies within one ulp of the rounded one: the lower end is the rounded
//! result stepped one double down, the upper end one double up (an exact zero operand keeps
//! a result exact, so 0·x and x + 0 stay exact). Products take the two end products that are
//! extreme for the operands' signs, quotients the extremes of the four end quotients. An end that overflows is ±∞, and an interval with an infinite
//! or NaN end is the interval of every number ([`DoubleInterval::ENTIRE`]), which every
//! operation propagates (except that an exact 0 times any number is 0, as for balls): such an
//! interval decides nothing.
//!
//! **The transcendental functions** are evaluated by the library itself, never by libm (whose
//! error is not documented as a bound):
//!
//! | function | method | error term added |
//! |---|---|---|
//! | sin, cos | x − kπ/2 (π/2 enclosed by two doubles), Taylor to degree 17 / 16 on \|t\| ≤ 0.8 | 0.8¹⁹/19! resp. 0.8¹⁸/18! |
//! | atan | q or 1/q in [0, 1], then atan q = atan(k/8) + atan u with u = (q − c)/(1 + cq), \|u\| ≤ 0.07, Taylor to degree 15 | 0.07¹⁷/17 (alternating series) |
//! | atan2(y, x) | atan2 of the box's centre (from atan of y/x by quadrant), plus (r_x + r_y)/ρ_min | the gradient's norm is 1/ρ |
//!
//! The polynomials are evaluated in this interval arithmetic, with their coefficients 1/n!
//! and 1/(2n + 1) enclosed by directed divisions, and atan(k/8) enclosed by MPFR's directed
//! rounding at 53 bits (computed once). Outside the ranges above (sin and cos of \|x\| > 64,
//! a box around the origin or across atan2's branch cut) the result is the function's whole
//! range, which is still an enclosure. `exp` and `ln` are not implemented in intervals: they
//! return [`DoubleInterval::ENTIRE`], so a computation that needs them decides nothing here
//! and goes to balls. The unit tests check every function against MPFR at 256 bits on random
//! and edge inputs.
//!
//! Comparisons are honest and quiet: `a < b` only when the intervals are disjoint, `None`
//! (`partial_cmp`) otherwise; this type does not count undecided comparisons as balls do,
//! because the code that uses it treats every undecided outcome as "ask the balls".

use super::ball::next_double;
use super::{BigRational, Field, Real};
use rug::float::Round;
use rug::Float;
use std::cmp::Ordering;
use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};
use std::sync::OnceLock;

/// A closed interval [lo, hi] of doubles enclosing a real number (see the module doc).
#[derive(Clone, Copy, Debug)]
pub struct DoubleInterval {
    lo: f64,
    hi: f64,
}

/// π/2 rounded down and up to doubles.
const HALF_PI: (f64, f64) = (
    std::f64::consts::FRAC_PI_2,
    // FRAC_PI_2 = 1.5707963267948965580 < π/2 = 1.5707963267948966192: the next double up.
    1.570_796_326_794_896_8,
);
/// π rounded down and up.
const PI: (f64, f64) = (std::f64::consts::PI, 3.141_592_653_589_793_6);
/// A bound of the Taylor remainder of sin t for |t| ≤ 0.8 after degree 17: 0.8¹⁹/19! < 1.2e-19 (taken as 1.3e-19).
const SIN_REMAINDER: f64 = 1.3e-19;
/// The same for cos t after degree 16: 0.8¹⁸/18! < 2.9e-18.
const COS_REMAINDER: f64 = 2.9e-18;
/// The largest |t| the sine and cosine series are used for.
const SERIES_REACH: f64 = 0.8;
/// The largest |u| the arctangent series is used for, and its remainder after degree 15:
/// 0.07¹⁷/17 < 1.4e-21 (taken as 1.5e-21).
const ATAN_REACH: f64 = 0.07;
const ATAN_REMAINDER: f64 = 1.5e-21;

impl DoubleInterval {
    /// The interval of every number: what an overflow, a NaN or an undefined operation gives.
    pub const ENTIRE: DoubleInterval = DoubleInterval {
        lo: f64::NEG_INFINITY,
        hi: f64::INFINITY,
    };

    /// [lo, hi], or [`Self::ENTIRE`] when an end is not finite or lo > hi.
    pub fn new(lo: f64, hi: f64) -> Self {
        if lo.is_finite() && hi.is_finite() && lo <= hi {
            DoubleInterval { lo, hi }
        } else {
            Self::ENTIRE
        }
    }

    /// The single number x (a NaN or infinite x gives [`Self::ENTIRE`]).
    pub fn point(x: f64) -> Self {
        Self::new(x, x)
    }

    /// The lower end.
    pub fn lo(&self) -> f64 {
        self.lo
    }

    /// The upper end.
    pub fn hi(&self) -> f64 {
        self.hi
    }

    /// Whether x lies in the interval.
    pub fn contains(&self, x: f64) -> bool {
        self.lo <= x && x <= self.hi
    }

    fn is_point(&self) -> bool {
        self.lo == self.hi
    }

    fn is_entire(&self) -> bool {
        !self.lo.is_finite()
    }

    /// The interval widened by r ≥ 0 on both sides.
    fn widened(self, r: f64) -> Self {
        if r == 0.0 {
            self
        } else {
            Self::new(step_down(self.lo - r), step_up(self.hi + r))
        }
    }

    /// A point inside the interval and an upper bound of its distance to both ends.
    fn centre(&self) -> (f64, f64) {
        if self.is_point() {
            return (self.lo, 0.0);
        }
        let m = (0.5 * self.lo + 0.5 * self.hi).clamp(self.lo, self.hi);
        (m, step_up((m - self.lo).max(self.hi - m)))
    }

    /// The interval of x², whose lower end is never below 0.
    fn square(&self) -> Self {
        let (small, large) = if self.lo >= 0.0 {
            (self.lo, self.hi)
        } else if self.hi <= 0.0 {
            (-self.hi, -self.lo)
        } else {
            (0.0, self.lo.abs().max(self.hi.abs()))
        };
        let low = if small == 0.0 {
            0.0
        } else {
            step_down(small * small).max(0.0)
        };
        Self::new(
            low,
            if large == 0.0 {
                0.0
            } else {
                step_up(large * large)
            },
        )
    }

    /// c(s) = Σ coefficients[n]·sⁿ by Horner's rule in intervals.
    fn horner(s: &Self, coefficients: &[DoubleInterval]) -> Self {
        let mut acc = coefficients[coefficients.len() - 1];
        for c in coefficients.iter().rev().skip(1) {
            acc = acc * s + c;
        }
        acc
    }
}

/// Where an interval lies: in [0, ∞), in (−∞, 0], or across 0.
#[derive(Clone, Copy)]
enum Sign {
    Up,
    Down,
    Across,
}

impl DoubleInterval {
    fn sign(&self) -> Sign {
        if self.lo >= 0.0 {
            Sign::Up
        } else if self.hi <= 0.0 {
            Sign::Down
        } else {
            Sign::Across
        }
    }
}

/// The next double above x (∞ and NaN stay as they are, and an interval with them is
/// [`DoubleInterval::ENTIRE`]).
fn step_up(x: f64) -> f64 {
    next_double(x)
}

/// The next double below x.
fn step_down(x: f64) -> f64 {
    -next_double(-x)
}

/// The lower and upper rounding of an exact result whose nearest double is x (an exact zero
/// result stays exact: the callers pass `exact` when an operand makes it so).
fn enclose(x: f64) -> DoubleInterval {
    DoubleInterval::new(step_down(x), step_up(x))
}

impl PartialEq for DoubleInterval {
    /// Equal only when both are the same single number.
    fn eq(&self, other: &Self) -> bool {
        self.is_point() && other.is_point() && self.lo == other.lo
    }
}

impl PartialOrd for DoubleInterval {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        if self.hi < other.lo {
            Some(Ordering::Less)
        } else if self.lo > other.hi {
            Some(Ordering::Greater)
        } else if self == other {
            Some(Ordering::Equal)
        } else {
            None
        }
    }
}

impl Neg for DoubleInterval {
    type Output = Self;
    fn neg(self) -> Self {
        DoubleInterval {
            lo: -self.hi,
            hi: -self.lo,
        }
    }
}

impl AddAssign<&DoubleInterval> for DoubleInterval {
    fn add_assign(&mut self, b: &DoubleInterval) {
        *self = if b.is_zero() {
            *self
        } else if self.is_zero() {
            *b
        } else if self.is_entire() || b.is_entire() {
            Self::ENTIRE
        } else {
            Self::new(step_down(self.lo + b.lo), step_up(self.hi + b.hi))
        };
    }
}

impl SubAssign<&DoubleInterval> for DoubleInterval {
    fn sub_assign(&mut self, b: &DoubleInterval) {
        *self += &-*b;
    }
}

impl MulAssign<&DoubleInterval> for DoubleInterval {
    fn mul_assign(&mut self, b: &DoubleInterval) {
        let a = *self;
        *self = if a.is_zero() || b.is_zero() {
            Field::zero_in(&())
        } else if a.is_entire() || b.is_entire() {
            Self::ENTIRE
        } else {
            // The two end products that are the extremes, by the signs of the operands
            // (both ends ≥ 0, both ≤ 0, or across 0).
            let (lo, hi) = match (a.sign(), b.sign()) {
                (Sign::Up, Sign::Up) => (a.lo * b.lo, a.hi * b.hi),
                (Sign::Up, Sign::Down) => (a.hi * b.lo, a.lo * b.hi),
                (Sign::Down, Sign::Up) => (a.lo * b.hi, a.hi * b.lo),
                (Sign::Down, Sign::Down) => (a.hi * b.hi, a.lo * b.lo),
                (Sign::Up, Sign::Across) => (a.hi * b.lo, a.hi * b.hi),
                (Sign::Down, Sign::Across) => (a.lo * b.hi, a.lo * b.lo),
                (Sign::Across, Sign::Up) => (a.lo * b.hi, a.hi * b.hi),
                (Sign::Across, Sign::Down) => (a.hi * b.lo, a.lo * b.lo),
                (Sign::Across, Sign::Across) => (
                    (a.lo * b.hi).min(a.hi * b.lo),
                    (a.lo * b.lo).max(a.hi * b.hi),
                ),
            };
            Self::new(step_down(lo), step_up(hi))
        };
    }
}

impl DivAssign<&DoubleInterval> for DoubleInterval {
    fn div_assign(&mut self, b: &DoubleInterval) {
        let a = *self;
        *self = if a.is_entire() || b.is_entire() || b.contains(0.0) {
            // A divisor that may be zero: the quotient is unbounded.
            Self::ENTIRE
        } else if a.is_zero() {
            a
        } else if b.is_point() && a.is_point() {
            enclose(a.lo / b.lo)
        } else {
            let q = [a.lo / b.lo, a.lo / b.hi, a.hi / b.lo, a.hi / b.hi];
            let lo = q.iter().copied().fold(f64::INFINITY, f64::min);
            let hi = q.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            Self::new(step_down(lo), step_up(hi))
        };
    }
}

by_value_from_assign!(DoubleInterval);

/// 2⁵³: integers up to it in magnitude are doubles exactly.
const EXACT_INTEGERS: u64 = 1 << 53;

impl Field for DoubleInterval {
    type Ctx = ();
    const ENCLOSURE: bool = true;

    fn ctx(&self) {}
    fn scalar_name(_: &()) -> String {
        "interval:f64".into()
    }
    fn from_i64(v: i64, _: &()) -> Self {
        // Decided on v itself: 2⁵³ + 1 converts to 2⁵³, which would pass a test on the double.
        if v.unsigned_abs() <= EXACT_INTEGERS {
            Self::point(v as f64)
        } else {
            enclose(v as f64)
        }
    }
    fn from_ratio(n: i64, d: i64, ctx: &()) -> Self {
        Self::from_i64(n, ctx) / Self::from_i64(d, ctx)
    }
    fn from_rational(q: &BigRational, ctx: &()) -> Self {
        Self::from_exact(&super::mpfr::to_gmp_rational(q), ctx)
    }
    fn from_exact(q: &rug::Rational, _: &()) -> Self {
        // GMP's conversion truncates: the exact value lies strictly between the doubles
        // either side of it, unless it is an integer a double holds exactly.
        let x = q.to_f64();
        if *q.denom() == 1 && q.numer().significant_bits() <= 53 {
            Self::point(x)
        } else {
            enclose(x)
        }
    }
    fn from_f64(v: f64, _: &()) -> Self {
        Self::point(v)
    }
    fn abs(&self) -> Self {
        if self.lo >= 0.0 {
            *self
        } else if self.hi <= 0.0 {
            -*self
        } else {
            Self::new(0.0, (-self.lo).max(self.hi))
        }
    }
    fn is_zero(&self) -> bool {
        self.lo == 0.0 && self.hi == 0.0
    }
    fn is_finite(&self) -> bool {
        !self.is_entire()
    }
    fn to_f64(&self) -> f64 {
        if self.is_entire() {
            f64::NAN
        } else {
            self.centre().0
        }
    }
    /// The centre as a fraction (the interval's other points are not represented).
    fn to_rational(&self) -> Option<BigRational> {
        self.to_f64().to_rational()
    }
    fn to_plain_string(&self) -> String {
        format!("[{}, {}]", self.lo, self.hi)
    }
    fn decide_lt(&self, other: &Self) -> Option<bool> {
        self.partial_cmp(other).map(|o| o == Ordering::Less)
    }
    fn hull(lo: &Self, hi: &Self) -> Self {
        Self::new(lo.lo.min(hi.lo), lo.hi.max(hi.hi))
    }
    fn min_with(&self, other: &Self) -> Self {
        Self::new(self.lo.min(other.lo), self.hi.min(other.hi))
    }
    fn max_with(&self, other: &Self) -> Self {
        Self::new(self.lo.max(other.lo), self.hi.max(other.hi))
    }
    fn magnitude_bounds(&self) -> (f64, f64) {
        let a = self.abs();
        (a.lo, a.hi)
    }
}

/// The coefficients the series need, each enclosed once: (−1)ⁿ/(2n + 1)! and (−1)ⁿ/(2n)! for
/// sin and cos, (−1)ⁿ/(2n + 1) for atan, and atan(k/8) for k = 0..=8.
struct Tables {
    sin: [DoubleInterval; 9],
    cos: [DoubleInterval; 9],
    atan: [DoubleInterval; 8],
    atan_eighths: [DoubleInterval; 9],
}

fn tables() -> &'static Tables {
    static TABLES: OnceLock<Tables> = OnceLock::new();
    TABLES.get_or_init(|| {
        let signed = |n: usize, d: i64| {
            let c = DoubleInterval::from_ratio(1, d, &());
            if n % 2 == 0 {
                c
            } else {
                -c
            }
        };
        // (2n + 1)! and (2n)! for n ≤ 8 are below 2⁵³: exact doubles.
        let factorial = |m: i64| (1..=m).product::<i64>();
        let atan_of_eighth = |k: usize| {
            let bound = |round| {
                let mut x = Float::with_val(53, k as f64 / 8.0);
                x.atan_round(round);
                x.to_f64()
            };
            DoubleInterval::new(bound(Round::Down), bound(Round::Up))
        };
        Tables {
            sin: std::array::from_fn(|n| signed(n, factorial(2 * n as i64 + 1))),
            cos: std::array::from_fn(|n| signed(n, factorial(2 * n as i64))),
            atan: std::array::from_fn(|n| signed(n, 2 * n as i64 + 1)),
            atan_eighths: std::array::from_fn(atan_of_eighth),
        }
    })
}

/// (sin t, cos t) for |t| ≤ [`SERIES_REACH`].
fn sin_cos_series(t: &DoubleInterval) -> (DoubleInterval, DoubleInterval) {
    if t.is_zero() {
        return (*t, Field::one_in(&()));
    }
    let tables = tables();
    let s = t.square();
    let sin = (*t * DoubleInterval::horner(&s, &tables.sin)).widened(SIN_REMAINDER);
    let cos = DoubleInterval::horner(&s, &tables.cos).widened(COS_REMAINDER);
    (sin, cos)
}

/// (sin x, cos x) for a single double x with |x| ≤ 64, enclosed.
fn sin_cos_point(x: f64) -> (DoubleInterval, DoubleInterval) {
    let k = (x / HALF_PI.0).round();
    let half_pi = DoubleInterval::new(HALF_PI.0, HALF_PI.1);
    let t = DoubleInterval::point(x) - (DoubleInterval::point(k) * half_pi);
    if t.lo < -SERIES_REACH || t.hi > SERIES_REACH {
        let whole = DoubleInterval::new(-1.0, 1.0);
        return (whole, whole);
    }
    let (s, c) = sin_cos_series(&t);
    // sin(t + kπ/2), cos(t + kπ/2) by the quadrant k mod 4.
    match (k as i64).rem_euclid(4) {
        0 => (s, c),
        1 => (c, -s),
        2 => (-s, -c),
        _ => (-c, s),
    }
}

/// atan q for an interval q whose centre lies in [0, 1] and whose points are > −1/8.
fn atan_reduced(q: &DoubleInterval) -> DoubleInterval {
    let tables = tables();
    let k = (q.centre().0 * 8.0).round().clamp(0.0, 8.0);
    let c = DoubleInterval::point(k / 8.0);
    let one = DoubleInterval::point(1.0);
    // atan q = atan c + atan((q − c)/(1 + cq)), valid while 1 + cq > 0.
    let u = (*q - c) / (one + (c * q));
    if u.lo < -ATAN_REACH || u.hi > ATAN_REACH {
        return half_turn_range();
    }
    let series = (u * DoubleInterval::horner(&u.square(), &tables.atan)).widened(ATAN_REMAINDER);
    tables.atan_eighths[k as usize] + series
}

/// (−π/2, π/2) enclosed: atan's whole range.
fn half_turn_range() -> DoubleInterval {
    DoubleInterval::new(-HALF_PI.1, HALF_PI.1)
}

/// atan q for an interval q, enclosed.
fn atan(q: &DoubleInterval) -> DoubleInterval {
    if q.is_entire() {
        return half_turn_range();
    }
    if q.is_zero() {
        return *q;
    }
    let centre = q.centre().0;
    if centre < 0.0 {
        return -atan(&-*q);
    }
    if centre <= 1.0 {
        return atan_reduced(q);
    }
    if q.lo <= 0.0 {
        return half_turn_range();
    }
    // atan q = π/2 − atan(1/q) for q > 0.
    let reciprocal = DoubleInterval::point(1.0) / q;
    DoubleInterval::new(HALF_PI.0, HALF_PI.1) - atan_reduced(&reciprocal)
}

/// atan2(y, x) at a single point other than the origin, enclosed.
fn atan2_point(y: f64, x: f64) -> DoubleInterval {
    let pi = DoubleInterval::new(PI.0, PI.1);
    let half_pi = DoubleInterval::new(HALF_PI.0, HALF_PI.1);
    if x == 0.0 {
        return if y > 0.0 { half_pi } else { -half_pi };
    }
    let q = DoubleInterval::point(y) / DoubleInterval::point(x);
    let angle = atan(&q);
    if x > 0.0 {
        angle
    } else if y >= 0.0 {
        angle + pi
    } else {
        angle - pi
    }
}

impl Real for DoubleInterval {
    fn sqrt(&self) -> Self {
        if self.is_entire() || self.hi < 0.0 {
            return Self::ENTIRE;
        }
        let root = |x: f64| x.sqrt();
        let lo = if self.lo <= 0.0 {
            0.0
        } else {
            step_down(root(self.lo)).max(0.0)
        };
        let hi = if self.hi == 0.0 {
            0.0
        } else {
            step_up(root(self.hi))
        };
        Self::new(lo, hi)
    }
    fn sin_cos(&self) -> (Self, Self) {
        let whole = DoubleInterval::new(-1.0, 1.0);
        if self.is_entire() || self.lo < -64.0 || self.hi > 64.0 {
            return (whole, whole);
        }
        let (x, r) = self.centre();
        let (s, c) = sin_cos_point(x);
        // Both are Lipschitz with constant 1: the distance to the centre carries over.
        let clamp = |v: DoubleInterval| Self::new(v.lo.max(-1.0), v.hi.min(1.0));
        (clamp(s.widened(r)), clamp(c.widened(r)))
    }
    fn atan2(&self, x: &Self) -> Self {
        let y = self;
        let whole = DoubleInterval::new(-PI.1, PI.1);
        if y.is_entire() || x.is_entire() {
            return whole;
        }
        // On the positive x axis the angle is exactly 0 (as for balls).
        if y.is_zero() && x.lo > 0.0 {
            return *y;
        }
        // Distance from the origin of the nearest point of the box.
        let gap = |v: &DoubleInterval| {
            if v.lo > 0.0 {
                v.lo
            } else if v.hi < 0.0 {
                -v.hi
            } else {
                0.0
            }
        };
        // ρ_min² from below; a gap of 0 stays 0 (stepping 0 down would make it negative).
        let square_down = |g: f64| {
            if g == 0.0 {
                0.0
            } else {
                step_down(g * g).max(0.0)
            }
        };
        let (gx, gy) = (square_down(gap(x)), square_down(gap(y)));
        let rho_squared = if gx == 0.0 || gy == 0.0 {
            gx + gy
        } else {
            step_down(gx + gy).max(0.0)
        };
        let rho = step_down(rho_squared.sqrt()).max(0.0);
        let crosses_cut = x.lo < 0.0 && y.contains(0.0);
        // A box that may hold the origin (ρ_min = 0, or NaN from an overflow) has no angle.
        if rho.is_nan() || rho <= 0.0 || crosses_cut {
            return whole;
        }
        let ((cx, rx), (cy, ry)) = (x.centre(), y.centre());
        let spread = if rx == 0.0 && ry == 0.0 {
            0.0
        } else {
            step_up(step_up(rx + ry) / rho)
        };
        atan2_point(cy, cx).widened(spread)
    }
    /// Not implemented in intervals: every number (a caller then decides nothing here).
    fn exp(&self) -> Self {
        Self::ENTIRE
    }
    /// Not implemented in intervals: every number.
    fn ln(&self) -> Self {
        Self::ENTIRE
    }
    fn pi(_: &()) -> Self {
        DoubleInterval::new(PI.0, PI.1)
    }
    fn epsilon(_: &()) -> Self {
        Self::point(f64::EPSILON)
    }
    fn precision_bits(_: &()) -> u32 {
        53
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 256-bit value of x as an MPFR float.
    fn wide(x: f64) -> Float {
        Float::with_val(256, x)
    }

    fn encloses(i: &DoubleInterval, exact: &Float) -> bool {
        *exact >= i.lo && *exact <= i.hi
    }

    /// A reproducible stream of doubles spread over several scales and signs.
    fn samples(count: usize) -> Vec<f64> {
        let mut next = crate::scalar::xorshift(0x2545_f491_4f6c_dd1d);
        (0..count)
            .map(|_| {
                let unit = (next() >> 11) as f64 / (1u64 << 53) as f64;
                let scale = [1e-12, 1e-3, 0.5, 1.0, 3.0, 20.0, 1e3][(next() % 7) as usize];
                let sign = if next() % 2 == 0 { 1.0 } else { -1.0 };
                sign * unit * scale
            })
            .collect()
    }

    #[test]
    fn arithmetic_encloses_the_exact_results() {
        let xs = samples(400);
        for pair in xs.windows(2) {
            let (a, b) = (pair[0], pair[1]);
            let (ia, ib) = (DoubleInterval::point(a), DoubleInterval::point(b));
            let (wa, wb) = (wide(a), wide(b));
            assert!(encloses(&(ia + ib), &(wa.clone() + &wb)), "{a} + {b}");
            assert!(encloses(&(ia - ib), &(wa.clone() - &wb)), "{a} - {b}");
            assert!(encloses(&(ia * ib), &(wa.clone() * &wb)), "{a} * {b}");
            assert!(encloses(&(ia / ib), &(wa.clone() / &wb)), "{a} / {b}");
            let root = DoubleInterval::point(a.abs()).sqrt();
            assert!(encloses(&root, &wa.clone().abs().sqrt()), "sqrt {a}");
            // An interval operand: the result holds the result at the interval's ends.
            let wider = DoubleInterval::new(a.min(b), a.max(b));
            let product = wider * ib;
            assert!(
                encloses(&product, &(wa.clone() * &wb)) && encloses(&product, &(wb.clone() * &wb))
            );
        }
        // Integers beyond 2⁵³ are enclosed, not taken as the double they round to.
        let beyond = (1i64 << 53) + 1;
        let exact_beyond = Float::with_val(256, beyond);
        assert!(encloses(
            &DoubleInterval::from_i64(beyond, &()),
            &exact_beyond
        ));
        let rational = rug::Rational::from(beyond);
        assert!(encloses(
            &DoubleInterval::from_exact(&rational, &()),
            &exact_beyond
        ));
        assert!(DoubleInterval::from_i64(1 << 53, &()).is_point());
        let zero = DoubleInterval::point(0.0);
        assert!((zero * DoubleInterval::point(3.0)).is_zero());
        assert!((zero + zero).is_zero());
        assert!((DoubleInterval::point(1.0) / DoubleInterval::new(-1.0, 1.0)).is_entire());
    }

    #[test]
    fn sin_cos_and_atan2_enclose_mpfr_at_256_bits() {
        let xs = samples(2000);
        for pair in xs.windows(2) {
            let (a, b) = (pair[0], pair[1]);
            if a.abs() <= 64.0 {
                let (s, c) = DoubleInterval::point(a).sin_cos();
                let (ws, wc) = wide(a).sin_cos(Float::new(256));
                assert!(
                    encloses(&s, &ws) && encloses(&c, &wc),
                    "sin_cos {a}: {s:?} {c:?}"
                );
                assert!(s.hi - s.lo < 1e-13, "sin {a} is too wide: {s:?}");
            }
            if a != 0.0 || b != 0.0 {
                let angle = DoubleInterval::point(a).atan2(&DoubleInterval::point(b));
                let exact = wide(a).atan2(&wide(b));
                assert!(
                    encloses(&angle, &exact),
                    "atan2({a}, {b}): {angle:?} vs {exact}"
                );
                assert!(
                    angle.hi - angle.lo < 1e-13,
                    "atan2({a}, {b}) is too wide: {angle:?}"
                );
            }
        }
        // The axes, the diagonals, the quadrant edges of the reduction and the branch cut.
        let edges = [
            0.0, 1.0, -1.0, 0.125, 0.9375, 1.0625, 8.0, -8.0, 1e-300, 1e300,
        ];
        for &y in &edges {
            for &x in &edges {
                if x == 0.0 && y == 0.0 {
                    continue;
                }
                let angle = DoubleInterval::point(y).atan2(&DoubleInterval::point(x));
                assert!(
                    encloses(&angle, &wide(y).atan2(&wide(x))),
                    "atan2({y}, {x})"
                );
            }
        }
        for k in -40..=40 {
            let x = k as f64 * std::f64::consts::FRAC_PI_4;
            let (s, c) = DoubleInterval::point(x).sin_cos();
            let (ws, wc) = wide(x).sin_cos(Float::new(256));
            assert!(encloses(&s, &ws) && encloses(&c, &wc), "sin_cos({x})");
        }
        // Boxes: every corner's angle lies in the box's.
        let y = DoubleInterval::new(0.3, 0.3000001);
        let x = DoubleInterval::new(-2.0, -1.9999);
        let angle = y.atan2(&x);
        for (cy, cx) in [(0.3, -2.0), (0.3000001, -1.9999), (0.3, -1.9999)] {
            assert!(encloses(&angle, &wide(cy).atan2(&wide(cx))));
        }
        // At or around the origin: the whole range (a point box at the origin once gave −π/2:
        // its ρ_min was NaN, which no comparison with 0 caught).
        let origin = DoubleInterval::point(0.0);
        let at_origin = origin.atan2(&origin);
        assert!(at_origin.lo <= -std::f64::consts::PI && at_origin.hi >= std::f64::consts::PI);
        let around = DoubleInterval::new(-1.0, 1.0).atan2(&DoubleInterval::new(-1.0, 1.0));
        assert!(around.lo <= -std::f64::consts::PI && around.hi >= std::f64::consts::PI);
        // Across the branch cut: the whole range, not a guess.
        let across = DoubleInterval::new(-1e-9, 1e-9).atan2(&DoubleInterval::point(-1.0));
        assert!(across.lo <= -std::f64::consts::PI && across.hi >= std::f64::consts::PI);
    }

    #[test]
    fn the_tables_are_enclosures() {
        let t = tables();
        for k in 0..=8 {
            let exact = Float::with_val(256, k) / 8u32;
            assert!(encloses(&t.atan_eighths[k], &exact.atan()), "atan({k}/8)");
        }
        assert!(encloses(
            &DoubleInterval::pi(&()),
            &Float::with_val(256, rug::float::Constant::Pi)
        ));
        let half = Float::with_val(256, rug::float::Constant::Pi) / 2u32;
        assert!(encloses(&DoubleInterval::new(HALF_PI.0, HALF_PI.1), &half));
        assert!(HALF_PI.0 < HALF_PI.1 && PI.0 < PI.1);
    }
}
