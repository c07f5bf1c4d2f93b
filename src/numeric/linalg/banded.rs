//! Banded Gaussian elimination with partial pivoting over any [`Field`], and the cyclic
//! banded systems of periodic splines through the Sherman–Morrison–Woodbury identity.
//!
//! A matrix with `lower` sub- and `upper` superdiagonals is stored row by row in windows of
//! width 2·lower + upper + 1: row i keeps columns i − lower … i + lower + upper. The extra
//! `lower` columns on the right hold the fill of partial pivoting: at step c every row that
//! can be swapped with row c (rows c … c + lower) has its nonzeros in columns
//! c … c + lower + upper, which lie inside both rows' windows (Golub & Van Loan, *Matrix
//! Computations*, 4th ed., §4.3.5, the storage LAPACK's `gbtrf` uses). Work and memory are
//! O(n·lower·(lower + upper)) instead of the dense O(n³) and O(n²), which is what lets a
//! spline through a million samples be fitted at all.
//!
//! A cyclic banded matrix A (a band that wraps around the corners) is written A = B + U Vᵀ
//! with B the band without its corners and one column of U per corner column (Vᵀ picks that
//! column); then x = y − Z (I + Vᵀ Z)⁻¹ Vᵀ y with B y = b and B Z = U (Woodbury), one banded
//! elimination for all right-hand sides and a small dense solve.

use super::{gauss, LinalgError, Matrix};
use crate::scalar::Field;

/// A square banded matrix.
#[derive(Clone, Debug)]
pub struct Banded<T> {
    n: usize,
    lower: usize,
    upper: usize,
    /// Row i, column j is at `i * width + (j + lower − i)`.
    data: Vec<T>,
}

impl<T: Field> Banded<T> {
    /// The n × n zero matrix with `lower` sub- and `upper` superdiagonals.
    pub fn zeros(n: usize, lower: usize, upper: usize, ctx: &T::Ctx) -> Self {
        Banded {
            n,
            lower,
            upper,
            data: vec![T::zero_in(ctx); n * (2 * lower + upper + 1)],
        }
    }

    fn width(&self) -> usize {
        2 * self.lower + self.upper + 1
    }

    /// Whether (i, j) lies in the stored window of row i.
    fn stored(&self, i: usize, j: usize) -> bool {
        j + self.lower >= i && j <= i + self.lower + self.upper && j < self.n
    }

    fn at(&self, i: usize, j: usize) -> usize {
        i * self.width() + (j + self.lower - i)
    }

    /// Whether (i, j) is inside the band (|i − j| within the diagonals).
    pub fn in_band(&self, i: usize, j: usize) -> bool {
        i < self.n && j < self.n && j + self.lower >= i && j <= i + self.upper
    }

    /// Add v to entry (i, j).
    ///
    /// # Errors
    /// [`LinalgError::OutsideBand`] for an entry outside the band (nothing is added).
    pub fn add(&mut self, i: usize, j: usize, v: &T) -> Result<(), LinalgError> {
        if !self.in_band(i, j) {
            return Err(LinalgError::OutsideBand { row: i, col: j });
        }
        let k = self.at(i, j);
        self.data[k] += v;
        Ok(())
    }

    /// Solve A X = B for every column of `rhs` (n × k) by elimination with partial pivoting.
    ///
    /// # Errors
    /// [`LinalgError`] for the first column whose candidate pivots (the diagonal entry and the
    /// `lower` entries below it, after elimination) are all exactly zero; a nearly singular band
    /// is not detected in floating point.
    pub fn solve(mut self, mut rhs: Matrix<T>) -> Result<Matrix<T>, LinalgError> {
        let n = self.n;
        gauss::check_shape(n, n, rhs.rows())?;
        for c in 0..n {
            let last_row = (c + self.lower).min(n - 1);
            let last_col = (c + self.lower + self.upper).min(n - 1);
            let mut best = c;
            let mut best_abs = self.data[self.at(c, c)].abs();
            for r in c + 1..=last_row {
                let v = self.data[self.at(r, c)].abs();
                // A rounding heuristic, as in `gauss`: overlapping balls are ordered by their
                // midpoints, uncounted.
                let larger = best_abs
                    .decide_lt(&v)
                    .unwrap_or_else(|| v.to_f64() > best_abs.to_f64());
                if larger {
                    best = r;
                    best_abs = v;
                }
            }
            if best_abs.is_zero() {
                return Err(LinalgError::Singular { column: c });
            }
            if best != c {
                for j in c..=last_col {
                    let (a, b) = (self.at(c, j), self.at(best, j));
                    self.data.swap(a, b);
                }
                for j in 0..rhs.cols() {
                    let tmp = rhs[(c, j)].clone();
                    rhs[(c, j)] = rhs[(best, j)].clone();
                    rhs[(best, j)] = tmp;
                }
            }
            let pivot = self.data[self.at(c, c)].clone();
            for r in c + 1..=last_row {
                let factor = self.data[self.at(r, c)].clone() / &pivot;
                if factor.is_zero() {
                    continue;
                }
                for j in c..=last_col {
                    let delta = factor.clone() * &self.data[self.at(c, j)];
                    let k = self.at(r, j);
                    self.data[k] -= &delta;
                }
                for j in 0..rhs.cols() {
                    let delta = factor.clone() * &rhs[(c, j)];
                    rhs[(r, j)] -= &delta;
                }
            }
        }
        // Back substitution on the upper triangle (bandwidth lower + upper).
        for c in (0..n).rev() {
            let last_col = (c + self.lower + self.upper).min(n - 1);
            for j in 0..rhs.cols() {
                let mut v = rhs[(c, j)].clone();
                for k in c + 1..=last_col {
                    debug_assert!(self.stored(c, k));
                    let delta = self.data[self.at(c, k)].clone() * &rhs[(k, j)];
                    v -= &delta;
                }
                rhs[(c, j)] = v / &self.data[self.at(c, c)];
            }
        }
        Ok(rhs)
    }
}

/// A cyclic banded system: the band of `Banded` plus entries that wrap around the corners.
#[derive(Clone, Debug)]
pub struct Cyclic<T> {
    band: Banded<T>,
    /// Entries outside the band: (row, column, value).
    corners: Vec<(usize, usize, T)>,
}

impl<T: Field> Cyclic<T> {
    /// The n × n zero matrix whose band has `lower` sub- and `upper` superdiagonals.
    pub fn zeros(n: usize, lower: usize, upper: usize, ctx: &T::Ctx) -> Self {
        Cyclic {
            band: Banded::zeros(n, lower, upper, ctx),
            corners: Vec::new(),
        }
    }

    /// Add v to entry (i, j): into the band when inside it, else as a corner entry.
    ///
    /// # Errors
    /// [`LinalgError::OutsideBand`] for an entry outside the n × n matrix.
    pub fn add(&mut self, i: usize, j: usize, v: &T) -> Result<(), LinalgError> {
        if i >= self.band.n || j >= self.band.n {
            return Err(LinalgError::OutsideBand { row: i, col: j });
        }
        if self.band.in_band(i, j) {
            self.band.add(i, j, v)?;
        } else if !v.is_zero() {
            self.corners.push((i, j, v.clone()));
        }
        Ok(())
    }

    /// Solve A X = B (Woodbury: one banded elimination and a dense solve of the size of the
    /// number of corner columns).
    ///
    /// # Errors
    /// [`LinalgError`] when the elimination of the band B without its corners, or the dense
    /// solve of I + VᵀZ, finds no non-zero pivot in a column (then a column of B or of that small
    /// matrix, not of A): a singular B fails even where A itself is invertible.
    pub fn solve(self, rhs: Matrix<T>) -> Result<Matrix<T>, LinalgError> {
        let n = self.band.n;
        gauss::check_shape(n, n, rhs.rows())?;
        let k = rhs.cols();
        let Some(ctx) = rhs.entries().first().map(Field::ctx) else {
            // No equation, or no right-hand side: nothing to solve.
            return Ok(rhs);
        };
        let mut columns: Vec<usize> = self.corners.iter().map(|c| c.1).collect();
        columns.sort_unstable();
        columns.dedup();
        // [B | U]: the right-hand sides, then one column of U per corner column.
        let m = columns.len();
        let mut stacked = Matrix::zeros(n, k + m, &ctx);
        for i in 0..n {
            for j in 0..k {
                stacked[(i, j)] = rhs[(i, j)].clone();
            }
        }
        for (i, j, v) in &self.corners {
            let slot = columns.binary_search(j).unwrap_or_default();
            stacked[(*i, k + slot)] += v;
        }
        let solved = self.band.solve(stacked)?;
        // Capacitance I + Vᵀ Z, and Vᵀ Y: rows `columns` of the solutions.
        let capacitance = Matrix::from_fn(m, m, |a, b| {
            let z = solved[(columns[a], k + b)].clone();
            if a == b {
                z + &T::one_in(&ctx)
            } else {
                z
            }
        });
        let mut out = Matrix::zeros(n, k, &ctx);
        for j in 0..k {
            let picked: Vec<T> = columns.iter().map(|&c| solved[(c, j)].clone()).collect();
            let w = if m == 0 {
                Vec::new()
            } else {
                gauss::solve(&capacitance, &picked)?
            };
            for i in 0..n {
                let mut v = solved[(i, j)].clone();
                for (b, wb) in w.iter().enumerate() {
                    let delta = solved[(i, k + b)].clone() * wb;
                    v -= &delta;
                }
                out[(i, j)] = v;
            }
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::BigRational;

    fn q(n: i64) -> BigRational {
        BigRational::from_integer(n.into())
    }

    /// A deterministic pseudo-random integer in [−5, 5].
    fn entry(i: usize, j: usize) -> i64 {
        ((i * 7919 + j * 104_729 + 13) % 11) as i64 - 5
    }

    #[test]
    fn banded_and_cyclic_solves_match_dense_gauss_exactly() {
        let n = 12;
        let (lower, upper) = (2, 3);
        for cyclic in [false, true] {
            let mut dense = Matrix::zeros(n, n, &());
            let mut system = Cyclic::zeros(n, lower, upper, &());
            for i in 0..n {
                for off in -(lower as i64)..=upper as i64 {
                    let raw = i as i64 + off;
                    let j = if cyclic {
                        raw.rem_euclid(n as i64) as usize
                    } else if (0..n as i64).contains(&raw) {
                        raw as usize
                    } else {
                        continue;
                    };
                    // Zero pivots on the diagonal force row swaps.
                    let v = if off == 0 && i % 3 == 0 {
                        0
                    } else {
                        entry(i, j)
                    };
                    dense[(i, j)] = q(v);
                    system.add(i, j, &q(v)).unwrap();
                }
            }
            let rhs = Matrix::from_fn(n, 2, |i, j| q(entry(j, i) + 1));
            let b0: Vec<BigRational> = (0..n).map(|i| rhs[(i, 0)].clone()).collect();
            let b1: Vec<BigRational> = (0..n).map(|i| rhs[(i, 1)].clone()).collect();
            let x = system.solve(rhs.clone()).expect("nonsingular");
            assert_eq!(
                (0..n).map(|i| x[(i, 0)].clone()).collect::<Vec<_>>(),
                gauss::solve(&dense, &b0).unwrap()
            );
            assert_eq!(
                (0..n).map(|i| x[(i, 1)].clone()).collect::<Vec<_>>(),
                gauss::solve(&dense, &b1).unwrap()
            );
        }
    }

    #[test]
    fn a_singular_band_is_reported() {
        let mut b = Banded::zeros(3, 1, 1, &());
        b.add(0, 0, &q(1)).unwrap();
        b.add(1, 0, &q(1)).unwrap();
        let rhs = Matrix::from_fn(3, 1, |_, _| q(1));
        assert!(b.solve(rhs).is_err());
    }
}
