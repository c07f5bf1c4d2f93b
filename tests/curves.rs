//! The curve interface (`curve::parametric`) against independent computations: derivatives
//! per unit of t against central differences of the points, the PH spline's exact arc length
//! against quadrature, its frame and ω against the tangent and differences of the frame, and
//! each implementation against the module's own evaluator.

#![allow(clippy::needless_range_loop)] // component loops over fixed-size points
use trajverify::algo::bspline::fit::{SplineFit, SplineSpace};
use trajverify::algo::gerbs::{bfbs::Bfbs, path::GerbsPath, path::PathSpec, Side};
use trajverify::algo::hermite::hermite_curve;
use trajverify::algo::param::natural::NaturalSplineCurve;
use trajverify::algo::ph::piecewise::{fit, FitOptions};
use trajverify::curve::parametric::{
    curvature, quadrature_arc_length, ParamCurve, ParamCurveArclen, ParamCurveFrame,
};
use trajverify::curve::ExprCurve;
use trajverify::scalar::Float;

/// max over the components of |(γ⁽ᵏ⁾(t + δ) − γ⁽ᵏ⁾(t − δ))/(2δ) − γ⁽ᵏ⁺¹⁾(t)|.
fn difference_gap<const D: usize>(c: &impl ParamCurve<f64, D>, t: f64, k: usize) -> f64 {
    let delta = 1e-6;
    let (lo, hi) = (
        c.derivative(&(t - delta), k).unwrap(),
        c.derivative(&(t + delta), k).unwrap(),
    );
    let d = c.derivative(&t, k + 1).unwrap();
    (0..D)
        .map(|i| ((hi[i] - lo[i]) / (2.0 * delta) - d[i]).abs())
        .fold(0.0, f64::max)
}

fn helix_fit() -> trajverify::algo::ph::piecewise::PiecewisePh<f64> {
    let helix = ExprCurve::parse("[cos(t), sin(t), t/5]").unwrap();
    let options = FitOptions {
        segments: 32,
        ..FitOptions::default()
    };
    fit(&helix.compile::<f64>(&()), (&0.0, &6.0), &options).unwrap()
}

#[test]
fn ph_spline_derivatives_are_per_unit_of_t() {
    let pw = helix_fit();
    for t in [0.3, 1.7, 4.05] {
        for k in 0..3 {
            assert!(difference_gap(&pw, t, k) < 1e-5, "t = {t}, k = {k}");
        }
        // And they are the helix's: γ′ = (−sin t, cos t, 1/5).
        let v = pw.derivative(&t, 1).unwrap();
        assert!(
            (v[0] + t.sin()).abs() < 1e-6 && (v[2] - 0.2).abs() < 1e-6,
            "t = {t}"
        );
    }
    assert_eq!(pw.breakpoints().len(), 31);
}

#[test]
fn ph_spline_arc_length_is_exact_and_agrees_with_quadrature() {
    let pw = helix_fit();
    for t in [0.0, 0.1875, 2.5, 6.0] {
        let exact = pw.arc_length(&t).unwrap();
        let quad = quadrature_arc_length(&pw, &t).unwrap();
        assert!((exact - quad).abs() < 1e-12, "t = {t}: {exact} vs {quad}");
        assert!((exact - t * 1.04f64.sqrt()).abs() < 1e-6, "t = {t}");
    }
    // At 256 bits the exact length agrees with f64's to f64's precision.
    let helix = ExprCurve::parse("[cos(t), sin(t), t/5]").unwrap();
    let (a, b) = (Float::with_val(256, 0), Float::with_val(256, 6));
    let options = FitOptions {
        segments: 32,
        ..FitOptions::default()
    };
    let precise = fit(&helix.compile::<Float>(&256), (&a, &b), &options).unwrap();
    let l = precise.length().unwrap();
    assert!((l.to_f64() - pw.length().unwrap()).abs() < 1e-13);
}

#[test]
fn ph_spline_frame_is_adapted_and_omega_turns_it_per_unit_of_t() {
    let pw = helix_fit();
    let cross = |a: [f64; 3], b: [f64; 3]| {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    };
    for t in [0.4, 3.3] {
        let f = pw.frame(&t).unwrap();
        let v = pw.derivative(&t, 1).unwrap();
        let speed = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        assert!((f.speed - speed).abs() < 1e-12);
        for i in 0..3 {
            assert!(
                (f.axes[0][i] - v[i] / speed).abs() < 1e-12,
                "e1 is the tangent"
            );
        }
        // ė_k = ω × e_k, by central differences in t.
        let delta = 1e-6;
        let (lo, hi) = (
            pw.frame(&(t - delta)).unwrap(),
            pw.frame(&(t + delta)).unwrap(),
        );
        for k in 0..3 {
            let turn = cross(f.omega, f.axes[k]);
            for i in 0..3 {
                let rate = (hi.axes[k][i] - lo.axes[k][i]) / (2.0 * delta);
                assert!((rate - turn[i]).abs() < 1e-6, "t = {t}, e{}", k + 1);
            }
        }
    }
}

#[test]
fn hermite_curves_meet_their_data_per_unit_of_t() {
    let start = [[0.0, 0.0, 0.0], [1.0, 0.0, 2.0], [0.0, 3.0, 0.0]];
    let end = [[1.0, 1.0, 0.5], [0.0, 1.0, 0.0], [4.0, 0.0, -1.0]];
    let c = hermite_curve(&start, &end, (0.5, 2.0)).unwrap();
    for k in 0..3 {
        let (a, b) = (
            c.derivative(&0.5, k).unwrap(),
            c.derivative(&2.0, k).unwrap(),
        );
        for i in 0..3 {
            assert!((a[i] - start[k][i]).abs() < 1e-12 && (b[i] - end[k][i]).abs() < 1e-12);
        }
    }
    assert!(difference_gap(&c, 1.1, 2) < 1e-5);
    // The chord is the shortest path.
    assert!(c.length().unwrap() >= (1.0f64 + 1.0 + 0.25).sqrt());
}

#[test]
fn gerbs_path_derivatives_and_curvature_match_its_own_evaluator() {
    let waypoints = vec![
        [0.0, 0.0],
        [300.0, 100.0],
        [600.0, -50.0],
        [900.0, 150.0],
        [1200.0, 0.0],
    ];
    let path = GerbsPath::new(
        &PathSpec::new(waypoints, 80.0, &()),
        Bfbs::uniform(2, 5).unwrap(),
    )
    .unwrap();
    for t in [0.1, 0.37, 0.5, 0.93] {
        let own = path.at(&t, Side::Right).unwrap();
        let jet = path.derivatives(&t, 2).unwrap();
        assert_eq!(jet[0], own.point);
        assert_eq!(jet[1], own.d1);
        assert_eq!(jet[2], own.d2);
        assert!((curvature(&path, &t).unwrap() - own.curvature.abs()).abs() < 1e-12);
    }
    let quad = quadrature_arc_length(&path, &1.0).unwrap();
    let own = path.length().unwrap();
    assert!((quad - own).abs() < 1e-6 * own, "{quad} vs {own}");
}

#[test]
fn natural_spline_curves_and_spline_fits_match_their_modules() {
    let points = [
        [0.0, 0.0, 1.0],
        [1.0, 2.0, 0.0],
        [3.0, 3.0, 2.0],
        [4.0, 1.0, 1.0],
    ];
    let knots = vec![0.0, 0.3, 0.7, 1.0];
    let c = NaturalSplineCurve::new(knots.clone(), &points).unwrap();
    for t in [0.1, 0.5, 0.8] {
        for k in 0..3 {
            assert!(difference_gap(&c, t, k) < 1e-4, "t = {t}, k = {k}");
        }
        let own = c.component(1).unwrap().eval_all(&t);
        assert_eq!(c.derivative(&t, 2).unwrap()[1], own[2]);
    }
    let space = SplineSpace::new(3, 6, &()).unwrap();
    let f = SplineFit::interpolate(space, &[3.0, 4.0, 5.0, 6.0], &[0.0, 1.0, 0.0, 2.0]).unwrap();
    for t in [0.5, 3.5, 7.9] {
        let own = f.space().eval(f.control_points(), &t);
        assert_eq!(f.point(&t).unwrap(), [own]);
        assert!(difference_gap(&f, t, 0) < 1e-6);
    }
    assert_eq!(f.domain(), (0.0, 9.0));
}

#[test]
fn data_splines_and_expressions_are_curves_on_their_domain() {
    use trajverify::curve::parametric::{CurveError, CurveOn};
    use trajverify::curve::spline::ClampedSpline;
    // A quintic spline through 41 samples of the helix on [0, 6]: its derivatives per unit
    // of t agree with central differences, its length with the helix's within the fit's error.
    let times: Vec<f64> = (0..=40).map(|i| 0.15 * f64::from(i)).collect();
    let points: Vec<[f64; 3]> = times.iter().map(|t| [t.cos(), t.sin(), 0.2 * t]).collect();
    let spline = ClampedSpline::interpolate(5, &times, &points).unwrap();
    let on = spline.on::<f64>(&());
    assert_eq!(on.domain(), (0.0, 6.0));
    assert!(!on.breakpoints().is_empty());
    for t in [0.4, 2.5, 5.3] {
        assert!(difference_gap(&on, t, 1) < 1e-6, "derivative at {t}");
    }
    let length = on.length().unwrap();
    assert!(
        (length - 6.0 * 1.04f64.sqrt()).abs() < 1e-6,
        "length {length}"
    );
    assert!(on.point(&6.5).is_err());
    // The same spline evaluated in MPFR: the doubles are exact there.
    let slow = spline.on::<Float>(&128);
    let p = slow.point(&Float::with_val(128, 2.5)).unwrap();
    assert!((p[0].to_f64() - on.point(&2.5).unwrap()[0]).abs() < 1e-15);
    // An expression: a reversed or NaN domain is refused, a value that is not real is an error.
    let root = ExprCurve::parse("[sqrt(t - 10), t, t]")
        .unwrap()
        .compile::<f64>(&());
    assert!(matches!(
        CurveOn::new(&root, (1.0, 0.0)),
        Err(CurveError::Domain { .. })
    ));
    assert!(CurveOn::new(&root, (f64::NAN, 1.0)).is_err());
    let on_root = CurveOn::new(&root, (0.0, 20.0)).unwrap();
    assert!(matches!(
        on_root.point(&1.0),
        Err(CurveError::NotFinite { .. })
    ));
    assert!(on_root.point(&12.0).is_ok());
}

/// The point-only evaluation (order 0) is bit for bit the value the Taylor path gives at a
/// variable of order 0, in every number type, for every operation of the expression language.
#[test]
fn point_evaluation_equals_the_series_value_bit_for_bit() {
    use trajverify::curve::taylor::Taylor;
    use trajverify::curve::{CompiledCurve, Curve};
    use trajverify::scalar::ball::Ball;
    use trajverify::scalar::{Field, Real};
    fn series_point<T: Real>(c: &CompiledCurve<T>, t: &T) -> Vec<T> {
        let var = Taylor::variable(t.clone(), 0);
        (0..3)
            .map(|i| c.components[i].eval(&var).with_order(0).derivatives()[0].clone())
            .collect()
    }
    let text = "[1.5*sin(7.2*t)/(2+t) + tan(t/3), t^-3 + t^2.5 - atan(t)*sqrt(t), exp(cos(1.8*t)) - ln(1+t)]";
    let curve = ExprCurve::parse(text).unwrap();
    let f = curve.compile::<f64>(&());
    let m = curve.compile::<Float>(&256);
    let b = curve.compile::<Ball>(&256);
    for t in [0.3, 0.7, 1.9] {
        let p = f.jet(&t, 0)[0].map(f64::to_bits);
        let q: Vec<u64> = series_point(&f, &t).into_iter().map(f64::to_bits).collect();
        assert_eq!(p.to_vec(), q, "f64 at {t}");
        let tm = Float::with_val(256, t);
        assert_eq!(
            m.jet(&tm, 0)[0].to_vec(),
            series_point(&m, &tm),
            "MPFR at {t}"
        );
        let tb = Ball::from_f64(t, &256);
        let (p, q) = (b.jet(&tb, 0), series_point(&b, &tb));
        for i in 0..3 {
            assert_eq!(p[0][i].mid(), q[i].mid(), "ball midpoint at {t}");
            assert_eq!(p[0][i].rad(), q[i].rad(), "ball radius at {t}");
        }
    }
}
