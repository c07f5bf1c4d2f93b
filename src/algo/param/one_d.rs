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
use crate::scalar::{BigRational, Field, Real};

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

/// The discrete shape of the ordinates, which selects the case and the points of Eq. 13:
/// the sign of every difference Δᵢ, decided exactly.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Shape {
    /// Whether each Δᵢ = zᵢ − zᵢ₋₁ is positive (i = 1 … N).
    pub rising: Vec<bool>,
}

impl Shape {
    /// The shape of rational ordinates (an error for fewer than two points or a repeat).
    ///
    /// # Errors
    /// [`ParamError::TooFewPoints`] for fewer than two ordinates; [`ParamError::RepeatedPoint`]
    /// for the first two consecutive equal ones.
    pub fn of_exact<E: Field<Ctx = ()>>(z: &[E]) -> Result<Shape, ParamError> {
        let zero = E::zero_in(&());
        Ok(Shape {
            rising: deltas(z)?.iter().map(|d| *d > zero).collect(),
        })
    }

    /// The shape of the ordinates as given, decided exactly in rationals (every f64 and
    /// MPFR number is one), so no rounding of a difference can flip a sign. For ordinates
    /// that were themselves rounded from exact input, decide on that input
    /// ([`Shape::of_exact`]) and use [`parametrization_with_shape`].
    ///
    /// # Errors
    /// As [`Shape::of_exact`].
    pub fn of<T: Field>(z: &[T]) -> Result<Shape, ParamError> {
        let exact: Option<Vec<BigRational>> = z.iter().map(Field::to_rational).collect();
        match exact {
            Some(q) => Shape::of_exact(&q),
            // Not finite: the sign of a difference is the value's own.
            None => Ok(Shape {
                rising: deltas(z)?.iter().map(positive).collect(),
            }),
        }
    }

    /// Which case the shape is.
    pub fn case(&self) -> Case {
        let same: Vec<bool> = self.rising.windows(2).map(|w| w[0] == w[1]).collect();
        if same.iter().all(|&s| s) {
            Case::I
        } else if same.iter().all(|&s| !s) {
            Case::II
        } else {
            Case::III
        }
    }

    /// Indices of the endpoints and interior relative extremes, 0 = i₀ < … < i_M = N
    /// (Eq. 13).
    pub fn extremes(&self) -> Vec<usize> {
        let mut idx = vec![0];
        idx.extend((1..self.rising.len()).filter(|&i| self.rising[i - 1] != self.rising[i]));
        idx.push(self.rising.len());
        idx
    }
}

fn positive<T: Field>(x: &T) -> bool {
    *x > T::zero_in(&x.ctx())
}

/// Which case the ordinates fall in (decided exactly, [`Shape::of`]).
///
/// # Errors
/// As [`Shape::of`].
pub fn classify<T: Field>(z: &[T]) -> Result<Case, ParamError> {
    Ok(Shape::of(z)?.case())
}

/// Indices of the endpoints and interior relative extremes, 0 = i₀ < … < i_M = N (Eq. 13),
/// decided exactly ([`Shape::of`]).
///
/// # Errors
/// As [`Shape::of`].
pub fn extreme_indices<T: Field>(z: &[T]) -> Result<Vec<usize>, ParamError> {
    Ok(Shape::of(z)?.extremes())
}

/// |Δᵢ| with the sign of Δᵢ known: no comparison of the (possibly rounded) difference.
fn magnitudes<T: Field>(z: &[T], rising: &[bool]) -> Vec<T> {
    z.windows(2)
        .zip(rising)
        .map(|(w, &up)| {
            if up {
                w[1].clone() - &w[0]
            } else {
                w[0].clone() - &w[1]
            }
        })
        .collect()
}

/// Case I (Eq. 7), exact in any field: tᵢ = Σ_{j≤i} |Δⱼ| / Σ |Δⱼ|.
///
/// # Errors
/// As [`Shape::of`].
pub fn chord_length_1d<T: Field>(z: &[T]) -> Result<Vec<T>, ParamError> {
    let shape = Shape::of(z)?;
    Ok(chord_length_with(z, &shape.rising))
}

fn chord_length_with<T: Field>(z: &[T], rising: &[bool]) -> Vec<T> {
    chord_length_from(&magnitudes(z, rising), &z[0].ctx())
}

/// Eq. 7 from the magnitudes |Δᵢ|.
fn chord_length_from<T: Field>(d: &[T], ctx: &T::Ctx) -> Vec<T> {
    let total = d.iter().fold(T::zero_in(ctx), |acc, x| acc + x);
    let mut t = vec![T::zero_in(ctx)];
    let mut run = T::zero_in(ctx);
    for (i, x) in d.iter().enumerate() {
        run += x;
        // The last knot is exactly 1.
        t.push(if i + 1 == d.len() {
            T::one_in(ctx)
        } else {
            run.clone() / &total
        });
    }
    t
}

/// Case II (Eq. 9) for alternating ordinates.
///
/// # Errors
/// As [`Shape::of`].
pub fn alternating<T: Real>(z: &[T]) -> Result<Vec<T>, ParamError> {
    let shape = Shape::of(z)?;
    Ok(alternating_with(z, &shape.rising))
}

fn alternating_with<T: Real>(z: &[T], rising: &[bool]) -> Vec<T> {
    alternating_from(&magnitudes(z, rising), &z[0].ctx())
}

/// Eq. 9 from the magnitudes |Δᵢ|.
fn alternating_from<T: Real>(d: &[T], ctx: &T::Ctx) -> Vec<T> {
    let n = d.len();
    let root2 = T::from_i64(2, ctx).sqrt();
    let w: Vec<T> = d
        .iter()
        .enumerate()
        .map(|(i, x)| {
            let r = x.sqrt();
            if i == 0 || i == n - 1 {
                r
            } else {
                r * &root2
            }
        })
        .collect();
    let total = w.iter().fold(T::zero_in(ctx), |acc, x| acc + x);
    let mut t = vec![T::zero_in(ctx)];
    let mut run = T::zero_in(ctx);
    for (i, x) in w.iter().enumerate() {
        run += x;
        // The last knot is exactly 1 (the running sum may differ from it by rounding).
        t.push(if i == n - 1 {
            T::one_in(ctx)
        } else {
            run.clone() / &total
        });
    }
    t
}

/// The minimizing parametrization of scalar ordinates and its case, the shape decided
/// exactly on the ordinates as given ([`Shape::of`]).
///
/// # Errors
/// As [`Shape::of`].
pub fn minimizing_parametrization<T: Real>(z: &[T]) -> Result<(Vec<T>, Case), ParamError> {
    let shape = Shape::of(z)?;
    parametrization_with_shape(z, &shape)
}

/// The minimizing parametrization with the shape (case, extremes) decided by the caller on
/// the exact ordinates: every discrete choice comes from `shape`, none from comparing the
/// values of `z`, so ordinates rounded from exact input take the exact input's case.
///
/// # Errors
/// [`ParamError::TooFewPoints`] for fewer than two ordinates or a `shape` without one entry
/// per difference. Repeated points are not detected here (the shape is trusted).
pub fn parametrization_with_shape<T: Real>(
    z: &[T],
    shape: &Shape,
) -> Result<(Vec<T>, Case), ParamError> {
    if z.len() < 2 || shape.rising.len() + 1 != z.len() {
        return Err(ParamError::TooFewPoints);
    }
    parametrization_exact(z, &magnitudes(z, &shape.rising), shape)
}

/// [`parametrization_with_shape`] with the magnitudes |Δᵢ| given by the caller as well:
/// formed exactly from exact ordinates and rounded once, a difference of 1e-40 between
/// values near 1 keeps its relative accuracy (the difference of the rounded ordinates
/// would be 0).
///
/// # Errors
/// [`ParamError::TooFewPoints`] for fewer than two ordinates, or a `shape` or `magnitudes`
/// without one entry per difference. Repeated points are not detected here.
pub fn parametrization_exact<T: Real>(
    z: &[T],
    magnitudes: &[T],
    shape: &Shape,
) -> Result<(Vec<T>, Case), ParamError> {
    if z.len() < 2 || shape.rising.len() + 1 != z.len() || magnitudes.len() + 1 != z.len() {
        return Err(ParamError::TooFewPoints);
    }
    let case = shape.case();
    let t = match case {
        Case::I => chord_length_from(magnitudes, &z[0].ctx()),
        Case::II => alternating_from(magnitudes, &z[0].ctx()),
        Case::III => {
            let idx = shape.extremes();
            let edited: Vec<T> = idx.iter().map(|&i| z[i].clone()).collect();
            // The edited data alternate; each step's magnitude is the sum of the
            // magnitudes it spans (all of one sign between two extremes).
            let edited_magnitudes: Vec<T> = idx
                .windows(2)
                .map(|w| {
                    magnitudes[w[0]..w[1]]
                        .iter()
                        .fold(T::zero_in(&z[0].ctx()), |acc, m| acc + m)
                })
                .collect();
            let edited_rising: Vec<bool> = idx.windows(2).map(|w| shape.rising[w[0]]).collect();
            let t_hat = alternating_from(&edited_magnitudes, &z[0].ctx());
            // ψ is monotone between consecutive extremes (Eq. 8), rising where the data do;
            // its knots t̂ increase because every magnitude is positive (decided exactly).
            let psi = NaturalCubicSpline::with_increasing_knots(t_hat.clone(), edited)
                .map_err(|_| ParamError::TooFewPoints)?;
            let ctx = z[0].ctx();
            let mut t = vec![T::zero_in(&ctx); z.len()];
            for (k, &i) in idx.iter().enumerate() {
                t[i] = t_hat[k].clone();
            }
            for k in 1..idx.len() {
                for j in idx[k - 1] + 1..idx[k] {
                    t[j] = solve_monotone(&psi, k, &z[j], edited_rising[k - 1]);
                }
            }
            t
        }
    };
    Ok((t, case))
}

/// The t in ψ's piece [a, b] = [t̂_{piece−1}, t̂_piece] with ψ(t) = target, ψ strictly
/// monotone on [a, b] (rising when
/// `increasing`) and the target strictly between ψ(a) and ψ(b); bisection until the bracket
/// is as small as the precision allows. In ball arithmetic the bisection stops where ψ at
/// none of the middle, 3/8 and 5/8 of the bracket can be told from the target, and the last bracket — proven to hold the
/// root — is returned as one ball ([`Field::hull`]).
fn solve_monotone<T: Real>(
    psi: &NaturalCubicSpline<T>,
    piece: usize,
    target: &T,
    increasing: bool,
) -> T {
    let (a, b) = (&psi.knots()[piece - 1], &psi.knots()[piece]);
    let ctx = a.ctx();
    let (mut lo, mut hi) = (a.clone(), b.clone());
    let limit = T::epsilon(&ctx) * &(b.clone() - a);
    for _ in 0..(4 * T::precision_bits(&ctx) + 64) {
        if (hi.clone() - &lo).decide_lt(&limit) != Some(false) {
            break;
        }
        // Split at the middle, or — when ψ there cannot be told from the target (the root may
        // sit exactly at the middle: symmetric data put it there) — at 3/8 or 5/8 of the
        // bracket, so that it keeps narrowing around such a root.
        let width = hi.clone() - &lo;
        let decided = [(1, 2), (3, 8), (5, 8)].iter().find_map(|&(n, d)| {
            let split = lo.clone() + &(width.clone() * &T::from_ratio(n, d, &ctx));
            // ψ on its piece [a, b], named, not located by comparing a rounded split.
            let below = psi.eval_on(&split, piece)[0].decide_lt(target)?;
            Some((split, below))
        });
        let Some((mid, below)) = decided else {
            break;
        };
        if below == increasing {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    T::hull(&lo, &hi)
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
