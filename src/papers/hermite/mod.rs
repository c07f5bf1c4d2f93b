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

use super::{Ledger, Paper, PaperOutput};
use crate::papers::ClaimSpec;
use crate::report::plot::{self, Corner, Panel, Series, Style};
use crate::report::{claims_section, table};
use crate::scalar::certify::format_float_digits;
use crate::scalar::{Field, Float};

/// The paper's id (file name in `../shared/papers`).
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
    ClaimSpec { id: "hermite.fig5.kappa_grows", location: "Sec. 4, Fig. 5", statement: "the condition number grows with the number of derivatives", published: None },
    ClaimSpec { id: "hermite.fig5.interval_changes_kappa", location: "Sec. 4, text after Fig. 4", statement: "increasing or decreasing the interval will have an impact on the condition number", published: None },
    ClaimSpec { id: "hermite.sec4.degree_elevation", location: "Sec. 4, end", statement: "a Bernstein polynomial can be degree elevated: the curve is exactly represented with more control points", published: None },
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
        "Fig. 1",
        "an illustration of a Bernstein curve and its control points; the paper gives neither the control points nor any value read from the figure",
    ),
    (
        "Sec. 3, n = 2(m+1)",
        "the degree stated against the 2m+1 that Eqs. 14–15 and Fig. 2 need; not yet a claim: found missing by reading the paper against the ledger, to be added",
    ),
    (
        "Sec. 3.1, x0⁽¹⁾ = nΔ¹p0",
        "printed without the factor 1/(t1−t0); not yet a claim: found missing by reading the paper against the ledger, to be added",
    ),
    (
        "Sec. 2.3, the order rises by two per derivative (tenth derivative → order twenty-one)",
        "not yet a claim: found missing by reading the paper against the ledger, to be added",
    ),
    (
        "Fig. 2, the acceleration of the shorter duration",
        "not yet a claim: found missing by reading the paper against the ledger, to be added",
    ),
    (
        "Eq. 4, the endpoint properties",
        "not yet a claim: found missing by reading the paper against the ledger, to be added",
    ),
];

fn figure_name(n: u32) -> String {
    super::figure_file(ID, n)
}

/// Run every check of paper 000 and build its report.
pub fn verify() -> PaperOutput {
    let mut ledger = Ledger::new(ID, SPECS);
    let mut figures = Vec::new();
    let mut md = super::report_heading(ID, SHORT, TITLE);

    // Fig. 2
    let (fast, fast_curve) = exact::fig2(1, FIG2_FAST);
    let (slow, slow_curve) = exact::fig2(2, FIG2_SLOW);
    md.push_str("## Fig. 2: control points for H = [0 0 0 | 1 1 0]\n\n");
    md.push_str(&table(
        &["duration", "published", "reproduced (exact)", "verdict"],
        &[
            vec![
                "1".into(),
                format!("[{FIG2_FAST}]"),
                fast.reproduced.clone(),
                fast.verdict.as_str().into(),
            ],
            vec![
                "2".into(),
                format!("[{FIG2_SLOW}]"),
                slow.reproduced.clone(),
                slow.verdict.as_str().into(),
            ],
        ],
    ));
    md.push_str(&format!("\n![Fig. 2](./{})\n\n", figure_name(2)));
    figures.push((
        figure_name(2),
        plot::render_or_note(&fig2_panels(&fast_curve, &slow_curve), (1, 3), (1200, 380)),
    ));
    ledger.record("hermite.fig2.control_points.t1", fast);
    ledger.record("hermite.fig2.control_points.t2", slow);

    // Exact identities.
    ledger.record(
        "hermite.eq12_15.boundary_conditions",
        exact::boundary_conditions(),
    );
    ledger.record("hermite.eq13.derivatives", exact::eq13_derivatives());
    let (ranges, _) = exact::eq16_17_index_ranges();
    md.push_str("## Eqs. 16–18: which control points each end determines\n\n");
    md.push_str(&format!(
        "Eqs. 16–17 as printed give the start data m+2 control points and the end data m; the exact map gives each end m+1:\n\n\
         - printed: p_0…p_(m+1) from the start, p_(m+2)…p_(2m+1) from the end;\n- computed: {}.\n\n{}\n\n",
        ranges.reproduced, ranges.evidence
    ));
    ledger.record("hermite.eq16_17.index_ranges", ranges);
    ledger.record("hermite.eq18.vector", exact::eq18_vector());
    let (eq8_printed, eq8_restored) = exact::eq8();
    ledger.record("hermite.eq8.as_printed", eq8_printed);
    ledger.record("hermite.eq8.minus_restored", eq8_restored);
    ledger.record("hermite.eq9.self_inverse", exact::eq9_self_inverse());
    ledger.record("hermite.appA.a1_a2_inverse", exact::a1_a2_inverse());
    ledger.record("hermite.appA.a3_self_inverse", exact::a3_self_inverse());

    // Fig. 3
    md.push_str("## Fig. 3: one turn, three durations\n\n");
    md.push_str(
        "Data (ours; the paper prints none): a uniform quarter turn of radius 1 at speed 1, start (0, 0) with velocity (1, 0) \
         and acceleration (0, 1), end (1, 1) with velocity (0, 1) and acceleration (−1, 0); m = 2; nominal duration π/2 (the \
         circle's). Criteria fixed beforehand: *straight* = closer to the chord than to the arc (Hausdorff distance); \
         *circular* = closer to the arc than to the chord; *loops away* = gets farther from the terminal point than it started.\n\n",
    );
    match examples::turn_metrics() {
        Some(metrics) => {
            let rows: Vec<Vec<String>> = metrics
                .iter()
                .map(|t| {
                    vec![
                        if t.factor.1 == 1 {
                            t.factor.0.to_string()
                        } else {
                            format!("{}/{}", t.factor.0, t.factor.1)
                        },
                        examples::fmt4(t.duration),
                        examples::fmt4(t.hausdorff_chord),
                        examples::fmt4(t.hausdorff_arc),
                        examples::fmt4(t.max_radial_deviation),
                        examples::fmt4(t.farthest_from_end),
                        examples::fmt4(t.turning_degrees),
                        examples::fmt4(t.max_speed),
                    ]
                })
                .collect();
            md.push_str(&table(
                &[
                    "× nominal",
                    "duration",
                    "Hausdorff to chord",
                    "Hausdorff to arc",
                    "max radial dev.",
                    "max dist. to end / start's",
                    "tangent turning (°)",
                    "peak speed",
                ],
                &rows,
            ));
            md.push_str(&format!("\n![Fig. 3](./{})\n\n", figure_name(3)));
            figures.push((
                figure_name(3),
                plot::render_or_note(&examples::turn_figure(&metrics), (1, 1), (640, 640)),
            ));
            let [short, nominal, long] = examples::turn_claims(&metrics);
            ledger.record("hermite.fig3.short_is_straight", short);
            ledger.record("hermite.fig3.nominal_is_circular", nominal);
            ledger.record("hermite.fig3.long_loops_away", long);
        }
        None => md.push_str("The Fig. 3 instance failed to solve.\n\n"),
    }

    // Fig. 4
    md.push_str("## Fig. 4: landing\n\n");
    match examples::landing() {
        Some(l) => {
            let rows: Vec<Vec<String>> = ["x", "y", "z"]
                .iter()
                .zip(&l.curve)
                .map(|(name, b)| {
                    vec![
                        name.to_string(),
                        b.control_points
                            .iter()
                            .map(|c| c.to_plain_string())
                            .collect::<Vec<_>>()
                            .join(", "),
                    ]
                })
                .collect();
            md.push_str("Data (ours): runway along +x, threshold at the origin; start on the downwind leg at (0, 2000, 300) m flying (−60, 0, 0) m/s, zero acceleration; cross the threshold at (55, 0, 0) m/s, zero acceleration, after 60 s (a standard-rate 180° turn). Exact control points (m):\n\n");
            md.push_str(&table(&["coordinate", "control points p_0 … p_5"], &rows));
            let claim = examples::landing_claim(&l);
            md.push_str(&format!(
                "\n{}\n\n![Fig. 4](./{})\n\n",
                claim.evidence,
                figure_name(4)
            ));
            figures.push((
                figure_name(4),
                plot::render_or_note(&examples::landing_figure(&l), (1, 2), (1100, 420)),
            ));
            ledger.record("hermite.fig4.landing_constraints", claim);
        }
        None => md.push_str("The landing instance failed to solve.\n\n"),
    }

    // Fig. 5
    let rows = conditioning::table();
    md.push_str(&fig5_section(&rows));
    figures.push((
        figure_name(5),
        plot::render_or_note(&fig5_panels(&rows), (1, 1), (900, 560)),
    ));
    let [kappa_table, grows, interval] = conditioning::claims(&rows);
    ledger.record("hermite.fig5.kappa_table", kappa_table);
    ledger.record("hermite.fig5.kappa_grows", grows);
    ledger.record("hermite.fig5.interval_changes_kappa", interval);

    ledger.record("hermite.sec4.degree_elevation", exact::degree_elevation());

    let claims = ledger.finish();
    md.push_str(&crate::report::not_checked_section(NOT_CHECKED));
    md.push_str(&claims_section(&claims));
    PaperOutput {
        claims,
        markdown: md,
        figures,
    }
}

fn fig2_panels(
    fast: &crate::numeric::poly::Bernstein<crate::scalar::BigRational>,
    slow: &crate::numeric::poly::Bernstein<crate::scalar::BigRational>,
) -> Vec<Panel> {
    let titles = ["position", "velocity", "acceleration"];
    (0..3)
        .map(|j| {
            let series_for = |b: &crate::numeric::poly::Bernstein<crate::scalar::BigRational>,
                              name: &str,
                              style: Style,
                              color: usize| {
                let d = b.nth_derivative(j);
                let f: crate::numeric::poly::Bernstein<f64> = crate::numeric::poly::Bernstein::new(
                    d.control_points.iter().map(Field::to_f64).collect(),
                    d.t0.to_f64(),
                    d.t1.to_f64(),
                );
                let pts = (0..=200).map(|i| {
                    let t = f.t1 * i as f64 / 200.0;
                    (t, f.eval(&t))
                });
                Series::new(name, pts.collect(), style, color)
            };
            let ends = |b: &crate::numeric::poly::Bernstein<crate::scalar::BigRational>| {
                vec![
                    (0.0, b.derivative_at_start(j).to_f64()),
                    (b.t1.to_f64(), b.derivative_at_end(j).to_f64()),
                ]
            };
            Panel {
                title: format!("Fig. 2: {}", titles[j]),
                x_label: "t (time units)".into(),
                y_label: [
                    "position (length units)",
                    "velocity (length/time)",
                    "acceleration (length/time²)",
                ][j]
                    .into(),
                series: vec![
                    series_for(fast, "duration 1", Style::Solid, 0),
                    series_for(slow, "duration 2", Style::Dotted, 1),
                    Series::new(
                        "constraints",
                        [ends(fast), ends(slow)].concat(),
                        Style::Markers,
                        2,
                    ),
                ],
                legend: [Corner::LowerRight, Corner::LowerRight, Corner::UpperRight][j],
                ..Panel::default()
            }
        })
        .collect()
}

fn fmt_kappa(k: &Option<conditioning::Kappa>, digits: u32) -> String {
    k.as_ref().map_or("—".into(), |k| {
        format_float_digits(&k.exact, digits.min(k.value.digits))
    })
}

fn fig5_section(rows: &[conditioning::KappaRow]) -> String {
    let mut md = String::from("## Fig. 5: condition number of the transform\n\n");
    md.push_str(
        "κ2 = σmax/σmin (Eq. 10) of the matrix taking p_0…p_(2m+1) to H (Eqs. 14–15), for m derivatives at each end. Certified \
         column: MPFR at p and 2p bits, printed to 20 of its certified digits (the full values are in `claims.json` evidence \
         where needed). f64 columns: nalgebra's SVD and our one-sided Jacobi, each on the correctly rounded f64 matrix, with \
         their correct digits against the certified value. *binomial* is the same matrix without the factors n!/(n−j)!/T^j.\n\n",
    );
    let body: Vec<Vec<String>> = rows
        .iter()
        .map(|r| {
            let bits = r.unit.as_ref().map_or(0, |k| k.bits);
            let digits = r.unit.as_ref().map_or(0, |k| k.value.digits);
            let rel = match (r.nalgebra, &r.unit) {
                (Some(a), Some(k)) => format_float_digits(
                    &Float::with_val(53, crate::scalar::certify::relative_error(a, &k.exact)),
                    2,
                ),
                _ => "—".into(),
            };
            vec![
                r.m.to_string(),
                fmt_kappa(&r.unit, 20),
                format!("{digits} ({bits}/{} bits)", 2 * bits),
                match r.nalgebra {
                    None => "— (overflow)".into(),
                    Some(k) if k.is_infinite() => "∞ (σmin = 0)".into(),
                    Some(k) => crate::scalar::float_text(k),
                },
                rel,
                conditioning::f64_digits(r.nalgebra, &r.unit).to_string(),
                conditioning::f64_digits(r.jacobi_f64, &r.unit).to_string(),
                fmt_kappa(&r.durations[0], 6),
                fmt_kappa(&r.durations[1], 6),
                fmt_kappa(&r.durations[2], 6),
                fmt_kappa(&r.binomial, 6),
            ]
        })
        .collect();
    md.push_str(&table(
        &[
            "m",
            "κ2, T = 1 (certified)",
            "certified digits (precisions)",
            "f64 nalgebra",
            "rel. error",
            "f64 nalgebra digits",
            "f64 Jacobi digits",
            "T = 1/2",
            "T = 2",
            "T = 10",
            "binomial, T = 1",
        ],
        &body,
    ));
    md.push_str(&format!(
        "\nGrowth law observed: {}.\n\nnalgebra's f64 value has no correct digit from m = {}.\n\n![Fig. 5](./{})\n\n",
        conditioning::growth_law(rows),
        conditioning::f64_breakdown(rows).map_or("— (never)".to_string(), |m| m.to_string()),
        figure_name(5)
    ));
    md
}

fn fig5_panels(rows: &[conditioning::KappaRow]) -> Vec<Panel> {
    let line = |f: &dyn Fn(&conditioning::KappaRow) -> Option<f64>| {
        rows.iter()
            .filter_map(|r| f(r).map(|v| (r.m as f64, v)))
            .collect::<Vec<_>>()
    };
    let mut series = vec![Series::new(
        "T = 1 (certified)",
        line(&|r| r.unit.as_ref().map(|k| k.value.approx)),
        Style::LineMarkers,
        0,
    )];
    for (i, &(n, d)) in conditioning::DURATIONS.iter().enumerate() {
        let name = if d == 1 {
            format!("T = {n}")
        } else {
            format!("T = {n}/{d}")
        };
        series.push(Series::new(
            name,
            line(&|r| r.durations[i].as_ref().map(|k| k.value.approx)),
            Style::Solid,
            i + 1,
        ));
    }
    series.push(Series::new(
        "binomial, T = 1",
        line(&|r| r.binomial.as_ref().map(|k| k.value.approx)),
        Style::Dashed,
        5,
    ));
    series.push(Series::new(
        "f64 nalgebra SVD, T = 1 (∞ not drawn)",
        line(&|r| r.nalgebra),
        Style::Markers,
        4,
    ));
    vec![Panel {
        title: "Fig. 5: κ2 of the Hermite transform".into(),
        x_label: "m (derivatives at each end)".into(),
        y_label: "κ2 (dimensionless)".into(),
        series,
        log_y: true,
        ..Panel::default()
    }]
}
