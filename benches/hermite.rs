//! Criterion benches for paper 000: Hermite control points (m = 2, 10, 30) and the condition
//! number κ₂ (m = 10, 30), in f64, MPFR-256 and exact rationals. `docs/benchmarks.md` reports the
//! ratios to f64. κ₂ has no rational column: an SVD needs square roots.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use std::hint::black_box;
use std::time::Duration;
use trajverify::algo::hermite::{condition, HermiteData, TransformKind};
use trajverify::numeric::linalg::reference;
use trajverify::scalar::{BigRational, Field, Float};

/// Data with m derivatives on [0, 1]: x₀⁽ʲ⁾ = j + 1, x₁⁽ʲ⁾ = −(j + 2)/3 (exact in every type).
fn data<T: Field>(m: usize, ctx: &T::Ctx) -> HermiteData<T> {
    let start = (0..=m).map(|j| T::from_i64(j as i64 + 1, ctx)).collect();
    let end = (0..=m)
        .map(|j| T::from_ratio(-(j as i64 + 2), 3, ctx))
        .collect();
    HermiteData::new(start, end, (T::zero_in(ctx), T::one_in(ctx))).expect("valid data")
}

fn control_points(c: &mut Criterion) {
    let mut g = c.benchmark_group("hermite_control_points");
    g.sample_size(30)
        .measurement_time(Duration::from_secs(2))
        .warm_up_time(Duration::from_millis(500));
    for m in [2usize, 10, 30] {
        let f = data::<f64>(m, &());
        g.bench_function(BenchmarkId::new("f64", m), |b| {
            b.iter(|| black_box(&f).solve())
        });
        let p = data::<Float>(m, &256);
        g.bench_function(BenchmarkId::new("mpfr256", m), |b| {
            b.iter(|| black_box(&p).solve())
        });
        let r = data::<BigRational>(m, &());
        g.bench_function(BenchmarkId::new("rational", m), |b| {
            b.iter(|| black_box(&r).solve())
        });
    }
    g.finish();
}

fn condition_number(c: &mut Criterion) {
    let mut g = c.benchmark_group("hermite_condition");
    g.sample_size(10)
        .measurement_time(Duration::from_secs(3))
        .warm_up_time(Duration::from_millis(500));
    for m in [10usize, 30] {
        g.bench_function(BenchmarkId::new("f64_jacobi", m), |b| {
            b.iter(|| {
                condition::condition::<f64>(black_box(m), (&0.0, &1.0), TransformKind::Transform)
            })
        });
        let (t0, t1) = (
            BigRational::from_integer(0.into()),
            BigRational::from_integer(1.into()),
        );
        let a =
            trajverify::algo::hermite::transform_matrix(m, (&t0, &t1), TransformKind::Transform)
                .map(|q| q.to_f64());
        g.bench_function(BenchmarkId::new("f64_nalgebra_full", m), |b| {
            b.iter(|| reference::condition_number(black_box(&a)))
        });
        let (z, o) = (Float::with_val(256, 0), Float::with_val(256, 1));
        g.bench_function(BenchmarkId::new("mpfr256", m), |b| {
            b.iter(|| {
                condition::condition::<Float>(black_box(m), (&z, &o), TransformKind::Transform)
            })
        });
    }
    g.finish();
}

criterion_group!(benches, control_points, condition_number);
criterion_main!(benches);
