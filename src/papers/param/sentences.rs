//! Sentences of paper 004 checked on their own: the abstract's objective (without the
//! weights 1/α_l²), "gradient projection from chord length always improves", and bullet
//! (iii)'s "oscillations in the second derivative more centred about zero", each with the
//! data and the measure declared before computing.

use super::super::sample::SplitMix64;
use super::super::{Outcome, Verdict};
use super::data::{ROBOT_ALPHA, TABLE4};
use super::num;
use super::objective_claims::{ITERATES, ITERATES_NOTE};
use super::plane::components;
use super::proven_splines::{balls, decided, ProvenKnots, BITS};
use super::robot::{axes as robot_axes, robot_minimizer};
use crate::algo::param::descent::descend;
use crate::algo::param::natural::NaturalCubicSpline;
use crate::algo::param::objective::{chord_length_spacing, objective, Objective};
use crate::report::number::sig;
use crate::scalar::ball::Ball;
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
    let scalar = "ball:256";
    let h0 = chord_length_spacing(&robot());
    let computed = decided(|| {
        let (with, _) = robot_minimizer(&ROBOT_ALPHA, h0.clone())
            .map_err(|e| format!("with the weights: {e}"))?;
        let (without, _) =
            robot_minimizer(&[1; 6], h0).map_err(|e| format!("without the weights: {e}"))?;
        let gap = with
            .knots
            .iter()
            .zip(&without.knots)
            .fold(Ball::zero_in(&BITS), |a, (x, y)| {
                a.max_with(&(x.clone() - y).abs())
            });
        let differ = gap > Ball::from_ratio(1, 1000, &BITS);
        Ok((gap, differ))
    });
    let (gap, differ) = match computed {
        Ok(c) => c,
        Err(e) => return Outcome::failed(scalar, e),
    };
    Outcome::new(
        format!(
            "on the robot data the minimizers of Eq. 34 with and without the weights 1/α_l² differ by up to {} in a knot",
            crate::report::number::ball(&gap, 3)
        ),
        scalar,
        if differ { Verdict::Typo } else { Verdict::Failed },
        "gradient projection (exact line search) from 6-D chord length on Table IV, once with α = (1, 1, 2, 6, 6, 6) (Sec. 3) and \
         once with α = 1, each then polished by Newton's method at 256 bits and proven a strict local minimizer by Krawczyk's test \
         in balls (as marin.table6.approx); the largest difference of the knots, enclosed, and decided above 1e-3 (far above any \
         rounding: the two objectives differ, not their arithmetic). The weights change the parametrization, so the abstract's \
         formula is not the paper's method; Eq. 31 and the abstract's own words ('relative acceleration limits α_l') give the one \
         consistent reading: a lost factor, on which no number of the paper depends: clause 3",
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
        ITERATES,
        Verdict::holds(improved == cases.len() && failed.is_empty()),
        format!(
            "gradient projection with exact line search from normalized chord length; G at the start and at the end evaluated \
             exactly from the f64 knots read as rationals. Problems: Table II with Eqs. 31 and 34 (α = 1), Table IV with Eq. 34 and \
             α = (1, 1, 2, 6, 6, 6), and 20 random data sets (1–3 components, 5–11 points, random rationals, Eqs. 31 and 34 \
             alternately); none started at a stationary point. Failed runs: {failed:?}.{ITERATES_NOTE}"
        ),
    )
}

/// The declared measure of "centred about zero" for one component: |∫θ″ dt| / ∫|θ″| dt on
/// [0, 1] (0: as much area above zero as below; 1: all on one side), exact for the piecewise
/// linear θ″ of a natural cubic spline, here in balls on proven knots.
fn off_centre(knots: &ProvenKnots, z: &[Ball]) -> Result<Ball, String> {
    let s = knots.spline(z)?;
    let m = s.second_derivatives_at_knots();
    let zero = Ball::zero_in(&BITS);
    let two = Ball::from_i64(2, &BITS);
    let (mut signed, mut absolute) = (zero.clone(), zero.clone());
    for (w, h) in m.windows(2).zip(&knots.h) {
        let (a, b) = (&w[0], &w[1]);
        signed += &(h.clone() * &(a.clone() + b) / &two);
        // θ″ keeps its sign on the interval, or crosses zero once (two triangles).
        absolute += &(if a.clone() * b >= zero {
            h.clone() * &(a.abs() + &b.abs()) / &two
        } else {
            h.clone() * &(a.clone() * a + &(b.clone() * b)) / &(two.clone() * &(a.abs() + &b.abs()))
        });
    }
    if absolute <= zero {
        return Err(format!("{}: θ″ vanishes identically", knots.name));
    }
    Ok(signed.abs() / &absolute)
}

/// The declared measure of every component on each parametrization, chord length first, and
/// how many (minimizer, component) pairs are more and less centred than under chord length.
struct Centring {
    measures: Vec<Vec<Ball>>,
    better: usize,
    worse: usize,
    total: usize,
}

/// [`Centring`] of the components `data` on the parametrizations `knots` (chord length first),
/// inside [`decided`].
fn centring(knots: &[&ProvenKnots], data: &[Vec<Ball>]) -> Result<Centring, String> {
    let measures = knots
        .iter()
        .map(|k| {
            data.iter()
                .map(|z| off_centre(k, z))
                .collect::<Result<Vec<_>, _>>()
        })
        .collect::<Result<Vec<_>, String>>()?;
    let Some((chord, minimizers)) = measures.split_first() else {
        return Err("no chord-length spline".into());
    };
    let (mut better, mut worse) = (0usize, 0usize);
    for m in minimizers {
        for (c, v) in chord.iter().zip(m) {
            better += usize::from(v < c);
            worse += usize::from(v > c);
        }
    }
    let total = data.len() * minimizers.len();
    Ok(Centring {
        measures,
        better,
        worse,
        total,
    })
}

/// The verdict of one example: all more centred, reproduced; all less, discrepancy; else
/// undetermined.
fn centring_verdict(c: &Centring) -> Verdict {
    if c.better == c.total && c.total > 0 {
        Verdict::Reproduced
    } else if c.worse == c.total {
        Verdict::Discrepancy
    } else {
        Verdict::Undetermined
    }
}

/// "name: x …, y …" lines of one example's measures.
fn centring_rows(knots: &[&ProvenKnots], c: &Centring, axes: &[&str]) -> Vec<String> {
    knots
        .iter()
        .zip(&c.measures)
        .map(|(k, m)| {
            let cells: Vec<String> = axes
                .iter()
                .zip(m)
                .map(|(a, v)| format!("{a} {}", crate::report::number::ball(v, 3)))
                .collect();
            format!("{}: {}", k.name, cells.join(", "))
        })
        .collect()
}

const CENTRING_MEASURE: &str = "the paper gives no measure; declared before computing: the off-centre ratio |∫₀¹θ″ dt| / \
     ∫₀¹|θ″| dt of each component's natural spline (θ″ piecewise linear, integrated exactly per interval, in ball arithmetic at \
     256 bits on proven knots; each sign of θ″ and each comparison decided on disjoint enclosures), smaller is more centred";

/// Sec. 3, example 1 (Table II, Figs. 3–5): "oscillations in the second derivative are more
/// centered about zero" with the minimizing parametrizations than with chord length.
pub fn table2_oscillations_centred(proven: &Result<Vec<ProvenKnots>, String>) -> Outcome {
    let scalar = "ball:256";
    let computed = decided(|| {
        let proven: Vec<&ProvenKnots> = proven.as_ref().map_err(Clone::clone)?.iter().collect();
        let data: Vec<Vec<Ball>> = components::<BigRational>(&())
            .iter()
            .map(|z| balls(z))
            .collect();
        Ok((centring(&proven, &data)?, proven))
    });
    let (c, knots) = match computed {
        Ok(c) => c,
        Err(e) => return Outcome::failed(scalar, e),
    };
    Outcome::new(
        format!("|∫θ″| / ∫|θ″| (0 = centred): {}", centring_rows(&knots, &c, &["x", "y"]).join("; ")),
        scalar,
        centring_verdict(&c),
        format!(
            "{CENTRING_MEASURE}, on the proven knots of marin.fig3_5.second_derivatives. Reproduced when both components are more \
             centred under both minimizers (t^EX, t^AP) than under chord length; a discrepancy when all are less centred; otherwise \
             undetermined"
        ),
    )
}

/// Sec. 2 bullet (iii): for K > 1, "oscillations in the second derivative tend to be more
/// centered about zero" — the general remark, on both of the paper's examples: Table II
/// (t^CL, t^EX, t^AP) and the robot data (t^CL, t^AP; t^WC is not a parametrization of the
/// axis data).
pub fn oscillations_centred(
    plane: &Result<Vec<ProvenKnots>, String>,
    robot: [Option<&ProvenKnots>; 2],
) -> Outcome {
    let scalar = "ball:256";
    let computed = decided(|| {
        let plane: Vec<&ProvenKnots> = plane.as_ref().map_err(Clone::clone)?.iter().collect();
        let robot: Vec<&ProvenKnots> = robot
            .iter()
            .map(|k| k.ok_or("our robot t^AP was not proven (marin.table6.approx)"))
            .collect::<Result<_, _>>()?;
        let plane_data: Vec<Vec<Ball>> = components::<BigRational>(&())
            .iter()
            .map(|z| balls(z))
            .collect();
        let robot_data: Vec<Vec<Ball>> = robot_axes().iter().map(|z| balls(z)).collect();
        let examples = [
            centring(&plane, &plane_data)?,
            centring(&robot, &robot_data)?,
        ];
        Ok((examples, plane, robot))
    });
    let ([table2, arm], plane, robot) = match computed {
        Ok(c) => c,
        Err(e) => return Outcome::failed(scalar, e),
    };
    let verdicts = [centring_verdict(&table2), centring_verdict(&arm)];
    let verdict = if verdicts.iter().all(|v| *v == Verdict::Reproduced) {
        Verdict::Reproduced
    } else if verdicts.iter().all(|v| *v == Verdict::Discrepancy) {
        Verdict::Discrepancy
    } else {
        Verdict::Undetermined
    };
    let axes = ["1", "2", "3", "4", "5", "6"];
    Outcome::new(
        format!(
            "|∫θ″| / ∫|θ″| (0 = centred). Table II: {}; more centred in {} of {} cases. Robot (Table IV, axes 1–6): {}; more \
             centred in {} of {} cases",
            centring_rows(&plane, &table2, &["x", "y"]).join("; "),
            table2.better,
            table2.total,
            centring_rows(&robot, &arm, &axes).join("; "),
            arm.better,
            arm.total
        ),
        scalar,
        verdict,
        format!(
            "{CENTRING_MEASURE}. The remark is general, and the paper offers two examples for it: Table II (our proven t^CL, t^EX, \
             t^AP; marin.table2.oscillations_centred) and the robot data (our proven t^CL and t^AP of Table VI; t^WC parametrizes \
             the work-centre positions, not the axes). One measure for both, declared once. Per example: reproduced when every \
             component is more centred under every minimizer than under chord length, a discrepancy when every one is less; the \
             remark is reproduced when both examples reproduce it, a discrepancy when both contradict it, otherwise undetermined"
        ),
    )
}

/// Case III, observations (i) and (ii) before Corollary 2, on random mixed data: (i) every
/// z_j between two consecutive extremes lies strictly between them (exact); (ii) ψ, the
/// natural spline through the edited (extreme) data on their case II knots t̂, interpolates
/// them and is strictly monotone on each [t̂_{k−1}, t̂_k] — in balls at 256 bits: ψ(t̂_k) within
/// a proven 1e-70 of its datum, and every root of ψ′ on a piece (enclosed) within 1e-40·h of
/// the piece's ends, where Eq. 8 puts ψ′ = 0.
pub fn case3_observations() -> Outcome {
    use crate::algo::param::one_d::Shape;
    let scalar = "rational (i), ball:256 (ii)";
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
        let edited: Vec<Ball> = idx
            .iter()
            .map(|&i| Ball::from_rational(&z[i], &bits))
            .collect();
        match observation_ii(&edited) {
            Ok(holds) => holds_ii += usize::from(holds),
            Err(e) => return Outcome::failed(scalar, format!("set {sets}: {e}")),
        }
    }
    Outcome::new(
        format!("{sets} random case III data sets: observation (i) holds in {holds_i}, observation (ii) in {holds_ii}"),
        scalar,
        Verdict::holds(sets >= 10 && holds_i == sets && holds_ii == sets),
        "ordinates from 0 by steps k/10 (k = 1…20) in runs of equal direction (case III, classified exactly); the extremes \
         i_0 < … < i_M from the exact data; (i) checked exactly; (ii) t̂ by Eq. 9 on the edited data and ψ their natural spline, \
         in ball arithmetic at 256 bits: |ψ(t̂_k) − z_{i_k}| proven below 1e-70, and every root of ψ′ (a quadratic on each \
         interval, each root enclosed) proven within 1e-40·h of the interval's ends (Eq. 8 puts ψ′ = 0 at the interior t̂)",
    )
}

/// Observation (ii) on the edited (extreme) data, in balls: ψ interpolates them at t̂ (within a
/// proven 1e-70) and every root of ψ′ on a piece lies within 1e-40·h of the piece's ends.
///
/// # Errors
/// ψ's knots or spline, or a root of ψ′ that cannot be enclosed (the claim then fails).
fn observation_ii(edited: &[Ball]) -> Result<bool, String> {
    use crate::algo::param::one_d::alternating;
    let bits = 256;
    let t_hat = alternating(edited).map_err(|e| format!("t̂: {e}"))?;
    let psi = NaturalCubicSpline::with_increasing_knots(t_hat.clone(), edited.to_vec())
        .map_err(|e| format!("ψ: {e}"))?;
    let zero = Ball::zero_in(&bits);
    let tiny = Q::new(1.into(), num_bigint::BigInt::from(10).pow(40));
    let tiny = Ball::from_rational(&tiny, &bits);
    let mut holds = true;
    for k in 1..t_hat.len() {
        let h = t_hat[k].clone() - &t_hat[k - 1];
        let left = psi.eval_offsets(&h, &zero, k)[0].clone() - &edited[k - 1];
        let right = psi.eval_offsets(&zero, &h, k)[0].clone() - &edited[k];
        holds &= left.abs_upper() < 1e-70 && right.abs_upper() < 1e-70;
        let margin = h.clone() * &tiny;
        let roots = psi
            .slope_roots(k)
            .ok_or_else(|| format!("ψ′ on piece {k} could not be enclosed"))?;
        holds &= roots
            .iter()
            .all(|v| v.upper() < margin.lower() || v.lower() > (h.clone() - &margin).upper());
    }
    Ok(holds)
}

/// The index sets {i_1 < … < i_{M−1}} ⊂ {1, …, N − 1} whose consecutive members satisfy
/// `keep(Δ, i_k, i_{k+1})`, exactly (Δ_i = z_i − z_{i−1}, 1-based).
fn index_sets(delta: &[Q], keep: impl Fn(&[Q], usize, usize) -> bool) -> Vec<Vec<usize>> {
    let n = delta.len();
    (1u32..(1 << (n - 1)))
        .map(|mask| {
            (1..n)
                .filter(|i| mask & (1 << (i - 1)) != 0)
                .collect::<Vec<usize>>()
        })
        .filter(|set| set.windows(2).all(|w| keep(delta, w[0], w[1])))
        .collect()
}

/// Case III, before Eq. (13): "identify all indices 1 ≤ i_1 < … < i_{M−1} ≤ N − 1 for which
/// Δ_{i_{k+1}}/Δ_{i_k} < 0". As printed the condition relates chosen indices to each other and
/// does not determine the set; the case's heading ("Δ_{i+1}/Δ_i changes sign") and Corollary
/// 3 (ii) ("the indices which locate … interior relative extreme values") read Δ_{i_k+1}/Δ_{i_k}
/// < 0, which selects the extremes. Exact, on z = (0, 1, 2, 1, 0, 1): every subset of
/// {1, …, N − 1} whose consecutive members satisfy the printed condition, against the set the
/// intended one gives, and the edited data (Eq. 13) of each.
pub fn extremum_index() -> Outcome {
    let z: Vec<Q> = [0, 1, 2, 1, 0, 1]
        .iter()
        .map(|&v| Q::from_integer(v.into()))
        .collect();
    let delta: Vec<Q> = z.windows(2).map(|w| w[1].clone() - &w[0]).collect();
    let d = |i: usize| &delta[i - 1];
    // a/b < 0, decided as a·b < 0 (no division: an edited D can be 0).
    let negative = |a: &Q, b: &Q| (a.clone() * b) < Q::from_integer(0.into());
    let n = delta.len();
    let intended: Vec<usize> = (1..n).filter(|&i| negative(d(i + 1), d(i))).collect();
    let printed = index_sets(&delta, |delta, a, b| negative(&delta[b - 1], &delta[a - 1]));
    // Which printed sets leave edited data with every D ≠ 0 (case II needs D_{i_{k+1}}/D_{i_k} < 0).
    let case_two = |set: &Vec<usize>| {
        let mut idx = vec![0];
        idx.extend(set);
        idx.push(n);
        let big_d: Vec<Q> = idx.windows(2).map(|w| z[w[1]].clone() - &z[w[0]]).collect();
        big_d.windows(2).all(|w| negative(&w[1], &w[0]))
    };
    let valid = printed.iter().filter(|s| case_two(s)).count();
    let holds = printed.len() > 1 && printed.contains(&intended) && case_two(&intended);
    Outcome::new(
        format!(
            "z = (0, 1, 2, 1, 0, 1): {} index sets satisfy the printed condition Δ_(i_(k+1))/Δ_(i_k) < 0 ({:?}; {valid} of them \
             give edited data of case II); the intended Δ_(i_k+1)/Δ_(i_k) < 0 gives one, {intended:?} (the interior extremes)",
            printed.len(),
            printed
        ),
        "rational",
        if holds { Verdict::Typo } else { Verdict::Failed },
        "exact rationals; every subset of {1, …, N − 1} tested against the condition as printed (consecutive chosen indices with \
         Δ of opposite signs) and as the heading and Corollary 3 (ii) intend (Δ changes sign right after i_k); the edited data \
         z_(i_0), …, z_(i_M) of Eq. (13) must be of case II (consecutive D of opposite signs) for the paper's next step. One \
         misplaced subscript (i_(k+1) for i_k + 1), with one consistent reading that the paper's heading and Corollary 3 fix and \
         on which no printed number depends: clause 3",
    )
}

/// The proof of Corollary 2, Eq. (26), first line: "t̂_{i_k} = t*_{i_k}, k = 0, …, M", stated
/// as "the immediate implication of (25) and case II uniqueness". As printed the line is Eq.
/// (16), the definition of t*, and follows from nothing; what (25) and case II uniqueness give,
/// and what the next lines use (ψ̃ = ψ on the same knots), is t̃_{i_k} = t̂_{i_k}: any minimizer
/// t̃ has the case II knots at the extremes. That statement is checked where it can fail: on
/// `corollary`'s proven minimizers (random case III data, three starts each), every knot —
/// the extreme ones among them — lies within its proven bound of Eqs. 16–17, whose knots at
/// the extremes are t̂ (Eq. 16).
pub fn eq26_tilde(corollary: &Outcome) -> Outcome {
    let verdict = crate::papers::typo_if_reading_holds(corollary);
    Outcome::new(
        format!(
            "t̃_(i_k) = t̂_(i_k) for every minimizer t̃ (marin.cor2.unique_minimizer: {}); the printed t̂_(i_k) = t*_(i_k) is Eq. (16)",
            corollary.reproduced
        ),
        corollary.scalar.clone(),
        verdict,
        "the printed first line of Eq. (26) restates Eq. (16) (t*_(i_k) := t̂_(i_k)), so it cannot be what (25) and case II \
         uniqueness imply; the second line ψ̃ = ψ needs ψ̃'s knots t̃_(i_k) to be ψ's knots t̂_(i_k). Computed: on the proven \
         minimizers of marin.cor2.unique_minimizer every knot, the extreme ones included, equals Eqs. 16–17's within its proven \
         bound, so t̃_(i_k) = t̂_(i_k) holds. One symbol (a hat for a tilde), with the one reading the proof's next line fixes, on \
         which no printed number depends: clause 3",
    )
}

/// Sec. 3, example 1: "These observations [smaller third-derivative jumps; oscillations in the
/// second derivative more centred about zero] are most pronounced when the plot of d²x/dt² vs
/// t from Fig. 3 is compared to the one in Fig. 4" (t^CL against t^EX). Under the ledger's
/// measures, declared before this claim (marin.sec2.third_derivative_jumps: the jump sum at
/// non-extreme knots; marin.table2.oscillations_centred: |∫θ″|/∫|θ″|), each observation is "most
/// pronounced for x" when x's relative reduction from t^CL to t^EX is larger than y's, decided
/// on disjoint enclosures. The sentence names both observations: both hold, reproduced; neither,
/// discrepancy; one, undetermined (clause 5).
pub fn x_most_pronounced(proven: &Result<Vec<ProvenKnots>, String>) -> Outcome {
    let scalar = "ball:256";
    let computed = decided(|| {
        let proven = proven.as_ref().map_err(Clone::clone)?;
        let (Some(chord), Some(extremal)) = (proven.first(), proven.get(1)) else {
            return Err("the t^CL and t^EX knots are missing".into());
        };
        let data: Vec<Vec<Ball>> = components::<BigRational>(&())
            .iter()
            .map(|z| balls(z))
            .collect();
        let centring = |k: &ProvenKnots| {
            data.iter()
                .map(|z| off_centre(k, z))
                .collect::<Result<Vec<Ball>, String>>()
        };
        // (after − before)/before per component: the more negative, the larger the reduction.
        let change = |before: &[Ball], after: &[Ball]| -> Vec<Ball> {
            before
                .iter()
                .zip(after)
                .map(|(b, a)| (a.clone() - b) / b)
                .collect()
        };
        let jumps = change(
            &super::plane::jump_sums(chord)?,
            &super::plane::jump_sums(extremal)?,
        );
        let centred = change(&centring(chord)?, &centring(extremal)?);
        Ok((jumps, centred))
    });
    let (jumps, centred) = match computed {
        Ok(c) => c,
        Err(e) => return Outcome::failed(scalar, e),
    };
    let x_larger = |r: &[Ball]| r[0].decide_lt(&r[1]);
    let (Some(by_jumps), Some(by_centring)) = (x_larger(&jumps), x_larger(&centred)) else {
        return Outcome::failed(
            scalar,
            "a comparison of the reductions is not decided by the enclosures",
        );
    };
    let percent =
        |b: &Ball| crate::report::number::ball(&(b.clone() * &Ball::from_i64(100, &BITS)), 2);
    let verdict = match (by_jumps, by_centring) {
        (true, true) => Verdict::Reproduced,
        (false, false) => Verdict::Discrepancy,
        _ => Verdict::Undetermined,
    };
    Outcome::new(
        format!(
            "t^CL → t^EX: third-derivative jump sum x {} %, y {} % ({}); off-centre ratio x {} %, y {} % ({})",
            percent(&jumps[0]),
            percent(&jumps[1]),
            if by_jumps { "x reduced more" } else { "y reduced more" },
            percent(&centred[0]),
            percent(&centred[1]),
            if by_centring { "x more centred" } else { "y more centred" }
        ),
        scalar,
        verdict,
        "the natural splines of Table II on the proven t^CL and t^EX knots (marin.fig3_5.second_derivatives), in ball arithmetic \
         at 256 bits; relative changes of the two measures the ledger declared for these observations, compared on disjoint \
         enclosures. The sentence names both observations, so each is judged and clause 5 combines them",
    )
}

/// Corollary 3 (iii): "θ″(t_{i_k}) = −3 sgn(D_{i_k})(Σ_{j=1}^M ε_j √|D_j|)²" with "D_{i_k} =
/// z_{i_k} − z_{i_{k−1}}, k = 1, …, M" (Eq. 13). D is defined only at the extreme indices i_k,
/// so D_j for j ∉ {i_k} is undefined; the consistent reading is D_{i_j}. Checked under that
/// reading by `corollary` (marin.cor3.properties, which sums over the M differences of
/// consecutive extremes): where it holds, the reading is the paper's.
pub fn d_index(corollary: &Outcome) -> Outcome {
    let verdict = crate::papers::typo_if_reading_holds(corollary);
    Outcome::new(
        format!(
            "with D_(i_j) (the differences of consecutive extremes, Eq. 13) the formula holds (marin.cor3.properties: {})",
            corollary.reproduced
        ),
        corollary.scalar.clone(),
        verdict,
        "Eq. (13) defines D only at the extreme indices i_1 < … < i_M, so the printed Σ_(j=1)^M ε_j √|D_j| reads D at indices where it \
         is undefined (for j not an extreme index) or at the wrong one; marin.cor3.properties checks (iii) with D_(i_j), in balls at \
         256 bits on Table I and random case II and III data. A lost index level (D_j for D_(i_j)), with the one reading Eq. (13) \
         fixes, on which no printed number depends: clause 3",
    )
}
