//! Truncated Taylor series: forward-mode automatic differentiation to any order.
//!
//! A [`Taylor`] holds the normalized coefficients c_k = f⁽ᵏ⁾(t₀)/k!, k = 0…K, of a function at
//! a point. Arithmetic and the elementary functions propagate them with the classical
//! recurrences (Griewank & Walther, *Evaluating Derivatives*, ch. 13): a product is a Cauchy
//! convolution, a quotient solves the convolution for the unknown, and exp, ln, sin/cos,
//! sqrt and atan use the differential equations they satisfy (e.g. (eᵘ)′ = u′eᵘ gives
//! k e_k = Σ j u_j e_{k−j}). Every coefficient is computed in the working precision with no
//! differencing, so the derivatives are as accurate as the function value.
//!
//! [`Taylor`] implements [`Field`] and [`Real`], so generic code (the expression evaluator,
//! quaternion frames) differentiates itself. A series of length 1 is a constant and combines
//! with a series of any length; two non-constant series combine to the shorter length.

use crate::scalar::{BigRational, Field, Real};
use std::cmp::Ordering;
use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};

/// c₀ + c₁ s + … + c_K s^K, the expansion of a function at a point in the offset s.
#[derive(Clone, Debug, PartialEq)]
pub struct Taylor<T> {
    /// The normalized Taylor coefficients c_k = f⁽ᵏ⁾(t₀)/k!.
    pub c: Vec<T>,
}

impl<T: Field> Taylor<T> {
    /// The constant v (a series of length 1).
    pub fn constant(v: T) -> Self {
        Taylor { c: vec![v] }
    }
    /// The variable t at t₀, to order K: t₀ + s.
    pub fn variable(t0: T, order: usize) -> Self {
        let ctx = t0.ctx();
        let mut c = vec![t0];
        if order >= 1 {
            c.push(T::one_in(&ctx));
        }
        c.resize(order + 1, T::zero_in(&ctx));
        Taylor { c }
    }
    /// Series with these normalized coefficients; `None` for no coefficient (a series has at
    /// least its value).
    pub fn from_coeffs(c: Vec<T>) -> Option<Self> {
        (!c.is_empty()).then_some(Taylor { c })
    }
    /// The series padded with zeros (or cut) to `order`: a constant result, such as an
    /// expression without t, as a series of the requested length.
    pub fn with_order(mut self, order: usize) -> Self {
        let ctx = self.c[0].ctx();
        self.c.resize(order + 1, T::zero_in(&ctx));
        self
    }
    /// The series of a function from its derivatives f(t₀), f′(t₀), …: c_k = f⁽ᵏ⁾/k!.
    pub fn from_derivatives(d: Vec<T>) -> Self {
        let ctx = d[0].ctx();
        let mut fact = T::one_in(&ctx);
        let c = d
            .into_iter()
            .enumerate()
            .map(|(k, x)| {
                if k > 1 {
                    fact *= &T::from_i64(k as i64, &ctx);
                }
                x / &fact
            })
            .collect();
        Taylor { c }
    }
    /// The order: the number of coefficients minus one.
    pub fn order(&self) -> usize {
        self.c.len() - 1
    }
    /// The value f(t₀).
    pub fn value(&self) -> &T {
        &self.c[0]
    }
    /// f⁽ᵏ⁾(t₀) = k! c_k for k = 0…K.
    pub fn derivatives(&self) -> Vec<T> {
        let ctx = self.c[0].ctx();
        let mut fact = T::one_in(&ctx);
        self.c
            .iter()
            .enumerate()
            .map(|(k, ck)| {
                if k > 1 {
                    fact *= &T::from_i64(k as i64, &ctx);
                }
                ck.clone() * &fact
            })
            .collect()
    }
    /// Coefficient k, zero beyond a constant's length.
    fn at(&self, k: usize) -> T {
        self.c
            .get(k)
            .cloned()
            .unwrap_or_else(|| T::zero_in(&self.c[0].ctx()))
    }
    /// Coefficients 0…n−1 (zeros beyond a constant's length), for the O(n²) recurrences:
    /// one copy each instead of one per use.
    fn padded(&self, n: usize) -> Vec<T> {
        (0..n).map(|k| self.at(k)).collect()
    }
    fn combined_len(&self, other: &Self) -> usize {
        match (self.c.len(), other.c.len()) {
            (1, n) | (n, 1) => n,
            (a, b) => a.min(b),
        }
    }
    fn with_len(mut self, n: usize) -> Self {
        let ctx = self.c[0].ctx();
        self.c.resize(n, T::zero_in(&ctx));
        self
    }
    fn scale(&self, s: &T) -> Self {
        Taylor {
            c: self.c.iter().map(|x| x.clone() * s).collect(),
        }
    }
    /// The series of the primitive of `deriv` with constant term `c0`: coefficient k of the
    /// result is deriv_{k−1}/k, of length n.
    pub fn integrate(deriv: &Taylor<T>, c0: T, n: usize) -> Self {
        let ctx = c0.ctx();
        let mut c = vec![c0];
        for k in 1..n {
            c.push(deriv.at(k - 1) / &T::from_i64(k as i64, &ctx));
        }
        Taylor { c }
    }
    /// u′ as a series one shorter (coefficient k is (k+1) u_{k+1}); a constant gives 0.
    pub fn derivative_series(&self) -> Self {
        let ctx = self.c[0].ctx();
        if self.c.len() == 1 {
            return Taylor::constant(T::zero_in(&ctx));
        }
        Taylor {
            c: (1..self.c.len())
                .map(|k| self.c[k].clone() * &T::from_i64(k as i64, &ctx))
                .collect(),
        }
    }
}

impl<T: Real> Taylor<T> {
    /// (sin u, cos u) together: s′ = c u′, c′ = −s u′.
    pub fn sin_cos_series(&self) -> (Self, Self) {
        let n = self.c.len();
        let (s0, c0) = self.c[0].sin_cos();
        let du = self.derivative_series().padded(n - 1);
        let (mut s, mut c) = (vec![s0], vec![c0]);
        let ctx = self.c[0].ctx();
        for k in 1..n {
            // k s_k = Σ_{j=1..k} j u_j c_{k−j},  k c_k = −Σ j u_j s_{k−j}
            let (mut sk, mut ck) = (T::zero_in(&ctx), T::zero_in(&ctx));
            for j in 1..=k {
                sk.mul_add_assign(&du[j - 1], &c[k - j]);
                ck.mul_sub_assign(&du[j - 1], &s[k - j]);
            }
            let kk = T::from_i64(k as i64, &ctx);
            s.push(sk / &kk);
            c.push(ck / &kk);
        }
        (Taylor { c: s }, Taylor { c })
    }
}

impl<T: Field> PartialOrd for Taylor<T> {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        self.c[0].partial_cmp(&other.c[0])
    }
}

impl<T: Field> Neg for Taylor<T> {
    type Output = Taylor<T>;
    fn neg(self) -> Self {
        Taylor {
            c: self.c.into_iter().map(|x| -x).collect(),
        }
    }
}
impl<T: Field> Add<&Taylor<T>> for Taylor<T> {
    type Output = Taylor<T>;
    fn add(self, r: &Taylor<T>) -> Self {
        let n = self.combined_len(r);
        let mut out = self.with_len(n);
        for (k, x) in out.c.iter_mut().enumerate() {
            if let Some(y) = r.c.get(k) {
                *x += y;
            }
        }
        out
    }
}
impl<T: Field> Sub<&Taylor<T>> for Taylor<T> {
    type Output = Taylor<T>;
    fn sub(self, r: &Taylor<T>) -> Self {
        let n = self.combined_len(r);
        let mut out = self.with_len(n);
        for (k, x) in out.c.iter_mut().enumerate() {
            if let Some(y) = r.c.get(k) {
                *x -= y;
            }
        }
        out
    }
}
impl<T: Field> Mul<&Taylor<T>> for Taylor<T> {
    type Output = Taylor<T>;
    /// The Cauchy product, truncated.
    fn mul(self, r: &Taylor<T>) -> Self {
        if r.c.len() == 1 {
            return self.scale(&r.c[0]);
        }
        if self.c.len() == 1 {
            return r.scale(&self.c[0]);
        }
        let n = self.combined_len(r);
        let ctx = self.c[0].ctx();
        let c = (0..n)
            .map(|k| {
                let mut s = T::zero_in(&ctx);
                for j in 0..=k {
                    s.mul_add_assign(&self.c[j], &r.c[k - j]);
                }
                s
            })
            .collect();
        Taylor { c }
    }
}
impl<T: Field> Div<&Taylor<T>> for Taylor<T> {
    type Output = Taylor<T>;
    /// q = u/v from u = q v: q_k = (u_k − Σ_{j≥1} v_j q_{k−j}) / v₀.
    fn div(self, r: &Taylor<T>) -> Self {
        if r.c.len() == 1 {
            let inv = T::one_in(&r.c[0].ctx()) / &r.c[0];
            return self.scale(&inv);
        }
        let n = self.combined_len(r);
        let mut q: Vec<T> = Vec::with_capacity(n);
        for k in 0..n {
            let mut s = self.at(k);
            for j in 1..=k {
                s.mul_sub_assign(&r.c[j], &q[k - j]);
            }
            q.push(s / &r.c[0]);
        }
        Taylor { c: q }
    }
}

macro_rules! forward_ops {
    ($($op:ident $method:ident $assign:ident $assign_method:ident),*) => {$(
        impl<T: Field> $op<Taylor<T>> for Taylor<T> {
            type Output = Taylor<T>;
            fn $method(self, r: Taylor<T>) -> Self {
                $op::<&Taylor<T>>::$method(self, &r)
            }
        }
        impl<T: Field> $assign<&Taylor<T>> for Taylor<T> {
            fn $assign_method(&mut self, r: &Taylor<T>) {
                *self = $op::<&Taylor<T>>::$method(self.clone(), r);
            }
        }
    )*};
}
forward_ops!(Add add AddAssign add_assign, Sub sub SubAssign sub_assign, Mul mul MulAssign mul_assign, Div div DivAssign div_assign);

impl<T: Field> Field for Taylor<T> {
    type Ctx = T::Ctx;

    fn ctx(&self) -> T::Ctx {
        self.c[0].ctx()
    }
    fn scalar_name(ctx: &T::Ctx) -> String {
        format!("taylor<{}>", T::scalar_name(ctx))
    }
    fn from_i64(v: i64, ctx: &T::Ctx) -> Self {
        Taylor::constant(T::from_i64(v, ctx))
    }
    fn from_ratio(n: i64, d: i64, ctx: &T::Ctx) -> Self {
        Taylor::constant(T::from_ratio(n, d, ctx))
    }
    fn from_rational(q: &BigRational, ctx: &T::Ctx) -> Self {
        Taylor::constant(T::from_rational(q, ctx))
    }
    fn from_f64(v: f64, ctx: &T::Ctx) -> Self {
        Taylor::constant(T::from_f64(v, ctx))
    }
    fn abs(&self) -> Self {
        if self.c[0] < T::zero_in(&self.ctx()) {
            -self.clone()
        } else {
            self.clone()
        }
    }
    fn is_zero(&self) -> bool {
        self.c.iter().all(|x| x.is_zero())
    }
    fn is_finite(&self) -> bool {
        self.c.iter().all(|x| x.is_finite())
    }
    fn to_f64(&self) -> f64 {
        self.c[0].to_f64()
    }
    fn to_rational(&self) -> Option<BigRational> {
        self.c[0].to_rational()
    }
    fn to_plain_string(&self) -> String {
        let parts: Vec<String> = self.c.iter().map(|x| x.to_plain_string()).collect();
        format!("[{}]", parts.join(", "))
    }
}

impl<T: Real> Real for Taylor<T> {
    /// r = √u from r² = u: r_k = (u_k − Σ_{j=1}^{k−1} r_j r_{k−j}) / (2 r₀).
    fn sqrt(&self) -> Self {
        let ctx = self.ctx();
        let n = self.c.len();
        let mut r = vec![self.c[0].sqrt()];
        let two_r0 = r[0].clone() * &T::from_i64(2, &ctx);
        for k in 1..n {
            let mut s = self.c[k].clone();
            for j in 1..k {
                s.mul_sub_assign(&r[j], &r[k - j]);
            }
            r.push(s / &two_r0);
        }
        Taylor { c: r }
    }
    fn sin_cos(&self) -> (Self, Self) {
        self.sin_cos_series()
    }
    /// θ′ = (x y′ − y x′)/(x² + y²), θ₀ = atan2(y₀, x₀).
    fn atan2(&self, x: &Self) -> Self {
        let n = self.combined_len(x);
        let (y, x) = (self.clone().with_len(n), x.clone().with_len(n));
        let num = x.clone() * &y.derivative_series() - &(y.clone() * &x.derivative_series());
        let den = x.clone() * &x + &(y.clone() * &y);
        let d = num / &den;
        Taylor::integrate(&d, y.c[0].atan2(&x.c[0]), n)
    }
    /// e′ = u′ e.
    fn exp(&self) -> Self {
        let ctx = self.ctx();
        let n = self.c.len();
        let du = self.derivative_series().padded(n - 1);
        let mut e = vec![self.c[0].exp()];
        for k in 1..n {
            let mut s = T::zero_in(&ctx);
            for j in 1..=k {
                s.mul_add_assign(&du[j - 1], &e[k - j]);
            }
            e.push(s / &T::from_i64(k as i64, &ctx));
        }
        Taylor { c: e }
    }
    /// (ln u)′ = u′/u.
    fn ln(&self) -> Self {
        let n = self.c.len();
        let d = self.derivative_series() / self;
        Taylor::integrate(&d, self.c[0].ln(), n)
    }
    fn pi(ctx: &T::Ctx) -> Self {
        Taylor::constant(T::pi(ctx))
    }
    fn epsilon(ctx: &T::Ctx) -> Self {
        Taylor::constant(T::epsilon(ctx))
    }
    fn precision_bits(ctx: &T::Ctx) -> u32 {
        T::precision_bits(ctx)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn derivatives_of_elementary_functions_at_a_point() {
        let t = Taylor::variable(0.3f64, 4);
        let close = |a: &[f64], b: &[f64]| {
            a.iter()
                .zip(b)
                .all(|(x, y)| (x - y).abs() < 1e-12 * (1.0 + y.abs()))
        };
        let (s, c) = t.sin_cos();
        let (s0, c0) = 0.3f64.sin_cos();
        assert!(close(&s.derivatives(), &[s0, c0, -s0, -c0, s0]));
        assert!(close(&c.derivatives(), &[c0, -s0, -c0, s0, c0]));
        let e = t.exp();
        assert!(close(&e.derivatives(), &[0.3f64.exp(); 5]));
        // ln t: 1/t, −1/t², 2/t³, −6/t⁴
        let l = t.ln().derivatives();
        let x: f64 = 0.3;
        assert!(close(
            &l,
            &[
                x.ln(),
                1.0 / x,
                -1.0 / x.powi(2),
                2.0 / x.powi(3),
                -6.0 / x.powi(4)
            ]
        ));
        // sqrt via r² = t
        let r = t.sqrt();
        let back = (r.clone() * &r).derivatives();
        assert!(close(&back, &[x, 1.0, 0.0, 0.0, 0.0]));
        // atan(t) = atan2(t, 1): 1/(1+t²), −2t/(1+t²)²
        let a = t.atan2(&Taylor::constant(1.0)).derivatives();
        let d = 1.0 + x * x;
        assert!(close(&a[..3], &[x.atan(), 1.0 / d, -2.0 * x / (d * d)]));
        // quotient: t/(1+t) = 1 − 1/(1+t): derivatives 1/(1+t)², −2/(1+t)³
        let q = (t.clone() / &(t.clone() + &Taylor::constant(1.0))).derivatives();
        assert!(close(
            &q[..3],
            &[
                x / (1.0 + x),
                1.0 / (1.0 + x).powi(2),
                -2.0 / (1.0 + x).powi(3)
            ]
        ));
    }
}
