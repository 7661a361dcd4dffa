//! Behaviour 8.15: `run` writes its table and JSON as the run goes — the
//! JSON the binary streams is the object of the whole run made in this
//! process ([`RunView`]), member for member, and a run of many blocks needs
//! memory for one block's report, not for every block it executes.
#![cfg(not(target_arch = "wasm32"))]

use std::io::Write;
use std::process::{Command, Stdio};

use offsetlab::view::RunView;
use offsetlab::{Document, MachineKind, Setup};
use serde_json::Value;

fn temp_file(name: &str, content: &[u8]) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("offsetlab-stream-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, content).unwrap();
    p
}

/// The binary's `run` of a document, in `format`: its output and status.
fn binary_run(name: &str, doc: &Document, format: &str) -> (Vec<u8>, i32) {
    let setup = temp_file(&format!("{name}.json"), doc.to_json().as_bytes());
    let out = Command::new(env!("CARGO_BIN_EXE_offsetlab"))
        .args(["run", "--format", format, "--setup"])
        .arg(&setup)
        .output()
        .unwrap();
    (out.stdout, out.status.code().unwrap())
}

fn documents() -> Vec<(&'static str, Document)> {
    let mut square = Document {
        program: include_str!("data/seed000_square.nc").to_string(),
        ..Document::default()
    };
    square.setup.set_register("01=6").unwrap();

    // G10 sets a register twice in a loop (the summary keeps the last),
    // a macro loop with variables set, an arc, and a call of a library
    // program whose blocks read their text from the library.
    let mut macros = Document {
        program: "G90 G21 G00 X0 Y0\n#1 = 0\nWHILE [#1 LT 3] DO1\n#1 = #1 + 1\n\
                  G10 L12 P1 R[#1]\nG01 X[#1 * 10] F100.\nEND1\n\
                  G02 X40. Y10. R10.\nM98 P1002\nM30\n"
            .to_string(),
        ..Document::default()
    };
    macros
        .setup
        .programs
        .insert(1002, "O1002\nG01 Y20.\nG04 P500\nM99\n".to_string());

    let mut lathe = Document {
        setup: Setup {
            machine: MachineKind::Lathe,
            ..Setup::default()
        },
        program: "G50 X120. Z60.\nG00 T0108\nX50. Z3.\nG01 Z-20. F0.2\nG02 X60. Z-25. R5.\nM30\n"
            .to_string(),
        ..Document::default()
    };
    lathe.setup.set_register("08=X0.4,Z-0.2").unwrap();

    // Stops with an error half way: the blocks before it and the error.
    let error = Document {
        program: "G00 X0 Y0\nG01 X10. F100.\nG02 X20. R2.\nM30\n".to_string(),
        ..Document::default()
    };
    vec![
        ("square", square),
        ("macros", macros),
        ("lathe", lathe),
        ("error", error),
    ]
}

#[test]
fn behaviour8_15_the_streamed_json_is_the_whole_runs_object() {
    for (name, doc) in documents() {
        let run = offsetlab::run(&doc.program, &doc.setup);
        let whole = serde_json::to_value(RunView {
            run: &run,
            text: &doc.program,
        })
        .unwrap();
        let (out, status) = binary_run(name, &doc, "json");
        let streamed: Value = serde_json::from_slice(&out).unwrap_or_else(|e| {
            panic!("{name}: not JSON ({e}): {}", String::from_utf8_lossy(&out))
        });
        assert_eq!(status, i32::from(run.has_errors()), "{name}");
        for member in ["summary", "blocks", "moves", "events", "diagnostics"] {
            assert_eq!(streamed[member], whole[member], "{name}: {member}");
        }
        assert!(!whole["blocks"].as_array().unwrap().is_empty(), "{name}");
    }
}

#[test]
fn behaviour8_15_the_streamed_table_has_a_row_per_block_then_the_diagnostics() {
    for (name, doc) in documents() {
        let run = offsetlab::run(&doc.program, &doc.setup);
        let (out, _) = binary_run(name, &doc, "table");
        let text = String::from_utf8(out).unwrap();
        let mut lines = text.lines();
        assert!(lines.next().unwrap().starts_with(" LINE  BLOCK"), "{name}");
        let rows: Vec<&str> = lines.by_ref().take_while(|l| !l.is_empty()).collect();
        assert_eq!(rows.len(), run.blocks.len(), "{name}: {text}");
        for (row, b) in rows.iter().zip(&run.blocks) {
            assert!(
                row.trim_start().starts_with(&b.span.line.to_string()),
                "{name}: {row}"
            );
            assert!(row.ends_with(&b.explanation()), "{name}: {row}");
        }
        let diagnostics: Vec<&str> = lines.collect();
        assert_eq!(diagnostics.len(), run.diagnostics.len(), "{name}: {text}");
    }
}

/// The peak resident memory of a child, in KiB, read from /proc while it
/// runs (VmHWM only grows, so the last reading is its peak but for the
/// last instants).
#[cfg(target_os = "linux")]
fn peak_kib(mut child: std::process::Child) -> (u64, std::process::ExitStatus) {
    let status_file = format!("/proc/{}/status", child.id());
    let mut peak = 0;
    loop {
        if let Ok(s) = std::fs::read_to_string(&status_file)
            && let Some(line) = s.lines().find(|l| l.starts_with("VmHWM:"))
        {
            let kib: u64 = line.split_whitespace().nth(1).unwrap().parse().unwrap();
            peak = peak.max(kib);
        }
        if let Some(status) = child.try_wait().unwrap() {
            return (peak, status);
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
}

#[cfg(target_os = "linux")]
#[test]
fn behaviour8_15_a_long_macro_loop_under_run_needs_memory_for_one_block() {
    // 40 000 passes of a 3-block loop: 120 000 reports of about a
    // kilobyte of JSON each, written and dropped one by one. Kept, they
    // would take more than 100 MiB; streamed, the peak is the binary's own
    // size plus one report (the 5 000 000-block figure is in
    // docs/performance.md, `scripts/memory.sh`).
    let program = "G90 G21 G00 X0 Y0\n#1 = 0\nWHILE [#1 LT 40000] DO1\n#1 = #1 + 1\n\
                   G01 X[#1 MOD 100] Y1. F100.\nEND1\nM30\n";
    let path = temp_file("loop.nc", program.as_bytes());
    for format in ["json", "table"] {
        let mut child = Command::new(env!("CARGO_BIN_EXE_offsetlab"))
            .args(["run", "--format", format])
            .arg(&path)
            .stdout(Stdio::piped())
            .spawn()
            .unwrap();
        // Read and count the output on a thread while the child runs.
        let mut stdout = child.stdout.take().unwrap();
        let reader = std::thread::spawn(move || {
            let mut sink = Counter(0);
            std::io::copy(&mut stdout, &mut sink).unwrap();
            sink.0
        });
        let (peak, status) = peak_kib(child);
        let bytes = reader.join().unwrap();
        assert!(status.success(), "{format}");
        assert!(peak > 0, "{format}: no reading of the peak");
        assert!(bytes > 10_000_000, "{format}: {bytes} bytes");
        assert!(
            peak < 48 * 1024,
            "{format}: peak {peak} KiB for {bytes} bytes of output"
        );
    }
}

struct Counter(u64);

impl Write for Counter {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.0 += buf.len() as u64;
        Ok(buf.len())
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}
