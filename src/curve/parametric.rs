//! One interface for every curve the library builds, in the spirit of kurbo's `ParamCurve`,
//! `ParamCurveDeriv` and `ParamCurveArclen`, generic over the number type.
//!
//! A curve is a map γ: [t₀, t₁] → Tᴰ of its own parameter t, a point being `[T; D]` in every
//! module (D = 3 for Hermite curves, PH splines and Marin's spline of 3-D points; D = 2 for a
//! GERBS path; D = 1 for a spline fit of one coordinate).
//! - [`ParamCurve`]: the domain [`ParamCurve::domain`], the derivatives
//!   γ(t), γ′(t), …, γ⁽ᵏ⁾(t) ([`ParamCurve::derivatives`]), the point and one derivative, and
//!   the parameters where the curve's polynomial pieces meet ([`ParamCurve::breakpoints`]).
//!   Derivatives are per unit of t, whatever local parameter the curve uses inside.
//!   Evaluation outside the domain, or at NaN, is [`CurveError::OutsideDomain`]: never an
//!   extrapolated or made-up point.
//! - [`ParamCurveArclen`]: the arc length s(t) = ∫_{t₀}^{t} |γ′(u)| du. The default is
//!   tanh–sinh quadrature on each piece between break points, to the relative tolerance
//!   2^(8−p) of the working precision p ([`crate::numeric::quadrature`]); that is an estimate,
//!   not a certified value. PH curves override it with the exact integral of their polynomial
//!   speed (paper 001, Eq. 13a).
//! - [`ParamCurveFrame`]: an orthonormal frame along a space curve and its angular velocity ω
//!   per unit of t (so ω = dθ/dt, not per unit of arc length or of a segment's local
//!   parameter). The PH splines give their Euler–Rodrigues frame (paper 001, Eqs. 11–12).
//! - [`curvature`]: κ = √(|γ′|²|γ″|² − (γ′·γ″)²)/|γ′|³ for any dimension, from the first two
//!   derivatives (|γ′ × γ″|/|γ′|³ in 3-D).
//!
//! # Examples
//! A cubic Bézier curve in the plane, in f64 and exactly in rationals:
//! ```
//! use trajverify::curve::bezier::BezierCurve;
//! use trajverify::curve::parametric::{ParamCurve, ParamCurveArclen};
//! use trajverify::scalar::BigRational;
//!
//! let fast = BezierCurve::new(vec![[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]], (0.0, 2.0)).unwrap();
//! assert_eq!(fast.point(&1.0).unwrap(), [2.0, 1.5]);
//! assert!(fast.point(&2.5).is_err()); // outside [0, 2]
//! assert!(fast.arc_length(&2.0).unwrap() > 4.0); // longer than the chord
//!
//! let q = |n: i64| BigRational::from_integer(n.into());
//! let exact = BezierCurve::new(vec![[q(0)], [q(1)], [q(3)], [q(4)]], (q(0), q(1))).unwrap();
//! let jet = exact.derivatives(&BigRational::new(1.into(), 2.into()), 1).unwrap();
//! assert_eq!(jet[0][0], q(2));
//! assert_eq!(jet[1][0], BigRational::new(9.into(), 2.into())); // 3·(¼·1 + ½·2 + ¼·1)
//! ```

use super::Curve;
use crate::numeric::quadrature::{default_tolerance, TanhSinh};
use crate::scalar::{Field, Real};

/// Why a curve could not be evaluated.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum CurveError {
    /// The parameter lies outside the curve's domain, or is NaN.
    #[error("t: {t} is outside the curve's domain [{start}, {end}]")]
    OutsideDomain {
        /// The parameter asked for (as a double, for the message).
        t: f64,
        /// The start of the domain.
        start: f64,
        /// The end of the domain.
        end: f64,
    },
    /// A domain that is not an interval t₀ < t₁ of finite numbers.
    #[error("domain: [{start}, {end}] is not an interval t0 < t1 of finite numbers")]
    Domain {
        /// The start asked for.
        start: f64,
        /// The end asked for.
        end: f64,
    },
    /// The curve has no finite value at this parameter (an expression outside its real
    /// domain, such as sqrt(t − 10) at t < 10).
    #[error("t: the curve is not finite at t = {t}")]
    NotFinite {
        /// The parameter asked for.
        t: f64,
    },
    /// More derivatives asked for than [`MAX_DERIVATIVE_ORDER`].
    #[error("order: {order} derivatives asked for, at most {max}")]
    Order {
        /// The order asked for.
        order: usize,
        /// [`MAX_DERIVATIVE_ORDER`].
        max: usize,
    },
    /// An index outside its range (a knot or segment number).
    #[error("{field}: {index} is outside 0…{max}")]
    Index {
        /// The argument.
        field: &'static str,
        /// The index asked for.
        index: usize,
        /// The largest index.
        max: usize,
    },
    /// An arc length outside [0, length] (or NaN), or a bad tolerance, for the inverse arc
    /// length.
    #[error("{field}: {value} for a curve of length {length}: {message}")]
    ArcLength {
        /// `s` or `tolerance`.
        field: &'static str,
        /// The value asked for.
        value: f64,
        /// The curve's length.
        length: f64,
        /// What is wrong.
        message: String,
    },
    /// An argument that is not what the function is defined for (a point that is not
    /// finite).
    #[error("{field}: {message}")]
    Argument {
        /// The argument.
        field: &'static str,
        /// What is wrong.
        message: String,
    },
    /// The frame is not defined at this parameter (zero speed).
    #[error("t: the frame is not defined at t = {t} ({reason})")]
    Frame {
        /// The parameter asked for.
        t: f64,
        /// What makes it undefined.
        reason: String,
    },
}

/// A parametric curve t ↦ γ(t) ∈ Tᴰ on a closed domain [t₀, t₁].
pub trait ParamCurve<T: Field, const D: usize> {
    /// The domain (t₀, t₁), t₀ < t₁.
    fn domain(&self) -> (T, T);

    /// γ(t), γ′(t), …, γ⁽ᵒʳᵈᵉʳ⁾(t), derivatives per unit of t; `order + 1` points. At a break
    /// point the piece that starts there is used (the end of the domain: the last piece).
    ///
    /// # Errors
    /// [`CurveError::OutsideDomain`] for t outside [`ParamCurve::domain`] or NaN;
    /// [`CurveError::Order`] for an order above [`MAX_DERIVATIVE_ORDER`].
    fn derivatives(&self, t: &T, order: usize) -> Result<Vec<[T; D]>, CurveError>;

    /// γ(t).
    ///
    /// # Errors
    /// As [`ParamCurve::derivatives`].
    fn point(&self, t: &T) -> Result<[T; D], CurveError> {
        let mut jet = self.derivatives(t, 0)?;
        Ok(jet.swap_remove(0))
    }

    /// γ⁽ᵏ⁾(t).
    ///
    /// # Errors
    /// As [`ParamCurve::derivatives`].
    fn derivative(&self, t: &T, k: usize) -> Result<[T; D], CurveError> {
        let mut jet = self.derivatives(t, k)?;
        Ok(jet.swap_remove(k))
    }

    /// The parameters strictly inside the domain where polynomial (or analytic) pieces meet,
    /// in increasing order; none for a curve of one piece.
    fn breakpoints(&self) -> Vec<T> {
        Vec::new()
    }
}

/// The highest derivative order [`ParamCurve::derivatives`] computes: every curve of the
/// library is made of polynomial pieces or Taylor series, and an order beyond this is a
/// mistake whose result (a vector of order + 1 points) would only exhaust memory.
pub const MAX_DERIVATIVE_ORDER: usize = 64;

/// The jet as computed, or [`CurveError::NotFinite`] at `t` when an entry is NaN or infinite
/// (a derivative per unit of t that overflows on a tiny domain, 1/h^k).
///
/// # Errors
/// As stated.
pub fn finite_jet<T: Field, const D: usize>(
    jet: Vec<[T; D]>,
    t: &T,
) -> Result<Vec<[T; D]>, CurveError> {
    if jet.iter().flatten().all(Field::is_finite) {
        Ok(jet)
    } else {
        Err(CurveError::NotFinite { t: t.to_f64() })
    }
}

/// `Ok` for an order up to [`MAX_DERIVATIVE_ORDER`].
///
/// # Errors
/// [`CurveError::Order`] above it.
pub fn check_order(order: usize) -> Result<(), CurveError> {
    if order > MAX_DERIVATIVE_ORDER {
        return Err(CurveError::Order {
            order,
            max: MAX_DERIVATIVE_ORDER,
        });
    }
    Ok(())
}

/// `Ok` when t₀ ≤ t ≤ t₁, else [`CurveError::OutsideDomain`] (also for NaN and ±∞). For an
/// enclosure (a ball over a box of parameters) only a box provably outside is refused: a box
/// that reaches past an end by its rounding is evaluated, the curve's polynomial continued.
///
/// # Errors
/// [`CurveError::OutsideDomain`] as stated.
pub fn check_domain<T: Field>(t: &T, (start, end): (&T, &T)) -> Result<(), CurveError> {
    let inside = if T::ENCLOSURE {
        t.is_finite() && t.decide_lt(start) != Some(true) && end.decide_lt(t) != Some(true)
    } else {
        *start <= *t && *t <= *end
    };
    if inside {
        Ok(())
    } else {
        Err(CurveError::OutsideDomain {
            t: t.to_f64(),
            start: start.to_f64(),
            end: end.to_f64(),
        })
    }
}

/// A curve given by its jet ([`Curve`]: an expression, a data spline) on a domain [t₀, t₁],
/// as a [`ParamCurve`] of points `[T; 3]`: what makes the curves the paper checks read
/// (`ExprCurve::compile`, [`crate::curve::spline`]'s splines through
/// `ClampedSpline::on` / `PeriodicSpline::on`) usable through the one interface.
///
/// # Examples
/// ```
/// use trajverify::curve::parametric::{CurveOn, ParamCurve, ParamCurveArclen};
/// use trajverify::curve::ExprCurve;
///
/// let helix = ExprCurve::parse("[cos(t), sin(t), 0.2*t]").unwrap().compile::<f64>(&());
/// let on = CurveOn::new(helix, (0.0, 6.0)).unwrap();
/// let length = on.length().unwrap();
/// assert!((length - 6.0 * 1.04f64.sqrt()).abs() < 1e-12);
/// assert!(on.point(&7.0).is_err());
/// ```
#[derive(Clone, Debug)]
pub struct CurveOn<C, T> {
    curve: C,
    domain: (T, T),
}

impl<C: Curve<T>, T: Real> CurveOn<C, T> {
    /// `curve` on [start, end].
    ///
    /// # Errors
    /// [`CurveError::Domain`] unless start < end, both finite.
    pub fn new(curve: C, (start, end): (T, T)) -> Result<Self, CurveError> {
        if !(start.is_finite() && end.is_finite() && start.decide_lt(&end) == Some(true)) {
            return Err(CurveError::Domain {
                start: start.to_f64(),
                end: end.to_f64(),
            });
        }
        Ok(CurveOn::of_domain(curve, start, end))
    }

    /// `curve` on a domain its maker knows to be an interval.
    pub(crate) fn of_domain(curve: C, start: T, end: T) -> Self {
        CurveOn {
            curve,
            domain: (start, end),
        }
    }

    /// The curve.
    pub fn curve(&self) -> &C {
        &self.curve
    }
}

impl<C: Curve<T>, T: Real> ParamCurve<T, 3> for CurveOn<C, T> {
    fn domain(&self) -> (T, T) {
        self.domain.clone()
    }
    fn derivatives(&self, t: &T, order: usize) -> Result<Vec<[T; 3]>, CurveError> {
        crate::curve::parametric::check_order(order)?;
        check_domain(t, (&self.domain.0, &self.domain.1))?;
        let jet = self.curve.jet(t, order);
        if jet.iter().flatten().any(|x| !x.is_finite()) {
            return Err(CurveError::NotFinite { t: t.to_f64() });
        }
        Ok(jet)
    }
    fn breakpoints(&self) -> Vec<T> {
        let (start, end) = &self.domain;
        let ctx = start.ctx();
        self.curve
            .breakpoints(start.to_f64(), end.to_f64())
            .into_iter()
            .map(|b| T::from_f64(b, &ctx))
            .filter(|b| b > start && b < end)
            .collect()
    }
}

impl<C: Curve<T>, T: Real> ParamCurveArclen<T, 3> for CurveOn<C, T> {}

/// |v| of a point of any dimension.
pub fn norm<T: Real, const D: usize>(v: &[T; D]) -> T {
    dot(v, v).sqrt()
}

/// u · v.
pub fn dot<T: Field, const D: usize>(u: &[T; D], v: &[T; D]) -> T {
    let mut s = T::zero_in(&u[0].ctx());
    for (a, b) in u.iter().zip(v) {
        s.mul_add_assign(a, b);
    }
    s
}

/// The curvature κ(t) = √(|γ′|²|γ″|² − (γ′·γ″)²)/|γ′|³ (|γ′ × γ″|/|γ′|³ in 3-D, |x′y″ −
/// y′x″|/|γ′|³ in the plane), unsigned.
///
/// # Errors
/// As [`ParamCurve::derivatives`]; [`CurveError::Frame`] where the curvature is not finite
/// (γ′ = 0, or a speed so small that |γ′|³ underflows).
pub fn curvature<T: Real, const D: usize, C: ParamCurve<T, D> + ?Sized>(
    curve: &C,
    t: &T,
) -> Result<T, CurveError> {
    let jet = curve.derivatives(t, 2)?;
    let (d1, d2) = (&jet[1], &jet[2]);
    let v2 = dot(d1, d1);
    let mut area2 = v2.clone() * &dot(d2, d2);
    let c = dot(d1, d2);
    area2.mul_sub_assign(&c, &c);
    // Rounding can make the Gram determinant slightly negative for a straight piece.
    let zero = T::zero_in(&t.ctx());
    let area2 = if area2 < zero { zero } else { area2 };
    let kappa = area2.sqrt() / &(v2.clone() * &v2.sqrt());
    if !kappa.is_finite() {
        return Err(CurveError::Frame {
            t: t.to_f64(),
            reason: "zero speed: the curvature is not defined".into(),
        });
    }
    Ok(kappa)
}

/// The arc length of a curve.
pub trait ParamCurveArclen<T: Real, const D: usize>: ParamCurve<T, D> {
    /// s(t) = ∫_{t₀}^{t} |γ′(u)| du. The default integrates |γ′| by tanh–sinh on each piece
    /// between [`ParamCurve::breakpoints`] to the relative tolerance 2^(8−p) of the working
    /// precision p: an estimate whose error the quadrature does not bound.
    ///
    /// # Errors
    /// [`CurveError::OutsideDomain`] for t outside the domain.
    fn arc_length(&self, t: &T) -> Result<T, CurveError> {
        quadrature_arc_length(self, t)
    }

    /// The length of the whole curve, s(t₁).
    ///
    /// # Errors
    /// None for a well-formed curve; an implementation may fail as [`ParamCurve::derivatives`].
    fn length(&self) -> Result<T, CurveError> {
        self.arc_length(&self.domain().1)
    }

    /// The parameter t at which the arc length from the start is `s` (inverse arc length, for
    /// constant-speed trajectories): safeguarded Newton on s(t) − s with the speed |γ′(t)| as
    /// slope, inside a bisection bracket that always shrinks, until |s(t) − s| ≤ `tolerance`
    /// (an absolute length) or the bracket is below the working precision; at most
    /// [`INVERSE_ARC_LENGTH_STEPS`] steps. As exact as [`ParamCurveArclen::arc_length`] is: an
    /// estimate for the default quadrature, not a proven parameter.
    ///
    /// # Errors
    /// [`CurveError::ArcLength`] for an `s` outside [0, length] or NaN, or a `tolerance` that is
    /// not positive and finite; the errors of [`ParamCurveArclen::arc_length`].
    ///
    /// # Examples
    /// ```
    /// use trajverify::curve::bezier::BezierCurve;
    /// use trajverify::curve::parametric::ParamCurveArclen;
    /// // A straight segment of length 5 run at non-uniform speed (control points bunched).
    /// let line = BezierCurve::new(vec![[0.0, 0.0], [0.3, 0.4], [3.0, 4.0]], (0.0, 1.0)).unwrap();
    /// let t = line.parameter_at_length(&2.5, &1e-12).unwrap();
    /// assert!((line.arc_length(&t).unwrap() - 2.5).abs() < 1e-10);
    /// assert!(line.parameter_at_length(&6.0, &1e-12).is_err());
    /// ```
    fn parameter_at_length(&self, s: &T, tolerance: &T) -> Result<T, CurveError> {
        inverse_arc_length(self, s, tolerance)
    }
}

/// The most Newton-or-bisection steps of [`ParamCurveArclen::parameter_at_length`].
pub const INVERSE_ARC_LENGTH_STEPS: usize = 200;

/// The default of [`ParamCurveArclen::parameter_at_length`].
///
/// # Errors
/// As [`ParamCurveArclen::parameter_at_length`].
pub fn inverse_arc_length<T: Real, const D: usize, C: ParamCurveArclen<T, D> + ?Sized>(
    curve: &C,
    s: &T,
    tolerance: &T,
) -> Result<T, CurveError> {
    let ctx = s.ctx();
    let zero = T::zero_in(&ctx);
    let total = curve.length()?;
    if !(tolerance.is_finite() && *tolerance > zero) {
        return Err(CurveError::ArcLength {
            field: "tolerance",
            value: tolerance.to_f64(),
            length: total.to_f64(),
            message: "the tolerance must be a positive finite number".into(),
        });
    }
    if !(s.is_finite() && *s >= zero && *s <= total) {
        return Err(CurveError::ArcLength {
            field: "s",
            value: s.to_f64(),
            length: total.to_f64(),
            message: "the arc length must lie in [0, length]".into(),
        });
    }
    let (mut lo, mut hi) = curve.domain();
    let two = T::from_i64(2, &ctx);
    // The linear guess: exact for a curve at constant speed.
    let mut t = lo.clone() + &((hi.clone() - &lo) * s / &total);
    for _ in 0..INVERSE_ARC_LENGTH_STEPS {
        let excess = curve.arc_length(&t)? - s;
        if excess.abs() <= *tolerance {
            return Ok(t);
        }
        if excess > zero {
            hi = t.clone();
        } else {
            lo = t.clone();
        }
        let midpoint = (lo.clone() + &hi) / &two;
        if !(lo < midpoint && midpoint < hi) {
            return Ok(t); // the bracket is below the working precision
        }
        let speed = norm(&curve.derivative(&t, 1)?);
        let newton = t.clone() - &(excess / &speed);
        t = if speed > zero && newton.is_finite() && lo < newton && newton < hi {
            newton
        } else {
            midpoint
        };
    }
    Ok(t)
}

/// The levels of step halving of the default arc-length quadrature.
const ARC_LENGTH_LEVELS: usize = 12;

/// ∫_{t₀}^{t} |γ′| by tanh–sinh on each piece between break points (the default of
/// [`ParamCurveArclen::arc_length`]).
///
/// # Errors
/// [`CurveError::OutsideDomain`] for t outside the domain.
pub fn quadrature_arc_length<T: Real, const D: usize, C: ParamCurve<T, D> + ?Sized>(
    curve: &C,
    t: &T,
) -> Result<T, CurveError> {
    let (start, end) = curve.domain();
    check_domain(t, (&start, &end))?;
    let ctx = t.ctx();
    let rule = TanhSinh::<T>::new(&ctx, ARC_LENGTH_LEVELS);
    let tol = default_tolerance::<T>(&ctx);
    let zero = T::zero_in(&ctx);
    let mut cuts = vec![start];
    cuts.extend(curve.breakpoints().into_iter().filter(|b| b < t));
    cuts.push(t.clone());
    let mut total = zero.clone();
    for w in cuts.windows(2) {
        if w[0] >= w[1] {
            continue;
        }
        // Every node lies inside [w0, w1] ⊂ the domain, so the evaluation cannot fail; a
        // failure would count as zero speed rather than panic.
        let speed = |near: &T, _: &T| {
            let u = w[0].clone() + near;
            curve
                .derivative(&u, 1)
                .map_or_else(|_| zero.clone(), |d| norm(&d))
        };
        total += &rule.integrate((&w[0], &w[1]), speed, &tol, &zero).value;
    }
    Ok(total)
}

/// An orthonormal frame along a space curve and how it turns.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame<T> {
    /// γ(t).
    pub point: [T; 3],
    /// The frame vectors e₁, e₂, e₃ (e₁ the unit tangent).
    pub axes: [[T; 3]; 3],
    /// The angular velocity ω per unit of t, in world coordinates: ėₖ = ω × eₖ.
    pub omega: [T; 3],
    /// The parametric speed |γ′(t)|.
    pub speed: T,
}

/// A space curve with an adapted frame.
pub trait ParamCurveFrame<T: Real>: ParamCurve<T, 3> {
    /// The frame at t with its angular velocity per unit of t.
    ///
    /// # Errors
    /// [`CurveError::OutsideDomain`] outside the domain; [`CurveError::Frame`] where the
    /// frame is not defined.
    fn frame(&self, t: &T) -> Result<Frame<T>, CurveError>;
}
