//! The cost models of `run` against measurement.
//!
//! Every `run` algorithm estimates its time from the sizes of its input before it computes
//! (`cli::budget`), and refuses what would exceed the 30 s budget. This bench runs each
//! algorithm in process on a grid of sizes in each number type it takes, and prints per run the
//! measured wall time, the model's estimate and their ratio; then, per algorithm and number
//! type, the range of the ratios. A model holds when every ratio lies in [1/4, 4]: it neither
//! lets a run overshoot the budget nor refuses runs four times cheaper than it says.
//!
//! `cargo bench --bench cost_models` (about two minutes; `COST_MODELS=quick` runs the two
//! smallest sizes only). The grid's largest sizes take a few seconds each, where the models
//! matter; the smallest show the fixed costs the models ignore (a ratio far from 1 on a
//! run of a few milliseconds is not a model that fails: the summary counts runs of at
//! least 0.05 s).

use std::time::Instant;
use trajverify::cli::{budget, run_text, Algorithm};
use trajverify::scalar::ScalarKind;

/// A deterministic pseudo-random decimal in [−10, 10] with six digits (the same inputs on
/// every run of the bench).
struct Digits(u64);

impl Digits {
    fn next(&mut self) -> String {
        // xorshift64*
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let r = self.0.wrapping_mul(0x2545_F491_4F6C_DD1D);
        let micro = (r % 20_000_001) as i64 - 10_000_000;
        format!("{}", micro as f64 / 1e6)
    }
    fn list(&mut self, n: usize) -> String {
        let items: Vec<String> = (0..n).map(|_| self.next()).collect();
        format!("[{}]", items.join(","))
    }
}

fn hermite(m: usize) -> String {
    let mut d = Digits(7);
    let side = |d: &mut Digits| {
        let rows: Vec<String> = (0..=m).map(|_| d.list(HERMITE_DIMENSIONS)).collect();
        format!("[{}]", rows.join(","))
    };
    format!(
        r#"{{"start": {}, "end": {}, "interval": [0, 1]}}"#,
        side(&mut d),
        side(&mut d)
    )
}

/// Hermite data in this many coordinates (enough work per derivative to time).
const HERMITE_DIMENSIONS: usize = 200;

/// Knots 1 ± 0.1 apart with six decimals, as measured data come.
fn knots(n: usize, d: &mut Digits) -> Vec<f64> {
    let mut t = Vec::with_capacity(n);
    let mut x = 0.0;
    for _ in 0..n {
        t.push((x * 1e6_f64).round() / 1e6);
        x += 1.0 + d.next().parse::<f64>().unwrap_or(0.0) / 100.0;
    }
    t
}

fn natural_spline(n: usize) -> String {
    let mut d = Digits(11);
    let knots = knots(n, &mut d);
    let t: Vec<String> = knots.iter().map(|x| format!("{x:.6}")).collect();
    let at: Vec<String> = knots
        .windows(2)
        .map(|w| format!("{:.6}", (w[0] + w[1]) / 2.0))
        .chain([format!("{:.6}", knots[n - 1])])
        .collect();
    format!(
        r#"{{"t": [{}], "z": {}, "at": [{}]}}"#,
        t.join(","),
        d.list(n),
        at.join(",")
    )
}

fn spline_fit(controls: usize) -> String {
    let mut d = Digits(13);
    let degree = 3;
    // One datum near the centre j + 2 of each cubic B_j, six decimals.
    let times: Vec<String> = (0..controls)
        .map(|i| {
            let jitter = d.next().parse::<f64>().unwrap_or(0.0) / 40.0;
            format!("{:.6}", i as f64 + 2.0 + jitter)
        })
        .collect();
    format!(
        r#"{{"degree": {degree}, "controls": {controls}, "times": [{}], "values": {}}}"#,
        times.join(","),
        d.list(controls)
    )
}

/// A smoothing fit (unit weights) of 2M data spread evenly over the support, M controls.
fn spline_smoothing(controls: usize) -> String {
    let mut d = Digits(23);
    let data = 2 * controls;
    let span = (controls + 2) as f64;
    let times: Vec<String> = (0..data)
        .map(|i| format!("{:.6}", 0.5 + span * (i as f64 + 0.5) / data as f64))
        .collect();
    let weights = vec!["1"; data].join(",");
    format!(
        r#"{{"degree": 3, "controls": {controls}, "times": [{}], "values": {}, "weights": [{weights}]}}"#,
        times.join(","),
        d.list(data)
    )
}

fn marin_1d(n: usize) -> String {
    let mut d = Digits(19);
    format!(r#"{{"z": {}}}"#, d.list(n))
}

fn marin(n: usize) -> String {
    let mut d = Digits(17);
    let points: Vec<String> = (0..n).map(|_| d.list(2)).collect();
    format!(r#"{{"points": [{}]}}"#, points.join(","))
}

fn hermite_condition(m: usize) -> String {
    format!(r#"{{"derivatives": {m}, "interval": [0, 1], "matrix": "transform"}}"#)
}

fn phodcos(segments: usize) -> String {
    format!(
        r#"{{"curve": "[1.5*sin(7.2*t), cos(9*t), exp(cos(1.8*t))]", "interval": [0, 1], "segments": {segments}}}"#
    )
}

fn convergence(level: usize) -> String {
    format!(
        r#"{{"curve": "[1.5*sin(7.2*t), cos(9*t), exp(cos(1.8*t))]", "interval": [0, 1], "levels": [{}, {level}]}}"#,
        level - 1
    )
}

fn waypoints(n: usize) -> String {
    let points: Vec<String> = (0..n)
        .map(|i| {
            format!(
                "[{}, {}]",
                300 * i,
                if i % 2 == 0 { 0 } else { 100 + 10 * (i % 7) }
            )
        })
        .collect();
    format!("[{}]", points.join(","))
}

fn gerbs_path(n: usize) -> String {
    format!(
        r#"{{"waypoints": {}, "radius": 30, "theta_o": "pi/8", "kind": "bfbs", "samples": 50}}"#,
        waypoints(n)
    )
}

fn dubins(n: usize) -> String {
    format!(
        r#"{{"waypoints": {}, "radius": 80, "samples": 20}}"#,
        waypoints(n)
    )
}

fn gerbs_basis(points: usize) -> String {
    let at: Vec<String> = (0..points)
        .map(|i| format!("{}", (i as f64 + 0.5) / points as f64))
        .collect();
    format!(
        r#"{{"knots": [0, 0, 0.25, 0.5, 0.75, 1, 1], "kind": "erbs", "at": [{}], "derivatives": 2}}"#,
        at.join(",")
    )
}

/// One algorithm in one number type on a grid of sizes.
struct Grid {
    algorithm: Algorithm,
    name: &'static str,
    scalar: &'static str,
    size: &'static str,
    sizes: &'static [usize],
    input: fn(usize) -> String,
}

const GRIDS: &[Grid] = &[
    Grid {
        algorithm: Algorithm::Hermite,
        name: "hermite",
        scalar: "f64",
        size: "m",
        sizes: &[20, 40, 80, 120],
        input: hermite,
    },
    Grid {
        algorithm: Algorithm::Hermite,
        name: "hermite",
        scalar: "rational",
        size: "m",
        sizes: &[25, 50, 100, 150],
        input: hermite,
    },
    Grid {
        algorithm: Algorithm::Hermite,
        name: "hermite",
        scalar: "mpfr:256",
        size: "m",
        sizes: &[20, 40, 80, 120],
        input: hermite,
    },
    Grid {
        algorithm: Algorithm::HermiteCondition,
        name: "hermite-condition",
        scalar: "f64",
        size: "m",
        sizes: &[10, 20, 30, 35],
        input: hermite_condition,
    },
    Grid {
        algorithm: Algorithm::HermiteCondition,
        name: "hermite-condition",
        scalar: "mpfr:256",
        size: "m",
        sizes: &[10, 20, 30, 40],
        input: hermite_condition,
    },
    Grid {
        algorithm: Algorithm::NaturalSpline,
        name: "natural-spline",
        scalar: "f64",
        size: "N = P",
        sizes: &[10_000, 40_000, 160_000],
        input: natural_spline,
    },
    Grid {
        algorithm: Algorithm::NaturalSpline,
        name: "natural-spline",
        scalar: "rational",
        size: "N = P",
        sizes: &[100, 200, 400, 800],
        input: natural_spline,
    },
    Grid {
        algorithm: Algorithm::NaturalSpline,
        name: "natural-spline",
        scalar: "mpfr:256",
        size: "N = P",
        sizes: &[1000, 4000, 16_000],
        input: natural_spline,
    },
    Grid {
        algorithm: Algorithm::SplineFit,
        name: "spline-fit smoothing",
        scalar: "f64",
        size: "M (N = 2M)",
        sizes: &[100, 200, 400],
        input: spline_smoothing,
    },
    Grid {
        algorithm: Algorithm::SplineFit,
        name: "spline-fit smoothing",
        scalar: "rational",
        size: "M (N = 2M)",
        sizes: &[20, 40, 80],
        input: spline_smoothing,
    },
    Grid {
        algorithm: Algorithm::SplineFit,
        name: "spline-fit smoothing",
        scalar: "mpfr:256",
        size: "M (N = 2M)",
        sizes: &[100, 200, 400],
        input: spline_smoothing,
    },
    Grid {
        algorithm: Algorithm::SplineFit,
        name: "spline-fit",
        scalar: "f64",
        size: "M = N",
        sizes: &[10, 20, 30, 40],
        input: spline_fit,
    },
    Grid {
        algorithm: Algorithm::SplineFit,
        name: "spline-fit",
        scalar: "rational",
        size: "M = N",
        sizes: &[10, 20, 30, 40],
        input: spline_fit,
    },
    Grid {
        algorithm: Algorithm::SplineFit,
        name: "spline-fit",
        scalar: "mpfr:256",
        size: "M = N",
        sizes: &[10, 20, 30, 40],
        input: spline_fit,
    },
    Grid {
        algorithm: Algorithm::Marin1d,
        name: "marin-1d",
        scalar: "f64",
        size: "N",
        sizes: &[1000, 4000, 16_000],
        input: marin_1d,
    },
    Grid {
        algorithm: Algorithm::Marin1d,
        name: "marin-1d",
        scalar: "mpfr:256",
        size: "N",
        sizes: &[100, 400, 1600],
        input: marin_1d,
    },
    Grid {
        algorithm: Algorithm::Marin,
        name: "marin",
        scalar: "f64",
        size: "N",
        sizes: &[20, 50, 100, 200],
        input: marin,
    },
    Grid {
        algorithm: Algorithm::Marin,
        name: "marin",
        scalar: "mpfr:256",
        size: "N",
        sizes: &[10, 20, 40, 80],
        input: marin,
    },
    Grid {
        algorithm: Algorithm::Phodcos,
        name: "phodcos",
        scalar: "f64",
        size: "segments",
        sizes: &[64, 256, 1024, 4096],
        input: phodcos,
    },
    Grid {
        algorithm: Algorithm::Phodcos,
        name: "phodcos",
        scalar: "mpfr:256",
        size: "segments",
        sizes: &[16, 64, 256, 1024],
        input: phodcos,
    },
    Grid {
        algorithm: Algorithm::Convergence,
        name: "convergence",
        scalar: "mpfr:256",
        size: "level",
        sizes: &[4, 6, 8, 10],
        input: convergence,
    },
    Grid {
        algorithm: Algorithm::GerbsBasis,
        name: "gerbs-basis",
        scalar: "f64",
        size: "points",
        sizes: &[1600, 16_000, 100_000],
        input: gerbs_basis,
    },
    Grid {
        algorithm: Algorithm::GerbsBasis,
        name: "gerbs-basis",
        scalar: "mpfr:128",
        size: "points",
        sizes: &[4, 64, 256],
        input: gerbs_basis,
    },
    Grid {
        algorithm: Algorithm::GerbsPath,
        name: "gerbs-path",
        scalar: "f64",
        size: "waypoints",
        sizes: &[5, 20, 80],
        input: gerbs_path,
    },
    Grid {
        algorithm: Algorithm::GerbsPath,
        name: "gerbs-path",
        scalar: "mpfr:128",
        size: "waypoints",
        sizes: &[4, 10, 20],
        input: gerbs_path,
    },
    Grid {
        algorithm: Algorithm::Dubins,
        name: "dubins",
        scalar: "f64",
        size: "waypoints",
        sizes: &[100, 1000, 4000],
        input: dubins,
    },
    Grid {
        algorithm: Algorithm::Dubins,
        name: "dubins",
        scalar: "mpfr:256",
        size: "waypoints",
        sizes: &[10, 40, 160, 640],
        input: dubins,
    },
];

/// Runs shorter than this show fixed costs, not the model's terms.
const COUNTED_SECONDS: f64 = 0.05;

fn main() {
    let quick = std::env::var("COST_MODELS").is_ok_and(|v| v == "quick");
    let filter = std::env::args().skip(1).find(|a| !a.starts_with('-'));
    println!("| algorithm | scalar | size | measured | model | measured/model |");
    println!("|---|---|---|---|---|---|");
    let mut summary = Vec::new();
    for grid in GRIDS {
        if filter
            .as_ref()
            .is_some_and(|f| !grid.name.contains(f.as_str()))
        {
            continue;
        }
        let scalar: ScalarKind = match grid.scalar.parse() {
            Ok(s) => s,
            Err(e) => {
                println!(
                    "| {} | {} | | cannot parse the scalar: {e} | | |",
                    grid.name, grid.scalar
                );
                continue;
            }
        };
        let sizes = if quick { &grid.sizes[..2] } else { grid.sizes };
        let mut ratios = Vec::new();
        for &n in sizes {
            let text = (grid.input)(n);
            let start = Instant::now();
            let result = run_text(grid.algorithm, Some(scalar), &text);
            let measured = start.elapsed().as_secs_f64();
            let model = budget::accepted_estimate();
            match (result, model) {
                (Ok(_), Some(model)) if model > 0.0 => {
                    let ratio = measured / model;
                    if measured >= COUNTED_SECONDS {
                        ratios.push(ratio);
                    }
                    println!(
                        "| {} | {} | {} = {n} | {measured:.3} s | {model:.3} s | {ratio:.2} |",
                        grid.name, grid.scalar, grid.size
                    );
                }
                (Ok(_), _) => println!(
                    "| {} | {} | {} = {n} | {measured:.3} s | no estimate | |",
                    grid.name, grid.scalar, grid.size
                ),
                (Err(e), _) => {
                    let message = format!("{e:?}");
                    let short: String = message.chars().take(120).collect();
                    println!(
                        "| {} | {} | {} = {n} | refused or failed: {short} | | |",
                        grid.name, grid.scalar, grid.size
                    );
                }
            }
        }
        summary.push((grid.name, grid.scalar, ratios));
    }
    println!();
    println!("| algorithm | scalar | runs ≥ {COUNTED_SECONDS} s | least ratio | largest ratio | within 4× |");
    println!("|---|---|---|---|---|---|");
    for (name, scalar, ratios) in summary {
        if ratios.is_empty() {
            println!("| {name} | {scalar} | 0 | | | no run long enough |");
            continue;
        }
        let least = ratios.iter().cloned().fold(f64::INFINITY, f64::min);
        let largest = ratios.iter().cloned().fold(0.0, f64::max);
        let holds = least >= 0.25 && largest <= 4.0;
        println!(
            "| {name} | {scalar} | {} | {least:.2} | {largest:.2} | {} |",
            ratios.len(),
            if holds { "yes" } else { "no" }
        );
    }
}
