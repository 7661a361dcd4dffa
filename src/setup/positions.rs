//! Where the machine starts and where its reference position is when the
//! setup leaves them out (behaviour 13.15, setting 7.49): at the work zero,
//! the seeds' drawings' convention, or where a typical machine of each kind
//! has them, or the tool at the work zero under a typical reference, so
//! that `G91 G28 Z0.` rises to the top of the travel and a
//! lathe starts at the turret's home rather than on the centre line.

use serde::{Deserialize, Serialize};

use super::{MachineKind, Position, Settings, Setup};
use crate::setup::Control;

/// What `start` and `reference` left out (all zero) are (behaviour 7.49).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum MachinePositions {
    /// The tool starts at the G54 zero and the reference position is machine
    /// zero, which the default work offsets put at the work zero.
    WorkZero,
    /// A typical machine's: the reference position at the positive end of
    /// the travel (where machine zero is on a Haas or Fanuc machine) and the
    /// tool starting there, homed.
    Typical,
    /// The tool starts at the G54 zero, as the seeds' drawings do, and the
    /// reference position is a typical machine's, above the work: a return
    /// to it (`G91 G28 Z0.`) goes up, as on every machine, never into the
    /// part (YASNAC's default).
    WorkZeroStart,
}

/// A typical vertical machining centre's reference position above the work
/// zero, in inches: the Haas VF-2's Z travel, 20 in (508 mm), the work zero
/// taken at the bottom of the travel and X, Y over it (behaviour 13.15).
const MILL_HOME_INCH: [f64; 3] = [0.0, 0.0, 20.0];

/// A typical small lathe's turret home from the work zero (the centre line
/// at the part's face), in inches: the Haas ST-10's travels, X 8 in (a
/// diameter of 16 in) and Z 14 in, the work zero at their near ends.
const LATHE_HOME_INCH: [f64; 3] = [16.0, 0.0, 14.0];

impl Settings {
    /// `start` and `reference` left out: on YASNAC the tool starts at the
    /// work zero (the seeds' drawings start there) under a typical
    /// machine's reference position, a typical machine's both on Fanuc and
    /// Haas.
    pub fn machine_positions(&self) -> MachinePositions {
        self.machine_positions.unwrap_or(match self.control {
            Control::Yasnac => MachinePositions::WorkZeroStart,
            Control::Fanuc | Control::Haas => MachinePositions::Typical,
            // LinuxCNC's interpreter starts at the origin with every stored
            // position (#5161…, #5181…) 0 until the parameter file says.
            Control::Linuxcnc => MachinePositions::WorkZero,
        })
    }
}

impl Setup {
    /// The typical machine's home in setup units, or the origin.
    fn home(&self) -> Position {
        if self.settings.machine_positions() == MachinePositions::WorkZero {
            return Position::default();
        }
        let inch = match self.machine {
            MachineKind::Mill => MILL_HOME_INCH,
            MachineKind::Lathe => LATHE_HOME_INCH,
        };
        let k = 25.4 / self.units.mm();
        Position {
            x: inch[0] * k,
            y: inch[1] * k,
            z: inch[2] * k,
        }
    }

    /// Where the tool starts, in G54 coordinates and setup units: `start`,
    /// or when it is left out (all zero) the home of setting 7.49 — a
    /// typical machine starts homed, at its reference position, which is
    /// in machine coordinates: less G54's zero and the external offset.
    pub fn start_position(&self) -> Position {
        if self.start != Position::default()
            || self.settings.machine_positions() != MachinePositions::Typical
        {
            return self.start;
        }
        let (home, w) = (self.first_reference(), &self.work_offsets);
        Position {
            x: home.x - w.g54.x - w.ext.x,
            y: home.y - w.g54.y - w.ext.y,
            z: home.z - w.g54.z - w.ext.z,
        }
    }

    /// The first reference position in machine coordinates and setup units:
    /// `reference`, or when it is left out the home of setting 7.49.
    pub fn first_reference(&self) -> Position {
        if self.reference != Position::default() {
            return self.reference;
        }
        self.home()
    }
}

/// The start and reference positions a run uses, as the setup gives them or
/// setting 7.49 fills them in (behaviour 13.16): what the Settings panel
/// shows beside the fields left at 0 0 0.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct PositionsInEffect {
    /// The setup's units, which the positions are in.
    pub units: super::Units,
    /// Setting 7.49 as in effect (the control's default when left out).
    pub machine_positions: MachinePositions,
    /// Where the tool starts, in G54 coordinates (lathe X a diameter).
    pub start: Position,
    /// The first reference position (G28), in machine coordinates.
    pub reference: Position,
    /// The second reference position (G30), in machine coordinates.
    pub second_reference: Position,
}

impl Setup {
    /// The start and reference positions in effect (behaviour 13.16).
    /// Rounded to a millionth of the unit, as the reports are (6.2).
    pub fn positions_in_effect(&self) -> PositionsInEffect {
        let round = |p: Position| Position {
            x: crate::geometry::round6(p.x),
            y: crate::geometry::round6(p.y),
            z: crate::geometry::round6(p.z),
        };
        PositionsInEffect {
            units: self.units,
            machine_positions: self.settings.machine_positions(),
            start: round(self.start_position()),
            reference: round(self.first_reference()),
            second_reference: round(
                self.second_reference
                    .unwrap_or_else(|| self.first_reference()),
            ),
        }
    }
}

impl Setup {
    /// Where the tool starts (G54 coordinates, mm; the lathe's Y 0) and
    /// G54's zero with the external work offset every system carries
    /// (machine coordinates, mm, behaviour 17.9): a run's first position.
    pub fn start_and_origin_mm(&self) -> (crate::geometry::Xyz, crate::geometry::Xyz) {
        use crate::geometry::{add, scale};
        let unit = self.units.mm();
        let w = &self.work_offsets;
        let origin = scale(add(w.get(0).to_array(), w.ext.to_array()), unit);
        let start = scale(self.start_position().to_array(), unit);
        let start = match self.machine {
            MachineKind::Mill => start,
            MachineKind::Lathe => [start[0], 0.0, start[2]],
        };
        (start, origin)
    }

    /// The tool's machine position before a run's first block, mm (the
    /// first block's distance to go starts there, behaviour 6.12).
    pub fn start_machine_position_mm(&self) -> crate::geometry::Xyz {
        let (start, origin) = self.start_and_origin_mm();
        crate::geometry::add(start, origin)
    }
}
