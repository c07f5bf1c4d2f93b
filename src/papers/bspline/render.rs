//! The Markdown report of paper 002, written from the checks' [`Results`](super::Results).

use super::{figures, fitting, Results, ID, SHORT, TITLE};
use crate::ledger::{Claim, PaperOutput};
use crate::report::number;
use crate::report::{plot, table};

fn figure_name(n: u32) -> String {
    super::super::figure_file(ID, n)
}

/// The report and figures of paper 002.
pub fn report(r: &Results, claims: Vec<Claim>) -> PaperOutput {
    let mut md = String::new();
    let mut figures = vec![(
        figure_name(1),
        plot::render_or_note(
            &figures::fig1_panels(&r.printed_switches, &r.amplitude),
            (1, 2),
            (1100, 420),
        ),
    )];
    md.push_str(&table1(r));
    md.push_str(&format!(
        "## Sec. 3: the geometric construction\n\n- Eqs. 3–5: {}\n- Eq. 6: {}\n- Eq. 7: {}\n\n",
        r.geometric[0], r.geometric[1], r.geometric[2]
    ));
    md.push_str(&bang_bang(r));
    md.push_str(&gram_and_limit(r));
    md.push_str("## Sec. 6: reconstructing a stroke (Fig. 3 analogue)\n\n");
    match &r.reconstruction {
        Some((recs, planar)) => {
            md.push_str(&reconstruction(recs));
            figures.push((
                figure_name(3),
                plot::render_or_note(&figures::fig3_panels(planar), (1, 1), (760, 620)),
            ));
        }
        None => md.push_str("The reconstruction failed.\n\n"),
    }
    super::super::report_output((ID, SHORT, TITLE), md, claims, figures)
}

fn table1(r: &Results) -> String {
    let body: Vec<Vec<String>> = r
        .table1
        .iter()
        .map(|r| {
            let comparison = if r.equal { "equal" } else { "different" };
            vec![
                r.k.to_string(),
                r.j.to_string(),
                number::printed(&r.printed),
                r.ours.clone(),
                comparison.into(),
            ]
        })
        .collect();
    format!(
        "## Table 1: N_{{j,k}} for k = 0…3\n\n{}\n",
        table(
            &["k", "j", "published", "Algorithm 1 (exact)", "comparison"],
            &body
        )
    )
}

fn bang_bang(r: &Results) -> String {
    let mut rows = Vec::new();
    if let Some(n) = &r.numeric {
        let names = ["t1", "t2", "t3"];
        for i in 0..3 {
            rows.push(vec![
                names[i].to_string(),
                ["2 − √2", "2", "2 + √2"][i].into(),
                r.printed_switches[i].to_math_string(),
                number::certified(&n.switches[i], number::PROSE_DIGITS),
                n.switches[i].digits.to_string(),
            ]);
        }
        rows.push(vec![
            "U (ξ = 2/3)".into(),
            "(2 + √2)/2".into(),
            r.amplitude.to_math_string(),
            number::certified(&n.amplitude, number::PROSE_DIGITS),
            n.amplitude.digits.to_string(),
        ]);
    }
    let headers = [
        "quantity",
        "published",
        "exact (Q(√2))",
        "Newton, MPFR 128/256 bits (ten digits shown)",
        "certified digits",
    ];
    format!(
        "## Sec. 4: the minimum-L∞ control\n\n{}\n{}\n\n![Fig. 1](./{})\n\n",
        table(&headers, &rows),
        r.does_better,
        figure_name(1)
    )
}

fn gram_and_limit(r: &Results) -> String {
    let mut md = String::from("## Sec. 5: Gram entries ĝ_0…ĝ_k of the k-th derivatives (exact integrals; closed form (−1)^m C(2k, k+m))\n\n");
    let body: Vec<Vec<String>> = r
        .gram
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
    md.push_str("## Eq. 15: smoothing → interpolation as w → ∞\n\n");
    let body: Vec<Vec<String>> = r
        .limit
        .iter()
        .map(|r| {
            vec![
                number::sig_in(
                    10f64.powi(r.exponent as i32),
                    1,
                    number::Notation::Scientific,
                ),
                number::float_in(&r.distance, 6, number::Notation::Scientific),
            ]
        })
        .collect();
    md.push_str(&table(
        &["w (W = wI)", "‖τ̂(w) − τ*‖ (exact, rounded)"],
        &body,
    ));
    md.push_str(&format!("\n{}\n\n", r.limit_finding));
    md
}

fn reconstruction(recs: &[fitting::Reconstruction]) -> String {
    let measured: Vec<Vec<f64>> = recs
        .iter()
        .map(|r| vec![r.max_to_original, r.max_to_interpolation])
        .collect();
    let body: Vec<Vec<String>> = recs
        .iter()
        .zip(number::columns(&measured, 4))
        .map(|(r, cells)| [vec![r.label.clone()], cells].concat())
        .collect();
    let headers = [
        "reconstruction",
        "max distance to the original on [3, 20]",
        "max distance to the interpolation",
    ];
    format!(
        "The paper's character data are not printed. Ours: a cubic spline in R³ with the 20 control points (counting multiplicities) {:?}, sampled at t = 3, 5, …, 19, 20 and reconstructed per coordinate (k = 3, M = 20).\n\n{}\n![Fig. 3](./{})\n\n",
        fitting::stroke_control_points(),
        table(&headers, &body),
        figure_name(3)
    )
}
