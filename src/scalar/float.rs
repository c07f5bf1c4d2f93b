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
        let decimal = JsonDecimal::parse(text)?;
        if let Some(x) = decimal.clinger() {
            return Some(x);
        }
        if text.len() > 40 {
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
    fn to_exact(&self) -> Option<rug::Rational> {
        rug::Rational::from_f64(*self)
    }
    fn to_plain_string(&self) -> String {
        format_f64(*self)
    }
    fn write_plain_string(&self, out: &mut String) {
        write_f64(*self, out);
    }
}

/// Powers of ten that are exact doubles: 10⁰ … 10²².
const EXACT_POWERS_OF_TEN: [f64; 23] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
    1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
];

/// A number of the JSON grammar `-?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?`, taken apart:
/// its value is ±w·10^exponent, w the integer of all its digits.
struct JsonDecimal {
    negative: bool,
    /// w modulo 2⁶⁴ (exact while `digit_count` ≤ 19, as 10¹⁹ − 1 < 2⁶⁴).
    digits: u64,
    /// The number of digits of w, leading zeros included.
    digit_count: usize,
    /// The written exponent less the fraction's digits (saturating).
    exponent: i64,
}

impl JsonDecimal {
    /// `text` taken apart in one pass, or `None` if it is not a number of the JSON grammar.
    fn parse(text: &str) -> Option<Self> {
        let bytes = text.as_bytes();
        let mut at = 0;
        let negative = bytes.first() == Some(&b'-');
        if negative {
            at += 1;
        }
        let mut digits: u64 = 0;
        let mut digit_count = 0;
        // The run of digits from `at`, appended to w; how many.
        let mut take_digits = |at: &mut usize, append: bool| {
            let start = *at;
            while let Some(&b) = bytes.get(*at).filter(|b| b.is_ascii_digit()) {
                if append {
                    digits = digits.wrapping_mul(10).wrapping_add(u64::from(b - b'0'));
                    digit_count += 1;
                }
                *at += 1;
            }
            *at - start
        };
        let whole_start = at;
        let whole = take_digits(&mut at, true);
        if whole == 0 || (whole > 1 && bytes[whole_start] == b'0') {
            return None;
        }
        let mut exponent: i64 = 0;
        if bytes.get(at) == Some(&b'.') {
            at += 1;
            let fraction = take_digits(&mut at, true);
            if fraction == 0 {
                return None;
            }
            exponent = -(fraction as i64);
        }
        if matches!(bytes.get(at), Some(b'e' | b'E')) {
            at += 1;
            let sign = match bytes.get(at) {
                Some(b'-') => {
                    at += 1;
                    -1
                }
                Some(b'+') => {
                    at += 1;
                    1
                }
                _ => 1,
            };
            let start = at;
            if take_digits(&mut at, false) == 0 {
                return None;
            }
            let written = text[start..at].bytes().fold(0i64, |e, b| {
                e.saturating_mul(10).saturating_add(i64::from(b - b'0'))
            });
            exponent = exponent.saturating_add(sign * written);
        }
        (at == bytes.len()).then_some(JsonDecimal {
            negative,
            digits,
            digit_count,
            exponent,
        })
    }

    /// The double nearest to the number when its digits w, read as an integer, are at most
    /// 2⁵³ and |exponent| ≤ 22: then w and 10^|exponent| are both exact doubles, so one
    /// multiplication or division rounds the exact value once, correctly (Clinger's fast path,
    /// the one core's parser also takes first, without its general machinery). `None`
    /// otherwise, zeros included (a rational has no −0; they are read the long way).
    fn clinger(&self) -> Option<f64> {
        if self.digit_count > 19 || self.digits == 0 || self.digits > 1 << 53 {
            return None;
        }
        let power =
            *EXACT_POWERS_OF_TEN.get(usize::try_from(self.exponent.unsigned_abs()).ok()?)?;
        let w = self.digits as f64;
        let magnitude = if self.exponent >= 0 {
            w * power
        } else {
            w / power
        };
        Some(if self.negative { -magnitude } else { magnitude })
    }
}

/// The shortest decimal that reads back as the same double ("0.6", "1e-7", "1.5e300").
pub fn format_f64(x: f64) -> String {
    let mut s = String::new();
    write_f64(x, &mut s);
    s
}

/// (m, e) with x = m·2^e and m odd, for a finite x > 0.
fn odd_mantissa(x: f64) -> (u64, i32) {
    let bits = x.to_bits();
    let (raw_exponent, fraction) = ((bits >> 52) as i32 & 0x7ff, bits & ((1 << 52) - 1));
    let (m, e) = match raw_exponent {
        0 => (fraction, -1074),
        _ => (fraction | 1 << 52, raw_exponent - 1075),
    };
    let zeros = m.trailing_zeros().min(63);
    (m >> zeros, e + zeros as i32)
}

/// Whether x > 0 can lie halfway between two shortest decimals at all: [`is_decimal_tie`]
/// needs e = q − 1 with |q| ≤ 27 (beyond, the odd parts exceed 2^53 or 2·10^17).
fn may_be_decimal_tie(x: f64) -> bool {
    (-28..=26).contains(&odd_mantissa(x).1)
}

/// Whether x > 0 is exactly (D + ½)·10^q, D the integer of `digits` and q = point − count:
/// halfway between D and D + 1 in the last printed place.
///
/// x = m·2^e with m odd; (2D + 1)·5^q·2^(q−1) for q ≥ 0, and (2D + 1)/(5^−q·2^(1−q)) for
/// q < 0, have odd parts (2D + 1)·5^q and (2D + 1)/5^−q and the power of two 2^(q−1), so
/// the tie holds exactly when e = q − 1 and the odd parts agree (integers below 2^128).
fn is_decimal_tie(x: f64, digits: &[u8], point: i32) -> bool {
    let (m, e) = odd_mantissa(x);
    if m == 0 {
        return false;
    }
    let q = point - digits.len() as i32;
    if e != q - 1 || q.abs() > 27 {
        return false;
    }
    let d = digits
        .iter()
        .fold(0u128, |acc, &b| acc * 10 + u128::from(b - b'0'));
    let (odd, five) = (2 * d + 1, 5u128.pow(q.unsigned_abs()));
    if q >= 0 {
        u128::from(m) == odd * five
    } else {
        u128::from(m) * five == odd
    }
}

/// [`format_f64`] appended to `out`: the layout of Rust's `{:?}` without a trailing ".0" —
/// plain decimals for 1e-4 ≤ |x| < 1e16, `d.ddde±k` outside — and "0" for ±0.
///
/// The digits are Ryū's (the `ryu` crate, three times faster than core's Grisu here): the
/// shortest that read back as x and, among those, the nearest to x, which is what core's
/// `{:?}` prints too (the test compares both on random and hard doubles); only their layouts
/// differ, so Ryū's output is taken apart into digits and exponent and laid out as core does.
pub fn write_f64(x: f64, out: &mut String) {
    if x == 0.0 {
        out.push('0');
        return;
    }
    if !x.is_finite() {
        write_core_debug(x, out); // "NaN", "inf", "-inf"
        return;
    }
    let mut buffer = ryu::Buffer::new();
    let abs = x.abs();
    // Ryū lays out as core does except for 1e-5 ≤ |x| < 1e-4 (Ryū "0.00001234", core
    // "1.234e-5"), and its digits are core's except at a tie: elsewhere its text is taken.
    if !may_be_decimal_tie(abs) && !(1e-5..1e-4).contains(&abs) {
        let printed = buffer.format_finite(x);
        out.push_str(printed.strip_suffix(".0").unwrap_or(printed));
        return;
    }
    let (digits, count, point) = shortest_digits(buffer.format_finite(abs).as_bytes());
    let digits = &digits[..count];
    if is_decimal_tie(abs, digits, point) {
        // x lies exactly halfway between two shortest decimals: Ryū takes the even one,
        // core the upper one. Rare (only short binary fractions); core prints it.
        write_core_debug(x, out);
        return;
    }
    lay_out_as_core(x < 0.0, (1e-4..1e16).contains(&abs), digits, point, out);
}

/// core's `{:?}` of x appended to `out`, without a trailing ".0".
fn write_core_debug(x: f64, out: &mut String) {
    use std::fmt::Write;
    let start = out.len();
    let _ = write!(out, "{x:?}"); // writing to a String cannot fail
    if out[start..].ends_with(".0") {
        out.truncate(out.len() - 2);
    }
}

/// The significant digits of Ryū's text for x > 0 (mantissa with or without a point, then
/// `e` and an exponent), their count, and the power of ten of the first: x = 0.d₁d₂… × 10^point.
fn shortest_digits(printed: &[u8]) -> ([u8; 24], usize, i32) {
    let mut digits = [0u8; 24];
    let (mut count, mut point, mut seen_point) = (0usize, 0i32, false);
    let mut rest = printed;
    while let [b, tail @ ..] = rest {
        match *b {
            b'.' => seen_point = true,
            b'e' => {
                let exponent = std::str::from_utf8(tail)
                    .ok()
                    .and_then(|e| e.parse::<i32>().ok());
                point += exponent.unwrap_or(0);
                break;
            }
            b'0' if count == 0 => {
                if seen_point {
                    point -= 1; // a leading zero after the point ("0.00123")
                }
            }
            digit => {
                if count < digits.len() {
                    digits[count] = digit;
                    count += 1;
                }
                if !seen_point {
                    point += 1;
                }
            }
        }
        rest = tail;
    }
    while count > 1 && digits[count - 1] == b'0' {
        count -= 1; // trailing zeros of "1200.0" or "1e16"
    }
    (digits, count, point)
}

/// The digits d₁d₂… with x = ±0.d₁d₂… × 10^point appended to `out` as core's `{:?}` prints
/// them (without ".0"): a plain decimal when `plain` (1e-4 ≤ |x| < 1e16), `d.ddde±k` otherwise.
fn lay_out_as_core(negative: bool, plain: bool, digits: &[u8], point: i32, out: &mut String) {
    // Laid out in a stack buffer (at most 1 + 17 digits + 16 zeros + a point, or "e-324"),
    // then appended once.
    let mut text = [0u8; 48];
    let mut n = 0;
    let mut put = |bytes: &[u8]| {
        text[n..n + bytes.len()].copy_from_slice(bytes);
        n += bytes.len();
    };
    if negative {
        put(b"-");
    }
    if plain {
        if point <= 0 {
            put(b"0.");
            for _ in 0..point.unsigned_abs() {
                put(b"0");
            }
            put(digits);
        } else if (point as usize) < digits.len() {
            let (int, frac) = digits.split_at(point as usize);
            put(int);
            put(b".");
            put(frac);
        } else {
            put(digits);
            for _ in digits.len()..point as usize {
                put(b"0");
            }
        }
    } else {
        let (first, rest) = digits.split_at(digits.len().min(1));
        put(first);
        if !rest.is_empty() {
            put(b".");
            put(rest);
        }
        put(b"e");
        put(itoa::Buffer::new().format(point - 1).as_bytes());
    }
    out.push_str(std::str::from_utf8(&text[..n]).unwrap_or("NaN"));
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

    /// core's `{:?}` without ".0", which [`write_f64`] must reproduce.
    fn core_debug(x: f64) -> String {
        if x == 0.0 {
            return "0".into();
        }
        let s = format!("{x:?}");
        s.strip_suffix(".0").map(str::to_owned).unwrap_or(s)
    }

    #[test]
    fn ryu_digits_laid_out_as_core_prints_them() {
        let hard = [
            1.0,
            0.1,
            0.3,
            1e-4,
            9.999999999999999e-5,
            1e16,
            9999999999999998.0,
            1e15,
            123456.0,
            1e23,
            5e-324,
            2.2250738585072014e-308,
            f64::from_bits(0x4317_9085_685d_83c9),
            0.5,
            2.5,
            1e15 + 0.5,
            f64::MAX,
            f64::MIN_POSITIVE,
            1.5e-7,
            0.001,
            100.0,
            1e21,
            2f64.powi(60),
            2f64.powi(-60),
            1.0 / 3.0,
            f64::EPSILON,
            -0.0,
            4.35,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ];
        for x in hard.into_iter().flat_map(|x| [x, -x]) {
            assert_eq!(format_f64(x), core_debug(x), "{x:e}");
        }
        // Random bit patterns (every exponent), and random doubles near each layout switch.
        let mut next = crate::scalar::xorshift(0x9e37_79b9_7f4a_7c15);
        for _ in 0..200_000 {
            let x = f64::from_bits(next());
            assert_eq!(format_f64(x), core_debug(x), "{:#x}", x.to_bits());
            let near = [1e-4, 1e-5, 1e16, 1.0][(next() % 4) as usize];
            let y = near * (1.0 + ((next() % 2001) as f64 - 1000.0) * 1e-13);
            assert_eq!(format_f64(y), core_debug(y), "{y:e}");
            // Short binary fractions, where ties between two shortest decimals live.
            let z = (next() >> 11) as f64 * 2f64.powi((next() % 40) as i32 - 20);
            assert_eq!(format_f64(z), core_debug(z), "{z:e}");
        }
    }

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
        // The fast path's edges: 2⁵³ and 10²² are exact, one past them is read the long way.
        for text in [
            "9007199254740992",
            "9007199254740993e0",
            "1e22",
            "1e23",
            "1e-22",
            "1e-23",
            "4.5e-1",
            "0.000000000000000000001",
            "12345678901234567890",
            "1.2e+03",
            "0.50",
        ] {
            assert!(agrees_with_exact_path(text), "{text}");
        }
        for declined in [
            "1e400", "1e-400", "0", "-0", "+1", ".5", "5.", "01", "inf", "1/3", "0x10", "1e",
            "1e+", "-", "1.5x", "00.5", "0.0e5",
        ] {
            assert_eq!(f64::from_json_number(declined, &()), None, "{declined}");
        }
    }

    /// "-" if negative, the whole digits, "." and the fraction's if any, then the exponent.
    fn decimal_text(
        negative: bool,
        whole: &str,
        fraction: Option<String>,
        exponent: Option<String>,
    ) -> String {
        let sign = if negative { "-" } else { "" };
        let fraction = fraction.map_or(String::new(), |f| format!(".{f}"));
        format!("{sign}{whole}{fraction}{}", exponent.unwrap_or_default())
    }

    proptest! {
        #[test]
        fn random_decimals_read_as_the_exact_path_rounds_them(
            negative in any::<bool>(),
            whole in "[1-9][0-9]{0,18}",
            fraction in proptest::option::of("[0-9]{1,18}"),
            exponent in proptest::option::of(-340i32..320),
        ) {
            let text = decimal_text(negative, &whole, fraction, exponent.map(|e| format!("e{e}")));
            prop_assert!(agrees_with_exact_path(&text), "{}", text);
        }

        /// Short decimals with small exponents, where the fast path (`JsonDecimal::clinger`)
        /// answers: bit for bit the exact path's double, and core's.
        #[test]
        fn short_decimals_read_as_the_exact_path_rounds_them(
            negative in any::<bool>(),
            whole in "0|[1-9][0-9]{0,9}",
            fraction in proptest::option::of("[0-9]{1,9}"),
            exponent in proptest::option::of(-30i32..30),
            capital in any::<bool>(),
        ) {
            let marker = if capital { "E" } else { "e" };
            let text =
                decimal_text(negative, &whole, fraction, exponent.map(|e| format!("{marker}{e:+}")));
            prop_assert!(agrees_with_exact_path(&text), "{}", text);
            if let Some(x) = f64::from_json_number(&text, &()) {
                prop_assert_eq!(x.to_bits(), text.parse::<f64>().unwrap().to_bits(), "{}", text);
            }
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
