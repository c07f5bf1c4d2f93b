//! Work budgets of `run`: every accepted input is answered within [`BUDGET_SECONDS`] on the
//! project's reference machine (two cores), in at most [`MEMORY_BOUND_BYTES`] of memory, or
//! refused before anything is computed.
//!
//! Each algorithm estimates its running time from the sizes of its input (points, segments,
//! samples, derivatives, levels, the length of a curve expression) and the number type. The
//! estimates are cost models fitted to measured runs (see `docs/limits.md`):
//! a power of the sizes times a rate per number type, with the rates measured on the
//! reference machine and rounded up. An MPFR run computes at p and at 2p bits; its cost
//! relative to `mpfr:256` is [`mpfr_factor`]. The models err on the side of refusing: the
//! fuzz test (`tests/fuzz.rs`) runs accepted inputs under a wall-clock and memory limit.
//!
//! A refusal is one line naming the field that drives the cost, the estimate and the limit.

use super::input::{fail, InputError};
use crate::scalar::ScalarKind;

/// The longest an accepted run may take on the reference machine (two cores), in seconds.
pub const BUDGET_SECONDS: f64 = 30.0;
/// The memory an accepted run stays under (checked by the fuzz test with an address-space
/// limit).
pub const MEMORY_BOUND_BYTES: u64 = 2 << 30;
/// The most numbers one output may hold (about 200 bytes each while it is built and
/// printed, so well under [`MEMORY_BOUND_BYTES`]).
pub const MAX_OUTPUT_NUMBERS: f64 = 3.0e6;
/// The largest input document, in bytes.
pub const MAX_INPUT_BYTES: usize = 16 << 20;

/// The cost of an MPFR run at `bits` (computed at `bits` and at 2·`bits`) relative to one at
/// 256 bits: per precision, a fixed overhead plus a part growing as p^1.6 (GMP's
/// multiplication in this range), fitted to κ₂ of paper 000 at m = 30 from 53 to 2048 bits.
pub fn mpfr_factor(bits: u32) -> f64 {
    let one = |p: f64| 0.5 + 0.5 * (p / 256.0).powf(1.6);
    let pair = |p: f64| one(p) + one(2.0 * p);
    pair(bits as f64) / pair(256.0)
}

/// Seconds per unit of work for each number type (None: the number type is refused
/// elsewhere, or costs nothing worth modelling).
#[derive(Clone, Copy, Debug)]
pub struct Rates {
    /// In f64.
    pub f64: f64,
    /// At `mpfr:256` (both precisions); other precisions scale by [`mpfr_factor`].
    pub mpfr256: f64,
    /// In exact rationals.
    pub rational: f64,
}

impl Rates {
    /// The estimated seconds for `units` of work in `scalar`.
    pub fn seconds(&self, units: f64, scalar: ScalarKind) -> f64 {
        units
            * match scalar {
                ScalarKind::F64 => self.f64,
                // One ball run costs about what the two certified MPFR runs do.
                ScalarKind::Mpfr(bits) | ScalarKind::Ball(bits) => self.mpfr256 * mpfr_factor(bits),
                ScalarKind::Rational => self.rational,
            }
    }
}

impl Rates {
    /// [`check_time`] of `units` of work in `scalar`.
    pub fn check(
        &self,
        units: f64,
        scalar: ScalarKind,
        field: &str,
        what: &str,
    ) -> Result<(), InputError> {
        check_time(self.seconds(units, scalar), field, what)
    }
}

/// Refuse a run whose estimate exceeds the budget, naming `field` (the size that drives the
/// cost) and describing the run as `what` ("4096 segments at mpfr:1024").
pub fn check_time(seconds: f64, field: &str, what: &str) -> Result<(), InputError> {
    if seconds.is_finite() && seconds <= BUDGET_SECONDS {
        return Ok(());
    }
    let shown = if seconds.is_finite() && seconds < 1e6 {
        format!("about {} s", seconds.ceil())
    } else {
        "far longer".to_string()
    };
    fail(format!(
        "field \"{field}\": {what} would take {shown} on two cores, beyond the {BUDGET_SECONDS} s budget of one run; make it smaller or lower the precision"
    ))
}

/// Refuse an output of more than [`MAX_OUTPUT_NUMBERS`] numbers, naming `field`.
pub fn check_output(numbers: f64, field: &str, what: &str) -> Result<(), InputError> {
    if numbers <= MAX_OUTPUT_NUMBERS {
        return Ok(());
    }
    fail(format!(
        "field \"{field}\": {what} would print {numbers:.3e} numbers, more than the {MAX_OUTPUT_NUMBERS:.0e} one output may hold"
    ))
}

/// How much a curve expression of `len` characters costs per evaluation relative to the
/// README's example curves (about 50 characters): every node is evaluated as a Taylor series.
pub fn expression_factor(len: usize) -> f64 {
    (len as f64 / 64.0).max(1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mpfr_factor_is_one_at_256_bits_and_grows() {
        assert!((mpfr_factor(256) - 1.0).abs() < 1e-12);
        assert!(mpfr_factor(64) < 1.0 && mpfr_factor(64) > 0.2);
        // Measured: κ₂ at m = 30 costs 6.2× at 1024 bits and 19.8× at 2048 bits.
        assert!((5.0..8.0).contains(&mpfr_factor(1024)));
        assert!((15.0..25.0).contains(&mpfr_factor(2048)));
    }

    #[test]
    fn refusals_name_the_field_and_the_budget() {
        assert!(check_time(29.0, "segments", "x").is_ok());
        let e = check_time(45.2, "segments", "4096 segments at mpfr:1024").unwrap_err();
        assert!(e.0.starts_with("field \"segments\": 4096 segments"), "{e}");
        assert!(
            e.0.contains("about 46 s") && e.0.contains("30 s budget"),
            "{e}"
        );
        assert!(check_time(f64::INFINITY, "a", "b")
            .unwrap_err()
            .0
            .contains("far longer"));
        assert!(check_output(4e6, "at", "this")
            .unwrap_err()
            .0
            .contains("field \"at\""));
        assert!(check_output(1e6, "at", "this").is_ok());
    }
}
