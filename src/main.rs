//! The `trajverify` binary: see `trajverify --help` and the README.

use clap::Parser;
use std::io::Write;
use std::process::ExitCode;
use trajverify::cli::{execute, Cli};

fn main() -> ExitCode {
    let cli = Cli::parse(); // usage errors: clap prints them and exits with status 2
    match execute(cli) {
        Ok(text) => {
            let mut stdout = std::io::stdout().lock();
            // A closed pipe (e.g. `| head`) is not an error worth a panic.
            let _ = stdout.write_all(text.as_bytes());
            ExitCode::SUCCESS
        }
        Err(failure) => {
            eprintln!("error: {}", failure.message());
            ExitCode::from(failure.exit_code() as u8)
        }
    }
}
