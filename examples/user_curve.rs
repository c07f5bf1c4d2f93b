//! A curve written in Rust — one generic function of t — through the whole pipeline: a C⁴ PH
//! spline fitted to it (f64), the spline's conversion error proven in ball arithmetic, a
//! convergence study over the closed curve's period [0, 2π] (proven errors on 4 … 64 segments,
//! the observed order against Theorem 1's six), and a library curve of another kind (a plane Bézier curve) fitted through the same
//! interface. The derivatives the fit needs come from the library's Taylor scalar: nothing is
//! differentiated by hand.
//!
//! Run with `cargo run --release --example user_curve`.

use rug::float::Round;
use trajverify::algo::convergence::{study, StudyOptions};
use trajverify::algo::ph::piecewise::{fit, FitOptions};
use trajverify::curve::adapter::AsCurve;
use trajverify::curve::bezier::BezierCurve;
use trajverify::curve::enclosure::{proven_error, ProofOptions};
use trajverify::curve::function::{CurveFn, FnCurve};
use trajverify::curve::interval::Interval;
use trajverify::curve::parametric::ParamCurve;
use trajverify::report::number::bound;
use trajverify::scalar::{ball::Ball, Field, Real};

/// A trefoil-like space curve: (sin t + 2 sin 2t, cos t − 2 cos 2t, −sin 3t) / 3.
struct Trefoil;

impl CurveFn for Trefoil {
    fn at<R: Real>(&self, t: &R) -> [R; 3] {
        let ctx = t.ctx();
        let k = |n: i64| R::from_i64(n, &ctx);
        let third = R::from_ratio(1, 3, &ctx);
        let (t2, t3) = (t.clone() * &k(2), t.clone() * &k(3));
        [
            (t.sin() + &(k(2) * &t2.sin())) * &third,
            (t.cos() - &(k(2) * &t2.cos())) * &third,
            -(t3.sin()) * &third,
        ]
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let curve = FnCurve(Trefoil);

    // 1. A PH spline of 16 segments on [0, 2], in f64.
    let options = FitOptions {
        segments: 16,
        ..FitOptions::default()
    };
    let spline = fit(&curve, (&0.0, &2.0), &options)?;
    let p = spline.point(&1.0)?;
    println!(
        "PH spline, 16 segments: p(1) = ({:.6}, {:.6}, {:.6})",
        p[0], p[1], p[2]
    );

    // 2. The same fit in balls, and its conversion error proven by branch and bound.
    let (a, b) = (Ball::from_i64(0, &128), Ball::from_i64(2, &128));
    let proven = fit(
        &curve,
        (&a, &b),
        &FitOptions {
            segments: 16,
            ..FitOptions::default()
        },
    )?;
    let e = proven_error(
        &curve,
        &proven,
        &ProofOptions {
            target: 1e-3,
            ..ProofOptions::default()
        },
    )?;
    // Bounds printed rounded outward, so the printed interval still encloses E.
    let lower = bound(e.lower.to_f64_round(Round::Down), 5, Round::Down);
    let upper = bound(e.upper.to_f64_round(Round::Up), 5, Round::Up);
    println!("proven conversion error: {lower} ≤ E ≤ {upper}");

    // 3. A convergence study over the whole closed curve, t in [0, 2π]: proven errors on
    //    4, 8, …, 64 segments and the observed order. The end 2π is exact in the interval
    //    and enclosed in a ball for the proof.
    let whole = Interval::parse("0", "2*pi")?;
    let study_options = StudyOptions {
        levels: (2..=6).collect(),
        ..StudyOptions::default()
    };
    let result = study(&curve, &whole, &study_options, &mut |_, _| {})?;
    for (row, order) in result.rows.iter().zip(&result.orders).skip(1) {
        match order.as_ref().and_then(|o| o.proven) {
            Some((lo, hi)) => println!(
                "  {:>2} segments: observed order in [{}, {}]",
                row.segments,
                bound(lo, 4, Round::Down),
                bound(hi, 4, Round::Up)
            ),
            None => println!("  {:>2} segments: order not resolved", row.segments),
        }
    }
    println!(
        "  expected: {} ({})",
        result.expected.order, result.expected.reason
    );

    // 4. Another library curve through the same interface: a plane cubic Bézier curve.
    let k = 0.5522847498;
    let arc = BezierCurve::new(vec![[1.0, 0.0], [1.0, k], [k, 1.0], [0.0, 1.0]], (0.0, 1.0))?;
    let ph = fit(
        &AsCurve::new(&arc),
        (&0.0, &1.0),
        &FitOptions {
            segments: 4,
            ..FitOptions::default()
        },
    )?;
    let (x, y) = (ph.point(&0.3)?, arc.point(&0.3)?);
    println!(
        "PH spline of a Bézier quarter circle at t = 0.3: |Δ| = {:.2e}",
        (x[0] - y[0]).hypot(x[1] - y[1])
    );
    Ok(())
}
