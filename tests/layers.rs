//! The one-way architecture, checked: every `crate::<module>` reference in the source (outside
//! comments) must point to a module allowed below it in the layer order of the README's Design
//! section. A new import that runs upwards (an algorithm using a claim, a renderer using a
//! paper's checks) fails this test and names the file and line.

use std::path::{Path, PathBuf};

/// The building blocks, in layer order (each uses only some of those before it).
const BUILDING_BLOCKS: &[&str] = &["scalar", "linalg", "poly", "quat", "quadrature", "curve"];
/// The algorithm modules: each may use every building block and none of the others.
const ALGORITHMS: &[&str] = &["hermite", "ph", "bspline", "gerbs", "param"];

/// The modules `module` may use, or `None` for a module missing from the layer order.
fn allowed(module: &str) -> Option<Vec<&'static str>> {
    Some(match module {
        "scalar" | "ledger" => vec![],
        "linalg" | "quat" | "quadrature" => vec!["scalar"],
        "poly" => vec!["scalar", "linalg"],
        "curve" => vec!["scalar", "linalg", "poly", "quat"],
        m if ALGORITHMS.contains(&m) => BUILDING_BLOCKS.to_vec(),
        "report" => vec!["scalar", "ledger"],
        "claims" => [BUILDING_BLOCKS, ALGORITHMS, &["ledger", "report"]].concat(),
        "cli" => [BUILDING_BLOCKS, ALGORITHMS, &["ledger", "report", "claims"]].concat(),
        _ => return None,
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

/// The top-level module a source file belongs to (`src/ph/hermite.rs` → `ph`).
fn module_of(src: &Path, file: &Path) -> Option<String> {
    let rel = file.strip_prefix(src).ok()?;
    let first = rel.components().next()?.as_os_str().to_str()?;
    let name = first.trim_end_matches(".rs");
    (name != "lib" && name != "main").then(|| name.to_string())
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
                let target: String = rest
                    .chars()
                    .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                    .collect();
                if rest.starts_with('{') {
                    violations.push(format!(
                        "{}:{}: write crate::<module>::… paths, one per module, so this check can read them",
                        file.display(),
                        n + 1
                    ));
                    continue;
                }
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
    // The scan above must recognise an upward reference: a line as an algorithm would write it.
    let line = "use crate::claims::Verdict;";
    let target: String = line["use crate::".len()..]
        .chars()
        .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
        .collect();
    let allowed = allowed("ph").unwrap();
    assert_eq!(target, "claims");
    assert!(!allowed.contains(&target.as_str()));
}
