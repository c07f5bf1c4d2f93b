//! A proven maximum of a real function of one variable on an interval, by branch and bound
//! in ball arithmetic.
//!
//! The caller gives an **interval extension** f of the function: for a ball X inside
//! [a, b], f(X) is a ball enclosing every value f(x), x ∈ X (natural interval evaluation,
//! or better a mean-value form f(m) + f′(X)(X − m), see [`mean_value`]). The search keeps
//! a list of boxes covering [a, b], each with the upper end of f on it; the box with the
//! largest upper end is halved and both halves evaluated. Every box's midpoint, evaluated
//! as an exact point, gives a proven lower bound of the maximum (the lower end of f at a
//! point the function takes); the largest upper end over the boxes is a proven upper bound.
//! The search stops when upper − lower ≤ the tolerance, or when the box budget is spent
//! (the enclosure is then proven but wider, and says so by its width).
//!
//! Nothing is sampled: a maximum between two sample points is inside some box, whose upper
//! end is never below it. A minimum is the maximum of −f.

use crate::scalar::ball::Ball;
use crate::scalar::{Field, Float};
use rug::float::Round;
use std::cmp::Ordering;
use std::collections::BinaryHeap;

/// When the search stops.
#[derive(Clone, Debug)]
pub struct SearchOptions {
    /// Stop when the proven upper bound exceeds the proven lower bound by at most this much.
    pub tolerance: f64,
    /// Or by at most this fraction of the lower bound's magnitude (0: only `tolerance`).
    pub relative: f64,
    /// The most boxes to evaluate (the enclosure is returned, wider, when they run out).
    pub max_boxes: usize,
    /// The precision of the box ends and of the points evaluated (bits).
    pub bits: u32,
}

impl Default for SearchOptions {
    fn default() -> Self {
        SearchOptions {
            tolerance: 1e-12,
            relative: 0.0,
            max_boxes: 100_000,
            bits: 256,
        }
    }
}

/// A proven enclosure lower ≤ max_{x ∈ [a, b]} f(x) ≤ upper.
#[derive(Clone, Debug)]
pub struct MaximumEnclosure {
    /// A value f takes (proven lower bound of the maximum).
    pub lower: Float,
    /// A proven upper bound of f on the whole interval.
    pub upper: Float,
    /// The point whose value gave `lower` (the maximum is near it when the enclosure is
    /// tight; the maximizer is not proven unique).
    pub at: Float,
    /// The boxes evaluated.
    pub boxes: usize,
}

impl MaximumEnclosure {
    /// The enclosure as one ball [lower, upper].
    pub fn ball(&self) -> Ball {
        Ball::from_bounds(&self.lower, &self.upper)
    }
}

/// Why a maximum was not enclosed.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum SearchError {
    /// The interval is empty or an end is not finite.
    #[error("the interval [{start}, {end}] is empty or not finite")]
    BadInterval {
        /// The start, as given.
        start: String,
        /// The end, as given.
        end: String,
    },
    /// The function could not be evaluated on a box (its own error).
    #[error("evaluating the function on [{lower}, {upper}]: {message}")]
    Evaluation {
        /// The box's lower end.
        lower: String,
        /// The box's upper end.
        upper: String,
        /// The function's error.
        message: String,
    },
    /// The function returned an enclosure that is not finite on a box that could not be
    /// split further (a pole, or an extension too coarse to bound f there).
    #[error("the function has no finite bound on [{lower}, {upper}]")]
    Unbounded {
        /// The box's lower end.
        lower: String,
        /// The box's upper end.
        upper: String,
    },
}

/// A box [lo, hi] and the upper end of f on it, ordered by that upper end (for the heap).
struct Piece {
    lo: Float,
    hi: Float,
    upper: Float,
}

impl PartialEq for Piece {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}
impl Eq for Piece {}
impl PartialOrd for Piece {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for Piece {
    fn cmp(&self, other: &Self) -> Ordering {
        // Upper ends are finite (checked on insertion); ties broken by position so the
        // order, and with it the search, is deterministic.
        self.upper
            .partial_cmp(&other.upper)
            .unwrap_or(Ordering::Equal)
            .then_with(|| other.lo.partial_cmp(&self.lo).unwrap_or(Ordering::Equal))
    }
}

/// A proven enclosure of max_{x ∈ [start, end]} f(x), where `f(X)` encloses f on every ball
/// X inside the interval (see the module doc).
///
/// # Errors
/// [`SearchError::BadInterval`] for an empty or infinite interval; [`SearchError::Evaluation`]
/// when `f` fails on a box; [`SearchError::Unbounded`] when `f` gives no finite bound on a
/// box too narrow to split.
///
/// # Example
/// ```
/// use trajverify::numeric::maximum::{mean_value, midpoint, proven_maximum, SearchOptions};
/// use trajverify::scalar::ball::Ball;
/// use trajverify::scalar::Field;
/// use rug::Float;
/// // f(x) = x(1 − x) on [0, 1]: its maximum is 1/4, at x = 1/2. The mean-value form
/// // f(m) + f′(X)(X − m), with f′(x) = 1 − 2x, keeps the boxes near the top few.
/// let one = Ball::one_in(&128);
/// let f = |x: &Ball| -> Result<Ball, String> {
///     let m = midpoint(x);
///     let slope = one.clone() - &(Ball::from_i64(2, &128) * x);
///     Ok(mean_value(&(m.clone() * &(one.clone() - &m)), &slope, x))
/// };
/// let (a, b) = (Float::with_val(128, 0), Float::with_val(128, 1));
/// let options = SearchOptions { tolerance: 1e-9, ..SearchOptions::default() };
/// let max = proven_maximum(f, (&a, &b), &options).unwrap();
/// assert!(max.lower <= 0.25 && max.upper >= 0.25);
/// assert!(max.upper.to_f64() - max.lower.to_f64() <= 1e-9);
/// ```
pub fn proven_maximum<F>(
    f: F,
    (start, end): (&Float, &Float),
    options: &SearchOptions,
) -> Result<MaximumEnclosure, SearchError>
where
    F: Fn(&Ball) -> Result<Ball, String>,
{
    if !(start.is_finite() && end.is_finite() && start <= end) {
        return Err(SearchError::BadInterval {
            start: start.to_string(),
            end: end.to_string(),
        });
    }
    let bits = options.bits.max(start.prec()).max(end.prec());
    let evaluate = |lo: &Float, hi: &Float| -> Result<Ball, SearchError> {
        f(&Ball::from_bounds_at(lo, hi, bits)).map_err(|message| SearchError::Evaluation {
            lower: lo.to_string(),
            upper: hi.to_string(),
            message,
        })
    };
    let mut frontier = Frontier {
        heap: BinaryHeap::new(),
        best: (Float::with_val(bits, f64::NEG_INFINITY), start.clone()),
        boxes: 0,
        bits,
    };
    frontier.visit(start.clone(), end.clone(), &evaluate)?;
    while let Some(top) = frontier.heap.pop() {
        crate::cancel::checkpoint();
        let gap = Float::with_val_round(64, &top.upper - &frontier.best.0, Round::Up).0;
        let mid = Float::with_val(bits, Float::with_val(bits + 2, &top.lo + &top.hi) / 2u32);
        // Done when the gap is within tolerance or the budget is spent; a box that cannot be
        // split at this precision keeps its bound as final.
        let allowed = options
            .tolerance
            .max(options.relative * frontier.best.0.to_f64().abs());
        if gap.to_f64_round(Round::Up) <= allowed
            || frontier.boxes >= options.max_boxes
            || mid <= top.lo
            || mid >= top.hi
        {
            frontier.heap.push(top);
            break;
        }
        frontier.visit(top.lo, mid.clone(), &evaluate)?;
        frontier.visit(mid, top.hi, &evaluate)?;
    }
    let (lower, at) = frontier.best;
    if !lower.is_finite() {
        return Err(SearchError::Unbounded {
            lower: start.to_string(),
            upper: end.to_string(),
        });
    }
    let upper = frontier
        .heap
        .peek()
        .map_or_else(|| lower.clone(), |p| p.upper.clone());
    Ok(MaximumEnclosure {
        lower,
        upper,
        at,
        boxes: frontier.boxes,
    })
}

/// The search's state: the boxes not yet split, the best proven lower bound and where.
struct Frontier {
    heap: BinaryHeap<Piece>,
    best: (Float, Float),
    boxes: usize,
    bits: u32,
}

impl Frontier {
    /// Evaluate f on [lo, hi] (an upper bound there) and at its midpoint (a lower bound of the
    /// maximum), and keep the box.
    fn visit(
        &mut self,
        lo: Float,
        hi: Float,
        evaluate: &impl Fn(&Float, &Float) -> Result<Ball, SearchError>,
    ) -> Result<(), SearchError> {
        let whole = evaluate(&lo, &hi)?;
        let mid = Float::with_val(self.bits, Float::with_val(self.bits + 2, &lo + &hi) / 2u32);
        let at = evaluate(&mid, &mid)?;
        self.boxes += 2;
        if at.is_finite() && at.lower() > self.best.0 {
            self.best = (at.lower(), mid);
        }
        let mut upper = whole.upper();
        if upper.is_nan() {
            upper = Float::with_val(self.bits, f64::INFINITY);
        }
        if !upper.is_finite() && hi <= next_up(&lo) {
            return Err(SearchError::Unbounded {
                lower: lo.to_string(),
                upper: hi.to_string(),
            });
        }
        self.heap.push(Piece { lo, hi, upper });
        Ok(())
    }
}

/// The next representable number above x at its precision.
fn next_up(x: &Float) -> Float {
    let mut y = x.clone();
    y.next_up();
    y
}

/// The mean-value form of an interval extension: for a box X with midpoint m, every f(x),
/// x ∈ X, lies in f(m) + f′(X)·(X − m), given `at_mid` ⊇ f(m) and `slope` ⊇ f′(X). Its
/// overestimation shrinks with the square of the box's width (natural evaluation: linearly),
/// so a search needs far fewer boxes near a maximum.
pub fn mean_value(at_mid: &Ball, slope: &Ball, x: &Ball) -> Ball {
    let offset = Ball::new(Float::with_val(x.mid().prec(), 0), x.rad());
    at_mid.clone() + &(slope.clone() * &offset)
}

/// The ball of a box's midpoint, exactly (radius 0).
pub fn midpoint(x: &Ball) -> Ball {
    Ball::exact(x.mid().clone())
}

/// Both ends of f's range on [start, end]: (a proven enclosure of the minimum, one of the
/// maximum).
///
/// # Errors
/// As [`proven_maximum`], for either search.
pub fn proven_range<F>(
    f: F,
    (start, end): (&Float, &Float),
    options: &SearchOptions,
) -> Result<(MaximumEnclosure, MaximumEnclosure), SearchError>
where
    F: Fn(&Ball) -> Result<Ball, String>,
{
    let max = proven_maximum(&f, (start, end), options)?;
    let negated = proven_maximum(|x: &Ball| f(x).map(|v| -v), (start, end), options)?;
    let min = MaximumEnclosure {
        lower: -negated.upper,
        upper: -negated.lower,
        at: negated.at,
        boxes: negated.boxes,
    };
    Ok((min, max))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::Real;

    fn unit() -> (Float, Float) {
        (Float::with_val(128, 0), Float::with_val(128, 1))
    }

    #[test]
    fn encloses_a_known_maximum_between_grid_points() {
        // sin(40x) peaks at x = π/80 + k·π/20; the largest on [0, 1] is 1.
        let f = |x: &Ball| -> Result<Ball, String> {
            let forty = Ball::from_i64(40, &128);
            let y = forty.clone() * x;
            // Mean-value form: f′ = 40 cos(40x) on the box.
            Ok(mean_value(
                &(forty.clone() * &midpoint(x)).sin(),
                &(forty * &y.cos()),
                x,
            ))
        };
        let (a, b) = unit();
        let options = SearchOptions {
            tolerance: 1e-20,
            ..SearchOptions::default()
        };
        let max = proven_maximum(f, (&a, &b), &options).unwrap();
        assert!(max.lower <= 1.0 && max.upper >= 1.0);
        assert!(Float::with_val(128, &max.upper - &max.lower) <= 1e-20);
    }

    #[test]
    fn a_range_and_its_errors() {
        let (a, b) = unit();
        let options = SearchOptions {
            tolerance: 1e-12,
            ..SearchOptions::default()
        };
        let (min, max) = proven_range(
            |x: &Ball| Ok(x.clone() - &Ball::from_f64(0.5, &128)),
            (&a, &b),
            &options,
        )
        .unwrap();
        assert!(min.lower <= -0.5 && min.upper >= -0.5);
        assert!(max.lower <= 0.5 && max.upper >= 0.5);
        let failing = proven_maximum(|_: &Ball| Err("no value".to_string()), (&a, &b), &options);
        assert!(matches!(failing, Err(SearchError::Evaluation { .. })));
        assert!(matches!(
            proven_maximum(|x: &Ball| Ok(x.clone()), (&b, &a), &options),
            Err(SearchError::BadInterval { .. })
        ));
    }

    #[test]
    fn a_small_budget_still_gives_a_proven_enclosure() {
        let (a, b) = unit();
        let options = SearchOptions {
            tolerance: 0.0,
            relative: 0.0,
            max_boxes: 10,
            bits: 128,
        };
        let f = |x: &Ball| -> Result<Ball, String> { Ok(x.clone() * &(Ball::one_in(&128) - x)) };
        let max = proven_maximum(f, (&a, &b), &options).unwrap();
        assert!(max.lower <= 0.25 && max.upper >= 0.25);
        assert!(max.boxes <= 12);
    }
}
