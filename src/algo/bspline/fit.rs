//! Splines from shifted B-splines and their optimal control points (paper 002, Secs. 5–6).
//!
//! x(t) = Σᵢ τᵢ B_k(t − i + 1), i = 1…M (Eqs. 2, 16); the basis function i is supported on
//! [i−1, i+k], so the spline lives on [0, M+k]. For data (tⱼ, αⱼ), B is the N×M collocation
//! matrix Bⱼᵢ = B_k(tⱼ − i + 1) and G the Gram matrix of k-th derivatives ([`super::gram`]):
//! - interpolation (Problem 4, Eq. 13): min τᵀGτ subject to Bτ = α, solved by
//!   τ* = G⁻¹Bᵀ(BG⁻¹Bᵀ)⁻¹α (Eq. 14), which needs B of full row rank;
//! - smoothing (Problem 5): min τᵀGτ + (Bτ−α)ᵀW(Bτ−α), solved by
//!   τ̂* = (G + BᵀWB)⁻¹BᵀWα (Eq. 15), W = diag(w) with wⱼ ≥ 0;
//! - [`interpolate_kkt`] solves the same interpolation problem from its optimality system
//!   [[2G, Bᵀ], [B, 0]]·[τ; λ] = [0; α], independently of Eq. 14.
//!
//! Exact in rationals; Gaussian elimination with partial pivoting in floating point.

use super::gram::{gram_entries, gram_matrix};
use super::CardinalBSpline;
use crate::curve::parametric::{check_domain, CurveError, ParamCurve, ParamCurveArclen};
use crate::numeric::linalg::{inverse, solve, Matrix};
use crate::scalar::{Field, Real};

/// Why a fit cannot be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FitError {
    /// The degree is below 1.
    #[error("degree {0} is below 1: the Gram matrix of k-th derivatives needs k ≥ 1")]
    DegreeTooLow(usize),
    /// No data were given.
    #[error("no data")]
    NoData,
    #[error("{times} times but {values} values")]
    /// Times and values of different lengths.
    LengthMismatch {
        /// Number of data times.
        times: usize,
        /// Number of data values.
        values: usize,
    },
    #[error("{controls} control points cannot interpolate {data} data: M must be at least N")]
    /// Fewer control points than data: interpolation needs M ≥ N.
    TooFewControls {
        /// Number of control points M.
        controls: usize,
        /// Number of data N.
        data: usize,
    },
    #[error("time #{index} lies outside the open support (0, M+k) of the spline, where every basis function vanishes")]
    /// A data time outside the open support (0, M+k).
    OutsideSupport {
        /// Index of the offending time.
        index: usize,
    },
    /// The collocation matrix is not of full row rank.
    #[error("the collocation matrix B is not of full row rank (repeated times, or too many data on too few basis functions: the Schoenberg–Whitney condition fails)")]
    RankDeficient,
    /// The solution has no correct digit in the number type used.
    #[error("the fit is too ill-conditioned for {scalar}: its condition estimate κ₁(G)·κ₁(BG⁻¹Bᵀ) ≈ {condition:.1e} times the unit roundoff {unit:.1e} leaves no correct digit; use more bits (mpfr:<bits>) or rational")]
    IllConditioned {
        /// The number type.
        scalar: String,
        /// The condition estimate.
        condition: f64,
        /// The unit roundoff of the number type.
        unit: f64,
    },
    #[error("{what} #{index} is not a finite number")]
    /// A time, value or weight that is NaN or infinite.
    NotFinite {
        /// "time", "value" or "weight".
        what: &'static str,
        /// Index of the offending entry.
        index: usize,
    },
    #[error("a spline space needs at least one control point")]
    /// M = 0: no basis function.
    NoControls,
    #[error("weight #{index} is negative")]
    /// A negative weight.
    NegativeWeight {
        /// Index of the offending weight.
        index: usize,
    },
    #[error("{weights} weights for {data} data")]
    /// Weights and data of different lengths.
    WeightsLength {
        /// Number of weights.
        weights: usize,
        /// Number of data.
        data: usize,
    },
}

/// The spline space S_k with M control points: basis, Gram matrix, collocation.
pub struct SplineSpace<T: Field> {
    /// The cardinal B-spline B_k of the basis.
    pub(crate) basis: CardinalBSpline<T>,
    /// The number of control points (shifted basis functions) M.
    pub(crate) controls: usize,
    gram_entries: Vec<T>,
    ctx: T::Ctx,
}

impl<T: Field> SplineSpace<T> {
    /// The basis of `controls` shifted B-splines of degree `degree`.
    ///
    /// # Errors
    /// [`FitError::DegreeTooLow`] for `degree` = 0, [`FitError::NoControls`] for
    /// `controls` = 0.
    pub fn new(degree: usize, controls: usize, ctx: &T::Ctx) -> Result<Self, FitError> {
        if degree < 1 {
            return Err(FitError::DegreeTooLow(degree));
        }
        if controls == 0 {
            return Err(FitError::NoControls);
        }
        Ok(SplineSpace {
            basis: CardinalBSpline::from_algorithm1(degree, ctx),
            controls,
            gram_entries: gram_entries(degree, ctx),
            ctx: ctx.clone(),
        })
    }

    /// The cardinal B-spline B_k of the basis.
    pub fn basis(&self) -> &CardinalBSpline<T> {
        &self.basis
    }

    /// The number of control points (shifted basis functions) M.
    pub fn controls(&self) -> usize {
        self.controls
    }

    /// The degree k of the basis.
    pub fn degree(&self) -> usize {
        self.basis.degree()
    }

    /// The M×M Gram matrix.
    pub fn gram(&self, ctx: &T::Ctx) -> Matrix<T> {
        gram_matrix(&self.gram_entries, self.controls, ctx)
    }

    /// The N×M collocation matrix for the data times (checked to lie inside the support).
    ///
    /// # Errors
    /// [`FitError::NoData`] for no times; [`FitError::NotFinite`] for a NaN or infinite time;
    /// [`FitError::OutsideSupport`] for the first time found ≤ 0 or ≥ M + k.
    pub fn collocation(&self, times: &[T]) -> Result<Matrix<T>, FitError> {
        let Some(first) = times.first() else {
            return Err(FitError::NoData);
        };
        check_finite("time", times)?;
        let ctx = first.ctx();
        let (zero, end) = (
            T::zero_in(&ctx),
            T::from_i64((self.controls + self.degree()) as i64, &ctx),
        );
        if let Some(index) = times.iter().position(|t| !(*t > zero && *t < end)) {
            return Err(FitError::OutsideSupport { index });
        }
        Ok(self.collocation_of(times))
    }

    /// The collocation matrix without the support check (for times the caller checked on
    /// their exact values: a time within rounding of the support's end gives the basis's
    /// continuous value there).
    pub fn collocation_of(&self, times: &[T]) -> Matrix<T> {
        let ctx = &self.ctx;
        Matrix::from_fn(times.len(), self.controls, |j, i| {
            self.basis
                .eval(&(times[j].clone() - &T::from_i64(i as i64, ctx)))
        })
    }

    /// The d-th derivative of x(t) = Σ τᵢ B_k(t − i + 1) at t.
    pub fn eval_derivative(&self, tau: &[T], t: &T, d: usize) -> T {
        let ctx = t.ctx();
        let mut acc = T::zero_in(&ctx);
        for (i, c) in tau.iter().enumerate() {
            acc.mul_add_assign(
                c,
                &self
                    .basis
                    .eval_derivative(&(t.clone() - &T::from_i64(i as i64, &ctx)), d),
            );
        }
        acc
    }

    /// The spline Σᵢ τᵢ B_k(t − i + 1) with control points `tau`, at `t`.
    pub fn eval(&self, tau: &[T], t: &T) -> T {
        self.eval_derivative(tau, t, 0)
    }

    fn check(&self, times: &[T], values: &[T]) -> Result<Matrix<T>, FitError> {
        if times.len() != values.len() {
            return Err(FitError::LengthMismatch {
                times: times.len(),
                values: values.len(),
            });
        }
        check_finite("value", values)?;
        self.collocation(times)
    }

    /// τ* of Eq. 14.
    ///
    /// # Errors
    /// As [`SplineSpace::interpolate_with_condition`].
    pub fn interpolate(&self, times: &[T], values: &[T]) -> Result<Vec<T>, FitError> {
        self.interpolate_with_condition(times, values)
            .map(|(tau, _)| tau)
    }

    /// τ* of Eq. 14 and an estimate of its condition, κ₁(G)·κ₁(BG⁻¹Bᵀ) from the two
    /// inverses the method forms: a relative perturbation ε of the data or of the arithmetic
    /// moves τ* by up to about that many times ε, so in a number type with unit roundoff u
    /// the result has no correct digit once u·κ approaches 1 ([`FitError::IllConditioned`]
    /// is the caller's to raise: rationals are exact). Whether B has full row rank is
    /// decided first, exactly ([`schoenberg_whitney`]), not by a pivot that rounding made
    /// small or non-zero.
    ///
    /// # Errors
    /// [`FitError::LengthMismatch`], [`FitError::NoData`] or [`FitError::OutsideSupport`] for
    /// the data's shape; [`FitError::TooFewControls`] for N > M; [`FitError::RankDeficient`]
    /// when [`schoenberg_whitney`] fails; [`FitError::IllConditioned`] (condition ∞) when G or
    /// BG⁻¹Bᵀ is singular at this precision.
    pub fn interpolate_with_condition(
        &self,
        times: &[T],
        values: &[T],
    ) -> Result<(Vec<T>, T), FitError> {
        self.check(times, values)?;
        if times.len() > self.controls {
            return Err(FitError::TooFewControls {
                controls: self.controls,
                data: times.len(),
            });
        }
        schoenberg_whitney(times, self.degree(), self.controls)?;
        self.interpolate_checked(times, values)
    }

    /// [`SplineSpace::interpolate_with_condition`] for data whose support and rank the
    /// caller decided on their exact values ([`schoenberg_whitney`] on the exact times, as
    /// lengths and M ≥ N): `times` may be those values rounded, so nothing is decided on
    /// them again.
    ///
    /// # Errors
    /// [`FitError::LengthMismatch`] for no times or unequal lengths; then those of
    /// [`SplineSpace::interpolate_collocation`].
    pub fn interpolate_checked(&self, times: &[T], values: &[T]) -> Result<(Vec<T>, T), FitError> {
        if times.is_empty() || times.len() != values.len() {
            return Err(FitError::LengthMismatch {
                times: times.len(),
                values: values.len(),
            });
        }
        self.interpolate_collocation(&self.collocation_of(times), values)
    }

    /// Eq. 14 from the collocation matrix B itself (N×M, N ≤ M, of full row rank), for a
    /// caller that formed B exactly (in rationals, from exact times) and rounded it once:
    /// an entry B_k(tⱼ − i + 1) of a time 1e-40 inside the support's end is then ~1e-80 and
    /// accurate, where the same entry of the rounded time would be 0.
    ///
    /// # Errors
    /// [`FitError::LengthMismatch`] when B has no row, not one row per value, or not M
    /// columns; [`FitError::NotFinite`] for a NaN or infinite value or entry of B;
    /// [`FitError::IllConditioned`] (condition ∞) when inverting G or BG⁻¹Bᵀ meets a zero
    /// pivot.
    pub fn interpolate_collocation(
        &self,
        b: &Matrix<T>,
        values: &[T],
    ) -> Result<(Vec<T>, T), FitError> {
        if b.rows() == 0 || b.rows() != values.len() || b.cols() != self.controls {
            return Err(FitError::LengthMismatch {
                times: b.rows(),
                values: values.len(),
            });
        }
        check_finite("value", values)?;
        check_finite("collocation entry", b.entries())?;
        let ctx = values[0].ctx();
        let gram = self.gram(&ctx);
        // B has full row rank (decided exactly), so a singular system here is singular only
        // at this precision.
        let singular = |_| FitError::IllConditioned {
            scalar: T::scalar_name(&ctx),
            condition: f64::INFINITY,
            unit: T::unit_roundoff(&ctx).unwrap_or(0.0),
        };
        let g_inv = inverse(&gram).map_err(singular)?;
        let g_inv_bt = g_inv.mul(&b.transpose());
        let schur = b.mul(&g_inv_bt);
        let schur_inv = inverse(&schur).map_err(singular)?;
        let y = schur_inv.mul_vec(values);
        let condition = norm1(&gram) * &norm1(&g_inv) * &norm1(&schur) * &norm1(&schur_inv);
        Ok((g_inv_bt.mul_vec(&y), condition))
    }

    /// τ̂* of Eq. 15 for weights wⱼ ≥ 0.
    ///
    /// # Errors
    /// [`FitError::LengthMismatch`], [`FitError::NoData`], [`FitError::NotFinite`] or
    /// [`FitError::OutsideSupport`] for the data's shape; [`FitError::WeightsLength`] unless
    /// one weight per datum; [`FitError::NegativeWeight`] for the first wⱼ < 0;
    /// [`FitError::RankDeficient`] when elimination on G + BᵀWB meets a zero pivot.
    pub fn smooth(&self, times: &[T], values: &[T], weights: &[T]) -> Result<Vec<T>, FitError> {
        self.check(times, values)?;
        if weights.len() != times.len() {
            return Err(FitError::WeightsLength {
                weights: weights.len(),
                data: times.len(),
            });
        }
        check_finite("weight", weights)?;
        let zero = T::zero_in(&self.ctx);
        if let Some(index) = weights.iter().position(|w| *w < zero) {
            return Err(FitError::NegativeWeight { index });
        }
        self.smooth_checked(times, values, weights)
    }

    /// [`SplineSpace::smooth`] for data the caller checked on their exact values (times in
    /// the support, weights ≥ 0, lengths): nothing is decided on `times` again.
    ///
    /// # Errors
    /// [`FitError::LengthMismatch`] for no times or times and values of unequal lengths,
    /// [`FitError::WeightsLength`] unless one weight per time; then those of
    /// [`SplineSpace::smooth_collocation`].
    pub fn smooth_checked(
        &self,
        times: &[T],
        values: &[T],
        weights: &[T],
    ) -> Result<Vec<T>, FitError> {
        if times.is_empty() || times.len() != values.len() {
            return Err(FitError::LengthMismatch {
                times: times.len(),
                values: values.len(),
            });
        }
        if weights.len() != times.len() {
            return Err(FitError::WeightsLength {
                weights: weights.len(),
                data: times.len(),
            });
        }
        self.smooth_collocation(&self.collocation_of(times), values, weights)
    }

    /// Eq. 15 from the collocation matrix B (formed exactly by the caller, see
    /// [`SplineSpace::interpolate_collocation`]).
    ///
    /// # Errors
    /// [`FitError::LengthMismatch`] when B has no row, not M columns, or `values` does not
    /// have one entry per row; [`FitError::WeightsLength`] unless one weight per row;
    /// [`FitError::NotFinite`] for a NaN or infinite value, weight or entry of B;
    /// [`FitError::RankDeficient`] when elimination on G + BᵀWB meets a zero pivot.
    pub fn smooth_collocation(
        &self,
        b: &Matrix<T>,
        values: &[T],
        weights: &[T],
    ) -> Result<Vec<T>, FitError> {
        if b.rows() == 0 || b.rows() != values.len() || b.cols() != self.controls {
            return Err(FitError::LengthMismatch {
                times: b.rows(),
                values: values.len(),
            });
        }
        if weights.len() != values.len() {
            return Err(FitError::WeightsLength {
                weights: weights.len(),
                data: values.len(),
            });
        }
        check_finite("value", values)?;
        check_finite("weight", weights)?;
        check_finite("collocation entry", b.entries())?;
        let ctx = values[0].ctx();
        let wb = Matrix::from_fn(b.rows(), b.cols(), |j, i| weights[j].clone() * &b[(j, i)]);
        let bt = b.transpose();
        let gram = self.gram(&ctx);
        let lhs = Matrix::from_fn(self.controls, self.controls, |r, c| {
            let mut acc = gram[(r, c)].clone();
            for j in 0..b.rows() {
                acc.mul_add_assign(&bt[(r, j)], &wb[(j, c)]);
            }
            acc
        });
        let rhs: Vec<T> = (0..self.controls)
            .map(|r| {
                let mut acc = T::zero_in(&ctx);
                for j in 0..b.rows() {
                    acc.mul_add_assign(&wb[(j, r)], &values[j]);
                }
                acc
            })
            .collect();
        solve(&lhs, &rhs).map_err(|_| FitError::RankDeficient)
    }
}

/// [`FitError::NotFinite`] naming the first NaN or infinite entry of `xs`.
fn check_finite<T: Field>(what: &'static str, xs: &[T]) -> Result<(), FitError> {
    match xs.iter().position(|x| !x.is_finite()) {
        Some(index) => Err(FitError::NotFinite { what, index }),
        None => Ok(()),
    }
}

/// The 1-norm (largest column sum of magnitudes) of a matrix.
fn norm1<T: Field>(a: &Matrix<T>) -> T {
    let ctx = a[(0, 0)].ctx();
    (0..a.cols())
        .map(|c| (0..a.rows()).fold(T::zero_in(&ctx), |acc, r| acc + &a[(r, c)].abs()))
        .fold(T::zero_in(&ctx), |m, x| m.max_with(&x))
}

/// A fitted spline x(t) = Σᵢ τᵢ B_k(t − i + 1) as a curve of t on its support [0, M + k]
/// (points are `[T; 1]`; fit each coordinate of a space curve separately).
///
/// # Examples
/// The optimal cubic interpolant (Eq. 14) of four values, exactly and in f64:
/// ```
/// use trajverify::algo::bspline::fit::{SplineFit, SplineSpace};
/// use trajverify::curve::parametric::ParamCurve;
/// use trajverify::scalar::BigRational;
///
/// let q = |n: i64| BigRational::from_integer(n.into());
/// let space = SplineSpace::new(3, 6, &()).unwrap();
/// let fit = SplineFit::interpolate(space, &[q(3), q(4), q(5), q(6)], &[q(0), q(1), q(0), q(2)]).unwrap();
/// assert_eq!(fit.point(&q(5)).unwrap(), [q(0)]);
///
/// let space = SplineSpace::new(3, 6, &()).unwrap();
/// let fast = SplineFit::interpolate(space, &[3.0, 4.0, 5.0, 6.0], &[0.0, 1.0, 0.0, 2.0]).unwrap();
/// assert!((fast.point(&6.0).unwrap()[0] - 2.0).abs() < 1e-12);
/// assert!(fast.point(&-1.0).is_err());
/// ```
pub struct SplineFit<T: Field> {
    space: SplineSpace<T>,
    tau: Vec<T>,
    /// The support [0, M + k].
    domain: (T, T),
}

impl<T: Field> SplineFit<T> {
    /// The interpolating spline of least k-th derivative energy (Eq. 14).
    ///
    /// # Errors
    /// Those of [`SplineSpace::interpolate`].
    pub fn interpolate(space: SplineSpace<T>, times: &[T], values: &[T]) -> Result<Self, FitError> {
        let tau = space.interpolate(times, values)?;
        Ok(SplineFit::with(space, tau))
    }

    /// The smoothing spline with weights wⱼ ≥ 0 (Eq. 15).
    ///
    /// # Errors
    /// Those of [`SplineSpace::smooth`].
    pub fn smooth(
        space: SplineSpace<T>,
        times: &[T],
        values: &[T],
        weights: &[T],
    ) -> Result<Self, FitError> {
        let tau = space.smooth(times, values, weights)?;
        Ok(SplineFit::with(space, tau))
    }

    fn with(space: SplineSpace<T>, tau: Vec<T>) -> Self {
        let ctx = space.ctx.clone();
        let end = T::from_i64((space.controls + space.degree()) as i64, &ctx);
        SplineFit {
            space,
            tau,
            domain: (T::zero_in(&ctx), end),
        }
    }

    /// The control points τ₁ … τ_M.
    pub fn control_points(&self) -> &[T] {
        &self.tau
    }

    /// The spline space.
    pub fn space(&self) -> &SplineSpace<T> {
        &self.space
    }
}

impl<T: Field> ParamCurve<T, 1> for SplineFit<T> {
    fn domain(&self) -> (T, T) {
        self.domain.clone()
    }
    fn derivatives(&self, t: &T, order: usize) -> Result<Vec<[T; 1]>, CurveError> {
        crate::curve::parametric::check_order(order)?;
        check_domain(t, (&self.domain.0, &self.domain.1))?;
        Ok((0..=order)
            .map(|d| [self.space.eval_derivative(&self.tau, t, d)])
            .collect())
    }
}

impl<T: Real> ParamCurveArclen<T, 1> for SplineFit<T> {}

/// Whether the N×M collocation matrix of the (distinct) data times has full row rank N,
/// decided exactly by the Schoenberg–Whitney condition: B-spline collocation matrices are
/// totally positive, so B has rank N exactly when the sorted times t₁ < … < t_N can be
/// matched to basis functions i₁ < … < i_N with each tⱼ inside the open support
/// (iⱼ − 1, iⱼ + k) of its own (Schoenberg & Whitney 1953; de Boor, *A Practical Guide to
/// Splines*, XIII). The greedy match takes the leftmost basis function each time. The
/// times are compared as exact rationals (every f64 and MPFR value is one), so a time
/// within rounding of a support's end is placed on its true side.
///
/// # Errors
/// [`FitError::RankDeficient`] when a time is not finite, two times are equal, or the sorted
/// times cannot be matched to basis functions i₁ < … < i_N ≤ M as stated (a time outside
/// (0, M + k) never can).
pub fn schoenberg_whitney<T: Field>(
    times: &[T],
    degree: usize,
    controls: usize,
) -> Result<(), FitError> {
    use crate::scalar::BigRational;
    let mut sorted: Vec<BigRational> = times
        .iter()
        .map(Field::to_rational)
        .collect::<Option<_>>()
        .ok_or(FitError::RankDeficient)?;
    sorted.sort();
    if sorted.windows(2).any(|w| w[0] == w[1]) {
        return Err(FitError::RankDeficient);
    }
    let k = BigRational::from_integer((degree as i64).into());
    let mut previous = 0usize;
    for t in &sorted {
        // The smallest i > previous with i − 1 < t < i + k, i.e. i > t − k and i < t + 1.
        let above = (t.clone() - &k).floor().to_integer();
        let lowest =
            num_traits::ToPrimitive::to_i64(&above).map_or(i64::MAX, |v| v.saturating_add(1));
        let i = lowest.max(previous as i64 + 1);
        let fits =
            BigRational::from_integer(i.into()) < t.clone() + BigRational::from_integer(1.into());
        if !fits || i > controls as i64 {
            return Err(FitError::RankDeficient);
        }
        previous = i as usize;
    }
    Ok(())
}

/// The interpolating τ* from the KKT system of Problem 4, independently of Eq. 14.
///
/// # Errors
/// [`FitError::LengthMismatch`] for unequal lengths, then [`FitError::NoData`] or
/// [`FitError::OutsideSupport`] ([`SplineSpace::collocation`]); [`FitError::RankDeficient`]
/// when elimination on the KKT matrix meets a zero pivot (exactly: B not of full row rank).
pub fn interpolate_kkt<T: Field>(
    space: &SplineSpace<T>,
    times: &[T],
    values: &[T],
) -> Result<Vec<T>, FitError> {
    let b = space.check(times, values)?;
    let ctx = times[0].ctx();
    let (m, n) = (space.controls, times.len());
    let g = space.gram(&ctx);
    let two = T::from_i64(2, &ctx);
    let kkt = Matrix::from_fn(m + n, m + n, |r, c| match (r < m, c < m) {
        (true, true) => two.clone() * &g[(r, c)],
        (true, false) => b[(c - m, r)].clone(),
        (false, true) => b[(r - m, c)].clone(),
        (false, false) => T::zero_in(&ctx),
    });
    let rhs: Vec<T> = (0..m + n)
        .map(|r| {
            if r < m {
                T::zero_in(&ctx)
            } else {
                values[r - m].clone()
            }
        })
        .collect();
    let sol = solve(&kkt, &rhs).map_err(|_| FitError::RankDeficient)?;
    Ok(sol[..m].to_vec())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::BigRational;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    #[test]
    fn interpolation_meets_data_and_matches_kkt() {
        let space = SplineSpace::<BigRational>::new(3, 8, &()).unwrap();
        let times = vec![q(3, 2), q(3, 1), q(9, 2), q(6, 1), q(15, 2)];
        let values = vec![q(1, 1), q(-2, 1), q(0, 1), q(5, 3), q(1, 2)];
        let tau = space.interpolate(&times, &values).unwrap();
        for (t, v) in times.iter().zip(&values) {
            assert_eq!(&space.eval(&tau, t), v);
        }
        assert_eq!(interpolate_kkt(&space, &times, &values).unwrap(), tau);
    }

    #[test]
    fn errors() {
        let space = SplineSpace::<BigRational>::new(3, 4, &()).unwrap();
        assert_eq!(
            space.collocation(&[q(0, 1)]).unwrap_err(),
            FitError::OutsideSupport { index: 0 }
        );
        assert_eq!(
            space.collocation(&[q(1, 1), q(7, 1)]).unwrap_err(),
            FitError::OutsideSupport { index: 1 }
        );
        let twice = [q(2, 1), q(2, 1)];
        assert_eq!(
            space.interpolate(&twice, &[q(0, 1), q(1, 1)]).unwrap_err(),
            FitError::RankDeficient
        );
        assert!(matches!(
            SplineSpace::<BigRational>::new(0, 4, &()),
            Err(FitError::DegreeTooLow(0))
        ));
        let five: Vec<_> = (1..=5).map(|i| q(i, 1)).collect();
        assert!(matches!(
            space.interpolate(&five, &five),
            Err(FitError::TooFewControls { .. })
        ));
        assert!(matches!(
            space.smooth(&[q(1, 1)], &[q(1, 1)], &[q(-1, 1)]),
            Err(FitError::NegativeWeight { index: 0 })
        ));
    }
}
