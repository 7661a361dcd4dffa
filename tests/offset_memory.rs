//! Behaviour 17.1–17.4: the offset memory types A, B and C of the mill,
//! the lathe table's nose radius and tip direction, and the forms the setup
//! document, `--offset` and plain links give them.
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;

use offsetlab::setup::{Control, MillPart, MillRegister, OffsetMemory};
use offsetlab::share::{decode, encode_plain};
use offsetlab::{Document, MachineKind, Setup, run};

/// A mill setup of `json`'s fields.
fn setup(json: &str) -> Setup {
    Setup::from_json(json).unwrap()
}

/// Z after `G43 Z0 H01` and X after `G91 G00 G45 X10. D01` from the
/// origin: what H01 and D01 read.
fn h_and_d(s: &Setup) -> (f64, f64) {
    let r = ok("G90 G00 G43 Z0 H01\nG91 G00 G45 X10. D01", s);
    (actual(&r, 0)[2], actual(&r, 1)[0] - 10.0)
}

#[test]
fn behaviour17_1_memory_a_one_value_read_by_h_and_d() {
    // Memory A (the seeds): register 01 = 6. is H01 and D01 alike.
    let s = mill(&[(1, 6.0)]);
    assert_eq!(s.settings.offset_memory(), OffsetMemory::A);
    let (h, d) = h_and_d(&s);
    // G43 Z0 H01 → Z 0 + 6 = 6; G45 X10. D01 → 10 + 6 = 16, so D reads 6.
    same([h, d, 0.0], [6.0, 6.0, 0.0]);
}

#[test]
fn behaviour17_1_memory_a_adds_the_wear_of_a_document_written_before() {
    // A document written before memory types, with a wear part: memory A
    // reads the sum, 10 - 0.5 = 9.5, as it always did (behaviour 1.18).
    let s = setup(r#"{"offsets":{"01":{"geometry":10,"wear":-0.5}}}"#);
    let (h, d) = h_and_d(&s);
    same([h, d, 0.0], [9.5, 9.5, 0.0]);
}

#[test]
fn behaviour17_1_memory_b_geometry_and_wear_shared_by_h_and_d() {
    // Memory B: geometry 120.5 and wear -0.05 of number 01, read by both:
    // 120.45.
    let s = setup(
        r#"{"settings":{"offset_memory":"B"},"offsets":{"01":{"geometry":120.5,"wear":-0.05}}}"#,
    );
    let (h, d) = h_and_d(&s);
    same([h, d, 0.0], [120.45, 120.45, 0.0]);
}

#[test]
fn behaviour17_1_memory_c_keeps_the_h_and_d_tables_apart() {
    // Memory C: H01 = 120 - 0.1 = 119.9, D01 = 5 + 0.02 = 5.02.
    let s = setup(
        r#"{"settings":{"offset_memory":"C"},"offsets":{"01":{"h":120,"h_wear":-0.1,"d":5,"d_wear":0.02}}}"#,
    );
    assert_eq!(s.h_value(1), 119.9);
    assert_eq!(s.d_value(1), 5.02);
    // mill_value, the callers' D read, is the D table's.
    assert_eq!(s.mill_value(1), 5.02);
    let (h, d) = h_and_d(&s);
    // G43 Z0 → Z 119.9; G45 X10. → 10 + 5.02 = 15.02.
    same([h, d, 0.0], [119.9, 5.02, 0.0]);
}

#[test]
fn behaviour17_1_memory_c_reads_a_register_of_one_value_for_both_tables() {
    // A register written as one value gives H and D the same in memory C:
    // every document written before memory types runs as it did.
    let s = setup(r#"{"settings":{"offset_memory":"C"},"offsets":{"01":7.5}}"#);
    let (h, d) = h_and_d(&s);
    same([h, d, 0.0], [7.5, 7.5, 0.0]);
    // An H table alone: D reads 0 (`{"h": 120}`).
    let s = setup(r#"{"settings":{"offset_memory":"C"},"offsets":{"01":{"h":120}}}"#);
    assert_eq!((s.h_value(1), s.d_value(1)), (120.0, 0.0));
}

#[test]
fn behaviour17_1_the_profile_gives_the_memory_type_and_a_setting_wins() {
    let mut s = Setup::default();
    for (control, memory) in [
        (Control::Yasnac, OffsetMemory::A),
        (Control::Fanuc, OffsetMemory::C),
        (Control::Haas, OffsetMemory::C),
    ] {
        s.settings.control = control;
        assert_eq!(s.settings.offset_memory(), memory, "{control:?}");
    }
    s.settings.offset_memory = Some(OffsetMemory::B);
    assert_eq!(s.settings.offset_memory(), OffsetMemory::B);
    // The summary says which type the tables were read with (mill only).
    let r = run("G00 X1.", &s);
    let summary = offsetlab::view::summary(&r);
    assert_eq!(summary.offset_memory, Some("B"));
    let r = run("G00 X1.", &lathe(&[]));
    assert_eq!(offsetlab::view::summary(&r).offset_memory, None);
}

#[test]
fn behaviour17_2_a_memory_c_register_in_memory_a_or_b_is_refused() {
    for memory in ["A", "B"] {
        let e = Setup::from_json(&format!(
            r#"{{"settings":{{"offset_memory":"{memory}"}},"offsets":{{"03":{{"h":100,"d":4}}}}}}"#
        ))
        .unwrap_err();
        assert_eq!(e.diagnostics[0].code, "setup-memory", "{memory}");
        assert!(
            e.to_string().contains("register 03") && e.to_string().contains("memory C"),
            "{e}"
        );
    }
    // The YASNAC profile is memory A: the same without the setting.
    assert!(Setup::from_json(r#"{"offsets":{"03":{"d":4}}}"#).is_err());
}

#[test]
fn behaviour17_2_each_table_is_held_to_the_offset_range() {
    let bad = [
        r#"{"settings":{"offset_memory":"C"},"offsets":{"01":{"h":1000}}}"#,
        r#"{"settings":{"offset_memory":"C"},"offsets":{"01":{"d":999,"d_wear":1}}}"#,
        r#"{"offsets":{"01":{"geometry":999.9,"wear":0.5}}}"#,
        r#"{"offsets":{"01":{"h":1,"geometry":2}}}"#,
    ];
    for json in bad {
        let e = Setup::from_json(json).unwrap_err();
        assert!(
            matches!(e.diagnostics[0].code, "setup-range" | "setup-syntax"),
            "{json}: {e}"
        );
    }
    let e = Setup::from_json(bad[1]).unwrap_err();
    assert!(
        e.to_string().contains("register D01 geometry + wear"),
        "{e}"
    );
}

#[test]
fn behaviour17_2_each_form_is_written_as_it_is_read() {
    // One value: a number; geometry and wear: the object; memory C's
    // tables apart: h, h_wear, d, d_wear, zeros left out.
    let mut s = Setup::default();
    s.settings.offset_memory = Some(OffsetMemory::C);
    s.offsets.insert(1, MillRegister::new(6.0, 0.0));
    s.offsets.insert(2, MillRegister::new(120.5, -0.05));
    let mut split = MillRegister::new(100.0, 0.0);
    split.set_d(MillPart {
        geometry: 4.0,
        wear: -0.02,
    });
    s.offsets.insert(3, split);
    let json = s.to_json();
    assert!(json.contains("\"01\": 6.0"), "{json}");
    assert!(json.contains("\"geometry\": 120.5"), "{json}");
    assert!(
        json.contains("\"h\": 100.0") && json.contains("\"d_wear\": -0.02"),
        "{json}"
    );
    assert!(!json.contains("\"h_wear\""), "{json}");
    let back = Setup::from_json(&json).unwrap();
    assert_eq!(back, s);
    assert_eq!((back.h_value(3), back.d_value(3)), (100.0, 3.98));
    // A D part equal to the H part is a register of one value.
    let mut same_parts = MillRegister::new(5.0, 0.0);
    same_parts.set_d(MillPart {
        geometry: 5.0,
        wear: 0.0,
    });
    assert!(!same_parts.is_split());
    assert_eq!(same_parts, MillRegister::new(5.0, 0.0));
}

#[test]
fn behaviour17_3_the_lathe_table_holds_the_nose_radius_and_the_tip() {
    let s = Setup::from_json(
        r#"{"machine":"lathe","lathe_offsets":{"05":{"x":0.4,"z":-0.2,"r":0.8,"r_wear":-0.01,"t":3}}}"#,
    )
    .unwrap();
    let reg = s.lathe_register(5);
    assert_eq!((reg.r_value(), reg.t), (0.8 - 0.01, 3));
    assert!(s.to_json().contains("\"t\": 3"));
    assert_eq!(Setup::from_json(&s.to_json()).unwrap(), s);
    // The tip direction is 0 to 9.
    let e = Setup::from_json(r#"{"machine":"lathe","lathe_offsets":{"05":{"t":10}}}"#).unwrap_err();
    assert_eq!(e.diagnostics[0].code, "setup-range");
    assert!(e.to_string().contains("tip direction"), "{e}");
    // No path reads R or T yet (nose radius compensation is refused): a
    // T code's vector is X and Z alone, here X 0.4 Z -0.2 from X100 Z50.
    let r = ok("G50 X100. Z50.\nG00 T0105", &s);
    same(actual(&r, 1), [100.4, 0.0, 49.8]);
}

#[test]
fn behaviour17_4_offset_specs_for_each_table() {
    // Lathe: nose radius and tip, the other parts 0.
    let mut s = lathe(&[]);
    s.set_register("05=R4.,T3").unwrap();
    let reg = s.lathe_register(5);
    assert_eq!((reg.x, reg.z, reg.r, reg.t), (0.0, 0.0, 4.0, 3));
    s.set_register("06=X0.4,Z-0.2,XW0.01,RW-0.02,R0.8").unwrap();
    assert_eq!(s.lathe_register(6).r_value(), 0.78);
    for bad in ["05=T10", "05=T1.5", "H05=1", "05=Q3"] {
        assert!(s.set_register(bad).is_err(), "{bad}");
    }
    // Mill, memory C: each table alone; the other keeps what it read.
    let mut s = Setup::default();
    s.settings.offset_memory = Some(OffsetMemory::C);
    s.set_register("01=7").unwrap();
    s.set_register("H01=120.,W-0.1").unwrap();
    assert_eq!((s.h_value(1), s.d_value(1)), (119.9, 7.0));
    s.set_register("D01=5.").unwrap();
    assert_eq!((s.h_value(1), s.d_value(1)), (119.9, 5.0));
    s.set_register("d02=3").unwrap();
    assert_eq!((s.h_value(2), s.d_value(2)), (0.0, 3.0));
    assert!(s.clone().validated().is_ok());
    // The same specs in memory A are refused when the setup is read.
    s.settings.offset_memory = Some(OffsetMemory::A);
    assert_eq!(
        s.validated().unwrap_err().diagnostics[0].code,
        "setup-memory"
    );
}

#[test]
fn behaviour17_4_plain_links_carry_every_form() {
    let mut doc = Document::default();
    doc.setup.settings.offset_memory = Some(OffsetMemory::C);
    doc.setup.set_register("H01=120.,W-0.1").unwrap();
    doc.setup.set_register("D01=5.").unwrap();
    doc.setup.set_register("02=7").unwrap();
    let plain = encode_plain(&doc, false);
    assert!(
        plain.contains("offset=H01:120,W-0.1&offset=D01:5&offset=02:7"),
        "{plain}"
    );
    assert!(plain.contains("offset_memory=C"), "{plain}");
    assert_eq!(decode(&format!("#{plain}")).unwrap().document, doc);
    // Written by hand: D01 before the memory type is named.
    let l = decode("#offset=D01:5&offset=H01:100&offset_memory=C&program=G00").unwrap();
    assert_eq!(
        (l.document.setup.h_value(1), l.document.setup.d_value(1)),
        (100.0, 5.0)
    );
    // The lathe's nose radius and tip.
    let mut doc = Document::default();
    doc.setup.machine = MachineKind::Lathe;
    doc.setup.set_register("05=X0.4,Z-0.2,R0.8,T3").unwrap();
    let plain = encode_plain(&doc, false);
    assert!(plain.contains("offset=05:X0.4,Z-0.2,R0.8,T3"), "{plain}");
    assert_eq!(decode(&format!("#{plain}")).unwrap().document, doc);
}
