//! The CLI's library from a folder: `--program DIR` (behaviour 19.10) and
//! the called programs found in the program's own folder (19.13).

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use serde_json::Value;

fn offsetlab(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_offsetlab"))
        .args(args)
        .output()
        .expect("binary runs")
}

/// A folder of its own for one test, holding `files`.
fn folder(test: &str, files: &[(&str, &str)]) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("offsetlab-lib-{}-{test}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    for (name, text) in files {
        std::fs::write(dir.join(name), text).unwrap();
    }
    dir
}

fn path(dir: &Path, name: &str) -> String {
    dir.join(name).to_str().unwrap().to_string()
}

fn run_json(args: &[&str]) -> (Value, String, i32) {
    let out = offsetlab(args);
    let v: Value = serde_json::from_slice(&out.stdout)
        .unwrap_or_else(|e| panic!("not JSON ({e}): {}", String::from_utf8_lossy(&out.stdout)));
    let stderr = String::from_utf8_lossy(&out.stderr).to_string();
    (v, stderr, out.status.code().unwrap())
}

const MAIN: &str = "O1000\nG90 G00 X0 Y0 Z0\nM98 P1002 L2\nG65 P3001 A3.\nM30\n";
const STEP: &str = "%\nO1002 (STEP)\nG91 G01 X10. F100\nM99\n%\n";
const MACRO: &str = "O3001\nG91 G01 Y#1\nM99\n";

#[test]
fn behaviour19_10_program_dir_reads_every_file_and_says_which_it_leaves_out() {
    let lib = folder(
        "dir",
        &[
            ("a_step.nc", STEP),
            ("b_macro.txt", MACRO),
            ("notes.txt", "cut the part twice\n"),
        ],
    );
    let main = folder("dir-main", &[("main.nc", MAIN)]);
    let (v, stderr, code) = run_json(&[
        "run",
        "--format",
        "json",
        "--program",
        lib.to_str().unwrap(),
        &path(&main, "main.nc"),
    ]);
    assert_eq!(code, 0, "{stderr}");
    // O1002 twice: X 0 + 10 + 10 = 20; O3001 with A3. (#1 = 3): Y 0 + 3.
    let blocks = v["blocks"].as_array().unwrap();
    let last = blocks
        .iter()
        .rev()
        .find(|b| b["program"] == "O3001")
        .unwrap();
    assert_eq!(last["actual"]["x"], 20.0);
    assert_eq!(last["actual"]["y"], 3.0);
    // The file without a header is said, with its name and why.
    assert!(
        stderr.contains("left out of the library") && stderr.contains("notes.txt"),
        "{stderr}"
    );
    assert!(stderr.contains("no program header"), "{stderr}");
    // A folder without a single program file is a usage error.
    let empty = folder("dir-empty", &[("notes.txt", "nothing\n")]);
    let out = offsetlab(&[
        "check",
        "--program",
        empty.to_str().unwrap(),
        &path(&main, "main.nc"),
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        String::from_utf8_lossy(&out.stderr).contains("no file in it opens with a program header")
    );
}

#[test]
fn behaviour19_13_a_called_program_in_the_programs_folder_joins_the_library() {
    let dir = folder(
        "folder",
        &[("main.nc", MAIN), ("o1002.nc", STEP), ("macro.nc", MACRO)],
    );
    let main = path(&dir, "main.nc");
    let (v, stderr, code) = run_json(&["run", "--format", "json", &main]);
    assert_eq!(code, 0, "{stderr}");
    let blocks = v["blocks"].as_array().unwrap();
    // M98 P1002 L2 from line 3: O1002's G91 G01 X10. twice, X 10 then 20.
    let steps: Vec<f64> = blocks
        .iter()
        .filter(|b| b["program"] == "O1002" && b["line"] == 2)
        .map(|b| b["actual"]["x"].as_f64().unwrap())
        .collect();
    assert_eq!(steps, [10.0, 20.0]);
    assert_eq!(
        blocks
            .iter()
            .rev()
            .find(|b| b["program"] == "O3001")
            .unwrap()["actual"]["y"],
        3.0
    );
    // Each program read is said with its file.
    assert!(
        stderr.contains("O1002") && stderr.contains("o1002.nc"),
        "{stderr}"
    );
    assert!(
        stderr.contains("O3001") && stderr.contains("macro.nc"),
        "{stderr}"
    );
    // `check` finds them too; the link carries them.
    let out = offsetlab(&["check", &main]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
    let out = offsetlab(&["link", &main]);
    let link = String::from_utf8(out.stdout).unwrap().trim().to_string();
    let out = offsetlab(&["link", "--decode", &link]);
    let doc: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(
        doc["programs"]["1002"],
        "O1002 (STEP)\nG91 G01 X10. F100\nM99\n%\n"
    );
    // A program the folder does not hold stays PS0076 at its P word.
    let alone = folder("alone", &[("main.nc", MAIN), ("o1002.nc", STEP)]);
    let out = offsetlab(&["check", &path(&alone, "main.nc")]);
    assert_eq!(out.status.code(), Some(1));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains(":4:5: error[program-not-found]"), "{text}");
}

#[test]
fn behaviour19_13_the_folder_adds_no_program_past_the_librarys_1000() {
    // A library folder of 1000 programs (O1–O1000) fills the library; the
    // O3001 the program calls, in the program's own folder, is named as not
    // read (behaviour 9.10's bound) and the run stops at the call.
    let files: Vec<(String, String)> = (1..=1000)
        .map(|n| (format!("p{n:04}.nc"), format!("O{n}\nM99\n")))
        .collect();
    let refs: Vec<(&str, &str)> = files
        .iter()
        .map(|(a, b)| (a.as_str(), b.as_str()))
        .collect();
    let lib = folder("full", &refs);
    let main = folder(
        "full-main",
        &[
            ("main.nc", "O2000\nG65 P3001 A3.\nM30\n"),
            ("macro.nc", MACRO),
        ],
    );
    let out = offsetlab(&[
        "check",
        "--program",
        lib.to_str().unwrap(),
        &path(&main, "main.nc"),
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        stderr.contains("O3001 in")
            && stderr.contains("is not read")
            && stderr.contains("at most 1000"),
        "{stderr}"
    );
    assert!(
        stdout.contains("program-not-found") || stderr.contains("program-not-found"),
        "{stdout}{stderr}"
    );
    assert_ne!(out.status.code(), Some(0));
}
