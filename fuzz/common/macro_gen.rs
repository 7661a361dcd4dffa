//! Custom Macro B programs made from bytes, for the `macros` fuzz target and
//! the "no input aborts" property test (`tests/macro_props.rs`): every byte
//! picks the next choice of a grammar of the language — assignments with
//! expressions of every operator and function, direct and indirect
//! variables, IF … GOTO / THEN, WHILE … DO … END (nested, mismatched,
//! endless), GOTO to labels that exist or not, words whose values are
//! expressions, G65 and M98 calls of a program in the same file, G10,
//! #3000 and #3006 — so that random input reaches the evaluator, not only
//! the parser's first error. Bounded: at most [`MAX_STATEMENTS`] statements
//! and [`MAX_DEPTH`] levels of brackets (past five, PS0118), with now and
//! then a flat chain of a few thousand terms.

/// Statements of one generated program (the called program's included).
pub const MAX_STATEMENTS: usize = 48;

/// Deepest nesting of brackets and functions generated.
pub const MAX_DEPTH: u32 = 7;

/// A cursor over the input bytes; past their end every choice is 0.
struct Bytes<'a> {
    data: &'a [u8],
    at: usize,
}

impl Bytes<'_> {
    fn next(&mut self) -> u8 {
        let b = self.data.get(self.at).copied().unwrap_or(0);
        self.at += 1;
        b
    }

    fn below(&mut self, n: u8) -> u8 {
        self.next() % n
    }

    fn done(&self) -> bool {
        self.at >= self.data.len()
    }
}

/// Variables a program sets and reads.
const VARIABLES: [&str; 10] = [
    "#1", "#2", "#3", "#24", "#26", "#33", "#100", "#101", "#500", "#13",
];

/// Variables that are vacant, out of range, write-protected or the
/// control's (offsets, work origins, modal codes, the clock): each has its
/// rule or its alarm.
const RARE_VARIABLES: [&str; 8] = [
    "#0", "#34", "#2001", "#5221", "#4001", "#3001", "#99", "#10001",
];

const FUNCTIONS: [&str; 16] = [
    "SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN", "SQRT", "SQR", "ABS", "BIN", "BCD", "ROUND",
    "FIX", "FUP", "LN", "EXP",
];

const OPERATORS: [&str; 8] = ["+", "-", "*", "/", "AND", "OR", "XOR", "MOD"];

const COMPARISONS: [&str; 6] = ["EQ", "NE", "GT", "LT", "GE", "LE"];

const NUMBERS: [&str; 12] = [
    "0",
    "1",
    "2",
    "3.5",
    ".5",
    "10.",
    "-1",
    "360",
    "0.0001",
    "99999999",
    "123456789012345",
    "1000000",
];

fn number(b: &mut Bytes<'_>, out: &mut String) {
    out.push_str(NUMBERS[usize::from(b.below(NUMBERS.len() as u8))]);
}

fn variable(b: &mut Bytes<'_>, out: &mut String, depth: u32) {
    if b.below(8) == 0 && depth < MAX_DEPTH {
        out.push_str("#[");
        expr(b, out, depth + 1);
        out.push(']');
    } else if b.below(8) == 0 {
        out.push_str(RARE_VARIABLES[usize::from(b.below(RARE_VARIABLES.len() as u8))]);
    } else {
        out.push_str(VARIABLES[usize::from(b.below(VARIABLES.len() as u8))]);
    }
}

fn operand(b: &mut Bytes<'_>, out: &mut String, depth: u32) {
    // Deeper, a compound operand is rarer: the sixth bracket level
    // (PS0118) is reached now and then, not by every expression.
    let pick = if depth >= MAX_DEPTH {
        b.below(2)
    } else {
        b.below(8 + 6 * depth as u8)
    };
    match pick {
        0 => number(b, out),
        1 => variable(b, out, depth),
        2 | 7 => {
            out.push('[');
            expr(b, out, depth + 1);
            out.push(']');
        }
        3 => {
            out.push('-');
            operand(b, out, depth + 1);
        }
        4 => {
            let f = FUNCTIONS[usize::from(b.below(FUNCTIONS.len() as u8))];
            out.push_str(f);
            out.push('[');
            expr(b, out, depth + 1);
            if f == "ATAN" && b.below(2) == 0 {
                out.push_str(if b.below(2) == 0 { "]/[" } else { "," });
                expr(b, out, depth + 1);
            }
            out.push(']');
        }
        5 => {
            out.push_str("POW[");
            expr(b, out, depth + 1);
            out.push(',');
            expr(b, out, depth + 1);
            out.push(']');
        }
        6 => {
            out.push_str("ADP[");
            variable(b, out, depth + 1);
            out.push(']');
        }
        n if n % 2 == 0 => number(b, out),
        _ => variable(b, out, depth),
    }
}

fn expr(b: &mut Bytes<'_>, out: &mut String, depth: u32) {
    operand(b, out, depth);
    let terms = match b.below(64) {
        0 if depth <= 1 => 2000 + usize::from(b.next()) * 8,
        n => usize::from(n % 3),
    };
    let op = OPERATORS[usize::from(b.below(OPERATORS.len() as u8))];
    for i in 0..terms {
        // A long chain repeats one operator on constants: the point is its
        // length, and the input runs out long before.
        if terms > 100 {
            out.push_str(op);
            out.push_str(if i % 2 == 0 { "1" } else { "2" });
            continue;
        }
        out.push_str(OPERATORS[usize::from(b.below(OPERATORS.len() as u8))]);
        operand(b, out, depth);
    }
}

fn condition(b: &mut Bytes<'_>, out: &mut String) {
    // Now and then one that always holds: a loop that never ends.
    if b.below(6) == 0 {
        out.push_str("[1EQ1]");
        return;
    }
    out.push('[');
    for i in 0..=b.below(3) {
        if i > 0 {
            out.push_str(if b.below(2) == 0 { "AND" } else { "OR" });
        }
        let bracketed = b.below(3) == 0;
        if bracketed {
            out.push('[');
        }
        expr(b, out, 2);
        if b.below(6) != 0 {
            out.push_str(COMPARISONS[usize::from(b.below(COMPARISONS.len() as u8))]);
            expr(b, out, 2);
        }
        if bracketed {
            out.push(']');
        }
    }
    out.push(']');
}

fn label(b: &mut Bytes<'_>) -> u8 {
    1 + b.below(9)
}

/// One statement or NC block, with its end of block.
fn statement(b: &mut Bytes<'_>, out: &mut String, open_loops: &mut Vec<u8>) {
    if b.below(5) == 0 {
        out.push_str(&format!("N{}", label(b)));
    }
    match b.below(16) {
        0..=3 => {
            variable(b, out, 1);
            out.push('=');
            expr(b, out, 1);
        }
        4 => {
            out.push_str("IF");
            condition(b, out);
            out.push_str(&format!("GOTO{}", label(b)));
        }
        5 => {
            out.push_str("IF");
            condition(b, out);
            out.push_str("THEN");
            variable(b, out, 1);
            out.push('=');
            expr(b, out, 1);
        }
        6 if open_loops.len() < 3 => {
            let m = 1 + b.below(3);
            out.push_str("WHILE");
            condition(b, out);
            out.push_str(&format!("DO{m}"));
            open_loops.push(m);
        }
        7 => match open_loops.pop() {
            // Now and then the wrong number: PS0124.
            Some(m) if b.below(8) != 0 => out.push_str(&format!("END{m}")),
            Some(_) => out.push_str(&format!("END{}", 1 + b.below(3))),
            None if b.below(8) == 0 => out.push_str(&format!("END{}", 1 + b.below(3))),
            None => out.push_str("#1=#1+1"),
        },
        8 => out.push_str(&format!("GOTO{}", label(b))),
        9 | 10 => {
            let g = ["G00", "G01", "G02", "G03", "G91G01", "G90G00"][usize::from(b.below(6))];
            out.push_str(g);
            for axis in ["X", "Y", "Z"] {
                if b.below(2) == 0 {
                    out.push_str(axis);
                    if b.below(2) == 0 {
                        variable(b, out, 1);
                    } else {
                        out.push('[');
                        expr(b, out, 1);
                        out.push(']');
                    }
                }
            }
            if g.contains("G02") || g.contains("G03") {
                out.push_str("R[");
                expr(b, out, 1);
                out.push(']');
            }
            out.push_str("F100.");
        }
        11 => {
            out.push_str("G65P9010A");
            variable(b, out, 1);
            out.push_str("B[");
            expr(b, out, 1);
            out.push(']');
        }
        12 => {
            out.push_str("M98P9010L");
            number(b, out);
        }
        13 => {
            out.push_str(["G10L2P1X", "G10L12P1R", "G10L10P2R"][usize::from(b.below(3))]);
            variable(b, out, 1);
        }
        14 => {
            out.push_str(["#3000=", "#3006="][usize::from(b.below(2))]);
            number(b, out);
            out.push_str("(STOP)");
        }
        _ => {
            // A few raw bytes: what a paste brings.
            for _ in 0..b.below(6) {
                let c = b.next();
                out.push(if c.is_ascii_graphic() {
                    char::from(c)
                } else {
                    ' '
                });
            }
        }
    }
    out.push('\n');
}

/// The program the bytes describe: a main program ending in M30 and the
/// macro O9010 that its G65 and M98 call, which reads its arguments (#1,
/// #2) and returns with M99.
pub fn program_from(data: &[u8]) -> String {
    let mut b = Bytes { data, at: 0 };
    // Most variables set first, so that reading one is mostly a number:
    // vacant has its own rules (behaviour 20.4) and the rare ones read it.
    let mut out = String::from(
        "%\nO0001\nG90G21G17G00X0Y0Z10.\n#1=1\n#2=2.5\n#3=3\n#13=-4\n#24=24\n#26=-2\n#33=0.5\n#100=10\n#101=-1\n#500=7\n",
    );
    let mut open = Vec::new();
    let main = 1 + usize::from(b.below(MAX_STATEMENTS as u8 - 8));
    for _ in 0..main {
        if b.done() {
            break;
        }
        statement(&mut b, &mut out, &mut open);
    }
    out.push_str("M30\nO9010\n");
    let mut open = Vec::new();
    for _ in 0..b.below(8) {
        statement(&mut b, &mut out, &mut open);
    }
    out.push_str("M99\n%\n");
    out
}
