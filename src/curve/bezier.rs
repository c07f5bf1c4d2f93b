//! A polynomial curve in Bernstein form with vector control points: γ(t) = Σₖ pₖ Bₖⁿ(ξ),
//! ξ = (t − t₀)/(t₁ − t₀) (paper 000, Eq. 4, one polynomial per coordinate). The k-th
//! derivative is n!/(n−k)!/(t₁ − t₀)ᵏ times de Casteljau's value of the k-th forward
//! differences of the control points ([`bernstein_jet`]); arc length by quadrature
//! ([`ParamCurveArclen`]'s default).
//!
//! [`crate::algo::hermite::hermite_curve`] builds one from derivatives at two times.

use super::parametric::{check_domain, CurveError, ParamCurve, ParamCurveArclen};
use crate::numeric::poly::bernstein::{bernstein_jet, BernsteinError};
use crate::scalar::{powi, Field, Real};

/// A Bézier curve of degree n = (number of control points) − 1 on [t₀, t₁].
#[derive(Clone, Debug, PartialEq)]
pub struct BezierCurve<T, const D: usize> {
    points: Vec<[T; D]>,
    t0: T,
    t1: T,
}

impl<T: Field, const D: usize> BezierCurve<T, D> {
    /// The curve with control points `points` on [t₀, t₁].
    ///
    /// # Errors
    /// [`BernsteinError::Empty`] without a control point; [`BernsteinError::Interval`] unless
    /// t₀ < t₁ with both finite.
    ///
    /// # Examples
    /// ```
    /// use trajverify::curve::bezier::BezierCurve;
    /// use trajverify::curve::parametric::ParamCurve;
    /// let line = BezierCurve::new(vec![[0.0, 0.0, 0.0], [2.0, 4.0, 6.0]], (1.0, 3.0)).unwrap();
    /// assert_eq!(line.point(&2.0).unwrap(), [1.0, 2.0, 3.0]);
    /// assert_eq!(line.derivative(&2.0, 1).unwrap(), [1.0, 2.0, 3.0]); // per unit of t
    /// assert!(BezierCurve::<f64, 3>::new(vec![], (0.0, 1.0)).is_err());
    /// ```
    pub fn new(points: Vec<[T; D]>, (t0, t1): (T, T)) -> Result<Self, BernsteinError> {
        if points.is_empty() {
            return Err(BernsteinError::Empty);
        }
        if !(t0.is_finite() && t1.is_finite() && t0 < t1) {
            return Err(BernsteinError::Interval);
        }
        if let Some(i) = points.iter().position(|p| !p.iter().all(Field::is_finite)) {
            return Err(BernsteinError::NotFinite(i));
        }
        Ok(BezierCurve { points, t0, t1 })
    }

    /// The control points p₀ … pₙ.
    pub fn control_points(&self) -> &[[T; D]] {
        &self.points
    }

    /// The degree n.
    pub fn degree(&self) -> usize {
        self.points.len() - 1
    }
}

impl<T: Field, const D: usize> ParamCurve<T, D> for BezierCurve<T, D> {
    fn domain(&self) -> (T, T) {
        (self.t0.clone(), self.t1.clone())
    }

    fn derivatives(&self, t: &T, order: usize) -> Result<Vec<[T; D]>, CurveError> {
        crate::curve::parametric::check_order(order)?;
        check_domain(t, (&self.t0, &self.t1))?;
        let duration = self.t1.clone() - &self.t0;
        let xi = (t.clone() - &self.t0) / &duration;
        let mut jet = bernstein_jet(&self.points, &xi, order);
        // d/dt = (1/(t₁ − t₀)) d/dξ.
        let inv = T::one_in(&t.ctx()) / &duration;
        for (k, v) in jet.iter_mut().enumerate().skip(1) {
            let scale = powi(&inv, k as u32);
            for x in v.iter_mut() {
                *x *= &scale;
            }
        }
        crate::curve::parametric::finite_jet(jet, t)
    }
}

impl<T: Real, const D: usize> ParamCurveArclen<T, D> for BezierCurve<T, D> {}
