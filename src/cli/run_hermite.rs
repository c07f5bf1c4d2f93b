//! `run hermite` and `run hermite-condition`: the JSON shapes of issue 2.

use super::input::{self, fail, InputError};
use super::output::Out;
use super::Rendered;
use crate::hermite::{self, condition, TransformKind};
use crate::scalar::certify::{correct_digits, Certified};
use crate::scalar::{BigRational, Field, Float, ScalarKind};
use serde_json::{Map, Value};

/// The most derivatives accepted by `run hermite` (degree 1001).
pub const MAX_HERMITE_DERIVATIVES: usize = 500;
/// The most derivatives accepted by `run hermite-condition` (a 202 × 202 SVD at high precision).
pub const MAX_CONDITION_DERIVATIVES: usize = 100;

struct HermiteInput {
    start: Vec<Vec<BigRational>>,
    end: Vec<Vec<BigRational>>,
    t0: BigRational,
    t1: BigRational,
    is_point: bool,
}

fn read_hermite(doc: &Map<String, Value>) -> Result<HermiteInput, InputError> {
    input::only_fields(doc, &["start", "end", "interval"])?;
    let (start, start_points) = input::uniform_values(input::field(doc, "start")?, "start")?;
    let (end, end_points) = input::uniform_values(input::field(doc, "end")?, "end")?;
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

/// Control points of every coordinate in the number type `T`.
fn hermite_in<T: Field>(data: &HermiteInput, ctx: &T::Ctx) -> Result<Out<T>, InputError> {
    let conv = |v: &[Vec<BigRational>]| -> Vec<Vec<T>> {
        v.iter()
            .map(|p| p.iter().map(|q| T::from_rational(q, ctx)).collect())
            .collect()
    };
    let (t0, t1) = (
        T::from_rational(&data.t0, ctx),
        T::from_rational(&data.t1, ctx),
    );
    let polygon = hermite::solve_points(&conv(&data.start), &conv(&data.end), &t0, &t1)
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
pub fn run_hermite(doc: &Map<String, Value>, scalar: ScalarKind) -> Result<Rendered, InputError> {
    let data = read_hermite(doc)?;
    let name = scalar.to_string();
    Ok(match scalar {
        ScalarKind::F64 => {
            Rendered::plain(hermite_in::<f64>(&data, &())?.with_field("scalar", Out::Text(name)))
        }
        ScalarKind::Rational => Rendered::plain(
            hermite_in::<BigRational>(&data, &())?.with_field("scalar", Out::Text(name)),
        ),
        ScalarKind::Mpfr(bits) => Rendered::certified(
            hermite_in::<Float>(&data, &bits)?.with_field("scalar", Out::Text(name.clone())),
            hermite_in::<Float>(&data, &(2 * bits))?.with_field("scalar", Out::Text(name)),
        ),
    })
}

/// `run hermite-condition`: κ₂ of the transform or of its binomial part.
pub fn run_condition(doc: &Map<String, Value>, scalar: ScalarKind) -> Result<Rendered, InputError> {
    input::only_fields(doc, &["derivatives", "interval", "matrix"])?;
    let m = input::count(
        input::field(doc, "derivatives")?,
        "derivatives",
        MAX_CONDITION_DERIVATIVES,
    )?;
    let (t0, t1) = input::interval(input::field(doc, "interval")?, "interval")?;
    let kind = input::choice(
        doc,
        "matrix",
        &[
            ("transform", TransformKind::Transform),
            ("binomial", TransformKind::Binomial),
        ],
        None,
    )?;
    // JSON has no infinity: null when the f64 matrix overflows or nalgebra's σ_min is 0.
    let raw_reference = condition::f64_reference(m, &t0, &t1, kind);
    let reference = raw_reference.filter(|k| k.is_finite());
    let f64_note = match raw_reference {
        None => "the f64 matrix overflows",
        Some(k) if k.is_infinite() => "nalgebra's f64 SVD returns σmin = 0",
        Some(_) => "nalgebra's f64 SVD of the correctly rounded matrix",
    };
    let jacobi_failed = |e: crate::linalg::svd::NoConvergence| InputError(format!("input: {e}"));
    let (value, digits, scalar_name): (String, u32, String) = match scalar {
        ScalarKind::Rational => {
            return fail("option --scalar: rational cannot take the square roots of an SVD; use f64 or mpfr:<bits>");
        }
        ScalarKind::Mpfr(bits) => {
            let (c, _): (Certified, Float) =
                condition::certified(m, &t0, &t1, kind, bits).map_err(jacobi_failed)?;
            (c.text, c.digits, format!("mpfr:{bits}"))
        }
        ScalarKind::F64 => {
            let Some(k) = f64_matrix_condition(m, &t0, &t1, kind) else {
                return fail(format!(
                    "field \"derivatives\": the factorials n!/(n−j)! of {m} derivatives overflow f64; use --scalar mpfr:<bits>"
                ));
            };
            let k = k.map_err(jacobi_failed)?;
            // Digits of the f64 result that a certified MPFR value confirms.
            let (exact, reference_value) =
                condition::certified(m, &t0, &t1, kind, 256).map_err(jacobi_failed)?;
            let confirmed = correct_digits(k, &reference_value).min(exact.digits);
            (crate::scalar::float_text(k), confirmed, "f64".into())
        }
    };
    let out: Out<f64> = Out::object(vec![
        ("condition_number", Out::Text(value)),
        ("certified_digits", Out::Int(digits as i64)),
        ("f64", reference.map_or(Out::Null, Out::F64)),
        ("f64_note", Out::Text(f64_note.into())),
        ("scalar", Out::Text(scalar_name)),
        ("size", Out::Int(2 * m as i64 + 2)),
    ]);
    Ok(Rendered::plain(out))
}

/// Our generic Jacobi in f64 on the f64 matrix, or `None` when an entry is not finite.
fn f64_matrix_condition(
    m: usize,
    t0: &BigRational,
    t1: &BigRational,
    kind: TransformKind,
) -> Option<Result<f64, crate::linalg::svd::NoConvergence>> {
    let a = crate::hermite::transform_matrix(m, t0, t1, kind).map(|q| q.to_f64());
    if a.entries().iter().any(|x| !x.is_finite()) {
        return None;
    }
    Some(crate::linalg::condition_number(&a))
}
