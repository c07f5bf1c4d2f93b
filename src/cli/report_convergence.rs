//! `trajverify report convergence`: Table 1 for a user's own curve, as a report.
//!
//! For each refinement level n the curve is approximated on 2ⁿ uniform segments — converted
//! to C⁴ PH interpolants with φ* = 0 (`--method phodcos`, paper 001), or interpolated by
//! two-point Hermite pieces in Bernstein form (`--method hermite:<m>`, paper 000) — and the
//! error E = max_ξ ‖γ − p‖ (paper 001, Eq. 21) is found:
//! certified (MPFR at p and 2p bits, sampled maxima refined by Newton) and, with
//! `--scalar ball:<bits>`, proven (a branch-and-bound enclosure in balls). Beside it, the same
//! pipeline in f64. The report gives the observed order of each refinement, log₂(E_{n−1}/E_n),
//! a least-squares order over the finer half of the levels with a 95 % confidence interval
//! (Student's t on the residuals; "exact fit" when they vanish) set against the order the
//! theory expects (6 by Theorem 1; 2m + 2 by the classical Hermite remainder), and the level
//! from which f64 stops improving. It writes `convergence.md`, `convergence.svg` and
//! `convergence.json` into the output directory, each complete or not at all.

use super::budget;
use super::input::{fail, InputError};
use super::Failure;
use crate::algo::hermite;
use crate::algo::ph::hermite::FreeParameters;
use crate::algo::ph::piecewise::{certified_error, convert, observed_order};
use crate::curve::approx::{
    certified_max_error, conversion_error, BernsteinPieces, PiecewiseBernstein, DEFAULT_SAMPLES,
};
use crate::curve::enclosure::proven_error;
use crate::curve::spline::{ClampedSpline, PeriodicSpline};
use crate::curve::{Curve, ExprCurve};
use crate::report::number::{bound_text, sig};
use crate::report::plot::{self, Corner, Panel, Series, Style};
use crate::report::table;
use crate::scalar::ball::Ball;
use crate::scalar::{BigRational, Field, Float, Real, ScalarKind};
use rug::float::Round;
use serde_json::json;
use std::path::Path;
use std::time::Instant;

/// The deepest level accepted (2¹⁴ segments).
pub const MAX_LEVEL: u32 = 14;

/// One refinement level.
struct Level {
    segments: usize,
    /// The certified error: (value at p bits, at 2p bits).
    certified: (Float, Float),
    /// Proven bounds (ball runs only).
    proven: Option<(Float, Float)>,
    /// The f64 pipeline's error.
    f64_error: f64,
}

/// Where the curve comes from.
pub enum Source {
    /// An expression `[x(t), y(t), z(t)]`.
    Expression(String),
    /// A CSV file of samples t, x, y, z: a closed curve when the last row repeats the first
    /// point (one period later), fitted by the periodic quintic spline of paper 001, Sec. 6A;
    /// otherwise an open curve, fitted by the clamped quintic spline (C⁴ either way).
    Data(std::path::PathBuf),
}

/// The curve in one number type: an expression compiled for it, or the data's spline
/// (borrowed: it is the same exact piecewise polynomial in every type).
enum UserCurve<'a, T> {
    Expression(crate::curve::CompiledCurve<T>),
    Closed(&'a PeriodicSpline),
    Open(&'a ClampedSpline),
}

impl<T: crate::scalar::Real> UserCurve<'_, T> {
    fn as_curve(&self) -> &dyn Curve<T> {
        match self {
            UserCurve::Expression(c) => c,
            UserCurve::Closed(s) => *s,
            UserCurve::Open(s) => *s,
        }
    }
}

impl<T: crate::scalar::Real> Curve<T> for UserCurve<'_, T> {
    fn jet(&self, t: &T, order: usize) -> Vec<[T; 3]> {
        self.as_curve().jet(t, order)
    }
    fn seam_bound(&self, lo: f64, centre: (f64, f64), hi: f64) -> f64 {
        self.as_curve().seam_bound(lo, centre, hi)
    }
    fn breakpoints(&self, lo: f64, hi: f64) -> Vec<f64> {
        self.as_curve().breakpoints(lo, hi)
    }
}

/// The parsed curve, before it is put into a number type.
enum Parsed {
    Expression(ExprCurve),
    /// The spline through the data and the number of rows.
    Closed(PeriodicSpline, usize),
    Open(ClampedSpline, usize),
}

impl Parsed {
    fn in_type<T: crate::scalar::Real>(&self, ctx: &T::Ctx) -> UserCurve<'_, T> {
        match self {
            Parsed::Expression(e) => UserCurve::Expression(e.compile::<T>(ctx)),
            Parsed::Closed(s, _) => UserCurve::Closed(s),
            Parsed::Open(s, _) => UserCurve::Open(s),
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
    eprintln!(
        "fitted the quintic spline through {n} rows, {:.1} s",
        start.elapsed().as_secs_f64()
    );
    fitted.map_err(|e| InputError(format!("option --data: {e}")))
}

/// What the user asked for.
pub struct Request {
    /// The curve: an expression or a data file.
    pub source: Source,
    /// The interval [a, b], as written.
    pub interval: (String, String),
    /// "phodcos" or "hermite:<m>".
    pub method: String,
    /// The levels, e.g. "0-10" or "2,4,6".
    pub levels: String,
    /// mpfr:<bits> or ball:<bits>.
    pub scalar: ScalarKind,
}

/// The approximation whose error is measured.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Method {
    /// C⁴ PH interpolants with φ* = 0 (paper 001, Algorithm 2).
    Phodcos,
    /// Piecewise Hermite–Bernstein interpolation with m derivatives at every joint (paper 000).
    Hermite(usize),
}

/// The most derivatives per joint for `hermite:<m>`: degree 2m + 1 ≤ 17, what the proven
/// enclosure's Taylor models cover.
const MAX_HERMITE_DERIVATIVES: usize = (crate::curve::enclosure::ORDER - 1) / 2;

impl Method {
    fn parse(text: &str) -> Result<Method, InputError> {
        if text == "phodcos" {
            return Ok(Method::Phodcos);
        }
        match text.strip_prefix("hermite:").map(str::parse::<usize>) {
            Some(Ok(m)) if m <= MAX_HERMITE_DERIVATIVES => Ok(Method::Hermite(m)),
            _ => fail(format!(
                "option --method: {text:?} is not \"phodcos\" or \"hermite:M\" with M in 0…{MAX_HERMITE_DERIVATIVES}"
            )),
        }
    }

    /// The order the theory predicts for a smooth curve, and where it comes from.
    fn expected_order(self) -> (usize, &'static str) {
        match self {
            Method::Phodcos => (6, "Theorem 1 of paper 001"),
            Method::Hermite(m) => (
                2 * m + 2,
                "the classical Hermite remainder; paper 000 claims no order",
            ),
        }
    }

    fn title(self) -> String {
        match self {
            Method::Phodcos => "the PHODCOS conversion".into(),
            Method::Hermite(m) => format!("piecewise Hermite–Bernstein interpolation (m = {m})"),
        }
    }

    fn pieces(self) -> String {
        match self {
            Method::Phodcos => "C⁴ PH interpolants (φ* = 0)".into(),
            Method::Hermite(m) => format!(
                "two-point Hermite interpolants of degree {} in Bernstein form (paper 000, Eqs. 11–18; C^{m} at the joints)",
                2 * m + 1
            ),
        }
    }
}

/// The checked request.
struct Plan {
    curve: Parsed,
    a: BigRational,
    b: BigRational,
    levels: Vec<u32>,
    bits: u32,
    method: Method,
}

/// Parse "a-b" or "n1,n2,…" into increasing levels within [0, MAX_LEVEL].
fn parse_levels(text: &str) -> Result<Vec<u32>, InputError> {
    let bad = || {
        InputError(format!(
            "option --levels: {text:?} is not \"a-b\" or a comma list of levels 0…{MAX_LEVEL}"
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
    if levels.len() < 2
        || levels.windows(2).any(|w| w[1] <= w[0])
        || levels.iter().any(|&n| n > MAX_LEVEL)
    {
        return Err(bad());
    }
    Ok(levels)
}

/// Check the request; return the parsed curve, interval and levels.
fn validate(r: &Request) -> Result<Plan, InputError> {
    let method = Method::parse(&r.method)?;
    let curve = match &r.source {
        Source::Expression(text) => Parsed::Expression(
            ExprCurve::parse(text).map_err(|e| InputError(format!("option --curve: {e}")))?,
        ),
        Source::Data(path) => read_data(path)?,
    };
    let read = |s: &str| {
        crate::scalar::parse::parse_rational(s)
            .map_err(|_| InputError(format!("option --interval: {s:?} is not a number")))
    };
    let (a, b) = (read(&r.interval.0)?, read(&r.interval.1)?);
    if b <= a {
        return fail("option --interval: need a < b");
    }
    if let Parsed::Open(spline, _) = &curve {
        // An open curve is known only between its first and last samples.
        let (first, last) = spline.domain();
        if a.to_f64() < first || b.to_f64() > last {
            return fail(format!("option --interval: an open curve's data cover only [{first}, {last}] (the first and last times)"));
        }
    }
    let levels = parse_levels(&r.levels)?;
    let bits = match r.scalar {
        ScalarKind::Mpfr(bits) | ScalarKind::Ball(bits) => bits,
        other => return fail(format!("option --scalar: {other} is not available here: the report certifies with mpfr:<bits> or proves with ball:<bits>")),
    };
    check_budget(r, &curve, (&a, &b), &levels, bits)?;
    Ok(Plan {
        curve,
        a,
        b,
        levels,
        bits,
        method,
    })
}

/// Refuse a request whose estimated time exceeds the budget of one run. Measured on two
/// cores at 256 bits, per segment and level (the f64 pipeline is negligible beside them):
/// Eq. (23) 0.6 ms certified, 1.7 ms with the proof; the NRHO spline 0.7 and 3.4 ms, and with
/// the proof also about 2.5 ms per knot inside the interval and level (the pieces split
/// there). The Hermite method costs less than the PH conversion; the PH rates bound it.
fn check_budget(
    r: &Request,
    curve: &Parsed,
    (a, b): (&BigRational, &BigRational),
    levels: &[u32],
    bits: u32,
) -> Result<(), InputError> {
    let segments: f64 = levels.iter().map(|&n| f64::from(n).exp2()).sum();
    let proven = matches!(r.scalar, ScalarKind::Ball(_));
    let width = (b.clone() - a).to_f64();
    let (per_segment, knots) = match curve {
        Parsed::Expression(_) => (if proven { 1.7e-3 } else { 6e-4 }, 0.0),
        Parsed::Closed(s, rows) => {
            let period = s.period_end - s.times[0];
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
        (segments * per_segment + knot_levels) * budget::mpfr_factor(bits),
        "levels",
        &format!("{segments} segments at {}", r.scalar),
    )
}

/// Compute every level, reporting progress on stderr.
fn compute(r: &Request, plan: &Plan) -> Result<Vec<Level>, Failure> {
    let start = Instant::now();
    let mut out = Vec::new();
    for &n in &plan.levels {
        let segments = 1usize << n;
        let failed = |what: &str, e: String| {
            Failure::Internal(format!("the {what} failed on {segments} segments: {e}"))
        };
        let certified = certified_level(plan, segments).map_err(|e| failed("conversion", e))?;
        let proven = match r.scalar {
            ScalarKind::Ball(bits) => {
                Some(proven_level(plan, segments, bits).map_err(|e| failed("ball conversion", e))?)
            }
            _ => None,
        };
        eprintln!(
            "level {n} ({segments} segments) done, {:.1} s",
            start.elapsed().as_secs_f64()
        );
        out.push(Level {
            segments,
            certified,
            proven,
            f64_error: f64_level(plan, segments),
        });
    }
    Ok(out)
}

/// The fit of `curve` on `segments` pieces of [a, b] by the plan's method, in any type.
fn fit<T: Real>(
    method: Method,
    curve: &UserCurve<'_, T>,
    (a, b): (&T, &T),
    segments: usize,
) -> Result<Fitted<T>, String> {
    Ok(match method {
        Method::Phodcos => {
            let zero = FreeParameters::zero(4, &a.ctx());
            Fitted::Ph(convert(curve, a, b, segments, 4, &zero, false).map_err(|e| e.to_string())?)
        }
        Method::Hermite(m) => Fitted::Hermite(
            hermite::piecewise::interpolate_curve(curve, (a, b), segments, m)
                .map_err(|e| e.to_string())?,
        ),
    })
}

/// The certified error (at p and 2p bits) on `segments` pieces.
fn certified_level(plan: &Plan, segments: usize) -> Result<(Float, Float), String> {
    let e = match plan.method {
        // One segment refitted at 2p bits (what Table 1 uses).
        Method::Phodcos => certified_error(
            |p| plan.curve.in_type::<Float>(&p),
            &plan.a,
            &plan.b,
            segments,
            4,
            &FreeParameters::zero(4, &()),
            plan.bits,
            2 * plan.bits,
        )
        .map_err(|e| e.to_string())?,
        Method::Hermite(_) => certified_max_error(
            |p| plan.curve.in_type::<Float>(&p),
            |c, p| {
                let (a, b) = (
                    Float::from_rational(&plan.a, &p),
                    Float::from_rational(&plan.b, &p),
                );
                fit(plan.method, c, (&a, &b), segments)
            },
            plan.bits,
            2 * plan.bits,
        )?,
    };
    Ok((e.lo, e.hi))
}

/// The proven enclosure [lower, upper] in ball:<bits>.
fn proven_level(plan: &Plan, segments: usize, bits: u32) -> Result<(Float, Float), String> {
    let c = plan.curve.in_type::<Ball>(&bits);
    let (a, b) = (
        Ball::from_rational(&plan.a, &bits),
        Ball::from_rational(&plan.b, &bits),
    );
    let e = proven_error(
        &c,
        &fit(plan.method, &c, (&a, &b), segments)?,
        1e-6,
        4_000_000,
    );
    Ok((e.lower, e.upper))
}

/// The error of the same pipeline in f64 (NaN when it fails there).
fn f64_level(plan: &Plan, segments: usize) -> f64 {
    let c = plan.curve.in_type::<f64>(&());
    fit(
        plan.method,
        &c,
        (&plan.a.to_f64(), &plan.b.to_f64()),
        segments,
    )
    .map_or(f64::NAN, |pw| {
        conversion_error(&c, &pw, DEFAULT_SAMPLES).max
    })
}

/// A fit by either method: both are pieces in Bernstein form.
enum Fitted<T> {
    Ph(crate::algo::ph::piecewise::PiecewisePh<T>),
    Hermite(PiecewiseBernstein<T>),
}

impl<T: Real> BernsteinPieces<T> for Fitted<T> {
    fn interval(&self) -> (&T, &T) {
        match self {
            Fitted::Ph(p) => p.interval(),
            Fitted::Hermite(p) => p.interval(),
        }
    }
    fn count(&self) -> usize {
        match self {
            Fitted::Ph(p) => p.count(),
            Fitted::Hermite(p) => p.count(),
        }
    }
    fn control_points(&self, k: usize) -> Vec<[T; 3]> {
        match self {
            Fitted::Ph(p) => p.control_points(k),
            Fitted::Hermite(p) => p.control_points(k),
        }
    }
}

/// log₂(E_coarse/E_fine) (the library's observed order), `None` when either is zero.
fn order(coarse: &Float, fine: &Float) -> Option<f64> {
    observed_order(coarse, fine).map(|(_, order)| order.to_f64())
}

/// Student's t quantile for a two-sided 95 % interval with `df` degrees of freedom.
fn t95(df: usize) -> f64 {
    const TABLE: [f64; 10] = [
        12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
    ];
    TABLE
        .get(df.wrapping_sub(1))
        .copied()
        .unwrap_or(if df > 30 { 1.96 } else { 2.1 })
}

/// The least-squares order −slope of log₂E against log₂N over the finer half of the levels,
/// with its 95 % confidence half-width (`None` when fewer than 2 usable points).
fn fitted_order(levels: &[Level]) -> Option<(f64, Option<f64>, usize)> {
    let points: Vec<(f64, f64)> = levels[levels.len() / 2..]
        .iter()
        .filter(|l| !l.certified.1.is_zero())
        .map(|l| {
            (
                (l.segments as f64).log2(),
                Float::with_val(64, l.certified.1.log2_ref()).to_f64(),
            )
        })
        .collect();
    let k = points.len();
    if k < 2 {
        return None;
    }
    let mx = points.iter().map(|p| p.0).sum::<f64>() / k as f64;
    let my = points.iter().map(|p| p.1).sum::<f64>() / k as f64;
    let sxx: f64 = points.iter().map(|p| (p.0 - mx).powi(2)).sum();
    let slope = points.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum::<f64>() / sxx;
    let ci = (k > 2).then(|| {
        let rss: f64 = points
            .iter()
            .map(|p| (p.1 - my - slope * (p.0 - mx)).powi(2))
            .sum();
        t95(k - 2) * (rss / (k - 2) as f64 / sxx).sqrt()
    });
    Some((-slope, ci, k))
}

/// The observed orders across the levels the fit uses, (first, last), when they move
/// monotonically (at least two of them): the order is still drifting there, which the
/// constant-order fit and its interval do not model.
fn order_drift(levels: &[Level]) -> Option<(f64, f64)> {
    let window = &levels[levels.len() / 2..];
    let orders: Vec<f64> = window
        .windows(2)
        .filter_map(|w| order(&w[0].certified.1, &w[1].certified.1))
        .collect();
    let rising = orders.windows(2).all(|w| w[1] > w[0]);
    let falling = orders.windows(2).all(|w| w[1] < w[0]);
    (orders.len() >= 2 && orders.len() + 1 == window.len() && (rising || falling))
        .then(|| (orders[0], orders[orders.len() - 1]))
}

/// The first level from which f64 stops improving: its error no longer falls while the
/// certified one still does by more than a factor 2.
fn f64_floor(levels: &[Level]) -> Option<usize> {
    (1..levels.len()).find(|&i| {
        let (prev, cur) = (levels[i - 1].f64_error, levels[i].f64_error);
        let certified_falls =
            order(&levels[i - 1].certified.1, &levels[i].certified.1).is_some_and(|o| o > 1.0);
        certified_falls && cur.is_finite() && prev.is_finite() && cur >= prev / 2.0
    })
}

/// The first level whose f64 error is more than 10 % away from the certified one: from there
/// f64 no longer measures the conversion but its own rounding.
fn f64_departs(levels: &[Level]) -> Option<usize> {
    levels.iter().position(|l| {
        let exact = l.certified.1.to_f64();
        exact > 0.0 && ((l.f64_error - exact) / exact).abs() > 0.1
    })
}

/// Write the report for `r` into `out`.
pub fn run(r: &Request, out: &Path) -> Result<String, Failure> {
    let plan = validate(r).map_err(|e| Failure::Usage(e.0))?;
    let (curve, bits) = (&plan.curve, plan.bits);
    let described = match (&r.source, curve) {
        (Source::Data(path), Parsed::Closed(_, rows)) => {
            format!("given by `{}` ({rows} rows of a closed curve; periodic quintic spline, paper 001 Sec. 6A)", path.display())
        }
        (Source::Data(path), Parsed::Open(_, rows)) => {
            format!("given by `{}` ({rows} rows of an open curve; quintic spline on a clamped knot vector with averaged interior knots, C⁴)", path.display())
        }
        _ => format!("`{}`", source_text(&r.source)),
    };
    let rows = compute(r, &plan)?;
    let fit = fitted_order(&rows);
    let floor = (f64_floor(&rows), f64_departs(&rows));
    let files = vec![
        (
            "convergence.md".to_string(),
            markdown(r, (&described, bits, plan.method), &rows, fit, floor),
        ),
        ("convergence.svg".to_string(), figure(&rows)),
        (
            "convergence.json".to_string(),
            json_rows(r, plan.method, &rows, fit, floor),
        ),
    ];
    crate::report::write_files(out, &files)
        .map_err(|e| Failure::Usage(format!("option --out: {e}")))?;
    Ok(format!(
        "wrote {} files to {}\n",
        files.len(),
        out.display()
    ))
}

/// The certified value with the digits its two precisions agree on (at most `cap`).
fn certified_text(l: &Level, cap: u32) -> String {
    let c = crate::scalar::certify::certify(&l.certified.0, &l.certified.1);
    crate::scalar::certify::format_float_digits(&l.certified.1, c.digits.min(cap))
}

fn proven_text(l: &Level) -> String {
    l.proven.as_ref().map_or("—".into(), |(lo, hi)| {
        format!(
            "[{}, {}]",
            bound_text(lo, 8, Round::Down),
            bound_text(hi, 8, Round::Up)
        )
    })
}

/// The curve as the user gave it.
fn source_text(s: &Source) -> String {
    match s {
        Source::Expression(text) => text.clone(),
        Source::Data(path) => path.display().to_string(),
    }
}

fn markdown(
    r: &Request,
    (described, bits, method): (&str, u32, Method),
    rows: &[Level],
    fit: Option<(f64, Option<f64>, usize)>,
    (floor, departs): (Option<usize>, Option<usize>),
) -> String {
    let body: Vec<Vec<String>> = rows
        .iter()
        .enumerate()
        .map(|(i, l)| {
            let ord = |k: usize| {
                i.checked_sub(1)
                    .and_then(|p| order(&rows[p].certified.1, &rows[k].certified.1))
            };
            vec![
                l.segments.to_string(),
                certified_text(l, 20),
                proven_text(l),
                sig(l.f64_error, 4),
                ord(i).map_or("—".into(), |o| format!("{o:.4}")),
            ]
        })
        .collect();
    let fit_text = match fit {
        Some((o, Some(ci), k)) => {
            format!("{o:.4} ± {ci:.4} (95 %, least squares over the finest {k} levels)")
        }
        Some((o, None, k)) => format!(
            "{o:.4} (exact fit through the finest {k} levels; no confidence from two points)"
        ),
        None => "— (fewer than two non-zero errors)".into(),
    };
    let floor_text = floor.map_or("f64 keeps improving over these levels".into(), |i| {
        format!("f64 stops improving at {} segments (error {}), where the certified error keeps falling", rows[i].segments, sig(rows[i].f64_error, 3))
    });
    let departs_text = departs.map_or(
        "f64 stays within 10 % of the certified error at every level".into(),
        |i| {
            format!(
                "f64 departs from the certified error by more than 10 % from {} segments",
                rows[i].segments
            )
        },
    );
    let (expected, source) = method.expected_order();
    let drift = order_drift(rows).map_or(String::new(), |(first, last)| {
        format!(
            "\n- the observed order still {} across the fitted levels ({first:.4} → {last:.4}): the interval assumes a constant order, so terms of higher order in h bias it; finer levels move it",
            if last > first { "rises" } else { "falls" }
        )
    });
    let verdict = match fit {
        Some((o, Some(ci), _)) if (o - expected as f64).abs() <= ci => "inside",
        Some((_, Some(_), _)) => "outside",
        _ => "no interval to compare",
    };
    format!(
        "# Convergence of {}\n\nCurve {} on [{}, {}], {} on 2ⁿ uniform segments; \
         E = max over ξ of ‖γ − p‖ (paper 001, Eq. 21). Certified: MPFR at {} and {} bits (digits both agree on, at most 20 shown; all are in the JSON); proven: a \
         branch-and-bound enclosure in ball arithmetic (`--scalar ball:<bits>` only); f64: the same pipeline in double precision.\n\n\
         {}\n- fitted order: {fit_text}{drift}\n- expected order for a smooth curve: {expected} ({source}); the expected order is {verdict} the 95 % interval\n- {floor_text}\n- {departs_text}\n\n![error against segments](./convergence.svg)\n",
        method.title(),
        described,
        r.interval.0,
        r.interval.1,
        method.pieces(),
        bits,
        2 * bits,
        table(&["segments", "E certified", "E proven", "E f64", "observed order"], &body)
    )
}

fn figure(rows: &[Level]) -> String {
    let x = |l: &Level| (l.segments as f64).log2();
    let mut series = vec![
        Series::new(
            "certified E",
            rows.iter()
                .map(|l| (x(l), l.certified.1.to_f64()))
                .collect(),
            Style::LineMarkers,
            0,
        ),
        Series::new(
            "f64 pipeline",
            rows.iter().map(|l| (x(l), l.f64_error)).collect(),
            Style::Markers,
            1,
        ),
    ];
    if rows.iter().all(|l| l.proven.is_some()) {
        let bound = |upper: bool| -> Vec<(f64, f64)> {
            rows.iter()
                .filter_map(|l| {
                    l.proven
                        .as_ref()
                        .map(|(lo, hi)| (x(l), if upper { hi.to_f64() } else { lo.to_f64() }))
                })
                .collect()
        };
        series.push(Series::new(
            "proven upper bound",
            bound(true),
            Style::Dashed,
            2,
        ));
        series.push(Series::new(
            "proven lower bound",
            bound(false),
            Style::Dotted,
            3,
        ));
    }
    let panel = Panel {
        title: "error against refinement".into(),
        x_label: "n (2ⁿ segments, dimensionless)".into(),
        y_label: "E = max ‖γ − p‖ (curve units)".into(),
        series,
        log_y: true,
        legend: Corner::UpperRight,
        ..Panel::default()
    };
    plot::render(&[panel], (1, 1), (900, 560)).unwrap_or_default()
}

fn json_rows(
    r: &Request,
    method: Method,
    rows: &[Level],
    fit: Option<(f64, Option<f64>, usize)>,
    (floor, departs): (Option<usize>, Option<usize>),
) -> String {
    let items: Vec<serde_json::Value> = rows
        .iter()
        .enumerate()
        .map(|(i, l)| {
            json!({
                "segments": l.segments,
                "error_certified": certified_text(l, u32::MAX),
                "error_proven": l.proven.as_ref().map(|(lo, hi)| json!({
                    "lower": bound_text(lo, 17, Round::Down),
                    "upper": bound_text(hi, 17, Round::Up)
                })),
                "error_f64": l.f64_error,
                "order": i.checked_sub(1).and_then(|p| order(&rows[p].certified.1, &l.certified.1)),
            })
        })
        .collect();
    let doc = json!({
        "curve": source_text(&r.source),
        "method": r.method,
        "expected_order": method.expected_order().0,
        "order_drift": order_drift(rows).map(|(first, last)| json!({"first": first, "last": last})),
        "interval": [r.interval.0, r.interval.1],
        "scalar": r.scalar.to_string(),
        "rows": items,
        "fitted_order": fit.map(|(o, ci, k)| json!({"order": o, "ci95": ci, "levels": k})),
        "f64_stops_improving_at": floor.map(|i| rows[i].segments),
        "f64_departs_at": departs.map(|i| rows[i].segments),
    });
    let mut s = serde_json::to_string_pretty(&doc).unwrap_or_default();
    s.push('\n');
    s
}
