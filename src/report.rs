//! What a run reports (spec 6): per block the programmed and actual position,
//! the modal state and the offsets with a sentence saying what they did; per
//! move its kind and ends; events such as M codes and dwells.
//!
//! Positions are kept in millimetres in the current work coordinate system;
//! they are converted to the block's units when reported.

use serde::Serialize;

use crate::diag::{Diagnostic, Span};
use crate::machine::arc::Circle;
use crate::machine::modal::{Modal, Plane};
use crate::setup::{MachineKind, Units};

/// X, Y, Z (a lathe uses X as diameter and Z; Y stays 0).
pub type Xyz = [f64; 3];

/// What kind of motion a move is (spec 2).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum MoveKind {
    /// G00 positioning.
    Rapid,
    /// G01 linear cutting feed (and the feed legs of cycles).
    Feed,
    /// G02.
    ArcCw,
    /// G03.
    ArcCcw,
    /// A move caused only by an offset change, made in the current G00/G01
    /// mode (see [`Move::at_feed`]).
    Offset,
}

impl MoveKind {
    /// The name used in JSON.
    pub fn as_str(self) -> &'static str {
        match self {
            MoveKind::Rapid => "rapid",
            MoveKind::Feed => "feed",
            MoveKind::ArcCw => "arc_cw",
            MoveKind::ArcCcw => "arc_ccw",
            MoveKind::Offset => "offset",
        }
    }

    /// A number for typed arrays: 0 rapid, 1 feed, 2 arc_cw, 3 arc_ccw,
    /// 4 offset at rapid, 5 offset at feed.
    pub fn code(self, at_feed: bool) -> u8 {
        match self {
            MoveKind::Rapid => 0,
            MoveKind::Feed => 1,
            MoveKind::ArcCw => 2,
            MoveKind::ArcCcw => 3,
            MoveKind::Offset if at_feed => 5,
            MoveKind::Offset => 4,
        }
    }
}

/// The circle of an arc move, for the actual and the programmed path.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ArcInfo {
    /// The plane the arc lies in.
    pub plane: Plane,
    /// Centre of the actual arc (at the start's height along the plane's normal).
    pub center: Xyz,
    /// Centre of the programmed arc.
    pub programmed_center: Xyz,
    /// Radius of the actual arc (mm; on a lathe a radius, not a diameter).
    pub radius: f64,
    /// Radius of the programmed arc.
    pub programmed_radius: f64,
    /// Signed sweep of the actual arc in radians (positive counter-clockwise).
    pub sweep: f64,
    /// Signed sweep of the programmed arc.
    pub programmed_sweep: f64,
    /// Angle of the actual arc's start point about its centre (radians, in
    /// the plane's frame; radius space on the lathe).
    pub start_angle: f64,
    /// Angle of the programmed arc's start point.
    pub programmed_start_angle: f64,
    /// X is a diameter (lathe): the geometry is in radius space.
    pub diameter_x: bool,
}

/// One motion of the tool.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Move {
    /// Rapid, feed, arc or offset motion.
    pub kind: MoveKind,
    /// For offset motion: made at the cutting feed (G01 mode) rather than rapid.
    pub at_feed: bool,
    /// Index of the block in [`Run::blocks`].
    pub block: u32,
    /// 1-based source line.
    pub line: u32,
    /// Units of the block (reporting only; coordinates are mm).
    pub units: Units,
    /// Where the tool reference point starts (actual).
    pub from: Xyz,
    /// Where it ends (actual).
    pub to: Xyz,
    /// Start of the same motion on the programmed path.
    pub programmed_from: Xyz,
    /// End of the same motion on the programmed path.
    pub programmed_to: Xyz,
    /// Arc geometry, for arc moves.
    pub arc: Option<ArcInfo>,
}

/// Something that happens at a block besides motion.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum EventKind {
    /// M00.
    ProgramStop,
    /// M01.
    OptionalStop,
    /// M02 or M30.
    ProgramEnd {
        /// 2 or 30.
        m: u32,
    },
    /// M03.
    SpindleCw,
    /// M04.
    SpindleCcw,
    /// M05.
    SpindleStop,
    /// M19 and the oriented stop of boring cycles.
    SpindleOrient,
    /// M06 on the mill.
    ToolChange {
        /// The tool selected by T.
        tool: u32,
    },
    /// Lathe: a new tool number in a T code indexes the turret (spec 5.6).
    ToolIndex {
        /// The new tool number.
        tool: u32,
    },
    /// M07/M08.
    CoolantOn {
        /// 7 (mist) or 8 (flood).
        m: u32,
    },
    /// M09.
    CoolantOff,
    /// Any other M code, carried through.
    Auxiliary {
        /// The M code.
        m: u32,
    },
    /// G04 or a cycle's dwell at the bottom.
    Dwell {
        /// Seconds.
        seconds: f64,
    },
    /// G88: the operator retracts by hand.
    ManualRetract,
}

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

/// Tool length offset state (spec 3).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LengthState {
    /// G43 (+1), G44 (-1) or G49 (0).
    pub sign: i8,
    /// Active H number.
    pub h: u16,
    /// Value of register H as read (mm).
    pub value: f64,
    /// The Z vector the mode asks for: sign × value (mm).
    pub target: f64,
    /// The Z vector in the actual position now (mm). It differs from `target`
    /// after G28 Z, or with `length_offset_without_z = next_z`, until Z moves.
    pub vector: f64,
}

/// Tool position offset state (spec 4).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PositionState {
    /// Active (modal) D number.
    pub d: u16,
    /// Value of register D as last read (mm).
    pub value: f64,
    /// Accumulated position-offset vector (mm): actual − programmed from
    /// G45–G48 (seed 003's offset distance from the programmed end point).
    pub vector: Xyz,
}

/// Lathe T-code offset state (spec 5).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LatheState {
    /// Tool number (tt of Tttoo).
    pub tool: u32,
    /// Offset number (oo of Tttoo).
    pub offset: u16,
    /// The vector the active offset asks for (X diameter, Z; mm).
    pub target: Xyz,
    /// The vector in the actual position now (X diameter, Z; mm).
    pub vector: Xyz,
}

/// The state of the machine after a block.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BlockState {
    /// Mill or lathe.
    pub machine: MachineKind,
    /// Programmed position (mm, current work coordinates).
    pub programmed: Xyz,
    /// Actual position of the tool reference point (mm).
    pub actual: Xyz,
    /// Modal G codes.
    pub modal: Modal,
    /// Modal feed (in the block's units per minute or per revolution).
    pub feed: Option<f64>,
    /// Spindle speed word.
    pub spindle: Option<f64>,
    /// Mill: tool in the spindle (after M06) and the one selected by T.
    pub tool: u32,
    /// Mill: T selected for the next M06.
    pub next_tool: u32,
    /// Tool length offset (mill).
    pub length: LengthState,
    /// Tool position offset (mill).
    pub position: PositionState,
    /// T-code offset (lathe).
    pub lathe: LatheState,
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
    /// Index of the first move of this block in [`Run::moves`].
    pub first_move: u32,
    /// Number of moves of this block.
    pub move_count: u32,
}

impl BlockReport {
    /// One sentence saying what the offsets did in this block (spec 6).
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
    /// Stopped at the first error (spec 2), at this line.
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
    /// lathe: the offset part of T codes), ascending, without 00.
    pub registers: Vec<u16>,
    /// Number of moves (also when the moves are not kept).
    pub move_count: usize,
    /// Bounds of both paths (mm), kept as the moves are made.
    pub bounds: Option<Bounds>,
}

impl Run {
    /// True if any diagnostic is an error.
    pub fn has_errors(&self) -> bool {
        self.diagnostics.iter().any(Diagnostic::is_error)
    }

    /// Bounds of the actual and programmed paths (mm), or None without moves.
    pub fn bounds(&self) -> Option<Bounds> {
        self.bounds
    }
}

impl ArcInfo {
    /// The actual arc in plane coordinates (radius space on the lathe).
    pub fn circle(&self) -> Circle {
        self.plane_circle(self.center, self.radius, self.start_angle, self.sweep)
    }

    /// The programmed arc in plane coordinates.
    pub fn programmed_circle(&self) -> Circle {
        self.plane_circle(
            self.programmed_center,
            self.programmed_radius,
            self.programmed_start_angle,
            self.programmed_sweep,
        )
    }

    fn plane_circle(&self, c: Xyz, radius: f64, start_angle: f64, sweep: f64) -> Circle {
        let (ia, ib, _) = self.plane.axes();
        let s = |i: usize| if self.diameter_x && i == 0 { 0.5 } else { 1.0 };
        Circle {
            center: [c[ia] * s(ia), c[ib] * s(ib)],
            radius,
            start_angle,
            sweep,
        }
    }

    /// The points where the actual and the programmed arc of `m` reach their
    /// extremes along the plane's axes (for bounding boxes).
    pub fn each_extreme(&self, m: &Move, mut f: impl FnMut(Xyz)) {
        let (ia, ib, _) = self.plane.axes();
        let s = |i: usize| if self.diameter_x && i == 0 { 0.5 } else { 1.0 };
        for (circle, from) in [
            (self.circle(), m.from),
            (self.programmed_circle(), m.programmed_from),
        ] {
            for e in circle.extremes() {
                let mut p = from;
                p[ia] = e[0] / s(ia);
                p[ib] = e[1] / s(ib);
                f(p);
            }
        }
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
    /// includes a few points per move; `f64::min`'s NaN handling cost twice
    /// the instructions, callgrind). A NaN `p` is passed over as `f64::min`
    /// passes it over; the box never holds one, because it starts at a
    /// move's start, a position the machine checked finite.
    fn include(&mut self, p: Xyz) {
        for (i, &v) in p.iter().enumerate() {
            self.min[i] = if v < self.min[i] { v } else { self.min[i] };
            self.max[i] = if v > self.max[i] { v } else { self.max[i] };
        }
    }
}

/// Millimetres to `units`, rounded to a millionth of the unit so that
/// reported numbers read as written (no 64.99999999999999).
pub fn to_units(mm: f64, units: Units) -> f64 {
    round6(mm / units.mm())
}

/// Rounds to six decimals (and turns -0 into 0).
pub fn round6(v: f64) -> f64 {
    let r = (v * 1e6).round() / 1e6;
    if r == 0.0 { 0.0 } else { r }
}
