//! The field Q(√2) = {a + b√2 : a, b ∈ Q}, exact, as a [`Field`].
//!
//! Paper 002's bang-bang control has switching times 2 ± √2 and amplitude (2 + √2)/2; in this
//! field every constraint it must meet is checked with no rounding at all. Order is exact
//! too: the sign of a + b√2 follows from the signs of a and b and, when they differ, from
//! comparing a² with 2b².

use super::{BigRational, Field};
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;
use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};

/// a + b√2 with rational a and b (the representation is unique, so `==` is equality).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct QSqrt2 {
    /// The rational part a.
    pub a: BigRational,
    /// The coefficient b of √2.
    pub b: BigRational,
}

impl QSqrt2 {
    /// The value as a reader writes it: over one common denominator, with √2 and a minus sign
    /// ("2 − √2", "(2 + √2)/2", "−3√2/4").
    pub fn to_math_string(&self) -> String {
        let d = num_integer::Integer::lcm(self.a.denom(), self.b.denom());
        let a = (&self.a * BigRational::from_integer(d.clone())).to_integer();
        let b = (&self.b * BigRational::from_integer(d.clone())).to_integer();
        let root = |b: &num_bigint::BigInt| {
            if Signed::abs(b).is_one() {
                "√2".to_string()
            } else {
                format!("{}√2", Signed::abs(b))
            }
        };
        let minus = |n: &num_bigint::BigInt| if n.is_negative() { "−" } else { "" };
        let (numerator, terms) = match (Zero::is_zero(&a), Zero::is_zero(&b)) {
            (_, true) => (format!("{}{}", minus(&a), Signed::abs(&a)), 1),
            (true, false) => (format!("{}{}", minus(&b), root(&b)), 1),
            (false, false) => (
                format!(
                    "{}{} {} {}",
                    minus(&a),
                    Signed::abs(&a),
                    if b.is_negative() { "−" } else { "+" },
                    root(&b)
                ),
                2,
            ),
        };
        match (d.is_one(), terms) {
            (true, _) => numerator,
            (false, 1) => format!("{numerator}/{d}"),
            (false, _) => format!("({numerator})/{d}"),
        }
    }

    /// a + b√2.
    pub fn new(a: BigRational, b: BigRational) -> Self {
        QSqrt2 { a, b }
    }

    /// √2 itself.
    pub fn sqrt2() -> Self {
        QSqrt2 {
            a: BigRational::zero(),
            b: BigRational::one(),
        }
    }

    /// The conjugate a − b√2.
    pub fn conjugate(&self) -> Self {
        QSqrt2 {
            a: self.a.clone(),
            b: -self.b.clone(),
        }
    }

    /// The sign of a + b√2.
    pub fn signum(&self) -> Ordering {
        let (sa, sb) = (
            self.a.cmp(&BigRational::zero()),
            self.b.cmp(&BigRational::zero()),
        );
        match (sa, sb) {
            (Ordering::Equal, s) | (s, Ordering::Equal) => s,
            (s, t) if s == t => s,
            // Opposite signs: |a| against |b|√2, i.e. a² against 2b².
            (s, _) => {
                let a2 = self.a.clone() * &self.a;
                let b2 = self.b.clone() * &self.b * BigRational::from_integer(2.into());
                match a2.cmp(&b2) {
                    Ordering::Greater => s,
                    Ordering::Less => s.reverse(),
                    Ordering::Equal => Ordering::Equal, // impossible for rationals unless both 0
                }
            }
        }
    }
}

impl PartialOrd for QSqrt2 {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some((self.clone() - other).signum())
    }
}

impl Neg for QSqrt2 {
    type Output = QSqrt2;
    fn neg(self) -> QSqrt2 {
        QSqrt2 {
            a: -self.a,
            b: -self.b,
        }
    }
}

impl Add<&QSqrt2> for QSqrt2 {
    type Output = QSqrt2;
    fn add(self, r: &QSqrt2) -> QSqrt2 {
        QSqrt2 {
            a: self.a + &r.a,
            b: self.b + &r.b,
        }
    }
}
impl Sub<&QSqrt2> for QSqrt2 {
    type Output = QSqrt2;
    fn sub(self, r: &QSqrt2) -> QSqrt2 {
        QSqrt2 {
            a: self.a - &r.a,
            b: self.b - &r.b,
        }
    }
}
impl Mul<&QSqrt2> for QSqrt2 {
    type Output = QSqrt2;
    fn mul(self, r: &QSqrt2) -> QSqrt2 {
        // (a + b√2)(c + d√2) = (ac + 2bd) + (ad + bc)√2
        let two = BigRational::from_integer(2.into());
        QSqrt2 {
            a: self.a.clone() * &r.a + two * &self.b * &r.b,
            b: self.a * &r.b + self.b * &r.a,
        }
    }
}
impl Div<&QSqrt2> for QSqrt2 {
    type Output = QSqrt2;
    /// Multiply by the conjugate: 1/(c + d√2) = (c − d√2)/(c² − 2d²). Division by zero panics,
    /// as for `BigRational`.
    fn div(self, r: &QSqrt2) -> QSqrt2 {
        let norm = r.a.clone() * &r.a - BigRational::from_integer(2.into()) * &r.b * &r.b;
        let num = self * &r.conjugate();
        QSqrt2 {
            a: num.a / &norm,
            b: num.b / &norm,
        }
    }
}

/// The owned-right-operand and compound-assignment forms, from the borrowed ones above.
macro_rules! forward_ops {
    ($($op:ident $method:ident $assign:ident $assign_method:ident),*) => {$(
        impl $op<QSqrt2> for QSqrt2 {
            type Output = QSqrt2;
            fn $method(self, r: QSqrt2) -> QSqrt2 {
                $op::<&QSqrt2>::$method(self, &r)
            }
        }
        impl $assign<&QSqrt2> for QSqrt2 {
            fn $assign_method(&mut self, r: &QSqrt2) {
                let lhs = std::mem::replace(self, QSqrt2 { a: BigRational::zero(), b: BigRational::zero() });
                *self = $op::<&QSqrt2>::$method(lhs, r);
            }
        }
    )*};
}
forward_ops!(Add add AddAssign add_assign, Sub sub SubAssign sub_assign, Mul mul MulAssign mul_assign, Div div DivAssign div_assign);

impl Field for QSqrt2 {
    type Ctx = ();

    fn ctx(&self) {}
    fn scalar_name(_: &()) -> String {
        "Q(sqrt2)".into()
    }
    fn from_i64(v: i64, _: &()) -> Self {
        Self::from_rational(&BigRational::from_integer(v.into()), &())
    }
    fn from_ratio(n: i64, d: i64, _: &()) -> Self {
        Self::from_rational(&BigRational::new(n.into(), d.into()), &())
    }
    fn from_rational(q: &BigRational, _: &()) -> Self {
        QSqrt2 {
            a: q.clone(),
            b: BigRational::zero(),
        }
    }
    fn from_f64(v: f64, _: &()) -> Self {
        Self::from_rational(&<BigRational as Field>::from_f64(v, &()), &())
    }
    fn abs(&self) -> Self {
        if self.signum() == Ordering::Less {
            -self.clone()
        } else {
            self.clone()
        }
    }
    fn is_zero(&self) -> bool {
        Zero::is_zero(&self.a) && Zero::is_zero(&self.b)
    }
    fn is_finite(&self) -> bool {
        true
    }
    fn to_f64(&self) -> f64 {
        self.to_float(64).to_f64()
    }
    fn to_rational(&self) -> Option<BigRational> {
        Zero::is_zero(&self.b).then(|| self.a.clone())
    }
    fn to_plain_string(&self) -> String {
        let root = |b: &BigRational| {
            if Signed::abs(b).is_one() {
                "sqrt(2)".to_string()
            } else {
                format!("{}*sqrt(2)", Signed::abs(b))
            }
        };
        match (Zero::is_zero(&self.a), Zero::is_zero(&self.b)) {
            (_, true) => self.a.to_string(),
            (true, false) => format!(
                "{}{}",
                if self.b.is_negative() { "-" } else { "" },
                root(&self.b)
            ),
            (false, false) => format!(
                "{} {} {}",
                self.a,
                if self.b.is_negative() { "-" } else { "+" },
                root(&self.b)
            ),
        }
    }
}

impl QSqrt2 {
    /// The value in any real number type: a + b·√2 with a, b rounded once each and √2 taken
    /// in `T` (in balls, an enclosure of the exact value).
    pub fn to_real<T: super::Real>(&self, ctx: &T::Ctx) -> T {
        let root = T::from_i64(2, ctx).sqrt();
        T::from_rational(&self.a, ctx) + &(T::from_rational(&self.b, ctx) * &root)
    }

    /// Proven bounds lo ≤ a + b√2 ≤ hi at `bits` precision, for any size of a and b (no
    /// ball radius to overflow): √2 is bracketed by its downward and upward roundings, and
    /// each exact operation with a rational is rounded outward.
    pub fn bounds(&self, bits: u32) -> (super::Float, super::Float) {
        use rug::float::Round;
        let work = bits + 32;
        let two = super::Float::with_val(work, 2);
        let root_down = super::Float::with_val_round(work, two.sqrt_ref(), Round::Down).0;
        let root_up = super::Float::with_val_round(work, two.sqrt_ref(), Round::Up).0;
        let a = super::mpfr_rational(&self.a);
        let b = super::mpfr_rational(&self.b);
        let end = |round: Round| {
            // b·√2 is smallest with the smaller root when b ≥ 0, with the larger one otherwise.
            let root = if (b >= 0) == (round == Round::Down) {
                &root_down
            } else {
                &root_up
            };
            let product = super::Float::with_val_round(work, root * &b, round).0;
            super::Float::with_val_round(bits, product + &a, round).0
        };
        (end(Round::Down), end(Round::Up))
    }

    /// The value rounded to an MPFR number of `bits` precision (√2 correctly rounded first,
    /// then a + b·√2 with one rounding per operation).
    pub fn to_float(&self, bits: u32) -> super::Float {
        let work = bits + 32;
        let root = super::Float::with_val(work, 2).sqrt();
        let a = <super::Float as Field>::from_rational(&self.a, &work);
        let b = <super::Float as Field>::from_rational(&self.b, &work);
        super::Float::with_val(bits, a + b * root)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    #[test]
    fn arithmetic_is_exact() {
        let r2 = QSqrt2::sqrt2();
        assert_eq!(r2.clone() * &r2, QSqrt2::from_i64(2, &()));
        let x = QSqrt2::new(q(2, 1), q(1, 1)); // 2 + √2
        let inv = QSqrt2::from_i64(1, &()) / &x;
        assert_eq!(inv.clone() * &x, QSqrt2::from_i64(1, &()));
        assert_eq!(inv, QSqrt2::new(q(1, 1), q(-1, 2))); // 1/(2+√2) = 1 − √2/2
        assert_eq!(x.to_plain_string(), "2 + sqrt(2)");
        assert_eq!(
            QSqrt2::new(q(1, 1), q(-1, 2)).to_plain_string(),
            "1 - 1/2*sqrt(2)"
        );
    }

    #[test]
    fn order_is_exact() {
        let r2 = QSqrt2::sqrt2();
        assert!(r2 > QSqrt2::from_ratio(141, 100, &()));
        assert!(r2 < QSqrt2::from_ratio(142, 100, &()));
        assert!(QSqrt2::new(q(3, 1), q(-2, 1)) > QSqrt2::from_i64(0, &())); // 3 − 2√2 ≈ 0.17
        assert!(QSqrt2::new(q(-3, 1), q(2, 1)) < QSqrt2::from_i64(0, &()));
        assert!((QSqrt2::new(q(1, 1), q(-1, 1))).abs() > QSqrt2::from_i64(0, &()));
        assert!((QSqrt2::from_i64(2, &()).to_f64() - 2.0).abs() == 0.0);
        assert!((r2.to_f64() - std::f64::consts::SQRT_2).abs() == 0.0);
    }
}
