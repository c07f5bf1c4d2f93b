//! SVG figures with plotters: panels of line and marker series, linear or log₁₀ y axes.
//!
//! plotters is built without a font backend, so text sizes are estimated by a fixed rule
//! rather than measured from system fonts: the SVG bytes do not depend on the machine.
//! A log axis is drawn as log₁₀ of the data on a linear axis with ticks labelled 1eK, which
//! keeps one code path for both kinds of axis.

use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use plotters::style::RGBColor;

/// How a series is drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Style {
    /// A solid line.
    Solid,
    /// A dashed line.
    Dashed,
    /// A dotted line.
    Dotted,
    /// A marker at each point, no line.
    Markers,
    /// Solid line with a marker at each point.
    LineMarkers,
}

/// One named series of (x, y) points.
#[derive(Clone, Debug)]
pub struct Series {
    /// The legend text.
    pub name: String,
    /// The (x, y) points.
    pub points: Vec<(f64, f64)>,
    /// How the series is drawn.
    pub style: Style,
    /// Index into the palette (black, blue, red, green, orange, purple, grey for guides).
    pub color: usize,
}

impl Series {
    /// A series with a colour from the palette.
    pub fn new(
        name: impl Into<String>,
        points: Vec<(f64, f64)>,
        style: Style,
        color: usize,
    ) -> Self {
        Series {
            name: name.into(),
            points,
            style,
            color,
        }
    }
}

/// One chart: axes, labels and series.
#[derive(Clone, Debug, Default)]
pub struct Panel {
    /// The title above the panel.
    pub title: String,
    /// The x-axis label, with units.
    pub x_label: String,
    /// The y-axis label, with units.
    pub y_label: String,
    /// The series drawn.
    pub series: Vec<Series>,
    /// Draw y on a log₁₀ axis (non-positive values are skipped).
    pub log_y: bool,
    /// Same scale on both axes (for paths in the plane).
    pub equal_aspect: bool,
    /// Which corner the legend goes in (another one, or room above the data, when it would
    /// cover data there).
    pub legend: Corner,
    /// A fixed y range (before padding), e.g. one scale shared by the panels of several
    /// figures so they can be compared; `None`: from the data.
    pub y_range: Option<(f64, f64)>,
}

/// A corner of the plotting area.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum Corner {
    /// Upper left.
    #[default]
    UpperLeft,
    /// Upper right.
    UpperRight,
    /// Lower left.
    LowerLeft,
    /// Lower right.
    LowerRight,
}

const PALETTE: [RGBColor; 7] = [
    RGBColor(0, 0, 0),
    RGBColor(0, 90, 181),
    RGBColor(220, 50, 32),
    RGBColor(0, 140, 70),
    RGBColor(230, 140, 0),
    RGBColor(120, 50, 160),
    RGBColor(150, 150, 150),
];

/// A figure could not be drawn.
#[derive(Debug, thiserror::Error)]
#[error("drawing figure failed: {0}")]
pub struct PlotError(String);

fn err<E: std::fmt::Debug>(e: E) -> PlotError {
    PlotError(format!("{e:?}"))
}

/// Render `panels` on a grid of `rows × cols` cells into an SVG document of `size` pixels.
pub fn render(
    panels: &[Panel],
    (rows, cols): (usize, usize),
    size: (u32, u32),
) -> Result<String, PlotError> {
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, size).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let areas = root.split_evenly((rows, cols));
        for (panel, area) in panels.iter().zip(areas.iter()) {
            draw_panel(panel, area)?;
        }
        root.present().map_err(err)?;
    }
    Ok(svg)
}

/// [`render`], or on failure a one-line SVG that says why (so a report never lacks its file).
pub fn render_or_note(panels: &[Panel], layout: (usize, usize), size: (u32, u32)) -> String {
    render(panels, layout, size).unwrap_or_else(|e| {
        format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\"><text x=\"10\" y=\"20\">{e}</text></svg>\n"
        )
    })
}

fn transformed(panel: &Panel, points: &[(f64, f64)]) -> Vec<(f64, f64)> {
    points
        .iter()
        .filter(|(x, y)| x.is_finite() && y.is_finite() && (!panel.log_y || *y > 0.0))
        .map(|&(x, y)| if panel.log_y { (x, y.log10()) } else { (x, y) })
        .collect()
}

fn bounds(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    });
    if !lo.is_finite() {
        return (0.0, 1.0);
    }
    if hi - lo < 1e-12 * (1.0 + lo.abs()) {
        return (lo - 0.5, hi + 0.5);
    }
    let pad = 0.05 * (hi - lo);
    (lo - pad, hi + pad)
}

fn draw_panel<DB: DrawingBackend>(
    panel: &Panel,
    area: &DrawingArea<DB, plotters::coord::Shift>,
) -> Result<(), PlotError> {
    check_distinct(panel)?;
    let data: Vec<Vec<(f64, f64)>> = panel
        .series
        .iter()
        .map(|s| transformed(panel, &s.points))
        .collect();
    let (margin, label_area) = (12u32, 50u32);
    let plot = plot_size(area.dim_in_pixel(), margin, label_area);
    let ranges = axis_ranges(panel, &data, plot);
    let (legend_corner, ((x0, x1), (y0, y1))) = place_legend(panel, &data, ranges, plot);
    let mut chart = ChartBuilder::on(area)
        .caption(&panel.title, ("sans-serif", 16))
        .margin(margin)
        .x_label_area_size(label_area - 10)
        .y_label_area_size(label_area + 10)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(err)?;
    let log_y = panel.log_y;
    let y_fmt = move |v: &f64| {
        if log_y {
            format!("1e{}", v.round() as i64)
        } else {
            tick(*v, y1 - y0)
        }
    };
    let x_fmt = move |v: &f64| tick(*v, x1 - x0);
    let mut mesh = chart.configure_mesh();
    mesh.x_desc(panel.x_label.as_str())
        .y_desc(panel.y_label.as_str())
        .x_label_formatter(&x_fmt)
        .y_label_formatter(&y_fmt)
        .light_line_style(RGBColor(235, 235, 235));
    if log_y {
        mesh.y_labels(((y1 - y0) as usize + 1).min(12));
    }
    mesh.draw().map_err(err)?;
    for (series, points) in panel.series.iter().zip(data) {
        draw_series(&mut chart, series, points)?;
    }
    if panel.series.iter().any(|s| !s.name.is_empty()) {
        let position = match legend_corner {
            Corner::UpperLeft => SeriesLabelPosition::UpperLeft,
            Corner::UpperRight => SeriesLabelPosition::UpperRight,
            Corner::LowerLeft => SeriesLabelPosition::LowerLeft,
            Corner::LowerRight => SeriesLabelPosition::LowerRight,
        };
        chart
            .configure_series_labels()
            .position(position)
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .draw()
            .map_err(err)?;
    }
    Ok(())
}

/// The plotting area's size in pixels inside a panel of `size` (margins, axis labels and the
/// caption taken off).
fn plot_size(size: (u32, u32), margin: u32, label_area: u32) -> (f64, f64) {
    let (w, h) = size;
    (
        w.saturating_sub(margin * 2 + label_area).max(1) as f64,
        h.saturating_sub(margin * 2 + label_area + 24).max(1) as f64,
    )
}

type Ranges = ((f64, f64), (f64, f64));

/// The axis ranges of `panel` over its transformed `data`: padded data bounds, whole decades
/// on a log axis, and equal units on both axes for an equal-aspect panel.
fn axis_ranges(panel: &Panel, data: &[Vec<(f64, f64)>], plot: (f64, f64)) -> Ranges {
    let (x0, x1) = bounds(data.iter().flatten().map(|p| p.0));
    let (mut y0, mut y1) = match panel.y_range {
        Some((lo, hi)) => bounds([lo, hi].into_iter()),
        None => bounds(data.iter().flatten().map(|p| p.1)),
    };
    if panel.log_y {
        (y0, y1) = (y0.floor(), y1.ceil());
    }
    equal_aspect(panel, ((x0, x1), (y0, y1)), plot)
}

/// For an equal-aspect panel, the ranges widened (about their centres) to one scale on both
/// axes; other panels unchanged.
fn equal_aspect(panel: &Panel, ranges: Ranges, (plot_w, plot_h): (f64, f64)) -> Ranges {
    let ((x0, x1), (y0, y1)) = ranges;
    if !panel.equal_aspect {
        return ranges;
    }
    let scale = ((x1 - x0) / plot_w).max((y1 - y0) / plot_h);
    let (cx, cy) = ((x0 + x1) / 2.0, (y0 + y1) / 2.0);
    (
        (cx - scale * plot_w / 2.0, cx + scale * plot_w / 2.0),
        (cy - scale * plot_h / 2.0, cy + scale * plot_h / 2.0),
    )
}

/// The legend's size in pixels, by the same fixed text rule as the rest of the figure: a
/// sample, a gap and about 7 px per character across; 20 px per entry down.
fn legend_size(panel: &Panel) -> (f64, f64) {
    let named: Vec<&Series> = panel.series.iter().filter(|s| !s.name.is_empty()).collect();
    let chars = named
        .iter()
        .map(|s| s.name.chars().count())
        .max()
        .unwrap_or(0);
    (chars as f64 * 7.0 + 50.0, named.len() as f64 * 20.0 + 16.0)
}

/// Where the legend goes so that it covers no data: the panel's preferred corner if its box is
/// empty, else the first empty corner, else above the data (the y range grown by the legend's
/// height, which leaves the upper corners empty). Lines are checked between their points too.
fn place_legend(
    panel: &Panel,
    data: &[Vec<(f64, f64)>],
    ranges: Ranges,
    plot: (f64, f64),
) -> (Corner, Ranges) {
    if panel.series.iter().all(|s| s.name.is_empty()) {
        return (panel.legend, ranges);
    }
    // The points a reader sees: each series' points, and for lines 8 more per segment.
    let mut seen = Vec::new();
    for (series, points) in panel.series.iter().zip(data) {
        seen.extend_from_slice(points);
        if series.style != Style::Markers {
            for w in points.windows(2) {
                let ((ax, ay), (bx, by)) = (w[0], w[1]);
                seen.extend((1..8).map(|k| {
                    let f = k as f64 / 8.0;
                    (ax + f * (bx - ax), ay + f * (by - ay))
                }));
            }
        }
    }
    let (lw, lh) = legend_size(panel);
    // The legend's box with a 10-pixel gap to the frame, as fractions of the plotting area.
    let (fw, fh) = (
        ((lw + 14.0) / plot.0).min(1.0),
        ((lh + 14.0) / plot.1).min(0.9),
    );
    let free = |corner: Corner, ((x0, x1), (y0, y1)): Ranges| {
        let (w, h) = (fw * (x1 - x0), fh * (y1 - y0));
        let (left, right) = match corner {
            Corner::UpperLeft | Corner::LowerLeft => (x0, x0 + w),
            _ => (x1 - w, x1),
        };
        let (bottom, top) = match corner {
            Corner::UpperLeft | Corner::UpperRight => (y1 - h, y1),
            _ => (y0, y0 + h),
        };
        !seen
            .iter()
            .any(|&(x, y)| x >= left && x <= right && y >= bottom && y <= top)
    };
    let order = [
        panel.legend,
        Corner::UpperRight,
        Corner::UpperLeft,
        Corner::LowerRight,
        Corner::LowerLeft,
    ];
    if let Some(&corner) = order.iter().find(|&&c| free(c, ranges)) {
        return (corner, ranges);
    }
    // Headroom: a span S with S·fh ≤ S − H leaves the legend's height above the data.
    let ((x0, x1), (y0, y1)) = ranges;
    let grown = equal_aspect(panel, ((x0, x1), (y0, y0 + (y1 - y0) / (1.0 - fh))), plot);
    let corner = match panel.legend {
        Corner::UpperLeft | Corner::LowerLeft => Corner::UpperLeft,
        _ => Corner::UpperRight,
    };
    (corner, grown)
}

/// One series in its style, with its legend entry drawn in the same style.
fn draw_series<'a, DB: DrawingBackend + 'a>(
    chart: &mut ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>,
    series: &Series,
    points: Vec<(f64, f64)>,
) -> Result<(), PlotError> {
    let color = PALETTE[series.color % PALETTE.len()];
    let line = color.stroke_width(2);
    let anno = match series.style {
        Style::Solid => chart
            .draw_series(LineSeries::new(points, line))
            .map_err(err)?,
        Style::Dashed => chart
            .draw_series(DashedLineSeries::new(points, 8, 5, line))
            .map_err(err)?,
        Style::Dotted => chart
            .draw_series(DashedLineSeries::new(points, 2, 4, line))
            .map_err(err)?,
        Style::Markers => chart
            .draw_series(
                points
                    .into_iter()
                    .map(|p| Circle::new(p, 3, color.filled())),
            )
            .map_err(err)?,
        Style::LineMarkers => {
            chart
                .draw_series(LineSeries::new(points.clone(), line))
                .map_err(err)?;
            chart
                .draw_series(
                    points
                        .into_iter()
                        .map(|p| Circle::new(p, 3, color.filled())),
                )
                .map_err(err)?
        }
    };
    if !series.name.is_empty() {
        let style = series.style;
        anno.label(series.name.as_str()).legend(move |(x, y)| {
            let ([a, b, c], dot) = legend_sample(style, color);
            EmptyElement::at((x, y)) + a + b + c + dot
        });
    }
    Ok(())
}

/// Three segments and a marker, relative to a legend entry's anchor.
type LegendSample = ([PathElement<(i32, i32)>; 3], Circle<(i32, i32), i32>);

/// The legend's sample of a series, drawn in its own style (line, dashes, dots, marker), so
/// that two series of one colour are still told apart: always three segments and a marker,
/// in coordinates relative to the legend entry's anchor; the parts a style does not use are
/// transparent.
fn legend_sample(style: Style, color: RGBColor) -> LegendSample {
    let line = |on: bool| {
        if on {
            color.stroke_width(2)
        } else {
            color.mix(0.0).stroke_width(0)
        }
    };
    let segments: [(i32, i32); 3] = match style {
        Style::Dashed => [(0, 7), (11, 18), (18, 18)],
        Style::Dotted => [(0, 2), (8, 10), (16, 18)],
        _ => [(0, 6), (6, 12), (12, 18)],
    };
    let drawn = !matches!(style, Style::Markers);
    let marker = matches!(style, Style::Markers | Style::LineMarkers);
    let lines = segments.map(|(s, e)| PathElement::new(vec![(s, 0), (e, 0)], line(drawn)));
    let dot = Circle::new(
        (9, 0),
        3,
        if marker {
            color.filled()
        } else {
            color.mix(0.0).filled()
        },
    );
    (lines, dot)
}

/// Two named series of one panel that look the same (colour and style) cannot be told apart
/// in the legend: refuse to draw such a panel.
fn check_distinct(panel: &Panel) -> Result<(), PlotError> {
    let named: Vec<&Series> = panel.series.iter().filter(|s| !s.name.is_empty()).collect();
    for (i, a) in named.iter().enumerate() {
        if let Some(b) = named[i + 1..]
            .iter()
            .find(|b| b.color % PALETTE.len() == a.color % PALETTE.len() && b.style == a.style)
        {
            return Err(PlotError(format!(
                "panel \"{}\": series \"{}\" and \"{}\" have the same colour and style",
                panel.title, a.name, b.name
            )));
        }
    }
    Ok(())
}

/// A short tick label: integers plainly, others with up to 4 significant digits; a value
/// within 1e-9 of the axis span from 0 is 0 (tick positions are sums of steps, and a roundoff
/// "2.78e-17" would overprint the axis label).
fn tick(v: f64, span: f64) -> String {
    let v = if v.abs() <= 1e-9 * span.abs() { 0.0 } else { v };
    if v == 0.0 || (v.abs() >= 1e-3 && v.abs() < 1e5) {
        let s = format!("{:.4}", v);
        let s = s.trim_end_matches('0').trim_end_matches('.');
        if s == "-0" {
            "0".into()
        } else {
            s.into()
        }
    } else {
        format!("{v:.2e}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn panel(log_y: bool) -> Panel {
        Panel {
            title: "t".into(),
            x_label: "x".into(),
            y_label: "y".into(),
            series: vec![Series::new(
                "a",
                vec![(0.0, 1.0), (1.0, 100.0), (2.0, 1e6)],
                Style::LineMarkers,
                1,
            )],
            log_y,
            ..Panel::default()
        }
    }

    #[test]
    fn renders_identical_bytes_twice() {
        let a = render(&[panel(true), panel(false)], (1, 2), (800, 300)).unwrap();
        let b = render(&[panel(true), panel(false)], (1, 2), (800, 300)).unwrap();
        assert_eq!(a, b);
        assert!(a.starts_with("<svg"));
        assert!(a.contains("1e6"));
    }

    #[test]
    fn series_that_look_alike_are_refused() {
        let mut p = panel(false);
        p.series
            .push(Series::new("b", vec![(0.0, 2.0)], Style::LineMarkers, 1));
        assert!(render(&[p.clone()], (1, 1), (400, 300)).is_err());
        p.series[1].style = Style::Dashed;
        assert!(render(&[p], (1, 1), (400, 300)).is_ok());
    }

    #[test]
    fn legends_go_to_an_empty_corner_or_above_the_data() {
        // Data only in the upper-left corner: the preferred upper left is taken, another
        // corner is chosen and the ranges are kept.
        let mut p = panel(false);
        p.series = vec![Series::new(
            "a",
            vec![(0.0, 1.0), (0.1, 0.9)],
            Style::Solid,
            1,
        )];
        p.series
            .push(Series::new("b", vec![(1.0, 0.0)], Style::Markers, 2));
        let plot = (400.0, 300.0);
        let data: Vec<Vec<(f64, f64)>> = p.series.iter().map(|s| s.points.clone()).collect();
        let ranges = axis_ranges(&p, &data, plot);
        let (corner, kept) = place_legend(&p, &data, ranges, plot);
        assert_ne!(corner, Corner::UpperLeft);
        assert_eq!(kept, ranges);
        // A square's outline touches all four corners: the legend goes above the data.
        let square = vec![(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0), (0.0, 0.0)];
        p.series[0].points = square.clone();
        let data: Vec<Vec<(f64, f64)>> = p.series.iter().map(|s| s.points.clone()).collect();
        let ranges = axis_ranges(&p, &data, plot);
        let (corner, ((_, _), (y0, y1))) = place_legend(&p, &data, ranges, plot);
        assert!(matches!(corner, Corner::UpperLeft | Corner::UpperRight));
        let (_, lh) = legend_size(&p);
        let legend_bottom = y1 - (lh + 14.0) / plot.1 * (y1 - y0);
        assert!(
            legend_bottom >= 1.0,
            "legend reaches down to y = {legend_bottom}"
        );
    }

    #[test]
    fn tick_labels() {
        assert_eq!(tick(2.0, 10.0), "2");
        assert_eq!(tick(0.25, 1.0), "0.25");
        assert_eq!(tick(-0.0, 1.0), "0");
        assert_eq!(tick(123456.0, 1e6), "1.23e5");
        // A roundoff zero among ticks 0.1 apart is 0; a genuinely small axis keeps it.
        assert_eq!(tick(2.78e-17, 0.5), "0");
        assert_eq!(tick(2.78e-17, 1e-16), "2.78e-17");
    }
}
