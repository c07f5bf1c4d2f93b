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

use super::hermite::{interpolate, FreeParameters, HermiteData, PhHermiteError};
use super::{bernstein_jet, PhCurve};
use crate::curve::approx::recertify;
use crate::curve::approx::SegmentDistance;
pub use crate::curve::approx::{
    conversion_error, knot, refine_local_max, BernsteinPieces, CertifiedError, ConversionError,
    DEFAULT_SAMPLES,
};
use crate::curve::taylor::Taylor;
use crate::curve::Curve;
use crate::numeric::quat::{vec3, Quat};
use crate::scalar::ball::carried;
use crate::scalar::{BigRational, Field, Float, Real};
use rayon::prelude::*;

/// A curve converted on N uniform segments of [a, b].
#[derive(Clone, Debug)]
pub struct PiecewisePh<T> {
    /// The start of the interval.
    pub a: T,
    /// The end of the interval.
    pub b: T,
    /// The PH curve of each segment, in order.
    pub segments: Vec<PhCurve<T>>,
}

impl<T: Real> PiecewisePh<T> {
    /// Segment length h = (b − a)/N.
    pub fn step(&self) -> T {
        let ctx = self.a.ctx();
        (self.b.clone() - &self.a) / &T::from_i64(self.segments.len() as i64, &ctx)
    }
    /// The start t_k = a + k h of segment k (computed as a + (b − a)k/N).
    pub fn knot(&self, k: usize) -> T {
        knot(&self.a, &self.b, self.segments.len(), k)
    }
    /// The segment containing t and the local parameter ξ ∈ [0, 1] (clamped to [a, b]).
    pub fn locate(&self, t: &T) -> (usize, T) {
        let ctx = t.ctx();
        let n = self.segments.len();
        let u = (t.clone() - &self.a) / &self.step();
        let mut k = 0usize;
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
        k = k.max(lo);
        let xi = u - &T::from_i64(k as i64, &ctx);
        (k, xi)
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
    a: &T,
    b: &T,
    segments: usize,
    m: usize,
) -> Vec<HermiteData<T>> {
    let ctx = a.ctx();
    let h = (b.clone() - a) / &T::from_i64(segments as i64, &ctx);
    let jets: Vec<Vec<[T; 3]>> = (0..=segments)
        .into_par_iter()
        .map(carried(|k| {
            segment_jet(curve, &knot(a, b, segments, k), &h, m)
        }))
        .collect();
    (0..segments)
        .map(|k| HermiteData::from_jets(&jets[k], &jets[k + 1]))
        .collect()
}

/// Convert `curve` on `segments` uniform pieces of [a, b] with C^m interpolants (m = 4:
/// PHODCOS; m = 2: the C² baseline) and free parameters `free` on every segment; with
/// `roll`, apply the roll correction of Eq. (22) so A, R and ω are continuous.
///
/// # Errors
/// [`PhHermiteError::NoSegments`] for `segments` = 0, [`PhHermiteError::Interval`] unless
/// a < b, [`PhHermiteError::NotFinite`] where the curve or its derivatives are not finite at
/// a segment end (e.g. `sqrt(t − 10)` on [0, 1]), or the first segment's interpolation error.
pub fn convert<T: Real, C: Curve<T> + ?Sized>(
    curve: &C,
    a: &T,
    b: &T,
    segments: usize,
    m: usize,
    free: &FreeParameters<T>,
    roll: bool,
) -> Result<PiecewisePh<T>, PhHermiteError> {
    if segments == 0 {
        return Err(PhHermiteError::NoSegments);
    }
    if a.partial_cmp(b) != Some(std::cmp::Ordering::Less) {
        return Err(PhHermiteError::Interval);
    }
    let data = segment_data(curve, a, b, segments, m);
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
    if roll {
        align_roll(&mut pieces);
    }
    Ok(PiecewisePh {
        a: a.clone(),
        b: b.clone(),
        segments: pieces,
    })
}

/// Make the preimage continuous at every joint (Eq. 22, as a right product): segment k+1
/// is multiplied on the right by the unit Q(α) = cos α + i sin α with A_{k+1}(0) Q(α) = A_k(1).
pub fn align_roll<T: Real>(segments: &mut [PhCurve<T>]) {
    for k in 1..segments.len() {
        let end = segments[k - 1].preimage.last().expect("preimage").clone();
        let start = &segments[k].preimage[0];
        // A_{k+1}(0)* A_k(1) = |A|² Q(α) when both solve X i X* = v; drop the j, k parts
        // left by rounding so the correction commutes with i exactly.
        let q = start.conj().mul(&end);
        let ctx = q.ctx();
        let len = (q.w.clone() * &q.w + &(q.x.clone() * &q.x)).sqrt();
        if len.is_zero() {
            continue;
        }
        let inv = T::one_in(&ctx) / &len;
        let z = T::zero_in(&ctx);
        let rot = Quat::new(q.w.clone() * &inv, q.x.clone() * &inv, z.clone(), z);
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
pub fn phodcos<T: Real, C: Curve<T> + ?Sized>(
    curve: &C,
    a: &T,
    b: &T,
    tolerance: &T,
    max_segments: usize,
) -> Result<Option<Converted<T>>, PhHermiteError> {
    let ctx = a.ctx();
    let free = FreeParameters::zero(4, &ctx);
    let attempt = |n: usize| -> Result<(PiecewisePh<T>, ConversionError<T>), PhHermiteError> {
        let pw = convert(curve, a, b, n, 4, &free, true)?;
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
                if jump > jumps[j] {
                    jumps[j] = jump;
                }
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

/// The distances |γ(t) − p(t)| at the global parameters `ts` (each in [a, b]), in order:
/// what a sampled evaluation of the error measures.
pub fn grid_distances<T: Real, C: Curve<T> + ?Sized>(
    curve: &C,
    pw: &PiecewisePh<T>,
    ts: &[T],
) -> Vec<T> {
    let h = pw.step();
    let mut per_segment: Vec<Vec<(usize, T)>> = vec![Vec::new(); pw.segments.len()];
    for (i, t) in ts.iter().enumerate() {
        // locate puts t = b at ξ = 1 of the last segment.
        let (k, xi) = pw.locate(t);
        per_segment[k].push((i, xi));
    }
    let found: Vec<Vec<(usize, T)>> = pw
        .segments
        .par_iter()
        .enumerate()
        .map(carried(|(k, seg): (usize, &PhCurve<T>)| {
            if per_segment[k].is_empty() {
                return Vec::new();
            }
            let dist = SegmentDistance::new(curve, &seg.control_points(), &pw.knot(k), &h);
            per_segment[k]
                .iter()
                .map(|(i, xi)| (*i, dist.value(xi).sqrt()))
                .collect()
        }))
        .collect();
    let mut out = vec![T::zero_in(&h.ctx()); ts.len()];
    for (i, d) in found.into_iter().flatten() {
        out[i] = d;
    }
    out
}

/// The largest of [`grid_distances`]: the error as a maximum over sample points, which can
/// only be below the true maximum of [`conversion_error`].
pub fn grid_error<T: Real, C: Curve<T> + ?Sized>(curve: &C, pw: &PiecewisePh<T>, ts: &[T]) -> T {
    grid_distances(curve, pw, ts)
        .into_iter()
        .fold(T::zero_in(&pw.a.ctx()), |m, d| if d > m { d } else { m })
}

/// A uniform piecewise conversion of `curve` on [a, b] (given exactly) at `bits`, without the
/// roll correction (positions do not depend on it).
fn convert_at<C: Curve<Float>>(
    curve: &C,
    (a, b): (&BigRational, &BigRational),
    segments: usize,
    m: usize,
    free: &FreeParameters<BigRational>,
    bits: u32,
) -> Result<PiecewisePh<Float>, PhHermiteError> {
    let (a, b) = (
        Float::from_rational(a, &bits),
        Float::from_rational(b, &bits),
    );
    let free = free.map(|x| Float::from_rational(x, &bits));
    convert(curve, &a, &b, segments, m, &free, false)
}

/// Segment k of that conversion alone, at `bits`: the PH curve, its start t_k and the step h.
fn segment_at<C: Curve<Float>>(
    curve: &C,
    (a, b): (&BigRational, &BigRational),
    (segments, k): (usize, usize),
    m: usize,
    free: &FreeParameters<BigRational>,
    bits: u32,
) -> Result<(PhCurve<Float>, Float, Float), PhHermiteError> {
    let (a, b) = (
        Float::from_rational(a, &bits),
        Float::from_rational(b, &bits),
    );
    let free = free.map(|x| Float::from_rational(x, &bits));
    let h = (b.clone() - &a) / &Float::from_i64(segments as i64, &bits);
    let jet_at = |j: usize| segment_jet(curve, &knot(&a, &b, segments, j), &h, m);
    let seg = interpolate(&HermiteData::from_jets(&jet_at(k), &jet_at(k + 1)), &free)?;
    Ok((seg, knot(&a, &b, segments, k), h))
}

/// The maximum of ‖γ − p‖ over the grid `ts` of [a, b], certified like [`certified_error`]:
/// every point at `bits`, then the points whose distance comes within the evaluation noise of
/// the largest (2^(10−bits) relative to the curve's size) again at `hi_bits`, each on its
/// segment interpolated at `hi_bits`. Returns the two maxima.
pub fn certified_grid_error<C: Curve<Float>>(
    make: impl Fn(u32) -> C,
    interval: (&BigRational, &BigRational),
    segments: usize,
    m: usize,
    free: &FreeParameters<BigRational>,
    ts: &[BigRational],
    (bits, hi_bits): (u32, u32),
) -> Result<(Float, Float), PhHermiteError> {
    let lo_curve = make(bits);
    let pw = convert_at(&lo_curve, interval, segments, m, free, bits)?;
    let ts_lo: Vec<Float> = ts.iter().map(|q| Float::from_rational(q, &bits)).collect();
    let d = grid_distances(&lo_curve, &pw, &ts_lo);
    let max_lo = d
        .iter()
        .fold(Float::new(bits), |m, x| if *x > m { x.clone() } else { m });
    let size = vec3::norm(&lo_curve.jet(&pw.a, 0)[0]).max(&Float::with_val(bits, 1));
    let noise = size * Float::with_val(bits, Float::i_exp(1, 10 - bits as i32));
    let hi_curve = make(hi_bits);
    let mut max_hi = Float::new(hi_bits);
    for (i, _) in d
        .iter()
        .enumerate()
        .filter(|(_, x)| **x >= max_lo.clone() - &noise)
    {
        let (k, _) = pw.locate(&ts_lo[i]);
        let (seg, t0, h) = segment_at(&hi_curve, interval, (segments, k), m, free, hi_bits)?;
        // ξ exactly: (t − t_k)/h from the rational t.
        let xi_hi = (Float::from_rational(&ts[i], &hi_bits) - &t0) / &h;
        let value = SegmentDistance::new(&hi_curve, &seg.control_points(), &t0, &h)
            .value(&xi_hi)
            .sqrt();
        if value > max_hi {
            max_hi = value;
        }
    }
    Ok((max_lo, max_hi))
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
#[allow(clippy::too_many_arguments)]
pub fn certified_error<C: Curve<Float>>(
    make: impl Fn(u32) -> C,
    a: &BigRational,
    b: &BigRational,
    segments: usize,
    m: usize,
    free: &FreeParameters<BigRational>,
    bits: u32,
    hi_bits: u32,
) -> Result<CertifiedError, PhHermiteError> {
    let lo_curve = make(bits);
    let pw = convert_at(&lo_curve, (a, b), segments, m, free, bits)?;
    let e = conversion_error(&lo_curve, &pw, DEFAULT_SAMPLES);
    let hi_curve = make(hi_bits);
    let k = e.segment;
    let (seg, t0, h) = segment_at(&hi_curve, (a, b), (segments, k), m, free, hi_bits)?;
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
        let pw = convert(&c, &0.0, &1.0, n, 4, &FreeParameters::zero(4, &()), false).unwrap();
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
