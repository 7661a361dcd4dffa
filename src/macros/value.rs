//! A macro variable's value (behaviour 20.1): vacant, or a number.

use std::fmt;

/// The value of a variable or an expression. A variable that was never set
/// (and `#0`, always) is vacant, which is not zero: Fanuc's Custom Macro B
/// tells the two apart in EQ/NE and in a word's address (behaviour 20.4).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum Value {
    /// No value (`#0`, a variable never set).
    #[default]
    Vacant,
    /// A number.
    Number(f64),
}

impl Value {
    /// The number arithmetic reads: vacant reads as 0 (behaviour 20.4).
    #[inline]
    pub fn number(self) -> f64 {
        match self {
            Value::Vacant => 0.0,
            Value::Number(v) => v,
        }
    }

    /// True for a vacant value.
    #[inline]
    pub fn is_vacant(self) -> bool {
        matches!(self, Value::Vacant)
    }

    /// The number, or None when vacant.
    pub fn get(self) -> Option<f64> {
        match self {
            Value::Vacant => None,
            Value::Number(v) => Some(v),
        }
    }
}

impl fmt::Display for Value {
    /// `vacant`, or the number with three decimals as the control's
    /// variable page shows it (`12.500`).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Value::Vacant => f.write_str("vacant"),
            Value::Number(v) => {
                let v = if *v == 0.0 { 0.0 } else { *v };
                write!(f, "{v:.3}")
            }
        }
    }
}
