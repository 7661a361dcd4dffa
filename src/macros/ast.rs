//! The parsed form of macro expressions and statements (behaviour 20.2,
//! 20.3): every node keeps its span, so an alarm points at its operand.

use crate::diag::Span;

/// An expression with its place in the text.
#[derive(Clone, Debug, PartialEq)]
pub struct Expr {
    /// What it is.
    pub kind: ExprKind,
    /// Where it is written.
    pub span: Span,
}

/// The kinds of expression.
#[derive(Clone, Debug, PartialEq)]
pub enum ExprKind {
    /// A constant (`12`, `1.5`, `.5`).
    Number(f64),
    /// A variable: `#n` (the index a constant) or `#[expr]`.
    Var(Box<Expr>),
    /// `-e`.
    Neg(Box<Expr>),
    /// `a op b op c …` of one precedence level of the arithmetic and logic
    /// operators, applied left to right (behaviour 20.3). A chain, not
    /// nested pairs: a flat expression of any length is one node whose
    /// operands are walked in a loop, so only brackets (at most five levels,
    /// PS0118) deepen the tree and the recursion that walks it (behaviour
    /// 20.17).
    Chain(Box<Expr>, Vec<(BinOp, Expr)>),
    /// `a EQ b` and the other comparisons.
    Compare(CmpOp, Box<Expr>, Box<Expr>),
    /// A function of one argument, `SIN[e]`.
    Call(Func, Box<Expr>),
    /// `ATAN[a]/[b]` or `ATAN[a,b]`: the angle of the point (b, a).
    Atan2(Box<Expr>, Box<Expr>),
    /// `POW[a,b]`.
    Pow(Box<Expr>, Box<Expr>),
    /// `[e]`: kept so that ROUND in a word's address can tell its own
    /// bracket, and the report can write the expression as written.
    Bracket(Box<Expr>),
    /// LinuxCNC's named parameter `#<name>` (behaviour 22.6): the name as
    /// the control keys it, lower case and without blanks.
    Named(Box<str>),
    /// LinuxCNC's `EXISTS[#<name>]`: 1 when the named parameter is set.
    Exists(Box<str>),
}

/// Binary operators, in two precedence levels (behaviour 20.3): `* / AND
/// MOD` bind tighter than `+ - OR XOR`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(missing_docs)]
pub enum BinOp {
    Add,
    Sub,
    Or,
    Xor,
    Mul,
    Div,
    And,
    Mod,
    /// LinuxCNC's `**`, which binds tighter than `*` (behaviour 22.5).
    Pow,
    /// A comparison in a LinuxCNC chain (`3 GT 2 EQ 1`: left to right,
    /// each result 1 or 0).
    Cmp(CmpOp),
}

impl BinOp {
    /// True for the multiplication level (`* / AND MOD`).
    pub fn multiplicative(self) -> bool {
        matches!(self, BinOp::Mul | BinOp::Div | BinOp::And | BinOp::Mod)
    }

    /// The operator as written.
    pub fn text(self) -> &'static str {
        match self {
            BinOp::Add => "+",
            BinOp::Sub => "-",
            BinOp::Or => "OR",
            BinOp::Xor => "XOR",
            BinOp::Mul => "*",
            BinOp::Div => "/",
            BinOp::And => "AND",
            BinOp::Mod => "MOD",
            BinOp::Pow => "**",
            BinOp::Cmp(c) => c.text(),
        }
    }
}

/// Comparison operators (behaviour 20.5).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(missing_docs)]
pub enum CmpOp {
    Eq,
    Ne,
    Gt,
    Lt,
    Ge,
    Le,
}

impl CmpOp {
    /// The operator as written.
    pub fn text(self) -> &'static str {
        match self {
            CmpOp::Eq => "EQ",
            CmpOp::Ne => "NE",
            CmpOp::Gt => "GT",
            CmpOp::Lt => "LT",
            CmpOp::Ge => "GE",
            CmpOp::Le => "LE",
        }
    }
}

/// Functions of one argument (behaviour 20.6).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(missing_docs)]
pub enum Func {
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    Atan,
    Sqrt,
    Abs,
    Round,
    Fix,
    Fup,
    Ln,
    Exp,
    Bin,
    Bcd,
    Adp,
}

impl Func {
    /// The function of a name (upper case), without POW (two arguments).
    pub fn of(name: &str) -> Option<Func> {
        Some(match name {
            "SIN" => Func::Sin,
            "COS" => Func::Cos,
            "TAN" => Func::Tan,
            "ASIN" => Func::Asin,
            "ACOS" => Func::Acos,
            "ATAN" => Func::Atan,
            "SQRT" => Func::Sqrt,
            "ABS" => Func::Abs,
            "ROUND" => Func::Round,
            "FIX" => Func::Fix,
            "FUP" => Func::Fup,
            "LN" => Func::Ln,
            "EXP" => Func::Exp,
            "BIN" => Func::Bin,
            "BCD" => Func::Bcd,
            "ADP" => Func::Adp,
            _ => return None,
        })
    }

    /// The name as written.
    pub fn name(self) -> &'static str {
        match self {
            Func::Sin => "SIN",
            Func::Cos => "COS",
            Func::Tan => "TAN",
            Func::Asin => "ASIN",
            Func::Acos => "ACOS",
            Func::Atan => "ATAN",
            Func::Sqrt => "SQRT",
            Func::Abs => "ABS",
            Func::Round => "ROUND",
            Func::Fix => "FIX",
            Func::Fup => "FUP",
            Func::Ln => "LN",
            Func::Exp => "EXP",
            Func::Bin => "BIN",
            Func::Bcd => "BCD",
            Func::Adp => "ADP",
        }
    }
}

/// A macro statement (behaviour 20.7) with its span.
#[derive(Clone, Debug, PartialEq)]
pub struct Statement {
    /// What it is.
    pub kind: StatementKind,
    /// From its first to its last character.
    pub span: Span,
}

/// The statements of Custom Macro B.
#[derive(Clone, Debug, PartialEq)]
pub enum StatementKind {
    /// `#i = e` (`target` is the index expression of `#i`).
    Assign {
        /// The variable's number, as an expression.
        target: Expr,
        /// Where `#i` is written.
        target_span: Span,
        /// The value.
        value: Expr,
    },
    /// `GOTO n`.
    Goto(Expr),
    /// `IF [c] GOTO n`.
    IfGoto(Expr, Expr),
    /// `IF [c] THEN #i = e`.
    IfThen(Expr, Box<Statement>),
    /// `WHILE [c] DO m` (m 1 to 3).
    While(Expr, u8),
    /// `DO m` without WHILE: a loop with no condition.
    Do(u8),
    /// `END m`.
    End(u8),
    /// LinuxCNC's `#<name> = e` (behaviour 22.6).
    AssignNamed {
        /// The name as keyed (lower case, no blanks).
        name: Box<str>,
        /// Where `#<name>` is written.
        target_span: Span,
        /// The value.
        value: Expr,
    },
    /// A LinuxCNC o-word (behaviour 22.7): `o100 if [c]`, `o<name> call`.
    OWord(Box<OWord>),
}

/// A LinuxCNC o-word line: its label and what it does.
#[derive(Clone, Debug, PartialEq)]
pub struct OWord {
    /// `o100` or `o<name>`.
    pub label: OLabel,
    /// What the line does, with its expressions.
    pub op: OOp,
}

/// An o-word's label: a number or a name (lower case, no blanks), as
/// LinuxCNC matches them.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum OLabel {
    /// `o100`.
    Number(u32),
    /// `o<name>`.
    Name(Box<str>),
}

impl std::fmt::Display for OLabel {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            OLabel::Number(n) => write!(f, "o{n}"),
            OLabel::Name(s) => write!(f, "o<{s}>"),
        }
    }
}

/// The o-word keywords with their expressions.
#[derive(Clone, Debug, PartialEq)]
#[allow(missing_docs)]
pub enum OOp {
    Sub,
    /// `endsub`, with the value it returns if written.
    EndSub(Option<Expr>),
    /// `call`, with its arguments `[a] [b] …` (#1, #2, … of the sub).
    Call(Vec<Expr>),
    /// `return`, with the value it returns if written.
    Return(Option<Expr>),
    If(Expr),
    ElseIf(Expr),
    Else,
    EndIf,
    /// `while [c]`: opens a loop, or closes the `do` of its label.
    While(Expr),
    EndWhile,
    Do,
    Repeat(Expr),
    EndRepeat,
    Break,
    Continue,
}

impl OOp {
    /// The keyword as written.
    pub fn keyword(&self) -> &'static str {
        match self {
            OOp::Sub => "sub",
            OOp::EndSub(_) => "endsub",
            OOp::Call(_) => "call",
            OOp::Return(_) => "return",
            OOp::If(_) => "if",
            OOp::ElseIf(_) => "elseif",
            OOp::Else => "else",
            OOp::EndIf => "endif",
            OOp::While(_) => "while",
            OOp::EndWhile => "endwhile",
            OOp::Do => "do",
            OOp::Repeat(_) => "repeat",
            OOp::EndRepeat => "endrepeat",
            OOp::Break => "break",
            OOp::Continue => "continue",
        }
    }
}

impl StatementKind {
    /// The statement's keyword (`#=` for an assignment), for messages.
    pub fn keyword(&self) -> &'static str {
        match self {
            StatementKind::Assign { .. } => "#i = …",
            StatementKind::Goto(_) => "GOTO",
            StatementKind::IfGoto(..) => "IF … GOTO",
            StatementKind::IfThen(..) => "IF … THEN",
            StatementKind::While(..) => "WHILE … DO",
            StatementKind::Do(_) => "DO",
            StatementKind::End(_) => "END",
            StatementKind::AssignNamed { .. } => "#<name> = …",
            StatementKind::OWord(o) => o.op.keyword(),
        }
    }
}
