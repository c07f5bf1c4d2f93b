//! Quaternions over any [`Field`], and the two quaternion equations of PH interpolation.
//!
//! A = a + a_x i + a_y j + a_z k with Hamilton's product (paper 001, Sec. 4A, Eq. 3). The
//! commutative product of Definition 1 (Eq. 4),
//!
//! A ⋆ B = ½ (A i B* + B i A*) = vec(A i B*),
//!
//! is a symmetric bilinear map to pure quaternions; A ⋆ A = A i A* is the hodograph of a
//! spatial PH curve (Eq. 9). [`solve_linear`] is Lemma 1 (X ⋆ B = a, Eq. 5b) and
//! [`solve_quadratic`] Lemma 2 (X ⋆ X = a, Eq. 6b).
//!
//! Everything except Lemma 2 and the norm needs only field operations, so products and
//! Lemma 1 run exactly in rationals; Lemma 2 needs a square root ([`Real`]).

use crate::scalar::{Field, Real};
use std::ops::{Add, Mul, Neg, Sub};

/// w + x i + y j + z k.
#[derive(Clone, Debug, PartialEq)]
pub struct Quat<T> {
    /// The real part.
    pub w: T,
    /// The i component.
    pub x: T,
    /// The j component.
    pub y: T,
    /// The k component.
    pub z: T,
}

impl<T: Field> Quat<T> {
    /// w + xi + yj + zk.
    pub fn new(w: T, x: T, y: T, z: T) -> Self {
        Quat { w, x, y, z }
    }
    /// The zero quaternion.
    pub fn zero(ctx: &T::Ctx) -> Self {
        let z = T::zero_in(ctx);
        Quat::new(z.clone(), z.clone(), z.clone(), z)
    }
    /// The pure quaternion v_x i + v_y j + v_z k.
    pub fn pure(v: &[T; 3]) -> Self {
        let z = T::zero_in(&v[0].ctx());
        Quat::new(z, v[0].clone(), v[1].clone(), v[2].clone())
    }
    /// The real number s as a quaternion.
    pub fn scalar(s: T) -> Self {
        let z = T::zero_in(&s.ctx());
        Quat::new(s, z.clone(), z.clone(), z)
    }
    /// The unit i.
    pub fn i(ctx: &T::Ctx) -> Self {
        let (z, o) = (T::zero_in(ctx), T::one_in(ctx));
        Quat::new(z.clone(), o, z.clone(), z)
    }
    /// The context of the components.
    pub fn ctx(&self) -> T::Ctx {
        self.w.ctx()
    }
    /// The vector part (x, y, z).
    pub fn vector(&self) -> [T; 3] {
        [self.x.clone(), self.y.clone(), self.z.clone()]
    }
    /// The components (w, x, y, z).
    pub fn components(&self) -> [T; 4] {
        [
            self.w.clone(),
            self.x.clone(),
            self.y.clone(),
            self.z.clone(),
        ]
    }
    /// From [w, x, y, z].
    pub fn from_components(c: [T; 4]) -> Self {
        let [w, x, y, z] = c;
        Quat::new(w, x, y, z)
    }
    /// A* = w − x i − y j − z k.
    pub fn conj(&self) -> Self {
        Quat::new(
            self.w.clone(),
            -self.x.clone(),
            -self.y.clone(),
            -self.z.clone(),
        )
    }
    /// |A|² = A A*.
    pub fn norm2(&self) -> T {
        let mut s = self.w.clone() * &self.w;
        s.mul_add_assign(&self.x, &self.x);
        s.mul_add_assign(&self.y, &self.y);
        s.mul_add_assign(&self.z, &self.z);
        s
    }
    /// The Euclidean inner product of the components (the real part of A B*).
    pub fn dot(&self, b: &Quat<T>) -> T {
        let mut s = self.w.clone() * &b.w;
        s.mul_add_assign(&self.x, &b.x);
        s.mul_add_assign(&self.y, &b.y);
        s.mul_add_assign(&self.z, &b.z);
        s
    }
    /// The quaternion times a scalar.
    pub fn scale(&self, s: &T) -> Self {
        Quat::new(
            self.w.clone() * s,
            self.x.clone() * s,
            self.y.clone() * s,
            self.z.clone() * s,
        )
    }
    /// self += s·b, component by component (fused in MPFR).
    pub fn add_scaled(&mut self, s: &T, b: &Quat<T>) {
        self.w.mul_add_assign(s, &b.w);
        self.x.mul_add_assign(s, &b.x);
        self.y.mul_add_assign(s, &b.y);
        self.z.mul_add_assign(s, &b.z);
    }
    /// Hamilton's product self · b.
    pub fn mul(&self, b: &Quat<T>) -> Self {
        let (a0, a1, a2, a3) = (&self.w, &self.x, &self.y, &self.z);
        let (b0, b1, b2, b3) = (&b.w, &b.x, &b.y, &b.z);
        let comb = |p: [(&T, &T); 4], s: [bool; 4]| {
            let mut acc = p[0].0.clone() * p[0].1;
            for k in 1..4 {
                if s[k] {
                    acc.mul_add_assign(p[k].0, p[k].1);
                } else {
                    acc.mul_sub_assign(p[k].0, p[k].1);
                }
            }
            acc
        };
        Quat::new(
            comb(
                [(a0, b0), (a1, b1), (a2, b2), (a3, b3)],
                [true, false, false, false],
            ),
            comb(
                [(a0, b1), (a1, b0), (a2, b3), (a3, b2)],
                [true, true, true, false],
            ),
            comb(
                [(a0, b2), (a1, b3), (a2, b0), (a3, b1)],
                [true, false, true, true],
            ),
            comb(
                [(a0, b3), (a1, b2), (a2, b1), (a3, b0)],
                [true, true, false, true],
            ),
        )
    }
    /// A i B* as a full quaternion; its vector part is A ⋆ B and its real part vanishes when A = B.
    pub fn i_conj(&self, b: &Quat<T>) -> Self {
        // A i = (−a_x, a, a_z, −a_y): multiplying by i on the right permutes components.
        let ai = Quat::new(
            -self.x.clone(),
            self.w.clone(),
            self.z.clone(),
            -self.y.clone(),
        );
        ai.mul(&b.conj())
    }
    /// The commutative product A ⋆ B = vec(A i B*) of Definition 1, as a 3-vector.
    ///
    /// Written out (12 products instead of the 16 of a full product, symmetric in A and B):
    /// (a_w b_w + a_x b_x − a_y b_y − a_z b_z, a_w b_z + a_z b_w + a_x b_y + a_y b_x,
    ///  a_x b_z + a_z b_x − a_w b_y − a_y b_w).
    pub fn star(&self, b: &Quat<T>) -> [T; 3] {
        let mut out = [self.w.clone(), self.w.clone(), self.x.clone()];
        self.star_into(b, &mut out);
        out
    }
    /// [`Quat::star`] written into `out`, bit for bit, reusing its storage (a loop of many
    /// products keeps one scratch vector instead of allocating three numbers a product).
    pub fn star_into(&self, b: &Quat<T>, out: &mut [T; 3]) {
        let (a, b) = (self, b);
        let [x, y, z] = out;
        x.assign_mul(&a.w, &b.w);
        x.mul_add_assign(&a.x, &b.x);
        x.mul_sub_assign(&a.y, &b.y);
        x.mul_sub_assign(&a.z, &b.z);
        y.assign_mul(&a.w, &b.z);
        y.mul_add_assign(&a.z, &b.w);
        y.mul_add_assign(&a.x, &b.y);
        y.mul_add_assign(&a.y, &b.x);
        z.assign_mul(&a.x, &b.z);
        z.mul_add_assign(&a.z, &b.x);
        z.mul_sub_assign(&a.w, &b.y);
        z.mul_sub_assign(&a.y, &b.w);
    }
    /// A ⋆ A = A i A*, the Euler–Rodrigues image of i under A (Eq. 9).
    pub fn star_square(&self) -> [T; 3] {
        self.star(self)
    }
    /// Rotate a vector: A v A* (scaled by |A|² when A is not a unit).
    pub fn sandwich(&self, v: &[T; 3]) -> [T; 3] {
        self.mul(&Quat::pure(v)).mul(&self.conj()).vector()
    }
    /// The matrix M with M v = A v A* for every v (Euler–Rodrigues, scaled by |A|²): one
    /// matrix, then 9 products per vector instead of the 32 of two quaternion products when
    /// many vectors turn by the same A.
    pub fn sandwich_matrix(&self) -> [[T; 3]; 3] {
        let (w, x, y, z) = (&self.w, &self.x, &self.y, &self.z);
        let sq = |a: &T| a.clone() * a;
        let (ww, xx, yy, zz) = (sq(w), sq(x), sq(y), sq(z));
        // 2(a b ± c d) for the off-diagonal entries.
        let twice = |a: &T, b: &T, c: &T, d: &T, plus: bool| {
            let mut s = a.clone() * b;
            if plus {
                s.mul_add_assign(c, d);
            } else {
                s.mul_sub_assign(c, d);
            }
            s.clone() + &s
        };
        [
            [
                ww.clone() + &xx - &yy - &zz,
                twice(x, y, w, z, false),
                twice(x, z, w, y, true),
            ],
            [
                twice(x, y, w, z, true),
                ww.clone() - &xx + &yy - &zz,
                twice(y, z, w, x, false),
            ],
            [
                twice(x, z, w, y, false),
                twice(y, z, w, x, true),
                ww - &xx - &yy + &zz,
            ],
        ]
    }
}

/// The unit quaternion Q(φ) = cos φ + i sin φ (Sec. 4A).
pub fn q_phi<T: Real>(phi: &T) -> Quat<T> {
    let (s, c) = phi.sin_cos();
    let z = T::zero_in(&phi.ctx());
    Quat::new(c, s, z.clone(), z)
}

/// Lemma 1 (Eq. 5b): X_τ = −(τ + a) B i / |B|², the solutions of X ⋆ B = a for a pure
/// quaternion a (given as a 3-vector) and B ≠ 0. Returns `None` when B = 0.
pub fn solve_linear<T: Field>(a: &[T; 3], b: &Quat<T>, tau: &T) -> Option<Quat<T>> {
    let n2 = b.norm2();
    if n2.is_zero() {
        return None;
    }
    let lhs = Quat::new(tau.clone(), a[0].clone(), a[1].clone(), a[2].clone());
    let bi = Quat::new(-b.x.clone(), b.w.clone(), b.z.clone(), -b.y.clone());
    let inv = -(T::one_in(&n2.ctx()) / &n2);
    Some(lhs.mul(&bi).scale(&inv))
}

/// Why Lemma 2 has no solution in the form of Eq. (6b).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum QuadraticError {
    /// a = 0: every solution is X = 0 and no frame can be attached.
    Zero,
}

impl std::fmt::Display for QuadraticError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            QuadraticError::Zero => write!(
                f,
                "a = 0 (|a| computed as zero): X ⋆ X = a has no solution with a frame"
            ),
        }
    }
}

impl std::error::Error for QuadraticError {}

/// Lemma 2 (Eq. 6b): X_φ = √|a| (a/|a| + i)/|a/|a| + i| Q(φ), the solutions of X ⋆ X = a.
///
/// When a is a negative multiple of i the formula divides by zero; the solutions are then
/// √|a| j Q(φ) (j i j* = −i), which is what this function returns, so every non-zero a has
/// its one-parameter family.
///
/// # Errors
/// [`QuadraticError::Zero`] when the computed |a| is zero: a = 0, or in floating point an a
/// so small that |a|² underflows.
pub fn solve_quadratic<T: Real>(a: &[T; 3], phi: &T) -> Result<Quat<T>, QuadraticError> {
    let ctx = a[0].ctx();
    let norm = crate::numeric::quat::vec3::norm(a);
    if norm.is_zero() {
        return Err(QuadraticError::Zero);
    }
    // b = |a|(â + i) = (s, a_y, a_z) with s = |a| + a_x, and |b|² = 2|a|s, so
    // X = √|a| b/|b| = b/√(2s). s is formed without cancellation when a_x < 0.
    let s = sum_with_norm(&norm, a);
    let zero = T::zero_in(&ctx);
    let base = if s.is_zero() {
        Quat::new(zero.clone(), zero.clone(), norm.sqrt(), zero)
    } else {
        let scale = T::one_in(&ctx) / &(s.clone() * &T::from_i64(2, &ctx)).sqrt();
        Quat::new(zero, s, a[1].clone(), a[2].clone()).scale(&scale)
    };
    Ok(base.mul(&q_phi(phi)))
}

/// |a| + a_x, computed as (a_y² + a_z²)/(|a| − a_x) when a_x < 0 to avoid cancellation.
///
/// The two forms are equal, so the branch is a rounding choice, not a decision the value
/// rests on: a ball that straddles 0 takes the first form without counting a comparison.
pub fn sum_with_norm<T: Real>(norm: &T, a: &[T; 3]) -> T {
    if a[0].decide_lt(&T::zero_in(&a[0].ctx())) == Some(true) {
        (a[1].clone() * &a[1] + &(a[2].clone() * &a[2])) / &(norm.clone() - &a[0])
    } else {
        norm.clone() + &a[0]
    }
}

/// Operator forms, so quaternion expressions read like the paper's.
impl<T: Field> Add<&Quat<T>> for Quat<T> {
    type Output = Quat<T>;
    fn add(self, r: &Quat<T>) -> Quat<T> {
        Quat::new(self.w + &r.w, self.x + &r.x, self.y + &r.y, self.z + &r.z)
    }
}
impl<T: Field> Sub<&Quat<T>> for Quat<T> {
    type Output = Quat<T>;
    fn sub(self, r: &Quat<T>) -> Quat<T> {
        Quat::new(self.w - &r.w, self.x - &r.x, self.y - &r.y, self.z - &r.z)
    }
}
impl<T: Field> Neg for Quat<T> {
    type Output = Quat<T>;
    fn neg(self) -> Quat<T> {
        Quat::new(-self.w, -self.x, -self.y, -self.z)
    }
}
impl<T: Field> Mul<&Quat<T>> for &Quat<T> {
    type Output = Quat<T>;
    fn mul(self, r: &Quat<T>) -> Quat<T> {
        Quat::mul(self, r)
    }
}

/// Component-wise helpers on 3-vectors used by the PH modules.
pub mod vec3 {
    use crate::scalar::{Field, Real};

    /// a + b.
    pub fn add<T: Field>(a: &[T; 3], b: &[T; 3]) -> [T; 3] {
        [
            a[0].clone() + &b[0],
            a[1].clone() + &b[1],
            a[2].clone() + &b[2],
        ]
    }
    /// a − b.
    pub fn sub<T: Field>(a: &[T; 3], b: &[T; 3]) -> [T; 3] {
        [
            a[0].clone() - &b[0],
            a[1].clone() - &b[1],
            a[2].clone() - &b[2],
        ]
    }
    /// s · a.
    pub fn scale<T: Field>(a: &[T; 3], s: &T) -> [T; 3] {
        [a[0].clone() * s, a[1].clone() * s, a[2].clone() * s]
    }
    /// a += s·b
    pub fn axpy<T: Field>(a: &mut [T; 3], s: &T, b: &[T; 3]) {
        for k in 0..3 {
            a[k].mul_add_assign(s, &b[k]);
        }
    }
    /// a · b.
    pub fn dot<T: Field>(a: &[T; 3], b: &[T; 3]) -> T {
        let mut s = a[0].clone() * &b[0];
        s.mul_add_assign(&a[1], &b[1]);
        s.mul_add_assign(&a[2], &b[2]);
        s
    }
    /// a × b.
    pub fn cross<T: Field>(a: &[T; 3], b: &[T; 3]) -> [T; 3] {
        [
            a[1].clone() * &b[2] - &(a[2].clone() * &b[1]),
            a[2].clone() * &b[0] - &(a[0].clone() * &b[2]),
            a[0].clone() * &b[1] - &(a[1].clone() * &b[0]),
        ]
    }
    /// |a|.
    pub fn norm<T: Real>(a: &[T; 3]) -> T {
        dot(a, a).sqrt()
    }
    /// The zero vector.
    pub fn zero<T: Field>(ctx: &T::Ctx) -> [T; 3] {
        [T::zero_in(ctx), T::zero_in(ctx), T::zero_in(ctx)]
    }
    /// Each component mapped by `f`.
    pub fn map<T: Field, U>(a: &[T; 3], f: impl Fn(&T) -> U) -> [U; 3] {
        [f(&a[0]), f(&a[1]), f(&a[2])]
    }
    /// The matrix–vector product M v.
    pub fn transform<T: Field>(m: &[[T; 3]; 3], v: &[T; 3]) -> [T; 3] {
        [dot(&m[0], v), dot(&m[1], v), dot(&m[2], v)]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::BigRational;

    fn q(w: i64, x: i64, y: i64, z: i64) -> Quat<BigRational> {
        let r = |v: i64| BigRational::from_integer(v.into());
        Quat::new(r(w), r(x), r(y), r(z))
    }

    #[test]
    fn hamilton_rules() {
        let (i, j, k) = (q(0, 1, 0, 0), q(0, 0, 1, 0), q(0, 0, 0, 1));
        assert_eq!(i.mul(&j), k);
        assert_eq!(j.mul(&k), i);
        assert_eq!(k.mul(&i), j);
        assert_eq!(i.mul(&i), q(-1, 0, 0, 0));
        assert_eq!(i.mul(&j).mul(&k), q(-1, 0, 0, 0));
    }

    #[test]
    fn star_is_symmetric_and_matches_definition_1() {
        let a = q(1, 2, -3, 4);
        let b = q(-2, 5, 1, 3);
        let i = q(0, 1, 0, 0);
        let full = a.mul(&i).mul(&b.conj()) + &b.mul(&i).mul(&a.conj());
        let half = BigRational::new(1.into(), 2.into());
        assert_eq!(full.scale(&half), Quat::pure(&a.star(&b)));
        assert_eq!(a.star(&b), b.star(&a));
    }

    #[test]
    fn the_sandwich_matrix_turns_vectors_exactly_as_the_two_products_do() {
        let v = [3, -1, 2].map(|x: i64| BigRational::from_integer(x.into()));
        for a in [q(1, 2, -3, 4), q(0, 0, 1, 0), q(-2, 5, 1, 3)] {
            assert_eq!(vec3::transform(&a.sandwich_matrix(), &v), a.sandwich(&v));
        }
    }

    #[test]
    fn lemma_1_solves_the_linear_equation_exactly() {
        let b = q(1, 2, -3, 4);
        let a = [3, -1, 2].map(|v: i64| BigRational::from_integer(v.into()));
        for tau in [-2, 0, 5] {
            let x = solve_linear(&a, &b, &BigRational::from_integer(tau.into())).unwrap();
            assert_eq!(x.star(&b), a);
        }
    }

    #[test]
    fn lemma_2_solves_the_quadratic_equation() {
        for a in [
            [1.0, 2.0, -3.0],
            [-2.0, 0.0, 0.0],
            [-1.0, 1e-9, 0.0],
            [0.0, 0.0, 1.0],
        ] {
            for phi in [0.0, 0.7, -2.0] {
                let x = solve_quadratic(&a, &phi).unwrap();
                let h = x.star_square();
                for k in 0..3 {
                    assert!((h[k] - a[k]).abs() < 1e-12, "{a:?} {phi} {h:?}");
                }
            }
        }
        assert_eq!(
            solve_quadratic(&[0.0, 0.0, 0.0], &0.0),
            Err(QuadraticError::Zero)
        );
    }
}
