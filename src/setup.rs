//! The setup document: everything a run depends on besides the program text —
//! machine kind, offset registers, work offsets, start position, units and the
//! settings that controls disagree on (behaviour 1, 2, 3.3, 5). It is read from
//! JSON (`--setup FILE`, the page, share links), versioned from day one, and
//! strict: unknown fields and out-of-range values are errors, not guesses.

use std::collections::BTreeMap;
use std::fmt;

use serde::{Deserialize, Deserializer, Serialize, Serializer};

use crate::diag::{Diagnostic, Span};

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

/// How a dimension word without a decimal point is read (behaviour 1.15).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum DecimalInput {
    /// Standard Fanuc/YASNAC: the least input increment. `X12345` = 12.345 mm.
    #[default]
    Increment,
    /// Calculator type: the value in units. `X12345` = 12345 mm.
    Calculator,
}

/// What `G43 H…` does in a block with no Z word (behaviour 3.3).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum LengthOffsetWithoutZ {
    /// Z moves by the offset amount in that block (seed 001, YASNAC).
    #[default]
    Move,
    /// No motion; the next Z move lands offset (Fanuc parameter TOS, LinuxCNC).
    NextZ,
}

/// How the lathe offset table's X values are read (behaviour 5).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum LatheXOffset {
    /// X offsets are diameter values, added to X as they are.
    #[default]
    Diameter,
    /// X offsets are radius values, doubled on the diameter axis.
    Radius,
}

/// Mirror image switches (behaviour 2), written as a list of axis names.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Mirror {
    /// Reverse movements along X.
    pub x: bool,
    /// Reverse movements along Y.
    pub y: bool,
}

impl Mirror {
    /// Per-axis switches, indexed X, Y, Z.
    pub fn axes(self) -> [bool; 3] {
        [self.x, self.y, false]
    }
}

impl Serialize for Mirror {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut axes = Vec::new();
        if self.x {
            axes.push("x");
        }
        if self.y {
            axes.push("y");
        }
        axes.serialize(s)
    }
}

impl<'de> Deserialize<'de> for Mirror {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let axes = Vec::<String>::deserialize(d)?;
        let mut m = Mirror::default();
        for a in axes {
            match a.to_ascii_lowercase().as_str() {
                "x" => m.x = true,
                "y" => m.y = true,
                other => {
                    return Err(serde::de::Error::custom(format!(
                        "mirror axis `{other}` is not one of `x`, `y`"
                    )));
                }
            }
        }
        Ok(m)
    }
}

/// The control whose manual a program is written for (behaviour 12): it
/// gives the default of every setting on which controls disagree (each
/// setting of that kind is an `Option`, read through its accessor, and a
/// value set in the setup wins over the control's default).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Control {
    /// Yaskawa YASNAC (PC NC, J50M/J50L): the seeds' control, the default.
    #[default]
    Yasnac,
    /// Fanuc 0i-MF/TF and the 30i family (G-code system A on the lathe).
    Fanuc,
    /// Haas mills and lathes (the NGC operator's manuals).
    Haas,
}

impl Control {
    /// Every control, in the order the page lists them.
    pub const ALL: [Control; 3] = [Control::Yasnac, Control::Fanuc, Control::Haas];

    /// "yasnac", "fanuc" or "haas".
    pub fn as_str(self) -> &'static str {
        match self {
            Control::Yasnac => "yasnac",
            Control::Fanuc => "fanuc",
            Control::Haas => "haas",
        }
    }

    /// The control's name as its maker writes it.
    pub fn name(self) -> &'static str {
        match self {
            Control::Yasnac => "YASNAC",
            Control::Fanuc => "Fanuc",
            Control::Haas => "Haas",
        }
    }
}

/// What two G codes of one modal group in a block do (behaviour 1.11, 7.17).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SameGroupCodes {
    /// An error: the block is refused (YASNAC: an input error).
    Error,
    /// The last one written is in effect, with a warning that names the one
    /// it replaces (Fanuc: "only the last G code specified is valid").
    LastWins,
}

/// A decimal point in the P word of a dwell (G04, and the dwell at the
/// bottom of a canned cycle) (behaviour 1.23, 7.26).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum DwellPDecimalPoint {
    /// P is a whole number of milliseconds; `P3.` is an error (Fanuc,
    /// YASNAC: a decimal point is not allowed in P).
    Error,
    /// `P3.` is 3 seconds and `P3` 3 milliseconds (Haas G04).
    Seconds,
}

/// What G12/G13 mean on the mill (behaviour 7.20, 14.13).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum CirclePocket {
    /// Haas circular pocket milling: I, K, Q, L, D, Z, F.
    Haas,
    /// Not a code of the control: an alarm.
    Alarm,
}

/// The lathe's G-code system (behaviour 7.18): which numbers the single
/// cycles, coordinate setting, feed modes and inch/metric have.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum GCodeSystem {
    /// System A: G90/G92/G94 are the single cycles, G50 sets coordinates,
    /// X/Z absolute and U/W incremental, G98/G99 feed per minute/revolution.
    A,
    /// System B: G90/G91 absolute/incremental, G77/G78/G79 the single cycles,
    /// G92 sets coordinates, G94/G95 feed per minute/revolution.
    B,
    /// System C: as B, with the single cycles G20/G21/G24 and inch/metric
    /// G70/G71.
    C,
}

impl GCodeSystem {
    /// "A", "B" or "C".
    pub fn as_str(self) -> &'static str {
        match self {
            GCodeSystem::A => "A",
            GCodeSystem::B => "B",
            GCodeSystem::C => "C",
        }
    }
}

/// What G28 or G30 without an axis word returns (behaviour 13.5, 7.21).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ReturnWithoutAxes {
    /// Every axis returns (Haas: "when no axis is specified, all axes
    /// return").
    AllAxes,
    /// No axis moves: only the axes named return (Fanuc), with a warning.
    NoAxis,
}

/// How a program names the additional work coordinate systems (behaviour
/// 13.3, 7.22).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum ExtendedWork {
    /// `G54.1 P1`–`P48`, or `G54 P1`–`P48` (Fanuc).
    #[serde(rename = "g54_1")]
    G54_1,
    /// `G154 P1`–`P99` (Haas).
    #[serde(rename = "g154")]
    G154,
}

impl ExtendedWork {
    /// The setting's value as written.
    pub fn as_str(self) -> &'static str {
        match self {
            ExtendedWork::G54_1 => "g54_1",
            ExtendedWork::G154 => "g154",
        }
    }
}

/// How G68's R reads in G91 (behaviour 13.10, 7.23; Fanuc parameter RIN, No.
/// 5400#0).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum RotationAngle {
    /// R is the angle, whatever G90/G91 say (RIN = 0, the standard setting).
    #[default]
    Absolute,
    /// In G91, R is added to the angle of the rotation in force (RIN = 1).
    DistanceMode,
}

/// Cutter compensation start-up and cancel type (behaviour 16.3, 16.10;
/// Fanuc parameter SUP, No. 5003#0; Haas setting 43).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum CutterStartUp {
    /// Type A: the start-up block ends perpendicular to the next block (a
    /// cancel starts perpendicular to the block before).
    A,
    /// Type B: the start-up block's end is compensated as a corner too (the
    /// intersection, or a vector perpendicular to each block).
    B,
}

/// How cutter compensation goes round an outside corner in offset mode
/// (behaviour 16.6, 16.7).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum CutterOutsideCorner {
    /// Fanuc: the intersection of the offset paths at 90° or more, the
    /// extra vectors under 90°.
    Vectors,
    /// An arc of the compensation radius about the corner (Haas setting 58
    /// = YASNAC, as offsetlab reads it).
    Arc,
}

/// G40 (or D00) in a block with no move in the plane (behaviour 16.11).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum CutterCancelWithoutMotion {
    /// The tool moves back onto the programmed point in that block (Fanuc).
    Move,
    /// Nothing changes until the next move in the plane, which is the
    /// cancel block (Haas).
    NextMove,
}

/// The interference check of cutter compensation (behaviour 16.12; Fanuc
/// parameter CNC, No. 5008#1).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum CutterInterference {
    /// An overcutting block stops the program with an alarm (PS0041).
    #[default]
    Alarm,
    /// No check: the path is drawn as the control would cut it, with a
    /// warning.
    Off,
}

/// The most blocks without a move in the plane `cutter_blocks_without_motion`
/// may name (a control reads at most 8 blocks in offset mode: Fanuc
/// parameter No. 19625).
pub const MAX_CUTTER_BLOCKS_WITHOUT_MOTION: u8 = 6;

/// Settings where controls disagree; the seeds' behaviour is the default.
/// A setting whose default depends on the control is an `Option` read
/// through its accessor (`None`: the control's default).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Settings {
    /// The control profile (behaviour 12): the defaults of the settings below
    /// that are left out.
    #[serde(skip_serializing_if = "is_default")]
    pub control: Control,
    /// Dimension words without a decimal point (behaviour 1.15).
    #[serde(skip_serializing_if = "is_default")]
    pub decimal_input: DecimalInput,
    /// Optional block skip switch: when on, blocks starting with `/` are skipped.
    #[serde(skip_serializing_if = "is_default")]
    pub block_skip: bool,
    /// `G43 H…` with no Z word (behaviour 3.3).
    #[serde(skip_serializing_if = "is_default")]
    pub length_offset_without_z: LengthOffsetWithoutZ,
    /// Lathe table X values: diameter or radius (behaviour 5).
    #[serde(skip_serializing_if = "is_default")]
    pub lathe_x_offset: LatheXOffset,
    /// Mirror image switches (mill).
    #[serde(skip_serializing_if = "is_default")]
    pub mirror: Mirror,
    /// Retract amount `d` of the G73/G83 peck cycles, in setup units
    /// (a machine parameter on a real control). Default 1 mm / 0.04 in.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub peck_retract: Option<f64>,
    /// Two G codes of one modal group in a block (behaviour 7.17); read it
    /// with [`Settings::same_group_codes`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub same_group_codes: Option<SameGroupCodes>,
    /// The lathe's G-code system (behaviour 7.18); read it with
    /// [`Settings::gcode_system`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gcode_system: Option<GCodeSystem>,
    /// A decimal point in a dwell's P (behaviour 7.26); read it with
    /// [`Settings::dwell_p_decimal_point`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dwell_p_decimal_point: Option<DwellPDecimalPoint>,
    /// G12/G13 on the mill (behaviour 7.20); read it with
    /// [`Settings::circle_pocket`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub circle_pocket: Option<CirclePocket>,
    /// G28/G30 without an axis word (behaviour 7.21); read it with
    /// [`Settings::reference_return_without_axes`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reference_return_without_axes: Option<ReturnWithoutAxes>,
    /// G54.1 Pn or G154 Pn (behaviour 7.22); read it with
    /// [`Settings::extended_work_offsets`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub extended_work_offsets: Option<ExtendedWork>,
    /// G68's R in G91 (behaviour 7.23).
    #[serde(skip_serializing_if = "is_default")]
    pub rotation_angle: RotationAngle,
    /// How D reads in a lathe G71/G72/G74–G76 block (behaviour 7.24, 15.2);
    /// read it with [`Settings::depth_word`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub depth_word: Option<DepthWord>,
    /// What the G00 blocks that end a G71/G72 contour going back toward
    /// the start are (behaviour 7.25, 15.6); read it with
    /// [`Settings::trailing_rapids`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub trailing_rapids: Option<TrailingRapids>,
    /// Cutter compensation start-up and cancel type (behaviour 16.3); read
    /// it with [`Settings::cutter_start_up`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cutter_start_up: Option<CutterStartUp>,
    /// Outside corners in offset mode (behaviour 16.7); read it with
    /// [`Settings::cutter_outside_corner`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cutter_outside_corner: Option<CutterOutsideCorner>,
    /// G40/D00 without a move in the plane (behaviour 16.11); read it with
    /// [`Settings::cutter_cancel_without_motion`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cutter_cancel_without_motion: Option<CutterCancelWithoutMotion>,
    /// How many blocks without a move in the plane the control reads past
    /// to find the next move in offset mode (behaviour 16.9); read it with
    /// [`Settings::cutter_blocks_without_motion`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cutter_blocks_without_motion: Option<u8>,
    /// The interference check (behaviour 16.12).
    #[serde(skip_serializing_if = "is_default")]
    pub cutter_interference_check: CutterInterference,
}

impl Settings {
    /// Two G codes of one group in a block: YASNAC refuses the block (an
    /// input error, as it refuses two of G45–G48, seed 003); Fanuc documents
    /// that the last one specified is valid (0i-MF/TF operator's manuals,
    /// "Preparatory function (G function)"), and the Haas profile follows
    /// the Fanuc rule its manuals are written against.
    pub fn same_group_codes(&self) -> SameGroupCodes {
        self.same_group_codes.unwrap_or(match self.control {
            Control::Yasnac => SameGroupCodes::Error,
            Control::Fanuc | Control::Haas => SameGroupCodes::LastWins,
        })
    }

    /// G12/G13 on the mill: Haas mills cut a circular pocket (Haas mill
    /// operator's manual, "G12 Circular Pocket Milling CW / G13 … CCW");
    /// neither the Fanuc 0i-MF G-code list nor the YASNAC seeds' manual has
    /// them on the mill, where the control alarms.
    pub fn circle_pocket(&self) -> CirclePocket {
        self.circle_pocket.unwrap_or(match self.control {
            Control::Haas => CirclePocket::Haas,
            Control::Yasnac | Control::Fanuc => CirclePocket::Alarm,
        })
    }

    /// The lathe's G-code system: A on every profile (Fanuc's default, the
    /// parameters GSB/GSC of No. 3401 choosing B or C; Haas lathes and the
    /// seed 004 manual write system A).
    pub fn gcode_system(&self) -> GCodeSystem {
        self.gcode_system.unwrap_or(match self.control {
            Control::Yasnac | Control::Fanuc | Control::Haas => GCodeSystem::A,
        })
    }

    /// A decimal point in a dwell's P: Fanuc allows none in P (0i-MF/TF
    /// operator's manuals, "Dwell (G04)": X takes a decimal point, P does
    /// not; alarm PS0007, illegal use of decimal point), nor does YASNAC,
    /// whose P is a whole number of milliseconds; Haas reads P with a point
    /// as seconds and without one as milliseconds (mill and lathe operator's
    /// manuals, G04), and its canned cycles' P the same way.
    pub fn dwell_p_decimal_point(&self) -> DwellPDecimalPoint {
        self.dwell_p_decimal_point.unwrap_or(match self.control {
            Control::Yasnac | Control::Fanuc => DwellPDecimalPoint::Error,
            Control::Haas => DwellPDecimalPoint::Seconds,
        })
    }

    /// G28/G30 without an axis word: Haas returns every axis (mill and lathe
    /// operator's manuals, G28); Fanuc returns the axes the block names, so
    /// none (0i-MF/TF operator's manuals, "Reference position return": the
    /// axes commanded return); the YASNAC manuals at hand do not say, and the
    /// profile follows the Fanuc family (our convention).
    pub fn reference_return_without_axes(&self) -> ReturnWithoutAxes {
        self.reference_return_without_axes
            .unwrap_or(match self.control {
                Control::Haas => ReturnWithoutAxes::AllAxes,
                Control::Yasnac | Control::Fanuc => ReturnWithoutAxes::NoAxis,
            })
    }

    /// The additional work systems: Haas writes G154 P1–P99 (mill operator's
    /// manual, G154); Fanuc G54.1 P1–P48 or G54 P1–P48 (0i-MF operator's
    /// manual, "Adding workpiece coordinate systems"); YASNAC follows Fanuc
    /// (our convention).
    pub fn extended_work_offsets(&self) -> ExtendedWork {
        self.extended_work_offsets.unwrap_or(match self.control {
            Control::Haas => ExtendedWork::G154,
            Control::Yasnac | Control::Fanuc => ExtendedWork::G54_1,
        })
    }

    /// Cutter compensation start-up and cancel: type A on every profile —
    /// Fanuc's parameter SUP (No. 5003#0) is 0 as shipped, Haas's setting
    /// 43 is A by default; no YASNAC manual the project has describes a
    /// type B (our convention).
    pub fn cutter_start_up(&self) -> CutterStartUp {
        self.cutter_start_up.unwrap_or(match self.control {
            Control::Yasnac | Control::Fanuc | Control::Haas => CutterStartUp::A,
        })
    }

    /// Outside corners: Fanuc's intersection and extra vectors (0i-MF,
    /// "Details of cutter compensation C", offset mode) on every profile;
    /// Haas's setting 58 is FANUC by default. The Haas manual says
    /// YASNAC-class controls go round outside corners otherwise (setting 58
    /// = YASNAC): `arc` is offsetlab's reading of that, unconfirmed by a
    /// YASNAC manual, so the YASNAC profile keeps the Fanuc rule (our
    /// convention).
    pub fn cutter_outside_corner(&self) -> CutterOutsideCorner {
        self.cutter_outside_corner.unwrap_or(match self.control {
            Control::Yasnac | Control::Fanuc | Control::Haas => CutterOutsideCorner::Vectors,
        })
    }

    /// G40 without a move in the plane: Fanuc takes the vector off in that
    /// block; Haas makes no change until the next X or Y move (Haas mill
    /// operator's manual, "Entry and exit from cutter compensation"); the
    /// YASNAC profile follows Fanuc (our convention).
    pub fn cutter_cancel_without_motion(&self) -> CutterCancelWithoutMotion {
        self.cutter_cancel_without_motion
            .unwrap_or(match self.control {
                Control::Yasnac | Control::Fanuc => CutterCancelWithoutMotion::Move,
                Control::Haas => CutterCancelWithoutMotion::NextMove,
            })
    }

    /// Blocks without a move in the plane read past in offset mode: 2 on
    /// every profile. Fanuc reads a parameter's number of blocks N (No.
    /// 19625 on the 0i-F, No. 6009 on the 15i) and finds the intersection
    /// while no more than N − 2 of them make no move (15i-MA operator's
    /// manual, 14.4.3); 2 is our reading of the common setting, and our
    /// convention for YASNAC and Haas.
    pub fn cutter_blocks_without_motion(&self) -> u8 {
        self.cutter_blocks_without_motion
            .unwrap_or(match self.control {
                Control::Yasnac | Control::Fanuc | Control::Haas => 2,
            })
    }

    /// How the D word of the one-block G71/G72 (depth of cut), G74/G75
    /// (relief) and G76 (first depth) reads (behaviour 7.24): Haas reads it
    /// as a length with a decimal point (Haas lathe operator's manual, G71:
    /// "D – depth of cut for each pass, positive radius", written `D0.05`);
    /// the Fanuc Series 10/11 tape format of the 0i-TF (parameter FCV) in
    /// least input increments, without a decimal point (`D7000` = 7 mm).
    /// YASNAC (the seeds' control) writes it as Haas's YASNAC mode does:
    /// a length.
    pub fn trailing_rapids(&self) -> TrailingRapids {
        // Fanuc checks every block from P to Q (a shape that turns back is
        // PS0064/PS0329); Haas school programs end the contour with `G00
        // G40 Z0.1` back to the start and run: our reading of the Haas
        // profile takes those rapids as the exit.
        self.trailing_rapids.unwrap_or(match self.control {
            Control::Haas => TrailingRapids::Exit,
            Control::Yasnac | Control::Fanuc => TrailingRapids::Shape,
        })
    }

    /// How the D word of the one-block G71/G72 (depth of cut), G74/G75
    /// (relief) and G76 (first depth) reads: see [`DepthWord`].
    pub fn depth_word(&self) -> DepthWord {
        self.depth_word.unwrap_or(match self.control {
            Control::Fanuc => DepthWord::Increments,
            Control::Yasnac | Control::Haas => DepthWord::Dimension,
        })
    }
}

/// What the G00 blocks that end a G71/G72 contour going back along the
/// cut toward the start are (behaviour 7.25).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum TrailingRapids {
    /// Part of the shape, which then turns back: Fanuc alarm PS0064/PS0329.
    Shape,
    /// The tool's exit: the roughing stops at the last block before them,
    /// with a warning.
    Exit,
}

/// How D reads in a lathe G71/G72/G74–G76 block (behaviour 7.24).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum DepthWord {
    /// A length, read as a dimension word (decimal point: program units;
    /// without: decimal input, behaviour 1.15): Haas, YASNAC.
    Dimension,
    /// A whole number of least input increments, no decimal point (Fanuc
    /// Series 10/11 format: `D7000` = 7.000 mm).
    Increments,
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

/// Work coordinate systems G54–G59, as offsets of their zero from machine zero.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct WorkOffsets {
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
}

impl WorkOffsets {
    /// The offset of G54 + `index` (0 = G54 … 5 = G59).
    pub fn get(&self, index: usize) -> Position {
        match index {
            0 => self.g54,
            1 => self.g55,
            2 => self.g56,
            3 => self.g57,
            4 => self.g58,
            _ => self.g59,
        }
    }
    fn all(&self) -> [(&'static str, Position); 6] {
        [
            ("G54", self.g54),
            ("G55", self.g55),
            ("G56", self.g56),
            ("G57", self.g57),
            ("G58", self.g58),
            ("G59", self.g59),
        ]
    }
}

/// One mill register: geometry + wear; their sum is used (behaviour 1.18).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct MillRegister {
    /// Geometry value.
    pub geometry: f64,
    /// Wear value.
    pub wear: f64,
}

impl MillRegister {
    /// The value a D or H code reads.
    pub fn value(&self) -> f64 {
        self.geometry + self.wear
    }
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct MillRegisterFull {
    #[serde(default)]
    geometry: f64,
    #[serde(default)]
    wear: f64,
}

#[derive(Deserialize)]
#[serde(untagged)]
enum MillRegisterForm {
    Value(f64),
    Full(MillRegisterFull),
}

impl Serialize for MillRegister {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        if self.wear == 0.0 {
            self.geometry.serialize(s)
        } else {
            MillRegisterFull {
                geometry: self.geometry,
                wear: self.wear,
            }
            .serialize(s)
        }
    }
}

impl<'de> Deserialize<'de> for MillRegister {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        match MillRegisterForm::deserialize(d).map_err(|_| {
            serde::de::Error::custom(
                "a mill register is a number or {\"geometry\": …, \"wear\": …}",
            )
        })? {
            MillRegisterForm::Value(v) => Ok(MillRegister {
                geometry: v,
                wear: 0.0,
            }),
            MillRegisterForm::Full(f) => Ok(MillRegister {
                geometry: f.geometry,
                wear: f.wear,
            }),
        }
    }
}

/// One lathe register: X (diameter or radius, see [`LatheXOffset`]) and Z,
/// each geometry + wear (behaviour 5).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct LatheRegister {
    /// X geometry.
    pub x: f64,
    /// Z geometry.
    pub z: f64,
    /// X wear.
    #[serde(skip_serializing_if = "is_zero")]
    pub x_wear: f64,
    /// Z wear.
    #[serde(skip_serializing_if = "is_zero")]
    pub z_wear: f64,
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

impl LatheRegister {
    /// X value used (geometry + wear), as stored (diameter or radius).
    pub fn x_value(&self) -> f64 {
        self.x + self.x_wear
    }
    /// Z value used (geometry + wear).
    pub fn z_value(&self) -> f64 {
        self.z + self.z_wear
    }
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
    /// Where the tool starts, in the G54 system.
    #[serde(skip_serializing_if = "is_default")]
    pub start: Position,
    /// The reference position G28 returns to, in machine coordinates.
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
        }
    }
}

/// Register maps are written with two-digit keys, `"01"`, as on the control.
mod register_map {
    use super::*;

    pub fn serialize<S: Serializer, T: Serialize>(
        map: &BTreeMap<u16, T>,
        s: S,
    ) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let mut m = s.serialize_map(Some(map.len()))?;
        for (k, v) in map {
            m.serialize_entry(&format!("{k:02}"), v)?;
        }
        m.end()
    }

    pub fn deserialize<'de, D: Deserializer<'de>, T: Deserialize<'de>>(
        d: D,
    ) -> Result<BTreeMap<u16, T>, D::Error> {
        let raw = BTreeMap::<String, T>::deserialize(d)?;
        let mut out = BTreeMap::new();
        for (k, v) in raw {
            let n = parse_register_number(&k).map_err(serde::de::Error::custom)?;
            if out.insert(n, v).is_some() {
                return Err(serde::de::Error::custom(format!(
                    "register {n:02} is given twice"
                )));
            }
        }
        Ok(out)
    }
}

fn parse_register_number(k: &str) -> Result<u16, String> {
    let t = k.trim();
    if t.is_empty() || t.len() > 4 || !t.bytes().all(|b| b.is_ascii_digit()) {
        return Err(format!(
            "register number `{k}` is not a number such as 01 or 12"
        ));
    }
    t.parse::<u16>()
        .map_err(|_| format!("register number `{k}` is not a number"))
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
        let mut out = Vec::new();
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
        for (&n, r) in &self.offsets {
            check_number(&mut out, n);
            check_value(&mut out, format!("register {n:02} geometry"), r.geometry);
            check_value(&mut out, format!("register {n:02} wear"), r.wear);
            check_value(
                &mut out,
                format!("register {n:02} geometry + wear"),
                r.value(),
            );
        }
        for (&n, r) in &self.lathe_offsets {
            check_number(&mut out, n);
            check_value(&mut out, format!("lathe register {n:02} X"), r.x);
            check_value(&mut out, format!("lathe register {n:02} Z"), r.z);
            check_value(&mut out, format!("lathe register {n:02} X wear"), r.x_wear);
            check_value(&mut out, format!("lathe register {n:02} Z wear"), r.z_wear);
        }
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

    /// Sets one register from a command-line style spec: mill `NN=VALUE`
    /// (`01=5.0`, `1=-2.5`), lathe `NN=X<v>,Z<v>` (`08=X0.4,Z-0.2`).
    /// Wear can follow as `W<v>` (mill) or `XW<v>`/`ZW<v>` (lathe).
    pub fn set_register(&mut self, spec: &str) -> Result<(), String> {
        let (num, value) = spec
            .split_once('=')
            .ok_or_else(|| format!("offset `{spec}`: expected NN=VALUE"))?;
        let n = parse_register_number(num).map_err(|e| format!("offset `{spec}`: {e}"))?;
        let number = |t: &str| -> Result<f64, String> {
            let t = t.trim();
            t.parse::<f64>()
                .ok()
                .filter(|v| v.is_finite() && !t.is_empty())
                .ok_or_else(|| format!("offset `{spec}`: `{t}` is not a number"))
        };
        match self.machine {
            MachineKind::Mill => {
                let mut reg = MillRegister::default();
                for (i, part) in value.split(',').enumerate() {
                    let p = part.trim();
                    let upper = p.to_ascii_uppercase();
                    if let Some(w) = upper.strip_prefix('W') {
                        reg.wear = number(w)?;
                    } else if i == 0 {
                        reg.geometry = number(upper.strip_prefix('G').unwrap_or(&upper))?;
                    } else {
                        return Err(format!(
                            "offset `{spec}`: mill registers are NN=VALUE or NN=VALUE,W<wear>"
                        ));
                    }
                }
                self.offsets.insert(n, reg);
            }
            MachineKind::Lathe => {
                let mut reg = LatheRegister::default();
                for part in value.split(',') {
                    let p = part.trim().to_ascii_uppercase();
                    if let Some(v) = p.strip_prefix("XW") {
                        reg.x_wear = number(v)?;
                    } else if let Some(v) = p.strip_prefix("ZW") {
                        reg.z_wear = number(v)?;
                    } else if let Some(v) = p.strip_prefix('X') {
                        reg.x = number(v)?;
                    } else if let Some(v) = p.strip_prefix('Z') {
                        reg.z = number(v)?;
                    } else {
                        return Err(format!(
                            "offset `{spec}`: lathe registers are NN=X<v>,Z<v> (wear: XW<v>, ZW<v>)"
                        ));
                    }
                }
                self.lathe_offsets.insert(n, reg);
            }
        }
        Ok(())
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
        .unwrap_or(self.reference)
    }

    /// The value register `n` holds for D and H (00 and unset read 0).
    pub fn mill_value(&self, n: u16) -> f64 {
        self.offsets.get(&n).map_or(0.0, MillRegister::value)
    }

    /// Lathe register `n` (00 and unset read 0).
    pub fn lathe_register(&self, n: u16) -> LatheRegister {
        self.lathe_offsets.get(&n).copied().unwrap_or_default()
    }

    /// The G73/G83 retract amount in millimetres.
    pub fn peck_retract_mm(&self) -> f64 {
        match self.settings.peck_retract {
            Some(d) => d * self.units.mm(),
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
