//! The Markdown report of paper 003, written from the checks' [`Results`](super::Results).

use super::setup::{self, ErbsSet};
use super::{figures, Results, ID, SHORT, TITLE};
use crate::algo::gerbs::path::ArcConvention;
use crate::ledger::{Claim, PaperOutput};
use crate::report::number;
use crate::report::table;

fn figure_name(n: u32) -> String {
    super::super::figure_file(ID, n)
}

/// The figures' captions, in figure order.
const CAPTIONS: [(u32, &str); 7] = [
    (1, "Fig. 1: BFBS basis (i = 2) on the knots of Fig. 1"),
    (
        2,
        "Fig. 2: ERBS basis for the three parameter sets and both readings of Eq. (4). With σ = 0.2 the weight Ψ = exp(−β|t − c|^0.4/…) is sharply peaked at the interval's centre c (|t − c|^0.4 has an infinite slope there), so its running integral, the basis, is nearly a step at c",
    ),
    (
        3,
        "Fig. 3: ERBS path with the arcs swept in the turn direction and with Eqs. (21)–(22) as printed; right: zoomed where they differ most (the printed arc angles make left turns run backwards)",
    ),
    (4, "Fig. 4: ERBS path with its local curves; right: at W2"),
    (5, "Fig. 5: BFBS path; right: at W3, against the waypoint polygon"),
    (6, "Fig. 6: BFBS vs ERBS, where the paths differ most, and their curvature"),
    (7, "Fig. 7: ERBS vs Dubins, paths and curvature"),
];

/// The report and figures of paper 003.
pub fn report(r: &Results, claims: Vec<Claim>) -> PaperOutput {
    let mut md = String::new();
    md.push_str(&format!(
        "Documented inputs (the paper gives R, θ_o and the knot vector, not the waypoints): waypoints {:?}, R = {}, θ_o = π/8, line length l = 2Rθ_o, knots {{0, 0, 1/4, 2/4, 3/4, 1, 1}} (Fig. 1). ERBS parameter sets: {}, {}, {} (λ = 0.5, β = 3, γ = 1 throughout). The ERBS paths of Figs. 3–7 use the last set (see the Fig. 2 claim for why). Certified values agree between 128 and 256 bits.\n\n",
        setup::WAYPOINTS,
        setup::RADIUS,
        ErbsSet::Fig2Literal.label(),
        ErbsSet::Fig2Alpha1.label(),
        ErbsSet::Smooth.label()
    ));
    md.push_str(&tables(r));
    md.push_str("\n## Figures\n\n");
    for (n, caption) in CAPTIONS {
        md.push_str(&format!("![{caption}]({})\n\n", figure_name(n)));
        md.push_str(&material_findings_on(&claims, n));
    }
    super::super::report_output((ID, SHORT, TITLE), md, claims, figures(r))
}

/// The material findings about figure `n`, under the figure, so a reader who looks at the
/// figure sees what it shows (they rest on the documented inputs at the top of the report).
fn material_findings_on(claims: &[Claim], n: u32) -> String {
    let figure = format!("Fig. {n}");
    claims
        .iter()
        .filter(|c| {
            // "Fig. 1" names Fig. 1, not Fig. 12.
            c.location.match_indices(&figure).any(|(i, _)| {
                !c.location[i + figure.len()..].starts_with(|ch: char| ch.is_ascii_digit())
            })
        })
        .filter_map(|c| {
            let f = c.finding.as_ref()?;
            (f.severity == crate::ledger::Severity::Material).then(|| {
                format!(
                    "**Material finding** (`{}`, {}, on the documented inputs above): {}. {}.\n\n",
                    c.id,
                    c.verdict.as_str(),
                    f.computed,
                    f.severity_reason
                )
            })
        })
        .collect()
}

/// The figures in file-name order.
fn figures(r: &Results) -> Vec<(String, String)> {
    let (bfbs, erbs) = (&r.bfbs_points, &r.erbs_points);
    // The smooth ERBS path is finite everywhere; were it not, figure 3 would be missing and
    // the committed-figures test would say so.
    let printed =
        setup::erbs_path::<f64>(&(), ErbsSet::Smooth, ArcConvention::AsPrinted).sample(801);
    let mut figures = vec![
        (figure_name(1), figures::figure1()),
        (figure_name(2), figures::figure2()),
    ];
    if let Ok(printed) = printed {
        figures.push((figure_name(3), figures::figure3(erbs, &printed)));
    }
    figures.extend([
        (figure_name(4), figures::figure4(erbs)),
        (figure_name(5), figures::figure5(bfbs)),
        (figure_name(6), figures::figure6(bfbs, erbs)),
        (figure_name(7), figures::figure7(erbs, &r.legs)),
    ]);
    figures.sort_by(|a, b| a.0.cmp(&b.0));
    figures
}

/// The smoothness, centre, Algorithm 2 and Dubins tables.
fn tables(r: &Results) -> String {
    let mut md = String::from("## Smoothness at the knots\n\nBFBS: the largest jump over all basis functions of B^(r), r = 1 … i_k + 1, exact. ERBS: the largest |B^(r)(t_k ± ε)|, r = 1…8, over t_3, t_4, t_5 (α > 0), or B_4′ from both sides (α = 0).\n\n");
    let smooth: Vec<Vec<String>> = r
        .smoothness
        .iter()
        .map(|r| {
            vec![
                r.basis.clone(),
                r.knot.clone(),
                r.jumps.join(", "),
                r.class.clone(),
            ]
        })
        .collect();
    md.push_str(&table(
        &["basis", "knot", "jumps / values", "class"],
        &smooth,
    ));
    md.push_str("\n## Eq. (4): the centre term\n\nα = 1, σ = 0.2, λ = 0.5 on the Fig. 1 knots; interval (1/4, 1/2).\n\n");
    md.push_str(&table(
        &[
            "reading",
            "centre",
            "max |B_4(t_4 − s) − B_4(t_4 + s)|, s = k/32, k = 1…7 (proven bound)",
        ],
        &r.centre,
    ));
    md.push_str("\n## Algorithm 2 at the waypoints\n\ncos(p′, m_i) at W1…W5 (turns: W2 right, W3 left, W4 right), the largest |p(t_k) − W|, and the largest one-sided jumps of κ and dκ/dt at the interior knots, in ball arithmetic at 256 bits (upper bounds, and the digits each cosine's enclosure proves).\n\n");
    md.push_str(&table(
        &[
            "basis",
            "arc angles",
            "max interpolation error",
            "cos(p′, m_i)",
            "κ jump",
            "dκ/dt jump",
        ],
        &r.algorithm2,
    ));
    md.push_str("\n## Dubins legs (Fig. 7)\n\n");
    let legs: Vec<Vec<String>> = r
        .legs
        .iter()
        .enumerate()
        .map(|(i, l)| {
            vec![
                format!("W{} → W{}", i + 1, i + 2),
                l.word_name(),
                l.lengths
                    .iter()
                    .map(|&x| number::sig(x, 5))
                    .collect::<Vec<_>>()
                    .join(", "),
                number::sig(l.total(), 5),
            ]
        })
        .collect();
    md.push_str(&table(&["leg", "word", "segment lengths", "total"], &legs));
    md
}
