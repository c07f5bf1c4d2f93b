//! Any library curve as the input of a conversion: [`AsCurve`] lets every [`ParamCurve`] of
//! dimension 1, 2 or 3 (a Bézier curve, a natural spline, a GERBS path, a PH spline, a B-spline
//! fit) be what [`Curve`] stands for — the curve a PH spline is fitted to
//! ([`crate::algo::ph::piecewise::fit`]), measured against ([`crate::curve::approx`],
//! [`crate::curve::enclosure::proven_error`]) or studied (built in each number type,
//! `algo::convergence::CurveFamily`, through [`OwnedCurve`]) — so one library curve can be
//! converted and compared with another without hand-written jets.
//!
//! A curve of fewer than three coordinates is embedded in ℝ³ with zeros (a plane curve lies in
//! z = 0, which changes neither its distances nor its PH conversion). The jet is the curve's own
//! [`ParamCurve::derivatives`]; where it cannot give them (a parameter outside the domain) the
//! jet is NaN, which every conversion refuses with its "not finite" error rather than using.
//! Breakpoints are passed on, so conversions and sampled errors split there. A proven
//! enclosure needs a bound of the seam where two polynomial pieces meet, which only the curve
//! itself can give: through the adapter every piece that touches a breakpoint gets an infinite
//! seam bound, so the enclosure of a piecewise curve is unbounded (never wrong); a curve of one
//! piece (a Bézier curve) is proven as usual.

use super::parametric::ParamCurve;
use super::Curve;
use crate::scalar::Real;

/// A [`ParamCurve`] of dimension D ≤ 3 seen as a [`Curve`] (see the module doc).
///
/// # Examples
/// A PH spline fitted to a plane Bézier curve (a quarter circle's cubic approximation):
/// ```
/// use trajverify::algo::ph::piecewise::{fit, FitOptions};
/// use trajverify::curve::adapter::AsCurve;
/// use trajverify::curve::bezier::BezierCurve;
/// use trajverify::curve::parametric::ParamCurve;
///
/// let k = 0.5522847498;
/// let arc = BezierCurve::new(vec![[1.0, 0.0], [1.0, k], [k, 1.0], [0.0, 1.0]], (0.0, 1.0)).unwrap();
/// let options = FitOptions { segments: 4, ..FitOptions::default() };
/// let spline = fit(&AsCurve::new(&arc), (&0.0, &1.0), &options).unwrap();
/// let p = spline.point(&0.5).unwrap();
/// let q = arc.point(&0.5).unwrap();
/// assert!((p[0] - q[0]).abs() < 1e-9 && (p[1] - q[1]).abs() < 1e-9 && p[2].abs() < 1e-12);
/// ```
pub struct AsCurve<'a, C: ?Sized, const D: usize> {
    curve: &'a C,
}

impl<'a, C: ?Sized, const D: usize> AsCurve<'a, C, D> {
    /// The adapter over `curve`.
    pub fn new(curve: &'a C) -> Self {
        AsCurve { curve }
    }
}

impl<T: Real, C: ParamCurve<T, D> + Sync + ?Sized, const D: usize> Curve<T> for AsCurve<'_, C, D> {
    fn jet(&self, t: &T, order: usize) -> Vec<[T; 3]> {
        embedded_jet(self.curve, t, order)
    }

    fn seam_bound(&self, lo: f64, _centre: (f64, f64), hi: f64) -> f64 {
        seam_bound_of(self.curve, lo, hi)
    }

    fn breakpoints(&self, lo: f64, hi: f64) -> Vec<f64> {
        breakpoints_of(self.curve, lo, hi)
    }
}

/// [`AsCurve`] that owns its curve (for a curve built on demand, e.g. in each number type of
/// a convergence study).
pub struct OwnedCurve<C, const D: usize>(pub C);

impl<T: Real, C: ParamCurve<T, D> + Sync, const D: usize> Curve<T> for OwnedCurve<C, D> {
    fn jet(&self, t: &T, order: usize) -> Vec<[T; 3]> {
        embedded_jet(&self.0, t, order)
    }

    fn seam_bound(&self, lo: f64, _centre: (f64, f64), hi: f64) -> f64 {
        seam_bound_of(&self.0, lo, hi)
    }

    fn breakpoints(&self, lo: f64, hi: f64) -> Vec<f64> {
        breakpoints_of(&self.0, lo, hi)
    }
}

/// The curve's jet embedded in ℝ³; NaN where the curve gives none.
fn embedded_jet<T: Real, C: ParamCurve<T, D> + ?Sized, const D: usize>(
    curve: &C,
    t: &T,
    order: usize,
) -> Vec<[T; 3]> {
    let ctx = t.ctx();
    let embed = |p: &[T; D]| -> [T; 3] {
        std::array::from_fn(|c| {
            if c < D {
                p[c].clone()
            } else {
                T::zero_in(&ctx)
            }
        })
    };
    match curve.derivatives(t, order) {
        Ok(jet) if D <= 3 => jet.iter().map(embed).collect(),
        // Outside the domain, or more than three coordinates: not a value to convert.
        _ => vec![std::array::from_fn(|_| T::from_f64(f64::NAN, &ctx)); order + 1],
    }
}

/// Infinite on a piece that touches a breakpoint, zero elsewhere.
fn seam_bound_of<T: Real, C: ParamCurve<T, D> + ?Sized, const D: usize>(
    curve: &C,
    lo: f64,
    hi: f64,
) -> f64 {
    // A breakpoint inside the piece or on its ends (its f64 rounding may sit an ulp from the
    // true one): the curve's other polynomial piece may reach into [lo, hi], and no generic
    // bound of that seam is known here, so the bound is infinite.
    let slack = 1e-9 * (hi - lo).abs();
    let touches = curve
        .breakpoints()
        .iter()
        .map(|b| b.to_f64())
        .any(|b| lo - slack <= b && b <= hi + slack);
    if touches {
        f64::INFINITY
    } else {
        0.0
    }
}

/// The curve's breakpoints inside (lo, hi).
fn breakpoints_of<T: Real, C: ParamCurve<T, D> + ?Sized, const D: usize>(
    curve: &C,
    lo: f64,
    hi: f64,
) -> Vec<f64> {
    curve
        .breakpoints()
        .iter()
        .map(|b| b.to_f64())
        .filter(|b| lo < *b && *b < hi)
        .collect()
}
