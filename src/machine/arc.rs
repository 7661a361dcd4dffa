//! Circle geometry of G02/G03 in the coordinates of the selected plane
//! (behaviour 2.12, 2.13): centre from I/J/K or from R, the radius check, the sweep, and the
//! tessellation used for drawing.

use std::f64::consts::{PI, TAU};

/// A point in the plane: (first axis, second axis).
pub type P2 = [f64; 2];

/// Chord tolerance of the drawn polyline: no point of the true arc is farther
/// than this from the polyline (mm).
pub const CHORD_TOLERANCE_MM: f64 = 0.01;
/// Most segments one arc is drawn with (past this the chord tolerance is
/// relaxed; only arcs of radius over ~10 m reach it).
pub const MAX_ARC_SEGMENTS: usize = 1024;

/// Start and end closer than this are the same point (a full circle with I/J/K).
const SAME_POINT: f64 = 1e-9;

/// A circular arc in plane coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Circle {
    /// Centre.
    pub center: P2,
    /// Radius.
    pub radius: f64,
    /// Angle of the start point (radians).
    pub start_angle: f64,
    /// Signed sweep (positive counter-clockwise), up to ±2π but for
    /// LinuxCNC's whole turns (G2/G3 P, behaviour 22.16).
    pub sweep: f64,
}

/// Why an arc cannot be made.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ArcError {
    /// Start and end are at different distances from the centre.
    RadiusMismatch {
        /// Distance of the start from the centre.
        start: f64,
        /// Distance of the end from the centre.
        end: f64,
    },
    /// R is smaller than half the distance from start to end.
    RadiusTooSmall {
        /// |R|.
        radius: f64,
        /// Half the chord.
        half_chord: f64,
    },
    /// The centre is at the start point.
    ZeroRadius,
    /// An R arc whose end is its start: no chord, so no centre (a full
    /// circle needs I/J/K).
    NoChord,
}

fn dist(a: P2, b: P2) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

fn angle(c: P2, p: P2) -> f64 {
    (p[1] - c[1]).atan2(p[0] - c[0])
}

/// True if two points coincide (start = end: a full circle with I/J/K).
pub fn same_point(a: P2, b: P2) -> bool {
    dist(a, b) < SAME_POINT
}

fn sweep_between(start_angle: f64, end_angle: f64, ccw: bool, full: bool) -> f64 {
    if full {
        return if ccw { TAU } else { -TAU };
    }
    if ccw {
        let s = (end_angle - start_angle).rem_euclid(TAU);
        if s == 0.0 { TAU } else { s }
    } else {
        let s = (start_angle - end_angle).rem_euclid(TAU);
        -(if s == 0.0 { TAU } else { s })
    }
}

/// The whole turns of a sweep beyond its first (radians, not signed): 0 up
/// to a full circle, 2π for LinuxCNC's `P2` (behaviour 22.16).
pub fn extra_turns(sweep: f64) -> f64 {
    let turns = (sweep.abs() / TAU - 1e-9).ceil() - 1.0;
    TAU * turns.max(0.0)
}

/// The arc from `start` to `end` around `center` (I/J/K form). Start = end is
/// a full circle. `tolerance` is the largest allowed difference between the
/// start and end radii (behaviour 2.13: 0.01 mm / 0.0005 in).
pub fn from_center(
    start: P2,
    end: P2,
    center: P2,
    ccw: bool,
    tolerance: f64,
) -> Result<Circle, ArcError> {
    let r0 = dist(start, center);
    let r1 = dist(end, center);
    if r0 < SAME_POINT {
        return Err(ArcError::ZeroRadius);
    }
    if (r0 - r1).abs() > tolerance {
        return Err(ArcError::RadiusMismatch { start: r0, end: r1 });
    }
    let full = same_point(start, end);
    let a0 = angle(center, start);
    // A full circle's sweep is a whole turn: its end angle (an `atan2`) is
    // not needed.
    let sweep = if full {
        sweep_between(a0, a0, ccw, true)
    } else {
        sweep_between(a0, angle(center, end), ccw, false)
    };
    Ok(Circle {
        center,
        radius: r0,
        start_angle: a0,
        sweep,
    })
}

/// [`from_center`] where the caller has measured and checked the radii:
/// `r0` the start's distance from the centre (over [`SAME_POINT`]), the
/// end's within the tolerance of it. The angles alone are worked out
/// (cutter compensation ends an arc at its corner at every arc block in
/// offset mode: the `check` instruction count with G41, docs/performance.md).
pub fn from_center_measured(start: P2, end: P2, center: P2, r0: f64, ccw: bool) -> Circle {
    let (dx, dy) = (start[0] - end[0], start[1] - end[1]);
    let full = (dx * dx + dy * dy).sqrt() < SAME_POINT;
    let a0 = angle(center, start);
    let sweep = if full {
        sweep_between(a0, a0, ccw, true)
    } else {
        sweep_between(a0, angle(center, end), ccw, false)
    };
    Circle {
        center,
        radius: r0,
        start_angle: a0,
        sweep,
    }
}

/// The centre of the R arc from `start` to `end` (`d` apart, more than 0;
/// |R| at least `d` / 2), and its distance from the chord.
#[inline]
fn radius_center(start: P2, end: P2, d: f64, r: f64, ccw: bool) -> (P2, f64) {
    let half = d / 2.0;
    let radius = r.abs();
    let h = (radius * radius - half * half).max(0.0).sqrt();
    let mid = [(start[0] + end[0]) / 2.0, (start[1] + end[1]) / 2.0];
    // Left normal of the chord, in the plane's right-handed frame.
    let left = [-(end[1] - start[1]) / d, (end[0] - start[0]) / d];
    // Counter-clockwise arcs of 180° or less turn about a centre on the left of
    // the chord; clockwise ones about a centre on the right; R < 0 swaps.
    let side = if ccw == (r > 0.0) { 1.0 } else { -1.0 };
    (
        [mid[0] + side * h * left[0], mid[1] + side * h * left[1]],
        h,
    )
}

/// The centre [`from_radius`] finds, without the angles (cutter
/// compensation reads the next block's arc ahead at every block); None
/// where it is an error.
pub fn center_of_radius(start: P2, end: P2, r: f64, ccw: bool, tolerance: f64) -> Option<P2> {
    let d = dist(start, end);
    let radius = r.abs();
    if d < SAME_POINT || radius < d / 2.0 - tolerance || radius < SAME_POINT {
        return None;
    }
    Some(radius_center(start, end, d, r, ccw).0)
}

/// The arc from `start` to `end` with radius `r` (R form): R > 0 is 180° or
/// less, R < 0 more than 180° (behaviour 2.12). Start equal to end is
/// [`ArcError::NoChord`]: the centre would be undefined.
pub fn from_radius(
    start: P2,
    end: P2,
    r: f64,
    ccw: bool,
    tolerance: f64,
) -> Result<Circle, ArcError> {
    let d = dist(start, end);
    if d < SAME_POINT {
        return Err(ArcError::NoChord);
    }
    let half = d / 2.0;
    let radius = r.abs();
    if radius < half - tolerance || radius < SAME_POINT {
        return Err(ArcError::RadiusTooSmall {
            radius,
            half_chord: half,
        });
    }
    let (center, h) = radius_center(start, end, d, r, ccw);
    let a0 = angle(center, start);
    let mut sweep = sweep_between(a0, angle(center, end), ccw, false);
    if h == 0.0 {
        sweep = if ccw { PI } else { -PI };
    }
    Ok(Circle {
        center,
        radius,
        start_angle: a0,
        sweep,
    })
}

impl Circle {
    /// The point at angle `start_angle + t·sweep`, t in 0..=1.
    pub fn point(&self, t: f64) -> P2 {
        let a = self.start_angle + t * self.sweep;
        [
            self.center[0] + self.radius * a.cos(),
            self.center[1] + self.radius * a.sin(),
        ]
    }

    /// Segments to draw this arc with, keeping the chord error under
    /// `tolerance` (and at most [`MAX_ARC_SEGMENTS`]).
    pub fn segments(&self, tolerance: f64) -> usize {
        let step = if self.radius > tolerance {
            2.0 * (1.0 - tolerance / self.radius).acos()
        } else {
            PI / 2.0
        };
        let n = (self.sweep.abs() / step.max(1e-6)).ceil();
        if n.is_finite() {
            (n as usize).clamp(1, MAX_ARC_SEGMENTS)
        } else {
            MAX_ARC_SEGMENTS
        }
    }

    /// The points of the arc that are extreme along either plane axis (those
    /// of the four quadrant points the sweep passes), for bounding boxes.
    pub fn extremes(&self) -> impl Iterator<Item = P2> + '_ {
        // Quadrant angles in [-π, π); each is passed if it (or it shifted by
        // one turn towards the sweep) lies between the start and the end.
        const QUADRANTS: [(f64, f64, f64); 4] = [
            (-PI, -1.0, 0.0),
            (-PI / 2.0, 0.0, -1.0),
            (0.0, 1.0, 0.0),
            (PI / 2.0, 0.0, 1.0),
        ];
        let a0 = self.start_angle;
        let end = a0 + self.sweep;
        QUADRANTS.into_iter().filter_map(move |(q, cx, cy)| {
            let passed = if self.sweep >= 0.0 {
                let q = if q >= a0 { q } else { q + TAU };
                q <= end
            } else {
                let q = if q <= a0 { q } else { q - TAU };
                q >= end
            };
            passed.then(|| {
                [
                    self.center[0] + self.radius * cx,
                    self.center[1] + self.radius * cy,
                ]
            })
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: P2, b: P2) -> bool {
        dist(a, b) < 1e-9
    }

    #[test]
    fn quarter_circle_ccw_with_center() {
        let c = from_center([10.0, 0.0], [0.0, 10.0], [0.0, 0.0], true, 0.01).unwrap();
        assert!((c.sweep - PI / 2.0).abs() < 1e-12);
        assert!(close(c.point(1.0), [0.0, 10.0]));
        let c = from_center([10.0, 0.0], [0.0, 10.0], [0.0, 0.0], false, 0.01).unwrap();
        assert!((c.sweep + 3.0 * PI / 2.0).abs() < 1e-12);
    }

    #[test]
    fn full_circle_when_start_equals_end() {
        let c = from_center([10.0, 0.0], [10.0, 0.0], [0.0, 0.0], false, 0.01).unwrap();
        assert_eq!(c.sweep, -TAU);
    }

    #[test]
    fn radius_check() {
        let e = from_center([10.0, 0.0], [0.0, 10.02], [0.0, 0.0], true, 0.01).unwrap_err();
        assert!(matches!(e, ArcError::RadiusMismatch { .. }));
        assert!(from_center([10.0, 0.0], [0.0, 10.005], [0.0, 0.0], true, 0.01).is_ok());
    }

    #[test]
    fn r_positive_is_the_short_arc_and_negative_the_long_one() {
        let c = from_radius([10.0, 0.0], [0.0, 10.0], 10.0, true, 0.01).unwrap();
        assert!(close(c.center, [0.0, 0.0]));
        assert!((c.sweep - PI / 2.0).abs() < 1e-9);
        let c = from_radius([10.0, 0.0], [0.0, 10.0], -10.0, true, 0.01).unwrap();
        assert!(close(c.center, [10.0, 10.0]));
        assert!((c.sweep - 3.0 * PI / 2.0).abs() < 1e-9);
        let c = from_radius([10.0, 0.0], [0.0, 10.0], 10.0, false, 0.01).unwrap();
        assert!(close(c.center, [10.0, 10.0]));
        assert!((c.sweep + PI / 2.0).abs() < 1e-9);
    }

    #[test]
    fn r_arc_without_chord_is_an_error_not_a_nan() {
        // Fuzz finding 2: the chord's normal was 0/0.
        let e = from_radius([3.0, 4.0], [3.0, 4.0], 0.1, false, 0.01).unwrap_err();
        assert_eq!(e, ArcError::NoChord);
        let c = from_radius([0.0, 0.0], [1e-8, 0.0], 99999.999, true, 0.01).unwrap();
        assert!(c.center.iter().all(|v| v.is_finite()) && c.sweep.is_finite());
    }

    #[test]
    fn r_too_small_is_an_error_and_half_circle_is_exact() {
        assert!(from_radius([0.0, 0.0], [20.0, 0.0], 9.0, true, 0.01).is_err());
        let c = from_radius([0.0, 0.0], [20.0, 0.0], 10.0, true, 0.01).unwrap();
        assert!(close(c.center, [10.0, 0.0]));
        assert!((c.sweep - PI).abs() < 1e-12);
    }

    #[test]
    fn segments_follow_the_chord_tolerance() {
        let c = from_center([10.0, 0.0], [10.0, 0.0], [0.0, 0.0], true, 0.01).unwrap();
        let n = c.segments(CHORD_TOLERANCE_MM);
        let step = c.sweep / n as f64;
        let sagitta = c.radius * (1.0 - (step / 2.0).cos());
        assert!(sagitta <= CHORD_TOLERANCE_MM + 1e-12, "{n} {sagitta}");
        assert!(n < 200);
    }

    #[test]
    fn extremes_of_arcs() {
        let c = from_center([10.0, 0.0], [0.0, 10.0], [0.0, 0.0], true, 0.01).unwrap();
        let e: Vec<P2> = c.extremes().collect();
        assert_eq!(e, vec![[10.0, 0.0], [0.0, 10.0]]);
        // Clockwise the long way round passes the other three.
        let c = from_center([10.0, 0.0], [0.0, 10.0], [0.0, 0.0], false, 0.01).unwrap();
        assert_eq!(c.extremes().count(), 4);
        let c = from_center([0.0, -10.0], [0.0, 10.0], [0.0, 0.0], false, 0.01).unwrap();
        assert_eq!(
            c.extremes().collect::<Vec<_>>(),
            vec![[-10.0, 0.0], [0.0, -10.0], [0.0, 10.0]]
        );
        // A full circle passes all four.
        let c = from_center([10.0, 0.0], [10.0, 0.0], [0.0, 0.0], true, 0.01).unwrap();
        assert_eq!(c.extremes().count(), 4);
    }
}
