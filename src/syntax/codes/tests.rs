//! The code tables: every code read back, the lathe's systems, the reasons.
use super::*;

#[test]
fn lathe_g90_is_a_cycle_not_absolute_mode() {
    assert_eq!(g_group(CodeTable::LATHE, GCode::new(90)), Ok(Group::Motion));
    assert_eq!(
        g_group(CodeTable::MILL, GCode::new(90)),
        Ok(Group::Distance)
    );
}

#[test]
fn lathe_g90_is_a_turning_cycle_and_g92_sets_coordinates_on_the_mill() {
    let g = GCode::new;
    assert_eq!(
        Code::of(CodeTable::LATHE, g(90)),
        Some(Code::Motion(Motion::LatheCycle(LatheCycle::Turning)))
    );
    assert_eq!(
        Code::of(CodeTable::MILL, g(90)),
        Some(Code::Distance(Distance::Absolute))
    );
    assert_eq!(
        Code::of(CodeTable::MILL, g(92)),
        Some(Code::NonModal(NonModal::SetCoordinates))
    );
    assert_eq!(
        Code::of(CodeTable::LATHE, g(99)),
        Some(Code::FeedMode(FeedMode::PerRevolution))
    );
}

#[test]
fn every_code_writes_back_the_number_it_was_read_from() {
    let tables = [MachineKind::Mill, MachineKind::Lathe]
        .into_iter()
        .flat_map(|m| {
            [GCodeSystem::A, GCodeSystem::B, GCodeSystem::C].map(|s| CodeTable::new(m, s))
        });
    for table in tables {
        let decimals = (0..=200).flat_map(|n| (1..=9).map(move |m| GCode { major: n, minor: m }));
        for g in (0..=200).map(GCode::new).chain(decimals) {
            if let Some(code) = Code::of(table, g) {
                assert_eq!(code.gcode(table), g.to_string(), "{table:?} {g}");
                assert_eq!(g_group(table, g), Ok(code.group()));
                let mut codes = Codes::default();
                codes.set(code, code.group());
                assert_eq!(codes.each().collect::<Vec<_>>(), vec![code]);
            }
        }
        assert_eq!(Code::of(table, GCode { major: 1, minor: 5 }), None);
        assert_eq!(
            g_group(table, GCode { major: 7, minor: 1 }),
            Ok(Group::NonModal)
        );
    }
}

#[test]
fn unsupported_codes_say_why() {
    let e = g_group(CodeTable::LATHE, GCode::new(43)).unwrap_err();
    assert!(e.contains("T-code offsets"), "{e}");
    let e = g_group(CodeTable::MILL, GCode::new(7)).unwrap_err();
    assert!(e.contains("G07 is not a G code"), "{e}");
    let e = g_group(
        CodeTable::MILL,
        GCode {
            major: 61,
            minor: 1,
        },
    )
    .unwrap_err();
    assert!(
        e.contains("G61.1") && e.contains("G61 for exact stop"),
        "{e}"
    );
    let e = g_group(CodeTable::LATHE, GCode { major: 5, minor: 1 }).unwrap_err();
    assert!(e.contains("G05.1"), "{e}");
    let e = g_group(CodeTable::LATHE, GCode::new(83)).unwrap_err();
    assert!(e.contains("drilling canned cycles"), "{e}");
}
#[test]
fn decimal_codes_write_back_what_was_read() {
    for (major, minor, mill_only) in [
        (50, 1, true),
        (51, 1, true),
        (54, 1, false),
        (90, 1, true),
        (91, 1, true),
        (92, 1, true),
    ] {
        let g = GCode { major, minor };
        let code = Code::of(CodeTable::MILL, g).unwrap();
        assert_eq!(code.gcode(CodeTable::MILL), g.to_string());
        assert_eq!(Code::of(CodeTable::LATHE, g).is_none(), mill_only, "{g}");
    }
}
