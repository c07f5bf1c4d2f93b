//! The one number formatter of every report table, summary and figure label.
//!
//! A number shows a chosen count of significant digits, rounded (never a prefix of a longer
//! string, which would drop an exponent: "1.89784150e-7" cut to ten characters reads as 1.9).
//! Its notation is plain from 10⁻³ up to the digits shown or six integer digits
//! ("0.00160821195", "911600", "1670") and scientific otherwise ("2.547675220e-5", "6.94771e7"), so no number opens with a long run of
//! zeros; [`column()`] picks one notation for a whole table column. A certified value shows at
//! most the digits it has. Prose, summaries and evidence show at most ten significant digits
//! ([`shorten`]); `claims.json` keeps every certified digit.
//!
//! [`audit`] lets a test check every number a report shows against the value it was rendered
//! from (to the digits shown), and tell formatter output from text built elsewhere.

use crate::scalar::ball::Ball;
use crate::scalar::certify::{decimal_text, Certified};
use crate::scalar::Float;
use rug::float::Round;

/// The most significant digits a report shows in prose, summaries and evidence.
pub const PROSE_DIGITS: u32 = 10;

/// Plain or scientific notation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Notation {
    /// Plain from 10⁻³ up to the digits shown, scientific otherwise.
    Auto,
    /// Always `d.ddde±k`.
    Scientific,
}

/// `x` rounded to `digits` significant digits in `notation` ("0" for zero; "NaN", "inf",
/// "-inf" as such).
fn style(x: &Float, digits: u32, notation: Notation) -> String {
    style_rounded(x, digits, notation, Round::Nearest)
}

/// [`style`] with the decimal rounding direction given: plain from 10⁻³ up to the digits
/// shown, or up to six integer digits padded with zeros ("1670" rather than "1.67e3" beside
/// "891" in one column).
fn style_rounded(x: &Float, digits: u32, notation: Notation, round: Round) -> String {
    decimal_text(x, digits, round, |point, k| {
        notation == Notation::Auto && (-2..=k.clamp(6, 21)).contains(&point)
    })
}

/// `x` to `digits` significant digits.
pub fn sig(x: f64, digits: u32) -> String {
    sig_in(x, digits, Notation::Auto)
}

/// `x` to `digits` significant digits in `notation`.
pub fn sig_in(x: f64, digits: u32, notation: Notation) -> String {
    if x.is_nan() {
        return "NaN".into();
    }
    let value = Float::with_val(53, x);
    let text = style(&value, digits, notation);
    if x.is_finite() {
        audit::formatted(&text, &value);
    }
    text
}

/// A high-precision `x` to `digits` significant digits.
pub fn float(x: &Float, digits: u32) -> String {
    float_in(x, digits, Notation::Auto)
}

/// A high-precision `x` to `digits` significant digits in `notation`.
pub fn float_in(x: &Float, digits: u32, notation: Notation) -> String {
    let text = style(x, digits, notation);
    if x.is_finite() {
        audit::formatted(&text, x);
    }
    text
}

/// A proven number (a ball) to at most `digits` significant digits: the digits every point of
/// the enclosure rounds to (fewer when it is wider), so the text is true of the value it
/// stands for; "value ± radius" as [`Ball::printed`] gives it when not even one digit is
/// shared, "—" for a ball that is not finite.
pub fn ball(x: &Ball, digits: u32) -> String {
    ball_in(x, digits, Notation::Auto)
}

/// [`ball`] in the given notation (a table column keeps one notation for all its cells).
pub fn ball_in(x: &Ball, digits: u32, notation: Notation) -> String {
    let (lo, hi) = (x.lower(), x.upper());
    for d in (1..=digits).rev() {
        let text = style(&lo, d, notation);
        if text == style(&hi, d, notation) {
            audit::formatted(&text, x.mid());
            return text;
        }
    }
    x.printed()
        .map_or("—".into(), |p| format!("{} ± {}", p.value, p.radius))
}

/// `x` with its sign and `decimals` decimals: a difference such as (ours − printed) in units
/// of a printed cell's last digit.
pub fn signed_fixed(x: f64, decimals: usize) -> String {
    let text = format!("{x:+.decimals$}");
    audit::formatted(text.trim_start_matches('+'), &Float::with_val(64, x));
    text
}

/// A table column: every value to `digits` significant digits in one notation, scientific
/// for the whole column when any of its values needs it.
pub fn column(values: &[f64], digits: u32) -> Vec<String> {
    let notation = if values
        .iter()
        .all(|&x| !sig(x, digits).contains('e') || !x.is_finite())
    {
        Notation::Auto
    } else {
        Notation::Scientific
    };
    values
        .iter()
        .map(|&x| sig_in(x, digits, notation))
        .collect()
}

/// Rows of values as table cells, each column in one notation ([`column()`]).
pub fn columns(rows: &[Vec<f64>], digits: u32) -> Vec<Vec<String>> {
    let width = rows.iter().map(Vec::len).max().unwrap_or(0);
    let cols: Vec<Vec<String>> = (0..width)
        .map(|k| {
            let values: Vec<f64> = rows
                .iter()
                .map(|r| r.get(k).copied().unwrap_or(f64::NAN))
                .collect();
            column(&values, digits)
        })
        .collect();
    (0..rows.len())
        .map(|i| (0..rows[i].len()).map(|k| cols[k][i].clone()).collect())
        .collect()
}

/// A value as the paper prints it (or exact input data as given), shown verbatim.
pub fn printed(text: &str) -> String {
    audit::printed(text);
    text.to_string()
}

/// A certified value with at most `max_digits` of its certified digits, rounded.
pub fn certified(c: &Certified, max_digits: u32) -> String {
    certified_in(c, max_digits, Notation::Auto)
}

/// A certified value with at most `max_digits` of its certified digits, in `notation`.
pub fn certified_in(c: &Certified, max_digits: u32, notation: Notation) -> String {
    // The certified text carries `c.digits` correct digits; rounding it to fewer digits
    // needs a precision that holds them all (about 3.33 bits a digit).
    let bits = (c.digits * 4 + 16).max(64);
    match Float::parse(&c.text) {
        Ok(parsed) if c.digits > 0 => {
            let value = Float::with_val(bits, parsed);
            let text = style(&value, c.digits.min(max_digits), notation);
            audit::formatted(&text, &value);
            text
        }
        _ => c.text.clone(),
    }
}

/// A printed cell marked by how it compares with the computed value, from the difference in
/// units of its last printed digit: "✓" within half a unit (it is the rounded value), "≈"
/// within one unit (the last digit differs), "✗" beyond; unmarked when there is no computed
/// value.
pub fn marked(printed: &str, units: Option<f64>) -> String {
    // A cell the paper leaves empty ("-") reads as the reports' one sign for "none".
    let printed = if printed == "-" { "–" } else { printed };
    audit::printed(printed);
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
    let text = format!("{}{lead}.{rest}e{e}", if negative { "-" } else { "" });
    audit::bound(&text, x, round);
    text
}

/// A bound `x` in the report style with `digits` significant digits, rounded outward
/// (`Round::Down` for a lower bound, `Round::Up` for an upper one), so it is still a bound.
pub fn bound(x: f64, digits: u32, round: Round) -> String {
    let value = Float::with_val(53, x);
    let text = style_rounded(&value, digits, Notation::Auto, round);
    if x.is_finite() {
        audit::bound(&text, &value, round);
    }
    text
}

/// `text` with every decimal number of more than `max` significant digits rounded to `max`
/// ("2.6432542729944189731668883147678153029" → "2.643254273"), and every number below 10⁻³
/// in scientific notation ("0.0000254767522" → "2.54767522e-5"): prose, summaries and
/// evidence in reports show at most ten digits; `claims.json` keeps every certified digit.
/// Numbers inside identifiers (`n8192`, `t1`) and fractions (`3/19`) are left alone.
pub fn shorten(text: &str, max: u32) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some((before, token, after)) = next_number(rest) {
        out.push_str(before);
        out.push_str(&reformat(token, after.starts_with('/'), max).unwrap_or_else(|| token.into()));
        rest = after;
    }
    out.push_str(rest);
    out
}

/// The next decimal number of `text` that is not part of an identifier: the text before it,
/// the number (digits, one optional point, an optional exponent) and the text after it.
pub fn next_number(text: &str) -> Option<(&str, &str, &str)> {
    let bytes = text.as_bytes();
    let mut i = 0;
    while i < bytes.len() {
        let glued = i > 0 && {
            let prev = text[..i].chars().next_back().unwrap_or(' ');
            prev.is_alphanumeric() || prev == '_' || prev == '.'
        };
        if !bytes[i].is_ascii_digit() || glued {
            i += text[i..].chars().next().map_or(1, char::len_utf8);
            continue;
        }
        let start = i;
        let mut seen_point = false;
        while i < bytes.len()
            && (bytes[i].is_ascii_digit()
                || (bytes[i] == b'.'
                    && !seen_point
                    && bytes.get(i + 1).is_some_and(u8::is_ascii_digit)))
        {
            seen_point |= bytes[i] == b'.';
            i += 1;
        }
        // An exponent: e, an optional sign, digits.
        if i < bytes.len() && (bytes[i] == b'e' || bytes[i] == b'E') {
            let mut j = i + 1;
            if j < bytes.len() && (bytes[j] == b'-' || bytes[j] == b'+') {
                j += 1;
            }
            if j < bytes.len() && bytes[j].is_ascii_digit() {
                while j < bytes.len() && bytes[j].is_ascii_digit() {
                    j += 1;
                }
                i = j;
            }
        }
        return Some((&text[..start], &text[start..i], &text[i..]));
    }
    None
}

/// The significant digits of a number token and whether it is below 10⁻³ in plain notation.
pub fn token_shape(token: &str) -> (u32, bool) {
    let mantissa = token.split(['e', 'E']).next().unwrap_or("");
    let significant = mantissa
        .chars()
        .filter(char::is_ascii_digit)
        .skip_while(|&c| c == '0')
        .count() as u32;
    let tiny_plain = !token.contains(['e', 'E']) && mantissa.starts_with("0.000");
    (significant, tiny_plain)
}

/// A number token in the report style when it has more than `max` digits or opens with a long
/// run of zeros; `None` when it is fine as it is (or is a fraction's numerator).
fn reformat(token: &str, numerator: bool, max: u32) -> Option<String> {
    let (significant, tiny_plain) = token_shape(token);
    if numerator || !(significant > max || tiny_plain) {
        return None;
    }
    let parsed = Float::parse(token).ok()?;
    let value = Float::with_val((significant * 4 + 16).max(64), parsed);
    let text = style(&value, significant.min(max), Notation::Auto);
    audit::formatted(&text, &value);
    Some(text)
}

/// A record of the numbers the formatter printed, for tests: each text with whether it shows
/// the value it was rendered from to the digits shown, and the paper's printed values shown
/// verbatim. Off unless a test calls [`audit::start`]; the record is shared by the process.
#[doc(hidden)]
pub mod audit {
    use super::Float;
    use rug::float::Round;
    use std::collections::HashSet;
    use std::sync::Mutex;

    /// What the formatter printed since [`start`].
    #[derive(Clone, Debug, Default)]
    pub struct Record {
        /// Texts that show their value to the digits shown.
        pub formatted: HashSet<String>,
        /// The paper's printed values, shown verbatim.
        pub printed: HashSet<String>,
        /// Texts that do not show their value (with the value): always a defect.
        pub wrong: Vec<String>,
    }

    static RECORD: Mutex<Option<Record>> = Mutex::new(None);

    fn with(f: impl FnOnce(&mut Record)) {
        if let Ok(mut guard) = RECORD.lock() {
            if let Some(record) = guard.as_mut() {
                f(record);
            }
        }
    }

    /// Start recording (idempotent).
    pub fn start() {
        if let Ok(mut guard) = RECORD.lock() {
            guard.get_or_insert_with(Record::default);
        }
    }

    /// A copy of the record so far.
    pub fn record() -> Record {
        RECORD
            .lock()
            .ok()
            .and_then(|g| g.clone())
            .unwrap_or_default()
    }

    /// The unit of the last digit `text` shows, and its value, at `bits`.
    fn unit_and_value(text: &str, bits: u32) -> Option<(Float, Float)> {
        let (mantissa, exp) = match text.split_once(['e', 'E']) {
            Some((m, e)) => (m, e.parse::<i32>().ok()?),
            None => (text, 0),
        };
        // An integer's trailing zeros pad it ("1670" from 1668 to three digits): the unit is
        // that of its last nonzero digit.
        let fraction_digits = match mantissa.split_once('.') {
            Some((_, f)) => f.len() as i32,
            None => -((mantissa.len() - mantissa.trim_end_matches('0').len()) as i32),
        };
        let unit = rug::ops::Pow::pow(Float::with_val(bits, 10), exp - fraction_digits);
        let shown = Float::with_val(bits, Float::parse(text).ok()?);
        Some((unit, shown))
    }

    /// `text` was rendered from `value` to nearest: it must be within half a unit of its last
    /// digit.
    pub(super) fn formatted(text: &str, value: &Float) {
        with(|r| {
            let bits = value.prec().max(128) + 64;
            let ok = unit_and_value(text, bits).is_some_and(|(unit, shown)| {
                let slack = Float::with_val(bits, &unit * 1e-9);
                Float::with_val(bits, &shown - value).abs() <= unit / 2 + slack
            });
            if ok {
                r.formatted.insert(text.to_string());
            } else {
                r.wrong.push(format!("{text} (from {value})"));
            }
        });
    }

    /// `text` was rendered from `value` rounded outward (`round`): within one unit of its last
    /// digit, on the side that keeps it a bound.
    pub(super) fn bound(text: &str, value: &Float, round: Round) {
        with(|r| {
            let bits = value.prec().max(128) + 64;
            let ok = unit_and_value(text, bits).is_some_and(|(unit, shown)| {
                let diff = Float::with_val(bits, &shown - value);
                let side = match round {
                    Round::Down => diff <= 0,
                    Round::Up => diff >= 0,
                    _ => true,
                };
                side && diff.abs() <= unit
            });
            if ok {
                r.formatted.insert(text.to_string());
            } else {
                r.wrong.push(format!("{text} (bound of {value})"));
            }
        });
    }

    /// Each decimal number of `text` with its sign, and whether it is exact as written (an
    /// integer, or part of a fraction such as 3/19).
    fn tokens(text: &str) -> Vec<(String, bool)> {
        let mut out = Vec::new();
        let mut rest = text;
        while let Some((before, token, after)) = super::next_number(rest) {
            let exact =
                !token.contains(['.', 'e', 'E']) || before.ends_with('/') || after.starts_with('/');
            let negative = before.ends_with('-') || before.ends_with('−');
            out.push((format!("{}{token}", if negative { "-" } else { "" }), exact));
            rest = after;
        }
        out
    }

    /// The problems of one Markdown report against the record: every decimal number of a table
    /// cell (outside the claims ledger, whose evidence columns are prose, and the first
    /// column, which labels the row) must be the formatter's output shown to its digits, or a
    /// printed value; one notation per column; nowhere more than ten significant digits or a
    /// long run of leading zeros. Empty when the report is sound; call after rendering it.
    pub fn check(markdown: &str) -> Vec<String> {
        let record = record();
        let mut problems: Vec<String> = record
            .wrong
            .iter()
            .map(|w| format!("a number that does not show its value: {w}"))
            .collect();
        let mut table: Option<Table> = None;
        for line in markdown.lines() {
            // Outside code spans (claim ids such as `phodcos.table1.n16`).
            let prose: String = line.split('`').step_by(2).collect::<Vec<_>>().join(" ");
            for (token, _) in tokens(&prose).into_iter().filter(|(_, exact)| !exact) {
                let (significant, tiny_plain) = super::token_shape(&token);
                if significant > super::PROSE_DIGITS || tiny_plain {
                    problems.push(format!("{token} in: {line}"));
                }
            }
            if !line.starts_with('|') {
                if let Some(t) = table.take() {
                    problems.extend(t.mixed_columns());
                }
                continue;
            }
            let cells: Vec<&str> = line.trim_matches('|').split(" | ").map(str::trim).collect();
            match table.as_mut() {
                None => table = Some(Table::new(&cells)),
                Some(t) => problems.extend(t.row(&cells, line, &record)),
            }
        }
        if let Some(t) = table.take() {
            problems.extend(t.mixed_columns());
        }
        problems
    }

    /// One Markdown table being checked: its columns' notations so far.
    struct Table {
        ledger: bool,
        columns: Vec<Vec<(bool, String)>>,
    }

    impl Table {
        fn new(header: &[&str]) -> Self {
            Table {
                ledger: header.starts_with(&["id", "location", "published", "reproduced"]),
                columns: vec![Vec::new(); header.len()],
            }
        }

        /// The problems of one row; the separator row and the ledger's rows have none.
        fn row(&mut self, cells: &[&str], line: &str, record: &Record) -> Vec<String> {
            let mut problems = Vec::new();
            if self.ledger || cells.iter().all(|c| c.chars().all(|ch| "-|".contains(ch))) {
                return problems;
            }
            for (k, cell) in cells.iter().enumerate().skip(1) {
                let bare = cell.trim_end_matches([' ', '✓', '≈', '✗']);
                if record.printed.contains(bare) {
                    continue;
                }
                let found = tokens(bare);
                for (token, exact) in &found {
                    if !exact && !record.formatted.contains(token) {
                        problems.push(format!(
                            "{token} (cell '{cell}') is not the formatter's: {line}"
                        ));
                    }
                }
                // A single number in the cell, the formatter's (an integer count is not);
                // zero has no notation.
                if let [(single, exact)] = found.as_slice() {
                    if single != "0" && (!exact || record.formatted.contains(single)) {
                        if let Some(col) = self.columns.get_mut(k) {
                            col.push((single.contains('e'), single.clone()));
                        }
                    }
                }
            }
            problems
        }

        fn mixed_columns(self) -> Vec<String> {
            self.columns
                .into_iter()
                .filter(|col| {
                    let scientific = col.iter().filter(|(s, _)| *s).count();
                    scientific > 0 && scientific < col.len()
                })
                .map(|col| {
                    let texts: Vec<&String> = col.iter().map(|(_, t)| t).collect();
                    format!("a column mixes notations: {texts:?}")
                })
                .collect()
        }
    }

    /// A value the paper prints, shown verbatim.
    pub(super) fn printed(text: &str) {
        with(|r| {
            r.printed.insert(text.to_string());
        });
    }
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
