//! The command line: `verify`, `list` and `run <algorithm>` (README, "Command line"; `docs/commands.md`).
//!
//! No mathematics lives here: arguments and JSON are read, an algorithm of the library is
//! called, and JSON or a summary is printed. Every user error becomes one line on stderr and
//! exit status 2, with nothing on stdout; an internal failure of a method (non-convergence)
//! exits 3; `verify` exits 1 when a claim failed. Every `run` checks its work budget
//! ([`budget`]) before computing.

pub mod budget;
mod dispatch;
mod input;
mod json;
mod output;
mod report_convergence;
mod run_bspline;
mod run_gerbs;
mod run_hermite;
mod run_param;
mod run_ph;

use crate::papers::{self, Paper, Verdict};
use crate::report;
use crate::scalar::ScalarKind;
use clap::{Parser, Subcommand, ValueEnum};
use input::RunError;
use output::{render_plain, Out};
use serde_json::Value;
use std::io::Read;
use std::path::PathBuf;

/// Verify the claims of five papers on curves and trajectories, in exact rationals, MPFR and f64.
#[derive(Parser, Debug)]
#[command(name = "trajverify", version, about, long_about = None)]
pub struct Cli {
    /// The subcommand.
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands of `trajverify`.
#[derive(Subcommand, Debug)]
pub enum Command {
    /// Check every claim; write claims.json, a Markdown report per paper and SVG figures.
    Verify {
        /// Only these papers (id such as 000_d51e5cedfa8471cf, or short name such as hermite).
        #[arg(long = "paper", value_name = "ID")]
        papers: Vec<String>,
        /// Where to write the ledger, reports and figures [default: reports, for all papers;
        /// required with --paper, so that one paper's ledger never replaces the whole one].
        #[arg(long, value_name = "DIR")]
        out: Option<PathBuf>,
    },
    /// Write a report (Markdown, SVG, JSON) of a method applied to your own input.
    Report {
        /// Which report.
        #[command(subcommand)]
        kind: ReportKind,
    },
    /// List the claim ids with their locations in the papers (runs nothing).
    List {
        /// Only these papers.
        #[arg(long = "paper", value_name = "ID")]
        papers: Vec<String>,
    },
    /// Run one algorithm on a JSON object (from --input or stdin); print a JSON object.
    #[command(after_long_help = RUN_HELP)]
    Run {
        /// The algorithm to run.
        algorithm: Algorithm,
        /// Number type: f64, rational (exact), mpfr:BITS (ball arithmetic at BITS bits, each
        /// number printed with the digits its enclosure proves; an ERBS gerbs-path prints
        /// digits that agree between BITS and 2·BITS bits, labelled "not proven"),
        /// or ball:BITS (proven enclosures: each number as the digits every point of its ball
        /// rounds to, and the radius). Default: f64 for hermite, spline-fit, natural-spline,
        /// ph-hermite, phodcos, gerbs-basis, gerbs-path and dubins; mpfr:256 for convergence,
        /// hermite-condition, bang-bang, marin-1d and marin; bspline-basis and bspline-gram
        /// are always exact.
        #[arg(long, value_name = "SCALAR", value_parser = parse_scalar)]
        scalar: Option<ScalarKind>,
        /// Read the input from this file instead of stdin.
        #[arg(long, value_name = "FILE")]
        input: Option<PathBuf>,
    },
}

const RUN_HELP: &str = r#"Algorithms and their input:
  hermite            {"start": [x0, x0', ..., x0^(m)], "end": [x1, ..., x1^(m)], "interval": [t0, t1]}
                     each value a number or a point [x, y, ...]; output {"degree", "control_points"}
  hermite-condition  {"derivatives": m, "interval": [t0, t1], "matrix": "transform" | "binomial"}
                     output {"condition_number", "f64"} (f64: also "correct_digits")
  bspline-basis      {"degree": k} -> {"pieces": [[c0, ..., ck] x (k+1)]}, piece j on [j, j+1] in s = t - j, exact
  bspline-gram       {"degree": k} (k >= 1) -> {"entries": [g0, ..., gk]}, exact
  spline-fit         {"degree": k, "controls": M, "times": [...], "values": [...], "weights": null | [...]}
                     -> {"tau": [tau_1, ..., tau_M]}; values numbers or points; null weights = interpolation
  bang-bang          {"xi": "2/3"} -> {"switching_times", "amplitude", "exact"}
  marin-1d           {"z": [z0, ..., zN]} -> {"t": [...], "case": "I" | "II" | "III"}
  marin              {"points": [[...], ...], "weights": [a1, ...] (optional), "objective": "exact" | "approx"}
                     -> {"t": [...], "G", "G_chord", "iterations"}
  natural-spline     {"t": [...], "z": [...] or [[...], ...], "at": [...]} -> {"values", "first", "second"}
  ph-hermite         {"p_b": [x,y,z], "p_e", "v_b", "v_e", "a_b", "a_e", "j_b", "j_e", "s_b", "s_e",
                      "free": {"theta0", "tau1", "tau2", "tau3", "theta4", "tau5", "tau6", "tau7", "theta8"} (optional)}
                     derivatives in xi on [0, 1]; -> {"preimage": [[u,v,p,q] x 9], "control_points": [[x,y,z] x 18], "arc_length"}
  phodcos            {"curve": "[1.5*sin(7.2*t), cos(9*t), exp(cos(1.8*t))]", "interval": [a, b],
                      "segments": N | "tolerance": eps, "max_segments": M (optional, default 4096)}
                     -> {"segments", "max_error", "sampled_error", "preimages": [[[u,v,p,q] x 9] x N]}
                     (mpfr and ball: max_error proven by branch and bound, no sampled_error)
  convergence        {"curve", "interval", "levels": [0, ..., 13], "free": {...} (optional)}
                     -> {"rows": [{"segments", "error", "ratio", "order"}]} (default scalar mpfr:256);
                     levels increase; order = log2(ratio)/(level gap); errors proven by branch and bound
  gerbs-basis        {"knots": [t1, ..., t(n+2)], "kind": "bfbs" | "erbs", "params": {...} (optional),
                      "at": [...], "derivatives": d (optional, default 0), "side": "right" | "left" (optional)}
                     -> {"values": [[[B, B', ..., B^(d)] x n] x points]} for B_2 ... B_(n+1); null where a
                     derivative does not exist (erbs with 2*sigma < d, at an interval's centre); erbs
                     values are accurate relative to 1, so a tiny value near a knot has fewer digits
                     params bfbs: {"i": 2 | [i_2, ..., i_(n+1)]}; erbs: {"alpha", "beta", "gamma",
                     "lambda", "sigma"} (each a number or one per knot interval; default 1, 3, 1, 1/2, 1),
                     "centre": "cited" | "printed" (Eq. 4's centre term; default cited)
  gerbs-path         {"waypoints": [[x, y], ...], "radius": R, "theta_o": "pi/8", "kind": "bfbs" | "erbs",
                      "params": {...} (optional; per-interval arrays have one value per leg),
                      "samples": n (optional, default 101), "line_length": l (optional, default 2*R*theta_o),
                      "arcs": "turn" | "printed" (optional; Eqs. 21-22 as printed run left turns backwards)}
                     -> {"t", "points", "curvature", "length", "at_waypoints": [{"t", "point", "tangent",
                         "curvature"}], "turns"}; erbs in mpfr takes seconds to a minute (the length)
  dubins             {"waypoints": [[x, y], ...], "headings": [...] (optional, default from Algorithm 1),
                      "radius": R, "samples": n per leg (optional, default 33)}
                     -> {"headings", "legs": [{"from", "to", "word", "lengths", "length", "samples": [[x, y, heading]]}], "length"}
  curves: numbers, t, pi, + - * / ^, sin cos tan exp ln sqrt atan, parentheses
  angles (theta_o, headings, ERBS parameters) may also be constant expressions such as "pi/8"
Numbers may be JSON numbers or strings ("3/5", "0.6", "1e-3"); both are read exactly.
Every input is answered within 30 s on two cores and 2 GiB, or refused at once: each run
estimates its work from its sizes and the number type (see docs/limits.md).
Exit status: 0 success, 2 bad input (one line naming the field, nothing on stdout),
3 internal failure of a method on accepted input; `verify` exits 1 when a claim failed."#;

/// The reports `report` writes.
#[derive(Subcommand, Debug)]
pub enum ReportKind {
    /// Table 1 for your curve: the PHODCOS conversion (or piecewise Hermite–Bernstein) error
    /// against 2ⁿ segments, proven by branch and bound (with the sampled maximum and f64
    /// beside it), observed and fitted orders against the expected one, where f64 stops
    /// improving. A curve that is not finite or whose tangent vanishes on the interval is
    /// refused, naming t.
    Convergence {
        /// The curve, "[x(t), y(t), z(t)]" (numbers, t, pi, + - * / ^, sin cos tan exp ln sqrt atan).
        #[arg(
            long,
            value_name = "EXPRESSION",
            required_unless_present = "data",
            conflicts_with = "data"
        )]
        curve: Option<String>,
        /// Or a CSV file of samples t, x, y, z fitted by a C⁴ quintic spline: periodic (paper 001,
        /// Sec. 6A) when the last row repeats the first point, clamped otherwise (then the
        /// interval must lie within the first and last times).
        #[arg(long, value_name = "CSV")]
        data: Option<PathBuf>,
        /// The parameter interval a b: numbers ("0.5", "1/3") or constants ("4*pi"), kept exact
        /// (rounded per precision, enclosed in balls for the proof).
        #[arg(long, num_args = 2, required = true, value_names = ["A", "B"], allow_hyphen_values = true)]
        interval: Vec<String>,
        /// The approximation: "phodcos" (C⁴ PH curves, paper 001; expected order 6) or
        /// "hermite:M" (piecewise Hermite–Bernstein with M = 0…8 derivatives at each joint,
        /// paper 000's map; degree 2M+1, classical order 2M+2).
        #[arg(long, value_name = "METHOD", default_value = "phodcos")]
        method: String,
        /// Levels n (2ⁿ segments): "a-b" or "n1,n2,…", within 0…14.
        #[arg(long, default_value = "0-8")]
        levels: String,
        /// ball:BITS (proven errors, with the sampled maximum at BITS and 2·BITS as a
        /// cross-check) or mpfr:BITS (sampled maxima only: not certified, no proven order).
        #[arg(long, value_name = "SCALAR", value_parser = parse_scalar, default_value = "ball:128")]
        scalar: ScalarKind,
        /// The directory to write convergence.md, convergence.svg and convergence.json into.
        #[arg(long, value_name = "DIR")]
        out: PathBuf,
    },
}

/// The algorithms `run` knows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Algorithm {
    /// Two-point Hermite data → Bernstein control points (paper 000, Eqs. 11–18).
    Hermite,
    /// Condition number κ₂ of the Hermite transform (paper 000, Eq. 10, Fig. 5).
    HermiteCondition,
    /// Pieces of the cardinal B-spline B_k, exact (paper 002, Algorithm 1).
    BsplineBasis,
    /// Gram entries ĝ_0…ĝ_k of the k-th derivatives, exact (paper 002, Sec. 5).
    BsplineGram,
    /// Optimal interpolating or smoothing B-spline control points (paper 002, Eqs. 14–15).
    SplineFit,
    /// Minimum-L∞ bang-bang control through x(2) = ξ (paper 002, Sec. 4).
    BangBang,
    /// Exact minimizing parametrization of scalar data (paper 004, Sec. 2).
    #[value(name = "marin-1d")]
    Marin1d,
    /// Minimizing parametrization of K-dimensional points (paper 004, Eq. 30).
    Marin,
    /// Natural cubic spline values and derivatives (paper 004).
    NaturalSpline,
    /// C⁴ Hermite data → degree-17 PH curve, preimage and control points (paper 001, Alg. 1).
    PhHermite,
    /// A parametric curve converted to a piecewise PH curve (paper 001, Alg. 2).
    Phodcos,
    /// Conversion error on 2ⁿ segments, ratios and orders (paper 001, Table 1).
    Convergence,
    /// BFBS or ERBS basis functions and derivatives on a knot vector (paper 003, Eqs. 3–9).
    GerbsBasis,
    /// A curvature-continuous GERBS path through waypoints (paper 003, Algorithms 1–2).
    GerbsPath,
    /// Shortest Dubins paths between consecutive waypoint poses (paper 003, Fig. 7).
    Dubins,
}

fn parse_scalar(s: &str) -> Result<ScalarKind, String> {
    s.parse()
}

/// What `run` prints, before it is turned into JSON text.
pub struct Rendered {
    body: Body,
    /// Fields appended to the output object after rendering (e.g. exact values).
    extra: Vec<(String, Value)>,
}

/// The rendered output: a JSON value, or plain output already written as JSON text.
enum Body {
    Value(Value),
    /// The text of [`render_plain`] and its top-level keys ([`output::write_plain`]).
    Text(String, Vec<String>),
}

impl Rendered {
    /// An output in one number type, printed as it is.
    pub fn plain<T: crate::scalar::Field>(out: Out<T>) -> Self {
        let mut text = String::with_capacity(out.text_size_hint());
        let body = match output::write_plain(&out, &mut text) {
            Some(keys) => Body::Text(text, keys),
            None => Body::Value(render_plain(&out)),
        };
        Rendered {
            body,
            extra: Vec::new(),
        }
    }
    /// Output already rendered as JSON (strings carry their certified digits).
    pub fn json(value: Value) -> Self {
        Rendered {
            body: Body::Value(value),
            extra: Vec::new(),
        }
    }
    /// The same output with one more field at the end.
    pub fn with_extra(mut self, key: &str, value: Value) -> Self {
        self.extra.push((key.to_string(), value));
        self
    }
    /// The final JSON text, without its newline (extra fields appended, and refused if any
    /// number is not finite).
    fn into_text(self) -> Result<String, RunError> {
        let internal = |e: serde_json::Error| RunError::internal(e);
        let value_route = |value: Value, extra| {
            serde_json::to_string(&Self::finish(value, extra)?).map_err(internal)
        };
        let (mut text, keys) = match self.body {
            Body::Value(value) => return value_route(value, self.extra),
            Body::Text(text, keys) => (text, keys),
        };
        // Plain text takes the extra fields as they are when they can only be appended: a
        // new key of an object, with nothing non-finite in them. Otherwise it goes the value
        // route (`finish`), which replaces a repeated key and names a non-finite field.
        let appendable = text.ends_with('}')
            && self.extra.iter().enumerate().all(|(i, (key, value))| {
                !keys.contains(key)
                    && !self.extra[..i].iter().any(|(k, _)| k == key)
                    && output::check_finite(value, key, "").is_ok()
            });
        if !appendable {
            return value_route(serde_json::from_str(&text).map_err(internal)?, self.extra);
        }
        text.pop();
        for (key, value) in &self.extra {
            let separator = if text.ends_with('{') { "" } else { "," };
            let key = serde_json::to_string(key).map_err(internal)?;
            let value = serde_json::to_string(value).map_err(internal)?;
            text.push_str(&format!("{separator}{key}:{value}"));
        }
        text.push('}');
        Ok(text)
    }
    /// The final JSON value: extra fields appended, refused if any number is not finite.
    fn finish(mut value: Value, extra: Vec<(String, Value)>) -> Result<Value, RunError> {
        if let Value::Object(map) = &mut value {
            map.extend(extra);
        }
        let scalar = value
            .get("scalar")
            .and_then(Value::as_str)
            .unwrap_or("the chosen number type")
            .to_string();
        output::check_finite(&value, "", &scalar)?;
        Ok(value)
    }
}

/// How a command ended, for the exit status.
#[derive(Debug)]
pub enum Failure {
    /// Bad input or usage: exit 2.
    Usage(String),
    /// A claim failed: exit 1.
    Run(String),
    /// A method did not do its job on accepted input (non-convergence, a broken internal
    /// check): exit 3.
    Internal(String),
}

impl Failure {
    /// The exit status: 1 for a failed claim, 2 for bad input, 3 for an internal failure.
    pub fn exit_code(&self) -> i32 {
        match self {
            Failure::Usage(_) => 2,
            Failure::Run(_) => 1,
            Failure::Internal(_) => 3,
        }
    }
    /// The one-line message.
    pub fn message(&self) -> &str {
        match self {
            Failure::Usage(m) | Failure::Run(m) | Failure::Internal(m) => m,
        }
    }
}

/// Run a parsed command line; the text to print on stdout on success.
pub fn execute(cli: Cli) -> Result<String, Failure> {
    match cli.command {
        Command::List { papers } => list(&select(&papers)?),
        Command::Verify { papers, out } => {
            let selected = select(&papers)?;
            let out = match (out, papers.is_empty()) {
                (Some(dir), _) => dir,
                (None, true) => PathBuf::from("reports"),
                (None, false) => {
                    return Err(Failure::Usage(
                        "option --paper: needs --out <dir>; writing some papers into reports/ would replace the ledger of all five (reports/claims.json)".into(),
                    ))
                }
            };
            verify(&selected, &out)
        }
        Command::Report {
            kind:
                ReportKind::Convergence {
                    curve,
                    data,
                    interval,
                    method,
                    levels,
                    scalar,
                    out,
                },
        } => {
            let source = match (curve, data) {
                (Some(text), _) => report_convergence::Source::Expression(text),
                (None, Some(path)) => report_convergence::Source::Data(path),
                (None, None) => {
                    return Err(Failure::Usage(
                        "option --curve: give --curve or --data".into(),
                    ))
                }
            };
            let request = report_convergence::Request {
                source,
                interval: (interval[0].clone(), interval[1].clone()),
                method,
                levels,
                scalar,
            };
            report_convergence::run(&request, &out)
        }
        Command::Run {
            algorithm,
            scalar,
            input,
        } => run(algorithm, scalar, input),
    }
}

fn select(names: &[String]) -> Result<Vec<Paper>, Failure> {
    let all = papers::all();
    if names.is_empty() {
        return Ok(all);
    }
    for name in names {
        if !all.iter().any(|p| p.id == name || p.short == name) {
            let known: Vec<String> = all
                .iter()
                .map(|p| format!("{} ({})", p.id, p.short))
                .collect();
            return Err(Failure::Usage(format!(
                "option --paper: unknown paper {name:?}; known: {}",
                known.join(", ")
            )));
        }
    }
    Ok(all
        .into_iter()
        .filter(|p| names.iter().any(|n| n == p.id || n == p.short))
        .collect())
}

fn list(papers: &[Paper]) -> Result<String, Failure> {
    let mut out = String::new();
    for paper in papers {
        out.push_str(&format!(
            "# {} ({}): {}\n",
            paper.id, paper.short, paper.title
        ));
        for spec in paper.specs {
            out.push_str(&format!("{}\t{}\n", spec.id, spec.location));
        }
    }
    Ok(out)
}

/// Make sure `dir` exists and takes a file, before anything is computed.
fn check_output_dir(dir: &std::path::Path) -> Result<(), Failure> {
    let unusable = |e: std::io::Error| {
        Failure::Usage(format!(
            "option --out: cannot write to {}: {e}",
            dir.display()
        ))
    };
    std::fs::create_dir_all(dir).map_err(unusable)?;
    let probe = dir.join(".trajverify-probe.tmp");
    std::fs::write(&probe, b"").map_err(unusable)?;
    std::fs::remove_file(&probe).map_err(unusable)
}

fn verify(papers: &[Paper], out_dir: &std::path::Path) -> Result<String, Failure> {
    check_output_dir(out_dir)?;
    let mut all_claims = Vec::new();
    let mut files = Vec::new();
    let mut summary = String::new();
    for paper in papers {
        let output = (paper.verify)();
        summary.push_str(&format!(
            "{} ({}): {} claims: {}\n",
            paper.id,
            paper.short,
            output.claims.len(),
            report::counts_text(&output.claims)
        ));
        for c in output
            .claims
            .iter()
            .filter(|c| c.verdict == Verdict::Failed)
        {
            summary.push_str(&format!("  FAILED {}: {}\n", c.id, c.evidence));
        }
        files.push((format!("{}.md", paper.id), output.markdown));
        files.extend(output.figures);
        all_claims.extend(output.claims);
    }
    files.push(("claims.json".to_string(), report::ledger_json(&all_claims)));
    report::write_files(out_dir, &files)
        .map_err(|e| Failure::Usage(format!("option --out: writing {}: {e}", out_dir.display())))?;
    summary.push_str(&format!(
        "wrote {} files to {}\n",
        files.len(),
        out_dir.display()
    ));
    let failed = all_claims
        .iter()
        .filter(|c| c.verdict == Verdict::Failed)
        .count();
    if failed > 0 {
        Err(Failure::Run(format!("{summary}{failed} claim(s) failed")))
    } else {
        Ok(summary)
    }
}

fn run(
    algorithm: Algorithm,
    scalar: Option<ScalarKind>,
    input: Option<PathBuf>,
) -> Result<String, Failure> {
    // At most MAX_INPUT_BYTES are read: a larger document is refused, not swallowed.
    let limit = budget::MAX_INPUT_BYTES as u64;
    let (source, reader): (String, Box<dyn Read>) = match &input {
        Some(path) => (
            format!("option --input: {}", path.display()),
            Box::new(std::fs::File::open(path).map_err(|e| {
                Failure::Usage(format!(
                    "option --input: cannot read {}: {e}",
                    path.display()
                ))
            })?),
        ),
        None => ("input: stdin".to_string(), Box::new(std::io::stdin())),
    };
    let mut bytes = Vec::new();
    reader
        .take(limit + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| Failure::Usage(format!("{source}: cannot read: {e}")))?;
    if bytes.len() as u64 > limit {
        return Err(Failure::Usage(format!(
            "{source}: the input is larger than {} MiB",
            limit >> 20
        )));
    }
    let text = String::from_utf8(bytes)
        .map_err(|e| Failure::Usage(format!("{source}: not UTF-8 text: {e}")))?;
    run_text(algorithm, scalar, &text)
}

/// `run <algorithm> [--scalar <scalar>]` on the JSON input `text`, in process: the JSON
/// line it prints, or how it failed (for the differential soundness test, which runs
/// thousands of inputs without a process each).
#[doc(hidden)]
pub fn run_text(
    algorithm: Algorithm,
    scalar: Option<ScalarKind>,
    text: &str,
) -> Result<String, Failure> {
    budget::mark_start();
    let doc = input::parse_document(text).map_err(|e| Failure::Usage(e.0))?;
    let value = match algorithm {
        Algorithm::Hermite => run_hermite::run_hermite(&doc, scalar.unwrap_or(ScalarKind::F64)),
        Algorithm::HermiteCondition => {
            run_hermite::run_condition(&doc, scalar.unwrap_or(ScalarKind::Mpfr(256)))
        }
        Algorithm::BsplineBasis => run_bspline::run_basis(&doc),
        Algorithm::BsplineGram => run_bspline::run_gram(&doc),
        Algorithm::SplineFit => run_bspline::run_fit(&doc, scalar.unwrap_or(ScalarKind::F64)),
        Algorithm::BangBang => {
            run_bspline::run_bang_bang(&doc, scalar.unwrap_or(ScalarKind::Mpfr(256)))
        }
        Algorithm::Marin1d => {
            run_param::run_marin_1d(&doc, scalar.unwrap_or(ScalarKind::Mpfr(256)))
        }
        Algorithm::Marin => run_param::run_marin(&doc, scalar.unwrap_or(ScalarKind::Mpfr(256))),
        Algorithm::NaturalSpline => {
            run_param::run_natural_spline(&doc, scalar.unwrap_or(ScalarKind::F64))
        }
        Algorithm::PhHermite => run_ph::run_ph_hermite(&doc, scalar.unwrap_or(ScalarKind::F64)),
        Algorithm::Phodcos => run_ph::run_phodcos(&doc, scalar.unwrap_or(ScalarKind::F64)),
        Algorithm::Convergence => {
            run_ph::run_convergence(&doc, scalar.unwrap_or(ScalarKind::Mpfr(256)))
        }
        Algorithm::GerbsBasis => {
            run_gerbs::run_gerbs_basis(&doc, scalar.unwrap_or(ScalarKind::F64))
        }
        Algorithm::GerbsPath => run_gerbs::run_gerbs_path(&doc, scalar.unwrap_or(ScalarKind::F64)),
        Algorithm::Dubins => run_gerbs::run_dubins(&doc, scalar.unwrap_or(ScalarKind::F64)),
    }
    .and_then(Rendered::into_text)
    .map_err(|e| match e {
        RunError::Input(m) => Failure::Usage(m),
        RunError::Internal(m) => Failure::Internal(m),
    })?;
    let mut s = value;
    s.push('\n');
    Ok(s)
}
