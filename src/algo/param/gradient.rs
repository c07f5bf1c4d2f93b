//! The gradient of G(h) (paper 004; the paper uses it in Eq. 30 but does not print it).
//!
//! For one component, G = rᵀM⁻¹r with r = Q(h)z and m = M⁻¹r the interior second derivatives
//! (m₀ = m_N = 0). Since ∂(rᵀM⁻¹r) = 2(∂r)ᵀm − mᵀ(∂M)m, and hₖ enters only
//! r_{k−1} (through −Δₖ/hₖ), r_k (through −Δₖ/hₖ in the opposite sign), M_{k−1,k−1}, M_{kk}
//! (each hₖ/3) and M_{k−1,k} = M_{k,k−1} (hₖ/6):
//!
//!   ∂G/∂hₖ = 2Δₖ(mₖ − mₖ₋₁)/hₖ² − (mₖ₋₁² + mₖ₋₁mₖ + mₖ²)/3,   Δₖ = zₖ − zₖ₋₁.
//!
//! For the approximate objective (Eq. 34) M is replaced by its diagonal M̂, so
//! m̂ᵢ = rᵢ/M̂ᵢᵢ and the off-diagonal term drops:
//!
//!   ∂G/∂hₖ = 2Δₖ(m̂ₖ − m̂ₖ₋₁)/hₖ² − (m̂ₖ₋₁² + m̂ₖ²)/3.
//!
//! Components are summed with weights α_l⁻². The claims check both formulas exactly against
//! dual-number differentiation of [`super::objective::objective`] in rationals, and against
//! central differences in MPFR.

use super::natural::{NaturalCubicSpline, SplineError};
use super::objective::{check_spacing, knots_from_spacing, Objective};
use crate::scalar::Field;

/// ∇G(h) for components `z[l]` with weights α_l.
///
/// # Errors
/// As [`super::objective::objective`] ([`check_spacing`]).
pub fn gradient<T: Field>(
    h: &[T],
    z: &[Vec<T>],
    alpha: &[T],
    form: Objective,
) -> Result<Vec<T>, SplineError> {
    let ctx = check_spacing(h, z, alpha)?;
    let n = h.len();
    let (two, three) = (T::from_i64(2, &ctx), T::from_i64(3, &ctx));
    let mut grad = vec![T::zero_in(&ctx); n];
    for (zl, al) in z.iter().zip(alpha) {
        crate::cancel::checkpoint();
        let m: Vec<T> = match form {
            Objective::Exact => NaturalCubicSpline::new(knots_from_spacing(h, &ctx), zl.clone())?
                .second_derivatives_at_knots()
                .to_vec(),
            Objective::Approximate => {
                let mut m = vec![T::zero_in(&ctx); n + 1];
                for i in 1..n {
                    let r = (zl[i + 1].clone() - &zl[i]) / &h[i]
                        - &((zl[i].clone() - &zl[i - 1]) / &h[i - 1]);
                    m[i] = r * &three / &(h[i - 1].clone() + &h[i]);
                }
                m
            }
        };
        let weight = T::one_in(&ctx) / &(al.clone() * al);
        for k in 1..=n {
            let hk = &h[k - 1];
            let delta = zl[k].clone() - &zl[k - 1];
            let (a, b) = (&m[k - 1], &m[k]);
            let first = two.clone() * &delta * &(b.clone() - a) / &(hk.clone() * hk);
            let quadratic = match form {
                Objective::Exact => a.clone() * a + &(a.clone() * b) + &(b.clone() * b),
                Objective::Approximate => a.clone() * a + &(b.clone() * b),
            };
            let term = first - &(quadratic / &three);
            grad[k - 1] += &(term * &weight);
        }
    }
    Ok(grad)
}

/// The projection π_B(y) = y − (y·n̂)n̂ onto the plane Σ xᵢ = 0 (Eq. 30); empty for an
/// empty `y`.
pub fn project<T: Field>(y: &[T]) -> Vec<T> {
    let Some(ctx) = y.first().map(Field::ctx) else {
        return Vec::new();
    };
    let mean =
        y.iter().fold(T::zero_in(&ctx), |acc, x| acc + x) / &T::from_i64(y.len() as i64, &ctx);
    y.iter().map(|x| x.clone() - &mean).collect()
}

#[cfg(test)]
mod tests {
    use super::super::objective::objective;
    use super::*;
    use crate::scalar::dual::Dual;
    use crate::scalar::BigRational;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    #[test]
    fn matches_central_differences_in_mpfr() {
        use crate::scalar::Float;
        let f = |v: f64| Float::with_val(256, v);
        let h: Vec<Float> = [0.2, 0.3, 0.1, 0.4].iter().map(|&v| f(v)).collect();
        let z = vec![[0.0, 1.0, -0.5, 2.0, 1.0]
            .iter()
            .map(|&v| f(v))
            .collect::<Vec<_>>()];
        let alpha = [f(1.0)];
        // Error budget of a central difference at 256 bits (ε ≈ 1.7e-77): rounding ε·|G|/(s·|G′|)
        // plus truncation s²·|G‴|/(6|G′|), smallest near s ≈ ε^(1/3) ≈ 1e-26, where both are far
        // below 1e-40. A wrong formula would differ at order one.
        let step = Float::with_val(256, 1e-26);
        for form in [Objective::Exact, Objective::Approximate] {
            let g = gradient(&h, &z, &alpha, form).unwrap();
            for (k, gk) in g.iter().enumerate() {
                let shifted = |s: &Float| -> Float {
                    let mut hk = h.clone();
                    hk[k] += s;
                    objective(&hk, &z, &alpha, form).unwrap()
                };
                let central = (shifted(&step) - shifted(&-step.clone())) / (step.clone() * 2u32);
                let rel = ((central - gk) / gk).abs();
                assert!(
                    rel < 1e-40,
                    "{form:?} k = {k}: relative difference {}",
                    rel.to_f64()
                );
            }
        }
    }

    #[test]
    fn matches_dual_number_derivative_exactly() {
        let h = vec![q(1, 5), q(3, 10), q(1, 10), q(2, 5)];
        let z = vec![
            vec![q(0, 1), q(1, 1), q(-1, 2), q(2, 1), q(1, 1)],
            vec![q(1, 1), q(0, 1), q(1, 3), q(1, 1), q(-1, 1)],
        ];
        let alpha = vec![q(1, 1), q(2, 1)];
        for form in [Objective::Exact, Objective::Approximate] {
            let g = gradient(&h, &z, &alpha, form).unwrap();
            for (k, gk) in g.iter().enumerate() {
                let hd = Dual::seeded(&h, k);
                let zd: Vec<Vec<Dual<BigRational>>> = z
                    .iter()
                    .map(|c| c.iter().cloned().map(Dual::constant).collect())
                    .collect();
                let ad: Vec<Dual<BigRational>> =
                    alpha.iter().cloned().map(Dual::constant).collect();
                let value = objective(&hd, &zd, &ad, form).unwrap();
                assert_eq!(&value.du, gk, "{form:?}, k = {k}");
            }
        }
    }
}
