//! The everyday queries of `curve::query` on library curves, against answers known in
//! closed form: batch evaluation, subsegments, extrema and bounding boxes, nearest points.

use trajverify::algo::ph::piecewise::{fit, FitOptions};
use trajverify::curve::bezier::BezierCurve;
use trajverify::curve::parametric::{ParamCurve, ParamCurveArclen};
use trajverify::curve::query::{bounding_box, extrema, nearest_point, points_at, Subsegment};
use trajverify::curve::ExprCurve;
use trajverify::scalar::{Field, Float};

/// A PH spline of the helix (cos t, sin t, t/5) on [0, 2π], 16 segments: close to the helix
/// (conversion error about 1e-7), so its box and nearest points are the helix's to that.
fn helix_spline() -> trajverify::algo::ph::piecewise::PiecewisePh<f64> {
    let helix = ExprCurve::parse("[cos(t), sin(t), t/5]")
        .expect("a curve")
        .compile::<f64>(&());
    let options = FitOptions {
        segments: 16,
        ..FitOptions::default()
    };
    fit(&helix, (&0.0, &(2.0 * std::f64::consts::PI)), &options).expect("a fit")
}

#[test]
fn the_helix_box_and_extrema_are_found_inside_the_pieces() {
    let spline = helix_spline();
    let (low, high) = bounding_box(&spline).expect("a box");
    let tau = 2.0 * std::f64::consts::PI;
    for (got, want) in low.iter().zip([-1.0, -1.0, 0.0]) {
        assert!((got - want).abs() < 1e-6, "{low:?}");
    }
    for (got, want) in high.iter().zip([1.0, 1.0, tau / 5.0]) {
        assert!((got - want).abs() < 1e-6, "{high:?}");
    }
    // x = cos t is smallest at t = π, inside a piece (not at a sample or a joint's end).
    let e = extrema(&spline).expect("extrema");
    assert!(
        (e[0].min_at - std::f64::consts::PI).abs() < 1e-3,
        "{:?}",
        e[0]
    );
    assert!(
        (e[1].max_at - std::f64::consts::FRAC_PI_2).abs() < 1e-3,
        "{:?}",
        e[1]
    );
}

#[test]
fn the_nearest_point_of_the_helix_to_a_point_on_its_axis() {
    let spline = helix_spline();
    // From (0, 0, z) every point of the helix at height z is at distance 1; the nearest has
    // t = 5z.
    let n = nearest_point(&spline, &[0.0, 0.0, 0.5]).expect("a nearest point");
    assert!((n.t - 2.5).abs() < 1e-3, "{n:?}");
    assert!((n.distance - 1.0).abs() < 1e-6, "{n:?}");
    // Outside the curve's span: the nearest is an end.
    let beyond = nearest_point(&spline, &[1.0, 0.0, -3.0]).expect("a nearest point");
    assert_eq!(beyond.t, 0.0);
    let e = nearest_point(&spline, &[f64::NAN, 0.0, 0.0]).expect_err("NaN");
    assert!(e.to_string().starts_with("q:"), "{e}");
}

#[test]
fn subsegments_keep_the_parameter_and_measure_from_their_start() {
    let spline = helix_spline();
    let part = Subsegment::new(&spline, (1.0, 2.0)).expect("inside the domain");
    assert_eq!(part.domain(), (1.0, 2.0));
    assert_eq!(part.point(&1.5).unwrap(), spline.point(&1.5).unwrap());
    assert!(part.point(&2.5).is_err());
    // The PH spline's exact arc length, from the subsegment's start.
    let length = part.length().expect("a length");
    let whole = spline.arc_length(&2.0).unwrap() - spline.arc_length(&1.0).unwrap();
    assert_eq!(length, whole);
    assert!((length - 1.04f64.sqrt()).abs() < 1e-6);
    // Its break points are the spline's inside [1, 2] (knots at multiples of 2π/16).
    assert!(part.breakpoints().iter().all(|b| *b > 1.0 && *b < 2.0));
    assert_eq!(part.breakpoints().len(), 3);
    for (a, b) in [(2.0, 1.0), (-1.0, 1.0), (1.0, 7.0), (f64::NAN, 1.0)] {
        assert!(Subsegment::new(&spline, (a, b)).is_err(), "[{a}, {b}]");
    }
}

#[test]
fn batch_evaluation_matches_pointwise_and_names_the_bad_parameter() {
    let spline = helix_spline();
    let ts: Vec<f64> = (0..=100).map(|i| f64::from(i) * 0.06).collect();
    let batch = points_at(&spline, &ts).expect("inside the domain");
    for (t, p) in ts.iter().zip(&batch) {
        assert_eq!(*p, spline.point(t).unwrap());
    }
    assert!(points_at(&spline, &[0.5, f64::NAN]).is_err());
    assert!(points_at(&spline, &[7.0]).is_err());
}

/// The same queries in MPFR agree with f64 to f64's precision and with the closed form to
/// MPFR's: a parabola's apex.
#[test]
fn queries_run_in_every_real_number_type() {
    let bits = 200u32;
    let q = |n: i64| Float::from_i64(n, &bits);
    let c = BezierCurve::new(vec![[q(0), q(0)], [q(1), q(2)], [q(2), q(0)]], (q(0), q(1)))
        .expect("a parabola");
    let e = extrema(&c).expect("extrema");
    let apex = Float::from_ratio(1, 2, &bits);
    let off = (e[1].max_at.clone() - &apex).abs().to_f64();
    assert!(off < 1e-55, "{off:e}");
    assert!((e[1].max.clone() - &q(1)).abs().to_f64() < 1e-55);
}

/// Any library curve built in each number type is studied like an expression: a natural
/// spline through Marin's knots (piecewise: sampled, its proven bounds would be unbounded at
/// the knots) and a Bézier curve (one piece: proven).
#[test]
fn library_curves_are_studied_through_their_family() {
    use trajverify::algo::convergence::{study, CurveFamily, Family, Smoothness, StudyOptions};
    use trajverify::algo::param::natural::NaturalSplineCurve;
    use trajverify::curve::interval::Interval;
    use trajverify::scalar::Real;
    struct Plane;
    impl CurveFamily<2> for Plane {
        type Member<T: Real> = NaturalSplineCurve<T, 2>;
        fn build<T: Real>(&self, ctx: &T::Ctx) -> Option<NaturalSplineCurve<T, 2>> {
            let p = |x: i64, y: i64| [T::from_i64(x, ctx), T::from_i64(y, ctx)];
            let knots = [(0, 1), (1, 3), (2, 3), (1, 1)].map(|(n, d)| T::from_ratio(n, d, ctx));
            NaturalSplineCurve::new(knots.to_vec(), &[p(0, 0), p(1, 2), p(3, 3), p(4, 1)]).ok()
        }
        fn smoothness(&self) -> Smoothness {
            Smoothness::Piecewise { continuity: 2 }
        }
    }
    let options = StudyOptions {
        levels: vec![2, 3, 4, 5],
        proof: false,
        ..StudyOptions::default()
    };
    let result = study(&Family(Plane), &Interval::unit(), &options, &mut |_, _| {})
        .expect("a sampled study");
    assert_eq!(result.rows.len(), 4);
    // Each doubling shrinks the error (the cubic pieces' third derivative jumps at the knots).
    for w in result.rows.windows(2) {
        assert!(w[1].value() < w[0].value(), "{:?}", result.rows);
    }
}

/// The largest distance between a PH fit and its target curve, found by the generic query,
/// agrees with the conversion error the library measures its own way (sampled maximum
/// refined by Newton's method on each segment).
#[test]
fn the_largest_distance_between_two_library_curves_is_the_conversion_error() {
    use trajverify::curve::approx::conversion_error;
    use trajverify::curve::parametric::CurveOn;
    use trajverify::curve::query::largest_distance;
    let spline = helix_spline();
    let helix = ExprCurve::parse("[cos(t), sin(t), t/5]")
        .expect("a curve")
        .compile::<f64>(&());
    let tau = 2.0 * std::f64::consts::PI;
    let target = CurveOn::new(&helix, (0.0, tau)).expect("a domain");
    let far = largest_distance(&spline, &target).expect("overlapping domains");
    let measured = conversion_error(&helix, &spline, 16).max;
    // Both are differences of points of size 1 evaluated in f64: they can agree only to the
    // rounding of those points, a few ulps of 1 (the error itself is 5e-9).
    assert!(
        (far.distance - measured).abs() <= 1e-14,
        "{far:?} against {measured:e}"
    );
    let elsewhere = CurveOn::new(&helix, (10.0, 11.0)).expect("a domain");
    assert!(largest_distance(&spline, &elsewhere).is_err());
}
