//! The renderer: draws a [`Toolpath`] fitted to a surface — background, a
//! 1-2-5 grid with coordinate labels, the axes through the origin, a scale bar,
//! the programmed path (thin, dashed) and the actual path (solid), rapid and
//! feed moves in distinct colours, and a legend.
//!
//! It draws through the small [`Surface`] trait so that one renderer serves
//! two backends: [`svg::SvgSurface`] (a string, native and wasm; how the
//! renderer is tested) and `canvas::CanvasSurface` (an OffscreenCanvas 2D
//! context through web-sys, wasm only), which lets the page draw a million
//! segments without them ever crossing into JavaScript. What a frame keeps
//! for the next one (the pixel layer's drawings and their tracings, what
//! the canvas shows) has one owner, [`Kept`].
//!
//! Everything is laid out in CSS pixels; a backend scales to device pixels.

mod annotate;
#[cfg(target_arch = "wasm32")]
pub mod canvas;
pub mod display;
mod holes;
mod kept;
mod orbit;
mod paths;
pub mod raster;
mod resume;
pub mod scene;
pub mod style;
pub mod svg;
#[cfg(test)]
mod test_support;
mod tool;
mod tracer;
pub mod view;

use crate::setup::MachineKind;
use crate::toolpath::{ArcPoints, Toolpath};
pub use annotate::grid_step;
use annotate::{draw_axes, draw_grid, draw_legend, draw_scale_bar, legend_row_count};
pub use kept::{Kept, LayerPut, ShownLayer};
#[cfg(test)]
use paths::draw_path;
use paths::draw_paths;
pub use raster::Raster;
pub use scene::Scene;
pub use style::{Align, Font, Stroke, Theme};
pub use view::{Angles, Extent, Plane, Projection, Rect, Transform, nice_step};

/// What draws the paths: strokes of straight segments in CSS pixels, y down.
pub trait Pen {
    /// Starts a path stroked with `stroke` when [`Pen::stroke`] is called.
    fn begin_path(&mut self, stroke: &Stroke);
    /// Starts a sub-path at a point.
    fn move_to(&mut self, x: f64, y: f64);
    /// Adds a straight segment to the current sub-path.
    fn line_to(&mut self, x: f64, y: f64);
    /// Strokes the path begun by [`Pen::begin_path`].
    fn stroke(&mut self);
    /// The next move of the path starts at (x, y), the point drawn last,
    /// continuing the line; with `restart`, a dashed line's pattern starts
    /// afresh there (a new sub-path: [`RESTART_EVERY`] says where), else
    /// the line goes on as it was.
    fn next_move(&mut self, x: f64, y: f64, restart: bool) {
        if restart {
            self.move_to(x, y);
        }
    }
    /// Starts a named group of drawing (an SVG `<g class>`; a canvas ignores it).
    fn begin_group(&mut self, _name: &str) {}
    /// Ends the group started last.
    fn end_group(&mut self) {}
    /// How the points of arcs are placed for this pen: exactly (the
    /// default; a vector output's text must not change), or turned point
    /// to point for a pixel layer ([`ArcPoints`]).
    fn arc_points(&self) -> ArcPoints {
        ArcPoints::Exact
    }
    /// Whether this pen takes the next arc whole ([`Pen::arc`]) rather
    /// than as its points: a pixel layer does in large drawings, and
    /// tessellates only the arcs it does not find hidden (most, front to
    /// back in a dense drawing).
    fn takes_arcs(&self) -> bool {
        false
    }
    /// Adds an arc to the current sub-path, which is at its start (see
    /// [`Pen::takes_arcs`]); false when this one is to come as its points
    /// instead.
    fn arc(&mut self, _arc: &WholeArc) -> bool {
        false
    }
}

/// An arc on the screen (CSS pixels, y down), whole: from `from` about
/// `centre` through `sweep` radians (positive from +x towards +y) to `to`,
/// drawn as `count` equal segments.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WholeArc {
    /// The circle's centre.
    pub centre: (f64, f64),
    /// Where the arc starts (the current point).
    pub from: (f64, f64),
    /// Where it ends.
    pub to: (f64, f64),
    /// Its turn about the centre.
    pub sweep: f64,
    /// Its segments.
    pub count: usize,
}

/// A 2D drawing surface in CSS pixels, y down.
pub trait Surface: Pen {
    /// Fills the whole surface with a colour.
    fn clear(&mut self, width: f64, height: f64, color: &str);
    /// What the surface keeps from one frame to the next ([`Kept`]), with a
    /// drawing begun on its transparent pixel layer the size of the surface,
    /// for the paths of a large drawing — when the backend has one (the
    /// page's canvas; see [`raster`] for why). None: draw them as vectors.
    fn kept(&mut self) -> Option<&mut Kept> {
        None
    }
    /// Puts what was drawn on the layer of [`Surface::kept`] on the
    /// surface; `transform` is the one it was drawn with.
    fn composite(&mut self, _transform: &Transform) {}
    /// Puts the last layer composited back on the surface, moved and scaled
    /// from its transform to `transform`, if the backend kept it and it
    /// shows the same thing; false when it did not (then draw the paths).
    /// With `exact`, only when `transform` is the one it was drawn with: the
    /// same pixels as drawing it again.
    fn reuse_layer(&mut self, _transform: &Transform, _exact: bool) -> bool {
        false
    }
    /// Fills a rectangle, with an optional one-pixel border.
    fn fill_rect(&mut self, rect: Rect, fill: &str, border: Option<&str>);
    /// Draws a text; `y` is its alphabetic baseline. Text is data, never markup.
    fn fill_text(&mut self, text: &str, x: f64, y: f64, font: &Font);
    /// Fills a closed polygon (arrow heads).
    fn fill_polygon(&mut self, points: &[(f64, f64)], fill: &str);
    /// A circle of radius `r`, filled and/or stroked (the tool marker).
    fn circle(&mut self, x: f64, y: f64, r: f64, fill: Option<&str>, stroke: Option<&Stroke>);
}

/// Space kept free around the path: left (vertical labels), right, top,
/// bottom (horizontal labels and the scale bar).
const MARGIN: (f64, f64, f64, f64) = (52.0, 24.0, 24.0, 48.0);
/// Grid lines are at least this far apart.
const MIN_GRID_PX: f64 = 40.0;
/// The scale bar is at least this long.
const MIN_SCALE_PX: f64 = 70.0;
/// Vertices closer than this to the last one drawn are skipped (level of
/// detail: a million tiny segments cost a million calls for nothing).
const MIN_SEGMENT_PX: f64 = 0.5;
/// Where a dashed path's pattern starts afresh: at a move after one whose
/// ends are at least a period of the pattern apart on screen (along x or
/// y), and at every move whose number is a multiple of this. So how a move
/// is dashed depends on a few moves before it at most, not on the length
/// of all of them, and an edit
/// changes the drawing only around the moves it changes ([`Raster`] keeps
/// the pixels of the others); short moves (a surface milled in steps of a
/// pixel or two) still show dashes run across several of them.
pub const RESTART_EVERY: usize = 16;
/// Toolpaths of this many moves or more are drawn on the surface's pixel
/// layer when it has one ([`Surface::raster`]); smaller ones as vector
/// strokes, which have round joins and the browser's own anti-aliasing.
pub const RASTER_FROM_MOVES: usize = 2_000;

/// While the 3D view is turned (a gesture's moving frame), a path of more
/// moves than this is drawn by a sample of about this many, spread evenly
/// over it: a turned view cannot reuse the last frame's pixels as a pan
/// does, and the whole path's frame comes when the gesture pauses
/// (behaviour 10.8).
pub const ORBIT_MOVES: usize = 10_000;
/// Toolpaths of this many moves or more are drawn on the pixel layer in
/// parts, front to back, what lies hidden not even recorded
/// ([`Raster::plan`]): from here a drawing records more points than
/// [`Raster`] keeps for the next edit (1 Mi: four points a move, a
/// sub-path of two for each path), so nothing is lost by drawing it so.
pub const IN_PARTS_FROM_MOVES: usize = 1 << 18;
/// Arcs are drawn as polylines no farther than this (CSS pixels) from the
/// true circle at the scale drawn: smooth at any zoom, and a few segments
/// for an arc that is a few pixels across.
pub const DRAW_TOLERANCE_PX: f64 = 0.2;
/// Legend geometry.
const LEGEND_WIDTH: f64 = 218.0;
const LEGEND_WIDTH_COMPACT: f64 = 150.0;
/// Views narrower or lower than this (CSS pixels) get the short legend.
const COMPACT_BELOW: (f64, f64) = (720.0, 440.0);
const LEGEND_ROW: f64 = 17.0;
const LEGEND_PAD: f64 = 8.0;

/// Where things go on a surface of a given size.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    /// Surface width in CSS pixels.
    pub width: f64,
    /// Surface height in CSS pixels.
    pub height: f64,
    /// The plane drawn.
    pub plane: Plane,
    /// The plane's projection, worked out once for the frame.
    pub projection: Projection,
    /// Every how many moves one is drawn: 1, but in a frame of a 3D
    /// view being turned over a large path ([`ORBIT_MOVES`]).
    pub stride: usize,
    /// The rectangle the path is fitted into.
    pub plot: Rect,
    /// The legend box.
    pub legend: Rect,
    /// World to screen.
    pub transform: Transform,
    /// Colours.
    pub theme: &'static Theme,
    /// The legend has a row for the tool marker (when stepping).
    pub tool_row: bool,
    /// The short legend of small views (embedded lessons, phones).
    pub compact: bool,
    /// The legend is drawn (not folded away, behaviour 10.7).
    pub legend_shown: bool,
    /// The path has holes seen as points in this plane (behaviour 6.11):
    /// their rings are drawn, and the legend has their row.
    pub holes: bool,
}

impl Frame {
    /// Lays out a surface and fits the toolpath (both paths) into it. The
    /// legend sits in the top right corner; the path gets the whole surface
    /// less the margins when it clears the legend there, otherwise the larger
    /// of the area beside the legend and the area below it, so the legend
    /// never covers the path.
    pub fn fit(toolpath: &Toolpath, plane: Plane, width: f64, height: f64) -> Frame {
        Frame::fit_with(
            toolpath,
            plane,
            width,
            height,
            &style::LIGHT,
            false,
            true,
            scene::Reach::default(),
        )
    }

    /// [`Frame::fit`] with a colour scheme and, when `tool_row`, room in
    /// the legend for the tool marker; without `legend` (folded away) the
    /// path gets the whole surface less the margins; the path's box grown
    /// by `reach`, what is drawn round the tool (behaviour 10.5).
    #[allow(clippy::too_many_arguments)]
    pub fn fit_with(
        toolpath: &Toolpath,
        plane: Plane,
        width: f64,
        height: f64,
        theme: &'static Theme,
        tool_row: bool,
        legend_shown: bool,
        reach: scene::Reach,
    ) -> Frame {
        let width = if width.is_finite() {
            width.max(1.0)
        } else {
            1.0
        };
        let height = if height.is_finite() {
            height.max(1.0)
        } else {
            1.0
        };
        // A full legend would take a third of a small view and squeeze the
        // path beside it; small views get the short one.
        let compact = width < COMPACT_BELOW.0 || height < COMPACT_BELOW.1;
        let holes = holes::has_holes(toolpath, plane);
        let rows = legend_row_count(plane, theme, tool_row, compact, holes) as f64 + 1.0;
        let legend_h = rows * LEGEND_ROW + 2.0 * LEGEND_PAD;
        let legend_w = if compact {
            LEGEND_WIDTH_COMPACT
        } else {
            LEGEND_WIDTH
        };
        let legend = if legend_shown {
            Rect::new(width - legend_w - 10.0, 10.0, legend_w, legend_h)
        } else {
            Rect::new(width - 10.0, 10.0, 0.0, 0.0)
        };
        let (l, r, t, b) = MARGIN;
        let full = Rect::new(l, t, (width - l - r).max(1.0), (height - t - b).max(1.0));
        let beside = Rect::new(l, t, legend.x - 12.0 - l, full.h);
        let below_top = legend.bottom() + 8.0;
        let below = Rect::new(l, below_top, full.w, height - b - below_top);
        let min_size = 10.0 / toolpath.units.mm();
        let (extent, min_size) = match reaching_extent(toolpath, plane, reach) {
            Some(extent) => (extent, min_size),
            // Nothing drawn: show the origin and a few grid cells around it.
            None => (Extent::point(0.0, 0.0), 10.0 * min_size),
        };
        let fit = |plot: Rect| (plot, Transform::fit(extent, plot, min_size));
        let (plot, transform) = {
            let (plot, t) = fit(full);
            let drawn = t.screen_rect(&extent);
            let inflated = Rect::new(drawn.x - 4.0, drawn.y - 4.0, drawn.w + 8.0, drawn.h + 8.0);
            if !legend_shown || !inflated.intersects(&legend) {
                (plot, t)
            } else {
                [beside, below]
                    .into_iter()
                    .filter(|p| p.w > 40.0 && p.h > 40.0)
                    .map(fit)
                    .max_by(|a, b| a.1.scale.total_cmp(&b.1.scale))
                    .unwrap_or((plot, t))
            }
        };
        Frame {
            width,
            height,
            plane,
            projection: plane.projection(),
            stride: 1,
            plot,
            legend,
            transform,
            theme,
            tool_row,
            compact,
            legend_shown,
            holes,
        }
    }

    /// Where the scale bar goes and the length it stands for, or None
    /// when it would not fit.
    pub fn scale_bar(&self) -> Option<(Rect, f64)> {
        let length = nice_step(MIN_SCALE_PX / self.transform.scale);
        let px = length * self.transform.scale;
        if !px.is_finite() || px > self.width * 0.6 {
            return None;
        }
        let right = self.width - MARGIN.1;
        let y = self.height - 30.0;
        Some((
            Rect::new(right - px - 6.0, y - 20.0, px + 12.0, 28.0),
            length,
        ))
    }
}

/// The box of both paths in the plane (with the centre line on the lathe):
/// the box of the projections of their 3D box's eight corners, arcs
/// included (in the 3D view the projected box, behaviour 10.8).
pub fn path_extent(toolpath: &Toolpath, plane: Plane) -> Option<Extent> {
    reaching_extent(toolpath, plane, scene::Reach::default())
}

/// [`path_extent`] of the paths' 3D box grown by `reach`, what is drawn
/// round the tool over the run (behaviour 10.5): a constant of the run,
/// so a frame pays eight projections for it.
pub fn reaching_extent(toolpath: &Toolpath, plane: Plane, reach: scene::Reach) -> Option<Extent> {
    let bounds = toolpath.bounds()?;
    let bounds = if reach == scene::Reach::default() {
        bounds
    } else {
        reach.grow(bounds, toolpath.machine == MachineKind::Lathe)
    };
    let mut extent = tool::projected_box(plane, bounds);
    if let (Some(e), true) = (&mut extent, plane.has_centre_line()) {
        e.include(e.min_u, 0.0);
    }
    if let (Some(e), true) = (&mut extent, plane.has_spindle_centre()) {
        e.include(0.0, 0.0);
    }
    extent
}

/// Draws the toolpath on a surface of `width` x `height` CSS pixels, in its
/// machine's usual plane.
pub fn draw(surface: &mut impl Surface, toolpath: &Toolpath, width: f64, height: f64) -> Frame {
    let plane = Plane::for_machine(toolpath.machine);
    draw_in(surface, toolpath, plane, width, height)
}

/// Draws the toolpath in a given plane.
pub fn draw_in(
    surface: &mut impl Surface,
    toolpath: &Toolpath,
    plane: Plane,
    width: f64,
    height: f64,
) -> Frame {
    let scene = Scene {
        plane,
        ..Scene::default()
    };
    draw_scene(surface, toolpath, &scene, width, height)
}

/// Draws the toolpath as a [`Scene`] asks: its plane, zoom and pan, colours,
/// and when it has a current block, the path up to that block in colour and
/// the rest faint, the block highlighted and the tool marker at its end.
/// Arrows go from the programmed to the actual end point of every drawn
/// block where the two differ.
pub fn draw_scene(
    surface: &mut impl Surface,
    toolpath: &Toolpath,
    scene: &Scene,
    width: f64,
    height: f64,
) -> Frame {
    draw_scene_as(surface, toolpath, scene, width, height, false)
}

/// [`draw_scene`] while the view is being moved (a pan or zoom gesture):
/// when the paths are drawn as pixels and the surface kept the last ones,
/// they are that image moved and scaled (and the arrows left out) — a frame
/// of a million-move path in the time of one image copy. The frame after
/// the gesture is drawn with [`draw_scene`].
pub fn draw_scene_moving(
    surface: &mut impl Surface,
    toolpath: &Toolpath,
    scene: &Scene,
    width: f64,
    height: f64,
) -> Frame {
    draw_scene_as(surface, toolpath, scene, width, height, true)
}

fn draw_scene_as(
    surface: &mut impl Surface,
    toolpath: &Toolpath,
    scene: &Scene,
    width: f64,
    height: f64,
    moving: bool,
) -> Frame {
    let mut frame = scene.frame(toolpath, width, height);
    let moves = toolpath.len();
    if moving && frame.plane.is_orbit() && moves > ORBIT_MOVES {
        frame.stride = moves.div_ceil(ORBIT_MOVES);
    }
    let sampled = frame.stride > 1;
    let split = scene.drawn_moves(toolpath);
    surface.clear(frame.width, frame.height, frame.theme.background);
    if frame.plane.is_orbit() {
        orbit::draw_grid(surface, &frame, toolpath);
        orbit::draw_axes(surface, &frame, toolpath);
    } else {
        draw_grid(surface, &frame);
        draw_axes(surface, &frame);
    }
    // Past a few thousand moves the canvas's own stroking is what makes a
    // frame slow (`raster`): the paths go on a pixel layer instead.
    let large = moves >= RASTER_FROM_MOVES;
    // A layer kept from a drawing of the same paths at the same place (a
    // run whose path did not change: an edit of an N number, a comment, a
    // feed) is that drawing; during a gesture it is moved and scaled.
    // The swept band is vectors under the paths, never on their kept layer
    // (behaviour 16.20).
    paths::draw_swept(surface, &frame, toolpath, scene, split);
    let reused = large && !sampled && surface.reuse_layer(&frame.transform, !moving);
    let moved = (reused && moving) || sampled;
    if reused {
        // A moved layer's arrows come back with the next whole frame.
    } else if large && let Some(kept) = surface.kept() {
        kept.draw_paths(&frame, toolpath, scene, split);
        surface.composite(&frame.transform);
    } else {
        draw_paths(surface, &frame, toolpath, scene, split);
    }
    if !moved {
        holes::draw_holes(surface, &frame, toolpath, split);
        scene::draw_arrows(surface, &frame, toolpath, split);
    }
    if let Some(marker) = scene.marker {
        tool::draw_marker(surface, &frame, marker, (scene.cutter, scene.tool));
    }
    draw_scale_bar(surface, &frame, toolpath);
    draw_legend(surface, &frame, toolpath);
    frame
}

/// True for moves drawn in the rapid colour: G00 and offset motion in G00.
pub fn is_rapid(kind: u8) -> bool {
    kind == 0 || kind == 4
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::test_support::toolpath;

    #[test]
    fn path_never_runs_under_the_legend_and_stays_on_the_surface() {
        let tp = toolpath(
            "G90 G00 X-30. Y-20.\nG91 G46 X30. Y20. D01\nG01 G47 X80. F200.\nG47 Y50.\nG47 X-80.\nG47 Y-50.",
        );
        let extent = path_extent(&tp, Plane::Xy).unwrap();
        for (w, h) in [
            (800.0, 500.0),
            (500.0, 800.0),
            (904.0, 820.0),
            (400.0, 300.0),
            (1600.0, 400.0),
        ] {
            let f = Frame::fit(&tp, Plane::Xy, w, h);
            let drawn = f.transform.screen_rect(&extent);
            assert!(
                !drawn.intersects(&f.legend),
                "{w}x{h}: {drawn:?} under {:?}",
                f.legend
            );
            assert!(drawn.x >= 0.0 && drawn.y >= 0.0, "{w}x{h}: {drawn:?}");
            assert!(
                drawn.right() <= w && drawn.bottom() <= h,
                "{w}x{h}: {drawn:?}"
            );
        }
    }

    #[test]
    fn a_path_clear_of_the_legend_gets_the_whole_surface() {
        // A wide, flat path stays below the legend when fitted to the full
        // width: no room is given away beside the legend.
        let tp = toolpath("G01 X100. F100.");
        let f = Frame::fit(&tp, Plane::Xy, 800.0, 600.0);
        assert_eq!(f.plot.w, 800.0 - MARGIN.0 - MARGIN.1);
    }

    #[test]
    fn grid_spacing_is_at_least_the_minimum_and_one_two_five() {
        for scale in [0.013, 0.5, 1.0, 3.7, 40.0, 1234.0] {
            let t = Transform {
                scale,
                origin_x: 0.0,
                origin_y: 0.0,
            };
            let step = grid_step(&t);
            assert!(step * scale >= MIN_GRID_PX * (1.0 - 1e-9));
            assert!(step * scale < MIN_GRID_PX * 5.0 + 1e-9, "not too sparse");
            let mantissa = step / 10f64.powf(step.log10().floor());
            assert!(
                [1.0, 2.0, 5.0].iter().any(|m| (mantissa - m).abs() < 1e-9),
                "{step}"
            );
        }
    }

    #[test]
    fn a_dashed_path_starts_its_pattern_afresh_after_long_moves_and_every_sixteen() {
        // Where each programmed feed sub-path starts (move_to), and the
        // moves that continue it without a new pattern (next_move, false).
        #[derive(Default)]
        struct Starts {
            dashed: bool,
            starts: Vec<usize>,
            ongoing: Vec<usize>,
            moves: usize,
        }
        impl Pen for Starts {
            fn begin_path(&mut self, stroke: &Stroke) {
                self.dashed = stroke.dash == style::PROGRAMMED_FEED.dash;
            }
            fn move_to(&mut self, _: f64, _: f64) {
                if self.dashed {
                    self.starts.push(self.moves);
                }
            }
            fn line_to(&mut self, _: f64, _: f64) {
                if self.dashed {
                    self.moves += 1;
                }
            }
            fn next_move(&mut self, x: f64, y: f64, restart: bool) {
                if restart {
                    self.move_to(x, y);
                } else if self.dashed {
                    self.ongoing.push(self.moves);
                }
            }
            fn stroke(&mut self) {}
        }
        // 40 moves across the view (100 mm in some 500 px), then 40 of half
        // a millimetre (a fraction of the pattern's 10 px) each.
        let mut program = String::from("G90 G01 F100.\n");
        for k in 1..=40 {
            let x = if k % 2 == 1 { 100 } else { 0 };
            program.push_str(&format!("X{x}. Y{k}.\n"));
        }
        program.push_str("G91\n");
        for _ in 0..40 {
            program.push_str("X0.5\n");
        }
        let tp = toolpath(&program);
        let f = Frame::fit(&tp, Plane::Xy, 640.0, 480.0);
        let mut pen = Starts::default();
        draw_path(&mut pen, &f, &tp, true, 0..tp.len(), |_| {
            &style::PROGRAMMED_FEED
        });
        assert_eq!(pen.moves, 80);
        // Every move after a long one starts afresh (the first short one
        // too); the short ones run the pattern on, afresh at moves 48 and
        // 64 (multiples of RESTART_EVERY).
        let mut afresh: Vec<usize> = (0..=40).collect();
        afresh.extend([48, 64]);
        assert_eq!(pen.starts, afresh);
        let ongoing: Vec<usize> = (41..80).filter(|m| m % RESTART_EVERY != 0).collect();
        assert_eq!(pen.ongoing, ongoing);
    }

    #[test]
    fn level_of_detail_skips_sub_pixel_vertices_but_keeps_ends() {
        #[derive(Default)]
        struct Count {
            lines: usize,
            last: (f64, f64),
        }
        impl Pen for Count {
            fn begin_path(&mut self, _: &Stroke) {}
            fn move_to(&mut self, _: f64, _: f64) {}
            fn line_to(&mut self, x: f64, y: f64) {
                self.lines += 1;
                self.last = (x, y);
            }
            fn stroke(&mut self) {}
        }
        // 5000 feed moves of 0.001 mm after one long move: on a small
        // surface almost all of them are below half a pixel.
        let mut program = String::from("G91 G01 X100. F100.\n");
        for _ in 0..5000 {
            program.push_str("X0.001\n");
        }
        let tp = toolpath(&program);
        let f = Frame::fit(&tp, Plane::Xy, 200.0, 200.0);
        let mut count = Count::default();
        let stroke = style::ACTUAL_FEED;
        draw_path(&mut count, &f, &tp, false, 0..tp.len(), |_| &stroke);
        assert!(count.lines < 100, "{} segments drawn", count.lines);
        // The very end (X105.) is drawn exactly.
        let (u, v) = Plane::Xy.project(&tp.actual[tp.actual.len() - 3..]);
        assert_eq!(count.last, f.transform.to_screen(u, v));
        assert!((u - 105.0).abs() < 1e-9);

        // Arcs are tessellated for the scale drawn: 2,000 circles of 1 mm
        // on a 100 mm part, 200 px wide, are a few segments each, and the
        // same circle zoomed to fill the view is smooth.
        let mut program = String::from("G01 X100. F100.\nG00 X0\n");
        program.push_str(&"G02 X0 Y0 I0.5 J0\n".repeat(2000));
        let tp = toolpath(&program);
        let f = Frame::fit(&tp, Plane::Xy, 200.0, 200.0);
        let mut count = Count::default();
        draw_path(&mut count, &f, &tp, false, 0..tp.len(), |_| &stroke);
        assert!(count.lines < 2000 * 8, "{} segments drawn", count.lines);
        let one = toolpath("G02 X0 Y0 I0.5 J0 F100.\n");
        let f = Frame::fit(&one, Plane::Xy, 800.0, 800.0);
        let mut count = Count::default();
        draw_path(&mut count, &f, &one, false, 0..1, |_| &stroke);
        assert!(
            count.lines > 60,
            "{} segments for a circle 700 px across",
            count.lines
        );
    }

    /// A surface with a pixel layer, which counts what it is asked to do.
    #[derive(Default)]
    struct Layered {
        kept: Kept,
        composited: usize,
        vector_paths: usize,
    }
    impl Pen for Layered {
        fn begin_path(&mut self, _: &Stroke) {
            self.vector_paths += 1;
        }
        fn move_to(&mut self, _: f64, _: f64) {}
        fn line_to(&mut self, _: f64, _: f64) {}
        fn stroke(&mut self) {}
    }
    impl Surface for Layered {
        fn clear(&mut self, _: f64, _: f64, _: &str) {}
        fn kept(&mut self) -> Option<&mut Kept> {
            self.kept
                .begin(400, 300, (1.0, 1.0))
                .then_some(&mut self.kept)
        }
        fn composite(&mut self, _: &Transform) {
            self.composited += 1;
        }
        fn fill_rect(&mut self, _: Rect, _: &str, _: Option<&str>) {}
        fn fill_text(&mut self, _: &str, _: f64, _: f64, _: &Font) {}
        fn fill_polygon(&mut self, _: &[(f64, f64)], _: &str) {}
        fn circle(&mut self, _: f64, _: f64, _: f64, _: Option<&str>, _: Option<&Stroke>) {}
    }

    /// The opaque colours of a surface's pixel layer.
    fn layer_colours(s: &mut Layered) -> std::collections::HashSet<String> {
        let raster = s.kept.raster();
        let (w, h) = raster.size();
        let mut colours = std::collections::HashSet::new();
        for y in 0..h {
            for x in 0..w {
                let [r, g, b, a] = raster.pixel(x, y);
                if a == 255 {
                    colours.insert(format!("#{r:02x}{g:02x}{b:02x}"));
                }
            }
        }
        colours
    }

    /// Two rapids (the second, upwards at X-50, apart from everything
    /// else), then RASTER_FROM_MOVES feed moves zigzagging `dy` mm up and
    /// down, `dx` mm apart.
    fn zigzag(dx: f64, dy: f64) -> Toolpath {
        let mut program = String::from("G90 G00 X-50. Y30.\nY80.\nG01 F100.\n");
        for i in 0..RASTER_FROM_MOVES {
            let x = 5.0 + dx * (i % 2000) as f64;
            program.push_str(&format!("X{x:.3} Y{:.3}\n", (i % 2) as f64 * dy));
        }
        toolpath(&program)
    }

    #[test]
    fn large_paths_go_on_the_pixel_layer_in_their_colours_small_ones_stay_vectors() {
        // 2,000 moves along 1,000 mm: a band of lines, on the full grid.
        let tp = zigzag(0.5, 1.0);
        assert!(tp.len() >= RASTER_FROM_MOVES);
        let mut s = Layered::default();
        draw_scene(&mut s, &tp, &Scene::default(), 400.0, 300.0);
        assert_eq!(s.composited, 1);
        assert_eq!(s.kept.raster().factor(), 1);
        let around = s.vector_paths; // grid, axes, scale bar, legend samples
        let colours = layer_colours(&mut s);
        let drawn = [
            style::ACTUAL_FEED.color,
            style::PROGRAMMED_FEED.color,
            style::ACTUAL_RAPID.color,
            style::PROGRAMMED_RAPID.color,
        ];
        for c in drawn {
            assert!(colours.contains(c), "{c} in {colours:?}");
        }
        // A small program: vector strokes, no layer.
        let small = toolpath("G90 G00 X-10. Y20.\nG01 X10. F100.\n");
        let mut s = Layered::default();
        draw_scene(&mut s, &small, &Scene::default(), 400.0, 300.0);
        assert_eq!(s.composited, 0);
        // The same, and the four paths: actual and programmed, rapid and feed.
        assert_eq!(s.vector_paths, around + 4);
    }

    #[test]
    fn dense_paths_are_drawn_on_the_coarse_grid() {
        // The same number of moves, 40 mm up and down within 50 mm: the
        // lines cover the 400 x 300 surface many times over.
        let tp = zigzag(0.025, 40.0);
        let mut s = Layered::default();
        draw_scene(&mut s, &tp, &Scene::default(), 400.0, 300.0);
        assert_eq!(s.composited, 1);
        assert_eq!(s.kept.raster().factor(), 2);
        assert_eq!(s.kept.raster().size(), (200, 150));
        // The actual path's lines (2.25 px) still have pixels of their own
        // colour; the thinner programmed ones blend with what lies below.
        let colours = layer_colours(&mut s);
        for c in [style::ACTUAL_FEED.color, style::ACTUAL_RAPID.color] {
            assert!(colours.contains(c), "{c} in {colours:?}");
        }
    }
}
