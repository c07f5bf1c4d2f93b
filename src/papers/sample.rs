//! Deterministic pseudo-random test data for claims checked "on random data": the same
//! seed gives the same data on every machine, so the ledger's bytes do not change.

use crate::scalar::BigRational;

/// SplitMix64 (Steele, Lea & Flood 2014): a tiny, well-mixed 64-bit generator.
pub struct SplitMix64(u64);

impl SplitMix64 {
    pub fn new(seed: u64) -> Self {
        SplitMix64(seed)
    }

    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// An integer in [lo, hi].
    pub fn int(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next_u64() % (hi - lo + 1) as u64) as i64
    }

    /// A rational n/d with |n| ≤ 1000 and 1 ≤ d ≤ 100.
    pub fn rational(&mut self) -> BigRational {
        BigRational::new(self.int(-1000, 1000).into(), self.int(1, 100).into())
    }

    /// A positive rational in [1/100, 10].
    pub fn positive(&mut self) -> BigRational {
        BigRational::new(self.int(1, 1000).into(), self.int(1, 100).into())
    }

    pub fn rationals(&mut self, n: usize) -> Vec<BigRational> {
        (0..n).map(|_| self.rational()).collect()
    }
}
