//! The setup document: everything a run depends on besides the program text —
//! machine kind, offset registers, work offsets, start position, units and the
//! settings that controls disagree on (behaviour 1, 2, 3.3, 5). It is read from
//! JSON (`--setup FILE`, the page, share links), versioned from day one, and
//! strict: unknown fields and out-of-range values are errors, not guesses.

use std::collections::BTreeMap;
use std::fmt;

use serde::{Deserialize, Serialize};

use crate::diag::{Diagnostic, Span};

mod choices;
mod positions;
pub mod programs;
mod registers;
mod settings;
mod specs;
mod tool_table;
mod tools;

pub use choices::*;
pub use positions::{MachinePositions, PositionsInEffect};
use registers::register_map;
pub use registers::{LatheRegister, MAX_TIP, MillPart, MillRegister};
pub use settings::*;
pub use tool_table::{MAX_TABLE_TOOL, OFFSET_AXES, TableProblem, TableRead, TableTool, ToolTable};
pub use tools::{MAX_TOOL, Tool};

/// The only document version this build writes; every version up to it reads.
pub const SETUP_VERSION: u32 = 1;
/// Largest offset value, metric and inch alike (seed 001, table 3.4.1.2).
pub const MAX_OFFSET_VALUE: f64 = 999.999;
/// Largest dimension word: ±99999.999 mm (behaviour 1.17).
pub const MAX_DIMENSION_MM: f64 = 99_999.999;
/// Largest dimension word: ±9999.9999 in (behaviour 1.17).
pub const MAX_DIMENSION_INCH: f64 = 9_999.999_9;
/// Default number of offset registers (01–99, behaviour 1.17).
pub const DEFAULT_TABLE_SIZE: u16 = 99;
/// Largest table a setup may ask for.
pub const MAX_TABLE_SIZE: u16 = 999;
/// Most additional work systems a setup holds (Haas G154 P1–P99; Fanuc's
/// G54.1 reads the first 48).
pub const MAX_EXTENDED_WORK: u16 = 99;
/// The rapid rate a setup leaves out, in mm/min (behaviour 7.41).
pub const DEFAULT_RAPID_RATE: f64 = 24_000.0;
/// The largest rapid rate a setup may give, in its units per minute.
pub const MAX_RAPID_RATE: f64 = 1_000_000.0;
/// The largest arc radius tolerance a setup may give, in its units
/// (behaviour 7.56): past it the check would pass a different arc.
pub const MAX_ARC_TOLERANCE: f64 = 10.0;

/// Milling machine (G43/G44/G45–G48) or lathe (T-code offsets).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum MachineKind {
    /// Three linear axes X, Y, Z.
    #[default]
    Mill,
    /// X (diameter) and Z, U/W incremental, T-code offsets.
    Lathe,
}

impl MachineKind {
    /// "mill" or "lathe".
    pub fn as_str(self) -> &'static str {
        match self {
            MachineKind::Mill => "mill",
            MachineKind::Lathe => "lathe",
        }
    }
}

/// Metric (G21) or inch (G20).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Units {
    /// Millimetres, G21.
    #[default]
    Mm,
    /// Inches, G20.
    Inch,
}

impl Units {
    /// Millimetres in one unit.
    pub fn mm(self) -> f64 {
        match self {
            Units::Mm => 1.0,
            Units::Inch => 25.4,
        }
    }
    /// The least input increment (behaviour 1.15): 0.001 mm or 0.0001 in.
    pub fn increment(self) -> f64 {
        match self {
            Units::Mm => 0.001,
            Units::Inch => 0.0001,
        }
    }
    /// Decimal places a control shows in this unit.
    pub fn decimals(self) -> usize {
        match self {
            Units::Mm => 3,
            Units::Inch => 4,
        }
    }
    /// Largest dimension word in this unit.
    pub fn max_dimension(self) -> f64 {
        match self {
            Units::Mm => MAX_DIMENSION_MM,
            Units::Inch => MAX_DIMENSION_INCH,
        }
    }
    /// "mm" or "inch".
    pub fn as_str(self) -> &'static str {
        match self {
            Units::Mm => "mm",
            Units::Inch => "inch",
        }
    }
    /// The G code that selects this unit.
    pub fn gcode(self) -> &'static str {
        match self {
            Units::Mm => "G21",
            Units::Inch => "G20",
        }
    }
}

/// A point of the setup (start, reference, work offset), in setup units.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Position {
    /// X (diameter on a lathe).
    pub x: f64,
    /// Y (unused on a lathe).
    pub y: f64,
    /// Z.
    pub z: f64,
}

impl Position {
    /// As an array indexed X, Y, Z.
    pub fn to_array(self) -> [f64; 3] {
        [self.x, self.y, self.z]
    }
}

/// Work coordinate systems G54–G59, as offsets of their zero from machine
/// zero, and the external work offset added to every system.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct WorkOffsets {
    /// The external workpiece zero point offset (Fanuc EXT, `G10 L2 P0`;
    /// the Haas G52/common row): added to every work system's zero
    /// (behaviour 17.9).
    #[serde(rename = "EXT", skip_serializing_if = "is_default")]
    pub ext: Position,
    #[serde(rename = "G54", skip_serializing_if = "is_default")]
    #[allow(missing_docs)]
    pub g54: Position,
    #[serde(rename = "G55", skip_serializing_if = "is_default")]
    #[allow(missing_docs)]
    pub g55: Position,
    #[serde(rename = "G56", skip_serializing_if = "is_default")]
    #[allow(missing_docs)]
    pub g56: Position,
    #[serde(rename = "G57", skip_serializing_if = "is_default")]
    #[allow(missing_docs)]
    pub g57: Position,
    #[serde(rename = "G58", skip_serializing_if = "is_default")]
    #[allow(missing_docs)]
    pub g58: Position,
    #[serde(rename = "G59", skip_serializing_if = "is_default")]
    #[allow(missing_docs)]
    pub g59: Position,
    /// LinuxCNC's G59.1–G59.3, the seventh to ninth systems (behaviour
    /// 22.14); the other profiles select none of them.
    #[serde(rename = "G59.1", skip_serializing_if = "is_default")]
    pub g59_1: Position,
    #[serde(rename = "G59.2", skip_serializing_if = "is_default")]
    #[allow(missing_docs)]
    pub g59_2: Position,
    #[serde(rename = "G59.3", skip_serializing_if = "is_default")]
    #[allow(missing_docs)]
    pub g59_3: Position,
}

impl WorkOffsets {
    /// The offset of G54 + `index` (0 = G54 … 5 = G59, 6–8 = G59.1–G59.3).
    pub fn get(&self, index: usize) -> Position {
        match index {
            0 => self.g54,
            1 => self.g55,
            2 => self.g56,
            3 => self.g57,
            4 => self.g58,
            5 => self.g59,
            6 => self.g59_1,
            7 => self.g59_2,
            _ => self.g59_3,
        }
    }
    /// The offset of P `p` of `G10 L2` (0 = EXT, 1 = G54 … 6 = G59, 7–9 =
    /// LinuxCNC's G59.1–G59.3).
    pub fn by_p(&self, p: usize) -> Position {
        match p {
            0 => self.ext,
            n => self.get(n - 1),
        }
    }
    /// The offset of P `p` of `G10 L2`, to change.
    pub fn by_p_mut(&mut self, p: usize) -> &mut Position {
        match p {
            0 => &mut self.ext,
            1 => &mut self.g54,
            2 => &mut self.g55,
            3 => &mut self.g56,
            4 => &mut self.g57,
            5 => &mut self.g58,
            6 => &mut self.g59,
            7 => &mut self.g59_1,
            8 => &mut self.g59_2,
            _ => &mut self.g59_3,
        }
    }
    /// The name of P `p` of `G10 L2`: "EXT", "G54" … "G59", "G59.1" …
    /// "G59.3".
    pub fn name_of_p(p: usize) -> &'static str {
        [
            "EXT", "G54", "G55", "G56", "G57", "G58", "G59", "G59.1", "G59.2", "G59.3",
        ][p.min(9)]
    }
    fn all(&self) -> [(&'static str, Position); 10] {
        [
            ("EXT", self.ext),
            ("G54", self.g54),
            ("G55", self.g55),
            ("G56", self.g56),
            ("G57", self.g57),
            ("G58", self.g58),
            ("G59", self.g59),
            ("G59.1", self.g59_1),
            ("G59.2", self.g59_2),
            ("G59.3", self.g59_3),
        ]
    }
}

fn is_zero(v: &f64) -> bool {
    *v == 0.0
}

/// Documents leave out what is at its default: shorter links, and a decoded
/// document shows what its author changed.
fn is_default<T: Default + PartialEq>(v: &T) -> bool {
    *v == T::default()
}

fn is_default_table(n: &u16) -> bool {
    *n == DEFAULT_TABLE_SIZE
}

/// The setup document (see the README for its JSON form).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Setup {
    /// Document version; this build reads 1.
    pub version: u32,
    /// Mill or lathe.
    pub machine: MachineKind,
    /// Units at program start (G20/G21 state) and of the setup's positions.
    pub units: Units,
    /// Settings where controls disagree.
    #[serde(skip_serializing_if = "is_default")]
    pub settings: Settings,
    /// Number of offset registers (01 to this).
    #[serde(skip_serializing_if = "is_default_table")]
    pub table_size: u16,
    /// Where the tool starts, in the G54 system; left out (all zero), the
    /// positions of setting `machine_positions` (behaviour 13.15).
    #[serde(skip_serializing_if = "is_default")]
    pub start: Position,
    /// The reference position G28 returns to, in machine coordinates; left
    /// out (all zero), that of setting `machine_positions` (13.15).
    #[serde(skip_serializing_if = "is_default")]
    pub reference: Position,
    /// The second reference position (G30, G30 P2), in machine coordinates;
    /// left out, the first.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub second_reference: Option<Position>,
    /// The third reference position (G30 P3); left out, the first.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub third_reference: Option<Position>,
    /// The fourth reference position (G30 P4); left out, the first.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fourth_reference: Option<Position>,
    /// G54–G59 zero points in machine coordinates.
    #[serde(skip_serializing_if = "is_default")]
    pub work_offsets: WorkOffsets,
    /// The additional work systems' zero points in machine coordinates,
    /// keyed by their P number (G54.1 Pn, G154 Pn); one left out is at
    /// machine zero.
    #[serde(with = "register_map", skip_serializing_if = "BTreeMap::is_empty")]
    pub extended_work_offsets: BTreeMap<u16, Position>,
    /// Mill registers read by D and H.
    #[serde(with = "register_map", skip_serializing_if = "BTreeMap::is_empty")]
    pub offsets: BTreeMap<u16, MillRegister>,
    /// Lathe registers read by the offset part of T codes.
    #[serde(with = "register_map", skip_serializing_if = "BTreeMap::is_empty")]
    pub lathe_offsets: BTreeMap<u16, LatheRegister>,
    /// The library: programs kept with the document by number, each text
    /// opening with its own header (behaviour 9.10, 19.10).
    #[serde(skip_serializing_if = "BTreeMap::is_empty")]
    pub programs: BTreeMap<u32, String>,
    /// The tool list, keyed by tool number: each tool's size, for drawing
    /// it (behaviour 13.16); compensation reads the registers, not this.
    #[serde(with = "register_map", skip_serializing_if = "BTreeMap::is_empty")]
    pub tools: BTreeMap<u16, Tool>,
    /// LinuxCNC's tool table (behaviour 22.9): under `linuxcnc`, what T,
    /// G43 and G41/G42 read; left out, they read the registers.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tool_table: Option<ToolTable>,
}

impl Default for Setup {
    fn default() -> Self {
        Setup {
            version: SETUP_VERSION,
            machine: MachineKind::Mill,
            units: Units::Mm,
            settings: Settings::default(),
            table_size: DEFAULT_TABLE_SIZE,
            start: Position::default(),
            reference: Position::default(),
            second_reference: None,
            third_reference: None,
            fourth_reference: None,
            work_offsets: WorkOffsets::default(),
            extended_work_offsets: BTreeMap::new(),
            offsets: BTreeMap::new(),
            lathe_offsets: BTreeMap::new(),
            programs: BTreeMap::new(),
            tools: BTreeMap::new(),
            tool_table: None,
        }
    }
}

/// A setup document that could not be read.
#[derive(Clone, Debug, PartialEq)]
pub struct SetupError {
    /// Every problem found, as diagnostics with code `setup-…` and line 0.
    pub diagnostics: Vec<Diagnostic>,
}

impl fmt::Display for SetupError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, d) in self.diagnostics.iter().enumerate() {
            if i > 0 {
                writeln!(f)?;
            }
            write!(f, "{}[{}]: {}", d.severity.as_str(), d.code, d.message)?;
        }
        Ok(())
    }
}

impl std::error::Error for SetupError {}

fn setup_error(code: &'static str, message: String) -> Diagnostic {
    Diagnostic::error(code, Span::default(), message)
}

impl Setup {
    /// Reads and validates a setup document.
    pub fn from_json(text: &str) -> Result<Setup, SetupError> {
        let setup: Setup = serde_json::from_str(text).map_err(|e| SetupError {
            diagnostics: vec![setup_error("setup-syntax", format!("setup document: {e}"))],
        })?;
        setup.validated()
    }

    /// Returns the setup if every value is in range, or every problem found.
    pub fn validated(self) -> Result<Setup, SetupError> {
        let diagnostics = self.validate();
        if diagnostics.is_empty() {
            Ok(self)
        } else {
            Err(SetupError { diagnostics })
        }
    }

    /// Every problem with this setup (empty when it is usable).
    pub fn validate(&self) -> Vec<Diagnostic> {
        let mut out = programs::check(&self.programs);
        if self.version == 0 || self.version > SETUP_VERSION {
            out.push(setup_error(
                "setup-version",
                format!(
                    "setup version {} is not known to this build (it reads versions 1 to {SETUP_VERSION})",
                    self.version
                ),
            ));
        }
        if self.table_size == 0 || self.table_size > MAX_TABLE_SIZE {
            out.push(setup_error(
                "setup-range",
                format!(
                    "table_size {} is outside 1 to {MAX_TABLE_SIZE}",
                    self.table_size
                ),
            ));
        }
        let check_value = |out: &mut Vec<Diagnostic>, what: String, v: f64| {
            if !v.is_finite() || v.abs() > MAX_OFFSET_VALUE + 1e-9 {
                out.push(setup_error(
                    "setup-range",
                    format!("{what} = {v} is outside ±999.999 (seed 001, table 3.4.1.2)"),
                ));
            }
        };
        let check_number = |out: &mut Vec<Diagnostic>, n: u16| {
            if n == 0 || n > self.table_size {
                out.push(setup_error(
                    "setup-range",
                    format!(
                        "register {n:02} is outside 01 to {:02} (register 00 always reads 0)",
                        self.table_size
                    ),
                ));
            }
        };
        let memory = self.settings.offset_memory();
        for (&n, r) in &self.offsets {
            check_number(&mut out, n);
            let (h, d) = (r.h_part(), r.d_part());
            let split = r.is_split();
            let tables: &[(&str, registers::MillPart)] = if split {
                &[("H", h), ("D", d)]
            } else {
                &[("", h)]
            };
            for (t, part) in tables {
                check_value(
                    &mut out,
                    format!("register {t}{n:02} geometry"),
                    part.geometry,
                );
                check_value(&mut out, format!("register {t}{n:02} wear"), part.wear);
                check_value(
                    &mut out,
                    format!("register {t}{n:02} geometry + wear"),
                    part.value(),
                );
            }
            if split && memory != OffsetMemory::C {
                out.push(setup_error(
                    "setup-memory",
                    format!(
                        "register {n:02} gives H and D different values (h, d): that is offset memory C, and this setup's offset_memory is {} ({})",
                        memory.as_str(),
                        match memory {
                            OffsetMemory::A => "one value per number, read by H and D",
                            _ => "one geometry and wear per number, read by H and D",
                        }
                    ),
                ));
            }
        }
        for (&n, r) in &self.lathe_offsets {
            check_number(&mut out, n);
            check_value(&mut out, format!("lathe register {n:02} X"), r.x);
            check_value(&mut out, format!("lathe register {n:02} Z"), r.z);
            check_value(&mut out, format!("lathe register {n:02} X wear"), r.x_wear);
            check_value(&mut out, format!("lathe register {n:02} Z wear"), r.z_wear);
            check_value(&mut out, format!("lathe register {n:02} R"), r.r);
            check_value(&mut out, format!("lathe register {n:02} R wear"), r.r_wear);
            if r.t > MAX_TIP {
                out.push(setup_error(
                    "setup-range",
                    format!(
                        "lathe register {n:02} tip direction T = {} is outside 0 to {MAX_TIP}",
                        r.t
                    ),
                ));
            }
        }
        self.validate_tools(&mut out);
        self.validate_tool_table(&mut out);
        let max = self.units.max_dimension();
        let mut check_pos = |what: &str, p: Position| {
            for (axis, v) in [("x", p.x), ("y", p.y), ("z", p.z)] {
                if !v.is_finite() || v.abs() > max + 1e-9 {
                    out.push(setup_error(
                        "setup-range",
                        format!(
                            "{what}.{axis} = {v} is outside ±{max} {}",
                            self.units.as_str()
                        ),
                    ));
                }
            }
        };
        check_pos("start", self.start);
        check_pos("reference", self.reference);
        for (name, p) in self.work_offsets.all() {
            check_pos(&format!("work_offsets.{name}"), p);
        }
        for (name, p) in [
            ("second_reference", self.second_reference),
            ("third_reference", self.third_reference),
            ("fourth_reference", self.fourth_reference),
        ] {
            if let Some(p) = p {
                check_pos(name, p);
            }
        }
        let mut extended = Vec::new();
        for (&n, &p) in &self.extended_work_offsets {
            check_pos(&format!("extended_work_offsets.{n:02}"), p);
            if n == 0 || n > MAX_EXTENDED_WORK {
                extended.push(n);
            }
        }
        for n in extended {
            out.push(setup_error(
                "setup-range",
                format!(
                    "extended work offset {n:02} is outside 01 to {MAX_EXTENDED_WORK} (G54.1 P1–P48, G154 P1–P99)"
                ),
            ));
        }
        if let Some(r) = self.settings.rapid_rate
            && (!r.is_finite() || r <= 0.0 || r > MAX_RAPID_RATE)
        {
            out.push(setup_error(
                "setup-range",
                format!(
                    "settings.rapid_rate = {r} must be more than 0 and at most {MAX_RAPID_RATE} (units per minute)"
                ),
            ));
        }
        if let Some(t) = self.settings.arc_tolerance
            && (!t.is_finite() || t <= 0.0 || t > MAX_ARC_TOLERANCE)
        {
            out.push(setup_error(
                "setup-range",
                format!(
                    "settings.arc_tolerance = {t} must be more than 0 and at most {MAX_ARC_TOLERANCE} (setup units)"
                ),
            ));
        }
        if let Some(d) = self.settings.peck_retract
            && (!d.is_finite() || d < 0.0 || d > max)
        {
            out.push(setup_error(
                "setup-range",
                format!("settings.peck_retract = {d} must be 0 to {max}"),
            ));
        }
        if let Some(n) = self.settings.cutter_blocks_without_motion
            && n > MAX_CUTTER_BLOCKS_WITHOUT_MOTION
        {
            out.push(setup_error(
                "setup-range",
                format!(
                    "settings.cutter_blocks_without_motion = {n} must be 0 to {MAX_CUTTER_BLOCKS_WITHOUT_MOTION}"
                ),
            ));
        }
        if self.machine == MachineKind::Lathe && (self.settings.mirror.x || self.settings.mirror.y)
        {
            out.push(setup_error(
                "setup-mirror",
                "mirror image switches apply to the mill only".to_string(),
            ));
        }
        out
    }

    /// The document as pretty JSON.
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_default()
    }

    /// Reference position `n` (1 to 4; G28 returns to 1, G30 to 2–4), in
    /// setup units: an unset one is the first.
    pub fn reference_point(&self, n: u8) -> Position {
        match n {
            2 => self.second_reference,
            3 => self.third_reference,
            4 => self.fourth_reference,
            _ => None,
        }
        .unwrap_or_else(|| self.first_reference())
    }

    /// The value a D code reads from register `n` (00 and unset read 0):
    /// in offset memory A and B the number's one value, which H reads too;
    /// in C the D table's (behaviour 17.1). Kept for the callers that read
    /// D; [`Setup::d_value`] and [`Setup::h_value`] say which table.
    pub fn mill_value(&self, n: u16) -> f64 {
        self.d_value(n)
    }

    /// The value an H code reads from register `n`: geometry + wear of the
    /// number (memory A, B) or of its H table (C) (behaviour 17.1).
    pub fn h_value(&self, n: u16) -> f64 {
        self.offsets.get(&n).map_or(0.0, MillRegister::value)
    }

    /// The value a D code reads from register `n`: geometry + wear of the
    /// number (memory A, B) or of its D table (C) (behaviour 17.1).
    pub fn d_value(&self, n: u16) -> f64 {
        self.offsets.get(&n).map_or(0.0, |r| r.d_part().value())
    }

    /// Lathe register `n` (00 and unset read 0).
    pub fn lathe_register(&self, n: u16) -> LatheRegister {
        self.lathe_offsets.get(&n).copied().unwrap_or_default()
    }

    /// The rapid traverse rate in mm/min (behaviour 7.41): the setting, or
    /// 24,000 mm/min, near the rapids of a small machining centre or
    /// lathe (Haas VF-2 25.4 m/min, ST-10 24 m/min).
    pub fn rapid_rate_mm(&self) -> f64 {
        self.settings
            .rapid_rate
            .map_or(DEFAULT_RAPID_RATE, |r| r * self.units.mm())
    }

    /// How far apart an arc's start and end may lie from its centre, in
    /// millimetres (behaviour 2.13, 7.56): the setting (Fanuc parameter
    /// 3410, in setup units), or 0.01 mm in a metric program and 0.0005 in
    /// in an inch one (`units` is the program's units at the arc).
    pub fn arc_tolerance_mm(&self, units: Units) -> f64 {
        match self.settings.arc_tolerance {
            Some(t) => t * self.units.mm(),
            None => match units {
                Units::Mm => 0.01,
                Units::Inch => 0.0005 * 25.4,
            },
        }
    }

    /// The G73/G83 retract amount in millimetres.
    pub fn peck_retract_mm(&self) -> f64 {
        match self.settings.peck_retract {
            Some(d) => d * self.units.mm(),
            // LinuxCNC's G73/G83 back off 0.010 in whatever the units
            // (`rs274 -g`, behaviour 22.3).
            None if self.settings.control == Control::Linuxcnc => 0.254,
            None => match self.units {
                Units::Mm => 1.0,
                Units::Inch => 0.04 * 25.4,
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn default_document_round_trips() {
        let s = Setup::default();
        let back = Setup::from_json(&s.to_json()).unwrap();
        assert_eq!(s, back);
    }

    #[test]
    fn registers_accept_numbers_and_objects() {
        let s = Setup::from_json(
            r#"{"version":1,"offsets":{"01":5.0,"2":{"geometry":10,"wear":-0.05}}}"#,
        )
        .unwrap();
        assert_eq!(s.mill_value(1), 5.0);
        assert!((s.mill_value(2) - 9.95).abs() < 1e-12);
        assert_eq!(s.mill_value(0), 0.0);
        assert!(s.to_json().contains("\"01\": 5.0"));
    }

    #[test]
    fn unknown_setting_is_an_error() {
        let e = Setup::from_json(r#"{"settings":{"decimal":"x"}}"#).unwrap_err();
        assert_eq!(e.diagnostics[0].code, "setup-syntax");
        assert!(e.to_string().contains("unknown field `decimal`"), "{e}");
    }

    #[test]
    fn register_value_out_of_range_is_an_error() {
        // Seed 001: offset values are 0 to ±999.999.
        let e = Setup::from_json(r#"{"offsets":{"01":1000.0}}"#).unwrap_err();
        assert_eq!(e.diagnostics[0].code, "setup-range");
        assert!(e.to_string().contains("999.999"));
        let e = Setup::from_json(r#"{"offsets":{"100":1.0}}"#).unwrap_err();
        assert!(e.to_string().contains("outside 01 to 99"), "{e}");
    }

    #[test]
    fn unknown_version_is_an_error() {
        let e = Setup::from_json(r#"{"version":2}"#).unwrap_err();
        assert_eq!(e.diagnostics[0].code, "setup-version");
    }

    #[test]
    fn register_specs_from_the_command_line() {
        let mut s = Setup::default();
        s.set_register("01=5.0").unwrap();
        s.set_register("1=-2.5").unwrap();
        assert_eq!(s.mill_value(1), -2.5);
        s.set_register("3=1.0,W-0.1").unwrap();
        assert!((s.mill_value(3) - 0.9).abs() < 1e-12);
        assert!(s.set_register("x=1").is_err());
        assert!(s.set_register("01=abc").is_err());
        s.machine = MachineKind::Lathe;
        s.set_register("08=X0.4,Z-0.2").unwrap();
        assert_eq!(s.lathe_register(8).x_value(), 0.4);
        assert_eq!(s.lathe_register(8).z_value(), -0.2);
        assert!(s.set_register("08=Y1").is_err());
    }

    #[test]
    fn mirror_is_a_list_of_axes() {
        let s = Setup::from_json(r#"{"settings":{"mirror":["x"]}}"#).unwrap();
        assert!(s.settings.mirror.x && !s.settings.mirror.y);
        assert!(Setup::from_json(r#"{"settings":{"mirror":["q"]}}"#).is_err());
    }
}
