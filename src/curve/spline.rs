//! Interpolating B-splines of odd degree through sampled data: periodic on non-uniform knots
//! (the smooth closed curve through orbit data, paper 001, Sec. 6A) and open on a clamped
//! knot vector ([`ClampedSpline`], for data that do not close).
//!
//! The spline s(t) = Σ_j c_j B_j(t) of degree p = 2r+1 has one B-spline centred on every data
//! time t_j (support [t_{j−r−1}, t_{j+r+1}], knots extended periodically with the period T),
//! so interpolating s(t_i) = x_i gives a cyclic banded system with p nonzeros per row
//! (B_{i±(r+1)} vanish at t_i). With simple knots a degree-p spline is C^{p−1}; the PHODCOS
//! conversion needs C⁴ Hermite data, hence p = 5 (the paper's fourth-order spline is C³ or,
//! read as degree 4, still only C³).
//!
//! The coefficients are solved once (banded elimination with partial pivoting in 128-bit
//! MPFR, rounded to nearest f64: the exact interpolant's coefficients, correctly rounded,
//! independent of the solver) and then *define* the curve: `jet` evaluates that exact
//! piecewise polynomial and its derivatives in any precision (de Boor–Cox derivatives, The
//! NURBS Book, Algorithm A2.3), so an MPFR evaluation is the same curve as the f64 one, not a
//! refit.
//!
//! # Seams
//!
//! Adjacent pieces of a C^{p−1} spline of degree p agree in p derivatives at their knot κ, so
//! P_right(x) − P_left(x) = J_κ (x − κ)^p/p!, with J_κ the jump of the p-th derivative. Let
//! P be the piece at a point c of an interval X. For x ∈ X the knots between P and x are
//! knots inside X on the far side of c, so ‖γ(x) − P(x)‖ ≤ Σ_{κ ∈ X} ‖J_κ‖ d_κ^p/p!, with d_κ
//! the distance from κ to the end of X beyond it as seen from c (the whole width of X when c
//! may lie on either side of κ). [`Curve::seam_bound`] returns this sum, rounded up, each
//! ‖J_κ‖ bounded in ball arithmetic from the f64 coefficients; [`Curve::breakpoints`] lists
//! the knots. The proven enclosures of `curve::enclosure` split their pieces at the knots and
//! add the sum to their Taylor remainders, which otherwise hold only within one piece.

use super::parametric::CurveOn;
use super::Curve;
use crate::numeric::linalg::banded::{Banded, Cyclic};
use crate::numeric::linalg::Matrix;
use crate::scalar::ball::Ball;
use crate::scalar::{Field, Float, Real};

/// The precision the interpolation systems are solved in before rounding to f64.
const FIT_BITS: u32 = 128;

/// A periodic spline curve in ℝ³.
#[derive(Clone, Debug)]
pub struct PeriodicSpline {
    /// Degree p (odd).
    degree: usize,
    /// Data times t_0 < … < t_{N−1}, and the period end t_N = t_0 + T.
    times: Vec<f64>,
    /// t_N = t_0 + T, the end of the period.
    period_end: f64,
    /// B-spline coefficients, one per data time.
    coefficients: Vec<[f64; 3]>,
}

/// Why a spline could not be fitted.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SplineError {
    /// Too few points for the degree.
    #[error("need at least {0} points for a periodic spline of this degree")]
    TooFewPoints(usize),
    /// Times that do not increase strictly (index of the first).
    #[error("times must increase strictly (row {0})")]
    NotIncreasing(usize),
    /// The periodic interpolation system is singular.
    #[error("the interpolation system is singular")]
    Singular,
    /// An even degree was asked for; interpolation here needs an odd degree.
    #[error("the degree must be odd")]
    EvenDegree,
    /// A time or a point that is NaN or infinite (the row).
    #[error("row {0} is not finite")]
    NotFinite(usize),
}

/// The first row whose time or point is not finite.
fn first_not_finite(times: &[f64], points: &[[f64; 3]]) -> Option<usize> {
    let row_ok = |i: usize| {
        times[i].is_finite()
            && points
                .get(i)
                .is_none_or(|p| p.iter().all(|x| x.is_finite()))
    };
    (0..times.len()).find(|&i| !row_ok(i))
}

impl PeriodicSpline {
    /// Interpolate points x_i at times t_i (i < N) with period end `period_end` > t_{N−1}.
    ///
    /// # Errors
    /// [`SplineError::EvenDegree`] for an even degree; [`SplineError::TooFewPoints`] for fewer
    /// than p + 2 points or one point per time missing; [`SplineError::NotFinite`] for a NaN
    /// or infinite time, coordinate or period end; [`SplineError::NotIncreasing`] for times
    /// that do not increase strictly or a period end not after the last time;
    /// [`SplineError::Singular`] if the collocation system is.
    pub fn interpolate(
        degree: usize,
        times: &[f64],
        period_end: f64,
        points: &[[f64; 3]],
    ) -> Result<Self, SplineError> {
        if degree % 2 == 0 {
            return Err(SplineError::EvenDegree);
        }
        let n = times.len();
        if n < degree + 2 || points.len() != n {
            return Err(SplineError::TooFewPoints(degree + 2));
        }
        if let Some(i) = first_not_finite(times, points).or((!period_end.is_finite()).then_some(n))
        {
            return Err(SplineError::NotFinite(i));
        }
        for i in 1..n {
            if times[i] <= times[i - 1] {
                return Err(SplineError::NotIncreasing(i));
            }
        }
        if period_end <= times[n - 1] {
            return Err(SplineError::NotIncreasing(n));
        }
        let mut spline = PeriodicSpline {
            degree,
            times: times.to_vec(),
            period_end,
            coefficients: vec![[0.0; 3]; n],
        };
        // Rows have p nonzeros around the diagonal; the band of half-width r + 1 wraps around
        // the corners (periodic knots), a cyclic banded system solved in O(N). It is solved
        // in 128-bit MPFR and rounded to nearest f64, so the curve is the exact interpolant
        // of the data with correctly rounded coefficients, whatever the elimination order.
        let half = degree.div_ceil(2);
        let mut a = Cyclic::zeros(n, half, half, &FIT_BITS);
        for (i, time) in times.iter().enumerate() {
            let t = Float::from_f64(*time, &FIT_BITS);
            let (first, values) = spline.basis_derivatives(&t, 0);
            for (j, v) in values[0].iter().enumerate() {
                let col = (first + j as i64).rem_euclid(n as i64) as usize;
                a.add(i, col, v).map_err(|_| SplineError::Singular)?;
            }
        }
        let c = a
            .solve(data_matrix(points))
            .map_err(|_| SplineError::Singular)?;
        spline.coefficients = rounded_rows(&c);
        Ok(spline)
    }

    fn n(&self) -> usize {
        self.times.len()
    }
    fn period(&self) -> f64 {
        self.period_end - self.times[0]
    }
    /// The extended knot τ_k = t_{k mod N} + ⌊k/N⌋ T, as an exact f64 sum rounded into T.
    fn knot<T: Field>(&self, k: i64, ctx: &T::Ctx) -> T {
        let n = self.n() as i64;
        let wraps = k.div_euclid(n);
        let base = T::from_f64(self.times[k.rem_euclid(n) as usize], ctx);
        base + &(T::from_f64(self.period(), ctx) * &T::from_i64(wraps, ctx))
    }

    /// The index of the first nonzero B-spline at t and the derivatives 0…`order` of the
    /// p+1 B-splines nonzero on the knot span containing t (t reduced into one period).
    fn basis_derivatives<T: Field>(&self, t: &T, order: usize) -> (i64, Vec<Vec<T>>) {
        let ctx = t.ctx();
        // Reduce t into [t_0, t_N) and find the span i with t_i ≤ t < t_{i+1}.
        let t0 = T::from_f64(self.times[0], &ctx);
        let period = T::from_f64(self.period(), &ctx);
        let mut t = t.clone();
        while t < t0 {
            t += &period;
        }
        let end = T::from_f64(self.period_end, &ctx);
        while t >= end {
            t -= &period;
        }
        let (mut lo, mut hi) = (0usize, self.n());
        while hi - lo > 1 {
            let mid = (lo + hi) / 2;
            if t >= T::from_f64(self.times[mid], &ctx) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        self.on_span(lo as i64, &t, order)
    }

    /// As [`Self::basis_derivatives`], on the polynomial piece of span i (t_i ≤ t < t_{i+1},
    /// i taken periodically), evaluated at t wherever t is.
    fn on_span<T: Field>(&self, span: i64, t: &T, order: usize) -> (i64, Vec<Vec<T>>) {
        let ctx = t.ctx();
        let p = self.degree;
        let r = (p as i64 - 1) / 2;
        // B_j has support [τ_{j−r−1}, τ_{j+r+1}]: as the NURBS-book N_{k,p} with knots
        // u_k = τ_{k−r−1}, B_j = N_{j}. On [τ_i, τ_{i+1}] = [u_s, u_{s+1}] with s = i + r + 1
        // the nonzero functions are N_{s−p} … N_s.
        let s = span + r + 1;
        let u = |k: i64| self.knot::<T>(k - r - 1, &ctx);
        let ders = ders_basis_funs(s, t, p, order, &u);
        (s - p as i64, ders)
    }

    /// An upper bound of ‖P_i^(p) − P_{i−1}^(p)‖ at the knot t_i (module doc, "Seams").
    fn jump_bound(&self, i: i64) -> f64 {
        let n = self.n() as i64;
        let t = Ball::from_f64(self.times[i.rem_euclid(n) as usize], &FIT_BITS);
        let top = |span: i64| {
            let (first, ders) = self.on_span(span, &t, self.degree);
            combine(&ders, self.degree, |j| {
                &self.coefficients[(first + j as i64).rem_euclid(n) as usize]
            })
            .swap_remove(self.degree)
        };
        norm_up(&top(i), &top(i - 1))
    }
}

/// The data points as an N × 3 right-hand side at `FIT_BITS` (exact: they are doubles).
fn data_matrix(points: &[[f64; 3]]) -> Matrix<Float> {
    Matrix::from_fn(points.len(), 3, |i, d| {
        Float::from_f64(points[i][d], &FIT_BITS)
    })
}

/// The rows of an N × 3 solution, each entry rounded to the nearest double.
fn rounded_rows(c: &Matrix<Float>) -> Vec<[f64; 3]> {
    (0..c.rows())
        .map(|j| [c[(j, 0)].to_f64(), c[(j, 1)].to_f64(), c[(j, 2)].to_f64()])
        .collect()
}

/// ‖a − b‖ rounded up, for balls.
fn norm_up(a: &[Ball; 3], b: &[Ball; 3]) -> f64 {
    let squares: f64 = (0..3)
        .map(|d| {
            let diff = a[d].clone() - &b[d];
            let top = diff.upper().abs().max(&diff.lower().abs());
            top.to_f64_round(rug::float::Round::Up).powi(2)
        })
        .sum();
    (squares * (1.0 + 1e-12)).sqrt() * (1.0 + 1e-12)
}

/// Σ_κ J_κ d_κ^p/p! rounded up over the knots (position, jump bound) of [lo, hi]: d_κ is
/// the distance from κ to the end of [lo, hi] away from the centre (the side where γ and the
/// centre's piece differ), the whole width when κ may be on either side of the centre
/// (module doc, "Seams"). Infinite for a non-finite window.
fn seam_sum(
    knots: impl Iterator<Item = (f64, f64)>,
    (lo, hi): (f64, f64),
    (centre_lo, centre_hi): (f64, f64),
    degree: usize,
) -> f64 {
    let (lo, hi) = widen(lo, hi);
    if !(lo.is_finite() && hi.is_finite()) {
        return f64::INFINITY;
    }
    // Knot positions are rounded sums: a margin covers them.
    let margin = 1e-12 * (lo.abs().max(hi.abs()) + (hi - lo));
    let factorial: f64 = (1..=degree).map(|k| k as f64).product();
    let total: f64 = knots
        .map(|(at, jump)| {
            let d = if at > centre_hi + margin {
                hi - at
            } else if at < centre_lo - margin {
                at - lo
            } else {
                hi - lo
            };
            let d = (d.max(0.0) + margin) * (1.0 + 1e-12);
            jump * d.powi(degree as i32)
        })
        .sum();
    total * (1.0 + 1e-12) / factorial * (1.0 + 1e-12)
}

/// The NURBS Book, Algorithm A2.3: derivatives 0…n of the p+1 nonzero B-splines
/// N_{s−p}, …, N_s of degree p at u in the span [U_s, U_{s+1}]. Generic over the field.
#[allow(clippy::needless_range_loop)] // the book's index arithmetic, kept recognisable
fn ders_basis_funs<T: Field>(
    s: i64,
    u: &T,
    p: usize,
    n: usize,
    knot: &impl Fn(i64) -> T,
) -> Vec<Vec<T>> {
    let ctx = u.ctx();
    let zero = T::zero_in(&ctx);
    let mut ndu = vec![vec![zero.clone(); p + 1]; p + 1];
    ndu[0][0] = T::one_in(&ctx);
    let mut left = vec![zero.clone(); p + 1];
    let mut right = vec![zero.clone(); p + 1];
    for j in 1..=p {
        left[j] = u.clone() - &knot(s + 1 - j as i64);
        right[j] = knot(s + j as i64) - u;
        let mut saved = zero.clone();
        for r in 0..j {
            ndu[j][r] = right[r + 1].clone() + &left[j - r];
            let temp = ndu[r][j - 1].clone() / &ndu[j][r];
            ndu[r][j] = saved + &(right[r + 1].clone() * &temp);
            saved = left[j - r].clone() * &temp;
        }
        ndu[j][j] = saved;
    }
    let mut ders = vec![vec![zero.clone(); p + 1]; n + 1];
    for j in 0..=p {
        ders[0][j] = ndu[j][p].clone();
    }
    let mut a = vec![vec![zero.clone(); p + 1]; 2];
    for r in 0..=p {
        let (mut s1, mut s2) = (0usize, 1usize);
        a[0][0] = T::one_in(&ctx);
        for k in 1..=n.min(p) {
            let mut d = zero.clone();
            let rk = r as i64 - k as i64;
            let pk = p - k;
            if r >= k {
                a[s2][0] = a[s1][0].clone() / &ndu[pk + 1][rk as usize];
                d = a[s2][0].clone() * &ndu[rk as usize][pk];
            }
            let j1 = if rk >= -1 { 1 } else { (-rk) as usize };
            let j2 = if r as i64 - 1 <= pk as i64 {
                k - 1
            } else {
                p - r
            };
            for j in j1..=j2 {
                let idx = (rk + j as i64) as usize;
                a[s2][j] = (a[s1][j].clone() - &a[s1][j - 1]) / &ndu[pk + 1][idx];
                d += &(a[s2][j].clone() * &ndu[idx][pk]);
            }
            if r <= pk {
                a[s2][k] = -a[s1][k - 1].clone() / &ndu[pk + 1][r];
                d += &(a[s2][k].clone() * &ndu[r][pk]);
            }
            ders[k][r] = d;
            std::mem::swap(&mut s1, &mut s2);
        }
    }
    let mut factor = p as i64;
    for k in 1..=n.min(p) {
        let f = T::from_i64(factor, &ctx);
        for j in 0..=p {
            ders[k][j] *= &f;
        }
        factor *= (p - k) as i64;
    }
    ders
}

impl PeriodicSpline {
    /// The degree p (odd).
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The data times t_0 < … < t_{N−1}.
    pub fn times(&self) -> &[f64] {
        &self.times
    }

    /// The B-spline coefficients, one per data time.
    pub fn coefficients(&self) -> &[[f64; 3]] {
        &self.coefficients
    }

    /// One period [t_0, t_N], t_N = t_0 + T.
    pub fn domain(&self) -> (f64, f64) {
        (self.times[0], self.period_end)
    }

    /// One period of the spline as a [`ParamCurve`](crate::curve::parametric::ParamCurve)
    /// of t on [`PeriodicSpline::domain`], evaluated in `T`.
    pub fn on<T: Real>(&self, ctx: &T::Ctx) -> CurveOn<&Self, T> {
        let (start, end) = self.domain();
        CurveOn::of_domain(self, T::from_f64(start, ctx), T::from_f64(end, ctx))
    }
}

impl<T: Real> Curve<T> for PeriodicSpline {
    fn jet(&self, t: &T, order: usize) -> Vec<[T; 3]> {
        let (first, ders) = self.basis_derivatives(t, order);
        let n = self.n() as i64;
        combine(&ders, order, |j| {
            &self.coefficients[(first + j as i64).rem_euclid(n) as usize]
        })
    }

    fn seam_bound(&self, lo: f64, centre: (f64, f64), hi: f64) -> f64 {
        let Some(knots) = self.knots_in(lo, hi) else {
            return f64::INFINITY;
        };
        let jumps = knots.iter().map(|&(at, i)| (at, self.jump_bound(i)));
        seam_sum(jumps, (lo, hi), centre, self.degree)
    }

    fn breakpoints(&self, lo: f64, hi: f64) -> Vec<f64> {
        self.knots_in(lo, hi)
            .unwrap_or_default()
            .into_iter()
            .map(|k| k.0)
            .collect()
    }
}

impl PeriodicSpline {
    /// Every knot t_i + mT in [lo, hi] widened (so rounding can only add knots), as
    /// (position, i); `None` for a window that is not finite or spans more than a few periods.
    fn knots_in(&self, lo: f64, hi: f64) -> Option<Vec<(f64, i64)>> {
        let (lo, hi) = widen(lo, hi);
        let (t0, period) = (self.times[0], self.period());
        if !(lo.is_finite() && hi.is_finite()) {
            return None;
        }
        let first_wrap = ((lo - self.period_end) / period).floor() as i64 - 1;
        let last_wrap = ((hi - t0) / period).ceil() as i64 + 1;
        if last_wrap - first_wrap > 8 {
            return None; // wider than a few periods: no useful list
        }
        // Per wrap m, the times with lo ≤ t_i + mT ≤ hi by a binary search (the widening
        // makes up for the rounding of t_i + mT, so no knot is missed).
        let knots = (first_wrap..=last_wrap)
            .flat_map(|m| {
                let shift = m as f64 * period;
                let first = self.times.partition_point(|&t| t + shift < lo);
                let last = self.times.partition_point(|&t| t + shift <= hi);
                (first..last.max(first)).map(move |i| (self.times[i] + shift, i as i64))
            })
            .collect();
        Some(knots)
    }
}

/// [lo, hi] widened by a relative 1e-12 of its magnitude on each side.
fn widen(lo: f64, hi: f64) -> (f64, f64) {
    let margin = 1e-12 * (lo.abs().max(hi.abs()) + (hi - lo)) + f64::MIN_POSITIVE;
    (lo - margin, hi + margin)
}

/// Σ_j c_j B_j^(k)(t) for k = 0…order, from the derivatives of the nonzero B-splines
/// (`ders[k][j]`, zero beyond the degree) and their coefficients.
fn combine<'a, T: Real>(
    ders: &[Vec<T>],
    order: usize,
    coefficient: impl Fn(usize) -> &'a [f64; 3],
) -> Vec<[T; 3]> {
    let ctx = ders[0][0].ctx();
    (0..=order)
        .map(|k| {
            let mut v = [T::zero_in(&ctx), T::zero_in(&ctx), T::zero_in(&ctx)];
            if k < ders.len() {
                for (j, b) in ders[k].iter().enumerate() {
                    let c = coefficient(j);
                    for d in 0..3 {
                        v[d].mul_add_assign(b, &T::from_f64(c[d], &ctx));
                    }
                }
            }
            v
        })
        .collect()
}

/// An open interpolating spline in ℝ³ of odd degree p on a clamped knot vector: p + 1 knots
/// at each end and interior knots at the averages of p consecutive data times (The NURBS
/// Book, Eq. 9.8, the choice that satisfies Schoenberg–Whitney, so the collocation system is
/// nonsingular). Interior knots are simple, so the spline is C^{p−1}: C⁴ for p = 5.
#[derive(Clone, Debug)]
pub struct ClampedSpline {
    /// Degree p.
    degree: usize,
    /// The knot vector u_0 … u_{N+p} (N data points).
    knots: Vec<f64>,
    /// B-spline coefficients, one per data point.
    coefficients: Vec<[f64; 3]>,
}

impl ClampedSpline {
    /// Interpolate points x_i at strictly increasing times t_i.
    ///
    /// # Errors
    /// [`SplineError::EvenDegree`] for an even degree; [`SplineError::TooFewPoints`] for fewer
    /// than p + 1 points or one point per time missing; [`SplineError::NotFinite`] for a NaN
    /// or infinite time or coordinate; [`SplineError::NotIncreasing`] for times that do not
    /// increase strictly; [`SplineError::Singular`] if the collocation system is.
    ///
    /// # Examples
    /// A quintic spline through eight samples of a helix, evaluated through the curve
    /// interface: it passes through the samples.
    /// ```
    /// use trajverify::curve::parametric::ParamCurve;
    /// use trajverify::curve::spline::ClampedSpline;
    /// let times: Vec<f64> = (0..8).map(f64::from).collect();
    /// let points: Vec<[f64; 3]> = times.iter().map(|&t| [t.cos(), t.sin(), t / 5.0]).collect();
    /// let spline = ClampedSpline::interpolate(5, &times, &points).unwrap();
    /// let p = spline.on::<f64>(&()).point(&3.0).unwrap();
    /// assert!((p[0] - 3f64.cos()).abs() < 1e-12 && (p[1] - 3f64.sin()).abs() < 1e-12);
    /// ```
    pub fn interpolate(
        degree: usize,
        times: &[f64],
        points: &[[f64; 3]],
    ) -> Result<Self, SplineError> {
        if degree % 2 == 0 {
            return Err(SplineError::EvenDegree);
        }
        let n = times.len();
        if n < degree + 1 || points.len() != n {
            return Err(SplineError::TooFewPoints(degree + 1));
        }
        if let Some(i) = first_not_finite(times, points) {
            return Err(SplineError::NotFinite(i));
        }
        if let Some(i) = (1..n).find(|&i| times[i] <= times[i - 1]) {
            return Err(SplineError::NotIncreasing(i));
        }
        let mut knots = vec![times[0]; degree + 1];
        for j in 1..n - degree {
            let sum: f64 = times[j..j + degree].iter().sum();
            knots.push(sum / degree as f64);
        }
        knots.extend(std::iter::repeat_n(times[n - 1], degree + 1));
        let mut spline = ClampedSpline {
            degree,
            knots,
            coefficients: vec![[0.0; 3]; n],
        };
        // Row i has its p + 1 nonzeros in columns span − p … span; the band is measured.
        let rows: Vec<(usize, Vec<Float>)> = times
            .iter()
            .map(|t| spline.basis_derivatives(&Float::from_f64(*t, &FIT_BITS), 0))
            .map(|(first, ders)| (first, ders.into_iter().next().unwrap_or_default()))
            .collect();
        let lower = rows.iter().enumerate().map(|(i, r)| i.saturating_sub(r.0));
        let upper = rows
            .iter()
            .enumerate()
            .map(|(i, r)| (r.0 + degree).saturating_sub(i));
        let mut a = Banded::zeros(
            n,
            lower.max().unwrap_or(0),
            upper.max().unwrap_or(0),
            &FIT_BITS,
        );
        for (i, (first, values)) in rows.iter().enumerate() {
            for (j, v) in values.iter().enumerate() {
                a.add(i, first + j, v).map_err(|_| SplineError::Singular)?;
            }
        }
        let c = a
            .solve(data_matrix(points))
            .map_err(|_| SplineError::Singular)?;
        spline.coefficients = rounded_rows(&c);
        Ok(spline)
    }

    /// The degree p.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The B-spline coefficients, one per data point.
    pub fn coefficients(&self) -> &[[f64; 3]] {
        &self.coefficients
    }

    /// The spline as a [`ParamCurve`](crate::curve::parametric::ParamCurve) of t on
    /// [`ClampedSpline::domain`], evaluated in `T` (the coefficients are doubles, exact in
    /// every number type with at least 53 bits).
    pub fn on<T: Real>(&self, ctx: &T::Ctx) -> CurveOn<&Self, T> {
        let (start, end) = self.domain();
        CurveOn::of_domain(self, T::from_f64(start, ctx), T::from_f64(end, ctx))
    }

    /// The data's time range [t_0, t_{N−1}].
    pub fn domain(&self) -> (f64, f64) {
        (self.knots[0], self.knots[self.knots.len() - 1])
    }

    /// The index of the first nonzero B-spline at t and the derivatives 0…`order` of the
    /// p + 1 B-splines nonzero there (outside the domain, the end pieces extended).
    fn basis_derivatives<T: Field>(&self, t: &T, order: usize) -> (usize, Vec<Vec<T>>) {
        let ctx = t.ctx();
        let p = self.degree;
        let last = self.knots.len() - p - 2;
        // The span s in p … N−1 with u_s ≤ t < u_{s+1} (the last span is closed).
        let (mut lo, mut hi) = (p, last + 1);
        while hi - lo > 1 {
            let mid = (lo + hi) / 2;
            if *t >= T::from_f64(self.knots[mid], &ctx) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        self.on_span(lo, t, order)
    }

    /// As [`Self::basis_derivatives`], on the polynomial piece of span s (p ≤ s ≤ N − 1).
    fn on_span<T: Field>(&self, s: usize, t: &T, order: usize) -> (usize, Vec<Vec<T>>) {
        let ctx = t.ctx();
        let knot = |k: i64| T::from_f64(self.knots[k as usize], &ctx);
        (
            s - self.degree,
            ders_basis_funs(s as i64, t, self.degree, order, &knot),
        )
    }

    /// An upper bound of the jump of the p-th derivative at the interior knot u_s
    /// (p < s < N), between spans s − 1 and s.
    fn jump_bound(&self, s: usize) -> f64 {
        let t = Ball::from_f64(self.knots[s], &FIT_BITS);
        let top = |span: usize| {
            let (first, ders) = self.on_span(span, &t, self.degree);
            combine(&ders, self.degree, |j| &self.coefficients[first + j]).swap_remove(self.degree)
        };
        norm_up(&top(s), &top(s - 1))
    }
}

impl<T: Real> Curve<T> for ClampedSpline {
    fn jet(&self, t: &T, order: usize) -> Vec<[T; 3]> {
        let (first, ders) = self.basis_derivatives(t, order);
        combine(&ders, order, |j| &self.coefficients[first + j])
    }

    fn seam_bound(&self, lo: f64, centre: (f64, f64), hi: f64) -> f64 {
        let jumps = self
            .knots_in(lo, hi)
            .map(|s| (self.knots[s], self.jump_bound(s)));
        seam_sum(jumps, (lo, hi), centre, self.degree)
    }

    fn breakpoints(&self, lo: f64, hi: f64) -> Vec<f64> {
        self.knots_in(lo, hi).map(|s| self.knots[s]).collect()
    }
}

impl ClampedSpline {
    /// The indices of the interior knots u_{p+1} … u_{N−1} inside [lo, hi] widened (sorted:
    /// two binary searches).
    fn knots_in(&self, lo: f64, hi: f64) -> std::ops::Range<usize> {
        let (lo, hi) = widen(lo, hi);
        if !(lo.is_finite() && hi.is_finite()) {
            return 0..0;
        }
        let p = self.degree;
        let first = self.knots.partition_point(|&k| k < lo).max(p + 1);
        let last = self
            .knots
            .partition_point(|&k| k <= hi)
            .min(self.knots.len() - p - 1);
        first..last.max(first)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn periodic_quintic_reproduces_a_circle_closely_and_is_c4() {
        // Non-uniform times on one period of a circle.
        let n = 40;
        let times: Vec<f64> = (0..n)
            .map(|i| {
                let u = i as f64 / n as f64;
                u + 0.02 * (6.0 * u).sin()
            })
            .collect();
        let pts: Vec<[f64; 3]> = times
            .iter()
            .map(|&t| {
                let a = 2.0 * std::f64::consts::PI * t;
                [a.cos(), a.sin(), 0.0]
            })
            .collect();
        let s = PeriodicSpline::interpolate(5, &times, 1.0, &pts).unwrap();
        for (i, &t) in times.iter().enumerate() {
            let j = Curve::<f64>::jet(&s, &t, 0);
            assert!((j[0][0] - pts[i][0]).abs() < 1e-12 && (j[0][1] - pts[i][1]).abs() < 1e-12);
        }
        // Between the data: close to the circle.
        let j = Curve::<f64>::jet(&s, &0.5123, 1);
        let a = 2.0 * std::f64::consts::PI * 0.5123;
        assert!((j[0][0] - a.cos()).abs() < 1e-6);
        assert!((j[1][1] - 2.0 * std::f64::consts::PI * a.cos()).abs() < 1e-4);
        // C⁴ across a knot, and periodic across the period end.
        for t in [times[7], 1.0] {
            let l = Curve::<f64>::jet(&s, &(t - 1e-9), 4);
            let r = Curve::<f64>::jet(&s, &(t + 1e-9), 4);
            for k in 0..=4 {
                let scale = (2.0 * std::f64::consts::PI).powi(k as i32);
                assert!((l[k][0] - r[k][0]).abs() < 1e-4 * scale, "order {k} at {t}");
            }
            // The fifth derivative jumps at a knot (C⁴, not C⁵) in general.
        }
    }

    #[test]
    fn clamped_quintic_reproduces_quintic_polynomials_and_is_c4() {
        // Degree-5 polynomials lie in the spline space, so their interpolant is themselves.
        let poly = |t: f64| {
            [
                t.powi(5) - 2.0 * t * t,
                1.0 - t.powi(3),
                0.5 * t.powi(4) + t,
            ]
        };
        let times: Vec<f64> = (0..17)
            .map(|i| {
                let u = i as f64 / 16.0;
                u * u * 1.5 - 0.25
            })
            .collect();
        let points: Vec<[f64; 3]> = times.iter().map(|&t| poly(t)).collect();
        let s = ClampedSpline::interpolate(5, &times, &points).unwrap();
        assert_eq!(s.domain(), (times[0], times[16]));
        for t in [-0.25, -0.1, 0.3337, 0.9, 1.25] {
            let j = Curve::<f64>::jet(&s, &t, 5);
            let exact = poly(t);
            for d in 0..3 {
                assert!((j[0][d] - exact[d]).abs() < 1e-12, "value at {t}");
            }
            // Fifth derivative of x: 120 everywhere.
            assert!((j[5][0] - 120.0).abs() < 1e-6, "x^(5) at {t}: {}", j[5][0]);
        }
        // A non-polynomial is C⁴ across an interior knot, not C⁵.
        let wave: Vec<[f64; 3]> = times
            .iter()
            .map(|&t| [t.sin(), (3.0 * t).cos(), 0.0])
            .collect();
        let w = ClampedSpline::interpolate(5, &times, &wave).unwrap();
        let knot = w.knots[9];
        let l = Curve::<f64>::jet(&w, &(knot - 1e-9), 5);
        let r = Curve::<f64>::jet(&w, &(knot + 1e-9), 5);
        for k in 0..=4 {
            assert!((l[k][1] - r[k][1]).abs() < 1e-4, "order {k}");
        }
        assert!(
            (l[5][1] - r[5][1]).abs() > 1e-3,
            "the fifth derivative jumps"
        );
        assert_eq!(
            ClampedSpline::interpolate(5, &[0.0, 1.0, 1.0, 2.0, 3.0, 4.0], &[[0.0; 3]; 6]).err(),
            Some(SplineError::NotIncreasing(2))
        );
    }

    /// ‖γ(x) − P(x)‖ at `samples` points of [lo, hi], P the piece of `span` evaluated by
    /// `piece`, against the seam bound.
    fn check_seams(
        curve: &dyn Curve<Float>,
        piece: &dyn Fn(&Float) -> [Float; 3],
        (lo, hi): (f64, f64),
        bound: f64,
    ) -> f64 {
        let mut largest = 0.0f64;
        for i in 0..=200 {
            let x = Float::with_val(256, lo + (hi - lo) * f64::from(i) / 200.0);
            let g = curve.jet(&x, 0).swap_remove(0);
            let p = piece(&x);
            let d: f64 = (0..3)
                .map(|k| Float::with_val(256, &g[k] - &p[k]).to_f64().powi(2))
                .sum::<f64>()
                .sqrt();
            assert!(d <= bound, "{d:e} > seam bound {bound:e} at {x}");
            largest = largest.max(d);
        }
        largest
    }

    #[test]
    fn seam_bounds_cover_the_distance_to_a_neighbouring_piece() {
        let times: Vec<f64> = (0..30)
            .map(|i| {
                let u = f64::from(i) / 30.0;
                u + 0.02 * (6.0 * u).sin()
            })
            .collect();
        let pts: Vec<[f64; 3]> = times
            .iter()
            .map(|&t| [(6.0 * t).cos(), (4.0 * t).sin(), t * t])
            .collect();
        let closed = PeriodicSpline::interpolate(5, &times, 1.0, &pts).unwrap();
        let open = ClampedSpline::interpolate(5, &times, &pts).unwrap();
        let closed = &closed;
        let piece_closed = |span: i64| {
            move |x: &Float| {
                let (first, ders) = closed.on_span(span, x, 0);
                combine(&ders, 0, |j| {
                    &closed.coefficients[(first + j as i64).rem_euclid(30) as usize]
                })
                .swap_remove(0)
            }
        };
        // Around knots 10–12, from span 10; and across the period's end from span 29.
        for (span, window) in [
            (10i64, (times[10] - 0.01, times[12] + 0.02)),
            (29, (0.99, 1.03)),
        ] {
            // The piece of `span` at a point of the window inside that span.
            let centre = if span == 10 {
                (times[10] + times[11]) / 2.0
            } else {
                0.995
            };
            let bound = Curve::<Float>::seam_bound(closed, window.0, (centre, centre), window.1);
            let seen = check_seams(closed, &piece_closed(span), window, bound);
            assert!(
                seen > 0.0 && bound < 1e4 * seen,
                "bound {bound:e}, seen {seen:e}"
            );
        }
        // Inside one span there is no seam.
        assert_eq!(
            Curve::<Float>::seam_bound(
                closed,
                times[3] + 1e-3,
                (times[3] + 0.01, times[3] + 0.01),
                times[4] - 1e-3
            ),
            0.0
        );
        let s = 5 + 8; // span of the clamped knot vector
        let window = (open.knots[s] - 0.02, open.knots[s + 2] + 0.01);
        let piece_open = |x: &Float| {
            let (first, ders) = open.on_span(s, x, 0);
            combine(&ders, 0, |j| &open.coefficients[first + j]).swap_remove(0)
        };
        let centre = (open.knots[s] + open.knots[s + 1]) / 2.0;
        let bound = Curve::<Float>::seam_bound(&open, window.0, (centre, centre), window.1);
        let seen = check_seams(&open, &piece_open, window, bound);
        assert!(
            seen > 0.0 && bound < 1e4 * seen,
            "bound {bound:e}, seen {seen:e}"
        );
    }
}
