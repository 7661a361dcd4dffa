//! The view: which plane is drawn, and the world-to-screen transform that
//! fits a path into a rectangle of the drawing surface. Screen coordinates are
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
}

impl Plane {
    /// The usual view of a machine: XY for the mill, ZX for the lathe.
    pub fn for_machine(machine: MachineKind) -> Plane {
        match machine {
            MachineKind::Mill => Plane::Xy,
            MachineKind::Lathe => Plane::LatheZx,
        }
    }

    /// Projects an x, y, z vertex onto the plane: (horizontal, vertical).
    /// Missing coordinates read as 0.
    pub fn project(self, p: &[f64]) -> (f64, f64) {
        let at = |i: usize| p.get(i).copied().unwrap_or(0.0);
        let (x, y, z) = (at(0), at(1), at(2));
        match self {
            Plane::Xy => (x, y),
            Plane::Xz => (x, z),
            Plane::Yz => (y, z),
            Plane::LatheZx => (z, x / 2.0),
            Plane::LatheXc => (x / 2.0, y),
        }
    }

    /// Names of the horizontal and the vertical axis, for labels.
    pub fn axis_names(self) -> (&'static str, &'static str) {
        match self {
            Plane::Xy => ("X", "Y"),
            Plane::Xz => ("X", "Z"),
            Plane::Yz => ("Y", "Z"),
            Plane::LatheZx => ("Z", "X (radius)"),
            Plane::LatheXc => ("X (radius)", "C"),
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
        }
    }

    /// Reads a view name as [`Plane::name`] writes it (any case): XY, XZ,
    /// YZ, ZX or XC.
    pub fn parse(name: &str) -> Option<Plane> {
        Some(match name.to_ascii_uppercase().as_str() {
            "XY" => Plane::Xy,
            "XZ" => Plane::Xz,
            "YZ" => Plane::Yz,
            "ZX" => Plane::LatheZx,
            "XC" => Plane::LatheXc,
            _ => return None,
        })
    }

    /// True when the horizontal axis (vertical = 0) is a lathe's centre line.
    pub fn has_centre_line(self) -> bool {
        self == Plane::LatheZx
    }

    /// True for the lathe's views (ZX and the face, XC); the others are the
    /// mill's.
    pub fn is_lathe(self) -> bool {
        matches!(self, Plane::LatheZx | Plane::LatheXc)
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

    #[test]
    fn lathe_view_draws_x_as_a_radius() {
        assert_eq!(Plane::LatheZx.project(&[120.0, 0.0, 60.0]), (60.0, 60.0));
        assert_eq!(Plane::Xy.project(&[1.0, 2.0, 3.0]), (1.0, 2.0));
        assert_eq!(Plane::for_machine(MachineKind::Lathe), Plane::LatheZx);
    }
}
