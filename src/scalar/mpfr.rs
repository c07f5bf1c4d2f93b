//! [`rug::Float`] (MPFR) as a [`Field`] and [`Real`]; the context is the precision in bits.
//!
//! Every operation is correctly rounded to the precision of its left operand, so all values
//! of one computation should share one precision: constants are made with `ctx()` of the
//! values they meet.

use super::{BigInt, BigRational, Field, Real};
use num_bigint::Sign;
use rug::float::{Constant, Round};
use rug::integer::Order;
use rug::ops::DivAssignRound;
use rug::{Assign, Float, Integer, Rational};

/// num-bigint → GMP integer, exactly.
pub fn bigint_to_integer(n: &BigInt) -> Integer {
    let (sign, bytes) = n.to_bytes_le();
    let magnitude = Integer::from_digits(&bytes, Order::Lsf);
    if sign == Sign::Minus {
        -magnitude
    } else {
        magnitude
    }
}

/// GMP integer → num-bigint, exactly.
pub fn integer_to_bigint(n: &Integer) -> BigInt {
    let bytes: Vec<u8> = n.to_digits(Order::Lsf);
    let sign = match n.cmp0() {
        std::cmp::Ordering::Less => Sign::Minus,
        std::cmp::Ordering::Equal => Sign::NoSign,
        std::cmp::Ordering::Greater => Sign::Plus,
    };
    BigInt::from_bytes_le(sign, &bytes)
}

/// num-rational → GMP rational, exactly.
pub fn to_gmp_rational(q: &BigRational) -> Rational {
    Rational::from((bigint_to_integer(q.numer()), bigint_to_integer(q.denom())))
}

/// GMP rational → num-rational, exactly.
pub fn from_gmp_rational(q: &Rational) -> BigRational {
    BigRational::new(integer_to_bigint(q.numer()), integer_to_bigint(q.denom()))
}

/// A rational rounded once to the nearest double (through a 53-bit MPFR value, whose
/// exponent range is wider, so only results in the subnormal range can round twice).
pub fn rational_to_f64(q: &BigRational) -> f64 {
    gmp_rational_to_f64(&to_gmp_rational(q))
}

/// A GMP rational rounded once to the nearest double (ties to even), subnormals included:
/// rounding to 53 bits and then to a subnormal's fewer bits would round twice (e.g.
/// 1.6725613558992932035e-308 became …293e-308 instead of …2935e-308), so below 2⁻¹⁰²² the
/// value is rounded directly to the bits the double has there.
pub fn gmp_rational_to_f64(r: &rug::Rational) -> f64 {
    use rug::float::Round;
    // Numerator and denominator both exact in a double (every decimal of up to 15 digits
    // with a small exponent): IEEE division rounds their quotient once, correctly, to
    // nearest with ties to even, subnormal results included — no MPFR value needed.
    if r.numer().significant_bits() <= 53 && r.denom().significant_bits() <= 53 {
        return r.numer().to_f64() / r.denom().to_f64();
    }
    // Truncation gives the exponent without a carry into the next binade: |r| = m·2^e,
    // m ∈ [1/2, 1).
    let truncated = Float::with_val_round(53, r, Round::Zero).0;
    let Some(exp) = truncated.get_exp().filter(|_| truncated.is_normal()) else {
        return Float::with_val(53, r).to_f64();
    };
    // A double below 2⁻¹⁰²² carries e + 1074 significant bits (its last is 2⁻¹⁰⁷⁴).
    let bits = exp + 1074;
    if bits >= 53 {
        Float::with_val(53, r).to_f64()
    } else if bits >= 1 {
        Float::with_val(bits as u32, r).to_f64()
    } else {
        // |r| < 2⁻¹⁰⁷⁴: 0 up to half of it (the tie goes to the even 0), the smallest
        // subnormal above.
        let half_smallest = rug::Rational::from((1, 1)) >> 1075u32;
        let magnitude = if rug::Rational::from(r.abs_ref()) > half_smallest {
            f64::from_bits(1)
        } else {
            0.0
        };
        if *r < 0 {
            -magnitude
        } else {
            magnitude
        }
    }
}

/// A precision MPFR accepts: `bits` clamped to [`rug::float::prec_min`],
/// [`rug::float::prec_max`] (a context of 0 bits would make MPFR abort), so the `Field`
/// constructors of `Float` and `Ball` never panic.
/// n/d (d ≠ 0) rounded to nearest at `prec` bits, with the direction of the rounding (as
/// `mpfr_set_q` gives for the fraction): at 64 bits or more n is exact in a Float, so one
/// correctly rounded division by d gives the same number and direction without building a
/// GMP rational (a gcd and two allocations; the hot constants of the PH conversion).
pub(crate) fn ratio_rounded(n: i64, d: i64, prec: u32) -> (Float, std::cmp::Ordering) {
    if prec >= 64 {
        let mut x = Float::with_val(prec, n);
        let direction = x.div_assign_round(d, Round::Nearest);
        (x, direction)
    } else {
        Float::with_val_round(prec, Rational::from((n, d)), Round::Nearest)
    }
}

pub fn precision(bits: u32) -> u32 {
    bits.clamp(rug::float::prec_min(), rug::float::prec_max())
}

impl Field for Float {
    type Ctx = u32;

    fn ctx(&self) -> u32 {
        self.prec()
    }
    fn scalar_name(bits: &u32) -> String {
        format!("mpfr:{bits}")
    }
    fn unit_roundoff(bits: &u32) -> Option<f64> {
        Some(2f64.powi(-(*bits as i32).min(1074)))
    }
    fn from_i64(v: i64, bits: &u32) -> Self {
        Float::with_val(precision(*bits), v)
    }
    fn from_ratio(n: i64, d: i64, bits: &u32) -> Self {
        if d == 0 {
            // IEEE: ±∞, or NaN for 0/0 (a GMP rational with denominator 0 would abort).
            return Float::with_val(precision(*bits), n) / 0u32;
        }
        ratio_rounded(n, d, precision(*bits)).0
    }
    fn from_rational(q: &BigRational, bits: &u32) -> Self {
        Float::with_val(precision(*bits), &to_gmp_rational(q))
    }
    fn from_exact(q: &Rational, bits: &u32) -> Self {
        Float::with_val(precision(*bits), q)
    }
    fn from_f64(v: f64, bits: &u32) -> Self {
        Float::with_val(precision(*bits), v)
    }
    fn abs(&self) -> Self {
        self.clone().abs()
    }
    fn is_zero(&self) -> bool {
        Float::is_zero(self)
    }
    fn is_finite(&self) -> bool {
        Float::is_finite(self)
    }
    fn to_f64(&self) -> f64 {
        Float::to_f64_round(self, Round::Nearest)
    }
    fn to_rational(&self) -> Option<BigRational> {
        Float::to_rational(self).map(|q| from_gmp_rational(&q))
    }
    fn to_exact(&self) -> Option<Rational> {
        Float::to_rational(self)
    }
    fn assign_mul(&mut self, a: &Self, b: &Self) {
        if self.prec() == a.prec() {
            // mpfr_mul into self at a's precision: `a.clone() * b` without the allocation.
            self.assign(a * b);
        } else {
            *self = a.clone() * b;
        }
    }
    fn mul_add_assign(&mut self, a: &Self, b: &Self) {
        *self += a * b; // mpfr_fma: one rounding, no temporary
    }
    fn mul_sub_assign(&mut self, a: &Self, b: &Self) {
        *self -= a * b;
    }
    fn horner_step(&mut self, x: &Self, c: &Self) {
        // fma(self, x, c) rounded to self's precision, as c + self·x rounded to c's: the
        // Horner loops keep one precision throughout.
        if self.prec() == c.prec() {
            self.mul_add_mut(x, c);
        } else {
            super::horner_step_into_copy(self, x, c);
        }
    }
    fn to_plain_string(&self) -> String {
        super::certify::format_float_digits(self, super::certify::max_digits(self.prec()))
    }
}

impl Real for Float {
    fn sqrt(&self) -> Self {
        self.clone().sqrt()
    }
    fn sin_cos(&self) -> (Self, Self) {
        let (s, c) = self.clone().sin_cos(Float::new(self.prec()));
        (s, c)
    }
    fn sin(&self) -> Self {
        Float::with_val(self.prec(), self.sin_ref())
    }
    fn cos(&self) -> Self {
        Float::with_val(self.prec(), self.cos_ref())
    }
    fn atan2(&self, x: &Self) -> Self {
        self.clone().atan2(x)
    }
    fn exp(&self) -> Self {
        self.clone().exp()
    }
    fn ln(&self) -> Self {
        self.clone().ln()
    }
    fn log2(&self) -> Self {
        self.clone().log2()
    }
    fn pi(bits: &u32) -> Self {
        Float::with_val(precision(*bits), Constant::Pi)
    }
    fn epsilon(bits: &u32) -> Self {
        // 2^(1−p)
        Float::with_val(precision(*bits), 1) >> (*bits as i32 - 1)
    }
    fn precision_bits(bits: &u32) -> u32 {
        *bits
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integer_round_trip() {
        for s in [
            "0",
            "-1",
            "123456789012345678901234567890",
            "-987654321098765432109876543210",
        ] {
            let b: BigInt = s.parse().unwrap();
            let i = bigint_to_integer(&b);
            assert_eq!(i.to_string(), s);
            assert_eq!(integer_to_bigint(&i), b);
        }
    }

    #[test]
    fn rational_to_double_is_correctly_rounded() {
        let tenth = BigRational::new(1.into(), 10.into());
        assert_eq!(rational_to_f64(&tenth), 0.1);
        let third = BigRational::new(1.into(), 3.into());
        assert_eq!(rational_to_f64(&third), 1.0 / 3.0);
    }

    #[test]
    fn epsilon_is_two_to_one_minus_p() {
        let e = Float::epsilon(&100);
        assert_eq!(e, Float::with_val(100, Float::i_exp(1, -99)));
        assert_eq!(<f64 as Real>::epsilon(&()), f64::EPSILON);
    }
}
