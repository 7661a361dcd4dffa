//! Diagnostics: every problem the parser, the machine or the setup finds is a
//! value with a severity, a stable code, a message and a place in the text.
//! Nothing in the core panics on bad input; it reports one of these instead.

use serde::Serialize;

/// How bad a diagnostic is. An error stops execution at that block (a control
/// raises an alarm); a warning never stops anything.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Severity {
    /// Execution stops here.
    Error,
    /// Worth knowing; execution goes on.
    Warning,
}

impl Severity {
    /// The lower-case name used in JSON and in `check` output.
    pub fn as_str(self) -> &'static str {
        match self {
            Severity::Error => "error",
            Severity::Warning => "warning",
        }
    }
}

/// A byte range of the program text and the 1-based line it starts on.
/// Blocks and words never span lines, so one line number is enough.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Span {
    /// Byte offset of the first byte.
    pub start: u32,
    /// Byte offset one past the last byte.
    pub end: u32,
    /// 1-based line number of `start`.
    pub line: u32,
}

impl Span {
    /// A span from byte offsets and a line number.
    pub fn new(start: usize, end: usize, line: u32) -> Span {
        Span {
            start: clamp_u32(start),
            end: clamp_u32(end),
            line,
        }
    }

    /// 1-based columns (in characters) of the start and the end of the span on
    /// its line. `text` must be the text the span was made from.
    pub fn columns(&self, text: &str) -> (u32, u32) {
        let bytes = text.as_bytes();
        let start = (self.start as usize).min(bytes.len());
        let end = (self.end as usize).clamp(start, bytes.len());
        let line_start = bytes[..start]
            .iter()
            .rposition(|&b| b == b'\n' || b == b'\r')
            .map_or(bom(text).min(start), |p| p + 1);
        let col = count_chars(&bytes[line_start..start]) + 1;
        let end_col = col + count_chars(&bytes[start..end]);
        (clamp_u32(col), clamp_u32(end_col))
    }
}

/// Columns of many spans in one pass over the text: spans asked for in
/// increasing order of their start cost the bytes between them, not a scan
/// back to their line's start each (a megabyte-long line with a thousand
/// diagnostics, or a line of many `;`-separated blocks, would be quadratic;
/// `tests/cli_robustness.rs` runs such lines). A span before the last one asked for falls
/// back to [`Span::columns`].
pub struct Columns<'t> {
    text: &'t str,
    /// Bytes read so far.
    pos: usize,
    /// Characters from the start of the line to `pos`.
    chars: usize,
}

impl<'t> Columns<'t> {
    /// A cursor at the start of `text`.
    pub fn new(text: &'t str) -> Columns<'t> {
        Columns {
            text,
            pos: bom(text),
            chars: 0,
        }
    }

    /// The same as [`Span::columns`] on the cursor's text.
    pub fn of(&mut self, span: Span) -> (u32, u32) {
        let bytes = self.text.as_bytes();
        let start = (span.start as usize).min(bytes.len());
        let end = (span.end as usize).clamp(start, bytes.len());
        if start < self.pos {
            return span.columns(self.text);
        }
        for &b in &bytes[self.pos..start] {
            if b == b'\n' || b == b'\r' {
                self.chars = 0;
            } else if (b & 0xC0) != 0x80 {
                self.chars += 1;
            }
        }
        self.pos = start;
        let col = self.chars + 1;
        let end_col = col + count_chars(&bytes[start..end]);
        (clamp_u32(col), clamp_u32(end_col))
    }
}

/// The bytes of a UTF-8 byte order mark opening `text` (3, or 0 without
/// one): an encoding mark, not a character of the first line's columns.
fn bom(text: &str) -> usize {
    if text.starts_with('\u{feff}') { 3 } else { 0 }
}

/// Characters in a byte slice that may start or end inside a UTF-8 sequence
/// (continuation bytes are not counted).
fn count_chars(bytes: &[u8]) -> usize {
    bytes.iter().filter(|&&b| (b & 0xC0) != 0x80).count()
}

fn clamp_u32(n: usize) -> u32 {
    u32::try_from(n).unwrap_or(u32::MAX)
}

/// One problem found in a program or its setup.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Diagnostic {
    /// Error or warning.
    pub severity: Severity,
    /// Stable identifier (kebab-case); tools and tests match on it.
    pub code: &'static str,
    /// A sentence for a person, saying what is wrong and how to write it.
    pub message: String,
    /// 1-based line (0 for problems that belong to no line, such as setup).
    pub line: u32,
    /// 1-based column of the first character, in characters.
    pub column: u32,
    /// 1-based column one past the last character.
    pub end_column: u32,
    /// Where in the text (bytes).
    #[serde(skip)]
    pub span: Span,
}

impl Diagnostic {
    /// An error at `span`. Columns are filled in by [`Diagnostic::locate`].
    pub fn error(code: &'static str, span: Span, message: impl Into<String>) -> Diagnostic {
        Diagnostic::new(Severity::Error, code, span, message)
    }

    /// A warning at `span`.
    pub fn warning(code: &'static str, span: Span, message: impl Into<String>) -> Diagnostic {
        Diagnostic::new(Severity::Warning, code, span, message)
    }

    fn new(severity: Severity, code: &'static str, span: Span, message: impl Into<String>) -> Self {
        Diagnostic {
            severity,
            code,
            message: message.into(),
            line: span.line,
            column: 0,
            end_column: 0,
            span,
        }
    }

    /// Fills in line and columns from the text the span refers to.
    pub fn locate(&mut self, text: &str) {
        if self.span.line == 0 {
            return;
        }
        let (column, end_column) = self.span.columns(text);
        self.line = self.span.line;
        self.column = column;
        self.end_column = end_column;
    }

    /// True for errors.
    pub fn is_error(&self) -> bool {
        self.severity == Severity::Error
    }
}

/// Sorts diagnostics by place, errors first at the same place, and fills in
/// their columns (in one pass over the text).
pub fn finish(diagnostics: &mut [Diagnostic], text: &str) {
    diagnostics.sort_by(|a, b| {
        (a.span.line, a.span.start, a.severity).cmp(&(b.span.line, b.span.start, b.severity))
    });
    let mut columns = Columns::new(text);
    for d in diagnostics.iter_mut() {
        if d.span.line != 0 {
            (d.column, d.end_column) = columns.of(d.span);
            d.line = d.span.line;
        }
    }
}

/// `n` with thousands separated (`1,000,000`), as a message writes it.
pub(crate) fn thousands(n: u64) -> String {
    let digits = n.to_string();
    let mut out = String::new();
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i).is_multiple_of(3) {
            out.push(',');
        }
        out.push(c);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn columns_count_characters_not_bytes() {
        let text = "(µm)\nG01 X1.";
        // "X1." starts at byte 10 on line 2 (µ is two bytes): column 5.
        let span = Span::new(10, 13, 2);
        assert_eq!(span.columns(text), (5, 8));
        let span = Span::new(1, 3, 1);
        assert_eq!(span.columns(text), (2, 3));
    }

    #[test]
    fn the_cursor_agrees_with_columns_in_any_order() {
        let text = "(µm)\nG01 X1.\r\nY2.;Z3.\rX\u{e9}\u{e9} Y4.";
        let spans: Vec<Span> = (0..text.len())
            .flat_map(|s| (s..=text.len()).map(move |e| Span::new(s, e, 1)))
            .collect();
        let mut cursor = Columns::new(text);
        for span in &spans {
            assert_eq!(cursor.of(*span), span.columns(text), "{span:?}");
        }
        // Backwards (the fallback).
        for span in spans.iter().rev().step_by(7) {
            assert_eq!(cursor.of(*span), span.columns(text), "{span:?}");
        }
    }

    #[test]
    fn many_diagnostics_at_the_end_of_a_long_line_are_located_in_linear_time() {
        let text = format!("({}) {}", "A".repeat(20_000_000), "X ".repeat(1000));
        let mut diagnostics: Vec<Diagnostic> = (0..1000)
            .map(|i| {
                let at = 20_000_003 + 2 * i;
                Diagnostic::error("missing-number", Span::new(at, at + 1, 1), "X")
            })
            .collect();
        let start = std::time::Instant::now();
        finish(&mut diagnostics, &text);
        assert!(start.elapsed().as_secs() < 10, "{:?}", start.elapsed());
        assert_eq!(diagnostics[999].column, 20_000_003 + 2 * 999 + 1);
    }

    #[test]
    fn a_byte_order_mark_opening_the_text_takes_no_column() {
        let text = "\u{feff}G01 X1.\nY2.";
        // "X1." starts at byte 7 (the mark is three bytes): column 5.
        assert_eq!(Span::new(7, 10, 1).columns(text), (5, 8));
        assert_eq!(Columns::new(text).of(Span::new(7, 10, 1)), (5, 8));
        assert_eq!(Span::new(11, 14, 2).columns(text), (1, 4));
    }

    #[test]
    fn columns_after_cr_line_end() {
        let text = "G00\rX1.";
        assert_eq!(Span::new(4, 7, 2).columns(text), (1, 4));
    }
}
