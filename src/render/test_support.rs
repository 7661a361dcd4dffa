//! What the render tests share: a program run into the toolpath they draw
//! (seed 000's square among them, from its fixture), the groups of an SVG
//! drawing, and a scene's paths drawn from nothing on the pixel layer with
//! the pixel-for-pixel comparison that a drawing made in parts, or on a
//! kept drawing's pixels, must pass against it.

use super::paths::draw_paths;
use super::svg::SvgSurface;
use super::{Frame, Raster, Scene, draw_scene};
use crate::toolpath::Toolpath;
use crate::{MachineKind, Setup, run};

/// Seed 000's program: the G45–G48 square, for register 01 = 6 (the page's
/// default example).
pub(crate) const SEED_000_SQUARE: &str = include_str!("../../tests/data/seed000_square.nc");

/// Seed 000's setup: a mill whose register 01 holds 6.
pub(crate) fn seed_000_setup() -> Setup {
    let mut setup = Setup::default();
    setup.set_register("01=6.0").unwrap();
    setup
}

/// The toolpath of `program` run with `setup`; asserts that it ran
/// without an error.
pub(crate) fn toolpath_with(program: &str, setup: &Setup) -> Toolpath {
    let r = run(program, setup);
    assert!(!r.has_errors(), "{:?}", r.diagnostics);
    Toolpath::from_run(&r)
}

/// The toolpath of `program` with seed 000's setup ([`toolpath_with`]).
pub(crate) fn toolpath(program: &str) -> Toolpath {
    toolpath_with(program, &seed_000_setup())
}

/// The toolpath of `program` on `machine`, its registers empty
/// ([`toolpath_with`]).
pub(crate) fn toolpath_on(program: &str, machine: MachineKind) -> Toolpath {
    let setup = Setup {
        machine,
        ..Setup::default()
    };
    toolpath_with(program, &setup)
}

/// The toolpath of `program` with the default setup, up to where its run
/// stops (an edited program may stop at an error: an arc's radius too
/// small for its ends, say).
pub(crate) fn toolpath_to_stop(program: &str) -> Toolpath {
    Toolpath::from_run(&run(program, &Setup::default()))
}

/// Seed 000's square ([`SEED_000_SQUARE`]) with its setup.
pub(crate) fn square() -> Toolpath {
    toolpath(SEED_000_SQUARE)
}

/// A scene drawn as an SVG document of 800 × 500 CSS pixels.
pub(crate) fn svg_of(tp: &Toolpath, scene: &Scene) -> String {
    let mut s = SvgSurface::new();
    let f = draw_scene(&mut s, tp, scene, 800.0, 500.0);
    s.finish(f.width, f.height)
}

/// The text between `<g class="name">` and its `</g>` (groups do not nest
/// in the renderer's output); asserts that the group is there.
pub(crate) fn group<'a>(svg: &'a str, name: &str) -> &'a str {
    let open = format!("<g class=\"{name}\">");
    let start = svg.find(&open).expect("group present") + open.len();
    let end = svg[start..].find("</g>").expect("group closed") + start;
    &svg[start..end]
}

/// The paths of `scene` in frame `f` drawn from nothing on a new raster of
/// `w` × `h` device pixels at `scale` device pixels per CSS pixel, in one
/// go, as a drawing that is not kept would be.
pub(crate) fn drawn_from_nothing(
    f: &Frame,
    tp: &Toolpath,
    scene: &Scene,
    (w, h, scale): (usize, usize, f64),
) -> Raster {
    let mut fresh = Raster::new();
    assert!(fresh.begin(w, h, (scale, scale)));
    draw_paths(&mut fresh, f, tp, scene, scene.drawn_moves(tp));
    fresh
}

/// Every pixel of a drawing, row by row, as straight RGBA.
pub(crate) fn pixels(r: &mut Raster) -> Vec<[u8; 4]> {
    let (w, h) = r.size();
    (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .map(|(x, y)| r.pixel(x, y))
        .collect()
}

/// Asserts that two drawings are the same size and alike pixel for pixel;
/// the first pixel that differs is named, with `what` (which drawings).
pub(crate) fn assert_same_pixels(a: &mut Raster, b: &mut Raster, what: &str) {
    let (w, h) = a.size();
    assert_eq!(b.size(), (w, h), "{what}");
    for y in 0..h {
        for x in 0..w {
            assert_eq!(a.pixel(x, y), b.pixel(x, y), "pixel ({x}, {y}), {what}");
        }
    }
}
