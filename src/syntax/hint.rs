//! Which machine a program is written for, read from words only one kind of
//! machine uses (behaviour 1.24): a program pasted for the wrong machine
//! stops in its first lines with errors that do not say why, so the page and
//! the command offer the other machine instead.
//!
//! A quick look at the first part of the text, not a parse: it reads
//! address letters and their numbers, skips comments, and never fails.

use crate::setup::MachineKind;

/// How much of a program the look reads: enough for any program's first
/// tool, and a bounded cost on a huge one.
const LOOK: usize = 256 * 1024;

/// The other machine a program reads as, and why.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MachineHint {
    /// The machine the program's words belong to.
    pub machine: MachineKind,
    /// What in the program says so, one phrase each.
    pub reasons: Vec<&'static str>,
}

const U_W: &str = "U and W words (the lathe's incremental X and Z)";
const T_FOUR: &str = "four-digit T codes such as T0101 (tool and offset number)";
const G96: &str = "G96 (constant surface speed)";
const G50_S: &str = "G50 S (the spindle speed limit)";
const MRC: &str = "G70/G71/G72 with P and Q (the lathe's repetitive cycles)";
const Y: &str = "Y words";
const H: &str = "H words (tool length offset registers)";
const G43: &str = "G43/G44 (tool length offset)";

/// The machine `text` reads as when it is not `machine`: words of the other
/// machine and none of `machine`'s own (a lathe program with a Y axis, or
/// a mill with a U axis, stays where it is).
pub fn machine_hint(text: &str, machine: MachineKind) -> Option<MachineHint> {
    let mut lathe: Vec<&'static str> = Vec::new();
    let mut mill: Vec<&'static str> = Vec::new();
    let add = |list: &mut Vec<&'static str>, reason| {
        if !list.contains(&reason) {
            list.push(reason);
        }
    };
    let end = text.len().min(LOOK);
    let end = (end..=text.len())
        .find(|&i| text.is_char_boundary(i))
        .unwrap_or(text.len());
    for line in text[..end].lines() {
        let words = words(line);
        let has = |letter: u8| words.iter().any(|w| w.letter == letter);
        let g = |n: u32| words.iter().any(|w| w.letter == b'G' && w.whole == Some(n));
        for w in &words {
            match w.letter {
                b'U' | b'W' => add(&mut lathe, U_W),
                b'T' if w.digits == 4 && w.whole.is_some_and(|t| t % 100 != 0) => {
                    add(&mut lathe, T_FOUR)
                }
                b'Y' => add(&mut mill, Y),
                b'H' => add(&mut mill, H),
                _ => {}
            }
        }
        if g(96) {
            add(&mut lathe, G96);
        }
        if g(50) && has(b'S') {
            add(&mut lathe, G50_S);
        }
        if (g(70) || g(71) || g(72)) && has(b'P') && has(b'Q') {
            add(&mut lathe, MRC);
        }
        if g(43) || g(44) {
            add(&mut mill, G43);
        }
    }
    let (own, other, kind) = match machine {
        MachineKind::Mill => (mill, lathe, MachineKind::Lathe),
        MachineKind::Lathe => (lathe, mill, MachineKind::Mill),
    };
    (own.is_empty() && !other.is_empty()).then_some(MachineHint {
        machine: kind,
        reasons: other,
    })
}

/// An address letter, the whole part of its number (if it has one that
/// fits) and how many digits that part was written with.
struct Look {
    letter: u8,
    whole: Option<u32>,
    digits: u8,
}

/// The words of one line, comments `( … )` left out.
fn words(line: &str) -> Vec<Look> {
    let bytes = line.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        let c = bytes[i].to_ascii_uppercase();
        i += 1;
        // What follows `;` on a line is another dialect's comment as often
        // as a block (behaviour 1.4): not evidence either way.
        if c == b';' {
            break;
        }
        if c == b'(' {
            while i < bytes.len() && bytes[i] != b')' {
                i += 1;
            }
            continue;
        }
        if !c.is_ascii_uppercase() {
            continue;
        }
        while i < bytes.len() && bytes[i] == b' ' {
            i += 1;
        }
        if i < bytes.len() && matches!(bytes[i], b'+' | b'-') {
            i += 1;
        }
        let start = i;
        let mut whole: u32 = 0;
        let mut fits = true;
        while i < bytes.len() && bytes[i].is_ascii_digit() {
            match whole
                .checked_mul(10)
                .and_then(|w| w.checked_add(u32::from(bytes[i] - b'0')))
            {
                Some(w) => whole = w,
                None => fits = false,
            }
            i += 1;
        }
        let digits = (i - start).min(255) as u8;
        let fraction = i + 1 < bytes.len() && bytes[i] == b'.' && bytes[i + 1].is_ascii_digit();
        // A letter without a number is part of a word (IF, GOTO, a
        // sentence), not an address.
        if digits == 0 && !fraction {
            continue;
        }
        out.push(Look {
            letter: c,
            whole: (digits > 0 && fits).then_some(whole),
            digits,
        });
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn words_skip_comments_and_read_numbers() {
        let w = words("N10 G01 (U5. IS NOT A WORD) T0101 X-1.5 y.5 ; W1. see www.x");
        let letters: Vec<u8> = w.iter().map(|w| w.letter).collect();
        assert_eq!(letters, b"NGTXY".to_vec());
        assert!(words("GOTO W. IF").is_empty());
        assert_eq!((w[2].whole, w[2].digits), (Some(101), 4));
        assert_eq!(w[4].whole, None);
    }
}
