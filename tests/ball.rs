//! The ball scalar (`ball:<bits>`): every enclosure contains the value a much higher MPFR
//! precision computes, through single operations and through the generic algorithms; a
//! deliberately wrong bound is caught; overlapping comparisons are undecided and counted.

use trajverify::algo::hermite::HermiteData;
use trajverify::algo::ph::hermite::{interpolate, FreeParameters, HermiteData as PhData};
use trajverify::scalar::ball::{undecided_comparisons, Ball};
use trajverify::scalar::{Field, Float, Real};

const REFERENCE_BITS: u32 = 1024;

/// A fixed expression using every operation with a derivative bound of its own.
fn expression<T: Real>(a: &T, b: &T, c: &T) -> T {
    let ctx = a.ctx();
    let one = T::one_in(&ctx);
    let r = (a.clone() * a + &(b.clone() * b)).sqrt();
    let (s, co) = (c.clone() / &T::from_i64(3, &ctx)).sin_cos();
    let angle = b.atan2(&(a.clone() + &T::from_i64(10, &ctx)));
    let log = (one.clone() + &(a.clone() * a)).ln();
    r * &(c.clone() / &T::from_i64(7, &ctx)).exp() - &(log * &s / &co) + &angle
        - &(one / &(b.clone() - &T::from_ratio(1, 3, &ctx)))
}

fn rational(n: i64, d: i64) -> trajverify::scalar::BigRational {
    trajverify::scalar::BigRational::new(n.into(), d.into())
}

#[test]
fn single_operations_enclose_the_reference() {
    for (i, (n1, n2, n3)) in [
        (3, -7, 5),
        (-11, 2, 1),
        (1, 2, -13),
        (29, 5, 2),
        (-2, 17, 40),
    ]
    .iter()
    .enumerate()
    {
        let (a, b, c) = (rational(*n1, 7), rational(*n2, 3), rational(*n3, 5));
        for bits in [53, 64, 200] {
            let ball = expression(
                &Ball::from_rational(&a, &bits),
                &Ball::from_rational(&b, &bits),
                &Ball::from_rational(&c, &bits),
            );
            let reference = expression(
                &Float::from_rational(&a, &REFERENCE_BITS),
                &Float::from_rational(&b, &REFERENCE_BITS),
                &Float::from_rational(&c, &REFERENCE_BITS),
            );
            assert!(
                ball.contains(&reference),
                "case {i} at {bits} bits: {ball:?} misses {reference}"
            );
            // And the enclosure is not vacuous: about the working precision.
            let relative = ball.rad() / reference.to_f64().abs();
            assert!(
                relative < 2f64.powi(10 - bits as i32),
                "case {i}: radius {relative:e} too wide"
            );
        }
    }
}

#[test]
fn a_deliberately_wrong_bound_fails() {
    // 1/3 and √2 are not representable: the same midpoints with the rounding bound removed
    // (radius 0) must no longer contain the true values.
    let third = Ball::from_ratio(1, 3, &64);
    let root = Ball::from_i64(2, &64).sqrt();
    let exact_third = Float::with_val(REFERENCE_BITS, 1) / 3u32;
    assert!(third.contains(&exact_third));
    assert!(root.contains(&Float::with_val(REFERENCE_BITS, 2).sqrt()));
    let stripped = |b: &Ball| Ball::new(b.mid().clone(), 0.0);
    assert!(!stripped(&third).contains(&exact_third));
    assert!(!stripped(&root).contains(&Float::with_val(REFERENCE_BITS, 2).sqrt()));
    // A radius below the actual error of the midpoint is caught as well.
    let exact_root = Float::with_val(REFERENCE_BITS, 2).sqrt();
    let err = Float::with_val(REFERENCE_BITS, root.mid() - &exact_root)
        .abs()
        .to_f64();
    assert!(err > 0.0 && err <= root.rad());
    assert!(!Ball::new(root.mid().clone(), err / 2.0).contains(&exact_root));
}

#[test]
fn overlapping_comparisons_are_undecided_and_counted() {
    let x = Ball::new(Float::with_val(64, 1), 0.5);
    let y = Ball::new(Float::with_val(64, 1.2), 0.5);
    let z = Ball::new(Float::with_val(64, 3), 0.5);
    let before = undecided_comparisons();
    assert_eq!(x.partial_cmp(&y), None);
    // Neither `<` nor `>` holds: an undecided comparison is never a guess either way.
    let (less, greater) = (x.lt(&y), x.gt(&y));
    assert!(!less && !greater);
    assert!(undecided_comparisons() >= before + 3);
    assert_eq!(x.partial_cmp(&z), Some(std::cmp::Ordering::Less));
    assert_eq!(z.partial_cmp(&x), Some(std::cmp::Ordering::Greater));
    // Exact balls compare exactly.
    assert_eq!(Ball::from_i64(2, &64), Ball::from_i64(2, &64));
    // A ball containing 0 is not "exactly zero"; division by it is unbounded.
    let around_zero = Ball::new(Float::with_val(64, 0), 1e-30);
    assert!(!around_zero.is_zero());
    assert!(!(Ball::from_i64(1, &64) / &around_zero).is_finite());
}

/// Every number of an f64-free generic computation, in balls at `bits`, against MPFR at 1024.
fn assert_contained(balls: &[Ball], reference: &[Float], what: &str) {
    assert_eq!(balls.len(), reference.len());
    for (i, (b, r)) in balls.iter().zip(reference).enumerate() {
        assert!(b.contains(r), "{what}[{i}]: {b:?} misses {r}");
    }
}

#[test]
fn the_hermite_map_encloses_the_reference() {
    fn control_points<T: Field>(ctx: &T::Ctx) -> Vec<T> {
        let v = |n: i64, d: i64| T::from_ratio(n, d, ctx);
        let data = HermiteData::new(
            vec![v(0, 1), v(1, 3), v(-2, 7), v(5, 11)],
            vec![v(1, 1), v(0, 1), v(3, 13), v(-1, 17)],
            (v(0, 1), v(3, 7)),
        )
        .unwrap();
        data.solve().unwrap().into_control_points()
    }
    assert_contained(
        &control_points::<Ball>(&128),
        &control_points::<Float>(&REFERENCE_BITS),
        "hermite",
    );
}

#[test]
fn the_ph_interpolant_encloses_the_reference() {
    fn points<T: Real>(ctx: &T::Ctx) -> Vec<T> {
        let v = |x: (i64, i64), y: (i64, i64), z: (i64, i64)| {
            [
                T::from_ratio(x.0, x.1, ctx),
                T::from_ratio(y.0, y.1, ctx),
                T::from_ratio(z.0, z.1, ctx),
            ]
        };
        let data = PhData {
            p_b: v((0, 1), (0, 1), (0, 1)),
            p_e: v((1, 1), (1, 2), (1, 3)),
            start: vec![
                v((1, 1), (0, 1), (1, 5)),
                v((0, 1), (1, 3), (0, 1)),
                v((1, 7), (0, 1), (-1, 9)),
                v((0, 1), (0, 1), (1, 11)),
            ],
            end: vec![
                v((1, 2), (1, 1), (0, 1)),
                v((-1, 3), (0, 1), (1, 4)),
                v((0, 1), (1, 6), (0, 1)),
                v((1, 13), (0, 1), (0, 1)),
            ],
        };
        let curve = interpolate(&data, &FreeParameters::zero(4, ctx)).unwrap();
        let mut out: Vec<T> = curve.control_points().into_iter().flatten().collect();
        out.push(curve.arc_length());
        out
    }
    let balls = points::<Ball>(&256);
    assert_contained(&balls, &points::<Float>(&REFERENCE_BITS), "ph");
    // The enclosures are tight: every radius below 1e-60 of the largest coordinate.
    assert!(balls.iter().all(|b| b.rad() < 1e-60), "{balls:?}");
}
