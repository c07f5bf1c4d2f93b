//! The Gram matrix of k-th derivatives of shifted B-splines (paper 002, Sec. 5).
//!
//! J(τ) = ∫ (Σᵢ τᵢ B_k⁽ᵏ⁾(t − i + 1))² dt = τᵀGτ with G Toeplitz, gᵢⱼ = ĝ_{|i−j|},
//! ĝₘ = ∫ B_k⁽ᵏ⁾(t) B_k⁽ᵏ⁾(t − m) dt, zero for m > k. [`gram_entries`] integrates the products of
//! the exact pieces; since B_k⁽ᵏ⁾ equals (−1)ʲC(k, j) on [j, j+1] (the k-th difference
//! stencil), Vandermonde's identity gives the closed form ĝₘ = (−1)ᵐ C(2k, k+m)
//! ([`gram_entry_closed_form`]), which the claims check against the integrals.

use super::CardinalBSpline;
use crate::numeric::linalg::Matrix;
use crate::numeric::poly::{binomial, int_in};
use crate::scalar::Field;

/// ĝ₀…ĝ_k for degree k by exact integration over the common support.
pub fn gram_entries<T: Field>(k: usize, ctx: &T::Ctx) -> Vec<T> {
    let d = CardinalBSpline::<T>::from_algorithm1(k, ctx).derivative(k);
    let (zero, one) = (T::zero_in(ctx), T::one_in(ctx));
    (0..=k)
        .map(|m| {
            // On [j, j+1], B(t) is piece j and B(t − m) is piece j − m, both in s = t − j.
            (m..=k).fold(zero.clone(), |acc, j| {
                acc + &d.piece(j).mul(d.piece(j - m)).integrate((&zero, &one))
            })
        })
        .collect()
}

/// ĝₘ = (−1)ᵐ C(2k, k+m), zero for m > k.
pub fn gram_entry_closed_form<T: Field>(k: usize, m: usize, ctx: &T::Ctx) -> T {
    let c: T = int_in(&binomial(2 * k, k + m), ctx);
    if m % 2 == 1 {
        -c
    } else {
        c
    }
}

/// The M × M Gram matrix G from its entries ĝ.
pub fn gram_matrix<T: Field>(entries: &[T], size: usize, ctx: &T::Ctx) -> Matrix<T> {
    Matrix::from_fn(size, size, |i, j| {
        entries
            .get(i.abs_diff(j))
            .cloned()
            .unwrap_or_else(|| T::zero_in(ctx))
    })
}

pub use crate::numeric::linalg::ldl_pivots;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::BigRational;

    #[test]
    fn cubic_entries_are_the_papers() {
        let g = gram_entries::<BigRational>(3, &());
        let want: Vec<BigRational> = [20, -15, 6, -1]
            .iter()
            .map(|&v| BigRational::from_integer(v.into()))
            .collect();
        assert_eq!(g, want);
        for k in 1..=6 {
            let integrals = gram_entries::<BigRational>(k, &());
            let closed: Vec<BigRational> =
                (0..=k).map(|m| gram_entry_closed_form(k, m, &())).collect();
            assert_eq!(integrals, closed, "k = {k}");
        }
    }

    #[test]
    fn ldl_detects_definiteness() {
        let g = gram_matrix(&gram_entries::<BigRational>(3, &()), 8, &());
        let pivots = ldl_pivots(&g).unwrap();
        assert!(pivots
            .iter()
            .all(|p| *p > BigRational::from_integer(0.into())));
        let indefinite = Matrix::from_rows(vec![vec![1.0, 2.0], vec![2.0, 1.0]]);
        assert!(ldl_pivots(&indefinite).unwrap()[1] < 0.0);
    }
}
