//! Paper 003: Andersen, Bouzidi, Kristiansen, *Curvature Continuous Path Generation for UAVs
//! based on Generalized Expo-Rational B-Splines*.
//!
//! `setup`: the documented waypoints and parameter sets; `basis`: Eqs. (4), (10)–(18),
//! partition of unity, smoothness; `paths`: Algorithms 1–2, Figs. 5–7, locality.

mod basis;
mod paths;
mod setup;

use super::{ClaimSpec, Ledger, Paper, PaperOutput};
use crate::algo::gerbs::basis_derivatives;
use crate::algo::gerbs::bfbs::Bfbs;
use crate::algo::gerbs::erbs::CentreReading;
use crate::algo::gerbs::path::{ArcConvention, PathPoint};
use crate::algo::gerbs::Side;
use crate::report::plot::{self, Corner, Panel, Series, Style};
use crate::report::{claims_section, table};
use setup::ErbsSet;

/// The paper's id (file name in `../shared/papers`).
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
    spec!("gerbs.partition_of_unity", "Eqs. (3), (6)–(7)", "the basis functions sum to 1 on every knot interval"),
    spec!("gerbs.interpolates_at_knot", "Eqs. (3), (11)", "B_k(t_k) = 1, so the curve interpolates c_k at t_k"),
    spec!("gerbs.bfbs.smoothness", "Sec. II-B", "the BFBS is C^m with m = min i_k"),
    spec!("gerbs.erbs.smoothness", "Sec. II-A", "for α > 0 the ERBS basis is C^∞ (all one-sided derivatives vanish at the knots)"),
    spec!("gerbs.fig2.parameters", "Fig. 2 caption, Sec. IV", "the ERBS of Fig. 2 (α = 0, β = 3, γ = 1, σ = 0.2, λ = 0.5) generates a C^∞ curve"),
    spec!("gerbs.eq4.centre", "Eq. (4)", "the centre term of Ψ_k, |t − (1−λ_k)t_k + λ_k t_{k+1}|, as in the cited ERBS definition"),
    spec!("gerbs.alg2.interpolates", "Sec. III, Algorithm 2", "the GERBS path interpolates every waypoint"),
    spec!("gerbs.alg2.tangent", "Eqs. (19)–(22), Algorithm 1", "the local arcs give the path the tangent m_i (travel direction) at each waypoint, for left and right turns"),
    spec!("gerbs.alg2.curvature_continuous", "Sec. III", "the path is curvature continuous (BFBS i = 2: C²; ERBS: C^∞)"),
    spec!("gerbs.fig6.bfbs_vs_erbs", "Figs. 5–6", "BFBS and ERBS paths compared; the BFBS turns are tighter"),
    spec!("gerbs.fig7.dubins", "Fig. 7", "the ERBS path follows the Dubins path closely but keeps curvature continuous"),
    spec!("gerbs.locality", "Sec. II", "moving one waypoint changes the path only on its neighbouring knot intervals"),
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
const NOT_CHECKED: &[(&str, &str)] = &[];

fn figure_name(n: u32) -> String {
    super::figure_file(ID, n)
}

/// Run every check of paper 003 and build its report.
pub fn verify() -> PaperOutput {
    let mut ledger = Ledger::new(ID, SPECS);
    let mut md = super::report_heading(ID, SHORT, TITLE);
    md.push_str(&format!(
        "Documented inputs (the paper gives R, θ_o and the knot vector, not the waypoints): waypoints {:?}, R = {}, θ_o = π/8, line length l = 2Rθ_o, knots {{0, 0, 1/4, 2/4, 3/4, 1, 1}} (Fig. 1). ERBS parameter sets: {}, {}, {} (λ = 0.5, β = 3, γ = 1 throughout). The ERBS paths of Figs. 3–7 use the last set (see the Fig. 2 claim for why). Certified values agree between 128 and 256 bits.\n\n",
        setup::WAYPOINTS,
        setup::RADIUS,
        ErbsSet::Fig2Literal.label(),
        ErbsSet::Fig2Alpha1.label(),
        ErbsSet::Smooth.label()
    ));

    let (closed, derivs) = basis::closed_forms();
    ledger.record("gerbs.eq12_13.closed_forms", closed);
    ledger.record("gerbs.eq14_18.derivatives", derivs);
    let (partition, at_knot) = basis::partition();
    ledger.record("gerbs.partition_of_unity", partition);
    ledger.record("gerbs.interpolates_at_knot", at_knot);

    let mut smooth_rows = Vec::new();
    ledger.record(
        "gerbs.bfbs.smoothness",
        basis::bfbs_smoothness(&mut smooth_rows),
    );
    let (erbs_smooth, fig2) = basis::erbs_smoothness(&mut smooth_rows);
    ledger.record("gerbs.erbs.smoothness", erbs_smooth);
    ledger.record("gerbs.fig2.parameters", fig2);
    md.push_str("## Smoothness at the knots\n\nBFBS: the largest jump over all basis functions of B^(r), r = 1 … i_k + 1, exact. ERBS: the largest |B^(r)(t_k ± ε)|, r = 1…8, over t_3, t_4, t_5 (α > 0), or B_4′ from both sides (α = 0).\n\n");
    md.push_str(&table(
        &["basis", "knot", "jumps / values", "class"],
        &smooth_rows
            .iter()
            .map(|r| {
                vec![
                    r.basis.clone(),
                    r.knot.clone(),
                    r.jumps.join(", "),
                    r.class.clone(),
                ]
            })
            .collect::<Vec<_>>(),
    ));
    let (centre, centre_rows) = basis::centre_reading();
    ledger.record("gerbs.eq4.centre", centre);
    md.push_str("\n## Eq. (4): the centre term\n\nα = 1, σ = 0.2, λ = 0.5 on the Fig. 1 knots; interval (1/4, 1/2).\n\n");
    md.push_str(&table(
        &[
            "reading",
            "centre",
            "peak of Ψ_3 (fraction of interval)",
            "max |B_4(t_4 − s) − B_4(t_4 + s)|",
        ],
        &centre_rows,
    ));

    let (interp, tangent, curvature, alg_rows) = paths::algorithm2();
    ledger.record("gerbs.alg2.interpolates", interp);
    ledger.record("gerbs.alg2.tangent", tangent);
    ledger.record("gerbs.alg2.curvature_continuous", curvature);
    md.push_str("\n## Algorithm 2 at the waypoints\n\ncos(p′, m_i) at W1…W5 (turns: W2 right, W3 left, W4 right), the largest |p(t_k) − W|, and the largest one-sided jumps of κ and dκ/dt at the interior knots (256 bits; digits agreeing with 128 bits).\n\n");
    md.push_str(&table(
        &[
            "basis",
            "arc angles",
            "max interpolation error",
            "cos(p′, m_i)",
            "κ jump",
            "dκ/dt jump",
        ],
        &alg_rows,
    ));

    let (cmp, bfbs_pts, erbs_pts) = paths::bfbs_vs_erbs();
    ledger.record("gerbs.fig6.bfbs_vs_erbs", cmp);
    let (dubins, legs) = paths::against_dubins(&erbs_pts);
    ledger.record("gerbs.fig7.dubins", dubins);
    md.push_str("\n## Dubins legs (Fig. 7)\n\n");
    md.push_str(&table(
        &["leg", "word", "segment lengths", "total"],
        &legs
            .iter()
            .enumerate()
            .map(|(i, l)| {
                vec![
                    format!("W{} → W{}", i + 1, i + 2),
                    l.word_name(),
                    l.lengths
                        .iter()
                        .map(|x| format!("{x:.2}"))
                        .collect::<Vec<_>>()
                        .join(", "),
                    format!("{:.2}", l.total()),
                ]
            })
            .collect::<Vec<_>>(),
    ));
    ledger.record("gerbs.locality", paths::locality());

    let printed =
        setup::erbs_path::<f64>(&(), ErbsSet::Smooth, ArcConvention::AsPrinted).sample(801);
    let mut figures = vec![
        (figure_name(1), figure1()),
        (figure_name(2), figure2()),
        (figure_name(3), figure3(&erbs_pts, &printed)),
        (figure_name(4), figure4(&erbs_pts)),
        (figure_name(5), path_figure(&[("BFBS (i = 2)", &bfbs_pts)])),
        (figure_name(6), figure6(&bfbs_pts, &erbs_pts)),
        (figure_name(7), figure7(&erbs_pts, &legs)),
    ];
    md.push_str("\n## Figures\n\n");
    for (n, caption) in [
        (1, "Fig. 1: BFBS basis (i = 2) on the knots of Fig. 1"),
        (
            2,
            "Fig. 2: ERBS basis for the three parameter sets and both readings of Eq. (4)",
        ),
        (
            3,
            "Fig. 3: ERBS path; middle: Eqs. (21)–(22) as printed; right: both, zoomed where they differ most (the printed arc angles make left turns run backwards)",
        ),
        (4, "Fig. 4: ERBS path with its local curves"),
        (5, "Fig. 5: BFBS path"),
        (6, "Fig. 6: BFBS vs ERBS, paths and curvature"),
        (7, "Fig. 7: ERBS vs Dubins, paths and curvature"),
    ] {
        md.push_str(&format!("![{caption}]({})\n\n", figure_name(n)));
    }
    let claims = ledger.finish();
    md.push_str(&crate::report::not_checked_section(NOT_CHECKED));
    md.push_str(&claims_section(&claims));
    figures.sort_by(|a, b| a.0.cmp(&b.0));
    PaperOutput {
        claims,
        markdown: md,
        figures,
    }
}

fn curve(name: &str, pts: Vec<(f64, f64)>, style: Style, color: usize) -> Series {
    Series::new(name, pts, style, color)
}

fn basis_panel(
    title: &str,
    knots: &crate::algo::gerbs::Knots<f64>,
    blend: &dyn crate::algo::gerbs::Blend<f64>,
) -> Panel {
    let mut series = Vec::new();
    for k in 0..5 {
        let pts = (0..=400)
            .map(|i| {
                let t = i as f64 / 400.0;
                let side = if i == 400 { Side::Left } else { Side::Right };
                (
                    t,
                    basis_derivatives(knots, blend, &t, 0, side).map_or(0.0, |d| d[k][0]),
                )
            })
            .collect();
        series.push(curve(&format!("B_{}", k + 2), pts, Style::Solid, k % 6));
    }
    Panel {
        title: title.into(),
        x_label: "t (knot parameter)".into(),
        y_label: "B_k(t) (dimensionless)".into(),
        series,
        legend: Corner::UpperRight,
        ..Panel::default()
    }
}

fn figure1() -> String {
    let k = setup::fig1_knots::<f64>(&());
    let b = Bfbs::uniform(2, 5).expect("exponents");
    plot::render_or_note(&[basis_panel("BFBS, i = 2", &k, &b)], (1, 1), (800, 500))
}

fn figure2() -> String {
    let k = setup::fig1_knots::<f64>(&());
    let panels: Vec<Panel> = [
        (ErbsSet::Fig2Literal, CentreReading::Cited),
        (ErbsSet::Fig2Alpha1, CentreReading::Cited),
        (ErbsSet::Fig2Alpha1, CentreReading::AsPrinted),
        (ErbsSet::Smooth, CentreReading::Cited),
    ]
    .iter()
    .map(|&(set, reading)| {
        let e = setup::erbs::<f64>(&(), set, reading);
        let r = if reading == CentreReading::Cited {
            "cited centre"
        } else {
            "Eq. (4) as printed"
        };
        basis_panel(&format!("{}, {r}", set.label()), &k, &e)
    })
    .collect();
    plot::render_or_note(&panels, (2, 2), (1200, 800))
}

fn xy(pts: &[PathPoint<f64>]) -> Vec<(f64, f64)> {
    pts.iter().map(|p| (p.point[0], p.point[1])).collect()
}

fn waypoint_series() -> Series {
    curve(
        "waypoints",
        setup::WAYPOINTS
            .iter()
            .map(|w| (w[0] as f64, w[1] as f64))
            .collect(),
        Style::Markers,
        0,
    )
}

/// A panel of paths in the plane (equal axes) with the waypoints marked.
fn plane_panel(title: &str, mut series: Vec<Series>) -> Panel {
    series.push(waypoint_series());
    Panel {
        title: title.into(),
        x_label: "x (length units)".into(),
        y_label: "y (length units)".into(),
        series,
        equal_aspect: true,
        legend: Corner::LowerLeft,
        ..Panel::default()
    }
}

fn path_figure(paths: &[(&str, &[PathPoint<f64>])]) -> String {
    let panels: Vec<Panel> = paths
        .iter()
        .map(|(name, pts)| plane_panel(name, vec![curve(name, xy(pts), Style::Solid, 1)]))
        .collect();
    let cols = panels.len();
    plot::render_or_note(&panels, (1, cols), (700 * cols as u32, 500))
}

/// Fig. 3: the path with arcs swept in the turn direction, the path of Eqs. (21)–(22) as
/// printed, and both overlaid in a window around the printed point farthest from the other
/// path (the turn the printed angles concern), since at full scale the difference is a few
/// units on a path of 1200.
fn figure3(turn: &[PathPoint<f64>], printed: &[PathPoint<f64>]) -> String {
    let (a, b) = (xy(turn), xy(printed));
    let distance_to_a = |q: &(f64, f64)| {
        a.iter()
            .map(|p| (p.0 - q.0).hypot(p.1 - q.1))
            .fold(f64::INFINITY, f64::min)
    };
    let (far, gap) = b
        .iter()
        .enumerate()
        .map(|(i, q)| (i, distance_to_a(q)))
        .fold((0, 0.0), |m, x| if x.1 > m.1 { x } else { m });
    // The window spans the farthest point and the waypoint of the turn nearest to it.
    let point = b.get(far).copied().unwrap_or((0.0, 0.0));
    let turn_at = setup::WAYPOINTS
        .iter()
        .map(|w| (w[0] as f64, w[1] as f64))
        .min_by(|p, q| {
            let d = |w: &(f64, f64)| (w.0 - point.0).hypot(w.1 - point.1);
            d(p).total_cmp(&d(q))
        })
        .unwrap_or(point);
    let centre = ((point.0 + turn_at.0) / 2.0, (point.1 + turn_at.1) / 2.0);
    let half =
        ((point.0 - turn_at.0).abs().max((point.1 - turn_at.1).abs()) / 2.0 + 3.0 * gap).max(40.0);
    let inside = |p: &(f64, f64)| (p.0 - centre.0).abs() <= half && (p.1 - centre.1).abs() <= half;
    let clip = |pts: &[(f64, f64)]| pts.iter().copied().filter(inside).collect::<Vec<_>>();
    let zoom = Panel {
        title: format!(
            "zoom: the printed path passes {gap:.1} from the other at t = {:.3}",
            printed.get(far).map_or(0.0, |p| p.t)
        ),
        x_label: "x (length units)".into(),
        y_label: "y (length units)".into(),
        series: vec![
            curve("turn direction", clip(&a), Style::Solid, 1),
            curve("as printed", clip(&b), Style::Dashed, 2),
            curve("waypoint", vec![turn_at], Style::Markers, 0),
        ],
        equal_aspect: true,
        legend: Corner::UpperLeft,
        ..Panel::default()
    };
    let panels = vec![
        plane_panel(
            "ERBS, arcs swept in the turn direction",
            vec![curve("turn direction", a.clone(), Style::Solid, 1)],
        ),
        plane_panel(
            "ERBS, Eqs. (21)-(22) as printed",
            vec![curve("as printed", b.clone(), Style::Dashed, 2)],
        ),
        zoom,
    ];
    plot::render_or_note(&panels, (1, 3), (2100, 550))
}

fn figure4(erbs: &[PathPoint<f64>]) -> String {
    let p = setup::erbs_path::<f64>(&(), ErbsSet::Smooth, ArcConvention::TurnDirection);
    let mut series = vec![curve("ERBS path", xy(erbs), Style::Solid, 1)];
    for (i, c) in p.curves.iter().enumerate() {
        let pts = (0..=50)
            .map(|j| {
                let q = c.at(&(j as f64 / 50.0));
                (q[0], q[1])
            })
            .collect();
        series.push(curve(
            if i == 0 { "local curves" } else { "" },
            pts,
            Style::Dashed,
            2,
        ));
    }
    plot::render_or_note(
        &[plane_panel(
            "local curves: lines at the ends, arcs R = 80, theta_o = pi/8",
            series,
        )],
        (1, 1),
        (900, 500),
    )
}

fn curvature_series(name: &str, pts: &[PathPoint<f64>], color: usize) -> Series {
    curve(
        name,
        pts.iter().map(|p| (p.t, p.curvature)).collect(),
        Style::Solid,
        color,
    )
}

fn figure6(bfbs: &[PathPoint<f64>], erbs: &[PathPoint<f64>]) -> String {
    let a = plane_panel(
        "Fig. 6: BFBS and ERBS paths",
        vec![
            curve("BFBS", xy(bfbs), Style::Solid, 2),
            curve("ERBS", xy(erbs), Style::Dashed, 1),
        ],
    );
    let b = Panel {
        title: "signed curvature".into(),
        x_label: "t (knot parameter)".into(),
        y_label: "signed curvature κ (1/length unit)".into(),
        series: vec![
            curvature_series("BFBS", bfbs, 2),
            curvature_series("ERBS", erbs, 1),
        ],
        legend: Corner::LowerLeft,
        ..Panel::default()
    };
    plot::render_or_note(&[a, b], (1, 2), (1400, 500))
}

fn figure7(
    erbs: &[PathPoint<f64>],
    legs: &[crate::algo::gerbs::dubins::DubinsPath<f64>],
) -> String {
    let dubins: Vec<(f64, f64)> = paths::dubins_points(legs, 2.0)
        .iter()
        .map(|p| (p[0], p[1]))
        .collect();
    // Dubins curvature against arc length, and the ERBS curvature against its arc length.
    let mut kd = Vec::new();
    let mut s0 = 0.0;
    for leg in legs {
        let k = leg.curvatures();
        for (kk, l) in k.iter().zip(&leg.lengths) {
            kd.push((s0, *kk));
            s0 += l;
            kd.push((s0, *kk));
        }
    }
    let mut ke = Vec::new();
    let mut s = 0.0;
    for (i, p) in erbs.iter().enumerate() {
        if i > 0 {
            let q = &erbs[i - 1];
            s += (p.point[0] - q.point[0]).hypot(p.point[1] - q.point[1]);
        }
        ke.push((s, p.curvature));
    }
    let a = plane_panel(
        "Fig. 7: Dubins (R = 80) and ERBS paths",
        vec![
            curve("Dubins (R = 80)", dubins, Style::Solid, 2),
            curve("ERBS", xy(erbs), Style::Dashed, 1),
        ],
    );
    let b = Panel {
        title: "signed curvature along the path".into(),
        x_label: "arc length (length units)".into(),
        y_label: "signed curvature κ (1/length unit)".into(),
        series: vec![
            curve("Dubins", kd, Style::Solid, 2),
            curve("ERBS", ke, Style::Dashed, 1),
        ],
        legend: Corner::LowerLeft,
        ..Panel::default()
    };
    plot::render_or_note(&[a, b], (1, 2), (1400, 500))
}
