//! A polynomial in Bernstein form on an interval [t₀, t₁] (paper 000, Sec. 2.1 and 3.1).
//!
//! B(t) = Σₖ pₖ b̄ₖⁿ(t) with b̄ₖⁿ(t) = C(n,k)(t₁−t)ⁿ⁻ᵏ(t−t₀)ᵏ/(t₁−t₀)ⁿ (Eqs. 1–4). The
//! j-th derivative is again in Bernstein form:
//! dʲB/dtʲ = n!/(n−j)!/(t₁−t₀)ʲ Σₖ b̄ₖⁿ⁻ʲ(t) Δʲpₖ (Eqs. 12–13), so at the ends it is
//! n!/(n−j)!/(t₁−t₀)ʲ·Δʲp₀ and n!/(n−j)!/(t₁−t₀)ʲ·∇ʲpₙ (Eqs. 14–15).
//!
//! Evaluation is by de Casteljau (convex combinations: stable in floating point, exact in
//! rationals). [`Bernstein::to_power_basis`] expands the basis polynomials directly, without
//! the difference operators, and serves as the independent check of the derivative
//! formulas.

use super::differences::{backward_differences, forward_differences};
use super::{binomial, falling_factorial, int_in};
use crate::scalar::{powi, Field};

/// Why control points and an interval do not make a Bernstein polynomial.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum BernsteinError {
    /// No control point.
    #[error("a Bernstein polynomial needs at least one control point")]
    Empty,
    /// An interval without t₀ < t₁.
    #[error("the interval [t0, t1] needs t0 < t1")]
    Interval,
    /// A control point that is not finite (NaN or ±∞), by its index.
    #[error("control point {0} is not finite")]
    NotFinite(usize),
}

/// A scalar polynomial of degree n = `control_points.len() − 1` on [t₀, t₁].
///
/// An arithmetic kernel: its constructor refuses non-finite data, but evaluation and the
/// derivatives are plain arithmetic in `T` and are not checked for overflow (the j-th
/// derivative carries 1/(t₁ − t₀)ʲ, beyond f64's range on a tiny interval). The checked
/// curve, whose every evaluation is an error rather than NaN or ∞, is
/// [`crate::curve::bezier::BezierCurve`].
#[derive(Clone, Debug, PartialEq)]
pub struct Bernstein<T> {
    control_points: Vec<T>,
    t0: T,
    t1: T,
}

/// The value at `t` of the basis polynomial b̄ₖⁿ on [t₀, t₁] (Eq. 4).
pub fn basis<T: Field>(n: usize, k: usize, t: &T, (t0, t1): (&T, &T)) -> T {
    let ctx = t.ctx();
    let c: T = int_in(&binomial(n, k), &ctx);
    let left = t1.clone() - t;
    let right = t.clone() - t0;
    let width = t1.clone() - t0;
    c * &powi(&left, (n - k) as u32) * &powi(&right, k as u32) / &powi(&width, n as u32)
}

impl<T: Field> Bernstein<T> {
    /// A polynomial from its control points on [t₀, t₁].
    ///
    /// # Errors
    /// [`BernsteinError::Empty`] without a control point; [`BernsteinError::Interval`] unless
    /// t₀ < t₁ with a finite width t₁ − t₀ (equal ends would divide by zero, NaN compares
    /// neither way); [`BernsteinError::NotFinite`] for a control point that is NaN or ±∞.
    ///
    /// # Examples
    /// ```
    /// use trajverify::numeric::poly::Bernstein;
    /// use trajverify::scalar::BigRational;
    /// let q = |n: i64| BigRational::from_integer(n.into());
    /// // The Fig. 2 control points of paper 000 on [0, 1]: B(1/2) = 1/2 exactly.
    /// let b = Bernstein::new(vec![q(0), q(0), q(0), q(1), q(1), q(1)], (q(0), q(1))).unwrap();
    /// assert_eq!(b.eval(&BigRational::new(1.into(), 2.into())), BigRational::new(1.into(), 2.into()));
    /// assert!(Bernstein::<f64>::new(vec![], (0.0, 1.0)).is_err());
    /// assert!(Bernstein::new(vec![1.0], (1.0, 1.0)).is_err());
    /// ```
    pub fn new(control_points: Vec<T>, (t0, t1): (T, T)) -> Result<Self, BernsteinError> {
        if control_points.is_empty() {
            return Err(BernsteinError::Empty);
        }
        // Finite ends a finite width apart (the derivatives divide by t₁ − t₀).
        let width = t1.clone() - &t0;
        if t0.partial_cmp(&t1) != Some(std::cmp::Ordering::Less) || !width.is_finite() {
            return Err(BernsteinError::Interval);
        }
        if let Some(k) = control_points.iter().position(|p| !p.is_finite()) {
            return Err(BernsteinError::NotFinite(k));
        }
        Ok(Bernstein {
            control_points,
            t0,
            t1,
        })
    }

    /// A polynomial on this one's interval (valid by construction: the interval was checked,
    /// and `control_points` is never empty where it is called).
    fn on_same_interval(&self, control_points: Vec<T>) -> Bernstein<T> {
        Bernstein {
            control_points,
            t0: self.t0.clone(),
            t1: self.t1.clone(),
        }
    }

    /// The control points b_0 … b_n.
    pub fn control_points(&self) -> &[T] {
        &self.control_points
    }

    /// The control points, by value.
    pub fn into_control_points(self) -> Vec<T> {
        self.control_points
    }

    /// The start t₀ of the interval.
    pub fn t0(&self) -> &T {
        &self.t0
    }

    /// The end t₁ of the interval.
    pub fn t1(&self) -> &T {
        &self.t1
    }

    /// The degree n.
    pub fn degree(&self) -> usize {
        self.control_points.len() - 1
    }

    /// t₁ − t₀.
    pub fn duration(&self) -> T {
        self.t1.clone() - &self.t0
    }

    /// ζ = (t − t₀)/(t₁ − t₀) (Eq. 3).
    pub fn local_parameter(&self, t: &T) -> T {
        (t.clone() - &self.t0) / &self.duration()
    }

    /// B(t) by de Casteljau's algorithm.
    pub fn eval(&self, t: &T) -> T {
        let zeta = self.local_parameter(t);
        let one_minus = T::one_in(&zeta.ctx()) - &zeta;
        let mut row = self.control_points.clone();
        for len in (1..row.len()).rev() {
            for i in 0..len {
                row[i] = one_minus.clone() * &row[i] + &(zeta.clone() * &row[i + 1]);
            }
        }
        row.swap_remove(0)
    }

    /// The derivative dB/dt as a polynomial of degree n − 1 (Eq. 5 with the factor
    /// 1/(t₁−t₀) of Eq. 13). The derivative of a constant is the zero constant.
    pub fn derivative(&self) -> Bernstein<T> {
        let ctx = self.t0.ctx();
        let n = self.degree();
        if n == 0 {
            return self.on_same_interval(vec![T::zero_in(&ctx)]);
        }
        let scale = T::from_i64(n as i64, &ctx) / &self.duration();
        let points = self
            .control_points
            .windows(2)
            .map(|w| (w[1].clone() - &w[0]) * &scale)
            .collect();
        self.on_same_interval(points)
    }

    /// The j-th derivative dʲB/dtʲ as a polynomial (repeated [`Self::derivative`]).
    pub fn nth_derivative(&self, j: usize) -> Bernstein<T> {
        (0..j).fold(self.clone(), |b, _| b.derivative())
    }

    /// The j-th derivative in the closed form of Eqs. 12–13: the polynomial of degree n−j
    /// with control points n!/(n−j)!/(t₁−t₀)ʲ·Δʲpₖ, k = 0…n−j. For j > n, the zero constant.
    pub fn derivative_closed_form(&self, j: usize) -> Bernstein<T> {
        let ctx = self.t0.ctx();
        if j > self.degree() {
            return self.on_same_interval(vec![T::zero_in(&ctx)]);
        }
        let factor = self.derivative_factor(j);
        let n = self.degree();
        let points = (0..=n - j)
            .map(|k| forward_differences(&self.control_points[k..=k + j])[j].clone() * &factor)
            .collect();
        self.on_same_interval(points)
    }

    /// The factor n!/(n−j)!/(t₁−t₀)ʲ of Eqs. 13–15.
    pub fn derivative_factor(&self, j: usize) -> T {
        let ctx = self.t0.ctx();
        let ff: T = super::falling_factorial_in(self.degree(), j, &ctx);
        ff / &powi(&self.duration(), j as u32)
    }

    /// dʲB/dtʲ(t₀) = n!/(n−j)!/(t₁−t₀)ʲ·Δʲp₀ (Eq. 14); zero for j > n.
    pub fn derivative_at_start(&self, j: usize) -> T {
        match forward_differences(&self.control_points).get(j) {
            Some(d) => d.clone() * &self.derivative_factor(j),
            None => T::zero_in(&self.t0.ctx()),
        }
    }

    /// dʲB/dtʲ(t₁) = n!/(n−j)!/(t₁−t₀)ʲ·∇ʲpₙ (Eq. 15); zero for j > n.
    pub fn derivative_at_end(&self, j: usize) -> T {
        match backward_differences(&self.control_points).get(j) {
            Some(d) => d.clone() * &self.derivative_factor(j),
            None => T::zero_in(&self.t0.ctx()),
        }
    }

    /// The coefficients a₀…aₙ of B in powers of the local parameter, B = Σ aᵢ ζⁱ, obtained by
    /// expanding each C(n,k)(1−ζ)ⁿ⁻ᵏζᵏ with the binomial theorem (no difference operators).
    pub fn to_power_basis(&self) -> Vec<T> {
        let ctx = self.t0.ctx();
        let n = self.degree();
        let mut a = vec![T::zero_in(&ctx); n + 1];
        for (k, p) in self.control_points.iter().enumerate() {
            let ck = binomial(n, k);
            // (1−ζ)^(n−k) ζ^k = Σ_l C(n−k, l)(−1)^l ζ^(k+l)
            for l in 0..=n - k {
                let c: T = int_in(&(ck.clone() * binomial(n - k, l)), &ctx);
                let term = c * p;
                if l % 2 == 0 {
                    a[k + l] += &term;
                } else {
                    a[k + l] -= &term;
                }
            }
        }
        a
    }

    /// The same curve as a polynomial of degree n + 1:
    /// p̂ᵢ = i/(n+1)·pᵢ₋₁ + (1 − i/(n+1))·pᵢ (end of Sec. 4).
    pub fn elevate(&self) -> Bernstein<T> {
        let ctx = self.t0.ctx();
        let n = self.degree();
        let m = (n + 1) as i64;
        let p = &self.control_points;
        let points = (0..=n + 1)
            .map(|i| {
                let w = T::from_ratio(i as i64, m, &ctx);
                let one_minus = T::one_in(&ctx) - &w;
                match i {
                    0 => p[0].clone(),
                    i if i == n + 1 => p[n].clone(),
                    i => w * &p[i - 1] + &(one_minus * &p[i]),
                }
            })
            .collect();
        self.on_same_interval(points)
    }

    /// Elevate `times` times.
    pub fn elevate_by(&self, times: usize) -> Bernstein<T> {
        (0..times).fold(self.clone(), |b, _| b.elevate())
    }
}

/// The j-th derivative with respect to t at ζ of a polynomial given by power-basis
/// coefficients in ζ on an interval of length `duration`: Σᵢ i!/(i−j)! aᵢ ζ^(i−j) / durationʲ.
pub fn power_basis_derivative<T: Field>(a: &[T], j: usize, zeta: &T, duration: &T) -> T {
    let ctx = zeta.ctx();
    let mut acc = T::zero_in(&ctx);
    for i in (j..a.len()).rev() {
        // Horner in ζ over the differentiated coefficients.
        let c: T = int_in(&falling_factorial(i, j), &ctx);
        acc = acc * zeta + &(c * &a[i]);
    }
    acc / &powi(duration, j as u32)
}

/// Values and derivatives up to `order` of the Bernstein polynomial Σ c_i B_i^n on [0, 1]
/// with vector coefficients: the k-th derivative is n!/(n−k)! times the de Casteljau value
/// of the k-th forward differences.
#[allow(clippy::needless_range_loop)] // component loops over the const dimension D
pub fn bernstein_jet<T: Field, const D: usize>(
    ctrl: &[[T; D]],
    xi: &T,
    order: usize,
) -> Vec<[T; D]> {
    let n = ctrl.len() - 1;
    let ctx = xi.ctx();
    let one_minus = T::one_in(&ctx) - xi;
    let mut diffs: Vec<[T; D]> = ctrl.to_vec();
    let mut out = Vec::with_capacity(order + 1);
    let mut factor = T::one_in(&ctx);
    for k in 0..=order {
        if k > n {
            out.push(std::array::from_fn(|_| T::zero_in(&ctx)));
            continue;
        }
        if k > 0 {
            for i in 0..diffs.len() - 1 {
                for d in 0..D {
                    let next = diffs[i + 1][d].clone() - &diffs[i][d];
                    diffs[i][d] = next;
                }
            }
            diffs.pop();
            factor *= &T::from_i64((n - k + 1) as i64, &ctx);
        }
        let mut work = diffs.clone();
        for r in (1..work.len()).rev() {
            for i in 0..r {
                for d in 0..D {
                    let mut v = work[i][d].clone() * &one_minus;
                    v.mul_add_assign(&work[i + 1][d], xi);
                    work[i][d] = v;
                }
            }
        }
        let mut value = work.swap_remove(0);
        if k > 0 {
            for v in value.iter_mut() {
                *v *= &factor;
            }
        }
        out.push(value);
    }
    out
}

/// The whole Taylor expansion at `u` of the Bernstein polynomial Σ c_i B_i^n on [0, 1] with
/// vector coefficients: a_j = p^(j)(u)/j! for j = 0…n, in O(n²) operations where
/// [`bernstein_jet`] to order n takes O(n³).
///
/// For u ≤ ½, one de Casteljau triangle at u gives the control points r_0…r_n of p on [u, 1]
/// (subdivision), and p(u + (1 − u)v) = Σ r_i B_i^n(v) has the Taylor coefficients
/// C(n, j)·Δ^j r_0 in v at v = 0 (Eq. 14 of paper 000 with n!/(n−j)!/j! = C(n, j)), so
/// a_j = C(n, j)·Δ^j r_0/(1 − u)^j. For u > ½ the reversed polygon at 1 − u gives the same
/// with the odd coefficients negated; either way the division is by a length of at least ½.
///
/// # Panics
/// If `ctrl` is empty.
#[allow(clippy::needless_range_loop)] // component loops over the const dimension D
pub fn bernstein_taylor<T: Field, const D: usize>(ctrl: &[[T; D]], u: &T) -> Vec<[T; D]> {
    let ctx = u.ctx();
    let one = T::one_in(&ctx);
    let half = T::from_ratio(1, 2, &ctx);
    let mirrored = *u > half;
    let (mut work, x): (Vec<[T; D]>, T) = if mirrored {
        (ctrl.iter().rev().cloned().collect(), one.clone() - u)
    } else {
        (ctrl.to_vec(), u.clone())
    };
    let n = work.len() - 1;
    let length = one - &x;
    // The triangle in place: after pass r, work[0..=n−r] holds level r of de Casteljau,
    // b_i^(r) = (1 − x)·b_i^(r−1) + x·b_(i+1)^(r−1). The right polygon is the last entry of
    // every level, r_j = b_j^(n−j): pass r yields r_(n−r).
    let mut right: Vec<[T; D]> = Vec::with_capacity(n + 1);
    right.push(work[n].clone());
    for r in 1..=n {
        for i in 0..=n - r {
            for d in 0..D {
                let mut v = work[i][d].clone() * &length;
                v.mul_add_assign(&work[i + 1][d], &x);
                work[i][d] = v;
            }
        }
        right.push(work[n - r].clone());
    }
    // right[r] = r_(n−r); reversed, right[j] = r_j.
    right.reverse();
    // Forward differences of r in place: after pass j, right[0] is Δ^j r_0.
    let mut out = Vec::with_capacity(n + 1);
    let mut scale = T::one_in(&ctx);
    for j in 0..=n {
        if j > 0 {
            for i in 0..=n - j {
                for d in 0..D {
                    let next = right[i + 1][d].clone() - &right[i][d];
                    right[i][d] = next;
                }
            }
            // C(n, j)/(1 − x)^j from C(n, j − 1)/(1 − x)^(j − 1).
            scale *= &T::from_ratio((n - j + 1) as i64, j as i64, &ctx);
            scale /= &length;
        }
        let negate = mirrored && j % 2 == 1;
        out.push(std::array::from_fn(|d| {
            let a = right[0][d].clone() * &scale;
            if negate {
                -a
            } else {
                a
            }
        }));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::BigRational;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    fn sample() -> Bernstein<BigRational> {
        Bernstein::new(
            vec![q(1, 1), q(-2, 1), q(3, 2), q(5, 1)],
            (q(1, 1), q(3, 1)),
        )
        .unwrap()
    }

    #[test]
    fn de_casteljau_matches_basis_sum() {
        let b = sample();
        for t in [q(1, 1), q(3, 2), q(7, 3), q(3, 1)] {
            let direct = (0..=3).fold(q(0, 1), |acc, k| {
                acc + basis(3, k, &t, (&b.t0, &b.t1)) * &b.control_points[k]
            });
            assert_eq!(b.eval(&t), direct);
        }
        assert_eq!(b.eval(&q(1, 1)), q(1, 1));
        assert_eq!(b.eval(&q(3, 1)), q(5, 1));
    }

    #[test]
    fn end_derivatives_match_power_basis() {
        let b = sample();
        let a = b.to_power_basis();
        let zero = q(0, 1);
        let one = q(1, 1);
        for j in 0..=4 {
            assert_eq!(
                b.derivative_at_start(j),
                power_basis_derivative(&a, j, &zero, &b.duration())
            );
            assert_eq!(
                b.derivative_at_end(j),
                power_basis_derivative(&a, j, &one, &b.duration())
            );
            assert_eq!(
                b.nth_derivative(j).eval(&q(2, 1)),
                power_basis_derivative(&a, j, &q(1, 2), &b.duration())
            );
        }
    }

    #[test]
    fn taylor_expansion_is_the_jet_over_factorials() {
        let ctrl: Vec<[BigRational; 2]> = [(1, 3), (-2, 5), (7, 2), (0, 1), (5, -4), (-3, 2)]
            .iter()
            .map(|&(x, y)| [q(x, 1), q(y, 7)])
            .collect();
        // Both sides of ½ (the mirrored branch), ½ itself and the ends.
        for u in [q(0, 1), q(1, 3), q(1, 2), q(3, 4), q(1, 1)] {
            let jet = bernstein_jet(&ctrl, &u, 5);
            let taylor = bernstein_taylor(&ctrl, &u);
            assert_eq!(taylor.len(), 6);
            let mut factorial = q(1, 1);
            for (j, (a, d)) in taylor.iter().zip(&jet).enumerate() {
                if j > 0 {
                    factorial *= q(j as i64, 1);
                }
                for i in 0..2 {
                    assert_eq!(a[i], d[i].clone() / &factorial, "u = {u}, j = {j}");
                }
            }
        }
    }

    #[test]
    fn elevation_keeps_the_curve() {
        let b = sample();
        let e = b.elevate_by(3);
        assert_eq!(e.degree(), 6);
        let mut pa = b.to_power_basis();
        pa.resize(7, q(0, 1));
        assert_eq!(e.to_power_basis(), pa);
    }
}
