//! Stopping a long computation midway: cooperative cancellation.
//!
//! A caller that may want to stop a computation (the Python package on Ctrl-C) runs it with
//! [`run_stoppable`] and a [`StopFlag`]; the library's long loops (Jacobi sweeps, descents,
//! branch and bound, quadratures, fits segment by segment, convergence levels, the claims of
//! `verify`) call [`checkpoint`] once per step. After [`StopFlag::stop`], the next checkpoint
//! on any thread of the job unwinds the job's stack to [`run_stoppable`], which returns
//! [`Stopped`]: memory is freed by the unwinding, nothing is returned half computed, and the
//! threads are free for the next job within a step of the stop.
//!
//! Why unwinding and not a `Result` through every loop: the checkpoints sit deep inside
//! generic algorithms whose signatures (and whose callers' signatures) would all change for
//! a condition only an interactive caller can raise. The unwinding starts with
//! [`std::panic::resume_unwind`], which runs no panic hook (nothing is printed), and it is
//! caught by [`run_stoppable`] only: outside it, [`checkpoint`] does nothing, so the library's
//! public functions never unwind on a caller that did not ask for it.
//!
//! The flag reaches the job's own thread and every thread of a rayon pool built for the job
//! (its threads' start handler installs it), so the library's parallel loops stop too.

use std::cell::RefCell;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

thread_local! {
    /// The flag of the stoppable job this thread works for, if any.
    static CURRENT: RefCell<Option<Arc<AtomicBool>>> = const { RefCell::new(None) };
}

/// The stack of each thread of a stoppable job: the main thread's on Linux, which the
/// expression language's nesting limit is set for.
pub const JOB_STACK_BYTES: usize = 8 << 20;

/// A request to stop, shared between the caller and the job it started with
/// [`run_stoppable`].
#[derive(Clone, Debug, Default)]
pub struct StopFlag(Arc<AtomicBool>);

impl StopFlag {
    /// A flag not yet raised.
    pub fn new() -> Self {
        Self::default()
    }

    /// Ask the job to stop at its next [`checkpoint`].
    pub fn stop(&self) {
        self.0.store(true, Ordering::Relaxed);
    }

    /// Whether [`stop`](Self::stop) was called.
    pub fn is_stopped(&self) -> bool {
        self.0.load(Ordering::Relaxed)
    }
}

/// The job ended at a [`checkpoint`] because its [`StopFlag`] was raised.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Stopped;

impl std::fmt::Display for Stopped {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("the computation was stopped on request")
    }
}

impl std::error::Error for Stopped {}

/// A point where a long loop may stop: unwinds to [`run_stoppable`] if this thread works for
/// a job whose flag was raised; otherwise (and always outside [`run_stoppable`]) does
/// nothing. Costs a thread-local read and an atomic load.
#[inline]
pub fn checkpoint() {
    let raised = CURRENT.with(|current| {
        current
            .borrow()
            .as_ref()
            .is_some_and(|flag| flag.load(Ordering::Relaxed))
    });
    if raised {
        std::panic::resume_unwind(Box::new(Stopped));
    }
}

/// Run `job` so that raising `flag` stops it at its next [`checkpoint`], on `threads`
/// threads of a rayon pool of its own (0: rayon's default, one per core), each with the
/// stack of a command line's worker ([`JOB_STACK_BYTES`]). A panic inside `job` that is not
/// a stop is passed on unchanged.
pub fn run_stoppable<R: Send>(
    flag: &StopFlag,
    threads: usize,
    job: impl FnOnce() -> R + Send,
) -> Result<R, Stopped> {
    let for_pool = Arc::clone(&flag.0);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .stack_size(JOB_STACK_BYTES)
        .start_handler(move |_| {
            install(Some(Arc::clone(&for_pool)));
        })
        .build();
    let outcome = match pool {
        Ok(pool) => std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| pool.install(job))),
        // No threads to be had: run on this one (rayon's loops then use the global pool,
        // whose threads do not see the flag; this thread's checkpoints still do).
        Err(_) => {
            let previous = install(Some(Arc::clone(&flag.0)));
            let outcome = std::panic::catch_unwind(std::panic::AssertUnwindSafe(job));
            install(previous);
            outcome
        }
    };
    match outcome {
        Ok(value) => Ok(value),
        Err(payload) if payload.is::<Stopped>() => Err(Stopped),
        Err(payload) => std::panic::resume_unwind(payload),
    }
}

/// Make `flag` this thread's job flag; returns the one it replaces.
fn install(flag: Option<Arc<AtomicBool>>) -> Option<Arc<AtomicBool>> {
    CURRENT.with(|current| current.replace(flag))
}

#[cfg(test)]
mod tests {
    use super::*;
    use rayon::prelude::*;

    #[test]
    fn a_checkpoint_outside_a_stoppable_job_does_nothing() {
        checkpoint();
    }

    #[test]
    fn a_raised_flag_stops_the_job_on_every_thread_of_its_pool() {
        let flag = StopFlag::new();
        let raise = flag.clone();
        let raiser = std::thread::spawn(move || {
            std::thread::sleep(std::time::Duration::from_millis(50));
            raise.stop();
        });
        // Parallel work on both threads that runs forever unless a checkpoint stops it.
        let outcome = run_stoppable(&flag, 2, || {
            (0..64).into_par_iter().for_each(|_| loop {
                checkpoint();
                std::hint::spin_loop();
            });
            1
        });
        raiser.join().expect("the raising thread ends");
        assert_eq!(outcome, Err(Stopped));
        assert!(flag.is_stopped());
    }

    #[test]
    fn an_unraised_flag_returns_the_answer_and_other_panics_pass_through() {
        let flag = StopFlag::new();
        let sum: Result<i64, Stopped> = run_stoppable(&flag, 2, || {
            (1..=100i64)
                .into_par_iter()
                .map(|i| {
                    checkpoint();
                    i
                })
                .sum()
        });
        assert_eq!(sum, Ok(5050));
        let other = std::panic::catch_unwind(|| {
            run_stoppable(&flag, 1, || std::panic::resume_unwind(Box::new("other")))
        });
        let payload = other.expect_err("the job's own panic is passed on");
        assert_eq!(payload.downcast_ref::<&str>(), Some(&"other"));
    }
}
