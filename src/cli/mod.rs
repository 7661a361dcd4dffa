//! Command-line parsing (clap) and the two subcommands' output.

mod table;

use std::io::{self, BufWriter, Read, Write};
use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Args, Parser, Subcommand, ValueEnum};
use offsetlab::view::{RunView, summary};
use offsetlab::{MachineKind, RunOptions, Setup, run_with};

#[derive(Parser)]
#[command(
    name = "offsetlab",
    version,
    about = "CNC tool-offset interpreter: programmed and actual paths, block by block",
    long_about = None
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Run a program and print every block: programmed and actual position
    /// and what the offsets did.
    Run {
        #[command(flatten)]
        common: Common,
        /// Output format.
        #[arg(long, value_enum, default_value_t = Format::Table)]
        format: Format,
    },
    /// Check a program: diagnostics as FILE:LINE:COL and a one-line summary.
    Check {
        #[command(flatten)]
        common: Common,
    },
}

#[derive(Args)]
struct Common {
    /// Machine kind (overrides the setup file).
    #[arg(long, value_enum)]
    machine: Option<Machine>,
    /// One offset register: mill NN=VALUE (01=5.0), lathe NN=X<v>,Z<v>
    /// (08=X0.4,Z-0.2). Repeatable; applied after --setup.
    #[arg(long = "offset", value_name = "SPEC")]
    offsets: Vec<String>,
    /// Setup document (JSON; see the README).
    #[arg(long, value_name = "FILE")]
    setup: Option<PathBuf>,
    /// Program file, or - for standard input.
    #[arg(value_name = "PROGRAM")]
    program: String,
}

#[derive(Clone, Copy, ValueEnum)]
enum Machine {
    Mill,
    Lathe,
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
enum Format {
    Table,
    Json,
}

/// A failure that is the user's input or usage, not the program's: exit 2.
struct Fatal(String);

pub fn main() -> ExitCode {
    let cli = Cli::parse();
    match execute(cli) {
        Ok(code) => code,
        Err(Fatal(msg)) => {
            let _ = writeln!(io::stderr(), "offsetlab: {msg}");
            ExitCode::from(2)
        }
    }
}

fn execute(cli: Cli) -> Result<ExitCode, Fatal> {
    let (common, format) = match &cli.command {
        Command::Run { common, format } => (common, Some(*format)),
        Command::Check { common } => (common, None),
    };
    let setup = build_setup(common)?;
    let (name, text) = read_program(&common.program)?;
    let stdout = io::stdout();
    let mut out = BufWriter::new(stdout.lock());
    let result = match format {
        Some(format) => {
            let run = run_with(
                &text,
                &setup,
                RunOptions {
                    keep_blocks: true,
                    ..RunOptions::default()
                },
            );
            let written = match format {
                Format::Json => serde_json::to_writer(
                    &mut out,
                    &RunView {
                        run: &run,
                        text: &text,
                    },
                )
                .map_err(io::Error::from)
                .and_then(|_| writeln!(out)),
                Format::Table => table::write(&mut out, &run, &text),
            };
            (written, run.has_errors())
        }
        None => {
            let run = run_with(
                &text,
                &setup,
                RunOptions {
                    keep_blocks: false,
                    ..RunOptions::default()
                },
            );
            (check(&mut out, &name, &run), run.has_errors())
        }
    };
    let (written, errors) = result;
    match written.and_then(|_| out.flush()) {
        Ok(()) => {}
        // A closed pipe (`| head`) is the reader's choice, not a failure.
        Err(e) if e.kind() == io::ErrorKind::BrokenPipe => {}
        Err(e) => return Err(Fatal(format!("cannot write the output: {e}"))),
    }
    Ok(if errors {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    })
}

fn build_setup(common: &Common) -> Result<Setup, Fatal> {
    let mut setup = match &common.setup {
        Some(path) => {
            let text = std::fs::read_to_string(path)
                .map_err(|e| Fatal(format!("cannot read setup {}: {e}", path.display())))?;
            Setup::from_json(&text).map_err(|e| Fatal(format!("setup {}: {e}", path.display())))?
        }
        None => Setup::default(),
    };
    if let Some(m) = common.machine {
        setup.machine = match m {
            Machine::Mill => MachineKind::Mill,
            Machine::Lathe => MachineKind::Lathe,
        };
    }
    for spec in &common.offsets {
        setup.set_register(spec).map_err(Fatal)?;
    }
    setup.validated().map_err(|e| Fatal(e.to_string()))
}

/// Reads the program; `-` is standard input. Invalid UTF-8 is refused with
/// the offset of the first bad byte.
fn read_program(path: &str) -> Result<(String, String), Fatal> {
    let (name, bytes) = if path == "-" {
        let mut buf = Vec::new();
        io::stdin()
            .read_to_end(&mut buf)
            .map_err(|e| Fatal(format!("cannot read standard input: {e}")))?;
        ("<stdin>".to_string(), buf)
    } else {
        let bytes = std::fs::read(path).map_err(|e| Fatal(format!("cannot read {path}: {e}")))?;
        (path.to_string(), bytes)
    };
    let text = String::from_utf8(bytes).map_err(|e| {
        Fatal(format!(
            "{name} is not UTF-8 text: invalid byte at offset {}",
            e.utf8_error().valid_up_to()
        ))
    })?;
    Ok((name, text))
}

/// `check`: diagnostics as FILE:LINE:COL and one summary line.
fn check(out: &mut impl Write, name: &str, run: &offsetlab::Run) -> io::Result<()> {
    for d in &run.diagnostics {
        writeln!(
            out,
            "{name}:{}:{}: {}[{}]: {}",
            d.line,
            d.column,
            d.severity.as_str(),
            d.code,
            d.message
        )?;
    }
    let s = summary(run);
    let bounds = match s.bounds {
        Some(b) => {
            let dec = run.units.decimals();
            let mut parts = vec![format!("X{:.dec$}..{:.dec$}", b.min.x, b.max.x)];
            if let (Some(y0), Some(y1)) = (b.min.y, b.max.y) {
                parts.push(format!("Y{y0:.dec$}..{y1:.dec$}"));
            }
            parts.push(format!("Z{:.dec$}..{:.dec$}", b.min.z, b.max.z));
            format!("bounds {} {}", parts.join(" "), run.units.as_str())
        }
        None => "no motion".to_string(),
    };
    writeln!(
        out,
        "{name}: {} blocks, {} moves, {bounds}; {} errors, {} warnings",
        s.blocks, s.moves, s.errors, s.warnings
    )
}
