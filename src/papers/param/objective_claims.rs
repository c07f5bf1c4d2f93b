//! Claims of Sec. 3 on the objective G itself: Eq. 31 is the bending energy of the natural
//! spline, and gradient projection (Eq. 30) never increases G. Both checked exactly in
//! rationals.

use super::super::{Outcome, Verdict};
use super::data::TABLE3;
use super::num;
use super::plane::components;
use crate::algo::param::descent::descend;
use crate::algo::param::natural::NaturalCubicSpline;
use crate::algo::param::objective::{chord_length_spacing, objective, Objective};
use crate::scalar::{BigRational, Field};

type Q = BigRational;

/// Eq. 31: G(h) = Σ_l α_l⁻² zᵀQᵀM⁻¹Qz equals Σ_l α_l⁻² ∫θ_l''², exactly.
pub fn eq31_is_bending_energy() -> Outcome {
    let z = components::<Q>(&());
    let t: Vec<Q> = TABLE3.iter().map(|r| num(r.0)).collect();
    let h: Vec<Q> = t.windows(2).map(|w| w[1].clone() - &w[0]).collect();
    let alpha = [Q::from_integer(1.into()), Q::from_integer(2.into())];
    let g = objective(&h, &z, &alpha, Objective::Exact);
    let energy: Option<Q> = z
        .iter()
        .zip(&alpha)
        .map(|(zl, al)| {
            let s = NaturalCubicSpline::new(t.clone(), zl.clone()).ok()?;
            Some(s.bending_energy() / (al.clone() * al))
        })
        .sum();
    let (Ok(g), Some(energy)) = (g, energy) else {
        return Outcome::new("", "rational", Verdict::Failed, "the splines did not solve");
    };
    Outcome::new(
        format!("equal exactly: G = Σ α⁻² ∫θ″² = {:.10}", g.to_f64()),
        "rational",
        Verdict::holds(g == energy),
        "Table II data on the printed chord-length knots t^C1 of Table III (exact rationals), weights α = (1, 2): Eq. 31 as printed (Q and \
         M of Sec. 3, M solved exactly) against ∫θ″² of each natural cubic spline integrated exactly (θ″ piecewise linear)",
    )
}

/// Sec. 3 after Eq. 30: the gradient-projection iterates have nonincreasing G.
pub fn nonincreasing_objective() -> Outcome {
    let z64 = components::<f64>(&());
    let zq = components::<Q>(&());
    let ones_q = [Q::from_integer(1.into()), Q::from_integer(1.into())];
    let mut report = Vec::new();
    let mut increases = Vec::new();
    for form in [Objective::Exact, Objective::Approximate] {
        let h0 = chord_length_spacing(&z64);
        let mut iterates: Vec<Vec<f64>> = vec![h0.clone()];
        let result = descend(h0, &z64, &[1.0, 1.0], form, &mut |_, h| {
            iterates.push(h.to_vec())
        });
        if result.is_err() {
            return Outcome::new("", "f64", Verdict::Failed, "the descent failed");
        }
        // Each f64 iterate read exactly, G evaluated exactly: no rounding in the comparison.
        let values: Vec<Q> = iterates
            .iter()
            .filter_map(|h| {
                let hq: Vec<Q> = h.iter().filter_map(|x| Q::from_float(*x)).collect();
                objective(&hq, &zq, &ones_q, form).ok()
            })
            .collect();
        let name = if form == Objective::Exact {
            "Eq. 31"
        } else {
            "Eq. 34"
        };
        for (i, w) in values.windows(2).enumerate() {
            if w[1] > w[0] {
                increases.push(format!("{name}, iterate {}", i + 1));
            }
        }
        report.push(format!(
            "{name}: {} iterates, G from {:.6} to {:.6}",
            values.len(),
            values.first().map_or(f64::NAN, Field::to_f64),
            values.last().map_or(f64::NAN, Field::to_f64)
        ));
    }
    Outcome::new(
        format!("{} ({} increases)", report.join("; "), increases.len()),
        "f64 iterates, G exact",
        Verdict::holds(increases.is_empty()),
        format!(
            "gradient projection with exact line search from chord length on the Table II data (α = 1), every iterate h⁽ⁱ⁾ read exactly \
             as rationals and G(h⁽ⁱ⁾) evaluated exactly, so the comparison has no rounding; increases: {increases:?}"
        ),
    )
}
