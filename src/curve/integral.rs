//! Proven integrals: ∫ₐᵇ f enclosed in a ball, by Taylor models with a proven remainder.
//!
//! The integrand is given by its Taylor series ([`Taylor`] over [`Ball`]): `f(t, order)` is
//! the series of f at t to `order`, and at a ball t it encloses f⁽ᵏ⁾(ξ)/k! for every ξ of the
//! ball (Taylor arithmetic on balls is an interval extension of each coefficient). On a piece
//! [c − h, c + h] Taylor's theorem with the Lagrange remainder gives
//!
//! ∫_{c−h}^{c+h} f = Σ_{k even ≤ N} 2 f_k(c) h^{k+1}/(k+1) + R,
//! |R| ≤ sup_{ξ ∈ piece} |f_{N+1}(ξ)| · 2 h^{N+2}/(N+2),
//!
//! with f_k = f⁽ᵏ⁾/k!: the first sum from the series at the exact midpoint c, the bound from
//! the series at the whole piece. The pieces are refined adaptively — the piece whose
//! enclosure is widest is halved — until the sum's radius is below the tolerance, the
//! precision floor stops the narrowing, or the piece budget is spent; whichever ends it, the
//! ball returned encloses the integral (a budget only leaves it wider). Ends given as balls
//! (a knot like 1/3) add their own radius times a bound of |f| over them.
//!
//! This is the quadrature of the proven path lengths (paper 003's GERBS paths, `run
//! gerbs-path` in MPFR and balls): there tanh–sinh estimates, this proves.
//!
//! ```
//! use trajverify::curve::integral::{integrate, IntegralOptions};
//! use trajverify::curve::taylor::Taylor;
//! use trajverify::scalar::ball::Ball;
//! use trajverify::scalar::{Field, Real};
//!
//! // ∫₀¹ eᵗ dt = e − 1, proven.
//! let bits = 128;
//! let exp = |t: &Ball, order: usize| Some(Taylor::variable(t.clone(), order).exp());
//! let (a, b) = (Ball::zero_in(&bits), Ball::one_in(&bits));
//! let result = integrate(&exp, (&a, &b), &IntegralOptions::default()).unwrap();
//! let e_minus_1 = Ball::one_in(&bits).exp() - &Ball::one_in(&bits);
//! assert!(result.value.rad() < 1e-30);
//! assert!(result.value.contains(e_minus_1.mid()));
//! ```

use crate::curve::taylor::Taylor;
use crate::scalar::ball::Ball;
use crate::scalar::{Field, Float};
use std::collections::BinaryHeap;

/// How an integral is refined.
#[derive(Clone, Debug)]
pub struct IntegralOptions {
    /// The order N of the Taylor models (the remainder is of order h^(N+2)).
    pub order: usize,
    /// The absolute radius the enclosure aims for; `None`: 2^(16−p) of the integral's size.
    pub tolerance: Option<f64>,
    /// The most pieces (each costs two series evaluations).
    pub max_pieces: usize,
    /// The pieces [a, b] is split into before any refinement.
    pub initial_pieces: usize,
}

impl Default for IntegralOptions {
    fn default() -> Self {
        IntegralOptions {
            order: 16,
            tolerance: None,
            max_pieces: 4096,
            initial_pieces: 4,
        }
    }
}

/// A proven integral and how it was reached.
#[derive(Clone, Debug)]
pub struct ProvenIntegral {
    /// A ball containing the integral.
    pub value: Ball,
    /// The pieces used.
    pub pieces: usize,
    /// Whether the tolerance was reached (otherwise the ball is proven but wider).
    pub reached: bool,
}

/// Why an integral could not be enclosed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum IntegralError {
    /// The integrand has no finite enclosure on a piece that cannot be split further (a
    /// singularity, or a function undefined there), near t.
    #[error("the integrand has no finite enclosure near t = {t}")]
    NotFinite {
        /// The piece's midpoint, as a double.
        t: f64,
    },
    /// b < a, an end that is not finite, or an order of 0.
    #[error("the interval or options are not usable: {0}")]
    Invalid(String),
}

/// The integrand: its Taylor series, and the bound of a piece where the series fails.
struct Integrand<'a, F> {
    series: &'a F,
    bound: &'a dyn Fn(&Float, &Float) -> Option<Ball>,
}

/// One piece [lo, hi] (exact MPFR ends) and its enclosure.
struct Piece {
    lo: Float,
    hi: Float,
    value: Ball,
}

impl PartialEq for Piece {
    fn eq(&self, other: &Self) -> bool {
        self.value.rad() == other.value.rad()
    }
}
impl Eq for Piece {}
impl PartialOrd for Piece {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for Piece {
    /// The widest enclosure first (radii are never NaN: a piece without a finite enclosure
    /// is split or refused before it is queued).
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        self.value.rad().total_cmp(&other.value.rad())
    }
}

/// ∫ₐᵇ f enclosed in a ball (see the module doc); `f(t, order)` is the Taylor series of the
/// integrand at t, `None` where it is not defined.
///
/// # Errors
/// [`IntegralError::Invalid`] for b < a (as balls, decided on their midpoints), an end that is
/// not finite, or order 0; [`IntegralError::NotFinite`] when a piece narrower than 2^−(p−8)
/// of the interval still has no finite enclosure.
pub fn integrate(
    f: &impl Fn(&Ball, usize) -> Option<Taylor<Ball>>,
    (a, b): (&Ball, &Ball),
    options: &IntegralOptions,
) -> Result<ProvenIntegral, IntegralError> {
    integrate_with(f, &|_, _| None, (a, b), options)
}

/// [`integrate`] for an integrand whose Taylor models fail on some pieces (an essential
/// singularity at an end, |t − c|^σ at a point c): `bound(lo, hi)` encloses ∫ over the piece
/// [lo, hi] some other way (from bounds of f there), `None` if it cannot. Every piece keeps
/// the narrower of the two enclosures, so the bound also serves where the series is finite
/// but wide. Pieces are halved like the others, so a bound that shrinks with the piece
/// converges.
///
/// # Errors
/// As [`integrate`].
pub fn integrate_with(
    f: &impl Fn(&Ball, usize) -> Option<Taylor<Ball>>,
    bound: &dyn Fn(&Float, &Float) -> Option<Ball>,
    (a, b): (&Ball, &Ball),
    options: &IntegralOptions,
) -> Result<ProvenIntegral, IntegralError> {
    if options.order == 0 {
        return Err(IntegralError::Invalid("order 0".into()));
    }
    if !a.is_finite() || !b.is_finite() {
        return Err(IntegralError::Invalid("an end is not finite".into()));
    }
    let bits = a.ctx().max(b.ctx());
    let (lo, hi) = (a.mid().clone(), b.mid().clone());
    if hi < lo {
        return Err(IntegralError::Invalid("b < a".into()));
    }
    let ends = ends_contribution(f, (a, b))?;
    let integrand = Integrand { series: f, bound };
    if lo == hi {
        return Ok(ProvenIntegral {
            value: ends,
            pieces: 0,
            reached: true,
        });
    }
    let width = Float::with_val(bits + 64, &hi - &lo);
    let smallest = Float::with_val(64, &width) >> (bits.saturating_sub(8)).min(1 << 20);
    let mut queue = BinaryHeap::new();
    let initial = options.initial_pieces.clamp(1, options.max_pieces.max(1));
    for i in 0..initial {
        // Equal pieces; consecutive ones share the (deterministically rounded) cut exactly.
        let at = |k: usize| match k {
            0 => lo.clone(),
            k if k == initial => hi.clone(),
            k => Float::with_val(
                bits + 64,
                &lo + Float::with_val(bits + 64, &width * k as u32) / initial as u32,
            ),
        };
        split_into(
            &integrand,
            at(i),
            at(i + 1),
            options.order,
            &smallest,
            &mut queue,
        )?;
    }
    refine(&integrand, queue, &ends, bits, &smallest, options)
}

/// Halve the widest piece until the sum's radius meets the tolerance (see the module doc).
fn refine<F: Fn(&Ball, usize) -> Option<Taylor<Ball>>>(
    f: &Integrand<'_, F>,
    mut queue: BinaryHeap<Piece>,
    ends: &Ball,
    bits: u32,
    smallest: &Float,
    options: &IntegralOptions,
) -> Result<ProvenIntegral, IntegralError> {
    let mut count = queue.len();
    loop {
        crate::cancel::checkpoint();
        let total = sum(&queue, ends);
        let target = options.tolerance.unwrap_or_else(|| {
            (total.mid().to_f64().abs() * (2f64).powi(16 - bits.min(1000) as i32))
                .max(f64::MIN_POSITIVE)
        });
        if total.rad() <= target {
            return Ok(ProvenIntegral {
                value: total,
                pieces: count,
                reached: true,
            });
        }
        let unfinished = |total: Ball, count: usize| ProvenIntegral {
            value: total,
            pieces: count,
            reached: false,
        };
        if count >= options.max_pieces {
            return Ok(unfinished(total, count));
        }
        let Some(piece) = queue.pop() else {
            return Ok(unfinished(total, count));
        };
        // The precision floor: halving no longer narrows a piece this narrow.
        if Float::with_val(64, &piece.hi - &piece.lo) <= *smallest {
            queue.push(piece);
            return Ok(unfinished(total, count));
        }
        let mid = midpoint(&piece.lo, &piece.hi);
        split_into(
            f,
            piece.lo,
            mid.clone(),
            options.order,
            smallest,
            &mut queue,
        )?;
        split_into(f, mid, piece.hi, options.order, smallest, &mut queue)?;
        count += 1;
    }
}

/// Ends known only as balls (a knot like 1/3): ∫ over [a, mid a] and [mid b, b] is at most
/// the radius times a bound of |f| over the end's ball, as a ball around 0.
fn ends_contribution(
    f: &impl Fn(&Ball, usize) -> Option<Taylor<Ball>>,
    (a, b): (&Ball, &Ball),
) -> Result<Ball, IntegralError> {
    let mut ends = Ball::zero_in(&a.ctx().max(b.ctx()));
    for end in [a, b] {
        if end.rad() > 0.0 {
            let bound = value_bound(f, end)?;
            ends = ends.widen(bound * end.rad() * (1.0 + 1e-15));
        }
    }
    Ok(ends)
}

/// The sum of every piece's enclosure and the ends' contribution, accumulated 32 bits above
/// the working precision: thousands of additions rounded at p bits would otherwise leave a
/// floor of (pieces · 2^−p) of the sum that no refinement narrows.
fn sum(queue: &BinaryHeap<Piece>, ends: &Ball) -> Ball {
    let mut total = Ball::zero_in(&(ends.ctx() + 32));
    total += ends;
    for p in queue.iter() {
        total += &p.value;
    }
    total
}

/// (lo + hi)/2, exactly (one bit more than the ends).
fn midpoint(lo: &Float, hi: &Float) -> Float {
    let prec = lo.prec().max(hi.prec()) + 1;
    Float::with_val(prec, lo + hi) / 2u32
}

/// Enclose ∫ over [lo, hi] and queue it; a piece without a finite enclosure is halved until
/// it has one or is narrower than `smallest` (then the integrand is not finite there).
fn split_into<F: Fn(&Ball, usize) -> Option<Taylor<Ball>>>(
    integrand: &Integrand<'_, F>,
    lo: Float,
    hi: Float,
    order: usize,
    smallest: &Float,
    queue: &mut BinaryHeap<Piece>,
) -> Result<(), IntegralError> {
    let mut pending = vec![(lo, hi)];
    while let Some((lo, hi)) = pending.pop() {
        crate::cancel::checkpoint();
        // Both are enclosures of one integral: the narrower is kept (next to an essential
        // singularity the series may be finite but far wider than the range's bound).
        let series = piece_integral(integrand.series, &lo, &hi, order);
        let bound = (integrand.bound)(&lo, &hi).filter(Field::is_finite);
        let enclosed = match (series, bound) {
            (Some(s), Some(b)) => Some(if b.rad() < s.rad() { b } else { s }),
            (s, b) => s.or(b),
        };
        match enclosed {
            Some(value) => queue.push(Piece { lo, hi, value }),
            None => {
                let mid = midpoint(&lo, &hi);
                if Float::with_val(64, &hi - &lo) <= *smallest {
                    return Err(IntegralError::NotFinite { t: mid.to_f64() });
                }
                pending.push((lo, mid.clone()));
                pending.push((mid, hi));
            }
        }
    }
    Ok(())
}

/// The Taylor model's enclosure of ∫ over [lo, hi], or `None` when the integrand's series is
/// not finite there.
fn piece_integral(
    f: &impl Fn(&Ball, usize) -> Option<Taylor<Ball>>,
    lo: &Float,
    hi: &Float,
    order: usize,
) -> Option<Ball> {
    let prec = lo.prec().max(hi.prec()) + 1;
    let c = Ball::exact(midpoint(lo, hi));
    let h = Ball::exact(Float::with_val(prec, hi - lo) / 2u32);
    let at_mid = f(&c, order)?;
    let over = f(&Ball::from_bounds(lo, hi), order + 1)?;
    let remainder_coefficient = over.c.get(order + 1)?.clone();
    if !remainder_coefficient.is_finite() {
        return None;
    }
    // Σ_{k even} 2 f_k h^{k+1}/(k+1), with h^{k+1} carried along.
    let mut total = Ball::zero_in(&prec);
    let mut power = h.clone(); // h^{k+1}
    let h2 = h.clone() * &h;
    for (k, coefficient) in at_mid.c.iter().enumerate().take(order + 1) {
        if k % 2 == 0 {
            let term = coefficient.clone() * &power * &Ball::from_ratio(2, k as i64 + 1, &prec);
            total += &term;
            power *= &h2;
        }
    }
    // |R| ≤ sup |f_{N+1}| · 2 h^{N+2}/(N+2).
    // The three factors are upper bounds; their product is rounded up by the 1 + 2⁻⁵⁰ margin
    // (two roundings of a positive product).
    let bound = remainder_coefficient.abs_upper()
        * (2.0 / (order as f64 + 2.0) * (1.0 + f64::EPSILON))
        * crate::scalar::powi(&h, order as u32 + 2).abs_upper();
    let value = total.widen(bound * (1.0 + 1e-15));
    value.is_finite().then_some(value)
}

/// An upper bound of |f| over the ball `t` (the series' constant term there).
fn value_bound(
    f: &impl Fn(&Ball, usize) -> Option<Taylor<Ball>>,
    t: &Ball,
) -> Result<f64, IntegralError> {
    let v = f(t, 0)
        .and_then(|s| s.c.first().cloned())
        .filter(Field::is_finite)
        .ok_or(IntegralError::NotFinite { t: t.to_f64() })?;
    Ok(v.abs_upper())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::Real;

    fn series(
        f: impl Fn(Taylor<Ball>) -> Taylor<Ball>,
    ) -> impl Fn(&Ball, usize) -> Option<Taylor<Ball>> {
        move |t: &Ball, order: usize| Some(f(Taylor::variable(t.clone(), order)))
    }

    #[test]
    fn encloses_known_integrals_to_the_precision() {
        let bits = 256;
        // ∫₀^π sin = 2, with π a ball (an end known only as an enclosure).
        let sin = series(|t| t.sin());
        let (a, b) = (Ball::zero_in(&bits), Ball::pi(&bits));
        let r = integrate(&sin, (&a, &b), &IntegralOptions::default()).unwrap();
        assert!(r.reached, "{r:?}");
        assert!(r.value.contains(&Float::with_val(bits, 2)), "{r:?}");
        assert!(r.value.rad() < 1e-60, "{r:?}");
        // ∫₀¹ 1/(1 + t²) = π/4: the series' remainder must hold at the interval's ball.
        let arctan_slope = series(|t| {
            let one = Taylor::constant(Ball::one_in(&bits));
            one.clone() / &(one + &(t.clone() * &t))
        });
        let r = integrate(
            &arctan_slope,
            (&a, &Ball::one_in(&bits)),
            &IntegralOptions::default(),
        )
        .unwrap();
        let quarter_pi = Ball::pi(&bits) / &Ball::from_i64(4, &bits);
        assert!(r.value.contains(quarter_pi.mid()), "{r:?}");
        assert!(r.value.rad() < 1e-60, "{r:?}");
    }

    #[test]
    fn a_budget_leaves_a_wider_ball_that_still_encloses() {
        let bits = 128;
        let exp = series(|t| (t.clone() * &t).exp());
        let options = IntegralOptions {
            order: 2,
            max_pieces: 8,
            ..IntegralOptions::default()
        };
        let r = integrate(
            &exp,
            (&Ball::zero_in(&bits), &Ball::from_i64(3, &bits)),
            &options,
        )
        .unwrap();
        assert!(!r.reached);
        // ∫₀³ e^{t²} = 1444.545122…
        let value = Float::with_val(bits, 1444.545122);
        assert!(r.value.contains(&value), "{r:?}");
    }

    #[test]
    fn a_singularity_is_an_error_and_bad_intervals_are_refused() {
        let bits = 128;
        let reciprocal = series(|t| Taylor::constant(Ball::one_in(&bits)) / &t);
        let e = integrate(
            &reciprocal,
            (&Ball::from_i64(-1, &bits), &Ball::one_in(&bits)),
            &IntegralOptions::default(),
        );
        assert!(matches!(e, Err(IntegralError::NotFinite { .. })), "{e:?}");
        let e = integrate(
            &reciprocal,
            (&Ball::from_i64(2, &bits), &Ball::one_in(&bits)),
            &IntegralOptions::default(),
        );
        assert!(matches!(e, Err(IntegralError::Invalid(_))), "{e:?}");
    }
}
