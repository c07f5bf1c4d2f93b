//! Piecewise two-point Hermite interpolation of a curve in Bernstein form: paper 000's map
//! (Eqs. 11–18) on every segment of a uniform subdivision.
//!
//! [a, b] is split into N segments of length h. On segment k, in the local parameter
//! ξ = (t − t_k)/h ∈ [0, 1], the data are γ(t_k), hγ′(t_k), …, h^m γ⁽ᵐ⁾(t_k) at ξ = 0 and the
//! same at t_{k+1} (the local-parameter data of paper 001, Eq. 20), and the piece is the
//! polynomial of degree 2m + 1 that [`super::solve_points`] gives on [0, 1]. Neighbouring
//! pieces share m derivatives at their joint, so the interpolant is C^m.
//!
//! Paper 000 claims no approximation order. The classical Hermite remainder does: each
//! component satisfies γ(t) − p(t) = γ⁽²ᵐ⁺²⁾(ζ)/(2m+2)! · (t − t_k)^{m+1}(t − t_{k+1})^{m+1},
//! so E ≤ max|γ⁽²ᵐ⁺²⁾| h^{2m+2}/((2m+2)! 4^{m+1}) (per component): order 2m + 2 for a smooth
//! curve. `trajverify report convergence --method hermite:<m>` measures it.

use super::{solve_points, HermiteError};
use crate::curve::approx::{knot, PiecewiseBernstein};
use crate::curve::Curve;
use crate::scalar::ball::carried;
use crate::scalar::Real;
use rayon::prelude::*;

/// The most segments [`interpolate_curve`] builds.
pub const MAX_SEGMENTS: usize = 1 << 19;

/// The most derivatives per joint [`interpolate_curve`] matches (degree 2m + 1 ≤ 61).
pub const MAX_JOINT_DERIVATIVES: usize = 30;

/// The shape of a piecewise Hermite interpolant.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct InterpolationOptions {
    /// The number of uniform segments. Default 8.
    pub segments: usize,
    /// The derivatives m matched at every joint (degree 2m + 1). Default 2 (quintic, C²).
    pub derivatives: usize,
}

impl Default for InterpolationOptions {
    fn default() -> Self {
        InterpolationOptions {
            segments: 8,
            derivatives: 2,
        }
    }
}

/// The interpolant of `curve` on `options.segments` uniform pieces of [a, b] matching
/// m = `options.derivatives` derivatives at every joint (degree 2m + 1).
///
/// # Examples
/// ```
/// use trajverify::algo::hermite::piecewise::{interpolate_curve, InterpolationOptions};
/// use trajverify::curve::{approx::conversion_error, ExprCurve};
/// let helix = ExprCurve::parse("[cos(t), sin(t), t/5]").unwrap().compile::<f64>(&());
/// let pw = interpolate_curve(&helix, (&0.0, &1.0), &InterpolationOptions::default()).unwrap();
/// assert!(conversion_error(&helix, &pw, 16).max < 1e-8);
/// ```
///
/// # Errors
/// [`HermiteError::NoSegments`] for `segments` = 0, [`HermiteError::TooManySegments`] above
/// [`MAX_SEGMENTS`], [`HermiteError::TooManyDerivatives`] for m above
/// [`MAX_JOINT_DERIVATIVES`], [`HermiteError::EmptyInterval`] unless a < b, and the errors of
/// [`solve_points`].
pub fn interpolate_curve<T: Real, C: Curve<T> + ?Sized>(
    curve: &C,
    (a, b): (&T, &T),
    options: &InterpolationOptions,
) -> Result<PiecewiseBernstein<T>, HermiteError> {
    let InterpolationOptions {
        segments,
        derivatives: m,
    } = *options;
    if segments == 0 {
        return Err(HermiteError::NoSegments);
    }
    if segments > MAX_SEGMENTS {
        return Err(HermiteError::TooManySegments(segments));
    }
    if m > MAX_JOINT_DERIVATIVES {
        return Err(HermiteError::TooManyDerivatives {
            m,
            max: MAX_JOINT_DERIVATIVES,
        });
    }
    if a.partial_cmp(b) != Some(std::cmp::Ordering::Less) {
        return Err(HermiteError::EmptyInterval);
    }
    let ctx = a.ctx();
    let h = (b.clone() - a) / &T::from_i64(segments as i64, &ctx);
    // h^j γ^(j)(t_k) as rows of points, for every joint.
    let jets: Vec<Vec<Vec<T>>> = (0..=segments)
        .into_par_iter()
        .map(carried(|k| {
            let mut scale = T::one_in(&ctx);
            let jet = curve.jet(&knot((a, b), segments, k), m);
            jet.into_iter()
                .enumerate()
                .map(|(j, v)| {
                    if j > 0 {
                        scale *= &h;
                    }
                    v.iter().map(|x| x.clone() * &scale).collect()
                })
                .collect()
        }))
        .collect();
    let (zero, one) = (T::zero_in(&ctx), T::one_in(&ctx));
    let pieces = (0..segments)
        .into_par_iter()
        .map(carried(|k: usize| {
            let points = solve_points(&jets[k], &jets[k + 1], (&zero, &one))?;
            Ok(points
                .into_iter()
                .map(|p| [p[0].clone(), p[1].clone(), p[2].clone()])
                .collect())
        }))
        .collect::<Result<Vec<_>, HermiteError>>()?;
    PiecewiseBernstein::new(pieces, (a.clone(), b.clone())).map_err(|_| HermiteError::EmptyInterval)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::approx::{conversion_error, BernsteinPieces, DEFAULT_SAMPLES};
    use crate::curve::ExprCurve;
    use crate::numeric::poly::bernstein::bernstein_jet;

    #[test]
    fn pieces_match_the_data_and_converge_at_order_2m_plus_2() {
        let curve = ExprCurve::parse("[cos(3*t), sin(2*t), exp(t)]")
            .unwrap()
            .compile::<f64>(&());
        for m in [1usize, 2] {
            let fit = interpolate_curve(
                &curve,
                (&0.0, &1.0),
                &InterpolationOptions {
                    segments: 4,
                    derivatives: m,
                },
            )
            .unwrap();
            assert_eq!(fit.control_points(0).len(), 2 * m + 2);
            // The end of piece 1 has the curve's jet at t = 0.5, scaled by h = 1/4.
            let end = bernstein_jet(&fit.control_points(1), &1.0, m);
            let jet = curve.jet(&0.5, m);
            for (j, (p, g)) in end.iter().zip(&jet).enumerate() {
                let scale = 0.25f64.powi(j as i32);
                assert!(
                    (p[0] - g[0] * scale).abs() < 1e-12,
                    "m = {m}, derivative {j}"
                );
            }
            let error = |n: usize| {
                let fit = interpolate_curve(
                    &curve,
                    (&0.0, &1.0),
                    &InterpolationOptions {
                        segments: n,
                        derivatives: m,
                    },
                )
                .unwrap();
                conversion_error(&curve, &fit, DEFAULT_SAMPLES).max
            };
            let order = (error(8) / error(16)).log2();
            let expected = (2 * m + 2) as f64;
            assert!((order - expected).abs() < 0.1, "m = {m}: order {order}");
        }
    }
}
