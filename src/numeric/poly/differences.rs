//! Forward and backward differences and their inverses (paper 000, Sec. 2.2 and App. A).
//!
//! For x = (x₀, …, xₙ):
//! - forward differences at the first element, Δʲx₀ (Eq. 6), in matrix form Y = A1·x with
//!   A1ⱼₖ = (−1)^(j−k) C(j, k) (Eq. A1);
//! - their inverse, the binomial transform xⱼ = Σₖ C(j, k) yₖ (Eq. A2), computed by the
//!   anti-difference recursion Sʲ(yᵢ) = Sʲ⁻¹(yᵢ) + Sʲ⁻¹(yᵢ₊₁), S⁰(yᵢ) = yᵢ, xⱼ = Sʲ(y₀). This
//!   is Eq. 8 read with the superscript −(j−1) = −j+1; the extracted text prints j+1, and
//!   that literal reading is kept as [`anti_difference_as_printed`] so the claims ledger can
//!   show it does not invert Eq. 6;
//! - backward differences at the last element, ∇ʲxₙ (Eq. 7), in matrix form
//!   A3ⱼₖ = (−1)ᵏ C(j, k) acting on (xₙ, xₙ₋₁, …, x₀) (Eq. A3), a self-inverse matrix, so
//!   the same recursion recovers x from its backward differences (Eq. 9).

use super::{binomial, int_in};
use crate::numeric::linalg::Matrix;
use crate::scalar::Field;

/// One edge of a difference (or sum) table: row 0 is `x`, row r+1 combines neighbours of row r
/// pairwise with `combine(left, right)`, and the result holds the first (or last) entry of every
/// row. All the recursions of Eqs. 6–9 are of this form.
fn table_edge<T: Field>(x: &[T], last: bool, combine: impl Fn(&T, &T) -> T) -> Vec<T> {
    let mut row = x.to_vec();
    let mut out = Vec::with_capacity(x.len());
    while let Some(edge) = if last { row.last() } else { row.first() } {
        out.push(edge.clone());
        row = row.windows(2).map(|w| combine(&w[0], &w[1])).collect();
    }
    out
}

/// Δʲx₀ for j = 0…n (Eq. 6), by the recursion on the whole difference table.
pub fn forward_differences<T: Field>(x: &[T]) -> Vec<T> {
    table_edge(x, false, |a, b| b.clone() - a)
}

/// ∇ʲxₙ for j = 0…n (Eq. 7).
pub fn backward_differences<T: Field>(x: &[T]) -> Vec<T> {
    table_edge(x, true, |a, b| b.clone() - a)
}

/// The inverse of [`forward_differences`]: x with Δʲx₀ = yⱼ (Eq. A2, and Eq. 8 with the
/// superscript −j+1), by repeated pairwise sums: row j of the table holds Sʲ(yᵢ) and
/// xⱼ = Sʲ(y₀).
pub fn anti_difference<T: Field>(y: &[T]) -> Vec<T> {
    table_edge(y, false, |a, b| a.clone() + b)
}

/// The inverse of [`backward_differences`]: x with ∇ʲxₙ = yⱼ (Eq. 9; A3 is self-inverse).
pub fn backward_anti_difference<T: Field>(y: &[T]) -> Vec<T> {
    // A3 applied to y gives (xₙ, xₙ₋₁, …, x₀): apply the backward difference table to y
    // read in reverse, which computes exactly Σₖ (−1)ᵏ C(j,k) yₖ for each j.
    let reversed: Vec<T> = y.iter().rev().cloned().collect();
    let mut x = backward_differences(&reversed);
    x.reverse();
    x
}

/// Eq. 8 exactly as the extracted text prints it: Δ^{−j}(y_i) = Δ^{j+1}(y_{i+1}) + Δ^{j+1}(y_i),
/// Δ⁰(y₀) = y₀, where Δ^{j+1} are forward differences of y. Entry j of the result is this
/// "Δ^{−j}(y₀)", defined while j + 2 ≤ n; entries beyond are `None`.
pub fn anti_difference_as_printed<T: Field>(y: &[T]) -> Vec<Option<T>> {
    let n = y.len().saturating_sub(1);
    (0..=n)
        .map(|j| {
            if j == 0 {
                return Some(y[0].clone());
            }
            if j + 2 > n {
                return None;
            }
            let d0 = forward_differences(&y[0..])[j + 1].clone();
            let d1 = forward_differences(&y[1..])[j + 1].clone();
            Some(d1 + &d0)
        })
        .collect()
}

/// The (n+1)×(n+1) forward difference matrix of Eq. A1: entry (j, k) = (−1)^(j−k) C(j, k).
pub fn forward_difference_matrix<T: Field>(n: usize, ctx: &T::Ctx) -> Matrix<T> {
    Matrix::from_fn(n + 1, n + 1, |j, k| {
        let c: T = int_in(&binomial(j, k), ctx);
        if (j + k) % 2 == 1 {
            -c
        } else {
            c
        }
    })
}

/// The binomial (Pascal) matrix of Eq. A2: entry (j, k) = C(j, k).
pub fn binomial_matrix<T: Field>(n: usize, ctx: &T::Ctx) -> Matrix<T> {
    Matrix::from_fn(n + 1, n + 1, |j, k| int_in(&binomial(j, k), ctx))
}

/// The backward difference matrix of Eq. A3: entry (j, k) = (−1)ᵏ C(j, k), acting on
/// (xₙ, …, x₀).
pub fn backward_difference_matrix<T: Field>(n: usize, ctx: &T::Ctx) -> Matrix<T> {
    Matrix::from_fn(n + 1, n + 1, |j, k| {
        let c: T = int_in(&binomial(j, k), ctx);
        if k % 2 == 1 {
            -c
        } else {
            c
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::BigRational;

    fn qs(v: &[i64]) -> Vec<BigRational> {
        v.iter()
            .map(|&x| BigRational::from_integer(x.into()))
            .collect()
    }

    #[test]
    fn differences_of_squares() {
        let x = qs(&[0, 1, 4, 9, 16]);
        assert_eq!(forward_differences(&x), qs(&[0, 1, 2, 0, 0]));
        assert_eq!(backward_differences(&x), qs(&[16, 7, 2, 0, 0]));
        assert_eq!(anti_difference(&forward_differences(&x)), x);
        assert_eq!(backward_anti_difference(&backward_differences(&x)), x);
    }

    #[test]
    fn matrices_match_recursions() {
        let x = qs(&[3, -1, 4, 1, -5, 9]);
        let n = x.len() - 1;
        let a1 = forward_difference_matrix::<BigRational>(n, &());
        assert_eq!(a1.mul_vec(&x), forward_differences(&x));
        let a2 = binomial_matrix::<BigRational>(n, &());
        assert_eq!(a2.mul_vec(&forward_differences(&x)), x);
        let a3 = backward_difference_matrix::<BigRational>(n, &());
        let reversed: Vec<_> = x.iter().rev().cloned().collect();
        assert_eq!(a3.mul_vec(&reversed), backward_differences(&x));
    }

    #[test]
    fn literal_eq8_differs_from_a2() {
        let y = qs(&[1, 2, 3, 5, 8]);
        let printed = anti_difference_as_printed(&y);
        let inverse = anti_difference(&y);
        assert_eq!(printed[0].as_ref(), Some(&inverse[0]));
        assert_ne!(printed[1].as_ref(), Some(&inverse[1]));
        assert!(printed[4].is_none());
    }
}
