//! The serialisable face of a run: the JSON the CLI prints and the objects
//! the page receives through serde-wasm-bindgen are the same structures, so
//! the two never disagree. Positions are converted to the block's units and
//! rounded to a millionth; a lathe position has `x` (diameter) and `z` only.

use serde::Serialize;
use serde::ser::{SerializeStruct, Serializer};

use crate::diag::{Diagnostic, Severity};
use crate::geometry::{Xyz, round6, to_units};
use crate::machine::DataSet;
use crate::machine::modal::ModalCodes;
use crate::machine::{Move, MoveKind};
use crate::report::{BlockReport, End, Event, Run, SetByProgram};
use crate::setup::{MachineKind, Units};

/// A position in the units of its block.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Pos {
    /// X (a diameter on the lathe).
    pub x: f64,
    /// Y (absent on the lathe).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub y: Option<f64>,
    /// Z.
    pub z: f64,
}

/// Converts a position (mm) for reporting. A lathe position has a `y` only
/// off the XZ plane: in polar coordinate interpolation, where Y is the
/// hypothetical axis of the face plane (behaviour 6.2, 14.16).
pub fn pos(p: Xyz, units: Units, machine: MachineKind) -> Pos {
    let y = to_units(p[1], units);
    Pos {
        x: to_units(p[0], units),
        y: (machine == MachineKind::Mill || y != 0.0).then_some(y),
        z: to_units(p[2], units),
    }
}

/// Tool length offset of a block (mill).
#[derive(Clone, Copy, Debug, Serialize)]
pub struct LengthView {
    /// G43, G44 or G49.
    pub mode: &'static str,
    /// Active H number.
    pub h: u16,
    /// Value of register H.
    pub value: f64,
    /// The Z vector in the actual position.
    pub vector: f64,
    /// The Z vector the mode asks for (differs from `vector` until the next Z
    /// move after G28 Z or with `length_offset_without_z = next_z`).
    pub target: f64,
}

/// Tool position offset of a block (mill).
#[derive(Clone, Copy, Debug, Serialize)]
pub struct PositionView {
    /// Active (modal) D number.
    pub d: u16,
    /// Value of register D.
    pub value: f64,
    /// The accumulated position-offset vector (seed 003: offset distance
    /// from the programmed end point).
    pub vector: Pos,
}

/// Cutter radius compensation of a block (mill, behaviour 16).
#[derive(Clone, Copy, Debug, Serialize)]
pub struct CutterView {
    /// G40, G41 or G42.
    pub mode: &'static str,
    /// The D number the radius was read from (lathe: the T code's offset
    /// number).
    pub d: u16,
    /// Value of register D (a negative value swaps the side; lathe: the
    /// offset's nose radius, behaviour 18).
    pub radius: f64,
    /// Lathe: the imaginary tool nose direction 0–9 (behaviour 18.2).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tip: Option<u8>,
    /// The block's role: `cancel` (cancel mode), `start_up`, `offset`
    /// (offset mode) or `cancelling` (this block cancelled).
    pub phase: &'static str,
    /// The offset vector at the block's end: actual − programmed from the
    /// compensation.
    pub vector: Pos,
}

/// Lathe T-code offset of a block.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct LatheView {
    /// Tool number.
    pub tool: u32,
    /// Offset number.
    pub offset: u16,
    /// The vector of the active offset (X diameter, Z).
    pub value: Pos,
    /// The vector in the actual position.
    pub vector: Pos,
}

/// Where the block's coordinate system lies on the machine (behaviour 13):
/// its zero in machine coordinates and the parts beyond the work system's
/// own zero.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct CoordinatesView {
    /// The zero of the coordinate system the positions are in, in machine
    /// coordinates (the work offset, the G92/G50 shift and the G52 local
    /// offset added).
    pub zero: Pos,
    /// The G92 (lathe G50) shift.
    pub shift: Pos,
    /// The G52 local offset: the local zero in the work system.
    pub local: Pos,
}

/// The mill's programmable mirror image (G51.1): each axis's mirror
/// coordinate, or null.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct MirrorView {
    /// X is mirrored about this X.
    pub x: Option<f64>,
    /// Y is mirrored about this Y.
    pub y: Option<f64>,
    /// Z is mirrored about this Z.
    pub z: Option<f64>,
}

/// G51 scaling.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct ScalingView {
    /// The centre.
    pub center: Pos,
    /// The factor of each axis.
    pub factors: Pos,
}

/// G68 rotation.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct RotationView {
    /// G17, G18 or G19.
    pub plane: &'static str,
    /// The centre.
    pub center: Pos,
    /// The angle, degrees counter-clockwise.
    pub degrees: f64,
}

/// The mill's transformations in force (behaviour 13.8–13.10).
#[derive(Clone, Copy, Debug, Serialize)]
pub struct TransformsView {
    /// G51.1.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mirror: Option<MirrorView>,
    /// G51.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub scaling: Option<ScalingView>,
    /// G68.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rotation: Option<RotationView>,
}

/// Polar coordinate interpolation on the lathe (behaviour 14.16): where the
/// machine's axes stand for the block's face point.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct PolarView {
    /// How far the C axis has turned since G12.1, degrees
    /// (counter-clockwise seen from the tailstock).
    pub c: f64,
    /// The machine's X (a diameter, as the lathe shows X): the actual
    /// point's distance from the spindle axis, doubled.
    pub x: f64,
    /// The same as a radius.
    pub radius: f64,
}

/// The rotary axes a program named (degrees): reported, not drawn
/// (behaviour 13.14).
#[derive(Clone, Copy, Debug, Serialize)]
pub struct RotaryView {
    /// A.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub a: Option<f64>,
    /// B.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub b: Option<f64>,
    /// C.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub c: Option<f64>,
}

/// One block as reported.
#[derive(Clone, Debug, Serialize)]
pub struct BlockView<'a> {
    /// Index in the run's blocks.
    pub index: u32,
    /// 1-based line.
    pub line: u32,
    /// 1-based column of the block's first character.
    pub column: u32,
    /// Column one past its last character.
    pub end_column: u32,
    /// The block's text.
    pub text: &'a str,
    /// Units of the block ("mm" or "inch").
    pub units: &'static str,
    /// Programmed position after the block.
    pub programmed: Pos,
    /// Actual position after the block.
    pub actual: Pos,
    /// The actual position in machine coordinates (behaviour 13.1).
    pub machine: Pos,
    /// The block's motion as the control's distance to go shows it when
    /// the block starts: its position after it less its position before
    /// it, along the machine's axes (behaviour 6.12).
    pub distance_to_go: Pos,
    /// Where the coordinate system lies on the machine.
    pub coordinates: CoordinatesView,
    /// Mill: the transformations in force, absent when none is.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub transforms: Option<TransformsView>,
    /// Mill: the rotary axes, absent until a block names one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rotary: Option<RotaryView>,
    /// Lathe: the machine's C and X in polar coordinate interpolation,
    /// absent outside it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub polar: Option<PolarView>,
    /// Modal codes after the block.
    pub modal: ModalCodes,
    /// Modal feed.
    pub feed: Option<f64>,
    /// Spindle speed word.
    pub spindle: Option<f64>,
    /// Tool (mill: in the spindle after M06; lathe: of the T code).
    pub tool: u32,
    /// Mill: tool length offset.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub length_offset: Option<LengthView>,
    /// Mill: tool position offset.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub position_offset: Option<PositionView>,
    /// Cutter radius compensation (mill), tool nose radius compensation
    /// (lathe).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cutter: Option<CutterView>,
    /// Lathe: T-code offset.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lathe_offset: Option<LatheView>,
    /// What the offsets did (behaviour 6.5).
    pub explanation: String,
    /// Index of the block's first move.
    pub first_move: u32,
    /// Number of moves of the block.
    pub move_count: u32,
    /// G10: the values the block set, absent for every other block
    /// (behaviour 17.8).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub data_set: Vec<DataSet>,
    /// The variables a macro statement set, absent for every other block
    /// (behaviour 20.8).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub variables_set: Vec<crate::machine::VariableSet>,
    /// The variables the program read or set up to this block, with their
    /// values after it and the line that last set each (behaviour 21.12);
    /// absent in a program without `#`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub watch: Option<crate::machine::WatchView>,
    /// The program the block ran in, inside a subprogram call (behaviour
    /// 19.7); absent in the main program outside calls.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub program: Option<String>,
    /// The calls open (outermost first) and the program being read; empty
    /// outside calls.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub stack: Vec<String>,
    /// The program is the setup's library's: `line`, `column` and `text`
    /// are in its text (behaviour 19.10); absent otherwise.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub library: bool,
}

/// Builds the report of one block.
pub fn block_view<'a>(b: &BlockReport, text: &'a str) -> BlockView<'a> {
    block_view_at(b, text, b.span.columns(text))
}

/// The text block `b` was read from: the file's `text`, or for a block
/// of a library program (behaviour 19.10) that program's text in
/// `library` (its place's program, `O1002` or Haas's `O1002 N100`).
pub fn text_of<'a>(
    b: &BlockReport,
    text: &'a str,
    library: &'a std::collections::BTreeMap<u32, String>,
) -> &'a str {
    let Some(place) = b.place.as_deref().filter(|p| p.library) else {
        return text;
    };
    let digits = place.program.get(1..).unwrap_or("");
    let digits = &digits[..digits.bytes().take_while(u8::is_ascii_digit).count()];
    digits
        .parse::<u32>()
        .ok()
        .and_then(|n| library.get(&n))
        .map_or(text, String::as_str)
}

/// The reports of every block of a run, in order, their columns found in
/// one pass over the text (a [`block_view`] per block scans back to the
/// line's start each time: quadratic on a long line of `;`-separated
/// blocks).
pub fn block_views<'a>(run: &'a Run, text: &'a str) -> impl Iterator<Item = BlockView<'a>> + 'a {
    let mut viewer = BlockViewer::new(text, &run.library);
    run.blocks.iter().map(move |b| viewer.view(b))
}

/// Makes the reports of a run's blocks one at a time, in run order, as
/// [`block_views`] does: for a run whose reports are taken as they are made
/// ([`crate::Observer::takes_reports`]), where the run keeps none.
pub struct BlockViewer<'a> {
    text: &'a str,
    library: &'a std::collections::BTreeMap<u32, String>,
    columns: crate::diag::Columns<'a>,
}

impl<'a> BlockViewer<'a> {
    /// For the blocks of `text` and of the `library` programs it calls
    /// (the setup's programs, behaviour 19.10).
    pub fn new(text: &'a str, library: &'a std::collections::BTreeMap<u32, String>) -> Self {
        BlockViewer {
            text,
            library,
            columns: crate::diag::Columns::new(text),
        }
    }

    /// The report of the next block.
    pub fn view(&mut self, b: &BlockReport) -> BlockView<'a> {
        match b.place.as_deref().is_some_and(|p| p.library) {
            true => {
                let own = text_of(b, self.text, self.library);
                block_view_at(b, own, b.span.columns(own))
            }
            false => block_view_at(b, self.text, self.columns.of(b.span)),
        }
    }
}

/// [`block_view`] with the block's columns already known.
fn block_view_at<'a>(b: &BlockReport, text: &'a str, columns: (u32, u32)) -> BlockView<'a> {
    let s = &b.state;
    let u = s.modal.units;
    let m = s.machine;
    let (column, end_column) = columns;
    let mill = m == MachineKind::Mill;
    let start = (b.span.start as usize).min(text.len());
    let end = (b.span.end as usize).clamp(start, text.len());
    BlockView {
        index: b.index,
        line: b.span.line,
        column,
        end_column,
        text: text.get(start..end).unwrap_or(""),
        units: u.as_str(),
        programmed: pos(s.programmed, u, m),
        actual: pos(s.actual, u, m),
        machine: pos(s.machine_position(), u, m),
        distance_to_go: pos(crate::geometry::sub(s.machine_position(), b.before), u, m),
        coordinates: CoordinatesView {
            zero: pos(s.coords.zero, u, m),
            shift: pos(s.coords.shift, u, m),
            local: pos(s.coords.local, u, m),
        },
        transforms: transforms_view(s),
        rotary: (s.rotary != [None; 3]).then_some(RotaryView {
            a: s.rotary[0].map(round6),
            b: s.rotary[1].map(round6),
            c: s.rotary[2].map(round6),
        }),
        polar: s.polar.map(|p| {
            let x = p.machine_x(s.programmed);
            PolarView {
                c: round6(p.angle.to_degrees()),
                x: to_units(x, u),
                radius: to_units(x / 2.0, u),
            }
        }),
        modal: s.modal_codes(),
        feed: s.feed,
        spindle: s.spindle,
        tool: if mill { s.tool } else { s.lathe.tool },
        length_offset: mill.then(|| LengthView {
            mode: match s.length.sign {
                1 => "G43",
                -1 => "G44",
                _ => "G49",
            },
            h: s.length.h,
            value: to_units(s.length.value, u),
            vector: to_units(s.length.vector, u),
            target: to_units(s.length.target, u),
        }),
        position_offset: mill.then(|| PositionView {
            d: s.position.d,
            value: to_units(s.position.value, u),
            vector: pos(s.position.vector, u, m),
        }),
        cutter: Some(CutterView {
            mode: s.cutter.mode.gcode(),
            d: s.cutter.d,
            radius: to_units(s.cutter.radius, u),
            tip: s.cutter.tip,
            phase: s.cutter.phase.as_str(),
            vector: pos(s.cutter.vector, u, m),
        }),
        lathe_offset: (!mill).then(|| LatheView {
            tool: s.lathe.tool,
            offset: s.lathe.offset,
            value: pos(s.lathe.target, u, m),
            vector: pos(s.lathe.vector, u, m),
        }),
        explanation: b.explanation(),
        first_move: b.first_move,
        move_count: b.move_count,
        data_set: b.data.clone(),
        variables_set: b.variables.clone(),
        watch: b.watch.as_deref().cloned(),
        program: b.place.as_ref().map(|p| p.program.clone()),
        stack: b
            .place
            .as_ref()
            .map(|p| p.stack.clone())
            .unwrap_or_default(),
        library: b.place.as_ref().is_some_and(|p| p.library),
    }
}

/// The transformations of a block's state, if any is on.
fn transforms_view(s: &crate::machine::BlockState) -> Option<TransformsView> {
    let t = &s.modal.transforms;
    if t.is_identity() {
        return None;
    }
    let (u, m) = (s.modal.units, s.machine);
    let mm = |v: Option<f64>| v.map(|v| to_units(v, u));
    Some(TransformsView {
        mirror: (t.mirror != [None; 3]).then_some(MirrorView {
            x: mm(t.mirror[0]),
            y: mm(t.mirror[1]),
            z: mm(t.mirror[2]),
        }),
        scaling: t.scaling.map(|sc| ScalingView {
            center: pos(sc.center, u, m),
            factors: Pos {
                x: round6(sc.factors[0]),
                y: Some(round6(sc.factors[1])),
                z: round6(sc.factors[2]),
            },
        }),
        rotation: t.rotation.map(|r| RotationView {
            plane: r.plane.gcode(),
            center: pos(r.center, u, m),
            degrees: round6(r.degrees),
        }),
    })
}

/// The circle of an arc move as reported.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct ArcView {
    /// G17, G18 or G19.
    pub plane: &'static str,
    /// "cw" or "ccw" (of the actual arc).
    pub direction: &'static str,
    /// Centre of the actual arc.
    pub center: Pos,
    /// Radius of the actual arc.
    pub radius: f64,
    /// Centre of the programmed arc.
    pub programmed_center: Pos,
    /// Radius of the programmed arc.
    pub programmed_radius: f64,
    /// Swept angle of the actual arc, degrees (positive counter-clockwise).
    pub sweep_degrees: f64,
}

/// One move as reported.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct MoveView {
    /// 1-based line of its block.
    pub line: u32,
    /// Index of its block.
    pub block: u32,
    /// rapid, feed, arc_cw, arc_ccw or offset.
    pub kind: MoveKind,
    /// For offset motion: "rapid" (G00 mode) or "feed" (G01 mode).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rate: Option<&'static str>,
    /// Actual start.
    pub from: Pos,
    /// Actual end.
    pub to: Pos,
    /// Programmed start.
    pub programmed_from: Pos,
    /// Programmed end.
    pub programmed_to: Pos,
    /// Arc geometry.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub arc: Option<ArcView>,
}

/// Builds the report of one move.
pub fn move_view(m: &Move, machine: MachineKind) -> MoveView {
    let u = m.units;
    let p = |x: Xyz| pos(x, u, machine);
    MoveView {
        line: m.line,
        block: m.block,
        kind: m.kind,
        rate: (m.kind == MoveKind::Offset).then_some(if m.at_feed { "feed" } else { "rapid" }),
        from: p(m.from),
        to: p(m.to),
        programmed_from: p(m.programmed_from),
        programmed_to: p(m.programmed_to),
        arc: m.arc.map(|a| ArcView {
            plane: a.plane.gcode(),
            direction: if a.sweep > 0.0 { "ccw" } else { "cw" },
            center: p(a.center),
            radius: to_units(a.radius, u),
            programmed_center: p(a.programmed_center),
            programmed_radius: to_units(a.programmed_radius, u),
            sweep_degrees: round6(a.sweep.to_degrees()),
        }),
    }
}

/// Bounds of the actual path.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct BoundsView {
    /// Smallest coordinates.
    pub min: Pos,
    /// Largest coordinates.
    pub max: Pos,
}

/// Counts and bounds of a run.
#[derive(Clone, Debug, Serialize)]
pub struct Summary {
    /// Mill or lathe.
    pub machine: MachineKind,
    /// Units of the drawing and of the bounds.
    pub units: Units,
    /// Executed blocks.
    pub blocks: u32,
    /// Moves.
    pub moves: usize,
    /// Error diagnostics.
    pub errors: usize,
    /// Warning diagnostics.
    pub warnings: usize,
    /// Why execution ended.
    pub end: End,
    /// Bounds of the actual and programmed paths together.
    pub bounds: Option<BoundsView>,
    /// Offset registers the program names (mill D/H, lathe T offset
    /// numbers) or sets (G10).
    pub registers: Vec<u16>,
    /// Mill: the offset memory type the tables were read with, `A`, `B` or
    /// `C` (behaviour 17.1); absent on the lathe.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub offset_memory: Option<&'static str>,
    /// Lathe: the G-code system the codes were read in, `A`, `B` or `C`
    /// (behaviour 7.18); absent on the mill.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gcode_system: Option<&'static str>,
    /// The values G10 blocks set, each with the line of the last block that
    /// set it (behaviour 17.8).
    pub set_by_program: Vec<SetByProgram>,
    /// Path length (in `units`) and the time estimate (behaviour 6.10).
    pub travel: TravelView,
    /// Blocks passed over with setting `continue_past_errors` on (behaviour
    /// 2.24); each has a `block-skipped` warning beside its error.
    pub skipped: u32,
    /// The other machine, when the program's words belong to it and none to
    /// this one (behaviour 1.24); set by those who hold the text
    /// ([`Summary::with_hint`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub machine_hint: Option<HintView>,
    /// The start and reference positions the run used, in the setup's
    /// units (behaviour 13.16).
    pub positions: crate::setup::PositionsInEffect,
}

/// How far the tool went and how long it took (behaviour 6.10).
#[derive(Clone, Copy, Debug, Serialize)]
pub struct TravelView {
    /// Length of the rapid moves, in the summary's units.
    pub rapid: f64,
    /// Length of the feed moves, in the summary's units.
    pub feed: f64,
    /// Estimated cycle time, seconds (rapids at the setup's rapid rate,
    /// feeds at F, dwells).
    pub seconds: f64,
    /// Of that, dwells.
    pub dwell: f64,
    /// Feed moves that had no rate (no F, or per revolution without S),
    /// left out of `seconds`.
    pub untimed: u32,
}

/// The machine a program reads as, and why (behaviour 1.24).
#[derive(Clone, Debug, Serialize)]
pub struct HintView {
    /// `mill` or `lathe`.
    pub machine: MachineKind,
    /// What in the program says so.
    pub reasons: Vec<&'static str>,
}

impl Summary {
    /// The summary with the machine `text` reads as, if not this one.
    pub fn with_hint(mut self, text: &str) -> Summary {
        self.machine_hint = crate::syntax::machine_hint(text, self.machine).map(|h| HintView {
            machine: h.machine,
            reasons: h.reasons,
        });
        self
    }
}

/// The summary of a run.
pub fn summary(run: &Run) -> Summary {
    let count = |s: Severity| run.diagnostics.iter().filter(|d| d.severity == s).count();
    Summary {
        machine: run.machine,
        units: run.units,
        blocks: run.block_count,
        moves: run.move_count,
        errors: count(Severity::Error),
        warnings: count(Severity::Warning),
        end: run.end,
        bounds: run.bounds().map(|b| BoundsView {
            min: pos(b.min, run.units, run.machine),
            max: pos(b.max, run.units, run.machine),
        }),
        registers: run.registers.clone(),
        offset_memory: (run.machine == MachineKind::Mill).then(|| run.offset_memory.as_str()),
        gcode_system: (run.machine == MachineKind::Lathe).then(|| run.gcode_system.as_str()),
        set_by_program: run.set_by_program(),
        travel: TravelView {
            rapid: to_units(run.travel.rapid, run.units),
            feed: to_units(run.travel.feed, run.units),
            seconds: (run.travel.seconds * 1000.0).round() / 1000.0,
            dwell: (run.travel.dwell * 1000.0).round() / 1000.0,
            untimed: run.travel.untimed,
        },
        skipped: run.skipped,
        machine_hint: None,
        positions: run.positions,
    }
}

/// The whole run as the CLI's JSON object; blocks and moves are serialised
/// one at a time, never collected.
pub struct RunView<'a> {
    /// The run.
    pub run: &'a Run,
    /// The program text it was made from.
    pub text: &'a str,
}

struct Blocks<'a>(&'a Run, &'a str);
struct Moves<'a>(&'a Run);

impl Serialize for Blocks<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_seq(block_views(self.0, self.1))
    }
}

impl Serialize for Moves<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_seq(self.0.moves.iter().map(|m| move_view(m, self.0.machine)))
    }
}

impl Serialize for RunView<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut st = s.serialize_struct("Run", 6)?;
        st.serialize_field("summary", &summary(self.run).with_hint(self.text))?;
        st.serialize_field("blocks", &Blocks(self.run, self.text))?;
        st.serialize_field("moves", &Moves(self.run))?;
        st.serialize_field("events", &self.run.events as &[Event])?;
        st.serialize_field("diagnostics", &self.run.diagnostics as &[Diagnostic])?;
        st.end()
    }
}
