//! `run gerbs-basis`, `run gerbs-path` and `run dubins`: the JSON shapes that `docs/commands.md` documents (paper 003).
//!
//! Inputs are read exactly (rationals, or constant expressions such as `"pi/8"` for angles)
//! and checked before anything is computed: knots, waypoints (collinearity decided exactly on
//! the rationals), radius, basis parameters. The computation then runs in f64, or in balls
//! (`mpfr:<bits>` prints their proven digits); the BFBS basis also runs exactly. In balls the
//! ERBS integrals are proven ([`ProvenErbs`]), and so is every path length
//! ([`GerbsPath::proven_length`]).

use super::budget::{self, check_time, Rates};
use super::dispatch::{run_real, run_real_or_exact, RealJob};
use super::input::{self, fail, InputError, RealInput, RunError};
use super::json::{Map, Value};
use super::output::{flush, largest, noise_level, Out};
use super::Rendered;
use crate::algo::gerbs::bfbs::{Bfbs, MAX_EXPONENT};
use crate::algo::gerbs::dubins::{
    self, algorithm1_headings, algorithm1_legs, legs_with_headings, total_length, DubinsError,
    DubinsPath, DubinsPlan, ExactLeg,
};
use crate::algo::gerbs::erbs::{CentreReading, Erbs, ErbsParams};
use crate::algo::gerbs::path::{
    check_waypoints, exact_turn_signs, ArcConvention, GerbsPath, PathSpec,
};
use crate::algo::gerbs::proven_erbs::ProvenErbs;
use crate::algo::gerbs::quadrature::default_tolerance;
use crate::algo::gerbs::{basis_derivatives_located, Blend, GerbsError, Knots, Located, Side};
use crate::curve::integral::IntegralOptions;
use crate::scalar::ball::{carried, Ball};
use crate::scalar::{mpfr_rational, Exact, Field, Real, ScalarKind};
use rayon::prelude::*;

/// The highest derivative order `run gerbs-basis` accepts.
pub const MAX_DERIVATIVES: usize = 30;
/// The most evaluation points or samples one command accepts.
pub const MAX_POINTS: usize = 100_000;
/// The largest |angle| in radians accepted for a heading or θ_o: beyond it an angle carries
/// no information at the working precision and its reduction modulo 2π is meaningless.
pub const MAX_ANGLE: f64 = 1e6;
/// The most waypoints of `run gerbs-path`: every path point blends all local curves and the
/// length integrates every interval, so the work grows as W²; 1000 waypoints take about 20 s
/// in f64 (a larger limit would only ever be refused by the budget).
pub const MAX_PATH_WAYPOINTS: usize = 1000;
/// Samples of a path when `samples` is not given.
pub const DEFAULT_PATH_SAMPLES: usize = 101;
/// Samples per Dubins leg when `samples` is not given.
pub const DEFAULT_LEG_SAMPLES: usize = 33;

const ERBS_FIELDS: [&str; 5] = ["alpha", "beta", "gamma", "lambda", "sigma"];
/// The ERBS parameters used when a field is not given: the Fig. 2 caption (β = 3, γ = 1,
/// λ = 1/2) with α = 1 and σ = 1, the set of the report's ERBS paths (C^∞ everywhere).
const ERBS_DEFAULTS: [(i64, i64); 5] = [(1, 1), (3, 1), (1, 1), (1, 2), (1, 1)];

fn gerbs_error(e: GerbsError) -> InputError {
    match e {
        GerbsError::Knots(m) => InputError(format!("field \"knots\": {m}")),
        GerbsError::Waypoints(m) => InputError(format!("field \"waypoints\": {m}")),
        GerbsError::Parameter { field, message } => {
            InputError(format!("field \"{field}\": {message}"))
        }
    }
}

/// x, or null where the quantity does not exist: an ERBS has no k-th derivative at the centre
/// of an interval when k − 1 ≥ 2σ (|t − c|^{2σ}, 2σ not even), and so may the path's curvature.
fn finite_or_null<T: Field>(x: T) -> Out<T> {
    if x.is_finite() {
        Out::Num(x)
    } else {
        Out::Null
    }
}

/// The refusal of `--scalar rational` for a GERBS computation described as `what`.
fn needs_real(what: &str) -> String {
    format!("option --scalar: {what} needs square roots and trigonometry; use f64 or mpfr:<bits>")
}

/// `"bfbs"` or `"erbs"`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Bfbs,
    Erbs,
}

fn kind(doc: &Map) -> Result<Kind, InputError> {
    input::choice(
        doc,
        "kind",
        &[("bfbs", Kind::Bfbs), ("erbs", Kind::Erbs)],
        None,
    )
}

/// The basis parameters, already expanded to the knot vector they are used on.
#[derive(Clone, Debug)]
enum BasisParams {
    /// One exponent per basis function B_2 … B_{n+1}.
    Bfbs(Vec<u32>),
    /// One set (α, β, γ, λ, σ) for all intervals, or one per knot interval t_j … t_{j+1}.
    Erbs {
        sets: Vec<[RealInput; 5]>,
        centre: CentreReading,
    },
}

/// Read `params` for `kind` on knots t_1 … t_{n+2} (`nonempty[j]`: interval j+1 is not
/// empty). A per-interval array has one entry per knot interval, or one per non-empty
/// interval (the empty end intervals of doubled end knots then copy their neighbour).
fn basis_params(doc: &Map, kind: Kind, nonempty: &[bool]) -> Result<BasisParams, InputError> {
    let empty = Map::default();
    let params = match doc.get("params") {
        None => &empty,
        Some(Value::Object(map)) => map,
        Some(other) => {
            return fail(format!(
                "field \"params\": expected an object, found {}",
                input::kind(other)
            ))
        }
    };
    match kind {
        Kind::Bfbs => bfbs_params(params, nonempty.len() - 1),
        Kind::Erbs => erbs_params(params, nonempty),
    }
}

/// `params` of a BFBS: `i`, one exponent for all `basis_count` basis functions or one each.
fn bfbs_params(params: &Map, basis_count: usize) -> Result<BasisParams, InputError> {
    input::only_fields(params, &["i"])
        .map_err(|e| InputError(e.0.replacen("input:", "field \"params\":", 1)))?;
    let exponent = |v: &Value, path: &str| {
        input::count(v, path, MAX_EXPONENT as usize).and_then(|i| {
            if i == 0 {
                fail(format!("field \"{path}\": exponents must be at least 1"))
            } else {
                Ok(i as u32)
            }
        })
    };
    let exponents = match params.get("i") {
        None => vec![2; basis_count],
        Some(Value::Array(items)) => {
            if items.len() != basis_count {
                return fail(format!(
                    "field \"params.i\": expected one exponent per basis function ({basis_count}), found {}",
                    items.len()
                ));
            }
            items
                .iter()
                .enumerate()
                .map(|(k, v)| exponent(v, &format!("params.i[{k}]")))
                .collect::<Result<_, _>>()?
        }
        Some(v) => vec![exponent(v, "params.i")?; basis_count],
    };
    Ok(BasisParams::Bfbs(exponents))
}

/// `params` of an ERBS: each of α, β, γ, λ, σ one value or one per knot interval, and the
/// reading of the centre.
fn erbs_params(params: &Map, nonempty: &[bool]) -> Result<BasisParams, InputError> {
    let mut known = ERBS_FIELDS.to_vec();
    known.push("centre");
    input::only_fields(params, &known)
        .map_err(|e| InputError(e.0.replacen("input:", "field \"params\":", 1)))?;
    let centre = input::choice(
        params,
        "centre",
        &[
            ("cited", CentreReading::Cited),
            ("printed", CentreReading::AsPrinted),
        ],
        Some(CentreReading::Cited),
    )
    .map_err(|e| InputError(e.0.replacen("\"centre\"", "\"params.centre\"", 1)))?;
    let intervals = nonempty.len();
    let filled = nonempty.iter().filter(|&&b| b).count();
    // Each field: one value, or one per interval.
    let mut columns: Vec<Option<Vec<RealInput>>> = Vec::new();
    let mut single = Vec::new();
    for (name, (n, d)) in ERBS_FIELDS.iter().zip(ERBS_DEFAULTS) {
        let path = format!("params.{name}");
        match params.get(name) {
            None => {
                single.push(RealInput::Exact(crate::scalar::BigRational::new(
                    n.into(),
                    d.into(),
                )));
                columns.push(None);
            }
            Some(Value::Array(items)) => {
                let values: Vec<RealInput> = items
                    .iter()
                    .enumerate()
                    .map(|(k, v)| input::real(v, &format!("{path}[{k}]")))
                    .collect::<Result<_, _>>()?;
                let per_interval = if values.len() == intervals {
                    values
                } else if values.len() == filled {
                    spread(&values, nonempty)
                } else {
                    return fail(format!(
                        "field \"{path}\": expected one value per knot interval ({intervals}, or {filled} without the empty ones), found {}",
                        values.len()
                    ));
                };
                single.push(per_interval[0].clone());
                columns.push(Some(per_interval));
            }
            Some(v) => {
                single.push(input::real(v, &path)?);
                columns.push(None);
            }
        }
    }
    let sets = if columns.iter().all(Option::is_none) {
        vec![array5(single)]
    } else {
        (0..intervals)
            .map(|j| {
                array5(
                    columns
                        .iter()
                        .zip(&single)
                        .map(|(c, s)| c.as_ref().map_or(s, |c| &c[j]).clone())
                        .collect(),
                )
            })
            .collect()
    };
    Ok(BasisParams::Erbs { sets, centre })
}

fn array5(v: Vec<RealInput>) -> [RealInput; 5] {
    let mut it = v.into_iter();
    std::array::from_fn(|_| {
        it.next()
            .unwrap_or(RealInput::Exact(crate::scalar::BigRational::from_integer(
                0.into(),
            )))
    })
}

/// Values given for the non-empty intervals, copied onto the empty ones from the nearest
/// non-empty interval (so an empty end interval takes the first or last value).
fn spread(values: &[RealInput], nonempty: &[bool]) -> Vec<RealInput> {
    let mut out = Vec::with_capacity(nonempty.len());
    let mut next = 0;
    for &full in nonempty {
        out.push(values[next.min(values.len() - 1)].clone());
        if full {
            next += 1;
        }
    }
    out
}

impl BasisParams {
    /// The ERBS basis on `knots` in `T`, with each parameter set checked (α > 0 …).
    fn erbs<T: Real>(
        sets: &[[RealInput; 5]],
        centre: CentreReading,
        knots: &Knots<T>,
        ctx: &T::Ctx,
    ) -> Result<Erbs<T>, InputError> {
        let params = BasisParams::erbs_params(sets, ctx)?;
        Erbs::new(knots, params, centre).map_err(gerbs_error)
    }

    /// The ERBS basis on ball knots with its integrals proven ([`ProvenErbs`]).
    fn proven_erbs(
        sets: &[[RealInput; 5]],
        centre: CentreReading,
        knots: &Knots<Ball>,
        bits: u32,
    ) -> Result<ProvenErbs, InputError> {
        let params = BasisParams::erbs_params(sets, &bits)?;
        let options = IntegralOptions {
            order: (bits as usize / 6).clamp(12, 40),
            ..IntegralOptions::default()
        };
        ProvenErbs::new(knots, params, centre, options).map_err(gerbs_error)
    }

    /// The ERBS parameter sets in `T`, each checked (α > 0 …).
    fn erbs_params<T: Real>(
        sets: &[[RealInput; 5]],
        ctx: &T::Ctx,
    ) -> Result<Vec<ErbsParams<T>>, InputError> {
        let mut params = Vec::with_capacity(sets.len());
        for (j, set) in sets.iter().enumerate() {
            let index = if sets.len() == 1 {
                String::new()
            } else {
                format!("[{j}]")
            };
            let mut v = Vec::with_capacity(5);
            for (x, name) in set.iter().zip(ERBS_FIELDS) {
                v.push(input::real_in::<T>(
                    x,
                    ctx,
                    &format!("params.{name}{index}"),
                )?);
            }
            let [alpha, beta, gamma, lambda, sigma]: [T; 5] = v
                .try_into()
                .map_err(|_| InputError("internal: five ERBS parameters".into()))?;
            params.push(ErbsParams::new(alpha, beta, gamma, lambda, sigma).map_err(
                |e| match e {
                    GerbsError::Parameter { field, message } => {
                        InputError(format!("field \"{field}{index}\": {message}"))
                    }
                    other => gerbs_error(other),
                },
            )?);
        }
        Ok(params)
    }
}

/// A list of knots read exactly and checked (`field "knots": …`).
fn knots(doc: &Map) -> Result<Knots<Exact>, InputError> {
    let items = input::array(input::field(doc, "knots")?, "knots")?;
    let t = items
        .iter()
        .enumerate()
        .map(|(k, v)| input::number(v, format_args!("knots[{k}]")))
        .collect::<Result<Vec<_>, _>>()?;
    Knots::new(t).map_err(gerbs_error)
}

fn nonempty_intervals<T: Field>(knots: &Knots<T>) -> Vec<bool> {
    knots.as_slice().windows(2).map(|w| w[0] < w[1]).collect()
}

fn side(doc: &Map) -> Result<Side, InputError> {
    input::choice(
        doc,
        "side",
        &[("right", Side::Right), ("left", Side::Left)],
        Some(Side::Right),
    )
}

/// What `run gerbs-basis` asks for.
struct BasisJob {
    knots: Knots<Exact>,
    params: BasisParams,
    at: Vec<Exact>,
    derivatives: usize,
    side: Side,
}

impl BasisJob {
    fn values<T: Field, B: Blend<T>>(
        &self,
        knots: &Knots<T>,
        blend: &B,
    ) -> Result<Out<T>, RunError> {
        let ctx = knots.at(1).ctx();
        let mut rows = Vec::with_capacity(self.at.len());
        for (i, q) in self.at.iter().enumerate() {
            // The knot interval and side are decided on the exact point, never on its
            // rounding (a point 1e-40 below a knot rounds onto it).
            let Some(j) = self.knots.paper_interval(q, self.side) else {
                rows.push(Out::List(Vec::new()));
                continue;
            };
            // The distances to the interval's ends exact, rounded once.
            let at = Located {
                t: T::from_exact(q, &ctx),
                interval: j,
                after_start: T::from_exact(&(q.clone() - self.knots.at(j)), &ctx),
                before_end: T::from_exact(&(self.knots.at(j + 1).clone() - q), &ctx),
            };
            let mut row = Vec::new();
            for (b, derivatives) in basis_derivatives_located(knots, blend, &at, self.derivatives)
                .into_iter()
                .enumerate()
            {
                let mut entries = Vec::with_capacity(derivatives.len());
                for (k, x) in derivatives.into_iter().enumerate() {
                    entries.push(if x.is_finite() {
                        Out::Num(x)
                    } else if self.derivative_missing(q, j, k) {
                        // It does not exist (decided on the exact input): null, as documented.
                        Out::Null
                    } else {
                        // A BFBS is a polynomial, and an ERBS derivative exists everywhere but
                        // at its centre: a value that is not finite left the number type's
                        // range or (in balls) was not proven.
                        return fail(format!(
                            "output \"values\"[{i}][{b}][{k}]: derivative {k} of B_{} at t = {q} is \
                             not finite at this precision (out of range, or not proven); raise \
                             the precision",
                            b + 2
                        ));
                    });
                }
                row.push(Out::List(entries));
            }
            rows.push(Out::List(row));
        }
        Ok(Out::object(vec![("values", Out::List(rows))]))
    }

    /// Whether derivative `k` of the ERBS does not exist at the exact point q of interval j:
    /// q is exactly the centre c_j, 2σ is not an even integer (Ψ holds |t − c|^{2σ}) and
    /// k − 1 ≥ 2σ. Decided only on rational parameters; `false` otherwise (and for a BFBS).
    fn derivative_missing(&self, q: &Exact, j: usize, k: usize) -> bool {
        let BasisParams::Erbs { sets, centre } = &self.params else {
            return false;
        };
        let set = if sets.len() == 1 {
            &sets[0]
        } else {
            &sets[j - 1]
        };
        let (RealInput::Exact(lambda), RealInput::Exact(sigma)) = (&set[3], &set[4]) else {
            return false;
        };
        let (lambda, sigma) = (mpfr_rational(lambda), mpfr_rational(sigma));
        let (a, b) = (self.knots.at(j), self.knots.at(j + 1));
        let left = (Exact::from(1) - &lambda) * a;
        let right = lambda * b;
        let c = match centre {
            CentreReading::Cited => left + right,
            CentreReading::AsPrinted => left - right,
        };
        let two_sigma = sigma * Exact::from(2);
        let even = *two_sigma.denom() == 1 && two_sigma.numer().is_even();
        // B^(k) = Ψ^(k−1)/S, and the m-th derivative of |t − c|^{2σ} exists at c iff m < 2σ.
        // (2σ is rational: m ≥ 2σ is not m + 1 > 2σ.)
        k >= 1 && {
            let m = k - 1;
            *q == c && !even && two_sigma <= m
        }
    }

    fn knots_in<T: Field>(&self, ctx: &T::Ctx) -> Result<Knots<T>, InputError> {
        Knots::rounded(&self.knots, ctx).map_err(|e| match e {
            // Distinct rationals that round to one value in T.
            GerbsError::Knots(m) => InputError(format!(
                "field \"knots\": {m} after rounding to the working precision"
            )),
            other => gerbs_error(other),
        })
    }
}

impl RealJob for BasisJob {
    fn run<T: Real>(&self, ctx: &T::Ctx) -> Result<Out<T>, RunError> {
        let knots = self.knots_in::<T>(ctx)?;
        Ok(match &self.params {
            BasisParams::Bfbs(i) => {
                self.values(&knots, &Bfbs::new(i.clone()).map_err(gerbs_error)?)?
            }
            BasisParams::Erbs { sets, centre } => {
                let erbs = BasisParams::erbs(sets, *centre, &knots, ctx)?;
                self.values(&knots, &erbs)?
            }
        })
    }

    /// In balls the ERBS integrals are proven ([`ProvenErbs`]).
    fn run_ball(&self, bits: u32) -> Result<Out<Ball>, RunError> {
        let knots = self.knots_in::<Ball>(&bits)?;
        Ok(match &self.params {
            BasisParams::Bfbs(i) => {
                self.values(&knots, &Bfbs::new(i.clone()).map_err(gerbs_error)?)?
            }
            BasisParams::Erbs { sets, centre } => {
                let erbs = BasisParams::proven_erbs(sets, *centre, &knots, bits)?;
                self.values(&knots, &erbs)?
            }
        })
    }
}

/// `run gerbs-basis`: B_2 … B_{n+1} and their derivatives at the given points.
pub fn run_gerbs_basis(doc: &Map, scalar: ScalarKind) -> Result<Rendered, RunError> {
    input::only_fields(
        doc,
        &["knots", "kind", "params", "at", "derivatives", "side"],
    )?;
    let knots = knots(doc)?;
    let kind = kind(doc)?;
    let params = basis_params(doc, kind, &nonempty_intervals(&knots))?;
    let at = evaluation_points(doc, &knots)?;
    let derivatives = match doc.get("derivatives") {
        Some(v) => input::count(v, "derivatives", MAX_DERIVATIVES)?,
        None => 0,
    };
    basis_budget(&knots, at.len(), derivatives, kind, scalar)?;
    let job = BasisJob {
        knots,
        params,
        at,
        derivatives,
        side: side(doc)?,
    };
    // The BFBS is an exact polynomial: rationals take the Real job's field operations only.
    let exact = || {
        match &job.params {
        BasisParams::Bfbs(i) => {
            let bfbs = Bfbs::new(i.clone()).map_err(gerbs_error)?;
            job.values(&job.knots, &bfbs)
        }
        BasisParams::Erbs { .. } => fail(
            "option --scalar: the ERBS basis is an integral of exp(…) (quadrature); use f64 or mpfr:<bits>",
        ),
    }
    };
    run_real_or_exact(&job, scalar, exact)
}

/// The points `at`, each inside the knots, read exactly.
fn evaluation_points(doc: &Map, knots: &Knots<Exact>) -> Result<Vec<Exact>, InputError> {
    let items = input::array(input::field(doc, "at")?, "at")?;
    if items.len() > MAX_POINTS {
        return fail(format!(
            "field \"at\": {} points is more than the supported {MAX_POINTS}",
            items.len()
        ));
    }
    let (first, last) = (
        knots.at(1),
        knots.as_slice()[knots.as_slice().len() - 1].clone(),
    );
    let mut at = Vec::with_capacity(items.len());
    for (k, v) in items.iter().enumerate() {
        let t = input::number(v, format_args!("at[{k}]"))?;
        if t < *first || t > last {
            return fail(format!(
                "field \"at[{k}]\": {t} is outside the knots [{first}, {last}]"
            ));
        }
        at.push(t);
    }
    Ok(at)
}

/// The work budget of `gerbs-basis`: `points` points, every basis function, `derivatives`.
fn basis_budget(
    knots: &Knots<Exact>,
    points: usize,
    derivatives: usize,
    kind: Kind,
    scalar: ScalarKind,
) -> Result<(), InputError> {
    let n = knots.as_slice().len() as f64 - 2.0;
    let count = points as f64;
    let per_point = 1.0 + derivatives as f64 / 10.0;
    budget::check_output(count * n * (derivatives as f64 + 1.0), "at", "this run")?;
    // Measured: BFBS with n = 100, 1000 points, d = 2 in 0.1 s (f64) and 0.36 s (mpfr:128),
    // d = 10 in 1.9 s (rationals). ERBS in MPFR: a fixed cost per knot interval (the proven
    // Taylor models of the kernel) and one per point, nearly independent of n, both growing
    // faster than mpfr_factor with the bits (erbs_extra); on Fig. 2's knots (4 intervals),
    // d = 2: 4, 64 and 256 points in 0.68, 2.3 and 7.4 s at mpfr:128, in 3.6, 12.3 and 29 s
    // at mpfr:256.
    let seconds = match kind {
        Kind::Bfbs => Rates {
            f64: 1e-6,
            mpfr256: 6e-6,
            rational: 1.2e-5,
        }
        .seconds(count * (n + 10.0) * per_point, scalar),
        Kind::Erbs => {
            let per_basis = if scalar == ScalarKind::F64 {
                n + 10.0
            } else {
                1.0
            };
            let points = Rates {
                f64: 1.5e-6,
                mpfr256: 0.09 * erbs_extra(scalar) * (1.0 + n / 100.0),
                rational: 0.0,
            }
            .seconds(count * per_point * per_basis, scalar);
            let intervals = Rates {
                f64: 0.0,
                mpfr256: 0.75 * erbs_extra(scalar),
                rational: 0.0,
            }
            .seconds((n - 1.0).max(1.0), scalar);
            points + intervals
        }
    };
    check_time(
        seconds,
        "at",
        &format!("{points} points on {n} basis functions at {scalar}"),
    )
}

/// Waypoints [[x, y], …], read exactly and checked for Algorithm 1 (at least `min`).
fn waypoints(doc: &Map) -> Result<Vec<[Exact; 2]>, InputError> {
    let items = input::array(input::field(doc, "waypoints")?, "waypoints")?;
    if items.len() > MAX_POINTS {
        return fail(format!(
            "field \"waypoints\": {} waypoints is more than the supported {MAX_POINTS}",
            items.len()
        ));
    }
    items
        .iter()
        .enumerate()
        .map(|(k, v)| input::point::<2>(v, &format!("waypoints[{k}]")))
        .collect()
}

fn positive(doc: &Map, name: &str, what: &str) -> Result<Exact, InputError> {
    let r = input::number(input::field(doc, name)?, name)?;
    if r <= 0 {
        return fail(format!(
            "field \"{name}\": {what} must be positive, got {r}"
        ));
    }
    Ok(r)
}

fn to_points<T: Field>(w: &[[Exact; 2]], ctx: &T::Ctx) -> Vec<[T; 2]> {
    w.iter()
        .map(|p| [T::from_exact(&p[0], ctx), T::from_exact(&p[1], ctx)])
        .collect()
}

/// What `run gerbs-path` asks for.
struct PathJob {
    waypoints: Vec<[Exact; 2]>,
    radius: Exact,
    theta_o: RealInput,
    line_length: Option<Exact>,
    convention: ArcConvention,
    params: BasisParams,
    samples: usize,
}

impl PathJob {
    /// The output of `path`, its length `length` when it is proven, else estimated by
    /// tanh–sinh.
    fn out<T: Real, B: Blend<T> + Sync>(
        &self,
        path: &GerbsPath<T, B>,
        waypoints: &[[T; 2]],
        ctx: &T::Ctx,
        length: Option<T>,
    ) -> Result<Out<T>, RunError> {
        let samples = path.sample(self.samples).map_err(gerbs_error)?;
        let n = self.waypoints.len();
        let at_knots: Vec<_> = (0..n)
            .map(|i| {
                // Knot i + 1 (the paper's t_{i+2}) of waypoint i + 1 (from the inside at the ends).
                path.at_knot(i + 1, if i + 1 == n { Side::Left } else { Side::Right })
            })
            .collect::<Result<_, _>>()
            .map_err(gerbs_error)?;
        // Mathematical zeros print as 0 (noise_level): coordinates next to the largest
        // waypoint coordinate, tangents next to the largest tangent, curvature next to 1/R.
        // Each is also marked as a possible zero with its scale, so a value below the
        // lower precision's resolution at both precisions certifies as 0 (an ERBS weight of
        // 1e-58 is a real value at 256 bits and nothing at 128).
        let point_scale = largest(waypoints.iter().flatten());
        let tangent_scale = largest(at_knots.iter().flat_map(|p| p.d1.iter()));
        let curvature_scale = T::one_in(ctx) / &T::from_exact(&self.radius, ctx);
        let curvature_level = noise_level(&curvature_scale);
        let vector = |v: &[T; 2], scale: Option<&T>| {
            let level = scale.map(noise_level);
            // Every coordinate may vanish (an enclosure keeps its ball around 0; the scale
            // matters only to the flush of f64).
            let scale = scale.cloned().unwrap_or_else(|| T::zero_in(ctx));
            Out::List(
                v.iter()
                    .map(|x| Out::MaybeZero(flush(x.clone(), level.as_ref()), scale.clone()))
                    .collect(),
            )
        };
        let kappa = |k: &T| match finite_or_null(flush(k.clone(), Some(&curvature_level))) {
            Out::Num(x) => Out::MaybeZero(x, curvature_scale.clone()),
            other => other,
        };
        let at_waypoints = at_knots
            .iter()
            .map(|p| {
                Out::object(vec![
                    ("t", Out::Num(p.t.clone())),
                    ("point", vector(&p.point, point_scale.as_ref())),
                    ("tangent", vector(&p.d1, tangent_scale.as_ref())),
                    ("curvature", kappa(&p.curvature)),
                ])
            })
            .collect();
        Ok(Out::object(vec![
            (
                "t",
                Out::nums(samples.iter().map(|p| p.t.clone()).collect()),
            ),
            (
                "points",
                Out::List(
                    samples
                        .iter()
                        .map(|p| vector(&p.point, point_scale.as_ref()))
                        .collect(),
                ),
            ),
            (
                "curvature",
                Out::List(samples.iter().map(|p| kappa(&p.curvature)).collect()),
            ),
            (
                "length",
                Out::Num(
                    length.unwrap_or_else(|| path.length_within(&default_tolerance::<T>(ctx))),
                ),
            ),
            ("at_waypoints", Out::List(at_waypoints)),
            (
                "turns",
                Out::List(
                    path.tangents()
                        .s
                        .iter()
                        .map(|&s| Out::Int(s as i64))
                        .collect(),
                ),
            ),
        ]))
    }
}

impl PathJob {
    /// Algorithm 1's data in `T`: waypoints, radius, θ_o, the turn signs decided exactly.
    fn spec<T: Real>(&self, ctx: &T::Ctx) -> Result<PathSpec<T>, RunError> {
        Ok(PathSpec {
            waypoints: to_points(&self.waypoints, ctx),
            radius: T::from_exact(&self.radius, ctx),
            theta_o: input::real_in::<T>(&self.theta_o, ctx, "theta_o")?,
            line_length: self.line_length.as_ref().map(|l| T::from_exact(l, ctx)),
            convention: self.convention,
            // Decided on the exact waypoints, not on their rounding.
            turns: Some(exact_turn_signs(&self.waypoints).map_err(gerbs_error)?),
            end_curves: Default::default(),
        })
    }
}

impl RealJob for PathJob {
    fn run<T: Real>(&self, ctx: &T::Ctx) -> Result<Out<T>, RunError> {
        let spec = self.spec::<T>(ctx)?;
        match &self.params {
            BasisParams::Bfbs(i) => {
                let bfbs = Bfbs::new(i.clone()).map_err(gerbs_error)?;
                self.out(
                    &GerbsPath::new(&spec, bfbs).map_err(gerbs_error)?,
                    &spec.waypoints,
                    ctx,
                    None,
                )
            }
            BasisParams::Erbs { sets, centre } => {
                let knots = Knots::uniform(spec.waypoints.len(), ctx).map_err(gerbs_error)?;
                let erbs = BasisParams::erbs(sets, *centre, &knots, ctx)?;
                self.out(
                    &GerbsPath::new(&spec, erbs).map_err(gerbs_error)?,
                    &spec.waypoints,
                    ctx,
                    None,
                )
            }
        }
    }

    /// A BFBS path in balls, its length proven by Taylor models of the speed
    /// ([`GerbsPath::proven_length`]).
    fn run_ball(&self, bits: u32) -> Result<Out<Ball>, RunError> {
        let spec = self.spec::<Ball>(&bits)?;
        // Taylor models of a higher order at a higher precision: the pieces needed fall as
        // the tolerance^(1/(N+2)) (measured at 256 bits on the README's path: order 16 did not
        // reach the tolerance in 4096 pieces, order 64 took 1000 pieces in 4.7 s).
        let options = match self.params {
            BasisParams::Bfbs(_) => IntegralOptions {
                order: (bits as usize / 4).clamp(12, 56),
                ..IntegralOptions::default()
            },
            // The ERBS kernel's series over a piece grow fast with the order (its essential
            // singularities at the knots), so a higher order does not pay: measured on the
            // README's path, orders 8–24 took 430–630 pieces an interval at 64 bits, order 12
            // the fastest. 2048 pieces an interval prove 16 digits of its length (1024: 14).
            BasisParams::Erbs { .. } => IntegralOptions {
                order: 12,
                max_pieces: 2048,
                ..IntegralOptions::default()
            },
        };
        self.proven_path(&spec, bits, &options)
    }
}

impl PathJob {
    /// A BFBS path in balls, its length proven.
    fn proven_path(
        &self,
        spec: &PathSpec<Ball>,
        bits: u32,
        options: &IntegralOptions,
    ) -> Result<Out<Ball>, RunError> {
        match &self.params {
            BasisParams::Bfbs(i) => {
                let path = GerbsPath::new(spec, Bfbs::new(i.clone()).map_err(gerbs_error)?)
                    .map_err(gerbs_error)?;
                let length = path.proven_length(options).map_err(gerbs_error)?;
                self.out(&path, &spec.waypoints, &bits, Some(length))
            }
            BasisParams::Erbs { sets, centre } => {
                let knots = Knots::uniform(spec.waypoints.len(), &bits).map_err(gerbs_error)?;
                let erbs = BasisParams::proven_erbs(sets, *centre, &knots, bits)?;
                let path = GerbsPath::new(spec, erbs).map_err(gerbs_error)?;
                let length = path.proven_length(options).map_err(gerbs_error)?;
                self.out(&path, &spec.waypoints, &bits, Some(length))
            }
        }
    }
}

/// `run gerbs-path`: Algorithm 2 through the waypoints, sampled, with length and the
/// values at the waypoints' knots.
pub fn run_gerbs_path(doc: &Map, scalar: ScalarKind) -> Result<Rendered, RunError> {
    input::only_fields(
        doc,
        &[
            "waypoints",
            "radius",
            "theta_o",
            "kind",
            "params",
            "samples",
            "line_length",
            "arcs",
        ],
    )?;
    let waypoints = waypoints(doc)?;
    if waypoints.len() > MAX_PATH_WAYPOINTS {
        return fail(format!(
            "field \"waypoints\": {} waypoints is more than the supported {MAX_PATH_WAYPOINTS} for a path",
            waypoints.len()
        ));
    }
    check_waypoints(&waypoints).map_err(gerbs_error)?;
    let radius = positive(doc, "radius", "the arc radius R")?;
    let theta_o = match doc.get("theta_o") {
        Some(v) => angle(v, "theta_o")?,
        None => return fail("input: missing field \"theta_o\" (the paper uses \"pi/8\")"),
    };
    let kind = kind(doc)?;
    let knots = Knots::<Exact>::uniform(waypoints.len(), &()).map_err(gerbs_error)?;
    let params = basis_params(doc, kind, &nonempty_intervals(&knots))?;
    let samples = match doc.get("samples") {
        Some(v) => input::count(v, "samples", MAX_POINTS)?,
        None => DEFAULT_PATH_SAMPLES,
    };
    if samples < 2 {
        return fail("field \"samples\": at least 2 samples (the two ends)");
    }
    let line_length = doc
        .get("line_length")
        .map(|_| positive(doc, "line_length", "the line length l"))
        .transpose()?;
    let convention = input::choice(
        doc,
        "arcs",
        &[
            ("turn", ArcConvention::TurnDirection),
            ("printed", ArcConvention::AsPrinted),
        ],
        Some(ArcConvention::TurnDirection),
    )?;
    path_budget(waypoints.len(), samples, kind, scalar)?;
    let job = PathJob {
        waypoints,
        radius,
        theta_o,
        line_length,
        convention,
        params,
        samples,
    };
    run_real(&job, scalar, &needs_real("a GERBS path"))
}

/// The work budget of `gerbs-path`: `waypoints` waypoints, `samples` samples.
fn path_budget(
    waypoints: usize,
    samples: usize,
    kind: Kind,
    scalar: ScalarKind,
) -> Result<(), InputError> {
    // A path point blends every local curve (about W operations), the length integrates each
    // of the W − 1 intervals, and the ERBS in MPFR integrates again at each node. Measured
    // (seconds): BFBS f64 W = 50, S = 101 in 0.05 and W = 1000 in 11; mpfr:128 W = 50 in 2.8
    // and S = 10001 in 1.4; mpfr:256 W = 4 in 0.5; ERBS mpfr:64 W = 5, S = 10001 in 23 and
    // W = 50, S = 101 in 16.
    let (w, s) = (waypoints as f64, samples as f64);
    let seconds = match (kind, scalar) {
        // In MPFR and balls the length is proven by Taylor models of the speed on each of the
        // W − 1 knot intervals, on two cores: measured 1.05 CPU-s an interval at 128 bits
        // (W = 20, radius 30), 1.3–2.9 at 256 bits; the samples as before.
        (Kind::Bfbs, ScalarKind::Mpfr(bits) | ScalarKind::Ball(bits)) => {
            let per_interval = 1.5 * (f64::from(bits) / 128.0).powf(1.5);
            per_interval * (w - 1.0) / 2.0
                + Rates {
                    f64: 0.0,
                    mpfr256: bfbs_extra(scalar),
                    rational: 0.0,
                }
                .seconds(8e-5 * w * s + 1e-3 * w * w, scalar)
        }
        // The ERBS length proven the same way, F_j carried along each interval by proven
        // increments: measured on the README's path (W = 5) 0.12, 0.9, 3.8 and 10.5 CPU-s an
        // interval at 32, 64, 128 and 256 bits (2048 pieces an interval at most); each sample
        // integrates the kernel from its nearer knot to full relative accuracy, 0.016 s at 64
        // bits and up to 0.05 s at 128 (W = 4, S = 401: 26 s).
        (Kind::Erbs, ScalarKind::Mpfr(bits) | ScalarKind::Ball(bits)) => {
            let per_interval = 4.0 * (f64::from(bits) / 128.0).powf(1.5);
            per_interval * (w - 1.0) / 2.0 + 0.05 * s * f64::from(bits) / 128.0
        }
        (Kind::Bfbs, _) => 1.2e-6 * w * s + 2e-5 * w * w,
        (Kind::Erbs, _) => 1.8e-6 * w * s + 3e-5 * w * w,
    };
    check_time(
        seconds,
        "waypoints",
        &format!(
            "a path through {} waypoints with {samples} samples at {scalar}",
            waypoints
        ),
    )?;
    budget::check_output(4.0 * s + 5.0 * w, "samples", "this run")
}

/// A leg whose shortest word cannot be decided, as a one-line input error.
fn dubins_error(e: &DubinsError) -> InputError {
    let leg = match e {
        DubinsError::Degenerate { leg, .. }
        | DubinsError::Undecided { leg, .. }
        | DubinsError::Tie { leg, .. } => *leg,
        // Not raised by the planner (only by `pose_at`).
        DubinsError::Argument { .. } => return InputError(format!("field \"waypoints\": {e}")),
    };
    InputError(format!(
        "field \"waypoints\": no Dubins path from waypoint {} to {}: {e}",
        leg + 1,
        leg + 2
    ))
}

/// The ERBS quadrature's extra cost in MPFR beyond [`budget::mpfr_factor`]: the tanh–sinh
/// rule needs more levels (twice the nodes each) as the precision rises, about (p/256)².
fn erbs_extra(scalar: ScalarKind) -> f64 {
    match scalar {
        // The proven Taylor-model quadrature grows faster with the bits than tanh–sinh did
        // (24 points on 10 intervals: 0.13 s at 128 bits, 0.74 s at 256, 19 s at 512).
        ScalarKind::Mpfr(bits) | ScalarKind::Ball(bits) => (bits as f64 / 256.0)
            .powi(3)
            .max((bits as f64 / 256.0).powi(2)),
        _ => 1.0,
    }
}

/// An angle (a number or a constant expression) within ±[`MAX_ANGLE`] rad at `path`.
fn angle(v: &Value, path: &str) -> Result<RealInput, InputError> {
    let a = input::real(v, path)?;
    let value: f64 = input::real_in(&a, &(), path)?;
    if value.abs() > MAX_ANGLE {
        return fail(format!(
            "field \"{path}\": an angle must lie within ±{MAX_ANGLE:e} rad"
        ));
    }
    Ok(a)
}

/// The BFBS path length's extra cost in MPFR beyond [`budget::mpfr_factor`]: more tanh–sinh
/// levels as the precision rises, about (p/256)^0.7 above 256 bits (measured: four waypoints
/// in 0.5 s at 256 bits, 1.7 s at 512, 8 s at 1024).
fn bfbs_extra(scalar: ScalarKind) -> f64 {
    match scalar {
        ScalarKind::Mpfr(bits) | ScalarKind::Ball(bits) => (bits as f64 / 256.0).max(1.0).powf(0.7),
        _ => 1.0,
    }
}

/// What `run dubins` asks for: the legs given exactly, each with its shortest word
/// already decided on that exact input ([`dubins::plan`]).
struct DubinsJob {
    waypoints: Vec<[Exact; 2]>,
    headings: Option<Vec<RealInput>>,
    radius: Exact,
    samples: usize,
    legs: Vec<(ExactLeg, DubinsPlan)>,
}

impl RealJob for DubinsJob {
    fn run<T: Real>(&self, ctx: &T::Ctx) -> Result<Out<T>, RunError> {
        let w = to_points::<T>(&self.waypoints, ctx);
        let radius = T::from_exact(&self.radius, ctx);
        let headings = match &self.headings {
            Some(h) => h
                .iter()
                .enumerate()
                .map(|(k, x)| input::real_in::<T>(x, ctx, &format!("headings[{k}]")))
                .collect::<Result<Vec<_>, _>>()?,
            None => algorithm1_headings(&w).map_err(gerbs_error)?,
        };
        // The decided words, evaluated in T: no comparison decides a branch here.
        let legs: Vec<DubinsPath<T>> = self
            .legs
            .iter()
            .map(|(leg, plan)| plan.path::<T>(leg, ctx))
            .collect();
        let total = total_length(&legs, ctx);
        // Mathematical zeros print as 0 (noise_level): coordinates next to the largest
        // waypoint coordinate or R, headings next to π, segment lengths next to the total.
        let mut scale = radius.clone();
        if let Some(m) = largest(w.iter().flatten()) {
            if m > scale {
                scale = m;
            }
        }
        let (xy_level, angle_level, length_level) = (
            noise_level(&scale),
            noise_level(&T::pi(ctx)),
            noise_level(&total),
        );
        let scale = scale.clone();
        let levels = Levels {
            xy: (xy_level, scale),
            angle: noise_level(&T::pi(ctx)),
            length: (length_level, total.clone()),
            pi: T::pi(ctx),
        };
        let legs = legs
            .iter()
            .enumerate()
            .map(|(i, leg)| leg_out(i, leg, self.samples, &levels))
            .collect();
        Ok(Out::object(vec![
            (
                "headings",
                Out::List(
                    headings
                        .into_iter()
                        .map(|h| Out::MaybeZero(flush(h, Some(&angle_level)), T::pi(ctx)))
                        .collect(),
                ),
            ),
            ("legs", Out::List(legs)),
            ("length", Out::Num(total)),
        ]))
    }
}

/// The headings of `run dubins`: `None` for Algorithm 1's (whose checks then apply to the
/// waypoints), or one exact angle per waypoint.
fn dubins_headings(
    doc: &Map,
    waypoints: &[[Exact; 2]],
) -> Result<Option<Vec<RealInput>>, InputError> {
    Ok(match doc.get("headings") {
        None => {
            // Headings from Algorithm 1: its checks apply.
            check_waypoints(waypoints).map_err(gerbs_error)?;
            None
        }
        Some(v) => {
            let items = input::array(v, "headings")?;
            if waypoints.len() < 2 {
                return fail(format!(
                    "field \"waypoints\": need at least 2 waypoints, got {}",
                    waypoints.len()
                ));
            }
            if let Some(i) = (1..waypoints.len()).find(|&i| waypoints[i] == waypoints[i - 1]) {
                return fail(format!(
                    "field \"waypoints\": waypoint {} repeats waypoint {i}",
                    i + 1
                ));
            }
            if items.len() != waypoints.len() {
                return fail(format!(
                    "field \"headings\": expected one heading per waypoint ({}), found {}",
                    waypoints.len(),
                    items.len()
                ));
            }
            Some(
                items
                    .iter()
                    .enumerate()
                    .map(|(k, v)| angle(v, &format!("headings[{k}]")))
                    .collect::<Result<Vec<_>, _>>()?,
            )
        }
    })
}

/// Each leg given exactly, with its shortest word decided on that exact input (shared by
/// every number type and both precisions of a certified run).
fn planned_legs(
    waypoints: &[[Exact; 2]],
    headings: Option<&[RealInput]>,
    radius: &Exact,
) -> Result<Vec<(ExactLeg, DubinsPlan)>, InputError> {
    // The Dubins planner decides in GMP rationals, the input's own type (algo::gerbs::dubins).
    let exact_legs = match headings {
        Some(h) => legs_with_headings(waypoints, h, radius),
        None => algorithm1_legs(waypoints, radius),
    };
    // The legs are planned independently, on rayon's threads; the first leg that fails (in
    // order) is the error, as on one thread.
    let plans: Vec<Result<DubinsPlan, DubinsError>> = exact_legs
        .par_iter()
        .enumerate()
        .map(carried(|(i, leg)| dubins::plan(leg, i)))
        .collect();
    exact_legs
        .into_iter()
        .zip(plans)
        .map(|(leg, plan)| plan.map(|p| (leg, p)).map_err(|e| dubins_error(&e)))
        .collect()
}

/// The noise levels of a Dubins output with the scales they come from (see
/// [`Out::MaybeZero`]).
struct Levels<T> {
    xy: (T, T),
    angle: T,
    length: (T, T),
    pi: T,
}

/// One leg of the `run dubins` output.
fn leg_out<T: Real>(i: usize, leg: &DubinsPath<T>, samples: usize, levels: &Levels<T>) -> Out<T> {
    let maybe =
        |x: T, (level, scale): (&T, &T)| Out::MaybeZero(flush(x, Some(level)), scale.clone());
    let xy = (&levels.xy.0, &levels.xy.1);
    let angle = (&levels.angle, &levels.pi);
    let length = (&levels.length.0, &levels.length.1);
    let samples = leg
        .samples(samples)
        .into_iter()
        .map(|[x, y, h]| Out::List(vec![maybe(x, xy), maybe(y, xy), maybe(h, angle)]))
        .collect();
    Out::object(vec![
        ("from", Out::Int(i as i64 + 1)),
        ("to", Out::Int(i as i64 + 2)),
        ("word", Out::Text(leg.word_name())),
        (
            "lengths",
            Out::List(
                leg.lengths
                    .iter()
                    .map(|l| maybe(l.clone(), length))
                    .collect(),
            ),
        ),
        ("length", Out::Num(leg.total())),
        ("samples", Out::List(samples)),
    ])
}

/// `run dubins`: the shortest Dubins path of radius R between consecutive waypoint poses.
pub fn run_dubins(doc: &Map, scalar: ScalarKind) -> Result<Rendered, RunError> {
    input::only_fields(doc, &["waypoints", "headings", "radius", "samples"])?;
    let waypoints = waypoints(doc)?;
    let headings = dubins_headings(doc, &waypoints)?;
    let radius = positive(doc, "radius", "the turn radius R")?;
    let samples = match doc.get("samples") {
        Some(v) => input::count(v, "samples", MAX_POINTS)?,
        None => DEFAULT_LEG_SAMPLES,
    };
    if samples < 2 {
        return fail("field \"samples\": at least 2 samples per leg (its two ends)");
    }
    // Six words per leg and `samples` poses on each (measured on the cost-model grid with 20
    // samples: 4000 waypoints in 0.10 s in f64, most legs planned in double intervals; 640
    // in 0.68 s at mpfr:256).
    let units = waypoints.len() as f64 * samples as f64;
    let rates = Rates {
        f64: 1.5e-6,
        mpfr256: 1e-4,
        rational: 0.0,
    };
    rates.check(
        units,
        scalar,
        "waypoints",
        &format!(
            "{} legs with {samples} samples at {scalar}",
            waypoints.len().saturating_sub(1)
        ),
    )?;
    budget::check_output(3.0 * units, "samples", "this run")?;
    let legs = planned_legs(&waypoints, headings.as_deref(), &radius)?;
    let job = DubinsJob {
        waypoints,
        headings,
        radius,
        samples,
        legs,
    };
    run_real(&job, scalar, &needs_real("a Dubins path"))
}
