//! Claims about the B-spline basis (paper 002, Sec. 2–3): Table 1, Algorithm 1 against
//! Cox–de Boor, the properties stated after Eq. 2, and the geometric construction Eqs. 3–7.

use super::super::{Outcome, Verdict};
use crate::algo::bspline::CardinalBSpline;
use crate::numeric::linalg::{solve, Matrix};
use crate::numeric::poly::Poly;
use crate::scalar::{BigRational, Field};
use num_traits::{One, Signed};

type Q = BigRational;

fn q(n: i64, d: i64) -> Q {
    Q::new(n.into(), d.into())
}

/// Table 1 as printed: N_{j,k} for k = 0…3, as (numerator coefficients of s⁰, s¹, …; denominator).
pub const TABLE1_PRINTED: [(usize, usize, &str, &[i64], i64); 10] = [
    (0, 0, "1", &[1], 1),
    (1, 0, "(1-s)", &[1, -1], 1),
    (1, 1, "s", &[0, 1], 1),
    (2, 0, "(1-s)^2/2", &[1, -2, 1], 2),
    (2, 1, "(1+2s-2s^2)/2", &[1, 2, -2], 2),
    (2, 2, "s^2/2", &[0, 0, 1], 2),
    (3, 0, "(1-s)^3/3!", &[1, -3, 3, -1], 6),
    (3, 1, "(4-6s^2+3s^3)/3!", &[4, 0, -6, 3], 6),
    (3, 2, "(1+3s+3s^2-3s^3)/3!", &[1, 3, 3, -3], 6),
    (3, 3, "s^3/3!", &[0, 0, 0, 1], 6),
];

/// A polynomial in s printed with exact fraction coefficients, lowest power first, as a reader
/// writes it: "1 − s", "s^3/6", "2/3 − s^2 + s^3/2".
pub fn show(p: &Poly<Q>) -> String {
    if p.is_zero() {
        return "0".into();
    }
    let mut out = String::new();
    for (i, c) in p.coeffs().iter().enumerate() {
        if Field::is_zero(c) {
            continue;
        }
        let negative = c.is_negative();
        let (numer, denom) = (c.numer().abs(), c.denom().clone());
        let power = match i {
            0 => String::new(),
            1 => "s".into(),
            _ => format!("s^{i}"),
        };
        let factor = if power.is_empty() || !numer.is_one() {
            format!("{numer}{power}")
        } else {
            power
        };
        let term = if denom.is_one() {
            factor
        } else {
            format!("{factor}/{denom}")
        };
        out.push_str(match (out.is_empty(), negative) {
            (true, false) => "",
            (true, true) => "−",
            (false, false) => " + ",
            (false, true) => " − ",
        });
        out.push_str(&term);
    }
    out
}

/// One entry of Table 1: the printed polynomial beside Algorithm 1's.
pub struct Table1Row {
    pub k: usize,
    pub j: usize,
    pub printed: String,
    pub ours: String,
    pub equal: bool,
}

/// Each printed entry of Table 1 against Algorithm 1, exactly.
pub fn table1() -> (Vec<Table1Row>, Outcome) {
    let table = CardinalBSpline::<Q>::algorithm1_table(3, &());
    let rows: Vec<_> = TABLE1_PRINTED
        .iter()
        .map(|&(k, j, printed, num, den)| {
            let printed_poly = Poly::new(num.iter().map(|&c| q(c, den)).collect());
            let ours = &table[k][j];
            Table1Row {
                k,
                j,
                printed: printed.to_string(),
                ours: show(ours),
                equal: *ours == printed_poly,
            }
        })
        .collect();
    let bad = rows.iter().filter(|r| !r.equal).count();
    let outcome = Outcome::new(
        format!("{} of 10 entries equal", 10 - bad),
        "rational",
        if bad == 0 { Verdict::Reproduced } else { Verdict::Discrepancy },
        "every N_{j,k}, k = 0…3, computed by Algorithm 1 in exact rational polynomial arithmetic and compared \
         coefficient by coefficient with the printed entry",
    );
    (rows, outcome)
}

/// Algorithm 1 against the Cox–de Boor recursion for k = 0…8.
pub fn algorithm1_vs_de_boor() -> Outcome {
    let bad: Vec<usize> = (0..=8)
        .filter(|&k| {
            CardinalBSpline::<Q>::from_algorithm1(k, &())
                != CardinalBSpline::from_de_boor_cox(k, &())
        })
        .collect();
    Outcome::new(
        format!("identical for k = 0…8 ({} differ)", bad.len()),
        "rational",
        Verdict::holds(bad.is_empty()),
        format!("all k+1 pieces of B_k from Algorithm 1 with Eq. 1 compared exactly with the Cox–de Boor recursion on the knots 0…k+1; differing degrees: {bad:?}"),
    )
}

/// The properties after Eq. 2, k = 1…8: vanishing end derivatives, degree k, C^(k−1) (and not C^k).
pub fn properties() -> [Outcome; 3] {
    let (mut end_bad, mut smooth_bad, mut degree_bad, mut unity_bad) =
        (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for k in 1..=8usize {
        let b = CardinalBSpline::<Q>::from_algorithm1(k, &());
        for l in 0..k {
            let (_, at0) = b.one_sided_derivatives(0, l, &());
            let (at_end, _) = b.one_sided_derivatives(k + 1, l, &());
            if !Field::is_zero(&at0) || !Field::is_zero(&at_end) {
                end_bad.push((k, l));
            }
        }
        // C^(k−1) at every knot 0…k+1 (the outside is the zero polynomial), and a jump in the k-th derivative.
        for j in 0..=k + 1 {
            for l in 0..k {
                let (left, right) = b.one_sided_derivatives(j, l, &());
                if left != right {
                    smooth_bad.push((k, j, l));
                }
            }
            let (left, right) = b.one_sided_derivatives(j, k, &());
            if left == right {
                smooth_bad.push((k, j, k));
            }
        }
        if b.pieces().iter().any(|p| p.degree() != Some(k)) {
            degree_bad.push(k);
        }
        // Partition of unity: on [0, 1], Σᵢ B_k(s + i) = Σ_j piece_j(s) must be the constant 1.
        let sum = b.pieces().iter().fold(Poly::zero(), |acc, p| acc.add(p));
        if sum != Poly::constant(q(1, 1)) {
            unity_bad.push(k);
        }
    }
    [
        Outcome::new(
            format!("B_k^(l)(0) = B_k^(l)(k+1) = 0 for l < k, k = 1…8 ({} failures)", end_bad.len()),
            "rational",
            Verdict::holds(end_bad.is_empty()),
            format!("one-sided derivatives from inside the support, exact; failures (k, l): {end_bad:?}"),
        ),
        Outcome::new(
            format!("every piece of degree exactly k; C^(k−1) with a jump in the k-th derivative at every knot, k = 1…8 ({} failures)", smooth_bad.len() + degree_bad.len()),
            "rational",
            Verdict::holds(smooth_bad.is_empty() && degree_bad.is_empty()),
            format!(
                "left and right derivatives of orders 0…k compared exactly at the knots 0…k+1 (outside the support B_k is 0): \
                 equal up to k−1 and different at k; failures (k, knot, order): {smooth_bad:?}; pieces of other degree for k: {degree_bad:?}"
            ),
        ),
        Outcome::new(
            format!("Σ_i B_k(t − i) = 1 exactly for k = 1…8 ({} failures)", unity_bad.len()),
            "rational",
            Verdict::holds(unity_bad.is_empty()),
            "the sum of the k+1 pieces (each shifted to [0, 1]) is the constant polynomial 1, which is the partition of unity on every unit interval",
        ),
    ]
}

/// Eqs. 3–5 solved exactly (with a = 1 as the scale), and Eq. 6 against Algorithm 1, and Eq. 7.
pub fn geometric() -> [Outcome; 3] {
    // Unknowns (b, c, d) with a = 1: (3) b + 3a = c + 3d; (4) 2b + 2a = −2c − 2d; (5) 7a + b + c + 7d = 0.
    let a = Matrix::from_rows(vec![
        vec![q(1, 1), q(-1, 1), q(-3, 1)],
        vec![q(2, 1), q(2, 1), q(2, 1)],
        vec![q(1, 1), q(1, 1), q(7, 1)],
    ]);
    let rhs = vec![q(-3, 1), q(-2, 1), q(-7, 1)];
    let solved = solve(&a, &rhs).ok();
    let want = vec![q(-3, 1), q(3, 1), q(-1, 1)];
    let eqs = Outcome::new(
        match &solved {
            Some(s) => {
                let times_a = |c: &Q| match c.to_string().as_str() {
                    "1" => "a".to_string(),
                    "-1" => "-a".to_string(),
                    other => format!("{other}a"),
                };
                format!("b = {}, c = {}, d = {} (unique)", times_a(&s[0]), times_a(&s[1]), times_a(&s[2]))
            }
            None => "singular".into(),
        },
        "rational",
        if solved.as_ref() == Some(&want) { Verdict::Reproduced } else { Verdict::Discrepancy },
        "Eqs. 3–5 are linear and homogeneous in (a, b, c, d); with a = 1 the 3×3 system in (b, c, d) was solved by exact \
         Gaussian elimination (non-singular, so the solution is unique up to the scale a). The equations themselves \
         (b + 3a = c + 3d, 2b + 2a = −2c − 2d, B3(4) = (7a + b + c + 7d)/3) are re-derived from the ansatz in \
         bspline.sec3.derivation_steps",
    );
    // Eq. 6 as printed, each piece a polynomial in its printed variable u, then moved to the
    // local s = t − j of piece j: u = t on [0,1] (u = s), u = t − 1 on [1,2] (u = s),
    // u = t − 3 on [2,3] (u = s − 1), u = t − 4 on [3,4] (u = s − 1).
    let a_half = q(1, 2);
    let printed = |c: [Q; 4]| Poly::new(c.to_vec()).scale(&a_half);
    let pieces = [
        printed([q(0, 1), q(0, 1), q(0, 1), q(1, 3)]), // a·t³/3
        printed([q(1, 3), q(1, 1), q(1, 1), q(-1, 1)]), // a(1/3 − u³ + u² + u)
        printed([q(1, 3), q(-1, 1), q(1, 1), q(1, 1)]).shift(&q(-1, 1)), // a(1/3 + u³ + u² − u)
        printed([q(0, 1), q(0, 1), q(0, 1), q(-1, 3)]).shift(&q(-1, 1)), // −a·u³/3
    ];
    let half = a_half.clone();
    let alg1 = CardinalBSpline::<Q>::from_algorithm1(3, &());
    let same = pieces.iter().zip(alg1.pieces()).all(|(x, y)| x == y);
    let eq6_outcome = Outcome::new(
        if same { "equal to Algorithm 1's B_3 for a = 1/2".to_string() } else { "differs from Algorithm 1 for a = 1/2".into() },
        "rational",
        if same { Verdict::Reproduced } else { Verdict::Discrepancy },
        "a is fixed by the first piece (a/3·t³ = t³/6 gives a = 1/2); all four pieces of Eq. 6 then compared exactly with \
         Algorithm 1's, each written in s = t − j",
    );
    let third: Vec<Q> = alg1
        .derivative(3)
        .pieces()
        .iter()
        .map(|p| p.coeffs().first().cloned().unwrap_or_else(|| q(0, 1)))
        .collect();
    let want7: Vec<Q> = [2, -6, 6, -2].iter().map(|&c| q(c, 1) * &half).collect();
    let eq7 = Outcome::new(
        format!(
            "B3''' = ({}) on the four unit intervals, i.e. (2a, −6a, 6a, −2a) with a = 1/2",
            third
                .iter()
                .map(|x| x.to_string())
                .collect::<Vec<_>>()
                .join(", ")
        ),
        "rational",
        if third == want7 {
            Verdict::Reproduced
        } else {
            Verdict::Discrepancy
        },
        "third derivative of each exact piece of B_3 (constants), compared with Eq. 7 at a = 1/2",
    );
    [eqs, eq6_outcome, eq7]
}

/// The Bernstein coefficients on [0, 1] of the power-form polynomial with coefficients `a`
/// (degree n = a.len() − 1): b_j = Σ_{k≤j} C(j, k)/C(n, k) a_k.
fn bernstein_coefficients(a: &[Q]) -> Vec<Q> {
    let n = a.len().saturating_sub(1);
    let c = |n: usize, k: usize| Q::from_integer(crate::numeric::poly::binomial(n, k));
    (0..=n)
        .map(|j| (0..=j).fold(q(0, 1), |acc, k| acc + c(j, k) / c(n, k) * &a[k]))
        .collect()
}

/// Sec. 5: "B_3(t_j − i + 1) ≠ 0 if and only if i − 1 < t_j < i + 3", that is, B_k is positive
/// exactly on (0, k+1), proved for k = 1…8 from the pieces of Algorithm 1.
pub fn support() -> Outcome {
    let mut failures = Vec::new();
    for k in 1..=8usize {
        let b = CardinalBSpline::<Q>::from_algorithm1(k, &());
        if b.pieces().len() != k + 1 {
            failures.push(format!("k = {k}: {} pieces", b.pieces().len()));
        }
        for (j, piece) in b.pieces().iter().enumerate() {
            let coeffs = piece.coeffs_padded(k + 1, &());
            let bern = bernstein_coefficients(&coeffs);
            // Non-negative Bernstein coefficients, not all zero: positive on the open interval.
            if bern.iter().any(|x| *x < q(0, 1)) || bern.iter().all(Field::is_zero) {
                failures.push(format!(
                    "k = {k}, piece {j}: Bernstein coefficients {bern:?}"
                ));
            }
        }
        // Zero outside: at the ends of the support and beyond.
        for s in [
            q(-1, 2),
            q(0, 1),
            q(k as i64 + 1, 1),
            q(2 * k as i64 + 3, 2),
        ] {
            if !b.eval(&s).is_zero() {
                failures.push(format!("k = {k}: B({s}) ≠ 0"));
            }
        }
    }
    Outcome::new(
        format!("B_k > 0 exactly on (0, k+1) for k = 1…8, so B_3(t_j − i + 1) ≠ 0 iff i − 1 < t_j < i + 3 ({} failures)", failures.len()),
        "rational",
        Verdict::holds(failures.is_empty()),
        format!(
            "each of the k+1 polynomial pieces of Algorithm 1 written in Bernstein form on its unit interval, exactly: all coefficients \
             non-negative and not all zero, so the piece is positive inside the interval (a proof, not sampling); B evaluated exactly \
             at −1/2, 0, k+1 and (2k+3)/2 is zero. Failures: {failures:?}"
        ),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bernstein_coefficients_decide_positivity_only_when_they_can() {
        // s(1 − s): Bernstein coefficients 0, 1/2, 0, positive inside (0, 1).
        assert_eq!(
            bernstein_coefficients(&[q(0, 1), q(1, 1), q(-1, 1)]),
            vec![q(0, 1), q(1, 2), q(0, 1)]
        );
        // (s − 1/2)² vanishes at 1/2: a negative coefficient, so no positivity is claimed.
        let b = bernstein_coefficients(&[q(1, 4), q(-1, 1), q(1, 1)]);
        assert_eq!(b, vec![q(1, 4), q(-1, 4), q(1, 4)]);
    }
}
