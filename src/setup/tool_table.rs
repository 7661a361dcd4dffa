//! LinuxCNC's tool table (behaviour 22.9): the file `T1 P1 Z0.5 D0.25 ;note`
//! a LinuxCNC machine keeps, one tool a line. Under the `linuxcnc` profile
//! a T word must name a tool of the table, G43 reads the tool's offsets and
//! G41/G42 half its diameter, and G10 L1/L10/L11 change it (LinuxCNC 2.9
//! documentation, "Tool Table Format" and "Tool Compensation").

use std::collections::BTreeMap;

use serde::{Deserialize, Deserializer, Serialize, Serializer};

use super::{Setup, Units, setup_error};
use crate::diag::Diagnostic;

/// Highest tool number a table holds (LinuxCNC reads an int; the page and
/// the links keep to six digits).
pub const MAX_TABLE_TOOL: u32 = 999_999;

/// The axes a LinuxCNC tool offset has, in its file's order.
pub const OFFSET_AXES: [char; 9] = ['X', 'Y', 'Z', 'A', 'B', 'C', 'U', 'V', 'W'];

/// One tool of the table. Lengths are in the table's units.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct TableTool {
    /// The pocket (P) it sits in.
    #[serde(skip_serializing_if = "is_zero_u32")]
    pub pocket: u32,
    /// Its offsets X Y Z A B C U V W (G43 applies them).
    #[serde(skip_serializing_if = "all_zero")]
    pub offsets: [f64; 9],
    /// Its diameter (D): G41/G42 offset by half of it.
    #[serde(skip_serializing_if = "is_zero")]
    pub diameter: f64,
    /// The lathe insert's front angle (I).
    #[serde(skip_serializing_if = "is_zero")]
    pub front_angle: f64,
    /// The lathe insert's back angle (J).
    #[serde(skip_serializing_if = "is_zero")]
    pub back_angle: f64,
    /// The lathe insert's orientation (Q), 0–9.
    #[serde(skip_serializing_if = "is_zero_u8")]
    pub orientation: u8,
    /// The text after `;`.
    #[serde(skip_serializing_if = "String::is_empty")]
    pub comment: String,
}

fn is_zero(v: &f64) -> bool {
    *v == 0.0
}
fn is_zero_u32(v: &u32) -> bool {
    *v == 0
}
fn is_zero_u8(v: &u8) -> bool {
    *v == 0
}
fn all_zero(v: &[f64; 9]) -> bool {
    v.iter().all(|x| *x == 0.0)
}

impl TableTool {
    /// The Z offset (G43's length).
    pub fn z(&self) -> f64 {
        self.offsets[2]
    }
}

/// The tool table: its units (a LinuxCNC machine's, the INI's
/// LINEAR_UNITS; left out, the setup's) and its tools by number.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct ToolTable {
    /// The units its lengths are in; left out, the setup's.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub units: Option<Units>,
    /// The tools by number.
    #[serde(with = "tool_map")]
    pub tools: BTreeMap<u32, TableTool>,
}

/// What [`ToolTable::read`] found.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct TableRead {
    /// The table, when the text has no error.
    pub table: Option<ToolTable>,
    /// Tools given twice (the first kept).
    pub warnings: Vec<TableProblem>,
    /// Every error, at its line and column.
    pub errors: Vec<TableProblem>,
}

/// A problem of a tool table file, at its line and column (1-based).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct TableProblem {
    /// The line.
    pub line: usize,
    /// The column.
    pub column: usize,
    /// What is wrong.
    pub message: String,
}

impl ToolTable {
    /// Reads LinuxCNC's tool table file format: per line `T` (the tool), `P`
    /// (its pocket), `X Y Z A B C U V W` (offsets), `D` (diameter), `I J`
    /// (front and back angle), `Q` (orientation), then `;` and a comment; a
    /// letter may be lower case, a line may be empty. As LinuxCNC's reader
    /// does, a tool given twice keeps its first line (a warning here).
    /// Returns the table and its warnings, or every error.
    pub fn parse(text: &str) -> Result<(ToolTable, Vec<TableProblem>), Vec<TableProblem>> {
        let mut tools: BTreeMap<u32, TableTool> = BTreeMap::new();
        let mut first_line: BTreeMap<u32, usize> = BTreeMap::new();
        let mut errors = Vec::new();
        let mut warnings = Vec::new();
        for (i, raw) in text.lines().enumerate() {
            let line = i + 1;
            let (body, comment) = match raw.split_once(';') {
                Some((b, c)) => (b, c.trim()),
                None => (raw, ""),
            };
            match parse_line(body, line) {
                Ok(None) => {}
                Ok(Some((n, column, mut tool))) => {
                    tool.comment = comment.to_string();
                    if let Some(first) = first_line.get(&n) {
                        warnings.push(TableProblem {
                            line,
                            column,
                            message: format!(
                                "T{n} is in the table already (line {first}): the first is kept, as LinuxCNC keeps it"
                            ),
                        });
                    } else {
                        first_line.insert(n, line);
                        tools.insert(n, tool);
                    }
                }
                Err(p) => errors.push(p),
            }
        }
        if errors.is_empty() {
            Ok((ToolTable { units: None, tools }, warnings))
        } else {
            Err(errors)
        }
    }

    /// [`ToolTable::parse`] as one value for the page: the table (None
    /// when the text has errors), its warnings and its errors.
    pub fn read(text: &str) -> TableRead {
        match ToolTable::parse(text) {
            Ok((table, warnings)) => TableRead {
                table: Some(table),
                warnings,
                errors: Vec::new(),
            },
            Err(errors) => TableRead {
                table: None,
                warnings: Vec::new(),
                errors,
            },
        }
    }

    /// The table of a file's text, or its first error as a sentence (a
    /// plain link's `tool_table=`).
    pub fn from_text(text: &str) -> Result<ToolTable, String> {
        match ToolTable::parse(text) {
            Ok((table, _)) => Ok(table),
            Err(e) => Err(e.first().map_or_else(String::new, |p| {
                format!(
                    "tool_table line {} column {}: {}",
                    p.line, p.column, p.message
                )
            })),
        }
    }

    /// The table as a LinuxCNC tool table file, one tool a line.
    pub fn to_file(&self) -> String {
        let mut out = String::new();
        for (n, t) in &self.tools {
            out.push_str(&format!("T{n} P{}", t.pocket));
            for (a, v) in OFFSET_AXES.iter().zip(t.offsets) {
                if v != 0.0 {
                    out.push_str(&format!(" {a}{v}"));
                }
            }
            for (a, v) in [('D', t.diameter), ('I', t.front_angle), ('J', t.back_angle)] {
                if v != 0.0 {
                    out.push_str(&format!(" {a}{v}"));
                }
            }
            if t.orientation != 0 {
                out.push_str(&format!(" Q{}", t.orientation));
            }
            if !t.comment.is_empty() {
                out.push_str(&format!(" ;{}", t.comment));
            }
            out.push('\n');
        }
        out
    }
}

impl Setup {
    /// The units the tool table's lengths are in: its own, else the setup's.
    pub fn tool_table_units(&self) -> Units {
        self.tool_table
            .as_ref()
            .and_then(|t| t.units)
            .unwrap_or(self.units)
    }

    /// The tool table's problems (part of [`Setup::validate`]): every length
    /// a dimension the table's units allow, the diameter not negative.
    pub(super) fn validate_tool_table(&self, out: &mut Vec<Diagnostic>) {
        let Some(table) = &self.tool_table else {
            return;
        };
        let max = self.tool_table_units().max_dimension();
        for (n, t) in &table.tools {
            if *n > MAX_TABLE_TOOL {
                out.push(setup_error(
                    "setup-range",
                    format!("tool table T{n} is outside 0 to {MAX_TABLE_TOOL}"),
                ));
            }
            let lengths = OFFSET_AXES.iter().zip(t.offsets).map(|(a, v)| (*a, v));
            for (what, v) in lengths.chain([('D', t.diameter)]) {
                if !v.is_finite() || v.abs() > max + 1e-9 || (what == 'D' && v < 0.0) {
                    out.push(setup_error(
                        "setup-range",
                        format!("tool table T{n} {what} = {v} is outside the table's range (±{max}, D not negative)"),
                    ));
                }
            }
            if t.orientation > 9 {
                out.push(setup_error(
                    "setup-range",
                    format!("tool table T{n} Q = {} is outside 0 to 9", t.orientation),
                ));
            }
        }
    }
}

/// One line's tool: its number, the column of its T, and the tool; None for
/// a line with no words.
fn parse_line(body: &str, line: usize) -> Result<Option<(u32, usize, TableTool)>, TableProblem> {
    let mut tool = TableTool::default();
    let mut number: Option<(u32, usize)> = None;
    let mut pocket = None;
    let bytes = body.as_bytes();
    let mut i = 0;
    let problem = |column: usize, message: String| TableProblem {
        line,
        column,
        message,
    };
    while i < bytes.len() {
        let c = bytes[i];
        if c.is_ascii_whitespace() {
            i += 1;
            continue;
        }
        let column = i + 1;
        let letter = (c as char).to_ascii_uppercase();
        if !letter.is_ascii_alphabetic() {
            return Err(problem(
                column,
                format!(
                    "`{}` is not a tool table word: a line is T<tool> P<pocket> X… Z… D<diameter> … ;comment",
                    body[i..].chars().next().unwrap_or(' ')
                ),
            ));
        }
        let start = i + 1;
        let mut end = start;
        while end < bytes.len() && !bytes[end].is_ascii_whitespace() {
            end += 1;
        }
        let text = &body[start..end];
        let value: f64 = match text.parse::<f64>() {
            Ok(v) if v.is_finite() && !text.is_empty() => v,
            _ => {
                return Err(problem(
                    column,
                    format!("{letter}{text}: {letter} needs a number"),
                ));
            }
        };
        let whole = |what: &str, max: u32| -> Result<u32, TableProblem> {
            if value.fract() != 0.0 || value < 0.0 || value > f64::from(max) {
                Err(problem(
                    column,
                    format!("{letter}{text}: {what} is a whole number 0 to {max}"),
                ))
            } else {
                Ok(value as u32)
            }
        };
        match letter {
            'T' => number = Some((whole("the tool number", MAX_TABLE_TOOL)?, column)),
            'P' => pocket = Some(whole("the pocket", MAX_TABLE_TOOL)?),
            'D' => tool.diameter = value,
            'I' => tool.front_angle = value,
            'J' => tool.back_angle = value,
            'Q' => tool.orientation = whole("the orientation", 9)? as u8,
            a => match OFFSET_AXES.iter().position(|x| *x == a) {
                Some(k) => tool.offsets[k] = value,
                None => {
                    return Err(problem(
                        column,
                        format!(
                            "{letter}{text}: {letter} is not a tool table word (T P X Y Z A B C U V W D I J Q)"
                        ),
                    ));
                }
            },
        }
        i = end;
    }
    if let Some((n, column)) = number {
        tool.pocket = pocket.unwrap_or(0);
        return Ok(Some((n, column, tool)));
    }
    if pocket.is_some() || tool != TableTool::default() {
        return Err(problem(
            1,
            "a tool table line needs T, the tool's number".into(),
        ));
    }
    Ok(None)
}

mod tool_map {
    use super::*;

    pub fn serialize<S: Serializer>(
        map: &BTreeMap<u32, TableTool>,
        s: S,
    ) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let mut m = s.serialize_map(Some(map.len()))?;
        for (k, v) in map {
            m.serialize_entry(&k.to_string(), v)?;
        }
        m.end()
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(
        d: D,
    ) -> Result<BTreeMap<u32, TableTool>, D::Error> {
        let raw = BTreeMap::<String, TableTool>::deserialize(d)?;
        let mut out = BTreeMap::new();
        for (k, v) in raw {
            let n = k
                .trim()
                .parse::<u32>()
                .ok()
                .filter(|n| *n <= MAX_TABLE_TOOL)
                .ok_or_else(|| {
                    serde::de::Error::custom(format!(
                        "tool `{k}` of the tool table is not a number 0 to {MAX_TABLE_TOOL}"
                    ))
                })?;
            if out.insert(n, v).is_some() {
                return Err(serde::de::Error::custom(format!(
                    "tool {n} is in the tool table twice"
                )));
            }
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn behaviour22_9_tool_table_file_lines_words_and_comments() {
        let (t, warnings) = ToolTable::parse(
            "T1 P1 Z+0.511 D0.125 ;end mill\n\nt2 p3 z-1.5 x0.2 q3\n; header\nT1 P9 Z9\n",
        )
        .unwrap();
        assert_eq!(t.tools.len(), 2);
        assert_eq!(t.tools[&1].z(), 0.511);
        assert_eq!(t.tools[&1].diameter, 0.125);
        assert_eq!(t.tools[&1].comment, "end mill");
        assert_eq!(t.tools[&2].pocket, 3);
        assert_eq!(t.tools[&2].offsets[0], 0.2);
        assert_eq!(t.tools[&2].orientation, 3);
        assert_eq!(warnings.len(), 1);
        assert_eq!((warnings[0].line, warnings[0].column), (5, 1));
        let again = ToolTable::parse(&t.to_file()).unwrap().0;
        assert_eq!(again, t);
    }

    #[test]
    fn behaviour22_9_tool_table_errors_say_line_and_column() {
        let e = ToolTable::parse("T1 P1 Z0.5\nT2 P2 Zx\nP3 Z1\nT4 K1\nT1.5\n").unwrap_err();
        let at: Vec<(usize, usize)> = e.iter().map(|p| (p.line, p.column)).collect();
        assert_eq!(at, vec![(2, 7), (3, 1), (4, 4), (5, 1)]);
    }
}
