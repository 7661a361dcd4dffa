//! offsetlab's single-stroke font for Haas G47 text engraving (behaviour
//! 14.20). The Haas control engraves with a font compiled into it (once the
//! program O9876); its strokes are not published, so these letters are
//! ours: the start point, height, angle, depths and feeds follow the Haas
//! manual, the letter shapes and spacing do not claim to be Haas's.
//!
//! Each character of ASCII 32–126 (the codes G47 P32–P126 name) is drawn
//! on a grid 4 units wide with the capitals and digits 6 units high: the
//! baseline at 0, the lowercase letters 4 high, the descenders down to −2.
//! A character advances 6 units, so with the text height J (the capitals'
//! height) each character takes J along the line.

/// Grid units of the capitals' height (J).
pub(super) const CAP_HEIGHT: f64 = 6.0;
/// Grid units from one character's origin to the next one's.
pub(super) const ADVANCE: f64 = 6.0;

/// The strokes of ASCII 32–126, in order of code: strokes separated by a
/// space, each a run of points of two digits, x (0–4) and y + 2 (0–8). A
/// stroke of one point is a plunge alone (a dot).
const GLYPHS: [&str; 95] = [
    "",                                 // ' '
    "2824 22",                          // '!'
    "1816 3836",                        // '"'
    "1218 3238 0444 0646",              // '#'
    "473818070615354443321203 2822",    // '$'
    "0248 0818170708 3343423233",       // '%'
    "4216172837360403122244",           // '&'
    "2826",                             // "'"
    "38262432",                         // '('
    "18262412",                         // ')'
    "2723 0644 0446",                   // '*'
    "2723 0545",                        // '+'
    "232211",                           // ','
    "0545",                             // '-'
    "22",                               // '.'
    "0248",                             // '/'
    "120307183847433212",               // '0'
    "172822 1232",                      // '1'
    "07183847460242",                   // '2'
    "0718384746354443321203 1535",      // '3'
    "32380444",                         // '4'
    "4808053544433202",                 // '5'
    "38180703123243443505",             // '6'
    "084812",                           // '7'
    "15060718384746351504031232434435", // '8'
    "45150607183847433212",             // '9'
    "26 23",                            // ':'
    "26 2311",                          // ';'
    "470543",                           // '<'
    "0646 0444",                        // '='
    "074503",                           // '>'
    "07183847462524 22",                // '?'
    "34361614344547381807031242",       // '@'
    "0206284642 0545",                  // 'A'
    "02083847463505 3544433202",        // 'B'
    "4738180703123243",                 // 'C'
    "02083847433202",                   // 'D'
    "48080242 0535",                    // 'E'
    "480802 0535",                      // 'F'
    "47381807031232434525",             // 'G'
    "0208 4248 0545",                   // 'H'
    "1838 2822 1232",                   // 'I'
    "4843321203",                       // 'J'
    "0208 4804 1542",                   // 'K'
    "080242",                           // 'L'
    "0208254842",                       // 'M'
    "02084248",                         // 'N'
    "120307183847433212",               // 'O'
    "02083847463505",                   // 'P'
    "120307183847433212 2442",          // 'Q'
    "02083847463505 2542",              // 'R'
    "473818070615354443321203",         // 'S'
    "0848 2822",                        // 'T'
    "080312324348",                     // 'U'
    "082248",                           // 'V'
    "0812253248",                       // 'W'
    "0248 0842",                        // 'X'
    "082548 2522",                      // 'Y'
    "08480242",                         // 'Z'
    "38181232",                         // '['
    "0842",                             // '\\'
    "18383212",                         // ']'
    "062846",                           // '^'
    "0141",                             // '_'
    "1827",                             // '`'
    "4642 4536160503123243",            // 'a'
    "0802 0312324345361605",            // 'b'
    "4536160503123243",                 // 'c'
    "4842 4536160503123243",            // 'd'
    "044445361605031242",               // 'e'
    "38281712 0636",                    // 'f'
    "4641301001 4536160503123243",      // 'g'
    "0802 0516364542",                  // 'h'
    "2622 28",                          // 'i'
    "3631201001 38",                    // 'j'
    "0802 4603 1442",                   // 'k'
    "182822 1232",                      // 'l'
    "0602 05162522 25364542",           // 'm'
    "0602 0516364542",                  // 'n'
    "120305163645433212",               // 'o'
    "0600 0516364543321203",            // 'p'
    "4640 4536160503123243",            // 'q'
    "0602 05163645",                    // 'r'
    "45361605143443321203",             // 's'
    "18132232 0636",                    // 't'
    "0603123243 4642",                  // 'u'
    "062246",                           // 'v'
    "0612253246",                       // 'w'
    "0246 0642",                        // 'x'
    "0622 4610",                        // 'y'
    "06460242",                         // 'z'
    "38272615242332",                   // '{'
    "2821",                             // '|'
    "18272635242312",                   // '}'
    "05163445",                         // '~'
];

/// The strokes of character `c` (a code 32–126), each a run of grid
/// points; None for any other character.
pub(super) fn strokes(c: u8) -> Option<impl Iterator<Item = impl Iterator<Item = [f64; 2]>>> {
    let glyph = GLYPHS.get(usize::from(c).checked_sub(32)?)?;
    Some(glyph.split(' ').filter(|s| !s.is_empty()).map(|stroke| {
        stroke
            .as_bytes()
            .chunks_exact(2)
            .map(|p| [f64::from(p[0] - b'0'), f64::from(p[1] - b'0') - 2.0])
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_printable_character_has_its_strokes_on_the_grid() {
        for c in 32u8..=126 {
            let glyph = strokes(c).expect("a glyph");
            let points: Vec<[f64; 2]> = glyph.flatten().collect();
            // Only the space is empty.
            assert_eq!(points.is_empty(), c == b' ', "{}", c as char);
            for [x, y] in points {
                assert!(
                    (0.0..=4.0).contains(&x) && (-2.0..=6.0).contains(&y),
                    "{}",
                    c as char
                );
            }
        }
        assert!(strokes(31).is_none() && strokes(127).is_none());
    }

    #[test]
    fn capital_l_is_one_stroke_down_and_along_the_baseline() {
        let l: Vec<Vec<[f64; 2]>> = strokes(b'L').unwrap().map(Iterator::collect).collect();
        assert_eq!(l, vec![vec![[0.0, 6.0], [0.0, 0.0], [4.0, 0.0]]]);
    }
}
