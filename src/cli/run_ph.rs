//! `run ph-hermite`, `run phodcos` and `run convergence`: the JSON shapes that `docs/commands.md` documents.

use super::budget::{self, Rates};
use super::dispatch::{run_proven_job, run_real, ProvenJob, RealJob};
use super::input::{self, fail, InputError, RunError};
use super::json::{Map, Value};
use super::output::{flush, largest, noise_level, Out};
use super::Rendered;
use crate::algo::ph::hermite::{interpolate, FreeParameters, HermiteData, PhHermiteError};
use crate::algo::ph::piecewise::{
    conversion_error, convert, observed_order, phodcos, DEFAULT_SAMPLES,
};
use crate::algo::ph::PhCurve;
use crate::curve::enclosure::{proven_error, ProofOptions};
use crate::curve::{Curve, ExprCurve};
use crate::scalar::ball::Ball;
use crate::scalar::certify::format_float_digits;
use crate::scalar::{Exact, Field, Float, Real, ScalarKind};
use std::cell::Cell;

/// The most segments `run phodcos` accepts (directly or as the tolerance search's limit).
pub const MAX_SEGMENTS: usize = 1 << 16;
/// The largest level of `run convergence` (2ⁿ segments).
pub const MAX_LEVEL: usize = 16;

const DATA_FIELDS: [&str; 10] = [
    "p_b", "p_e", "v_b", "v_e", "a_b", "a_e", "j_b", "j_e", "s_b", "s_e",
];
const FREE_FIELDS: [&str; 9] = [
    "theta0", "tau1", "tau2", "tau3", "theta4", "tau5", "tau6", "tau7", "theta8",
];

/// The optional `free` object: θ0, τ1, τ2, τ3, θ4, τ5, τ6, τ7, θ8 (missing ones are 0).
fn free_parameters(doc: &Map) -> Result<FreeParameters<Exact>, InputError> {
    let mut f = FreeParameters::zero(4, &());
    let Some(v) = doc.get("free") else {
        return Ok(f);
    };
    let obj = v.as_object().ok_or_else(|| {
        InputError(format!(
            "field \"free\": expected an object, found {}",
            input::kind(v)
        ))
    })?;
    input::only_fields(obj, &FREE_FIELDS)
        .map_err(|e| InputError(e.0.replacen("input:", "field \"free\":", 1)))?;
    let get = |name: &str| -> Result<Exact, InputError> {
        obj.get(name).map_or(Ok(Exact::from(0)), |v| {
            input::number(v, format_args!("free.{name}"))
        })
    };
    f.theta_start = get("theta0")?;
    f.theta_mid = get("theta4")?;
    f.theta_end = get("theta8")?;
    f.tau_start = vec![get("tau1")?, get("tau2")?, get("tau3")?];
    f.tau_end = vec![get("tau7")?, get("tau6")?, get("tau5")?];
    Ok(f)
}

fn ph_error(e: PhHermiteError) -> InputError {
    let field = match e {
        PhHermiteError::NoStandardForm => "v_e",
        PhHermiteError::ZeroTangent(name) => name,
        _ => "free",
    };
    InputError(format!("field \"{field}\": {e}"))
}

/// The refusal of `--scalar rational` for the PH commands.
const NEEDS_REAL: &str =
    "option --scalar: PH interpolation takes square roots (Lemma 2); use f64 or mpfr:<bits>";

/// A list of vectors with every entry below the rounding level of the largest one set to 0
/// (see [`noise_level`]: components that vanish mathematically, such as the real part of A_0
/// in standard form, come out as rounding noise of either sign).
fn vectors<T: Real>(rows: Vec<Vec<T>>) -> Out<T> {
    let scale = largest(rows.iter().flatten());
    let level = scale.as_ref().map(noise_level);
    // Every entry may vanish mathematically (balls keep their enclosure of 0; the scale
    // matters only to the flush of the rounding types).
    let entry = |x: T| {
        let s = scale.clone().unwrap_or_else(|| T::zero_in(&x.ctx()));
        Out::MaybeZero(flush(x, level.as_ref()), s)
    };
    Out::List(
        rows.into_iter()
            .map(|r| Out::List(r.into_iter().map(entry).collect()))
            .collect(),
    )
}

fn preimage_out<T: Real>(c: &PhCurve<T>) -> Out<T> {
    vectors(c.preimage.iter().map(|q| q.components().to_vec()).collect())
}

fn curve_out<T: Real>(c: &PhCurve<T>) -> Vec<(&'static str, Out<T>)> {
    vec![
        ("preimage", preimage_out(c)),
        (
            "control_points",
            vectors(c.control_points().into_iter().map(|p| p.to_vec()).collect()),
        ),
        ("arc_length", Out::Num(c.arc_length())),
    ]
}

/// `run ph-hermite`: C⁴ Hermite data → the degree-17 PH interpolant (Algorithm 1).
pub fn run_ph_hermite(doc: &Map, scalar: ScalarKind) -> Result<Rendered, RunError> {
    let mut known = DATA_FIELDS.to_vec();
    known.push("free");
    input::only_fields(doc, &known)?;
    let mut vectors = Vec::new();
    for name in DATA_FIELDS {
        vectors.push(input::point::<3>(input::field(doc, name)?, name)?);
    }
    let free = free_parameters(doc)?;
    run_real(&PhHermiteJob { vectors, free }, scalar, NEEDS_REAL)
}

/// The ten Hermite vectors (in `DATA_FIELDS` order) and the free parameters of `ph-hermite`.
struct PhHermiteJob {
    vectors: Vec<[Exact; 3]>,
    free: FreeParameters<Exact>,
}

impl RealJob for PhHermiteJob {
    fn run<T: Real>(&self, ctx: &T::Ctx) -> Result<Out<T>, RunError> {
        Ok(ph_hermite_in(&self.vectors, &self.free, ctx)?)
    }
}

/// The interpolant of the ten vectors (in `DATA_FIELDS` order) in the number type `T`.
fn ph_hermite_in<T: Real>(
    vectors: &[[Exact; 3]],
    free: &FreeParameters<Exact>,
    ctx: &T::Ctx,
) -> Result<Out<T>, InputError> {
    let conv = |k: usize| vectors[k].clone().map(|q| T::from_exact(&q, ctx));
    let data = HermiteData {
        p_b: conv(0),
        p_e: conv(1),
        start: vec![conv(2), conv(4), conv(6), conv(8)],
        end: vec![conv(3), conv(5), conv(7), conv(9)],
    };
    let c = interpolate(&data, &free.map(|q| T::from_exact(q, ctx))).map_err(ph_error)?;
    Ok(Out::object(curve_out(&c)))
}

/// A curve read from its text, with the text's length (what its evaluation costs).
struct CurveInput {
    curve: ExprCurve,
    text_len: usize,
}

fn read_curve(doc: &Map) -> Result<(CurveInput, Exact, Exact), InputError> {
    let text = match input::field(doc, "curve")? {
        Value::String(s) => s,
        other => {
            return fail(format!(
                "field \"curve\": expected a string like \"[sin(t), cos(t), t]\", found {}",
                input::kind(other)
            ))
        }
    };
    let curve =
        ExprCurve::parse(text.as_ref()).map_err(|e| InputError(format!("field \"curve\": {e}")))?;
    let (a, b) = input::interval(input::field(doc, "interval")?, "interval")?;
    // Proven before any conversion: finite derivatives up to the 4th and a tangent that
    // never vanishes on [a, b] (a cusp is named at its t, not as the empty tangent of a
    // segment's end).
    match crate::curve::regularity::check(
        &curve.compile::<crate::scalar::ball::Ball>(&128),
        &crate::curve::interval::Interval::new(
            crate::scalar::big_rational(&a),
            crate::scalar::big_rational(&b),
        )
        .map_err(|e| InputError(format!("field \"interval\": {e}")))?,
        4,
        128,
    ) {
        // Beyond a ball's range: the per-joint checks of each number type decide.
        Ok(_) | Err(crate::curve::regularity::Irregular::BeyondBallRange { .. }) => {}
        Err(e) => return fail(format!("field \"curve\": on [{a}, {b}] {e}")),
    }
    let curve = CurveInput {
        curve,
        text_len: text.len(),
    };
    Ok((curve, a, b))
}

/// How far a `run` proves a conversion error: to the default relative width, within a box
/// budget, stopping at the run's search deadline (the bounds found by then are printed).
fn run_proof() -> ProofOptions {
    ProofOptions {
        max_boxes: 4_000_000,
        deadline: Some(budget::search_deadline()),
        ..ProofOptions::default()
    }
}

/// Check that the curve is finite with its derivatives at the ends of every segment; return
/// its scale, the largest |coordinate| there, against which a conversion error is noise.
fn check_finite<T: Real, C: Curve<T>>(
    c: &C,
    a: &T,
    b: &T,
    segments: usize,
) -> Result<T, InputError> {
    let mut scale = T::zero_in(&a.ctx());
    for k in 0..=segments {
        let t = crate::algo::ph::piecewise::knot((a, b), segments, k);
        let jet = c.jet(&t, 4);
        if jet.iter().flatten().any(|x| !x.is_finite()) {
            return fail(format!(
                "field \"curve\": not finite (or a derivative up to the 4th is not) at t = {}",
                format_float_digits(&Float::with_val(64, t.to_f64()), 8)
            ));
        }
        if let Some(m) = largest(&jet[0]) {
            if m > scale {
                scale = m;
            }
        }
    }
    Ok(scale)
}

/// What `run phodcos` asks for.
struct PhodcosInput {
    curve: ExprCurve,
    a: Exact,
    b: Exact,
    segments: Option<usize>,
    tolerance: Option<Exact>,
    max_segments: usize,
}

/// The conversion in the number type `T` with `fixed` segments if given, else as asked.
fn phodcos_in<T: Real>(
    input: &PhodcosInput,
    ctx: &T::Ctx,
    fixed: Option<usize>,
) -> Result<(usize, Out<T>), InputError> {
    let c = input.curve.compile::<T>(ctx);
    let (a, b) = (T::from_exact(&input.a, ctx), T::from_exact(&input.b, ctx));
    let scale;
    let (pw, err) = match (fixed.or(input.segments), &input.tolerance) {
        (Some(n), _) => {
            scale = check_finite(&c, &a, &b, n)?;
            let pw = convert(&c, (&a, &b), n, 4, &FreeParameters::zero(4, ctx), true)
                .map_err(ph_error)?;
            let e = conversion_error(&c, &pw, DEFAULT_SAMPLES);
            (pw, e)
        }
        (None, Some(tol)) => {
            scale = check_finite(&c, &a, &b, 1)?;
            phodcos(&c, (&a, &b), &T::from_exact(tol, ctx), input.max_segments)
                .map_err(ph_error)?
                .ok_or_else(|| {
                    InputError(format!(
                    "field \"tolerance\": not reached with {} segments (raise \"max_segments\")",
                    input.max_segments
                ))
                })?
        }
        (None, None) => return fail("input: give exactly one of \"segments\" and \"tolerance\""),
    };
    let n = pw.segments().len();
    let pre = pw.segments().iter().map(preimage_out).collect();
    Ok((
        n,
        Out::object(vec![
            ("segments", Out::Int(n as i64)),
            ("max_error", Out::MaybeZero(err.max, scale.clone())),
            ("sampled_error", Out::MaybeZero(err.sampled, scale)),
            ("preimages", Out::List(pre)),
        ]),
    ))
}

/// The conversion of `run phodcos`. In MPFR the higher precision uses the number of segments
/// the lower one chose (dispatch runs p bits first), so that the two outputs have the same
/// shape and a tolerance search is certified on one segmentation.
struct PhodcosJob {
    input: PhodcosInput,
    chosen: Cell<Option<usize>>,
}

impl RealJob for PhodcosJob {
    fn run<T: Real>(&self, ctx: &T::Ctx) -> Result<Out<T>, RunError> {
        let (n, out) = phodcos_in::<T>(&self.input, ctx, self.chosen.get())?;
        self.chosen.set(Some(n));
        Ok(out)
    }

    /// In balls the error is proven: lower ≤ E ≤ upper by branch and bound
    /// (`curve::enclosure`, relative width 1e-6), printed as the ball [lower, upper]. With a
    /// tolerance, Algorithm 2's search (on sampled errors, in MPFR at `bits`) proposes the
    /// segments, and they are doubled until the proven upper bound meets the tolerance.
    fn run_ball(&self, bits: u32) -> Result<Out<Ball>, RunError> {
        let input = &self.input;
        let Some(mut n) = input.segments else {
            let (proposed, _) = phodcos_in::<Float>(input, &bits, None)?;
            let tolerance = Float::from_exact(input.tolerance.as_ref().unwrap_or(&input.a), &bits);
            let mut n = proposed;
            loop {
                let out = self.proven_at(bits, n)?;
                let proven_below = match &out {
                    Out::Object(fields) => fields.iter().any(|(k, v)| {
                        k == "max_error"
                            && matches!(v, Out::MaybeZero(e, _) if e.upper() < tolerance)
                    }),
                    _ => false,
                };
                if proven_below {
                    return Ok(out);
                }
                if n >= input.max_segments {
                    return fail(format!(
                        "field \"tolerance\": not proven with {} segments at {bits} bits (raise \"max_segments\" or the precision)",
                        input.max_segments
                    ));
                }
                n = (2 * n).min(input.max_segments);
            }
        };
        n = n.max(1);
        self.proven_at(bits, n)
    }
}

impl PhodcosJob {
    /// The conversion on `n` segments in balls at `bits`, its error proven.
    fn proven_at(&self, bits: u32, n: usize) -> Result<Out<Ball>, RunError> {
        let input = &self.input;
        let c = input.curve.compile::<Ball>(&bits);
        let (a, b) = (
            Ball::from_exact(&input.a, &bits),
            Ball::from_exact(&input.b, &bits),
        );
        check_finite(&c, &a, &b, n)?;
        let free = FreeParameters::zero(4, &bits);
        // The error depends on positions only, which the roll correction (Eq. 22) leaves
        // alone: it is searched on the conversion before the roll, whose balls the chained
        // rotations do not widen; the printed preimages are that conversion rolled.
        let mut pw = convert(&c, (&a, &b), n, 4, &free, false).map_err(ph_error)?;
        let e =
            proven_error(&c, &pw, &run_proof()).map_err(|e| RunError::Internal(e.to_string()))?;
        pw.align_roll();
        Ok(Out::object(vec![
            ("segments", Out::Int(n as i64)),
            // 0 for a curve the method reproduces (a straight line), up to the enclosure.
            (
                "max_error",
                Out::MaybeZero(Ball::from_bounds(&e.lower, &e.upper), Ball::zero_in(&bits)),
            ),
            ("max_error_relative_width", Out::F64(e.relative_width())),
            (
                "preimages",
                Out::List(pw.segments().iter().map(preimage_out).collect()),
            ),
        ]))
    }
}

/// `run phodcos`: a curve on uniform segments (or the fewest meeting a tolerance).
pub fn run_phodcos(doc: &Map, scalar: ScalarKind) -> Result<Rendered, RunError> {
    input::only_fields(
        doc,
        &["curve", "interval", "segments", "tolerance", "max_segments"],
    )?;
    let (curve, a, b) = read_curve(doc)?;
    let segments = doc
        .get("segments")
        .map(|v| input::count(v, "segments", MAX_SEGMENTS))
        .transpose()?;
    let tolerance = doc
        .get("tolerance")
        .map(|v| input::number(v, "tolerance"))
        .transpose()?;
    let max_segments = doc
        .get("max_segments")
        .map(|v| input::count(v, "max_segments", MAX_SEGMENTS))
        .transpose()?
        .unwrap_or(4096);
    match (&segments, &tolerance) {
        (Some(_), Some(_)) | (None, None) => {
            return fail("input: give exactly one of \"segments\" and \"tolerance\"")
        }
        (Some(0), _) => return fail("field \"segments\": at least 1 segment"),
        (_, Some(t)) if *t <= 0 => return fail("field \"tolerance\": must be positive"),
        _ => {}
    }
    if max_segments == 0 {
        return fail("field \"max_segments\": at least 1 segment");
    }
    // One conversion and error search per segment (measured on the README's curve: 65536
    // segments in 2.1 s in f64, 1024 in 1.3 s at mpfr:256); a tolerance search may convert
    // up to twice max_segments. Output: 36 numbers per segment.
    let (field, worst) = match segments {
        Some(n) => ("segments", n as f64),
        None => ("max_segments", 2.0 * max_segments as f64),
    };
    // A proven enclosure (ball, and mpfr, which prints its digits) adds the branch and bound,
    // whose boxes grow faster than the segments: as segments^1.3 (measured at mpfr:256: 256
    // segments in 0.18 s; at ball:256 4096 in 6.5 s, 16384 in over 60 s).
    let proven = matches!(scalar, ScalarKind::Ball(_) | ScalarKind::Mpfr(_));
    let units = if proven { 1.8 * worst.powf(1.3) } else { worst }
        * budget::expression_factor(curve.text_len);
    let rates = Rates {
        f64: 4e-5,
        mpfr256: 1.2e-4,
        rational: 0.0,
    };
    rates.check(
        units,
        scalar,
        field,
        &format!("{worst} segments at {scalar}"),
    )?;
    budget::check_output(36.0 * worst, field, "this run")?;
    let input = PhodcosInput {
        curve: curve.curve,
        a,
        b,
        segments,
        tolerance,
        max_segments,
    };
    let job = PhodcosJob {
        input,
        chosen: Cell::new(None),
    };
    run_real(&job, scalar, NEEDS_REAL)
}

/// The levels of `run convergence` and what each one converts.
struct ConvergenceJob {
    curve: ExprCurve,
    a: Exact,
    b: Exact,
    levels: Vec<u32>,
    free: FreeParameters<Exact>,
}

impl ConvergenceJob {
    /// One row per level: the error, the ratio to the previous level's error and the observed
    /// order log₂(ratio)/(level gap) (both `null` where an error may be zero).
    fn rows<T: Real>(
        &self,
        mut error: impl FnMut(usize) -> Result<Out<T>, RunError>,
    ) -> Result<Out<T>, RunError> {
        let mut rows = Vec::new();
        let mut previous: Option<(u32, Out<T>)> = None;
        for &n in &self.levels {
            let segments = 1usize << n;
            let e = error(segments)?;
            let (ratio, order) = match (&previous, &e) {
                (
                    Some((level, Out::Num(coarse) | Out::MaybeZero(coarse, _))),
                    Out::Num(fine) | Out::MaybeZero(fine, _),
                ) if proven_nonzero(coarse) && proven_nonzero(fine) => {
                    let gap = T::from_i64(i64::from(n - level), &fine.ctx());
                    match observed_order(coarse, fine) {
                        Some((ratio, log2)) => (Out::Num(ratio), Out::Num(log2 / &gap)),
                        None => (Out::Null, Out::Null),
                    }
                }
                _ => (Out::Null, Out::Null),
            };
            rows.push(Out::object(vec![
                ("segments", Out::Int(segments as i64)),
                ("error", e.clone()),
                ("ratio", ratio),
                ("order", order),
            ]));
            previous = Some((n, e));
        }
        Ok(Out::object(vec![("rows", Out::List(rows))]))
    }
}

/// Whether x ≠ 0 is decided (for a ball: the enclosure excludes 0).
fn proven_nonzero<T: Field>(x: &T) -> bool {
    T::zero_in(&x.ctx()).decide_lt(&x.clone().abs()) == Some(true)
}

impl ProvenJob for ConvergenceJob {
    fn f64(&self) -> Result<Rendered, RunError> {
        let c = self.curve.compile::<f64>(&());
        let (fa, fb) = (f64::from_exact(&self.a, &()), f64::from_exact(&self.b, &()));
        let free = self.free.map(|q| f64::from_exact(q, &()));
        let rows = self.rows(|segments| {
            check_finite(&c, &fa, &fb, segments)?;
            let pw = convert(&c, (&fa, &fb), segments, 4, &free, true).map_err(ph_error)?;
            Ok(Out::Num(conversion_error(&c, &pw, DEFAULT_SAMPLES).max))
        })?;
        Ok(Rendered::plain(
            rows.with_field("scalar", Out::Text("f64".into())),
        ))
    }

    /// Each level's error proven by branch and bound in balls (`curve::enclosure`, to a
    /// relative width of 1e-6 or the deadline), so the ratios and orders are proven too; an
    /// enclosure that reaches 0 (a curve the method reproduces) has no ratio or order.
    fn ball(&self, bits: u32) -> Result<Out<Ball>, RunError> {
        let c = self.curve.compile::<Ball>(&bits);
        let (a, b) = (
            Ball::from_exact(&self.a, &bits),
            Ball::from_exact(&self.b, &bits),
        );
        let free = self.free.map(|q| Ball::from_exact(q, &bits));
        self.rows(|segments| {
            check_finite(&c, &a, &b, segments)?;
            // The error depends on positions only, which the roll correction leaves alone.
            let pw = convert(&c, (&a, &b), segments, 4, &free, false).map_err(ph_error)?;
            let e = proven_error(&c, &pw, &run_proof())
                .map_err(|e| RunError::Internal(e.to_string()))?;
            Ok(Out::MaybeZero(
                Ball::from_bounds(&e.lower, &e.upper),
                Ball::zero_in(&bits),
            ))
        })
    }
}

/// `run convergence`: the error on 2ⁿ segments for each level, with ratios and orders.
pub fn run_convergence(doc: &Map, scalar: ScalarKind) -> Result<Rendered, RunError> {
    input::only_fields(doc, &["curve", "interval", "levels", "free"])?;
    let (curve, a, b) = read_curve(doc)?;
    let levels: Vec<u32> = input::array(input::field(doc, "levels")?, "levels")?
        .iter()
        .enumerate()
        .map(|(i, v)| input::count(v, &format!("levels[{i}]"), MAX_LEVEL).map(|n| n as u32))
        .collect::<Result<_, _>>()?;
    if levels.is_empty() {
        return fail("field \"levels\": at least one level");
    }
    if let Some(i) = (1..levels.len()).find(|&i| levels[i] <= levels[i - 1]) {
        return fail(format!(
            "field \"levels[{i}]\": levels must increase ({} after {})",
            levels[i],
            levels[i - 1]
        ));
    }
    let free = free_parameters(doc)?;
    // Conversion and certified error on 2ⁿ segments per level (measured on the README's
    // curve: 65536 segments in 1 s in f64; levels 9 and 10, 1536 segments, in 0.58 s at
    // mpfr:256, the proven error's branch and bound included).
    let segments: f64 = levels.iter().map(|&n| (n as f64).exp2()).sum();
    let units = segments * budget::expression_factor(curve.text_len);
    // In MPFR and balls each error is proven by branch and bound, as `phodcos` in balls.
    let rates = Rates {
        f64: 2.5e-5,
        mpfr256: 1e-3,
        rational: 0.0,
    };
    rates.check(
        units,
        scalar,
        "levels",
        &format!("{segments} segments over the levels at {scalar}"),
    )?;
    let job = ConvergenceJob {
        curve: curve.curve,
        a,
        b,
        levels,
        free,
    };
    run_proven_job(&job, scalar, NEEDS_REAL)
}
