//! The control's macro alarms (behaviour 20.9): each a stable diagnostic
//! code and the Fanuc alarm number its message opens with.

use crate::diag::{Diagnostic, Span};

/// One alarm: the diagnostic's code and the control's number and name.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Alarm {
    /// The stable diagnostic code.
    pub code: &'static str,
    /// The Fanuc alarm (`PS0112 ZERO DIVIDE`).
    pub alarm: &'static str,
}

impl Alarm {
    /// The error at `span`, its message opening with the alarm.
    pub fn at(self, span: Span, message: impl AsRef<str>) -> Diagnostic {
        Diagnostic::error(
            self.code,
            span,
            format!("{}: {}", self.alarm, message.as_ref()),
        )
    }
}

/// A value out of the variables' range (±10^308).
pub const OVERFLOW: Alarm = Alarm {
    code: "macro-overflow",
    alarm: "PS0111 OVERFLOW :FLOATING",
};
/// Division by zero (also MOD 0 and TAN of 90°: TAN is SIN/COS).
pub const ZERO_DIVIDE: Alarm = Alarm {
    code: "macro-zero-divide",
    alarm: "PS0112 ZERO DIVIDE",
};
/// An expression written wrong, or a value of the wrong kind (a condition
/// stored in a variable).
pub const FORMAT: Alarm = Alarm {
    code: "macro-expression",
    alarm: "PS0114 ILLEGAL EXPRESSION FORMAT",
};
/// A variable number no variable has.
pub const VARIABLE_NUMBER: Alarm = Alarm {
    code: "macro-variable-number",
    alarm: "PS0115 VARIABLE NO. OUT OF RANGE",
};
/// A variable that can only be read (`#0`).
pub const WRITE_PROTECTED: Alarm = Alarm {
    code: "macro-write-protected",
    alarm: "PS0116 WRITE PROTECTED VARIABLE",
};
/// Brackets nested more than five deep.
pub const NESTING: Alarm = Alarm {
    code: "macro-bracket-nesting",
    alarm: "PS0118 TOO MANY BRACKET NESTING",
};
/// A function's argument outside its domain.
pub const ARGUMENT: Alarm = Alarm {
    code: "macro-argument-range",
    alarm: "PS0119 ARGUMENT VALUE OUT OF RANGE",
};
/// A DO without its END (behaviour 20.13).
pub const MISSING_END: Alarm = Alarm {
    code: "macro-missing-end",
    alarm: "PS0124 MISSING END STATEMENT",
};
/// A statement written wrong.
pub const STATEMENT: Alarm = Alarm {
    code: "macro-statement",
    alarm: "PS0125 MACRO STATEMENT FORMAT ERROR",
};
/// DO/END's number not 1, 2 or 3.
pub const LOOP_NUMBER: Alarm = Alarm {
    code: "macro-loop-number",
    alarm: "PS0126 ILLEGAL LOOP NUMBER",
};
/// An NC word and a macro statement in one block.
pub const NC_AND_MACRO: Alarm = Alarm {
    code: "macro-nc-statement",
    alarm: "PS0127 DUPLICATE NC,MACRO STATEMENT",
};
/// A jump's sequence number out of range.
pub const SEQUENCE: Alarm = Alarm {
    code: "macro-sequence-number",
    alarm: "PS0128 ILLEGAL MACRO SEQUENCE NUMBER",
};
/// A vacant value where a number is needed (a jump's target): vacant reads
/// as 0 in arithmetic, and no sequence number is 0.
pub const VACANT: Alarm = Alarm {
    code: "macro-vacant",
    alarm: "PS0128 ILLEGAL MACRO SEQUENCE NUMBER",
};
