//! The proven enclosure of max‖γ − p‖ (`curve::enclosure`) holds the certified maximum and is
//! narrow, for an analytic curve and for a spline through data (whose seams it must account
//! for: without them the "proof" excludes the true value).

use trajverify::algo::ph::hermite::FreeParameters;
use trajverify::algo::ph::piecewise::{certified_error, convert};
use trajverify::curve::enclosure::{proven_error, ProofOptions};
use trajverify::curve::interval::Interval;
use trajverify::curve::{Curve, ExprCurve};
use trajverify::scalar::ball::Ball;
use trajverify::scalar::{BigRational, Field, Float, Real};
const CURVE: &str = "[1.5*sin(7.2*t), cos(9*t), exp(cos(1.8*t))]";

/// The test curve, zero free parameters and [0, 1]: the conversion problem given exactly.
fn exact_problem() -> (
    ExprCurve,
    FreeParameters<BigRational>,
    (BigRational, BigRational),
) {
    (
        ExprCurve::parse(CURVE).unwrap(),
        FreeParameters::zero(4, &()),
        (
            BigRational::from_integer(0.into()),
            BigRational::from_integer(1.into()),
        ),
    )
}

/// The test curve in balls at 256 bits and its C⁴ conversion on `n` segments of [0, 1].
fn in_balls(
    n: usize,
) -> (
    trajverify::curve::CompiledCurve<Ball>,
    trajverify::algo::ph::piecewise::PiecewisePh<Ball>,
) {
    let curve = ExprCurve::parse(CURVE).unwrap().compile::<Ball>(&256);
    let pw = convert(
        &curve,
        (&Ball::from_i64(0, &256), &Ball::from_i64(1, &256)),
        n,
        4,
        &FreeParameters::zero(4, &256),
        false,
    )
    .unwrap();
    (curve, pw)
}

#[test]
fn the_enclosure_contains_the_certified_maximum_and_is_narrow() {
    let (c, zero, (a, b)) = exact_problem();
    // 128 segments: the whole-segment remainders come from shared bounds of γ^(18).
    for n in [1usize, 4, 64, 128] {
        let (curve, pw) = in_balls(n);
        let e = proven_error(&curve, &pw, &ProofOptions::default()).unwrap();
        let certified = certified_error(
            |bits| c.compile::<Float>(&bits),
            &Interval::new(a.clone(), b.clone()).unwrap(),
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
            (&Ball::from_i64(0, &256), &Ball::from_i64(2, &256)),
            n,
            4,
            &FreeParameters::zero(4, &256),
            false,
        )
        .unwrap();
        proven_error(curve, &pw, &ProofOptions::default()).unwrap()
    };
    let mut hidden_excludes = false;
    for n in [1usize, 8] {
        let certified = certified_error(
            |_| spline.clone(),
            &Interval::new(a.clone(), b.clone()).unwrap(),
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
    use trajverify::algo::hermite::piecewise::{interpolate_curve, InterpolationOptions};
    use trajverify::curve::approx::certified_max_error;
    let c = ExprCurve::parse("[1.5*sin(7.2*t), cos(9*t), exp(cos(1.8*t))]").unwrap();
    for (m, n) in [(2usize, 1usize), (3, 8), (8, 2)] {
        let certified = certified_max_error(
            |bits| c.compile::<Float>(&bits),
            |curve, bits| {
                let (a, b) = (Float::with_val(bits, 0), Float::with_val(bits, 1));
                interpolate_curve(
                    curve,
                    (&a, &b),
                    &InterpolationOptions {
                        segments: n,
                        derivatives: m,
                    },
                )
            },
            128,
            256,
        )
        .unwrap()
        .hi;
        let curve = c.compile::<Ball>(&256);
        let (a, b) = (Ball::from_i64(0, &256), Ball::from_i64(1, &256));
        let fit = interpolate_curve(
            &curve,
            (&a, &b),
            &InterpolationOptions {
                segments: n,
                derivatives: m,
            },
        )
        .unwrap();
        let e = proven_error(&curve, &fit, &ProofOptions::default()).unwrap();
        assert!(
            e.lower <= certified && certified <= e.upper,
            "m = {m}, n = {n}: [{}, {}] misses {certified}",
            e.lower,
            e.upper
        );
        assert!(e.relative_width() <= 1e-6, "m = {m}, n = {n}");
    }
}

/// The test curve's conversion on `n` segments in balls, its error models and enclosure.
fn models_of(
    n: usize,
) -> (
    trajverify::algo::ph::piecewise::PiecewisePh<Ball>,
    trajverify::curve::enclosure::ErrorModels,
    trajverify::curve::enclosure::ErrorEnclosure,
) {
    use trajverify::curve::enclosure::ErrorModels;
    let (curve, pw) = in_balls(n);
    let models = ErrorModels::build(&curve, &pw, 1e-6, None);
    let e = models.enclose(1e-6, 200_000, None);
    (pw, models, e)
}

#[test]
fn outside_the_regions_reaching_a_threshold_the_error_is_proven_below_it() {
    use trajverify::numeric::poly::bernstein::bernstein_jet;
    use trajverify::numeric::quat::vec3;
    let n = 16;
    let (pw, models, e) = models_of(n);
    let curve = ExprCurve::parse(CURVE).unwrap().compile::<Ball>(&256);
    let threshold = e.lower.to_f64() * 0.7;
    let regions = models.regions_reaching(threshold, 1.0 / 32.0);
    let h = Ball::from_ratio(1, n as i64, &256);
    let (mut outside, mut total) = (0, 0);
    for k in 0..n {
        let points = pw.segments()[k].control_points();
        for j in 0..=200 {
            let xi = f64::from(j) / 200.0;
            total += 1;
            if regions
                .iter()
                .any(|r| r.segment == k && r.lo <= xi && xi <= r.hi)
            {
                continue;
            }
            outside += 1;
            let u = Ball::from_f64(xi, &256);
            let t = Ball::from_i64(k as i64, &256) * &h + &(h.clone() * &u);
            let d = vec3::sub(&curve.jet(&t, 0)[0], &bernstein_jet(&points, &u, 0)[0]);
            let norm = vec3::dot(&d, &d).sqrt();
            assert!(
                norm.upper().to_f64() < threshold,
                "segment {k}, ξ = {xi}: {} ≥ {threshold}",
                norm.upper()
            );
        }
    }
    // The screen must leave most points out to be worth anything, and keep the maximum.
    assert!(outside * 2 > total, "{outside} of {total} points left out");
    assert!(regions.iter().any(|r| r.segment == e.segment));
}

#[test]
fn a_screened_grid_gives_the_full_grids_maxima_bit_for_bit() {
    use trajverify::algo::ph::grid::{certified_grid_error, ErrorScreen};
    let (c, zero, (a, b)) = exact_problem();
    for n in [4usize, 64] {
        let (_, models, e) = models_of(n);
        // linspace(1e-6, 1, 100·n), as the authors' code evaluates it, and a grid through
        // every knot (where the screen locates points exactly rather than in f64).
        let m = 100 * n as i64;
        let authors: Vec<BigRational> = (0..m)
            .map(|j| BigRational::new((m - 1 + 999_999 * j).into(), (1_000_000 * (m - 1)).into()))
            .collect();
        let knots: Vec<BigRational> = (0..=16 * n as i64)
            .map(|j| BigRational::new(j.into(), (16 * n as i64).into()))
            .collect();
        for ts in [authors, knots] {
            let grid = |screen: Option<&ErrorScreen>| {
                certified_grid_error(
                    |bits| c.compile::<Float>(&bits),
                    (&a, &b),
                    n,
                    4,
                    &zero,
                    &ts,
                    (128, 256),
                    screen,
                )
                .unwrap()
            };
            let full = grid(None);
            let screen = ErrorScreen {
                models: &models,
                seed_segment: e.segment,
            };
            // Any segment to start from gives the same maxima; so does the worst one.
            for seed in [e.segment, 0] {
                let screened = grid(Some(&ErrorScreen {
                    seed_segment: seed,
                    ..screen
                }));
                assert_eq!(full, screened, "n = {n}, seed segment {seed}");
            }
        }
    }
}

#[test]
fn a_screened_search_finds_the_full_searchs_maximum_bit_for_bit() {
    use trajverify::algo::ph::grid::ErrorScreen;
    use trajverify::algo::ph::piecewise::certified_error_screened;
    let (c, zero, (a, b)) = exact_problem();
    for n in [4usize, 128] {
        let (_, models, e) = models_of(n);
        let search = |screen: Option<&ErrorScreen>| {
            certified_error_screened(
                |bits| c.compile::<Float>(&bits),
                &Interval::new(a.clone(), b.clone()).unwrap(),
                n,
                4,
                &zero,
                (128, 256),
                screen,
            )
            .unwrap()
        };
        let full = search(None);
        for seed in [e.segment, 0] {
            let screened = search(Some(&ErrorScreen {
                models: &models,
                seed_segment: seed,
            }));
            let same = (
                &screened.lo,
                &screened.hi,
                &screened.sampled,
                screened.segment,
                &screened.xi,
            ) == (&full.lo, &full.hi, &full.sampled, full.segment, &full.xi);
            assert!(
                same,
                "n = {n}, seed segment {seed}: {screened:?} vs {full:?}"
            );
        }
    }
}
