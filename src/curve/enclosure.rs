//! A proven enclosure of the error E = max_ξ ‖γ(ξ) − p(ξ)‖ (paper 001, Eq. 21) of a piecewise
//! Bernstein approximant of degree ≤ 17 ([`BernsteinPieces`]: the PHODCOS conversion, or a
//! piecewise Hermite–Bernstein interpolant) by branch and bound in ball arithmetic.
//!
//! On a piece [u_a, u_b] of a segment's local parameter u (ξ = t_k + h u), with centre u_c
//! and half-width ω, the error d(u) = γ(t_k + h u) − p(u) is a Taylor model of order 17 in
//! s = u − u_c:
//!
//! d(u_c + s) = Σ_{j ≤ 17} q_j s^j + r(s),  q_j = γ^(j)(x_c) h^j/j! − p^(j)(u_c)/j!,
//! |r_i(s)| ≤ max_{x ∈ X} |γ_i^(18)(x)| (hω)^18/18!,
//!
//! since p has degree at most 17 (its 18th derivative vanishes) and X = t_k + h[u_a, u_b] is covered
//! by one ball on which the curve's jet is evaluated. For a piecewise curve (a spline through
//! data) the jet describes one polynomial piece P, and ‖γ − P‖ ≤ the curve's seam bound on X
//! ([`Curve::seam_bound`]: the knots inside X) is added to the remainder; each segment is
//! first split at the curve's breakpoints ([`Curve::breakpoints`]), so a knot sits at a
//! piece's end and its seam term is rounding-sized. A piece is halved until that remainder
//! is negligible (below a tenth of the target width of the current lower bound). The squared
//! norm F(s) = Σ_i Q_i(s)² of the polynomial part is a polynomial of degree 34; on a box
//! S = [s₀ − w, s₀ + w] of the piece,
//!
//! F(S) ⊆ F(s₀) + F′(s₀)[−w, w] + F″(S)[0, w²/2]
//!
//! (F″ evaluated on the whole box by Horner's rule in balls), a second-order bound: near the
//! maximum F′ ≈ 0, so boxes of width ~√target suffice. Each box centre gives a proven lower
//! bound of E (the ball of ‖Q(s₀)‖ minus ‖r‖), each box a proven upper bound of E on it
//! (√ of the upper end plus ‖r‖). The box with the largest upper bound is bisected until
//! (upper − lower)/lower ≤ the target, or the box budget runs out (the width achieved is
//! returned either way). Both bounds are proofs, not estimates: every quantity is a ball and
//! every decision compares only bounds that are already rigorous.

use super::approx::BernsteinPieces;
use super::Curve;
use crate::numeric::poly::bernstein::{bernstein_jet, bernstein_taylor};
use crate::numeric::quat::vec3;
use crate::scalar::ball::carried;
use crate::scalar::ball::Ball;
use crate::scalar::{Field, Float, Real};
use rayon::prelude::*;
use rug::float::Round;
use std::collections::BinaryHeap;
use std::time::Instant;

/// The Taylor order of the models (the degree of the C⁴ PH interpolants): the highest degree
/// of a piece [`proven_error`] accepts.
pub const ORDER: usize = 17;
/// Halvings of a piece allowed while its Taylor remainder is too large.
const MAX_PIECE_DEPTH: u32 = 12;
/// The boxes a branch and bound may evaluate without narrowing its gap by 1 % before it
/// stops (see [`ErrorModels::enclose`]).
const STALL_BOXES: usize = 20_000;
/// Halvings of a box allowed in [`ErrorModels::regions_reaching`].
const MAX_REGION_DEPTH: u32 = 20;

/// A proven enclosure lower ≤ E ≤ upper.
#[derive(Clone, Debug)]
pub struct ErrorEnclosure {
    /// A proven lower bound of E.
    pub lower: Float,
    /// A proven upper bound of E.
    pub upper: Float,
    /// The segment whose box gave the lower bound.
    pub segment: usize,
    /// Boxes evaluated in the search.
    pub boxes: usize,
}

impl ErrorEnclosure {
    /// (upper − lower)/lower, as a double (∞ when the lower bound is 0).
    pub fn relative_width(&self) -> f64 {
        if self.lower.is_zero() {
            return f64::INFINITY;
        }
        (Float::with_val(64, &self.upper - &self.lower) / &self.lower).to_f64()
    }
}

/// The Taylor model of d on one piece: the squared norm of its polynomial part in s, and a
/// bound of its remainder's norm.
struct Model {
    segment: usize,
    /// Centre u_c of the piece.
    centre: Float,
    /// Half-width ω of the piece in u.
    half_width: Float,
    /// F(s) = ‖Q(s)‖², coefficients of s⁰ … s³⁴.
    norm2: Vec<Ball>,
    /// F′ and F″, coefficients.
    slope: Vec<Ball>,
    curvature: Vec<Ball>,
    /// An upper bound of ‖r(s)‖ on the piece.
    remainder: f64,
}

/// A box of a piece: its centre s₀ and half-width w (in s), with its proven upper bound.
struct Candidate {
    upper: f64,
    model: usize,
    centre: Float,
    half_width: Float,
}

impl PartialEq for Candidate {
    fn eq(&self, other: &Self) -> bool {
        self.upper == other.upper
    }
}
impl Eq for Candidate {}
impl PartialOrd for Candidate {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for Candidate {
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        self.upper.total_cmp(&other.upper)
    }
}

/// p(u) = Σ c_j s^j at a ball s by Horner's rule.
fn horner(coefficients: &[Ball], s: &Ball) -> Ball {
    let ctx = s.ctx();
    coefficients
        .iter()
        .rev()
        .fold(Ball::zero_in(&ctx), |mut acc, c| {
            acc.horner_step(s, c);
            acc
        })
}

/// The derivative's coefficients.
fn derivative(coefficients: &[Ball]) -> Vec<Ball> {
    let ctx = coefficients[0].ctx();
    coefficients
        .iter()
        .enumerate()
        .skip(1)
        .map(|(j, c)| c.clone() * &Ball::from_i64(j as i64, &ctx))
        .collect()
}

/// An upper bound of |x| for a ball, as a double.
fn magnitude_up(x: &Ball) -> f64 {
    let top = x.upper().abs().max(&x.lower().abs());
    top.to_f64_round(Round::Up)
}

/// Bounds of |γ_i^(18)| over an interval [lo, hi] of t spanning many segments: the
/// remainders of their whole-segment models from one jet instead of one each.
struct HighBound {
    lo: Float,
    hi: Float,
    bound: [f64; 3],
}

/// Segments above which the whole-segment models take their remainders from
/// [`HIGH_BLOCKS`] shared bounds (at most this many: one jet per segment, as for pieces).
const SHARED_ABOVE: usize = 64;
/// The blocks of consecutive segments sharing one bound of γ^(18).
const HIGH_BLOCKS: usize = 64;

/// The segments per block and each block's bound of |γ^(18)| over its segments (padded by
/// 2⁻¹⁰ of a segment), for an analytic curve (no breakpoints) on more than [`SHARED_ABOVE`]
/// segments; `None` otherwise, or where a bound is not finite. A bound over a block is larger
/// than over one segment, but the remainder it gives, (hω)¹⁸/18! times it, is then far below
/// any error the search resolves.
fn high_bounds<C: Curve<Ball> + ?Sized, P: BernsteinPieces<Ball> + ?Sized>(
    curve: &C,
    pw: &P,
) -> Option<(usize, Vec<HighBound>)> {
    let n = pw.count();
    let (a, b) = pw.interval();
    let analytic = curve
        .breakpoints(
            a.lower().to_f64_round(Round::Down),
            b.upper().to_f64_round(Round::Up),
        )
        .is_empty();
    if n <= SHARED_ABOVE || !analytic {
        return None;
    }
    let bits = a.ctx();
    let h = pw.step();
    let pad = magnitude_up(&h) / 1024.0;
    let per_block = n.div_ceil(HIGH_BLOCKS);
    (0..n.div_ceil(per_block))
        .into_par_iter()
        .map(carried(|block: usize| {
            let first = block * per_block;
            let last = (first + per_block).min(n) - 1;
            let end = pw.knot(last) + &h;
            let lo = Float::with_val_round(bits, pw.knot(first).lower() - pad, Round::Down).0;
            let hi = Float::with_val_round(bits, end.upper() + pad, Round::Up).0;
            let mid = Float::with_val(bits, &lo + &hi) / 2u32;
            // Half the width, rounded up, with margin for the midpoint's rounding.
            let rad = Float::with_val_round(64, &hi - &lo, Round::Up)
                .0
                .to_f64_round(Round::Up)
                * (0.5 + 1e-15);
            let high = curve
                .jet(&Ball::new(mid, rad), ORDER + 1)
                .swap_remove(ORDER + 1);
            let bound = [0, 1, 2].map(|i| magnitude_up(&high[i]));
            bound
                .iter()
                .all(|g| g.is_finite())
                .then_some(HighBound { lo, hi, bound })
        }))
        .collect::<Option<Vec<HighBound>>>()
        .map(|blocks| (per_block, blocks))
}

/// The Taylor model of segment k on the piece [u_a, u_b]; `shared`, a bound of |γ^(18)| on
/// an interval of t, serves for the remainder when that interval contains the piece's.
fn model<C: Curve<Ball> + ?Sized, P: BernsteinPieces<Ball> + ?Sized>(
    curve: &C,
    pw: &P,
    (k, points): (usize, &[[Ball; 3]]),
    (ua, ub): (&Float, &Float),
    shared: Option<&HighBound>,
) -> Model {
    assert!(
        points.len() <= ORDER + 1,
        "proven_error needs pieces of degree at most {ORDER}"
    );
    let bits = pw.interval().0.ctx();
    let h = pw.step();
    let tk = pw.knot(k);
    let uc = Float::with_val(bits, ua + ub) / 2u32;
    let omega = Float::with_val(bits, ub - ua) / 2u32;
    let xc = tk.clone() + &(h.clone() * &Ball::exact(uc.clone()));
    let gamma = curve.jet(&xc, ORDER);
    // p^(j)(u_c)/j!, all of them at once (p has degree ≤ ORDER: the rest are 0).
    let p = bernstein_taylor(points, &Ball::exact(uc.clone()));
    // q_j = γ^(j) h^j/j! − p^(j)/j!.
    let mut scale = Ball::one_in(&bits);
    let mut factorial = Ball::one_in(&bits);
    let q: Vec<[Ball; 3]> = (0..=ORDER)
        .map(|j| {
            if j > 0 {
                scale *= &h;
                factorial *= &Ball::from_i64(j as i64, &bits);
            }
            let g = vec3::scale(&gamma[j], &(scale.clone() / &factorial));
            match p.get(j) {
                Some(pj) => vec3::sub(&g, pj),
                None => g,
            }
        })
        .collect();
    // The remainder: γ^(18) over the whole piece X = x_c ± |h|ω.
    let hw = h.clone().abs() * &Ball::exact(omega.clone());
    let spread = Ball::new(
        xc.mid().clone(),
        (xc.rad() + magnitude_up(&hw)) * (1.0 + 1e-15),
    );
    let contains = |s: &HighBound| spread.lower() >= s.lo && spread.upper() <= s.hi;
    let high: [f64; 3] = match shared.filter(|s| contains(s)) {
        Some(s) => s.bound,
        None => {
            let high = curve.jet(&spread, ORDER + 1).swap_remove(ORDER + 1);
            [0, 1, 2].map(|i| magnitude_up(&high[i]))
        }
    };
    let mut term = Ball::one_in(&bits);
    for j in 1..=ORDER + 1 {
        term = term * &hw / &Ball::from_i64(j as i64, &bits);
    }
    let remainder2: f64 = high.iter().map(|g| (g * magnitude_up(&term)).powi(2)).sum();
    // A piecewise curve (a spline) differs from the piece the jet described by at most its
    // seam bound on X.
    let seam = curve.seam_bound(
        spread.lower().to_f64_round(Round::Down),
        (
            xc.lower().to_f64_round(Round::Down),
            xc.upper().to_f64_round(Round::Up),
        ),
        spread.upper().to_f64_round(Round::Up),
    );
    // F = Σ_i Q_i², by convolution.
    let mut norm2 = vec![Ball::zero_in(&bits); 2 * ORDER + 1];
    // Σ_i Q_i² by convolution, each cross term once and doubled.
    let two = Ball::from_i64(2, &bits);
    for (a, qa) in q.iter().enumerate() {
        for (b, qb) in q.iter().enumerate().skip(a) {
            let mut dot = Ball::zero_in(&bits);
            for i in 0..3 {
                dot.mul_add_assign(&qa[i], &qb[i]);
            }
            if a != b {
                dot *= &two;
            }
            norm2[a + b] += &dot;
        }
    }
    let slope = derivative(&norm2);
    let curvature = derivative(&slope);
    Model {
        segment: k,
        centre: uc,
        half_width: omega,
        norm2,
        slope,
        curvature,
        // √ rounded up, with margin for the f64 sum.
        remainder: ((remainder2 * (1.0 + 1e-12)).sqrt() * (1.0 + 1e-12) + seam) * (1.0 + 1e-15),
    }
}

/// The two halves of the box s₀ ± w: their half-width w/2 and centres s₀ ∓ w/2.
fn halves(centre: &Float, half_width: &Float) -> (Float, [Float; 2]) {
    let bits = centre.prec();
    let w = Float::with_val(bits, half_width) / 2u32;
    let centres = [-1i32, 1].map(|sign| {
        let step = Float::with_val(bits, &w * sign);
        Float::with_val(bits, centre + &step)
    });
    (w, centres)
}

/// An end of the box s₀ ± w of a model in u = u_c + s: the lower end rounded down
/// (`Round::Down`) or the upper end rounded up (`Round::Up`), every step in that direction.
fn box_end(m: &Model, centre: &Float, half_width: &Float, round: Round) -> f64 {
    let bits = centre.prec();
    let u = Float::with_val_round(bits, &m.centre + centre, round).0;
    let end = match round {
        Round::Down => Float::with_val_round(bits, &u - half_width, round).0,
        _ => Float::with_val_round(bits, &u + half_width, round).0,
    };
    end.to_f64_round(round)
}

/// Proven bounds of ‖d‖ on the box s₀ ± w of a model: (lower at s₀, upper on the box).
fn box_bounds(m: &Model, centre: &Float, half_width: &Float) -> (f64, f64) {
    let bits = centre.prec();
    let s0 = Ball::exact(centre.clone());
    let f0 = horner(&m.norm2, &s0);
    let f1 = horner(&m.slope, &s0);
    let whole = Ball::new(
        centre.clone(),
        Float::with_val(64, half_width).to_f64_round(Round::Up),
    );
    let f2 = horner(&m.curvature, &whole);
    let w = Ball::exact(Float::with_val(bits, half_width));
    let spread =
        magnitude_up(&(f1 * &w)) + magnitude_up(&(f2 * &w * &w / &Ball::from_i64(2, &bits)));
    let top = f0.upper().to_f64_round(Round::Up) * (1.0 + 1e-15) + spread * (1.0 + 1e-15);
    let bottom = f0.lower().to_f64_round(Round::Down).max(0.0);
    // f64 steps rounded to nearest, each widened by a relative 1e-15 (≫ the 1.1e-16 of one
    // rounding) in the safe direction.
    let lower = ((bottom.sqrt() * (1.0 - 1e-15) - m.remainder) * (1.0 - 1e-15)).max(0.0);
    let upper = (top.max(0.0).sqrt() * (1.0 + 1e-15) + m.remainder) * (1.0 + 1e-15);
    (lower, upper)
}

/// The pieces of segment k, starting from its whole-segment model `whole`, halved until the
/// Taylor remainder is below `tolerance`.
fn pieces<C: Curve<Ball> + ?Sized, P: BernsteinPieces<Ball> + ?Sized>(
    curve: &C,
    pw: &P,
    (whole, points): (Model, &[[Ball; 3]]),
    tolerance: f64,
    deadline: Option<Instant>,
) -> Vec<Model> {
    let bits = pw.interval().0.ctx();
    let k = whole.segment;
    // A piecewise curve's breakpoints split the segment first: a piece ending at a knot
    // sees it only within rounding of its end, so its seam term vanishes.
    let splits = breakpoints_in_segment(curve, pw, k);
    let mut todo = if splits.is_empty() {
        vec![(
            Float::with_val(bits, 0),
            Float::with_val(bits, 1),
            0u32,
            f64::INFINITY,
            Some(whole),
        )]
    } else {
        let ends: Vec<Float> = std::iter::once(Float::with_val(bits, 0))
            .chain(splits)
            .chain(std::iter::once(Float::with_val(bits, 1)))
            .collect();
        ends.windows(2)
            .map(|w| (w[0].clone(), w[1].clone(), 0u32, f64::INFINITY, None))
            .collect()
    };
    let mut done = Vec::new();
    while let Some((a, b, depth, parent, known)) = todo.pop() {
        crate::cancel::checkpoint();
        let m = known.unwrap_or_else(|| model(curve, pw, (k, points), (&a, &b), None));
        // Past the deadline a piece is kept whole: its remainder is in both bounds, so the
        // enclosure stays proven, only wider. A remainder that halving no longer shrinks
        // below half its parent's is rounding, not truncation (the precision floor of a low
        // precision): splitting it further only spends the deadline.
        let stalled = m.remainder > 0.5 * parent;
        if m.remainder <= tolerance || depth >= MAX_PIECE_DEPTH || stalled || passed(deadline) {
            done.push(m);
        } else {
            let mid = Float::with_val(bits, &a + &b) / 2u32;
            let r = m.remainder;
            todo.push((mid.clone(), b, depth + 1, r, None));
            todo.push((a, mid, depth + 1, r, None));
        }
    }
    done
}

/// The curve's breakpoints inside segment k, as local parameters u ∈ (0, 1), increasing
/// (each rounded: the seam bound accounts for the knot's true position).
fn breakpoints_in_segment<C: Curve<Ball> + ?Sized, P: BernsteinPieces<Ball> + ?Sized>(
    curve: &C,
    pw: &P,
    k: usize,
) -> Vec<Float> {
    let (tk, h) = (pw.knot(k), pw.step());
    let end = tk.clone() + &h;
    let (lo, hi) = (
        tk.lower()
            .to_f64_round(Round::Down)
            .min(end.lower().to_f64_round(Round::Down)),
        tk.upper()
            .to_f64_round(Round::Up)
            .max(end.upper().to_f64_round(Round::Up)),
    );
    let bits = h.ctx();
    let mut us: Vec<Float> = curve
        .breakpoints(lo, hi)
        .into_iter()
        .map(|at| (Float::with_val(bits, at) - tk.mid()) / h.mid())
        .filter(|u| *u > 0 && *u < 1)
        .collect();
    us.sort_by(|a, b| a.partial_cmp(b).unwrap_or(std::cmp::Ordering::Equal));
    us.dedup();
    us
}

/// Points per whole-segment model for the first lower bound.
const LOWER_SAMPLES: i64 = 8;

/// A proven lower bound of E from the whole-segment models evaluated at their centre and at
/// `LOWER_SAMPLES` points across the segment (‖Q(s₀)‖ − ‖r‖ at each). It sizes the remainder
/// tolerance: the centre alone can sit near a zero of the error (a Hermite interpolant with
/// many derivatives at both ends is nearly symmetric), which would make the tolerance, and
/// the work, needlessly small.
fn sampled_lower_bound(whole: &[Model], bits: u32) -> f64 {
    whole
        .par_iter()
        .map(carried(|m: &Model| {
            (0..=LOWER_SAMPLES)
                .map(|i| {
                    // s₀ = ω(2i/L − 1) spans the piece [u_c − ω, u_c + ω].
                    let s0 = Float::with_val(bits, &m.half_width)
                        * Float::with_val(bits, 2 * i - LOWER_SAMPLES)
                        / LOWER_SAMPLES;
                    box_bounds(m, &s0, &Float::with_val(bits, 0)).0
                })
                .fold(0.0, f64::max)
        }))
        .reduce(|| 0.0, f64::max)
}

/// A proven lower bound of E from ‖γ − p‖ evaluated directly in balls at `LOWER_SAMPLES` + 1
/// points of every segment (no Taylor remainder involved).
fn evaluated_lower_bound<C: Curve<Ball> + ?Sized, P: BernsteinPieces<Ball> + ?Sized>(
    curve: &C,
    pw: &P,
    points: &[Vec<[Ball; 3]>],
) -> f64 {
    let bits = pw.interval().0.ctx();
    let h = pw.step();
    (0..pw.count())
        .into_par_iter()
        .map(carried(|k| {
            let points = &points[k];
            let tk = pw.knot(k);
            (0..=LOWER_SAMPLES)
                .map(|i| {
                    let u = Ball::from_ratio(i, LOWER_SAMPLES, &bits);
                    let gamma = curve.jet(&(tk.clone() + &(h.clone() * &u)), 0);
                    let d = vec3::sub(&gamma[0], &bernstein_jet(points, &u, 0)[0]);
                    let norm = vec3::dot(&d, &d).sqrt();
                    norm.lower().to_f64_round(Round::Down).max(0.0)
                })
                .fold(0.0, f64::max)
        }))
        .reduce(|| 0.0, f64::max)
}

/// The width below which no box narrows the bounds: the width they already have at the
/// centre of a whole segment (a box of width 0: only the radii of the balls, the Taylor
/// remainder taken out), four times over, plus the floor of the squared norm: the bounds come
/// from F = ‖Q‖², whose rounding noise is about 2^−p·size², so E is not resolved below
/// √(2^−p)·size. An error that is rounding noise (a curve the method reproduces exactly) is
/// then enclosed in [0, about the floor] instead of being split and bisected to the budget.
fn precision_floor(points: &[Vec<[Ball; 3]>], whole: &[Model], bits: u32) -> f64 {
    let zero_width = Float::with_val(bits, 0);
    let size = points
        .iter()
        .flatten()
        .flatten()
        .map(|x| x.mid().to_f64().abs())
        .fold(0.0f64, f64::max);
    let squared_floor = 16.0 * size * 2f64.powi(-(bits.min(2000) as i32) / 2);
    whole
        .iter()
        .map(|m| {
            let (lo, up) = box_bounds(m, &zero_width, &zero_width);
            (up - lo - 2.0 * m.remainder).max(0.0)
        })
        .fold(f64::MIN_POSITIVE, f64::max)
        .mul_add(4.0, squared_floor)
}

/// One box per piece, the whole piece, with the best lower bound (and its segment) they give.
fn first_boxes(models: &[Model], bits: u32) -> (BinaryHeap<Candidate>, (f64, usize)) {
    let mut best = (0.0f64, 0usize);
    let mut heap = BinaryHeap::new();
    for (i, m) in models.iter().enumerate() {
        let centre = Float::with_val(bits, 0);
        let (lo, up) = box_bounds(m, &centre, &m.half_width);
        if lo > best.0 {
            best = (lo, m.segment);
        }
        heap.push(Candidate {
            upper: up,
            model: i,
            centre,
            half_width: m.half_width.clone(),
        });
    }
    (heap, best)
}

/// How far a proven error search goes.
#[derive(Clone, Debug, PartialEq)]
pub struct ProofOptions {
    /// Stop when (upper − lower)/lower ≤ this relative width. Default 10⁻⁶.
    pub target: f64,
    /// Or after this many boxes. Default 200 000.
    pub max_boxes: usize,
    /// Or at this instant: the bounds found by then are returned, still proven (a piece left
    /// unsplit keeps its whole remainder in both bounds), only wider than `target`; the
    /// caller reads the width achieved from the result. Default: none.
    pub deadline: Option<Instant>,
}

impl Default for ProofOptions {
    fn default() -> Self {
        ProofOptions {
            target: 1e-6,
            max_boxes: 200_000,
            deadline: None,
        }
    }
}

/// Proven bounds lower ≤ E ≤ upper of the conversion error of `pw` against `curve`,
/// searched until (upper − lower)/lower ≤ `options.target`, or upper − lower is below the
/// precision floor (about √(2^−p) times the size of the control points, where the squared
/// norm the bounds come from is rounding noise: an error the method does not resolve at p
/// bits, such as that of a curve it reproduces exactly), or `options.max_boxes` boxes were
/// evaluated, or `options.deadline` passed.
///
/// # Examples
/// ```
/// use trajverify::algo::ph::piecewise::{fit, FitOptions};
/// use trajverify::curve::{enclosure::{proven_error, ProofOptions}, ExprCurve};
/// use trajverify::scalar::{ball::Ball, Field};
/// let curve = ExprCurve::parse("[cos(t), sin(t), t]").unwrap().compile::<Ball>(&128);
/// let (a, b) = (Ball::from_i64(0, &128), Ball::from_i64(1, &128));
/// let spline = fit(&curve, (&a, &b), &FitOptions { segments: 2, ..FitOptions::default() }).unwrap();
/// let e = proven_error(&curve, &spline, &ProofOptions::default()).unwrap();
/// assert!(e.lower <= e.upper && e.upper < 1e-6);
/// ```
///
/// # Errors
/// [`EnclosureError::Target`] unless `target` is a positive finite number;
/// [`EnclosureError::MaxBoxes`] for `max_boxes` = 0.
pub fn proven_error<C: Curve<Ball> + ?Sized, P: BernsteinPieces<Ball> + ?Sized>(
    curve: &C,
    pw: &P,
    options: &ProofOptions,
) -> Result<ErrorEnclosure, EnclosureError> {
    let ProofOptions {
        target,
        max_boxes,
        deadline,
    } = *options;
    if !(target.is_finite() && target > 0.0) {
        return Err(EnclosureError::Target(target));
    }
    if max_boxes == 0 {
        return Err(EnclosureError::MaxBoxes);
    }
    Ok(ErrorModels::build(curve, pw, target, deadline).enclose(target, max_boxes, deadline))
}

/// Why a proven error search cannot start.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum EnclosureError {
    /// A relative width that is not a positive finite number.
    #[error("target: the relative width must be a positive finite number, got {0}")]
    Target(f64),
    /// No box to evaluate.
    #[error("max_boxes: the search needs at least one box")]
    MaxBoxes,
}

/// Whether the deadline (if any) has passed.
fn passed(deadline: Option<Instant>) -> bool {
    deadline.is_some_and(|d| Instant::now() >= d)
}

/// The Taylor models of the error d = γ − p over every segment, each piece's remainder below
/// what a search to relative width `target` needs: what [`proven_error`] searches, kept for
/// other questions about the same error ([`ErrorModels::regions_reaching`]).
pub struct ErrorModels {
    models: Vec<Model>,
    /// The precision floor (see [`precision_floor`]).
    floor: f64,
    bits: u32,
    segments: usize,
}

/// An interval [lo, hi] of the local parameter u of one segment (bounds rounded outward).
#[derive(Clone, Debug, PartialEq)]
pub struct Region {
    /// The segment.
    pub segment: usize,
    /// Lower end in u, rounded down.
    pub lo: f64,
    /// Upper end in u, rounded up.
    pub hi: f64,
}

impl ErrorModels {
    /// The models of `pw` against `curve`, pieces halved until their Taylor remainders allow
    /// a search to relative width `target` (or until `deadline`: a piece left unsplit keeps
    /// its whole remainder in every bound, which stays proven, only wider).
    pub fn build<C: Curve<Ball> + ?Sized, P: BernsteinPieces<Ball> + ?Sized>(
        curve: &C,
        pw: &P,
        target: f64,
        deadline: Option<Instant>,
    ) -> Self {
        let bits = pw.interval().0.ctx();
        let n = pw.count();
        // Whole-segment models first: their centres give a lower bound that sizes the
        // remainder tolerance; only segments whose remainder exceeds it are split.
        let (zero, one) = (Float::with_val(bits, 0), Float::with_val(bits, 1));
        // Every segment's control points, computed once (a PH segment derives them from its
        // preimage by quaternion products).
        let points: Vec<Vec<[Ball; 3]>> = (0..n)
            .into_par_iter()
            .map(carried(|k| pw.control_points(k)))
            .collect();
        let shared = high_bounds(curve, pw);
        let whole: Vec<Model> = (0..n)
            .into_par_iter()
            .map(carried(|k| {
                let bound = shared.as_ref().map(|(per_block, b)| &b[k / per_block]);
                model(curve, pw, (k, &points[k]), (&zero, &one), bound)
            }))
            .collect();
        let floor = precision_floor(&points, &whole, bits);
        // The remainder each piece must reach: a tenth of the target width at the lower
        // bound, or the floor.
        let tolerance_at = |lower: f64| (lower * target / 10.0).max(floor);
        let mut rough = sampled_lower_bound(&whole, bits);
        if whole.iter().any(|m| m.remainder > tolerance_at(rough)) {
            // Some segment must be split: the bound sets how finely, so make it as good as a
            // direct evaluation can (the models' remainders may be too large to give one).
            rough = rough.max(evaluated_lower_bound(curve, pw, &points));
        }
        let tolerance = tolerance_at(rough);
        let models: Vec<Model> = whole
            .into_par_iter()
            .flat_map_iter(carried(|m: Model| {
                let k = m.segment;
                pieces(curve, pw, (m, &points[k]), tolerance, deadline)
            }))
            .collect();
        ErrorModels {
            models,
            floor,
            bits,
            segments: n,
        }
    }

    /// The number of segments the models cover.
    pub fn segments(&self) -> usize {
        self.segments
    }

    /// Proven bounds lower ≤ E ≤ upper by branch and bound over the boxes of the models,
    /// until (upper − lower)/lower ≤ `target`, upper − lower is irreducible (the models'
    /// remainders and the precision floor), `max_boxes` boxes were evaluated, or `deadline`.
    pub fn enclose(
        &self,
        target: f64,
        max_boxes: usize,
        deadline: Option<Instant>,
    ) -> ErrorEnclosure {
        let (models, floor, bits) = (&self.models, self.floor, self.bits);
        let (mut heap, mut best) = first_boxes(models, bits);
        let mut boxes = models.len();
        // The gap upper − lower at the last check: a search that no longer narrows it
        // (by 1 % in a window of boxes) has met rounding it cannot halve, at a precision too
        // low for the target; it stops there rather than at the deadline.
        // The window is fixed at each check: STALL_BOXES, or twice the boxes then
        // waiting, since the gap narrows only once every box above the new upper bound has
        // been split, and with many segments the heap holds about one such box per model (a
        // fixed window stopped 8192 segments of a helix at an upper bound 90 times the
        // error, at every precision). A window that grew with the heap would never close
        // on a search that rounding stalls, whose heap grows with every split.
        let window = |waiting: usize| STALL_BOXES.max(2 * waiting);
        let mut last_check = (boxes, f64::INFINITY, window(heap.len()));
        let upper = loop {
            crate::cancel::checkpoint();
            let Some(top) = heap.pop() else { break best.0 };
            // No bisection narrows a box below its model's Taylor remainder (both bounds
            // carry it) and the precision floor: stop there too.
            let irreducible = 2.0 * (models[top.model].remainder + floor);
            let gap = top.upper - best.0;
            let done = top.upper <= best.0 * (1.0 + target) || gap <= irreducible;
            if boxes - last_check.0 >= last_check.2 {
                if gap > 0.99 * last_check.1 {
                    break top.upper;
                }
                last_check = (boxes, gap, window(heap.len()));
            }
            if done || boxes >= max_boxes || passed(deadline) {
                break top.upper;
            }
            let (w, centres) = halves(&top.centre, &top.half_width);
            for centre in centres {
                let (lo, up) = box_bounds(&models[top.model], &centre, &w);
                boxes += 1;
                if lo > best.0 {
                    best = (lo, models[top.model].segment);
                }
                if up > best.0 {
                    heap.push(Candidate {
                        upper: up,
                        model: top.model,
                        centre,
                        half_width: w.clone(),
                    });
                }
            }
        };
        ErrorEnclosure {
            lower: Float::with_val(64, best.0),
            upper: Float::with_val(64, upper.max(best.0)),
            segment: best.1,
            boxes,
        }
    }

    /// Where ‖γ − p‖ may reach `threshold`: intervals of u of at most `width` (or whole
    /// boxes at the halving limit) outside which every point of every segment is proven to
    /// have ‖γ(t_k + hu) − p_k(u)‖ < `threshold`. Each model's piece is halved while a box's
    /// proven upper bound is at least the threshold; boxes below it are dropped.
    pub fn regions_reaching(&self, threshold: f64, width: f64) -> Vec<Region> {
        let bits = self.bits;
        self.models
            .par_iter()
            .flat_map_iter(|m| {
                let mut found = Vec::new();
                let mut todo = vec![(Float::with_val(bits, 0), m.half_width.clone(), 0u32)];
                while let Some((centre, half_width, depth)) = todo.pop() {
                    crate::cancel::checkpoint();
                    if box_bounds(m, &centre, &half_width).1 < threshold {
                        continue;
                    }
                    let narrow = half_width.to_f64_round(Round::Up) * 2.0 <= width;
                    if narrow || depth >= MAX_REGION_DEPTH {
                        found.push(Region {
                            segment: m.segment,
                            lo: box_end(m, &centre, &half_width, Round::Down),
                            hi: box_end(m, &centre, &half_width, Round::Up),
                        });
                        continue;
                    }
                    let (w, centres) = halves(&centre, &half_width);
                    for c in centres {
                        todo.push((c, w.clone(), depth + 1));
                    }
                }
                found
            })
            .collect()
    }
}
