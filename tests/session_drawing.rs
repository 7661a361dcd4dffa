//! The page's session, natively: what a frame draws beyond the paths —
//! the cutter and nose circles, the swept width, the legend and the hole
//! rings (behaviour 16.13, 16.20, 18.2, 10.7, 6.11).

mod common;
use common::session::{run, view_change};
use offsetlab::render;
use offsetlab::render::svg::SvgSurface;
use offsetlab::session::Session;
use serde_json::json;

#[test]
fn behaviour16_13_the_cutter_is_drawn_round_the_tool_while_g41_is_on() {
    // D01 = 5 round a square with G41: at block 2 (offset mode) the scene
    // has the cutter, radius 5 in the XY view, and the frame draws its
    // circle (5 mm at the frame's scale) round the tool marker; after G40
    // there is none.
    let mut s = Session::new();
    let text =
        "G00 X-20. Y-20.\nG01 G41 D01 X0 Y0 F100.\nY40.\nX60.\nY0\nX0\nG40 X-20. Y-20.\nM30\n";
    run(&mut s, text, Some(r#"{"offsets":{"01":5.0}}"#));
    s.set_step(2);
    let cutter = s.scene().cutter.expect("a cutter at a G41 block");
    assert_eq!(cutter.radius, 5.0);
    assert_eq!(cutter.plane, render::Plane::Xy);
    assert_eq!(s.scene().marker.unwrap()[0], [-5.0, 45.0, 0.0]);
    let mut svg = SvgSurface::new();
    let frame = render::draw_scene(&mut svg, s.toolpath(), s.scene(), 640.0, 480.0);
    let r = format!("{:.2}", 5.0 * frame.transform.scale);
    let r = r.trim_end_matches('0').trim_end_matches('.');
    let drawn = svg.finish(640.0, 480.0);
    assert!(
        drawn.contains(&format!("r=\"{r}\"")),
        "no circle of radius {r}"
    );
    s.set_step(6);
    assert_eq!(s.scene().cutter, None);
}

#[test]
fn behaviour16_20_the_swept_width_is_drawn_under_the_current_block_when_asked() {
    // D01 = 5 round a square with G41 (the program of 16.13). Block 2
    // (Y40.) is on the left side of the square, the cutter on its left: its
    // centre runs X-5 from (-5, 0) (the start-up's vector, perpendicular to
    // Y40.) to the corner (-5, 45) before X60. The band is that line
    // stroked 2·R = 2 × 5 = 10 mm wide, i.e. 10 × scale pixels.
    let mut s = Session::new();
    let text =
        "G00 X-20. Y-20.\nG01 G41 D01 X0 Y0 F100.\nY40.\nX60.\nY0\nX0\nG40 X-20. Y-20.\nM30\n";
    run(&mut s, text, Some(r#"{"offsets":{"01":5.0}}"#));
    s.set_step(2);
    let draw = |s: &Session| {
        let mut svg = SvgSurface::new();
        let frame = render::draw_scene(&mut svg, s.toolpath(), s.scene(), 640.0, 480.0);
        (frame, svg.finish(640.0, 480.0))
    };
    // Off by default: no band, in the document neither.
    assert!(!s.scene().swept);
    let (_, off) = draw(&s);
    assert!(!off.contains("class=\"swept\""), "a band while off");
    assert!(!s.document().to_json().contains("swept"));
    let v = s.set_view(&view_change(r#"{"swept":true}"#));
    assert_eq!(v.swept, Some(true));
    let (frame, on) = draw(&s);
    let width = 2.0 * 5.0 * frame.transform.scale;
    let band = on
        .split("<g class=\"swept\">")
        .nth(1)
        .and_then(|rest| rest.split("</g>").next())
        .expect("a swept group");
    let num = |v: f64| {
        let t = format!("{v:.2}");
        t.trim_end_matches('0').trim_end_matches('.').to_owned()
    };
    assert!(
        band.contains(&format!("stroke-width=\"{}\"", num(width))),
        "{band}"
    );
    assert!(band.contains(render::style::LIGHT.swept), "{band}");
    let (x0, y0) = frame.transform.to_screen(-5.0, 0.0);
    let (x1, y1) = frame.transform.to_screen(-5.0, 45.0);
    assert!(
        band.contains(&format!("M{} {}", num(x0), num(y0)))
            && band.contains(&format!("{} {}", num(x1), num(y1))),
        "{band}"
    );
    // Under the paths: the band comes before the actual path.
    assert!(on.find("class=\"swept\"") < on.find("class=\"actual\""));
    // Carried by the document, and only when on.
    let doc = s.document();
    assert!(doc.view.as_ref().is_some_and(|v| v.swept));
    assert!(doc.to_json().contains("\"swept\":true"));
    // Another plane than the compensation's, or no compensation: no band.
    s.set_view(&view_change(r#"{"plane":"XZ"}"#));
    assert!(!draw(&s).1.contains("class=\"swept\""));
    s.set_view(&view_change(r#"{"plane":"XY"}"#));
    s.set_step(7);
    assert!(!draw(&s).1.contains("class=\"swept\""));
}

#[test]
fn behaviour18_2_the_nose_circle_is_drawn_about_the_nose_centre() {
    // T0101: nose R 0.8, tip 3. At N40 (the diameter X40. toward
    // the chuck, G42) the program's point, the imaginary nose, ends at
    // X40. Z-20.8 at N40 = block 6 (behaviour 18.2: cut on the line, 0.8 on in Z at the
    // corner the arc makes). Tip 3's vector is (Z -1, X -1): the nose
    // centre is 0.8 up (X +1.6 as a diameter) and 0.8 toward +Z from it:
    // X41.6 Z-20.0. The circle of radius 0.8 is drawn there in the ZX view.
    let mut s = Session::new();
    let text = "G18 G21 G99\nT0101\nG00 X0 Z2.\nG42 G01 Z0 F0.15\nX30.\nX40. Z-5.\nZ-20.\nG02 X60. Z-30. R10.\nG01 Z-45.\nG40 G00 X80. Z5.\nM30\n";
    run(
        &mut s,
        text,
        Some(r#"{"machine":"lathe","lathe_offsets":{"01":{"x":0,"z":0,"r":0.8,"t":3}}}"#),
    );
    s.set_step(6);
    let marker = s.scene().marker.unwrap()[0];
    assert!(
        (marker[0] - 40.0).abs() < 1e-9 && (marker[2] + 20.8).abs() < 1e-9,
        "{marker:?}"
    );
    let cutter = s.scene().cutter.expect("the nose at a G42 block");
    assert_eq!(cutter.plane, render::Plane::LatheZx);
    assert!((cutter.radius - 0.8).abs() < 1e-12);
    let centre = [marker[0] + cutter.centre[0], marker[2] + cutter.centre[2]];
    assert!(
        (centre[0] - 41.6).abs() < 1e-9 && (centre[1] + 20.0).abs() < 1e-9,
        "{centre:?}"
    );
    // Drawn: a circle of radius 0.8 at the frame's scale, centred on the
    // nose centre's screen point (Z right, X as a radius up).
    let mut svg = SvgSurface::new();
    let frame = render::draw_scene(&mut svg, s.toolpath(), s.scene(), 640.0, 480.0);
    let (cx, cy) = frame.transform.to_screen(-20.0, 20.8);
    let r = format!("{:.2}", 0.8 * frame.transform.scale);
    let r = r.trim_end_matches('0').trim_end_matches('.');
    let drawn = svg.finish(640.0, 480.0);
    let cx = format!("{cx:.2}");
    let cx = cx.trim_end_matches('0').trim_end_matches('.');
    assert!(
        drawn.contains(&format!("cx=\"{cx}\"")) && drawn.contains(&format!("r=\"{r}\"")),
        "no circle of radius {r} at x {cx} ({cy})"
    );
    // After G40 (block 9) there is none.
    s.set_step(9);
    assert_eq!(s.scene().cutter, None);
}

#[test]
fn behaviour10_7_the_legend_folds_away_and_the_path_gets_the_whole_view() {
    // A 170 × 100 rectangle, about the shape of a 470 × 280 view (the
    // drawing of a 720 × 420 lesson frame): fitted to the whole view it
    // would run under the legend in the top right corner, so with the
    // legend it is fitted beside it or below it, both much smaller; folded
    // away, the whole view less the margins is the plot, and it is drawn
    // larger.
    let mut s = Session::new();
    run(&mut s, "G01 X170. F100.\nY100.\nX0\nY0\nM30\n", None);
    let draw = |s: &Session| {
        let mut svg = SvgSurface::new();
        let frame = render::draw_scene(&mut svg, s.toolpath(), s.scene(), 470.0, 280.0);
        (frame, svg.finish(470.0, 280.0))
    };
    let (shown, with) = draw(&s);
    assert!(with.contains("<g class=\"legend\">"));
    assert!(!s.document().to_json().contains("legend"));
    let v = s.set_view(&view_change(r#"{"legend":false}"#));
    assert_eq!(v.legend, Some(false));
    let (folded, without) = draw(&s);
    assert!(
        !without.contains("class=\"legend\""),
        "a legend while folded"
    );
    // The plot is the whole view less the margins: it holds the legend's
    // corner, which the plot beside or below it does not.
    assert!(folded.plot.x + folded.plot.w > shown.legend.x);
    assert!(folded.plot.y < shown.legend.y + shown.legend.h);
    assert!(
        folded.transform.scale > 1.2 * shown.transform.scale,
        "{} vs {}",
        folded.transform.scale,
        shown.transform.scale
    );
    // Kept in the document (written only when folded) and back on request.
    assert!(s.document().to_json().contains("\"legend\":false"));
    s.set_view(&view_change(r#"{"legend":true}"#));
    let (again, _) = draw(&s);
    assert_eq!(again.transform.scale, shown.transform.scale);
    assert!(!s.document().to_json().contains("legend"));
}

/// The centres of the rings in the drawing's `holes` group.
fn rings(svg: &str) -> Vec<(f64, f64)> {
    let Some(group) = svg
        .split("<g class=\"holes\">")
        .nth(1)
        .and_then(|rest| rest.split("</g>").next())
    else {
        return Vec::new();
    };
    group
        .split("<circle ")
        .skip(1)
        .map(|c| {
            let attr = |name: &str| -> f64 {
                let start = c.find(&format!("{name}=\"")).unwrap() + name.len() + 2;
                c[start..].split('"').next().unwrap().parse().unwrap()
            };
            (attr("cx"), attr("cy"))
        })
        .collect()
}

#[test]
fn behaviour6_11_each_canned_cycle_hole_is_a_ring_in_the_top_view() {
    // G81 at X10 Y10 and X30 Y10 (G99: back to R2 between them), a G83
    // peck hole at X50 Y20 (Q2 to Z-6: three pecks, one hole), then a
    // plunge written by hand at X80 Y80 (G00, then G01 Z-5 in a block of
    // its own), which is not a hole. Three rings, at the holes' X Y.
    let mut s = Session::new();
    let text = "G90 G00 X0 Y0 Z10.\nG99 G81 X10. Y10. Z-5. R2. F100.\nX30.\nG83 X50. Y20. Z-6. R2. Q2.\nG80\nG00 X80. Y80.\nG01 Z-5. F100.\nX90.\nG00 Z10.\nM30\n";
    let answer = run(&mut s, text, None);
    assert_eq!(answer["summary"]["errors"], json!(0), "{answer}");
    let draw = |s: &Session| {
        let mut svg = SvgSurface::new();
        let frame = render::draw_scene(&mut svg, s.toolpath(), s.scene(), 800.0, 600.0);
        (frame, svg.finish(800.0, 600.0))
    };
    let (frame, svg) = draw(&s);
    assert!(frame.holes);
    let found = rings(&svg);
    let expected: Vec<(f64, f64)> = [(10.0, 10.0), (30.0, 10.0), (50.0, 20.0)]
        .iter()
        .map(|&(x, y)| frame.transform.to_screen(x, y))
        .collect();
    assert_eq!(found.len(), 3, "{found:?}");
    for ((fx, fy), (ex, ey)) in found.iter().zip(&expected) {
        // The SVG writes two decimals.
        assert!(
            (fx - ex).abs() < 0.01 && (fy - ey).abs() < 0.01,
            "{found:?} vs {expected:?}"
        );
    }
    assert!(
        svg.contains("hole (canned cycle)"),
        "the legend names them: {}",
        svg.split("<g class=\"legend\">").nth(1).unwrap_or("")
    );
    // Seen from the front (XZ) the holes are lines, not points: no rings.
    s.set_view(&view_change(r#"{"plane":"XZ"}"#));
    let (frame, svg) = draw(&s);
    assert!(!frame.holes);
    assert!(rings(&svg).is_empty());
    assert!(!svg.contains("hole (canned cycle)"));
    // Stepped to the first hole's block, the later rings are drawn in the
    // colour of moves not run yet.
    s.set_view(&view_change(r#"{"plane":"XY","step":1}"#));
    let (_, svg) = draw(&s);
    let group = svg.split("<g class=\"holes\">").nth(1).unwrap();
    let group = group.split("</g>").next().unwrap();
    let drilled = render::style::LIGHT.actual_feed;
    let ahead = render::style::LIGHT.ghost;
    assert_eq!(
        group.matches(&format!("stroke=\"{drilled}\"")).count(),
        1,
        "{group}"
    );
    assert_eq!(
        group.matches(&format!("stroke=\"{ahead}\"")).count(),
        2,
        "{group}"
    );
}
