//! `f64` as a [`Field`] and [`Real`]: the fast reference every report compares against.

use super::{BigRational, Field, Real};
use num_traits::FromPrimitive;

impl Field for f64 {
    type Ctx = ();

    fn ctx(&self) {}
    fn scalar_name(_: &()) -> String {
        "f64".into()
    }
    fn unit_roundoff(_: &()) -> Option<f64> {
        Some(f64::EPSILON / 2.0)
    }
    fn from_i64(v: i64, _: &()) -> Self {
        v as f64
    }
    fn from_ratio(n: i64, d: i64, _: &()) -> Self {
        // Both operands are exact when |n|, |d| < 2^53, so the quotient is correctly rounded.
        if n.unsigned_abs() < (1 << 53) && d.unsigned_abs() < (1 << 53) {
            n as f64 / d as f64
        } else {
            Self::from_rational(&BigRational::new(n.into(), d.into()), &())
        }
    }
    fn from_ratio_nearest(_: i64, _: i64, nearest: f64, _: &()) -> Self {
        nearest
    }
    fn from_rational(q: &BigRational, _: &()) -> Self {
        super::mpfr::rational_to_f64(q)
    }
    fn from_exact(q: &rug::Rational, _: &()) -> Self {
        super::mpfr::gmp_rational_to_f64(q)
    }
    fn from_f64(v: f64, _: &()) -> Self {
        v
    }
    fn abs(&self) -> Self {
        f64::abs(*self)
    }
    fn is_zero(&self) -> bool {
        *self == 0.0
    }
    fn is_finite(&self) -> bool {
        f64::is_finite(*self)
    }
    fn to_f64(&self) -> f64 {
        *self
    }
    fn to_rational(&self) -> Option<BigRational> {
        <BigRational as FromPrimitive>::from_f64(*self)
    }
    fn to_plain_string(&self) -> String {
        format_f64(*self)
    }
}

/// The shortest decimal that reads back as the same double ("0.6", "1e-7", "1.5e300").
pub fn format_f64(x: f64) -> String {
    // Debug prints the shortest round-trip form and switches to an exponent for very large
    // and very small magnitudes; "-0.0" prints as "0".
    if x == 0.0 {
        return "0".into();
    }
    let s = format!("{x:?}");
    s.strip_suffix(".0").map(str::to_owned).unwrap_or(s)
}

impl Real for f64 {
    fn sqrt(&self) -> Self {
        f64::sqrt(*self)
    }
    fn sin_cos(&self) -> (Self, Self) {
        f64::sin_cos(*self)
    }
    fn atan2(&self, x: &Self) -> Self {
        f64::atan2(*self, *x)
    }
    fn exp(&self) -> Self {
        f64::exp(*self)
    }
    fn ln(&self) -> Self {
        f64::ln(*self)
    }
    fn log2(&self) -> Self {
        f64::log2(*self)
    }
    fn pi(_: &()) -> Self {
        std::f64::consts::PI
    }
    fn epsilon(_: &()) -> Self {
        f64::EPSILON
    }
    fn precision_bits(_: &()) -> u32 {
        53
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shortest_round_trip() {
        assert_eq!(format_f64(0.6), "0.6");
        assert_eq!(format_f64(1.0), "1");
        assert_eq!(format_f64(-0.0), "0");
        assert_eq!(format_f64(1e-7), "1e-7");
        assert_eq!(format_f64(1.5e300), "1.5e300");
        for x in [0.1, 1.0 / 3.0, 6.02e23, -2.5e-310] {
            assert_eq!(format_f64(x).parse::<f64>().unwrap(), x);
        }
    }

    #[test]
    fn ratio_is_correctly_rounded() {
        assert_eq!(f64::from_ratio(3, 5, &()), 0.6);
        let big = (1i64 << 60) + 1;
        assert_eq!(f64::from_ratio(big, 1, &()), (1u64 << 60) as f64);
    }
}
