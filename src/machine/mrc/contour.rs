//! The contour of a G70–G73: the blocks from sequence number P to Q, read
//! again from the program text (behaviour 15.3) and checked as the control
//! checks them (behaviour 15.6).

use super::super::arc::{self, Circle};
use super::super::modal::{ArcDirection, Distance, Motion};
use super::super::program::ProgramText;
use super::Machine;
use crate::diag::Diagnostic;
use crate::syntax::codes::{CutterCompensation, MCode, NonModal, Repetitive};
use crate::syntax::{Address, Block};

/// Most blocks one contour may have (bounds the memory a cycle takes).
pub(super) const MAX_CONTOUR_BLOCKS: usize = 10_000;

/// One piece of the contour: a straight move or an arc to `to`.
#[derive(Clone, Copy, Debug)]
pub(super) struct Seg {
    /// End point: X diameter and Z, programmed, mm.
    pub to: [f64; 2],
    /// For an arc: its circle in the ZX plane's (Z, X radius) coordinates.
    pub arc: Option<Circle>,
    /// Made at rapid (a G00 block of the contour).
    pub rapid: bool,
    /// The feed and spindle speed in effect for it (G70 uses them).
    pub feed: Option<f64>,
    pub spindle: Option<f64>,
    /// A G04 block of the contour: its dwell (seconds), no motion.
    pub dwell: Option<f64>,
    /// The group 07 code (G40, G41, G42) the block writes: tool nose
    /// radius compensation in the cycle (behaviour 18.11).
    pub nose: Option<CutterCompensation>,
}

/// A contour read from the program.
#[derive(Clone, Debug)]
pub(super) struct Contour {
    /// Where the cycle starts: X diameter and Z (the tool's programmed
    /// position before the cycle, point A).
    pub start: [f64; 2],
    /// The P block's move first (A to A'), then the others to B.
    pub segs: Vec<Seg>,
    /// The P block names X (or U), and Z (or W).
    pub p_x: bool,
    pub p_z: bool,
    /// Byte offset of the P block and line of the P and Q blocks.
    pub p_start: u32,
    pub p_line: u32,
    pub q_line: u32,
}

impl Contour {
    /// A' (the P block's end) and B (the Q block's end).
    pub fn a_prime(&self) -> [f64; 2] {
        self.segs.first().map_or(self.start, |s| s.to)
    }

    pub fn end(&self) -> [f64; 2] {
        self.segs.last().map_or(self.start, |s| s.to)
    }
}

impl Machine {
    /// Reads the contour N`p`…N`q` of the cycle in block `b` (behaviour
    /// 15.3, 15.6), starting from the tool's programmed position.
    pub(super) fn read_contour(
        &self,
        b: &Block,
        cycle: Repetitive,
        (p, q): (u32, u32),
        program: &mut dyn ProgramText,
        out: &mut super::Out,
    ) -> Result<Contour, Diagnostic> {
        let mut blocks: Vec<Block> = Vec::new();
        let mut too_long = false;
        let mut reached_q = false;
        let found = program.read_from(p, &mut |blk| {
            if blocks.len() >= MAX_CONTOUR_BLOCKS {
                too_long = true;
                return false;
            }
            blocks.push(blk.clone());
            reached_q = blk.get(Address::N).is_some_and(|w| w.int() == q);
            !reached_q
        });
        // The search reads the text from its start: the cycle depends on
        // all of it up to the contour's end (or all of it, when the
        // contour is not found).
        out.reads = Some(match (reached_q, blocks.last()) {
            (true, Some(last)) => last.span.end,
            _ => u32::MAX,
        });
        let Some(p_start) = found else {
            return Err(self.mrc_error(
                b,
                "mrc-sequence",
                "PS0063",
                cycle,
                format!("no block has the sequence number P{p}"),
            ));
        };
        if too_long {
            return Err(self.mrc_error(
                b,
                "mrc-sequence",
                "PS0063",
                cycle,
                format!(
                    "the contour from N{p} has more than {MAX_CONTOUR_BLOCKS} blocks before N{q} (offsetlab reads at most that many)"
                ),
            ));
        }
        if !reached_q {
            return Err(self.mrc_error(
                b,
                "mrc-sequence",
                "PS0063",
                cycle,
                format!("no block after N{p} has the sequence number Q{q}"),
            ));
        }
        let start = [self.state.programmed[0], self.state.programmed[2]];
        let mut c = Contour {
            start,
            segs: Vec::with_capacity(blocks.len()),
            p_x: false,
            p_z: false,
            p_start,
            p_line: blocks[0].span.line,
            q_line: blocks[blocks.len() - 1].span.line,
        };
        let mut motion = self.state.modal.motion;
        let mut distance = self.state.modal.distance;
        let mut at = start;
        let mut feed = self.state.feed;
        let mut spindle = self.state.spindle;
        let mut nose = None;
        for (i, blk) in blocks.iter().enumerate() {
            let skipped = blk.skip && self.setup.settings.block_skip;
            if skipped && i != 0 {
                continue;
            }
            let line = blk.span.line;
            if blk.error {
                return Err(self.mrc_error(
                    b,
                    "mrc-shape",
                    "PS0325",
                    cycle,
                    format!("the contour block at line {line} has an error (see its diagnostic)"),
                ));
            }
            self.contour_codes(b, blk, cycle)?;
            self.refuse_unmodelled(blk)?;
            let codes = blk.codes();
            if i == 0 && !matches!(codes.motion(), Some(Motion::Rapid | Motion::Linear)) {
                return Err(self.mrc_error(
                    b,
                    "mrc-first-block",
                    "PS0065",
                    cycle,
                    format!("the contour's first block N{p} (line {line}) must command G00 or G01"),
                ));
            }
            if let Some(m) = codes.motion() {
                motion = m;
            }
            if let Some(f) = blk.value(Address::F) {
                feed = Some(f);
            }
            if let Some(s) = blk.value(Address::S) {
                spindle = Some(s);
            }
            if codes.non_modal() == Some(NonModal::Dwell) {
                let seconds = match (blk.value(Address::P), blk.value(Address::U)) {
                    (Some(ms), _) => ms / 1000.0,
                    (None, Some(s)) => s,
                    (None, None) => blk.value(Address::X).unwrap_or(0.0),
                };
                c.segs.push(Seg {
                    to: at,
                    arc: None,
                    rapid: true,
                    feed,
                    spindle,
                    dwell: Some(seconds),
                    nose: codes.cutter(),
                });
                continue;
            }
            // X and Z absolute (incremental after G91 in G-code systems B
            // and C, behaviour 7.18), U and W incremental.
            if let Some(d) = codes.distance() {
                distance = d;
            }
            let mut to = at;
            for (i, abs, inc) in [(0, Address::X, Address::U), (1, Address::Z, Address::W)] {
                to[i] = match (blk.get(abs), blk.get(inc)) {
                    (Some(_), Some(w)) => {
                        return Err(self.mrc_error(
                            b,
                            "mrc-shape",
                            "PS0325",
                            cycle,
                            format!(
                                "the contour block at line {line} has {} and {} together (axis-conflict)",
                                abs.letter(),
                                w.address.letter()
                            ),
                        ));
                    }
                    (Some(v), None) if distance == Distance::Incremental => {
                        at[i] + self.mm(v.value)
                    }
                    (Some(v), None) => self.mm(v.value),
                    (None, Some(d)) => at[i] + self.mm(d.value),
                    (None, None) => at[i],
                };
            }
            if i == 0 {
                c.p_x = blk.has(Address::X) || blk.has(Address::U);
                c.p_z = blk.has(Address::Z) || blk.has(Address::W);
            }
            let arc_words = [Address::R, Address::I, Address::K]
                .iter()
                .any(|a| blk.has(*a));
            if to == at && !arc_words {
                // G40/G41/G42 alone act with the next move (behaviour 18.4).
                nose = codes.cutter().or(nose);
                continue;
            }
            let arc = match motion {
                Motion::Arc(dir) => Some(self.contour_arc(b, blk, cycle, at, to, dir)?),
                Motion::Rapid | Motion::Linear | Motion::LatheCycle(_) => None,
            };
            c.segs.push(Seg {
                to,
                arc,
                rapid: motion == Motion::Rapid,
                feed,
                spindle,
                dwell: None,
                nose: codes.cutter().or(nose.take()),
            });
            at = to;
        }
        Ok(c)
    }

    /// The codes a contour block may not hold (Fanuc, "Restrictions" of the
    /// multiple repetitive cycles: one-shot codes but G04, group 01 codes
    /// but G00–G03, inch/metric, M98/M99; our convention: no work system
    /// change, no T code and no cycle inside the contour).
    fn contour_codes(&self, b: &Block, blk: &Block, cycle: Repetitive) -> Result<(), Diagnostic> {
        let line = blk.span.line;
        let refuse = |what: String| {
            self.mrc_error(
                b,
                "mrc-shape",
                "PS0325",
                cycle,
                format!(
                    "the contour block at line {line} has {what}, which a contour may not hold"
                ),
            )
        };
        let codes = blk.codes();
        match codes.non_modal() {
            None | Some(NonModal::Dwell) => {}
            Some(other) => return Err(refuse(other.gcode(self.setup.machine).to_string())),
        }
        if let Some(Motion::LatheCycle(_)) = codes.motion() {
            let m = codes.motion().map_or("", |m| m.gcode());
            return Err(refuse(m.to_string()));
        }
        if let Some(u) = codes.units() {
            return Err(refuse(u.gcode().to_string()));
        }
        // Fanuc wants G40–G42 before the cycle, not in the shape program
        // (PS0325); Haas starts and ends the compensation in the contour
        // (behaviour 7.34, 18.11).
        if let Some(c) = codes.cutter()
            && self.setup.settings.nose_in_contour() == crate::setup::NoseInContour::BeforeCycle
        {
            return Err(self.error(
                "nose-in-cycle",
                blk.code_span(crate::syntax::codes::Group::Cutter),
                format!(
                    "{}: the contour block at line {line} of the {} writes tool nose radius compensation, which goes before the cycle on this control (Fanuc alarm PS0325; setting nose_in_contour)",
                    c.gcode(),
                    self.code_name(cycle)
                ),
            ));
        }
        if let Some(w) = codes.work() {
            return Err(refuse(w.gcode().to_string()));
        }
        if blk.has(Address::T) {
            return Err(refuse(
                "a T code (a tool change inside a contour is not modelled)".into(),
            ));
        }
        for m in blk.mcodes(self.setup.machine) {
            match m {
                MCode::SubprogramCall | MCode::SubprogramReturn | MCode::LocalSubprogramCall => {
                    return Err(refuse(format!("M{:02}", m.number())));
                }
                _ => {}
            }
        }
        Ok(())
    }

    /// The circle of a contour arc from `at` to `to` (X diameter, Z), in
    /// (Z, X radius) coordinates (behaviour 2.12 and 5.11).
    fn contour_arc(
        &self,
        b: &Block,
        blk: &Block,
        cycle: Repetitive,
        at: [f64; 2],
        to: [f64; 2],
        dir: ArcDirection,
    ) -> Result<Circle, Diagnostic> {
        let ccw = dir == ArcDirection::Ccw;
        let tol = self.arc_tolerance();
        let p0 = [at[1], at[0] / 2.0];
        let p1 = [to[1], to[0] / 2.0];
        let circle = match blk.value(Address::R) {
            Some(r) => arc::from_radius(p0, p1, self.mm(r), ccw, tol),
            None => {
                let i = self.mm(blk.value(Address::I).unwrap_or(0.0));
                let k = self.mm(blk.value(Address::K).unwrap_or(0.0));
                arc::from_center(p0, p1, [p0[0] + k, p0[1] + i], ccw, tol)
            }
        };
        circle.map_err(|_| {
            self.mrc_error(
                b,
                "arc-radius",
                "PS0325",
                cycle,
                format!(
                    "the contour's arc at line {} has no circle through its start and end",
                    blk.span.line
                ),
            )
        })
    }
}
