//! The values of the settings where controls disagree (behaviour 7): one
//! type per setting that is not a plain number or switch, read through
//! [`super::Settings`]'s accessors.

use serde::{Deserialize, Deserializer, Serialize, Serializer};

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
    /// LinuxCNC 2.9 (the RS274/NGC dialect; its `rs274` interpreter is the
    /// oracle, behaviour 22).
    Linuxcnc,
}

impl Control {
    /// Every control, in the order the page lists them.
    pub const ALL: [Control; 4] = [
        Control::Yasnac,
        Control::Fanuc,
        Control::Haas,
        Control::Linuxcnc,
    ];

    /// "yasnac", "fanuc", "haas" or "linuxcnc".
    pub fn as_str(self) -> &'static str {
        match self {
            Control::Yasnac => "yasnac",
            Control::Fanuc => "fanuc",
            Control::Haas => "haas",
            Control::Linuxcnc => "linuxcnc",
        }
    }

    /// The control's name as its maker writes it.
    pub fn name(self) -> &'static str {
        match self {
            Control::Yasnac => "YASNAC",
            Control::Fanuc => "Fanuc",
            Control::Haas => "Haas",
            Control::Linuxcnc => "LinuxCNC",
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
    /// P is seconds, with a point or without: `P3` is 3 seconds (LinuxCNC
    /// G4 and the canned cycles' dwell, RS274/NGC "G4 Dwell").
    Always,
}

/// What `;` is in the program text (behaviour 1.22, 7.61).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Semicolon {
    /// The end of a block (EOB in ISO code: Fanuc, Haas, YASNAC).
    EndOfBlock,
    /// A comment to the end of the line (LinuxCNC, Mach3).
    Comment,
}

/// A decimal point in S, the spindle speed (behaviour 1.13, 7.57).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SDecimalPoint {
    /// S is a whole number; `S5000.` is an error (Fanuc: PS0007).
    Error,
    /// `S5000.` is 5000, as `S5000` (the Haas programs' habit).
    Value,
}

/// The roughing cycles' words (U, W, D, I, K, R) written on a G70 finishing
/// block (behaviour 15.22, 7.58).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FinishingExtraWords {
    /// An error at the word (Fanuc PS0066: G70 reads P and Q).
    Error,
    /// Passed over with a warning that names them (Haas).
    Warn,
}

/// The macro words' two-letter abbreviations (behaviour 20.19, 7.59).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum MacroAbbreviations {
    /// Read as the words they stand for (`WH` for WHILE), as Fanuc does.
    Fanuc,
    /// Words in full only; an abbreviation is refused with its word.
    Off,
}

/// The range of the angles ATAN and ASIN give (behaviour 7.39, 20.6).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum MacroAngles {
    /// ATAN 0 to 360, ASIN 270 to 90 (Fanuc parameter NAT, No. 6004#0, = 0).
    Positive,
    /// ATAN −180 to 180, ASIN −90 to 90 (NAT = 1).
    Signed,
}

/// What a macro condition is (behaviour 7.40, 20.5).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum MacroConditions {
    /// A comparison is true or false, never a number (Fanuc).
    Boolean,
    /// Every expression is a number: a comparison is 1.0 or 0.0 and a
    /// condition holds when not 0 (Haas).
    Numeric,
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

/// What G47 is on the mill (behaviour 7.60, 14.20).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum G47Code {
    /// Fanuc's and YASNAC's tool position offset, double extension (G45–G48).
    PositionOffset,
    /// Haas text engraving: P, X, Y, Z, R, I, J, E, F and the text.
    Engraving,
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
    /// LinuxCNC: the start-up block's end is a corner as in offset mode
    /// (inside the intersection, outside per `cutter_outside_corner`); a
    /// cancel starts perpendicular to the block before, as type A.
    #[serde(rename = "corner")]
    Corner,
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

/// How the mill's offset memory keeps the values D and H read (behaviour
/// 7.32, 17.1): Fanuc's tool compensation memory A, B or C.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum OffsetMemory {
    /// One value per number, read by H and D alike (the seeds' YASNAC
    /// memory; Fanuc memory A). `G10 L11` (or `L1`) sets it.
    A,
    /// Geometry and wear per number, shared by H and D (Fanuc memory B):
    /// `G10 L10` geometry, `L11` wear.
    B,
    /// Separate H and D tables, each geometry and wear (Fanuc memory C, the
    /// Haas offset page): `G10 L10`/`L11` H geometry/wear, `L12`/`L13` D
    /// geometry/wear.
    C,
}

impl OffsetMemory {
    /// "A", "B" or "C".
    pub fn as_str(self) -> &'static str {
        match self {
            OffsetMemory::A => "A",
            OffsetMemory::B => "B",
            OffsetMemory::C => "C",
        }
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

/// Where a G70–G73 contour may write G40/G41/G42 (behaviour 7.34).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum NoseInContour {
    /// In the contour: the compensation starts up at the block with
    /// G41/G42 and is cancelled at the block with G40 (Haas).
    Contour,
    /// Before the cycle only: G40–G42 between P and Q is an alarm (PS0325),
    /// the mode in force compensates the whole contour (Fanuc).
    BeforeCycle,
}

/// Tool nose radius compensation in G90/G94 (behaviour 7.35).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum NoseSingleCycles {
    /// The cycle's legs compensated, the side given by the tip direction.
    Tip,
    /// The cycle runs as programmed, with a warning.
    Off,
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

/// How a lathe program writes the face plane of polar coordinate
/// interpolation, G12.1/G112 (behaviour 7.33, 14.11).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PolarInterpolation {
    /// X a diameter, C the hypothetical axis; G01, G02, G03 only (Fanuc T).
    Fanuc,
    /// X a radius, Y the hypothetical axis, G00 allowed (Haas G112, "XY to
    /// XC").
    Haas,
}

/// What M99 in the main program does (behaviour 7.42).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum MainM99 {
    /// The run ends at the M99, after one pass, with a note that the
    /// control would repeat the program.
    Once,
    /// Back to the start (or to N of its P) as the control goes, until the
    /// run's block limit.
    Loop,
}

/// How M98's P reads (behaviour 7.36).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SubprogramP {
    /// Up to four digits the program number; more, the digits before the
    /// last four the repeat count (`P50010`: O0010 five times), as Fanuc
    /// and YASNAC read it.
    RepeatAndNumber,
    /// The program number, whatever its digits (Haas: O00000–O99999);
    /// repeats with L only.
    Number,
}
