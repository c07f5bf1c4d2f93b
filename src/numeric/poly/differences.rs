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
    let mut edge = x.to_vec();
    table_edge_in_place(&mut edge, 1, last, combine);
    edge
}

/// [`table_edge`] in place, for `lanes` independent tables side by side: entry i of row 0 is
/// `x[i·lanes .. (i+1)·lanes]`, one number per table, and so is entry i of the edge that
/// replaces it. Each table sees exactly the operations of the table written out row by row
/// (entry k of row r+1 is combine(entry k, entry k+1) of row r), in the same order, so the
/// numbers are the same bit for bit; only where they are stored differs:
/// - first edge: row r occupies entries r…n−1, updated from the end so that entry k−1 is
///   still row r−1's when entry k is formed; the first entry of row r stays at r;
/// - last edge: row r occupies entries 0…n−1−r, updated from the front; the last entry of
///   row r stays at n−1−r, so the edge comes out reversed and is turned round at the end.
fn table_edge_in_place<T: Field>(
    x: &mut [T],
    lanes: usize,
    last: bool,
    combine: impl Fn(&T, &T) -> T,
) {
    let n = x.len().checked_div(lanes).unwrap_or(0);
    for r in 1..n {
        if last {
            for i in 0..(n - r) * lanes {
                x[i] = combine(&x[i], &x[i + lanes]);
            }
        } else {
            for i in (r * lanes..n * lanes).rev() {
                x[i] = combine(&x[i - lanes], &x[i]);
            }
        }
    }
    if last {
        reverse_entries(x, lanes);
    }
}

/// The entries of `x` (each `lanes` numbers) in reverse order, in place.
fn reverse_entries<T>(x: &mut [T], lanes: usize) {
    let n = x.len().checked_div(lanes).unwrap_or(0);
    for i in 0..n / 2 {
        for l in 0..lanes {
            x.swap(i * lanes + l, (n - 1 - i) * lanes + l);
        }
    }
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
    let mut x = y.to_vec();
    anti_difference_lanes(&mut x, 1);
    x
}

/// [`anti_difference`] of `lanes` sequences at once, in place, interleaved: y_j of sequence l
/// is `y[j·lanes + l]` and is replaced by x_j. Bit for bit [`anti_difference`] of each.
pub fn anti_difference_lanes<T: Field>(y: &mut [T], lanes: usize) {
    table_edge_in_place(y, lanes, false, |a, b| a.clone() + b);
}

/// The inverse of [`backward_differences`]: x with ∇ʲxₙ = yⱼ (Eq. 9; A3 is self-inverse).
pub fn backward_anti_difference<T: Field>(y: &[T]) -> Vec<T> {
    let mut x = y.to_vec();
    backward_anti_difference_lanes(&mut x, 1);
    x
}

/// [`backward_anti_difference`] of `lanes` interleaved sequences in place, as
/// [`anti_difference_lanes`]. Bit for bit [`backward_anti_difference`] of each.
pub fn backward_anti_difference_lanes<T: Field>(y: &mut [T], lanes: usize) {
    // A3 applied to y gives (xₙ, xₙ₋₁, …, x₀): the backward difference table of y read in
    // reverse, which computes exactly Σₖ (−1)ᵏ C(j,k) yₖ for each j. Read forwards, entry k
    // of that table's next row is yₖ − yₖ₊₁ (the same two operands as the reversed table's
    // difference) and its last edge is the forward reading's first.
    table_edge_in_place(y, lanes, false, |a, b| a.clone() - b);
    reverse_entries(y, lanes);
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

    /// Doubles that make rounding differ with the order of operations.
    fn scrambled(count: usize, seed: u64) -> Vec<f64> {
        let mut state = seed;
        (0..count)
            .map(|_| {
                state = state
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                let mantissa = (state >> 11) as f64 / (1u64 << 53) as f64;
                (mantissa - 0.5) * 10f64.powi((state % 17) as i32 - 8)
            })
            .collect()
    }

    #[test]
    fn lanes_are_each_sequence_alone_bit_for_bit() {
        for (n, lanes) in [(1, 1), (2, 3), (6, 5), (25, 4)] {
            let y = scrambled(n * lanes, (n * 31 + lanes) as u64);
            let lane = |l: usize| -> Vec<f64> { (0..n).map(|j| y[j * lanes + l]).collect() };
            let (mut forward, mut backward) = (y.clone(), y.clone());
            anti_difference_lanes(&mut forward, lanes);
            backward_anti_difference_lanes(&mut backward, lanes);
            for l in 0..lanes {
                let alone = lane(l);
                // The reference: Eq. 9 as written, the backward table of y read in reverse.
                let reversed: Vec<f64> = alone.iter().rev().copied().collect();
                let mut eq9 = backward_differences(&reversed);
                eq9.reverse();
                for j in 0..n {
                    assert_eq!(
                        forward[j * lanes + l].to_bits(),
                        anti_difference(&alone)[j].to_bits()
                    );
                    assert_eq!(
                        backward[j * lanes + l].to_bits(),
                        eq9[j].to_bits(),
                        "n {n} lane {l} j {j}"
                    );
                    assert_eq!(
                        backward_anti_difference(&alone)[j].to_bits(),
                        eq9[j].to_bits()
                    );
                }
            }
        }
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
