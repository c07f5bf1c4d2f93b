//! Paper 000: Patterson et al., *On Hermite Interpolation using Bernstein Polynomials for
//! Trajectory Generation*, NASA/TM-20230013467 (2023).
//!
//! Claims: the Fig. 2 control points, the boundary conditions of Eqs. 12–15, the index ranges
//! of Eqs. 16–17 and the vector of Eq. 18, the difference identities of Eqs. 8–9 and App. A,
//! the Fig. 3 and Fig. 4 examples, the condition numbers of Fig. 5 and degree elevation.
//! The modules split them by kind: `exact` (rational identities), `examples` (Figs. 3–4),
//! `conditioning` (Fig. 5).

mod conditioning;
mod exact;
mod examples;
mod figures;
mod render;
mod statements;
mod turn_proofs;

use super::{Ledger, Outcome, Paper, PaperOutput, Verdict};
use crate::ledger::Severity;
use crate::numeric::poly::Bernstein;
use crate::papers::ClaimSpec;
use crate::scalar::BigRational;

/// The paper's id (its text's file stem; `docs/papers.md` cites the paper).
pub const ID: &str = "000_d51e5cedfa8471cf";
/// The short name: the prefix of every claim id and a `--paper` value.
pub const SHORT: &str = "hermite";
/// Authors and title.
pub const TITLE: &str = "Patterson et al., On Hermite Interpolation using Bernstein Polynomials for Trajectory Generation, NASA/TM-20230013467 (2023)";

const FIG2_FAST: &str = "0 0 0 0.6 0.8 1";
const FIG2_SLOW: &str = "0 0 0 0.2 0.6 1";

/// The claims of the paper, in report order.
pub const SPECS: &[ClaimSpec] = &[
    ClaimSpec { id: "hermite.fig2.control_points.t1", location: "Sec. 4, Fig. 2", statement: "for H = [0 0 0 | 1 1 0] and duration 1 the control points are [0 0 0 0.6 0.8 1]", published: Some(FIG2_FAST) },
    ClaimSpec { id: "hermite.fig2.control_points.t2", location: "Sec. 4, Fig. 2", statement: "for the same H and duration 2 the control points are [0 0 0 0.2 0.6 1]", published: Some(FIG2_SLOW) },
    ClaimSpec { id: "hermite.eq12_15.boundary_conditions", location: "Eqs. 12–15", statement: "the Bernstein polynomial of Eq. 18 meets all 2(m+1) boundary conditions of H on any interval", published: None },
    ClaimSpec { id: "hermite.eq13.derivatives", location: "Eqs. 5, 12, 13", statement: "the j-th derivative of a Bernstein polynomial on [t0, t1] is n!/(n−j)!/(t1−t0)^j Σ b^(n−j)_k Δ^j p_k", published: None },
    ClaimSpec { id: "hermite.eq16_17.index_ranges", location: "Eqs. 16–17", statement: "[p_0 … p_(m+1)] = [q, Δ^-1 q, …, Δ^-m q] from the start data and [p_(m+2) … p_(2m+1)] = [∇^m q, …, ∇^1 q, q] from the end data", published: Some("p_0…p_(m+1) | p_(m+2)…p_(2m+1)") },
    ClaimSpec { id: "hermite.eq18.vector", location: "Eq. 18", statement: "P = [q_0, Δ^-1(q_0), …, Δ^-m(q_0) | ∇^m(q_n), …, ∇^1(q_n), q_n] solves Eqs. 14–15", published: None },
    ClaimSpec { id: "hermite.eq8.as_printed", location: "Eq. 8", statement: "the anti-difference Δ^-j(y_i) = Δ^(j+1)(y_(i+1)) + Δ^(j+1)(y_i) inverts the forward difference (as printed in the extracted text)", published: Some("Δ^-j(y_i) = Δ^(j+1)(y_(i+1)) + Δ^(j+1)(y_i)") },
    ClaimSpec { id: "hermite.eq8.minus_restored", location: "Eq. 8, App. A (A2)", statement: "Eq. 8 with the superscript read as −j+1 is the binomial transform (A2)", published: None },
    ClaimSpec { id: "hermite.eq9.self_inverse", location: "Eq. 9", statement: "the backward difference is self-inverse for the final element: Eq. 9 recovers x from ∇^j x_n", published: None },
    ClaimSpec { id: "hermite.appA.a1_a2_inverse", location: "App. A, Eqs. A1–A2", statement: "the forward difference matrix (A1) and the binomial matrix (A2) are inverse to each other", published: None },
    ClaimSpec { id: "hermite.appA.a3_self_inverse", location: "App. A, Eq. A3", statement: "the backward difference matrix (A3) is self-inverse", published: None },
    ClaimSpec { id: "hermite.fig3.short_is_straight", location: "Sec. 4, Fig. 3", statement: "reducing the duration (×0.2) leads to an almost straight-line connection", published: None },
    ClaimSpec { id: "hermite.fig3.nominal_is_circular", location: "Sec. 4, Fig. 3", statement: "with an appropriately chosen duration the curve approximates a circular turn", published: None },
    ClaimSpec { id: "hermite.fig3.long_loops_away", location: "Sec. 4, Fig. 3", statement: "an increased duration (×3) makes the curve loop away from the terminal point", published: None },
    ClaimSpec { id: "hermite.fig4.landing_constraints", location: "Sec. 4, Fig. 4", statement: "the interpolation immediately produces a trajectory meeting the initial position, velocity, acceleration and the landing point and speed along the runway in 60 s", published: None },
    ClaimSpec { id: "hermite.fig5.kappa_table", location: "Sec. 4, Fig. 5; Eq. 10", statement: "the condition number κ2 = σmax/σmin of the transform for m derivatives on the unit interval (Fig. 5)", published: None },
    ClaimSpec { id: "hermite.fig5.proven", location: "Sec. 4, Fig. 5; Eq. 10", statement: "the condition numbers of Fig. 5, each enclosed with proof, and where f64 loses its last correct digit", published: None },
    ClaimSpec { id: "hermite.fig5.kappa_grows", location: "Sec. 4, Fig. 5", statement: "the condition number grows with the number of derivatives", published: None },
    ClaimSpec { id: "hermite.sec23.sensitivity_mechanism", location: "Sec. 2.3, last paragraph", statement: "the solution is sensitive to input perturbations, since a small change in a high-order derivative, allowed to integrate over a long time period, will lead to a large change in the position of the curve", published: None },
    ClaimSpec { id: "hermite.fig5.interval_changes_kappa", location: "Sec. 4, text after Fig. 4", statement: "increasing or decreasing the interval will have an impact on the condition number", published: None },
    ClaimSpec { id: "hermite.eq4.basis_endpoints", location: "Sec. 2.1, Eqs. 3–4", statement: "the basis on [t0, t1] is Eq. 4, the standard basis at ζ(t) of Eq. 3, and the curve interpolates its first and last control points", published: None },
    ClaimSpec { id: "hermite.sec23.order_count", location: "Sec. 2.3", statement: "each derivative constraint raises the order by two: constraints up to the tenth derivative give order twenty-one", published: Some("twenty-one") },
    ClaimSpec { id: "hermite.sec3.n_is_count", location: "Sec. 3, after Eq. 11", statement: "f : H ∈ R^n → P ∈ R^n with n = 2(m + 1), the n of Eqs. 12–18", published: Some("n = 2(m + 1)") },
    ClaimSpec { id: "hermite.sec31.first_derivative", location: "Sec. 3.1, after Eq. 15", statement: "x_0^(1) = nΔ¹(p_0) = n(p_1 − p_0)", published: Some("x_0^(1) = n(p_1 − p_0)") },
    ClaimSpec { id: "hermite.sec31.triangular", location: "Sec. 3.1", statement: "note the triangular structure of the problem; these equations can be recursively solved", published: None },
    ClaimSpec { id: "hermite.fig2.duration_coupling", location: "Sec. 4, Fig. 2", statement: "both curves meet their associated constraints but only when connected to the duration of the underlying parameter", published: None },
    ClaimSpec { id: "hermite.fig2.shorter_accelerates_more", location: "Sec. 4, Fig. 2", statement: "the lower duration curve must have larger acceleration (and deceleration)", published: None },
    ClaimSpec { id: "hermite.sec4.degree_elevation", location: "Sec. 4, end", statement: "a Bernstein polynomial can be degree elevated: the curve is exactly represented with more control points", published: None },
    ClaimSpec { id: "hermite.fig4.caption_vs_text", location: "Sec. 4, Fig. 4 caption and text", statement: "the landing trajectory connects the vehicle's initial position, velocity and acceleration (caption) — the initial condition is the current position and velocity (text)", published: Some("position, velocity, and acceleration | position and velocity") },
    ClaimSpec { id: "hermite.sec22.indexing", location: "Sec. 2.2, Eqs. 6–7, App. A (A1)", statement: "the difference operators act on \"a vector of length n\", indexed j = 0…n−1, whose elements are x_0…x_n, and (A1) reaches Δⁿx_0", published: Some("length n, j = 0…n−1 | x_0…x_n | Δⁿx_0") },
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

/// What the checks of paper 000 computed, for the report.
struct Results {
    /// The Fig. 2 outcomes for durations 1 and 2.
    fig2: [Outcome; 2],
    /// The Fig. 2 curves for durations 1 and 2, exact.
    fig2_curves: [Bernstein<BigRational>; 2],
    /// The Eqs. 16–17 index-range outcome.
    ranges: Outcome,
    /// The Fig. 3 measurements (`None` if the instance failed to solve).
    turn: Option<Vec<examples::TurnMetrics>>,
    /// The Fig. 3 curves' proven measures, in the order of `turn` (or why they are not).
    turn_proven: Result<Vec<turn_proofs::ProvenTurn>, String>,
    /// The Fig. 4 instance and its claim (`None` if it failed to solve).
    landing: Option<(examples::LandingMetrics, Outcome)>,
    /// The Fig. 5 rows.
    kappa: Vec<conditioning::KappaRow>,
}

/// Why each of this paper's claims that is only certified or floating is not proven (issue
/// 36); the ledger appends the reason to the claim's evidence.
const UNPROVEN: &[(&str, &str)] = &[];

/// Run every check of paper 000 and build its report.
pub fn verify() -> PaperOutput {
    let mut ledger = Ledger::new(ID, SPECS);
    ledger.explain_unproven(UNPROVEN);
    let (fast, fast_curve) = exact::fig2(1, FIG2_FAST);
    let (slow, slow_curve) = exact::fig2(2, FIG2_SLOW);
    ledger.record("hermite.fig2.control_points.t1", fast.clone());
    ledger.record("hermite.fig2.control_points.t2", slow.clone());
    let ranges = exact_checks(&mut ledger);
    let turn = examples::turn_metrics();
    let turn_proven = turn_section(&mut ledger, turn.as_deref());
    let landing = landing_check(&mut ledger);
    ledger.record(
        "hermite.fig4.caption_vs_text",
        statements::fig4_caption_vs_text(),
    );
    ledger.record("hermite.sec22.indexing", statements::sec22_indexing());
    let kappa = conditioning::table();
    let [kappa_table, grows, interval] = conditioning::claims(&kappa);
    ledger.record("hermite.fig5.kappa_table", kappa_table);
    ledger.record("hermite.fig5.proven", conditioning::proven_outcome(&kappa));
    ledger.record("hermite.fig5.kappa_grows", grows);
    ledger.record("hermite.fig5.interval_changes_kappa", interval);
    ledger.record(
        "hermite.sec23.sensitivity_mechanism",
        crate::papers::found(
            conditioning::sensitivity_mechanism(&kappa),
            "sensitive since a small change in a high-order derivative, integrated over a long time, moves the curve a lot",
            "true of the curve's absolute response over long durations; not the cause of the large κ₂ of Fig. 5, which falls as the interval grows",
            crate::ledger::Severity::Minor,
            "no printed number depends on it, and κ₂'s growth with m stands (hermite.fig5.kappa_grows)",
        ),
    );
    ledger.record(
        "hermite.eq4.basis_endpoints",
        statements::eq4_basis_and_endpoints(),
    );
    ledger.record("hermite.sec23.order_count", statements::order_count());
    sec3_checks(&mut ledger);
    ledger.record(
        "hermite.fig2.shorter_accelerates_more",
        statements::shorter_accelerates_more(&fast_curve, &slow_curve),
    );
    ledger.record(
        "hermite.fig2.duration_coupling",
        statements::duration_coupling(&fast_curve, &slow_curve),
    );
    ledger.record("hermite.sec31.triangular", statements::triangular());
    ledger.record("hermite.sec4.degree_elevation", exact::degree_elevation());
    let results = Results {
        fig2: [fast, slow],
        fig2_curves: [fast_curve, slow_curve],
        ranges,
        turn,
        turn_proven,
        landing,
        kappa,
    };
    render::report(&results, ledger.finish())
}

/// Sec. 3's two statements with a lost symbol (typos with their findings).
fn sec3_checks(ledger: &mut Ledger) {
    let n_is_count = statements::n_is_count(FIG2_FAST);
    let computed = n_is_count.reproduced.clone();
    ledger.record(
        "hermite.sec3.n_is_count",
        n_is_count.finding(
            (
                "n = 2(m + 1) in Eqs. 12–18",
                &computed,
                "n is the degree 2m + 1 there, one less than the count of conditions",
            ),
            Severity::Material,
            "it is the last definition of n before Eqs. 14–17, so a reader implementing them as printed gets wrong control points \
             (for Fig. 2, an end velocity of 5/6 instead of 1); the printed Fig. 2 vector fixes the reading",
        ),
    );
    let first = statements::first_derivative_factor();
    let computed = first.reproduced.clone();
    ledger.record(
        "hermite.sec31.first_derivative",
        first.finding(
            (
                "x_0^(1) = n(p_1 − p_0)",
                &computed,
                "the factor 1/(t_1 − t_0) is lost (it is 1 on Fig. 2's unit interval)",
            ),
            Severity::Minor,
            "Eq. 13, which a reader implements, carries the factor",
        ),
    );
}

/// Fig. 4 on landing data of our own: `illustrated` (policy clauses 1 and 2).
fn landing_check(ledger: &mut Ledger) -> Option<(examples::LandingMetrics, Outcome)> {
    examples::landing().map(|l| {
        // Provenance (and by construction): the landing data are our own, and a Hermite
        // solution meets its boundary conditions by construction.
        let claim = examples::landing_claim(&l).with_verdict(Verdict::Illustrated);
        let reproduced = claim.reproduced.clone();
        let claim = claim.finding(
            (
                "a trajectory meeting the initial state and the landing point and speed in 60 s",
                &reproduced,
                "on landing data of our own (the paper gives none), and the conditions hold by construction of the Hermite \
                 solution: nothing of Fig. 4 is reproduced",
            ),
            Severity::Minor,
            "an illustration of the method on invented data",
        );
        ledger.record("hermite.fig4.landing_constraints", claim.clone());
        (l, claim)
    })
}

/// The Fig. 3 claims, on the proven measures of the curves (the samples of `metrics` only
/// choose where the recession is evaluated); returns those measures for the report.
fn turn_section(
    ledger: &mut Ledger,
    metrics: Option<&[examples::TurnMetrics]>,
) -> Result<Vec<turn_proofs::ProvenTurn>, String> {
    const IDS: [&str; 3] = [
        "hermite.fig3.short_is_straight",
        "hermite.fig3.nominal_is_circular",
        "hermite.fig3.long_loops_away",
    ];
    let proven = metrics
        .ok_or_else(|| "the Fig. 3 instance failed to solve".to_string())
        .and_then(|m| {
            turn_proofs::prove_all(&m.iter().map(|t| t.samples.clone()).collect::<Vec<_>>())
        });
    match &proven {
        Ok(p) => {
            for (id, outcome) in IDS.iter().zip(turn_proofs::turn_claims(p)) {
                ledger.record(id, fig3_illustrated(outcome));
            }
        }
        Err(e) => {
            for id in IDS {
                ledger.record(id, Outcome::new("", "ball:128", Verdict::Failed, e.clone()));
            }
        }
    }
    proven
}

/// A Fig. 3 claim, computed on turn data of our own (the paper gives neither the directions,
/// the speeds nor the nominal duration): `illustrated` (policy clause 1), with what the two
/// readings of the data gave.
fn fig3_illustrated(outcome: Outcome) -> Outcome {
    if outcome.verdict == Verdict::Failed {
        return outcome;
    }
    let readings = match outcome.verdict {
        Verdict::Reproduced => "on turn data of our own (the paper gives none), it holds under both readings of that data",
        Verdict::Discrepancy => "on turn data of our own (the paper gives none), it holds under neither reading of that data",
        _ => "on turn data of our own (the paper gives none), it holds under one reading of that data and not the other",
    };
    let computed = outcome.reproduced.clone();
    outcome.with_verdict(Verdict::Illustrated).finding(
        ("the qualitative behaviour of Fig. 3", &computed, readings),
        Severity::Minor,
        "the figure's data are not in the paper, so this illustrates the method, it reproduces nothing",
    )
}

/// The exact identities (Eqs. 8–9, 12–18, App. A); returns the index-range outcome, which
/// the report shows.
fn exact_checks(ledger: &mut Ledger) -> Outcome {
    ledger.record(
        "hermite.eq12_15.boundary_conditions",
        exact::boundary_conditions(),
    );
    ledger.record("hermite.eq13.derivatives", exact::eq13_derivatives());
    let (ranges, _) = exact::eq16_17_index_ranges();
    // Typo, not discrepancy (policy clause 3): an index offset by one, with one consistent
    // reading that Eq. 18 and Fig. 2 use; no number depends on the labels.
    let computed = ranges.reproduced.clone();
    let ranges = ranges.with_verdict(Verdict::Typo).finding(
        (
            "p_0…p_(m+1) | p_(m+2)…p_(2m+1)",
            &computed,
            "each range is off by one index; Eq. 18 and Fig. 2 use the ranges computed",
        ),
        Severity::Minor,
        "Eq. 18, the vector a reader builds, is right",
    );
    ledger.record("hermite.eq16_17.index_ranges", ranges.clone());
    ledger.record("hermite.eq18.vector", exact::eq18_vector());
    let (eq8_printed, eq8_restored) = exact::eq8();
    let computed = eq8_printed.reproduced.clone();
    ledger.record(
        "hermite.eq8.as_printed",
        eq8_printed.finding(
            ("Δ^-j(y_i) = Δ^(j+1)(y_(i+1)) + Δ^(j+1)(y_i)", &computed, "a lost minus in the superscript: read as −j+1 it is (A2) (hermite.eq8.minus_restored)"),
            Severity::Material,
            "Eq. 8 is the recursion a reader implements, and as printed it does not invert the difference",
        ),
    );
    ledger.record("hermite.eq8.minus_restored", eq8_restored);
    ledger.record("hermite.eq9.self_inverse", exact::eq9_self_inverse());
    ledger.record("hermite.appA.a1_a2_inverse", exact::a1_a2_inverse());
    ledger.record("hermite.appA.a3_self_inverse", exact::a3_self_inverse());
    ranges
}
