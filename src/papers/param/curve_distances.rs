//! Proven maxima over the parameter of natural splines on proven knots, for the claims of paper
//! 004 that compare curves (Fig. 2 "nearly identical", Figs. 4–5 "the validity of (34)", Fig. 6
//! the oscillation near a corner).
//!
//! Each quantity is a maximum over t ∈ [0, 1] of a function built from splines in balls
//! ([`NaturalCubicSpline::enclose_over`]), enclosed by branch and bound
//! ([`proven_maximum`]) with a mean-value form f(m) + f′(X)(X − m) where the derivative is at
//! hand, so the enclosure is proven and tight:
//! - a panel's difference max_t |θ_a⁽ᵈ⁾(t) − θ_b⁽ᵈ⁾(t)| and its range max θ⁽ᵈ⁾ − min θ⁽ᵈ⁾;
//! - the distance between two plane curves through the same points on different knots, bounded
//!   above by max_t |c_a(t) − c_b(φ(t))| with φ the piecewise-linear map taking each knot of
//!   one parametrization to the same knot of the other: every point of either curve is then
//!   within that distance of a point of the other, so it bounds the Hausdorff distance (it is
//!   the Fréchet distance under that one matching, an upper bound of both);
//! - the largest distance of a plane curve from a polygon (1-Lipschitz in the point, so the
//!   box's displacement bounds its change).
//!
//! The stopping tolerances are set from the data's scale (not from any published value); a
//! search that runs out of boxes returns a wider enclosure, which the verdict then decides or
//! leaves undecided.

use crate::algo::param::natural::NaturalCubicSpline;
use crate::curve::distance::CurveBox;
use crate::numeric::maximum::{mean_value, midpoint, proven_maximum, proven_range};
use crate::numeric::maximum::{MaximumEnclosure, SearchOptions};
use crate::scalar::ball::Ball;
use crate::scalar::{Field, Float, Real};

/// The parameter interval of the normalized parametrizations, [0, 1].
fn unit(bits: u32) -> (Float, Float) {
    (Float::with_val(bits, 0), Float::with_val(bits, 1))
}

/// Options for a search to an absolute `tolerance`.
fn options(tolerance: f64, bits: u32) -> SearchOptions {
    SearchOptions {
        tolerance,
        relative: 0.0,
        max_boxes: 200_000,
        bits,
    }
}

/// The largest |θ⁽ᵈ⁾| at the knots: a scale for stopping tolerances only (never a result).
fn scale(spline: &NaturalCubicSpline<Ball>, order: usize) -> f64 {
    spline
        .knots()
        .iter()
        .map(|t| spline.enclose_over(t)[order].abs_upper())
        .fold(f64::MIN_POSITIVE, f64::max)
}

/// θ⁽ᵈ⁾ over the box x in the mean-value form (d ≤ 2: the next derivative is enclosed too).
fn derivative_over(spline: &NaturalCubicSpline<Ball>, order: usize, x: &Ball) -> Ball {
    let at_mid = spline.enclose_over(&midpoint(x))[order].clone();
    let slope = spline.enclose_over(x)[order + 1].clone();
    mean_value(&at_mid, &slope, x)
}

/// A proven enclosure of the range max θ⁽ᵈ⁾ − min θ⁽ᵈ⁾ over [0, 1] (d = 0, 1, 2).
///
/// # Errors
/// The search's error.
pub fn panel_range(spline: &NaturalCubicSpline<Ball>, order: usize) -> Result<Ball, String> {
    let bits = spline.knots()[0].mid().prec();
    let (a, b) = unit(bits);
    let tolerance = 1e-6 * scale(spline, order);
    let (min, max) = proven_range(
        |x: &Ball| Ok(derivative_over(spline, order, x)),
        (&a, &b),
        &options(tolerance, bits),
    )
    .map_err(|e| e.to_string())?;
    Ok(max.ball() - &min.ball())
}

/// A proven enclosure of max_t |θ_a⁽ᵈ⁾(t) − θ_b⁽ᵈ⁾(t)| over [0, 1] (d = 0, 1, 2).
///
/// # Errors
/// The search's error.
pub fn max_difference(
    a: &NaturalCubicSpline<Ball>,
    b: &NaturalCubicSpline<Ball>,
    order: usize,
) -> Result<MaximumEnclosure, String> {
    let bits = a.knots()[0].mid().prec();
    let (start, end) = unit(bits);
    let tolerance = 1e-6 * scale(a, order);
    let difference = |x: &Ball| -> Result<Ball, String> {
        let m = midpoint(x);
        let at_mid = a.enclose_over(&m)[order].clone() - &b.enclose_over(&m)[order];
        let slope = a.enclose_over(x)[order + 1].clone() - &b.enclose_over(x)[order + 1];
        Ok(mean_value(&at_mid, &slope, x).abs())
    };
    proven_maximum(difference, (&start, &end), &options(tolerance, bits)).map_err(|e| e.to_string())
}

/// A plane curve: its x and y splines on one parametrization.
pub type PlaneCurve = [NaturalCubicSpline<Ball>; 2];

/// The knots of a curve's parametrization (both components share them).
fn knots(curve: &PlaneCurve) -> &[Ball] {
    curve[0].knots()
}

/// A proven upper bound of the Hausdorff distance between two plane curves through the same
/// points: max_t |c_a(t) − c_b(φ(t))| (see the module doc), with the enclosure of that maximum.
///
/// # Errors
/// Curves with different numbers of knots, or the search's error.
pub fn matched_distance(a: &PlaneCurve, b: &PlaneCurve) -> Result<MaximumEnclosure, String> {
    let (ka, kb) = (knots(a), knots(b));
    if ka.len() != kb.len() {
        return Err(format!(
            "the curves have {} and {} knots",
            ka.len(),
            kb.len()
        ));
    }
    let bits = ka[0].mid().prec();
    let (start, end) = unit(bits);
    // On piece i, t = tᵃᵢ₋₁ + v maps to tᵇᵢ₋₁ + r v with r = hᵇᵢ/hᵃᵢ; the difference
    // D(t) = c_a(t) − c_b(φ(t)) has D′ = c_a′ − r c_b′.
    let on_piece = |x: &Ball, i: usize| -> [Ball; 2] {
        let (ha, hb) = (ka[i].clone() - &ka[i - 1], kb[i].clone() - &kb[i - 1]);
        let ratio = hb / &ha;
        let (va, ua) = (x.clone() - &ka[i - 1], ka[i].clone() - x);
        let (vb, ub) = (ratio.clone() * &va, ratio.clone() * &ua);
        [0, 1].map(|c| {
            let m = midpoint(x);
            let (vm, um) = (m.clone() - &ka[i - 1], ka[i].clone() - &m);
            let pa = a[c].eval_offsets(&um, &vm, i);
            let pb = b[c].eval_offsets(&(ratio.clone() * &um), &(ratio.clone() * &vm), i);
            let at_mid = pa[0].clone() - &pb[0];
            let slope = a[c].eval_offsets(&ua, &va, i)[1].clone()
                - &(ratio.clone() * &b[c].eval_offsets(&ub, &vb, i)[1]);
            mean_value(&at_mid, &slope, x)
        })
    };
    let distance = |x: &Ball| -> Result<Ball, String> {
        let mut hull: Option<Ball> = None;
        for i in a[0].pieces_meeting(x) {
            let [dx, dy] = on_piece(x, i);
            let d = (dx.clone() * &dx + &(dy.clone() * &dy)).sqrt();
            hull = Some(hull.map_or(d.clone(), |h| Ball::hull(&h, &d)));
        }
        hull.ok_or_else(|| "no piece meets the box".to_string())
    };
    let tolerance = 1e-6 * extent(a);
    proven_maximum(distance, (&start, &end), &options(tolerance, bits)).map_err(|e| e.to_string())
}

/// The larger side of the bounding box of a curve's data points (a scale for tolerances).
fn extent(curve: &PlaneCurve) -> f64 {
    curve
        .iter()
        .map(|s| {
            let values: Vec<f64> = s
                .knots()
                .iter()
                .map(|t| s.enclose_over(t)[0].mid().to_f64())
                .collect();
            let max = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            let min = values.iter().copied().fold(f64::INFINITY, f64::min);
            max - min
        })
        .fold(f64::MIN_POSITIVE, f64::max)
}

/// Both components' (θ, θ′, θ″, θ‴) over the box x.
fn curve_at(curve: &PlaneCurve, x: &Ball) -> [[Ball; 4]; 2] {
    [curve[0].enclose_over(x), curve[1].enclose_over(x)]
}

/// A proven enclosure of the largest distance of the curve from the polygon through
/// `vertices`, over t ∈ [0, 1], the distance over a box of t enclosed by [`CurveBox`].
///
/// # Errors
/// A polygon of fewer than two vertices, or the search's error.
pub fn max_distance_from_polygon(
    curve: &PlaneCurve,
    vertices: &[[Ball; 2]],
) -> Result<MaximumEnclosure, String> {
    let bits = knots(curve)[0].mid().prec();
    let (start, end) = unit(bits);
    let distance = |x: &Ball| -> Result<Ball, String> {
        let (mid, over) = (curve_at(curve, &midpoint(x)), curve_at(curve, x));
        CurveBox {
            at_mid: [mid[0][0].clone(), mid[1][0].clone()],
            over: [over[0][0].clone(), over[1][0].clone()],
            velocity: [over[0][1].clone(), over[1][1].clone()],
            parameter: x.clone(),
        }
        .distance_to_polygon(vertices)
        .ok_or_else(|| "the polygon has fewer than two vertices".to_string())
    };
    let tolerance = 1e-6 * extent(curve);
    proven_maximum(distance, (&start, &end), &options(tolerance, bits)).map_err(|e| e.to_string())
}

/// A ratio of two enclosures as a percentage.
pub fn percent(numerator: &Ball, denominator: &Ball) -> Ball {
    let bits = numerator.mid().prec();
    Ball::from_i64(100, &bits) * numerator / denominator
}

/// Proven enclosures of the smallest and the largest speed ‖θ′(t)‖ over t ∈ [0, 1] of the
/// curve whose components are `splines` (all on the same knots): the search runs on the
/// squared speed Σ θ_j′², in the mean-value form with slope 2 Σ θ_j′ θ_j″, and the square
/// root, being increasing, carries both enclosures over.
///
/// # Errors
/// No component, or the search's error.
pub fn speed_range(splines: &[NaturalCubicSpline<Ball>]) -> Result<(Ball, Ball), String> {
    let first = splines.first().ok_or("a curve with no component")?;
    let bits = first.knots()[0].mid().prec();
    let (start, end) = unit(bits);
    let zero = Ball::zero_in(&bits);
    let two = Ball::from_i64(2, &bits);
    let squared_speed = |x: &Ball| -> Result<Ball, String> {
        let m = midpoint(x);
        let (mut at_mid, mut slope) = (zero.clone(), zero.clone());
        for s in splines {
            let (mid, over) = (s.enclose_over(&m), s.enclose_over(x));
            at_mid += &(mid[1].clone() * &mid[1]);
            slope += &(two.clone() * &over[1] * &over[2]);
        }
        Ok(mean_value(&at_mid, &slope, x))
    };
    let scale: f64 = splines.iter().map(|s| scale(s, 1).powi(2)).sum();
    let (min, max) = proven_range(squared_speed, (&start, &end), &options(1e-9 * scale, bits))
        .map_err(|e| e.to_string())?;
    // The squared speed is never negative: a box reaching below 0 is only overestimated.
    let root = |b: Ball| {
        if b.lower() < 0 {
            Ball::from_bounds(&Float::with_val(bits, 0), &b.upper()).sqrt()
        } else {
            b.sqrt()
        }
    };
    Ok((root(min.ball()), root(max.ball())))
}
