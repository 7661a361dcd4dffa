//! What the machine produces: the state after a block, the moves and their
//! arcs, and the events besides motion (behaviour 2). The report (`crate::report`)
//! collects these; the machine never reads the report.

use serde::Serialize;

use super::arc::Circle;
pub use super::frame::Coordinates;
use super::modal::{Modal, Plane};
use crate::geometry::Xyz;
use crate::offsets::cutter::CutterState;
use crate::offsets::lathe::LatheState;
use crate::offsets::length::LengthState;
use crate::offsets::position::PositionState;
use crate::setup::{GCodeSystem, MachineKind, Units};
use crate::syntax::codes::CodeTable;

/// What kind of motion a move is (behaviour 2).
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
        Circle {
            center: self.in_plane(c),
            radius,
            start_angle,
            sweep,
        }
    }

    /// A point of the program in the arc's plane coordinates (radius space
    /// on the lathe).
    pub fn in_plane(&self, p: Xyz) -> crate::machine::arc::P2 {
        let (ia, ib, _) = self.plane.axes();
        let s = |i: usize| if self.diameter_x && i == 0 { 0.5 } else { 1.0 };
        [p[ia] * s(ia), p[ib] * s(ib)]
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

/// One motion of the tool.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Move {
    /// Rapid, feed, arc or offset motion.
    pub kind: MoveKind,
    /// For offset motion: made at the cutting feed (G01 mode) rather than rapid.
    pub at_feed: bool,
    /// Index of the block in [`crate::Run::blocks`].
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
    /// Lathe: a new tool number in a T code indexes the turret (behaviour 5.6).
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
    /// G10: a value of the offset tables or the work offsets set by the
    /// program (behaviour 17.8).
    DataSet(DataSet),
    /// A macro statement set a variable (behaviour 20.8).
    VariableSet(VariableSet),
}

/// A variable a macro statement set (behaviour 20.8).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct VariableSet {
    /// Its number (`101` for `#101`).
    pub variable: u32,
    /// Its new value (None: vacant).
    pub value: Option<f64>,
    /// Its value before the block (None: vacant).
    pub was: Option<f64>,
}

/// One value a G10 block set (behaviour 17.8), named as the setup document
/// names it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct DataSet {
    /// The setup document's table: `offsets`, `lathe_offsets`,
    /// `work_offsets` or `extended_work_offsets`.
    pub table: &'static str,
    /// The entry in it: `"01"`, `"G54"`, `"EXT"`.
    pub key: String,
    /// The field: mill `value` (offset memory A), `geometry`/`wear` (B),
    /// `h_geometry`/`h_wear`/`d_geometry`/`d_wear` (C); lathe `x`, `z`,
    /// `r`, `x_wear`, `z_wear`, `r_wear`, `t`; work offsets `x`, `y`, `z`.
    pub field: &'static str,
    /// The new value, as the document holds it (registers as numbers, work
    /// offsets in the setup's units).
    pub value: f64,
    /// The value before.
    pub was: f64,
}

impl DataSet {
    /// True when `other` sets the same entry and field (a later one
    /// replaces it in what the program set, the summary's `set_by_program`).
    pub fn same_entry(&self, other: &DataSet) -> bool {
        (self.table, &self.key, self.field) == (other.table, &other.key, other.field)
    }
}

/// The state of the machine after a block.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BlockState {
    /// Mill or lathe.
    pub machine: MachineKind,
    /// The lathe's G-code system (how its codes are written back).
    pub system: GCodeSystem,
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
    /// Lathe: the spindle speed limit of G50 S (G92 S in G-code systems
    /// B/C), which constant surface speed keeps under.
    pub spindle_limit: Option<f64>,
    /// Mill: tool in the spindle (after M06) and the one selected by T.
    pub tool: u32,
    /// Mill: T selected for the next M06.
    pub next_tool: u32,
    /// Tool length offset (mill).
    pub length: LengthState,
    /// LinuxCNC: the radius (mm) G41/G42 took from the tool table, or
    /// G41.1/G42.1 from D (behaviour 22.9); None reads register D.
    pub table_radius: Option<f64>,
    /// Tool position offset (mill).
    pub position: PositionState,
    /// Cutter radius compensation (mill).
    pub cutter: CutterState,
    /// T-code offset (lathe).
    pub lathe: LatheState,
    /// Where the current coordinate system lies on the machine (behaviour
    /// 13).
    pub coords: Coordinates,
    /// The rotary axes A, B, C (degrees), once a block names them: reported,
    /// not drawn (behaviour 13.14).
    pub rotary: [Option<f64>; 3],
    /// Lathe: polar coordinate interpolation in force, with the C axis's
    /// turn (behaviour 14.11, 14.16).
    pub polar: Option<PolarState>,
}

/// Polar coordinate interpolation in force (lathe, behaviour 14.15–14.17):
/// the positions are the face plane's — X (a diameter-valued coordinate,
/// as everywhere on the lathe) and the hypothetical axis as Y — and the
/// machine turns C and moves X to follow them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PolarState {
    /// How far the C axis has turned since G12.1 (radians, counter-clockwise
    /// seen from the tailstock, unwound: one and a half turns is 3π).
    pub angle: f64,
    /// The X part of the T vector the tool carried at G12.1 (mm, a
    /// diameter): it acts along the machine's X axis, which turns with C
    /// in the face plane (behaviour 14.17).
    pub x_offset: f64,
}

impl PolarState {
    /// The offset vector in the face plane at the C angle `angle` (mm, X
    /// diameter-valued, the hypothetical axis as Y), with the Z part `z`.
    pub fn vector(&self, angle: f64, z: f64) -> Xyz {
        let (sin, cos) = angle.sin_cos();
        [self.x_offset * cos, self.x_offset / 2.0 * sin, z]
    }

    /// Where the machine's X axis stands for the face point of `programmed`
    /// (mm, a diameter): twice its distance from the spindle axis, plus the
    /// X offset.
    pub fn machine_x(&self, programmed: Xyz) -> f64 {
        2.0 * (programmed[0] / 2.0).hypot(programmed[1]) + self.x_offset
    }
}

impl BlockState {
    /// The modal codes as the manuals write them, group 07 included (its
    /// mode is the cutter or nose radius compensation's state).
    pub fn modal_codes(&self) -> super::modal::ModalCodes {
        let mut codes = self.modal.codes(self.table());
        codes.cutter = Some(self.cutter.mode.gcode());
        codes
    }

    /// The actual position in machine coordinates (mm): where the machine's
    /// axes stand (behaviour 13.1).
    pub fn machine_position(&self) -> Xyz {
        match &self.polar {
            // The face plane's point is the machine's X and C (behaviour 14.16).
            Some(p) => [
                p.machine_x(self.programmed) + self.coords.zero[0],
                0.0,
                self.actual[2] + self.coords.zero[2],
            ],
            None => crate::geometry::add(self.actual, self.coords.zero),
        }
    }

    /// The table the block's codes are written back with.
    pub fn table(&self) -> CodeTable {
        CodeTable::new(self.machine, self.system)
    }
}
