//! The machine's side of macro calls (behaviour 21): the local variable
//! level, the locals a G65 or a modal call hands the macro it calls, the
//! G66 modal call in force, and the two clocks a program can set. Kept
//! with the machine, so a checkpoint holds them; boxed and absent until a
//! program makes a macro call or sets a clock (a program without them
//! carries one empty pointer).

use super::Machine;
use crate::macros::Value;

/// The local variables #1–#33 of one level (`[0]` is #1).
pub(crate) type Locals = [Value; 33];

/// A G66 modal call in force (behaviour 21.5).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct ModalCall {
    /// The program it calls.
    pub(crate) program: u32,
    /// How many times a call runs it (L).
    pub(crate) times: u32,
    /// The locals each call starts with.
    pub(crate) locals: Locals,
    /// The arguments as the notes write them (`A=#1=3.000`).
    pub(crate) said: String,
    /// The G66 block's line.
    pub(crate) line: u32,
}

/// The macro calls' state.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct MacroCalls {
    /// The local variable level: 0 in the main program, one more in each
    /// open G65 or modal call (Fanuc, "Local variable levels").
    pub(crate) level: u8,
    /// Open calls made by the modal call: a move inside one calls no
    /// macro again.
    pub(crate) in_modal: u8,
    /// The locals of the call the last block asked for, until the run
    /// makes it.
    pub(crate) pending: Option<Box<Locals>>,
    /// G66's call, until G67.
    pub(crate) modal: Option<Box<ModalCall>>,
    /// #3001 (ms) and #3002 (hours) as a program set them (behaviour
    /// 21.9: the run has no clock, they stand still).
    pub(crate) clocks: [f64; 2],
    /// LinuxCNC's named parameters (behaviour 22.6).
    pub(crate) named: Named,
}

/// LinuxCNC's named parameters: the globals (`#<_name>`), and the locals
/// of the level running (the main program's or an o-word call's; a call
/// keeps its caller's on its frame).
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct Named {
    pub(crate) globals: std::collections::BTreeMap<Box<str>, f64>,
    pub(crate) locals: std::collections::BTreeMap<Box<str>, f64>,
}

impl Machine {
    /// The macro calls' state, made at its first use.
    pub(crate) fn macro_calls_mut(&mut self) -> &mut MacroCalls {
        self.macro_calls.get_or_insert_with(Default::default)
    }

    /// The local variable level (0 in the main program).
    pub(crate) fn macro_level(&self) -> u8 {
        self.macro_calls.as_ref().map_or(0, |m| m.level)
    }

    /// The local variables #1–#33 now.
    pub(crate) fn locals(&self) -> Locals {
        let mut l = [Value::Vacant; 33];
        for (k, v) in l.iter_mut().enumerate() {
            *v = self.variables.get(k as u32 + 1).unwrap_or_default();
        }
        l
    }

    /// Sets the local variables #1–#33 (the store is written only where a
    /// value changes: a store never written stays unmade).
    pub(crate) fn set_locals(&mut self, l: &Locals) {
        for (k, v) in l.iter().enumerate() {
            let n = k as u32 + 1;
            if self.variables.get(n) != Some(*v) {
                self.variables.set(n, *v);
            }
        }
    }
}
