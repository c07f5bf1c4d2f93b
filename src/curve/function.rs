//! A curve written in Rust as one generic function of t, with its derivatives computed
//! automatically: the function is evaluated on the library's Taylor scalar
//! ([`Taylor`], truncated power series), so γ(t), γ′(t), …, γ⁽ᵐ⁾(t) come out exact to the
//! working precision (no finite differences). Because the function is generic over [`Real`],
//! the same code runs in f64, MPFR and balls (proven errors: ball arithmetic over a box of t
//! encloses every value, so the enclosure's Taylor models hold) — and the curve can be fitted
//! ([`crate::algo::ph::piecewise::fit`]), measured ([`crate::curve::enclosure::proven_error`])
//! and studied ([`crate::algo::convergence::study`]).
//!
//! A [`CurveFn`] is assumed analytic where it is evaluated (a composition of the [`Real`]
//! operations: arithmetic, sqrt, exp, ln, sin, cos, …); a study proves it regular on its
//! interval before trusting the order it measures. A function with a kink (abs, a branch on
//! t) is not analytic there, and its expected order would be wrong.

use super::taylor::Taylor;
use super::Curve;
use crate::scalar::Real;

/// A space curve t ↦ γ(t) ∈ ℝ³ written once for every number type.
///
/// # Examples
/// The helix (cos t, sin t, t/5), fitted by a PH spline in f64 and its error proven in balls:
/// ```
/// use trajverify::algo::ph::piecewise::{fit, FitOptions};
/// use trajverify::curve::enclosure::{proven_error, ProofOptions};
/// use trajverify::curve::function::{CurveFn, FnCurve};
/// use trajverify::scalar::{ball::Ball, Field, Real};
///
/// struct Helix;
/// impl CurveFn for Helix {
///     fn at<R: Real>(&self, t: &R) -> [R; 3] {
///         [t.cos(), t.sin(), t.clone() / &R::from_i64(5, &t.ctx())]
///     }
/// }
/// let helix = FnCurve(Helix);
/// let options = FitOptions { segments: 8, ..FitOptions::default() };
/// let spline = fit(&helix, (&0.0, &6.0), &options).unwrap();
/// assert_eq!(spline.segments().len(), 8);
///
/// let (a, b) = (Ball::from_i64(0, &128), Ball::from_i64(6, &128));
/// let proven = fit(&helix, (&a, &b), &FitOptions { segments: 8, ..FitOptions::default() }).unwrap();
/// let e = proven_error(&helix, &proven, &ProofOptions { target: 1e-3, max_boxes: 100_000, ..ProofOptions::default() }).unwrap();
/// assert!(e.lower <= e.upper && e.upper < 1e-3);
/// ```
pub trait CurveFn: Sync {
    /// γ(t), for t of any [`Real`] type (f64, MPFR, balls, and the Taylor series the
    /// derivatives come from).
    fn at<R: Real>(&self, t: &R) -> [R; 3];
}

/// A [`CurveFn`] as a [`Curve`] in every number type (and, in `algo::convergence`, as a
/// study's curve).
pub struct FnCurve<F>(pub F);

impl<T: Real, F: CurveFn> Curve<T> for FnCurve<F> {
    fn jet(&self, t: &T, order: usize) -> Vec<[T; 3]> {
        let series = self.0.at(&Taylor::variable(t.clone(), order));
        let derivatives = series.map(|c| c.derivatives());
        let zero = T::zero_in(&t.ctx());
        (0..=order)
            .map(|k| {
                std::array::from_fn(|c| {
                    derivatives[c]
                        .get(k)
                        .cloned()
                        .unwrap_or_else(|| zero.clone())
                })
            })
            .collect()
    }
}
