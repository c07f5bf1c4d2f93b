//! Criterion benches for paper 003: evaluating a GERBS path at one point (position, first
//! and second derivatives, curvature and its rate) with the BFBS closed form against the
//! ERBS quadrature, in f64 and MPFR-256; and the whole path length. The BFBS is the named
//! baseline of the ERBS figures in `docs/benchmarks.md`.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use std::hint::black_box;
use std::time::Duration;
use trajverify::algo::gerbs::bfbs::Bfbs;
use trajverify::algo::gerbs::erbs::{CentreReading, Erbs, ErbsParams};
use trajverify::algo::gerbs::path::{ArcConvention, GerbsPath, PathSpec};
use trajverify::algo::gerbs::quadrature::default_tolerance;
use trajverify::algo::gerbs::{Knots, Side};
use trajverify::scalar::{Float, Real};

/// The report's waypoints, R = 80, θ_o = π/8.
fn spec<T: Real>(ctx: &T::Ctx) -> PathSpec<T> {
    let w = [[0, 0], [300, 100], [600, -50], [900, 150], [1200, 0]];
    PathSpec {
        waypoints: w
            .iter()
            .map(|p| [T::from_i64(p[0], ctx), T::from_i64(p[1], ctx)])
            .collect(),
        radius: T::from_i64(80, ctx),
        theta_o: T::pi(ctx) / &T::from_i64(8, ctx),
        line_length: None,
        convention: ArcConvention::TurnDirection,
        turns: None,
        end_curves: Default::default(),
    }
}

fn bfbs_path<T: Real>(ctx: &T::Ctx) -> GerbsPath<T, Bfbs> {
    GerbsPath::new(&spec(ctx), Bfbs::uniform(2, 5).expect("exponents")).expect("path")
}

/// α = 1, β = 3, γ = 1, λ = 1/2, σ = 1: the report's ERBS paths.
fn erbs_path<T: Real>(ctx: &T::Ctx) -> GerbsPath<T, Erbs<T>> {
    let r = |n: i64, d: i64| T::from_ratio(n, d, ctx);
    let p = ErbsParams::new(r(1, 1), r(3, 1), r(1, 1), r(1, 2), r(1, 1)).expect("params");
    let knots = Knots::uniform(5, ctx).expect("knots");
    let erbs = Erbs::new(&knots, vec![p], CentreReading::Cited).expect("erbs");
    GerbsPath::new(&spec(ctx), erbs).expect("path")
}

fn point(c: &mut Criterion) {
    let mut g = c.benchmark_group("gerbs_path_point");
    g.sample_size(30)
        .measurement_time(Duration::from_secs(2))
        .warm_up_time(Duration::from_millis(500));
    // t = 0.3 lies inside (t_3, t_4) = (1/4, 1/2), before its midpoint.
    let (b64, e64) = (bfbs_path::<f64>(&()), erbs_path::<f64>(&()));
    g.bench_function(BenchmarkId::new("f64", "bfbs"), |b| {
        b.iter(|| b64.at(black_box(&0.3), Side::Right))
    });
    g.bench_function(BenchmarkId::new("f64", "erbs"), |b| {
        b.iter(|| e64.at(black_box(&0.3), Side::Right))
    });
    let t = Float::with_val(256, 0.3);
    let (bm, em) = (bfbs_path::<Float>(&256), erbs_path::<Float>(&256));
    g.bench_function(BenchmarkId::new("mpfr256", "bfbs"), |b| {
        b.iter(|| bm.at(black_box(&t), Side::Right))
    });
    g.bench_function(BenchmarkId::new("mpfr256", "erbs"), |b| {
        b.iter(|| em.at(black_box(&t), Side::Right))
    });
    g.finish();
}

fn length(c: &mut Criterion) {
    let mut g = c.benchmark_group("gerbs_path_length");
    g.sample_size(10)
        .measurement_time(Duration::from_secs(2))
        .warm_up_time(Duration::from_millis(300));
    let tol = default_tolerance::<f64>(&());
    let (b64, e64) = (bfbs_path::<f64>(&()), erbs_path::<f64>(&()));
    g.bench_function(BenchmarkId::new("f64", "bfbs"), |b| {
        b.iter(|| b64.length_within(&tol))
    });
    g.bench_function(BenchmarkId::new("f64", "erbs"), |b| {
        b.iter(|| e64.length_within(&tol))
    });
    g.finish();
}

criterion_group!(benches, point, length);
criterion_main!(benches);
