//! What the fuzz targets check, shared with `tests/fuzz_regressions.rs`
//! (through `#[path]`) so that a crash input replays exactly as the fuzzer
//! ran it.
//!
//! The `run` target reads a setup from the first [`HEADER`] bytes of its
//! input (machine, units, every setting, table size, peck retract, start
//! point, a G55 offset and four registers within ±999.999) and runs the rest
//! as the program. Inputs shorter than the header are padded with zeros.
#![allow(dead_code)]

pub mod macro_gen;

use offsetlab::Move;
use offsetlab::document::{ViewPlane, ViewState};
use offsetlab::geometry::Xyz;
use offsetlab::machine::BlockState;
use offsetlab::setup::{
    DecimalInput, LatheRegister, LatheXOffset, LengthOffsetWithoutZ, MillRegister, Position,
};
use offsetlab::toolpath::{ArcPoints, PathBuilder};
use offsetlab::view::RunView;
use offsetlab::{
    Document, MachineKind, ParseOptions, RunOptions, Setup, Toolpath, Units, parse, run_with, share,
};

/// Bytes of the setup header of a `run` input.
pub const HEADER: usize = 44;

/// Moves one fuzz run may record: far below the default limit so that a
/// run stays fast, and still reached by repeated cycles.
pub const FUZZ_MAX_MOVES: usize = 10_000;

fn byte(h: &[u8], i: usize) -> u8 {
    h.get(i).copied().unwrap_or(0)
}

fn i16_at(h: &[u8], i: usize) -> i16 {
    i16::from_le_bytes([byte(h, i), byte(h, i + 1)])
}

/// A register value within ±999.999 from three bytes.
fn value_at(h: &[u8], i: usize) -> f64 {
    let raw = i32::from_le_bytes([byte(h, i), byte(h, i + 1), byte(h, i + 2), 0]);
    let signed = raw - (1 << 23);
    f64::from(signed % 1_000_000) / 1000.0
}

/// The setup the first [`HEADER`] bytes describe. Always valid.
pub fn setup_from(h: &[u8]) -> Setup {
    let flags = byte(h, 0);
    let more = byte(h, 1);
    let mut s = Setup {
        machine: if flags & 1 == 0 {
            MachineKind::Mill
        } else {
            MachineKind::Lathe
        },
        units: if flags & 2 == 0 {
            Units::Mm
        } else {
            Units::Inch
        },
        ..Setup::default()
    };
    s.settings.decimal_input = if flags & 4 == 0 {
        Some(DecimalInput::Increment)
    } else {
        Some(DecimalInput::Calculator)
    };
    s.settings.block_skip = flags & 8 != 0;
    s.settings.length_offset_without_z = if flags & 16 == 0 {
        Some(LengthOffsetWithoutZ::Move)
    } else {
        Some(LengthOffsetWithoutZ::NextZ)
    };
    s.settings.lathe_x_offset = if flags & 32 == 0 {
        LatheXOffset::Diameter
    } else {
        LatheXOffset::Radius
    };
    if s.machine == MachineKind::Mill {
        s.settings.mirror.x = flags & 64 != 0;
        s.settings.mirror.y = flags & 128 != 0;
    }
    s.table_size = match more & 3 {
        0 => 99,
        1 => 9,
        2 => 999,
        _ => 1 + u16::from(byte(h, 2)),
    };
    if more & 4 != 0 {
        s.settings.peck_retract = Some(f64::from(byte(h, 3)) / 50.0);
    }
    let max = s.units.max_dimension();
    // Start point and G55 within a tenth of the dimension range.
    let pos = |i: usize| -> Position {
        let k = max / 10.0 / f64::from(i16::MAX);
        Position {
            x: f64::from(i16_at(h, i)) * k,
            y: f64::from(i16_at(h, i + 2)) * k,
            z: f64::from(i16_at(h, i + 4)) * k,
        }
    };
    if more & 8 != 0 {
        s.start = pos(4);
    }
    if more & 16 != 0 {
        s.work_offsets.g55 = pos(10);
    }
    if s.machine == MachineKind::Lathe {
        s.start.y = 0.0;
    }
    // Four registers of seven bytes: number, geometry (mill) or X (lathe),
    // and Z (lathe); the wear is a hundredth of the value, negated.
    for r in 0..4 {
        let at = 16 + r * 7;
        let n = u16::from(byte(h, at)) % (s.table_size + 1);
        if n == 0 {
            continue;
        }
        let v = value_at(h, at + 1);
        let z = value_at(h, at + 4);
        let wear = more & 32 != 0;
        match s.machine {
            MachineKind::Mill => {
                let wear = if wear { -v / 100.0 } else { 0.0 };
                s.offsets.insert(n, MillRegister::new(v, wear));
            }
            MachineKind::Lathe => {
                s.lathe_offsets.insert(
                    n,
                    LatheRegister {
                        x: v,
                        z,
                        x_wear: if wear { -v / 100.0 } else { 0.0 },
                        z_wear: if wear { -z / 100.0 } else { 0.0 },
                        ..LatheRegister::default()
                    },
                );
            }
        }
    }
    s
}

/// The setup and the program of a `run` input.
pub fn split(data: &[u8]) -> (Setup, String) {
    let (h, rest) = data.split_at(data.len().min(HEADER));
    (setup_from(h), String::from_utf8_lossy(rest).into_owned())
}

/// `parse` target: every setting that changes parsing, on any text.
pub fn check_parse(data: &[u8]) {
    let text = String::from_utf8_lossy(data);
    let flags = data.first().copied().unwrap_or(0);
    let setup = setup_from(&[flags]);
    let program = parse(&text, &ParseOptions::from(&setup));
    check_diagnostics(&program.diagnostics, &text);
    for b in &program.blocks {
        assert!(b.span.line >= 1, "block on line 0");
        assert!(b.span.start <= b.span.end, "block span backwards");
        assert!(b.span.end as usize <= text.len(), "block span past the end");
        for w in &b.words {
            assert!(w.value.is_finite(), "word value {}", w.value);
            assert!(w.span.start >= b.span.start && w.span.end <= b.span.end);
        }
    }
}

/// `run` target: setup from the header, the rest as the program.
pub fn check_run(data: &[u8]) {
    let (setup, program) = split(data);
    check_run_with(&setup, &program, FUZZ_MAX_MOVES);
}

/// Blocks one `macros` run may execute: a loop that never ends stops here
/// with `too-many-blocks`, as at the default limit, in a fraction of it.
pub const FUZZ_MAX_BLOCKS: usize = 20_000;

/// `macros` target: setup from the header, the rest read as choices of the
/// macro grammar ([`macro_gen::program_from`]).
pub fn check_macros(data: &[u8]) {
    check_macros_bounded(data, FUZZ_MAX_BLOCKS);
}

/// [`check_macros`] with a block limit of its own (the property test's is
/// smaller: it runs unoptimised).
pub fn check_macros_bounded(data: &[u8], max_blocks: usize) {
    let (h, rest) = data.split_at(data.len().min(HEADER));
    let program = macro_gen::program_from(rest);
    check_run_bounded(&setup_from(h), &program, FUZZ_MAX_MOVES, max_blocks);
}

/// Runs `program` with and without per-block reports and checks what a
/// page relies on.
pub fn check_run_with(setup: &Setup, program: &str, max_moves: usize) {
    check_run_bounded(setup, program, max_moves, offsetlab::MAX_BLOCKS);
}

/// [`check_run_with`] with a block limit too (a macro loop that does not
/// end stops at it: `macros` target).
pub fn check_run_bounded(setup: &Setup, program: &str, max_moves: usize, max_blocks: usize) {
    let full = run_with(
        program,
        setup,
        RunOptions {
            max_moves,
            max_blocks,
            ..RunOptions::default()
        },
    );
    check_diagnostics(&full.diagnostics, program);
    for m in &full.moves {
        check_move(m);
    }
    for b in &full.blocks {
        check_state(&b.state);
        assert!(b.span.line >= 1);
    }
    if let Some(b) = full.bounds {
        assert!(finite(&b.min) && finite(&b.max), "bounds {b:?}");
    }
    for e in &full.events {
        assert!(e.line >= 1);
        if let offsetlab::machine::EventKind::Dwell { seconds } = e.kind {
            assert!(seconds.is_finite() && seconds >= 0.0, "dwell {seconds}");
        }
    }
    assert_eq!(full.moves.len(), full.move_count);
    assert_eq!(full.blocks.len(), full.block_count as usize);

    let path = Toolpath::from_run(&full);
    assert_eq!(path.actual.len(), path.programmed.len());
    assert_eq!(path.actual.len() % 3, 0);
    assert!(path.actual.iter().all(|v| v.is_finite()), "NaN in actual");
    assert!(
        path.programmed.iter().all(|v| v.is_finite()),
        "NaN in programmed"
    );
    assert_eq!(path.len(), full.moves.len());
    assert_eq!(path.starts.len(), full.moves.len());
    assert_eq!(path.blocks.len(), path.len());
    assert_eq!(path.lines.len(), path.len());
    assert!(
        path.starts.windows(2).all(|w| w[0] < w[1]),
        "moves in order"
    );
    assert!(
        path.starts
            .iter()
            .all(|&s| (s as usize) + 1 < path.vertex_count() + 1)
    );
    assert_eq!(
        path.arcs.len(),
        full.moves.iter().filter(|m| m.arc.is_some()).count()
    );
    if let Some((min, max)) = path.bounds() {
        assert!(
            finite(&min) && finite(&max),
            "toolpath bounds {min:?} {max:?}"
        );
    }
    // Arcs tessellated at a coarse and a fine tolerance give finite points,
    // placed either way.
    for tolerance in [1.0, 0.001] {
        for arcs in [ArcPoints::Exact, ArcPoints::Rotated] {
            path.for_each_point(
                0..path.len(),
                false,
                (tolerance, arcs),
                |_| true,
                |_, _, p| {
                    assert!(finite(&p), "tessellated point {p:?}");
                },
            );
        }
    }
    // At the chord tolerance of the vector outputs, both paths: every move
    // has its two ends at least, every point finite.
    if full.moves.len() <= 2_000 {
        assert_eq!(path.actual.len(), path.programmed.len());
        for programmed in [false, true] {
            let mut points = vec![0usize; path.len()];
            path.for_each_point(
                0..path.len(),
                programmed,
                (offsetlab::toolpath::CHORD_TOLERANCE, ArcPoints::Exact),
                |_| true,
                |m, _, p| {
                    assert!(finite(&p), "NaN in a tessellated move: {p:?}");
                    points[m] += 1;
                },
            );
            assert!(points.iter().all(|&n| n >= 2), "empty move");
        }
    }

    // The page's way: checkpoints, reports made again equal the kept ones.
    if full.block_count <= 300 {
        let (light, checkpoints) = offsetlab::run_observed(
            program,
            setup,
            RunOptions {
                keep_blocks: false,
                checkpoint_every: 7,
                max_moves,
                max_blocks,
                ..RunOptions::default()
            },
            &mut (),
        );
        assert_eq!(light.block_count, full.block_count);
        for b in &full.blocks {
            let again = offsetlab::report_at(program, setup, &checkpoints, b.index);
            assert_eq!(again.as_ref(), Some(b), "block {} made again", b.index);
        }
        check_runs_made_again(setup, program, max_moves, max_blocks);
    }

    // The JSON the CLI prints (and the page's block view) is valid JSON.
    let json = serde_json::to_string(&RunView {
        run: &full,
        text: program,
    })
    .expect("the run serialises");
    let value: serde_json::Value = serde_json::from_str(&json).expect("valid JSON");
    assert!(value.is_object());

    // `check` (no block reports, no moves) reports the same.
    let fast = run_with(
        program,
        setup,
        RunOptions {
            keep_blocks: false,
            keep_moves: false,
            max_moves,
            max_blocks,
            ..RunOptions::default()
        },
    );
    assert_eq!(fast.diagnostics, full.diagnostics);
    assert_eq!(fast.end, full.end);
    assert_eq!(fast.block_count, full.block_count);
    assert_eq!(fast.move_count, full.move_count);
    assert_eq!(fast.bounds, full.bounds);

    // The CLI's run on two threads is the one-thread run, field for field
    // (near the diagnostics cap it is not made: None).
    for (one, options) in [
        (
            &full,
            RunOptions {
                max_moves,
                max_blocks,
                ..RunOptions::default()
            },
        ),
        (
            &fast,
            RunOptions {
                keep_blocks: false,
                keep_moves: false,
                max_moves,
                max_blocks,
                ..RunOptions::default()
            },
        ),
    ] {
        if let Some(two) = offsetlab::run_on_two_threads(program, setup, options) {
            assert_eq!(&two, one, "the run on two threads");
        } else {
            // A program that jumps (a subprogram call, a macro GOTO or
            // loop) runs on one thread (behaviour 19.9, 20.15).
            assert!(
                one.diagnostics.len() >= offsetlab::syntax::MAX_DIAGNOSTICS
                    || one.end == offsetlab::End::Error { line: 0 }
                    || jumps(program, setup, max_moves, max_blocks)
                    // A jump asked for and refused (END without DO, GOTO
                    // to no block): the one thread finds the alarm.
                    || one.diagnostics.iter().any(|d| {
                        matches!(
                            d.code,
                            "macro-loop-number" | "macro-sequence-number" | "macro-missing-end"
                        )
                    })
            );
        }
    }
}

fn finite(p: &Xyz) -> bool {
    p.iter().all(|v| v.is_finite())
}

fn check_move(m: &Move) {
    assert!(
        finite(&m.from) && finite(&m.to) && finite(&m.programmed_from) && finite(&m.programmed_to),
        "{m:?}"
    );
    assert!(m.line >= 1);
    if let Some(a) = &m.arc {
        let all = [
            a.radius,
            a.programmed_radius,
            a.sweep,
            a.programmed_sweep,
            a.start_angle,
            a.programmed_start_angle,
        ];
        assert!(
            all.iter().all(|v| v.is_finite()) && finite(&a.center) && finite(&a.programmed_center),
            "{a:?}"
        );
        assert!(a.radius > 0.0 && a.programmed_radius > 0.0, "{a:?}");
    }
}

fn check_state(s: &BlockState) {
    assert!(finite(&s.programmed) && finite(&s.actual), "{s:?}");
    assert!(
        s.length.value.is_finite() && s.length.vector.is_finite() && s.length.target.is_finite()
    );
    assert!(s.position.value.is_finite() && finite(&s.position.vector));
    assert!(finite(&s.lathe.vector) && finite(&s.lathe.target));
    assert!(s.feed.is_none_or(f64::is_finite) && s.spindle.is_none_or(f64::is_finite));
}

/// Every diagnostic has a place: line ≥ 1 with column ≥ 1, or line 0 for
/// problems of the setup or of the program as a whole.
pub fn check_diagnostics(diagnostics: &[offsetlab::Diagnostic], text: &str) {
    let lines = 1 + text
        .as_bytes()
        .iter()
        .enumerate()
        .filter(|&(i, &b)| b == b'\n' || (b == b'\r' && text.as_bytes().get(i + 1) != Some(&b'\n')))
        .count();
    for d in diagnostics {
        assert!(!d.message.is_empty(), "{d:?}");
        if d.line == 0 {
            assert!(
                d.code.starts_with("setup-") || d.code == "program-too-large",
                "line 0: {d:?}"
            );
        } else {
            assert!(d.column >= 1 && d.end_column >= d.column, "{d:?}");
            assert!(
                d.line as usize <= lines,
                "line {} of {lines}: {d:?}",
                d.line
            );
        }
    }
}

/// `link` target: decoding never panics; a decoded document is valid and
/// survives encoding and decoding again; a document built from the bytes
/// survives both link forms.
pub fn check_link(data: &[u8]) {
    let text = String::from_utf8_lossy(data);
    if let Ok(link) = share::decode(&text) {
        let doc = link.document;
        assert!(
            doc.clone().validated().is_ok(),
            "decoded an invalid document"
        );
        let again = share::decode(&share::encode(&doc)).expect("re-encoded link decodes");
        assert_eq!(again.document, doc);
    }
    round_trip(data);
}

/// decode(encode(doc)) == doc for a document made from the bytes: the setup
/// of [`setup_from`], the rest as the program, a view and a step.
pub fn round_trip(data: &[u8]) {
    let (setup, program) = split(data);
    let flags = data.get(2).copied().unwrap_or(0);
    let mut doc = Document::new(setup, program);
    if flags & 1 != 0 {
        doc.view = Some(ViewState {
            plane: [ViewPlane::XY, ViewPlane::XZ, ViewPlane::YZ, ViewPlane::ZX]
                [usize::from(flags >> 1) % 4],
            zoom: 1.0 + f64::from(data.get(3).copied().unwrap_or(0)) / 16.0,
            pan: [
                f64::from(i16_at(data, 4)) / 8.0,
                f64::from(i16_at(data, 6)) / 8.0,
            ],
            // The 3D view's angles (behaviour 10.9) for some: yaw 0–255°,
            // pitch −90…90°.
            angles: (flags & 128 != 0).then(|| {
                let byte = |i: usize| f64::from(data.get(i).copied().unwrap_or(0));
                [byte(8), byte(9) * 180.0 / 255.0 - 90.0]
            }),
            swept: flags & 32 != 0,
            legend: flags & 64 == 0,
        });
    }
    if flags & 8 != 0 {
        doc.step = Some(u32::from(data.get(8).copied().unwrap_or(0)));
    }
    let compact = share::decode(&share::encode(&doc)).expect("compact link decodes");
    assert_eq!(compact.document, doc, "compact round trip");
    // The plain form carries what a person writes by hand: not the table
    // size, the peck retract or the work offsets.
    let s = &doc.setup;
    if s.table_size == 99
        && s.settings.peck_retract.is_none()
        && s.work_offsets == Default::default()
    {
        let plain = share::decode(&share::encode_plain(&doc, flags & 16 != 0));
        let plain = plain.expect("plain link decodes");
        assert_eq!(plain.document, doc, "plain round trip");
        assert_eq!(plain.embed, flags & 16 != 0);
    }
}

/// The page's way after an edit: the program run again from a run of it
/// with a line taken out (and the other way round) equals a whole run of
/// it — diagnostics, totals, lines, events and toolpath
/// (`offsetlab::rerun_observed`).
fn check_runs_made_again(setup: &Setup, program: &str, max_moves: usize, max_blocks: usize) {
    let options = RunOptions {
        keep_blocks: false,
        keep_moves: false,
        checkpoint_every: 3,
        max_moves,
        max_blocks,
    };
    type PageRun = (offsetlab::Run, offsetlab::Checkpoints, Toolpath);
    let page_run = |text: &str, earlier: Option<(&str, &PageRun)>| {
        let mut b = PathBuilder::new(setup.machine, setup.units, earlier.map(|(_, e)| &e.2));
        let earlier = earlier.map(|(text, e)| offsetlab::Earlier {
            text,
            run: &e.0,
            checkpoints: &e.1,
        });
        let (run, checkpoints, reuse) =
            offsetlab::rerun_observed(text, setup, options, earlier, &mut b);
        let path = b.finish(&run, &reuse);
        (run, checkpoints, path)
    };
    // The middle line out: an edit that moves everything after it.
    let lines: Vec<&str> = program.split_inclusive('\n').collect();
    let cut: String = lines
        .iter()
        .enumerate()
        .filter(|&(i, _)| i != lines.len() / 2)
        .map(|(_, l)| *l)
        .collect();
    for (from, to) in [(cut.as_str(), program), (program, cut.as_str())] {
        let earlier = page_run(from, None);
        let (got, got_checkpoints, got_path) = page_run(to, Some((from, &earlier)));
        let (want, want_checkpoints, want_path) = page_run(to, None);
        assert_eq!(got.diagnostics, want.diagnostics, "diagnostics run again");
        assert_eq!(
            (got.block_count, got.move_count, &got.end, &got.registers),
            (
                want.block_count,
                want.move_count,
                &want.end,
                &want.registers
            ),
            "totals run again"
        );
        assert_eq!(
            (&got_checkpoints.lines, &got.events),
            (&want_checkpoints.lines, &want.events),
            "lines run again"
        );
        assert_eq!(got.bounds, want.bounds, "bounds run again");
        assert_eq!(got_path, want_path, "toolpath run again");
    }
}

/// True when the run of `program` jumps: it calls a subprogram or makes a
/// macro statement's jump or loop (its checkpoints say so).
fn jumps(program: &str, setup: &Setup, max_moves: usize, max_blocks: usize) -> bool {
    let options = RunOptions {
        keep_blocks: false,
        keep_moves: false,
        max_moves,
        max_blocks,
        checkpoint_every: 1_000_000,
    };
    offsetlab::run_observed(program, setup, options, &mut ())
        .1
        .calls
}
