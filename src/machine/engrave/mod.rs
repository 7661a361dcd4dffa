//! Haas G47 text engraving on the mill (behaviour 14.20; Haas mill
//! operator's manual, "G47 Text Engraving (Group 00)"): P0 engraves the
//! block's comment, P1 a serial number kept in #599, P32–P126 one
//! character; X Y the lower left of the first character, J its height, I
//! the angle of the line, R the plane the tool rises to between strokes, Z
//! the depth, E the plunge feed and F the engraving feed. The letters are
//! offsetlab's single-stroke font ([`font`]).

mod font;

use super::modal::{Distance, Plane};
use super::{Machine, MoveKind, Out};
use crate::diag::{Diagnostic, Span};
use crate::geometry::to_units;
use crate::macros::Value;
use crate::syntax::codes::Group;
use crate::syntax::{Address, Block};

/// The macro variable that holds the next serial number (Haas).
const SERIAL: u32 = 599;
/// J when the block gives none: 1.0 inch (Haas), in mm.
const DEFAULT_HEIGHT: f64 = 25.4;
/// The least J: 0.001 inch (Haas), in mm.
const LEAST_HEIGHT: f64 = 0.0254;
/// Most characters one G47 engraves (a bound of ours, behaviour 8).
const MOST_CHARACTERS: usize = 256;

impl Machine {
    /// A G47 block with setting g47 = engraving (behaviour 14.20).
    pub(super) fn engrave(&mut self, b: &Block, out: &mut Out) -> Result<(), Diagnostic> {
        let code = b.code_span(Group::NonModal);
        let comment = self.engraving_text.take();
        let err = |span: Span, msg: String| Diagnostic::error("g47-words", span, msg);
        if self.state.modal.plane != Plane::XY {
            return Err(err(
                code,
                "G47 engraves in the XY plane: select G17 first".into(),
            ));
        }
        if let Some(cycle) = self.state.modal.cycle {
            return Err(err(
                code,
                format!(
                    "G47 cannot be given while canned cycle {} is active: cancel it with G80 first",
                    cycle.gcode()
                ),
            ));
        }
        if !self.plain_words || self.mirror.iter().any(|m| *m) {
            return Err(err(
                code,
                "G47 turns its text by I itself: cancel polar coordinates, scaling, rotation and mirror image first (our convention; the Haas manual asks for Setting 73 off and says nothing of the others)".into(),
            ));
        }
        for w in &b.words {
            use Address::*;
            if !matches!(
                w.address,
                N | O | G | M | S | T | D | F | E | P | X | Y | Z | R | I | J
            ) {
                return Err(err(
                    w.span,
                    format!(
                        "G47 does not read {}: its words are P, X, Y, Z, R, I, J, E and F (Haas)",
                        w.address.letter()
                    ),
                ));
            }
        }
        if b.holds_group(Group::Length) {
            return Err(err(
                b.code_span(Group::Length),
                "G47: give the tool length offset in a block before it".into(),
            ));
        }
        let Some(p) = b.get(Address::P) else {
            return Err(err(
                code,
                "G47 needs P: 0 engraves the comment's text, 1 a serial number, 32–126 one ASCII character (Haas)".into(),
            ));
        };
        let text: String = match p.value {
            0.0 => {
                let Some(t) = comment.filter(|t| !t.trim().is_empty()) else {
                    return Err(err(
                        p.span,
                        "G47 P0 engraves the text of the block's comment, and the block has none: write `G47 P0 (TEXT)` (Haas)".into(),
                    ));
                };
                t.trim().to_string()
            }
            1.0 => self.serial_text(comment.as_deref(), p.span, out)?,
            v if v.fract() == 0.0 && (32.0..=126.0).contains(&v) => char::from(v as u8).to_string(),
            _ => {
                return Err(err(
                    p.span,
                    "G47's P is 0 (the comment's text), 1 (a serial number) or 32–126 (one ASCII character) (Haas)".into(),
                ));
            }
        };
        if let Some(bad) = text.chars().find(|c| !(' '..='~').contains(c)) {
            return Err(err(
                p.span,
                format!(
                    "G47 engraves the ASCII characters 32–126 only, and the text holds {bad:?} (Haas)"
                ),
            ));
        }
        if text.len() > MOST_CHARACTERS {
            return Err(err(
                p.span,
                format!(
                    "G47 engraves at most {MOST_CHARACTERS} characters in one block (offsetlab's bound); the text has {}",
                    text.len()
                ),
            ));
        }
        let Some(z_word) = b.get(Address::Z) else {
            return Err(err(
                code,
                "G47 needs Z, the depth the strokes are cut at (our convention: the Haas manual marks Z optional without saying what depth it takes)".into(),
            ));
        };
        let height = match b.get(Address::J) {
            Some(j) if self.mm(j.value) < LEAST_HEIGHT - 1e-9 => {
                return Err(err(
                    j.span,
                    "G47's J, the height of the text, is at least 0.001 inch (Haas)".into(),
                ));
            }
            Some(j) => self.mm(j.value),
            None => DEFAULT_HEIGHT,
        };
        let angle = match b.get(Address::I) {
            Some(i) if !(-360.0..=360.0).contains(&i.value) => {
                return Err(err(
                    i.span,
                    "G47's I, the angle of the text, is −360 to 360 degrees (Haas)".into(),
                ));
            }
            Some(i) => i.value,
            None => 0.0,
        };

        let incremental = self.state.modal.distance == Distance::Incremental;
        let start_z = self.state.programmed[2];
        // R, then Z from R, in G91 (our reading of the Haas O9876 template,
        // which moves to R "with the user's G90/G91" and takes the depth
        // from there).
        let r = b.value(Address::R).map_or(start_z, |v| {
            if incremental {
                start_z + self.mm(v)
            } else {
                self.mm(v)
            }
        });
        let depth = if incremental {
            r + self.mm(z_word.value)
        } else {
            self.mm(z_word.value)
        };
        if depth >= r {
            return Err(err(
                z_word.span,
                "G47: Z, the depth, must be below R, the plane the tool rises to between strokes"
                    .into(),
            ));
        }

        // To the start point at rapid, then down (or up) to R (the O9876
        // template: G00 X Y, then Z R).
        let from = self.mark();
        for axis in 0..2 {
            if let Some(v) = b.value([Address::X, Address::Y][axis]) {
                self.state.programmed[axis] = self.target(axis, self.mm(v), incremental);
            }
        }
        let origin = [self.state.programmed[0], self.state.programmed[1]];
        let to = self.mark();
        self.push_move(out, MoveKind::Rapid, from, to, None);
        self.engrave_step(out, MoveKind::Rapid, None, r);

        let unit = height / font::CAP_HEIGHT;
        let (sin, cos) = angle.to_radians().sin_cos();
        let place = |k: usize, [gx, gy]: [f64; 2]| -> [f64; 2] {
            let x = (k as f64 * font::ADVANCE + gx) * unit;
            let y = gy * unit;
            [origin[0] + x * cos - y * sin, origin[1] + x * sin + y * cos]
        };
        let mut strokes = 0usize;
        for (k, c) in text.bytes().enumerate() {
            let Some(glyph) = font::strokes(c) else {
                continue;
            };
            for stroke in glyph {
                if self.overflow {
                    break;
                }
                let mut points = stroke.map(|g| place(k, g));
                let Some(first) = points.next() else { continue };
                strokes += 1;
                self.engrave_step(out, MoveKind::Rapid, Some(first), r);
                self.engrave_step(out, MoveKind::Feed, None, depth);
                for point in points {
                    self.engrave_step(out, MoveKind::Feed, Some(point), depth);
                }
                self.engrave_step(out, MoveKind::Rapid, None, r);
            }
        }
        if let Some(f) = b.value(Address::F) {
            self.state.feed = Some(f);
        }

        let units = self.units();
        let dec = units.decimals();
        let f = |mm: f64| format!("{:.dec$}", to_units(mm, units));
        let feed = |a: Address| b.value(a).map(|v| format!("{}{v}", a.letter()));
        let plunge = feed(Address::E)
            .or_else(|| feed(Address::F))
            .unwrap_or_else(|| "the feed in force".into());
        let cut = feed(Address::F).unwrap_or_else(|| "the feed in force".into());
        out.notes.push(format!(
            "G47 text engraving (Haas): \"{text}\" from X{} Y{} (the lower left of the first character), {} high, at {angle}° — {strokes} strokes, each plunged from R{} to Z{} at {plunge} and cut at {cut}, the tool rising to R between strokes; distance and motion modes are as before (offsetlab's single-stroke font, not the Haas control's letter shapes)",
            f(origin[0]),
            f(origin[1]),
            f(height),
            f(r),
            f(depth),
        ));
        Ok(())
    }

    /// One move of the engraving: to `xy` (when given) and height `z`.
    fn engrave_step(&mut self, out: &mut Out, kind: MoveKind, xy: Option<[f64; 2]>, z: f64) {
        let from = self.mark();
        if let Some([x, y]) = xy {
            self.state.programmed[0] = x;
            self.state.programmed[1] = y;
        }
        self.state.programmed[2] = z;
        let to = self.mark();
        self.push_move(out, kind, from, to, None);
    }

    /// G47 P1: the serial number's text, #599 (or the comment's digits,
    /// which set it) in as many digits as the comment has `#` or digits;
    /// #599 is one more after the block (Haas, "Sequential Serial Number
    /// Engraving").
    fn serial_text(
        &mut self,
        comment: Option<&str>,
        span: Span,
        out: &mut Out,
    ) -> Result<String, Diagnostic> {
        let format = comment.map(str::trim).unwrap_or("");
        let digits = format.len();
        let hashes = !format.is_empty() && format.bytes().all(|c| c == b'#');
        let number = !format.is_empty() && format.bytes().all(|c| c.is_ascii_digit());
        if !(hashes || number) || digits > 9 {
            return Err(Diagnostic::error(
                "g47-words",
                span,
                "G47 P1 engraves a serial number: the block's comment gives its digits as `#` (`(####)`, #599 the number) or as the first number (`(1234)`), at most 9 (Haas)",
            ));
        }
        if number {
            let n: f64 = format.parse().unwrap_or(0.0);
            self.variables.set(SERIAL, Value::Number(n));
        }
        let serial = match self.variables.get(SERIAL) {
            Some(Value::Number(n)) if n >= 0.0 && n.fract() == 0.0 && n < 1e15 => n as u64,
            Some(Value::Vacant) | None => 0,
            Some(Value::Number(n)) => {
                return Err(Diagnostic::error(
                    "g47-words",
                    span,
                    format!(
                        "G47 P1 engraves #599 as the serial number, a whole number 0 or more, and #599 is {n}"
                    ),
                ));
            }
        };
        let modulus = 10u64.pow(digits as u32);
        let text = format!("{:0digits$}", serial % modulus);
        self.variables
            .set(SERIAL, Value::Number(serial as f64 + 1.0));
        out.notes.push(format!(
            "G47 P1: serial number {serial} engraved in {digits} digits as {text}; #599 is now {}",
            serial + 1
        ));
        Ok(text)
    }
}
