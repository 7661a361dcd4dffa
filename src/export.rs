//! The toolpath as files: the moves as JSON (the same fields as the CLI's
//! `run --format json` `moves`, built by [`view::move_view`]) and as CSV
//! (one row per move, the same fields flattened: `from.x` is the column
//! `from_x`, `arc.center.x` is `arc_center_x`). The page's export menu uses
//! both through the wasm module, so the files never disagree with the CLI.
//!
//! [`view::move_view`]: crate::view::move_view

use serde::Serialize;
use serde::ser::{SerializeStruct, Serializer};
use serde_json::Value;

use crate::report::Run;
use crate::setup::MachineKind;
use crate::view::{move_view, summary};

const POINTS: [&str; 4] = ["from", "to", "programmed_from", "programmed_to"];
const ARC_POINTS: [&str; 2] = ["center", "programmed_center"];

/// The CSV columns of a machine's moves, in order. A lathe position has no
/// `y`, so the lathe has no `_y` columns (but see [`run_columns`]).
pub fn csv_columns(machine: MachineKind) -> Vec<String> {
    columns(machine == MachineKind::Mill)
}

/// The CSV columns of a run's moves: a lathe run that moved in polar
/// coordinate interpolation has the `_y` columns too, the hypothetical axis
/// (behaviour 14.16).
pub fn run_columns(run: &Run) -> Vec<String> {
    let off_plane = |p: &crate::geometry::Xyz| p[1] != 0.0;
    let y = run.machine == MachineKind::Mill
        || run.moves.iter().any(|m| {
            [m.from, m.to, m.programmed_from, m.programmed_to]
                .iter()
                .any(off_plane)
        });
    columns(y)
}

fn columns(y: bool) -> Vec<String> {
    let axes: &[&str] = if y { &["x", "y", "z"] } else { &["x", "z"] };
    let mut columns: Vec<String> = ["line", "block", "kind", "rate"]
        .iter()
        .map(|s| s.to_string())
        .collect();
    for p in POINTS {
        columns.extend(axes.iter().map(|a| format!("{p}_{a}")));
    }
    columns.extend(["arc_plane".to_string(), "arc_direction".to_string()]);
    for (p, radius) in ARC_POINTS
        .iter()
        .zip(["arc_radius", "arc_programmed_radius"])
    {
        columns.extend(axes.iter().map(|a| format!("arc_{p}_{a}")));
        columns.push(radius.to_string());
    }
    columns.push("arc_sweep_degrees".to_string());
    columns
}

/// Flattens a JSON object: nested keys joined with `_`.
fn flatten(prefix: &str, value: &Value, out: &mut Vec<(String, Value)>) {
    match value {
        Value::Object(map) => {
            for (key, v) in map {
                let name = if prefix.is_empty() {
                    key.clone()
                } else {
                    format!("{prefix}_{key}")
                };
                flatten(&name, v, out);
            }
        }
        other => out.push((prefix.to_string(), other.clone())),
    }
}

/// The fields of one move, flattened (`from_x`, `arc_center_x`, …).
pub fn flat_move(value: &Value) -> Vec<(String, Value)> {
    let mut out = Vec::new();
    flatten("", value, &mut out);
    out
}

/// One CSV cell: numbers as the shortest text that reads back the same,
/// strings quoted only when they need it, absent values empty.
fn cell(value: Option<&Value>) -> String {
    match value {
        None | Some(Value::Null) => String::new(),
        Some(Value::Number(n)) => match n.as_f64() {
            Some(f) if n.is_f64() => format!("{f}"),
            _ => n.to_string(),
        },
        Some(Value::String(s)) => {
            if s.contains([',', '"', '\n', '\r']) {
                format!("\"{}\"", s.replace('"', "\"\""))
            } else {
                s.clone()
            }
        }
        Some(Value::Bool(b)) => b.to_string(),
        Some(other) => other.to_string(),
    }
}

/// The moves of a run as CSV (RFC 4180, `\r\n` line ends): a header of
/// [`run_columns`], then one row per move.
pub fn moves_csv(run: &Run) -> String {
    let columns = run_columns(run);
    let mut out = columns.join(",");
    out.push_str("\r\n");
    for m in &run.moves {
        let value = serde_json::to_value(move_view(m, run.machine)).unwrap_or(Value::Null);
        let flat = flat_move(&value);
        let row: Vec<String> = columns
            .iter()
            .map(|c| cell(flat.iter().find(|(k, _)| k == c).map(|(_, v)| v)))
            .collect();
        out.push_str(&row.join(","));
        out.push_str("\r\n");
    }
    out
}

struct Moves<'a>(&'a Run);

impl Serialize for Moves<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_seq(self.0.moves.iter().map(|m| move_view(m, self.0.machine)))
    }
}

struct MovesFile<'a>(&'a Run);

impl Serialize for MovesFile<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut st = s.serialize_struct("Toolpath", 2)?;
        st.serialize_field("summary", &summary(self.0))?;
        st.serialize_field("moves", &Moves(self.0))?;
        st.end()
    }
}

/// The moves of a run as indented JSON: `{ "summary": …, "moves": [ … ] }`,
/// both exactly as in the CLI's `run --format json`.
pub fn moves_json(run: &Run) -> String {
    serde_json::to_string_pretty(&MovesFile(run)).unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::setup::Setup;
    use crate::view::RunView;

    fn cam_like() -> (String, Setup) {
        let mut setup = Setup::default();
        setup.set_register("01=5").unwrap();
        let program = "G90 G00 X0 Y0 Z10.\nG01 Z-2. F100.\nG91 G45 G03 X10. Y10. J10. D01\n\
                       G90 G98 G81 X5. Y5. Z-3. R2. F80.\nG80 M30\n";
        (program.to_string(), setup)
    }

    #[test]
    fn json_moves_are_the_cli_moves() {
        let (program, setup) = cam_like();
        let run = crate::run(&program, &setup);
        let file: Value = serde_json::from_str(&moves_json(&run)).unwrap();
        let cli = serde_json::to_value(RunView {
            run: &run,
            text: &program,
        })
        .unwrap();
        assert_eq!(file["moves"], cli["moves"]);
        assert_eq!(file["summary"], cli["summary"]);
        assert!(file["moves"].as_array().unwrap().len() >= 4);
    }

    #[test]
    fn csv_has_every_field_of_every_move() {
        for machine in [MachineKind::Mill, MachineKind::Lathe] {
            let (program, mut setup) = match machine {
                MachineKind::Mill => cam_like(),
                MachineKind::Lathe => {
                    let mut s = Setup {
                        machine: MachineKind::Lathe,
                        ..Setup::default()
                    };
                    s.set_register("08=X0.4,Z-0.2").unwrap();
                    (
                        "G50 X120. Z60.\nG00 T0108\nX50. Z3.\nG01 Z-20. F0.2\nG02 X60. Z-25. R5.\nG00 T0100\n"
                            .to_string(),
                        s,
                    )
                }
            };
            setup.machine = machine;
            let run = crate::run(&program, &setup);
            assert!(run.diagnostics.is_empty(), "{:?}", run.diagnostics);
            let csv = moves_csv(&run);
            let lines: Vec<&str> = csv.split("\r\n").filter(|l| !l.is_empty()).collect();
            let header: Vec<&str> = lines[0].split(',').collect();
            assert_eq!(header, csv_columns(machine));
            assert_eq!(lines.len(), run.moves.len() + 1);
            let mut arcs = 0;
            for (m, line) in run.moves.iter().zip(&lines[1..]) {
                let cells: Vec<&str> = line.split(',').collect();
                assert_eq!(cells.len(), header.len());
                let value = serde_json::to_value(move_view(m, machine)).unwrap();
                for (key, v) in flat_move(&value) {
                    let i = header
                        .iter()
                        .position(|h| *h == key)
                        .unwrap_or_else(|| panic!("no CSV column for `{key}`"));
                    match v {
                        Value::Number(n) => {
                            assert_eq!(cells[i].parse::<f64>().unwrap(), n.as_f64().unwrap())
                        }
                        Value::String(s) => assert_eq!(cells[i], s),
                        other => panic!("{key}: {other}"),
                    }
                }
                arcs += usize::from(
                    !cells[header.iter().position(|h| *h == "arc_plane").unwrap()].is_empty(),
                );
            }
            assert!(arcs >= 1, "{machine:?} has an arc row");
        }
    }

    #[test]
    fn behaviour14_16_a_lathe_run_in_polar_interpolation_exports_its_y_columns() {
        // The face point (10, 10) is the lathe's X20. and Y10. (the
        // hypothetical axis C10.).
        let setup = Setup {
            machine: MachineKind::Lathe,
            ..Setup::default()
        };
        let run = crate::run(
            "G98 G00 X40. Z-1.\nG12.1\nG01 X20. C10. F100.\nG13.1\n",
            &setup,
        );
        assert!(!run.has_errors(), "{:?}", run.diagnostics);
        let csv = moves_csv(&run);
        let lines: Vec<&str> = csv.split("\r\n").filter(|l| !l.is_empty()).collect();
        let header: Vec<&str> = lines[0].split(',').collect();
        assert_eq!(header, run_columns(&run));
        assert_eq!(
            &header[4..10],
            ["from_x", "from_y", "from_z", "to_x", "to_y", "to_z"]
        );
        assert!(
            lines[2].starts_with("3,2,feed,,40,,-1,20,10,-1,"),
            "{}",
            lines[2]
        );
        // A turning run keeps its columns without y.
        let turning = crate::run("G00 X40. Z-1.\n", &setup);
        assert_eq!(run_columns(&turning), csv_columns(MachineKind::Lathe));
    }

    #[test]
    fn csv_cells_quote_when_needed() {
        assert_eq!(cell(Some(&Value::from("a,b"))), "\"a,b\"");
        assert_eq!(cell(Some(&Value::from("say \"hi\""))), "\"say \"\"hi\"\"\"");
        assert_eq!(cell(Some(&Value::from(6.0))), "6");
        assert_eq!(cell(Some(&Value::from(-0.125))), "-0.125");
        assert_eq!(cell(Some(&Value::from(12u32))), "12");
        assert_eq!(cell(None), "");
    }

    #[test]
    fn an_empty_run_has_a_header_only() {
        let run = crate::run("", &Setup::default());
        assert_eq!(
            moves_csv(&run),
            format!("{}\r\n", csv_columns(MachineKind::Mill).join(","))
        );
        let v: Value = serde_json::from_str(&moves_json(&run)).unwrap();
        assert_eq!(v["moves"], Value::Array(vec![]));
    }
}
