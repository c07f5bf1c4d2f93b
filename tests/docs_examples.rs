//! The command-line examples of the README and `docs/commands.md` are true: every line
//! `$ echo '…' | trajverify run …` (optionally piped into `jq`) is run as a user would, and what
//! it prints must be the lines that follow it in the document, byte for byte.
//!
//! `report convergence` examples are not run here (they write files into `docs/examples/`);
//! `.ci/run` regenerates the reports. Lines piped into `jq` are skipped, with a note, where jq
//! is not installed.

use std::process::Command;

/// Every example of `text`: the command line (after `$ `) and the output lines after it.
fn examples(text: &str) -> Vec<(String, String)> {
    let lines: Vec<&str> = text.lines().collect();
    let mut found = Vec::new();
    let mut i = 0;
    while i < lines.len() {
        let Some(command) = lines[i].strip_prefix("$ ") else {
            i += 1;
            continue;
        };
        let mut j = i + 1;
        while j < lines.len() && !lines[j].starts_with("$ ") && !lines[j].starts_with("```") {
            j += 1;
        }
        if command.contains("trajverify run") {
            found.push((command.to_string(), lines[i + 1..j].join("\n")));
        }
        i = j;
    }
    found
}

fn jq_installed() -> bool {
    Command::new("jq")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success())
}

#[test]
fn documented_run_examples_print_what_the_documents_show() {
    let root = env!("CARGO_MANIFEST_DIR");
    let binary = env!("CARGO_BIN_EXE_trajverify");
    let jq = jq_installed();
    let mut wrong = Vec::new();
    // The reader must find the examples each document has (a reader that finds none would
    // pass vacuously): the README's six, `docs/commands.md`'s thirteen.
    for (document, at_least) in [("README.md", 6), ("docs/commands.md", 13)] {
        let text = std::fs::read_to_string(format!("{root}/{document}")).expect("document");
        let found = examples(&text);
        assert!(
            found.len() >= at_least,
            "{document}: only {} examples found",
            found.len()
        );
        for (command, expected) in found {
            if command.contains("| jq") && !jq {
                println!("skipped (jq is not installed): {command}");
                continue;
            }
            let shell = command.replace("trajverify run", &format!("{binary} run"));
            let out = Command::new("sh")
                .arg("-c")
                .arg(&shell)
                .current_dir(root)
                .output()
                .expect("sh runs");
            let printed = format!(
                "{}{}",
                String::from_utf8_lossy(&out.stdout),
                String::from_utf8_lossy(&out.stderr)
            );
            if printed.trim_end() != expected.trim_end() {
                wrong.push(format!(
                    "{document}: {command}\n  documented: {expected}\n  printed:    {}",
                    printed.trim_end()
                ));
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn the_example_reader_finds_commands_and_their_output() {
    let text = "intro\n```sh\n$ echo '{}' | trajverify run hermite\n{\"a\":1}\n$ trajverify report x\n```\n";
    let found = examples(text);
    assert_eq!(found.len(), 1);
    assert_eq!(found[0].1, "{\"a\":1}");
}
