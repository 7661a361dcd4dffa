//! LinuxCNC's own G codes with a decimal, read under the `linuxcnc`
//! profile only (the mill's table `MillLinuxcnc`): the other profiles keep
//! refusing them as codes no Fanuc, Haas or YASNAC control has.

use super::WorkSystem;
use super::{
    Code, CodeTable, CutterCompensation, CuttingMode, GCode, LengthOffset, NonModal, WorkCode,
};

/// LinuxCNC's one-shot codes of stored values (behaviour 22.14): the G92
/// offset put aside and taken back, and the G28/G30 positions stored.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Stored {
    /// G92.2: the G92 offset off, its values kept in #5211–#5219.
    SuspendShift,
    /// G92.3: the G92 offset again, from #5211–#5219.
    RestoreShift,
    /// G28.1: the current machine position stored as the G28 position.
    StoreReference,
    /// G30.1: the current machine position stored as the G30 position.
    StoreOtherReference,
}

impl Stored {
    /// The G code.
    pub fn gcode(self) -> &'static str {
        match self {
            Stored::SuspendShift => "G92.2",
            Stored::RestoreShift => "G92.3",
            Stored::StoreReference => "G28.1",
            Stored::StoreOtherReference => "G30.1",
        }
    }
}

/// The LinuxCNC code `g` (with a decimal) is under `table`, or None for
/// the Fanuc family's reading. LinuxCNC 2.9 documentation, "G41.1, G42.1",
/// "G43.1", "G43.2", "G61.1", "G54-G59.3", "G92.1, G92.2", "G92.3", "G28, G28.1",
/// "G30, G30.1".
pub(super) fn decimal(table: CodeTable, g: GCode) -> Option<Code> {
    use Code as C;
    if table != CodeTable::MillLinuxcnc {
        return None;
    }
    Some(match (g.major, g.minor) {
        (41, 1) => C::CutterCompensation(CutterCompensation::Left),
        (42, 1) => C::CutterCompensation(CutterCompensation::Right),
        (43, 1) => C::Length(LengthOffset::Dynamic),
        (43, 2) => C::Length(LengthOffset::AddTool),
        (61, 1) => C::CuttingMode(CuttingMode::ExactStopLinuxcnc),
        (59, 1) => C::Work(WorkCode::Standard(WorkSystem::G59_1)),
        (59, 2) => C::Work(WorkCode::Standard(WorkSystem::G59_2)),
        (59, 3) => C::Work(WorkCode::Standard(WorkSystem::G59_3)),
        (92, 2) => C::NonModal(NonModal::Stored(Stored::SuspendShift)),
        (92, 3) => C::NonModal(NonModal::Stored(Stored::RestoreShift)),
        (28, 1) => C::NonModal(NonModal::Stored(Stored::StoreReference)),
        (30, 1) => C::NonModal(NonModal::Stored(Stored::StoreOtherReference)),
        _ => return None,
    })
}
