//! offsetlab: a CNC tool-offset interpreter.
//!
//! It parses Fanuc/YASNAC-style G-code, runs it on a model mill or lathe with
//! a tool offset table, and reports for every block where the program says the
//! tool goes (the *programmed* path) and where it really goes (the *actual*
//! path) with the reason for every difference: tool length offset G43/G44/G49,
//! tool position offset G45–G48, and lathe T-code offsets.
//!
//! ```
//! use offsetlab::{Setup, run};
//!
//! let mut setup = Setup::default();
//! setup.set_register("01=6.0").unwrap();
//! let program = "G91 G00 G46 X30. Y20. D01;";
//! let result = run(program, &setup);
//! let block = &result.blocks[0];
//! assert_eq!(block.state.programmed, [30.0, 20.0, 0.0]);
//! assert_eq!(block.state.actual, [24.0, 14.0, 0.0]);
//! ```
#![deny(unsafe_code)]
#![warn(missing_docs)]

pub mod diag;
pub mod document;
pub mod export;
pub mod geometry;
pub mod machine;
pub mod macros;
pub mod offsets;
pub mod render;
pub mod report;
mod run;
pub mod session;
pub mod setup;
pub mod share;
pub mod syntax;
pub mod toolpath;
pub mod travel;
pub mod view;
#[cfg(target_arch = "wasm32")]
pub mod wasm;

pub use diag::{Diagnostic, Severity, Span};
pub use document::Document;
pub use machine::{Move, MoveKind};
pub use report::{BlockReport, End, Event, Place, Run};
pub use run::again::{Earlier, Reuse, Tail, rerun_observed};
#[cfg(not(target_arch = "wasm32"))]
pub use run::pipeline::{PIPELINE_FROM_BYTES, run_on_two_threads, run_pipelined};
pub use run::{
    Checkpoint, Checkpoints, MAX_BLOCKS, MAX_MOVES, Observer, Read, RunOptions, report_at, run,
    run_observed, run_with,
};
pub use setup::{MachineKind, Setup, Units};
pub use syntax::{ParseOptions, Program, parse};
pub use toolpath::Toolpath;
