//! The words the parser reads but no rule of the machine acts on yet
//! (behaviour 1.7): an error at the word, never a word passed over.

use super::Machine;
use crate::diag::Diagnostic;
use crate::setup::MachineKind;
use crate::syntax::codes::NonModal;
use crate::syntax::{Address, Block};

impl Machine {
    /// Refuses the words the parser reads but no rule of the machine acts on
    /// yet (behaviour 1.7): rotary axes A/B/C, E, and the chamfer and corner
    /// words `,C`/`,R` — an error at the word, never a word passed over.
    /// A code that models one of them takes it out of this list for the
    /// blocks it handles.
    pub(super) fn refuse_unmodelled(&self, b: &Block) -> Result<(), Diagnostic> {
        const UNMODELLED: [Address; 6] = [
            Address::A,
            Address::B,
            Address::C,
            Address::E,
            Address::CommaC,
            Address::CommaR,
        ];
        if !b.holds_any(&UNMODELLED) {
            return Ok(());
        }
        let lathe = self.setup.machine == MachineKind::Lathe;
        // The mill cuts the corner words (`corner.rs`) and reports its
        // rotary axes, not drawn (behaviour 13.14); section 14 models G187's
        // E and the rotary word of G07.1 (`models_word`); G76's A is its tool
        // angle (behaviour 15.12).
        let g76 = b.codes().non_modal()
            == Some(NonModal::Repetitive(
                crate::syntax::codes::Repetitive::Threading,
            ));
        // The lathe's `,C`/`,R` are read where `corner.rs` runs the block
        // (behaviour 2.35), not in a cycle's contour or its compensation.
        let modelled = |a: Address| {
            (g76 && a == Address::A)
                || (matches!(a, Address::CommaC | Address::CommaR)
                    && (!lathe || self.corner_words_read))
                || (!lathe && matches!(a, Address::A | Address::B | Address::C))
        };
        let Some(w) = b.words.iter().find(|w| {
            UNMODELLED.contains(&w.address)
                && !modelled(w.address)
                && !self.models_word(b, w.address)
        }) else {
            return Ok(());
        };
        let letter = w.address.letter();
        let why = match w.address {
            Address::C if lathe => "the C axis and the chamfer word C are not modelled yet",
            Address::A | Address::B | Address::C => "rotary axes are not modelled yet",
            Address::E => "thread lead is not modelled yet (Haas G187 and G47 read E)",
            _ => {
                "a chamfer or corner rounding here (a G70–G73 contour, a cycle, tool nose radius compensation) is not modelled yet: the lathe cuts it between two feed moves (behaviour 2.35)"
            }
        };
        Err(self.error("unsupported-word", w.span, format!("{letter}: {why}")))
    }

    /// True for a word of [`Machine::refuse_unmodelled`]'s list that this
    /// block models: G187's E (behaviour 14.6), the rotary word of G07.1 and
    /// of the blocks in its mode (behaviour 14.10).
    pub(super) fn models_word(&self, b: &Block, a: Address) -> bool {
        use crate::syntax::codes::NonModal;
        let code = b.codes().non_modal();
        match a {
            Address::E => matches!(code, Some(NonModal::Smoothness | NonModal::Engraving)),
            // The lathe G10's C adds to the nose radius (behaviour 17.6).
            Address::C
                if code == Some(NonModal::DataSetting)
                    && self.setup.machine == MachineKind::Lathe =>
            {
                true
            }
            Address::A | Address::B | Address::C => {
                let rotary: &[Address] = match self.setup.machine {
                    MachineKind::Mill => &[Address::A, Address::B, Address::C],
                    MachineKind::Lathe => &[Address::C],
                };
                (code == Some(NonModal::Cylindrical) && rotary.contains(&a))
                    || self.state.modal.cylinder.is_some_and(|(axis, _)| axis == a)
                    // The hypothetical axis of polar interpolation (behaviour 14.15).
                    || (self.in_polar_mode(b) && a == self.polar_axis())
            }
            _ => false,
        }
    }
}
