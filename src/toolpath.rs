//! The toolpath for drawing: struct-of-arrays, one run of vertices per move,
//! arcs tessellated within [`CHORD_TOLERANCE_MM`]. The actual and the
//! programmed path have the same number of vertices per move, so vertex `i`
//! of one corresponds to vertex `i` of the other. Coordinates are in the
//! run's display units ([`Run::units`]); on the lathe X stays a diameter.
//!
//! This is what crosses the wasm boundary as typed arrays, never one object
//! per move.

use crate::machine::arc::{CHORD_TOLERANCE_MM, Circle};
use crate::report::{ArcInfo, Move, Run, Xyz};
use crate::setup::{MachineKind, Units};

pub use crate::machine::arc::CHORD_TOLERANCE_MM as CHORD_TOLERANCE;

/// Most vertices of one toolpath (each path). A line move has two; an arc
/// up to [`crate::machine::arc::MAX_ARC_SEGMENTS`] + 1. When the arcs of a
/// run would need more, every arc is drawn with proportionally fewer
/// segments (at least one), so the toolpath of any run that stays within
/// [`crate::MAX_MOVES`] fits: 2 × 5,000,000 line vertices are below it.
/// 16 Mi vertices are 384 MiB per path.
pub const MAX_VERTICES: usize = 1 << 24;
const _: () = assert!(MAX_VERTICES >= 2 * crate::MAX_MOVES && MAX_VERTICES <= u32::MAX as usize);

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
    /// Index of each move's first vertex, plus one final entry: the vertex
    /// count. Move `i` spans vertices `starts[i]..starts[i + 1]`.
    pub starts: Vec<u32>,
    /// Per move: [`crate::MoveKind::code`] (0 rapid, 1 feed, 2 arc cw,
    /// 3 arc ccw, 4 offset at rapid, 5 offset at feed).
    pub kinds: Vec<u8>,
    /// Per move: index of its block.
    pub blocks: Vec<u32>,
    /// Per move: 1-based source line.
    pub lines: Vec<u32>,
}

impl Toolpath {
    /// Builds the toolpath of a run (at most [`MAX_VERTICES`] per path).
    pub fn from_run(run: &Run) -> Toolpath {
        Toolpath::build(run, MAX_VERTICES)
    }

    fn build(run: &Run, max_vertices: usize) -> Toolpath {
        let mut t = Toolpath {
            units: run.units,
            machine: run.machine,
            ..Toolpath::default()
        };
        let k = 1.0 / run.units.mm();
        let arcs = ArcBudget::of(&run.moves, max_vertices);
        for m in &run.moves {
            t.starts.push(t.vertex_count() as u32);
            t.kinds.push(m.kind.code(m.at_feed));
            t.blocks.push(m.block);
            t.lines.push(m.line);
            match &m.arc {
                None => {
                    t.push(m.from, m.programmed_from, k);
                    t.push(m.to, m.programmed_to, k);
                }
                Some(a) => t.push_arc(m, a, k, &arcs),
            }
        }
        t.starts.push(t.vertex_count() as u32);
        t
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

    fn push(&mut self, actual: Xyz, programmed: Xyz, k: f64) {
        self.actual.extend(actual.map(|v| v * k));
        self.programmed.extend(programmed.map(|v| v * k));
    }

    fn push_arc(&mut self, m: &Move, a: &ArcInfo, k: f64, budget: &ArcBudget) {
        let (ia, ib, n) = a.plane.axes();
        let s = |i: usize| if a.diameter_x && i == 0 { 0.5 } else { 1.0 };
        let act = a.circle();
        let prog = a.programmed_circle();
        let count = budget.segments(arc_segments(a));
        let point = |c: &Circle, from: Xyz, to: Xyz, i: usize| -> Xyz {
            if i == count {
                return to;
            }
            let t = i as f64 / count as f64;
            let q = c.point(t);
            let mut p = from;
            p[ia] = q[0] / s(ia);
            p[ib] = q[1] / s(ib);
            p[n] = from[n] + (to[n] - from[n]) * t;
            p
        };
        for i in 0..=count {
            let pa = if i == 0 {
                m.from
            } else {
                point(&act, m.from, m.to, i)
            };
            let pp = if i == 0 {
                m.programmed_from
            } else {
                point(&prog, m.programmed_from, m.programmed_to, i)
            };
            self.push(pa, pp, k);
        }
    }

    /// Bounds of both paths: (min, max), or None without moves.
    pub fn bounds(&self) -> Option<(Xyz, Xyz)> {
        if self.actual.is_empty() {
            return None;
        }
        let mut min = [f64::INFINITY; 3];
        let mut max = [f64::NEG_INFINITY; 3];
        for chunk in self
            .actual
            .chunks_exact(3)
            .chain(self.programmed.chunks_exact(3))
        {
            for i in 0..3 {
                min[i] = min[i].min(chunk[i]);
                max[i] = max[i].max(chunk[i]);
            }
        }
        Some((min, max))
    }
}

/// Segments an arc is drawn with at the chord tolerance (the finer of its
/// actual and programmed circle).
fn arc_segments(a: &ArcInfo) -> usize {
    a.circle()
        .segments(CHORD_TOLERANCE_MM)
        .max(a.programmed_circle().segments(CHORD_TOLERANCE_MM))
}

/// How the arcs of a run share [`MAX_VERTICES`]: each arc keeps its first
/// segment, and the segments past the first are scaled by one factor when
/// their sum would pass the budget.
struct ArcBudget {
    /// Vertices for the segments past each arc's first, and how many those
    /// arcs want; `None` when everything fits.
    scale: Option<(usize, usize)>,
}

impl ArcBudget {
    fn of(moves: &[Move], max_vertices: usize) -> ArcBudget {
        // Two vertices per move (an arc's start and its first segment's end).
        let base = moves.len().saturating_mul(2);
        let extra: usize = moves
            .iter()
            .filter_map(|m| m.arc.as_ref())
            .map(|a| arc_segments(a) - 1)
            .sum();
        let room = max_vertices.saturating_sub(base);
        ArcBudget {
            scale: (base.saturating_add(extra) > max_vertices).then_some((room, extra)),
        }
    }

    fn segments(&self, wanted: usize) -> usize {
        match self.scale {
            None => wanted,
            Some((room, extra)) => {
                let more = (wanted - 1) as u128 * room as u128 / extra.max(1) as u128;
                1 + more as usize
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Setup, run};

    #[test]
    fn one_vertex_run_per_move_and_equal_lengths() {
        let mut setup = Setup::default();
        setup.set_register("01=6").unwrap();
        let r = run(
            "G91 G00 G46 X30. Y20. D01\nG01 G47 X80. F200.\nG03 X-10. Y10. I-10. F100.",
            &setup,
        );
        assert!(!r.has_errors(), "{:?}", r.diagnostics);
        let t = Toolpath::from_run(&r);
        assert_eq!(t.len(), 3);
        assert_eq!(t.starts.len(), 4);
        assert_eq!(t.actual.len(), t.programmed.len());
        assert_eq!(*t.starts.last().unwrap() as usize, t.vertex_count());
        assert_eq!(&t.actual[3..6], &[24.0, 14.0, 0.0]);
        assert_eq!(t.kinds, vec![0, 1, 3]);
        // The arc ends exactly where the move ends.
        let last = &t.programmed[t.programmed.len() - 3..];
        assert_eq!(last, &[100.0, 30.0, 0.0]);
        assert!(t.starts[3] - t.starts[2] > 10, "arcs are tessellated");
    }

    #[test]
    fn arc_vertices_lie_on_the_circle_within_tolerance() {
        let r = run("G02 X20. Y0 I10. J0 F100.", &Setup::default());
        let t = Toolpath::from_run(&r);
        for p in t.actual.chunks_exact(3) {
            let d = ((p[0] - 10.0).powi(2) + p[1].powi(2)).sqrt();
            assert!((d - 10.0).abs() < 1e-9);
        }
        // Chord midpoints stay within the tolerance.
        let v: Vec<&[f64]> = t.actual.chunks_exact(3).collect();
        for w in v.windows(2) {
            let mx = (w[0][0] + w[1][0]) / 2.0 - 10.0;
            let my = (w[0][1] + w[1][1]) / 2.0;
            assert!(10.0 - (mx * mx + my * my).sqrt() <= CHORD_TOLERANCE + 1e-12);
        }
    }

    #[test]
    fn arcs_share_the_vertex_budget() {
        // 100 full circles of radius 50 m want 1024 segments each, and
        // two lines two vertices each: 102,604 vertices for a budget of
        // 10,000 (MAX_VERTICES works the same way, 20,000 such circles).
        let text = "G02 X0 Y0 I50000. F100.\n".repeat(100) + "G01 X1.\nG01 X2.";
        let r = run(&text, &Setup::default());
        assert!(!r.has_errors(), "{:?}", r.diagnostics);
        assert_eq!(Toolpath::from_run(&r).vertex_count(), 100 * 1025 + 4);
        let t = Toolpath::build(&r, 10_000);
        assert_eq!(t.len(), 102);
        assert!(t.vertex_count() <= 10_000, "{}", t.vertex_count());
        assert!(t.vertex_count() > 9_000, "{}", t.vertex_count());
        assert_eq!(t.starts[101] - t.starts[100], 2, "lines keep both ends");
        assert_eq!(*t.starts.last().unwrap() as usize, t.vertex_count());
        // Each circle still ends where it started, on the circle.
        let end = t.starts[1] as usize - 1;
        assert_eq!(&t.actual[end * 3..end * 3 + 3], &[0.0, 0.0, 0.0]);
        let mid = (t.starts[0] as usize + end) / 2;
        let p = &t.actual[mid * 3..mid * 3 + 2];
        let d = ((p[0] - 50_000.0).powi(2) + p[1].powi(2)).sqrt();
        assert!((d - 50_000.0).abs() < 1e-6, "{d}");
    }

    #[test]
    fn inch_runs_are_drawn_in_inches() {
        let r = run("G20\nG01 X1. F10.", &Setup::default());
        let t = Toolpath::from_run(&r);
        assert_eq!(t.units, Units::Inch);
        assert!((t.actual[3] - 1.0).abs() < 1e-12);
    }
}
