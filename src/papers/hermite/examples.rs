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
//! - "loops away from the terminal point": the tangent turns through a full extra
//!   revolution and the distance to the terminal point rises by more than 1 % of the start's
//!   above the closest it had come.
//!
//! The claims rest on the proven measures of `turn_proofs` (the curves in balls); the samples
//! here draw the figure and the report's sampled columns.
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

/// Sampled measurements of one Fig. 3 curve, for the figure and the report's sampled columns
/// (the claims rest on `turn_proofs`' proven measures).
pub struct TurnMetrics {
    /// The boundary data the curve is given.
    pub data: TurnData,
    pub factor: (i64, i64),
    pub duration: f64,
    pub max_radial_deviation: f64,
    /// max distance from the terminal point divided by the start's distance from it.
    pub farthest_from_end: f64,
    pub turning_degrees: f64,
    pub max_speed: f64,
    pub samples: Vec<(f64, f64)>,
}

/// Solve one coordinate's Hermite problem (all data valid by construction).
fn solve_coordinate<T: Field>(start: Vec<T>, end: Vec<T>, t0: T, t1: T) -> Option<Bernstein<T>> {
    HermiteData::new(start, end, (t0, t1))
        .and_then(|d| d.solve())
        .ok()
}

fn to_f64_curve<T: Field>(c: &Curve<T>) -> Curve<f64> {
    c.iter()
        .map(|b| {
            Bernstein::new(
                b.control_points().iter().map(Field::to_f64).collect(),
                (b.t0().to_f64(), b.t1().to_f64()),
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

/// Total absolute turning of the tangent along the samples, in degrees (MPFR atan2, so the
/// result does not depend on the platform's libm).
fn total_turning_degrees(velocities: &[(f64, f64)]) -> f64 {
    let mut total = Float::with_val(64, 0);
    for w in velocities.windows(2) {
        let (a, b) = (w[0], w[1]);
        let cross = Float::with_val(64, a.0 * b.1 - a.1 * b.0);
        let dot = Float::with_val(64, a.0 * b.0 + a.1 * b.1);
        total += cross.atan2(&dot).abs();
    }
    (total * 180u32 / Float::pi(&64)).to_f64()
}

/// The Fig. 3 curve for duration factor num/den of the nominal π/2, given `data`, over any
/// real scalar (MPFR for the sampled figure, balls for the proofs of `turn_proofs`).
pub fn turn_curve<T: Real>(factor: (i64, i64), data: TurnData, ctx: &T::Ctx) -> Option<Curve<T>> {
    let i = |v: i64| T::from_i64(v, ctx);
    let duration = T::pi(ctx) / &T::from_i64(2, ctx) * &T::from_ratio(factor.0, factor.1, ctx);
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
    TURN_FACTORS
        .iter()
        .map(|&factor| {
            let exact = turn_curve::<Float>(factor, data, &TURN_BITS)?;
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
            let turning_degrees = total_turning_degrees(&vel);
            Some(TurnMetrics {
                data,
                factor,
                duration: exact[0].duration().to_f64(),
                max_radial_deviation: pts
                    .iter()
                    .map(|&p| (dist(p, (0.0, 1.0)) - 1.0).abs())
                    .fold(0.0, f64::max),
                farthest_from_end: pts.iter().map(|&p| dist(p, end)).fold(0.0, f64::max)
                    / start_dist,
                turning_degrees,
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
