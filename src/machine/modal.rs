//! Modal state: the G codes that stay in effect until another code of their
//! group replaces them (behaviour 2.3: mill start state G00 G17 G90 G21 G40 G49 G80
//! G54 G94).

use serde::Serialize;

use super::frame::Transforms;
use crate::setup::{MachineKind, Units};
use crate::syntax::Address;
pub use crate::syntax::codes::{
    ArcCenter, ArcDirection, CuttingMode, Cycle, Distance, FeedMode, LatheCycle, LengthOffset,
    Motion, Plane, Polar, PolarMode, PolarSpelling, ReturnLevel, SurfaceSpeed, WorkSystem,
};
use crate::syntax::codes::{CannedCycle, Code, CodeTable, MirrorMode, RotationMode, ScalingMode};

/// All modal codes a block report shows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Modal {
    /// Group 01.
    pub motion: Motion,
    /// Group 02 (the lathe is always G18).
    pub plane: Plane,
    /// Group 03 (mill).
    pub distance: Distance,
    /// Group 06.
    pub units: Units,
    /// Group 05: feed per minute (mill G94, lathe G98) or per revolution.
    pub feed_mode: FeedMode,
    /// Group 08 (mill): G43, G44 or G49.
    pub length: LengthOffset,
    /// Group 09 (mill): the active canned cycle, None after G80.
    pub cycle: Option<Cycle>,
    /// Group 10 (mill): where a canned cycle returns to.
    pub return_level: ReturnLevel,
    /// Group 14.
    pub work: WorkSystem,
    /// Constant surface speed (G96) or G97: lathe group 02, mill group 13.
    pub surface_speed: SurfaceSpeed,
    /// Mill group 15: G61–G64 (behaviour 14.2).
    pub cutting_mode: CuttingMode,
    /// Mill: Fanuc AI contour control, G05.1 Q1 (behaviour 14.4).
    pub ai_contour: bool,
    /// Mill: Fanuc look-ahead, G08 P1 (behaviour 14.5).
    pub look_ahead: bool,
    /// Mill: Haas G187 smoothness, once a G187 was given (behaviour 14.6).
    pub smoothness: Option<Smoothness>,
    /// G07.1: cylindrical interpolation on, with its rotary axis and the
    /// cylinder's radius (mm) (behaviour 14.10).
    pub cylinder: Option<(Address, f64)>,
    /// Lathe group 21: polar coordinate interpolation (behaviour 14.11).
    pub polar: Polar,
    /// Groups 11, 16 and 22 (mill) with their data: scaling, rotation and
    /// programmable mirror image (behaviour 13.8–13.10).
    pub transforms: Transforms,
    /// Group 17 (mill): polar coordinates (behaviour 13.11).
    pub polar_coordinates: PolarMode,
    /// G90.1/G91.1 (mill), None until the program writes one (behaviour
    /// 13.12).
    pub arc_center: Option<ArcCenter>,
    /// LinuxCNC's G80 motion mode (behaviour 22.18): no motion code is in
    /// effect, at the start and after G80; `motion` keeps the last one.
    pub motion_none: bool,
}

/// Haas G187's smoothness: a level and a corner tolerance (behaviour 14.6).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Smoothness {
    /// P1 (rough) to P3 (finish); 0 for G187 without P, Setting 191's level.
    pub level: u8,
    /// E: how far the control may round a corner (mm), if given.
    pub corner: Option<f64>,
}

impl Smoothness {
    /// The code as the state panel shows it.
    pub fn code(self) -> &'static str {
        match self.level {
            1 => "G187 P1",
            2 => "G187 P2",
            3 => "G187 P3",
            _ => "G187",
        }
    }
}

impl Modal {
    /// The start state (behaviour 2.3).
    pub fn start(setup: &crate::setup::Setup) -> Modal {
        let (machine, units) = (setup.machine, setup.units);
        Modal {
            motion: Motion::Rapid,
            plane: match machine {
                MachineKind::Mill => Plane::XY,
                MachineKind::Lathe => Plane::ZX,
            },
            distance: Distance::Absolute,
            units,
            feed_mode: match machine {
                MachineKind::Mill => FeedMode::PerMinute,
                MachineKind::Lathe => FeedMode::PerRevolution,
            },
            length: LengthOffset::Cancel,
            cycle: None,
            // LinuxCNC starts in G99 (`rs274 -g`: a cycle without G98/G99
            // returns to R, behaviour 22.3); the Fanuc family in G98.
            return_level: match setup.settings.control {
                crate::setup::Control::Linuxcnc => ReturnLevel::R,
                _ => ReturnLevel::Initial,
            },
            work: WorkSystem::G54,
            surface_speed: SurfaceSpeed::Cancel,
            cutting_mode: CuttingMode::Cutting,
            ai_contour: false,
            look_ahead: false,
            smoothness: None,
            cylinder: None,
            polar: Polar::Off(PolarSpelling::Fanuc),
            transforms: Transforms::default(),
            polar_coordinates: PolarMode::Cancel,
            arc_center: None,
            motion_none: setup.settings.control == crate::setup::Control::Linuxcnc
                && machine == MachineKind::Mill,
        }
    }

    /// The modal codes as the manuals write them in this table, for reports.
    pub fn codes(&self, table: impl Into<CodeTable>) -> ModalCodes {
        let table: CodeTable = table.into();
        let mill = table.machine() == MachineKind::Mill;
        ModalCodes {
            motion: match self.motion_none {
                true => CannedCycle::Cancel.gcode(),
                false => Code::Motion(self.motion).gcode(table),
            },
            plane: self.plane.gcode(),
            // The lathe has the distance codes in G-code systems B and C.
            distance: (mill || table.lathe_distance_codes()).then_some(self.distance.gcode()),
            units: Code::Units(self.units).gcode(table),
            feed_mode: Code::FeedMode(self.feed_mode).gcode(table),
            cutter: None,
            length: mill.then_some(self.length.gcode()),
            // The lathe's G80 (behaviour 14.9): no drilling cycle is ever active there.
            cycle: Some(self.cycle.map_or(CannedCycle::Cancel.gcode(), Cycle::gcode)),
            return_level: mill.then_some(self.return_level.gcode()),
            work: self.work.gcode(),
            surface_speed: Some(self.surface_speed.gcode()),
            cutting_mode: mill.then_some(self.cutting_mode.gcode()),
            ai_contour: self.ai_contour.then_some("G05.1 Q1"),
            look_ahead: self.look_ahead.then_some("G08 P1"),
            smoothness: self.smoothness.map(Smoothness::code),
            cylindrical: self.cylinder.map(|_| "G07.1"),
            polar: (!mill).then_some(self.polar.gcode()),
            scaling: mill.then_some(match self.transforms.scaling {
                Some(_) => ScalingMode::Start.gcode(),
                None => ScalingMode::Cancel.gcode(),
            }),
            rotation: mill.then_some(match self.transforms.rotation {
                Some(_) => RotationMode::Start.gcode(),
                None => RotationMode::Cancel.gcode(),
            }),
            polar_coordinates: mill.then_some(self.polar_coordinates.gcode()),
            mirror: mill.then_some(if self.transforms.mirror == [None; 3] {
                MirrorMode::Cancel.gcode()
            } else {
                MirrorMode::Start.gcode()
            }),
            arc_center: self.arc_center.filter(|_| mill).map(ArcCenter::gcode),
        }
    }
}

/// Modal codes by group, as written in the manuals (JSON `modal`).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ModalCodes {
    /// Group 01.
    pub motion: &'static str,
    /// Group 02.
    pub plane: &'static str,
    /// Group 03 (mill).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub distance: Option<&'static str>,
    /// Group 06.
    pub units: &'static str,
    /// Group 05.
    pub feed_mode: &'static str,
    /// Group 07 (mill): G40, G41 or G42 (behaviour 16), filled from the
    /// block's [`crate::offsets::cutter::CutterState`] by
    /// [`crate::machine::BlockState::modal_codes`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cutter: Option<&'static str>,
    /// Group 08 (mill).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub length: Option<&'static str>,
    /// Group 09 (mill).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cycle: Option<&'static str>,
    /// Group 10 (mill).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub return_level: Option<&'static str>,
    /// Group 14.
    pub work: &'static str,
    /// Constant surface speed: lathe group 02, mill group 13.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub surface_speed: Option<&'static str>,
    /// Group 15 (mill): G61–G64.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cutting_mode: Option<&'static str>,
    /// `G05.1 Q1` while AI contour control is on (mill).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ai_contour: Option<&'static str>,
    /// `G08 P1` while look-ahead is on (mill).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub look_ahead: Option<&'static str>,
    /// Haas G187's level, once given (mill).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub smoothness: Option<&'static str>,
    /// `G07.1` while cylindrical interpolation is on.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cylindrical: Option<&'static str>,
    /// Group 21 (lathe): G12.1/G112 or G13.1/G113.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub polar: Option<&'static str>,
    /// Group 11 (mill): G51 or G50.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub scaling: Option<&'static str>,
    /// Group 16 (mill): G68 or G69.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rotation: Option<&'static str>,
    /// Group 17 (mill): G16 or G15.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub polar_coordinates: Option<&'static str>,
    /// Group 22 (mill): G51.1 or G50.1.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mirror: Option<&'static str>,
    /// G90.1 or G91.1 (mill), once the program writes one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub arc_center: Option<&'static str>,
}
