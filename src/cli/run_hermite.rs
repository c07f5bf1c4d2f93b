//! `run hermite` and `run hermite-condition`: the JSON shapes that `docs/commands.md` documents.

use super::budget::{self, check_output, Rates};
use super::dispatch::{run_field, run_proven_job, FieldJob, ProvenJob};
use super::input::{self, fail, InputError, RunError, ValuePath};
use super::json::{Map, Value};
use super::output::Out;
use super::Rendered;
use crate::algo::hermite::{self, condition, TransformKind};
use crate::scalar::ball::Ball;
use crate::scalar::certify::correct_digits;
use crate::scalar::{big_rational, BigRational, Exact, Field, Float, ScalarKind};
use rug::float::Round;

/// The most derivatives accepted by `run hermite` (degree 1001).
pub const MAX_HERMITE_DERIVATIVES: usize = 500;
/// The most derivatives accepted by `run hermite-condition`: the largest m whose one-sided
/// Jacobi converges at the default 256 bits (m = 70 does not, at 256 or 1024 bits).
pub const MAX_CONDITION_DERIVATIVES: usize = 60;

/// The Hermite data of `run hermite`. The derivatives stay JSON values until the run's number
/// type reads them ([`input::number_in`]: an f64 run reads no big rational).
struct HermiteInput<'a> {
    start: Vec<Vec<&'a Value<'a>>>,
    end: Vec<Vec<&'a Value<'a>>>,
    t0: Exact,
    t1: Exact,
    is_point: bool,
}

fn read_hermite<'a>(doc: &'a Map<'a>) -> Result<HermiteInput<'a>, InputError> {
    input::only_fields(doc, &["start", "end", "interval"])?;
    let values = |name: &str| {
        input::uniform_values_with(input::field(doc, name)?, name, |x, p| {
            input::number_value(x, p)
        })
    };
    let (start, start_points) = values("start")?;
    let (end, end_points) = values("end")?;
    let (t0, t1) = input::interval(input::field(doc, "interval")?, "interval")?;
    if start.len() != end.len() {
        return fail(format!(
            "field \"end\": {} values where \"start\" has {}: both ends need the same number of derivatives",
            end.len(),
            start.len()
        ));
    }
    if start.len() > MAX_HERMITE_DERIVATIVES + 1 {
        return fail(format!(
            "field \"start\": {} derivatives is more than the supported {MAX_HERMITE_DERIVATIVES}",
            start.len() - 1
        ));
    }
    if start_points != end_points || start[0].len() != end[0].len() {
        return fail(format!(
            "field \"end\": mixed dimensions: values of dimension {}{} where \"start\" has dimension {}{}",
            end[0].len(),
            if end_points { "" } else { " (numbers)" },
            start[0].len(),
            if start_points { "" } else { " (numbers)" }
        ));
    }
    Ok(HermiteInput {
        start,
        end,
        t0,
        t1,
        is_point: start_points,
    })
}

impl FieldJob for HermiteInput<'_> {
    fn run<T: Field>(&self, ctx: &T::Ctx) -> Result<Out<T>, RunError> {
        Ok(hermite_in(self, ctx)?)
    }
}

/// Control points of every coordinate in the number type `T`.
fn hermite_in<T: Field>(data: &HermiteInput, ctx: &T::Ctx) -> Result<Out<T>, InputError> {
    let conv = |v: &[Vec<&Value>], name: &str| -> Result<Vec<Vec<T>>, InputError> {
        v.iter()
            .enumerate()
            .map(|(i, p)| {
                p.iter()
                    .enumerate()
                    .map(|(coordinate, q)| {
                        let is_point = data.is_point;
                        let path = ValuePath {
                            name,
                            index: i,
                            coordinate,
                            is_point,
                        };
                        input::number_in(q, path, ctx)
                    })
                    .collect()
            })
            .collect()
    };
    // The control points depend only on the width t1 − t0 (the derivatives scale by its
    // powers): it is formed exactly and rounded once, so that [1, 1 + 1e-40] is not rounded
    // to an empty interval.
    let (t0, t1) = (
        T::zero_in(ctx),
        T::from_exact(&(data.t1.clone() - &data.t0), ctx),
    );
    let (start, end) = (conv(&data.start, "start")?, conv(&data.end, "end")?);
    let polygon = hermite::solve_points(&start, &end, (&t0, &t1))
        .map_err(|e| InputError(format!("field \"start\": {e}")))?;
    let degree = polygon.len() as i64 - 1;
    let points = polygon
        .into_iter()
        .map(|mut p| {
            if data.is_point {
                Out::nums(p)
            } else {
                Out::Num(p.swap_remove(0))
            }
        })
        .collect();
    Ok(Out::object(vec![
        ("degree", Out::Int(degree)),
        ("control_points", Out::List(points)),
    ]))
}

/// `run hermite`: two-point Hermite data → Bernstein control points.
pub fn run_hermite(doc: &Map, scalar: ScalarKind) -> Result<Rendered, RunError> {
    let data = read_hermite(doc)?;
    // The binomial transforms cost about (m+1)^3 operations per coordinate (measured: 0.03 s
    // at mpfr:256 for m = 200). In rationals the numbers grow with m and with the bits of the
    // interval's width (the scales (t1 − t0)^j), not with the data's digits: measured in GMP's
    // rationals, three coordinates, m = 100 and 200 on [0, 1] in 0.05 and 0.40 s, m = 150 on
    // [0, 1.234567] in 0.87 s against 0.16 s on [0, 1].
    let (m, dims) = (data.start.len() as f64 - 1.0, data.start[0].len() as f64);
    let rates = Rates {
        f64: 1e-11,
        mpfr256: 2e-10,
        rational: 7e-9,
    };
    let units = if scalar == ScalarKind::Rational {
        let width = data.t1.clone() - &data.t0;
        dims * (m + 1.0).powf(3.2) * budget::exact_size_factor([&width], 1.0)
    } else {
        dims * (m + 1.0).powf(3.5)
    };
    // Reading and printing every number costs about as much as the transforms at small m
    // (measured: m = 20 in 200 coordinates, 16 800 numbers in and out, 0.08 s at mpfr:256,
    // whose proven digits are printed from each ball, and 6 ms in f64).
    let numbers = dims * (m + 1.0) * 4.0;
    let per_number = Rates {
        f64: 5e-7,
        mpfr256: 7e-6,
        rational: 2e-6,
    };
    budget::check_time(
        rates.seconds(units, scalar) + per_number.seconds(numbers, scalar),
        "start",
        &format!("{m} derivatives in {dims} coordinates at {scalar}"),
    )?;
    check_output(dims * 2.0 * (m + 1.0), "start", "this run")?;
    run_field(&data, scalar)
}

/// `run hermite-condition`: κ₂ of the transform or of its binomial part.
pub fn run_condition(doc: &Map, scalar: ScalarKind) -> Result<Rendered, RunError> {
    input::only_fields(doc, &["derivatives", "interval", "matrix"])?;
    let m = input::count(
        input::field(doc, "derivatives")?,
        "derivatives",
        MAX_CONDITION_DERIVATIVES,
    )?;
    let (t0, t1) = input::interval(input::field(doc, "interval")?, "interval")?;
    // The matrix depends only on the width t1 − t0 (Eq. 11's factors n!/(n−j)!/(t1 − t0)^j):
    // take it exactly here, so that [1, 1 + 1e-40] is not rounded to an empty interval.
    let (t0, t1) = (Exact::from(0), t1 - &t0);
    // κ₂'s library functions (condition::*) take num-rational ends: two numbers, converted once.
    let (t0, t1) = (big_rational(&t0), big_rational(&t1));
    // Our f64 one-sided Jacobi on the (m+1) × (2m+2) start block: about (m+1)^3.8
    // operations over its sweeps (f64 only; every other number type is the proof below).
    let units = (m as f64 + 1.0).powf(3.8);
    let rates = Rates {
        f64: 5e-9,
        mpfr256: 0.0,
        rational: 0.0,
    };
    rates.check(
        units,
        scalar,
        "derivatives",
        &format!("κ₂ for {m} derivatives at {scalar}"),
    )?;
    let kind = input::choice(
        doc,
        "matrix",
        &[
            ("transform", TransformKind::Transform),
            ("binomial", TransformKind::Binomial),
        ],
        None,
    )?;
    let scale = scale_range(m, &(t1.clone() - &t0), kind, scalar)?;
    // Every number type proves κ₂ (f64 to confirm its digits). The proof's exact LDLᵀ works
    // on integers whose size grows with m and with the derivative scales (t1 − t0)^−j.
    // Measured: m = 30 on [0, 1] in 0.6 s, m = 60 in 14 s; m = 30 on [0, 1e-3] in 1.2–4.6 s,
    // m = 60 there in over 2 minutes. Refit on a slower shared machine (ball:64 on [0, 1]):
    // m = 50 in 9.8 s, 55 in 18.2 s, 58 in 23.6 s, 60 stopped at the 29 s deadline, so 60 is
    // (and 59, for margin) now refused at once rather than accepted at 14 s and stopped.
    let scale_bits = m as f64 * condition::log2_abs(&(t1.clone() - &t0)).abs();
    let seconds = 34.0 * ((m as f64 + 1.0) / 61.0).powf(5.5) * (1.0 + scale_bits / 600.0).powi(3);
    budget::check_time(
        seconds,
        "derivatives",
        &format!("a proven κ₂ for {m} derivatives on this interval at {scalar}"),
    )?;
    // JSON has no infinity: null when the f64 matrix leaves f64's range or nalgebra's σ_min
    // is 0.
    let raw_reference = condition::f64_reference(m, (&t0, &t1), kind);
    let reference = raw_reference.filter(|k| k.is_finite());
    let f64_note = match (raw_reference, condition::f64_out_of_range(m, scale)) {
        (None, Some(why)) => why,
        (None, None) => "the f64 matrix overflows",
        (Some(k), _) if k.is_infinite() => "nalgebra's f64 SVD returns σmin = 0",
        (Some(_), _) => "nalgebra's f64 SVD of the correctly rounded matrix",
    };
    let job = ConditionJob {
        m,
        t0,
        t1,
        kind,
        scale,
        reference,
        f64_note,
    };
    run_proven_job(
        &job,
        scalar,
        "option --scalar: rational cannot take the square roots of an SVD; use f64 or mpfr:<bits>",
    )
}

/// κ₂ of the transform for m derivatives on [t0, t1], with nalgebra's f64 value beside it.
struct ConditionJob {
    m: usize,
    t0: BigRational,
    t1: BigRational,
    kind: TransformKind,
    /// The least and greatest binary exponents of the scale factors
    /// ([`condition::scale_exponents`]).
    scale: (f64, f64),
    /// nalgebra's f64 κ₂ (`None`: overflow or σmin = 0), and what it is.
    reference: Option<f64>,
    f64_note: &'static str,
}

impl ConditionJob {
    /// κ₂ proven: the extreme eigenvalues of BᵀB bracketed exactly by Sylvester inertia
    /// (`condition::proven`) to a relative width of 2^−`bits`, as (lower, upper).
    fn enclosure(&self, bits: u32) -> Result<(Float, Float), RunError> {
        // MPFR only locates the eigenvalues that the exact inertia brackets: it needs about
        // log₂κ₂ bits beyond the bracket's width to resolve σ_min (below that the brackets do
        // not close, and at ball:64 with m = 60 the search ran for minutes). log₂κ₂ is about
        // the spread of the scale exponents plus 4 bits per derivative (m = 30 on [0, 1]:
        // 197 bits).
        let (low, high) = self.scale;
        let needed = f64::from(bits) + 64.0 + (high - low) + 4.0 * self.m as f64;
        let locate = needed.min(f64::from(u32::MAX / 4)) as u32;
        let relative = 2f64.powi(-(bits.min(1000) as i32));
        condition::proven(self.m, (&self.t0, &self.t1), self.kind, locate, relative).ok_or_else(|| {
            RunError::Input(format!(
                "output \"condition_number\": the inertia brackets did not close at {bits} bits; raise the precision"
            ))
        })
    }
}

impl ProvenJob for ConditionJob {
    /// κ₂ proven, printed as the ball [lower, upper] (in `mpfr:<bits>`, its proven digits).
    fn ball(&self, bits: u32) -> Result<Out<Ball>, RunError> {
        let (lo, hi) = self.enclosure(bits)?;
        // Rounded outward to the precision asked for (the inertia may have located the
        // eigenvalues with more bits); as bounds, not a ball, whose f64 radius would stop at
        // κ₂ ≈ 1e308.
        let lo = Float::with_val_round(bits, &lo, Round::Down).0;
        let hi = Float::with_val_round(bits, &hi, Round::Up).0;
        Ok(Out::object(vec![
            ("condition_number", Out::Bounds(Box::new((lo, hi)))),
            ("f64", self.reference.map_or(Out::Null, Out::F64)),
            ("f64_note", Out::Text(self.f64_note.into())),
            ("size", Out::Int(2 * self.m as i64 + 2)),
        ]))
    }

    /// Our f64 Jacobi on the f64 matrix, with the number of its digits the proven κ₂ confirms
    /// (`correct_digits`: every point of the enclosure agrees with the f64 value to that many
    /// significant digits).
    fn f64(&self) -> Result<Rendered, RunError> {
        let (m, t0, t1, kind) = (self.m, &self.t0, &self.t1, self.kind);
        let Some(k) = f64_matrix_condition(m, t0, t1, kind) else {
            return fail(format!(
                "field \"interval\": the matrix entries n!/(n−j)!/(t1 − t0)^j of {m} derivatives on this interval are beyond \
                 the range of f64; use --scalar mpfr:<bits>"
            ));
        };
        let (value, digits, note) = match k {
            Ok(k) if k.is_finite() => {
                let (lo, hi) = self.enclosure(128)?;
                let confirmed = correct_digits(k, &lo).min(correct_digits(k, &hi));
                (Out::Text(crate::scalar::float_text(k)), confirmed, None)
            }
            Ok(_) => (
                Out::Null,
                0,
                Some("our f64 Jacobi finds σmin = 0".to_string()),
            ),
            Err(e) => (
                Out::Null,
                0,
                Some(format!(
                    "our f64 Jacobi: {e}: f64 cannot resolve this matrix"
                )),
            ),
        };
        let mut out: Out<f64> = Out::object(vec![
            ("condition_number", value),
            ("correct_digits", Out::Int(digits as i64)),
            ("f64", self.reference.map_or(Out::Null, Out::F64)),
            ("f64_note", Out::Text(self.f64_note.into())),
            ("scalar", Out::Text("f64".into())),
            ("size", Out::Int(2 * self.m as i64 + 2)),
        ]);
        if let Some(note) = note {
            out = out.with_field("note", Out::Text(note));
        }
        Ok(Rendered::plain(out))
    }
}

/// The binary exponents (least, greatest) of the scale factors n!/(n−j)!/(t1 − t0)^j
/// ([`condition::scale_exponents`]); in f64 an interval whose factors leave f64's range is
/// refused, naming it.
fn scale_range(
    m: usize,
    width: &BigRational,
    kind: TransformKind,
    scalar: ScalarKind,
) -> Result<(f64, f64), InputError> {
    let (low, high) = condition::scale_exponents(m, width, kind);
    if scalar == ScalarKind::F64 && (high > 1023.0 || low < -1022.0) {
        let w = condition::log2_abs(width);
        let what = if !(-1074.0..=1024.0).contains(&w) {
            format!("t1 − t0 ≈ 2^{w:.0} is itself beyond the range of f64")
        } else {
            let reach = if high > 1023.0 { high } else { low };
            format!(
                "its scale factors n!/(n−j)!/(t1 − t0)^j for {m} derivatives reach 2^{reach:.0}"
            )
        };
        return fail(format!(
            "field \"interval\": {what}; use --scalar mpfr:<bits>"
        ));
    }
    Ok((low, high))
}

/// Our generic Jacobi in f64 on the f64 matrix, or `None` when an entry is not finite.
fn f64_matrix_condition(
    m: usize,
    t0: &BigRational,
    t1: &BigRational,
    kind: TransformKind,
) -> Option<Result<f64, crate::numeric::linalg::svd::NoConvergence>> {
    let a = crate::algo::hermite::transform_matrix(m, (t0, t1), kind).map(|q| q.to_f64());
    if a.entries().iter().any(|x| !x.is_finite()) {
        return None;
    }
    Some(crate::numeric::linalg::condition_number(&a))
}
