//! Modal codes without geometry (behaviour 14): the cutting modes G61–G64,
//! exact stop G09, Fanuc's AI contour control G05.1 and look-ahead G08,
//! Haas's smoothness G187, the mill's feed modes G93/G94/G95 and surface
//! speed G96/G97, the lathe's G80, and the skip function G31. None of them
//! changes where the tool goes; each is kept in the modal state, its words are
//! read or refused, and the block says in a sentence what changed.

use super::modal::{CuttingMode, FeedMode, Modal, Motion, Smoothness, SurfaceSpeed};
use super::{Machine, Out};
use crate::diag::Diagnostic;
use crate::setup::MachineKind;
use crate::syntax::codes::{Group, NonModal};
use crate::syntax::{Address, Block, Word};

/// The words that move the tool or shape a move: a block of G05.1, G08 or
/// G187 may hold none of them but its own (behaviour 14.3).
const SHAPING_WORDS: [Address; 17] = [
    Address::X,
    Address::Y,
    Address::Z,
    Address::U,
    Address::W,
    Address::I,
    Address::J,
    Address::K,
    Address::R,
    Address::P,
    Address::Q,
    Address::L,
    Address::D,
    Address::E,
    Address::A,
    Address::B,
    Address::C,
];

impl Machine {
    /// The modal codes of behaviour 14 in a block (both machines), after the
    /// common words: kept, their words checked, their sentence noted.
    /// `before` is the modal state before the block.
    pub(super) fn mode_codes(
        &mut self,
        b: &Block,
        out: &mut Out,
        before: Modal,
    ) -> Result<(), Diagnostic> {
        let c = b.codes();
        let mill = self.setup.machine == MachineKind::Mill;
        let linuxcnc = self.setup.settings.control == crate::setup::Control::Linuxcnc;
        if let Some(mode) = c.cutting_mode()
            && linuxcnc
        {
            self.linuxcnc_path_mode(b, out, mode)?;
        } else if let Some(mode) = c.cutting_mode()
            && let Some(w) = b.get(Address::P).or_else(|| b.get(Address::Q))
        {
            return Err(self.error(
                "mode-words",
                w.span,
                format!(
                    "{} takes no {} (a path tolerance G64 P… is LinuxCNC's, not a Fanuc, Haas or YASNAC word)",
                    mode.gcode(),
                    w.address.letter()
                ),
            ));
        }
        if let Some(mode) = c.cutting_mode()
            && mode != before.cutting_mode
        {
            self.state.modal.cutting_mode = mode;
            // LinuxCNC's sentence was said above, at every such block.
            if !linuxcnc {
                out.notes.push(cutting_mode_sentence(mode).to_string());
            }
        }
        if mill
            && let Some(feed) = c.feed_mode()
            && feed != before.feed_mode
        {
            out.notes.push(feed_mode_sentence(feed).to_string());
        }
        if mill
            && let Some(css) = c.surface_speed()
            && css != before.surface_speed
        {
            out.notes.push(surface_speed_sentence(css).to_string());
        }
        match c.non_modal() {
            Some(NonModal::ExactStop) => out.notes.push(
                "G09 exact stop: the tool comes to a full stop at this block's end point before the next block starts (this block only); the path is unchanged".to_string(),
            ),
            Some(NonModal::AiContour) => self.ai_contour(b, out)?,
            Some(NonModal::LookAhead) => self.look_ahead(b, out)?,
            Some(NonModal::Smoothness) => self.smoothness(b, out)?,
            Some(NonModal::BlockLimit) => self.block_limit(b, out)?,
            Some(NonModal::Cylindrical) => self.cylindrical(b, out)?,
            Some(
                NonModal::Dwell
                | NonModal::Skip
                | NonModal::CirclePocket(_)
                | NonModal::Engraving
                | NonModal::ReferenceReturn
                | NonModal::PositionOffset(_)
                | NonModal::SetCoordinates
                | NonModal::ReferenceCheck
                | NonModal::OtherReference
                | NonModal::LocalCoordinates
                | NonModal::MachineCoordinates
                | NonModal::PresetCoordinates
                | NonModal::Stored(_)
                | NonModal::CornerArc
                // G70–G76 are the lathe's; G10 takes no mode code's path.
                | NonModal::Repetitive(_)
                | NonModal::DataSetting,
            )
            | None => {}
        }
        self.polar_code(b, out, before);
        self.cylinder_word(b, out);
        self.update_special();
        Ok(())
    }

    /// The one word a mode code of group 00 takes (`Q` of G05.1, `P` of
    /// G08), with every shaping word but `own` refused (behaviour 14.3).
    fn mode_word(
        &self,
        b: &Block,
        own: &[Address],
        code: &str,
        takes: &str,
    ) -> Result<(), Diagnostic> {
        if let Some(w) = b
            .words
            .iter()
            .find(|w| SHAPING_WORDS.contains(&w.address) && !own.contains(&w.address))
        {
            return Err(self.error(
                "mode-words",
                w.span,
                format!(
                    "{code} takes {takes} in a block of its own (Fanuc: specify it alone); {} is not read here",
                    w.address.letter()
                ),
            ));
        }
        Ok(())
    }

    /// The value of a switch word that must be 0 or 1 (G05.1 Q, G08 P).
    /// G05.1's Q is read as a dimension: without a point, `Q1` is its number
    /// as written only in calculator input, else that many least increments
    /// (behaviour 14.4).
    fn switch(&self, b: &Block, a: Address, code: &str) -> Result<bool, Diagnostic> {
        let increments = a == Address::Q
            && self.setup.settings.decimal_input() == crate::setup::DecimalInput::Increment;
        let scale = 10f64.powi(self.units().decimals() as i32);
        let on_off = |w: &Word| {
            let v = if increments && !w.point {
                w.value * scale
            } else {
                w.value
            };
            match v {
                v if (v - 0.0).abs() < 1e-9 => Some(false),
                v if (v - 1.0).abs() < 1e-9 => Some(true),
                _ => None,
            }
        };
        match b.get(a) {
            Some(w) => on_off(w).ok_or_else(|| {
                self.error(
                    "mode-words",
                    w.span,
                    format!("{code} takes {}1 (on) or {}0 (off)", a.letter(), a.letter()),
                )
            }),
            None => Err(self.error(
                "mode-words",
                b.code_span(Group::NonModal),
                format!("{code} needs {}1 (on) or {}0 (off)", a.letter(), a.letter()),
            )),
        }
    }

    /// G05.1 Q1 / Q0: Fanuc AI contour control (behaviour 14.4).
    fn ai_contour(&mut self, b: &Block, out: &mut Out) -> Result<(), Diagnostic> {
        self.mode_word(b, &[Address::Q], "G05.1", "Q1 or Q0")?;
        let on = self.switch(b, Address::Q, "G05.1")?;
        self.state.modal.ai_contour = on;
        out.notes.push(if on {
            "G05.1 Q1 AI contour control on: the control looks ahead and slows the feed before corners and tight arcs; the path is unchanged and offsetlab does not simulate feed rates".to_string()
        } else {
            "G05.1 Q0 AI contour control off".to_string()
        });
        Ok(())
    }

    /// G08 P1 / P0: Fanuc look-ahead, advanced preview control (behaviour 14.5).
    fn look_ahead(&mut self, b: &Block, out: &mut Out) -> Result<(), Diagnostic> {
        self.mode_word(b, &[Address::P], "G08", "P1 or P0")?;
        let on = self.switch(b, Address::P, "G08")?;
        self.state.modal.look_ahead = on;
        out.notes.push(if on {
            "G08 P1 look-ahead (advanced preview control) on: the control reads blocks ahead to accelerate and decelerate before they come; the path is unchanged and offsetlab does not simulate feed rates".to_string()
        } else {
            "G08 P0 look-ahead off".to_string()
        });
        Ok(())
    }

    /// G187 P1–P3 E…: Haas smoothness (behaviour 14.6).
    fn smoothness(&mut self, b: &Block, out: &mut Out) -> Result<(), Diagnostic> {
        self.mode_word(b, &[Address::P, Address::E], "G187", "P1–P3 and E")?;
        let level = match b.get(Address::P) {
            Some(w) if (1..=3).contains(&w.int()) => w.int() as u8,
            Some(w) => {
                return Err(self.error(
                    "mode-words",
                    w.span,
                    "G187 takes P1 (rough), P2 (medium) or P3 (finish)",
                ));
            }
            None => 0,
        };
        let corner = self.smoothness_corner(b)?;
        let s = Smoothness { level, corner };
        self.state.modal.smoothness = Some(s);
        let mut note = match level {
            1 => "G187 P1 smoothness rough: the control favours speed over following sharp corners"
                .to_string(),
            2 => "G187 P2 smoothness medium".to_string(),
            3 => "G187 P3 smoothness finish: the control favours following the path over speed"
                .to_string(),
            _ => "G187 without P: the smoothness returns to Setting 191's default".to_string(),
        };
        if let Some(e) = corner {
            let u = self.units();
            let d = u.decimals();
            note.push_str(&format!(
                "; E{:.d$}: the control may round each corner by up to this much, while offsetlab draws the programmed corners",
                crate::geometry::to_units(e, u)
            ));
        }
        out.notes.push(note);
        Ok(())
    }

    /// Haas G103 P0–P15: the blocks the control looks ahead (behaviour
    /// 14.22). offsetlab runs every block in order, macro statements when
    /// their block is reached, so the path and the values are unchanged.
    fn block_limit(&mut self, b: &Block, out: &mut Out) -> Result<(), Diagnostic> {
        self.mode_word(b, &[Address::P], "G103", "P0–P15")?;
        let note = match b.get(Address::P) {
            Some(w) if w.value.fract() == 0.0 && (1.0..=15.0).contains(&w.value) => format!(
                "G103 P{}: the control looks at most {} ahead while it moves, so macro statements are read that close to the block being cut (Haas); offsetlab reads every block in order, the path is unchanged",
                w.int(),
                if w.int() == 1 { "one block".to_string() } else { format!("{} blocks", w.int()) }
            ),
            Some(w) if w.value == 0.0 => "G103 P0: the control's look-ahead is no longer limited (Haas); the path is unchanged".to_string(),
            None => "G103 without P: the control's look-ahead is no longer limited (Haas); the path is unchanged".to_string(),
            Some(w) => {
                return Err(self.error(
                    "mode-words",
                    w.span,
                    "G103 takes P0 to P15, the most blocks the control looks ahead (Haas)",
                ));
            }
        };
        out.notes.push(note);
        Ok(())
    }

    /// G187's E word: how far a corner may be rounded (mm), not negative.
    fn smoothness_corner(&self, b: &Block) -> Result<Option<f64>, Diagnostic> {
        match b.get(Address::E) {
            Some(e) if e.value < 0.0 => Err(self.error(
                "mode-words",
                e.span,
                "G187 E, the corner tolerance, is not negative",
            )),
            Some(e) => Ok(Some(self.mm(e.value))),
            None => Ok(None),
        }
    }

    /// G07.1 with the rotary axis word whose value is the cylinder's radius
    /// (0 cancels) (behaviour 14.10, Fanuc "Cylindrical interpolation").
    fn cylindrical(&mut self, b: &Block, out: &mut Out) -> Result<(), Diagnostic> {
        let rotary: &[Address] = match self.setup.machine {
            MachineKind::Mill => &[Address::A, Address::B, Address::C],
            MachineKind::Lathe => &[Address::C],
        };
        let words: Vec<&Word> = b
            .words
            .iter()
            .filter(|w| rotary.contains(&w.address))
            .collect();
        self.mode_word(
            b,
            rotary,
            "G07.1",
            "the rotary axis word and the cylinder's radius",
        )?;
        let [w] = words[..] else {
            return Err(self.error(
                "mode-words",
                b.code_span(Group::NonModal),
                if self.setup.machine == MachineKind::Lathe {
                    "G07.1 needs C, the cylinder's radius (C0 cancels)"
                } else {
                    "G07.1 needs one rotary axis word (A, B or C), the cylinder's radius (0 cancels)"
                },
            ));
        };
        let letter = w.address.letter();
        if w.value < 0.0 {
            return Err(self.error(
                "mode-words",
                w.span,
                format!("G07.1 {letter}: the cylinder's radius is not negative"),
            ));
        }
        if w.value == 0.0 {
            self.state.modal.cylinder = None;
            out.notes
                .push(format!("G07.1 {letter}0 cylindrical interpolation off"));
            return Ok(());
        }
        let r = self.mm(w.value);
        self.state.modal.cylinder = Some((w.address, r));
        let u = self.units();
        let d = u.decimals();
        out.notes.push(format!(
            "G07.1 cylindrical interpolation on, about a cylinder of radius {:.d$}: the {letter} axis turns the work by the angle of each {letter} word (degrees), a length of radius × angle along its surface; offsetlab reports those moves and does not draw them (the drawing shows the other axes only)",
            crate::geometry::to_units(r, u)
        ));
        Ok(())
    }

    /// In G07.1's mode, a block's rotary word: reported, not drawn
    /// (behaviour 14.10).
    fn cylinder_word(&self, b: &Block, out: &mut Out) {
        let Some((axis, r)) = self.state.modal.cylinder else {
            return;
        };
        if b.codes().non_modal() == Some(NonModal::Cylindrical) {
            return;
        }
        if let Some(w) = b.get(axis) {
            let u = self.units();
            let d = u.decimals();
            out.notes.push(format!(
                "{}{}° on the cylinder of radius {:.d$} ({:.d$} along its surface from 0°, G07.1): not drawn",
                axis.letter(),
                w.value,
                crate::geometry::to_units(r, u),
                crate::geometry::to_units(r * w.value.to_radians(), u)
            ));
        }
    }

    /// G93 in effect: a feed block without F is refused (behaviour 14.8,
    /// Fanuc: F is given in every block in inverse time).
    pub(super) fn check_inverse_time(&self, b: &Block) -> Result<(), Diagnostic> {
        let c = b.codes();
        let motion = c.motion().unwrap_or(self.state.modal.motion);
        let moves = [Address::X, Address::Y, Address::Z]
            .iter()
            .any(|a| b.has(*a));
        let feed = match c.non_modal() {
            // G39's corner arc is cut at the feed (behaviour 16.14).
            Some(
                NonModal::Skip
                | NonModal::CirclePocket(_)
                | NonModal::Engraving
                | NonModal::CornerArc,
            ) => true,
            Some(
                NonModal::Dwell
                | NonModal::ReferenceReturn
                | NonModal::SetCoordinates
                | NonModal::ExactStop
                | NonModal::AiContour
                | NonModal::LookAhead
                | NonModal::Smoothness
                | NonModal::BlockLimit
                | NonModal::Cylindrical
                // The reference returns, G53 and the coordinate codes move at
                // rapid or not at all (behaviour 13).
                | NonModal::ReferenceCheck
                | NonModal::OtherReference
                | NonModal::LocalCoordinates
                | NonModal::MachineCoordinates
                | NonModal::PresetCoordinates
                | NonModal::Stored(_)
                // G70–G76 are the lathe's; G10 moves nothing.
                | NonModal::Repetitive(_)
                | NonModal::DataSetting,
            ) => false,
            Some(NonModal::PositionOffset(_)) | None => {
                moves
                    && self.state.modal.cycle.is_none()
                    && c.cycle().is_none()
                    && matches!(motion, Motion::Linear | Motion::Arc(_))
            }
        };
        match b.get(Address::F) {
            None if feed => Err(self.error(
                "inverse-time-feed",
                b.span,
                "in G93 (inverse time) every feed block needs its own F, 1 / the minutes the move takes: a Fanuc control alarms without one",
            )),
            Some(f) if feed && f.value <= 0.0 => Err(self.error(
                "inverse-time-feed",
                f.span,
                "in G93 F is 1 / the minutes the move takes and cannot be 0",
            )),
            _ => Ok(()),
        }
    }

    /// G31: the skip function's words and sentence (behaviour 14.7). The
    /// move itself is a G01's, made by the caller.
    pub(super) fn skip_note(&self, b: &Block, out: &mut Out) -> Result<(), Diagnostic> {
        if let Some(cycle) = self.state.modal.cycle {
            return Err(self.error(
                "skip-words",
                b.code_span(Group::NonModal),
                format!(
                    "G31 cannot be given while canned cycle {} is active: cancel it with G80 first",
                    cycle.gcode()
                ),
            ));
        }
        let axes: &[Address] = match self.setup.machine {
            MachineKind::Mill => &[Address::X, Address::Y, Address::Z],
            MachineKind::Lathe => &[Address::X, Address::U, Address::Z, Address::W],
        };
        if !axes.iter().any(|a| b.has(*a)) {
            return Err(self.error(
                "skip-words",
                b.code_span(Group::NonModal),
                "G31 needs the axis words of the move a skip signal may stop",
            ));
        }
        for a in [
            Address::I,
            Address::J,
            Address::K,
            Address::R,
            Address::Q,
            Address::L,
        ] {
            if let Some(w) = b.get(a) {
                return Err(self.error(
                    "skip-words",
                    w.span,
                    format!(
                        "G31 moves in a straight line: {} is not read with it",
                        a.letter()
                    ),
                ));
            }
        }
        let signal = match b.get(Address::P) {
            Some(w) if (1..=4).contains(&w.int()) => format!(
                " (skip signal {} of the multi-step skip, P{})",
                w.int(),
                w.int()
            ),
            Some(w) => {
                return Err(self.error(
                    "skip-words",
                    w.span,
                    "G31 P selects the skip signal of Fanuc's multi-step skip: P1 to P4",
                ));
            }
            None => String::new(),
        };
        out.notes.push(format!(
            "G31 skip: moves at the feed to the end point as G01 does{signal}; on a real control a skip signal (a probe touching) stops the move where it comes and the control keeps that position (Fanuc #5061–#5063), so the tool may stop earlier than drawn"
        ));
        Ok(())
    }
}

/// The sentence of a new cutting mode (behaviour 14.2); LinuxCNC's are
/// `linuxcnc_path_mode`'s (22.16).
fn cutting_mode_sentence(mode: CuttingMode) -> &'static str {
    match mode {
        CuttingMode::ExactStop => {
            "G61 exact stop mode: every move comes to a full stop at its end point before the next starts; the path is unchanged"
        }
        CuttingMode::ExactPath | CuttingMode::ExactStopLinuxcnc => {
            "LinuxCNC's G61 exact path or G61.1 exact stop: the path is unchanged"
        }
        CuttingMode::CornerOverride => {
            "G62 automatic corner override: the feed is reduced at inner corners under cutter compensation; the path is unchanged"
        }
        CuttingMode::Tapping => {
            "G63 tapping mode: feed override and feed hold are ignored and moves do not decelerate at their ends; the path is unchanged"
        }
        CuttingMode::Cutting => {
            "G64 cutting mode: moves follow one another without a stop at block ends (the start state); the path is unchanged"
        }
    }
}

/// The sentence of a new feed mode on the mill (behaviour 14.8).
fn feed_mode_sentence(mode: FeedMode) -> &'static str {
    match mode {
        FeedMode::InverseTime => {
            "G93 inverse time feed: in each feed block F is 1 / the minutes the move takes (F2. is a 30 s move) and must be given in every such block; offsetlab draws the path and does not simulate time"
        }
        FeedMode::PerMinute => "G94 feed per minute: F is mm/min (in/min in G20)",
        FeedMode::PerRevolution => "G95 feed per revolution: F is mm (in) per spindle revolution",
    }
}

/// The sentence of G96/G97 on the mill (behaviour 14.8).
fn surface_speed_sentence(css: SurfaceSpeed) -> &'static str {
    match css {
        SurfaceSpeed::Constant => {
            "G96 constant surface speed: S is the cutting speed in m/min (ft/min in G20), and the control sets the spindle speed from the tool's distance to the axis its parameter names; offsetlab keeps S as written"
        }
        SurfaceSpeed::Cancel => {
            "G97 constant surface speed off: S is spindle revolutions per minute"
        }
    }
}

impl Machine {
    /// LinuxCNC's path control modes (behaviour 22.16; LinuxCNC 2.9
    /// documentation, "G61, G61.1", "G64"; `interp_convert.cc`
    /// `convert_control_mode`): G61 exact path, G61.1 exact stop, G64 with
    /// P (blending tolerance) and Q (naive CAM tolerance). Each block that
    /// names one is said, as rs274 sends SET_MOTION_CONTROL_MODE for each:
    /// the trajectory planner follows them, while the path drawn is the
    /// interpreter's, with its corners, as `rs274 -g` prints it.
    #[cold]
    #[inline(never)]
    fn linuxcnc_path_mode(
        &mut self,
        b: &Block,
        out: &mut Out,
        mode: CuttingMode,
    ) -> Result<(), Diagnostic> {
        use crate::syntax::codes::CutterCompensation;
        // rs274 runs G40–G42 before G61–G64 in a block.
        let comp = b.codes().cutter().unwrap_or(self.state.cutter.mode);
        if comp != CutterCompensation::Cancel {
            return Err(self.error(
                "cutter-path-mode",
                b.code_span(Group::CuttingMode),
                format!(
                    "{} with cutter compensation on: LinuxCNC changes the path control mode only in G40 (rs274: \"Cannot change control mode with cutter radius compensation on\")",
                    mode.gcode()
                ),
            ));
        }
        let value = |a: Address| b.get(a).map(|w| w.value);
        let (p, q) = (value(Address::P), value(Address::Q));
        if mode != CuttingMode::Cutting
            && let Some(w) = b.get(Address::P).or_else(|| b.get(Address::Q))
        {
            return Err(self.error(
                "mode-words",
                w.span,
                format!(
                    "{} takes no {}: only G64 reads P and Q, its tolerances (rs274: \"{} word with no … G64 … to use it\")",
                    mode.gcode(),
                    w.address.letter(),
                    w.address.letter()
                ),
            ));
        }
        let sentence = match mode {
            CuttingMode::ExactPath => {
                "G61 exact path: LinuxCNC's planner follows the programmed path exactly, slowing or stopping at each corner as it must; the path is the one drawn".to_string()
            }
            CuttingMode::ExactStopLinuxcnc => {
                "G61.1 exact stop: LinuxCNC stops the tool at the end of every move; the path is the one drawn".to_string()
            }
            _ => {
                // rs274: a P or Q below 0 is as none; Q left out is P.
                let p = p.filter(|v| *v >= 0.0);
                let q_given = q.filter(|v| *v >= 0.0);
                let p_said = match p {
                    Some(v) => format!("P{v}"),
                    None => "none (the best speed, however far from the corner)".to_string(),
                };
                let q_said = match (q_given, p) {
                    (Some(v), _) => format!("Q{v}"),
                    (None, Some(v)) => format!("Q{v} (P's: no Q of its own)"),
                    (None, None) => "none".to_string(),
                };
                format!(
                    "G64 blending tolerance {p_said}, naive CAM tolerance {q_said}: LinuxCNC's planner may round each corner within the first and merge nearly collinear moves within the second; the path drawn is the programmed one, with its corners, as rs274's canonical moves give it"
                )
            }
        };
        out.notes.push(sentence);
        Ok(())
    }
}
