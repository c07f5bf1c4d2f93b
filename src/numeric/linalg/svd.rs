//! Singular values by one-sided Jacobi (Hestenes), at any precision.
//!
//! The rows r_i of A are orthogonalised pairwise by plane rotations (applied to the row
//! space, which leaves the singular values unchanged) until every pair satisfies
//! |r_i·r_j| ≤ ℓ·ε‖r_i‖‖r_j‖, with ε = 2^(1−p) and ℓ the row length: a dot product of length
//! ℓ cannot be computed more accurately than that, so a stricter test may never be met.
//! The singular values are then the row norms.
//! Working on rows rather than columns is deliberate: for a row-scaled matrix A = D·C
//! (D diagonal) the method delivers each singular value with relative error of order
//! ε·κ(C) rather than ε·κ(A) (Demmel & Veselić, 1992), and the Hermite transform of
//! paper 000 is exactly such a matrix, its rows scaled by n!/(n−j)!/(t₁−t₀)^j.

use super::Matrix;
use crate::scalar::{Field, Real};

/// Why the singular values could not be computed.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum NoConvergence {
    /// Jacobi stopped before convergence (after this many sweeps).
    #[error("one-sided Jacobi did not converge in {sweeps} sweeps")]
    Sweeps {
        /// The number of Jacobi sweeps used.
        sweeps: usize,
    },
    /// A matrix with no entry has no condition number (and no context to make one in).
    #[error("the matrix is empty")]
    Empty,
}

const MAX_SWEEPS: usize = 60;

/// The singular values of `a`, largest first (min(rows, cols) of them).
///
/// # Errors
/// [`NoConvergence`] when some pair of rows is still not orthogonal to the tolerance after
/// 60 sweeps (non-finite entries, for instance). An empty matrix has no singular value
/// (`Ok` of an empty list).
pub fn singular_values<T: Real>(a: &Matrix<T>) -> Result<Vec<T>, NoConvergence> {
    let Some(ctx) = a.entries().first().map(Field::ctx) else {
        return Ok(Vec::new());
    };
    // Orthogonalise the shorter side: rows of A when rows ≤ cols, else rows of Aᵀ.
    let work = if a.rows() <= a.cols() {
        a.clone()
    } else {
        a.transpose()
    };
    let n = work.rows();
    let mut rows: Vec<Vec<T>> = (0..n).map(|i| work.row(i).to_vec()).collect();
    let tolerance = T::epsilon(&ctx) * &T::from_i64(work.cols() as i64, &ctx);
    let one = T::one_in(&ctx);
    let zero = T::zero_in(&ctx);
    let dot = |x: &[T], y: &[T]| {
        let mut acc = zero.clone();
        for (xk, yk) in x.iter().zip(y) {
            acc.mul_add_assign(xk, yk);
        }
        acc
    };
    let mut scratch = rows.first().cloned().unwrap_or_default();
    for _ in 0..MAX_SWEEPS {
        // Squared row norms, recomputed each sweep and updated exactly by each rotation
        // (‖rᵢ‖² − t·γ and ‖rⱼ‖² + t·γ) within it: one dot product per pair instead of three.
        let mut norms: Vec<T> = rows.iter().map(|r| dot(r, r)).collect();
        let mut rotated = false;
        for i in 0..n {
            for j in i + 1..n {
                crate::cancel::checkpoint();
                let gamma = dot(&rows[i], &rows[j]);
                if gamma.is_zero()
                    || gamma.abs() <= tolerance.clone() * &(norms[i].clone() * &norms[j]).sqrt()
                {
                    continue;
                }
                rotated = true;
                // The rotation that annihilates the (i, j) entry of the Gram matrix:
                // ζ = (‖rⱼ‖² − ‖rᵢ‖²)/(2γ), t = sign(ζ)/(|ζ| + √(1+ζ²)), c = 1/√(1+t²), s = c·t.
                let zeta = (norms[j].clone() - &norms[i]) / &(gamma.clone() + &gamma);
                let root = (one.clone() + &(zeta.clone() * &zeta)).sqrt();
                let t = if zeta >= zero {
                    one.clone() / &(zeta + &root)
                } else {
                    -(one.clone() / &(root - &zeta))
                };
                let c = one.clone() / &(one.clone() + &(t.clone() * &t)).sqrt();
                let s = c.clone() * &t;
                norms[i].mul_sub_assign(&t, &gamma);
                norms[j].mul_add_assign(&t, &gamma);
                let (head, tail) = rows.split_at_mut(j);
                let (ri, rj) = (&mut head[i], &mut tail[0]);
                for k in 0..ri.len() {
                    scratch[k].clone_from(&ri[k]);
                    ri[k] *= &c; // rᵢ ← c·rᵢ − s·rⱼ
                    ri[k].mul_sub_assign(&s, &rj[k]);
                    rj[k] *= &c; // rⱼ ← s·rᵢ + c·rⱼ
                    rj[k].mul_add_assign(&s, &scratch[k]);
                }
            }
        }
        if !rotated {
            let mut sigma: Vec<T> = rows.iter().map(|r| dot(r, r).sqrt()).collect();
            sigma.sort_by(|x, y| y.partial_cmp(x).unwrap_or(std::cmp::Ordering::Equal));
            return Ok(sigma);
        }
    }
    Err(NoConvergence::Sweeps { sweeps: MAX_SWEEPS })
}

/// The spectral condition number κ₂ = σ_max/σ_min (infinite when σ_min = 0, the zero
/// matrix included: +∞ in f64 and MPFR, the unbounded ball for balls).
///
/// # Errors
/// [`NoConvergence::Sweeps`] as [`singular_values`]; [`NoConvergence::Empty`] for a matrix
/// without entries.
pub fn condition_number<T: Real>(a: &Matrix<T>) -> Result<T, NoConvergence> {
    let sigma = singular_values(a)?;
    let (Some(max), Some(min)) = (sigma.first(), sigma.last()) else {
        return Err(NoConvergence::Empty);
    };
    if min.is_zero() {
        // σ_max/0, not 0/0 = NaN for the zero matrix.
        let one = T::one_in(&min.ctx());
        return Ok(one / min);
    }
    Ok(max.clone() / min)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numeric::linalg::reference;
    use rug::Float;

    #[test]
    fn diagonal_and_known_values() {
        let a = Matrix::from_rows(vec![vec![3.0, 0.0], vec![0.0, -4.0]]);
        assert_eq!(singular_values(&a).unwrap(), vec![4.0, 3.0]);
        // [[1,1],[0,1]]: σ = (√5 ± 1)/2.
        let b = Matrix::from_rows(vec![vec![1.0, 1.0], vec![0.0, 1.0]]);
        let s = singular_values(&b).unwrap();
        assert!((s[0] - (5f64.sqrt() + 1.0) / 2.0).abs() < 1e-15);
        assert!((s[1] - (5f64.sqrt() - 1.0) / 2.0).abs() < 1e-15);
    }

    #[test]
    fn agrees_with_nalgebra_in_f64() {
        let a = Matrix::from_fn(5, 4, |i, j| {
            ((i * 7 + j * 3) % 11) as f64 - 4.5 + (i == j) as u8 as f64
        });
        let ours = singular_values(&a).unwrap();
        let theirs = reference::singular_values(&a);
        for (x, y) in ours.iter().zip(&theirs) {
            assert!((x - y).abs() <= 1e-13 * theirs[0], "{x} vs {y}");
        }
    }

    #[test]
    fn high_precision_beats_f64_on_a_graded_matrix() {
        // rows scaled by 1, 1e20, 1e40: κ ≈ 1e40 but Jacobi on rows keeps full relative accuracy.
        let scale = [1.0, 1e20, 1e40];
        let a = Matrix::from_fn(3, 3, |i, j| {
            Float::with_val(256, (1 + i + 2 * j) as f64 * scale[i]) + (i == j) as u32
        });
        let s256 = condition_number(&a).unwrap();
        let a512 = a.map(|x| Float::with_val(512, x));
        let s512 = condition_number(&a512).unwrap();
        let agree = crate::scalar::certify::agreeing_digits(&s256, &s512);
        assert!(agree >= 60, "only {agree} digits agree");
    }
}
