//! The coefficient tables of paper 001 derived exactly, with A_0 … A_n as symbols.
//!
//! A quadratic expression Σ w_ij A_i i A_j* over ordered pairs is stored as its weights;
//! because vec(A_i i A_j*) = vec(A_j i A_i*) = A_i ⋆ A_j, the same expression in the ⋆ form of
//! Eqs. (15) and (17c) has weight w_ii on A_i^{2⋆} and w_ij + w_ji on A_i ⋆ A_j (i < j).

use super::binom;
use super::weights::middle_weights;
use crate::scalar::BigRational;
use std::collections::BTreeMap;

/// Weights of a quadratic form in the preimage control points, keyed by (i, j).
pub type Form = BTreeMap<(usize, usize), BigRational>;

fn ratio(n: i64, d: i64) -> BigRational {
    BigRational::new(n.into(), d.into())
}

/// h_k in ordered-pair form (Eq. 28): weight C(n,i)C(n,j)/C(2n,k) on A_i i A_j*, i + j = k.
pub fn hodograph_products(n: usize, k: usize) -> Form {
    (0..=n)
        .filter(|&i| k >= i && k - i <= n)
        .map(|i| {
            (
                (i, k - i),
                ratio(binom(n, i) * binom(n, k - i), binom(2 * n, k)),
            )
        })
        .collect()
}

/// A form in ⋆ notation: (i, j) with i ≤ j; (i, i) is A_i^{2⋆}.
pub fn star_form(products: &Form) -> Form {
    let mut out = Form::new();
    for (&(i, j), w) in products {
        let key = (i.min(j), i.max(j));
        let e = out.entry(key).or_insert_with(|| ratio(0, 1));
        *e += w;
    }
    out.retain(|_, w| *w != ratio(0, 1));
    out
}

/// The weight of h_j in the k-th derivative of the hodograph of degree `big` at ξ = 0
/// (`at_end` false) or ξ = 1 (Eq. 16): big!/(big−k)! times the signed binomials of Δᵏ or ∇ᵏ.
pub fn end_derivative(big: usize, k: usize, at_end: bool) -> BTreeMap<usize, i64> {
    let falling: i64 = (0..k).map(|i| (big - i) as i64).product();
    (0..=k)
        .map(|j| {
            if at_end {
                // ∇ᵏ h_big = Σ_j (−1)^j C(k,j) h_{big−j}
                let sign = if j % 2 == 0 { 1 } else { -1 };
                (big - j, sign * binom(k, j) * falling)
            } else {
                let sign = if (k - j) % 2 == 0 { 1 } else { -1 };
                (j, sign * binom(k, j) * falling)
            }
        })
        .collect()
}

/// λ, α_0 … α_n and c_p (ordered-pair form) of Eq. (17) for preimage degree n.
pub fn middle(n: usize) -> (BigRational, Vec<BigRational>, Form) {
    let w = middle_weights(n);
    let mut form = Form::new();
    for term in &w.c_p {
        if term.i == term.j {
            form.insert((term.i, term.j), term.weight.value.clone());
        } else {
            // The cached weight holds both orders (i, j) and (j, i); the form lists each.
            let half = &term.weight.value / BigRational::from_integer(2.into());
            form.insert((term.i, term.j), half.clone());
            form.insert((term.j, term.i), half);
        }
    }
    (
        w.lambda.value.clone(),
        w.alpha.iter().map(|a| a.value.clone()).collect(),
        form,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn eq_15c_and_16e_from_the_products() {
        let h2 = star_form(&hodograph_products(8, 2));
        assert_eq!(h2[&(0, 2)], ratio(7, 15));
        assert_eq!(h2[&(1, 1)], ratio(8, 15));
        let jb = end_derivative(16, 2, false);
        assert_eq!(
            jb.into_iter().collect::<Vec<_>>(),
            vec![(0, 240), (1, -480), (2, 240)]
        );
        let se = end_derivative(16, 3, true);
        assert_eq!(se[&13], -3360);
        assert_eq!(se[&16], 3360);
    }
}
