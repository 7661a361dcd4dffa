//! The mill's programmable transformations (behaviour 13.7–13.13):
//! the codes G51.1/G50.1 mirror image, G51/G50 scaling, G68/G69 rotation,
//! G16/G15 polar coordinates and G90.1/G91.1 arc centres, and what they do
//! to a block's words — its end point, an arc's centre, turn and radius, a
//! canned cycle's hole — with the sentence that says so. The geometry is
//! [`super::frame`]'s; the codes that say where the coordinates lie are
//! [`super::coords`].

use super::frame::{self, Rotation, Scaling};
use super::modal::Distance;
use super::{AXES, Machine, Out};
use crate::diag::Diagnostic;
use crate::geometry::{Xyz, show, sub};
use crate::setup::RotationAngle;
use crate::syntax::codes::{ArcCenter, Group, MirrorMode, PolarMode, RotationMode, ScalingMode};
use crate::syntax::{Address, Block, Word};

impl Machine {
    /// The codes Fanuc forbids while scaling, rotation or programmable mirror
    /// image is on: reference returns (G27–G30) and the coordinate system codes
    /// (G52–G59, G92) (behaviour 13.13).
    pub(super) fn refuse_in_transforms(
        &self,
        span: crate::diag::Span,
        gcode: &str,
    ) -> Result<(), Diagnostic> {
        let t = &self.state.modal.transforms;
        if t.is_identity() {
            return Ok(());
        }
        let active: Vec<&str> = [
            (t.mirror != [None; 3], "G51.1"),
            (t.scaling.is_some(), "G51"),
            (t.rotation.is_some(), "G68"),
        ]
        .iter()
        .filter(|(on, _)| *on)
        .map(|(_, g)| *g)
        .collect();
        Err(self.error(
            "code-in-transform",
            span,
            format!(
                "{gcode} cannot be given while {} is on (Fanuc: reference returns and coordinate system codes only after the mirror image, scaling and rotation are cancelled)",
                active.join(", ")
            ),
        ))
    }

    /// The tool's point in the program's own coordinates: where the words
    /// of the blocks so far put it before mirror image, scaling and
    /// rotation, with the mirror image switches (setting 7.5) undone.
    pub(super) fn program_point(&self) -> Xyz {
        if !self.state.modal.transforms.is_identity() {
            return self.command;
        }
        let p = self.state.programmed;
        std::array::from_fn(|i| {
            if self.mirror[i] {
                2.0 * (self.mirror_center[i] - self.state.coords.zero[i]) - p[i]
            } else {
                p[i]
            }
        })
    }

    /// Notes whether every word reads plainly (no transformation, no polar
    /// coordinates, no absolute arc centres): the motion's fast path asks.
    pub(super) fn note_frame(&mut self) {
        let m = &self.state.modal;
        self.plain_words = m.transforms.is_identity()
            && m.polar_coordinates == PolarMode::Cancel
            && m.arc_center != Some(ArcCenter::Absolute);
    }

    /// The programmed end point (work coordinates) of the axis words of `b`
    /// for the axes in `axes`, through polar coordinates (G16), the
    /// transformations (G51.1, G51, G68) and the mirror image switches, and
    /// the program point after the block (behaviour 13.7). Absolute words
    /// send the whole program point through the transformations; a block of
    /// incremental words moves by the transformed movement (Fanuc: the
    /// centre of rotation of an incremental move made before the first
    /// absolute one is the tool's place when G68 was given).
    pub(super) fn program_targets(
        &self,
        b: &Block,
        axes: [bool; 3],
        incremental: bool,
    ) -> (Xyz, Xyz) {
        let p0 = self.program_point();
        let mut cmd = p0;
        let mut named = [false; 3];
        let mut absolute = [false; 3];
        let polar = self.state.modal.polar_coordinates == PolarMode::Start;
        let (ia, ib, _) = self.state.modal.plane.axes();
        let word = |i: usize| b.get(AXES[i].0).filter(|_| axes[i]);
        for i in 0..3 {
            let Some(w) = word(i) else { continue };
            if polar && (i == ia || i == ib) {
                continue;
            }
            named[i] = true;
            absolute[i] = !incremental;
            let v = self.mm(w.value);
            cmd[i] = if incremental { p0[i] + v } else { v };
        }
        if polar && (word(ia).is_some() || word(ib).is_some()) {
            let radius = word(ia).map(|w| self.mm(w.value));
            let angle = word(ib).map(|w| self.unitless(w));
            let q = frame::polar_point([p0[ia], p0[ib]], radius, angle, incremental);
            cmd[ia] = q[0];
            cmd[ib] = q[1];
            for i in [ia, ib] {
                named[i] = true;
                absolute[i] = true;
            }
        }
        let t = &self.state.modal.transforms;
        let p = self.state.programmed;
        let mut target = p;
        if t.is_identity() {
            for i in 0..3 {
                if named[i] {
                    target[i] = if absolute[i] {
                        self.target(i, cmd[i], false)
                    } else {
                        self.target(i, cmd[i] - p0[i], true)
                    };
                }
            }
        } else if absolute.iter().any(|a| *a) {
            let w = t.point(cmd);
            for i in 0..3 {
                target[i] = self.target(i, w[i], false);
            }
        } else {
            let d = t.vector(sub(cmd, p0));
            for i in 0..3 {
                target[i] = self.target(i, d[i], true);
            }
        }
        (target, cmd)
    }

    /// The sentence of a block whose words polar coordinates or the
    /// transformations sent elsewhere than they read: which did, the words,
    /// and the programmed point they give (behaviour 13.7).
    pub(super) fn frame_sentence(&self, b: &Block, axes: [bool; 3], target: Xyz) -> Option<String> {
        let m = &self.state.modal;
        let t = &m.transforms;
        let polar = m.polar_coordinates == PolarMode::Start;
        let mut by = Vec::new();
        if polar {
            by.push("G16");
        }
        if t.mirror != [None; 3] {
            by.push("G51.1");
        }
        if t.scaling.is_some() {
            by.push("G51");
        }
        if t.rotation.is_some() {
            by.push("G68");
        }
        if by.is_empty() {
            return None;
        }
        let (_, angle_axis, _) = m.plane.axes();
        let u = self.units();
        let words: Vec<String> = (0..3)
            .filter_map(|i| {
                let w = b.get(AXES[i].0).filter(|_| axes[i])?;
                Some(if polar && i == angle_axis {
                    format!("{}{:.3}°", AXES[i].1, self.unitless(w))
                } else {
                    format!("{}{}", AXES[i].1, show(self.mm(w.value), u))
                })
            })
            .collect();
        if words.is_empty() {
            return None;
        }
        Some(format!(
            "{}: {} goes to {}",
            by.join(", "),
            words.join(" "),
            self.show_point(target)
        ))
    }

    /// A canned cycle's hole position through polar coordinates and the
    /// transformations (behaviour 13.7): the plane's two axis words are
    /// read as a move's would be; the drilling axis's levels are not
    /// transformed (our convention). A rotation of a plane that holds the
    /// drilling axis is refused.
    pub(super) fn hole_position(
        &mut self,
        b: &Block,
        incremental: bool,
        out: &mut Out,
    ) -> Result<(), Diagnostic> {
        let plane = self.state.modal.plane;
        let (ia, ib, _) = plane.axes();
        if let Some(r) = self.state.modal.transforms.rotation
            && r.plane != plane
        {
            return Err(self.error(
                "rotation-plane",
                b.span,
                format!(
                    "a canned cycle in {} while G68 rotates the {} plane: its drilling axis would be rotated",
                    plane.gcode(),
                    r.plane.gcode()
                ),
            ));
        }
        let mut axes = [false; 3];
        axes[ia] = true;
        axes[ib] = true;
        let (t, cmd) = self.program_targets(b, axes, incremental);
        if let Some(note) = self.frame_sentence(b, axes, t) {
            out.notes.push(note);
        }
        self.state.programmed[ia] = t[ia];
        self.state.programmed[ib] = t[ib];
        self.command = cmd;
        Ok(())
    }

    /// After a hole: the program point's drilling axis follows the level the
    /// tool came back to (the levels are not transformed).
    pub(super) fn hole_done(&mut self, n: usize) {
        let t = self.state.modal.transforms;
        let z = self.state.programmed[n];
        self.command[n] = if t.is_identity() {
            z
        } else {
            t.axis_inverse(n, z)
        };
    }

    /// What polar coordinates and the transformations do to an arc
    /// (behaviour 13.8–13.11): true when it turns the other way. A rotation
    /// of another plane is the control's alarm (Fanuc PS0144: the arc's and
    /// the rotation's planes must be one), and so is a centre word in polar
    /// coordinates (an arc there takes R).
    pub(super) fn framed_arc(&self, b: &Block) -> Result<bool, Diagnostic> {
        let m = &self.state.modal;
        if let Some(r) = m.transforms.rotation
            && r.plane != m.plane
        {
            return Err(self.error(
                "rotation-plane",
                b.span,
                format!(
                    "an arc in {} while G68 rotates the {} plane (Fanuc alarm PS0144: the planes must be one)",
                    m.plane.gcode(),
                    r.plane.gcode()
                ),
            ));
        }
        if m.polar_coordinates == PolarMode::Start
            && let Some(w) = [Address::I, Address::J, Address::K]
                .iter()
                .find_map(|a| b.get(*a))
        {
            return Err(self.error(
                "polar-arc-center",
                w.span,
                "in polar coordinates (G16) an arc takes its radius R, not centre words (Fanuc)",
            ));
        }
        Ok(m.transforms.reverses(m.plane))
    }

    /// The centre of an arc whose words polar coordinates, the
    /// transformations or G90.1 read (behaviour 13.8–13.12), as the offset
    /// from the arc's programmed start (mm, work coordinates): I, J, K from
    /// the start in G91.1 (the manuals' only way), the centre's coordinates
    /// in G90.1; through the transformations and the mirror image switches,
    /// with G45–G48's change of each word (behaviour 4.8). A centre word of
    /// another plane is passed over with a warning (behaviour 2.13).
    pub(super) fn framed_centres(
        &self,
        b: &Block,
        words: [Option<f64>; 3],
        change: Option<crate::offsets::position::PositionChange>,
        req: &mut super::ArcRequest,
        out: &mut Out,
    ) -> Result<(), Diagnostic> {
        let m = &self.state.modal;
        let (ia, ib, _) = m.plane.axes();
        let in_plane = |i: usize| i == ia || i == ib;
        let centre_addr = [Address::I, Address::J, Address::K];
        for (i, w) in words.iter().enumerate() {
            if w.is_some() && !in_plane(i) {
                out.warnings.push(Diagnostic::warning(
                    "arc-center-word",
                    self.word_span(b, centre_addr[i]),
                    format!(
                        "{} is not a centre word of the {} plane and is ignored",
                        centre_addr[i].letter(),
                        m.plane.gcode()
                    ),
                ));
            }
        }
        let plane_word = |i: usize| words[i].map(|v| self.mm(v));
        let t = &m.transforms;
        let offsets: Xyz = if m.arc_center == Some(ArcCenter::Absolute) {
            let (Some(a), Some(c)) = (plane_word(ia), plane_word(ib)) else {
                return Err(self.error(
                    "arc-without-center",
                    b.span,
                    format!(
                        "in G90.1 an arc's centre is the point its two centre words of {} give: write both",
                        m.plane.gcode()
                    ),
                ));
            };
            let mut centre = self.program_point();
            centre[ia] = a;
            centre[ib] = c;
            let w = t.point(centre);
            std::array::from_fn(|i| self.target(i, w[i], false) - self.state.programmed[i])
        } else {
            let mut v = [0.0; 3];
            for i in [ia, ib] {
                v[i] = plane_word(i).unwrap_or(0.0);
            }
            let d = t.vector(v);
            std::array::from_fn(|i| if self.mirror[i] { -d[i] } else { d[i] })
        };
        for i in [ia, ib] {
            req.center[i] = offsets[i];
            if let (Some(c), Some(_)) = (change, words[i]) {
                req.center_change[i] = c.center(i, offsets[i], &mut out.notes);
            }
        }
        Ok(())
    }

    /// An angle or a magnification word (behaviour 13.9–13.11).
    pub(super) fn unitless(&self, w: &Word) -> f64 {
        frame::unitless(w, self.units(), self.setup.settings.decimal_input())
    }

    /// The group 11, 16, 17, 22 codes and G90.1/G91.1 of a mill block
    /// (behaviour 13.8–13.12). Returns true when the block's axis words were
    /// theirs (a centre, a mirror axis): the block then moves by none of
    /// them.
    pub(super) fn transform_codes(&mut self, b: &Block, out: &mut Out) -> Result<bool, Diagnostic> {
        let c = b.codes();
        let (mirror, scaling, rotation, polar, arc) = (
            c.mirror(),
            c.scaling(),
            c.rotation(),
            c.polar_coordinates(),
            c.arc_center(),
        );
        if mirror.is_none()
            && scaling.is_none()
            && rotation.is_none()
            && polar.is_none()
            && arc.is_none()
        {
            return Ok(false);
        }
        let mut t = self.state.modal.transforms;
        let was_identity = t.is_identity();
        let p0 = self.program_point();
        let words: [Option<f64>; 3] = AXES.map(|(a, _)| b.value(a).map(|v| self.mm(v)));
        let order = |code: &str, on: &str, span| {
            self.error(
                "transform-order",
                span,
                format!(
                    "{code} cannot be given while {on} is on (Fanuc: mirror image, then scaling, then rotation; cancel them in the reverse order)"
                ),
            )
        };
        let mut consumed = false;
        if let Some(m) = mirror {
            let span = b.code_span(Group::Mirror);
            if t.rotation.is_some() {
                return Err(order(m.gcode(), "G68", span));
            }
            if t.scaling.is_some() {
                return Err(order(m.gcode(), "G51", span));
            }
            consumed = true;
            let any = words.iter().any(Option::is_some);
            match m {
                MirrorMode::Start if !any => {
                    return Err(self.error(
                        "mirror-without-axis",
                        span,
                        "G51.1 needs the axes to mirror and the coordinate each is mirrored about (G51.1 X50.)",
                    ));
                }
                MirrorMode::Start => {
                    for (axis, w) in words.iter().enumerate() {
                        if let Some(v) = w {
                            t.mirror[axis] = Some(*v);
                        }
                    }
                }
                MirrorMode::Cancel if !any => t.mirror = [None; 3],
                MirrorMode::Cancel => {
                    for (axis, w) in words.iter().enumerate() {
                        if w.is_some() {
                            t.mirror[axis] = None;
                        }
                    }
                }
            }
        }
        if let Some(s) = scaling {
            let span = b.code_span(Group::Scaling);
            if t.rotation.is_some() {
                return Err(order(s.gcode(), "G68", span));
            }
            match s {
                ScalingMode::Start => {
                    consumed = true;
                    let center: Xyz = std::array::from_fn(|i| words[i].unwrap_or(p0[i]));
                    let factors = self.scaling_factors(b, span)?;
                    t.scaling = Some(Scaling {
                        center: t.mirrored(center),
                        factors,
                    });
                }
                ScalingMode::Cancel => t.scaling = None,
            }
        }
        if let Some(r) = rotation {
            let span = b.code_span(Group::Rotation);
            match r {
                RotationMode::Start => {
                    consumed = true;
                    let plane = self.state.modal.plane;
                    let (ia, ib, n) = plane.axes();
                    if let Some(w) = b.get(AXES[n].0) {
                        return Err(self.error(
                            "rotation-words",
                            w.span,
                            format!(
                                "G68 in {} takes the centre on {} and {}; {} is not one of them",
                                plane.gcode(),
                                AXES[ia].1,
                                AXES[ib].1,
                                AXES[n].1
                            ),
                        ));
                    }
                    let Some(rw) = b.get(Address::R) else {
                        return Err(self.error(
                            "rotation-angle",
                            span,
                            "G68 needs R, the angle of rotation in degrees (the control's default-angle parameter is not modelled)",
                        ));
                    };
                    let mut degrees = self.unitless(rw);
                    let incremental_r = self.setup.settings.rotation_angle
                        == RotationAngle::DistanceMode
                        && self.state.modal.distance == Distance::Incremental;
                    if incremental_r && let Some(old) = t.rotation {
                        degrees += old.degrees;
                    }
                    let mut center = p0;
                    for i in [ia, ib] {
                        if let Some(v) = words[i] {
                            center[i] = v;
                        }
                    }
                    t.rotation = Some(Rotation {
                        plane,
                        center: t.before_rotation(center),
                        degrees,
                    });
                }
                RotationMode::Cancel => t.rotation = None,
            }
        }
        // A sentence only for a mode the block changes.
        let polar = polar.filter(|p| *p != self.state.modal.polar_coordinates);
        if let Some(p) = polar {
            self.state.modal.polar_coordinates = p;
        }
        let arc = arc.filter(|a| Some(*a) != self.state.modal.arc_center);
        if let Some(a) = arc {
            self.state.modal.arc_center = Some(a);
            if !self.arc_center_warned {
                self.arc_center_warned = true;
                out.warnings.push(Diagnostic::warning(
                    "arc-center-mode",
                    b.code_span(Group::ArcCenter),
                    format!(
                        "{} is not in the Fanuc, Haas or YASNAC manuals (their I, J, K are always measured from the arc's start, as G91.1 says); offsetlab reads it as Mach3 and LinuxCNC do",
                        a.gcode()
                    ),
                ));
            }
        }
        if was_identity && !t.is_identity() {
            self.command = p0;
        }
        let before = self.state.modal.transforms;
        self.state.modal.transforms = t;
        self.note_frame();
        self.transform_notes(before, polar, arc, out);
        Ok(consumed)
    }

    /// G51's magnifications (behaviour 13.9): P for every axis, in
    /// thousandths (P1500 is ×1.5), or I, J, K each for its axis (an axis
    /// left out keeps ×1); a negative one mirrors its axis.
    fn scaling_factors(&self, b: &Block, span: crate::diag::Span) -> Result<Xyz, Diagnostic> {
        let ijk = [Address::I, Address::J, Address::K].map(|a| b.get(a));
        let factors = match (b.get(Address::P), ijk.iter().any(Option::is_some)) {
            (Some(p), false) => [f64::from(p.int()) * 0.001; 3],
            (None, true) => ijk.map(|w| w.map_or(1.0, |w| self.unitless(w))),
            (Some(p), true) => {
                return Err(self.error(
                    "scaling-factor",
                    p.span,
                    "G51 takes P (every axis) or I, J, K (each axis), not both",
                ));
            }
            (None, false) => {
                return Err(self.error(
                    "scaling-factor",
                    span,
                    "G51 needs P (every axis, in thousandths: P2000 is ×2) or I, J, K (each axis); the control's default-magnification parameter is not modelled",
                ));
            }
        };
        if factors.contains(&0.0) {
            return Err(self.error(
                "scaling-factor",
                span,
                "a scaling magnification of 0 would send every point to the centre",
            ));
        }
        Ok(factors)
    }

    /// The sentences of a block that changed the transformations.
    fn transform_notes(
        &self,
        before: frame::Transforms,
        polar: Option<PolarMode>,
        arc: Option<ArcCenter>,
        out: &mut Out,
    ) {
        let t = self.state.modal.transforms;
        let u = self.units();
        if t.mirror != before.mirror {
            let on: Vec<String> = (0..3)
                .filter_map(|i| {
                    t.mirror[i].map(|m| format!("{} about {}{}", AXES[i].1, AXES[i].1, show(m, u)))
                })
                .collect();
            out.notes.push(if on.is_empty() {
                "G50.1: programmable mirror image off".to_string()
            } else {
                format!(
                    "G51.1: mirror image of {}: arcs turn the other way when one axis of their plane is mirrored",
                    on.join(", ")
                )
            });
        }
        if t.scaling != before.scaling {
            out.notes.push(match t.scaling {
                Some(s) => format!(
                    "G51: scaling ×{} about {} (the offsets are not scaled)",
                    factors_text(s.factors),
                    self.show_point(s.center)
                ),
                None => "G50: scaling off".to_string(),
            });
        }
        if t.rotation != before.rotation {
            out.notes.push(match t.rotation {
                Some(r) => {
                    let (a, bb, _) = r.plane.axes();
                    format!(
                        "G68: coordinates rotated {:.3}° about {}{} {}{} ({})",
                        r.degrees,
                        AXES[a].1,
                        show(r.center[a], u),
                        AXES[bb].1,
                        show(r.center[bb], u),
                        r.plane.gcode()
                    )
                }
                None => "G69: rotation off".to_string(),
            });
        }
        match polar {
            Some(PolarMode::Start) => {
                let (a, bb, _) = self.state.modal.plane.axes();
                out.notes.push(format!(
                    "G16: polar coordinates: {} is the radius, {} the angle in degrees ({})",
                    AXES[a].1,
                    AXES[bb].1,
                    self.state.modal.plane.gcode()
                ));
            }
            Some(PolarMode::Cancel) => out.notes.push("G15: Cartesian coordinates".into()),
            None => {}
        }
        match arc {
            Some(ArcCenter::Absolute) => out
                .notes
                .push("G90.1: I, J, K are the coordinates of an arc's centre".into()),
            Some(ArcCenter::Incremental) => out
                .notes
                .push("G91.1: I, J, K measure an arc's centre from its start".into()),
            None => {}
        }
    }
}

/// Scaling magnifications as a sentence writes them: one number when they
/// agree.
fn factors_text(f: Xyz) -> String {
    if f[0] == f[1] && f[1] == f[2] {
        format!("{:.3}", f[0])
    } else {
        format!("X{:.3} Y{:.3} Z{:.3}", f[0], f[1], f[2])
    }
}
