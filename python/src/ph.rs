//! PH splines in f64 (paper 001, Algorithm 2): a curve given as an expression or as a Python
//! function of its jet, converted by the library's [`fit`] and evaluated on numpy arrays.
//!
//! A Python curve reaches the library as a [`Curve`] whose `jet(t, order)` calls back into
//! Python (the package differentiates the user's callable by Taylor arithmetic, so the
//! derivatives are exact up to rounding, never finite differences). The conversion runs on a
//! worker thread without the GIL (Ctrl-C interrupts the wait and stops the conversion at its
//! next checkpoint, [`interruptible`]; the callbacks until then answer NaN, so no more of the
//! user's code runs); each callback takes the GIL for its call. An exception raised by the callable
//! is kept and raised once the conversion returns (the library sees a non-finite jet and stops
//! at that segment). Every method that evaluates takes a flat array of parameters and returns
//! a flat array; the Python class `trajverify.PhSpline` shapes them.

use numpy::{PyArray1, PyReadonlyArray1};
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};
use trajverify::algo::ph::piecewise::{
    conversion_error, fit, FitOptions, PiecewisePh, DEFAULT_SAMPLES,
};
use trajverify::curve::parametric::{ParamCurve, ParamCurveArclen, ParamCurveFrame};
use trajverify::curve::{Curve, ExprCurve};
use trajverify::scalar::ball::Ball;
use trajverify::scalar::parse::parse_exact;
use trajverify::{Field, Real};

use crate::{input_error, interruptible, Counted};

/// A curve whose jets a Python function gives: `jet(t, order)` returns (order + 1)·3 floats,
/// row k the k-th derivative.
struct PythonCurve {
    jet: Py<PyAny>,
    /// The first exception the function raised, raised again after the conversion.
    failure: Mutex<Option<PyErr>>,
    /// Set when the caller was interrupted: the remaining jets are NaN without a call, so
    /// the abandoned conversion fails at once instead of calling Python on in the background.
    cancelled: AtomicBool,
}

impl PythonCurve {
    fn call(&self, t: f64, order: usize) -> PyResult<Vec<[f64; 3]>> {
        if self.cancelled.load(Ordering::Relaxed) {
            return Ok(vec![[f64::NAN; 3]; order + 1]);
        }
        Python::attach(|py| {
            let flat: Vec<f64> = self.jet.call1(py, (t, order))?.extract(py)?;
            if flat.len() != 3 * (order + 1) {
                return Err(input_error(format!(
                    "curve: the jet at t = {t} has {} numbers, expected {} (order + 1 rows of x, y, z)",
                    flat.len(),
                    3 * (order + 1)
                )));
            }
            Ok(flat.chunks(3).map(|c| [c[0], c[1], c[2]]).collect())
        })
    }
}

impl Curve<f64> for PythonCurve {
    fn jet(&self, t: &f64, order: usize) -> Vec<[f64; 3]> {
        match self.call(*t, order) {
            Ok(jet) => jet,
            Err(e) => {
                if let Ok(mut slot) = self.failure.lock() {
                    slot.get_or_insert(e);
                }
                vec![[f64::NAN; 3]; order + 1]
            }
        }
    }
}

/// How many conversions of a Python curve are running on worker threads, interrupted or
/// not. The package waits for them at exit ([`python_workers`]): a thread that asks for the
/// GIL while Python 3.11 finalises is ended by `pthread_exit`, which aborts the process when
/// it unwinds through Rust frames.
static PYTHON_WORKERS: AtomicUsize = AtomicUsize::new(0);

/// The number of conversions of Python curves still running (see [`PYTHON_WORKERS`]).
#[pyfunction]
pub fn python_workers() -> usize {
    PYTHON_WORKERS.load(Ordering::SeqCst)
}

/// A piecewise PH spline in f64 and the conversion error the fit measured.
#[pyclass(frozen, module = "trajverify._trajverify")]
pub struct NativePhSpline {
    spline: PiecewisePh<f64>,
    sampled_error: f64,
}

/// Convert `curve` (an expression string or a jet function) on `interval` = (a, b); the
/// options are those of the library's [`FitOptions`].
#[pyfunction]
#[pyo3(signature = (curve, interval, segments, tolerance, derivatives, roll))]
pub fn ph_fit(
    py: Python<'_>,
    curve: &Bound<'_, PyAny>,
    interval: (f64, f64),
    segments: usize,
    tolerance: Option<f64>,
    derivatives: usize,
    roll: bool,
) -> PyResult<NativePhSpline> {
    let (a, b) = interval;
    if !(a.is_finite() && b.is_finite() && a < b) {
        return Err(input_error(format!(
            "interval: [{a}, {b}] is not an interval a < b of finite numbers"
        )));
    }
    let options = FitOptions {
        segments,
        tolerance,
        derivatives,
        free: None,
        roll,
    };
    if let Ok(text) = curve.extract::<String>() {
        let parsed = ExprCurve::parse(&text).map_err(|e| input_error(format!("curve: {e}")))?;
        return interruptible(py, 0, move || {
            let compiled = parsed.compile::<f64>(&());
            convert(&compiled, (a, b), &options)
        })?;
    }
    let python = Arc::new(PythonCurve {
        jet: curve.clone().unbind(),
        failure: Mutex::new(None),
        cancelled: AtomicBool::new(false),
    });
    let worker = Arc::clone(&python);
    let running = Counted::start(&PYTHON_WORKERS);
    // On one thread holding the GIL: every callback needs it, so the library's parallel loops
    // would only hand it back and forth, and attaching a thread to Python for each call costs
    // more than the call (measured on 4096 segments: 6.6 s with half of it in the kernel).
    // Python's eval loop still yields the GIL to the waiting caller between callbacks.
    let result = interruptible(py, 1, move || {
        let converted = Python::attach(|_| convert(&*worker, (a, b), &options));
        // The curve (a Python object) goes before the count says this worker is done.
        drop(worker);
        drop(running);
        converted
    })
    .inspect_err(|_| python.cancelled.store(true, Ordering::Relaxed))?;
    let failure = python.failure.lock().ok().and_then(|mut slot| slot.take());
    match failure {
        Some(e) => Err(e),
        None => result,
    }
}

fn convert<C: Curve<f64>>(
    curve: &C,
    (a, b): (f64, f64),
    options: &FitOptions<f64>,
) -> PyResult<NativePhSpline> {
    let spline = fit(curve, (&a, &b), options).map_err(fit_error)?;
    let sampled_error = conversion_error(curve, &spline, DEFAULT_SAMPLES).max;
    Ok(NativePhSpline {
        spline,
        sampled_error,
    })
}

/// A refusal of [`fit`]: messages about an option already name it; the others are about the
/// curve.
fn fit_error(e: impl std::fmt::Display) -> PyErr {
    let text = e.to_string();
    let named = ["segments:", "derivatives:", "tolerance:"];
    if named.iter().any(|field| text.starts_with(field)) {
        input_error(text)
    } else {
        input_error(format!("curve: {text}"))
    }
}

fn curve_error(e: impl std::fmt::Display) -> PyErr {
    input_error(e.to_string())
}

/// The numbers both classes return, written once over the number type: the jet of order
/// `order` at t (3·(order + 1) numbers), a frame row (point 3, axes 9, ω 3, speed 1), the
/// control points and the preimages' quaternions (w, x, y, z) of every segment, flat.
fn jet_numbers<T: Real>(spline: &PiecewisePh<T>, t: &T, order: usize) -> PyResult<Vec<T>> {
    let jet = spline.derivatives(t, order).map_err(curve_error)?;
    Ok(jet.into_iter().flatten().collect())
}

fn frame_numbers<T: Real>(spline: &PiecewisePh<T>, t: &T) -> PyResult<Vec<T>> {
    let f = spline.frame(t).map_err(curve_error)?;
    let mut row: Vec<T> = f.point.to_vec();
    row.extend(f.axes.into_iter().flatten());
    row.extend(f.omega);
    row.push(f.speed);
    Ok(row)
}

fn control_point_numbers<T: Real>(spline: &PiecewisePh<T>) -> Vec<T> {
    spline
        .segments()
        .iter()
        .flat_map(|s| s.control_points().into_iter().flatten())
        .collect()
}

fn preimage_numbers<T: Real>(spline: &PiecewisePh<T>) -> Vec<T> {
    spline
        .segments()
        .iter()
        .flat_map(|s| {
            s.preimage()
                .iter()
                .flat_map(|q| [q.w.clone(), q.x.clone(), q.y.clone(), q.z.clone()])
                .collect::<Vec<_>>()
        })
        .collect()
}

/// Apply `f` to every parameter, flattening the rows it returns.
fn each<'py>(
    py: Python<'py>,
    ts: &PyReadonlyArray1<'py, f64>,
    f: impl Fn(f64) -> PyResult<Vec<f64>>,
) -> PyResult<Bound<'py, PyArray1<f64>>> {
    let mut out = Vec::new();
    for t in ts.as_array() {
        out.extend(f(*t)?);
    }
    Ok(PyArray1::from_vec(py, out))
}

#[pymethods]
impl NativePhSpline {
    /// (a, b).
    fn interval(&self) -> (f64, f64) {
        self.spline.domain()
    }
    /// The number of segments N.
    fn segments(&self) -> usize {
        self.spline.segments().len()
    }
    /// The sampled conversion error E (Eq. 21) measured after the fit: an estimate.
    fn sampled_error(&self) -> f64 {
        self.sampled_error
    }
    /// The derivatives 0…order at each t, flat: len(t)·(order + 1)·3 numbers.
    fn derivatives<'py>(
        &self,
        py: Python<'py>,
        t: PyReadonlyArray1<'py, f64>,
        order: usize,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        each(py, &t, |t| jet_numbers(&self.spline, &t, order))
    }
    /// s(t) at each t.
    fn arc_length<'py>(
        &self,
        py: Python<'py>,
        t: PyReadonlyArray1<'py, f64>,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        each(py, &t, |t| {
            Ok(vec![self.spline.arc_length(&t).map_err(curve_error)?])
        })
    }
    /// The whole length s(b).
    fn length(&self) -> PyResult<f64> {
        self.spline.length().map_err(curve_error)
    }
    /// The parameter t with s(t) = s, for each s.
    fn parameter_at_length<'py>(
        &self,
        py: Python<'py>,
        s: PyReadonlyArray1<'py, f64>,
        tolerance: f64,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        each(py, &s, |s| {
            let t = self
                .spline
                .parameter_at_length(&s, &tolerance)
                .map_err(curve_error)?;
            Ok(vec![t])
        })
    }
    /// Point (3), axes (9, row k the k-th axis), ω (3) and speed (1) at each t: 16 numbers.
    fn frames<'py>(
        &self,
        py: Python<'py>,
        t: PyReadonlyArray1<'py, f64>,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        each(py, &t, |t| frame_numbers(&self.spline, &t))
    }
    /// The control points of every segment, flat: N·(degree + 1)·3 numbers.
    fn control_points<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_vec(py, control_point_numbers(&self.spline))
    }
    /// The preimage A(ξ) of every segment as quaternions (w, x, y, z), flat.
    fn preimages<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_vec(py, preimage_numbers(&self.spline))
    }
}

/// A piecewise PH spline converted in ball arithmetic at `bits` bits (an expression curve
/// only: a Python callable is differentiated in doubles). Every number comes out as the ball
/// `run` prints for it: a decimal value and a radius, every point of the ball within
/// [value − radius, value + radius] as printed; the value carries the digits the ball proves.
#[pyclass(frozen, module = "trajverify._trajverify")]
pub struct NativeBallPhSpline {
    spline: PiecewisePh<Ball>,
    bits: u32,
}

/// A printed ball: (value, radius).
type Printed = (String, String);

/// Convert the expression `curve` on [a, b] (exact decimal or fraction texts) with
/// `segments` segments in balls of `bits` bits.
#[pyfunction]
#[pyo3(signature = (curve, interval, segments, derivatives, roll, bits))]
pub fn ph_fit_ball(
    py: Python<'_>,
    curve: &str,
    interval: (String, String),
    segments: usize,
    derivatives: usize,
    roll: bool,
    bits: u32,
) -> PyResult<NativeBallPhSpline> {
    let parsed = ExprCurve::parse(curve).map_err(|e| input_error(format!("curve: {e}")))?;
    let end =
        |text: &str| parse_exact(text).map_err(|e| input_error(format!("interval: {text:?}: {e}")));
    let (a, b) = (end(&interval.0)?, end(&interval.1)?);
    if a >= b {
        return Err(input_error("interval: a < b is needed"));
    }
    interruptible(py, 0, move || {
        let (a, b) = (Ball::from_exact(&a, &bits), Ball::from_exact(&b, &bits));
        let options = FitOptions {
            segments,
            tolerance: None,
            derivatives,
            free: None,
            roll,
        };
        let spline = fit(&parsed.compile::<Ball>(&bits), (&a, &b), &options).map_err(fit_error)?;
        Ok(NativeBallPhSpline { spline, bits })
    })?
}

fn printed(x: &Ball) -> PyResult<Printed> {
    x.printed()
        .map(|p| (p.value, p.radius))
        .ok_or_else(|| PyRuntimeError::new_err("a number of the spline is not finite"))
}

impl NativeBallPhSpline {
    fn parameter(&self, text: &str, field: &str) -> PyResult<Ball> {
        let q = parse_exact(text).map_err(|e| input_error(format!("{field}: {text:?}: {e}")))?;
        Ok(Ball::from_exact(&q, &self.bits))
    }

    /// `f` of every parameter, its balls printed and flattened.
    fn each(
        &self,
        texts: &[String],
        field: &str,
        f: impl Fn(&Ball) -> PyResult<Vec<Ball>>,
    ) -> PyResult<Vec<Printed>> {
        let mut out = Vec::new();
        for text in texts {
            for x in f(&self.parameter(text, field)?)? {
                out.push(printed(&x)?);
            }
        }
        Ok(out)
    }
}

#[pymethods]
impl NativeBallPhSpline {
    /// The number N of segments.
    fn segments(&self) -> usize {
        self.spline.segments().len()
    }
    /// The derivatives 0…order at each t, flat: len(t)·(order + 1)·3 balls.
    fn derivatives(&self, t: Vec<String>, order: usize) -> PyResult<Vec<Printed>> {
        self.each(&t, "t", |t| jet_numbers(&self.spline, t, order))
    }
    /// s(t) at each t.
    fn arc_length(&self, t: Vec<String>) -> PyResult<Vec<Printed>> {
        self.each(&t, "t", |t| {
            Ok(vec![self.spline.arc_length(t).map_err(curve_error)?])
        })
    }
    /// The whole length.
    fn length(&self) -> PyResult<Printed> {
        printed(&self.spline.length().map_err(curve_error)?)
    }
    /// Point (3), axes (9), ω (3) and speed (1) at each t: 16 balls.
    fn frames(&self, t: Vec<String>) -> PyResult<Vec<Printed>> {
        self.each(&t, "t", |t| frame_numbers(&self.spline, t))
    }
    /// The control points of every segment, flat.
    fn control_points(&self) -> PyResult<Vec<Printed>> {
        control_point_numbers(&self.spline)
            .iter()
            .map(printed)
            .collect()
    }
    /// The preimages as quaternions (w, x, y, z), flat.
    fn preimages(&self) -> PyResult<Vec<Printed>> {
        preimage_numbers(&self.spline).iter().map(printed).collect()
    }
}
