//! Paper 002: Kano, Egerstedt, Nakata & Martin, *B-splines and control theory*.
//!
//! Most claims are exact: Table 1 and the basis properties (`basis`), the bang-bang optimum
//! in Q(√2) beside its certified numerical solution (`optimal`), the Gram matrix and the
//! optimal splines (`fitting`).

mod basis;
mod fitting;
mod optimal;

use super::{ClaimSpec, Ledger, Paper, PaperOutput};
use crate::algo::bspline::bang_bang::response;
use crate::algo::bspline::CardinalBSpline;
use crate::report::plot::{self, Corner, Panel, Series, Style};
use crate::report::{claims_section, table};
use crate::scalar::certify::format_float_digits;
use crate::scalar::qsqrt2::QSqrt2;
use crate::scalar::{BigRational, Field, Float};

/// The paper's id (file name in `../shared/papers`).
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
    ClaimSpec { id: "bspline.sec3.eqs3_5", location: "Sec. 3, Eqs. 3–5", statement: "solving (3)–(5) gives b = −3a, c = 3a, d = −a", published: Some("b = -3a, c = 3a, d = -a") },
    ClaimSpec { id: "bspline.sec3.eq6_is_basis", location: "Sec. 3, Eq. 6", statement: "Eq. 6 is the cubic B-spline, a being a scaling parameter", published: None },
    ClaimSpec { id: "bspline.sec3.eq7", location: "Sec. 3, Eq. 7", statement: "the third derivative is 2a, −6a, 6a, −2a on the four unit intervals", published: Some("2a, -6a, 6a, -2a") },
    ClaimSpec { id: "bspline.sec41.switching_times", location: "Sec. 4.1, Eq. 9", statement: "the system for r has the unique solution r = (2+√2, 2, 2−√2), so t = (2−√2, 2, 2+√2)", published: Some("t1 = 2 - sqrt(2), t2 = 2, t3 = 2 + sqrt(2)") },
    ClaimSpec { id: "bspline.sec41.uniqueness", location: "Sec. 4.1", statement: "the solution with 4 > r1 > r2 > r3 > 0 is unique", published: None },
    ClaimSpec { id: "bspline.sec41.amplitude", location: "Sec. 4.1", statement: "U = (2+√2)/2 for ξ = 2/3", published: Some("(2 + sqrt(2))/2") },
    ClaimSpec { id: "bspline.sec41.trajectory", location: "Sec. 4.1, Fig. 1", statement: "the bang-bang x(t) meets x(4) = ẋ(4) = ẍ(4) = 0 and x(2) = 2/3, with the printed closed form", published: None },
    ClaimSpec { id: "bspline.sec42.solution", location: "Sec. 4.2", statement: "the continuity equations at t2 with a+b+c+d = 4 give c = b = √2, a = d = 2−√2", published: Some("a = d = 2 - sqrt(2), b = c = sqrt(2)") },
    ClaimSpec { id: "bspline.sec4.does_better", location: "Sec. 4", statement: "there is a bang-bang control law that does better than the uniform B-spline", published: None },
    ClaimSpec { id: "bspline.sec5.gram_k3", location: "Sec. 5", statement: "for k = 3, g_ij = ĝ_|i−j| with ĝ0 = 20, ĝ1 = −15, ĝ2 = 6, ĝ3 = −1, ĝi = 0 for i ≥ 4", published: Some("20, -15, 6, -1") },
    ClaimSpec { id: "bspline.sec5.gram_positive_definite", location: "Sec. 5", statement: "the matrix G is positive definite", published: None },
    ClaimSpec { id: "bspline.sec5.gram_closed_form", location: "Sec. 5 (beyond the paper)", statement: "the Gram entries for k = 1…10, and a closed form for them", published: None },
    ClaimSpec { id: "bspline.eq14.interpolation", location: "Eqs. 13–14", statement: "τ* = G⁻¹Bᵀ(BG⁻¹Bᵀ)⁻¹α solves min τᵀGτ subject to Bτ = α", published: None },
    ClaimSpec { id: "bspline.eq15.smoothing_limit", location: "Eq. 15", statement: "as w_i → ∞ the smoothing solution τ̂* converges to the interpolating τ*", published: None },
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

/// Parts of the paper with a quantitative statement that no claim covers, and why (shown in
/// the report's "Not checked" section).
const NOT_CHECKED: &[(&str, &str)] = &[
    (
        "Fig. 2 (the character ‘Ru’ from a cubic spline)",
        "the control points p_i and the cone-and-plane rendering are not given; Sec. 6 is checked on a stroke of our own instead (the Fig. 3 analogue above)",
    ),
    (
        "Sec. 4, L∞ optimality of the bang-bang control (the dual certificate)",
        "the optimum is verified as the printed solution, not yet proved optimal by constructing the dual certificate; not yet a claim: found missing by reading the paper against the ledger, to be added",
    ),
    (
        "Sec. 4, the printed dual objective max ξa4",
        "against the constraint ⟨(2−t)₊², u⟩ = 2ξ; not yet a claim: found missing by reading the paper against the ledger, to be added",
    ),
    (
        "Sec. 3, B_k for general k and the support of B3(t_j − i + 1)",
        "not yet a claim: found missing by reading the paper against the ledger, to be added",
    ),
];

fn figure_name(n: u32) -> String {
    super::figure_file(ID, n)
}

/// Run every check of paper 002 and build its report.
pub fn verify() -> PaperOutput {
    let mut ledger = Ledger::new(ID, SPECS);
    let mut figures = Vec::new();
    let mut md = super::report_heading(ID, SHORT, TITLE);

    // Sec. 2: Table 1 and the basis.
    let (rows, t1) = basis::table1();
    md.push_str("## Table 1: N_{j,k} for k = 0…3\n\n");
    let body: Vec<Vec<String>> = rows
        .iter()
        .map(|r| {
            let comparison = if r.equal { "equal" } else { "different" };
            vec![
                r.k.to_string(),
                r.j.to_string(),
                r.printed.clone(),
                r.ours.clone(),
                comparison.into(),
            ]
        })
        .collect();
    md.push_str(&table(
        &["k", "j", "published", "Algorithm 1 (exact)", "comparison"],
        &body,
    ));
    md.push('\n');
    ledger.record("bspline.table1.n_jk", t1);
    ledger.record("bspline.alg1.de_boor_cox", basis::algorithm1_vs_de_boor());
    let [ends, smooth, unity] = basis::properties();
    ledger.record("bspline.eq2.end_derivatives", ends);
    ledger.record("bspline.eq2.smoothness", smooth);
    ledger.record("bspline.eq2.partition_of_unity", unity);
    let [eqs, eq6, eq7] = basis::geometric();
    md.push_str(&format!(
        "## Sec. 3: the geometric construction\n\n- Eqs. 3–5: {}\n- Eq. 6: {}\n- Eq. 7: {}\n\n",
        eqs.reproduced, eq6.reproduced, eq7.reproduced
    ));
    ledger.record("bspline.sec3.eqs3_5", eqs);
    ledger.record("bspline.sec3.eq6_is_basis", eq6);
    ledger.record("bspline.sec3.eq7", eq7);

    // Sec. 4: bang-bang.
    let numeric = optimal::numeric();
    let [times, unique, amp, trajectory] = optimal::section41(&numeric);
    md.push_str("## Sec. 4: the minimum-L∞ control\n\n");
    let printed = optimal::printed_switches();
    let exact_u =
        crate::algo::bspline::bang_bang::amplitude(&printed, &QSqrt2::from_ratio(2, 3, &()));
    let mut rows = Vec::new();
    if let Some(n) = &numeric {
        let names = ["t1", "t2", "t3"];
        for i in 0..3 {
            rows.push(vec![
                names[i].to_string(),
                ["2 − √2", "2", "2 + √2"][i].into(),
                printed[i].to_plain_string(),
                n.switches[i].text.clone(),
                n.switches[i].digits.to_string(),
            ]);
        }
        rows.push(vec![
            "U (ξ = 2/3)".into(),
            "(2 + √2)/2".into(),
            exact_u.to_plain_string(),
            n.amplitude.text.clone(),
            n.amplitude.digits.to_string(),
        ]);
    }
    md.push_str(&table(
        &[
            "quantity",
            "published",
            "exact (Q(√2))",
            "Newton, MPFR 128/256 bits",
            "certified digits",
        ],
        &rows,
    ));
    let better = optimal::does_better(&exact_u);
    md.push_str(&format!(
        "\n{}\n\n![Fig. 1](./{})\n\n",
        better.reproduced,
        figure_name(1)
    ));
    figures.push((
        figure_name(1),
        plot::render_or_note(&fig1_panels(&printed, &exact_u), (1, 2), (1100, 420)),
    ));
    ledger.record("bspline.sec41.switching_times", times);
    ledger.record("bspline.sec41.uniqueness", unique);
    ledger.record("bspline.sec41.amplitude", amp);
    ledger.record("bspline.sec41.trajectory", trajectory);
    ledger.record("bspline.sec42.solution", optimal::section42());
    ledger.record("bspline.sec4.does_better", better);

    // Sec. 5: Gram matrix and optimal splines.
    ledger.record("bspline.sec5.gram_k3", fitting::gram_k3());
    let (pd, _) = fitting::gram_positive_definite();
    ledger.record("bspline.sec5.gram_positive_definite", pd);
    let (all, tables) = fitting::gram_all(10);
    md.push_str("## Sec. 5: Gram entries ĝ_0…ĝ_k of the k-th derivatives (exact integrals; closed form (−1)^m C(2k, k+m))\n\n");
    let body: Vec<Vec<String>> = tables
        .iter()
        .enumerate()
        .map(|(i, g)| {
            vec![
                (i + 1).to_string(),
                g.iter()
                    .map(|x| x.to_string())
                    .collect::<Vec<_>>()
                    .join(", "),
            ]
        })
        .collect();
    md.push_str(&table(&["k", "ĝ_0, ĝ_1, …, ĝ_k"], &body));
    md.push_str("\nThe paper prints k = 3: 20, −15, 6, −1.\n\n");
    ledger.record("bspline.sec5.gram_closed_form", all);
    ledger.record("bspline.eq14.interpolation", fitting::interpolation());
    let (limit, limit_rows) = fitting::smoothing_limit();
    md.push_str("## Eq. 15: smoothing → interpolation as w → ∞\n\n");
    let body: Vec<Vec<String>> = limit_rows
        .iter()
        .map(|r| {
            vec![
                format!("1e{}", r.exponent),
                format_float_digits(&r.distance, 6),
            ]
        })
        .collect();
    md.push_str(&table(
        &["w (W = wI)", "‖τ̂(w) − τ*‖ (exact, rounded)"],
        &body,
    ));
    md.push_str(&format!("\n{}\n\n", limit.reproduced));
    ledger.record("bspline.eq15.smoothing_limit", limit);

    // Sec. 6.
    md.push_str("## Sec. 6: reconstructing a stroke (Fig. 3 analogue)\n\n");
    match fitting::reconstruction() {
        Some((recs, planar)) => {
            md.push_str(&format!(
                "The paper's character data are not printed. Ours: a cubic spline in R³ with the 20 control points (counting multiplicities) {:?}, sampled at t = 3, 5, …, 19, 20 and reconstructed per coordinate (k = 3, M = 20).\n\n",
                fitting::stroke_control_points()
            ));
            let fmt = |x: f64| format_float_digits(&Float::with_val(53, x), 4);
            let body: Vec<Vec<String>> = recs
                .iter()
                .map(|r| {
                    vec![
                        r.label.clone(),
                        fmt(r.max_to_original),
                        fmt(r.max_to_interpolation),
                    ]
                })
                .collect();
            md.push_str(&table(
                &[
                    "reconstruction",
                    "max distance to the original on [3, 20]",
                    "max distance to the interpolation",
                ],
                &body,
            ));
            md.push_str(&format!("\n![Fig. 3](./{})\n\n", figure_name(3)));
            figures.push((
                figure_name(3),
                plot::render_or_note(&fig3_panels(&planar), (1, 1), (760, 620)),
            ));
            ledger.record(
                "bspline.sec6.reconstruction",
                fitting::reconstruction_claim(&recs),
            );
        }
        None => md.push_str("The reconstruction failed.\n\n"),
    }

    let claims = ledger.finish();
    md.push_str(&crate::report::not_checked_section(NOT_CHECKED));
    md.push_str(&claims_section(&claims));
    PaperOutput {
        claims,
        markdown: md,
        figures,
    }
}

fn fig1_panels(t: &[QSqrt2; 3], u: &QSqrt2) -> Vec<Panel> {
    let b3 = CardinalBSpline::<BigRational>::from_algorithm1(3, &());
    let grid: Vec<BigRational> = (0..=400)
        .map(|i| BigRational::new(i.into(), 100.into()))
        .collect();
    let bang: Vec<(f64, f64)> = grid
        .iter()
        .map(|s| {
            (
                s.to_f64(),
                response(t, u, &QSqrt2::from_rational(s, &()))[0].to_f64(),
            )
        })
        .collect();
    let spline: Vec<(f64, f64)> = grid
        .iter()
        .map(|s| (s.to_f64(), b3.eval(s).to_f64()))
        .collect();
    let (t1, t3, uf) = (t[0].to_f64(), t[2].to_f64(), u.to_f64());
    let control = vec![
        (0.0, uf),
        (t1, uf),
        (t1, -uf),
        (2.0, -uf),
        (2.0, uf),
        (t3, uf),
        (t3, -uf),
        (4.0, -uf),
    ];
    let spline_control = vec![
        (0.0, 1.0),
        (1.0, 1.0),
        (1.0, -3.0),
        (2.0, -3.0),
        (2.0, 3.0),
        (3.0, 3.0),
        (3.0, -1.0),
        (4.0, -1.0),
    ];
    vec![
        Panel {
            title: "Fig. 1: x(t), bang-bang optimum and B_3".into(),
            x_label: "t (time units)".into(),
            y_label: "x (length units)".into(),
            series: vec![
                Series::new("bang-bang x(t)", bang, Style::Solid, 0),
                Series::new("B_3(t)", spline, Style::Dotted, 1),
            ],
            legend: Corner::UpperRight,
            ..Panel::default()
        },
        Panel {
            title: "controls u = x'''".into(),
            x_label: "t (time units)".into(),
            y_label: "u = x‴ (length/time³)".into(),
            series: vec![
                Series::new("bang-bang, U = (2+√2)/2", control, Style::Solid, 0),
                Series::new("B_3'''", spline_control, Style::Dotted, 1),
            ],
            legend: Corner::LowerLeft,
            ..Panel::default()
        },
    ]
}

fn fig3_panels(planar: &[Vec<(f64, f64)>]) -> Vec<Panel> {
    let names = ["original", "W = I", "W = 10I", "W = 100I", "interpolation"];
    let styles = [
        Style::Solid,
        Style::Dotted,
        Style::Dashed,
        Style::Solid,
        Style::Dotted,
    ];
    let mut series: Vec<Series> = planar
        .iter()
        .zip(names.iter().zip(styles))
        .enumerate()
        .map(|(i, (pts, (n, s)))| Series::new(*n, pts.clone(), s, i))
        .collect();
    let polygon: Vec<(f64, f64)> = fitting::stroke_control_points()
        .iter()
        .map(|p| (p[0] as f64, p[1] as f64))
        .collect();
    series.push(Series::new(
        "control polygon",
        polygon,
        Style::LineMarkers,
        5,
    ));
    vec![Panel {
        title: "Fig. 3 analogue: smoothing reconstructions (xy projection)".into(),
        x_label: "x (data units)".into(),
        y_label: "y (data units)".into(),
        series,
        equal_aspect: true,
        legend: Corner::UpperRight,
        ..Panel::default()
    }]
}
