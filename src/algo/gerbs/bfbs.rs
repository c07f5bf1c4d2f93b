//! Beta-function B-splines (BFBS, Eqs. 7–18).
//!
//! On the interval (t_j, t_{j+1}) of length h the kernel of Eq. (9) is
//! Ψ_j ∝ (t − t_j)^p (t_{j+1} − t)^q with p = i_j, q = i_{j+1}, and S_j normalizes its
//! integral (Eq. 8), so the rising function is the regularized incomplete beta function in
//! u = (t − t_j)/h, which has the exact Bernstein form
//!
//! F_j(u) = S_j ∫ Ψ_j = I_u(p+1, q+1) = Σ_{r=p+1}^{N} C(N, r) u^r (1−u)^{N−r},  N = p + q + 1,
//!
//! and the falling 1 − F_j is the complementary sum over r = 0 … p (no cancellation near
//! t_{j+1}; the two sums add to (u + 1 − u)^N = 1 only as an identity, which the claims check).
//!
//! It is evaluated as a Taylor series in t (exact in rational arithmetic). B_k − 1 has a zero
//! of order i_k + 1 at t_k from both sides, so the basis is C^{i_k} there and no more
//! (Dechevsky's m = min i_k). For i = 2 this is the quintic 10u³ − 15u⁴ + 6u⁵, which
//! Eqs. (12)–(13) print as Φ and Θ and Eqs. (14)–(18) differentiate: [`phi_printed`],
//! [`theta_printed`] transcribe them for the claims.

use super::{Blend, GerbsError, Knots, Located};
use crate::curve::taylor::Taylor;
use crate::numeric::poly::binom;
use crate::scalar::{powi, Field};

/// The BFBS of exponents i_k, one per basis function B_2 … B_{n+1} (the knot t_k); the end
/// intervals (t_1, t_2) and (t_{n+1}, t_{n+2}), when not empty, reuse the nearest exponent.
#[derive(Clone, Debug, PartialEq)]
pub struct Bfbs {
    /// The exponents (a, b, …) of the BFBS integrand, one per factor (private: only
    /// [`Bfbs::new`] makes a BFBS, so every exponent is in range).
    exponents: Vec<u32>,
}

/// The largest exponent accepted (keeps C(N, r) inside the binomial table).
pub const MAX_EXPONENT: u32 = 29;

impl Bfbs {
    /// A BFBS with these exponents; refused when empty or zero.
    ///
    /// # Errors
    /// [`GerbsError::Parameter`] (`params.i`) for no exponent, or one outside
    /// 1..=[`MAX_EXPONENT`].
    pub fn new(exponents: Vec<u32>) -> Result<Self, GerbsError> {
        if exponents.is_empty() {
            return Err(GerbsError::Parameter {
                field: "params.i",
                message: "need one exponent per basis function".into(),
            });
        }
        if let Some(bad) = exponents.iter().find(|&&i| i == 0 || i > MAX_EXPONENT) {
            return Err(GerbsError::Parameter {
                field: "params.i",
                message: format!("exponents must be integers in 1..={MAX_EXPONENT}, got {bad}"),
            });
        }
        Ok(Bfbs { exponents })
    }

    /// The exponents, one per basis function.
    pub fn exponents(&self) -> &[u32] {
        &self.exponents
    }

    /// The same exponent i for n basis functions (i = 2: the curvature-continuous case).
    ///
    /// # Errors
    /// [`GerbsError::Parameter`] (`params.i`) for n = 0 or i outside 1..=[`MAX_EXPONENT`].
    pub fn uniform(i: u32, n: usize) -> Result<Self, GerbsError> {
        Bfbs::new(vec![i; n])
    }

    /// The exponent i_j of knot t_j in the paper's 1-based numbering of Eq. (7), clamped to
    /// the basis functions' range 2 … n + 1 (the API's 0-based list is [`Bfbs::exponents`]:
    /// entry k is i_{k+2}).
    pub(crate) fn exponent(&self, j: usize) -> u32 {
        let n = self.exponents.len();
        self.exponents[j.clamp(2, n + 1) - 2]
    }

    /// The smoothness min i_k of the path (Sec. II-B).
    pub fn smoothness(&self) -> u32 {
        self.exponents.iter().copied().min().unwrap_or(0)
    }
}

impl Bfbs {
    /// Σ_{r ∈ terms} C(N, r) u^r (1−u)^{N−r} on interval j as a series in t: the terms
    /// r = p+1 … N give F_j, the terms r = 0 … p its complement 1 − F_j.
    fn bernstein_sum<T: Field>(
        &self,
        knots: &Knots<T>,
        at: &Located<T>,
        order: usize,
        rising: bool,
    ) -> Taylor<T> {
        let j = at.interval;
        let (p, q) = (self.exponent(j) as usize, self.exponent(j + 1) as usize);
        let ctx = at.t.ctx();
        let h = Taylor::constant(knots.at(j + 1).clone() - knots.at(j));
        // u = (t − t_j)/h and v = (t_{j+1} − t)/h from the two distances, so that each keeps
        // its relative accuracy at its own end of the interval (u^r near t_j, v^s near t_{j+1}).
        let u = Taylor::variable(at.after_start.clone(), order) / &h;
        let v = -(Taylor::variable(-at.before_end.clone(), order)) / &h;
        let big = p + q + 1;
        let mut f = Taylor::constant(T::zero_in(&ctx)).with_order(order);
        let terms = if rising { p + 1..=big } else { 0..=p };
        for r in terms {
            let term = powi(&u, r as u32) * &powi(&v, (big - r) as u32);
            f += &(term * &Taylor::constant(T::from_i64(binom(big, r), &ctx)));
        }
        f
    }
}

impl<T: Field> Blend<T> for Bfbs {
    fn rising(&self, knots: &Knots<T>, j: usize, t: &T, order: usize) -> Taylor<T> {
        self.bernstein_sum(knots, &Located::from_t(knots, t, j), order, true)
    }

    fn falling(&self, knots: &Knots<T>, j: usize, t: &T, order: usize) -> Taylor<T> {
        self.bernstein_sum(knots, &Located::from_t(knots, t, j), order, false)
    }

    fn rising_located(&self, knots: &Knots<T>, at: &Located<T>, order: usize) -> Taylor<T> {
        self.pair_located(knots, at, order).1
    }

    fn falling_located(&self, knots: &Knots<T>, at: &Located<T>, order: usize) -> Taylor<T> {
        self.pair_located(knots, at, order).0
    }

    /// 1 − F_j and F_j, each series accurate relative to itself: the one that is small at
    /// this end of the interval (F_j near t_j, its terms carry u^(p+1); 1 − F_j near
    /// t_{j+1}, v^(q+1)) is summed from its own terms, the other is 1 minus it. Summing the
    /// large one's terms would cancel in every derivative (the derivatives of the two are
    /// opposite), leaving only accuracy relative to 1 where the derivative is tiny.
    fn pair_located(
        &self,
        knots: &Knots<T>,
        at: &Located<T>,
        order: usize,
    ) -> (Taylor<T>, Taylor<T>) {
        let one = Taylor::constant(T::one_in(&at.t.ctx())).with_order(order);
        // Which end is nearer is a rounding choice (both forms are exact): a ball that
        // cannot tell takes the first.
        let near_start = at.after_start.decide_lt(&at.before_end).unwrap_or(true);
        if near_start {
            let rising = self.bernstein_sum(knots, at, order, true);
            (one - &rising, rising)
        } else {
            let falling = self.bernstein_sum(knots, at, order, false);
            (falling.clone(), one - &falling)
        }
    }

    fn basis_count(&self) -> Option<usize> {
        Some(self.exponents.len())
    }
}

/// Φ(t_{k−1}, t_k, t) and its first two derivatives as Eqs. (12), (14), (15) and (18) print
/// them (a = t_{k−1}, b = t_k).
pub fn phi_printed<T: Field>(a: &T, b: &T, t: &T) -> [T; 3] {
    let ctx = t.ctx();
    let c = |v: i64| T::from_i64(v, &ctx);
    let den = powi(&(a.clone() - b), 5);
    let at = a.clone() - t;
    let big_a = powi(&at, 3) / &den;
    let big_b = (a.clone() - &(c(5) * b) + &(c(3) * t)) * a
        + &((c(10) * b - &(c(15) * t)) * b)
        + &(c(6) * t * t);
    let da = -(c(3) * &powi(&at, 2)) / &den;
    let db = c(3) * a - &(c(15) * b) + &(c(12) * t);
    let dda = c(6) * &at / &den;
    let ddb = c(12);
    [
        big_a.clone() * &big_b,
        da.clone() * &big_b + &(big_a.clone() * &db),
        dda * &big_b + &(c(2) * &da * &db) + &(big_a * &ddb),
    ]
}

/// Θ(t_k, t_{k+1}, t) and its first two derivatives as Eqs. (13), (16), (17) and (18) print
/// them (a = t_k, b = t_{k+1}).
pub fn theta_printed<T: Field>(a: &T, b: &T, t: &T) -> [T; 3] {
    let ctx = t.ctx();
    let c = |v: i64| T::from_i64(v, &ctx);
    let den = powi(&(a.clone() - b), 5);
    let tb = t.clone() - b;
    let big_a = powi(&tb, 3) / &den;
    let big_b = (b.clone() - &(c(5) * a) + &(c(3) * t)) * b
        + &((c(10) * a - &(c(15) * t)) * a)
        + &(c(6) * t * t);
    let da = c(3) * &powi(&tb, 2) / &den;
    let db = c(3) * b - &(c(15) * a) + &(c(12) * t);
    let dda = c(6) * &tb / &den;
    let ddb = c(12);
    [
        big_a.clone() * &big_b,
        da.clone() * &big_b + &(big_a.clone() * &db),
        dda * &big_b + &(c(2) * &da * &db) + &(big_a * &ddb),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algo::gerbs::{basis_derivatives, Side};
    use crate::scalar::BigRational;

    fn r(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    #[test]
    fn quintic_case_equals_the_printed_closed_forms() {
        let knots = Knots::<BigRational>::uniform(5, &()).expect("knots");
        let b = Bfbs::uniform(2, 5).expect("exponents");
        let t = r(3, 10); // in (t_3, t_4) = (1/4, 1/2)
        let d = basis_derivatives(&knots, &b, &t, 2, Side::Right).expect("inside");
        // B_4 rises there (Φ with t_{k−1} = 1/4, t_k = 1/2), B_3 falls (Θ).
        assert_eq!(d[2], phi_printed(&r(1, 4), &r(1, 2), &t).to_vec());
        assert_eq!(d[1], theta_printed(&r(1, 4), &r(1, 2), &t).to_vec());
        let sum: BigRational = d.iter().map(|x| x[0].clone()).sum();
        assert_eq!(sum, r(1, 1));
    }
}
