//! The claims ledger's types: what a claim is before it is checked ([`ClaimSpec`]), the
//! result of a check ([`Outcome`]), a checked claim in the schema of `reports/claims.json`
//! ([`Claim`]) with its [`Verdict`], and the [`Ledger`] that joins outcomes with specs.
//!
//! This module sits below both the paper checks (`papers/`) and the renderers (`report/`):
//! checks produce these values, renderers read them, and neither imports the other's
//! internals through it (DESIGN.md, "Layers").
//!
//! Verdicts (DESIGN.md): `reproduced` — the computed value agrees with the printed one within
//! the precision printed, or the property holds to the stated digits; `discrepancy` — the
//! paper's own method, computed to certified precision, does not give what is printed (a
//! finding, with evidence); `failed` — something that must hold does not.

use serde::Serialize;

/// The verdict of one claim.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, PartialOrd, Ord)]
#[serde(rename_all = "lowercase")]
pub enum Verdict {
    Reproduced,
    Discrepancy,
    Failed,
}

impl Verdict {
    pub fn as_str(self) -> &'static str {
        match self {
            Verdict::Reproduced => "reproduced",
            Verdict::Discrepancy => "discrepancy",
            Verdict::Failed => "failed",
        }
    }

    /// `Reproduced` when `ok`, else `Failed`: for properties that must hold.
    pub fn holds(ok: bool) -> Verdict {
        if ok {
            Verdict::Reproduced
        } else {
            Verdict::Failed
        }
    }
}

/// What is known about a claim before it is checked.
#[derive(Clone, Copy, Debug)]
pub struct ClaimSpec {
    pub id: &'static str,
    pub location: &'static str,
    pub statement: &'static str,
    /// The value as printed, verbatim, or `None` for a property.
    pub published: Option<&'static str>,
}

/// One checked claim, in the schema of `reports/claims.json`.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct Claim {
    pub id: String,
    pub paper: String,
    pub location: String,
    pub statement: String,
    pub published: Option<String>,
    pub reproduced: String,
    pub scalar: String,
    pub verdict: Verdict,
    pub evidence: String,
}

/// The result of one check, before it is joined with its spec.
#[derive(Clone, Debug)]
pub struct Outcome {
    pub reproduced: String,
    pub scalar: String,
    pub verdict: Verdict,
    pub evidence: String,
}

impl Outcome {
    pub fn new(
        reproduced: impl Into<String>,
        scalar: impl Into<String>,
        verdict: Verdict,
        evidence: impl Into<String>,
    ) -> Self {
        Outcome {
            reproduced: reproduced.into(),
            scalar: scalar.into(),
            verdict,
            evidence: evidence.into(),
        }
    }
}

/// Collects the outcomes of one paper's checks against its spec table.
pub struct Ledger {
    paper: &'static str,
    specs: &'static [ClaimSpec],
    claims: Vec<Claim>,
}

impl Ledger {
    pub fn new(paper: &'static str, specs: &'static [ClaimSpec]) -> Self {
        Ledger {
            paper,
            specs,
            claims: Vec::new(),
        }
    }

    /// Record the outcome of the claim `id`. An id missing from the spec table, or recorded
    /// twice, becomes a `failed` claim (never a panic), and a test keeps the tables honest.
    pub fn record(&mut self, id: &str, outcome: Outcome) {
        let spec = self.specs.iter().find(|s| s.id == id);
        let duplicate = self.claims.iter().any(|c| c.id == id);
        let (verdict, evidence) = match (spec, duplicate) {
            (None, _) => (
                Verdict::Failed,
                format!(
                    "internal: claim id {id} is not in the spec table. {}",
                    outcome.evidence
                ),
            ),
            (Some(_), true) => (
                Verdict::Failed,
                format!(
                    "internal: claim id {id} recorded twice. {}",
                    outcome.evidence
                ),
            ),
            (Some(_), false) => (outcome.verdict, outcome.evidence),
        };
        self.claims.push(Claim {
            id: id.to_string(),
            paper: self.paper.to_string(),
            location: spec.map_or("", |s| s.location).to_string(),
            statement: spec.map_or("", |s| s.statement).to_string(),
            published: spec.and_then(|s| s.published).map(str::to_string),
            reproduced: outcome.reproduced,
            scalar: outcome.scalar,
            verdict,
            evidence,
        });
    }

    /// The claims in spec-table order; a spec never recorded becomes a `failed` claim.
    pub fn finish(mut self) -> Vec<Claim> {
        for spec in self.specs {
            if !self.claims.iter().any(|c| c.id == spec.id) {
                self.claims.push(Claim {
                    id: spec.id.into(),
                    paper: self.paper.into(),
                    location: spec.location.into(),
                    statement: spec.statement.into(),
                    published: spec.published.map(str::to_string),
                    reproduced: String::new(),
                    scalar: String::new(),
                    verdict: Verdict::Failed,
                    evidence: "internal: the check was never run".into(),
                });
            }
        }
        let order = |id: &str| {
            self.specs
                .iter()
                .position(|s| s.id == id)
                .unwrap_or(usize::MAX)
        };
        self.claims.sort_by_key(|c| order(&c.id));
        self.claims
    }
}

/// Everything one paper's verification produces.
pub struct PaperOutput {
    pub claims: Vec<Claim>,
    /// The Markdown report, `reports/<paper-id>.md`.
    pub markdown: String,
    /// SVG figures: (file name, contents), written next to the report.
    pub figures: Vec<(String, String)>,
}

/// A paper the project verifies.
pub struct Paper {
    /// The paper's id: its file stem in `papers/`.
    pub id: &'static str,
    /// The short name used in claim ids and accepted by `--paper`.
    pub short: &'static str,
    pub title: &'static str,
    pub specs: &'static [ClaimSpec],
    pub verify: fn() -> PaperOutput,
}
