//! Every claim's id, verdict and reproduced value, pinned by an insta snapshot per paper in
//! `snapshots/`: any drift in any digit shows up in review.

use trajverify::papers::{self, Verdict};
use trajverify::report::number::{self, audit};

fn snapshot_paper(short: &str) {
    let paper = papers::all()
        .into_iter()
        .find(|p| p.short == short)
        .expect("the paper is registered");
    audit::start();
    let output = (paper.verify)();
    report_numbers(&output.markdown);
    let failed: Vec<&str> = output
        .claims
        .iter()
        .filter(|c| c.verdict == Verdict::Failed)
        .map(|c| c.id.as_str())
        .collect();
    assert!(failed.is_empty(), "failed claims: {failed:?}");
    assert_eq!(output.claims.len(), paper.specs.len());
    verdict_policy(&output.claims);
    let text: String = output
        .claims
        .iter()
        .map(|c| {
            format!(
                "{}\n  verdict: {}\n  scalar: {}\n  reproduced: {}\n",
                c.id,
                c.verdict.as_str(),
                c.scalar,
                c.reproduced
            )
        })
        .collect();
    let mut settings = insta::Settings::clone_current();
    settings.set_snapshot_path(concat!(env!("CARGO_MANIFEST_DIR"), "/snapshots"));
    settings.set_prepend_module_to_snapshot(false);
    settings.bind(|| insta::assert_snapshot!(format!("claims_{}", paper.id), text));
}

/// Every number the report shows, checked against the value it was rendered from
/// ([`audit::check`]).
fn report_numbers(markdown: &str) {
    let problems = audit::check(markdown);
    assert!(
        problems.is_empty(),
        "{} report numbers:\n{}",
        problems.len(),
        problems.join("\n")
    );
}

/// The rules of the verdict policy (`ledger` module doc) a test can decide.
fn verdict_policy(claims: &[trajverify::ledger::Claim]) {
    for c in claims {
        match (&c.verdict, &c.finding) {
            // Clause 7: a reproduced claim has no finding; every other verdict has one, with a
            // severity and its reason.
            (Verdict::Reproduced, Some(_)) => panic!("{}: reproduced with a finding", c.id),
            (Verdict::Reproduced, None) => {}
            (_, None) => panic!("{}: {} without a finding", c.id, c.verdict.as_str()),
            (_, Some(f)) => {
                assert!(
                    !f.paper.is_empty() && !f.difference.is_empty(),
                    "{}: empty finding",
                    c.id
                );
                assert!(
                    !f.severity_reason.is_empty(),
                    "{}: a severity without a reason",
                    c.id
                );
            }
        }
        // Clause 4: "reproduced-rounding" needs printed digits to round (a count has none).
        if c.verdict == Verdict::ReproducedRounding {
            assert!(
                c.published.is_some(),
                "{}: rounding without a printed value",
                c.id
            );
        }
        // Clause 1: an illustration says what it substituted.
        if c.verdict == Verdict::Illustrated {
            let says = c.finding.as_ref().is_some_and(|f| {
                ["our own", "of our own", "invented", "substitut", "ours"]
                    .iter()
                    .any(|w| f.difference.contains(w))
            });
            assert!(
                says,
                "{}: illustrated without naming the substitution",
                c.id
            );
        }
    }
}

/// The cell check is not vacuous: a number cut from a longer string (an exponent lost), a
/// column in two notations and a long run of leading zeros each fail it.
#[test]
fn the_report_number_check_catches_cut_numbers_and_mixed_columns() {
    audit::start();
    // Both notations of one value come from the formatter: only the column rule can object.
    assert_eq!(number::sig(0.987654321, 4), "0.9877");
    assert_eq!(
        number::sig_in(0.987654321, 4, number::Notation::Scientific),
        "9.877e-1"
    );
    for markdown in [
        "| n | error |\n|---|---|\n| 64 | 2.2907030107 |\n",
        "| n | error |\n|---|---|\n| 1 | 0.9877 |\n| 2 | 9.877e-1 |\n",
        "An error of 0.0000254767522 in prose.\n",
    ] {
        let caught = std::panic::catch_unwind(|| report_numbers(markdown)).is_err();
        assert!(caught, "not caught:\n{markdown}");
    }
}

/// `report convergence` writes its tables through the same formatter: its report passes the
/// same check.
#[test]
fn the_convergence_report_shows_its_numbers_as_computed() {
    use trajverify::algo::convergence::{study, Method, StudyOptions};
    use trajverify::report::convergence::{files, Described};
    audit::start();
    let curve = trajverify::curve::ExprCurve::parse("[cos(t), sin(2*t), t/5]").expect("parses");
    let interval = trajverify::curve::interval::Interval::new(0, 2).expect("0 < 2");
    let options = StudyOptions {
        method: Method::Hermite(2),
        levels: vec![1, 2, 3, 4, 5],
        ..StudyOptions::default()
    };
    let result = study(&curve, &interval, &options, &mut |_, _| {}).expect("the study runs");
    let described = Described {
        curve: "[cos(t), sin(2*t), t/5]",
        label: "test curve",
        interval: ("0", "2"),
        scalar: "ball:128".into(),
    };
    let markdown = files(&result, &described)
        .into_iter()
        .find(|(name, _)| name.ends_with(".md"))
        .expect("a Markdown report")
        .1;
    assert!(markdown.contains('|'), "the report has a table");
    report_numbers(&markdown);
}

#[test]
fn hermite_bernstein_claims() {
    snapshot_paper("hermite");
}

#[test]
fn bspline_control_claims() {
    snapshot_paper("bspline");
}

#[test]
fn marin_param_claims() {
    snapshot_paper("marin");
}

#[test]
fn phodcos_claims() {
    snapshot_paper("phodcos");
}

#[test]
fn gerbs_paths_claims() {
    snapshot_paper("gerbs");
}
