//! The setup's library of programs (behaviour 19.10–19.12): programs kept
//! by number with the document, called as the programs of the file are.
//!
//! The run reads one text (its parsers and checkpoints name places in it
//! by byte), so a run with a library reads the main text with the library
//! after it: every library program opens with its header (9.10), and a
//! program after the first is a program to call, never one that runs on
//! after the first (1.21). The main text comes first, so a number both
//! hold is the main text's program (19.1: the first of a number). What
//! the run reports is then put back into each text's own terms: a block
//! or diagnostic in a library program has its line and bytes within that
//! program's text, and its diagnostics name the program. A run without a
//! library never comes here (one test of an empty map).

use crate::diag::Span;
use crate::report::{BlockReport, End, Run};
use crate::setup::Setup;

/// The main text with the library after it, and where each program is.
pub(crate) struct Joined {
    /// The text the run reads.
    pub(crate) text: String,
    /// The setup without its library (the run's own).
    pub(crate) setup: Setup,
    /// The library, for the run's report.
    programs: std::collections::BTreeMap<u32, String>,
    /// Where the library starts (bytes).
    from: usize,
    /// The library's programs in order.
    parts: Vec<Part>,
}

/// One library program in the joined text.
struct Part {
    label: String,
    /// Its first byte.
    start: usize,
    /// Its first line.
    line: u32,
}

/// Line breaks as the parser counts them: `\r\n`, `\n`, a lone `\r`.
fn breaks(s: &str) -> u32 {
    let b = s.as_bytes();
    let mut n = 0;
    for (i, &c) in b.iter().enumerate() {
        if c == b'\n' || (c == b'\r' && b.get(i + 1) != Some(&b'\n')) {
            n += 1;
        }
    }
    n
}

/// Ends `text` with a line break (a `\r` becomes `\r\n`, so the next
/// text's first line starts a line of its own and no break merges).
fn end_line(text: &mut String) {
    if !text.is_empty() && !text.ends_with('\n') {
        text.push('\n');
    }
}

impl Joined {
    /// The joined text of `main` and the setup's library; None without a
    /// library.
    pub(crate) fn new(main: &str, setup: &Setup) -> Option<Joined> {
        if setup.programs.is_empty() {
            return None;
        }
        let mut text = String::with_capacity(
            main.len() + setup.programs.values().map(|p| p.len() + 1).sum::<usize>() + 1,
        );
        text.push_str(main);
        end_line(&mut text);
        let from = text.len();
        let mut line = 1 + breaks(&text);
        let mut parts = Vec::with_capacity(setup.programs.len());
        for (n, program) in &setup.programs {
            let program = program.strip_prefix('\u{feff}').unwrap_or(program);
            let start = text.len();
            parts.push(Part {
                label: format!("O{n:04}"),
                start,
                line,
            });
            text.push_str(program);
            end_line(&mut text);
            line += breaks(&text[start..]);
        }
        let mut setup = setup.clone();
        let programs = std::mem::take(&mut setup.programs);
        Some(Joined {
            text,
            setup,
            programs,
            from,
            parts,
        })
    }

    /// The run of the joined text, told in its texts' terms (its
    /// checkpoints keep the joined text's places: [`Joined::report_at`]
    /// reads them).
    pub(crate) fn run_observed(
        &self,
        options: super::RunOptions,
        observer: &mut impl super::Observer,
    ) -> (Run, super::Checkpoints) {
        if let Some(mut refused) = super::refused(&self.text, &self.setup) {
            self.run(&mut refused);
            return (refused, super::Checkpoints::default());
        }
        let mut lines = Lines {
            joined: self,
            inner: observer,
        };
        let (mut run, checkpoints) = super::run_text(&self.text, &self.setup, options, &mut lines);
        self.run(&mut run);
        (run, checkpoints)
    }

    /// A block's report made again from a checkpoint of
    /// [`Joined::run_observed`], in its text's terms.
    pub(crate) fn report_at(
        &self,
        checkpoints: &super::Checkpoints,
        index: u32,
    ) -> Option<BlockReport> {
        let mut b = super::report_at(&self.text, &self.setup, checkpoints, index)?;
        self.block(&mut b);
        Some(b)
    }

    /// The library program holding byte `at`, or None in the main text.
    fn part_at(&self, at: usize) -> Option<&Part> {
        if at < self.from {
            return None;
        }
        self.parts.iter().rev().find(|p| p.start <= at)
    }

    /// The library program holding line `line`, or None in the main text.
    fn part_on(&self, line: u32) -> Option<&Part> {
        self.parts.iter().rev().find(|p| p.line <= line)
    }

    /// A line of the joined text as a line of its own text.
    fn line(&self, line: u32) -> u32 {
        self.part_on(line).map_or(line, |p| line - p.line + 1)
    }

    /// A span of the joined text as one of its own text; the program it
    /// is in, None for the main text.
    fn span(&self, span: &mut Span) -> Option<&str> {
        if span.line == 0 {
            return None;
        }
        let p = self.part_at(span.start as usize)?;
        span.start -= p.start as u32;
        span.end = span.end.saturating_sub(p.start as u32);
        span.line = span.line - p.line + 1;
        Some(&p.label)
    }

    /// A sentence with each "line N" of a library program said in its own
    /// text's terms ("line 2 of O1002", or "line 2" when `named` is
    /// false: the sentence names the program already).
    fn sentence(&self, s: &str, named: bool) -> String {
        const KEY: &str = "line ";
        if !s.contains(KEY) {
            return s.to_string();
        }
        let mut out = String::with_capacity(s.len() + 16);
        let mut rest = s;
        while let Some(i) = rest.find(KEY) {
            let after = &rest[i + KEY.len()..];
            let digits = after.bytes().take_while(u8::is_ascii_digit).count();
            out.push_str(&rest[..i + KEY.len()]);
            let number = after[..digits].parse::<u32>().ok();
            match number.and_then(|n| Some((n, self.part_on(n)?))) {
                Some((n, p)) => {
                    out.push_str(&(n - p.line + 1).to_string());
                    if named {
                        out.push_str(" of ");
                        out.push_str(&p.label);
                    }
                }
                None => out.push_str(&after[..digits]),
            }
            rest = &after[digits..];
        }
        out.push_str(rest);
        out
    }

    /// A block's report in its own text's terms.
    pub(crate) fn block(&self, b: &mut BlockReport) {
        let library = self.span(&mut b.span).is_some();
        if let (true, Some(place)) = (library, &mut b.place) {
            place.library = true;
        }
        for note in &mut b.notes {
            *note = self.sentence(note, true);
        }
        if let Some(place) = &mut b.place {
            for site in &mut place.stack {
                *site = self.sentence(site, false);
            }
        }
        if let Some(watch) = &mut b.watch {
            for v in &mut watch.variables {
                v.line = v.line.map(|l| self.line(l));
            }
        }
    }

    /// A run in its texts' terms: the library's lines and bytes its
    /// programs' own, its diagnostics naming their program, and no
    /// `program-not-run` warning for a library program (it is there to
    /// be called, 19.10).
    pub(crate) fn run(&self, run: &mut Run) {
        run.blocks.iter_mut().for_each(|b| self.block(b));
        run.library.clone_from(&self.programs);
        for m in &mut run.moves {
            m.line = self.line(m.line);
        }
        for e in &mut run.events {
            e.line = self.line(e.line);
        }
        let from = self.from;
        run.diagnostics
            .retain(|d| !(d.code == "program-not-run" && d.span.start as usize >= from));
        for d in &mut run.diagnostics {
            let message = self.sentence(&d.message, true);
            d.message = match self.span(&mut d.span) {
                Some(label) => {
                    d.line = d.span.line;
                    format!("in {label}: {message}")
                }
                None => message,
            };
        }
        match &mut run.end {
            End::Error { line } | End::ProgramEnd { line } => *line = self.line(*line),
            End::Completed => {}
        }
    }
}

/// Tells the observer of each move with its line in its own text.
pub(crate) struct Lines<'a, O> {
    pub(crate) joined: &'a Joined,
    pub(crate) inner: &'a mut O,
}

impl<O: super::Observer> super::Observer for Lines<'_, O> {
    fn on_move(&mut self, m: &crate::machine::Move) {
        let mut m = *m;
        m.line = self.joined.line(m.line);
        self.inner.on_move(&m);
    }

    fn on_progress(&mut self, read: usize) {
        self.inner.on_progress(read);
    }

    fn on_resume(&mut self, prefix_moves: usize) {
        self.inner.on_resume(prefix_moves);
    }

    fn takes_reports(&self) -> bool {
        self.inner.takes_reports()
    }

    fn on_block(&mut self, b: &BlockReport) {
        let mut b = b.clone();
        self.joined.block(&mut b);
        self.inner.on_block(&b);
    }

    fn on_event(&mut self, e: &crate::report::Event) {
        let mut e = e.clone();
        e.line = self.joined.line(e.line);
        self.inner.on_event(&e);
    }
}
