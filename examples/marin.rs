//! Marin's optimal parametrization of ten points in space (paper 004): the knots that
//! minimize the bending energy of the natural cubic spline through the points, against
//! normalized chord length, and the spline on those knots.
//!
//! Run with `cargo run --release --example marin`.

use trajverify::algo::param::descent::{parametrize, ParametrizeOptions};
use trajverify::algo::param::natural::{NaturalSplineCurve, SplineError};
use trajverify::curve::parametric::{ParamCurve, ParamCurveArclen};
use trajverify::scalar::Float;

fn main() -> Result<(), SplineError> {
    let points = [
        [0.0, 0.0, 0.0],
        [1.0, 0.5, 0.2],
        [2.0, 2.0, 0.4],
        [2.5, 3.5, 1.0],
        [2.0, 5.0, 1.5],
        [1.0, 5.5, 1.5],
        [0.0, 5.0, 1.0],
        [-0.5, 3.5, 0.8],
        [0.5, 2.5, 1.2],
        [3.0, 2.0, 2.0],
    ];
    // In f64 (every α = 1, Eq. 31).
    let m = parametrize(&points, &ParametrizeOptions::default())?;
    println!(
        "f64 knots: {:?}",
        m.knots
            .iter()
            .map(|t| format!("{t:.6}"))
            .collect::<Vec<_>>()
    );
    println!(
        "G at the minimum {:.10}, at chord length {:.10}",
        m.objective, m.chord_objective
    );
    let curve = NaturalSplineCurve::new(m.knots.clone(), &points)?;
    println!(
        "spline length {:.6}, γ(0.5) = {:?}",
        curve.length().expect("in the domain"),
        curve.point(&0.5).expect("in the domain")
    );

    // The same minimization refined by Newton's method at 256 bits.
    let precise: Vec<[Float; 3]> = points
        .iter()
        .map(|p| p.map(|x| Float::with_val(256, x)))
        .collect();
    let mp = parametrize(&precise, &ParametrizeOptions::default())?;
    println!(
        "MPFR-256 knot t_5 = {}",
        mp.knots[5].to_string_radix(10, Some(40))
    );
    println!(
        "projected gradient norm at 256 bits: {:.3e}",
        mp.projected_gradient_norm.to_f64()
    );
    Ok(())
}
