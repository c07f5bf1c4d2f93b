//! Remarks of paper 004 judged on both of its worked examples, Table II (plane data) and the
//! robot of Tables IV–VII, each with the measure declared before computing:
//! - Sec. 1: chord length "merely ensures that approximate constant speed is maintained" —
//!   the proven range of the speed ‖θ′(t)‖ of the chord-length natural spline, relative to
//!   the chord speed L (the total chord length: on every interval |Δθᵢ|/hᵢ = L by Eq. 5);
//! - Sec. 2, after Corollary 3: for K > 1 components the interpolants "do not satisfy
//!   precisely the properties listed in Corollary 3" — overshoots (i) and third-derivative
//!   jumps at non-extreme knots (ii) under the minimizers of Table II;
//! - Sec. 3, example 3: t^AP "can reduce significantly component function accelerations"
//!   (Table VII) and "tends to align local extrema in the data with local extrema in the
//!   cubic spline interpolant" (Table VI, all six axes).
//!
//! - Sec. 1 (i): minimizers' curves "closer to the interpolating polygon" — the proven largest
//!   distance of the Table II curve from its polygon.
//!
//! Every number is proven: speeds by ball branch and bound ([`speed_range`]), extrema and
//! overshoots from the roots of θ′ in balls, Table VII's maxima exactly.

use super::super::{Outcome, Verdict};
use super::curve_distances::{max_distance_from_polygon, speed_range};
use super::overshoot::{measure, printed_knots, FIG9_AXIS};
use super::plane::{components, jump_sums, plane_splines};
use super::proven_splines::{balls, decided, ProvenKnots, BITS};
use super::robot::{axes, NAMES};
use crate::report::number::{ball, sig};
use crate::scalar::ball::Ball;
use crate::scalar::{BigRational, Field, Real};

/// The total chord length L = Σᵢ ‖zᵢ − zᵢ₋₁‖ of the points whose coordinates are `components`.
fn chord_total(components: &[Vec<Ball>]) -> Ball {
    let zero = Ball::zero_in(&BITS);
    let n = components.first().map_or(0, Vec::len);
    (1..n).fold(zero.clone(), |total, i| {
        let squared = components.iter().fold(zero.clone(), |a, c| {
            let d = c[i].clone() - &c[i - 1];
            a + &(d.clone() * &d)
        });
        total + &squared.sqrt()
    })
}

/// (min, max) of ‖θ′(t)‖ / L over [0, 1] for the natural spline of `data` on chord `knots`.
fn relative_speed_range(
    knots: &ProvenKnots,
    data: &[Vec<BigRational>],
) -> Result<(Ball, Ball), String> {
    let components: Vec<Vec<Ball>> = data.iter().map(|z| balls(z)).collect();
    let splines = components
        .iter()
        .map(|z| knots.spline(z))
        .collect::<Result<Vec<_>, _>>()?;
    let total = chord_total(&components);
    let (min, max) = speed_range(&splines)?;
    Ok((min / &total, max / &total))
}

/// Sec. 1: "it merely ensures that approximate constant speed is maintained", on the
/// chord-length splines of Table II and of the robot data (Table IV).
pub fn chord_constant_speed(
    plane: &Result<Vec<ProvenKnots>, String>,
    robot_chord: &ProvenKnots,
) -> Outcome {
    let scalar = "ball:256";
    let computed = decided(|| {
        let plane = plane.as_ref().map_err(Clone::clone)?;
        let plane_chord = plane
            .first()
            .ok_or("no chord-length parametrization of Table II")?;
        let examples = [
            ("Table II", plane_chord, components::<BigRational>(&())),
            ("robot (Table IV)", robot_chord, axes()),
        ];
        let (low, high) = (Ball::from_ratio(3, 4, &BITS), Ball::from_ratio(5, 4, &BITS));
        examples
            .into_iter()
            .map(|(name, knots, data)| {
                let (min, max) = relative_speed_range(knots, &data)?;
                let within = min >= low && max <= high;
                Ok((name, min, max, within))
            })
            .collect::<Result<Vec<_>, String>>()
    });
    let rows = match computed {
        Ok(rows) => rows,
        Err(e) => return Outcome::failed(scalar, e),
    };
    let listing: Vec<String> = rows
        .iter()
        .map(|(name, min, max, within)| {
            format!(
                "{name}: ‖θ′(t)‖/L from {} to {} ({} ±25 %)",
                ball(min, 4),
                ball(max, 4),
                if *within { "within" } else { "outside" }
            )
        })
        .collect();
    Outcome::new(
        listing.join("; "),
        scalar,
        if rows.iter().all(|r| r.3) { Verdict::Reproduced } else { Verdict::Undetermined },
        "the natural cubic spline of every component on the chord-length knots (Eq. 5, proven in balls at 256 bits), its speed \
         ‖θ′(t)‖ over all t ∈ [0, 1] enclosed by ball branch and bound (mean-value form of the squared speed; nothing sampled) and \
         divided by the total chord length L, the speed chord length gives each interval (|Δθᵢ|/hᵢ = L). The sentence gives no \
         measure; declared before computing (the independent reading's threshold): 'approximately constant' holds when the speed \
         stays within ±25 % of L on all of [0, 1]. Both of the paper's examples are used, the robot data being the application \
         the sentence names; reproduced when both stay within, otherwise undetermined (clause 5: a qualitative statement that \
         misses its declared threshold). On every interval the mean of ‖θ′‖ is at least L by construction, so the chord speed \
         per interval is no test (clause 2)",
    )
}

/// Sec. 2, after Corollary 3: for the plane data of Table II, the interpolants on the
/// minimizing parametrizations "do not satisfy precisely the properties listed in Corollary 3".
pub fn cor3_fails_k2(plane: &Result<Vec<ProvenKnots>, String>) -> Outcome {
    let scalar = "ball:256";
    let computed = decided(|| {
        let plane = plane.as_ref().map_err(Clone::clone)?;
        let data = components::<BigRational>(&());
        plane
            .iter()
            .skip(1)
            .map(|k| {
                let overshooting: usize = data
                    .iter()
                    .map(|z| measure(k, z).map(|r| r.overshooting))
                    .sum::<Result<usize, String>>()?;
                let jumps = jump_sums(k)?;
                let jumping = jumps.iter().filter(|j| j.lower() > 0).count();
                Ok((k.name, overshooting, jumps, jumping))
            })
            .collect::<Result<Vec<_>, String>>()
    });
    let rows = match computed {
        Ok(rows) if !rows.is_empty() => rows,
        Ok(_) => return Outcome::failed(scalar, "no minimizing parametrization of Table II"),
        Err(e) => return Outcome::failed(scalar, e),
    };
    let fails = rows
        .iter()
        .all(|(_, over, _, jumping)| *over > 0 || *jumping > 0);
    let listing: Vec<String> = rows
        .iter()
        .map(|(name, over, jumps, _)| {
            format!(
                "{name}: {over} overshooting intervals (against (i)); third-derivative jumps at non-extreme knots x {}, y {} (against (ii))",
                ball(&jumps[0], 4),
                ball(&jumps[1], 4)
            )
        })
        .collect();
    Outcome::new(
        listing.join("; "),
        scalar,
        if fails { Verdict::Reproduced } else { Verdict::Discrepancy },
        "x and y of Table II on our proven minimizers t^EX and t^AP (marin.fig3_5.second_derivatives): property (i), no \
         overshoots, from the roots of θ′ per interval (as marin.table2.overshoots_no_problem); property (ii), breakpoints only at \
         the extremes, from the jump of θ‴ at every interior knot that is not a relative extreme of the exact data (as \
         marin.sec2.third_derivative_jumps), a jump counting when its enclosure is above 0. Reproduced when, under each minimizer, \
         (i) or (ii) fails for some component; every comparison decided on disjoint enclosures",
    )
}

/// Sec. 3, example 3: "the minimizing parametrization can reduce significantly component
/// function accelerations compared to those obtained with the other two parametrizations",
/// on the maxima of Table VII computed exactly on the printed knots (`from_printed`, per
/// parametrization in the order of [`NAMES`]).
pub fn ap_lowest(from_printed: &[Vec<BigRational>]) -> Outcome {
    let scalar = "rational";
    let [cl, wc, ap] = match from_printed {
        [cl, wc, ap] if [cl, wc, ap].iter().all(|c| c.len() == 6) => [cl, wc, ap],
        _ => {
            return Outcome::failed(
                scalar,
                "Table VII could not be computed (marin.table7.max_acceleration)",
            )
        }
    };
    let two = BigRational::from_integer(2.into());
    let below_both = (0..6).filter(|&j| ap[j] < cl[j] && ap[j] < wc[j]).count();
    let halved = (0..6)
        .filter(|&j| cl[j] >= two.clone() * &ap[j] && wc[j] >= two.clone() * &ap[j])
        .count();
    let ratio = |a: &BigRational, b: &BigRational| sig((a.clone() / b).to_f64(), 3);
    let ratios: Vec<String> = (0..6)
        .map(|j| {
            format!(
                "axis {}: {}× / {}×",
                j + 1,
                ratio(&cl[j], &ap[j]),
                ratio(&wc[j], &ap[j])
            )
        })
        .collect();
    Outcome::new(
        format!(
            "max |θ″| of {} is below those of {} and {} on {below_both} of 6 axes, and at most half of both on {halved}; ratios {}/{} to {}: {}",
            NAMES[2],
            NAMES[0],
            NAMES[1],
            NAMES[0],
            NAMES[1],
            NAMES[2],
            ratios.join("; ")
        ),
        scalar,
        if below_both == 6 && halved >= 1 { Verdict::Reproduced } else { Verdict::Discrepancy },
        "the maxima of Table VII computed exactly on the printed Table VI knots (marin.table7.max_acceleration). Declared before \
         computing: 'reduce … compared to the other two' holds when t^AP's maximum is below both others on every axis (the \
         independent reading's criterion), and 'can … significantly' when on at least one axis it is at most half of both (the \
         factor the paper's next sentence uses); exact comparisons",
    )
}

/// Sec. 3, example 3: "the minimizing parametrization tends to align local extrema in the
/// data with local extrema in the cubic spline interpolant of the data", on all six axes.
pub fn align_extrema() -> Outcome {
    let scalar = "ball:256";
    let data = axes();
    let computed = decided(|| {
        NAMES
            .iter()
            .enumerate()
            .map(|(c, name)| {
                let knots = printed_knots(name, c)?;
                data.iter()
                    .map(|z| {
                        let row = measure(&knots, z)?;
                        Ok(row.extrema_between_data.saturating_sub(row.data_extrema))
                    })
                    .collect::<Result<Vec<usize>, String>>()
            })
            .collect::<Result<Vec<_>, String>>()
    });
    let excess = match computed {
        Ok(e) => e,
        Err(e) => return Outcome::failed(scalar, e),
    };
    let totals: Vec<usize> = excess.iter().map(|e| e.iter().sum()).collect();
    let illustration =
        excess[2][FIG9_AXIS] == 0 && excess[0][FIG9_AXIS] > 0 && excess[1][FIG9_AXIS] > 0;
    let all_axes = totals[2] < totals[0] && totals[2] < totals[1];
    let listing: Vec<String> = NAMES
        .iter()
        .zip(&excess)
        .zip(&totals)
        .map(|((name, e), total)| {
            format!("{name}: {total} unaligned spline extrema (axes 1–6: {e:?})")
        })
        .collect();
    Outcome::new(
        listing.join("; "),
        scalar,
        match (illustration, all_axes) {
            (true, true) => Verdict::Reproduced,
            (false, false) => Verdict::Discrepancy,
            _ => Verdict::Undetermined,
        },
        format!(
            "every axis of Table IV interpolated by the natural spline on each printed Table VI column; unaligned extrema are the \
             spline's local extrema strictly between data points beyond one per interior data extremum (the measure of \
             marin.fig9.oscillations: roots of θ′ in balls at 256 bits, data extrema exact). Two readings of 'tends to align' \
             (clause 5): (a) on axis #3, the paper's illustration (Fig. 9), t^AP leaves none while t^CL and t^WC leave some: {}; \
             (b) over the six axes, t^AP leaves fewer than each of the other two: {}",
            if illustration { "holds" } else { "fails" },
            if all_axes { "holds" } else { "fails" }
        ),
    )
}

/// Sec. 1 (i): "we anticipate that parametrizations which minimize G will also provide
/// interpolating curves θ(t) which are closer to the interpolating polygon", on the paper's
/// printed plane data (Table II); the corner of Fig. 6, whose data the paper does not print,
/// is `marin.fig6.corner`.
pub fn closer_to_polygon(plane: &Result<Vec<ProvenKnots>, String>) -> Outcome {
    let scalar = "ball:256";
    let computed = (|| {
        let curves = plane_splines(plane)?;
        let names: Vec<&'static str> = plane
            .as_ref()
            .map_err(Clone::clone)?
            .iter()
            .map(|k| k.name)
            .collect();
        let z = components::<Ball>(&BITS);
        let vertices: Vec<[Ball; 2]> = (0..z[0].len())
            .map(|i| [z[0][i].clone(), z[1][i].clone()])
            .collect();
        let distances = curves
            .iter()
            .map(|c| max_distance_from_polygon(c, &vertices).map(|m| m.ball()))
            .collect::<Result<Vec<_>, String>>()?;
        let (closer, farther) = decided(|| {
            let chord = &distances[0];
            Ok((
                distances[1..].iter().filter(|d| *d < chord).count(),
                distances[1..].iter().filter(|d| *d > chord).count(),
            ))
        })?;
        Ok::<_, String>((names, distances, closer, farther))
    })();
    let (names, distances, closer, farther) = match computed {
        Ok(c) => c,
        Err(e) => return Outcome::failed(scalar, e),
    };
    let listing: Vec<String> = names
        .iter()
        .zip(&distances)
        .map(|(n, d)| format!("{n}: {}", ball(d, 4)))
        .collect();
    Outcome::new(
        format!(
            "largest distance of the Table II spline curve from the interpolating polygon: {}; {closer} of {} minimizers closer, {farther} farther",
            listing.join("; "),
            distances.len() - 1
        ),
        scalar,
        if closer == distances.len() - 1 { Verdict::Reproduced } else { Verdict::Undetermined },
        "the plane curve (x(t), y(t)) of the natural splines on our proven t^CL, t^EX and t^AP (marin.fig3_5.second_derivatives), \
         its largest distance from the polygon through the Table II points over all t ∈ [0, 1] enclosed by ball branch and bound \
         (nothing sampled). Declared before computing: 'closer' holds when each minimizer's curve has a smaller largest distance \
         than chord length's. The sentence is an anticipation the paper supports with the corner of Fig. 6, whose data it does not \
         print (our own corner, marin.fig6.corner, comes closer); on the only plane data it prints the minimizers' curves are \
         farther, so the paper gives too little to decide: reproduced when they are closer here, otherwise undetermined (clause 5)",
    )
}
