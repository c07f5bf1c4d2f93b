//! A C⁴ Pythagorean-hodograph spline of the helix (cos t, sin t, 0.2 t) on [0, 6] with 32
//! segments (paper 001, Algorithm 2), its Euler–Rodrigues frame, angular velocity and arc
//! length, in f64 and in MPFR at 256 bits.
//!
//! Run with `cargo run --release --example ph_helix`.

use trajverify::algo::ph::hermite::PhHermiteError;
use trajverify::algo::ph::piecewise::{conversion_error, fit, FitOptions, DEFAULT_SAMPLES};
use trajverify::curve::parametric::{ParamCurve, ParamCurveArclen, ParamCurveFrame};
use trajverify::curve::ExprCurve;
use trajverify::scalar::{Float, Real};

const HELIX: &str = "[cos(t), sin(t), 0.2*t]";

/// The fit and what a user reads from it, for any number type.
fn report<T: Real>(label: &str, ctx: &T::Ctx) -> Result<(), PhHermiteError> {
    let helix = ExprCurve::parse(HELIX)
        .expect("a valid expression")
        .compile::<T>(ctx);
    let (a, b) = (T::from_i64(0, ctx), T::from_i64(6, ctx));
    let options = FitOptions {
        segments: 32,
        ..FitOptions::default()
    };
    let spline = fit(&helix, (&a, &b), &options)?;
    let error = conversion_error(&helix, &spline, DEFAULT_SAMPLES).max;
    let t = T::from_ratio(3, 2, ctx);
    let frame = spline.frame(&t).expect("1.5 lies in [0, 6]");
    let length = spline.length().expect("the whole spline");
    println!("{label}:");
    println!(
        "  conversion error E = {:.3e} (sampled maximum)",
        error.to_f64()
    );
    // The spline's length is the exact integral of its polynomial speed (Eq. 13a); the
    // helix's is 6·√1.04. They differ by the approximation, not by rounding.
    let helix_length = T::from_ratio(104, 100, ctx).sqrt() * &b;
    println!("  spline length L    = {:.15}", length.to_f64());
    println!(
        "  L − 6·√1.04        = {:.3e}",
        (length - &helix_length).to_f64()
    );
    println!(
        "  γ(1.5)             = {:?}",
        spline.point(&t).expect("in the domain").map(|x| x.to_f64())
    );
    println!(
        "  e1(1.5)            = {:?}",
        frame.axes[0].clone().map(|x| x.to_f64())
    );
    println!(
        "  ω(1.5) per unit t  = {:?}",
        frame.omega.map(|x| x.to_f64())
    );
    println!("  speed |γ′(1.5)|    = {}", frame.speed.to_f64());
    Ok(())
}

fn main() -> Result<(), PhHermiteError> {
    report::<f64>("f64", &())?;
    report::<Float>("MPFR, 256 bits", &256)
}
