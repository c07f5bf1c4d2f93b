//! The one-way architecture, checked: every `crate::<module>` reference in the source (outside
//! comments) must point to a module allowed below it in the layer order of the README's Design
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

/// The modules `module` may use, or `None` for a module missing from the layer order.
fn allowed(module: &str) -> Option<Vec<&'static str>> {
    Some(match module {
        "scalar" | "ledger" | "algo" | "numeric" => vec![],
        "numeric::linalg" | "numeric::quat" | "numeric::quadrature" => vec!["scalar"],
        "numeric::poly" => vec!["scalar", "numeric::linalg"],
        "curve" => vec![
            "scalar",
            "numeric::linalg",
            "numeric::poly",
            "numeric::quat",
        ],
        m if ALGORITHMS.contains(&m) => BUILDING_BLOCKS.to_vec(),
        "report" => vec!["scalar", "ledger"],
        "papers" => [BUILDING_BLOCKS, ALGORITHMS, &["ledger", "report"]].concat(),
        "cli" => [BUILDING_BLOCKS, ALGORITHMS, &["ledger", "report", "papers"]].concat(),
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
