//! Hermite → Bernstein in 3-D (paper 000): position, velocity and acceleration at two times
//! give the six control points of the quintic that meets them, in f64 and exactly.
//!
//! Run with `cargo run --release --example hermite_bernstein`.

use trajverify::algo::hermite::{hermite_curve, HermiteError};
use trajverify::curve::parametric::{ParamCurve, ParamCurveArclen};
use trajverify::scalar::BigRational;

fn main() -> Result<(), HermiteError> {
    // [position, velocity, acceleration] at t0 = 0 and at t1 = 2.
    let start = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.5], [0.0, 0.0, 0.0]];
    let end = [[2.0, 1.0, 1.0], [0.0, 1.0, 0.0], [0.0, -1.0, 0.0]];
    let fast = hermite_curve(&start, &end, (0.0, 2.0))?;
    println!("f64: degree {} on [0, 2]", fast.degree());
    for (k, p) in fast.control_points().iter().enumerate() {
        println!("  p{k} = {p:?}");
    }
    let mid = fast.point(&1.0).expect("1 lies in [0, 2]");
    let v_end = fast.derivative(&2.0, 1).expect("2 lies in [0, 2]");
    println!("  γ(1) = {mid:?}, γ′(2) = {v_end:?} (the data: [0, 1, 0])");
    println!(
        "  arc length ≈ {:.12} (quadrature)",
        fast.length().expect("in the domain")
    );

    // The same data as exact rationals: the control points are fractions, with no rounding.
    let q = |n: i64, d: i64| BigRational::new(n.into(), d.into());
    let exact_point = |p: [f64; 3]| p.map(|x| q((x * 2.0) as i64, 2));
    let exact = hermite_curve(
        &start.map(exact_point),
        &end.map(exact_point),
        (q(0, 1), q(2, 1)),
    )?;
    println!("exact:");
    for (k, p) in exact.control_points().iter().enumerate() {
        let text: Vec<String> = p.iter().map(ToString::to_string).collect();
        println!("  p{k} = [{}]", text.join(", "));
    }
    Ok(())
}
