//! LinuxCNC's motion mode G80 (behaviour 22.18; LinuxCNC 2.9 "G-code
//! reference", G80, and rs274's `enhance_block`): in RS274/NGC G80 is a code
//! of the motion group, so it ends G0–G3 as well as a canned cycle, and the
//! interpreter starts in it. An axis word then needs a code that uses it —
//! a motion code on its line, or G10, G28, G30, G52, G92, G43.1 or G43.2
//! (whose axis words are offsets) — else rs274
//! refuses the block ("Cannot use axis values without a G code that uses
//! them"), and axis words on G80's own line are refused ("Cannot use axis
//! values with G80"). The Fanuc family keeps G0/G1 across G80 (its cycles
//! are a group of their own), so this is the LinuxCNC profile's rule only.

use crate::diag::Diagnostic;
use crate::machine::Machine;
use crate::syntax::codes::{CannedCycle, NonModal};
use crate::syntax::{Address, Block};

/// The words rs274 counts as axis values (polar `@` `^` become X and Y);
/// the six axes first, which the G4 block's motion reads too.
pub(super) const AXIS_WORDS: [Address; 8] = [
    Address::X,
    Address::Y,
    Address::Z,
    Address::A,
    Address::B,
    Address::C,
    Address::PolarDist,
    Address::PolarAngle,
];

impl Machine {
    /// Follows the LinuxCNC motion mode through the block's group 01 codes
    /// and refuses axis words no code uses.
    pub(super) fn linuxcnc_motion_mode(&mut self, b: &Block) -> Result<(), Diagnostic> {
        let c = b.codes();
        let covets = self.axes_are_offsets(b)
            || matches!(
                c.non_modal(),
                Some(
                    NonModal::DataSetting
                        | NonModal::ReferenceReturn
                        | NonModal::OtherReference
                        | NonModal::LocalCoordinates
                        | NonModal::SetCoordinates
                )
            );
        let axis = || {
            b.words
                .iter()
                .find(|w| AXIS_WORDS.contains(&w.address))
                .filter(|_| !covets)
        };
        match (c.motion(), c.cycle()) {
            (Some(_), _) | (_, Some(CannedCycle::Cycle(_))) => self.state.modal.motion_none = false,
            (None, Some(CannedCycle::Cancel)) => {
                if let Some(w) = axis() {
                    return Err(self.error(
                        "axis-with-g80",
                        w.span,
                        format!(
                            "{}: G80 ends the motion mode, and LinuxCNC refuses an axis word on its line (rs274: \"Cannot use axis values with G80\"); move on a line of its own with G0 or G1",
                            w.address.letter()
                        ),
                    ));
                }
                self.state.modal.motion_none = true;
            }
            (None, None) if self.state.modal.motion_none => {
                if let Some(w) = axis() {
                    return Err(self.error(
                        "axis-without-motion",
                        w.span,
                        format!(
                            "{}: no motion mode is in effect (LinuxCNC starts in G80, and G80 ends G0–G3 too), so no code uses this axis word (rs274: \"Cannot use axis values without a G code that uses them\"); give G0 or G1 on its line",
                            w.address.letter()
                        ),
                    ));
                }
            }
            (None, None) => {}
        }
        self.update_special();
        Ok(())
    }
}
