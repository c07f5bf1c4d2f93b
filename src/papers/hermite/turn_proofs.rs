//! Proven measures of the Fig. 3 curves (paper 000, Sec. 4): the Hermite curves of the quarter
//! turn solved in ball arithmetic, their distances from the chord and the arc enclosed by
//! branch and bound, and their net tangent turning enclosed.
//!
//! **Hausdorff distances as one-sided maxima.** The curve c runs from A = (0, 0) to
//! B = (1, 1), the ends of both the chord and the arc (exactly, by interpolation). Then
//! - to the chord: for each chord point q, the projection (c(t) − A)·(B − A)/|B − A| runs
//!   continuously from 0 to |B − A|, so some c(t) projects onto q and |c(t) − q| is its
//!   distance from the line, at most its distance from the segment. Hence
//!   H(c, chord) = max_t d(c(t), chord).
//! - to the arc (centre (0, 1), radius 1, from angle −90° to 0°): if c never meets the centre
//!   and the continuous angle of c(t) − centre, starting at −90°, ends at 0° + k·360° with
//!   k ≠ −1, every direction of the arc is taken by some c(t), at distance |r(t) − 1| ≤
//!   d(c(t), arc) from the arc point on that ray. Hence H(c, arc) = max_t d(c(t), arc); for
//!   k = −1 only H ≥ max_t d(c(t), arc) is claimed.
//!
//! Each max_t is enclosed by [`proven_maximum`] (the distance over a box of the parameter by
//! [`CurveBox`]: mean-value and Lipschitz forms), the winding about the centre and the tangent's turning by
//! [`net_turning`]. How far the curve recedes from the terminal point is a proven lower
//! bound: two parameters t₁ < t₂ (found on samples) with d(t₂) − d(t₁) enclosed.

use super::super::{Outcome, Verdict};
use super::examples::{turn_curve, Curve, TurnData, TURN_FACTORS};
use crate::curve::distance::{net_turning, CurveBox, Point2};
use crate::numeric::maximum::{midpoint, proven_maximum, SearchOptions};
use crate::numeric::poly::Bernstein;
use crate::scalar::ball::Ball;
use crate::scalar::{Field, Float, Real};

/// The working precision of the proofs (bits).
pub const BITS: u32 = 128;

/// The proven measures of one Fig. 3 curve.
#[derive(Clone, Debug)]
pub struct ProvenTurn {
    /// The reading of the data.
    pub data: TurnData,
    /// The duration factor of the nominal π/2.
    pub factor: (i64, i64),
    /// H(c, chord) = max_t d(c(t), chord), enclosed.
    pub chord: Ball,
    /// max_t d(c(t), arc), enclosed: H(c, arc) itself when `arc_is_hausdorff`, else a lower
    /// bound of it.
    pub arc: Ball,
    /// Whether the winding condition of the module doc holds (proven).
    pub arc_is_hausdorff: bool,
    /// The net turning of the tangent, in degrees, enclosed.
    pub net_turning_degrees: Ball,
    /// A proven lower bound of the largest rise of the distance to the terminal point above
    /// the least distance reached before, over the start's distance.
    pub recedes_at_least: Float,
}

/// A curve's coordinates as Bernstein polynomials in its local parameter u ∈ [0, 1] (the same
/// control points on [0, 1]), and their derivatives d/du; evaluated on a ball u by
/// [`Bernstein::eval`] (de Casteljau), which encloses the polynomial over the ball.
struct Polygons {
    points: [Bernstein<Ball>; 2],
    velocity: [Bernstein<Ball>; 2],
}

impl Polygons {
    fn new(curve: &Curve<Ball>) -> Result<Polygons, String> {
        let local = |b: &Bernstein<Ball>| {
            Bernstein::new(
                b.control_points().to_vec(),
                (Ball::zero_in(&BITS), Ball::one_in(&BITS)),
            )
            .map_err(|e| e.to_string())
        };
        let points = [local(&curve[0])?, local(&curve[1])?];
        let velocity = [points[0].derivative(), points[1].derivative()];
        Ok(Polygons { points, velocity })
    }

    fn point(&self, u: &Ball) -> Point2 {
        [self.points[0].eval(u), self.points[1].eval(u)]
    }

    fn velocity(&self, u: &Ball) -> Point2 {
        [self.velocity[0].eval(u), self.velocity[1].eval(u)]
    }

    /// A proven enclosure of max_u f(c(u)), f a distance enclosed over a box of the curve.
    fn max_of(&self, f: impl Fn(&CurveBox) -> Ball) -> Result<Ball, String> {
        let g = |u: &Ball| -> Result<Ball, String> {
            Ok(f(&CurveBox {
                at_mid: self.point(&midpoint(u)),
                over: self.point(u),
                velocity: self.velocity(u),
                parameter: u.clone(),
            }))
        };
        let options = SearchOptions {
            // Four printed digits need about 1e-5 of the value.
            tolerance: 0.0,
            relative: 1e-5,
            max_boxes: 100_000,
            bits: BITS,
        };
        let (a, b) = (Float::with_val(BITS, 0), Float::with_val(BITS, 1));
        proven_maximum(g, (&a, &b), &options)
            .map(|m| m.ball())
            .map_err(|e| e.to_string())
    }
}

fn point(x: i64, y: i64) -> Point2 {
    [Ball::from_i64(x, &BITS), Ball::from_i64(y, &BITS)]
}

fn degrees(radians: &Ball) -> Ball {
    radians.clone() * &Ball::from_i64(180, &BITS) / &Ball::pi(&BITS)
}

/// The proven measures of the curve for duration factor `factor` given `data`; `samples`
/// are the curve's points at u = i/(n − 1) (for choosing where to evaluate only).
pub fn prove_turn(
    factor: (i64, i64),
    data: TurnData,
    samples: &[(f64, f64)],
) -> Result<ProvenTurn, String> {
    let curve =
        turn_curve::<Ball>(factor, data, &BITS).ok_or("the Hermite system did not solve")?;
    let c = Polygons::new(&curve)?;
    let (start, end, centre) = (point(0, 0), point(1, 1), point(0, 1));
    let chord = c.max_of(|b| b.distance_to_segment(&start, &end))?;
    // The arc about (0, 1) from angle −90° (direction (0, −1)) to 0° (direction (1, 0)).
    let (down, right) = (point(0, -1), point(1, 0));
    let one = Ball::one_in(&BITS);
    let arc = c.max_of(|b| b.distance_to_quarter_arc(&centre, &one, [&down, &right]))?;
    let about_centre = |u: &Ball| {
        let p = c.point(u);
        [p[0].clone() - &centre[0], p[1].clone() - &centre[1]]
    };
    let winding = degrees(
        &net_turning(about_centre, 64, 24, BITS)
            .map_err(|e| format!("the angle about the centre: {e}"))?,
    );
    // The angle goes from −90° to 0° + k·360°: net = 90° + k·360°; k decided on the enclosure.
    let k = (winding.clone() - &Ball::from_i64(90, &BITS)) / &Ball::from_i64(360, &BITS);
    let k_is_minus_one = k.lower() > -1.5 && k.upper() < -0.5;
    let k_not_minus_one = k.upper() < -1.5 || k.lower() > -0.5;
    if !(k_is_minus_one || k_not_minus_one) {
        return Err("the winding about the arc's centre is not decided".into());
    }
    let net = degrees(
        &net_turning(|u: &Ball| c.velocity(u), 64, 24, BITS)
            .map_err(|e| format!("the tangent: {e}"))?,
    );
    Ok(ProvenTurn {
        data,
        factor,
        chord,
        arc,
        arc_is_hausdorff: k_not_minus_one,
        net_turning_degrees: net,
        recedes_at_least: recedes_at_least(&c, &end, samples)?,
    })
}

/// The sampled pair (i₁ ≤ i₂) with the largest rise of the distance to `end` above the least
/// before it, evaluated again in balls at those parameters: a proven lower bound of the rise
/// over the start's distance (0 when the rise is not proven positive).
fn recedes_at_least(c: &Polygons, end: &Point2, samples: &[(f64, f64)]) -> Result<Float, String> {
    if samples.len() < 2 {
        return Err("fewer than two samples".into());
    }
    let d = |p: &(f64, f64)| ((p.0 - 1.0).powi(2) + (p.1 - 1.0).powi(2)).sqrt();
    let (mut closest, mut best) = (0usize, (0usize, 0usize, 0.0f64));
    for (i, p) in samples.iter().enumerate() {
        if d(p) < d(&samples[closest]) {
            closest = i;
        }
        let rise = d(p) - d(&samples[closest]);
        if rise > best.2 {
            best = (closest, i, rise);
        }
    }
    let at = |i: usize| {
        let u =
            crate::scalar::BigRational::new((i as i64).into(), (samples.len() as i64 - 1).into());
        let p = c.point(&Ball::from_rational(&u, &BITS));
        let v = [p[0].clone() - &end[0], p[1].clone() - &end[1]];
        (v[0].clone() * &v[0] + &(v[1].clone() * &v[1])).sqrt()
    };
    let start_distance = Ball::from_i64(2, &BITS).sqrt();
    let rise = (at(best.1) - &at(best.0)) / &start_distance;
    Ok(rise.lower().max(&Float::with_val(BITS, 0)))
}

/// Every Fig. 3 curve proven, in the order of `turn_metrics` (with accelerations, then
/// velocity only; each for the factors of [`TURN_FACTORS`]); `samples` per curve in that order.
pub fn prove_all(samples: &[Vec<(f64, f64)>]) -> Result<Vec<ProvenTurn>, String> {
    let cases: Vec<(TurnData, (i64, i64))> = [TurnData::WithAcceleration, TurnData::VelocityOnly]
        .iter()
        .flat_map(|&d| TURN_FACTORS.iter().map(move |&f| (d, f)))
        .collect();
    if cases.len() != samples.len() {
        return Err(format!(
            "{} sampled curves for {} cases",
            samples.len(),
            cases.len()
        ));
    }
    cases
        .iter()
        .zip(samples)
        .map(|(&(data, factor), s)| prove_turn(factor, data, s))
        .collect()
}

/// The digits of a proven distance, as the claims and the report print them.
pub fn distance_text(x: &Ball) -> String {
    crate::report::number::ball(x, 4)
}

/// How the arc's Hausdorff distance is printed: the enclosure, or "≥ lower" when only the
/// one-sided maximum is proven (see the module doc).
pub fn arc_text(t: &ProvenTurn) -> String {
    arc_text_in(t, crate::report::number::Notation::Auto)
}

/// [`arc_text`] in the given notation (for a table column).
pub fn arc_text_in(t: &ProvenTurn, notation: crate::report::number::Notation) -> String {
    if t.arc_is_hausdorff {
        crate::report::number::ball_in(&t.arc, 4, notation)
    } else {
        format!(
            "≥ {}",
            crate::report::number::bound(
                t.arc.lower().to_f64_round(rug::float::Round::Down),
                4,
                rug::float::Round::Down
            )
        )
    }
}

/// Whether the curve is proven closer to the chord than to the arc (`Some(true)`), proven
/// farther (`Some(false)`), or neither is proven (`None`).
fn closer_to_chord(t: &ProvenTurn) -> Option<bool> {
    if t.chord.upper() < t.arc.lower() {
        Some(true)
    } else if t.arc_is_hausdorff && t.chord.lower() > t.arc.upper() {
        Some(false)
    } else {
        None
    }
}

/// Whether the curve is proven closer to the arc than to the chord, proven not, or neither.
fn closer_to_arc(t: &ProvenTurn) -> Option<bool> {
    if t.arc_is_hausdorff && t.arc.upper() < t.chord.lower() {
        Some(true)
    } else if t.chord.upper() < t.arc.lower() {
        Some(false)
    } else {
        None
    }
}

/// Whether the tangent's net turning is proven other than 90° by a revolution (a loop), proven
/// 90° (no loop), or not decided.
fn loops(t: &ProvenTurn) -> Option<bool> {
    let net = &t.net_turning_degrees;
    if net.lower() > 270 || net.upper() < -90 {
        Some(true)
    } else if net.lower() > -90 && net.upper() < 270 {
        Some(false)
    } else {
        None
    }
}

/// Whether the curve loops and recedes by more than 1 % of the start's distance (the recession
/// only has a proven lower bound, so "not more" is undecided unless there is no loop).
fn loops_away(t: &ProvenTurn) -> Option<bool> {
    match loops(t)? {
        false => Some(false),
        true if t.recedes_at_least > 0.01 => Some(true),
        true => None,
    }
}

/// The three Fig. 3 claims from the proven measures of both readings of the data (the first
/// three entries with accelerations, the next three velocity only). A claim is `reproduced`
/// when it holds under both readings, `discrepancy` when under neither, `undetermined` when the
/// reading decides it, and `failed` when a comparison is not decided by the enclosures.
pub fn turn_claims(m: &[ProvenTurn]) -> [Outcome; 3] {
    let describe = |t: &ProvenTurn| {
        format!(
            "{}, duration {}×π/2: Hausdorff distance to the chord {} and to the arc {}; net tangent turning {}°; recedes from the terminal point by ≥ {}× the start's distance",
            t.data.label(),
            if t.factor.1 == 1 { t.factor.0.to_string() } else { format!("{}/{}", t.factor.0, t.factor.1) },
            distance_text(&t.chord),
            arc_text(t),
            distance_text(&t.net_turning_degrees),
            crate::report::number::bound(t.recedes_at_least.to_f64_round(rug::float::Round::Down), 4, rug::float::Round::Down)
        )
    };
    let method = "data of a uniform quarter turn (R = 1, V = 1), once with the circle's centripetal accelerations (m = 2) and once \
                  with velocities only (m = 1), since the text states only \"identical start and end speeds but different directions\"; \
                  solved in ball arithmetic at 128 bits (the duration's π enclosed). Each Hausdorff distance is the one-sided maximum \
                  max_t d(c(t), set), which equals it because the curve shares the chord's and the arc's ends (for the arc, when its \
                  winding about the centre is not −1 extra turn, proven; otherwise only a lower bound is claimed and printed ≥), \
                  enclosed by branch and bound; net turnings by a cover of boxes on which the vector is proven to turn by less \
                  than 90°; the recession is a lower bound proven at two parameters";
    let claim = |k: usize,
                 holds: &dyn Fn(&ProvenTurn) -> Option<bool>,
                 what: &dyn Fn(&ProvenTurn) -> String,
                 criterion: &str| {
        let (acc, vel) = (&m[k], &m[k + 3]);
        let verdict = match (holds(acc), holds(vel)) {
            (Some(true), Some(true)) => Verdict::Reproduced,
            (Some(false), Some(false)) => Verdict::Discrepancy,
            (Some(_), Some(_)) => Verdict::Undetermined,
            _ => Verdict::Failed,
        };
        Outcome::new(
            format!("with accelerations: {}; velocity only: {}", what(acc), what(vel)),
            format!("ball:{BITS}"),
            verdict,
            format!(
                "criterion: {criterion}; reproduced when it holds under both readings of the data, undetermined when only one, failed \
                 when an enclosure does not decide it. {method}. {}. {}",
                describe(acc),
                describe(vel)
            ),
        )
    };
    [
        claim(
            0,
            &closer_to_chord,
            &|t| format!("closer to the chord ({}) than to the arc ({})", distance_text(&t.chord), arc_text(t)),
            "Hausdorff distance to the chord < to the arc",
        ),
        claim(
            1,
            &closer_to_arc,
            &|t| format!("closer to the arc ({}) than to the chord ({})", arc_text(t), distance_text(&t.chord)),
            "Hausdorff distance to the arc < to the chord",
        ),
        claim(
            2,
            // The end tangents are fixed, so the net turning is 90° plus whole revolutions: a
            // loop is a net turning other than 90° (any threshold below 360° is the same test).
            &loops_away,
            &|t| {
                format!(
                    "net tangent turning {}° ({}); moves away from the terminal point by ≥ {}× the start's distance",
                    distance_text(&t.net_turning_degrees),
                    match loops(t) { Some(true) => "a loop", Some(false) => "no loop", None => "undecided" },
                    crate::report::number::bound(t.recedes_at_least.to_f64_round(rug::float::Round::Down), 4, rug::float::Round::Down)
                )
            },
            "the sentence, which the figure captions interrupt in the text, reads \"Finally, the dotted line shows the effect of an \
             increased duration, the connecting curve loops away from the terminal point.\" Criterion, fixed before computing: the \
             curve makes a loop (its tangent turns through a full extra revolution: net turning ≠ 90°) and, along it, moves away from \
             the terminal point (its distance to it rises by more than 1 % of the start's distance above the closest it had come)",
        ),
    ]
}
