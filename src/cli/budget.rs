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
use std::sync::{mpsc, Mutex};
use std::time::{Duration, Instant};

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
/// multiplication in this range), fitted to κ₂ of paper 000 at m = 30 from 256 to 2048 bits.
/// Below 256 bits it stays 1: a lower precision makes each operation a little cheaper, but
/// quadratures, searches and bisections then take more steps (measured: `run convergence`
/// at level 16 took 42 s at mpfr:64 where level 12 at mpfr:128 took 0.9 s, 3× the per-segment
/// cost; an ERBS path at mpfr:64 more than at mpfr:128).
pub fn mpfr_factor(bits: u32) -> f64 {
    let one = |p: f64| 0.5 + 0.5 * (p / 256.0).powf(1.6);
    let pair = |p: f64| one(p) + one(2.0 * p);
    pair(bits.max(256) as f64) / pair(256.0)
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

/// The largest estimate accepted since the command started ([`mark_start`]), with the field
/// and run it described: what the deadline's message names if the model was wrong.
static ACCEPTED: Mutex<Option<(f64, String, String)>> = Mutex::new(None);

/// The time after which a `run` is stopped ([`run_with_deadline`]): the budget less a margin
/// for starting the process and printing.
pub const DEADLINE_SECONDS: f64 = BUDGET_SECONDS - 1.0;

/// Refuse a run whose estimate exceeds the budget, naming `field` (the size that drives the
/// cost) and describing the run as `what` ("4096 segments at mpfr:1024").
pub fn check_time(seconds: f64, field: &str, what: &str) -> Result<(), InputError> {
    if seconds.is_finite() && seconds <= BUDGET_SECONDS {
        if let Ok(mut accepted) = ACCEPTED.lock() {
            if accepted.as_ref().is_none_or(|(s, _, _)| seconds >= *s) {
                *accepted = Some((seconds, field.to_string(), what.to_string()));
            }
        }
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

/// Run `job` (a whole `run` command) on a worker thread and wait at most
/// [`DEADLINE_SECONDS`]: the cost models are fitted and err on the side of refusing, and this
/// is the guarantee behind them. A run past the deadline ends with `Err(message)` naming the
/// field of the largest estimate accepted; nothing has been printed (the caller prints the
/// output only after the job returns), and returning from `main` ends the worker.
pub fn run_with_deadline<R: Send + 'static>(
    job: impl FnOnce() -> R + Send + 'static,
    deadline: Duration,
) -> Result<R, String> {
    let (send, receive) = mpsc::channel();
    // The main thread's stack size: expression nesting is limited for it.
    let spawned = std::thread::Builder::new()
        .stack_size(WORKER_STACK_BYTES)
        .spawn(move || {
            let _ = send.send(job());
        });
    if spawned.is_err() {
        return Err("internal: could not start the worker thread".into());
    }
    match receive.recv_timeout(deadline) {
        Ok(result) => Ok(result),
        Err(mpsc::RecvTimeoutError::Timeout) => Err(deadline_message(deadline)),
        Err(mpsc::RecvTimeoutError::Disconnected) => {
            Err("internal: the run stopped without an answer".into())
        }
    }
}

/// When the latest command started ([`mark_start`]), for deadlines inside methods.
static STARTED: Mutex<Option<Instant>> = Mutex::new(None);

/// Record the start of a command: the process's one command, or each of the commands a
/// test runs in process ([`super::run_text`]), so that a proof's deadline counts from its own
/// command, not from the process's start.
pub fn mark_start() {
    if let Ok(mut started) = STARTED.lock() {
        *started = Some(Instant::now());
    }
    if let Ok(mut accepted) = ACCEPTED.lock() {
        *accepted = None;
    }
}

/// The cost model's estimate for the latest command, in seconds on the reference machine:
/// the largest one it accepted ([`check_time`]), `None` if it checked none. For the bench
/// that sets the models against measured times (`benches/cost_models.rs`).
pub fn accepted_estimate() -> Option<f64> {
    ACCEPTED
        .lock()
        .ok()
        .and_then(|a| a.as_ref().map(|(s, _, _)| *s))
}

/// The time by which a refining search (a proven enclosure's branch and bound) should stop
/// and return the bounds it has, leaving time to print them inside the budget: 8 s before
/// [`DEADLINE_SECONDS`] after the command started.
pub fn search_deadline() -> Instant {
    let started = match STARTED.lock() {
        Ok(mut s) => *s.get_or_insert_with(Instant::now),
        Err(_) => Instant::now(),
    };
    started + Duration::from_secs_f64(DEADLINE_SECONDS - 8.0)
}

/// The stack of the thread that runs a command (as the main thread's on Linux).
const WORKER_STACK_BYTES: usize = 8 << 20;

fn deadline_message(deadline: Duration) -> String {
    let (seconds, field, what) = ACCEPTED.lock().ok().and_then(|a| a.clone()).unwrap_or((
        0.0,
        "input".into(),
        "this run".into(),
    ));
    format!(
        "field \"{field}\": {what} did not finish within {:.0} s (its cost model estimated about {} s), so it was stopped inside the {BUDGET_SECONDS} s budget of one run; make it smaller or change the precision",
        deadline.as_secs_f64(),
        seconds.ceil()
    )
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

/// How much longer exact arithmetic takes on these input numbers than on small integers: the
/// numbers an exact elimination builds grow with the bits of its inputs, and each operation
/// costs about the square of their size (GMP's gcd). `bits` is the mean of the numerators'
/// and denominators' bits over `values`; the factor is (1 + bits/6.6)^`power`, fitted per
/// algorithm on decimals of 2 to 16 digits (`benches/cost_models.rs`). 1 for no values.
pub fn exact_size_factor<'a>(
    values: impl IntoIterator<Item = &'a crate::scalar::Exact>,
    power: f64,
) -> f64 {
    let (mut total, mut count) = (0.0, 0.0);
    for q in values {
        total += f64::from(q.numer().significant_bits() + q.denom().significant_bits());
        count += 1.0;
    }
    if count == 0.0 {
        return 1.0;
    }
    (1.0 + total / count / 6.6).powf(power)
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
        assert_eq!(mpfr_factor(64), 1.0);
        assert_eq!(mpfr_factor(16), 1.0);
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

    #[test]
    fn a_run_past_its_deadline_is_stopped_with_the_field_named() {
        check_time(2.0, "segments", "64 segments at ball:16").unwrap();
        let quick = run_with_deadline(|| 7, Duration::from_secs(5));
        assert_eq!(quick, Ok(7));
        let slow = run_with_deadline(
            || std::thread::sleep(Duration::from_secs(3)),
            Duration::from_millis(100),
        );
        let message = slow.unwrap_err();
        assert!(message.starts_with("field \""), "{message}");
        assert!(message.contains("did not finish within"), "{message}");
    }
}
