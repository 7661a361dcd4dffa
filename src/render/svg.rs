//! SVG backend: the renderer's drawing as a standalone SVG document (for
//! export and for native tests of the renderer). Every text is escaped;
//! coordinates are written with two decimals.

use std::fmt::Write;

use super::style::{Align, FONT_FAMILY, Font, Stroke};
use super::{Pen, Rect, Surface};
use crate::toolpath::Toolpath;

/// Collects SVG elements into a string.
#[derive(Debug, Default)]
pub struct SvgSurface {
    body: String,
    path: String,
    stroke: Option<Stroke>,
    depth: usize,
}

impl SvgSurface {
    /// An empty drawing.
    pub fn new() -> SvgSurface {
        SvgSurface::default()
    }

    /// The finished document, `width` x `height` CSS pixels.
    pub fn finish(mut self, width: f64, height: f64) -> String {
        while self.depth > 0 {
            self.end_group();
        }
        let mut out = String::with_capacity(self.body.len() + 256);
        let _ = writeln!(
            out,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" \
             viewBox=\"0 0 {w} {h}\" font-family=\"{family}\">",
            w = num(width),
            h = num(height),
            family = escape(FONT_FAMILY),
        );
        out.push_str(&self.body);
        out.push_str("</svg>\n");
        out
    }
}

/// Draws a toolpath fitted to `width` x `height` and returns the SVG text.
pub fn render(toolpath: &Toolpath, width: f64, height: f64) -> String {
    let mut surface = SvgSurface::new();
    let frame = super::draw(&mut surface, toolpath, width, height);
    surface.finish(frame.width, frame.height)
}

/// Draws a toolpath as a scene (plane, zoom, pan, step, colours) and
/// returns the SVG text.
pub fn render_scene(toolpath: &Toolpath, scene: &super::Scene, width: f64, height: f64) -> String {
    let mut surface = SvgSurface::new();
    let frame = super::draw_scene(&mut surface, toolpath, scene, width, height);
    surface.finish(frame.width, frame.height)
}

impl Pen for SvgSurface {
    fn begin_group(&mut self, name: &str) {
        let _ = writeln!(self.body, "<g class=\"{}\">", escape(name));
        self.depth += 1;
    }

    fn end_group(&mut self) {
        if self.depth > 0 {
            self.body.push_str("</g>\n");
            self.depth -= 1;
        }
    }

    fn begin_path(&mut self, stroke: &Stroke) {
        self.path.clear();
        self.stroke = Some(*stroke);
    }

    fn move_to(&mut self, x: f64, y: f64) {
        let _ = write!(self.path, "M{} {}", num(x), num(y));
    }

    fn line_to(&mut self, x: f64, y: f64) {
        let _ = write!(self.path, "L{} {}", num(x), num(y));
    }

    fn stroke(&mut self) {
        let Some(stroke) = self.stroke.take() else {
            return;
        };
        if self.path.is_empty() {
            return;
        }
        let _ = write!(
            self.body,
            "<path d=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"{}\" \
             stroke-linecap=\"round\" stroke-linejoin=\"round\"",
            self.path,
            escape(stroke.color),
            num(stroke.width)
        );
        if !stroke.dash.is_empty() {
            let dash: Vec<String> = stroke.dash.iter().map(|d| num(*d)).collect();
            let _ = write!(self.body, " stroke-dasharray=\"{}\"", dash.join(" "));
        }
        self.body.push_str("/>\n");
        self.path.clear();
    }
}

impl Surface for SvgSurface {
    fn clear(&mut self, width: f64, height: f64, color: &str) {
        let _ = writeln!(
            self.body,
            "<rect class=\"background\" x=\"0\" y=\"0\" width=\"{}\" height=\"{}\" fill=\"{}\"/>",
            num(width),
            num(height),
            escape(color)
        );
    }

    fn fill_rect(&mut self, rect: Rect, fill: &str, border: Option<&str>) {
        let _ = write!(
            self.body,
            "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{}\"",
            num(rect.x),
            num(rect.y),
            num(rect.w),
            num(rect.h),
            escape(fill)
        );
        if let Some(border) = border {
            let _ = write!(
                self.body,
                " stroke=\"{}\" stroke-width=\"1\"",
                escape(border)
            );
        }
        self.body.push_str("/>\n");
    }

    fn fill_text(&mut self, text: &str, x: f64, y: f64, font: &Font) {
        let anchor = match font.align {
            Align::Start => "start",
            Align::Middle => "middle",
            Align::End => "end",
        };
        let _ = write!(
            self.body,
            "<text x=\"{}\" y=\"{}\" font-size=\"{}\" fill=\"{}\" text-anchor=\"{anchor}\"",
            num(x),
            num(y),
            num(font.size),
            escape(font.color)
        );
        if font.bold {
            self.body.push_str(" font-weight=\"bold\"");
        }
        let _ = writeln!(self.body, ">{}</text>", escape(text));
    }

    fn fill_polygon(&mut self, points: &[(f64, f64)], fill: &str) {
        let list: Vec<String> = points
            .iter()
            .map(|(x, y)| format!("{},{}", num(*x), num(*y)))
            .collect();
        let _ = writeln!(
            self.body,
            "<polygon points=\"{}\" fill=\"{}\"/>",
            list.join(" "),
            escape(fill)
        );
    }

    fn circle(&mut self, x: f64, y: f64, r: f64, fill: Option<&str>, stroke: Option<&Stroke>) {
        let _ = write!(
            self.body,
            "<circle cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"{}\"",
            num(x),
            num(y),
            num(r),
            escape(fill.unwrap_or("none"))
        );
        if let Some(stroke) = stroke {
            let _ = write!(
                self.body,
                " stroke=\"{}\" stroke-width=\"{}\"",
                escape(stroke.color),
                num(stroke.width)
            );
            if !stroke.dash.is_empty() {
                let dash: Vec<String> = stroke.dash.iter().map(|d| num(*d)).collect();
                let _ = write!(self.body, " stroke-dasharray=\"{}\"", dash.join(" "));
            }
        }
        self.body.push_str("/>\n");
    }
}

/// A number with at most two decimals, without trailing zeros.
fn num(v: f64) -> String {
    if !v.is_finite() {
        return "0".to_string();
    }
    let s = format!("{v:.2}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" || s.is_empty() {
        "0".to_string()
    } else {
        s.to_string()
    }
}

/// Escapes text for element content and attribute values.
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            // Control characters are not allowed in XML 1.0.
            c if (c as u32) < 0x20 && !matches!(c, '\t' | '\n' | '\r') => {}
            c => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::style;
    use crate::render::test_support::{group, square, toolpath_on, toolpath_to_stop};

    fn render_in(tp: &Toolpath, plane: crate::render::Plane, w: f64, h: f64) -> String {
        let scene = crate::render::Scene {
            plane,
            ..crate::render::Scene::default()
        };
        render_scene(tp, &scene, w, h)
    }

    #[test]
    fn square_draws_both_paths_as_groups_with_their_styles() {
        let svg = render(&square(), 800.0, 500.0);
        assert!(svg.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"800\""));
        assert!(svg.ends_with("</svg>\n"));
        assert_eq!(svg.matches("<g class=\"actual\">").count(), 1);
        assert_eq!(svg.matches("<g class=\"programmed\">").count(), 1);
        assert_eq!(svg.matches("<g").count(), svg.matches("</g>").count());
        let actual = group(&svg, "actual");
        let programmed = group(&svg, "programmed");
        // Rapid and feed moves: one path each, in their own colours.
        assert_eq!(actual.matches("<path").count(), 2);
        assert_eq!(programmed.matches("<path").count(), 2);
        assert!(actual.contains(style::ACTUAL_FEED.color));
        assert!(actual.contains(style::ACTUAL_RAPID.color));
        assert!(programmed.contains(style::PROGRAMMED_FEED.color));
        assert!(programmed.contains(style::PROGRAMMED_RAPID.color));
        // Programmed thin and dashed, actual solid and wider.
        assert!(!actual.contains("stroke-dasharray"));
        assert_eq!(programmed.matches("stroke-dasharray=\"6 4\"").count(), 2);
        assert!(programmed.contains("stroke-width=\"1.5\""));
        assert!(actual.contains("stroke-width=\"2.25\""));
        // The legend names both, the scale bar has a length and units.
        let legend = group(&svg, "legend");
        assert!(legend.contains(">actual, feed</text>"));
        assert!(legend.contains(">programmed, rapid</text>"));
        assert!(legend.contains("mill · XY · mm"));
        let scale = group(&svg, "scale");
        assert!(scale.contains(" mm</text>"), "{scale}");
        let axes = group(&svg, "axes");
        assert!(axes.contains(">X</text>") && axes.contains(">Y</text>"));
    }

    #[test]
    fn small_views_get_the_short_legend_still_naming_machine_plane_and_units() {
        // A 496 x 550 view (the page at 1280 x 800) or an embedded lesson:
        // four short rows instead of five long ones, the title unchanged.
        let svg = render(&square(), 496.0, 550.0);
        let legend = group(&svg, "legend");
        for row in [
            "mill · XY · mm",
            ">actual</text>",
            ">programmed</text>",
            ">rapid</text>",
            ">offset</text>",
        ] {
            assert!(legend.contains(row), "{row}: {legend}");
        }
        assert!(!legend.contains("actual, feed"));
        // The legend box stays inside the view and the path clear of it.
        let width: f64 = legend
            .split("width=\"")
            .nth(1)
            .and_then(|w| w.split('"').next())
            .and_then(|w| w.parse().ok())
            .expect("legend rectangle");
        assert!(width < 496.0 / 3.0, "{width}");
    }

    #[test]
    fn actual_square_is_offset_outward_on_screen() {
        // Programmed square 0..80 x 0..50, actual -6..86 x -6..56: the actual
        // feed path spans more pixels than the programmed one.
        let svg = render(&square(), 800.0, 500.0);
        let span = |group_text: &str, color: &str| {
            let path = group_text
                .split("<path ")
                .find(|p| p.contains(color))
                .expect("path");
            let d = &path[path.find("d=\"").unwrap() + 3..];
            let d = &d[..d.find('"').unwrap()];
            let xs: Vec<f64> = d
                .split(['M', 'L'])
                .filter(|s| !s.is_empty())
                .map(|p| p.split(' ').next().unwrap().parse().unwrap())
                .collect();
            let min = xs.iter().cloned().fold(f64::INFINITY, f64::min);
            let max = xs.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
            max - min
        };
        let actual = span(group(&svg, "actual"), style::ACTUAL_FEED.color);
        let programmed = span(group(&svg, "programmed"), style::PROGRAMMED_FEED.color);
        let ratio = actual / programmed;
        assert!(
            (ratio - 92.0 / 80.0).abs() < 0.01,
            "{actual} / {programmed}"
        );
    }

    #[test]
    fn path_fits_inside_the_surface() {
        let svg = render(&square(), 640.0, 480.0);
        for group_name in ["actual", "programmed"] {
            let g = group(&svg, group_name);
            for token in g.split(['M', 'L']).skip(1) {
                let mut it = token.split([' ', '"']);
                let x: f64 = it.next().unwrap().parse().unwrap();
                let y: f64 = it.next().unwrap().parse().unwrap();
                assert!((0.0..=640.0).contains(&x) && (0.0..=480.0).contains(&y));
            }
        }
    }

    #[test]
    fn lathe_is_drawn_in_zx_with_a_centre_line() {
        let tp = toolpath_on(
            "G50 X120. Z60.\nG00 X50. Z3.\nG01 Z-20. F0.2\n",
            crate::MachineKind::Lathe,
        );
        let svg = render(&tp, 900.0, 600.0);
        assert!(svg.contains("lathe · ZX · mm"));
        assert!(svg.contains(">X (radius)</text>"));
        assert!(svg.contains(">centre line</text>"));
        assert!(svg.contains(style::CENTRE_STROKE.color));
        // A small view (an embedded lesson) gets the short legend.
        let small = render(&tp, 600.0, 400.0);
        assert!(small.contains(">lathe · ZX · mm</text>") && small.contains(">centre</text>"));
        assert!(!small.contains("programmed → actual end"));
    }

    /// A 20 × 20 square on the face, centred on the spindle axis, with a
    /// rounded corner (behaviour 14.16): in the face view it is a square
    /// around the origin; in ZX, moves along X at one Z.
    const FACE_SQUARE: &str = "G98 G00 X40. Z2.\nG01 Z-1. F100.\nG12.1\nG01 X20. C-10.\nC5.\nG03 X10. C10. R5.\nG01 X-20.\nC-10.\nX20.\nG13.1\nG00 Z5.\n";

    #[test]
    fn behaviour14_16_the_face_view_draws_the_polar_contour_around_the_spindle_axis() {
        let tp = toolpath_on(FACE_SQUARE, crate::MachineKind::Lathe);
        let svg = render_in(&tp, crate::render::Plane::LatheXc, 600.0, 600.0);
        assert!(svg.contains("lathe · XC · mm"));
        let axes = group(&svg, "axes");
        assert!(axes.contains(">X (radius)</text>") && axes.contains(">C</text>"));
        // The programmed feed path's corners: x from -10 to 10 and C from
        // -10 to 10 (X20. is a radius of 10), drawn as a square: equal
        // spans on screen.
        let programmed = group(&svg, "programmed");
        let path = programmed
            .split("<path ")
            .find(|p| p.contains(style::PROGRAMMED_FEED.color))
            .expect("programmed feed path");
        let d = &path[path.find("d=\"").unwrap() + 3..];
        let d = &d[..d.find('"').unwrap()];
        let points: Vec<(f64, f64)> = d
            .split(['M', 'L'])
            .filter(|s| !s.trim().is_empty())
            .map(|p| {
                let mut it = p.split_whitespace().map(|v| v.parse::<f64>().unwrap());
                (it.next().unwrap(), it.next().unwrap())
            })
            .collect();
        let span = |f: fn(&(f64, f64)) -> f64| {
            let v: Vec<f64> = points.iter().map(f).collect();
            let max = v.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
            let min = v.iter().cloned().fold(f64::INFINITY, f64::min);
            max - min
        };
        // The feed path also holds the plunge G01 Z-1. (a point here: it
        // moves along Z only) and the lead-in from X40. (radius 20) to the
        // first corner: from x = 20 to -10 across, C from -10 to 10 up.
        let (across, up) = (span(|p| p.0), span(|p| p.1));
        assert!((across / up - 30.0 / 20.0).abs() < 0.02, "{across} / {up}");
        // insta is a native dev-dependency (wasm-pack builds these tests too).
        #[cfg(not(target_arch = "wasm32"))]
        insta::assert_snapshot!("face_view_of_a_polar_square", svg);
        // The ZX view keeps showing the face moves along X at Z-1.
        let zx = render_in(&tp, crate::render::Plane::LatheZx, 600.0, 600.0);
        assert!(zx.contains("lathe · ZX · mm"));
    }

    #[test]
    fn empty_run_draws_grid_axes_and_legend_but_no_path() {
        let svg = render(&toolpath_to_stop(""), 300.0, 200.0);
        assert!(group(&svg, "actual").trim().is_empty());
        assert!(group(&svg, "grid").contains("<path"));
        assert!(group(&svg, "axes").contains("<path"));
    }

    #[test]
    fn tiny_and_odd_surfaces_never_panic() {
        let t = square();
        for (w, h) in [
            (0.0, 0.0),
            (1.0, 1.0),
            (5.0, 300.0),
            (300.0, 5.0),
            (f64::NAN, 10.0),
        ] {
            let svg = render(&t, w, h);
            assert!(svg.ends_with("</svg>\n"));
        }
    }

    #[test]
    fn text_is_escaped() {
        assert_eq!(escape("<a & \"b\">'"), "&lt;a &amp; &quot;b&quot;&gt;&#39;");
        let mut s = SvgSurface::new();
        s.fill_text("<script>", 0.0, 0.0, &style::LABEL_FONT);
        let out = s.finish(10.0, 10.0);
        assert!(out.contains("&lt;script&gt;") && !out.contains("<script>"));
    }

    #[test]
    fn numbers_are_short() {
        assert_eq!(num(1.0), "1");
        assert_eq!(num(1.256), "1.26");
        assert_eq!(num(-0.001), "0");
        assert_eq!(num(f64::NAN), "0");
    }
}
