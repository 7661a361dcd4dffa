//! M codes with a meaning, resolved by the parser for the machine, and
//! their groups: two codes of one group exclude each other in a block.
//! Codes without a meaning to offsetlab are carried through as
//! [`MCode::Other`], each its own group.

use crate::setup::MachineKind;

/// An M code.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MCode {
    /// M00: program stop.
    ProgramStop,
    /// M01: optional stop.
    OptionalStop,
    /// M02: end of program.
    ProgramEnd,
    /// M30: end of program and rewind.
    ProgramEndRewind,
    /// M03: spindle on, clockwise.
    SpindleCw,
    /// M04: spindle on, counter-clockwise.
    SpindleCcw,
    /// M05: spindle stop.
    SpindleStop,
    /// M19: spindle orientation.
    SpindleOrient,
    /// M06 (mill): tool change to the tool selected by T.
    ToolChange,
    /// M07: mist coolant on.
    CoolantMist,
    /// M08: flood coolant on.
    CoolantFlood,
    /// M09: coolant off.
    CoolantOff,
    /// M97 (Haas): call of a subprogram in the same program, by its N.
    LocalSubprogramCall,
    /// M98: subprogram call.
    SubprogramCall,
    /// M99: end of subprogram, return to the caller.
    SubprogramReturn,
    /// M198 (Fanuc): call of a subprogram kept outside the program memory
    /// (memory card, data server).
    ExternalSubprogramCall,
    /// Any other M code, carried through.
    Other(u32),
}

impl MCode {
    /// The code this machine gives M`n` (the lathe's turret indexes with
    /// the T code, so its M06 is no tool change).
    #[inline]
    pub fn of(machine: MachineKind, n: u32) -> MCode {
        match n {
            0 => MCode::ProgramStop,
            1 => MCode::OptionalStop,
            2 => MCode::ProgramEnd,
            3 => MCode::SpindleCw,
            4 => MCode::SpindleCcw,
            5 => MCode::SpindleStop,
            6 if machine == MachineKind::Mill => MCode::ToolChange,
            7 => MCode::CoolantMist,
            8 => MCode::CoolantFlood,
            9 => MCode::CoolantOff,
            19 => MCode::SpindleOrient,
            30 => MCode::ProgramEndRewind,
            97 => MCode::LocalSubprogramCall,
            98 => MCode::SubprogramCall,
            99 => MCode::SubprogramReturn,
            198 => MCode::ExternalSubprogramCall,
            other => MCode::Other(other),
        }
    }

    /// The number written after M.
    pub fn number(self) -> u32 {
        match self {
            MCode::ProgramStop => 0,
            MCode::OptionalStop => 1,
            MCode::ProgramEnd => 2,
            MCode::SpindleCw => 3,
            MCode::SpindleCcw => 4,
            MCode::SpindleStop => 5,
            MCode::ToolChange => 6,
            MCode::CoolantMist => 7,
            MCode::CoolantFlood => 8,
            MCode::CoolantOff => 9,
            MCode::SpindleOrient => 19,
            MCode::ProgramEndRewind => 30,
            MCode::LocalSubprogramCall => 97,
            MCode::SubprogramCall => 98,
            MCode::SubprogramReturn => 99,
            MCode::ExternalSubprogramCall => 198,
            MCode::Other(n) => n,
        }
    }

    /// Its group: 1 stops and ends, 2 spindle, 3 coolant, 4 tool change;
    /// every other code is its own group (100 + its number).
    pub fn group(self) -> u32 {
        match self {
            MCode::ProgramStop
            | MCode::OptionalStop
            | MCode::ProgramEnd
            | MCode::ProgramEndRewind => 1,
            MCode::SpindleCw | MCode::SpindleCcw | MCode::SpindleStop | MCode::SpindleOrient => 2,
            MCode::CoolantMist | MCode::CoolantFlood | MCode::CoolantOff => 3,
            MCode::ToolChange => 4,
            MCode::LocalSubprogramCall
            | MCode::SubprogramCall
            | MCode::SubprogramReturn
            | MCode::ExternalSubprogramCall
            | MCode::Other(_) => 100 + self.number(),
        }
    }

    /// M02 or M30: the program ends after this block.
    pub fn ends_program(self) -> bool {
        match self {
            MCode::ProgramEnd | MCode::ProgramEndRewind => true,
            MCode::ProgramStop
            | MCode::OptionalStop
            | MCode::SpindleCw
            | MCode::SpindleCcw
            | MCode::SpindleStop
            | MCode::SpindleOrient
            | MCode::ToolChange
            | MCode::CoolantMist
            | MCode::CoolantFlood
            | MCode::CoolantOff
            | MCode::LocalSubprogramCall
            | MCode::SubprogramCall
            | MCode::SubprogramReturn
            | MCode::ExternalSubprogramCall
            | MCode::Other(_) => false,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_m_code_writes_back_its_number() {
        for machine in [MachineKind::Mill, MachineKind::Lathe] {
            for n in 0..=200 {
                assert_eq!(MCode::of(machine, n).number(), n, "{machine:?} M{n}");
            }
        }
    }

    #[test]
    fn m06_is_a_tool_change_on_the_mill_only() {
        assert_eq!(MCode::of(MachineKind::Mill, 6), MCode::ToolChange);
        assert_eq!(MCode::of(MachineKind::Lathe, 6), MCode::Other(6));
    }

    #[test]
    fn m_groups_as_the_manuals_group_them() {
        let group = |n| MCode::of(MachineKind::Mill, n).group();
        assert_eq!([0, 1, 2, 30].map(group), [1; 4]);
        assert_eq!([3, 4, 5, 19].map(group), [2; 4]);
        assert_eq!([7, 8, 9].map(group), [3; 3]);
        assert_eq!(group(6), 4);
        assert_eq!([97, 98, 99, 123].map(group), [197, 198, 199, 223]);
    }
}
