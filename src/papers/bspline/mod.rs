//! Paper 002: Kano, Egerstedt, Nakata & Martin, *B-splines and control theory*.
//!
//! Most claims are exact: Table 1 and the basis properties (`basis`), the bang-bang optimum
//! in Q(√2) beside its certified numerical solution (`optimal`), the Gram matrix and the
//! optimal splines (`fitting`), and the statements of Secs. 4–6 around them — Problem 3 as
//! printed, the integral forms of Sec. 4.1, the dual-space sentence, the minimiser of Eq. 15
//! and its limit, the sample times of Sec. 6 (`statements`).

mod basis;
mod control;
mod figures;
mod fitting;
mod optimal;
mod render;
mod statements;

use super::{ClaimSpec, Ledger, Paper, PaperOutput};
use crate::scalar::qsqrt2::QSqrt2;
use crate::scalar::{BigRational, Field};

/// The paper's id (its text's file stem; `docs/papers.md` cites the paper).
pub const ID: &str = "002_f491c66a0b3f232c";
/// The short name: the prefix of every claim id and a `--paper` value.
pub const SHORT: &str = "bspline";
/// Authors and title.
pub const TITLE: &str = "Kano, Egerstedt, Nakata, Martin, B-splines and control theory";

/// The claims of the paper, in report order.
pub const SPECS: &[ClaimSpec] = &[
    ClaimSpec { id: "bspline.table1.n_jk", location: "Sec. 2, Table 1", statement: "N_{j,k} for k = 0…3 computed by Algorithm 1 are the printed polynomials", published: Some("Table 1 (10 entries)") },
    ClaimSpec { id: "bspline.alg1.de_boor_cox", location: "Sec. 2, Algorithm 1, Eq. 1", statement: "Algorithm 1 with Eq. 1 computes the standard basis for normalized uniform B-splines", published: None },
    ClaimSpec { id: "bspline.eq2.end_derivatives", location: "Sec. 2, after Eq. 2", statement: "B_k^(l)(0) = 0 and B_k^(l)(k+1) = 0 for l = 0, …, k−1", published: None },
    ClaimSpec { id: "bspline.eq2.smoothness", location: "Sec. 2, after Eq. 2", statement: "B_k is a piecewise polynomial of degree k and k−1 times continuously differentiable", published: None },
    ClaimSpec { id: "bspline.eq2.partition_of_unity", location: "Sec. 2, Eq. 2", statement: "the shifted B-splines form the normalized basis (partition of unity)", published: None },
    ClaimSpec { id: "bspline.sec2.generated_by_control", location: "Sec. 2, end", statement: "the k-th derivative of B_k is piecewise constant, and d^k y/dt^k = u with that input generates B_k (any k)", published: None },
    ClaimSpec { id: "bspline.sec3.derivation_steps", location: "Sec. 3, before Eqs. 3–5", statement: "γ = a and α = 2a; B_3' = c(t−T+1)² − 2d(t−T+1) + d on [T−2, T−1]; Eqs. 3–4; B_3 = ((7a+b+c+7d) + d(t−4)³)/3 on [3, 4]", published: Some("γ = a, α = 2a; (7a + b + c + 7d)") },
    ClaimSpec { id: "bspline.sec3.eqs3_5", location: "Sec. 3, Eqs. 3–5", statement: "solving (3)–(5) gives b = −3a, c = 3a, d = −a", published: Some("b = -3a, c = 3a, d = -a") },
    ClaimSpec { id: "bspline.sec3.eq6_is_basis", location: "Sec. 3, Eq. 6", statement: "Eq. 6 is the cubic B-spline, a being a scaling parameter", published: None },
    ClaimSpec { id: "bspline.sec3.eq7", location: "Sec. 3, Eq. 7", statement: "the third derivative is 2a, −6a, 6a, −2a on the four unit intervals", published: Some("2a, -6a, 6a, -2a") },
    ClaimSpec { id: "bspline.problem3.missing_constraint", location: "Sec. 4, Problem 3", statement: "Problem 3 (min ‖u‖∞ with zero state at t = 0 and t = 4) is the problem the bang-bang law solves and the B-spline does not", published: None },
    ClaimSpec { id: "bspline.sec41.integral_forms", location: "Sec. 4.1, the four constraint displays", statement: "ẍ(4) = ∫u, ẋ(4) = ∫(4−t)u, x(4) = ½∫(4−t)²u, x(2) = ½∫(2−t)₊²u, and ⟨(2−t)₊², u⟩ = 2ξ", published: Some("the four integral forms") },
    ClaimSpec { id: "bspline.sec41.dual_variable_space", location: "Sec. 4.1, after the dual problem", statement: "if a* ∈ L₁[0, 4] solves the dual problem then the optimal u* has to satisfy ⟨Ya*, u*⟩ = ‖Ya*‖_(L₁)‖u*‖_(L∞)", published: None },
    ClaimSpec { id: "bspline.sec5.not_optimal_any", location: "Sec. 5, first sentence", statement: "the basis elements for uniform B-splines are not optimal in any usual sense", published: None },
    ClaimSpec { id: "bspline.sec41.dual_space", location: "Sec. 4.1, after the constraints", statement: "the inner product pairs L∞[0,4] with L1[0,4], which is the dual space of L∞[0,4]", published: None },
    ClaimSpec { id: "bspline.sec41.switching_times", location: "Sec. 4.1, Eq. 9", statement: "the system for r has the unique solution r = (2+√2, 2, 2−√2), so t = (2−√2, 2, 2+√2)", published: Some("t1 = 2 - sqrt(2), t2 = 2, t3 = 2 + sqrt(2)") },
    ClaimSpec { id: "bspline.sec41.uniqueness", location: "Sec. 4.1", statement: "the solution with 4 > r1 > r2 > r3 > 0 is unique", published: None },
    ClaimSpec { id: "bspline.sec41.amplitude", location: "Sec. 4.1", statement: "U = (2+√2)/2 for ξ = 2/3", published: Some("(2 + sqrt(2))/2") },
    ClaimSpec { id: "bspline.sec41.trajectory", location: "Sec. 4.1, Fig. 1", statement: "the bang-bang x(t) meets x(4) = ẋ(4) = ẍ(4) = 0 and x(2) = 2/3, with the printed closed form", published: None },
    ClaimSpec { id: "bspline.sec41.dual_certificate", location: "Sec. 4.1, Theorem 1", statement: "the bang-bang control u* solves Problem 3: a dual a with ‖Ya‖_L1 = 1 and ⟨Ya, u*⟩ = ‖u*‖∞ exists, so min ‖u‖∞ = max c·a = U", published: None },
    ClaimSpec { id: "bspline.sec41.dual_objective", location: "Sec. 4.1, dual problem", statement: "by Theorem 1 the dual problem is max ξa₄ subject to ‖Ya‖_L1 ≤ 1", published: Some("max ξ a_4") },
    ClaimSpec { id: "bspline.sec42.solution", location: "Sec. 4.2", statement: "the continuity equations at t2 with a+b+c+d = 4 give c = b = √2, a = d = 2−√2", published: Some("a = d = 2 - sqrt(2), b = c = sqrt(2)") },
    ClaimSpec { id: "bspline.sec4.does_better", location: "Sec. 4", statement: "there is a bang-bang control law that does better than the uniform B-spline", published: None },
    ClaimSpec { id: "bspline.sec5.support", location: "Sec. 5, after the interpolation conditions", statement: "B_3(t_j − i + 1) ≠ 0 if and only if i − 1 < t_j < i + 3", published: None },
    ClaimSpec { id: "bspline.sec5.gram_k3", location: "Sec. 5", statement: "for k = 3, g_ij = ĝ_|i−j| with ĝ0 = 20, ĝ1 = −15, ĝ2 = 6, ĝ3 = −1, ĝi = 0 for i ≥ 4", published: Some("20, -15, 6, -1") },
    ClaimSpec { id: "bspline.sec5.gram_positive_definite", location: "Sec. 5", statement: "the matrix G is positive definite", published: None },
    ClaimSpec { id: "bspline.sec5.gram_closed_form", location: "Sec. 5 (beyond the paper)", statement: "the Gram entries for k = 1…10, and a closed form for them", published: None },
    ClaimSpec { id: "bspline.eq14.interpolation", location: "Eqs. 13–14", statement: "τ* = G⁻¹Bᵀ(BG⁻¹Bᵀ)⁻¹α solves min τᵀGτ subject to Bτ = α", published: None },
    ClaimSpec { id: "bspline.eq15.minimizer", location: "Sec. 5, Eq. 15", statement: "G + BᵀWB is positive definite and τ̂* = (G + BᵀWB)⁻¹BᵀWα minimises τᵀGτ + (Bτ − α)ᵀW(Bτ − α) = J(u) of Eq. 12", published: None },
    ClaimSpec { id: "bspline.eq15.smoothing_limit", location: "Eq. 15", statement: "as w_i → ∞ the smoothing solution τ̂* converges to the interpolating τ*", published: None },
    ClaimSpec { id: "bspline.eq15.limit_each_weight", location: "Sec. 5, after Eq. 15", statement: "if B has full row rank, τ̂* → τ* as w_i → +∞ for all i (each weight at its own rate)", published: None },
    ClaimSpec { id: "bspline.sec6.limit_printed_times", location: "Sec. 6", statement: "we also verified that by increasing the weights further the pattern approaches the interpolation result (on the printed sample times)", published: None },
    ClaimSpec { id: "bspline.sec6.vector_separates", location: "Sec. 6", statement: "we apply the method developed in Section 5 for scalar case to each of the three elements independently, producing optimal vector-valued control points", published: None },
    ClaimSpec { id: "bspline.sec6.data_points", location: "Sec. 6", statement: "p(t) is sampled at ten equally spaced data points {3, 5, 7, 9, 11, 13, 15, 17, 19, 20}", published: Some("{3, 5, 7, 9, 11, 13, 15, 17, 19, 20}") },
    ClaimSpec { id: "bspline.sec6.reconstruction", location: "Sec. 6, Fig. 3", statement: "the curve is recovered more accurately as the weights increase, and approaches the interpolation result", published: None },
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

/// What the checks of paper 002 computed, for the report.
struct Results {
    table1: Vec<basis::Table1Row>,
    /// The findings on Eqs. 3–5, 6 and 7, one line each.
    geometric: [String; 3],
    /// The printed switching times as exact numbers of Q(√2).
    printed_switches: [QSqrt2; 3],
    /// U for ξ = 2/3 from the printed switching times, exact.
    amplitude: QSqrt2,
    /// The certified Newton solution (`None` if it did not converge).
    numeric: Option<optimal::Numeric>,
    /// The finding on "does better than B_3", one line.
    does_better: String,
    /// ĝ_0…ĝ_k for k = 1…10.
    gram: Vec<Vec<BigRational>>,
    limit: Vec<fitting::LimitRow>,
    /// The finding on Eq. 15, one line.
    limit_finding: String,
    reconstruction: Option<(Vec<fitting::Reconstruction>, Vec<fitting::Polyline>)>,
}

/// Why each of this paper's claims that is only certified or floating is not proven (issue
/// 36); the ledger appends the reason to the claim's evidence.
const UNPROVEN: &[(&str, &str)] = &[("bspline.sec6.reconstruction", REC)];
const REC: &str = "the fits are exact; the distances to the strokes are sampled in f64 (a proven maximum needs the rational splines evaluated in balls by branch and bound)";

/// Run every check of paper 002 and build its report.
pub fn verify() -> PaperOutput {
    let mut ledger = Ledger::new(ID, SPECS);
    ledger.explain_unproven(UNPROVEN);
    let (table1, geometric) = basis_checks(&mut ledger);
    let (printed_switches, amplitude, numeric, does_better) = optimal_checks(&mut ledger);
    let (gram, limit, limit_finding) = fitting_checks(&mut ledger);
    let reconstruction = fitting::reconstruction();
    if let Some((recs, _)) = &reconstruction {
        ledger.record(
            "bspline.sec6.reconstruction",
            fitting::reconstruction_claim(recs),
        );
    }
    let results = Results {
        table1,
        geometric,
        printed_switches,
        amplitude,
        numeric,
        does_better,
        gram,
        limit,
        limit_finding,
        reconstruction,
    };
    policy(&mut ledger);
    render::report(&results, ledger.finish())
}

/// Sec. 2–3: Table 1, Algorithm 1, the basis properties and the geometric construction.
fn basis_checks(ledger: &mut Ledger) -> (Vec<basis::Table1Row>, [String; 3]) {
    let (rows, t1) = basis::table1();
    ledger.record("bspline.table1.n_jk", t1);
    ledger.record("bspline.alg1.de_boor_cox", basis::algorithm1_vs_de_boor());
    let [ends, smooth, unity] = basis::properties();
    ledger.record("bspline.eq2.end_derivatives", ends);
    ledger.record("bspline.eq2.smoothness", smooth);
    ledger.record("bspline.eq2.partition_of_unity", unity);
    ledger.record(
        "bspline.sec2.generated_by_control",
        control::generated_by_control(),
    );
    ledger.record("bspline.sec3.derivation_steps", control::geometric_steps());
    let [eqs, eq6, eq7] = basis::geometric();
    let findings = [
        eqs.reproduced.clone(),
        eq6.reproduced.clone(),
        eq7.reproduced.clone(),
    ];
    ledger.record("bspline.sec3.eqs3_5", eqs);
    ledger.record("bspline.sec3.eq6_is_basis", eq6);
    ledger.record("bspline.sec3.eq7", eq7);
    (rows, findings)
}

/// Sec. 4: the bang-bang optimum, exact and certified.
fn optimal_checks(ledger: &mut Ledger) -> ([QSqrt2; 3], QSqrt2, Option<optimal::Numeric>, String) {
    let numeric = optimal::numeric();
    let [times, unique, amp, trajectory] = optimal::section41(&numeric);
    let printed = optimal::printed_switches();
    let exact_u =
        crate::algo::bspline::bang_bang::amplitude(&printed, &QSqrt2::from_ratio(2, 3, &()));
    let better = optimal::does_better(&exact_u);
    let finding = better.reproduced.clone();
    ledger.record("bspline.sec41.switching_times", times);
    ledger.record("bspline.sec41.uniqueness", unique);
    ledger.record("bspline.sec41.amplitude", amp);
    ledger.record("bspline.sec41.trajectory", trajectory);
    let [certificate, objective] = optimal::dual_claims(&printed, &exact_u);
    let certified = certificate.verdict == super::Verdict::Reproduced;
    ledger.record("bspline.sec41.dual_certificate", certificate);
    ledger.record("bspline.sec41.dual_objective", objective);
    ledger.record(
        "bspline.problem3.missing_constraint",
        statements::problem3_as_printed(&exact_u),
    );
    ledger.record(
        "bspline.sec41.integral_forms",
        statements::integral_forms(&printed, &exact_u),
    );
    ledger.record(
        "bspline.sec41.dual_space",
        statements::dual_space(certified),
    );
    ledger.record("bspline.sec42.solution", optimal::section42());
    let bang_bang_better = better.verdict == super::Verdict::Reproduced;
    ledger.record("bspline.sec4.does_better", better);
    ledger.record(
        "bspline.sec41.dual_variable_space",
        statements::dual_variable_space(),
    );
    ledger.record(
        "bspline.sec5.not_optimal_any",
        statements::not_optimal_any(bang_bang_better),
    );
    (printed, exact_u, numeric, finding)
}

/// Sec. 5: the Gram matrix and the optimal splines.
fn fitting_checks(ledger: &mut Ledger) -> (Vec<Vec<BigRational>>, Vec<fitting::LimitRow>, String) {
    ledger.record("bspline.sec5.support", basis::support());
    ledger.record("bspline.sec5.gram_k3", fitting::gram_k3());
    let (pd, _) = fitting::gram_positive_definite();
    ledger.record("bspline.sec5.gram_positive_definite", pd);
    let (all, tables) = fitting::gram_all(10);
    ledger.record("bspline.sec5.gram_closed_form", all);
    ledger.record("bspline.eq14.interpolation", fitting::interpolation());
    let (limit, limit_rows) = fitting::smoothing_limit();
    let finding = limit.reproduced.clone();
    ledger.record("bspline.eq15.smoothing_limit", limit);
    ledger.record("bspline.eq15.minimizer", statements::minimizer());
    ledger.record(
        "bspline.eq15.limit_each_weight",
        statements::limit_each_weight(),
    );
    ledger.record(
        "bspline.sec6.data_points",
        statements::data_points(&fitting::sample_times()),
    );
    ledger.record(
        "bspline.sec6.vector_separates",
        statements::vector_separates(),
    );
    ledger.record(
        "bspline.sec6.limit_printed_times",
        statements::limit_printed_times(),
    );
    (tables, limit_rows, finding)
}

/// The verdict policy (`ledger` module doc) applied to the claims it changes or qualifies.
fn policy(ledger: &mut Ledger) {
    use crate::ledger::Severity::Minor;
    ledger.amend(
        "bspline.sec41.dual_objective",
        None,
        (
            "max ξa₄",
            "the objective must be 2ξa₄ (c = (0, 0, 0, 2ξ)); ξa₄ is half of U at the optimum",
        ),
        Minor,
        "the factor 2 changes neither the switching times nor U",
    );
    ledger.amend(
        "bspline.problem3.missing_constraint",
        None,
        ("Problem 3: min ‖u‖∞ with zero state at t = 0 and t = 4", "as printed u ≡ 0 solves it; the constraint x(2) = ξ appears only in Sec. 4.1"),
        Minor,
        "Sec. 4.1 adds the constraint before solving, and every number of Sec. 4 is computed with it",
    );
    ledger.amend(
        "bspline.sec41.dual_variable_space",
        None,
        (
            "a* ∈ L₁[0, 4]",
            "a* ∈ R⁴ and Ya* ∈ L₁[0, 4]: the Y is lost (Y is injective, so the reading is unique)",
        ),
        Minor,
        "the next display uses Ya* and ‖Ya*‖_(L₁); no number depends on it",
    );
    ledger.amend(
        "bspline.sec41.dual_space",
        None,
        ("L1 is the dual space of L∞", "L∞ is the dual of L1 (the reading the paper's Theorem 1 uses); the dual of L∞ is larger than L1"),
        Minor,
        "two words swapped; the duality argument and every number use the correct pairing",
    );
    ledger.amend(
        "bspline.sec6.data_points",
        None,
        (
            "ten equally spaced data points {3, 5, …, 19, 20}",
            "gaps 2, …, 2, 1: the odd integers and the curve's end point 20",
        ),
        Minor,
        "the times themselves are printed and used; only the description 'equally spaced' is wrong",
    );
    // Provenance (clause 1): the stroke is ours; the paper prints neither its control points nor its data.
    ledger.amend(
        "bspline.sec6.reconstruction",
        Some(super::Verdict::Illustrated),
        (
            "the stroke of Fig. 3 is reconstructed from ten samples",
            "on a stroke of our own: the paper gives neither the stroke nor its samples",
        ),
        Minor,
        "an illustration of Eq. 14 on invented data",
    );
}
