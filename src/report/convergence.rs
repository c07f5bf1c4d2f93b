//! A convergence study ([`crate::algo::convergence`]) as a report: Markdown with the table of
//! levels and what the orders say, an SVG figure with a slope guide for the expected order
//! and the precision floor marked, and the JSON of every number.

use super::number::{self, bound_text, sig};
use super::plot::{self, Corner, Panel, Series, Style};
use super::table;
use crate::algo::convergence::{FitOutcome, Row, Status, Study};

use rug::float::Round;
use serde_json::json;

/// What the report says of the curve: how the user gave it, and a short name for titles.
pub struct Described<'a> {
    /// The curve as given ("`[sin(t), t, 0]`", or a data file with its fit).
    pub curve: &'a str,
    /// A short label for the figure's title.
    pub label: &'a str,
    /// [a, b] as written.
    pub interval: (&'a str, &'a str),
    /// The scalar as given on the command line.
    pub scalar: String,
}

/// The three files: `convergence.md`, `convergence.svg`, `convergence.json`.
pub fn files(study: &Study, d: &Described) -> Vec<(String, String)> {
    vec![
        ("convergence.md".into(), markdown(study, d)),
        ("convergence.svg".into(), figure(study, d)),
        ("convergence.json".into(), json_text(study, d)),
    ]
}

/// The sampled maximum with the digits its two precisions agree on (at most `cap`).
fn sampled_text(r: &Row, cap: u32) -> String {
    number::float_in(
        &r.sampled.1,
        r.sampled_digits().clamp(1, cap),
        number::Notation::Scientific,
    )
}

fn proven_text(r: &Row) -> String {
    r.proven.as_ref().map_or("—".into(), |(lo, hi)| {
        format!(
            "[{}, {}]",
            bound_text(lo, 8, Round::Down),
            bound_text(hi, 8, Round::Up)
        )
    })
}

fn status_text(r: &Row) -> &'static str {
    match r.status {
        Status::Resolved => "",
        Status::Zero => "zero to this precision",
        Status::Floor if r.proven.is_some() => "below the proof's precision floor (raise the bits)",
        Status::Floor => "below the precision floor",
    }
}

fn f64_text(r: &Row) -> String {
    r.f64_error.map_or("not finite in f64".into(), |e| {
        number::sig_in(e, 4, number::Notation::Scientific)
    })
}

fn table_rows(study: &Study) -> Vec<Vec<String>> {
    study
        .rows
        .iter()
        .zip(&study.orders)
        .map(|(r, o)| {
            let order = o.as_ref().map_or("—".into(), |o| match o.proven {
                Some((lo, hi)) if hi - lo > 1e-3 => format!(
                    "{} ∈ [{}, {}]",
                    order_text(o.value),
                    number::bound(lo, 4, Round::Down),
                    number::bound(hi, 4, Round::Up)
                ),
                _ => order_text(o.value),
            });
            let mut row = vec![r.segments.to_string()];
            if study.proof {
                row.push(proven_text(r));
            }
            row.push(match r.sampled_digits() {
                0 => "no digit agrees".into(),
                1 => format!("{} (1 digit)", sampled_text(r, 10)),
                d => format!("{} ({d} digits)", sampled_text(r, 10)),
            });
            row.push(f64_text(r));
            row.push(order);
            let mut note = status_text(r).to_string();
            if r.search_missed {
                note.push_str(if note.is_empty() { "" } else { "; " });
                note.push_str("sampled search missed the maximum");
            }
            row.push(note);
            row
        })
        .collect()
}

/// An order to five significant digits ("0" for zero, never "-0").
fn order_text(value: f64) -> String {
    if value == 0.0 {
        return "0".into();
    }
    sig(value, 5)
}

fn fit_lines(study: &Study) -> Vec<String> {
    let expected = &study.expected;
    match &study.fit {
        FitOutcome::Reproduced { bound } => vec![format!(
            "the method reproduces the curve: every error is zero to the working precision (E ≤ {}), so there is no order to fit",
            sig(*bound, 3)
        )],
        FitOutcome::TooFew(why) => vec![format!("no order fitted: {why}")],
        FitOutcome::Fitted(f) => {
            let value = match f.ci95 {
                Some(ci) => format!("{:.4} ± {ci:.4} (95 %)", f.order),
                None => format!("{:.4} (two levels fit exactly; no interval)", f.order),
            };
            let mut lines = vec![
                format!("fitted order: {value}, least squares over {}", f.why),
                match f.expected_inside {
                    Some(true) => format!(
                        "the expected order {} lies inside the 95 % interval",
                        expected.order
                    ),
                    Some(false) => format!(
                        "the expected order {} lies outside the 95 % interval",
                        expected.order
                    ),
                    None => format!(
                        "the expected order {} cannot be tested against two levels (no interval)",
                        expected.order
                    ),
                },
            ];
            if let Some((first, last)) = f.drift {
                lines.push(format!(
                    "the observed order still {} across the fitted levels ({first:.4} → {last:.4}), by more than the interval: \
                     the fit assumes a constant order, so terms of higher order in h bias it and its interval is too narrow; \
                     the finest observed order is the better estimate, and finer levels move it",
                    if last > first { "rises" } else { "falls" }
                ));
            }
            lines
        }
    }
}

fn f64_lines(study: &Study) -> Vec<String> {
    let rows = &study.rows;
    let floor = study.f64_floor.map_or(
        "f64 keeps improving over these levels".into(),
        |i| {
            format!(
                "f64 stops improving at {} segments, its smallest error ({}); the true error keeps falling after it",
                rows[i].segments,
                sig(rows[i].f64_error.unwrap_or(f64::NAN), 3)
            )
        },
    );
    let departs = study.f64_departs.map_or(
        "f64 stays within 10 % of the reference error at every resolved level".into(),
        |i| {
            format!(
                "f64 departs from the reference error by more than 10 % from {} segments",
                rows[i].segments
            )
        },
    );
    vec![floor, departs]
}

fn markdown(study: &Study, d: &Described) -> String {
    let (bits, method) = (study.bits, study.method);
    let measured = if study.proof {
        format!(
            "E proven: lower ≤ E ≤ upper by branch and bound in ball arithmetic at {bits} bits, printed rounded outward. \
             E sampled: the maximum over 16 samples per segment refined by Newton at {bits} bits and recomputed at {} bits, \
             with the digits the two agree on — a cross-check of the proof, certified in its arithmetic only (a maximum the \
             samples miss is missed at both precisions).",
            2 * bits
        )
    } else {
        format!(
            "E sampled: the maximum over 16 samples per segment refined by Newton at {bits} bits and recomputed at {} bits, \
             with the digits the two agree on. **This is a sampled maximum, not certified**: the two precisions certify its \
             arithmetic, not the search; run with `--scalar ball:<bits>` for proven errors. No order below is certified.",
            2 * bits
        )
    };
    let mut headers = vec!["segments"];
    if study.proof {
        headers.push("E proven");
    }
    headers.extend([
        "E sampled (agreeing digits)",
        "E f64",
        "observed order",
        "note",
    ]);
    let mut bullets = fit_lines(study);
    bullets.push(format!(
        "expected order: {} ({})",
        study.expected.order, study.expected.reason
    ));
    bullets.extend(f64_lines(study));
    bullets.extend(study.notes.iter().cloned());
    let bullets: String = bullets.iter().map(|b| format!("- {b}\n")).collect();
    format!(
        "# Convergence of {} on {}\n\nCurve {} on [{}, {}], {} on 2ⁿ uniform segments; E = max over ξ of ‖γ − p‖ \
         (paper 001, Eq. 21). {measured} E f64: the same pipeline in double precision. Levels whose error is zero or has no \
         digit at this precision (below {}) are marked and left out of every order.\n\n{}\n{bullets}\n\
         ![error against segments](./convergence.svg)\n",
        method.title(),
        d.label,
        d.curve,
        d.interval.0,
        d.interval.1,
        method.pieces(),
        sig(study.proof_floor.unwrap_or(study.precision_floor), 2),
        table(&headers, &table_rows(study)),
    )
}

/// The error series: the proven bounds, or the sampled maxima without a proof.
fn error_series(study: &Study) -> Vec<Series> {
    let x = |r: &Row| (r.segments as f64).log2();
    if !study.proof {
        return vec![Series::new(
            "sampled maximum (not certified)",
            study
                .rows
                .iter()
                .map(|r| (x(r), r.sampled.1.to_f64()))
                .collect(),
            Style::LineMarkers,
            0,
        )];
    }
    let bound = |upper: bool| -> Vec<(f64, f64)> {
        study
            .rows
            .iter()
            .filter_map(|r| {
                r.proven
                    .as_ref()
                    .map(|(lo, hi)| (x(r), if upper { hi.to_f64() } else { lo.to_f64() }))
            })
            .collect()
    };
    vec![
        Series::new("proven upper bound", bound(true), Style::LineMarkers, 0),
        Series::new("proven lower bound", bound(false), Style::Dotted, 0),
    ]
}

fn figure(study: &Study, d: &Described) -> String {
    let x = |r: &Row| (r.segments as f64).log2();
    let resolved: Vec<&Row> = study
        .rows
        .iter()
        .filter(|r| r.status == Status::Resolved)
        .collect();
    let mut series = error_series(study);
    series.push(Series::new(
        "f64 pipeline",
        study
            .rows
            .iter()
            .filter_map(|r| r.f64_error.map(|e| (x(r), e)))
            .collect(),
        Style::Markers,
        2,
    ));
    // The slope guide: the expected order through the finest resolved level.
    if let Some(last) = resolved.last() {
        let k = study.expected.order as f64;
        let (x1, y1) = (x(last), last.value());
        let x0 = x(&study.rows[0]);
        let guide: Vec<(f64, f64)> = [x0, x1]
            .iter()
            .map(|&xi| (xi, y1 * 2f64.powf(-k * (xi - x1))))
            .collect();
        series.push(Series::new(
            format!("slope of order {} (expected)", study.expected.order),
            guide,
            Style::Dashed,
            1,
        ));
    }
    // The floor that applies (the proof's, or the sampled values'), drawn when it lies
    // within two decades of the smallest error shown (further down it would only squash the
    // data; the Markdown states it either way).
    let (first, last) = (x(&study.rows[0]), x(&study.rows[study.rows.len() - 1]));
    let floor = study.proof_floor.unwrap_or(study.precision_floor);
    let smallest = study
        .rows
        .iter()
        .map(|r| {
            r.proven
                .as_ref()
                .map_or(r.sampled.1.to_f64(), |p| p.1.to_f64())
        })
        .filter(|v| *v > 0.0)
        .fold(f64::INFINITY, f64::min);
    if floor >= smallest / 100.0 {
        series.push(Series::new(
            "precision floor",
            vec![(first, floor), (last, floor)],
            Style::Dotted,
            6,
        ));
    }
    let panel = Panel {
        title: format!("{} of {}", study.method.title(), d.label),
        x_label: "n (2ⁿ segments)".into(),
        y_label: "E = max ‖γ − p‖ (curve units)".into(),
        series,
        log_y: true,
        legend: Corner::LowerLeft,
        ..Panel::default()
    };
    plot::render_or_note(&[panel], (1, 1), (900, 560))
}

fn json_text(study: &Study, d: &Described) -> String {
    let rows: Vec<serde_json::Value> = study
        .rows
        .iter()
        .zip(&study.orders)
        .map(|(r, o)| {
            json!({
                "level": r.level,
                "segments": r.segments,
                "status": match r.status {
                    Status::Resolved => "resolved",
                    Status::Zero => "zero",
                    Status::Floor => "floor",
                },
                "error_proven": r.proven.as_ref().map(|(lo, hi)| json!({
                    "lower": bound_text(lo, 17, Round::Down),
                    "upper": bound_text(hi, 17, Round::Up),
                })),
                "error_sampled": sampled_text(r, u32::MAX),
                "error_sampled_digits": r.sampled_digits(),
                "sampled_search_missed": r.search_missed,
                "error_f64": r.f64_error,
                "order": o.as_ref().map(|o| json!({"value": o.value, "proven": o.proven.map(|(a, b)| [a, b])})),
            })
        })
        .collect();
    let fit = match &study.fit {
        FitOutcome::Reproduced { bound } => json!({"outcome": "reproduced", "bound": bound}),
        FitOutcome::TooFew(why) => json!({"outcome": "too few levels", "why": why}),
        FitOutcome::Fitted(f) => json!({
            "outcome": "fitted", "order": f.order, "ci95": f.ci95, "levels": f.levels, "why": f.why,
            "expected_inside": f.expected_inside,
            "drift": f.drift.map(|(a, b)| json!({"first": a, "last": b})),
        }),
    };
    let doc = json!({
        "curve": d.curve,
        "method": study.method.title(),
        "interval": [d.interval.0, d.interval.1],
        "scalar": d.scalar,
        "proven": study.proof,
        "expected_order": {"order": study.expected.order, "reason": study.expected.reason},
        "precision_floor": study.precision_floor,
        "rows": rows,
        "fit": fit,
        "f64_stops_improving_at": study.f64_floor.map(|i| study.rows[i].segments),
        "f64_departs_at": study.f64_departs.map(|i| study.rows[i].segments),
        "notes": study.notes,
    });
    let mut s = serde_json::to_string_pretty(&doc).unwrap_or_default();
    s.push('\n');
    s
}
