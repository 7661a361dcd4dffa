//! Where the parser stands between two blocks ([`Resume`]): a run's
//! checkpoint keeps it, and a run made again after an edit goes on from it.

use super::Tape;
use super::program::Programs;
use crate::setup::Units;

/// Where the parser stands between two blocks: enough to go on from there
/// (a run's checkpoint; the diagnostics so far are not part of it).
#[derive(Clone, Copy, Debug)]
pub struct Resume {
    pub(super) pos: usize,
    pub(super) line: u32,
    pub(super) units: Units,
    pub(super) in_cycle: bool,
    pub(super) tape: Tape,
    pub(super) warned_integer: bool,
    pub(super) programs: Programs,
}

impl Resume {
    /// Byte offset of the next unread character.
    pub fn offset(&self) -> usize {
        self.pos
    }

    /// The line of the next unread character (1-based).
    pub fn line(&self) -> u32 {
        self.line
    }

    /// True when a parser at `other` reads the same text the way one here
    /// does: the same G20/G21 and canned-cycle context, tape state and
    /// warnings given (the place in the text aside).
    pub fn same_course(&self, other: &Resume) -> bool {
        (
            self.units,
            self.in_cycle,
            self.tape,
            self.warned_integer,
            self.programs,
        ) == (
            other.units,
            other.in_cycle,
            other.tape,
            other.warned_integer,
            other.programs,
        )
    }

    /// The same state `bytes` further on and `lines` lines further down
    /// (the place of this point in a text edited before it).
    pub fn shifted(self, bytes: i64, lines: i64) -> Resume {
        Resume {
            pos: shift(self.pos as i64, bytes) as usize,
            line: shift(i64::from(self.line), lines) as u32,
            ..self
        }
    }
}

/// `at + by`, never below 0 (places after an edit are past its start).
pub(crate) fn shift(at: i64, by: i64) -> i64 {
    (at + by).max(0)
}

impl Resume {
    /// The start of the program whose header is at byte `pos` on `line`
    /// (a subprogram called by number, behaviour 19.1), read in the G20/G21
    /// and canned-cycle context of `context`, the caller's place: the
    /// modal state goes on into the subprogram.
    pub fn program_start(pos: usize, line: u32, context: &Resume) -> Resume {
        Resume {
            pos,
            line,
            units: context.units,
            in_cycle: context.in_cycle,
            tape: Tape::Before,
            warned_integer: context.warned_integer,
            programs: Programs::default(),
        }
    }

    /// This place, read in the G20/G21 and canned-cycle context of
    /// `context` (a jump or a return goes on with the modal state the run
    /// has, not the one the text had there: behaviour 19.2).
    pub fn in_context(self, context: &Resume) -> Resume {
        Resume {
            units: context.units,
            in_cycle: context.in_cycle,
            ..self
        }
    }

    /// The G20/G21 the parser reads numbers in here.
    pub fn units(&self) -> Units {
        self.units
    }
}
