//! Natural splines on proven parametrizations, for the claims about the splines of paper 004
//! (Figs. 3–5, Table VII, overshoots and oscillations).
//!
//! A parametrization is carried as balls: chord length (Eq. 5) evaluated in ball arithmetic,
//! or a minimizer proven by Krawczyk's test ([`crate::algo::param::proven`]), each with its
//! spacings hᵢ enclosed. The natural spline on it (the tridiagonal system of Sec. 3) is then
//! solved in balls, so every θ″(tᵢ), every maximum over the knots (θ″ is piecewise linear) and
//! every root of θ′ (a quadratic per interval) is an enclosure of the value on the proven
//! parametrization itself, not on a rounded copy of it. A comparison of two balls that
//! overlap cannot be decided: [`decided`] runs a computation under a tally of such
//! comparisons and turns any into an error, so a claim built on it is proven or fails.

use crate::algo::param::natural::NaturalCubicSpline;
use crate::algo::param::objective::{chord_length_spacing, knots_from_spacing};
use crate::algo::param::proven::ProvenMinimum;
use crate::scalar::ball::{tally, Ball};
use crate::scalar::{Field, Float};
use rug::float::Round;

/// The working precision of the proven parametrizations (bits).
pub const BITS: u32 = 256;

/// A parametrization with every spacing and knot enclosed.
#[derive(Clone, Debug)]
pub struct ProvenKnots {
    /// Its name in the paper ("t^CL", "t^EX (Eq. 31)", …).
    pub name: &'static str,
    /// The spacings hᵢ = tᵢ − tᵢ₋₁, each enclosed.
    pub h: Vec<Ball>,
    /// The knots t₀ = 0, …, t_N = 1, each enclosed.
    pub knots: Vec<Ball>,
}

impl ProvenKnots {
    /// Normalized accumulated chord length (Eq. 5) of the points whose coordinates are the
    /// `components` (each a column of balls), in ball arithmetic.
    pub fn chord(name: &'static str, components: &[Vec<Ball>]) -> ProvenKnots {
        let h = chord_length_spacing(components);
        let knots = knots_from_spacing(&h, &BITS);
        ProvenKnots { name, h, knots }
    }

    /// Exact knots (a printed column), as exact balls where the binary format holds them and
    /// tight enclosures where it does not; the order is decided on the exact values.
    ///
    /// # Errors
    /// The first knot not above the one before it.
    pub fn exact(
        name: &'static str,
        knots: &[crate::scalar::BigRational],
    ) -> Result<ProvenKnots, String> {
        if let Some(i) = (1..knots.len()).find(|&i| knots[i] <= knots[i - 1]) {
            return Err(format!("{name}: knot {i} is not above the one before it"));
        }
        let h: Vec<_> = knots.windows(2).map(|w| w[1].clone() - &w[0]).collect();
        Ok(ProvenKnots {
            name,
            h: balls(&h),
            knots: balls(knots),
        })
    }

    /// The knots of a proven minimizer.
    pub fn minimizer(name: &'static str, minimum: &ProvenMinimum) -> ProvenKnots {
        ProvenKnots {
            name,
            h: minimum.h.clone(),
            knots: minimum.knots.clone(),
        }
    }

    /// The natural spline through `values` on these knots, in balls.
    ///
    /// # Errors
    /// A spacing not proven positive (the knots would not be proven to increase), or the
    /// spline's error (lengths), naming the parametrization.
    pub fn spline(&self, values: &[Ball]) -> Result<NaturalCubicSpline<Ball>, String> {
        if let Some(i) = self.h.iter().position(|h| h.lower() <= 0) {
            return Err(format!(
                "{}: spacing h{} is not proven positive",
                self.name,
                i + 1
            ));
        }
        NaturalCubicSpline::with_spacings(self.knots.clone(), self.h.clone(), values.to_vec())
            .map_err(|e| format!("the spline on {}: {e}", self.name))
    }
}

/// Exact rationals (data or printed knots) as balls at [`BITS`].
pub fn balls(values: &[crate::scalar::BigRational]) -> Vec<Ball> {
    values
        .iter()
        .map(|q| Ball::from_rational(q, &BITS))
        .collect()
}

/// max |θ″| over [t₀, t_N]: θ″ is piecewise linear, so the maximum modulus is at a knot; an
/// enclosure of the largest |mᵢ| (no comparison is taken: the hull of the candidates).
pub fn max_abs_second<T: Field>(spline: &NaturalCubicSpline<T>) -> Option<T> {
    let m = spline.second_derivatives_at_knots();
    let first = m.first()?.abs();
    Some(m[1..].iter().fold(first, |a, x| a.max_with(&x.abs())))
}

/// The third derivative on each interval, (mᵢ − mᵢ₋₁)/hᵢ, i = 1…N (θ‴ is piecewise constant).
pub fn third_derivatives<T: Field>(spline: &NaturalCubicSpline<T>, h: &[T]) -> Vec<T> {
    let m = spline.second_derivatives_at_knots();
    (1..m.len())
        .map(|i| (m[i].clone() - &m[i - 1]) / &h[i - 1])
        .collect()
}

/// Run `f` counting the ball comparisons it could not decide.
///
/// # Errors
/// `f`'s own error, or how many comparisons were undecided (the result would rest on a guess).
pub fn decided<R>(f: impl FnOnce() -> Result<R, String>) -> Result<R, String> {
    let (result, undecided) = tally(f);
    let value = result?;
    if undecided > 0 {
        return Err(format!(
            "{undecided} comparison(s) of enclosures could not be decided at {BITS} bits"
        ));
    }
    Ok(value)
}

/// A proven upper bound of how far the spline leaves the range of its end values on piece i
/// — its overshoot (paper 004, Corollary 3 (i)): θ enclosed over each root of θ′
/// ([`NaturalCubicSpline::slope_roots`]) against the end values' range. `None` as that.
pub fn overshoot_bound(spline: &NaturalCubicSpline<Ball>, h: &Ball, i: usize) -> Option<f64> {
    let bits = h.mid().prec();
    let zero = Ball::zero_in(&bits);
    let ends = [
        spline.eval_offsets(h, &zero, i)[0].clone(),
        spline.eval_offsets(&zero, h, i)[0].clone(),
    ];
    let (lo, hi) = (ends[0].min_with(&ends[1]), ends[0].max_with(&ends[1]));
    let mut worst = 0.0f64;
    for v in spline.slope_roots(i)? {
        let value = spline.eval_offsets(&(h.clone() - &v), &v, i)[0].clone();
        let above = Float::with_val(64, value.upper() - hi.lower()).to_f64_round(Round::Up);
        let below = Float::with_val(64, lo.upper() - value.lower()).to_f64_round(Round::Up);
        worst = worst.max(above).max(below);
    }
    Some(worst)
}
