//! The ERBS basis proven: its integrals (S_j of Eq. 5 and F_j of Eq. 3) enclosed by Taylor
//! models with a proven remainder ([`crate::curve::integral`]) instead of estimated by
//! tanh–sinh, so every value and derivative of the basis is a ball that contains it.
//!
//! The kernel Ψ_j = exp(−β|t − c|^{2σ}/((t − t_j)(t_{j+1} − t)^γ)^α) has an essential
//! singularity at both knots (every derivative vanishes there) and, for 2σ not an even
//! integer, a kink of |t − c|^{2σ} at its centre c. On the pieces that touch those points the
//! Taylor models are not finite; there the integral over [lo, hi] is bounded from the
//! kernel's range instead: 0 < Ψ ≤ exp(−g_min) with g_min = β·N_min/D_max, where N is the
//! numerator |t − c|^{2σ} and D the denominator, each bounded over the piece (N_min is the
//! distance to c raised to 2σ, 0 when the piece reaches c; D_max is finite on a piece inside
//! the interval), and Ψ ≥ exp(−g_max) with g_max = β·N_max/D_min when D_min > 0. Near a knot
//! exp(−g_min) is astronomically small, near c the bound's width shrinks like the piece's
//! width^(1+2σ): the adaptive halving converges either way.

use super::erbs::{CentreReading, Erbs, ErbsParams};
use super::{Blend, GerbsError, Knots};
use crate::curve::integral::{integrate_with, IntegralOptions};
use crate::curve::taylor::Taylor;
use crate::scalar::ball::Ball;
use crate::scalar::{Field, Float, Real};

/// An ERBS basis over balls whose integrals are proven.
#[derive(Clone, Debug)]
pub struct ProvenErbs {
    erbs: Erbs<Ball>,
    options: IntegralOptions,
}

impl ProvenErbs {
    /// The basis on `knots` with `params` (one set, or one per knot interval); every S_j is
    /// proven. An integral that cannot be enclosed makes S_j an unbounded ball, so every
    /// value that depends on it is refused where it is printed.
    ///
    /// # Errors
    /// As [`Erbs::new`]: a parameter count that is neither one nor one per interval.
    pub fn new(
        knots: &Knots<Ball>,
        params: Vec<ErbsParams<Ball>>,
        reading: CentreReading,
        options: IntegralOptions,
    ) -> Result<Self, GerbsError> {
        super::erbs::check_param_count(knots, &params)?;
        let erbs = Erbs::with_normalizers(knots, params, reading, |erbs, j| {
            proven_integral(erbs, knots, j, knots.at(j), knots.at(j + 1), &options)
        });
        Ok(ProvenErbs { erbs, options })
    }

    /// ∫_lo^hi Ψ_j, proven (an unbounded ball when it cannot be enclosed).
    pub fn integral(&self, knots: &Knots<Ball>, j: usize, lo: &Ball, hi: &Ball) -> Ball {
        proven_integral(&self.erbs, knots, j, lo, hi, &self.options)
    }
}

/// ∫_lo^hi Ψ_j for t_j ≤ lo ≤ hi ≤ t_{j+1}, split at the centre where |t − c|^{2σ} has a
/// kink; an unbounded ball when it is not proven.
fn proven_integral(
    erbs: &Erbs<Ball>,
    knots: &Knots<Ball>,
    j: usize,
    lo: &Ball,
    hi: &Ball,
    options: &IntegralOptions,
) -> Ball {
    let bits = lo.ctx();
    let unbounded = || Ball::new(Float::with_val(bits, 0), f64::INFINITY);
    let (a, b) = (knots.at(j), knots.at(j + 1));
    let series = |t: &Ball, order: usize| -> Option<Taylor<Ball>> {
        let var = Taylor::variable(t.clone(), order);
        let left = var.clone() - &Taylor::constant(a.clone());
        let right = Taylor::constant(b.clone()) - &var;
        let psi = erbs.kernel(knots, j, &left, &right, |v| Taylor::constant(v.clone()));
        psi.c.iter().all(Field::is_finite).then_some(psi)
    };
    let bound = |p: &Float, q: &Float| piece_bound(erbs, knots, j, p, q);
    let mut cuts = vec![lo.clone()];
    if let Some(c) = erbs.break_points(knots, j).into_iter().next() {
        if lo.decide_lt(&c) == Some(true) && c.decide_lt(hi) == Some(true) {
            cuts.push(c);
        }
    }
    cuts.push(hi.clone());
    let mut total = Ball::zero_in(&bits);
    for w in cuts.windows(2) {
        match integrate_with(&series, &bound, &w[0], &w[1], options) {
            Ok(piece) => total += &piece.value,
            Err(_) => return unbounded(),
        }
    }
    total
}

/// An enclosure of ∫ Ψ_j over [p, q] from bounds of Ψ there (see the module doc), for the
/// pieces where its Taylor models are not finite.
fn piece_bound(
    erbs: &Erbs<Ball>,
    knots: &Knots<Ball>,
    j: usize,
    p: &Float,
    q: &Float,
) -> Option<Ball> {
    let bits = p.prec().max(q.prec());
    let params = erbs.params(j);
    let (a, b) = (knots.at(j), knots.at(j + 1));
    let piece = Ball::from_bounds(p, q);
    let width = Ball::exact(Float::with_val(bits + 1, q - p));
    let zero = Float::with_val(bits, 0);
    // |t − c| over the piece: its lowest point (0 when the piece reaches c) and its highest.
    let offset = piece.clone() - &erbs.centre_point(knots, j);
    let (lo_off, hi_off) = (offset.lower(), offset.upper());
    let far = if lo_off.clone().abs() > hi_off.clone().abs() {
        lo_off.clone().abs()
    } else {
        hi_off.clone().abs()
    };
    let near = if lo_off <= zero && hi_off >= zero {
        zero.clone()
    } else if lo_off > zero {
        lo_off
    } else {
        hi_off.abs()
    };
    let two_sigma = params.sigma.clone() * &Ball::from_i64(2, &bits);
    let power = |x: Float| -> Ball {
        if x.is_zero() {
            Ball::zero_in(&bits)
        } else {
            (two_sigma.clone() * &Ball::exact(x).ln()).exp()
        }
    };
    let (n_min, n_max) = (power(near), power(far));
    // D = ((t − t_j)(t_{j+1} − t)^γ)^α over the piece, from its extreme factors.
    let left = (Ball::exact(p.clone()) - a, Ball::exact(q.clone()) - a);
    let right = (
        b.clone() - &Ball::exact(q.clone()),
        b.clone() - &Ball::exact(p.clone()),
    );
    let denominator = |l: &Ball, r: &Ball| -> Option<Ball> {
        let zero_ball = Ball::zero_in(&bits);
        if params.alpha.is_zero() {
            return Some(Ball::one_in(&bits));
        }
        if zero_ball.decide_lt(l) != Some(true) || zero_ball.decide_lt(r) != Some(true) {
            return None;
        }
        Some((params.alpha.clone() * &(l.ln() + &(params.gamma.clone() * &r.ln()))).exp())
    };
    let d_max = denominator(&left.1, &right.1)?;
    // Ψ ≤ exp(−β N_min / D_max); Ψ ≥ exp(−β N_max / D_min) where D_min > 0, else Ψ ≥ 0.
    let upper = (-(params.beta.clone() * &n_min / &d_max)).exp().upper();
    let lower = denominator(&left.0, &right.0)
        .map(|d_min| (-(params.beta.clone() * &n_max / &d_min)).exp().lower())
        .filter(|l| l.is_finite() && *l >= 0)
        .unwrap_or(zero);
    let hi = Float::with_val(bits + 64, &upper * width.mid());
    let lo = Float::with_val(bits + 64, &lower * width.mid());
    (hi.is_finite() && lo <= hi)
        .then(|| Ball::from_bounds(&lo, &hi).widen(hi.to_f64().abs() * 1e-15))
}

impl Blend<Ball> for ProvenErbs {
    fn rising(&self, knots: &Knots<Ball>, j: usize, t: &Ball, order: usize) -> Taylor<Ball> {
        self.pair(knots, j, t, order).1
    }

    fn falling(&self, knots: &Knots<Ball>, j: usize, t: &Ball, order: usize) -> Taylor<Ball> {
        self.pair(knots, j, t, order).0
    }

    fn pair(
        &self,
        knots: &Knots<Ball>,
        j: usize,
        t: &Ball,
        order: usize,
    ) -> (Taylor<Ball>, Taylor<Ball>) {
        self.erbs.pair_with(knots, j, t, order, &|lo, hi| {
            self.integral(knots, j, lo, hi)
        })
    }

    fn slope(&self, knots: &Knots<Ball>, j: usize, t: &Ball) -> Ball {
        self.erbs.slope(knots, j, t)
    }

    fn break_points(&self, knots: &Knots<Ball>, j: usize) -> Vec<Ball> {
        self.erbs.break_points(knots, j)
    }

    fn sweeps(&self) -> bool {
        true
    }

    fn increment(&self, knots: &Knots<Ball>, j: usize, from: &Ball, to: &Ball) -> Ball {
        self.integral(knots, j, from, to) / self.erbs.normalizer(j)
    }
}
