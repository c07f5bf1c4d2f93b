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

/// Every number the report shows, checked against the value it was rendered from: each
/// decimal number of a table cell (outside the claims ledger, whose evidence columns are prose)
/// is the one formatter's output, shown to its digits (or the paper's printed value, verbatim);
/// one notation per column; and nowhere in the report more than ten significant digits or a
/// long run of leading zeros.
fn report_numbers(markdown: &str) {
    let record = audit::record();
    assert!(
        record.wrong.is_empty(),
        "numbers that do not show their value: {:?}",
        record.wrong
    );
    // Each decimal number of `text` with its sign, and whether it is exact as written (an
    // integer, or part of a fraction such as 3/19).
    let tokens = |text: &str| -> Vec<(String, bool)> {
        let mut out = Vec::new();
        let mut rest = text;
        while let Some((before, token, after)) = number::next_number(rest) {
            let exact =
                !token.contains(['.', 'e', 'E']) || before.ends_with('/') || after.starts_with('/');
            let sign = if before.ends_with('-') || before.ends_with('−') {
                "-"
            } else {
                ""
            };
            out.push((format!("{sign}{token}"), exact));
            rest = after;
        }
        out
    };
    let mut problems = Vec::new();
    let mut in_ledger = false;
    let mut columns: Vec<Vec<(bool, String)>> = Vec::new();
    let flush = |columns: &mut Vec<Vec<(bool, String)>>, problems: &mut Vec<String>| {
        for col in columns.drain(..) {
            let scientific = col.iter().filter(|(s, _)| *s).count();
            if scientific > 0 && scientific < col.len() {
                problems.push(format!(
                    "a column mixes notations: {:?}",
                    col.iter().map(|(_, t)| t).collect::<Vec<_>>()
                ));
            }
        }
    };
    for line in markdown.lines() {
        // Outside code spans (claim ids such as `phodcos.table1.n16`).
        let prose: String = line.split('`').step_by(2).collect::<Vec<_>>().join(" ");
        for (token, _) in tokens(&prose).into_iter().filter(|(_, exact)| !exact) {
            let (significant, tiny_plain) = number::token_shape(&token);
            if significant > number::PROSE_DIGITS || tiny_plain {
                problems.push(format!("{token} in: {line}"));
            }
        }
        if !line.starts_with('|') {
            flush(&mut columns, &mut problems);
            in_ledger = false;
            continue;
        }
        let cells: Vec<&str> = line.trim_matches('|').split(" | ").map(str::trim).collect();
        if cells.iter().all(|c| c.chars().all(|ch| ch == '-')) {
            continue;
        }
        if columns.is_empty() {
            in_ledger = cells.starts_with(&["id", "location", "published", "reproduced"]);
            columns = vec![Vec::new(); cells.len()];
            continue;
        }
        if in_ledger {
            continue;
        }
        // The first column labels the row (its parameters are inputs as typed).
        for (k, cell) in cells.iter().enumerate().skip(1) {
            let bare = cell.trim_end_matches([' ', '✓', '≈', '✗']);
            if record.printed.contains(bare) {
                continue;
            }
            let found = tokens(bare);
            for (token, exact) in &found {
                if !exact && !record.formatted.contains(token) {
                    problems.push(format!(
                        "{token} (cell '{cell}') is not the formatter's: {line}"
                    ));
                }
            }
            // A single number in the cell, the formatter's (an integer count is not).
            if let [(single, exact)] = found.as_slice() {
                // Zero has no notation.
                if single != "0" && (!exact || record.formatted.contains(single)) {
                    if let Some(col) = columns.get_mut(k) {
                        col.push((single.contains('e'), single.clone()));
                    }
                }
            }
        }
    }
    flush(&mut columns, &mut problems);
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
