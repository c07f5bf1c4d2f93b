//! The coverage maps against the papers' texts: every numbered equation label a paper prints
//! has its own entry ("Eq. (N)") in the paper's map, and every claim a map names exists (the
//! second half also runs in the library's unit tests, without the texts).
//!
//! The texts are not part of the repository (`../shared/papers/<id>.txt`); without them this
//! test says so and passes, so a clone builds and tests on its own.

use std::collections::BTreeSet;
use std::path::Path;
use trajverify::papers::{self, coverage};

/// The equation labels of a paper's text: `\quad (N)` and `\tag{N}` in display math, and a
/// line that is only "(N)"; N is digits with an optional letter suffix or an appendix letter
/// prefix ("15a", "A1").
fn equation_labels(text: &str) -> BTreeSet<String> {
    let mut labels = BTreeSet::new();
    let is_label = |s: &str| {
        let core = s.trim_start_matches(|c: char| c.is_ascii_uppercase());
        !s.is_empty()
            && s.len() <= 5
            && core.starts_with(|c: char| c.is_ascii_digit())
            && core
                .trim_start_matches(|c: char| c.is_ascii_digit())
                .chars()
                .all(|c| c.is_ascii_lowercase())
            && s.chars().filter(|c| c.is_ascii_uppercase()).count() <= 1
    };
    let mut take = |after: &str, close: char| {
        if let Some(end) = after.find(close) {
            let inner = after[..end].trim();
            if is_label(inner) {
                labels.insert(inner.to_string());
            }
        }
    };
    for (marker, close) in [("\\quad (", ')'), ("\\qquad (", ')'), ("\\tag{", '}')] {
        let mut rest = text;
        while let Some(i) = rest.find(marker) {
            rest = &rest[i + marker.len()..];
            take(rest, close);
        }
    }
    for line in text.lines() {
        let t = line.trim();
        if t.starts_with('(') && t.ends_with(')') {
            take(&t[1..], ')');
        }
    }
    labels
}

#[test]
fn every_numbered_equation_of_every_paper_has_a_coverage_entry() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/papers");
    if !dir.is_dir() {
        eprintln!(
            "skipped: the papers' texts are not at {} (they are not part of the repository); the maps' claim ids are still \
             checked by the unit tests",
            dir.display()
        );
        return;
    }
    let mut missing = Vec::new();
    let mut found = 0;
    for paper in papers::all() {
        let Ok(text) = std::fs::read_to_string(dir.join(format!("{}.txt", paper.id))) else {
            eprintln!("skipped {}: no text", paper.id);
            continue;
        };
        let map = coverage::map(paper.short).unwrap_or_else(|e| panic!("{e}"));
        let labels: BTreeSet<&str> = map.entries.iter().map(|e| e.label.as_str()).collect();
        for n in equation_labels(&text) {
            found += 1;
            let label = format!("Eq. ({n})");
            if !labels.contains(label.as_str()) {
                missing.push(format!("{}: {label}", paper.short));
            }
        }
    }
    assert!(
        found > 150,
        "only {found} equation labels found in the texts"
    );
    assert!(
        missing.is_empty(),
        "numbered equations with no coverage entry:\n{}",
        missing.join("\n")
    );
}

#[test]
fn the_label_scan_finds_what_it_should() {
    let text = "$$x = 1 \\quad (12)$$\n$$y \\tag{15a}$$\n(26)\n$$z \\quad (A1)$$ and (not a label) \\quad (see 3)";
    let labels = equation_labels(text);
    assert_eq!(
        labels.into_iter().collect::<Vec<_>>(),
        vec!["12", "15a", "26", "A1"]
    );
}

/// The README's coverage table is the one the maps give (regenerate it with
/// `coverage::render::readme_table()` when a map changes), and its verdict counts per paper are those
/// of the committed ledger.
#[test]
fn the_readme_states_the_current_coverage_and_verdict_counts() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let readme = std::fs::read_to_string(root.join("README.md")).expect("README.md");
    let table = coverage::render::readme_table();
    assert!(
        readme.contains(&table),
        "README.md lacks the current coverage table:\n{table}"
    );
    let ledger: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(root.join("reports/claims.json")).expect("claims.json"),
    )
    .expect("claims.json parses");
    let claims = ledger["claims"].as_array().expect("a claims array");
    for paper in papers::all() {
        let of: Vec<&str> = claims
            .iter()
            .filter(|c| c["paper"] == paper.id)
            .filter_map(|c| c["verdict"].as_str())
            .collect();
        let counts: Vec<String> = papers::Verdict::ALL
            .iter()
            .filter_map(|v| {
                let n = of.iter().filter(|s| **s == v.as_str()).count();
                (n > 0).then(|| format!("{n} {}", v.as_str()))
            })
            .collect();
        let line = format!("{}: {}", of.len(), counts.join(", "));
        assert!(
            readme.contains(&line),
            "README.md lacks the verdict counts of {}: {line}",
            paper.short
        );
    }
    // The assurance sentence: "In the committed ledger N claims are exact, N proven by balls,
    // N certified and N rest on …".
    let count = |a: &str| claims.iter().filter(|c| c["assurance"] == a).count();
    let sentence = format!(
        "In the committed ledger {} claims are exact, {} proven by balls, {} certified and {} rest on",
        count("exact"),
        count("proven"),
        count("certified"),
        count("floating")
    );
    assert!(
        readme
            .split_whitespace()
            .collect::<Vec<_>>()
            .join(" ")
            .contains(&sentence),
        "README.md lacks the ledger's assurance counts: {sentence}"
    );
}

/// Issue 36: every claim that is only certified or floating says in its evidence why it is
/// not proven, with a reason its paper records (not the ledger's fallback).
#[test]
fn every_unproven_claim_says_why() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let ledger: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(root.join("reports/claims.json")).expect("claims.json"),
    )
    .expect("claims.json parses");
    for c in ledger["claims"].as_array().expect("a claims array") {
        let unproven = matches!(c["assurance"].as_str(), Some("certified" | "floating"));
        let evidence = c["evidence"].as_str().unwrap_or_default();
        if unproven && c["verdict"] != "failed" {
            assert!(
                evidence.contains("Not proven: ")
                    && !evidence.contains(trajverify::ledger::NO_REASON),
                "{} is {} without a recorded reason",
                c["id"],
                c["assurance"]
            );
        }
    }
}
