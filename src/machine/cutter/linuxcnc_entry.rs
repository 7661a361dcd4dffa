//! LinuxCNC's arcs under cutter radius compensation (behaviour 22.16):
//! an arc may be the first move after G41/G42 (rs274's `convert_arc_comp1`
//! in `interp_convert.cc`), and a tool as big as an arc it is inside runs
//! it standing on the centre, one bigger is refused. The Fanuc family
//! refuses the arc entry (alarm PS0034, behaviour 16.3).

use crate::diag::Diagnostic;
use crate::geometry::{Xyz, show};
use crate::machine::arc::{self, P2};
use crate::machine::{ArcInfo, Machine, Move};
use crate::offsets::cutter::geometry as geo;

/// rs274's TOLERANCE_EQUAL: an entry arc whose chord is square to the line
/// from its end to the centre has no centre.
const TOLERANCE_EQUAL: f64 = 0.0001;

fn angle(from: P2, to: P2) -> f64 {
    (to[1] - from[1]).atan2(to[0] - from[0])
}

impl Machine {
    /// rs274's checks of an arc that is compensation's first move, made on
    /// the block's programmed arc `m` (the compensation's vector off):
    /// its end more than the tool radius from the tool, and a tool inside
    /// the arc smaller than it. `o` is the signed offset (left positive).
    pub(super) fn linuxcnc_entry_checks(
        &self,
        b: &crate::syntax::Block,
        m: &Move,
        o: f64,
    ) -> Result<(), Diagnostic> {
        let Some(info) = &m.arc else { return Ok(()) };
        let (ia, ib, _) = self.state.modal.plane.axes();
        let p = |x: Xyz| [x[ia], x[ib]];
        let tool = o.abs();
        if geo::dist(p(m.from), p(m.to)) <= tool {
            return Err(self.error(
                "cutter-entry",
                b.span,
                format!(
                    "the compensation's entry arc ends within the tool radius {} of where the tool stands (rs274: \"Radius of cutter compensation entry arc is not greater than the tool radius\")",
                    show(tool, self.units())
                ),
            ));
        }
        let inside = (o > 0.0) == (info.programmed_sweep > 0.0);
        if inside && info.programmed_radius <= tool {
            return Err(self.tool_not_less(b, info.programmed_radius, tool));
        }
        Ok(())
    }

    /// The error of a tool inside an arc that does not fit it.
    pub(super) fn tool_not_less(
        &self,
        b: &crate::syntax::Block,
        radius: f64,
        tool: f64,
    ) -> Diagnostic {
        self.error(
            "cutter-tool-radius",
            b.span,
            format!(
                "the tool's radius {} is not less than the radius {} of the arc it is inside (rs274: \"Tool radius not less than arc radius with comp\")",
                show(tool, self.units()),
                show(radius, self.units())
            ),
        )
    }

    /// The entry arc rs274 makes: from where the tool stands (`from`) to
    /// `end` (the corner with the next move), about the point that is as
    /// far from `from` as from the end offset square to the programmed
    /// arc, on the line from that end to the programmed centre `centre`
    /// (plane, actual). A concave corner moves the end, not the centre, as
    /// rs274's `move_endpoint_and_flush` does.
    pub(super) fn linuxcnc_entry_arc(
        &self,
        b: &crate::syntax::Block,
        info: &ArcInfo,
        (from, end): (Xyz, Xyz),
        (programmed_end, centre): (P2, P2),
        o: f64,
    ) -> Result<ArcInfo, Diagnostic> {
        let (ia, ib, _) = self.state.modal.plane.axes();
        let p = |x: Xyz| [x[ia], x[ib]];
        let ccw = info.programmed_sweep > 0.0;
        let tool = o.abs();
        let inside = (o > 0.0) == ccw;
        let gamma = if inside {
            angle(programmed_end, centre)
        } else {
            angle(centre, programmed_end)
        };
        let e = [
            programmed_end[0] + tool * gamma.cos(),
            programmed_end[1] + tool * gamma.sin(),
        ];
        let start = p(from);
        let half = geo::dist(start, e) / 2.0;
        let ab = angle(e, centre);
        let a = angle(e, start) - ab;
        if a.cos().abs() < TOLERANCE_EQUAL {
            return Err(self.tool_not_less(b, info.programmed_radius, tool));
        }
        let along = half / a.cos();
        let c = [e[0] + along * ab.cos(), e[1] + along * ab.sin()];
        let r0 = geo::dist(start, c);
        let mut circle = arc::from_center_measured(start, p(end), c, r0, ccw);
        circle.sweep += arc::extra_turns(info.programmed_sweep).copysign(circle.sweep);
        let mut center = from;
        center[ia] = c[0];
        center[ib] = c[1];
        Ok(ArcInfo {
            center,
            radius: circle.radius,
            sweep: circle.sweep,
            start_angle: circle.start_angle,
            ..*info
        })
    }
}
