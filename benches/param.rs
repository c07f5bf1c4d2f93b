//! Criterion benches for paper 004: the objective G (Eq. 31) and its gradient for N = 20, 200,
//! 2000 intervals (two components) in f64 and MPFR-256, and the exact 1-D minimizer.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use std::hint::black_box;
use std::time::Duration;
use trajverify::algo::param::gradient::gradient;
use trajverify::algo::param::objective::{objective, Objective};
use trajverify::algo::param::one_d::minimizing_parametrization;
use trajverify::scalar::{Field, Float};

/// A wiggly plane curve sampled at N+1 points, uniform spacing.
fn data<T: Field>(n: usize, ctx: &T::Ctx) -> (Vec<T>, Vec<Vec<T>>, Vec<T>) {
    let h = vec![T::from_ratio(1, n as i64, ctx); n];
    let x = (0..=n)
        .map(|i| T::from_ratio((i * i % 17) as i64 + i as i64, 7, ctx))
        .collect();
    let y = (0..=n)
        .map(|i| T::from_ratio((i * 5 % 11) as i64 - 5, 3, ctx))
        .collect();
    (h, vec![x, y], vec![T::one_in(ctx), T::one_in(ctx)])
}

fn objective_and_gradient(c: &mut Criterion) {
    let mut g = c.benchmark_group("marin_objective");
    g.sample_size(10)
        .measurement_time(Duration::from_secs(2))
        .warm_up_time(Duration::from_millis(300));
    for n in [20usize, 200, 2000] {
        let (h, z, a) = data::<f64>(n, &());
        g.bench_function(BenchmarkId::new("G_f64", n), |b| {
            b.iter(|| objective(black_box(&h), &z, &a, Objective::Exact))
        });
        g.bench_function(BenchmarkId::new("grad_f64", n), |b| {
            b.iter(|| gradient(black_box(&h), &z, &a, Objective::Exact))
        });
        let (h, z, a) = data::<Float>(n, &256);
        g.bench_function(BenchmarkId::new("G_mpfr256", n), |b| {
            b.iter(|| objective(black_box(&h), &z, &a, Objective::Exact))
        });
        g.bench_function(BenchmarkId::new("grad_mpfr256", n), |b| {
            b.iter(|| gradient(black_box(&h), &z, &a, Objective::Exact))
        });
    }
    g.finish();
}

/// The exact objective in num-rational's `BigRational` and GMP's `rug::Rational`, on spacings
/// that are doubles read exactly (denominators 2^k, as paper 004's claim that every f64
/// iterate lowers G evaluates them): which rational type the exact paths should use.
fn exact_objective(c: &mut Criterion) {
    use trajverify::scalar::BigRational;
    let mut g = c.benchmark_group("marin_objective_exact");
    g.sample_size(10)
        .measurement_time(Duration::from_secs(2))
        .warm_up_time(Duration::from_millis(300));
    fn from_doubles<T: Field<Ctx = ()>>(n: usize) -> (Vec<T>, Vec<Vec<T>>, Vec<T>) {
        let (_, z, a) = data::<T>(n, &());
        // 1/n perturbed, as a descent's iterates are, then read exactly.
        let h = (0..n)
            .map(|i| T::from_f64((1.0 + 1e-3 * (i % 3) as f64) / n as f64, &()))
            .collect();
        (h, z, a)
    }
    for n in [20usize, 200] {
        let (h, z, a) = from_doubles::<BigRational>(n);
        g.bench_function(BenchmarkId::new("num_rational", n), |b| {
            b.iter(|| objective(black_box(&h), &z, &a, Objective::Exact))
        });
        let (h, z, a) = from_doubles::<rug::Rational>(n);
        g.bench_function(BenchmarkId::new("gmp_rational", n), |b| {
            b.iter(|| objective(black_box(&h), &z, &a, Objective::Exact))
        });
    }
    g.finish();
}

fn exact_minimizer(c: &mut Criterion) {
    let mut g = c.benchmark_group("marin_1d");
    g.sample_size(10)
        .measurement_time(Duration::from_secs(2))
        .warm_up_time(Duration::from_millis(300));
    for n in [20usize, 200] {
        // Mixed (case III) ordinates: runs of two rising steps, then one falling.
        let z64: Vec<f64> = (0..=n)
            .scan(0.0, |s, i| {
                *s += if i % 3 == 2 {
                    -1.5
                } else {
                    1.0 + (i % 5) as f64 / 10.0
                };
                Some(*s)
            })
            .collect();
        g.bench_function(BenchmarkId::new("f64", n), |b| {
            b.iter(|| minimizing_parametrization(black_box(&z64)))
        });
        let zf: Vec<Float> = z64.iter().map(|x| Float::with_val(256, *x)).collect();
        g.bench_function(BenchmarkId::new("mpfr256", n), |b| {
            b.iter(|| minimizing_parametrization(black_box(&zf)))
        });
    }
    g.finish();
}

criterion_group!(
    benches,
    objective_and_gradient,
    exact_objective,
    exact_minimizer
);
criterion_main!(benches);
