//! The coverage map of each paper: every numbered equation (each sub-equation on its own),
//! theorem, lemma, corollary, remark, algorithm step, table column, figure and quantitative
//! sentence, mapped to the claims that check it or to the reason it is not checked.
//!
//! The maps are TOML files next to each paper's module (`papers/<subject>/coverage.toml`),
//! compiled into the binary. Each `[[entry]]` has a `label` as the paper numbers it ("Eq.
//! (15a)", "Theorem 1", "Table III, column 't_i^EX'"), a `kind`, `where` and `what`, and either
//! `claims` (ids of the claims that check it) or `not_checked` (why not). A test
//! (`tests/coverage.rs`) reads the papers' texts and fails when a numbered equation label has
//! no entry or an entry names a claim that does not exist; each report's "Not checked" section
//! and the README's coverage table are generated from the maps.

use serde::Deserialize;

pub mod render;

/// One numbered statement of a paper.
#[derive(Clone, Debug, Deserialize, PartialEq)]
pub struct Entry {
    /// How the paper numbers it: "Eq. (12)", "Theorem 1", "Fig. 3", …
    pub label: String,
    /// equation, theorem, lemma, corollary, proposition, remark, definition, algorithm-step,
    /// table-column, figure or sentence.
    pub kind: String,
    /// Where in the paper.
    #[serde(rename = "where")]
    pub place: String,
    /// What it says, briefly.
    pub what: String,
    /// The claims that check it.
    #[serde(default)]
    pub claims: Vec<String>,
    /// Why it is not checked (when no claim does).
    #[serde(default)]
    pub not_checked: Option<String>,
}

/// A paper's coverage map.
#[derive(Clone, Debug, Deserialize, PartialEq)]
pub struct Coverage {
    /// The paper's id.
    pub paper: String,
    /// Its entries, in the paper's order.
    #[serde(rename = "entry")]
    pub entries: Vec<Entry>,
}

/// The map of the paper with short name `short`, or why it could not be read (a map that
/// does not parse is a defect the coverage test reports; `verify` shows the error in the
/// report instead of panicking).
pub fn map(short: &str) -> Result<Coverage, String> {
    let text = match short {
        "hermite" => include_str!("../hermite/coverage.toml"),
        "phodcos" => include_str!("../ph/coverage.toml"),
        "bspline" => include_str!("../bspline/coverage.toml"),
        "gerbs" => include_str!("../gerbs/coverage.toml"),
        "marin" => include_str!("../param/coverage.toml"),
        other => return Err(format!("no coverage map for paper {other:?}")),
    };
    toml::from_str(text).map_err(|e| format!("the coverage map of {short} does not parse: {e}"))
}

/// Counts for the README: entries, checked by at least one claim, not checked.
pub fn counts(c: &Coverage) -> (usize, usize, usize) {
    let checked = c.entries.iter().filter(|e| !e.claims.is_empty()).count();
    (c.entries.len(), checked, c.entries.len() - checked)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_map_parses_names_its_paper_and_gives_a_reason_for_each_unchecked_entry() {
        for paper in crate::papers::all() {
            let c = map(paper.short).unwrap_or_else(|e| panic!("{e}"));
            assert_eq!(c.paper, paper.id);
            for e in &c.entries {
                assert!(
                    !e.claims.is_empty() || e.not_checked.as_ref().is_some_and(|r| !r.is_empty()),
                    "{}: {} has neither claims nor a reason",
                    paper.short,
                    e.label
                );
            }
        }
    }

    #[test]
    fn every_claim_named_exists_and_every_claim_is_named() {
        let mut problems = Vec::new();
        for paper in crate::papers::all() {
            let c = map(paper.short).unwrap_or_else(|e| panic!("{e}"));
            let named: std::collections::BTreeSet<&str> = c
                .entries
                .iter()
                .flat_map(|e| e.claims.iter().map(String::as_str))
                .collect();
            for id in &named {
                if !paper.specs.iter().any(|s| s.id == *id) {
                    problems.push(format!(
                        "{}: the coverage map names {id}, which is not a claim",
                        paper.short
                    ));
                }
            }
            for spec in paper.specs {
                if !named.contains(spec.id) {
                    problems.push(format!(
                        "{}: claim {} checks no entry of the coverage map",
                        paper.short, spec.id
                    ));
                }
            }
        }
        assert!(problems.is_empty(), "{}", problems.join("\n"));
    }
}
