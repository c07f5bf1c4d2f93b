//! A proven enclosure in ball arithmetic: the conversion error E = max‖γ − p‖ (paper 001,
//! Eq. 21) of a 4-segment PH spline of a test curve, bounded from both sides by branch and
//! bound, every quantity a ball of radius bounding its rounding.
//!
//! Run with `cargo run --release --example proven_enclosure`.

use rug::float::Round;
use trajverify::algo::ph::piecewise::{fit, FitOptions};
use trajverify::curve::enclosure::{proven_error, ProofOptions};
use trajverify::curve::ExprCurve;
use trajverify::scalar::ball::{tally, Ball};
use trajverify::scalar::Field;

fn main() {
    let bits = 256;
    let curve = ExprCurve::parse("[1.5*sin(7.2*t), cos(9*t), exp(cos(1.8*t))]")
        .expect("a valid expression")
        .compile::<Ball>(&bits);
    let (a, b) = (Ball::from_i64(0, &bits), Ball::from_i64(1, &bits));
    let options = FitOptions {
        segments: 4,
        roll: false,
        ..FitOptions::default()
    };
    // `tally` counts the comparisons of balls that could not be decided in this computation.
    let (result, undecided) = tally(|| {
        let spline = fit(&curve, (&a, &b), &options).map_err(|e| e.to_string())?;
        proven_error(&curve, &spline, &ProofOptions::default()).map_err(|e| e.to_string())
    });
    let e = match result {
        Ok(e) => e,
        Err(err) => {
            eprintln!("error: {err}");
            std::process::exit(2);
        }
    };
    // Printed rounded outward (the lower bound down, the upper up), so the printed interval
    // still encloses E.
    let lower = e.lower.to_string_radix_round(10, Some(12), Round::Down);
    let upper = e.upper.to_string_radix_round(10, Some(12), Round::Up);
    println!("{lower} ≤ E ≤ {upper}");
    let width = (e.upper.to_f64() - e.lower.to_f64()) / e.lower.to_f64();
    println!(
        "relative width {width:.2e}, {} boxes, segment {}",
        e.boxes, e.segment
    );
    println!("undecided ball comparisons: {undecided}");
}
