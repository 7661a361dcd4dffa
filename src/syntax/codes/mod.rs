//! The G and M codes offsetlab knows: [`Code::of`] resolves a G code as
//! written into the typed value of its modal group for the machine, once,
//! in the parser; the machine, the offsets and the parser's context rules
//! match those values (so a new code is a new variant the compiler leads to
//! every place it must reach). For codes offsetlab recognises but does not
//! model, the reason it says so (behaviour 2: an unsupported code is an error,
//! never a silent skip).

mod groups;
mod linuxcnc;
mod mcodes;
mod work;

pub use groups::{
    ArcCenter, ArcDirection, CannedCycle, CutterCompensation, CuttingMode, Cycle, Distance,
    FeedMode, LatheCycle, LengthOffset, MirrorMode, Motion, NonModal, Plane, Polar, PolarMode,
    PolarSpelling, PositionOffset, Repetitive, ReturnLevel, RotationMode, ScalingMode,
    SurfaceSpeed,
};
pub use linuxcnc::Stored;
pub use mcodes::MCode;
pub use work::{MAX_ADDITIONAL_WORK, MAX_HAAS_WORK, WorkCode, WorkSystem};

use crate::setup::{G47Code, GCodeSystem, MachineKind, Setup, Units};

/// A G-code modal group. Two codes of one group in a block is an error
/// (behaviour 1). Numbers follow the Fanuc/YASNAC M tables where they exist.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Group {
    /// 00: one-shot codes (G04, G28, G45–G48, G92 / lathe G50).
    NonModal,
    /// 01: interpolation (G00–G03; on the lathe also the G90/G92/G94 cycles).
    Motion,
    /// 02: plane selection.
    Plane,
    /// 03: absolute / incremental (mill).
    Distance,
    /// 05: feed per minute / per revolution.
    FeedMode,
    /// 06: inch / metric.
    Units,
    /// 07: cutter compensation (G40–G42; on the lathe tool nose radius
    /// compensation, behaviour 18).
    Cutter,
    /// 08: tool length offset.
    Length,
    /// 09: canned cycles (mill); the lathe has its G80 (Fanuc T group 10).
    Cycle,
    /// 10: canned-cycle return level (mill).
    Return,
    /// 14: work coordinate systems.
    Work,
    /// Constant surface speed on/off (lathe 02, Fanuc M 13).
    SurfaceSpeed,
    /// 15 (mill): exact stop, corner override, tapping and cutting modes.
    CuttingMode,
    /// 21 (lathe): polar coordinate interpolation.
    Polar,
    /// 11 (mill): scaling G50/G51.
    Scaling,
    /// 16 (mill): coordinate system rotation G68/G69.
    Rotation,
    /// 17 (mill): polar coordinate command G15/G16.
    PolarCoordinates,
    /// 22 (mill): programmable mirror image G50.1/G51.1.
    Mirror,
    /// Arc centre mode G90.1/G91.1 (Mach3 and LinuxCNC; no Fanuc group).
    ArcCenter,
}

impl Group {
    /// Index for per-group tables.
    pub fn index(self) -> usize {
        self as usize
    }
    /// Number of groups.
    pub const COUNT: usize = 19;
    /// Every group, in index order.
    pub const ALL: [Group; Group::COUNT] = [
        Group::NonModal,
        Group::Motion,
        Group::Plane,
        Group::Distance,
        Group::FeedMode,
        Group::Units,
        Group::Cutter,
        Group::Length,
        Group::Cycle,
        Group::Return,
        Group::Work,
        Group::SurfaceSpeed,
        Group::CuttingMode,
        Group::Polar,
        Group::Scaling,
        Group::Rotation,
        Group::PolarCoordinates,
        Group::Mirror,
        Group::ArcCenter,
    ];
    /// The group's name in the manuals.
    pub fn label(self) -> &'static str {
        match self {
            Group::NonModal => "00 (one-shot)",
            Group::Motion => "01 (interpolation)",
            Group::Plane => "02 (plane)",
            Group::Distance => "03 (absolute/incremental)",
            Group::FeedMode => "05 (feed mode)",
            Group::Units => "06 (inch/metric)",
            Group::Cutter => "07 (cutter compensation)",
            Group::Length => "08 (tool length offset)",
            Group::Cycle => "09 (canned cycle)",
            Group::Return => "10 (return level)",
            Group::Work => "14 (work coordinates)",
            Group::SurfaceSpeed => "02/13 (constant surface speed)",
            Group::CuttingMode => "15 (cutting mode)",
            Group::Polar => "21 (polar coordinate interpolation)",
            Group::Scaling => "11 (scaling)",
            Group::Rotation => "16 (coordinate rotation)",
            Group::PolarCoordinates => "17 (polar coordinates)",
            Group::Mirror => "22 (programmable mirror image)",
            Group::ArcCenter => "arc centre mode",
        }
    }
}

/// A G code as written: `G05.1` is major 5, minor 1.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct GCode {
    /// The integer part.
    pub major: u16,
    /// The tenths digit (0 for every code offsetlab models).
    pub minor: u8,
}

impl GCode {
    /// A plain integer code.
    pub const fn new(major: u16) -> GCode {
        GCode { major, minor: 0 }
    }
}

impl std::fmt::Display for GCode {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.minor == 0 {
            write!(f, "G{:02}", self.major)
        } else {
            write!(f, "G{:02}.{}", self.major, self.minor)
        }
    }
}

/// Which table turns a G number into a code: the mill's, or the lathe's in
/// its G-code system (behaviour 7.18). One byte, compared once per G word.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CodeTable {
    /// The mill, G47 the tool position offset (Fanuc, YASNAC).
    Mill,
    /// The mill, G47 text engraving (Haas; setting g47, behaviour 7.60).
    MillEngraving,
    /// The mill under LinuxCNC: its G41.1/G42.1, G43.1, G43.2 (behaviour
    /// 22.9), G61 and G61.1 (22.16) besides the Fanuc family's codes.
    MillLinuxcnc,
    /// The lathe, G-code system A.
    LatheA,
    /// The lathe, G-code system B.
    LatheB,
    /// The lathe, G-code system C.
    LatheC,
}

impl CodeTable {
    /// The mill's table.
    pub const MILL: CodeTable = CodeTable::Mill;
    /// The lathe's table in G-code system A.
    pub const LATHE: CodeTable = CodeTable::LatheA;

    /// The table a setup reads programs with.
    pub fn of(setup: &Setup) -> CodeTable {
        CodeTable::new(setup.machine, setup.settings.gcode_system())
            .with_engraving(setup.settings.g47() == G47Code::Engraving)
            .with_linuxcnc(setup.settings.control == crate::setup::Control::Linuxcnc)
    }

    /// The mill's table with LinuxCNC's own codes when `linuxcnc`.
    #[inline(always)]
    pub fn with_linuxcnc(self, linuxcnc: bool) -> CodeTable {
        match self {
            CodeTable::Mill if linuxcnc => CodeTable::MillLinuxcnc,
            table => table,
        }
    }

    /// The table with G47 as Haas text engraving when `engraving` (the
    /// mill's only; setting g47, behaviour 7.60).
    #[inline(always)]
    pub fn with_engraving(self, engraving: bool) -> CodeTable {
        match self {
            CodeTable::Mill if engraving => CodeTable::MillEngraving,
            table => table,
        }
    }

    /// The table of `machine`; `system` counts on the lathe only.
    pub fn new(machine: MachineKind, system: GCodeSystem) -> CodeTable {
        match (machine, system) {
            (MachineKind::Mill, _) => CodeTable::Mill,
            (MachineKind::Lathe, GCodeSystem::A) => CodeTable::LatheA,
            (MachineKind::Lathe, GCodeSystem::B) => CodeTable::LatheB,
            (MachineKind::Lathe, GCodeSystem::C) => CodeTable::LatheC,
        }
    }

    /// Mill or lathe.
    #[inline]
    pub fn machine(self) -> MachineKind {
        match self {
            CodeTable::Mill | CodeTable::MillEngraving | CodeTable::MillLinuxcnc => {
                MachineKind::Mill
            }
            CodeTable::LatheA | CodeTable::LatheB | CodeTable::LatheC => MachineKind::Lathe,
        }
    }

    /// The lathe's G-code system (A on the mill, where it means nothing).
    #[inline]
    pub fn system(self) -> GCodeSystem {
        match self {
            CodeTable::Mill
            | CodeTable::MillEngraving
            | CodeTable::MillLinuxcnc
            | CodeTable::LatheA => GCodeSystem::A,
            CodeTable::LatheB => GCodeSystem::B,
            CodeTable::LatheC => GCodeSystem::C,
        }
    }

    /// True on the lathe in system B or C (G90/G91 are distance modes).
    pub fn lathe_distance_codes(self) -> bool {
        matches!(self, CodeTable::LatheB | CodeTable::LatheC)
    }
}

impl Default for CodeTable {
    fn default() -> Self {
        CodeTable::MILL
    }
}

impl From<MachineKind> for CodeTable {
    /// The machine's table in G-code system A.
    fn from(machine: MachineKind) -> CodeTable {
        CodeTable::new(machine, GCodeSystem::A)
    }
}

/// A G code resolved for the machine: the value of its modal group.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[allow(missing_docs)]
pub enum Code {
    NonModal(NonModal),
    Motion(Motion),
    Plane(Plane),
    Distance(Distance),
    FeedMode(FeedMode),
    Units(Units),
    CutterCompensation(CutterCompensation),
    Length(LengthOffset),
    Cycle(CannedCycle),
    Return(ReturnLevel),
    Work(WorkCode),
    SurfaceSpeed(SurfaceSpeed),
    CuttingMode(CuttingMode),
    Polar(Polar),
    Scaling(ScalingMode),
    Rotation(RotationMode),
    PolarCoordinates(PolarMode),
    Mirror(MirrorMode),
    ArcCenter(ArcCenter),
}

impl Code {
    /// The code this machine models for `g`, or None (then [`g_group`] says
    /// why). The one table from numbers to codes: the mill and the lathe
    /// read some numbers differently, and the lathe's G-code systems A, B
    /// and C number some codes differently (Fanuc 0i-TF, "G code list":
    /// behaviour 7.18). A new code is a line here and a variant of its
    /// group's type.
    #[inline(always)]
    pub fn of(table: CodeTable, g: GCode) -> Option<Code> {
        use ArcDirection::{Ccw, Cw};
        use Code as C;
        if g.minor != 0 {
            return Code::of_decimal(table, g);
        }
        Some(match table.machine() {
            MachineKind::Mill => match g.major {
                0 => C::Motion(Motion::Rapid),
                1 => C::Motion(Motion::Linear),
                2 => C::Motion(Motion::Arc(Cw)),
                3 => C::Motion(Motion::Arc(Ccw)),
                4 => C::NonModal(NonModal::Dwell),
                8 => C::NonModal(NonModal::LookAhead),
                9 => C::NonModal(NonModal::ExactStop),
                10 => C::NonModal(NonModal::DataSetting),
                12 => C::NonModal(NonModal::CirclePocket(Cw)),
                13 => C::NonModal(NonModal::CirclePocket(Ccw)),
                15 => C::PolarCoordinates(PolarMode::Cancel),
                16 => C::PolarCoordinates(PolarMode::Start),
                17 => C::Plane(Plane::XY),
                18 => C::Plane(Plane::ZX),
                19 => C::Plane(Plane::YZ),
                20 => C::Units(Units::Inch),
                21 => C::Units(Units::Mm),
                27 => C::NonModal(NonModal::ReferenceCheck),
                28 => C::NonModal(NonModal::ReferenceReturn),
                30 => C::NonModal(NonModal::OtherReference),
                31 => C::NonModal(NonModal::Skip),
                39 => C::NonModal(NonModal::CornerArc),
                40 => C::CutterCompensation(CutterCompensation::Cancel),
                41 => C::CutterCompensation(CutterCompensation::Left),
                42 => C::CutterCompensation(CutterCompensation::Right),
                43 => C::Length(LengthOffset::Add),
                44 => C::Length(LengthOffset::Subtract),
                45 => C::NonModal(NonModal::PositionOffset(PositionOffset::Extension)),
                46 => C::NonModal(NonModal::PositionOffset(PositionOffset::Reduction)),
                // Haas has no G45–G48: its G47 engraves text (behaviour 7.60).
                47 if table == CodeTable::MillEngraving => C::NonModal(NonModal::Engraving),
                47 => C::NonModal(NonModal::PositionOffset(PositionOffset::DoubleExtension)),
                48 => C::NonModal(NonModal::PositionOffset(PositionOffset::DoubleReduction)),
                49 => C::Length(LengthOffset::Cancel),
                50 => C::Scaling(ScalingMode::Cancel),
                51 => C::Scaling(ScalingMode::Start),
                52 => C::NonModal(NonModal::LocalCoordinates),
                53 => C::NonModal(NonModal::MachineCoordinates),
                54..=59 => C::Work(WorkCode::Standard(work_system(g.major))),
                61 if table == CodeTable::MillLinuxcnc => C::CuttingMode(CuttingMode::ExactPath),
                61 => C::CuttingMode(CuttingMode::ExactStop),
                62 => C::CuttingMode(CuttingMode::CornerOverride),
                63 => C::CuttingMode(CuttingMode::Tapping),
                64 => C::CuttingMode(CuttingMode::Cutting),
                68 => C::Rotation(RotationMode::Start),
                69 => C::Rotation(RotationMode::Cancel),
                73 => C::Cycle(CannedCycle::Cycle(Cycle::HighSpeedPeck)),
                74 => C::Cycle(CannedCycle::Cycle(Cycle::LeftHandTapping)),
                76 => C::Cycle(CannedCycle::Cycle(Cycle::FineBoring)),
                80 => C::Cycle(CannedCycle::Cancel),
                81 => C::Cycle(CannedCycle::Cycle(Cycle::Drilling)),
                82 => C::Cycle(CannedCycle::Cycle(Cycle::CounterBoring)),
                83 => C::Cycle(CannedCycle::Cycle(Cycle::PeckDrilling)),
                84 => C::Cycle(CannedCycle::Cycle(Cycle::Tapping)),
                85 => C::Cycle(CannedCycle::Cycle(Cycle::Boring)),
                86 => C::Cycle(CannedCycle::Cycle(Cycle::BoringSpindleStop)),
                87 => C::Cycle(CannedCycle::Cycle(Cycle::BackBoring)),
                88 => C::Cycle(CannedCycle::Cycle(Cycle::BoringManualRetract)),
                89 => C::Cycle(CannedCycle::Cycle(Cycle::BoringDwell)),
                90 => C::Distance(Distance::Absolute),
                91 => C::Distance(Distance::Incremental),
                92 => C::NonModal(NonModal::SetCoordinates),
                93 => C::FeedMode(FeedMode::InverseTime),
                94 => C::FeedMode(FeedMode::PerMinute),
                95 => C::FeedMode(FeedMode::PerRevolution),
                96 => C::SurfaceSpeed(SurfaceSpeed::Constant),
                97 => C::SurfaceSpeed(SurfaceSpeed::Cancel),
                98 => C::Return(ReturnLevel::Initial),
                99 => C::Return(ReturnLevel::R),
                103 => C::NonModal(NonModal::BlockLimit),
                110..=129 => C::Work(WorkCode::HaasNamed((g.major - 109) as u8)),
                154 => C::Work(WorkCode::Haas),
                187 => C::NonModal(NonModal::Smoothness),
                _ => return None,
            },
            MachineKind::Lathe => return lathe_code(table.system(), g.major),
        })
    }

    /// [`Code::of`] for a code written with a decimal (`G05.1`): out of line,
    /// as nearly every G code is a whole number (the parser's dispatch).
    #[inline(never)]
    fn of_decimal(table: CodeTable, g: GCode) -> Option<Code> {
        use Code as C;
        if let Some(code) = linuxcnc::decimal(table, g) {
            return Some(code);
        }
        Some(match (table.machine(), g.major, g.minor) {
            (MachineKind::Mill, 5, 1) => C::NonModal(NonModal::AiContour),
            (_, 7, 1) => C::NonModal(NonModal::Cylindrical),
            (MachineKind::Lathe, 12, 1) => C::Polar(Polar::On(PolarSpelling::Fanuc)),
            (MachineKind::Lathe, 13, 1) => C::Polar(Polar::Off(PolarSpelling::Fanuc)),
            (_, 54, 1) => C::Work(WorkCode::Additional),
            (MachineKind::Mill, 50, 1) => C::Mirror(MirrorMode::Cancel),
            (MachineKind::Mill, 51, 1) => C::Mirror(MirrorMode::Start),
            (MachineKind::Mill, 90, 1) => C::ArcCenter(ArcCenter::Absolute),
            (MachineKind::Mill, 91, 1) => C::ArcCenter(ArcCenter::Incremental),
            (MachineKind::Mill, 92, 1) => C::NonModal(NonModal::PresetCoordinates),
            _ => return None,
        })
    }

    /// The code's modal group (two of a group in one block is an error).
    #[inline(always)]
    pub fn group(self) -> Group {
        match self {
            Code::NonModal(_) => Group::NonModal,
            Code::Motion(_) => Group::Motion,
            Code::Plane(_) => Group::Plane,
            Code::Distance(_) => Group::Distance,
            Code::FeedMode(_) => Group::FeedMode,
            Code::Units(_) => Group::Units,
            Code::CutterCompensation(_) => Group::Cutter,
            Code::Length(_) => Group::Length,
            Code::Cycle(_) => Group::Cycle,
            Code::Return(_) => Group::Return,
            Code::Work(_) => Group::Work,
            Code::SurfaceSpeed(_) => Group::SurfaceSpeed,
            Code::CuttingMode(_) => Group::CuttingMode,
            Code::Polar(_) => Group::Polar,
            Code::Scaling(_) => Group::Scaling,
            Code::Rotation(_) => Group::Rotation,
            Code::PolarCoordinates(_) => Group::PolarCoordinates,
            Code::Mirror(_) => Group::Mirror,
            Code::ArcCenter(_) => Group::ArcCenter,
        }
    }

    /// The G code as the manuals write it in this table.
    pub fn gcode(self, table: CodeTable) -> &'static str {
        let machine = table.machine();
        if table.lathe_distance_codes() {
            // System B and C spell some lathe codes otherwise (behaviour 7.18).
            let c = table.system() == GCodeSystem::C;
            match self {
                Code::Motion(Motion::LatheCycle(cycle)) => {
                    return match (cycle, c) {
                        (LatheCycle::Turning, false) => "G77",
                        (LatheCycle::Threading, false) => "G78",
                        (LatheCycle::Facing, false) => "G79",
                        (LatheCycle::Turning, true) => "G20",
                        (LatheCycle::Threading, true) => "G21",
                        (LatheCycle::Facing, true) => "G24",
                    };
                }
                Code::NonModal(NonModal::Repetitive(r)) if c => return r.gcode_system_c(),
                Code::Units(Units::Inch) if c => return "G70",
                Code::Units(Units::Mm) if c => return "G71",
                Code::NonModal(NonModal::SetCoordinates) => return "G92",
                Code::FeedMode(FeedMode::PerMinute) => return "G94",
                Code::FeedMode(FeedMode::PerRevolution) => return "G95",
                _ => {}
            }
        }
        match self {
            Code::NonModal(c) => c.gcode(machine),
            Code::Motion(c) => c.gcode(),
            Code::Plane(c) => c.gcode(),
            Code::Distance(c) => c.gcode(),
            Code::FeedMode(c) => c.gcode(machine),
            Code::Units(c) => c.gcode(),
            Code::CutterCompensation(c) => c.gcode(),
            Code::Length(c) => c.gcode(),
            Code::Cycle(c) => c.gcode(),
            Code::Return(c) => c.gcode(),
            Code::Work(c) => c.gcode(),
            Code::SurfaceSpeed(c) => c.gcode(),
            Code::CuttingMode(c) => c.gcode(),
            Code::Polar(c) => c.gcode(),
            Code::Scaling(c) => c.gcode(),
            Code::Rotation(c) => c.gcode(),
            Code::PolarCoordinates(c) => c.gcode(),
            Code::Mirror(c) => c.gcode(),
            Code::ArcCenter(c) => c.gcode(),
        }
    }
}

/// The lathe's table (behaviour 1.12, 7.18), out of line: the parser's reading
/// of every block inlines the mill's table, and this one's size kept the
/// reading of a block from being inlined (the `check` instruction count in
/// docs/performance.md).
#[inline(never)]
fn lathe_code(system: GCodeSystem, major: u16) -> Option<Code> {
    use ArcDirection::{Ccw, Cw};
    use Code as C;
    // The codes every system numbers alike.
    match major {
        0 => return Some(C::Motion(Motion::Rapid)),
        1 => return Some(C::Motion(Motion::Linear)),
        2 => return Some(C::Motion(Motion::Arc(Cw))),
        3 => return Some(C::Motion(Motion::Arc(Ccw))),
        4 => return Some(C::NonModal(NonModal::Dwell)),
        10 => return Some(C::NonModal(NonModal::DataSetting)),
        // G17: the XY plane of live tooling, which polar coordinate
        // interpolation uses (Haas writes it before G112; behaviour 14.15).
        17 => return Some(C::Plane(Plane::XY)),
        18 => return Some(C::Plane(Plane::ZX)),
        27 => return Some(C::NonModal(NonModal::ReferenceCheck)),
        28 => return Some(C::NonModal(NonModal::ReferenceReturn)),
        30 => return Some(C::NonModal(NonModal::OtherReference)),
        40 => return Some(C::CutterCompensation(CutterCompensation::Cancel)),
        // Tool nose radius compensation (behaviour 18).
        41 => return Some(C::CutterCompensation(CutterCompensation::Left)),
        42 => return Some(C::CutterCompensation(CutterCompensation::Right)),
        31 => return Some(C::NonModal(NonModal::Skip)),
        52 => return Some(C::NonModal(NonModal::LocalCoordinates)),
        53 => return Some(C::NonModal(NonModal::MachineCoordinates)),
        54..=59 => return Some(C::Work(WorkCode::Standard(work_system(major)))),
        154 => return Some(C::Work(WorkCode::Haas)),
        // The lathe's canned cycle cancel (Fanuc T group 10): its drilling
        // cycles are refused (behaviour 14.9).
        80 => return Some(C::Cycle(CannedCycle::Cancel)),
        96 => return Some(C::SurfaceSpeed(SurfaceSpeed::Constant)),
        97 => return Some(C::SurfaceSpeed(SurfaceSpeed::Cancel)),
        112 => return Some(C::Polar(Polar::On(PolarSpelling::Haas))),
        113 => return Some(C::Polar(Polar::Off(PolarSpelling::Haas))),
        _ => {}
    }
    let turning = C::Motion(Motion::LatheCycle(LatheCycle::Turning));
    let threading = C::Motion(Motion::LatheCycle(LatheCycle::Threading));
    let facing = C::Motion(Motion::LatheCycle(LatheCycle::Facing));
    let mrc = |r| C::NonModal(NonModal::Repetitive(r));
    Some(match (system, major) {
        (GCodeSystem::A | GCodeSystem::B, 20) | (GCodeSystem::C, 70) => C::Units(Units::Inch),
        (GCodeSystem::A | GCodeSystem::B, 21) | (GCodeSystem::C, 71) => C::Units(Units::Mm),
        (GCodeSystem::A, 50) | (GCodeSystem::B | GCodeSystem::C, 92) => {
            C::NonModal(NonModal::SetCoordinates)
        }
        (GCodeSystem::A, 90) | (GCodeSystem::B, 77) | (GCodeSystem::C, 20) => turning,
        (GCodeSystem::A, 92) | (GCodeSystem::B, 78) | (GCodeSystem::C, 21) => threading,
        (GCodeSystem::A, 94) | (GCodeSystem::B, 79) | (GCodeSystem::C, 24) => facing,
        (GCodeSystem::A, 98) | (GCodeSystem::B | GCodeSystem::C, 94) => {
            C::FeedMode(FeedMode::PerMinute)
        }
        (GCodeSystem::A, 99) | (GCodeSystem::B | GCodeSystem::C, 95) => {
            C::FeedMode(FeedMode::PerRevolution)
        }
        // The multiple repetitive cycles: G70–G76 in systems A and B,
        // G72–G78 in C (Fanuc 0i-TF, "G code list"; behaviour 15.1).
        (GCodeSystem::A | GCodeSystem::B, 70) | (GCodeSystem::C, 72) => mrc(Repetitive::Finishing),
        (GCodeSystem::A | GCodeSystem::B, 71) | (GCodeSystem::C, 73) => {
            mrc(Repetitive::TurningStock)
        }
        (GCodeSystem::A | GCodeSystem::B, 72) | (GCodeSystem::C, 74) => {
            mrc(Repetitive::FacingStock)
        }
        (GCodeSystem::A | GCodeSystem::B, 73) | (GCodeSystem::C, 75) => {
            mrc(Repetitive::PatternRepeat)
        }
        (GCodeSystem::A | GCodeSystem::B, 74) | (GCodeSystem::C, 76) => mrc(Repetitive::FacePeck),
        (GCodeSystem::A | GCodeSystem::B, 75) | (GCodeSystem::C, 77) => {
            mrc(Repetitive::DiameterPeck)
        }
        (GCodeSystem::A | GCodeSystem::B, 76) | (GCodeSystem::C, 78) => mrc(Repetitive::Threading),
        (GCodeSystem::B | GCodeSystem::C, 90) => C::Distance(Distance::Absolute),
        (GCodeSystem::B | GCodeSystem::C, 91) => C::Distance(Distance::Incremental),
        _ => return None,
    })
}

/// G54 … G59 from 54 … 59 (other numbers are not passed here).
#[inline(always)]
fn work_system(major: u16) -> WorkSystem {
    match major {
        54 => WorkSystem::G54,
        55 => WorkSystem::G55,
        56 => WorkSystem::G56,
        57 => WorkSystem::G57,
        58 => WorkSystem::G58,
        _ => WorkSystem::G59,
    }
}

/// The G codes of one block, one typed value per modal group: the parser
/// resolved each (and refused a block with two of a group or an unknown
/// code), so the machine reads them here.
#[derive(Clone, Copy, Debug)]
pub struct Codes {
    /// The groups that hold a code, a bit each (by [`Group::index`]):
    /// emptying the block for the next is this one store, whatever the
    /// values left behind (the `check` instruction count in
    /// docs/performance.md: clearing an array of `Option<Code>` cost two
    /// dozen instructions a block).
    present: u32,
    /// Per group, its code, valid where `present` has the group's bit:
    /// keeping a code is one store, which the parser does for every G word.
    by_group: [Code; Group::COUNT],
}

impl Default for Codes {
    fn default() -> Self {
        Codes {
            present: 0,
            by_group: [Code::Motion(Motion::Rapid); Group::COUNT],
        }
    }
}

impl PartialEq for Codes {
    fn eq(&self, other: &Codes) -> bool {
        self.present == other.present && self.each().eq(other.each())
    }
}

impl Eq for Codes {}

/// The accessor of one group's value.
macro_rules! group_value {
    ($(#[$doc:meta])* $name:ident, $variant:ident, $group:ident, $ty:ty) => {
        $(#[$doc])*
        #[inline(always)]
        pub fn $name(&self) -> Option<$ty> {
            if self.present & 1 << Group::$group as usize == 0 {
                return None;
            }
            match self.by_group[Group::$group as usize] {
                Code::$variant(c) => Some(c),
                // `set` keeps each code under its own group.
                _ => None,
            }
        }
    };
}

impl Codes {
    /// Keeps `code` as its group's value.
    #[inline(always)]
    pub(crate) fn set(&mut self, code: Code, group: Group) {
        self.by_group[group.index()] = code;
        self.present |= 1 << group.index();
    }

    /// Forgets every code (the values stay, unread).
    #[inline(always)]
    pub(crate) fn clear(&mut self) {
        self.present = 0;
    }

    /// Every code of the block, in group order ([`Group::ALL`]).
    pub fn each(&self) -> impl Iterator<Item = Code> + '_ {
        self.by_group
            .iter()
            .enumerate()
            .filter(|(i, _)| self.present & 1 << i != 0)
            .map(|(_, c)| *c)
    }

    group_value!(
        /// Group 00: G04, G28, G45–G48, G92 (lathe G50).
        non_modal, NonModal, NonModal, NonModal
    );
    group_value!(
        /// Group 01.
        motion, Motion, Motion, Motion
    );
    group_value!(
        /// Group 02.
        plane, Plane, Plane, Plane
    );
    group_value!(
        /// Group 03 (mill).
        distance, Distance, Distance, Distance
    );
    group_value!(
        /// Group 05.
        feed_mode, FeedMode, FeedMode, FeedMode
    );
    group_value!(
        /// Group 06.
        units, Units, Units, Units
    );
    group_value!(
        /// Group 07.
        cutter, CutterCompensation, Cutter, CutterCompensation
    );
    group_value!(
        /// Group 08 (mill).
        length, Length, Length, LengthOffset
    );
    group_value!(
        /// Group 09 (mill).
        cycle, Cycle, Cycle, CannedCycle
    );
    group_value!(
        /// Group 10 (mill).
        return_level, Return, Return, ReturnLevel
    );
    group_value!(
        /// Group 14.
        work, Work, Work, WorkCode
    );
    group_value!(
        /// Lathe group 02, mill group 13.
        surface_speed, SurfaceSpeed, SurfaceSpeed, SurfaceSpeed
    );
    group_value!(
        /// Mill group 15.
        cutting_mode, CuttingMode, CuttingMode, CuttingMode
    );
    group_value!(
        /// Lathe group 21.
        polar, Polar, Polar, Polar
    );
    group_value!(
        /// Group 11 (mill).
        scaling, Scaling, Scaling, ScalingMode
    );
    group_value!(
        /// Group 16 (mill).
        rotation, Rotation, Rotation, RotationMode
    );
    group_value!(
        /// Group 17 (mill).
        polar_coordinates, PolarCoordinates, PolarCoordinates, PolarMode
    );
    group_value!(
        /// Group 22 (mill).
        mirror, Mirror, Mirror, MirrorMode
    );
    group_value!(
        /// G90.1/G91.1 (mill).
        arc_center, ArcCenter, ArcCenter, ArcCenter
    );
}

/// The modal group of a G code this table models, or why it does not.
pub fn g_group(table: CodeTable, g: GCode) -> Result<Group, String> {
    Code::of(table, g)
        .map(Code::group)
        .ok_or_else(|| unsupported_reason(table, g))
}

fn unsupported_reason(table: CodeTable, g: GCode) -> String {
    let machine = table.machine();
    let lathe = machine == MachineKind::Lathe;
    let system_b_or_c = table.lathe_distance_codes();
    if g.minor != 0 {
        let why = match (g.major, g.minor) {
            (12 | 13, 1) => {
                "polar coordinate interpolation is modelled on the lathe only (with X and C)"
            }
            (5, 1) => "AI contour control is a mill code (G05.1 Q1/Q0)",
            (66, 1) => {
                "the modal macro call G66.1 (a call at every block) is not modelled; G66 calls after each move (behaviour 21.5)"
            }
            (61, 1) => "G61.1 is LinuxCNC's exact stop (and Mitsubishi's); use G61 for exact stop",
            (31, _) => {
                "the multi-step and high-speed skip codes are not modelled; G31 (with P1–P4) is"
            }
            _ => "is not a G code offsetlab knows",
        };
        return if why.starts_with("is not") {
            format!("{g} {why} on the {}", machine.as_str())
        } else {
            format!("{g}: {why}")
        };
    }
    let why = match g.major {
        39 if lathe => "corner circular interpolation is a mill code (cutter compensation)",
        43 | 44 | 49 if lathe => "the lathe uses T-code offsets, not G43/G44/G49 (seed 004)",
        45..=48 if lathe => "the lathe uses T-code offsets, not G45–G48 (seed 004)",
        32..=34 => "thread cutting blocks are not supported",
        50 if lathe && system_b_or_c => {
            "in G-code system B and C the coordinate system is set with G92 (setting gcode_system)"
        }
        51 if lathe => "scaling is the mill's (the lathe's G50 sets the coordinate system)",
        68 | 69 if lathe => "coordinate rotation is the mill's in offsetlab",
        15 | 16 if lathe => "polar coordinates are the mill's in offsetlab",
        19 if lathe => {
            "the lathe's planes are G18 (ZX, turning) and G17 (the face, for polar coordinate interpolation); the YZ plane of a Y-axis lathe is not modelled"
        }
        61..=64 | 9 | 8 | 93 | 187 if lathe => "this cutting-mode or feed code is a mill code",
        12 | 13 if lathe => {
            "circular pocket milling is a mill code; polar coordinate interpolation is G12.1/G13.1 (Haas G112/G113)"
        }
        81..=89 if lathe => {
            "the lathe's drilling canned cycles (live tooling) are not modelled; G80 cancels them"
        }
        112 | 113 => "polar coordinate interpolation is modelled on the lathe only",
        91 if lathe => {
            "the lathe in G-code system A has no G91: U and W are the incremental axes (setting gcode_system B or C makes G90/G91 the distance modes)"
        }
        _ => "is not a G code offsetlab knows",
    };
    if why.starts_with("is not") {
        let system = if system_b_or_c {
            format!(" (G-code system {})", table.system().as_str())
        } else {
            String::new()
        };
        format!("{g} {why} on the {}{system}", machine.as_str())
    } else {
        format!("{g}: {why}")
    }
}

#[cfg(test)]
mod tests;
