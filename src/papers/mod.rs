//! The claims ledger: every published statement that computation can check.
//!
//! Each paper has a module with a static table of [`ClaimSpec`]s (id, location, statement,
//! printed value) and a `verify` function that runs the checks, records one [`Claim`] per
//! spec through a [`Ledger`], and returns the paper's Markdown report and figures.
//! `trajverify list` prints the specs without running anything.
//!
//! Verdicts (README, "Reading the ledger"; `docs/papers.md`): `reproduced` — the computed value agrees with the printed one within
//! the precision printed, or the property holds to the stated digits; `discrepancy` — the
//! paper's own method, computed to certified precision, does not give what is printed (a
//! finding, with evidence); `failed` — something that must hold does not.
//!
//! The folders carry the names of the algorithm folders they check (`papers::ph` checks
//! `algo::ph`, paper 001); the papers' short ids in claim ids (`phodcos.…`) are unchanged.

pub mod bspline;
pub mod coverage;
pub mod gerbs;
pub mod hermite;
pub mod param;
pub mod ph;
mod sample;

pub use crate::ledger::{Claim, ClaimSpec, Ledger, Outcome, Paper, PaperOutput, Verdict};

/// `outcome` with its finding (ledger policy, clause 7): what the paper prints, what is
/// computed (the outcome's reproduced text), how they differ, the severity and why.
pub fn found(
    outcome: Outcome,
    paper: &str,
    difference: &str,
    severity: crate::ledger::Severity,
    reason: &str,
) -> Outcome {
    let computed = outcome.reproduced.clone();
    outcome.finding((paper, &computed, difference), severity, reason)
}

/// The verdict of a printed garble whose one consistent reading another claim checks (policy
/// clause 3): `typo` when that check (`reading`) holds, `failed` when it could not be
/// computed, `discrepancy` when the reading itself fails.
pub fn typo_if_reading_holds(reading: &Outcome) -> Verdict {
    match reading.verdict {
        Verdict::Reproduced => Verdict::Typo,
        Verdict::Failed => Verdict::Failed,
        _ => Verdict::Discrepancy,
    }
}

/// A paper's output from its report `body`, `claims` and `figures`: the heading (title, id,
/// claim prefix, how to regenerate it) and the coverage section (from its map) around the
/// body, shared by the five renderers.
pub fn report_output(
    (id, short, title): (&str, &str, &str),
    body: String,
    claims: Vec<crate::ledger::Claim>,
    figures: Vec<(String, String)>,
) -> crate::ledger::PaperOutput {
    let heading = format!("# {title}\n\nPaper id `{id}`; claim ids start with `{short}.`. Regenerate with `trajverify verify` (every paper, into `reports/`), or this paper alone with `trajverify verify --paper {short} --out <dir>`.\n\n");
    crate::report::paper_output(
        heading,
        body,
        coverage::render::not_checked_section(short),
        claims,
        figures,
    )
}

/// The file name of figure `n` of paper `id`, written next to its report.
pub fn figure_file(id: &str, n: u32) -> String {
    format!("{id}_fig{n}.svg")
}

/// The papers verified so far, in id order.
pub fn all() -> Vec<Paper> {
    vec![
        hermite::paper(),
        ph::paper(),
        bspline::paper(),
        gerbs::paper(),
        param::paper(),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    const SPECS: &[ClaimSpec] = &[
        ClaimSpec {
            id: "x.a",
            location: "Eq. 1",
            statement: "a",
            published: None,
        },
        ClaimSpec {
            id: "x.b",
            location: "Eq. 2",
            statement: "b",
            published: Some("2"),
        },
    ];

    #[test]
    fn unknown_missing_and_duplicate_ids_fail() {
        let mut l = Ledger::new("p", SPECS);
        l.record(
            "x.b",
            Outcome::new("2", "rational", Verdict::Reproduced, "ok"),
        );
        l.record(
            "x.b",
            Outcome::new("2", "rational", Verdict::Reproduced, "ok"),
        );
        l.record("x.zzz", Outcome::new("", "", Verdict::Reproduced, ""));
        let claims = l.finish();
        assert_eq!(claims[0].id, "x.a");
        assert_eq!(claims[0].verdict, Verdict::Failed);
        assert_eq!(claims[1].verdict, Verdict::Reproduced);
        assert!(claims[2..].iter().all(|c| c.verdict == Verdict::Failed));
    }

    #[test]
    fn ids_are_unique_and_dotted_with_the_paper_short_name() {
        for paper in all() {
            let mut seen = std::collections::BTreeSet::new();
            for spec in paper.specs {
                assert!(seen.insert(spec.id), "duplicate id {}", spec.id);
                assert!(
                    spec.id.starts_with(&format!("{}.", paper.short)),
                    "{}",
                    spec.id
                );
            }
        }
    }
}
