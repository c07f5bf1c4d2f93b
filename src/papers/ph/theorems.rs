//! Algorithm 1 on random data, Theorems 2–4, the roll correction (Sec. 5E, Eq. 22) and the
//! geometric quantities of Eq. (13).

use super::super::sample::SplitMix64;
use super::super::{Outcome, Verdict};
use super::table1;
use crate::algo::ph::hermite::{
    interpolate, interpolate_with, FreeParameters, HermiteData, MiddleRule,
};
use crate::algo::ph::piecewise::{
    convert, frame_entries, joint_jumps, omega_components, preimage_components, PiecewisePh,
};
use crate::algo::ph::{bernstein_jet, curvature_torsion, PhCurve};
use crate::curve::integral::{integrate, IntegralOptions};
use crate::curve::taylor::Taylor;
use crate::curve::Curve;
use crate::numeric::quat::{vec3, Quat};
use crate::scalar::ball::Ball;
use crate::scalar::certify::format_float_digits;
use crate::scalar::{BigRational, Field, Float, Real};

/// Precision of the property checks.
pub const BITS: u32 = 256;

fn small(rng: &mut SplitMix64) -> BigRational {
    BigRational::new(rng.int(-20, 20).into(), 10.into())
}

fn vector(rng: &mut SplitMix64) -> [BigRational; 3] {
    [small(rng), small(rng), small(rng)]
}

/// Random C⁴ data with exact rational entries (v_b + v_e ≠ 0 and v_b, v_e ≠ 0 by rejection).
pub fn random_data(rng: &mut SplitMix64) -> HermiteData<BigRational> {
    loop {
        let d = HermiteData {
            p_b: vector(rng),
            p_e: vector(rng),
            start: (0..4).map(|_| vector(rng)).collect(),
            end: (0..4).map(|_| vector(rng)).collect(),
        };
        let nonzero = |v: &[BigRational; 3]| v.iter().any(|x| !Field::is_zero(x));
        if nonzero(&d.start[0]) && nonzero(&d.end[0]) && nonzero(&vec3::add(&d.start[0], &d.end[0]))
        {
            return d;
        }
    }
}

/// Random free parameters in [−1, 1].
pub fn random_free(rng: &mut SplitMix64) -> FreeParameters<BigRational> {
    let mut f = FreeParameters::zero(4, &());
    for x in [&mut f.theta_start, &mut f.theta_end]
        .into_iter()
        .chain(f.tau_start.iter_mut())
        .chain(f.tau_end.iter_mut())
    {
        *x = BigRational::new(rng.int(-10, 10).into(), 10.into());
    }
    f
}

pub(super) fn into<T: Field>(d: &HermiteData<BigRational>, ctx: &T::Ctx) -> HermiteData<T> {
    let v = |x: &[BigRational; 3]| vec3::map(x, |q| T::from_rational(q, ctx));
    HermiteData {
        p_b: v(&d.p_b),
        p_e: v(&d.p_e),
        start: d.start.iter().map(v).collect(),
        end: d.end.iter().map(v).collect(),
    }
}

pub(super) fn free_into<T: Field>(
    f: &FreeParameters<BigRational>,
    ctx: &T::Ctx,
) -> FreeParameters<T> {
    f.map(|q| T::from_rational(q, ctx))
}

/// The largest residual of the ten boundary vectors, relative to the data's size, and of the
/// PH identity σ² = ‖p′‖² at 21 points (relative to σ²).
fn residuals<T: Real>(data: &HermiteData<T>, curve: &PhCurve<T>) -> (f64, f64) {
    let ctx = data.p_b[0].ctx();
    let pts = curve.control_points();
    let (zero, one) = (T::zero_in(&ctx), T::one_in(&ctx));
    let s = bernstein_jet(&pts, &zero, 4);
    let e = bernstein_jet(&pts, &one, 4);
    let mut worst = 0.0f64;
    let mut check = |got: &[T; 3], want: &[T; 3]| {
        let scale = vec3::norm(want).to_f64().max(1.0);
        worst = worst.max(vec3::norm(&vec3::sub(got, want)).to_f64() / scale);
    };
    check(&s[0], &data.p_b);
    check(&e[0], &data.p_e);
    for k in 0..4 {
        check(&s[k + 1], &data.start[k]);
        check(&e[k + 1], &data.end[k]);
    }
    let mut ph = 0.0f64;
    for i in 0..=20 {
        let xi = T::from_ratio(i, 20, &ctx);
        let a = &curve.preimage_jet(&xi, 0)[0];
        let sigma = a.norm2();
        let d = bernstein_jet(&pts, &xi, 1);
        let speed2 = vec3::dot(&d[1], &d[1]);
        let s2 = sigma.clone() * &sigma;
        ph = ph.max(((s2.clone() - &speed2).abs() / &s2).to_f64());
    }
    (worst, ph)
}

/// Algorithm 1 on 40 random data sets with random φ, in f64 and MPFR-256.
pub fn algorithm1() -> (Outcome, Outcome) {
    let mut rng = SplitMix64::new(0x01a1);
    let (mut w64, mut p64, mut wmp, mut pmp) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for _ in 0..40 {
        let d = random_data(&mut rng);
        let f = random_free(&mut rng);
        let (df, ff) = (into::<f64>(&d, &()), free_into::<f64>(&f, &()));
        let c = interpolate(&df, &ff).expect("valid random data");
        let (a, b) = residuals(&df, &c);
        w64 = w64.max(a);
        p64 = p64.max(b);
        let (dm, fm) = (into::<Float>(&d, &BITS), free_into::<Float>(&f, &BITS));
        let c = interpolate(&dm, &fm).expect("valid random data");
        let (a, b) = residuals(&dm, &c);
        wmp = wmp.max(a);
        pmp = pmp.max(b);
    }
    let interp = Outcome::new(
        format!("largest relative residual of the ten boundary vectors: f64 {w64:.1e}, mpfr:{BITS} {wmp:.1e}"),
        format!("f64, mpfr:{BITS}"),
        Verdict::holds(w64 < 1e-9 && wmp < 1e-60),
        "40 random data sets (entries k/10, |k| ≤ 20) with random φ (entries in [−1, 1]); criterion: residual below 1e-9 in f64 and 1e-60 at 256 bits (the data carry up to 16!/12! = 43680 amplification in s)",
    );
    let ph = Outcome::new(
        format!("largest relative |σ² − ‖p′‖²|/σ² at 21 points: f64 {p64:.1e}, mpfr:{BITS} {pmp:.1e}"),
        format!("f64, mpfr:{BITS}"),
        Verdict::holds(p64 < 1e-12 && pmp < 1e-70),
        "same 40 interpolants; σ = |A|² from the preimage, p′ from the control points of Eq. (10d); criterion 1e-12 (f64), 1e-70 (256 bits)",
    );
    (interp, ph)
}

/// A rotation as a unit quaternion from random components.
fn random_rotation(rng: &mut SplitMix64) -> Quat<Float> {
    let q = Quat::new(
        Float::with_val(BITS, rng.int(-9, 9)),
        Float::with_val(BITS, rng.int(-9, 9)),
        Float::with_val(BITS, rng.int(-9, 9)),
        Float::with_val(BITS, rng.int(1, 9)),
    );
    let n = q.norm2().sqrt();
    q.scale(&(Float::with_val(BITS, 1) / &n))
}

fn max_distance(a: &[[Float; 3]], b: &[[Float; 3]]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| vec3::norm(&vec3::sub(x, y)).to_f64())
        .fold(0.0, f64::max)
}

/// One random data set of [`theorems`]: the largest planarity, rigid-motion, reflection and
/// reversion differences, and the distance of the reversed data as printed.
fn trial(rng: &mut SplitMix64) -> [f64; 5] {
    let one = Float::with_val(BITS, 1);
    let d = into::<Float>(&random_data(rng), &BITS);
    let f = free_into::<Float>(&random_free(rng), &BITS);
    let zero_free = FreeParameters::zero(4, &BITS);
    // Theorem 2: data in the plane through p_b spanned by two random directions.
    let rot = random_rotation(rng);
    let flat = d.map(
        |p| rot.sandwich(&[p[0].clone(), p[1].clone(), Float::with_val(BITS, 0)]),
        |v| rot.sandwich(&[v[0].clone(), v[1].clone(), Float::with_val(BITS, 0)]),
    );
    let normal = rot.sandwich(&[
        Float::with_val(BITS, 0),
        Float::with_val(BITS, 0),
        one.clone(),
    ]);
    let c = interpolate(&flat, &zero_free).expect("planar data");
    let planar = c
        .control_points()
        .iter()
        .map(|p| vec3::dot(p, &normal).abs().to_f64())
        .fold(0.0, f64::max);
    // Theorem 3: rotation, translation and scaling (φ* = 0 for the scaling) and any φ
    // for the rotation.
    let shift = [
        Float::with_val(BITS, rng.int(-5, 5)),
        Float::with_val(BITS, 2),
        Float::with_val(BITS, -1),
    ];
    let scale = Float::with_val(BITS, rng.int(1, 30)) / 10u32;
    let moved = d.map(|p| vec3::add(&rot.sandwich(p), &shift), |v| rot.sandwich(v));
    let base = interpolate(&d, &f).expect("data").control_points();
    let image: Vec<[Float; 3]> = base
        .iter()
        .map(|p| vec3::add(&rot.sandwich(p), &shift))
        .collect();
    let rigid = max_distance(
        &interpolate(&moved, &f).expect("data").control_points(),
        &image,
    );
    let scaled = d.map(|p| vec3::scale(p, &scale), |v| vec3::scale(v, &scale));
    let base0 = interpolate(&d, &zero_free).expect("data").control_points();
    let image0: Vec<[Float; 3]> = base0.iter().map(|p| vec3::scale(p, &scale)).collect();
    let rigid = rigid.max(max_distance(
        &interpolate(&scaled, &zero_free)
            .expect("data")
            .control_points(),
        &image0,
    ));
    // Reflection in the plane x = 0 after the rotation: φ → −φ.
    let mirror = |v: &[Float; 3]| {
        let r = rot.sandwich(v);
        [-r[0].clone(), r[1].clone(), r[2].clone()]
    };
    let reflected = d.map(mirror, mirror);
    let image: Vec<[Float; 3]> = base.iter().map(mirror).collect();
    let reflect = max_distance(
        &interpolate(&reflected, &f.negated())
            .expect("data")
            .control_points(),
        &image,
    );
    let (reverse, printed) = reversion(&d, &f, &base, &base0);
    [planar, rigid, reflect, reverse, printed]
}

/// Theorem 4 on data `d` with free parameters `f`: the distance of the reversed interpolant
/// (traced backwards) from `base`, and that of the reversed data as printed (φ* = 0) from
/// `base0`.
fn reversion(
    d: &HermiteData<Float>,
    f: &FreeParameters<Float>,
    base: &[[Float; 3]],
    base0: &[[Float; 3]],
) -> (f64, f64) {
    let zero_free = FreeParameters::zero(4, &BITS);
    // Theorem 4: the reversed data, interpolated with −φ, traced backwards. The roles of
    // the two ends swap, so θ_0 ↔ θ_8 and τ_k ↔ τ_{8−k}.
    let swapped = FreeParameters {
        theta_start: f.theta_end.clone(),
        theta_mid: f.theta_mid.clone(),
        theta_end: f.theta_start.clone(),
        tau_start: f.tau_end.clone(),
        tau_end: f.tau_start.clone(),
    };
    let rev = interpolate(&d.reversed(), &swapped.negated()).expect("data");
    let mut pts = rev.control_points();
    pts.reverse();
    let reverse = max_distance(&pts, base);
    // The reversed data as printed (no sign change of odd derivatives), with φ* = 0.
    let as_printed = HermiteData {
        p_b: d.p_e.clone(),
        p_e: d.p_b.clone(),
        start: d.end.clone(),
        end: d.start.clone(),
    };
    let printed = interpolate(&as_printed, &zero_free).map_or(f64::INFINITY, |c| {
        let mut pts = c.control_points();
        pts.reverse();
        max_distance(&pts, base0)
    });
    (reverse, printed)
}

/// Theorems 2, 3 (rigid motions and scaling; reflections with φ → −φ) and 4 (reversion),
/// and the reversed data exactly as printed.
pub fn theorems() -> [Outcome; 5] {
    let mut rng = SplitMix64::new(0x01b2);
    let (mut planar, mut rigid, mut reflect, mut reverse, mut printed) =
        (0.0f64, 0.0f64, 0.0f64, 0.0f64, f64::INFINITY);
    for _ in 0..20 {
        let [p, g, f, r, q] = trial(&mut rng);
        (planar, rigid, reflect, reverse, printed) = (
            planar.max(p),
            rigid.max(g),
            reflect.max(f),
            reverse.max(r),
            printed.min(q),
        );
    }
    let tol = 1e-60;
    [
        Outcome::new(format!("largest distance of a control point from the plane: {planar:.1e}"), format!("mpfr:{BITS}"), Verdict::holds(planar < tol), "20 random planar data sets (a random rotation of data with zero third components), φ* = 0; criterion 1e-60"),
        Outcome::new(format!("largest control-point difference: {rigid:.1e}"), format!("mpfr:{BITS}"), Verdict::holds(rigid < tol), "20 random data sets: a random rotation plus translation with random φ, and a scaling by k/10 with φ* = 0; the interpolant of the moved data equals the moved interpolant; criterion 1e-60"),
        Outcome::new(format!("largest control-point difference: {reflect:.1e}"), format!("mpfr:{BITS}"), Verdict::holds(reflect < tol), "reflection (rotation then x → −x) of 20 random data sets: the interpolant of the reflected data with −φ equals the reflected interpolant with φ; criterion 1e-60"),
        Outcome::new(format!("largest control-point difference: {reverse:.1e}"), format!("mpfr:{BITS}"), Verdict::holds(reverse < tol), "reversed data (p̄_b = p_e, and the k-th derivatives multiplied by (−1)^k, which is what traversing the same curve backwards gives) interpolated with −φ, with the two ends' parameters exchanged (θ0 ↔ θ8, τ_k ↔ τ_{8−k}), traced backwards equals p_φ; criterion 1e-60"),
        Outcome::new(
            format!("smallest control-point difference over 20 data sets: {printed:.3}"),
            format!("mpfr:{BITS}"),
            if printed > 1e-3 { Verdict::Discrepancy } else { Verdict::Reproduced },
            "Theorem 4 prints the reversed data as v̄_b = v_e, ā_b = a_e, j̄_b = j_e, s̄_b = s_e (and the same at the other end) without the signs (−1)^k of a reversed parameter; read literally, the curve p̄ starts at p_e moving along +v_e, away from the original curve, so p̄(1 − ξ) = p(ξ) fails (distance shown, φ* = 0). With the signs it holds exactly (previous claim). The extraction may have dropped the minus signs.",
        ),
    ]
}

/// Sec. 5E: jumps at the joints of A (orders 0–4), R (0–4) and ω (0–3), with and without the
/// roll correction, on `segments` segments of the test curve.
pub struct Jumps {
    pub segments: usize,
    pub corrected: [Vec<f64>; 3],
    pub uncorrected: [Vec<f64>; 3],
}

pub fn jumps_of(pw: &PiecewisePh<Float>) -> [Vec<f64>; 3] {
    let f = |v: Vec<Float>| v.iter().map(|x| x.to_f64()).collect::<Vec<_>>();
    [
        f(joint_jumps(pw, 4, preimage_components)),
        f(joint_jumps(pw, 4, frame_entries)),
        f(joint_jumps(pw, 4, omega_components)),
    ]
}

pub fn continuity(segments: usize) -> Jumps {
    let c = table1::curve().compile::<Float>(&BITS);
    let (a, b) = (Float::with_val(BITS, 0), Float::with_val(BITS, 1));
    let free = FreeParameters::zero(4, &BITS);
    let raw = convert(&c, &a, &b, segments, 4, &free, false).expect("test curve");
    let mut fixed = raw.clone();
    fixed.align_roll();
    Jumps {
        segments,
        corrected: jumps_of(&fixed),
        uncorrected: jumps_of(&raw),
    }
}

/// The continuity claim from jump tables.
pub fn continuity_outcome(all: &[Jumps]) -> Outcome {
    let tiny = 1e-50;
    let mut ok = true;
    let mut notes = Vec::new();
    for j in all {
        let [a, r, w] = &j.corrected;
        let smooth = a[..4]
            .iter()
            .chain(&r[..4])
            .chain(&w[..3])
            .all(|x| *x < tiny);
        let breaks = a[4] > 1e-6 && w[3] > 1e-6;
        let lost = j.uncorrected[0][0] > 1e-6 && j.uncorrected[1][0] > 1e-6;
        ok &= smooth && breaks && lost;
        notes.push(format!(
            "{} segments: corrected max jump of A…A‴, R…R‴, ω…ω″ {:.1e}; A⁗ jump {:.2e}, ω‴ jump {:.2e}; without correction A jumps {:.3}, R jumps {:.3}",
            j.segments,
            a[..4].iter().chain(&r[..4]).chain(&w[..3]).fold(0.0f64, |m, x| m.max(*x)),
            a[4],
            w[3],
            j.uncorrected[0][0],
            j.uncorrected[1][0]
        ));
    }
    Outcome::new(
        notes.join("; "),
        format!("mpfr:{BITS}"),
        Verdict::holds(ok),
        "jumps between the one-sided derivatives (global parameter) at every joint of the test curve's conversion; criterion: with the roll correction A, R are C³ and ω is C² (jumps < 1e-50), A⁗ and ω‴ jump (> 1e-6, so no more smoothness is claimed than holds); without it A and R themselves jump (> 1e-6)",
    )
}

/// Eq. (22b) as printed: the correction multiplied on the left. Returns the outcome and the
/// largest displacement of the curve it causes.
pub fn left_product() -> Outcome {
    let c = table1::curve().compile::<Float>(&BITS);
    let (a, b) = (Float::with_val(BITS, 0), Float::with_val(BITS, 1));
    let free = FreeParameters::zero(4, &BITS);
    let raw = convert(&c, &a, &b, 2, 4, &free, false).expect("test curve");
    let mut right = raw.clone();
    right.align_roll();
    // The left factor with the same effect at the joint: A_α A_1(0) = A_1(0) Q, i.e.
    // A_α = A_1(0) Q A_1(0)⁻¹, a rotation about the joint tangent.
    let a10 = raw.segments()[1].preimage[0].clone();
    let q = a10
        .conj()
        .mul(&right.segments()[1].preimage[0])
        .scale(&(Float::with_val(BITS, 1) / &a10.norm2()));
    let alpha = a10
        .mul(&q)
        .mul(&a10.conj())
        .scale(&(Float::with_val(BITS, 1) / &a10.norm2()));
    let left = PhCurve::new(
        raw.segments()[1]
            .preimage
            .iter()
            .map(|x| alpha.mul(x))
            .collect(),
        raw.segments()[1].start.clone(),
    )
    .expect("a preimage of degree ≤ 30");
    let moved = max_distance(&left.control_points(), &raw.segments()[1].control_points());
    let kept = max_distance(
        &right.segments()[1].control_points(),
        &raw.segments()[1].control_points(),
    );
    let joint = vec3::norm(&vec3::sub(
        &left.preimage[0].star_square(),
        &raw.segments()[1].preimage[0].star_square(),
    ))
    .to_f64();
    Outcome::new(
        format!("left product moves the second segment's control points by up to {moved:.4}; right product by {kept:.1e}"),
        format!("mpfr:{BITS}"),
        if moved > 1e-6 && kept < 1e-60 { Verdict::Discrepancy } else { Verdict::Failed },
        format!("2 segments of the test curve. Eq. (22b) prints A_i ← A_α A_i. Any A_α that aligns the frames at the joint (here the rotation about the joint tangent, which keeps h(0) to {joint:.1e}) rotates the whole hodograph when applied on the left, so the curve no longer interpolates the data; multiplying on the right by Q(α) = cos α + i sin α commutes with i and leaves h = A i A* unchanged. We implement the right product."),
    )
}

/// Eq. (13c): the printed torsion divides by |p‴|², the standard formula by |p′×p″|². Checked
/// exactly on the twisted cubic (t, t², t³) at t = 1 and against the Frenet definition
/// τ = −B′·N/|p′| by Taylor AD.
pub fn torsion_formula() -> Outcome {
    let r = |v: i64| BigRational::from_integer(v.into());
    let (d1, d2, d3) = ([r(1), r(2), r(3)], [r(0), r(2), r(6)], [r(0), r(0), r(6)]);
    let cross = vec3::cross(&d1, &d2);
    let num = vec3::dot(&cross, &d3);
    let printed = num.clone() / vec3::dot(&d3, &d3);
    let standard = num / vec3::dot(&cross, &cross);
    // Frenet: B = (p′×p″)/|p′×p″|, N = B × T, τ = −B′·N/|p′| with Taylor series at t = 1.
    let t = Taylor::variable(Float::with_val(BITS, 1), 1);
    let p1 = [
        Taylor::constant(Float::with_val(BITS, 1)),
        t.clone() * &Taylor::from_i64(2, &BITS),
        t.clone() * &t * &Taylor::from_i64(3, &BITS),
    ];
    let p2 = [
        Taylor::from_i64(0, &BITS),
        Taylor::from_i64(2, &BITS),
        t.clone() * &Taylor::from_i64(6, &BITS),
    ];
    let c = vec3::cross(&p1, &p2);
    let bn = vec3::scale(&c, &(Taylor::from_i64(1, &BITS) / &vec3::norm(&c)));
    let tn = vec3::scale(&p1, &(Taylor::from_i64(1, &BITS) / &vec3::norm(&p1)));
    let n = vec3::cross(&bn, &tn);
    let db = vec3::map(&bn, |x| x.derivative_series());
    let speed = vec3::norm(&p1);
    let tau = -(vec3::dot(&db, &n) / &speed);
    let frenet = tau.value().clone();
    let frenet_text = format_float_digits(&frenet, 30);
    let agree = (frenet.clone() - Float::with_val(BITS, 3) / 19u32).abs() < 1e-60;
    Outcome::new(
        format!("printed formula {printed}, standard formula {standard}, Frenet definition {frenet_text}"),
        format!("rational, mpfr:{BITS}"),
        if printed != standard && agree { Verdict::Discrepancy } else { Verdict::Failed },
        "twisted cubic (t, t², t³) at t = 1: p′ = (1,2,3), p″ = (0,2,6), p‴ = (0,0,6). Eq. (13c) as printed, [p′×p″]·p‴/‖p‴‖², gives 1/3; the torsion is [p′×p″]·p‴/‖p′×p″‖² = 3/19, which the Frenet definition −B′·N/|p′| (by Taylor AD, independent of either formula) confirms. We use the standard formula.",
    )
}

/// Eq. (18) as printed (Lemma 2 applied to c_p) against the derived rule: how far the
/// resulting curve ends from p_e.
pub fn eq18() -> Outcome {
    let mut rng = SplitMix64::new(0x01c3);
    let mut worst_printed = f64::INFINITY;
    let mut worst_derived = 0.0f64;
    for _ in 0..10 {
        let d = into::<Float>(&random_data(&mut rng), &BITS);
        let free = FreeParameters::zero(4, &BITS);
        let end = |c: &PhCurve<Float>| {
            let pts = c.control_points();
            vec3::norm(&vec3::sub(&pts[pts.len() - 1], &d.p_e)).to_f64()
        };
        worst_derived = worst_derived.max(end(&interpolate(&d, &free).expect("data")));
        worst_printed =
            worst_printed.min(end(
                &interpolate_with(&d, &free, MiddleRule::AsPrintedEq18).expect("data")
            ));
    }
    Outcome::new(
        format!("distance of p(1) from p_e: with Eq. (18) as printed at least {worst_printed:.3}; with Lemma 2 applied to (490/21879)(p_e − p_b) − c_p at most {worst_derived:.1e}"),
        format!("mpfr:{BITS}"),
        if worst_printed > 1e-6 && worst_derived < 1e-60 { Verdict::Discrepancy } else { Verdict::Failed },
        "10 random data sets, φ* = 0. Eq. (18) writes √|c_p| (c_p/|c_p| + i)/|c_p/|c_p| + i| Q(θ4), i.e. Lemma 2 solving X ⋆ X = c_p, but Eq. (17a) requires A_p ⋆ A_p = (490/21879)(p_e − p_b) − c_p; with (18) as printed the end point is missed. The coefficients inside (18) are those of (17b) (checked there).",
    )
}

/// (segments, |ΔL|, max |Δκ|, max |Δτ|, E).
pub type GeometryRow = (usize, f64, f64, f64, f64);

/// Eq. (13): arc length, curvature and torsion of the converted test curve against the
/// curve's own, for 8, 64 and 512 segments (MPFR-128). Returns rows (segments, ΔL, max Δκ,
/// max Δτ, E), the proven length (`None` when it could not be enclosed: the claim fails) and
/// the outcome.
pub fn geometry() -> (Vec<GeometryRow>, Option<f64>, Outcome) {
    let bits = table1::BITS;
    let c = table1::curve().compile::<Float>(&bits);
    let proven = match proven_length(bits) {
        Ok(l) => l,
        Err(e) => {
            let out = Outcome::new(
                "not computed".to_string(),
                format!("mpfr:{bits}"),
                Verdict::Failed,
                format!("the reference arc length ∫₀¹|γ′| could not be enclosed: {e}"),
            );
            return (Vec::new(), None, out);
        }
    };
    let length = proven.mid().clone();
    let (a, b) = (Float::with_val(bits, 0), Float::with_val(bits, 1));
    let free = FreeParameters::zero(4, &bits);
    let mut rows = Vec::new();
    for segments in [8usize, 64, 512] {
        let pw = convert(&c, &a, &b, segments, 4, &free, true).expect("test curve");
        let mut l = Float::with_val(bits, 0);
        for s in pw.segments() {
            l += &s.arc_length();
        }
        let dl = (l - &length).abs().to_f64();
        let (mut dk, mut dt) = (0.0f64, 0.0f64);
        let samples = 400;
        for i in 0..=samples {
            let t = Float::with_val(bits, i) / samples as u32;
            let (k, xi) = pw.locate(&t);
            let seg = &pw.segments()[k];
            let h = pw.step();
            let mut jet = bernstein_jet(&seg.control_points(), &xi, 3);
            let mut sc = Float::with_val(bits, 1);
            for d in jet.iter_mut().skip(1) {
                sc /= &h;
                *d = vec3::scale(d, &sc);
            }
            let (kp, tp) = curvature_torsion(&jet);
            let (kg, tg) = curvature_torsion(&c.jet(&t, 3));
            dk = dk.max((kp - kg).abs().to_f64());
            dt = dt.max((tp - tg).abs().to_f64());
        }
        let e = crate::algo::ph::piecewise::conversion_error(
            &c,
            &pw,
            crate::algo::ph::piecewise::DEFAULT_SAMPLES,
        )
        .max
        .to_f64();
        rows.push((segments, dl, dk, dt, e));
    }
    let decreasing = rows
        .windows(2)
        .all(|w| w[1].1 < w[0].1 && w[1].2 < w[0].2 && w[1].3 < w[0].3);
    let text = rows
        .iter()
        .map(|r| {
            format!(
                "{} segments: |ΔL| {:.2e}, max|Δκ| {:.2e}, max|Δτ| {:.2e} (E {:.2e})",
                r.0, r.1, r.2, r.3, r.4
            )
        })
        .collect::<Vec<_>>()
        .join("; ");
    let out = Outcome::new(
        text,
        format!("mpfr:{bits}"),
        Verdict::holds(decreasing),
        format!("L from the exact integral of σ per segment (Eq. 13a) against ∫₀¹|γ′| proven by Taylor models with a proven remainder (`curve::integral`: L = {}, every digit proven; |ΔL| is taken from the enclosure's midpoint, which is within {:.1e} of L); κ and τ (standard formula) at 401 points of the global parameter; criterion: all three differences decrease as the segments increase. They are not bounded by E itself: κ and τ involve two and three derivatives, so their errors scale like E/h² and E/h³ (compare the columns).", proven.proven_digits().1, proven.rad()),
    );
    (rows, Some(length.to_f64()), out)
}

/// ∫₀¹ |γ′(t)| dt of the test curve, proven: Taylor models of the speed in balls with a
/// proven remainder ([`crate::curve::integral`]).
fn proven_length(bits: u32) -> Result<Ball, crate::curve::integral::IntegralError> {
    let c = table1::curve().compile::<Ball>(&bits);
    let speed = |t: &Ball, order: usize| -> Option<Taylor<Ball>> {
        let var = Taylor::variable(t.clone(), order + 1);
        let mut square = Taylor::constant(Ball::zero_in(&bits)).with_order(order);
        for component in &c.components {
            let d = component.eval(&var).derivative_series();
            square += &(d.clone() * &d);
        }
        let speed = square.sqrt();
        speed.c.iter().all(Field::is_finite).then_some(speed)
    };
    let (a, b) = (Ball::zero_in(&bits), Ball::one_in(&bits));
    integrate(&speed, &a, &b, &IntegralOptions::default()).map(|r| r.value)
}

/// Eq. (13b): κ = ‖p′ × p″‖/‖p′‖³, against the definition κ = ‖dT/ds‖ = ‖dT/dξ‖/‖p′‖ with
/// the unit tangent T = p′/‖p′‖ differentiated by Taylor AD (independent of the formula), on
/// the twisted cubic (ξ, ξ², ξ³) at ξ = 0, 1/2, 1, 2 and the helix (cos ξ, sin ξ, ξ), whose
/// curvature is 1/2 everywhere.
pub fn curvature_formula() -> Outcome {
    let f = |v: i64| Float::with_val(BITS, v);
    let cubic = |x: &Taylor<Float>| [x.clone(), x.clone() * x, x.clone() * x * x];
    let helix = |x: &Taylor<Float>| {
        let (s, c) = x.sin_cos_series();
        [c, s, x.clone()]
    };
    let mut worst = Float::with_val(BITS, 0);
    let mut helix_off = Float::with_val(BITS, 0);
    let points = [(0, 1), (1, 2), (1, 1), (2, 1)];
    for (curve_index, path) in [
        &cubic as &dyn Fn(&Taylor<Float>) -> [Taylor<Float>; 3],
        &helix,
    ]
    .into_iter()
    .enumerate()
    {
        for &(num, den) in &points {
            let x = Taylor::variable(f(num) / den, 3);
            let p = path(&x);
            let d1 = vec3::map(&p, |c| c.derivative_series());
            let d2 = vec3::map(&d1, |c| c.derivative_series());
            let speed = vec3::norm(&d1);
            let cubed = Float::with_val(BITS, speed.value().square_ref()) * speed.value();
            let formula = vec3::norm(&vec3::cross(&d1, &d2)).value().clone() / cubed;
            let tangent = vec3::scale(&d1, &(Taylor::from_i64(1, &BITS) / &speed));
            let dt = vec3::map(&tangent, |c| c.derivative_series());
            let definition = vec3::norm(&dt).value().clone() / speed.value();
            worst = worst.max(&(formula.clone() - &definition).abs());
            if curve_index == 1 {
                helix_off = helix_off.max(&(formula - Float::with_val(BITS, 0.5)).abs());
            }
        }
    }
    let (worst, helix_off) = (worst.to_f64(), helix_off.to_f64());
    Outcome::new(
        format!(
            "largest difference from ‖dT/dξ‖/‖p′‖: {worst:.1e} (twisted cubic and helix, four points each); helix: within {helix_off:.1e} of 1/2"
        ),
        format!("mpfr:{BITS}"),
        Verdict::holds(worst < 1e-60 && helix_off < 1e-60),
        "Eq. (13b) evaluated from the jets of (ξ, ξ², ξ³) at ξ = 0, 1/2, 1, 2 and of (cos ξ, sin ξ, ξ) at the same points, \
         against the curvature's definition, the rate of turn of the unit tangent per unit length, by Taylor AD; criterion: \
         agreement to 1e-60 at 256 bits",
    )
}
