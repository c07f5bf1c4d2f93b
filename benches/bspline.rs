//! Criterion benches for paper 002: the Gram entries (k = 3, 10) and the smoothing solve of
//! Eq. 15 (M = 20, 200 control points, N = M/2 data), in f64, MPFR-256 and exact rationals.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use std::hint::black_box;
use std::time::Duration;
use trajverify::algo::bspline::fit::SplineSpace;
use trajverify::algo::bspline::gram::gram_entries;
use trajverify::scalar::{BigRational, Field, Float};

fn gram(c: &mut Criterion) {
    let mut g = c.benchmark_group("bspline_gram");
    g.sample_size(20)
        .measurement_time(Duration::from_secs(2))
        .warm_up_time(Duration::from_millis(300));
    for k in [3usize, 10] {
        g.bench_function(BenchmarkId::new("f64", k), |b| {
            b.iter(|| gram_entries::<f64>(black_box(k), &()))
        });
        g.bench_function(BenchmarkId::new("mpfr256", k), |b| {
            b.iter(|| gram_entries::<Float>(black_box(k), &256))
        });
        g.bench_function(BenchmarkId::new("rational", k), |b| {
            b.iter(|| gram_entries::<BigRational>(black_box(k), &()))
        });
    }
    g.finish();
}

/// N = M/2 data at t = 2i + 3/2 with values (i mod 7) − 3, unit weights.
fn problem<T: Field>(m: usize, ctx: &T::Ctx) -> (SplineSpace<T>, Vec<T>, Vec<T>, Vec<T>) {
    let n = m / 2;
    let space = SplineSpace::new(3, m, ctx).expect("degree 3");
    let times = (0..n)
        .map(|i| T::from_ratio(4 * i as i64 + 3, 2, ctx))
        .collect();
    let values = (0..n)
        .map(|i| T::from_i64((i % 7) as i64 - 3, ctx))
        .collect();
    (space, times, values, vec![T::one_in(ctx); n])
}

fn smoothing(c: &mut Criterion) {
    let mut g = c.benchmark_group("bspline_smoothing");
    g.sample_size(10)
        .measurement_time(Duration::from_secs(3))
        .warm_up_time(Duration::from_millis(300));
    for m in [20usize, 200] {
        let (s, t, v, w) = problem::<f64>(m, &());
        g.bench_function(BenchmarkId::new("f64", m), |b| {
            b.iter(|| s.smooth(black_box(&t), &v, &w))
        });
        let (s, t, v, w) = problem::<Float>(m, &256);
        g.bench_function(BenchmarkId::new("mpfr256", m), |b| {
            b.iter(|| s.smooth(black_box(&t), &v, &w))
        });
        let (s, t, v, w) = problem::<BigRational>(m, &());
        g.bench_function(BenchmarkId::new("rational", m), |b| {
            b.iter(|| s.smooth(black_box(&t), &v, &w))
        });
    }
    g.finish();
}

criterion_group!(benches, gram, smoothing);
criterion_main!(benches);
