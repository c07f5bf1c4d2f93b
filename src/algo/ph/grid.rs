//! The conversion error of paper 001 measured the way the authors' code measures it: the
//! largest distance ‖γ(t) − p(t)‖ over a grid of parameters t (their `phodcos.py` evaluates
//! linspace(1e-6, 1, 100·N)), as opposed to the true maximum over ξ of Eq. (21)
//! ([`super::piecewise::certified_error`]).
//!
//! [`certified_grid_error`] evaluates every grid point at p bits and recomputes at 2p bits
//! the points within the evaluation noise of the largest. With an [`ErrorScreen`] (proven
//! Taylor models of the same conversion's error, [`ErrorModels`]) it evaluates only the points
//! that can reach the maximum: it first evaluates one segment's points (the one where the
//! proven lower bound of the error was found), takes their largest distance L, and keeps
//! only the points lying in the regions where the models do not prove ‖γ − p‖ < L − 4ε
//! (ε the evaluation noise). A skipped point's distance at p bits is then below L − 3ε, so it
//! is neither the maximum nor among the points recomputed at 2p bits, and both maxima are the
//! ones the full grid gives, bit for bit; what it assumes is what the recomputation's own
//! choice of points assumes, that a distance at p bits is within ε of the exact one.
//!
//! The same screen serves the search for the true maximum
//! ([`super::piecewise::certified_error`]): with L the seed segment's largest *sampled*
//! distance, a segment where the models leave no region reaching L − 4ε has every sampled
//! and every refined distance below L − 3ε, so it changes neither the sampled maximum nor
//! the refined one, and is not searched.

use super::hermite::{FreeParameters, PhHermiteError};
use super::piecewise::{convert_at, segment_at, PiecewisePh};
use super::PhCurve;
use crate::curve::approx::{BernsteinPieces, SegmentDistance};
use crate::curve::enclosure::{ErrorModels, Region};
use crate::curve::Curve;
use crate::numeric::quat::vec3;
use crate::scalar::ball::{carried, Ball};
use crate::scalar::{BigRational, Field, Float, Real};
use rayon::prelude::*;
use rug::float::Round;

/// A grid point located on its segment: (index in the grid, segment k, local ξ).
type Located<T> = (usize, usize, T);
/// The grid located in f64 for the screen, and the error bound of those ξ.
type RoughlyLocated = (Vec<Located<f64>>, f64);

/// ‖γ − p‖ at located points, evaluated segment by segment in parallel: (index, segment,
/// distance) in the order of the segments, then of `points`.
fn distances_at<T: Real, C: Curve<T> + ?Sized>(
    curve: &C,
    pw: &PiecewisePh<T>,
    points: &[Located<T>],
) -> Vec<(usize, usize, T)> {
    let h = pw.step();
    let mut per_segment: Vec<Vec<(usize, &T)>> = vec![Vec::new(); pw.segments().len()];
    for (i, k, xi) in points {
        per_segment[*k].push((*i, xi));
    }
    let found: Vec<Vec<(usize, usize, T)>> = pw
        .segments()
        .par_iter()
        .enumerate()
        .map(carried(|(k, seg): (usize, &PhCurve<T>)| {
            if per_segment[k].is_empty() {
                return Vec::new();
            }
            let dist = SegmentDistance::new(
                curve,
                &seg.control_points(),
                &BernsteinPieces::knot(pw, k),
                &h,
            );
            per_segment[k]
                .iter()
                .map(|(i, xi)| (*i, k, dist.value(xi).sqrt()))
                .collect()
        }))
        .collect();
    found.into_iter().flatten().collect()
}

/// The grid `ts` located on the segments of `pw` (t = b at ξ = 1 of the last segment).
fn located<T: Real>(pw: &PiecewisePh<T>, ts: &[T]) -> Vec<Located<T>> {
    ts.iter()
        .enumerate()
        .map(|(i, t)| {
            let (k, xi) = pw.locate_clamped(t);
            (i, k, xi)
        })
        .collect()
}

/// The distances |γ(t) − p(t)| at the global parameters `ts` (each in [a, b]), in order:
/// what a sampled evaluation of the error measures.
pub fn grid_distances<T: Real, C: Curve<T> + ?Sized>(
    curve: &C,
    pw: &PiecewisePh<T>,
    ts: &[T],
) -> Vec<T> {
    let mut out = vec![T::zero_in(&pw.step().ctx()); ts.len()];
    for (i, _, d) in distances_at(curve, pw, &located(pw, ts)) {
        out[i] = d;
    }
    out
}

/// The largest of [`grid_distances`]: the error as a maximum over sample points, which can
/// only be below the true maximum of [`super::piecewise::conversion_error`].
pub fn grid_error<T: Real, C: Curve<T> + ?Sized>(curve: &C, pw: &PiecewisePh<T>, ts: &[T]) -> T {
    let zero = T::zero_in(&pw.step().ctx());
    grid_distances(curve, pw, ts)
        .into_iter()
        .fold(zero, |m, d| if d > m { d } else { m })
}

/// The largest distance ‖γ(t) − p(t)‖ over the grid `ts`, proven: an enclosure (a ball) of
/// the maximum, for a conversion `pw` computed in balls on the interval [a, b] given exactly
/// as `interval`. Each t is located on its segment exactly, in rationals (s = (t − a)N/(b − a),
/// segment k = ⌊s⌋, so a t on a joint belongs to the segment it starts, and t = b to the
/// last one; a t outside [a, b] is clamped to the nearer end, as [`PiecewisePh::locate`]
/// does), ξ = s − k is made a ball only then, and the distance is formed in ball arithmetic.
/// The maximum is an enclosure of the largest distance ([`Field::max_with`]), so no
/// comparison of balls is decided.
///
/// # Example
/// ```
/// use trajverify::algo::ph::grid::proven_grid_error;
/// use trajverify::algo::ph::hermite::FreeParameters;
/// use trajverify::algo::ph::piecewise::convert;
/// use trajverify::curve::ExprCurve;
/// use trajverify::scalar::ball::Ball;
/// use trajverify::scalar::{BigRational, Field};
///
/// let curve = ExprCurve::parse("[t, t^2, sin(t)]").unwrap().compile::<Ball>(&128);
/// let (a, b) = (Ball::zero_in(&128), Ball::one_in(&128));
/// let pw = convert(&curve, (&a, &b), 2, 4, &FreeParameters::zero(4, &128), false).unwrap();
/// let ts: Vec<BigRational> = (0..=10).map(|i| BigRational::new(i.into(), 10.into())).collect();
/// let zero = BigRational::from_integer(0.into());
/// let one = BigRational::from_integer(1.into());
/// let max = proven_grid_error(&curve, &pw, (&zero, &one), &ts);
/// // A proven enclosure of the grid maximum: positive, and small for this smooth curve.
/// assert!(max.lower() > 0 && max.upper() < 1e-2);
/// ```
pub fn proven_grid_error<C: Curve<Ball> + ?Sized>(
    curve: &C,
    pw: &PiecewisePh<Ball>,
    interval: (&BigRational, &BigRational),
    ts: &[BigRational],
) -> Ball {
    let bits = pw.step().ctx();
    proven_grid_distances(curve, pw, interval, ts)
        .into_iter()
        .fold(Ball::zero_in(&bits), |m, d| m.max_with(&d))
}

/// The distances ‖γ(t) − p(t)‖ at the grid `ts`, in order, each proven (a ball), each t
/// located exactly as [`proven_grid_error`] locates it.
pub fn proven_grid_distances<C: Curve<Ball> + ?Sized>(
    curve: &C,
    pw: &PiecewisePh<Ball>,
    (a, b): (&BigRational, &BigRational),
    ts: &[BigRational],
) -> Vec<Ball> {
    let bits = pw.step().ctx();
    let count = pw.segments().len();
    let n = BigRational::from_integer(count.into());
    let last = BigRational::from_integer((count - 1).into());
    let points: Vec<Located<Ball>> = ts
        .iter()
        .enumerate()
        .map(|(i, t)| {
            let s = ((t.clone() - a) * &n / (b.clone() - a))
                .clamp(BigRational::from_integer(0.into()), n.clone());
            let k = s.floor().min(last.clone());
            let xi = Ball::from_rational(&(s - &k), &bits);
            let k = usize::try_from(k.to_integer()).unwrap_or(count - 1);
            (i, k, xi)
        })
        .collect();
    let mut out = vec![Ball::zero_in(&bits); ts.len()];
    for (i, _, d) in distances_at(curve, pw, &points) {
        out[i] = d;
    }
    out
}

/// What lets [`certified_grid_error`] and [`super::piecewise::certified_error`] skip grid
/// points and segments that cannot reach the maximum (see the module doc): proven Taylor
/// models of the error of the same conversion (built in balls from the same curve, interval,
/// segment count and free parameters), and the segment to start from (where the models'
/// proven lower bound of the error was found:
/// [`crate::curve::enclosure::ErrorEnclosure::segment`]).
pub struct ErrorScreen<'a> {
    /// The models.
    pub models: &'a ErrorModels,
    /// The segment evaluated first.
    pub seed_segment: usize,
}

/// The evaluation noise ε of a distance computed at p bits (the precision of `pw`):
/// 2^(10−p) times the curve's size (|γ(a)|, at least 1).
pub(super) fn evaluation_noise<C: Curve<Float>>(curve: &C, pw: &PiecewisePh<Float>) -> Float {
    let bits = pw.start().prec();
    let size = vec3::norm(&curve.jet(pw.start(), 0)[0]).max(&Float::with_val(bits, 1));
    size * Float::with_val(bits, Float::i_exp(1, 10 - bits as i32))
}

/// The threshold L − 4ε below which a screen drops points, as a double rounded down (the
/// distances ‖γ − p‖ of everything it drops are proven below it).
fn threshold(largest: &Float, noise: &Float) -> f64 {
    Float::with_val_round(noise.prec(), largest - &(noise.clone() * 4u32), Round::Down)
        .0
        .to_f64_round(Round::Down)
}

impl ErrorScreen<'_> {
    /// The regions where ‖γ − p‖ may reach the threshold L − 4ε (L = `largest`), outside
    /// which the screen drops everything; `None` when it cannot drop anything (a threshold
    /// ≤ 0, or models of another segment count than `count`).
    fn regions(&self, largest: &Float, noise: &Float, count: usize) -> Option<Vec<Region>> {
        let threshold = threshold(largest, noise);
        (threshold > 0.0 && self.models.segments() == count)
            .then(|| self.models.regions_reaching(threshold, REGION_WIDTH))
    }

    /// The segments where ‖γ − p‖ may reach L − 4ε, the seed segment included,
    /// increasing; `None` as [`ErrorScreen::regions`].
    pub(super) fn segments_reaching(
        &self,
        largest: &Float,
        noise: &Float,
        count: usize,
    ) -> Option<Vec<usize>> {
        let regions = self.regions(largest, noise, count)?;
        let mut reaching = vec![false; count];
        reaching[self.seed_segment] = true;
        for r in regions {
            reaching[r.segment] = true;
        }
        Some((0..count).filter(|&k| reaching[k]).collect())
    }
}

/// The largest of `values`, 0 at `bits` for none.
fn largest<'a>(values: impl Iterator<Item = &'a Float>, bits: u32) -> Float {
    values.fold(Float::new(bits), |m, d| if *d > m { d.clone() } else { m })
}

/// The width (in ξ) of the regions [`ErrorModels::regions_reaching`] returns: a few grid
/// points each at the authors' 100 points per segment.
const REGION_WIDTH: f64 = 1.0 / 32.0;
/// How far (in ξ) a point's ξ at p bits may be from the exact one, with margin: a region is
/// widened by it before a point is tested against it.
const XI_SLACK: f64 = 1e-9;

/// The grid located cheaply, for the screen only: (index, segment, ξ as a double) from the
/// rationals in f64, with the error bound of those ξ; points within that bound of a knot
/// are located exactly, as [`located`] does at `bits`. `None` when the interval makes f64
/// too coarse to tell the segments apart.
fn located_roughly(
    pw: &PiecewisePh<Float>,
    (a, b): (&BigRational, &BigRational),
    ts: &[BigRational],
) -> Option<RoughlyLocated> {
    use num_traits::ToPrimitive;
    let bits = pw.start().prec();
    let n = pw.segments().len();
    let to_f64 = |t: &BigRational| ToPrimitive::to_f64(t).filter(|x| x.is_finite());
    let (a, b) = (to_f64(a)?, to_f64(b)?);
    let ts_f64: Vec<f64> = ts.iter().map(to_f64).collect::<Option<_>>()?;
    let largest = ts_f64
        .iter()
        .fold(a.abs().max(b.abs()), |m, t| m.max(t.abs()));
    // u = N(t − a)/(b − a) from values each within a relative 2⁻⁵³ and a few roundings.
    let slack = 16.0 * f64::EPSILON * n as f64 * (3.0 * largest) / (b - a) + 1e-12;
    if slack.is_nan() || slack >= 1e-3 {
        return None;
    }
    let points = ts_f64
        .iter()
        .enumerate()
        .map(|(i, t)| {
            let u = (t - a) / (b - a) * n as f64;
            let k = u.floor().clamp(0.0, (n - 1) as f64);
            let xi = u - k;
            if xi <= slack || xi >= 1.0 - slack {
                let (k, xi) = pw.locate_clamped(&Float::from_rational(&ts[i], &bits));
                (i, k, xi.to_f64())
            } else {
                (i, k as usize, xi)
            }
        })
        .collect();
    Some((points, slack))
}

/// The distances at p bits of the grid points that can reach the maximum (see the module
/// doc): the seed segment's, and those in the regions the models leave above L − 4ε;
/// `None` when the screen cannot be used (the grid cannot be located in f64).
fn screened_distances<C: Curve<Float>>(
    curve: &C,
    pw: &PiecewisePh<Float>,
    (interval, ts): ((&BigRational, &BigRational), &[BigRational]),
    screen: &ErrorScreen,
    noise: &Float,
) -> Option<Vec<(usize, usize, Float)>> {
    let bits = noise.prec();
    let count = pw.segments().len();
    let (rough, slack) = located_roughly(pw, interval, ts)?;
    // The points to evaluate, located at `bits` as the full grid locates them.
    let exactly = |points: Vec<Located<f64>>| -> Vec<Located<Float>> {
        points
            .into_iter()
            .map(|(i, _, _)| {
                let (k, xi) = pw.locate_clamped(&Float::from_rational(&ts[i], &bits));
                (i, k, xi)
            })
            .collect()
    };
    let seed = screen.seed_segment;
    let (first, rest): (Vec<_>, Vec<_>) = rough.into_iter().partition(|p| p.1 == seed);
    let mut found = distances_at(curve, pw, &exactly(first));
    let seed_largest = largest(found.iter().map(|(_, _, d)| d), bits);
    let kept = match screen.regions(&seed_largest, noise, count) {
        Some(reaching) => {
            let margin = slack + XI_SLACK;
            let mut regions: Vec<Vec<(f64, f64)>> = vec![Vec::new(); count];
            for r in reaching {
                regions[r.segment].push((r.lo - margin, r.hi + margin));
            }
            rest.into_iter()
                .filter(|&(_, k, x)| regions[k].iter().any(|&(lo, hi)| lo <= x && x <= hi))
                .collect()
        }
        None => rest,
    };
    found.extend(distances_at(curve, pw, &exactly(kept)));
    Some(found)
}

/// The maximum of ‖γ − p‖ over the grid `ts` of [a, b], certified like
/// [`super::piecewise::certified_error`]: every point at `bits` (or, with a [`ErrorScreen`],
/// every point the screen does not prove below the maximum: the same maxima, see the module
/// doc), then the points whose distance comes within the evaluation noise of the largest
/// (2^(10−bits) relative to the curve's size) again at `hi_bits`, each on its segment
/// interpolated at `hi_bits`. Returns the two maxima.
///
/// # Errors
/// Those of [`super::piecewise::convert`] at `bits` (a, b rounded to `bits`); those of
/// [`super::hermite::interpolate`] for a segment rebuilt at `hi_bits` (its data are not
/// checked for finiteness there).
#[allow(clippy::too_many_arguments)] // the conversion's definition, its grid and its screen
pub fn certified_grid_error<C: Curve<Float>>(
    make: impl Fn(u32) -> C,
    interval: (&BigRational, &BigRational),
    segments: usize,
    m: usize,
    free: &FreeParameters<BigRational>,
    ts: &[BigRational],
    (bits, hi_bits): (u32, u32),
    screen: Option<&ErrorScreen>,
) -> Result<(Float, Float), PhHermiteError> {
    let lo_curve = make(bits);
    let ends_at = |p: u32| {
        (
            Float::from_rational(interval.0, &p),
            Float::from_rational(interval.1, &p),
        )
    };
    let (a, b) = ends_at(bits);
    let pw = convert_at(&lo_curve, (&a, &b), segments, m, free, bits)?;
    let noise = evaluation_noise(&lo_curve, &pw);
    let screened = screen
        .and_then(|screen| screened_distances(&lo_curve, &pw, (interval, ts), screen, &noise));
    let mut d = screened.unwrap_or_else(|| {
        let ts_lo: Vec<Float> = ts.iter().map(|q| Float::from_rational(q, &bits)).collect();
        distances_at(&lo_curve, &pw, &located(&pw, &ts_lo))
    });
    // Grid order, so that the recomputation below meets the points as the full grid has them.
    d.sort_by_key(|(i, _, _)| *i);
    let max_lo = largest(d.iter().map(|(_, _, x)| x), bits);
    let hi_curve = make(hi_bits);
    let mut max_hi = Float::new(hi_bits);
    for (i, k, _) in d.iter().filter(|(_, _, x)| *x >= max_lo.clone() - &noise) {
        let k = *k;
        let (a, b) = ends_at(hi_bits);
        let (seg, t0, h) = segment_at(&hi_curve, (&a, &b), (segments, k), m, free, hi_bits)?;
        // ξ exactly: (t − t_k)/h from the rational t.
        let xi_hi = (Float::from_rational(&ts[*i], &hi_bits) - &t0) / &h;
        let value = SegmentDistance::new(&hi_curve, &seg.control_points(), &t0, &h)
            .value(&xi_hi)
            .sqrt();
        if value > max_hi {
            max_hi = value;
        }
    }
    Ok((max_lo, max_hi))
}
