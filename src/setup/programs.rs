//! The document's library of programs (behaviour 9.10, 19.10): programs
//! kept by number beside the main program, as a control's memory keeps
//! them. Each text opens with its own header, so a library program's line
//! numbers are those of the text the user wrote and the header the
//! control stores it under is there to see.

use std::collections::BTreeMap;

use crate::diag::{Diagnostic, Span};

/// Largest program number (Fanuc's eight digits, behaviour 19.1).
pub const MAX_PROGRAM_NUMBER: u32 = 99_999_999;

/// Most programs a library holds.
pub const MAX_PROGRAMS: usize = 1000;

/// The number of the header that opens `text` (past blank lines and `%`
/// lines, 1.3): `O`/`:` and one to eight digits not followed by a letter
/// other than N (the rule of 19.1's headers). None when the text's first
/// block is not a header.
pub fn opening_header(text: &str) -> Option<u32> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let line = text
        .lines()
        .map(str::trim)
        .find(|l| !l.is_empty() && *l != "%")?;
    let rest = line.strip_prefix(['O', 'o', ':'])?;
    let digits = rest.bytes().take_while(u8::is_ascii_digit).count();
    let after = rest.as_bytes().get(digits).copied();
    let ends = !after.is_some_and(|c| c.is_ascii_alphabetic() && c != b'N' && c != b'n');
    if !(1..=8).contains(&digits) || !ends {
        return None;
    }
    rest[..digits].parse().ok()
}

/// Every problem with a library: a number outside 1 to 99999999, too
/// many programs, or a text that does not open with its number's header.
pub(super) fn check(programs: &BTreeMap<u32, String>) -> Vec<Diagnostic> {
    let mut out = Vec::new();
    let mut bad = |m: String| out.push(Diagnostic::error("setup-program", Span::default(), m));
    if programs.len() > MAX_PROGRAMS {
        bad(format!(
            "programs: {} programs; a library holds at most {MAX_PROGRAMS}",
            programs.len()
        ));
    }
    for (n, text) in programs {
        if *n == 0 || *n > MAX_PROGRAM_NUMBER {
            bad(format!(
                "programs: {n} is not a program number (1 to {MAX_PROGRAM_NUMBER})"
            ));
            continue;
        }
        match opening_header(text) {
            Some(h) if h == *n => {}
            Some(h) => bad(format!(
                "programs: program {n} opens with the header of O{h:04}; write O{n:04} as its first line"
            )),
            None => bad(format!(
                "programs: program {n} does not open with its header; write O{n:04} as its first line"
            )),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn behaviour9_10_a_library_program_opens_with_its_own_header() {
        assert_eq!(opening_header("O1002\nG01 X1."), Some(1002));
        assert_eq!(opening_header("%\n  :12 (NAME)\nM99"), Some(12));
        assert_eq!(opening_header("G01 X1.\nO1002"), None);
        assert_eq!(opening_header("OX1"), None);
        let mut p = BTreeMap::new();
        p.insert(1002, "O1002\nM99".to_string());
        assert!(check(&p).is_empty());
        p.insert(1003, "O1004\nM99".to_string());
        p.insert(1005, "G01 X1.\nM99".to_string());
        p.insert(0, "O0\nM99".to_string());
        let codes: Vec<String> = check(&p).into_iter().map(|d| d.message).collect();
        assert_eq!(codes.len(), 3, "{codes:?}");
        assert!(codes[1].contains("O1004"), "{codes:?}");
    }
}
