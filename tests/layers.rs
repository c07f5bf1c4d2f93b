//! The one-way architecture, checked: every `crate::<module>` reference in the source (outside
//! comments) must point to a module allowed below it in the layer order of `docs/design.md` ("Architecture")
//! section. A new import that runs upwards (an algorithm using a claim, a renderer using a
//! paper's checks) fails this test and names the file and line.

use std::path::{Path, PathBuf};

/// The building blocks, in layer order (each uses only some of those before it).
const BUILDING_BLOCKS: &[&str] = &[
    "scalar",
    "numeric::linalg",
    "numeric::poly",
    "numeric::quat",
    "numeric::quadrature",
    "numeric::krawczyk",
    "numeric::maximum",
    "curve",
];
/// The algorithm modules: each may use every building block and none of the others.
const ALGORITHMS: &[&str] = &[
    "algo::hermite",
    "algo::ph",
    "algo::bspline",
    "algo::gerbs",
    "algo::param",
];
/// Top-level folders whose children are separate modules of the layer table.
const GROUPS: &[&str] = &["algo", "numeric"];

/// The modules `module` may use, or `None` for a module missing from the layer order:
/// those of [`layer_allowed`] and `cancel`, the checkpoints of long loops, which is below
/// every layer and uses none.
fn allowed(module: &str) -> Option<Vec<&'static str>> {
    if module == "cancel" {
        return Some(vec![]);
    }
    let mut uses = layer_allowed(module)?;
    uses.push("cancel");
    Some(uses)
}

/// The modules of the layer order `module` may use, or `None` for a module missing from it.
fn layer_allowed(module: &str) -> Option<Vec<&'static str>> {
    Some(match module {
        "scalar" | "ledger" | "algo" | "numeric" => vec![],
        "numeric::linalg" | "numeric::quat" | "numeric::quadrature" | "numeric::maximum" => {
            vec!["scalar"]
        }
        "numeric::poly" | "numeric::krawczyk" => vec!["scalar", "numeric::linalg"],
        "curve" => vec![
            "scalar",
            "numeric::linalg",
            "numeric::poly",
            "numeric::quat",
            "numeric::quadrature",
            "numeric::krawczyk",
            "numeric::maximum",
        ],
        m if ALGORITHMS.contains(&m) => BUILDING_BLOCKS.to_vec(),
        // A study built on the algorithms (the PHODCOS and Hermite methods side by side).
        "algo::convergence" => [BUILDING_BLOCKS, ALGORITHMS].concat(),
        // Reports render the ledger, and the studies users run.
        "report" => vec!["scalar", "ledger", "algo::convergence"],
        "papers" => [BUILDING_BLOCKS, ALGORITHMS, &["ledger", "report"]].concat(),
        "cli" => [
            BUILDING_BLOCKS,
            ALGORITHMS,
            &["algo::convergence", "ledger", "report", "papers"],
        ]
        .concat(),
        _ => return None,
    })
}

/// The module named by the path after `crate::` (`algo::ph::hermite::X` → `algo::ph`), or
/// `None` when the path is a brace group (`crate::{…}` or `crate::algo::{…}`), which this check
/// cannot read.
fn target_of(rest: &str) -> Option<String> {
    let ident = |s: &str| -> String {
        s.chars()
            .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
            .collect()
    };
    if rest.starts_with('{') {
        return None;
    }
    let first = ident(rest);
    if !GROUPS.contains(&first.as_str()) {
        return Some(first);
    }
    let after = rest[first.len()..].strip_prefix("::").unwrap_or("");
    if after.starts_with('{') {
        return None;
    }
    let second = ident(after);
    Some(if second.is_empty() {
        first
    } else {
        format!("{first}::{second}")
    })
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir)
        .expect("readable source tree")
        .flatten()
    {
        let path = entry.path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The layer-table module a source file belongs to (`src/algo/ph/hermite.rs` → `algo::ph`,
/// `src/report/plot.rs` → `report`).
fn module_of(src: &Path, file: &Path) -> Option<String> {
    let rel = file.strip_prefix(src).ok()?;
    let mut parts = rel
        .components()
        .map(|c| c.as_os_str().to_str().unwrap_or("").trim_end_matches(".rs"));
    let first = parts.next()?;
    if first == "lib" || first == "main" {
        return None;
    }
    if GROUPS.contains(&first) {
        let second = parts.next()?;
        return Some(if second == "mod" {
            first.to_string()
        } else {
            format!("{first}::{second}")
        });
    }
    Some(first.to_string())
}

#[test]
fn no_import_runs_against_the_layer_order() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    files.sort();
    let mut violations = Vec::new();
    for file in &files {
        let Some(module) = module_of(&src, file) else {
            continue;
        };
        let Some(allowed) = allowed(&module) else {
            violations.push(format!(
                "{}: module {module} is not in the layer table",
                file.display()
            ));
            continue;
        };
        let text = std::fs::read_to_string(file).expect("readable");
        for (n, line) in text.lines().enumerate() {
            if line.trim_start().starts_with("//") {
                continue;
            }
            for (i, _) in line.match_indices("crate::") {
                let rest = &line[i + "crate::".len()..];
                let Some(target) = target_of(rest) else {
                    violations.push(format!(
                        "{}:{}: write crate::<module>::… paths, one per module, so this check can read them",
                        file.display(),
                        n + 1
                    ));
                    continue;
                };
                if target.is_empty() || target == module {
                    continue;
                }
                if !allowed.contains(&target.as_str()) {
                    violations.push(format!(
                        "{}:{}: {module} uses crate::{target}",
                        file.display(),
                        n + 1
                    ));
                }
            }
        }
    }
    assert!(
        violations.is_empty(),
        "imports against the layer order:\n{}",
        violations.join("\n")
    );
}

#[test]
fn the_check_sees_a_violation() {
    // The scan above must recognise an upward reference, as an algorithm would write it, and a
    // reference from one algorithm to another.
    let line = "use crate::papers::Verdict;";
    let target = target_of(&line["use crate::".len()..]).unwrap();
    assert_eq!(target, "papers");
    assert!(!allowed("algo::ph").unwrap().contains(&target.as_str()));
    let target = target_of("algo::gerbs::Knots;").unwrap();
    assert_eq!(target, "algo::gerbs");
    assert!(!allowed("algo::ph").unwrap().contains(&target.as_str()));
    assert!(allowed("papers").unwrap().contains(&target.as_str()));
    assert_eq!(target_of("algo::{ph, gerbs}"), None);
    let src = Path::new("/x/src");
    assert_eq!(
        module_of(src, Path::new("/x/src/algo/ph/hermite.rs")).as_deref(),
        Some("algo::ph")
    );
    assert_eq!(
        module_of(src, Path::new("/x/src/numeric/quat.rs")).as_deref(),
        Some("numeric::quat")
    );
}

/// `text` with comments, string literals and character literals blanked out (newlines kept),
/// so that braces and keywords can be counted on what is left.
fn code_only(text: &str) -> String {
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len());
    let blank = |c: char| if c == '\n' { '\n' } else { ' ' };
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let next = chars.get(i + 1).copied();
        if c == '/' && next == Some('/') {
            while i < chars.len() && chars[i] != '\n' {
                out.push(' ');
                i += 1;
            }
        } else if c == '/' && next == Some('*') {
            while i < chars.len() && !(chars[i] == '*' && chars.get(i + 1) == Some(&'/')) {
                out.push(blank(chars[i]));
                i += 1;
            }
            out.push_str("  ");
            i += 2;
        } else if c == '"' {
            out.push(' ');
            i += 1;
            while i < chars.len() && chars[i] != '"' {
                let skip = if chars[i] == '\\' { 2 } else { 1 };
                for k in 0..skip {
                    if let Some(&ch) = chars.get(i + k) {
                        out.push(blank(ch));
                    }
                }
                i += skip;
            }
            out.push(' ');
            i += 1;
        } else if c == '\'' && (chars.get(i + 2) == Some(&'\'') || next == Some('\\')) {
            // A character literal ('x' or '\n', '\''); a lifetime ('a) has no closing quote.
            let end = (i + 2..chars.len())
                .find(|&k| chars[k] == '\'' && (k > i + 2 || next != Some('\\')))
                .unwrap_or(i + 2);
            for _ in i..=end {
                out.push(' ');
            }
            i = end + 1;
        } else {
            out.push(c);
            i += 1;
        }
    }
    out
}

/// (name, first line, number of lines) of every function with a body in `code`.
fn function_lengths(code: &str) -> Vec<(String, usize, usize)> {
    let lines: Vec<&str> = code.lines().collect();
    let mut found = Vec::new();
    for (n, line) in lines.iter().enumerate() {
        let words: Vec<&str> = line
            .split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
            .collect();
        let Some(at) = words.iter().position(|w| *w == "fn") else {
            continue;
        };
        let Some(name) = words.get(at + 1).filter(|w| !w.is_empty()) else {
            continue; // a function-pointer type such as `fn() -> T`
        };
        // From the `fn` line: the first `{` opens the body unless a `;` ends a declaration.
        let (mut depth, mut opened) = (0i64, false);
        'scan: for (k, l) in lines.iter().enumerate().skip(n) {
            let start = if k == n {
                line.find("fn ").unwrap_or(0)
            } else {
                0
            };
            for ch in l[start..].chars() {
                match ch {
                    ';' if !opened => break 'scan,
                    '{' => {
                        depth += 1;
                        opened = true;
                    }
                    '}' => {
                        depth -= 1;
                        if opened && depth == 0 {
                            found.push((name.to_string(), n + 1, k - n + 1));
                            break 'scan;
                        }
                    }
                    _ => {}
                }
            }
        }
    }
    found
}

/// The longest function the house style allows (tables of published data are constants,
/// not functions, so they are not limited).
const MAX_FUNCTION_LINES: usize = 80;

#[test]
fn no_function_is_longer_than_eighty_lines() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    files.sort();
    let mut long = Vec::new();
    for file in &files {
        let text = std::fs::read_to_string(file).expect("readable");
        for (name, line, count) in function_lengths(&code_only(&text)) {
            if count > MAX_FUNCTION_LINES {
                long.push(format!(
                    "{}:{line}: fn {name} has {count} lines",
                    file.display()
                ));
            }
        }
    }
    assert!(
        long.is_empty(),
        "functions over {MAX_FUNCTION_LINES} lines:\n{}",
        long.join("\n")
    );
}

#[test]
fn the_length_check_counts_bodies_and_ignores_braces_in_text() {
    let code = code_only(
        "/// fn doc() {\nfn short(x: u8) -> u8 {\n    let s = \"{{\"; // }\n    let c = '{';\n    x\n}\ntrait T {\n    fn declared(&self);\n}\nstruct P { f: fn() -> u8 }\nfn generic<'a>(s: &'a str) -> &'a str {\n    s\n}\n",
    );
    assert_eq!(
        function_lengths(&code),
        vec![("short".to_string(), 2, 5), ("generic".to_string(), 11, 3)]
    );
}

/// What only a paper's renderers (`render.rs`, `figures.rs`) may use: Markdown tables and
/// sections, and plotting.
const RENDERING: &[&str] = &[
    "report::table",
    "report::plot",
    "report::{",
    "claims_section",
    "not_checked_section",
    "report_heading",
];

#[test]
fn paper_checks_return_data_and_only_renderers_draw() {
    let papers = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/papers");
    let mut files = Vec::new();
    rust_files(&papers, &mut files);
    files.sort();
    let mut violations = Vec::new();
    let mut renderers = 0;
    for file in &files {
        let name = file.file_name().and_then(|n| n.to_str()).unwrap_or("");
        if name == "render.rs" || name == "figures.rs" {
            renderers += 1;
            continue;
        }
        let code = code_only(&std::fs::read_to_string(file).expect("readable"));
        for (n, line) in code.lines().enumerate() {
            for pattern in RENDERING.iter().chain(&["md.push_str(", "Panel {"]) {
                if line.contains(pattern) && !file.ends_with("papers/mod.rs") {
                    violations.push(format!("{}:{}: {pattern}", file.display(), n + 1));
                }
            }
        }
    }
    assert_eq!(
        renderers, 11,
        "each of the five papers has render.rs and figures.rs, and the coverage maps their render.rs"
    );
    assert!(
        violations.is_empty(),
        "checks that write Markdown or draw:\n{}",
        violations.join("\n")
    );
}
