//! The condition number of the Hermite transform (paper 000, Sec. 2.3 and Fig. 5).
//!
//! κ₂(A) = σ_max(A)/σ_min(A) (Eq. 10) of the matrix A of [`transform_matrix`].
//!
//! **Block structure.** Row j ≤ m of A (Δʲp₀) involves only p₀…pⱼ and row m+1+j (∇ʲpₙ) only
//! pₙ₋ⱼ…pₙ, so A is block diagonal up to a permutation: the start block B (rows and columns
//! 0…m) and the end block, whose entry (j, k) on pₙ₋ₖ is (−1)ᵏC(j,k)f_j = (−1)ʲ·B_{jk}. With
//! D = diag((−1)ʲ) and the column order reversed, A = P₁·diag(B, D·B)·P₂ for permutations P₁, P₂;
//! all these factors are orthogonal, so σ(A) is σ(B) with every value twice and κ₂(A) = κ₂(B).
//! [`condition`] therefore runs the SVD on B, of order m+1 instead of 2m+2 (8× less work), after
//! [`has_block_structure`] confirms the structure exactly in rationals;
//! [`condition_full`] keeps the direct computation for cross-checks.
//!
//! The SVD is one-sided Jacobi over rows ([`crate::numeric::linalg::svd`]), which keeps full relative
//! accuracy on these row-scaled matrices. [`certified`] runs it at p and 2p bits of MPFR and
//! keeps the digits that agree; [`f64_reference`] is what nalgebra's SVD gives in double
//! precision for the full matrix, as a user of a standard library would compute it.
//!
//! **Proven enclosure.** [`proven`] encloses κ₂ exactly: the extreme eigenvalues of BᵀB
//! (exact in rationals) are bracketed by Sylvester's law of inertia around the squares of
//! the MPFR singular values ([`crate::numeric::linalg::inertia`]: the floating-point values
//! only say where to look; the bracket is decided by exact LDLᵀ), and
//! κ₂ = √(λ_max/λ_min) is rounded outward.

use super::{transform_matrix, TransformKind};
use crate::numeric::linalg::inertia::IntegerSymmetric;
use crate::numeric::linalg::{
    condition_number, reference, singular_values, svd::NoConvergence, Matrix,
};
use crate::scalar::certify::{at_two_precisions, Certified};
use crate::scalar::{BigRational, Field, Float, Real};
use rug::float::Round;

/// The start block B: rows and columns 0…m of the transform matrix.
pub fn start_block<T: Field>(m: usize, (t0, t1): (&T, &T), kind: TransformKind) -> Matrix<T> {
    let a = transform_matrix(m, (t0, t1), kind);
    Matrix::from_fn(m + 1, m + 1, |j, k| a[(j, k)].clone())
}

/// Exact check of the structure stated in the module doc: A vanishes outside the two blocks
/// and the end block equals D·B with its columns in reverse order.
pub fn has_block_structure(
    m: usize,
    (t0, t1): (&BigRational, &BigRational),
    kind: TransformKind,
) -> bool {
    let a = transform_matrix(m, (t0, t1), kind);
    let n = 2 * m + 1;
    (0..=n).all(|r| {
        (0..=n).all(|c| {
            let (r_start, c_start) = (r <= m, c <= m);
            if r_start != c_start {
                return a[(r, c)].is_zero();
            }
            if r_start {
                return true;
            }
            // End block: row m+1+j, column n−k holds (−1)ʲ·B_{jk}.
            let (j, k) = (r - m - 1, n - c);
            let b = a[(j, k)].clone();
            a[(r, c)] == if j % 2 == 1 { -b } else { b }
        })
    })
}

/// κ₂ of the transform for m derivatives on [t₀, t₁], in the number type of t₀, computed on
/// the start block (see the module doc for why that is exact).
///
/// # Errors
/// [`NoConvergence`] when the Jacobi SVD of the start block does not converge
/// ([`singular_values`]).
pub fn condition<T: Real>(
    m: usize,
    (t0, t1): (&T, &T),
    kind: TransformKind,
) -> Result<T, NoConvergence> {
    condition_number(&start_block(m, (t0, t1), kind))
}

/// κ₂ of the whole (2m+2)×(2m+2) matrix, without using its block structure.
///
/// # Errors
/// [`NoConvergence`] when the Jacobi SVD of the full matrix does not converge
/// ([`singular_values`]).
pub fn condition_full<T: Real>(
    m: usize,
    (t0, t1): (&T, &T),
    kind: TransformKind,
) -> Result<T, NoConvergence> {
    condition_number(&transform_matrix(m, (t0, t1), kind))
}

/// κ₂ in MPFR at `bits` and `2·bits`, certified by their agreement; also the 2·bits value.
///
/// # Errors
/// [`NoConvergence`] as [`condition`], at `bits` (`2·bits` is then not tried) or at `2·bits`.
pub fn certified(
    m: usize,
    (t0, t1): (&BigRational, &BigRational),
    kind: TransformKind,
    bits: u32,
) -> Result<(Certified, Float), NoConvergence> {
    at_two_precisions(bits, |p| {
        condition::<Float>(
            m,
            (&Float::from_rational(t0, &p), &Float::from_rational(t1, &p)),
            kind,
        )
    })
    .map(|(c, _, hi)| (c, hi))
}

/// log₂|q| to within a few units in the last place of f64, for any size of q (0: −∞).
pub fn log2_abs(q: &BigRational) -> f64 {
    let bits_log2 = |n: &num_bigint::BigInt| {
        let b = n.bits();
        let shift = b.saturating_sub(60);
        let top: num_bigint::BigInt = n.magnitude().clone().into();
        let top = top >> shift as usize;
        num_traits::ToPrimitive::to_f64(&top).map_or(f64::NAN, f64::log2) + shift as f64
    };
    if q.numer().bits() == 0 {
        return f64::NEG_INFINITY;
    }
    bits_log2(q.numer()) - bits_log2(q.denom())
}

/// The least and greatest log₂ of the scale factors n!/(n−j)!/w^j, j = 0 … m, n = 2m + 1,
/// of the transform on an interval of width w (all 0 for the binomial matrix, which has no
/// scale factors). Decided on the exact width, before any exact matrix is built: its entries
/// have about m·|log₂ w| bits.
pub fn scale_exponents(m: usize, width: &BigRational, kind: TransformKind) -> (f64, f64) {
    if kind == TransformKind::Binomial {
        return (0.0, 0.0);
    }
    let w = log2_abs(width);
    let n = 2 * m + 1;
    let (mut low, mut high, mut falling) = (0.0f64, 0.0f64, 0.0f64);
    for j in 1..=m {
        falling += ((n - j + 1) as f64).log2();
        let e = falling - j as f64 * w;
        low = low.min(e);
        high = high.max(e);
    }
    (low, high)
}

/// Whether the f64 matrix of the transform leaves f64's range, from its scale exponents
/// (`low`, `high`, [`scale_exponents`]), as a note: it overflows above 2^1100 (the entries
/// of a row are its scale factor times integers ≥ 1 where they are not 0); it underflows when
/// a row's factor is below 2^−1200 and 2^(−1076 − (2m+2)), so that the row rounds to 0 (the
/// integers it multiplies stay under 2^(2m+1)); `None` when it may fit.
pub fn f64_out_of_range(m: usize, (low, high): (f64, f64)) -> Option<&'static str> {
    if high > 1100.0 {
        Some("the f64 matrix overflows")
    } else if low < (-1200.0f64).min(-1076.0 - (2 * m + 2) as f64) {
        Some("the f64 matrix underflows (whole rows round to 0)")
    } else {
        None
    }
}

/// κ₂ by nalgebra's f64 SVD of the full f64 matrix (entries correctly rounded from the exact
/// ones); `None` when an entry overflows f64, or when the scale factors say the f64 matrix
/// leaves f64's range ([`f64_out_of_range`]). That is decided before the exact matrix is
/// built, whose entries would otherwise take minutes for a width like 1e-9999. It is +∞ when
/// nalgebra's σ_min comes out as 0.
pub fn f64_reference(
    m: usize,
    (t0, t1): (&BigRational, &BigRational),
    kind: TransformKind,
) -> Option<f64> {
    if f64_out_of_range(m, scale_exponents(m, &(t1.clone() - t0), kind)).is_some() {
        return None;
    }
    let exact = transform_matrix(m, (t0, t1), kind);
    let a = exact.map(|q| q.to_f64());
    if a.entries().iter().any(|x| !x.is_finite()) {
        return None;
    }
    Some(reference::condition_number(&a))
}

/// A proven enclosure lo ≤ κ₂ ≤ hi of the transform for m derivatives on [t₀, t₁] (see the
/// module doc), with MPFR at `bits` locating the eigenvalues (enough bits to resolve σ_min
/// to the bracket's width: about log₂κ₂ + 24 beyond it) and each extreme eigenvalue of BᵀB
/// bracketed exactly within a relative width of `relative` (widened by doubling when the
/// estimate is not that close). `None` if the brackets could not be decided.
pub fn proven(
    m: usize,
    (t0, t1): (&BigRational, &BigRational),
    kind: TransformKind,
    bits: u32,
    relative: f64,
) -> Option<(Float, Float)> {
    // The exact block in GMP's rationals (the same numbers as num-rational's, at GMP's speed).
    let exact = crate::scalar::mpfr_rational;
    let b = start_block::<crate::scalar::Exact>(m, (&exact(t0), &exact(t1)), kind);
    let gram = IntegerSymmetric::gram(&b)?;
    let sigma = singular_values(&b.map(|q| Float::from_exact(q, &bits))).ok()?;
    let square = |s: &Float| Float::with_val(bits, s * s);
    let (largest, smallest) = (square(sigma.first()?), square(sigma.last()?));
    let n = b.rows();
    let (min_lo, min_hi) = gram.bracket(0, &smallest, relative, 30)?;
    let (max_lo, max_hi) = gram.bracket(n - 1, &largest, relative, 30)?;
    if min_lo <= 0 {
        return None;
    }
    let root = |q: rug::Rational, round: Round| {
        let x = Float::with_val_round(bits, &q, round).0;
        Float::with_val_round(bits, x.sqrt_ref(), round).0
    };
    Some((
        root(max_lo / min_hi, Round::Down),
        root(max_hi / min_lo, Round::Up),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn block_structure_holds_and_gives_the_full_kappa() {
        let (t0, t1) = (
            BigRational::new((-1).into(), 3.into()),
            BigRational::new(7.into(), 2.into()),
        );
        for m in 0..=8 {
            for kind in [TransformKind::Transform, TransformKind::Binomial] {
                assert!(has_block_structure(m, (&t0, &t1), kind), "m = {m}");
                let (a, b) = (
                    Float::from_rational(&t0, &256),
                    Float::from_rational(&t1, &256),
                );
                let block = condition(m, (&a, &b), kind).unwrap();
                let full = condition_full(m, (&a, &b), kind).unwrap();
                let agree = crate::scalar::certify::agreeing_digits(&block, &full);
                assert!(agree >= 60, "m = {m}: {agree} digits");
            }
        }
    }

    fn unit_interval() -> (BigRational, BigRational) {
        (
            BigRational::from_integer(0.into()),
            BigRational::from_integer(1.into()),
        )
    }

    #[test]
    fn m0_transform_is_identity() {
        let (t0, t1) = unit_interval();
        let (c, _) = certified(0, (&t0, &t1), TransformKind::Transform, 64).unwrap();
        assert_eq!(c.text, "1.000000000000000000");
        assert_eq!(
            f64_reference(0, (&t0, &t1), TransformKind::Transform),
            Some(1.0)
        );
    }

    #[test]
    fn m1_unit_interval_closed_form() {
        // A is two copies of [[1,0],[-3,3]] (up to column order), whose squared singular
        // values are (19 ± √325)/2, so κ = √((19+√325)/(19−√325)).
        let (t0, t1) = unit_interval();
        let (c, _) = certified(1, (&t0, &t1), TransformKind::Transform, 128).unwrap();
        let root = (325f64).sqrt();
        let expected = ((19.0 + root) / (19.0 - root)).sqrt();
        assert!(
            (c.approx - expected).abs() < 1e-12 * expected,
            "{} vs {expected}",
            c.approx
        );
        assert!(c.digits >= 35);
    }
}
