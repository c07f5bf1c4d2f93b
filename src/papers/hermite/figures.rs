//! The figures of paper 000, drawn from the checks' results (the exact Fig. 2 curves, the
//! Fig. 3–4 samples, the Fig. 5 rows): plotting only, no verdicts.

use super::conditioning;
use super::examples::{LandingMetrics, TurnMetrics};
use crate::numeric::poly::Bernstein;
use crate::report::plot::{Corner, Panel, Series, Style};
use crate::scalar::{BigRational, Field, Float, Real};

/// Fig. 2: position, velocity and acceleration for durations 1 and 2.
pub fn fig2_panels(fast: &Bernstein<BigRational>, slow: &Bernstein<BigRational>) -> Vec<Panel> {
    let titles = ["position", "velocity", "acceleration"];
    (0..3)
        .map(|j| {
            let series_for =
                |b: &Bernstein<BigRational>, name: &str, style: Style, color: usize| {
                    let d = b.nth_derivative(j);
                    let f: Bernstein<f64> = Bernstein::new(
                        d.control_points().iter().map(Field::to_f64).collect(),
                        (d.t0().to_f64(), d.t1().to_f64()),
                    )
                    .expect("the solved curve's interval, rounded to f64");
                    let pts = (0..=200).map(|i| {
                        let t = f.t1() * i as f64 / 200.0;
                        (t, f.eval(&t))
                    });
                    Series::new(name, pts.collect(), style, color)
                };
            let ends = |b: &Bernstein<BigRational>| {
                vec![
                    (0.0, b.derivative_at_start(j).to_f64()),
                    (b.t1().to_f64(), b.derivative_at_end(j).to_f64()),
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

/// Fig. 3 from the measurements: one panel per reading of the data.
pub fn turn_figure(m: &[TurnMetrics]) -> Vec<Panel> {
    m.chunks(3).map(turn_panel).collect()
}

/// One reading of the Fig. 3 data: its three durations, the arc and the end points.
fn turn_panel(m: &[TurnMetrics]) -> Panel {
    let styles = [Style::Dashed, Style::Solid, Style::Dotted];
    let mut series: Vec<Series> = m
        .iter()
        .zip(styles)
        .enumerate()
        .map(|(i, (t, style))| {
            let name = if t.factor.1 == 1 {
                format!("{} × nominal", t.factor.0)
            } else {
                format!("{}/{} × nominal", t.factor.0, t.factor.1)
            };
            Series::new(name, t.samples.clone(), style, [1, 0, 2][i])
        })
        .collect();
    let arc: Vec<(f64, f64)> = (0..=200)
        .map(|i| {
            let angle = Float::pi(&64) / 2u32 * Float::with_val(64, i) / 200u32;
            let (s, c) = Real::sin_cos(&angle);
            (s.to_f64(), 1.0 - c.to_f64())
        })
        .collect();
    series.push(Series::new("circular arc", arc, Style::Dotted, 3));
    series.push(Series::new(
        "start, end",
        vec![(0.0, 0.0), (1.0, 1.0)],
        Style::Markers,
        0,
    ));
    let data = m.first().map_or("", |t| t.data.label());
    Panel {
        title: format!("Fig. 3, {data}: durations 0.2, 1 and 3 × π/2"),
        x_label: "x (length units)".into(),
        y_label: "y (length units)".into(),
        series,
        equal_aspect: true,
        legend: Corner::LowerRight,
        ..Panel::default()
    }
}

/// Panels of Fig. 4: top view and altitude.
pub fn landing_figure(l: &LandingMetrics) -> Vec<Panel> {
    let top: Vec<(f64, f64)> = l.samples.iter().map(|p| (p[0], p[1])).collect();
    let t_alt: Vec<(f64, f64)> = l
        .samples
        .iter()
        .enumerate()
        .map(|(i, p)| (i as f64 * 0.1, p[2]))
        .collect();
    vec![
        Panel {
            title: "Fig. 4: landing, top view".into(),
            x_label: "x along the runway (m)".into(),
            y_label: "y (m)".into(),
            series: vec![
                Series::new("runway", vec![(0.0, 0.0), (3000.0, 0.0)], Style::Solid, 0),
                Series::new("trajectory", top, Style::Dotted, 1),
                Series::new(
                    "start, threshold",
                    vec![(0.0, 2000.0), (0.0, 0.0)],
                    Style::Markers,
                    2,
                ),
            ],
            equal_aspect: true,
            legend: Corner::LowerRight,
            ..Panel::default()
        },
        Panel {
            title: "altitude".into(),
            x_label: "t (s)".into(),
            y_label: "z (m)".into(),
            series: vec![Series::new("altitude", t_alt, Style::Solid, 1)],
            legend: Corner::UpperRight,
            ..Panel::default()
        },
    ]
}

/// Fig. 5: κ2 against m for every duration, the binomial matrix and f64.
pub fn fig5_panels(rows: &[conditioning::KappaRow]) -> Vec<Panel> {
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
