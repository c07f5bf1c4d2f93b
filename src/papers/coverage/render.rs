//! The coverage maps rendered: the README's coverage table and each report's "Coverage and
//! what is not checked" section.

use super::{counts, map, Entry};

/// The README's coverage table: per paper, the statements its map lists, how many claims
/// check, and how many are not checked (definitions among them). `tests/coverage.rs` fails
/// when the README's table differs from this.
pub fn readme_table() -> String {
    let mut md = String::from(
        "| paper | statements in the map | checked by claims | not checked (of which definitions) |\n|---|---|---|---|\n",
    );
    for paper in crate::papers::all() {
        let Ok(c) = map(paper.short) else {
            md.push_str(&format!("| `{}` | map does not parse | | |\n", paper.short));
            continue;
        };
        let (total, checked, unchecked) = counts(&c);
        let definitions = c
            .entries
            .iter()
            .filter(|e| e.claims.is_empty() && e.kind == "definition")
            .count();
        md.push_str(&format!(
            "| `{}` | {total} | {checked} | {unchecked} ({definitions}) |\n",
            paper.short
        ));
    }
    md
}

/// The report's "Not checked" section from the map: every entry no claim checks, with its
/// reason; definitions (which state nothing to check) are listed together at the end.
pub fn not_checked_section(short: &str) -> String {
    let c = match map(short) {
        Ok(c) => c,
        Err(e) => return format!("## Not checked\n\n{e}\n\n"),
    };
    let (total, checked, unchecked) = counts(&c);
    let mut md = format!(
        "## Coverage and what is not checked\n\nThe coverage map (`src/papers/*/coverage.toml`) lists {total} numbered statements \
         of the paper — every numbered equation and sub-equation, theorem, lemma, remark, algorithm step, table column, figure \
         and quantitative sentence: {checked} are checked by claims, {unchecked} are not. Those not checked, and why:\n\n"
    );
    let (definitions, others): (Vec<&Entry>, Vec<&Entry>) = c
        .entries
        .iter()
        .filter(|e| e.claims.is_empty())
        .partition(|e| e.kind == "definition");
    for e in &others {
        md.push_str(&format!(
            "- **{}** ({}): {} — {}\n",
            e.label,
            e.place,
            e.what,
            e.not_checked.as_deref().unwrap_or("no reason given")
        ));
    }
    if !definitions.is_empty() {
        let labels: Vec<&str> = definitions.iter().map(|e| e.label.as_str()).collect();
        md.push_str(&format!(
            "- **Definitions** ({}): {} — notation the checked statements use; a definition states nothing to check on its own\n",
            labels.len(),
            labels.join("; ")
        ));
    }
    md.push('\n');
    md
}
