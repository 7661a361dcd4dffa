//! The program's variables (behaviour 20.1): local #1–#33, common
//! #100–#199 (cleared at reset) and #500–#999 (kept), and #0, always
//! vacant. System variables (#1000 on) belong to the machine: a store
//! alone refuses them.

use std::collections::BTreeMap;
use std::sync::Arc;

use super::alarm;
use super::eval::Variables;
use super::value::Value;
use crate::diag::{Diagnostic, Span};

/// Variables a store holds: #0 to #999.
const SIZE: usize = 1000;

/// What a variable number is (Fanuc 0i-F, "Types of variables").
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// #0: always vacant, never written.
    Null,
    /// #1–#33.
    Local,
    /// #100–#199.
    Common,
    /// #500–#999.
    Kept,
    /// #1000 and on: the control's own.
    System,
    /// Any other number: no variable (#34–#99, #200–#499).
    None,
}

/// The kind of `#n`.
pub fn kind(n: u32) -> Kind {
    match n {
        0 => Kind::Null,
        1..=33 => Kind::Local,
        100..=199 => Kind::Common,
        500..=999 => Kind::Kept,
        1000.. => Kind::System,
        _ => Kind::None,
    }
}

/// The variables #0–#999, shared until written (a machine is cloned for
/// each checkpoint: an untouched store costs nothing, a written one is
/// copied at its first write after the clone).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Store {
    values: Option<Arc<[Value; SIZE]>>,
    /// LinuxCNC's parameters from #1000 on that the program set (behaviour
    /// 22.10): few, so kept by number.
    high: Option<Arc<BTreeMap<u32, f64>>>,
}

impl Store {
    /// The value of a local or common variable (vacant if never set); None
    /// for other numbers.
    pub fn get(&self, n: u32) -> Option<Value> {
        match kind(n) {
            Kind::Null => Some(Value::Vacant),
            Kind::Local | Kind::Common | Kind::Kept => Some(
                self.values
                    .as_ref()
                    .map_or(Value::Vacant, |t| t[n as usize]),
            ),
            Kind::System | Kind::None => None,
        }
    }

    /// Sets a local or common variable; false for other numbers.
    pub fn set(&mut self, n: u32, v: Value) -> bool {
        if !matches!(kind(n), Kind::Local | Kind::Common | Kind::Kept) {
            return false;
        }
        let table = self
            .values
            .get_or_insert_with(|| Arc::new([Value::Vacant; SIZE]));
        Arc::make_mut(table)[n as usize] = v;
        true
    }

    /// A LinuxCNC parameter the program keeps (#1 to #5601, behaviour
    /// 22.10): never set, 0.
    pub fn parameter(&self, n: u32) -> f64 {
        self.parameter_written(n).unwrap_or(0.0)
    }

    /// A LinuxCNC parameter's value if the program has set it.
    pub fn parameter_written(&self, n: u32) -> Option<f64> {
        match n as usize {
            1..SIZE => self.values.as_ref().and_then(|t| t[n as usize].get()),
            _ => self.high.as_ref().and_then(|m| m.get(&n).copied()),
        }
    }

    /// Sets a LinuxCNC parameter the program keeps (#1 to #5601).
    pub fn set_parameter(&mut self, n: u32, v: f64) {
        match n as usize {
            1..SIZE => {
                let table = self
                    .values
                    .get_or_insert_with(|| Arc::new([Value::Vacant; SIZE]));
                Arc::make_mut(table)[n as usize] = Value::Number(v);
            }
            _ => {
                let map = self.high.get_or_insert_with(Default::default);
                // Bounded: at most one entry per number up to #5601.
                Arc::make_mut(map).insert(n, v);
            }
        }
    }

    /// The variables that hold a value, in order of number.
    pub fn set_variables(&self) -> Vec<(u32, f64)> {
        let low = self
            .values
            .iter()
            .flat_map(|t| (0..SIZE as u32).filter_map(|n| t[n as usize].get().map(|v| (n, v))));
        let high = self
            .high
            .iter()
            .flat_map(|m| m.iter().map(|(&n, &v)| (n, v)));
        low.chain(high).collect()
    }
}

/// The message for a number that is no variable.
pub fn no_variable(n: u32, span: Span) -> Diagnostic {
    alarm::VARIABLE_NUMBER.at(
        span,
        format!("#{n} is no variable: the variables are #0, local #1–#33, common #100–#199 and #500–#999, and system variables from #1000"),
    )
}

/// A system variable the store does not model.
pub fn system_variable(n: u32, span: Span) -> Diagnostic {
    Diagnostic::error(
        "macro-system-variable",
        span,
        format!(
            "#{n} is a system variable (the control's offsets, positions or modes): offsetlab does not model system variables yet"
        ),
    )
}

impl Variables for Store {
    fn read(&mut self, number: u32, span: Span) -> Result<Value, Diagnostic> {
        match kind(number) {
            Kind::System => Err(system_variable(number, span)),
            Kind::None => Err(no_variable(number, span)),
            _ => Ok(self.get(number).unwrap_or_default()),
        }
    }

    fn write(&mut self, number: u32, value: Value, span: Span) -> Result<(), Diagnostic> {
        match kind(number) {
            Kind::Null => Err(alarm::WRITE_PROTECTED.at(
                span,
                "#0 is always vacant and cannot be set (write `#1 = #0` to make #1 vacant)",
            )),
            Kind::System => Err(system_variable(number, span)),
            Kind::None => Err(no_variable(number, span)),
            _ => {
                self.set(number, value);
                Ok(())
            }
        }
    }
}
