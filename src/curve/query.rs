//! Everyday questions about any [`ParamCurve`], in any number type: the points at many
//! parameters at once ([`points_at`]), a part of the curve as a curve ([`Subsegment`]), the
//! extreme values of each coordinate and the bounding box ([`extrema`], [`bounding_box`]),
//! the point nearest to a given one ([`nearest_point`]) and the largest distance between two
//! curves ([`largest_distance`]) — what kurbo's `ParamCurveExtrema`,
//! `ParamCurveNearest` and `subsegment` and scipy's vectorised `__call__` give.
//!
//! # How the searches work, and what they promise
//! An extremum of coordinate c on a piece (between two [`ParamCurve::breakpoints`]) is an end
//! of the piece or a zero of γ_c′; the point nearest to q is an end or a zero of
//! g(t) = (γ(t) − q)·γ′(t) where g changes sign from − to +; two curves are farthest apart at
//! an end or where (γ₁ − γ₂)·(γ₁′ − γ₂′) changes sign from + to −. Each piece is sampled at
//! [`SAMPLES_PER_PIECE`] + 1 equally spaced parameters; every sign change of the function
//! between two samples is bisected to the working precision (at most
//! 4 × its bits steps), and the best candidate is kept. The values are computed in the curve's
//! number type, but the search is **an estimate, not a proof**: two zeros between the same
//! two samples cancel and are not seen. For a proven range of a curve's coordinates, use ball
//! branch and bound ([`crate::numeric::maximum::proven_range`]) on its interval extension.

use super::parametric::{dot, CurveError, ParamCurve, ParamCurveArclen};
use crate::scalar::{Field, Real};

/// Samples per piece at which the searches look for sign changes.
pub const SAMPLES_PER_PIECE: usize = 64;

/// The most parameters [`points_at`] evaluates in one call.
pub const MAX_POINTS: usize = 10_000_000;

/// γ(t) at every t of `ts`, in order: scipy's vectorised evaluation.
///
/// # Errors
/// [`CurveError::Index`] (field `ts`) for more than [`MAX_POINTS`] parameters; the first
/// error of [`ParamCurve::point`] (a t outside the domain, or NaN).
///
/// # Examples
/// ```
/// use trajverify::curve::bezier::BezierCurve;
/// use trajverify::curve::query::points_at;
/// let c = BezierCurve::new(vec![[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]], (0.0, 1.0)).unwrap();
/// let p = points_at(&c, &[0.0, 0.5, 1.0]).unwrap();
/// assert_eq!(p, vec![[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]]);
/// assert!(points_at(&c, &[0.5, 2.0]).is_err());
/// ```
pub fn points_at<T: Field, const D: usize, C: ParamCurve<T, D> + ?Sized>(
    curve: &C,
    ts: &[T],
) -> Result<Vec<[T; D]>, CurveError> {
    if ts.len() > MAX_POINTS {
        return Err(CurveError::Index {
            field: "ts",
            index: ts.len(),
            max: MAX_POINTS,
        });
    }
    ts.iter().map(|t| curve.point(t)).collect()
}

/// The part of a curve on [start, end] ⊆ its domain, as a curve of the same parameter t
/// (not reparametrized: γ(t) is the original curve's point at t). Its break points are the
/// original's inside (start, end); its arc length is measured from `start` with the
/// original's own method (exact for PH splines).
///
/// # Examples
/// ```
/// use trajverify::curve::bezier::BezierCurve;
/// use trajverify::curve::parametric::{ParamCurve, ParamCurveArclen};
/// use trajverify::curve::query::Subsegment;
/// let line = BezierCurve::new(vec![[0.0, 0.0], [4.0, 0.0]], (0.0, 1.0)).unwrap();
/// let middle = Subsegment::new(&line, (0.25, 0.75)).unwrap();
/// assert_eq!(middle.domain(), (0.25, 0.75));
/// assert_eq!(middle.point(&0.5).unwrap(), [2.0, 0.0]);
/// assert!(middle.point(&0.9).is_err());
/// assert!((middle.length().unwrap() - 2.0).abs() < 1e-12);
/// ```
#[derive(Clone, Debug)]
pub struct Subsegment<'a, C: ?Sized, T> {
    curve: &'a C,
    start: T,
    end: T,
}

impl<'a, T: Field, C: ?Sized> Subsegment<'a, C, T> {
    /// `curve` on [start, end].
    ///
    /// # Errors
    /// [`CurveError::Domain`] unless start < end (decided) and both lie in the curve's domain.
    pub fn new<const D: usize>(curve: &'a C, (start, end): (T, T)) -> Result<Self, CurveError>
    where
        C: ParamCurve<T, D>,
    {
        let (first, last) = curve.domain();
        let inside = |x: &T| x.is_finite() && first <= *x && *x <= last;
        if !(inside(&start) && inside(&end) && start.decide_lt(&end) == Some(true)) {
            return Err(CurveError::Domain {
                start: start.to_f64(),
                end: end.to_f64(),
            });
        }
        Ok(Subsegment { curve, start, end })
    }
}

impl<T: Field, const D: usize, C: ParamCurve<T, D> + ?Sized> ParamCurve<T, D>
    for Subsegment<'_, C, T>
{
    fn domain(&self) -> (T, T) {
        (self.start.clone(), self.end.clone())
    }
    fn derivatives(&self, t: &T, order: usize) -> Result<Vec<[T; D]>, CurveError> {
        super::parametric::check_domain(t, (&self.start, &self.end))?;
        self.curve.derivatives(t, order)
    }
    fn breakpoints(&self) -> Vec<T> {
        self.curve
            .breakpoints()
            .into_iter()
            .filter(|b| *b > self.start && *b < self.end)
            .collect()
    }
}

impl<T: Real, const D: usize, C: ParamCurveArclen<T, D> + ?Sized> ParamCurveArclen<T, D>
    for Subsegment<'_, C, T>
{
    fn arc_length(&self, t: &T) -> Result<T, CurveError> {
        super::parametric::check_domain(t, (&self.start, &self.end))?;
        Ok(self.curve.arc_length(t)? - &self.curve.arc_length(&self.start)?)
    }
}

/// The smallest and largest value of one coordinate, and where they are taken.
#[derive(Clone, Debug, PartialEq)]
pub struct Extremum<T> {
    /// The smallest value found.
    pub min: T,
    /// A parameter where it is taken.
    pub min_at: T,
    /// The largest value found.
    pub max: T,
    /// A parameter where it is taken.
    pub max_at: T,
}

/// The extreme values of each coordinate over the whole domain (an estimate: see the module
/// doc).
///
/// # Errors
/// The first error of [`ParamCurve::derivatives`] at a sample (a curve that is not finite
/// somewhere).
///
/// # Examples
/// ```
/// use trajverify::curve::bezier::BezierCurve;
/// use trajverify::curve::query::{bounding_box, extrema};
/// // y = 2t(1 − t)·2 peaks at t = 1/2 with y = 1, between the control points' 0 and 2.
/// let c = BezierCurve::new(vec![[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]], (0.0, 1.0)).unwrap();
/// let e = extrema(&c).unwrap();
/// assert!((e[1].max - 1.0).abs() < 1e-15 && (e[1].max_at - 0.5).abs() < 1e-8);
/// let (low, high) = bounding_box(&c).unwrap();
/// assert_eq!(low, [0.0, 0.0]);
/// assert!((high[0] - 2.0).abs() < 1e-15 && (high[1] - 1.0).abs() < 1e-15);
/// ```
pub fn extrema<T: Real, const D: usize, C: ParamCurve<T, D> + ?Sized>(
    curve: &C,
) -> Result<Vec<Extremum<T>>, CurveError> {
    let mut found: Vec<Option<Extremum<T>>> = vec![None; D];
    for (lo, hi) in pieces(curve) {
        let grid = samples(&lo, &hi);
        let jets = grid
            .iter()
            .map(|t| curve.derivatives(t, 1))
            .collect::<Result<Vec<_>, _>>()?;
        for (c, slot) in found.iter_mut().enumerate() {
            let mut candidates: Vec<T> = vec![lo.clone(), hi.clone()];
            let slope = |t: &T| curve.derivatives(t, 1).map(|j| j[1][c].clone());
            for (i, w) in jets.windows(2).enumerate() {
                if changes_sign(&w[0][1][c], &w[1][1][c]) {
                    candidates.push(bisect(&slope, &grid[i], &grid[i + 1])?);
                }
            }
            for t in candidates {
                let value = curve.point(&t)?[c].clone();
                let better = match slot.as_ref() {
                    None => (true, true),
                    Some(e) => (value < e.min, value > e.max),
                };
                match (slot.as_mut(), better) {
                    (None, _) => {
                        *slot = Some(Extremum {
                            min: value.clone(),
                            min_at: t.clone(),
                            max: value,
                            max_at: t,
                        })
                    }
                    (Some(e), (low, high)) => {
                        if low {
                            e.min = value.clone();
                            e.min_at = t.clone();
                        }
                        if high {
                            e.max = value;
                            e.max_at = t;
                        }
                    }
                }
            }
        }
    }
    found
        .into_iter()
        .map(|e| {
            e.ok_or_else(|| {
                let (start, end) = curve.domain();
                CurveError::Domain {
                    start: start.to_f64(),
                    end: end.to_f64(),
                }
            })
        })
        .collect()
}

/// The axis-aligned box [low, high] of the curve: each coordinate's extreme values
/// ([`extrema`], an estimate).
///
/// # Errors
/// As [`extrema`].
pub fn bounding_box<T: Real, const D: usize, C: ParamCurve<T, D> + ?Sized>(
    curve: &C,
) -> Result<([T; D], [T; D]), CurveError> {
    let e = extrema(curve)?;
    Ok((
        std::array::from_fn(|c| e[c].min.clone()),
        std::array::from_fn(|c| e[c].max.clone()),
    ))
}

/// The point of the curve nearest to `q`.
#[derive(Clone, Debug, PartialEq)]
pub struct Nearest<T, const D: usize> {
    /// Its parameter.
    pub t: T,
    /// The point γ(t).
    pub point: [T; D],
    /// |γ(t) − q|.
    pub distance: T,
}

/// The point of the curve nearest to `q` (an estimate: see the module doc).
///
/// # Errors
/// [`CurveError::Argument`] (field `q`) for a point that is not finite; the first error of
/// [`ParamCurve::derivatives`] at a sample.
///
/// # Examples
/// ```
/// use trajverify::curve::bezier::BezierCurve;
/// use trajverify::curve::query::nearest_point;
/// let c = BezierCurve::new(vec![[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]], (0.0, 1.0)).unwrap();
/// let n = nearest_point(&c, &[1.0, 3.0]).unwrap();
/// assert!((n.t - 0.5).abs() < 1e-8 && (n.distance - 2.0).abs() < 1e-12);
/// ```
pub fn nearest_point<T: Real, const D: usize, C: ParamCurve<T, D> + ?Sized>(
    curve: &C,
    q: &[T; D],
) -> Result<Nearest<T, D>, CurveError> {
    if !q.iter().all(Field::is_finite) {
        return Err(CurveError::Argument {
            field: "q",
            message: "the point is not finite".into(),
        });
    }
    let offset = |p: &[T; D]| -> [T; D] { std::array::from_fn(|c| p[c].clone() - &q[c]) };
    let slope = |t: &T| curve.derivatives(t, 1).map(|j| dot(&offset(&j[0]), &j[1]));
    let mut best: Option<Nearest<T, D>> = None;
    for (lo, hi) in pieces(curve) {
        let grid = samples(&lo, &hi);
        let g = grid.iter().map(&slope).collect::<Result<Vec<_>, _>>()?;
        let mut candidates = vec![lo.clone(), hi.clone()];
        let zero = T::zero_in(&lo.ctx());
        for (i, w) in g.windows(2).enumerate() {
            // A minimum of the distance: g rises through zero.
            if w[0] < zero && w[1] >= zero {
                candidates.push(bisect(&slope, &grid[i], &grid[i + 1])?);
            }
        }
        for t in candidates {
            let point = curve.point(&t)?;
            let distance = scaled_norm(&offset(&point));
            if !distance.is_finite() {
                return Err(CurveError::Argument {
                    field: "q",
                    message: "its distance to the curve is not representable".into(),
                });
            }
            if best.as_ref().is_none_or(|b| distance < b.distance) {
                best = Some(Nearest { t, point, distance });
            }
        }
    }
    best.ok_or_else(|| {
        let (start, end) = curve.domain();
        CurveError::Domain {
            start: start.to_f64(),
            end: end.to_f64(),
        }
    })
}

/// |v| without overflow or underflow in the squares: the largest |vᵢ| times the norm of v
/// divided by it.
fn scaled_norm<T: Real, const D: usize>(v: &[T; D]) -> T {
    let zero = T::zero_in(&v[0].ctx());
    let largest = v.iter().fold(zero.clone(), |m, x| m.max_with(&x.abs()));
    if largest.is_zero() || !largest.is_finite() {
        return largest;
    }
    let scaled: [T; D] = std::array::from_fn(|c| v[c].clone() / &largest);
    largest * &dot(&scaled, &scaled).sqrt()
}

/// The largest distance max_t |γ₁(t) − γ₂(t)| between two curves of the same parameter over
/// their common domain, and where it is taken (an estimate: see the module doc): how far one
/// library curve is from another — a fit from its target, one number type from another.
///
/// # Errors
/// [`CurveError::Domain`] when the domains do not overlap in an interval; the first error of
/// [`ParamCurve::derivatives`] at a sample; [`CurveError::Argument`] (field `other`) when the
/// distance is not representable.
///
/// # Examples
/// ```
/// use trajverify::curve::bezier::BezierCurve;
/// use trajverify::curve::query::largest_distance;
/// // Two parabolas 2t(1 − t) apart in y: farthest at t = 1/2, by 1/2.
/// let a = BezierCurve::new(vec![[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]], (0.0, 1.0)).unwrap();
/// let b = BezierCurve::new(vec![[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]], (0.0, 1.0)).unwrap();
/// let far = largest_distance(&a, &b).unwrap();
/// assert!((far.distance - 0.5).abs() < 1e-15 && (far.t - 0.5).abs() < 1e-8);
/// ```
pub fn largest_distance<T, const D: usize, A, B>(
    one: &A,
    other: &B,
) -> Result<Farthest<T>, CurveError>
where
    T: Real,
    A: ParamCurve<T, D> + ?Sized,
    B: ParamCurve<T, D> + ?Sized,
{
    let ((s1, e1), (s2, e2)) = (one.domain(), other.domain());
    let start = if s1 > s2 { s1 } else { s2 };
    let end = if e1 < e2 { e1 } else { e2 };
    if start.decide_lt(&end) != Some(true) {
        return Err(CurveError::Domain {
            start: start.to_f64(),
            end: end.to_f64(),
        });
    }
    let mut cuts = vec![start.clone()];
    let mut inner: Vec<T> = one
        .breakpoints()
        .into_iter()
        .chain(other.breakpoints())
        .filter(|b| *b > start && *b < end)
        .collect();
    inner.sort_by(|a, b| a.partial_cmp(b).unwrap_or(std::cmp::Ordering::Equal));
    cuts.extend(inner);
    cuts.push(end);
    let difference = |t: &T| -> Result<[[T; D]; 2], CurveError> {
        let (p, q) = (one.derivatives(t, 1)?, other.derivatives(t, 1)?);
        Ok([
            std::array::from_fn(|c| p[0][c].clone() - &q[0][c]),
            std::array::from_fn(|c| p[1][c].clone() - &q[1][c]),
        ])
    };
    // g = (γ₁ − γ₂)·(γ₁′ − γ₂′) falls through zero at a local maximum of the distance.
    let slope = |t: &T| difference(t).map(|[d, v]| dot(&d, &v));
    let mut best: Option<Farthest<T>> = None;
    for w in cuts.windows(2).filter(|w| w[0] < w[1]) {
        let grid = samples(&w[0], &w[1]);
        let g = grid.iter().map(&slope).collect::<Result<Vec<_>, _>>()?;
        let zero = T::zero_in(&w[0].ctx());
        let mut candidates = vec![w[0].clone(), w[1].clone()];
        for (i, pair) in g.windows(2).enumerate() {
            if pair[0] > zero && pair[1] <= zero {
                candidates.push(bisect(&slope, &grid[i], &grid[i + 1])?);
            }
        }
        for t in candidates {
            let [d, _] = difference(&t)?;
            let distance = scaled_norm(&d);
            if !distance.is_finite() {
                return Err(CurveError::Argument {
                    field: "other",
                    message: "the distance between the curves is not representable".into(),
                });
            }
            if best.as_ref().is_none_or(|b| distance > b.distance) {
                best = Some(Farthest { t, distance });
            }
        }
    }
    best.ok_or(CurveError::Domain {
        start: f64::NAN,
        end: f64::NAN,
    })
}

/// Where two curves are farthest apart.
#[derive(Clone, Debug, PartialEq)]
pub struct Farthest<T> {
    /// The parameter.
    pub t: T,
    /// |γ₁(t) − γ₂(t)|.
    pub distance: T,
}

/// The pieces between the domain's ends and its break points.
fn pieces<T: Field, const D: usize, C: ParamCurve<T, D> + ?Sized>(curve: &C) -> Vec<(T, T)> {
    let (start, end) = curve.domain();
    let mut cuts = vec![start];
    cuts.extend(curve.breakpoints());
    cuts.push(end);
    cuts.windows(2)
        .filter(|w| w[0] < w[1])
        .map(|w| (w[0].clone(), w[1].clone()))
        .collect()
}

/// [`SAMPLES_PER_PIECE`] + 1 equally spaced parameters from lo to hi, both ends exact.
fn samples<T: Field>(lo: &T, hi: &T) -> Vec<T> {
    let ctx = lo.ctx();
    let n = SAMPLES_PER_PIECE as i64;
    let width = hi.clone() - lo;
    let mut grid: Vec<T> = (0..n)
        .map(|i| lo.clone() + &(width.clone() * &T::from_ratio(i, n, &ctx)))
        .collect();
    grid.push(hi.clone());
    grid
}

/// Whether a and b have strictly opposite signs, or b is zero and a is not.
fn changes_sign<T: Field>(a: &T, b: &T) -> bool {
    let zero = T::zero_in(&a.ctx());
    (*a < zero && *b >= zero) || (*a > zero && *b <= zero)
}

/// A zero of f between lo and hi, where f changes sign, by bisection to the working
/// precision (at most 4 × its bits steps).
fn bisect<T: Real>(
    f: &dyn Fn(&T) -> Result<T, CurveError>,
    lo: &T,
    hi: &T,
) -> Result<T, CurveError> {
    let ctx = lo.ctx();
    let zero = T::zero_in(&ctx);
    let half = T::from_ratio(1, 2, &ctx);
    let (mut lo, mut hi) = (lo.clone(), hi.clone());
    let negative_at_lo = f(&lo)? < zero;
    for _ in 0..4 * T::precision_bits(&ctx) {
        let mid = (lo.clone() + &hi) * &half;
        if mid <= lo || mid >= hi {
            break;
        }
        let value = f(&mid)?;
        if value.is_zero() {
            return Ok(mid);
        }
        if (value < zero) == negative_at_lo {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok((lo + &hi) * &half)
}
