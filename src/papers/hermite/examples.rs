//! The trajectory examples of Sec. 4: the turn of Fig. 3 and the landing of Fig. 4.
//!
//! The paper does not print the data of these figures; the instances below are ours and
//! documented in the report.
//!
//! **Fig. 3 (turn).** A uniform circular quarter turn of radius R = 1 at speed V = 1:
//! start p = (0, 0), v = (1, 0), a = (0, 1); end p = (1, 1), v = (0, 1), a = (−1, 0)
//! (m = 2, degree 5; the accelerations are the centripetal ones of the turn). The nominal
//! duration is the time the circle takes, T₀ = πR/(2V) = π/2; the figure uses 0.2·T₀, T₀ and
//! 3·T₀. The text's three descriptions become measurable comparisons, fixed before any
//! number was computed:
//! - "almost straight-line": the curve is closer (Hausdorff distance) to the chord from
//!   start to end than to the circular arc;
//! - "approximates a circular turn": it is closer to the arc than to the chord;
//! - "loops away from the terminal point": somewhere its distance from the terminal point
//!   exceeds the start's distance from it.
//!
//! **Fig. 4 (landing).** Runway along +x with its threshold at the origin, altitude z.
//! The aircraft is on the downwind leg abeam the threshold: p = (0, 2000, 300) m,
//! v = (−60, 0, 0) m/s, a = 0. It must cross the threshold p = (0, 0, 0) at the landing speed
//! along the runway, v = (55, 0, 0) m/s, with a = 0, after T = 60 s (a standard-rate turn,
//! 3°/s, turns 180° in one minute). All data are rational, so the check is exact.

use super::super::{Outcome, Verdict};
use crate::algo::hermite::HermiteData;
use crate::numeric::poly::bernstein::power_basis_derivative;
use crate::numeric::poly::Bernstein;
use crate::scalar::{BigRational, Field, Float, Real};

/// Working precision for the Fig. 3 curves (their duration involves π).
const TURN_BITS: u32 = 128;
/// Parameter samples per curve for the Fig. 3 and Fig. 4 measurements.
const SAMPLES: usize = 2001;

/// A planar or spatial curve: one Bernstein polynomial per coordinate.
pub type Curve<T> = Vec<Bernstein<T>>;

/// The duration factors of Fig. 3.
pub const TURN_FACTORS: [(i64, i64); 3] = [(1, 5), (1, 1), (3, 1)];

/// Which boundary data a Fig. 3 curve is given. The text says only "identical start and end
/// speeds but different directions", so both readings are computed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TurnData {
    /// Positions, velocities and the centripetal accelerations of the circle (m = 2, quintic).
    WithAcceleration,
    /// Positions and velocities only (m = 1, cubic).
    VelocityOnly,
}

impl TurnData {
    /// How the report names the reading.
    pub fn label(self) -> &'static str {
        match self {
            TurnData::WithAcceleration => "velocity and acceleration (m = 2)",
            TurnData::VelocityOnly => "velocity only (m = 1)",
        }
    }
}

/// Measurements of one Fig. 3 curve (from samples; see module doc).
pub struct TurnMetrics {
    /// The boundary data the curve is given.
    pub data: TurnData,
    pub factor: (i64, i64),
    pub duration: f64,
    pub hausdorff_chord: f64,
    pub hausdorff_arc: f64,
    pub max_radial_deviation: f64,
    /// max distance from the terminal point divided by the start's distance from it.
    pub farthest_from_end: f64,
    /// How far the curve moves away from the terminal point along some stretch: the largest
    /// rise of its distance to it above the smallest distance reached before, over the
    /// start's distance.
    pub recedes: f64,
    pub turning_degrees: f64,
    /// The signed (net) turning of the tangent, in degrees: 90 for a quarter turn that does not
    /// wind back.
    pub net_turning_degrees: f64,
    pub max_speed: f64,
    pub samples: Vec<(f64, f64)>,
}

/// Solve one coordinate's Hermite problem (all data valid by construction).
fn solve_coordinate<T: Field>(start: Vec<T>, end: Vec<T>, t0: T, t1: T) -> Option<Bernstein<T>> {
    HermiteData::new(start, end, t0, t1)
        .and_then(|d| d.solve())
        .ok()
}

fn to_f64_curve<T: Field>(c: &Curve<T>) -> Curve<f64> {
    c.iter()
        .map(|b| {
            Bernstein::new(
                b.control_points().iter().map(Field::to_f64).collect(),
                b.t0().to_f64(),
                b.t1().to_f64(),
            )
            .expect("the solved curve's interval, rounded to f64")
        })
        .collect()
}

fn sample(c: &Curve<f64>, n: usize) -> Vec<Vec<f64>> {
    let (t0, t1) = (*c[0].t0(), *c[0].t1());
    (0..n)
        .map(|i| {
            let t = t0 + (t1 - t0) * i as f64 / (n - 1) as f64;
            c.iter().map(|b| b.eval(&t)).collect()
        })
        .collect()
}

fn dist(a: (f64, f64), b: (f64, f64)) -> f64 {
    ((a.0 - b.0).powi(2) + (a.1 - b.1).powi(2)).sqrt()
}

fn dist_to_segment(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let s = (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / (dx * dx + dy * dy)).clamp(0.0, 1.0);
    dist(p, (a.0 + s * dx, a.1 + s * dy))
}

/// Distance to the quarter arc of the unit circle about (0, 1) from (0, 0) to (1, 1).
fn dist_to_arc(p: (f64, f64)) -> f64 {
    let (x, y) = (p.0, p.1 - 1.0);
    // The arc spans the angles −90°…0° about the centre: x ≥ 0 and y ≤ 0.
    if x >= 0.0 && y <= 0.0 {
        ((x * x + y * y).sqrt() - 1.0).abs()
    } else {
        dist(p, (0.0, 0.0)).min(dist(p, (1.0, 1.0)))
    }
}

/// Symmetric Hausdorff distance between the sampled curve and a reference set given by its
/// distance function and its own samples.
fn hausdorff(
    curve: &[(f64, f64)],
    dist_to_ref: impl Fn((f64, f64)) -> f64,
    reference: &[(f64, f64)],
) -> f64 {
    let forward = curve.iter().map(|&p| dist_to_ref(p)).fold(0.0, f64::max);
    let backward = reference
        .iter()
        .map(|&r| {
            curve
                .iter()
                .map(|&p| dist(p, r))
                .fold(f64::INFINITY, f64::min)
        })
        .fold(0.0, f64::max);
    forward.max(backward)
}

/// Total absolute and net (signed) turning of the tangent along the samples, in degrees
/// (MPFR atan2, so the result does not depend on the platform's libm).
fn turning_degrees(velocities: &[(f64, f64)]) -> (f64, f64) {
    let mut total = Float::with_val(64, 0);
    let mut net = Float::with_val(64, 0);
    for w in velocities.windows(2) {
        let (a, b) = (w[0], w[1]);
        let cross = Float::with_val(64, a.0 * b.1 - a.1 * b.0);
        let dot = Float::with_val(64, a.0 * b.0 + a.1 * b.1);
        let angle = cross.atan2(&dot);
        net += &angle;
        total += angle.abs();
    }
    let degrees = |x: Float| (x * 180u32 / Float::pi(&64)).to_f64();
    (degrees(total), degrees(net))
}

/// The Fig. 3 curve for duration factor num/den of the nominal π/2, in MPFR, given `data`.
fn turn_curve(factor: (i64, i64), data: TurnData) -> Option<Curve<Float>> {
    let bits = TURN_BITS;
    let i = |v: i64| Float::from_i64(v, &bits);
    let duration = Float::pi(&bits) / 2u32 * Float::from_ratio(factor.0, factor.1, &bits);
    // (position, velocity, acceleration) at both ends, per coordinate, of the quarter turn.
    let ends = |start: [i64; 3], end: [i64; 3]| {
        let order = if data == TurnData::WithAcceleration {
            3
        } else {
            2
        };
        (
            start[..order].iter().map(|&v| i(v)).collect::<Vec<_>>(),
            end[..order].iter().map(|&v| i(v)).collect::<Vec<_>>(),
        )
    };
    let (xs, xe) = ends([0, 1, 0], [1, 0, -1]);
    let (ys, ye) = ends([0, 0, 1], [1, 1, 0]);
    let x = solve_coordinate(xs, xe, i(0), duration.clone())?;
    let y = solve_coordinate(ys, ye, i(0), duration)?;
    Some(vec![x, y])
}

/// Solve and measure the three Fig. 3 curves for each reading of the data: first with
/// accelerations, then velocity only.
pub fn turn_metrics() -> Option<Vec<TurnMetrics>> {
    let mut all = turn_metrics_for(TurnData::WithAcceleration)?;
    all.extend(turn_metrics_for(TurnData::VelocityOnly)?);
    Some(all)
}

/// The three Fig. 3 curves given `data`.
fn turn_metrics_for(data: TurnData) -> Option<Vec<TurnMetrics>> {
    let chord_ref: Vec<(f64, f64)> = (0..401)
        .map(|i| (i as f64 / 400.0, i as f64 / 400.0))
        .collect();
    let arc_ref: Vec<(f64, f64)> = (0..401)
        .map(|i| {
            // Points of the arc from MPFR sin/cos (platform independent).
            let angle = Float::pi(&64) / 2u32 * Float::with_val(64, i) / 400u32;
            let (s, c) = Real::sin_cos(&angle);
            (s.to_f64(), 1.0 - c.to_f64())
        })
        .collect();
    TURN_FACTORS
        .iter()
        .map(|&factor| {
            let exact = turn_curve(factor, data)?;
            let c = to_f64_curve(&exact);
            let pts: Vec<(f64, f64)> = sample(&c, SAMPLES)
                .into_iter()
                .map(|v| (v[0], v[1]))
                .collect();
            let vel_curve: Curve<f64> = c.iter().map(|b| b.derivative()).collect();
            let vel: Vec<(f64, f64)> = sample(&vel_curve, SAMPLES)
                .into_iter()
                .map(|v| (v[0], v[1]))
                .collect();
            let end = (1.0, 1.0);
            let start_dist = dist((0.0, 0.0), end);
            let (turning_degrees, net_turning_degrees) = turning_degrees(&vel);
            Some(TurnMetrics {
                data,
                factor,
                duration: exact[0].duration().to_f64(),
                hausdorff_chord: hausdorff(
                    &pts,
                    |p| dist_to_segment(p, (0.0, 0.0), end),
                    &chord_ref,
                ),
                hausdorff_arc: hausdorff(&pts, dist_to_arc, &arc_ref),
                max_radial_deviation: pts
                    .iter()
                    .map(|&p| (dist(p, (0.0, 1.0)) - 1.0).abs())
                    .fold(0.0, f64::max),
                farthest_from_end: pts.iter().map(|&p| dist(p, end)).fold(0.0, f64::max)
                    / start_dist,
                recedes: pts
                    .iter()
                    .scan(f64::INFINITY, |closest, &p| {
                        let d = dist(p, end);
                        *closest = closest.min(d);
                        Some(d - *closest)
                    })
                    .fold(0.0, f64::max)
                    / start_dist,
                turning_degrees,
                net_turning_degrees,
                max_speed: vel.iter().map(|&v| dist(v, (0.0, 0.0))).fold(0.0, f64::max),
                samples: pts,
            })
        })
        .collect()
}

/// Four significant digits of a sampled measurement.
pub fn fmt4(x: f64) -> String {
    crate::report::number::sig(x, 4)
}

/// The three Fig. 3 claims from the measurements of both readings of the data (the first
/// three entries of `m` with accelerations, the next three velocity only). A claim is
/// `reproduced` when it holds under both readings, `discrepancy` when under neither, and
/// `undetermined` when the reading decides it: the paper gives speeds and directions only.
pub fn turn_claims(m: &[TurnMetrics]) -> [Outcome; 3] {
    let describe = |t: &TurnMetrics| {
        format!(
            "{}, duration {}×π/2: Hausdorff distance to the chord {} and to the arc {}; max radial deviation from the circle {}; \
             farthest distance from the terminal point {}× the start's; tangent turns {}° in total, {}° net; peak speed {}",
            t.data.label(),
            if t.factor.1 == 1 { t.factor.0.to_string() } else { format!("{}/{}", t.factor.0, t.factor.1) },
            fmt4(t.hausdorff_chord),
            fmt4(t.hausdorff_arc),
            fmt4(t.max_radial_deviation),
            fmt4(t.farthest_from_end),
            fmt4(t.turning_degrees),
            fmt4(t.net_turning_degrees),
            fmt4(t.max_speed)
        )
    };
    let method = "data of a uniform quarter turn (R = 1, V = 1), once with the circle's centripetal accelerations (m = 2) and once \
                  with velocities only (m = 1), since the text states only \"identical start and end speeds but different directions\"; \
                  solved in MPFR-128 and sampled at 2001 parameters; Hausdorff distances against the sampled chord and arc (401 points each)";
    let claim = |k: usize,
                 holds: &dyn Fn(&TurnMetrics) -> bool,
                 what: &dyn Fn(&TurnMetrics) -> String,
                 criterion: &str| {
        let (acc, vel) = (&m[k], &m[k + 3]);
        let verdict = match (holds(acc), holds(vel)) {
            (true, true) => Verdict::Reproduced,
            (false, false) => Verdict::Discrepancy,
            _ => Verdict::Undetermined,
        };
        Outcome::new(
            format!("with accelerations: {}; velocity only: {}", what(acc), what(vel)),
            "mpfr:128",
            verdict,
            format!(
                "criterion: {criterion}; reproduced when it holds under both readings of the data, undetermined when only one. {method}. {}. {}",
                describe(acc),
                describe(vel)
            ),
        )
    };
    [
        claim(
            0,
            &|t| t.hausdorff_chord < t.hausdorff_arc,
            &|t| format!("closer to the chord ({}) than to the arc ({})", fmt4(t.hausdorff_chord), fmt4(t.hausdorff_arc)),
            "Hausdorff distance to the chord < to the arc",
        ),
        claim(
            1,
            &|t| t.hausdorff_arc < t.hausdorff_chord,
            &|t| format!("closer to the arc ({}) than to the chord ({})", fmt4(t.hausdorff_arc), fmt4(t.hausdorff_chord)),
            "Hausdorff distance to the arc < to the chord",
        ),
        claim(
            2,
            // The end tangents are fixed, so the net turning is 90° plus whole revolutions: a
            // loop is a net turning other than 90° (any threshold below 360° is the same test).
            &|t| (t.net_turning_degrees - 90.0).abs() > 180.0 && t.recedes > 0.01,
            &|t| {
                format!(
                    "net tangent turning {}° ({}); moves away from the terminal point by {}× the start's distance",
                    fmt4(t.net_turning_degrees),
                    if (t.net_turning_degrees - 90.0).abs() > 180.0 { "a loop" } else { "no loop" },
                    fmt4(t.recedes)
                )
            },
            "the sentence, which the figure captions interrupt in the text, reads \"Finally, the dotted line shows the effect of an \
             increased duration, the connecting curve loops away from the terminal point.\" Criterion, fixed before computing: the \
             curve makes a loop (its tangent turns through a full extra revolution: net turning ≠ 90°) and, along it, moves away from \
             the terminal point (its distance to it rises by more than 1 % of the start's distance above the closest it had come)",
        ),
    ]
}

/// The landing instance of Fig. 4 (exact), one polynomial per coordinate x, y, z.
pub fn landing_data() -> [HermiteData<BigRational>; 3] {
    let q = |v: i64| BigRational::from_integer(v.into());
    let (t0, t1) = (q(0), q(60));
    let mk = |start: [i64; 3], end: [i64; 3]| {
        HermiteData::new_unchecked(
            start.into_iter().map(q).collect(),
            end.into_iter().map(q).collect(),
            t0.clone(),
            t1.clone(),
        )
    };
    [
        mk([0, -60, 0], [0, 55, 0]),
        mk([2000, 0, 0], [0, 0, 0]),
        mk([300, 0, 0], [0, 0, 0]),
    ]
}

/// Measurements of the landing trajectory.
pub struct LandingMetrics {
    pub curve: Curve<BigRational>,
    pub conditions: usize,
    pub violated: usize,
    pub max_speed: f64,
    pub min_speed: f64,
    pub max_accel_g: f64,
    pub min_altitude: f64,
    pub max_lateral_overshoot: f64,
    pub samples: Vec<Vec<f64>>,
}

/// Solve the landing exactly and measure it.
pub fn landing() -> Option<LandingMetrics> {
    let data = landing_data();
    let curve: Curve<BigRational> = data.iter().map(|d| d.solve().ok()).collect::<Option<_>>()?;
    let mut violated = 0;
    let mut conditions = 0;
    for (d, b) in data.iter().zip(&curve) {
        let a = b.to_power_basis();
        for j in 0..=d.derivatives() {
            let zero = BigRational::from_integer(0.into());
            let one = BigRational::from_integer(1.into());
            conditions += 2;
            violated +=
                (power_basis_derivative(&a, j, &zero, &b.duration()) != d.start()[j]) as usize;
            violated += (power_basis_derivative(&a, j, &one, &b.duration()) != d.end()[j]) as usize;
        }
    }
    let c = to_f64_curve(&curve);
    let vel: Curve<f64> = c.iter().map(|b| b.derivative()).collect();
    let acc: Curve<f64> = vel.iter().map(|b| b.derivative()).collect();
    let norm = |v: &Vec<f64>| v.iter().map(|x| x * x).sum::<f64>().sqrt();
    let speeds: Vec<f64> = sample(&vel, 601).iter().map(norm).collect();
    let accels: Vec<f64> = sample(&acc, 601).iter().map(norm).collect();
    let pts = sample(&c, 601);
    Some(LandingMetrics {
        conditions,
        violated,
        max_speed: speeds.iter().copied().fold(0.0, f64::max),
        min_speed: speeds.iter().copied().fold(f64::INFINITY, f64::min),
        max_accel_g: accels.iter().copied().fold(0.0, f64::max) / 9.80665,
        min_altitude: pts.iter().map(|p| p[2]).fold(f64::INFINITY, f64::min),
        max_lateral_overshoot: pts.iter().map(|p| -p[1]).fold(0.0, f64::max),
        samples: pts,
        curve,
    })
}

/// The Fig. 4 claim.
pub fn landing_claim(l: &LandingMetrics) -> Outcome {
    Outcome::new(
        format!("{} of {} conditions met exactly", l.conditions - l.violated, l.conditions),
        "rational",
        Verdict::holds(l.violated == 0),
        format!(
            "start (0, 2000, 300) m at (−60, 0, 0) m/s, zero acceleration; end at the threshold (0, 0, 0) at (55, 0, 0) m/s, \
             zero acceleration; T = 60 s; m = 2, degree 5 per coordinate, solved exactly; position, velocity and acceleration \
             at both ends re-derived from the power basis. Sampled every 0.1 s: speed {}…{} m/s, peak acceleration {} g, \
             lowest altitude {} m, largest overshoot beyond the runway centre line {} m",
            fmt4(l.min_speed),
            fmt4(l.max_speed),
            fmt4(l.max_accel_g),
            fmt4(l.min_altitude),
            fmt4(l.max_lateral_overshoot)
        ),
    )
}
