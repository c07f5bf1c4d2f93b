//! The minimum-L∞ control of paper 002, Sec. 4: drive d³x/dt³ = u from rest at t = 0 to rest
//! at t = 4 through x(2) = ξ with the smallest sup |u|.
//!
//! By duality (Sec. 4.1, Luenberger's theorem) the optimum is bang-bang with three switches:
//! u = U on [0, t₁), −U on [t₁, t₂), U on [t₂, t₃), −U on [t₃, 4] (Eq. 8). Written as steps,
//! u(t) = U·Σₖ cₖ·H(t − sₖ) with (s, c) = ((0, t₁, t₂, t₃), (1, −2, 2, −2)), so
//! ẍ(t) = U Σ cₖ(t−sₖ)₊, ẋ(t) = U Σ cₖ(t−sₖ)₊²/2, x(t) = U Σ cₖ(t−sₖ)₊³/6 ([`response`]).
//! The three terminal conditions do not involve U, so the switching times do not depend on ξ:
//! [`switching_times`] solves them by Newton's method from the B-spline's knots (1, 2, 3), and
//! U = ξ / x₁(2), x₁ the response to U = 1 ([`amplitude`]). The paper's solution
//! t = (2−√2, 2, 2+√2), U = (2+√2)/2 for ξ = 2/3 is checked exactly in Q(√2) by the claims.

use crate::numeric::linalg::{solve, Matrix};
use crate::scalar::qsqrt2::QSqrt2;
use crate::scalar::{BigRational, Field, Real};

/// The final time of the problem.
pub const FINAL_TIME: i64 = 4;
/// The sign changes of the control as steps: u = U Σ cₖ H(t − sₖ).
const STEP_WEIGHTS: [i64; 4] = [1, -2, 2, -2];

/// (x, ẋ, ẍ) at t of the bang-bang response with switches t₁ ≤ t₂ ≤ t₃ and amplitude U.
pub fn response<T: Field>(switches: &[T; 3], amplitude: &T, t: &T) -> [T; 3] {
    let ctx = t.ctx();
    let zero = T::zero_in(&ctx);
    let starts = [
        zero.clone(),
        switches[0].clone(),
        switches[1].clone(),
        switches[2].clone(),
    ];
    let (mut x, mut v, mut a) = (zero.clone(), zero.clone(), zero.clone());
    for (s, &c) in starts.iter().zip(&STEP_WEIGHTS) {
        if *t > *s {
            let h = t.clone() - s;
            let c = T::from_i64(c, &ctx);
            let h2 = h.clone() * &h;
            a += &(c.clone() * &h);
            v += &(c.clone() * &h2 / &T::from_i64(2, &ctx));
            x += &(c * &h2 * &h / &T::from_i64(6, &ctx));
        }
    }
    [x * amplitude, v * amplitude, a * amplitude]
}

/// The terminal residuals (ẍ(4), ẋ(4), x(4)) of the unit-amplitude response.
pub fn terminal_residuals<T: Field>(switches: &[T; 3]) -> [T; 3] {
    let ctx = switches[0].ctx();
    let [x, v, a] = response(switches, &T::one_in(&ctx), &T::from_i64(FINAL_TIME, &ctx));
    [a, v, x]
}

/// Newton's method did not converge, or left the ordered region 0 < t₁ < t₂ < t₃ < 4.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("Newton's method for the switching times did not converge")]
pub struct NoSolution;

/// The switching times (t₁, t₂, t₃) solving ẍ(4) = ẋ(4) = x(4) = 0, to the working precision.
///
/// # Errors
/// [`NoSolution`] when a Newton step's Jacobian is singular, when 200 steps do not bring the
/// largest step to 64ε, or when the converged times are not ordered 0 < t₁ < t₂ < t₃ < 4.
///
/// # Examples
/// ```
/// use trajverify::algo::bspline::bang_bang::{switching_times, terminal_residuals};
/// let t: [f64; 3] = switching_times(&()).unwrap();
/// assert!(0.0 < t[0] && t[0] < t[1] && t[1] < t[2] && t[2] < 4.0);
/// assert!(terminal_residuals(&t).iter().all(|r| r.abs() < 1e-12));
/// ```
pub fn switching_times<T: Real>(ctx: &T::Ctx) -> Result<[T; 3], NoSolution> {
    let i = |v: i64| T::from_i64(v, ctx);
    let mut t = [i(1), i(2), i(3)];
    let tolerance = T::epsilon(ctx) * &i(64);
    for _ in 0..200 {
        let f = terminal_residuals(&t);
        // ∂/∂sₖ of (Σ c(4−s), Σ c(4−s)²/2, Σ c(4−s)³/6) is −c·(1, (4−s), (4−s)²/2).
        let jacobian = Matrix::from_fn(3, 3, |row, col| {
            let r = i(FINAL_TIME) - &t[col];
            let c = i(-STEP_WEIGHTS[col + 1]);
            match row {
                0 => c,
                1 => c * &r,
                _ => c * &r * &r / &i(2),
            }
        });
        let step = solve(&jacobian, &f).map_err(|_| NoSolution)?;
        let mut size = T::zero_in(ctx);
        for (tk, dk) in t.iter_mut().zip(&step) {
            *tk -= dk;
            size = crate::scalar::max_of(size, dk.abs());
        }
        if size <= tolerance {
            let ordered = i(0) < t[0] && t[0] < t[1] && t[1] < t[2] && t[2] < i(FINAL_TIME);
            return if ordered { Ok(t) } else { Err(NoSolution) };
        }
    }
    Err(NoSolution)
}

/// The switching times exactly, by elimination. With r = 4 − t, the terminal conditions read
/// r1 − r2 + r3 = 2, r1² − r2² + r3² = 8, r1³ − r2³ + r3³ = 32 (Sec. 4.1). Put p = r1 + r3,
/// q = r1·r3: the first gives r2 = p − 2, the second q = 2p − 6, and the third then reduces to
/// 6p + 8 = 32. So p = 4, q = 2, and r1, r3 = (p ± √(p² − 4q))/2; the discriminant p² − 4q = 8
/// is 2·2², so its root 2√2 lies in Q(√2). Returns `None` if the discriminant were not of the
/// form 2·(rational square), or if the result failed the exact check of the terminal state.
pub fn exact_switching_times() -> Option<[QSqrt2; 3]> {
    let q = |n: i64| BigRational::from_integer(n.into());
    let p = (q(32) - q(8)) / q(6);
    let prod = q(2) * &p - q(6);
    let disc = p.clone() * &p - q(4) * &prod;
    // √disc = s·√2 with s² = disc/2, s a rational square root.
    let half = disc / q(2);
    let s = rational_sqrt(&half)?;
    let root = QSqrt2::new(q(0), s);
    let two = QSqrt2::from_i64(2, &());
    let pp = QSqrt2::from_rational(&p, &());
    let (r1, r3) = ((pp.clone() + &root) / &two, (pp.clone() - &root) / &two);
    let r2 = pp - &two;
    let four = QSqrt2::from_i64(FINAL_TIME, &());
    let t = [four.clone() - &r1, four.clone() - &r2, four - &r3];
    terminal_residuals(&t)
        .iter()
        .all(Field::is_zero)
        .then_some(t)
}

/// The exact square root of a non-negative rational that is a square of a rational.
fn rational_sqrt(x: &BigRational) -> Option<BigRational> {
    if *x < BigRational::from_integer(0.into()) {
        return None;
    }
    let (n, d) = (x.numer().sqrt(), x.denom().sqrt());
    let r = BigRational::new(n, d);
    (r.clone() * &r == *x).then_some(r)
}

/// The amplitude U with x(2) = ξ for these switching times.
pub fn amplitude<T: Field>(switches: &[T; 3], xi: &T) -> T {
    let ctx = xi.ctx();
    let [x2, _, _] = response(switches, &T::one_in(&ctx), &T::from_i64(2, &ctx));
    xi.clone() / &x2
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::qsqrt2::QSqrt2;
    use crate::scalar::Float;

    #[test]
    fn paper_solution_is_exact_in_q_sqrt2() {
        let r2 = QSqrt2::sqrt2();
        let i = |v: i64| QSqrt2::from_i64(v, &());
        let t = [i(2) - &r2, i(2), i(2) + &r2];
        assert!(terminal_residuals(&t).iter().all(Field::is_zero));
        let u = amplitude(&t, &QSqrt2::from_ratio(2, 3, &()));
        assert_eq!(u, (i(2) + &r2) / &i(2));
    }

    #[test]
    fn elimination_gives_the_exact_times() {
        let r2 = QSqrt2::sqrt2();
        let i = |v: i64| QSqrt2::from_i64(v, &());
        assert_eq!(
            exact_switching_times(),
            Some([i(2) - &r2, i(2), i(2) + &r2])
        );
    }

    #[test]
    fn newton_finds_it_in_mpfr() {
        let t = switching_times::<Float>(&200).unwrap();
        let r2 = Float::with_val(200, 2).sqrt();
        assert!((t[0].clone() - (Float::with_val(200, 2) - &r2)).abs() < 1e-55);
        assert!((t[1].clone() - 2u32).abs() < 1e-55);
    }
}
