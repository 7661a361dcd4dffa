//! The view: which plane is drawn (or the 3D view's angles), the projection
//! of a 3D point onto the screen's plane, and the world-to-screen transform
//! that fits a path into a rectangle of the drawing surface. Screen coordinates are
//! CSS pixels with y pointing down; world coordinates are the toolpath's units
//! with the vertical axis pointing up, as on a machine drawing.

use crate::setup::MachineKind;

/// Which two axes are drawn, horizontal first.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Plane {
    /// X right, Y up (the mill's default, G17).
    #[default]
    Xy,
    /// X right, Z up (G18 seen from the front).
    Xz,
    /// Y right, Z up (G19 seen from the side).
    Yz,
    /// The lathe's view: Z right, X up **as a radius** (the diameter halved),
    /// so the part profile is drawn true to size above its centre line.
    LatheZx,
    /// The lathe's face view, looking along Z from the tailstock: X right
    /// **as a radius**, the hypothetical axis C of polar coordinate
    /// interpolation up (the toolpath's Y), the spindle axis at the origin
    /// (behaviour 14.16).
    LatheXc,
    /// The mill's 3D view: orthographic, turned by a yaw and a pitch
    /// (behaviour 10.8). XY, XZ and YZ are this view at fixed angles.
    Orbit(Angles),
    /// The lathe's 3D view (behaviour 10.18): the same turn of the lathe's
    /// space, Z along the spindle to the right, X **as a radius** up and
    /// the face's C (the toolpath's Y) towards the eye, so that at yaw 0
    /// and pitch 0 it is exactly the ZX view.
    LatheOrbit(Angles),
}

/// The 3D view's angles in thousandths of a degree (whole numbers, so a
/// view compares, hashes and round-trips through a link exactly).
///
/// Yaw turns the part about Z: at 0 the screen's right is +X, at 90 it is
/// +Y. Pitch lifts the eye from the XY plane: at 0 the screen's up is +Z
/// (a front view), at 90 the eye looks straight down (the top view).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Angles {
    yaw: i32,
    pitch: i32,
}

impl Angles {
    /// The isometric view: yaw 45°, pitch atan(1/√2) ≈ 35.264°, the three
    /// axes drawn at the same length.
    pub const ISO: Angles = Angles {
        yaw: 45_000,
        pitch: 35_264,
    };

    /// Angles in degrees: yaw taken into [0, 360), pitch limited to
    /// [-90, 90], both to a thousandth; non-finite reads 0.
    pub fn degrees(yaw: f64, pitch: f64) -> Angles {
        let thousandths = |d: f64| {
            if d.is_finite() {
                (d.clamp(-1e6, 1e6) * 1000.0).round() as i64
            } else {
                0
            }
        };
        Angles {
            yaw: thousandths(yaw).rem_euclid(360_000) as i32,
            pitch: thousandths(pitch).clamp(-90_000, 90_000) as i32,
        }
    }

    /// Yaw in degrees, in [0, 360).
    pub fn yaw(self) -> f64 {
        f64::from(self.yaw) / 1000.0
    }

    /// Pitch in degrees, in [-90, 90].
    pub fn pitch(self) -> f64 {
        f64::from(self.pitch) / 1000.0
    }

    /// Turned by `dyaw` and `dpitch` degrees (pitch stops at ±90).
    pub fn turned(self, dyaw: f64, dpitch: f64) -> Angles {
        Angles::degrees(self.yaw() + dyaw, self.pitch() + dpitch)
    }

    /// The rotation from world to view: rows are the screen's right, the
    /// screen's up and the direction towards the eye. With yaw ψ and pitch
    /// θ: right = (cos ψ, sin ψ, 0), up = (−sin ψ sin θ, cos ψ sin θ, cos θ),
    /// towards the eye = right × up = (sin ψ cos θ, −cos ψ cos θ, sin θ).
    pub fn rotation(self) -> [[f64; 3]; 3] {
        let (sy, cy) = sin_cos_degrees(self.yaw());
        let (sp, cp) = sin_cos_degrees(self.pitch());
        [
            [cy, sy, 0.0],
            [-sy * sp, cy * sp, cp],
            [sy * cp, -cy * cp, sp],
        ]
    }
}

/// Sine and cosine of an angle in degrees, exact at multiples of 90° (so
/// the plane views' rotations hold exact zeros and ones).
fn sin_cos_degrees(d: f64) -> (f64, f64) {
    let r = d.rem_euclid(360.0);
    match r {
        0.0 => (0.0, 1.0),
        90.0 => (1.0, 0.0),
        180.0 => (0.0, -1.0),
        270.0 => (-1.0, 0.0),
        _ => r.to_radians().sin_cos(),
    }
}

/// A 3D point to the view's (horizontal, vertical) coordinates: the first
/// two rows of a linear map. Every view goes through it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Projection {
    rows: [[f64; 3]; 2],
}

impl Projection {
    /// Projects an x, y, z vertex: (horizontal, vertical). Missing
    /// coordinates read as 0.
    #[inline]
    pub fn project(&self, p: &[f64]) -> (f64, f64) {
        let at = |i: usize| p.get(i).copied().unwrap_or(0.0);
        let (x, y, z) = (at(0), at(1), at(2));
        let [a, b] = &self.rows;
        (
            a[0] * x + a[1] * y + a[2] * z,
            b[0] * x + b[1] * y + b[2] * z,
        )
    }
}

impl Plane {
    /// The usual view of a machine: XY for the mill, ZX for the lathe.
    pub fn for_machine(machine: MachineKind) -> Plane {
        match machine {
            MachineKind::Mill => Plane::Xy,
            MachineKind::Lathe => Plane::LatheZx,
        }
    }

    /// The views as 3D angles, those a drag turns from: XY is the top
    /// view (yaw 0, pitch 90), XZ the front (0, 0), YZ the side (90, 0);
    /// the lathe's ZX is its 3D view at (0, 0). None for the face view XC,
    /// which no yaw and pitch of the lathe's space show (behaviour 10.18).
    pub fn angles(self) -> Option<Angles> {
        match self {
            Plane::Xy => Some(Angles::degrees(0.0, 90.0)),
            Plane::Xz | Plane::LatheZx => Some(Angles::degrees(0.0, 0.0)),
            Plane::Yz => Some(Angles::degrees(90.0, 0.0)),
            Plane::Orbit(a) | Plane::LatheOrbit(a) => Some(a),
            Plane::LatheXc => None,
        }
    }

    /// The view's projection: the first two rows of the rotation of its
    /// angles; the lathe's views take X as a radius (halved). The lathe's
    /// space is turned as the mill's with its Z as the mill's X, its X
    /// radius as the mill's Z and its Y (C) as the mill's −Y (a right-handed
    /// frame): a row (a, b, c) of the rotation reads z·a − y·b + (x/2)·c.
    pub fn projection(self) -> Projection {
        let rows = match self {
            Plane::LatheZx => [[0.0, 0.0, 1.0], [0.5, 0.0, 0.0]],
            Plane::LatheXc => [[0.5, 0.0, 0.0], [0.0, 1.0, 0.0]],
            Plane::LatheOrbit(a) => {
                let [r, u, _] = a.rotation();
                let lathe = |row: [f64; 3]| [row[2] / 2.0, -row[1], row[0]];
                [lathe(r), lathe(u)]
            }
            Plane::Xy | Plane::Xz | Plane::Yz | Plane::Orbit(_) => {
                let a = self.angles().unwrap_or(Angles::ISO);
                let [r, u, _] = a.rotation();
                [r, u]
            }
        };
        Projection { rows }
    }

    /// The plane as the machine has it: a 3D view is the machine's own
    /// (the lathe's turns the lathe's space); None for a plane the machine
    /// does not have (XY, XZ, YZ on the lathe; ZX, XC on the mill).
    pub fn on(self, machine: MachineKind) -> Option<Plane> {
        let lathe = machine == MachineKind::Lathe;
        match self {
            Plane::Orbit(a) | Plane::LatheOrbit(a) => Some(if lathe {
                Plane::LatheOrbit(a)
            } else {
                Plane::Orbit(a)
            }),
            p if p.is_lathe() == lathe => Some(p),
            _ => None,
        }
    }

    /// The 3D view of the machine at `angles`.
    pub fn orbit(machine: MachineKind, angles: Angles) -> Plane {
        Plane::Orbit(angles)
            .on(machine)
            .unwrap_or(Plane::Orbit(angles))
    }

    /// Projects an x, y, z vertex onto the plane: (horizontal, vertical).
    /// Missing coordinates read as 0. (Drawing loops keep the frame's
    /// [`Projection`] rather than work it out per point.)
    pub fn project(self, p: &[f64]) -> (f64, f64) {
        self.projection().project(p)
    }

    /// True for the 3D view at any angles (the plane views are drawn
    /// with their axes and grid as flat views).
    pub fn is_orbit(self) -> bool {
        matches!(self, Plane::Orbit(_) | Plane::LatheOrbit(_))
    }

    /// Names of the horizontal and the vertical axis, for labels.
    pub fn axis_names(self) -> (&'static str, &'static str) {
        match self {
            Plane::Xy => ("X", "Y"),
            Plane::Xz => ("X", "Z"),
            Plane::Yz => ("Y", "Z"),
            Plane::LatheZx => ("Z", "X (radius)"),
            Plane::LatheXc => ("X (radius)", "C"),
            Plane::Orbit(_) | Plane::LatheOrbit(_) => ("", ""),
        }
    }

    /// A short name for the view caption.
    pub fn name(self) -> &'static str {
        match self {
            Plane::Xy => "XY",
            Plane::Xz => "XZ",
            Plane::Yz => "YZ",
            Plane::LatheZx => "ZX",
            Plane::LatheXc => "XC",
            Plane::Orbit(_) | Plane::LatheOrbit(_) => "3D",
        }
    }

    /// Reads a view name as [`Plane::name`] writes it (any case): XY, XZ,
    /// YZ, ZX, XC, or 3D (at the isometric angles; the mill's until
    /// [`Plane::on`] makes it the lathe's).
    pub fn parse(name: &str) -> Option<Plane> {
        Some(match name.to_ascii_uppercase().as_str() {
            "XY" => Plane::Xy,
            "XZ" => Plane::Xz,
            "YZ" => Plane::Yz,
            "ZX" => Plane::LatheZx,
            "XC" => Plane::LatheXc,
            "3D" => Plane::Orbit(Angles::ISO),
            _ => return None,
        })
    }

    /// True when the horizontal axis (vertical = 0) is a lathe's centre line.
    pub fn has_centre_line(self) -> bool {
        self == Plane::LatheZx
    }

    /// True for the lathe's views (ZX, the face XC and its 3D view); the
    /// others are the mill's.
    pub fn is_lathe(self) -> bool {
        matches!(self, Plane::LatheZx | Plane::LatheXc | Plane::LatheOrbit(_))
    }

    /// True when the origin is the spindle axis seen end on (the face
    /// view): the drawing always holds it.
    pub fn has_spindle_centre(self) -> bool {
        self == Plane::LatheXc
    }
}

/// An axis-aligned rectangle in screen pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rect {
    /// Left edge.
    pub x: f64,
    /// Top edge.
    pub y: f64,
    /// Width.
    pub w: f64,
    /// Height.
    pub h: f64,
}

impl Rect {
    /// A rectangle from its left, top, width and height.
    pub fn new(x: f64, y: f64, w: f64, h: f64) -> Rect {
        Rect { x, y, w, h }
    }

    /// Right edge.
    pub fn right(&self) -> f64 {
        self.x + self.w
    }

    /// Bottom edge.
    pub fn bottom(&self) -> f64 {
        self.y + self.h
    }

    /// True when the two rectangles overlap (touching edges do not).
    pub fn intersects(&self, other: &Rect) -> bool {
        self.x < other.right()
            && other.x < self.right()
            && self.y < other.bottom()
            && other.y < self.bottom()
    }
}

/// A box in plane (world) coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Extent {
    /// Smallest horizontal coordinate.
    pub min_u: f64,
    /// Smallest vertical coordinate.
    pub min_v: f64,
    /// Largest horizontal coordinate.
    pub max_u: f64,
    /// Largest vertical coordinate.
    pub max_v: f64,
}

impl Extent {
    /// The box holding one point.
    pub fn point(u: f64, v: f64) -> Extent {
        Extent {
            min_u: u,
            min_v: v,
            max_u: u,
            max_v: v,
        }
    }

    /// Grows the box to hold a point (non-finite points are ignored).
    pub fn include(&mut self, u: f64, v: f64) {
        if !(u.is_finite() && v.is_finite()) {
            return;
        }
        self.min_u = self.min_u.min(u);
        self.min_v = self.min_v.min(v);
        self.max_u = self.max_u.max(u);
        self.max_v = self.max_v.max(v);
    }

    /// Width.
    pub fn width(&self) -> f64 {
        self.max_u - self.min_u
    }

    /// Height.
    pub fn height(&self) -> f64 {
        self.max_v - self.min_v
    }
}

/// World to screen: `x = origin_x + u * scale`, `y = origin_y - v * scale`
/// (the vertical axis is flipped so that +Y is up). One scale for both axes:
/// a circle stays round.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transform {
    /// Pixels per world unit.
    pub scale: f64,
    /// Screen x of world u = 0.
    pub origin_x: f64,
    /// Screen y of world v = 0.
    pub origin_y: f64,
}

impl Transform {
    /// The largest scale that shows all of `extent` inside `rect`, centred.
    /// A degenerate extent (a point, or nothing drawn yet) is shown as a box
    /// `min_size` wide around its centre; a line gets that size across it.
    pub fn fit(extent: Extent, rect: Rect, min_size: f64) -> Transform {
        let min_size = if min_size.is_finite() && min_size > 0.0 {
            min_size
        } else {
            1.0
        };
        let w = extent.width().max(0.0);
        let h = extent.height().max(0.0);
        let (w, h) = if w < min_size * 1e-6 && h < min_size * 1e-6 {
            (min_size, min_size)
        } else {
            (w, h)
        };
        let sx = if w > 0.0 { rect.w / w } else { f64::INFINITY };
        let sy = if h > 0.0 { rect.h / h } else { f64::INFINITY };
        let mut scale = sx.min(sy);
        if !scale.is_finite() || scale <= 0.0 {
            scale = 1.0;
        }
        let cu = (extent.min_u + extent.max_u) / 2.0;
        let cv = (extent.min_v + extent.max_v) / 2.0;
        let (cu, cv) = if cu.is_finite() && cv.is_finite() {
            (cu, cv)
        } else {
            (0.0, 0.0)
        };
        Transform {
            scale,
            origin_x: rect.x + rect.w / 2.0 - cu * scale,
            origin_y: rect.y + rect.h / 2.0 + cv * scale,
        }
    }

    /// Screen position of a world point.
    pub fn to_screen(&self, u: f64, v: f64) -> (f64, f64) {
        (
            self.origin_x + u * self.scale,
            self.origin_y - v * self.scale,
        )
    }

    /// World position of a screen point.
    pub fn to_world(&self, x: f64, y: f64) -> (f64, f64) {
        (
            (x - self.origin_x) / self.scale,
            (self.origin_y - y) / self.scale,
        )
    }

    /// The screen rectangle a world box covers.
    pub fn screen_rect(&self, extent: &Extent) -> Rect {
        let (x0, y0) = self.to_screen(extent.min_u, extent.max_v);
        let (x1, y1) = self.to_screen(extent.max_u, extent.min_v);
        Rect::new(x0, y0, x1 - x0, y1 - y0)
    }

    /// The world box a screen rectangle shows.
    pub fn visible(&self, rect: Rect) -> Extent {
        let (u0, v0) = self.to_world(rect.x, rect.bottom());
        let (u1, v1) = self.to_world(rect.right(), rect.y);
        Extent {
            min_u: u0,
            min_v: v0,
            max_u: u1,
            max_v: v1,
        }
    }
}

/// The smallest "nice" length of the 1-2-5 series (…, 0.5, 1, 2, 5, 10, 20,
/// …) that is at least `at_least`. Used for grid spacing and the scale bar so
/// that labels read as round numbers at every zoom.
pub fn nice_step(at_least: f64) -> f64 {
    if !(at_least.is_finite() && at_least > 0.0) {
        return 1.0;
    }
    let exponent = at_least.log10().floor();
    let base = 10f64.powf(exponent);
    for m in [1.0, 2.0, 5.0, 10.0] {
        let step = m * base;
        // Guard against log10 rounding just below a power of ten.
        if step >= at_least * (1.0 - 1e-9) {
            return step;
        }
    }
    10.0 * base
}

/// Decimal places needed to print multiples of a 1-2-5 `step` exactly.
pub fn decimals_for(step: f64) -> usize {
    if !(step.is_finite() && step > 0.0) || step >= 1.0 {
        return 0;
    }
    let d = (-step.log10()).ceil();
    (d.max(0.0) as usize).min(6)
}

/// A coordinate for a label: `decimals` places, never "-0".
pub fn format_number(v: f64, decimals: usize) -> String {
    let s = format!("{v:.decimals$}");
    if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') {
        s[1..].to_string()
    } else {
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nice_steps_follow_the_one_two_five_series() {
        assert_eq!(nice_step(1.0), 1.0);
        assert_eq!(nice_step(1.1), 2.0);
        assert_eq!(nice_step(2.0), 2.0);
        assert_eq!(nice_step(2.5), 5.0);
        assert_eq!(nice_step(6.0), 10.0);
        assert_eq!(nice_step(37.0), 50.0);
        assert_eq!(nice_step(120.0), 200.0);
        assert!((nice_step(0.003) - 0.005).abs() < 1e-15);
        assert!((nice_step(0.01) - 0.01).abs() < 1e-15);
        assert_eq!(nice_step(0.0), 1.0);
        assert_eq!(nice_step(f64::NAN), 1.0);
    }

    #[test]
    fn label_decimals_match_the_step() {
        assert_eq!(decimals_for(10.0), 0);
        assert_eq!(decimals_for(1.0), 0);
        assert_eq!(decimals_for(0.5), 1);
        assert_eq!(decimals_for(0.2), 1);
        assert_eq!(decimals_for(0.05), 2);
        assert_eq!(format_number(-0.0001, 2), "0.00");
        assert_eq!(format_number(-2.5, 1), "-2.5");
        assert_eq!(format_number(40.0, 0), "40");
    }

    #[test]
    fn fit_centres_the_extent_and_keeps_one_scale() {
        // 100 x 50 world units into a 400 x 400 rectangle at (10, 20):
        // the width limits the scale to 4 px per unit.
        let e = Extent {
            min_u: -50.0,
            min_v: 0.0,
            max_u: 50.0,
            max_v: 50.0,
        };
        let rect = Rect::new(10.0, 20.0, 400.0, 400.0);
        let t = Transform::fit(e, rect, 1.0);
        assert_eq!(t.scale, 4.0);
        // The centre of the extent lands on the centre of the rectangle.
        assert_eq!(t.to_screen(0.0, 25.0), (210.0, 220.0));
        // +v is up on the screen.
        assert_eq!(t.to_screen(-50.0, 50.0), (10.0, 120.0));
        assert_eq!(t.to_screen(50.0, 0.0), (410.0, 320.0));
        assert_eq!(t.to_world(210.0, 220.0), (0.0, 25.0));
    }

    #[test]
    fn fit_of_a_point_or_a_line_uses_the_minimum_size() {
        let rect = Rect::new(0.0, 0.0, 200.0, 100.0);
        let t = Transform::fit(Extent::point(5.0, 5.0), rect, 10.0);
        assert_eq!(t.scale, 10.0);
        assert_eq!(t.to_screen(5.0, 5.0), (100.0, 50.0));
        // A horizontal line 40 long: only its length limits the scale.
        let mut line = Extent::point(0.0, 0.0);
        line.include(40.0, 0.0);
        let t = Transform::fit(line, rect, 10.0);
        assert_eq!(t.scale, 5.0);
        // Non-finite points never poison the extent.
        line.include(f64::NAN, 1.0);
        assert_eq!(line.height(), 0.0);
    }

    #[test]
    fn visible_box_inverts_the_transform() {
        let t = Transform {
            scale: 2.0,
            origin_x: 100.0,
            origin_y: 100.0,
        };
        let v = t.visible(Rect::new(0.0, 0.0, 200.0, 200.0));
        assert_eq!(
            (v.min_u, v.min_v, v.max_u, v.max_v),
            (-50.0, -50.0, 50.0, 50.0)
        );
    }

    /// Behaviour 10.8: the isometric view by hand. Yaw ψ = 45°, pitch
    /// θ = 35.264° (tan θ = 1/√2, so sin θ = 1/√3 = 0.57735, cos θ =
    /// √(2/3) = 0.81650); cos ψ = sin ψ = 0.70711.
    /// right = (cos ψ, sin ψ, 0) = (0.70711, 0.70711, 0)
    /// up = (−sin ψ sin θ, cos ψ sin θ, cos θ) = (−0.40825, 0.40825, 0.81650)
    /// so (1,0,0) lands at (0.70711, −0.40825), (0,1,0) at (0.70711,
    /// 0.40825) and (0,0,1) at (0, 0.81650): each axis √(0.5 + 1/6) =
    /// 0.81650 long on the screen, the isometric view's equal axes.
    #[test]
    // The figures are the hand computation's, to five places (0.70711 is
    // cos 45° as written above, not a constant to look up).
    #[allow(clippy::approx_constant)]
    fn behaviour10_8_iso_view_projects_the_axes_by_hand() {
        let p = Plane::Orbit(Angles::ISO).projection();
        let near = |a: (f64, f64), b: (f64, f64)| {
            assert!(
                (a.0 - b.0).abs() < 1e-4 && (a.1 - b.1).abs() < 1e-4,
                "{a:?} vs {b:?}"
            );
        };
        near(p.project(&[1.0, 0.0, 0.0]), (0.70711, -0.40825));
        near(p.project(&[0.0, 1.0, 0.0]), (0.70711, 0.40825));
        near(p.project(&[0.0, 0.0, 1.0]), (0.0, 0.81650));
        // Linear: (10, 20, 30) = 10·X + 20·Y + 30·Z =
        // (7.0711 + 14.1421 + 0, −4.0825 + 8.1650 + 24.4949) = (21.2132, 28.5774).
        near(p.project(&[10.0, 20.0, 30.0]), (21.2132, 28.5774));
        for unit in [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]] {
            let (u, v) = p.project(&unit);
            assert!((u.hypot(v) - 0.81650).abs() < 1e-4);
        }
    }

    /// Behaviour 10.8: the plane views are the 3D view at fixed angles,
    /// exactly: top (yaw 0, pitch 90) is XY, front (0, 0) is XZ, side
    /// (90, 0) is YZ.
    #[test]
    fn behaviour10_8_plane_views_are_the_3d_view_at_fixed_angles() {
        for (plane, yaw, pitch, seen) in [
            (Plane::Xy, 0.0, 90.0, (1.0, 2.0)),
            (Plane::Xz, 0.0, 0.0, (1.0, 3.0)),
            (Plane::Yz, 90.0, 0.0, (2.0, 3.0)),
        ] {
            let orbit = Plane::Orbit(Angles::degrees(yaw, pitch));
            assert_eq!(orbit.projection(), plane.projection(), "{plane:?}");
            assert_eq!(plane.project(&[1.0, 2.0, 3.0]), seen);
            assert_eq!(orbit.project(&[1.0, 2.0, 3.0]), seen);
            assert_eq!(plane.angles(), Some(Angles::degrees(yaw, pitch)));
        }
        assert_eq!(Plane::LatheXc.angles(), None);
        assert_eq!(Plane::parse("3d"), Some(Plane::Orbit(Angles::ISO)));
        assert_eq!(Plane::Orbit(Angles::ISO).name(), "3D");
    }

    /// The rotation is a rotation at any angles (rows orthonormal, right
    /// × up = towards the eye), so lengths along the screen are true.
    #[test]
    fn behaviour10_8_the_view_rotation_is_orthonormal() {
        for (yaw, pitch) in [(0.0, 0.0), (30.0, 10.0), (123.456, -47.5), (300.0, 89.0)] {
            let r = Angles::degrees(yaw, pitch).rotation();
            for i in 0..3 {
                for j in 0..3 {
                    let dot: f64 = (0..3).map(|k| r[i][k] * r[j][k]).sum();
                    let want = if i == j { 1.0 } else { 0.0 };
                    assert!((dot - want).abs() < 1e-12, "{yaw} {pitch} {i}{j}");
                }
            }
            let [a, b, n] = r;
            let cross = [
                a[1] * b[2] - a[2] * b[1],
                a[2] * b[0] - a[0] * b[2],
                a[0] * b[1] - a[1] * b[0],
            ];
            for k in 0..3 {
                assert!((cross[k] - n[k]).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn behaviour10_8_angles_wrap_the_yaw_and_stop_the_pitch() {
        // −30° of yaw is 330°; a pitch of 120° stops at 90° (straight down).
        let a = Angles::degrees(-30.0, 120.0);
        assert_eq!((a.yaw(), a.pitch()), (330.0, 90.0));
        // 725.5° is two turns and 5.5°; thousandths are kept, the rest rounded.
        let b = Angles::degrees(725.5, -12.34567);
        assert_eq!((b.yaw(), b.pitch()), (5.5, -12.346));
        assert_eq!(
            Angles::degrees(f64::NAN, f64::INFINITY),
            Angles::degrees(0.0, 0.0)
        );
        // Turning from the top view by −10° of yaw and −20° of pitch.
        let c = Angles::degrees(0.0, 90.0).turned(-10.0, -20.0);
        assert_eq!((c.yaw(), c.pitch()), (350.0, 70.0));
    }

    /// Behaviour 10.18: the lathe's 3D view turns the lathe's space, Z
    /// (spindle) as the mill's X, X as a radius as the mill's Z, C (the
    /// toolpath's Y) as the mill's −Y. At yaw 0, pitch 0 it is the ZX view,
    /// exactly. At the isometric angles (right = (0.70711, 0.70711, 0), up
    /// = (−0.40825, 0.40825, 0.81650) in that space): X20 (a diameter, 10
    /// as a radius) Z10 is the space's (10, 0, 10): u = 0.70711·10 =
    /// 7.0711, v = −0.40825·10 + 0.81650·10 = 4.0825; C5 (Y 5) is (0, −5,
    /// 0): u = −3.5355, v = −2.0412. Looking down X (pitch 90): right is Z,
    /// up is −C: X30 Y4 Z7 is at (7, −4).
    #[test]
    // Hand figures to five places (0.70711 is cos 45°, written out).
    #[allow(clippy::approx_constant)]
    fn behaviour10_18_the_lathe_3d_view_turns_the_lathes_space_by_hand() {
        let front = Plane::LatheOrbit(Angles::degrees(0.0, 0.0));
        assert_eq!(front.projection(), Plane::LatheZx.projection());
        assert_eq!(front.project(&[120.0, 0.0, 60.0]), (60.0, 60.0));
        let iso = Plane::LatheOrbit(Angles::ISO).projection();
        let near = |a: (f64, f64), b: (f64, f64)| {
            assert!(
                (a.0 - b.0).abs() < 1e-4 && (a.1 - b.1).abs() < 1e-4,
                "{a:?} vs {b:?}"
            );
        };
        near(iso.project(&[20.0, 0.0, 10.0]), (7.0711, 4.0825));
        near(iso.project(&[0.0, 5.0, 0.0]), (-3.5355, -2.0412));
        let down = Plane::LatheOrbit(Angles::degrees(0.0, 90.0));
        assert_eq!(down.project(&[30.0, 4.0, 7.0]), (7.0, -4.0));
        // From the tailstock (yaw 90, pitch 0: right = (0, 1, 0), up = (0,
        // 0, 1), so u = −C, v = X/2): a polar face move's corner X20 C−10
        // at Z−1 (the toolpath's (20, −10, −1)) is at (10, 10); the face
        // view XC draws it at (20/2, −10) = (10, −10): the same face, a
        // quarter turn round (XC's (h, v) is here (−v, h)).
        let tailstock = Plane::LatheOrbit(Angles::degrees(90.0, 0.0));
        assert_eq!(tailstock.project(&[20.0, -10.0, -1.0]), (10.0, 10.0));
        assert_eq!(Plane::LatheXc.project(&[20.0, -10.0, -1.0]), (10.0, -10.0));
        // The machine's own 3D view; the face view XC has no angles.
        assert_eq!(
            Plane::parse("3D").unwrap().on(MachineKind::Lathe),
            Some(Plane::LatheOrbit(Angles::ISO))
        );
        assert_eq!(
            Plane::LatheOrbit(Angles::ISO).on(MachineKind::Mill),
            Some(Plane::Orbit(Angles::ISO))
        );
        assert_eq!(Plane::Xy.on(MachineKind::Lathe), None);
        assert_eq!(Plane::LatheXc.on(MachineKind::Mill), None);
        assert_eq!(Plane::LatheZx.angles(), Some(Angles::degrees(0.0, 0.0)));
        assert_eq!(Plane::LatheOrbit(Angles::ISO).name(), "3D");
        assert!(Plane::LatheOrbit(Angles::ISO).is_lathe());
        assert!(Plane::LatheOrbit(Angles::ISO).is_orbit());
    }

    #[test]
    fn lathe_view_draws_x_as_a_radius() {
        assert_eq!(Plane::LatheZx.project(&[120.0, 0.0, 60.0]), (60.0, 60.0));
        assert_eq!(Plane::Xy.project(&[1.0, 2.0, 3.0]), (1.0, 2.0));
        assert_eq!(Plane::for_machine(MachineKind::Lathe), Plane::LatheZx);
    }
}
