//! Exact weights of the Bernstein products, derived once per preimage degree and cached.
//!
//! Every conversion of a segment needs the same rational constants: the product weights
//! C(n,i) C(n,j) / C(2n,i+j) of the hodograph (Eq. 28, App. C) and λ, α_j and the c_p weights
//! of step 5 of Algorithm 1 (Eq. 17). Deriving them per segment cost more than the
//! interpolation itself, so they are computed here exactly in rationals, reduced, and kept in
//! a table per degree; a conversion only turns each reduced fraction into its scalar type
//! (one correctly rounded division in f64 and MPFR, nothing in exact arithmetic).

use std::sync::OnceLock;

use num_traits::{ToPrimitive, Zero};

use super::{binom, MAX_PREIMAGE_DEGREE};
use crate::scalar::{BigRational, Field};

/// A rational constant, with its reduced numerator and denominator as i64 when they fit.
#[derive(Clone, Debug)]
pub struct ExactWeight {
    /// The exact value.
    pub value: BigRational,
    /// Reduced numerator and denominator (both below 2^53) and the nearest double.
    small: Option<(i64, i64, f64)>,
}

impl ExactWeight {
    fn new(value: BigRational) -> Self {
        let small = value
            .numer()
            .to_i64()
            .zip(value.denom().to_i64())
            .filter(|(n, d)| n.unsigned_abs() < (1 << 53) && *d < (1 << 53))
            .map(|(n, d)| (n, d, f64::from_ratio(n, d, &())));
        ExactWeight { value, small }
    }

    /// The constant in the scalar type of `ctx`, correctly rounded.
    pub fn to<T: Field>(&self, ctx: &T::Ctx) -> T {
        match self.small {
            Some((n, d, nearest)) => T::from_ratio_nearest(n, d, nearest, ctx),
            None => T::from_rational(&self.value, ctx),
        }
    }
}

/// One term w · vec(A_i i A_j*) of a symmetric Bernstein product, i ≤ j; w already holds
/// the factor 2 of the pair (i, j), (j, i) when i < j.
#[derive(Clone, Debug)]
pub struct PairTerm {
    /// The index i of A_i.
    pub i: usize,
    /// The index j of A_j.
    pub j: usize,
    /// The weight w.
    pub weight: ExactWeight,
}

/// The hodograph h_k = Σ_{i+j=k} C(n,i)C(n,j)/C(2n,k) A_i i A_j* as a list of pair terms
/// (Eq. 28); index k = i + j.
pub fn product_terms(n: usize) -> &'static [PairTerm] {
    static TABLE: [OnceLock<Vec<PairTerm>>; MAX_PREIMAGE_DEGREE + 1] =
        [const { OnceLock::new() }; MAX_PREIMAGE_DEGREE + 1];
    assert!(
        n <= MAX_PREIMAGE_DEGREE,
        "preimage degree {n} beyond the table"
    );
    TABLE[n].get_or_init(|| {
        let mut terms = Vec::new();
        for i in 0..=n {
            for j in i..=n {
                let pairs = if i == j { 1 } else { 2 };
                let w = BigRational::new(
                    (pairs * binom(n, i) * binom(n, j)).into(),
                    binom(2 * n, i + j).into(),
                );
                terms.push(PairTerm {
                    i,
                    j,
                    weight: ExactWeight::new(w),
                });
            }
        }
        terms
    })
}

/// λ, α_0 … α_n and the c_p terms of step 5 for preimage degree n = 2m (Eq. 17):
/// A_m solves A_m ⋆ A_m = λ(p_e − p_b) − c_p with A_m = (X − Σ_{j≠m} α_j A_j)/α_m.
#[derive(Debug)]
pub struct MiddleWeights {
    /// λ = α_m, the weight of A_m ⋆ A_m.
    pub lambda: ExactWeight,
    /// 1/α_m = 1/λ, so that A_m needs no division.
    pub inverse_lambda: ExactWeight,
    /// The weights α_j of the other A_j.
    pub alpha: Vec<ExactWeight>,
    /// The non-zero terms of c_p (row and column m are zero), i ≤ j.
    pub c_p: Vec<PairTerm>,
}

/// The exact [`MiddleWeights`] of even preimage degree n, derived once.
pub fn middle_weights(n: usize) -> &'static MiddleWeights {
    static TABLE: [OnceLock<MiddleWeights>; MAX_PREIMAGE_DEGREE + 1] =
        [const { OnceLock::new() }; MAX_PREIMAGE_DEGREE + 1];
    assert!(
        n <= MAX_PREIMAGE_DEGREE,
        "preimage degree {n} beyond the table"
    );
    TABLE[n].get_or_init(|| {
        let m = n / 2;
        let big = 2 * n;
        let odd = BigRational::from_integer(((big + 1) as i64).into());
        // ∫₀¹ B_i^n B_j^n dξ = C(n,i)C(n,j) / (C(2n,i+j)(2n+1)).
        let integral = |i: usize, j: usize| {
            BigRational::new((binom(n, i) * binom(n, j)).into(), binom(big, i + j).into()) / &odd
        };
        let alpha: Vec<BigRational> = (0..=n).map(|j| integral(m, j)).collect();
        let lambda = alpha[m].clone();
        let mut c_p = Vec::new();
        for i in (0..=n).filter(|&i| i != m) {
            for j in (i..=n).filter(|&j| j != m) {
                let w = &lambda * integral(i, j) - &alpha[i] * &alpha[j];
                if Zero::is_zero(&w) {
                    continue;
                }
                let w = if i == j {
                    w
                } else {
                    w * BigRational::from_integer(2.into())
                };
                c_p.push(PairTerm {
                    i,
                    j,
                    weight: ExactWeight::new(w),
                });
            }
        }
        MiddleWeights {
            inverse_lambda: ExactWeight::new(lambda.recip()),
            lambda: ExactWeight::new(lambda),
            alpha: alpha.into_iter().map(ExactWeight::new).collect(),
            c_p,
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_degree_has_its_tables_and_the_c4_constants_are_those_of_eq_17() {
        for n in (2..=MAX_PREIMAGE_DEGREE).step_by(2) {
            assert_eq!(product_terms(n).len(), (n + 1) * (n + 2) / 2);
            assert_eq!(middle_weights(n).alpha.len(), n + 1);
        }
        let w = middle_weights(8);
        assert_eq!(w.lambda.value, BigRational::new(490.into(), 21879.into()));
        assert_eq!(w.alpha[0].value, BigRational::new(1.into(), 442.into()));
        let c00 = w
            .c_p
            .iter()
            .find(|t| t.i == 0 && t.j == 0)
            .expect("c_p term (0, 0)");
        assert_eq!(
            c00.weight.value,
            BigRational::new(147807.into(), 112633092.into())
        );
        assert_eq!(w.lambda.to::<f64>(&()), 490.0 / 21879.0);
    }
}
