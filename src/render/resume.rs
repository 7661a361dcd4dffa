//! A kept drawing's paths recorded again only where an edit changed them.
//!
//! Why: after a one-character edit of a 10k-block program, the page's
//! frame is drawn again only where the path changed ([`Raster`]'s
//! `keep`), but every move was still traced — projected, passed through
//! the level of detail, clipped and recorded — to find which: a large
//! part of such a frame, for moves that the edit left as they were (the
//! kept frame's instruction count of `examples/render_time` with `EDITED`,
//! in `docs/performance.md`, guards it).
//!
//! How: while a path is traced, where the tracing stands (the tracer's
//! state, the recorder's, and how much is recorded) is noted at the start
//! of every [`EVERY`]-th move. The next drawing of the same view compares
//! its toolpath with the one traced ([`Toolpath::shared_moves`]): the moves
//! they share at the start and, shifted by the moves the edit added or
//! took away, at the end. Each path takes the last drawing's recording up
//! to its last checkpoint before the first changed move (the state there
//! is the same, so going on from it records what tracing from the start
//! would), traces from there, and at each checkpoint past the changed
//! moves compares where it stands with where the last tracing stood at the
//! same move: once the two agree, the rest is the last recording's, and is
//! taken as it is. What comes out is the recording that tracing the whole
//! path makes, point for point (the tests compare the two), so the pixels
//! are those of a drawing from nothing.

use std::ops::Range;

use super::paths::{Layer, Tracer, TracerState, draw_paths, layers};
use super::raster::{Drawing, Recorded};
use super::{Frame, Pen, RESTART_EVERY, Raster, Scene};
use crate::toolpath::Toolpath;

/// Checkpoints are noted every this many moves of a path (about a thousand
/// bytes per thousand moves; a resumed path traces up to this many moves
/// before the first changed one).
const EVERY: usize = 16;

/// What was traced to make a drawing's recording: the toolpath and the
/// view, and per path where the tracing stood at its checkpoints. Kept with
/// the raster's recording of the drawing ([`super::Kept`]).
pub(crate) struct Traced {
    toolpath: Toolpath,
    frame: Frame,
    paths: Vec<TracedPath>,
}

/// One path (one [`Layer`]) as it was traced.
struct TracedPath {
    layer: Layer,
    /// Its style in the recording, once begun.
    style: Option<u16>,
    /// Where the tracing stood at the start of some of its moves, in
    /// order: the first at its first move.
    marks: Vec<Mark>,
    /// Where it stood when done.
    end: Mark,
}

/// Where the tracing of a path stood at the start of move `m`.
#[derive(Clone, Copy, Debug)]
struct Mark {
    m: usize,
    tracer: TracerState,
    recorded: Recorded,
}

impl Mark {
    /// The same state, bit for bit (the path begun: before that the
    /// recorder's pen is the last path's, and not looked at), of a path
    /// `dashed` or not ([`Recorded::same_pen`]).
    fn same(&self, other: &Mark, dashed: bool) -> bool {
        self.tracer.begun
            && self.tracer.same(&other.tracer)
            && self.recorded.same_pen(&other.recorded, dashed)
    }

    /// This mark, of the last tracing, where it falls in this one: `by`
    /// moves on, and the recordings' lengths moved by what lies between
    /// `from` (of the last) and `to` (of this one).
    fn moved(&self, by: isize, from: &Mark, to: &Mark) -> Mark {
        Mark {
            m: self.m.wrapping_add_signed(by),
            tracer: self.tracer,
            recorded: to.recorded.plus(&from.recorded, &self.recorded),
        }
    }
}

/// How this toolpath's moves stand to those traced last: the first
/// `shared` are the same, and from `end_from` on they are the last ones
/// from `end_from - shift` on.
#[derive(Clone, Copy, Debug)]
struct Shared {
    shared: usize,
    end_from: usize,
    shift: isize,
}

/// A kept drawing's tracing to take pieces of: which drawing it traced,
/// and how its moves stand to these.
struct Source<'a> {
    which: Drawing,
    traced: &'a Traced,
    shared: Shared,
}

/// How a drawing's paths were recorded ([`record_paths`]).
pub(super) struct RecordedPaths {
    /// What was traced, for the next drawing; None when the paths were
    /// recorded in one go, not so that pieces of the recording can be taken.
    pub(super) traced: Option<Box<Traced>>,
    /// How many moves of its paths were traced (each path counts its moves).
    pub(super) moves_traced: usize,
}

/// [`draw_paths`] on a raster, taking from the last drawing's recording
/// (or from the one before it's) the pieces that tracing the paths again
/// would record alike: `tracings` are what was traced to make them (the
/// last drawing's first), when the raster lets this drawing take pieces of
/// their recordings ([`Raster::resumable`]).
pub(super) fn record_paths(
    r: &mut Raster,
    tracings: [Option<&Traced>; 2],
    f: &Frame,
    tp: &Toolpath,
    scene: &Scene,
    split: usize,
) -> RecordedPaths {
    let layers = layers(f, tp, scene, split);
    let source = choose(tracings, f, tp, &layers);
    let mut traced = Traced {
        toolpath: tp.clone(),
        frame: *f,
        paths: Vec::with_capacity(layers.len()),
    };
    let mut resumed = false;
    let mut copied = true;
    let mut visited = 0;
    for (k, layer) in layers.iter().enumerate() {
        let last = source.as_ref().map(|s| (s, &s.traced.paths[k]));
        let (path, took) = trace_path(r, f, tp, layer, last, &mut copied, &mut visited);
        resumed |= took;
        traced.paths.push(path);
    }
    if !copied || (resumed && r.recorded().points >= r.most_resumed()) {
        // A piece could not be taken as it was, or a recording this long
        // would not be made alike in pieces: in one go.
        r.restart();
        draw_paths(r, f, tp, scene, split);
        return RecordedPaths {
            traced: None,
            moves_traced: layers.iter().map(|l| l.moves.len()).sum(),
        };
    }
    RecordedPaths {
        traced: Some(Box::new(traced)),
        moves_traced: visited,
    }
}

/// Of the last drawing and the one before it, the one traced in this view
/// with these paths whose toolpath differs from this one in the fewest
/// moves.
fn choose<'a>(
    tracings: [Option<&'a Traced>; 2],
    f: &Frame,
    tp: &Toolpath,
    layers: &[Layer],
) -> Option<Source<'a>> {
    let alike = |t: &Traced| {
        t.frame == *f
            && t.paths.len() == layers.len()
            && t.paths.iter().zip(layers).all(|(p, l)| {
                (p.layer.group, p.layer.kind, p.layer.stroke) == (l.group, l.kind, l.stroke)
            })
    };
    [Drawing::Last, Drawing::BeforeLast]
        .into_iter()
        .zip(tracings)
        .filter_map(|(which, t)| {
            let traced = t.filter(|t| alike(t))?;
            let (start, end) = tp.shared_moves(&traced.toolpath);
            let shared = Shared {
                shared: start,
                end_from: tp.len() - end,
                shift: tp.len() as isize - traced.toolpath.len() as isize,
            };
            Some(Source {
                which,
                traced,
                shared,
            })
        })
        .min_by_key(|s| s.shared.end_from - s.shared.shared)
}

/// Traces one path, resumed from the last tracing of it (`last`) where
/// that records alike; false in `copied` when a piece of the last
/// recording could not be taken, the moves traced added to `visited`.
/// Returns how it was traced, and whether pieces were taken.
fn trace_path(
    r: &mut Raster,
    f: &Frame,
    tp: &Toolpath,
    layer: &Layer,
    last: Option<(&Source, &TracedPath)>,
    copied: &mut bool,
    visited: &mut usize,
) -> (TracedPath, bool) {
    let moves = layer.moves.clone();
    let mut tracer = Tracer::new(&layer.stroke, TracerState::default());
    let mut marks = Vec::with_capacity(moves.len() / EVERY + 2);
    let here = |tracer: &Tracer, r: &Raster, m: usize| Mark {
        m,
        tracer: tracer.state(),
        recorded: r.recorded(),
    };
    let start = here(&tracer, r, moves.start);
    // The last tracing of this path, when it started at the same move.
    let last = last.filter(|(_, path)| path.layer.moves.start == moves.start);
    let mut at = moves.start;
    let mut took = false;
    if let Some((source, path)) = last {
        // Its last checkpoint before the first changed move: up to there the
        // two tracings are the same.
        let upto = source.shared.shared.min(moves.end);
        let i = path.marks.partition_point(|m| m.m <= upto);
        if let Some(resume) = path.marks.get(i.wrapping_sub(1))
            && resume.m > moves.start
        {
            let first = &path.marks[0];
            if resume.tracer.begun {
                r.begin_path(&layer.stroke);
                if let (Some(style), Some(_)) = (r.path_style(), path.style) {
                    let subs = first.recorded.subs..resume.recorded.subs;
                    let points = first.recorded.points..resume.recorded.points;
                    *copied &= r.copy_recorded(source.which, subs, points, style);
                }
                r.add_ink(resume.recorded.ink - first.recorded.ink);
                r.resume_pen(&resume.recorded);
                tracer = Tracer::new(&layer.stroke, resume.tracer);
            }
            marks.extend(
                path.marks[..i - 1]
                    .iter()
                    .map(|m| m.moved(0, first, &start)),
            );
            at = resume.m;
            took = true;
        }
    }
    while at < moves.end {
        let mark = here(&tracer, r, at);
        if let Some((source, path)) = last
            && let Some(j) = same_from(source.shared, path, &moves, &tracer, &mark, r.path_dashed())
        {
            // The rest is the last tracing's.
            let from = &path.marks[j];
            if let (Some(style), Some(_)) = (r.path_style(), path.style) {
                let subs = from.recorded.subs..path.end.recorded.subs;
                let points = from.recorded.points..path.end.recorded.points;
                *copied &= r.copy_recorded(source.which, subs, points, style);
            }
            r.add_ink(path.end.recorded.ink - from.recorded.ink);
            let shift = source.shared.shift;
            marks.push(mark);
            marks.extend(
                path.marks[j + 1..]
                    .iter()
                    .map(|m| m.moved(shift, from, &mark)),
            );
            let end = path.end.moved(shift, from, &mark);
            r.stroke();
            let style = r.path_style();
            let traced = traced_path(layer, style, marks, end);
            return (traced, true);
        }
        marks.push(mark);
        let next = last
            .map(|(source, path)| next_mark(source.shared, path, at))
            .unwrap_or(None)
            .unwrap_or((at / EVERY + 1) * EVERY)
            .min(moves.end);
        tracer.visit(r, f, tp, layer.kind, at..next);
        *visited += next - at;
        at = next;
    }
    let begun = tracer.finish(r);
    if begun {
        r.stroke();
    }
    let end = here(&tracer, r, moves.end);
    let style = begun.then(|| r.path_style()).flatten();
    (traced_path(layer, style, marks, end), took)
}

fn traced_path(layer: &Layer, style: Option<u16>, marks: Vec<Mark>, end: Mark) -> TracedPath {
    TracedPath {
        layer: layer.clone(),
        style,
        marks,
        end,
    }
}

/// Whether the rest of this path, from `mark` (at its move `mark.m`), is
/// what the last tracing recorded from one of its checkpoints on: the
/// moves from there to the end are the same (past the changed ones, or
/// the whole path before them), the path ends at the same move, a dashed
/// pattern starts afresh at the same moves ([`RESTART_EVERY`]), and the
/// tracing stands where the last stood there (how far along a sub-path
/// too when its line is `dashed`). Its checkpoint's index.
fn same_from(
    shared: Shared,
    path: &TracedPath,
    moves: &Range<usize>,
    tracer: &Tracer,
    mark: &Mark,
    dashed: bool,
) -> Option<usize> {
    let q = mark.m;
    let p = if q >= shared.end_from {
        let dashes_alike = !tracer.dashed() || shared.shift % RESTART_EVERY as isize == 0;
        let ends_alike = path.layer.moves.end.checked_add_signed(shared.shift) == Some(moves.end);
        (dashes_alike && ends_alike).then(|| q.checked_add_signed(-shared.shift))??
    } else if moves.end <= shared.shared && path.layer.moves.end == moves.end {
        q
    } else {
        return None;
    };
    let j = path.marks.binary_search_by_key(&p, |m| m.m).ok()?;
    path.marks[j]
        .same(mark, dashed || tracer.dashed())
        .then_some(j)
}

/// Where the next checkpoint goes past move `at`: past the changed moves,
/// where the last tracing had one (so the two can be compared there).
fn next_mark(shared: Shared, path: &TracedPath, at: usize) -> Option<usize> {
    if at < shared.end_from {
        return None;
    }
    let p = at.checked_add_signed(-shared.shift)?;
    let j = path.marks.partition_point(|m| m.m <= p);
    path.marks.get(j)?.m.checked_add_signed(shared.shift)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::test_support::{assert_same_pixels, drawn_from_nothing, toolpath_to_stop};
    use crate::render::{Kept, Plane};

    /// A block of [`program`]: (kind, x, y, r).
    type Block = (u8, f64, f64, f64);

    /// A program of `blocks`: each (kind, x, y, r) a rapid (0), a feed
    /// (1), an arc (2 clockwise, 3 counter-clockwise, of radius `r` times
    /// half its chord) or a rapid in Z (4), to (x, y).
    fn program(blocks: &[Block]) -> String {
        let mut out = String::from("G90 G17 G00 X0 Y0 Z5.\n");
        let mut at = (0.0_f64, 0.0_f64);
        for &(kind, x, y, r) in blocks {
            let chord = (x - at.0).hypot(y - at.1);
            let line = match kind {
                0 => format!("G00 X{x:.3} Y{y:.3}"),
                1 => format!("G01 X{x:.3} Y{y:.3} F300."),
                2 | 3 if chord > 0.01 => {
                    let r = chord / 2.0 * (1.0 + r);
                    format!("G0{kind} X{x:.3} Y{y:.3} R{r:.4} F200.")
                }
                _ => format!("G00 Z{:.3}", 1.0 + r),
            };
            if kind != 4 {
                at = (x, y);
            }
            out.push_str(&line);
            out.push('\n');
        }
        out
    }

    const SURFACE: (usize, usize, f64) = (240, 180, 2.0);

    /// Draws `tp` with `kept` as the page does (resumed where it can be);
    /// asserts that it recorded and painted what a new raster does
    /// drawing it in one go. How many moves were traced.
    fn draws_as_from_nothing(kept: &mut Kept, f: &Frame, tp: &Toolpath, scene: &Scene) -> usize {
        let (w, h, scale) = SURFACE;
        assert!(kept.begin(w, h, (scale, scale)));
        let traced = kept.draw_paths(f, tp, scene, scene.drawn_moves(tp));
        let mut fresh = drawn_from_nothing(f, tp, scene, SURFACE);
        let r = kept.raster();
        assert_eq!(r.kept_recording(), fresh.kept_recording());
        assert_same_pixels(r, &mut fresh, "resumed against from nothing");
        traced
    }

    fn blocks(n: usize) -> Vec<Block> {
        // A pseudo-random walk (a fixed sequence: the test is repeatable).
        let mut seed = 12345_u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        (0..n)
            .map(|_| {
                let kind = [1, 1, 1, 0, 2, 3, 4][(next() * 7.0) as usize % 7];
                (kind, next() * 100.0, next() * 70.0, next())
            })
            .collect()
    }

    /// `n` blocks ([`blocks`]) drawn on a new raster in the default scene,
    /// in a view fitted to them: the blocks, their toolpath, the scene, the
    /// frame, what was kept and how many moves were traced.
    fn first_drawing(n: usize) -> (Vec<Block>, Toolpath, Scene, Frame, Kept, usize) {
        let v = blocks(n);
        let tp = toolpath_to_stop(&program(&v));
        let scene = Scene::default();
        let f = scene.frame(&tp, 120.0, 90.0);
        let mut r = Kept::new();
        let all = draws_as_from_nothing(&mut r, &f, &tp, &scene);
        (v, tp, scene, f, r, all)
    }

    #[test]
    fn an_edit_of_one_move_traces_a_few_moves_and_records_what_tracing_all_does() {
        let (mut v, before, scene, f, mut r, all) = first_drawing(600);
        assert!(all >= 4 * 600, "{all}");
        // A digit typed into a line's X: two moves change.
        v[300].1 += 0.4;
        v[300].0 = 1;
        let after = toolpath_to_stop(&program(&v));
        let traced = draws_as_from_nothing(&mut r, &f, &after, &scene);
        assert!(traced <= 4 * 3 * EVERY, "{traced} of {all}");
        // And back: the last drawing's pieces again.
        let traced = draws_as_from_nothing(&mut r, &f, &before, &scene);
        assert!(traced <= 4 * 3 * EVERY, "{traced} of {all}");
    }

    #[test]
    fn a_block_inserted_traces_from_it_on_only_the_dashed_paths() {
        let (v, before, scene, f, mut r, all) = first_drawing(600);
        let mut w = v.clone();
        w.insert(200, (1, 50.0, 35.0, 0.0));
        let after = toolpath_to_stop(&program(&w));
        // The solid paths take up the last recording again past the new
        // block; the dashed ones (rapids) start their dashes afresh at
        // other moves from there on, and are traced to their ends.
        let traced = draws_as_from_nothing(&mut r, &f, &after, &scene);
        assert!(traced < all * 2 / 3, "{traced} of {all}");
        // Sixteen blocks inserted: the dashes start afresh where they did.
        let mut x = v.clone();
        for k in 0..16 {
            x.insert(200, (1, 50.0 + k as f64, 35.0, 0.0));
        }
        let after = toolpath_to_stop(&program(&x));
        let back = draws_as_from_nothing(&mut r, &f, &before, &scene);
        assert!(back < all * 2 / 3, "{back} of {all}");
        let traced = draws_as_from_nothing(&mut r, &f, &after, &scene);
        assert!(traced <= 4 * 3 * EVERY + 4 * 16, "{traced} of {all}");
    }

    #[test]
    fn a_dense_drawing_made_on_the_coarse_grid_is_taken_up_at_full_scale() {
        let (mut v, _, scene, f, mut r, all) = first_drawing(3000);
        assert_eq!(r.raster().factor(), 2, "the drawing is dense");
        v[1500].1 += 0.4;
        let after = toolpath_to_stop(&program(&v));
        let traced = draws_as_from_nothing(&mut r, &f, &after, &scene);
        assert!(traced <= 4 * 3 * EVERY, "{traced} of {all}");
    }

    #[test]
    fn a_step_through_the_program_is_recorded_as_in_one_go() {
        let v = blocks(400);
        let tp = toolpath_to_stop(&program(&v));
        let f = Scene::default().frame(&tp, 120.0, 90.0);
        let mut r = Kept::new();
        for step in [Some(100), Some(101), Some(250), None, Some(250), Some(3)] {
            let scene = Scene {
                step,
                ..Scene::default()
            };
            draws_as_from_nothing(&mut r, &f, &tp, &scene);
        }
    }

    #[test]
    fn another_view_traces_everything() {
        let tp = toolpath_to_stop(&program(&blocks(300)));
        let scene = Scene::default();
        let f = scene.frame(&tp, 120.0, 90.0);
        let g = Scene {
            plane: Plane::Xz,
            ..Scene::default()
        }
        .frame(&tp, 120.0, 90.0);
        let mut r = Kept::new();
        let all = draws_as_from_nothing(&mut r, &f, &tp, &scene);
        assert_eq!(draws_as_from_nothing(&mut r, &g, &tp, &scene), all);
    }

    // (proptest is a native dev-dependency: `wasm-pack test` builds these too.)
    #[cfg(not(target_arch = "wasm32"))]
    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig { cases: 48, ..Default::default() })]

        #[test]
        fn any_sequence_of_edits_records_what_tracing_all_does(
            blocks in proptest::collection::vec((0u8..5, 0.0..100.0f64, 0.0..70.0f64, 0.0..1.0f64), 20..300),
            edits in proptest::collection::vec((0u8..5, 0usize..300, -3.0..3.0f64, 0u8..3), 1..6),
            zoom in proptest::sample::select(vec![1.0, 3.0]),
        ) {
            let mut v = blocks.clone();
            let first = toolpath_to_stop(&program(&v));
            let view = Scene { zoom, ..Scene::default() };
            let f = view.frame(&first, 120.0, 90.0);
            let mut r = Kept::new();
            draws_as_from_nothing(&mut r, &f, &first, &view);
            for (kind, at, d, step) in edits {
                let i = at % v.len();
                match kind {
                    // A coordinate changed (an arc's may no longer fit its
                    // radius: the run stops there).
                    0 | 1 => v[i].1 += d,
                    2 => v.insert(i, (1, v[i].1 + d, v[i].2, 0.0)),
                    3 if v.len() > 2 => {
                        v.remove(i);
                    }
                    _ => {
                        for k in 0..16 {
                            v.insert(i, (k % 2, v[i].1 + d, v[i].2 - d, 0.0));
                        }
                    }
                }
                let tp = toolpath_to_stop(&program(&v));
                let scene = Scene {
                    step: (step > 0).then_some((at * usize::from(step) % 400) as u32),
                    ..view
                };
                draws_as_from_nothing(&mut r, &f, &tp, &scene);
            }
            // The first again: the drawing before the last may be its.
            draws_as_from_nothing(&mut r, &f, &first, &view);
        }
    }
}
