//! Krawczyk's test: a proof that F(x) = 0 has exactly one solution in a box, and a ball
//! around it.
//!
//! For an approximate zero x̃ (exact MPFR numbers, from Newton's method), a matrix Y close to
//! J(x̃)⁻¹ and a box X ∋ x̃, the Krawczyk operator
//!
//!   K(X) = x̃ − Y·F(x̃) + (I − Y·J(X))·(X − x̃)
//!
//! evaluated in ball arithmetic, with J(X) an enclosure of the Jacobian over the whole box,
//! satisfies: if K(X) lies in the interior of X, then F has exactly one zero in X, and it lies
//! in K(X) (Krawczyk 1969; Moore's form of the theorem; Rump, *Verification methods*, Acta
//! Numerica 2010, Thm. 13.1). Any Y works; a good one makes ‖I − Y·J(X)‖ small so the test
//! succeeds. The box starts as x̃ ± 2|Y·F(x̃)| plus a few units of the precision and is
//! inflated ("ε-inflation") up to [`MAX_ATTEMPTS`] times; failing that, nothing is proven
//! and the caller says so.
//!
//! Used to prove Marin's optimal knots (paper 004: the stationary point of G on the simplex,
//! `algo::param::proven`).
//!
//! ```
//! use trajverify::numeric::krawczyk::krawczyk;
//! use trajverify::numeric::linalg::Matrix;
//! use trajverify::scalar::ball::Ball;
//! use trajverify::scalar::{Field, Float, Real};
//!
//! // x² − 2 = 0: √2 proven in a ball at 128 bits, from an approximation good to 1e-8 (the
//! // ball is about as wide as the approximation's error squared) and from MPFR's √2.
//! let bits = 128;
//! let f = |x: &[Ball]| Some(vec![x[0].clone() * &x[0] - &Ball::from_i64(2, &bits)]);
//! let j = |x: &[Ball]| Some(Matrix::from_rows(vec![vec![x[0].clone() * &Ball::from_i64(2, &bits)]]));
//! let sqrt2 = Ball::from_i64(2, &bits).sqrt();
//! let rough = krawczyk(&[Float::with_val(bits, 1.41421356)], f, j).unwrap();
//! assert!(rough[0].contains(sqrt2.mid()));
//! assert!(rough[0].rad() < 1e-14);
//! let close = krawczyk(&[Float::with_val(bits, 2).sqrt()], f, j).unwrap();
//! assert!(close[0].contains(sqrt2.mid()));
//! assert!(close[0].rad() < 1e-35);
//! ```

use super::linalg::{inverse, Matrix};
use crate::scalar::ball::Ball;
use crate::scalar::{Field, Float};

/// How many times the box is inflated before the test gives up.
pub const MAX_ATTEMPTS: usize = 8;

/// Why no zero was proven.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum KrawczykError {
    /// F or J has no finite enclosure at the approximation or over a box.
    #[error("F or its Jacobian has no finite enclosure near the approximation")]
    NotFinite,
    /// J(x̃) is singular at the working precision: no preconditioner.
    #[error("the Jacobian at the approximation is singular")]
    Singular,
    /// K(X) never fell inside X: the approximation is not close enough to a simple zero, or
    /// the precision is too low.
    #[error("the Krawczyk operator did not contract in {0} attempts")]
    NotContracting(usize),
    /// F, J and x̃ disagree in size, or x̃ is empty.
    #[error("F, its Jacobian and the approximation disagree in size")]
    Shape,
}

/// The ball enclosing the unique zero of F near `approx` (see the module doc). `f(x)` and
/// `jacobian(x)` evaluate F and J on balls (over every point of them), `None` where they are
/// not defined; the precision is that of `approx`.
///
/// # Errors
/// [`KrawczykError`]: nothing proven (the zero may still exist; the test could not show it).
pub fn krawczyk(
    approx: &[Float],
    f: impl Fn(&[Ball]) -> Option<Vec<Ball>>,
    jacobian: impl Fn(&[Ball]) -> Option<Matrix<Ball>>,
) -> Result<Vec<Ball>, KrawczykError> {
    let n = approx.len();
    let Some(bits) = approx.iter().map(Float::prec).max() else {
        return Err(KrawczykError::Shape);
    };
    let center: Vec<Ball> = approx.iter().cloned().map(Ball::exact).collect();
    let fx = f(&center).ok_or(KrawczykError::NotFinite)?;
    let j_center = jacobian(&center).ok_or(KrawczykError::NotFinite)?;
    if fx.len() != n || j_center.rows() != n || j_center.cols() != n {
        return Err(KrawczykError::Shape);
    }
    if !fx.iter().all(Field::is_finite) {
        return Err(KrawczykError::NotFinite);
    }
    // Y ≈ J(x̃)⁻¹ from the midpoints, used as exact numbers.
    let y = inverse(&j_center.map(|b| b.mid().clone())).map_err(|_| KrawczykError::Singular)?;
    let y = y.map(|v| Ball::exact(v.clone()));
    let step = y.mul_vec(&fx); // Y·F(x̃)
    let base: Vec<Ball> = center
        .iter()
        .zip(&step)
        .map(|(c, s)| c.clone() - s)
        .collect();
    // Initial radii: twice the Newton step, plus a few units of the precision.
    let unit = 2f64.powi(8 - bits.min(1000) as i32);
    let mut radius: Vec<f64> = step
        .iter()
        .zip(approx)
        .map(|(s, x)| 2.0 * s.abs_upper() + unit * (x.to_f64().abs() + f64::MIN_POSITIVE))
        .collect();
    let identity = Matrix::identity(n, &bits);
    for _ in 0..MAX_ATTEMPTS {
        let boxes: Vec<Ball> = approx
            .iter()
            .zip(&radius)
            .map(|(x, r)| Ball::new(x.clone(), *r))
            .collect();
        let jx = jacobian(&boxes).ok_or(KrawczykError::NotFinite)?;
        let contraction = subtract(&identity, &y.mul(&jx));
        let offsets: Vec<Ball> = radius
            .iter()
            .map(|r| Ball::new(Float::with_val(bits, 0), *r))
            .collect();
        let k: Vec<Ball> = base
            .iter()
            .zip(contraction.mul_vec(&offsets))
            .map(|(b, m)| b.clone() + &m)
            .collect();
        if !k.iter().all(Field::is_finite) {
            return Err(KrawczykError::NotFinite);
        }
        if k.iter().zip(&boxes).all(|(ki, xi)| inside(ki, xi)) {
            return Ok(k);
        }
        // ε-inflation: the next box covers K(X) with room to spare.
        for ((r, ki), x) in radius.iter_mut().zip(&k).zip(approx) {
            let reach = distance_upper(ki, x);
            *r = (2.0 * *r).max(1.5 * reach);
        }
    }
    Err(KrawczykError::NotContracting(MAX_ATTEMPTS))
}

/// a − b, entrywise.
fn subtract(a: &Matrix<Ball>, b: &Matrix<Ball>) -> Matrix<Ball> {
    let mut out = a.clone();
    for i in 0..a.rows() {
        for j in 0..a.cols() {
            out[(i, j)] = a[(i, j)].clone() - &b[(i, j)];
        }
    }
    out
}

/// Whether the ball `k` lies strictly inside the ball `x`.
fn inside(k: &Ball, x: &Ball) -> bool {
    k.lower() > x.lower() && k.upper() < x.upper()
}

/// An upper bound of the distance from x to the farthest point of k, as a double.
fn distance_upper(k: &Ball, x: &Float) -> f64 {
    let centre = Ball::exact(x.clone());
    (k.clone() - &centre).abs_upper()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::Real;

    #[test]
    fn proves_a_two_dimensional_zero_and_refuses_a_bad_start() {
        let bits = 192;
        // x² + y² = 4, x·y = 1: a zero near (1.93, 0.52).
        let f = |v: &[Ball]| {
            Some(vec![
                v[0].clone() * &v[0] + &(v[1].clone() * &v[1]) - &Ball::from_i64(4, &bits),
                v[0].clone() * &v[1] - &Ball::one_in(&bits),
            ])
        };
        let j = |v: &[Ball]| {
            let two = Ball::from_i64(2, &bits);
            Some(Matrix::from_rows(vec![
                vec![two.clone() * &v[0], two * &v[1]],
                vec![v[1].clone(), v[0].clone()],
            ]))
        };
        // Newton's approximation at 192 bits.
        let mut x = [Float::with_val(bits, 1.9), Float::with_val(bits, 0.5)];
        for _ in 0..12 {
            let b: Vec<Ball> = x.iter().cloned().map(Ball::exact).collect();
            let (fx, jx) = (f(&b).unwrap(), j(&b).unwrap());
            let jm = jx.map(|e| e.mid().clone());
            let step =
                crate::numeric::linalg::solve(&jm, &[fx[0].mid().clone(), fx[1].mid().clone()])
                    .unwrap();
            x = [x[0].clone() - &step[0], x[1].clone() - &step[1]];
        }
        let root = krawczyk(&x, f, j).unwrap();
        // x = √(2 + √3): the exact value lies in the ball.
        let exact = (Ball::from_i64(2, &bits) + &Ball::from_i64(3, &bits).sqrt()).sqrt();
        assert!(root[0].contains(exact.mid()), "{root:?}");
        assert!(root[0].rad() < 1e-50, "{root:?}");
        // A start far from any zero proves nothing.
        let far = [Float::with_val(bits, 5.0), Float::with_val(bits, -3.0)];
        assert!(krawczyk(&far, f, j).is_err());
    }
}
