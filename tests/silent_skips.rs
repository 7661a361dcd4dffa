//! Behaviour 2.22, never a silent skip: every address in every kind of block
//! of the mill and the lathe is acted on, or refused with an error at its
//! word. The table below says which addresses each kind of block refuses;
//! the test adds each address to each block and checks both the table and
//! that an address the block does not refuse changes what the run does
//! (its moves, events, state, notes or diagnostics). A new code or path that
//! drops a word without a word said fails here.
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use offsetlab::setup::CirclePocket;
use offsetlab::syntax::Address;
use offsetlab::{Run, Setup, run};

/// One kind of block: the program before it, the block, the program after
/// it (which reads the data the block keeps, such as a cycle's Q), and the
/// addresses it refuses (`unused-word`, the refusals of the codes that
/// check their own words — `skip-words`, `pocket-words`, `mode-words` —
/// and those of behaviour 1.7 and 2.21: the other machine's addresses and
/// the words not modelled, less those written `-A` here).
struct Kind {
    name: &'static str,
    before: &'static str,
    block: &'static str,
    after: &'static str,
    refused: &'static str,
}

/// Refused on every mill block: the lathe's axes (`lathe-address`), E and
/// the comma words (`unsupported-word`; `,C`/`,R` are cut between two G01
/// moves only, and these blocks have no next move). Rotary axes A, B, C are
/// reported, not drawn (behaviour 13).
const MILL_NEVER: &str = "U W E ,C ,R";
/// Refused on every lathe block: the mill's addresses (`mill-address`) and
/// the words not modelled. (X with U, or Z with W, is `axis-conflict`, and
/// a dwell's time given twice `dwell-words`: in the tables below.)
const LATHE_NEVER: &str = "Y J D H A B C E ,C ,R";

const MILL: &[Kind] = &[
    Kind {
        name: "G00 straight move",
        before: "",
        block: "G00 X10. Y5.",
        after: "",
        refused: "I J K R Q P L",
    },
    Kind {
        name: "G01 straight move",
        before: "",
        block: "G01 X10. Y5. F100.",
        after: "",
        refused: "I J K R Q P L",
    },
    Kind {
        name: "a modal code alone (G17)",
        before: "",
        block: "G17",
        after: "",
        refused: "I J K R Q P L",
    },
    Kind {
        name: "G02 arc with I J",
        before: "G00 X10. Y0\n",
        block: "G02 X0 Y10. I-10. J0 F100.",
        after: "",
        refused: "Q P L",
    },
    Kind {
        name: "G03 arc with R",
        before: "G00 X10. Y0\n",
        block: "G03 X0 Y10. R10. F100.",
        after: "",
        refused: "Q P L",
    },
    Kind {
        name: "G81 starting a canned cycle",
        before: "G00 X0 Y0 Z10.\n",
        block: "G81 X10. Y5. Z-5. R1. F100.",
        after: "G82 X30. Y5.\nG83 X20. Y5.\nG80\n",
        refused: "I J",
    },
    Kind {
        name: "a hole in the canned cycle mode",
        before: "G00 X0 Y0 Z10.\nG81 X10. Y5. Z-5. R1. F100.\n",
        block: "X20. Y5.",
        after: "G82 X30. Y5.\nG83 X40. Y5.\nG80\n",
        refused: "I J",
    },
    Kind {
        name: "G80 cancelling the cycle",
        before: "G00 X0 Y0 Z10.\nG81 X10. Y5. Z-5. R1. F100.\n",
        block: "G80 Z20.",
        after: "",
        refused: "I J K R Q P L",
    },
    Kind {
        name: "G41 start-up move",
        before: "G00 X-10. Y0\n",
        block: "G01 G41 D01 X10. Y5. F100.",
        after: "X20. Y5.\nG40 X30.\n",
        // I/J give the IJ-type vector's direction (behaviour 16.14); K is
        // not a direction in G17 (`cutter-ijk`).
        refused: "K R Q P L",
    },
    Kind {
        name: "G41 with I/J and no move (the vector's direction)",
        before: "",
        block: "G01 G41 D01 I1. J0 F100.",
        after: "X10.\nG40 X20.\n",
        // K is not a direction in G17 (`cutter-ijk`).
        refused: "K R Q P L",
    },
    Kind {
        name: "G39 corner arc",
        before: "G01 G41 D01 X10. F100.\n",
        block: "G39",
        after: "Y-10.\nG40 X0\n",
        // An axis word: `cutter-g39`; K off the plane: `cutter-ijk`.
        refused: "X Y Z K H R Q P L",
    },
    Kind {
        name: "G04 dwell",
        before: "",
        block: "G04 P500",
        after: "",
        // X with P, Y and Z: `dwell-words` (behaviour 2.9).
        refused: "H I J K R Q L X Y Z",
    },
    Kind {
        name: "G92 coordinate setting",
        before: "",
        block: "G92 X0 Y0",
        after: "",
        refused: "H I J K R Q P L S",
    },
    Kind {
        name: "G28 reference return",
        before: "G00 X10. Y5. Z20.\n",
        block: "G91 G28 Z0",
        after: "",
        refused: "I J K R Q P L",
    },
    Kind {
        name: "G45 in a straight move",
        before: "",
        block: "G91 G01 G45 X10. D01 F100.",
        after: "",
        refused: "I J K R Q P L",
    },
    Kind {
        name: "G45 in an arc",
        before: "G00 X10. Y0\n",
        block: "G91 G03 G45 X-10. Y10. I-10. D01 F100.",
        after: "",
        refused: "Q P L",
    },
    Kind {
        name: "G45 full circle",
        before: "G00 X10. Y0\n",
        block: "G91 G02 G45 I-10. D01 F100.",
        after: "",
        refused: "Q P L",
    },
    Kind {
        name: "G09 exact stop in a straight move",
        before: "",
        block: "G09 G01 X10. Y5. F100.",
        after: "",
        refused: "I J K R Q P L",
    },
    Kind {
        name: "G61 exact stop mode",
        before: "",
        block: "G61 G01 X10. F100.",
        after: "",
        refused: "I J K R Q P L",
    },
    Kind {
        name: "G31 skip",
        before: "",
        block: "G31 X10. F100.",
        after: "",
        refused: "I J K R Q P L",
    },
    Kind {
        name: "G12 circular pocket (Haas)",
        before: "",
        block: "G12 I8. K15. Q4. D01 F100.",
        after: "",
        refused: "H J P R",
    },
    Kind {
        name: "G05.1 AI contour",
        before: "",
        block: "G05.1 Q1",
        after: "",
        refused: "A B C D I J K L P R X Y Z",
    },
    Kind {
        name: "G08 look-ahead",
        before: "",
        block: "G08 P1",
        after: "",
        refused: "A B C D I J K L Q R X Y Z",
    },
    Kind {
        name: "G187 smoothness (Haas)",
        before: "",
        block: "G187 P1",
        after: "",
        refused: "A B C D I J K L Q R X Y Z -E",
    },
    Kind {
        name: "G93 inverse time feed",
        before: "",
        block: "G93 G01 X10. F2.",
        after: "",
        refused: "I J K R Q P L",
    },
    Kind {
        name: "G27 reference position check",
        // At the reference position's Z (behaviour 13.15), so the check holds.
        before: "G00 X10. Y5. Z508.\n",
        block: "G91 G27 Z0",
        after: "",
        refused: "I J K L P Q R",
    },
    Kind {
        name: "G30 second reference position",
        before: "G00 X10. Y5.\n",
        block: "G91 G30 P3 Z0",
        after: "",
        refused: "I J K L Q R",
    },
    Kind {
        name: "G52 local coordinates",
        before: "",
        block: "G52 X10. Y5.",
        after: "",
        refused: "I J K L P Q R",
    },
    Kind {
        name: "G53 machine coordinates",
        before: "",
        block: "G53 G00 X10. Y5.",
        after: "",
        refused: "I J K L P Q R",
    },
    Kind {
        name: "G92.1 preset",
        before: "G92 X0 Y0\n",
        block: "G92.1 X0",
        after: "",
        refused: "I J K L P Q R Y Z",
    },
    Kind {
        name: "G54.1 additional work system",
        before: "",
        block: "G54.1 P1",
        after: "",
        refused: "I J K L Q R",
    },
    Kind {
        name: "G68 rotation",
        before: "",
        block: "G68 X0 Y0 R30.",
        after: "G69\n",
        refused: "I J K L P Q Z",
    },
    Kind {
        name: "G51 scaling",
        before: "",
        block: "G51 X0 Y0 P2000",
        after: "G50\n",
        refused: "L Q R",
    },
    Kind {
        name: "G51.1 mirror",
        before: "",
        block: "G51.1 X5.",
        after: "G50.1\n",
        refused: "I J K L P Q R",
    },
];

const LATHE: &[Kind] = &[
    Kind {
        name: "lathe G00 straight move",
        before: "",
        block: "G00 X50. Z5.",
        after: "",
        refused: "I K R Q P L U W",
    },
    Kind {
        name: "lathe G01 straight move",
        before: "G00 X50. Z5.\n",
        block: "G01 X40. Z-10. F0.2",
        after: "",
        refused: "I K R Q P L U W",
    },
    Kind {
        name: "a T code alone",
        before: "",
        block: "T0101",
        after: "",
        refused: "I K R Q P L",
    },
    Kind {
        name: "lathe G02 arc",
        before: "G00 X40. Z-10.\n",
        block: "G02 X50. Z-20. R10. F0.2",
        after: "",
        refused: "Q P L U W",
    },
    Kind {
        name: "G90 turning cycle",
        before: "G00 X50. Z5.\n",
        block: "G90 X40. Z-20. F0.2",
        after: "",
        refused: "I K Q P L U W",
    },
    Kind {
        name: "lathe G04 dwell",
        before: "",
        block: "G04 U1.",
        after: "",
        refused: "T I K R Q P L X Z W",
    },
    Kind {
        name: "G50 coordinate setting",
        before: "",
        block: "G50 X100. Z50.",
        after: "",
        refused: "T I K R Q P L U W",
    },
    Kind {
        name: "lathe G28 reference return",
        before: "G00 X50. Z5.\n",
        block: "G28 U0.",
        after: "",
        refused: "T I K R Q P L X",
    },
    Kind {
        name: "lathe G31 skip",
        before: "G00 X50. Z5.\n",
        block: "G31 X40. F0.2",
        after: "",
        refused: "I K R Q P L U",
    },
    Kind {
        name: "lathe G30",
        before: "G00 X50. Z5.\n",
        block: "G30 U0.",
        after: "",
        refused: "I K L P Q R T X",
    },
    Kind {
        name: "lathe G52",
        before: "",
        block: "G52 Z-5.",
        after: "",
        refused: "I K L P Q R T U W",
    },
    Kind {
        name: "lathe G53",
        before: "",
        block: "G53 X100. Z50.",
        after: "",
        refused: "I K L P Q R T U W",
    },
    // Polar coordinate interpolation (behaviour 14.15, 14.18): the mode's
    // codes stand alone, its moves read the face plane's words.
    Kind {
        name: "G12.1 polar interpolation on",
        before: "G98 G00 X40. Z-1.\n",
        block: "G12.1",
        after: "G01 X20. C10.\nG13.1\n",
        refused: "X U Z W I K R T P Q L",
    },
    Kind {
        name: "G01 in polar interpolation",
        before: "G98 G00 X40. Z-1.\nG12.1\n",
        block: "G01 X20. C10. F100.",
        after: "G13.1\n",
        refused: "I K R Q P L U T",
    },
    Kind {
        name: "G03 in polar interpolation",
        before: "G98 G00 X40. Z-1.\nG12.1\nG01 X20. C5. F100.\n",
        block: "G03 X10. C10. R5.",
        after: "G13.1\n",
        // I and J with R: R is used, with a warning (behaviour 2.13).
        refused: "K Q P L U T -J",
    },
    Kind {
        name: "G13.1 polar interpolation off",
        before: "G98 G00 X40. Z-1.\nG12.1\nG01 X20. C10. F100.\n",
        block: "G13.1",
        after: "G00 X60.\n",
        refused: "X U Z W I K R T P Q L",
    },
    Kind {
        name: "G71 first block (depth of cut, retract)",
        before: "G00 X50. Z2.\n",
        block: "G71 U2. R0.5",
        after: "G71 P10 Q20 U0.4 W0.1\nN10 G00 X30.\nG01 Z-20.\nN20 X50.\n",
        refused: "I K L O Q W X Z -D",
    },
    Kind {
        name: "G71 second block (the contour)",
        before: "G00 X50. Z2.\nG71 U2. R0.5\n",
        block: "G71 P10 Q20 U0.4 W0.1 F0.2",
        after: "N10 G00 X30.\nG01 Z-20.\nN20 X50.\n",
        refused: "I K L O R X Z -D",
    },
    Kind {
        name: "G70 finishing",
        before: "G00 X50. Z2.\nG71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F0.2\nN10 G00 X30.\nG01 Z-20.\nN20 X50.\n",
        block: "G70 P10 Q20",
        after: "",
        refused: "I K L O R U W X Z",
    },
];

/// Each address with a value any block could hold.
const WORDS: &[(Address, &str)] = &[
    (Address::D, "D02"),
    (Address::F, "F200."),
    (Address::H, "H02"),
    (Address::I, "I3."),
    (Address::J, "J3."),
    (Address::K, "K2"),
    (Address::L, "L2"),
    (Address::M, "M08"),
    (Address::N, "N5"),
    (Address::O, "O1234"),
    (Address::P, "P5"),
    (Address::Q, "Q2."),
    (Address::R, "R3."),
    (Address::S, "S500"),
    (Address::T, "T0202"),
    (Address::U, "U1."),
    (Address::W, "W1."),
    (Address::X, "X7."),
    (Address::Y, "Y7."),
    (Address::Z, "Z7."),
    (Address::A, "A1."),
    (Address::B, "B1."),
    (Address::C, "C1."),
    (Address::E, "E1."),
    (Address::CommaC, ",C1."),
    (Address::CommaR, ",R1."),
];

/// What a run did, without the places in the text (the block's text
/// changes with the word added).
fn effect(r: &Run) -> String {
    let last = r.blocks.last().map(|b| &b.state);
    let notes: Vec<&Vec<String>> = r.blocks.iter().map(|b| &b.notes).collect();
    let diagnostics: Vec<(&str, &str)> = r
        .diagnostics
        .iter()
        .map(|d| (d.code, d.message.as_str()))
        .collect();
    let moves: Vec<String> = r
        .moves
        .iter()
        .map(|m| format!("{:?} {:?} {:?}", m.kind, m.from, m.to))
        .collect();
    let events: Vec<String> = r.events.iter().map(|e| format!("{:?}", e.kind)).collect();
    format!(
        "{moves:?} {events:?} {last:?} {notes:?} {diagnostics:?} {}",
        r.block_count
    )
}

/// Adds every address to every block of `kinds` and checks it is refused
/// at its word exactly when the table says so, and otherwise acted on.
fn audit(kinds: &[Kind], setup: &Setup, never: &str) {
    let mut failures = Vec::new();
    let mut checked = 0;
    for kind in kinds {
        let base = format!("{}{}\n{}", kind.before, kind.block, kind.after);
        let base_run = run(&base, setup);
        assert!(
            !base_run
                .diagnostics
                .iter()
                .any(|d| d.is_error() && d.span.line as usize == kind.before.lines().count() + 1),
            "{}: the block itself fails: {:#?}",
            kind.name,
            base_run.diagnostics
        );
        let line = kind.before.lines().count() as u32 + 1;
        // "-E": an address of `never` this kind of block models.
        let own: Vec<&str> = kind.refused.split(' ').collect();
        let refused: Vec<&str> = own
            .iter()
            .copied()
            .filter(|a| !a.starts_with('-'))
            .chain(
                never
                    .split(' ')
                    .filter(|a| !own.contains(&format!("-{a}").as_str())),
            )
            .collect();
        for (address, word) in WORDS {
            let letter = address.letter();
            // A word already in the block is refused as a second one (behaviour 1.10).
            let duplicate = kind.block.split(' ').any(|w| {
                w.starts_with(letter)
                    && w[letter.len()..]
                        .starts_with(|c: char| c == '-' || c == '.' || c.is_ascii_digit())
            });
            let text = format!("{}{} {word}\n{}", kind.before, kind.block, kind.after);
            let column = kind.block.chars().count() as u32 + 2;
            let r = run(&text, setup);
            checked += 1;
            let at_word = r
                .diagnostics
                .iter()
                .find(|d| d.is_error() && d.line == line && d.column == column);
            let want_refused = refused.contains(&letter) || duplicate;
            let outcome = match (at_word, want_refused) {
                (Some(d), true) => {
                    // Refused with a sentence that says so, not a bare code.
                    if d.message.len() < 20 {
                        Some(format!("a bare message: {}", d.message))
                    } else {
                        None
                    }
                }
                (Some(d), false) => Some(format!(
                    "refused ({}: {}), the table says acted on",
                    d.code, d.message
                )),
                (None, true) => Some("not refused, the table says refused".to_string()),
                // Sequence and program numbers are labels (behaviour 1.4).
                (None, false) if matches!(address, Address::N | Address::O) => None,
                (None, false) if effect(&r) == effect(&base_run) => Some(
                    "SILENTLY SKIPPED: no error, and the run is the same without it".to_string(),
                ),
                (None, false) => None,
            };
            if let Some(why) = outcome {
                failures.push(format!("{} + {word}: {why}", kind.name));
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert_eq!(checked, kinds.len() * WORDS.len());
}

#[test]
fn behaviour2_22_every_address_in_every_mill_block_is_acted_on_or_refused() {
    let mut setup = mill(&[(1, 5.0), (2, 10.0)]);
    // G12/G13 are Haas's circular pockets (behaviour 14.12).
    setup.settings.circle_pocket = Some(CirclePocket::Haas);
    audit(MILL, &setup, MILL_NEVER);
}

#[test]
fn behaviour2_22_every_address_in_every_lathe_block_is_acted_on_or_refused() {
    audit(LATHE, &lathe(&[(1, 0.4, -0.2), (2, 0.6, 0.1)]), LATHE_NEVER);
}

#[test]
fn behaviour2_22_every_address_in_haas_polar_interpolation_is_acted_on_or_refused() {
    // Haas's G112 reads Y for the hypothetical axis and moves at rapid too
    // (behaviour 14.15); C is refused there (`polar-words`).
    const HAAS_POLAR: &[Kind] = &[
        Kind {
            name: "G01 in G112",
            before: "G98 G00 X40. Z-1.\nG112\n",
            block: "G01 X10. Y10. F100.",
            after: "G113\n",
            refused: "I K R Q P L U T -Y",
        },
        Kind {
            name: "G00 in G112",
            before: "G98 G00 X40. Z-1.\nG112\n",
            block: "G00 Z1.",
            after: "G113\n",
            refused: "I K R Q P L W T -Y",
        },
    ];
    let mut setup = lathe(&[(1, 0.4, -0.2), (2, 0.6, 0.1)]);
    setup.settings.control = offsetlab::setup::Control::Haas;
    audit(HAAS_POLAR, &setup, LATHE_NEVER);
}

#[test]
fn behaviour2_22_the_known_drops_are_errors_at_their_word() {
    // Each was dropped without a word before (issue 20).
    let lathe = lathe(&[(1, 0.4, -0.2)]);
    for (text, column) in [
        ("G50 X100. Z50. T0101", 16),
        ("G00 X50. Z5.\nG28 U0. T0101", 9),
        ("G04 U1. T0101", 9),
    ] {
        let r = run(text, &lathe);
        let d = r.diagnostics.iter().find(|d| d.is_error()).unwrap();
        assert_eq!((d.code, d.column), ("unused-word", column), "{text}");
        assert!(
            d.message.contains("write the T code in a block of its own"),
            "{}",
            d.message
        );
    }
    let mill = mill(&[(1, 5.0)]);
    for (text, code_column) in [("G92 X0 G43 H01", 8), ("G04 P100 G43 H01", 10)] {
        let r = run(text, &mill);
        let d = r.diagnostics.iter().find(|d| d.is_error()).unwrap();
        assert_eq!(d.code, "unused-word", "{text}");
        // The H word is refused first (it comes first among the words the
        // block does not read); without it, the G43.
        assert!(d.message.contains("H01"), "{}", d.message);
        let without_h = text.replace(" H01", "");
        let r = run(&without_h, &mill);
        let d = r.diagnostics.iter().find(|d| d.is_error()).unwrap();
        assert_eq!(
            (d.code, d.column),
            ("unused-word", code_column),
            "{without_h}"
        );
        assert!(
            d.message
                .contains("G43/G44/G49 and H in a block of their own"),
            "{}",
            d.message
        );
    }
}
