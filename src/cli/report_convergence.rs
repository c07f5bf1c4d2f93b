//! `trajverify report convergence`: a convergence study of a user's own curve, as a report.
//!
//! This module parses the options, reads the curve (an expression, or a CSV file fitted by a
//! quintic spline), checks the work budget, runs the study of the library
//! ([`crate::algo::convergence`]) with progress on stderr, and writes the three files the
//! report module renders ([`crate::report::convergence`]), each complete or not at all.
// The option docs below are clap's `--help` text, where `<m>` and `<bits>` are literal.
#![allow(rustdoc::invalid_html_tags)]

use super::budget;
use super::input::{fail, InputError};
use super::Failure;
use crate::algo::convergence::{self, Method, StudyCurve, StudyOptions};
use crate::curve::interval::Interval;
use crate::curve::spline::{ClampedSpline, PeriodicSpline};
use crate::curve::ExprCurve;
use crate::report::convergence::Described;
use crate::scalar::{Field, ScalarKind};
use std::path::Path;
use std::time::Instant;

pub use crate::algo::convergence::MAX_LEVEL;

/// Where the curve comes from.
pub enum Source {
    /// An expression `[x(t), y(t), z(t)]`.
    Expression(String),
    /// A CSV file of samples t, x, y, z: a closed curve when the last row repeats the first
    /// point (one period later), fitted by the periodic quintic spline of paper 001, Sec. 6A;
    /// otherwise an open curve, fitted by the clamped quintic spline (C⁴ either way).
    Data(std::path::PathBuf),
}

/// The curve, parsed or fitted.
enum Parsed {
    Expression(ExprCurve),
    /// The spline through the data and the number of rows.
    Closed(PeriodicSpline, usize),
    Open(ClampedSpline, usize),
}

impl Parsed {
    fn study_curve(&self) -> &dyn StudyCurve {
        match self {
            Parsed::Expression(e) => e,
            Parsed::Closed(s, _) => s,
            Parsed::Open(s, _) => s,
        }
    }
}

/// The most rows a data file may have.
const MAX_ROWS: usize = 1_000_000;

/// Read t, x, y, z rows (a header line and extra columns are allowed) and fit the periodic
/// quintic spline when the last row repeats the first point (a closed curve), the clamped
/// one otherwise.
fn read_data(path: &std::path::Path) -> Result<Parsed, InputError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| InputError(format!("option --data: {}: {e}", path.display())))?;
    let mut times = Vec::new();
    let mut points = Vec::new();
    for (i, line) in text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty())
    {
        let fields: Vec<&str> = line.split(',').map(str::trim).collect();
        let numbers: Option<Vec<f64>> = fields
            .iter()
            .take(4)
            .map(|f| f.parse::<f64>().ok().filter(|x| x.is_finite()))
            .collect();
        match numbers {
            Some(v) if v.len() == 4 => {
                times.push(v[0]);
                points.push([v[1], v[2], v[3]]);
            }
            _ if i == 0 => continue, // a header
            _ => {
                return fail(format!(
                    "option --data: line {}: expected numbers t, x, y, z",
                    i + 1
                ))
            }
        }
        if times.len() > MAX_ROWS {
            return fail(format!("option --data: more than {MAX_ROWS} rows"));
        }
    }
    let n = times.len();
    if n < 6 {
        return fail("option --data: at least 6 rows (a quintic spline needs 6 samples)");
    }
    let size = points
        .iter()
        .flatten()
        .fold(0.0f64, |m, x| m.max(x.abs()))
        .max(1.0);
    let gap = (0..3)
        .map(|k| (points[n - 1][k] - points[0][k]).abs())
        .fold(0.0, f64::max);
    let start = Instant::now();
    let fitted = if gap <= 1e-9 * size {
        if n < 8 {
            return fail("option --data: a closed curve needs at least 8 rows (7 samples and the closing row)");
        }
        PeriodicSpline::interpolate(5, &times[..n - 1], times[n - 1], &points[..n - 1])
            .map(|s| Parsed::Closed(s, n))
    } else {
        ClampedSpline::interpolate(5, &times, &points).map(|s| Parsed::Open(s, n))
    };
    let fitted = fitted.map_err(|e| InputError(format!("option --data: {e}")))?;
    // Progress only once the fit stands: a refusal is the one line on stderr.
    eprintln!(
        "fitted the quintic spline through {n} rows, {:.1} s",
        start.elapsed().as_secs_f64()
    );
    Ok(fitted)
}

/// What the user asked for.
pub struct Request {
    /// The curve: an expression or a data file.
    pub source: Source,
    /// The interval [a, b], as written.
    pub interval: (String, String),
    /// "phodcos" or "hermite:<m>".
    pub method: String,
    /// The levels, e.g. "0-10", "2-2" or "2,4,6".
    pub levels: String,
    /// mpfr:<bits> (sampled maxima, not certified) or ball:<bits> (proven, the default).
    pub scalar: ScalarKind,
}

/// Parse "a-b" or "n1,n2,…" into increasing levels within [0, MAX_LEVEL] (one level is
/// allowed: it has an error but no order).
fn parse_levels(text: &str) -> Result<Vec<u32>, InputError> {
    let bad = || {
        InputError(format!(
            "option --levels: {text:?} is not \"a-b\" (a ≤ b) or a comma list of increasing levels 0…{MAX_LEVEL}"
        ))
    };
    let levels: Vec<u32> = if let Some((a, b)) = text.split_once('-') {
        let (a, b): (u32, u32) = (
            a.trim().parse().map_err(|_| bad())?,
            b.trim().parse().map_err(|_| bad())?,
        );
        (a..=b).collect()
    } else {
        text.split(',')
            .map(|s| s.trim().parse().map_err(|_| bad()))
            .collect::<Result<_, _>>()?
    };
    convergence::check_levels(&levels).map_err(|_| bad())?;
    Ok(levels)
}

/// The options that do not depend on the curve, checked before any data is read.
struct Options {
    interval: Interval,
    study: StudyOptions,
}

fn options(r: &Request) -> Result<Options, InputError> {
    let method =
        Method::parse(&r.method).map_err(|e| InputError(format!("option --method: {e}")))?;
    // Each end a number or a constant expression ("4*pi"), kept exact.
    let interval = Interval::parse(&r.interval.0, &r.interval.1)
        .map_err(|e| InputError(format!("option --{e}")))?;
    let levels = parse_levels(&r.levels)?;
    let (bits, proof) = match r.scalar {
        ScalarKind::Ball(bits) => (bits, true),
        ScalarKind::Mpfr(bits) => (bits, false),
        other => return fail(format!("option --scalar: {other} is not available here: the report proves with ball:<bits> or samples with mpfr:<bits>")),
    };
    Ok(Options {
        interval,
        study: StudyOptions {
            method,
            levels,
            bits,
            proof,
        },
    })
}

/// Refuse a request whose estimated time exceeds the budget of one run. Measured on two
/// cores at 256 bits, per segment and level (the f64 pipeline is negligible beside them):
/// Eq. (23) 0.6 ms sampled, 1.7 ms with the proof; the NRHO spline 0.7 and 3.4 ms, and with
/// the proof also about 2.5 ms per knot inside the interval and level (the pieces split
/// there). The Hermite method costs less than the PH conversion; the PH rates bound it.
fn check_budget(r: &Request, curve: &Parsed, o: &Options) -> Result<(), InputError> {
    let levels = &o.study.levels;
    let segments: f64 = levels.iter().map(|&n| f64::from(n).exp2()).sum();
    let proven = o.study.proof;
    let width = {
        let (a, b) = o.interval.to_f64();
        b - a
    };
    let (per_segment, knots) = match curve {
        Parsed::Expression(_) => (if proven { 1.7e-3 } else { 6e-4 }, 0.0),
        Parsed::Closed(s, rows) => {
            let (start, end) = s.domain();
            let period = end - start;
            (
                if proven { 3.4e-3 } else { 7e-4 },
                *rows as f64 * (width / period).max(1.0),
            )
        }
        Parsed::Open(s, rows) => {
            let (first, last) = s.domain();
            (
                if proven { 3.4e-3 } else { 7e-4 },
                *rows as f64 * (width / (last - first)).min(1.0),
            )
        }
    };
    let knot_levels = if proven {
        knots * levels.len() as f64 * 2.5e-3
    } else {
        0.0
    };
    budget::check_time(
        (segments * per_segment + knot_levels) * budget::mpfr_factor(o.study.bits),
        "levels",
        &format!("{segments} segments at {}", r.scalar),
    )
}

/// Write the report for `r` into `out`.
pub fn run(r: &Request, out: &Path) -> Result<String, Failure> {
    let usage = |e: InputError| Failure::Usage(e.0);
    let o = options(r).map_err(usage)?;
    let curve = match &r.source {
        Source::Expression(text) => Parsed::Expression(
            ExprCurve::parse(text).map_err(|e| Failure::Usage(format!("option --curve: {e}")))?,
        ),
        Source::Data(path) => read_data(path).map_err(usage)?,
    };
    if let Parsed::Open(spline, _) = &curve {
        // An open curve is known only between its first and last samples.
        let (first, last) = spline.domain();
        // Decided on floats around the exact ends, so an end a rounding would move inside
        // the data is refused.
        let (lo, hi) = o.interval.enclosure(128);
        if lo < first || hi > last {
            return Err(Failure::Usage(format!("option --interval: an open curve's data cover only [{first}, {last}] (the first and last times)")));
        }
    }
    check_budget(r, &curve, &o).map_err(usage)?;
    let start = Instant::now();
    let mut progress = |n: u32, segments: usize| {
        eprintln!(
            "level {n} ({segments} segments) done, {:.1} s",
            start.elapsed().as_secs_f64()
        );
    };
    let study = convergence::study(curve.study_curve(), &o.interval, &o.study, &mut progress)
        .map_err(|e| match e {
            convergence::StudyError::Irregular(i) => Failure::Usage(format!(
                "option --curve: on [{}, {}] {i}",
                r.interval.0, r.interval.1
            )),
            convergence::StudyError::Failed { .. } => {
                Failure::Usage(format!("option --curve: {e}"))
            }
            other => Failure::Usage(format!("option --levels: {other}")),
        })?;
    let (curve_text, label) = match (&r.source, &curve) {
        (Source::Data(path), Parsed::Closed(_, rows)) => (
            format!("given by `{}` ({rows} rows of a closed curve; periodic quintic spline, paper 001 Sec. 6A)", path.display()),
            path.file_name().map_or("data".into(), |f| f.to_string_lossy().into_owned()),
        ),
        (Source::Data(path), Parsed::Open(_, rows)) => (
            format!("given by `{}` ({rows} rows of an open curve; quintic spline on a clamped knot vector with averaged interior knots, C⁴)", path.display()),
            path.file_name().map_or("data".into(), |f| f.to_string_lossy().into_owned()),
        ),
        (Source::Expression(text), _) => (format!("`{text}`"), text.clone()),
        (Source::Data(path), _) => (path.display().to_string(), path.display().to_string()),
    };
    let described = Described {
        curve: &curve_text,
        label: &label,
        interval: (&r.interval.0, &r.interval.1),
        scalar: r.scalar.to_string(),
    };
    let files = crate::report::convergence::files(&study, &described);
    crate::report::write_files(out, &files)
        .map_err(|e| Failure::Usage(format!("option --out: {e}")))?;
    Ok(format!(
        "wrote {} files to {}\n",
        files.len(),
        out.display()
    ))
}
