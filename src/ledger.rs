//! The claims ledger's types: what a claim is before it is checked ([`ClaimSpec`]), the
//! result of a check ([`Outcome`]), a checked claim in the schema of `reports/claims.json`
//! ([`Claim`]) with its [`Verdict`] and, when it is not reproduced, its [`Finding`], and the
//! [`Ledger`] that joins outcomes with specs.
//!
//! This module sits below both the paper checks (`papers/`) and the renderers (`report/`):
//! checks produce these values, renderers read them, and neither imports the other's
//! internals through it (`docs/design.md`, "Architecture").
//!
//! # The verdict policy
//!
//! One policy for every claim (the README's "Reading the ledger" gives an example of each;
//! `tests/claims_snapshot.rs` checks the rules a test can decide):
//!
//! 1. **Provenance.** A claim computed on data or parameters the paper does not give —
//!    invented waypoints, strokes, landing or corner data, parameters other than the paper's —
//!    reproduces nothing of the paper: it is `illustrated`, and its evidence names each
//!    substitution.
//! 2. **By construction.** A check that holds by construction (a boundary condition the
//!    method imposes, an identity at the one point where both sides vanish) reproduces
//!    nothing: the claim tests the statement where it could fail, or is not a claim.
//! 3. **Typo or discrepancy.** An evident garble — the print differs from a consistent reading
//!    by one lost or swapped symbol (a sign, a conjugate mark, a factor, a pair of parentheses,
//!    an index offset, a digit, two exchanged factors or words), or by the same such edit at each place
//!    one quantity is printed — with one consistent reading that the paper itself fixes and on
//!    which no number the paper computes depends, is `typo`. Several independent edits (signs
//!    lost from four different vectors) are not one garble, and a wrong, added or missing word
//!    or phrase is not a symbol: where the paper's own numbers or method contradict the print,
//!    it is `discrepancy`; where the method poses both readings and nothing printed decides
//!    between them, clause 5 applies. A statement the paper's own method contradicts otherwise
//!    (a printed value, a formula that is wrong beyond one symbol, a claim about its results)
//!    is `discrepancy`.
//! 4. **Printed values.** Within half a unit of the last printed digit is `reproduced`,
//!    within one unit `reproduced-rounding`. A count has no last digit: it is equal
//!    (`reproduced`) or not (`discrepancy`), and what it counts is evaluated on computed
//!    values, never on the ranges the rounding of printed values allows.
//! 5. **Two readings.** A sentence that admits two readings is checked under both: both hold,
//!    `reproduced`; neither, `discrepancy`; exactly one, `undetermined` (the evidence gives
//!    both). `undetermined` also marks a statement the paper gives too little to decide.
//! 6. **Metric forensics.** A printed value that is not the true one is `metric` only when a
//!    member of a family of alternative metrics, declared before computing (for a sampled
//!    maximum: every count of equally spaced samples per segment in a declared range, and the
//!    grids of the authors' code and of common tools), reproduces it; the evidence names the
//!    member, how many cells it explains and how large the family is. A derived cell (a ratio
//!    of errors, an observed order) is compared with the same derivation of unrounded values of
//!    one definition, never of the printed cells. A table row is one claim: every cell within
//!    ½ (1) unit of the true values, `reproduced` (`reproduced-rounding`); else `metric` when
//!    one member gives every cell of the row within one unit; else `typo` when, under the true
//!    values or the table's best member, exactly one cell is off by one symbol other than its
//!    last digit and every later cell computed from it agrees; else `discrepancy`.
//! 7. **Severity.** Every claim not reproduced carries a [`Finding`]: what the paper printed,
//!    what is computed, how they differ (at most ten significant digits each), and its
//!    [`Severity`], `material` when it changes a conclusion the paper draws or a formula a
//!    reader would implement, `minor` otherwise, with the reason. Summaries list material
//!    findings first.
//! 8. **True evidence.** Evidence quotes the paper completely, and a criterion is the
//!    paper's, fixed before the computation, never tuned toward a printed number.
//!
//! # Assurance
//!
//! A claim's [`Assurance`] is the **weakest** of the number types its `scalar` names
//! ([`Assurance::of_scalar`]): `exact` (rationals, Q(√2)), `proven` (balls: a decision taken
//! on an enclosure — an upper bound below a criterion, a lower bound above it, a whole
//! enclosure within half a unit of a print), `certified` (two MPFR precisions that both ran
//! and agree), `floating` (f64, or one MPFR precision). Values shown beside the basis of the
//! verdict and not used by it are named in parentheses, which do not count
//! (`ball:256 (mpfr:128/256 shown)`: Table 1 of paper 001 is decided on enclosures and shows
//! the certified maxima). A check that cannot compute a number fails its claim with the error
//! ([`Outcome::failed`]), never a default.

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
    /// Computed on data or parameters the paper does not give (invented waypoints, strokes,
    /// landing data; parameters other than the paper's): it shows the method's behaviour on
    /// substituted data and reproduces nothing of the paper; the evidence names what was
    /// substituted.
    #[serde(rename = "illustrated")]
    Illustrated,
    /// The paper does not give enough data to decide, or a sentence has two readings of which
    /// exactly one holds; the evidence says what each reading gives.
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
    pub const ALL: [Verdict; 8] = [
        Verdict::Reproduced,
        Verdict::ReproducedRounding,
        Verdict::Metric,
        Verdict::Typo,
        Verdict::Illustrated,
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
            Verdict::Illustrated => "illustrated",
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
    /// How its numbers are known, the weakest of the number types `scalar` names: exact,
    /// proven (ball), certified (two MPFR precisions, both named) or floating (f64, or MPFR at
    /// one precision).
    pub assurance: Assurance,
    /// The verdict.
    pub verdict: Verdict,
    /// For a claim not reproduced: what the paper printed, what is computed, how they differ,
    /// and whether it is material or minor.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub finding: Option<Finding>,
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
    /// MPFR at two precisions, both named: the digits on which they agree (strong evidence,
    /// not a proof).
    Certified,
    /// Rounded arithmetic whose digits nothing checked: f64, or MPFR at one precision.
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

    /// The **weakest** assurance of the number types a check's scalar field names (its parts
    /// separated by commas or "and", remarks in parentheses ignored): `rational` or `Q(sqrt2)`
    /// exact, `ball:` proven, `mpfr:` certified only when the field names two MPFR precisions
    /// (`mpfr:128/256`, or `mpfr:128, mpfr:256`: a run at one precision checks nothing),
    /// anything else (f64) floating. A claim is labelled no stronger than its weakest number.
    pub fn of_scalar(scalar: &str) -> Assurance {
        // Q(sqrt2)'s own parentheses are not a remark.
        let mut text = String::new();
        let mut depth = 0usize;
        for c in scalar.replace("Q(sqrt2)", "Qsqrt2").chars() {
            match c {
                '(' => depth += 1,
                ')' => depth = depth.saturating_sub(1),
                _ if depth == 0 => text.push(c),
                _ => {}
            }
        }
        let mut precisions: Vec<&str> = text
            .split("mpfr:")
            .skip(1)
            .flat_map(|rest| {
                let end = rest
                    .find(|c: char| !c.is_ascii_digit() && c != '/')
                    .unwrap_or(rest.len());
                rest[..end].split('/').filter(|p| !p.is_empty())
            })
            .collect();
        precisions.sort_unstable();
        precisions.dedup();
        text.split(',')
            .flat_map(|part| part.split(" and "))
            .map(str::trim)
            .filter(|part| !part.is_empty())
            .map(|part| {
                if part.contains("rational") || part.contains("Qsqrt2") {
                    Assurance::Exact
                } else if part.contains("ball:") {
                    Assurance::Proven
                } else if part.contains("mpfr:") && precisions.len() >= 2 {
                    Assurance::Certified
                } else {
                    Assurance::Floating
                }
            })
            .max()
            .unwrap_or(Assurance::Floating)
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

/// How much a finding matters (every claim not reproduced carries one).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, PartialOrd, Ord)]
#[serde(rename_all = "lowercase")]
pub enum Severity {
    /// It changes a conclusion the paper draws, or a formula a reader would implement.
    Material,
    /// It does not.
    Minor,
}

impl Severity {
    /// The name used in claims.json and the reports.
    pub fn as_str(self) -> &'static str {
        match self {
            Severity::Material => "material",
            Severity::Minor => "minor",
        }
    }
}

/// A claim not reproduced, as its summary line states it: what the paper printed, what the
/// computation gives, how they differ (each in at most ten significant digits), and how much
/// it matters.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct Finding {
    /// What the paper printed or states.
    pub paper: String,
    /// What the computation gives.
    pub computed: String,
    /// How they differ.
    pub difference: String,
    /// Material or minor.
    pub severity: Severity,
    /// Why that severity.
    pub severity_reason: String,
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
    /// For a claim not reproduced: its finding.
    pub finding: Option<Finding>,
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
            finding: None,
        }
    }

    /// A check that could not compute a number it needs: the claim fails, with the error as
    /// its evidence (never a default standing in for the number).
    pub fn failed(scalar: impl Into<String>, error: impl std::fmt::Display) -> Self {
        Outcome::new(
            "",
            scalar,
            Verdict::Failed,
            format!("the check could not compute its numbers: {error}"),
        )
    }

    /// The same outcome with another verdict (a policy clause applied after the check).
    pub fn with_verdict(mut self, verdict: Verdict) -> Self {
        self.verdict = verdict;
        self
    }

    /// The same outcome with its finding: what the paper printed, what is computed, how they
    /// differ, and the severity with its reason.
    pub fn finding(
        mut self,
        (paper, computed, difference): (&str, &str, &str),
        severity: Severity,
        reason: &str,
    ) -> Self {
        self.finding = Some(Finding {
            paper: paper.into(),
            computed: computed.into(),
            difference: difference.into(),
            severity,
            severity_reason: reason.into(),
        });
        self
    }
}

/// One row of a paper's policy table: the claim, the verdict the policy gives it (`None`:
/// the check's own), what the paper prints, how the computation differs, the severity and why.
pub type Amendment = (
    &'static str,
    Option<Verdict>,
    &'static str,
    &'static str,
    Severity,
    &'static str,
);

/// Collects the outcomes of one paper's checks against its spec table.
pub struct Ledger {
    paper: &'static str,
    specs: &'static [ClaimSpec],
    claims: Vec<Claim>,
    /// Why a claim is not yet exact or proven, by claim id ([`Ledger::explain_unproven`]).
    unproven: &'static [(&'static str, &'static str)],
}

impl Ledger {
    /// An empty ledger for `paper` with these specs.
    pub fn new(paper: &'static str, specs: &'static [ClaimSpec]) -> Self {
        Ledger {
            paper,
            specs,
            claims: Vec::new(),
            unproven: &[],
        }
    }

    /// Why each claim that is only certified or floating is not proven (id, reason): at
    /// [`Ledger::finish`] each such claim's evidence ends with "Not proven: …", and one with no
    /// reason listed says so (a test keeps that from happening).
    pub fn explain_unproven(&mut self, reasons: &'static [(&'static str, &'static str)]) {
        self.unproven = reasons;
    }

    /// Record the outcome of the claim `id`. An id missing from the spec table, or recorded
    /// twice, becomes a `failed` claim (never a panic), and a test keeps the tables honest.
    pub fn record(&mut self, id: &str, outcome: Outcome) {
        // Between claims, `verify` may stop (the Python package's Ctrl-C).
        crate::cancel::checkpoint();
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
            finding: outcome.finding,
            evidence,
        });
    }

    /// Apply a paper's policy table: each claim whose check did not reproduce (or whose
    /// verdict the table changes) gets its finding; a reproduced claim is left alone, so a
    /// finding never outlives the discrepancy it describes (clause 7).
    pub fn apply(&mut self, amendments: &[Amendment]) {
        for &(id, verdict, paper, difference, severity, reason) in amendments {
            if verdict.is_some()
                || self
                    .verdict_of(id)
                    .is_some_and(|v| v != Verdict::Reproduced)
            {
                self.amend(id, verdict, (paper, difference), severity, reason);
            }
        }
    }

    /// The verdict recorded for `id` so far, if any.
    pub fn verdict_of(&self, id: &str) -> Option<Verdict> {
        self.claims.iter().find(|c| c.id == id).map(|c| c.verdict)
    }

    /// Apply the verdict policy to a claim already recorded: a new verdict, if the policy's
    /// clause changes it, and its finding (what the paper prints, how the computed value —
    /// the claim's reproduced text — differs, the severity and why). An unknown id is a
    /// `failed` claim of its own, never a panic.
    pub fn amend(
        &mut self,
        id: &str,
        verdict: Option<Verdict>,
        (paper, difference): (&str, &str),
        severity: Severity,
        reason: &str,
    ) {
        match self.claims.iter_mut().find(|c| c.id == id) {
            Some(claim) => {
                if let Some(v) = verdict {
                    claim.verdict = v;
                }
                claim.finding = Some(Finding {
                    paper: paper.into(),
                    computed: claim.reproduced.clone(),
                    difference: difference.into(),
                    severity,
                    severity_reason: reason.into(),
                });
            }
            None => self.record(
                id,
                Outcome::new(
                    "",
                    "",
                    Verdict::Failed,
                    format!("internal: amended before it was recorded: {reason}"),
                ),
            ),
        }
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
                    finding: None,
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
        for claim in &mut self.claims {
            if claim.assurance >= Assurance::Certified && claim.verdict != Verdict::Failed {
                let reason = self
                    .unproven
                    .iter()
                    .find(|(id, _)| *id == claim.id)
                    .map_or(NO_REASON, |(_, why)| why);
                // A sentence of its own, after the evidence's last one.
                let stop = if claim.evidence.trim_end().ends_with('.') {
                    ""
                } else {
                    "."
                };
                claim.evidence =
                    format!("{}{stop} Not proven: {reason}.", claim.evidence.trim_end());
            }
        }
        self.claims
    }
}

/// What the evidence of a certified or floating claim says when its paper lists no reason.
pub const NO_REASON: &str = "no reason recorded";

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

#[cfg(test)]
mod tests {
    use super::Assurance::{self, *};

    #[test]
    fn assurance_is_the_weakest_number_type_named() {
        let cases = [
            ("rational", Exact),
            ("Q(sqrt2)", Exact),
            ("rational, Q(sqrt2)", Exact),
            ("rational (inertia)", Exact),
            ("ball:256", Proven),
            (
                "ball:inertia (exact brackets, MPFR ends rounded outward)",
                Proven,
            ),
            ("mpfr:128/256", Certified),
            ("mpfr:128, mpfr:256", Certified),
            ("mpfr:128/256 and Q(sqrt2)", Certified),
            ("rational, mpfr:128, mpfr:256", Certified),
            // One precision checks nothing: as unchecked as f64.
            ("mpfr:256", Floating),
            ("rational, mpfr:256", Floating),
            ("mpfr:128, ball:256", Floating),
            ("f64, mpfr:128/256", Floating),
            (
                "f64 (search), mpfr:128/256 (the maximum and its t)",
                Floating,
            ),
            ("f64 (splines on certified knots)", Floating),
            ("", Floating),
        ];
        for (scalar, expected) in cases {
            assert_eq!(Assurance::of_scalar(scalar), expected, "{scalar}");
        }
    }
}
