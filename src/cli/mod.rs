//! Command-line parsing (clap) and the subcommands' output: `run`, `check`
//! and `link`.

mod library;
mod stream;
mod table;
mod tooltable;

use std::io::{self, BufWriter, Read, Write};
use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Args, Parser, Subcommand, ValueEnum};
use offsetlab::document::{ViewPlane, ViewState};
use offsetlab::setup::Control;
use offsetlab::share::{self, DEFAULT_BASE, LONG_LINK};
use offsetlab::view::{BlockViewer, summary};
use offsetlab::{Document, MachineKind, RunOptions, run_observed, run_pipelined, run_with};

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
    /// Print a share link carrying the program with its offsets and settings,
    /// or with --decode print the document a link carries.
    Link {
        #[command(flatten)]
        common: Common,
        /// The page the link opens (http or https).
        #[arg(long, value_name = "URL", default_value = DEFAULT_BASE)]
        base: String,
        /// Write the plain, hand-writable form (#program=…&offset=…) instead
        /// of the compact one (#v1.…).
        #[arg(long)]
        plain: bool,
        /// Open the page in embed mode (view, steps and a read-only editor).
        #[arg(long)]
        embed: bool,
        /// The block the page shows first (0 = the first executed block).
        #[arg(long, value_name = "N")]
        step: Option<u32>,
        /// The view plane: XY, XZ, YZ (mill), ZX or XC, the face view (lathe), or 3D (isometric; either).
        #[arg(long, value_name = "PLANE")]
        plane: Option<String>,
        /// Decode LINK (a URL, a #fragment or the fragment) and print its
        /// document as JSON instead.
        #[arg(long, value_name = "LINK", conflicts_with_all = ["program", "base", "plain", "embed", "step", "plane"])]
        decode: Option<String>,
    },
}

#[derive(Args)]
struct Common {
    /// Machine kind (overrides the setup file).
    #[arg(long, value_enum)]
    machine: Option<Machine>,
    /// Control profile: the defaults of the settings where controls differ
    /// (overrides the setup file's; settings the setup sets stay).
    #[arg(long, value_enum)]
    control: Option<ControlArg>,
    /// Continue past errors: a block that cannot run is reported and
    /// skipped, and the rest runs (setting continue_past_errors; the
    /// default stops at the first error, as a control does).
    #[arg(long = "continue")]
    keep_going: bool,
    /// One offset register: mill NN=VALUE (01=5.0), lathe NN=X<v>,Z<v>
    /// (08=X0.4,Z-0.2). Repeatable; applied after --setup.
    #[arg(long = "offset", value_name = "SPEC")]
    offsets: Vec<String>,
    /// One tool of the tool list: mill N=D<diameter>,L<length>
    /// (1=D10,L120), lathe N=R<nose radius>,T<tip>,L<length> (1=R0.8,T3).
    /// Repeatable; it draws the tool at its size, compensation still reads
    /// the registers.
    #[arg(long = "tool", value_name = "SPEC")]
    tools: Vec<String>,
    /// LinuxCNC's tool table file (`T1 P1 Z0.5 D0.25 ;note` a line), for
    /// the linuxcnc profile: T must name one of its tools, G43 reads its
    /// offsets, G41/G42 half its diameter (behaviour 22.9).
    #[arg(long = "tool-table", value_name = "FILE")]
    tool_table: Option<PathBuf>,
    /// The units of the tool table's lengths, a LinuxCNC machine's
    /// (its INI's LINEAR_UNITS); left out, the setup's.
    #[arg(long = "tool-table-units", value_enum, requires = "tool_table")]
    tool_table_units: Option<UnitsArg>,
    /// Setup document (JSON; see the README). A document that carries a
    /// program (as `link --decode` prints) may stand in for PROGRAM.
    #[arg(long, value_name = "FILE")]
    setup: Option<PathBuf>,
    /// A file of programs, or a folder of such files, for the setup's
    /// library (behaviour 9.10, 19.10): each program in it, by its O/:
    /// header, is there for M98/G65 to call. Repeatable; a file without a
    /// header is refused (in a folder: left out, and said).
    #[arg(long = "program", value_name = "FILE|DIR")]
    programs: Vec<PathBuf>,
    /// Program file, or - for standard input.
    #[arg(value_name = "PROGRAM")]
    program: Option<String>,
}

#[derive(Clone, Copy, ValueEnum)]
enum Machine {
    Mill,
    Lathe,
}

#[derive(Clone, Copy, ValueEnum)]
enum UnitsArg {
    Mm,
    Inch,
}

#[derive(Clone, Copy, ValueEnum)]
enum ControlArg {
    Yasnac,
    Fanuc,
    Haas,
    Linuxcnc,
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
    let stdout = io::stdout();
    let mut out = BufWriter::new(stdout.lock());
    let result = execute(cli, &mut out);
    let flushed = out.flush();
    match result.and_then(|code| match flushed {
        Ok(()) => Ok(code),
        Err(e) => written(Err(e)).map(|_| code),
    }) {
        Ok(code) => code,
        Err(Fatal(msg)) => {
            let _ = writeln!(io::stderr(), "offsetlab: {msg}");
            ExitCode::from(2)
        }
    }
}

/// Output errors: a closed pipe (`| head`) is the reader's choice, not a
/// failure; anything else is.
fn written(r: io::Result<()>) -> Result<(), Fatal> {
    match r {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == io::ErrorKind::BrokenPipe => Ok(()),
        Err(e) => Err(Fatal(format!("cannot write the output: {e}"))),
    }
}

/// A temporary file for the JSON's moves or events.
fn spill() -> Result<stream::Spill, Fatal> {
    stream::Spill::new().map_err(|e| Fatal(format!("cannot make a temporary file: {e}")))
}

fn exit(errors: bool) -> ExitCode {
    if errors {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}

fn execute(cli: Cli, out: &mut impl Write) -> Result<ExitCode, Fatal> {
    match cli.command {
        Command::Run { common, format } => {
            let (_, mut doc) = load(&common)?;
            folder_library(&common, &mut doc);
            let options = RunOptions {
                keep_blocks: true,
                keep_moves: false,
                ..RunOptions::default()
            };
            let output = match format {
                Format::Table => stream::Output::Table,
                Format::Json => stream::Output::Json {
                    moves: spill()?,
                    events: spill()?,
                },
            };
            let viewer = BlockViewer::new(&doc.program, &doc.setup.programs);
            let mut streamer = stream::Streamer::new(out, viewer, output, doc.setup.machine);
            let (mut run, _) = run_observed(&doc.program, &doc.setup, options, &mut streamer);
            written(streamer.finish(&mut run, &doc.program))?;
            Ok(exit(run.has_errors()))
        }
        Command::Check { common } => {
            let (name, mut doc) = load_setup(&common)?;
            let mapped = match &common.program {
                Some(path) => map_program(path)?,
                None => None,
            };
            let name = match mapped {
                Some(_) => name,
                None => program_into(&common, name, &mut doc)?,
            };
            let program = mapped.as_ref().map_or(doc.program.as_str(), Mapped::text);
            let options = RunOptions {
                keep_blocks: false,
                keep_moves: false,
                ..RunOptions::default()
            };
            let run = match &common.program {
                Some(path) => library::from_folder(path, program, &mut doc.setup, |t, s| {
                    run_program(t, s, options)
                }),
                None => None,
            }
            .unwrap_or_else(|| run_program(program, &doc.setup, options));
            written(check(out, &name, &run, program))?;
            Ok(exit(run.has_errors()))
        }
        Command::Link {
            common,
            base,
            plain,
            embed,
            step,
            plane,
            decode,
        } => {
            if let Some(link) = decode {
                let decoded = share::decode(&link).map_err(|e| Fatal(e.to_string()))?;
                if decoded.embed {
                    let _ = writeln!(io::stderr(), "offsetlab: the link opens in embed mode");
                }
                written(writeln!(out, "{}", decoded.document.to_json_pretty()))?;
                return Ok(ExitCode::SUCCESS);
            }
            let (_, mut doc) = load(&common)?;
            folder_library(&common, &mut doc);
            if let Some(p) = plane {
                let plane = ViewPlane::parse(&p).ok_or_else(|| {
                    Fatal(format!(
                        "--plane {p}: expected XY, XZ, YZ (mill), ZX or XC (lathe), or 3D"
                    ))
                })?;
                doc.view.get_or_insert_with(ViewState::default).plane = plane;
            }
            if step.is_some() {
                doc.step = step;
            }
            let doc = doc.validated().map_err(|e| Fatal(e.to_string()))?;
            share::check_base(&base).map_err(|e| Fatal(e.message))?;
            let text = if plain {
                format!("{base}#{}", share::encode_plain(&doc, embed))
            } else {
                share::link(&base, &doc, embed).map_err(|e| Fatal(e.message))?
            };
            if text.len() > LONG_LINK {
                let _ = writeln!(
                    io::stderr(),
                    "offsetlab: this link is {} characters; past {LONG_LINK} chat tools and some browsers may cut it — share the document file instead (offsetlab link --decode LINK > lesson.json)",
                    text.len()
                );
            }
            written(writeln!(out, "{text}"))?;
            Ok(ExitCode::SUCCESS)
        }
    }
}

/// The document a command works on: `--setup` (a setup document or a whole
/// document), `--machine` and `--offset` on top, and the program from
/// PROGRAM or, without it, from the document.
fn load(common: &Common) -> Result<(String, Document), Fatal> {
    let (name, mut doc) = load_setup(common)?;
    let name = program_into(common, name, &mut doc)?;
    Ok((name, doc))
}

/// Reads PROGRAM, when there is one, into the document of
/// [`load_setup`]; returns the name of the program read (else `name`).
fn program_into(common: &Common, name: String, doc: &mut Document) -> Result<String, Fatal> {
    let Some(path) = &common.program else {
        return Ok(name);
    };
    let (name, text) = read_program(path)?;
    doc.program = text;
    Ok(name)
}

/// [`load`] but for reading PROGRAM, when there is one: the caller reads
/// it (the name returned is then PROGRAM as given, and the document's
/// program is the setup document's).
fn load_setup(common: &Common) -> Result<(String, Document), Fatal> {
    let mut doc = match &common.setup {
        Some(path) => {
            // A document carries a program: twice the program limit for
            // its JSON escapes.
            let name = format!("setup {}", path.display());
            let file =
                std::fs::File::open(path).map_err(|e| Fatal(format!("cannot read {name}: {e}")))?;
            let text = read_text(&name, file, 2 * offsetlab::syntax::MAX_PROGRAM_BYTES)?;
            Document::from_json(&text)
                .map_err(|e| Fatal(format!("setup {}: {e}", path.display())))?
        }
        None => Document::default(),
    };
    if let Some(m) = common.machine {
        doc.setup.machine = match m {
            Machine::Mill => MachineKind::Mill,
            Machine::Lathe => MachineKind::Lathe,
        };
    }
    if let Some(c) = common.control {
        doc.setup.settings.control = match c {
            ControlArg::Yasnac => Control::Yasnac,
            ControlArg::Fanuc => Control::Fanuc,
            ControlArg::Haas => Control::Haas,
            ControlArg::Linuxcnc => Control::Linuxcnc,
        };
    }
    if common.keep_going {
        doc.setup.settings.continue_past_errors = true;
    }
    for spec in &common.offsets {
        doc.setup.set_register(spec).map_err(Fatal)?;
    }
    for spec in &common.tools {
        doc.setup.set_tool(spec).map_err(Fatal)?;
    }
    for path in &common.programs {
        library::library_into(path, &mut doc.setup.programs)?;
    }
    if let Some(path) = &common.tool_table {
        let mut table = tooltable::read_tool_table(path)?;
        table.units = common.tool_table_units.map(|u| match u {
            UnitsArg::Mm => offsetlab::Units::Mm,
            UnitsArg::Inch => offsetlab::Units::Inch,
        });
        doc.setup.tool_table = Some(table);
    }
    let doc = doc.validated().map_err(|e| Fatal(e.to_string()))?;
    let name = match &common.program {
        Some(path) => path.clone(),
        None if !doc.program.is_empty() => match &common.setup {
            Some(p) => p.display().to_string(),
            None => "<document>".to_string(),
        },
        None => {
            return Err(Fatal(
                "no PROGRAM given (a file, or - for standard input), and no program in the setup document"
                    .to_string(),
            ));
        }
    };
    Ok((name, doc))
}

/// The programs PROGRAM calls that sit in other files of its folder, into
/// the library (behaviour 19.13), found by a run without block reports:
/// made only for a program that calls one (M98, G65, G66).
fn folder_library(common: &Common, doc: &mut Document) {
    let Some(path) = &common.program else {
        return;
    };
    if !calls_a_program(&doc.program) {
        return;
    }
    let options = RunOptions {
        keep_blocks: false,
        keep_moves: false,
        ..RunOptions::default()
    };
    library::from_folder(path, &doc.program, &mut doc.setup, |t, s| {
        run_program(t, s, options)
    });
}

/// True if `text` holds M98, G65 or G66 (any case): a program that may
/// call another.
fn calls_a_program(text: &str) -> bool {
    text.as_bytes().windows(3).any(|w| {
        matches!(
            [w[0].to_ascii_uppercase(), w[1], w[2]],
            [b'M', b'9', b'8'] | [b'G', b'6', b'5'] | [b'G', b'6', b'6']
        )
    })
}

/// The run of `run` and `check`: a large program's parser on a thread of
/// its own, unless the environment says `OFFSETLAB_THREADS=1` (a machine
/// whose second core is busy, or a measure of the one-thread run).
fn run_program(text: &str, setup: &offsetlab::Setup, options: RunOptions) -> offsetlab::Run {
    if std::env::var_os("OFFSETLAB_THREADS").is_some_and(|v| v == "1") {
        run_with(text, setup, options)
    } else {
        run_pipelined(text, setup, options)
    }
}

/// A program file of at least this many bytes is mapped, not read.
const MAP_FROM_BYTES: u64 = 1 << 20;

/// A program file mapped into memory, its text checked to be UTF-8.
struct Mapped(memmap2::Mmap);

impl Mapped {
    fn text(&self) -> &str {
        // SAFETY: `map_program` checked these bytes to be UTF-8 (a file
        // changed by another program while it is checked is that
        // program's race, as for any tool that maps its input).
        #[allow(unsafe_code)]
        unsafe {
            std::str::from_utf8_unchecked(&self.0)
        }
    }
}

/// `check`'s program, when it is a regular file of [`MAP_FROM_BYTES`] or
/// more: mapped, not read (reading would copy a large program into memory
/// of its own: target 6 of `docs/performance.md`, the 1M-block `check`);
/// None for standard input and smaller files. The same refusals as
/// [`read_text`].
fn map_program(path: &str) -> Result<Option<Mapped>, Fatal> {
    if path == "-" {
        return Ok(None);
    }
    let file = std::fs::File::open(path).map_err(|e| Fatal(format!("cannot read {path}: {e}")))?;
    let meta = file
        .metadata()
        .map_err(|e| Fatal(format!("cannot read {path}: {e}")))?;
    if !meta.is_file() || meta.len() < MAP_FROM_BYTES {
        return Ok(None);
    }
    let limit = offsetlab::syntax::MAX_PROGRAM_BYTES;
    if meta.len() > limit as u64 {
        return Err(too_large(path, limit));
    }
    // SAFETY: the map is read only; see `Mapped::text` for a file changed
    // meanwhile.
    #[allow(unsafe_code)]
    let map = unsafe { memmap2::Mmap::map(&file) };
    let Ok(map) = map else {
        return Ok(None); // not mappable (a special file system): read it
    };
    if let Err(e) = std::str::from_utf8(&map) {
        return Err(not_utf8(path, e));
    }
    Ok(Some(Mapped(map)))
}

/// Reads the program; `-` is standard input.
fn read_program(path: &str) -> Result<(String, String), Fatal> {
    let limit = offsetlab::syntax::MAX_PROGRAM_BYTES;
    if path == "-" {
        let name = "<stdin>".to_string();
        let text = read_text(&name, io::stdin(), limit)?;
        return Ok((name, text));
    }
    let file = std::fs::File::open(path).map_err(|e| Fatal(format!("cannot read {path}: {e}")))?;
    Ok((path.to_string(), read_text(path, file, limit)?))
}

/// Reads UTF-8 text of at most `limit` bytes. Invalid UTF-8 is refused with
/// the offset of the first bad byte, and a longer input before it is read
/// whole (`/dev/zero` or an endless pipe would otherwise fill memory).
fn read_text(name: &str, reader: impl Read, limit: usize) -> Result<String, Fatal> {
    let mut bytes = Vec::new();
    reader
        .take(limit as u64 + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| Fatal(format!("cannot read {name}: {e}")))?;
    if bytes.len() > limit {
        return Err(too_large(name, limit));
    }
    String::from_utf8(bytes).map_err(|e| not_utf8(name, e.utf8_error()))
}

/// The refusal of an input over `limit` bytes.
fn too_large(name: &str, limit: usize) -> Fatal {
    Fatal(format!(
        "{name} is larger than {} MiB, the most offsetlab reads",
        limit / (1024 * 1024)
    ))
}

/// The refusal of an input that is not UTF-8, with its first bad byte.
fn not_utf8(name: &str, e: std::str::Utf8Error) -> Fatal {
    Fatal(format!(
        "{name} is not UTF-8 text: invalid byte at offset {}",
        e.valid_up_to()
    ))
}

/// `check`: diagnostics as FILE:LINE:COL and one summary line.
fn check(out: &mut impl Write, name: &str, run: &offsetlab::Run, text: &str) -> io::Result<()> {
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
    // A program stopped by errors may be for the other machine (behaviour
    // 1.24): say so once, with the option that runs it there. Only then is
    // the text looked at again (a look at its first 256 KiB, after the run:
    // the `check` of the 1M-block G41 file, docs/performance.md).
    let s = if run.has_errors() {
        summary(run).with_hint(text)
    } else {
        summary(run)
    };
    if let (true, Some(h)) = (run.has_errors(), &s.machine_hint) {
        let kind = h.machine.as_str();
        writeln!(
            out,
            "{name}: note: this program reads as a {kind} program ({}): try --machine {kind}",
            h.reasons.join("; ")
        )?;
    }
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
    let travel = travel_text(&s.travel, run.units);
    // Behaviour 2.24: how many blocks a run that continued past its errors
    // passed over (each listed above with its error).
    let skipped = match s.skipped {
        0 => String::new(),
        1 => ", 1 block skipped".to_string(),
        n => format!(", {n} blocks skipped"),
    };
    writeln!(
        out,
        "{name}: {} blocks, {} moves, {bounds}; {travel}; {} errors, {} warnings{skipped}",
        s.blocks, s.moves, s.errors, s.warnings
    )
}

/// The path length and the time estimate of `check`'s summary line
/// (behaviour 6.10): `path 120.000 mm (rapid 20.000, feed 100.000), time
/// 1 min 5.0 s`, and how many feed moves had no rate.
fn travel_text(t: &offsetlab::view::TravelView, units: offsetlab::Units) -> String {
    let dec = units.decimals();
    let mut text = format!(
        "path {:.dec$} {} (rapid {:.dec$}, feed {:.dec$}), time {}",
        t.rapid + t.feed,
        units.as_str(),
        t.rapid,
        t.feed,
        duration(t.seconds)
    );
    if t.untimed > 0 {
        text.push_str(&format!(
            " + {} feed move{} without a rate",
            t.untimed,
            if t.untimed == 1 { "" } else { "s" }
        ));
    }
    text
}

/// Seconds as `1 h 2 min 3.4 s`, `2 min 3.4 s` or `3.4 s`.
fn duration(seconds: f64) -> String {
    let tenths = (seconds * 10.0).round() as u64;
    let (h, rest) = (tenths / 36_000, tenths % 36_000);
    let (m, t) = (rest / 600, rest % 600);
    let s = format!("{}.{} s", t / 10, t % 10);
    match (h, m) {
        (0, 0) => s,
        (0, m) => format!("{m} min {s}"),
        (h, m) => format!("{h} h {m} min {s}"),
    }
}
