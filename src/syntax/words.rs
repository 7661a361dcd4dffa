//! How a word's number is read (behaviour 1.13–1.16): the context the text
//! sets (G20/G21, canned cycles, the lathe's repetitive cycles), typing a
//! lexed word with it, the integer-dimension warning, and the errors at a
//! word. Both readings of a block (`read.rs`) type their words here.

use super::*;

impl Blocks<'_> {
    /// Tracks the G codes that change how numbers are read: G20/G21 (least
    /// increment) and mill canned cycles (K is then a repeat count), from
    /// a G word's number as lexed (written without a point or sign).
    pub(super) fn note_context(&mut self, n: Number) {
        if n.negative {
            return;
        }
        if n.frac_digits != 0 {
            return self.note_decimal_context(n);
        }
        let Ok(major) = u16::try_from(n.mantissa) else {
            return;
        };
        if let Some(code) = Code::of(self.table, GCode::new(major)) {
            self.note_code(code);
        }
    }

    /// [`Blocks::note_context`] for a G code written with a decimal: G05.1's
    /// Q is a switch (Q1/Q0, behaviour 14.4), no dimension to warn about.
    /// Out of line: few G codes have a decimal.
    #[inline(never)]
    pub(super) fn note_decimal_context(&mut self, n: Number) {
        let (Ok(major), Ok(scaled)) = (
            u16::try_from(n.mantissa / 10),
            u8::try_from(n.mantissa % 10),
        ) else {
            return;
        };
        if n.frac_digits != 1 {
            return;
        }
        let g = GCode {
            major,
            minor: scaled,
        };
        if Code::of(self.table, g) == Some(Code::NonModal(codes::NonModal::AiContour)) {
            self.whole_q = true;
        }
    }

    /// [`Blocks::note_context`] for a G code resolved (and written as a whole
    /// number).
    #[inline(always)]
    pub(super) fn note_code(&mut self, code: Code) {
        match code {
            // A group 01 code ends the canned cycle (only the mill has one).
            // Only the mill has canned cycles and only the lathe G70–G76,
            // so leaving a cycle leaves no context.
            Code::Motion(_) | Code::Cycle(codes::CannedCycle::Cancel) => {
                if self.in_cycle {
                    self.in_cycle = false;
                    self.context = false;
                }
            }
            Code::Cycle(codes::CannedCycle::Cycle(_)) => {
                self.in_cycle = true;
                self.context = true;
            }
            Code::Units(units) => self.units = units,
            Code::NonModal(NonModal::Repetitive(r)) => {
                self.mrc = Some(r);
                self.context = true;
            }
            // The lathe G10's Q is the tool tip direction, a digit: no
            // dimension to warn about (behaviour 17.6).
            Code::NonModal(NonModal::DataSetting) => self.whole_q = true,
            Code::NonModal(_)
            | Code::Plane(_)
            | Code::Distance(_)
            | Code::FeedMode(_)
            | Code::CutterCompensation(_)
            | Code::Length(_)
            | Code::Return(_)
            | Code::Work(_)
            | Code::SurfaceSpeed(_)
            | Code::CuttingMode(_)
            | Code::Polar(_)
            | Code::Scaling(_)
            | Code::Rotation(_)
            | Code::PolarCoordinates(_)
            | Code::Mirror(_)
            | Code::ArcCenter(_) => {}
        }
    }

    /// Types a word of an address offsetlab reads with the context the
    /// parser has now (units, canned cycle): the word and how its number was
    /// read, or why it is refused (behaviour 1). Both readings of a block type
    /// words with this.
    #[inline(always)]
    pub(super) fn read_word(
        &self,
        address: Address,
        n: Number,
        span: Span,
    ) -> Result<(Word, WordKind), Refusal> {
        let kind = if self.context {
            self.context_kind(address)
        } else {
            address.kind()
        };
        let value = match kind {
            WordKind::Integer if address == Address::G => {
                if n.negative || n.frac_digits > 1 || (n.point && n.frac_digits == 0) {
                    return Err(Refusal::GCode);
                }
                n.value()
            }
            WordKind::Integer => {
                if n.point {
                    return Err(Refusal::DecimalPoint);
                }
                let limit = integer_limit(self.options, address, self.in_cycle, self.mrc);
                if n.negative && n.mantissa != 0 || n.mantissa > limit {
                    return Err(Refusal::Integer(limit));
                }
                if address == Address::T
                    && self.options.machine == MachineKind::Lathe
                    && n.mantissa % 100 > u64::from(self.options.table_size)
                {
                    return Err(Refusal::LatheOffset);
                }
                n.mantissa_f64()
            }
            WordKind::Feed => {
                let v = n.value();
                if !(0.0..=max_feed(self.options.linuxcnc)).contains(&v) {
                    return Err(Refusal::Feed);
                }
                v
            }
            WordKind::Dimension => {
                let v = self.dimension(n);
                if v.abs() > self.units.max_dimension() + 1e-9 {
                    return Err(Refusal::Dimension);
                }
                v
            }
        };
        let word = Word {
            address,
            value,
            point: n.point,
            span,
        };
        Ok((word, kind))
    }

    /// How `address` reads in a mill canned cycle (K a repeat count,
    /// behaviour 1.16) or a lathe G70–G76 block (behaviour 15.2): P and Q
    /// are whole numbers there — sequence numbers in G70–G73, least input
    /// increments or G76's `mmrraa` code in G74–G76 — and so are G73's R
    /// and D (counts of divisions); D elsewhere reads as setting
    /// `depth_word` says. Out of line: few blocks have either.
    #[inline(never)]
    #[cold]
    pub(super) fn context_kind(&self, address: Address) -> WordKind {
        match (address, self.mrc) {
            (Address::K, _) if self.in_cycle => WordKind::Integer,
            (Address::P | Address::Q, Some(_)) => WordKind::Integer,
            (Address::R | Address::D, Some(Repetitive::PatternRepeat)) => WordKind::Integer,
            // G76's tool angle, in whole degrees (Haas: no decimal point).
            (Address::A, Some(Repetitive::Threading)) => WordKind::Integer,
            (Address::D, Some(_)) => match self.options.depth_word {
                DepthWord::Increments => WordKind::Integer,
                DepthWord::Dimension => WordKind::Dimension,
            },
            _ => address.kind(),
        }
    }

    /// The value of a dimension word in the current units (decimal input,
    /// behaviour 1).
    pub(super) fn dimension(&self, n: Number) -> f64 {
        if n.point || self.options.decimal_input == DecimalInput::Calculator {
            n.value()
        } else {
            n.scaled(self.units.decimals() as u8)
        }
    }

    /// True if this dimension word's number is read in least increments and
    /// the program has not been warned about it yet (one warning a program).
    pub(super) fn integer_warning_due(&self, n: Number) -> bool {
        !n.point
            && n.mantissa != 0
            && self.options.decimal_input == DecimalInput::Increment
            && !self.warned_integer
    }

    /// Types one lexed word, reporting what is wrong with it.
    pub(super) fn type_word(&mut self, w: &RawWord, line: u32, block: &mut Block) -> Option<Word> {
        let span = Span::new(w.start, w.end, line);
        let address = match w.comma {
            true => Address::comma(w.letter),
            false => Address::from_letter(w.letter),
        };
        let read = address
            .ok_or(Refusal::Address)
            .and_then(|a| Ok((a, w.number.map_err(Refusal::Number)?)))
            .and_then(|(a, n)| {
                self.read_word(a, n, span).or_else(|refusal| match refusal {
                    // Haas: a dwell's P with a point is seconds, S5000. is 5000 (behaviour 1.23, 7.57).
                    Refusal::DecimalPoint => self.decimal_allowed(a, n, span),
                    _ => Err(refusal),
                })
            });
        match read {
            Ok((word, kind)) => {
                if kind == WordKind::Dimension
                    && !(word.address == Address::Q && self.whole_q)
                    && let Ok(n) = w.number
                    && self.integer_warning_due(n)
                {
                    self.warned_integer = true;
                    let msg = self.integer_warning(w, n);
                    self.report(Diagnostic::warning("integer-dimension", span, msg));
                }
                Some(word)
            }
            Err(refusal) => {
                let (code, msg) = self.refusal_message(w, refusal);
                self.error_span(block, code, span, &msg);
                None
            }
        }
    }

    pub(super) fn error_span(
        &mut self,
        block: &mut Block,
        code: &'static str,
        span: Span,
        msg: &str,
    ) {
        block.error = true;
        self.report(Diagnostic::error(code, span, msg));
    }

    pub(super) fn error_word(
        &mut self,
        block: &mut Block,
        code: &'static str,
        word: &Word,
        msg: &str,
    ) {
        self.error_span(block, code, word.span, msg);
    }

    pub(super) fn error_at(
        &mut self,
        block: &mut Block,
        code: &'static str,
        start: usize,
        end: usize,
        line: u32,
        msg: &str,
    ) {
        self.error_span(block, code, Span::new(start, end, line), msg);
    }
}

/// The largest feed rate a word may give: 999999 on the Fanuc family;
/// rs274 takes any positive F (`F1000000`, behaviour 22.13), so the LinuxCNC
/// profile takes what the number reader reads, 15 digits.
pub(super) fn max_feed(linuxcnc: bool) -> f64 {
    if linuxcnc {
        999_999_999_999_999.0
    } else {
        999_999.0
    }
}

pub(super) fn integer_limit(
    options: ParseOptions,
    address: Address,
    in_cycle: bool,
    mrc: Option<Repetitive>,
) -> u64 {
    match address {
        // A lathe G70–G76 block's D is a depth or a count (behaviour 15.2).
        Address::D if mrc.is_some() => MAX_INTEGER,
        Address::D | Address::H => u64::from(options.table_size),
        Address::T if options.machine == MachineKind::Lathe => 9999,
        Address::L => MAX_REPEATS,
        Address::K if in_cycle => MAX_REPEATS,
        _ => MAX_INTEGER,
    }
}
