//! Two-point Hermite interpolation in Bernstein form (paper 000, Sec. 3).
//!
//! Given the values and first m derivatives at both ends of [t₀, t₁],
//! H = [x₀, x₀′, …, x₀⁽ᵐ⁾ | x₁, x₁′, …, x₁⁽ᵐ⁾] (Eq. 11), find the control points p₀…pₙ,
//! n = 2m + 1, of the unique polynomial of degree n meeting all 2(m+1) conditions.
//!
//! With T = t₁ − t₀, Eqs. 14–15 say Δʲp₀ = qʲ₀ and ∇ʲpₙ = qʲ₁ with
//! qʲ = Tʲ (n−j)!/n! x⁽ʲ⁾. Both systems are triangular:
//! - p₀…pₘ = binomial transform of (q⁰₀…qᵐ₀) (Eq. 16 via A2);
//! - pₙ₋ₖ = Σⱼ (−1)ʲ C(k, j) qʲ₁ for k = 0…m (Eq. 17 via the self-inverse A3).
//!
//! The start data fix exactly m+1 control points, p₀…pₘ, and the end data the other m+1,
//! pₘ₊₁…p₂ₘ₊₁. Eqs. 16–17 as printed assign p₀…pₘ₊₁ (m+2 points) to the m+1 start values
//! and p_{m+2}…p_{2m+1} (m points) to the m+1 end values; Eq. 18 read as one vector is the
//! map implemented here. The claims ledger records that finding.
//!
//! Exact in rationals. In floating point each control point is a short signed sum of the
//! scaled data, so the map is as accurate as its condition number allows (see
//! [`transform_matrix`] and the Fig. 5 claims).
//!
//! Fig. 2's data on [0, 2] (the slower of its two durations), exactly and in f64: the control
//! points are 0, 0, 0, 1/5, 3/5, 1.
//!
//! ```
//! use trajverify::algo::hermite::HermiteData;
//! use trajverify::scalar::BigRational;
//!
//! let q = |n: i64, d: i64| BigRational::new(n.into(), d.into());
//! let exact = HermiteData::new(vec![q(0, 1); 3], vec![q(1, 1), q(1, 1), q(0, 1)], (q(0, 1), q(2, 1)))
//!     .unwrap()
//!     .solve()
//!     .unwrap();
//! assert_eq!(exact.control_points()[3..], [q(1, 5), q(3, 5), q(1, 1)]);
//! let fast = HermiteData::new(vec![0.0; 3], vec![1.0, 1.0, 0.0], (0.0, 2.0)).unwrap().solve().unwrap();
//! assert!((fast.control_points()[3] - 0.2).abs() < 1e-15);
//! ```

pub mod condition;
pub mod piecewise;

use crate::curve::bezier::BezierCurve;
use crate::numeric::linalg::Matrix;
use crate::numeric::poly::differences::{anti_difference_lanes, backward_anti_difference_lanes};
use crate::numeric::poly::{binomial, falling_factorial, falling_factorial_in, int_in, Bernstein};
use crate::scalar::{powi, Field};

/// Why Hermite data cannot be mapped.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum HermiteError {
    /// No boundary data.
    #[error("no boundary data: start and end need at least the position")]
    Empty,
    /// Start and end with different numbers of derivatives.
    #[error(
        "start has {start} values and end has {end}: both ends need the same number of derivatives"
    )]
    LengthMismatch {
        /// Number of values at the start.
        start: usize,
        /// Number of values at the end.
        end: usize,
    },
    /// Points of different dimensions.
    #[error("every point must have the same dimension d ≥ 1")]
    DimensionMismatch,
    /// A piecewise interpolation asked for more segments than
    /// [`piecewise::MAX_SEGMENTS`].
    #[error("segments: at most {max} segments, got {0}", max = crate::algo::hermite::piecewise::MAX_SEGMENTS)]
    TooManySegments(usize),
    /// More derivatives per joint than a piecewise interpolation supports.
    #[error("m: at most {max} derivatives per joint, got {m}")]
    TooManyDerivatives {
        /// The derivatives asked for.
        m: usize,
        /// The most supported.
        max: usize,
    },
    /// Data that are NaN or infinite, or control points that overflow (named).
    #[error("{0} is not finite")]
    NotFinite(String),
    /// A piecewise interpolation asked for no segment.
    #[error("segments: a piecewise interpolant needs at least one segment")]
    NoSegments,
    /// The interval has t1 ≤ t0.
    #[error("the interval [t0, t1] must have t1 > t0")]
    EmptyInterval,
    /// A scale factor (t1−t0)^j (n−j)!/n! that overflows or underflows the number type.
    #[error("the scale factor (t1−t0)^{j}·({n}−{j})!/{n}! is not representable in {scalar} (overflow or underflow)")]
    ScaleNotRepresentable {
        /// The derivative order.
        j: usize,
        /// The polynomial degree.
        n: usize,
        /// The number type that overflowed or underflowed.
        scalar: String,
    },
}

/// The boundary data of Eq. 11 on an interval.
#[derive(Clone, Debug, PartialEq)]
pub struct HermiteData<T> {
    /// x₀, x₀′, …, x₀⁽ᵐ⁾ at t₀.
    start: Vec<T>,
    /// x₁, x₁′, …, x₁⁽ᵐ⁾ at t₁.
    end: Vec<T>,
    /// The start of the interval.
    t0: T,
    /// The end of the interval.
    t1: T,
}

impl<T: Field> HermiteData<T> {
    /// Check the shape: non-empty, equal lengths, t₁ > t₀.
    ///
    /// # Errors
    /// [`HermiteError::Empty`] when `start` or `end` is empty; [`HermiteError::LengthMismatch`]
    /// when their lengths differ; [`HermiteError::EmptyInterval`] unless t₀ < t₁ (NaN fails).
    pub fn new(start: Vec<T>, end: Vec<T>, (t0, t1): (T, T)) -> Result<Self, HermiteError> {
        let data = HermiteData { start, end, t0, t1 };
        data.check()?;
        Ok(data)
    }

    /// The shape `new` checks, checked again where the fields may have been set directly.
    fn check(&self) -> Result<(), HermiteError> {
        check_shape(self.start.len(), self.end.len(), (&self.t0, &self.t1))?;
        check_lane(&self.start, &self.end, 1, 0)
    }

    /// Data whose shape the caller built right (equal non-empty lengths, t₀ < t₁): the
    /// paper checks' constants and random problems, which `new` would only re-check.
    pub(crate) fn new_unchecked(start: Vec<T>, end: Vec<T>, t0: T, t1: T) -> Self {
        debug_assert!(!start.is_empty() && start.len() == end.len());
        HermiteData { start, end, t0, t1 }
    }

    /// m, the highest derivative constrained at each end.
    pub fn derivatives(&self) -> usize {
        self.start.len() - 1
    }

    /// x₀, x₀′, …, x₀⁽ᵐ⁾ at t₀.
    pub fn start(&self) -> &[T] {
        &self.start
    }

    /// x₁, x₁′, …, x₁⁽ᵐ⁾ at t₁.
    pub fn end(&self) -> &[T] {
        &self.end
    }

    /// The interval (t₀, t₁), t₀ < t₁.
    pub fn interval(&self) -> (&T, &T) {
        (&self.t0, &self.t1)
    }

    /// The vector H of Eq. 11.
    pub fn boundary_vector(&self) -> Vec<T> {
        self.start.iter().chain(&self.end).cloned().collect()
    }

    /// The control points of the interpolating polynomial of degree 2m+1 (Eq. 18).
    ///
    /// # Errors
    /// Those of [`HermiteData::new`] (checked again); [`HermiteError::ScaleNotRepresentable`] as
    /// [`derivative_scales`].
    pub fn solve(&self) -> Result<Bernstein<T>, HermiteError> {
        // One problem is one lane of `solve_lanes`, which checks what `new` checks, in order.
        let points = solve_lanes(&self.start, &self.end, 1, (&self.t0, &self.t1))?;
        Bernstein::new(points, (self.t0.clone(), self.t1.clone())).map_err(|e| match e {
            crate::numeric::poly::bernstein::BernsteinError::Empty => HermiteError::Empty,
            crate::numeric::poly::bernstein::BernsteinError::Interval => {
                HermiteError::EmptyInterval
            }
            crate::numeric::poly::bernstein::BernsteinError::NotFinite(k) => {
                HermiteError::NotFinite(format!("control point {k} (overflow)"))
            }
        })
    }
}

/// The Hermite map for points in Rᵈ: `start[j]` and `end[j]` are the j-th derivative vectors
/// (all of one dimension d ≥ 1). The map acts on each coordinate separately, so the result is
/// the control polygon as points: `result[k][c]` is coordinate c of p_k.
///
/// # Errors
/// [`HermiteError::DimensionMismatch`] when `start` is empty or its first vector has no
/// coordinate, or any vector has another dimension; then, per coordinate, those of
/// [`HermiteData::new`] (an empty `end`: [`HermiteError::Empty`]) and [`HermiteData::solve`].
pub fn solve_points<T: Field>(
    start: &[Vec<T>],
    end: &[Vec<T>],
    (t0, t1): (&T, &T),
) -> Result<Vec<Vec<T>>, HermiteError> {
    let dims = start.first().map_or(0, Vec::len);
    if dims == 0 || start.iter().chain(end).any(|v| v.len() != dims) {
        return Err(HermiteError::DimensionMismatch);
    }
    let points = solve_lanes(&start.concat(), &end.concat(), dims, (t0, t1))?;
    Ok(points.chunks(dims).map(<[T]>::to_vec).collect())
}

/// [`solve_points`] on flat data: `lanes` problems (coordinates, or whole batches of
/// problems) side by side, the j-th derivative of problem l at `start[j·lanes + l]` and
/// `end[j·lanes + l]`; control point k of problem l is entry `k·lanes + l` of the result.
///
/// Each problem is the one [`HermiteData::solve`] solves, all with one m and one interval:
/// the shape is checked once, the scales formed once, and the two difference tables run on
/// every problem at once as lanes (bit for bit each problem's own tables, without allocating
/// per problem). Errors come in the order a loop over the problems would give them: problem
/// 0's checks, the scales, then per problem its non-finite data before its overflowing
/// control points.
///
/// # Errors
/// [`HermiteError::DimensionMismatch`] for `lanes` = 0 or lengths that are not multiples of
/// it; then those of [`solve_points`].
pub fn solve_lanes<T: Field>(
    start: &[T],
    end: &[T],
    lanes: usize,
    (t0, t1): (&T, &T),
) -> Result<Vec<T>, HermiteError> {
    if lanes == 0 || start.len() % lanes != 0 || end.len() % lanes != 0 {
        return Err(HermiteError::DimensionMismatch);
    }
    check_shape(start.len() / lanes, end.len() / lanes, (t0, t1))?;
    check_lane(start, end, lanes, 0)?;
    let scales = derivative_scales(start.len() / lanes - 1, (t0, t1))?;
    // One buffer, p₀…pₘ from the start's scaled derivatives and pₘ₊₁…pₙ from the end's.
    let mut points: Vec<T> = Vec::with_capacity(start.len() + end.len());
    for x in [start, end] {
        for (row, s) in x.chunks(lanes).zip(&scales) {
            points.extend(row.iter().map(|v| v.clone() * s));
        }
    }
    let (head, tail) = points.split_at_mut(start.len());
    anti_difference_lanes(head, lanes);
    backward_anti_difference_lanes(tail, lanes);
    if [start, end, &points]
        .iter()
        .all(|x| x.iter().all(Field::is_finite))
    {
        return Ok(points);
    }
    for l in 0..lanes {
        check_lane(start, end, lanes, l)?;
        if let Some(k) = points.chunks(lanes).position(|p| !p[l].is_finite()) {
            return Err(HermiteError::NotFinite(format!(
                "control point {k} (overflow)"
            )));
        }
    }
    Ok(points)
}

/// The checks of [`HermiteData::new`] that do not depend on the values: data at both ends,
/// as many derivatives at each, and a finite interval t₀ < t₁.
fn check_shape<T: Field>(start: usize, end: usize, (t0, t1): (&T, &T)) -> Result<(), HermiteError> {
    if start == 0 || end == 0 {
        return Err(HermiteError::Empty);
    }
    if start != end {
        return Err(HermiteError::LengthMismatch { start, end });
    }
    // Written so that NaN (which compares false both ways) is refused too.
    if t0.partial_cmp(t1) != Some(std::cmp::Ordering::Less) {
        return Err(HermiteError::EmptyInterval);
    }
    if !(t0.is_finite() && t1.is_finite()) {
        return Err(HermiteError::NotFinite("the interval [t0, t1]".into()));
    }
    Ok(())
}

/// The finiteness check of [`HermiteData::new`] on problem l of [`solve_lanes`]'s data.
fn check_lane<T: Field>(
    start: &[T],
    end: &[T],
    lanes: usize,
    l: usize,
) -> Result<(), HermiteError> {
    for (name, list) in [("start", start), ("end", end)] {
        if let Some(j) = list.chunks(lanes).position(|p| !p[l].is_finite()) {
            return Err(HermiteError::NotFinite(format!("{name}[{j}]")));
        }
    }
    Ok(())
}

/// The Hermite interpolant of points in Rᴰ as a curve of t ∈ [t₀, t₁] (like scipy's
/// `BPoly.from_derivatives` for two times): `start[j]` and `end[j]` are the j-th derivative
/// vectors at t₀ and t₁, the same number m + 1 at both ends; the result has degree 2m + 1.
///
/// # Errors
/// [`HermiteError::Empty`] without data, [`HermiteError::LengthMismatch`] for unequal
/// numbers of derivatives, [`HermiteError::DimensionMismatch`] for D = 0,
/// [`HermiteError::EmptyInterval`] unless t₀ < t₁ (both finite), and
/// [`HermiteError::ScaleNotRepresentable`] where the scales (t₁ − t₀)ʲ(n−j)!/n! overflow.
///
/// # Examples
/// Position, velocity and acceleration at both ends of [0, 2] in 3-D, in f64 and exactly:
/// ```
/// use trajverify::algo::hermite::hermite_curve;
/// use trajverify::curve::parametric::ParamCurve;
/// use trajverify::scalar::BigRational;
///
/// let start = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 0.0]];
/// let end = [[1.0, 1.0, 0.5], [0.0, 1.0, 0.0], [0.0, 0.0, 0.0]];
/// let curve = hermite_curve(&start, &end, (0.0, 2.0)).unwrap();
/// assert_eq!(curve.degree(), 5);
/// let v = curve.derivative(&2.0, 1).unwrap();
/// assert!((v[1] - 1.0).abs() < 1e-15 && v[0].abs() < 1e-15);
///
/// let q = |n: i64| BigRational::from_integer(n.into());
/// let exact = hermite_curve(&[[q(0)], [q(0)], [q(0)]], &[[q(1)], [q(1)], [q(0)]], (q(0), q(2))).unwrap();
/// assert_eq!(exact.control_points()[3][0], BigRational::new(1.into(), 5.into())); // paper 000, Fig. 2
/// ```
pub fn hermite_curve<T: Field, const D: usize>(
    start: &[[T; D]],
    end: &[[T; D]],
    (t0, t1): (T, T),
) -> Result<BezierCurve<T, D>, HermiteError> {
    if start.is_empty() || end.is_empty() {
        return Err(HermiteError::Empty);
    }
    if !(t0.is_finite() && t1.is_finite()) {
        return Err(HermiteError::NotFinite("the interval [t0, t1]".into()));
    }
    for (name, list) in [("start", start), ("end", end)] {
        if let Some(j) = list.iter().position(|p| !p.iter().all(Field::is_finite)) {
            return Err(HermiteError::NotFinite(format!("{name}[{j}]")));
        }
    }
    let rows = |v: &[[T; D]]| v.iter().map(|p| p.to_vec()).collect::<Vec<_>>();
    let polygon = solve_points(&rows(start), &rows(end), (&t0, &t1))?;
    let points = polygon
        .into_iter()
        .map(|p| std::array::from_fn(|c| p[c].clone()))
        .collect();
    BezierCurve::new(points, (t0, t1)).map_err(|e| match e {
        crate::numeric::poly::bernstein::BernsteinError::NotFinite(k) => {
            HermiteError::NotFinite(format!("control point {k} (overflow)"))
        }
        _ => HermiteError::EmptyInterval,
    })
}

/// The scales Tʲ(n−j)!/n!, j = 0…m, n = 2m+1, that turn derivatives into differences.
///
/// # Errors
/// [`HermiteError::ScaleNotRepresentable`] for the first j whose n!/(n−j)! is not finite,
/// or whose scale (t₁ − t₀)ʲ(n−j)!/n! is not finite or is zero (overflow, underflow, or
/// t₁ = t₀ for j ≥ 1).
pub fn derivative_scales<T: Field>(m: usize, (t0, t1): (&T, &T)) -> Result<Vec<T>, HermiteError> {
    let ctx = t0.ctx();
    let n = 2 * m + 1;
    let width = t1.clone() - t0;
    (0..=m)
        .map(|j| {
            let ff: T = falling_factorial_in(n, j, &ctx);
            let s = powi(&width, j as u32) / &ff;
            if !s.is_finite() || s.is_zero() || !ff.is_finite() {
                Err(HermiteError::ScaleNotRepresentable {
                    j,
                    n,
                    scalar: T::scalar_name(&ctx),
                })
            } else {
                Ok(s)
            }
        })
        .collect()
}

/// Which matrix of the map to build (see [`transform_matrix`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TransformKind {
    /// With the factors n!/(n−j)!/(t₁−t₀)ʲ: control points → derivatives (Eqs. 14–15).
    Transform,
    /// Without them: control points → differences (the rows of A1 and A3).
    Binomial,
}

/// The (2m+2)×(2m+2) matrix taking (p₀…pₙ) to H (Eqs. 14–15): row j is
/// n!/(n−j)!/Tʲ times row j of A1 (on p₀…pⱼ); row m+1+j is the same factor times
/// ∇ʲpₙ = Σₖ (−1)ᵏ C(j,k) pₙ₋ₖ. [`TransformKind::Binomial`] omits the factors.
pub fn transform_matrix<T: Field>(m: usize, (t0, t1): (&T, &T), kind: TransformKind) -> Matrix<T> {
    let ctx = t0.ctx();
    let n = 2 * m + 1;
    let width = t1.clone() - t0;
    let mut a = Matrix::zeros(n + 1, n + 1, &ctx);
    for j in 0..=m {
        let factor = match kind {
            TransformKind::Transform => {
                int_in::<T>(&falling_factorial(n, j), &ctx) / &powi(&width, j as u32)
            }
            TransformKind::Binomial => T::one_in(&ctx),
        };
        for k in 0..=j {
            let c = int_in::<T>(&binomial(j, k), &ctx) * &factor;
            // Δʲp₀ = Σₖ (−1)^(j−k) C(j,k) pₖ ; ∇ʲpₙ = Σₖ (−1)ᵏ C(j,k) pₙ₋ₖ
            a[(j, k)] = if (j - k) % 2 == 1 {
                -c.clone()
            } else {
                c.clone()
            };
            a[(m + 1 + j, n - k)] = if k % 2 == 1 { -c } else { c };
        }
    }
    a
}

/// The matrix of the Hermite map H → P itself, column by column (the map applied to unit
/// boundary vectors). It is the inverse of [`transform_matrix`] with `Transform`.
///
/// # Errors
/// [`HermiteError::EmptyInterval`] unless t₀ < t₁; [`HermiteError::ScaleNotRepresentable`] as
/// [`derivative_scales`].
pub fn hermite_matrix<T: Field>(m: usize, (t0, t1): (&T, &T)) -> Result<Matrix<T>, HermiteError> {
    let ctx = t0.ctx();
    let size = 2 * m + 2;
    let mut columns = Vec::with_capacity(size);
    for c in 0..size {
        let unit: Vec<T> = (0..size)
            .map(|i| {
                if i == c {
                    T::one_in(&ctx)
                } else {
                    T::zero_in(&ctx)
                }
            })
            .collect();
        let data = HermiteData::new(
            unit[..=m].to_vec(),
            unit[m + 1..].to_vec(),
            (t0.clone(), t1.clone()),
        )?;
        columns.push(data.solve()?.into_control_points());
    }
    Ok(Matrix::from_fn(size, size, |i, j| columns[j][i].clone()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::BigRational;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    #[test]
    fn lanes_are_each_problem_solved_alone_bit_for_bit() {
        let mut state = 7u64;
        let mut next = || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((state >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 10f64.powi((state % 9) as i32 - 4)
        };
        for (m, lanes) in [(0, 3), (2, 7), (11, 4)] {
            let start: Vec<f64> = (0..(m + 1) * lanes).map(|_| next()).collect();
            let end: Vec<f64> = (0..(m + 1) * lanes).map(|_| next()).collect();
            let points = solve_lanes(&start, &end, lanes, (&0.25, &1.75)).unwrap();
            for l in 0..lanes {
                let lane = |x: &[f64]| x.chunks(lanes).map(|row| row[l]).collect::<Vec<_>>();
                let alone = HermiteData::new(lane(&start), lane(&end), (0.25, 1.75))
                    .unwrap()
                    .solve()
                    .unwrap();
                for (k, p) in alone.control_points().iter().enumerate() {
                    assert_eq!(
                        points[k * lanes + l].to_bits(),
                        p.to_bits(),
                        "m {m} lane {l} k {k}"
                    );
                }
            }
        }
    }

    #[test]
    fn lanes_report_errors_in_the_order_of_a_loop_over_the_problems() {
        // Problem 0 overflows, problem 1 has a NaN: the loop meets problem 0's overflow first.
        // (m = 1 on [0, 3]: p₁ = x₀ + x₀′·3/3 = 3e308.)
        let start = [1.5e308, f64::NAN, 1.5e308, 0.0];
        let end = [0.0, 0.0, 0.0, 0.0];
        let err = solve_lanes(&start, &end, 2, (&0.0, &3.0)).unwrap_err();
        assert!(
            matches!(&err, HermiteError::NotFinite(w) if w.contains("control point")),
            "{err}"
        );
        // A NaN in problem 0 comes before anything else.
        let start = [f64::NAN, 0.0, 1.5e308, 0.0];
        let err = solve_lanes(&start, &end, 2, (&0.0, &3.0)).unwrap_err();
        assert_eq!(err, HermiteError::NotFinite("start[0]".into()));
        assert_eq!(
            solve_lanes(&[1.0, 2.0, 3.0], &[1.0], 2, (&0.0, &1.0)),
            Err(HermiteError::DimensionMismatch)
        );
    }

    fn ints(v: &[i64]) -> Vec<BigRational> {
        v.iter().map(|&x| q(x, 1)).collect()
    }

    #[test]
    fn figure_two_control_points() {
        let fast =
            HermiteData::new(ints(&[0, 0, 0]), ints(&[1, 1, 0]), (q(0, 1), q(1, 1))).unwrap();
        let p = fast.solve().unwrap().into_control_points();
        assert_eq!(
            p,
            vec![q(0, 1), q(0, 1), q(0, 1), q(3, 5), q(4, 5), q(1, 1)]
        );
        let slow =
            HermiteData::new(ints(&[0, 0, 0]), ints(&[1, 1, 0]), (q(0, 1), q(2, 1))).unwrap();
        let p = slow.solve().unwrap().into_control_points();
        assert_eq!(
            p,
            vec![q(0, 1), q(0, 1), q(0, 1), q(1, 5), q(3, 5), q(1, 1)]
        );
    }

    #[test]
    fn matrices_are_mutually_inverse() {
        for m in 0..6 {
            let (t0, t1) = (q(-1, 3), q(5, 2));
            let a = transform_matrix(m, (&t0, &t1), TransformKind::Transform);
            let h = hermite_matrix(m, (&t0, &t1)).unwrap();
            assert_eq!(a.mul(&h), Matrix::identity(2 * m + 2, &()));
        }
    }

    #[test]
    fn points_are_solved_coordinate_by_coordinate() {
        let start = vec![vec![q(0, 1), q(0, 1)], vec![q(1, 1), q(0, 1)]];
        let end = vec![vec![q(1, 1), q(1, 1)], vec![q(0, 1), q(1, 1)]];
        let p = solve_points(&start, &end, (&q(0, 1), &q(3, 2))).unwrap();
        assert_eq!(
            p,
            vec![
                vec![q(0, 1), q(0, 1)],
                vec![q(1, 2), q(0, 1)],
                vec![q(1, 1), q(1, 2)],
                vec![q(1, 1), q(1, 1)]
            ]
        );
        let ragged = vec![vec![q(0, 1)], vec![q(1, 1), q(2, 1)]];
        assert_eq!(
            solve_points(&ragged, &ragged, (&q(0, 1), &q(1, 1))),
            Err(HermiteError::DimensionMismatch)
        );
    }

    #[test]
    fn shape_errors() {
        assert_eq!(
            HermiteData::new(ints(&[0]), ints(&[1, 2]), (q(0, 1), q(1, 1))),
            Err(HermiteError::LengthMismatch { start: 1, end: 2 })
        );
        assert_eq!(
            HermiteData::new(ints(&[0]), ints(&[1]), (q(1, 1), q(1, 1))),
            Err(HermiteError::EmptyInterval)
        );
        assert_eq!(
            HermiteData::<BigRational>::new(vec![], vec![], (q(0, 1), q(1, 1))),
            Err(HermiteError::Empty)
        );
    }

    #[test]
    fn f64_scale_overflow_is_an_error() {
        // m = 200: 401!/201! ≈ 1e496 overflows f64 (m = 119 still fits: 239!/120! ≈ 1e267).
        let data = HermiteData::new(vec![0.0; 201], vec![0.0; 201], (0.0, 1.0)).unwrap();
        assert!(matches!(
            data.solve(),
            Err(HermiteError::ScaleNotRepresentable { .. })
        ));
    }
}
