//! Recording a drawing: the canvas-like calls of [`Pen`] become sub-paths
//! of `f32` points in device pixels, clipped to the surface, each with its
//! style and the dash phase it starts at ([`Raster::finish`] draws them).

use super::keep::MOST_KEPT;
use super::{Ink, Raster, RecordedArc, Sub, WHOLE_ARC, length};
use crate::render::style::Stroke;
use crate::render::{Pen, WholeArc};
use crate::toolpath::ArcPoints;

/// The pen while recording: where it is, how far along its sub-path, and
/// whether the next segment drawn starts a new recorded sub-path.
#[derive(Clone, Copy, Default)]
pub(super) struct Recorder {
    pub(super) style: Option<u16>,
    pub(super) at: Option<(f64, f64)>,
    pub(super) along: f64,
    pub(super) broken: bool,
}

/// The area a segment's line covers, in whole 64ths of a device pixel²:
/// such areas add up exactly in any order (far below 2^53 of them), so a
/// recording made partly of the last one's pieces ([`super::pieces`])
/// sums to what recording it in one go does, and chooses the same grid.
pub(super) fn covered(area: f64) -> f64 {
    (area * 64.0).round() / 64.0
}

impl Raster {
    fn to_device(&self, x: f64, y: f64) -> (f64, f64) {
        (x * self.rec.0, y * self.rec.1)
    }

    /// The size of the surface recorded on: the device pixels, or those
    /// of a planned drawing's grid ([`Raster::plan`]).
    fn recorded_size(&self) -> (f64, f64) {
        let (w, h) = if self.planned {
            (self.width, self.height)
        } else {
            self.full
        };
        (w as f64, h as f64)
    }

    /// Where a segment (device pixels) of `length` is within the surface
    /// and the line's width around it: the parameters (as lengths along it)
    /// where it enters and leaves, or None when it never does.
    fn clip(
        &self,
        from: (f64, f64),
        to: (f64, f64),
        length: f64,
        margin: f64,
    ) -> Option<(f64, f64)> {
        clip_within(self.recorded_size(), from, to, length, margin)
    }

    /// What measures the ink of a drawing on this surface before it is
    /// recorded ([`InkMeter`]).
    pub fn ink_meter(&self) -> InkMeter {
        InkMeter {
            size: (self.full.0 as f64, self.full.1 as f64),
            scale: self.scale,
            half_width: 0.0,
            at: None,
            area: 0.0,
        }
    }
}

/// Where a segment (pixels) of `length` is within a surface of `(w, h)`
/// pixels and `margin` around it: the parameters (as lengths along it)
/// where it enters and leaves, or None when it never does.
fn clip_within(
    (w, h): (f64, f64),
    from: (f64, f64),
    to: (f64, f64),
    length: f64,
    margin: f64,
) -> Option<(f64, f64)> {
    if !(length > 0.0 && length.is_finite()) {
        return None;
    }
    // Most segments lie well inside. With both ends a pixel inside the
    // edges, each edge is more than a pixel beyond the segment's ends
    // along it, far more than the rounding of the divisions below: they
    // would give (0, length) too (and were a measurable share of recording
    // a 1M-block frame: `examples/render_time` guards it).
    let inside = |(x, y): (f64, f64)| {
        (1.0 - margin..=w + margin - 1.0).contains(&x)
            && (1.0 - margin..=h + margin - 1.0).contains(&y)
    };
    if inside(from) && inside(to) {
        return Some((0.0, length));
    }
    // Liang–Barsky, in units of length.
    let (mut t0, mut t1) = (0.0_f64, length);
    let (dx, dy) = ((to.0 - from.0) / length, (to.1 - from.1) / length);
    let edges = [
        (-dx, from.0 + margin),
        (dx, w + margin - from.0),
        (-dy, from.1 + margin),
        (dy, h + margin - from.1),
    ];
    for (p, q) in edges {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
        }
    }
    (t0 < t1).then_some((t0, t1))
}

/// The area (device pixels², overlaps counted) that the lines drawn with
/// it would cover on a raster's surface, as [`Raster`] records them:
/// what a planned drawing chooses its grid by ([`Raster::plan`]).
pub struct InkMeter {
    size: (f64, f64),
    scale: (f64, f64),
    half_width: f64,
    at: Option<(f64, f64)>,
    /// The area measured.
    pub area: f64,
}

impl Pen for InkMeter {
    fn begin_path(&mut self, stroke: &Stroke) {
        let scale = (self.scale.0 + self.scale.1) / 2.0;
        self.half_width = stroke.width.max(0.0) * scale / 2.0;
        self.at = None;
    }

    fn move_to(&mut self, x: f64, y: f64) {
        self.at = Some((x * self.scale.0, y * self.scale.1));
    }

    fn line_to(&mut self, x: f64, y: f64) {
        let to = (x * self.scale.0, y * self.scale.1);
        let Some(from) = self.at.replace(to) else {
            return;
        };
        let length = length(to.0 - from.0, to.1 - from.1);
        let margin = self.half_width + 2.0;
        if let Some((t0, t1)) = clip_within(self.size, from, to, length, margin) {
            self.area += (t1 - t0) * 2.0 * self.half_width;
        }
    }

    fn stroke(&mut self) {
        self.at = None;
    }
}

impl Raster {
    /// The next sub-paths recorded belong to the path begun last
    /// ([`Pen::begin_path`]), from a new place: the next part of a planned
    /// drawing ([`Raster::plan`]).
    pub fn resume_path(&mut self) {
        self.pen = Recorder {
            style: self.pen.style,
            ..Recorder::default()
        };
    }
}

impl Ink {
    fn of(stroke: &Stroke, scale: f64) -> Ink {
        let [r, g, b, alpha] = parse_color(stroke.color);
        let mut dash: Vec<f64> = stroke.dash.iter().map(|d| d.max(0.0) * scale).collect();
        // A pattern with nothing to draw (all zero) is drawn solid, as the
        // canvas ignores it; an odd-length one is repeated to make it even,
        // as the canvas does.
        if !dash.iter().any(|d| *d > 0.0) || dash.iter().any(|d| !d.is_finite()) {
            dash.clear();
        }
        if dash.len() % 2 == 1 {
            dash.extend_from_within(..);
        }
        Ink {
            rgb: [r as u32, g as u32, b as u32],
            alpha,
            half_width: stroke.width.max(0.0) * scale / 2.0,
            period: dash.iter().sum(),
            dash,
        }
    }
}

impl Pen for Raster {
    fn arc_points(&self) -> ArcPoints {
        ArcPoints::Rotated
    }

    fn begin_path(&mut self, stroke: &Stroke) {
        let scale = (self.rec.0 + self.rec.1) / 2.0;
        // A drawing has a few paths (six layers at most); past 2^15, further
        // ones are not drawn rather than share a stamp.
        let style = u16::try_from(self.styles.len())
            .ok()
            .filter(|s| *s < u16::MAX / 2);
        if style.is_some() {
            self.styles.push(Ink::of(stroke, scale));
        }
        self.pen = Recorder {
            style,
            ..Recorder::default()
        };
    }

    /// Every move is a sub-path of its own here, dashed or not (its
    /// pattern goes on unless `restart`; a solid line's pixels are the same
    /// either way): the unit in which a drawing is compared with the last
    /// one ([`super::keep`]), in drawings small enough to be kept. In
    /// larger ones dashes run on across moves, as they did before.
    fn next_move(&mut self, x: f64, y: f64, restart: bool) {
        if self.points.len() >= MOST_KEPT {
            // Past what is kept, the line runs on, dashes too: a sub-path
            // per move would only cost time and wasm memory ([`MOST_KEPT`];
            // `make bench-browser`, target 3, guards both).
        } else if restart {
            self.move_to(x, y);
        } else {
            self.pen.broken = true;
        }
    }

    fn move_to(&mut self, x: f64, y: f64) {
        // Every sub-path starts its dash pattern afresh.
        self.pen.at = Some(self.to_device(x, y));
        self.pen.along = 0.0;
        self.pen.broken = true;
    }

    fn line_to(&mut self, x: f64, y: f64) {
        let to = self.to_device(x, y);
        let (Some(style), Some(from)) = (self.pen.style, self.pen.at.replace(to)) else {
            return;
        };
        let finite =
            to.0.is_finite() && to.1.is_finite() && from.0.is_finite() && from.1.is_finite();
        let length = length(to.0 - from.0, to.1 - from.1);
        if !finite || length.is_nan() || length <= 0.0 {
            // A canvas skips such a segment; the pen moves on.
            self.pen.broken = true;
            return;
        }
        let half_width = self.styles[usize::from(style)].half_width;
        let margin = half_width + 2.0;
        let Some((t0, t1)) = self.clip(from, to, length, margin) else {
            self.pen.along += length;
            self.pen.broken = true;
            return;
        };
        let at = |t: f64| {
            let k = t / length;
            [
                recorded(from.0 + (to.0 - from.0) * k),
                recorded(from.1 + (to.1 - from.1) * k),
            ]
        };
        if self.planned && self.hidden(at(t0), at(t1), half_width) {
            // Below what is drawn already: not recorded, and the next
            // segment starts a sub-path where its dashes fall.
            self.pen.along += length;
            self.pen.broken = true;
            return;
        }
        if self.pen.broken || t0 > 0.0 {
            let period = self.styles[usize::from(style)].period;
            let phase = phase_of(self.pen.along + t0, period);
            self.subs.push(Sub {
                first: self.points.len() as u32,
                phase: recorded(phase),
                style,
            });
            self.points.push(at(t0));
        }
        self.points.push(at(t1));
        self.ink_area += covered((t1 - t0) * 2.0 * half_width);
        self.pen.along += length;
        self.pen.broken = t1 < length;
    }

    fn stroke(&mut self) {
        self.pen.at = None;
    }

    /// Past [`Raster::take_arcs_whole_past`] recorded points (1 Mi: past
    /// what is kept for the next edit, [`MOST_KEPT`], so drawings that are
    /// kept are recorded as before).
    fn takes_arcs(&self) -> bool {
        self.planned || self.points.len() >= self.whole_arcs_past
    }

    /// Records the arc whole when it lies within the surface (no clipping
    /// then) and the scale is the same along x and y (a circle stays one).
    fn arc(&mut self, arc: &WholeArc) -> bool {
        let (Some(style), Some(_)) = (self.pen.style, self.pen.at) else {
            return false;
        };
        let count = u32::try_from(arc.count).unwrap_or(0);
        if self.rec.0 != self.rec.1 || count == 0 || !arc.sweep.is_finite() {
            return false;
        }
        let [centre, from, to] = [arc.centre, arc.from, arc.to].map(|(x, y)| self.to_device(x, y));
        let r = length(from.0 - centre.0, from.1 - centre.1);
        let ink = &self.styles[usize::from(style)];
        let margin = ink.half_width + 2.0;
        let (w, h) = self.recorded_size();
        let within = |c: f64, size: f64| c - r >= 1.0 - margin && c + r <= size + margin - 1.0;
        if !(r > 0.0 && within(centre.0, w) && within(centre.1, h)) {
            return false;
        }
        let f = |(x, y): (f64, f64)| [x as f32, y as f32];
        let recorded = RecordedArc {
            centre: f(centre),
            from: f(from),
            to: f(to),
            sweep: arc.sweep as f32,
            count,
        };
        // The length of its segments together, from the unrounded ends
        // (as the segments of its points are measured: then the dashes
        // after it fall where they would).
        let n = f64::from(count);
        let length = n * 2.0 * r * (arc.sweep.abs() / (2.0 * n)).sin();
        let (period, half_width) = (ink.period, ink.half_width);
        // (The pen's distance is kept within a period of the arc's end, so
        // that the next phase needs no `rem_euclid`.)
        let phase = phase_of(self.pen.along, period);
        let hidden = self.planned && {
            let [cx, cy] = recorded.centre;
            let r = r as f32;
            self.hidden([cx - r, cy - r], [cx + r, cy + r], half_width)
        };
        self.pen.along = phase + length;
        self.pen.at = Some(to);
        // The next segment starts a sub-path of its own.
        self.pen.broken = true;
        if hidden {
            // Below what is drawn already (a planned drawing): not recorded.
            return true;
        }
        self.subs.push(Sub {
            first: self.points.len() as u32,
            phase: phase as f32,
            style: style | WHOLE_ARC,
        });
        self.arcs.push(recorded);
        self.ink_area += covered(length * 2.0 * half_width);
        true
    }
}

/// A coordinate or a phase as recorded: as `f32`, with the tiniest numbers
/// (below 2^-100 pixels) made 0, so that halving a recording for the
/// coarse grid ([`Raster::choose_grid`]) and doubling it back (a recording
/// resumed from the last one's pieces: `super::pieces`) is exact — it is
/// for every normal `f32` at least 2^-125.
pub(super) fn recorded(v: f64) -> f32 {
    let v = v as f32;
    if v.abs() < TINY { 0.0 } else { v }
}

const TINY: f32 = 1.0 / (1u128 << 100) as f32;

/// Where the distance `along` a sub-path falls in a dash pattern of
/// `period` (0 for a solid line). `rem_euclid` is a call to fmod (a share
/// of a 1M-block frame of `examples/render_time`), so it is made only when
/// `along` is not within the first period already (a move's sub-path
/// mostly starts at 0).
fn phase_of(along: f64, period: f64) -> f64 {
    if period > 0.0 && !(0.0..period).contains(&along) {
        along.rem_euclid(period)
    } else if period > 0.0 {
        along
    } else {
        0.0
    }
}

/// `#rrggbb` or `rgba(r, g, b, a)` (the styles' forms) as RGB 0–255 and
/// alpha 0–1; anything else is opaque black.
pub fn parse_color(css: &str) -> [f32; 4] {
    if let Some(hex) = css.strip_prefix('#')
        && hex.len() == 6
        && let Ok(v) = u32::from_str_radix(hex, 16)
    {
        return [
            (v >> 16) as f32,
            (v >> 8 & 0xff) as f32,
            (v & 0xff) as f32,
            1.0,
        ];
    }
    if let Some(inner) = css.strip_prefix("rgba(").and_then(|s| s.strip_suffix(')')) {
        let parts: Vec<f32> = inner
            .split(',')
            .filter_map(|p| p.trim().parse::<f32>().ok())
            .collect();
        if let [r, g, b, a] = parts[..] {
            return [
                r.clamp(0.0, 255.0),
                g.clamp(0.0, 255.0),
                b.clamp(0.0, 255.0),
                a.clamp(0.0, 1.0),
            ];
        }
    }
    [0.0, 0.0, 0.0, 1.0]
}
