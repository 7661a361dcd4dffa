//! The toolpath for drawing: struct-of-arrays, a few dozen bytes per move.
//! Each move adds its end point to the vertex arrays (and its start point
//! first when it does not start where the previous move ended, both paths
//! alike), so the actual and the programmed path have the same vertices and
//! vertex `i` of one corresponds to vertex `i` of the other. Arcs are kept
//! as circles, not as polylines: whoever draws them tessellates them for the
//! scale they are drawn at ([`Toolpath::for_each_point`]), so a million
//! small arcs cost a few points each at full view and stay smooth when
//! zoomed in. Coordinates are in the run's display units ([`Run::units`]);
//! on the lathe X stays a diameter.
//!
//! It stays in the core: the page's session draws it where it is kept
//! (the worker's canvas), so it never crosses the wasm boundary.

mod builder;
#[cfg(test)]
mod tests;

pub use builder::PathBuilder;

use std::ops::Range;
use std::sync::Mutex;

use crate::geometry::Xyz;
use crate::machine::Move;
use crate::machine::arc::Circle;
use crate::machine::modal::Plane;
use crate::report::Run;
use crate::setup::{MachineKind, Units};

pub use crate::machine::arc::CHORD_TOLERANCE_MM as CHORD_TOLERANCE;

/// The circle of an arc move on both paths, in the toolpath's units (plane
/// coordinates; on the lathe X in radius, as [`crate::machine::ArcInfo`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ToolArc {
    /// The plane of the arc.
    pub plane: Plane,
    /// X is a diameter (lathe): the circle's first coordinate is X / 2.
    pub diameter_x: bool,
    /// The actual circle.
    pub actual: Circle,
    /// The programmed circle.
    pub programmed: Circle,
}

impl ToolArc {
    /// Segments for a chord error under `tolerance` on both circles.
    pub fn segments(&self, tolerance: f64) -> usize {
        self.actual
            .segments(tolerance)
            .max(self.programmed.segments(tolerance))
    }

    /// The circle of one path, the plane's axes (first, second, normal)
    /// and per axis what a plane coordinate is of the axis's (X / 2 on a
    /// lathe, whose X is a diameter).
    fn circle(&self, programmed: bool) -> (&Circle, (usize, usize, usize), impl Fn(usize) -> f64) {
        let c = if programmed {
            &self.programmed
        } else {
            &self.actual
        };
        let x = if self.diameter_x { 0.5 } else { 1.0 };
        (
            c,
            self.plane.axes(),
            move |axis| if axis == 0 { x } else { 1.0 },
        )
    }

    /// The plane's axes as vectors of the toolpath's space: a plane
    /// coordinate of 1 along its first and its second axis (on the lathe
    /// X / 2 is the plane coordinate), and 1 along its normal.
    pub fn frame(&self) -> [Xyz; 3] {
        let (_, (ia, ib, n), s) = self.circle(false);
        let mut axes = [[0.0; 3]; 3];
        axes[0][ia] = 1.0 / s(ia);
        axes[1][ib] = 1.0 / s(ib);
        axes[2][n] = 1.0;
        axes
    }

    /// The centre of one path's circle as a point (its normal coordinate
    /// `at`'s), and the circle's signed sweep (radians, positive from the
    /// plane's first axis towards its second).
    pub fn centre_and_sweep(&self, programmed: bool, at: Xyz) -> (Xyz, f64) {
        let (c, (ia, ib, _), s) = self.circle(programmed);
        let mut centre = at;
        centre[ia] = c.center[0] / s(ia);
        centre[ib] = c.center[1] / s(ib);
        (centre, c.sweep)
    }

    /// Point `i` of `count` along the arc from `from` to `to` (`i` = 0 is
    /// `from`, `count` is `to`); the axis normal to the plane moves linearly
    /// (a helix).
    fn point(&self, programmed: bool, from: Xyz, to: Xyz, i: usize, count: usize) -> Xyz {
        if i == 0 {
            return from;
        }
        if i >= count {
            return to;
        }
        let (c, (ia, ib, n), s) = self.circle(programmed);
        let t = i as f64 / count as f64;
        let q = c.point(t);
        let mut p = from;
        p[ia] = q[0] / s(ia);
        p[ib] = q[1] / s(ib);
        p[n] = from[n] + (to[n] - from[n]) * t;
        p
    }

    /// `f(i, point(programmed, from, to, i, count))` for `i` = 0 to
    /// `count`, the points between the ends placed as
    /// [`ArcPoints::Rotated`] says.
    fn rotated_points(
        &self,
        programmed: bool,
        (from, to): (Xyz, Xyz),
        count: usize,
        mut f: impl FnMut(usize, Xyz),
    ) {
        let (c, (ia, ib, n), s) = self.circle(programmed);
        let (step_sin, step_cos) = (c.sweep / count as f64).sin_cos();
        let (mut sin, mut cos) = c.start_angle.sin_cos();
        f(0, from);
        for i in 1..count {
            (cos, sin) = (
                cos * step_cos - sin * step_sin,
                sin * step_cos + cos * step_sin,
            );
            let t = i as f64 / count as f64;
            let mut p = from;
            p[ia] = (c.center[0] + c.radius * cos) / s(ia);
            p[ib] = (c.center[1] + c.radius * sin) / s(ib);
            p[n] = from[n] + (to[n] - from[n]) * t;
            f(i, p);
        }
        f(count.max(1), to);
    }
}

/// What [`Toolpath::visit`] shows of a move.
#[derive(Clone, Copy, Debug)]
pub enum Visit<'a> {
    /// Point `i` of the move (0: its start).
    Point(usize, Xyz),
    /// The whole of an arc move, after its start: its circles, which path,
    /// its ends, and the segments [`Toolpath::for_each_point`] would make
    /// of it.
    Arc {
        /// Its circles.
        arc: &'a ToolArc,
        /// Which of them: the programmed path's or the actual one's.
        programmed: bool,
        /// Its start.
        from: Xyz,
        /// Its end.
        to: Xyz,
        /// How many segments make it.
        count: usize,
    },
}

/// How [`Toolpath::for_each_point`] places the points of an arc.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ArcPoints {
    /// Each from its angle's sine and cosine ([`Circle::point`]): what the
    /// vector outputs (SVG) are made of.
    Exact,
    /// Each by turning the last one through the step's angle: within about
    /// 1e-13 of the radius of the exact points (each turn rounds by about
    /// 1e-16, at most 1024 turns), which no pixel shows. For a pixel
    /// layer: a sine and a cosine per point were a share of a
    /// million-block frame worth saving (bench-browser target 3 and
    /// `examples/render_time` guard the choice).
    Rotated,
}

/// Drawable toolpath.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Toolpath {
    /// Units of every coordinate.
    pub units: Units,
    /// Mill or lathe (the lathe's X is a diameter).
    pub machine: MachineKind,
    /// Actual path vertices, x y z interleaved.
    pub actual: Vec<f64>,
    /// Programmed path vertices, x y z interleaved, same count as `actual`.
    pub programmed: Vec<f64>,
    /// Per move: index of its start vertex; it ends at the next one.
    pub starts: Vec<u32>,
    /// Per move: [`crate::MoveKind::code`] (0 rapid, 1 feed, 2 arc cw,
    /// 3 arc ccw, 4 offset at rapid, 5 offset at feed).
    pub kinds: Vec<u8>,
    /// Per move: index of its block.
    pub blocks: Vec<u32>,
    /// Per move: 1-based source line.
    pub lines: Vec<u32>,
    /// The circles of the arc moves, in move order.
    pub arcs: Vec<ToolArc>,
    /// Per arc: its move.
    pub arc_moves: Vec<u32>,
    /// Bounds of both paths, arcs included: (min, max).
    bounds: Option<(Xyz, Xyz)>,
    /// Millimetres to `units`.
    k: f64,
    /// Answers worked out from every move ([`Toolpath::remembered`]).
    memo: Memo,
}

/// How many answers [`Toolpath::remembered`] keeps.
pub const MEMO_SLOTS: usize = 3;

/// Answers about the whole path, each worked out once by a walk over every
/// move and kept while the path has that many moves: a toolpath only ever
/// grows at its end ([`Toolpath::push`], [`Toolpath::append_moves`]), so an
/// answer about the moves it had is still about them. The view asks some of
/// them for every step of a pan or zoom gesture, whose steps come faster
/// than a walk over a large path's moves. Not part of the path: two
/// toolpaths with the same moves are equal whatever each has worked out.
#[derive(Default)]
struct Memo(Mutex<(usize, [Option<bool>; MEMO_SLOTS])>);

impl Memo {
    fn answers(&self) -> (usize, [Option<bool>; MEMO_SLOTS]) {
        // A poisoned lock (a panic while it was held) only held answers: read them.
        *self.0.lock().unwrap_or_else(|e| e.into_inner())
    }
}

impl Clone for Memo {
    fn clone(&self) -> Memo {
        Memo(Mutex::new(self.answers()))
    }
}

impl PartialEq for Memo {
    fn eq(&self, _: &Memo) -> bool {
        true
    }
}

impl std::fmt::Debug for Memo {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("Memo")
    }
}

impl Toolpath {
    /// An empty toolpath to [`push`](Toolpath::push) the moves of a run
    /// into as they are made.
    pub fn new(machine: MachineKind, units: Units) -> Toolpath {
        Toolpath {
            machine,
            units,
            k: 1.0 / units.mm(),
            ..Toolpath::default()
        }
    }

    /// Builds the toolpath of a run.
    pub fn from_run(run: &Run) -> Toolpath {
        let mut t = Toolpath::new(run.machine, run.units);
        for m in &run.moves {
            t.push(m);
        }
        t
    }

    /// Adds a move. The first move sets the units (a run is drawn in the
    /// units of its first move).
    pub fn push(&mut self, m: &Move) {
        self.push_move(m, true);
    }

    /// Adds a move, and grows the bounds with it when `grow_bounds`: a
    /// run's toolpath built as it runs takes the run's own bounds at the
    /// end instead ([`PathBuilder::finish`]), which the run grows with the
    /// same points — growing both works out each arc's extremes twice (the
    /// page's run, `session_memory` and bench-browser target 3, guards it).
    #[inline(always)]
    fn push_move(&mut self, m: &Move, grow_bounds: bool) {
        if self.kinds.is_empty() {
            self.units = m.units;
            self.k = 1.0 / m.units.mm();
        }
        let k = self.k;
        let scaled = |p: Xyz| p.map(|v| v * k);
        let (from, pfrom) = (scaled(m.from), scaled(m.programmed_from));
        let (to, pto) = (scaled(m.to), scaled(m.programmed_to));
        // The bounds hold every vertex (a move that starts where the last
        // one ended adds its end only, not each end twice) and the arcs'
        // extremes.
        let mut bounds = self.bounds;
        if !self.ends_at(from, pfrom) {
            self.push_vertex(from, pfrom);
            if grow_bounds {
                include(&mut bounds, from);
                include(&mut bounds, pfrom);
            }
        }
        self.starts.push(self.vertex_count() as u32 - 1);
        self.push_vertex(to, pto);
        if grow_bounds {
            include(&mut bounds, to);
            include(&mut bounds, pto);
            if let Some(a) = &m.arc {
                a.each_extreme(m, |p| include(&mut bounds, scaled(p)));
            }
            self.bounds = bounds;
        }
        self.kinds.push(m.kind.code(m.at_feed));
        self.blocks.push(m.block);
        self.lines.push(m.line);
        if let Some(a) = &m.arc {
            let circle = |c: Circle| Circle {
                center: c.center.map(|v| v * k),
                radius: c.radius * k,
                ..c
            };
            self.arc_moves.push(self.kinds.len() as u32 - 1);
            self.arcs.push(ToolArc {
                plane: a.plane,
                diameter_x: a.diameter_x,
                actual: circle(a.circle()),
                programmed: circle(a.programmed_circle()),
            });
        }
    }

    /// The lengths of the arrays: actual, programmed, starts, kinds,
    /// blocks, lines, arcs, arc moves.
    fn lengths(&self) -> [usize; 8] {
        [
            self.actual.len(),
            self.programmed.len(),
            self.starts.len(),
            self.kinds.len(),
            self.blocks.len(),
            self.lines.len(),
            self.arcs.len(),
            self.arc_moves.len(),
        ]
    }

    /// Room in each array for as many items as `lengths` says (in the
    /// order of [`Toolpath::lengths`]), at once.
    fn reserve_to(&mut self, lengths: [usize; 8]) {
        let [a, p, s, k, b, l, c, m] = lengths;
        let room = |want: usize, len: usize| want.saturating_sub(len);
        self.actual.reserve(room(a, self.actual.len()));
        self.programmed.reserve(room(p, self.programmed.len()));
        self.starts.reserve(room(s, self.starts.len()));
        self.kinds.reserve(room(k, self.kinds.len()));
        self.blocks.reserve(room(b, self.blocks.len()));
        self.lines.reserve(room(l, self.lines.len()));
        self.arcs.reserve(room(c, self.arcs.len()));
        self.arc_moves.reserve(room(m, self.arc_moves.len()));
    }

    /// Appends the moves `moves` of `from` (a toolpath in the same units),
    /// their blocks `blocks` and lines `lines` further on: how a run made
    /// again keeps the parts of the earlier run's path before and after an
    /// edit ([`crate::rerun_observed`]). The first move joins on as
    /// [`Toolpath::push`] joins a move; the others keep their joins, so
    /// their vertices and arcs are copied whole.
    pub fn append_moves(&mut self, from: &Toolpath, moves: Range<usize>, blocks: i64, lines: i64) {
        let (first, end) = (moves.start.min(from.len()), moves.end.min(from.len()));
        if first >= end {
            return;
        }
        if self.kinds.is_empty() {
            self.units = from.units;
            self.k = from.k;
        }
        let shift = |v: u32, by: i64| (i64::from(v) + by).clamp(0, i64::from(u32::MAX)) as u32;
        let moves_before = self.kinds.len();
        // The first move: its start vertex unless it continues this path.
        let Some([[a0, a1], [p0, p1]]) = from.ends(first) else {
            return;
        };
        if !self.ends_at(a0, p0) {
            self.push_vertex(a0, p0);
        }
        self.starts.push(self.vertex_count() as u32 - 1);
        self.push_vertex(a1, p1);
        // The others: the vertices after the first move's end, as they are.
        let end_vertex = from.starts[first] as usize + 1;
        let last_vertex = from.starts[end - 1] as usize + 1;
        let offset = (self.vertex_count() - 1) as i64 - end_vertex as i64;
        self.actual
            .extend_from_slice(&from.actual[3 * (end_vertex + 1)..3 * (last_vertex + 1)]);
        self.programmed
            .extend_from_slice(&from.programmed[3 * (end_vertex + 1)..3 * (last_vertex + 1)]);
        self.starts.extend(
            from.starts[first + 1..end]
                .iter()
                .map(|&v| shift(v, offset)),
        );
        self.kinds.extend_from_slice(&from.kinds[first..end]);
        self.blocks
            .extend(from.blocks[first..end].iter().map(|&b| shift(b, blocks)));
        self.lines
            .extend(from.lines[first..end].iter().map(|&l| shift(l, lines)));
        let arcs = from.arcs_from(first).next..from.arcs_from(end).next;
        self.arcs.extend_from_slice(&from.arcs[arcs.clone()]);
        let moved = moves_before as i64 - first as i64;
        self.arc_moves
            .extend(from.arc_moves[arcs].iter().map(|&m| shift(m, moved)));
    }

    /// Sets the bounds from a run's (mm): a toolpath made with
    /// [`Toolpath::append_moves`] takes the bounds of the run made again.
    /// Scaling by a positive factor keeps the order of numbers, so this is
    /// the box [`Toolpath::push`] would have grown.
    pub fn set_bounds(&mut self, bounds: Option<crate::report::Bounds>) {
        let k = self.k;
        self.bounds = bounds.map(|b| (b.min.map(|v| v * k), b.max.map(|v| v * k)));
    }

    /// Whether the paths end at these points (a move starting there
    /// continues them and shares their last vertex).
    fn ends_at(&self, actual: Xyz, programmed: Xyz) -> bool {
        self.vertex_count() > 0 && {
            let i = self.actual.len() - 3;
            self.actual[i..] == actual && self.programmed[i..] == programmed
        }
    }

    fn push_vertex(&mut self, actual: Xyz, programmed: Xyz) {
        self.actual.extend(actual);
        self.programmed.extend(programmed);
    }

    /// Number of moves.
    pub fn len(&self) -> usize {
        self.kinds.len()
    }

    /// True without moves.
    pub fn is_empty(&self) -> bool {
        self.kinds.is_empty()
    }

    /// Number of vertices.
    pub fn vertex_count(&self) -> usize {
        self.actual.len() / 3
    }

    /// Gives back the room the arrays grew into (up to half of them).
    pub fn shrink_to_fit(&mut self) {
        self.actual.shrink_to_fit();
        self.programmed.shrink_to_fit();
        self.starts.shrink_to_fit();
        self.kinds.shrink_to_fit();
        self.blocks.shrink_to_fit();
        self.lines.shrink_to_fit();
        self.arcs.shrink_to_fit();
        self.arc_moves.shrink_to_fit();
    }

    /// Bytes held (what a run costs the page to draw).
    pub fn heap_bytes(&self) -> usize {
        (self.actual.capacity() + self.programmed.capacity()) * 8
            + (self.starts.capacity() + self.blocks.capacity() + self.lines.capacity()) * 4
            + self.kinds.capacity()
            + self.arcs.capacity() * std::mem::size_of::<ToolArc>()
            + self.arc_moves.capacity() * 4
    }

    fn vertex(vertices: &[f64], i: usize) -> Option<Xyz> {
        let v = vertices.get(i * 3..i * 3 + 3)?;
        Some([v[0], v[1], v[2]])
    }

    /// Start and end of move `m` on the actual and the programmed path:
    /// `[[actual from, actual to], [programmed from, programmed to]]`.
    pub fn ends(&self, m: usize) -> Option<[[Xyz; 2]; 2]> {
        let a = *self.starts.get(m)? as usize;
        Some([
            [
                Self::vertex(&self.actual, a)?,
                Self::vertex(&self.actual, a + 1)?,
            ],
            [
                Self::vertex(&self.programmed, a)?,
                Self::vertex(&self.programmed, a + 1)?,
            ],
        ])
    }

    /// How many moves this toolpath shares with `other` at its start, and
    /// how many of the rest at its end (the two never overlap): moves alike
    /// in kind, in their ends on both paths (bit for bit) and in their
    /// circles, which any drawing of the same view draws alike — after an
    /// edit, a kept drawing records again only the moves between
    /// ([`crate::render::Raster`]).
    pub fn shared_moves(&self, other: &Toolpath) -> (usize, usize) {
        // A move's ends are the six coordinates from its start vertex on.
        let same_ends = |m: usize, o: usize| {
            fn ends(t: &Toolpath, m: usize) -> Option<(&[f64], &[f64])> {
                let a = t.starts[m] as usize * 3;
                Some((t.actual.get(a..a + 6)?, t.programmed.get(a..a + 6)?))
            }
            let same =
                |a: &[f64], b: &[f64]| a.iter().zip(b).all(|(x, y)| x.to_bits() == y.to_bits());
            match (ends(self, m), ends(other, o)) {
                (Some((a, p)), Some((b, q))) => same(a, b) && same(p, q),
                (None, None) => true,
                _ => false,
            }
        };
        let n = self.len().min(other.len());
        let (mut mine, mut theirs) = (self.arcs_from(0), other.arcs_from(0));
        let mut first = 0;
        while first < n
            && self.kinds[first] == other.kinds[first]
            && same_ends(first, first)
            && mine.of(self, first) == theirs.of(other, first)
        {
            first += 1;
        }
        // From the end, each arc found by stepping back through the arcs.
        let arc_back = |t: &'_ Toolpath, next: &mut usize, m: usize| -> Option<ToolArc> {
            (*next > 0 && t.arc_moves[*next - 1] as usize == m).then(|| {
                *next -= 1;
                t.arcs[*next]
            })
        };
        let (mut mine, mut theirs) = (self.arc_moves.len(), other.arc_moves.len());
        let mut last = 0;
        while last < n - first {
            let (m, o) = (self.len() - 1 - last, other.len() - 1 - last);
            if self.kinds[m] != other.kinds[o]
                || !same_ends(m, o)
                || arc_back(self, &mut mine, m) != arc_back(other, &mut theirs, o)
            {
                break;
            }
            last += 1;
        }
        (first, last)
    }

    /// Index of the first arc of move `m` or later.
    /// A cursor over the arcs for a walk over the moves from `m` on.
    fn arcs_from(&self, m: usize) -> ArcCursor {
        ArcCursor {
            next: self.arc_moves.partition_point(|&a| (a as usize) < m),
        }
    }

    /// Calls `f(move, i, point)` for the points of every move in `range`
    /// that `keep` accepts, on the programmed or the actual path: its start
    /// (`i` = 0), and its end, with an arc's points between so that no
    /// point of the true arc is farther than `tolerance` (toolpath units)
    /// from the polyline (at most [`crate::machine::arc::MAX_ARC_SEGMENTS`] segments),
    /// placed as `arc_points` says.
    pub fn for_each_point(
        &self,
        range: Range<usize>,
        programmed: bool,
        arcs: (f64, ArcPoints),
        keep: impl Fn(usize) -> bool,
        mut f: impl FnMut(usize, usize, Xyz),
    ) {
        self.visit(range, programmed, arcs, keep, |m, visit| {
            if let Visit::Point(i, p) = visit {
                f(m, i, p);
            }
            false
        });
    }

    /// As [`Toolpath::for_each_point`], with `f(move, visit)`; after an
    /// arc's start, [`Visit::Arc`] offers the whole arc, and the points
    /// after its start follow only when `f` answers false to it (a pixel
    /// layer takes the arcs of a large drawing whole, and tessellates only
    /// those it does not find hidden).
    pub fn visit(
        &self,
        range: Range<usize>,
        programmed: bool,
        (tolerance, arc_points): (f64, ArcPoints),
        keep: impl Fn(usize) -> bool,
        mut f: impl FnMut(usize, Visit) -> bool,
    ) {
        let vertices = if programmed {
            &self.programmed
        } else {
            &self.actual
        };
        let mut arcs = self.arcs_from(range.start);
        for m in range.start..range.end.min(self.len()) {
            let arc = arcs.of(self, m);
            if !keep(m) {
                continue;
            }
            let a = self.starts[m] as usize;
            let (Some(from), Some(to)) = (Self::vertex(vertices, a), Self::vertex(vertices, a + 1))
            else {
                continue;
            };
            match arc {
                Some(c) => {
                    let count = c.segments(tolerance);
                    f(m, Visit::Point(0, from));
                    let whole = Visit::Arc {
                        arc: c,
                        programmed,
                        from,
                        to,
                        count,
                    };
                    if f(m, whole) {
                        continue;
                    }
                    match arc_points {
                        ArcPoints::Exact => {
                            for i in 1..=count {
                                f(m, Visit::Point(i, c.point(programmed, from, to, i, count)));
                            }
                        }
                        ArcPoints::Rotated => {
                            c.rotated_points(programmed, (from, to), count, |i, p| {
                                if i > 0 {
                                    f(m, Visit::Point(i, p));
                                }
                            });
                        }
                    }
                }
                None => {
                    f(m, Visit::Point(0, from));
                    f(m, Visit::Point(1, to));
                }
            }
        }
    }

    /// Bounds of both paths, arcs included: (min, max), or None without
    /// moves.
    pub fn bounds(&self) -> Option<(Xyz, Xyz)> {
        self.bounds
    }

    /// The answer `work_out(self)` kept in `slot` (below [`MEMO_SLOTS`]),
    /// worked out now if the path has had moves added since, or never was:
    /// for questions about all the moves that a view asks again and again
    /// (whether any hole is seen along a plane's normal, behaviour 6.11).
    /// Each slot is one question, always asked with the same `work_out`.
    pub fn remembered(&self, slot: usize, work_out: impl FnOnce(&Toolpath) -> bool) -> bool {
        if slot >= MEMO_SLOTS {
            return work_out(self);
        }
        let (moves, answers) = self.memo.answers();
        if moves == self.len()
            && let Some(known) = answers[slot]
        {
            return known;
        }
        let answer = work_out(self);
        let mut kept = self.memo.0.lock().unwrap_or_else(|e| e.into_inner());
        if kept.0 != self.len() {
            *kept = (self.len(), [None; MEMO_SLOTS]);
        }
        kept.1[slot] = Some(answer);
        answer
    }
}

/// Where a walk over the moves in order is among the arcs: the index of
/// the next arc move.
struct ArcCursor {
    next: usize,
}

impl ArcCursor {
    /// The circle of move `m` if it is an arc; moves are asked in order.
    fn of<'a>(&mut self, t: &'a Toolpath, m: usize) -> Option<&'a ToolArc> {
        if t.arc_moves.get(self.next) != Some(&(m as u32)) {
            return None;
        }
        self.next += 1;
        t.arcs.get(self.next - 1)
    }
}

/// Grows the box to hold `p`, passing over a NaN coordinate as `f64::min`
/// does (written as comparisons, which compile to one instruction each).
fn include(b: &mut Option<(Xyz, Xyz)>, p: Xyz) {
    match b {
        None => *b = Some((p, p)),
        Some((min, max)) => {
            for i in 0..3 {
                if p[i] < min[i] {
                    min[i] = p[i];
                }
                if p[i] > max[i] {
                    max[i] = p[i];
                }
            }
        }
    }
}
