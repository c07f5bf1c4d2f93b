//! The Markdown report of paper 004, written from the checks' [`Results`](super::Results).

use super::data::{TABLE1, TABLE3, TABLE4, TABLE6, TABLE7};
use super::geometry::{CornerCurves, H1Row, CORNER};
use super::one_d::{printed_units, TableOne};
use super::overshoot::{axis_range, OvershootRow, FIG9_AXIS};
use super::plane::PlaneSection;
use super::robot::{two_digit_units, RobotSection, NAMES};
use super::{figures, num, Results, ID, SHORT, TITLE};
use crate::ledger::{Claim, PaperOutput};
use crate::report::number;
use crate::report::number::{marked, sig as fmt};
use crate::report::table;
use crate::scalar::{Field, Float};

/// How the printed cells of the tables are marked.
const MARKS: &str = "Printed cells are marked ✓ when the computed value rounds to them, ≈ when only their last digit differs (within one unit), ✗ beyond.\n\n";

fn figure_file(n: u32) -> String {
    super::super::figure_file(ID, n)
}

/// The report and figures of paper 004.
pub fn report(r: &Results, claims: Vec<Claim>) -> PaperOutput {
    let mut md = String::new();
    let mut figures = Vec::new();
    md.push_str(&h1(&r.h1));
    md.push_str("## Table I: the minimizing parametrization of scalar data\n\n");
    if let Some(t) = &r.table1 {
        md.push_str(&table1(t));
        if let Some(s) = &t.spline {
            figures.push((figure_file(1), figures::figure1(s)));
        }
    }
    md.push_str(&plane(&r.plane, &mut figures));
    if let Some(c) = &r.corner {
        md.push_str(&corner(c));
        figures.push((figure_file(6), figures::corner(c)));
    }
    md.push_str(&robot(&r.robot));
    md.push_str(&fig9(&r.fig9, &r.robot, &mut figures));
    super::super::report_output((ID, SHORT, TITLE), md, claims, figures)
}

fn h1(rows: &[H1Row]) -> String {
    let body: Vec<Vec<String>> = rows
        .iter()
        .map(|r| {
            vec![
                r.name.clone(),
                number::float(&r.h1, 6),
                number::float(&r.energy, 6),
                number::float(&Float::with_val(53, r.ratio), 4),
            ]
        })
        .collect();
    let headers = [
        "component, parametrization",
        "‖θ − φ‖²_H¹",
        "∫θ''²",
        "ratio",
    ];
    format!(
        "## Sec. 1 (i): ‖θ − φ‖²_H¹ ≤ ∫θ''²\n\n{}\n",
        table(&headers, &body)
    )
}

fn table1(t: &TableOne) -> String {
    let rows: Vec<Vec<String>> = TABLE1
        .iter()
        .enumerate()
        .map(|(i, (z, printed))| {
            vec![
                i.to_string(),
                number::printed(z),
                marked(printed, Some(printed_units(&t.t_star[i], printed))),
                number::float(&t.t_star[i], 10.min(t.digits[i].max(1))),
                if t.agrees[i] { "agrees" } else { "differs" }.into(),
            ]
        })
        .collect();
    let headers = [
        "i",
        "z_i",
        "published t_i*",
        "computed (MPFR, 10 of its certified digits)",
        "to 4 decimals",
    ];
    format!(
        "{MARKS}{}\n![Fig. 1](./{ID}_fig1.svg)\n\n",
        table(&headers, &rows)
    )
}

fn plane(p: &PlaneSection, figures: &mut Vec<(String, String)>) -> String {
    let mut md = String::from("## Table III: parametrizations of the Table II plane data\n\n");
    let rows: Vec<Vec<String>> = (0..20)
        .map(|i| {
            let mut row = vec![
                i.to_string(),
                marked(TABLE3[i].0, Some(printed_units(&p.chord[i], TABLE3[i].0))),
                number::float(&p.chord[i], 6),
            ];
            for (c, col) in p.columns.iter().enumerate() {
                let printed = [TABLE3[i].1, TABLE3[i].2][c];
                row.push(marked(
                    printed,
                    col.as_ref().map(|k| printed_units(&k.exact[i], printed)),
                ));
                row.push(
                    col.as_ref()
                        .map_or("—".into(), |k| number::float(&k.exact[i], 6)),
                );
            }
            row
        })
        .collect();
    md.push_str(MARKS);
    md.push_str(&table(
        &[
            "i",
            "t^C1 published",
            "t^CL computed",
            "t^EX published",
            "t^EX computed",
            "t^AP published",
            "t^AP computed",
        ],
        &rows,
    ));
    md.push_str(
        "\nComputed columns: chord length at 256 bits; t^EX and t^AP are the minimizers of G (Eqs. 31 and 34), found by gradient projection \
         in f64 from chord length (Eq. 30) and refined by Newton's method on the optimality system at 128 and 256 bits (certified; 6 \
         decimals shown).\n\n",
    );
    md.push_str(&second_derivatives(p));
    md.push_str(&format!("\n![Fig. 2](./{ID}_fig2.svg)\n\n"));
    md.push_str(
        "Figs. 3–5 share one y scale per panel, so the second derivatives can be compared.\n\n",
    );
    let drawn = figures::component_figures(&p.parametrizations, &p.data);
    for (n, ((name, _), svg)) in p.parametrizations.iter().zip(drawn).enumerate() {
        let file = figure_file(n as u32 + 3);
        md.push_str(&format!(
            "![Fig. {}: components with {name}](./{file})\n\n",
            n + 3
        ));
        figures.push((file, svg));
    }
    if let Some(ex) = &p.columns[0] {
        let t: Vec<f64> = ex.exact.iter().map(Field::to_f64).collect();
        figures.push((figure_file(2), figures::figure2(&t, &p.data)));
    }
    md
}

/// Figs. 3–5 as numbers: the component second derivatives per parametrization.
fn second_derivatives(p: &PlaneSection) -> String {
    let mut md = String::new();
    let stat_rows: Vec<Vec<String>> = p
        .parametrizations
        .iter()
        .zip(&p.second_derivatives)
        .map(|((name, _), comps)| {
            std::iter::once(name.to_string())
                .chain(comps.iter().flat_map(|(peak, jumps)| {
                    [
                        crate::report::number::ball(peak, 4),
                        crate::report::number::ball(jumps, 4),
                    ]
                }))
                .collect()
        })
        .collect();
    md.push_str("\n### Figs. 3–5 as numbers: component second derivatives\n\n");
    md.push_str(&table(
        &[
            "parametrization",
            "max |x''|",
            "sum of |jumps| of x'''",
            "max |y''|",
            "sum of |jumps| of y'''",
        ],
        &stat_rows,
    ));
    md
}

fn corner(c: &CornerCurves) -> String {
    format!(
        "## Fig. 6: widely spaced data near a corner\n\nData (ours; the paper prints none): {:?}. Maximum distance of the parametric natural cubic spline from \
         the interpolating polygon: {} with chord length, {} with the minimizing parametrization (exact objective).\n\n![Fig. 6](./{ID}_fig6.svg)\n\n",
        CORNER,
        number::ball(&c.distances.0, 4),
        number::ball(&c.distances.1, 4)
    )
}

fn robot(r: &RobotSection) -> String {
    let rows: Vec<Vec<String>> = (0..21)
        .map(|i| {
            vec![
                i.to_string(),
                marked(TABLE6[i][0], Some(printed_units(&r.chord[i], TABLE6[i][0]))),
                number::float(&r.chord[i], 6),
                marked(
                    TABLE6[i][1],
                    Some(printed_units(&r.work_centre[i], TABLE6[i][1])),
                ),
                number::float(&r.work_centre[i], 6),
                marked(
                    TABLE6[i][2],
                    r.approx
                        .get(i)
                        .map(|x| printed_units(&Float::with_val(53, *x), TABLE6[i][2])),
                ),
                r.approx.get(i).map_or("—".into(), |x| fmt(*x, 6)),
            ]
        })
        .collect();
    let headers6 = [
        "i",
        "t^CL published",
        "t^CL computed",
        "t^WC published",
        "t^WC computed",
        "t^AP published",
        "t^AP computed",
    ];
    let mut body = Vec::new();
    // Empty when Table VII was not computed (its claims fail with the error).
    for c in 0..r.from_printed.len().min(r.from_ours.len()).min(3) {
        let row = |label: String, cells: Vec<String>| -> Vec<String> {
            std::iter::once(label).chain(cells).collect()
        };
        body.push(row(
            format!("{} published", NAMES[c]),
            TABLE7[c]
                .iter()
                .zip(&r.from_printed[c])
                .map(|(s, x)| marked(s, Some(two_digit_units(x, s).to_f64())))
                .collect(),
        ));
        body.push(row(
            format!("{} computed (printed t)", NAMES[c]),
            r.from_printed[c]
                .iter()
                .map(|x| fmt(x.to_f64(), 3))
                .collect(),
        ));
        body.push(row(
            format!("{} computed (our t)", NAMES[c]),
            match &r.from_ours[c] {
                Some(ours) => ours
                    .iter()
                    .map(|x| crate::report::number::ball(x, 3))
                    .collect(),
                None => vec!["—".into(); 6],
            },
        ));
    }
    let headers7 = [
        "parametrization",
        "axis 1",
        "axis 2",
        "axis 3",
        "axis 4",
        "axis 5",
        "axis 6",
    ];
    format!(
        "## Tables VI–VII: the six-axis robot example\n\n{MARKS}{}\n### Table VII: max |d²θ_j/dt²| on [0, 1]\n\n{}\n",
        table(&headers6, &rows),
        table(&headers7, &body)
    )
}

/// Fig. 9: the overshoots of axis #3 on each parametrization, as a table and as the figure.
fn fig9(
    rows: &[OvershootRow],
    robot: &RobotSection,
    figures: &mut Vec<(String, String)>,
) -> String {
    let body: Vec<Vec<String>> = rows
        .iter()
        .map(|r| {
            vec![
                r.parametrization.clone(),
                r.overshooting.to_string(),
                format!("{} (data: {})", r.extrema_between_data, r.data_extrema),
                crate::report::number::ball(&r.largest, 4),
                r.largest.proven_digits().0.to_string(),
            ]
        })
        .collect();
    let headers = [
        "parametrization",
        "overshooting intervals",
        "extrema between data points",
        "largest excursion (rad)",
        "proven digits",
    ];
    let axis: Vec<f64> = TABLE4.iter().map(|r| num(r[FIG9_AXIS]).to_f64()).collect();
    let mut drawn: Vec<(String, Vec<f64>)> = (0..3)
        .map(|c| {
            (
                format!("{} (printed)", NAMES[c]),
                TABLE6.iter().map(|r| num(r[c]).to_f64()).collect(),
            )
        })
        .collect();
    if robot.approx.len() == axis.len() {
        drawn.push(("t^AP (ours)".into(), robot.approx.clone()));
    }
    let counts: Vec<usize> = rows.iter().map(|r| r.overshooting).collect();
    if counts.len() == drawn.len() {
        figures.push((figure_file(9), figures::figure9(&drawn, &axis, &counts)));
    }
    let range = axis_range(&TABLE4.iter().map(|r| num(r[FIG9_AXIS])).collect::<Vec<_>>());
    format!(
        "## Fig. 9: axis #3 on each parametrization\n\nAn interval overshoots when the spline leaves the range of its two end values \
         (Corollary 3 (i)); the excursion is enclosed from the roots of θ′ in balls at 256 bits, every decision proven. Extrema between data points are the spline's \
         local extrema strictly between knots, beside the data's interior extrema: more of them than of the data's are unwanted \
         oscillations. The axis #3 data span {} rad.\n\n{}\n\
         ![Fig. 9: axis #3 natural cubic spline on each parametrization](./{})\n\n",
        fmt(range, 4),
        table(&headers, &body),
        figure_file(9)
    )
}
