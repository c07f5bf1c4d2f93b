//! Gradient projection for min G(h) over the simplex B = {h ≥ 0, Σhᵢ = 1} (paper 004, Eq. 30).
//!
//! h⁽ⁱ⁾ = h⁽ⁱ⁻¹⁾ − λ·π_B(∇G), with λ minimizing f(λ) = G(h − λp) on [0, λ_max] (λ_max: the largest
//! step keeping every hᵢ ≥ 0). The line search is exact in the sense of the paper: it solves
//! f′(λ) = −∇G(h − λp)·p = 0, which has f′(0) = −‖p‖² < 0 and f′ → +∞ towards λ_max (G is
//! infinite where a spacing vanishes for data with zᵢ ≠ zᵢ₊₁), by the Illinois variant of
//! regula falsi on a bracket inside (0, λ_max) until the bracket or f′ is at the working
//! precision. The iteration stops when ‖π_B(∇G)‖ ≤ `tolerance`·‖π_B(∇G(h⁽⁰⁾))‖ or after
//! `max_iterations`; both are reported, so a result that stopped on the iteration limit is
//! visible as such.
//!
//! The project minimizes G in two stages, [`descend`] then [`polish`]: gradient projection in
//! f64 only has to land in Newton's basin (relative tolerance [`DESCENT_TOLERANCE`], at most
//! [`DESCENT_MAX_ITERATIONS`] iterations), and Newton's method on the optimality system
//! ([`newton_polish`], at most [`NEWTON_MAX_STEPS`] steps) then converges quadratically at
//! any precision. Every caller (the `marin` command and the paper-004 claims) uses this one
//! pipeline.

use super::gradient::{gradient, project};
use super::natural::SplineError;
use super::objective::{chord_length_spacing, knots_from_spacing, objective, Objective};
use crate::scalar::{Field, Real};

/// Where and how the iteration stopped.
#[derive(Clone, Debug)]
pub struct Descent<T> {
    /// The knot spacings h_i found.
    pub h: Vec<T>,
    /// The objective G(h) there.
    pub objective: T,
    /// The number of iterations used.
    pub iterations: usize,
    /// ‖π_B(∇G)‖ at the final h.
    pub projected_gradient_norm: T,
    /// ‖π_B(∇G)‖ at the start, for the relative stopping rule.
    pub initial_gradient_norm: T,
    /// Whether the relative tolerance was met (otherwise the iteration limit stopped it).
    pub converged: bool,
}

fn dot<T: Field>(a: &[T], b: &[T]) -> T {
    let mut acc = T::zero_in(&a[0].ctx());
    for (x, y) in a.iter().zip(b) {
        acc.mul_add_assign(x, y);
    }
    acc
}

fn step<T: Field>(h: &[T], p: &[T], lambda: &T) -> Vec<T> {
    h.iter()
        .zip(p)
        .map(|(x, d)| x.clone() - &(lambda.clone() * d))
        .collect()
}

/// The f64 descent stops when ‖π_B(∇G)‖ has fallen by this factor from its start…
pub const DESCENT_TOLERANCE: f64 = 1e-6;
/// … or after this many iterations.
pub const DESCENT_MAX_ITERATIONS: usize = 5000;
/// The shape of a problem: at least two points, every component with the same number of
/// points, one weight α per component and `spacings` = points − 1 (so no entry point indexes
/// past its data).
///
/// # Errors
/// [`SplineError::TooFewKnots`], [`SplineError::LengthMismatch`] or
/// [`SplineError::WeightCount`], naming what differs.
pub fn check_problem<T>(spacings: usize, z: &[Vec<T>], alpha: &[T]) -> Result<(), SplineError> {
    let n = z.first().map_or(0, Vec::len);
    if n < 2 {
        return Err(SplineError::TooFewKnots);
    }
    if let Some(c) = z.iter().find(|c| c.len() != n) {
        return Err(SplineError::LengthMismatch {
            knots: n,
            values: c.len(),
        });
    }
    if alpha.len() != z.len() {
        return Err(SplineError::WeightCount {
            weights: alpha.len(),
            components: z.len(),
        });
    }
    if spacings != n - 1 {
        return Err(SplineError::LengthMismatch {
            knots: spacings + 1,
            values: n,
        });
    }
    Ok(())
}

/// The most Newton steps [`polish`] takes (it stops earlier when a step no longer changes h).
pub const NEWTON_MAX_STEPS: usize = 60;

/// Stage one: gradient projection in f64 from `h0`, calling `observe(i, h⁽ⁱ⁾)` after every
/// iteration (pass `&mut |_, _| {}` when nothing is observed).
///
/// # Errors
/// As [`gradient_projection_observed`].
pub fn descend(
    h0: Vec<f64>,
    z: &[Vec<f64>],
    alpha: &[f64],
    form: Objective,
    observe: &mut dyn FnMut(usize, &[f64]),
) -> Result<Descent<f64>, SplineError> {
    gradient_projection_observed(
        h0,
        z,
        alpha,
        form,
        &DESCENT_TOLERANCE,
        DESCENT_MAX_ITERATIONS,
        observe,
    )
}

/// Stage two: Newton's method in the number type of `z` from the f64 descent's end point.
///
/// # Errors
/// Those of [`check_problem`] for `rough.h`, `z` and `alpha`; then those of [`newton_polish`].
pub fn polish<T: Real>(
    rough: &Descent<f64>,
    z: &[Vec<T>],
    alpha: &[T],
    form: Objective,
) -> Result<Vec<T>, SplineError> {
    polish_outcome(rough, z, alpha, form).map(|o| o.h)
}

/// [`polish`], saying how Newton's method stopped.
fn polish_outcome<T: Real>(
    rough: &Descent<f64>,
    z: &[Vec<T>],
    alpha: &[T],
    form: Objective,
) -> Result<NewtonOutcome<T>, SplineError> {
    check_problem(rough.h.len(), z, alpha)?;
    let ctx = alpha[0].ctx();
    let start = rough.h.iter().map(|x| T::from_f64(*x, &ctx)).collect();
    newton_polish_outcome(start, z, alpha, form, NEWTON_MAX_STEPS)
}

/// A minimizing parametrization with the quantities that describe it.
#[derive(Clone, Debug)]
pub struct Minimum<T> {
    /// The knots t_0 = 0 < … < t_N = 1 (Eq. 30's variables accumulated).
    pub knots: Vec<T>,
    /// G at the minimizer.
    pub objective: T,
    /// G at normalized chord length, the descent's starting point, for comparison.
    pub chord_objective: T,
    /// ‖π_B(∇G)‖ at the minimizer: the stopping rule's quantity, at the working precision.
    pub projected_gradient_norm: T,
    /// The f64 gradient projection's iterations.
    pub descent_iterations: usize,
    /// Whether the gradient projection met its relative tolerance ([`DESCENT_TOLERANCE`])
    /// rather than stopping on its iteration budget.
    pub descent_converged: bool,
    /// Newton's steps in the working precision.
    pub newton_steps: usize,
    /// Whether Newton's method stopped because a step no longer changed h (at 4 ulps of the
    /// working precision), rather than on [`NEWTON_MAX_STEPS`] or a singular system.
    pub newton_converged: bool,
}

impl<T> Minimum<T> {
    /// Whether both stages converged: the knots are the minimizer to the working precision.
    /// When it is false the knots are the last iterate, not a minimizer.
    pub fn converged(&self) -> bool {
        self.descent_converged && self.newton_converged
    }
}

/// Stage two with its summary: [`polish`] in the number type of `z`, then G there and at
/// chord length, and the norm of the projected gradient at the result.
///
/// # Errors
/// As [`polish`]; with [`Objective::Exact`] also [`SplineError::NotIncreasing`] when the
/// polished h, or the chord-length spacing of `z` (coincident consecutive points), has a
/// spacing ≤ 0.
pub fn refine<T: Real>(
    rough: &Descent<f64>,
    z: &[Vec<T>],
    alpha: &[T],
    form: Objective,
) -> Result<Minimum<T>, SplineError> {
    check_problem(rough.h.len(), z, alpha)?;
    let ctx = alpha[0].ctx();
    let newton = polish_outcome(rough, z, alpha, form)?;
    let h = newton.h;
    let objective_at = objective(&h, z, alpha, form)?;
    let chord_objective = objective(&chord_length_spacing(z), z, alpha, form)?;
    let p = project(&gradient(&h, z, alpha, form)?);
    let projected_gradient_norm = p
        .iter()
        .fold(T::zero_in(&ctx), |acc, x| acc + x.clone() * x)
        .sqrt();
    Ok(Minimum {
        knots: knots_from_spacing(&h, &ctx),
        objective: objective_at,
        chord_objective,
        projected_gradient_norm,
        descent_iterations: rough.iterations,
        descent_converged: rough.converged,
        newton_steps: newton.steps,
        newton_converged: newton.converged,
    })
}

/// Minimize G from `h0` (a point of B with all hᵢ > 0).
///
/// # Errors
/// As [`gradient_projection_observed`].
pub fn gradient_projection<T: Real>(
    h0: Vec<T>,
    z: &[Vec<T>],
    alpha: &[T],
    form: Objective,
    tolerance: &T,
    max_iterations: usize,
) -> Result<Descent<T>, SplineError> {
    gradient_projection_observed(
        h0,
        z,
        alpha,
        form,
        tolerance,
        max_iterations,
        &mut |_, _| {},
    )
}

/// [`gradient_projection`], calling `observe(i, h⁽ⁱ⁾)` after every iteration.
///
/// # Errors
/// Those of [`check_problem`] for `h0`, `z` and `alpha`; with [`Objective::Exact`] also
/// [`SplineError::NotIncreasing`] when `h0` or an iterate has a spacing ≤ 0 (e.g. a
/// chord-length start for coincident consecutive points).
pub fn gradient_projection_observed<T: Real>(
    h0: Vec<T>,
    z: &[Vec<T>],
    alpha: &[T],
    form: Objective,
    tolerance: &T,
    max_iterations: usize,
    observe: &mut dyn FnMut(usize, &[T]),
) -> Result<Descent<T>, SplineError> {
    check_problem(h0.len(), z, alpha)?;
    let ctx = h0[0].ctx();
    let zero = T::zero_in(&ctx);
    let mut h = h0;
    let mut p = project(&gradient(&h, z, alpha, form)?);
    let initial = dot(&p, &p).sqrt();
    let mut norm = initial.clone();
    let mut iterations = 0;
    let target = tolerance.clone() * &initial;
    while iterations < max_iterations && norm > target && !norm.is_zero() {
        crate::cancel::checkpoint();
        // λ_max: the first spacing to reach zero along −p.
        let lambda_max = h
            .iter()
            .zip(&p)
            .filter(|(_, d)| **d > zero)
            .map(|(x, d)| x.clone() / d)
            .fold(None, |m: Option<T>, v| match m {
                Some(m) if m <= v => Some(m),
                _ => Some(v),
            });
        let Some(lambda_max) = lambda_max else { break };
        let slope = |lambda: &T| -> Result<T, SplineError> {
            Ok(-dot(&gradient(&step(&h, &p, lambda), z, alpha, form)?, &p))
        };
        // Bracket: f′(0) < 0; move the upper end towards λ_max until f′ > 0.
        let two = T::from_i64(2, &ctx);
        let (mut lo, mut f_lo) = (zero.clone(), -dot(&p, &p));
        let mut hi = lambda_max.clone() / &two;
        let mut f_hi = slope(&hi)?;
        let mut gap = lambda_max.clone() / &two;
        let mut guard = 0;
        while f_hi < zero && guard < 200 {
            lo = hi.clone();
            f_lo = f_hi;
            gap /= &two;
            hi = lambda_max.clone() - &gap;
            f_hi = slope(&hi)?;
            guard += 1;
        }
        let lambda = if f_hi < zero {
            hi
        } else {
            illinois(&slope, lo, f_lo, hi, f_hi, T::epsilon(&ctx))?
        };
        h = step(&h, &p, &lambda);
        p = project(&gradient(&h, z, alpha, form)?);
        norm = dot(&p, &p).sqrt();
        iterations += 1;
        observe(iterations, &h);
    }
    let value = objective(&h, z, alpha, form)?;
    Ok(Descent {
        converged: norm <= target,
        h,
        objective: value,
        iterations,
        projected_gradient_norm: norm,
        initial_gradient_norm: initial,
    })
}

/// A root of `f` in [lo, hi] with f(lo) < 0 < f(hi), by regula falsi with the Illinois
/// modification (superlinear, always bracketed).
fn illinois<T: Real>(
    f: &dyn Fn(&T) -> Result<T, SplineError>,
    mut lo: T,
    mut f_lo: T,
    mut hi: T,
    mut f_hi: T,
    eps: T,
) -> Result<T, SplineError> {
    let ctx = lo.ctx();
    let zero = T::zero_in(&ctx);
    let half = T::from_ratio(1, 2, &ctx);
    let mut last_side = 0i8;
    for _ in 0..(4 * T::precision_bits(&ctx) as usize) {
        let width = hi.clone() - &lo;
        if width <= eps.clone() * &hi.abs() {
            break;
        }
        let x = lo.clone() - &(f_lo.clone() * &width / &(f_hi.clone() - &f_lo));
        // Guard against a point on the bracket's edge (no progress): bisect instead.
        let x = if x <= lo || x >= hi {
            (lo.clone() + &hi) * &half
        } else {
            x
        };
        let fx = f(&x)?;
        if fx.is_zero() {
            return Ok(x);
        }
        if fx < zero {
            lo = x;
            f_lo = fx;
            if last_side == -1 {
                f_hi *= &half;
            }
            last_side = -1;
        } else {
            hi = x;
            f_hi = fx;
            if last_side == 1 {
                f_lo *= &half;
            }
            last_side = 1;
        }
    }
    Ok((lo + &hi) * &half)
}

/// Newton's method on the optimality system ∇G(h) − μ·1 = 0, Σhᵢ = 1, from a nearby `h`
/// (e.g. a gradient projection iterate): each step solves
/// [[∇²G, 1], [1ᵀ, 0]]·[δh; δμ] = [μ1 − ∇G; 1 − Σhᵢ], with the Hessian's columns obtained exactly
/// (to the working precision) by evaluating the gradient in dual numbers. Stops after
/// `steps` steps or when a step no longer changes h at the working precision.
///
/// # Errors
/// Those of [`super::objective::check_spacing`] for `h` or an iterate: the shape of the
/// problem, or a spacing that is not positive and finite. A singular Newton system ends the
/// iteration without an error.
pub fn newton_polish<T: Real>(
    h: Vec<T>,
    z: &[Vec<T>],
    alpha: &[T],
    form: Objective,
    steps: usize,
) -> Result<Vec<T>, SplineError> {
    newton_polish_outcome(h, z, alpha, form, steps).map(|o| o.h)
}

/// Where Newton's method stopped and why.
#[derive(Clone, Debug)]
pub struct NewtonOutcome<T> {
    /// The last iterate.
    pub h: Vec<T>,
    /// The steps taken.
    pub steps: usize,
    /// Whether the last step was below 4 ulps of the working precision (otherwise the step
    /// limit or a singular system stopped it).
    pub converged: bool,
}

/// [`newton_polish`], saying how it stopped.
///
/// # Errors
/// Those of [`newton_polish`].
pub fn newton_polish_outcome<T: Real>(
    mut h: Vec<T>,
    z: &[Vec<T>],
    alpha: &[T],
    form: Objective,
    steps: usize,
) -> Result<NewtonOutcome<T>, SplineError> {
    use crate::numeric::linalg::{solve, Matrix};
    use crate::scalar::dual::Dual;
    let ctx = super::objective::check_spacing(&h, z, alpha)?;
    let n = h.len();
    let zd: Vec<Vec<Dual<T>>> = z
        .iter()
        .map(|c| c.iter().cloned().map(Dual::constant).collect())
        .collect();
    let ad: Vec<Dual<T>> = alpha.iter().cloned().map(Dual::constant).collect();
    let (mut taken, mut converged) = (0, false);
    for _ in 0..steps {
        crate::cancel::checkpoint();
        let g = gradient(&h, z, alpha, form)?;
        let mut hessian = Matrix::zeros(n + 1, n + 1, &ctx);
        for k in 0..n {
            let hd = Dual::seeded(&h, k);
            let column = gradient(&hd, &zd, &ad, form)?;
            for (i, c) in column.iter().enumerate() {
                hessian[(i, k)] = c.du.clone();
            }
            hessian[(n, k)] = T::one_in(&ctx);
            hessian[(k, n)] = T::one_in(&ctx);
        }
        // μ estimate: the mean gradient (the multiplier for which μ1 − ∇G is ⟂ 1).
        let mean = g.iter().fold(T::zero_in(&ctx), |a, x| a + x) / &T::from_i64(n as i64, &ctx);
        let mut rhs: Vec<T> = g.iter().map(|x| mean.clone() - x).collect();
        // The constraint row restores Σhᵢ = 1 (a start rounded from another precision misses it).
        let total = h.iter().fold(T::zero_in(&ctx), |a, x| a + x);
        rhs.push(T::one_in(&ctx) - &total);
        let Ok(delta) = solve(&hessian, &rhs) else {
            break;
        };
        let size = delta[..n]
            .iter()
            .fold(T::zero_in(&ctx), |m, d| crate::scalar::max_of(m, d.abs()));
        h = h.iter().zip(&delta).map(|(x, d)| x.clone() + d).collect();
        taken += 1;
        if size <= T::epsilon(&ctx) * &T::from_i64(4, &ctx) {
            converged = true;
            break;
        }
    }
    Ok(NewtonOutcome {
        h,
        steps: taken,
        converged,
    })
}

/// Options of [`parametrize`]: which form of G, and the weights α of the components.
#[derive(Clone, Debug, PartialEq)]
pub struct ParametrizeOptions<T> {
    /// Eq. 31 (the default) or Eq. 34.
    pub objective: Objective,
    /// One weight α_l per coordinate (Eq. 31's 1/α_l²); `None`: every α_l = 1.
    pub alpha: Option<Vec<T>>,
    /// The gradient projection's budget: it stops after this many iterations
    /// ([`DESCENT_MAX_ITERATIONS`] by default) and the result says it did not converge.
    pub max_iterations: usize,
}

impl<T> Default for ParametrizeOptions<T> {
    fn default() -> Self {
        ParametrizeOptions {
            objective: Objective::Exact,
            alpha: None,
            max_iterations: DESCENT_MAX_ITERATIONS,
        }
    }
}

/// The most points [`parametrize`] accepts: its gradient projection costs about N³ per
/// iteration (measured: 3000 points took 106 s; 1000 stay within a few seconds).
pub const MAX_PARAMETRIZE_POINTS: usize = 1000;

/// Marin's minimizing parametrization of `points` in Rᴰ (D ≥ 1): gradient projection in f64 from normalized chord length, then
/// Newton's method in `T` ([`descend`], then [`refine`]). The knots run from 0 to 1. The
/// minimizer does not depend on the points' scale (G is quadratic in them), so the points are
/// first scaled by a power of two (exactly) to a largest coordinate near 1: points of 1e-200
/// or 1e200 give the knots of the same points at unit scale.
///
/// # Errors
/// [`SplineError::TooFewKnots`] for fewer than two points; [`SplineError::TooManyPoints`]
/// above [`MAX_PARAMETRIZE_POINTS`]; [`SplineError::LengthMismatch`] for D = 0;
/// [`SplineError::NotFinite`] for a coordinate that is NaN or infinite;
/// [`SplineError::RepeatedPoint`] for two equal consecutive points;
/// [`SplineError::WeightCount`] for an `alpha` whose length is not D;
/// [`SplineError::BadWeight`] for a weight that is not positive and finite; and the errors of
/// the minimization. Pass the knots and the points to
/// [`super::natural::NaturalSplineCurve::new`] for the curve.
///
/// # Examples
/// ```
/// use trajverify::algo::param::descent::{parametrize, ParametrizeOptions};
/// // Four points in the plane; the knots are increasing from 0 to 1.
/// let points = [[0.0, 0.0], [1.0, 2.0], [3.0, 3.0], [4.0, 1.0]];
/// let m = parametrize(&points, &ParametrizeOptions::default()).unwrap();
/// assert_eq!(m.knots.len(), 4);
/// assert!(m.knots.windows(2).all(|w| w[0] < w[1]));
/// assert!(m.objective <= m.chord_objective);
/// assert!(m.converged());
/// ```
pub fn parametrize<T: Real, const D: usize>(
    points: &[[T; D]],
    options: &ParametrizeOptions<T>,
) -> Result<Minimum<T>, SplineError> {
    let n = points.len();
    let d = D;
    if n < 2 {
        return Err(SplineError::TooFewKnots);
    }
    if d == 0 {
        return Err(SplineError::LengthMismatch {
            knots: n,
            values: 0,
        });
    }
    // Component-major, as the objective reads them: z[l][i] is coordinate l of point i.
    let z: Vec<Vec<T>> = (0..d)
        .map(|l| points.iter().map(|p| p[l].clone()).collect())
        .collect();
    let ctx = z[0][0].ctx();
    let alpha = match &options.alpha {
        Some(a) => a.clone(),
        None => vec![T::one_in(&ctx); d],
    };
    check_problem(n - 1, &z, &alpha)?;
    if n > MAX_PARAMETRIZE_POINTS {
        return Err(SplineError::TooManyPoints {
            count: n,
            max: MAX_PARAMETRIZE_POINTS,
        });
    }
    if let Some(index) = points.iter().position(|p| !p.iter().all(Field::is_finite)) {
        return Err(SplineError::NotFinite {
            field: "point",
            index,
        });
    }
    if let Some(index) = (1..n).find(|&i| points[i] == points[i - 1]) {
        return Err(SplineError::RepeatedPoint { index });
    }
    let zero = T::zero_in(&ctx);
    if let Some(index) = alpha.iter().position(|a| !(a.is_finite() && *a > zero)) {
        return Err(SplineError::BadWeight { index });
    }
    // Scale by 2^−k, k the binary exponent of the largest coordinate: exact in every scalar.
    let largest = z
        .iter()
        .flatten()
        .map(|x| x.to_f64().abs())
        .fold(0.0f64, f64::max);
    let k = if largest > 0.0 && largest.is_finite() {
        largest.log2().floor() as i32
    } else {
        0
    };
    let scale = (0..k.unsigned_abs()).fold(T::one_in(&ctx), |s, _| {
        if k > 0 {
            s / &T::from_i64(2, &ctx)
        } else {
            s * &T::from_i64(2, &ctx)
        }
    });
    let z: Vec<Vec<T>> = z
        .iter()
        .map(|c| c.iter().map(|x| x.clone() * &scale).collect())
        .collect();
    let z64: Vec<Vec<f64>> = z
        .iter()
        .map(|c| c.iter().map(Field::to_f64).collect())
        .collect();
    let a64: Vec<f64> = alpha.iter().map(Field::to_f64).collect();
    let rough = gradient_projection(
        chord_length_spacing(&z64),
        &z64,
        &a64,
        options.objective,
        &DESCENT_TOLERANCE,
        options.max_iterations,
    )?;
    let mut minimum = refine(&rough, &z, &alpha, options.objective)?;
    // G and its gradient are quadratic in the points: back to the points as given.
    let squared = scale.clone() * &scale;
    for value in [
        &mut minimum.objective,
        &mut minimum.chord_objective,
        &mut minimum.projected_gradient_norm,
    ] {
        *value = value.clone() / &squared;
    }
    // The spacings sum to 1 by the constraint of Eq. 30: the ends are 0 and 1 exactly, not
    // the rounded sum (0.9999999999999999 in f64 would leave t = 1 outside the domain).
    if let Some(last) = minimum.knots.len().checked_sub(1) {
        minimum.knots[0] = T::zero_in(&ctx);
        minimum.knots[last] = T::one_in(&ctx);
    }
    Ok(minimum)
}
