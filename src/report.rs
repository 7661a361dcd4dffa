//! What a run reports (behaviour 6): per block the programmed and actual position,
//! the modal state and the offsets with a sentence saying what they did; per
//! move its kind and ends; events such as M codes and dwells.
//!
//! Positions are kept in millimetres in the current work coordinate system;
//! they are converted to the block's units when reported.

use serde::Serialize;

use crate::diag::{Diagnostic, Span};
use crate::geometry::{Xyz, to_units};
use crate::machine::{BlockState, DataSet, EventKind, Move};
use crate::setup::{MachineKind, Units};

/// An event with its place.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Event {
    /// Index of the block in [`Run::blocks`].
    #[serde(skip)]
    pub block: u32,
    /// 1-based source line.
    pub line: u32,
    /// What happened.
    #[serde(flatten)]
    pub kind: EventKind,
}

/// The report of one executed block.
#[derive(Clone, Debug, PartialEq)]
pub struct BlockReport {
    /// Index in [`Run::blocks`].
    pub index: u32,
    /// The block's text in the program.
    pub span: Span,
    /// State after the block.
    pub state: BlockState,
    /// What the offsets did, as sentences (empty when nothing changed).
    pub notes: Vec<String>,
    /// The tool's position in machine coordinates (mm) before the block:
    /// its distance to go runs from there (behaviour 6.12).
    pub before: Xyz,
    /// Index of the first move of this block in [`Run::moves`].
    pub first_move: u32,
    /// Number of moves of this block.
    pub move_count: u32,
    /// What a G10 block set (behaviour 17.8); empty for every other block.
    pub data: Vec<DataSet>,
    /// The variables a macro statement set (behaviour 20.8).
    pub variables: Vec<crate::machine::VariableSet>,
    /// The variables the program touched up to this block, with their
    /// values after it (behaviour 21.12): None when it touched none.
    pub watch: Option<Box<crate::machine::WatchView>>,
    /// Where the block ran among subprogram calls (behaviour 19.7): None
    /// in the main program outside any call.
    pub place: Option<Box<Place>>,
}

/// Where a block ran among the subprogram calls (behaviour 19.7).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Place {
    /// The program the block is in: `O2000`, or for Haas's M97 the
    /// program and the sequence number called (`O1000 N1000`).
    pub program: String,
    /// The calls open, outermost first: each call's program and its
    /// sequence number (or line), then the program being read
    /// (`["O1000 N40", "O2000"]`).
    pub stack: Vec<String>,
    /// The program is the setup's library's (behaviour 19.10): the block's
    /// span and line are in that program's text, not the file's.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub library: bool,
}

impl BlockReport {
    /// One sentence saying what the offsets did in this block (behaviour 6.5).
    pub fn explanation(&self) -> String {
        if !self.notes.is_empty() {
            let mut s = self.notes.join("; ");
            if !s.ends_with('.') {
                s.push('.');
            }
            return s;
        }
        carried_sentence(&self.state)
    }
}

/// The sentence for a block where no offset changed.
fn carried_sentence(s: &BlockState) -> String {
    let u = s.modal.units;
    let d = u.decimals();
    let f = |mm: f64| format!("{:+.d$}", to_units(mm, u));
    let mut parts = Vec::new();
    match s.machine {
        MachineKind::Mill => {
            if s.length.vector != 0.0 {
                parts.push(format!("Z {} (H{:02})", f(s.length.vector), s.length.h));
            }
            let v = s.position.vector;
            for (i, name) in ["X", "Y", "Z"].iter().enumerate() {
                if v[i] != 0.0 {
                    parts.push(format!("{name} {} (G45–G48)", f(v[i])));
                }
            }
            let c = s.cutter.vector;
            if c != [0.0; 3] {
                let axes: Vec<String> = ["X", "Y", "Z"]
                    .iter()
                    .zip(c)
                    .filter(|(_, v)| *v != 0.0)
                    .map(|(name, v)| format!("{name} {}", f(v)))
                    .collect();
                parts.push(format!(
                    "{} ({} D{:02})",
                    axes.join(" "),
                    s.cutter.mode.gcode(),
                    s.cutter.d
                ));
            }
        }
        MachineKind::Lathe => {
            let v = s.lathe.vector;
            if v[0] != 0.0 || v[2] != 0.0 {
                parts.push(format!(
                    "X {} Z {} (T{:02}{:02})",
                    f(v[0]),
                    f(v[2]),
                    s.lathe.tool,
                    s.lathe.offset
                ));
            }
            let c = s.cutter.vector;
            if c != [0.0; 3] {
                parts.push(format!(
                    "X {} Z {} ({} nose radius, offset {:02})",
                    f(c[0]),
                    f(c[2]),
                    s.cutter.mode.gcode(),
                    s.cutter.d
                ));
            }
        }
    }
    if parts.is_empty() {
        "No offset applies: actual = programmed.".to_string()
    } else {
        format!("Offsets carried: {}.", parts.join(", "))
    }
}

/// Why execution ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(tag = "reason", rename_all = "snake_case")]
pub enum End {
    /// Ran past the last block.
    Completed,
    /// M02 or M30 at this line.
    ProgramEnd {
        /// Line of the M02/M30.
        line: u32,
    },
    /// Stopped at the first error (behaviour 2.1), at this line.
    Error {
        /// Line of the error.
        line: u32,
    },
}

/// The result of running a program.
#[derive(Clone, Debug, PartialEq)]
pub struct Run {
    /// Mill or lathe.
    pub machine: MachineKind,
    /// Units for drawing: those of the first move (without moves, those
    /// in effect at the end).
    pub units: Units,
    /// Units in effect at the end of the run (G20/G21).
    pub end_units: Units,
    /// One report per executed block (empty when run without block reports).
    pub blocks: Vec<BlockReport>,
    /// Every move, in order.
    pub moves: Vec<Move>,
    /// Events (M codes, dwells, tool changes).
    pub events: Vec<Event>,
    /// Parse and run diagnostics, sorted by place.
    pub diagnostics: Vec<Diagnostic>,
    /// Number of executed blocks (also when block reports are not kept).
    pub block_count: u32,
    /// Why execution ended.
    pub end: End,
    /// Offset registers the executed blocks name (mill: D and H numbers;
    /// lathe: the offset part of T codes) or set (G10), ascending, without
    /// 00.
    pub registers: Vec<u16>,
    /// The mill's offset memory type the run read its tables with
    /// (behaviour 17.1).
    pub offset_memory: crate::setup::OffsetMemory,
    /// The lathe's G-code system the run read its codes with (behaviour
    /// 7.18).
    pub gcode_system: crate::setup::GCodeSystem,
    /// Number of moves (also when the moves are not kept).
    pub move_count: usize,
    /// Bounds of both paths (mm), kept as the moves are made.
    pub bounds: Option<Bounds>,
    /// Path length and estimated time (behaviour 6.10).
    pub travel: crate::travel::Travel,
    /// Blocks the run could not run and passed over, with the setting
    /// `continue_past_errors` on (behaviour 2.24); each has its diagnostics.
    pub skipped: u32,
    /// The largest |radius| (mm) of cutter or nose radius compensation
    /// over the blocks that moved with it engaged, 0 without: the page's
    /// fit leaves room for the circle it draws round the tool (behaviour
    /// 10.5).
    pub cutter_reach: f64,
    /// The setup's library the run called from (behaviour 19.10): the
    /// texts of the blocks whose place says `library` (empty without one).
    pub library: std::collections::BTreeMap<u32, String>,
    /// The start and reference positions in effect (behaviour 13.16).
    pub positions: crate::setup::PositionsInEffect,
}

/// A value the program set, as it stands at the run's end: the last G10
/// that set it and where (behaviour 17.8).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SetByProgram {
    /// 1-based line of the G10 block that set it last.
    pub line: u32,
    /// Its table, entry, field, value and the value before that block.
    #[serde(flatten)]
    pub set: DataSet,
}

impl Run {
    /// The values G10 blocks set, each as the last one left it, in the
    /// order they were first set (behaviour 17.8).
    pub fn set_by_program(&self) -> Vec<SetByProgram> {
        let mut out: Vec<SetByProgram> = Vec::new();
        for e in &self.events {
            let EventKind::DataSet(set) = &e.kind else {
                continue;
            };
            let same = |s: &SetByProgram| s.set.same_entry(set);
            let entry = SetByProgram {
                line: e.line,
                set: set.clone(),
            };
            match out.iter_mut().find(|s| same(s)) {
                Some(s) => *s = entry,
                None => out.push(entry),
            }
        }
        out
    }

    /// True if any diagnostic is an error.
    pub fn has_errors(&self) -> bool {
        self.diagnostics.iter().any(Diagnostic::is_error)
    }

    /// Bounds of the actual and programmed paths (mm), or None without moves.
    pub fn bounds(&self) -> Option<Bounds> {
        self.bounds
    }
}

/// An axis-aligned box (mm).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bounds {
    /// Smallest X, Y, Z.
    pub min: Xyz,
    /// Largest X, Y, Z.
    pub max: Xyz,
}

/// Grows `b` to hold every point of a move, both paths, arcs included.
pub fn include_move(b: &mut Option<Bounds>, m: &Move) {
    let bounds = b.get_or_insert(Bounds {
        min: m.from,
        max: m.from,
    });
    each_point_of(m, |p: Xyz| bounds.include(p));
}

/// Calls `f` with the points that bound a move on both paths: its ends and,
/// for an arc, where the circles reach their extremes (mm).
pub fn each_point_of(m: &Move, mut f: impl FnMut(Xyz)) {
    for p in [m.from, m.to, m.programmed_from, m.programmed_to] {
        f(p);
    }
    if let Some(a) = &m.arc {
        a.each_extreme(m, f);
    }
}

impl Bounds {
    /// Grows the box to hold `p`: per axis `f64::min`/`f64::max` written as
    /// comparisons, which compile to one `minsd`/`maxsd` each (a run
    /// includes a few points per move; `f64::min`'s NaN handling costs
    /// more, the `check` instruction count in docs/performance.md). A NaN `p` is passed over as `f64::min`
    /// passes it over; the box never holds one, because it starts at a
    /// move's start, a position the machine checked finite.
    fn include(&mut self, p: Xyz) {
        for (i, &v) in p.iter().enumerate() {
            self.min[i] = if v < self.min[i] { v } else { self.min[i] };
            self.max[i] = if v > self.max[i] { v } else { self.max[i] };
        }
    }
}
