//! The one place where `run` turns the user's `--scalar` into a number type.
//!
//! A command describes its computation once, generically, as a [`FieldJob`] (field
//! operations only: it also runs exactly in rationals) or a [`RealJob`] (square roots and
//! transcendental functions: f64 and MPFR only). [`run_field`] and [`run_real`] then run it
//! in f64, in rationals, or in MPFR at p and at 2p bits (printed with the digits the two
//! agree on), and add the `"scalar"` field to the output. Commands whose precision handling
//! is part of their method (the certified error of `convergence`, the segment count chosen at
//! the lower precision in `phodcos`, the exact extras of `bang-bang`) dispatch themselves.

use super::input::{fail, RunError};
use super::output::Out;
use super::Rendered;
use crate::scalar::{BigRational, Field, Float, Real, ScalarKind};

/// A computation that needs only `+ − × ÷`: runs in f64, rationals and MPFR.
pub trait FieldJob {
    fn run<T: Field>(&self, ctx: &T::Ctx) -> Result<Out<T>, RunError>;
}

/// A computation that needs square roots or transcendental functions: f64 and MPFR.
pub trait RealJob {
    fn run<T: Real>(&self, ctx: &T::Ctx) -> Result<Out<T>, RunError>;
}

fn named<T>(out: Out<T>, scalar: ScalarKind) -> Out<T> {
    out.with_field("scalar", Out::Text(scalar.to_string()))
}

/// MPFR at `bits` and `2·bits`, to be printed with the digits the two agree on.
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

/// `job` in the number type `scalar` names.
pub fn run_field(job: &impl FieldJob, scalar: ScalarKind) -> Result<Rendered, RunError> {
    match scalar {
        ScalarKind::F64 => Ok(Rendered::plain(named(job.run::<f64>(&())?, scalar))),
        ScalarKind::Rational => Ok(Rendered::plain(named(job.run::<BigRational>(&())?, scalar))),
        ScalarKind::Mpfr(bits) => certified(scalar, bits, |p| job.run::<Float>(&p)),
    }
}

/// `job` in f64 or MPFR; `rational_refusal` is the one-line error for `--scalar rational`.
pub fn run_real(
    job: &impl RealJob,
    scalar: ScalarKind,
    rational_refusal: &str,
) -> Result<Rendered, RunError> {
    match scalar {
        ScalarKind::F64 => Ok(Rendered::plain(named(job.run::<f64>(&())?, scalar))),
        ScalarKind::Rational => fail(rational_refusal),
        ScalarKind::Mpfr(bits) => certified(scalar, bits, |p| job.run::<Float>(&p)),
    }
}
