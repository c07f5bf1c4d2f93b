//! Paper 003: Andersen, Bouzidi, Kristiansen, *Curvature Continuous Path Generation for UAVs
//! based on Generalized Expo-Rational B-Splines*.
//!
//! `setup`: the documented waypoints and parameter sets; `basis`: Eqs. (4), (10)–(18),
//! partition of unity, smoothness; `paths`: Algorithms 1–2, Figs. 5–7, locality.

mod basis;
mod figures;
mod paths;
mod render;
mod setup;
mod statements;

use super::{ClaimSpec, Ledger, Paper, PaperOutput, Verdict};
use crate::algo::gerbs::dubins::DubinsPath;
use crate::algo::gerbs::path::PathPoint;
use crate::ledger::Amendment;
use crate::ledger::Severity::{Material, Minor};

/// The paper's id (its text's file stem; `docs/papers.md` cites the paper).
pub const ID: &str = "003_96e0e92e8c1da747";
/// The short name: the prefix of every claim id and a `--paper` value.
pub const SHORT: &str = "gerbs";
/// Authors and title.
pub const TITLE: &str = "Andersen, Bouzidi, Kristiansen, Curvature Continuous Path Generation for UAVs based on Generalized Expo-Rational B-Splines";

macro_rules! spec {
    ($id:expr, $loc:expr, $st:expr) => {
        ClaimSpec {
            id: $id,
            location: $loc,
            statement: $st,
            published: None,
        }
    };
}

/// The claims of the paper, in report order.
pub const SPECS: &[ClaimSpec] = &[
    spec!("gerbs.eq12_13.closed_forms", "Eqs. (10)–(13)", "for i_k = 2, S_k∫Ψ_k equals Φ on (t_{k−1}, t_k) and Θ on (t_k, t_{k+1})"),
    spec!("gerbs.eq14_18.derivatives", "Eqs. (14)–(18)", "the printed first and second derivatives of Φ and Θ"),
    spec!("gerbs.eq7_10.beta_kernel", "Eqs. (7)–(10)", "S_k of Eq. (8) normalizes the kernel Ψ_k of Eq. (9) in Eq. (7); Eq. (10) is Eq. (9) with i_k = 2"),
    spec!("gerbs.partition_of_unity", "Eqs. (3), (6)–(7)", "the basis functions sum to 1 on every knot interval"),
    spec!("gerbs.sec4.support_at_knot", "Sec. IV, on Fig. 1", "the local support for B_k is zero when t = t_k, which means that the BFBS will interpolate the local curve when t = t_k"),
    spec!("gerbs.interpolates_at_knot", "Eqs. (3), (11)", "B_k(t_k) = 1, so the curve interpolates c_k at t_k"),
    spec!("gerbs.bfbs.smoothness", "Sec. II-B", "the BFBS is C^m with m = min i_k"),
    spec!("gerbs.erbs.smoothness", "Sec. II-A", "for α > 0 the ERBS basis is C^∞ (all one-sided derivatives vanish at the knots)"),
    spec!("gerbs.sec2.derivatives_vanish", "Sec. II-A", "all derivatives of c_k(t)B_k(t) are zero at t_{k−1} and t_{k+1} for lines, arcs and Bézier curves"),
    spec!("gerbs.eq6.f_conditions", "Sec. II-B, after Eq. (6)", "F_j is monotonously increasing and left-continuous, and the left-hand limits satisfy F(t_{j−1}+) = F(t_{i_1}) = 0 and F(t_i+) = F(t_i) = 1"),
    spec!("gerbs.erbs.parameter_range", "Sec. II-A, after Eq. (4)", "with α_k > 0, β_k > 0, γ_k > 0, 1 ≥ λ_k ≥ 0, σ_k ≥ 0 the basis B_k(t) is C^∞"),
    spec!("gerbs.sec2.second_order_bspline", "Sec. II-A", "in contrast to normal B-splines where a second order B-spline is C¹ continuous"),
    spec!("gerbs.alg2.loop_range", "Algorithm 2, step 9; Eq. (1)", "for t ∈ (T[1], T[n+2]): evaluate the path"),
    spec!("gerbs.sec2.cdr_rule", "Sec. II-A; Sec. IV", "a B-spline of degree d is C^{d−r} at a knot of multiplicity r; an order-two B-spline would not give a smooth path"),
    spec!("gerbs.sec3.lines_c0", "Sec. I", "a path of straight lines between the waypoints is only C⁰"),
    spec!("gerbs.eq1_25.index_range", "Eqs. (1), (25); Algorithm 2", "p(t) = Σ_{i=1}^n c_i(t)B_i(t) over the knots t_1…t_{n+2}"),
    spec!("gerbs.alg1.degenerate_turns", "Sec. III (\"{s_i} ∈ {−1, 1} using Algorithm 1\"); Algorithm 1, steps 8, 10, 12", "Algorithm 1 gives unit tangents m_i and turning directions s_i ∈ {−1, 1} for the waypoints"),
    spec!("gerbs.alg1.returns_s", "Algorithm 1, step 14; Algorithm 2, step 1", "Algorithm 1 returns m; Algorithm 2 takes (W, m, s)"),
    spec!("gerbs.alg2.end_curves", "Algorithm 2, steps 4–5; Sec. III, Eqs. (23)–(24); Fig. 4", "the first and last local curves are straight lines, the others arcs (Algorithm 2 builds the local curves)"),
    spec!("gerbs.fig3.curvature_reduced", "Sec. IV, on Figs. 2–3", "the intrinsic parameters are chosen to give a smooth transition at the peaks, which reduces the required curvature"),
    spec!("gerbs.fig2.parameters", "Fig. 2 caption, Sec. IV", "the ERBS of Fig. 2 (α = 0, β = 3, γ = 1, σ = 0.2, λ = 0.5) generates a C^∞ curve"),
    spec!("gerbs.eq4.centre", "Eq. (4)", "the centre term of Ψ_k, |t − (1−λ_k)t_k + λ_k t_{k+1}|, as in the cited ERBS definition"),
    spec!("gerbs.sec3.knots", "Sec. III, before Algorithm 1", "t_1 = t_2 = 0, t_j = t_{j−1} + 1/(n−1), t_{n+1} = t_{n+2} = 1: a consistent knot vector (Fig. 1's for n = 5)"),
    spec!("gerbs.sec3.knot_vector_words", "Sec. III, before Algorithm 1", "the knot vector is strictly increasing with interior multiplicity of zero, where t_1 = t_2 = 0 and t_{n+1} = t_{n+2} = 1"),
    spec!("gerbs.alg2.interpolates", "Sec. III, Algorithm 2", "the GERBS path interpolates every waypoint"),
    spec!("gerbs.alg2.tangent", "Eqs. (19)–(22), Algorithm 1", "the local arcs give the path the tangent m_i (travel direction) at each waypoint, for left and right turns"),
    spec!("gerbs.alg2.curvature_continuous", "Sec. II-B; Sec. III", "for the case when i_k = 2 a curvature continuous path can be constructed (BFBS i = 2: C²; checked also on the ERBS with α = σ = 1, where the path is C^∞)"),
    spec!("gerbs.sec4.order_smoothness", "Sec. IV, on Fig. 1", "by reducing the order of the beta function a smoother path is generated, while the local support remains the same"),
    spec!("gerbs.fig6.bfbs_vs_erbs", "Figs. 5–6", "BFBS and ERBS paths compared; the BFBS turns are tighter"),
    spec!("gerbs.fig7.dubins", "Fig. 7", "the ERBS path follows the Dubins path closely but keeps curvature continuous"),
    spec!("gerbs.locality", "Sec. II-A", "changing the position of a local curve has only local effect on the entire curve p(t)"),
    spec!("gerbs.sec2.waypoint_edit", "Sec. II-A; Sec. II-B", "changes to the location of a waypoint do not require complete reevaluation of the entire path; changing the position of a waypoint only requires recomputation of the connected path segments"),
    spec!("gerbs.abstract.midpoints", "Abstract", "a global smooth path which also interpolates the midpoint of the curves"),
    spec!("gerbs.sec3.erbs_path_smooth", "Sec. II-A; Sec. III; Abstract; Sec. V", "if the internal knots are simple, p(t) is C^∞ smooth when Expo-Rational basis functions are used, hence curvature continuous"),
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

/// What the checks of paper 003 computed, for the report.
struct Results {
    /// Smoothness at the knots, BFBS then ERBS.
    smoothness: Vec<basis::SmoothRow>,
    /// The two readings of Eq. (4)'s centre, one row each.
    centre: Vec<Vec<String>>,
    /// Algorithm 2 at the waypoints, one row per basis and arc convention.
    algorithm2: Vec<Vec<String>>,
    /// The BFBS and ERBS paths sampled in f64.
    bfbs_points: Vec<PathPoint<f64>>,
    erbs_points: Vec<PathPoint<f64>>,
    /// The Dubins legs between the waypoints.
    legs: Vec<DubinsPath<f64>>,
}

/// Why each of this paper's claims that is only certified or floating is not proven (issue
/// 36); the ledger appends the reason to the claim's evidence.
const UNPROVEN: &[(&str, &str)] = &[
    ("gerbs.fig3.curvature_reduced", SAMPLED),
    ("gerbs.fig6.bfbs_vs_erbs", SAMPLED),
    ("gerbs.fig7.dubins", SAMPLED),
];
const SAMPLED: &str = "a maximum or comparison over f64 samples of the path; a proven one needs the path in balls and a branch-and-bound search (not yet done)";

/// Run every check of paper 003 and build its report.
pub fn verify() -> PaperOutput {
    let mut ledger = Ledger::new(ID, SPECS);
    ledger.explain_unproven(UNPROVEN);
    let (smoothness, centre) = basis_checks(&mut ledger);
    let (interp, tangent, curvature, algorithm2) = paths::algorithm2();
    ledger.record("gerbs.alg2.interpolates", interp);
    ledger.record("gerbs.alg2.tangent", tangent);
    ledger.record("gerbs.alg1.returns_s", paths::algorithm1_returns_s());
    ledger.record("gerbs.alg2.end_curves", paths::end_curves());
    ledger.record(
        "gerbs.alg1.degenerate_turns",
        statements::degenerate_turns(),
    );
    ledger.record(
        "gerbs.fig3.curvature_reduced",
        paths::curvature_by_parameters(),
    );
    ledger.record("gerbs.alg2.curvature_continuous", curvature);
    let (cmp, bfbs_points, erbs_points) = paths::bfbs_vs_erbs();
    ledger.record("gerbs.fig6.bfbs_vs_erbs", cmp);
    let (dubins, legs) = paths::against_dubins(&erbs_points);
    ledger.record("gerbs.fig7.dubins", dubins);
    let (locality, waypoint_edit) = paths::locality();
    ledger.record("gerbs.locality", locality);
    ledger.record("gerbs.sec2.waypoint_edit", waypoint_edit);
    ledger.record("gerbs.abstract.midpoints", paths::abstract_midpoints());
    ledger.record("gerbs.sec3.erbs_path_smooth", paths::erbs_path_smooth());
    let results = Results {
        smoothness,
        centre,
        algorithm2,
        bfbs_points,
        erbs_points,
        legs,
    };
    policy(&mut ledger);
    render::report(&results, ledger.finish())
}

/// The basis claims: closed forms, partition of unity, smoothness, Eq. (4)'s centre.
fn basis_checks(ledger: &mut Ledger) -> (Vec<basis::SmoothRow>, Vec<Vec<String>>) {
    let (closed, derivs) = basis::closed_forms();
    ledger.record("gerbs.eq12_13.closed_forms", closed);
    ledger.record("gerbs.eq14_18.derivatives", derivs);
    ledger.record("gerbs.eq7_10.beta_kernel", statements::beta_kernel());
    ledger.record(
        "gerbs.sec4.order_smoothness",
        statements::order_and_support(),
    );
    ledger.record("gerbs.sec3.knots", statements::knot_rule());
    ledger.record(
        "gerbs.sec3.knot_vector_words",
        statements::knot_vector_words(),
    );
    ledger.record(
        "gerbs.sec2.derivatives_vanish",
        statements::derivatives_vanish(),
    );
    ledger.record("gerbs.sec2.cdr_rule", statements::continuity_rule());
    ledger.record(
        "gerbs.sec2.second_order_bspline",
        statements::second_order_bspline(),
    );
    ledger.record("gerbs.eq6.f_conditions", statements::f_conditions());
    ledger.record("gerbs.alg2.loop_range", paths::loop_range());
    ledger.record("gerbs.sec3.lines_c0", statements::polyline_c0());
    ledger.record("gerbs.eq1_25.index_range", statements::index_range());
    let (partition, at_knot) = basis::partition();
    ledger.record("gerbs.partition_of_unity", partition);
    ledger.record("gerbs.interpolates_at_knot", at_knot);
    ledger.record("gerbs.sec4.support_at_knot", basis::support_at_knot());
    let (bfbs, mut rows) = basis::bfbs_smoothness();
    ledger.record("gerbs.bfbs.smoothness", bfbs);
    let (erbs_smooth, fig2, sigma_range, erbs_rows) = basis::erbs_smoothness();
    rows.extend(erbs_rows);
    ledger.record("gerbs.erbs.smoothness", erbs_smooth);
    ledger.record("gerbs.fig2.parameters", fig2);
    ledger.record("gerbs.erbs.parameter_range", sigma_range);
    let (centre, centre_rows) = basis::centre_reading();
    ledger.record("gerbs.eq4.centre", centre);
    (rows, centre_rows)
}

/// The findings of paper 003: (claim, new verdict if the policy changes it, what the paper
/// prints, how the computation differs, severity, why). Typos follow clause 3, the
/// illustrations clause 1 (the paper's waypoints are not printed; ours are used, and the ERBS
/// parameters α = σ = 1 stand for the α = 0, σ = 0.2 of Figs. 2–3, with which the basis is only
/// C⁰, gerbs.fig2.parameters).
const AMENDMENTS: &[Amendment] = &[
    ("gerbs.sec3.erbs_path_smooth", None, "the ERBS path is C^∞, hence curvature continuous", "with the paper's σ = 0.2 the curvature is unbounded at every interval's centre (see the reproduced value): the path is C¹ only", Material, "curvature continuity of the ERBS path is the paper's conclusion, and its own parameters (Figs. 2–4, 6, 7) break it"),
    ("gerbs.sec2.waypoint_edit", None, "moving a waypoint recomputes only the connected segments", "with Algorithm 1's tangents re-run, three local curves change and on five waypoints the whole path; with the tangents kept, only the moved curve's two intervals", Minor, "the blending step is local (gerbs.locality); the sentence omits that Algorithm 1 couples neighbouring tangents"),
    ("gerbs.abstract.midpoints", None, "interpolates the midpoint of the curves", "the arcs' midpoints (the waypoints) are interpolated; the end lines are met at their ends, not their midpoints (see the reproduced value)", Minor, "the abstract's wording; Sec. III states where the path meets each curve"),
    ("gerbs.fig2.parameters", None, "α = 0, σ = 0.2 give a C^∞ ERBS", "with α = 0 the basis is only C⁰ at every knot, and σ = 0.2 leaves a derivative unbounded at each centre", Material, "the paper's smoothness conclusion for its own parameters fails"),
    ("gerbs.eq4.centre", Some(Verdict::Typo), "|t − (1−λ_k)t_k + λ_k t_{k+1}|", "the parentheses around (1−λ)t_k + λt_{k+1} are lost: as printed the centre leaves the interval", Material, "Eq. (4) is the kernel a reader implements; as printed it gives an asymmetric basis"),
    ("gerbs.alg2.tangent", None, "the arcs run with the tangent m_i", "Eqs. (21)–(22) sweep every arc clockwise: left turns run backwards", Material, "a reader implementing Eqs. (21)–(22) gets a path that reverses at every left turn"),
    ("gerbs.sec4.order_smoothness", None, "a lower beta order gives a smoother path", "the path is C^i: a higher order gives a smoother path", Minor, "the rule a reader implements, Sec. II-B's C^m with m = min i_k, is printed correctly, and the paths use i_k = 2; no conclusion rests on the sentence (clause 7)"),
    ("gerbs.sec2.derivatives_vanish", None, "all derivatives of c_k B_k vanish at t_{k±1} (ERBS, 1 ≥ λ_k ≥ 0)", "at λ = 0, an end of the stated range, the rising basis function leaves its knot with slope 1/S_j ≠ 0 (see the reproduced value); inside the range (0 < λ < 1) it holds", Minor, "the paper's examples use λ = 0.5, where it holds; the root is the stated parameter range (gerbs.erbs.parameter_range)"),
    ("gerbs.sec3.knot_vector_words", None, "a strictly increasing knot vector … where t_1 = t_2 = 0", "the end knots repeat, so the vector is increasing, not strictly; the interior knots are simple", Minor, "the printed knots themselves are consistent (gerbs.sec3.knots)"),
    ("gerbs.eq1_25.index_range", None, "p(t) = Σ_{i=1}^n c_i(t)B_i(t), knots t_1…t_{n+2}", "the knots define B_2…B_{n+1}, Algorithm 2's range; B_1 would need t_0", Minor, "Algorithm 2, which a reader implements, uses the consistent range"),
    ("gerbs.alg1.returns_s", None, "Algorithm 1 returns m", "it must return (m, s): Algorithm 2 takes s, and without it every right turn bends the wrong way", Minor, "s is computed in Algorithm 1 and its use in Algorithm 2 is printed"),
    ("gerbs.sec4.support_at_knot", None, "B_k is zero when t = t_k", "B_k(t_k) = 1; the basis functions that vanish at t_k are B_(k±1)", Minor, "one index; the sentence's conclusion (interpolation at t_k) is what B_k(t_k) = 1 gives"),
    ("gerbs.eq6.f_conditions", None, "F(t_{j−1}+) = F(t_{i_1}) = 0 and F(t_i+) = F(t_i) = 1", "indices i_1 and i that Eq. (6) does not define and a right-hand limit at the right end; the consistent reading F(t_{j−1}) = 0, F(t_j−) = F(t_j) = 1 holds for the BFBS", Minor, "the bases the paper uses satisfy the consistent reading; no number depends on it"),
    ("gerbs.erbs.parameter_range", None, "B_k ∈ C^∞ for α_k > 0, β_k > 0, γ_k > 0, 1 ≥ λ_k ≥ 0, σ_k ≥ 0", "a non-integer σ (the paper's own σ = 0.2) leaves B″ unbounded at the centre of each knot interval: C¹ only; σ ∈ ℕ₀ keeps C^∞", Material, "Figs. 2–4, 6 and 7 use σ = 0.2, and a reader taking the stated range gets unbounded curvature between the waypoints"),
    ("gerbs.sec2.second_order_bspline", None, "a second order B-spline is C¹ continuous", "C⁰ for C¹: a second-order B-spline (degree 1, the order whose interpolating property the paper invokes next) is C⁰ at simple knots; degree 2 is C¹ but does not interpolate", Minor, "one digit; the paper's own C^(d−r) rule gives C⁰, and the argument (ERBS raise the continuity without raising the degree) stands"),
    ("gerbs.alg2.loop_range", None, "for t ∈ (T[1], T[n+2])", "the open right end never evaluates t = 1, where the path reaches W_n; Eq. (1)'s domain (t_1, t_{n+2}] includes it", Minor, "one bracket; Eq. (1) fixes the reading and no printed number depends on it"),
    ("gerbs.alg1.degenerate_turns", None, "unit tangents and turns s_i ∈ {−1, 1} from Algorithm 1, no condition on the waypoints", "a straight continuation gives s = 0 and a path that passes its knot 2R past the waypoint; a U-turn divides by zero in step 8; for n = 2, s[2] is never set", Material, "a reader implementing Algorithm 1 silently misses a collinear waypoint by 2R (the precedent of gerbs.alg2.end_curves)"),
    ("gerbs.alg2.end_curves", None, "straight lines at the first and last waypoints (text, Fig. 4)", "Algorithm 2 as printed builds arcs there, and the path then misses the first and last waypoints by 2R sin(θ_o/2)", Material, "a reader implementing Algorithm 2 as printed gets a path that does not start and end at its waypoints"),
    ("gerbs.fig3.curvature_reduced", None, "parameters chosen to reduce the required curvature (Figs. 2–3)", "on waypoints of our own: the paper gives no waypoints and no reference curvature", Minor, "an illustration; the paper draws no quantitative conclusion from it"),
    ("gerbs.fig6.bfbs_vs_erbs", Some(Verdict::Illustrated), "BFBS and ERBS paths compared (Figs. 5–6)", "on waypoints of our own and ERBS parameters α = σ = 1, not the paper's α = 0, σ = 0.2", Minor, "the figures' data are not in the paper"),
    ("gerbs.fig7.dubins", Some(Verdict::Illustrated), "the ERBS path follows the Dubins path and keeps curvature continuous", "on waypoints of our own with R = 80 and α = σ = 1 (the paper gives neither): the ERBS curvature is continuous but peaks far above the Dubins 1/R (see the reproduced value)", Material, "a vehicle whose turn radius is R could not fly the ERBS path, against the paper's conclusion"),
];

/// The verdict policy (`ledger` module doc) applied to the claims it changes or qualifies.
fn policy(ledger: &mut Ledger) {
    ledger.apply(AMENDMENTS);
}
