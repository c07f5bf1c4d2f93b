//! The `trajverify` binary: see `trajverify --help` and the README.

use clap::error::ErrorKind;
use clap::Parser;
use std::io::Write;
use std::process::ExitCode;
use std::time::Duration;
use trajverify::cli::{budget, execute, Cli, Command, Failure};

// mimalloc: `run` builds and frees hundreds of thousands of small values (JSON numbers,
// rationals, strings); glibc's allocator spent a fifth of an f64 run in page faults.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() -> ExitCode {
    budget::mark_start();
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => match e.kind() {
            // Help and version requests (and a bare `trajverify`) print as clap formats them.
            ErrorKind::DisplayHelp
            | ErrorKind::DisplayVersion
            | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => e.exit(),
            // Usage errors: clap's first line only, like every other input error.
            _ => {
                let text = e.render().to_string();
                eprintln!(
                    "{}",
                    text.lines().next().unwrap_or("error: invalid arguments")
                );
                return ExitCode::from(2);
            }
        },
    };
    // A `run` answers within its budget or is stopped (cli::budget::run_with_deadline).
    let result = if matches!(cli.command, Command::Run { .. }) {
        let deadline = Duration::from_secs_f64(budget::DEADLINE_SECONDS);
        budget::run_with_deadline(move || execute(cli), deadline)
            .unwrap_or_else(|message| Err(Failure::Usage(message)))
    } else {
        execute(cli)
    };
    match result {
        Ok(text) => {
            // A closed pipe (e.g. `| head`) is not worth a panic.
            let _ = std::io::stdout().lock().write_all(text.as_bytes());
            ExitCode::SUCCESS
        }
        Err(failure) => {
            eprintln!("error: {}", failure.message());
            ExitCode::from(failure.exit_code() as u8)
        }
    }
}
