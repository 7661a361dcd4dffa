//! The typed result of parsing: words (an address and its value, with a
//! span) grouped into blocks.

use serde::Serialize;

use super::codes::{Code, CodeTable, Codes, GCode, Group, MCode};
use crate::diag::Span;
use crate::setup::MachineKind;

/// The address letters offsetlab reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[allow(missing_docs)]
pub enum Address {
    D,
    F,
    G,
    H,
    I,
    J,
    K,
    L,
    M,
    N,
    O,
    P,
    Q,
    R,
    S,
    T,
    U,
    W,
    X,
    Y,
    Z,
    /// Rotary axis about X (mill) (behaviour 1.7).
    A,
    /// Rotary axis about Y (mill).
    B,
    /// Rotary axis about Z; on the lathe also the chamfer word of some
    /// controls.
    C,
    /// Thread lead (lathe, inch threading), Haas G187's corner tolerance.
    E,
    /// `,C`: chamfer at the end of a G01 block (Fanuc "optional angle
    /// chamfering").
    CommaC,
    /// `,R`: corner rounding at the end of a G01 block.
    CommaR,
    /// `@`: LinuxCNC's polar distance of the XY end point (behaviour 22.12).
    PolarDist,
    /// `^`: LinuxCNC's polar angle of the XY end point, degrees (behaviour 22.12).
    PolarAngle,
}

/// How a word's number is read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WordKind {
    /// Always an integer, no decimal point (G M N O T D H S P L; behaviour 1.13).
    Integer,
    /// Feed rate: read in units with or without a decimal point (behaviour 1.14).
    Feed,
    /// Dimension words X Y Z U W I J K R Q, A B C E and `,C` `,R`: decimal
    /// input applies (behaviour 1.15).
    Dimension,
}

impl Address {
    /// Number of addresses.
    pub const COUNT: usize = 29;

    /// Every address, in declaration order (`ALL[a as usize] == a`).
    pub const ALL: [Address; Address::COUNT] = {
        use Address::*;
        [
            D, F, G, H, I, J, K, L, M, N, O, P, Q, R, S, T, U, W, X, Y, Z, A, B, C, E, CommaC,
            CommaR, PolarDist, PolarAngle,
        ]
    };

    /// The address for a byte of program text, a letter of either case, if
    /// the one-pass reading reads it (all but O, behaviour 1.21): one load
    /// from a table (the parser's dispatch on a word's letter).
    #[inline]
    pub fn from_byte(c: u8) -> Option<Address> {
        const BY_BYTE: [Option<Address>; 256] = {
            let mut table = [None; 256];
            let mut c = 0;
            while c < 256 {
                table[c] = Address::from_letter((c as u8).to_ascii_uppercase());
                c += 1;
            }
            // A program header (O, or `:` in ISO code) is read in two passes,
            // where the programs of a file are told apart (behaviour 1.21):
            // ordinary blocks pay nothing for it.
            table[b'O' as usize] = None;
            table[b'o' as usize] = None;
            // LinuxCNC's polar words are lexed only under its profile, in
            // the two-pass reading (behaviour 22.12).
            table[b'@' as usize] = None;
            table[b'^' as usize] = None;
            table
        };
        BY_BYTE[usize::from(c)]
    }

    /// The address for an upper-case letter, if offsetlab reads it.
    pub const fn from_letter(c: u8) -> Option<Address> {
        use Address::*;
        Some(match c {
            b'D' => D,
            b'F' => F,
            b'G' => G,
            b'H' => H,
            b'I' => I,
            b'J' => J,
            b'K' => K,
            b'L' => L,
            b'M' => M,
            b'N' => N,
            b'O' => O,
            b'P' => P,
            b'Q' => Q,
            b'R' => R,
            b'S' => S,
            b'T' => T,
            b'U' => U,
            b'W' => W,
            b'X' => X,
            b'Y' => Y,
            b'Z' => Z,
            b'A' => A,
            b'B' => B,
            b'C' => C,
            b'E' => E,
            b'@' => PolarDist,
            b'^' => PolarAngle,
            _ => return None,
        })
    }

    /// The comma word written `,` + this letter (either case), if offsetlab
    /// reads it: `,C` and `,R`.
    #[inline]
    pub const fn comma(c: u8) -> Option<Address> {
        match c.to_ascii_uppercase() {
            b'C' => Some(Address::CommaC),
            b'R' => Some(Address::CommaR),
            _ => None,
        }
    }

    /// The address as written: its letter, or `,C` / `,R`.
    pub fn letter(self) -> &'static str {
        use Address::*;
        match self {
            D => "D",
            F => "F",
            G => "G",
            H => "H",
            I => "I",
            J => "J",
            K => "K",
            L => "L",
            M => "M",
            N => "N",
            O => "O",
            P => "P",
            Q => "Q",
            R => "R",
            S => "S",
            T => "T",
            U => "U",
            W => "W",
            X => "X",
            Y => "Y",
            Z => "Z",
            A => "A",
            B => "B",
            C => "C",
            E => "E",
            CommaC => ",C",
            CommaR => ",R",
            PolarDist => "@",
            PolarAngle => "^",
        }
    }

    /// How the number of this address is read: one load from a table
    /// (every word asks; a `match` here cost the parser several percent of
    /// the `check` instruction count in docs/performance.md, depending on
    /// what the compiler inlined around it).
    #[inline]
    pub fn kind(self) -> WordKind {
        const KINDS: [WordKind; Address::COUNT] = {
            let mut kinds = [WordKind::Dimension; Address::COUNT];
            let mut i = 0;
            while i < Address::COUNT {
                kinds[i] = Address::ALL[i].kind_of();
                i += 1;
            }
            kinds
        };
        KINDS[self as usize]
    }

    const fn kind_of(self) -> WordKind {
        use Address::*;
        match self {
            G | M | N | O | T | D | H | S | P | L => WordKind::Integer,
            F => WordKind::Feed,
            X | Y | Z | U | W | I | J | K | R | Q | A | B | C | E | CommaC | CommaR | PolarDist
            | PolarAngle => WordKind::Dimension,
        }
    }

    pub(super) fn bit(self) -> u32 {
        1 << (self as u32)
    }
}

/// One word: an address and its value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Word {
    /// The address letter.
    pub address: Address,
    /// The value: dimension words in program units after decimal input;
    /// integers exact; a G code's tenths digit after the point.
    pub value: f64,
    /// A decimal point was written.
    pub point: bool,
    /// Where the word is (letter through number).
    pub span: Span,
}

impl Word {
    /// The value of an integer word (the parser has checked its range).
    pub fn int(&self) -> u32 {
        self.value as u32
    }

    /// The code of a G word.
    pub fn gcode(&self) -> GCode {
        // Nearly every G code is a whole number: it needs no `trunc` and
        // `round` (library calls on x86-64).
        let whole = self.value as u16;
        if f64::from(whole) == self.value {
            return GCode {
                major: whole,
                minor: 0,
            };
        }
        let major = self.value.trunc();
        GCode {
            major: major as u16,
            minor: ((self.value - major) * 10.0).round() as u8,
        }
    }
}

/// One block: the words between two end-of-block characters.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Block {
    /// The block's text, from its first to its last non-blank character.
    pub span: Span,
    /// The block starts with `/` (optional block skip).
    pub skip: bool,
    /// The words, in text order (add them with [`Block::push`], which keeps
    /// the lookup by address).
    pub words: Vec<Word>,
    /// A parse error was reported in this block: execution stops here.
    pub error: bool,
    /// A LinuxCNC comment that speaks, `(MSG,…)`, `(DEBUG,…)` or
    /// `(PRINT,…)`, is in the block (behaviour 22.2): the run says it.
    pub speaks: bool,
    /// Per address, 1 + the index of its (first) word, or 0: the machine
    /// looks words up by address many times per block.
    slots: [u8; Address::COUNT],
    /// The addresses of all the words, a bit each ([`Address::bit`]).
    addresses: u32,
    /// The block's G codes, resolved by the parser (which refuses a second
    /// one of a group), so the machine need not do it again.
    codes: Codes,
    /// Per G-code modal group, 1 + the index of the block's G word of that
    /// group (for the word's span and text), or 0: none, or past the first
    /// 65,534 words (then [`Block::group_word`] looks for it). Two bytes, not
    /// four: the block is handed between threads in batches (the 1M-block
    /// `check`, target 6 in docs/performance.md).
    groups: [u16; Group::COUNT],
    /// The table the parser read the block's G numbers with.
    pub(super) table: CodeTable,
    /// The groups of the block's G codes, a bit each (by [`Group::index`]).
    group_bits: u32,
    /// The block's Custom Macro B part (behaviour 20.8): a statement, and
    /// the words whose value is a variable or an expression; None in a
    /// block without macro syntax.
    pub macros: Option<Box<super::macro_words::MacroBlock>>,
}

impl Block {
    /// Empties the block for reuse.
    pub fn clear(&mut self) {
        self.words.clear();
        self.slots = [0; Address::COUNT];
        self.addresses = 0;
        self.codes.clear();
        self.groups = [0; Group::COUNT];
        self.group_bits = 0;
        // A test, and the drop out of line: nearly every block has no macro
        // part, and an inline drop here cost every block (the `check`
        // instruction count in docs/performance.md).
        if self.macros.is_some() {
            self.clear_macros();
        }
    }

    #[cold]
    #[inline(never)]
    fn clear_macros(&mut self) {
        self.macros = None;
    }

    /// Notes that the next word pushed is the block's G code `code`, of
    /// `group` (its [`Code::group`]).
    #[inline(always)]
    pub(super) fn set_code(&mut self, code: Code, group: Group) {
        self.codes.set(code, group);
        self.groups[group.index()] = u16::try_from(self.words.len() + 1).unwrap_or(0);
        self.group_bits |= 1 << group.index();
    }

    /// The block's G codes, one typed value per modal group.
    #[inline]
    pub fn codes(&self) -> &Codes {
        &self.codes
    }

    /// Where the block's G code of a group is written (the block's span if it
    /// has none).
    pub fn code_span(&self, group: Group) -> Span {
        self.group_word(group).map_or(self.span, |w| w.span)
    }

    /// True if the block has a G code of this modal group.
    #[inline]
    pub fn holds_group(&self, group: Group) -> bool {
        self.group_bits & 1 << group.index() != 0
    }

    /// The G word of a modal group.
    pub fn group_word(&self, group: Group) -> Option<&Word> {
        match self.groups[group.index()] {
            0 if self.holds_group(group) => self.words.iter().find(|w| {
                w.address == Address::G
                    && Code::of(self.table, w.gcode()).is_some_and(|c| c.group() == group)
            }),
            0 => None,
            i => self.words.get(usize::from(i) - 1),
        }
    }

    /// The block without the words `drop` picks, its G codes as they
    /// were (a subprogram call's block runs its other words without the
    /// call's M, P and L: behaviour 19.3).
    pub fn without(&self, drop: impl Fn(&Word) -> bool) -> Block {
        let mut b = Block {
            words: Vec::with_capacity(self.words.len()),
            slots: [0; Address::COUNT],
            addresses: 0,
            groups: [0; Group::COUNT],
            ..self.clone()
        };
        for w in self.words.iter().filter(|w| !drop(w)) {
            let group = (w.address == Address::G)
                .then(|| Code::of(self.table, w.gcode()))
                .flatten()
                .map(|c| c.group());
            if let Some(group) = group {
                b.groups[group.index()] = u16::try_from(b.words.len() + 1).unwrap_or(0);
            }
            b.push(*w);
        }
        b
    }

    /// Appends a word.
    #[inline(always)]
    pub fn push(&mut self, word: Word) {
        self.addresses |= word.address.bit();
        let slot = &mut self.slots[word.address as usize];
        if *slot == 0 && self.words.len() < usize::from(u8::MAX) {
            *slot = self.words.len() as u8 + 1;
        }
        self.words.push(word);
    }

    /// The word with this address (for G and M, the first one).
    pub fn get(&self, address: Address) -> Option<&Word> {
        match self.slots[address as usize] {
            0 => None,
            i => self.words.get(usize::from(i) - 1),
        }
    }

    /// The value of the word with this address.
    pub fn value(&self, address: Address) -> Option<f64> {
        self.get(address).map(|w| w.value)
    }

    /// True if the block has a word with this address.
    pub fn has(&self, address: Address) -> bool {
        self.get(address).is_some()
    }

    /// True if any word has this address. Unlike [`Block::has`] this counts
    /// every word (a slot holds only the first 255): a cheap test before
    /// a loop over the words.
    pub fn holds(&self, address: Address) -> bool {
        self.addresses & address.bit() != 0
    }

    /// True if any word of the block has one of these addresses.
    #[inline]
    pub fn holds_any(&self, addresses: &[Address]) -> bool {
        let words = addresses.iter().fold(0, |bits, a| bits | a.bit());
        self.addresses & words != 0
    }

    /// The first word whose address is not one of `allowed`, if any: a
    /// cheap test first, then a look at the words.
    #[inline]
    pub fn first_outside(&self, allowed: &[Address]) -> Option<&Word> {
        let mask = allowed.iter().fold(0, |bits, a| bits | a.bit());
        if self.addresses & !mask == 0 {
            return None;
        }
        self.words.iter().find(|w| mask & w.address.bit() == 0)
    }

    /// True if every word of the block has one of these addresses and every
    /// G code is in one of these groups: a cheap test that a block needs
    /// none of the handling of the others.
    #[inline]
    pub fn holds_only(&self, addresses: &[Address], groups: &[Group]) -> bool {
        let words = addresses.iter().fold(0, |bits, a| bits | a.bit());
        let codes = groups.iter().fold(0, |bits, g| bits | 1 << g.index());
        self.addresses & !words == 0 && self.group_bits & !codes == 0
    }

    /// The G codes of the block with their words.
    pub fn gcodes(&self) -> impl Iterator<Item = (GCode, &Word)> {
        self.words
            .iter()
            .filter(|w| w.address == Address::G)
            .map(|w| (w.gcode(), w))
    }

    /// The M codes of the block, in text order, as this machine reads them
    /// (the parser checked their groups with the same [`MCode::of`]; they
    /// are read from the words again because few blocks have any, and
    /// keeping them cost every block).
    pub fn mcodes(&self, machine: MachineKind) -> impl Iterator<Item = MCode> + '_ {
        self.words
            .iter()
            .filter(|w| w.address == Address::M)
            .map(move |w| MCode::of(machine, w.int()))
    }
}
