//! The one place where `run` turns the user's `--scalar` into a number type.
//!
//! A command describes its computation once, generically, as a [`FieldJob`] (field
//! operations only: it also runs exactly in rationals) or a [`RealJob`] (square roots and
//! transcendental functions: f64 and MPFR only). [`run_field`] and [`run_real`] then run it
//! in f64, in rationals, or in MPFR at p and at 2p bits (printed with the digits the two
//! agree on), and add the `"scalar"` field to the output. A command whose method uses its two
//! precisions together (the certified error search of `convergence`, the Jacobi of
//! `hermite-condition` raised until digits agree, checked against MPFR in f64) is a
//! [`TwoPrecisionJob`], run by [`run_two_precision`]. This is the only `match` on the
//! number type in `run`.

use super::input::{fail, RunError};
use super::output::Out;
use super::Rendered;
use crate::scalar::ball::{tally, Ball};
use crate::scalar::{BigRational, Field, Float, Real, ScalarKind};

/// A computation that needs only `+ − × ÷`: runs in f64, rationals and MPFR.
pub trait FieldJob {
    fn run<T: Field>(&self, ctx: &T::Ctx) -> Result<Out<T>, RunError>;
}

/// A computation that needs square roots or transcendental functions: f64, MPFR and balls.
pub trait RealJob {
    fn run<T: Real>(&self, ctx: &T::Ctx) -> Result<Out<T>, RunError>;
    /// The computation in ball arithmetic at `bits`: by default the generic one; a job
    /// overrides it where the generic method would only estimate what balls can prove (a
    /// sampled maximum, replaced by a proven enclosure).
    fn run_ball(&self, bits: u32) -> Result<Out<Ball>, RunError> {
        self.run::<Ball>(&bits)
    }
}

fn named<T>(out: Out<T>, scalar: ScalarKind) -> Out<T> {
    out.with_field("scalar", Out::Text(scalar.to_string()))
}

/// MPFR at `bits` and then at `2·bits` (in that order: a job may carry a choice made at the
/// lower precision to the higher), to be printed with the digits the two agree on.
fn certified(
    scalar: ScalarKind,
    bits: u32,
    run: impl Fn(u32) -> Result<Out<Float>, RunError>,
) -> Result<Rendered, RunError> {
    Ok(Rendered::certified(
        named(run(bits)?, scalar),
        named(run(2 * bits)?, scalar),
    ))
}

/// A ball computation at `bits`, printed with the digits its enclosures prove and their
/// radii; refused when it made an undecided comparison (its branches may not hold for every
/// point of the balls, so the enclosure would not be proven).
fn proven(
    scalar: ScalarKind,
    run: impl FnOnce() -> Result<Out<Ball>, RunError>,
) -> Result<Rendered, RunError> {
    let (out, undecided) = tally(run);
    let out = out?;
    if undecided > 0 {
        return Err(RunError::Internal(format!(
            "{undecided} comparison(s) could not be decided in {scalar} (the balls overlap), so the result is not proven; \
             raise the precision, or use mpfr:<bits> for certified digits"
        )));
    }
    Ok(Rendered::json(super::output::render_proven(
        &named(out, scalar),
        "",
    )?))
}

/// Refuse `--scalar ball:<bits>` for a method whose result a ball cannot prove (an
/// iteration stopped by a tolerance, a quadrature whose truncation error is not enclosed).
pub fn refuse_ball(scalar: ScalarKind, reason: &str) -> Result<(), RunError> {
    match scalar {
        ScalarKind::Ball(_) => fail(format!(
            "option --scalar: {scalar} is not available here: {reason}"
        )),
        _ => Ok(()),
    }
}

/// `job` in the number type `scalar` names.
pub fn run_field(job: &impl FieldJob, scalar: ScalarKind) -> Result<Rendered, RunError> {
    match scalar {
        ScalarKind::F64 => Ok(Rendered::plain(named(job.run::<f64>(&())?, scalar))),
        ScalarKind::Rational => Ok(Rendered::plain(named(job.run::<BigRational>(&())?, scalar))),
        ScalarKind::Mpfr(bits) => certified(scalar, bits, |p| job.run::<Float>(&p)),
        ScalarKind::Ball(bits) => proven(scalar, || job.run::<Ball>(&bits)),
    }
}

/// `job` in f64 or MPFR; `rational_refusal` is the one-line error for `--scalar rational`.
pub fn run_real(
    job: &impl RealJob,
    scalar: ScalarKind,
    rational_refusal: &str,
) -> Result<Rendered, RunError> {
    run_real_or_exact(job, scalar, || fail(rational_refusal))
}

/// `job` in f64 or MPFR, and for `--scalar rational` the computation's exact form `exact`,
/// for the inputs that have one (it returns the refusal for the others).
pub fn run_real_or_exact(
    job: &impl RealJob,
    scalar: ScalarKind,
    exact: impl FnOnce() -> Result<Out<BigRational>, RunError>,
) -> Result<Rendered, RunError> {
    match scalar {
        ScalarKind::F64 => Ok(Rendered::plain(named(job.run::<f64>(&())?, scalar))),
        ScalarKind::Rational => Ok(Rendered::plain(named(exact()?, scalar))),
        ScalarKind::Mpfr(bits) => certified(scalar, bits, |p| job.run::<Float>(&p)),
        ScalarKind::Ball(bits) => proven(scalar, || job.run_ball(bits)),
    }
}

/// A computation whose method uses its two MPFR precisions together, so it renders its own
/// certified output; this module still chooses which number type runs.
pub trait TwoPrecisionJob {
    /// The computation in f64.
    fn f64(&self) -> Result<Rendered, RunError>;
    /// The computation at `bits` (and whatever higher precision its method certifies with).
    fn mpfr(&self, bits: u32) -> Result<Rendered, RunError>;
    /// A proven form at `bits`, for the methods that have one (by default, refused).
    fn ball(&self, bits: u32) -> Result<Out<Ball>, RunError> {
        fail(format!(
            "option --scalar: ball:{bits} is not available here: this method compares two MPFR precisions to certify its digits"
        ))
    }
}

/// `job` in f64 or MPFR; `rational_refusal` is the one-line error for `--scalar rational`.
pub fn run_two_precision(
    job: &impl TwoPrecisionJob,
    scalar: ScalarKind,
    rational_refusal: &str,
) -> Result<Rendered, RunError> {
    match scalar {
        ScalarKind::F64 => job.f64(),
        ScalarKind::Rational => fail(rational_refusal),
        ScalarKind::Mpfr(bits) => job.mpfr(bits),
        ScalarKind::Ball(bits) => proven(scalar, || job.ball(bits)),
    }
}
