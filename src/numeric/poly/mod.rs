//! Polynomials in Bernstein form and the difference operators behind their derivatives.
//!
//! - [`differences`]: forward and backward differences (paper 000, Eqs. 6–7), their
//!   inverses (Eqs. 8–9) and the matrix forms (App. A, Eqs. A1–A3).
//! - [`bernstein`]: the Bernstein basis on [t₀, t₁] (Eqs. 1–4), de Casteljau evaluation,
//!   derivatives (Eqs. 5, 12, 13), conversion to the power basis, degree elevation.
//!
//! Everything is generic over [`Field`]: exact in rationals.

pub mod bernstein;
pub mod differences;
pub mod power;

pub use bernstein::Bernstein;
pub use power::Poly;

use crate::scalar::{BigInt, Field};
use num_traits::One;

/// C(n, k) as an i64, read from a Pascal triangle built at compile time for n ≤ 60 (every
/// entry fits in i64): PH interpolation evaluates dozens of them per segment and the BFBS
/// one per term, so a lookup must cost no more than an index. Beyond the table, the
/// multiplicative formula (exact while the result fits in i64).
#[inline]
pub fn binom(n: usize, k: usize) -> i64 {
    if k > n {
        return 0;
    }
    if n < PASCAL_ROWS {
        return PASCAL[n][k];
    }
    let k = k.min(n - k);
    (0..k).fold(1i64, |r, i| r * (n - i) as i64 / (i + 1) as i64)
}

/// Rows 0…60 of Pascal's triangle (C(60, 30) ≈ 1.2e17 < 2⁶³).
const PASCAL_ROWS: usize = 61;
static PASCAL: [[i64; PASCAL_ROWS]; PASCAL_ROWS] = pascal_triangle();

const fn pascal_triangle() -> [[i64; PASCAL_ROWS]; PASCAL_ROWS] {
    let mut t = [[0i64; PASCAL_ROWS]; PASCAL_ROWS];
    let mut r = 0;
    while r < PASCAL_ROWS {
        t[r][0] = 1;
        let mut j = 1;
        while j <= r {
            t[r][j] = t[r - 1][j - 1] + t[r - 1][j];
            j += 1;
        }
        r += 1;
    }
    t
}

/// The binomial coefficient C(n, k) as an exact integer.
pub fn binomial(n: usize, k: usize) -> BigInt {
    if k > n {
        return BigInt::from(0);
    }
    let k = k.min(n - k);
    let mut c = BigInt::one();
    for i in 0..k {
        c = c * (n - i) / (i + 1);
    }
    c
}

/// The falling factorial n!/(n−j)! = n(n−1)…(n−j+1) as an exact integer.
pub fn falling_factorial(n: usize, j: usize) -> BigInt {
    (0..j).fold(BigInt::one(), |acc, i| acc * (n - i))
}

/// n!/(n−j)! as a value of `T`, correctly rounded (exact in rationals). Products that fit in
/// 64 bits skip the big-integer detour: `T::from_i64` rounds them once, like `int_in`.
pub fn falling_factorial_in<T: Field>(n: usize, j: usize, ctx: &T::Ctx) -> T {
    let small = (0..j)
        .try_fold(1u64, |acc, i| acc.checked_mul((n - i) as u64))
        .filter(|&v| v <= i64::MAX as u64);
    match small {
        Some(v) => T::from_i64(v as i64, ctx),
        None => int_in(&falling_factorial(n, j), ctx),
    }
}

/// An exact integer as a value of `T` (correctly rounded).
pub fn int_in<T: Field>(n: &BigInt, ctx: &T::Ctx) -> T {
    T::from_rational(&crate::scalar::BigRational::from_integer(n.clone()), ctx)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pascal_and_falling() {
        assert_eq!(binomial(5, 2), BigInt::from(10));
        assert_eq!(binomial(61, 30).to_string(), "232714176627630544");
        assert_eq!(binomial(3, 4), BigInt::from(0));
        assert_eq!(falling_factorial(5, 2), BigInt::from(20));
        assert_eq!(falling_factorial(5, 0), BigInt::from(1));
        // The 64-bit fast path and the big-integer path agree (21·20·…·2 = 21!, beyond 2^63 at 21).
        for (n, j) in [(5, 2), (20, 20), (21, 21), (61, 31)] {
            let exact: crate::scalar::BigRational = falling_factorial_in(n, j, &());
            assert_eq!(
                exact,
                crate::scalar::BigRational::from_integer(falling_factorial(n, j))
            );
            let rounded: f64 = falling_factorial_in(n, j, &());
            assert_eq!(rounded, int_in::<f64>(&falling_factorial(n, j), &()));
        }
    }
}
