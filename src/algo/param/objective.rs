//! The smoothness objective G(h) of paper 004 (Eqs. 1, 31, 34).
//!
//! G(h) = Σₗ α_l⁻² ∫₀¹ (θˡ″)² dt, θˡ the natural cubic spline through (tᵢ, zᵢˡ) with
//! tᵢ = h₁ + … + hᵢ. In algebraic form (Eq. 31) each term is zᵀQᵀM⁻¹Qz = (Qz)·m with m the
//! interior second derivatives ([`super::natural`]); Eq. 34 replaces M by its diagonal M̂,
//! which needs no tridiagonal solve: Σᵢ (Qz)ᵢ²/Mᵢᵢ.

use super::natural::{NaturalCubicSpline, SplineError};
use crate::scalar::Field;

/// Which form of G to evaluate.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Objective {
    /// Eq. 31 (exact: the true integral of θ″²).
    Exact,
    /// Eq. 34 (M replaced by its diagonal).
    Approximate,
}

/// The knots tᵢ = h₁ + … + hᵢ, t₀ = 0.
pub fn knots_from_spacing<T: Field>(h: &[T], ctx: &T::Ctx) -> Vec<T> {
    let mut t = vec![T::zero_in(ctx)];
    for hi in h {
        let next = t[t.len() - 1].clone() + hi;
        t.push(next);
    }
    t
}

/// Check what [`objective`] and its gradient read: at least two points, every component
/// of `h.len()` + 1 points, one weight per component ([`super::descent::check_problem`]),
/// and every spacing a positive finite number (knot i + 1 above knot i). Returns the
/// context of `h`.
///
/// # Errors
/// [`SplineError::TooFewKnots`], [`SplineError::LengthMismatch`] or
/// [`SplineError::WeightCount`] for the shape; [`SplineError::NotIncreasing`] naming the
/// knot after the first spacing that is not positive and finite.
pub fn check_spacing<T: Field>(h: &[T], z: &[Vec<T>], alpha: &[T]) -> Result<T::Ctx, SplineError> {
    super::descent::check_problem(h.len(), z, alpha)?;
    // check_problem saw two points or more, so h has an entry.
    let ctx = h.first().map(Field::ctx).ok_or(SplineError::TooFewKnots)?;
    let zero = T::zero_in(&ctx);
    if let Some(i) = h
        .iter()
        .position(|hi| !hi.is_finite() || zero.decide_lt(hi) != Some(true))
    {
        return Err(SplineError::NotIncreasing { index: i + 1 });
    }
    Ok(ctx)
}

/// (Qz)ᵢ, i = 1…N−1: the second divided differences times their spacing structure.
fn q_times<T: Field>(h: &[T], z: &[T]) -> Vec<T> {
    (1..h.len())
        .map(|i| (z[i + 1].clone() - &z[i]) / &h[i] - &((z[i].clone() - &z[i - 1]) / &h[i - 1]))
        .collect()
}

/// G(h) for K components `z[l]` (each of length N+1) with weights α_l.
///
/// # Errors
/// Those of [`check_spacing`]: the shape of the problem ([`SplineError::TooFewKnots`],
/// [`SplineError::LengthMismatch`], [`SplineError::WeightCount`]) and
/// [`SplineError::NotIncreasing`] for a spacing hᵢ that is not a positive finite number.
pub fn objective<T: Field>(
    h: &[T],
    z: &[Vec<T>],
    alpha: &[T],
    form: Objective,
) -> Result<T, SplineError> {
    let ctx = check_spacing(h, z, alpha)?;
    let t = knots_from_spacing(h, &ctx);
    let mut total = T::zero_in(&ctx);
    for (zl, al) in z.iter().zip(alpha) {
        let qz = q_times(h, zl);
        let term = match form {
            Objective::Exact => {
                let spline = NaturalCubicSpline::new(t.clone(), zl.clone())?;
                let m = spline.second_derivatives_at_knots();
                qz.iter()
                    .zip(&m[1..])
                    .fold(T::zero_in(&ctx), |acc, (a, b)| acc + &(a.clone() * b))
            }
            Objective::Approximate => {
                let three = T::from_i64(3, &ctx);
                qz.iter().enumerate().fold(T::zero_in(&ctx), |acc, (i, a)| {
                    acc + &(a.clone() * a * &three / &(h[i].clone() + &h[i + 1]))
                })
            }
        };
        total += &(term / &(al.clone() * al));
    }
    Ok(total)
}

/// Normalized accumulated chord length (Eq. 5) as a spacing h: hᵢ = dᵢ / Σⱼ dⱼ with dᵢ the
/// Euclidean distance between points i−1 and i, the points given by their `components`
/// (`z[l][i]` is coordinate l of point i). Fewer than two points have no spacing (empty);
/// components of different lengths are read to the shortest; coincident points (total length
/// zero) get the uniform spacing.
pub fn chord_length_spacing<T: crate::scalar::Real>(components: &[Vec<T>]) -> Vec<T> {
    let Some(ctx) = components.first().and_then(|c| c.first()).map(|x| x.ctx()) else {
        return Vec::new();
    };
    let n = components.iter().map(Vec::len).min().unwrap_or(0);
    if n < 2 {
        return Vec::new();
    }
    let d: Vec<T> = (1..n)
        .map(|i| {
            let mut sq = T::zero_in(&ctx);
            for c in components {
                let delta = c[i].clone() - &c[i - 1];
                sq.mul_add_assign(&delta, &delta);
            }
            sq.sqrt()
        })
        .collect();
    let total = d.iter().fold(T::zero_in(&ctx), |a, x| a + x);
    if total.is_zero() {
        let uniform = T::one_in(&ctx) / &T::from_i64(d.len() as i64, &ctx);
        return vec![uniform; d.len()];
    }
    d.iter().map(|x| x.clone() / &total).collect()
}
