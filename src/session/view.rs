//! What the page looks at: the view state (plane, zoom, pan, colours), the
//! current block and the tool marker at its end, the size and layout of
//! the last frame (which zoom, pan and picking measure against), and
//! whether a frame asked for is the one the canvas already shows.

use std::hash::{DefaultHasher, Hash, Hasher};

use serde::{Deserialize, Serialize};

use crate::offsets::cutter::Phase;
use crate::render::scene::{self, Scene};
use crate::render::{Angles, Frame, Plane, Theme};
use crate::report::{BlockReport, Run};
use crate::run::Checkpoints;
use crate::setup::{MachineKind, Setup};
use crate::toolpath::Toolpath;

/// The view state as the page reads it (`view()`) and sets it
/// (`set_view()`): the document's `view` (plane, zoom, pan) plus the
/// current block. When set, absent keys stay as they are and `step: -1`
/// clears the current block.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct ViewChange {
    /// `XY`, `XZ`, `YZ`, `3D` (mill), `ZX` or `XC` (lathe).
    pub plane: Option<String>,
    /// The 3D view's yaw and pitch, degrees (behaviour 10.8): reported
    /// with plane `3D` only; set, they choose the 3D view on the mill.
    #[serde(default)]
    pub angles: Option<[f64; 2]>,
    /// 1 fits the whole path.
    pub zoom: Option<f64>,
    /// The view centre's offset from the fitted centre, in program units.
    pub pan: Option<[f64; 2]>,
    /// The current block (None: none; set: negative clears it).
    #[serde(default)]
    pub step: Option<i64>,
    /// Draw the band the cutter sweeps along the current block while
    /// G41/G42 is on (behaviour 16.20).
    #[serde(default)]
    pub swept: Option<bool>,
    /// The legend is drawn (true) or folded away (false), behaviour 10.7.
    #[serde(default)]
    pub legend: Option<bool>,
}

/// CSS pixels of drag per degree the 3D view turns: a drag across a
/// 720-pixel view turns it about a full turn.
pub const PIXELS_PER_DEGREE: f64 = 2.0;

/// A frame asked for, its sizes clamped to what a canvas can be.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrameAsk {
    /// CSS pixels, 1 to 8192 each way.
    pub css: (u32, u32),
    /// Device pixels per CSS pixel, up to 8 (1 for nonsense).
    pub dpr: f64,
    /// Device pixels of the canvas, 1 to 16384 each way.
    pub device: (u32, u32),
    /// Device pixels per CSS pixel as the canvas rounds them, per axis.
    pub scale: (f64, f64),
    /// Everything a kept pixel layer depends on but the zoom and pan: the
    /// drawing, plane, current block, colours, size and pixel ratio (the
    /// renderer reuses a layer only for the same key).
    pub key: u64,
    /// What the whole frame shows: the drawing, the view state, the size
    /// and the pixel ratio.
    shows: Shown,
}

/// What a whole frame on the canvas shows.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Shown {
    drawing: u64,
    scene: Scene,
    css: (u32, u32),
    dpr_bits: u64,
}

/// The view of a session's run.
#[derive(Debug)]
pub struct View {
    /// Plane, zoom, pan, current block, marker and colours.
    scene: Scene,
    /// The CSS size last asked for, for zoom, pan and picking.
    size: (f64, f64),
    /// The layout last drawn, which picking measures against.
    frame: Option<Frame>,
    /// Whether the current block was set at the last block: the next runs
    /// keep it at their last block (editing at the end shows the whole
    /// program). A block set elsewhere stays where it was set, also across
    /// a run that stopped short of it at an error and clamped it there.
    follows_end: bool,
    /// What the last whole frame on the canvas showed. A frame asked for
    /// the same (after a run that changed nothing drawn, such as an edit of
    /// an N number) is that one, and is not drawn again.
    last_whole: Option<Shown>,
}

impl Default for View {
    fn default() -> Self {
        View {
            scene: Scene::default(),
            size: (300.0, 150.0),
            frame: None,
            follows_end: false,
            last_whole: None,
        }
    }
}

/// What the view needs of the run it shows.
#[derive(Clone, Copy)]
pub struct Showing<'a> {
    /// The program run.
    pub text: &'a str,
    /// Its setup.
    pub setup: &'a Setup,
    /// The run.
    pub run: &'a Run,
    /// What the run kept to make its blocks' reports again.
    pub checkpoints: &'a Checkpoints,
    /// Its toolpath.
    pub toolpath: &'a Toolpath,
}

impl Showing<'_> {
    fn report(&self, index: u32) -> Option<BlockReport> {
        crate::run::report_at(self.text, self.setup, self.checkpoints, index)
    }
}

impl View {
    /// Plane, zoom, pan, current block, marker and colours, as drawn.
    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// Keeps the view sensible for a new run (`drawing` counts the runs
    /// whose drawing changed): the lathe is drawn in ZX, the mill in one of
    /// its planes; a current block past the end moves to the last block,
    /// and a view set at the last block stays at the last block (so editing
    /// at the end shows the whole program). Only the user sets it there
    /// ([`View::set_step`]): a digit that stops the run at an error just
    /// after the block being edited makes that block the last one, and the
    /// key that mends the error must not send the current block to the
    /// program's end.
    pub fn after_run(&mut self, run: &Showing<'_>, drawing: u64) {
        self.scene.adapt_to(run.run.machine);
        let count = run.run.block_count;
        if let Some(step) = self.scene.step {
            self.scene.step = match count {
                0 => None,
                n if self.follows_end || step >= n => Some(n - 1),
                _ => Some(step),
            };
        }
        self.scene.reach = reach(run);
        self.update_marker(run);
        // The layout drawn (which picking measures against) holds while the
        // drawing is the one drawn last.
        if self.last_whole.is_none_or(|w| w.drawing != drawing) {
            self.frame = None;
        }
    }

    /// The tool at the end of the current block: where its last move
    /// drawn ends or, before any move, where the block leaves it.
    fn update_marker(&mut self, run: &Showing<'_>) {
        let k = 1.0 / run.run.units.mm();
        let report = self.scene.step.and_then(|step| run.report(step));
        self.scene.marker = self.scene.step.and_then(|_| {
            let drawn = self.scene.drawn_moves(run.toolpath);
            scene::tool_position(run.toolpath, drawn).or_else(|| {
                let b = report.as_ref()?;
                Some([
                    b.state.actual.map(|v| v * k),
                    b.state.programmed.map(|v| v * k),
                ])
            })
        });
        // The cutter's circle while G41/G42 is the mode or its vector is on
        // (behaviour 16.13); on the lathe the nose's, about the nose centre
        // (behaviour 18.2).
        self.scene.cutter = report.as_ref().and_then(|b| {
            let c = b.state.cutter;
            let on = c.mode != crate::syntax::codes::CutterCompensation::Cancel
                || matches!(c.phase, Phase::StartUp | Phase::Offset);
            if !on || c.radius == 0.0 {
                return None;
            }
            Some(circle(&b.state, c.radius.abs() * k, c.tip.unwrap_or(0)))
        });
        // The tool at its size from the tool list (behaviour 13.16): the
        // mill's cutter seen along its axis in the plan view, the lathe's
        // nose circle about its centre.
        self.scene.tool = report.as_ref().and_then(|b| {
            let s = &b.state;
            let (number, plane) = match s.machine {
                MachineKind::Mill => (s.tool, Plane::Xy),
                MachineKind::Lathe => (s.lathe.tool, Plane::LatheZx),
            };
            let t = run.setup.tool(number)?;
            let to_path = run.setup.units.mm() * k;
            let radius = match s.machine {
                MachineKind::Mill => t.diameter / 2.0,
                MachineKind::Lathe => t.nose_radius,
            } * to_path;
            let mut c = circle(s, radius, t.tip);
            c.plane = plane;
            // The mill's cutter is a cylinder up the spindle (10.16).
            if s.machine == MachineKind::Mill {
                c.length = Some(t.length * to_path);
            }
            (radius > 0.0).then_some(c)
        });
    }

    /// Makes block `index` the current one (the path is drawn up to it,
    /// the tool marker sits at its end); a negative index clears it, an
    /// index past the last block means the last. Returns the current block
    /// or -1.
    pub fn set_step(&mut self, run: &Showing<'_>, index: i32) -> i32 {
        let count = run.run.block_count as usize;
        self.scene.step = match usize::try_from(index) {
            Ok(_) if count == 0 => None,
            Ok(i) => u32::try_from(i.min(count - 1)).ok(),
            Err(_) => None,
        };
        self.follows_end = count > 0 && self.scene.step == u32::try_from(count - 1).ok();
        self.update_marker(run);
        self.step()
    }

    /// The current block, or -1.
    pub fn step(&self) -> i32 {
        self.scene
            .step
            .and_then(|s| i32::try_from(s).ok())
            .unwrap_or(-1)
    }

    /// The view state (see [`ViewChange`]).
    pub fn view(&self) -> ViewChange {
        ViewChange {
            plane: Some(self.scene.plane.name().to_owned()),
            angles: match self.scene.plane {
                Plane::Orbit(a) | Plane::LatheOrbit(a) => Some([a.yaw(), a.pitch()]),
                _ => None,
            },
            zoom: Some(self.scene.zoom),
            pan: Some(self.scene.pan),
            step: self.scene.step.map(i64::from),
            swept: Some(self.scene.swept),
            legend: Some(!self.scene.legend_folded),
        }
    }

    /// Sets what `change` holds, limited to the document's ranges (a
    /// plane the machine does not have is ignored); returns the view state.
    pub fn set_view(&mut self, run: &Showing<'_>, change: &ViewChange) -> ViewChange {
        if let Some(plane) = &change.plane {
            self.set_plane(run.run.machine, plane);
        }
        if let Some([yaw, pitch]) = change.angles
            && change
                .plane
                .as_deref()
                .is_none_or(|p| p.eq_ignore_ascii_case("3D"))
        {
            let angles = Angles::degrees(yaw, pitch);
            self.scene.plane = Plane::orbit(run.run.machine, angles);
        }
        if let Some(zoom) = change.zoom {
            self.scene.set_zoom(zoom);
        }
        if let Some(pan) = change.pan {
            self.scene.set_pan(pan);
        }
        if let Some(swept) = change.swept {
            self.scene.swept = swept;
        }
        if let Some(legend) = change.legend {
            self.scene.legend_folded = !legend;
        }
        if let Some(step) = change.step {
            self.set_step(run, i32::try_from(step).unwrap_or(i32::MAX));
        }
        self.view()
    }

    /// Chooses the plane drawn (`XY`, `XZ`, `YZ` on the mill; `ZX` and the
    /// face view `XC` on the lathe; `3D`, the isometric view, on both).
    /// False, changing nothing, for another name.
    pub fn set_plane(&mut self, machine: MachineKind, name: &str) -> bool {
        match Plane::parse(name).and_then(|p| p.on(machine)) {
            Some(plane) => {
                self.scene.plane = plane;
                true
            }
            None => false,
        }
    }

    /// Turns the view by a drag of (dx, dy) CSS pixels, a degree for
    /// every [`PIXELS_PER_DEGREE`]: across turns about the vertical axis
    /// (yaw: the mill's Z, the lathe's X), up and down lifts or lowers the
    /// eye (pitch, stopping at ±90°). A plane view turns from its own
    /// angles (XY is the top view, the lathe's ZX the front) into the
    /// machine's 3D view. False in the lathe's face view XC, which does not
    /// turn (behaviour 10.18).
    pub fn orbit_by(&mut self, machine: MachineKind, dx: f64, dy: f64) -> bool {
        let Some(angles) = self.scene.plane.angles() else {
            return false;
        };
        if !(dx.is_finite() && dy.is_finite()) {
            return false;
        }
        let turned = angles.turned(-dx / PIXELS_PER_DEGREE, dy / PIXELS_PER_DEGREE);
        self.scene.plane = Plane::orbit(machine, turned);
        true
    }

    /// Zooms by `factor` about the CSS pixel (x, y) of the last frame.
    pub fn zoom_at(&mut self, toolpath: &Toolpath, x: f64, y: f64, factor: f64) {
        let (w, h) = self.size;
        self.scene.zoom_at(toolpath, w, h, x, y, factor);
    }

    /// Moves the drawing by (dx, dy) CSS pixels.
    pub fn pan_by(&mut self, toolpath: &Toolpath, dx: f64, dy: f64) {
        let (w, h) = self.size;
        self.scene.pan_by(toolpath, w, h, dx, dy);
    }

    /// Zoom 1, no pan: the whole path.
    pub fn fit(&mut self) {
        self.scene.fit();
    }

    /// `"light"` or `"dark"`: the colours.
    pub fn set_theme(&mut self, name: &str) {
        self.scene.theme = Theme::named(name);
    }

    /// The block whose move passes nearest to CSS pixel (x, y) of the last
    /// frame drawn, on either path, within `tolerance` pixels (at most
    /// 100); or -1, also before any frame.
    pub fn pick(&self, toolpath: &Toolpath, x: f64, y: f64, tolerance: f64) -> i32 {
        let Some(frame) = &self.frame else {
            return -1;
        };
        scene::pick(toolpath, frame, x, y, tolerance.clamp(0.0, 100.0))
            .and_then(|b| i32::try_from(b).ok())
            .unwrap_or(-1)
    }

    /// The frame asked for at `width` × `height` CSS pixels and `dpr`
    /// device pixels per CSS pixel, of drawing number `drawing`; also the
    /// size zoom, pan and picking go by from now on (asked with or without
    /// a canvas to draw on).
    pub fn ask(&mut self, width: u32, height: u32, dpr: f64, drawing: u64) -> FrameAsk {
        let dpr = if dpr.is_finite() && dpr > 0.0 {
            dpr.min(8.0)
        } else {
            1.0
        };
        let (w, h) = (width.clamp(1, 8192), height.clamp(1, 8192));
        self.size = (f64::from(w), f64::from(h));
        let device = |css: u32| ((f64::from(css) * dpr).round() as u32).clamp(1, 16384);
        let key = {
            let mut hash = DefaultHasher::new();
            // The plane with its angles: a turned 3D view is another drawing.
            (drawing, self.scene.plane, self.scene.step).hash(&mut hash);
            (self.scene.theme.name, w, h, dpr.to_bits()).hash(&mut hash);
            hash.finish()
        };
        FrameAsk {
            css: (w, h),
            dpr,
            device: (device(w), device(h)),
            scale: (
                f64::from(device(w)) / f64::from(w),
                f64::from(device(h)) / f64::from(h),
            ),
            key,
            shows: Shown {
                drawing,
                scene: self.scene,
                css: (w, h),
                dpr_bits: dpr.to_bits(),
            },
        }
    }

    /// The frame asked for during a gesture: in the 3D view its large
    /// paths may be a sample ([`crate::render::ORBIT_MOVES`]), a layer that
    /// must not be taken for the whole drawing's.
    pub fn ask_moving(&mut self, width: u32, height: u32, dpr: f64, drawing: u64) -> FrameAsk {
        let mut ask = self.ask(width, height, dpr, drawing);
        if self.scene.plane.is_orbit() {
            let mut hash = DefaultHasher::new();
            (ask.key, "sampled").hash(&mut hash);
            ask.key = hash.finish();
        }
        ask
    }

    /// True when the canvas already shows the whole frame `ask` asks for:
    /// it need not be drawn again.
    pub fn shown(&self, ask: &FrameAsk) -> bool {
        self.last_whole == Some(ask.shows) && self.frame.is_some()
    }

    /// The frame `ask` asked for was drawn with layout `frame`: `moved`,
    /// the last whole frame's pixels moved and scaled during a gesture
    /// (not a whole frame).
    pub fn drawn(&mut self, ask: &FrameAsk, frame: Frame, moved: bool) {
        self.last_whole = (!moved).then_some(ask.shows);
        self.frame = Some(frame);
    }

    /// The canvas shows nothing known (attached again, blank): the next
    /// frame is drawn whole.
    pub fn forget_frame(&mut self) {
        self.last_whole = None;
    }
}

/// How far the drawings round the tool reach from the path over the run
/// (behaviour 10.5), in the toolpath's units: the largest of the tool
/// list's tools the run changes to (the mill's radius, and its length up
/// the spindle or its diameter without one; the lathe's nose circle, whose
/// far side lies 2R from the imaginary nose) and of the compensation's
/// radius while engaged. Worked out once a run.
fn reach(run: &Showing<'_>) -> scene::Reach {
    let k = 1.0 / run.run.units.mm();
    let to_path = run.setup.units.mm() * k;
    let lathe = run.run.machine == MachineKind::Lathe;
    let mut reach = scene::Reach {
        radius: run.run.cutter_reach * k,
        up: 0.0,
    };
    let mut seen = std::collections::BTreeSet::new();
    for e in &run.run.events {
        let number = match e.kind {
            crate::machine::EventKind::ToolChange { tool } if !lathe => tool,
            crate::machine::EventKind::ToolIndex { tool } if lathe => tool,
            _ => continue,
        };
        if !seen.insert(number) {
            continue;
        }
        let Some(t) = run.setup.tool(number) else {
            continue;
        };
        if lathe {
            reach.radius = reach.radius.max(t.nose_radius * to_path);
        } else {
            let r = t.diameter / 2.0 * to_path;
            let up = if t.length > 0.0 { t.length } else { t.diameter } * to_path;
            reach.radius = reach.radius.max(r);
            reach.up = reach.up.max(up);
        }
    }
    if lathe {
        reach.radius *= 2.0;
    }
    reach
}

/// A circle of `radius` (the toolpath's units) round the tool: in the
/// compensation plane about the marker on the mill; on the lathe about the
/// nose centre, which lies R × the tip's vector (Z, X radius) from the
/// imaginary nose the path follows (behaviour 18.2; X is a diameter).
fn circle(s: &crate::machine::BlockState, radius: f64, tip: u8) -> scene::Cutter {
    match s.machine {
        MachineKind::Mill => scene::Cutter {
            radius,
            plane: match s.modal.plane {
                crate::machine::modal::Plane::XY => Plane::Xy,
                crate::machine::modal::Plane::ZX => Plane::Xz,
                crate::machine::modal::Plane::YZ => Plane::Yz,
            },
            centre: [0.0; 3],
            length: None,
        },
        MachineKind::Lathe => {
            let [tz, tx] = crate::offsets::cutter::nose::tip_vector(tip);
            scene::Cutter {
                radius,
                plane: Plane::LatheZx,
                centre: [-2.0 * radius * tx, 0.0, -radius * tz],
                length: None,
            }
        }
    }
}
