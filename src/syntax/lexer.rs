//! Token-level grammar of a block over bytes: blanks, comments (nom) and a
//! word's number (behaviour 1).
//!
//! Tape controls ignore spaces anywhere in a word, so `X 1 2 . 5` is `X12.5`;
//! the number grammar therefore runs on the word's characters with blanks
//! removed. The number is the parser's hot loop: [`number`] reads it in one
//! hand-written pass (nom's combinator chain cost several times its
//! instructions: the `check` instruction count in docs/performance.md guards it), and the nom grammar
//! [`number_grammar`] is kept as its specification, which a property test
//! holds it to.

use nom::{IResult, Parser, bytes::complete::take_till, character::complete::char, sequence::pair};
#[cfg(test)]
use nom::{
    character::complete::{digit0, one_of},
    combinator::{all_consuming, opt},
};

type In<'a> = &'a [u8];
type Res<'a, T> = IResult<In<'a>, T, ()>;
/// Sign, integer digits, and the point with the fraction digits.
#[cfg(test)]
type NumberParts<'a> = (Option<char>, In<'a>, Option<(char, In<'a>)>);

/// Skips spaces and tabs from `i`: the position of the first other byte
/// (or the end). Blanks separate nearly every word, so this is a plain loop.
pub fn skip_blanks(bytes: In<'_>, mut i: usize) -> usize {
    while let Some(b' ' | b'\t') = bytes.get(i) {
        i += 1;
    }
    i
}

/// A comment `( … )`, not nested. Returns the rest of the input and whether
/// the closing parenthesis was found (an unclosed comment runs to the end of
/// the line; a `;` inside a comment does not end the block).
pub fn comment(i: In<'_>) -> Option<(In<'_>, bool)> {
    let r: Res<'_, (char, In<'_>)> = pair(
        char('('),
        take_till(|c| c == b')' || c == b'\n' || c == b'\r'),
    )
    .parse(i);
    let (rest, _) = r.ok()?;
    let closed: Res<'_, char> = char(')').parse(rest);
    Some(match closed {
        Ok((rest, _)) => (rest, true),
        Err(_) => (rest, false),
    })
}

/// A number as written, before units and decimal input are applied.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Number {
    /// A minus sign was written.
    pub negative: bool,
    /// All digits, as an integer.
    pub mantissa: u64,
    /// Digits after the decimal point.
    pub frac_digits: u8,
    /// A decimal point was written.
    pub point: bool,
}

/// Why a word's number could not be read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NumberError {
    /// The address letter has no number at all.
    Missing,
    /// Characters that do not form a number (`1.2.3`, `--1`, `-`).
    Malformed,
    /// More significant digits than a control reads.
    TooLong,
}

/// Largest count of digits in a number (a control reads at most 9 + 4).
const MAX_DIGITS: usize = 15;

/// Reads a word's number from `bytes[start..]`, the characters after its
/// address letter: digits, an optional sign first, an optional point, and
/// blanks between them (tape controls ignore spaces). Returns where the
/// number ends (its trailing blanks are not part of it), where the next
/// non-blank character is, and the number or why it is not one.
///
/// This is the hot loop of the parser, so it is one hand-written pass; the
/// grammar it implements is [`number_grammar`], written with nom, and a test
/// checks that the two agree on every input.
#[inline(always)]
pub fn number(bytes: In<'_>, start: usize) -> (usize, usize, Result<Number, NumberError>) {
    // Fast path for the shape nearly every word has: `[+-]digits[.digits]`
    // followed by something that is not part of a number — a loop over the
    // whole digits and one over the fraction's.
    let (negative, digits_start) = match bytes.get(start) {
        Some(b'-') => (true, start + 1),
        Some(b'+') => (false, start + 1),
        _ => (false, start),
    };
    let (int_end, mantissa) = digits(bytes, digits_start, 0);
    let point = bytes.get(int_end) == Some(&b'.');
    let (end, mantissa) = if point {
        digits(bytes, int_end + 1, mantissa)
    } else {
        (int_end, mantissa)
    };
    let frac_digits = if point { end - int_end - 1 } else { 0 };
    let count = end - digits_start - usize::from(point);
    // What follows must not continue the number (after blanks: a digit, a
    // second point or a sign means spaces inside it or a malformed one).
    let next = skip_blanks(bytes, end);
    let clean = !matches!(bytes.get(next), Some(b'0'..=b'9' | b'.' | b'+' | b'-'));
    if clean && count > 0 && count <= MAX_DIGITS {
        let number = Number {
            negative,
            mantissa,
            frac_digits: frac_digits as u8,
            point,
        };
        return (end, next, Ok(number));
    }
    number_general(bytes, start)
}

/// Reads the digits of `i` from `p` on into `mantissa` (wrapping: a number
/// with more than [`MAX_DIGITS`] digits is refused by the caller). Returns
/// the position after the last digit and the mantissa.
#[inline]
fn digits(i: In<'_>, mut p: usize, mut mantissa: u64) -> (usize, u64) {
    while p < i.len() {
        let digit = i[p].wrapping_sub(b'0');
        if digit >= 10 {
            break;
        }
        mantissa = mantissa.wrapping_mul(10).wrapping_add(u64::from(digit));
        p += 1;
    }
    (p, mantissa)
}

/// The general case of [`number`]: blanks inside the number, malformed and
/// over-long numbers.
fn number_general(bytes: In<'_>, start: usize) -> (usize, usize, Result<Number, NumberError>) {
    let i = &bytes[start..];
    let mut end = 0;
    let mut negative = false;
    let mut seen = false;
    let mut digits = false;
    let mut point = false;
    let mut malformed = false;
    let mut mantissa = 0u64;
    let mut significant = 0usize;
    let mut frac = 0usize;
    for (pos, &c) in i.iter().enumerate() {
        match c {
            b'0'..=b'9' => {
                digits = true;
                if point {
                    frac += 1;
                }
                if mantissa != 0 || c != b'0' {
                    significant += 1;
                    if significant <= MAX_DIGITS {
                        mantissa = mantissa * 10 + u64::from(c - b'0');
                    }
                }
            }
            b'.' => {
                malformed |= point;
                point = true;
            }
            b'+' | b'-' => {
                malformed |= seen;
                negative = c == b'-';
            }
            b' ' | b'\t' => continue,
            _ => break,
        }
        seen = true;
        end = pos + 1;
    }
    let result = if !seen {
        Err(NumberError::Missing)
    } else if malformed || !digits {
        Err(NumberError::Malformed)
    } else if significant > MAX_DIGITS || frac > MAX_DIGITS {
        Err(NumberError::TooLong)
    } else {
        Ok(Number {
            negative,
            mantissa,
            frac_digits: frac as u8,
            point,
        })
    };
    let end = start + end;
    (end, skip_blanks(bytes, end), result)
}

/// The grammar of a number, without blanks: `[+-]? digit* ('.' digit*)?`
/// with at least one digit. [`number`] implements it in one pass; this nom
/// version is the reference it is tested against.
#[cfg(test)]
pub fn number_grammar(text: In<'_>) -> Result<Number, NumberError> {
    if text.is_empty() {
        return Err(NumberError::Missing);
    }
    let grammar = (opt(one_of("+-")), digit0, opt(pair(char('.'), digit0)));
    let r: Res<'_, NumberParts<'_>> = all_consuming(grammar).parse(text);
    let (_, (sign, int, frac)) = r.map_err(|_| NumberError::Malformed)?;
    let frac = frac.map(|(_, f)| f);
    let frac_len = frac.map_or(0, <[u8]>::len);
    if int.len() + frac_len == 0 {
        return Err(NumberError::Malformed);
    }
    let significant = int
        .iter()
        .chain(frac.unwrap_or(&[]))
        .skip_while(|&&c| c == b'0')
        .count();
    if significant > MAX_DIGITS || frac_len > MAX_DIGITS {
        return Err(NumberError::TooLong);
    }
    let mantissa = int
        .iter()
        .chain(frac.unwrap_or(&[]))
        .fold(0u64, |m, &c| m * 10 + u64::from(c - b'0'));
    Ok(Number {
        negative: sign == Some('-'),
        mantissa,
        frac_digits: frac_len as u8,
        point: frac.is_some(),
    })
}

impl Number {
    /// The value as written (`12.5` → 12.5, `12345` → 12345.0).
    pub fn value(&self) -> f64 {
        self.scaled(self.frac_digits)
    }

    /// The mantissa as a double, exactly. A number has at most
    /// [`MAX_DIGITS`] digits, so the mantissa fits an `i64`, whose
    /// conversion is one instruction on x86-64 (a `u64`'s is six).
    #[inline]
    pub fn mantissa_f64(&self) -> f64 {
        debug_assert!(self.mantissa < 10u64.pow(MAX_DIGITS as u32));
        self.mantissa as i64 as f64
    }

    /// The mantissa divided by 10^`digits`, signed. Dividing the exact integer
    /// by an exact power of ten gives the correctly rounded double.
    pub fn scaled(&self, digits: u8) -> f64 {
        let v = self.mantissa_f64() / POW10[usize::from(digits).min(POW10.len() - 1)];
        if self.negative { -v } else { v }
    }
}

const POW10: [f64; 20] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
    1e17, 1e18, 1e19,
];

#[cfg(test)]
mod tests {
    use super::*;

    fn read(s: &str) -> Result<Number, NumberError> {
        let (end, _, n) = number(s.as_bytes(), 0);
        let rest = &s.as_bytes()[end..];
        assert!(rest.is_empty() || !rest[0].is_ascii_digit(), "{s}");
        n
    }

    #[test]
    fn numbers_as_written() {
        assert_eq!(read("12.5").unwrap().value(), 12.5);
        assert_eq!(read("-.5").unwrap().value(), -0.5);
        assert_eq!(read("+3.").unwrap().value(), 3.0);
        assert!(read("3.").unwrap().point);
        assert!(!read("12345").unwrap().point);
        assert_eq!(read("1 2 . 5").unwrap().value(), 12.5);
        assert_eq!(read("0000000000000000001").unwrap().value(), 1.0);
        assert_eq!(read("0.000100").unwrap().value(), 0.0001);
    }

    #[test]
    fn malformed_numbers() {
        assert_eq!(read(""), Err(NumberError::Missing));
        assert_eq!(read("1.2.3"), Err(NumberError::Malformed));
        assert_eq!(read("--1"), Err(NumberError::Malformed));
        assert_eq!(read("-"), Err(NumberError::Malformed));
        assert_eq!(read("."), Err(NumberError::Malformed));
        assert_eq!(read("1-2"), Err(NumberError::Malformed));
        assert_eq!(read("1234567890123456"), Err(NumberError::TooLong));
    }

    #[test]
    fn number_leaves_trailing_blanks_and_the_next_word() {
        let (end, next, n) = number(b"X1 2 Y3", 1);
        assert_eq!(n.unwrap().value(), 12.0);
        assert_eq!((end, next), (4, 5));
        let (end, next, n) = number(b"X ;", 1);
        assert_eq!(n, Err(NumberError::Missing));
        assert_eq!((end, next), (1, 2));
    }

    #[test]
    fn comments() {
        assert_eq!(comment(b"(abc) X1"), Some((&b" X1"[..], true)));
        assert_eq!(comment(b"(abc"), Some((&b""[..], false)));
        assert_eq!(comment(b"X1"), None);
    }

    #[cfg(not(target_arch = "wasm32"))]
    proptest::proptest! {
        /// The one-pass lexer reads exactly what the nom grammar accepts.
        #[test]
        fn the_fast_lexer_agrees_with_the_nom_grammar(text in "[0-9.+\\- ]{0,24}") {
            let (end, next, fast) = number(text.as_bytes(), 0);
            let (taken, rest) = (&text[..end], &text.as_bytes()[end..]);
            proptest::prop_assert_eq!(next, text.len() - rest.iter().skip_while(|c| **c == b' ').count());
            let compact: Vec<u8> = taken.bytes().filter(|c| *c != b' ').collect();
            proptest::prop_assert!(rest.iter().all(|c| *c == b' '), "{:?}", text);
            proptest::prop_assert_eq!(fast, number_grammar(&compact), "{:?}", text);
        }
    }
}
