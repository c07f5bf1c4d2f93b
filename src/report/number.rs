//! The one number formatter of every report table and figure label.
//!
//! A table cell shows a number to a chosen count of significant digits, rounded (never a
//! prefix of a longer string, which would drop an exponent: "1.89784150e-7" cut to ten
//! characters reads as 1.9), in plain notation for moderate exponents and scientific
//! notation otherwise. A certified value shows at most the digits it has.

use crate::scalar::certify::{format_float_digits, Certified};
use crate::scalar::Float;

/// `x` to `digits` significant digits ("0" for zero; "NaN", "inf", "-inf" as such).
pub fn sig(x: f64, digits: u32) -> String {
    if x.is_nan() {
        return "NaN".into();
    }
    format_float_digits(&Float::with_val(53, x), digits)
}

/// A certified value with at most `max_digits` of its certified digits, rounded.
pub fn certified(c: &Certified, max_digits: u32) -> String {
    if c.digits <= max_digits {
        return c.text.clone();
    }
    // The certified text carries `c.digits` correct digits; rounding it to fewer digits
    // needs a precision that holds them all (about 3.33 bits a digit).
    let bits = (c.digits * 4 + 16).max(64);
    match Float::parse(&c.text) {
        Ok(parsed) => format_float_digits(&Float::with_val(bits, parsed), max_digits),
        Err(_) => c.text.clone(),
    }
}

/// A printed cell marked by how it compares with the computed value, from the difference in
/// units of its last printed digit: "✓" within half a unit (it is the rounded value), "≈"
/// within one unit (the last digit differs), "✗" beyond; unmarked when there is no computed
/// value.
pub fn marked(printed: &str, units: Option<f64>) -> String {
    // A cell the paper leaves empty ("-") reads as the reports' one sign for "none".
    let printed = if printed == "-" { "–" } else { printed };
    match units {
        Some(u) if u.abs() <= 0.5 => format!("{printed} ✓"),
        Some(u) if u.abs() <= 1.0 => format!("{printed} ≈"),
        Some(u) if u.is_finite() => format!("{printed} ✗"),
        _ => printed.to_string(),
    }
}

/// A bound printed with `digits` significant digits, rounded outward (`Round::Down` for a
/// lower bound, `Round::Up` for an upper one), so the printed bound is still a bound.
pub fn bound_text(x: &rug::Float, digits: usize, round: rug::float::Round) -> String {
    if x.is_zero() {
        return "0".into();
    }
    let (negative, mantissa, exp) = x.to_sign_string_exp_round(10, Some(digits), round);
    let e = exp.unwrap_or(0) - 1;
    let (lead, rest) = mantissa.split_at(1.min(mantissa.len()));
    format!("{}{lead}.{rest}e{e}", if negative { "-" } else { "" })
}

/// `text` with every decimal number of more than `max` significant digits rounded to `max`
/// ("2.6432542729944189731668883147678153029" → "2.643254273"): prose, summaries and
/// evidence in reports show at most ten; `claims.json` keeps every certified digit. Numbers
/// inside identifiers (`n8192`, `t1`) and fractions are left alone.
pub fn shorten(text: &str, max: u32) -> String {
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len());
    let mut i = 0;
    while i < chars.len() {
        let starts_number = chars[i].is_ascii_digit()
            && (i == 0
                || !(chars[i - 1].is_alphanumeric() || chars[i - 1] == '_' || chars[i - 1] == '.'));
        if !starts_number {
            out.push(chars[i]);
            i += 1;
            continue;
        }
        let start = i;
        while i < chars.len() && (chars[i].is_ascii_digit() || chars[i] == '.') {
            i += 1;
        }
        // An exponent: e, an optional sign, digits.
        let mut end = i;
        if end < chars.len() && (chars[end] == 'e' || chars[end] == 'E') {
            let mut j = end + 1;
            if j < chars.len() && (chars[j] == '-' || chars[j] == '+') {
                j += 1;
            }
            if j < chars.len() && chars[j].is_ascii_digit() {
                while j < chars.len() && chars[j].is_ascii_digit() {
                    j += 1;
                }
                end = j;
            }
        }
        let token: String = chars[start..end].iter().collect();
        let mantissa = token.split(['e', 'E']).next().unwrap_or("");
        let significant = mantissa
            .chars()
            .filter(char::is_ascii_digit)
            .skip_while(|&c| c == '0')
            .count();
        let fraction_follows = end < chars.len() && chars[end] == '/';
        let rounded =
            (significant as u32 > max && !fraction_follows && mantissa.matches('.').count() <= 1)
                .then(|| Float::parse(&token).ok())
                .flatten()
                .map(|p| {
                    format_float_digits(
                        &Float::with_val((significant as u32 * 4 + 16).max(64), p),
                        max,
                    )
                });
        out.push_str(rounded.as_deref().unwrap_or(&token));
        i = end;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_numbers_in_prose_are_rounded_and_identifiers_kept() {
        assert_eq!(
            shorten("B′ = 2.6432542729944189731668883147678153029 at n8192, 3/19 = 0.157894736842105263", 10),
            "B′ = 2.643254273 at n8192, 3/19 = 0.1578947368"
        );
        assert_eq!(
            shorten("error 1.897841500679692294263964960759e-7", 10),
            "error 1.897841501e-7"
        );
        assert_eq!(
            shorten("12345678901234567890/3 and 1.5", 10),
            "12345678901234567890/3 and 1.5"
        );
    }
    use crate::scalar::certify::certify;

    #[test]
    fn every_magnitude_keeps_its_exponent() {
        for e in -300..=300 {
            let x = 1.8978415012345 * 10f64.powi(e);
            let s = sig(x, 6);
            let back: f64 = s.parse().unwrap();
            assert!(((back - x) / x).abs() < 1e-5, "{x:e} printed as {s}");
            let neg = sig(-x, 3);
            let back: f64 = neg.parse().unwrap();
            assert!(((back + x) / x).abs() < 1e-2, "{:e} printed as {neg}", -x);
        }
        assert_eq!(sig(0.0, 4), "0");
        assert_eq!(sig(f64::INFINITY, 4), "inf");
        assert_eq!(sig(f64::NAN, 4), "NaN");
        assert_eq!(sig(123.456, 4), "123.5");
        assert_eq!(sig(1.89784150e-7, 9), "1.89784150e-7");
    }

    #[test]
    fn certified_values_are_rounded_not_cut() {
        for e in [-300, -77, -7, 0, 7, 77, 300] {
            let x = 1.897841504987 * 10f64.powi(e);
            let lo = Float::with_val(200, x);
            let hi = Float::with_val(400, x);
            let c = certify(&lo, &hi);
            assert!(c.digits >= 15);
            let s = certified(&c, 9);
            let back: f64 = s.parse().unwrap();
            assert!(((back - x) / x).abs() < 1e-8, "{x:e} printed as {s}");
            assert!(s.matches(char::is_numeric).count() >= 9, "{s}");
        }
        let few = certify(
            &Float::with_val(64, 0.125),
            &Float::with_val(128, 0.1250001),
        );
        assert_eq!(certified(&few, 9), few.text);
    }

    #[test]
    fn cells_are_marked_by_units_of_the_last_digit() {
        assert_eq!(marked("0.6586", Some(0.4)), "0.6586 ✓");
        assert_eq!(marked("0.6586", Some(-0.51)), "0.6586 ≈");
        assert_eq!(marked("470", Some(3.5)), "470 ✗");
        // The paper's empty cell reads as the reports' one "none" sign.
        assert_eq!(marked("-", None), "–");
        assert_eq!(marked("1", Some(f64::NAN)), "1");
    }
}
