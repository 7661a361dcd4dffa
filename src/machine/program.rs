//! What the machine may ask of the program it runs: the blocks from the one
//! with a given sequence number on (behaviour 15.3). A run streams its
//! blocks one at a time and never holds the program as a tree, so a cycle
//! that reads a contour by sequence number (G70–G73: P and Q) asks the run
//! through [`ProgramText`]; the run answers by reading the text again
//! (`run/sequence.rs`). Subprogram calls by sequence number (M97, GOTO)
//! will ask the same way.

use crate::syntax::Block;

/// The program's text, read again from a sequence number.
pub trait ProgramText {
    /// Hands `each` the blocks of the program from the first one whose
    /// sequence number (N) is `n`, in program order, until `each` returns
    /// false or the program ends. Returns the byte offset where that block
    /// starts, or None when no block has sequence number `n` (then `each`
    /// is not called).
    fn read_from(&mut self, n: u32, each: &mut dyn FnMut(&Block) -> bool) -> Option<u32>;
}

/// A program whose text cannot be read again: no sequence number is found
/// (a machine run block by block without its text, as some tests do).
pub struct NoText;

impl ProgramText for NoText {
    fn read_from(&mut self, _: u32, _: &mut dyn FnMut(&Block) -> bool) -> Option<u32> {
        None
    }
}
