//! The hostile calls of issue 38, each under `catch_unwind`: every call that panicked, aborted,
//! hung, or answered NaN, ∞ or finite garbage inside `Ok` now returns the module's error
//! naming the field (or a correct answer, checked).

use std::panic::{catch_unwind, AssertUnwindSafe};
use trajverify::algo::convergence::{study, Method, StudyOptions};
use trajverify::algo::gerbs::bfbs::Bfbs;
use trajverify::algo::gerbs::erbs::{CentreReading, Erbs, ErbsParams};
use trajverify::algo::gerbs::path::{GerbsPath, PathSpec};
use trajverify::algo::gerbs::{Knots, Side};
use trajverify::curve::interval::Interval;
use trajverify::curve::parametric::ParamCurve;

/// Run `f`, failing the test with `what` if it panics.
fn no_panic<R>(what: &str, f: impl FnOnce() -> R) -> R {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(r) => r,
        Err(_) => panic!("{what} panicked"),
    }
}

/// The five waypoints about 1.2 km long, R = 80.
fn waypoints() -> Vec<[f64; 2]> {
    vec![
        [0.0, 0.0],
        [300.0, 100.0],
        [600.0, -50.0],
        [900.0, 150.0],
        [1200.0, 0.0],
    ]
}

fn bfbs_path() -> GerbsPath<f64, Bfbs> {
    let spec = PathSpec::new(waypoints(), 80.0, &());
    GerbsPath::new(&spec, Bfbs::uniform(2, 5).expect("exponents")).expect("a path")
}

/// The error's message, which must name the field.
fn message<T, E: std::fmt::Display>(r: Result<T, E>) -> String {
    match r {
        Ok(_) => String::from("Ok"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn gerbs_indices_counts_and_intervals_are_checked() {
    let path = bfbs_path();
    // Indices count from 0: knots 0 … 6, intervals 0 … 5 (0 and 5 empty: doubled ends).
    let e = message(no_panic("at_on(0.3, 99)", || path.at_on(&0.3, 99)));
    assert!(e.starts_with("interval:"), "{e}");
    let e = message(no_panic("at_on(0.3, 0)", || path.at_on(&0.3, 0)));
    assert!(e.starts_with("interval:") && e.contains("empty"), "{e}");
    let e = message(no_panic("at_on(0.9, 2)", || path.at_on(&0.9, 2)));
    assert!(e.starts_with("t:"), "t outside interval 2 answered: {e}");
    assert!(no_panic("at_on(NaN, 2)", || path.at_on(&f64::NAN, 2)).is_err());
    let e = message(no_panic("at_knot(99)", || path.at_knot(99, Side::Left)));
    assert!(e.starts_with("knot:"), "{e}");
    let e = message(no_panic("at_knot(7)", || path.at_knot(7, Side::Right)));
    assert!(e.starts_with("knot:") && e.contains("0 to 6"), "{e}");
    let e = message(no_panic("series_on(0.3, 6)", || path.series_on(&0.3, 6, 2)));
    assert!(e.starts_with("interval:"), "{e}");
    let e = message(no_panic("sample(usize::MAX)", || path.sample(usize::MAX)));
    assert!(e.starts_with("count:"), "{e}");
    // The answers inside the ranges: W1 at knot 0 (t = 0) and W2 at knot 2 (t = 1/4); the
    // point at 0.3 on interval 2 is the path's point there.
    let w1 = path.at_knot(0, Side::Right).expect("knot 0");
    assert!(
        w1.point[0].abs() < 1e-9 && w1.point[1].abs() < 1e-9,
        "{:?}",
        w1.point
    );
    let on = path.at_on(&0.3, 2).expect("interval 2");
    assert_eq!(on.point, path.point(&0.3).expect("inside"));
    let w2 = path.at_knot(2, Side::Right).expect("knot 2");
    assert!((w2.point[0] - 300.0).abs() < 1e-9 && (w2.point[1] - 100.0).abs() < 1e-9);
    assert_eq!(path.sample(11).expect("11 samples").len(), 11);
}

#[test]
fn gerbs_refuses_a_basis_built_on_other_knots() {
    let spec = PathSpec::new(waypoints(), 80.0, &());
    let params = ErbsParams::new(1.0, 3.0, 1.0, 0.5, 1.0).expect("parameters");
    // Knots of three waypoints, a path of five.
    let other = Knots::uniform(3, &()).expect("knots");
    let erbs = Erbs::new(&other, vec![params], CentreReading::Cited).expect("a basis");
    let e = message(no_panic("GerbsPath::new with foreign ERBS", || {
        GerbsPath::new(&spec, erbs)
    }));
    assert!(e.starts_with("blend:"), "{e}");
}

#[test]
fn gerbs_radius_turns_and_extreme_waypoints_are_errors_not_garbage() {
    let huge = PathSpec::new(waypoints(), 1e6, &());
    let e = message(no_panic("radius 1e6", || {
        GerbsPath::new(&huge, Bfbs::uniform(2, 5).unwrap())
    }));
    assert!(e.starts_with("radius:"), "{e}");
    let mut turns = PathSpec::new(waypoints(), 80.0, &());
    turns.turns = Some(vec![0, 7, 0, -9, 0]);
    let e = message(no_panic("turns [0, 7, 0, -9, 0]", || {
        GerbsPath::new(&turns, Bfbs::uniform(2, 5).unwrap())
    }));
    assert!(e.starts_with("turns:"), "{e}");
    let far: Vec<[f64; 2]> = waypoints()
        .iter()
        .map(|w| [w[0] * 1e300, w[1] * 1e300 + 1e300])
        .collect();
    let spec = PathSpec::new(far, 80.0, &());
    let r = no_panic("waypoints near 1e300", || {
        GerbsPath::new(&spec, Bfbs::uniform(2, 5).unwrap())
    });
    if let Ok(path) = r {
        let s = no_panic("sample", || path.sample(101));
        assert!(s.is_err() || s.unwrap().iter().all(|p| p.curvature.is_finite()));
    }
    let tiny = PathSpec::new(waypoints(), 1e-300, &());
    if let Ok(path) = no_panic("radius 1e-300", || {
        GerbsPath::new(&tiny, Bfbs::uniform(2, 5).unwrap())
    }) {
        for t in [0.1, 0.25, 0.5, 0.9] {
            if let Ok(p) = no_panic("at", || path.at(&t, Side::Right)) {
                assert!(
                    p.curvature.is_finite() && p.point.iter().all(|x| x.is_finite()),
                    "t = {t}: {p:?}"
                );
            }
        }
    }
}

#[test]
fn erbs_with_fractional_sigma_refuses_the_kernel_centre() {
    let spec = PathSpec::new(waypoints(), 80.0, &());
    let knots = Knots::uniform(5, &()).expect("knots");
    let params = ErbsParams::new(1.0, 3.0, 1.0, 0.5, 0.2).expect("parameters");
    let erbs = Erbs::new(&knots, vec![params], CentreReading::Cited).expect("a basis");
    let path = GerbsPath::new(&spec, erbs).expect("a path");
    // The centre of [1/4, 1/2] is 3/8: the curvature is unbounded there.
    let r = no_panic("curvature at the centre", || path.at(&0.375, Side::Right));
    match r {
        Ok(p) => assert!(p.curvature.is_finite(), "Ok holding {p:?}"),
        Err(e) => assert!(e.to_string().starts_with("t:"), "{e}"),
    }
}

#[test]
fn derivative_orders_are_bounded() {
    use trajverify::curve::bezier::BezierCurve;
    let line = BezierCurve::new(vec![[0.0, 0.0], [1.0, 1.0]], (0.0, 1.0)).expect("a line");
    for order in [usize::MAX, 1_000_000_000] {
        let e = message(no_panic("derivatives", || line.derivatives(&0.5, order)));
        assert!(e.starts_with("order:"), "{e}");
    }
    assert_eq!(line.derivatives(&0.5, 3).expect("order 3").len(), 4);
}

#[test]
fn constructors_refuse_nan_and_infinite_data() {
    use trajverify::algo::hermite::hermite_curve;
    use trajverify::algo::param::natural::NaturalSplineCurve;
    use trajverify::curve::bezier::BezierCurve;
    assert!(no_panic("Bezier NaN", || BezierCurve::new(
        vec![[0.0, f64::NAN]],
        (0.0, 1.0)
    ))
    .is_err());
    for bad in [f64::NAN, f64::INFINITY] {
        let start = [[0.0, 0.0], [bad, 0.0]];
        let end = [[1.0, 1.0], [0.0, 1.0]];
        assert!(no_panic("hermite_curve", || hermite_curve(&start, &end, (0.0, 1.0))).is_err());
        let knots = vec![0.0, bad, 2.0];
        let points = [[0.0], [1.0], [0.0]];
        assert!(no_panic("spline knot", || NaturalSplineCurve::new(knots, &points)).is_err());
        let points = [[0.0], [bad], [0.0]];
        assert!(no_panic("spline point", || NaturalSplineCurve::new(
            vec![0.0, 1.0, 2.0],
            &points
        ))
        .is_err());
    }
}

#[test]
fn conversions_cap_their_segments_and_check_their_arguments() {
    use trajverify::algo::hermite::piecewise::{interpolate_curve, InterpolationOptions};
    use trajverify::algo::ph::piecewise::{fit, FitOptions};
    use trajverify::curve::enclosure::{proven_error, ProofOptions};
    use trajverify::curve::ExprCurve;
    use trajverify::scalar::ball::Ball;
    use trajverify::scalar::Field;
    let helix = ExprCurve::parse("[cos(t), sin(t), t/5]").expect("a curve");
    let c = helix.compile::<f64>(&());
    for segments in [1_000_000_000, usize::MAX] {
        let options = FitOptions {
            segments,
            ..FitOptions::default()
        };
        let e = message(no_panic("fit", || fit(&c, (&0.0, &1.0), &options)));
        assert!(e.starts_with("segments:"), "{e}");
    }
    let e = message(no_panic("interpolate_curve", || {
        interpolate_curve(
            &c,
            (&0.0, &1.0),
            &InterpolationOptions {
                segments: usize::MAX,
                derivatives: 2,
            },
        )
    }));
    assert!(e.starts_with("segments:"), "{e}");
    let cb = helix.compile::<Ball>(&128);
    let (a, b) = (Ball::from_i64(0, &128), Ball::from_i64(1, &128));
    let pw = fit(
        &cb,
        (&a, &b),
        &FitOptions {
            segments: 2,
            ..FitOptions::default()
        },
    )
    .expect("a fit");
    for target in [f64::NAN, -1.0, 0.0] {
        let e = message(no_panic("proven_error", || {
            proven_error(
                &cb,
                &pw,
                &ProofOptions {
                    target,
                    max_boxes: 1000,
                    ..ProofOptions::default()
                },
            )
        }));
        assert!(e.starts_with("target:"), "target {target}: {e}");
    }
}

#[test]
fn piecewise_ph_locate_and_clamped_splines_check_their_input() {
    use trajverify::algo::ph::piecewise::{fit, FitOptions};
    use trajverify::curve::spline::ClampedSpline;
    use trajverify::curve::ExprCurve;
    let c = ExprCurve::parse("[cos(t), sin(t), t]")
        .expect("a curve")
        .compile::<f64>(&());
    let pw = fit(
        &c,
        (&0.0, &1.0),
        &FitOptions {
            segments: 8,
            ..FitOptions::default()
        },
    )
    .expect("a fit");
    assert!(no_panic("locate(NaN)", || pw.locate(&f64::NAN)).is_err());
    assert!(no_panic("locate(2)", || pw.locate(&2.0)).is_err());
    let (k, xi) = pw.locate(&0.5).expect("inside");
    assert!(k == 4 && xi.abs() < 1e-12);
    let times = [0.0, 1.0, 2.0, 3.0, 4.0, 5.0];
    let points = [[0.0; 3]; 6];
    assert!(no_panic("even degree", || ClampedSpline::interpolate(
        4, &times, &points
    ))
    .is_err());
    let nan_times = [0.0, f64::NAN, 2.0, 3.0, 4.0, 5.0];
    assert!(no_panic("NaN time", || ClampedSpline::interpolate(
        3, &nan_times, &points
    ))
    .is_err());
}

#[test]
fn studies_check_precision_and_method() {
    use trajverify::curve::ExprCurve;
    let curve = ExprCurve::parse("[sin(3*t), cos(2*t), t^2]").expect("a curve");
    for (bits, method) in [
        (0, Method::Phodcos),
        (1, Method::Phodcos),
        (1_000_000, Method::Phodcos),
        (128, Method::Hermite(100)),
    ] {
        let options = StudyOptions {
            method,
            levels: vec![0, 1],
            bits,
            proof: false,
        };
        let r = no_panic("study", || {
            study(&curve, &Interval::unit(), &options, &mut |_, _| {})
        });
        let e = message(r);
        assert!(
            e.starts_with("bits:") || e.starts_with("method:"),
            "bits {bits}, {method:?}: {e}"
        );
    }
}

#[test]
fn marins_parametrization_refuses_bad_points_and_ignores_scale() {
    use trajverify::algo::param::descent::{parametrize, ParametrizeOptions};
    let default = ParametrizeOptions::default();
    let repeated = [[0.0, 0.0], [1.0, 2.0], [1.0, 2.0], [4.0, 1.0]];
    let e = message(no_panic("repeated", || parametrize(&repeated, &default)));
    assert!(e.starts_with("points:"), "{e}");
    let nan = [[0.0, 0.0], [f64::NAN, 2.0], [3.0, 3.0]];
    assert!(message(no_panic("NaN", || parametrize(&nan, &default))).contains("not finite"));
    let zero_alpha = ParametrizeOptions {
        alpha: Some(vec![0.0, 1.0]),
        ..ParametrizeOptions::default()
    };
    let points = [[0.0, 0.0], [1.0, 2.0], [3.0, 3.0], [4.0, 1.0]];
    let e = message(no_panic("α = 0", || parametrize(&points, &zero_alpha)));
    assert!(e.starts_with("alpha:"), "{e}");
    let many: Vec<[f64; 2]> = (0..3000)
        .map(|i| [i as f64, ((i * 7) % 13) as f64])
        .collect();
    let e = message(no_panic("3000 points", || parametrize(&many, &default)));
    assert!(e.starts_with("points:"), "{e}");
    // The knots end at 0 and 1 exactly, and do not depend on the points' scale.
    let unit = parametrize(&points, &default).expect("four points");
    assert_eq!((unit.knots[0], unit.knots[3]), (0.0, 1.0));
    // The result says whether the minimization converged; a budget of one iteration of the
    // descent is reported as not converged, with increasing knots from the last iterate.
    assert!(unit.converged(), "{unit:?}");
    let wavy: Vec<[f64; 2]> = (0..40)
        .map(|i| [f64::from(i), f64::from((i * 7) % 13)])
        .collect();
    let budget = ParametrizeOptions {
        max_iterations: 1,
        ..ParametrizeOptions::default()
    };
    let cut = parametrize(&wavy, &budget).expect("a budget is not an error");
    assert!(!cut.descent_converged && !cut.converged(), "{cut:?}");
    assert_eq!(cut.descent_iterations, 1);
    assert!(cut.knots.windows(2).all(|w| w[0] < w[1]));
    assert!(parametrize(&wavy, &default).expect("40 points").converged());
    for s in [1e-200, 1e200] {
        let scaled: Vec<[f64; 2]> = points.iter().map(|p| [p[0] * s, p[1] * s]).collect();
        let m = parametrize(&scaled, &default).expect("scaled points");
        for (a, b) in m.knots.iter().zip(&unit.knots) {
            assert!(
                (a - b).abs() < 1e-9,
                "scale {s}: {:?} against {:?}",
                m.knots,
                unit.knots
            );
        }
    }
}

#[test]
fn fits_name_the_derivatives_and_refuse_overflow() {
    use trajverify::algo::ph::piecewise::{fit, FitOptions};
    use trajverify::curve::ExprCurve;
    let helix = ExprCurve::parse("[cos(t), sin(t), t]")
        .expect("a curve")
        .compile::<f64>(&());
    let options = FitOptions {
        derivatives: 20,
        ..FitOptions::default()
    };
    let e = message(no_panic("derivatives 20", || {
        fit(&helix, (&0.0, &1.0), &options)
    }));
    assert!(e.starts_with("derivatives:"), "{e}");
    let huge = ExprCurve::parse("[1e200*cos(t), 1e200*sin(t), t]")
        .expect("a curve")
        .compile::<f64>(&());
    let r = no_panic("1e200 curve", || {
        fit(&huge, (&0.0, &1.0), &FitOptions::default())
    });
    match r {
        Ok(pw) => {
            let p = pw.point(&0.5).expect("inside");
            assert!(p.iter().all(|x| x.is_finite()), "Ok holding {p:?}");
        }
        Err(e) => assert!(
            e.to_string().contains("overflow") || e.to_string().contains("not finite"),
            "{e}"
        ),
    }
    let pw = fit(&helix, (&0.0, &1.0), &FitOptions::default()).expect("a fit");
    let e = message(no_panic("knot(1000)", || pw.knot(1000)));
    assert!(e.starts_with("k:"), "{e}");
    assert_eq!(pw.knot(8).expect("the last knot"), 1.0);
}

#[test]
fn curvature_at_zero_speed_and_inverse_arc_length_are_errors_not_nan() {
    use trajverify::curve::bezier::BezierCurve;
    use trajverify::curve::parametric::{curvature, ParamCurveArclen};
    // A cubic with a cusp: γ′(1/2) = 0.
    let cusp = BezierCurve::new(
        vec![[0.0, 0.0], [1.0, 1.0], [0.0, 1.0], [1.0, 0.0]],
        (0.0, 1.0),
    )
    .expect("a cubic");
    let r = no_panic("curvature at the cusp", || curvature(&cusp, &0.5));
    match r {
        Ok(k) => assert!(k.is_finite(), "Ok holding {k}"),
        Err(e) => assert!(e.to_string().starts_with("t:"), "{e}"),
    }
    let line = BezierCurve::new(vec![[0.0, 0.0], [3.0, 4.0]], (0.0, 1.0)).expect("a line");
    for s in [f64::NAN, -1.0, 6.0] {
        let e = message(no_panic("parameter_at_length", || {
            line.parameter_at_length(&s, &1e-12)
        }));
        assert!(e.starts_with("s:"), "s = {s}: {e}");
    }
    let e = message(no_panic("tolerance 0", || {
        line.parameter_at_length(&1.0, &0.0)
    }));
    assert!(e.starts_with("tolerance:"), "{e}");
    let t = line.parameter_at_length(&2.5, &1e-12).expect("inside");
    assert!((t - 0.5).abs() < 1e-12);
}

#[test]
fn every_library_curve_can_be_fitted_through_the_adapter() {
    use trajverify::algo::gerbs::erbs::ErbsParams;
    use trajverify::algo::ph::piecewise::{conversion_error, fit, FitOptions, DEFAULT_SAMPLES};
    use trajverify::curve::adapter::AsCurve;
    use trajverify::curve::taylor::Taylor;
    assert!(Taylor::<f64>::from_coeffs(vec![]).is_none());
    let params = ErbsParams::<f64>::default();
    assert_eq!(
        (*params.alpha(), *params.sigma(), *params.lambda()),
        (1.0, 1.0, 0.5)
    );
    // The GERBS path (2-D, C² with the BFBS) fitted by a C² PH spline in z = 0.
    let path = bfbs_path();
    let adapted = AsCurve::new(&path);
    let options = FitOptions {
        segments: 16,
        derivatives: 2,
        ..FitOptions::default()
    };
    let pw = fit(&adapted, (&0.0, &1.0), &options).expect("a fit of the path");
    let e = conversion_error(&adapted, &pw, DEFAULT_SAMPLES).max;
    assert!(e.is_finite() && e < 10.0, "E = {e}");
    // Outside the path's domain the adapter's jet is NaN, which the conversion refuses.
    assert!(fit(&adapted, (&0.0, &2.0), &options).is_err());
}
