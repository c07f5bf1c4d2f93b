//! Polynomials in the power basis, Σ aᵢ xⁱ, over any [`Field`]: the exact pieces of splines.
//!
//! Products, derivatives, antiderivatives, definite integrals and the shift x → x + c are all
//! exact in rationals, which is what lets B-spline identities and Gram matrices be verified
//! exactly rather than to a tolerance.

use crate::scalar::Field;

/// A polynomial Σ aᵢ xⁱ. The zero polynomial has no coefficients; trailing zero
/// coefficients are trimmed, so equality is equality of polynomials.
#[derive(Clone, Debug, PartialEq)]
pub struct Poly<T> {
    coeffs: Vec<T>,
}

impl<T: Field> Poly<T> {
    /// The polynomial with these coefficients of x⁰, x¹, … (trailing zeros trimmed).
    pub fn new(mut coeffs: Vec<T>) -> Self {
        while coeffs.last().is_some_and(Field::is_zero) {
            coeffs.pop();
        }
        Poly { coeffs }
    }

    /// The zero polynomial.
    pub fn zero() -> Self {
        Poly { coeffs: Vec::new() }
    }

    /// The constant polynomial c.
    pub fn constant(c: T) -> Self {
        Self::new(vec![c])
    }

    /// a + b·x.
    pub fn linear(a: T, b: T) -> Self {
        Self::new(vec![a, b])
    }

    /// The coefficients of x⁰, x¹, … (empty for the zero polynomial).
    pub fn coeffs(&self) -> &[T] {
        &self.coeffs
    }

    /// The coefficients padded with zeros to `len` entries (for fixed-size output).
    pub fn coeffs_padded(&self, len: usize, ctx: &T::Ctx) -> Vec<T> {
        let mut c = self.coeffs.clone();
        c.resize(len.max(c.len()), T::zero_in(ctx));
        c
    }

    /// Whether every coefficient is zero.
    pub fn is_zero(&self) -> bool {
        self.coeffs.is_empty()
    }

    /// The degree, or `None` for the zero polynomial.
    pub fn degree(&self) -> Option<usize> {
        self.coeffs.len().checked_sub(1)
    }

    /// The value at x by Horner's rule (`zero` supplies the context for the zero polynomial).
    pub fn eval(&self, x: &T) -> T {
        let mut acc = T::zero_in(&x.ctx());
        for c in self.coeffs.iter().rev() {
            acc = acc * x + c;
        }
        acc
    }

    /// The sum.
    pub fn add(&self, other: &Poly<T>) -> Poly<T> {
        let (long, short) = if self.coeffs.len() >= other.coeffs.len() {
            (self, other)
        } else {
            (other, self)
        };
        let mut c = long.coeffs.clone();
        for (a, b) in c.iter_mut().zip(&short.coeffs) {
            *a += b;
        }
        Poly::new(c)
    }

    /// The sum, reusing this polynomial's storage (the same operations as [`Poly::add`]).
    pub fn plus(mut self, other: &Poly<T>) -> Poly<T> {
        if self.coeffs.len() < other.coeffs.len() {
            return other.add(&self);
        }
        for (a, b) in self.coeffs.iter_mut().zip(&other.coeffs) {
            *a += b;
        }
        Poly::new(self.coeffs)
    }

    /// The polynomial times a scalar, in its own storage (the same operations as
    /// [`Poly::scale`]).
    pub fn times(mut self, s: &T) -> Poly<T> {
        for c in &mut self.coeffs {
            *c *= s;
        }
        Poly::new(self.coeffs)
    }

    /// The polynomial times a scalar.
    pub fn scale(&self, s: &T) -> Poly<T> {
        Poly::new(self.coeffs.iter().map(|c| c.clone() * s).collect())
    }

    /// The difference.
    pub fn sub(&self, other: &Poly<T>) -> Poly<T> {
        let ctx = match (self.coeffs.first(), other.coeffs.first()) {
            (Some(c), _) | (None, Some(c)) => c.ctx(),
            (None, None) => return Poly::zero(),
        };
        self.add(&other.scale(&-T::one_in(&ctx)))
    }

    /// The product (exact convolution of the coefficients).
    pub fn mul(&self, other: &Poly<T>) -> Poly<T> {
        if self.is_zero() || other.is_zero() {
            return Poly::zero();
        }
        let ctx = self.coeffs[0].ctx();
        let mut c = vec![T::zero_in(&ctx); self.coeffs.len() + other.coeffs.len() - 1];
        for (i, a) in self.coeffs.iter().enumerate() {
            for (j, b) in other.coeffs.iter().enumerate() {
                c[i + j].mul_add_assign(a, b);
            }
        }
        Poly::new(c)
    }

    /// The derivative d/dx.
    pub fn derivative(&self) -> Poly<T> {
        Poly::new(
            self.coeffs
                .iter()
                .enumerate()
                .skip(1)
                .map(|(i, c)| c.clone() * &T::from_i64(i as i64, &c.ctx()))
                .collect(),
        )
    }

    /// The j-th derivative.
    pub fn nth_derivative(&self, j: usize) -> Poly<T> {
        (0..j).fold(self.clone(), |p, _| p.derivative())
    }

    /// The antiderivative vanishing at 0.
    pub fn antiderivative(&self) -> Poly<T> {
        let Some(first) = self.coeffs.first() else {
            return Poly::zero();
        };
        let ctx = first.ctx();
        let mut c = vec![T::zero_in(&ctx)];
        c.extend(
            self.coeffs
                .iter()
                .enumerate()
                .map(|(i, a)| a.clone() / &T::from_i64(i as i64 + 1, &ctx)),
        );
        Poly::new(c)
    }

    /// ∫ₐᵇ p(x) dx.
    pub fn integrate(&self, (a, b): (&T, &T)) -> T {
        let anti = self.antiderivative();
        anti.eval(b) - &anti.eval(a)
    }

    /// The polynomial q(x) = p(x + c), by Horner's rule on polynomials.
    pub fn shift(&self, c: &T) -> Poly<T> {
        let mut acc = Poly::zero();
        for a in self.coeffs.iter().rev() {
            acc = acc
                .mul(&Poly::linear(c.clone(), T::one_in(&c.ctx())))
                .add(&Poly::constant(a.clone()));
        }
        acc
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::BigRational;

    fn p(c: &[i64]) -> Poly<BigRational> {
        Poly::new(
            c.iter()
                .map(|&x| BigRational::from_integer(x.into()))
                .collect(),
        )
    }
    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    #[test]
    fn arithmetic_and_calculus() {
        let a = p(&[1, 2]); // 1 + 2x
        let b = p(&[-1, 0, 3]); // −1 + 3x²
        assert_eq!(a.mul(&b), p(&[-1, -2, 3, 6]));
        assert_eq!(a.add(&b), p(&[0, 2, 3]));
        assert_eq!(a.sub(&a), Poly::zero());
        assert_eq!(b.derivative(), p(&[0, 6]));
        assert_eq!(b.integrate((&q(0, 1), &q(1, 1))), q(0, 1));
        assert_eq!(p(&[0, 0, 1]).shift(&q(1, 1)), p(&[1, 2, 1]));
        assert_eq!(p(&[5, 0, 0, 0]).degree(), Some(0));
        assert_eq!(b.eval(&q(2, 1)), q(11, 1));
    }
}
