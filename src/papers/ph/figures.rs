//! The figures of paper 001, drawn from the checks' results (Table 1) or from the
//! conversions sampled in f64 for drawing (Figs. 1–4): plotting only, no verdicts.

use super::{nrho, table1};
use crate::algo::ph::hermite::{interpolate, FreeParameters, HermiteData};
use crate::algo::ph::piecewise::{convert, PiecewisePh};
use crate::algo::ph::{bernstein_jet, frame_and_omega};
use crate::curve::Curve;
use crate::numeric::quat::vec3;
use crate::report::plot::{self, Corner, Panel, Series, Style};
use crate::scalar::Field;

/// The Table 1 figure: error against segments, certified, published, f64 and the other orders.
pub fn convergence_figure(
    rows: &[table1::Row],
    baseline: &[table1::Row],
    f64_col: &[(usize, f64)],
    theta: &[table1::Row],
    tau: &[table1::Row],
) -> String {
    let lg = |s: usize| (s as f64).log2();
    let pts = |r: &[table1::Row]| {
        r.iter()
            .map(|x| (lg(x.segments), x.error.hi.to_f64()))
            .collect::<Vec<_>>()
    };
    let published: Vec<(f64, f64)> = table1::TABLE1
        .iter()
        .filter_map(|(s, e, _)| {
            crate::scalar::parse::parse_rational(e)
                .ok()
                .map(|q| (lg(*s), Field::to_f64(&q)))
        })
        .collect();
    let last = rows.last().map_or(1e-21, |r| r.error.hi.to_f64());
    let guide: Vec<(f64, f64)> = (0..=13)
        .map(|n| (n as f64, 100.0 * last * 64f64.powi(13 - n)))
        .collect();
    let panel = Panel {
        title: "Table 1: conversion error of Eq. (23)".into(),
        x_label: "n (2^n segments)".into(),
        y_label: "max ‖γ − p‖ (length units of Eq. 23)".into(),
        series: vec![
            // First, so that it is drawn beneath the data; two decades above the certified
            // line so that it does not hide it.
            Series::new("slope −6 guide (100× above)", guide, Style::Dashed, 6),
            Series::new("C4 PHODCOS, certified", pts(rows), Style::LineMarkers, 1),
            Series::new("published", published, Style::Markers, 2),
            Series::new(
                "C4 in f64",
                f64_col.iter().map(|(s, e)| (lg(*s), *e)).collect(),
                Style::Dashed,
                4,
            ),
            Series::new("C2 baseline", pts(baseline), Style::Dotted, 3),
            Series::new(
                "theta0 = theta8 = 1/2 (order 1)",
                pts(theta),
                Style::Dashed,
                5,
            ),
            Series::new("tau1 = 1/10 (no convergence)", pts(tau), Style::Dotted, 0),
        ],
        log_y: true,
        equal_aspect: false,
        legend: Corner::LowerLeft,
        y_range: None,
    };
    plot::render_or_note(&[panel], (1, 1), (900, 600))
}

/// The test curve and its conversions (f64) sampled for plots.
fn test_curve_points(per: usize) -> Vec<[f64; 3]> {
    let c = table1::curve().compile::<f64>(&());
    (0..=per)
        .map(|i| c.jet(&(i as f64 / per as f64), 0).swap_remove(0))
        .collect()
}

fn converted_points(pw: &PiecewisePh<f64>, per: usize) -> Vec<[f64; 3]> {
    crate::algo::ph::piecewise::sample_points(pw, per)
}

fn project(points: &[[f64; 3]], a: usize, b: usize) -> Vec<(f64, f64)> {
    points.iter().map(|p| (p[a], p[b])).collect()
}

pub fn figure2a() -> String {
    let c = table1::curve().compile::<f64>(&());
    let original = test_curve_points(400);
    let free = FreeParameters::zero(4, &());
    let mut panels = Vec::new();
    for (a, b, view) in [(0usize, 1usize, "top (x, y)"), (0, 2, "side (x, z)")] {
        for segments in [1usize, 2, 8] {
            let pw = convert(&c, (&0.0, &1.0), segments, 4, &free, true).expect("test curve");
            panels.push(Panel {
                title: format!("{segments} segment(s), {view}"),
                x_label: format!("{} (length units)", ["x", "y", "z"][a]),
                y_label: format!("{} (length units)", ["x", "y", "z"][b]),
                series: vec![
                    Series::new("Eq. (23)", project(&original, a, b), Style::Dashed, 0),
                    Series::new(
                        "PHODCOS",
                        project(&converted_points(&pw, 100), a, b),
                        Style::Solid,
                        2,
                    ),
                ],
                log_y: false,
                equal_aspect: true,
                legend: Corner::UpperRight,
                y_range: None,
            });
        }
    }
    plot::render_or_note(&panels, (2, 3), (1200, 750))
}

/// A function of A and A′ with up to four plotted components.
type QuatMap =
    dyn Fn(&crate::numeric::quat::Quat<f64>, &crate::numeric::quat::Quat<f64>) -> [f64; 4];

/// Fig. 2B: A, e2 and ω on 2 segments, with (solid) and without (dashed) the roll correction.
pub fn figure2b() -> String {
    let c = table1::curve().compile::<f64>(&());
    let free = FreeParameters::zero(4, &());
    let raw = convert(&c, (&0.0, &1.0), 2, 4, &free, false).expect("test curve");
    let mut fixed = raw.clone();
    fixed.align_roll();
    let sample = |pw: &PiecewisePh<f64>, f: &QuatMap| {
        let mut out: Vec<Vec<(f64, f64)>> = vec![Vec::new(); 4];
        for (k, seg) in pw.segments().iter().enumerate() {
            for i in 0..=100 {
                let xi = i as f64 / 100.0;
                let jet = seg.preimage_jet(&xi, 1);
                let v = f(&jet[0], &jet[1]);
                for d in 0..4 {
                    out[d].push(((k as f64 + xi) / 2.0, v[d]));
                }
            }
        }
        out
    };
    let names = ["u", "v", "p", "q"];
    let a_of =
        |a: &crate::numeric::quat::Quat<f64>, _: &crate::numeric::quat::Quat<f64>| a.components();
    let e2_of = |a: &crate::numeric::quat::Quat<f64>, d: &crate::numeric::quat::Quat<f64>| {
        let (f, _) = frame_and_omega(a, d);
        [f[1][0], f[1][1], f[1][2], 0.0]
    };
    let w_of = |a: &crate::numeric::quat::Quat<f64>, d: &crate::numeric::quat::Quat<f64>| {
        let (_, w) = frame_and_omega(a, d);
        [w[0] / 2.0, w[1] / 2.0, w[2] / 2.0, 0.0] // per unit ξ of the whole curve: h = 1/2
    };
    let mut panels = Vec::new();
    for (title, f, count) in [
        ("preimage A", &a_of as &QuatMap, 4usize),
        ("frame column e2", &e2_of, 3),
        ("angular velocity ω", &w_of, 3),
    ] {
        let with = sample(&fixed, f);
        let without = sample(&raw, f);
        let mut series = Vec::new();
        for d in 0..count {
            let label = if count == 4 {
                names[d].to_string()
            } else {
                ["x", "y", "z"][d].to_string()
            };
            series.push(Series::new(
                format!("{label} corrected"),
                with[d].clone(),
                Style::Solid,
                d + 1,
            ));
            series.push(Series::new(
                format!("{label} uncorrected"),
                without[d].clone(),
                Style::Dashed,
                d + 1,
            ));
        }
        panels.push(Panel {
            title: title.into(),
            x_label: "global parameter ξ (dimensionless)".into(),
            y_label: title.into(),
            series,
            log_y: false,
            equal_aspect: false,
            legend: Corner::UpperLeft,
            y_range: None,
        });
    }
    plot::render_or_note(&panels, (1, 3), (1500, 500))
}

/// Fig. 3: the planar test curve on one segment; moved and moved back; reversed.
pub fn figure3() -> String {
    let c = crate::curve::ExprCurve::parse("[1.5*sin(7.2*t), 0, exp(cos(1.8*t))]")
        .expect("planar curve")
        .compile::<f64>(&());
    let data = HermiteData::from_jets(&c.jet(&0.0, 4), &c.jet(&1.0, 4)).expect("two jets of 5");
    let free = FreeParameters::zero(4, &());
    let sample = |curve: &crate::algo::ph::PhCurve<f64>| {
        let pts = curve.control_points();
        (0..=200)
            .map(|i| bernstein_jet(&pts, &(i as f64 / 200.0), 0).swap_remove(0))
            .collect::<Vec<_>>()
    };
    let original = interpolate(&data, &free).expect("planar data");
    // Rotation by π/2 about y: (x, y, z) ↦ (z, y, −x); translation [−1, 0, 2.5].
    let rot = |v: &[f64; 3]| [v[2], v[1], -v[0]];
    let unrot = |v: &[f64; 3]| [-v[2], v[1], v[0]];
    let shift = [-1.0, 0.0, 2.5];
    let moved = data.map(|p| vec3::add(&rot(p), &shift), rot);
    let transformed = interpolate(&moved, &free).expect("moved data");
    let back: Vec<[f64; 3]> = sample(&transformed)
        .iter()
        .map(|p| unrot(&vec3::sub(p, &shift)))
        .collect();
    let reversed = interpolate(&data.reversed(), &free).expect("reversed data");
    let exact: Vec<[f64; 3]> = (0..=200)
        .map(|i| c.jet(&(i as f64 / 200.0), 0).swap_remove(0))
        .collect();
    let a = Panel {
        title: "A: invariance (xz plane)".into(),
        x_label: "x (length units)".into(),
        y_label: "z (length units)".into(),
        series: vec![
            Series::new(
                "original",
                project(&sample(&original), 0, 2),
                Style::Solid,
                1,
            ),
            Series::new(
                "transformed",
                project(&sample(&transformed), 0, 2),
                Style::Solid,
                2,
            ),
            Series::new("transformed back", project(&back, 0, 2), Style::Dashed, 2),
        ],
        equal_aspect: true,
        legend: Corner::LowerLeft,
        ..Panel::default()
    };
    let b = Panel {
        title: "B: reversion".into(),
        x_label: "x (length units)".into(),
        y_label: "z (length units)".into(),
        series: vec![
            Series::new(
                "curve y = 0 of Eq. (23)",
                project(&exact, 0, 2),
                Style::Dotted,
                0,
            ),
            Series::new(
                "interpolant",
                project(&sample(&original), 0, 2),
                Style::Solid,
                1,
            ),
            Series::new(
                "reversed interpolant",
                project(&sample(&reversed), 0, 2),
                Style::Dashed,
                2,
            ),
        ],
        equal_aspect: true,
        legend: Corner::LowerLeft,
        ..Panel::default()
    };
    plot::render_or_note(&[a, b], (1, 2), (1100, 550))
}

pub fn nrho_figure1(n: &nrho::Nrho) -> String {
    let pts = converted_points(&n.inertial, 8);
    let moon: Vec<[f64; 3]> = (0..=200)
        .map(|i| {
            let t = n.period * i as f64 / 200.0;
            let (s, c) = t.sin_cos();
            [c, s, 0.0]
        })
        .collect();
    let panels: Vec<Panel> = [(0usize, 1usize, "ECI, x–y"), (0, 2, "ECI, x–z")]
        .iter()
        .map(|&(a, b, title)| Panel {
            title: title.into(),
            x_label: format!("{} (LU)", ["x", "y", "z"][a]),
            y_label: format!("{} (LU)", ["x", "y", "z"][b]),
            series: vec![
                Series::new(
                    "NRHO (PHODCOS, 256 segments)",
                    project(&pts, a, b),
                    Style::Solid,
                    2,
                ),
                Series::new(
                    "Moon's path over the same period",
                    project(&moon, a, b),
                    Style::Dashed,
                    0,
                ),
                Series::new("Earth", vec![(0.0, 0.0)], Style::Markers, 3),
            ],
            log_y: false,
            equal_aspect: true,
            legend: Corner::LowerLeft,
            y_range: None,
        })
        .collect();
    plot::render_or_note(&panels, (1, 2), (1100, 550))
}

pub fn nrho_figure4(n: &nrho::Nrho) -> String {
    let pw = &n.rotating;
    let pts = converted_points(pw, 8);
    let (sigma, omega) = nrho::speed_and_turn_rate(pw, 8);
    let mut panels: Vec<Panel> = [
        (0usize, 1usize, "A: top (x–y); the paper's A is a 3-D view"),
        (0, 2, "B: front (x–z)"),
        (1, 2, "C: side (y–z)"),
    ]
    .iter()
    .map(|&(a, b, title)| Panel {
        title: title.into(),
        x_label: format!("{} (LU)", ["x", "y", "z"][a]),
        y_label: format!("{} (LU)", ["x", "y", "z"][b]),
        series: vec![
            Series::new("NRHO, rotating frame", project(&pts, a, b), Style::Solid, 2),
            Series::new(
                "Moon",
                vec![(if a == 0 { 1.0 - nrho::MU } else { 0.0 }, 0.0)],
                Style::Markers,
                0,
            ),
        ],
        log_y: false,
        equal_aspect: true,
        legend: Corner::LowerLeft,
        y_range: None,
    })
    .collect();
    panels.push(Panel {
        title: "D: parametric speed σ".into(),
        x_label: "t (TU)".into(),
        y_label: "σ (LU/TU)".into(),
        series: vec![Series::new("σ", sigma, Style::Solid, 1)],
        log_y: false,
        equal_aspect: false,
        legend: Corner::UpperRight,
        y_range: None,
    });
    panels.push(Panel {
        title: "E: |ω|".into(),
        x_label: "t (TU)".into(),
        y_label: "|ω| (rad/TU)".into(),
        series: vec![Series::new("|ω|", omega, Style::Solid, 2)],
        log_y: true,
        equal_aspect: false,
        legend: Corner::UpperRight,
        y_range: None,
    });
    plot::render_or_note(&panels, (2, 3), (1500, 900))
}
