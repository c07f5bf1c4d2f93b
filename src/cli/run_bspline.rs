//! `run bspline-basis`, `bspline-gram`, `spline-fit` and `bang-bang`: the JSON shapes that `docs/commands.md` documents.

use super::budget::{self, Rates};
use super::dispatch::{run_field, run_real, FieldJob, RealJob};
use super::input::{self, fail, InputError, RunError};
use super::json::{Map, Value};
use super::output::Out;
use super::Rendered;
use crate::algo::bspline::bang_bang;
use crate::algo::bspline::fit::{schoenberg_whitney, FitError, SplineSpace};
use crate::algo::bspline::gram::gram_entries;
use crate::algo::bspline::CardinalBSpline;
use crate::scalar::ball::Ball;
use crate::scalar::qsqrt2::QSqrt2;
use crate::scalar::{Exact, Field, Real, ScalarKind};

/// The highest degree accepted by the basis and Gram commands (exact polynomials of degree k).
pub const MAX_DEGREE: usize = 60;
/// The most control points accepted by `spline-fit`.
pub const MAX_CONTROLS: usize = 2000;

fn degree(doc: &Map, minimum: usize) -> Result<usize, InputError> {
    let value = input::field(doc, "degree")?;
    let k = input::count(value, "degree", MAX_DEGREE)?;
    if k < minimum {
        return fail(format!("field \"degree\": {k} is below {minimum} (the Gram matrix of k-th derivatives needs k ≥ 1)"));
    }
    Ok(k)
}

/// `run bspline-basis`: the pieces of B_k in s = t − j, exact.
pub fn run_basis(doc: &Map) -> Result<Rendered, RunError> {
    input::only_fields(doc, &["degree"])?;
    let k = degree(doc, 0)?;
    let b = CardinalBSpline::<Exact>::from_algorithm1(k, &());
    let pieces = b
        .pieces()
        .iter()
        .map(|p| Out::nums(p.coeffs_padded(k + 1, &())))
        .collect();
    Ok(Rendered::plain(Out::object(vec![
        ("degree", Out::Int(k as i64)),
        ("pieces", Out::List(pieces)),
    ])))
}

/// `run bspline-gram`: ĝ₀…ĝ_k, exact.
pub fn run_gram(doc: &Map) -> Result<Rendered, RunError> {
    input::only_fields(doc, &["degree"])?;
    let k = degree(doc, 1)?;
    Ok(Rendered::plain(Out::object(vec![
        ("degree", Out::Int(k as i64)),
        ("entries", Out::nums(gram_entries::<Exact>(k, &()))),
    ])))
}

struct FitInput {
    degree: usize,
    controls: usize,
    times: Vec<Exact>,
    values: Vec<Vec<Exact>>,
    is_point: bool,
    weights: Option<Vec<Exact>>,
}

fn read_fit(doc: &Map) -> Result<FitInput, InputError> {
    input::only_fields(doc, &["degree", "controls", "times", "values", "weights"])?;
    let degree = degree(doc, 1)?;
    let controls = input::count(input::field(doc, "controls")?, "controls", MAX_CONTROLS)?;
    let times_value = input::array(input::field(doc, "times")?, "times")?;
    let times = times_value
        .iter()
        .enumerate()
        .map(|(i, t)| input::number(t, format_args!("times[{i}]")))
        .collect::<Result<Vec<_>, _>>()?;
    let (values, is_point) = input::uniform_values(input::field(doc, "values")?, "values")?;
    if times.is_empty() {
        return fail("field \"times\": needs at least one data time");
    }
    if values.len() != times.len() {
        return fail(format!(
            "field \"values\": {} values for {} times",
            values.len(),
            times.len()
        ));
    }
    let weights = match doc.get("weights") {
        None | Some(Value::Null) => None,
        Some(w) => {
            let list = input::array(w, "weights")?;
            let parsed = list
                .iter()
                .enumerate()
                .map(|(i, x)| input::number(x, format_args!("weights[{i}]")))
                .collect::<Result<Vec<_>, _>>()?;
            if parsed.len() != times.len() {
                return fail(format!(
                    "field \"weights\": {} weights for {} times",
                    parsed.len(),
                    times.len()
                ));
            }
            if let Some(i) = parsed.iter().position(|w| w.cmp0().is_lt()) {
                return fail(format!(
                    "field \"weights[{i}]\": a weight must not be negative"
                ));
            }
            Some(parsed)
        }
    };
    if weights.is_none() && times.len() > controls {
        return fail(format!("field \"controls\": {controls} control points cannot interpolate {} data (M must be at least N)", times.len()));
    }
    let end = Exact::from(controls + degree);
    if let Some(i) = times.iter().position(|t| t.cmp0().is_le() || *t >= end) {
        return fail(format!("field \"times[{i}]\": {} lies outside the support (0, {end}) of the spline, where every basis function vanishes", times[i]));
    }
    if weights.is_none() {
        // Full row rank of B, decided exactly on the rational times (never on a pivot).
        schoenberg_whitney(&times, degree, controls)
            .map_err(|e| InputError(format!("field \"times\": {e}")))?;
    }
    Ok(FitInput {
        degree,
        controls,
        times,
        values,
        is_point,
        weights,
    })
}

fn fit_in<T: Field>(data: &FitInput, ctx: &T::Ctx) -> Result<Out<T>, InputError> {
    let conv = |q: &Exact| T::from_exact(q, ctx);
    let space = SplineSpace::<T>::new(data.degree, data.controls, ctx)
        .map_err(|e| InputError(format!("field \"degree\": {e}")))?;
    let collocation = SplineSpace::<Exact>::new(data.degree, data.controls, &())
        .map_err(|e| InputError(format!("field \"degree\": {e}")))?
        .collocation_of(&data.times)
        .map(|q| T::from_exact(q, ctx));
    let weights: Option<Vec<T>> = data.weights.as_ref().map(|w| w.iter().map(conv).collect());
    let dims = data.values[0].len();
    let mut per_coordinate = Vec::with_capacity(dims);
    for c in 0..dims {
        let values: Vec<T> = data.values.iter().map(|v| conv(&v[c])).collect();
        let tau = match &weights {
            // Support, rank and weights were decided on the exact input (`read_fit`), and B
            // is formed exactly and rounded once.
            None => space
                .interpolate_collocation(&collocation, &values)
                .and_then(|(tau, condition)| check_conditioning(tau, &condition, ctx)),
            Some(w) => space.smooth_collocation(&collocation, &values, w),
        }
        .map_err(|e| InputError(format!("field \"times\": {e}")))?;
        per_coordinate.push(tau);
    }
    let tau = (0..data.controls)
        .map(|i| {
            if data.is_point {
                Out::nums(per_coordinate.iter().map(|c| c[i].clone()).collect())
            } else {
                Out::Num(per_coordinate[0][i].clone())
            }
        })
        .collect();
    let kind = if data.weights.is_some() {
        "smoothing (Eq. 15)"
    } else {
        "interpolation (Eq. 14)"
    };
    Ok(Out::object(vec![
        ("tau", Out::List(tau)),
        ("problem", Out::Text(kind.into())),
    ]))
}

/// τ, or the refusal of a fit whose condition estimate leaves no correct digit at the
/// unit roundoff of `T` (f64, MPFR; rationals are exact and balls carry their radius).
fn check_conditioning<T: Field>(
    tau: Vec<T>,
    condition: &T,
    ctx: &T::Ctx,
) -> Result<Vec<T>, FitError> {
    match T::unit_roundoff(ctx) {
        Some(unit) if (condition.to_f64() * unit).is_nan() || condition.to_f64() * unit >= 0.5 => {
            Err(FitError::IllConditioned {
                scalar: T::scalar_name(ctx),
                condition: condition.to_f64(),
                unit,
            })
        }
        _ => Ok(tau),
    }
}

/// `run spline-fit`: optimal interpolating (weights null) or smoothing control points.
pub fn run_fit(doc: &Map, scalar: ScalarKind) -> Result<Rendered, RunError> {
    let data = read_fit(doc)?;
    // Dense elimination per coordinate: on max(M, N) unknowns for interpolation, on the M
    // controls for smoothing (the data enter through banded products), so (size)^3
    // operations in f64 and MPFR; in rationals see below. Measured: f64 smoothing M = 400,
    // N = 800 in 3.7 s; mpfr:256 M = N = 500 in 26.7 s (interpolation) and 3 s (smoothing),
    // smoothing M = 200, N = 400 in 0.2 s; f64 interpolation below.
    let size = if data.weights.is_some() {
        data.controls as f64
    } else {
        data.controls.max(data.times.len()) as f64
    };
    let dims = data.values[0].len() as f64;
    let rates = if data.weights.is_some() {
        Rates {
            f64: 6.4e-8,
            mpfr256: 4.2e-8,
            rational: 1.5e-8,
        }
    } else {
        // An f64 interpolation is checked against proven ball solves at 128 and, when that
        // enclosure is too wide to decide, 512 bits (dispatch::check_f64), which cost far
        // more than the f64 solve: measured M = N = 20, 30, 40 in 9, 26 and 64 ms, all but
        // a fraction of a millisecond in the balls. (Interpolations much larger are refused
        // as ill-conditioned for f64 before they are solved.)
        Rates {
            f64: 1e-6,
            mpfr256: 2.1e-7,
            rational: 1.5e-8,
        }
    };
    // In rationals the entries grow along the elimination, and with the bits of the data
    // times (budget::exact_size_factor): measured in GMP's rationals, interpolation with
    // times of 16 digits M = N = 20 in 0.4 s, 40 in 7.0 s, 50 in 18.3 s (size^4.2); at
    // M = N = 40, times of 2, 6, 10 and 16 digits in 0.5, 1.8, 3.7 and 7.0 s.
    // Smoothing grows as M^3.4 (M = 20, 40, 80 with N = 2M in 0.005, 0.04, 0.42 s).
    let power = if data.weights.is_some() { 3.4 } else { 4.2 };
    let units = if scalar == ScalarKind::Rational {
        dims * size.powf(power) * budget::exact_size_factor(&data.times, 1.75)
    } else {
        dims * size.powi(3)
    };
    rates.check(
        units,
        scalar,
        "controls",
        &format!(
            "a fit with {} controls and {} data in {dims} coordinates at {scalar}",
            data.controls,
            data.times.len()
        ),
    )?;
    run_field(&data, scalar)
}

impl FieldJob for FitInput {
    fn run<T: Field>(&self, ctx: &T::Ctx) -> Result<Out<T>, RunError> {
        Ok(fit_in(self, ctx)?)
    }

    /// A smoothing fit with weights across many orders of magnitude can lose every digit in
    /// f64 below the condition estimate's threshold.
    fn checks_f64(&self) -> bool {
        true
    }
}

/// `run bang-bang`: switching times and amplitude of the minimum-L∞ control through x(2) = ξ.
pub fn run_bang_bang(doc: &Map, scalar: ScalarKind) -> Result<Rendered, RunError> {
    input::only_fields(doc, &["xi"])?;
    let xi = input::number(input::field(doc, "xi")?, "xi")?;
    let Some(exact_times) = bang_bang::exact_switching_times() else {
        return Err(RunError::internal(
            "the exact switching times failed their check",
        ));
    };
    let exact_u = bang_bang::amplitude(&exact_times, &QSqrt2::from_exact(&xi, &()));
    let exact = Out::object(vec![
        ("switching_times", Out::nums(exact_times.to_vec())),
        ("amplitude", Out::Num(exact_u)),
    ]);
    let exact_json = super::output::render_plain(&exact);
    let refusal = "option --scalar: the switching times are irrational (2 ± √2); use f64 or mpfr:<bits>, and see \"exact\"";
    let job = BangBangJob { xi, exact };
    Ok(run_real(&job, scalar, refusal)?.with_extra("exact", exact_json))
}

/// Every number of an exact tree as its proven bounds at `bits` ([`QSqrt2::bounds`]: an
/// amplitude of 1e10000 is beyond the f64 radius of a ball, not beyond its bounds).
fn bounds_of(exact: &Out<QSqrt2>, bits: u32) -> Out<Ball> {
    match exact {
        Out::Num(q) | Out::MaybeZero(q, _) => {
            let (lo, hi) = q.bounds(bits);
            Out::Bounds(Box::new((lo, hi)))
        }
        Out::List(items) => Out::List(items.iter().map(|v| bounds_of(v, bits)).collect()),
        Out::Object(fields) => Out::Object(
            fields
                .iter()
                .map(|(k, v)| (k.clone(), bounds_of(v, bits)))
                .collect(),
        ),
        other => other.map(&|q: &QSqrt2| q.to_real::<Ball>(&bits)),
    }
}

/// The switching times by Newton's method and the amplitude for x(2) = ξ, in one number type;
/// in balls, the exact values in Q(√2) enclosed.
struct BangBangJob {
    xi: Exact,
    exact: Out<QSqrt2>,
}

impl RealJob for BangBangJob {
    fn run<T: Real>(&self, ctx: &T::Ctx) -> Result<Out<T>, RunError> {
        // The switching times do not depend on ξ: a failure here is the method's, not the input's.
        let t = bang_bang::switching_times::<T>(ctx).map_err(RunError::internal)?;
        let u = bang_bang::amplitude(&t, &T::from_exact(&self.xi, ctx));
        Ok(Out::object(vec![
            ("switching_times", Out::nums(t.to_vec())),
            ("amplitude", Out::Num(u)),
        ]))
    }

    /// Newton's method stops at a tolerance, which a ball cannot prove; the exact values it
    /// converges to (2 − √2, 2, 2 + √2 and U in Q(√2)) are enclosed instead.
    fn run_ball(&self, bits: u32) -> Result<Out<Ball>, RunError> {
        Ok(bounds_of(&self.exact, bits))
    }

    fn checks_f64(&self) -> bool {
        true
    }
}
