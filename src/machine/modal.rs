//! Modal state: the G codes that stay in effect until another code of their
//! group replaces them (spec 2: mill start state G00 G17 G90 G21 G40 G49 G80
//! G54 G94).

use serde::Serialize;

use crate::setup::{MachineKind, Units};

/// Group 01: how axis words move the tool.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Motion {
    /// G00.
    Rapid,
    /// G01.
    Linear,
    /// G02.
    ArcCw,
    /// G03.
    ArcCcw,
    /// Lathe G90: outer/inner diameter turning cycle.
    TurningCycle,
    /// Lathe G92: thread cutting cycle.
    ThreadingCycle,
    /// Lathe G94: end facing cycle.
    FacingCycle,
}

impl Motion {
    /// The G code.
    pub fn gcode(self) -> &'static str {
        match self {
            Motion::Rapid => "G00",
            Motion::Linear => "G01",
            Motion::ArcCw => "G02",
            Motion::ArcCcw => "G03",
            Motion::TurningCycle => "G90",
            Motion::ThreadingCycle => "G92",
            Motion::FacingCycle => "G94",
        }
    }
    /// From a group-01 code number.
    pub fn from_code(machine: MachineKind, n: u16) -> Option<Motion> {
        Some(match (machine, n) {
            (_, 0) => Motion::Rapid,
            (_, 1) => Motion::Linear,
            (_, 2) => Motion::ArcCw,
            (_, 3) => Motion::ArcCcw,
            (MachineKind::Lathe, 90) => Motion::TurningCycle,
            (MachineKind::Lathe, 92) => Motion::ThreadingCycle,
            (MachineKind::Lathe, 94) => Motion::FacingCycle,
            _ => return None,
        })
    }
    /// G02 or G03.
    pub fn is_arc(self) -> bool {
        matches!(self, Motion::ArcCw | Motion::ArcCcw)
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

/// A canned cycle of the mill (group 09), or none (G80).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Cycle(pub u16);

impl Cycle {
    /// G80.
    pub const NONE: Cycle = Cycle(80);
    /// True when a cycle is active.
    pub fn active(self) -> bool {
        self.0 != 80
    }
}

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
    pub feed_per_rev: bool,
    /// Group 08 (mill): G43, G44 or G49.
    pub length: u16,
    /// Group 09 (mill).
    pub cycle: Cycle,
    /// Group 10 (mill): return to the R level (G99) instead of the initial level.
    pub return_to_r: bool,
    /// Group 14: 0 = G54 … 5 = G59.
    pub work: u8,
    /// Lathe: constant surface speed (G96) instead of G97.
    pub surface_speed: bool,
}

impl Modal {
    /// The start state (spec 2).
    pub fn start(machine: MachineKind, units: Units) -> Modal {
        Modal {
            motion: Motion::Rapid,
            plane: match machine {
                MachineKind::Mill => Plane::XY,
                MachineKind::Lathe => Plane::ZX,
            },
            distance: Distance::Absolute,
            units,
            feed_per_rev: machine == MachineKind::Lathe,
            length: 49,
            cycle: Cycle::NONE,
            return_to_r: false,
            work: 0,
            surface_speed: false,
        }
    }

    /// The modal codes as the manuals write them, for reports.
    pub fn codes(&self, machine: MachineKind) -> ModalCodes {
        let mill = machine == MachineKind::Mill;
        ModalCodes {
            motion: self.motion.gcode(),
            plane: self.plane.gcode(),
            distance: mill.then_some(match self.distance {
                Distance::Absolute => "G90",
                Distance::Incremental => "G91",
            }),
            units: self.units.gcode(),
            feed_mode: match (mill, self.feed_per_rev) {
                (true, false) => "G94",
                (true, true) => "G95",
                (false, false) => "G98",
                (false, true) => "G99",
            },
            length: mill.then_some(match self.length {
                43 => "G43",
                44 => "G44",
                _ => "G49",
            }),
            cycle: mill.then(|| cycle_name(self.cycle.0)),
            return_level: mill.then_some(if self.return_to_r { "G99" } else { "G98" }),
            work: ["G54", "G55", "G56", "G57", "G58", "G59"][usize::from(self.work.min(5))],
            surface_speed: (!mill).then_some(if self.surface_speed { "G96" } else { "G97" }),
        }
    }
}

fn cycle_name(n: u16) -> &'static str {
    match n {
        73 => "G73",
        74 => "G74",
        76 => "G76",
        81 => "G81",
        82 => "G82",
        83 => "G83",
        84 => "G84",
        85 => "G85",
        86 => "G86",
        87 => "G87",
        88 => "G88",
        89 => "G89",
        _ => "G80",
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
