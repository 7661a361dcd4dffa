//! The system variables a program reads of the machine's state (behaviour
//! 21.7–21.10): modal information (#4001…, #4107…), positions (#5001…,
//! #5021…, #5041…, #5081…), the additional work systems (#7001…, #14001…),
//! the lathe's tool offsets (#2001…) and the clocks (#3001, #3002). The
//! offsets' numbers of the mill and G54–G59 are `sysvars.rs`'s (behaviour
//! 20.10); this file answers the numbers it leaves.
//!
//! Source: Fanuc 0i-MF/0i-TF operator's manuals, "Custom macro", "System
//! variables" (modal information, current position, workpiece coordinate
//! system compensation values, tool compensation values, clock).

use std::sync::Arc;

use super::data::clean;
use super::sysvars::{offset_in_range, offset_written};
use super::{Machine, Out};
use crate::diag::{Diagnostic, Span};
use crate::macros::alarm;
use crate::setup::MachineKind;

/// The number of a modal code as #4001… give it (`G54.1 P1` is 54.1).
fn g_number(code: &str) -> Option<f64> {
    let digits = code.strip_prefix('G')?;
    digits.split(' ').next()?.parse().ok()
}

/// A lathe tool offset's field by its system variable (Fanuc 0i-TF,
/// offsets up to 64: #2001 X wear, #2101 Z wear, #2201 R wear, #2301 the
/// tip T, #2701 X geometry, #2801 Z geometry, #2901 R geometry).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum LatheField {
    XWear,
    ZWear,
    RWear,
    Tip,
    X,
    Z,
    R,
}

impl LatheField {
    fn of(n: u32) -> Option<(LatheField, u16)> {
        let number = (n % 100) as u16;
        if !(2001..=2999).contains(&n) || number == 0 || number > 64 {
            return None;
        }
        let field = match (n - 2000) / 100 {
            0 => LatheField::XWear,
            1 => LatheField::ZWear,
            2 => LatheField::RWear,
            3 => LatheField::Tip,
            7 => LatheField::X,
            8 => LatheField::Z,
            9 => LatheField::R,
            _ => return None,
        };
        Some((field, number))
    }

    /// The setup document's key and the note's name.
    fn key(self) -> (&'static str, &'static str) {
        match self {
            LatheField::XWear => ("x_wear", "X wear"),
            LatheField::ZWear => ("z_wear", "Z wear"),
            LatheField::RWear => ("r_wear", "R wear"),
            LatheField::Tip => ("t", "tip T"),
            LatheField::X => ("x", "X geometry"),
            LatheField::Z => ("z", "Z geometry"),
            LatheField::R => ("r", "R geometry"),
        }
    }
}

/// Modal information and positions: read only.
fn read_only(n: u32) -> bool {
    matches!(n, 4001..=4130 | 4201..=4330 | 5001..=5100)
}

impl Machine {
    /// A length in mm as the program reads it (its G20/G21).
    pub(super) fn in_program_units(&self, mm: f64) -> f64 {
        clean(mm / self.units().mm())
    }

    /// The axis index (0 X, 1 Y, 2 Z) of a position variable's axis number
    /// 0, 1, 2: the lathe's second axis is Z.
    fn axis_of(&self, k: u32) -> Option<usize> {
        match (self.setup.machine, k) {
            (MachineKind::Mill, 0..=2) => Some(k as usize),
            (MachineKind::Lathe, 0) => Some(0),
            (MachineKind::Lathe, 1) => Some(2),
            _ => None,
        }
    }

    /// #4001–#4030 (and #4201–#4230, the block being run: the same here,
    /// where a block's macro words are read just before it runs): the G
    /// code of a modal group.
    fn modal_group(&self, group: u32) -> Option<f64> {
        let c = self.state.modal_codes();
        let mill = self.setup.machine == MachineKind::Mill;
        let modal_call = match self.macro_calls.as_ref().and_then(|m| m.modal.as_ref()) {
            Some(_) => 66.0,
            None => 67.0,
        };
        let code = match (mill, group) {
            (_, 1) => Some(c.motion),
            (true, 2) => Some(c.plane),
            (true, 3) | (false, 3) => c.distance,
            (_, 5) => Some(c.feed_mode),
            (_, 6) => Some(c.units),
            (_, 7) => c.cutter,
            (true, 8) => c.length,
            (true, 9) | (false, 10) => c.cycle,
            (true, 10) => c.return_level,
            (true, 11) => c.scaling,
            (_, 12) => return Some(modal_call),
            (true, 13) | (false, 2) => c.surface_speed,
            (_, 14) => Some(c.work),
            (true, 15) => c.cutting_mode,
            (true, 16) => c.rotation,
            (true, 17) => c.polar_coordinates,
            (false, 21) => c.polar,
            (true, 22) => c.mirror,
            _ => None,
        };
        code.and_then(g_number)
    }

    /// #4102–#4130: the other modal words.
    fn modal_word(&self, n: u32) -> Option<f64> {
        let s = &self.state;
        let mill = self.setup.machine == MachineKind::Mill;
        Some(match n {
            4107 if mill => f64::from(s.cutter.d),
            4109 => s.feed.unwrap_or(0.0),
            4111 if mill => f64::from(s.length.h),
            4119 => s.spindle.unwrap_or(0.0),
            4120 if mill => f64::from(s.next_tool),
            4120 => f64::from(s.lathe.tool * 100 + u32::from(s.lathe.offset)),
            _ => return None,
        })
    }

    /// The value of one of the state's system variables: Ok(None) when
    /// offsetlab does not model it.
    pub(crate) fn read_state(&self, n: u32, span: Span) -> Result<Option<f64>, Diagnostic> {
        let s = &self.state;
        Ok(match n {
            3001 | 3002 => Some(
                self.macro_calls
                    .as_ref()
                    .map_or(0.0, |m| m.clocks[(n - 3001) as usize]),
            ),
            4001..=4030 => self.modal_group(n - 4000),
            4201..=4230 => self.modal_group(n - 4200),
            4102..=4130 => self.modal_word(n),
            4302..=4330 => self.modal_word(n - 200),
            5001..=5003 => self
                .axis_of(n - 5001)
                .map(|a| self.in_program_units(s.programmed[a])),
            5021..=5023 => self
                .axis_of(n - 5021)
                .map(|a| self.in_program_units(s.machine_position()[a])),
            5041..=5043 => self
                .axis_of(n - 5041)
                .map(|a| self.in_program_units(s.actual[a])),
            5081..=5083 => self.axis_of(n - 5081).map(|a| {
                let v = match self.setup.machine {
                    MachineKind::Mill if a == 2 => s.length.vector,
                    MachineKind::Mill => 0.0,
                    MachineKind::Lathe => s.lathe.vector[a],
                };
                self.in_program_units(v)
            }),
            _ => match self.extended_work(n) {
                Some((p, axis)) => {
                    let z = self.setup.extended_work_offsets.get(&p).copied();
                    let z = z.unwrap_or_default().to_array();
                    Some(clean(z[axis] * self.setup.units.mm() / self.units().mm()))
                }
                None => match LatheField::of(n) {
                    Some((field, number)) if self.setup.machine == MachineKind::Lathe => {
                        self.check_lathe_register(n, number, span)?;
                        let r = self.setup.lathe_register(number);
                        Some(clean(match field {
                            LatheField::XWear => r.x_wear,
                            LatheField::ZWear => r.z_wear,
                            LatheField::RWear => r.r_wear,
                            LatheField::Tip => f64::from(r.t),
                            LatheField::X => r.x,
                            LatheField::Z => r.z,
                            LatheField::R => r.r,
                        }))
                    }
                    _ => None,
                },
            },
        })
    }

    /// #7001–#7960 (G54.1 P1–P48) and #14001–#19980 (Fanuc 30i, P1–P300):
    /// twenty numbers a system, X, Y, Z first. The mill's.
    fn extended_work(&self, n: u32) -> Option<(u16, usize)> {
        if self.setup.machine != MachineKind::Mill {
            return None;
        }
        let (base, most) = match n {
            7001..=7960 => (7001, 48),
            14001..=19980 => (14001, 300),
            _ => return None,
        };
        let k = n - base;
        let (p, axis) = (k / 20 + 1, (k % 20) as usize);
        (p <= most && axis < 3).then_some((p as u16, axis))
    }

    fn check_lathe_register(&self, n: u32, number: u16, span: Span) -> Result<(), Diagnostic> {
        let table = self.setup.table_size;
        if number > table {
            return Err(alarm::VARIABLE_NUMBER.at(
                span,
                format!(
                    "#{n} is tool offset {number}; the table has 1 to {table} (setting table_size)"
                ),
            ));
        }
        Ok(())
    }

    /// Sets one of the state's system variables: Ok(false) when offsetlab
    /// does not model it; a read-only one is alarm PS0116.
    pub(crate) fn write_state(
        &mut self,
        n: u32,
        v: f64,
        span: Span,
        out: &mut Out,
    ) -> Result<bool, Diagnostic> {
        if read_only(n) && self.read_state(n, span)?.is_some() {
            return Err(alarm::WRITE_PROTECTED.at(
                span,
                format!(
                    "#{n} is the control's modal information or position: it is read, never set"
                ),
            ));
        }
        if let 3001 | 3002 = n {
            self.macro_calls_mut().clocks[(n - 3001) as usize] = v;
            out.notes.push(format!(
                "#{n} (the {} clock) is preset to {}",
                if n == 3001 { "millisecond" } else { "hour" },
                clean(v)
            ));
            return Ok(true);
        }
        if let Some((p, axis)) = self.extended_work(n) {
            self.write_extended_work(n, p, axis, v, span, out)?;
            return Ok(true);
        }
        match LatheField::of(n) {
            Some((field, number)) if self.setup.machine == MachineKind::Lathe => {
                self.check_lathe_register(n, number, span)?;
                self.write_lathe_offset(n, field, number, v, span, out)?;
                Ok(true)
            }
            _ => Ok(false),
        }
    }

    fn write_extended_work(
        &mut self,
        n: u32,
        p: u16,
        axis: usize,
        v: f64,
        span: Span,
        out: &mut Out,
    ) -> Result<(), Diagnostic> {
        let v = self.work_value(n, v, span)?;
        let mut zero = self
            .setup
            .extended_work_offsets
            .get(&p)
            .copied()
            .unwrap_or_default();
        let was = super::sysvars::set_axis(&mut zero, axis, v);
        Arc::make_mut(&mut self.setup)
            .extended_work_offsets
            .insert(p, zero);
        let in_force = matches!(
            self.state.modal.work,
            crate::syntax::codes::WorkSystem::Additional(q) if u16::from(q) == p
        );
        self.work_zero_written(
            out,
            (n, axis, v, was),
            ("extended_work_offsets", format!("{p}")),
            &format!("the G54.1 P{p} zero's"),
            "G10 L20",
            in_force,
        );
        Ok(())
    }

    fn write_lathe_offset(
        &mut self,
        n: u32,
        field: LatheField,
        number: u16,
        v: f64,
        span: Span,
        out: &mut Out,
    ) -> Result<(), Diagnostic> {
        let mut reg = self.setup.lathe_register(number);
        let (key, name) = field.key();
        let was = match field {
            LatheField::Tip => {
                if !(0.0..=9.0).contains(&v) || v.fract() != 0.0 {
                    return Err(Diagnostic::error(
                        "g10-value",
                        span,
                        format!(
                            "#{n} = {v}: the imaginary tool tip direction is a whole number 0 to 9"
                        ),
                    ));
                }
                let was = f64::from(reg.t);
                reg.t = v as u8;
                was
            }
            _ => {
                offset_in_range(n, v, span)?;
                let slot = match field {
                    LatheField::XWear => &mut reg.x_wear,
                    LatheField::ZWear => &mut reg.z_wear,
                    LatheField::RWear => &mut reg.r_wear,
                    LatheField::X => &mut reg.x,
                    LatheField::Z => &mut reg.z,
                    _ => &mut reg.r,
                };
                let was = *slot;
                *slot = v;
                was
            }
        };
        Arc::make_mut(&mut self.setup)
            .lathe_offsets
            .insert(number, reg);
        let mut note = format!(
            "#{n} is offset {number:02} {name}: set as G10 sets it, read by the blocks after this one"
        );
        if self.state.lathe.offset == number {
            note.push_str(&format!(
                "; offset {number:02} is in force with its old values until a T code names it again"
            ));
        }
        offset_written(out, ("lathe_offsets", number, key), (v, was), note);
        Ok(())
    }
}
