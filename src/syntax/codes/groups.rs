//! The value of each G-code modal group: what a code of the group means, as
//! the parser resolves it for the machine (the mill's G90 is absolute mode,
//! the lathe's a turning cycle) and as the modal state keeps it. Each type
//! writes its own code back (`gcode`), so a message never spells a number.
//!
//! Group 06 (inch/metric) is [`crate::setup::Units`].

use crate::setup::MachineKind;

/// Group 01: how axis words move the tool.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Motion {
    /// G00 positioning.
    Rapid,
    /// G01 linear interpolation.
    Linear,
    /// G02 (clockwise) or G03 (counter-clockwise) circular interpolation.
    Arc(ArcDirection),
    /// Lathe G90/G92/G94: a single cycle (G-code system A).
    LatheCycle(LatheCycle),
}

/// The turn of a G02/G03 arc, seen from the positive side of the plane's
/// normal.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ArcDirection {
    /// G02.
    Cw,
    /// G03.
    Ccw,
}

/// The lathe's single cycles of group 01 (G-code system A).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LatheCycle {
    /// G90: outer/inner diameter turning cycle.
    Turning,
    /// G92: thread cutting cycle.
    Threading,
    /// G94: end facing cycle.
    Facing,
}

impl Motion {
    /// The G code.
    pub fn gcode(self) -> &'static str {
        match self {
            Motion::Rapid => "G00",
            Motion::Linear => "G01",
            Motion::Arc(ArcDirection::Cw) => "G02",
            Motion::Arc(ArcDirection::Ccw) => "G03",
            Motion::LatheCycle(LatheCycle::Turning) => "G90",
            Motion::LatheCycle(LatheCycle::Threading) => "G92",
            Motion::LatheCycle(LatheCycle::Facing) => "G94",
        }
    }

    /// G02 or G03.
    pub fn is_arc(self) -> bool {
        match self {
            Motion::Arc(_) => true,
            Motion::Rapid | Motion::Linear | Motion::LatheCycle(_) => false,
        }
    }
}

/// Group 02: the plane of arcs (and of canned-cycle hole positions).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Plane {
    /// G17: XY, normal Z.
    XY,
    /// G18: ZX, normal Y.
    ZX,
    /// G19: YZ, normal X.
    YZ,
}

impl Plane {
    /// The G code.
    pub fn gcode(self) -> &'static str {
        match self {
            Plane::XY => "G17",
            Plane::ZX => "G18",
            Plane::YZ => "G19",
        }
    }
    /// Axis indices (first, second, normal). CW/CCW are seen from the normal's
    /// positive side, in the right-handed frame (first, second):
    /// G17 (X, Y), G18 (Z, X), G19 (Y, Z).
    pub fn axes(self) -> (usize, usize, usize) {
        match self {
            Plane::XY => (0, 1, 2),
            Plane::ZX => (2, 0, 1),
            Plane::YZ => (1, 2, 0),
        }
    }
}

/// Group 03 (mill): absolute or incremental.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Distance {
    /// G90.
    Absolute,
    /// G91.
    Incremental,
}

impl Distance {
    /// The G code.
    pub fn gcode(self) -> &'static str {
        match self {
            Distance::Absolute => "G90",
            Distance::Incremental => "G91",
        }
    }
}

/// Group 05: what F means.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FeedMode {
    /// Feed per minute: mill G94, lathe G98.
    PerMinute,
    /// Feed per revolution: mill G95, lathe G99.
    PerRevolution,
    /// Mill G93: inverse time, F is 1 / the minutes a move takes (behaviour 14.8).
    InverseTime,
}

impl FeedMode {
    /// The G code on this machine (the lathe's G98/G99 are the mill's return
    /// levels).
    pub fn gcode(self, machine: MachineKind) -> &'static str {
        match (machine, self) {
            (MachineKind::Mill, FeedMode::PerMinute) => "G94",
            (MachineKind::Mill, FeedMode::PerRevolution) => "G95",
            (MachineKind::Lathe, FeedMode::PerMinute) => "G98",
            (MachineKind::Lathe, FeedMode::PerRevolution) => "G99",
            // Only the mill reads G93 (the lathe's table has no such code).
            (_, FeedMode::InverseTime) => "G93",
        }
    }
}

/// Group 07: cutter radius compensation C on the mill (behaviour 16), tool
/// nose radius compensation on the lathe (behaviour 18).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum CutterCompensation {
    /// G40: cancel.
    #[default]
    Cancel,
    /// G41: the tool centre left of the path, seen along the direction of
    /// travel from the positive side of the plane's normal.
    Left,
    /// G42: the tool centre right of the path.
    Right,
}

impl CutterCompensation {
    /// The G code.
    pub fn gcode(self) -> &'static str {
        match self {
            CutterCompensation::Cancel => "G40",
            CutterCompensation::Left => "G41",
            CutterCompensation::Right => "G42",
        }
    }
}

/// Group 08 (mill): tool length offset (seed 001).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LengthOffset {
    /// G43: the register value is added to Z.
    Add,
    /// G44: the register value is subtracted from Z.
    Subtract,
    /// G49: cancel.
    Cancel,
    /// G43.1 (LinuxCNC): the offset the block's Z gives.
    Dynamic,
    /// G43.2 (LinuxCNC): another tool's offset, or the Z given, added.
    AddTool,
}

impl LengthOffset {
    /// The G code.
    pub fn gcode(self) -> &'static str {
        match self {
            LengthOffset::Add => "G43",
            LengthOffset::Subtract => "G44",
            LengthOffset::Cancel => "G49",
            LengthOffset::Dynamic => "G43.1",
            LengthOffset::AddTool => "G43.2",
        }
    }
}

/// Group 09 (mill): a canned cycle, or G80.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CannedCycle {
    /// G80: canned cycle cancel.
    Cancel,
    /// G73–G89: a cycle starts (or another replaces it).
    Cycle(Cycle),
}

impl CannedCycle {
    /// The G code.
    pub fn gcode(self) -> &'static str {
        match self {
            CannedCycle::Cancel => "G80",
            CannedCycle::Cycle(c) => c.gcode(),
        }
    }
}

/// The mill's canned cycles (Fanuc/YASNAC M names).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Cycle {
    /// G73: high-speed peck drilling.
    HighSpeedPeck,
    /// G74: left-hand (counter) tapping.
    LeftHandTapping,
    /// G76: fine boring.
    FineBoring,
    /// G81: drilling, spot drilling.
    Drilling,
    /// G82: drilling with a dwell, counter boring.
    CounterBoring,
    /// G83: peck drilling.
    PeckDrilling,
    /// G84: tapping.
    Tapping,
    /// G85: boring, feed out.
    Boring,
    /// G86: boring, spindle stop at the bottom.
    BoringSpindleStop,
    /// G87: back boring.
    BackBoring,
    /// G88: boring, manual retract.
    BoringManualRetract,
    /// G89: boring with a dwell, feed out.
    BoringDwell,
}

impl Cycle {
    /// The G code.
    pub fn gcode(self) -> &'static str {
        match self {
            Cycle::HighSpeedPeck => "G73",
            Cycle::LeftHandTapping => "G74",
            Cycle::FineBoring => "G76",
            Cycle::Drilling => "G81",
            Cycle::CounterBoring => "G82",
            Cycle::PeckDrilling => "G83",
            Cycle::Tapping => "G84",
            Cycle::Boring => "G85",
            Cycle::BoringSpindleStop => "G86",
            Cycle::BackBoring => "G87",
            Cycle::BoringManualRetract => "G88",
            Cycle::BoringDwell => "G89",
        }
    }
}

/// Group 10 (mill): where a canned cycle returns to after a hole.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ReturnLevel {
    /// G98: the initial level.
    Initial,
    /// G99: the R level.
    R,
}

impl ReturnLevel {
    /// The G code.
    pub fn gcode(self) -> &'static str {
        match self {
            ReturnLevel::Initial => "G98",
            ReturnLevel::R => "G99",
        }
    }
}

/// Group 11 (mill): scaling.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ScalingMode {
    /// G51: scaling on.
    Start,
    /// G50: scaling off (the lathe's G50 is coordinate setting).
    Cancel,
}

impl ScalingMode {
    /// The G code.
    pub fn gcode(self) -> &'static str {
        match self {
            ScalingMode::Start => "G51",
            ScalingMode::Cancel => "G50",
        }
    }
}

/// Group 16 (mill): coordinate system rotation.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum RotationMode {
    /// G68: rotation on.
    Start,
    /// G69: rotation off.
    Cancel,
}

impl RotationMode {
    /// The G code.
    pub fn gcode(self) -> &'static str {
        match self {
            RotationMode::Start => "G68",
            RotationMode::Cancel => "G69",
        }
    }
}

/// Group 17 (mill): polar coordinate command.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PolarMode {
    /// G16: the plane's first axis word is a radius, the second an angle.
    Start,
    /// G15: Cartesian words.
    Cancel,
}

impl PolarMode {
    /// The G code.
    pub fn gcode(self) -> &'static str {
        match self {
            PolarMode::Start => "G16",
            PolarMode::Cancel => "G15",
        }
    }
}

/// Group 22 (mill): programmable mirror image.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MirrorMode {
    /// G51.1: mirror the axes named about the coordinates given.
    Start,
    /// G50.1: cancel it on the axes named.
    Cancel,
}

impl MirrorMode {
    /// The G code.
    pub fn gcode(self) -> &'static str {
        match self {
            MirrorMode::Start => "G51.1",
            MirrorMode::Cancel => "G50.1",
        }
    }
}

/// G90.1/G91.1 (mill): how I, J, K give an arc's centre (behaviour 13.12).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ArcCenter {
    /// G90.1: the centre's coordinates.
    Absolute,
    /// G91.1: the centre from the start point (the only mode of the
    /// Fanuc, Haas and YASNAC manuals).
    Incremental,
}

impl ArcCenter {
    /// The G code.
    pub fn gcode(self) -> &'static str {
        match self {
            ArcCenter::Absolute => "G90.1",
            ArcCenter::Incremental => "G91.1",
        }
    }
}

/// Lathe group 02: constant surface speed control.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SurfaceSpeed {
    /// G96: S is a surface speed.
    Constant,
    /// G97: cancel; S is spindle revolutions per minute.
    Cancel,
}

impl SurfaceSpeed {
    /// The G code.
    pub fn gcode(self) -> &'static str {
        match self {
            SurfaceSpeed::Constant => "G96",
            SurfaceSpeed::Cancel => "G97",
        }
    }
}

/// Fanuc M group 15 (mill): how a move ends and the next begins. None of
/// them changes the path (behaviour 14.2).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CuttingMode {
    /// G61: exact stop mode.
    ExactStop,
    /// G62: automatic corner override.
    CornerOverride,
    /// G63: tapping mode.
    Tapping,
    /// G64: cutting mode (the start state).
    Cutting,
    /// LinuxCNC's G61: exact path, the corners kept, no stop where none is needed.
    ExactPath,
    /// LinuxCNC's G61.1: exact stop at the end of every move.
    ExactStopLinuxcnc,
}

impl CuttingMode {
    /// The G code.
    pub fn gcode(self) -> &'static str {
        match self {
            CuttingMode::ExactStop => "G61",
            CuttingMode::CornerOverride => "G62",
            CuttingMode::Tapping => "G63",
            CuttingMode::Cutting => "G64",
            CuttingMode::ExactPath => "G61",
            CuttingMode::ExactStopLinuxcnc => "G61.1",
        }
    }
}

/// Lathe group 21: polar coordinate interpolation (behaviour 14.11).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Polar {
    /// Fanuc G12.1 / Haas G112: X and the rotary axis C make a Cartesian plane.
    On(PolarSpelling),
    /// Fanuc G13.1 / Haas G113: cancel (the start state).
    Off(PolarSpelling),
}

/// How a program writes the polar interpolation codes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PolarSpelling {
    /// G12.1 / G13.1 (Fanuc).
    Fanuc,
    /// G112 / G113 (Haas).
    Haas,
}

impl Polar {
    /// The G code as written.
    pub fn gcode(self) -> &'static str {
        match self {
            Polar::On(PolarSpelling::Fanuc) => "G12.1",
            Polar::Off(PolarSpelling::Fanuc) => "G13.1",
            Polar::On(PolarSpelling::Haas) => "G112",
            Polar::Off(PolarSpelling::Haas) => "G113",
        }
    }

    /// True for G12.1 / G112.
    pub fn is_on(self) -> bool {
        matches!(self, Polar::On(_))
    }
}

/// Group 00: one-shot codes, in effect in their block only (some of them,
/// G05.1, G07.1, G08, G187, switch a mode the control keeps: behaviour 14).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum NonModal {
    /// G04: dwell.
    Dwell,
    /// G09 (mill): exact stop at the end of this block.
    ExactStop,
    /// G31: skip function, a feed move a skip signal may cut short.
    Skip,
    /// G05.1 (mill): AI contour control on (Q1) or off (Q0), Fanuc.
    AiContour,
    /// G08 (mill): look-ahead (advanced preview control) on (P1) or off (P0), Fanuc.
    LookAhead,
    /// G187 (mill): smoothness level P1–P3 and corner tolerance E, Haas.
    Smoothness,
    /// G103 (mill): the blocks the control looks ahead limited to P, Haas.
    BlockLimit,
    /// G07.1: cylindrical interpolation, the rotary word the cylinder's radius.
    Cylindrical,
    /// G12 (clockwise) / G13 (counter-clockwise) on the mill: Haas circular
    /// pocket milling.
    CirclePocket(ArcDirection),
    /// G47 on a Haas mill: text engraving (behaviour 14.20).
    Engraving,
    /// G28: return to the reference position.
    ReferenceReturn,
    /// G45–G48 (mill): tool position offset (seeds 000 and 003).
    PositionOffset(PositionOffset),
    /// Coordinate system setting: G92 on the mill, G50 on the lathe.
    SetCoordinates,
    /// G27: reference position return check (behaviour 13.6).
    ReferenceCheck,
    /// G30: return to the second, third or fourth reference position (P2–P4;
    /// behaviour 13.5).
    OtherReference,
    /// G52: local coordinate system (behaviour 13.2).
    LocalCoordinates,
    /// G53: positioning in machine coordinates (behaviour 13.1).
    MachineCoordinates,
    /// G92.1: workpiece coordinate system preset, the G92 shift undone
    /// (behaviour 13.4).
    PresetCoordinates,
    /// G39 (mill): corner circular interpolation in cutter compensation
    /// (behaviour 16).
    CornerArc,
    /// Lathe G70–G76: a multiple repetitive cycle (behaviour 15).
    Repetitive(Repetitive),
    /// G10: programmable data input, the offset tables and work offsets
    /// set from the program (behaviour 17).
    DataSetting,
    /// LinuxCNC's G92.2, G92.3, G28.1 and G30.1 (behaviour 22.14).
    Stored(super::linuxcnc::Stored),
}

/// The lathe's multiple repetitive cycles, group 00 (Fanuc 0i-TF operator's
/// manual B-64604EN-1, "Multiple repetitive cycle (G70–G76)"; behaviour 15).
/// G-code system C numbers them G72–G78 (behaviour 15.1).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Repetitive {
    /// G70: finishing cycle along the P–Q contour.
    Finishing,
    /// G71: stock removal in turning (cuts along Z, depth in X).
    TurningStock,
    /// G72: stock removal in facing (cuts along X, depth in Z).
    FacingStock,
    /// G73: pattern repeating.
    PatternRepeat,
    /// G74: end face peck drilling (pecks along Z).
    FacePeck,
    /// G75: outer/inner diameter grooving (pecks along X).
    DiameterPeck,
    /// G76: multiple threading cycle.
    Threading,
}

impl Repetitive {
    /// The G code in G-code systems A and B.
    pub fn gcode(self) -> &'static str {
        match self {
            Repetitive::Finishing => "G70",
            Repetitive::TurningStock => "G71",
            Repetitive::FacingStock => "G72",
            Repetitive::PatternRepeat => "G73",
            Repetitive::FacePeck => "G74",
            Repetitive::DiameterPeck => "G75",
            Repetitive::Threading => "G76",
        }
    }

    /// The G code in G-code system C (each number two higher).
    pub fn gcode_system_c(self) -> &'static str {
        match self {
            Repetitive::Finishing => "G72",
            Repetitive::TurningStock => "G73",
            Repetitive::FacingStock => "G74",
            Repetitive::PatternRepeat => "G75",
            Repetitive::FacePeck => "G76",
            Repetitive::DiameterPeck => "G77",
            Repetitive::Threading => "G78",
        }
    }

    /// True for the cycles that read a P–Q contour (G70–G73): their P and Q
    /// are sequence numbers.
    pub fn reads_contour(self) -> bool {
        match self {
            Repetitive::Finishing
            | Repetitive::TurningStock
            | Repetitive::FacingStock
            | Repetitive::PatternRepeat => true,
            Repetitive::FacePeck | Repetitive::DiameterPeck | Repetitive::Threading => false,
        }
    }
}

impl NonModal {
    /// The G code on this machine.
    pub fn gcode(self, machine: MachineKind) -> &'static str {
        match (self, machine) {
            (NonModal::Dwell, _) => "G04",
            (NonModal::ExactStop, _) => "G09",
            (NonModal::Skip, _) => "G31",
            (NonModal::AiContour, _) => "G05.1",
            (NonModal::LookAhead, _) => "G08",
            (NonModal::Smoothness, _) => "G187",
            (NonModal::BlockLimit, _) => "G103",
            (NonModal::Cylindrical, _) => "G07.1",
            (NonModal::CirclePocket(ArcDirection::Cw), _) => "G12",
            (NonModal::CirclePocket(ArcDirection::Ccw), _) => "G13",
            (NonModal::Engraving, _) => "G47",
            (NonModal::ReferenceReturn, _) => "G28",
            (NonModal::PositionOffset(p), _) => p.gcode(),
            (NonModal::SetCoordinates, MachineKind::Mill) => "G92",
            (NonModal::SetCoordinates, MachineKind::Lathe) => "G50",
            (NonModal::ReferenceCheck, _) => "G27",
            (NonModal::OtherReference, _) => "G30",
            (NonModal::LocalCoordinates, _) => "G52",
            (NonModal::MachineCoordinates, _) => "G53",
            (NonModal::PresetCoordinates, _) => "G92.1",
            (NonModal::CornerArc, _) => "G39",
            (NonModal::Repetitive(r), _) => r.gcode(),
            (NonModal::DataSetting, _) => "G10",
            (NonModal::Stored(s), _) => s.gcode(),
        }
    }
}

/// G45–G48: how a block's movements are changed by register D (seed 000's
/// table).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PositionOffset {
    /// G45: extended by the register value.
    Extension,
    /// G46: reduced by the register value.
    Reduction,
    /// G47: extended by twice the register value.
    DoubleExtension,
    /// G48: reduced by twice the register value.
    DoubleReduction,
}

impl PositionOffset {
    /// The G code.
    pub fn gcode(self) -> &'static str {
        match self {
            PositionOffset::Extension => "G45",
            PositionOffset::Reduction => "G46",
            PositionOffset::DoubleExtension => "G47",
            PositionOffset::DoubleReduction => "G48",
        }
    }
}
