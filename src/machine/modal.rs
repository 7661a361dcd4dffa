//! Modal state: the G codes that stay in effect until another code of their
//! group replaces them (behaviour 2.3: mill start state G00 G17 G90 G21 G40 G49 G80
//! G54 G94).

use serde::Serialize;

use crate::setup::{MachineKind, Units};
pub use crate::syntax::codes::{
    ArcDirection, Cycle, Distance, FeedMode, LatheCycle, LengthOffset, Motion, Plane, ReturnLevel,
    SurfaceSpeed, WorkSystem,
};
use crate::syntax::codes::{CannedCycle, Code, CodeTable};

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
    /// Lathe group 02: constant surface speed (G96) or G97.
    pub surface_speed: SurfaceSpeed,
}

impl Modal {
    /// The start state (behaviour 2.3).
    pub fn start(machine: MachineKind, units: Units) -> Modal {
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
            return_level: ReturnLevel::Initial,
            work: WorkSystem::G54,
            surface_speed: SurfaceSpeed::Cancel,
        }
    }

    /// The modal codes as the manuals write them in this table, for reports.
    pub fn codes(&self, table: impl Into<CodeTable>) -> ModalCodes {
        let table: CodeTable = table.into();
        let mill = table.machine() == MachineKind::Mill;
        ModalCodes {
            motion: Code::Motion(self.motion).gcode(table),
            plane: self.plane.gcode(),
            // The lathe has the distance codes in G-code systems B and C.
            distance: (mill || table.lathe_distance_codes()).then_some(self.distance.gcode()),
            units: Code::Units(self.units).gcode(table),
            feed_mode: Code::FeedMode(self.feed_mode).gcode(table),
            length: mill.then_some(self.length.gcode()),
            cycle: mill.then(|| self.cycle.map_or(CannedCycle::Cancel.gcode(), Cycle::gcode)),
            return_level: mill.then_some(self.return_level.gcode()),
            work: self.work.gcode(),
            surface_speed: (!mill).then_some(self.surface_speed.gcode()),
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
    /// Lathe group 02.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub surface_speed: Option<&'static str>,
}
