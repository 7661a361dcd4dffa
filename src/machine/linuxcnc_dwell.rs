//! LinuxCNC's G4 takes its time from P only (behaviour 22.13; LinuxCNC 2.9
//! "G-code reference", G4, and what `rs274` does): the axis words of a G4
//! block are the motion mode's, as in any block with a non-modal code that
//! uses no axes, so the block dwells and then moves (`G4 P1 X5` in G0 waits
//! a second and goes to X5). A Fanuc-family control reads G4 X as seconds
//! (behaviour 2.9), so this is the LinuxCNC profile's reading only; and a
//! LinuxCNC G4 needs its P.

use super::linuxcnc_motion::AXIS_WORDS;
use crate::diag::Diagnostic;
use crate::machine::Machine;
use crate::machine::program::ProgramText;
use crate::machine::{Ahead, Out};
use crate::syntax::codes::NonModal;
use crate::syntax::{Address, Block};

/// Besides the six axes, the words the motion of a G4 block reads (arc
/// centre and radius, a cycle's repeat and peck; P stays the dwell's).
const CENTRE_AND_REPEAT: [Address; 5] =
    [Address::I, Address::J, Address::K, Address::R, Address::L];

/// `a` belongs to the motion of a G4 block.
fn motion_word(a: Address) -> bool {
    AXIS_WORDS[..6].contains(&a) || CENTRE_AND_REPEAT.contains(&a)
}

impl Machine {
    /// True for a LinuxCNC G4 block with an axis word; a LinuxCNC G4
    /// without P is an error (rs274: "Dwell time missing with g4").
    pub(super) fn dwell_moves(&self, b: &Block) -> Result<bool, Diagnostic> {
        if b.codes().non_modal() != Some(NonModal::Dwell)
            || self.setup.settings.control != crate::setup::Control::Linuxcnc
        {
            return Ok(false);
        }
        if !b.has(Address::P) {
            return Err(self.error(
                "dwell-words",
                b.code_span(crate::syntax::codes::Group::NonModal),
                "LinuxCNC's G4 takes its time in seconds from P, and this G4 has none (rs274: \"Dwell time missing with g4\")",
            ));
        }
        Ok(b.holds_any(&AXIS_WORDS[..6]))
    }

    /// The G4 block without its motion words (the dwell, with the block's
    /// codes and other words, first, as rs274 dwells before it moves), then
    /// a block of the motion words in the motion mode.
    pub(super) fn dwell_then_move(
        &mut self,
        b: &Block,
        out: &mut Out,
        ahead: &mut dyn Ahead,
        program: &mut dyn ProgramText,
    ) -> Result<(), Diagnostic> {
        let dwell = b.without(|w| motion_word(w.address));
        self.mill_block(&dwell, out, ahead, program)?;
        // rs274 gives P to an arc (its turns) and to a cycle (G82's dwell)
        // too: the motion block reads it by its own rules.
        let modal = self.state.modal;
        let p_too = modal.cycle.is_some() || modal.motion.is_arc();
        let moves = |a: Address| motion_word(a) || (p_too && a == Address::P);
        let mut motion = b.without(|_| true);
        motion.clear();
        motion.speaks = false;
        for w in b.words.iter().filter(|w| moves(w.address)) {
            motion.push(*w);
        }
        self.mill_block(&motion, out, ahead, program)
    }
}
