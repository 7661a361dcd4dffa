//! What the machine may ask of the program it runs: the blocks from the one
//! with a given sequence number on (behaviour 15.3). A run streams its
//! blocks one at a time and never holds the program as a tree, so a cycle
//! that reads a contour by sequence number (G70–G73: P and Q) asks the run
//! through [`ProgramText`]; the run answers by reading the text again
//! (`run/sequence.rs`). Subprogram calls and returns (M98, M97, M99 P:
//! behaviour 19) ask it whether their target exists before the run jumps.

use crate::syntax::Block;

/// The program's text, read again from a sequence number.
pub trait ProgramText {
    /// Hands `each` the blocks of the program from the first one whose
    /// sequence number (N) is `n`, in program order, until `each` returns
    /// false or the program ends. Returns the byte offset where that block
    /// starts, or None when no block has sequence number `n` (then `each`
    /// is not called).
    fn read_from(&mut self, n: u32, each: &mut dyn FnMut(&Block) -> bool) -> Option<u32>;

    /// True when program O`n` is in the program memory: the text's
    /// programs and the setup's (behaviour 19.1).
    fn has_program(&mut self, _n: u32) -> bool {
        false
    }

    /// True when the program being read has a block with sequence number
    /// `n` (M97's target, behaviour 19.5).
    fn has_local(&mut self, _n: u32) -> bool {
        false
    }

    /// True when the program M99 returns to (the caller, or the main
    /// program itself) has a block with sequence number `n` (behaviour
    /// 19.4).
    fn has_return(&mut self, _n: u32) -> bool {
        false
    }

    /// The text of the block at `span` as written (a comment a code reads:
    /// Haas G47's text, behaviour 14.20); None when the text is not kept.
    fn block_text(&self, _span: crate::diag::Span) -> Option<&str> {
        None
    }

    /// How many subprogram calls are open (0 in the main program).
    fn depth(&self) -> usize {
        0
    }
}

/// A program whose text cannot be read again: no sequence number is found
/// (a machine run block by block without its text, as some tests do).
pub struct NoText;

impl ProgramText for NoText {
    fn read_from(&mut self, _: u32, _: &mut dyn FnMut(&Block) -> bool) -> Option<u32> {
        None
    }
}

impl super::Machine {
    /// LinuxCNC's comments that speak (behaviour 22.2): `(MSG,text)` shows
    /// its text to the operator, `(DEBUG,text)` and `(PRINT,text)` print it;
    /// each is a note of its block, DEBUG's only while #5599 is not 0.
    /// Other comments say nothing.
    #[cold]
    #[inline(never)]
    pub(crate) fn comment_messages(
        &self,
        b: &Block,
        out: &mut super::Out,
        program: &dyn ProgramText,
    ) {
        let Some(text) = program.block_text(b.span) else {
            return;
        };
        let mut rest = text;
        while let Some(open) = rest.find('(') {
            let inner = &rest[open + 1..];
            let close = inner.find(')').unwrap_or(inner.len());
            let comment = &inner[..close];
            rest = &inner[close..];
            let Some((head, said)) = comment.split_once(',') else {
                continue;
            };
            let head = head.trim();
            let what = ["MSG", "DEBUG", "PRINT"]
                .into_iter()
                .find(|k| head.eq_ignore_ascii_case(k));
            if let Some(kind) = what {
                if kind == "DEBUG" && self.debug_switch() == 0.0 {
                    out.note(|| {
                        format!(
                            "(DEBUG) silent: #5599 is 0, so LinuxCNC does not show \"{}\"",
                            said.trim()
                        )
                    });
                    continue;
                }
                let caveat = if kind != "MSG" && said.contains('#') {
                    " (offsetlab shows it as written, without the parameters' values)"
                } else {
                    ""
                };
                out.note(|| format!("({kind}) {}{caveat}", said.trim()));
            }
        }
    }
}
