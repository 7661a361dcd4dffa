//! The programs of a text by number (behaviour 19.1): where each `O`/`:`
//! header stands, found once when a run first calls a subprogram. A file
//! of several programs (behaviour 1.21) is a program memory: the first
//! program runs, the others are there to be called by M98.

/// A program header: its number and where its line starts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Header {
    /// The number after `O` or `:`.
    pub number: u32,
    /// Byte offset of the header's line start.
    pub pos: usize,
    /// Its 1-based line.
    pub line: u32,
}

/// Most digits of a program number (Fanuc's 8-digit program numbers).
const MAX_DIGITS: usize = 8;

/// The headers of `text` in order: each line whose first character past
/// blanks is `O` or `:` followed by a number (the header a control stores
/// a program under; `O` inside a line is an O word of a block, which
/// behaviour 1.21 reads as a header too, but no program is written so).
pub fn program_headers(text: &str) -> Vec<Header> {
    let bytes = text.as_bytes();
    let mut headers = Vec::new();
    let (mut pos, mut line) = (0usize, 1u32);
    if text.starts_with('\u{feff}') {
        pos = 3;
    }
    while pos < bytes.len() {
        let start = pos;
        let mut i = pos;
        while i < bytes.len() && matches!(bytes[i], b' ' | b'\t') {
            i += 1;
        }
        if i < bytes.len() && matches!(bytes[i], b'O' | b'o' | b':') {
            let digits = bytes[i + 1..]
                .iter()
                .take_while(|c| c.is_ascii_digit())
                .count();
            let after = bytes.get(i + 1 + digits).copied();
            let ends = !after.is_some_and(|c| c.is_ascii_alphabetic() && c != b'N' && c != b'n');
            if (1..=MAX_DIGITS).contains(&digits) && ends {
                let number = text[i + 1..i + 1 + digits].parse().unwrap_or(0);
                headers.push(Header {
                    number,
                    pos: start,
                    line,
                });
            }
        }
        // On to the next line (`\r\n`, `\n` or a lone `\r`).
        while pos < bytes.len() && !matches!(bytes[pos], b'\n' | b'\r') {
            pos += 1;
        }
        if pos < bytes.len() {
            pos += if bytes[pos] == b'\r' && bytes.get(pos + 1) == Some(&b'\n') {
                2
            } else {
                1
            };
            line += 1;
        }
    }
    headers
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn behaviour19_1_headers_are_found_by_number_with_their_lines() {
        let text = "%\nO1000 (MAIN)\nG00 X1.\nM30\n%\n:2000\r\nM99\n  O0030N10\nX1. O5\nO12A\n";
        let found: Vec<(u32, u32)> = program_headers(text)
            .iter()
            .map(|h| (h.number, h.line))
            .collect();
        // Line 2 O1000; line 6 :2000 (after a \r\n line end); line 8
        // O0030 with its N on the line. `X1. O5` is not at the line's
        // start; `O12A` is a name, not a number.
        assert_eq!(found, vec![(1000, 2), (2000, 6), (30, 8)]);
        assert_eq!(program_headers(text)[1].pos, 29);
    }
}
