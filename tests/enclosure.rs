//! The proven enclosure of max‖γ − p‖ (`curve::enclosure`) holds the certified maximum and is
//! narrow, for an analytic curve and for a spline through data (whose seams it must account
//! for: without them the "proof" excludes the true value).

use trajverify::algo::ph::hermite::FreeParameters;
use trajverify::algo::ph::piecewise::{certified_error, convert};
use trajverify::curve::enclosure::proven_error;
use trajverify::curve::{Curve, ExprCurve};
use trajverify::scalar::ball::Ball;
use trajverify::scalar::{BigRational, Field, Float};
const CURVE: &str = "[1.5*sin(7.2*t), cos(9*t), exp(cos(1.8*t))]";

#[test]
fn the_enclosure_contains_the_certified_maximum_and_is_narrow() {
    let c = ExprCurve::parse(CURVE).unwrap();
    let zero = FreeParameters::zero(4, &());
    let (a, b) = (
        BigRational::from_integer(0.into()),
        BigRational::from_integer(1.into()),
    );
    for n in [1usize, 4, 64] {
        let curve = c.compile::<Ball>(&256);
        let pw = convert(
            &curve,
            &Ball::from_i64(0, &256),
            &Ball::from_i64(1, &256),
            n,
            4,
            &FreeParameters::zero(4, &256),
            false,
        )
        .unwrap();
        let e = proven_error(&curve, &pw, 1e-6, 200_000);
        let certified = certified_error(
            |bits| c.compile::<Float>(&bits),
            &a,
            &b,
            n,
            4,
            &zero,
            128,
            256,
        )
        .unwrap();
        eprintln!(
            "n = {n}: [{}, {}] width {:e}, {} boxes; certified {}",
            e.lower,
            e.upper,
            e.relative_width(),
            e.boxes,
            certified.hi
        );
        assert!(
            e.lower <= certified.hi && certified.hi <= e.upper,
            "n = {n}"
        );
        assert!(
            e.relative_width() <= 1e-6,
            "n = {n}: {}",
            e.relative_width()
        );
    }
}

/// A spline that hides its seams: what the enclosure would be told without
/// [`Curve::seam_bound`].
struct SeamsHidden(trajverify::curve::spline::ClampedSpline);

impl Curve<Ball> for SeamsHidden {
    fn jet(&self, t: &Ball, order: usize) -> Vec<[Ball; 3]> {
        self.0.jet(t, order)
    }
}

#[test]
fn a_splines_enclosure_contains_the_certified_maximum_only_with_its_seams() {
    use trajverify::curve::spline::ClampedSpline;
    // 41 samples of a smooth open curve on [0, 2]: 35 interior knots, C⁴ across each.
    let times: Vec<f64> = (0..41).map(|i| f64::from(i) / 20.0).collect();
    let points: Vec<[f64; 3]> = times
        .iter()
        .map(|&t| [t.cos(), (2.0 * t).sin(), t * t / 3.0])
        .collect();
    let spline = ClampedSpline::interpolate(5, &times, &points).unwrap();
    let (a, b) = (
        BigRational::from_integer(0.into()),
        BigRational::from_integer(2.into()),
    );
    let enclose = |n: usize, curve: &dyn Curve<Ball>| {
        let pw = convert(
            curve,
            &Ball::from_i64(0, &256),
            &Ball::from_i64(2, &256),
            n,
            4,
            &FreeParameters::zero(4, &256),
            false,
        )
        .unwrap();
        proven_error(curve, &pw, 1e-6, 200_000)
    };
    let mut hidden_excludes = false;
    for n in [1usize, 8] {
        let certified = certified_error(
            |_| spline.clone(),
            &a,
            &b,
            n,
            4,
            &FreeParameters::zero(4, &()),
            128,
            256,
        )
        .unwrap()
        .hi;
        let e = enclose(n, &spline);
        assert!(
            e.lower <= certified && certified <= e.upper,
            "n = {n}: [{}, {}] misses {certified}",
            e.lower,
            e.upper
        );
        let blind = enclose(n, &SeamsHidden(spline.clone()));
        hidden_excludes |= !(blind.lower <= certified && certified <= blind.upper);
    }
    // Without the seam term the Taylor models run across knots and the "proof" is wrong.
    assert!(hidden_excludes, "the seam term made no difference");
}

#[test]
fn a_hermite_interpolants_enclosure_contains_its_certified_maximum() {
    use trajverify::algo::hermite::piecewise::interpolate_curve;
    use trajverify::curve::approx::certified_max_error;
    let c = ExprCurve::parse("[1.5*sin(7.2*t), cos(9*t), exp(cos(1.8*t))]").unwrap();
    for (m, n) in [(2usize, 1usize), (3, 8), (8, 2)] {
        let certified = certified_max_error(
            |bits| c.compile::<Float>(&bits),
            |curve, bits| {
                let (a, b) = (Float::with_val(bits, 0), Float::with_val(bits, 1));
                interpolate_curve(curve, (&a, &b), n, m)
            },
            128,
            256,
        )
        .unwrap()
        .hi;
        let curve = c.compile::<Ball>(&256);
        let (a, b) = (Ball::from_i64(0, &256), Ball::from_i64(1, &256));
        let fit = interpolate_curve(&curve, (&a, &b), n, m).unwrap();
        let e = proven_error(&curve, &fit, 1e-6, 200_000);
        assert!(
            e.lower <= certified && certified <= e.upper,
            "m = {m}, n = {n}: [{}, {}] misses {certified}",
            e.lower,
            e.upper
        );
        assert!(e.relative_width() <= 1e-6, "m = {m}, n = {n}");
    }
}
