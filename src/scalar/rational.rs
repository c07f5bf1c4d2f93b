//! [`BigRational`] as an exact [`Field`]. It deliberately does not implement `Real`.

use super::{BigRational, Field};
use num_traits::{Signed, Zero};

impl Field for BigRational {
    type Ctx = ();

    fn ctx(&self) {}
    fn scalar_name(_: &()) -> String {
        "rational".into()
    }
    fn from_i64(v: i64, _: &()) -> Self {
        BigRational::from_integer(v.into())
    }
    fn from_ratio(n: i64, d: i64, _: &()) -> Self {
        BigRational::new(n.into(), d.into())
    }
    fn from_rational(q: &BigRational, _: &()) -> Self {
        q.clone()
    }
    fn from_f64(v: f64, _: &()) -> Self {
        num_traits::FromPrimitive::from_f64(v).unwrap_or_else(BigRational::zero)
    }
    fn abs(&self) -> Self {
        Signed::abs(self)
    }
    fn is_zero(&self) -> bool {
        Zero::is_zero(self)
    }
    fn is_finite(&self) -> bool {
        true
    }
    fn to_f64(&self) -> f64 {
        super::mpfr::rational_to_f64(self)
    }
    fn to_rational(&self) -> Option<BigRational> {
        Some(self.clone())
    }
    fn to_plain_string(&self) -> String {
        // "3/5", "-7", "0": the Display of Ratio prints integers without a denominator.
        self.to_string()
    }
}

/// GMP's rationals (`rug::Rational`) as an exact [`Field`], beside num-rational's
/// [`BigRational`]: the same exact values, with GMP's integer arithmetic underneath (its gcd
/// is subquadratic and in assembly, num-bigint's is a binary gcd in Rust). `benches/param.rs`
/// measures the two on the exact objective of paper 004 (docs/benchmarks.md).
impl Field for rug::Rational {
    type Ctx = ();

    fn ctx(&self) {}
    fn scalar_name(_: &()) -> String {
        "rational".into()
    }
    fn from_i64(v: i64, _: &()) -> Self {
        rug::Rational::from(v)
    }
    fn from_ratio(n: i64, d: i64, _: &()) -> Self {
        // Panics for d = 0, as the BigRational form and i64 division do.
        rug::Rational::from((n, d))
    }
    fn from_rational(q: &BigRational, _: &()) -> Self {
        super::mpfr::to_gmp_rational(q)
    }
    fn from_exact(q: &rug::Rational, _: &()) -> Self {
        q.clone()
    }
    fn from_f64(v: f64, _: &()) -> Self {
        rug::Rational::from_f64(v).unwrap_or_default()
    }
    fn abs(&self) -> Self {
        self.clone().abs()
    }
    fn is_zero(&self) -> bool {
        self.cmp0() == std::cmp::Ordering::Equal
    }
    fn is_finite(&self) -> bool {
        true
    }
    fn to_f64(&self) -> f64 {
        super::mpfr::gmp_rational_to_f64(self)
    }
    fn to_rational(&self) -> Option<BigRational> {
        Some(super::mpfr::from_gmp_rational(self))
    }
    fn to_exact(&self) -> Option<rug::Rational> {
        Some(self.clone())
    }
    fn to_plain_string(&self) -> String {
        self.to_string()
    }
    // Each integer's digits in a string of exactly their size (GMP's `mpz_sizeinbase`),
    // appended: the `Display` route grows a formatter's string by doubling, and on output
    // of thousands of digits per number those growing buffers were a quarter of a run
    // (fresh pages zeroed). The same text as `to_plain_string`: "n/d", or "n" when d = 1.
    fn write_plain_string(&self, out: &mut String) {
        out.push_str(&self.numer().to_string_radix(10));
        if *self.denom() != 1 {
            out.push('/');
            out.push_str(&self.denom().to_string_radix(10));
        }
    }
    fn plain_string_len_hint(&self) -> usize {
        // log10(2) ≈ 0.30103 decimal digits per bit, for numerator and denominator.
        let bits = self.numer().significant_bits() + self.denom().significant_bits();
        (bits as usize * 30103).div_ceil(100_000) + 2
    }
    // The product straight into its own value, not into a copy of `a` (the default clones
    // `a`, then multiplies): one allocation and one big-number copy fewer per step, and no
    // addition at all onto a zero (the first term of every convolution).
    fn mul_add_assign(&mut self, a: &Self, b: &Self) {
        if Field::is_zero(self) {
            rug::Assign::assign(self, a * b);
        } else {
            *self += rug::Rational::from(a * b);
        }
    }
    fn mul_sub_assign(&mut self, a: &Self, b: &Self) {
        *self -= rug::Rational::from(a * b);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::ops::Pow;

    /// The direct writer prints exactly what `Display` prints: "n/d", "n" for integers,
    /// signs and zero, and numbers of thousands of digits.
    #[test]
    fn plain_text_written_directly_is_the_display_text() {
        let big = rug::Integer::from(3).pow(5000);
        let cases = [
            rug::Rational::new(),
            rug::Rational::from((-7, 1)),
            rug::Rational::from((3, 5)),
            rug::Rational::from((-3, 5)),
            rug::Rational::from((big.clone(), rug::Integer::from(2).pow(4000) + 1u32)),
            rug::Rational::from((-big, 7)),
        ];
        for q in cases {
            let mut text = String::from("prefix:");
            Field::write_plain_string(&q, &mut text);
            assert_eq!(text, format!("prefix:{q}"));
        }
    }
}
