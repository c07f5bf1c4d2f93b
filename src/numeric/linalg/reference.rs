//! f64 reference computations through nalgebra: what a standard double-precision library
//! returns for the same matrices, so reports can show where f64 stops being enough.

use super::Matrix;
use nalgebra::DMatrix;

fn to_dmatrix(a: &Matrix<f64>) -> DMatrix<f64> {
    DMatrix::from_row_slice(a.rows(), a.cols(), a.entries())
}

/// Singular values by nalgebra's SVD, largest first.
pub fn singular_values(a: &Matrix<f64>) -> Vec<f64> {
    let mut s: Vec<f64> = to_dmatrix(a).singular_values().iter().copied().collect();
    s.sort_by(|x, y| y.total_cmp(x));
    s
}

/// κ₂ = σ_max/σ_min by nalgebra's SVD (∞ when σ_min is 0, NaN when an entry is not finite).
pub fn condition_number(a: &Matrix<f64>) -> f64 {
    if a.entries().iter().any(|x| !x.is_finite()) {
        return f64::NAN;
    }
    let s = singular_values(a);
    s[0] / s[s.len() - 1]
}

/// The inverse by nalgebra's LU, if it finds one.
pub fn inverse(a: &Matrix<f64>) -> Option<Matrix<f64>> {
    let inv = to_dmatrix(a).try_inverse()?;
    Some(Matrix::from_fn(inv.nrows(), inv.ncols(), |i, j| {
        inv[(i, j)]
    }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numeric::linalg::gauss;

    #[test]
    fn generic_inverse_matches_nalgebra() {
        let a = Matrix::from_fn(6, 6, |i, j| {
            1.0 / (1.0 + i as f64 + 2.0 * j as f64) + (i == j) as u8 as f64
        });
        let ours = gauss::inverse(&a).unwrap();
        let theirs = inverse(&a).unwrap();
        for (x, y) in ours.entries().iter().zip(theirs.entries()) {
            assert!((x - y).abs() < 1e-12 * (1.0 + y.abs()), "{x} vs {y}");
        }
    }
}
