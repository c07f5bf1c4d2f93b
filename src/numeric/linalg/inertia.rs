//! Proven eigenvalue brackets of a symmetric matrix by Sylvester's law of inertia.
//!
//! For symmetric A and a shift x, the LDLᵀ factorisation of A − xI (without pivoting, when no
//! pivot vanishes) has as many negative pivots as A has eigenvalues below x. In exact
//! arithmetic that count is a proof: λ_k (0-based, ascending) lies in [lo, hi) exactly when
//! fewer than k + 1 eigenvalues are below lo and at least k + 1 are below hi. An estimate
//! from floating point only chooses where to look; the bracket is decided exactly.

use super::{ldl_pivots, Matrix};
use crate::scalar::Field;

/// The number of eigenvalues of the symmetric `a` below `shift`; `None` when a zero pivot
/// stops the factorisation of a − shift·I (then a nearby shift decides), or `a` is not square.
pub fn eigenvalues_below<T: Field>(a: &Matrix<T>, shift: &T) -> Option<usize> {
    if !a.is_square() {
        return None;
    }
    let n = a.rows();
    let shifted = Matrix::from_fn(n, n, |i, j| {
        if i == j {
            a[(i, j)].clone() - shift
        } else {
            a[(i, j)].clone()
        }
    });
    let zero = T::zero_in(&shift.ctx());
    ldl_pivots(&shifted).map(|d| d.iter().filter(|p| **p < zero).count())
}

/// A symmetric matrix of exact rationals scaled to integers (GMP), for fast exact inertia:
/// the rational matrix is `entries / scale`.
pub struct IntegerSymmetric {
    entries: Vec<Vec<rug::Integer>>,
    scale: rug::Integer,
}

impl IntegerSymmetric {
    /// The matrix `a` (exact rationals) as integers over their common denominator; `None`
    /// for a matrix that is not square.
    pub fn new(a: &Matrix<crate::scalar::BigRational>) -> Option<Self> {
        if !a.is_square() {
            return None;
        }
        let n = a.rows();
        Self::from_gmp(
            (0..n)
                .map(|i| {
                    (0..n)
                        .map(|j| crate::scalar::mpfr_rational(&a[(i, j)]))
                        .collect()
                })
                .collect(),
        )
    }

    /// The Gram matrix BᵀB of the exact rational `b`, formed in GMP (much faster than
    /// `num-rational` for the wide entries of graded matrices); `None` never for a matrix
    /// with at least one row.
    pub fn gram(b: &Matrix<rug::Rational>) -> Option<Self> {
        let (rows, cols) = (b.rows(), b.cols());
        let gram = (0..cols)
            .map(|i| {
                (0..cols)
                    .map(|j| {
                        (0..rows).fold(rug::Rational::new(), |sum, r| {
                            sum + rug::Rational::from(&b[(r, i)] * &b[(r, j)])
                        })
                    })
                    .collect()
            })
            .collect();
        Self::from_gmp(gram)
    }

    /// Square GMP rationals as integers over their common denominator.
    fn from_gmp(gmp: Vec<Vec<rug::Rational>>) -> Option<Self> {
        if gmp.iter().any(|row| row.len() != gmp.len()) {
            return None;
        }
        let scale = gmp
            .iter()
            .flatten()
            .fold(rug::Integer::from(1), |l, q| l.lcm(q.denom()));
        let entries = gmp
            .iter()
            .map(|row| {
                row.iter()
                    .map(|q| (q.numer().clone() * &scale) / q.denom())
                    .collect()
            })
            .collect();
        Some(IntegerSymmetric { entries, scale })
    }

    /// The number of eigenvalues below the rational `shift`: the sign changes along the
    /// leading principal minors of scale·q·(A − shift·I) = q·entries − scale·p·I (shift = p/q),
    /// by fraction-free (Bareiss) elimination, whose divisions are exact. `None` when a minor
    /// vanishes.
    pub fn eigenvalues_below(&self, shift: &rug::Rational) -> Option<usize> {
        let n = self.entries.len();
        let diagonal = rug::Integer::from(&self.scale * shift.numer());
        let mut m: Vec<Vec<rug::Integer>> = self
            .entries
            .iter()
            .enumerate()
            .map(|(i, row)| {
                row.iter()
                    .enumerate()
                    .map(|(j, x)| {
                        let v = rug::Integer::from(x * shift.denom());
                        if i == j {
                            v - &diagonal
                        } else {
                            v
                        }
                    })
                    .collect()
            })
            .collect();
        let mut previous = rug::Integer::from(1);
        let mut negative = 0usize;
        for k in 0..n {
            crate::cancel::checkpoint();
            let pivot = m[k][k].clone();
            if pivot == 0 {
                return None;
            }
            // The pivot is the leading minor Δ_(k+1); d_k = Δ_(k+1)/Δ_k is negative when the
            // two differ in sign.
            if (pivot < 0) != (previous < 0) {
                negative += 1;
            }
            for i in k + 1..n {
                for j in k + 1..n {
                    let value = rug::Integer::from(&m[i][j] * &pivot)
                        - rug::Integer::from(&m[i][k] * &m[k][j]);
                    m[i][j] = value.div_exact(&previous);
                }
            }
            previous = pivot;
        }
        Some(negative)
    }

    /// A proven bracket lo ≤ λ_k < hi around `estimate` (relative half-width `relative`,
    /// doubled up to `tries` times), the shifts rounded to 64-bit dyadic rationals.
    pub fn bracket(
        &self,
        k: usize,
        estimate: &rug::Float,
        relative: f64,
        tries: usize,
    ) -> Option<(rug::Rational, rug::Rational)> {
        let mut width = relative;
        for _ in 0..tries {
            // estimate·(1 ± width), exactly enough for any width (64 bits beyond the estimate's).
            let prec = estimate.prec().max(64) + 64;
            let shift = |sign: f64| -> Option<rug::Rational> {
                let factor =
                    rug::Float::with_val(prec, 1) + rug::Float::with_val(prec, sign * width);
                rug::Float::with_val(prec, estimate * factor).to_rational()
            };
            let (lo, hi) = (shift(-1.0)?, shift(1.0)?);
            if let (Some(below_lo), Some(below_hi)) =
                (self.eigenvalues_below(&lo), self.eigenvalues_below(&hi))
            {
                if below_lo <= k && below_hi > k {
                    return Some((lo, hi));
                }
            }
            width *= 2.0;
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::BigRational;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    #[test]
    fn brackets_are_decided_exactly() {
        // diag(1, 4, 9) turned by an exact rotation (3/5, 4/5): eigenvalues 1, 4, 9.
        let (c, s) = (q(3, 5), q(4, 5));
        let r = Matrix::from_rows(vec![
            vec![c.clone(), -s.clone(), q(0, 1)],
            vec![s.clone(), c.clone(), q(0, 1)],
            vec![q(0, 1), q(0, 1), q(1, 1)],
        ]);
        let d = Matrix::from_rows(vec![
            vec![q(1, 1), q(0, 1), q(0, 1)],
            vec![q(0, 1), q(4, 1), q(0, 1)],
            vec![q(0, 1), q(0, 1), q(9, 1)],
        ]);
        let a = r.mul(&d).mul(&r.transpose());
        assert_eq!(eigenvalues_below(&a, &q(5, 1)), Some(2));
        let fast = IntegerSymmetric::new(&a).unwrap();
        let estimate = |x: f64| rug::Float::with_val(64, x);
        let contains = |(lo, hi): (rug::Rational, rug::Rational), v: i32| lo <= v && v < hi;
        assert!(contains(
            fast.bracket(1, &estimate(4.1), 0.01, 10).unwrap(),
            4
        ));
        // A wrong estimate is widened until it brackets, never accepted as it is.
        assert!(contains(
            fast.bracket(0, &estimate(1.5), 0.01, 20).unwrap(),
            1
        ));
        assert!(fast.bracket(0, &estimate(1.5), 0.01, 3).is_none());
        // The integer (Bareiss) count agrees with the rational LDLᵀ one at every shift.
        for (n, d) in [(1, 2), (3, 2), (5, 1), (17, 2), (10, 1)] {
            let shift = rug::Rational::from((n, d));
            assert_eq!(
                fast.eigenvalues_below(&shift),
                eigenvalues_below(&a, &q(n, d)),
                "{n}/{d}"
            );
        }
    }

    #[test]
    fn gram_in_gmp_counts_as_the_rational_gram() {
        let b = Matrix::from_fn(3, 3, |i, j| q((i * 3 + j) as i64 % 5 - 2, 1 + j as i64));
        let slow = IntegerSymmetric::new(&b.transpose().mul(&b)).unwrap();
        let fast = IntegerSymmetric::gram(&b.map(crate::scalar::mpfr_rational)).unwrap();
        for (n, d) in [(1, 3), (1, 2), (2, 1), (9, 2), (25, 1)] {
            let shift = rug::Rational::from((n, d));
            assert_eq!(
                fast.eigenvalues_below(&shift),
                slow.eigenvalues_below(&shift)
            );
        }
    }
}
