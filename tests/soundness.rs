//! The differential soundness test: every printed digit is checked against an independent
//! reference, on seeded random inputs of every `run` algorithm, ordinary and deliberately
//! ill-conditioned.
//!
//! For each input the algorithm runs (in process, through `cli::run_text`) in every number
//! type it accepts at p bits (p = 16, 64 and 128 by default; `SOUNDNESS_BITS` sets the list,
//! `just soundness` runs 16, 24, 32, 64, 128 and 256): `mpfr:p` prints the digits its
//! enclosures prove, `ball:p` prints enclosures. The reference is the exact `rational` run
//! where the algorithm has one, otherwise a run at 64 more bits and at least 128
//! (`mpfr:max(p + 64, 128)`, whose digits are proven too). Then
//! - every number `mpfr:p` prints must lie within half a unit of its last printed digit of
//!   the reference (widened by the reference's own half unit when it is a rounded decimal);
//!   a zero printed at a unit, "0eK", within ½·10^K of it; a bare "0" must be the
//!   reference's exact 0;
//! - every ball {"value", "radius"} must contain the reference as printed:
//!   |value − reference| ≤ radius;
//! - every word, case and count must equal the reference's;
//! - an `f64` answer (at the first p) must have a correct digit in the norm,
//!   max |x − r| < ½ max |r|: a method whose f64 result can lose every digit checks it
//!   against a proven enclosure and refuses it.
//!
//! A run that refuses (exit 2) is counted apart, not compared; exit 3 (an internal defect)
//! on these valid inputs fails the test, as do a wrong digit and a ball that misses, with the
//! input to reproduce it. Inputs include points, knots and times within 1e-30 … 1e-45 of
//! each other, points within 1e-40 of a knot on either side, many derivatives on tiny
//! intervals, straight legs and zero-length arcs, nearly collinear waypoints, weights across
//! 60 orders of magnitude, data of size 1e-20, nearly equal data and near-zero results.
//!
//! `SOUNDNESS_SEED` (default fixed; `random` for a new one), `SOUNDNESS_CASES` (inputs per
//! algorithm, default 12; a third of that for `gerbs-path`, whose runs prove a path length
//! by Taylor models), `SOUNDNESS_BITS` and `SOUNDNESS_SECONDS` (no new input after this
//! many seconds per algorithm) set the run; `just soundness` runs many more. Each test prints
//! its counts (`--nocapture`).

use num_traits::{Signed, Zero};
use serde_json::{json, Value};
use std::time::Instant;
use trajverify::cli::{run_text, Algorithm, Failure};
use trajverify::scalar::parse::parse_rational;
use trajverify::scalar::{BigRational, ScalarKind};

/// SplitMix64: a small, seedable generator (the cases are reproducible from the seed).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// An integer in lo..=hi.
    fn int(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next() % (hi - lo + 1) as u64) as i64
    }
    fn chance(&mut self, p: f64) -> bool {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64 <= p
    }
    fn pick<'a, T>(&mut self, items: &'a [T]) -> &'a T {
        &items[self.int(0, items.len() as i64 - 1) as usize]
    }
    /// A moderate rational as a string: an integer, a fraction or a decimal.
    fn number(&mut self) -> String {
        match self.int(0, 3) {
            0 => self.int(-9, 9).to_string(),
            1 => format!("{}/{}", self.int(-40, 40), self.int(1, 17)),
            2 => format!("{}.{:03}", self.int(-5, 5), self.int(0, 999)),
            _ => format!("{}e-{}", self.int(-99, 99), self.int(1, 3)),
        }
    }
    /// A number of size 1e-20 (near-zero data and results), of either sign.
    fn tiny(&mut self) -> String {
        format!("{}e-{}", self.int(-9, 9), self.int(20, 22))
    }
    /// A moderate number, or with chance `p` one of size 1e-20.
    fn number_or_tiny(&mut self, p: f64) -> String {
        if self.chance(p) {
            self.tiny()
        } else {
            self.number()
        }
    }
    /// A positive number anywhere in 1e-30 … 1e30 (weights across 60 orders of magnitude).
    fn wide_positive(&mut self) -> String {
        format!("{}e{}", self.int(1, 9), self.int(-30, 30))
    }
    /// A positive moderate rational.
    fn positive(&mut self) -> String {
        match self.int(0, 2) {
            0 => self.int(1, 9).to_string(),
            1 => format!("{}/{}", self.int(1, 40), self.int(1, 17)),
            _ => format!("{}.{:03}", self.int(0, 5), self.int(1, 999)),
        }
    }
}

/// `x` plus or minus 10^-e, exactly, as a fraction string (x an integer).
fn near(x: i64, e: u32, above: bool) -> String {
    let scale = BigRational::from_integer(num_bigint::BigInt::from(10).pow(e));
    let step = BigRational::from_integer(1.into()) / scale;
    let q = if above {
        BigRational::from_integer(x.into()) + step
    } else {
        BigRational::from_integer(x.into()) - step
    };
    q.to_string()
}

fn tiny_exponent(rng: &mut Rng) -> u32 {
    rng.int(30, 45) as u32
}

/// One algorithm's generator of inputs, the number types it is tested in, and whether its
/// exact `rational` run is the reference.
struct Subject {
    algorithm: Algorithm,
    name: &'static str,
    generate: fn(&mut Rng) -> Value,
    mpfr: bool,
    ball: bool,
    rational_reference: bool,
}

fn subjects() -> Vec<Subject> {
    use Algorithm::*;
    let s = |algorithm, name, generate: fn(&mut Rng) -> Value, mpfr, ball, rational_reference| {
        Subject {
            algorithm,
            name,
            generate,
            mpfr,
            ball,
            rational_reference,
        }
    };
    vec![
        s(Hermite, "hermite", gen_hermite, true, true, true),
        s(
            HermiteCondition,
            "hermite-condition",
            gen_condition,
            true,
            true,
            false,
        ),
        s(SplineFit, "spline-fit", gen_spline_fit, true, true, true),
        s(BangBang, "bang-bang", gen_bang_bang, true, false, false),
        s(Marin1d, "marin-1d", gen_marin_1d, true, true, false),
        s(Marin, "marin", gen_marin, true, true, false),
        s(
            NaturalSpline,
            "natural-spline",
            gen_natural_spline,
            true,
            true,
            true,
        ),
        s(PhHermite, "ph-hermite", gen_ph_hermite, true, true, false),
        s(Phodcos, "phodcos", gen_phodcos, true, true, false),
        s(
            Convergence,
            "convergence",
            gen_convergence,
            true,
            false,
            false,
        ),
        s(
            GerbsBasis,
            "gerbs-basis",
            gen_gerbs_basis,
            true,
            true,
            false,
        ),
        s(GerbsPath, "gerbs-path", gen_gerbs_path, true, true, false),
        s(Dubins, "dubins", gen_dubins, true, true, false),
    ]
}

fn gen_hermite(rng: &mut Rng) -> Value {
    let m = rng.int(0, 6) as usize;
    let dims = rng.int(1, 3) as usize;
    let tiny = if rng.chance(0.2) { 0.7 } else { 0.0 };
    let value = |rng: &mut Rng| {
        if dims == 1 {
            json!(rng.number_or_tiny(tiny))
        } else {
            json!((0..dims)
                .map(|_| rng.number_or_tiny(tiny))
                .collect::<Vec<_>>())
        }
    };
    let start: Vec<Value> = (0..=m).map(|_| value(rng)).collect();
    let end: Vec<Value> = (0..=m).map(|_| value(rng)).collect();
    let interval = match rng.int(0, 2) {
        0 => json!([0, 1]),
        1 => json!([rng.number(), "100"]),
        _ => {
            let e = tiny_exponent(rng);
            json!(["1", near(1, e, true)])
        }
    };
    json!({"start": start, "end": end, "interval": interval})
}

fn gen_condition(rng: &mut Rng) -> Value {
    let m = rng.int(0, 10);
    let interval = match rng.int(0, 2) {
        0 => json!([0, 1]),
        1 => json!([0, rng.positive()]),
        _ => json!(["1", near(1, tiny_exponent(rng), true)]),
    };
    let matrix = *rng.pick(&["transform", "binomial"]);
    json!({"derivatives": m, "interval": interval, "matrix": matrix})
}

fn gen_spline_fit(rng: &mut Rng) -> Value {
    let degree = rng.int(1, 4);
    let controls = rng.int(2, 9);
    let end = controls + degree;
    let interpolate = rng.chance(0.6);
    let n = if interpolate {
        rng.int(1, controls)
    } else {
        rng.int(1, 10)
    };
    // Times on a grid of quarters inside (0, M + k), some moved 1e-40 off a knot.
    let mut times: Vec<String> = Vec::new();
    while times.len() < n as usize {
        let q = rng.int(1, 4 * end - 1);
        let t = if rng.chance(0.2) {
            near(q / 4 + 1, tiny_exponent(rng), rng.chance(0.5))
        } else {
            format!("{q}/4")
        };
        let exact = parse_rational(&t).unwrap();
        if exact > BigRational::zero()
            && exact < BigRational::from_integer(end.into())
            && !times.iter().any(|s| parse_rational(s).unwrap() == exact)
        {
            times.push(t);
        }
    }
    let tiny = if rng.chance(0.2) { 0.7 } else { 0.0 };
    let values: Vec<String> = times.iter().map(|_| rng.number_or_tiny(tiny)).collect();
    let wide = rng.chance(0.4);
    let weights = if interpolate {
        Value::Null
    } else if wide {
        // Weights across 60 orders of magnitude, now and then a zero.
        json!(times
            .iter()
            .map(|_| if rng.chance(0.1) {
                "0".to_string()
            } else {
                rng.wide_positive()
            })
            .collect::<Vec<_>>())
    } else {
        json!(times.iter().map(|_| rng.positive()).collect::<Vec<_>>())
    };
    json!({"degree": degree, "controls": controls, "times": times, "values": values, "weights": weights})
}

fn gen_bang_bang(rng: &mut Rng) -> Value {
    json!({"xi": rng.number_or_tiny(0.3)})
}

fn gen_marin_1d(rng: &mut Rng) -> Value {
    let n = rng.int(2, 9);
    if rng.chance(0.2) {
        // Nearly equal data: moderate values, one of them moved by 1e-20 relative (the
        // issue's case III data needed 70 bits).
        let mut z: Vec<BigRational> = Vec::new();
        for i in 0..n {
            let mut v = parse_rational(&rng.number()).unwrap();
            if i > 0 && rng.chance(0.5) {
                let prev = z[i as usize - 1].clone();
                let step = BigRational::new(
                    rng.int(1, 99).into(),
                    num_bigint::BigInt::from(10).pow(rng.int(18, 22) as u32),
                );
                v = if rng.chance(0.5) {
                    prev.clone() + step
                } else {
                    prev - step
                };
            }
            while i > 0 && v == z[i as usize - 1] {
                v = parse_rational(&rng.number()).unwrap();
            }
            z.push(v);
        }
        return json!({"z": z.iter().map(|q| q.to_string()).collect::<Vec<_>>()});
    }
    let mut z: Vec<String> = Vec::new();
    for i in 0..n {
        // Occasionally a point 1e-40 above or below its predecessor (a tiny step that still
        // sets a direction).
        if i > 0 && rng.chance(0.2) {
            let prev = parse_rational(&z[i as usize - 1]).unwrap();
            let step = BigRational::new(
                1.into(),
                num_bigint::BigInt::from(10).pow(tiny_exponent(rng)),
            );
            let q = if rng.chance(0.5) {
                prev + step
            } else {
                prev - step
            };
            z.push(q.to_string());
        } else {
            let mut v = rng.number();
            while i > 0
                && parse_rational(&v).unwrap() == parse_rational(&z[i as usize - 1]).unwrap()
            {
                v = rng.number();
            }
            z.push(v);
        }
    }
    json!({"z": z})
}

fn gen_marin(rng: &mut Rng) -> Value {
    let n = rng.int(3, 5);
    let points: Vec<Vec<i64>> = (0..n)
        .map(|i| vec![3 * i + rng.int(0, 2), rng.int(-4, 4)])
        .collect();
    let objective = *rng.pick(&["exact", "approx"]);
    json!({"points": points, "objective": objective})
}

fn gen_natural_spline(rng: &mut Rng) -> Value {
    let n = rng.int(2, 7);
    let t: Vec<i64> = (0..n).map(|i| 2 * i + rng.int(0, 1)).collect();
    let tiny = if rng.chance(0.2) { 0.7 } else { 0.0 };
    let z: Vec<String> = t.iter().map(|_| rng.number_or_tiny(tiny)).collect();
    if rng.chance(0.25) {
        // A knot 1e-30 after another (a near-duplicate), evaluated on both sides of it.
        let k = rng.int(0, n - 2) as usize;
        let close = near(t[k], rng.int(25, 35) as u32, true);
        let mut knots: Vec<String> = t.iter().map(|x| x.to_string()).collect();
        knots.insert(k + 1, close.clone());
        let mut values = z.clone();
        values.insert(k + 1, rng.number());
        let inside = {
            let a = BigRational::from_integer(t[k].into());
            let b = parse_rational(&close).unwrap();
            ((a + b) / BigRational::from_integer(2.into())).to_string()
        };
        let at = vec![
            t[k].to_string(),
            inside,
            close,
            format!("{}/2", 2 * t[0] + 1),
        ];
        return json!({"t": knots, "z": values, "at": at});
    }
    let (first, last) = (t[0], t[t.len() - 1]);
    let at: Vec<String> = (0..4)
        .map(|_| {
            let k = t[rng.int(0, n - 1) as usize];
            match rng.int(0, 2) {
                0 => k.to_string(),
                1 if k < last => near(k, tiny_exponent(rng), true),
                1 | 2 if k > first => near(k, tiny_exponent(rng), false),
                _ => format!("{}/{}", 2 * first + 1, 2),
            }
        })
        .collect();
    json!({"t": t, "z": z, "at": at})
}

fn gen_ph_hermite(rng: &mut Rng) -> Value {
    let v = |rng: &mut Rng| json!([rng.number(), rng.number(), rng.number()]);
    let mut doc = serde_json::Map::new();
    for name in [
        "p_b", "p_e", "v_b", "v_e", "a_b", "a_e", "j_b", "j_e", "s_b", "s_e",
    ] {
        doc.insert(name.into(), v(rng));
    }
    if rng.chance(0.3) {
        // A straight start tangent along x (a branch of the standard form).
        doc.insert("v_b".into(), json!([rng.positive(), 0, 0]));
        doc.insert("v_e".into(), json!(["-7/3", 0, 0]));
    }
    Value::Object(doc)
}

const CURVES: [&str; 5] = [
    "[t, t^2, t^3]",
    "[sin(t), cos(t), t]",
    "[1 + t/3, 2*t - t^2, exp(t/2)]",
    "[t, 0, 0]",
    "[cos(2*t), sin(3*t), t^2/5]",
];

fn gen_phodcos(rng: &mut Rng) -> Value {
    json!({"curve": rng.pick(&CURVES), "interval": [0, rng.positive()], "segments": rng.int(1, 3)})
}

fn gen_convergence(rng: &mut Rng) -> Value {
    let levels = rng
        .pick(&[json!([0, 1, 2]), json!([0, 2, 3]), json!([1, 3])])
        .clone();
    json!({"curve": rng.pick(&CURVES), "interval": [0, rng.pick(&["1", "3/2"])], "levels": levels})
}

fn gen_gerbs_basis(rng: &mut Rng) -> Value {
    let n = rng.int(1, 4);
    // Doubled end knots 0, 0, 1, …, n − 1, n, n.
    let knots: Vec<i64> = {
        let mut k = vec![0, 0];
        k.extend(1..n);
        k.push(n);
        k.push(n);
        k
    };
    if n >= 2 && rng.chance(0.2) {
        // Interior knots 1e-40 apart: knot 1 and one just after it.
        let close = near(1, 40, true);
        let mut with_close: Vec<Value> = knots.iter().map(|k| json!(k)).collect();
        with_close.insert(3, json!(close.clone()));
        let at = vec![json!("1"), json!(close), json!("1/2")];
        return json!({
            "knots": with_close, "kind": "bfbs", "params": {"i": rng.int(1, 3)}, "at": at,
            "derivatives": rng.int(0, 2), "side": rng.pick(&["left", "right"]),
        });
    }
    let kind = if rng.chance(0.8) { "bfbs" } else { "erbs" };
    let at: Vec<String> = (0..3)
        .map(|_| {
            let k = rng.int(0, n);
            match rng.int(0, 3) {
                0 => k.to_string(),
                1 if k < n => near(k, tiny_exponent(rng), true),
                2 if k > 0 => near(k, tiny_exponent(rng), false),
                _ => format!("{}/{}", rng.int(0, 3 * n), 3),
            }
        })
        .collect();
    let params = if kind == "bfbs" {
        json!({"i": rng.int(1, 3)})
    } else {
        json!({})
    };
    json!({
        "knots": knots, "kind": kind, "params": params, "at": at,
        "derivatives": rng.int(0, 3), "side": rng.pick(&["left", "right"]),
    })
}

/// Waypoints: random, nearly collinear (a point 1e-40 off the line), or with a straight
/// stretch.
fn waypoints(rng: &mut Rng, count: i64, allow_collinear: bool) -> Vec<Value> {
    let mut w: Vec<Value> = Vec::new();
    for i in 0..count {
        let x = 100 * i + rng.int(-20, 20);
        let y = match rng.int(0, 3) {
            0 if allow_collinear => json!(0),
            1 => json!(near(
                rng.int(-1, 1) * 50,
                tiny_exponent(rng),
                rng.chance(0.5)
            )),
            _ => json!(rng.int(-80, 80)),
        };
        w.push(json!([x, y]));
    }
    w
}

fn gen_gerbs_path(rng: &mut Rng) -> Value {
    let w = loop {
        let count = rng.int(3, 4);
        let w = waypoints(rng, count, false);
        if noncollinear(&w) {
            break w;
        }
    };
    json!({"waypoints": w, "radius": rng.int(10, 60), "theta_o": "pi/8", "kind": "bfbs", "samples": 5})
}

/// Whether every interior triple turns (the exact wedge is not 0).
fn noncollinear(w: &[Value]) -> bool {
    let p = |v: &Value| -> [BigRational; 2] {
        let c = |x: &Value| match x {
            Value::String(s) => parse_rational(s).unwrap(),
            other => parse_rational(&other.to_string()).unwrap(),
        };
        [c(&v[0]), c(&v[1])]
    };
    (1..w.len() - 1).all(|i| {
        let (a, b, c) = (p(&w[i - 1]), p(&w[i]), p(&w[i + 1]));
        let wedge = (b[0].clone() - &a[0]) * (c[1].clone() - &b[1])
            - (b[1].clone() - &a[1]) * (c[0].clone() - &b[0]);
        !wedge.is_zero()
    })
}

fn gen_dubins(rng: &mut Rng) -> Value {
    let count = rng.int(2, 4);
    let radius = rng.int(5, 60);
    if rng.chance(0.5) {
        // Given headings: 0 (straight legs along x), multiples of π/4, or rationals.
        let w = waypoints(rng, count, true);
        let headings: Vec<Value> = (0..count)
            .map(|_| match rng.int(0, 2) {
                0 => json!(0),
                1 => json!(*rng.pick(&["pi/4", "-pi/2", "pi", "3*pi/4"])),
                _ => json!(rng.number()),
            })
            .collect();
        json!({"waypoints": w, "headings": headings, "radius": radius, "samples": 5})
    } else {
        let w = loop {
            let w = waypoints(rng, count.max(3), false);
            if noncollinear(&w) {
                break w;
            }
        };
        json!({"waypoints": w, "radius": radius, "samples": 5})
    }
}

/// What one comparison found.
#[derive(Default)]
struct Counts {
    inputs: usize,
    comparisons: usize,
    wrong_digits: Vec<String>,
    misses: Vec<String>,
    refusals: usize,
    internal: usize,
    /// Ball runs, and how many of them were refused (either exit status).
    ball_runs: usize,
    ball_refusals: usize,
    no_reference: usize,
    /// f64 runs, their refusals, and answers with no correct digit in the norm.
    f64_runs: usize,
    f64_refusals: usize,
    f64_without_digit: Vec<String>,
    /// The first refusals, for the report.
    refusal_messages: Vec<String>,
    /// Every internal error (exit 3), which valid input must never cause.
    internal_messages: Vec<String>,
}

/// The half unit of the last digit of a printed decimal ("1.25e-3" → 5e-6), exactly, or
/// `None` for "0" (a zero printed without digits).
fn half_unit(text: &str) -> Option<BigRational> {
    let t = text.trim_start_matches('-');
    if t == "0" {
        return None;
    }
    let (mantissa, exponent) = match t.split_once(['e', 'E']) {
        Some((m, e)) => (m, e.parse::<i32>().ok()?),
        None => (t, 0),
    };
    let fraction = mantissa.split_once('.').map_or(0, |(_, f)| f.len() as i32);
    let power = exponent - fraction;
    let ten = BigRational::from_integer(10.into());
    let unit = if power >= 0 {
        num_traits::pow(ten, power as usize)
    } else {
        BigRational::from_integer(1.into()) / num_traits::pow(ten, (-power) as usize)
    };
    Some(unit / BigRational::from_integer(2.into()))
}

/// A reference number: its exact value and its own uncertainty (0 when exact).
struct Reference {
    value: BigRational,
    uncertainty: BigRational,
}

fn reference_number(v: &Value, exact: bool) -> Option<Reference> {
    let text = v.as_str()?;
    let value = exact_number(text)?;
    let uncertainty = if exact {
        BigRational::zero()
    } else {
        half_unit(text).unwrap_or_else(BigRational::zero)
    };
    Some(Reference { value, uncertainty })
}

/// Keys whose values legitimately differ between number types.
/// Keys whose values legitimately differ between number types: names, diagnostics of an
/// iteration at its own precision (a residual at the precision floor), a ball's own width.
const SKIP: [&str; 10] = [
    "digits",
    "scalar",
    "certified_digits",
    "f64",
    "f64_note",
    "note",
    "iterations",
    "descent_converged",
    "projected_gradient_norm",
    "max_error_relative_width",
];

/// An exact number: a decimal, or a fraction of integers of any length (the rational runs
/// print fractions longer than an input may be).
fn exact_number(text: &str) -> Option<BigRational> {
    match text.split_once('/') {
        Some((n, d)) => {
            let n: num_bigint::BigInt = n.trim().parse().ok()?;
            let d: num_bigint::BigInt = d.trim().parse().ok()?;
            (!d.is_zero()).then(|| BigRational::new(n, d))
        }
        None => parse_rational(text).ok(),
    }
}

struct Context<'a> {
    case: &'a str,
    exact_reference: bool,
}

/// Compare a tested output with the reference, recording every number checked.
fn compare(tested: &Value, reference: &Value, path: &str, cx: &Context, counts: &mut Counts) {
    match (tested, reference) {
        // A ball: it must contain the reference as printed.
        (Value::Object(t), _)
            if t.contains_key("value") && t.contains_key("radius") && t.len() == 2 =>
        {
            let Some(rf) = reference_number(reference, cx.exact_reference) else {
                counts.wrong_digits.push(format!(
                    "{}: {path}: ball {tested} against non-number {reference}",
                    cx.case
                ));
                return;
            };
            let value =
                parse_rational(t["value"].as_str().unwrap_or("x")).expect("ball value parses");
            let radius =
                parse_rational(t["radius"].as_str().unwrap_or("x")).expect("ball radius parses");
            counts.comparisons += 1;
            if (value.clone() - &rf.value).abs() > radius + &rf.uncertainty {
                counts.misses.push(format!(
                    "{}: {path}: ball {} ± {} does not contain the reference {}",
                    cx.case, t["value"], t["radius"], reference
                ));
            }
        }
        (Value::Object(t), Value::Object(r)) => {
            for (k, v) in t {
                if SKIP.contains(&k.as_str()) {
                    continue;
                }
                match r.get(k) {
                    Some(rv) => compare(v, rv, &format!("{path}.{k}"), cx, counts),
                    None => counts
                        .wrong_digits
                        .push(format!("{}: {path}.{k} missing in the reference", cx.case)),
                }
            }
        }
        (Value::Array(t), Value::Array(r)) => {
            if t.len() != r.len() {
                counts.wrong_digits.push(format!(
                    "{}: {path}: {} items against {}",
                    cx.case,
                    t.len(),
                    r.len()
                ));
                return;
            }
            for (i, (a, b)) in t.iter().zip(r).enumerate() {
                compare(a, b, &format!("{path}[{i}]"), cx, counts);
            }
        }
        (Value::String(s), _) if parse_rational(s).is_ok() => {
            let Some(rf) = reference_number(reference, cx.exact_reference) else {
                counts.wrong_digits.push(format!(
                    "{}: {path}: {s} against non-number {reference}",
                    cx.case
                ));
                return;
            };
            counts.comparisons += 1;
            let printed = parse_rational(s).unwrap();
            let error = (printed - &rf.value).abs();
            let allowed = match half_unit(s) {
                Some(h) => h + &rf.uncertainty,
                // A bare "0" claims an exact zero: only the reference's own uncertainty.
                None => rf.uncertainty.clone(),
            };
            if error > allowed {
                counts.wrong_digits.push(format!(
                    "{}: {path}: printed {s}, reference {reference} (error {:.3e}, allowed {:.3e})",
                    cx.case,
                    ratio_f64(&error),
                    ratio_f64(&allowed)
                ));
            }
        }
        // A convergence ratio or order is null where an error's enclosure reaches 0 (not
        // proven nonzero at this precision): unknown, not wrong.
        (Value::Null, Value::String(_)) if path.ends_with(".ratio") || path.ends_with(".order") => {
        }
        (a, b) => {
            if a != b {
                counts
                    .wrong_digits
                    .push(format!("{}: {path}: {a} against {b}", cx.case));
            }
        }
    }
}

fn ratio_f64(q: &BigRational) -> f64 {
    num_traits::ToPrimitive::to_f64(q).unwrap_or(f64::NAN)
}

fn run(algorithm: Algorithm, scalar: &str, input: &str) -> Result<Value, Failure> {
    let kind: ScalarKind = scalar.parse().expect("scalar");
    run_text(algorithm, Some(kind), input)
        .map(|s| serde_json::from_str(&s).expect("one JSON object"))
}

fn seed() -> u64 {
    match std::env::var("SOUNDNESS_SEED") {
        Ok(s) if s == "random" => {
            let t = std::time::SystemTime::now()
                .duration_since(std::time::UNIX_EPOCH)
                .map_or(1, |d| d.as_nanos() as u64);
            eprintln!("SOUNDNESS_SEED={t}");
            t
        }
        Ok(s) => s.parse().expect("SOUNDNESS_SEED is a number or 'random'"),
        Err(_) => 0x5EED_2026,
    }
}

/// The precision of the reference run of an algorithm without an exact one: its digits are
/// proven, so it only has to carry more of them than the run it checks.
fn reference_bits(bits: u32) -> u32 {
    (bits + 64).max(128)
}

/// The precisions tested: `SOUNDNESS_BITS` (a comma-separated list), by default 16, 64, 128.
fn bits_list() -> Vec<u32> {
    std::env::var("SOUNDNESS_BITS")
        .ok()
        .map(|s| {
            s.split(',')
                .map(|b| b.trim().parse().expect("SOUNDNESS_BITS lists bit counts"))
                .collect()
        })
        .unwrap_or_else(|| vec![16, 64, 128])
}

fn env_number(name: &str, default: f64) -> f64 {
    std::env::var(name)
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(default)
}

/// Every number of a tested output paired with the reference's (for the normwise check of
/// f64 results): (tested, reference) as exact rationals.
fn pairs(tested: &Value, reference: &Value, out: &mut Vec<(BigRational, BigRational)>) {
    match (tested, reference) {
        (Value::Object(t), Value::Object(r)) => {
            for (k, v) in t {
                if SKIP.contains(&k.as_str()) {
                    continue;
                }
                if let Some(rv) = r.get(k) {
                    pairs(v, rv, out);
                }
            }
        }
        (Value::Array(t), Value::Array(r)) if t.len() == r.len() => {
            for (a, b) in t.iter().zip(r) {
                pairs(a, b, out);
            }
        }
        (Value::String(a), Value::String(b)) => {
            if let (Some(x), Some(y)) = (exact_number(a), exact_number(b)) {
                out.push((x, y));
            }
        }
        _ => {}
    }
}

/// Whether an f64 output has at least one correct digit in the norm: max |x − r| < ½ max |r|
/// over all its numbers (every method refuses an answer without one, on its own
/// conditioning estimate or at the output).
fn f64_has_a_digit(tested: &Value, reference: &Value) -> bool {
    let mut p = Vec::new();
    pairs(tested, reference, &mut p);
    let error = p
        .iter()
        .map(|(x, r)| (x.clone() - r).abs())
        .max()
        .unwrap_or_else(BigRational::zero);
    let size = p
        .iter()
        .map(|(_, r)| r.abs())
        .max()
        .unwrap_or_else(BigRational::zero);
    error * BigRational::from_integer(2.into()) < size || size.is_zero()
}

/// Run one subject's cases and return its counts.
fn check_subject(subject: &Subject) -> Counts {
    let mut cases = env_number("SOUNDNESS_CASES", 12.0) as usize;
    if subject.algorithm == Algorithm::GerbsPath {
        // Every run proves the path length by Taylor models (about a second a case).
        cases = cases.div_ceil(3);
    }
    let seconds = env_number("SOUNDNESS_SECONDS", 600.0);
    let mut rng = Rng(seed()
        ^ (subject.name.len() as u64 * 0x1000_0001)
        ^ subject.name.bytes().map(u64::from).sum::<u64>());
    let mut counts = Counts::default();
    let start = Instant::now();
    for case in 0..cases {
        if start.elapsed().as_secs_f64() > seconds {
            break;
        }
        let input = (subject.generate)(&mut rng).to_string();
        counts.inputs += 1;
        let all_bits = bits_list();
        for &bits in &all_bits {
            let (reference, exact) = if subject.rational_reference {
                (run(subject.algorithm, "rational", &input), true)
            } else {
                (
                    run(
                        subject.algorithm,
                        &format!("mpfr:{}", reference_bits(bits)),
                        &input,
                    ),
                    false,
                )
            };
            let reference = match reference {
                Ok(r) => r,
                Err(e) => {
                    counts.no_reference += 1;
                    if counts.no_reference <= 2 {
                        counts.refusal_messages.push(format!(
                            "reference for {bits} bits, {input}: {}",
                            e.message()
                        ));
                    }
                    continue;
                }
            };
            if bits == all_bits[0] {
                match run(subject.algorithm, "f64", &input) {
                    Ok(out) => {
                        counts.f64_runs += 1;
                        if !f64_has_a_digit(&out, &reference) {
                            counts
                                .f64_without_digit
                                .push(format!("{} case {case} f64 {input}", subject.name));
                        }
                    }
                    Err(e) => {
                        counts.f64_refusals += 1;
                        if matches!(e, Failure::Internal(_)) {
                            counts.internal_messages.push(format!(
                                "{} case {case} f64 {input}: {}",
                                subject.name,
                                e.message()
                            ));
                        }
                    }
                }
            }
            let mut scalars = Vec::new();
            if subject.mpfr {
                scalars.push(format!("mpfr:{bits}"));
            }
            if subject.ball {
                scalars.push(format!("ball:{bits}"));
            }
            for scalar in scalars {
                let is_ball = scalar.starts_with("ball");
                counts.ball_runs += usize::from(is_ball);
                match run(subject.algorithm, &scalar, &input) {
                    Ok(out) => {
                        let label = format!("{} case {case} {scalar} {input}", subject.name);
                        let context = Context {
                            case: &label,
                            exact_reference: exact,
                        };
                        compare(&out, &reference, "", &context, &mut counts);
                    }
                    Err(e) => {
                        counts.ball_refusals += usize::from(is_ball);
                        if matches!(e, Failure::Internal(_)) {
                            counts.internal += 1;
                            counts.internal_messages.push(format!(
                                "{} case {case} {scalar} {input}: {}",
                                subject.name,
                                e.message()
                            ));
                        } else {
                            counts.refusals += 1;
                        }
                        if counts.refusal_messages.len() < 3 {
                            counts
                                .refusal_messages
                                .push(format!("{scalar} {input}: {}", e.message()));
                        }
                    }
                }
            }
        }
    }
    println!(
        "soundness {}: {} inputs, {} comparisons, {} wrong digits, {} misses, {} refusals (exit 2), {} internal (exit 3), {} without reference; ball refused {} of {}; {:.1} s",
        subject.name,
        counts.inputs,
        counts.comparisons,
        counts.wrong_digits.len(),
        counts.misses.len(),
        counts.refusals,
        counts.internal,
        counts.no_reference,
        counts.ball_refusals,
        counts.ball_runs,
        start.elapsed().as_secs_f64()
    );
    println!(
        "  f64: {} answers, {} refused, {} without a correct digit",
        counts.f64_runs,
        counts.f64_refusals,
        counts.f64_without_digit.len()
    );
    for m in counts.f64_without_digit.iter().take(3) {
        println!("  f64 without a digit: {m}");
    }
    for m in &counts.refusal_messages {
        println!("  refused: {m}");
    }
    counts
}

fn assert_sound(name: &str) {
    let subject = subjects()
        .into_iter()
        .find(|s| s.name == name)
        .expect("known subject");
    let counts = check_subject(&subject);
    let problems: Vec<&String> = counts
        .wrong_digits
        .iter()
        .chain(&counts.misses)
        .chain(&counts.f64_without_digit)
        .chain(&counts.internal_messages)
        .take(10)
        .collect();
    assert!(
        problems.is_empty(),
        "{name}: {} wrong digits, {} misses, {} f64 answers without a correct digit, {} internal errors (exit 3), e.g.\n{}",
        counts.wrong_digits.len(),
        counts.misses.len(),
        counts.f64_without_digit.len(),
        counts.internal_messages.len(),
        problems
            .iter()
            .map(|s| s.as_str())
            .collect::<Vec<_>>()
            .join("\n")
    );
    assert!(counts.comparisons > 0, "{name}: nothing was compared");
}

macro_rules! soundness_tests {
    ($($test:ident => $name:literal),* $(,)?) => {
        $(
            #[test]
            fn $test() {
                assert_sound($name);
            }
        )*
    };
}

soundness_tests! {
    hermite => "hermite",
    hermite_condition => "hermite-condition",
    spline_fit => "spline-fit",
    bang_bang => "bang-bang",
    marin_1d => "marin-1d",
    marin => "marin",
    natural_spline => "natural-spline",
    ph_hermite => "ph-hermite",
    phodcos => "phodcos",
    convergence => "convergence",
    gerbs_basis => "gerbs-basis",
    gerbs_path => "gerbs-path",
    dubins => "dubins",
}

/// 10^-40 above (`+`) or below (`-`) the integer `x`, as an exact fraction.
fn off(x: i64, sign: char) -> String {
    near(x, 40, sign == '+')
}

/// The discrete decisions `docs/design.md` lists ("Decisions on the exact input"), each with
/// inputs within 1e-40 of its boundary on both sides: every number type must take the exact
/// input's branch (the reference: the rational run or a proven run at more bits), and answer.
fn decision_cases() -> Vec<(Algorithm, &'static str, bool, Value)> {
    use Algorithm::*;
    let mut cases = Vec::new();
    for sign in ['+', '-'] {
        // The knot interval and side of a GERBS basis point (derivatives jump at a knot).
        for side in ["left", "right"] {
            cases.push((
                GerbsBasis,
                "knot side",
                false,
                json!({"knots": [0, 0, 1, 2, 3, 3], "kind": "bfbs", "params": {"i": 1},
                       "at": [off(1, sign)], "derivatives": 3, "side": side}),
            ));
        }
        // The turn direction at a nearly collinear waypoint (Algorithm 1's s_i).
        cases.push((
            GerbsPath,
            "turn sign",
            false,
            json!({"waypoints": [[0, 0], [100, off(0, sign)], [200, 0]], "radius": 10,
                   "theta_o": "pi/8", "kind": "bfbs", "samples": 3}),
        ));
        // A Dubins leg along the chord or 1e-40 off it: the word and its zero-length arcs.
        cases.push((
            Dubins,
            "Dubins word",
            false,
            json!({"waypoints": [[0, 0], [100, off(0, sign)], [200, "1/2"]], "radius": 10,
                   "headings": [0, 0, 0], "samples": 3}),
        ));
        cases.push((
            Dubins,
            "Dubins word (Algorithm 1 headings)",
            false,
            json!({"waypoints": [[0, 0], [100, off(0, sign)], [200, "1/2"]], "radius": 10, "samples": 3}),
        ));
        // The case of Marin's 1-D parametrization (a step of 1e-40 sets a direction).
        cases.push((
            Marin1d,
            "Marin case",
            false,
            json!({"z": ["0", "1", off(1, sign), "3"]}),
        ));
        // The support and rank of an interpolating spline fit (Schoenberg–Whitney), and the
        // piece of the cardinal B-spline at a time next to an integer knot.
        cases.push((
            SplineFit,
            "spline-fit support and knot",
            true,
            json!({"degree": 2, "controls": 4, "times": [off(1, sign), off(3, sign), "5"],
                   "values": [1, -2, "1/3"], "weights": null}),
        ));
        // The piece of a natural spline at a knot (and the distance to it, exactly).
        cases.push((
            NaturalSpline,
            "natural-spline piece",
            true,
            json!({"t": [0, 1, 3], "z": [1, -1, 2], "at": [off(1, sign), "1/2"]}),
        ));
    }
    // An interval of width 1e-40 (rounded, it would be empty).
    cases.push((
        Hermite,
        "interval width",
        true,
        json!({"start": [1, 2, 3], "end": [0, 1, 5], "interval": ["1", off(1, '+')]}),
    ));
    cases.push((
        HermiteCondition,
        "interval width",
        false,
        json!({"derivatives": 5, "interval": ["1", off(1, '+')], "matrix": "transform"}),
    ));
    cases
}

#[test]
fn decisions_follow_the_exact_input_on_both_sides_of_every_boundary() {
    let mut problems = Vec::new();
    let mut checked = 0;
    for (algorithm, what, rational, input) in decision_cases() {
        let input = input.to_string();
        for bits in [64u32, 128] {
            let (reference, exact) = if rational {
                (run(algorithm, "rational", &input), true)
            } else {
                (
                    run(algorithm, &format!("mpfr:{}", reference_bits(bits)), &input),
                    false,
                )
            };
            let reference = reference
                .unwrap_or_else(|e| panic!("{what}: reference refused {input}: {}", e.message()));
            for scalar in [format!("mpfr:{bits}"), format!("ball:{bits}")] {
                let label = format!("{what} {scalar} {input}");
                match run(algorithm, &scalar, &input) {
                    Ok(out) => {
                        let mut counts = Counts::default();
                        let cx = Context {
                            case: &label,
                            exact_reference: exact,
                        };
                        compare(&out, &reference, "", &cx, &mut counts);
                        checked += counts.comparisons;
                        problems.extend(counts.wrong_digits);
                        problems.extend(counts.misses);
                    }
                    Err(e) => problems.push(format!("{label}: refused: {}", e.message())),
                }
            }
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
    assert!(checked > 100, "only {checked} numbers checked");
}

#[test]
fn the_comparison_catches_a_wrong_digit_and_a_missing_ball() {
    // The test must be able to fail: a digit off by one unit and a ball that excludes the
    // reference are both reported.
    let mut counts = Counts::default();
    let cx = Context {
        case: "synthetic",
        exact_reference: true,
    };
    compare(
        &json!(["0.8666666666666666666"]),
        &json!(["13/15"]),
        "",
        &cx,
        &mut counts,
    );
    compare(
        &json!({"value": "0.866666666666666667", "radius": "1.4e-19"}),
        &json!("13/15"),
        "",
        &cx,
        &mut counts,
    );
    compare(
        &json!(["0.8666666666666666667"]),
        &json!(["13/15"]),
        "",
        &cx,
        &mut counts,
    );
    compare(
        &json!({"value": "0.866666666666666667", "radius": "4.6e-19"}),
        &json!("13/15"),
        "",
        &cx,
        &mut counts,
    );
    assert!(f64_has_a_digit(
        &json!(["0.8", "3"]),
        &json!(["13/15", "3"])
    ));
    assert!(!f64_has_a_digit(
        &json!(["-1e13", "3"]),
        &json!(["13/15", "3"])
    ));
    assert_eq!(counts.wrong_digits.len(), 1, "{:?}", counts.wrong_digits);
    assert_eq!(counts.misses.len(), 1, "{:?}", counts.misses);
    assert_eq!(counts.comparisons, 4);
}
