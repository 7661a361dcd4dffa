//! The sentences of the parser's diagnostics: why a word is refused, why
//! it clashes with the words before it, what an unexpected character is
//! (behaviour 1). The codes go with them.

use super::*;

impl Blocks<'_> {
    /// The `integer-dimension` warning's sentence.
    pub(super) fn integer_warning(&self, w: &RawWord, n: Number) -> String {
        let units = self.units;
        let d = units.decimals();
        let v = self.dimension(n);
        let letter = w.letter as char;
        let text = &self.text[w.start..w.end];
        format!(
            "{text} has no decimal point: read as {v:.d$} {u} (least input increment {inc:.d$} {u}); \
             write {letter}{v:.d$} for {v:.d$} {u}, or {text}. for {whole} {u} (setting decimal_input)",
            u = units.as_str(),
            inc = units.increment(),
            whole = n.value(),
        )
    }

    /// The diagnostic code and sentence of a refused word.
    pub(super) fn refusal_message(&self, w: &RawWord, refusal: Refusal) -> (&'static str, String) {
        // The word as written.
        let text = &self.text[w.start..w.end];
        let letter = match (w.comma, self.text.as_bytes()[w.start]) {
            (true, _) => format!(",{}", w.letter as char),
            // `:`, the program number address of ISO code.
            (false, b':') => ":".to_string(),
            (false, _) => (w.letter as char).to_string(),
        };
        match refusal {
            Refusal::Address => {
                let msg = match w.letter {
                    b'V' => format!(
                        "{letter} is not an address offsetlab reads (a U/V/W secondary axis of a mill is not modelled)"
                    ),
                    _ => format!("{letter} is not an address offsetlab reads"),
                };
                ("unsupported-address", msg)
            }
            Refusal::Number(NumberError::Missing) if letter == ":" => (
                "missing-number",
                "`:` has no number: `:` is the program number address of ISO code (:1234, as O1234); a comment goes in ( )".to_string(),
            ),
            Refusal::Number(NumberError::Missing) => (
                "missing-number",
                format!("{letter} has no number: an address letter needs a value"),
            ),
            Refusal::Number(NumberError::Malformed) => (
                "malformed-number",
                format!("{text}: `{}` is not a number", text[1..].trim()),
            ),
            Refusal::Number(NumberError::TooLong) => (
                "out-of-range",
                format!("{text}: too many digits for a control to read"),
            ),
            Refusal::GCode => (
                "malformed-number",
                format!("{text}: a G code is a number such as G01 or G05.1"),
            ),
            Refusal::DecimalPoint if w.letter == b'P' => (
                "decimal-point",
                format!(
                    "{text}: P takes a whole number, written without a decimal point (a dwell in milliseconds: P3000 for 3 s; setting dwell_p_decimal_point: seconds, the Haas rule, reads {text} as seconds)"
                ),
            ),
            Refusal::DecimalPoint if w.letter == b'S' => (
                "decimal-point",
                format!(
                    "{text}: S takes a whole number, written without a decimal point (setting s_decimal_point: value, the Haas rule, reads {text} as its value)"
                ),
            ),
            Refusal::DecimalPoint => (
                "decimal-point",
                format!("{text}: {letter} takes a whole number, written without a decimal point"),
            ),
            Refusal::Integer(limit) => {
                let address = Address::from_letter(w.letter).unwrap_or(Address::N);
                let msg = integer_range_message(text, &letter, address, limit, self.options);
                ("out-of-range", msg)
            }
            Refusal::LatheOffset => {
                let offset = w.number.map_or(0, |n| n.mantissa % 100);
                let msg = format!(
                    "{text}: offset number {offset:02} is beyond the offset table (00 to {:02})",
                    self.options.table_size
                );
                ("out-of-range", msg)
            }
            Refusal::Feed => (
                "out-of-range",
                format!(
                    "{text}: a feed rate is 0 to {}",
                    super::words::max_feed(self.options.linuxcnc)
                ),
            ),
            Refusal::Dimension => {
                let units = self.units;
                let msg = format!(
                    "{text} is outside ±{max:.*} {} (behaviour 1.17)",
                    units.decimals(),
                    units.as_str(),
                    max = units.max_dimension(),
                );
                ("out-of-range", msg)
            }
        }
    }

    /// The warning's sentence when `word`'s G code replaces the block's
    /// earlier code of `group` (setting `same_group_codes = last_wins`).
    pub(super) fn replaced_message(&self, block: &Block, word: &Word, group: Group) -> String {
        let first = block.group_word(group).map_or(word.gcode(), Word::gcode);
        format!(
            "{first} and {} are both in group {}: the last one, {}, is in effect and {first} is not (Fanuc: the last G code of a group specified in a block is valid)",
            word.gcode(),
            group.label(),
            word.gcode(),
        )
    }

    /// The diagnostic code and sentence of a word the block's earlier words
    /// exclude.
    pub(super) fn clash_message(
        &self,
        block: &Block,
        word: &Word,
        clash: Clash,
    ) -> (&'static str, String) {
        match clash {
            Clash::UnknownGCode(why) => ("unsupported-g-code", why),
            Clash::Group(group) => {
                let first = block.group_word(group).map_or(word.gcode(), Word::gcode);
                let msg = format!(
                    "{first} and {} are both in group {}; a block may hold one of them{} (setting same_group_codes: last_wins, the Fanuc rule, takes the last)",
                    word.gcode(),
                    group.label(),
                    conflict_hint(self.table, group)
                );
                ("modal-conflict", msg)
            }
            Clash::MCode => {
                // The block holds one M code of the group: the earlier one.
                let machine = self.options.machine;
                let group = MCode::of(machine, word.int()).group();
                let earlier = block
                    .mcodes(machine)
                    .find(|m| m.group() == group)
                    .map_or(0, |m| m.number());
                let msg = format!(
                    "M{earlier:02} and M{:02} exclude each other; a block may hold one of them",
                    word.int()
                );
                ("modal-conflict", msg)
            }
            Clash::Duplicate => {
                let a = word.address;
                let first = block.get(a).map_or(word.span, |f| f.span);
                let msg = format!(
                    "{} appears twice in this block ({} and {}); each address may appear once",
                    a.letter(),
                    &self.text[first.start as usize..first.end as usize],
                    &self.text[word.span.start as usize..word.span.end as usize],
                );
                ("duplicate-address", msg)
            }
        }
    }
}

fn integer_range_message(
    text: &str,
    letter: &str,
    address: Address,
    limit: u64,
    options: ParseOptions,
) -> String {
    match address {
        Address::D | Address::H => format!(
            "{text}: offset number is beyond the offset table (00 to {:02})",
            options.table_size
        ),
        Address::T if options.machine == MachineKind::Lathe => {
            format!("{text}: a lathe T code is Tttoo, tool tt and offset oo (at most T9999)")
        }
        _ => format!("{text}: {letter} is a whole number from 0 to {limit}"),
    }
}

fn conflict_hint(table: CodeTable, group: Group) -> &'static str {
    match (table.machine(), group) {
        (MachineKind::Lathe, Group::Motion) if !table.lathe_distance_codes() => {
            " (on the lathe, G-code system A, G90/G92/G94 are turning cycles; X/Z are absolute and U/W incremental)"
        }
        (_, Group::NonModal) => " (one-shot codes such as G45–G48 take one per block, seed 003)",
        _ => "",
    }
}

pub(super) fn unexpected_message(ch: char) -> String {
    match ch {
        '#' | '[' | ']' | '=' => {
            format!(
                "`{ch}` is not part of a word here: a macro statement opens its block (`#1 = ...`), and a word's macro value is `#n` or `[...]` (behaviour 20)"
            )
        }
        '/' => "`/` (optional block skip) must start the block".to_string(),
        ',' => "`,` starts the comma words ,C (chamfer) and ,R (corner rounding) only; other comma words (such as ,A, the angle of direct drawing dimension programming) are not read".to_string(),
        '%' => "`%` marks the tape start or end and must be alone on its line".to_string(),
        ')' => "`)` closes no comment".to_string(),
        '\u{feff}' => "character '\\u{feff}' (a byte order mark) is not part of a program: save the file as UTF-8 without BOM".to_string(),
        // Controls and invisible characters (zero-width, bidirectional
        // overrides, combining marks) are written escaped, so that the
        // message shows them and cannot reorder the text around it.
        c if c.is_control() || c.escape_debug().nth(1).is_some() => {
            format!("character {:?} is not part of a program", c)
        }
        c => format!("`{c}` is not part of a word"),
    }
}
