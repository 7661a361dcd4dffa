//! The program buffer: where the page's worker writes the next program
//! straight into the session's memory, or makes it from the last one by an
//! edit, instead of passing it as a string.
//!
//! Why: wasm-bindgen copies a `String` argument into wasm memory a UTF-16
//! unit at a time in JavaScript, and `TextEncoder.encode` and a copy is
//! slower again; `encodeInto` on a view of the buffer writes it in place
//! (the run's share of bench-browser target 3). And a keystroke in a long
//! program would write its whole text again: an edit is spliced into the
//! text kept from the last run instead (bench-browser target 4).
//!
//! The buffer answers `None` (a null address to JavaScript) where it cannot
//! do what is asked — no memory, or an edit of a text it does not hold —
//! and the worker then writes the whole text (`www/worker.js`, `resend`).

/// Programs of up to this many bytes stay in the buffer after their run
/// ([`ProgramBuffer::take`] copies them out), for the next one to be made
/// from by an edit; larger ones (a file of a million blocks) are not held
/// twice.
pub const KEPT_PROGRAM: usize = 8 << 20;

/// The next program's bytes, as the caller wrote or spliced them.
#[derive(Debug, Default)]
pub struct ProgramBuffer {
    bytes: Vec<u8>,
}

impl ProgramBuffer {
    /// Room for a program of up to `capacity` bytes of UTF-8, zeroed, for
    /// the caller to write into before anything else touches the buffer.
    /// None, the buffer left empty, when there is not that much memory.
    pub fn room(&mut self, capacity: usize) -> Option<&mut [u8]> {
        self.bytes = Vec::new();
        self.bytes.try_reserve_exact(capacity).ok()?;
        self.bytes.resize(capacity, 0);
        Some(&mut self.bytes)
    }

    /// Makes the next program from the one held, which is `length` bytes
    /// long: its bytes `from..to` replaced by `insert` zeroed bytes, which
    /// are returned for the caller to write the inserted text into. None,
    /// and the buffer left empty, when the buffer does not hold `length`
    /// bytes (another program, or none kept: the length is how the caller
    /// knows it is the text it means), `from..to` is not within it, or
    /// there is not the memory.
    pub fn splice(
        &mut self,
        length: usize,
        from: usize,
        to: usize,
        insert: usize,
    ) -> Option<&mut [u8]> {
        let len = self.bytes.len();
        let grow = insert.saturating_sub(to.saturating_sub(from));
        if len != length || from > to || to > len || self.bytes.try_reserve(grow).is_err() {
            self.bytes = Vec::new();
            return None;
        }
        self.bytes.splice(from..to, std::iter::repeat_n(0, insert));
        Some(&mut self.bytes[from..from + insert])
    }

    /// The program of the first `length` bytes written (at most the room
    /// asked for; invalid UTF-8 is read with U+FFFD in its place, as the
    /// page's decoder shows it). A program of up to [`KEPT_PROGRAM`] bytes
    /// stays held, for the next one to be spliced from it.
    pub fn take(&mut self, length: usize) -> String {
        self.bytes.truncate(length);
        let bytes = if self.bytes.len() <= KEPT_PROGRAM {
            self.bytes.clone()
        } else {
            std::mem::take(&mut self.bytes)
        };
        String::from_utf8(bytes)
            .unwrap_or_else(|e| String::from_utf8_lossy(e.as_bytes()).into_owned())
    }

    /// Bytes held.
    pub fn len(&self) -> usize {
        self.bytes.len()
    }

    /// True when no program is held.
    pub fn is_empty(&self) -> bool {
        self.bytes.is_empty()
    }
}
