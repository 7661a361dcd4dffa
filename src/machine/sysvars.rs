//! The Custom Macro B system variables of the offset tables and the work
//! offsets (behaviour 20.10): reading one gives the table's value, writing
//! one sets it from that block on, as G10 does (behaviour 17.8: the same
//! machine copy of the setup, the same `DataSet` event).
//!
//! The numbers (Fanuc 0i-MF operator's manual, "System variables", tool
//! compensation values and workpiece origin offset values): by the offset
//! memory type (7.32), A: #2001–#2200 or #10001–#10999 the one value; B:
//! those the wear, #2201–#2400 or #11001–#11999 the geometry; C: the H
//! wear and geometry so, #2401–#2600 or #12001–#12999 the D wear and
//! #2601–#2800 or #13001–#13999 the D geometry. Work offsets: #5201–#5203
//! the external offset's X, Y, Z, then 20 numbers a system: #5221 G54 X …
//! #5323 G59 Z. On the lathe #5201–#5322 the same with X first and Z
//! second (behaviour 21.15).

use std::sync::Arc;

use super::data::{MillField, clean};
use super::{EventKind, Machine, Out, state::DataSet};
use crate::diag::{Diagnostic, Span};
use crate::setup::{MAX_OFFSET_VALUE, MachineKind, OffsetMemory, Position, WorkOffsets};

/// What a system variable names.
#[derive(Clone, Copy, Debug)]
enum Target {
    /// A field of a tool offset register.
    Tool(MillField, u16),
    /// An axis (0 X, 1 Y, 2 Z) of a work offset by its G10 L2 P (0 EXT,
    /// 1–6 G54–G59).
    Work(usize, usize),
}

impl Machine {
    fn system_target(&self, n: u32) -> Option<Target> {
        if self.setup.machine == MachineKind::Lathe {
            // A two-axis lathe's first axis is X and its second Z (the
            // 0i-TF numbering, as the positions of 21.8): #5221 G54 X,
            // #5222 G54 Z. Its tool offsets are 21.10's.
            if let 5201..=5322 = n {
                let k = (n - 5201) as usize;
                let (p, axis) = (k / 20, k % 20);
                let axis = match axis {
                    0 => 0,
                    1 => 2,
                    _ => return None,
                };
                return (p <= 6).then_some(Target::Work(p, axis));
            }
            return None;
        }
        let memory = self.setup.settings.offset_memory();
        // (range index 0–3, register number)
        let tool = match n {
            2001..=2800 => Some(((n - 2001) / 200, (n - 2001) % 200 + 1)),
            10001..=13999 if !n.is_multiple_of(1000) => Some(((n - 10001) / 1000, n % 1000)),
            _ => None,
        };
        if let Some((range, number)) = tool {
            let field = match (memory, range) {
                (OffsetMemory::A, 0) => MillField::Value,
                (OffsetMemory::B, 0) => MillField::Wear,
                (OffsetMemory::B, 1) => MillField::Geometry,
                (OffsetMemory::C, 0) => MillField::HWear,
                (OffsetMemory::C, 1) => MillField::HGeometry,
                (OffsetMemory::C, 2) => MillField::DWear,
                (OffsetMemory::C, 3) => MillField::DGeometry,
                _ => return None,
            };
            return Some(Target::Tool(field, number as u16));
        }
        if let 5201..=5323 = n {
            let k = (n - 5201) as usize;
            let (p, axis) = (k / 20, k % 20);
            return (p <= 6 && axis < 3).then_some(Target::Work(p, axis));
        }
        None
    }

    /// The value of system variable `#n`: Ok(None) when offsetlab does not
    /// model it.
    pub(crate) fn read_system(&self, n: u32, span: Span) -> Result<Option<f64>, Diagnostic> {
        Ok(match self.system_target(n) {
            None => self.read_state(n, span)?,
            Some(Target::Tool(field, number)) => {
                self.check_register(n, number, span)?;
                let r = self.setup.offsets.get(&number).copied().unwrap_or_default();
                Some(clean(field.get(&r)))
            }
            Some(Target::Work(p, axis)) => {
                let z = self.setup.work_offsets.by_p(p).to_array();
                // The table is in the setup's units, the program reads its own.
                Some(clean(z[axis] * self.setup.units.mm() / self.units().mm()))
            }
        })
    }

    fn check_register(&self, n: u32, number: u16, span: Span) -> Result<(), Diagnostic> {
        let table = self.setup.table_size;
        if number > table {
            return Err(crate::macros::alarm::VARIABLE_NUMBER.at(
                span,
                format!(
                    "#{n} is tool offset {number}; the table has 1 to {table} (setting table_size)"
                ),
            ));
        }
        Ok(())
    }

    /// Sets system variable `#n` to `v`, as G10 would: Ok(false) when
    /// offsetlab does not model it.
    pub(crate) fn write_system(
        &mut self,
        n: u32,
        v: f64,
        span: Span,
        out: &mut Out,
    ) -> Result<bool, Diagnostic> {
        match self.system_target(n) {
            None => self.write_state(n, v, span, out),
            Some(Target::Tool(field, number)) => {
                self.check_register(n, number, span)?;
                offset_in_range(n, v, span)?;
                let mut reg = self.setup.offsets.get(&number).copied().unwrap_or_default();
                let was = field.get(&reg);
                field.set(&mut reg, v);
                Arc::make_mut(&mut self.setup).offsets.insert(number, reg);
                let note = format!(
                    "#{n} is {}: set as G10 sets it, read by the blocks after this one",
                    field.label(number)
                );
                offset_written(out, ("offsets", number, field.key()), (v, was), note);
                Ok(true)
            }
            Some(Target::Work(p, axis)) => {
                let v = self.work_value(n, v, span)?;
                let mut zero = self.setup.work_offsets.by_p(p);
                let was = set_axis(&mut zero, axis, v);
                *Arc::make_mut(&mut self.setup).work_offsets.by_p_mut(p) = zero;
                let work = self.state.modal.work;
                let in_force = p == 0 || work.index() == Some(p - 1);
                let name = WorkOffsets::name_of_p(p);
                self.work_zero_written(
                    out,
                    (n, axis, v, was),
                    ("work_offsets", name.to_string()),
                    &format!("the {name} zero's"),
                    "G10 L2",
                    in_force,
                );
                Ok(true)
            }
        }
    }
}

/// Sets `axis` of `zero` to `v`; gives what it was.
/// An offset written through `#n` is held to G10's limit (Fanuc alarm
/// PS0032, behaviour 17.7).
pub(super) fn offset_in_range(n: u32, v: f64, span: Span) -> Result<(), Diagnostic> {
    if v.abs() > MAX_OFFSET_VALUE + 1e-9 {
        return Err(Diagnostic::error(
            "g10-value",
            span,
            format!("#{n} = {v}: an offset is at most ±{MAX_OFFSET_VALUE} (Fanuc alarm PS0032)"),
        ));
    }
    Ok(())
}

/// What an offset register written through `#` reports, on the mill and
/// the lathe alike: the event G10 gives and the block's sentence.
pub(super) fn offset_written(
    out: &mut Out,
    (table, number, field): (&'static str, u16, &'static str),
    (v, was): (f64, f64),
    note: String,
) {
    out.events.push(EventKind::DataSet(DataSet {
        table,
        key: format!("{number:02}"),
        field,
        value: clean(v),
        was: clean(was),
    }));
    out.notes.push(note);
}

pub(super) fn set_axis(zero: &mut Position, axis: usize, v: f64) -> f64 {
    let slot = match axis {
        0 => &mut zero.x,
        1 => &mut zero.y,
        _ => &mut zero.z,
    };
    std::mem::replace(slot, v)
}

impl Machine {
    /// A work offset value written through a system variable, in the
    /// setup's units (the program's converted), within the work offsets'
    /// range.
    pub(super) fn work_value(&self, n: u32, v: f64, span: Span) -> Result<f64, Diagnostic> {
        let unit = self.setup.units;
        let v = v * self.units().mm() / unit.mm();
        if v.abs() > unit.max_dimension() {
            return Err(Diagnostic::error(
                "g10-value",
                span,
                format!("#{n} = {v}: beyond the work offsets' range"),
            ));
        }
        Ok(v)
    }

    /// What writing a work zero's axis through `#n` says (the event G10
    /// gives and the block's sentence), and the zero moved now when its
    /// system is in force (behaviour 20.10, 21).
    pub(super) fn work_zero_written(
        &mut self,
        out: &mut Out,
        (n, axis, v, was): (u32, usize, f64, f64),
        (table, key): (&'static str, String),
        whose: &str,
        g10: &str,
        in_force: bool,
    ) {
        out.events.push(EventKind::DataSet(DataSet {
            table,
            key,
            field: ["x", "y", "z"][axis],
            value: clean(v),
            was: clean(was),
        }));
        out.notes.push(format!(
            "#{n} is {whose} {}: set as {g10} sets it{}",
            ["X", "Y", "Z"][axis],
            if in_force {
                "; the system is in force: its zero moves now"
            } else {
                ""
            }
        ));
        if in_force {
            self.select_work(self.state.modal.work);
        }
    }
}
