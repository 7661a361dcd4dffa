//! The CLI contract (issue 2, item 4): `run --format json`, `run --format
//! table`, `check`, options, and exit statuses — by running the binary.
#![cfg(not(target_arch = "wasm32"))]

use std::io::Write;
use std::process::{Command, Output, Stdio};

use serde_json::Value;

/// Seed 000's square, the page's default example: a comment line, seven
/// moving blocks and M30.
const SQUARE: &str = include_str!("data/seed000_square.nc");

fn offsetlab(args: &[&str], stdin: &[u8]) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_offsetlab"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("binary runs");
    // A run that refuses its arguments exits before it reads: the pipe may
    // be closed already, and the exit status is what the test checks.
    let written = child.stdin.take().unwrap().write_all(stdin);
    if let Err(e) = written {
        assert_eq!(e.kind(), std::io::ErrorKind::BrokenPipe, "{e}");
    }
    child.wait_with_output().unwrap()
}

fn json(args: &[&str], stdin: &str) -> (Value, i32) {
    let out = offsetlab(args, stdin.as_bytes());
    let v: Value = serde_json::from_slice(&out.stdout)
        .unwrap_or_else(|e| panic!("not JSON ({e}): {}", String::from_utf8_lossy(&out.stdout)));
    (v, out.status.code().unwrap())
}

fn temp_file(name: &str, content: &[u8]) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("offsetlab-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, content).unwrap();
    p
}

#[test]
fn run_json_has_blocks_moves_and_diagnostics() {
    let (v, code) = json(
        &["run", "--format", "json", "--offset", "01=6.0", "-"],
        SQUARE,
    );
    assert_eq!(code, 0);
    let blocks = v["blocks"].as_array().unwrap();
    // One entry per executed block: the comment line has none.
    assert_eq!(blocks.len(), 8);
    assert_eq!(blocks[7]["text"], "M30");
    assert_eq!(
        v["summary"]["end"],
        serde_json::json!({"reason": "program_end", "line": 9})
    );
    let b = &blocks[1];
    assert_eq!(b["line"], 3);
    assert_eq!(
        b["programmed"],
        serde_json::json!({"x": 0.0, "y": 0.0, "z": 0.0})
    );
    assert_eq!(
        b["actual"],
        serde_json::json!({"x": -6.0, "y": -6.0, "z": 0.0})
    );
    assert!(
        b["explanation"]
            .as_str()
            .unwrap()
            .contains("reduced by D01 (6.000)")
    );
    assert_eq!(b["position_offset"]["vector"]["x"], -6.0);
    let moves = v["moves"].as_array().unwrap();
    assert_eq!(moves.len(), 7);
    assert_eq!(moves[0]["kind"], "rapid");
    assert_eq!(moves[2]["kind"], "feed");
    assert_eq!(moves[2]["line"], 4);
    assert_eq!(
        moves[2]["from"],
        serde_json::json!({"x": -6.0, "y": -6.0, "z": 0.0})
    );
    assert_eq!(
        moves[2]["to"],
        serde_json::json!({"x": 86.0, "y": -6.0, "z": 0.0})
    );
    assert_eq!(
        moves[2]["programmed_to"],
        serde_json::json!({"x": 80.0, "y": 0.0, "z": 0.0})
    );
    assert_eq!(v["diagnostics"], serde_json::json!([]));
}

#[test]
fn run_json_two_blocks_on_one_line_share_the_line() {
    let (v, _) = json(
        &["run", "--format", "json", "-"],
        "G00 X1.;G00 X2.\nG00 X3.",
    );
    let lines: Vec<i64> = v["blocks"]
        .as_array()
        .unwrap()
        .iter()
        .map(|b| b["line"].as_i64().unwrap())
        .collect();
    assert_eq!(lines, vec![1, 1, 2]);
}

#[test]
fn run_json_diagnostics_have_severity_code_message_line_column() {
    let (v, code) = json(
        &["run", "--format", "json", "-"],
        "G00 X1.\nG01 X1.2.3 F100.",
    );
    assert_eq!(code, 1);
    let d = &v["diagnostics"][0];
    assert_eq!(d["severity"], "error");
    assert_eq!(d["code"], "malformed-number");
    assert_eq!(d["line"], 2);
    assert_eq!(d["column"], 5);
    assert!(d["message"].as_str().unwrap().contains("1.2.3"));
    assert_eq!(v["blocks"].as_array().unwrap().len(), 1);
}

#[test]
fn run_json_arcs_and_offset_moves() {
    let (v, _) = json(
        &["run", "--format", "json", "--offset", "2=15", "-"],
        "G90 G00 Z50.\nG43 H02\nG01 X10. F100.\nG02 X20. R5.\nG03 X30. R5.",
    );
    let kinds: Vec<&str> = v["moves"]
        .as_array()
        .unwrap()
        .iter()
        .map(|m| m["kind"].as_str().unwrap())
        .collect();
    assert_eq!(kinds, vec!["rapid", "offset", "feed", "arc_cw", "arc_ccw"]);
    assert_eq!(v["moves"][1]["rate"], "rapid");
    let arc = &v["moves"][3]["arc"];
    assert_eq!(
        arc["center"],
        serde_json::json!({"x": 15.0, "y": 0.0, "z": 65.0})
    );
    assert_eq!(arc["direction"], "cw");
}

#[test]
fn run_json_lathe_positions_have_x_and_z() {
    let (v, code) = json(
        &[
            "run",
            "--format",
            "json",
            "--machine",
            "lathe",
            "--offset",
            "08=X0.4,Z-0.2",
            "-",
        ],
        "G50 X120. Z60.;\nG00 S800 M03 T0108;\nX50. Z3.;\nT0100;",
    );
    assert_eq!(code, 0);
    let b = &v["blocks"][1];
    assert_eq!(b["actual"], serde_json::json!({"x": 120.4, "z": 59.8}));
    assert_eq!(
        v["blocks"][2]["actual"],
        serde_json::json!({"x": 50.4, "z": 2.8})
    );
    assert_eq!(
        v["blocks"][3]["actual"],
        serde_json::json!({"x": 50.0, "z": 3.0})
    );
}

#[test]
fn run_table_is_readable() {
    let out = offsetlab(&["run", "--offset", "01=6", "-"], SQUARE.as_bytes());
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8(out.stdout).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert!(
        lines[0].contains("LINE") && lines[0].contains("PROGRAMMED") && lines[0].contains("ACTUAL")
    );
    assert!(lines[2].contains("G91 G00 G46 X30. Y20. D01"));
    assert!(lines[2].contains("X-6.000 Y-6.000 Z0.000"));
    assert!(lines[3].contains("2 × D01 (6.000)"));
}

#[test]
fn check_prints_file_line_col_and_a_summary() {
    let path = temp_file("bad.nc", b"G00 X10.\nG01 X1.2.3\nG01 Y\n");
    let out = offsetlab(&["check", path.to_str().unwrap()], b"");
    assert_eq!(out.status.code(), Some(1));
    let text = String::from_utf8(out.stdout).unwrap();
    let p = path.display();
    assert!(
        text.contains(&format!("{p}:2:5: error[malformed-number]:")),
        "{text}"
    );
    assert!(
        text.contains(&format!("{p}:3:5: error[missing-number]:")),
        "{text}"
    );
    let last = text.lines().last().unwrap();
    assert!(
        last.contains("1 blocks") && last.contains("1 moves") && last.contains("2 errors"),
        "{last}"
    );
}

#[test]
fn check_clean_program_exits_zero_with_bounds() {
    let out = offsetlab(&["check", "--offset", "01=6", "-"], SQUARE.as_bytes());
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8(out.stdout).unwrap();
    assert_eq!(
        text.trim(),
        "<stdin>: 8 blocks, 7 moves, bounds X-30.000..86.000 Y-20.000..56.000 Z0.000..0.000 mm; path 399.625 mm (rapid 91.625, feed 308.000), time 1 min 32.6 s; 0 errors, 0 warnings"
    );
    // Behaviour 6.10 by hand: rapids (0,0) → (-30,-20) 36.056, the G46
    // (24, 14) out and back 27.785 twice: 91.625; feeds 92 + 62 + 92 + 62 =
    // 308 at F200: 92.4 s, and the rapids' longest axes 30, 24, 24 at
    // 24,000 mm/min: 0.195 s.
}

#[test]
fn check_warnings_do_not_fail() {
    let out = offsetlab(&["check", "-"], b"G01 X12345\n");
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.contains("<stdin>:1:5: warning[integer-dimension]"),
        "{text}"
    );
    assert!(
        text.contains("<stdin>:1:1: warning[missing-feed]"),
        "{text}"
    );
}

#[test]
fn setup_file_is_read_and_options_override_it() {
    let setup = temp_file(
        "setup.json",
        br#"{"version": 1, "machine": "mill", "offsets": {"01": {"geometry": 5.0, "wear": 1.0}}}"#,
    );
    let s = setup.to_str().unwrap();
    let (v, _) = json(
        &["run", "--format", "json", "--setup", s, "-"],
        "G91 G45 X10. D01",
    );
    assert_eq!(v["blocks"][0]["actual"]["x"], 16.0);
    let (v, _) = json(
        &[
            "run", "--format", "json", "--setup", s, "--offset", "1=2", "-",
        ],
        "G91 G45 X10. D01",
    );
    assert_eq!(v["blocks"][0]["actual"]["x"], 12.0);
}

#[test]
fn behaviour11_3_control_sets_the_profile_over_the_setup_and_keeps_its_settings() {
    // Two codes of group 01: an error on YASNAC (the default), a warning on
    // Fanuc (the last one wins).
    let out = offsetlab(&["check", "-"], b"G00 G01 X1. F100.");
    assert_eq!(out.status.code(), Some(1));
    let out = offsetlab(&["check", "--control", "fanuc", "-"], b"G00 G01 X1. F100.");
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("warning[modal-conflict]"), "{text}");
    // A setting the setup sets stays whatever the profile.
    let setup = temp_file(
        "strict.json",
        br#"{"settings": {"control": "haas", "same_group_codes": "error"}}"#,
    );
    let s = setup.to_str().unwrap();
    let out = offsetlab(
        &["check", "--setup", s, "--control", "fanuc", "-"],
        b"G00 G01 X1. F100.",
    );
    assert_eq!(out.status.code(), Some(1));
    let out = offsetlab(&["check", "--control", "siemens", "-"], b"G00");
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn bad_usage_and_unreadable_input_exit_2() {
    let cases: Vec<(Vec<&str>, &[u8], &str)> = vec![
        (vec!["run", "--bogus", "-"], b"", "unexpected argument"),
        (vec!["run"], b"", "PROGRAM"),
        (vec!["run", "--offset", "01", "-"], b"", "NN=VALUE"),
        (vec!["run", "--offset", "01=1000", "-"], b"", "999.999"),
        (vec!["run", "/nonexistent/file.nc"], b"", "cannot read"),
        (
            vec!["run", "--setup", "/nonexistent.json", "-"],
            b"",
            "cannot read setup",
        ),
        (vec!["run", "-"], b"G00 X1.\n\xff\xfe", "offset 8"),
    ];
    for (args, stdin, msg) in cases {
        let out = offsetlab(&args, stdin);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(msg), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{err}");
    }
    let setup = temp_file("bad-setup.json", br#"{"versoin": 1}"#);
    let out = offsetlab(&["check", "--setup", setup.to_str().unwrap(), "-"], b"");
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("unknown field `versoin`"));
}

#[test]
fn empty_program_is_fine() {
    let out = offsetlab(&["check", "-"], b"");
    assert_eq!(out.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&out.stdout).contains("0 blocks, 0 moves, no motion"));
}

#[test]
fn summary_lists_the_registers_the_program_names() {
    let (v, _) = json(
        &["run", "--format", "json", "-"],
        "G43 Z10. H02\nG91 G45 X1. D01\nD05\nH00",
    );
    assert_eq!(v["summary"]["registers"], serde_json::json!([1, 2, 5]));
    let (v, _) = json(
        &["run", "--format", "json", "--machine", "lathe", "-"],
        "T0108\nT0200\nT0316",
    );
    assert_eq!(v["summary"]["registers"], serde_json::json!([8, 16]));
}

#[test]
fn link_round_trips_through_decode() {
    let out = offsetlab(
        &[
            "link", "--offset", "01=6", "--step", "2", "--plane", "XY", "-",
        ],
        SQUARE.as_bytes(),
    );
    assert_eq!(out.status.code(), Some(0));
    let link = String::from_utf8(out.stdout).unwrap().trim().to_string();
    assert!(link.starts_with("http://127.0.0.1:8000/#v1."), "{link}");
    let out = offsetlab(&["link", "--decode", &link], b"");
    assert_eq!(out.status.code(), Some(0));
    let doc: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(doc["program"], SQUARE);
    assert_eq!(doc["offsets"]["01"], 6.0);
    assert_eq!(doc["step"], 2);
    assert_eq!(doc["view"]["plane"], "XY");
    // The decoded document runs as a --setup file without PROGRAM.
    let path = temp_file("decoded.json", &out.stdout);
    let (v, code) = json(
        &["run", "--format", "json", "--setup", path.to_str().unwrap()],
        "",
    );
    assert_eq!(code, 0);
    assert_eq!(v["blocks"][1]["actual"]["x"], -6.0);
}

#[test]
fn link_plain_form_and_base() {
    let out = offsetlab(
        &[
            "link",
            "--plain",
            "--embed",
            "--base",
            "https://example.org/play/",
            "--machine",
            "lathe",
            "--offset",
            "08=X0.4,Z-0.2",
            "-",
        ],
        b"G50 X120. Z60.\nT0108\n",
    );
    let link = String::from_utf8(out.stdout).unwrap();
    assert!(
        link.starts_with("https://example.org/play/#program=G50%20X120.%20Z60.%0AT0108%0A"),
        "{link}"
    );
    assert!(
        link.contains("machine=lathe")
            && link.contains("offset=08:X0.4,Z-0.2")
            && link.trim().ends_with("embed=1"),
        "{link}"
    );
    let out = offsetlab(&["link", "--decode", link.trim()], b"");
    assert_eq!(out.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&out.stderr).contains("embed mode"));
    let out = offsetlab(&["link", "--base", "javascript:alert(1)", "-"], b"G00 X1.");
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn link_decode_errors_exit_2_with_the_reason() {
    for (link, code) in [
        ("#v2.abc", "link-version"),
        ("#v1.!!", "link-base64"),
        ("#v1.AAAA", "link-deflate"),
        ("#nonsense", "link-plain"),
    ] {
        let out = offsetlab(&["link", "--decode", link], b"");
        assert_eq!(out.status.code(), Some(2), "{link}");
        assert!(
            String::from_utf8_lossy(&out.stderr).contains(code),
            "{link}"
        );
    }
    let out = offsetlab(&["run"], b"");
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("no PROGRAM"));
}

#[test]
fn behaviour1_24_a_lathe_program_on_the_mill_is_offered_the_lathe() {
    let lathe = "G50 S2000\nG00 X40. Z2. T0101\nG01 U-4. W-20. F0.2\nM30\n";
    // `check` stopped by the mill's errors: a note naming the lathe and why.
    let out = offsetlab(&["check", "-"], lathe.as_bytes());
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{text}");
    let note = text
        .lines()
        .find(|l| l.contains(": note: "))
        .unwrap_or_else(|| panic!("{text}"));
    assert!(note.ends_with("try --machine lathe"), "{note}");
    for why in ["T0101", "U and W", "G50 S"] {
        assert!(note.contains(why), "{why}: {note}");
    }
    // The JSON summary carries it.
    let (v, _) = json(&["run", "--format", "json", "-"], lathe);
    let hint = &v["summary"]["machine_hint"];
    assert_eq!(hint["machine"], "lathe");
    assert_eq!(hint["reasons"].as_array().unwrap().len(), 3, "{hint}");
    // On the lathe it runs, and nothing is offered.
    let (v, code) = json(
        &["run", "--format", "json", "--machine", "lathe", "-"],
        lathe,
    );
    assert_eq!(code, 0, "{v}");
    assert!(v["summary"].get("machine_hint").is_none(), "{v}");
}

#[test]
fn behaviour1_24_a_mill_program_on_the_lathe_is_offered_the_mill_and_mixed_words_are_not() {
    let mill = "G90 G54 G00 X10. Y10.\nG43 Z5. H01\nM30\n";
    let (v, code) = json(
        &["run", "--format", "json", "--machine", "lathe", "-"],
        mill,
    );
    assert_eq!(code, 1);
    assert_eq!(v["summary"]["machine_hint"]["machine"], "mill", "{v}");
    let reasons: Vec<&str> = v["summary"]["machine_hint"]["reasons"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r.as_str().unwrap())
        .collect();
    assert_eq!(reasons.len(), 3, "Y, G43 and H: {reasons:?}");
    // A program with words of both machines (a lathe with a Y axis) names
    // neither: the choice stays the user's.
    let both = "G00 X10. Y5. T0101\nM30\n";
    let (v, _) = json(
        &["run", "--format", "json", "--machine", "lathe", "-"],
        both,
    );
    assert!(v["summary"].get("machine_hint").is_none(), "{v}");
    let (v, _) = json(&["run", "--format", "json", "--machine", "mill", "-"], both);
    assert!(v["summary"].get("machine_hint").is_none(), "{v}");
    // Comments, and text after `;`, are not evidence.
    let commented = "(U1. W2. T0101)\nG00 X1. Y1. ; see www.w3.org\nM30\n";
    let (v, _) = json(&["run", "--format", "json", "-"], commented);
    assert!(v["summary"].get("machine_hint").is_none(), "{v}");
}

#[test]
fn behaviour19_10_cli_program_files_fill_the_library() {
    // The main program calls O1002 twice and the macro O2001 once; both
    // are in another file, after a `%` line. Lines are counted in each
    // program's text from its header: O2001's `#3=1/0` is its line 3, the
    // divisor `0` its column 6.
    let main = temp_file(
        "lib_main.nc",
        b"O1000\nG90 G00 X0 Y0 Z0\nM98 P1002 L2\nG65 P2001 A3.\nM30\n",
    );
    let subs = temp_file(
        "lib_subs.nc",
        b"%\nO1002 (STEP)\nG91 G01 X10. F100\nM99\nO2001\nG91 G01 Y#1\n#3=1/0\nM99\n%\n",
    );
    let (v, code) = json(
        &[
            "run",
            "--format",
            "json",
            "--program",
            subs.to_str().unwrap(),
            main.to_str().unwrap(),
        ],
        "",
    );
    assert_eq!(code, 1);
    let blocks = v["blocks"].as_array().unwrap();
    // Block 4: O1002's G01, its line 2, X0 + 10 = 10; block 7: the second
    // pass, X 10 + 10 = 20.
    assert_eq!(blocks[4]["line"], 2);
    assert_eq!(blocks[4]["program"], "O1002");
    assert_eq!(blocks[4]["actual"]["x"], 10.0);
    assert_eq!(blocks[4]["text"], "G91 G01 X10. F100");
    assert_eq!(blocks[4]["library"], true);
    assert_eq!(blocks[7]["actual"]["x"], 20.0);
    assert_eq!(
        blocks[7]["stack"],
        serde_json::json!(["O1000 line 3", "O1002"])
    );
    // Block 11: O2001's G91 G01 Y#1 with A3. (#1 = 3): Y 0 + 3 = 3.
    assert_eq!(blocks[11]["program"], "O2001");
    assert_eq!(blocks[11]["line"], 2);
    assert_eq!(blocks[11]["actual"]["y"], 3.0);
    let d = &v["diagnostics"][0];
    assert_eq!(
        (d["line"].as_u64(), d["column"].as_u64()),
        (Some(3), Some(6))
    );
    assert!(d["message"].as_str().unwrap().starts_with("in O2001: "));
    // A file without a header is a usage error (exit 2) that says why.
    let bare = temp_file("lib_bare.nc", b"G01 X1.\nM99\n");
    let out = offsetlab(
        &[
            "run",
            "--program",
            bare.to_str().unwrap(),
            main.to_str().unwrap(),
        ],
        b"",
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("no program header"));
    // `link` carries the library: decoded, its document holds both.
    let out = offsetlab(
        &[
            "link",
            "--program",
            subs.to_str().unwrap(),
            main.to_str().unwrap(),
        ],
        b"",
    );
    let link = String::from_utf8(out.stdout).unwrap().trim().to_string();
    let out = offsetlab(&["link", "--decode", &link], b"");
    let doc: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(
        doc["programs"]["1002"],
        "O1002 (STEP)\nG91 G01 X10. F100\nM99\n"
    );
    assert!(
        doc["programs"]["2001"]
            .as_str()
            .unwrap()
            .starts_with("O2001\n")
    );
}

/// `--tool` sets an entry of the tool list (behaviour 7.53, 11.3): `link
/// --plain` writes it back as `tool=01:D10,L120`; `run --format json`
/// carries each block's distance to go (6.12); a bad spec exits 2.
#[test]
fn behaviour7_53_the_tool_option_sets_the_tool_list() {
    let out = offsetlab(&["link", "--plain", "--tool", "1=D10,L120", "-"], b"T1 M06");
    assert_eq!(out.status.code(), Some(0));
    let link = String::from_utf8_lossy(&out.stdout);
    assert!(link.contains("tool=01:D10,L120"), "{link}");
    let (v, code) = json(
        &["run", "--format", "json", "--tool", "1=D10", "-"],
        "G90 G00 X3. Y4.",
    );
    assert_eq!(code, 0);
    // From the origin (the default YASNAC start) to X3 Y4.
    assert_eq!(v["blocks"][0]["distance_to_go"]["x"], 3.0);
    assert_eq!(v["blocks"][0]["distance_to_go"]["y"], 4.0);
    let out = offsetlab(&["check", "--tool", "1=Q5", "-"], b"G00 X1.");
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("tool `1=Q5`"));
}
