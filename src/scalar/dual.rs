//! Dual numbers a + bε (ε² = 0) over any [`Field`]: forward-mode differentiation of generic code.
//!
//! Evaluating a function written over `Field` at x + 1·ε yields f(x) + f′(x)ε, so with
//! `Dual<BigRational>` the derivative of, say, paper 004's objective G(h) comes out exactly,
//! independently of any hand-derived gradient formula. Order compares the real parts (then the
//! infinitesimal parts), which is what comparisons in the differentiated code mean.

use super::{BigRational, Field};
use std::cmp::Ordering;
use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};

/// re + du·ε.
#[derive(Clone, Debug, PartialEq)]
pub struct Dual<T> {
    /// The value.
    pub re: T,
    /// The derivative.
    pub du: T,
}

impl<T: Field> Dual<T> {
    /// The constant c (derivative 0).
    pub fn constant(re: T) -> Self {
        let du = T::zero_in(&re.ctx());
        Dual { re, du }
    }
    /// The variable x (derivative 1).
    pub fn variable(re: T) -> Self {
        let du = T::one_in(&re.ctx());
        Dual { re, du }
    }
    /// The point `values` seeded for the partial derivative with respect to entry `k`: entry
    /// k is a variable, every other entry a constant.
    pub fn seeded(values: &[T], k: usize) -> Vec<Self> {
        values
            .iter()
            .enumerate()
            .map(|(i, x)| {
                if i == k {
                    Dual::variable(x.clone())
                } else {
                    Dual::constant(x.clone())
                }
            })
            .collect()
    }
    /// Every entry as a constant.
    pub fn constants(values: &[T]) -> Vec<Self> {
        values.iter().cloned().map(Dual::constant).collect()
    }
}

impl<T: Field> PartialOrd for Dual<T> {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        match self.re.partial_cmp(&other.re)? {
            Ordering::Equal => self.du.partial_cmp(&other.du),
            o => Some(o),
        }
    }
}

impl<T: Field> Neg for Dual<T> {
    type Output = Dual<T>;
    fn neg(self) -> Self {
        Dual {
            re: -self.re,
            du: -self.du,
        }
    }
}
impl<T: Field> Add<&Dual<T>> for Dual<T> {
    type Output = Dual<T>;
    fn add(self, r: &Dual<T>) -> Self {
        Dual {
            re: self.re + &r.re,
            du: self.du + &r.du,
        }
    }
}
impl<T: Field> Sub<&Dual<T>> for Dual<T> {
    type Output = Dual<T>;
    fn sub(self, r: &Dual<T>) -> Self {
        Dual {
            re: self.re - &r.re,
            du: self.du - &r.du,
        }
    }
}
impl<T: Field> Mul<&Dual<T>> for Dual<T> {
    type Output = Dual<T>;
    fn mul(self, r: &Dual<T>) -> Self {
        let du = self.re.clone() * &r.du + &(self.du * &r.re);
        Dual {
            re: self.re * &r.re,
            du,
        }
    }
}
impl<T: Field> Div<&Dual<T>> for Dual<T> {
    type Output = Dual<T>;
    /// (a + bε)/(c + dε) = a/c + (bc − ad)/c² ε.
    fn div(self, r: &Dual<T>) -> Self {
        let re = self.re.clone() / &r.re;
        let du = (self.du * &r.re - &(self.re * &r.du)) / &(r.re.clone() * &r.re);
        Dual { re, du }
    }
}

/// The owned-right-operand and compound-assignment forms, from the borrowed ones.
macro_rules! forward_ops {
    ($($op:ident $method:ident $assign:ident $assign_method:ident),*) => {$(
        impl<T: Field> $op<Dual<T>> for Dual<T> {
            type Output = Dual<T>;
            fn $method(self, r: Dual<T>) -> Self {
                $op::<&Dual<T>>::$method(self, &r)
            }
        }
        impl<T: Field> $assign<&Dual<T>> for Dual<T> {
            fn $assign_method(&mut self, r: &Dual<T>) {
                *self = $op::<&Dual<T>>::$method(self.clone(), r);
            }
        }
    )*};
}
forward_ops!(Add add AddAssign add_assign, Sub sub SubAssign sub_assign, Mul mul MulAssign mul_assign, Div div DivAssign div_assign);

impl<T: Field> Field for Dual<T> {
    type Ctx = T::Ctx;

    fn ctx(&self) -> T::Ctx {
        self.re.ctx()
    }
    fn scalar_name(ctx: &T::Ctx) -> String {
        format!("dual<{}>", T::scalar_name(ctx))
    }
    fn from_i64(v: i64, ctx: &T::Ctx) -> Self {
        Dual::constant(T::from_i64(v, ctx))
    }
    fn from_ratio(n: i64, d: i64, ctx: &T::Ctx) -> Self {
        Dual::constant(T::from_ratio(n, d, ctx))
    }
    fn from_rational(q: &BigRational, ctx: &T::Ctx) -> Self {
        Dual::constant(T::from_rational(q, ctx))
    }
    fn from_exact(q: &rug::Rational, ctx: &T::Ctx) -> Self {
        Dual::constant(T::from_exact(q, ctx))
    }
    fn from_f64(v: f64, ctx: &T::Ctx) -> Self {
        Dual::constant(T::from_f64(v, ctx))
    }
    fn abs(&self) -> Self {
        if self.re < T::zero_in(&self.ctx()) {
            -self.clone()
        } else {
            self.clone()
        }
    }
    fn is_zero(&self) -> bool {
        self.re.is_zero() && self.du.is_zero()
    }
    fn is_finite(&self) -> bool {
        self.re.is_finite() && self.du.is_finite()
    }
    fn to_f64(&self) -> f64 {
        self.re.to_f64()
    }
    fn to_rational(&self) -> Option<BigRational> {
        self.re.to_rational()
    }
    fn to_plain_string(&self) -> String {
        format!(
            "{} + {}ε",
            self.re.to_plain_string(),
            self.du.to_plain_string()
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn derivative_of_a_rational_function() {
        // f(x) = (x² + 1)/(x − 2) at x = 3: f = 10, f′ = (2x(x−2) − (x²+1))/(x−2)² = −4.
        let x = Dual::variable(BigRational::from_integer(3.into()));
        let one = Dual::from_i64(1, &());
        let two = Dual::from_i64(2, &());
        let f = (x.clone() * &x + &one) / &(x - &two);
        assert_eq!(f.re, BigRational::from_integer(10.into()));
        assert_eq!(f.du, BigRational::from_integer((-4).into()));
    }
}
