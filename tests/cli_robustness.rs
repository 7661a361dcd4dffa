//! The command line on input nobody should give it (issue 7, item 6):
//! binary data, invalid UTF-8, empty input, a 50 MB program, a reader that
//! closes the pipe early, errors in JSON mode, unreadable paths and bad
//! usage. Every case ends with a message and the documented exit status
//! (0 no error, 1 an error diagnostic, 2 bad usage or unreadable input),
//! never with a panic trace.
#![cfg(not(target_arch = "wasm32"))]

#[path = "../benches/programs.rs"]
mod programs;

use std::io::{BufRead, BufReader, Write};
use std::path::PathBuf;
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

use serde_json::Value;

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_offsetlab"))
}

/// Runs the binary with `stdin` and checks it never printed a panic.
fn offsetlab(args: &[&str], stdin: &[u8]) -> Output {
    let mut child = bin()
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("binary runs");
    let mut input = child.stdin.take().unwrap();
    let data = stdin.to_vec();
    // A writer thread: the binary may exit before reading everything.
    let writer = std::thread::spawn(move || {
        let _ = input.write_all(&data);
    });
    let out = child.wait_with_output().unwrap();
    writer.join().unwrap();
    no_panic(&out);
    out
}

fn no_panic(out: &Output) {
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        !err.contains("panicked") && !err.contains("RUST_BACKTRACE"),
        "panic trace: {err}"
    );
    assert!(out.status.code().is_some(), "killed by a signal: {out:?}");
}

fn code(out: &Output) -> i32 {
    out.status.code().unwrap()
}

fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

fn stdout(out: &Output) -> String {
    String::from_utf8_lossy(&out.stdout).into_owned()
}

fn temp(name: &str, content: &[u8]) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cli_robustness");
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, content).unwrap();
    p
}

#[test]
fn invalid_utf8_is_refused_with_the_offset_of_the_first_bad_byte() {
    for (input, offset) in [
        (&b"G01 X1. F100.\n\xffG00"[..], 14),
        (&b"\xfe\xff\x00G"[..], 0),
        (&b"(caf\xc3\xa9) \xc3"[..], 8), // a sequence cut short at the end
        (&b"G00 X1.\r\n(\xed\xa0\x80)"[..], 10), // an encoded surrogate
    ] {
        for args in [
            &["check", "-"][..],
            &["run", "-"],
            &["run", "--format", "json", "-"],
        ] {
            let out = offsetlab(args, input);
            assert_eq!(code(&out), 2, "{args:?} {input:?}");
            let msg = stderr(&out);
            assert!(
                msg.contains(&format!(
                    "<stdin> is not UTF-8 text: invalid byte at offset {offset}"
                )),
                "{msg}"
            );
            assert!(out.stdout.is_empty(), "nothing on stdout");
        }
    }
    let path = temp("latin1.nc", b"(R\xe9sum\xe9)\nG00 X1.\n");
    let out = offsetlab(&["check", path.to_str().unwrap()], b"");
    assert_eq!(code(&out), 2);
    assert!(stderr(&out).contains("latin1.nc is not UTF-8 text: invalid byte at offset 2"));
}

#[test]
fn binary_junk_is_refused_or_diagnosed_never_a_panic() {
    // Deterministic junk: every byte value, then a pseudo-random megabyte.
    let mut junk: Vec<u8> = (0..=255u8).collect();
    let mut x = 0x2545_F491_4F6C_DD1Du64;
    junk.extend((0..1 << 20).map(|_| {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        (x >> 24) as u8
    }));
    let out = offsetlab(&["check", "-"], &junk);
    assert_eq!(code(&out), 2);
    assert!(
        stderr(&out).contains("invalid byte at offset 128"),
        "{}",
        stderr(&out)
    );
    // The same junk made valid UTF-8 (control characters, NULs, symbols):
    // a program full of errors, reported with places and exit 1.
    let text = String::from_utf8_lossy(&junk).into_owned();
    let out = offsetlab(&["check", "-"], text.as_bytes());
    assert_eq!(code(&out), 1);
    let report = stdout(&out);
    assert!(
        report.contains("error["),
        "{}",
        &report[..report.len().min(500)]
    );
    assert!(report.lines().last().unwrap().starts_with("<stdin>: "));
    let out = offsetlab(&["run", "--format", "json", "-"], text.as_bytes());
    assert_eq!(code(&out), 1);
    let v: Value = serde_json::from_slice(&out.stdout).expect("valid JSON");
    assert!(v["summary"]["errors"].as_u64().unwrap() >= 1);
    // NULs alone are characters that are not part of a program.
    let out = offsetlab(&["check", "-"], &[0u8; 4096]);
    assert_eq!(code(&out), 1);
    assert!(stdout(&out).contains("<stdin>:1:1: error[unexpected-character]"));
}

#[test]
fn empty_input_is_an_empty_program() {
    let out = offsetlab(&["check", "-"], b"");
    assert_eq!(code(&out), 0);
    assert_eq!(
        stdout(&out),
        "<stdin>: 0 blocks, 0 moves, no motion; path 0.000 mm (rapid 0.000, feed 0.000), time 0.0 s; 0 errors, 0 warnings\n"
    );
    let out = offsetlab(&["run", "--format", "json", "-"], b"");
    assert_eq!(code(&out), 0);
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["blocks"], Value::Array(vec![]));
    assert_eq!(v["summary"]["end"]["reason"], "completed");
    let empty = temp("empty.nc", b"");
    let out = offsetlab(&["run", empty.to_str().unwrap()], b"");
    assert_eq!(code(&out), 0);
    // Only blanks, comments and tape marks: still nothing to run.
    let out = offsetlab(&["check", "-"], b"%\n\n   \t\n(NOTHING)\n%\n");
    assert_eq!(code(&out), 0);
}

#[test]
fn a_50_mb_program_is_checked() {
    // ~1.6 million blocks of CAM output, generated here (benches/programs.rs).
    let mut text = String::new();
    while text.len() < 50_000_000 {
        text = programs::mill_program(1_600_000);
    }
    let path = temp("big.nc", text.as_bytes());
    let setup = temp("big.json", programs::SETUP_JSON.as_bytes());
    drop(text);
    let start = Instant::now();
    let out = offsetlab(
        &[
            "check",
            "--setup",
            setup.to_str().unwrap(),
            path.to_str().unwrap(),
        ],
        b"",
    );
    let elapsed = start.elapsed();
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let report = stdout(&out);
    assert!(report.contains("big.nc: "), "{report}");
    assert!(report.contains(" 0 errors, 0 warnings"), "{report}");
    let blocks: u64 = report
        .split("big.nc: ")
        .nth(1)
        .unwrap()
        .split(' ')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    assert!(blocks > 1_400_000, "{report}");
    assert!(elapsed < Duration::from_secs(120), "{elapsed:?}");
    std::fs::remove_file(path).unwrap();
}

#[test]
fn a_reader_that_closes_the_pipe_early_ends_the_run_quietly() {
    // Far more output than a pipe holds (64 KiB), for every format.
    let text = programs::mill_program(40_000);
    let path = temp("pipe.nc", text.as_bytes());
    let setup = temp("pipe.json", programs::SETUP_JSON.as_bytes());
    // 1000 diagnostic lines of ~90 bytes for check.
    let errors = temp(
        "pipe-errors.nc",
        "G01 X1.2.3 (ONE ERROR)\n".repeat(5000).as_bytes(),
    );
    let (path, setup) = (path.to_str().unwrap(), setup.to_str().unwrap());
    let errors = errors.to_str().unwrap();
    for args in [
        &["run", "--setup", setup, path][..],
        &["run", "--format", "json", "--setup", setup, path],
        &["check", errors],
    ] {
        let mut child = bin()
            .args(args)
            .stdin(Stdio::null())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        // `| head -1`: read one line, then close the pipe.
        let mut reader = BufReader::new(child.stdout.take().unwrap());
        let mut first = String::new();
        reader.read_line(&mut first).unwrap();
        assert!(!first.is_empty());
        drop(reader);
        let out = child.wait_with_output().unwrap();
        no_panic(&out);
        assert!(stderr(&out).is_empty(), "{args:?}: {}", stderr(&out));
        let expected = if args[0] == "check" { 1 } else { 0 };
        assert_eq!(code(&out), expected, "{args:?}");
    }
    // And through a real shell pipe, as a person types it.
    let out = Command::new("sh")
        .arg("-c")
        .arg(format!(
            "'{}' run --setup '{setup}' '{path}' | head -1",
            env!("CARGO_BIN_EXE_offsetlab")
        ))
        .output()
        .unwrap();
    no_panic(&out);
    assert!(stdout(&out).starts_with(" LINE  BLOCK"), "{}", stdout(&out));
    assert!(stderr(&out).is_empty(), "{}", stderr(&out));
}

#[test]
fn json_with_errors_is_valid_json_and_exit_1() {
    let program = "G01 X1.2.3 F100.\nG02 X10. Y0 R2.\nQ\n<script>alert(1)</script>\n";
    let out = offsetlab(&["run", "--format", "json", "-"], program.as_bytes());
    assert_eq!(code(&out), 1);
    let v: Value = serde_json::from_slice(&out.stdout).expect("valid JSON");
    let diags = v["diagnostics"].as_array().unwrap();
    assert!(diags.len() >= 3, "{diags:?}");
    for d in diags {
        assert_eq!(d["severity"], "error");
        assert!(d["line"].as_u64().unwrap() >= 1);
        assert!(d["column"].as_u64().unwrap() >= 1);
        assert!(!d["message"].as_str().unwrap().is_empty());
    }
    assert_eq!(v["summary"]["end"]["reason"], "error");
    assert!(stderr(&out).is_empty());
    // A setup with an error: exit 2 and a message, nothing on stdout.
    let bad = temp(
        "bad-setup.json",
        br#"{"version": 1, "offsets": {"01": 1e9}}"#,
    );
    let out = offsetlab(
        &[
            "run",
            "--format",
            "json",
            "--setup",
            bad.to_str().unwrap(),
            "-",
        ],
        b"G00 X1.",
    );
    assert_eq!(code(&out), 2);
    assert!(stderr(&out).contains("setup-range"), "{}", stderr(&out));
    assert!(out.stdout.is_empty());
}

#[test]
fn unreadable_input_and_bad_usage_exit_2_with_a_message() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    let missing = dir.join("no-such-program.nc");
    let cases: Vec<(Vec<String>, &str)> = vec![
        (
            vec!["check".into(), missing.display().to_string()],
            "cannot read",
        ),
        (
            vec!["check".into(), dir.display().to_string()],
            "cannot read",
        ),
        (vec!["run".into()], "no PROGRAM given"),
        (
            vec!["run".into(), "--format".into(), "xml".into(), "-".into()],
            "invalid value",
        ),
        (vec!["explode".into()], "unrecognized subcommand"),
        (
            vec!["run".into(), "--offset".into(), "01=abc".into(), "-".into()],
            "01=abc",
        ),
        (
            vec!["link".into(), "--decode".into(), "#v1.@@@".into()],
            "link-base64",
        ),
        (
            vec!["link".into(), "--decode".into(), "#v9.AAAA".into()],
            "link-version",
        ),
        (
            vec!["link".into(), "--decode".into(), "".into()],
            "link-empty",
        ),
    ];
    for (args, message) in cases {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let out = offsetlab(&args, b"G00 X1.");
        assert_eq!(code(&out), 2, "{args:?}: {}", stderr(&out));
        assert!(stderr(&out).contains(message), "{args:?}: {}", stderr(&out));
    }
    // Help and version are not errors.
    assert_eq!(code(&offsetlab(&["--help"], b"")), 0);
    assert_eq!(code(&offsetlab(&["--version"], b"")), 0);
}

#[test]
fn a_huge_single_line_and_many_errors_are_reported_within_the_caps() {
    // One megabyte on one line, 100 000 `;`-separated blocks (each within
    // the longest block, behaviour 1.25), every one in error: the
    // diagnostics stop at 1000 and one warning says how many more there
    // were.
    let line = "G01 X1.2.3;".repeat(100_000);
    let out = offsetlab(&["check", "-"], line.as_bytes());
    assert_eq!(code(&out), 1);
    let report = stdout(&out);
    assert_eq!(
        report.lines().count(),
        1000 + 1 + 1,
        "1000, the warning, the summary"
    );
    assert!(
        report.contains("more diagnostics were not reported (at most 1000 are)"),
        "{}",
        &report[report.len() - 300..]
    );
}

#[test]
fn an_endless_or_oversized_input_is_refused_before_it_fills_memory() {
    // /dev/zero as PROGRAM, as standard input and as --setup: exit 2 after
    // reading one byte past the limit, not an out-of-memory abort.
    let start = Instant::now();
    let out = offsetlab(&["check", "/dev/zero"], b"");
    assert_eq!(code(&out), 2);
    assert!(
        stderr(&out).contains("/dev/zero is larger than 256 MiB"),
        "{}",
        stderr(&out)
    );
    let out = bin()
        .args(["check", "-"])
        .stdin(std::fs::File::open("/dev/zero").unwrap())
        .output()
        .unwrap();
    no_panic(&out);
    assert_eq!(code(&out), 2);
    assert!(stderr(&out).contains("<stdin> is larger than 256 MiB"));
    let out = offsetlab(&["check", "--setup", "/dev/zero", "-"], b"G00 X1.");
    assert_eq!(code(&out), 2);
    assert!(stderr(&out).contains("setup /dev/zero is larger than 512 MiB"));
    assert!(
        start.elapsed() < Duration::from_secs(60),
        "{:?}",
        start.elapsed()
    );
    // A setup file that is not UTF-8 names its offset too.
    let bad = temp(
        "latin1-setup.json",
        b"{\"version\": 1, \"program\": \"(R\xe9)\"}",
    );
    let out = offsetlab(&["check", "--setup", bad.to_str().unwrap()], b"");
    assert_eq!(code(&out), 2);
    assert!(stderr(&out).contains("is not UTF-8 text: invalid byte at offset 29"));
}

#[test]
fn a_long_line_of_blocks_is_printed_in_linear_time() {
    // 50,000 `;`-separated blocks on one line: the table took 8.9 s in a
    // release build when every row scanned back to the line's start.
    let text = "X1.;Y1.;".repeat(25_000);
    let start = Instant::now();
    for args in [&["run", "-"][..], &["run", "--format", "json", "-"]] {
        let out = offsetlab(args, text.as_bytes());
        assert_eq!(code(&out), 0);
        assert_eq!(
            stdout(&out).lines().count(),
            if args.len() == 2 { 50_001 } else { 1 }
        );
    }
    assert!(
        start.elapsed() < Duration::from_secs(20),
        "{:?}",
        start.elapsed()
    );
}

#[test]
fn a_large_program_file_is_checked_as_the_same_text_from_standard_input() {
    // Files of 1 MiB or more are mapped, not read; standard input is read.
    let text = programs::mill_program(40_000).replace("M30", "G01 X1.2.3 (Fräsen)\nG01 X1. Q\nM30");
    assert!(text.len() > 1 << 20, "{} bytes", text.len());
    let path = temp("mapped.nc", text.as_bytes());
    let setup = temp("mapped.json", programs::SETUP_JSON.as_bytes());
    let (path, setup) = (path.to_str().unwrap(), setup.to_str().unwrap());
    let from_file = offsetlab(&["check", "--setup", setup, path], b"");
    let from_stdin = offsetlab(&["check", "--setup", setup, "-"], text.as_bytes());
    assert_eq!(code(&from_file), 1);
    assert_eq!(
        stdout(&from_file).replace(path, "<stdin>"),
        stdout(&from_stdin)
    );
    // One thread (OFFSETLAB_THREADS=1) prints the same.
    let one = bin()
        .args(["check", "--setup", setup, path])
        .env("OFFSETLAB_THREADS", "1")
        .output()
        .unwrap();
    no_panic(&one);
    assert_eq!(stdout(&one), stdout(&from_file));
    assert!(stdout(&from_file).contains("error[malformed-number]"));
    assert!(stdout(&from_file).contains("error[missing-number]"));

    // Invalid UTF-8 in a large file: the same refusal as a small one.
    let mut bytes = text.into_bytes();
    assert!(bytes[1 << 20].is_ascii());
    bytes[1 << 20] = 0xff;
    let bad = temp("mapped-latin1.nc", &bytes);
    let out = offsetlab(&["check", bad.to_str().unwrap()], b"");
    assert_eq!(code(&out), 2);
    assert!(
        stderr(&out).contains(&format!(
            "is not UTF-8 text: invalid byte at offset {}",
            1 << 20
        )),
        "{}",
        stderr(&out)
    );

    // Larger than the interpreter reads (a sparse file: no disk used).
    let huge = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cli_robustness/huge.nc");
    std::fs::File::create(&huge)
        .unwrap()
        .set_len(300 << 20)
        .unwrap();
    let out = offsetlab(&["check", huge.to_str().unwrap()], b"");
    assert_eq!(code(&out), 2);
    assert!(
        stderr(&out).contains("is larger than 256 MiB"),
        "{}",
        stderr(&out)
    );
    let _ = std::fs::remove_file(huge);
}
