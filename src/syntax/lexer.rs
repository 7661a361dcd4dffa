//! Token-level grammar of a block, written with nom over bytes: blanks,
//! comments, the address letter of a word and its number (spec 1).
//!
//! Tape controls ignore spaces anywhere in a word, so `X 1 2 . 5` is `X12.5`;
//! the number grammar therefore runs on the word's characters with blanks
//! removed.

use nom::{
    IResult, Parser,
    bytes::complete::{take_till, take_while},
    character::complete::{char, digit0, one_of},
    combinator::{all_consuming, opt},
    sequence::pair,
};

type In<'a> = &'a [u8];
type Res<'a, T> = IResult<In<'a>, T, ()>;
/// Sign, integer digits, and the point with the fraction digits.
type NumberParts<'a> = (Option<char>, In<'a>, Option<(char, In<'a>)>);

fn is_blank(c: u8) -> bool {
    c == b' ' || c == b'\t'
}

fn is_number_char(c: u8) -> bool {
    c.is_ascii_digit() || c == b'.' || c == b'-' || c == b'+'
}

/// Skips spaces and tabs.
pub fn blanks(i: In<'_>) -> In<'_> {
    let r: Res<'_, In<'_>> = take_while(is_blank).parse(i);
    r.map_or(i, |(rest, _)| rest)
}

/// A comment `( … )`, not nested. Returns the rest of the input and whether
/// the closing parenthesis was found (an unclosed comment runs to the end of
/// the block).
pub fn comment(i: In<'_>) -> Option<(In<'_>, bool)> {
    let r: Res<'_, (char, In<'_>)> = pair(char('('), take_till(|c| c == b')')).parse(i);
    let (rest, _) = r.ok()?;
    let closed: Res<'_, char> = char(')').parse(rest);
    Some(match closed {
        Ok((rest, _)) => (rest, true),
        Err(_) => (rest, false),
    })
}

/// The characters of a word's number: digits, signs, points and blanks
/// between them (trailing blanks are left in the input).
pub fn number_text(i: In<'_>) -> (In<'_>, In<'_>) {
    let r: Res<'_, In<'_>> = take_while(|c| is_number_char(c) || is_blank(c)).parse(i);
    let (_, run) = r.unwrap_or((i, &i[..0]));
    let mut len = run.len();
    while len > 0 && is_blank(run[len - 1]) {
        len -= 1;
    }
    (&i[len..], &i[..len])
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

impl Number {
    /// Reads the characters returned by [`number_text`].
    pub fn read(text: In<'_>) -> Result<Number, NumberError> {
        if text.is_empty() {
            return Err(NumberError::Missing);
        }
        let mut buf = [0u8; 32];
        let compact: In<'_> = if text.iter().any(|&c| is_blank(c)) {
            let mut n = 0;
            for &c in text.iter().filter(|&&c| !is_blank(c)) {
                if n == buf.len() {
                    return Err(NumberError::TooLong);
                }
                buf[n] = c;
                n += 1;
            }
            &buf[..n]
        } else {
            text
        };
        let grammar = (opt(one_of("+-")), digit0, opt(pair(char('.'), digit0)));
        let r: Res<'_, NumberParts<'_>> = all_consuming(grammar).parse(compact);
        let (_, (sign, int, frac)) = r.map_err(|_| NumberError::Malformed)?;
        let frac = frac.map(|(_, f)| f);
        let frac_len = frac.map_or(0, <[u8]>::len);
        if int.len() + frac_len == 0 {
            return Err(NumberError::Malformed);
        }
        // Leading zeros carry no value; only significant digits count.
        let significant = int.iter().skip_while(|&&c| c == b'0').count() + frac_len;
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

    /// The value as written (`12.5` → 12.5, `12345` → 12345.0).
    pub fn value(&self) -> f64 {
        self.scaled(self.frac_digits)
    }

    /// The mantissa divided by 10^`digits`, signed. Dividing the exact integer
    /// by an exact power of ten gives the correctly rounded double.
    pub fn scaled(&self, digits: u8) -> f64 {
        let v = self.mantissa as f64 / POW10[usize::from(digits).min(POW10.len() - 1)];
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
        Number::read(s.as_bytes())
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
    fn number_text_leaves_trailing_blanks() {
        let (rest, num) = number_text(b"1 2 Y3");
        assert_eq!(num, b"1 2");
        assert_eq!(rest, b" Y3");
    }

    #[test]
    fn comments() {
        assert_eq!(comment(b"(abc) X1"), Some((&b" X1"[..], true)));
        assert_eq!(comment(b"(abc"), Some((&b""[..], false)));
        assert_eq!(comment(b"X1"), None);
    }
}
