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
use super::{Blend, GerbsError, Knots, Located};
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
            let (a, b) = (knots.at(j), knots.at(j + 1));
            // S_j divides every value of the basis, so it is narrowed to 2^(6−p) of itself
            // (the integrator's default leaves 2^(16−p)): a first pass gives its size.
            let rough = proven_integral(erbs, knots, j, a, b, &options);
            let size = rough.mid().to_f64().abs();
            if !rough.is_finite() || size == 0.0 {
                return rough;
            }
            proven_integral(erbs, knots, j, a, b, &absolute(&options, size, 6, a.ctx()))
        });
        Ok(ProvenErbs { erbs, options })
    }

    /// S_j = ∫ Ψ_j over its interval (Eq. 5), proven.
    pub fn normalizer(&self, j: usize) -> &Ball {
        self.erbs.normalizer(j)
    }

    /// ∫_lo^hi Ψ_j, proven (an unbounded ball when it cannot be enclosed).
    pub fn integral(&self, knots: &Knots<Ball>, j: usize, lo: &Ball, hi: &Ball) -> Ball {
        proven_integral(&self.erbs, knots, j, lo, hi, &self.options)
    }
}

/// `options` with the absolute tolerance size · 2^(spare − bits): `spare` bits short of the
/// working precision `bits`, relative to a known size.
fn absolute(options: &IntegralOptions, size: f64, spare: i32, bits: u32) -> IntegralOptions {
    IntegralOptions {
        tolerance: Some(size * (2f64).powi(spare - bits.min(1000) as i32)),
        ..options.clone()
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
    // Ends known only as balls (a knot 1/3, a rounded t) are replaced by their exact
    // midpoints, and ∫ between an end and its midpoint is at most the radius: 0 < Ψ ≤ 1, its
    // exponent being −β·N/D ≤ 0. (The kernel's series is not finite on a ball that reaches
    // past a knot, so the integrator's own end bound would refuse there.)
    let slack = lo.rad() + hi.rad();
    let (lo, hi) = (Ball::exact(lo.mid().clone()), Ball::exact(hi.mid().clone()));
    if hi.mid() <= lo.mid() {
        // Equal exact ends: 0; a span shorter than the ends' rounding: within the slack of 0;
        // exact ends in the wrong order: not an integral this function is asked for.
        return if hi.mid() == lo.mid() || slack > 0.0 {
            Ball::zero_in(&bits).widen(slack * (1.0 + 1e-15))
        } else {
            unbounded()
        };
    }
    let mut cuts = vec![lo.clone()];
    if let Some(c) = erbs.break_points(knots, j).into_iter().next() {
        // Any cut is valid; the exact midpoint of the centre's ball keeps every end exact.
        let c = Ball::exact(c.mid().clone());
        if lo.decide_lt(&c) == Some(true) && c.decide_lt(&hi) == Some(true) {
            cuts.push(c);
        }
    }
    cuts.push(hi.clone());
    let mut total = Ball::zero_in(&bits).widen(slack * (1.0 + 1e-15));
    for w in cuts.windows(2) {
        match integrate_with(&series, &bound, (&w[0], &w[1]), options) {
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
    let (lower, upper) = kernel_range(erbs, knots, j, p, q)?;
    let bits = p.prec().max(q.prec());
    let width = Float::with_val(bits + 1, q - p);
    let hi = Float::with_val(bits + 64, &upper * &width);
    let lo = Float::with_val(bits + 64, &lower * &width);
    (hi.is_finite() && lo <= hi)
        .then(|| Ball::from_bounds(&lo, &hi).widen(hi.to_f64().abs() * 1e-15))
}

/// Bounds (lower, upper) of Ψ_j over the part of [p, q] inside interval j, from bounds of its
/// numerator and denominator there (see the module doc); where the denominator is not proven
/// positive (a piece reaching into a knot's ball) 0 ≤ Ψ ≤ 1. `None` only when a bound is not
/// finite.
fn kernel_range(
    erbs: &Erbs<Ball>,
    knots: &Knots<Ball>,
    j: usize,
    p: &Float,
    q: &Float,
) -> Option<(Float, Float)> {
    let bits = p.prec().max(q.prec());
    let params = erbs.params(j);
    let (a, b) = (knots.at(j), knots.at(j + 1));
    let piece = Ball::from_bounds(p, q);
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
    // Ψ ≤ exp(−β N_min / D_max) where D_max is proven positive, else Ψ ≤ 1 (its exponent is
    // ≤ 0: a piece that reaches into a knot's ball); Ψ ≥ exp(−β N_max / D_min) where
    // D_min > 0, else Ψ ≥ 0.
    let upper = match denominator(&left.1, &right.1) {
        Some(d_max) => (-(params.beta.clone() * &n_min / &d_max)).exp().upper(),
        None => Float::with_val(bits, 1),
    };
    let upper = if upper > 1 {
        Float::with_val(bits, 1)
    } else {
        upper
    };
    let lower = denominator(&left.0, &right.0)
        .map(|d_min| (-(params.beta.clone() * &n_max / &d_min)).exp().lower())
        .filter(|l| l.is_finite() && *l >= 0)
        .unwrap_or(zero);
    (upper.is_finite() && lower <= upper).then_some((lower, upper))
}

impl Blend<Ball> for ProvenErbs {
    fn built_on(&self) -> Option<&[Ball]> {
        self.erbs.built_on()
    }

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
        self.pair_located(knots, &Located::from_t(knots, t, j), order)
    }

    fn pair_located(
        &self,
        knots: &Knots<Ball>,
        at: &Located<Ball>,
        order: usize,
    ) -> (Taylor<Ball>, Taylor<Ball>) {
        self.erbs.pair_with(knots, at, order, &|lo, hi| {
            self.integral(knots, at.interval, lo, hi)
        })
    }

    fn slope(&self, knots: &Knots<Ball>, j: usize, t: &Ball) -> Ball {
        self.erbs.slope(knots, j, t)
    }

    fn slope_series(&self, knots: &Knots<Ball>, j: usize, t: &Ball, order: usize) -> Taylor<Ball> {
        self.erbs.slope_series(knots, j, t, order)
    }

    /// Ψ_j/S_j bounded over the piece as in the module doc.
    fn slope_range(&self, knots: &Knots<Ball>, j: usize, lo: &Ball, hi: &Ball) -> Option<Ball> {
        let (lower, upper) = kernel_range(&self.erbs, knots, j, &lo.lower(), &hi.upper())?;
        Some(Ball::from_bounds(&lower, &upper) / self.erbs.normalizer(j))
    }

    fn break_points(&self, knots: &Knots<Ball>, j: usize) -> Vec<Ball> {
        self.erbs.break_points(knots, j)
    }

    fn sweeps(&self) -> bool {
        true
    }

    /// F_j(to) − F_j(from) to an absolute tolerance of 2^(8−p) (F_j lies in [0, 1]): a
    /// sweep along the path needs F_j's value, not the tiny increments' relative digits,
    /// which next to a knot would cost thousands of pieces each.
    fn increment(&self, knots: &Knots<Ball>, j: usize, from: &Ball, to: &Ball) -> Ball {
        let s = self.erbs.normalizer(j);
        // The working precision is the knots' (an exact point carries as many bits as its
        // binary expansion needs).
        let bits = knots.at(j).ctx();
        let options = absolute(&self.options, s.mid().to_f64().abs(), 8, bits);
        proven_integral(&self.erbs, knots, j, from, to, &options) / s
    }
}
