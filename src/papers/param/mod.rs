//! Paper 004: Marin, *An Approach to Data Parametrization in Parametric Cubic Spline
//! Interpolation Problems*, J. Approx. Theory (1984).
//!
//! Claims checked so far: the exact 1-D minimizers (case I, Table I, Eqs. 8 and 11,
//! Corollaries 2 and 3), the plane-curve example (Table III, the second-derivative comparison
//! of Figs. 3–5), the robot example (Tables VI–VII), the corner example (Fig. 6) and the H¹
//! inequality of Sec. 1.

mod curve_distances;
mod data;
mod figures;
mod geometry;
mod objective_claims;
mod one_d;
mod overshoot;
mod plane;
mod proven_splines;
mod remarks;
mod render;
mod robot;
mod sentences;

use super::{ClaimSpec, Ledger, Paper, PaperOutput, Verdict};
use crate::ledger::Amendment;
use crate::ledger::Severity::Minor;
use crate::scalar::parse::parse_rational;
use crate::scalar::BigRational;

/// The paper's id (its text's file stem; `docs/papers.md` cites the paper).
pub const ID: &str = "004_2a9dc6e62cca15f1";
/// The short name: the prefix of every claim id and a `--paper` value.
pub const SHORT: &str = "marin";
/// Authors and title.
pub const TITLE: &str = "Marin, An Approach to Data Parametrization in Parametric Cubic Spline Interpolation Problems, J. Approx. Theory (1984)";

/// The claims of the paper, in report order.
pub const SPECS: &[ClaimSpec] = &[
    ClaimSpec { id: "marin.sec1.h1_inequality", location: "Sec. 1 (i)", statement: "‖θ − φ‖²_H¹ = ∫(e² + e'²) ≤ ∫θ''² for each component, φ the piecewise linear interpolant", published: None },
    ClaimSpec { id: "marin.case1.chord_length", location: "Sec. 2, case I, Eq. 7", statement: "for strictly monotone data the minimizing parametrization is normalized accumulated chord length, θ is linear and G = 0", published: None },
    ClaimSpec { id: "marin.table1.t_star", location: "Table I, Eq. 9, Corollary 1", statement: "the minimizing parametrization of the Table I ordinates", published: Some("Table I, column t_i*") },
    ClaimSpec { id: "marin.cor1.numerical", location: "Sec. 2, Corollary 1 (case II)", statement: "for alternating data the parametrization of Eq. 9 is the minimizer of G", published: None },
    ClaimSpec { id: "marin.eq8.interior_slope", location: "Sec. 2, Lemma, Eq. 8", statement: "at the minimizing parametrization of alternating data, dθ/dt(t_i*) = 0 at every interior knot", published: None },
    ClaimSpec { id: "marin.eq11.jump", location: "Eqs. 11–12", statement: "the jump in the second derivative given by Eq. 11 vanishes at the minimizing parametrization", published: None },
    ClaimSpec { id: "marin.cor2.unique_minimizer", location: "Sec. 2, case III, Corollary 2", statement: "the parametrization of Eqs. 16–17 is the unique minimizer of G for general scalar data", published: None },
    ClaimSpec { id: "marin.cor3.properties", location: "Corollary 3 (i)–(iii)", statement: "no overshoots; breakpoints only at the extremes; |θ''| = 3(Σ ε_j √|D_j|)² at the interior extremes, alternating in sign", published: None },
    ClaimSpec { id: "marin.remark.existence", location: "Sec. 1, Remark (Existence of Solutions)", statement: "z_i ≠ z_(i+1) implies that G(h) becomes infinite if any component of h vanishes", published: None },
    ClaimSpec { id: "marin.eq31.bending_energy", location: "Sec. 3, Eq. 31", statement: "G(h) = Σ α_l⁻² (z^l)ᵀQᵀM⁻¹Qz^l is the smoothness objective Σ α_l⁻² ∫θ_l''² of the natural splines", published: None },
    ClaimSpec { id: "marin.eq30.nonincreasing", location: "Sec. 3, after Eq. 30", statement: "the gradient-projection iterates have nonincreasing objective values G(h⁽⁰⁾), G(h⁽¹⁾), …", published: None },
    ClaimSpec { id: "marin.table3.chord", location: "Table III, column t^C1; Eq. 5", statement: "normalized accumulated chord length of the Table II data", published: Some("Table III, column t_i^C1") },
    ClaimSpec { id: "marin.table3.exact", location: "Table III, column t^EX; Eqs. 30–31", statement: "the minimizing parametrization of the Table II data with the exact objective (31)", published: Some("Table III, column t_i^EX") },
    ClaimSpec { id: "marin.table3.approx", location: "Table III, column t^AP; Eqs. 30, 34", statement: "the minimizing parametrization of the Table II data with the approximate objective (34)", published: Some("Table III, column t_i^AP") },
    ClaimSpec { id: "marin.fig3_5.second_derivatives", location: "Sec. 3, Figs. 3–5", statement: "the minimizing parametrizations substantially reduce the second derivatives of both components compared with chord length", published: None },
    ClaimSpec { id: "marin.sec2.third_derivative_jumps", location: "Sec. 2, after Corollary 3, bullet (ii)", statement: "for higher-dimensional data the minimizing parametrization reduces the jump in the third derivative at breakpoints not coinciding with relative extreme values", published: None },
    ClaimSpec { id: "marin.sec2.overshoots_reduced", location: "Sec. 2, after Corollary 3, bullet (i)", statement: "for higher-dimensional data the minimizing parametrization reduces position overshoots (compared with chord length)", published: None },
    ClaimSpec { id: "marin.eq34.quadrature_factor", location: "Sec. 3, before Eq. 34", statement: "replacing M by its diagonal has the same effect as rectangular quadrature with centred differences for the second derivatives", published: None },
    ClaimSpec { id: "marin.abstract.objective_weights", location: "Abstract", statement: "parametrizations are chosen by minimizing Σ_l ∫(d²θ^l/dt²)² dt (the weights 1/α_l² not written)", published: None },
    ClaimSpec { id: "marin.eq30.always_improves", location: "Sec. 3, after Eq. 30; Sec. 4", statement: "gradient projection from chord length always results in an improved parametrization, provided π_B(∇G|h⁽⁰⁾) ≠ 0", published: None },
    ClaimSpec { id: "marin.fig34.x_most_pronounced", location: "Sec. 3, example 1", statement: "these observations (smaller third-derivative jumps, oscillations more centred about zero) are most pronounced when the plot of d²x/dt² from Fig. 3 is compared to the one in Fig. 4", published: None },
    ClaimSpec { id: "marin.sec2.oscillations_centred", location: "Sec. 2, after Corollary 3, bullet (iii)", statement: "for higher-dimensional data, oscillations in the second derivative tend to be more centered about zero with the minimizing parametrization", published: None },
    ClaimSpec { id: "marin.table2.oscillations_centred", location: "Sec. 3, example 1 (Table II, Figs. 3–5)", statement: "with the minimizing parametrizations, oscillations in the second derivative are more centred about zero than with chord length", published: None },
    ClaimSpec { id: "marin.sec1.chord_constant_speed", location: "Sec. 1, after Eq. (5)", statement: "when used in applications of robot trajectory design, [chord length] merely ensures that approximate constant speed is maintained", published: None },
    ClaimSpec { id: "marin.sec2.cor3_fails_k2", location: "Sec. 2, after Corollary 3", statement: "when higher dimensional data is parametrized by solving (2), the associated natural cubic spline interpolants of the data components do not satisfy precisely the properties listed in Corollary 3", published: None },
    ClaimSpec { id: "marin.table7.ap_lowest", location: "Sec. 3, example 3 (Table VII)", statement: "the minimizing parametrization can reduce significantly component function accelerations compared to those obtained with the other two parametrizations", published: None },
    ClaimSpec { id: "marin.sec1.closer_to_polygon", location: "Sec. 1 (i)", statement: "we anticipate that parametrizations which minimize G will also provide interpolating curves θ(t) which are closer to the interpolating polygon", published: None },
    ClaimSpec { id: "marin.sec3.align_extrema", location: "Sec. 3, example 3", statement: "the minimizing parametrization tends to align local extrema in the data with local extrema in the cubic spline interpolant of the data", published: None },
    ClaimSpec { id: "marin.cor3.d_index", location: "Corollary 3 (iii)", statement: "θ″(t_{i_k}) = −3 sgn(D_{i_k})(Σ_{j=1}^M ε_j √|D_j|)², with D_{i_k} = z_{i_k} − z_{i_{k−1}} (Eq. 13)", published: None },
    ClaimSpec { id: "marin.eq26.tilde", location: "Sec. 2, proof of Corollary 2, Eq. (26), first line", statement: "the immediate implication of (25) and case II uniqueness is that t̂_{i_k} = t*_{i_k}, k = 0, …, M", published: None },
    ClaimSpec { id: "marin.eq13.extremum_index", location: "Sec. 2, case III, before Eq. (13)", statement: "identify all indices 1 ≤ i_1 < … < i_{M−1} ≤ N−1 for which Δ_{i_{k+1}}/Δ_{i_k} < 0", published: None },
    ClaimSpec { id: "marin.case3.observations", location: "Sec. 2, case III, observations (i)–(ii)", statement: "z_j lies strictly between consecutive extremes; ψ interpolates the edited data and is strictly monotone between them, so Eq. 17 is uniquely solvable", published: None },
    ClaimSpec { id: "marin.table2.overshoots_no_problem", location: "Sec. 3, on Table II", statement: "position overshoots are not a problem in any of the parametrizations of this data", published: None },
    ClaimSpec { id: "marin.fig2.plane_curves", location: "Sec. 3, Fig. 2", statement: "the resulting plane curves are nearly identical for the three parametrizations", published: None },
    ClaimSpec { id: "marin.fig45.validity_of_34", location: "Sec. 3, Figs. 4–5", statement: "the validity of using the approximate objective (34) in place of the exact one (31) is illustrated by comparing Figs. 4 and 5", published: None },
    ClaimSpec { id: "marin.fig6.corner", location: "Sec. 3, Fig. 6", statement: "with widely spaced data near a corner, chord length gives oscillations whose amplitude the minimizing parametrization reduces", published: None },
    ClaimSpec { id: "marin.table6.chord_6d", location: "Table VI, column t^CL; Eq. 5", statement: "normalized accumulated chord length of the six-dimensional axis data of Table IV", published: Some("Table VI, column t_i^CL") },
    ClaimSpec { id: "marin.table6.chord_wc", location: "Table VI, column t^WC; Eq. 5", statement: "normalized accumulated chord length of the work-centre positions of Table V", published: Some("Table VI, column t_i^WC") },
    ClaimSpec { id: "marin.table6.approx", location: "Table VI, column t^AP; Eqs. 30, 34", statement: "the minimizing parametrization of the axis data with objective (34) and α = 1, 1, 2, 6, 6, 6", published: Some("Table VI, column t_i^AP") },
    ClaimSpec { id: "marin.table7.max_acceleration", location: "Table VII", statement: "the maximum second derivative of each axis' natural cubic spline for each parametrization", published: Some("Table VII (18 values)") },
    ClaimSpec { id: "marin.fig9.overshoots", location: "Sec. 3, Fig. 9", statement: "for axis #3, overshoots occur in several areas with t^CL and t^WC and are eliminated with t^AP", published: None },
    ClaimSpec { id: "marin.fig9.oscillations", location: "Sec. 3, Fig. 9", statement: "for axis #3, t^AP aligns the spline's local extrema with the data's: the unwanted oscillations of t^CL and t^WC are eliminated", published: None },
    ClaimSpec { id: "marin.table7.reduction", location: "Sec. 3, after Table VII", statement: "reduction by a factor of two or more was obtained on five of the six axes", published: Some("five of the six axes") },
];

/// The paper: its specs and its checks.
pub fn paper() -> Paper {
    Paper {
        id: ID,
        short: SHORT,
        title: TITLE,
        specs: SPECS,
        verify,
    }
}

/// A printed decimal as an exact rational (the transcribed tables parse by construction; a
/// test checks every entry).
pub(crate) fn num(s: &str) -> BigRational {
    parse_rational(s).unwrap_or_else(|_| BigRational::from_integer(0.into()))
}

/// What the checks of paper 004 computed, for the report.
struct Results {
    h1: Vec<geometry::H1Row>,
    table1: Option<one_d::TableOne>,
    plane: plane::PlaneSection,
    corner: Option<geometry::CornerCurves>,
    robot: robot::RobotSection,
    /// Fig. 9: the overshoots of axis #3 on each parametrization.
    fig9: Vec<overshoot::OvershootRow>,
}

/// Why each of this paper's claims that is only certified or floating is not proven (issue
/// 36); the ledger appends the reason to the claim's evidence. Every claim of paper 004 is
/// now exact or proven.
const UNPROVEN: &[(&str, &str)] = &[];

/// Run every check of paper 004 and build its report.
pub fn verify() -> PaperOutput {
    let mut ledger = Ledger::new(ID, SPECS);
    ledger.explain_unproven(UNPROVEN);
    ledger.record("marin.remark.existence", objective_claims::existence());
    ledger.record(
        "marin.eq31.bending_energy",
        objective_claims::eq31_is_bending_energy(),
    );
    ledger.record(
        "marin.eq30.nonincreasing",
        objective_claims::nonincreasing_objective(),
    );
    let h1 = geometry::h1_inequality(&mut ledger);
    let table1 = one_d::section(&mut ledger);
    let plane = plane::section(&mut ledger);
    let corner = geometry::corner(&mut ledger);
    let robot = robot::section(&mut ledger);
    ledger.record(
        "marin.sec2.overshoots_reduced",
        overshoot::reduced(&plane.proven, robot.approx_knots.as_ref()),
    );
    ledger.record(
        "marin.eq34.quadrature_factor",
        objective_claims::quadrature_factor(),
    );
    ledger.record(
        "marin.abstract.objective_weights",
        sentences::objective_weights(),
    );
    ledger.record("marin.eq30.always_improves", sentences::always_improves());
    ledger.record("marin.case3.observations", sentences::case3_observations());
    ledger.record("marin.eq13.extremum_index", sentences::extremum_index());
    remark_checks(&mut ledger, &plane, &robot);
    ledger.record(
        "marin.fig34.x_most_pronounced",
        sentences::x_most_pronounced(&plane.proven),
    );
    ledger.record(
        "marin.table2.overshoots_no_problem",
        overshoot::table2_no_problem(&plane.proven),
    );
    ledger.record(
        "marin.fig2.plane_curves",
        plane::plane_curves(&plane.proven),
    );
    ledger.record(
        "marin.fig45.validity_of_34",
        plane::validity_of_34(&plane.proven),
    );
    let (fig9, [overshoots, oscillations]) = overshoot::fig9(robot.approx_knots.as_ref());
    ledger.record("marin.fig9.overshoots", overshoots);
    ledger.record("marin.fig9.oscillations", oscillations);
    let results = Results {
        h1,
        table1,
        plane,
        corner,
        robot,
        fig9,
    };
    policy(&mut ledger);
    render::report(&results, ledger.finish())
}

/// The remarks judged on both examples (Table II and the robot): centring, constant speed,
/// Corollary 3 for K > 1, Table VII's reductions, aligned extrema, closeness to the polygon.
fn remark_checks(ledger: &mut Ledger, plane: &plane::PlaneSection, robot: &robot::RobotSection) {
    ledger.record(
        "marin.table2.oscillations_centred",
        sentences::table2_oscillations_centred(&plane.proven),
    );
    ledger.record(
        "marin.sec2.oscillations_centred",
        sentences::oscillations_centred(
            &plane.proven,
            [Some(&robot.chord_knots), robot.approx_knots.as_ref()],
        ),
    );
    ledger.record(
        "marin.sec1.chord_constant_speed",
        remarks::chord_constant_speed(&plane.proven, &robot.chord_knots),
    );
    ledger.record(
        "marin.sec2.cor3_fails_k2",
        remarks::cor3_fails_k2(&plane.proven),
    );
    ledger.record(
        "marin.table7.ap_lowest",
        remarks::ap_lowest(&robot.from_printed),
    );
    ledger.record("marin.sec3.align_extrema", remarks::align_extrema());
    ledger.record(
        "marin.sec1.closer_to_polygon",
        remarks::closer_to_polygon(&plane.proven),
    );
}

// The findings of paper 004, all minor: (claim, new verdict if the policy changes it, what
// the paper prints, how the computation differs, severity, why).

const LAST_DIGIT: &str = "rounding of the last digit";
const LOOSE: &str = "a loose stopping tolerance: the printed knots are a near-minimizer, the objective only slightly above its minimum (evidence)";
const FIG9: &str = "Fig. 9 illustrates; the optimality results do not depend on it";

const AMENDMENTS: &[Amendment] = &[
    ("marin.table3.chord", None, "Table III, t^C1", "one entry differs in its last printed digit", Minor, LAST_DIGIT),
    ("marin.table3.exact", None, "Table III, t^EX", "the printed knots are not the certified minimizer (see the computed value)", Minor, LOOSE),
    ("marin.table3.approx", None, "Table III, t^AP", "the printed knots are not the certified minimizer (see the computed value)", Minor, LOOSE),
    ("marin.table6.chord_6d", None, "Table VI, t^CL", "one entry differs in its last printed digit", Minor, LAST_DIGIT),
    ("marin.table6.chord_wc", None, "Table VI, t^WC", "not the chord length of Table V's positions (see the computed value)", Minor, "the column is a baseline; the paper's conclusions rest on t^AP"),
    ("marin.table6.approx", None, "Table VI, t^AP", "some entries differ in their last printed digit", Minor, LAST_DIGIT),
    ("marin.table7.max_acceleration", None, "Table VII", "one printed value differs beyond its two digits (see the reproduced value)", Minor, "the reductions the paper draws from the table hold"),
    // Counts have no last digit (clause 4).
    ("marin.table7.reduction", None, "five of the six axes", "4 of 6 axes on the printed Table VII and on ours", Minor, "the reduction holds on most axes; the count is off by one"),
    // One sentence, two readings (clause 5): "overshoots … are eliminated with t^AP" read as
    // excursions beyond the data (fails) and as spurious oscillations (holds): undetermined.
    ("marin.fig9.overshoots", Some(Verdict::Undetermined), "overshoots are eliminated with t^AP", "read as excursions beyond the data, they are not (see the reproduced value); read as spurious oscillations they are (marin.fig9.oscillations)", Minor, FIG9),
    ("marin.fig9.oscillations", Some(Verdict::Undetermined), "overshoots are eliminated with t^AP", "read as spurious oscillations, they are; read as excursions beyond the data, they are not (marin.fig9.overshoots)", Minor, FIG9),
    ("marin.sec2.overshoots_reduced", None, "the minimizing parametrization reduces overshoots", "one reading holds on the robot data, not on Table II (see the evidence)", Minor, "a remark, not a result of the paper"),
    ("marin.fig45.validity_of_34", None, "Figs. 4 and 5 illustrate that (34) may replace (31)", "some panels differ by more than the declared 1 % of their range (see the reproduced value)", Minor, "an illustration; the paper compares the two objectives by Table III (marin.table3.*)"),
    ("marin.eq34.quadrature_factor", None, "M̂ has the same effect as rectangular quadrature with centred differences", "Eq. 34's G is 3/2 times that objective for every h: the same minimizer, not the same value", Minor, "a constant factor changes no parametrization the paper computes"),
    ("marin.fig34.x_most_pronounced", None, "most pronounced for x", "x's jump sum falls more than y's, but y becomes more centred than x under the declared measure", Minor, "an observation about two figures; no number depends on it"),
    ("marin.cor3.d_index", None, "Σ_j ε_j √|D_j|", "D is defined only at the extreme indices (Eq. 13): D_(i_j), with which the formula holds", Minor, "one index level; Eq. (13) fixes the reading"),
    ("marin.eq26.tilde", None, "t̂_{i_k} = t*_{i_k} as the implication of (25)", "the printed line is Eq. (16), a definition; the step needs t̃_{i_k} = t̂_{i_k}, which holds", Minor, "one symbol in a proof; the corollary itself is checked by marin.cor2.unique_minimizer"),
    ("marin.eq13.extremum_index", None, "indices for which Δ_{i_{k+1}}/Δ_{i_k} < 0", "the condition relates chosen indices to each other and admits many index sets; Δ_{i_k+1}/Δ_{i_k} < 0 (the case's heading, Corollary 3 (ii)) selects the interior extremes", Minor, "one misplaced subscript; the heading and Corollary 3 fix the reading"),
    ("marin.abstract.objective_weights", None, "Σ_l ∫(d²θ^l/dt²)² dt", "the weights 1/α_l² of Eq. 31 are lost; they change the robot's parametrization (see the reproduced value)", Minor, "Eq. 31, which the paper computes with, carries them"),
    ("marin.sec2.oscillations_centred", None, "oscillations in θ″ tend to be more centred about zero", "more centred on Table II, less centred on the robot data (see the reproduced value)", Minor, "a qualitative remark; the paper gives no measure"),
    ("marin.table2.oscillations_centred", None, "oscillations in θ″ more centred about zero", "not under the declared measure for every component (see the reproduced value)", Minor, "a qualitative remark; the paper gives no measure"),
    ("marin.sec1.chord_constant_speed", None, "approximately constant speed", "within ±25 % of the chord speed on Table II, not on the robot data (see the reproduced value)", Minor, "a remark on the baseline parametrization; no result of the paper depends on it"),
    ("marin.sec1.closer_to_polygon", None, "minimizers' curves closer to the interpolating polygon", "on Table II, the paper's only printed plane data, both minimizers' curves are farther from the polygon (see the reproduced value)", Minor, "a hedged anticipation; the paper's results do not rest on it"),
    ("marin.sec3.align_extrema", None, "t^AP tends to align spline extrema with the data's", "holds on axis #3 (Fig. 9), not over the six axes, where t^WC leaves fewer unaligned extrema (see the reproduced value)", Minor, FIG9),
    // Provenance (clause 1): the corner data are ours.
    ("marin.fig6.corner", Some(Verdict::Illustrated), "oscillations near a widely spaced corner (Fig. 6)", "on corner data of our own: the paper prints none", Minor, "an illustration on invented data"),
];

/// The verdict policy (`ledger` module doc) applied to the claims it changes or qualifies.
fn policy(ledger: &mut Ledger) {
    ledger.apply(AMENDMENTS);
}

#[cfg(test)]
mod tests {
    use super::data::*;

    #[test]
    fn every_transcribed_number_parses() {
        let all = TABLE1
            .iter()
            .flat_map(|(a, b)| [*a, *b])
            .chain(TABLE2.iter().flat_map(|(a, b)| [*a, *b]))
            .chain(TABLE3.iter().flat_map(|(a, b, c)| [*a, *b, *c]));
        for s in all {
            assert!(crate::scalar::parse::parse_rational(s).is_ok(), "{s}");
        }
    }
}
