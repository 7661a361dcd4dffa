//! The `offsetlab` command: run or check a program natively with the same
//! core the page uses.
//!
//! Exit status: 0 no error diagnostic, 1 an error diagnostic, 2 bad usage or
//! unreadable input (with a message on standard error).

#[cfg(not(target_arch = "wasm32"))]
mod cli;

#[cfg(not(target_arch = "wasm32"))]
fn main() -> std::process::ExitCode {
    cli::main()
}

#[cfg(target_arch = "wasm32")]
fn main() {}
