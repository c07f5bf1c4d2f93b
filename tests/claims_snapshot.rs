//! Every claim's id, verdict and reproduced value, pinned by an insta snapshot per paper in
//! `snapshots/`: any drift in any digit shows up in review.

use trajverify::papers::{self, Verdict};

fn snapshot_paper(short: &str) {
    let paper = papers::all()
        .into_iter()
        .find(|p| p.short == short)
        .expect("the paper is registered");
    let output = (paper.verify)();
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
