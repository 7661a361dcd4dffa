//! Tool nose radius compensation on the lathe (behaviour 18): the machine's
//! side of what differs from the mill's compensation C. The lathe runs the
//! same start-up, corners and cancel in the ZX plane; here are the plane's
//! scale (the program's X is a diameter, the compensation works in radius:
//! Fanuc 0i-TF, "Tool nose radius compensation"), the register the radius
//! and tip come from (the T code's offset number), the shift from the nose
//! centre to the imaginary tool nose, and what the lathe refuses in
//! compensation (the cycles, a new offset number, polar interpolation).

use super::P2;
use crate::diag::Diagnostic;
use crate::machine::Machine;
use crate::machine::modal::Motion;
use crate::offsets::cutter::{Phase, nose};
use crate::setup::MachineKind;
use crate::syntax::codes::{Code, CutterCompensation, Group, NonModal, Repetitive};
use crate::syntax::{Address, Block};

impl Machine {
    /// True on the lathe, where G41/G42 are tool nose radius compensation.
    #[inline(always)]
    pub(in crate::machine) fn nose_lathe(&self) -> bool {
        self.setup.machine == MachineKind::Lathe
    }

    /// The factors from the program's coordinates to the compensation
    /// plane's: the lathe's X (the plane's second axis, a diameter) is
    /// halved, so that the offsets are the nose radius away on the part
    /// (behaviour 18.1).
    #[inline(always)]
    pub(in crate::machine) fn plane_scale(&self) -> P2 {
        if self.nose_lathe() {
            [1.0, 0.5]
        } else {
            [1.0, 1.0]
        }
    }

    /// A lathe block as tool nose radius compensation runs it, out of the
    /// mill's way (the mill's compensation is the 1M-block G41 benchmark's
    /// path, docs/performance.md). The cycles that read the program again
    /// are refused before (`nose_checks`), so no program text is needed.
    #[cold]
    #[inline(never)]
    pub(super) fn nose_run(
        &mut self,
        b: &Block,
        out: &mut crate::machine::Out,
    ) -> Result<(), Diagnostic> {
        self.lathe_run(b, out, &mut crate::machine::program::NoText)
    }

    /// True for a G70–G73 or G90/G92/G94 cycle block while G41/G42 is the
    /// mode or its vector is on: the cycle compensates itself (behaviour
    /// 18.11, 18.15) instead of the block-by-block compensation.
    pub(in crate::machine) fn nose_cycle_block(&self, b: &Block) -> bool {
        if !self.nose_lathe() || !self.state.cutter.engaged() || b.codes().cutter().is_some() {
            return false;
        }
        if let Some(NonModal::Repetitive(r)) = b.codes().non_modal() {
            return handled(r);
        }
        let axis = [Address::X, Address::U, Address::Z, Address::W, Address::R]
            .iter()
            .any(|a| b.has(*a));
        axis && b.codes().non_modal().is_none()
            && matches!(
                b.codes().motion().unwrap_or(self.state.modal.motion),
                Motion::LatheCycle(_)
            )
    }

    /// A cycle block in G41/G42 (behaviour 18.11, 18.15): what the mode
    /// refuses, then the cycle, which leaves the tool at its start point
    /// without a vector.
    #[cold]
    #[inline(never)]
    pub(in crate::machine) fn nose_cycle_run(
        &mut self,
        b: &Block,
        out: &mut crate::machine::Out,
        program: &mut dyn crate::machine::program::ProgramText,
    ) -> Result<(), Diagnostic> {
        self.nose_checks(b)?;
        if self.state.cutter.mode == CutterCompensation::Cancel
            && self.state.cutter.phase == Phase::Cancelling
        {
            self.state.cutter.phase = Phase::Cancel;
        }
        let moves = out.moves.len();
        self.lathe_run(b, out, program)?;
        if out.moves.len() > moves {
            self.nose_after_cycle();
        }
        Ok(())
    }

    /// The nose radius of the active T code's offset register (geometry +
    /// wear, mm; 0 with offset 00) and its tip direction (behaviour 18.1).
    #[inline(never)]
    pub(in crate::machine) fn nose_register(&self) -> (f64, u8) {
        let n = self.state.lathe.offset;
        if n == 0 {
            return (0.0, 0);
        }
        let reg = self.setup.lathe_register(n);
        (self.mm(reg.r_value()), reg.t)
    }

    /// Imaginary tool nose − nose centre in the plane (Z, X radius; mm)
    /// while the vector is on: the tip direction's vector times the nose
    /// radius (behaviour 18.2); zero on the mill and for tips 0 and 9.
    pub(in crate::machine) fn nose_tip(&self) -> P2 {
        let c = self.state.cutter;
        match c.tip {
            Some(t) => {
                let v = nose::tip_vector(t);
                let r = c.radius.abs();
                [v[0] * r, v[1] * r]
            }
            None => [0.0, 0.0],
        }
    }

    /// What tool nose radius compensation refuses before a lathe block runs
    /// (behaviour 18.7, 18.8): the single cycles G90/G92/G94 and the
    /// multiple repetitive cycles G70–G73 while G41/G42 is the mode or its
    /// vector is on, a T code naming another offset, polar interpolation.
    #[inline(never)]
    pub(super) fn nose_checks(&self, b: &Block) -> Result<(), Diagnostic> {
        let now = self.state.cutter;
        let codes = b.codes();
        let mode = codes.cutter().unwrap_or(now.mode);
        let on = mode != CutterCompensation::Cancel || now.engaged();
        if !on {
            return Ok(());
        }
        let name = if mode == CutterCompensation::Cancel {
            now.mode.gcode()
        } else {
            mode.gcode()
        };
        let axis = [Address::X, Address::U, Address::Z, Address::W, Address::R]
            .iter()
            .any(|a| b.has(*a));
        if let Motion::LatheCycle(_) = codes.motion().unwrap_or(self.state.modal.motion)
            && axis
            && codes.cutter().is_some()
        {
            let m = codes.motion().unwrap_or(self.state.modal.motion);
            return Err(self.error(
                "nose-in-cycle",
                b.code_span(Group::Motion),
                format!(
                    "{} with {name} in one block: write G41/G42 in a block before the cycle (the cycle then compensates its legs, behaviour 18.15)",
                    Code::Motion(m).gcode(self.state.table())
                ),
            ));
        }
        if let Some(NonModal::Repetitive(r)) = codes.non_modal()
            && (!handled(r) || codes.cutter().is_some())
        {
            return Err(self.error(
                "nose-in-cycle",
                b.code_span(Group::NonModal),
                format!(
                    "{} with {name}: G74–G76 with tool nose radius compensation are not modelled, nor G41/G42 in a cycle's own block (cancel with G40 before, or write G41/G42 in a block before G70–G73)",
                    Code::NonModal(NonModal::Repetitive(r)).gcode(self.state.table())
                ),
            ));
        }
        // A new offset number for the same tool reads its radius and tip
        // as a new D does on the mill (16.8: the block ends on the new
        // offset); another tool is not modelled under the compensation.
        if let Some(t) = b.get(Address::T)
            && t.int() / 100 != self.state.lathe.tool
            && (now.mode != CutterCompensation::Cancel
                || matches!(now.phase, Phase::StartUp | Phase::Offset))
        {
            return Err(self.error(
                "nose-t-change",
                t.span,
                format!(
                    "T{:04}: a tool change while {name} is on is not modelled: cancel with G40 first (a new offset number for tool {:02} is read as a new nose radius and tip)",
                    t.int(),
                    self.state.lathe.tool
                ),
            ));
        }
        // Compensation works in the ZX plane, X as a radius (18.1); G17 is
        // the face plane of polar interpolation only.
        if codes.plane().unwrap_or(self.state.modal.plane) != crate::machine::modal::Plane::ZX
            && !self.in_polar_mode(b)
        {
            return Err(self.error(
                "nose-plane",
                b.code_span(Group::Plane),
                format!("{name}: tool nose radius compensation works in the ZX plane (G18)"),
            ));
        }
        if self.in_polar_mode(b) {
            return Err(self.error(
                "nose-polar",
                b.span,
                format!(
                    "{name} in polar coordinate interpolation (the face plane) is not modelled: cancel with G40 before G12.1"
                ),
            ));
        }
        Ok(())
    }

    /// The sentence of a lathe start-up saying which point the program
    /// follows and where it lies from the nose centre (behaviour 18.2).
    pub(super) fn nose_note(&self, tip: u8) -> String {
        let follows = nose::follows(tip);
        let t = self.nose_tip();
        if t == [0.0, 0.0] {
            return format!(
                "the program's points are {follows}: the tool runs on the offset path itself"
            );
        }
        let u = self.units();
        format!(
            "the program's points are {follows}: the tool is placed so that it runs where the nose centre runs moved by Z {} X {} (X as a diameter), so on a face or a diameter it cuts on the programmed line",
            crate::geometry::show_signed(t[0], u),
            crate::geometry::show_signed(2.0 * t[1], u)
        )
    }
}

/// The multiple repetitive cycles that compensate their contour (behaviour
/// 18.11): G70–G73; G74–G76 are refused in G41/G42.
fn handled(r: Repetitive) -> bool {
    match r {
        Repetitive::Finishing
        | Repetitive::TurningStock
        | Repetitive::FacingStock
        | Repetitive::PatternRepeat => true,
        Repetitive::FacePeck | Repetitive::DiameterPeck | Repetitive::Threading => false,
    }
}
