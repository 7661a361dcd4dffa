//! The circle of an arc block on both paths (behaviour 2.12, 2.13, 4.8):
//! the programmed circle from the block's words, the actual one from the
//! offsets' end point and centre changes, and the errors a control alarms on.

use super::arc::{self, ArcError, Circle};
use super::{ArcInfo, Machine, modal};
use crate::diag::Diagnostic;
use crate::geometry::{Xyz, to_units};
use crate::setup::MachineKind;
use crate::syntax::Block;

// LinuxCNC's arc rules (behaviour 22.16), declared where they are called.
#[path = "linuxcnc_arcs.rs"]
mod linuxcnc_arcs;
pub(in crate::machine) use linuxcnc_arcs::point_arc;

impl Machine {
    /// Builds the circle of an arc move for both paths (behaviour 2.12, 4.8).
    pub(super) fn arc_geometry(&self, b: &Block, req: &ArcRequest) -> Result<ArcInfo, Diagnostic> {
        self.arc_geometry_in(b, req, self.state.modal.plane)
    }

    /// [`Machine::arc_geometry`] in a given plane (the face plane of polar
    /// coordinate interpolation is the lathe's XY: behaviour 14.15).
    pub(super) fn arc_geometry_in(
        &self,
        b: &Block,
        req: &ArcRequest,
        plane: modal::Plane,
    ) -> Result<ArcInfo, Diagnostic> {
        let (ia, ib, _) = plane.axes();
        let lathe = self.setup.machine == MachineKind::Lathe;
        // The lathe's X is a diameter: its arcs are drawn in radius space.
        let s = |axis: usize| if lathe && axis == 0 { 0.5 } else { 1.0 };
        let to_plane = |p: Xyz| [p[ia] * s(ia), p[ib] * s(ib)];
        let from_plane = |c: arc::P2, at: Xyz| {
            let mut p = at;
            p[ia] = c[0] / s(ia);
            p[ib] = c[1] / s(ib);
            p
        };
        let ccw = req.ccw;
        let tol = self.arc_tolerance();
        let prog0 = self.state.programmed;
        let act0 = self.actual();
        let (p0, p1, a0, a1) = (
            to_plane(prog0),
            to_plane(req.target),
            to_plane(act0),
            to_plane(req.actual_end),
        );
        // When the offsets only move the arc (the same vector at both ends,
        // nothing changed by G45–G48: nearly every arc), the actual circle is
        // the programmed one moved by that vector; solving it again would
        // only repeat the work.
        if self.setup.settings.control == crate::setup::Control::Linuxcnc {
            let centre = match req.radius {
                Some((r, _)) => linuxcnc_arcs::Centre::Radius(r),
                None => {
                    linuxcnc_arcs::Centre::Point([p0[0] + req.center[ia], p0[1] + req.center[ib]])
                }
            };
            self.linuxcnc_arc_check(b, p0, p1, centre)?;
        }
        let shift = [a0[0] - p0[0], a0[1] - p0[1]];
        let moved = (a1[0] - p1[0] - shift[0]).abs() < 1e-9
            && (a1[1] - p1[1] - shift[1]).abs() < 1e-9
            && req.center_change == [0.0; 3]
            && req.radius.is_none_or(|(_, dr)| dr == 0.0);
        let prog = match req.radius {
            Some((r, _)) => arc::from_radius(p0, p1, r, ccw, tol),
            None => {
                let c = req.center;
                arc::from_center(p0, p1, [p0[0] + c[ia], p0[1] + c[ib]], ccw, tol)
            }
        };
        let act = match (moved, &prog, req.radius) {
            (true, Ok(circle), _) => Ok(Circle {
                center: [circle.center[0] + shift[0], circle.center[1] + shift[1]],
                ..*circle
            }),
            (_, _, Some((r, dr))) => arc::from_radius(a0, a1, r + dr, ccw, tol),
            (_, _, None) => {
                let c = req.center;
                let dc = req.center_change;
                let ac = [a0[0] + c[ia] + dc[ia], a0[1] + c[ib] + dc[ib]];
                arc::from_center(a0, a1, ac, ccw, tol)
            }
        };
        let unit = self.units();
        let say = |e: ArcError, path: &str| -> String {
            let d = unit.decimals();
            let f = |v: f64| format!("{:.d$}", to_units(v, unit));
            match e {
                ArcError::RadiusMismatch { start, end } => format!(
                    "the {path} arc's start is {} from its centre and its end {} (difference {} > {}, setting arc_tolerance: Fanuc parameter 3410, alarm PS0020)",
                    f(start),
                    f(end),
                    f((start - end).abs()),
                    f(tol)
                ),
                ArcError::RadiusTooSmall { radius, half_chord } => format!(
                    "the {path} arc's radius {} is less than half the distance from start to end ({})",
                    f(radius),
                    f(half_chord)
                ),
                ArcError::ZeroRadius => format!("the {path} arc's centre is its start point"),
                ArcError::NoChord => format!(
                    "the {path} arc's end is its start: an R arc makes no circle (a full circle needs the centre words)"
                ),
            }
        };
        let mut prog: Circle =
            prog.map_err(|e| self.error("arc-radius", b.span, say(e, "programmed")))?;
        let mut act: Circle = act.map_err(|e| {
            let mut m = say(e, "actual");
            m.push_str(
                ": the offsets make this arc impossible (seed 003: build the arc from quarter circles whose ends lie on the axes through the centre)",
            );
            self.error("arc-radius", b.span, m)
        })?;
        // LinuxCNC's P: whole turns before the arc's own sweep (22.16).
        if req.turns > 0 {
            let extra = std::f64::consts::TAU * f64::from(req.turns);
            prog.sweep += extra.copysign(prog.sweep);
            act.sweep += extra.copysign(act.sweep);
        }
        Ok(ArcInfo {
            plane,
            center: from_plane(act.center, act0),
            programmed_center: from_plane(prog.center, prog0),
            radius: act.radius,
            programmed_radius: prog.radius,
            sweep: act.sweep,
            programmed_sweep: prog.sweep,
            start_angle: act.start_angle,
            programmed_start_angle: prog.start_angle,
            diameter_x: lathe,
        })
    }
}

/// What an arc block asks for, after offsets changed its words.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct ArcRequest {
    /// Programmed end point.
    pub(super) target: Xyz,
    /// Actual end point.
    pub(super) actual_end: Xyz,
    /// Counter-clockwise in the plane's frame (after mirror image).
    pub(super) ccw: bool,
    /// Centre offsets I, J, K (mm, X/Y/Z order, after mirror image).
    pub(super) center: Xyz,
    /// Changes G45–G48 made to I, J, K.
    pub(super) center_change: Xyz,
    /// R (mm) and the change G45–G48 made to it.
    pub(super) radius: Option<(f64, f64)>,
    /// LinuxCNC's G2/G3 P less 1: the whole turns made before the arc's
    /// own sweep (behaviour 22.16); 0 elsewhere.
    pub(super) turns: u32,
}
