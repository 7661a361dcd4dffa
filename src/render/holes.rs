//! Hole markers (behaviour 6.11): seen along a canned cycle's drilling
//! axis, a hole is a single point, so a drilling program's top view showed
//! the rapids between its holes and nothing where it drilled. Each hole is
//! drawn as a ring where the actual path drilled it.
//!
//! A hole is read from the toolpath alone: a feed move along the plane's
//! normal and nothing else, made in the same block as the rapid move just
//! before it. A canned cycle makes its hole that way (G73, G74, G76,
//! G81–G89: position at rapid, rapid to R, feed along the drilling axis,
//! all in the cycle's block); a plunge written by hand is a G01 block of
//! its own after a G00 block, and is not a hole. The pecks of one hole are
//! one hole.

use super::{Frame, Plane, Surface};
use crate::render::style::Stroke;
use crate::toolpath::Toolpath;

/// Most rings drawn in one frame (a drilling program of more holes still
/// runs and draws its paths; the rings past this are left out of the view).
const MAX_RINGS: usize = 20_000;

/// Ring radius, CSS pixels.
const RING_PX: f64 = 4.5;

/// The index of a plane's normal among x, y, z: the axis a hole seen as a
/// point runs along. The lathe's views have none (its drilling runs along
/// Z, which they show), nor the 3D view (a hole is seen as its plunge).
fn normal(plane: Plane) -> Option<usize> {
    match plane {
        Plane::Xy => Some(2),
        Plane::Xz => Some(1),
        Plane::Yz => Some(0),
        Plane::LatheZx | Plane::LatheXc | Plane::Orbit(_) | Plane::LatheOrbit(_) => None,
    }
}

/// Calls `f(move, (u, v))` for each hole of `tp` seen along `plane`'s
/// normal, in move order, until it returns false.
pub(super) fn for_each_hole(
    tp: &Toolpath,
    plane: Plane,
    mut f: impl FnMut(usize, (f64, f64)) -> bool,
) {
    let Some(n) = normal(plane) else {
        return;
    };
    // Far below any least input increment (0.0001 in, 0.001 mm).
    const SAME: f64 = 1e-7;
    let mut last: Option<(f64, f64)> = None;
    for m in 1..tp.kinds.len() {
        // Feed (1) after rapid (0), one block: bytes and numbers compared
        // before any vertex is read.
        if tp.kinds[m] != 1 || tp.kinds[m - 1] != 0 || tp.blocks[m] != tp.blocks[m - 1] {
            continue;
        }
        let Some([[from, to], _]) = tp.ends(m) else {
            continue;
        };
        let along_normal_only = (0..3).all(|k| (from[k] - to[k]).abs() <= SAME || k == n)
            && (from[n] - to[n]).abs() > SAME;
        if !along_normal_only {
            continue;
        }
        let at = plane.project(&from);
        if last.is_some_and(|p| (p.0 - at.0).abs() <= SAME && (p.1 - at.1).abs() <= SAME) {
            continue;
        }
        last = Some(at);
        if !f(m, at) {
            return;
        }
    }
}

/// Whether `tp` has a hole seen along `plane`'s normal (the legend's row).
/// Kept with the toolpath, one answer per normal: every frame's layout asks
/// (the legend's row), and so does every step of a pan or zoom gesture, and
/// a path without holes is only known to have none after a walk over all
/// its moves.
pub(super) fn has_holes(tp: &Toolpath, plane: Plane) -> bool {
    let Some(n) = normal(plane) else {
        return false;
    };
    tp.remembered(n, |tp| {
        let mut any = false;
        for_each_hole(tp, plane, |_, _| {
            any = true;
            false
        });
        any
    })
}

/// The ring of a hole, in the legend and the view.
fn ring(s: &mut impl Surface, stroke: &Stroke, (x, y): (f64, f64)) {
    s.circle(x, y, RING_PX, None, Some(stroke));
}

/// The legend's sample of [`Key::Hole`].
pub(super) fn hole_symbol(s: &mut impl Surface, f: &Frame, at: (f64, f64)) {
    ring(s, &hole_stroke(f, true), at);
}

fn hole_stroke(f: &Frame, drilled: bool) -> Stroke {
    Stroke {
        color: if drilled {
            f.theme.actual_feed
        } else {
            f.theme.ghost
        },
        width: 1.5,
        dash: &[],
    }
}

/// Draws the rings of the holes on the surface: those of the moves drawn
/// in colour (`drawn`, up to the current block) in the actual feed's
/// colour, the others in the colour of moves not run yet.
pub(super) fn draw_holes(s: &mut impl Surface, f: &Frame, tp: &Toolpath, drawn: usize) {
    if !f.holes {
        return;
    }
    let margin = RING_PX + 2.0;
    let (right, bottom) = (f.width + margin, f.height + margin);
    let (done, ahead) = (hole_stroke(f, true), hole_stroke(f, false));
    let mut count = 0;
    s.begin_group("holes");
    for_each_hole(tp, f.plane, |m, (u, v)| {
        let (x, y) = f.transform.to_screen(u, v);
        if x >= -margin && x <= right && y >= -margin && y <= bottom {
            ring(s, if m < drawn { &done } else { &ahead }, (x, y));
            count += 1;
        }
        count < MAX_RINGS
    });
    s.end_group();
}
