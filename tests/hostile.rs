//! Hostile calls of the public API, each under `catch_unwind`: a call must return an error (or
//! a documented answer), never panic, and never return `Ok` holding NaN.
//!
//! This covers most of the calls found by trying the library as an engineer would. Still
//! open: `BigRational::from_ratio(1, 0, &())` (the `Field` constructors cannot fail),
//! `Knots::at(0)` (1-based), and struct literals of `Bernstein`, `PiecewisePh` and
//! `PathSpec`, whose fields are public (`HermiteData::solve` re-checks its fields).

use std::panic::{catch_unwind, AssertUnwindSafe};
use trajverify::algo::gerbs::bfbs::Bfbs;
use trajverify::algo::gerbs::path::{ArcConvention, EndCurves, GerbsPath, PathSpec};
use trajverify::algo::gerbs::Side;
use trajverify::algo::param::descent::{descend, refine};
use trajverify::algo::param::objective::{chord_length_spacing, Objective};
use trajverify::algo::ph::hermite::{FreeParameters, PhHermiteError};
use trajverify::algo::ph::piecewise::convert;
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
            HermiteData::new(vec![0.0], vec![1.0], t0, t1)
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
        no_panic("convert", || convert(&compiled, &a, &b, n, 4, &free, true))
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
    assert!(no_panic("empty", || Bernstein::<f64>::new(vec![], 0.0, 1.0)).is_err());
    let q = |n: i64| BigRational::from_integer(n.into());
    assert!(no_panic("t0 = t1", || Bernstein::new(vec![q(1)], q(1), q(1))).is_err());
    assert!(no_panic("NaN", || Bernstein::new(vec![1.0], 0.0, f64::NAN)).is_err());
    // A struct literal of Hermite data with no points is refused when solved.
    let data = HermiteData::<f64> {
        start: vec![],
        end: vec![],
        t0: 0.0,
        t1: 1.0,
    };
    assert!(no_panic("solve of empty data", || data.solve()).is_err());
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
    let points = vec![
        vec![0.0, 0.0],
        vec![1.0, 2.0],
        vec![3.0, 3.0],
        vec![4.0, 1.0],
    ];
    let wrong_alpha = ParametrizeOptions {
        alpha: Some(vec![1.0]),
        ..ParametrizeOptions::default()
    };
    assert!(no_panic("one α for two coordinates", || parametrize(
        &points,
        &wrong_alpha
    ))
    .is_err());
    let ragged = vec![vec![0.0, 0.0], vec![1.0], vec![3.0, 3.0]];
    let default = ParametrizeOptions::default();
    assert!(no_panic("ragged points", || parametrize(&ragged, &default)).is_err());
    assert!(no_panic("one point", || parametrize(&points[..1], &default)).is_err());
    let repeated = vec![
        vec![0.0, 0.0],
        vec![1.0, 2.0],
        vec![1.0, 2.0],
        vec![4.0, 1.0],
    ];
    if let Ok(m) = no_panic("repeated point", || parametrize(&repeated, &default)) {
        assert!(
            m.knots.iter().all(|t| t.is_finite()),
            "Ok holding NaN: {:?}",
            m.knots
        );
    }
    let m = parametrize(&points, &default).expect("four distinct points");
    assert!(m.knots.iter().all(|t| t.is_finite()));
}
