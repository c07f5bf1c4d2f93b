//! Periodic interpolating B-splines of odd degree on non-uniform knots: the smooth curve
//! through sampled orbit data (paper 001, Sec. 6A).
//!
//! The spline s(t) = Σ_j c_j B_j(t) of degree p = 2r+1 has one B-spline centred on every data
//! time t_j (support [t_{j−r−1}, t_{j+r+1}], knots extended periodically with the period T),
//! so interpolating s(t_i) = x_i gives a cyclic banded system with p nonzeros per row
//! (B_{i±(r+1)} vanish at t_i). With simple knots a degree-p spline is C^{p−1}; the PHODCOS
//! conversion needs C⁴ Hermite data, hence p = 5 (the paper's fourth-order spline is C³ or,
//! read as degree 4, still only C³).
//!
//! The coefficients are solved once in f64 (Gaussian elimination with partial pivoting) and
//! then *define* the curve: [`PeriodicSpline::jet`] evaluates that exact piecewise
//! polynomial and its derivatives in any precision (de Boor–Cox derivatives, The NURBS Book,
//! Algorithm A2.3), so an MPFR evaluation is the same curve as the f64 one, not a refit.

use super::Curve;
use crate::numeric::linalg::{gauss, Matrix};
use crate::scalar::{Field, Real};

/// A periodic spline curve in ℝ³.
#[derive(Clone, Debug)]
pub struct PeriodicSpline {
    /// Degree p (odd).
    pub degree: usize,
    /// Data times t_0 < … < t_{N−1}, and the period end t_N = t_0 + T.
    pub times: Vec<f64>,
    /// t_N = t_0 + T, the end of the period.
    pub period_end: f64,
    /// B-spline coefficients, one per data time.
    pub coefficients: Vec<[f64; 3]>,
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
    /// An even degree was asked for; periodic interpolation here needs an odd degree.
    #[error("the degree must be odd")]
    EvenDegree,
}

impl PeriodicSpline {
    /// Interpolate points x_i at times t_i (i < N) with period end `period_end` > t_{N−1}.
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
        let mut a = Matrix::from_fn(n, n, |_, _| 0.0);
        for i in 0..n {
            let (first, values) = spline.basis_derivatives(&times[i], 0);
            for (j, v) in values[0].iter().enumerate() {
                let col = (first + j as i64).rem_euclid(n as i64) as usize;
                a[(i, col)] += *v;
            }
        }
        for d in 0..3 {
            let b: Vec<f64> = points.iter().map(|p| p[d]).collect();
            let c = gauss::solve(&a, &b).map_err(|_| SplineError::Singular)?;
            for (j, cj) in c.into_iter().enumerate() {
                spline.coefficients[j][d] = cj;
            }
        }
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
        let p = self.degree;
        let r = (p as i64 - 1) / 2;
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
        let span = lo as i64;
        // B_j has support [τ_{j−r−1}, τ_{j+r+1}]: as the NURBS-book N_{k,p} with knots
        // u_k = τ_{k−r−1}, B_j = N_{j}. On [τ_i, τ_{i+1}] = [u_s, u_{s+1}] with s = i + r + 1
        // the nonzero functions are N_{s−p} … N_s.
        let s = span + r + 1;
        let u = |k: i64| self.knot::<T>(k - r - 1, &ctx);
        let ders = ders_basis_funs(s, &t, p, order, &u);
        (s - p as i64, ders)
    }
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

impl<T: Real> Curve<T> for PeriodicSpline {
    fn jet(&self, t: &T, order: usize) -> Vec<[T; 3]> {
        let ctx = t.ctx();
        let (first, ders) = self.basis_derivatives(t, order);
        let n = self.n() as i64;
        (0..=order)
            .map(|k| {
                let mut v = [T::zero_in(&ctx), T::zero_in(&ctx), T::zero_in(&ctx)];
                if k < ders.len() {
                    for (j, b) in ders[k].iter().enumerate() {
                        let c = &self.coefficients[(first + j as i64).rem_euclid(n) as usize];
                        for d in 0..3 {
                            v[d].mul_add_assign(b, &T::from_f64(c[d], &ctx));
                        }
                    }
                }
                v
            })
            .collect()
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
}
