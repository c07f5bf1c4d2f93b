//! The dual certificate of paper 002, Sec. 4.1: a proof that the bang-bang control solves
//! Problem 3 (minimum ‖u‖∞ subject to rest at t = 0 and t = 4 and x(2) = ξ).
//!
//! The constraints are ⟨yᵢ, u⟩ = cᵢ with y = (1, 4 − t, (4 − t)², (2 − t)₊²) and
//! c = (0, 0, 0, 2ξ) (the paper's inner-product form of ẍ(4) = ẋ(4) = x(4) = 0, x(2) = ξ).
//! Theorem 1 (Luenberger) pairs it with max c·a over ‖Ya‖_L1 ≤ 1, where
//! Ya(t) = a₁ + a₂(4 − t) + a₃(4 − t)² + a₄(2 − t)₊². Weak duality is Hölder's inequality:
//! for every feasible u and every a with ‖Ya‖₁ = 1,
//!
//! ‖u‖∞ = ‖u‖∞·‖Ya‖₁ ≥ ⟨Ya, u⟩ = Σ aᵢ⟨yᵢ, u⟩ = c·a,
//!
//! so an a with c·a equal to the U of a feasible control proves that control optimal.
//!
//! [`certificate`] builds that a from the switching times: Ya must vanish where u* switches,
//! Ya(tᵢ) = 0 for i = 1, 2, 3 — three homogeneous linear equations, solved with a₄ = 1 and
//! then scaled to ‖Ya‖₁ = 1. Ya is a quadratic on [0, 2] and on [2, 4]; on each piece one
//! known root and Vieta's formula give the other, so the code knows every root of Ya and
//! checks that none lies strictly inside the four intervals (0, t₁), (t₁, t₂), (t₂, t₃),
//! (t₃, 4). The sign of Ya on each interval (at its midpoint) and the exact L1 norm (integrals
//! of the polynomial pieces) follow. Generic over [`Field`]: exact in Q(√2) for the paper's
//! data.

use crate::numeric::linalg::{solve, Matrix};
use crate::numeric::poly::Poly;
use crate::scalar::Field;
use std::cmp::Ordering;

/// A normalised dual solution and what it proves.
#[derive(Clone, Debug, PartialEq)]
pub struct DualCertificate<T> {
    /// a = (a₁, a₂, a₃, a₄), scaled so that ‖Ya‖_L1 = 1.
    pub weights: [T; 4],
    /// The dual objective c·a = 2ξ·a₄: a lower bound on ‖u‖∞ for every feasible u.
    pub value: T,
    /// The sign of Ya on (0, t₁), (t₁, t₂), (t₂, t₃), (t₃, 4).
    pub signs: [Ordering; 4],
    /// The L1 norm of Ya before scaling (with a₄ = 1).
    pub unscaled_l1_norm: T,
}

/// Why no certificate could be built from these switching times.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum CertificateError {
    /// Ya(tᵢ) = 0 with a₄ = 1 has no unique solution.
    #[error("the interpolation conditions Ya(t_i) = 0 are singular")]
    Singular,
    /// Ya has a root strictly inside one of the four intervals, so it cannot match a
    /// control with exactly these switches.
    #[error("Ya changes sign inside an interval between switches")]
    ExtraRoot,
    /// Ya vanishes identically on one of its two pieces.
    #[error("Ya vanishes on a whole piece")]
    Degenerate,
}

/// The four constraint functions yᵢ(t) on [0, 2] (first) and on [2, 4] (second), as
/// polynomials in t.
fn constraint_pieces<T: Field>(ctx: &T::Ctx) -> [[Poly<T>; 4]; 2] {
    let i = |v: i64| T::from_i64(v, ctx);
    let four_minus_t = Poly::linear(i(4), i(-1));
    let two_minus_t = Poly::linear(i(2), i(-1));
    let one = Poly::constant(i(1));
    let square = four_minus_t.mul(&four_minus_t);
    [
        [
            one.clone(),
            four_minus_t.clone(),
            square.clone(),
            two_minus_t.mul(&two_minus_t),
        ],
        [one, four_minus_t, square, Poly::zero()],
    ]
}

/// Ya on [0, 2] and on [2, 4] as polynomials in t.
pub fn dual_function<T: Field>(a: &[T; 4], ctx: &T::Ctx) -> [Poly<T>; 2] {
    constraint_pieces::<T>(ctx).map(|ys| {
        ys.iter()
            .zip(a)
            .fold(Poly::zero(), |acc, (y, ai)| acc.add(&y.scale(ai)))
    })
}

/// The roots of a polynomial of degree ≤ 2 of which `known` is one (Vieta: r₁ + r₂ = −b/a).
fn roots_given_one<T: Field>(q: &Poly<T>, known: &T) -> Result<Vec<T>, CertificateError> {
    match q.degree() {
        None => Err(CertificateError::Degenerate),
        Some(2) => {
            let c = q.coeffs();
            Ok(vec![known.clone(), -(c[1].clone() / &c[2]) - known])
        }
        _ => Ok(vec![known.clone()]),
    }
}

/// The dual certificate for the bang-bang control with these switching times and x(2) = ξ.
///
/// # Errors
/// [`CertificateError::Singular`] when the conditions Ya(tᵢ) = 0 have no unique solution;
/// [`CertificateError::ExtraRoot`] when a piece of Ya holds no switching time or changes
/// sign between switches; [`CertificateError::Degenerate`] when Ya vanishes on a piece.
pub fn certificate<T: Field>(
    switches: &[T; 3],
    xi: &T,
) -> Result<DualCertificate<T>, CertificateError> {
    let ctx = xi.ctx();
    let i = |v: i64| T::from_i64(v, &ctx);
    let two = i(2);
    // Ya(tᵢ) = 0 with a₄ = 1: a₁ + a₂(4 − tᵢ) + a₃(4 − tᵢ)² = −(2 − tᵢ)₊².
    let y = |t: &T| -> [T; 4] {
        let piece = usize::from(*t >= two);
        constraint_pieces::<T>(&ctx)[piece]
            .each_ref()
            .map(|p| p.eval(t))
    };
    let rows: Vec<[T; 4]> = switches.iter().map(y).collect();
    let m = Matrix::from_rows(rows.iter().map(|r| r[..3].to_vec()).collect());
    let rhs: Vec<T> = rows.iter().map(|r| -r[3].clone()).collect();
    let s = solve(&m, &rhs).map_err(|_| CertificateError::Singular)?;
    let a = [s[0].clone(), s[1].clone(), s[2].clone(), i(1)];
    let pieces = dual_function(&a, &ctx);
    // Every root of each piece, from one switching time on it.
    let ends = [[i(0), two.clone()], [two.clone(), i(4)]];
    let mut roots = Vec::new();
    for (q, [lo, hi]) in pieces.iter().zip(&ends) {
        let known = switches.iter().find(|t| *t >= lo && *t <= hi);
        let Some(known) = known else {
            return Err(CertificateError::ExtraRoot);
        };
        roots.extend(
            roots_given_one(q, known)?
                .into_iter()
                .filter(|r| r > lo && r < hi),
        );
    }
    let bounds = [
        i(0),
        switches[0].clone(),
        switches[1].clone(),
        switches[2].clone(),
        i(4),
    ];
    let strictly_inside = |r: &T, k: usize| *r > bounds[k] && *r < bounds[k + 1];
    if roots.iter().any(|r| (0..4).any(|k| strictly_inside(r, k))) {
        return Err(CertificateError::ExtraRoot);
    }
    let eval = |t: &T| pieces[usize::from(*t >= two)].eval(t);
    let mut signs = [Ordering::Equal; 4];
    let mut norm = i(0);
    for k in 0..4 {
        let mid = (bounds[k].clone() + &bounds[k + 1]) / &two;
        signs[k] = eval(&mid).partial_cmp(&i(0)).unwrap_or(Ordering::Equal);
        // ∫ over the interval, split at the breakpoint t = 2 of Ya.
        let mut cuts = vec![bounds[k].clone()];
        if bounds[k] < two && two < bounds[k + 1] {
            cuts.push(two.clone());
        }
        cuts.push(bounds[k + 1].clone());
        let integral = cuts.windows(2).fold(i(0), |acc, w| {
            let piece = usize::from(w[0] >= two);
            acc + &pieces[piece].integrate((&w[0], &w[1]))
        });
        norm += &match signs[k] {
            Ordering::Less => -integral,
            _ => integral,
        };
    }
    let weights = a.map(|ai| ai / &norm);
    let value = two * xi * &weights[3];
    Ok(DualCertificate {
        weights,
        value,
        signs,
        unscaled_l1_norm: norm,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algo::bspline::bang_bang::amplitude;
    use crate::scalar::qsqrt2::QSqrt2;

    fn paper_switches() -> [QSqrt2; 3] {
        let i = |v: i64| QSqrt2::from_i64(v, &());
        [i(2) - &QSqrt2::sqrt2(), i(2), i(2) + &QSqrt2::sqrt2()]
    }

    #[test]
    fn the_paper_solution_is_certified_optimal() {
        let t = paper_switches();
        let xi = QSqrt2::from_ratio(2, 3, &());
        let c = certificate(&t, &xi).unwrap();
        assert_eq!(c.value, amplitude(&t, &xi));
        use Ordering::{Greater, Less};
        assert_eq!(c.signs, [Greater, Less, Greater, Less]);
    }

    #[test]
    fn other_switches_give_strictly_weaker_lower_bounds() {
        // Weak duality holds for every a, so a certificate built on other switches still
        // bounds the optimum from below — strictly, since only the optimal switches align
        // Ya with a feasible control.
        let i = |v: i64| QSqrt2::from_i64(v, &());
        let xi = QSqrt2::from_ratio(2, 3, &());
        let optimum = amplitude(&paper_switches(), &xi);
        let others = [
            [i(1), i(2), i(3)],
            [
                QSqrt2::from_ratio(1, 2, &()),
                i(2),
                QSqrt2::from_ratio(7, 2, &()),
            ],
        ];
        for t in others {
            let c = certificate(&t, &xi).unwrap();
            assert!(
                c.value < optimum && c.value > i(0),
                "{:?}",
                c.value.to_f64()
            );
            let ya = dual_function(&c.weights, &());
            assert!(t
                .iter()
                .all(|s| ya[usize::from(*s >= i(2))].eval(s).is_zero()));
        }
    }
}
