//! What a run tells as it goes ([`Observer`]): its moves, its progress
//! through the text, and — for an observer that takes them — every block's
//! report and every event, which the run then does not keep (behaviour
//! 8.15).

use crate::report::{BlockReport, Event};

/// Watches a run as it goes.
pub trait Observer {
    /// Every move, as it is made (whether or not the run keeps it): the
    /// page builds its toolpath this way without keeping the moves.
    fn on_move(&mut self, _m: &crate::machine::Move) {}

    /// After every [`PROGRESS_EVERY`] bytes of program: how many bytes have
    /// been read (the page shows a large program's progress).
    fn on_progress(&mut self, _read: usize) {}

    /// A run made again ([`crate::rerun_observed`]) starts after the earlier run's
    /// first `prefix_moves` moves, before any other call.
    fn on_resume(&mut self, _prefix_moves: usize) {}

    /// True when the observer takes the run's reports as they are made
    /// ([`Observer::on_block`], [`Observer::on_event`]) instead of the run
    /// keeping them: the run's `blocks` then holds only the last report
    /// and its `events` none, so a run that reports every block needs
    /// memory for one block, not for every block it executes (`run` of the
    /// CLI writes its table and JSON as it goes, behaviour 8.15).
    fn takes_reports(&self) -> bool {
        false
    }

    /// Every block's report as it is made, when [`Observer::takes_reports`]
    /// and the run makes reports ([`RunOptions::keep_blocks`]).
    fn on_block(&mut self, _b: &BlockReport) {}

    /// Every event as it happens, when [`Observer::takes_reports`].
    fn on_event(&mut self, _e: &Event) {}
}

/// Nothing to watch.
impl Observer for () {}

/// A closure watches the moves.
impl<F: FnMut(&crate::machine::Move)> Observer for F {
    fn on_move(&mut self, m: &crate::machine::Move) {
        self(m)
    }
}

/// Bytes of program between two [`Observer::on_progress`] calls.
pub const PROGRESS_EVERY: usize = 1 << 20;
