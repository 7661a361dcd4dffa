//! Behaviour 22 (`docs/behaviour.md`): the linuxcnc profile's program text
//! and defaults — numbers as values, P in seconds, `;` comments, the
//! comments that speak, the start at the origin — with settings 7.1, 7.26
//! and 7.61. The move-by-move comparison with LinuxCNC's own interpreter is
//! `scripts/oracle-linuxcnc.py` over `tests/linuxcnc/` (`make test`).
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use offsetlab::setup::{Control, DecimalInput, DwellPDecimalPoint, Semicolon, Settings};
use offsetlab::{Setup, run};

#[test]
fn behaviour22_1_the_linuxcnc_profile_reads_numbers_as_values_and_starts_at_the_origin() {
    let mut s = Settings {
        control: Control::Linuxcnc,
        ..Settings::default()
    };
    assert_eq!(s.decimal_input(), DecimalInput::Calculator);
    s.control = Control::Haas;
    assert_eq!(s.decimal_input(), DecimalInput::Increment);
    // `X1` is 1 mm and `.5` is 0.5 mm; G91 `X-2` from X1 is X-1.
    let r = ok("G21 G90\nG0 X1 Y.5 Z3\nG91 G1 X-2 F100\nM2\n", &linuxcnc());
    assert_eq!(r.moves.len(), 2);
    same(r.moves[0].to, [1.0, 0.5, 3.0]);
    same(r.moves[1].to, [-1.0, 0.5, 3.0]);
    // The run starts at the origin, as rs274 does with no parameter file.
    same(r.moves[0].from, [0.0, 0.0, 0.0]);
    // G28 alone goes to the stored position, 0 on every axis.
    let r = ok("G21\nG0 X5 Y6 Z7\nG28\nM2\n", &linuxcnc());
    same(r.moves.last().unwrap().to, [0.0, 0.0, 0.0]);
    // Set in the setup, the Fanuc reading wins: `X1` is 0.001 mm.
    let mut setup = linuxcnc();
    setup.settings.decimal_input = Some(DecimalInput::Increment);
    let r = ok("G21\nG0 X1000\nM2\n", &setup);
    same(r.moves[0].to, [1.0, 0.0, 0.0]);
}

#[test]
fn behaviour7_26_linuxcnc_dwells_p_seconds_with_or_without_a_point() {
    let s = Settings {
        control: Control::Linuxcnc,
        ..Settings::default()
    };
    assert_eq!(s.dwell_p_decimal_point(), DwellPDecimalPoint::Always);
    // G4 P2 is 2 s, P1.5 1.5 s; a G82's P0.25 a quarter of a second.
    let r = ok(
        "G21 G90\nG4 P2\nG4 P1.5\nG0 Z5\nG82 X1 Y1 Z-2 R1 P0.25 F100\nG80\nM2\n",
        &linuxcnc(),
    );
    assert_eq!(dwells(&r), vec![2.0, 1.5, 0.25]);
    // Haas keeps P3 as 3 ms.
    let mut haas = Setup::default();
    haas.settings.control = Control::Haas;
    let r = ok("G04 P3\nM30\n", &haas);
    assert_eq!(dwells(&r), vec![0.003]);
}

#[test]
fn behaviour7_61_a_semicolon_starts_a_comment_under_linuxcnc_and_the_setting_chooses() {
    let text =
        "; a whole line of comment: G1 X99\nG21 G90 ; G0 X50\nG0 X1 (a ; in a comment) Y2\nM2\n";
    let r = ok(text, &linuxcnc());
    assert_eq!(r.moves.len(), 1);
    same(r.moves[0].to, [1.0, 2.0, 0.0]);
    // The block's text runs to the line's end, its comment shown with it.
    let b = &r.blocks[0];
    assert_eq!(
        &text[b.span.start as usize..b.span.end as usize],
        "G21 G90 ; G0 X50"
    );
    // Fanuc: `;` ends a block, and the text after it is words.
    let mut fanuc = Setup::default();
    fanuc.settings.control = Control::Fanuc;
    assert!(errors(text, &fanuc).contains(&"semicolon-comment"));
    let r = ok("G21 G90;G0 X1.;G1 X2. F100.\nM30\n", &fanuc);
    assert_eq!(r.moves.len(), 2);
    // The setting wins over the profile, either way.
    fanuc.settings.semicolon = Some(Semicolon::Comment);
    let r = ok(text, &fanuc);
    assert_eq!(r.moves.len(), 1);
    let mut l = linuxcnc();
    l.settings.semicolon = Some(Semicolon::EndOfBlock);
    assert!(errors(text, &l).contains(&"semicolon-comment"));
    let setup = Setup::from_json(r#"{"settings":{"semicolon":"comment"}}"#).unwrap();
    assert_eq!(setup.settings.semicolon(), Semicolon::Comment);
    assert!(setup.to_json().contains("\"semicolon\": \"comment\""));
}

#[test]
fn behaviour22_2_msg_and_debug_comments_are_notes_of_their_block() {
    let text = "G21\n(MSG, Insert the 6 mm end mill)\nG0 X1 (debug,X is #1) Z2\n(print,done)\n(a plain comment)\nM2\n";
    let r = ok(text, &linuxcnc());
    let notes: Vec<(u32, &str)> = r
        .blocks
        .iter()
        .flat_map(|b| b.notes.iter().map(move |n| (b.span.line, n.as_str())))
        .collect();
    assert_eq!(
        notes,
        vec![
            (2, "(MSG) Insert the 6 mm end mill"),
            (
                3,
                "(DEBUG) X is #1 (offsetlab shows it as written, without the parameters' values)"
            ),
            (4, "(PRINT) done"),
        ]
    );
    // A plain comment line is no block; the move is still made.
    assert_eq!(r.blocks.len(), 5);
    same(r.moves[0].to, [1.0, 0.0, 2.0]);
    // On the Fanuc family a comment is only a comment.
    let r = run(text.replace("X1", "X1.").as_str(), &Setup::default());
    assert!(
        r.blocks
            .iter()
            .all(|b| b.notes.iter().all(|n| !n.contains("MSG")))
    );
}

#[test]
fn behaviour22_2_debug_is_silent_while_5599_is_0() {
    // rs274 -g: no MESSAGE for a DEBUG after #5599=0, PRINT still prints,
    // any other value speaks again; #5599 reads 1 before any setting.
    let text =
        "G21\n#1 = #5599\n#5599 = 0\n(DEBUG,quiet)\n(PRINT,loud)\n#5599 = 2.5\n(DEBUG,back)\nM2\n";
    let r = ok(text, &linuxcnc());
    let notes: Vec<(u32, &str)> = r
        .blocks
        .iter()
        .flat_map(|b| b.notes.iter().map(move |n| (b.span.line, n.as_str())))
        .filter(|(_, n)| n.starts_with('('))
        .collect();
    assert_eq!(
        notes,
        vec![
            (
                4,
                "(DEBUG) silent: #5599 is 0, so LinuxCNC does not show \"quiet\""
            ),
            (5, "(PRINT) loud"),
            (7, "(DEBUG) back"),
        ]
    );
    let r = ok("G21\n#1 = #5599\nG0 X#1\nM2\n", &linuxcnc());
    same(r.moves[0].to, [1.0, 0.0, 0.0]);
}

#[test]
fn behaviour22_3_linuxcnc_offsets_at_the_next_z_pecks_back_0_254_mm_and_starts_in_g99() {
    use offsetlab::setup::LengthOffsetWithoutZ;
    let s = Settings {
        control: Control::Linuxcnc,
        ..Settings::default()
    };
    assert_eq!(s.length_offset_without_z(), LengthOffsetWithoutZ::NextZ);
    // H01 = 25: G43 without Z moves nothing; the next Z5 lands at Z30.
    let mut setup = linuxcnc();
    setup.set_register("H01=25.").unwrap();
    let r = ok("G21 G90\nG43 H1\nG0 X10\nG0 Z5\nM2\n", &setup);
    assert_eq!(r.moves.len(), 2);
    same(r.moves[0].to, [10.0, 0.0, 0.0]);
    same(r.moves[1].to, [10.0, 0.0, 30.0]);
    // G83 from Z10 to Z-2 with R1, Q1 pecks: in at R1 → Z0, back to R, down
    // to 0.254 above Z0, on to Z-1, back to R, down to Z-0.746, to Z-2.
    // No G98/G99: LinuxCNC's start mode G99 returns to R, not to Z10.
    let r = ok(
        "G21 G90\nG0 X5 Y5 Z10\nG83 Z-2 R1 Q1 F100\nG80\nM2\n",
        &linuxcnc(),
    );
    let z: Vec<f64> = r.moves.iter().skip(1).map(|m| m.to[2]).collect();
    let want = [1.0, 0.0, 1.0, 0.254, -1.0, 1.0, -0.746, -2.0, 1.0];
    assert_eq!(z.len(), want.len(), "{z:?}");
    for (got, want) in z.iter().zip(want) {
        assert!((got - want).abs() < 1e-9, "{z:?}");
    }
}

#[test]
fn behaviour22_4_linuxcnc_refuses_g53_in_g91_a_second_g41_and_g41_in_g19_and_reads_g64_p() {
    use offsetlab::setup::MacroAngles;
    let s = Settings {
        control: Control::Linuxcnc,
        ..Settings::default()
    };
    assert_eq!(s.macro_angles(), MacroAngles::Signed);
    let mut setup = linuxcnc();
    setup.set_register("D01=3.").unwrap();
    let cases = [
        ("G21 G91\nG53 G0 X1\nM2\n", "g53-incremental", 2),
        (
            "G21\nG41 D1 G1 X10 F100\nG42 D1 X20\nM2\n",
            "cutter-already-on",
            3,
        ),
        ("G21 G19\nG41 D1 G1 Y10 F100\nM2\n", "cutter-plane", 2),
        ("G21\nG0 X1\nG1 X2\nM2\n", "missing-feed", 3),
    ];
    for (text, code, line) in cases {
        let r = run(text, &setup);
        let d = r.diagnostics.iter().find(|d| d.is_error()).expect(text);
        assert_eq!((d.code, d.line), (code, line), "{text}");
    }
    // The Fanuc profile ignores the G53 in G91 with a warning and moves X1.
    let mut fanuc = Setup::default();
    fanuc.settings.control = Control::Fanuc;
    let r = run("G21 G91\nG53 G0 X1.\nM30\n", &fanuc);
    assert!(!r.has_errors(), "{:?}", r.diagnostics);
    // G64 P0.01 Q0.02 is read, said, and leaves the path as programmed;
    // the Fanuc family refuses P on G64.
    let r = ok("G21\nG64 P0.01 Q0.02\nG1 X5 F100\nM2\n", &linuxcnc());
    assert!(
        r.blocks[1].notes[0]
            .starts_with("G64 blending tolerance P0.01, naive CAM tolerance Q0.02: "),
        "{:?}",
        r.blocks[1].notes
    );
    same(r.moves[0].to, [5.0, 0.0, 0.0]);
    assert!(errors("G64 P1\nM30\n", &fanuc).contains(&"mode-words"));
    // ATAN[-1]/[-1] is −135° under LinuxCNC: X = 10·cos, Y = 10·sin.
    let r = ok(
        "G21\n#1 = ATAN[-1]/[-1]\nG1 X[10*COS[#1]] Y[#1] F100\nM2\n",
        &linuxcnc(),
    );
    let to = r.moves[0].to;
    assert!((to[1] + 135.0).abs() < 1e-9, "{to:?}");
    assert!(
        (to[0] + 10.0 * std::f64::consts::FRAC_1_SQRT_2).abs() < 1e-3,
        "{to:?}"
    );
}

#[test]
fn behaviour22_5_linuxcnc_fix_fup_round_mod_and_unrounded_words() {
    // Each value worked by hand: FIX[-2.7] = −3, FUP[-2.2] = −2,
    // ROUND[2.5] = 3, -7 MOD 3 = 2, 1/3 kept to 10 decimals.
    let text =
        "G21 G90\nG1 X[FIX[-2.7]] Y[FUP[-2.2]] F100\nG1 X[ROUND[2.5]] Y[-7 MOD 3]\nG1 X[1/3]\nM2\n";
    let r = ok(text, &linuxcnc());
    same(r.moves[0].to, [-3.0, -2.0, 0.0]);
    same(r.moves[1].to, [3.0, 2.0, 0.0]);
    assert!(
        (r.moves[2].to[0] - 1.0 / 3.0).abs() < 1e-9,
        "{:?}",
        r.moves[2].to
    );
    // The Fanuc profile: FIX −2, FUP −3, X[1/3] read as X0.333.
    let mut fanuc = Setup::default();
    fanuc.settings.control = Control::Fanuc;
    let r = ok(
        "G21 G90\nG1 X[FIX[-2.7]] Y[FUP[-2.2]] F100.\nG1 X[1/3]\nM30\n",
        &fanuc,
    );
    let to = r.moves[0].to;
    assert_eq!((to[0], to[1]), (-2.0, -3.0));
    assert!(
        (r.moves[1].to[0] - 0.333).abs() < 1e-12,
        "{:?}",
        r.moves[1].to
    );
}

#[test]
fn behaviour22_5_linuxcnc_power_chained_comparisons_and_logic_on_values() {
    // 2**3**2 is [2**3]**2 = 64, /8 = 8; -2**2 is 4 (the sign binds
    // tighter); [#1 GT 2 AND #1 LT 5] with #1 = 3 is 1; [2 AND 3] is 1;
    // [3 GT 2 EQ 1] is [1 EQ 1] = 1, ×4 = 4; 1.00001 EQ 1 holds within
    // rs274's 0.0001.
    let text = "G21 G90\nG0 X[2 ** 3 ** 2 / 8] Y[-2 ** 2]\n#1 = 3\nG0 X[#1 GT 2 AND #1 LT 5] Y[2 AND 3]\nG0 X[[3 GT 2 EQ 1] * 4] Y[1.00001 EQ 1]\nM2\n";
    let r = ok(text, &linuxcnc());
    same(r.moves[0].to, [8.0, 4.0, 0.0]);
    same(r.moves[1].to, [1.0, 1.0, 0.0]);
    same(r.moves[2].to, [4.0, 1.0, 0.0]);
}

#[test]
fn behaviour22_6_named_parameters_local_to_their_level_global_with_an_underscore() {
    // #<Side Len> is #<sidelen> (case and blanks left out). The sub's
    // #<side> is 2 × 3 = 6; the global depth −2 is read inside the sub;
    // #<_x> is then 6 and #<_metric> 1, so Y is 7.
    let text = "#<_depth> = -2\no1 sub\n  #<side> = [#1 * 2]\n  G1 X#<side> Z#<_depth> F100\no1 endsub\nG21 G90\n#<Side Len> = 3\no1 call [#<sidelen>]\nG0 X#<_x> Y[#<_metric> * 7] Z[EXISTS[#<side>]]\nM2\n";
    let r = ok(text, &linuxcnc());
    assert_eq!(r.moves.len(), 2);
    same(r.moves[0].to, [6.0, 0.0, -2.0]);
    // The sub's local is gone after it: EXISTS gives 0.
    same(r.moves[1].to, [6.0, 7.0, 0.0]);
    // Reading a name never set is LinuxCNC's error, at its line.
    assert_eq!(
        error_line("G21\n#<depth> = 1\nG0 Z#<dpeth>\nM2\n", &linuxcnc()),
        ("named-parameter", 3)
    );
    // A main program's local is not the sub's.
    assert_eq!(
        error_line(
            "o2 sub\n  G0 X#<a>\no2 endsub\n#<a> = 1\no2 call\nM2\n",
            &linuxcnc()
        ),
        ("named-parameter", 2)
    );
    // A predefined parameter is read, never set.
    assert_eq!(
        error_line("#<_x> = 1\nM2\n", &linuxcnc()),
        ("named-parameter", 1)
    );
}

#[test]
fn behaviour22_7_owords_branch_loop_and_call_as_rs274_runs_them() {
    // Three passes of the while: #1 = 1 takes the else (X1), #1 = 2 the
    // if (Y2), #1 = 3 the else (X3); repeat [2.5] runs twice (half to
    // even), each pass Z−1 in G91.
    let text = "G21 G90 F100\n#1 = 0\no10 while [#1 LT 3]\n  #1 = [#1 + 1]\n  o20 if [#1 EQ 2]\n    G1 Y#1\n  o20 else\n    G1 X#1\n  o20 endif\no10 endwhile\no30 repeat [2.5]\n  G91 G1 Z-1\no30 endrepeat\nG90\nM2\n";
    let r = ok(text, &linuxcnc());
    let to: Vec<[f64; 3]> = r.moves.iter().map(|m| m.to).collect();
    assert_eq!(to.len(), 5, "{to:?}");
    same(to[0], [1.0, 0.0, 0.0]);
    same(to[1], [1.0, 2.0, 0.0]);
    same(to[2], [3.0, 2.0, 0.0]);
    same(to[3], [3.0, 2.0, -1.0]);
    same(to[4], [3.0, 2.0, -2.0]);
    // A call: #1 #2 are the arguments, the caller's #1 (7) comes back,
    // and return [#2 * 2] leaves 8 in #<_value>. The sub defined after
    // the M2 is found ahead of the call.
    let text = "G21 G90\n#1 = 7\no100 call [1] [4]\nG0 X#<_value> Y#1 Z#<_value_returned>\nM2\no100 sub\n  #1 = 50\n  o100 return [#2 * 2]\n  G0 Z99\no100 endsub\nM2\n";
    let r = ok(text, &linuxcnc());
    assert_eq!(r.moves.len(), 1);
    same(r.moves[0].to, [8.0, 7.0, 1.0]);
    // do … while runs once with a false condition; break leaves a while.
    let text = "G21 G90 F100\n#1 = 0\no1 do\n  G1 X5\no1 while [0]\no2 while [1]\n  #1 = [#1 + 1]\n  o3 if [#1 GT 2]\n    o2 break\n  o3 endif\n  G1 Y#1\no2 endwhile\nM2\n";
    let r = ok(text, &linuxcnc());
    let to: Vec<[f64; 3]> = r.moves.iter().map(|m| m.to).collect();
    assert_eq!(to, vec![[5.0, 0.0, 0.0], [5.0, 1.0, 0.0], [5.0, 2.0, 0.0]]);
    // rs274's repeat counts its passes at its own block: a `continue` of
    // the while around it leaves the count running, so the second while
    // pass runs the repeat's second pass (X2) and the third none; then a
    // plain repeat [3] moves Y by 2 three times.
    let text = "G21 G90 F100\n#1 = 0\no1 while [#1 LT 3]\n  #1 = [#1 + 1]\n  o2 repeat [2]\n    G91 G1 X1\n    o1 continue\n  o2 endrepeat\no1 endwhile\nG90\no3 repeat [3]\n  G91 G1 Y2\no3 endrepeat\nM2\n";
    let r = ok(text, &linuxcnc());
    let to: Vec<[f64; 3]> = r.moves.iter().map(|m| m.to).collect();
    assert_eq!(
        to,
        vec![
            [1.0, 0.0, 0.0],
            [2.0, 0.0, 0.0],
            [2.0, 2.0, 0.0],
            [2.0, 4.0, 0.0],
            [2.0, 6.0, 0.0]
        ]
    );
    // rs274's refusals: break in a repeat, a sub defined twice, a call to
    // no sub, a false if with no endif (reported at the file's end).
    assert_eq!(
        error_line("o1 repeat [2]\n  o1 break\no1 endrepeat\nM2\n", &linuxcnc()),
        ("oword", 2)
    );
    assert_eq!(
        error_line(
            "o1 sub\no1 endsub\no1 call\no1 sub\no1 endsub\nM2\n",
            &linuxcnc()
        ),
        ("oword", 4)
    );
    assert_eq!(
        error_line("G21\no<nosuch> call\nM2\n", &linuxcnc()),
        ("oword", 2)
    );
    // `O1000 (NAME)` with no keyword is the program's number, as rs274
    // reads it; an unknown keyword is an error.
    let r = ok("%\nO1000 (NAME)\nG21\nG0 X1\nM2\n%\n", &linuxcnc());
    same(r.moves[0].to, [1.0, 0.0, 0.0]);
    assert_eq!(error_line("o1 loop\nM2\n", &linuxcnc()), ("oword", 1));
    assert_eq!(
        error_line("G21\no5 if [0]\nG0 X1\nM2\n", &linuxcnc()),
        ("oword", 4)
    );
}

#[test]
fn behaviour22_7_a_runaway_oword_loop_stops_at_the_block_limit() {
    // Each pass reads two blocks: with a limit of 1,000 the run stops
    // after 1,000, with the limit's error; a sub calling itself stops at
    // LinuxCNC's 10 levels.
    let options = offsetlab::RunOptions {
        max_blocks: 1000,
        ..offsetlab::RunOptions::default()
    };
    let r = offsetlab::run_with("o1 while [1]\no1 endwhile\nM2\n", &linuxcnc(), options);
    assert_eq!(r.block_count, 1000);
    assert!(
        r.diagnostics.iter().any(|d| d.code == "too-many-blocks"),
        "{:#?}",
        r.diagnostics
    );
    assert_eq!(
        error_line("o1 sub\n  o1 call\no1 endsub\no1 call\nM2\n", &linuxcnc()),
        ("oword", 2)
    );
}
