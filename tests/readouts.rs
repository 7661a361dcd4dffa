//! Readouts a machinist expects (issue 23 item 5): the distance to go of
//! the current block (behaviour 6.12), the start and reference positions in
//! effect (6.13, 13.16 in the Settings panel) and the tool list that draws
//! the tool at its size (7.53, 9.9, 10.13, 13.16).

mod common;
use common::{lathe, mill, ok};
use offsetlab::render::svg::SvgSurface;
use offsetlab::session::view::ViewChange;
use offsetlab::session::{Session, read_setup};
use offsetlab::setup::{Control, MachinePositions, Tool};
use offsetlab::view::{RunView, block_view};
use offsetlab::{Setup, Units, render};
use serde_json::{Value, json};

fn with(mut s: Setup, control: Control) -> Setup {
    s.settings.control = control;
    s
}

/// The JSON of every block of a run, as `run --format json` prints them.
fn blocks_json(text: &str, setup: &Setup) -> Vec<Value> {
    let r = ok(text, setup);
    let v = serde_json::to_value(RunView { run: &r, text }).unwrap();
    v["blocks"].as_array().unwrap().clone()
}

fn to_go(b: &Value) -> Value {
    b["distance_to_go"].clone()
}

/// On the Fanuc mill the tool starts homed at X0 Y0 Z508 (13.15). Each
/// block's distance to go is its whole motion: where it ends less where it
/// started.
#[test]
fn behaviour6_12_distance_to_go_is_the_blocks_whole_move() {
    let s = with(mill(&[]), Control::Fanuc);
    let text = "G90 G54 G00 X10. Y20. Z5.\nG01 X15. Y5. F100.\nM03 S1000\nG98 G81 X30. Y5. Z-4. R2.\nG80\n";
    let b = blocks_json(text, &s);
    // Line 1: from (0, 0, 508) to (10, 20, 5): X 10 − 0 = +10,
    // Y 20 − 0 = +20, Z 5 − 508 = −503.
    assert_eq!(to_go(&b[0]), json!({"x": 10.0, "y": 20.0, "z": -503.0}));
    // Line 2: from (10, 20, 5) to (15, 5, 5): X +5, Y 5 − 20 = −15, Z 0.
    assert_eq!(to_go(&b[1]), json!({"x": 5.0, "y": -15.0, "z": 0.0}));
    // Line 3 makes no motion: nothing to go.
    assert_eq!(to_go(&b[2]), json!({"x": 0.0, "y": 0.0, "z": 0.0}));
    // Line 4, G98 G81: to X30 Y5, down to Z−4 and back to the initial
    // level Z5; its net motion is X 30 − 15 = +15, Y 0, Z 5 − 5 = 0.
    assert_eq!(to_go(&b[3]), json!({"x": 15.0, "y": 0.0, "z": 0.0}));
}

/// A block that changes the work system counts the tool's travel, not the
/// jump of the coordinates: with G55's zero at machine X100, `G55 X10.`
/// after `G00 X10.` in G54 (zero at machine 0) moves the tool from machine
/// X10 to X110 — a distance to go of +100 although X reads 10 before and
/// after.
#[test]
fn behaviour6_12_a_change_of_work_system_counts_the_tools_travel() {
    let mut s = mill(&[]);
    s.work_offsets.g55.x = 100.0;
    let b = blocks_json("G90 G00 X10.\nG55 X10.\n", &s);
    assert_eq!(to_go(&b[0]), json!({"x": 10.0, "y": 0.0, "z": 0.0}));
    assert_eq!(b[1]["actual"]["x"], json!(10.0));
    assert_eq!(to_go(&b[1]), json!({"x": 100.0, "y": 0.0, "z": 0.0}));
}

/// The lathe's X is a diameter, as its positions are, and it has no Y.
/// The Fanuc lathe starts at the turret's home X406.4 Z355.6 (13.15).
#[test]
fn behaviour6_12_the_lathe_distance_to_go_has_x_as_a_diameter() {
    let s = with(lathe(&[]), Control::Fanuc);
    let b = blocks_json("G00 X50. Z2.\nG01 U-10. F0.2\n", &s);
    // Line 1: X 50 − 406.4 = −356.4, Z 2 − 355.6 = −353.6.
    assert_eq!(to_go(&b[0]), json!({"x": -356.4, "z": -353.6}));
    // Line 2: U−10 is 10 less on the diameter.
    assert_eq!(to_go(&b[1]), json!({"x": -10.0, "z": 0.0}));
}

/// In inches the distance is in inches: from X0 to X1. is 1 in (25.4 mm).
#[test]
fn behaviour6_12_the_distance_is_in_the_blocks_units() {
    let b = blocks_json("G20 G90 G00 X1. Y0.5\n", &mill(&[]));
    assert_eq!(to_go(&b[0]), json!({"x": 1.0, "y": 0.5, "z": 0.0}));
}

/// The page makes a block's report again from the checkpoint before it
/// (10.2): its distance to go is the one of the whole run, at a checkpoint
/// (block 512, the first of a new stretch) as anywhere else. 600 blocks of
/// `G91 G01 X1.`: every one goes +1 in X.
#[test]
fn behaviour6_12_the_page_shows_the_distance_of_the_whole_run() {
    let text = format!("F100.\n{}", "G91 G01 X1.\n".repeat(600));
    let mut s = Session::new();
    s.run(text.clone(), read_setup(None), |_| ());
    let whole = ok(&text, &Setup::default());
    for i in [1u32, 511, 512, 513, 600] {
        let page = serde_json::to_value(s.block(i)).unwrap();
        let run = serde_json::to_value(block_view(&whole.blocks[i as usize], &text)).unwrap();
        assert_eq!(
            page["distance_to_go"],
            json!({"x": 1.0, "y": 0.0, "z": 0.0})
        );
        assert_eq!(page, run, "block {i}");
    }
    // The F block before them moves nothing.
    let first = serde_json::to_value(s.block(0)).unwrap();
    assert_eq!(
        first["distance_to_go"],
        json!({"x": 0.0, "y": 0.0, "z": 0.0})
    );
}

/// The summary reports the start and reference positions the run used, in
/// the setup's units: the typical machine's on Fanuc and Haas (13.15),
/// on YASNAC the tool at the origin under the typical reference, and
/// whatever the setup sets.
#[test]
fn behaviour6_13_the_summary_has_the_positions_in_effect() {
    let summary = |s: &Setup| {
        let r = ok("G00 X1.\n", s);
        serde_json::to_value(offsetlab::view::summary(&r)).unwrap()["positions"].clone()
    };
    let p = summary(&with(mill(&[]), Control::Fanuc));
    assert_eq!(p["machine_positions"], "typical");
    assert_eq!(p["units"], "mm");
    assert_eq!(p["start"], json!({"x": 0.0, "y": 0.0, "z": 508.0}));
    assert_eq!(p["reference"], json!({"x": 0.0, "y": 0.0, "z": 508.0}));
    assert_eq!(p["second_reference"], p["reference"]);
    // The lathe: the turret home, X 16 in = 406.4 mm, Z 14 in = 355.6 mm.
    let p = summary(&with(lathe(&[]), Control::Haas));
    assert_eq!(p["start"], json!({"x": 406.4, "y": 0.0, "z": 355.6}));
    // YASNAC: the tool starts at the work zero, the reference is above it.
    let p = summary(&mill(&[]));
    assert_eq!(p["machine_positions"], "work_zero_start");
    assert_eq!(p["start"], json!({"x": 0.0, "y": 0.0, "z": 0.0}));
    assert_eq!(p["reference"], json!({"x": 0.0, "y": 0.0, "z": 508.0}));
    // An inch setup: 20 in.
    let mut inch = with(mill(&[]), Control::Haas);
    inch.units = Units::Inch;
    assert_eq!(summary(&inch)["reference"]["z"], json!(20.0));
    // A start the setup sets wins; the reference stays the typical one;
    // G54 at machine Z−400 moves the homed start but not a set one.
    let mut set = with(mill(&[]), Control::Fanuc);
    set.start.z = 100.0;
    let p = summary(&set);
    assert_eq!(p["start"]["z"], json!(100.0));
    assert_eq!(p["reference"]["z"], json!(508.0));
    let mut g54 = with(mill(&[]), Control::Fanuc);
    g54.work_offsets.g54.z = -400.0;
    // 508 − (−400) = 908 in G54 coordinates.
    assert_eq!(summary(&g54)["start"]["z"], json!(908.0));
    let mut zero = with(mill(&[]), Control::Fanuc);
    zero.settings.machine_positions = Some(MachinePositions::WorkZero);
    assert_eq!(summary(&zero)["machine_positions"], "work_zero");
}

/// The tool list in the document: keyed by tool number with two digits,
/// each part left out at 0; `--tool` specs set the same entries; bad
/// values are refused.
#[test]
fn behaviour7_53_the_tool_list_reads_writes_and_is_checked() {
    let s = Setup::from_json(
        r#"{"tools":{"1":{"diameter":10,"length":120},"12":{"nose_radius":0.8,"tip":3}}}"#,
    )
    .unwrap();
    assert_eq!(
        s.tools[&1],
        Tool {
            diameter: 10.0,
            length: 120.0,
            ..Tool::default()
        }
    );
    assert_eq!(s.tools[&12].tip, 3);
    let written = serde_json::to_value(&s).unwrap();
    assert_eq!(
        written["tools"],
        json!({"01": {"diameter": 10.0, "length": 120.0}, "12": {"nose_radius": 0.8, "tip": 3}})
    );
    let mut by_spec = Setup::default();
    by_spec.set_tool("1=D10,L120").unwrap();
    by_spec.set_tool("12=R0.8,T3").unwrap();
    assert_eq!(by_spec.tools, s.tools);
    // A spec replaces the tool's entry.
    by_spec.set_tool("1=D6").unwrap();
    assert_eq!(by_spec.tools[&1].length, 0.0);
    for bad in ["0=D10", "10000=D1", "1=X5", "1=T12", "1=Dten", "D10"] {
        assert!(Setup::default().set_tool(bad).is_err(), "{bad}");
    }
    for bad in [
        r#"{"tools":{"01":{"diameter":-1}}}"#,
        r#"{"tools":{"01":{"length":1000}}}"#,
        r#"{"tools":{"01":{"tip":10}}}"#,
        r#"{"tools":{"01":{"radius":1}}}"#,
    ] {
        assert!(Setup::from_json(bad).is_err(), "{bad}");
    }
    // A tool 0 is refused too (T0 is no tool).
    let mut zero = Setup::default();
    zero.tools.insert(0, Tool::default());
    assert!(!zero.validate().is_empty());
}

/// Plain links carry the tool list as `tool=NN:D…,L…`, repeatable, and
/// read it back.
#[test]
fn behaviour9_9_plain_links_carry_the_tool_list() {
    let mut doc = offsetlab::Document {
        program: "T1 M06\n".into(),
        ..Default::default()
    };
    doc.setup.set_tool("1=D10,L120").unwrap();
    doc.setup.set_tool("2=D6").unwrap();
    let link = offsetlab::share::encode_plain(&doc, false);
    assert!(link.contains("tool=01:D10,L120&tool=02:D6"), "{link}");
    let back = offsetlab::share::decode(&link).unwrap();
    assert_eq!(back.document.setup.tools, doc.setup.tools);
    // Written by hand, and a bad one names the key's problem.
    let hand = offsetlab::share::decode("#program=T1&machine=lathe&tool=1:R0.4,T3").unwrap();
    assert_eq!(hand.document.setup.tools[&1].nose_radius, 0.4);
    let bad = offsetlab::share::decode("#program=T1&tool=1:Q4").unwrap_err();
    assert_eq!(bad.code, "link-plain");
}

fn session(text: &str, setup: &str) -> Session {
    let mut s = Session::new();
    let answer = s.run(text.into(), read_setup(Some(Some(setup))), |_| ());
    assert_eq!(answer.summary.errors, 0);
    s
}

fn step(s: &mut Session, plane: &str, index: u32) {
    let change: ViewChange =
        serde_json::from_str(&format!(r#"{{"plane":"{plane}","step":{index}}}"#)).unwrap();
    s.set_view(&change);
}

/// The `tool` group's circles: (cx, cy, r, dashed).
fn tool_circles(s: &Session) -> (render::Frame, Vec<(f64, f64, f64, bool)>) {
    let mut svg = SvgSurface::new();
    let frame = render::draw_scene(&mut svg, s.toolpath(), s.scene(), 800.0, 600.0);
    let out = svg.finish(800.0, 600.0);
    let group = out.split("<g class=\"tool\">").nth(1).unwrap();
    let group = group.split("</g>").next().unwrap();
    let circles = group
        .split("<circle ")
        .skip(1)
        .map(|c| {
            let attr = |name: &str| -> f64 {
                let start = c
                    .find(&format!(" {name}=\""))
                    .map(|i| i + 1)
                    .unwrap_or_else(|| c.find(&format!("{name}=\"")).unwrap())
                    + name.len()
                    + 2;
                c[start..].split('"').next().unwrap().parse().unwrap()
            };
            (
                attr("cx"),
                attr("cy"),
                attr("r"),
                c.contains("stroke-dasharray"),
            )
        })
        .collect();
    (frame, circles)
}

/// The mill's tool from the tool list is drawn at its size in the plan
/// view: after `T1 M06` with tool 1 of 10 mm diameter, a dashed circle of
/// radius 5 mm (5 × the view's scale in pixels) round the tool at X20 Y10;
/// none in the side views, and none for a tool the list does not have.
#[test]
fn behaviour10_13_the_mill_tool_is_drawn_at_its_size_in_the_plan_view() {
    let text = "T1 M06\nG90 G00 X20. Y10.\nT2 M06\nX30.\n";
    let mut s = session(text, r#"{"tools":{"01":{"diameter":10,"length":120}}}"#);
    step(&mut s, "XY", 1);
    let (frame, circles) = tool_circles(&s);
    let dashed: Vec<_> = circles.iter().filter(|c| c.3).collect();
    assert_eq!(dashed.len(), 1, "{circles:?}");
    let (x, y) = frame.transform.to_screen(20.0, 10.0);
    let r = 5.0 * frame.transform.scale;
    // The SVG writes two decimals.
    assert!((dashed[0].0 - x).abs() < 0.01 && (dashed[0].1 - y).abs() < 0.01);
    assert!((dashed[0].2 - r).abs() < 0.01, "{} vs {r}", dashed[0].2);
    step(&mut s, "XZ", 1);
    assert!(tool_circles(&s).1.iter().all(|c| !c.3));
    // Tool 2 is not in the list: the marker alone.
    step(&mut s, "XY", 3);
    assert!(tool_circles(&s).1.iter().all(|c| !c.3));
}

/// The lathe's insert is drawn as its nose circle about the nose centre:
/// tool 1 with R0.8 and tip 3 (the imaginary nose below and left of the
/// centre, 18.2) at X40 Z2 has its centre 0.8 further in +X (1.6 on the
/// diameter: X41.6) and +Z (Z2.8).
#[test]
fn behaviour10_13_the_lathe_nose_circle_is_about_the_nose_centre() {
    let text = "T0101\nG00 X40. Z2.\n";
    let mut s = session(
        text,
        r#"{"machine":"lathe","tools":{"01":{"nose_radius":0.8,"tip":3}}}"#,
    );
    step(&mut s, "ZX", 1);
    let (frame, circles) = tool_circles(&s);
    let dashed: Vec<_> = circles.iter().filter(|c| c.3).collect();
    assert_eq!(dashed.len(), 1, "{circles:?}");
    let (u, v) = frame.plane.project(&[41.6, 0.0, 2.8]);
    let (x, y) = frame.transform.to_screen(u, v);
    assert!((dashed[0].0 - x).abs() < 0.01 && (dashed[0].1 - y).abs() < 0.01);
    assert!((dashed[0].2 - 0.8 * frame.transform.scale).abs() < 0.01);
}

/// The tool list describes the tool; compensation reads the registers as
/// the control does. Tool 1 is 10 mm across but D01 is empty: G41 D01
/// offsets by 0 (the actual path is the programmed one), no cutter circle
/// is drawn from the list, only the tool's own dashed one.
#[test]
fn behaviour13_16_compensation_reads_the_register_not_the_tool_list() {
    let text = "T1 M06\nG90 G00 X0 Y0\nG41 G01 X20. Y0 D01 F100.\nY20.\n";
    let setup = r#"{"tools":{"01":{"diameter":10}}}"#;
    let mut s = session(text, setup);
    let b = serde_json::to_value(s.block(3)).unwrap();
    assert_eq!(b["cutter"]["radius"], json!(0.0));
    assert_eq!(b["actual"], b["programmed"]);
    step(&mut s, "XY", 3);
    let (_, circles) = tool_circles(&s);
    assert_eq!(circles.iter().filter(|c| c.3).count(), 1);
    // With D01 = 5 the register's circle (solid, radius 5) joins it.
    let mut s = session(
        text,
        r#"{"tools":{"01":{"diameter":10}},"offsets":{"01":5}}"#,
    );
    step(&mut s, "XY", 3);
    let (frame, circles) = tool_circles(&s);
    let r = 5.0 * frame.transform.scale;
    let solid: Vec<_> = circles
        .iter()
        .filter(|c| !c.3 && (c.2 - r).abs() < 0.01)
        .collect();
    assert_eq!(solid.len(), 1, "{circles:?}");
}
