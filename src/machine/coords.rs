//! Coordinates and positioning (behaviour 13.1–13.4, 13.14): the codes that
//! say where a program's coordinates lie — G52 local coordinates,
//! G54.1/G154 additional work systems, G92.1 preset, G53 machine
//! coordinates — and the rotary axis words A, B, C, reported and not drawn.
//! The mill's transformations are [`super::transform`]; the reference
//! returns [`super::reference`].

use super::modal::{Distance, WorkSystem};
use super::{AXES, Machine, Out};
use crate::diag::Diagnostic;
use crate::geometry::{Xyz, add, scale, show, sub};
use crate::setup::{ExtendedWork, MachineKind};
use crate::syntax::codes::{
    Group, MAX_ADDITIONAL_WORK, MAX_HAAS_WORK, NonModal, ScalingMode, WorkCode,
};
use crate::syntax::{Address, Block, Word};

/// The rotary axis words, in the order of [`super::BlockState::rotary`].
const ROTARY: [Address; 3] = [Address::A, Address::B, Address::C];

impl Machine {
    // ----- where the coordinates lie --------------------------------------

    /// The machine position of the zero of work system `work` (mm): its
    /// row of the setup, machine zero when the setup leaves it out (behaviour
    /// 13.3).
    /// The external work offset (`G10 L2 P0`, Fanuc EXT) is added to every
    /// system (behaviour 17.9).
    pub(super) fn work_zero(&self, work: WorkSystem) -> Xyz {
        let unit = self.setup.units.mm();
        let p = match work.index() {
            Some(i) => self.setup.work_offsets.get(i),
            None => match work {
                WorkSystem::Additional(n) | WorkSystem::Haas(n) => self
                    .setup
                    .extended_work_offsets
                    .get(&u16::from(n))
                    .copied()
                    .unwrap_or_default(),
                _ => Default::default(),
            },
        };
        let ext = self.setup.work_offsets.ext;
        scale(add(p.to_array(), ext.to_array()), unit)
    }

    /// The zero of the current coordinate system from its three parts: the
    /// work system, the G92/G50 shift and the G52 local offset.
    pub(super) fn zero_now(&self) -> Xyz {
        let c = &self.state.coords;
        add(add(self.work_zero(self.state.modal.work), c.shift), c.local)
    }

    /// Moves the zero of the current coordinate system to `zero` (machine
    /// coordinates) without moving the tool: its coordinates change.
    pub(super) fn move_zero(&mut self, zero: Xyz) {
        let delta = sub(self.state.coords.zero, zero);
        self.state.programmed = add(self.state.programmed, delta);
        if self.setup.machine == MachineKind::Lathe {
            self.state.programmed[1] = 0.0;
        }
        self.state.coords.zero = zero;
    }

    /// G54–G59, G54.1 Pn, G154 Pn (behaviour 2.7, 13.3): the tool stays; its
    /// coordinates change to the new system, whose zero carries the G92
    /// shift and the G52 local offset along.
    pub(super) fn select_work(&mut self, work: WorkSystem) {
        self.state.modal.work = work;
        let zero = self.zero_now();
        self.move_zero(zero);
    }

    /// A group 14 code (behaviour 13.3): which system it names, with the
    /// block's P for the additional ones, as setting
    /// `extended_work_offsets` (7.22) says the control writes them.
    pub(super) fn work_code(
        &mut self,
        b: &Block,
        code: WorkCode,
        out: &mut Out,
    ) -> Result<(), Diagnostic> {
        if self.setup.settings.control == crate::setup::Control::Linuxcnc {
            // Even the system in use (behaviour 22.14).
            self.refuse_in_compensation(
                b,
                "selects a work system",
                "Cannot change coordinate systems with cutter radius compensation on",
            )?;
        }
        let setting = self.setup.settings.extended_work_offsets();
        let span = b.code_span(Group::Work);
        let p = b.get(Address::P);
        let numbered = |max: u8, written: &str| -> Result<u8, Diagnostic> {
            let Some(p) = p else {
                return Err(self.error(
                    "work-offset-number",
                    span,
                    format!("{written} needs P, the number of the work system (P1 to P{max})"),
                ));
            };
            let n = p.int();
            if n == 0 || n > u32::from(max) {
                return Err(self.error(
                    "work-offset-number",
                    p.span,
                    format!("{written} P{n}: the work systems are P1 to P{max}"),
                ));
            }
            Ok(n as u8)
        };
        let foreign = |written: &str, native: &str| {
            self.error(
                "work-offset-code",
                span,
                format!(
                    "{written} is not this control's code for additional work systems (setting extended_work_offsets = {}): write {native}",
                    setting.as_str()
                ),
            )
        };
        let work = match (code, setting) {
            (WorkCode::Standard(w), _) if p.is_none() => w,
            (WorkCode::Standard(WorkSystem::G54), ExtendedWork::G54_1) => {
                WorkSystem::Additional(numbered(MAX_ADDITIONAL_WORK, "G54 P")?)
            }
            (WorkCode::Standard(w), _) => {
                return Err(self.error(
                    "work-offset-number",
                    p.map_or(span, |p| p.span),
                    format!(
                        "{} takes no P (Fanuc reads G54 Pn as G54.1 Pn; setting extended_work_offsets = {})",
                        w.gcode(),
                        setting.as_str()
                    ),
                ));
            }
            (WorkCode::Additional, ExtendedWork::G54_1) => {
                WorkSystem::Additional(numbered(MAX_ADDITIONAL_WORK, "G54.1")?)
            }
            (WorkCode::Haas, ExtendedWork::G154) => {
                WorkSystem::Haas(numbered(MAX_HAAS_WORK, "G154")?)
            }
            // Haas: G110–G129 are G154 P1–P20 (behaviour 13.3).
            (WorkCode::HaasNamed(n), ExtendedWork::G154) if p.is_none() => WorkSystem::Haas(n),
            (WorkCode::HaasNamed(n), ExtendedWork::G154) => {
                return Err(self.error(
                    "work-offset-number",
                    p.map_or(span, |p| p.span),
                    format!("{} is G154 P{n} and takes no P", code.gcode()),
                ));
            }
            (WorkCode::HaasNamed(n), ExtendedWork::G54_1) => {
                return Err(foreign(code.gcode(), &format!("G54.1 P{n}")));
            }
            (WorkCode::Additional, ExtendedWork::G154) => return Err(foreign("G54.1", "G154 Pn")),
            (WorkCode::Haas, ExtendedWork::G54_1) => return Err(foreign("G154", "G54.1 Pn")),
        };
        if let Some(p) = p.filter(|_| work.index().is_none()) {
            self.p_is_the_work_systems(b, p)?;
        }
        self.refuse_in_transforms(span, work.gcode())?;
        self.select_work(work);
        if let WorkSystem::Additional(n) | WorkSystem::Haas(n) = work {
            let set = self.setup.extended_work_offsets.contains_key(&u16::from(n));
            out.notes.push(format!(
                "{}: zero at machine {}{}",
                work.gcode(),
                self.show_point(self.work_zero(work)),
                if set {
                    ""
                } else {
                    " (the setup leaves it out: machine zero)"
                }
            ));
        }
        Ok(())
    }

    /// Refuses a block where the P of G54.1/G154 would be read by another
    /// code too (a dwell, a canned cycle, G51's magnification).
    fn p_is_the_work_systems(&self, b: &Block, p: &Word) -> Result<(), Diagnostic> {
        let c = b.codes();
        let other = if c.non_modal() == Some(NonModal::Dwell) {
            Some("G04")
        } else if c.non_modal() == Some(NonModal::OtherReference) {
            Some("G30")
        } else if c.scaling() == Some(ScalingMode::Start) {
            Some("G51")
        } else if c.cycle().is_some() || self.state.modal.cycle.is_some() {
            Some("the canned cycle")
        } else {
            None
        };
        match other {
            Some(other) => Err(self.error(
                "p-conflict",
                p.span,
                format!("P numbers the work system here and is read by {other} too: write them in separate blocks"),
            )),
            None => Ok(()),
        }
    }

    /// G52 (behaviour 13.2): the local coordinate system's zero at the
    /// position the words give in the work system, on the named axes; `G52 X0
    /// Y0` cancels it there. The tool does not move.
    pub(super) fn g52(&mut self, b: &Block, out: &mut Out) -> Result<(), Diagnostic> {
        let span = b.code_span(Group::NonModal);
        self.refuse_in_transforms(span, "G52")?;
        let lathe = self.setup.machine == MachineKind::Lathe;
        for a in [Address::U, Address::W] {
            if let Some(w) = b.get(a).filter(|_| lathe) {
                return Err(self.error(
                    "g52-words",
                    w.span,
                    "G52 takes the local zero as X and Z in the work system, not U or W",
                ));
            }
        }
        let mut named = false;
        for (axis, (a, _)) in AXES.iter().enumerate() {
            if let Some(v) = b.value(*a) {
                named = true;
                self.state.coords.local[axis] = self.mm(v);
            }
        }
        if !named {
            return Err(self.error(
                "g52-without-axis",
                span,
                "G52 needs the axes of the local zero (G52 X0 Y0 cancels it)",
            ));
        }
        if lathe {
            self.state.coords.local[1] = 0.0;
        }
        let zero = self.zero_now();
        self.move_zero(zero);
        let local = self.state.coords.local;
        out.notes.push(if local == [0.0; 3] {
            format!(
                "G52: no local offset: coordinates are {}'s again",
                self.state.modal.work.gcode()
            )
        } else {
            format!(
                "G52: local zero at {} of {} (machine {})",
                self.show_point(local),
                self.state.modal.work.gcode(),
                self.show_point(self.state.coords.zero)
            )
        });
        Ok(())
    }

    /// G92.1 (mill, behaviour 13.4): the G92 shift of the named axes undone,
    /// each word 0 (Fanuc's workpiece coordinate system preset, `G92.1 X0`).
    pub(super) fn g92_1(&mut self, b: &Block, out: &mut Out) -> Result<(), Diagnostic> {
        let span = b.code_span(Group::NonModal);
        self.refuse_in_transforms(span, "G92.1")?;
        if self.setup.settings.control == crate::setup::Control::Linuxcnc {
            return self.g92_1_linuxcnc(b, out);
        }
        let mut named = Vec::new();
        for (axis, (a, letter)) in AXES.iter().enumerate() {
            let Some(w) = b.get(*a) else { continue };
            if w.value != 0.0 {
                return Err(self.error(
                    "g92-1-value",
                    w.span,
                    format!("G92.1 presets the axes it names: write {letter}0 (Fanuc: G92.1 IP 0)"),
                ));
            }
            self.state.coords.shift[axis] = 0.0;
            named.push(letter.to_string());
        }
        if named.is_empty() {
            return Err(self.error(
                "g92-1-without-axis",
                span,
                "G92.1 needs the axes whose G92 shift it undoes, each 0 (G92.1 X0 Y0 Z0)",
            ));
        }
        let zero = self.zero_now();
        self.move_zero(zero);
        out.notes.push(format!(
            "G92.1: the G92 shift on {} is undone; zero at machine {}",
            named.join(", "),
            self.show_point(self.state.coords.zero)
        ));
        Ok(())
    }

    /// How a G53 block moves: at rapid (Fanuc, 13.1); under LinuxCNC in
    /// the motion mode, G0 or G1 (behaviour 22.11; rs274 refuses the
    /// others).
    fn g53_kind(&self, span: crate::diag::Span) -> Result<super::MoveKind, Diagnostic> {
        use crate::syntax::codes::Motion;
        if self.setup.settings.control != crate::setup::Control::Linuxcnc {
            return Ok(super::MoveKind::Rapid);
        }
        match self.state.modal.motion {
            Motion::Rapid => Ok(super::MoveKind::Rapid),
            Motion::Linear if self.state.feed.is_some() => Ok(super::MoveKind::Feed),
            Motion::Linear => Err(self.error(
                "missing-feed",
                span,
                "G53 in G1 before any F: LinuxCNC refuses a feed move with no feed rate (\"Cannot do g1 with zero feed rate\")",
            )),
            _ => Err(self.error(
                "g53-motion",
                span,
                "G53 moves in G0 or G1 under LinuxCNC (rs274: \"Must use g0 or g1 with g53\"); write G0 or G1 in the block",
            )),
        }
    }

    /// LinuxCNC's G92.1 (behaviour 22.11): the G92 offset cancelled and
    /// zeroed on every axis. rs274 reads a G92.1 block's axis words as a
    /// move in the motion mode, which offsetlab does not follow: an error.
    fn g92_1_linuxcnc(&mut self, b: &Block, out: &mut Out) -> Result<(), Diagnostic> {
        if let Some(w) = AXES.iter().find_map(|(a, _)| b.get(*a)) {
            return Err(self.error(
                "g92-1-value",
                w.span,
                "G92.1 takes no axis words under LinuxCNC (rs274 cancels every axis and moves to the words in the motion mode, which offsetlab does not follow): write the move in a block of its own",
            ));
        }
        self.state.coords.shift = [0.0; 3];
        self.keep_g92_parameters(false);
        let zero = self.zero_now();
        self.move_zero(zero);
        out.notes.push(format!(
            "G92.1: the G92 offset is cancelled and zeroed on every axis (#5211… 0, LinuxCNC); zero at machine {}",
            self.show_point(self.state.coords.zero)
        ));
        Ok(())
    }

    /// G53 (behaviour 13.1): the named axes go at rapid to the machine
    /// coordinates the words give, whatever G52, G54–G59 and G92 say. On Z
    /// the length vector is off in this block and comes back at the next Z
    /// move; the G45–G48 vector stays (Fanuc: the machine moves by the
    /// offsets left on). On the lathe the T vector is off on the named axes
    /// until each moves again. Returns false for a G53 in G91, which Fanuc
    /// ignores: the block then runs as it would without G53.
    pub(super) fn g53(&mut self, b: &Block, out: &mut Out) -> Result<bool, Diagnostic> {
        let span = b.code_span(Group::NonModal);
        let lathe = self.setup.machine == MachineKind::Lathe;
        if self.state.modal.distance == Distance::Incremental && !lathe {
            if self.setup.settings.control == crate::setup::Control::Linuxcnc {
                // rs274: "Cannot use g53 incremental" (behaviour 22.4).
                return Err(self.error(
                    "g53-incremental",
                    span,
                    "G53 in G91: LinuxCNC refuses it (\"Cannot use g53 incremental\"); write G90 first",
                ));
            }
            out.warnings.push(Diagnostic::warning(
                "g53-incremental",
                span,
                "G53 in G91 is ignored (Fanuc: G53 takes absolute machine coordinates only): the words move incrementally as the block's motion mode says",
            ));
            out.notes
                .push("G53 in G91 is ignored: the block moves as it would without it".into());
            return Ok(false);
        }
        self.refuse_in_transforms(span, "G53")?;
        let letters = if lathe {
            [(0, Address::X), (2, Address::Z)].as_slice()
        } else {
            [(0, Address::X), (1, Address::Y), (2, Address::Z)].as_slice()
        };
        if lathe {
            for a in [Address::U, Address::W] {
                if let Some(w) = b.get(a) {
                    return Err(self.error(
                        "g53-words",
                        w.span,
                        "G53 takes absolute machine coordinates: X and Z, not U or W",
                    ));
                }
            }
        }
        let old_length = if lathe {
            self.state.length
        } else {
            self.length_words(b, out)?
        };
        let start = self.mark();
        let mut named = [false; 3];
        for &(axis, a) in letters {
            if let Some(v) = b.value(a) {
                named[axis] = true;
                self.state.programmed[axis] = self.mm(v) - self.state.coords.zero[axis];
                if lathe {
                    self.state.lathe.vector[axis] = 0.0;
                }
            }
        }
        let changed = self.state.length.changed_since(&old_length);
        let suspended = !lathe && named[2] && self.state.length.target != 0.0;
        if !named.iter().any(|n| *n) {
            out.notes
                .push("G53 without axis words: no axis moves by it".to_string());
            if !lathe {
                self.length_only_motion(out, old_length)?;
            }
            return Ok(true);
        }
        if !lathe {
            self.state.length.vector = if named[2] {
                0.0
            } else {
                let setting = self.setup.settings.length_offset_without_z();
                self.state.length.vector_after(false, changed, setting)
            };
        }
        let kind = self.g53_kind(span)?;
        self.emit(out, start, kind, false, None);
        let machine = add(self.actual(), self.state.coords.zero);
        let axes: Vec<String> = letters
            .iter()
            .filter(|(axis, _)| named[*axis])
            .map(|&(axis, a)| format!("{}{}", a.letter(), show(machine[axis], self.units())))
            .collect();
        let mut note = format!("G53: to machine {}", axes.join(" "));
        if suspended {
            note.push_str(&format!(
                " with the length offset off on Z; {} H{:02} applies again at the next Z move",
                self.state.length.mode().gcode(),
                self.state.length.h
            ));
        }
        if lathe && self.state.lathe.target != [0.0; 3] {
            note.push_str("; the T offset applies again at each axis's next move");
        }
        if !lathe && self.state.position.vector != [0.0; 3] {
            note.push_str("; the G45–G48 vector is carried");
        }
        out.notes.push(note);
        if changed && !named[2] {
            self.length_note(old_length, None, out);
        }
        Ok(true)
    }

    // ----- the rotary axes --------------------------------------------------

    /// A rotary axis word A, B or C (behaviour 13.14): its position is kept
    /// and reported (degrees; G91 adds to it, `absolute` blocks such as G92
    /// and G53 set it), never drawn; the first of a program gets a warning.
    pub(super) fn rotary_words(&mut self, b: &Block, absolute: bool, out: &mut Out) {
        for (i, a) in ROTARY.iter().enumerate() {
            // G07.1's rotary word is its cylinder's radius, and in its mode
            // the word moves on the cylinder (behaviour 14.10).
            let Some(w) = b.get(*a).filter(|_| !self.models_word(b, *a)) else {
                continue;
            };
            let v = self.unitless(w);
            let incremental = !absolute && self.state.modal.distance == Distance::Incremental;
            let now = match (self.state.rotary[i], incremental) {
                (Some(p), true) => p + v,
                (None, true) | (_, false) => v,
            };
            self.state.rotary[i] = Some(now);
            if !self.rotary_warned {
                self.rotary_warned = true;
                out.warnings.push(Diagnostic::warning(
                    "rotary-axis",
                    w.span,
                    format!(
                        "rotary axis {} is reported, not drawn: the drawing shows X, Y and Z",
                        a.letter()
                    ),
                ));
            }
            out.notes.push(format!(
                "rotary axis {} at {:.3}° (reported, not drawn)",
                a.letter(),
                now
            ));
        }
    }

    /// A point (mm) as `X… Y… Z…` in the block's units (a lathe point
    /// without Y).
    pub(super) fn show_point(&self, p: Xyz) -> String {
        let u = self.units();
        if self.setup.machine == MachineKind::Lathe {
            format!("X{} Z{}", show(p[0], u), show(p[2], u))
        } else {
            format!("X{} Y{} Z{}", show(p[0], u), show(p[1], u), show(p[2], u))
        }
    }
}
