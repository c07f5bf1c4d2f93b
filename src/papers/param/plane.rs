//! Claims of Sec. 3, first example: the plane data of Table II, Table III, Figs. 2–5.

use super::super::{Ledger, Outcome, Verdict};
use super::data::{TABLE2, TABLE3};
use super::one_d::compare_with_printed;
use super::{num, ID};
use crate::algo::param::descent::{descend, polish};
use crate::algo::param::natural::NaturalCubicSpline;
use crate::algo::param::objective::{chord_length_spacing, knots_from_spacing, Objective};
use crate::report::plot::{self, Corner, Panel, Series, Style};
use crate::report::table;
use crate::scalar::certify::{certify, format_float_digits, Certified};
use crate::scalar::{Field, Float};

/// The two components (x, y) in a number type.
fn components<T: Field>(ctx: &T::Ctx) -> Vec<Vec<T>> {
    vec![
        TABLE2
            .iter()
            .map(|(x, _)| T::from_rational(&num(x), ctx))
            .collect(),
        TABLE2
            .iter()
            .map(|(_, y)| T::from_rational(&num(y), ctx))
            .collect(),
    ]
}

/// A parametrization certified at two precisions, with the closest gradient-projection iterate.
struct Column {
    name: &'static str,
    knots: Vec<Certified>,
    exact: Vec<Float>,
    iterations: usize,
    converged: bool,
    closest: Option<(usize, f64)>,
}

fn printed(col: usize) -> Vec<&'static str> {
    TABLE3.iter().map(|r| [r.0, r.1, r.2][col]).collect()
}

fn max_dev(t: &[f64], printed: &[&str]) -> f64 {
    t.iter()
        .zip(printed)
        .map(|(a, p)| (a - num(p).to_f64()).abs())
        .fold(0.0, f64::max)
}

/// The minimizer of G in the given form: gradient projection in f64 from chord length (the
/// paper's method), then Newton's method at 128 and 256 bits for the certified minimizer.
fn minimize(form: Objective, col: usize, name: &'static str) -> Option<Column> {
    let z64 = components::<f64>(&());
    let alpha = [1.0, 1.0];
    let h0 = chord_length_spacing(&z64);
    let target = printed(col);
    let mut closest: Option<(usize, f64)> = None;
    let mut observe = |i: usize, h: &[f64]| {
        let dev = max_dev(&knots_from_spacing(h, &()), &target);
        if closest.is_none_or(|(_, d)| dev < d) {
            closest = Some((i, dev));
        }
    };
    let rough = descend(h0, &z64, &alpha, form, &mut observe).ok()?;
    let polish = |bits: u32| -> Option<Vec<Float>> {
        let z = components::<Float>(&bits);
        let h = polish(
            &rough,
            &z,
            &[Float::with_val(bits, 1), Float::with_val(bits, 1)],
            form,
        )
        .ok()?;
        Some(knots_from_spacing(&h, &bits))
    };
    let (lo, hi) = (polish(128)?, polish(256)?);
    Some(Column {
        name,
        knots: lo.iter().zip(&hi).map(|(a, b)| certify(a, b)).collect(),
        exact: hi,
        iterations: rough.iterations,
        converged: rough.converged,
        closest,
    })
}

fn compare(column: &[Float], col: usize) -> (usize, f64) {
    compare_with_printed(column, &printed(col))
}

use crate::report::number::sig as fmt;

/// Table III, Figs. 2–5.
pub fn section(ledger: &mut Ledger, md: &mut String, figures: &mut Vec<(String, String)>) {
    md.push_str("## Table III: parametrizations of the Table II plane data\n\n");
    // Chord length, certified.
    let cl =
        |bits: u32| knots_from_spacing(&chord_length_spacing(&components::<Float>(&bits)), &bits);
    let (cl_lo, cl_hi) = (cl(128), cl(256));
    let chord_digits = cl_lo
        .iter()
        .zip(&cl_hi)
        .map(|(a, b)| certify(a, b).digits)
        .min()
        .unwrap_or(0);
    let (agree, dev) = compare(&cl_hi, 0);
    ledger.record(
        "marin.table3.chord",
        Outcome::new(
            format!("{agree} of 20 entries agree to the 4 printed decimals (largest difference {}; ≥ {chord_digits} certified digits)", fmt(dev, 2)),
            "mpfr:128/256",
            if agree == 20 { Verdict::Reproduced } else { Verdict::Discrepancy },
            "Eq. 5 with Euclidean distances between consecutive Table II points, at 128 and 256 bits; each printed value compared within half a \
             unit of its last decimal",
        ),
    );
    let columns = [
        minimize(Objective::Exact, 1, "t^EX (Eq. 31)"),
        minimize(Objective::Approximate, 2, "t^AP (Eq. 34)"),
    ];
    let mut rows = Vec::new();
    for i in 0..20 {
        let mut row = vec![
            i.to_string(),
            TABLE3[i].0.into(),
            format_float_digits(&cl_hi[i], 6),
        ];
        for (c, col) in columns.iter().enumerate() {
            row.push([TABLE3[i].1, TABLE3[i].2][c].into());
            row.push(
                col.as_ref()
                    .map_or("—".into(), |k| format_float_digits(&k.exact[i], 6)),
            );
        }
        rows.push(row);
    }
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
    for (id, column, col) in [
        ("marin.table3.exact", &columns[0], 1),
        ("marin.table3.approx", &columns[1], 2),
    ] {
        let Some(k) = column else {
            ledger.record(
                id,
                Outcome::new("", "mpfr", Verdict::Failed, "the minimization failed"),
            );
            continue;
        };
        let (agree, dev) = compare(&k.exact, col);
        let min_digits = k.knots.iter().map(|c| c.digits).min().unwrap_or(0);
        let closest = match k.closest {
            None => "no iterate was recorded".to_string(),
            Some((i, d)) if i == k.iterations => format!(
                "no iterate comes closer than the last one (iterate {i}, largest difference {}): the printed column is not an early-stopped \
                 iterate of this method either, and what produced it is not determined by the paper's data",
                fmt(d, 2)
            ),
            Some((i, d)) => format!(
                "the closest iterate is number {i} (largest difference {}), so an iteration stopped early is at most a partial explanation",
                fmt(d, 2)
            ),
        };
        ledger.record(
            id,
            Outcome::new(
                format!("{agree} of 20 entries agree to the 4 printed decimals; largest difference {} from the certified minimizer", fmt(dev, 2)),
                "mpfr:128/256",
                if agree == 20 { Verdict::Reproduced } else { Verdict::Discrepancy },
                format!(
                    "{}: gradient projection from chord length ({} iterations, relative tolerance 1e-6 {}), then Newton's method at 128 and 256 \
                     bits: a stationary point with ≥ {min_digits} certified digits per knot. Each printed value compared with it within half a \
                     unit of its last decimal: the printed values are not the converged minimizer of the stated objective, by more than \
                     rounding. Following the gradient-projection iterates from chord length (exact line search): {closest}.",
                    k.name,
                    k.iterations,
                    if k.converged { "met" } else { "not met" }
                ),
            ),
        );
    }
    // Figs. 3–5: second derivatives and third-derivative jumps per parametrization.
    let param: Vec<(&str, Vec<f64>)> =
        std::iter::once(("t^CL", cl_hi.iter().map(Field::to_f64).collect()))
            .chain(
                columns
                    .iter()
                    .flatten()
                    .map(|c| (c.name, c.exact.iter().map(Field::to_f64).collect())),
            )
            .collect();
    let z64 = components::<f64>(&());
    let mut stats = Vec::new();
    let mut stat_rows = Vec::new();
    for (name, t) in &param {
        let mut row = vec![name.to_string()];
        let mut peaks = Vec::new();
        for comp in &z64 {
            let Ok(s) = NaturalCubicSpline::new(t.clone(), comp.clone()) else {
                continue;
            };
            let m = s.second_derivatives_at_knots();
            let peak = m.iter().fold(0.0f64, |a, x| a.max(x.abs()));
            let third: Vec<f64> = (1..t.len())
                .map(|i| (m[i] - m[i - 1]) / (t[i] - t[i - 1]))
                .collect();
            let jumps: f64 = third.windows(2).map(|w| (w[1] - w[0]).abs()).sum();
            row.push(fmt(peak, 4));
            row.push(fmt(jumps, 4));
            peaks.push(peak);
        }
        stats.push((name.to_string(), peaks));
        stat_rows.push(row);
    }
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
    let base = stats.first().map(|s| s.1.clone()).unwrap_or_default();
    let reduced = stats.len() == 3
        && stats[1..]
            .iter()
            .all(|(_, p)| p.len() == 2 && base.len() == 2 && p[0] < base[0] && p[1] < base[1]);
    let describe: Vec<String> = stats
        .iter()
        .map(|(n, p)| {
            format!(
                "{n}: max |x''| = {}, max |y''| = {}",
                fmt(p.first().copied().unwrap_or(f64::NAN), 4),
                fmt(p.get(1).copied().unwrap_or(f64::NAN), 4)
            )
        })
        .collect();
    ledger.record(
        "marin.fig3_5.second_derivatives",
        Outcome::new(
            describe.join("; "),
            "f64 (splines on certified knots)",
            if reduced { Verdict::Reproduced } else { Verdict::Discrepancy },
            "natural cubic splines x(t), y(t) through Table II for each parametrization; θ'' is piecewise linear, so its maximum modulus is at a \
             knot and is exact up to f64 rounding. Criterion: both components' maxima smaller for t^EX and for t^AP than for chord length. The \
             report also lists the total third-derivative jump over the interior knots",
        ),
    );
    md.push_str(&format!("\n![Fig. 2](./{ID}_fig2.svg)\n\n"));
    for (n, (name, t)) in param.iter().enumerate() {
        let file = super::super::figure_file(ID, n as u32 + 3);
        md.push_str(&format!(
            "![Fig. {}: components with {name}](./{file})\n\n",
            n + 3
        ));
        figures.push((file, component_figure(name, t, &z64)));
    }
    if let Some(ex) = &columns[0] {
        figures.push((
            super::super::figure_file(ID, 2),
            figure2(
                &ex.exact.iter().map(Field::to_f64).collect::<Vec<_>>(),
                &z64,
            ),
        ));
    }
}

/// Figs. 3–5: x, x', x'' and y, y', y'' against t for one parametrization.
fn component_figure(name: &str, t: &[f64], z: &[Vec<f64>]) -> String {
    let mut panels = Vec::new();
    for (c, comp) in ["x", "y"].iter().enumerate() {
        let Ok(s) = NaturalCubicSpline::new(t.to_vec(), z[c].clone()) else {
            return String::new();
        };
        let grid: Vec<[f64; 3]> = (0..=600).map(|k| s.eval_all(&(k as f64 / 600.0))).collect();
        for (j, label) in ["", "'", "''"].iter().enumerate() {
            let mut series = vec![Series::new(
                "",
                (0..=600).map(|k| (k as f64 / 600.0, grid[k][j])).collect(),
                Style::Solid,
                c + 1,
            )];
            if j == 0 {
                series.push(Series::new(
                    "data",
                    t.iter().copied().zip(z[c].iter().copied()).collect(),
                    Style::Markers,
                    2,
                ));
            }
            let legend = if c == 0 {
                Corner::LowerLeft
            } else {
                Corner::UpperRight
            };
            panels.push(Panel {
                title: format!("{comp}{label}(t), {name}"),
                x_label: "t (parameter, dimensionless)".into(),
                y_label: format!("{comp}{label}"),
                series,
                legend,
                ..Panel::default()
            });
        }
    }
    plot::render(&panels, (2, 3), (1200, 640)).unwrap_or_default()
}

fn figure2(t: &[f64], z: &[Vec<f64>]) -> String {
    let (Ok(x), Ok(y)) = (
        NaturalCubicSpline::new(t.to_vec(), z[0].clone()),
        NaturalCubicSpline::new(t.to_vec(), z[1].clone()),
    ) else {
        return String::new();
    };
    let curve: Vec<(f64, f64)> = (0..=600)
        .map(|k| k as f64 / 600.0)
        .map(|s| (x.eval_all(&s)[0], y.eval_all(&s)[0]))
        .collect();
    let data: Vec<(f64, f64)> = z[0].iter().copied().zip(z[1].iter().copied()).collect();
    let panel = Panel {
        title: "Fig. 2: parametric natural cubic spline with t^EX".into(),
        x_label: "x (data units)".into(),
        y_label: "y (data units)".into(),
        series: vec![
            Series::new("spline", curve, Style::Solid, 0),
            Series::new("Table II data", data, Style::Markers, 2),
        ],
        equal_aspect: true,
        legend: Corner::UpperRight,
        ..Panel::default()
    };
    plot::render(&[panel], (1, 1), (640, 640)).unwrap_or_default()
}
