//! Evaluating expressions and statements (behaviour 20.3–20.8) over any
//! variables: the machine, or a test's table, implements [`Variables`].

use super::alarm;
use super::ast::{BinOp, CmpOp, Expr, ExprKind, Func, Statement, StatementKind};
use super::value::Value;
use crate::diag::{Diagnostic, Span};

/// Largest magnitude a variable holds (Fanuc 0i-F: ±10^308; PS0111 past it).
pub const MAX_MAGNITUDE: f64 = 1e308;

/// How near two values are equal for LinuxCNC's EQ and NE.
const LINUXCNC_EQUAL: f64 = 0.0001;

/// Largest sequence number a jump names.
pub const MAX_SEQUENCE: f64 = 99_999_999.0;

/// Where the variables are: local, common, system (the implementor says
/// which numbers exist, and refuses the others with a diagnostic).
pub trait Variables {
    /// The value of `#number`; `span` is where it is written.
    fn read(&mut self, number: u32, span: Span) -> Result<Value, Diagnostic>;
    /// Sets `#number`.
    fn write(&mut self, number: u32, value: Value, span: Span) -> Result<(), Diagnostic>;
    /// The value of LinuxCNC's `#<name>` (behaviour 22.6); None when it
    /// is not set.
    fn read_named(&mut self, name: &str, span: Span) -> Result<Option<f64>, Diagnostic> {
        let _ = name;
        Err(named_unknown(span))
    }
    /// Sets LinuxCNC's `#<name>`.
    fn write_named(&mut self, name: &str, value: f64, span: Span) -> Result<(), Diagnostic> {
        let _ = (name, value);
        Err(named_unknown(span))
    }
}

/// A named parameter where the profile has none.
fn named_unknown(span: Span) -> Diagnostic {
    alarm::FORMAT.at(
        span,
        "`#<name>` is LinuxCNC's named parameter: this profile numbers its variables",
    )
}

/// The points on which controls differ (behaviour 7.39, 7.40).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Options {
    /// ATAN and ASIN give −180…180 and −90…90 (Fanuc parameter NAT = 1),
    /// not 0…360 and 270…90 (NAT = 0) (setting 7.39).
    pub signed_angles: bool,
    /// A comparison is the number 1 or 0 and a condition any number, true
    /// when not 0 (Haas); else a comparison is true or false only, and
    /// storing it is an alarm (Fanuc) (setting 7.40).
    pub numeric_conditions: bool,
    /// LinuxCNC's functions (behaviour 22.5): FIX is the floor, FUP the
    /// ceiling, ROUND the nearest whole number even in a word, and MOD's
    /// result is not negative.
    pub linuxcnc: bool,
}

/// What a statement did (the jumps are for the executor to make).
#[derive(Clone, Debug, PartialEq)]
pub enum Outcome {
    /// `#number = value`, which was `was`.
    Assigned {
        /// The variable.
        number: u32,
        /// Its new value.
        value: Value,
        /// Its value before.
        was: Value,
    },
    /// IF … THEN whose condition does not hold, or IF … GOTO not taken.
    NotTaken,
    /// GOTO n, or IF … GOTO n taken.
    Goto(u32),
    /// WHILE [c] DO m: whether the condition holds.
    While {
        /// The condition holds (the loop's body runs).
        holds: bool,
        /// m.
        label: u8,
    },
    /// DO m without WHILE.
    Do(u8),
    /// END m.
    End(u8),
    /// `#<name> = value` (behaviour 22.6).
    AssignedNamed {
        /// The value set.
        value: f64,
        /// Its value before, if it was set.
        was: Option<f64>,
    },
    /// An o-word: the run evaluates what it needs as it goes (behaviour
    /// 22.7).
    OWord,
}

/// A LinuxCNC parameter setting read, not yet made (behaviour 22.10).
#[derive(Clone, Debug, PartialEq)]
pub enum Setting {
    /// `#number = value`.
    Numbered(u32, Value),
    /// `#<name> = value`.
    Named(Box<str>, f64),
}

/// A value while evaluating: a number, or the truth of a comparison.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Val {
    Num(Value),
    Bool(bool),
}

/// Evaluates over `vars` with the control's `options`.
pub struct Evaluator<'v> {
    vars: &'v mut dyn Variables,
    options: Options,
    /// In a word's value: the increment ROUND rounds to (behaviour 20.6).
    round_to: Option<f64>,
}

impl<'v> Evaluator<'v> {
    /// An evaluator of statements and conditions.
    pub fn new(vars: &'v mut dyn Variables, options: Options) -> Evaluator<'v> {
        Evaluator {
            vars,
            options,
            round_to: None,
        }
    }

    /// The parameter and the value of LinuxCNC's setting `s`, read with
    /// the parameters as they were before the line (behaviour 22.10).
    pub fn setting(&mut self, s: &Statement) -> Result<(Setting, Span), Diagnostic> {
        match &s.kind {
            StatementKind::Assign {
                target,
                target_span,
                value,
            } => {
                let number = self.index(target)?;
                Ok((Setting::Numbered(number, self.value(value)?), *target_span))
            }
            StatementKind::AssignNamed {
                name,
                target_span,
                value,
            } => Ok((
                Setting::Named(name.clone(), self.number(value)?),
                *target_span,
            )),
            _ => Err(Diagnostic::error(
                "internal",
                s.span,
                "a parameter setting was expected",
            )),
        }
    }

    /// Runs a statement.
    pub fn execute(&mut self, s: &Statement) -> Result<Outcome, Diagnostic> {
        Ok(match &s.kind {
            StatementKind::Assign {
                target,
                target_span,
                value,
            } => {
                let number = self.index(target)?;
                let v = self.value(value)?;
                let was = self.vars.read(number, *target_span).unwrap_or_default();
                self.vars.write(number, v, *target_span)?;
                Outcome::Assigned {
                    number,
                    value: v,
                    was,
                }
            }
            StatementKind::Goto(n) => Outcome::Goto(self.sequence(n)?),
            StatementKind::IfGoto(c, n) => match self.condition(c)? {
                true => Outcome::Goto(self.sequence(n)?),
                false => Outcome::NotTaken,
            },
            StatementKind::IfThen(c, then) => match self.condition(c)? {
                true => self.execute(then)?,
                false => Outcome::NotTaken,
            },
            StatementKind::While(c, label) => Outcome::While {
                holds: self.condition(c)?,
                label: *label,
            },
            StatementKind::Do(label) => Outcome::Do(*label),
            StatementKind::End(label) => Outcome::End(*label),
            StatementKind::AssignNamed {
                name,
                target_span,
                value,
            } => {
                let v = self.number(value)?;
                let was = self.vars.read_named(name, *target_span).ok().flatten();
                self.vars.write_named(name, v, *target_span)?;
                Outcome::AssignedNamed { value: v, was }
            }
            StatementKind::OWord(_) => Outcome::OWord,
        })
    }

    /// The value of an expression.
    pub fn value(&mut self, e: &Expr) -> Result<Value, Diagnostic> {
        match self.eval(e)? {
            Val::Num(v) => Ok(v),
            Val::Bool(b) if self.options.numeric_conditions => Ok(Value::Number(f64::from(b))),
            Val::Bool(_) => Err(alarm::FORMAT.at(
                e.span,
                "a comparison is true or false, not a number: it cannot be a value",
            )),
        }
    }

    /// The value of a word's expression: ROUND in it rounds to `increment`
    /// (the address's least input increment), not to a whole number.
    pub fn word_value(&mut self, e: &Expr, increment: f64) -> Result<Value, Diagnostic> {
        self.round_to = Some(increment);
        let v = self.value(e);
        self.round_to = None;
        v
    }

    /// Whether a condition (IF, WHILE) holds.
    pub fn condition(&mut self, e: &Expr) -> Result<bool, Diagnostic> {
        match self.eval(e)? {
            Val::Bool(b) => Ok(b),
            Val::Num(v) if self.options.numeric_conditions => Ok(v.number() != 0.0),
            Val::Num(_) => Err(alarm::FORMAT.at(
                e.span,
                "IF and WHILE take a comparison (`[#1 LT 10]`), not a number",
            )),
        }
    }

    /// The number of `#[e]`: vacant reads as 0 (so `#0`), a fraction is
    /// rounded, a negative or too large number is PS0115.
    fn index(&mut self, e: &Expr) -> Result<u32, Diagnostic> {
        let v = self.number(e)?.round();
        if !(0.0..=f64::from(u32::MAX)).contains(&v) {
            return Err(alarm::VARIABLE_NUMBER.at(
                e.span,
                format!("#{v} is no variable: variable numbers are 0 or more"),
            ));
        }
        Ok(v as u32)
    }

    fn sequence(&mut self, e: &Expr) -> Result<u32, Diagnostic> {
        let v = self.value(e)?;
        let Value::Number(n) = v else {
            return Err(alarm::VACANT.at(e.span, "the sequence number to jump to is vacant"));
        };
        let n = n.round();
        if !(1.0..=MAX_SEQUENCE).contains(&n) {
            return Err(
                alarm::SEQUENCE.at(e.span, format!("{n} is no sequence number (1 to 99999999)"))
            );
        }
        Ok(n as u32)
    }

    fn number(&mut self, e: &Expr) -> Result<f64, Diagnostic> {
        Ok(self.value(e)?.number())
    }

    fn eval(&mut self, e: &Expr) -> Result<Val, Diagnostic> {
        let v = match &e.kind {
            ExprKind::Number(v) => *v,
            ExprKind::Bracket(inner) => return self.eval(inner),
            ExprKind::Named(name) => match self.vars.read_named(name, e.span)? {
                Some(v) => v,
                None => {
                    return Err(Diagnostic::error(
                        "named-parameter",
                        e.span,
                        format!(
                            "#<{name}> is not set: LinuxCNC refuses to read a named parameter before it is set (\"Named parameter #<{name}> not defined\")"
                        ),
                    ));
                }
            },
            ExprKind::Exists(name) => f64::from(u8::from(
                self.vars.read_named(name, e.span).ok().flatten().is_some(),
            )),
            ExprKind::Var(index) => {
                let n = self.index(index)?;
                return Ok(Val::Num(self.vars.read(n, e.span)?));
            }
            ExprKind::Neg(inner) => 0.0 - self.number(inner)?,
            ExprKind::Compare(op, a, b) => {
                let (a, b) = (self.value(a)?, self.value(b)?);
                return Ok(Val::Bool(self.compare(*op, a, b)));
            }
            ExprKind::Chain(first, rest) => return self.chain(first, rest, e.span),
            ExprKind::Call(f, a) => {
                let x = self.number(a)?;
                self.call(*f, x, a.span, e.span)?
            }
            ExprKind::Atan2(a, b) => {
                let (y, x) = (self.number(a)?, self.number(b)?);
                if x == 0.0 && y == 0.0 {
                    return Err(alarm::ARGUMENT.at(e.span, "ATAN of 0 and 0 has no angle"));
                }
                self.angle(y.atan2(x).to_degrees(), 360.0)
            }
            ExprKind::Pow(a, b) => {
                let (x, y) = (self.number(a)?, self.number(b)?);
                if (x < 0.0 && y.fract() != 0.0) || (x == 0.0 && y < 0.0) {
                    return Err(
                        alarm::ARGUMENT.at(e.span, format!("POW[{x},{y}] has no real value"))
                    );
                }
                x.powf(y)
            }
        };
        checked(v, e.span).map(|v| Val::Num(Value::Number(v)))
    }

    /// A level's operators left to right (`1-2-3` is `[1-2]-3`): each
    /// result is the left operand of the next, its span from the chain's
    /// start to the operand's end.
    fn chain(
        &mut self,
        first: &Expr,
        rest: &[(BinOp, Expr)],
        span: Span,
    ) -> Result<Val, Diagnostic> {
        let mut acc = self.eval(first)?;
        let mut left = first.span;
        for (op, b) in rest {
            let y = self.eval(b)?;
            let joined = Span {
                end: b.span.end,
                ..left
            };
            acc = self.binary(*op, acc, left, y, b.span, joined)?;
            left = joined;
        }
        debug_assert_eq!(left.end, span.end);
        Ok(acc)
    }

    fn binary(
        &mut self,
        op: BinOp,
        x: Val,
        a: Span,
        y: Val,
        b: Span,
        span: Span,
    ) -> Result<Val, Diagnostic> {
        if self.options.linuxcnc
            && let BinOp::And | BinOp::Or | BinOp::Xor = op
        {
            // LinuxCNC: logic on any values, 0 false and any other true,
            // the result 1 or 0 (behaviour 22.5).
            let p = self.as_number(x, a)? != 0.0;
            let q = self.as_number(y, b)? != 0.0;
            let r = match op {
                BinOp::And => p && q,
                BinOp::Or => p || q,
                _ => p != q,
            };
            return Ok(Val::Num(Value::Number(f64::from(u8::from(r)))));
        }
        if let (BinOp::And | BinOp::Or | BinOp::Xor, Val::Bool(p), Val::Bool(q)) = (op, x, y) {
            return Ok(Val::Bool(match op {
                BinOp::And => p && q,
                BinOp::Or => p || q,
                _ => p != q,
            }));
        }
        let x = self.as_number(x, a)?;
        let y = self.as_number(y, b)?;
        let v = match op {
            BinOp::Add => x + y,
            BinOp::Sub => x - y,
            BinOp::Mul => x * y,
            BinOp::Div | BinOp::Mod if y == 0.0 => {
                return Err(alarm::ZERO_DIVIDE
                    .at(b, format!("the divisor of {} is 0 (or vacant)", op.text())));
            }
            BinOp::Div => x / y,
            // LinuxCNC: fmod, then the divisor's size added to a negative
            // result (`-7 MOD 3` is 2).
            BinOp::Mod if self.options.linuxcnc && x % y < 0.0 => x % y + y.abs(),
            BinOp::Mod => x % y,
            BinOp::Cmp(c) => f64::from(u8::from(self.compare(
                c,
                Value::Number(x),
                Value::Number(y),
            ))),
            BinOp::Pow => {
                if (x < 0.0 && y.fract() != 0.0) || (x == 0.0 && y < 0.0) {
                    return Err(alarm::ARGUMENT.at(span, format!("{x} ** {y} has no real value")));
                }
                x.powf(y)
            }
            // Bit by bit on the whole parts (Haas: the integer portion).
            BinOp::And => (whole(x) & whole(y)) as f64,
            BinOp::Or => (whole(x) | whole(y)) as f64,
            BinOp::Xor => (whole(x) ^ whole(y)) as f64,
        };
        checked(v, span).map(|v| Val::Num(Value::Number(v)))
    }

    /// A comparison: Fanuc's ([`compare`]), or LinuxCNC's, whose EQ and
    /// NE hold within 0.0001 (rs274's TOLERANCE_EQUAL; behaviour 22.5).
    fn compare(&self, op: CmpOp, a: Value, b: Value) -> bool {
        match op {
            CmpOp::Eq | CmpOp::Ne if self.options.linuxcnc => {
                ((a.number() - b.number()).abs() < LINUXCNC_EQUAL) == (op == CmpOp::Eq)
            }
            _ => compare(op, a, b),
        }
    }

    fn as_number(&self, v: Val, at: Span) -> Result<f64, Diagnostic> {
        match v {
            Val::Num(v) => Ok(v.number()),
            Val::Bool(b) if self.options.numeric_conditions => Ok(f64::from(b)),
            Val::Bool(_) => Err(alarm::FORMAT.at(
                at,
                "a comparison is true or false: only AND, OR and XOR join it to another",
            )),
        }
    }

    fn call(&mut self, f: Func, x: f64, arg: Span, span: Span) -> Result<f64, Diagnostic> {
        let out_of_range =
            |what: &str| Err(alarm::ARGUMENT.at(arg, format!("{}[{x}]: {what}", f.name())));
        Ok(match f {
            Func::Sin => x.to_radians().sin(),
            Func::Cos => x.to_radians().cos(),
            Func::Tan => {
                // TAN is SIN/COS: at ±90° (and every 180° on) a division by 0.
                let c = x.to_radians().cos();
                if c.abs() < 1e-12 {
                    return Err(alarm::ZERO_DIVIDE.at(span, format!("TAN[{x}]: the cosine is 0")));
                }
                x.to_radians().sin() / c
            }
            Func::Asin | Func::Acos if !(-1.0..=1.0).contains(&x) => {
                return out_of_range("the argument is outside -1 to 1");
            }
            Func::Asin => self.angle(x.asin().to_degrees(), 360.0),
            Func::Acos => x.acos().to_degrees(),
            Func::Atan => self.angle(x.atan().to_degrees(), 360.0),
            Func::Sqrt if x < 0.0 => return out_of_range("the square root of a negative number"),
            Func::Sqrt => x.sqrt(),
            Func::Abs => x.abs(),
            Func::Round if self.options.linuxcnc => x.round(),
            Func::Round => match self.round_to {
                Some(inc) if inc > 0.0 => (x / inc).round() * inc,
                _ => x.round(),
            },
            Func::Fix if self.options.linuxcnc => x.floor(),
            Func::Fix => x.trunc(),
            Func::Fup if self.options.linuxcnc => x.ceil(),
            Func::Fup => x.abs().ceil().copysign(x),
            Func::Ln if x <= 0.0 => return out_of_range("the logarithm of 0 or less"),
            Func::Ln => x.ln(),
            Func::Exp => x.exp(),
            Func::Bin => match bin(x) {
                Some(v) => v,
                None => return out_of_range("not a BCD number (whole, each hex digit 0 to 9)"),
            },
            Func::Bcd => match bcd(x) {
                Some(v) => v,
                None => return out_of_range("BCD takes a whole number from 0 to 99999999"),
            },
            Func::Adp => {
                return Err(Diagnostic::error(
                    "macro-not-modelled",
                    span,
                    "ADP (decimal point addition) is not modelled yet: its value depends on how a macro call's argument was written (issue 22 part 1)",
                ));
            }
        })
    }

    /// An angle of ATAN or ASIN in the control's range (setting 7.39):
    /// −180…180 as computed, or 0…360 with the negative ones turned once.
    fn angle(&self, degrees: f64, turn: f64) -> f64 {
        if self.options.signed_angles || degrees >= 0.0 {
            degrees
        } else {
            degrees + turn
        }
    }
}

/// Fanuc's comparisons (behaviour 20.5): EQ and NE tell vacant from 0 (two
/// vacants are equal); GT, LT, GE, LE read vacant as 0.
pub fn compare(op: CmpOp, a: Value, b: Value) -> bool {
    match op {
        CmpOp::Eq | CmpOp::Ne => {
            let same = match (a, b) {
                (Value::Vacant, Value::Vacant) => true,
                (Value::Number(x), Value::Number(y)) => x == y,
                _ => false,
            };
            same == (op == CmpOp::Eq)
        }
        CmpOp::Gt => a.number() > b.number(),
        CmpOp::Lt => a.number() < b.number(),
        CmpOp::Ge => a.number() >= b.number(),
        CmpOp::Le => a.number() <= b.number(),
    }
}

/// A result in the variables' range (PS0111 past ±10^308 or not a number).
fn checked(v: f64, span: Span) -> Result<f64, Diagnostic> {
    if v.is_finite() && v.abs() <= MAX_MAGNITUDE {
        Ok(v)
    } else {
        Err(alarm::OVERFLOW.at(
            span,
            "the result is beyond ±10^308, the range of a macro variable",
        ))
    }
}

fn whole(x: f64) -> i64 {
    x.trunc() as i64
}

/// BIN: the BCD number `x` (each hexadecimal digit a decimal one) as binary.
fn bin(x: f64) -> Option<f64> {
    if x < 0.0 || x.fract() != 0.0 || x > f64::from(u32::MAX) {
        return None;
    }
    let mut n = x as u32;
    let (mut v, mut scale) = (0u64, 1u64);
    for _ in 0..8 {
        let digit = n & 0xF;
        if digit > 9 {
            return None;
        }
        v += u64::from(digit) * scale;
        scale *= 10;
        n >>= 4;
    }
    Some(v as f64)
}

/// BCD: the whole number `x` (0 to 99999999) as BCD.
fn bcd(x: f64) -> Option<f64> {
    if !(0.0..=99_999_999.0).contains(&x) || x.fract() != 0.0 {
        return None;
    }
    let mut n = x as u64;
    let (mut v, mut shift) = (0u64, 0);
    while n > 0 {
        v |= (n % 10) << shift;
        n /= 10;
        shift += 4;
    }
    Some(v as f64)
}
