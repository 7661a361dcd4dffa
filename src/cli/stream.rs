//! `run` written as it goes (behaviour 8.15): the run hands each block's
//! report and each event to [`Streamer`] as it is made and keeps none, so a
//! run of millions of blocks (a long program, a macro loop that never ends
//! until the block limit) needs memory for one block, not for all of them.
//! The table's rows go straight to the output; the JSON's blocks too, its
//! moves and events to unnamed temporary files that are copied after them
//! (the object's members follow one another, the run makes them together).

use std::fs::File;
use std::io::{self, BufWriter, Seek, Write};

use offsetlab::report::{BlockReport, Event};
use offsetlab::view::{BlockViewer, move_view, summary};
use offsetlab::{MachineKind, Observer, Run};

use super::table;

/// What `run` writes.
pub enum Output {
    /// One row per block, then the diagnostics.
    Table,
    /// The JSON object of [`offsetlab::view::RunView`], its members written
    /// as the run makes them.
    Json { moves: Spill, events: Spill },
}

/// A JSON array's elements written to a temporary file while the run goes.
pub struct Spill {
    file: BufWriter<File>,
    count: u64,
}

impl Spill {
    pub fn new() -> io::Result<Spill> {
        Ok(Spill {
            file: BufWriter::new(tempfile::tempfile()?),
            count: 0,
        })
    }

    fn push(&mut self, value: &impl serde::Serialize) -> io::Result<()> {
        if self.count > 0 {
            self.file.write_all(b",")?;
        }
        self.count += 1;
        serde_json::to_writer(&mut self.file, value).map_err(io::Error::from)
    }

    /// The elements, copied to `out` as `[…]`.
    fn copy_to(self, out: &mut impl Write) -> io::Result<()> {
        let mut file = self.file.into_inner().map_err(|e| e.into_error())?;
        file.rewind()?;
        out.write_all(b"[")?;
        io::copy(&mut file, out)?;
        out.write_all(b"]")
    }
}

/// The observer of `run`: writes every block and event as the run makes
/// it. A write error stops the writing (the run still ends, within its
/// block limit) and is given back by [`Streamer::finish`].
pub struct Streamer<'a, W: Write> {
    out: &'a mut W,
    viewer: BlockViewer<'a>,
    output: Output,
    machine: MachineKind,
    /// A block has been written (the JSON's blocks are parted by commas).
    wrote_block: bool,
    /// The last G10 of each register and field, for the summary's
    /// `set_by_program` (a list as long as the registers set, not as the
    /// blocks run).
    data_sets: Vec<Event>,
    error: Option<io::Error>,
}

impl<'a, W: Write> Streamer<'a, W> {
    pub fn new(
        out: &'a mut W,
        viewer: BlockViewer<'a>,
        output: Output,
        machine: MachineKind,
    ) -> Self {
        let mut s = Streamer {
            out,
            viewer,
            output,
            machine,
            wrote_block: false,
            data_sets: Vec::new(),
            error: None,
        };
        s.attempt(|s| match &s.output {
            Output::Table => table::header(s.out, s.machine),
            Output::Json { .. } => s.out.write_all(b"{\"blocks\":["),
        });
        s
    }

    fn attempt(&mut self, f: impl FnOnce(&mut Self) -> io::Result<()>) {
        if self.error.is_none()
            && let Err(e) = f(self)
        {
            self.error = Some(e);
        }
    }

    /// The rest of the output, after the run: the moves and events, the
    /// diagnostics and the summary (JSON), or the diagnostics (table).
    pub fn finish(mut self, run: &mut Run, text: &str) -> io::Result<()> {
        if let Some(e) = self.error.take() {
            return Err(e);
        }
        run.events = std::mem::take(&mut self.data_sets);
        match self.output {
            Output::Table => table::diagnostics(self.out, run),
            Output::Json { moves, events } => {
                let out = &mut *self.out;
                out.write_all(b"],\"moves\":")?;
                moves.copy_to(out)?;
                out.write_all(b",\"events\":")?;
                events.copy_to(out)?;
                out.write_all(b",\"diagnostics\":")?;
                serde_json::to_writer(&mut *out, &run.diagnostics)?;
                out.write_all(b",\"summary\":")?;
                serde_json::to_writer(&mut *out, &summary(run).with_hint(text))?;
                out.write_all(b"}\n")
            }
        }
    }
}

impl<W: Write> Observer for Streamer<'_, W> {
    fn takes_reports(&self) -> bool {
        true
    }

    fn on_block(&mut self, b: &BlockReport) {
        self.attempt(|s| {
            let view = s.viewer.view(b);
            let first = !std::mem::replace(&mut s.wrote_block, true);
            match &s.output {
                Output::Table => table::row(s.out, b, &view, s.machine),
                Output::Json { .. } => {
                    if !first {
                        s.out.write_all(b",")?;
                    }
                    serde_json::to_writer(&mut *s.out, &view).map_err(io::Error::from)
                }
            }
        });
    }

    fn on_move(&mut self, m: &offsetlab::machine::Move) {
        let machine = self.machine;
        self.attempt(|s| match &mut s.output {
            Output::Json { moves, .. } => moves.push(&move_view(m, machine)),
            Output::Table => Ok(()),
        });
    }

    fn on_event(&mut self, e: &Event) {
        if let offsetlab::machine::EventKind::DataSet(set) = &e.kind {
            let same = |k: &Event| match &k.kind {
                offsetlab::machine::EventKind::DataSet(s) => s.same_entry(set),
                _ => false,
            };
            match self.data_sets.iter_mut().find(|k| same(k)) {
                Some(k) => *k = e.clone(),
                None => self.data_sets.push(e.clone()),
            }
        }
        self.attempt(|s| match &mut s.output {
            Output::Json { events, .. } => events.push(e),
            Output::Table => Ok(()),
        });
    }
}
