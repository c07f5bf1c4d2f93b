//! Certified digits: a number is reported with the significant digits on which two
//! computations at different precisions agree (README, "Precision is a result"; `docs/design.md`, "Precision").
//!
//! A value computed at p bits and again at 2p bits (or more) agrees on about
//! −log₁₀(|x_p − x_2p| / |x_2p|) significant decimal digits; those digits are the ones the
//! report prints. Agreement of two precisions is strong evidence, not a proof: it fails only
//! if both computations share an error that does not shrink with precision (a wrong
//! formula), which the claims check by other means.

use rug::float::Round;
use rug::Float;

/// How many decimal digits `prec` bits can carry: ⌊p·log₁₀2⌋.
pub fn max_digits(prec: u32) -> u32 {
    ((prec as u64 * 30_103) / 100_000) as u32
}

/// The number of leading significant decimal digits on which `lo` and `hi` agree, at most
/// what the lower of the two precisions carries. Two zeros agree to every digit.
pub fn agreeing_digits(lo: &Float, hi: &Float) -> u32 {
    let cap = max_digits(lo.prec().min(hi.prec()));
    if lo == hi {
        return cap;
    }
    if !lo.is_finite() || !hi.is_finite() || hi.is_zero() {
        return 0;
    }
    let work = lo.prec().max(hi.prec());
    let diff = Float::with_val(work, lo - hi).abs();
    let rel = diff / Float::with_val(work, hi.abs_ref());
    let digits = -rel.log10();
    if digits <= 0 {
        0
    } else {
        digits.to_f64().floor().min(cap as f64) as u32
    }
}

/// `x` rounded to `digits` significant decimal digits, as a decimal string: plain notation
/// ("0.6000", "123.4") when the digits reach the units place and the exponent is moderate,
/// otherwise scientific ("1.234e-7", "5.07e49"). Trailing zeros are kept: they are
/// certified digits too.
pub fn format_float_digits(x: &Float, digits: u32) -> String {
    decimal_text(x, digits, Round::Nearest, |point, k| {
        (-4..=0).contains(&point) || (point > 0 && point <= k && point <= 21)
    })
}

/// `x` rounded in direction `round` to `digits` significant decimal digits: in plain notation
/// when `plain(point, k)` holds, with the value 0.mantissa × 10^point and k mantissa digits
/// (zeros pad an integer whose point lies beyond its digits), scientific otherwise. "0" for
/// zero; "NaN", "inf", "-inf" as such. The one decimal printer behind every notation rule
/// (this module's and the reports').
pub fn decimal_text(
    x: &Float,
    digits: u32,
    round: Round,
    plain: impl Fn(i64, i64) -> bool,
) -> String {
    if x.is_zero() {
        return "0".into();
    }
    if !x.is_finite() {
        return if x.is_nan() {
            "NaN".into()
        } else if x.is_sign_negative() {
            "-inf".into()
        } else {
            "inf".into()
        };
    }
    let (negative, mantissa, exp) =
        x.to_sign_string_exp_round(10, Some(digits.max(1) as usize), round);
    let point = exp.unwrap_or(0) as i64; // value = 0.mantissa × 10^point
    let sign = if negative { "-" } else { "" };
    let k = mantissa.len() as i64;
    let plain = plain(point, k);
    let body = if plain && point <= 0 {
        format!("0.{}{}", "0".repeat((-point) as usize), mantissa)
    } else if plain && point > k {
        format!("{mantissa}{}", "0".repeat((point - k) as usize))
    } else if plain {
        let (int, frac) = mantissa.split_at(point as usize);
        if frac.is_empty() {
            int.to_string()
        } else {
            format!("{int}.{frac}")
        }
    } else {
        let (lead, rest) = mantissa.split_at(1);
        let e = point - 1;
        if rest.is_empty() {
            format!("{lead}e{e}")
        } else {
            format!("{lead}.{rest}e{e}")
        }
    };
    format!("{sign}{body}")
}

/// A value known at two precisions, printed with the digits they agree on.
#[derive(Clone, Debug, PartialEq)]
pub struct Certified {
    /// The decimal string with exactly `digits` significant digits.
    pub text: String,
    /// How many significant digits agree (0: none, the value is not known at all).
    pub digits: u32,
    /// The higher-precision value as a double, for plots and f64 comparisons.
    pub approx: f64,
}

/// Certify `hi` (the more precise computation) against `lo`.
pub fn certify(lo: &Float, hi: &Float) -> Certified {
    let digits = agreeing_digits(lo, hi);
    Certified {
        text: format_float_digits(hi, digits),
        digits,
        approx: hi.to_f64_round(Round::Nearest),
    }
}

/// Run `f` at `bits` and at `2·bits` and certify the second result against the first.
/// Returns the certified value and both raw results.
///
/// # Errors
/// The first error of `f`: at `bits` (then `f` is not run at `2·bits`), else at `2·bits`.
pub fn at_two_precisions<E>(
    bits: u32,
    f: impl Fn(u32) -> Result<Float, E>,
) -> Result<(Certified, Float, Float), E> {
    let lo = f(bits)?;
    let hi = f(2 * bits)?;
    Ok((certify(&lo, &hi), lo, hi))
}

/// Relative error |approx − reference| / |reference| of a double against a high-precision
/// reference, computed at the reference's precision (0 when both are zero, ∞ when only the
/// reference is zero).
pub fn relative_error(approx: f64, reference: &Float) -> f64 {
    if !approx.is_finite() {
        return f64::INFINITY;
    }
    let p = reference.prec();
    let diff = Float::with_val(p, approx) - reference;
    if reference.is_zero() {
        return if diff.is_zero() { 0.0 } else { f64::INFINITY };
    }
    (diff / reference).abs().to_f64()
}

/// Correct significant digits of a double against a reference: ⌊−log₁₀ rel. error⌋, at
/// least 0 and at most 17.
pub fn correct_digits(approx: f64, reference: &Float) -> u32 {
    let rel = relative_error(approx, reference);
    if rel == 0.0 {
        return 17;
    }
    let d = -Float::with_val(64, rel).log10().to_f64();
    if d.is_nan() || d <= 0.0 {
        0
    } else {
        d.floor().min(17.0) as u32
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formatting_keeps_exactly_the_requested_digits() {
        let x = Float::with_val(200, 0.6f64); // 0.59999999999999997779…
        assert_eq!(format_float_digits(&x, 4), "0.6000");
        assert_eq!(format_float_digits(&x, 20), "0.59999999999999997780");
        let big = Float::with_val(100, 5.0736e49);
        assert_eq!(format_float_digits(&big, 3), "5.07e49");
        assert_eq!(
            format_float_digits(&Float::with_val(53, 123.456), 4),
            "123.5"
        );
        assert_eq!(
            format_float_digits(&Float::with_val(53, 1200.0), 2),
            "1.2e3"
        );
        assert_eq!(
            format_float_digits(&Float::with_val(53, -1e-7), 2),
            "-1.0e-7"
        );
        assert_eq!(
            format_float_digits(&Float::with_val(53, 0.00012), 2),
            "0.00012"
        );
        assert_eq!(format_float_digits(&Float::with_val(53, 0), 5), "0");
    }

    #[test]
    fn agreement_counts_digits() {
        let third_lo = Float::with_val(64, 1) / 3u32;
        let third_hi = Float::with_val(128, 1) / 3u32;
        let d = agreeing_digits(&third_lo, &third_hi);
        assert!((18..=19).contains(&d), "{d}");
        let a = Float::with_val(100, 1.2345);
        let b = Float::with_val(100, 1.2346);
        assert_eq!(agreeing_digits(&a, &b), 4);
        assert_eq!(
            agreeing_digits(&Float::with_val(64, 0), &Float::with_val(128, 0)),
            19
        );
    }

    #[test]
    fn f64_error_against_reference() {
        let third = Float::with_val(200, 1) / 3u32;
        assert!(correct_digits(1.0 / 3.0, &third) >= 15);
        assert_eq!(correct_digits(0.5, &third), 0);
    }
}
