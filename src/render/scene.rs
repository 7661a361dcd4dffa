//! What the view shows besides the toolpath: the plane, the zoom and pan
//! relative to "fit the whole path", the current block when stepping, the
//! colour scheme — and what follows from them: the camera transform, the
//! arrows from programmed to actual end points, the tool marker, and which
//! block lies under the pointer (picking happens here, in screen space, so
//! the page never needs the vertices).
//!
//! Zoom and pan mean what the document's `view` means (`src/document.rs`):
//! zoom 1 fits the whole path; pan moves the view's centre from the fitted
//! centre, in program units along the plane's horizontal and vertical axes.

use super::style::{LIGHT, Stroke, Theme};
pub use super::tool::{Cutter, Reach, draw_marker, tool_symbol};
use super::{Frame, Plane, Rect, Surface, Transform};
use crate::document::{MAX_PAN, MAX_ZOOM, MIN_ZOOM};
use crate::setup::MachineKind;
use crate::toolpath::{ArcPoints, Toolpath};

/// Arrows shorter than this (CSS pixels) are not drawn: the offset is too
/// small to see at this zoom.
const MIN_ARROW_PX: f64 = 2.5;
/// At most this many arrows are drawn (a huge program would bury its path).
const MAX_ARROWS: usize = 20_000;

/// The view state of a session.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Scene {
    /// The plane drawn.
    pub plane: Plane,
    /// 1 = the whole path fits; 2 = twice as large.
    pub zoom: f64,
    /// Offset of the view's centre from the fitted centre (program units).
    pub pan: [f64; 2],
    /// The current block (index into the run's blocks); None shows the
    /// whole run with no current block.
    pub step: Option<u32>,
    /// Where the tool is after the current block: actual and programmed
    /// position (x, y, z in the toolpath's units).
    pub marker: Option<[[f64; 3]; 2]>,
    /// The cutter of cutter radius compensation at the current block
    /// (behaviour 16.13), drawn round the tool marker in its plane.
    pub cutter: Option<Cutter>,
    /// The current tool at its size from the setup's tool list (behaviour
    /// 13.16), drawn dashed round the tool marker in its plane.
    pub tool: Option<Cutter>,
    /// Draw the band the cutter sweeps along the current block (behaviour
    /// 16.20): off unless asked for.
    pub swept: bool,
    /// The legend is folded away (behaviour 10.7): the path gets the
    /// whole surface, and nothing covers it.
    pub legend_folded: bool,
    /// How far the tool and compensation drawings reach from the path
    /// over the run: the fit leaves room for them (behaviour 10.5).
    pub reach: Reach,
    /// Colours.
    pub theme: &'static Theme,
}

impl Default for Scene {
    fn default() -> Self {
        Scene {
            plane: Plane::Xy,
            zoom: 1.0,
            pan: [0.0, 0.0],
            step: None,
            marker: None,
            cutter: None,
            tool: None,
            swept: false,
            legend_folded: false,
            reach: Reach::default(),
            theme: &LIGHT,
        }
    }
}

impl Scene {
    /// The machine's usual view, fitted.
    pub fn for_machine(machine: MachineKind) -> Scene {
        Scene {
            plane: Plane::for_machine(machine),
            ..Scene::default()
        }
    }

    /// Makes the plane one the machine has: the lathe is drawn in ZX or in
    /// its face view XC, the mill in XY, XZ or YZ.
    pub fn adapt_to(&mut self, machine: MachineKind) {
        let lathe = machine == MachineKind::Lathe;
        if lathe != self.plane.is_lathe() {
            self.plane = Plane::for_machine(machine);
        }
    }

    /// The layout fitted to the whole path, before zoom and pan. The legend
    /// always has the tool marker's row, so the drawing does not jump when
    /// stepping starts.
    pub fn fitted(&self, tp: &Toolpath, width: f64, height: f64) -> Frame {
        Frame::fit_with(
            tp,
            self.plane,
            width,
            height,
            self.theme,
            true,
            !self.legend_folded,
            self.reach,
        )
    }

    /// The layout with this scene's zoom and pan.
    pub fn frame(&self, tp: &Toolpath, width: f64, height: f64) -> Frame {
        let mut f = self.fitted(tp, width, height);
        f.transform = self.camera(f.transform, f.plot);
        f
    }

    fn camera(&self, fit: Transform, plot: Rect) -> Transform {
        let (cx, cy) = centre(plot);
        let (cu, cv) = fit.to_world(cx, cy);
        let scale = fit.scale * self.zoom;
        let (u, v) = (cu + self.pan[0], cv + self.pan[1]);
        Transform {
            scale,
            origin_x: cx - u * scale,
            origin_y: cy + v * scale,
        }
    }

    /// Zooms by `factor` keeping the world point under screen point (x, y)
    /// where it is (zoom at the cursor). The zoom stays within the document's
    /// limits.
    pub fn zoom_at(&mut self, tp: &Toolpath, width: f64, height: f64, x: f64, y: f64, factor: f64) {
        if !(factor.is_finite() && factor > 0.0 && x.is_finite() && y.is_finite()) {
            return;
        }
        let fit = self.fitted(tp, width, height);
        let (wu, wv) = self.camera(fit.transform, fit.plot).to_world(x, y);
        let zoom = (self.zoom * factor).clamp(MIN_ZOOM, MAX_ZOOM);
        let scale = fit.transform.scale * zoom;
        let (cx, cy) = centre(fit.plot);
        let (cu, cv) = fit.transform.to_world(cx, cy);
        // The new centre puts (wu, wv) at (x, y).
        let u = wu + (cx - x) / scale;
        let v = wv - (cy - y) / scale;
        self.zoom = zoom;
        self.set_pan([u - cu, v - cv]);
    }

    /// Moves the drawing by (dx, dy) CSS pixels (a drag).
    pub fn pan_by(&mut self, tp: &Toolpath, width: f64, height: f64, dx: f64, dy: f64) {
        if !(dx.is_finite() && dy.is_finite()) {
            return;
        }
        let scale = self.fitted(tp, width, height).transform.scale * self.zoom;
        self.set_pan([self.pan[0] - dx / scale, self.pan[1] + dy / scale]);
    }

    /// Sets the pan, limited to the document's range (non-finite reads 0).
    pub fn set_pan(&mut self, pan: [f64; 2]) {
        self.pan = pan.map(|p| {
            if p.is_finite() {
                p.clamp(-MAX_PAN, MAX_PAN)
            } else {
                0.0
            }
        });
    }

    /// Sets the zoom, limited to the document's range (non-finite reads 1).
    pub fn set_zoom(&mut self, zoom: f64) {
        self.zoom = if zoom.is_finite() {
            zoom.clamp(MIN_ZOOM, MAX_ZOOM)
        } else {
            1.0
        };
    }

    /// Back to the whole path.
    pub fn fit(&mut self) {
        self.zoom = 1.0;
        self.pan = [0.0, 0.0];
    }

    /// How many moves are drawn in colour: those of the blocks up to the
    /// current one (all without one).
    pub fn drawn_moves(&self, tp: &Toolpath) -> usize {
        match self.step {
            Some(step) => tp.blocks.partition_point(|&b| b <= step),
            None => tp.len(),
        }
    }
}

fn centre(r: Rect) -> (f64, f64) {
    (r.x + r.w / 2.0, r.y + r.h / 2.0)
}

/// The end of the last move drawn in colour (actual, programmed), or None
/// before the first move.
pub fn tool_position(tp: &Toolpath, drawn: usize) -> Option<[[f64; 3]; 2]> {
    let [[_, a], [_, p]] = tp.ends(drawn.checked_sub(1)?)?;
    Some([a, p])
}

/// A line from `from` to `to` ending in a filled head.
pub fn arrow(s: &mut impl Surface, stroke: &Stroke, from: (f64, f64), to: (f64, f64)) {
    let (dx, dy) = (to.0 - from.0, to.1 - from.1);
    let len = dx.hypot(dy);
    if !(len.is_finite() && len > 0.0) {
        return;
    }
    let (ux, uy) = (dx / len, dy / len);
    let head = (len * 0.5).min(8.0);
    let half = head * 0.5;
    let base = (to.0 - ux * head, to.1 - uy * head);
    s.begin_path(stroke);
    s.move_to(from.0, from.1);
    s.line_to(base.0, base.1);
    s.stroke();
    s.fill_polygon(
        &[
            to,
            (base.0 - uy * half, base.1 + ux * half),
            (base.0 + uy * half, base.1 - ux * half),
        ],
        stroke.color,
    );
}

/// Arrows from the programmed to the actual end point of every block drawn
/// in colour (the first `drawn` moves) where the two differ on screen.
pub fn draw_arrows(s: &mut impl Surface, f: &Frame, tp: &Toolpath, drawn: usize) {
    let stroke = f.theme.arrow();
    let seen = Rect::new(-20.0, -20.0, f.width + 40.0, f.height + 40.0);
    let inside =
        |(x, y): (f64, f64)| x >= seen.x && x <= seen.right() && y >= seen.y && y <= seen.bottom();
    let mut count = 0;
    s.begin_group("offsets");
    for m in 0..drawn.min(tp.len()) {
        // Only the last move of a block: its end is the block's end.
        if m + 1 < drawn && tp.blocks.get(m + 1) == tp.blocks.get(m) {
            continue;
        }
        let Some([[_, a], [_, p]]) = tp.ends(m) else {
            continue;
        };
        let screen = |q: &[f64; 3]| {
            let (u, v) = f.projection.project(q);
            f.transform.to_screen(u, v)
        };
        let (to, from) = (screen(&a), screen(&p));
        let len = (to.0 - from.0).hypot(to.1 - from.1);
        if !(len.is_finite() && len >= MIN_ARROW_PX) || !(inside(to) || inside(from)) {
            continue;
        }
        arrow(s, &stroke, from, to);
        count += 1;
        if count >= MAX_ARROWS {
            break;
        }
    }
    s.end_group();
}

/// Distance from point `p` to the segment `a`–`b`.
fn segment_distance(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let len2 = dx * dx + dy * dy;
    let t = if len2 > 0.0 {
        (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p.0 - (a.0 + t * dx)).hypot(p.1 - (a.1 + t * dy))
}

/// The block of the move nearest to screen point (x, y) on either path,
/// if one passes within `tolerance` CSS pixels; ties go to the earlier move.
pub fn pick(tp: &Toolpath, f: &Frame, x: f64, y: f64, tolerance: f64) -> Option<u32> {
    if !(x.is_finite() && y.is_finite() && tolerance.is_finite()) {
        return None;
    }
    let mut best: Option<(f64, u32)> = None;
    // Arcs tessellated as drawn, so a click on the drawn line hits it.
    let within = super::DRAW_TOLERANCE_PX / f.transform.scale;
    for programmed in [false, true] {
        let mut last: Option<(usize, (f64, f64))> = None;
        tp.for_each_point(
            0..tp.len(),
            programmed,
            (within, ArcPoints::Exact),
            |_| true,
            |m, i, q| {
                let (u, v) = f.projection.project(&q);
                let here = f.transform.to_screen(u, v);
                if !(here.0.is_finite() && here.1.is_finite()) {
                    return;
                }
                let from = match last {
                    Some((lm, p)) if lm == m && i > 0 => p,
                    _ => here,
                };
                let d = segment_distance((x, y), from, here);
                let block = tp.blocks[m];
                // Ties go to the earlier move (the actual path is walked first).
                if d <= tolerance && best.is_none_or(|(bd, bb)| d < bd || (d == bd && block < bb)) {
                    best = Some((d, block));
                }
                last = Some((m, here));
            },
        );
    }
    best.map(|(_, block)| block)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::style;
    use crate::render::test_support::{group, square, svg_of};

    #[test]
    fn zoom_at_the_cursor_keeps_the_point_under_it() {
        let tp = square();
        let mut scene = Scene::default();
        let before = scene.frame(&tp, 800.0, 500.0).transform;
        let (x, y) = (250.0, 310.0);
        let world = before.to_world(x, y);
        scene.zoom_at(&tp, 800.0, 500.0, x, y, 2.5);
        let after = scene.frame(&tp, 800.0, 500.0).transform;
        assert!((after.scale / before.scale - 2.5).abs() < 1e-9);
        let (sx, sy) = after.to_screen(world.0, world.1);
        assert!((sx - x).abs() < 1e-6 && (sy - y).abs() < 1e-6, "{sx} {sy}");
        // Zoom is limited; fit goes back to the fitted transform.
        scene.zoom_at(&tp, 800.0, 500.0, x, y, 1e12);
        assert_eq!(scene.zoom, MAX_ZOOM);
        scene.fit();
        assert_eq!(scene.frame(&tp, 800.0, 500.0).transform, before);
    }

    #[test]
    fn a_drag_moves_the_drawing_with_the_pointer() {
        let tp = square();
        let mut scene = Scene::default();
        let before = scene.frame(&tp, 800.0, 500.0).transform;
        scene.pan_by(&tp, 800.0, 500.0, 40.0, -25.0);
        let after = scene.frame(&tp, 800.0, 500.0).transform;
        let (x0, y0) = before.to_screen(10.0, 10.0);
        let (x1, y1) = after.to_screen(10.0, 10.0);
        assert!((x1 - x0 - 40.0).abs() < 1e-9 && (y1 - y0 + 25.0).abs() < 1e-9);
        // Pan is in program units: right and down on screen is +u, -v.
        assert!(scene.pan[0] < 0.0 && scene.pan[1] < 0.0);
    }

    #[test]
    fn every_differing_block_gets_an_arrow_from_programmed_to_actual() {
        // Seed 000: all seven moves end off the programmed point but the
        // last (back on the programmed path at (-30, -20)) and the first
        // (no offset yet).
        let tp = square();
        let out = svg_of(&tp, &Scene::default());
        let arrows = group(&out, "offsets");
        assert_eq!(arrows.matches("<polygon").count(), 5, "{arrows}");
        assert!(arrows.contains(style::LIGHT.arrow));
    }

    #[test]
    fn stepping_draws_the_path_up_to_the_block_and_the_tool_there() {
        let tp = square();
        let scene = Scene {
            step: Some(2),
            marker: tool_position(&tp, 3),
            ..Scene::default()
        };
        assert_eq!(scene.drawn_moves(&tp), 3);
        // Block 2 (G01 G47 X80.) ends at (86, -6), programmed (80, 0).
        assert_eq!(scene.marker, Some([[86.0, -6.0, 0.0], [80.0, 0.0, 0.0]]));
        let out = svg_of(&tp, &scene);
        assert!(group(&out, "ghost").contains(style::LIGHT.ghost));
        assert!(group(&out, "current").contains("<path"));
        assert_eq!(group(&out, "offsets").matches("<polygon").count(), 2);
        let tool = group(&out, "tool");
        assert_eq!(tool.matches("<circle").count(), 2);
        assert!(tool.contains(style::LIGHT.tool));
        assert!(group(&out, "legend").contains("tool at current block"));
        assert_eq!(tool_position(&tp, 0), None);
    }

    #[test]
    fn pick_finds_the_block_of_the_nearest_segment_in_screen_space() {
        let tp = square();
        let scene = Scene::default();
        let f = scene.frame(&tp, 800.0, 500.0);
        // Midway along the actual bottom edge (block 2: X move to 86 at Y-6).
        let (x, y) = f.transform.to_screen(40.0, -6.0);
        assert_eq!(pick(&tp, &f, x, y + 3.0, 6.0), Some(2));
        // The programmed top edge Y50 (block 4, G47 X-80.).
        let (x, y) = f.transform.to_screen(40.0, 50.0);
        assert_eq!(pick(&tp, &f, x, y, 6.0), Some(4));
        // Far from every segment: nothing.
        let (x, y) = f.transform.to_screen(40.0, 25.0);
        assert_eq!(pick(&tp, &f, x, y, 6.0), None);
        assert_eq!(pick(&tp, &f, f64::NAN, 0.0, 6.0), None);
    }

    #[test]
    fn the_dark_theme_paints_its_own_colours() {
        let tp = square();
        let scene = Scene {
            theme: Theme::named("dark"),
            ..Scene::default()
        };
        let out = svg_of(&tp, &scene);
        assert!(out.contains(style::DARK.background) && out.contains(style::DARK.actual_feed));
        assert!(!out.contains(style::LIGHT.actual_feed));
    }

    #[test]
    fn the_lathe_stays_in_zx_and_the_mill_leaves_it() {
        let mut scene = Scene {
            plane: Plane::Yz,
            ..Scene::default()
        };
        scene.adapt_to(MachineKind::Lathe);
        assert_eq!(scene.plane, Plane::LatheZx);
        scene.adapt_to(MachineKind::Mill);
        assert_eq!(scene.plane, Plane::Xy);
    }
}
