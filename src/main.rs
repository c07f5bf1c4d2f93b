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

/// GMP's allocation functions, on mimalloc. GMP and MPFR call malloc, realloc and free of
/// the C library by default, which was a tenth of a `run dubins` in a profile; mimalloc
/// ignores the sizes GMP passes, so a size GMP reports loosely cannot matter.
mod gmp_allocation {
    use std::ffi::c_void;

    extern "C" fn allocate(size: usize) -> *mut c_void {
        // SAFETY: mi_malloc takes any size; GMP treats a null result as out of memory.
        unsafe { libmimalloc_sys::mi_malloc(size) }
    }

    extern "C" fn reallocate(ptr: *mut c_void, _old: usize, size: usize) -> *mut c_void {
        // SAFETY: ptr came from `allocate` or `reallocate` (installed before any GMP call).
        unsafe { libmimalloc_sys::mi_realloc(ptr, size) }
    }

    extern "C" fn free(ptr: *mut c_void, _size: usize) {
        // SAFETY: as for `reallocate`.
        unsafe { libmimalloc_sys::mi_free(ptr) }
    }

    /// Install the functions; must run before GMP or MPFR allocates anything, so that no
    /// block is freed by an allocator that did not make it.
    pub fn install() {
        // SAFETY: called first thing in main, before any GMP number exists.
        unsafe {
            gmp_mpfr_sys::gmp::set_memory_functions(Some(allocate), Some(reallocate), Some(free))
        }
    }
}

fn main() -> ExitCode {
    gmp_allocation::install();
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
