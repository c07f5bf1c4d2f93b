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
