//! The page's session, natively (`offsetlab::session`): which run it makes
//! (an edit run again from the last run equals a whole run), the current
//! block (clamped, following the end), the view state and its ranges,
//! picking and the block of a line, whether a frame asked for is the one
//! the canvas shows, the program buffer and its edits (the length check,
//! ranges, invalid UTF-8, programs too large to keep), the document of the
//! current state and the exports. `tests/wasm/` pins what only a browser
//! shows: the JS shape of each export and the canvas pixels.

mod common;
use common::programs;
use common::session::{SQUARE, SQUARE_SETUP, block, draw, run, square, view_change};
use offsetlab::render::svg::SvgSurface;
use offsetlab::session::program::{KEPT_PROGRAM, ProgramBuffer};
use offsetlab::session::view::ViewChange;
use offsetlab::session::{Session, read_setup};
use offsetlab::{Document, MachineKind, Toolpath, render};
use serde_json::{Value, json};

#[test]
fn the_square_runs_with_its_summary_and_toolpath() {
    let mut s = Session::new();
    let result = run(&mut s, SQUARE, Some(SQUARE_SETUP));
    let summary = &result["summary"];
    assert_eq!(summary["machine"], "mill");
    assert_eq!(summary["units"], "mm");
    assert_eq!(summary["blocks"], 8);
    assert_eq!(summary["errors"], 0);
    assert_eq!(summary["end"]["reason"], "program_end");
    assert_eq!(summary["end"]["line"], 9);
    assert_eq!(summary["bounds"]["min"]["x"], -30.0);
    assert_eq!(summary["bounds"]["max"]["y"], 56.0);
    assert_eq!(result["diagnostics"], json!([]));
    assert_eq!(s.block_count(), 8);
    // Seed 000 makes seven moves: rapid, rapid, four feeds, the rapid home.
    let t = s.toolpath();
    assert_eq!(t.len(), 7, "seed 000 makes seven moves");
    assert_eq!(t.kinds, vec![0, 0, 1, 1, 1, 1, 0]);
    assert_eq!(t.blocks.len(), 7);
    assert_eq!(t.lines.len(), 7);
    assert_eq!(t.lines[2], 4);
    assert_eq!(t.actual.len(), t.programmed.len());
    // The second move ends at the actual point (-6, -6), the programmed
    // one at the origin.
    let [[_, actual], [_, programmed]] = t.ends(1).unwrap();
    assert_eq!(actual, [-6.0, -6.0, 0.0]);
    assert_eq!(programmed, [0.0, 0.0, 0.0]);
    // Block 1 is line 3 (seed 000); out of range: none.
    assert_eq!(block(&s, 1)["text"], "G91 G00 G46 X30. Y20. D01");
    assert_eq!(block(&s, 2)["feed"], 200.0);
    assert!(s.block(8).is_none() && s.block(u32::MAX).is_none());
}

#[test]
fn a_refused_setup_runs_nothing_and_says_why() {
    for setup in [
        Some(r#"{"machine":"drill"}"#),
        Some(r#"{"offsets":{"01":5000}}"#),
        Some(r#"{"no_such_field":1}"#),
        Some("{ not json"),
        None,
    ] {
        let mut s = Session::new();
        let answer = s.run(SQUARE.into(), read_setup(Some(setup)), |_| ());
        assert!(!answer.diagnostics.is_empty(), "{setup:?}");
        for d in answer.diagnostics {
            assert!(d.code.starts_with("setup-"), "{d:?}");
            assert_eq!(d.span.line, 0);
            assert!(d.is_error());
        }
        assert!(answer.summary.bounds.is_none());
        assert!(s.toolpath().is_empty());
        assert_eq!(s.block_count(), 0);
        // The session holds the default setup, and the document carries it.
        assert_eq!(s.setup(), &offsetlab::Setup::default());
        assert_eq!(s.document().setup, offsetlab::Setup::default());
    }
}

#[test]
fn a_lathe_run_is_drawn_in_zx_with_its_own_toolpath() {
    let mut s = Session::new();
    let setup = r#"{"machine":"lathe","lathe_offsets":{"08":{"x":0.4,"z":-0.2}}}"#;
    let result = run(
        &mut s,
        "G50 X120. Z60.\nG00 S800 M03 T0108;\nX50. Z3.;\nT0100;",
        Some(setup),
    );
    assert_eq!(result["summary"]["errors"], 0);
    assert_eq!(result["summary"]["machine"], "lathe");
    assert_eq!(s.toolpath().machine, MachineKind::Lathe);
    assert_eq!(s.view().plane.as_deref(), Some("ZX"));
    let b = block(&s, 1);
    assert_eq!(b["actual"], json!({"x": 120.4, "z": 59.8}));
    assert!(s.render_svg(400, 300).contains("centre line"));
}

#[test]
fn step_is_clamped_and_follows_the_end() {
    let mut s = square();
    assert_eq!(s.step(), -1);
    assert_eq!(s.set_step(2), 2);
    assert_eq!(s.set_step(999), 7, "past the end: the last block");
    assert_eq!(s.set_step(-5), -1);
    // At the last block, a longer program keeps the session at its last block.
    s.set_step(7);
    let longer = SQUARE.replace("M30;\n", "G01 X5.;\nM30;\n");
    run(&mut s, &longer, Some(SQUARE_SETUP));
    assert_eq!(s.step(), 8);
    // Elsewhere, the step stays; past a shorter program's end it is clamped.
    s.set_step(2);
    run(&mut s, SQUARE, Some(SQUARE_SETUP));
    assert_eq!(s.step(), 2);
    run(&mut s, "G00 X1.", None);
    assert_eq!(s.step(), 0);
    // A block set by the user stays set when a run stops at an error just
    // after it (it is then the last block) and the next run mends it: the
    // current block does not jump to the program's end.
    run(&mut s, SQUARE, Some(SQUARE_SETUP));
    s.set_step(3);
    let broken = SQUARE.replacen("G47 X-80.", "G47 X-80. Q", 1);
    run(&mut s, &broken, Some(SQUARE_SETUP));
    assert_eq!(s.step(), 3);
    run(&mut s, SQUARE, Some(SQUARE_SETUP));
    assert_eq!(s.step(), 3);
    // At the end it follows the end, across a run stopped at an error too.
    s.set_step(7);
    run(&mut s, &broken, Some(SQUARE_SETUP));
    run(&mut s, &longer, Some(SQUARE_SETUP));
    assert_eq!(s.step(), 8);
}

#[test]
fn view_state_is_plane_zoom_pan_and_step() {
    let mut s = square();
    let v = s.view();
    assert_eq!(v.plane.as_deref(), Some("XY"));
    assert_eq!(v.zoom, Some(1.0));
    assert_eq!(v.pan, Some([0.0, 0.0]));
    assert_eq!(v.step, None, "no current block yet");
    // Zoom at the cursor and drag change zoom and pan; fit resets both. A
    // frame asked for without a canvas sets the size they measure by.
    s.ask_frame(800, 500, 1.0);
    s.zoom_at(200.0, 100.0, 2.0);
    s.pan_by(30.0, -10.0);
    let v = s.view();
    assert_eq!(v.zoom, Some(2.0));
    assert_ne!(v.pan, Some([0.0, 0.0]));
    s.fit();
    assert_eq!(s.view().pan, Some([0.0, 0.0]));
    // Planes: the mill has XY, XZ, YZ; ZX is the lathe's.
    assert!(s.set_plane("xz"));
    assert!(!s.set_plane("ZX"));
    assert!(!s.set_plane("QQ"));
    assert_eq!(s.view().plane.as_deref(), Some("XZ"));
    // set_view reads what view writes, and limits the values.
    let v = s.set_view(&view_change(
        r#"{"plane":"YZ","zoom":1e9,"pan":[5,-2],"step":3}"#,
    ));
    assert_eq!(v.plane.as_deref(), Some("YZ"));
    assert_eq!(v.zoom, Some(1e6));
    assert_eq!(v.pan, Some([5.0, -2.0]));
    assert_eq!(v.step, Some(3));
    assert_eq!(s.set_view(&s.view()), s.view());
    assert!(serde_json::from_str::<ViewChange>(r#"{"zoom":"big"}"#).is_err());
    // Absent keys stay; step -1 clears the current block.
    let v = s.set_view(&view_change(r#"{"step":-1}"#));
    assert_eq!(
        (v.plane.as_deref(), v.zoom, v.step),
        (Some("YZ"), Some(1e6), None)
    );
    // A lathe run is drawn in ZX.
    run(&mut s, "G50 X120. Z60.\nG00 X50. Z3.", None);
    run(
        &mut s,
        "G50 X120. Z60.\nG00 X50. Z3.",
        Some(r#"{"machine":"lathe"}"#),
    );
    assert_eq!(s.view().plane.as_deref(), Some("ZX"));
}

#[test]
fn behaviour14_16_the_lathe_has_the_face_view_xc_beside_zx() {
    // A face contour in polar coordinate interpolation: the lathe is drawn
    // in ZX first, and its face view XC can be chosen; the mill's planes
    // cannot, nor XC on the mill.
    let program = "G98 G00 X40. Z2.\nG01 Z-1. F100.\nG12.1\nG01 X20. C-10.\nC10.\nX-20.\nC-10.\nX20.\nG13.1\n";
    let mut s = Session::new();
    run(&mut s, program, Some(r#"{"machine":"lathe"}"#));
    assert_eq!(s.view().plane.as_deref(), Some("ZX"));
    assert!(s.set_plane("xc"));
    assert_eq!(s.view().plane.as_deref(), Some("XC"));
    assert!(!s.set_plane("XY"));
    assert_eq!(s.view().plane.as_deref(), Some("XC"));
    assert!(s.set_plane("ZX") && s.set_plane("XC"));
    // An edit keeps the face view; the document carries it, and a link
    // made of it reads back the same.
    run(
        &mut s,
        &program.replace("C10.", "C12."),
        Some(r#"{"machine":"lathe"}"#),
    );
    assert_eq!(s.view().plane.as_deref(), Some("XC"));
    let d = s.document();
    assert_eq!(d.view.map(|v| v.plane.as_str()), Some("XC"));
    assert_eq!(Document::from_json(&d.to_json()).unwrap(), d);
    let link = offsetlab::share::link("http://127.0.0.1:8000/", &d, false).unwrap();
    assert_eq!(offsetlab::share::decode(&link).unwrap().document, d);
    // The frame drawn in XC is the face: the square's corners ±10 on both
    // axes fit the view with the spindle axis at the origin.
    assert!(draw(&mut s, 600, 600, 1.0));
    let svg = s.render_svg(600, 600);
    assert!(svg.contains("lathe · XC · mm"), "{svg}");
    // A mill run goes back to its own first plane; XC is not the mill's.
    run(&mut s, SQUARE, Some(SQUARE_SETUP));
    assert_eq!(s.view().plane.as_deref(), Some("XY"));
    assert!(!s.set_plane("XC"));
}

#[test]
fn block_at_line_is_the_last_block_at_or_before_the_line() {
    let s = square();
    // Line 1 is a comment before any block.
    assert_eq!(s.block_at_line(1), -1);
    assert_eq!(s.block_at_line(2), 0);
    assert_eq!(s.block_at_line(3), 1);
    assert_eq!(s.block_at_line(9), 7);
    assert_eq!(s.block_at_line(500), 7);
    assert_eq!(s.block_at_line(0), -1);
}

#[test]
fn pick_returns_the_block_under_the_pointer() {
    let mut s = square();
    // Nothing drawn yet: -1.
    assert_eq!(s.pick(10.0, 10.0, 6.0), -1);
    assert!(draw(&mut s, 800, 500, 1.0));
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
    // Another drawing: the layout drawn no longer holds until drawn again.
    run(&mut s, "G00 X1.", None);
    assert_eq!(s.pick(400.0, 250.0, 100.0), -1);
}

#[test]
fn an_edit_is_run_again_from_the_last_run_with_the_result_of_a_whole_run() {
    let program = programs::numbered_program(3000);
    let edits = [
        program.replacen("N1500 G01 X", "N1500 G01 X1", 1),
        program.replacen("N1500 ", "N15007 ", 1),
        program.replacen("N2000 G01", "(A NOTE)\nN2000 G01", 1),
        program.replacen("N10 G01 X7.", "N10 G01 X7. Y1 E2", 1),
        program.replacen("N2", "N2 G91", 1),
    ];
    for edited in edits {
        let mut again = Session::new();
        run(&mut again, &program, None);
        let got = run(&mut again, &edited, None);
        let mut fresh = Session::new();
        let want = run(&mut fresh, &edited, None);
        assert_eq!(got, want, "{}", &edited[..60]);
        assert_eq!(again.toolpath(), fresh.toolpath(), "{}", &edited[..60]);
        assert_eq!(again.block_count(), fresh.block_count());
        for index in [0, 1499, 1500, 2999] {
            assert_eq!(block(&again, index), block(&fresh, index), "block {index}");
        }
    }
}

#[test]
fn a_frame_of_what_the_canvas_shows_is_not_drawn_again() {
    let program = programs::numbered_program(3000);
    let mut s = Session::new();
    run(&mut s, &program, None);
    assert!(draw(&mut s, 400, 300, 1.0));
    // The same view asked for again is that frame.
    assert!(!draw(&mut s, 400, 300, 1.0));
    // An N number typed: the same path, the same frame — not drawn again.
    let drawing = s.drawing();
    run(&mut s, &program.replacen("N1500 ", "N15007 ", 1), None);
    assert_eq!(s.drawing(), drawing);
    assert!(!draw(&mut s, 400, 300, 1.0));
    // A coordinate typed: the path moved, the frame is drawn again.
    run(
        &mut s,
        &program.replacen("N1500 G01 X", "N1500 G01 X1", 1),
        None,
    );
    assert_ne!(s.drawing(), drawing);
    assert!(draw(&mut s, 400, 300, 1.0));
    // Another size, pixel ratio, current block or colours: drawn again.
    assert!(draw(&mut s, 400, 301, 1.0));
    assert!(draw(&mut s, 400, 301, 2.0));
    s.set_step(10);
    assert!(draw(&mut s, 400, 301, 2.0));
    s.set_theme("dark");
    assert!(draw(&mut s, 400, 301, 2.0));
    assert!(!draw(&mut s, 400, 301, 2.0));
    // A canvas attached again shows nothing known: drawn whole.
    s.forget_frame();
    assert!(draw(&mut s, 400, 301, 2.0));
    // A frame moved in a gesture is not a whole frame.
    let ask = s.ask_frame(400, 301, 2.0);
    let frame = render::draw_scene(
        &mut SvgSurface::new(),
        s.toolpath(),
        s.scene(),
        400.0,
        301.0,
    );
    s.frame_drawn(&ask, frame, true);
    assert!(!s.frame_shown(&ask));
}

#[test]
fn a_frame_asked_for_is_clamped_to_what_a_canvas_can_be() {
    let mut s = square();
    let ask = s.ask_frame(300, 200, 2.0);
    assert_eq!(
        (ask.css, ask.device, ask.scale),
        ((300, 200), (600, 400), (2.0, 2.0))
    );
    // Odd sizes and silly ratios are clamped, never a panic.
    let ask = s.ask_frame(0, 0, f64::NAN);
    assert_eq!((ask.css, ask.device, ask.dpr), ((1, 1), (1, 1), 1.0));
    let ask = s.ask_frame(100_000, 100, 100.0);
    assert_eq!((ask.css, ask.dpr), ((8192, 100), 8.0));
    assert_eq!(ask.device, (16384, 800));
    // The key of a kept layer: the same for another zoom, not for another step.
    let key = s.ask_frame(300, 200, 1.0).key;
    s.zoom_at(10.0, 10.0, 2.0);
    assert_eq!(s.ask_frame(300, 200, 1.0).key, key);
    s.set_step(3);
    assert_ne!(s.ask_frame(300, 200, 1.0).key, key);
}

/// Everything the page reads of a run: its answer, the toolpath and the
/// last block's report.
fn seen(s: &Session, answer: Value) -> (Value, Toolpath, Value) {
    let last = block(s, s.block_count().saturating_sub(1));
    (answer, s.toolpath().clone(), last)
}

/// Writes `bytes` at the start of the session's program buffer of `room`
/// bytes, as the page's worker does; false when the session had no room.
fn write_program(s: &mut Session, bytes: &[u8], room: usize) -> bool {
    match s.program_buffer(room) {
        Some(buffer) => {
            buffer[..bytes.len()].copy_from_slice(bytes);
            true
        }
        None => false,
    }
}

fn run_buffer(s: &mut Session, length: usize, setup: Option<&str>) -> Value {
    let answer = s.run_buffer(length, read_setup(setup.map(Some)), |_| ());
    serde_json::to_value(answer).unwrap()
}

#[test]
fn a_program_written_into_the_buffer_runs_as_its_text_does() {
    // 2.6 MiB, beyond ASCII: the toolpath's room is foreseen after the
    // first MiB (PathBuilder::foresee), the columns count characters.
    let program = format!(
        "(Fräsen — 2 µm)\n{}(ß) G01 X1.2.3\n",
        "G01 X1. Y2. F100.\nG02 X3. Y4. R5.\n".repeat(80_000)
    );
    let mut by_text = Session::new();
    let text_result = run(&mut by_text, &program, Some(SQUARE_SETUP));
    let mut by_buffer = Session::new();
    assert!(write_program(
        &mut by_buffer,
        program.as_bytes(),
        program.len()
    ));
    let buffer_result = run_buffer(&mut by_buffer, program.len(), Some(SQUARE_SETUP));
    assert_eq!(buffer_result["diagnostics"][0]["column"], 9);
    assert_eq!(seen(&by_buffer, buffer_result), seen(&by_text, text_result));

    // Invalid UTF-8 reads as U+FFFD, as the page's decoder shows it.
    let mut s = Session::new();
    let bytes = b"G00 X1.\n(\xff\xfe)\nG01 X2. F1. Y\xc3\n";
    assert!(write_program(&mut s, bytes, bytes.len()));
    let r = run_buffer(&mut s, bytes.len(), None);
    let mut t = Session::new();
    let tr = run(&mut t, &String::from_utf8_lossy(bytes), None);
    assert_eq!(seen(&s, r), seen(&t, tr));
    assert!(s.text().contains('\u{fffd}'));

    // A length past the room runs what the room holds; no room, nothing.
    assert!(write_program(&mut s, b"G00 X7.", 7));
    let r = run_buffer(&mut s, 1 << 20, None);
    assert_eq!(r["summary"]["moves"], 1);
    assert!(s.program_buffer(usize::MAX).is_none(), "more than memory");
    let r = run_buffer(&mut s, 100, None);
    assert_eq!(r["summary"]["blocks"], 0);
}

#[test]
fn an_edit_made_in_the_buffer_runs_as_the_edited_text_does() {
    let program = "G00 X0 Y0\nG01 X10. F100.\nG01 Y10.\n";
    let mut s = Session::new();
    assert!(write_program(&mut s, program.as_bytes(), program.len()));
    run_buffer(&mut s, program.len(), None);
    // "X10." becomes "X12.5", as the page's worker makes a typed edit.
    let (from, to) = (15, 18);
    let inserted = s.program_splice(program.len(), from, to, 4).unwrap();
    inserted.copy_from_slice(b"12.5");
    let edited = "G00 X0 Y0\nG01 X12.5 F100.\nG01 Y10.\n";
    let r = run_buffer(&mut s, edited.len(), None);
    let mut t = Session::new();
    let tr = run(&mut t, edited, None);
    assert_eq!(seen(&s, r), seen(&t, tr));
    // And again, on the text just run (a line added at the end).
    let inserted = s
        .program_splice(edited.len(), edited.len(), edited.len(), 9)
        .unwrap();
    inserted.copy_from_slice(b"G00 Z5.\n\n");
    let again = format!("{edited}G00 Z5.\n\n");
    let r = run_buffer(&mut s, again.len(), None);
    let tr = run(&mut t, &again, None);
    assert_eq!(seen(&s, r), seen(&t, tr));
    // Not the length of the text held, or not within it: refused, and the
    // buffer is empty (the worker then writes the whole text).
    assert!(s.program_splice(again.len() + 1, 0, 0, 0).is_none());
    assert!(s.program_splice(0, 0, 1, 0).is_none());
    let r = run_buffer(&mut s, again.len(), None);
    assert_eq!(r["summary"]["blocks"], 0);
    // A range past the end, or backwards: refused too.
    let mut b = ProgramBuffer::default();
    b.room(4).unwrap().copy_from_slice(b"G00;");
    b.take(4);
    assert!(b.splice(4, 3, 5, 1).is_none() && b.is_empty());
    b.room(4).unwrap().copy_from_slice(b"G00;");
    b.take(4);
    assert!(b.splice(4, 3, 2, 1).is_none() && b.is_empty());
}

#[test]
fn programs_over_kept_program_are_not_kept_for_an_edit() {
    let mut b = ProgramBuffer::default();
    b.room(KEPT_PROGRAM).unwrap().fill(b';');
    assert_eq!(b.take(KEPT_PROGRAM).len(), KEPT_PROGRAM);
    assert_eq!(b.len(), KEPT_PROGRAM, "kept");
    assert!(b.splice(KEPT_PROGRAM, 0, 1, 1).is_some());
    b.room(KEPT_PROGRAM + 1).unwrap().fill(b';');
    assert_eq!(b.take(KEPT_PROGRAM + 1).len(), KEPT_PROGRAM + 1);
    assert!(b.is_empty(), "not held twice");
    assert!(b.splice(KEPT_PROGRAM + 1, 0, 0, 0).is_none());
}

#[test]
fn document_is_program_setup_view_and_step() {
    let mut s = square();
    // The machine's default view and no current block: none.
    let d = s.document();
    assert_eq!(d.program, SQUARE);
    assert_eq!(d.setup.mill_value(1), 6.0);
    assert!(d.view.is_none() && d.step.is_none());
    // Another plane, a zoom and a current block are carried; the zoom is
    // rounded to six significant digits, the pan to 1e-4.
    s.set_view(&view_change(
        r#"{"plane":"XZ","zoom":1.23456789,"pan":[0.123456,-2],"step":3}"#,
    ));
    let d = s.document();
    let view = d.view.unwrap();
    assert_eq!(view.plane.as_str(), "XZ");
    assert_eq!(view.zoom, 1.23457);
    assert_eq!(view.pan, [0.1235, -2.0]);
    assert_eq!(d.step, Some(3));
    // The document reads back as itself.
    assert_eq!(Document::from_json(&d.to_json()).unwrap(), d);
}

#[test]
fn moves_export_as_the_cli_json_and_csv() {
    let mut s = square();
    let file: Value = serde_json::from_str(&s.moves_json()).unwrap();
    let moves = file["moves"].as_array().unwrap();
    assert_eq!(moves.len(), 7);
    assert_eq!(file["summary"]["machine"], "mill");
    assert_eq!(moves[1]["to"], json!({"x": -6.0, "y": -6.0, "z": 0.0}));
    assert_eq!(moves[1]["programmed_to"]["x"], 0.0);
    let csv = s.moves_csv();
    let lines: Vec<&str> = csv.split("\r\n").filter(|l| !l.is_empty()).collect();
    assert_eq!(lines.len(), 8);
    assert!(lines[0].starts_with("line,block,kind,rate,from_x,from_y,from_z,to_x"));
    assert!(
        lines[2].starts_with("3,1,rapid,,-30,-20,0,-6,-6,0,"),
        "{}",
        lines[2]
    );
    // After a refused setup nothing ran: the exports have no moves (and the
    // program is not run again with some other setup).
    run(&mut s, SQUARE, Some("{\"version\": 99}"));
    let file: Value = serde_json::from_str(&s.moves_json()).unwrap();
    assert_eq!(file["moves"].as_array().map(Vec::len), Some(0));
    assert_eq!(
        s.moves_csv()
            .split("\r\n")
            .filter(|l| !l.is_empty())
            .count(),
        1
    );
}

#[test]
fn a_long_run_reports_growing_fractions_and_the_same_result() {
    // 3 MiB of program: a progress call after each MiB read.
    let program = "G01 X1. Y2. F100.\nG01 X3. Y4.\n".repeat(110_000);
    let mut fractions = Vec::new();
    let mut s = Session::new();
    let with = s.run(program.clone(), read_setup(Some(Some(SQUARE_SETUP))), |f| {
        fractions.push(f)
    });
    let with = serde_json::to_value(with).unwrap();
    assert!(fractions.len() >= 2, "{fractions:?}");
    assert!(fractions.windows(2).all(|w| w[0] < w[1]), "{fractions:?}");
    assert!(
        fractions.iter().all(|f| *f > 0.0 && *f <= 1.0),
        "{fractions:?}"
    );
    let without = run(&mut Session::new(), &program, Some(SQUARE_SETUP));
    assert_eq!(with["summary"], without["summary"]);
    assert_eq!(with["summary"]["blocks"], 220_000);
}
