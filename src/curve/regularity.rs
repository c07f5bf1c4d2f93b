//! Whether a curve is regular on an interval, proven in ball arithmetic: its derivatives up
//! to a given order are finite everywhere on [a, b], and its tangent never vanishes.
//!
//! A conversion or an interpolation evaluates the curve's jet at joints and samples; a jet
//! that is not finite there (√t at 0, ln t at 0, 1/t at 0, √−1 anywhere) poisons every
//! number after it, and a vanishing tangent (a cusp such as (t², t³, 0) at 0) leaves a PH
//! curve nothing to interpolate. Sampling cannot rule either out between its samples, so
//! [`check`] proves it: the jet is evaluated on a ball that covers a box of [a, b] (Taylor
//! arithmetic in balls encloses every derivative over the box); a box whose jet is finite
//! and whose ‖γ′‖² excludes 0 is proven regular, any other is split, its midpoint evaluated
//! exactly, until a point is found where the curve fails (reported with that t) or the
//! boxes are too small to decide (reported as "at or near" t). The exact end points are
//! checked first. The smallest and largest ‖γ′‖ seen bound the curve's speed, from which a
//! near-cusp is reported ([`Regularity::speed_ratio`]).

use super::interval::Interval;
use super::Curve;
use crate::scalar::ball::Ball;
use crate::scalar::{Field, Float};
use rug::float::Round;

/// Why a curve is not regular on the interval.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum Irregular {
    /// A derivative up to the order asked for is not finite at t (or in a tiny box at t).
    #[error("the curve or one of its first {order} derivatives is not finite {at}t = {t}")]
    NotFinite {
        /// Where (approximately, when `at` says "at or near ").
        t: String,
        /// "at " for an exact point, "at or near " for a box too small to split further.
        at: &'static str,
        /// The derivative order checked.
        order: usize,
    },
    /// The curve's values near t are beyond what a ball can enclose (its radius is an f64,
    /// up to about 1e308): regularity cannot be proven in balls, though MPFR may carry it.
    #[error("the curve reaches about {size} near t = {t}, beyond the range of ball arithmetic (its radii are f64); use mpfr:<bits>")]
    BeyondBallRange {
        /// Where.
        t: String,
        /// How large, roughly.
        size: String,
    },
    /// The tangent γ′ vanishes at t (or cannot be told from 0 in a tiny box at t).
    #[error("the tangent vanishes {at}t = {t} (a cusp or a stationary point): no parametrization with a non-zero speed passes there")]
    TangentVanishes {
        /// Where.
        t: String,
        /// "at " or "at or near ".
        at: &'static str,
    },
}

/// What the check proved.
#[derive(Clone, Debug, PartialEq)]
pub struct Regularity {
    /// A proven lower bound of ‖γ′‖ on [a, b].
    pub min_speed: f64,
    /// An upper bound of ‖γ′‖ on [a, b] (from the same boxes).
    pub max_speed: f64,
    /// Where the smallest lower bound was found.
    pub slowest_at: f64,
}

impl Regularity {
    /// min ‖γ′‖ / max ‖γ′‖: near 0 the curve nearly has a cusp and any approximation by
    /// segments of equal parameter length needs many of them there.
    pub fn speed_ratio(&self) -> f64 {
        if self.max_speed > 0.0 {
            self.min_speed / self.max_speed
        } else {
            0.0
        }
    }
}

/// Boxes evaluated at most.
const MAX_BOXES: usize = 20_000;
/// A box narrower than this fraction of [a, b] is not split again.
const MIN_RELATIVE_WIDTH: f64 = 1e-12;

/// Prove that `curve` (in balls at `bits`) has finite derivatives up to `order` and a
/// non-vanishing tangent on [a, b] (a < b).
///
/// # Errors
/// [`Irregular::BeyondBallRange`], [`Irregular::NotFinite`] or [`Irregular::TangentVanishes`]
/// at the first end point or box midpoint whose jet is too large for a ball, not finite,
/// or whose ‖γ′‖² is not proven positive; the last two also ("at or near ") when a failing
/// box is narrower than 10⁻¹²·(b − a) or 20 000 boxes have been evaluated.
pub fn check<C: Curve<Ball> + ?Sized>(
    curve: &C,
    interval: &Interval,
    order: usize,
    bits: u32,
) -> Result<Regularity, Irregular> {
    let order = order.max(1);
    // Floats around the exact ends (equal to them when they are floats at `bits`): the
    // proof covers the true interval.
    let (a_f, b_f) = interval.enclosure(bits);
    for end in [&a_f, &b_f] {
        point(curve, end, order)?;
    }
    let width = Float::with_val(bits, &b_f - &a_f).to_f64();
    let start = a_f.to_f64();
    let mut boxes = vec![(a_f, b_f)];
    let mut seen = 0usize;
    let mut proven = Regularity {
        min_speed: f64::INFINITY,
        max_speed: 0.0,
        slowest_at: start,
    };
    while let Some((lo, hi)) = boxes.pop() {
        crate::cancel::checkpoint();
        seen += 1;
        let ball = Ball::from_bounds_at(&lo, &hi, bits);
        let jet = curve.jet(&ball, order);
        let speed2 = squared_norm(&jet[1]);
        let finite = jet.iter().flatten().all(Field::is_finite);
        let lower = speed2.lower();
        if finite && lower > 0 {
            let (low, high) = (
                lower.to_f64_round(Round::Down).sqrt(),
                speed2.upper().to_f64_round(Round::Up).sqrt(),
            );
            if low < proven.min_speed {
                proven.min_speed = low;
                proven.slowest_at = ball.mid().to_f64();
            }
            proven.max_speed = proven.max_speed.max(high);
            continue;
        }
        let mid = Float::with_val(bits, &lo + &hi) / 2u32;
        point(curve, &mid, order)?;
        let narrow = Float::with_val(53, &hi - &lo).to_f64() <= MIN_RELATIVE_WIDTH * width;
        if narrow || seen >= MAX_BOXES {
            let t = crate::scalar::certify::format_float_digits(&mid, 6);
            return Err(if finite {
                Irregular::TangentVanishes {
                    t,
                    at: "at or near ",
                }
            } else {
                Irregular::NotFinite {
                    t,
                    at: "at or near ",
                    order,
                }
            });
        }
        boxes.push((mid.clone(), hi));
        boxes.push((lo, mid));
    }
    Ok(proven)
}

/// A jet entry whose midpoint is finite but too large for an f64 radius, if any.
fn beyond_range(jet: &[[Ball; 3]]) -> Option<&Ball> {
    jet.iter()
        .flatten()
        .find(|x| x.mid().is_finite() && !x.rad().is_finite() && x.mid().clone().abs() > 1e290)
}

/// The checks at one exact point.
fn point<C: Curve<Ball> + ?Sized>(curve: &C, t: &Float, order: usize) -> Result<(), Irregular> {
    let jet = curve.jet(&Ball::exact(t.clone()), order);
    let text = || crate::scalar::certify::format_float_digits(t, 17);
    if let Some(big) = beyond_range(&jet) {
        return Err(Irregular::BeyondBallRange {
            t: text(),
            size: crate::scalar::certify::format_float_digits(big.mid(), 2),
        });
    }
    if !jet.iter().flatten().all(Field::is_finite) {
        return Err(Irregular::NotFinite {
            t: text(),
            at: "at ",
            order,
        });
    }
    let speed2 = squared_norm(&jet[1]);
    if speed2.lower() <= 0 || speed2.lower().is_nan() {
        return Err(Irregular::TangentVanishes {
            t: text(),
            at: if Field::is_zero(&speed2) {
                "at "
            } else {
                "at or near "
            },
        });
    }
    Ok(())
}

fn squared_norm(v: &[Ball; 3]) -> Ball {
    v[0].clone() * &v[0] + &(v[1].clone() * &v[1]) + &(v[2].clone() * &v[2])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::ExprCurve;

    fn verdict(text: &str, a: i64, b: i64) -> Result<Regularity, Irregular> {
        let c = ExprCurve::parse(text).unwrap().compile::<Ball>(&128);
        check(&c, &Interval::new(a, b).expect("a < b"), 4, 128)
    }

    #[test]
    fn regular_curves_pass_and_singular_ones_name_t() {
        assert!(verdict("[sin(t), cos(t), t]", 0, 1).is_ok());
        assert!(matches!(
            verdict("[sqrt(t), t, 0]", 0, 1),
            Err(Irregular::NotFinite { ref t, at: "at ", .. }) if t == "0"
        ));
        assert!(matches!(
            verdict("[1/t, t, 0]", -1, 1),
            Err(Irregular::NotFinite { ref t, .. }) if t == "0"
        ));
        assert!(matches!(
            verdict("[t^2, t^3, 0]", -1, 1),
            Err(Irregular::TangentVanishes { ref t, at: "at " }) if t == "0"
        ));
        assert!(verdict("[sqrt(-1), t, t]", 0, 1).is_err());
        let near = verdict("[t^2, t^3, 0.001*t]", -1, 1).unwrap();
        assert!(near.speed_ratio() < 1e-3, "{near:?}");
    }
}
