//! A property test over the public API (issue 38): arbitrary f64 — NaN, ±∞, ±1e±300, −0,
//! subnormals and ordinary values — and extreme counts into the public constructors and
//! evaluators. A case fails on any panic, on any `Ok` holding NaN or ∞, and on a call that
//! runs past [`HANG`]; an error is always an acceptable answer. The hand-picked calls of
//! `hostile_api.rs` (each call the issue lists) are its seeds, and its strategies reach them.

use proptest::prelude::*;
use proptest::test_runner::RngSeed;
use std::panic::{catch_unwind, AssertUnwindSafe};
use trajverify::algo::gerbs::bfbs::Bfbs;
use trajverify::algo::gerbs::path::{GerbsPath, PathSpec};
use trajverify::algo::gerbs::Side;
use trajverify::algo::hermite::hermite_curve;
use trajverify::algo::param::descent::{parametrize, ParametrizeOptions};
use trajverify::algo::param::natural::NaturalSplineCurve;
use trajverify::algo::ph::piecewise::{fit, FitOptions};
use trajverify::curve::bezier::BezierCurve;
use trajverify::curve::parametric::{curvature, ParamCurve, ParamCurveArclen};
use trajverify::curve::ExprCurve;

/// Doubles a careless or hostile caller passes.
fn hostile_f64() -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(f64::NAN),
        Just(f64::INFINITY),
        Just(f64::NEG_INFINITY),
        Just(-0.0),
        Just(1e300),
        Just(-1e300),
        Just(1e-300),
        Just(5e-324),
        -1e3..1e3f64,
        -1.0..1.0f64,
    ]
}

/// Counts from tiny to absurd.
fn hostile_count() -> impl Strategy<Value = usize> {
    prop_oneof![
        Just(0usize),
        Just(1),
        Just(2),
        Just(usize::MAX),
        Just(1_000_000_000),
        0usize..40
    ]
}

/// A call that runs this long has hung: the slowest call of these tests takes about a tenth
/// of a second on two cores, and every long computation of the API has a work budget or a
/// documented cost cap that refuses it first. Not a speed test: two orders of magnitude of
/// room.
const HANG: std::time::Duration = std::time::Duration::from_secs(20);

/// `f` must not panic or hang; the answer is returned for the finiteness checks.
fn no_panic<R>(what: &str, f: impl FnOnce() -> R) -> Result<R, TestCaseError> {
    let start = std::time::Instant::now();
    let r = catch_unwind(AssertUnwindSafe(f))
        .map_err(|_| TestCaseError::fail(format!("{what} panicked")))?;
    let took = start.elapsed();
    if took > HANG {
        return Err(TestCaseError::fail(format!(
            "{what} ran {took:?}, past its budget"
        )));
    }
    Ok(r)
}

fn all_finite<const D: usize>(points: &[[f64; D]]) -> bool {
    points.iter().flatten().all(|x| x.is_finite())
}

/// Fixed cases by default, so the test command gives the same answer on every run and
/// machine; `API_SEED=random` (or a number) explores others.
fn config() -> ProptestConfig {
    let seed = match std::env::var("API_SEED").ok().as_deref() {
        Some("random") => RngSeed::Random,
        Some(n) => RngSeed::Fixed(n.parse().unwrap_or(38)),
        None => RngSeed::Fixed(38),
    };
    ProptestConfig {
        cases: 256,
        rng_seed: seed,
        ..ProptestConfig::default()
    }
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn bezier_and_hermite_curves(x in hostile_f64(), y in hostile_f64(), t0 in hostile_f64(), t1 in hostile_f64(), t in hostile_f64(), order in hostile_count()) {
        if let Ok(c) = no_panic("BezierCurve::new", || BezierCurve::new(vec![[0.0, 0.0], [x, y], [1.0, 0.0]], (t0, t1)))? {
            if let Ok(d) = no_panic("derivatives", || c.derivatives(&t, order))? {
                prop_assert!(all_finite(&d), "Ok holding {d:?}");
            }
            if let Ok(k) = no_panic("curvature", || curvature(&c, &t))? {
                prop_assert!(k.is_finite(), "curvature Ok({k})");
            }
            if let Ok(s) = no_panic("parameter_at_length", || c.parameter_at_length(&x.abs(), &1e-9))? {
                prop_assert!(s.is_finite(), "parameter Ok({s})");
            }
        }
        let start = [[0.0, 0.0], [x, 1.0]];
        let end = [[1.0, y], [0.0, 1.0]];
        if let Ok(c) = no_panic("hermite_curve", || hermite_curve(&start, &end, (t0, t1)))? {
            prop_assert!(all_finite(c.control_points()), "Ok holding {:?}", c.control_points());
        }
    }

    #[test]
    fn natural_splines_and_marins_knots(a in hostile_f64(), b in hostile_f64(), t in hostile_f64(), count in hostile_count()) {
        // Many points (3000 took 106 s before the cap): refused at once, or a converged result.
        let many: Vec<[f64; 2]> = (0..count.min(3000)).map(|i| [i as f64, ((i * 7) % 13) as f64]).collect();
        if let Ok(m) = no_panic("parametrize many", || parametrize(&many, &ParametrizeOptions::default()))? {
            prop_assert!(m.knots.iter().all(|k| k.is_finite()), "Ok holding {:?}", m.knots);
        }
        let points = [[0.0, 0.0], [a, 1.0], [2.0, b], [3.0, 0.5]];
        if let Ok(c) = no_panic("NaturalSplineCurve::new", || NaturalSplineCurve::new(vec![0.0, 1.0, a.abs() + 2.0, 9.0], &points))? {
            if let Ok(p) = no_panic("point", || c.point(&t))? {
                prop_assert!(p.iter().all(|v| v.is_finite()), "Ok holding {p:?}");
            }
        }
        if let Ok(m) = no_panic("parametrize", || parametrize(&points, &ParametrizeOptions::default()))? {
            prop_assert!(m.knots.iter().all(|k| k.is_finite()), "Ok holding {:?}", m.knots);
            prop_assert!(m.knots[0] == 0.0 && m.knots[3] == 1.0, "knots {:?}", m.knots);
        }
    }

    #[test]
    fn gerbs_paths(x in hostile_f64(), radius in hostile_f64(), t in hostile_f64(), j in hostile_count(), count in hostile_count()) {
        let waypoints = vec![[0.0, 0.0], [300.0, 100.0], [x, -50.0], [900.0, 150.0], [1200.0, 0.0]];
        let spec = PathSpec::new(waypoints, radius, &());
        let Ok(bfbs) = Bfbs::uniform(2, 5) else { return Ok(()) };
        if let Ok(path) = no_panic("GerbsPath::new", || GerbsPath::new(&spec, bfbs))? {
            if let Ok(p) = no_panic("at", || path.at(&t, Side::Right))? {
                prop_assert!(p.curvature.is_finite() && p.point.iter().all(|v| v.is_finite()), "Ok holding {p:?}");
            }
            if let Ok(p) = no_panic("at_on", || path.at_on(&t, j))? {
                prop_assert!(p.curvature.is_finite(), "Ok holding {p:?}");
            }
            if let Ok(p) = no_panic("at_knot", || path.at_knot(j, Side::Left))? {
                prop_assert!(p.curvature.is_finite(), "Ok holding {p:?}");
            }
            if count <= 64 {
                if let Ok(s) = no_panic("sample", || path.sample(count))? {
                    prop_assert!(s.iter().all(|p| p.curvature.is_finite()), "a sample holds NaN");
                }
            } else {
                let r = no_panic("sample", || path.sample(count))?;
                prop_assert!(r.is_err() || count <= 10_000_000);
            }
        }
    }

    #[test]
    fn ph_fits(scale in hostile_f64(), a in hostile_f64(), b in hostile_f64(), segments in hostile_count(), derivatives in hostile_count()) {
        let text = format!("[{scale:e}*cos(t), sin(t), t]");
        let Ok(expr) = ExprCurve::parse(&text) else { return Ok(()) };
        let curve = expr.compile::<f64>(&());
        // Segment counts that would be accepted but are slow are not this test's subject.
        let segments = if (1..=64).contains(&segments) || segments > 1 << 20 || segments == 0 { segments } else { 8 };
        let options = FitOptions { segments, derivatives, ..FitOptions::default() };
        if let Ok(pw) = no_panic("fit", || fit(&curve, (&a, &b), &options))? {
            let (lo, hi) = pw.domain();
            if let Ok(p) = no_panic("point", || pw.point(&((lo + hi) / 2.0)))? {
                prop_assert!(p.iter().all(|v| v.is_finite()), "Ok holding {p:?}");
            }
        }
    }
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn gerbs_bases_and_dubins(a in hostile_f64(), b in hostile_f64(), lambda in hostile_f64(), sigma in hostile_f64(), n in hostile_count(), i in 0u32..40, t in hostile_f64()) {
        use trajverify::algo::gerbs::dubins::shortest;
        use trajverify::algo::gerbs::erbs::{CentreReading, Erbs, ErbsParams};
        use trajverify::algo::gerbs::Knots;
        let _ = no_panic("Knots::new", || Knots::new(vec![0.0, a, b, 1.0]))?;
        if n <= 1000 {
            let _ = no_panic("Knots::uniform", || Knots::<f64>::uniform(n, &()))?;
            let _ = no_panic("Bfbs::uniform", || Bfbs::uniform(i, n))?;
        }
        if let Ok(params) = no_panic("ErbsParams::new", || ErbsParams::new(a.abs(), 1.0, 1.0, lambda, sigma))? {
            let Ok(knots) = Knots::<f64>::uniform(4, &()) else { return Ok(()) };
            if let Ok(erbs) = no_panic("Erbs::new", || Erbs::new(&knots, vec![params], CentreReading::Cited))? {
                let spec = PathSpec::new(vec![[0.0, 0.0], [300.0, 100.0], [600.0, -50.0], [900.0, 150.0]], 80.0, &());
                if let Ok(path) = no_panic("ERBS path", || GerbsPath::new(&spec, erbs))? {
                    if let Ok(p) = no_panic("ERBS at", || path.at(&t, Side::Right))? {
                        prop_assert!(p.curvature.is_finite() && p.point.iter().all(|v| v.is_finite()), "Ok holding {p:?}");
                    }
                }
            }
        }
        if let Some(d) = no_panic("Dubins", || shortest(&[0.0, 0.0, a], &[b, 1.0, 0.0], &lambda))? {
            prop_assert!(d.total().is_finite() && d.lengths().iter().all(|l| l.is_finite()), "Some holding {:?}", d.lengths());
        }
    }

    #[test]
    fn interpolants_and_proofs(x in hostile_f64(), t0 in hostile_f64(), t1 in hostile_f64(), segments in hostile_count(), m in hostile_count(), degree in 0usize..8, target in hostile_f64()) {
        use trajverify::algo::hermite::piecewise::{interpolate_curve, InterpolationOptions};
        use trajverify::curve::enclosure::{proven_error, ProofOptions};
        use trajverify::curve::spline::ClampedSpline;
        use trajverify::scalar::ball::Ball;
        use trajverify::scalar::Field;
        let curve = ExprCurve::parse("[cos(t), sin(t), t]").expect("a curve");
        let c = curve.compile::<f64>(&());
        let small = |n: usize| if n <= 64 || n > 1 << 20 { n } else { 8 };
        if let Ok(pw) = no_panic("interpolate_curve", || interpolate_curve(&c, (&t0, &t1), &InterpolationOptions { segments: small(segments), derivatives: m.min(40) }))? {
            let (lo, hi) = pw.domain();
            if let Ok(p) = no_panic("point", || pw.point(&((lo + hi) / 2.0)))? {
                prop_assert!(p.iter().all(|v| v.is_finite()), "Ok holding {p:?}");
            }
        }
        let times = [0.0, 1.0, x, 3.0, 4.0, 5.0, 6.0, 7.0];
        let _ = no_panic("ClampedSpline", || ClampedSpline::interpolate(degree, &times, &[[x, 0.0, 1.0]; 8]))?;
        let cb = curve.compile::<Ball>(&64);
        let (a, b) = (Ball::from_i64(0, &64), Ball::from_i64(1, &64));
        let Ok(pw) = fit(&cb, (&a, &b), &FitOptions { segments: 1, ..FitOptions::default() }) else { return Ok(()) };
        if let Ok(e) = no_panic("proven_error", || proven_error(&cb, &pw, &ProofOptions { target, max_boxes: 2000, ..ProofOptions::default() }))? {
            prop_assert!(e.lower.is_finite() && e.upper.is_finite() && e.lower <= e.upper, "{e:?}");
        }
    }
}

proptest! {
    #![proptest_config(config())]

    /// Studies: hostile precisions, methods and intervals are refused naming the field; a
    /// study that runs has finite errors.
    #[test]
    fn studies_and_intervals(bits_pick in 0usize..8, m in hostile_count(), a in hostile_f64(), b in hostile_f64(), proof in any::<bool>()) {
        use trajverify::algo::convergence::{study, Method, StudyOptions};
        use trajverify::curve::interval::Interval;
        let bits = [0u32, 1, 15, 16, 64, 4096, 4097, u32::MAX][bits_pick];
        let Ok(interval) = no_panic("Interval::from_f64", || Interval::from_f64(a, b))? else {
            return Ok(());
        };
        // Only cheap studies run to the end: short intervals, two coarse levels, low precision.
        if bits > 256 || (b - a) > 8.0 {
            return Ok(());
        }
        let method = if m % 2 == 0 { Method::Phodcos } else { Method::Hermite(m) };
        let options = StudyOptions { method, levels: vec![0, 1], bits, proof };
        let curve = ExprCurve::parse("[cos(t), sin(t), t/5]").expect("a curve");
        match no_panic("study", || study(&curve, &interval, &options, &mut |_, _| {}))? {
            Ok(s) => {
                for r in &s.rows {
                    prop_assert!(r.value().is_finite(), "a row holds {:?}", r.sampled);
                    if let Some((lo, hi)) = &r.proven {
                        prop_assert!(lo.is_finite() && hi.is_finite() && lo <= hi, "{lo} > {hi}");
                    }
                }
            }
            Err(e) => {
                let text = e.to_string();
                prop_assert!(!text.is_empty());
            }
        }
    }

    /// B-spline fits, periodic splines, Bernstein polynomials and the Hermite map: a
    /// constructor refuses what it cannot represent; what it returns is finite.
    #[test]
    fn splines_bernstein_and_the_hermite_map(degree in hostile_count(), controls in hostile_count(), x in hostile_f64(), w in hostile_f64(), t0 in hostile_f64(), t1 in hostile_f64(), t in hostile_f64()) {
        use trajverify::algo::bspline::fit::SplineSpace;
        use trajverify::algo::hermite::HermiteData;
        use trajverify::curve::spline::PeriodicSpline;
        use trajverify::numeric::poly::bernstein::Bernstein;
        if degree <= 60 && controls <= 200 {
            if let Ok(space) = no_panic("SplineSpace::new", || SplineSpace::<f64>::new(degree, controls, &()))? {
                let times = [0.0, 0.5, x, 2.0];
                let values = [1.0, x, 0.0, -1.0];
                if let Ok(c) = no_panic("interpolate", || space.interpolate(&times, &values))? {
                    prop_assert!(c.iter().all(|v| v.is_finite()), "Ok holding {c:?}");
                }
                if let Ok(c) = no_panic("smooth", || space.smooth(&times, &values, &[1.0, w, 1.0, 1.0]))? {
                    prop_assert!(c.iter().all(|v| v.is_finite()), "Ok holding {c:?}");
                }
            }
        }
        let times = [0.0, 1.0, 2.0, x, 4.0, 5.0];
        let _ = no_panic("PeriodicSpline", || PeriodicSpline::interpolate(degree.min(9), &times, 6.0, &[[x, 0.0, 1.0]; 6]))?;
        // `Bernstein` is an arithmetic kernel (its evaluators return T, not Result: a width of
        // 5e-324 gives derivatives beyond f64's range); its constructor refuses non-finite
        // data, and the checked evaluation is `BezierCurve`'s (`bezier_and_hermite_curves`).
        if let Ok(p) = no_panic("Bernstein::new", || Bernstein::new(vec![0.0, x, 1.0], (t0, t1)))? {
            prop_assert!(p.control_points().iter().all(|v| v.is_finite()));
            let _ = no_panic("derivative_at_start", || p.derivative_at_start(1))?;
            let _ = no_panic("eval", || p.eval(&t))?;
        }
        if let Ok(data) = no_panic("HermiteData::new", || HermiteData::new(vec![0.0, x], vec![1.0, w], (t0, t1)))? {
            if let Ok(b) = no_panic("solve", || data.solve())? {
                prop_assert!(b.control_points().iter().all(|v| v.is_finite()), "Ok holding {:?}", b.control_points());
            }
        }
    }

    /// Dubins poses, PH frames and the everyday queries on hostile parameters.
    #[test]
    fn poses_frames_and_queries(a in hostile_f64(), s in hostile_f64(), t in hostile_f64(), q in hostile_f64()) {
        use trajverify::algo::gerbs::dubins::shortest;
        use trajverify::curve::parametric::ParamCurveFrame;
        use trajverify::curve::query::{extrema, nearest_point, points_at, Subsegment};
        if let Some(d) = shortest(&[0.0, 0.0, 0.3], &[40.0, 10.0, a], &5.0) {
            if let Ok(p) = no_panic("pose_at", || d.pose_at(&s))? {
                prop_assert!(p.iter().all(|v| v.is_finite()), "Ok holding {p:?}");
            }
        }
        let curve = ExprCurve::parse("[cos(t), sin(t), t/5]").expect("a curve").compile::<f64>(&());
        let Ok(pw) = fit(&curve, (&0.0, &3.0), &FitOptions { segments: 4, ..FitOptions::default() }) else { return Ok(()) };
        if let Ok(f) = no_panic("frame", || pw.frame(&t))? {
            prop_assert!(f.omega.iter().all(|v| v.is_finite()), "Ok holding {f:?}");
        }
        if let Ok(p) = no_panic("points_at", || points_at(&pw, &[t, 1.0]))? {
            prop_assert!(all_finite(&p), "Ok holding {p:?}");
        }
        if let Ok(n) = no_panic("nearest_point", || nearest_point(&pw, &[q, 0.0, 0.5]))? {
            prop_assert!(n.distance.is_finite() && n.t.is_finite(), "Ok holding {n:?}");
        }
        if let Ok(part) = no_panic("Subsegment::new", || Subsegment::new(&pw, (t, s)))? {
            let e = no_panic("extrema", || extrema(&part))?;
            prop_assert!(e.is_ok(), "{e:?}");
        }
    }
}
