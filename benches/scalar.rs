//! One multiply-add step of a degree-17 Horner loop at 256 bits, per number type: the
//! per-operation cost of trajverify's `Ball` beside MPFR and beside Arb (FLINT), whose C
//! bench `benches/arb/horner.c` runs the same loop on the same values
//! (docs/benchmarks.md, "Ball arithmetic against Arb"). Criterion reports the time of one
//! evaluation (17 steps); `scripts/bench_report.py` divides by 17.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use std::hint::black_box;
use trajverify::scalar::ball::Ball;
use trajverify::scalar::{Field, Float};

const BITS: u32 = 256;
const DEGREE: usize = 17;

/// c_k = 1/(k + 1) rounded to 256 bits, and x = 0.7, as in the C bench; the balls carry the
/// radius 2^-256, as values a computation produced would.
fn coefficients<T: Field<Ctx = u32>>() -> Vec<T> {
    (0..=DEGREE)
        .map(|k| T::from_ratio(1, k as i64 + 1, &BITS))
        .collect()
}

fn with_radius(b: Ball) -> Ball {
    Ball::new(b.mid().clone(), 2f64.powi(-256))
}

fn horner(c: &mut Criterion) {
    let mut g = c.benchmark_group("horner_degree17_256bits");
    let cf: Vec<Float> = coefficients();
    let xf = Float::with_val(BITS, 0.7);
    g.bench_function(BenchmarkId::new("mpfr", "fma_in_place"), |b| {
        b.iter(|| {
            let mut acc = cf[DEGREE].clone();
            for k in (0..DEGREE).rev() {
                // acc ← acc·x + c_k in one rounding (mpfr_fma), as the C bench.
                acc.mul_add_mut(black_box(&xf), &cf[k]);
            }
            acc
        })
    });
    let cb: Vec<Ball> = coefficients::<Ball>()
        .into_iter()
        .map(with_radius)
        .collect();
    let xb = with_radius(Ball::from_f64(0.7, &BITS));
    g.bench_function(BenchmarkId::new("ball", "in_place"), |b| {
        b.iter(|| {
            let mut acc = cb[DEGREE].clone();
            for k in (0..DEGREE).rev() {
                acc *= black_box(&xb);
                acc += &cb[k];
            }
            acc
        })
    });
    g.bench_function(BenchmarkId::new("ball", "fma_in_place"), |b| {
        b.iter(|| {
            let mut acc = cb[DEGREE].clone();
            for k in (0..DEGREE).rev() {
                acc.mul_add_mut(black_box(&xb), &cb[k]);
            }
            acc
        })
    });
    g.bench_function(BenchmarkId::new("ball", "by_value"), |b| {
        b.iter(|| {
            let mut acc = cb[DEGREE].clone();
            for k in (0..DEGREE).rev() {
                acc = acc * black_box(&xb) + &cb[k];
            }
            acc
        })
    });
    g.finish();
}

criterion_group!(benches, horner);
criterion_main!(benches);
