//! The figures of paper 004, drawn from the checks' results (splines sampled in f64 for
//! drawing): plotting only, no verdicts.

use super::data::TABLE1;
use super::geometry::CornerCurves;
use super::num;
use crate::algo::param::natural::NaturalCubicSpline;
use crate::report::plot::{self, Corner, Panel, Series, Style};
use crate::scalar::{Field, Float};

/// Fig. 1: θ, θ′ and θ″ of the Table I data on t*.
pub fn figure1(s: &NaturalCubicSpline<Float>) -> String {
    let t = s.knots();
    let (a, b) = (t[0].clone(), t[t.len() - 1].clone());
    let samples: Vec<[f64; 4]> = (0..=400u32)
        .map(|k| {
            let x = a.clone() + (b.clone() - &a) * k / 400u32;
            let [v, d, c] = s.eval_all(&x);
            [x.to_f64(), v.to_f64(), d.to_f64(), c.to_f64()]
        })
        .collect();
    let knots: Vec<(f64, f64)> = t
        .iter()
        .zip(TABLE1.iter())
        .map(|(x, (z, _))| (x.to_f64(), num(z).to_f64()))
        .collect();
    let panel = |title: &str, j: usize, extra: Vec<Series>| {
        let mut series = vec![Series::new(
            "",
            samples.iter().map(|p| (p[0], p[j])).collect(),
            Style::Solid,
            0,
        )];
        series.extend(extra);
        Panel {
            title: title.into(),
            x_label: "t (parameter, dimensionless)".into(),
            y_label: title.into(),
            series,
            legend: Corner::UpperRight,
            ..Panel::default()
        }
    };
    let panels = vec![
        panel(
            "θ(t)",
            1,
            vec![Series::new("data (t_i*, z_i)", knots, Style::Markers, 2)],
        ),
        panel("θ'(t)", 2, vec![]),
        panel("θ''(t)", 3, vec![]),
    ];
    plot::render_or_note(&panels, (1, 3), (1200, 380))
}

/// Figs. 3–5: x, x', x'' and y, y', y'' against t, one figure per parametrization (name,
/// knots). Each panel position has one y scale across the figures, so the second derivatives
/// of the parametrizations can be compared by eye.
pub fn component_figures(parametrizations: &[(&str, Vec<f64>)], z: &[Vec<f64>]) -> Vec<String> {
    let mut figures: Vec<Vec<Panel>> = parametrizations
        .iter()
        .map(|(name, t)| component_panels(name, t, z))
        .collect();
    let positions = figures.iter().map(Vec::len).max().unwrap_or(0);
    for k in 0..positions {
        let ys = figures
            .iter()
            .filter_map(|panels| panels.get(k))
            .flat_map(|p| p.series.iter().flat_map(|s| s.points.iter().map(|q| q.1)))
            .filter(|y| y.is_finite());
        let range = ys.fold(None, |r: Option<(f64, f64)>, y| {
            Some(r.map_or((y, y), |(lo, hi)| (lo.min(y), hi.max(y))))
        });
        for panels in &mut figures {
            if let Some(p) = panels.get_mut(k) {
                p.y_range = range;
            }
        }
    }
    figures
        .iter()
        .map(|panels| plot::render_or_note(panels, (2, 3), (1200, 640)))
        .collect()
}

/// The six panels of one of Figs. 3–5 (empty if the spline cannot be built).
fn component_panels(name: &str, t: &[f64], z: &[Vec<f64>]) -> Vec<Panel> {
    let mut panels = Vec::new();
    for (c, comp) in ["x", "y"].iter().enumerate() {
        let Some(zc) = z.get(c) else {
            return Vec::new();
        };
        let Ok(s) = NaturalCubicSpline::new(t.to_vec(), zc.clone()) else {
            return Vec::new();
        };
        let grid: Vec<[f64; 3]> = (0..=600).map(|k| s.eval_all(&(k as f64 / 600.0))).collect();
        for (j, label) in ["", "′", "″"].iter().enumerate() {
            let mut series = vec![Series::new(
                "",
                (0..=600).map(|k| (k as f64 / 600.0, grid[k][j])).collect(),
                Style::Solid,
                c + 1,
            )];
            if j == 0 {
                series.push(Series::new(
                    "data",
                    t.iter().copied().zip(zc.iter().copied()).collect(),
                    Style::Markers,
                    2,
                ));
            }
            panels.push(Panel {
                title: format!("{comp}{label}(t), {name}"),
                x_label: "t (parameter, dimensionless)".into(),
                y_label: format!("{comp}{label}"),
                series,
                legend: Corner::UpperRight,
                ..Panel::default()
            });
        }
    }
    panels
}

/// Fig. 2: the parametric spline through the Table II data with t^EX.
pub fn figure2(t: &[f64], z: &[Vec<f64>]) -> String {
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
    plot::render_or_note(&[panel], (1, 1), (640, 640))
}

/// Fig. 6: the polygon, the data, and the chord-length and minimizing splines.
pub fn corner(c: &CornerCurves) -> String {
    let panel = Panel {
        title: "Fig. 6: interpolation near a corner".into(),
        x_label: "x (data units)".into(),
        y_label: "y (data units)".into(),
        series: vec![
            Series::new("polygon", c.polygon.clone(), Style::Solid, 0),
            Series::new("chord length", c.chord.clone(), Style::Dashed, 1),
            Series::new("minimizing", c.minimizing.clone(), Style::Dotted, 2),
            Series::new("data", c.polygon.clone(), Style::Markers, 0),
        ],
        equal_aspect: true,
        legend: Corner::UpperLeft,
        ..Panel::default()
    };
    plot::render_or_note(&[panel], (1, 1), (640, 640))
}

/// Fig. 9: the axis #3 spline against t for each parametrization (printed knots), with the
/// data and, per panel, the overshooting intervals' count in the title.
pub fn figure9(parametrizations: &[(String, Vec<f64>)], axis: &[f64], counts: &[usize]) -> String {
    let mut panels = Vec::new();
    for (k, ((name, t), count)) in parametrizations.iter().zip(counts).enumerate() {
        let Ok(s) = NaturalCubicSpline::new(t.clone(), axis.to_vec()) else {
            return String::new();
        };
        let curve = (0..=800)
            .map(|j| {
                let x = j as f64 / 800.0;
                (x, s.eval_all(&x)[0])
            })
            .collect();
        panels.push(Panel {
            title: format!(
                "({}) {name}: {count} overshooting intervals",
                ['a', 'b', 'c', 'd'][k.min(3)]
            ),
            x_label: "t (normalized time, dimensionless)".into(),
            y_label: "θ₃ (rad)".into(),
            series: vec![
                Series::new("natural cubic spline", curve, Style::Solid, 1),
                Series::new(
                    "data (Table IV)",
                    t.iter().copied().zip(axis.iter().copied()).collect(),
                    Style::Markers,
                    2,
                ),
            ],
            legend: Corner::UpperLeft,
            ..Panel::default()
        });
    }
    plot::render_or_note(&panels, (1, panels.len()), (400 * panels.len() as u32, 400))
}
