//! The hostile corpus (`tests/data/hostile/`, see its README): every file
//! through `run` in this process, with a mill and a lathe setup, and through
//! the `offsetlab` binary (`check`, `run --format json`). No panic, bounded
//! time and moves, diagnostics with sane places, JSON without NaN, and
//! markup only ever inside JSON strings.
#![cfg(not(target_arch = "wasm32"))]

#[path = "../fuzz/common/mod.rs"]
mod fuzz_common;

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

use offsetlab::view::RunView;
use offsetlab::{MachineKind, RunOptions, Setup, run_with};
use serde_json::Value;

/// Moves a run in this process may record: the runaway cycle file reaches
/// it, and the binary's `check` runs it to the default limit.
const MAX_MOVES: usize = 50_000;

/// Time one file may take (debug build, both setups, the binary too), with
/// room for a loaded machine: a hang or a quadratic path takes far longer.
const TIME_LIMIT: Duration = Duration::from_secs(180);

fn corpus() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/hostile");
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_none_or(|e| e != "md"))
        .collect();
    files.sort();
    assert!(files.len() >= 25, "{files:?}");
    files
}

fn setups() -> [Setup; 2] {
    let mut mill = Setup::default();
    mill.set_register("01=6").unwrap();
    let mut lathe = Setup {
        machine: MachineKind::Lathe,
        ..Setup::default()
    };
    lathe.set_register("01=X0.4,Z-0.2").unwrap();
    [mill, lathe]
}

/// `<` and `>` appear only inside JSON strings (serde_json escapes nothing
/// else that a page could mistake for markup, so the page must render
/// strings as text; this pins that markup never leaks into the structure).
fn markup_only_in_strings(json: &str) {
    let mut in_string = false;
    let mut escaped = false;
    for (i, c) in json.char_indices() {
        if in_string {
            match (escaped, c) {
                (true, _) => escaped = false,
                (false, '\\') => escaped = true,
                (false, '"') => in_string = false,
                _ => {}
            }
        } else {
            match c {
                '"' => in_string = true,
                '<' | '>' => panic!("markup outside a string at byte {i}"),
                _ => {}
            }
        }
    }
    assert!(!in_string);
}

/// No number of the report is null (serde_json writes NaN and ∞ as null).
fn numbers_never_null(v: &Value, key: &str) {
    const NUMERIC: &[&str] = &[
        "x",
        "y",
        "z",
        "radius",
        "programmed_radius",
        "sweep_degrees",
        "value",
        "vector",
        "target",
        "seconds",
        "line",
        "column",
        "end_column",
    ];
    match v {
        Value::Null => assert!(!NUMERIC.contains(&key), "`{key}` is null"),
        Value::Number(n) => assert!(n.as_f64().is_some_and(f64::is_finite)),
        Value::Array(a) => a.iter().for_each(|x| numbers_never_null(x, key)),
        Value::Object(o) => o.iter().for_each(|(k, x)| numbers_never_null(x, k)),
        _ => {}
    }
}

fn check_json(json: &str, name: &str) -> Value {
    markup_only_in_strings(json);
    let v: Value = serde_json::from_str(json).unwrap_or_else(|e| panic!("{name}: {e}"));
    numbers_never_null(&v, "");
    v
}

#[test]
fn every_hostile_file_runs_in_process_within_the_limits() {
    for path in corpus() {
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        let bytes = std::fs::read(&path).unwrap();
        // What the page does with bytes: lossy UTF-8.
        let text = String::from_utf8_lossy(&bytes);
        for setup in setups() {
            let start = Instant::now();
            fuzz_common::check_run_with(&setup, &text, MAX_MOVES);
            let options = RunOptions {
                max_moves: MAX_MOVES,
                ..RunOptions::default()
            };
            let run = run_with(&text, &setup, options);
            assert!(run.move_count <= MAX_MOVES, "{name}");
            assert!(run.diagnostics.len() <= 1001, "{name}");
            let json = serde_json::to_string(&RunView {
                run: &run,
                text: &text,
            })
            .unwrap();
            check_json(&json, &name);
            assert!(
                start.elapsed() < TIME_LIMIT,
                "{name}: {:?}",
                start.elapsed()
            );
        }
    }
}

fn binary(args: &[&str]) -> std::process::Output {
    let out = Command::new(env!("CARGO_BIN_EXE_offsetlab"))
        .args(args)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!err.contains("panicked"), "{args:?}: {err}");
    out
}

#[test]
fn every_hostile_file_through_the_binary() {
    for path in corpus() {
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        let p = path.to_str().unwrap();
        let bytes = std::fs::read(&path).unwrap();
        let start = Instant::now();
        let check = binary(&["check", p]);
        match std::str::from_utf8(&bytes) {
            Err(e) => {
                assert_eq!(check.status.code(), Some(2), "{name}");
                let msg = String::from_utf8_lossy(&check.stderr);
                let want = format!("invalid byte at offset {}", e.valid_up_to());
                assert!(msg.contains(&want), "{name}: {msg}");
                continue;
            }
            Ok(_) => {
                let code = check.status.code();
                assert!(code == Some(0) || code == Some(1), "{name}: {code:?}");
            }
        }
        let report = String::from_utf8(check.stdout).unwrap();
        let mut lines: Vec<&str> = report.lines().collect();
        let summary = lines.pop().unwrap();
        assert!(summary.starts_with(&format!("{p}: ")), "{summary}");
        for line in lines {
            // FILE:LINE:COL: severity[code]: message
            let rest = line.strip_prefix(&format!("{p}:")).unwrap();
            let mut parts = rest.splitn(3, ':');
            let l: u32 = parts.next().unwrap().parse().unwrap();
            let c: u32 = parts.next().unwrap().parse().unwrap();
            let what = parts.next().unwrap();
            assert!(l >= 1 && c >= 1, "{name}: {line}");
            assert!(
                what.starts_with(" error[") || what.starts_with(" warning["),
                "{line}"
            );
        }
        // The whole JSON, except for the runaway cycle (5 million moves).
        if name != "deep-cycle-repeats.nc" {
            let out = binary(&["run", "--format", "json", p]);
            assert_eq!(out.status.code(), check.status.code(), "{name}");
            let v = check_json(&String::from_utf8(out.stdout).unwrap(), &name);
            assert_eq!(
                v["summary"]["errors"].as_u64() == Some(0),
                check.status.code() == Some(0)
            );
        }
        assert!(
            start.elapsed() < TIME_LIMIT,
            "{name}: {:?}",
            start.elapsed()
        );
    }
}

fn codes(name: &str) -> Vec<(&'static str, u32)> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/hostile")
        .join(name);
    let text = String::from_utf8_lossy(&std::fs::read(path).unwrap()).into_owned();
    let options = RunOptions {
        keep_blocks: false,
        keep_moves: false,
        ..RunOptions::default()
    };
    let run = run_with(&text, &setups()[0], options);
    run.diagnostics.iter().map(|d| (d.code, d.line)).collect()
}

#[test]
fn the_limits_stop_the_runaway_files_with_their_own_errors() {
    assert_eq!(codes("runaway-position.nc"), [("numeric-overflow", 10_002)]);
    assert_eq!(codes("deep-cycle-repeats.nc"), [("too-many-moves", 4)]);
    assert_eq!(codes("deep-cycle-pecks.nc"), [("cycle-pecks", 2)]);
    // One block of a megabyte: refused whole, its errors not read one by
    // one (behaviour 1.25).
    assert_eq!(codes("one-megabyte-line.nc"), [("block-too-long", 1)]);
    let nul = codes("nul-filled.bin");
    assert!(
        nul.iter()
            .all(|(c, l)| *c == "unexpected-character" && *l == 1)
    );
    assert_eq!(codes("percent-lines.nc"), [("text-after-tape-end", 3)]);
    assert!(codes("empty.nc").is_empty() && codes("only-blanks.nc").is_empty());
}

#[test]
fn markup_in_a_program_is_only_ever_text_in_the_json() {
    let text = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/hostile/markup.nc"),
    )
    .unwrap();
    let run = offsetlab::run(&text, &Setup::default());
    assert!(run.has_errors());
    let json = serde_json::to_string(&RunView {
        run: &run,
        text: &text,
    })
    .unwrap();
    markup_only_in_strings(&json);
    // The markup is carried as text in messages, never dropped or altered.
    let v: Value = serde_json::from_str(&json).unwrap();
    let messages: Vec<&str> = v["diagnostics"]
        .as_array()
        .unwrap()
        .iter()
        .map(|d| d["message"].as_str().unwrap())
        .collect();
    assert!(messages.iter().any(|m| m.contains('<')), "{messages:?}");
}

/// Messages show invisible characters escaped (`'\u{feff}'`, `'\u{200b}'`,
/// `'\u{1b}'`), so a byte order mark or a zero-width space is visible and a
/// bidirectional override cannot reorder the text a message is shown in.
#[test]
fn messages_carry_no_invisible_or_control_characters() {
    for path in corpus() {
        let bytes = std::fs::read(&path).unwrap();
        let text = String::from_utf8_lossy(&bytes);
        let run = offsetlab::run(&text, &Setup::default());
        for d in &run.diagnostics {
            let bad = d.message.chars().find(|&c| {
                c.is_ascii_control() || (!c.is_ascii() && c.escape_debug().nth(1).is_some())
            });
            assert!(
                bad.is_none(),
                "{}: {:?} in {}",
                path.display(),
                bad,
                d.message
            );
        }
    }
    // A byte order mark opening the text is an encoding mark, read as
    // nothing (behaviour 1.9); one anywhere else is a character shown escaped.
    let bom = codes("utf8-bom.nc");
    assert_eq!(bom, []);
    let run = offsetlab::run("G00 X1.\n\u{feff}G00 X2.", &Setup::default());
    assert!(
        run.diagnostics[0]
            .message
            .contains(r"'\u{feff}' (a byte order mark)")
    );
}
