//! What is drawn round the tool marker (behaviour 10.13, 10.16, 16.13):
//! the tool list's tool dashed — on the mill its cylinder, D wide and L
//! long up the spindle from the tool point, seen in any view; on the lathe
//! the insert's nose circle — and the compensation's circle solid, from
//! the register, in every view of its machine's space. A circle is drawn
//! as the projection makes it: a circle where its plane faces the screen,
//! a line where it is seen edge on, an ellipse between. Also how far these
//! reach beyond the path, which the fit leaves room for (10.5).

use super::style::Theme;
use super::{Extent, Frame, Plane, Stroke, Surface};

/// The cutter G41/G42 offsets the tool by: its radius (the toolpath's
/// units), the view plane of the plane it compensates in, and where its
/// centre lies from the tool marker.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cutter {
    /// |register D| (mill) or the nose radius R (lathe) in the toolpath's
    /// units.
    pub radius: f64,
    /// The view of the compensation plane (G17 XY, G18 XZ, G19 YZ; the
    /// lathe's ZX).
    pub plane: Plane,
    /// From the tool marker to the circle's centre, in the toolpath's
    /// coordinates (X a diameter on the lathe): zero on the mill; on the
    /// lathe the nose centre lies this far from the imaginary tool nose the
    /// program follows (behaviour 18.2).
    pub centre: [f64; 3],
    /// A mill tool of the tool list: a cylinder up the spindle (+Z) from
    /// the tool point, this long (0: the list has no length), drawn in
    /// every mill view (behaviour 10.16); None for a circle in `plane`.
    pub length: Option<f64>,
}

/// The tool as drawn in the view and in the legend: a filled disc with a
/// ring in the background colour so it stands out on any path.
pub fn tool_symbol(s: &mut impl Surface, t: &Theme, (x, y): (f64, f64)) {
    let ring = Stroke {
        color: t.background,
        width: 1.5,
        dash: &[],
    };
    s.circle(x, y, 5.5, Some(t.tool), Some(&ring));
}

/// Segments of a projected circle (an ellipse) drawn as a polyline.
const ELLIPSE_SEGMENTS: usize = 72;
/// The tool list's tool is dashed, the register's circle solid (13.16).
const TOOL_DASH: &[f64] = &[5.0, 3.0];

/// How far what is drawn round the tool reaches from the point the path
/// follows, in the toolpath's units, the largest over a run (behaviour
/// 10.5): `radius` across (the tool's and the compensation's circles; on
/// the lathe the nose circle's far side, 2R from the imaginary nose) and
/// `up` along +Z (the mill tool's length, or its diameter when the list
/// has no length).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Reach {
    /// Across the tool point, every way.
    pub radius: f64,
    /// Up the spindle (+Z) from the tool point (the mill).
    pub up: f64,
}

impl Reach {
    /// The toolpath's box (`min`, `max`) grown by the reach: on the mill
    /// by `radius` every way and `up` above; on the lathe (`lathe`, X a
    /// diameter) by `radius` in Z and along X's radius, none in Y.
    pub fn grow(
        self,
        (mut min, mut max): ([f64; 3], [f64; 3]),
        lathe: bool,
    ) -> ([f64; 3], [f64; 3]) {
        let r = finite(self.radius);
        let up = finite(self.up);
        let by = if lathe { [2.0 * r, 0.0, r] } else { [r, r, r] };
        for k in 0..3 {
            min[k] -= by[k];
            max[k] += by[k];
        }
        if !lathe {
            max[2] += (up - r).max(0.0);
        }
        (min, max)
    }
}

fn finite(v: f64) -> f64 {
    if v.is_finite() { v.abs() } else { 0.0 }
}

/// The two axes of a circle in a plane, in the toolpath's coordinates,
/// one unit of radius long each (on the lathe X is a diameter: 2 along
/// X is a unit of radius).
fn circle_axes(plane: Plane) -> Option<([f64; 3], [f64; 3])> {
    Some(match plane {
        Plane::Xy => ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
        Plane::Xz => ([1.0, 0.0, 0.0], [0.0, 0.0, 1.0]),
        Plane::Yz => ([0.0, 1.0, 0.0], [0.0, 0.0, 1.0]),
        Plane::LatheZx => ([0.0, 0.0, 1.0], [2.0, 0.0, 0.0]),
        _ => return None,
    })
}

fn add(p: [f64; 3], q: [f64; 3], k: f64) -> [f64; 3] {
    [p[0] + q[0] * k, p[1] + q[1] * k, p[2] + q[2] * k]
}

fn screen(f: &Frame, p: &[f64; 3]) -> (f64, f64) {
    let (u, v) = f.projection.project(p);
    f.transform.to_screen(u, v)
}

fn finite2(p: (f64, f64)) -> bool {
    p.0.is_finite() && p.1.is_finite()
}

/// What a circle of `radius` about `centre` with `axes` looks like in the
/// frame (screen pixels): a circle (its centre and radius), a line (its
/// ends) or an ellipse (its points, closed); None when under half a pixel.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum Seen {
    Circle((f64, f64), f64),
    Line((f64, f64), (f64, f64)),
    Ellipse(Vec<(f64, f64)>),
}

pub(super) fn seen(
    f: &Frame,
    centre: [f64; 3],
    (e1, e2): ([f64; 3], [f64; 3]),
    radius: f64,
) -> Option<Seen> {
    let scale = f.transform.scale;
    let (a, b) = (f.projection.project(&e1), f.projection.project(&e2));
    let (la, lb) = (a.0 * a.0 + a.1 * a.1, b.0 * b.0 + b.1 * b.1);
    let longest = la.max(lb).sqrt() * radius * scale;
    if !(longest.is_finite() && longest > 0.5) {
        return None;
    }
    let c = screen(f, &centre);
    if !finite2(c) {
        return None;
    }
    let dot = a.0 * b.0 + a.1 * b.1;
    let cross = a.0 * b.1 - a.1 * b.0;
    let big = la.max(lb);
    if (la - lb).abs() <= 1e-9 * big && dot.abs() <= 1e-9 * big {
        // Its plane faces the screen: a true circle (the plane views).
        return Some(Seen::Circle(c, la.sqrt() * radius * scale));
    }
    if cross.abs() <= 1e-9 * big {
        // Edge on: the points r(a cos t + b sin t) lie on one line, the
        // farthest r·√(|a|² + |b|²) from the centre (a and b parallel).
        let (ux, uy) = if la >= lb { a } else { b };
        let n = (ux * ux + uy * uy).sqrt();
        let half = radius * (la + lb).sqrt() * scale;
        let (dx, dy) = (ux / n * half, -uy / n * half);
        return Some(Seen::Line((c.0 - dx, c.1 - dy), (c.0 + dx, c.1 + dy)));
    }
    let points = (0..=ELLIPSE_SEGMENTS)
        .map(|i| {
            let t = std::f64::consts::TAU * i as f64 / ELLIPSE_SEGMENTS as f64;
            let (cos, sin) = (t.cos(), t.sin());
            screen(f, &add(add(centre, e1, radius * cos), e2, radius * sin))
        })
        .collect();
    Some(Seen::Ellipse(points))
}

fn draw_seen(s: &mut impl Surface, seen: &Seen, stroke: &Stroke) {
    match seen {
        Seen::Circle(c, r) => s.circle(c.0, c.1, *r, None, Some(stroke)),
        Seen::Line(a, b) => {
            s.begin_path(stroke);
            s.move_to(a.0, a.1);
            s.line_to(b.0, b.1);
            s.stroke();
        }
        Seen::Ellipse(points) => {
            s.begin_path(stroke);
            if let Some(first) = points.first() {
                s.move_to(first.0, first.1);
            }
            for p in &points[1..] {
                s.line_to(p.0, p.1);
            }
            s.stroke();
        }
    }
}

/// The mill tool of the tool list as the view sees it: its end at the
/// tool point (a circle across the spindle), its top `length` up (left
/// open when the list has no length: the sides then go up one diameter),
/// and its two sides, the cylinder's outline. The axis is Z, which every
/// mill view draws straight up the screen (its screen's right has no Z),
/// so the outline's sides stand `radius` left and right of the axis.
/// Seen along the axis (XY) it is the end's circle alone.
pub(super) fn cylinder(f: &Frame, point: [f64; 3], radius: f64, length: f64) -> Vec<Seen> {
    let mut out = Vec::new();
    let Some(angles) = f.plane.angles().filter(|_| !f.plane.is_lathe()) else {
        return out;
    };
    let axes = ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
    out.extend(seen(f, point, axes, radius));
    let rise = if length > 0.0 { length } else { 2.0 * radius };
    let top = add(point, [0.0, 0.0, 1.0], rise);
    let (_, v) = f.projection.project(&[0.0, 0.0, rise]);
    // Along the axis the sides and the top are the end's circle.
    if (v * f.transform.scale).abs() < 0.5 {
        return out;
    }
    if length > 0.0 {
        out.extend(seen(f, top, axes, radius));
    }
    let right = angles.rotation()[0];
    for side in [-1.0, 1.0] {
        let (a, b) = (
            screen(f, &add(point, right, side * radius)),
            screen(f, &add(top, right, side * radius)),
        );
        if finite2(a) && finite2(b) {
            out.push(Seen::Line(a, b));
        }
    }
    out
}

/// The tool marker at the current block's actual end point and a ring at
/// its programmed end point; round the marker, the tool list's tool
/// (dashed) and the compensation's circle (solid): a circle in the view
/// of its plane, a line in the other plane views, projected in the 3D
/// view; the mill tool's cylinder in every mill view.
pub fn draw_marker(
    s: &mut impl Surface,
    f: &Frame,
    [actual, programmed]: [[f64; 3]; 2],
    (cutter, tool): (Option<Cutter>, Option<Cutter>),
) {
    let (a, p) = (screen(f, &actual), screen(f, &programmed));
    s.begin_group("tool");
    for (c, dash) in [(cutter, &[][..]), (tool, TOOL_DASH)] {
        let Some(c) = c else {
            continue;
        };
        let edge = Stroke {
            color: f.theme.tool,
            width: 1.5,
            dash,
        };
        let centre = add(actual, c.centre, 1.0);
        let shapes = match (c.length, circle_axes(c.plane)) {
            (Some(length), _) => cylinder(f, centre, c.radius, length),
            (None, Some(axes)) if drawn_in(c.plane, f.plane) => {
                seen(f, centre, axes, c.radius).into_iter().collect()
            }
            _ => Vec::new(),
        };
        for shape in &shapes {
            draw_seen(s, shape, &edge);
        }
    }
    if finite2(p) {
        let ring = Stroke {
            color: f.theme.label,
            width: 1.5,
            dash: &[],
        };
        s.circle(p.0, p.1, 4.5, None, Some(&ring));
    }
    if finite2(a) {
        tool_symbol(s, f.theme, a);
    }
    s.end_group();
}

/// Whether a circle in `circle`'s plane is drawn in the view `view`
/// (behaviour 10.17): in every view of the same machine's space — its own
/// plane's view a circle, the other plane views a line (edge on), the 3D
/// view as projected — but not in the lathe's face view, whose up is the
/// polar C of the toolpath's Y, not a length of the ZX plane.
fn drawn_in(circle: Plane, view: Plane) -> bool {
    circle.is_lathe() == view.is_lathe() && view != Plane::LatheXc
}

/// The box of a world box's eight corners through the frame's plane.
pub(super) fn projected_box(plane: Plane, (min, max): ([f64; 3], [f64; 3])) -> Option<Extent> {
    let projection = plane.projection();
    let mut extent: Option<Extent> = None;
    for corner in 0..8 {
        let pick = |axis: usize| {
            if corner >> axis & 1 == 0 {
                min[axis]
            } else {
                max[axis]
            }
        };
        let (u, v) = projection.project(&[pick(0), pick(1), pick(2)]);
        match &mut extent {
            Some(e) => e.include(u, v),
            None if u.is_finite() && v.is_finite() => extent = Some(Extent::point(u, v)),
            None => {}
        }
    }
    extent
}

#[cfg(test)]
mod tests {
    use super::super::test_support::toolpath;
    use super::super::{Angles, Transform};
    use super::*;

    /// A frame of `plane` whose screen is (100 + 2u, 100 − 2v): scale 2,
    /// world (0, 0) at pixel (100, 100).
    fn frame(plane: Plane) -> Frame {
        let tp = toolpath("G01 X10. F100.");
        let mut f = Frame::fit(&tp, plane, 800.0, 600.0);
        f.transform = Transform {
            scale: 2.0,
            origin_x: 100.0,
            origin_y: 100.0,
        };
        f
    }

    fn near(a: (f64, f64), b: (f64, f64)) {
        assert!(
            (a.0 - b.0).abs() < 1e-3 && (a.1 - b.1).abs() < 1e-3,
            "{a:?} vs {b:?}"
        );
    }

    fn line(s: &Seen) -> ((f64, f64), (f64, f64)) {
        match s {
            Seen::Line(a, b) => (*a, *b),
            other => panic!("not a line: {other:?}"),
        }
    }

    /// Behaviour 10.16: in the side views the mill tool of the list (D 10,
    /// L 30) is a rectangle D wide from the tool point up L. At the point
    /// (20, 10, 0) in XZ (u = x, v = z): the end from x 15 to 25 at z 0,
    /// on screen (100 + 2·15, 100) = (130, 100) to (150, 100); the top at
    /// z 30, y = 100 − 60 = 40; the sides at x 15 and 25 from z 0 to 30.
    /// In YZ (u = y) the same about y 10: from y 5 to 15, x = 110 to 130.
    #[test]
    fn behaviour10_16_the_mill_tool_is_a_rectangle_in_the_side_views() {
        let shapes = cylinder(&frame(Plane::Xz), [20.0, 10.0, 0.0], 5.0, 30.0);
        assert_eq!(shapes.len(), 4, "{shapes:?}");
        let end = line(&shapes[0]);
        near(end.0, (130.0, 100.0));
        near(end.1, (150.0, 100.0));
        let top = line(&shapes[1]);
        near(top.0, (130.0, 40.0));
        near(top.1, (150.0, 40.0));
        let (left, right) = (line(&shapes[2]), line(&shapes[3]));
        near(left.0, (130.0, 100.0));
        near(left.1, (130.0, 40.0));
        near(right.0, (150.0, 100.0));
        near(right.1, (150.0, 40.0));
        let shapes = cylinder(&frame(Plane::Yz), [20.0, 10.0, 0.0], 5.0, 30.0);
        let end = line(&shapes[0]);
        near(end.0, (110.0, 100.0));
        near(end.1, (130.0, 100.0));
        // Seen along the spindle (XY) it is the end's circle alone, radius
        // 5 × 2 = 10 px at (100 + 40, 100 − 20).
        let shapes = cylinder(&frame(Plane::Xy), [20.0, 10.0, 0.0], 5.0, 30.0);
        assert_eq!(shapes, vec![Seen::Circle((140.0, 80.0), 10.0)]);
    }

    /// Behaviour 10.16: a tool listed without a length is drawn open: the
    /// end and the two sides one diameter (10) up, no top. In XZ at the
    /// origin: the sides from (90, 100) and (110, 100) up to y = 100 − 20.
    #[test]
    fn behaviour10_16_a_tool_without_a_length_is_drawn_open_a_diameter_up() {
        let shapes = cylinder(&frame(Plane::Xz), [0.0; 3], 5.0, 0.0);
        assert_eq!(shapes.len(), 3, "{shapes:?}");
        let (left, right) = (line(&shapes[1]), line(&shapes[2]));
        near(left.0, (90.0, 100.0));
        near(left.1, (90.0, 80.0));
        near(right.1, (110.0, 80.0));
    }

    /// Behaviour 10.16: the tool in the isometric view. right = (cos 45°,
    /// sin 45°, 0) = (0.70711, 0.70711, 0), up = (−0.40825, 0.40825,
    /// 0.81650). The sides stand at p ± r·right: (±3.5355, ±3.5355, 0)
    /// projects to u = 0.70711·3.5355·2 = ±5.000, v = 0, i.e. x = 100 ± 10;
    /// they rise L·0.81650 = 20·0.81650 = 16.330 (32.660 px: y = 67.340).
    /// The end's ellipse starts at (5, 0, 0): (3.5355, −2.0412), pixel
    /// (107.071, 104.082); a quarter turn on at (0, 5, 0): (3.5355,
    /// 2.0412), pixel (107.071, 95.918).
    #[test]
    fn behaviour10_16_the_tool_in_the_3d_view_is_the_cylinders_outline() {
        let f = frame(Plane::Orbit(Angles::ISO));
        let shapes = cylinder(&f, [0.0; 3], 5.0, 20.0);
        assert_eq!(shapes.len(), 4, "{shapes:?}");
        let Seen::Ellipse(end) = &shapes[0] else {
            panic!("{:?}", shapes[0]);
        };
        assert_eq!(end.len(), ELLIPSE_SEGMENTS + 1);
        near(end[0], (107.071, 104.082));
        near(end[ELLIPSE_SEGMENTS / 4], (107.071, 95.918));
        near(end[0], end[ELLIPSE_SEGMENTS]);
        let Seen::Ellipse(top) = &shapes[1] else {
            panic!("{:?}", shapes[1]);
        };
        near(top[0], (107.071, 104.082 - 32.660));
        let (left, right) = (line(&shapes[2]), line(&shapes[3]));
        near(left.0, (90.0, 100.0));
        near(left.1, (90.0, 67.340));
        near(right.0, (110.0, 100.0));
        near(right.1, (110.0, 67.340));
    }

    /// Behaviour 10.17: the compensation's circle in the 3D view is the
    /// circle in its plane, projected. G18's (XZ) circle of radius 5 in
    /// the iso view: (5, 0, 0) at (3.5355, −2.0412) as above, (0, 0, 5)
    /// at (0, 5·0.81650) = (0, 4.0825): pixel (100, 91.835). Its own plane
    /// view draws a true circle (10 px), a plane view seeing it edge on
    /// (XY) a line D long: from x 90 to 110 at y 100.
    #[test]
    fn behaviour10_17_the_compensation_circle_is_projected_in_its_plane() {
        let axes = circle_axes(Plane::Xz).unwrap();
        let f = frame(Plane::Orbit(Angles::ISO));
        let Some(Seen::Ellipse(points)) = seen(&f, [0.0; 3], axes, 5.0) else {
            panic!("an ellipse");
        };
        near(points[0], (107.071, 104.082));
        near(points[ELLIPSE_SEGMENTS / 4], (100.0, 91.835));
        assert_eq!(
            seen(&frame(Plane::Xz), [0.0; 3], axes, 5.0),
            Some(Seen::Circle((100.0, 100.0), 10.0))
        );
        let edge = seen(&frame(Plane::Xy), [0.0; 3], axes, 5.0).unwrap();
        let (a, b) = line(&edge);
        near(a, (90.0, 100.0));
        near(b, (110.0, 100.0));
        // Under half a pixel: nothing.
        assert_eq!(seen(&f, [0.0; 3], axes, 0.1), None);
    }

    /// Behaviour 10.17: which views draw the compensation's circle: every
    /// view of its machine's space but the lathe's face view.
    #[test]
    fn behaviour10_17_the_compensation_circle_is_drawn_in_every_view_of_its_space() {
        let orbit = Plane::Orbit(Angles::ISO);
        let lathe_orbit = Plane::LatheOrbit(Angles::ISO);
        for circle in [Plane::Xy, Plane::Xz, Plane::Yz] {
            for view in [Plane::Xy, Plane::Xz, Plane::Yz, orbit] {
                assert!(drawn_in(circle, view), "{circle:?} in {view:?}");
            }
            for view in [Plane::LatheZx, Plane::LatheXc, lathe_orbit] {
                assert!(!drawn_in(circle, view), "{circle:?} in {view:?}");
            }
        }
        assert!(drawn_in(Plane::LatheZx, Plane::LatheZx));
        assert!(drawn_in(Plane::LatheZx, lathe_orbit));
        assert!(!drawn_in(Plane::LatheZx, Plane::LatheXc));
        assert!(!drawn_in(Plane::LatheZx, Plane::Xy));
    }

    /// Behaviour 10.5: the box the fit holds grows by the reach. The mill's
    /// box (0, 0, −10)–(40, 20, 5) with radius 5 and a tool 30 long: every
    /// side out by 5, the top by 30 (5 + 25 more): (−5, −5, −15)–(45, 25,
    /// 35). The lathe's (X a diameter) with 2R = 1.6: X out by 3.2 on the
    /// diameter, Z by 1.6, Y not at all.
    #[test]
    fn behaviour10_5_the_fit_box_grows_by_the_reach() {
        let reach = Reach {
            radius: 5.0,
            up: 30.0,
        };
        let grown = reach.grow(([0.0, 0.0, -10.0], [40.0, 20.0, 5.0]), false);
        assert_eq!(grown, ([-5.0, -5.0, -15.0], [45.0, 25.0, 35.0]));
        let lathe = Reach {
            radius: 1.6,
            up: 0.0,
        };
        let grown = lathe.grow(([20.0, 0.0, -30.0], [60.0, 0.0, 2.0]), true);
        let want = ([16.8, 0.0, -31.6], [63.2, 0.0, 3.6]);
        for k in 0..3 {
            assert!((grown.0[k] - want.0[k]).abs() < 1e-12, "{grown:?}");
            assert!((grown.1[k] - want.1[k]).abs() < 1e-12, "{grown:?}");
        }
        // Nonsense reaches nothing.
        let none = Reach {
            radius: f64::NAN,
            up: f64::INFINITY,
        };
        assert_eq!(none.grow(([0.0; 3], [1.0; 3]), false), ([0.0; 3], [1.0; 3]));
    }
}
