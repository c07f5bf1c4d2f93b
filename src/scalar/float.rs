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
    /// core's decimal parser rounds correctly (to nearest, ties to even), as the exact path's
    /// [`gmp_rational_to_f64`](super::mpfr::gmp_rational_to_f64) does, without a big
    /// rational per number. Left to the exact path: long texts (which it may refuse as too
    /// long), zeros (a rational has no −0) and overflows (which it reports); a finite non-zero
    /// double from at most 40 characters has an exponent well inside the exact reader's range.
    fn from_json_number(text: &str, _: &()) -> Option<Self> {
        if text.len() > 40 || !is_json_number(text) {
            return None;
        }
        text.parse::<f64>()
            .ok()
            .filter(|x| x.is_finite() && *x != 0.0)
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
    fn write_plain_string(&self, out: &mut String) {
        write_f64(*self, out);
    }
}

/// Whether `text` is a number of the JSON grammar: `-?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?`.
fn is_json_number(text: &str) -> bool {
    let digits = |s: &[u8]| s.iter().take_while(|b| b.is_ascii_digit()).count();
    let mut rest = text.as_bytes();
    if let [b'-', tail @ ..] = rest {
        rest = tail;
    }
    let whole = digits(rest);
    if whole == 0 || (whole > 1 && rest[0] == b'0') {
        return false;
    }
    rest = &rest[whole..];
    if let [b'.', tail @ ..] = rest {
        let fraction = digits(tail);
        if fraction == 0 {
            return false;
        }
        rest = &tail[fraction..];
    }
    if let [b'e' | b'E', tail @ ..] = rest {
        let tail = match tail {
            [b'+' | b'-', signed @ ..] => signed,
            _ => tail,
        };
        let exponent = digits(tail);
        if exponent == 0 {
            return false;
        }
        rest = &tail[exponent..];
    }
    rest.is_empty()
}

/// The shortest decimal that reads back as the same double ("0.6", "1e-7", "1.5e300").
pub fn format_f64(x: f64) -> String {
    let mut s = String::new();
    write_f64(x, &mut s);
    s
}

/// [`format_f64`] appended to `out`.
pub fn write_f64(x: f64, out: &mut String) {
    // Debug prints the shortest round-trip form and switches to an exponent for very large
    // and very small magnitudes; "-0.0" prints as "0".
    if x == 0.0 {
        out.push('0');
        return;
    }
    use std::fmt::Write;
    let _ = write!(out, "{x:?}"); // writing to a String cannot fail
    if out.ends_with(".0") {
        out.truncate(out.len() - 2);
    }
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
    use crate::scalar::parse::parse_exact;
    use proptest::prelude::*;

    /// The shortcut either declines or gives the exact path's double, bit for bit.
    fn agrees_with_exact_path(text: &str) -> bool {
        let exact = parse_exact(text).map(|q| f64::from_exact(&q, &()));
        match (f64::from_json_number(text, &()), exact) {
            (None, _) => true,
            (Some(fast), Ok(exact)) => fast.to_bits() == exact.to_bits(),
            (Some(_), Err(_)) => false,
        }
    }

    #[test]
    fn json_numbers_read_as_the_exact_path_rounds_them() {
        let hard = [
            "0.1",
            "-0.1",
            "2.2250738585072011e-308",
            "2.2250738585072012e-308",
            "4.9406564584124654e-324",
            "2.4703282292062328e-324",
            "2.4703282292062327e-324",
            "1.7976931348623157e308",
            "1.7976931348623158e308",
            "1.7976931348623159e308",
            "9007199254740993",
            "9007199254740995",
            "18014398509481986",
            "1e23",
            "8.98846567431158e307",
            "123456789012345678901234567890",
            "0.30000000000000004441",
            "-5e-324",
            "1e-7",
            "3.0e+2",
            "1E-400",
            "1e400",
            "0",
            "-0",
            "0.0e5",
        ];
        for text in hard {
            assert!(agrees_with_exact_path(text), "{text}");
        }
        // Taken where the double is finite and non-zero; declined otherwise.
        assert_eq!(
            f64::from_json_number("9007199254740993", &()),
            Some(9007199254740992.0)
        );
        assert_eq!(
            f64::from_json_number("2.4703282292062328e-324", &()),
            Some(5e-324)
        );
        for declined in [
            "1e400", "1e-400", "0", "-0", "+1", ".5", "5.", "01", "inf", "1/3", "0x10",
        ] {
            assert_eq!(f64::from_json_number(declined, &()), None, "{declined}");
        }
    }

    proptest! {
        #[test]
        fn random_decimals_read_as_the_exact_path_rounds_them(
            negative in any::<bool>(),
            whole in "[1-9][0-9]{0,18}",
            fraction in proptest::option::of("[0-9]{1,18}"),
            exponent in proptest::option::of(-340i32..320),
        ) {
            let mut text = format!("{}{whole}", if negative { "-" } else { "" });
            if let Some(f) = fraction {
                text += &format!(".{f}");
            }
            if let Some(e) = exponent {
                text += &format!("e{e}");
            }
            prop_assert!(agrees_with_exact_path(&text), "{}", text);
        }
    }

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
