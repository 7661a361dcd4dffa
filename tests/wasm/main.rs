//! Wasm contract tests: the core runs in Chromium (`wasm-pack test --headless
//! --chrome -- --test wasm`) and these pin what only a browser shows — the
//! shape JavaScript sees (field names, `null`, never `undefined`, for absent
//! values, the program buffer's addresses), what throws and what answers an
//! error value, and the canvas's pixels — so the page and the core cannot
//! drift apart silently. The session's rules are tested natively, in
//! `tests/session.rs`.
#![cfg(target_arch = "wasm32")]

use js_sys::{Array, Function, JSON, Reflect, Uint8Array};
use offsetlab::wasm::Session;
use wasm_bindgen::{JsCast, JsValue};
use wasm_bindgen_test::{wasm_bindgen_test, wasm_bindgen_test_configure};
use web_sys::{OffscreenCanvas, OffscreenCanvasRenderingContext2d};

wasm_bindgen_test_configure!(run_in_browser);

#[allow(dead_code)]
#[path = "../common/programs.rs"]
mod programs;

/// Seed 000 (spec's worked example): the G45–G48 square, register 01 = 6.
const SQUARE: &str = include_str!("../data/seed000_square.nc");

fn json(text: &str) -> JsValue {
    JSON::parse(text).expect("test JSON parses")
}

fn get(value: &JsValue, key: &str) -> JsValue {
    Reflect::get(value, &JsValue::from_str(key)).expect("object")
}

fn has(value: &JsValue, key: &str) -> bool {
    Reflect::has(value, &JsValue::from_str(key)).expect("object")
}

fn num(value: &JsValue, key: &str) -> f64 {
    get(value, key)
        .as_f64()
        .unwrap_or_else(|| panic!("`{key}` is a number"))
}

fn string(value: &JsValue, key: &str) -> String {
    get(value, key)
        .as_string()
        .unwrap_or_else(|| panic!("`{key}` is a string"))
}

/// Asserts that a plain object has every key in `keys`.
fn assert_keys(value: &JsValue, keys: &[&str]) {
    assert!(value.is_object(), "an object");
    for key in keys {
        assert!(has(value, key), "missing key `{key}`");
        assert!(!get(value, key).is_undefined(), "`{key}` is undefined");
    }
}

fn array(value: &JsValue) -> Array {
    assert!(Array::is_array(value), "an array");
    value.clone().unchecked_into()
}

fn square_setup() -> JsValue {
    json(r#"{"offsets":{"01":6.0}}"#)
}

/// Writes `bytes` at the start of the session's program buffer of `room`
/// bytes, as the page's worker does with `TextEncoder.encodeInto`; false
/// when the session had no room.
fn write_program(s: &mut Session, bytes: &[u8], room: usize) -> bool {
    let at = s.program_buffer(room);
    if at.is_null() {
        return false;
    }
    write_at(at, bytes);
    true
}

/// Writes `bytes` at `at` in wasm memory (the address a session gave).
fn write_at(at: *mut u8, bytes: &[u8]) {
    let memory: js_sys::WebAssembly::Memory = wasm_bindgen::memory().unchecked_into();
    let view = Uint8Array::new_with_byte_offset_and_length(
        &memory.buffer(),
        at as u32,
        bytes.len() as u32,
    );
    view.copy_from(bytes);
}

/// Runs `program` with `setup` as the page's worker does: written into the
/// session's program buffer, then `run_buffer`.
fn run(s: &mut Session, program: impl AsRef<str>, setup: JsValue) -> JsValue {
    let bytes = program.as_ref().as_bytes();
    assert!(write_program(s, bytes, bytes.len()), "room for the program");
    s.run_buffer(bytes.len(), setup, None).expect("run")
}

#[wasm_bindgen_test]
fn run_returns_summary_and_diagnostics() {
    let mut s = Session::new();
    let result = run(&mut s, SQUARE, square_setup());
    assert_keys(&result, &["summary", "diagnostics"]);
    let summary = get(&result, "summary");
    assert_keys(
        &summary,
        &[
            "machine", "units", "blocks", "moves", "errors", "warnings", "end", "bounds",
        ],
    );
    assert_eq!(string(&summary, "machine"), "mill");
    assert_eq!(string(&summary, "units"), "mm");
    assert_eq!(num(&summary, "blocks"), 8.0);
    assert_eq!(num(&summary, "errors"), 0.0);
    let end = get(&summary, "end");
    assert_eq!(string(&end, "reason"), "program_end");
    assert_eq!(num(&end, "line"), 9.0);
    let bounds = get(&summary, "bounds");
    assert_eq!(num(&get(&bounds, "min"), "x"), -30.0);
    assert_eq!(num(&get(&bounds, "max"), "y"), 56.0);
    assert_eq!(array(&get(&result, "diagnostics")).length(), 0);
    assert_eq!(s.block_count(), 8);
}

#[wasm_bindgen_test]
fn block_shape_uses_null_for_absent_values() {
    let mut s = Session::new();
    run(&mut s, SQUARE, square_setup());
    // Block 1 is line 3: G91 G00 G46 X30. Y20. D01 from (-30, -20): the
    // programmed point is the origin, the actual one 6 short of it (seed 000).
    let b = s.block(1).expect("block");
    assert_keys(
        &b,
        &[
            "index",
            "line",
            "column",
            "end_column",
            "text",
            "units",
            "programmed",
            "actual",
            "modal",
            "tool",
            "length_offset",
            "position_offset",
            "explanation",
            "first_move",
            "move_count",
        ],
    );
    assert_eq!(num(&b, "line"), 3.0);
    assert_eq!(string(&b, "text"), "G91 G00 G46 X30. Y20. D01");
    // No F word yet: `feed` is present and null, not undefined; so is the spindle.
    assert!(has(&b, "feed") && get(&b, "feed").is_null());
    assert!(has(&b, "spindle") && get(&b, "spindle").is_null());
    let actual = get(&b, "actual");
    assert_eq!(num(&actual, "x"), -6.0);
    assert_eq!(num(&actual, "y"), -6.0);
    assert_eq!(num(&actual, "z"), 0.0);
    assert_eq!(num(&get(&b, "programmed"), "x"), 0.0);
    let modal = get(&b, "modal");
    assert_eq!(string(&modal, "motion"), "G00");
    assert_eq!(string(&modal, "distance"), "G91");
    let position = get(&b, "position_offset");
    assert_eq!(num(&position, "d"), 1.0);
    assert_eq!(num(&position, "value"), 6.0);
    assert_eq!(num(&get(&position, "vector"), "x"), -6.0);
    // A mill block has no lathe offset key at all.
    assert!(!has(&b, "lathe_offset"));
    // After F200. the feed is a number.
    assert_eq!(num(&s.block(2).expect("block"), "feed"), 200.0);
    // Out of range: null.
    assert!(s.block(8).expect("block").is_null());
    assert!(s.block(u32::MAX).expect("block").is_null());
}

#[wasm_bindgen_test]
fn a_syntax_error_is_a_diagnostic_with_line_and_column() {
    let mut s = Session::new();
    let result = run(&mut s, "G00 X10.\nG01 X1.2.3 F100.\n", JsValue::UNDEFINED);
    let diagnostics = array(&get(&result, "diagnostics"));
    assert_eq!(diagnostics.length(), 1);
    let d = diagnostics.get(0);
    assert_keys(
        &d,
        &[
            "severity",
            "code",
            "message",
            "line",
            "column",
            "end_column",
        ],
    );
    assert_eq!(string(&d, "severity"), "error");
    assert_eq!(string(&d, "code"), "malformed-number");
    assert_eq!(num(&d, "line"), 2.0);
    assert_eq!(num(&d, "column"), 5.0);
    assert!(!has(&d, "span"), "the byte span stays inside");
    let summary = get(&result, "summary");
    assert_eq!(num(&summary, "errors"), 1.0);
    assert_eq!(string(&get(&summary, "end"), "reason"), "error");
    // The block before the error ran.
    assert_eq!(s.block_count(), 1);
}

#[wasm_bindgen_test]
fn a_bad_setup_gives_diagnostics_not_an_exception() {
    let cases = [
        json(r#"{"machine":"drill"}"#),
        json(r#"{"offsets":{"01":5000}}"#),
        json(r#"{"no_such_field":1}"#),
        JsValue::from_str("{ not json"),
        JsValue::from_f64(3.0),
        js_sys::BigInt::from(1u32).into(),
    ];
    for setup in cases {
        let mut s = Session::new();
        let result = run(&mut s, SQUARE, setup);
        let diagnostics = array(&get(&result, "diagnostics"));
        assert!(diagnostics.length() >= 1);
        for d in diagnostics.iter() {
            assert!(string(&d, "code").starts_with("setup-"), "{:?}", d);
            assert_eq!(num(&d, "line"), 0.0);
            assert_eq!(string(&d, "severity"), "error");
        }
        // An empty path (its toolpath: tests/session.rs).
        assert_eq!(num(&get(&result, "summary"), "moves"), 0.0);
        assert_eq!(s.block_count(), 0);
        assert!(get(&get(&result, "summary"), "bounds").is_null());
    }
}

#[wasm_bindgen_test]
fn setup_may_be_json_text() {
    let mut s = Session::new();
    let result = run(
        &mut s,
        SQUARE,
        JsValue::from_str(r#"{"offsets":{"01":6.0}}"#),
    );
    assert_eq!(num(&get(&result, "summary"), "errors"), 0.0);
    let setup = s.setup().expect("setup");
    assert_eq!(num(&get(&setup, "offsets"), "01"), 6.0);
    assert_eq!(string(&setup, "machine"), "mill");
}

#[wasm_bindgen_test]
fn lathe_positions_have_x_and_z_only() {
    let mut s = Session::new();
    let setup = json(r#"{"machine":"lathe","lathe_offsets":{"08":{"x":0.4,"z":-0.2}}}"#);
    let result = run(
        &mut s,
        "G50 X120. Z60.\nG00 S800 M03 T0108;\nX50. Z3.;\nT0100;",
        setup,
    );
    assert_eq!(num(&get(&result, "summary"), "errors"), 0.0);
    assert_eq!(string(&get(&result, "summary"), "machine"), "lathe");
    let b = s.block(1).expect("block");
    let actual = get(&b, "actual");
    assert_eq!(num(&actual, "x"), 120.4);
    assert_eq!(num(&actual, "z"), 59.8);
    assert!(!has(&actual, "y"), "a lathe position has no y");
    assert!(!has(&get(&b, "programmed"), "y"));
    assert_eq!(num(&b, "spindle"), 800.0);
    let lathe = get(&b, "lathe_offset");
    assert_eq!(num(&lathe, "offset"), 8.0);
    assert_eq!(num(&get(&lathe, "value"), "x"), 0.4);
    assert!(!has(&b, "length_offset") && !has(&b, "position_offset"));
    // The svg backend draws the lathe's ZX view with its centre line.
    let svg = s.render_svg(400, 300);
    assert!(svg.contains("centre line"));
}

#[wasm_bindgen_test]
fn render_draws_on_an_offscreen_canvas_at_device_pixels() {
    let mut s = Session::new();
    run(&mut s, SQUARE, square_setup());
    // Without a canvas, render does nothing and does not throw.
    s.render(300, 200, 2.0).expect("render without canvas");
    let canvas = OffscreenCanvas::new(10, 10).expect("OffscreenCanvas");
    s.attach_canvas(canvas.clone()).expect("attach");
    s.render(300, 200, 2.0).expect("render");
    assert_eq!((canvas.width(), canvas.height()), (600, 400));
    // Read the pixels back through the same 2D context.
    let ctx = canvas.get_context("2d").expect("ctx").expect("2d");
    let get_image_data: Function = get(&ctx, "getImageData").dyn_into().expect("function");
    let args = Array::of4(&0.into(), &0.into(), &600.into(), &400.into());
    let image = get_image_data.apply(&ctx, &args).expect("image data");
    let data = get(&image, "data")
        .unchecked_into::<js_sys::Uint8ClampedArray>()
        .to_vec();
    let painted = data
        .chunks_exact(4)
        .filter(|p| p[0] < 200 || p[1] < 200 || p[2] < 200)
        .count();
    assert!(painted > 2000, "only {painted} dark pixels");
    // Odd sizes and silly ratios are clamped, never a panic.
    s.render(0, 0, f64::NAN).expect("render");
    assert_eq!((canvas.width(), canvas.height()), (1, 1));
    let svg = s.render_svg(300, 200);
    assert!(svg.contains("<g class=\"actual\">") && svg.contains("<g class=\"programmed\">"));
}

/// The pixels of an OffscreenCanvas, RGBA.
fn canvas_pixels(canvas: &OffscreenCanvas) -> Vec<u8> {
    let ctx = canvas.get_context("2d").expect("ctx").expect("2d");
    let get_image_data: Function = get(&ctx, "getImageData").dyn_into().expect("function");
    let (w, h) = (canvas.width(), canvas.height());
    let args = Array::of4(&0.into(), &0.into(), &w.into(), &h.into());
    let image = get_image_data.apply(&ctx, &args).expect("image data");
    get(&image, "data")
        .unchecked_into::<js_sys::Uint8ClampedArray>()
        .to_vec()
}

/// The 2D context of an OffscreenCanvas (the one the session draws with).
fn context_2d(canvas: &OffscreenCanvas) -> OffscreenCanvasRenderingContext2d {
    canvas
        .get_context("2d")
        .expect("ctx")
        .expect("2d")
        .dyn_into()
        .expect("2d context")
}

/// The painted (not background) pixels of an OffscreenCanvas.
fn painted_pixels(canvas: &OffscreenCanvas) -> usize {
    canvas_pixels(canvas)
        .chunks_exact(4)
        .filter(|p| p[0] < 200 || p[1] < 200 || p[2] < 200)
        .count()
}

#[wasm_bindgen_test]
fn a_large_path_is_drawn_as_pixels_and_moved_while_the_view_moves() {
    // 3,000 feed moves: past the renderer's RASTER_FROM_MOVES.
    let mut program = String::from("G90 G00 X0 Y0\nG01 F100.\n");
    for i in 0..3000 {
        program.push_str(&format!("X{}. Y{}.\n", i % 100, (i % 2) * 50));
    }
    let mut s = Session::new();
    run(&mut s, program.clone(), JsValue::NULL);
    let canvas = OffscreenCanvas::new(10, 10).expect("OffscreenCanvas");
    s.attach_canvas(canvas.clone()).expect("attach");
    // Before a whole frame there is nothing to move: it draws in full.
    assert!(!s.render_moving(400, 300, 2.0).expect("render_moving"));
    s.render(400, 300, 2.0).expect("render");
    let whole = painted_pixels(&canvas);
    assert!(whole > 50_000, "only {whole} painted pixels");
    // A zoom step: the last drawing, scaled.
    s.zoom_at(200.0, 150.0, 1.25);
    assert!(s.render_moving(400, 300, 2.0).expect("render_moving"));
    assert!(painted_pixels(&canvas) > whole / 2);
    // A run of the same path keeps the drawing: it is still moved.
    run(&mut s, program.clone(), JsValue::NULL);
    assert!(s.render_moving(400, 300, 2.0).expect("render_moving"));
    // Another path (or plane, step, colours, size): drawn in full again;
    // the same view asked for again is that frame, nothing is drawn.
    run(
        &mut s,
        program.replace("X7. Y50.", "X7. Y40."),
        JsValue::NULL,
    );
    assert!(!s.render_moving(400, 300, 2.0).expect("render_moving"));
    assert!(!s.render_moving(400, 300, 2.0).expect("render_moving"));
    s.pan_by(10.0, 0.0);
    assert!(s.render_moving(400, 300, 2.0).expect("render_moving"));
    s.set_step(10);
    assert!(!s.render_moving(400, 300, 2.0).expect("render_moving"));
}

fn view_of(s: &Session) -> JsValue {
    let v = s.view().expect("view");
    assert_keys(&v, &["plane", "zoom", "pan", "step"]);
    v
}

fn pan_of(v: &JsValue) -> (f64, f64) {
    let pan = array(&get(v, "pan"));
    assert_eq!(pan.length(), 2);
    (
        pan.get(0).as_f64().expect("number"),
        pan.get(1).as_f64().expect("number"),
    )
}

#[wasm_bindgen_test]
fn view_state_is_a_plain_object_with_null_for_no_step() {
    // The rules (ranges, planes, zoom and pan, the lathe's ZX): tests/session.rs.
    let mut s = Session::new();
    run(&mut s, SQUARE, square_setup());
    let v = view_of(&s);
    assert_eq!(string(&v, "plane"), "XY");
    assert_eq!(num(&v, "zoom"), 1.0);
    assert_eq!(pan_of(&v), (0.0, 0.0));
    assert!(get(&v, "step").is_null(), "no current block yet: null");
    // Zoom at the cursor and drag change zoom and pan; fit resets both.
    s.render(800, 500, 1.0)
        .expect("render without canvas keeps the size");
    s.zoom_at(200.0, 100.0, 2.0);
    s.pan_by(30.0, -10.0);
    let v = view_of(&s);
    assert_eq!(num(&v, "zoom"), 2.0);
    assert_ne!(pan_of(&v), (0.0, 0.0));
    s.fit();
    assert_eq!(pan_of(&view_of(&s)), (0.0, 0.0));
    assert!(s.set_plane("xz"));
    assert!(!s.set_plane("ZX"));
    assert_eq!(string(&view_of(&s), "plane"), "XZ");
    // set_view reads what view writes, and answers the view state.
    let v = s
        .set_view(json(r#"{"plane":"YZ","zoom":1e9,"pan":[5,-2],"step":3}"#))
        .expect("set_view");
    assert_keys(&v, &["plane", "zoom", "pan", "step"]);
    assert_eq!(string(&v, "plane"), "YZ");
    assert_eq!(num(&v, "zoom"), 1e6);
    assert_eq!(pan_of(&v), (5.0, -2.0));
    assert_eq!(num(&v, "step"), 3.0);
    let again = s.set_view(view_of(&s)).expect("set_view");
    assert_eq!(stringify(&again), stringify(&v));
    // An object of another shape throws an Error saying what is wrong.
    let e = s
        .set_view(json(r#"{"zoom":"big"}"#))
        .expect_err("a bad view");
    let e = JsValue::from(e);
    assert!(e.is_instance_of::<js_sys::Error>());
    assert!(string(&e, "message").starts_with("view: "), "{e:?}");
}

#[wasm_bindgen_test]
fn pick_returns_the_block_under_the_pointer() {
    let mut s = Session::new();
    run(&mut s, SQUARE, square_setup());
    // Nothing drawn yet: -1.
    assert_eq!(s.pick(10.0, 10.0, 6.0), -1);
    let canvas = OffscreenCanvas::new(10, 10).expect("OffscreenCanvas");
    s.attach_canvas(canvas).expect("attach");
    s.render(800, 500, 1.0).expect("render");
    let mut found = std::collections::BTreeSet::new();
    for y in (0..500).step_by(5) {
        for x in (0..800).step_by(5) {
            let b = s.pick(f64::from(x), f64::from(y), 4.0);
            assert!((-1..8).contains(&b), "{b}");
            found.insert(b);
        }
    }
    for block in [-1, 1, 2, 3, 4, 5, 6] {
        assert!(
            found.contains(&block),
            "block {block} never picked: {found:?}"
        );
    }
}

#[wasm_bindgen_test]
fn dark_theme_and_step_draw_on_the_canvas() {
    let mut s = Session::new();
    run(&mut s, SQUARE, square_setup());
    let canvas = OffscreenCanvas::new(10, 10).expect("OffscreenCanvas");
    s.attach_canvas(canvas.clone()).expect("attach");
    s.set_theme("dark");
    s.set_step(3);
    s.render(200, 100, 1.0).expect("render");
    let ctx = canvas.get_context("2d").expect("ctx").expect("2d");
    let get_image_data: Function = get(&ctx, "getImageData").dyn_into().expect("function");
    let args = Array::of4(&0.into(), &0.into(), &1.into(), &1.into());
    let image = get_image_data.apply(&ctx, &args).expect("image data");
    let corner = get(&image, "data")
        .unchecked_into::<js_sys::Uint8ClampedArray>()
        .to_vec();
    assert!(
        corner[0] < 60 && corner[1] < 60 && corner[2] < 60,
        "{corner:?}"
    );
    let svg = s.render_svg(400, 300);
    assert!(svg.contains("<g class=\"tool\">") && svg.contains("<g class=\"ghost\">"));
}

fn stringify(value: &JsValue) -> String {
    JSON::stringify(value)
        .expect("stringify")
        .as_string()
        .expect("string")
}

mod links;

#[wasm_bindgen_test]
fn a_run_that_changes_nothing_drawn_leaves_the_canvas_as_it_is() {
    let program = programs::numbered_program(3000);
    let mut s = Session::new();
    run(&mut s, program.clone(), JsValue::NULL);
    let canvas = OffscreenCanvas::new(10, 10).expect("OffscreenCanvas");
    s.attach_canvas(canvas.clone()).expect("attach");
    s.render(400, 300, 1.0).expect("render");
    let drawn = painted_pixels(&canvas);
    // Mark the canvas: a frame drawn again would paint over the mark.
    let ctx = context_2d(&canvas);
    ctx.set_fill_style_str("#000");
    ctx.fill_rect(0.0, 0.0, 400.0, 300.0);
    let black = painted_pixels(&canvas);
    assert!(black > drawn);
    // An N number typed: the same path, the same frame — not drawn again.
    run(
        &mut s,
        program.replacen("N1500 ", "N15007 ", 1),
        JsValue::NULL,
    );
    s.render(400, 300, 1.0).expect("render");
    assert_eq!(painted_pixels(&canvas), black);
    // A coordinate typed: the path moved, the frame is drawn again.
    run(
        &mut s,
        program.replacen("N1500 G01 X", "N1500 G01 X1", 1),
        JsValue::NULL,
    );
    s.render(400, 300, 1.0).expect("render");
    let again = painted_pixels(&canvas);
    assert!(again < black && again > drawn / 2, "{again} of {black}");
}

/// A frame of `program` with `step` at 400 × 300 CSS pixels and `dpr`,
/// drawn by a new session on a new canvas; and both.
fn whole_frame(program: &str, step: Option<i32>, dpr: f64) -> (Session, OffscreenCanvas) {
    let mut s = Session::new();
    run(&mut s, program, JsValue::NULL);
    let canvas = OffscreenCanvas::new(10, 10).expect("OffscreenCanvas");
    s.attach_canvas(canvas.clone()).expect("attach");
    if let Some(step) = step {
        s.set_step(step);
    }
    s.render(400, 300, dpr).expect("render");
    (s, canvas)
}

#[wasm_bindgen_test]
fn an_edit_is_painted_where_it_changed_with_the_pixels_of_a_whole_frame() {
    // Issue 6, target 4c: after an edit that moves a move and keeps the
    // bounds, the canvas is painted only inside the box that changed
    // (render::display); the pixels are those of a whole frame — with the
    // current block's marker and highlight too, and when they move.
    let program = programs::numbered_program(3000);
    let edited = program.replacen("N1500 G01 X17.", "N1500 G01 X17.5", 1);
    assert_ne!(edited, program);
    // (first step, the program then, its step, whether the top left corner
    // is left as it was: only the box around the change is painted — for
    // a step to the next block, whichever the drawing chooses).
    let cases = [
        (None, &edited, None, Some(true)),
        (Some(1497), &edited, Some(1497), Some(true)),
        (Some(1497), &program, Some(1498), None),
    ];
    for dpr in [1.0, 2.0] {
        for (first, then, step, boxed) in cases {
            let (mut s, canvas) = whole_frame(&program, first, dpr);
            // A mark in the top left corner, far from the edit: a frame
            // painted whole paints over it.
            let ctx = context_2d(&canvas);
            ctx.set_transform(1.0, 0.0, 0.0, 1.0, 0.0, 0.0)
                .expect("transform");
            ctx.set_fill_style_str("#ff00ff");
            ctx.fill_rect(0.0, 0.0, 1.0, 1.0);
            run(&mut s, then.clone(), JsValue::NULL);
            if let Some(step) = step {
                s.set_step(step);
            }
            s.render(400, 300, dpr).expect("render");
            let painted = canvas_pixels(&canvas);
            let case = format!("{first:?} → {step:?} at {dpr}");
            if let Some(boxed) = boxed {
                assert_eq!(painted[..4] == [255, 0, 255, 255], boxed, "{case}");
            }
            let whole = canvas_pixels(&whole_frame(then, step, dpr).1);
            assert_eq!(painted.len(), whole.len());
            let differ = painted[4..]
                .chunks_exact(4)
                .zip(whole[4..].chunks_exact(4))
                .filter(|(a, b)| a != b)
                .count();
            assert_eq!(differ, 0, "{differ} pixels differ: {case}");
            // And the drawing did change.
            let before = canvas_pixels(&whole_frame(&program, first, dpr).1);
            assert_ne!(before, whole, "{case}");
        }
    }
    // A canvas attached again (the worker does so when its context is
    // restored, blank) is painted whole, the same frame included.
    let (mut s, canvas) = whole_frame(&program, None, 1.0);
    let ctx = context_2d(&canvas);
    ctx.clear_rect(0.0, 0.0, 400.0, 300.0);
    s.attach_canvas(canvas.clone()).expect("attach");
    s.render(400, 300, 1.0).expect("render");
    assert_eq!(
        canvas_pixels(&canvas),
        canvas_pixels(&whole_frame(&program, None, 1.0).1)
    );
}

#[wasm_bindgen_test]
fn typing_back_and_forth_across_views_paints_the_pixels_of_a_whole_frame() {
    // Issue 6, target 4b: a digit that moves the path's bounds refits the
    // view (every pixel moves); the next key brings it back, and that frame
    // is made on the pixels of the one before the last (raster::keep::Older)
    // and put on the canvas whole. Each frame is pixel for pixel a new
    // session's whole frame.
    let program = programs::numbered_program(3000);
    let wide = program.replacen("N1500 G01 X17.", "N1500 G01 X1700.", 1);
    let edited = program.replacen("N1500 G01 X17.", "N1500 G01 X17.5", 1);
    let wider = program.replacen("N1500 G01 X17.", "N1500 G01 X1750.", 1);
    for dpr in [1.0, 2.0] {
        let (mut s, canvas) = whole_frame(&program, None, dpr);
        for (k, then) in [&wide, &program, &wide, &edited, &wider, &edited]
            .into_iter()
            .enumerate()
        {
            run(&mut s, then.clone(), JsValue::NULL);
            s.render(400, 300, dpr).expect("render");
            let whole = canvas_pixels(&whole_frame(then, None, dpr).1);
            let painted = canvas_pixels(&canvas);
            let differ = painted
                .chunks_exact(4)
                .zip(whole.chunks_exact(4))
                .filter(|(a, b)| a != b)
                .count();
            assert_eq!(differ, 0, "{differ} pixels differ, frame {k} at {dpr}");
        }
    }
}

#[wasm_bindgen_test]
fn progress_calls_get_growing_fractions_and_a_throwing_one_does_not_stop_the_run() {
    // 3 MiB of program: a progress call after each MiB read.
    let program = "G01 X1. Y2. F100.\nG01 X3. Y4.\n".repeat(110_000);
    let seen = Array::new();
    let record: Function =
        JsValue::from(Function::new_with_args("a, f", "a.push(f)").bind1(&JsValue::NULL, &seen))
            .unchecked_into();
    let mut s = Session::new();
    assert!(write_program(&mut s, program.as_bytes(), program.len()));
    let with = s
        .run_buffer(program.len(), square_setup(), Some(record))
        .expect("run");
    let fractions: Vec<f64> = seen.iter().map(|v| v.as_f64().expect("a number")).collect();
    assert!(fractions.len() >= 2, "{fractions:?}");
    assert!(fractions.windows(2).all(|w| w[0] < w[1]), "{fractions:?}");
    assert!(
        fractions.iter().all(|f| *f > 0.0 && *f <= 1.0),
        "{fractions:?}"
    );
    let without = run(&mut Session::new(), &program, square_setup());
    assert_eq!(
        stringify(&get(&with, "summary")),
        stringify(&get(&without, "summary"))
    );
    // A callback that throws does not stop the run.
    let throwing: Function =
        JsValue::from(Function::new_with_args("f", "throw new Error('no')")).unchecked_into();
    assert!(write_program(&mut s, program.as_bytes(), program.len()));
    let r = s
        .run_buffer(program.len(), square_setup(), Some(throwing))
        .expect("run");
    assert_eq!(num(&get(&r, "summary"), "blocks"), 220_000.0);
}

#[wasm_bindgen_test]
fn the_program_buffer_is_wasm_memory_at_the_address_returned() {
    // The rules (lengths, edits, U+FFFD, what is kept): tests/session.rs.
    // Beyond ASCII: the columns count characters.
    let program = "(Fräsen — 2 µm)\nG01 X1. Y2. F100.\n(ß) G01 X1.2.3\n";
    let mut s = Session::new();
    assert!(write_program(&mut s, program.as_bytes(), program.len()));
    let r = s
        .run_buffer(program.len(), square_setup(), None)
        .expect("run");
    assert_eq!(num(&get(&r, "summary"), "blocks"), 1.0);
    let diagnostics = array(&get(&r, "diagnostics"));
    assert_eq!(num(&diagnostics.get(0), "column"), 9.0);

    // "X10." becomes "X12.5", as the page's worker makes a typed edit.
    let program = "G00 X0 Y0\nG01 X10. F100.\nG01 Y10.\n";
    assert!(write_program(&mut s, program.as_bytes(), program.len()));
    s.run_buffer(program.len(), JsValue::NULL, None)
        .expect("run");
    let at = s.program_splice(program.len(), 15, 18, 4);
    assert!(!at.is_null());
    write_at(at, b"12.5");
    let edited = "G00 X0 Y0\nG01 X12.5 F100.\nG01 Y10.\n";
    let r = s
        .run_buffer(edited.len(), JsValue::NULL, None)
        .expect("run");
    let mut t = Session::new();
    let tr = run(&mut t, edited, JsValue::NULL);
    assert_eq!(stringify(&r), stringify(&tr));
    assert_eq!(
        stringify(&s.block(2).expect("block")),
        stringify(&t.block(2).expect("block"))
    );
    // Not the length of the text held: 0, and the buffer is empty (the
    // worker then writes the whole text).
    assert!(s.program_splice(edited.len() + 1, 0, 0, 0).is_null());
    let r = s
        .run_buffer(edited.len(), JsValue::NULL, None)
        .expect("run");
    assert_eq!(num(&get(&r, "summary"), "blocks"), 0.0);
    // No room: 0, and nothing to run.
    assert!(
        s.program_buffer(u32::MAX as usize).is_null(),
        "more than wasm32 can hold"
    );
    let r = s.run_buffer(100, JsValue::NULL, None).expect("run");
    assert_eq!(num(&get(&r, "summary"), "blocks"), 0.0);
}
