//! What the 3D view draws around the paths (behaviour 10.8, 10.18): the
//! grid on the XY plane at Z = 0 under the path (the lathe's: on the
//! profile's plane, Z and X as a radius), the three axes through the origin,
//! and a small triad in the corner that shows which way X, Y and Z point
//! at the view's angles. The paths, arrows and tool marker go through the
//! frame's projection like those of the plane views.

use super::*;

/// At most this many grid lines each way: the step grows past it.
const MAX_LINES: f64 = 200.0;
/// Length of the corner triad's arms, CSS pixels.
const TRIAD_PX: f64 = 28.0;

/// The machine's space as the 3D view draws it: the grid's plane is
/// spanned by the toolpath's coordinates `axes[0]` and `axes[1]` (at 0 of
/// `axes[2]`), each a unit `scale` of the toolpath's long, named `names`.
/// The mill's grid is XY at Z = 0; the lathe's the plane of the profile,
/// Z along the spindle and X as a radius (the toolpath's X is a diameter),
/// at C = 0 (behaviour 10.18).
struct Space {
    axes: [usize; 3],
    scale: [f64; 3],
    names: [&'static str; 3],
}

const MILL: Space = Space {
    axes: [0, 1, 2],
    scale: [1.0, 1.0, 1.0],
    names: ["X", "Y", "Z"],
};
const LATHE: Space = Space {
    axes: [2, 0, 1],
    scale: [1.0, 2.0, 1.0],
    names: ["Z", "X", "C"],
};

fn space(f: &Frame) -> &'static Space {
    if f.plane.is_lathe() { &LATHE } else { &MILL }
}

impl Space {
    /// The toolpath's point of the space's (a, b, c).
    fn point(&self, q: [f64; 3]) -> [f64; 3] {
        let mut p = [0.0; 3];
        for k in 0..3 {
            p[self.axes[k]] = q[k] * self.scale[k];
        }
        p
    }

    /// The path's box in the space's coordinates.
    fn bounds(&self, tp: &Toolpath) -> ([f64; 3], [f64; 3]) {
        let (lo, hi) = tp.bounds().unwrap_or(([0.0; 3], [0.0; 3]));
        let get = |p: [f64; 3]| std::array::from_fn(|k| p[self.axes[k]] / self.scale[k]);
        (get(lo), get(hi))
    }
}

/// The grid's box on its plane: the path's range along the two axes with
/// the origin, rounded out to whole steps (min a, min b, max a, max b).
fn grid_box(sp: &Space, tp: &Toolpath, step: f64) -> [f64; 4] {
    let (lo, hi) = sp.bounds(tp);
    let out = |v: f64, up: bool| {
        let n = v / step;
        let n = if up { n.ceil() } else { n.floor() };
        if n.is_finite() { n * step } else { 0.0 }
    };
    [
        out(lo[0].min(0.0), false),
        out(lo[1].min(0.0), false),
        out(hi[0].max(0.0), true),
        out(hi[1].max(0.0), true),
    ]
}

/// The grid's step: the plane views' 1-2-5 step for the frame's scale,
/// larger when the box would need more than [`MAX_LINES`] lines.
fn grid_step_for(sp: &Space, tp: &Toolpath, f: &Frame) -> f64 {
    let mut step = annotate::grid_step(&f.transform);
    for _ in 0..40 {
        let [x0, y0, x1, y1] = grid_box(sp, tp, step);
        if (x1 - x0) / step <= MAX_LINES && (y1 - y0) / step <= MAX_LINES {
            break;
        }
        step = nice_step(step * 1.5);
    }
    step
}

/// The grid lines on the grid's plane, projected.
pub(super) fn draw_grid(s: &mut impl Surface, f: &Frame, tp: &Toolpath) {
    let sp = space(f);
    let step = grid_step_for(sp, tp, f);
    let [x0, y0, x1, y1] = grid_box(sp, tp, step);
    let screen = |x: f64, y: f64| {
        let (u, v) = f.projection.project(&sp.point([x, y, 0.0]));
        f.transform.to_screen(u, v)
    };
    let lines = |lo: f64, hi: f64| {
        let n = ((hi - lo) / step).round().clamp(0.0, MAX_LINES * 2.0) as usize;
        (0..=n).map(move |i| lo + i as f64 * step)
    };
    let ends = lines(x0, x1)
        .map(|x| ((x, y0), (x, y1)))
        .chain(lines(y0, y1).map(|y| ((x0, y), (x1, y))));
    s.begin_group("grid");
    s.begin_path(&f.theme.grid());
    for (a, b) in ends {
        let (a, b) = (screen(a.0, a.1), screen(b.0, b.1));
        if [a.0, a.1, b.0, b.1].iter().all(|v| v.is_finite()) {
            s.move_to(a.0, a.1);
            s.line_to(b.0, b.1);
        }
    }
    s.stroke();
    s.end_group();
}

/// The axes through the origin (the grid's two across it, the third over
/// the path's range along it) and the corner triad with the axes' names.
pub(super) fn draw_axes(s: &mut impl Surface, f: &Frame, tp: &Toolpath) {
    let sp = space(f);
    let step = grid_step_for(sp, tp, f);
    let [x0, y0, x1, y1] = grid_box(sp, tp, step);
    let (lo, hi) = sp.bounds(tp);
    let (z0, z1) = (lo[2].min(0.0), hi[2].max(step));
    let screen = |p: [f64; 3]| {
        let (u, v) = f.projection.project(&sp.point(p));
        f.transform.to_screen(u, v)
    };
    s.begin_group("axes");
    s.begin_path(&f.theme.axis());
    for (a, b) in [
        ([x0, 0.0, 0.0], [x1, 0.0, 0.0]),
        ([0.0, y0, 0.0], [0.0, y1, 0.0]),
        ([0.0, 0.0, z0], [0.0, 0.0, z1]),
    ] {
        let (a, b) = (screen(a), screen(b));
        if [a.0, a.1, b.0, b.1].iter().all(|v| v.is_finite()) {
            s.move_to(a.0, a.1);
            s.line_to(b.0, b.1);
        }
    }
    s.stroke();
    // The triad: each axis's unit vector through the projection (the
    // screen's y runs down), named at its tip.
    let origin = (MARGIN.0 + 8.0, f.height - MARGIN.3 - 8.0);
    let bold = Font {
        bold: true,
        align: Align::Middle,
        ..f.theme.label_font()
    };
    let stroke = Stroke {
        width: 1.5,
        ..f.theme.axis()
    };
    for (k, name) in sp.names.iter().enumerate() {
        let mut unit = [0.0; 3];
        unit[k] = 1.0;
        let (u, v) = f.projection.project(&sp.point(unit));
        let tip = (origin.0 + u * TRIAD_PX, origin.1 - v * TRIAD_PX);
        s.begin_path(&stroke);
        s.move_to(origin.0, origin.1);
        s.line_to(tip.0, tip.1);
        s.stroke();
        // An axis seen end on has its name beside the origin.
        let (lx, ly) = (
            origin.0 + u * (TRIAD_PX + 9.0),
            origin.1 - v * (TRIAD_PX + 9.0),
        );
        s.fill_text(name, lx, ly + 4.0, &bold);
    }
    s.end_group();
}

#[cfg(test)]
mod tests {
    use super::super::test_support::{group, square, svg_of, toolpath};
    use super::super::{Angles, ORBIT_MOVES, draw_scene_moving, scene};
    use super::*;

    /// A square 40 × 20 at Z 0 with a plunge to Z −10 at its corner: three
    /// axes' worth of path.
    const BOX: &str = "G90 G00 X0 Y0 Z5.;\nG01 Z-10. F100.;\nX40.;\nY20.;\nX0;\nY0;\nG00 Z5.;";

    fn iso() -> Scene {
        Scene {
            plane: Plane::Orbit(Angles::ISO),
            ..Scene::default()
        }
    }

    /// Behaviour 10.8: the 3D view draws the grid, the axes with the
    /// triad's names, both paths and the legend titled "3D", and every
    /// point of the path inside the plot (fit uses the projected box).
    #[test]
    fn behaviour10_8_the_3d_view_draws_grid_axes_paths_and_fits_the_projection() {
        let tp = toolpath(BOX);
        let svg = svg_of(&tp, &iso());
        let axes = group(&svg, "axes");
        for name in [">X<", ">Y<", ">Z<"] {
            assert!(axes.contains(name), "{name} in {axes}");
        }
        assert!(group(&svg, "grid").contains("<path"));
        assert!(group(&svg, "actual").contains("<path"));
        assert!(group(&svg, "programmed").contains("<path"));
        assert!(group(&svg, "legend").contains("mill · 3D · mm"));
        // The projected box's eight corners lie in the plot.
        let f = iso().frame(&tp, 800.0, 500.0);
        let (lo, hi) = tp.bounds().unwrap();
        for c in 0..8 {
            let p = [0, 1, 2].map(|k| if c >> k & 1 == 0 { lo[k] } else { hi[k] });
            let (u, v) = f.projection.project(&p);
            let (x, y) = f.transform.to_screen(u, v);
            let r = f.plot;
            assert!(x >= r.x - 1e-6 && x <= r.right() + 1e-6, "{p:?} at x {x}");
            assert!(y >= r.y - 1e-6 && y <= r.bottom() + 1e-6, "{p:?} at y {y}");
        }
        // Not the top view's drawing.
        let top = svg_of(&tp, &Scene::default());
        assert_ne!(group(&svg, "actual"), group(&top, "actual"));
    }

    /// Behaviour 10.8: a click picks the block of the move under it in the
    /// 3D view as in a plane view. The plunge G01 Z-10. (block 1) runs from
    /// (0,0,5) to (0,0,-10); in the iso view it is vertical on the screen
    /// (Z projects to (0, 0.8165)), so its midpoint (0,0,-2.5) is on it and
    /// on no other move but the corner's, which start at its end.
    #[test]
    fn behaviour10_8_picking_works_in_the_3d_view() {
        let tp = toolpath(BOX);
        let f = iso().frame(&tp, 800.0, 500.0);
        let (u, v) = f.projection.project(&[0.0, 0.0, -2.5]);
        let (x, y) = f.transform.to_screen(u, v);
        assert_eq!(scene::pick(&tp, &f, x, y, 3.0), Some(1));
        // The middle of X40. (block 2) at (20, 0, -10).
        let (u, v) = f.projection.project(&[20.0, 0.0, -10.0]);
        let (x, y) = f.transform.to_screen(u, v);
        assert_eq!(scene::pick(&tp, &f, x, y, 3.0), Some(2));
    }

    /// Behaviour 10.8: while the 3D view is turned over a path of more
    /// than ORBIT_MOVES moves, a moving frame draws every n-th move; the
    /// plane views and whole frames draw every move.
    #[test]
    fn behaviour10_8_a_turned_large_path_is_drawn_by_a_sample() {
        let mut program = String::from("G90 G00 X0 Y0;\nG01 F500.;\n");
        let n = ORBIT_MOVES + ORBIT_MOVES / 2;
        for i in 0..n {
            let _ = std::fmt::Write::write_fmt(
                &mut program,
                format_args!("X{}. Y{}.;\n", i % 50, i / 50),
            );
        }
        let tp = toolpath(&program);
        let mut s = super::super::svg::SvgSurface::new();
        // About 1.5 × ORBIT_MOVES moves: every 2nd is drawn.
        let f = draw_scene_moving(&mut s, &tp, &iso(), 400.0, 300.0);
        assert_eq!(f.stride, tp.len().div_ceil(ORBIT_MOVES));
        assert_eq!(f.stride, 2);
        let f = draw_scene(&mut s, &tp, &iso(), 400.0, 300.0);
        assert_eq!(f.stride, 1);
        let f = draw_scene_moving(&mut s, &tp, &Scene::default(), 400.0, 300.0);
        assert_eq!(f.stride, 1);
    }

    #[test]
    fn the_grid_box_holds_the_path_and_the_origin_in_whole_steps() {
        // Seed 000's square runs over X 0…~56, Y 0…~46 (register 01 = 6):
        // with step 10 the box is rounded out to the next tens.
        let tp = square();
        let (lo, hi) = tp.bounds().unwrap();
        let [x0, y0, x1, y1] = grid_box(&MILL, &tp, 10.0);
        assert!(x0 <= lo[0].min(0.0) && y0 <= lo[1].min(0.0));
        assert!(x1 >= hi[0] && y1 >= hi[1]);
        for v in [x0, y0, x1, y1] {
            assert_eq!(v % 10.0, 0.0, "{v}");
        }
    }
}
