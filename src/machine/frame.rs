//! The coordinates a program's words are read in (behaviour 13): where the
//! current coordinate system's zero lies on the machine (the work offset,
//! the G92/G50 shift and the G52 local offset), and the programmable
//! transformations of the mill that turn a point written in the program into
//! the point the tool is sent to — mirror image G51.1, scaling G51, rotation
//! G68, in that order (Fanuc 0i-MF/30i: "processing proceeds from
//! programmable mirror image to scaling and coordinate system rotation") —
//! and the polar coordinates of G16, which turn a radius and an angle into a
//! point before any of them. Pure geometry: the machine owns the state and
//! applies it.

use crate::geometry::Xyz;
use crate::setup::{DecimalInput, Units};
use crate::syntax::Word;
use crate::syntax::codes::Plane;

/// Where the current coordinate system lies on the machine (behaviour 13.1–13.4):
/// its zero, and the parts beyond the work system's row that make it.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Coordinates {
    /// The zero of the current coordinate system in machine coordinates
    /// (mm): the work system's zero plus the G92/G50 shift plus the G52 local
    /// offset.
    pub zero: Xyz,
    /// The G92 (lathe G50) shift, kept across G54–G59 changes.
    pub shift: Xyz,
    /// The G52 local offset: where the local zero lies in the work system,
    /// the same in every work system.
    pub local: Xyz,
}

/// G51 scaling (mill): a centre and a factor per axis (P gives all three
/// one factor; a negative factor of I/J/K mirrors that axis).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Scaling {
    /// The centre of scaling (mm, after the mirror image, behaviour 13.9).
    pub center: Xyz,
    /// X, Y, Z factors.
    pub factors: Xyz,
}

/// G68 coordinate rotation (mill).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rotation {
    /// The plane selected when G68 was given; the rotation is about its
    /// normal.
    pub plane: Plane,
    /// The centre (mm, after mirror image and scaling; only the plane's two
    /// axes count).
    pub center: Xyz,
    /// The angle in degrees, counter-clockwise seen from the plane normal's
    /// positive side (as G03 turns).
    pub degrees: f64,
}

/// The programmable transformations in force (mill).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Transforms {
    /// G51.1: per axis, the coordinate the axis is mirrored about (mm,
    /// program coordinates), or None.
    pub mirror: [Option<f64>; 3],
    /// G51.
    pub scaling: Option<Scaling>,
    /// G68.
    pub rotation: Option<Rotation>,
}

impl Transforms {
    /// True when a point is sent where the program writes it.
    #[inline]
    pub fn is_identity(&self) -> bool {
        self.mirror == [None; 3] && self.scaling.is_none() && self.rotation.is_none()
    }

    /// The mirror image stage (behaviour 13.8).
    pub fn mirrored(&self, p: Xyz) -> Xyz {
        let mut q = p;
        for (axis, m) in self.mirror.iter().enumerate() {
            if let Some(m) = m {
                q[axis] = 2.0 * m - p[axis];
            }
        }
        q
    }

    /// Mirror image and scaling: where a centre written in a G68 block goes
    /// (Fanuc: in scaling mode the centre of rotation is scaled too).
    pub fn before_rotation(&self, p: Xyz) -> Xyz {
        let q = self.mirrored(p);
        match self.scaling {
            Some(s) => std::array::from_fn(|i| s.center[i] + s.factors[i] * (q[i] - s.center[i])),
            None => q,
        }
    }

    /// A point of the program in the coordinate system the tool is sent in:
    /// mirror image, scaling, rotation.
    pub fn point(&self, p: Xyz) -> Xyz {
        let q = self.before_rotation(p);
        match self.rotation {
            Some(r) => rotate(q, r.plane, r.center, r.degrees),
            None => q,
        }
    }

    /// A movement (or an arc's centre offset) of the program, as the tool
    /// makes it: the linear part of [`Transforms::point`].
    pub fn vector(&self, v: Xyz) -> Xyz {
        let mut q = v;
        for (axis, m) in self.mirror.iter().enumerate() {
            if m.is_some() {
                q[axis] = -q[axis];
            }
        }
        if let Some(s) = self.scaling {
            q = std::array::from_fn(|i| q[i] * s.factors[i]);
        }
        match self.rotation {
            Some(r) => rotate(q, r.plane, [0.0; 3], r.degrees),
            None => q,
        }
    }

    /// The factor along `axis` of the mirror image and scaling stages (−1
    /// for a mirrored axis): which way G45–G48 extend a movement along it.
    pub fn axis_factor(&self, axis: usize) -> f64 {
        let m = if self.mirror[axis].is_some() {
            -1.0
        } else {
            1.0
        };
        m * self.scaling.map_or(1.0, |s| s.factors[axis])
    }

    /// The program coordinate of `axis` whose mirror image and scaling give
    /// `v` (an axis no rotation turns).
    pub fn axis_inverse(&self, axis: usize, v: f64) -> f64 {
        let mut p = v;
        if let Some(s) = self.scaling {
            p = s.center[axis] + (p - s.center[axis]) / s.factors[axis];
        }
        match self.mirror[axis] {
            Some(m) => 2.0 * m - p,
            None => p,
        }
    }

    /// True when an arc in `plane` turns the other way: the mirror image and
    /// the negative factors reverse an odd number of the plane's axes
    /// (behaviour 13.8, 13.9; a rotation keeps the turn).
    pub fn reverses(&self, plane: Plane) -> bool {
        let (a, b, _) = plane.axes();
        (self.axis_factor(a) < 0.0) != (self.axis_factor(b) < 0.0)
    }

    /// What an arc's R in `plane` is multiplied by: the larger of the two
    /// axes' scaling magnifications (Fanuc: an arc does not become an
    /// ellipse; R takes the larger magnification).
    pub fn radius_factor(&self, plane: Plane) -> f64 {
        let (a, b, _) = plane.axes();
        match self.scaling {
            Some(s) => s.factors[a].abs().max(s.factors[b].abs()),
            None => 1.0,
        }
    }
}

/// `p` rotated by `degrees` about `center` in `plane` (counter-clockwise
/// from the plane's first axis toward its second).
pub fn rotate(p: Xyz, plane: Plane, center: Xyz, degrees: f64) -> Xyz {
    let (a, b, _) = plane.axes();
    let (s, c) = degrees.to_radians().sin_cos();
    let (u, v) = (p[a] - center[a], p[b] - center[b]);
    let mut q = p;
    q[a] = center[a] + u * c - v * s;
    q[b] = center[b] + u * s + v * c;
    q
}

/// The point of the plane a G16 block's radius and angle words name
/// (behaviour 13.11), in program coordinates, from `current`, the tool's
/// point in the plane (first axis, second axis; the zero of the coordinate
/// system at the origin). `radius` is in mm, `angle` in degrees; each is
/// incremental in G91.
///
/// - The radius written in G90 is measured from the zero of the coordinate
///   system (the G52 local zero, when there is one), in G91 from the
///   current point (Fanuc 0i-MF, "Polar coordinate command").
/// - An angle written in G90 is measured from the plane's first axis; in
///   G91 it is added to the angle of the current point about the zero.
/// - No radius: the zero is the centre and the radius the current point's
///   distance from it; no angle: the current point's angle (Mitsubishi
///   M700 programming manual, 6.12, which writes out what Fanuc's figures
///   show).
pub fn polar_point(
    current: [f64; 2],
    radius: Option<f64>,
    angle: Option<f64>,
    incremental: bool,
) -> [f64; 2] {
    let present = if current == [0.0, 0.0] {
        0.0
    } else {
        current[1].atan2(current[0]).to_degrees()
    };
    let (origin, r) = match radius {
        Some(r) if incremental => (current, r),
        Some(r) => ([0.0, 0.0], r),
        None => ([0.0, 0.0], current[0].hypot(current[1])),
    };
    let theta = match angle {
        Some(a) if incremental => present + a,
        Some(a) => a,
        None => present,
    };
    let (s, c) = theta.to_radians().sin_cos();
    [origin[0] + r * c, origin[1] + r * s]
}

/// A word that is an angle (G68 R, the G16 angle word) or a magnification
/// (G51 I/J/K), as its number is written: with a decimal point (or with
/// calculator-type decimal input) the value itself, in degrees or as a
/// factor, whatever G20/G21 say; without one, in thousandths (Fanuc: the
/// least input increment of an angle and of a magnification is 0.001),
/// where the parser read it in the least increment of the length unit.
pub fn unitless(word: &Word, units: Units, input: DecimalInput) -> f64 {
    if word.point || input == DecimalInput::Calculator {
        word.value
    } else {
        // The parser scaled the digits by the least increment of a length
        // (behaviour 1.15): undo it, then read them in thousandths.
        (word.value / units.increment()).round() * 0.001
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn near(a: Xyz, b: Xyz) -> bool {
        (0..3).all(|i| (a[i] - b[i]).abs() < 1e-9)
    }

    #[test]
    fn rotation_about_a_centre() {
        // behaviour 13.10: R30 about (10, 10): (20, 10) → (10 + 10 cos 30°,
        // 10 + 10 sin 30°) = (18.660254, 15).
        let t = Transforms {
            rotation: Some(Rotation {
                plane: Plane::XY,
                center: [10.0, 10.0, 0.0],
                degrees: 30.0,
            }),
            ..Transforms::default()
        };
        let p = t.point([20.0, 10.0, -5.0]);
        assert!(
            near(p, [10.0 + 10.0 * 3f64.sqrt() / 2.0, 15.0, -5.0]),
            "{p:?}"
        );
        // A movement of (10, 0) turns by 30°: (8.660254, 5).
        assert!(near(
            t.vector([10.0, 0.0, 0.0]),
            [5.0 * 3f64.sqrt(), 5.0, 0.0]
        ));
        assert!(!t.reverses(Plane::XY));
    }

    #[test]
    fn rotation_in_g18_turns_from_z_toward_x() {
        // In the ZX plane the first axis is Z: (X0, Z10) by +90° about the
        // origin goes to (X10, Z0).
        let p = rotate([0.0, 3.0, 10.0], Plane::ZX, [0.0; 3], 90.0);
        assert!(near(p, [10.0, 3.0, 0.0]), "{p:?}");
    }

    #[test]
    fn mirror_then_scaling_then_rotation() {
        // Mirror X about 10, scale ×2 about the origin, rotate 90° about the
        // origin: (12, 1) → (8, 1) → (16, 2) → (-2, 16).
        let t = Transforms {
            mirror: [Some(10.0), None, None],
            scaling: Some(Scaling {
                center: [0.0; 3],
                factors: [2.0; 3],
            }),
            rotation: Some(Rotation {
                plane: Plane::XY,
                center: [0.0; 3],
                degrees: 90.0,
            }),
        };
        assert!(near(t.point([12.0, 1.0, 0.0]), [-2.0, 16.0, 0.0]));
        assert!(t.reverses(Plane::XY));
        assert!(!t.reverses(Plane::YZ) || t.axis_factor(1) < 0.0);
        assert_eq!(t.radius_factor(Plane::XY), 2.0);
    }

    #[test]
    fn negative_factors_mirror_and_r_takes_the_larger_magnification() {
        let t = Transforms {
            scaling: Some(Scaling {
                center: [0.0; 3],
                factors: [-2.0, 1.0, 1.0],
            }),
            ..Transforms::default()
        };
        assert!(t.reverses(Plane::XY));
        assert!(!t.reverses(Plane::YZ));
        assert_eq!(t.radius_factor(Plane::XY), 2.0);
        assert_eq!(t.radius_factor(Plane::YZ), 1.0);
    }

    #[test]
    fn polar_points() {
        let close =
            |a: [f64; 2], b: [f64; 2]| (a[0] - b[0]).abs() < 1e-9 && (a[1] - b[1]).abs() < 1e-9;
        let r3 = 3f64.sqrt();
        // G90 X100. Y30.: 100 from the zero at 30°.
        assert!(close(
            polar_point([0.0, 0.0], Some(100.0), Some(30.0), false),
            [50.0 * r3, 50.0]
        ));
        // G91 Y120. from there: the radius stays 100, the angle 150°.
        assert!(close(
            polar_point([50.0 * r3, 50.0], None, Some(120.0), true),
            [-50.0 * r3, 50.0]
        ));
        // G91 X10. Y90. from (20, 0): 10 from the current point, at 0° + 90°.
        assert!(close(
            polar_point([20.0, 0.0], Some(10.0), Some(90.0), true),
            [20.0, 10.0]
        ));
        // G90 X50. alone from (0, 10): the angle of the current point, 90°.
        assert!(close(
            polar_point([0.0, 10.0], Some(50.0), None, false),
            [0.0, 50.0]
        ));
    }
}
