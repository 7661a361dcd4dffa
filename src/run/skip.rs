//! Continue past errors (behaviour 2.24, setting 7.48): a block the run
//! cannot run — a parse error in it, an unsupported code, an alarm of the
//! machine, a call that cannot be made — is reported and passed over, the
//! machine taken back to where it stood before the block, and the run goes
//! on. What ends the run whatever the setting: the limits (a runaway
//! program must still stop, behaviour 8) and a subprogram that ends without
//! M99 (there is no block to go on with, 19.5).

use super::{Runner, Step};
use crate::diag::Diagnostic;
use crate::machine::Machine;

/// True for an error the run may go on past; `None` is the parser's error
/// in the block (its diagnostics are already reported).
fn can_skip(d: Option<&Diagnostic>) -> bool {
    d.is_none_or(|d| !(d.code.starts_with("too-many-") || d.code == "missing-m99"))
}

impl Runner<'_> {
    /// [`Runner::step`] with the setting on: the block runs on the machine
    /// kept from before it, which is put back if the block cannot run.
    #[inline(never)]
    pub(super) fn step_keeping_going(&mut self) -> Option<Step> {
        let before = self.machine.clone();
        let step = self.run_block();
        self.skip_or_stop(step, before)
    }

    /// The step of a block run with the setting on: a stop at an error the
    /// run may go on past becomes a skip, with `before`, the machine as it
    /// stood before the block, put back.
    fn skip_or_stop(&mut self, step: Option<Step>, before: Machine) -> Option<Step> {
        let Some(Step::Stopped(d)) = step else {
            return step;
        };
        if !can_skip(d.as_ref()) {
            return Some(Step::Stopped(d));
        }
        self.machine = before;
        self.stopped = false;
        // What a block that failed read ahead was read for its index,
        // which the next block takes.
        self.ahead.forget();
        Some(Step::Skipped(d))
    }

    /// Reports a skipped block: its error (the parser has reported its
    /// own) and a warning that it was passed over, under the diagnostics'
    /// cap with the first parser's, as the machine's warnings are.
    pub(super) fn report_skipped(&mut self, d: Option<Diagnostic>) {
        let note = Diagnostic::warning(
            "block-skipped",
            self.block.span,
            "this block did not run: the run continues past errors (setting continue_past_errors) with the state before it",
        );
        let parser = match self.calls.as_deref_mut().and_then(|c| c.main_parser()) {
            Some(main) => main,
            None => &mut self.parser,
        };
        parser.report_all(d.into_iter().chain([note]));
    }
}
