//! Curves given by the user: parametric expressions ([`expr`]) and sampled data fitted by a
//! smooth spline ([`spline`]), both able to report their derivatives at a point in the working
//! precision ([`Curve::jet`]), which is what Hermite interpolation needs; and the distance
//! between a curve and a piecewise Bernstein approximation of it, as a certified maximum
//! ([`approx`]) or a proven enclosure ([`enclosure`]).

pub mod adapter;
pub mod approx;
pub mod bezier;
pub mod distance;
pub mod enclosure;
pub mod expr;
pub mod function;
pub mod integral;
pub mod interval;
pub mod parametric;
pub mod query;
pub mod regularity;
pub mod spline;
pub mod taylor;

use crate::scalar::Real;
use expr::{parse_vector, Compiled, Expr, ExprError};
use taylor::Taylor;

/// A curve γ: ℝ → ℝ³ that can report its derivatives.
pub trait Curve<T: Real>: Sync {
    /// γ(t), γ′(t), …, γ⁽ᵒʳᵈᵉʳ⁾(t): entry k is the k-th derivative.
    fn jet(&self, t: &T, order: usize) -> Vec<[T; 3]>;

    /// An upper bound of ‖γ(x) − P(x)‖ for x in [lo, hi], where P is the analytic piece that
    /// [`Curve::jet`] describes at the centre, a point of [lo, hi] known to lie in
    /// `centre` = (lower, upper) (P continued analytically past its piece's ends). Zero, the
    /// default, for a curve analytic on [lo, hi]; for a spline, the terms its knots inside add
    /// ([`spline`], "Seams"). Proven enclosures need it: their Taylor models are built from
    /// one piece and would not hold across a knot.
    fn seam_bound(&self, _lo: f64, _centre: (f64, f64), _hi: f64) -> f64 {
        0.0
    }

    /// The points of [lo, hi] where the curve is not analytic (a spline's knots), so that a
    /// proven enclosure can split its pieces there; none, the default, for an analytic curve.
    fn breakpoints(&self, _lo: f64, _hi: f64) -> Vec<f64> {
        Vec::new()
    }
}

impl<T: Real, C: Curve<T> + ?Sized> Curve<T> for &C {
    fn jet(&self, t: &T, order: usize) -> Vec<[T; 3]> {
        (**self).jet(t, order)
    }
    fn seam_bound(&self, lo: f64, centre: (f64, f64), hi: f64) -> f64 {
        (**self).seam_bound(lo, centre, hi)
    }
    fn breakpoints(&self, lo: f64, hi: f64) -> Vec<f64> {
        (**self).breakpoints(lo, hi)
    }
}

impl<T: Real, C: Curve<T> + ?Sized> Curve<T> for Box<C> {
    fn jet(&self, t: &T, order: usize) -> Vec<[T; 3]> {
        (**self).jet(t, order)
    }
    fn seam_bound(&self, lo: f64, centre: (f64, f64), hi: f64) -> f64 {
        (**self).seam_bound(lo, centre, hi)
    }
    fn breakpoints(&self, lo: f64, hi: f64) -> Vec<f64> {
        (**self).breakpoints(lo, hi)
    }
}

/// A curve written as `[x(t), y(t), z(t)]` in the expression language of [`expr`].
#[derive(Clone, Debug)]
pub struct ExprCurve {
    /// x(t), y(t), z(t).
    pub components: [Expr; 3],
}

impl ExprCurve {
    /// Parse `[x, y, z]`; exactly three components.
    ///
    /// # Errors
    /// [`ExprError`] for a syntax or name error ([`parse_vector`]), or at position 1 when the
    /// vector does not have exactly three components.
    pub fn parse(text: &str) -> Result<Self, ExprError> {
        let items = parse_vector(text)?;
        let n = items.len();
        let components: [Expr; 3] = items.try_into().map_err(|_| ExprError {
            position: 1,
            message: format!("a space curve has 3 components, this one has {n}"),
        })?;
        Ok(ExprCurve { components })
    }
}

impl ExprCurve {
    /// The curve with its numbers rounded into `ctx`, ready for fast evaluation.
    pub fn compile<T: Real>(&self, ctx: &T::Ctx) -> CompiledCurve<T> {
        CompiledCurve {
            components: [
                self.components[0].compile(ctx),
                self.components[1].compile(ctx),
                self.components[2].compile(ctx),
            ],
        }
    }
}

/// An [`ExprCurve`] compiled for one number type and precision.
#[derive(Clone, Debug)]
pub struct CompiledCurve<T> {
    /// x(t), y(t), z(t), each evaluated in Taylor arithmetic.
    pub components: [Compiled<Taylor<T>>; 3],
}

impl<T: Real> Curve<T> for CompiledCurve<T> {
    fn jet(&self, t: &T, order: usize) -> Vec<[T; 3]> {
        if order == 0 {
            // The point alone: the series' constant terms without the series, times the 0! = 1
            // that `Taylor::derivatives` multiplies by (bit for bit the general path's value).
            let one = T::one_in(&t.ctx());
            let point = std::array::from_fn(|i| self.components[i].eval_value(t) * &one);
            return vec![point];
        }
        let var = Taylor::variable(t.clone(), order);
        let d: Vec<Vec<T>> = self
            .components
            .iter()
            .map(|e| e.eval(&var).with_order(order).derivatives())
            .collect();
        (0..=order)
            .map(|k| [d[0][k].clone(), d[1][k].clone(), d[2][k].clone()])
            .collect()
    }
}
