//! The variables a program touched (behaviour 21.12): which it read or
//! set, and the line that last set each, for the page's Variables panel
//! and the CLI's per-block report. Kept with the machine, so a checkpoint
//! holds it and a block's report made again from one is the whole run's;
//! boxed and absent until a program reads or sets a variable (a program
//! without `#` carries one empty pointer and never reaches this file).

use serde::Serialize;

use super::Machine;
use crate::diag::Span;
use crate::macros::{self, Kind};

/// A variable touched but never set by the program (only read, or set by
/// no line: a G65 argument's level is set at its call's line).
const READ: u32 = u32::MAX;

/// The touched variables: per local variable level the locals (0: not
/// touched, [`READ`], or the line that last set it), and the common and
/// system variables by number with the same mark.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct Watch {
    levels: Vec<[u32; 33]>,
    shared: Vec<(u32, u32)>,
}

impl Watch {
    fn mark(&mut self, level: u8, n: u32, set_at: Option<u32>) {
        let level = usize::from(level);
        let mark = set_at.unwrap_or(READ);
        if let Kind::Local = macros::kind(n) {
            if self.levels.len() <= level {
                self.levels.resize(level + 1, [0; 33]);
            }
            let slot = &mut self.levels[level][n as usize - 1];
            // A read does not forget the line that set it.
            if set_at.is_some() || *slot == 0 {
                *slot = mark;
            }
            return;
        }
        match self.shared.binary_search_by_key(&n, |&(k, _)| k) {
            Ok(i) if set_at.is_some() => self.shared[i].1 = mark,
            Ok(_) => {}
            Err(i) => self.shared.insert(i, (n, mark)),
        }
    }
}

/// One variable as the Variables panel shows it after a block.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Watched {
    /// Its number (`101` for `#101`).
    pub variable: u32,
    /// Its value after the block (None: vacant).
    pub value: Option<f64>,
    /// The line that last set it (None: the program only read it).
    pub line: Option<u32>,
}

/// The variables a program touched, after one block (behaviour 21.12).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct WatchView {
    /// The local variable level whose locals are shown (0: the main
    /// program's).
    pub level: u8,
    /// The locals of that level, then the common and system variables, by
    /// number.
    pub variables: Vec<Watched>,
}

impl Machine {
    /// Notes that the program read `#n` (at `span`) or, with `set`, set it.
    /// #0 is no variable to show; #3000 and #3006 are written only, as
    /// alarms and messages (behaviour 20.16): neither is watched.
    pub(crate) fn watch(&mut self, n: u32, span: Span, set: bool) {
        if n == 0 || n == 3000 || n == 3006 {
            return;
        }
        let level = self.macro_level();
        let set_at = set.then_some(span.line);
        self.watch
            .get_or_insert_with(Default::default)
            .mark(level, n, set_at);
    }

    /// A macro call's level starts (behaviour 21.3): its locals are the
    /// arguments, set at the call's `line`. A repeat of L starts it again.
    pub(crate) fn watch_level(&mut self, args: &[crate::macros::Value; 33], line: u32) {
        let level = usize::from(self.macro_level());
        let w = self.watch.get_or_insert_with(Default::default);
        w.levels.resize(level + 1, [0; 33]);
        w.levels[level] = std::array::from_fn(|k| if args[k].is_vacant() { 0 } else { line });
    }

    /// M99 left a macro's level: its locals are forgotten, the caller's
    /// marks are as they were.
    pub(crate) fn watch_leave(&mut self) {
        let level = usize::from(self.macro_level());
        if let Some(w) = &mut self.watch {
            w.levels.truncate(level + 1);
        }
    }

    /// The variables touched, with their values now; None when the program
    /// touched none (or none of the level standing).
    #[inline]
    pub(crate) fn watched(&self) -> Option<Box<WatchView>> {
        match self.watch.as_deref() {
            Some(w) => self.watched_of(w),
            None => None,
        }
    }

    /// [`Machine::watched`] of a program that touched variables: out of
    /// line, so a run keeping block reports pays one test per block.
    #[cold]
    #[inline(never)]
    fn watched_of(&self, w: &Watch) -> Option<Box<WatchView>> {
        let level = self.macro_level();
        let locals = w.levels.get(usize::from(level)).into_iter().flat_map(|l| {
            l.iter()
                .enumerate()
                .filter(|&(_, &m)| m != 0)
                .map(|(k, &m)| (k as u32 + 1, m))
        });
        let variables = locals
            .chain(w.shared.iter().copied())
            .map(|(n, m)| Watched {
                variable: n,
                value: match macros::kind(n) {
                    Kind::System => self.read_system(n, Span::default()).ok().flatten(),
                    _ => self.variables.get(n).and_then(|v| v.get()),
                },
                line: (m != READ).then_some(m),
            })
            .collect::<Vec<_>>();
        // A macro's level may have touched variables its caller did not.
        (!variables.is_empty()).then(|| Box::new(WatchView { level, variables }))
    }
}
