//! The figures of paper 003: the bases and paths sampled in f64 for drawing, and the paths
//! the checks computed: plotting only, no verdicts.

use super::{paths, setup};
use crate::algo::gerbs::basis_derivatives;
use crate::algo::gerbs::bfbs::Bfbs;
use crate::algo::gerbs::erbs::CentreReading;
use crate::algo::gerbs::path::{ArcConvention, PathPoint};
use crate::algo::gerbs::Side;
use crate::report::plot::{self, Corner, Panel, Series, Style};
use setup::ErbsSet;

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

/// Fig. 1: the BFBS basis (i = 2).
pub fn figure1() -> String {
    let k = setup::fig1_knots::<f64>(&());
    let b = Bfbs::uniform(2, 5).expect("exponents");
    plot::render_or_note(&[basis_panel("BFBS, i = 2", &k, &b)], (1, 1), (800, 500))
}

/// Fig. 2: the ERBS basis for the three parameter sets and both readings of Eq. (4).
pub fn figure2() -> String {
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

/// Paths side by side in the plane (Fig. 5).
/// A square window of the plane, centre and half-width, in length units.
type Window = ((f64, f64), f64);

/// A panel of `series` clipped to `window` (with the waypoints inside it), drawn to equal
/// scale: where the full-scale paths overlap, the window shows how they differ.
fn zoom_panel(title: String, series: Vec<Series>, ((cx, cy), half): Window) -> Panel {
    let inside = |p: &(f64, f64)| (p.0 - cx).abs() <= half && (p.1 - cy).abs() <= half;
    let mut clipped: Vec<Series> = series
        .into_iter()
        .map(|mut s| {
            s.points.retain(inside);
            s
        })
        .collect();
    let mut waypoints = waypoint_series();
    waypoints.points.retain(inside);
    clipped.push(waypoints);
    Panel {
        title,
        x_label: "x (length units)".into(),
        y_label: "y (length units)".into(),
        series: clipped,
        equal_aspect: true,
        legend: Corner::UpperLeft,
        ..Panel::default()
    }
}

/// The window around waypoint `i` (0-based) of half-width `half`.
fn around_waypoint(i: usize, half: f64) -> Window {
    let w = setup::WAYPOINTS[i.min(setup::WAYPOINTS.len() - 1)];
    ((w[0] as f64, w[1] as f64), half)
}

/// The straight lines between the waypoints, for reference.
fn polygon_series() -> Series {
    let mut s = waypoint_series();
    s.name = "waypoint polygon".into();
    s.style = Style::Dotted;
    s.color = 6;
    s
}

/// Fig. 5: the BFBS path, and a window at W3 where it rounds the corner of the polygon.
pub fn figure5(bfbs: &[PathPoint<f64>]) -> String {
    let path = || curve("BFBS (i = 2)", xy(bfbs), Style::Solid, 1);
    let panels = [
        plane_panel("Fig. 5: BFBS path (i = 2)", vec![path()]),
        zoom_panel(
            "at W3: the path rounds the corner".into(),
            vec![path(), polygon_series()],
            around_waypoint(2, 70.0),
        ),
    ];
    plot::render_or_note(&panels, (1, 2), (1300, 520))
}

pub fn figure3(turn: &[PathPoint<f64>], printed: &[PathPoint<f64>]) -> String {
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
            "ERBS: arcs in the turn direction and Eqs. (21)–(22) as printed",
            vec![
                curve("turn direction", a.clone(), Style::Solid, 1),
                curve("as printed", b.clone(), Style::Dashed, 2),
            ],
        ),
        zoom,
    ];
    plot::render_or_note(&panels, (1, 2), (1300, 540))
}

pub fn figure4(erbs: &[PathPoint<f64>]) -> String {
    let p = setup::erbs_path::<f64>(&(), ErbsSet::Smooth, ArcConvention::TurnDirection);
    let series = || {
        let mut series = vec![curve("ERBS path", xy(erbs), Style::Solid, 1)];
        for (i, c) in p.curves().iter().enumerate() {
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
        series
    };
    let panels = [
        plane_panel(
            "local curves: lines at the ends, arcs R = 80, θ_o = π/8",
            series(),
        ),
        zoom_panel(
            "at W2: the arc local curve and the path".into(),
            series(),
            around_waypoint(1, 60.0),
        ),
    ];
    plot::render_or_note(&panels, (1, 2), (1300, 520))
}

fn curvature_series(name: &str, pts: &[PathPoint<f64>], color: usize) -> Series {
    curve(
        name,
        pts.iter().map(|p| (p.t, p.curvature)).collect(),
        Style::Solid,
        color,
    )
}

/// Fig. 6: BFBS and ERBS paths and their curvature.
pub fn figure6(bfbs: &[PathPoint<f64>], erbs: &[PathPoint<f64>]) -> String {
    // Equal-t samples: the window is centred where the two paths are farthest apart.
    let (far, gap) = bfbs
        .iter()
        .zip(erbs)
        .map(|(p, q)| (p.point[0] - q.point[0]).hypot(p.point[1] - q.point[1]))
        .enumerate()
        .fold((0, 0.0), |m, x| if x.1 > m.1 { x } else { m });
    let centre = match (bfbs.get(far), erbs.get(far)) {
        (Some(p), Some(q)) => (
            (p.point[0] + q.point[0]) / 2.0,
            (p.point[1] + q.point[1]) / 2.0,
        ),
        _ => (0.0, 0.0),
    };
    let at_far = |pts: &[PathPoint<f64>]| pts.get(far).map(|p| (p.point[0], p.point[1]));
    let t_far = bfbs.get(far).map_or(0.0, |p| p.t);
    let a = zoom_panel(
        format!(
            "Fig. 6: the paths nearly coincide; at equal t = {t_far:.3} they are {gap:.1} apart"
        ),
        vec![
            curve("BFBS", xy(bfbs), Style::Solid, 2),
            curve("ERBS", xy(erbs), Style::Dashed, 1),
            curve(
                "BFBS and ERBS points at that t",
                [at_far(bfbs), at_far(erbs)].into_iter().flatten().collect(),
                Style::Markers,
                4,
            ),
        ],
        (centre, (4.0 * gap).max(60.0)),
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

/// Fig. 7: the ERBS path against the Dubins path, and their curvature.
pub fn figure7(
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
            curve("ERBS", ke, Style::Solid, 1),
        ],
        legend: Corner::LowerLeft,
        ..Panel::default()
    };
    plot::render_or_note(&[a, b], (1, 2), (1400, 500))
}
