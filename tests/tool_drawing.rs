//! The tool drawn round the marker in every view and the fit that leaves
//! room for it (behaviour 10.5, 10.16, 10.17), through the page's session:
//! the tool list's mill tool as its cylinder (a rectangle in XZ and YZ, the
//! projected outline in 3D), the compensation's circle projected in the 3D
//! view, and zoom 1 holding all of it.

use offsetlab::render::{self, Font, Pen, Rect, Stroke, Surface};
use offsetlab::session::view::ViewChange;
use offsetlab::session::{Session, read_setup};

fn session(text: &str, setup: &str) -> Session {
    let mut s = Session::new();
    let answer = s.run(text.into(), read_setup(Some(Some(setup))), |_| ());
    assert_eq!(answer.summary.errors, 0);
    s
}

fn view(s: &mut Session, json: &str) {
    let change: ViewChange = serde_json::from_str(json).unwrap();
    s.set_view(&change);
}

/// What the `tool` group draws: its paths (dashed or not, their points)
/// and its circles (centre, radius, dashed).
#[derive(Default)]
struct Tool {
    depth: usize,
    in_tool: bool,
    dashed: bool,
    paths: Vec<(bool, Vec<(f64, f64)>)>,
    circles: Vec<((f64, f64), f64, bool)>,
}

impl Pen for Tool {
    fn begin_path(&mut self, stroke: &Stroke) {
        self.dashed = !stroke.dash.is_empty();
        if self.in_tool {
            self.paths.push((self.dashed, Vec::new()));
        }
    }
    fn move_to(&mut self, x: f64, y: f64) {
        self.line_to(x, y);
    }
    fn line_to(&mut self, x: f64, y: f64) {
        if let (true, Some(p)) = (self.in_tool, self.paths.last_mut()) {
            p.1.push((x, y));
        }
    }
    fn stroke(&mut self) {}
    fn begin_group(&mut self, name: &str) {
        self.depth += 1;
        if name == "tool" {
            self.in_tool = true;
        }
    }
    fn end_group(&mut self) {
        self.depth -= 1;
        self.in_tool = false;
    }
}

impl Surface for Tool {
    fn clear(&mut self, _: f64, _: f64, _: &str) {}
    fn fill_rect(&mut self, _: Rect, _: &str, _: Option<&str>) {}
    fn fill_text(&mut self, _: &str, _: f64, _: f64, _: &Font) {}
    fn fill_polygon(&mut self, _: &[(f64, f64)], _: &str) {}
    fn circle(&mut self, x: f64, y: f64, r: f64, _: Option<&str>, stroke: Option<&Stroke>) {
        if self.in_tool {
            let dashed = stroke.is_some_and(|s| !s.dash.is_empty());
            self.circles.push(((x, y), r, dashed));
        }
    }
}

fn drawn(s: &Session) -> (render::Frame, Tool) {
    let mut t = Tool::default();
    let f = render::draw_scene(&mut t, s.toolpath(), s.scene(), 800.0, 600.0);
    (f, t)
}

fn near(a: (f64, f64), b: (f64, f64)) {
    assert!(
        (a.0 - b.0).abs() < 1e-6 && (a.1 - b.1).abs() < 1e-6,
        "{a:?} vs {b:?}"
    );
}

/// Every point drawn round the tool lies in the plot (the fit's
/// rectangle), so nothing drawn is cut at the edge at zoom 1.
fn all_in_plot(f: &render::Frame, t: &Tool) {
    let r = f.plot;
    let inside = |(x, y): (f64, f64)| {
        x >= r.x - 1e-6 && x <= r.right() + 1e-6 && y >= r.y - 1e-6 && y <= r.bottom() + 1e-6
    };
    for (_, points) in &t.paths {
        for &p in points {
            assert!(inside(p), "{p:?} outside {r:?}");
        }
    }
    for &((x, y), radius, _) in &t.circles {
        for p in [
            (x - radius, y),
            (x + radius, y),
            (x, y - radius),
            (x, y + radius),
        ] {
            assert!(
                inside(p),
                "circle at {x} {y} r {radius}: {p:?} outside {r:?}"
            );
        }
    }
}

const MILL: &str = "T1 M06\nG90 G00 X20. Y10. Z0\nG01 X60. F200.\nY40.\n";
const TOOLS: &str = r#"{"tools":{"01":{"diameter":10,"length":120}}}"#;

/// Behaviour 10.16: tool 1 (D 10, L 120) in XZ at the end of block 1
/// (X20 Y10 Z0): a dashed rectangle from x 15 to 25, z 0 to 120 — the end,
/// the top and the two sides; the marker stays at the point. Its corners
/// through the frame's transform are where the rectangle's lines end.
#[test]
fn behaviour10_16_the_tool_is_a_rectangle_in_the_side_views() {
    let mut s = session(MILL, TOOLS);
    view(&mut s, r#"{"plane":"XZ","step":1}"#);
    let (f, t) = drawn(&s);
    let dashed: Vec<_> = t.paths.iter().filter(|p| p.0).map(|p| &p.1).collect();
    assert_eq!(dashed.len(), 4, "{:?}", t.paths);
    let at = |x: f64, z: f64| f.transform.to_screen(x, z);
    near(dashed[0][0], at(15.0, 0.0));
    near(dashed[0][1], at(25.0, 0.0));
    near(dashed[1][0], at(15.0, 120.0));
    near(dashed[1][1], at(25.0, 120.0));
    near(dashed[2][1], at(15.0, 120.0));
    near(dashed[3][1], at(25.0, 120.0));
    // The marker (a filled circle) at the point, not a dashed circle.
    assert!(t.circles.iter().all(|c| !c.2));
    assert!(t.circles.iter().any(|c| {
        let (x, y) = at(20.0, 0.0);
        (c.0.0 - x).abs() < 1e-6 && (c.0.1 - y).abs() < 1e-6
    }));
    // Zoom 1 holds the tool's 120 mm above a path that is flat at Z 0.
    all_in_plot(&f, &t);
    // In YZ about Y10: from y 5 to 15.
    view(&mut s, r#"{"plane":"YZ"}"#);
    let (f, t) = drawn(&s);
    let end = &t.paths.iter().find(|p| p.0).unwrap().1;
    near(end[0], f.transform.to_screen(5.0, 0.0));
    near(end[1], f.transform.to_screen(15.0, 0.0));
    all_in_plot(&f, &t);
}

/// Behaviour 10.16: in the 3D view the tool is the cylinder's outline:
/// two dashed ellipses (the end and the top) and two dashed sides, whose
/// screen ends are the projections of p ± r·right and of those 120 up
/// (right = (cos ψ, sin ψ, 0), here the iso view's (0.70711, 0.70711, 0)).
#[test]
fn behaviour10_16_the_tool_in_the_3d_view() {
    let mut s = session(MILL, TOOLS);
    view(&mut s, r#"{"plane":"3D","step":1}"#);
    let (f, t) = drawn(&s);
    let dashed: Vec<_> = t.paths.iter().filter(|p| p.0).map(|p| &p.1).collect();
    assert_eq!(dashed.len(), 4);
    assert!(dashed[0].len() > 40 && dashed[1].len() > 40, "ellipses");
    let c = std::f64::consts::FRAC_1_SQRT_2 * 5.0;
    let at = |p: [f64; 3]| {
        let (u, v) = f.projection.project(&p);
        f.transform.to_screen(u, v)
    };
    near(dashed[2][0], at([20.0 - c, 10.0 - c, 0.0]));
    near(dashed[2][1], at([20.0 - c, 10.0 - c, 120.0]));
    near(dashed[3][0], at([20.0 + c, 10.0 + c, 0.0]));
    all_in_plot(&f, &t);
}

/// Behaviour 10.5: the fit leaves room for what is drawn round the tool
/// over the whole run, so it does not change while stepping: the frame's
/// transform is the same at every block and with none, and larger
/// (smaller scale) than without the tool list.
#[test]
fn behaviour10_5_the_fit_holds_the_tool_and_stays_while_stepping() {
    let mut s = session(MILL, TOOLS);
    view(&mut s, r#"{"plane":"XZ"}"#);
    let whole = drawn(&s).0.transform;
    for step in 0..4 {
        view(&mut s, &format!(r#"{{"step":{step}}}"#));
        let (f, t) = drawn(&s);
        assert_eq!(f.transform, whole, "block {step}");
        all_in_plot(&f, &t);
    }
    let mut bare = session(MILL, "{}");
    view(&mut bare, r#"{"plane":"XZ"}"#);
    assert!(drawn(&bare).0.transform.scale > whole.scale);
}

/// Behaviour 10.17 and 10.5: the compensation's circle (G41 D01 = 5,
/// G17) is drawn solid in the 3D view as the projected circle: its point
/// at t = 0 is the centre + 5 along X, and a quarter turn on + 5 along Y;
/// in the plan view it is the circle, and the fit holds it there.
#[test]
fn behaviour10_17_the_cutter_circle_in_the_3d_view() {
    let text =
        "G00 X-20. Y-20.\nG01 G41 D01 X0 Y0 F100.\nY40.\nX60.\nY0\nX0\nG40 X-20. Y-20.\nM30\n";
    let mut s = session(text, r#"{"offsets":{"01":5.0}}"#);
    view(&mut s, r#"{"plane":"3D","step":2}"#);
    let (f, t) = drawn(&s);
    let solid: Vec<_> = t.paths.iter().filter(|p| !p.0).map(|p| &p.1).collect();
    assert_eq!(solid.len(), 1, "{:?}", t.paths);
    let centre = s.scene().marker.unwrap()[0];
    assert_eq!(centre, [-5.0, 45.0, 0.0]);
    let at = |p: [f64; 3]| {
        let (u, v) = f.projection.project(&p);
        f.transform.to_screen(u, v)
    };
    let points = solid[0];
    near(points[0], at([0.0, 45.0, 0.0]));
    near(points[points.len() / 4], at([-5.0, 50.0, 0.0]));
    all_in_plot(&f, &t);
    // The plan view: the circle, which the fit holds (the corner at
    // (−5, 45) reaches X −10 and Y 50).
    view(&mut s, r#"{"plane":"XY"}"#);
    let (f, t) = drawn(&s);
    let r = 5.0 * f.transform.scale;
    assert!(
        t.circles.iter().any(|c| !c.2 && (c.1 - r).abs() < 1e-9),
        "{:?}",
        t.circles
    );
    all_in_plot(&f, &t);
}

/// Behaviour 10.17: the G17 compensation's circle in the side views is
/// the circle seen edge on: a solid line D01 × 2 = 10 long, centred on the
/// tool at its height. At step 2 (the corner at (−5, 45), Z 0) the XZ
/// view's line runs from X −10 to X 0 at Z 0, the YZ view's from Y 40 to
/// Y 50.
#[test]
fn behaviour10_17_the_cutter_circle_edge_on_in_the_side_views() {
    let text =
        "G00 X-20. Y-20.\nG01 G41 D01 X0 Y0 F100.\nY40.\nX60.\nY0\nX0\nG40 X-20. Y-20.\nM30\n";
    let mut s = session(text, r#"{"offsets":{"01":5.0}}"#);
    for (plane, a, b) in [
        ("XZ", [-10.0, 45.0, 0.0], [0.0, 45.0, 0.0]),
        ("YZ", [-5.0, 40.0, 0.0], [-5.0, 50.0, 0.0]),
    ] {
        view(&mut s, &format!(r#"{{"plane":"{plane}","step":2}}"#));
        let (f, t) = drawn(&s);
        let solid: Vec<_> = t.paths.iter().filter(|p| !p.0).map(|p| &p.1).collect();
        assert_eq!(solid.len(), 1, "{plane}: {:?}", t.paths);
        let at = |p: [f64; 3]| {
            let (u, v) = f.projection.project(&p);
            f.transform.to_screen(u, v)
        };
        assert_eq!(solid[0].len(), 2, "{plane}: {:?}", solid[0]);
        near(solid[0][0], at(a));
        near(solid[0][1], at(b));
        all_in_plot(&f, &t);
    }
}

/// Behaviour 10.18 with 10.13: the lathe's nose circle (tool 1, R 0.8,
/// tip 3 at X40 Z2: its centre at X41.6 Z2.8, behaviour 10.13) is drawn
/// dashed in the lathe's 3D view as the projected circle in the ZX plane:
/// its point at t = 0 is the centre + 0.8 along Z (Z3.6), a quarter turn
/// on + 0.8 as a radius along X (X43.2 on the diameter).
#[test]
fn behaviour10_18_the_nose_circle_in_the_lathe_3d_view() {
    let mut s = session(
        "T0101\nG00 X40. Z2.\nG01 Z-20. F0.2\n",
        r#"{"machine":"lathe","tools":{"01":{"nose_radius":0.8,"tip":3}}}"#,
    );
    view(&mut s, r#"{"plane":"3D","angles":[30,20],"step":1}"#);
    let (f, t) = drawn(&s);
    let dashed: Vec<_> = t.paths.iter().filter(|p| p.0).map(|p| &p.1).collect();
    assert_eq!(dashed.len(), 1, "{:?}", t.paths);
    let at = |p: [f64; 3]| {
        let (u, v) = f.projection.project(&p);
        f.transform.to_screen(u, v)
    };
    let points = dashed[0];
    near(points[0], at([41.6, 0.0, 3.6]));
    near(points[points.len() / 4], at([43.2, 0.0, 2.8]));
    all_in_plot(&f, &t);
}
