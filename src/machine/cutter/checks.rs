//! What cutter compensation refuses before a block runs (behaviour 16.10,
//! 16.14, 16.16–16.19): a plane change, G45–G48, chamfers, G39 out of offset
//! mode, I/J/K it does not read, a canned cycle with the vector on.

use crate::diag::Diagnostic;
use crate::machine::Machine;
use crate::machine::corner::CORNER_WORDS;
use crate::offsets::cutter::Phase;
use crate::syntax::codes::{CannedCycle, CutterCompensation, NonModal};
use crate::syntax::{Address, Block};

impl Machine {
    /// The refusals of behaviour 16.16–16.19, before the block runs.
    pub(super) fn cutter_checks(&self, b: &Block) -> Result<(), Diagnostic> {
        let now = self.state.cutter;
        // G41/G42 is the mode, or a vector is on (a cancel block's own
        // role, `cancelling`, has none left).
        let vector_on = matches!(now.phase, Phase::StartUp | Phase::Offset);
        let engaged = now.mode != CutterCompensation::Cancel || vector_on;
        let codes = b.codes();
        if self.setup.settings.control == crate::setup::Control::Linuxcnc
            && let Some(c) = codes.cutter()
            && c != CutterCompensation::Cancel
        {
            self.linuxcnc_cutter_start(b, now.mode)?;
        }
        // LinuxCNC turns compensation off at G40 itself: the plane may
        // change before the move that leaves the offset path (rs274 -g,
        // behaviour 22.9).
        let linuxcnc_off = now.mode == CutterCompensation::Cancel
            && self.setup.settings.control == crate::setup::Control::Linuxcnc;
        if engaged
            && !linuxcnc_off
            && let Some(plane) = codes.plane()
            && plane != self.state.modal.plane
        {
            return Err(self.error(
                "cutter-plane",
                b.code_span(crate::syntax::codes::Group::Plane),
                format!(
                    "{}: the plane cannot change while {} is the mode or its vector is on: cancel with G40 first (Fanuc alarm PS0037)",
                    plane.gcode(),
                    now.mode.gcode()
                ),
            ));
        }
        if engaged && let Some(NonModal::PositionOffset(p)) = codes.non_modal() {
            return Err(self.error(
                "cutter-position-offset",
                b.code_span(crate::syntax::codes::Group::NonModal),
                format!(
                    "{}: tool position offset cannot be used in cutter compensation ({}): cancel with G40 first (Fanuc alarm PS0042)",
                    p.gcode(),
                    now.mode.gcode()
                ),
            ));
        }
        // In offset mode the corner is cut and compensated (behaviour
        // 16.19); not where the mode starts, ends or changes side.
        if b.holds_any(&CORNER_WORDS) && (!engaged || codes.cutter().is_some_and(|c| c != now.mode))
        {
            return Err(self.corner_in_cancel(b));
        }
        if codes.non_modal() == Some(NonModal::CornerArc) {
            let on = now.mode != CutterCompensation::Cancel
                && codes.cutter().is_none_or(|c| c == now.mode)
                && matches!(now.phase, Phase::StartUp | Phase::Offset);
            if !on {
                return Err(self.error(
                    "cutter-g39",
                    b.code_span(crate::syntax::codes::Group::NonModal),
                    "G39 (corner arc) works in offset mode only: after a G41/G42 start-up, before G40",
                ));
            }
            if let Some(w) = [Address::X, Address::Y, Address::Z]
                .iter()
                .find_map(|a| b.get(*a))
            {
                return Err(self.error(
                    "cutter-g39",
                    w.span,
                    format!(
                        "{}: a G39 block makes the corner arc only and takes no move (write the move in the next block)",
                        w.address.letter()
                    ),
                ));
            }
        }
        let arc_mode = codes.motion().unwrap_or(self.state.modal.motion).is_arc();
        let direction_block = codes.non_modal() == Some(NonModal::CornerArc)
            || (!arc_mode
                && matches!(
                    codes.cutter(),
                    Some(CutterCompensation::Left | CutterCompensation::Right)
                ));
        if direction_block {
            let (_, _, normal) = self.state.modal.plane.axes();
            let word = [Address::I, Address::J, Address::K][normal];
            if let Some(w) = b.get(word) {
                return Err(self.error(
                    "cutter-ijk",
                    w.span,
                    format!(
                        "{}: the direction of the vector lies in the {} plane, which {} is not a word of",
                        w.address.letter(),
                        self.state.modal.plane.gcode(),
                        w.address.letter()
                    ),
                ));
            }
        }
        if let Some(code) = codes.cutter()
            && b.holds_any(&[Address::I, Address::J, Address::K])
        {
            let arc = codes.motion().unwrap_or(self.state.modal.motion).is_arc();
            // The IJ-type vector of a G41/G42 block, with a move or without,
            // and the direction of a G40 block with a move are modelled
            // (behaviour 16.14, 18.4); a G40 without a move is not.
            if !arc && code == CutterCompensation::Cancel && !self.names_plane_axis(b) {
                let w = b
                    .get(Address::I)
                    .or_else(|| b.get(Address::J))
                    .or_else(|| b.get(Address::K));
                return Err(self.error(
                    "cutter-ijk",
                    w.map_or(b.span, |w| w.span),
                    format!(
                        "{}: I/J/K in a G40 block without a move (the direction of the corner vector) are not modelled yet",
                        w.map_or("I", |w| w.address.letter()),
                    ),
                ));
            }
        }
        if matches!(codes.cycle(), Some(CannedCycle::Cycle(_))) && vector_on {
            return Err(self.error(
                "cutter-in-cycle",
                b.code_span(crate::syntax::codes::Group::Cycle),
                format!(
                    "a canned cycle cannot start while the compensation's vector is on ({}): cancel with G40 first (Fanuc ignores cutter compensation in canned cycles)",
                    now.mode.gcode()
                ),
            ));
        }
        Ok(())
    }

    /// `,C`/`,R` in a block that starts, cancels (G40 or D00) or changes
    /// the side of the compensation (behaviour 16.19, Fanuc PS0039).
    #[cold]
    pub(super) fn corner_in_cancel(&self, b: &Block) -> Diagnostic {
        let w = b.get(Address::CommaC).or_else(|| b.get(Address::CommaR));
        self.error(
            "cutter-corner-words",
            w.map_or(b.span, |w| w.span),
            format!(
                "{}: a chamfer or corner rounding cannot be made in a block that starts, cancels or changes cutter compensation (Fanuc alarm PS0039)",
                w.map_or(",C", |w| w.address.letter())
            ),
        )
    }
}

impl Machine {
    /// LinuxCNC's refusals of a G41/G42 (`rs274 -g`, behaviour 22.4): while
    /// compensation is on ("Cannot turn cutter radius comp on when on"), and
    /// in G19 ("Cutter radius compensation allowed only in XY, XZ planes").
    #[cold]
    #[inline(never)]
    fn linuxcnc_cutter_start(&self, b: &Block, mode: CutterCompensation) -> Result<(), Diagnostic> {
        let span = b.code_span(crate::syntax::codes::Group::Cutter);
        if mode != CutterCompensation::Cancel {
            return Err(self.error(
                "cutter-already-on",
                span,
                format!(
                    "{} while {} is on: LinuxCNC refuses it (\"Cannot turn cutter radius comp on when on\"); cancel with G40 first",
                    b.codes().cutter().map_or("G41", |c| c.gcode()),
                    mode.gcode()
                ),
            ));
        }
        let plane = b.codes().plane().unwrap_or(self.state.modal.plane);
        if plane == crate::syntax::codes::Plane::YZ {
            return Err(self.error(
                "cutter-plane",
                span,
                "G41/G42 in G19: LinuxCNC compensates in G17 and G18 only (\"Cutter radius compensation allowed only in XY, XZ planes\")",
            ));
        }
        Ok(())
    }
}
