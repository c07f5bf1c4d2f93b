//! The claims ledger's types: what a claim is before it is checked ([`ClaimSpec`]), the
//! result of a check ([`Outcome`]), a checked claim in the schema of `reports/claims.json`
//! ([`Claim`]) with its [`Verdict`], and the [`Ledger`] that joins outcomes with specs.
//!
//! This module sits below both the paper checks (`papers/`) and the renderers (`report/`):
//! checks produce these values, renderers read them, and neither imports the other's
//! internals through it (DESIGN.md, "Layers").
//!
//! Verdicts ([`Verdict`], README "Reading the ledger"): `reproduced`, `reproduced-rounding`
//! (last printed digit), `metric` (agrees under the metric the paper's method uses),
//! `typo` (evidently garbled print, with the reading used), `undetermined` (the paper does not
//! give enough data), `discrepancy` (material: the paper's own method contradicts the printed
//! value) and `failed` (something that must hold does not).

use serde::Serialize;

/// The verdict of one claim: what kind of agreement or disagreement it is.
///
/// The order is by severity, from full agreement to a property that fails; a report lists
/// the material findings ([`Verdict::is_material`]) first.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, PartialOrd, Ord)]
pub enum Verdict {
    /// The computed value agrees with the printed one within half a unit of its last printed
    /// digit, or the property holds.
    #[serde(rename = "reproduced")]
    Reproduced,
    /// Agrees within one unit of the last printed digit but not within half a unit in some
    /// cells: a last-digit rounding difference; the evidence says how many cells.
    #[serde(rename = "reproduced-rounding")]
    ReproducedRounding,
    /// Agrees under the metric the paper's method actually uses (e.g. a maximum over a sample
    /// grid), which differs from the one it states; the evidence names both and gives both
    /// values.
    #[serde(rename = "metric")]
    Metric,
    /// A printed symbol or digit that is evidently garbled (in the paper or in its text
    /// extraction); the evidence gives the reading used and why it is the evident one.
    #[serde(rename = "typo")]
    Typo,
    /// The paper does not give enough data to decide; the evidence says what was assumed and
    /// what each reading gives.
    #[serde(rename = "undetermined")]
    Undetermined,
    /// Material: the paper's own method, computed to certified precision, contradicts the
    /// printed value.
    #[serde(rename = "discrepancy")]
    Discrepancy,
    /// Something that must hold does not (or the check did not run).
    #[serde(rename = "failed")]
    Failed,
}

impl Verdict {
    /// Every verdict, in severity order.
    pub const ALL: [Verdict; 7] = [
        Verdict::Reproduced,
        Verdict::ReproducedRounding,
        Verdict::Metric,
        Verdict::Typo,
        Verdict::Undetermined,
        Verdict::Discrepancy,
        Verdict::Failed,
    ];

    /// The verdict as written in claims.json and the reports.
    pub fn as_str(self) -> &'static str {
        match self {
            Verdict::Reproduced => "reproduced",
            Verdict::ReproducedRounding => "reproduced-rounding",
            Verdict::Metric => "metric",
            Verdict::Typo => "typo",
            Verdict::Undetermined => "undetermined",
            Verdict::Discrepancy => "discrepancy",
            Verdict::Failed => "failed",
        }
    }

    /// Whether the finding is material: the paper's content is wrong (`discrepancy`) or a
    /// property fails (`failed`), as opposed to rounding, metric, garbled print or missing
    /// data.
    pub fn is_material(self) -> bool {
        matches!(self, Verdict::Discrepancy | Verdict::Failed)
    }

    /// `Reproduced` when `ok`, else `Failed`: for properties that must hold.
    pub fn holds(ok: bool) -> Verdict {
        if ok {
            Verdict::Reproduced
        } else {
            Verdict::Failed
        }
    }

    /// The verdict of printed values compared with computed ones, from the largest
    /// difference in units of each value's last printed digit: within half a unit is
    /// `Reproduced` (the printed value is the rounded computed one), within one unit
    /// `ReproducedRounding` (the last digit differs), beyond that `Discrepancy`.
    pub fn by_printed_units(largest_units: f64) -> Verdict {
        if largest_units <= 0.5 {
            Verdict::Reproduced
        } else if largest_units <= 1.0 {
            Verdict::ReproducedRounding
        } else {
            Verdict::Discrepancy
        }
    }
}

/// What is known about a claim before it is checked.
#[derive(Clone, Copy, Debug)]
pub struct ClaimSpec {
    /// The claim id, `<paper short>.<location>.<name>`.
    pub id: &'static str,
    /// Where the claim is in the paper (equation, table, section).
    pub location: &'static str,
    /// What the paper states.
    pub statement: &'static str,
    /// The value as printed, verbatim, or `None` for a property.
    pub published: Option<&'static str>,
}

/// One checked claim, in the schema of `reports/claims.json`.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct Claim {
    /// The claim id.
    pub id: String,
    /// The paper id.
    pub paper: String,
    /// Where the claim is in the paper.
    pub location: String,
    /// What the paper states.
    pub statement: String,
    /// The value as printed, if the paper prints one.
    pub published: Option<String>,
    /// The value computed here.
    pub reproduced: String,
    /// The number type of the computation (e.g. `mpfr:256`, `rational`).
    pub scalar: String,
    /// How its numbers are known: exact, proven (ball), certified (two precisions) or
    /// floating (f64 alone).
    pub assurance: Assurance,
    /// The verdict.
    pub verdict: Verdict,
    /// The evidence for the verdict.
    pub evidence: String,
}

/// How the numbers behind a claim are known, from the number types its check ran in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, PartialOrd, Ord)]
#[serde(rename_all = "lowercase")]
pub enum Assurance {
    /// Exact arithmetic (rationals, Q(√2)): no rounding at all.
    Exact,
    /// Ball arithmetic: every number is proven to lie in its enclosure.
    Proven,
    /// MPFR at two precisions: the digits on which they agree (strong evidence, not a proof).
    Certified,
    /// f64 alone: no statement about its digits.
    Floating,
}

impl Assurance {
    /// Every assurance, strongest first.
    pub const ALL: [Assurance; 4] = [
        Assurance::Exact,
        Assurance::Proven,
        Assurance::Certified,
        Assurance::Floating,
    ];

    /// The strongest assurance a check's scalar field names: `rational` or `Q(sqrt2)` exact,
    /// `ball:` proven, `mpfr:` certified, otherwise floating.
    pub fn of_scalar(scalar: &str) -> Assurance {
        if scalar.contains("rational") || scalar.contains("Q(sqrt2)") {
            Assurance::Exact
        } else if scalar.contains("ball:") {
            Assurance::Proven
        } else if scalar.contains("mpfr:") {
            Assurance::Certified
        } else {
            Assurance::Floating
        }
    }

    /// The name used in claims.json and the reports.
    pub fn as_str(self) -> &'static str {
        match self {
            Assurance::Exact => "exact",
            Assurance::Proven => "proven",
            Assurance::Certified => "certified",
            Assurance::Floating => "floating",
        }
    }
}

/// The result of one check, before it is joined with its spec.
#[derive(Clone, Debug)]
pub struct Outcome {
    /// The value computed here.
    pub reproduced: String,
    /// The number type of the computation.
    pub scalar: String,
    /// The verdict.
    pub verdict: Verdict,
    /// The evidence for the verdict.
    pub evidence: String,
}

impl Outcome {
    /// An outcome from its four parts.
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
    /// An empty ledger for `paper` with these specs.
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
            assurance: Assurance::of_scalar(&outcome.scalar),
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
                    assurance: Assurance::Floating,
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
    /// The claims, in spec order.
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
    /// The paper's title.
    pub title: &'static str,
    /// Its claim specs.
    pub specs: &'static [ClaimSpec],
    /// Runs every check and builds the report.
    pub verify: fn() -> PaperOutput,
}
