//! Gaussian elimination with partial pivoting over any [`Field`].
//!
//! `solve` and `inverse` reduce `[A | B]` to `[I | A⁻¹B]`; `determinant` is the signed product
//! of the pivots. In rationals all three are exact; in floating point partial pivoting gives
//! the usual backward stability (error of order κ(A)·ε in the solution).

use super::Matrix;
use crate::scalar::Field;

/// Why a linear system could not be solved or built.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum LinalgError {
    /// The matrix has no inverse (in exact arithmetic), or every candidate pivot of some
    /// column was exactly zero in floating point.
    #[error("the matrix is singular (no non-zero pivot in column {column})")]
    Singular {
        /// The column where no pivot was found.
        column: usize,
    },
    /// The matrix is not square, or the right-hand side does not have one row per equation.
    #[error("a {rows}×{cols} system with a right-hand side of {rhs} rows: the matrix must be square and the right-hand side as tall")]
    Shape {
        /// Rows of the matrix.
        rows: usize,
        /// Columns of the matrix.
        cols: usize,
        /// Rows of the right-hand side.
        rhs: usize,
    },
    /// The determinant of a matrix without entries (1) has no context to be made in.
    #[error("the matrix is empty")]
    Empty,
    /// An entry added outside the matrix or, for a [`super::banded::Banded`] matrix,
    /// outside its band.
    #[error("entry ({row}, {col}) lies outside the stored matrix")]
    OutsideBand {
        /// Row of the entry.
        row: usize,
        /// Column of the entry.
        col: usize,
    },
}

/// The shape check of every solver: `a` square and `rhs_rows` tall.
pub(crate) fn check_shape(rows: usize, cols: usize, rhs: usize) -> Result<(), LinalgError> {
    if rows == cols && rhs == rows {
        Ok(())
    } else {
        Err(LinalgError::Shape { rows, cols, rhs })
    }
}

/// Eliminate in place on `a` (n × n) and `b` (n × k); on success `b` holds `A⁻¹B`.
/// Returns the sign of the row permutation times nothing else; pivots are left on the
/// diagonal of `a` (before normalisation) through `pivots`.
fn eliminate<T: Field>(
    a: &mut Matrix<T>,
    b: &mut Matrix<T>,
    pivots: &mut Vec<T>,
) -> Result<bool, LinalgError> {
    let n = a.rows();
    check_shape(n, a.cols(), b.rows())?;
    let mut swapped_odd = false;
    for col in 0..n {
        crate::cancel::checkpoint();
        // Largest magnitude pivot: exactness does not need it, floating point does.
        let mut best = col;
        let mut best_abs = a[(col, col)].abs();
        for r in col + 1..n {
            let v = a[(r, col)].abs();
            // The pivot order is a rounding heuristic, not a decision the result rests on:
            // balls whose magnitudes overlap are ordered by their midpoints, uncounted.
            let larger = best_abs
                .decide_lt(&v)
                .unwrap_or_else(|| v.to_f64() > best_abs.to_f64());
            if larger {
                best = r;
                best_abs = v;
            }
        }
        if best_abs.is_zero() {
            return Err(LinalgError::Singular { column: col });
        }
        if best != col {
            swap_rows(a, best, col);
            swap_rows(b, best, col);
            swapped_odd = !swapped_odd;
        }
        let pivot = a[(col, col)].clone();
        pivots.push(pivot.clone());
        for j in col..n {
            a[(col, j)] /= &pivot;
        }
        for j in 0..b.cols() {
            b[(col, j)] /= &pivot;
        }
        for r in 0..n {
            if r == col || a[(r, col)].is_zero() {
                continue;
            }
            let factor = a[(r, col)].clone();
            for j in col..n {
                let delta = factor.clone() * &a[(col, j)];
                a[(r, j)] -= &delta;
            }
            for j in 0..b.cols() {
                let delta = factor.clone() * &b[(col, j)];
                b[(r, j)] -= &delta;
            }
        }
    }
    Ok(swapped_odd)
}

fn swap_rows<T: Field>(m: &mut Matrix<T>, i: usize, j: usize) {
    for c in 0..m.cols() {
        let tmp = m[(i, c)].clone();
        m[(i, c)] = m[(j, c)].clone();
        m[(j, c)] = tmp;
    }
}

/// The solution x of `A x = b` (empty for a 0 × 0 system).
///
/// # Errors
/// [`LinalgError::Singular`] for the first column in which elimination finds only exactly
/// zero candidate pivots: a singular `a` in exact arithmetic; in floating point only when
/// rounding leaves exact zeros, not for a merely ill-conditioned matrix.
/// [`LinalgError::Shape`] when `a` is not square or `b` is not as long as `a` is tall.
pub fn solve<T: Field>(a: &Matrix<T>, b: &[T]) -> Result<Vec<T>, LinalgError> {
    let mut work = a.clone();
    let mut rhs = Matrix::from_fn(b.len(), 1, |i, _| b[i].clone());
    eliminate(&mut work, &mut rhs, &mut Vec::new())?;
    Ok(rhs.entries().to_vec())
}

/// The inverse `A⁻¹` (the 0 × 0 matrix is its own inverse).
///
/// # Errors
/// [`LinalgError::Singular`] as [`solve`]; [`LinalgError::Shape`] for a matrix that
/// is not square.
pub fn inverse<T: Field>(a: &Matrix<T>) -> Result<Matrix<T>, LinalgError> {
    check_shape(a.rows(), a.cols(), a.rows())?;
    let Some(ctx) = a.entries().first().map(Field::ctx) else {
        return Ok(a.clone());
    };
    let mut work = a.clone();
    let mut rhs = Matrix::identity(a.rows(), &ctx);
    eliminate(&mut work, &mut rhs, &mut Vec::new())?;
    Ok(rhs)
}

/// The determinant (zero for a singular matrix).
///
/// # Errors
/// [`LinalgError::Shape`] for a matrix that is not square, [`LinalgError::Empty`]
/// for the 0 × 0 matrix.
pub fn determinant<T: Field>(a: &Matrix<T>) -> Result<T, LinalgError> {
    check_shape(a.rows(), a.cols(), a.rows())?;
    let Some(ctx) = a.entries().first().map(Field::ctx) else {
        return Err(LinalgError::Empty);
    };
    let mut work = a.clone();
    let mut rhs = Matrix::zeros(a.rows(), 0, &ctx);
    let mut pivots = Vec::new();
    Ok(match eliminate(&mut work, &mut rhs, &mut pivots) {
        Err(_) => T::zero_in(&ctx),
        Ok(odd) => {
            let mut det = T::one_in(&ctx);
            for p in &pivots {
                det *= p;
            }
            if odd {
                -det
            } else {
                det
            }
        }
    })
}

/// The pivots d₁…d_M of the LDLᵀ factorisation of a symmetric matrix (without pivoting).
/// The matrix is positive definite exactly when every pivot is positive; `None` if a zero
/// pivot stops the factorisation, or the matrix is not square.
pub fn ldl_pivots<T: Field>(a: &Matrix<T>) -> Option<Vec<T>> {
    if !a.is_square() {
        return None;
    }
    let n = a.rows();
    let mut work = a.clone();
    let mut pivots = Vec::with_capacity(n);
    for c in 0..n {
        crate::cancel::checkpoint();
        let d = work[(c, c)].clone();
        if d.is_zero() {
            return None;
        }
        for r in c + 1..n {
            let l = work[(r, c)].clone() / &d;
            for j in c + 1..n {
                let delta = l.clone() * &work[(c, j)];
                work[(r, j)] -= &delta;
            }
        }
        pivots.push(d);
    }
    Some(pivots)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::BigRational;

    fn q(n: i64) -> BigRational {
        BigRational::from_integer(n.into())
    }

    fn hilbert(n: usize) -> Matrix<BigRational> {
        Matrix::from_fn(n, n, |i, j| {
            BigRational::new(1.into(), ((i + j + 1) as i64).into())
        })
    }

    #[test]
    fn exact_inverse_of_hilbert_matrix() {
        let h = hilbert(6);
        let inv = inverse(&h).unwrap();
        assert_eq!(h.mul(&inv), Matrix::identity(6, &()));
        // The (0,0) entry of the inverse Hilbert matrix of order n is n².
        assert_eq!(inv[(0, 0)], q(36));
    }

    #[test]
    fn determinant_sign_and_singularity() {
        let a = Matrix::from_rows(vec![vec![q(0), q(1)], vec![q(1), q(0)]]);
        assert_eq!(determinant(&a), Ok(q(-1)));
        let s = Matrix::from_rows(vec![vec![q(1), q(2)], vec![q(2), q(4)]]);
        assert_eq!(determinant(&s), Ok(q(0)));
        assert_eq!(inverse(&s), Err(LinalgError::Singular { column: 1 }));
        // det of the Hilbert matrix of order 3 is 1/2160.
        assert_eq!(
            determinant(&hilbert(3)),
            Ok(BigRational::new(1.into(), 2160.into()))
        );
    }

    #[test]
    fn solve_recovers_known_solution() {
        let a = Matrix::from_rows(vec![
            vec![q(2), q(1), q(1)],
            vec![q(4), q(-6), q(0)],
            vec![q(-2), q(7), q(2)],
        ]);
        let x = vec![q(1), q(-2), q(3)];
        let b = a.mul_vec(&x);
        assert_eq!(solve(&a, &b).unwrap(), x);
    }
}
