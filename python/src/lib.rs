//! `trajverify._trajverify`: the native half of the Python package (PyO3).
//!
//! Two kinds of entry point:
//! - f64 kernels on numpy arrays, in process and without the GIL: the Hermite map
//!   (`hermite_f64`, paper 000, Eq. 8 solved by the library's [`solve_lanes`]) and the
//!   natural cubic spline (`natural_spline_f64`, paper 004, Eq. 2.3), each the library's one
//!   generic algorithm instantiated at f64;
//! - `run`, every algorithm of the command line's `run` on a JSON document, in every number
//!   type, and `verify`, the claims ledger: the same code and the same bytes as the CLI.
//!
//! Errors are exceptions: `TrajverifyError` (a `ValueError`) for input the library refuses,
//! with the command line's one-line message naming the field, and `RuntimeError` for a method
//! that failed on accepted input.

mod ph;

use numpy::{PyArray1, PyArray2, PyArrayMethods, PyReadonlyArray1, PyReadonlyArray2};
use pyo3::create_exception;
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use std::borrow::Cow;
use std::sync::atomic::{AtomicUsize, Ordering};
use trajverify::algo::hermite::solve_lanes;
use trajverify::algo::param::natural::piece_index;
use trajverify::cancel::{run_stoppable, StopFlag};
use trajverify::cli::{run_text, Algorithm, Failure};
use trajverify::scalar::ScalarKind;
use trajverify::NaturalCubicSpline;

create_exception!(
    _trajverify,
    TrajverifyError,
    PyValueError,
    "Input the library refuses: the message names the field, as the command line's does."
);

pub(crate) fn input_error(message: impl Into<String>) -> PyErr {
    TrajverifyError::new_err(message.into())
}

/// The refusal of the first value of `values` (named `field`) that is not finite.
fn check_finite(field: &str, values: &[f64]) -> PyResult<()> {
    // A fold without early exit, which the compiler vectorises; the position only on failure.
    if values.iter().fold(true, |finite, x| finite & x.is_finite()) {
        return Ok(());
    }
    match values.iter().position(|x| !x.is_finite()) {
        Some(i) => Err(input_error(format!(
            "field \"{field}\": entry {i} is not a finite number"
        ))),
        None => Ok(()),
    }
}

/// A 2-D array as its rows.
fn rows(array: &PyReadonlyArray2<f64>) -> Vec<Vec<f64>> {
    array
        .as_array()
        .rows()
        .into_iter()
        .map(|r| r.to_vec())
        .collect()
}

/// Bernstein control points (rows) of the Hermite interpolant on an interval of width
/// `width`: `start[j]` and `end[j]` are the j-th derivative rows at both ends (one column per
/// coordinate, or per coordinate of every problem of a batch). The rows are read in place and
/// the map runs on all columns at once ([`solve_lanes`]) without the GIL; the result is moved
/// into numpy without a copy.
#[pyfunction]
fn hermite_f64<'py>(
    py: Python<'py>,
    start: PyReadonlyArray2<'py, f64>,
    end: PyReadonlyArray2<'py, f64>,
    width: f64,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let ((rows, lanes), (end_rows, end_lanes)) = (start.as_array().dim(), end.as_array().dim());
    let (start, end) = (row_major(&start), row_major(&end));
    check_finite("start", &start)?;
    check_finite("end", &end)?;
    if !(width.is_finite() && width > 0.0) {
        return Err(input_error(format!(
            "field \"interval\": the width t1 − t0 = {width} must be a positive finite number"
        )));
    }
    if end_rows != rows {
        return Err(input_error(format!(
            "field \"end\": {end_rows} derivatives where \"start\" has {rows}"
        )));
    }
    if end_lanes != lanes {
        return Err(input_error(format!(
            "field \"end\": points of dimension {end_lanes} where \"start\" has {lanes}"
        )));
    }
    let zero = 0.0;
    let points = py
        .detach(|| solve_lanes(&start, &end, lanes, (&zero, &width)))
        .map_err(|e| input_error(format!("field \"start\": {e}")))?;
    let count = points.len() / lanes.max(1);
    PyArray1::from_vec(py, points).reshape([count, lanes])
}

/// The numbers of a 2-D array row by row: borrowed when it is C-contiguous, else copied.
fn row_major<'a>(array: &'a PyReadonlyArray2<'_, f64>) -> Cow<'a, [f64]> {
    match array.as_slice() {
        Ok(slice) => Cow::Borrowed(slice),
        Err(_) => Cow::Owned(array.as_array().iter().copied().collect()),
    }
}

/// Values, first and second derivatives (one column per coordinate of `z`) of the natural
/// cubic spline through (t_i, z_i) at the points `at`, all inside [t_0, t_N]. As `run
/// natural-spline` does on the exact doubles: the piece is found by exact comparison, the
/// spacings and the distances to the piece's ends are rounded once (IEEE subtraction).
#[pyfunction]
#[allow(clippy::type_complexity)]
fn natural_spline_f64<'py>(
    py: Python<'py>,
    t: PyReadonlyArray1<'py, f64>,
    z: PyReadonlyArray2<'py, f64>,
    at: PyReadonlyArray1<'py, f64>,
) -> PyResult<(
    Bound<'py, PyArray2<f64>>,
    Bound<'py, PyArray2<f64>>,
    Bound<'py, PyArray2<f64>>,
)> {
    let t = t.as_array().to_vec();
    let at = at.as_array().to_vec();
    let z = rows(&z);
    check_finite("t", &t)?;
    check_finite("z", &z.concat())?;
    check_finite("at", &at)?;
    if t.len() < 2 {
        return Err(input_error(
            "field \"t\": a spline needs at least two knots",
        ));
    }
    if z.len() != t.len() {
        return Err(input_error(format!(
            "field \"z\": {} values for {} knots",
            z.len(),
            t.len()
        )));
    }
    if let Some(i) = (1..t.len()).find(|&i| t[i] <= t[i - 1]) {
        return Err(input_error(format!(
            "field \"t[{i}]\": knots must increase ({} after {})",
            t[i],
            t[i - 1]
        )));
    }
    let (first, last) = (t[0], t[t.len() - 1]);
    if let Some(k) = at.iter().position(|x| *x < first || *x > last) {
        return Err(input_error(format!(
            "field \"at[{k}]\": {} lies outside the knots [{first}, {last}], where the spline is not defined",
            at[k]
        )));
    }
    let dims = z.first().map_or(0, Vec::len);
    let columns = py.detach(|| {
        let spacings: Vec<f64> = t.windows(2).map(|w| w[1] - w[0]).collect();
        let splines = (0..dims)
            .map(|c| {
                let values = z.iter().map(|row| row[c]).collect();
                NaturalCubicSpline::with_spacings(t.clone(), spacings.clone(), values)
            })
            .collect::<Result<Vec<_>, _>>()?;
        let mut out = [vec![], vec![], vec![]];
        for q in &at {
            let piece = piece_index(&t, q);
            let (u, v) = (t[piece] - q, q - t[piece - 1]);
            let jets: Vec<[f64; 3]> = splines
                .iter()
                .map(|s| s.eval_offsets(&u, &v, piece))
                .collect();
            for (j, column) in out.iter_mut().enumerate() {
                column.push(jets.iter().map(|jet| jet[j]).collect::<Vec<f64>>());
            }
        }
        Ok::<_, trajverify::algo::param::natural::SplineError>(out)
    });
    let [values, first, second] = columns.map_err(|e| input_error(format!("field \"t\": {e}")))?;
    let array = |rows: Vec<Vec<f64>>| {
        if rows.is_empty() {
            return Ok(PyArray2::zeros(py, [0, dims], false));
        }
        PyArray2::from_vec2(py, &rows).map_err(|e| PyRuntimeError::new_err(e.to_string()))
    };
    Ok((array(values)?, array(first)?, array(second)?))
}

/// The JSON line `trajverify run <algorithm> [--scalar <scalar>]` prints for the JSON document
/// `input` (without the newline). The GIL is released while it runs.
#[pyfunction]
#[pyo3(signature = (algorithm, input, scalar=None))]
fn run(py: Python<'_>, algorithm: &str, input: &str, scalar: Option<&str>) -> PyResult<String> {
    use clap::ValueEnum;
    let algorithm = Algorithm::from_str(algorithm, false).map_err(|_| {
        let names: Vec<String> = Algorithm::value_variants()
            .iter()
            .filter_map(|a| a.to_possible_value().map(|v| v.get_name().to_string()))
            .collect();
        input_error(format!(
            "algorithm: unknown algorithm \"{algorithm}\" (expected one of {})",
            names.join(", ")
        ))
    })?;
    let scalar = scalar
        .map(|s| s.parse::<ScalarKind>())
        .transpose()
        .map_err(|e| input_error(format!("scalar: {e}")))?;
    let input = input.to_string();
    match interruptible(py, 0, move || run_text(algorithm, scalar, &input))? {
        Ok(mut line) => {
            line.truncate(line.trim_end().len());
            Ok(line)
        }
        Err(failure) => Err(failure_error(failure)),
    }
}

/// How many jobs of [`interruptible`] are running, interrupted or not ([`running_jobs`]).
static RUNNING_JOBS: AtomicUsize = AtomicUsize::new(0);

/// One running worker, counted in `count` (a static: [`RUNNING_JOBS`], the Python curves'
/// workers) from [`Counted::start`] until it is dropped.
pub(crate) struct Counted(&'static AtomicUsize);

impl Counted {
    pub(crate) fn start(count: &'static AtomicUsize) -> Counted {
        count.fetch_add(1, Ordering::SeqCst);
        Counted(count)
    }
}

impl Drop for Counted {
    fn drop(&mut self) {
        self.0.fetch_sub(1, Ordering::SeqCst);
    }
}

/// The number of jobs still running on worker threads: 0 shortly after Ctrl-C stopped one
/// (for the tests, and for a caller who wants to see the work end).
#[pyfunction]
fn running_jobs() -> usize {
    RUNNING_JOBS.load(Ordering::SeqCst)
}

/// Run `job` on worker threads (a rayon pool of `threads`, 0 for one per core) while this
/// thread, without the GIL, waits for it and checks every 50 ms for a signal. Ctrl-C raises
/// `KeyboardInterrupt` at once and raises the job's [`StopFlag`]: the library's long loops
/// stop at their next checkpoint ([`trajverify::cancel`]), so the work ends too, not only
/// the wait. A job that panics is a `RuntimeError`, not a crash of the interpreter.
pub(crate) fn interruptible<R: Send + 'static>(
    py: Python<'_>,
    threads: usize,
    job: impl FnOnce() -> R + Send + 'static,
) -> PyResult<R> {
    use std::sync::mpsc::{channel, RecvTimeoutError};
    use std::time::Duration;
    let (send, receive) = channel();
    let flag = StopFlag::new();
    let stop = flag.clone();
    let running = Counted::start(&RUNNING_JOBS);
    std::thread::Builder::new()
        .spawn(move || {
            let _running = running;
            let _ = send.send(run_stoppable(&flag, threads, job));
        })
        .map_err(|e| PyRuntimeError::new_err(format!("could not start a worker thread: {e}")))?;
    let mut receive = receive;
    loop {
        // The receiver is not `Sync`: it moves into the detached wait and back out.
        let (waited, back) = py.detach(move || {
            let waited = receive.recv_timeout(Duration::from_millis(50));
            (waited, receive)
        });
        receive = back;
        match waited {
            Ok(Ok(answer)) => return Ok(answer),
            Ok(Err(stopped)) => return Err(PyRuntimeError::new_err(stopped.to_string())),
            Err(RecvTimeoutError::Timeout) => {
                if let Err(interrupt) = py.check_signals() {
                    stop.stop();
                    return Err(interrupt);
                }
            }
            Err(RecvTimeoutError::Disconnected) => {
                return Err(PyRuntimeError::new_err(
                    "internal: the computation stopped without an answer (a panic in the library)",
                ))
            }
        }
    }
}

fn failure_error(failure: Failure) -> PyErr {
    match failure {
        Failure::Usage(m) => input_error(m),
        Failure::Run(m) | Failure::Internal(m) => PyRuntimeError::new_err(m),
    }
}

/// Run the command line on `args` (without the program name), e.g. `["verify", "--out",
/// dir]` or `["report", "convergence", …]`; returns what it prints. The GIL is released while
/// it runs; a usage error is a `TrajverifyError` with clap's first line.
#[pyfunction]
fn command(py: Python<'_>, args: Vec<String>) -> PyResult<String> {
    use clap::Parser;
    let argv = std::iter::once("trajverify".to_string()).chain(args);
    let cli = trajverify::cli::Cli::try_parse_from(argv).map_err(|e| {
        let text = e.render().to_string();
        input_error(text.lines().next().unwrap_or("").to_string())
    })?;
    interruptible(py, 0, move || trajverify::cli::execute(cli))?.map_err(failure_error)
}

#[pymodule]
fn _trajverify(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("TrajverifyError", m.py().get_type::<TrajverifyError>())?;
    m.add_function(wrap_pyfunction!(hermite_f64, m)?)?;
    m.add_function(wrap_pyfunction!(natural_spline_f64, m)?)?;
    m.add_function(wrap_pyfunction!(run, m)?)?;
    m.add_function(wrap_pyfunction!(command, m)?)?;
    m.add_function(wrap_pyfunction!(ph::ph_fit, m)?)?;
    m.add_class::<ph::NativePhSpline>()?;
    m.add_function(wrap_pyfunction!(ph::ph_fit_ball, m)?)?;
    m.add_function(wrap_pyfunction!(ph::python_workers, m)?)?;
    m.add_function(wrap_pyfunction!(running_jobs, m)?)?;
    m.add_class::<ph::NativeBallPhSpline>()?;
    Ok(())
}
