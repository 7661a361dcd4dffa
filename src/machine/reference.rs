//! Reference positions (behaviour 2.10, 5.12, 13.5, 13.6): G28 returns to
//! the first reference position and G30 P2–P4 to the second, third or
//! fourth, each through an intermediate point; G27 checks that the words
//! reach the first. The reference positions are machine coordinates from the
//! setup (setting 7.11).

use super::modal::Distance;
use super::{AXES, Machine, MoveKind, Out};
use crate::diag::{Diagnostic, Span};
use crate::geometry::{Xyz, add, scale, show};
use crate::setup::{MachineKind, ReturnWithoutAxes};
use crate::syntax::codes::{Group, NonModal};
use crate::syntax::{Address, Block};

impl Machine {
    /// Which reference position a G28 or G30 block returns to: 1 for G28;
    /// G30's P2, P3 or P4, 2 when P is left out (Fanuc 0i-MF, "2nd, 3rd and
    /// 4th reference position return").
    fn reference_number(&self, b: &Block, code: NonModal) -> Result<u8, Diagnostic> {
        let p = b.get(Address::P);
        match (code, p) {
            (NonModal::OtherReference, None) => Ok(2),
            (NonModal::OtherReference, Some(p)) if (2..=4).contains(&p.int()) => Ok(p.int() as u8),
            (NonModal::OtherReference, Some(p)) => Err(self.error(
                "reference-number",
                p.span,
                format!(
                    "G30 P{}: G30 returns to the second, third or fourth reference position (P2, P3, P4); G28 to the first",
                    p.int()
                ),
            )),
            (_, Some(p)) => Err(self.error(
                "reference-number",
                p.span,
                "G28 returns to the first reference position and takes no P (G30 P2–P4 returns to the others)",
            )),
            (_, None) => Ok(1),
        }
    }

    /// Reference position `n` in machine coordinates (mm).
    fn reference_point(&self, n: u8) -> Xyz {
        scale(
            self.setup.reference_point(n).to_array(),
            self.setup.units.mm(),
        )
    }

    /// Which axes a G28/G30 block without axis words returns (setting
    /// `reference_return_without_axes`, 7.21), or None when none move.
    fn axes_without_words(
        &self,
        span: Span,
        gcode: &str,
        axes: [bool; 3],
        out: &mut Out,
    ) -> Option<[bool; 3]> {
        match self.setup.settings.reference_return_without_axes() {
            ReturnWithoutAxes::AllAxes => {
                out.notes.push(format!(
                    "{gcode} without axis words: every axis returns (setting reference_return_without_axes = all_axes)"
                ));
                Some(axes)
            }
            ReturnWithoutAxes::NoAxis => {
                out.warnings.push(Diagnostic::warning(
                    "reference-without-axes",
                    span,
                    format!(
                        "{gcode} without axis words moves no axis on this control (setting reference_return_without_axes = no_axis): name the axes to return, as in G91 {gcode} Z0"
                    ),
                ));
                out.notes
                    .push(format!("{gcode} without axis words: no axis moves"));
                None
            }
        }
    }

    /// Mill G28 / G30 (behaviour 2.10, 13.5): the named axes go at rapid to
    /// the intermediate point (the words, absolute or incremental as G90/G91
    /// say), then to the reference position. On each axis that reaches it
    /// the position-offset vector is cleared, and on Z the length vector;
    /// G43/G44 stays and applies again at the next Z move (Fanuc 0i-MB
    /// B-63844EN 14.1.2: the vector is cancelled, the mode stays displayed).
    pub(super) fn mill_reference(
        &mut self,
        b: &Block,
        code: NonModal,
        out: &mut Out,
    ) -> Result<(), Diagnostic> {
        let span = b.code_span(Group::NonModal);
        let gcode = code.gcode(MachineKind::Mill);
        self.refuse_in_transforms(span, gcode)?;
        let n = self.reference_number(b, code)?;
        let mut named = AXES.map(|(a, _)| b.has(a));
        let mut rotary = [Address::A, Address::B, Address::C].map(|a| b.has(a));
        if !named.iter().any(|n| *n) && !rotary.iter().any(|n| *n) {
            match self.axes_without_words(span, gcode, [true; 3], out) {
                Some(all) => {
                    named = all;
                    // Every axis: the rotary axes the program has named too.
                    rotary = self.state.rotary.map(|r| r.is_some());
                }
                None => {
                    self.length_words(b, out)?;
                    return Ok(());
                }
            }
        }
        // A length offset commanded here applies at the next Z move: the
        // return clears the Z vector anyway.
        self.length_words(b, out)?;
        let incremental = self.state.modal.distance == Distance::Incremental;
        let start = self.mark();
        for (axis, (a, _)) in AXES.iter().enumerate() {
            if let Some(v) = b.value(*a) {
                self.state.programmed[axis] = self.target(axis, self.mm(v), incremental);
            }
        }
        self.emit(out, start, MoveKind::Rapid, false, None);
        let start = self.mark();
        let reference = self.reference_point(n);
        let mut cleared = Vec::new();
        for axis in 0..3 {
            if !named[axis] {
                continue;
            }
            let had = self.state.position.vector[axis] != 0.0
                || (axis == 2 && self.state.length.vector != 0.0);
            self.state.position.vector[axis] = 0.0;
            if axis == 2 {
                self.state.length.vector = 0.0;
            }
            self.state.programmed[axis] = reference[axis] - self.state.coords.zero[axis];
            if had {
                cleared.push(AXES[axis].1.to_string());
            }
        }
        for (i, r) in rotary.iter().enumerate() {
            if *r {
                // Our convention: a rotary axis's reference position is 0°.
                self.state.rotary[i] = Some(0.0);
            }
        }
        self.emit(out, start, MoveKind::Rapid, false, None);
        let which = if n == 1 {
            gcode.to_string()
        } else {
            format!("{gcode} P{n}")
        };
        if n != 1 {
            out.notes.push(format!(
                "{which}: to reference position {n} at machine {}",
                self.show_point(reference)
            ));
        }
        if !cleared.is_empty() {
            let mut note = format!(
                "{which}: offset vectors cleared on {} at the reference position",
                cleared.join(", ")
            );
            if named[2] && self.state.length.target != 0.0 {
                note.push_str(&format!(
                    "; {} H{:02} stays active and applies again at the next Z move",
                    self.state.length.mode().gcode(),
                    self.state.length.h
                ));
            }
            out.notes.push(note);
        }
        Ok(())
    }

    /// Lathe G28 / G30 (behaviour 5.12, 13.5): through the intermediate
    /// point (X/Z absolute, U/W incremental) to the reference position; the
    /// T vector is off on the axes that reach it and applies again at their
    /// next move (Fanuc 0i-TC B-64114EN 14.1.6: the vector is not cancelled;
    /// the block moves as if it were, the next block carries it).
    pub(super) fn lathe_reference(
        &mut self,
        b: &Block,
        code: NonModal,
        out: &mut Out,
    ) -> Result<(), Diagnostic> {
        let span = b.code_span(Group::NonModal);
        let gcode = code.gcode(MachineKind::Lathe);
        let n = self.reference_number(b, code)?;
        let mut named = [false; 3];
        let start = self.mark();
        for axis in [0, 2] {
            let Some(to) = self.lathe_target(b, axis) else {
                continue;
            };
            named[axis] = true;
            self.state.programmed[axis] = to;
        }
        if !named.iter().any(|n| *n) {
            match self.axes_without_words(span, gcode, [true, false, true], out) {
                Some(all) => named = all,
                None => return Ok(()),
            }
        }
        self.emit(out, start, MoveKind::Rapid, false, None);
        let start = self.mark();
        let reference = self.reference_point(n);
        for axis in [0, 2] {
            if named[axis] {
                self.state.lathe.vector[axis] = 0.0;
                self.state.programmed[axis] = reference[axis] - self.state.coords.zero[axis];
            }
        }
        self.emit(out, start, MoveKind::Rapid, false, None);
        if n != 1 {
            out.notes.push(format!(
                "{gcode} P{n}: to reference position {n} at machine {}",
                self.show_point(reference)
            ));
        }
        Ok(())
    }

    /// G27 (behaviour 13.6): the named axes go at rapid to the words' point,
    /// offsets and all, and each must then stand at the first reference
    /// position; one that does not is the control's alarm (Fanuc PS0092,
    /// "zero return check (G27) error"). The offsets move the tool off the
    /// point the words name, so the check fails with them on (Fanuc: cancel
    /// them before G27).
    pub(super) fn g27(&mut self, b: &Block, out: &mut Out) -> Result<(), Diagnostic> {
        let span = b.code_span(Group::NonModal);
        let lathe = self.setup.machine == MachineKind::Lathe;
        if !lathe {
            self.refuse_in_transforms(span, "G27")?;
        }
        let old_length = if lathe {
            self.state.length
        } else {
            self.length_words(b, out)?
        };
        let start = self.mark();
        let mut named = [false; 3];
        if lathe {
            for axis in [0, 2] {
                if let Some(to) = self.lathe_target(b, axis) {
                    named[axis] = true;
                    self.state.programmed[axis] = to;
                    self.state.lathe.vector[axis] = self.state.lathe.target[axis];
                }
            }
        } else {
            let incremental = self.state.modal.distance == Distance::Incremental;
            for (axis, (a, _)) in AXES.iter().enumerate() {
                if let Some(v) = b.value(*a) {
                    named[axis] = true;
                    self.state.programmed[axis] = self.target(axis, self.mm(v), incremental);
                }
            }
            let changed = self.state.length.changed_since(&old_length);
            let setting = self.setup.settings.length_offset_without_z();
            self.state.length.vector = self.state.length.vector_after(named[2], changed, setting);
        }
        if !named.iter().any(|n| *n) {
            return Err(self.error(
                "g27-without-axis",
                span,
                "G27 needs the axes whose return to the reference position it checks",
            ));
        }
        self.emit(out, start, MoveKind::Rapid, false, None);
        let reference = self.reference_point(1);
        let machine = add(self.actual(), self.state.coords.zero);
        let tol = 0.5 * self.units().increment() * self.units().mm();
        let u = self.units();
        let letters = ['X', 'Y', 'Z'];
        for axis in 0..3 {
            if named[axis] && (machine[axis] - reference[axis]).abs() > tol {
                return Err(self.error(
                    "reference-check",
                    span,
                    format!(
                        "G27: {} reached machine {}, not the reference position {} (the control's alarm: Fanuc PS0092){}",
                        letters[axis],
                        show(machine[axis], u),
                        show(reference[axis], u),
                        if self.actual()[axis] != self.state.programmed[axis] {
                            "; the offsets moved the tool off the point the words name: cancel them before G27"
                        } else {
                            ""
                        }
                    ),
                ));
            }
        }
        let checked: Vec<String> = (0..3)
            .filter(|&a| named[a])
            .map(|a| letters[a].to_string())
            .collect();
        out.notes.push(format!(
            "G27: {} at the reference position (checked)",
            checked.join(", ")
        ));
        Ok(())
    }
}
