//! The exact minimizing parametrization of scalar data (paper 004, Sec. 2).
//!
//! For ordinates z₀…z_N with Δᵢ = zᵢ − zᵢ₋₁ ≠ 0 (Eq. 6):
//! - case I, strictly monotone data: normalized accumulated |Δ| (Eq. 7); θ is linear, G = 0;
//! - case II, alternating data: hᵢ = εᵢ√|Δᵢ| / Σⱼ εⱼ√|Δⱼ| with ε₁ = ε_N = 1, εᵢ = √2 otherwise
//!   (Eq. 9), the unique spacing with θ′ = 0 at every interior knot (Eq. 8);
//! - case III, mixed: keep the endpoints and the interior extremes (Eq. 13), parametrize those
//!   by case II (Eq. 14), interpolate them by the natural spline ψ (Eq. 15), and place each
//!   remaining zⱼ at the unique solution of ψ(t) = zⱼ on its monotone stretch (Eqs. 16–17),
//!   found here by bisection to the working precision.
//!
//! Case I is exact in rationals; cases II and III need square roots ([`Real`]).

use super::natural::NaturalCubicSpline;
use crate::scalar::{Field, Real};

/// The three cases of Sec. 2.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Case {
    /// Monotone data: every difference has the same sign.
    I,
    /// Alternating data: consecutive differences change sign at every point.
    II,
    /// Mixed data: some consecutive differences change sign, some do not.
    III,
}

impl Case {
    /// The case as the paper writes it: "I", "II" or "III".
    pub fn name(self) -> &'static str {
        match self {
            Case::I => "I",
            Case::II => "II",
            Case::III => "III",
        }
    }
}

/// Why the data have no minimizing parametrization.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ParamError {
    /// Fewer than two points.
    #[error("need at least two points")]
    TooFewPoints,
    /// Two consecutive equal points.
    #[error("points #{index} and #{} are equal: the paper's existence assumption needs z_i ≠ z_(i+1)", index + 1)]
    RepeatedPoint {
        /// Index of the first of the two equal points.
        index: usize,
    },
}

fn deltas<T: Field>(z: &[T]) -> Result<Vec<T>, ParamError> {
    if z.len() < 2 {
        return Err(ParamError::TooFewPoints);
    }
    let d: Vec<T> = z.windows(2).map(|w| w[1].clone() - &w[0]).collect();
    match d.iter().position(Field::is_zero) {
        Some(index) => Err(ParamError::RepeatedPoint { index }),
        None => Ok(d),
    }
}

fn positive<T: Field>(x: &T) -> bool {
    *x > T::zero_in(&x.ctx())
}

/// Which case the ordinates fall in.
pub fn classify<T: Field>(z: &[T]) -> Result<Case, ParamError> {
    let d = deltas(z)?;
    let same: Vec<bool> = d
        .windows(2)
        .map(|w| positive(&w[0]) == positive(&w[1]))
        .collect();
    Ok(if same.iter().all(|&s| s) {
        Case::I
    } else if same.iter().all(|&s| !s) {
        Case::II
    } else {
        Case::III
    })
}

/// Indices of the endpoints and interior relative extremes, 0 = i₀ < … < i_M = N (Eq. 13).
pub fn extreme_indices<T: Field>(z: &[T]) -> Result<Vec<usize>, ParamError> {
    let d = deltas(z)?;
    let mut idx = vec![0];
    idx.extend((1..d.len()).filter(|&i| positive(&d[i - 1]) != positive(&d[i])));
    idx.push(z.len() - 1);
    Ok(idx)
}

/// Case I (Eq. 7), exact in any field: tᵢ = Σ_{j≤i} |Δⱼ| / Σ |Δⱼ|.
pub fn chord_length_1d<T: Field>(z: &[T]) -> Result<Vec<T>, ParamError> {
    let d = deltas(z)?;
    let ctx = z[0].ctx();
    let total = d.iter().fold(T::zero_in(&ctx), |acc, x| acc + &x.abs());
    let mut t = vec![T::zero_in(&ctx)];
    let mut run = T::zero_in(&ctx);
    for x in &d {
        run += &x.abs();
        t.push(run.clone() / &total);
    }
    Ok(t)
}

/// Case II (Eq. 9) for alternating ordinates.
pub fn alternating<T: Real>(z: &[T]) -> Result<Vec<T>, ParamError> {
    let d = deltas(z)?;
    let ctx = z[0].ctx();
    let n = d.len();
    let root2 = T::from_i64(2, &ctx).sqrt();
    let w: Vec<T> = d
        .iter()
        .enumerate()
        .map(|(i, x)| {
            let r = x.abs().sqrt();
            if i == 0 || i == n - 1 {
                r
            } else {
                r * &root2
            }
        })
        .collect();
    let total = w.iter().fold(T::zero_in(&ctx), |acc, x| acc + x);
    let mut t = vec![T::zero_in(&ctx)];
    let mut run = T::zero_in(&ctx);
    for (i, x) in w.iter().enumerate() {
        run += x;
        // The last knot is exactly 1 (the running sum may differ from it by rounding).
        t.push(if i == n - 1 {
            T::one_in(&ctx)
        } else {
            run.clone() / &total
        });
    }
    Ok(t)
}

/// The minimizing parametrization of scalar ordinates and its case.
pub fn minimizing_parametrization<T: Real>(z: &[T]) -> Result<(Vec<T>, Case), ParamError> {
    let case = classify(z)?;
    let t = match case {
        Case::I => chord_length_1d(z)?,
        Case::II => alternating(z)?,
        Case::III => {
            let idx = extreme_indices(z)?;
            let edited: Vec<T> = idx.iter().map(|&i| z[i].clone()).collect();
            let t_hat = alternating(&edited)?;
            // The edited data alternate, so ψ is monotone between consecutive extremes (Eq. 8).
            let psi = NaturalCubicSpline::new(t_hat.clone(), edited)
                .map_err(|_| ParamError::TooFewPoints)?;
            let ctx = z[0].ctx();
            let mut t = vec![T::zero_in(&ctx); z.len()];
            for (k, &i) in idx.iter().enumerate() {
                t[i] = t_hat[k].clone();
            }
            for k in 1..idx.len() {
                for j in idx[k - 1] + 1..idx[k] {
                    t[j] = solve_monotone(&psi, &t_hat[k - 1], &t_hat[k], &z[j]);
                }
            }
            t
        }
    };
    Ok((t, case))
}

/// The t in [a, b] with ψ(t) = target, ψ strictly monotone on [a, b] and the target strictly
/// between ψ(a) and ψ(b); bisection until the bracket is as small as the precision allows.
fn solve_monotone<T: Real>(psi: &NaturalCubicSpline<T>, a: &T, b: &T, target: &T) -> T {
    let ctx = a.ctx();
    let two = T::from_i64(2, &ctx);
    let increasing = psi.eval_all(b)[0] > psi.eval_all(a)[0];
    let (mut lo, mut hi) = (a.clone(), b.clone());
    let limit = T::epsilon(&ctx) * &(b.clone() - a);
    for _ in 0..(4 * T::precision_bits(&ctx) + 64) {
        if hi.clone() - &lo <= limit {
            break;
        }
        let mid = (lo.clone() + &hi) / &two;
        let below = psi.eval_all(&mid)[0] < *target;
        if below == increasing {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    (lo + &hi) / &two
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::{BigRational, Float};

    #[test]
    fn cases() {
        let z = |v: &[i64]| {
            v.iter()
                .map(|&x| BigRational::from_integer(x.into()))
                .collect::<Vec<_>>()
        };
        assert_eq!(classify(&z(&[0, 1, 3, 4])), Ok(Case::I));
        assert_eq!(classify(&z(&[0, 2, 1, 3])), Ok(Case::II));
        assert_eq!(classify(&z(&[0, 1, 3, 2])), Ok(Case::III));
        assert_eq!(
            classify(&z(&[0, 1, 1])),
            Err(ParamError::RepeatedPoint { index: 1 })
        );
        assert_eq!(
            chord_length_1d(&z(&[0, 1, 3, 4])).unwrap(),
            vec![
                BigRational::from_integer(0.into()),
                BigRational::new(1.into(), 4.into()),
                BigRational::new(3.into(), 4.into()),
                BigRational::from_integer(1.into())
            ]
        );
    }

    #[test]
    fn case_three_lands_on_psi() {
        let z: Vec<Float> = [0.0, 1.0, 3.0, 2.0, 2.5]
            .iter()
            .map(|&x| Float::with_val(128, x))
            .collect();
        let (t, case) = minimizing_parametrization(&z).unwrap();
        assert_eq!(case, Case::III);
        assert!(t.windows(2).all(|w| w[0] < w[1]));
        // The non-extreme point z₁ = 1 sits on ψ through the extremes 0, 3, 2, 2.5.
        let idx = extreme_indices(&z).unwrap();
        assert_eq!(idx, vec![0, 2, 3, 4]);
    }
}
