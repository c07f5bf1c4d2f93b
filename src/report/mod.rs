//! Turning checked claims into files: the ledger `claims.json`, one Markdown report per paper
//! and SVG figures (module [`plot`]).
//!
//! Output is deterministic: no timestamps, host names or timings, claims in spec order, and
//! figures drawn from values computed in MPFR or by IEEE basic operations only, so the same
//! bytes come out on every machine and thread count.

pub mod convergence;
pub mod number;
pub mod plot;

use crate::ledger::{Claim, PaperOutput, Verdict};
use serde::Serialize;
use std::path::Path;

#[derive(Serialize)]
struct Summary {
    total: usize,
    /// Claims per verdict, every verdict present (zero counts included).
    verdicts: serde_json::Map<String, serde_json::Value>,
    /// Claims per assurance (exact, proven, certified, floating), zero counts included.
    assurance: serde_json::Map<String, serde_json::Value>,
}

#[derive(Serialize)]
struct LedgerFile<'a> {
    summary: Summary,
    claims: &'a [Claim],
}

/// The number of claims of each verdict, in [`Verdict::ALL`] order (zero counts included).
pub fn counts(claims: &[Claim]) -> Vec<(Verdict, usize)> {
    Verdict::ALL
        .iter()
        .map(|&v| (v, claims.iter().filter(|c| c.verdict == v).count()))
        .collect()
}

/// The non-zero counts as text: "80 reproduced, 3 reproduced-rounding, 2 discrepancy".
pub fn counts_text(claims: &[Claim]) -> String {
    counts(claims)
        .iter()
        .filter(|(_, n)| *n > 0)
        .map(|(v, n)| format!("{n} {}", v.as_str()))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The contents of `claims.json`: a summary of counts by verdict and every claim.
pub fn ledger_json(claims: &[Claim]) -> String {
    let verdicts = counts(claims)
        .into_iter()
        .map(|(v, n)| (v.as_str().to_string(), serde_json::Value::from(n)))
        .collect();
    let assurance = crate::ledger::Assurance::ALL
        .iter()
        .map(|a| {
            let n = claims.iter().filter(|c| c.assurance == *a).count();
            (a.as_str().to_string(), serde_json::Value::from(n))
        })
        .collect();
    let file = LedgerFile {
        summary: Summary {
            total: claims.len(),
            verdicts,
            assurance,
        },
        claims,
    };
    // Serialising plain structs of strings cannot fail.
    let mut s = serde_json::to_string_pretty(&file).unwrap_or_default();
    s.push('\n');
    s
}

/// The opening summary of a paper report: the claims by verdict, then every finding that is
/// not a plain reproduction, one line each, the material ones (discrepancy, failed) first.
pub fn summary_section(claims: &[Claim]) -> String {
    let assurance: Vec<String> = crate::ledger::Assurance::ALL
        .iter()
        .map(|a| (a, claims.iter().filter(|c| c.assurance == *a).count()))
        .filter(|(_, n)| *n > 0)
        .map(|(a, n)| format!("{n} {}", a.as_str()))
        .collect();
    let mut out = format!(
        "## Summary\n\n{} claims: {}. Their numbers are {}.\n\n",
        claims.len(),
        counts_text(claims),
        assurance.join(", ")
    );
    let line = |c: &Claim| {
        number::shorten(
            &match &c.finding {
                Some(f) => format!(
                    "- **{}** `{}` ({}): paper: {}; computed: {}; {}\n",
                    c.verdict.as_str(),
                    c.id,
                    c.location,
                    f.paper,
                    f.computed,
                    f.difference
                ),
                None => format!(
                    "- **{}** `{}` ({}): {}\n",
                    c.verdict.as_str(),
                    c.id,
                    c.location,
                    c.reproduced
                ),
            },
            10,
        )
    };
    let severity = |c: &Claim| {
        c.finding
            .as_ref()
            .map(|f| f.severity)
            .unwrap_or(if c.verdict == Verdict::Failed {
                crate::ledger::Severity::Material
            } else {
                crate::ledger::Severity::Minor
            })
    };
    let findings: Vec<&Claim> = claims
        .iter()
        .filter(|c| c.verdict != Verdict::Reproduced)
        .collect();
    let (mut material, mut minor): (Vec<&Claim>, Vec<&Claim>) = findings
        .into_iter()
        .partition(|c| severity(c) == crate::ledger::Severity::Material);
    material.sort_by_key(|c| std::cmp::Reverse(c.verdict));
    minor.sort_by_key(|c| std::cmp::Reverse(c.verdict));
    if material.is_empty() {
        out.push_str("Material findings: none.\n\n");
    } else {
        out.push_str("Material findings (they change a conclusion the paper draws, or a formula a reader would implement):\n\n");
        out.extend(material.into_iter().map(line));
        out.push('\n');
    }
    if !minor.is_empty() {
        out.push_str(
            "Minor findings (rounding, metric, garbled print, data the paper does not give):\n\n",
        );
        out.extend(minor.into_iter().map(line));
        out.push('\n');
    }
    out
}

/// A Markdown table. Cells are escaped for `|` and line breaks.
pub fn table(headers: &[&str], rows: &[Vec<String>]) -> String {
    let esc = |s: &str| s.replace('|', "\\|").replace('\n', " ");
    let mut out = format!(
        "| {} |\n|{}\n",
        headers
            .iter()
            .map(|h| esc(h))
            .collect::<Vec<_>>()
            .join(" | "),
        "---|".repeat(headers.len())
    );
    for row in rows {
        out.push_str(&format!(
            "| {} |\n",
            row.iter().map(|c| esc(c)).collect::<Vec<_>>().join(" | ")
        ));
    }
    out
}

/// A paper's output: its `heading`, the summary of its claims, the report `body`, the
/// coverage section (what the paper states that no claim checks, from its coverage map) and
/// the claims table, with its figures.
pub fn paper_output(
    heading: String,
    body: String,
    coverage: String,
    claims: Vec<Claim>,
    figures: Vec<(String, String)>,
) -> PaperOutput {
    let mut markdown = heading;
    markdown.push_str(&summary_section(&claims));
    markdown.push_str(&shorten_prose(&body));
    markdown.push_str(&coverage);
    markdown.push_str(&claims_section(&claims));
    PaperOutput {
        claims,
        markdown,
        figures,
    }
}

/// `body` with every prose line's numbers at most ten significant digits and in the report
/// style ([`number::shorten`]); table rows are left as rendered, each cell having come from
/// the one formatter (which a test checks cell by cell).
fn shorten_prose(body: &str) -> String {
    body.split_inclusive('\n')
        .map(|line| {
            if line.starts_with('|') {
                line.to_string()
            } else {
                number::shorten(line, number::PROSE_DIGITS)
            }
        })
        .collect()
}

/// The ledger section of a paper report: every claim with its verdict and evidence.
pub fn claims_section(claims: &[Claim]) -> String {
    let rows: Vec<Vec<String>> = claims
        .iter()
        .map(|c| {
            vec![
                format!("`{}`", c.id),
                c.location.clone(),
                c.published.clone().unwrap_or_else(|| "—".into()),
                number::shorten(&c.reproduced, 10),
                c.scalar.clone(),
                c.assurance.as_str().to_string(),
                match &c.finding {
                    Some(f) => format!("**{}** ({})", c.verdict.as_str(), f.severity.as_str()),
                    None => format!("**{}**", c.verdict.as_str()),
                },
            ]
        })
        .collect();
    let mut out = String::from("## Claims ledger\n\n");
    out.push_str(&table(
        &[
            "id",
            "location",
            "published",
            "reproduced",
            "scalar",
            "assurance",
            "verdict",
        ],
        &rows,
    ));
    out.push_str("\n### Evidence\n\n");
    for c in claims {
        let severity = c.finding.as_ref().map_or(String::new(), |f| {
            format!(
                " Severity: {} — {}.",
                f.severity.as_str(),
                f.severity_reason
            )
        });
        out.push_str(&number::shorten(
            &format!(
                "- `{}` ({}) — {}: {}{severity}\n",
                c.id,
                c.verdict.as_str(),
                c.statement,
                c.evidence
            ),
            10,
        ));
    }
    out
}

/// Write every file, creating `dir` if needed. Each file goes to a temporary name first and
/// is renamed into place, so an interrupted run leaves either the old or the new file.
pub fn write_files(dir: &Path, files: &[(String, String)]) -> std::io::Result<()> {
    std::fs::create_dir_all(dir)?;
    for (name, contents) in files {
        let tmp = dir.join(format!(".{name}.tmp"));
        std::fs::write(&tmp, contents)?;
        std::fs::rename(&tmp, dir.join(name))?;
    }
    Ok(())
}
