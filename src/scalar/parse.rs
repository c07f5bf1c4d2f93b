//! Reading numbers exactly: `"3/5"`, `"0.6"`, `"-1.25e-3"`, `"7"`.
//!
//! Every accepted string denotes a rational number, which is read exactly into GMP's
//! rationals ([`parse_exact`], what `run` uses) or num-rational's [`BigRational`]
//! ([`parse_rational`]); converting that to f64 or MPFR rounds once, correctly
//! ([`Field::from_exact`](super::Field::from_exact), [`Field::from_rational`](super::Field::from_rational)). `NaN`, infinities, hexadecimal and
//! empty strings are rejected, and so are exponents beyond ±[`MAX_EXPONENT`] (a guard
//! against inputs like `1e999999999` that would build enormous integers).

use super::BigRational;

/// The largest decimal exponent accepted.
pub const MAX_EXPONENT: i64 = 10_000;
/// The most characters a number's digits may have (a guard against megabyte-long digit
/// strings; 1000 decimal digits carry about 3300 bits).
pub const MAX_DIGITS: usize = 1000;

/// Why a string is not a number trajverify accepts.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ParseNumberError {
    /// Not a number in the accepted syntax.
    #[error("{0:?} is not a number (expected a decimal such as \"0.6\" or \"1e-3\", or a fraction such as \"3/5\")")]
    Malformed(String),
    /// A fraction with denominator zero.
    #[error("{0:?} has a zero denominator")]
    ZeroDenominator(String),
    /// An exponent too large to expand exactly.
    #[error("{0:?} has an exponent beyond ±{MAX_EXPONENT}")]
    ExponentTooLarge(String),
    /// More characters than a number may have.
    #[error("a number of {0} characters is longer than the {MAX_DIGITS} accepted")]
    TooLong(usize),
}

/// Parse a decimal or a fraction of two decimals exactly.
///
/// # Errors
/// [`ParseNumberError::TooLong`] for more than [`MAX_DIGITS`] bytes after trimming;
/// [`ParseNumberError::Malformed`] outside the syntax (empty, `NaN`, `inf`, hexadecimal, a sign
/// or exponent without digits); [`ParseNumberError::ExponentTooLarge`] for an exponent beyond
/// ±[`MAX_EXPONENT`]; [`ParseNumberError::ZeroDenominator`] for a fraction `n/0`.
pub fn parse_rational(text: &str) -> Result<BigRational, ParseNumberError> {
    parse_exact(text).map(|q| super::mpfr::from_gmp_rational(&q))
}

/// [`parse_rational`] into GMP's rationals (`rug::Rational`, the exact type of `run`): the
/// same syntax, errors and values, read with GMP's subquadratic radix conversion.
///
/// # Errors
/// As [`parse_rational`].
pub fn parse_exact(text: &str) -> Result<rug::Rational, ParseNumberError> {
    let s = text.trim();
    if s.len() > MAX_DIGITS {
        return Err(ParseNumberError::TooLong(s.len()));
    }
    match s.split_once('/') {
        Some((num, den)) => {
            let n = decimal(num.trim(), text)?;
            let d = decimal(den.trim(), text)?;
            if d.cmp0() == std::cmp::Ordering::Equal {
                return Err(ParseNumberError::ZeroDenominator(text.into()));
            }
            Ok(n / d)
        }
        None => decimal(s, text),
    }
}

/// A decimal `[±]digits[.digits][e[±]digits]`, exactly.
fn decimal(s: &str, whole: &str) -> Result<rug::Rational, ParseNumberError> {
    let malformed = || ParseNumberError::Malformed(whole.into());
    let (negative, unsigned) = match s.as_bytes().first() {
        Some(b'-') => (true, &s[1..]),
        Some(b'+') => (false, &s[1..]),
        _ => (false, s),
    };
    let (mantissa, exponent) = match unsigned.find(['e', 'E']) {
        Some(i) => (&unsigned[..i], Some(&unsigned[i + 1..])),
        None => (unsigned, None),
    };
    let (int_part, frac_part) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let all_digits = |t: &str| t.bytes().all(|b| b.is_ascii_digit());
    if int_part.len() + frac_part.len() == 0 || !all_digits(int_part) || !all_digits(frac_part) {
        return Err(malformed());
    }
    let mut exp10: i64 = -(frac_part.len() as i64);
    if let Some(e) = exponent {
        let digits = e.strip_prefix(['+', '-']).unwrap_or(e);
        if digits.is_empty() || !all_digits(digits) {
            return Err(malformed());
        }
        let value: i64 = if digits.len() > 12 {
            i64::MAX
        } else {
            digits.parse().map_err(|_| malformed())?
        };
        if value > MAX_EXPONENT {
            return Err(ParseNumberError::ExponentTooLarge(whole.into()));
        }
        exp10 += if e.starts_with('-') { -value } else { value };
    }
    // The digits as one integer: up to 19 of them in a machine word, more through GMP.
    let count = int_part.len() + frac_part.len();
    let mut numer = if count <= 19 {
        let word = int_part
            .bytes()
            .chain(frac_part.bytes())
            .fold(0u64, |acc, b| acc * 10 + u64::from(b - b'0'));
        rug::Integer::from(word)
    } else {
        let digits = format!("{int_part}{frac_part}");
        rug::Integer::from_str_radix(&digits, 10).map_err(|_| malformed())?
    };
    if negative {
        numer = -numer;
    }
    let scale = rug::Integer::from(rug::Integer::u_pow_u(10, exp10.unsigned_abs() as u32));
    Ok(if exp10 >= 0 {
        rug::Rational::from(numer * scale)
    } else {
        rug::Rational::from((numer, scale))
    })
}

/// `true` when the string denotes exactly the same rational as `q` (used to compare a
/// printed decimal like "0.6" with an exact result).
pub fn denotes(text: &str, q: &BigRational) -> bool {
    parse_rational(text).is_ok_and(|p| &p == q)
}

/// The value of an integer-valued GMP rational as i64, if it is one and fits.
pub fn exact_integer(q: &rug::Rational) -> Option<i64> {
    if *q.denom() == 1 {
        q.numer().to_i64()
    } else {
        None
    }
}

/// The value of an integer-valued rational as i64, if it is one and fits.
pub fn denotes_integer(q: &BigRational) -> Option<i64> {
    use num_traits::ToPrimitive;
    if q.is_integer() {
        q.to_integer().to_i64()
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::Field;

    /// Reading a decimal exactly and rounding it once gives the double Rust's own
    /// correctly rounded parser gives, on the hard cases: halfway cases between two
    /// doubles (ties to even), subnormals and the smallest one's half, the ends of the
    /// range, and mantissas longer than a double holds (whose tail decides the rounding).
    #[test]
    fn exact_then_rounded_is_the_correctly_rounded_double() {
        let halfway = [
            // 2^53 + 1 lies halfway between 2^53 and 2^53 + 2: ties to the even 2^53.
            "9007199254740993",
            "9007199254740995",
            // 1 + 2^-53: halfway between 1 and the next double.
            "1.00000000000000011102230246251565404236316680908203125",
            "1.000000000000000111022302462515654042363166809082031250000001",
            "1.000000000000000111022302462515654042363166809082031249999999",
        ];
        let subnormal = [
            "4.9406564584124654e-324",
            "2.4703282292062327e-324",
            "2.4703282292062328e-324",
            "2.2250738585072011e-308",
            "2.2250738585072014e-308",
            "1.6725613558992932035e-308",
            "-3e-320",
        ];
        let ends = [
            "1.7976931348623157e308",
            "1.7976931348623158e308",
            "-1e308",
            "1e-308",
            "0.1",
            "-0.3",
            "123456.789012",
            "3.141592653589793238462643383279502884197169399375105820974944",
            "2.718281828459045235360287471352662497757247093699959574966967e-100",
        ];
        for text in halfway.iter().chain(&subnormal).chain(&ends) {
            let exact = parse_exact(text).unwrap();
            let ours = f64::from_exact(&exact, &());
            let rust: f64 = text.parse().unwrap();
            assert_eq!(
                ours.to_bits(),
                rust.to_bits(),
                "{text}: {ours:e} against {rust:e}"
            );
        }
        // Fractions round from the exact quotient, not from a rounded numerator.
        let third = f64::from_exact(&parse_exact("1/3").unwrap(), &());
        assert_eq!(third, 1.0 / 3.0);
        let big = f64::from_exact(&parse_exact("1e400/1e399").unwrap(), &());
        assert_eq!(big, 10.0);
    }

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    #[test]
    fn accepted_forms_are_exact() {
        assert_eq!(parse_rational("3/5").unwrap(), q(3, 5));
        assert_eq!(parse_rational("0.6").unwrap(), q(3, 5));
        assert_eq!(parse_rational("1e-3").unwrap(), q(1, 1000));
        assert_eq!(parse_rational("-1.25E+2").unwrap(), q(-125, 1));
        assert_eq!(parse_rational(" .5 ").unwrap(), q(1, 2));
        assert_eq!(parse_rational("5.").unwrap(), q(5, 1));
        assert_eq!(parse_rational("1.5/-3").unwrap(), q(-1, 2));
        assert_eq!(parse_rational("+7").unwrap(), q(7, 1));
    }

    #[test]
    fn rejected_forms_say_why() {
        for bad in [
            "", "NaN", "inf", "-", ".", "1e", "0x10", "1..2", "1e+", "3/", "a/b", "1 2",
        ] {
            assert!(
                matches!(parse_rational(bad), Err(ParseNumberError::Malformed(_))),
                "{bad}"
            );
        }
        assert!(matches!(
            parse_rational("1/0"),
            Err(ParseNumberError::ZeroDenominator(_))
        ));
        assert!(matches!(
            parse_rational("1e999999999999999"),
            Err(ParseNumberError::ExponentTooLarge(_))
        ));
        assert!(parse_rational(&"7".repeat(MAX_DIGITS)).is_ok());
        assert_eq!(
            parse_rational(&"7".repeat(MAX_DIGITS + 1)),
            Err(ParseNumberError::TooLong(MAX_DIGITS + 1))
        );
    }

    #[test]
    fn denotes_compares_exactly() {
        assert!(denotes("0.6", &q(3, 5)));
        assert!(!denotes("0.6", &q(2, 3)));
    }
}
