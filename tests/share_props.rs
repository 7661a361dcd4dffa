//! Property tests of the link codec (issue 5): compact and plain forms
//! round-trip any document, and no input makes decoding panic.
#![cfg(not(target_arch = "wasm32"))]

use offsetlab::document::{ViewPlane, ViewState};
use offsetlab::setup::{DecimalInput, LengthOffsetWithoutZ, Mirror, OffsetMemory};
use offsetlab::share::{decode, encode, encode_plain};
use offsetlab::{Document, MachineKind, Setup};
use proptest::prelude::*;

fn value() -> impl Strategy<Value = f64> {
    (-999_999i64..=999_999).prop_map(|v| v as f64 / 1000.0)
}

fn document() -> impl Strategy<Value = Document> {
    (
        any::<bool>(),
        "\\PC{0,300}",
        prop::collection::btree_map(
            1u16..=99,
            (
                (value(), value(), value(), value()),
                (value(), value(), 0u8..=9, any::<bool>()),
            ),
            0..6,
        ),
        any::<(bool, bool, bool, bool, bool)>(),
        prop::option::of((0usize..4, 1u32..1000, -1000i64..1000, -1000i64..1000)),
        prop::option::of(0u32..100_000),
        prop::option::of(0usize..3),
    )
        .prop_map(
            |(lathe, program, regs, (calc, skip, next_z, mx, my), view, step, memory)| {
                let mut s = Setup {
                    machine: if lathe {
                        MachineKind::Lathe
                    } else {
                        MachineKind::Mill
                    },
                    ..Setup::default()
                };
                // Each offset memory type, or the control's (behaviour 17.1):
                // in memory C a register may keep H and D apart.
                s.settings.offset_memory =
                    memory.map(|m| [OffsetMemory::A, OffsetMemory::B, OffsetMemory::C][m]);
                let c = s.settings.offset_memory() == OffsetMemory::C;
                for (n, ((a, b, c2, d), (e, f, tip, split))) in regs {
                    let specs = if lathe {
                        vec![format!("{n}=X{a},Z{b},XW{c2},ZW{d},R{e},RW{f},T{tip}")]
                    } else if c && split {
                        vec![format!("H{n}={a},W{b}"), format!("D{n}={c2},W{d}")]
                    } else {
                        vec![format!("{n}={a},W{b}")]
                    };
                    for spec in specs {
                        s.set_register(&spec).unwrap();
                    }
                }
                // Geometry + wear must stay within ±999.999 too, in each table.
                s.offsets.retain(|_, r| {
                    r.h_part().value().abs() <= 999.999 && r.d_part().value().abs() <= 999.999
                });
                if calc {
                    s.settings.decimal_input = Some(DecimalInput::Calculator);
                }
                s.settings.block_skip = skip;
                if next_z {
                    s.settings.length_offset_without_z = Some(LengthOffsetWithoutZ::NextZ);
                }
                if !lathe {
                    s.settings.mirror = Mirror { x: mx, y: my };
                }
                Document {
                    setup: s,
                    program,
                    view: view.map(|(p, z, a, b)| ViewState {
                        plane: [ViewPlane::XY, ViewPlane::XZ, ViewPlane::YZ, ViewPlane::ZX][p],
                        zoom: z as f64 / 10.0,
                        pan: [a as f64 / 4.0, b as f64 / 4.0],
                        angles: None,
                        // The swept width (behaviour 16.20), on for half the pans.
                        swept: a % 2 == 0,
                        // The legend folded away (behaviour 10.9) for some.
                        legend: b % 3 != 0,
                    }),
                    step,
                }
            },
        )
}

proptest! {
    #[test]
    fn compact_links_round_trip(doc in document(), embed in any::<bool>()) {
        let mut link = format!("https://example.org/#{}", encode(&doc));
        if embed {
            link.push_str("&embed=1");
        }
        let back = decode(&link).unwrap();
        prop_assert_eq!(back.document, doc);
        prop_assert_eq!(back.embed, embed);
    }

    #[test]
    fn plain_links_round_trip(doc in document(), embed in any::<bool>()) {
        // The plain form names the plane only with a view; a lathe view in
        // the plain form defaults to ZX, as a hand-written link would.
        let link = format!("#{}", encode_plain(&doc, embed));
        let back = decode(&link).unwrap();
        prop_assert_eq!(back.document, doc);
        prop_assert_eq!(back.embed, embed);
    }

    #[test]
    fn decoding_anything_never_panics(text in "\\PC{0,400}") {
        let _ = decode(&text);
        let _ = decode(&format!("#v1.{text}"));
    }
}
