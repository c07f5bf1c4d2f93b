//! The command line as a user runs it: the real binary, real JSON on stdin, exit statuses.

use serde_json::Value;
use std::io::Write;
use std::process::{Command, Stdio};

#[derive(Debug)]
struct Run {
    code: i32,
    stdout: String,
    stderr: String,
}

fn trajverify(args: &[&str], stdin: &str) -> Run {
    let mut child = Command::new(env!("CARGO_BIN_EXE_trajverify"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary starts");
    // A child that exits on a usage error before reading stdin closes the pipe: that is not a
    // failure of the test, whose assertions are on the exit status and the output.
    if let Err(e) = child
        .stdin
        .take()
        .expect("stdin is piped")
        .write_all(stdin.as_bytes())
    {
        assert_eq!(
            e.kind(),
            std::io::ErrorKind::BrokenPipe,
            "writing stdin: {e}"
        );
    }
    let out = child.wait_with_output().expect("the binary finishes");
    let run = Run {
        code: out.status.code().unwrap_or(-1),
        stdout: String::from_utf8_lossy(&out.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
    };
    check_printed_balls(args, stdin, &run);
    run
}

/// The ball contract, for every ball any test here prints: each {"value", "radius"} read as
/// exact decimals contains the value a run at 1024 bits prints (within that value's own half
/// unit), so the enclosure holds as printed, not only around an unprinted midpoint.
fn check_printed_balls(args: &[&str], stdin: &str, run: &Run) {
    let Some(at) = args.iter().position(|a| a.starts_with("ball:")) else {
        return;
    };
    if run.code != 0 || args.first() != Some(&"run") {
        return;
    }
    let mut reference_args: Vec<&str> = args.to_vec();
    reference_args[at] = "mpfr:1024";
    let reference = Command::new(env!("CARGO_BIN_EXE_trajverify"))
        .args(&reference_args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .and_then(|mut child| {
            let _ = child
                .stdin
                .take()
                .map(|mut s| s.write_all(stdin.as_bytes()));
            child.wait_with_output()
        })
        .expect("the reference runs");
    if !reference.status.success() {
        return; // e.g. a method whose 1024-bit run is beyond its budget
    }
    let tested: Value = serde_json::from_str(&run.stdout).expect("JSON");
    let exact: Value = serde_json::from_slice(&reference.stdout).expect("JSON");
    let mut checked = 0;
    contains(&tested, &exact, "", &mut checked);
    assert!(
        checked > 0,
        "no ball of {args:?} was checked against the 1024-bit run"
    );
}

fn exact_decimal(text: &str) -> trajverify::scalar::BigRational {
    trajverify::scalar::parse::parse_rational(text).unwrap_or_else(|e| panic!("{text}: {e}"))
}

/// Half a unit of the last digit of a printed decimal (0 for "0").
fn half_unit(text: &str) -> trajverify::scalar::BigRational {
    use trajverify::scalar::BigRational;
    let t = text.trim_start_matches('-');
    if t == "0" {
        return BigRational::from_integer(0.into());
    }
    let (mantissa, exponent) = t
        .split_once('e')
        .map_or((t, 0), |(m, e)| (m, e.parse().unwrap()));
    let fraction = mantissa.split_once('.').map_or(0, |(_, f)| f.len() as i32);
    let power: i32 = exponent - fraction;
    let ten = BigRational::from_integer(10.into());
    let unit = if power >= 0 {
        num_traits::pow(ten, power as usize)
    } else {
        BigRational::from_integer(1.into()) / num_traits::pow(ten, (-power) as usize)
    };
    unit / BigRational::from_integer(2.into())
}

fn contains(tested: &Value, reference: &Value, path: &str, checked: &mut usize) {
    use num_traits::Signed;
    match (tested, reference) {
        (Value::Object(t), Value::String(r)) if t.contains_key("radius") => {
            let value = exact_decimal(t["value"].as_str().expect("a value"));
            let radius = exact_decimal(t["radius"].as_str().expect("a radius"));
            let r_value = exact_decimal(r);
            *checked += 1;
            assert!(
                (value - &r_value).abs() <= radius + half_unit(r),
                "{path}: the ball {} ± {} does not contain the 1024-bit value {r}",
                t["value"],
                t["radius"]
            );
        }
        (Value::Object(t), Value::Object(r)) => {
            for (k, v) in t {
                if let Some(rv) = r.get(k) {
                    contains(v, rv, &format!("{path}.{k}"), checked);
                }
            }
        }
        (Value::Array(t), Value::Array(r)) if t.len() == r.len() => {
            for (i, (a, b)) in t.iter().zip(r).enumerate() {
                contains(a, b, &format!("{path}[{i}]"), checked);
            }
        }
        _ => {}
    }
}

fn json(run: &Run) -> Value {
    assert_eq!(run.code, 0, "stderr: {}", run.stderr);
    serde_json::from_str(&run.stdout).expect("stdout is one JSON object")
}

const FIG2: &str = r#"{"start": [0, 0, 0], "end": [1, 1, 0], "interval": [0, 1]}"#;

#[test]
fn hermite_rational_reproduces_figure_two_exactly() {
    let out = json(&trajverify(
        &["run", "hermite", "--scalar", "rational"],
        FIG2,
    ));
    assert_eq!(out["degree"], 5);
    assert_eq!(
        out["control_points"],
        serde_json::json!(["0", "0", "0", "3/5", "4/5", "1"])
    );
    let slow = json(&trajverify(
        &["run", "hermite", "--scalar", "rational"],
        r#"{"start": [0, 0, 0], "end": [1, 1, 0], "interval": ["0", "2"]}"#,
    ));
    assert_eq!(
        slow["control_points"],
        serde_json::json!(["0", "0", "0", "1/5", "3/5", "1"])
    );
}

#[test]
fn hermite_f64_prints_shortest_round_trip_decimals() {
    let out = json(&trajverify(&["run", "hermite"], FIG2));
    assert_eq!(out["scalar"], "f64");
    let points: Vec<f64> = out["control_points"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_str().unwrap().parse().unwrap())
        .collect();
    for (got, want) in points.iter().zip([0.0, 0.0, 0.0, 0.6, 0.8, 1.0]) {
        assert!((got - want).abs() < 1e-15, "{got} vs {want}");
    }
}

#[test]
fn hermite_mpfr_prints_only_certified_digits() {
    let out = json(&trajverify(
        &["run", "hermite", "--scalar", "mpfr:64"],
        r#"{"start": [0, 0, 0], "end": [1, 1, 0], "interval": [0, "1/3"]}"#,
    ));
    assert_eq!(out["scalar"], "mpfr:64");
    let p3 = out["control_points"][3].as_str().unwrap();
    // p3 = 1 − 2T/5 with T = 1/3: 13/15 = 0.8666…; 64 bits carry at most 19 digits.
    assert!(p3.starts_with("0.8666666666666666"), "{p3}");
    assert!(
        p3.len() <= 2 + 19,
        "{p3} has more digits than 64 bits can certify"
    );
}

#[test]
fn hermite_points_in_the_plane() {
    let out = json(&trajverify(
        &["run", "hermite", "--scalar", "rational"],
        r#"{"start": [[0, 0], [1, 0]], "end": [[1, 1], [0, 1]], "interval": [0, "3/2"]}"#,
    ));
    assert_eq!(out["degree"], 3);
    assert_eq!(
        out["control_points"],
        serde_json::json!([["0", "0"], ["1/2", "0"], ["1", "1/2"], ["1", "1"]])
    );
}

#[test]
fn condition_number_is_certified_and_compared_with_f64() {
    let out = json(&trajverify(
        &["run", "hermite-condition"],
        r#"{"derivatives": 2, "interval": [0, 1], "matrix": "transform"}"#,
    ));
    // mpfr:256 prints the digits the inertia brackets prove: about 75.
    let digits = out["condition_number"]
        .as_str()
        .unwrap()
        .chars()
        .filter(char::is_ascii_digit)
        .count();
    assert!(digits >= 70, "{out}");
    let k: f64 = out["condition_number"].as_str().unwrap().parse().unwrap();
    let f = out["f64"].as_f64().unwrap();
    assert!(
        (k - 87.26983291065).abs() < 1e-9 && (f - k).abs() < 1e-12 * k,
        "{k} {f}"
    );
    // From m = 10 nalgebra's SVD returns σmin = 0: no f64 value, and a note saying why.
    let big = json(&trajverify(
        &["run", "hermite-condition"],
        r#"{"derivatives": 10, "interval": [0, 1], "matrix": "transform"}"#,
    ));
    assert!(big["f64"].is_null());
    assert!(big["f64_note"].as_str().unwrap().contains("σmin = 0"));
    let ours = json(&trajverify(
        &["run", "hermite-condition", "--scalar", "f64"],
        r#"{"derivatives": 10, "interval": [0, 1], "matrix": "binomial"}"#,
    ));
    assert!(ours["correct_digits"].as_u64().unwrap() >= 10, "{ours}");
    // Proven: the ball from exact Sylvester-inertia brackets holds the mpfr:256 value.
    for m in [5, 30] {
        let input = format!(r#"{{"derivatives": {m}, "interval": [0, 1], "matrix": "transform"}}"#);
        let proven = json(&trajverify(
            &["run", "hermite-condition", "--scalar", "ball:128"],
            &input,
        ));
        let certified = json(&trajverify(&["run", "hermite-condition"], &input));
        let number = |v: &Value| v.as_str().unwrap().parse::<f64>().unwrap();
        let (mid, radius) = (
            number(&proven["condition_number"]["value"]),
            number(&proven["condition_number"]["radius"]),
        );
        let k = number(&certified["condition_number"]);
        assert!(
            (k - mid).abs() <= radius + 1e-10 * k && radius <= 1e-10 * k,
            "m = {m}: {proven} vs {k}"
        );
    }
}

#[test]
fn bad_input_is_one_line_exit_two_and_no_stdout() {
    let cases: &[(&[&str], &str, &str)] = &[
        (
            &["run", "hermite"],
            r#"{"start": [0], "interval": [0, 1]}"#,
            "\"end\"",
        ),
        (
            &["run", "hermite"],
            r#"{"start": [0, 1], "end": [1], "interval": [0, 1]}"#,
            "\"end\"",
        ),
        (
            &["run", "hermite"],
            r#"{"start": [0, [1, 2]], "end": [1, 1], "interval": [0, 1]}"#,
            "mixed dimensions",
        ),
        (
            &["run", "hermite"],
            r#"{"start": [[0, 0]], "end": [[1, 1, 1]], "interval": [0, 1]}"#,
            "mixed dimensions",
        ),
        (
            &["run", "hermite"],
            r#"{"start": ["NaN"], "end": [1], "interval": [0, 1]}"#,
            "start[0]",
        ),
        (
            &["run", "hermite"],
            r#"{"start": [0], "end": [1], "interval": [2, 1]}"#,
            "interval",
        ),
        (&["run", "hermite"], r#"{"start": [0"#, "malformed JSON"),
        (
            &["run", "hermite"],
            r#"{"start": [0], "end": [1], "interval": [0, 1], "extra": 1}"#,
            "extra",
        ),
        (
            &["run", "hermite-condition"],
            r#"{"derivatives": 2.5, "interval": [0, 1], "matrix": "transform"}"#,
            "derivatives",
        ),
        (
            &["run", "hermite-condition"],
            r#"{"derivatives": 2, "interval": [0, 1], "matrix": "other"}"#,
            "matrix",
        ),
        (
            &["run", "hermite-condition", "--scalar", "rational"],
            r#"{"derivatives": 2, "interval": [0, 1], "matrix": "transform"}"#,
            "--scalar",
        ),
        (&["run", "hermite", "--scalar", "mpfr:7"], FIG2, "mpfr"),
        (&["verify", "--paper", "nonexistent"], "", "nonexistent"),
        (&["run", "no-such-algorithm"], "", "no-such-algorithm"),
        (&["run", "bspline-basis"], r#"{"degree": -1}"#, "degree"),
        (&["run", "bspline-gram"], r#"{"degree": 0}"#, "degree"),
        (
            &["run", "spline-fit"],
            r#"{"degree": 3, "controls": 3, "times": [1, 2, 3, 4], "values": [1, 2, 3, 4], "weights": null}"#,
            "controls",
        ),
        (
            &["run", "spline-fit"],
            r#"{"degree": 3, "controls": 6, "times": [0, 2], "values": [1, 2], "weights": null}"#,
            "times[0]",
        ),
        (
            &["run", "spline-fit", "--scalar", "rational"],
            r#"{"degree": 3, "controls": 6, "times": [2, 2], "values": [1, 2], "weights": null}"#,
            "full row rank",
        ),
        (
            &["run", "spline-fit"],
            r#"{"degree": 3, "controls": 6, "times": [1, 2], "values": [1, 2], "weights": [1, -1]}"#,
            "weights[1]",
        ),
        (
            &["run", "spline-fit"],
            r#"{"degree": 3, "controls": 6, "times": [1, 2], "values": [1], "weights": null}"#,
            "values",
        ),
        (&["run", "bang-bang"], r#"{"xi": "x"}"#, "xi"),
        (
            &["run", "bang-bang", "--scalar", "rational"],
            r#"{"xi": 1}"#,
            "--scalar",
        ),
        (&["run", "marin-1d"], r#"{"z": [0, 1, 1, 2]}"#, "equal"),
        (&["run", "marin-1d"], r#"{"z": [0]}"#, "two points"),
        (
            &["run", "marin-1d", "--scalar", "rational"],
            r#"{"z": [0, 2, 1]}"#,
            "case II",
        ),
        (
            &["run", "marin"],
            r#"{"points": [[0, 0], [0, 0], [1, 1]]}"#,
            "points[1]",
        ),
        (
            &["run", "marin"],
            r#"{"points": [[0, 0], [1, 1]], "weights": [1, 0]}"#,
            "weights[1]",
        ),
        (
            &["run", "marin"],
            r#"{"points": [[0, 0], [1, 1]], "objective": "best"}"#,
            "objective",
        ),
        (
            &["run", "natural-spline"],
            r#"{"t": [0, 1, 1], "z": [0, 1, 2], "at": [0.5]}"#,
            "t[2]",
        ),
        (
            &["run", "natural-spline"],
            r#"{"t": [0], "z": [0], "at": [0]}"#,
            "two knots",
        ),
    ];
    for (args, input, needle) in cases {
        let run = trajverify(args, input);
        assert_eq!(run.code, 2, "{args:?} {input}: {}", run.stderr);
        assert!(run.stdout.is_empty(), "{args:?}: stdout {}", run.stdout);
        assert!(
            run.stderr.contains(needle),
            "{args:?}: {} lacks {needle}",
            run.stderr
        );
        assert_eq!(
            run.stderr.trim_end().lines().count(),
            1,
            "{args:?}: {}",
            run.stderr
        );
    }
}

#[test]
fn factorials_that_overflow_f64_are_reported() {
    let zeros = vec!["0"; 201].join(", ");
    let input = format!(r#"{{"start": [{zeros}], "end": [{zeros}], "interval": [0, 1]}}"#);
    let run = trajverify(&["run", "hermite", "--scalar", "f64"], &input);
    assert_eq!(run.code, 2);
    assert!(
        run.stdout.is_empty() && run.stderr.contains("not representable in f64"),
        "{}",
        run.stderr
    );
    // The same data are fine exactly.
    assert_eq!(
        trajverify(&["run", "hermite", "--scalar", "rational"], &input).code,
        0
    );
}

#[test]
fn list_names_every_claim_with_its_location() {
    let run = trajverify(&["list"], "");
    assert_eq!(run.code, 0);
    assert!(run
        .stdout
        .contains("hermite.fig2.control_points.t1\tSec. 4, Fig. 2"));
    assert!(run.stdout.contains("bspline.sec5.gram_k3\tSec. 5"));
    // Filtering by id or short name keeps exactly that paper's section of the full list.
    let hermite = trajverify(&["list", "--paper", "000_d51e5cedfa8471cf"], "");
    assert!(
        hermite.stdout.starts_with("# 000_d51e5cedfa8471cf")
            && !hermite.stdout.contains("bspline.")
    );
    let sections: String = ["hermite", "phodcos", "bspline", "gerbs", "marin"]
        .iter()
        .map(|p| trajverify(&["list", "--paper", p], "").stdout)
        .collect();
    assert_eq!(sections, run.stdout);
}

#[test]
fn verify_refuses_an_unwritable_out_before_computing() {
    let file = std::env::temp_dir().join(format!("trajverify-not-a-dir-{}", std::process::id()));
    std::fs::write(&file, "").unwrap();
    let start = std::time::Instant::now();
    let run = trajverify(&["verify", "--out", file.join("sub").to_str().unwrap()], "");
    std::fs::remove_file(&file).ok();
    assert_eq!(run.code, 2, "{}", run.stderr);
    assert_eq!(run.stderr.lines().count(), 1, "{}", run.stderr);
    assert!(
        run.stderr.starts_with("error: option --out: cannot write"),
        "{}",
        run.stderr
    );
    // Refused before the claims are computed (all of them take about 30 s).
    assert!(start.elapsed().as_secs() < 5, "took {:?}", start.elapsed());
}

#[test]
fn budgets_and_non_finite_results_are_refused_naming_the_field() {
    let over = trajverify(
        &["run", "phodcos", "--scalar", "mpfr:256"],
        r#"{"curve": "[sin(t), cos(t), t]", "interval": [0, 1], "segments": 65536}"#,
    );
    assert_eq!(over.code, 2);
    assert!(over.stdout.is_empty());
    assert!(
        over.stderr
            .starts_with("error: field \"segments\": 65536 segments at mpfr:256 would take about"),
        "{}",
        over.stderr
    );
    let inf = trajverify(
        &["run", "bang-bang", "--scalar", "f64"],
        r#"{"xi": "1e10000"}"#,
    );
    assert_eq!(inf.code, 2);
    assert!(inf.stdout.is_empty());
    assert!(
        inf.stderr.contains("output \"amplitude\" is inf in f64"),
        "{}",
        inf.stderr
    );
    // The same input is finite in MPFR.
    let mpfr = json(&trajverify(
        &["run", "bang-bang", "--scalar", "mpfr:64"],
        r#"{"xi": "1e10000"}"#,
    ));
    assert!(mpfr["amplitude"].as_str().unwrap().contains("e10000"));
    // At 16 bits the inertia brackets still prove κ₂'s first four digits (the 256-bit value
    // for m = 30 is 1.218974…e59).
    let low = json(&trajverify(
        &["run", "hermite-condition", "--scalar", "mpfr:16"],
        r#"{"derivatives": 30, "interval": [0, 1], "matrix": "transform"}"#,
    ));
    assert_eq!(low["condition_number"], "1.219e59", "{low}");
    // No proven digit at all is not printed as if it were one: the issue's case III data at
    // 16 bits (t₁ = 0.1352…, which 16-bit balls cannot resolve).
    let noise = trajverify(
        &["run", "marin-1d", "--scalar", "mpfr:16"],
        r#"{"z": ["0", "-5", "-13", "-53/4", "-157/12", "-67/4", "-1674999999999999999999/100000000000000000000"]}"#,
    );
    assert_eq!(noise.code, 2, "{}", noise.stdout);
    assert!(
        noise.stderr.contains("not even its first digit is proven"),
        "{}",
        noise.stderr
    );
}

#[test]
fn verify_of_some_papers_never_replaces_the_whole_ledger() {
    // Without --out, one paper's claims would overwrite reports/claims.json (141 → 25 claims).
    let run = trajverify(&["verify", "--paper", "hermite"], "");
    assert_eq!(run.code, 2, "{}", run.stdout);
    assert!(run.stderr.contains("needs --out"), "{}", run.stderr);
    assert_eq!(run.stderr.lines().count(), 1, "{}", run.stderr);
}

#[test]
fn verify_writes_the_ledger_and_reports() {
    let dir = std::env::temp_dir().join(format!("trajverify-cli-{}", std::process::id()));
    let run = trajverify(
        &[
            "verify",
            "--paper",
            "hermite",
            "--out",
            dir.to_str().unwrap(),
        ],
        "",
    );
    assert_eq!(run.code, 0, "{}", run.stderr);
    let ledger: Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("claims.json")).unwrap()).unwrap();
    // The summary counts every verdict of the vocabulary, zero counts included.
    let verdicts = ledger["summary"]["verdicts"].as_object().unwrap();
    let names: Vec<&str> = verdicts.keys().map(String::as_str).collect();
    assert_eq!(
        names,
        [
            "reproduced",
            "reproduced-rounding",
            "metric",
            "typo",
            "illustrated",
            "undetermined",
            "discrepancy",
            "failed"
        ]
    );
    assert_eq!(verdicts["failed"], 0);
    assert_eq!(
        ledger["summary"]["total"],
        ledger["claims"].as_array().unwrap().len()
    );
    let report = std::fs::read_to_string(dir.join("000_d51e5cedfa8471cf.md")).unwrap();
    for fig in 2..=5 {
        let name = format!("000_d51e5cedfa8471cf_fig{fig}.svg");
        assert!(report.contains(&name), "report does not link {name}");
        assert!(std::fs::read_to_string(dir.join(&name))
            .unwrap()
            .starts_with("<svg"));
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn bspline_basis_and_gram_are_exact() {
    let basis = json(&trajverify(&["run", "bspline-basis"], r#"{"degree": 3}"#));
    assert_eq!(
        basis["pieces"][0],
        serde_json::json!(["0", "0", "0", "1/6"])
    );
    assert_eq!(
        basis["pieces"][2],
        serde_json::json!(["2/3", "0", "-1", "1/2"])
    );
    let gram = json(&trajverify(&["run", "bspline-gram"], r#"{"degree": 3}"#));
    assert_eq!(gram["entries"], serde_json::json!(["20", "-15", "6", "-1"]));
}

#[test]
fn spline_fit_interpolates_exactly_in_rationals() {
    let input = r#"{"degree": 3, "controls": 6, "times": [1.5, 3, 4.5, 6], "values": [1, -2, 0, "5/3"], "weights": null}"#;
    let exact = json(&trajverify(
        &["run", "spline-fit", "--scalar", "rational"],
        input,
    ));
    assert_eq!(exact["tau"].as_array().unwrap().len(), 6);
    assert_eq!(exact["problem"], "interpolation (Eq. 14)");
    // The f64 answer agrees with the exact one.
    let fast = json(&trajverify(&["run", "spline-fit"], input));
    for (a, b) in exact["tau"]
        .as_array()
        .unwrap()
        .iter()
        .zip(fast["tau"].as_array().unwrap())
    {
        let q = trajverify::scalar::parse::parse_rational(a.as_str().unwrap()).unwrap();
        let x: f64 = b.as_str().unwrap().parse().unwrap();
        assert!(
            (trajverify::scalar::Field::to_f64(&q) - x).abs() < 1e-12,
            "{a} vs {b}"
        );
    }
    let points = json(&trajverify(
        &["run", "spline-fit"],
        r#"{"degree": 3, "controls": 6, "times": [1.5, 3], "values": [[1, 0], [0, 1]], "weights": [1, 1]}"#,
    ));
    assert_eq!(points["tau"][0].as_array().unwrap().len(), 2);
}

#[test]
fn bang_bang_is_certified_and_exact() {
    let out = json(&trajverify(&["run", "bang-bang"], r#"{"xi": "2/3"}"#));
    assert_eq!(
        out["exact"]["switching_times"],
        serde_json::json!(["2 - sqrt(2)", "2", "2 + sqrt(2)"])
    );
    assert_eq!(out["exact"]["amplitude"], "1 + 1/2*sqrt(2)");
    let t1 = out["switching_times"][0].as_str().unwrap();
    assert!(
        t1.starts_with("0.58578643762690495119831127579030192143"),
        "{t1}"
    );
    let half = json(&trajverify(&["run", "bang-bang"], r#"{"xi": "1/3"}"#));
    assert_eq!(half["exact"]["amplitude"], "1/2 + 1/4*sqrt(2)");
}

#[test]
fn marin_commands() {
    // Table I of paper 004, case II, to the printed four decimals.
    let out = json(&trajverify(
        &["run", "marin-1d"],
        r#"{"z": [0.0, 0.2, 0.1, 0.4, -0.1, 0.0, -0.3, 0.2, 0.0, 0.5, 0.4]}"#,
    ));
    assert_eq!(out["case"], "II");
    let t3: f64 = out["t"][3].as_str().unwrap().parse().unwrap();
    assert!((t3 - 0.2440).abs() < 5e-5, "{t3}");
    let exact = json(&trajverify(
        &["run", "marin-1d", "--scalar", "rational"],
        r#"{"z": [0, 1, 3, 4]}"#,
    ));
    assert_eq!(exact["t"], serde_json::json!(["0", "1/4", "3/4", "1"]));
    let spline = json(&trajverify(
        &["run", "natural-spline", "--scalar", "rational"],
        r#"{"t": [0, 0.5, 1], "z": [0, 1, 0], "at": [0.25, 0.5]}"#,
    ));
    assert_eq!(spline["values"], serde_json::json!(["11/16", "1"]));
    assert_eq!(spline["second"][1], "-12");
    let plane = json(&trajverify(
        &["run", "marin", "--scalar", "f64"],
        r#"{"points": [[0, 0], [1, 0.2], [1.5, 1], [0.5, 1.5]], "objective": "exact"}"#,
    ));
    let g: f64 = plane["G"].as_str().unwrap().parse().unwrap();
    let g_chord: f64 = plane["G_chord"].as_str().unwrap().parse().unwrap();
    assert!(g <= g_chord, "{g} > {g_chord}");
    // A yes/no field is a JSON boolean, not the string "true".
    assert!(
        plane["descent_converged"].is_boolean(),
        "{}",
        plane["descent_converged"]
    );
    // The endpoints are fixed exactly by the constraints: "0" and "1", not 77 digits of 1.
    let wide = json(&trajverify(
        &["run", "marin", "--scalar", "mpfr:256"],
        r#"{"points": [[0, 0], [1, 2], [3, 3], [4, 1]]}"#,
    ));
    let t = wide["t"].as_array().expect("t is a list");
    assert_eq!(
        (&t[0], &t[3]),
        (&serde_json::json!("0"), &serde_json::json!("1"))
    );
    assert!(t[1].as_str().is_some_and(|s| s.len() > 60), "{}", t[1]);
}

const PH_DATA: &str = r#"{"p_b":[0,0,0],"p_e":[1,0.2,0.1],"v_b":[1,0,0],"v_e":[1,0.3,0],"a_b":[0,1,0],"a_e":[0,-1,0.2],"j_b":[0,0,1],"j_e":[0.1,0,0],"s_b":[0,0,0],"s_e":[0,0,0]}"#;

#[test]
fn ph_hermite_gives_nine_quaternions_and_eighteen_points() {
    for scalar in ["f64", "mpfr:128"] {
        let v = json(&trajverify(
            &["run", "ph-hermite", "--scalar", scalar],
            PH_DATA,
        ));
        assert_eq!(v["preimage"].as_array().unwrap().len(), 9);
        let cp = v["control_points"].as_array().unwrap();
        assert_eq!(cp.len(), 18);
        // p_17 = p_e.
        let last: Vec<f64> = cp[17]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_str().unwrap().parse().unwrap())
            .collect();
        assert!(
            (last[0] - 1.0).abs() < 1e-12
                && (last[1] - 0.2).abs() < 1e-12
                && (last[2] - 0.1).abs() < 1e-12,
            "{last:?}"
        );
    }
    let r = trajverify(&["run", "ph-hermite", "--scalar", "rational"], PH_DATA);
    assert_eq!(r.code, 2);
    assert!(r.stderr.contains("square roots"), "{}", r.stderr);
}

#[test]
fn phodcos_and_convergence_reproduce_table_1_rows() {
    let v = json(&trajverify(
        &["run", "phodcos"],
        r#"{"curve": "[1.5*sin(7.2*t), cos(9*t), exp(cos(1.8*t))]", "interval": [0, 1], "segments": 64}"#,
    ));
    assert_eq!(v["segments"], 64);
    assert_eq!(v["preimages"].as_array().unwrap().len(), 64);
    let e: f64 = v["max_error"].as_str().unwrap().parse().unwrap();
    assert!((e / 5.0096343e-9 - 1.0).abs() < 1e-6, "{e}");
    let v = json(&trajverify(
        &["run", "phodcos"],
        r#"{"curve": "[cos(t), sin(t), t/2]", "interval": [0, 6], "tolerance": "1e-8"}"#,
    ));
    let e: f64 = v["max_error"].as_str().unwrap().parse().unwrap();
    assert!(e < 1e-8);
    let v = json(&trajverify(
        &["run", "convergence"],
        r#"{"curve": "[1.5*sin(7.2*t), cos(9*t), exp(cos(1.8*t))]", "interval": [0, 1], "levels": [8, 9]}"#,
    ));
    // Each error proven by branch and bound to a relative width of 1e-6: its digits are the
    // true maximum's (1.98195792667625e-14 to 15 digits, from a 512-bit search).
    let rows = v["rows"].as_array().unwrap();
    assert_eq!(rows[0]["ratio"], Value::Null);
    assert!(
        rows[1]["error"]
            .as_str()
            .unwrap()
            .starts_with("1.98196e-14"),
        "{v}"
    );
    assert!(
        rows[1]["order"].as_str().unwrap().starts_with("6.0036"),
        "{v}"
    );
}

#[test]
fn ph_bad_input_is_one_line_exit_two() {
    let cases: &[(&str, &str, &str)] = &[
        (
            "phodcos",
            r#"{"curve": "[sin(t), sinh(t), 1]", "interval": [0, 1], "segments": 2}"#,
            "character 10: unknown name \"sinh\"",
        ),
        (
            "phodcos",
            r#"{"curve": "[sin(t), cos(t)+, 1]", "interval": [0, 1], "segments": 2}"#,
            "character 17",
        ),
        (
            "phodcos",
            r#"{"curve": "[sin(t), cos(t)]", "interval": [0, 1], "segments": 2}"#,
            "3 components",
        ),
        (
            "phodcos",
            r#"{"curve": "[sin(t), cos(t), t]", "interval": [1, 0], "segments": 2}"#,
            "\"interval\"",
        ),
        (
            "phodcos",
            r#"{"curve": "[ln(t), t, 1]", "interval": [0, 1], "segments": 2}"#,
            "not finite",
        ),
        (
            "phodcos",
            r#"{"curve": "[t, t, 1]", "interval": [0, 1], "segments": 2, "tolerance": 1}"#,
            "exactly one",
        ),
        (
            "phodcos",
            r#"{"curve": "[t, t, 1]", "interval": [0, 1], "tolerance": -1}"#,
            "\"tolerance\"",
        ),
        (
            "phodcos",
            r#"{"curve": "[t, 0, 0]", "interval": [0, 1], "tolerance": "1e-300", "max_segments": 4}"#,
            "not reached",
        ),
        (
            "convergence",
            r#"{"curve": "[t, t, 1]", "interval": [0, 1], "levels": [40]}"#,
            "levels[0]",
        ),
        (
            "ph-hermite",
            &PH_DATA.replace(r#""v_e":[1,0.3,0]"#, r#""v_e":[-1,0,0]"#),
            "v_b + v_e = 0",
        ),
        (
            "ph-hermite",
            &PH_DATA.replace(r#""v_b":[1,0,0]"#, r#""v_b":[0,0,0]"#),
            "\"v_b\"",
        ),
        (
            "ph-hermite",
            &PH_DATA.replace(r#""s_e":[0,0,0]"#, r#""s_e":[0,0]"#),
            "\"s_e\"",
        ),
        (
            "ph-hermite",
            &PH_DATA.replace("}", r#","free":{"tau4":1}}"#),
            "tau4",
        ),
    ];
    for (alg, input, expected) in cases {
        let r = trajverify(&["run", alg], input);
        assert_eq!(r.code, 2, "{alg} {input}: {}", r.stderr);
        assert!(r.stdout.is_empty());
        assert_eq!(r.stderr.trim().lines().count(), 1, "{}", r.stderr);
        assert!(r.stderr.contains(expected), "{input}: {}", r.stderr);
    }
}

const WAYPOINTS: &str = "[[0,0],[300,100],[600,-50],[900,150],[1200,0]]";
const FIG1_KNOTS: &str = "[0, 0, 0.25, 0.5, 0.75, 1, 1]";

fn strings(v: &Value) -> Vec<String> {
    v.as_array()
        .expect("an array")
        .iter()
        .map(|x| x.as_str().expect("a string").to_string())
        .collect()
}

fn num(v: &Value) -> f64 {
    v.as_str().expect("a string").parse().expect("a number")
}

#[test]
fn gerbs_basis_bfbs_is_exact_and_erbs_proven() {
    // At t = 3/10, u = (t − 1/4)/(1/4) = 1/5 on (t_3, t_4): B_4 = 10u³ − 15u⁴ + 6u⁵ = 181/3125,
    // B_4′ = (30u² − 60u³ + 30u⁴)/h = 384/125, and B_3 = 1 − B_4.
    let r = trajverify(
        &["run", "gerbs-basis", "--scalar", "rational"],
        &format!(r#"{{"knots": {FIG1_KNOTS}, "kind": "bfbs", "at": ["3/10"], "derivatives": 1}}"#),
    );
    let v = json(&r);
    let row = &v["values"][0];
    assert_eq!(row.as_array().unwrap().len(), 5, "B_2 … B_6");
    assert_eq!(strings(&row[2]), ["181/3125", "384/125"]);
    assert_eq!(strings(&row[1]), ["2944/3125", "-384/125"]);
    assert_eq!(strings(&row[0]), ["0", "0"]);
    // ERBS in MPFR: proven digits (Taylor-model quadrature), partition of unity, B_k(t_k) = 1.
    let r = trajverify(
        &["run", "gerbs-basis", "--scalar", "mpfr:128"],
        &format!(
            r#"{{"knots": {FIG1_KNOTS}, "kind": "erbs", "params": {{"alpha": 1, "beta": 3, "gamma": 1, "lambda": 0.5, "sigma": 1}}, "at": [0.3, 0.5], "derivatives": 2}}"#
        ),
    );
    let v = json(&r);
    let at_03: Vec<Vec<String>> = v["values"][0]
        .as_array()
        .unwrap()
        .iter()
        .map(strings)
        .collect();
    let sum: f64 = at_03.iter().map(|b| b[0].parse::<f64>().unwrap()).sum();
    assert!((sum - 1.0).abs() < 1e-15, "{sum}");
    assert!(at_03[1][0].len() > 30, "proven digits: {}", at_03[1][0]);
    assert_eq!(num(&v["values"][1][2][0]), 1.0, "B_4(t_4) = 1");
    assert_eq!(v["scalar"], "mpfr:128");
    // Knots 1/3 and 2/3 are balls: t = 1/2 is their midpoint at every precision (which end
    // to integrate from is a choice, not a decision to refuse), t = 0.4 is inside, and at a
    // knot the exact distance 0 gives B = 1 exactly.
    for scalar in ["ball:64", "mpfr:64"] {
        let r = trajverify(
            &["run", "gerbs-basis", "--scalar", scalar],
            r#"{"knots": ["0", "0", "1/3", "2/3", "1", "1"], "kind": "erbs", "at": ["1/2", "0.4", "1/3"], "derivatives": 1}"#,
        );
        assert_eq!(r.code, 0, "{scalar}: {}", r.stderr);
        let v = json(&r);
        let value = |row: usize, b: usize, k: usize| -> f64 {
            let x = &v["values"][row][b][k];
            num(x.get("value").unwrap_or(x))
        };
        assert!((value(0, 1, 0) - 0.5).abs() < 1e-12, "{v}");
        assert!((value(1, 1, 0) - 0.983654973335918).abs() < 1e-12, "{v}");
        assert!((value(1, 2, 1) - 1.298316347706426).abs() < 1e-9, "{v}");
        assert_eq!(value(2, 1, 0), 1.0, "{v}");
    }
    // A derivative that does not exist (2σ = 1/2, the second derivative at exactly the
    // centre 1/4) is null, decided on the exact input; the first exists and prints.
    let v = json(&trajverify(
        &["run", "gerbs-basis"],
        r#"{"knots": ["0", "0", "1/2", "1", "1"], "kind": "erbs", "params": {"sigma": "1/4"}, "at": ["1/4"], "derivatives": 2}"#,
    ));
    assert!(v["values"][0][0][2].is_null(), "{v}");
    assert!(num(&v["values"][0][0][1]) < -500.0, "{v}");
}

#[test]
fn gerbs_path_interpolates_the_waypoints_with_curvature_one_over_r() {
    for kind in ["bfbs", "erbs"] {
        let input = format!(
            r#"{{"waypoints": {WAYPOINTS}, "radius": 80, "theta_o": "pi/8", "kind": "{kind}", "samples": 21}}"#
        );
        let v = json(&trajverify(&["run", "gerbs-path"], &input));
        assert_eq!(v["points"].as_array().unwrap().len(), 21);
        assert_eq!(v["curvature"].as_array().unwrap().len(), 21);
        let w: Value = serde_json::from_str(WAYPOINTS).unwrap();
        let at = v["at_waypoints"].as_array().unwrap();
        assert_eq!(at.len(), 5);
        for (i, a) in at.iter().enumerate() {
            for c in 0..2 {
                let got = num(&a["point"][c]);
                let want = w[i][c].as_f64().unwrap();
                assert!(
                    (got - want).abs() < 1e-9,
                    "{kind} W{}: {got} vs {want}",
                    i + 1
                );
            }
            if (1..4).contains(&i) {
                // On the arc at its middle: |κ| = 1/R, the sign of the turn.
                let k = num(&a["curvature"]);
                assert!((k.abs() - 1.0 / 80.0).abs() < 1e-12, "{kind}: κ = {k}");
                assert_eq!(k.signum() as i64, v["turns"][i].as_i64().unwrap());
            }
        }
        let length = num(&v["length"]);
        assert!(length > 1200.0 && length < 1500.0, "{kind}: {length}");
    }
    // Proven in MPFR: the BFBS path in balls, its length by Taylor models of the speed.
    let v = json(&trajverify(
        &["run", "gerbs-path", "--scalar", "mpfr:128"],
        &format!(
            r#"{{"waypoints": {WAYPOINTS}, "radius": 80, "theta_o": "pi/8", "kind": "bfbs", "samples": 3}}"#
        ),
    ));
    let length = v["length"].as_str().unwrap();
    assert!(length.starts_with("1349.14216332056819"), "{length}");
    assert!(length.len() > 30, "{length}");
    assert!(
        v.get("digits").is_none(),
        "a proven run has no \"not proven\" label: {v}"
    );
    // An ERBS weight near a knot is a real value of about 1e-47: the y of the first line's
    // sample prints as the zero its ball proves ("0eK"), not a refusal; the ERBS path's length
    // is proven like the BFBS one's.
    let erbs = trajverify(
        &["run", "gerbs-path", "--scalar", "mpfr:64"],
        r#"{"waypoints": [[0,0],[10,0],[10,10],[20,10]], "radius": 2, "theta_o": "pi/8", "kind": "erbs", "samples": 401}"#,
    );
    assert_eq!(erbs.code, 0, "{}", erbs.stderr);
    let v = json(&erbs);
    let text = v["points"][1][1].as_str().unwrap();
    // "0eK" is 0 to the unit 10^K.
    let y: f64 = if text.starts_with("0e") {
        0.0
    } else {
        text.parse().unwrap()
    };
    assert!(y.abs() < 1e-40, "{}", v["points"][1][1]);
    assert!(v["points"][1][0]
        .as_str()
        .unwrap()
        .starts_with("0.0117809724509617"));
    assert!(v.get("digits").is_none(), "{v}");
    let length = v["length"].as_str().unwrap();
    // f64's tanh–sinh gives 30.127151260198…; the ball proves at least ten digits.
    assert!(length.starts_with("30.12715126"), "{length}");
}

#[test]
fn dubins_words_and_legs_reach_the_next_waypoint() {
    let v = json(&trajverify(
        &["run", "dubins"],
        &format!(r#"{{"waypoints": {WAYPOINTS}, "radius": 80, "samples": 5}}"#),
    ));
    let legs = v["legs"].as_array().unwrap();
    let words: Vec<&str> = legs.iter().map(|l| l["word"].as_str().unwrap()).collect();
    assert_eq!(words, ["LSR", "RSL", "LSR", "RSL"]);
    let w: Value = serde_json::from_str(WAYPOINTS).unwrap();
    let mut total = 0.0;
    for (i, leg) in legs.iter().enumerate() {
        let samples = leg["samples"].as_array().unwrap();
        assert_eq!(samples.len(), 5);
        let end = samples.last().unwrap();
        for c in 0..2 {
            let got = num(&end[c]);
            assert!(
                (got - w[i + 1][c].as_f64().unwrap()).abs() < 1e-9,
                "leg {i}"
            );
        }
        let parts: f64 = strings(&leg["lengths"])
            .iter()
            .map(|x| x.parse::<f64>().unwrap())
            .sum();
        assert!((parts - num(&leg["length"])).abs() < 1e-9);
        total += num(&leg["length"]);
    }
    assert!((total - num(&v["length"])).abs() < 1e-9);
    // Given headings: two waypoints are enough; a U-turn to the side is RSR or LSL.
    let v = json(&trajverify(
        &["run", "dubins", "--scalar", "mpfr:64"],
        r#"{"waypoints": [[0, 0], [0, 500]], "headings": [0, "pi"], "radius": 100}"#,
    ));
    assert_eq!(v["legs"][0]["word"], "LSL");
    let length = num(&v["length"]);
    // Two quarter... half-turn arcs of π·100 in total plus the straight 500 − 200 = 300.
    assert!(
        (length - (std::f64::consts::PI * 100.0 + 300.0)).abs() < 1e-9,
        "{length}"
    );
}

#[test]
fn gerbs_bad_input_is_one_line_exit_two() {
    let path = |w: &str, extra: &str| {
        format!(r#"{{"waypoints": {w}, "radius": 80, "theta_o": "pi/8", "kind": "erbs"{extra}}}"#)
    };
    let cases: Vec<(&str, String, &str)> = vec![
        (
            "gerbs-path",
            path("[[0,0],[1,1]]", ""),
            "at least 3 waypoints",
        ),
        (
            "gerbs-path",
            path("[[0,0],[1,1],[1,1],[2,0]]", ""),
            "repeats",
        ),
        (
            "gerbs-path",
            path("[[0,0],[1,1],[3,3],[4,0]]", ""),
            "collinear",
        ),
        (
            "gerbs-path",
            path(WAYPOINTS, "").replace("80", "0"),
            "\"radius\"",
        ),
        (
            "gerbs-path",
            path(WAYPOINTS, r#", "params": {"alpha": 0}"#),
            "\"params.alpha\"",
        ),
        (
            "gerbs-path",
            path(WAYPOINTS, r#", "params": {"alpha": [1, -1, 1, 1]}"#),
            "\"params.alpha[2]\"",
        ),
        (
            "gerbs-path",
            path(WAYPOINTS, r#", "theta_o": "t/8""#),
            "\"theta_o\"",
        ),
        (
            "gerbs-path",
            path(WAYPOINTS, r#", "samples": 1"#),
            "\"samples\"",
        ),
        (
            "gerbs-path",
            path(WAYPOINTS, r#", "arcs": "clockwise""#),
            "\"arcs\"",
        ),
        (
            "gerbs-basis",
            r#"{"knots": [0, 0.5, 0.25, 1], "kind": "bfbs", "at": [0.3]}"#.into(),
            "knots must increase",
        ),
        (
            "gerbs-basis",
            format!(r#"{{"knots": {FIG1_KNOTS}, "kind": "bspline", "at": [0.3]}}"#),
            "\"kind\"",
        ),
        (
            "gerbs-basis",
            format!(r#"{{"knots": {FIG1_KNOTS}, "kind": "bfbs", "at": [1.5]}}"#),
            "\"at[0]\"",
        ),
        (
            "gerbs-basis",
            format!(
                r#"{{"knots": {FIG1_KNOTS}, "kind": "bfbs", "params": {{"i": [2, 2]}}, "at": [0.3]}}"#
            ),
            "\"params.i\"",
        ),
        (
            "gerbs-basis",
            format!(
                r#"{{"knots": {FIG1_KNOTS}, "kind": "erbs", "params": {{"lambda": 2}}, "at": [0.3]}}"#
            ),
            "\"params.lambda\"",
        ),
        (
            "dubins",
            format!(r#"{{"waypoints": {WAYPOINTS}, "headings": [0, 1], "radius": 80}}"#),
            "\"headings\"",
        ),
        (
            "dubins",
            format!(r#"{{"waypoints": {WAYPOINTS}, "radius": -5}}"#),
            "\"radius\"",
        ),
    ];
    for (alg, input, expected) in &cases {
        let r = trajverify(&["run", alg], input);
        assert_eq!(r.code, 2, "{alg} {input}: {}", r.stderr);
        assert!(r.stdout.is_empty());
        assert_eq!(r.stderr.trim().lines().count(), 1, "{}", r.stderr);
        assert!(r.stderr.contains(expected), "{input}: {}", r.stderr);
    }
    // The ERBS is a quadrature: no exact run.
    let r = trajverify(
        &["run", "gerbs-basis", "--scalar", "rational"],
        &format!(r#"{{"knots": {FIG1_KNOTS}, "kind": "erbs", "at": [0.3]}}"#),
    );
    assert_eq!(r.code, 2);
    assert!(r.stderr.contains("--scalar"), "{}", r.stderr);
}

#[test]
fn ball_prints_the_digits_its_enclosure_proves_and_the_radius() {
    let out = json(&trajverify(
        &["run", "hermite", "--scalar", "ball:64"],
        r#"{"start": [0, 0, 0], "end": [1, 1, 0], "interval": [0, "1/3"]}"#,
    ));
    assert_eq!(out["scalar"], "ball:64");
    // p3 = 13/15: every point of its ball rounds to the printed digits, and the radius is a
    // bound at the level of 64 bits.
    let p3 = &out["control_points"][3];
    let value = p3["value"].as_str().unwrap();
    assert!(
        value.starts_with("0.86666666666666666") && value.len() <= 2 + 19,
        "{p3}"
    );
    let radius: f64 = p3["radius"].as_str().unwrap().parse().unwrap();
    assert!(radius > 0.0 && radius < 1e-17, "{p3}");
    // The README's example: 13/15 lies in value ± radius, read exactly as printed.
    {
        use num_traits::Signed;
        let exact = trajverify::scalar::BigRational::new(13.into(), 15.into());
        let distance = (exact_decimal(value) - exact).abs();
        assert!(
            distance <= exact_decimal(p3["radius"].as_str().unwrap()),
            "{p3}"
        );
    }
    // Algorithm 1 (the PH conversion of a segment) runs in balls too.
    let data = r#"{"p_b":[0,0,0],"p_e":[1,1,0],"v_b":[1,0,0],"v_e":[0,1,0],"a_b":[0,0,0],"a_e":[0,0,0],
                   "j_b":[0,0,0],"j_e":[0,0,0],"s_b":[0,0,0],"s_e":[0,0,0]}"#;
    let ph = json(&trajverify(
        &["run", "ph-hermite", "--scalar", "ball:256"],
        data,
    ));
    let length = &ph["arc_length"];
    assert!(length["value"].as_str().unwrap().len() > 60, "{length}");
    // The conversion of a whole curve: in balls the error is a proven enclosure that contains
    // the certified maximum MPFR finds.
    let curve = r#"{"curve": "[sin(t), cos(t), t]", "interval": [0, 1], "segments": 4}"#;
    let proven = json(&trajverify(
        &["run", "phodcos", "--scalar", "ball:256"],
        curve,
    ));
    let certified = json(&trajverify(
        &["run", "phodcos", "--scalar", "mpfr:128"],
        curve,
    ));
    let mid: f64 = proven["max_error"]["value"]
        .as_str()
        .unwrap()
        .parse()
        .unwrap();
    let rad: f64 = proven["max_error"]["radius"]
        .as_str()
        .unwrap()
        .parse()
        .unwrap();
    let value: f64 = certified["max_error"].as_str().unwrap().parse().unwrap();
    assert!(
        rad < 1e-6 * mid && (value - mid).abs() <= rad + 1e-5 * mid,
        "{proven} {certified}"
    );
    assert!(proven["max_error_relative_width"].as_f64().unwrap() <= 1e-6);
    // The bang-bang control in balls encloses its exact values in Q(√2): 2 − √2 first.
    let bang = json(&trajverify(
        &["run", "bang-bang", "--scalar", "ball:128"],
        r#"{"xi": "2/3"}"#,
    ));
    let first = &bang["switching_times"][0];
    assert!(
        first["value"]
            .as_str()
            .unwrap()
            .starts_with("0.58578643762690495119831127579"),
        "{bang}"
    );
    // An ERBS path's length is proven too (F_j carried along the path by proven increments):
    // its ball holds the f64 tanh–sinh value 30.127151260198… and is narrow.
    let erbs = json(&trajverify(
        &["run", "gerbs-path", "--scalar", "ball:64"],
        r#"{"waypoints": [[0,0],[10,0],[10,10],[20,10]], "radius": 2, "theta_o": "pi/8", "kind": "erbs", "samples": 5}"#,
    ));
    let length = &erbs["length"];
    let value: f64 = length["value"].as_str().unwrap().parse().unwrap();
    let radius: f64 = length["radius"].as_str().unwrap().parse().unwrap();
    assert!((value - 30.127151260198).abs() <= radius + 1e-12, "{erbs}");
    assert!(radius < 1e-9, "{erbs}");
    // Marin's minimizer is proven by Krawczyk's test: the knots are enclosures.
    let marin = json(&trajverify(
        &["run", "marin", "--scalar", "ball:128"],
        r#"{"points": [[0, 0], [1, 1], [2, 0]]}"#,
    ));
    let t1 = &marin["t"][1];
    assert!(t1["value"].as_str().unwrap().starts_with("0.5"), "{marin}");
    assert!(
        t1["radius"].as_str().unwrap().parse::<f64>().unwrap() < 1e-30,
        "{marin}"
    );
    let bad = trajverify(&["run", "hermite", "--scalar", "ball:x"], FIG2);
    assert_eq!(bad.code, 2);
    assert!(bad.stderr.contains("ball precision"), "{}", bad.stderr);
}

#[test]
fn report_convergence_writes_markdown_svg_and_json_for_a_users_curve() {
    let dir = std::env::temp_dir().join(format!("trajverify-report-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let out = dir.to_str().unwrap();
    let run = trajverify(
        &[
            "report",
            "convergence",
            "--curve",
            "[sin(t), cos(t), t]",
            "--interval",
            "0",
            "1",
            "--levels",
            "0-4",
            "--scalar",
            "ball:128",
            "--out",
            out,
        ],
        "",
    );
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert!(
        run.stderr.contains("level 4 (16 segments) done"),
        "progress on stderr: {}",
        run.stderr
    );
    for name in ["convergence.md", "convergence.svg", "convergence.json"] {
        assert!(dir.join(name).exists(), "{name}");
    }
    let doc: Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("convergence.json")).unwrap())
            .unwrap();
    let rows = doc["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 5);
    sampled_inside_proven(&doc);
    let order = doc["fit"]["order"].as_f64().unwrap();
    assert!((order - 6.0).abs() < 0.2, "Theorem 1's order 6: {order}");
    let _ = std::fs::remove_dir_all(&dir);
    // Bad input: one line, exit 2, nothing written.
    let bad = trajverify(
        &[
            "report",
            "convergence",
            "--curve",
            "[t, t]",
            "--interval",
            "0",
            "1",
            "--out",
            out,
        ],
        "",
    );
    assert_eq!(bad.code, 2);
    assert_eq!(bad.stderr.trim().lines().count(), 1, "{}", bad.stderr);
    assert!(bad.stderr.contains("--curve"), "{}", bad.stderr);
    assert!(!dir.exists());
    // Piecewise Hermite–Bernstein (paper 000's map on every segment): with m = 1 the
    // classical order 4 lies in the fitted interval; an unknown method is refused.
    let hermite = trajverify(
        &[
            "report",
            "convergence",
            "--curve",
            "[cos(3*t), sin(2*t), t^2]",
            "--interval",
            "0",
            "1",
            "--levels",
            "2-8",
            "--method",
            "hermite:1",
            "--scalar",
            "ball:128",
            "--out",
            out,
        ],
        "",
    );
    assert_eq!(hermite.code, 0, "{}", hermite.stderr);
    let doc: Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("convergence.json")).unwrap())
            .unwrap();
    assert_eq!(doc["expected_order"]["order"], 4);
    let fit = &doc["fit"];
    let (order, ci) = (
        fit["order"].as_f64().unwrap(),
        fit["ci95"].as_f64().unwrap(),
    );
    assert!((order - 4.0).abs() < 0.01 && ci < 0.05, "{fit}");
    // Inside the interval, or the report says the orders still move across it.
    assert!(
        fit["expected_inside"] == true || fit["drift"].is_object(),
        "{fit}"
    );
    let finest = doc["rows"].as_array().unwrap().last().unwrap()["order"]["value"]
        .as_f64()
        .unwrap();
    assert!((finest - 4.0).abs() < 0.002, "{finest}");
    let md = std::fs::read_to_string(dir.join("convergence.md")).unwrap();
    assert!(
        md.contains("Hermite–Bernstein interpolation (m = 1)"),
        "{md}"
    );
    let _ = std::fs::remove_dir_all(&dir);
    for method in ["hermite:9", "bspline", "hermite:x"] {
        let bad = trajverify(
            &[
                "report",
                "convergence",
                "--curve",
                "[t, t, t]",
                "--interval",
                "0",
                "1",
                "--method",
                method,
                "--out",
                out,
            ],
            "",
        );
        assert_eq!(bad.code, 2, "{method}: {}", bad.stderr);
        assert!(bad.stderr.contains("--method"), "{}", bad.stderr);
        assert!(!dir.exists());
    }
    // A closed curve given as data: a circle sampled at 64 points, the last row closing it.
    let csv = std::env::temp_dir().join(format!("trajverify-circle-{}.csv", std::process::id()));
    let mut rows = vec!["t,x,y,z".to_string()];
    for i in 0..=64 {
        let t = std::f64::consts::TAU * f64::from(i) / 64.0;
        let (x, y) = if i == 64 {
            (1.0, 0.0)
        } else {
            (t.cos(), t.sin())
        };
        rows.push(format!("{t},{x},{y},0"));
    }
    std::fs::write(&csv, rows.join("\n")).unwrap();
    let data = trajverify(
        &[
            "report",
            "convergence",
            "--data",
            csv.to_str().unwrap(),
            "--interval",
            "0",
            "3",
            "--levels",
            "0-3",
            "--out",
            out,
        ],
        "",
    );
    assert_eq!(data.code, 0, "{}", data.stderr);
    let doc: Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("convergence.json")).unwrap())
            .unwrap();
    assert_eq!(doc["rows"].as_array().unwrap().len(), 4);
    let _ = std::fs::remove_dir_all(&dir);
    // Data that do not close: the clamped quintic spline, proven with ball; the enclosure
    // holds the certified value.
    let open_rows: Vec<String> = (0..=40)
        .map(|i| {
            let t = f64::from(i) / 20.0;
            format!("{t},{},{},{}", t.cos(), (2.0 * t).sin(), t * t / 3.0)
        })
        .collect();
    std::fs::write(&csv, open_rows.join("\n")).unwrap();
    let open_args = |interval: &'static str| {
        vec![
            "report".to_string(),
            "convergence".into(),
            "--data".into(),
            csv.to_str().unwrap().into(),
            "--interval".into(),
            "0".into(),
            interval.into(),
            "--levels".into(),
            "0-2".into(),
            "--scalar".into(),
            "ball:128".into(),
            "--out".into(),
            out.into(),
        ]
    };
    let args = open_args("2");
    let open = trajverify(&args.iter().map(String::as_str).collect::<Vec<_>>(), "");
    assert_eq!(open.code, 0, "{}", open.stderr);
    let doc: Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("convergence.json")).unwrap())
            .unwrap();
    sampled_inside_proven(&doc);
    let md = std::fs::read_to_string(dir.join("convergence.md")).unwrap();
    assert!(md.contains("41 rows of an open curve"), "{md}");
    let _ = std::fs::remove_dir_all(&dir);
    // An open curve is known only between its first and last times.
    let args = open_args("3");
    let outside = trajverify(&args.iter().map(String::as_str).collect::<Vec<_>>(), "");
    assert_eq!(outside.code, 2, "{}", outside.stderr);
    assert!(outside.stderr.contains("--interval"), "{}", outside.stderr);
    assert!(!dir.exists());
    let _ = std::fs::remove_file(&csv);
}

/// Every sampled maximum a convergence report prints with agreeing digits lies in the proven
/// enclosure of its level (within its own last digit), unless the report says the sampled
/// search missed the maximum.
fn sampled_inside_proven(doc: &Value) {
    for row in doc["rows"].as_array().unwrap() {
        if row["error_sampled_digits"].as_u64().unwrap() == 0
            || row["sampled_search_missed"].as_bool().unwrap()
        {
            continue;
        }
        let number = |v: &Value| exact_decimal(v.as_str().unwrap());
        let text = row["error_sampled"].as_str().unwrap();
        let sampled = exact_decimal(text);
        let (lower, upper) = (
            number(&row["error_proven"]["lower"]),
            number(&row["error_proven"]["upper"]),
        );
        let slack = half_unit(text);
        assert!(
            lower <= sampled.clone() + &slack && sampled - slack <= upper,
            "{row}"
        );
    }
}

fn convergence_report(args: &[&str], dir: &std::path::Path) -> Result<(Value, String), Run> {
    let mut all = vec!["report", "convergence"];
    all.extend_from_slice(args);
    all.extend(["--out", dir.to_str().unwrap()]);
    let run = trajverify(&all, "");
    if run.code != 0 {
        return Err(run);
    }
    let doc = serde_json::from_str(&std::fs::read_to_string(dir.join("convergence.json")).unwrap())
        .unwrap();
    let md = std::fs::read_to_string(dir.join("convergence.md")).unwrap();
    Ok((doc, md))
}

#[test]
fn report_convergence_refuses_curves_it_cannot_measure_and_says_what_happened() {
    let dir = std::env::temp_dir().join(format!("trajverify-conv-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    // Curves that are not finite or not regular on the interval: one line naming t, exit 2,
    // no file written.
    for (curve, a, b, says) in [
        ("[sqrt(t), t, 0]", "0", "1", "not finite at t = 0"),
        ("[ln(t), t, 0]", "0", "1", "not finite at t = 0"),
        ("[sqrt(-1), t, t]", "0", "1", "not finite"),
        ("[t^(1/3), t, t]", "0", "1", "not finite at t = 0"),
        ("[1/t, t, 0]", "-1", "1", "not finite at t = 0"),
        ("[t^2, t^3, 0]", "-1", "1", "tangent vanishes at t = 0"),
        ("[t^2, t^3, 0]", "0", "1", "tangent vanishes at t = 0"),
    ] {
        let Err(run) = convergence_report(&["--curve", curve, "--interval", a, b], &dir) else {
            panic!("{curve} on [{a}, {b}] was accepted");
        };
        assert_eq!(run.code, 2, "{curve}: {}", run.stderr);
        assert_eq!(run.stderr.trim().lines().count(), 1, "{}", run.stderr);
        assert!(run.stderr.contains(says), "{curve}: {}", run.stderr);
        assert!(!dir.exists(), "{curve}: files written");
    }
    // The options are checked before anything is read or computed.
    let Err(run) = convergence_report(
        &["--data", "/nonexistent.csv", "--interval", "1", "0"],
        &dir,
    ) else {
        panic!("accepted")
    };
    assert!(run.stderr.contains("--interval"), "{}", run.stderr);
    // A curve the method reproduces exactly: no order, and the report says so.
    let (doc, md) = convergence_report(
        &[
            "--curve",
            "[t^2, t^3, 0]",
            "--interval",
            "1",
            "2",
            "--method",
            "hermite:2",
            "--levels",
            "0-4",
        ],
        &dir,
    )
    .unwrap();
    assert_eq!(doc["fit"]["outcome"], "reproduced", "{doc}");
    assert!(md.contains("reproduces the curve"), "{md}");
    assert!(!md.contains("NaN"), "{md}");
    // A curve too large for f64: the f64 column says so instead of NaN (sampled in MPFR:
    // balls carry f64 radii and cannot enclose values near 1e600, which the default run
    // says on one line).
    let (doc, md) = convergence_report(
        &[
            "--curve",
            "[t, t^2, t]",
            "--interval",
            "0",
            "1e300",
            "--levels",
            "0-1",
            "--scalar",
            "mpfr:128",
        ],
        &dir,
    )
    .unwrap();
    assert!(
        !md.contains("NaN") && md.contains("not finite in f64"),
        "{md}"
    );
    assert!(doc["rows"][0]["error_f64"].is_null());
    // One level is a report too (an error, no order).
    let (doc, _) = convergence_report(
        &[
            "--curve",
            "[sin(t), cos(t), t]",
            "--interval",
            "0",
            "1",
            "--levels",
            "2-2",
        ],
        &dir,
    )
    .unwrap();
    assert_eq!(doc["fit"]["outcome"], "too few levels");
    // A near-cusp is measured, with a warning.
    let (_, md) = convergence_report(
        &[
            "--curve",
            "[t^2, t^3, 0.001*t]",
            "--interval",
            "-1",
            "1",
            "--levels",
            "0-2",
        ],
        &dir,
    )
    .unwrap();
    assert!(md.contains("nearly has a cusp"), "{md}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// The Lissajous curve of the review: every printed error lies in its enclosure and agrees
/// with a run at four times the bits; the sampled search that misses the maximum of one
/// segment is caught by the proof.
#[test]
fn report_convergence_on_a_lissajous_curve_agrees_with_four_times_the_bits() {
    let dir = std::env::temp_dir().join(format!("trajverify-lissajous-{}", std::process::id()));
    let curve = "[sin(3*t), sin(2*t), 0]";
    for (method, levels) in [("hermite:8", "0-6"), ("hermite:0", "0-3")] {
        let run = |bits: &str| {
            convergence_report(
                &[
                    "--curve",
                    curve,
                    "--interval",
                    "0",
                    "6.283185307",
                    "--method",
                    method,
                    "--levels",
                    levels,
                    "--scalar",
                    bits,
                ],
                &dir,
            )
            .unwrap()
        };
        let (low, md) = run("ball:128");
        sampled_inside_proven(&low);
        let (high, _) = run("ball:512");
        for (l, h) in low["rows"]
            .as_array()
            .unwrap()
            .iter()
            .zip(high["rows"].as_array().unwrap())
        {
            let bound = |r: &Value, k: &str| exact_decimal(r["error_proven"][k].as_str().unwrap());
            // The two proofs enclose the same E.
            assert!(
                bound(l, "lower") <= bound(h, "upper") && bound(h, "lower") <= bound(l, "upper"),
                "{l} {h}"
            );
            // A sampled value printed with agreeing digits agrees with the 4x run's.
            let digits = l["error_sampled_digits"].as_u64().unwrap();
            if digits >= 1 && !l["sampled_search_missed"].as_bool().unwrap() {
                let text = l["error_sampled"].as_str().unwrap();
                let (x, y) = (
                    exact_decimal(text),
                    exact_decimal(h["error_sampled"].as_str().unwrap()),
                );
                use num_traits::Signed;
                assert!(
                    (x - y).abs()
                        <= half_unit(text)
                            * trajverify::scalar::BigRational::from_integer(2.into()),
                    "{l} {h}"
                );
            }
        }
        if method == "hermite:0" {
            assert!(md.contains("sampled search missed"), "{md}");
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// The inputs that broke "every printed digit is true", each now answered right or refused.
#[test]
fn regressions_of_the_soundness_review() {
    let nines = format!("0.{}", "9".repeat(40));
    // A point 1e-40 below a knot: the exact branch at every precision (B₂″ = 6, B₂‴ = 12,
    // B₃‴ = −12, as the rational run says), not the knot's one-sided values.
    let basis = |at: &str, side: &str| {
        format!(
            r#"{{"knots": [0,0,1,2,3,3], "kind": "bfbs", "params": {{"i": 1}}, "at": ["{at}"], "derivatives": 3, "side": "{side}"}}"#
        )
    };
    for scalar in ["mpfr:64", "rational", "f64", "ball:64"] {
        let out = json(&trajverify(
            &["run", "gerbs-basis", "--scalar", scalar],
            &basis(&nines, "right"),
        ));
        let text = |v: &Value| match v {
            Value::Object(b) => b["value"].as_str().unwrap().to_string(),
            other => other.as_str().unwrap().to_string(),
        };
        let b2: Vec<f64> = out["values"][0][0]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| text(v).split('/').next().unwrap().parse::<f64>().unwrap())
            .collect();
        let b3_third = text(&out["values"][0][1][3]);
        assert!(b3_third.starts_with("-12"), "{scalar}: B₃‴ = {b3_third}");
        assert!(b2[3] > 11.9, "{scalar}: B₂ = {b2:?}");
    }
    // The same 1e-40 above the knot, from the left.
    let above = format!("1.{}1", "0".repeat(39));
    let out = json(&trajverify(
        &["run", "gerbs-basis", "--scalar", "mpfr:64"],
        &basis(&above, "left"),
    ));
    assert!(
        out["values"][0][1][3].as_str().unwrap().starts_with("12"),
        "{out}"
    );
    // A straight Dubins leg: samples along it, not all at the origin.
    let out = json(&trajverify(
        &["run", "dubins", "--scalar", "mpfr:64"],
        r#"{"waypoints": [[0,0],[100,0],[200,0.5]], "radius": 10, "headings": [0,0,0], "samples": 3}"#,
    ));
    let xs: Vec<&str> = out["legs"][0]["samples"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p[0].as_str().unwrap())
        .collect();
    assert!(
        xs[0] == "0" && xs[1].starts_with("50.0") && xs[2].starts_with("100.0"),
        "{xs:?}"
    );
    // Default headings and a waypoint 1e-40 off the axis: the last sample of leg 1 is at x = 100.
    let out = json(&trajverify(
        &["run", "dubins", "--scalar", "mpfr:64"],
        r#"{"waypoints": [[0,0],[100,"1e-40"],[200,0.5]], "radius": 10}"#,
    ));
    let last = out["legs"][0]["samples"]
        .as_array()
        .unwrap()
        .last()
        .unwrap();
    assert!(last[0].as_str().unwrap().starts_with("100.0"), "{last}");
    // A rank-deficient interpolation (Schoenberg–Whitney fails) is refused in f64 as in rationals.
    let fit = r#"{"degree": 4, "controls": 11, "times": [1.4, 1.6, 1.8, 2.7, 2.9, 4.2, 4.9, 5.4, 8.8, 10.3, 11.3],
                  "values": [1,2,3,4,5,6,7,8,9,10,11], "weights": null}"#;
    for scalar in ["f64", "rational", "mpfr:64", "ball:64"] {
        let run = trajverify(&["run", "spline-fit", "--scalar", scalar], fit);
        assert_eq!(run.code, 2, "{scalar}: {}", run.stdout);
        assert!(run.stderr.contains("Schoenberg"), "{}", run.stderr);
    }
    // κ₂ on [1, 1 + 1e-40] (an exact fraction): the width is taken exactly.
    let one_plus = format!("1{}1/1{}", "0".repeat(39), "0".repeat(40));
    for scalar in ["mpfr:64", "mpfr:128"] {
        let out = json(&trajverify(
            &["run", "hermite-condition", "--scalar", scalar],
            &format!(
                r#"{{"derivatives": 10, "interval": [1, "{one_plus}"], "matrix": "transform"}}"#
            ),
        ));
        assert!(
            out["condition_number"]
                .as_str()
                .unwrap()
                .starts_with("1.8246678151"),
            "{out}"
        );
    }
}

/// A long chain of roll corrections in balls: the rotations are chained on the joints' own
/// unit rotations, so 256 segments of the README's curve keep finite preimages (they used
/// to reach a ball around 0 after about 230 joints), and the error is proven.
#[test]
fn phodcos_balls_stay_finite_over_many_segments() {
    let input = r#"{"curve": "[sin(t), cos(t), t]", "interval": [0, 1], "segments": 256}"#;
    let run = trajverify(&["run", "phodcos", "--scalar", "ball:256"], input);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let out = json(&run);
    assert_eq!(out["preimages"].as_array().map(Vec::len), Some(256));
    assert!(out["max_error"]["value"]
        .as_str()
        .is_some_and(|v| v.starts_with("3.25")));
}

/// Interval ends may be constant expressions, kept exact: [0, 4π] is studied with 4π
/// enclosed in the proof's balls; ends whose order cannot be decided, or that are not finite,
/// are refused naming the option.
#[test]
fn report_convergence_takes_constant_interval_ends() {
    let dir = std::env::temp_dir().join(format!("trajverify-conv-pi-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let (doc, md) = convergence_report(
        &[
            "--curve",
            "[cos(t), sin(t), t/5]",
            "--interval",
            "0",
            "4*pi",
            "--levels",
            "2-4",
        ],
        &dir,
    )
    .unwrap_or_else(|run| panic!("{}", run.stderr));
    assert!(md.contains("on [0, 4*pi]"), "{md}");
    let rows = doc["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 3);
    assert!(rows.iter().all(|r| r["error_proven"].is_object()), "{doc}");
    let _ = std::fs::remove_dir_all(&dir);
    for (a, b, says) in [
        ("pi", "4*atan(1)", "not decided"),
        ("0", "ln(0)", "not a finite number"),
        ("4*pi", "12", "need a < b"),
        ("0", "2*t", "expression in t"),
    ] {
        let Err(run) = convergence_report(
            &["--curve", "[cos(t), sin(t), t/5]", "--interval", a, b],
            &dir,
        ) else {
            panic!("[{a}, {b}] was accepted");
        };
        assert_eq!(run.code, 2, "{}", run.stderr);
        assert_eq!(run.stderr.trim().lines().count(), 1, "{}", run.stderr);
        assert!(
            run.stderr.contains("--interval") && run.stderr.contains(says),
            "{}",
            run.stderr
        );
        assert!(!dir.exists());
    }
}
