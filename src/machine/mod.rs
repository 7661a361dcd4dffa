//! The interpreter: modal state, positions, motion and coordinates (behaviour 2).
//!
//! The machine tracks per axis the **programmed position** (what the program
//! commands, in the current work coordinate system) and the offset vectors;
//! the **actual position** is programmed + length vector + position vector
//! (mill) or + T-offset vector (lathe). Everything is kept in millimetres and
//! converted when reported. The offset rules themselves are in
//! [`crate::offsets`]; this module applies them block by block and owns the
//! positions.

pub mod arc;
mod arcs;
pub(crate) mod calls;
mod coords;
mod corner;
mod corner_geometry;
mod cutter;
mod cycles;
mod data;
mod engrave;
pub mod frame;
mod lathe;
pub(crate) mod macro_state;
mod mill;
pub mod modal;
mod modes;
mod mrc;
mod pocket;
mod polar;
pub mod program;
mod reference;
pub mod state;
mod sysvars;
mod sysvars_linuxcnc;
mod sysvars_state;
mod tool_table;
mod transform;
mod unmodelled;
mod watch;
mod words;

pub(crate) use arcs::ArcRequest;
pub use state::{ArcInfo, BlockState, DataSet, EventKind, Move, MoveKind, PolarState, VariableSet};
pub use watch::{WatchView, Watched};

use crate::diag::{Diagnostic, Span};
use crate::geometry::{Xyz, add};
use crate::offsets::cutter::CutterState;
use crate::offsets::lathe::LatheState;
use crate::offsets::length::LengthState;
use crate::offsets::position::PositionState;
use crate::setup::{MachineKind, MainM99, Setup, Units};
use crate::syntax::codes::{MCode, NonModal};
use crate::syntax::{Address, Block};
use calls::Jump;
use modal::Modal;
use std::sync::Arc;

/// The blocks that run after the current one (look-ahead), for the rules
/// that need the next move: the run reads them when a rule asks
/// (`run/ahead.rs`), skipping the blocks the block skip switch passes over.
pub(crate) trait Ahead {
    /// The `k`-th block that runs after the current one (0: the next), as
    /// parsed (a block with a parse error has `error` set), or None past the
    /// program's end.
    fn peek(&mut self, k: usize) -> Option<&Block>;
}

/// No blocks ahead: the program ends after the current block.
pub(crate) struct NoneAhead;

impl Ahead for NoneAhead {
    fn peek(&mut self, _: usize) -> Option<&Block> {
        None
    }
}

/// What happens after a block.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Flow {
    /// Go on with the next block.
    Continue,
    /// M02/M30: the program ends.
    End,
    /// M98, M97, M99: the run goes on elsewhere, where the machine's
    /// `jump` says (behaviour 19; kept out of the flow, which every block
    /// returns: the `check` instruction count in docs/performance.md).
    Jump,
}

/// What one block produced besides the state change.
#[derive(Debug, Default)]
pub(crate) struct Out {
    pub moves: Vec<Move>,
    pub events: Vec<EventKind>,
    pub notes: Vec<String>,
    pub warnings: Vec<Diagnostic>,
    /// The run keeps no block reports (`check`): the notes no one reads are
    /// not written where writing them costs (cutter compensation's sentence
    /// at every block).
    pub quiet: bool,
    /// A second `Out` lent to a machine copy reading ahead, kept from block
    /// to block (cutter compensation reads ahead at every block).
    pub(crate) scratch: Option<Box<Out>>,
    /// The block's result depends on the program text before this byte
    /// offset besides the block itself (a G70–G73 read its contour by
    /// sequence number, behaviour 15.3): a run made again after an edit
    /// there must run the block again.
    pub reads: Option<u32>,
}

impl Out {
    /// An `Out` for a run that keeps block reports or not.
    pub fn for_reports(keep_blocks: bool) -> Out {
        Out {
            quiet: !keep_blocks,
            ..Out::default()
        }
    }

    /// Adds the note `f` writes, unless the run keeps no reports.
    #[inline]
    pub fn note(&mut self, f: impl FnOnce() -> String) {
        if !self.quiet {
            self.notes.push(f());
        }
    }

    pub fn clear(&mut self) {
        self.moves.clear();
        self.events.clear();
        self.notes.clear();
        self.warnings.clear();
        self.reads = None;
    }
}

/// Programmed and actual position at one moment, to start a move from.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Mark {
    prog: Xyz,
    act: Xyz,
}

/// The interpreter's state between blocks. Cloning it is cheap (the setup
/// is shared), which is how a run keeps checkpoints to resume from.
#[derive(Clone, Debug)]
pub struct Machine {
    setup: Arc<Setup>,
    pub(crate) state: BlockState,
    /// The tool's point in the program's own coordinates, before the mill's
    /// transformations (mm; kept while one is on: behaviour 13.7).
    command: Xyz,
    /// No transformation, polar coordinates or absolute arc centre is on:
    /// the words read plainly (the motion's fast path).
    plain_words: bool,
    /// The program was warned that rotary axes are not drawn.
    rotary_warned: bool,
    /// The program was warned of G90.1/G91.1.
    arc_center_warned: bool,
    /// Mirror image switches per axis.
    mirror: [bool; 3],
    /// The point movements are mirrored about, in machine coordinates.
    mirror_center: Xyz,
    cycle: cycles::CycleData,
    turning: lathe::TurningData,
    /// The lathe's G70–G76 data and the contour being passed over after a
    /// G71–G73 (behaviour 15).
    mrc: mrc::MrcData,
    feed_warned: bool,
    /// A mode is in effect that every block must be checked against (G93,
    /// behaviour 14.8; cutter radius compensation engaged, behaviour 16):
    /// no block takes the mill's fast path for plain moves.
    special: bool,
    index: u32,
    line: u32,
    span: Span,
    /// Moves this run may still record; a block that would make more stops
    /// with an error instead of filling memory (behaviour 8.3).
    pub(crate) moves_left: usize,
    /// Set when a block ran out of `moves_left`.
    overflow: bool,
    /// The last block cut a chamfer or corner rounding at `corner`: the
    /// next block's words count from the corner (behaviour 2.32). A flag
    /// the next block tests, and the corner beside it (the `check`
    /// instruction count in docs/performance.md).
    pub(super) corner_cut: bool,
    /// The comment of the G47 block being run (Haas engraving's text).
    pub(super) engraving_text: Option<String>,
    /// The corner the last block's chamfer or rounding cut.
    pub(super) corner: Xyz,
    /// While a block after a corner runs from the corner: where the tool
    /// really starts (the chamfer's or the round's end).
    pub(super) corner_end: Option<Xyz>,
    /// This machine is a copy running the next block to find its direction
    /// (behaviour 2.31): its own chamfers are not cut.
    reading_ahead: bool,
    /// A lathe block with `,C`/`,R` runs through the chamfer's code, which
    /// reads those words (behaviour 2.35); elsewhere the lathe refuses them.
    pub(super) corner_words_read: bool,
    /// The program's macro variables (behaviour 20.1), kept with the
    /// machine so that a checkpoint holds them.
    pub(crate) variables: crate::macros::Store,
    /// The call or return the last block asked for (with [`Flow::Jump`]);
    /// the run takes it.
    pub(crate) jump: Option<calls::Jump>,
    /// Macro calls' state (behaviour 21), once a program makes one.
    pub(crate) macro_calls: Option<Box<macro_state::MacroCalls>>,
    /// The variables the program touched (behaviour 21.12), once it reads or sets one.
    watch: Option<Box<watch::Watch>>,
}

const AXES: [(Address, char); 3] = [(Address::X, 'X'), (Address::Y, 'Y'), (Address::Z, 'Z')];

impl Machine {
    /// A machine at the setup's start position, in its start state (behaviour 2.3).
    pub fn new(setup: Arc<Setup>) -> Machine {
        let (start, origin) = setup.start_and_origin_mm();
        let state = BlockState {
            machine: setup.machine,
            system: setup.settings.gcode_system(),
            programmed: start,
            actual: start,
            modal: Modal::start(&setup),
            feed: None,
            spindle: None,
            spindle_limit: None,
            tool: 0,
            next_tool: 0,
            length: LengthState::default(),
            table_radius: None,
            position: PositionState::default(),
            cutter: CutterState::default(),
            lathe: LatheState::default(),
            coords: frame::Coordinates {
                zero: origin,
                ..frame::Coordinates::default()
            },
            rotary: [None; 3],
            polar: None,
        };
        let mirror = if setup.machine == MachineKind::Mill {
            setup.settings.mirror.axes()
        } else {
            [false; 3]
        };
        Machine {
            setup,
            state,
            command: start,
            plain_words: true,
            rotary_warned: false,
            arc_center_warned: false,
            mirror,
            mirror_center: add(start, origin),
            cycle: cycles::CycleData::default(),
            turning: lathe::TurningData::default(),
            mrc: mrc::MrcData::default(),
            feed_warned: false,
            special: state.modal.motion_none,
            index: 0,
            line: 0,
            span: Span::default(),
            moves_left: usize::MAX,
            overflow: false,
            jump: None,
            macro_calls: None,
            watch: None,
            corner_cut: false,
            engraving_text: None,
            corner: [0.0; 3],
            corner_end: None,
            reading_ahead: false,
            corner_words_read: false,
            variables: crate::macros::Store::default(),
        }
    }

    /// The state after the last block.
    pub fn state(&self) -> &BlockState {
        &self.state
    }

    /// Sets `special` from the modes that keep blocks off the mill's fast
    /// path: inverse time feed (G93) and cutter compensation while engaged.
    fn update_special(&mut self) {
        // A copy reading ahead for the compensation runs plain moves by the
        // fast path: it wants their programmed moves only.
        self.special = self.state.modal.feed_mode == modal::FeedMode::InverseTime
            || (self.state.cutter.engaged() && !self.reading_ahead)
            || self.state.modal.motion_none;
    }

    /// The setup this machine runs with, with what G10 blocks have written
    /// into its offset tables and work offsets (behaviour 17.8).
    pub(crate) fn setup(&self) -> &Setup {
        &self.setup
    }

    /// True when this machine runs any block exactly as `other` does: every
    /// position, modal value, offset, cycle datum and macro variable (with
    /// the lines that set them, behaviour 21.12) equal to the bit (a
    /// run made again after an edit goes on with the earlier run's result
    /// from the first place where the two machines agree). The current
    /// block's place, the moves left and the overflow flag are set afresh
    /// by every block; the setup is compared by whoever makes the run, and
    /// what G10 blocks wrote into this machine's copy of it here.
    pub(crate) fn same_course(&self, other: &Machine) -> bool {
        // `==` would take -0.0 for 0.0 (a sign that can reach a report);
        // the Debug form of a float is its shortest round-trip text, which
        // tells them apart. The positions first: they differ most often.
        fn key(m: &Machine) -> String {
            format!(
                "{:?}",
                (
                    &m.state,
                    m.command,
                    m.plain_words,
                    (m.rotary_warned, m.arc_center_warned),
                    m.mirror,
                    m.mirror_center,
                    (m.cycle, m.turning, m.mrc),
                    m.feed_warned,
                    m.special,
                    m.corner_cut,
                    m.corner,
                    (&m.variables, &m.macro_calls, &m.watch)
                )
            )
        }
        // The tables and work offsets a G10 wrote are the setup's (both
        // machines started from the same one): the same values, the same
        // course (behaviour 17.8). Written values are never -0.
        self.state.actual == other.state.actual
            && self.state.programmed == other.state.programmed
            && key(self) == key(other)
            && (Arc::ptr_eq(&self.setup, &other.setup) || self.setup == other.setup)
    }

    /// Runs one block; `program` is the text it is part of, read again by
    /// sequence number when a block asks (behaviour 15.3). On error the block
    /// has no effect that matters: the run stops there (behaviour 2.1).
    pub(crate) fn execute(
        &mut self,
        block: &Block,
        index: u32,
        out: &mut Out,
        ahead: &mut dyn Ahead,
        program: &mut dyn program::ProgramText,
    ) -> Result<Flow, Diagnostic> {
        // A block with M may call or return (behaviour 19.3): out of line,
        // one flag test for a block without M (and one place that runs a
        // block, so that the mill's block stays inlined here: the `check`
        // instruction count in docs/performance.md).
        if block.holds(Address::M)
            && let Some(flow) = self.execute_call(block, index, out, ahead, program)?
        {
            return Ok(flow);
        }
        self.execute_block(block, index, out, ahead, program)
    }

    /// [`Machine::execute`] for a block with M codes that calls or
    /// returns: the block's other words first, then the jump; None for a
    /// block with no call.
    #[inline(never)]
    fn execute_call(
        &mut self,
        block: &Block,
        index: u32,
        out: &mut Out,
        ahead: &mut dyn Ahead,
        program: &mut dyn program::ProgramText,
    ) -> Result<Option<Flow>, Diagnostic> {
        let Some((jump, rest)) = self.subprogram_jump(block, program)? else {
            return Ok(None);
        };
        // `rest` has no call left: this runs it as any block.
        let flow = self.execute(&rest, index, out, ahead, program)?;
        if flow == Flow::End {
            return Ok(Some(Flow::End));
        }
        if let Jump::Return { to } = jump
            && program.depth() == 0
            && self.setup.settings.main_m99() == MainM99::Once
        {
            // Behaviour 19.4, setting 7.42: the control would go round
            // again until stopped; one pass is the drawing.
            let whither = match to {
                Some(n) => format!("on at N{n}"),
                None => "back to its start".to_string(),
            };
            out.notes.push(format!(
                "M99 in the main program: a control goes {whither} and runs the program again until it is stopped; offsetlab ends the run after this pass (setting main_m99 = loop repeats it)"
            ));
            return Ok(Some(Flow::End));
        }
        self.jump = Some(jump);
        Ok(Some(Flow::Jump))
    }

    /// [`Machine::execute`] for a block that is no call.
    #[inline(always)]
    fn execute_block(
        &mut self,
        block: &Block,
        index: u32,
        out: &mut Out,
        ahead: &mut dyn Ahead,
        program: &mut dyn program::ProgramText,
    ) -> Result<Flow, Diagnostic> {
        self.index = index;
        self.line = block.span.line;
        self.span = block.span;
        self.overflow = false;
        let after_corner = self.corner_cut.then(|| self.run_from_corner());
        let ran = match self.setup.machine {
            MachineKind::Mill => self.mill_block(block, out, ahead, program),
            MachineKind::Lathe => self.lathe_block(block, out, ahead, program),
        };
        if let Some(end) = after_corner {
            Self::start_at_corner_end(out, end);
            // Not left for a later block when this one fails and the run
            // goes on (setting continue_past_errors).
            self.corner_end = None;
        }
        ran?;
        if self.overflow {
            return Err(self.error(
                "too-many-moves",
                block.span,
                "the program makes more moves than the run may record (see the limits in the README); the run stops here",
            ));
        }
        self.state.actual = self.actual();
        // `abs() <= 1e9` is false for NaN and the infinities too.
        let within = |v: &f64| v.abs() <= 1e9;
        if !(self.state.actual.iter().all(within) && self.state.programmed.iter().all(within)) {
            return Err(self.error(
                "numeric-overflow",
                block.span,
                "this block takes the tool beyond any machine's travel",
            ));
        }
        let end =
            block.holds(Address::M) && block.mcodes(self.setup.machine).any(|m| m.ends_program());
        Ok(if end { Flow::End } else { Flow::Continue })
    }

    // ----- small helpers -------------------------------------------------

    fn units(&self) -> Units {
        self.state.modal.units
    }

    /// A program value in the current units, in mm.
    fn mm(&self, v: f64) -> f64 {
        v * self.units().mm()
    }

    fn error(&self, code: &'static str, span: Span, msg: impl Into<String>) -> Diagnostic {
        Diagnostic::error(code, span, msg)
    }

    fn word_span(&self, b: &Block, a: Address) -> Span {
        b.get(a).map_or(b.span, |w| w.span)
    }

    /// The actual position: programmed + every offset vector.
    fn actual(&self) -> Xyz {
        let s = &self.state;
        let mut a = add(s.programmed, s.position.vector);
        a[2] += s.length.vector;
        add(add(a, s.lathe.vector), s.cutter.vector)
    }

    fn mark(&self) -> Mark {
        Mark {
            prog: self.state.programmed,
            act: self.actual(),
        }
    }

    /// Records the motion from `from` to the current position. Line moves
    /// that go nowhere (on both paths) are not recorded. Inlined where it is
    /// called: a straight move's `None` arc then costs its tag alone, not a
    /// copy of a whole `Option<ArcInfo>` (the `check` instruction count in docs/performance.md).
    #[inline(always)]
    fn emit(
        &mut self,
        out: &mut Out,
        from: Mark,
        kind: MoveKind,
        at_feed: bool,
        arc: Option<ArcInfo>,
    ) {
        let to = self.actual();
        let prog = self.state.programmed;
        if arc.is_none() && from.act == to && from.prog == prog {
            return;
        }
        if out.moves.len() >= self.moves_left {
            self.overflow = true;
            return;
        }
        let feed = matches!(kind, MoveKind::Feed | MoveKind::ArcCw | MoveKind::ArcCcw)
            || (kind == MoveKind::Offset && at_feed);
        if feed && self.state.feed.is_none() && !self.feed_warned {
            self.feed_warned = true;
            out.warnings.push(Diagnostic::warning(
                "missing-feed",
                self.span,
                "feed move before any F word: a control would stop here with an alarm",
            ));
        }
        out.moves.push(Move {
            kind,
            at_feed,
            block: self.index,
            line: self.line,
            units: self.units(),
            from: from.act,
            to,
            programmed_from: from.prog,
            programmed_to: prog,
            arc,
        });
    }

    /// Records a generated move whose actual path is not the programmed one
    /// plus the offset vectors (a pocket's circles inside the contour,
    /// behaviour 14.12; a corner, behaviour 14.14): both ends given. Like
    /// [`Machine::emit`] it stops at the move budget and warns of a feed
    /// move before any F; a straight move that goes nowhere is not recorded.
    /// Out of line: ordinary moves take `emit`.
    #[inline(never)]
    pub(crate) fn push_move(
        &mut self,
        out: &mut Out,
        kind: MoveKind,
        from: Mark,
        to: Mark,
        arc: Option<ArcInfo>,
    ) {
        if arc.is_none() && from.act == to.act && from.prog == to.prog {
            return;
        }
        if out.moves.len() >= self.moves_left {
            self.overflow = true;
            return;
        }
        let feed = kind != MoveKind::Rapid;
        if feed && self.state.feed.is_none() && !self.feed_warned {
            self.feed_warned = true;
            out.warnings.push(Diagnostic::warning(
                "missing-feed",
                self.span,
                "feed move before any F word: a control would stop here with an alarm",
            ));
        }
        out.moves.push(Move {
            kind,
            at_feed: feed,
            block: self.index,
            line: self.line,
            units: self.units(),
            from: from.act,
            to: to.act,
            programmed_from: from.prog,
            programmed_to: to.prog,
            arc,
        });
    }

    fn event(&self, out: &mut Out, kind: EventKind) {
        out.events.push(kind);
    }

    /// The programmed target of an axis word (value in mm): absolute or
    /// incremental, reversed about the mirror centre when mirror image is on
    /// for the axis (behaviour 2.17).
    fn target(&self, axis: usize, word_mm: f64, incremental: bool) -> f64 {
        let p = self.state.programmed[axis];
        if self.mirror[axis] {
            let c = self.mirror_center[axis] - self.state.coords.zero[axis];
            if incremental {
                p - word_mm
            } else {
                2.0 * c - word_mm
            }
        } else if incremental {
            p + word_mm
        } else {
            word_mm
        }
    }

    /// Sets the programmed coordinate of `axis` to `value` without moving the
    /// tool (G92 / G50). With `clear_position` the axis's G45–G48 vector is
    /// cancelled first (behaviour 4.7, seed 003). The G52 local offset of the
    /// axis is cancelled: the shift takes it over (behaviour 13.2).
    fn set_coordinate(&mut self, axis: usize, value: f64, clear_position: bool) {
        let before = self.actual()[axis];
        if clear_position {
            self.state.position.cancel_for_coordinate_setting(axis);
        }
        self.state.programmed[axis] = value;
        let after = self.actual()[axis];
        let moved = before - after;
        let c = &mut self.state.coords;
        c.zero[axis] += moved;
        c.shift[axis] += moved + c.local[axis];
        c.local[axis] = 0.0;
        if self.mirror[axis] {
            // Mirror about the point where the coordinate was set.
            self.mirror_center[axis] = self.state.programmed[axis] + self.state.coords.zero[axis];
        }
    }

    /// Codes, words and M functions every block may carry: units, plane,
    /// distance, feed mode, return level, F, S, M codes (the work system is
    /// [`Machine::work_words`]).
    fn common_words(&mut self, b: &Block, out: &mut Out) -> Result<(), Diagnostic> {
        let machine = self.setup.machine;
        let c = b.codes();
        if let (Some(plane), Some(r)) = (c.plane(), self.state.modal.transforms.rotation)
            && plane != r.plane
        {
            return Err(self.error(
                "rotation-plane",
                b.code_span(crate::syntax::codes::Group::Plane),
                format!(
                    "{} cannot be selected while G68 rotates the {} plane (Fanuc: no plane selection in rotation mode)",
                    plane.gcode(),
                    r.plane.gcode()
                ),
            ));
        }
        let modal = &mut self.state.modal;
        if let Some(units) = c.units() {
            modal.units = units;
        }
        if let Some(plane) = c.plane() {
            modal.plane = plane;
        }
        if let Some(distance) = c.distance() {
            modal.distance = distance;
        }
        if let Some(feed_mode) = c.feed_mode() {
            modal.feed_mode = feed_mode;
        }
        if let Some(level) = c.return_level() {
            modal.return_level = level;
        }
        if let Some(surface_speed) = c.surface_speed() {
            modal.surface_speed = surface_speed;
        }
        // Group 07: the mode; what it does to the path is the cutter
        // compensation's (`cutter/`, behaviour 16). The lathe's table has
        // G40 alone.
        if let Some(mode) = c.cutter() {
            self.state.cutter.mode = mode;
        }
        if let Some(f) = b.value(Address::F) {
            self.state.feed = Some(f);
        }
        if let Some(s) = b.value(Address::S) {
            // G50 S on the lathe is the spindle speed limit, not a speed:
            // said, since no state shows it (behaviour 2.19, 2.22).
            if machine == MachineKind::Lathe && c.non_modal() == Some(NonModal::SetCoordinates) {
                self.state.spindle_limit = Some(s);
                let g = crate::syntax::codes::Code::NonModal(NonModal::SetCoordinates)
                    .gcode(self.state.table());
                out.notes.push(format!(
                    "{g} S{s}: the spindle speed limit, which constant surface speed (G96) keeps the spindle under; the spindle speed is not changed"
                ));
            } else {
                self.state.spindle = Some(s);
            }
        }
        if !b.holds(Address::M) {
            return Ok(());
        }
        for m in b.mcodes(machine) {
            let kind = match m {
                MCode::ProgramStop => EventKind::ProgramStop,
                MCode::OptionalStop => EventKind::OptionalStop,
                MCode::ProgramEnd | MCode::ProgramEndRewind => {
                    EventKind::ProgramEnd { m: m.number() }
                }
                MCode::SpindleCw => EventKind::SpindleCw,
                MCode::SpindleCcw => EventKind::SpindleCcw,
                MCode::SpindleStop => EventKind::SpindleStop,
                MCode::SpindleOrient => EventKind::SpindleOrient,
                MCode::ToolChange => {
                    self.state.tool = self.state.next_tool;
                    EventKind::ToolChange {
                        tool: self.state.tool,
                    }
                }
                MCode::CoolantMist | MCode::CoolantFlood => EventKind::CoolantOn { m: m.number() },
                MCode::CoolantOff => EventKind::CoolantOff,
                MCode::Other(61)
                    if self.setup.settings.control == crate::setup::Control::Linuxcnc =>
                {
                    self.m61(b, b.span, out)?;
                    EventKind::Auxiliary { m: 61 }
                }
                // The calls never get here: M98/M97/M99 are taken out of
                // their block (behaviour 19.3), M198 is refused (2.18).
                MCode::LocalSubprogramCall
                | MCode::SubprogramCall
                | MCode::SubprogramReturn
                | MCode::ExternalSubprogramCall
                | MCode::Other(_) => EventKind::Auxiliary { m: m.number() },
            };
            self.event(out, kind);
        }
        Ok(())
    }

    /// The block's group 14 code, if it has one (behaviour 2.7, 13.3).
    fn work_words(&mut self, b: &Block, out: &mut Out) -> Result<(), Diagnostic> {
        match b.codes().work() {
            Some(code) => self.work_code(b, code, out),
            None => Ok(()),
        }
    }
}
