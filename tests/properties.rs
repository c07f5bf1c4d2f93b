//! Property tests of the mathematics on random data (proptest).

use proptest::prelude::*;
use trajverify::algo::hermite::HermiteData;
use trajverify::numeric::linalg::{self, reference, Matrix};
use trajverify::numeric::poly::bernstein::{basis, power_basis_derivative};
use trajverify::numeric::poly::Bernstein;
use trajverify::scalar::parse::parse_rational;
use trajverify::scalar::{BigRational, Field, Float};

fn q(n: i64, d: i64) -> BigRational {
    BigRational::new(n.into(), d.into())
}

fn rational() -> impl Strategy<Value = BigRational> {
    (-500i64..=500, 1i64..=60).prop_map(|(n, d)| q(n, d))
}

/// m, start and end data of length m+1, and an interval t0 < t1.
fn hermite_data() -> impl Strategy<Value = HermiteData<BigRational>> {
    (0usize..=8).prop_flat_map(|m| {
        (
            prop::collection::vec(rational(), m + 1),
            prop::collection::vec(rational(), m + 1),
            rational(),
            (1i64..=400, 1i64..=40),
        )
            .prop_map(|(start, end, t0, (w, d))| {
                let t1 = t0.clone() + q(w, d);
                HermiteData::new(start, end, (t0, t1)).expect("valid by construction")
            })
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Random Hermite data round-trip exactly through the derivative formulas: the power-basis
    /// derivatives of the solution at both ends are the data.
    #[test]
    fn hermite_meets_every_boundary_condition(data in hermite_data()) {
        let curve = data.solve().unwrap();
        prop_assert_eq!(curve.degree(), 2 * data.derivatives() + 1);
        let a = curve.to_power_basis();
        for j in 0..=data.derivatives() {
            prop_assert_eq!(&power_basis_derivative(&a, j, &q(0, 1), &curve.duration()), &data.start()[j]);
            prop_assert_eq!(&power_basis_derivative(&a, j, &q(1, 1), &curve.duration()), &data.end()[j]);
            prop_assert_eq!(&curve.derivative_at_start(j), &data.start()[j]);
            prop_assert_eq!(&curve.derivative_at_end(j), &data.end()[j]);
        }
    }

    /// Reversing time maps the solution to the reversed control polygon (the problem on
    /// [t0, t1] with the ends swapped and odd derivatives negated).
    #[test]
    fn hermite_reversal(data in hermite_data()) {
        let flip = |v: &[BigRational]| v.iter().enumerate().map(|(j, x)| if j % 2 == 1 { -x.clone() } else { x.clone() }).collect::<Vec<_>>();
        let reversed = HermiteData::new(flip(data.end()), flip(data.start()), (data.interval().0.clone(), data.interval().1.clone())).unwrap();
        let mut p = data.solve().unwrap().into_control_points();
        p.reverse();
        prop_assert_eq!(reversed.solve().unwrap().into_control_points(), p);
    }

    /// f64 agrees with MPFR-256 where the transform is well conditioned (m ≤ 3, T ≈ 1).
    #[test]
    fn f64_agrees_with_mpfr_when_well_conditioned(
        start in prop::collection::vec(-10.0f64..10.0, 4),
        end in prop::collection::vec(-10.0f64..10.0, 4),
        width in 0.5f64..2.0,
    ) {
        let fast = HermiteData::new(start.clone(), end.clone(), (0.0, width)).unwrap().solve().unwrap();
        let to = |v: &[f64]| v.iter().map(|x| Float::with_val(256, *x)).collect::<Vec<_>>();
        let precise = HermiteData::new(to(&start), to(&end), (Float::with_val(256, 0), Float::with_val(256, width))).unwrap().solve().unwrap();
        let scale = start.iter().chain(&end).fold(1.0f64, |s, x| s.max(x.abs()));
        for (a, b) in fast.control_points().iter().zip(precise.control_points()) {
            prop_assert!((a - b.to_f64()).abs() <= 1e-13 * scale, "{} vs {}", a, b.to_f64());
        }
    }

    /// The Bernstein basis on any interval is a partition of unity (exactly).
    #[test]
    fn partition_of_unity(n in 0usize..=20, t0 in rational(), (w, d) in (1i64..=100, 1i64..=10), zeta in 0i64..=50) {
        let t1 = t0.clone() + q(w, d);
        let t = t0.clone() + (t1.clone() - &t0) * q(zeta, 50);
        let total = (0..=n).fold(q(0, 1), |acc, k| acc + basis(n, k, &t, (&t0, &t1)));
        prop_assert_eq!(total, q(1, 1));
    }

    /// Degree elevation keeps every value of the curve.
    #[test]
    fn elevation_keeps_values(points in prop::collection::vec(rational(), 1..10), times in 1usize..4, zeta in 0i64..=20) {
        let b = Bernstein::new(points, (q(-1, 1), q(3, 1))).unwrap();
        let e = b.elevate_by(times);
        let t = q(-1, 1) + q(4 * zeta, 20);
        prop_assert_eq!(b.eval(&t), e.eval(&t));
    }

    /// Gaussian elimination solves random non-singular rational systems exactly.
    #[test]
    fn exact_solve(entries in prop::collection::vec(rational(), 16), x in prop::collection::vec(rational(), 4)) {
        let a = Matrix::from_fn(4, 4, |i, j| entries[4 * i + j].clone() + if i == j { q(1000, 1) } else { q(0, 1) });
        let b = a.mul_vec(&x);
        prop_assert_eq!(linalg::solve(&a, &b).unwrap(), x);
    }

    /// The generic Jacobi singular values match nalgebra's on random f64 matrices.
    #[test]
    fn jacobi_matches_nalgebra(entries in prop::collection::vec(-5.0f64..5.0, 30)) {
        let a = Matrix::from_fn(6, 5, |i, j| entries[5 * i + j]);
        let ours = linalg::singular_values(&a).unwrap();
        let theirs = reference::singular_values(&a);
        for (x, y) in ours.iter().zip(&theirs) {
            prop_assert!((x - y).abs() <= 1e-12 * theirs[0], "{} vs {}", x, y);
        }
    }

    /// Decimal strings convert to f64 with exactly the rounding Rust's own parser gives.
    #[test]
    fn decimal_to_f64_is_correctly_rounded(mantissa in 0u64..u64::MAX, point in 0usize..19, exp in -320i32..300, neg in any::<bool>()) {
        let digits = mantissa.to_string();
        let point = point.min(digits.len());
        let text = format!("{}{}.{}e{}", if neg { "-" } else { "" }, &digits[..point], &digits[point..], exp);
        let ours = f64::from_rational(&parse_rational(&text).unwrap(), &());
        prop_assert_eq!(ours, text.parse::<f64>().unwrap(), "{}", text);
    }
}

mod bspline {
    use super::*;
    use trajverify::algo::bspline::fit::SplineSpace;
    use trajverify::algo::bspline::CardinalBSpline;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(32))]

        /// The shifted B-splines sum to one at any point inside the fully covered range.
        #[test]
        fn partition_of_unity(k in 0usize..=7, n in 0i64..=1000) {
            let b = CardinalBSpline::<BigRational>::from_algorithm1(k, &());
            let t = q(k as i64, 1) + q(n, 1000); // inside [k, k+1]
            let total = (0..=k as i64 + 1).fold(q(0, 1), |acc, i| acc + b.eval(&(t.clone() - q(i, 1))));
            prop_assert_eq!(total, q(1, 1));
        }

        /// Smoothing with a huge weight is close to interpolation, and both meet the problem's shape.
        #[test]
        fn smoothing_approaches_interpolation(values in prop::collection::vec(-50i64..50, 4), fracs in prop::collection::vec(1i64..10, 4)) {
            let space = SplineSpace::<BigRational>::new(3, 8, &()).unwrap();
            // One time inside each of the unit intervals 1, 3, 5, 7 (Schoenberg–Whitney holds).
            let times: Vec<BigRational> = fracs.iter().enumerate().map(|(i, f)| q(10 * (2 * i as i64 + 1) + f, 10)).collect();
            let alpha: Vec<BigRational> = values.iter().map(|&v| q(v, 1)).collect();
            let tau = space.interpolate(&times, &alpha).unwrap();
            for (t, a) in times.iter().zip(&alpha) {
                prop_assert_eq!(&space.eval(&tau, t), a);
            }
            let near = space.smooth(&times, &alpha, &vec![q(1_000_000_000, 1); 4]).unwrap();
            let far = space.smooth(&times, &alpha, &vec![q(1, 1); 4]).unwrap();
            let dist = |x: &[BigRational]| x.iter().zip(&tau).fold(q(0, 1), |s, (a, b)| s + (a.clone() - b) * (a.clone() - b));
            prop_assert!(dist(&near) <= dist(&far));
        }
    }
}

mod parametrization {
    use super::*;
    use trajverify::algo::param::objective::{objective, Objective};
    use trajverify::algo::param::one_d::minimizing_parametrization;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(32))]

        /// The exact 1-D minimizer (any case) is not beaten by random perturbations of its spacing.
        #[test]
        fn exact_minimizer_beats_perturbations(steps in prop::collection::vec((1i64..20, any::<bool>()), 3..9), kicks in prop::collection::vec(-100i64..100, 9)) {
            let mut z = vec![q(0, 1)];
            for (s, up) in &steps {
                let next = z[z.len() - 1].clone() + if *up { q(*s, 10) } else { q(-*s, 10) };
                z.push(next);
            }
            let zf: Vec<Float> = z.iter().map(|x| Float::from_rational(x, &128)).collect();
            let (t, _) = minimizing_parametrization(&zf).unwrap();
            let h: Vec<Float> = t.windows(2).map(|w| w[1].clone() - &w[0]).collect();
            let one = [Float::with_val(128, 1)];
            let best = objective(&h, std::slice::from_ref(&zf), &one, Objective::Exact).unwrap();
            // Perturb along a direction with zero sum, small enough to keep every spacing positive.
            let n = h.len();
            let mean = kicks[..n].iter().sum::<i64>() as f64 / n as f64;
            let min_h = h.iter().map(|x| x.to_f64()).fold(f64::INFINITY, f64::min);
            let moved: Vec<Float> = h.iter().enumerate().map(|(i, x)| x.clone() + (kicks[i] as f64 - mean) * min_h * 1e-3).collect();
            let other = objective(&moved, std::slice::from_ref(&zf), &one, Objective::Exact).unwrap();
            prop_assert!(best <= other, "{} > {}", best.to_f64(), other.to_f64());
        }
    }
}

/// Paper 001: Algorithm 1 on random C⁴ data, in f64 and MPFR, and Theorems 3–4.
mod ph_interpolation {
    use proptest::prelude::*;
    use trajverify::algo::ph::bernstein_jet;
    use trajverify::algo::ph::hermite::{interpolate, FreeParameters, HermiteData};
    use trajverify::numeric::quat::vec3;
    use trajverify::scalar::{Field, Float};

    fn vector() -> impl Strategy<Value = [i64; 3]> {
        [-20i64..=20, -20i64..=20, -20i64..=20]
    }

    /// Ten random vectors (entries k/10) with v_b, v_e and v_b + v_e non-zero, and φ.
    fn data() -> impl Strategy<Value = (Vec<[i64; 3]>, Vec<i64>)> {
        (
            prop::collection::vec(vector(), 10),
            prop::collection::vec(-10i64..=10, 8),
        )
            .prop_filter("non-degenerate tangents", |(v, _)| {
                let nz = |a: [i64; 3]| a != [0, 0, 0];
                nz(v[2])
                    && nz(v[3])
                    && nz([v[2][0] + v[3][0], v[2][1] + v[3][1], v[2][2] + v[3][2]])
            })
    }

    fn build<T: Field>(
        v: &[[i64; 3]],
        phi: &[i64],
        ctx: &T::Ctx,
    ) -> (HermiteData<T>, FreeParameters<T>) {
        let p = |a: [i64; 3]| a.map(|x| T::from_ratio(x, 10, ctx));
        let data = HermiteData {
            p_b: p(v[0]),
            p_e: p(v[1]),
            start: vec![p(v[2]), p(v[4]), p(v[6]), p(v[8])],
            end: vec![p(v[3]), p(v[5]), p(v[7]), p(v[9])],
        };
        let f = |x: i64| T::from_ratio(x, 10, ctx);
        let free = FreeParameters {
            theta_start: f(phi[0]),
            theta_mid: T::zero_in(ctx),
            theta_end: f(phi[7]),
            tau_start: vec![f(phi[1]), f(phi[2]), f(phi[3])],
            tau_end: vec![f(phi[6]), f(phi[5]), f(phi[4])],
        };
        (data, free)
    }

    fn worst_residual<T: trajverify::scalar::Real>(
        data: &HermiteData<T>,
        free: &FreeParameters<T>,
    ) -> f64 {
        let c = interpolate(data, free).expect("non-degenerate data");
        let pts = c.control_points();
        let ctx = data.p_b[0].ctx();
        let s = bernstein_jet(&pts, &T::zero_in(&ctx), 4);
        let e = bernstein_jet(&pts, &T::one_in(&ctx), 4);
        let mut worst = vec3::norm(&vec3::sub(&s[0], &data.p_b)).to_f64();
        worst = worst.max(vec3::norm(&vec3::sub(&e[0], &data.p_e)).to_f64());
        for k in 0..4 {
            worst = worst.max(vec3::norm(&vec3::sub(&s[k + 1], &data.start[k])).to_f64());
            worst = worst.max(vec3::norm(&vec3::sub(&e[k + 1], &data.end[k])).to_f64());
        }
        worst
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]

        /// The interpolant meets all ten boundary vectors for any free parameters.
        #[test]
        fn algorithm_1_interpolates(( v, phi) in data()) {
            let (d, f) = build::<f64>(&v, &phi, &());
            prop_assert!(worst_residual(&d, &f) < 1e-8);
            let (d, f) = build::<Float>(&v, &phi, &200);
            prop_assert!(worst_residual(&d, &f) < 1e-50);
        }

        /// f64 and MPFR give the same curve where the data are well conditioned.
        #[test]
        fn f64_agrees_with_mpfr((v, phi) in data()) {
            let (d, f) = build::<f64>(&v, &phi, &());
            let a = interpolate(&d, &f).unwrap().control_points();
            let (d, f) = build::<Float>(&v, &phi, &200);
            let b = interpolate(&d, &f).unwrap().control_points();
            let scale = b.iter().map(|p| vec3::norm(p).to_f64()).fold(1.0, f64::max);
            for (x, y) in a.iter().zip(&b) {
                for k in 0..3 {
                    prop_assert!((x[k] - y[k].to_f64()).abs() < 1e-7 * scale);
                }
            }
        }

        /// Theorem 4: reversed data with −φ (ends exchanged) trace the same curve backwards.
        #[test]
        fn reversion((v, phi) in data()) {
            let (d, f) = build::<Float>(&v, &phi, &200);
            let a = interpolate(&d, &f).unwrap().control_points();
            let swapped = FreeParameters {
                theta_start: -f.theta_end.clone(),
                theta_mid: -f.theta_mid.clone(),
                theta_end: -f.theta_start.clone(),
                tau_start: f.tau_end.iter().map(|x| -x.clone()).collect(),
                tau_end: f.tau_start.iter().map(|x| -x.clone()).collect(),
            };
            let mut b = interpolate(&d.reversed(), &swapped).unwrap().control_points();
            b.reverse();
            for (x, y) in a.iter().zip(&b) {
                prop_assert!(vec3::norm(&vec3::sub(x, y)).to_f64() < 1e-50);
            }
        }
    }
}

/// Paper 003: GERBS bases and paths on random knots and waypoints.
mod gerbs {
    use proptest::prelude::*;
    use trajverify::algo::gerbs::bfbs::Bfbs;
    use trajverify::algo::gerbs::erbs::{CentreReading, Erbs, ErbsParams};
    use trajverify::algo::gerbs::path::{
        check_waypoints, local_curves, tangents, ArcConvention, GerbsPath, PathSpec,
    };
    use trajverify::algo::gerbs::{basis_derivatives, Blend, Knots, Side};
    use trajverify::scalar::{BigRational, Real};

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    /// Increasing rational knots from positive steps k/7, the end pairs doubled or not.
    fn knots() -> impl Strategy<Value = Knots<BigRational>> {
        (
            prop::collection::vec(1i64..=20, 2..7),
            any::<bool>(),
            any::<bool>(),
        )
            .prop_map(|(steps, double_start, double_end)| {
                let mut t = vec![q(0, 1)];
                if double_start {
                    t.push(q(0, 1));
                }
                for s in steps {
                    let last = t[t.len() - 1].clone();
                    t.push(last + q(s, 7));
                }
                if double_end {
                    t.push(t[t.len() - 1].clone());
                }
                Knots::new(t).expect("increasing")
            })
            .prop_filter("a non-empty [t_2, t_{n+1}]", |k| k.basis_count() >= 2)
    }

    /// n = 3…7 waypoints marching in x with random offsets, no collinear triple.
    fn waypoints() -> impl Strategy<Value = Vec<[i64; 2]>> {
        prop::collection::vec((-40i64..=40, -150i64..=150), 3..=7)
            .prop_map(|offsets| {
                offsets
                    .iter()
                    .enumerate()
                    .map(|(i, (dx, dy))| [300 * i as i64 + dx, *dy])
                    .collect()
            })
            .prop_filter("a defined turn at every waypoint", |w: &Vec<[i64; 2]>| {
                let r: Vec<[BigRational; 2]> = w.iter().map(|p| [q(p[0], 1), q(p[1], 1)]).collect();
                check_waypoints(&r).is_ok()
            })
    }

    fn spec<T: Real>(w: &[[i64; 2]], radius: i64, ctx: &T::Ctx) -> PathSpec<T> {
        PathSpec {
            waypoints: w
                .iter()
                .map(|p| [T::from_i64(p[0], ctx), T::from_i64(p[1], ctx)])
                .collect(),
            radius: T::from_i64(radius, ctx),
            theta_o: T::pi(ctx) / &T::from_i64(8, ctx),
            line_length: None,
            convention: ArcConvention::TurnDirection,
            turns: None,
            end_curves: Default::default(),
        }
    }

    fn erbs(n: usize, beta: i64, lambda: i64) -> Erbs<f64> {
        let knots = Knots::<f64>::uniform(n, &()).expect("knots");
        let p = ErbsParams::new(1.0, beta as f64, 1.0, lambda as f64 / 10.0, 1.0).expect("params");
        Erbs::new(&knots, vec![p], CentreReading::Cited).expect("erbs")
    }

    /// p(t_k) = W_{k−1}, p′(t_k) along m (travel direction), κ(t_k) = s/R at the arcs.
    #[allow(clippy::needless_range_loop)] // i indexes waypoints, knots and tangents together
    fn check_interpolation<B: Blend<f64>>(path: &GerbsPath<f64, B>, w: &[[i64; 2]], radius: i64) {
        let n = w.len();
        for i in 0..n {
            let t = *path.knots().get(i + 1).unwrap();
            let p = path
                .at(&t, if i + 1 == n { Side::Left } else { Side::Right })
                .unwrap();
            let scale = 1e-9 * (1.0 + w[i][0].abs().max(w[i][1].abs()) as f64);
            assert!(
                (p.point[0] - w[i][0] as f64).abs() < scale,
                "W{}: {:?}",
                i + 1,
                p.point
            );
            assert!(
                (p.point[1] - w[i][1] as f64).abs() < scale,
                "W{}: {:?}",
                i + 1,
                p.point
            );
            let m = path.tangents().m[i];
            let speed = p.d1[0].hypot(p.d1[1]);
            let along = (p.d1[0] * m[0] + p.d1[1] * m[1]) / speed;
            assert!((along - 1.0).abs() < 1e-12, "W{}: cos = {along}", i + 1);
            if i > 0 && i + 1 < n {
                let want = path.tangents().s[i] as f64 / radius as f64;
                assert!(
                    (p.curvature - want).abs() < 1e-12,
                    "W{}: κ = {}",
                    i + 1,
                    p.curvature
                );
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]

        /// Σ B_k = 1 and Σ B_k^(r) = 0 exactly for the BFBS (its falling and rising sides are
        /// computed separately), on random knots, exponents and points of [t_2, t_{n+1}], from
        /// both sides.
        #[test]
        fn bfbs_partition_of_unity_is_exact(
            knots in knots(),
            exponents in prop::collection::vec(1u32..=5, 8),
            frac in 0i64..=1000,
        ) {
            let n = knots.basis_count();
            let bfbs = Bfbs::new(exponents[..n].to_vec()).expect("exponents");
            // The partition holds on [t_2, t_{n+1}] (all of [t_1, t_{n+2}] with doubled ends).
            let (a, b) = (knots.get(1).unwrap().clone(), knots.get(n).unwrap().clone());
            let t = a.clone() + (b.clone() - &a) * q(frac, 1000);
            for side in [Side::Left, Side::Right] {
                // At t_2 from the left (and at t_(n+1) from the right) the derivatives are
                // those of the end interval (t_1, t_2), where only one basis function lives
                // unless the end knot is doubled: outside the partition's domain.
                let outside = (t == a && side == Side::Left && *knots.get(0).unwrap() < a)
                    || (t == b && side == Side::Right && b < *knots.get(n + 1).unwrap());
                if outside {
                    continue;
                }
                let d = basis_derivatives(&knots, &bfbs, &t, 3, side).expect("inside");
                for r in 0..=3 {
                    let sum: BigRational = d.iter().map(|x| x[r].clone()).sum();
                    prop_assert_eq!(sum, q((r == 0) as i64, 1));
                }
            }
        }

        /// The ERBS sums to 1 (f64, random β and λ) and its slopes to 0.
        #[test]
        fn erbs_partition_of_unity(n in 3usize..=7, beta in 1i64..=6, lambda in 2i64..=8, frac in 0i64..=1000) {
            let e = erbs(n, beta, lambda);
            let knots = Knots::<f64>::uniform(n, &()).expect("knots");
            let t = frac as f64 / 1000.0;
            let d = basis_derivatives(&knots, &e, &t, 1, Side::Right).expect("inside");
            let sum: f64 = d.iter().map(|x| x[0]).sum();
            let slope: f64 = d.iter().map(|x| x[1]).sum();
            prop_assert!((sum - 1.0).abs() < 1e-14, "{}", sum);
            prop_assert!(slope.abs() < 1e-9 * d.iter().map(|x| x[1].abs()).fold(1.0, f64::max));
        }

        /// Algorithm 2 interpolates every waypoint along m_i with κ = s_i/R, BFBS and ERBS.
        #[test]
        fn paths_interpolate_random_waypoints(w in waypoints(), radius in 10i64..=100, beta in 1i64..=6) {
            let sp = spec::<f64>(&w, radius, &());
            let bfbs = GerbsPath::new(&sp, Bfbs::uniform(2, w.len()).expect("exponents")).expect("valid");
            check_interpolation(&bfbs, &w, radius);
            let erbs = GerbsPath::new(&sp, erbs(w.len(), beta, 5)).expect("valid");
            check_interpolation(&erbs, &w, radius);
        }

        /// Locality: moving waypoint k (tangents and turns kept) leaves the path bit for bit
        /// unchanged outside the support (t_k, t_{k+2}) of its basis function B_{k+1}.
        #[test]
        fn moving_a_waypoint_changes_only_its_support(
            w in waypoints(),
            pick in 0usize..7,
            (dx, dy) in (-30i64..=30, -30i64..=30),
            samples in prop::collection::vec(0i64..=1000, 24),
        ) {
            let n = w.len();
            let k = pick % n;
            let sp = spec::<f64>(&w, 50, &());
            let tan = tangents(&sp.waypoints).expect("valid");
            let mut moved = sp.clone();
            moved.waypoints[k] = [sp.waypoints[k][0] + dx as f64, sp.waypoints[k][1] + dy as f64];
            let (curves, _) = local_curves(&moved, Some(&tan)).expect("valid");
            let base = GerbsPath::new(&sp, Bfbs::uniform(2, n).expect("exponents")).expect("valid");
            let after = GerbsPath::from_parts(base.knots().clone(), base.blend().clone(), curves.clone(), tan.clone()).unwrap();
            let base_e = GerbsPath::new(&sp, erbs(n, 3, 5)).expect("valid");
            let after_e = GerbsPath::from_parts(base_e.knots().clone(), base_e.blend().clone(), curves, tan).unwrap();
            // B_{k+2} (paper numbering) carries c_{k+1}: support [t_{k+1}, t_{k+3}], knots k to k + 2
            // counted from 0.
            let (lo, hi) = (*base.knots().get(k).unwrap(), *base.knots().get(k + 2).unwrap());
            for s in samples {
                let t = s as f64 / 1000.0;
                if (lo..=hi).contains(&t) {
                    continue;
                }
                prop_assert_eq!(base.at(&t, Side::Right).unwrap().point, after.at(&t, Side::Right).unwrap().point);
                prop_assert_eq!(base_e.at(&t, Side::Right).unwrap().point, after_e.at(&t, Side::Right).unwrap().point);
            }
        }
    }

    /// The moved waypoint does change the path inside its support (the test above can fail).
    #[test]
    fn moving_a_waypoint_changes_the_path_inside_its_support() {
        let w = [[0, 0], [300, 100], [600, -50], [900, 150]];
        let sp = spec::<f64>(&w, 50, &());
        let tan = tangents(&sp.waypoints).expect("valid");
        let mut moved = sp.clone();
        moved.waypoints[1][1] += 10.0;
        let (curves, _) = local_curves(&moved, Some(&tan)).expect("valid");
        let base = GerbsPath::new(&sp, Bfbs::uniform(2, 4).expect("exponents")).expect("valid");
        let after =
            GerbsPath::from_parts(base.knots().clone(), base.blend().clone(), curves, tan).unwrap();
        let t = *base.knots().get(2).unwrap();
        assert_ne!(
            base.at(&t, Side::Right).unwrap().point,
            after.at(&t, Side::Right).unwrap().point
        );
    }
}

/// GMP's and num-rational's rationals give the same exact objective of paper 004 on spacings
/// read from doubles (verify evaluates that claim in GMP's for speed).
#[test]
fn gmp_and_num_rationals_agree_exactly() {
    use trajverify::algo::param::objective::{objective, Objective};
    use trajverify::scalar::{BigRational, Field};
    fn g<T: Field<Ctx = ()>>() -> Option<BigRational> {
        let h: Vec<T> = [0.3, 0.25, 0.45]
            .iter()
            .map(|x| T::from_f64(*x, &()))
            .collect();
        let z: Vec<Vec<T>> = vec![[0, 2, -1, 3].iter().map(|v| T::from_i64(*v, &())).collect()];
        let g = objective(&h, &z, &[T::from_ratio(3, 2, &())], Objective::Exact).ok()?;
        g.to_rational()
    }
    let (num, gmp) = (g::<BigRational>(), g::<rug::Rational>());
    assert!(num.is_some());
    assert_eq!(num, gmp);
}
