//! Dense linear algebra written once over [`Field`] / [`Real`](crate::scalar::Real).
//!
//! - [`Matrix`]: a row-major dense matrix with products and transposes.
//! - [`gauss`]: Gaussian elimination with partial pivoting: `solve`, `inverse`, `determinant`.
//!   Exact in rationals (any non-zero pivot is exact; the largest one is chosen anyway so
//!   the same code is the backward-stable choice in floating point).
//! - [`banded`]: banded and cyclic banded elimination, O(n) for the systems of spline fits.
//! - [`svd`]: singular values by one-sided Jacobi at any precision.
//! - [`inertia`]: proven eigenvalue brackets of symmetric matrices (Sylvester's law of inertia).
//! - [`reference`](mod@reference): the same quantities in f64 through nalgebra, the reference our generic
//!   routines are tested against and the "what f64 gives" column of every report.
//!
//! nalgebra's decompositions need `ComplexField`, which neither `rug::Float` nor
//! `BigRational` implement, hence these short generic routines (`docs/design.md`, "The library").

pub mod banded;
pub mod gauss;
pub mod inertia;
pub mod reference;
pub mod svd;

use crate::scalar::Field;
use std::ops::{Index, IndexMut};

pub use gauss::{determinant, inverse, ldl_pivots, solve, LinalgError};
pub use svd::{condition_number, singular_values};

/// A dense `rows × cols` matrix stored row by row.
#[derive(Clone, Debug, PartialEq)]
pub struct Matrix<T> {
    rows: usize,
    cols: usize,
    data: Vec<T>,
}

impl<T: Field> Matrix<T> {
    /// The zero matrix.
    pub fn zeros(rows: usize, cols: usize, ctx: &T::Ctx) -> Self {
        Matrix {
            rows,
            cols,
            data: vec![T::zero_in(ctx); rows * cols],
        }
    }

    /// The identity of order `n`.
    pub fn identity(n: usize, ctx: &T::Ctx) -> Self {
        let mut m = Self::zeros(n, n, ctx);
        for i in 0..n {
            m[(i, i)] = T::one_in(ctx);
        }
        m
    }

    /// A matrix from its rows, which must all have the same length.
    ///
    /// # Panics
    /// For rows of different lengths. Shapes are the calling program's logic, not data, so
    /// `Matrix` treats a mismatch as nalgebra and ndarray do: the solvers ([`solve`],
    /// [`inverse`], [`banded`]) check shapes and return [`LinalgError`], the building blocks
    /// (`from_rows`, `mul`, `mul_vec`, indexing) panic.
    pub fn from_rows(rows: Vec<Vec<T>>) -> Self {
        let cols = rows.first().map_or(0, Vec::len);
        assert!(
            rows.iter().all(|r| r.len() == cols),
            "rows of different lengths"
        );
        let n = rows.len();
        Matrix {
            rows: n,
            cols,
            data: rows.into_iter().flatten().collect(),
        }
    }

    /// The matrix with entry (i, j) = f(i, j).
    pub fn from_fn(rows: usize, cols: usize, mut f: impl FnMut(usize, usize) -> T) -> Self {
        let data = (0..rows * cols).map(|k| f(k / cols, k % cols)).collect();
        Matrix { rows, cols, data }
    }

    /// The number of rows.
    pub fn rows(&self) -> usize {
        self.rows
    }
    /// The number of columns.
    pub fn cols(&self) -> usize {
        self.cols
    }
    /// Whether rows = columns.
    pub fn is_square(&self) -> bool {
        self.rows == self.cols
    }

    /// Row `i` as a slice.
    pub fn row(&self, i: usize) -> &[T] {
        &self.data[i * self.cols..(i + 1) * self.cols]
    }

    /// The entries in row order.
    pub fn entries(&self) -> &[T] {
        &self.data
    }

    /// The transpose.
    pub fn transpose(&self) -> Self {
        Self::from_fn(self.cols, self.rows, |i, j| self[(j, i)].clone())
    }

    /// The product `self · other`.
    ///
    /// # Panics
    /// If the inner dimensions differ or `self` has no entry (see [`Matrix::from_rows`]).
    pub fn mul(&self, other: &Matrix<T>) -> Matrix<T> {
        assert_eq!(self.cols, other.rows, "inner dimensions differ");
        let ctx = self.data[0].ctx();
        Self::from_fn(self.rows, other.cols, |i, j| {
            let mut acc = T::zero_in(&ctx);
            for k in 0..self.cols {
                acc.mul_add_assign(&self[(i, k)], &other[(k, j)]);
            }
            acc
        })
    }

    /// The product `self · x`.
    ///
    /// # Panics
    /// If the lengths differ or are zero (see [`Matrix::from_rows`]).
    pub fn mul_vec(&self, x: &[T]) -> Vec<T> {
        assert_eq!(
            self.cols,
            x.len(),
            "vector length differs from the column count"
        );
        (0..self.rows)
            .map(|i| {
                let mut acc = T::zero_in(&x[0].ctx());
                for (a, b) in self.row(i).iter().zip(x) {
                    acc.mul_add_assign(a, b);
                }
                acc
            })
            .collect()
    }

    /// Apply `f` to every entry (for example to change the number type).
    pub fn map<U>(&self, f: impl FnMut(&T) -> U) -> Matrix<U> {
        Matrix {
            rows: self.rows,
            cols: self.cols,
            data: self.data.iter().map(f).collect(),
        }
    }
}

impl<T> Index<(usize, usize)> for Matrix<T> {
    type Output = T;
    fn index(&self, (i, j): (usize, usize)) -> &T {
        assert!(i < self.rows && j < self.cols, "index out of range");
        &self.data[i * self.cols + j]
    }
}

impl<T> IndexMut<(usize, usize)> for Matrix<T> {
    fn index_mut(&mut self, (i, j): (usize, usize)) -> &mut T {
        assert!(i < self.rows && j < self.cols, "index out of range");
        &mut self.data[i * self.cols + j]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::BigRational;

    #[test]
    fn products_and_transpose() {
        let a = Matrix::from_rows(vec![vec![1.0, 2.0], vec![3.0, 4.0], vec![5.0, 6.0]]);
        let at = a.transpose();
        assert_eq!(at.rows(), 2);
        let ata = at.mul(&a);
        assert_eq!(
            ata,
            Matrix::from_rows(vec![vec![35.0, 44.0], vec![44.0, 56.0]])
        );
        assert_eq!(a.mul_vec(&[1.0, -1.0]), vec![-1.0, -1.0, -1.0]);
        let id = Matrix::<BigRational>::identity(3, &());
        assert_eq!(id.mul(&id), id);
    }
}
