//! Statements of the prose of paper 000 that no equation number carries: the meaning of n in
//! Sec. 3, the first-derivative relation of Sec. 3.1, the order count of Sec. 2.3 and the
//! accelerations of Fig. 2. All exact in rationals.

use super::super::{Outcome, Verdict};
use crate::algo::hermite::HermiteData;
use crate::numeric::maximum::{mean_value, midpoint, proven_range, SearchOptions};
use crate::numeric::poly::differences::{anti_difference, backward_anti_difference};
use crate::numeric::poly::{binomial, Bernstein};
use crate::scalar::ball::Ball;
use crate::scalar::{BigRational, Field};

type Q = BigRational;

fn q(n: i64) -> Q {
    Q::from_integer(n.into())
}

/// Eqs. 16–17 with the symbol n of Eqs. 12–15 set to `n`: the control points the start data
/// fix (p_0 … p_m) and those the end data fix (p_(n−m) … p_n), on an interval of length `t`.
fn eq16_17(start: &[Q], end: &[Q], t: &Q, n: usize) -> (Vec<Q>, Vec<Q>) {
    // q_j = T^j (n−j)!/n! x^(j): the scaled derivatives of Eq. 16 (Q^0) and Eq. 17 (Q^1).
    let scaled = |x: &[Q]| -> Vec<Q> {
        let mut factor = q(1);
        x.iter()
            .enumerate()
            .map(|(j, v)| {
                if j > 0 {
                    factor = factor.clone() * t / q((n + 1 - j) as i64);
                }
                v.clone() * &factor
            })
            .collect()
    };
    // Eq. 16's Δ^(−j) and Eq. 17's ∇^(−j), as the library has them.
    (
        anti_difference(&scaled(start)),
        backward_anti_difference(&scaled(end)),
    )
}

/// Sec. 3: "n = 2(m + 1)" for the map f : R^n → R^n, while Eqs. 12–18 use n as the degree.
pub fn n_is_count(printed_fig2: &str) -> Outcome {
    let (start, end, t) = (vec![q(0), q(0), q(0)], vec![q(1), q(1), q(0)], q(1));
    let m = 2;
    let show = |v: &[Q]| {
        v.iter()
            .map(|x| x.to_string())
            .collect::<Vec<_>>()
            .join(", ")
    };
    let (s6, e6) = eq16_17(&start, &end, &t, 2 * (m + 1));
    let (s5, e5) = eq16_17(&start, &end, &t, 2 * m + 1);
    let as_degree_5: Vec<Q> = s5.iter().chain(&e5).cloned().collect();
    let printed: Vec<Option<Q>> = printed_fig2
        .split_whitespace()
        .map(|s| crate::scalar::parse::parse_rational(s).ok())
        .collect();
    let degree_5_matches = printed.len() == as_degree_5.len()
        && printed
            .iter()
            .zip(&as_degree_5)
            .all(|(p, c)| p.as_ref() == Some(c));
    Outcome::new(
        format!(
            "with n = 2(m+1) = 6 in Eqs. 14–17 the Fig. 2 data fix p_0…p_2 = {} and p_4…p_6 = {}, leaving p_3 free (7 control points, 6 conditions); with n = 2m+1 = 5 they give [{}], the printed vector",
            show(&s6),
            show(&e6),
            show(&as_degree_5)
        ),
        "rational",
        if degree_5_matches { Verdict::Typo } else { Verdict::Discrepancy },
        "Sec. 3 says f : H ∈ R^n → P ∈ R^n with n = 2(m+1): there n counts the control points. Eqs. 12–18 use n as the degree (n!/(n−j)!, \
         p_0…p_n). Eqs. 16–17 computed exactly with each value for the Fig. 2 data (m = 2, T = 1). Reading used: n is the degree 2m+1 in \
         Eqs. 12–18 and the dimension of H and P is n+1 = 2(m+1); one symbol with two meanings, which the printed Fig. 2 vector settles",
    )
}

/// Sec. 3.1: "x_0^(1) = nΔ¹(p_0) = n(p_1 − p_0)", printed without Eq. 14's 1/(t_1 − t_0).
pub fn first_derivative_factor() -> Outcome {
    // A documented instance on an interval of length 3.
    let data = HermiteData::new(vec![q(1), q(2)], vec![q(4), q(-1)], (q(0), q(3)));
    let Ok(curve) = data.and_then(|d| d.solve()) else {
        return Outcome::new(
            "",
            "rational",
            Verdict::Failed,
            "the instance did not solve",
        );
    };
    let n = curve.degree();
    let p = &curve.control_points();
    let printed = q(n as i64) * (p[1].clone() - &p[0]);
    let actual = curve.derivative_at_start(1);
    let with_factor = printed.clone() / q(3);
    let verdict = match (printed == actual, with_factor == actual) {
        (true, _) => Verdict::Reproduced,
        (false, true) => Verdict::Typo,
        (false, false) => Verdict::Discrepancy,
    };
    Outcome::new(
        format!("on [0, 3]: n(p_1 − p_0) = {printed}, the derivative x_0^(1) = {actual}; n(p_1 − p_0)/(t_1 − t_0) = {with_factor}"),
        "rational",
        verdict,
        "start (x, x′) = (1, 2), end (4, −1) on [0, 3], solved exactly (cubic). The prose drops the factor 1/(t_1 − t_0) that Eq. 14, two \
         lines above, carries; as printed the relation holds only on intervals of length 1. Reading used: Eq. 14's, which holds exactly",
    )
}

/// Sec. 2.3: each derivative constraint raises the order by two; the tenth derivative gives
/// order twenty-one.
pub fn order_count() -> Outcome {
    let mut degrees = Vec::new();
    for m in 0..=10usize {
        let start: Vec<Q> = (0..=m).map(|j| q(j as i64 + 1)).collect();
        let end: Vec<Q> = (0..=m).map(|j| q(2 * j as i64 - 3)).collect();
        match HermiteData::new(start, end, (q(0), q(1))).and_then(|d| d.solve()) {
            Ok(c) => degrees.push(c.degree()),
            Err(_) => degrees.push(usize::MAX),
        }
    }
    let steps_of_two = degrees.windows(2).all(|w| w[1] == w[0] + 2);
    let last = degrees.last().copied().unwrap_or(0);
    Outcome::new(
        format!("degrees for m = 0…10: {degrees:?}; up to the tenth derivative: {last}"),
        "rational",
        Verdict::holds(steps_of_two && last == 21),
        "the exact Hermite map solved for constraints up to the m-th derivative at both ends, m = 0…10 (unique solutions): the degree is \
         2m+1, two more per derivative, 21 for m = 10; the paper's \"order\" is this degree",
    )
}

/// Precision of the proven acceleration ranges (bits).
const RANGE_BITS: u32 = 128;

/// Proven enclosures of min and max of x″ over [t0, t1] of an exact curve: the curve's
/// control points as exact balls, branch and bound with the mean-value form
/// x″(m) + x‴(X)(X − m) (de Casteljau's evaluation over a box encloses the polynomial there).
fn acceleration_range(c: &Bernstein<Q>) -> Result<(Ball, Ball), String> {
    let to_balls = |b: &Bernstein<Q>| {
        let points = b
            .control_points()
            .iter()
            .map(|q| Ball::from_rational(q, &RANGE_BITS))
            .collect();
        let (t0, t1) = (
            Ball::from_rational(b.t0(), &RANGE_BITS),
            Ball::from_rational(b.t1(), &RANGE_BITS),
        );
        Bernstein::new(points, (t0, t1)).map_err(|e| e.to_string())
    };
    let (second, third) = (
        to_balls(&c.nth_derivative(2))?,
        to_balls(&c.nth_derivative(3))?,
    );
    let f = |x: &Ball| Ok(mean_value(&second.eval(&midpoint(x)), &third.eval(x), x));
    let (start, end) = (second.t0().mid().clone(), second.t1().mid().clone());
    let options = SearchOptions {
        tolerance: 1e-15,
        bits: RANGE_BITS,
        ..SearchOptions::default()
    };
    let (min, max) = proven_range(f, (&start, &end), &options).map_err(|e| e.to_string())?;
    Ok((min.ball(), max.ball()))
}

/// Fig. 2: "the lower duration curve must have … larger acceleration (and deceleration)".
pub fn shorter_accelerates_more(fast: &Bernstein<Q>, slow: &Bernstein<Q>) -> Outcome {
    let scalar = format!("rational, ball:{RANGE_BITS}");
    let ranges = acceleration_range(fast).and_then(|f| Ok((f, acceleration_range(slow)?)));
    let ((f_lo, f_hi), (s_lo, s_hi)) = match ranges {
        Ok(r) => r,
        Err(e) => return Outcome::failed(scalar, e),
    };
    let (larger, deeper) = (s_hi.decide_lt(&f_hi), f_lo.decide_lt(&s_lo));
    let verdict = match (larger, deeper) {
        (Some(a), Some(b)) => Verdict::holds(a && b),
        _ => Verdict::Failed,
    };
    let b = |x: &Ball| crate::report::number::ball(x, 9);
    Outcome::new(
        format!(
            "duration 1: x″ from {} to {}; duration 2: from {} to {}",
            b(&f_lo),
            b(&f_hi),
            b(&s_lo),
            b(&s_hi)
        ),
        scalar,
        verdict,
        "the exact Fig. 2 curves (H = [0 0 0 | 1 1 0]); the extremes of x″ over each whole interval enclosed by ball branch and \
         bound (nothing sampled); criterion: the shorter curve's largest acceleration is larger and its largest deceleration \
         (most negative x″) more negative, each comparison decided on disjoint enclosures",
    )
}

/// Eq. 4 and the sentence after it: the basis on [t0, t1] is b_k^n(ζ(t)) with Eq. 3's ζ, and
/// the curve interpolates its first and last control points.
pub fn eq4_basis_and_endpoints() -> Outcome {
    let mut rng = super::super::sample::SplitMix64::new(4);
    let (mut compared, mut bad) = (0usize, Vec::new());
    for n in 1..=12usize {
        let points = rng.rationals(n + 1);
        let (t0, t1) = (Q::new((-3).into(), 2.into()), Q::new(7.into(), 3.into()));
        let curve = Bernstein::new(points.clone(), (t0.clone(), t1.clone()))
            .expect("t0 < t1 and n + 1 points by construction");
        let span = t1.clone() - &t0;
        for t in [t0.clone(), Q::new(1.into(), 5.into()), t1.clone()] {
            // Eq. 4: C(n,k)(t1 − t)^(n−k)(t − t0)^k/(t1 − t0)^n, summed against the points.
            let eq4 = (0..=n).fold(q(0), |acc, k| {
                let b = Q::from_integer(binomial(n, k))
                    * crate::scalar::powi(&(t1.clone() - &t), (n - k) as u32)
                    * crate::scalar::powi(&(t.clone() - &t0), k as u32)
                    / crate::scalar::powi(&span, n as u32);
                acc + b * &points[k]
            });
            compared += 1;
            if eq4 != curve.eval(&t) {
                bad.push(format!("n = {n}, t = {t}"));
            }
        }
        if curve.eval(&t0) != points[0] || curve.eval(&t1) != points[n] {
            bad.push(format!("n = {n}: endpoints"));
        }
    }
    Outcome::new(
        format!("Eq. 4 equals de Casteljau's evaluation at ζ(t) at {compared} points, and B(t0) = p_0, B(t1) = p_n, for n = 1…12 ({} failures)", bad.len()),
        "rational",
        Verdict::holds(bad.is_empty()),
        format!(
            "random rational control points on [−3/2, 7/3], degrees 1…12, at t = t0, 1/5, t1: Eq. 4 summed exactly against the control \
             points and compared with de Casteljau's algorithm at ζ = (t − t0)/(t1 − t0) (Eq. 3); the endpoint values compared with p_0 \
             and p_n. Failures: {bad:?}"
        ),
    )
}

/// The Fig. 4 caption (initial position, velocity *and acceleration*) against the text
/// (initial position and velocity). A missing or added phrase is not a one-symbol garble
/// (clause 3), and the method poses both readings: the text's data with m = 1 at each end, the
/// caption's with m = 2 (the terminal acceleration then free data, as
/// `hermite.fig4.landing_constraints` poses it). The paper prints no data for Fig. 4, so
/// nothing decides between them: undetermined by clause 5.
pub fn fig4_caption_vs_text() -> Outcome {
    // Each reading as one exact problem of Eqs. 16–18 on one coordinate.
    let text_problem = HermiteData::new(vec![q(0), q(70)], vec![q(3000), q(60)], (q(0), q(60)))
        .and_then(|d| d.solve())
        .is_ok();
    let caption_problem = HermiteData::new(
        vec![q(0), q(70), q(-2)],
        vec![q(3000), q(60), q(0)],
        (q(0), q(60)),
    )
    .and_then(|d| d.solve())
    .is_ok();
    let verdict = if text_problem && caption_problem {
        Verdict::Undetermined
    } else {
        Verdict::Failed
    };
    let computed = format!(
        "text: position and velocity at the start, a problem of Eqs. 16–18 with m = 1 (solved: {text_problem}); caption: position, \
         velocity and acceleration at the start, with m = 2 (solved: {caption_problem})"
    );
    Outcome::new(
        computed.clone(),
        "rational",
        verdict,
        "the caption says the trajectory connects the vehicle's initial position, velocity and acceleration; the text says \"the \
         initial condition is set as the vehicle's current position and velocity\". The two differ by a phrase, not by one symbol \
         (clause 3 does not apply), and both are problems of the paper's method: m = 1 at each end, or m = 2 with the end's \
         acceleration as data (solved exactly here on one coordinate with data of our own). The paper prints no data for Fig. 4, \
         so nothing printed decides which the figure used: clause 5",
    )
    .finding(
        ("initial position, velocity, and acceleration (caption) | position and velocity (text)", &computed, "the caption names one derivative more than the text; both readings are problems of the method"),
        crate::ledger::Severity::Minor,
        "Fig. 4 carries no numbers, so neither reading changes a printed result",
    )
}

/// Sec. 2.2 indexes "a vector of length n" by j = 0…n−1 while its elements are x_0…x_n and
/// (A1) reaches Δⁿx_0: a vector x_0…x_n has n + 1 entries, and its forward differences
/// Δʲx_0, j = 0…n, fill the (n+1)×(n+1) matrix (A1). The words are off by one against the
/// paper's own symbols (policy clause 3: an index offset, one consistent reading).
pub fn sec22_indexing() -> Outcome {
    let mut consistent = true;
    for n in 1..=12 {
        let a1 = crate::numeric::poly::differences::forward_difference_matrix::<Q>(n, &());
        // x = (0, …, 0, 1) has Δⁿx_0 = 1: the last row of (A1) reaches Δⁿ.
        consistent &= a1.rows() == n + 1 && a1[(n, n)] == q(1);
    }
    let verdict = if consistent {
        Verdict::Typo
    } else {
        Verdict::Discrepancy
    };
    let computed = "for n = 1…12, (A1) is (n+1)×(n+1) on x_0…x_n and its last row is Δⁿx_0: the vector has length n + 1, j = 0…n";
    Outcome::new(
        computed,
        "rational",
        verdict,
        "the forward-difference matrix of (A1) built for n = 1…12 and applied to the unit vector e_n; the text says the vector has \
         length n and j runs over 0…n−1 while it writes the elements x_0…x_n and (A1) up to Δⁿx_0",
    )
    .finding(
        ("a vector of length n, j = 0…n−1, with elements x_0…x_n", computed, "length and range are one short of the paper's own symbols"),
        crate::ledger::Severity::Minor,
        "the equations and (A1) use n + 1 entries consistently; only the prose is off by one",
    )
}

/// Sec. 4 on Fig. 2: "Both curves meet their associated constraints but only when connected to
/// the duration of the underlying parameter". Exact: each curve on its own duration, and its
/// control points used on the other curve's duration, against H = [0 0 0 | 1 1 0] (x, x′, x″
/// at both ends). Criterion, declared: each curve meets every condition on its own duration and
/// violates at least one on the other's.
pub fn duration_coupling(fast: &Bernstein<Q>, slow: &Bernstein<Q>) -> Outcome {
    let required = [[q(0), q(0), q(0)], [q(1), q(1), q(0)]];
    let violations = |curve: &Bernstein<Q>| -> usize {
        (0..3)
            .map(|j| {
                usize::from(curve.derivative_at_start(j) != required[0][j])
                    + usize::from(curve.derivative_at_end(j) != required[1][j])
            })
            .sum()
    };
    let moved = |curve: &Bernstein<Q>, t1: i64| {
        Bernstein::new(curve.control_points().to_vec(), (q(0), q(t1))).ok()
    };
    let (Some(fast_on_two), Some(slow_on_one)) = (moved(fast, 2), moved(slow, 1)) else {
        return Outcome::new(
            "",
            "rational",
            Verdict::Failed,
            "a curve could not be moved to the other duration",
        );
    };
    let own = (violations(fast), violations(slow));
    let swapped = (violations(&fast_on_two), violations(&slow_on_one));
    let end = |c: &Bernstein<Q>| {
        (0..3)
            .map(|j| c.derivative_at_end(j).to_string())
            .collect::<Vec<_>>()
            .join(", ")
    };
    Outcome::new(
        format!(
            "on its own duration each curve meets all 6 conditions ({} and {} violated); the duration-1 points on [0, 2] end with \
             (x, x′, x″) = ({}), the duration-2 points on [0, 1] with ({}): {} and {} conditions violated",
            own.0,
            own.1,
            end(&fast_on_two),
            end(&slow_on_one),
            swapped.0,
            swapped.1
        ),
        "rational",
        Verdict::holds(own == (0, 0) && swapped.0 > 0 && swapped.1 > 0),
        "the exact Fig. 2 curves (hermite.fig2.control_points.*), their end derivatives by Eqs. 14–15 (Bernstein::derivative_at_start/end) \
         on their own interval and with the control points kept and the interval exchanged",
    )
}

/// Sec. 3.1: "First, note the triangular structure of the problem … These equations can be
/// recursively solved". Exact, for m = 0…12 and T ∈ {1, 3/7, 5}: in the matrix of Eqs. 14–15
/// the start row j involves only p₀…p_j, with a non-zero coefficient on p_j, and the end row j
/// only p_{n−j}…p_n, non-zero on p_{n−j}; and the recursive solution (`HermiteData::solve`,
/// Eqs. 16–17) equals Gaussian elimination on the whole matrix, for random rational data.
pub fn triangular() -> Outcome {
    use crate::algo::hermite::{transform_matrix, TransformKind};
    let mut rng = super::super::sample::SplitMix64::new(31);
    let (mut cases, mut failures) = (0usize, Vec::new());
    for m in 0..=12usize {
        let n = 2 * m + 1;
        for t1 in [q(1), Q::new(3.into(), 7.into()), q(5)] {
            cases += 1;
            let a = transform_matrix(m, (&q(0), &t1), TransformKind::Transform);
            let zero = q(0);
            let shaped = (0..=m).all(|j| {
                (0..=n).all(|k| {
                    (k <= j || a[(j, k)] == zero) && (k >= n - j || a[(m + 1 + j, k)] == zero)
                }) && a[(j, j)] != zero
                    && a[(m + 1 + j, n - j)] != zero
            });
            let (start, end) = (rng.rationals(m + 1), rng.rationals(m + 1));
            let recursive = HermiteData::new(start.clone(), end.clone(), (q(0), t1.clone()))
                .and_then(|d| d.solve())
                .map(|c| c.control_points().to_vec())
                .ok();
            let rhs: Vec<Q> = start.into_iter().chain(end).collect();
            let eliminated = crate::numeric::linalg::solve(&a, &rhs).ok();
            if !shaped || recursive.is_none() || recursive != eliminated {
                failures.push(format!("m = {m}, T = {t1}"));
            }
        }
    }
    Outcome::new(
        format!(
            "{} of {cases} cases triangular with non-zero diagonal, and solved recursively (Eqs. 16–17) to the same control points as by elimination",
            cases - failures.len()
        ),
        "rational",
        Verdict::holds(failures.is_empty()),
        format!(
            "exact rationals; the matrix of Eqs. 14–15 for m = 0…12 on [0, T], T ∈ {{1, 3/7, 5}}: zero pattern and diagonal of both \
             blocks; random rational data solved by the recursion and by Gaussian elimination on the full matrix, compared exactly. \
             Failures: {failures:?}"
        ),
    )
}
