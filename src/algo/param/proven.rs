//! Proven minimizers of Marin's objective: existence, uniqueness and location of the
//! minimizing spacings in a ball, and a proof that they are a strict local minimum.
//!
//! The minimizer of G(h) on the simplex Σhᵢ = 1 (paper 004, Eqs. 30–31) solves the optimality
//! system
//!
//!   F(h, μ) = (∇G(h) − μ·1, Σhᵢ − 1) = 0,   J = [[∇²G, −1], [1ᵀ, 0]],
//!
//! whose zero Newton's method approximates ([`super::descent::refine`]). Krawczyk's test
//! ([`crate::numeric::krawczyk`]) turns that approximation into a proof: ∇G in balls, the
//! Hessian over the whole box by differentiating the same gradient code in dual numbers over
//! balls, and K(X) ⊂ X proves that exactly one stationary point lies in the box. The reduced
//! Hessian ZᵀHZ on the plane Σhᵢ = 0 (Z = [I; −1ᵀ], eliminating h_N) is then factored as LDLᵀ
//! in balls over the same box; every pivot proven positive makes it positive definite at
//! every point of the box, so the stationary point is a strict local minimum of G on the
//! simplex. (Uniqueness of the *global* minimizer is not proven here; paper 004 proves it for
//! one component, Corollary 2.) G is then evaluated over the box: an enclosure of the minimum.
//!
//! ```
//! use trajverify::algo::param::descent::{descend, refine};
//! use trajverify::algo::param::objective::{chord_length_spacing, Objective};
//! use trajverify::algo::param::proven::prove_minimum;
//! use trajverify::scalar::ball::Ball;
//! use trajverify::scalar::{Field, Float};
//!
//! // Four points in the plane, one component per coordinate.
//! let z64 = vec![vec![0.0, 1.0, 1.5, 0.5], vec![0.0, 0.2, 1.0, 1.5]];
//! let rough = descend(chord_length_spacing(&z64), &z64, &[1.0, 1.0], Objective::Exact, &mut |_, _| {}).unwrap();
//! let bits = 128;
//! let z: Vec<Vec<Float>> = z64.iter().map(|c| c.iter().map(|&v| Float::with_val(bits, v)).collect()).collect();
//! let one = Float::with_val(bits, 1);
//! let minimum = refine(&rough, &z, &[one.clone(), one], Objective::Exact).unwrap();
//! let h: Vec<Float> = minimum.knots.windows(2).map(|w| Float::with_val(bits, &w[1] - &w[0])).collect();
//! let zb: Vec<Vec<Ball>> = z64.iter().map(|c| c.iter().map(|&v| Ball::from_f64(v, &bits)).collect()).collect();
//! let proven = prove_minimum(&h, &zb, &[Ball::one_in(&bits), Ball::one_in(&bits)], Objective::Exact).unwrap();
//! assert!(proven.knots[1].rad() < 1e-30);
//! assert!(proven.knots[1].contains(&minimum.knots[1]));
//! ```

use super::gradient::gradient;
use super::natural::SplineError;
use super::objective::{objective, Objective};
use crate::numeric::krawczyk::{krawczyk, KrawczykError};
use crate::numeric::linalg::{ldl_pivots, Matrix};
use crate::scalar::ball::Ball;
use crate::scalar::dual::Dual;
use crate::scalar::{Field, Float};

/// A minimizer of G on the simplex, proven (see the module doc).
#[derive(Clone, Debug)]
pub struct ProvenMinimum {
    /// The spacings hᵢ, each enclosed.
    pub h: Vec<Ball>,
    /// The knots t₀ = 0, tᵢ = h₁ + … + hᵢ (the last is 1).
    pub knots: Vec<Ball>,
    /// The multiplier μ of the constraint.
    pub multiplier: Ball,
    /// G at the minimizer, enclosed.
    pub objective: Ball,
}

/// Why a minimizer was not proven.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ProvenMinimumError {
    /// The problem itself is malformed ([`super::objective::check_spacing`]).
    #[error("{0}")]
    Problem(SplineError),
    /// Krawczyk's test did not prove a stationary point near the approximation.
    #[error("no stationary point proven near the approximation: {0}")]
    Stationary(KrawczykError),
    /// The reduced Hessian is not proven positive definite over the box (a saddle, or too
    /// little precision to tell).
    #[error("the reduced Hessian is not proven positive definite: not proven a minimum")]
    NotPositiveDefinite,
}

/// The minimizer of G near the spacings `approx` (exact MPFR numbers on the simplex, e.g.
/// Newton's result), for components `z` and weights `alpha` given as balls.
///
/// # Errors
/// [`ProvenMinimumError`]: the shape of the problem, no stationary point proven, or not a
/// proven minimum.
pub fn prove_minimum(
    approx: &[Float],
    z: &[Vec<Ball>],
    alpha: &[Ball],
    form: Objective,
) -> Result<ProvenMinimum, ProvenMinimumError> {
    let n = approx.len();
    let bits = approx.iter().map(Float::prec).max().unwrap_or(64);
    let exact: Vec<Ball> = approx.iter().cloned().map(Ball::exact).collect();
    let g = gradient(&exact, z, alpha, form).map_err(ProvenMinimumError::Problem)?;
    // μ̃: the mean gradient (the multiplier for which ∇G − μ1 is ⟂ 1).
    let mean = g.iter().fold(Ball::zero_in(&bits), |a, x| a + x) / &Ball::from_i64(n as i64, &bits);
    let mut start = approx.to_vec();
    start.push(mean.mid().clone());
    let system = |x: &[Ball]| -> Option<Vec<Ball>> {
        let (h, mu) = x.split_at(n);
        let mut f: Vec<Ball> = gradient(h, z, alpha, form)
            .ok()?
            .into_iter()
            .map(|gi| gi - &mu[0])
            .collect();
        f.push(h.iter().fold(Ball::zero_in(&bits), |a, x| a + x) - &Ball::one_in(&bits));
        Some(f)
    };
    let jacobian = |x: &[Ball]| -> Option<Matrix<Ball>> {
        let hessian = hessian(&x[..n], z, alpha, form)?;
        let mut j = Matrix::zeros(n + 1, n + 1, &bits);
        for r in 0..n {
            for c in 0..n {
                j[(r, c)] = hessian[(r, c)].clone();
            }
            j[(r, n)] = -Ball::one_in(&bits);
            j[(n, r)] = Ball::one_in(&bits);
        }
        Some(j)
    };
    let zero = krawczyk(&start, system, jacobian).map_err(ProvenMinimumError::Stationary)?;
    let (h, mu) = zero.split_at(n);
    let hessian_over = hessian(h, z, alpha, form).ok_or(ProvenMinimumError::NotPositiveDefinite)?;
    if !reduced_positive_definite(&hessian_over) {
        return Err(ProvenMinimumError::NotPositiveDefinite);
    }
    let mut knots = vec![Ball::zero_in(&bits)];
    for hi in &h[..n - 1] {
        let next = knots[knots.len() - 1].clone() + hi;
        knots.push(next);
    }
    knots.push(Ball::one_in(&bits));
    let objective = objective(h, z, alpha, form).map_err(ProvenMinimumError::Problem)?;
    Ok(ProvenMinimum {
        h: h.to_vec(),
        knots,
        multiplier: mu[0].clone(),
        objective,
    })
}

/// ∇²G over the box `h`: column k is the derivative of ∇G along hₖ, by the gradient code in
/// dual numbers over balls; `None` where G is not defined on the box.
fn hessian(h: &[Ball], z: &[Vec<Ball>], alpha: &[Ball], form: Objective) -> Option<Matrix<Ball>> {
    let n = h.len();
    let bits = h.first()?.ctx();
    let zd: Vec<Vec<Dual<Ball>>> = z
        .iter()
        .map(|c| c.iter().cloned().map(Dual::constant).collect())
        .collect();
    let ad: Vec<Dual<Ball>> = alpha.iter().cloned().map(Dual::constant).collect();
    let mut out = Matrix::zeros(n, n, &bits);
    for k in 0..n {
        crate::cancel::checkpoint();
        let column = gradient(&Dual::seeded(h, k), &zd, &ad, form).ok()?;
        for (i, c) in column.into_iter().enumerate() {
            out[(i, k)] = c.du;
        }
    }
    Some(out)
}

/// Whether ZᵀHZ (Z = [I; −1ᵀ]: h_N eliminated by Σhᵢ = 1) is positive definite at every point
/// of the ball matrix H: an LDLᵀ factorization in balls whose every pivot is proven positive.
fn reduced_positive_definite(h: &Matrix<Ball>) -> bool {
    let n = h.rows();
    if n < 2 {
        return true;
    }
    let m = n - 1;
    let last = n - 1;
    let mut r = Matrix::zeros(m, m, &h[(0, 0)].ctx());
    for i in 0..m {
        for j in 0..m {
            r[(i, j)] = h[(i, j)].clone() - &h[(i, last)] - &h[(last, j)] + &h[(last, last)];
        }
    }
    let zero = Ball::zero_in(&h[(0, 0)].ctx());
    ldl_pivots(&r).is_some_and(|pivots| pivots.iter().all(|d| zero.decide_lt(d) == Some(true)))
}
