//! LinuxCNC's `%` lines (behaviour 22.19; rs274's `read_text`): a `%` is
//! the tape mark only on a line of its own, and only as the text's first
//! non-blank line or, when the text opened so, as the line that ends it.
//! Any other `%` is a character rs274 refuses ("Bad character '%' used"),
//! where the Fanuc family reads it as the tape's end (behaviour 1.3).

use super::{Block, Blocks, Span, Tape};

impl Blocks<'_> {
    /// For a `%` at `at` under the LinuxCNC profile: the end of its line
    /// when rs274 would refuse it there (the block made an error), None when
    /// it is a tape mark.
    pub(super) fn linuxcnc_bad_percent(
        &mut self,
        at: usize,
        line: u32,
        block: &mut Block,
    ) -> Option<usize> {
        let bytes = self.text.as_bytes();
        let end = bytes[at..]
            .iter()
            .position(|&c| c == b'\n' || c == b'\r')
            .map_or(bytes.len(), |p| at + p);
        let alone = bytes[at + 1..end].iter().all(|c| matches!(c, b' ' | b'\t'));
        let first = bytes[..at].iter().all(u8::is_ascii_whitespace);
        let opened = || bytes.iter().find(|c| !c.is_ascii_whitespace()) == Some(&b'%');
        let why = match (first, self.tape) {
            _ if !alone => "text follows the `%` on its line, and a tape mark stands alone",
            (true, _) => return None,
            (false, Tape::Started | Tape::Reading) if opened() => return None,
            (false, Tape::Ended) => return None,
            _ => "the text did not open with a `%` line, so a `%` cannot end it",
        };
        block.clear();
        block.skip = false;
        block.error = false;
        block.speaks = false;
        block.span = Span::new(at, end, line);
        let msg = format!(
            "%: {why}; LinuxCNC refuses it here (rs274: \"Bad character '%' used\"): end the program with M2 or M30, or open it with a line of `%` alone"
        );
        self.error_span(block, "bad-character", Span::new(at, at + 1, line), &msg);
        self.tape = Tape::Reading;
        Some(end)
    }
}
