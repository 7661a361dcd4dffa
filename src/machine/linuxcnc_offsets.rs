//! LinuxCNC's work coordinates (behaviour 22.14): G10 L2/L20 with its nine
//! systems and P0 the one in use, G92.2/G92.3 and the G92 offset kept in
//! #5210–#5213, G28.1/G30.1 storing the machine position.
//!
//! Source: LinuxCNC 2.9 documentation, "G10 L2", "G10 L20", "G54-G59.3",
//! "G92.1, G92.2", "G92.3", "G28, G28.1", "G30, G30.1"; its interpreter's
//! `convert_setup`, `convert_axis_offsets`, `convert_savehome` and
//! `find_current_in_system` (interp_convert.cc, interp_find.cc); `rs274 -g`
//! on tests/linuxcnc/25, 26, 29, 32, 33 and w01–w10.

use std::sync::Arc;

use super::super::data::clean;
use super::super::{AXES, EventKind, Machine, Out, state::DataSet};
use crate::diag::{Diagnostic, Span};
use crate::setup::{Position, WorkOffsets};
use crate::syntax::codes::{CutterCompensation, Group, Stored};
use crate::syntax::{Address, Block};

use Address::{G, L, N, P, R, X, Y, Z};

/// #5210, 1 while the G92 offset is on (rs274 sets it at G92 and G92.3,
/// clears it at G92.1 and G92.2).
pub(in crate::machine) const G92_ON: u32 = 5210;
/// #5211–#5213: the G92 offset's X Y Z as LinuxCNC keeps it, in the
/// machine's units, what G92.3 takes back.
pub(in crate::machine) const G92_X: u32 = 5211;

impl Machine {
    /// True when the block, or the modes before it, have cutter radius
    /// compensation on: rs274 refuses to move a zero then (its group 07
    /// code runs before the block's group 00 code).
    fn compensating(&self, b: &Block) -> bool {
        b.codes().cutter().unwrap_or(self.state.cutter.mode) != CutterCompensation::Cancel
    }

    /// Refuses the block's code with cutter radius compensation on, as
    /// rs274 does (`rs274` its message).
    pub(in crate::machine) fn refuse_in_compensation(
        &self,
        b: &Block,
        what: &str,
        rs274: &str,
    ) -> Result<(), Diagnostic> {
        if !self.compensating(b) {
            return Ok(());
        }
        let span = match b.codes().work() {
            Some(_) => b.code_span(Group::Work),
            None => b.code_span(Group::NonModal),
        };
        let code = match b.codes().work() {
            Some(w) => w.gcode(),
            None => b
                .codes()
                .non_modal()
                .map_or("G10", |c| c.gcode(crate::setup::MachineKind::Mill)),
        };
        Err(self.error(
            "cutter-work-offset",
            span,
            format!(
                "{code} {what} with cutter radius compensation on: LinuxCNC refuses it (\"{rs274}\"); cancel it with G40 first"
            ),
        ))
    }

    /// The machine position of the controlled point (mm) without the tool
    /// length offset in force, as rs274's current point plus its G5x and G92
    /// offsets (the next Z move carries a length change made without Z,
    /// behaviour 22.3, yet rs274's point already reads from the new tip).
    fn tip_in_machine(&self) -> crate::geometry::Xyz {
        let mut p = crate::geometry::add(self.actual(), self.state.coords.zero);
        p[2] -= self.state.length.target;
        p
    }

    /// Keeps the G92 offset in force in #5210–#5213 as rs274 does at G92
    /// and G92.1 (`on` false zeroes them).
    pub(in crate::machine) fn keep_g92_parameters(&mut self, on: bool) {
        let unit = self.setup.units.mm();
        self.variables
            .set_parameter(G92_ON, f64::from(u8::from(on)));
        for axis in 0..3 {
            let v = if on {
                clean(self.state.coords.shift[axis] / unit)
            } else {
                0.0
            };
            self.variables.set_parameter(G92_X + axis as u32, v);
        }
    }

    /// G10 L2 and L20 under LinuxCNC: P0 the system in use, P1–P9 G54 to
    /// G59.3; L2 gives the zero as a machine position, L20 the values the
    /// current point is to read in that system (with the G92 offset on);
    /// G91 changes neither; R (L2 only) is the system's rotation.
    pub(in crate::machine) fn g10_work_linuxcnc(
        &mut self,
        b: &Block,
        l: u32,
        out: &mut Out,
    ) -> Result<(), Diagnostic> {
        let allowed: &[Address] = if l == 2 {
            &[N, G, L, P, X, Y, Z, R]
        } else {
            &[N, G, L, P, X, Y, Z]
        };
        self.g10_only(
            b,
            allowed,
            &format!(
                "G10 L{l} sets a work system's zero with P (0 the system in use, 1–9 G54 to G59.3) and X, Y, Z{}",
                if l == 2 { " (R its rotation)" } else { "" }
            ),
        )?;
        let p = self.linuxcnc_system_p(b, l)?;
        let active = self.state.modal.work.index().map(|i| i + 1);
        let p = match (p, active) {
            (0, Some(a)) => a,
            (0, None) => {
                return Err(self.error(
                    "g10-number",
                    self.word_span(b, P),
                    format!(
                        "G10 L{l} P0 names the system in use, {}, which is not one of LinuxCNC's nine (P1–P9 are G54 to G59.3)",
                        self.state.modal.work.gcode()
                    ),
                ));
            }
            (p, _) => p,
        };
        let name = WorkOffsets::name_of_p(p);
        let in_force = active == Some(p);
        if in_force {
            self.refuse_in_compensation(
                b,
                &format!("L{l} P{p} moves the zero of {name}, the system in use,"),
                "Cannot change the active coordinate system with cutter radius compensation on",
            )?;
        }
        let mut said = Vec::new();
        if let Some(r) = b.get(R) {
            if r.value != 0.0 {
                return Err(self.error(
                    "g10-rotation",
                    r.span,
                    format!(
                        "G10 L2 R{}: LinuxCNC turns {name} about its zero by R degrees, which offsetlab does not model (its systems are not rotated); leave R out or write R0",
                        r.value
                    ),
                ));
            }
            said.push("R = 0 (not rotated, as it was)".to_string());
        }
        let unit = self.setup.units;
        let tip = self.tip_in_machine();
        let c = self.state.coords;
        let mut zero = self.setup.work_offsets.by_p(p);
        let mut sets = Vec::new();
        for (axis, (a, letter)) in AXES.iter().enumerate() {
            let Some(w) = b.get(*a) else { continue };
            let v = self.mm(w.value);
            // L20: the zero that makes the point read v with the G92
            // offset on (rs274's find_current_in_system).
            let new_mm = match l {
                20 => tip[axis] - c.shift[axis] - c.local[axis] - v,
                _ => v,
            };
            let slot = match axis {
                0 => &mut zero.x,
                1 => &mut zero.y,
                _ => &mut zero.z,
            };
            let was = *slot;
            let label = format!("{name} {letter}");
            let new = self.g10_value(w, &label, new_mm / unit.mm(), unit.max_dimension())?;
            *slot = new;
            let d = unit.decimals();
            said.push(format!("{letter} = {new:.d$} (was {was:.d$})"));
            sets.push((["x", "y", "z"][axis], new, clean(was)));
        }
        *Arc::make_mut(&mut self.setup).work_offsets.by_p_mut(p) = zero;
        for (field, value, was) in sets {
            out.events.push(EventKind::DataSet(DataSet {
                table: "work_offsets",
                key: name.to_string(),
                field,
                value,
                was,
            }));
        }
        let mut note = format!("{}: {name} zero ", self.g10_text(b));
        if said.is_empty() {
            note.push_str("unchanged (no axis word)");
        } else {
            note.push_str(&format!(
                "{} (a machine position in {}{})",
                said.join(", "),
                unit.as_str(),
                if l == 20 {
                    "; the current point reads the words there"
                } else {
                    ""
                }
            ));
        }
        if self.state.modal.distance == crate::syntax::codes::Distance::Incremental {
            note.push_str("; G91 changes nothing here (LinuxCNC)");
        }
        if in_force {
            let work = self.state.modal.work;
            self.select_work(work);
            note.push_str(&format!(
                "; {name} is in force: its zero moves now, the tool stays and its position reads {}",
                self.show_point(self.state.programmed)
            ));
        }
        out.notes.push(note);
        Ok(())
    }

    /// G10 L2/L20's P as rs274 reads it: 0 to 9, a whole number within
    /// 0.0002 (P1.5 rounds to 2 in the check and is then read as 1, as
    /// rs274 does).
    fn linuxcnc_system_p(&self, b: &Block, l: u32) -> Result<usize, Diagnostic> {
        let range = |span: Span| {
            self.error(
                "g10-number",
                span,
                format!(
                    "G10 L{l} needs P0 to P9: 0 the system in use, 1–9 G54 to G59.3 (rs274: \"P value out of range (0-9) with G10 L{l}\")"
                ),
            )
        };
        let Some(w) = b.get(P) else {
            return Err(range(b.code_span(Group::NonModal)));
        };
        let v = w.value;
        let rounded = if v >= 0.0 {
            (v + 0.5).trunc()
        } else {
            (v - 0.5).trunc()
        };
        if v + 0.0001 - rounded > 0.0002 {
            return Err(self.error(
                "g10-number",
                w.span,
                format!("G10 L{l} P{v}: P is a whole number (rs274: \"P value not an integer with G10\")"),
            ));
        }
        if !(0.0..=9.0).contains(&rounded) {
            return Err(range(w.span));
        }
        Ok((v + 0.0001).max(0.0) as usize)
    }

    /// G92.2, G92.3, G28.1, G30.1 (behaviour 22.14).
    pub(in crate::machine) fn stored_code(
        &mut self,
        b: &Block,
        code: Stored,
        out: &mut Out,
    ) -> Result<(), Diagnostic> {
        let gcode = code.gcode();
        if let Some(w) = AXES.iter().find_map(|(a, _)| b.get(*a)) {
            return Err(self.error(
                "stored-code-words",
                w.span,
                format!(
                    "{gcode} takes no axis words in offsetlab (rs274 then moves to the words in the motion mode, which offsetlab does not follow): write the move in a block of its own"
                ),
            ));
        }
        // rs274 moves the G92 offset with G92.2/G92.3 under compensation
        // (only G92 itself is refused there), not the stored positions.
        if matches!(code, Stored::StoreReference | Stored::StoreOtherReference) {
            self.refuse_in_compensation(
                b,
                "stores a reference position",
                "Cannot set reference point with cutter compensation in effect",
            )?;
        }
        let unit = self.setup.units.mm();
        match code {
            Stored::SuspendShift => {
                self.state.coords.shift = [0.0; 3];
                self.variables.set_parameter(G92_ON, 0.0);
                let zero = self.zero_now();
                self.move_zero(zero);
                out.notes.push(format!(
                    "G92.2: the G92 offset is off, its values kept in #5211… for G92.3 (LinuxCNC); zero at machine {}",
                    self.show_point(self.state.coords.zero)
                ));
            }
            Stored::RestoreShift => {
                for axis in 0..3 {
                    let kept = self.variables.parameter(G92_X + axis as u32);
                    self.state.coords.shift[axis] = kept * unit;
                }
                self.variables.set_parameter(G92_ON, 1.0);
                let zero = self.zero_now();
                self.move_zero(zero);
                out.notes.push(format!(
                    "G92.3: the G92 offset is {} again, from #5211… (LinuxCNC); zero at machine {}",
                    self.show_point(self.state.coords.shift),
                    self.show_point(self.state.coords.zero)
                ));
            }
            Stored::StoreReference | Stored::StoreOtherReference => {
                // The machine position, the length offset in it
                // (rs274's convert_savehome).
                let m = crate::geometry::add(self.actual(), self.state.coords.zero);
                let p = Position {
                    x: clean(m[0] / unit),
                    y: clean(m[1] / unit),
                    z: clean(m[2] / unit),
                };
                let n = if code == Stored::StoreReference { 1 } else { 2 };
                self.set_home(n, p);
                out.notes.push(format!(
                    "{gcode}: the {} position is the machine position {} (#{}…, in {})",
                    if n == 1 { "G28" } else { "G30" },
                    self.show_point(crate::geometry::scale(p.to_array(), unit)),
                    if n == 1 { 5161 } else { 5181 },
                    self.setup.units.as_str()
                ));
            }
        }
        let old_length = self.length_words(b, out)?;
        self.length_only_motion(out, old_length)
    }

    /// Sets the G28 (`n` 1) or G30 (2) position, machine coordinates in the
    /// setup's units. A setup that leaves the G30 position out has it at the
    /// G28 one: it is pinned there before the G28 one changes.
    pub(in crate::machine) fn set_home(&mut self, n: u8, p: Position) {
        let first = self.setup.first_reference();
        let setup = Arc::make_mut(&mut self.setup);
        if n == 1 {
            setup.second_reference.get_or_insert(first);
            setup.reference = p;
        } else {
            setup.second_reference = Some(p);
        }
    }
}
