//! The paths of a scene as strokes: each move's points projected onto the
//! view and joined into lines, sub-pixel vertices passed over (level of
//! detail), a dashed pattern started afresh where [`super::RESTART_EVERY`] says;
//! a pen that takes arcs whole ([`Pen::arc`]) gets those whose projection is
//! a circle as one call instead of their points.

pub(super) use super::tracer::{Tracer, TracerState};
use super::{Frame, Pen, Raster, Scene, Stroke};
use crate::toolpath::Toolpath;

/// One stroke of a scene: the moves of `moves` on the programmed or the
/// actual path (`kind.0`) that are rapid or not (`kind.1`), and the group
/// it belongs to.
#[derive(Clone)]
pub(super) struct Layer {
    pub(super) group: &'static str,
    pub(super) kind: (bool, bool),
    pub(super) moves: std::ops::Range<usize>,
    pub(super) stroke: Stroke,
}

/// The strokes of a scene, bottom to top: the moves after the current
/// block (faint), the current block's highlight, the actual path and the
/// programmed path up to the current block; each path's rapid moves below
/// its others.
pub(super) fn layers(f: &Frame, tp: &Toolpath, scene: &Scene, split: usize) -> Vec<Layer> {
    let t = f.theme;
    let mut out = Vec::with_capacity(8);
    let mut path = |group, programmed, moves: std::ops::Range<usize>, strokes: [Stroke; 2]| {
        for (rapid, stroke) in [true, false].into_iter().zip(strokes) {
            let kind = (programmed, rapid);
            let moves = moves.clone();
            out.push(Layer {
                group,
                kind,
                moves,
                stroke,
            });
        }
    };
    if split < tp.len() {
        path("ghost", false, split..tp.len(), [t.ghost(); 2]);
    }
    if let Some(step) = scene.step {
        let first = tp.blocks.partition_point(|&b| b < step).min(split);
        if first < split {
            path("current", false, first..split, [t.highlight(); 2]);
        }
    }
    path(
        "actual",
        false,
        0..split,
        [t.actual_rapid(), t.actual_feed()],
    );
    path(
        "programmed",
        true,
        0..split,
        [t.programmed_rapid(), t.programmed_feed()],
    );
    out
}

/// The paths of a scene ([`layers`]), bottom to top, each group of
/// strokes in a group of the pen's.
pub(super) fn draw_paths(
    pen: &mut impl Pen,
    frame: &Frame,
    toolpath: &Toolpath,
    scene: &Scene,
    split: usize,
) {
    let layers = layers(frame, toolpath, scene, split);
    for (k, layer) in layers.iter().enumerate() {
        if k == 0 || layers[k - 1].group != layer.group {
            pen.begin_group(layer.group);
        }
        let (moves, stroke) = (layer.moves.clone(), &layer.stroke);
        if trace(pen, frame, toolpath, layer.kind, moves, stroke, false) {
            pen.stroke();
        }
        if layers
            .get(k + 1)
            .is_none_or(|next| next.group != layer.group)
        {
            pen.end_group();
        }
    }
}

/// At most this many moves of the current block are swept (behaviour
/// 16.20): a block is a handful of moves, and a bound keeps any frame fast.
pub(super) const MAX_SWEPT_MOVES: usize = 4096;

/// The band the cutter sweeps along the current block's actual moves
/// (behaviour 16.20): the tool centre's path stroked 2·R wide on screen,
/// translucent, when the view is the compensation's plane. Vectors on the
/// surface, drawn before (so under) the paths.
pub(super) fn draw_swept(
    pen: &mut impl Pen,
    frame: &Frame,
    tp: &Toolpath,
    scene: &Scene,
    split: usize,
) {
    let (Some(step), Some(cutter), true) = (scene.step, scene.cutter, scene.swept) else {
        return;
    };
    // The actual path is the cutter's centre on the mill; on the lathe it is
    // the imaginary nose, off the nose centre (behaviour 18.2): not swept.
    if cutter.plane != frame.plane || cutter.centre != [0.0; 3] {
        return;
    }
    let width = 2.0 * cutter.radius * frame.transform.scale;
    if !(width.is_finite() && width > 0.0) {
        return;
    }
    let first = tp.blocks.partition_point(|&b| b < step).min(split);
    let moves = first..split.min(first + MAX_SWEPT_MOVES);
    if moves.is_empty() {
        return;
    }
    let stroke = Stroke {
        color: frame.theme.swept,
        width,
        dash: &[],
    };
    pen.begin_group("swept");
    // One stroke for rapid and feed moves alike: the band is the cutter's.
    let begun = trace(pen, frame, tp, (false, true), moves.clone(), &stroke, false);
    if trace(pen, frame, tp, (false, false), moves, &stroke, begun) {
        pen.stroke();
    }
    pen.end_group();
}

/// One path (one stroke) drawn on `s` (for the tests: [`draw_paths`]
/// draws a scene's): the moves of `range` on the
/// programmed or the actual path, rapid ones with one stroke, the others
/// with another.
#[cfg(test)]
pub(super) fn draw_path<'a>(
    s: &mut impl Pen,
    f: &Frame,
    tp: &Toolpath,
    programmed: bool,
    range: std::ops::Range<usize>,
    stroke_for: impl Fn(bool) -> &'a Stroke,
) {
    for rapid in [true, false] {
        if trace(
            s,
            f,
            tp,
            (programmed, rapid),
            range.clone(),
            stroke_for(rapid),
            false,
        ) {
            s.stroke();
        }
    }
}

/// The moves of `range` on the programmed or the actual path that are
/// rapid or not (`rapid`), traced on `s` with `stroke`: the path begun
/// when the first point is drawn (`begun`: begun already). Returns
/// whether it was begun.
fn trace(
    s: &mut impl Pen,
    f: &Frame,
    tp: &Toolpath,
    kind: (bool, bool),
    range: std::ops::Range<usize>,
    stroke: &Stroke,
    begun: bool,
) -> bool {
    let mut t = Tracer::new(stroke, TracerState::begun(begun));
    t.visit(s, f, tp, kind, range);
    t.finish(s)
}

/// The moves of a part of a planned drawing ([`draw_paths_in_parts`]):
/// a multiple of [`super::RESTART_EVERY`], so that a part starts where a dashed
/// path starts its pattern afresh anyway, and its first move is drawn as
/// it would be in one go (but for the level of detail at its start).
const PART_MOVES: usize = 256;

/// Programs of more moves than this are measured on samples of their
/// moves for [`draw_paths_in_parts`]: `SAMPLES` stretches of
/// [`PART_MOVES`] spread over them.
const MEASURED_WHOLE: usize = 64 * PART_MOVES;
const SAMPLES: usize = 64;

/// [`draw_paths`] on a raster in parts, front to back: the top path
/// first, each path's last moves first, each part recorded and drawn
/// below what is drawn before the part before it is recorded — so that
/// what lies below finished pixels is found hidden when it is recorded
/// and not recorded at all ([`Raster::plan`]). For drawings too large to
/// be kept for the next edit: the parts' first moves start afresh, which
/// a kept drawing's comparison does not expect. Returns how many moves of
/// its paths it traced (each path counts its moves).
pub(super) fn draw_paths_in_parts(
    r: &mut Raster,
    f: &Frame,
    tp: &Toolpath,
    scene: &Scene,
    split: usize,
) -> usize {
    // Top first.
    let layers: Vec<Layer> = layers(f, tp, scene, split).into_iter().rev().collect();
    // The grid: from the ink the lines would cover, measured on samples.
    let mut meter = r.ink_meter();
    let mut ink = 0.0;
    for Layer {
        kind,
        moves: range,
        stroke,
        ..
    } in &layers
    {
        let (kind, n) = (*kind, range.len());
        if n <= MEASURED_WHOLE {
            meter.area = 0.0;
            trace(&mut meter, f, tp, kind, range.clone(), stroke, false);
            ink += meter.area;
            continue;
        }
        let mut sampled = 0.0;
        for k in 0..SAMPLES {
            let start = range.start + k * (n - PART_MOVES) / (SAMPLES - 1);
            meter.area = 0.0;
            trace(
                &mut meter,
                f,
                tp,
                kind,
                start..start + PART_MOVES,
                stroke,
                false,
            );
            sampled += meter.area;
        }
        ink += sampled * n as f64 / (SAMPLES * PART_MOVES) as f64;
    }
    r.plan(ink);
    let moves = layers.iter().map(|l| l.moves.len()).sum();
    for Layer {
        kind,
        moves: range,
        stroke,
        ..
    } in layers
    {
        let stroke = &stroke;
        r.begin_path(stroke);
        let mut end = range.end;
        while end > range.start {
            // Parts start at multiples of PART_MOVES.
            let start = ((end - 1) / PART_MOVES * PART_MOVES).max(range.start);
            r.resume_path();
            trace(r, f, tp, kind, start..end, stroke, true);
            r.stroke();
            r.finish();
            end = start;
        }
    }
    moves
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::MachineKind;
    use crate::render::test_support::{assert_same_pixels, toolpath_on};

    /// A program of `n` moves: long lines between scattered points, an
    /// arc by R every fifth move, a full circle every seventh, rapid moves
    /// now and then (no segment under a pixel: the level of detail, which
    /// starts afresh with each part, passes over none).
    fn scattered(n: usize) -> String {
        let mut program = String::from("G90 G17 G00 X0. Y0.\nG01 F500.\n");
        let mut at = (0.0, 0.0);
        for k in 0..n {
            let p = ((k * 37 % 101) as f64 - 50.0, (k * 53 % 89) as f64 - 44.0);
            let line = match k % 7 {
                _ if k % 5 == 4 => {
                    let r = (p.0 - at.0).hypot(p.1 - at.1) * 0.75;
                    format!("G02 X{:.3} Y{:.3} R{r:.3}", p.0, p.1)
                }
                3 => format!("G03 X{:.3} Y{:.3} I2. J0.", at.0, at.1),
                6 => format!("G00 X{:.3} Y{:.3}", p.0, p.1),
                _ => format!("G01 X{:.3} Y{:.3}", p.0, p.1),
            };
            if k % 7 != 3 {
                at = p;
            }
            program.push_str(&line);
            program.push('\n');
        }
        program
    }

    /// The scene drawn on a raster of `w` × `h` CSS pixels (scale 2) in one
    /// go ([`draw_paths`], arcs whole as a planned drawing takes them) or in
    /// parts ([`draw_paths_in_parts`]).
    fn scene_drawn(tp: &Toolpath, scene: &Scene, (w, h): (f64, f64), parts: bool) -> Raster {
        let f = scene.frame(tp, w, h);
        let split = scene.drawn_moves(tp);
        let mut r = Raster::new();
        r.take_arcs_whole_past(0);
        assert!(r.begin((2.0 * w) as usize, (2.0 * h) as usize, (2.0, 2.0)));
        if parts {
            draw_paths_in_parts(&mut r, &f, tp, scene, split);
        } else {
            super::draw_paths(&mut r, &f, tp, scene, split);
        }
        r
    }

    #[test]
    fn a_drawing_in_parts_has_the_pixels_of_one_in_one_go() {
        // Dense (the coarse grid), and sparse enough for the full one.
        // (20,000 moves: past MEASURED_WHOLE, the ink measured on samples.)
        for (n, size, coarse) in [
            (3000, (200.0, 160.0), 2),
            (300, (900.0, 700.0), 1),
            (20_000, (120.0, 100.0), 2),
        ] {
            let tp = toolpath_on(&scattered(n), MachineKind::Mill);
            // The whole path, and stepped to a block: the ghost of the
            // moves after it and the block's highlight too.
            for step in [None, Some(1234)] {
                let scene = Scene {
                    step,
                    ..Scene::default()
                };
                let mut whole = scene_drawn(&tp, &scene, size, false);
                let mut parts = scene_drawn(&tp, &scene, size, true);
                assert_eq!(whole.factor(), coarse);
                assert_eq!(parts.factor(), coarse);
                let what = format!("at {size:?}, step {step:?}");
                assert_same_pixels(&mut whole, &mut parts, &what);
            }
        }
    }
}
