//! Claims of Sec. 2: the exact minimizing parametrization of scalar data.

use super::super::sample::SplitMix64;
use super::super::{Ledger, Outcome, Verdict};
use super::data::TABLE1;
use super::num;
use crate::algo::param::descent::{descend, polish};
use crate::algo::param::natural::NaturalCubicSpline;
use crate::algo::param::objective::{objective, Objective};
use crate::algo::param::one_d::{
    chord_length_1d, classify, minimizing_parametrization, parametrization_with_shape, Case, Shape,
};
use crate::algo::param::proven::prove_minimum;
use crate::scalar::ball::Ball;
use crate::scalar::certify::certify;
use crate::scalar::{BigRational, Field, Float, Real};

type Q = BigRational;

/// Is the value within half a unit of the last printed decimal of `printed`?
pub(crate) fn rounds_to(x: &Float, printed: &str) -> bool {
    let decimals = printed.split_once('.').map_or(0, |(_, f)| f.len()) as i32;
    let p = Float::from_rational(&num(printed), &x.prec());
    let unit: BigRational = num_traits::Pow::pow(BigRational::from_integer(10.into()), -decimals);
    let half_unit = Float::from_rational(&(unit / BigRational::from_integer(2.into())), &x.prec());
    (x.clone() - &p).abs() <= half_unit
}

/// The difference of `x` from the printed decimal in units of its last printed digit.
pub(crate) fn printed_units(x: &Float, printed: &str) -> f64 {
    let decimals = printed.split_once('.').map_or(0, |(_, f)| f.len()) as i32;
    let unit: BigRational = num_traits::Pow::pow(BigRational::from_integer(10.into()), -decimals);
    let diff = x.clone() - &Float::from_rational(&num(printed), &x.prec());
    (diff.abs() / &Float::from_rational(&unit, &x.prec())).to_f64()
}

/// A computed column against a printed one.
pub(crate) struct ColumnComparison {
    /// Entries within half a unit of their last printed decimal.
    pub agree: usize,
    /// The largest absolute difference.
    pub largest: f64,
    /// The largest difference in units of the entry's last printed decimal.
    pub largest_units: f64,
}

impl ColumnComparison {
    /// The verdict by [`Verdict::by_printed_units`].
    pub fn verdict(&self) -> Verdict {
        Verdict::by_printed_units(self.largest_units)
    }
}

/// `column`, proven enclosures, against the printed `printed`: an entry agrees when both ends
/// of its ball round to the print (the set of such x is an interval, so then every point
/// does); its difference is the farther end's. An error names the first entry whose ball
/// straddles the half-unit boundary (its agreement is not decided).
pub(crate) fn compare_balls_with_printed(
    column: &[Ball],
    printed: &[&str],
) -> Result<ColumnComparison, String> {
    let mut comparison = ColumnComparison {
        agree: 0,
        largest: 0.0,
        largest_units: 0.0,
    };
    for (i, (x, s)) in column.iter().zip(printed).enumerate() {
        let (lo, hi) = (x.lower(), x.upper());
        match (rounds_to(&lo, s), rounds_to(&hi, s)) {
            (true, true) => comparison.agree += 1,
            (false, false) => {}
            _ => {
                return Err(format!(
                    "entry {} ({s}): the enclosure {} straddles half a unit of the print",
                    i + 1,
                    x.proven_digits().1
                ))
            }
        }
        let value = num(s).to_f64();
        for end in [&lo, &hi] {
            comparison.largest = comparison.largest.max((end.to_f64() - value).abs());
            comparison.largest_units = comparison.largest_units.max(printed_units(end, s));
        }
    }
    Ok(comparison)
}

fn table1_z<T: Field>(ctx: &T::Ctx) -> Vec<T> {
    TABLE1
        .iter()
        .map(|(z, _)| T::from_rational(&num(z), ctx))
        .collect()
}

/// Random alternating (case II) or mixed (case III) data, rationals with denominator 10.
fn random_ordinates(rng: &mut SplitMix64, n: usize, alternating: bool) -> Vec<Q> {
    let mut z = vec![Q::from_integer(0.into())];
    let mut up = true;
    for i in 0..n {
        let step = Q::new(rng.int(1, 20).into(), 10.into());
        // Alternate every step (case II), or keep the direction for a random stretch (case III).
        let flip = if alternating { true } else { i % 3 != 1 };
        if flip {
            up = !up;
        }
        z.push(if up {
            z[i].clone() + step
        } else {
            z[i].clone() - step
        });
    }
    z
}

fn to_float(z: &[Q], bits: u32) -> Vec<Float> {
    z.iter().map(|x| Float::from_rational(x, &bits)).collect()
}

/// Table I's t* proven: the case and extremes decided on the exact ordinates, Eq. 9 evaluated
/// in balls at 256 bits, each printed value compared with every point of its enclosure.
fn t_star_outcome(case: Case, min_digits: u32) -> Outcome {
    let scalar = "ball:256 (mpfr:128/256 shown)";
    let exact: Vec<Q> = TABLE1.iter().map(|(z, _)| num(z)).collect();
    let proven = Shape::of_exact(&exact)
        .and_then(|shape| parametrization_with_shape(&table1_z::<Ball>(&256), &shape))
        .map_err(|e| format!("the Table I data: {e}"));
    let printed: Vec<&str> = TABLE1.iter().map(|(_, t)| *t).collect();
    let compared = proven.and_then(|(t, _)| compare_balls_with_printed(&t, &printed));
    match compared {
        Ok(c) => Outcome::new(
            format!("case {}: {} of {} entries agree to the 4 printed decimals (proven; ≥ {min_digits} digits agree at 128/256 bits)", case.name(), c.agree, TABLE1.len()),
            scalar,
            if c.agree == TABLE1.len() { Verdict::Reproduced } else { Verdict::Discrepancy },
            "the ordinates alternate at every step (case II, decided on the exact ordinates), so t* is given by Eq. 9 (ε = 1, √2, …, \
             √2, 1), evaluated in ball arithmetic at 256 bits; each printed value compared with every point of its enclosure within \
             half a unit of its last printed decimal",
        ),
        Err(e) => Outcome::failed(scalar, e),
    }
}

/// Table I computed: t* at 256 bits with its certified digits, and the spline for Fig. 1.
pub struct TableOne {
    /// t* at 256 bits.
    pub t_star: Vec<Float>,
    /// The digits of each t*_i that 128 and 256 bits agree on.
    pub digits: Vec<u32>,
    /// Whether each t*_i rounds to the printed value.
    pub agrees: Vec<bool>,
    /// θ on t*, for Fig. 1.
    pub spline: Option<NaturalCubicSpline<Float>>,
}

/// Everything of Sec. 2 into the ledger; Table I for the report (`None` if it has no t*).
pub fn section(ledger: &mut Ledger) -> Option<TableOne> {
    ledger.record("marin.case1.chord_length", case_one());
    let lo = minimizing_parametrization(&table1_z::<Float>(&128));
    let hi = minimizing_parametrization(&table1_z::<Float>(&256));
    let (Ok((t_lo, case)), Ok((t_hi, _))) = (lo, hi) else {
        ledger.record(
            "marin.table1.t_star",
            Outcome::new(
                "",
                "mpfr",
                Verdict::Failed,
                "the Table I data have no parametrization",
            ),
        );
        return None;
    };
    let digits: Vec<u32> = t_lo
        .iter()
        .zip(&t_hi)
        .map(|(a, b)| certify(a, b).digits)
        .collect();
    let agrees: Vec<bool> = TABLE1
        .iter()
        .zip(&t_hi)
        .map(|((_, printed), b)| rounds_to(b, printed))
        .collect();
    let min_digits = digits.iter().copied().min().unwrap_or(u32::MAX);
    ledger.record("marin.table1.t_star", t_star_outcome(case, min_digits));
    let spline = NaturalCubicSpline::new(t_hi.clone(), table1_z::<Float>(&256)).ok();
    ledger.record("marin.eq8.interior_slope", eq8_slope());
    ledger.record("marin.eq11.jump", eq11_general());
    ledger.record("marin.cor1.numerical", corollary_one());
    let corollary = corollary_two();
    ledger.record("marin.eq26.tilde", super::sentences::eq26_tilde(&corollary));
    ledger.record("marin.cor2.unique_minimizer", corollary);
    let three = corollary_three();
    ledger.record("marin.cor3.d_index", super::sentences::d_index(&three));
    ledger.record("marin.cor3.properties", three);
    Some(TableOne {
        t_star: t_hi,
        digits,
        agrees,
        spline,
    })
}

fn case_one() -> Outcome {
    let mut rng = SplitMix64::new(7);
    let (mut cases, mut bad) = (0, 0);
    for n in [2usize, 3, 5, 8, 12] {
        let mut z = vec![rng.rational()];
        for _ in 0..n {
            let next = z[z.len() - 1].clone() + rng.positive();
            z.push(next);
        }
        cases += 1;
        let Ok(t) = chord_length_1d(&z) else {
            bad += 1;
            continue;
        };
        let h: Vec<Q> = t.windows(2).map(|w| w[1].clone() - &w[0]).collect();
        let g = objective(
            &h,
            &[z.clone()],
            &[Q::from_integer(1.into())],
            Objective::Exact,
        );
        let linear = NaturalCubicSpline::new(t.clone(), z.clone())
            .map(|s| s.second_derivatives_at_knots().iter().all(Field::is_zero));
        bad += (classify(&z) != Ok(Case::I)
            || g.map(|g| !g.is_zero()).unwrap_or(true)
            || linear != Ok(true)) as usize;
    }
    Outcome::new(
        format!("{} of {cases} random monotone data sets: case I, G = 0 exactly, θ linear", cases - bad),
        "rational",
        Verdict::holds(bad == 0),
        "strictly increasing random rational ordinates (N = 2…12); Eq. 7 computed exactly; G by Eq. 31 and the natural spline's \
         second derivatives all exactly zero, so this parametrization attains the lower bound G ≥ 0",
    )
}

/// Eq. 8 at the Table I minimizer: θ′(t_i*) at every interior knot, enclosed. t* is Eq. 9 in
/// balls on the case decided from the exact ordinates (as `t_star_outcome`), the spline is
/// solved in balls, and θ′ at knot i is evaluated on piece i by the distances (0, h_i) to its
/// ends, so no ball is located among the knots.
fn eq8_slope() -> Outcome {
    let scalar = "ball:256";
    let bits = 256;
    let exact: Vec<Q> = TABLE1.iter().map(|(z, _)| num(z)).collect();
    let z = table1_z::<Ball>(&bits);
    let slope = Shape::of_exact(&exact)
        .and_then(|shape| parametrization_with_shape(&z, &shape))
        .map_err(|e| format!("the Table I data: {e}"))
        .and_then(|(t, _)| {
            let s = NaturalCubicSpline::with_increasing_knots(t.clone(), z.clone())
                .map_err(|e| format!("the spline: {e}"))?;
            let zero = Ball::zero_in(&bits);
            Ok((1..t.len() - 1)
                .map(|i| {
                    let h = t[i].clone() - &t[i - 1];
                    s.eval_offsets(&zero, &h, i)[1].abs_upper()
                })
                .fold(0.0, f64::max))
        });
    match slope {
        Ok(bound) => Outcome::new(
            format!(
                "max |θ′(t_i*)| over the {} interior knots ≤ {}",
                TABLE1.len() - 2,
                crate::report::number::bound(bound, 2, rug::float::Round::Up)
            ),
            scalar,
            Verdict::holds(bound < 1e-60),
            "natural cubic spline through (t_i*, z_i) of Table I, t* by Eq. 9 in ball arithmetic at 256 bits (the case decided on \
             the exact ordinates), the spline solved in balls and θ′ at each interior knot enclosed on its left piece; the claim is \
             a zero, so what a proof can give is a bound: every enclosure lies within the printed bound of 0 (criterion, fixed \
             before computing: below 1e-60, far under the data's size 1–20 and far above 256-bit rounding)",
        ),
        Err(e) => Outcome::failed(scalar, e),
    }
}

/// Eq. 11 for general spacings h (policy clause 2: at the h of Eq. 9 its right side vanishes
/// by construction, which would reproduce nothing). The piecewise cubic of Corollary 1's
/// proof — the Hermite cubic on each interval with θ′ = 0 at interior knots and θ″ = 0 at
/// t₀ and t_N — is built exactly for random alternating ordinates and random spacings, and
/// the jump of θ″ at every interior knot is compared with Eq. 11, exactly.
fn eq11_general() -> Outcome {
    let q = |v: i64| Q::from_integer(v.into());
    let mut rng = SplitMix64::new(11);
    let (mut knots, mut bad) = (0usize, 0usize);
    for _ in 0..20 {
        let n = rng.int(3, 9) as usize;
        let z = random_ordinates(&mut rng, n + 1, true);
        let h: Vec<Q> = (0..n).map(|_| rng.positive()).collect();
        let delta = |i: usize| z[i].clone() - &z[i - 1];
        // ε² of Eq. 9: 1 on the end intervals, 2 inside.
        let eps2 = |i: usize| if i == 1 || i == n { q(1) } else { q(2) };
        // θ″ at the two ends of interval i (1-based, length h_i): the Hermite cubic with the
        // end conditions above, differentiated twice.
        let second = |i: usize, at_right: bool| -> Q {
            let (d, hh) = (delta(i), h[i - 1].clone() * &h[i - 1]);
            match (i == 1, i == n, at_right) {
                // [t₀, t₁]: θ = z₀ + Δ(3s/2 − s³/2), θ″ = −3Δs/h².
                (true, _, true) => -(q(3) * d) / hh,
                // [t_{N−1}, t_N]: θ = z_{N−1} + Δ(3s²/2 − s³/2), θ″(0) = 3Δ/h².
                (_, true, false) => q(3) * d / hh,
                // Inside: θ = z_{i−1} + Δ(3s² − 2s³), θ″ = Δ(6 − 12s)/h².
                (_, _, false) => q(6) * d / hh,
                (_, _, true) => -(q(6) * d) / hh,
            }
        };
        for i in 1..n {
            let jump = second(i + 1, false) - second(i, true);
            let printed = q(3) * eps2(i + 1) * delta(i + 1) / (h[i].clone() * &h[i])
                - (-(q(3) * eps2(i) * delta(i)) / (h[i - 1].clone() * &h[i - 1]));
            knots += 1;
            bad += usize::from(jump != printed);
        }
    }
    Outcome::new(
        format!("Eq. 11 equals the jump of θ″ at {} of {knots} interior knots (20 random alternating data sets with random spacings)", knots - bad),
        "rational",
        Verdict::holds(bad == 0),
        "for random alternating ordinates (N = 3…9) and random positive spacings h (not those of Eq. 9), the piecewise cubic of \
         Corollary 1's proof — Hermite cubics with θ′ = 0 at the interior knots and θ″ = 0 at t₀ and t_N — differentiated exactly; \
         the jump θ″(t_i⁺) − θ″(t_i⁻) compared with the right-hand side of Eq. 11 as printed (ε of Eq. 9). Only at the spacing of \
         Eq. 9 does it vanish (Eq. 12), which marin.table1.t_star and marin.eq8.interior_slope check",
    )
}

/// Corollary 2: the exact parametrization equals a numerical minimizer from several starts.
/// The numerical minimizer of G (gradient projection in f64 from three starts, then Newton at
/// 256 bits) against the exact parametrization of Sec. 2: the fewest agreeing digits over the
/// knots and the starts, or what failed.
fn minimizer_agreement(z: &[Q], rng: &mut SplitMix64) -> Result<f64, String> {
    let bits = 256;
    // The exact parametrization in balls, its shape decided on the exact ordinates.
    let exact = Shape::of_exact(z)
        .and_then(|shape| parametrization_with_shape(&to_balls(z, bits), &shape))
        .map(|(t, _)| t)
        .map_err(|e| format!("no exact parametrization: {e}"))?;
    let n = z.len() - 1;
    let starts: Vec<Vec<f64>> = vec![
        vec![1.0 / n as f64; n],
        chord_length_1d(z)
            .map_err(|e| format!("chord length: {e}"))?
            .windows(2)
            .map(|w| (w[1].clone() - &w[0]).to_f64())
            .collect(),
        {
            let raw: Vec<f64> = (0..n).map(|_| rng.int(1, 9) as f64).collect();
            let s: f64 = raw.iter().sum();
            raw.iter().map(|x| x / s).collect()
        },
    ];
    let z64: Vec<Vec<f64>> = vec![z.iter().map(Field::to_f64).collect()];
    let z256 = vec![to_float(z, bits)];
    let zb = vec![to_balls(z, bits)];
    let (one, one256, one_ball) = ([1.0f64], [Float::with_val(bits, 1)], [Ball::one_in(&bits)]);
    let mut worst = 0.0f64;
    for h0 in starts {
        let rough = descend(h0, &z64, &one, Objective::Exact, &mut |_, _| {})
            .map_err(|_| "descent failed".to_string())?;
        let h = polish(&rough, &z256, &one256, Objective::Exact)
            .map_err(|_| "Newton failed".to_string())?;
        let proven = prove_minimum(&h, &zb, &one_ball, Objective::Exact)
            .map_err(|e| format!("the numerical minimizer: {e}"))?;
        for (a, b) in proven.knots.iter().zip(&exact).skip(1) {
            worst = worst.max((a.clone() - b).magnitude_bounds().1);
        }
    }
    Ok(worst)
}

fn to_balls(z: &[Q], bits: u32) -> Vec<Ball> {
    z.iter().map(|x| Ball::from_rational(x, &bits)).collect()
}

/// Corollaries 1 (case II) and 2 (case III): the exact parametrization is the minimizer that an
/// independent numerical minimization finds, on `count` data sets made by `make` (which draws
/// from the same generator as the random starts, in turn).
fn numerical_confirmation(
    count: usize,
    mut make: impl FnMut(usize, &mut SplitMix64) -> Vec<Q>,
    case: Case,
    rng: &mut SplitMix64,
) -> (f64, Vec<String>) {
    let mut worst = 0.0f64;
    let mut failures = Vec::new();
    for trial in 0..count {
        let z = make(trial, rng);
        let z = &z;
        if classify(z) != Ok(case) {
            failures.push(format!("set {trial}: not case {}", case.name()));
            continue;
        }
        match minimizer_agreement(z, rng) {
            Ok(d) => worst = worst.max(d),
            Err(e) => failures.push(format!("set {trial}: {e}")),
        }
    }
    (worst, failures)
}

fn corollary_two() -> Outcome {
    let mut rng = SplitMix64::new(2);
    let (worst, failures) = numerical_confirmation(
        3,
        |trial, rng| random_ordinates(rng, 6 + trial, false),
        Case::III,
        &mut rng,
    );
    Outcome::new(
        format!("9 numerical minimizations (3 random case III data sets × 3 starts), each a proven minimizer, lie within {worst:.1e} of Eqs. 16–17 (proven)"),
        "ball:256",
        Verdict::holds(failures.is_empty() && worst < 1e-30),
        format!(
            "random mixed ordinates (N = 6…8, steps k/10); exact parametrization by Eqs. 13–17 in balls at 256 bits (its case decided on \
             the exact ordinates); numerical minimizer of G (Eq. 31) by gradient projection in f64 (Eq. 30, relative tolerance 1e-6, at \
             most 5000 iterations) from uniform spacing, from 1-D chord length and from a random spacing, then Newton's method on the \
             optimality system at 256 bits, then proven by Krawczyk's test (exactly one stationary point in a box, reduced Hessian \
             positive definite: a strict local minimum); criterion: every knot of every proven minimizer within 1e-30 of the exact \
             parametrization, a proven bound. Failures: {failures:?}"
        ),
    )
}

/// Corollary 1 in case II, confirmed by an independent minimization.
fn corollary_one() -> Outcome {
    let mut rng = SplitMix64::new(1);
    let (worst, failures) = numerical_confirmation(
        3,
        |trial, rng| match trial {
            0 => TABLE1.iter().map(|(z, _)| num(z)).collect(),
            _ => random_ordinates(rng, 5 + trial, true),
        },
        Case::II,
        &mut rng,
    );
    Outcome::new(
        format!("9 numerical minimizations (Table I and 2 random case II data sets × 3 starts), each a proven minimizer, lie within {worst:.1e} of Eq. 9 (proven)"),
        "ball:256",
        Verdict::holds(failures.is_empty() && worst < 1e-30),
        format!(
            "alternating ordinates (Table I; random N = 6, 7 with steps k/10); the parametrization of Corollary 1 (Eq. 9) in balls at 256 bits \
             against the numerical minimizer of G (Eq. 31): gradient projection in f64 from uniform spacing, 1-D chord length and a random \
             spacing, then Newton's method at 256 bits, then proven by Krawczyk's test (a strict local minimum in a box); criterion: every \
             knot within 1e-30 of Eq. 9, a proven bound, as for Corollary 2. Failures: {failures:?}"
        ),
    )
}

/// Corollary 3 on Table I and random data.
fn corollary_three() -> Outcome {
    let scalar = "ball:256";
    let mut rng = SplitMix64::new(3);
    let mut sets: Vec<Vec<Q>> = vec![TABLE1.iter().map(|(z, _)| num(z)).collect()];
    for i in 0..4 {
        sets.push(random_ordinates(&mut rng, 7 + i, i % 2 == 0));
    }
    let mut problems = Vec::new();
    for (s, z) in sets.iter().enumerate() {
        if let Err(e) = corollary_three_on(s, z, &mut problems) {
            return Outcome::failed(scalar, format!("data set {s}: {e}"));
        }
    }
    Outcome::new(
        format!("(i)–(iii) hold on Table I and 4 random data sets ({} violations)", problems.len()),
        scalar,
        Verdict::holds(problems.is_empty()),
        format!(
            "at the exact minimizing parametrization, in ball arithmetic at 256 bits (the case and the extremes decided on the exact \
             ordinates, t* by Eqs. 9–10 in balls): (i) on every interval θ stays between the interval's end values (each root of \
             the quadratic θ′ enclosed and θ enclosed over it: a proven bound of the excursion, at most 1e-40); (ii) θ''' (constant \
             per interval) is continuous at every knot that is not an endpoint or extreme (each jump's proven bound at most 1e-30); \
             (iii) θ'' at each interior extreme equals −3 sgn(D)(Σ ε_j √|D_j|)² (relative difference proven below 1e-40). Data: \
             Table I (case II), two random case II and two random case III sets. Violations: {problems:?}"
        ),
    )
}

/// Corollary 3 (i)–(iii) on data set `s` with exact ordinates `z`, in balls at 256 bits; each
/// violation (a proven bound above its tolerance) is pushed to `problems`.
///
/// # Errors
/// A computation the check needs that fails (the parametrization, the spline, a root that
/// cannot be enclosed), with its error: the claim then fails, it is not a violation.
fn corollary_three_on(s: usize, z: &[Q], problems: &mut Vec<String>) -> Result<(), String> {
    let bits = 256;
    let shape = Shape::of_exact(z).map_err(|e| format!("the data: {e}"))?;
    let zb: Vec<Ball> = z.iter().map(|x| Ball::from_rational(x, &bits)).collect();
    let (t, _) =
        parametrization_with_shape(&zb, &shape).map_err(|e| format!("the parametrization: {e}"))?;
    let spline = NaturalCubicSpline::with_increasing_knots(t.clone(), zb.clone())
        .map_err(|e| format!("the spline: {e}"))?;
    let h: Vec<Ball> = t.windows(2).map(|w| w[1].clone() - &w[0]).collect();
    // (i) no overshoot.
    for i in 1..t.len() {
        let bound = super::proven_splines::overshoot_bound(&spline, &h[i - 1], i)
            .ok_or_else(|| format!("θ′ on interval {i} could not be enclosed"))?;
        if bound > 1e-40 {
            problems.push(format!("set {s}: overshoot on interval {i}"));
        }
    }
    // (ii) the third derivative jumps only at extremes (decided on the exact data).
    let idx = shape.extremes();
    let third = super::proven_splines::third_derivatives(&spline, &h);
    for j in 1..t.len() - 1 {
        if !idx.contains(&j) && (third[j].clone() - &third[j - 1]).abs_upper() > 1e-30 {
            problems.push(format!(
                "set {s}: third-derivative jump at non-extreme knot {j}"
            ));
        }
    }
    // (iii) θ″ at the interior extremes: −3 sgn(D)(Σ ε_j √|D_j|)², D_j exact.
    let d: Vec<Q> = idx.windows(2).map(|w| z[w[1]].clone() - &z[w[0]]).collect();
    let mm = d.len();
    let root2 = Ball::from_i64(2, &bits).sqrt();
    let sum = d
        .iter()
        .enumerate()
        .fold(Ball::zero_in(&bits), |acc, (j, x)| {
            let r = Ball::from_rational(&x.abs(), &bits).sqrt();
            acc + &(if j == 0 || j == mm - 1 { r } else { r * &root2 })
        });
    let peak = sum.clone() * &sum * &Ball::from_i64(3, &bits);
    let m = spline.second_derivatives_at_knots();
    for k in 1..mm {
        let expected = if d[k - 1] > Q::default() {
            -peak.clone()
        } else {
            peak.clone()
        };
        let rel = ((m[idx[k]].clone() - &expected) / &expected).abs_upper();
        if rel > 1e-40 {
            problems.push(format!(
                "set {s}: θ'' at extreme {k} off by up to {rel:.1e}"
            ));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Corollary 3's data sets, case III included, get knots enclosed as tightly as the
    /// precision allows: the fourth random set puts a root of ψ(t) = z_j exactly at the middle
    /// of its bisection bracket, where the bisection once stopped and left a ball 0.09 wide. (A
    /// root next to an extreme of ψ, where ψ′ → 0, is fixed only to about the square root of
    /// the working precision: 1e-30 leaves room for that, not for the old failure.)
    #[test]
    fn ball_knots_stay_tight_when_a_root_sits_at_a_bracket_middle() {
        let mut rng = SplitMix64::new(3);
        let mut sets: Vec<Vec<Q>> = vec![TABLE1.iter().map(|(z, _)| num(z)).collect()];
        for i in 0..4 {
            sets.push(random_ordinates(&mut rng, 7 + i, i % 2 == 0));
        }
        for (s, z) in sets.iter().enumerate() {
            let shape = Shape::of_exact(z).unwrap();
            let zb: Vec<Ball> = z.iter().map(|x| Ball::from_rational(x, &256)).collect();
            let (t, _) = parametrization_with_shape(&zb, &shape).unwrap();
            let widest = t.iter().map(Ball::rad).fold(0.0, f64::max);
            assert!(widest < 1e-30, "set {s}: a knot {widest:e} wide");
        }
    }
}
