//! Where a path being traced is: the last point drawn and the vertex
//! passed over, where a dashed pattern starts afresh, and how an arc whose
//! projection is a circle is handed to a pen that takes it whole.

use super::{
    DRAW_TOLERANCE_PX, Frame, MIN_SEGMENT_PX, Pen, RESTART_EVERY, Stroke, WholeArc, is_rapid,
};
use crate::geometry::Xyz;
use crate::toolpath::{ToolArc, Toolpath, Visit};

/// Where a path being drawn is.
pub(super) struct Tracer<'a> {
    stroke: &'a Stroke,
    /// The dash pattern's length (0: solid).
    period: f64,
    state: TracerState,
}

/// What tracing a path has come to: all that the rest of it depends on
/// besides the moves still to trace (so a tracing resumed from here
/// records what going on would: [`super::resume`]).
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct TracerState {
    /// The first point of the last move, for where a dashed pattern
    /// starts afresh (after a move whose ends are a period apart).
    from: Option<(f64, f64)>,
    /// `pen` is the last point drawn, `pending` the last vertex passed
    /// over for being too close to it; ends of runs are always drawn.
    pen: Option<(f64, f64)>,
    pending: Option<(f64, f64)>,
    /// Whether the path was begun (its first point drawn).
    pub(super) begun: bool,
}

impl TracerState {
    /// Nothing traced yet, the path begun already or not.
    pub(super) fn begun(begun: bool) -> TracerState {
        TracerState {
            begun,
            ..TracerState::default()
        }
    }

    /// The same, bit for bit.
    pub(super) fn same(&self, other: &TracerState) -> bool {
        let bits = |p: Option<(f64, f64)>| p.map(|(x, y)| (x.to_bits(), y.to_bits()));
        self.begun == other.begun
            && bits(self.from) == bits(other.from)
            && bits(self.pen) == bits(other.pen)
            && bits(self.pending) == bits(other.pending)
    }
}

impl<'a> Tracer<'a> {
    /// A tracer of a path stroked with `stroke`, where `state` says.
    pub(super) fn new(stroke: &'a Stroke, state: TracerState) -> Tracer<'a> {
        Tracer {
            stroke,
            period: stroke.dash.iter().sum(),
            state,
        }
    }

    /// Where it has come to.
    pub(super) fn state(&self) -> TracerState {
        self.state
    }

    /// Whether its pattern is dashed.
    pub(super) fn dashed(&self) -> bool {
        self.period > 0.0
    }

    /// Traces the moves of `range` on the programmed or the actual path
    /// that are rapid or not (`kind`).
    pub(super) fn visit(
        &mut self,
        s: &mut impl Pen,
        f: &Frame,
        tp: &Toolpath,
        (programmed, rapid): (bool, bool),
        range: std::ops::Range<usize>,
    ) {
        // Arcs are tessellated for the scale they are drawn at.
        let arcs = (DRAW_TOLERANCE_PX / f.transform.scale, s.arc_points());
        let keep = |m: usize| tp.kinds.get(m).is_some_and(|&k| is_rapid(k) == rapid);
        let mut each = |m: usize, visit: Visit<'_>| match visit {
            Visit::Point(i, p) => {
                let (u, v) = f.projection.project(&p);
                let (x, y) = f.transform.to_screen(u, v);
                self.point(s, m, i, (x, y));
                false
            }
            Visit::Arc {
                arc,
                programmed,
                from,
                to,
                count,
            } => {
                // (Worked out only for a pen that may take it.)
                s.takes_arcs() && self.arc(s, whole_arc(f, arc, programmed, (from, to), count))
            }
        };
        // A turned 3D view's sample (behaviour 10.8): every stride-th move alone.
        match f.stride.max(1) {
            1 => tp.visit(range, programmed, arcs, keep, &mut each),
            n => (range.start.next_multiple_of(n)..range.end)
                .step_by(n)
                .for_each(|m| tp.visit(m..m + 1, programmed, arcs, keep, &mut each)),
        }
    }

    /// Ends the tracing: draws the vertex passed over last, if any.
    /// Returns whether the path was begun.
    pub(super) fn finish(&mut self, s: &mut impl Pen) -> bool {
        if let Some((px, py)) = self.state.pending {
            s.line_to(px, py);
        }
        self.state.begun
    }

    /// Point `i` of move `m` (0: its start), on the screen.
    fn point(&mut self, s: &mut impl Pen, m: usize, i: usize, (x, y): (f64, f64)) {
        if !(x.is_finite() && y.is_finite()) {
            return;
        }
        if !self.state.begun {
            s.begin_path(self.stroke);
            self.state.begun = true;
        }
        if i == 0 {
            let last_from = self.state.from.replace((x, y));
            // A move that starts where the last one ended continues
            // the line; any other starts a new sub-path.
            let last = self.state.pending.or(self.state.pen);
            if last.is_some_and(|(lx, ly)| distance_near(x - lx, y - ly, 0.01) <= 0.01) {
                // Where the last move's end was skipped (level of
                // detail), the line runs on across the two moves.
                if self.state.pending.is_none()
                    && let Some((px, py)) = self.state.pen
                {
                    let period = self.period;
                    let long = last_from.is_some_and(|(fx, fy)| {
                        (px - fx).abs() >= period || (py - fy).abs() >= period
                    });
                    let restart = period > 0.0 && (long || m.is_multiple_of(RESTART_EVERY));
                    s.next_move(px, py, restart);
                }
                return;
            }
            if let Some((px, py)) = self.state.pending.take() {
                s.line_to(px, py);
            }
            s.move_to(x, y);
            self.state.pen = Some((x, y));
            return;
        }
        if self
            .state
            .pen
            .is_some_and(|(px, py)| distance_near(x - px, y - py, MIN_SEGMENT_PX) < MIN_SEGMENT_PX)
        {
            self.state.pending = Some((x, y));
            return;
        }
        s.line_to(x, y);
        self.state.pen = Some((x, y));
        self.state.pending = None;
    }

    /// An arc whose start was just drawn ([`Tracer::point`]), offered to
    /// the pen whole; false when its points are to follow instead (the
    /// pen does not take it, or its projection is not a circle).
    fn arc(&mut self, s: &mut impl Pen, whole: Option<WholeArc>) -> bool {
        let Some(whole) = whole else {
            return false;
        };
        // Its start was passed over, or was not on the screen's plane.
        if !self.state.begun || self.state.pen.is_none() {
            return false;
        }
        if !s.takes_arcs() {
            return false;
        }
        // The arc starts at the vertex passed over, if any.
        if let Some((px, py)) = self.state.pending.take() {
            s.line_to(px, py);
            self.state.pen = Some((px, py));
        }
        if !s.arc(&whole) {
            return false;
        }
        self.state.pen = Some(whole.to);
        true
    }
}

/// An arc move on the screen, when the view shows its circle as a circle
/// (the view's plane is the arc's; a helix's rise is not seen): the circle
/// of one path, its ends, and its sweep as the screen turns (y down).
fn whole_arc(
    f: &Frame,
    arc: &ToolArc,
    programmed: bool,
    (from, to): (Xyz, Xyz),
    count: usize,
) -> Option<WholeArc> {
    // The plane's axes as the view shows them (a projection is linear).
    let [ea, eb, en] = arc.frame();
    let (a, b, n) = (
        f.projection.project(&ea),
        f.projection.project(&eb),
        f.projection.project(&en),
    );
    let (la, lb) = (a.0 * a.0 + a.1 * a.1, b.0 * b.0 + b.1 * b.1);
    let dot = a.0 * b.0 + a.1 * b.1;
    let circle =
        n == (0.0, 0.0) && la > 0.0 && (la - lb).abs() <= 1e-9 * la && dot.abs() <= 1e-9 * la;
    if !circle {
        return None;
    }
    let (centre, sweep) = arc.centre_and_sweep(programmed, from);
    let screen = |p: Xyz| {
        let (u, v) = f.projection.project(&p);
        f.transform.to_screen(u, v)
    };
    // Screen y runs down: the plane's turn from its first axis to its
    // second is the screen's negative turn when the two keep their order.
    let turn = a.1 * b.0 - a.0 * b.1;
    let whole = WholeArc {
        centre: screen(centre),
        from: screen(from),
        to: screen(to),
        sweep: if turn > 0.0 { sweep } else { -sweep },
        count,
    };
    let finite = [whole.centre, whole.from, whole.to]
        .iter()
        .all(|p| p.0.is_finite() && p.1.is_finite());
    (finite && whole.sweep.is_finite() && count > 0).then_some(whole)
}

/// `dx.hypot(dy)` where it is near `limit` or below; else a number that
/// compares with `limit` as it does (`<`, `<=`, `>`, `>=`). The level of
/// detail asks this of every point, and `hypot`, for this and for the
/// lengths of segments, was a large share of a 1M-block frame natively
/// (`examples/render_time` on the 1M-block program guards it): most points
/// are far apart along an axis, and
/// `hypot` (rounded faithfully) is never less than the longer side, nor
/// more than the sum of the sides rounded up.
#[inline(always)]
fn distance_near(dx: f64, dy: f64, limit: f64) -> f64 {
    let (ax, ay) = (dx.abs(), dy.abs());
    // Not `f64::max`, which answers for NaN too (a call to libm in wasm):
    // the points are finite.
    let longer = if ay > ax { ay } else { ax };
    if longer > limit {
        longer
    } else if ax + ay < limit * (1.0 - 1e-9) {
        ax + ay
    } else {
        dx.hypot(dy)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::MachineKind;
    use crate::render::paths::draw_path;
    use crate::render::style::{ACTUAL_FEED, PROGRAMMED_FEED};
    use crate::render::test_support::toolpath_on;
    use crate::render::{Plane, Raster};

    /// The toolpath drawn on a raster of `w` × `h` (scale 2) with `stroke`,
    /// its arcs taken whole or as their points; how many were taken whole.
    fn drawn(tp: &Toolpath, plane: Plane, stroke: &Stroke, whole: bool) -> (Raster, usize) {
        struct Counting(Raster, usize);
        impl Pen for Counting {
            fn begin_path(&mut self, s: &Stroke) {
                self.0.begin_path(s)
            }
            fn move_to(&mut self, x: f64, y: f64) {
                self.0.move_to(x, y)
            }
            fn line_to(&mut self, x: f64, y: f64) {
                self.0.line_to(x, y)
            }
            fn stroke(&mut self) {
                self.0.stroke()
            }
            fn next_move(&mut self, x: f64, y: f64, restart: bool) {
                self.0.next_move(x, y, restart)
            }
            fn arc_points(&self) -> crate::toolpath::ArcPoints {
                self.0.arc_points()
            }
            fn takes_arcs(&self) -> bool {
                self.0.takes_arcs()
            }
            fn arc(&mut self, arc: &WholeArc) -> bool {
                let taken = self.0.arc(arc);
                self.1 += usize::from(taken);
                taken
            }
        }
        let (w, h) = (300.0, 240.0);
        let f = Frame::fit(tp, plane, w, h);
        let mut raster = Raster::new();
        raster.take_arcs_whole_past(if whole { 0 } else { usize::MAX });
        assert!(raster.begin(600, 480, (2.0, 2.0)));
        let mut pen = Counting(raster, 0);
        draw_path(&mut pen, &f, tp, false, 0..tp.len(), |_| stroke);
        (pen.0, pen.1)
    }

    /// Asserts that two drawings show the same lines: the segments of
    /// whole arcs are those of their points to a float's rounding, and
    /// where a segment's or a dash's square end falls on a pixel's edge the
    /// rounding may take a column of pixels in or out (along a diagonal,
    /// pixels two apart). So: few pixels differ by more than a rounding,
    /// and each of those has ink of both drawings within two pixels of it
    /// (nothing drawn elsewhere, nothing missing).
    fn assert_same_lines(a: &mut Raster, b: &mut Raster) {
        assert_eq!(a.size(), b.size());
        let (w, h) = a.size();
        let inked = |r: &mut Raster, x: usize, y: usize| {
            let (x0, y0) = (x.saturating_sub(2), y.saturating_sub(2));
            (y0..(y + 3).min(h)).any(|y| (x0..(x + 3).min(w)).any(|x| r.pixel(x, y)[3] > 0))
        };
        let (mut ink, mut differ) = (0, 0);
        for y in 0..h {
            for x in 0..w {
                let (p, q) = (a.pixel(x, y), b.pixel(x, y));
                ink += usize::from(p[3] > 0 || q[3] > 0);
                let d = p.iter().zip(q).map(|(u, v)| u.abs_diff(v)).max().unwrap();
                if d > 2 {
                    differ += 1;
                    assert!(
                        inked(a, x, y) && inked(b, x, y),
                        "({x}, {y}): {p:?} against {q:?}"
                    );
                }
            }
        }
        assert!(ink > 0);
        assert!(differ * 100 < ink, "{differ} of {ink} pixels differ");
    }

    // Arcs of every kind on the mill: clockwise and counter-clockwise,
    // by R and by I J, a full circle, a helix, an arc in G18 (seen edge
    // on from above: its points), and one that runs off the view's edge
    // when zoomed (its points, clipped).
    const MILL: &str = "G90 G17 G00 X0. Y0.\nG01 X20. F100.\nG03 X40. Y20. R20.\nG02 X60. Y40. I20. J0.\n\
        G03 X60. Y40. I-15. J0.\nG01 X30. Y60.\nG03 X10. Y60. Z-5. I-10. J0.\nG18 G02 X0. Z-5. I-5. K0.\n\
        G17 G01 X-10. Y30.\nG02 X-10. Y30. I0. J-12.5\nG03 X5. Y45. R15.\n";

    #[test]
    fn a_raster_takes_arcs_whole_only_past_what_is_kept() {
        // Past 1 Mi recorded points a drawing is not kept for the next
        // edit; before, it is recorded as it always was.
        let mut r = Raster::new();
        assert!(r.begin(1000, 1000, (1.0, 1.0)));
        r.begin_path(&ACTUAL_FEED);
        r.move_to(10.0, 10.0);
        let mut points = 1;
        while !r.takes_arcs() {
            r.line_to(
                10.0 + (points % 2) as f64 * 900.0,
                10.0 + (points % 900) as f64,
            );
            points += 1;
        }
        assert_eq!(points, 1 << 20);
        // Vector pens (SVG, the canvas's strokes) always take points.
        assert!(!crate::render::svg::SvgSurface::new().takes_arcs());
    }

    #[test]
    fn whole_arcs_draw_the_pixels_their_points_draw() {
        let tp = toolpath_on(MILL, MachineKind::Mill);
        for stroke in [&ACTUAL_FEED, &PROGRAMMED_FEED] {
            let (mut points, by_points) = drawn(&tp, Plane::Xy, stroke, false);
            let (mut whole, taken) = drawn(&tp, Plane::Xy, stroke, true);
            assert_eq!(by_points, 0);
            // All six but the G18 arc (a line from above).
            assert_eq!(taken, 6);
            assert_same_lines(&mut points, &mut whole);
        }
        // From the side, the G18 arc is the circle.
        let (mut points, _) = drawn(&tp, Plane::Xz, &ACTUAL_FEED, false);
        let (mut whole, taken) = drawn(&tp, Plane::Xz, &ACTUAL_FEED, true);
        assert_eq!(taken, 1);
        assert_same_lines(&mut points, &mut whole);
    }

    #[test]
    fn lathe_arcs_are_whole_in_the_zx_view() {
        let tp = toolpath_on(
            "G50 X120. Z60.\nG00 X40. Z2.\nG01 Z-10. F0.2\nG02 X60. Z-20. R10.\nG03 X80. Z-30. R10.\nG01 Z-40.\n",
            MachineKind::Lathe,
        );
        let (mut points, _) = drawn(&tp, Plane::LatheZx, &ACTUAL_FEED, false);
        let (mut whole, taken) = drawn(&tp, Plane::LatheZx, &ACTUAL_FEED, true);
        assert_eq!(taken, 2);
        assert_same_lines(&mut points, &mut whole);
    }

    #[test]
    fn whole_arcs_under_what_was_drawn_after_them_are_not_tessellated() {
        // Fifty small circles, then a square filled by lines closer than
        // the stroke is wide over half of them: front to back, those are
        // hidden, and only the others are tessellated.
        let mut program = String::from("G90 G00 X0. Y0.\nG01 F100.\n");
        for k in 0..50 {
            let (x, y) = (2 + (k % 10) * 4, 2 + (k / 10) * 4);
            program.push_str(&format!(
                "G00 X{}. Y{y}.\nG03 X{}. Y{y}. I-1. J0.\n",
                x + 1,
                x + 1
            ));
        }
        program.push_str("G00 X0. Y-1.\n");
        for k in 0..120 {
            let y = -1.0 + f64::from(k) * 0.1;
            let x = if k % 2 == 0 { 41.0 } else { 0.0 };
            program.push_str(&format!("G01 X{x}. Y{y:.1}\nY{:.1}\n", y + 0.1));
        }
        let tp = toolpath_on(&program, MachineKind::Mill);
        let (mut points, _) = drawn(&tp, Plane::Xy, &ACTUAL_FEED, false);
        let (mut whole, taken) = drawn(&tp, Plane::Xy, &ACTUAL_FEED, true);
        assert_eq!(taken, 50);
        let tessellated = whole.arcs_tessellated();
        assert!(
            (20..=30).contains(&tessellated),
            "{tessellated} tessellated"
        );
        assert_same_lines(&mut points, &mut whole);
    }

    #[test]
    fn hidden_whole_arcs_are_not_drawn_and_the_rest_are() {
        // A thousand circles on one spot under a last one drawn over them
        // with a wide stroke: front to back, the first ones are hidden.
        let mut program = String::from("G90 G00 X0. Y0.\nG01 X10. F100.\n");
        for _ in 0..1000 {
            program.push_str("G03 X10. Y0. I-10. J0.\n");
        }
        let tp = toolpath_on(&program, MachineKind::Mill);
        let wide = Stroke {
            width: 6.0,
            ..ACTUAL_FEED
        };
        let (mut points, _) = drawn(&tp, Plane::Xy, &wide, false);
        let (mut whole, taken) = drawn(&tp, Plane::Xy, &wide, true);
        assert_eq!(taken, 1000);
        assert_same_lines(&mut points, &mut whole);
    }
}
