//! Distances in the plane and net turning of a plane polynomial curve, in ball arithmetic:
//! the building blocks of proven maxima over a curve ([`crate::numeric::maximum`]).
//!
//! - [`segment_distance`] and [`polygon_distance`]: the distance of a point (balls) from a
//!   segment or a polygon. Where the projection's side is not decided by the enclosures, the
//!   hull of the candidate formulas is returned (the true distance is one of them), so no
//!   comparison is guessed. The distance to a fixed set is 1-Lipschitz in the point: over a
//!   box of a curve's parameter it lies within |c′|·(half-width) of its value at the box's
//!   midpoint; where it is smooth, a mean-value form is tighter ([`CurveBox`] takes both).
//! - [`net_turning`]: the net angle a plane vector function v(u), u ∈ [0, 1], turns through
//!   (a curve's tangent, or its position about a point). On a box whose enclosure of v is a
//!   rectangle with v·v(a) > 0 for every point (the box's own enclosure, checked), the angle
//!   changes by less than 90°, so its change is the principal angle between the vectors at
//!   the box's ends; the net turning is the sum over a cover of [0, 1] by such boxes (halved
//!   until they qualify). A zero of v would stop it: then no box qualifies and the function
//!   says so.

use crate::scalar::ball::Ball;
use crate::scalar::{Field, Float, Real};

/// A point or vector of the plane, each coordinate enclosed.
pub type Point2 = [Ball; 2];

fn norm(v: &Point2) -> Ball {
    (v[0].clone() * &v[0] + &(v[1].clone() * &v[1])).sqrt()
}

fn minus(p: &Point2, q: &Point2) -> Point2 {
    [p[0].clone() - &q[0], p[1].clone() - &q[1]]
}

/// The distance of the point p from the segment [a, b] (a ≠ b), enclosed.
pub fn segment_distance(p: &Point2, a: &Point2, b: &Point2) -> Ball {
    CurveBox::at_point(p).distance_to_segment(a, b)
}

/// The hull of the candidates (the fallback when there are none, which the callers' case
/// analysis excludes).
fn hull_of(candidates: Vec<Ball>, fallback: impl FnOnce() -> Ball) -> Ball {
    let mut all = candidates.into_iter();
    let first = all.next().unwrap_or_else(fallback);
    all.fold(first, |h, c| Ball::hull(&h, &c))
}

/// The distance of the point p from the polygon through `vertices` (the least over its
/// segments; min is continuous, so no comparison is decided). `None` for fewer than two
/// vertices.
pub fn polygon_distance(p: &Point2, vertices: &[Point2]) -> Option<Ball> {
    CurveBox::at_point(p).distance_to_polygon(vertices)
}

/// The distance of p from the circular arc about `centre` of radius `radius` whose points
/// are the directions in the closed quarter-plane cone {x·e₁ ≥ 0, x·e₂ ≥ 0} spanned by the
/// orthonormal pair (e₁, e₂) (an arc of at most 90°, ends centre + radius·e₁ and
/// centre + radius·e₂): ||p − c| − r| when p − c lies in the cone, the nearer end otherwise;
/// the hull of both where the enclosures do not decide.
pub fn quarter_arc_distance(p: &Point2, centre: &Point2, radius: &Ball, e: [&Point2; 2]) -> Ball {
    CurveBox::at_point(p).distance_to_quarter_arc(centre, radius, e)
}

/// A plane curve over a box X of its parameter: its point at the box's midpoint m, and
/// enclosures of its points and of its velocity over the whole box. The distances below are
/// enclosed over the box from it, each by the tighter of two forms: the mean-value form
/// f(c(m)) + ∇f(c(X))·c′(X)·(X − m) on a piece where f is smooth (second order in the box's
/// width, so a search needs few boxes near a maximum), and the Lipschitz form
/// f(c(m)) ± |c′(X)|·rad(X) (a distance to a set is 1-Lipschitz in the point).
#[derive(Clone, Debug)]
pub struct CurveBox {
    /// c(m), enclosed.
    pub at_mid: Point2,
    /// c over the whole box.
    pub over: Point2,
    /// c′ over the whole box.
    pub velocity: Point2,
    /// The box X itself.
    pub parameter: Ball,
}

/// The intersection of two enclosures of the same quantity (the first when they are
/// disjoint, which rounding cannot cause since both are proven).
fn intersect(a: Ball, b: &Ball) -> Ball {
    let lo = a.lower().max(&b.lower());
    let hi = a.upper().min(&b.upper());
    if lo > hi {
        return a;
    }
    Ball::from_bounds_at(&lo, &hi, a.mid().prec())
}

impl CurveBox {
    /// A single point (a box of width 0 with no motion): the distances below are then those of
    /// the point itself.
    pub fn at_point(p: &Point2) -> CurveBox {
        let zero = Ball::zero_in(&p[0].mid().prec());
        CurveBox {
            at_mid: p.clone(),
            over: p.clone(),
            velocity: [zero.clone(), zero.clone()],
            parameter: zero,
        }
    }

    /// The Lipschitz form of a 1-Lipschitz function with value `at_mid` at c(m).
    pub fn lipschitz(&self, at_mid: Ball) -> Ball {
        let speed = norm(&self.velocity).abs_upper();
        let reach =
            (Ball::from_f64(speed, &64) * &Ball::from_f64(self.parameter.rad(), &64)).abs_upper();
        at_mid.widen(reach)
    }

    /// The mean-value form of a smooth function with value `at_mid` at c(m) and gradient
    /// enclosed by `gradient` over c(X).
    pub fn smooth(&self, at_mid: Ball, gradient: &Point2) -> Ball {
        let slope =
            gradient[0].clone() * &self.velocity[0] + &(gradient[1].clone() * &self.velocity[1]);
        let offset = Ball::new(
            Float::with_val(self.parameter.mid().prec(), 0),
            self.parameter.rad(),
        );
        at_mid + &(slope * &offset)
    }

    /// |c − q| over the box.
    pub fn distance_to_point(&self, q: &Point2) -> Ball {
        let at_mid = norm(&minus(&self.at_mid, q));
        let lipschitz = self.lipschitz(at_mid.clone());
        let away = minus(&self.over, q);
        let length = norm(&away);
        if length.lower() <= 0 {
            return lipschitz;
        }
        let gradient = [away[0].clone() / &length, away[1].clone() / &length];
        intersect(self.smooth(at_mid, &gradient), &lipschitz)
    }

    /// |g| over the box for a smooth signed g (value at c(m), gradient over c(X)), as a
    /// distance: both forms, intersected.
    fn signed(&self, at_mid: Ball, gradient: &Point2) -> Ball {
        let lipschitz = self.lipschitz(at_mid.clone().abs());
        intersect(self.smooth(at_mid, gradient).abs(), &lipschitz)
    }

    /// The distance from the segment [a, b] (a ≠ b) over the box: by the case of the
    /// projection decided over c(X), the hull of the cases' enclosures where it is not.
    pub fn distance_to_segment(&self, a: &Point2, b: &Point2) -> Ball {
        let d = minus(b, a);
        let length = norm(&d);
        let length2 = d[0].clone() * &d[0] + &(d[1].clone() * &d[1]);
        let w = minus(&self.over, a);
        let s = (w[0].clone() * &d[0] + &(w[1].clone() * &d[1])) / &length2;
        let line = || {
            // The signed distance from the line, cross(c − a, d)/|d|: gradient (d_y, −d_x)/|d|.
            let wm = minus(&self.at_mid, a);
            let at_mid = (wm[0].clone() * &d[1] - &(wm[1].clone() * &d[0])) / &length;
            self.signed(at_mid, &[d[1].clone() / &length, -(d[0].clone() / &length)])
        };
        let mut cases = Vec::new();
        if s.lower() <= 0 {
            cases.push(self.distance_to_point(a));
        }
        if s.upper() >= 1 {
            cases.push(self.distance_to_point(b));
        }
        if s.upper() >= 0 && s.lower() <= 1 {
            cases.push(line());
        }
        hull_of(cases, || self.distance_to_point(a))
    }

    /// The distance from the polygon through `vertices` over the box (`None` for fewer than
    /// two vertices).
    pub fn distance_to_polygon(&self, vertices: &[Point2]) -> Option<Ball> {
        vertices
            .windows(2)
            .map(|w| self.distance_to_segment(&w[0], &w[1]))
            .reduce(|a, b| a.min_with(&b))
    }

    /// The distance from the quarter arc of [`quarter_arc_distance`] over the box.
    pub fn distance_to_quarter_arc(&self, centre: &Point2, radius: &Ball, e: [&Point2; 2]) -> Ball {
        let v = minus(&self.over, centre);
        let along = |u: &Point2| v[0].clone() * &u[0] + &(v[1].clone() * &u[1]);
        let (a1, a2) = (along(e[0]), along(e[1]));
        let radial = || {
            // g = |c − centre| − r, gradient (c − centre)/|c − centre|.
            let at_mid = norm(&minus(&self.at_mid, centre)) - radius;
            let length = norm(&v);
            if length.lower() <= 0 {
                return self.lipschitz(at_mid.abs());
            }
            self.signed(at_mid, &[v[0].clone() / &length, v[1].clone() / &length])
        };
        let end = |u: &Point2| {
            self.distance_to_point(&[
                centre[0].clone() + &(radius.clone() * &u[0]),
                centre[1].clone() + &(radius.clone() * &u[1]),
            ])
        };
        let nearer_end = || end(e[0]).min_with(&end(e[1]));
        if a1.lower() >= 0 && a2.lower() >= 0 {
            radial()
        } else if a1.upper() < 0 || a2.upper() < 0 {
            nearer_end()
        } else {
            Ball::hull(&radial(), &nearer_end())
        }
    }
}

/// Why a net turning could not be enclosed.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum TurningError {
    /// No box around this parameter keeps v's enclosure away from 0 (v may vanish there).
    #[error("the vector may vanish near u = {at}: the turning is not defined or not resolved")]
    MayVanish {
        /// The parameter, rounded for the message.
        at: String,
    },
}

/// The net angle (radians, enclosed) through which v turns as u runs over [0, 1], where
/// `v(U)` encloses the vector over every ball U inside [0, 1] (see the module doc). Boxes
/// start at `initial` equal pieces and are halved up to `depth` times.
///
/// # Errors
/// [`TurningError::MayVanish`] where no box of the allowed depth qualifies.
///
/// # Example
/// ```
/// use trajverify::curve::distance::net_turning;
/// use trajverify::scalar::{ball::Ball, Field};
/// // v(u) = (1 − 2u, 2u(1 − u)·4): from (1, 0) over (0, 2) to (−1, 0), a half turn (π).
/// let v = |u: &Ball| {
///     let one = Ball::one_in(&128);
///     let two = Ball::from_i64(2, &128);
///     [one.clone() - &(two.clone() * u), Ball::from_i64(8, &128) * u * &(one - u)]
/// };
/// let turning = net_turning(v, 8, 20, 128).unwrap();
/// assert!(turning.contains(&rug::Float::with_val(128, rug::float::Constant::Pi)));
/// ```
pub fn net_turning(
    v: impl Fn(&Ball) -> Point2,
    initial: usize,
    depth: u32,
    bits: u32,
) -> Result<Ball, TurningError> {
    let mut total = Ball::zero_in(&bits);
    let initial = initial.max(1);
    let mut stack: Vec<(Float, Float, u32)> = (0..initial)
        .rev()
        .map(|i| {
            (
                Float::with_val(bits, i) / initial as u32,
                Float::with_val(bits, i + 1) / initial as u32,
                0,
            )
        })
        .collect();
    while let Some((lo, hi, level)) = stack.pop() {
        crate::cancel::checkpoint();
        let (va, vb) = (v(&Ball::exact(lo.clone())), v(&Ball::exact(hi.clone())));
        let whole = v(&Ball::from_bounds_at(&lo, &hi, bits));
        // Every vector of the box within 90° of v(a): its turning on the box is below 90°.
        let dot = whole[0].clone() * &va[0] + &(whole[1].clone() * &va[1]);
        let end_dot = va[0].clone() * &vb[0] + &(va[1].clone() * &vb[1]);
        if dot.lower() > 0 && end_dot.lower() > 0 {
            let cross = va[0].clone() * &vb[1] - &(va[1].clone() * &vb[0]);
            total += &cross.atan2(&end_dot);
            continue;
        }
        if level >= depth {
            return Err(TurningError::MayVanish {
                at: lo.to_f64().to_string(),
            });
        }
        let mid = Float::with_val(bits, Float::with_val(bits + 2, &lo + &hi) / 2u32);
        stack.push((mid.clone(), hi, level + 1));
        stack.push((lo, mid, level + 1));
    }
    Ok(total)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> Point2 {
        [Ball::from_f64(x, &128), Ball::from_f64(y, &128)]
    }

    #[test]
    fn distances_to_a_segment_a_polygon_and_an_arc() {
        let (a, b) = (p(0.0, 0.0), p(2.0, 0.0));
        // Beside, before and beyond the segment.
        assert!(segment_distance(&p(1.0, 3.0), &a, &b).contains(&Float::with_val(128, 3)));
        assert!(segment_distance(&p(-3.0, 4.0), &a, &b).contains(&Float::with_val(128, 5)));
        assert!(segment_distance(&p(5.0, 4.0), &a, &b).contains(&Float::with_val(128, 5)));
        let square = [p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0)];
        let d = polygon_distance(&p(2.0, 0.5), &square).unwrap();
        assert!(d.contains(&Float::with_val(128, 1)));
        assert!(polygon_distance(&p(0.0, 0.0), &square[..1]).is_none());
        // Quarter arc of the unit circle from (1, 0) to (0, 1): the origin is 1 away, (2, 2)
        // is 2√2 − 1 away, (−1, −1) is √2 from both ends' nearer one.
        let (c, r) = (p(0.0, 0.0), Ball::one_in(&128));
        let (e1, e2) = (p(1.0, 0.0), p(0.0, 1.0));
        let arc = |q: Point2| quarter_arc_distance(&q, &c, &r, [&e1, &e2]);
        assert!(arc(p(2.0, 2.0)).contains(&(Float::with_val(128, 8).sqrt() - 1u32)));
        assert!(arc(p(0.0, -1.0)).contains(&Float::with_val(128, 2).sqrt()));
    }

    /// The parabola c(u) = (u, u² − 1/2) over a box, as a search gives it.
    fn parabola_box(lo: f64, hi: f64) -> CurveBox {
        let x = Ball::from_bounds(&Float::with_val(128, lo), &Float::with_val(128, hi));
        let at = |u: &Ball| [u.clone(), u.clone() * u - &Ball::from_f64(0.5, &128)];
        CurveBox {
            at_mid: at(&Ball::exact(x.mid().clone())),
            over: at(&x),
            velocity: [Ball::one_in(&128), Ball::from_i64(2, &128) * &x],
            parameter: x,
        }
    }

    #[test]
    fn a_curve_box_encloses_every_point_distance_of_its_box() {
        let (a, b) = (p(0.0, 0.0), p(1.0, 0.0));
        let polygon = [p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0)];
        let (centre, one) = (p(0.0, 0.0), Ball::one_in(&128));
        let (e1, e2) = (p(1.0, 0.0), p(0.0, 1.0));
        for (lo, hi) in [(0.0, 0.25), (0.3, 0.9), (-0.5, 1.5), (0.69, 0.71)] {
            let cb = parabola_box(lo, hi);
            let enclosures = [
                cb.distance_to_segment(&a, &b),
                cb.distance_to_polygon(&polygon).unwrap(),
                cb.distance_to_quarter_arc(&centre, &one, [&e1, &e2]),
            ];
            for k in 0..=20 {
                let u = lo + (hi - lo) * k as f64 / 20.0;
                let q = p(u, u * u - 0.5);
                let pointwise = [
                    segment_distance(&q, &a, &b),
                    polygon_distance(&q, &polygon).unwrap(),
                    quarter_arc_distance(&q, &centre, &one, [&e1, &e2]),
                ];
                for (enclosure, value) in enclosures.iter().zip(&pointwise) {
                    assert!(
                        enclosure.lower() <= value.upper() && value.lower() <= enclosure.upper(),
                        "[{lo}, {hi}] at {u}: {enclosure:?} misses {value:?}"
                    );
                }
            }
        }
    }

    #[test]
    fn a_full_circle_turns_by_two_pi_and_a_vanishing_vector_is_refused() {
        let circle = |u: &Ball| {
            let angle = Ball::from_i64(2, &128) * &Ball::pi(&128) * u;
            let (s, c) = angle.sin_cos();
            [c, s]
        };
        let turn = net_turning(circle, 4, 16, 128).unwrap();
        let two_pi = Float::with_val(128, rug::float::Constant::Pi) * 2u32;
        assert!(turn.contains(&two_pi) && turn.rad() < 1e-20);
        // v(u) = (u − 1/2, 0) vanishes at u = 1/2.
        let through_zero = |u: &Ball| [u.clone() - &Ball::from_f64(0.5, &128), Ball::zero_in(&128)];
        assert!(matches!(
            net_turning(through_zero, 4, 10, 128),
            Err(TurningError::MayVanish { .. })
        ));
    }
}
