//! Piecewise PH conversion of a curve (paper 001, Sec. 5E–F, Algorithm 2) and its error.
//!
//! The interval [a, b] is split into N uniform segments of length h. On segment k the curve
//! γ_k(ξ) = γ(t_k + hξ), ξ ∈ [0, 1], gives Hermite data with derivatives h^j γ⁽ʲ⁾(t_k) (the
//! paper's Eq. 20), interpolated by [`super::hermite::interpolate`]. Successive segments then
//! share A i A* at the joint, so their preimages differ by a roll A_{k+1}(0) = A_k(1) Q(β)
//! (Sec. 5E). [`align_roll`] multiplies every control point of segment k+1 on the right by
//! Q(−β) (Eq. 22): right multiplication by cos α + i sin α commutes with i, so the hodograph
//! and the curve are unchanged while A, R and ω become continuous. (Eq. 22b prints a left
//! product A_α A_i, which would rotate the curve; see the claims.)
//!
//! The conversion error E = max_ξ ‖γ(ξ) − p(ξ)‖ (Eqs. 2, 21) is computed as a true maximum by
//! [`crate::curve::approx`] (sampling, then Newton on f′ = 0), which measures any piecewise
//! Bernstein approximant; [`PiecewisePh`] is one ([`BernsteinPieces`]). Here: the paper's grid
//! maximum and the certified error of a conversion, recomputed on one segment at 2p bits.

use super::grid::evaluation_noise;
pub use super::grid::{certified_grid_error, grid_distances, grid_error, ErrorScreen};
use super::hermite::{interpolate, FreeParameters, HermiteData, PhHermiteError};
use super::{bernstein_jet, PhCurve};
use crate::curve::approx::recertify;
pub use crate::curve::approx::{
    conversion_error, conversion_error_among, knot, refine_local_max, BernsteinPieces,
    CertifiedError, ConversionError, DEFAULT_SAMPLES,
};
use crate::curve::approx::{locate, locate_in_domain, pieces_breakpoints, pieces_derivatives};
use crate::curve::interval::Interval;
use crate::curve::parametric::{CurveError, Frame, ParamCurve, ParamCurveArclen, ParamCurveFrame};
use crate::curve::taylor::Taylor;
use crate::curve::Curve;
use crate::numeric::quat::{vec3, Quat};
use crate::scalar::ball::carried;
use crate::scalar::{BigRational, Field, Float, Real};
use rayon::prelude::*;

/// A curve converted on N ≥ 1 uniform segments of [a, b], a < b (built by [`fit`] or
/// [`convert`]; the fields are private so that no value breaks these invariants). As a curve
/// of t ∈ [a, b] it implements [`ParamCurve`], [`ParamCurveArclen`] (exactly, from the
/// polynomial speed) and [`ParamCurveFrame`] (the Euler–Rodrigues frame).
#[derive(Clone, Debug)]
pub struct PiecewisePh<T> {
    a: T,
    b: T,
    segments: Vec<PhCurve<T>>,
}

impl<T: Real> PiecewisePh<T> {
    /// The start a of the interval.
    pub fn start(&self) -> &T {
        &self.a
    }
    /// The end b of the interval.
    pub fn end(&self) -> &T {
        &self.b
    }
    /// The PH curve of each segment, in order, each in its local parameter ξ ∈ [0, 1].
    pub fn segments(&self) -> &[PhCurve<T>] {
        &self.segments
    }
    /// The same conversion with every number mapped by `f` ([`PhCurve::map`]).
    pub fn map<U: Real>(&self, f: impl Fn(&T) -> U) -> PiecewisePh<U> {
        PiecewisePh {
            a: f(&self.a),
            b: f(&self.b),
            segments: self.segments.iter().map(|s| s.map(&f)).collect(),
        }
    }
    /// Apply the roll correction of Eq. (22) ([`align_roll`]) to every joint.
    pub fn align_roll(&mut self) {
        align_roll(&mut self.segments);
    }
    /// Segment length h = (b − a)/N.
    pub fn step(&self) -> T {
        let ctx = self.a.ctx();
        (self.b.clone() - &self.a) / &T::from_i64(self.segments.len() as i64, &ctx)
    }
    /// The knot t_k = a + k h, k = 0 … N (computed as a + (b − a)k/N; t_N = b).
    ///
    /// # Errors
    /// [`CurveError::Index`] (field `k`) for k > N.
    pub fn knot(&self, k: usize) -> Result<T, CurveError> {
        let n = self.segments.len();
        if k > n {
            return Err(CurveError::Index {
                field: "k",
                index: k,
                max: n,
            });
        }
        Ok(knot((&self.a, &self.b), n, k))
    }
    /// The segment containing t ∈ [a, b] and the local parameter ξ ∈ [0, 1] (at a joint, the
    /// segment that starts there; at b, the last one).
    ///
    /// # Errors
    /// [`CurveError::OutsideDomain`] for t outside [a, b] or NaN.
    pub fn locate(&self, t: &T) -> Result<(usize, T), CurveError> {
        crate::curve::approx::locate_in_domain(self, t)
    }

    /// [`PiecewisePh::locate`] with t clamped to [a, b] (for grids whose points the caller
    /// built inside it).
    pub(crate) fn locate_clamped(&self, t: &T) -> (usize, T) {
        locate(self, t)
    }
}

impl<T: Real> BernsteinPieces<T> for PiecewisePh<T> {
    fn interval(&self) -> (&T, &T) {
        (&self.a, &self.b)
    }
    fn count(&self) -> usize {
        self.segments.len()
    }
    fn control_points(&self, k: usize) -> Vec<[T; 3]> {
        self.segments[k].control_points()
    }
}

/// γ(t), h γ′(t), …, h^m γ⁽ᵐ⁾(t): the jet in the local parameter of a segment of length h
/// (Eq. 20).
pub fn segment_jet<T: Real, C: Curve<T> + ?Sized>(
    curve: &C,
    t: &T,
    h: &T,
    m: usize,
) -> Vec<[T; 3]> {
    let mut jet = curve.jet(t, m);
    let mut scale = T::one_in(&h.ctx());
    for d in jet.iter_mut().skip(1) {
        scale *= h;
        *d = vec3::scale(d, &scale);
    }
    jet
}

/// The Hermite data of every segment: derivatives 1…m scaled by h^j (Eq. 20).
pub fn segment_data<T: Real, C: Curve<T> + ?Sized>(
    curve: &C,
    (a, b): (&T, &T),
    segments: usize,
    m: usize,
) -> Vec<HermiteData<T>> {
    let ctx = a.ctx();
    let h = (b.clone() - a) / &T::from_i64(segments as i64, &ctx);
    let jets: Vec<Vec<[T; 3]>> = (0..=segments)
        .into_par_iter()
        .map(carried(|k| {
            segment_jet(curve, &knot((a, b), segments, k), &h, m)
        }))
        .collect();
    // Every jet holds m + 1 ≥ 1 vectors, so from_jets cannot refuse one.
    (0..segments)
        .filter_map(|k| HermiteData::from_jets(&jets[k], &jets[k + 1]).ok())
        .collect()
}

/// Convert `curve` on `segments` uniform pieces of [a, b] with C^m interpolants (m = 4:
/// PHODCOS; m = 2: the C² baseline) and free parameters `free` on every segment; with
/// `roll`, apply the roll correction of Eq. (22) so A, R and ω are continuous.
///
/// [`fit`] with [`FitOptions`] is the entry point with named options and documented
/// defaults; `convert` is the positional form the paper checks use.
///
/// # Errors
/// [`PhHermiteError::NoSegments`] for `segments` = 0, [`PhHermiteError::TooManySegments`]
/// above [`MAX_SEGMENTS`], [`PhHermiteError::Derivatives`] unless
/// 1 ≤ m ≤ [`MAX_DERIVATIVES`], [`PhHermiteError::Overflow`] for an interpolant whose control
/// points are not finite, [`PhHermiteError::Interval`] unless
/// a < b, [`PhHermiteError::NotFinite`] where the curve or its derivatives are not finite at
/// a segment end (e.g. `sqrt(t − 10)` on [0, 1]), or the first segment's interpolation error.
pub fn convert<T: Real, C: Curve<T> + ?Sized>(
    curve: &C,
    (a, b): (&T, &T),
    segments: usize,
    m: usize,
    free: &FreeParameters<T>,
    roll: bool,
) -> Result<PiecewisePh<T>, PhHermiteError> {
    if segments == 0 {
        return Err(PhHermiteError::NoSegments);
    }
    if segments > MAX_SEGMENTS {
        return Err(PhHermiteError::TooManySegments(segments));
    }
    if m == 0 || m > MAX_DERIVATIVES {
        return Err(PhHermiteError::Derivatives(m));
    }
    if a.partial_cmp(b) != Some(std::cmp::Ordering::Less) {
        return Err(PhHermiteError::Interval);
    }
    let data = segment_data(curve, (a, b), segments, m);
    let finite = |v: &[T; 3]| v.iter().all(Field::is_finite);
    if let Some(k) = data.iter().position(|d| {
        !(finite(&d.p_b) && finite(&d.p_e) && d.start.iter().chain(&d.end).all(finite))
    }) {
        return Err(PhHermiteError::NotFinite(k));
    }
    let mut pieces = data
        .par_iter()
        .map(carried(|d| interpolate(d, free)))
        .collect::<Result<Vec<_>, _>>()?;
    let finite_segment = |p: &PhCurve<T>| p.control_points().iter().all(finite);
    if let Some(k) = pieces.iter().position(|p| !finite_segment(p)) {
        return Err(PhHermiteError::Overflow(k));
    }
    if roll {
        align_roll(&mut pieces);
    }
    Ok(PiecewisePh {
        a: a.clone(),
        b: b.clone(),
        segments: pieces,
    })
}

/// Options of [`fit`], with `Default` the paper's choices (Sec. 5F): C⁴ joints, φ* = 0,
/// the roll correction on, 8 segments.
#[derive(Clone, Debug, PartialEq)]
pub struct FitOptions<T> {
    /// The number N of uniform segments, or with `tolerance` the first N tried. Default 8.
    pub segments: usize,
    /// When set, N is doubled (from `segments`, up to [`MAX_FIT_SEGMENTS`]) until the
    /// conversion error E (Eq. 21; [`conversion_error`], a sampled maximum refined by
    /// Newton's method: an estimate, not a bound) is at most this. Default `None`.
    pub tolerance: Option<T>,
    /// The derivatives m matched at every joint (the spline is Cᵐ, degree 2m + 1). Default 4.
    pub derivatives: usize,
    /// The free parameters of Algorithm 1 (θ and τ); `None`, the default, is φ* = 0.
    pub free: Option<FreeParameters<T>>,
    /// Apply the roll correction (Eq. 22) so A, the frame and ω are continuous. Default true.
    pub roll: bool,
}

impl<T> Default for FitOptions<T> {
    fn default() -> Self {
        FitOptions {
            segments: 8,
            tolerance: None,
            derivatives: 4,
            free: None,
            roll: true,
        }
    }
}

/// The most derivatives m a conversion matches at a joint: the weights of Algorithm 1 are
/// tabulated in `i64` (their falling factorials overflow from m = 13) and the preimage
/// degree 2m + 1 must stay within `MAX_PREIMAGE_DEGREE`.
pub const MAX_DERIVATIVES: usize = 12;

/// The most segments [`fit`] tries for a tolerance.
pub const MAX_FIT_SEGMENTS: usize = 1 << 14;

/// The most segments a conversion builds (64 times Table 1's largest row; each segment holds
/// its preimage and control points, so far more would only exhaust memory).
pub const MAX_SEGMENTS: usize = 1 << 19;

/// The piecewise PH spline of `curve` on [a, b] (Algorithm 2), with the number of segments,
/// the continuity and the free parameters of `options`.
///
/// # Errors
/// Those of [`convert`]; [`PhHermiteError::FreeCount`] for free parameters not sized for
/// `options.derivatives`; [`PhHermiteError::BadTolerance`] for a tolerance that is not
/// positive and finite; [`PhHermiteError::Tolerance`] when no N ≤ [`MAX_FIT_SEGMENTS`]
/// meets the tolerance.
///
/// # Examples
/// The helix (cos t, sin t, t/5) on [0, 6] with 32 C⁴ segments, in f64 and in MPFR:
/// ```
/// use trajverify::algo::ph::piecewise::{fit, FitOptions};
/// use trajverify::curve::parametric::{ParamCurve, ParamCurveArclen};
/// use trajverify::curve::ExprCurve;
/// use trajverify::scalar::Float;
///
/// let helix = ExprCurve::parse("[cos(t), sin(t), t/5]").unwrap();
/// let options = FitOptions { segments: 32, ..FitOptions::default() };
/// let spline = fit(&helix.compile::<f64>(&()), (&0.0, &6.0), &options).unwrap();
/// let length = spline.length().unwrap(); // exact for the PH spline: 6·√(1 + 1/25)
/// assert!((length - 6.0 * 1.04f64.sqrt()).abs() < 1e-6);
///
/// let (a, b) = (Float::with_val(256, 0), Float::with_val(256, 6));
/// let precise = fit(&helix.compile::<Float>(&256), (&a, &b), &FitOptions::default()).unwrap();
/// let p = precise.point(&Float::with_val(256, 3)).unwrap();
/// assert!((p[0].to_f64() - 3f64.cos()).abs() < 1e-5);
/// ```
pub fn fit<T: Real, C: Curve<T> + ?Sized>(
    curve: &C,
    (a, b): (&T, &T),
    options: &FitOptions<T>,
) -> Result<PiecewisePh<T>, PhHermiteError> {
    let m = options.derivatives;
    if m == 0 || m > MAX_DERIVATIVES {
        return Err(PhHermiteError::Derivatives(m));
    }
    if let Some(tol) = &options.tolerance {
        if !(tol.is_finite() && *tol > T::zero_in(&tol.ctx())) {
            return Err(PhHermiteError::BadTolerance);
        }
    }
    let free = match &options.free {
        Some(f) => f.clone(),
        None => FreeParameters::zero(m, &a.ctx()),
    };
    let mut n = options.segments;
    loop {
        crate::cancel::checkpoint();
        let pw = convert(curve, (a, b), n, m, &free, options.roll)?;
        let Some(tol) = &options.tolerance else {
            return Ok(pw);
        };
        let error = conversion_error(curve, &pw, DEFAULT_SAMPLES).max;
        if error <= *tol {
            return Ok(pw);
        }
        if n >= MAX_FIT_SEGMENTS {
            return Err(PhHermiteError::Tolerance(n, error.to_f64()));
        }
        n = (2 * n).min(MAX_FIT_SEGMENTS);
    }
}

/// The antiderivative ∫₀^ξ σ of a Bernstein polynomial σ of degree m (coefficients σ_i):
/// the Bernstein polynomial of degree m + 1 with coefficients c_0 = 0,
/// c_{i+1} = c_i + σ_i/(m + 1), evaluated at ξ.
fn integral_to<T: Real>(sigma: &[T], xi: &T) -> T {
    let ctx = xi.ctx();
    let inv = T::one_in(&ctx) / &T::from_i64(sigma.len() as i64, &ctx);
    let mut c = vec![[T::zero_in(&ctx)]];
    for s in sigma {
        let next = c[c.len() - 1][0].clone() + &(s.clone() * &inv);
        c.push([next]);
    }
    bernstein_jet(&c, xi, 0).swap_remove(0)[0].clone()
}

impl<T: Real> ParamCurve<T, 3> for PiecewisePh<T> {
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

impl<T: Real> ParamCurveArclen<T, 3> for PiecewisePh<T> {
    /// Exact up to rounding: the lengths of the segments before t (each the mean of its
    /// speed coefficients, Eq. 13a) plus ∫₀^ξ σ of the segment holding t.
    fn arc_length(&self, t: &T) -> Result<T, CurveError> {
        let (k, xi) = locate_in_domain(self, t)?;
        let mut total = T::zero_in(&t.ctx());
        for segment in &self.segments[..k] {
            total += &segment.arc_length();
        }
        Ok(total + &integral_to(&self.segments[k].speed_coefficients(), &xi))
    }
}

impl<T: Real> ParamCurveFrame<T> for PiecewisePh<T> {
    /// The Euler–Rodrigues frame (Eq. 11) and ω (Eq. 12) divided by h, per unit of t.
    fn frame(&self, t: &T) -> Result<Frame<T>, CurveError> {
        let (k, xi) = locate_in_domain(self, t)?;
        let h = self.step();
        let segment = &self.segments[k];
        let state = segment.frame_state(&segment.control_points(), &xi);
        if state.speed.is_zero() {
            return Err(CurveError::Frame {
                t: t.to_f64(),
                reason: "the preimage A(ξ) is zero".into(),
            });
        }
        Ok(Frame {
            point: state.point,
            axes: state.frame,
            omega: state.omega.map(|w| w / &h),
            speed: state.speed / &h,
        })
    }
}

/// Make the preimage continuous at every joint (Eq. 22, as a right product): segment k+1
/// is multiplied on the right by the unit Q(α) = cos α + i sin α with A_{k+1}(0) Q(α) = A_k(1).
///
/// For balls the rotations are chained from the segments as converted: the joint's own
/// rotation r_k = A_{k+1}(0)* A_k(1)/|·| (both unrotated) times the rotation C_k already
/// applied to segment k, since A_{k+1}(0)*·A_k(1)C_k = (A_{k+1}(0)* A_k(1))·C_k. Reading the
/// already rotated end instead, as floating point does, makes each joint's ball wider than
/// the last by a constant factor, so past a few hundred segments the rotation's normalisation
/// divides by a ball around 0; chained on unit rotations, the radii grow by at most √2 per
/// joint. Floating point keeps the direct form, whose roundings the reports were made with.
pub fn align_roll<T: Real>(segments: &mut [PhCurve<T>]) {
    // Balls: segment k−1's end as converted, and the rotation C_{k−1} applied to it.
    let mut converted_end = segments.first().and_then(|s| s.preimage.last().cloned());
    let mut applied: Option<Quat<T>> = None;
    for k in 1..segments.len() {
        let next_converted_end = segments[k].preimage.last().cloned();
        let end = if T::ENCLOSURE {
            converted_end.take()
        } else {
            segments[k - 1].preimage.last().cloned()
        };
        converted_end = next_converted_end;
        let Some(end) = end else { continue };
        let start = &segments[k].preimage[0];
        // A_{k+1}(0)* A_k(1) = |A|² Q(α) when both solve X i X* = v; drop the j, k parts
        // left by rounding so the correction commutes with i exactly.
        let q = start.conj().mul(&end);
        let ctx = q.ctx();
        let len = (q.w.clone() * &q.w + &(q.x.clone() * &q.x)).sqrt();
        if len.is_zero() {
            applied = None;
            continue;
        }
        let inv = T::one_in(&ctx) / &len;
        let z = T::zero_in(&ctx);
        let mut rot = Quat::new(q.w.clone() * &inv, q.x.clone() * &inv, z.clone(), z);
        if T::ENCLOSURE {
            if let Some(c) = &applied {
                rot = rot.mul(c);
            }
            applied = Some(rot.clone());
        }
        for a in segments[k].preimage.iter_mut() {
            *a = a.mul(&rot);
        }
    }
}

/// A conversion and its error.
pub type Converted<T> = (PiecewisePh<T>, ConversionError<T>);

/// Algorithm 2: the smallest number of segments (found by doubling from `start`, then
/// bisection) whose conversion error is below `tolerance`, at most `max_segments`.
///
/// The printed algorithm increases N by one from 2; with E = O(h⁶) doubling reaches the
/// tolerance in a few steps and bisection then finds the smallest N that meets it, assuming
/// the error decreases with N between the bracketing powers of two (the paper notes the update
/// strategy "could be further tailored").
///
/// # Errors
/// Those of [`convert`] (m = 4, φ* = 0) at the first N tried that fails; no N ≤ `max_segments`
/// meeting the tolerance is `Ok(None)`, not an error.
pub fn phodcos<T: Real, C: Curve<T> + ?Sized>(
    curve: &C,
    (a, b): (&T, &T),
    tolerance: &T,
    max_segments: usize,
) -> Result<Option<Converted<T>>, PhHermiteError> {
    let ctx = a.ctx();
    let free = FreeParameters::zero(4, &ctx);
    let attempt = |n: usize| -> Result<(PiecewisePh<T>, ConversionError<T>), PhHermiteError> {
        let pw = convert(curve, (a, b), n, 4, &free, true)?;
        let e = conversion_error(curve, &pw, DEFAULT_SAMPLES);
        Ok((pw, e))
    };
    let mut n = 1usize;
    let mut last_fail = 0usize;
    let found = loop {
        let r = attempt(n)?;
        if r.1.max < *tolerance {
            break r;
        }
        last_fail = n;
        if n >= max_segments {
            return Ok(None);
        }
        n = (2 * n).min(max_segments);
    };
    let (mut lo, mut hi, mut best) = (last_fail, n, found);
    while hi - lo > 1 {
        let mid = (lo + hi) / 2;
        let r = attempt(mid)?;
        if r.1.max < *tolerance {
            hi = mid;
            best = r;
        } else {
            lo = mid;
        }
    }
    Ok(Some(best))
}

/// Continuity at the joints: for each derivative order j, the largest jump of a function of
/// the preimage between the end of segment k and the start of segment k+1, in the global
/// parameter (local derivatives divided by h^j). `f` maps A as Taylor series of order
/// `series_order` to the components of interest; their length sets how many orders are
/// compared.
pub fn joint_jumps<T: Real>(
    pw: &PiecewisePh<T>,
    series_order: usize,
    f: impl Fn(&Quat<Taylor<T>>) -> Vec<Taylor<T>>,
) -> Vec<T> {
    let ctx = pw.a.ctx();
    let h = pw.step();
    let mut jumps: Vec<T> = Vec::new();
    let (zero, one) = (T::zero_in(&ctx), T::one_in(&ctx));
    for k in 1..pw.segments.len() {
        let left = f(&pw.segments[k - 1].preimage_taylor(&one, series_order));
        let right = f(&pw.segments[k].preimage_taylor(&zero, series_order));
        for (l, r) in left.iter().zip(&right) {
            let (dl, dr) = (l.derivatives(), r.derivatives());
            if jumps.len() < dl.len() {
                jumps.resize(dl.len(), T::zero_in(&ctx));
            }
            let mut scale = T::one_in(&ctx);
            for j in 0..dl.len().min(dr.len()) {
                if j > 0 {
                    scale /= &h;
                }
                let jump = (dl[j].clone() - &dr[j]).abs() * &scale;
                // An enclosure of the maximum in balls: no comparison to decide.
                jumps[j] = jumps[j].max_with(&jump);
            }
        }
    }
    jumps
}

/// The three components of ω = 2 vec(A′A*)/|A|² (Eq. 12) as series one order shorter than A.
pub fn omega_components<T: Field>(a: &Quat<Taylor<T>>) -> Vec<Taylor<T>> {
    let da = Quat::new(
        a.w.derivative_series(),
        a.x.derivative_series(),
        a.y.derivative_series(),
        a.z.derivative_series(),
    );
    let (_, omega) = super::frame_and_omega(a, &da);
    omega.to_vec()
}

/// The components of A (for [`joint_jumps`]).
pub fn preimage_components<T: Field>(a: &Quat<T>) -> Vec<T> {
    a.components().to_vec()
}

/// The nine entries of R = [A i A*, A j A*, A k A*]/|A|² (Eq. 11).
pub fn frame_entries<T: Field>(a: &Quat<T>) -> Vec<T> {
    let (frame, _) = super::frame_and_omega(a, a);
    frame.into_iter().flatten().collect()
}

/// p at global parameter values from a conversion (for plots and comparisons).
pub fn sample_points<T: Real>(pw: &PiecewisePh<T>, per_segment: usize) -> Vec<[T; 3]> {
    let ctx = pw.a.ctx();
    let mut out = Vec::new();
    for (k, seg) in pw.segments.iter().enumerate() {
        let pts = seg.control_points();
        let first = if k == 0 { 0 } else { 1 };
        for i in first..=per_segment {
            let xi = T::from_ratio(i as i64, per_segment as i64, &ctx);
            out.push(bernstein_jet(&pts, &xi, 0).swap_remove(0));
        }
    }
    out
}

/// A uniform piecewise conversion of `curve` on [a, b] (the ends rounded to `bits` by the
/// caller) at `bits`, without the roll correction (positions do not depend on it).
pub(super) fn convert_at<C: Curve<Float>>(
    curve: &C,
    (a, b): (&Float, &Float),
    segments: usize,
    m: usize,
    free: &FreeParameters<BigRational>,
    bits: u32,
) -> Result<PiecewisePh<Float>, PhHermiteError> {
    let free = free.map(|x| Float::from_rational(x, &bits));
    convert(curve, (a, b), segments, m, &free, false)
}

/// Segment k of that conversion alone, at `bits`: the PH curve, its start t_k and the step h.
pub(super) fn segment_at<C: Curve<Float>>(
    curve: &C,
    (a, b): (&Float, &Float),
    (segments, k): (usize, usize),
    m: usize,
    free: &FreeParameters<BigRational>,
    bits: u32,
) -> Result<(PhCurve<Float>, Float, Float), PhHermiteError> {
    let free = free.map(|x| Float::from_rational(x, &bits));
    let h = (b.clone() - a) / &Float::from_i64(segments as i64, &bits);
    let jet_at = |j: usize| segment_jet(curve, &knot((a, b), segments, j), &h, m);
    let seg = interpolate(&HermiteData::from_jets(&jet_at(k), &jet_at(k + 1))?, &free)?;
    Ok((seg, knot((a, b), segments, k), h))
}

/// The observed convergence between two refinement levels (segments doubled): the ratio
/// E_coarse/E_fine and the observed order log₂ of it (Theorem 1 predicts 6 for C⁴ data).
/// `None` when either error is zero: a curve the method reproduces exactly has no rate.
pub fn observed_order<T: Real>(coarse: &T, fine: &T) -> Option<(T, T)> {
    if coarse.is_zero() || fine.is_zero() {
        return None;
    }
    let ratio = coarse.clone() / fine;
    let order = ratio.log2();
    Some((ratio, order))
}

/// The conversion error of `segments` uniform C^m pieces on [a, b] with free parameters
/// `free`, at `bits` and re-derived at `hi_bits` (see [`CertifiedError`]). `make` builds the
/// curve at a precision (numbers rounded once into it). The location of the maximum is a
/// discrete choice made at `bits`; only its value is recomputed, so the certified digits say
/// how much rounding affected the value, not whether another maximum was missed (the
/// sampling and the refinement are the same at both precisions).
///
/// # Errors
/// Those of [`convert`] at `bits` (a, b rounded to `bits`: an end like 4π is exact in the
/// [`Interval`] and rounded at each precision); those of [`interpolate`] for the
/// maximum's segment rebuilt at `hi_bits` (its data are not checked for finiteness there).
#[allow(clippy::too_many_arguments)]
pub fn certified_error<C: Curve<Float>>(
    make: impl Fn(u32) -> C,
    interval: &Interval,
    segments: usize,
    m: usize,
    free: &FreeParameters<BigRational>,
    bits: u32,
    hi_bits: u32,
) -> Result<CertifiedError, PhHermiteError> {
    certified_error_screened(make, interval, segments, m, free, (bits, hi_bits), None)
}

/// [`certified_error`] that, given an [`ErrorScreen`] of the same conversion, searches only
/// the segments the screen does not prove below the maximum: the same result, from fewer
/// segments (see [`super::grid`]).
///
/// # Errors
/// Those of [`certified_error`].
pub fn certified_error_screened<C: Curve<Float>>(
    make: impl Fn(u32) -> C,
    interval: &Interval,
    segments: usize,
    m: usize,
    free: &FreeParameters<BigRational>,
    (bits, hi_bits): (u32, u32),
    screen: Option<&ErrorScreen>,
) -> Result<CertifiedError, PhHermiteError> {
    let lo_curve = make(bits);
    let (a, b): (Float, Float) = interval.ends(&bits);
    let pw = convert_at(&lo_curve, (&a, &b), segments, m, free, bits)?;
    let reaching = screen.and_then(|screen| {
        let seed = conversion_error_among(&lo_curve, &pw, DEFAULT_SAMPLES, &[screen.seed_segment]);
        let noise = evaluation_noise(&lo_curve, &pw);
        screen.segments_reaching(&seed.sampled, &noise, segments)
    });
    let e = match reaching {
        Some(among) => conversion_error_among(&lo_curve, &pw, DEFAULT_SAMPLES, &among),
        None => conversion_error(&lo_curve, &pw, DEFAULT_SAMPLES),
    };
    let hi_curve = make(hi_bits);
    let k = e.segment;
    let (a, b): (Float, Float) = interval.ends(&hi_bits);
    let (seg, t0, h) = segment_at(&hi_curve, (&a, &b), (segments, k), m, free, hi_bits)?;
    Ok(recertify(e, &hi_curve, &seg.control_points(), (&t0, &h)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::ExprCurve;

    /// A grid maximum is a sampled maximum: on the sample points of `conversion_error` it
    /// equals that function's `sampled` value, it never exceeds the true maximum, and the
    /// certified version agrees with it.
    #[test]
    fn grid_maximum_is_the_sampled_maximum_and_below_the_true_one() {
        let curve = ExprCurve::parse("[cos(3*t), sin(2*t), t^2]").unwrap();
        let c = curve.compile::<f64>(&());
        let (n, samples) = (4usize, DEFAULT_SAMPLES);
        let pw = convert(&c, (&0.0, &1.0), n, 4, &FreeParameters::zero(4, &()), false).unwrap();
        let e = conversion_error(&c, &pw, samples);
        let grid: Vec<BigRational> = (0..=n * samples)
            .map(|i| BigRational::new((i as i64).into(), ((n * samples) as i64).into()))
            .collect();
        let ts: Vec<f64> = grid.iter().map(|q| q.to_f64()).collect();
        let g = grid_error(&c, &pw, &ts);
        assert!(
            (g - e.sampled).abs() <= 1e-12 * e.sampled,
            "{g} vs {}",
            e.sampled
        );
        assert!(g <= e.max, "{g} > {}", e.max);
        let (lo, hi) = certified_grid_error(
            |bits| curve.compile::<Float>(&bits),
            (
                &BigRational::from_integer(0.into()),
                &BigRational::from_integer(1.into()),
            ),
            n,
            4,
            &FreeParameters::zero(4, &()),
            &grid,
            (64, 128),
            None,
        )
        .unwrap();
        assert!((lo.to_f64() - g).abs() <= 1e-9 * g);
        // The two precisions agree to the lower one's noise on a curve of size 1: 2^(10−64).
        assert!(
            (hi.clone() - &lo).abs().to_f64() <= 2f64.powi(10 - 64),
            "{lo} vs {hi}"
        );
    }
}
