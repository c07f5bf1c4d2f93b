//! The one place where `run` turns the user's `--scalar` into a number type.
//!
//! A command describes its computation once, generically, as a [`FieldJob`] (field
//! operations only: it also runs exactly in rationals) or a [`RealJob`] (square roots and
//! transcendental functions: f64, MPFR and balls). [`run_field`] and [`run_real`] then run
//! it in f64, in rationals, or in ball arithmetic, and add the `"scalar"` field to the
//! output. `mpfr:<bits>` **is** ball arithmetic at `bits` printed as decimals: each number
//! with the digits its enclosure proves, so a printed digit cannot be wrong however many bits
//! the problem needs (a run at p and 2p bits can agree on wrong digits when the problem
//! needs more than both). A command whose proven form is not its generic body (κ₂
//! by inertia, conversion errors by branch and bound) is a [`ProvenJob`], run by
//! [`run_proven_job`]. This is the only `match` on the number type in `run`.

use super::input::{fail, RunError};
use super::output::Out;
use super::Rendered;
use crate::scalar::ball::{tally, Ball};
use crate::scalar::{Exact, Field, Real, ScalarKind};

/// A computation that needs only `+ − × ÷`: runs in f64, rationals, MPFR and balls.
pub trait FieldJob {
    fn run<T: Field>(&self, ctx: &T::Ctx) -> Result<Out<T>, RunError>;
    /// Whether an f64 answer is checked against a proven enclosure ([`check_f64`]): for the
    /// methods whose f64 result can lose every digit without an error of its own.
    fn checks_f64(&self) -> bool {
        false
    }
}

/// A computation that needs square roots or transcendental functions: f64, MPFR and balls.
pub trait RealJob {
    fn run<T: Real>(&self, ctx: &T::Ctx) -> Result<Out<T>, RunError>;
    /// The computation in ball arithmetic at `bits`: by default the generic one; a job
    /// overrides it where the generic method would only estimate what balls can prove (a
    /// sampled maximum, replaced by a proven enclosure; an iteration, replaced by the exact
    /// values it converges to).
    fn run_ball(&self, bits: u32) -> Result<Out<Ball>, RunError> {
        self.run::<Ball>(&bits)
    }
    /// Whether an f64 answer is checked against a proven enclosure ([`check_f64`]).
    fn checks_f64(&self) -> bool {
        false
    }
}

/// The precision of the enclosure an f64 answer is checked against, and the one tried when
/// that enclosure cannot decide.
pub const F64_CHECK_BITS: [u32; 2] = [128, 512];

/// The f64 answer `out`, refused (exit 2, naming the field) when it keeps no correct digit in
/// the norm: for each top-level field, max |x − y| over its numbers must stay below
/// ½ max |y|, y the exact values. `reference(bits)` computes the same output in balls, which
/// enclose every y; the check is exact arithmetic on the printed doubles and the balls' ends,
/// so it passes only where the digit is proven. When no reference at [`F64_CHECK_BITS`]
/// answers, the f64 answer cannot be checked and is refused too.
pub fn check_f64(
    out: Out<f64>,
    reference: impl Fn(u32) -> Result<Out<Ball>, RunError>,
) -> Result<Out<f64>, RunError> {
    // A number the double cannot hold is refused at the output, naming it (inf, NaN).
    let mut numbers = Vec::new();
    out.numbers("", &mut numbers);
    if numbers.iter().any(|(_, x)| !x.is_finite()) {
        return Ok(out);
    }
    let mut last = String::new();
    for bits in F64_CHECK_BITS {
        let enclosure = match decided(ScalarKind::Ball(bits), || reference(bits)) {
            Ok(e) => e,
            Err(e) => {
                last = match e {
                    RunError::Input(m) | RunError::Internal(m) => m,
                };
                continue;
            }
        };
        match super::output::f64_digit_in_norm(&out, &enclosure) {
            Some(Ok(())) => return Ok(out),
            Some(Err(field)) => {
                return fail(format!(
                    "output \"{field}\": the f64 answer has no correct digit (its error in the norm reaches half the exact value's size, \
                     proven at ball:{bits}); use --scalar mpfr:<bits> or rational"
                ))
            }
            None => last = format!("the ball:{bits} enclosure is too wide to decide"),
        }
    }
    fail(format!(
        "option --scalar: the f64 answer could not be checked against a proven enclosure ({last}); use --scalar mpfr:<bits>"
    ))
}

fn named<T>(out: Out<T>, scalar: ScalarKind) -> Out<T> {
    out.with_field("scalar", Out::Text(scalar.to_string()))
}

/// An f64 output, checked against the proven `reference` first when the job `checks` it
/// ([`check_f64`]).
fn f64_output(
    out: Out<f64>,
    checks: bool,
    reference: impl Fn(u32) -> Result<Out<Ball>, RunError>,
) -> Result<Rendered, RunError> {
    let out = if checks {
        check_f64(out, reference)?
    } else {
        out
    };
    Ok(Rendered::plain(named(out, ScalarKind::F64)))
}

/// A ball computation, refused (exit 2) when it branched on a comparison its balls could not
/// decide: that branch may not hold for every point of the balls, so nothing it computed is
/// proven. The precision is the user's to raise.
fn decided<R>(
    scalar: ScalarKind,
    run: impl FnOnce() -> Result<R, RunError>,
) -> Result<R, RunError> {
    let (out, undecided) = tally(run);
    let out = out?;
    if undecided > 0 {
        return fail(format!(
            "option --scalar: {undecided} comparison(s) could not be decided at {scalar} (the enclosures overlap), \
             so the result is not proven; raise the precision"
        ));
    }
    Ok(out)
}

/// `mpfr:<bits>`: the computation in ball arithmetic at `bits` (MPFR midpoints at that
/// precision with proven error bounds), printed with the digits the enclosures prove
/// ([`super::output::proven_text`]).
fn proven_digits(
    scalar: ScalarKind,
    run: impl FnOnce() -> Result<Out<Ball>, RunError>,
) -> Result<Rendered, RunError> {
    let out = decided(scalar, run)?;
    Ok(Rendered::json(super::output::render_digits(
        &named(out, scalar),
        "",
    )?))
}

/// `ball:<bits>`: the computation in ball arithmetic, each number printed as its enclosure.
fn proven(
    scalar: ScalarKind,
    run: impl FnOnce() -> Result<Out<Ball>, RunError>,
) -> Result<Rendered, RunError> {
    let out = decided(scalar, run)?;
    Ok(Rendered::json(super::output::render_proven(
        &named(out, scalar),
        "",
    )?))
}

/// `job` in the number type `scalar` names.
pub fn run_field(job: &impl FieldJob, scalar: ScalarKind) -> Result<Rendered, RunError> {
    match scalar {
        ScalarKind::F64 => f64_output(job.run::<f64>(&())?, job.checks_f64(), |bits| {
            job.run::<Ball>(&bits)
        }),
        ScalarKind::Rational => Ok(Rendered::plain(named(job.run::<Exact>(&())?, scalar))),
        ScalarKind::Mpfr(bits) => proven_digits(scalar, || job.run::<Ball>(&bits)),
        ScalarKind::Ball(bits) => proven(scalar, || job.run::<Ball>(&bits)),
    }
}

/// `job` in f64 or MPFR; `rational_refusal` is the one-line error for `--scalar rational`.
pub fn run_real(
    job: &impl RealJob,
    scalar: ScalarKind,
    rational_refusal: &str,
) -> Result<Rendered, RunError> {
    run_real_or_exact::<Exact>(job, scalar, || fail(rational_refusal))
}

/// `job` in f64, MPFR or balls, and for `--scalar rational` the computation's exact form
/// `exact`, for the inputs that have one (it returns the refusal for the others).
pub fn run_real_or_exact<E: Field>(
    job: &impl RealJob,
    scalar: ScalarKind,
    exact: impl FnOnce() -> Result<Out<E>, RunError>,
) -> Result<Rendered, RunError> {
    match scalar {
        ScalarKind::F64 => f64_output(job.run::<f64>(&())?, job.checks_f64(), |bits| {
            job.run_ball(bits)
        }),
        ScalarKind::Rational => Ok(Rendered::plain(named(exact()?, scalar))),
        ScalarKind::Mpfr(bits) => proven_digits(scalar, || job.run_ball(bits)),
        ScalarKind::Ball(bits) => proven(scalar, || job.run_ball(bits)),
    }
}

/// A computation with its own f64 form and a proven form in balls (κ₂ by inertia, conversion
/// errors by branch and bound), rather than one generic body; `mpfr:<bits>` prints the
/// digits the ball form proves.
pub trait ProvenJob {
    /// The computation in f64.
    fn f64(&self) -> Result<Rendered, RunError>;
    /// The proven form at `bits`.
    fn ball(&self, bits: u32) -> Result<Out<Ball>, RunError>;
}

/// `job` in f64, MPFR (proven digits) or balls; `rational_refusal` is the one-line error for
/// `--scalar rational`.
pub fn run_proven_job(
    job: &impl ProvenJob,
    scalar: ScalarKind,
    rational_refusal: &str,
) -> Result<Rendered, RunError> {
    match scalar {
        ScalarKind::F64 => job.f64(),
        ScalarKind::Rational => fail(rational_refusal),
        ScalarKind::Mpfr(bits) => proven_digits(scalar, || job.ball(bits)),
        ScalarKind::Ball(bits) => proven(scalar, || job.ball(bits)),
    }
}
