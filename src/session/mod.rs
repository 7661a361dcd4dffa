//! What the page keeps between two keystrokes, natively (no wasm, tested
//! with `cargo test`, `tests/session.rs`): the program and setup of the
//! last run, the run with its checkpoints and toolpath, which run to make
//! next, the view and current block ([`view`]), the program buffer the
//! page's worker writes into ([`program`]), the document of the current
//! state and the exports. `src/wasm/` is the door to it: it converts
//! JavaScript values in and out and holds the canvas, nothing else.
//!
//! Which run to make: an edit of the last program with the same setup is
//! run again from the last run ([`crate::rerun_observed`]), from its
//! checkpoint before the edit until the run catches up with it; another
//! program (less than half of its text in common with the last one) is run
//! afresh, and the last run goes before the new one's allocates.

pub mod documents;
pub mod program;
pub mod view;

use serde::Serialize;

use crate::diag::Diagnostic;
use crate::document::{Document, ViewPlane, ViewState};
use crate::machine::Move;
use crate::render::scene::Scene;
use crate::render::{self, Frame};
use crate::report::{BlockReport, End, Run};
use crate::run::again::Earlier;
use crate::run::{Checkpoints, Observer, RunOptions};
use crate::setup::{MachineKind, Setup};
use crate::toolpath::{PathBuilder, Toolpath};
use crate::view::{BlockView, Summary, block_view, summary};

/// How the page runs a program: a checkpoint every 512 blocks instead of a
/// report per block (a report is a few hundred bytes, a checkpoint about
/// twice that shared by 512 blocks), and the moves go straight into the
/// compact toolpath instead of being kept: a million-block program fits
/// (`session_memory`, target 2 in docs/performance.md). Showing a block
/// re-runs at most 511 blocks; an export re-runs the program keeping its
/// moves.
pub const SESSION_RUN: RunOptions = RunOptions {
    keep_blocks: false,
    keep_moves: false,
    max_moves: crate::MAX_MOVES,
    max_blocks: crate::MAX_BLOCKS,
    checkpoint_every: 512,
};

/// What a run answers the page: `{ summary, diagnostics }`.
#[derive(Clone, Debug, Serialize)]
pub struct RunAnswer<'a> {
    /// Counts, bounds and end of the run.
    pub summary: Summary,
    /// Parse and run diagnostics, in order.
    pub diagnostics: &'a [Diagnostic],
}

/// A program, its setup, the run and its toolpath, and the view of them.
#[derive(Debug, Default)]
pub struct Session {
    last: LastRun,
    /// Counts the runs whose toolpath differed from the one before: a kept
    /// frame or pixel layer shows one of them (a run that changed nothing
    /// drawn, such as an edit of an N number, keeps it).
    drawing: u64,
    /// The next program, as the page's worker writes it.
    program: program::ProgramBuffer,
    /// Plane, zoom, pan, current block, and the frame last drawn.
    view: view::View,
}

/// The last run and what it was made of.
#[derive(Debug)]
struct LastRun {
    text: String,
    setup: Setup,
    run: Run,
    /// What the run kept to make its blocks' reports again.
    checkpoints: Checkpoints,
    toolpath: Toolpath,
    /// The setup was refused: nothing ran (the diagnostics say why), and
    /// an export has no moves to run again for.
    setup_refused: bool,
}

impl Default for LastRun {
    fn default() -> Self {
        let setup = Setup::default();
        let run = crate::run("", &setup);
        let toolpath = Toolpath::from_run(&run);
        LastRun {
            text: String::new(),
            setup,
            run,
            checkpoints: Checkpoints::default(),
            toolpath,
            setup_refused: false,
        }
    }
}

impl LastRun {
    /// What the view needs of it.
    fn showing(&self) -> view::Showing<'_> {
        view::Showing {
            text: &self.text,
            setup: &self.setup,
            run: &self.run,
            checkpoints: &self.checkpoints,
            toolpath: &self.toolpath,
        }
    }
}

/// Builds the session's toolpath from the moves as they are made and
/// passes the progress on.
struct SessionObserver<'a, F> {
    path: PathBuilder<'a>,
    progress: F,
    /// The program's length in bytes.
    len: usize,
}

impl<F: FnMut(f64)> Observer for SessionObserver<'_, F> {
    fn on_move(&mut self, m: &Move) {
        self.path.on_move(m);
    }

    fn on_resume(&mut self, prefix_moves: usize) {
        self.path.on_resume(prefix_moves);
    }

    fn on_progress(&mut self, read: usize) {
        self.path.foresee(read, self.len);
        (self.progress)(read as f64 / self.len.max(1) as f64);
    }
}

/// True when `new` keeps at least half of `old` unchanged at its start and
/// end together: an edit, worth running again from the last run.
fn similar(old: &str, new: &str) -> bool {
    let (prefix, suffix) = crate::run::again::common_ends(old.as_bytes(), new.as_bytes());
    prefix + suffix >= new.len() / 2
}

/// A setup as the page passes it: None for the default setup, else its
/// JSON text (None: a value that is not JSON). Problems are `setup-…`
/// diagnostics, which the run reports.
pub fn read_setup(json: Option<Option<&str>>) -> Result<Setup, Vec<Diagnostic>> {
    match json {
        None => Ok(Setup::default()),
        Some(None) => Err(vec![Diagnostic::error(
            "setup-syntax",
            Default::default(),
            "setup document: not a JSON object",
        )]),
        Some(Some(text)) => Setup::from_json(text).map_err(|e| e.diagnostics),
    }
}

/// Rounds to `digits` significant digits (view values in links stay short
/// and read well: zoom 1.83 rather than 1.8301502738172).
fn significant(x: f64, digits: i32) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    let scale = 10f64.powi(digits - 1 - x.abs().log10().floor() as i32);
    let r = (x * scale).round() / scale;
    if r.is_finite() { r } else { x }
}

impl Session {
    /// An empty session (no program, default setup).
    pub fn new() -> Session {
        Session::default()
    }

    /// Runs `program` with `setup` (or, for a setup that was refused, its
    /// `setup-…` diagnostics: nothing runs, the path is empty) and keeps
    /// the result; `progress(fraction)` (0 to 1, of the program's bytes
    /// read) is called after every MiB of program.
    pub fn run(
        &mut self,
        // Owned: the text is kept as it is (a million-block program is not
        // held twice at the run's peak).
        program: String,
        setup: Result<Setup, Vec<Diagnostic>>,
        progress: impl FnMut(f64),
    ) -> RunAnswer<'_> {
        let last = &mut self.last;
        let earlier_text = match &setup {
            Ok(setup)
                if !last.setup_refused && *setup == last.setup && similar(&last.text, &program) =>
            {
                Some(std::mem::replace(&mut last.text, program))
            }
            _ => {
                last.text = program;
                last.run = crate::run("", &Setup::default());
                last.checkpoints = Checkpoints::default();
                last.toolpath = Toolpath::default();
                None
            }
        };
        match setup {
            Ok(setup) => {
                let earlier = earlier_text.as_deref().map(|text| Earlier {
                    text,
                    run: &last.run,
                    checkpoints: &last.checkpoints,
                });
                let mut observer = SessionObserver {
                    path: PathBuilder::new(
                        setup.machine,
                        setup.units,
                        earlier.map(|_| &last.toolpath),
                    ),
                    progress,
                    len: last.text.len(),
                };
                let (run, checkpoints, reuse) =
                    crate::rerun_observed(&last.text, &setup, SESSION_RUN, earlier, &mut observer);
                let mut toolpath = observer.path.finish(&run, &reuse);
                toolpath.shrink_to_fit();
                if toolpath != last.toolpath {
                    self.drawing += 1;
                }
                last.run = run;
                last.checkpoints = checkpoints;
                last.toolpath = toolpath;
                last.setup = setup;
                last.setup_refused = false;
            }
            Err(diagnostics) => {
                last.setup = Setup::default();
                let mut run = crate::run("", &last.setup);
                run.diagnostics = diagnostics;
                run.end = End::Error { line: 0 };
                last.run = run;
                last.checkpoints = Checkpoints::default();
                last.toolpath = Toolpath::new(last.setup.machine, last.setup.units);
                self.drawing += 1;
                last.setup_refused = true;
            }
        }
        drop(earlier_text);
        self.view.after_run(&self.last.showing(), self.drawing);
        RunAnswer {
            summary: summary(&self.last.run).with_hint(&self.last.text),
            diagnostics: &self.last.run.diagnostics,
        }
    }

    /// Room for the next program (see [`program::ProgramBuffer::room`]).
    pub fn program_buffer(&mut self, capacity: usize) -> Option<&mut [u8]> {
        self.program.room(capacity)
    }

    /// The next program made by an edit of the one in the buffer (see
    /// [`program::ProgramBuffer::splice`]).
    pub fn program_splice(
        &mut self,
        length: usize,
        from: usize,
        to: usize,
        insert: usize,
    ) -> Option<&mut [u8]> {
        self.program.splice(length, from, to, insert)
    }

    /// [`Session::run`] of the program in the buffer, its first `length`
    /// bytes (see [`program::ProgramBuffer::take`]).
    pub fn run_buffer(
        &mut self,
        length: usize,
        setup: Result<Setup, Vec<Diagnostic>>,
        progress: impl FnMut(f64),
    ) -> RunAnswer<'_> {
        let program = self.program.take(length);
        self.run(program, setup, progress)
    }

    /// The program of the last run.
    pub fn text(&self) -> &str {
        &self.last.text
    }

    /// The setup of the last run (the default setup after a refused one).
    pub fn setup(&self) -> &Setup {
        &self.last.setup
    }

    /// The last run (its blocks and moves are not kept: see
    /// [`Session::block`] and [`Session::with_moves`]).
    pub fn last_run(&self) -> &Run {
        &self.last.run
    }

    /// What the last run kept to make its blocks' reports again.
    pub fn checkpoints(&self) -> &Checkpoints {
        &self.last.checkpoints
    }

    /// The last run's toolpath.
    pub fn toolpath(&self) -> &Toolpath {
        &self.last.toolpath
    }

    /// Runs so far whose drawing changed.
    pub fn drawing(&self) -> u64 {
        self.drawing
    }

    /// Number of executed blocks.
    pub fn block_count(&self) -> u32 {
        self.last.run.block_count
    }

    /// The report of block `index`, made again from the checkpoint before
    /// it (the session keeps checkpoints, not a report per block); None
    /// out of range.
    pub fn report(&self, index: u32) -> Option<BlockReport> {
        crate::run::report_at(
            &self.last.text,
            &self.last.setup,
            &self.last.checkpoints,
            index,
        )
    }

    /// Block `index` as reported (the CLI's JSON `blocks` entries), or
    /// None out of range.
    pub fn block(&self, index: u32) -> Option<BlockView<'_>> {
        self.report(index).map(|b| {
            let text = crate::view::text_of(&b, &self.last.text, &self.last.setup.programs);
            block_view(&b, text)
        })
    }

    /// The last executed block at or before 1-based `line` (the block a
    /// cursor on that line belongs to, or the one before a comment line),
    /// or -1 when no block runs before it.
    pub fn block_at_line(&self, line: u32) -> i32 {
        self.last
            .checkpoints
            .block_at_line(line)
            .and_then(|b| i32::try_from(b).ok())
            .unwrap_or(-1)
    }

    /// The last run again, keeping its moves (for the exports: the session
    /// keeps only the toolpath). After a refused setup, the empty run (the
    /// program is not run with some other setup).
    pub fn with_moves(&self) -> Run {
        if self.last.setup_refused {
            return self.last.run.clone();
        }
        let options = RunOptions {
            keep_moves: true,
            checkpoint_every: 0,
            ..SESSION_RUN
        };
        crate::run_with(&self.last.text, &self.last.setup, options)
    }

    /// The moves as an indented JSON file: `{ summary, moves }` with
    /// exactly the CLI's `run --format json` fields.
    pub fn moves_json(&self) -> String {
        crate::export::moves_json(&self.with_moves())
    }

    /// The moves as CSV: the JSON fields flattened into columns.
    pub fn moves_csv(&self) -> String {
        crate::export::moves_csv(&self.with_moves())
    }

    /// The document of the current state: the program and setup of the
    /// last run, the view (None when it is the machine's default: its
    /// first plane, zoom 1, no pan; zoom to 6 significant digits, pan to
    /// 1e-4) and the current block as `step`. After a refused setup it
    /// carries the default setup.
    pub fn document(&self) -> Document {
        let default_plane = match self.last.run.machine {
            MachineKind::Lathe => ViewPlane::ZX,
            MachineKind::Mill => ViewPlane::XY,
        };
        let scene = self.view.scene();
        let plane = ViewPlane::parse(scene.plane.name()).unwrap_or(default_plane);
        let zoom = significant(scene.zoom, 6);
        let pan = scene.pan.map(|p| {
            let r = (p * 1e4).round() / 1e4;
            if r == 0.0 { 0.0 } else { r }
        });
        let swept = scene.swept;
        let legend = !scene.legend_folded;
        // The 3D view's angles, as its hundredths of a degree read.
        let angles = match scene.plane {
            render::Plane::Orbit(a) | render::Plane::LatheOrbit(a) => Some([a.yaw(), a.pitch()]),
            _ => None,
        };
        let view = (plane != default_plane || zoom != 1.0 || pan != [0.0, 0.0] || swept || !legend)
            .then_some(ViewState {
                plane,
                zoom,
                pan,
                angles,
                swept,
                legend,
            });
        Document {
            setup: self.last.setup.clone(),
            program: self.last.text.clone(),
            view,
            step: scene.step,
        }
    }

    /// The drawing as an SVG document (the same view state).
    pub fn render_svg(&self, width: u32, height: u32) -> String {
        render::svg::render_scene(
            &self.last.toolpath,
            self.view.scene(),
            f64::from(width),
            f64::from(height),
        )
    }

    /// Plane, zoom, pan, current block, marker and colours, as drawn.
    pub fn scene(&self) -> &Scene {
        self.view.scene()
    }

    /// The view state (see [`view::ViewChange`]).
    pub fn view(&self) -> view::ViewChange {
        self.view.view()
    }

    /// Sets any of plane, zoom, pan and current block (see
    /// [`view::View::set_view`]); returns the view state.
    pub fn set_view(&mut self, change: &view::ViewChange) -> view::ViewChange {
        self.view.set_view(&self.last.showing(), change)
    }

    /// Chooses the plane drawn (see [`view::View::set_plane`]).
    pub fn set_plane(&mut self, name: &str) -> bool {
        self.view.set_plane(self.last.run.machine, name)
    }

    /// Turns the 3D view by a drag of (dx, dy) CSS pixels (see
    /// [`view::View::orbit_by`]).
    pub fn orbit_by(&mut self, dx: f64, dy: f64) -> bool {
        self.view.orbit_by(self.last.run.machine, dx, dy)
    }

    /// Zooms by `factor` about the CSS pixel (x, y) of the last frame.
    pub fn zoom_at(&mut self, x: f64, y: f64, factor: f64) {
        self.view.zoom_at(&self.last.toolpath, x, y, factor);
    }

    /// Moves the drawing by (dx, dy) CSS pixels.
    pub fn pan_by(&mut self, dx: f64, dy: f64) {
        self.view.pan_by(&self.last.toolpath, dx, dy);
    }

    /// Zoom 1, no pan: the whole path.
    pub fn fit(&mut self) {
        self.view.fit();
    }

    /// `"light"` or `"dark"`: the colours.
    pub fn set_theme(&mut self, name: &str) {
        self.view.set_theme(name);
    }

    /// Makes block `index` the current one (see [`view::View::set_step`]).
    pub fn set_step(&mut self, index: i32) -> i32 {
        self.view.set_step(&self.last.showing(), index)
    }

    /// The current block, or -1.
    pub fn step(&self) -> i32 {
        self.view.step()
    }

    /// The block under CSS pixel (x, y) of the last frame drawn (see
    /// [`view::View::pick`]), or -1.
    pub fn pick(&self, x: f64, y: f64, tolerance: f64) -> i32 {
        self.view.pick(&self.last.toolpath, x, y, tolerance)
    }

    /// The frame asked for (see [`view::View::ask`]).
    pub fn ask_frame(&mut self, width: u32, height: u32, dpr: f64) -> view::FrameAsk {
        self.view.ask(width, height, dpr, self.drawing)
    }

    /// The frame asked for during a gesture (see [`view::View::ask_moving`]).
    pub fn ask_moving_frame(&mut self, width: u32, height: u32, dpr: f64) -> view::FrameAsk {
        self.view.ask_moving(width, height, dpr, self.drawing)
    }

    /// True when the canvas already shows the frame `ask` asks for.
    pub fn frame_shown(&self, ask: &view::FrameAsk) -> bool {
        self.view.shown(ask)
    }

    /// The frame `ask` asked for was drawn (see [`view::View::drawn`]).
    pub fn frame_drawn(&mut self, ask: &view::FrameAsk, frame: Frame, moved: bool) {
        self.view.drawn(ask, frame, moved);
    }

    /// The canvas shows nothing known: the next frame is drawn whole.
    pub fn forget_frame(&mut self) {
        self.view.forget_frame();
    }
}
