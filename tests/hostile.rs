//! Hostile calls of the public API, each under `catch_unwind`: a call must return an error (or
//! a documented answer), never panic, and never return `Ok` holding NaN.
//!
//! Every call found by trying the library as an engineer would. Struct literals of
//! `Bernstein`, `BezierCurve`, `PiecewisePh`, `PiecewiseBernstein`, `GerbsPath`, `SplineFit`,
//! `NaturalSplineCurve`, the Hermite data of paper 000 and the data splines no longer compile
//! (their fields are private); PH Hermite data and `PathSpec`, option-like records, keep
//! public fields and are re-checked where they are used. The one panic left
//! by design is `from_ratio(n, 0)` in the exact types (as `i64` division by zero), whose
//! fallible form `try_from_ratio` is tested here.

use std::panic::{catch_unwind, AssertUnwindSafe};
use trajverify::algo::gerbs::bfbs::Bfbs;
use trajverify::algo::gerbs::path::{ArcConvention, EndCurves, GerbsPath, PathSpec};
use trajverify::algo::gerbs::Side;
use trajverify::algo::param::descent::{descend, refine};
use trajverify::algo::param::objective::{chord_length_spacing, Objective};
use trajverify::algo::ph::hermite::{FreeParameters, PhHermiteError};
use trajverify::algo::ph::piecewise::{conversion_error, convert, DEFAULT_SAMPLES};
use trajverify::algo::ph::PhCurve;
use trajverify::curve::ExprCurve;
use trajverify::numeric::poly::Bernstein;
use trajverify::scalar::ball::Ball;
use trajverify::scalar::BigRational;
use trajverify::scalar::{Field, Float};
use trajverify::HermiteData;

/// Run `f`, failing the test with `what` if it panics.
fn no_panic<R>(what: &str, f: impl FnOnce() -> R) -> R {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(r) => r,
        Err(_) => panic!("{what} panicked"),
    }
}

#[test]
fn precisions_outside_mpfr_range_are_clamped_not_fatal() {
    let x = no_panic("Float::from_i64(1, &0)", || Float::from_i64(1, &0));
    assert_eq!(x, 1);
    let b = no_panic("Ball::from_i64(1, &0)", || Ball::from_i64(1, &0));
    assert!(b.is_finite());
}

#[test]
fn a_nan_double_is_no_exact_ball() {
    let b = no_panic("Ball::from_f64(NaN)", || Ball::from_f64(f64::NAN, &64));
    assert!(!b.is_finite(), "NaN became the finite ball {b:?}");
}

#[test]
fn hermite_data_refuse_a_nan_or_reversed_interval() {
    for (t0, t1) in [(0.0, f64::NAN), (f64::NAN, 1.0), (1.0, 1.0), (1.0, 0.0)] {
        let r = no_panic("HermiteData::new", || {
            HermiteData::new(vec![0.0], vec![1.0], (t0, t1))
        });
        assert!(r.is_err(), "[{t0}, {t1}] accepted");
    }
}

#[test]
fn ph_conversion_refuses_bad_segments_intervals_and_undefined_curves() {
    let helix = ExprCurve::parse("[cos(t), sin(t), t/5]").expect("parses");
    let free = FreeParameters::<f64>::zero(4, &());
    let run = |curve: &ExprCurve, a: f64, b: f64, n: usize| {
        let compiled = curve.compile::<f64>(&());
        no_panic("convert", || {
            convert(&compiled, (&a, &b), n, 4, &free, true)
        })
    };
    assert!(matches!(
        run(&helix, 0.0, 1.0, 0),
        Err(PhHermiteError::NoSegments)
    ));
    for (a, b) in [(1.0, 1.0), (1.0, 0.0), (0.0, f64::NAN)] {
        assert!(
            matches!(run(&helix, a, b, 4), Err(PhHermiteError::Interval)),
            "[{a}, {b}]"
        );
    }
    let undefined = ExprCurve::parse("[sqrt(t - 10), t, 0]").expect("parses");
    assert!(matches!(
        run(&undefined, 0.0, 1.0, 4),
        Err(PhHermiteError::NotFinite(_))
    ));
    assert!(run(&helix, 0.0, 1.0, 4).is_ok());
}

#[test]
fn marin_entry_points_check_their_shapes() {
    let empty: Vec<Vec<f64>> = vec![];
    assert!(no_panic("chord_length_spacing(&[])", || chord_length_spacing(&empty)).is_empty());
    let one = vec![vec![1.0]];
    assert!(no_panic("one point", || chord_length_spacing(&one)).is_empty());
    let same = vec![vec![2.0, 2.0, 2.0]];
    let h = no_panic("coincident points", || chord_length_spacing(&same));
    assert_eq!(h, vec![0.5, 0.5]);

    let descend_with = |h: Vec<f64>, z: &[Vec<f64>], alpha: &[f64]| {
        no_panic("descend", || {
            descend(h, z, alpha, Objective::Exact, &mut |_, _| {})
        })
    };
    assert!(descend_with(vec![], &empty, &[]).is_err(), "no points");
    assert!(descend_with(vec![], &one, &[1.0]).is_err(), "one point");
    let z = vec![vec![0.0, 1.0, 3.0, 4.0], vec![0.0, 2.0, 3.0, 1.0]];
    assert!(
        descend_with(vec![0.5; 3], &z, &[1.0]).is_err(),
        "one α for two components"
    );
    assert!(
        descend_with(vec![0.5; 2], &z, &[1.0, 1.0]).is_err(),
        "too few spacings"
    );
    let rough = descend_with(chord_length_spacing(&z), &z, &[1.0, 1.0]).expect("descends");
    let refined = no_panic("refine with no points", || {
        refine(&rough, &empty, &[], Objective::Exact)
    });
    assert!(refined.is_err());
    let refined = refine(&rough, &z, &[1.0, 1.0], Objective::Exact).expect("refines");
    assert!(refined.knots.iter().all(|t| t.is_finite()));
}

#[test]
fn bernstein_polynomials_need_points_and_an_interval() {
    assert!(no_panic("empty", || Bernstein::<f64>::new(vec![], (0.0, 1.0))).is_err());
    let q = |n: i64| BigRational::from_integer(n.into());
    assert!(no_panic("t0 = t1", || Bernstein::new(vec![q(1)], (q(1), q(1)))).is_err());
    assert!(no_panic("NaN", || Bernstein::new(vec![1.0], (0.0, f64::NAN))).is_err());
    // Hermite data with no points, or of unequal lengths, are refused (their fields are
    // private: no struct literal skips `new`).
    assert!(no_panic("empty data", || HermiteData::<f64>::new(
        vec![],
        vec![],
        (0.0, 1.0)
    ))
    .is_err());
    let r = no_panic("ragged data", || {
        HermiteData::new(vec![0.0, 1.0], vec![1.0], (0.0, 1.0))
    });
    assert!(r.is_err());
}

#[test]
fn a_ph_curve_needs_a_preimage() {
    let r = no_panic("PhCurve::new(vec![])", || {
        PhCurve::<f64>::new(vec![], [0.0; 3])
    });
    assert!(r.is_err());
}

#[test]
fn a_gerbs_path_is_evaluated_on_its_knots_only() {
    let spec = PathSpec {
        waypoints: vec![[0.0, 0.0], [300.0, 100.0], [600.0, -50.0]],
        radius: 80.0,
        theta_o: std::f64::consts::FRAC_PI_8,
        line_length: None,
        convention: ArcConvention::TurnDirection,
        turns: None,
        end_curves: EndCurves::default(),
    };
    let path = GerbsPath::new(&spec, Bfbs::uniform(2, 3).expect("exponents")).expect("a path");
    for t in [2.0, -0.5, f64::NAN] {
        let r = no_panic("GerbsPath::at", || path.at(&t, Side::Right));
        assert!(r.is_err(), "t = {t} answered");
    }
    let inside = path.at(&0.3, Side::Right).expect("inside");
    assert!(inside.curvature.is_finite() && inside.point.iter().all(|x| x.is_finite()));
}

#[test]
fn marins_parametrization_of_points_checks_its_options() {
    use trajverify::algo::param::descent::{parametrize, ParametrizeOptions};
    use trajverify::algo::param::natural::NaturalSplineCurve;
    use trajverify::curve::parametric::ParamCurve;
    let points = [[0.0, 0.0], [1.0, 2.0], [3.0, 3.0], [4.0, 1.0]];
    let wrong_alpha = ParametrizeOptions {
        alpha: Some(vec![1.0]),
        ..ParametrizeOptions::default()
    };
    assert!(no_panic("one α for two coordinates", || parametrize(
        &points,
        &wrong_alpha
    ))
    .is_err());
    // Ragged points no longer type-check: every point is a [T; D].
    let default = ParametrizeOptions::default();
    assert!(no_panic("one point", || parametrize(&points[..1], &default)).is_err());
    let none: [[f64; 0]; 3] = [[], [], []];
    assert!(no_panic("D = 0", || parametrize(&none, &default)).is_err());
    let repeated = [[0.0, 0.0], [1.0, 2.0], [1.0, 2.0], [4.0, 1.0]];
    if let Ok(m) = no_panic("repeated point", || parametrize(&repeated, &default)) {
        assert!(
            m.knots.iter().all(|t| t.is_finite()),
            "Ok holding NaN: {:?}",
            m.knots
        );
    }
    let m = parametrize(&points, &default).expect("four distinct points");
    assert!(m.knots.iter().all(|t| t.is_finite()));
    // The spline through the points: lengths and order checked, evaluation on its knots only.
    let curve = |k: Vec<f64>, p: &[[f64; 2]]| {
        no_panic("NaturalSplineCurve::new", || NaturalSplineCurve::new(k, p))
    };
    assert!(
        curve(m.knots.clone(), &points[..3]).is_err(),
        "3 points, 4 knots"
    );
    assert!(
        curve(vec![0.0, 1.0, 1.0, 2.0], &points).is_err(),
        "repeated knot"
    );
    assert!(curve(vec![0.0], &points[..1]).is_err(), "one knot");
    let spline = curve(m.knots.clone(), &points).expect("a spline");
    for t in [-0.1, 1.1, f64::NAN] {
        assert!(no_panic("point", || spline.point(&t)).is_err(), "t = {t}");
    }
    assert!(spline
        .point(&0.5)
        .expect("inside")
        .iter()
        .all(|x| x.is_finite()));
}

#[test]
fn exact_ratios_with_a_zero_denominator_are_refused_not_fatal() {
    use trajverify::scalar::qsqrt2::QSqrt2;
    assert_eq!(
        no_panic("BigRational 1/0", || BigRational::try_from_ratio(1, 0, &())),
        None
    );
    assert_eq!(
        no_panic("QSqrt2 1/0", || QSqrt2::try_from_ratio(1, 0, &())),
        None
    );
    assert_eq!(
        BigRational::try_from_ratio(3, 4, &()),
        Some(BigRational::new(3.into(), 4.into()))
    );
    // The floating types: IEEE ±∞ / NaN, and the ball of every number.
    assert_eq!(
        no_panic("f64 1/0", || f64::from_ratio(1, 0, &())),
        f64::INFINITY
    );
    assert!(no_panic("Float 1/0", || Float::from_ratio(1, 0, &64)).is_infinite());
    assert!(no_panic("Float 0/0", || Float::from_ratio(0, 0, &64)).is_nan());
    assert!(!no_panic("Ball 1/0", || Ball::from_ratio(1, 0, &64)).is_finite());
}

#[test]
fn knots_count_from_zero_and_refuse_out_of_range_indices() {
    use trajverify::algo::gerbs::{Knots, Side};
    let knots = Knots::<f64>::uniform(5, &()).expect("knots");
    assert_eq!(knots.get(0), Some(&0.0));
    assert_eq!(knots.get(2), Some(&0.25));
    assert_eq!(knots.get(6), Some(&1.0));
    assert_eq!(no_panic("Knots::get(7)", || knots.get(7)), None);
    // Interval i runs from knot i to knot i + 1: 0.3 lies in interval 2 = [1/4, 1/2].
    assert_eq!(knots.interval(&0.3, Side::Right), Some(2));
    assert_eq!(knots.interval(&0.25, Side::Left), Some(1));
    assert_eq!(knots.interval(&1.5, Side::Left), None);
}

#[test]
fn a_bfbs_for_the_wrong_number_of_waypoints_is_refused() {
    let spec = PathSpec::new(
        vec![[0.0, 0.0], [300.0, 100.0], [600.0, -50.0], [900.0, 0.0]],
        80.0,
        &(),
    );
    for n in [1, 3, 5, 40] {
        let blend = Bfbs::uniform(2, n).expect("exponents");
        let r = no_panic("GerbsPath::new", || GerbsPath::new(&spec, blend));
        assert!(r.is_err(), "{n} exponents for 4 waypoints accepted");
    }
    let path = GerbsPath::new(&spec, Bfbs::uniform(2, 4).expect("exponents")).expect("a path");
    // Parts that do not fit: the knots of 4 curves with the curves of 3.
    let other = PathSpec::new(spec.waypoints[..3].to_vec(), 80.0, &());
    let three = GerbsPath::new(&other, Bfbs::uniform(2, 3).expect("exponents")).expect("a path");
    let r = no_panic("from_parts", || {
        GerbsPath::from_parts(
            path.knots().clone(),
            path.blend().clone(),
            three.curves().to_vec(),
            three.tangents().clone(),
        )
    });
    assert!(r.is_err());
}

#[test]
fn curves_are_evaluated_on_their_domain_only() {
    use trajverify::algo::hermite::hermite_curve;
    use trajverify::algo::ph::piecewise::{fit, FitOptions};
    use trajverify::curve::bezier::BezierCurve;
    use trajverify::curve::parametric::{ParamCurve, ParamCurveArclen, ParamCurveFrame};
    let bezier =
        BezierCurve::new(vec![[0.0, 0.0, 0.0], [1.0, 1.0, 1.0]], (0.0, 1.0)).expect("a line");
    let ph = fit(
        &ExprCurve::parse("[cos(t), sin(t), t/5]")
            .expect("parses")
            .compile::<f64>(&()),
        (&0.0, &6.0),
        &FitOptions::default(),
    )
    .expect("a PH spline");
    for t in [-1e-9, 6.5, f64::NAN, f64::INFINITY] {
        assert!(no_panic("BezierCurve::point", || bezier.point(&t)).is_err());
        assert!(no_panic("PiecewisePh::derivatives", || ph.derivatives(&t, 3)).is_err());
        assert!(no_panic("PiecewisePh::frame", || ph.frame(&t)).is_err());
        assert!(no_panic("PiecewisePh::arc_length", || ph.arc_length(&t)).is_err());
    }
    assert!(no_panic("empty", || BezierCurve::<f64, 2>::new(vec![], (0.0, 1.0))).is_err());
    assert!(no_panic("t0 = t1", || BezierCurve::new(vec![[1.0]], (1.0, 1.0))).is_err());
    let q = |n: i64| BigRational::from_integer(n.into());
    assert!(no_panic("exact t0 = t1", || BezierCurve::new(
        vec![[q(1)]],
        (q(1), q(1))
    ))
    .is_err());
    // Hermite data: unequal derivative counts, no data, an empty interval.
    let d = [[0.0, 1.0], [1.0, 0.0]];
    assert!(no_panic("hermite_curve", || hermite_curve(&d, &d[..1], (0.0, 1.0))).is_err());
    assert!(no_panic("hermite_curve", || hermite_curve::<f64, 2>(
        &[],
        &[],
        (0.0, 1.0)
    ))
    .is_err());
    assert!(no_panic("hermite_curve", || hermite_curve(&d, &d, (1.0, 1.0))).is_err());
    assert!(no_panic("hermite_curve", || hermite_curve(&d, &d, (0.0, f64::NAN))).is_err());
    let ok = hermite_curve(&d, &d, (0.0, 1.0)).expect("C¹ data");
    assert!(ok.control_points().iter().flatten().all(|x| x.is_finite()));
}

#[test]
fn a_ph_fit_checks_its_options() {
    use trajverify::algo::ph::piecewise::{fit, FitOptions};
    let helix = ExprCurve::parse("[cos(t), sin(t), t/5]")
        .expect("parses")
        .compile::<f64>(&());
    let run = |options: FitOptions<f64>| no_panic("fit", || fit(&helix, (&0.0, &6.0), &options));
    assert!(run(FitOptions {
        segments: 0,
        ..FitOptions::default()
    })
    .is_err());
    assert!(run(FitOptions {
        derivatives: 0,
        ..FitOptions::default()
    })
    .is_err());
    let wrong = FreeParameters::zero(2, &());
    assert!(run(FitOptions {
        free: Some(wrong),
        ..FitOptions::default()
    })
    .is_err());
    for tol in [0.0, -1.0, f64::NAN] {
        assert!(
            run(FitOptions {
                tolerance: Some(tol),
                ..FitOptions::default()
            })
            .is_err(),
            "tolerance {tol}"
        );
    }
    let fine = run(FitOptions {
        tolerance: Some(1e-12),
        ..FitOptions::default()
    })
    .expect("reachable");
    let n = fine.segments().len();
    let error = conversion_error(&helix, &fine, DEFAULT_SAMPLES).max;
    assert!(n > 8 && error <= 1e-12, "{n} segments, error {error:e}");
    let coarser = convert(
        &helix,
        (&0.0, &6.0),
        n / 2,
        4,
        &FreeParameters::zero(4, &()),
        true,
    )
    .expect("converts");
    assert!(
        conversion_error(&helix, &coarser, DEFAULT_SAMPLES).max > 1e-12,
        "{n} is not the first N that meets it"
    );
}

/// The lower-level public functions a second reading of the API found panicking: the
/// smoothness objective and its gradient on short data, spline fits without controls or with
/// NaN data, the solvers on empty or misshapen systems, PH interpolation above the supported
/// order and GERBS local curves with too few given tangents.
#[test]
fn lower_level_functions_check_their_inputs() {
    use trajverify::algo::bspline::fit::{FitError, SplineSpace};
    use trajverify::algo::gerbs::path::{local_curves, Tangents};
    use trajverify::algo::param::descent::newton_polish;
    use trajverify::algo::param::gradient::{gradient, project};
    use trajverify::algo::param::objective::objective;
    use trajverify::algo::ph::hermite::interpolate_with;
    use trajverify::algo::ph::hermite::MiddleRule;
    use trajverify::numeric::linalg::banded::{Banded, Cyclic};
    use trajverify::numeric::linalg::{
        condition_number, determinant, inverse, singular_values, solve, Matrix,
    };

    // Marin's objective: a component shorter than h + 1, no h, a NaN or negative spacing.
    let z = vec![vec![0.0, 1.0, 0.0]];
    for form in [Objective::Exact, Objective::Approximate] {
        for h in [
            vec![0.5, 0.5, 0.5],
            vec![],
            vec![0.5, f64::NAN],
            vec![1.5, -0.5],
        ] {
            let g = no_panic("objective", || objective(&h, &z, &[1.0], form));
            assert!(g.is_err(), "objective on h = {h:?} gave {g:?}");
            let d = no_panic("gradient", || gradient(&h, &z, &[1.0], form));
            assert!(d.is_err(), "gradient on h = {h:?} gave {d:?}");
            let n = no_panic("newton_polish", || {
                newton_polish(h.clone(), &z, &[1.0], form, 3)
            });
            assert!(n.is_err(), "newton_polish on h = {h:?} gave {n:?}");
        }
    }
    assert!(no_panic("project(&[])", || project::<f64>(&[])).is_empty());

    // Spline fits: M = 0, NaN times, values and weights, a B with the wrong column count.
    assert_eq!(
        SplineSpace::<f64>::new(3, 0, &()).err(),
        Some(FitError::NoControls)
    );
    let space = SplineSpace::<f64>::new(3, 6, &()).unwrap();
    let good = [3.0, 4.0, 5.0, 6.0];
    let r = no_panic("interpolate NaN time", || {
        space.interpolate(&[3.0, f64::NAN, 5.0, 6.0], &good)
    });
    assert!(
        matches!(
            r,
            Err(FitError::NotFinite {
                what: "time",
                index: 1
            })
        ),
        "{r:?}"
    );
    let r = no_panic("interpolate NaN value", || {
        space.interpolate(&good, &[0.0, 1.0, f64::NAN, 2.0])
    });
    assert!(
        matches!(
            r,
            Err(FitError::NotFinite {
                what: "value",
                index: 2
            })
        ),
        "{r:?}"
    );
    let r = no_panic("smooth NaN weight", || {
        space.smooth(&good, &good, &[1.0, f64::NAN, 1.0, 1.0])
    });
    assert!(
        matches!(
            r,
            Err(FitError::NotFinite {
                what: "weight",
                index: 1
            })
        ),
        "{r:?}"
    );
    let r = no_panic("smooth_checked short weights", || {
        space.smooth_checked(&good, &good, &[1.0])
    });
    assert!(matches!(r, Err(FitError::WeightsLength { .. })), "{r:?}");
    let narrow = Matrix::zeros(4, 2, &());
    let r = no_panic("smooth_collocation 4×2", || {
        space.smooth_collocation(&narrow, &good, &[1.0; 4])
    });
    assert!(r.is_err(), "{r:?}");
    let r = no_panic("interpolate_collocation 4×2", || {
        space.interpolate_collocation(&narrow, &good)
    });
    assert!(r.is_err(), "{r:?}");

    // Solvers: empty, not square, a right-hand side of the wrong height, the zero matrix.
    let empty = Matrix::<f64>::zeros(0, 0, &());
    assert_eq!(no_panic("solve 0×0", || solve(&empty, &[])), Ok(vec![]));
    assert_eq!(
        no_panic("inverse 0×0", || inverse(&empty)),
        Ok(empty.clone())
    );
    assert!(no_panic("determinant 0×0", || determinant(&empty)).is_err());
    assert_eq!(
        no_panic("singular values 0×0", || singular_values(&empty)),
        Ok(vec![])
    );
    assert!(no_panic("κ 0×0", || condition_number(&empty)).is_err());
    let wide = Matrix::<f64>::zeros(2, 3, &());
    assert!(no_panic("solve 2×3", || solve(&wide, &[1.0, 2.0])).is_err());
    assert!(no_panic("inverse 2×3", || inverse(&wide)).is_err());
    let square = Matrix::<f64>::identity(2, &());
    assert!(no_panic("solve short b", || solve(&square, &[1.0])).is_err());
    let kappa = no_panic("κ of 0", || {
        condition_number(&Matrix::<f64>::zeros(2, 2, &()))
    });
    assert_eq!(kappa, Ok(f64::INFINITY));
    let mut band = Banded::<f64>::zeros(3, 1, 1, &());
    assert!(
        band.add(0, 2, &1.0).is_err(),
        "an entry outside the band was accepted"
    );
    let r = no_panic("banded short rhs", || band.solve(Matrix::zeros(2, 1, &())));
    assert!(r.is_err());
    let mut cyclic = Cyclic::<f64>::zeros(0, 1, 1, &());
    assert!(cyclic.add(0, 0, &1.0).is_err());
    let r = no_panic("cyclic n = 0", || cyclic.solve(Matrix::zeros(0, 1, &())));
    assert!(r.is_ok_and(|x| x.rows() == 0));

    // PH Hermite interpolation above MAX_DERIVATIVES, and from empty jets.
    let m = 13;
    use trajverify::algo::ph::hermite::HermiteData as PhData;
    let data = PhData {
        p_b: [0.0, 0.0, 0.0],
        p_e: [1.0, 0.0, 0.0],
        start: vec![[1.0, 0.0, 0.0]; m],
        end: vec![[1.0, 0.0, 0.0]; m],
    };
    let r = no_panic("interpolate_with m = 13", || {
        interpolate_with(&data, &FreeParameters::zero(m, &()), MiddleRule::Derived)
    });
    assert!(matches!(r, Err(PhHermiteError::Shape)), "{r:?}");
    let nan = PhData {
        p_b: [f64::NAN, 0.0, 0.0],
        p_e: [1.0, 0.0, 0.0],
        start: vec![[1.0, 0.0, 0.0]],
        end: vec![[1.0, 0.0, 0.0]],
    };
    let r = no_panic("interpolate_with NaN point", || {
        interpolate_with(&nan, &FreeParameters::zero(1, &()), MiddleRule::Derived)
    });
    assert!(matches!(r, Err(PhHermiteError::NotFinite(_))), "{r:?}");
    assert!(no_panic("from_jets(&[], …)", || PhData::<f64>::from_jets(
        &[],
        &[[0.0; 3]]
    ))
    .is_err());

    // GERBS local curves with given tangents for fewer waypoints than the path has.
    let spec = PathSpec::new(vec![[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]], 0.5, &());
    let short = Tangents {
        m: vec![[1.0, 0.0]],
        s: vec![1],
    };
    let r = no_panic("local_curves short tangents", || {
        local_curves(&spec, Some(&short))
    });
    assert!(r.is_err());
}
