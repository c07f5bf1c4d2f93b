//! Sentences of paper 004 checked on their own: the abstract's objective (without the
//! weights 1/α_l²), "gradient projection from chord length always improves", and bullet
//! (iii)'s "oscillations in the second derivative more centred about zero", each with the
//! data and the measure declared before computing.

use super::super::sample::SplitMix64;
use super::super::{Outcome, Verdict};
use super::data::{ROBOT_ALPHA, TABLE4};
use super::num;
use super::plane::components;
use crate::algo::param::descent::descend;
use crate::algo::param::natural::NaturalCubicSpline;
use crate::algo::param::objective::{chord_length_spacing, objective, Objective};
use crate::report::number::sig;
use crate::scalar::{BigRational, Field};

type Q = BigRational;

/// The robot data of Table IV as components, in f64.
fn robot() -> Vec<Vec<f64>> {
    (0..6)
        .map(|j| TABLE4.iter().map(|r| num(r[j]).to_f64()).collect())
        .collect()
}

/// The abstract states the objective as Σ∫(d²θ^l/dt²)² dt, without the weights 1/α_l² that
/// the same sentence introduces and Eq. 31 carries. Whether the weights matter: the minimizer
/// of Eq. 34 on the robot data (Table IV) with the paper's α = (1, 1, 2, 6, 6, 6) against
/// the one without weights, both by gradient projection from chord length.
pub fn objective_weights() -> Outcome {
    let z = robot();
    let h0 = chord_length_spacing(&z);
    let weighted: Vec<f64> = ROBOT_ALPHA.iter().map(|&a| a as f64).collect();
    let run = |alpha: &[f64]| {
        descend(
            h0.clone(),
            &z,
            alpha,
            Objective::Approximate,
            &mut |_, _| {},
        )
        .ok()
    };
    let (Some(with), Some(without)) = (run(&weighted), run(&[1.0; 6])) else {
        return Outcome::new("", "f64", Verdict::Failed, "a descent failed");
    };
    let knots = |h: &[f64]| {
        h.iter()
            .scan(0.0, |t, x| {
                *t += x;
                Some(*t)
            })
            .collect::<Vec<f64>>()
    };
    let (a, b) = (knots(&with.h), knots(&without.h));
    let gap = a
        .iter()
        .zip(&b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max);
    Outcome::new(
        format!("on the robot data the minimizers of Eq. 34 with and without the weights 1/α_l² differ by up to {} in a knot", sig(gap, 3)),
        "f64",
        if gap > 1e-3 { Verdict::Typo } else { Verdict::Failed },
        "gradient projection (exact line search) from 6-D chord length on Table IV, once with α = (1, 1, 2, 6, 6, 6) (Sec. 3) and \
         once with α = 1; the largest difference of the knots, in f64 (far above its rounding: the two objectives differ, not \
         their arithmetic). The weights change the parametrization, so the abstract's formula is not the paper's method; Eq. 31 \
         and the abstract's own words ('relative acceleration limits α_l') give the one consistent reading: a lost factor, on \
         which no number of the paper depends: clause 3",
    )
}

/// G at chord length and after gradient projection, exactly from the f64 iterates: (G₀, G_end).
fn improvement(z: &[Vec<f64>], alpha: &[f64], form: Objective) -> Option<(Q, Q)> {
    let h0 = chord_length_spacing(z);
    let end = descend(h0.clone(), z, alpha, form, &mut |_, _| {}).ok()?;
    let exact = |v: &[f64]| {
        v.iter()
            .map(|x| Q::from_float(*x))
            .collect::<Option<Vec<Q>>>()
    };
    let (zq, aq) = (
        z.iter().map(|c| exact(c)).collect::<Option<Vec<_>>>()?,
        exact(alpha)?,
    );
    Some((
        objective(&exact(&h0)?, &zq, &aq, form).ok()?,
        objective(&exact(&end.h)?, &zq, &aq, form).ok()?,
    ))
}

/// Sec. 3: starting from chord length, gradient projection "will always result in an
/// improved parametrization … provided π_B(∇G|h⁽⁰⁾) ≠ 0". On the paper's two examples (both
/// objectives on Table II; Eq. 34 with the paper's α on Table IV) and 20 random data sets.
pub fn always_improves() -> Outcome {
    let mut cases: Vec<(String, Option<(Q, Q)>)> = Vec::new();
    let plane = components::<f64>(&());
    cases.push((
        "Table II, Eq. 31".into(),
        improvement(&plane, &[1.0, 1.0], Objective::Exact),
    ));
    cases.push((
        "Table II, Eq. 34".into(),
        improvement(&plane, &[1.0, 1.0], Objective::Approximate),
    ));
    let alpha: Vec<f64> = ROBOT_ALPHA.iter().map(|&a| a as f64).collect();
    cases.push((
        "Table IV, Eq. 34".into(),
        improvement(&robot(), &alpha, Objective::Approximate),
    ));
    let mut rng = SplitMix64::new(30);
    for k in 0..20 {
        let dims = 1 + k % 3;
        let points = 5 + k % 7;
        let z: Vec<Vec<f64>> = (0..dims)
            .map(|_| rng.rationals(points).iter().map(Field::to_f64).collect())
            .collect();
        let form = if k % 2 == 0 {
            Objective::Exact
        } else {
            Objective::Approximate
        };
        cases.push((
            format!("random {dims}-D, {points} points"),
            improvement(&z, &vec![1.0; dims], form),
        ));
    }
    let improved = cases
        .iter()
        .filter(|(_, g)| g.as_ref().is_some_and(|(a, b)| b < a))
        .count();
    let failed: Vec<&str> = cases
        .iter()
        .filter(|(_, g)| g.is_none())
        .map(|(n, _)| n.as_str())
        .collect();
    let paper: Vec<String> = cases[..3]
        .iter()
        .filter_map(|(n, g)| {
            g.as_ref()
                .map(|(a, b)| format!("{n}: G {} → {}", sig(a.to_f64(), 6), sig(b.to_f64(), 6)))
        })
        .collect();
    Outcome::new(
        format!("G strictly decreases from chord length in {improved} of {} problems ({})", cases.len(), paper.join("; ")),
        "f64 iterates, G exact",
        Verdict::holds(improved == cases.len() && failed.is_empty()),
        format!(
            "gradient projection with exact line search from normalized chord length; G at the start and at the end evaluated \
             exactly from the f64 knots read as rationals. Problems: Table II with Eqs. 31 and 34 (α = 1), Table IV with Eq. 34 and \
             α = (1, 1, 2, 6, 6, 6), and 20 random data sets (1–3 components, 5–11 points, random rationals, Eqs. 31 and 34 \
             alternately); none started at a stationary point. Failed runs: {failed:?}"
        ),
    )
}

/// The declared measure of "centred about zero" for one component: |∫θ″ dt| / ∫|θ″| dt on
/// [0, 1] (0: as much area above zero as below; 1: all on one side), exact for the piecewise
/// linear θ″ of a natural cubic spline.
fn off_centre(t: &[f64], z: &[f64]) -> Option<f64> {
    let s = NaturalCubicSpline::new(t.to_vec(), z.to_vec()).ok()?;
    let m = s.second_derivatives_at_knots();
    let (mut signed, mut absolute) = (0.0, 0.0);
    for (w, h) in m.windows(2).zip(t.windows(2).map(|w| w[1] - w[0])) {
        let (a, b) = (w[0], w[1]);
        signed += h * (a + b) / 2.0;
        absolute += if a * b >= 0.0 {
            h * (a.abs() + b.abs()) / 2.0
        } else {
            h * (a * a + b * b) / (2.0 * (a.abs() + b.abs()))
        };
    }
    (absolute > 0.0).then(|| signed.abs() / absolute)
}

/// Sec. 2 bullet (iii) and Sec. 3: "oscillations in the second derivative are more centered
/// about zero" with the minimizing parametrizations than with chord length, on Table II.
pub fn oscillations_centred(parametrizations: &[(&str, Vec<f64>)], data: &[Vec<f64>]) -> Outcome {
    let mut rows = Vec::new();
    let mut better = 0usize;
    let mut worse = 0usize;
    let measure =
        |t: &[f64]| -> Option<Vec<f64>> { data.iter().map(|z| off_centre(t, z)).collect() };
    let Some(chord) = parametrizations.first().and_then(|(_, t)| measure(t)) else {
        return Outcome::new("", "f64", Verdict::Failed, "no chord-length spline");
    };
    rows.push(format!(
        "t^CL: x {}, y {}",
        sig(chord[0], 3),
        sig(chord[1], 3)
    ));
    for (name, t) in &parametrizations[1..] {
        let Some(m) = measure(t) else {
            return Outcome::new("", "f64", Verdict::Failed, format!("no spline for {name}"));
        };
        for (c, v) in chord.iter().zip(&m) {
            better += usize::from(v < c);
            worse += usize::from(v > c);
        }
        rows.push(format!("{name}: x {}, y {}", sig(m[0], 3), sig(m[1], 3)));
    }
    let total = 2 * (parametrizations.len() - 1);
    Outcome::new(
        format!("|∫θ″| / ∫|θ″| (0 = centred): {}", rows.join("; ")),
        "f64 (splines on certified knots)",
        if better == total && total > 0 { Verdict::Reproduced } else if worse == total { Verdict::Discrepancy } else { Verdict::Undetermined },
        "the paper gives no measure; declared before computing: the off-centre ratio |∫₀¹θ″ dt| / ∫₀¹|θ″| dt of each component's \
         natural spline (θ″ piecewise linear, integrated exactly per interval in f64), smaller is more centred. Reproduced when \
         both components are more centred under both minimizers (t^EX, t^AP) than under chord length; a discrepancy when all are \
         less centred; otherwise undetermined",
    )
}

/// Case III, observations (i) and (ii) before Corollary 2, on random mixed data: (i) every
/// z_j between two consecutive extremes lies strictly between them (exact); (ii) ψ, the
/// natural spline through the edited (extreme) data on their case II knots t̂, interpolates
/// them and is strictly monotone on each [t̂_{k−1}, t̂_k] (256 bits: no root of ψ′ inside an
/// interval farther than 1e-40·h from its ends, where Eq. 8 puts ψ′ = 0).
pub fn case3_observations() -> Outcome {
    use crate::algo::param::one_d::{alternating, Shape};
    use crate::scalar::Float;
    let bits = 256;
    let mut rng = SplitMix64::new(17);
    let (mut sets, mut holds_i, mut holds_ii) = (0usize, 0usize, 0usize);
    for trial in 0..30 {
        let mut z = vec![Q::from_integer(0.into())];
        for i in 0..(6 + trial % 8) {
            let step = Q::new(rng.int(1, 20).into(), 10.into());
            let down = (i / 2 + trial) % 3 == 0; // runs of equal direction: case III
            z.push(if down {
                z[i].clone() - step
            } else {
                z[i].clone() + step
            });
        }
        let Ok(shape) = Shape::of_exact(&z) else {
            continue;
        };
        if shape.case() != crate::algo::param::one_d::Case::III {
            continue;
        }
        sets += 1;
        let idx = shape.extremes();
        let between = |a: &Q, b: &Q, x: &Q| (a < x && x < b) || (b < x && x < a);
        holds_i += usize::from(
            idx.windows(2)
                .all(|w| (w[0] + 1..w[1]).all(|j| between(&z[w[0]], &z[w[1]], &z[j]))),
        );
        let edited: Vec<Float> = idx
            .iter()
            .map(|&i| Float::from_rational(&z[i], &bits))
            .collect();
        let Ok(t_hat) = alternating(&edited) else {
            continue;
        };
        let Ok(psi) = NaturalCubicSpline::new(t_hat.clone(), edited.clone()) else {
            continue;
        };
        let tiny = Float::with_val(bits, 1e-70);
        let interpolates = t_hat
            .iter()
            .zip(&edited)
            .all(|(t, v)| (psi.eval_all(t)[0].clone() - v).abs() < tiny);
        let m = psi.second_derivatives_at_knots();
        let monotone = (1..t_hat.len()).all(|i| {
            let h = t_hat[i].clone() - &t_hat[i - 1];
            // ψ′(t̂_{i−1} + v) = a v² + b v + c.
            let a = (m[i].clone() - &m[i - 1]) / (Float::with_val(bits, 2) * &h);
            let (b, c) = (m[i - 1].clone(), psi.eval_all(&t_hat[i - 1])[1].clone());
            let disc = b.clone() * &b - Float::with_val(bits, 4) * &a * &c;
            if disc.is_sign_negative() || a.is_zero() {
                return true;
            }
            let margin = h.clone() * Float::with_val(bits, 1e-40);
            [-1, 1].iter().all(|&sg| {
                let v = (-b.clone() + Float::with_val(bits, sg) * disc.clone().sqrt())
                    / (Float::with_val(bits, 2) * &a);
                !(v > margin && v < h.clone() - &margin)
            })
        });
        holds_ii += usize::from(interpolates && monotone);
    }
    Outcome::new(
        format!("{sets} random case III data sets: observation (i) holds in {holds_i}, observation (ii) in {holds_ii}"),
        "rational (i), mpfr:256 (ii)",
        Verdict::holds(sets >= 10 && holds_i == sets && holds_ii == sets),
        "ordinates from 0 by steps k/10 (k = 1…20) in runs of equal direction (case III, classified exactly); the extremes \
         i_0 < … < i_M from the exact data; (i) checked exactly; (ii) t̂ by Eq. 9 on the edited data and ψ their natural spline at \
         256 bits: |ψ(t̂_k) − z_{i_k}| < 1e-70, and ψ′ (a quadratic on each interval) has no root inside an interval farther than \
         1e-40·h from its ends (Eq. 8 puts ψ′ = 0 at the interior t̂, which rounding may move by ~1e-77)",
    )
}
