//! LinuxCNC's numbered parameters (behaviour 22.10): #1–#30 a call's
//! arguments, #31–#5000 the program's own, and from #5061 the control's,
//! read from the machine's state where offsetlab models it.
//!
//! Source: LinuxCNC 2.9 documentation, "Overview of the G-code language",
//! "Numbered Parameters" (the table of #5061–#5601); `rs274 -g` for what a
//! read gives and which writes it takes (tests/linuxcnc/README.md).

use std::sync::Arc;

use super::data::clean;
use super::{EventKind, Machine, Out, state::DataSet};
use crate::diag::{Diagnostic, Span};
use crate::macros::alarm;
use crate::setup::Position;

/// The highest parameter number (rs274 reads and sets #1 to #5601; #0 and
/// #5602 are "Parameter number out of range").
pub(crate) const LAST: u32 = 5601;

/// What a parameter number is under LinuxCNC.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Param {
    /// A position the control stores and reads when it uses it, in the
    /// machine's units (the setup's): #5161… G28, #5181… G30, #5221… a
    /// work system's origin (`p` 1 G54 … 6 G59, 7–9 G59.1–G59.3), each axis X Y Z A B C U V
    /// W (0–8; a work system's 9 is its R rotation).
    Stored(Stored, usize),
    /// #5210 G92 on, #5211–#5219 the G92 offset, as G92, G92.1, G92.2 and
    /// G92.3 leave them (behaviour 22.14).
    G92(Option<usize>),
    /// #5220: the work system in use, 1 to 9.
    System,
    /// #5400–#5413, #5420–#5428: the tool and the position, read only.
    ReadOnly,
    /// #5599: the DEBUG switch, 1 until the program sets it (behaviour 22.2).
    Debug,
    /// #5061–#5069 probe, #5399 M66, #5600/#5601 the tool changer's fault:
    /// what offsetlab does not model.
    Unmodelled(&'static str),
    /// Any other number up to #5601: a parameter the program keeps.
    Kept,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Stored {
    Home(u8),
    Work(usize),
}

fn param(n: u32) -> Param {
    match n {
        5161..=5169 => Param::Stored(Stored::Home(1), (n - 5161) as usize),
        5181..=5189 => Param::Stored(Stored::Home(2), (n - 5181) as usize),
        5210 => Param::G92(None),
        5211..=5219 => Param::G92(Some((n - 5211) as usize)),
        5220 => Param::System,
        5221..=5390 if (n - 5221) % 20 < 10 => {
            let k = (n - 5221) as usize;
            Param::Stored(Stored::Work(k / 20 + 1), k % 20)
        }
        5400..=5413 | 5420..=5428 => Param::ReadOnly,
        5061..=5069 => Param::Unmodelled("the probe's result (G38)"),
        5399 => Param::Unmodelled("M66's input"),
        5599 => Param::Debug,
        5600 | 5601 => Param::Unmodelled("the tool changer's fault"),
        _ => Param::Kept,
    }
}

const AXIS: [&str; 10] = ["X", "Y", "Z", "A", "B", "C", "U", "V", "W", "R"];

fn out_of_range(n: u32, span: Span) -> Diagnostic {
    alarm::VARIABLE_NUMBER.at(
        span,
        format!("#{n}: LinuxCNC's parameters are #1 to #{LAST} (rs274: \"Parameter number out of range\")"),
    )
}

fn get(p: &Position, axis: usize) -> f64 {
    p.to_array().get(axis).copied().unwrap_or(0.0)
}

impl Machine {
    /// #5599: `(DEBUG,…)` speaks unless the program set it to 0; LinuxCNC
    /// starts with 1 (its documentation, "Numbered Parameters"; rs274 -g
    /// shows no MESSAGE for a DEBUG after `#5599=0`, PRINT still prints).
    pub(crate) fn debug_switch(&self) -> f64 {
        self.variables.parameter_written(5599).unwrap_or(1.0)
    }

    fn stored(&self, s: Stored) -> Position {
        match s {
            Stored::Home(n) => self.setup.reference_point(n),
            // G54 … G59.3 (behaviour 22.14).
            Stored::Work(p) => self.setup.work_offsets.by_p(p),
        }
    }

    /// #5401–#5413: the offsets X…W, diameter, front and back angle and
    /// orientation of the tool in the spindle, from the tool table.
    fn spindle_entry(&self, n: u32) -> f64 {
        let Some(t) = self
            .setup
            .tool_table
            .as_ref()
            .and_then(|t| t.tools.get(&self.state.tool))
        else {
            return 0.0;
        };
        match n {
            5401..=5409 => t.offsets[(n - 5401) as usize],
            5410 => t.diameter,
            5411 => t.front_angle,
            5412 => t.back_angle,
            _ => f64::from(t.orientation),
        }
    }

    /// The value of LinuxCNC parameter `#n`.
    pub(crate) fn read_parameter(&self, n: u32, span: Span) -> Result<f64, Diagnostic> {
        if n == 0 || n > LAST {
            return Err(out_of_range(n, span));
        }
        let s = &self.state;
        // The stored positions are in the machine's units (rs274 keeps its
        // var file so), the current position in the program's.
        Ok(match param(n) {
            Param::Kept => self.variables.parameter(n),
            Param::Debug => self.debug_switch(),
            Param::Stored(st, axis) => get(&self.stored(st), axis),
            // As rs274 keeps them: set by G92, G92.1, G92.2, G92.3
            // (behaviour 22.14), in the machine's units.
            Param::G92(None) => self.variables.parameter(n),
            Param::G92(Some(axis)) if axis < 3 => self.variables.parameter(n),
            Param::G92(Some(_)) => 0.0,
            Param::System => s.modal.work.index().map_or(0.0, |i| i as f64 + 1.0),
            Param::ReadOnly => match n {
                5400 => f64::from(s.tool),
                // The spindle tool's entry as the table holds it, in its
                // units (rs274 -g, behaviour 22.9, 22.10); no table, 0.
                5401..=5413 => self.spindle_entry(n),
                5420..=5422 => self.in_program_units(s.programmed[(n - 5420) as usize]),
                _ => 0.0,
            },
            Param::Unmodelled(what) => {
                return Err(Diagnostic::error(
                    "macro-system-variable",
                    span,
                    format!("#{n} is {what}, which offsetlab does not model"),
                ));
            }
        })
    }

    /// Sets LinuxCNC parameter `#n` to `v` as rs274 does: a stored
    /// position is used when the control next reads it (G28, a work system
    /// selected), the program's parameters at once.
    pub(crate) fn write_parameter(
        &mut self,
        n: u32,
        v: f64,
        span: Span,
        out: &mut Out,
    ) -> Result<(), Diagnostic> {
        if n == 0 || n > LAST {
            return Err(out_of_range(n, span));
        }
        let refuse = |why: String| Err(Diagnostic::error("macro-system-variable", span, why));
        match param(n) {
            Param::Kept | Param::Debug => {
                self.variables.set_parameter(n, v);
                Ok(())
            }
            Param::ReadOnly => refuse(format!(
                "#{n} is read only: LinuxCNC sets it from the tool and the position (rs274: \"Parameter is readonly\")"
            )),
            Param::Unmodelled(what) => refuse(format!(
                "#{n} is {what}, which offsetlab does not model: the setting cannot take effect"
            )),
            Param::G92(Some(axis)) => self.write_g92(n, axis, v, span, out),
            Param::G92(None) | Param::System => refuse(format!(
                "#{n} is {}: LinuxCNC keeps the value for G92.3 and the next start, which offsetlab does not model; set the offset with G92 (the system with G54–G59)",
                if n == 5220 {
                    "the work system in use"
                } else {
                    "the G92 offset"
                }
            )),
            Param::Stored(st, axis) => self.write_stored(n, st, axis, v, span, out),
        }
    }

    fn write_stored(
        &mut self,
        n: u32,
        st: Stored,
        axis: usize,
        v: f64,
        span: Span,
        out: &mut Out,
    ) -> Result<(), Diagnostic> {
        let refuse = |why: String| Err(Diagnostic::error("macro-system-variable", span, why));
        let mut p = self.stored(st);
        let name = AXIS.get(axis).copied().unwrap_or("?");
        if axis > 2 {
            if v == 0.0 {
                out.notes.push(format!(
                    "#{n} = 0: the {name} of a machine with X, Y and Z only, 0 already"
                ));
                return Ok(());
            }
            return refuse(format!(
                "#{n} is the {name} of a stored position: the machine has X, Y and Z only, so it stays 0"
            ));
        }
        let in_force =
            matches!(st, Stored::Work(w) if self.state.modal.work.index() == Some(w - 1));
        if in_force {
            // rs274 keeps the zero in force until a system is selected
            // again; offsetlab's zero follows its table.
            return refuse(format!(
                "#{n} is the {name} origin of the work system in use: LinuxCNC moves the zero only at the next selection of a system, which offsetlab does not model; select another system first, or write G10 L2"
            ));
        }
        let was = get(&p, axis);
        super::sysvars::set_axis(&mut p, axis, v);
        let what = match st {
            Stored::Home(h) => {
                self.set_home(h, p);
                format!("the G{} position's", if h == 1 { 28 } else { 30 })
            }
            Stored::Work(w) => {
                *Arc::make_mut(&mut self.setup).work_offsets.by_p_mut(w) = p;
                let key = crate::setup::WorkOffsets::name_of_p(w);
                out.events.push(EventKind::DataSet(DataSet {
                    table: "work_offsets",
                    key: key.to_string(),
                    field: ["x", "y", "z"][axis],
                    value: clean(v),
                    was: clean(was),
                }));
                format!("the {key} origin's")
            }
        };
        out.notes.push(format!(
            "#{n} = {} is {what} {name} (was {}, machine units): LinuxCNC uses it when it next goes there or selects the system",
            clean(v),
            clean(was)
        ));
        Ok(())
    }

    /// #5211–#5219 set: the G92 offset LinuxCNC keeps for G92.3. While
    /// the offset is off (#5210 0) the value waits for G92.3; while it is
    /// on rs274 reads the parameters, not the offset in force, at the next
    /// system selected or G10 L20, which offsetlab does not follow.
    fn write_g92(
        &mut self,
        n: u32,
        axis: usize,
        v: f64,
        span: Span,
        out: &mut Out,
    ) -> Result<(), Diagnostic> {
        let refuse = |why: String| Err(Diagnostic::error("macro-system-variable", span, why));
        let name = AXIS.get(axis).copied().unwrap_or("?");
        if axis > 2 {
            if v == 0.0 {
                out.notes.push(format!(
                    "#{n} = 0: the G92 {name} of a machine with X, Y and Z only, 0 already"
                ));
                return Ok(());
            }
            return refuse(format!(
                "#{n} is the G92 offset's {name}: the machine has X, Y and Z only, so it stays 0"
            ));
        }
        if self
            .variables
            .parameter(super::mill::linuxcnc_offsets::G92_ON)
            != 0.0
        {
            return refuse(format!(
                "#{n} is the G92 offset's {name} while the offset is on: LinuxCNC then reads the parameter apart from the offset in force, which offsetlab does not model; set it after G92.2 or G92.1, for G92.3"
            ));
        }
        let was = self.variables.parameter(n);
        self.variables.set_parameter(n, v);
        out.notes.push(format!(
            "#{n} = {} is the G92 offset's {name} kept for G92.3 (was {}, machine units)",
            clean(v),
            clean(was)
        ));
        Ok(())
    }
}
