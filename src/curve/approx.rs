//! The distance between a curve and a piecewise polynomial approximation of it, as a true
//! maximum: E = max_ξ ‖γ(ξ) − p(ξ)‖ (paper 001, Eqs. 2, 21), for any approximant made of
//! Bernstein pieces on uniform segments ([`BernsteinPieces`]: the PHODCOS conversion, the
//! piecewise Hermite–Bernstein interpolant of paper 000).
//!
//! f(ξ) = ‖γ_k(ξ) − p_k(ξ)‖² is sampled on a uniform grid in every segment and each sampled
//! local maximum is refined by Newton's method on f′ = 0 with the exact second derivative
//! (curve derivatives from Taylor-mode AD, the piece in local power form), kept inside the
//! bracket of its neighbouring samples. The sampled maximum is reported too. The proven
//! counterpart, an enclosure by branch and bound in balls, is [`super::enclosure`].

use super::parametric::{check_domain, CurveError, ParamCurve, ParamCurveArclen};
use super::Curve;
use crate::numeric::poly::bernstein::{bernstein_jet, BernsteinError};
use crate::numeric::poly::binom;
use crate::numeric::quat::vec3;
use crate::scalar::ball::carried;
use crate::scalar::certify::{certify, Certified};
use crate::scalar::{Field, Float, Real};
use rayon::prelude::*;

/// Polynomial pieces in Bernstein form on N uniform segments of [a, b]: piece k lives on
/// [t_k, t_k + h], t_k = a + k h, in the local parameter ξ = (t − t_k)/h ∈ [0, 1].
pub trait BernsteinPieces<T: Real>: Sync {
    /// a and b.
    fn interval(&self) -> (&T, &T);
    /// N ≥ 1, the number of segments (every implementation in the library has at least one;
    /// [`conversion_error`] relies on it).
    fn count(&self) -> usize;
    /// The control points of piece k.
    fn control_points(&self, k: usize) -> Vec<[T; 3]>;
    /// Segment length h = (b − a)/N.
    fn step(&self) -> T {
        let (a, b) = self.interval();
        (b.clone() - a) / &T::from_i64(self.count() as i64, &a.ctx())
    }
    /// The start t_k = a + (b − a)k/N of segment k (k = N gives b; a larger k continues the
    /// same formula past b: callers pass k ≤ N).
    fn knot(&self, k: usize) -> T {
        let (a, b) = self.interval();
        knot((a, b), self.count(), k)
    }
}

/// a + (b − a) k / N.
pub fn knot<T: Field>((a, b): (&T, &T), n: usize, k: usize) -> T {
    let ctx = a.ctx();
    a.clone() + &((b.clone() - a) * &T::from_i64(k as i64, &ctx) / &T::from_i64(n as i64, &ctx))
}

/// The segment k holding t and the local parameter ξ = (t − t_k)/h ∈ [0, 1] (t clamped to
/// [a, b]; at a joint, the segment that starts there; at b, the last one).
pub fn locate<T: Real, P: BernsteinPieces<T> + ?Sized>(pieces: &P, t: &T) -> (usize, T) {
    let ctx = t.ctx();
    let n = pieces.count();
    let u = (t.clone() - pieces.interval().0) / &pieces.step();
    // The floor of u, found by comparison so no conversion of huge values can overflow.
    let nn = T::from_i64(n as i64, &ctx);
    let u = if u < T::zero_in(&ctx) {
        T::zero_in(&ctx)
    } else if u > nn {
        nn
    } else {
        u
    };
    let (mut lo, mut hi) = (0usize, n);
    while hi - lo > 1 {
        let mid = (lo + hi) / 2;
        if u >= T::from_i64(mid as i64, &ctx) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let xi = u - &T::from_i64(lo as i64, &ctx);
    (lo, xi)
}

/// [`locate`] for a t in [a, b] only.
///
/// # Errors
/// [`CurveError::OutsideDomain`] for t outside [a, b] or NaN.
pub fn locate_in_domain<T: Real, P: BernsteinPieces<T> + ?Sized>(
    pieces: &P,
    t: &T,
) -> Result<(usize, T), CurveError> {
    check_domain(t, pieces.interval())?;
    Ok(locate(pieces, t))
}

/// γ(t), γ′(t), … per unit of t for pieces in Bernstein form ([`ParamCurve::derivatives`]):
/// the derivatives in ξ divided by hᵏ.
///
/// # Errors
/// [`CurveError::OutsideDomain`] for t outside [a, b].
pub fn pieces_derivatives<T: Real, P: BernsteinPieces<T> + ?Sized>(
    pieces: &P,
    t: &T,
    order: usize,
) -> Result<Vec<[T; 3]>, CurveError> {
    let (k, xi) = locate_in_domain(pieces, t)?;
    let mut jet = bernstein_jet(&pieces.control_points(k), &xi, order);
    let inv = T::one_in(&t.ctx()) / &pieces.step();
    let mut scale = T::one_in(&t.ctx());
    for v in jet.iter_mut().skip(1) {
        scale *= &inv;
        for x in v.iter_mut() {
            *x *= &scale;
        }
    }
    crate::curve::parametric::finite_jet(jet, t)
}

/// The joints t_1 … t_{N−1} ([`ParamCurve::breakpoints`]).
pub fn pieces_breakpoints<T: Real, P: BernsteinPieces<T> + ?Sized>(pieces: &P) -> Vec<T> {
    (1..pieces.count()).map(|k| pieces.knot(k)).collect()
}

/// Pieces given by their control points: N ≥ 1 pieces on [a, b], a < b (built by
/// [`crate::algo::hermite::piecewise::interpolate_curve`]). As a curve of t it implements
/// [`ParamCurve`] and [`ParamCurveArclen`] (by quadrature).
#[derive(Clone, Debug)]
pub struct PiecewiseBernstein<T> {
    a: T,
    b: T,
    segments: Vec<Vec<[T; 3]>>,
}

impl<T: Real> PiecewiseBernstein<T> {
    /// The pieces with these control points on uniform segments of [a, b].
    ///
    /// # Errors
    /// [`crate::numeric::poly::bernstein::BernsteinError::Empty`] without a piece or for a
    /// piece without a control point, [`crate::numeric::poly::bernstein::BernsteinError::Interval`]
    /// unless a < b, both finite.
    pub fn new(segments: Vec<Vec<[T; 3]>>, (a, b): (T, T)) -> Result<Self, BernsteinError> {
        if segments.is_empty() || segments.iter().any(Vec::is_empty) {
            return Err(BernsteinError::Empty);
        }
        if !(a.is_finite() && b.is_finite() && a < b) {
            return Err(BernsteinError::Interval);
        }
        Ok(PiecewiseBernstein { a, b, segments })
    }
}

impl<T: Real> ParamCurve<T, 3> for PiecewiseBernstein<T> {
    fn domain(&self) -> (T, T) {
        (self.a.clone(), self.b.clone())
    }
    fn derivatives(&self, t: &T, order: usize) -> Result<Vec<[T; 3]>, CurveError> {
        crate::curve::parametric::check_order(order)?;
        pieces_derivatives(self, t, order)
    }
    fn breakpoints(&self) -> Vec<T> {
        pieces_breakpoints(self)
    }
}

impl<T: Real> ParamCurveArclen<T, 3> for PiecewiseBernstein<T> {}

impl<T: Real> BernsteinPieces<T> for PiecewiseBernstein<T> {
    fn interval(&self) -> (&T, &T) {
        (&self.a, &self.b)
    }
    fn count(&self) -> usize {
        self.segments.len()
    }
    fn control_points(&self, k: usize) -> Vec<[T; 3]> {
        self.segments[k].clone()
    }
}

/// The error of one approximation (for PHODCOS, the conversion error E of paper 001, Eq. 21).
#[derive(Clone, Debug)]
pub struct ConversionError<T> {
    /// max over ξ of ‖γ − p‖, refined to the working precision.
    pub max: T,
    /// The maximum over the sample grid only.
    pub sampled: T,
    /// Where the maximum is: segment and local parameter.
    pub segment: usize,
    /// The local parameter ξ ∈ [0, 1] of the maximum.
    pub xi: T,
}

/// Samples per segment for locating the maxima before refinement.
pub const DEFAULT_SAMPLES: usize = 16;

/// E = max_ξ ‖γ(ξ) − p(ξ)‖ over all segments (paper 001, Eq. 21), sampled with `samples`
/// intervals per segment, then refined.
///
/// # Panics
/// If `pw.count()` is 0, which breaks [`BernsteinPieces::count`]'s contract (no pieces built
/// by the library have it).
pub fn conversion_error<T: Real, C: Curve<T> + ?Sized, P: BernsteinPieces<T> + ?Sized>(
    curve: &C,
    pw: &P,
    samples: usize,
) -> ConversionError<T> {
    let all: Vec<usize> = (0..pw.count()).collect();
    conversion_error_among(curve, pw, samples, &all)
}

/// [`conversion_error`] searched on the segments `segments` only (increasing, each below
/// `pw.count()`): the same result whenever the others are known not to reach the maximum,
/// sampled or refined (a screen by proven bounds, [`crate::algo::ph::grid::ErrorScreen`]).
///
/// # Panics
/// If `segments` is empty or names a segment `pw` does not have.
pub fn conversion_error_among<T: Real, C: Curve<T> + ?Sized, P: BernsteinPieces<T> + ?Sized>(
    curve: &C,
    pw: &P,
    samples: usize,
    segments: &[usize],
) -> ConversionError<T> {
    let h = pw.step();
    let per_segment: Vec<(T, T, T)> = segments
        .par_iter()
        .map(carried(|&k| {
            segment_error(curve, &pw.control_points(k), &pw.knot(k), &h, samples)
        }))
        .collect();
    let mut best = 0usize;
    for i in 1..per_segment.len() {
        if per_segment[i].0 > per_segment[best].0 {
            best = i;
        }
    }
    let mut sampled = per_segment[0].1.clone();
    for s in &per_segment {
        if s.1 > sampled {
            sampled = s.1.clone();
        }
    }
    let (max, _, xi) = per_segment[best].clone();
    ConversionError {
        max,
        sampled,
        segment: segments[best],
        xi,
    }
}

/// The power-basis coefficients of a Bernstein polynomial on [0, 1] with vector values.
fn power_form<T: Field>(points: &[[T; 3]]) -> Vec<[T; 3]> {
    let n = points.len() - 1;
    let ctx = points[0][0].ctx();
    // c_k = C(n,k) Δᵏ p_0
    let mut diffs = points.to_vec();
    let mut out = Vec::with_capacity(n + 1);
    for k in 0..=n {
        if k > 0 {
            for i in 0..diffs.len() - 1 {
                diffs[i] = vec3::sub(&diffs[i + 1], &diffs[i]);
            }
            diffs.pop();
        }
        out.push(vec3::scale(&diffs[0], &T::from_i64(binom(n, k), &ctx)));
    }
    out
}

/// p (and p′, p″ when `order` is 2) at ξ from power-form coefficients (Horner).
fn horner_jet<T: Field>(c: &[[T; 3]], xi: &T, order: usize) -> [[T; 3]; 3] {
    let ctx = xi.ctx();
    let mut p = c[c.len() - 1].clone();
    let mut d1 = vec3::zero::<T>(&ctx);
    let mut d2 = vec3::zero::<T>(&ctx);
    for ck in c.iter().rev().skip(1) {
        for d in 0..3 {
            if order > 0 {
                // d2 = d2 ξ + 2 d1; d1 = d1 ξ + p (before p is updated)
                let two_d1 = d1[d].clone() + &d1[d];
                d2[d] = d2[d].clone() * xi + &two_d1;
                d1[d] = d1[d].clone() * xi + &p[d];
            }
            p[d].horner_step(xi, &ck[d]);
        }
    }
    [p, d1, d2]
}

/// The squared distance f = |γ_k − p_k|² on one segment, with g = ½f′ and g′ for Newton.
pub struct SegmentDistance<'a, T, C: ?Sized> {
    curve: &'a C,
    coeffs: Vec<[T; 3]>,
    t0: T,
    h: T,
}

impl<'a, T: Real, C: Curve<T> + ?Sized> SegmentDistance<'a, T, C> {
    /// The distance of the piece with control points `points` on [t0, t0 + h] from `curve`.
    pub fn new(curve: &'a C, points: &[[T; 3]], t0: &T, h: &T) -> Self {
        SegmentDistance {
            curve,
            coeffs: power_form(points),
            t0: t0.clone(),
            h: h.clone(),
        }
    }
    /// f(ξ).
    pub fn value(&self, xi: &T) -> T {
        let t = self.t0.clone() + &(self.h.clone() * xi);
        let g = self.curve.jet(&t, 0);
        let p = horner_jet(&self.coeffs, xi, 0);
        let e0 = vec3::sub(&g[0], &p[0]);
        vec3::dot(&e0, &e0)
    }
    /// (g, g′) with g = (γ−p)·(hγ′−p′) = ½f′ and g′ = |hγ′−p′|² + (γ−p)·(h²γ″−p″).
    fn slope(&self, xi: &T) -> (T, T) {
        let t = self.t0.clone() + &(self.h.clone() * xi);
        let g = self.curve.jet(&t, 2);
        let p = horner_jet(&self.coeffs, xi, 2);
        let e0 = vec3::sub(&g[0], &p[0]);
        let e1 = vec3::sub(&vec3::scale(&g[1], &self.h), &p[1]);
        let h2 = self.h.clone() * &self.h;
        let e2 = vec3::sub(&vec3::scale(&g[2], &h2), &p[2]);
        let slope = vec3::dot(&e0, &e1);
        let curv = vec3::dot(&e1, &e1) + &vec3::dot(&e0, &e2);
        (slope, curv)
    }
    /// Newton on g = 0 from `x`, kept inside (lo, hi); the maximum f found and where.
    fn refine(&self, mut x: T, lo: &T, hi: &T) -> (T, T) {
        let ctx = x.ctx();
        let tolerance = T::epsilon(&ctx).sqrt() * &T::from_ratio(1, 1 << 10, &ctx);
        let half = T::from_ratio(1, 2, &ctx);
        let mut previous: Option<T> = None;
        for _ in 0..40 {
            let (g, dg) = self.slope(&x);
            if dg.is_zero() {
                break;
            }
            let step = g / &dg;
            let mut next = x.clone() - &step;
            if next <= *lo || next >= *hi || !next.is_finite() {
                // Newton left the bracket: bisect towards the ascent instead.
                next = if step < T::zero_in(&ctx) {
                    (x.clone() + hi) * &half
                } else {
                    (x.clone() + lo) * &half
                };
            }
            let moved = (next.clone() - &x).abs();
            x = next;
            // Converged, or no longer converging quadratically: the step is then set by
            // rounding noise in f′ (the error is far below the curve's size) and ξ is as
            // accurate as f′ allows; f is flat there, so f(ξ) is accurate regardless.
            let stalled = previous
                .as_ref()
                .is_some_and(|p| moved.clone() * &T::from_i64(4, &ctx) > *p);
            previous = Some(moved.clone());
            if stalled || moved <= tolerance {
                break;
            }
        }
        (self.value(&x), x)
    }
}

/// (refined max, sampled max, argmax ξ) of ‖γ_k − p_k‖ on one segment.
fn segment_error<T: Real, C: Curve<T> + ?Sized>(
    curve: &C,
    points: &[[T; 3]],
    t0: &T,
    h: &T,
    samples: usize,
) -> (T, T, T) {
    let ctx = h.ctx();
    let dist = SegmentDistance::new(curve, points, t0, h);
    let samples = samples.max(2);
    let grid: Vec<T> = (0..=samples)
        .map(|i| T::from_ratio(i as i64, samples as i64, &ctx))
        .collect();
    let values: Vec<T> = grid.iter().map(|x| dist.value(x)).collect();
    let mut sampled_best = 0usize;
    for i in 1..values.len() {
        if values[i] > values[sampled_best] {
            sampled_best = i;
        }
    }
    let mut best = (values[sampled_best].clone(), grid[sampled_best].clone());
    for i in 1..samples {
        if !(values[i] >= values[i - 1] && values[i] >= values[i + 1]) || values[i].is_zero() {
            continue;
        }
        let (f, x) = dist.refine(grid[i].clone(), &grid[i - 1], &grid[i + 1]);
        if f > best.0 {
            best = (f, x);
        }
    }
    (best.0.sqrt(), values[sampled_best].sqrt(), best.1)
}

/// The local maximum of ‖γ_k − p_k‖ near ξ₀ on the segment with control points `points`
/// starting at t0: Newton from ξ₀
/// inside (ξ₀ − w, ξ₀ + w) ∩ (0, 1). Used to recompute a maximum found at one precision at
/// a higher one (certified digits).
pub fn refine_local_max<T: Real, C: Curve<T> + ?Sized>(
    curve: &C,
    points: &[[T; 3]],
    t0: &T,
    h: &T,
    xi0: &T,
    width: &T,
) -> (T, T) {
    let ctx = h.ctx();
    let dist = SegmentDistance::new(curve, points, t0, h);
    let lo = crate::scalar::max_of(xi0.clone() - width, T::zero_in(&ctx));
    let hi = xi0.clone() + width;
    let hi = if hi > T::one_in(&ctx) {
        T::one_in(&ctx)
    } else {
        hi
    };
    let (f, x) = dist.refine(xi0.clone(), &lo, &hi);
    (f.sqrt(), x)
}

/// An approximation error computed at p bits over all segments and recomputed at a higher
/// precision on the segment and near the parameter where the maximum was found.
#[derive(Clone, Debug)]
pub struct CertifiedError {
    /// The maximum at p bits (all segments sampled and refined).
    pub lo: Float,
    /// The same local maximum at the higher precision.
    pub hi: Float,
    /// The sampled maximum at p bits.
    pub sampled: Float,
    /// The segment of the local maximum.
    pub segment: usize,
    /// The local parameter ξ of the local maximum.
    pub xi: Float,
}

impl CertifiedError {
    /// The error with the digits the two precisions agree on.
    pub fn certified(&self) -> Certified {
        certify(&self.lo, &self.hi)
    }
}

/// The error of the approximation `fit` builds, at `bits` over all segments, then the same
/// local maximum recomputed from a fit at `hi_bits` (see [`CertifiedError`]). `make` builds
/// the curve at a precision (numbers rounded once into it).
///
/// When `fit` does not split both curves into the same segments, the maximum at `hi_bits` is
/// searched again over every segment rather than refined on the segment found at `bits`.
///
/// # Errors
/// The first error of `fit`: on the curve built at `bits`, else on the curve at `hi_bits`.
pub fn certified_max_error<C: Curve<Float>, P: BernsteinPieces<Float>, E>(
    make: impl Fn(u32) -> C,
    fit: impl Fn(&C, u32) -> Result<P, E>,
    bits: u32,
    hi_bits: u32,
) -> Result<CertifiedError, E> {
    let lo_curve = make(bits);
    let lo_fit = fit(&lo_curve, bits)?;
    let e = conversion_error(&lo_curve, &lo_fit, DEFAULT_SAMPLES);
    let hi_curve = make(hi_bits);
    let hi_fit = fit(&hi_curve, hi_bits)?;
    let k = e.segment;
    if hi_fit.count() != lo_fit.count() {
        // Not the same partition at both precisions: the maximum is searched again over the
        // whole fit at hi_bits instead of refined on the segment found at bits.
        let hi = conversion_error(&hi_curve, &hi_fit, DEFAULT_SAMPLES);
        return Ok(CertifiedError {
            lo: e.max,
            hi: hi.max,
            sampled: e.sampled,
            segment: e.segment,
            xi: e.xi,
        });
    }
    Ok(recertify(
        e,
        &hi_curve,
        &hi_fit.control_points(k),
        (&hi_fit.knot(k), &hi_fit.step()),
    ))
}

/// The maximum `e` found at p bits, recomputed on its segment (control points `points` on
/// [t0, t0 + h], all at the higher precision) by Newton from the same ξ within one sample
/// interval: the [`CertifiedError`] of the two.
pub fn recertify<C: Curve<Float> + ?Sized>(
    e: ConversionError<Float>,
    hi_curve: &C,
    points: &[[Float; 3]],
    (t0, h): (&Float, &Float),
) -> CertifiedError {
    let bits = h.prec();
    let xi_hi = Float::with_val(bits, &e.xi);
    let width = Float::from_ratio(1, DEFAULT_SAMPLES as i64, &bits);
    let (hi, _) = refine_local_max(hi_curve, points, t0, h, &xi_hi, &width);
    CertifiedError {
        lo: e.max,
        hi,
        sampled: e.sampled,
        segment: e.segment,
        xi: e.xi,
    }
}
