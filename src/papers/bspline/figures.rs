//! The figures of paper 002: the bang-bang optimum beside B_3 (Fig. 1, exact values sampled)
//! and the smoothing reconstructions (Fig. 3 analogue): plotting only, no verdicts.

use super::fitting;
use crate::algo::bspline::bang_bang::response;
use crate::algo::bspline::CardinalBSpline;
use crate::report::plot::{Corner, Panel, Series, Style};
use crate::scalar::qsqrt2::QSqrt2;
use crate::scalar::{BigRational, Field};

/// Fig. 1: x(t) and u = x‴ of the bang-bang optimum and of B_3.
pub fn fig1_panels(t: &[QSqrt2; 3], u: &QSqrt2) -> Vec<Panel> {
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

/// Fig. 3 analogue: the reconstructions of the stroke, xy projection.
pub fn fig3_panels(planar: &[Vec<(f64, f64)>]) -> Vec<Panel> {
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
