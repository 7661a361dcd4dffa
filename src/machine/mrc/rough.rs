//! G71/G72 stock removal (types I and II), G73 pattern repeating and G70
//! finishing: the passes each makes along the contour it read (behaviour
//! 15.7–15.9, 15.11).
//!
//! G71 and G72 are worked out in a frame of their own: `q` along the cut
//! (Z for G71, X for G72) growing from the start A toward the contour's end
//! B, and `p` across it (the depth axis) growing from the contour toward A,
//! both in mm with X as a radius. The roughing levels are lines of constant
//! `p` from A down by Δd; at each level the tool cuts where the contour —
//! shifted by the finishing allowance — lies below the level.

use super::super::arc::Circle;
use super::super::{ArcRequest, Machine, MoveKind, Out};
use super::contour::{Contour, Seg};
use super::{MAX_PASSES, Skip};
use crate::diag::Diagnostic;
use crate::geometry::show;
use crate::syntax::codes::Repetitive;
use crate::syntax::{Address, Block};
use std::f64::consts::FRAC_PI_2;

/// Below this (mm) two coordinates are the same.
const EPS: f64 = 1e-7;

/// The cut frame of a G71 (turning) or G72 (facing): see the module.
#[derive(Clone, Copy, Debug)]
struct Frame {
    facing: bool,
    sq: f64,
    sp: f64,
}

impl Frame {
    /// (q, p) of a point given as X diameter and Z.
    fn to(&self, x: f64, z: f64) -> (f64, f64) {
        let r = x / 2.0;
        if self.facing {
            (self.sq * r, self.sp * z)
        } else {
            (self.sq * z, self.sp * r)
        }
    }

    /// X diameter and Z of (q, p).
    fn back(&self, q: f64, p: f64) -> (f64, f64) {
        if self.facing {
            (2.0 * self.sq * q, self.sp * p)
        } else {
            (2.0 * self.sp * p, self.sq * q)
        }
    }
}

/// A piece of the shifted contour, monotonic along both axes of the frame
/// (arcs are split where they turn along an axis).
#[derive(Clone, Copy, Debug)]
struct Piece {
    a: (f64, f64),
    b: (f64, f64),
    /// An arc's circle in (Z, X radius) and the angles of its ends.
    arc: Option<(Circle, f64, f64)>,
}

/// A point of a circle in (Z, X radius), as X diameter and Z.
fn on_circle(c: &Circle, angle: f64) -> (f64, f64) {
    let z = c.center[0] + c.radius * angle.cos();
    let r = c.center[1] + c.radius * angle.sin();
    (2.0 * r, z)
}

/// The contour from `start` through `segs`, shifted by `shift` (X
/// diameter, Z; the start itself is not shifted), as monotonic pieces.
fn pieces(frame: Frame, start: [f64; 2], segs: &[Seg], shift: [f64; 2]) -> Vec<Piece> {
    let mut out = Vec::with_capacity(segs.len() + 4);
    let mut at = start;
    for s in segs.iter().filter(|s| s.dwell.is_none()) {
        let to = [s.to[0] + shift[0], s.to[1] + shift[1]];
        match s.arc {
            None => out.push(Piece {
                a: frame.to(at[0], at[1]),
                b: frame.to(to[0], to[1]),
                arc: None,
            }),
            Some(c) => {
                let c = Circle {
                    center: [c.center[0] + shift[1], c.center[1] + shift[0] / 2.0],
                    ..c
                };
                let (t0, t1) = (c.start_angle, c.start_angle + c.sweep);
                // The quarter points inside the sweep, in its direction.
                let mut cuts = vec![t0];
                let (lo, hi) = (t0.min(t1), t0.max(t1));
                let mut k = (lo / FRAC_PI_2).floor() + 1.0;
                let mut inner = Vec::new();
                while k * FRAC_PI_2 < hi - 1e-12 {
                    inner.push(k * FRAC_PI_2);
                    k += 1.0;
                }
                if c.sweep < 0.0 {
                    inner.reverse();
                }
                cuts.extend(inner);
                cuts.push(t1);
                for w in cuts.windows(2) {
                    let pa = if w[0] == t0 {
                        (at[0], at[1])
                    } else {
                        on_circle(&c, w[0])
                    };
                    let pb = if w[1] == t1 {
                        (to[0], to[1])
                    } else {
                        on_circle(&c, w[1])
                    };
                    out.push(Piece {
                        a: frame.to(pa.0, pa.1),
                        b: frame.to(pb.0, pb.1),
                        arc: Some((c, w[0], w[1])),
                    });
                }
            }
        }
        at = to;
    }
    out
}

/// Where a piece reaches depth `level` (its q), the piece being monotonic
/// and `level` between its ends.
fn cross(frame: Frame, piece: &Piece, level: f64) -> f64 {
    let (qa, pa) = piece.a;
    let (qb, pb) = piece.b;
    match piece.arc {
        None => {
            let t = if (pb - pa).abs() < 1e-15 {
                0.0
            } else {
                (level - pa) / (pb - pa)
            };
            qa + t.clamp(0.0, 1.0) * (qb - qa)
        }
        Some((c, ta, tb)) => {
            let p_at = |t: f64| {
                let (x, z) = on_circle(&c, t);
                frame.to(x, z)
            };
            let (mut lo, mut hi) = (ta, tb);
            let rising = pb > pa;
            for _ in 0..64 {
                let mid = 0.5 * (lo + hi);
                if (p_at(mid).1 < level) == rising {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            p_at(0.5 * (lo + hi)).0
        }
    }
}

/// The stretches of `q` a pass at depth `level` cuts: where the contour is
/// below the level. Each with the index of the piece it starts on.
fn intervals(frame: Frame, pieces: &[Piece], level: f64) -> Vec<(usize, f64, f64)> {
    let threshold = level + EPS;
    let mut out = Vec::new();
    let mut open: Option<(usize, f64)> = None;
    for (i, pc) in pieces.iter().enumerate() {
        let below_a = pc.a.1 < threshold;
        let below_b = pc.b.1 < threshold;
        if open.is_none() && below_a {
            open = Some((i, pc.a.0));
        }
        if below_a && !below_b {
            let (from, a) = open.take().unwrap_or((i, pc.a.0));
            out.push((from, a, cross(frame, pc, threshold)));
        } else if !below_a && below_b {
            open = Some((i, cross(frame, pc, threshold)));
        }
    }
    if let (Some((from, a)), Some(last)) = (open, pieces.last()) {
        out.push((from, a, last.b.0));
    }
    out
}

impl Machine {
    /// `G71 U(Δd) R(e);` / `G72 W(Δd) R(e);`: the depth of cut and the
    /// escape, kept for the cycles after (behaviour 15.4).
    pub(super) fn rough_first_block(
        &mut self,
        b: &Block,
        cycle: Repetitive,
        depth: Address,
        out: &mut Out,
    ) -> Result<(), Diagnostic> {
        if let Some(d) = self.length(b, depth) {
            if d <= 0.0 {
                return Err(self.mrc_error(
                    b,
                    "mrc-value",
                    "PS0062",
                    cycle,
                    format!("the depth of cut {}(Δd) must be positive", depth.letter()),
                ));
            }
            self.mrc.rough_depth = Some(d);
        }
        if let Some(e) = self.length(b, Address::R) {
            if e < 0.0 {
                return Err(self.mrc_error(
                    b,
                    "mrc-value",
                    "PS0062",
                    cycle,
                    "the escape R(e) is not negative".into(),
                ));
            }
            self.mrc.rough_retract = Some(e);
        }
        let units = self.units();
        let say = |v: Option<f64>| v.map_or("unset".to_string(), |v| show(v, units));
        out.notes.push(format!(
            "{}: depth of cut Δd {} and escape e {} kept for the stock removal cycles that follow (behaviour 15.4)",
            self.code_name(cycle),
            say(self.mrc.rough_depth),
            say(self.mrc.rough_retract)
        ));
        Ok(())
    }

    /// The second block of G71/G72, or the one-block form with D
    /// (behaviour 15.7, 15.8).
    pub(super) fn stock_removal(
        &mut self,
        b: &Block,
        cycle: Repetitive,
        p: u32,
        q: u32,
        out: &mut Out,
        program: &mut dyn super::ProgramText,
    ) -> Result<(), Diagnostic> {
        let facing = cycle == Repetitive::FacingStock;
        let depth = match b.has(Address::D) {
            true => self.depth_word(b),
            false => self.mrc.rough_depth,
        };
        let Some(depth) = depth.filter(|d| *d > 0.0) else {
            return Err(self.mrc_error(
                b,
                "mrc-value",
                "PS0062",
                cycle,
                format!(
                    "no positive depth of cut: give it in a first block ({} {}… R…) or with D",
                    self.code_name(cycle),
                    if facing { 'W' } else { 'U' }
                ),
            ));
        };
        let e = self
            .mrc
            .rough_retract
            .unwrap_or_else(|| self.setup.peck_retract_mm());
        let du = self.length(b, Address::U).unwrap_or(0.0);
        let dw = self.length(b, Address::W).unwrap_or(0.0);
        let mut c = self.read_contour(b, cycle, (p, q), program, out)?;
        let type_two = if facing { c.p_x } else { c.p_z };
        let (depth_axis, cut_axis) = if facing { (1, 0) } else { (0, 1) };
        self.trailing_exit(b, cycle, &mut c, cut_axis, out);
        let shape = self.nose_shape(b, cycle, &c, out)?;
        let a = c.start;
        let a1 = c.a_prime();
        let end = c.end();
        let (depth_name, cut_name) = if facing { ('Z', 'X') } else { ('X', 'Z') };
        if (a[depth_axis] - a1[depth_axis]).abs() < EPS {
            return Err(self.mrc_error(
                b,
                "mrc-first-block",
                "PS0065",
                cycle,
                format!(
                    "the contour's first block N{p} must move {depth_name} away from the start: the passes go down toward it"
                ),
            ));
        }
        if (end[cut_axis] - a[cut_axis]).abs() < EPS {
            return Err(self.mrc_error(
                b,
                "mrc-monotonic",
                if facing { "PS0329" } else { "PS0064" },
                cycle,
                format!("the contour N{p}–N{q} does not move along {cut_name}"),
            ));
        }
        let frame = Frame {
            facing,
            sq: super::sign(end[cut_axis] - a[cut_axis]),
            sp: super::sign(a[depth_axis] - a1[depth_axis]),
        };
        self.nose_side(b, cycle, shape.as_ref(), (frame.sq, frame.sp))?;
        // The checks look at the contour as programmed; the passes cut the
        // one shifted by the finishing allowance.
        let programmed = pieces(frame, a, &c.segs, [0.0, 0.0]);
        self.check_shape(b, cycle, &c, &programmed, type_two, (p, q))?;
        // With compensation the passes cut the compensated shape (18.11).
        let cut = shape.as_ref().map_or(&c.segs, |s| &s.segs);
        let pieces = pieces(frame, a, cut, [du, dw]);
        let (q_a, p_a) = frame.to(a[0], a[1]);
        let p_min = pieces
            .iter()
            .flat_map(|pc| [pc.a.1, pc.b.1])
            .fold(p_a, f64::min);
        let steps = ((p_a - p_min) / depth - 1e-9).ceil().max(0.0);
        if steps > MAX_PASSES as f64 {
            return Err(self.passes_error(b, cycle, steps));
        }
        // Δd apart from the start, and (type II) a level at each pocket's
        // bottom too, so that no pocket is left to the finishing pass.
        let mut depths: Vec<f64> = (1..=steps as usize)
            .map(|k| (p_a - k as f64 * depth).max(p_min))
            .collect();
        if type_two {
            depths.extend(pocket_bottoms(&pieces));
            depths.sort_by(|x, y| y.total_cmp(x));
            depths.dedup_by(|x, y| (*x - *y).abs() < 1e-6);
        }
        let levels = depths.len() as f64;
        // Each level looks at every piece of the contour: bound the work as
        // the passes are bounded (behaviour 15.14).
        if levels * pieces.len() as f64 > (MAX_PASSES * 2_000) as f64 {
            return Err(self.error(
                "mrc-passes",
                b.span,
                format!(
                    "{}: {levels} levels over a contour of {} pieces is more than offsetlab works out in one cycle",
                    self.code_name(cycle),
                    pieces.len()
                ),
            ));
        }
        let approach = match c.segs.first() {
            Some(s) if s.rapid => MoveKind::Rapid,
            _ => MoveKind::Feed,
        };
        self.nose_take_off(out);
        self.take_offset();
        let mut at = (q_a, p_a);
        let mut prev = p_a;
        let go = |m: &mut Machine, out: &mut Out, at: &mut (f64, f64), q: f64, p: f64, k| {
            let (x, z) = frame.back(q, p);
            m.cycle_move(out, x, z, k);
            *at = (q, p);
        };
        let mut cuts = 0usize;
        for &level in &depths {
            if self.out_of_moves() {
                break;
            }
            let stretches = intervals(frame, &pieces, level);
            let mut from_start = false;
            for &(first_piece, qa, qb) in &stretches {
                if qb - qa <= EPS && first_piece != 0 {
                    continue;
                }
                if first_piece == 0 {
                    // Down at the start side, as the P block moves (Fanuc:
                    // the infeed is made in the P block's G00 or G01).
                    if (at.0 - q_a).abs() > EPS {
                        let q0 = at.0;
                        go(self, out, &mut at, q0, p_a, MoveKind::Rapid);
                        go(self, out, &mut at, q_a, p_a, MoveKind::Rapid);
                    }
                    go(self, out, &mut at, q_a, level, approach);
                    from_start = true;
                } else {
                    // A pocket (type II): over the top to above it, down
                    // through what the pass before cut, then in at the feed.
                    if at.1 < p_a - EPS {
                        let q0 = at.0;
                        go(self, out, &mut at, q0, p_a, MoveKind::Rapid);
                    }
                    go(self, out, &mut at, qa, p_a, MoveKind::Rapid);
                    go(self, out, &mut at, qa, prev, MoveKind::Rapid);
                    go(self, out, &mut at, qa, level, MoveKind::Feed);
                }
                go(self, out, &mut at, qb, level, MoveKind::Feed);
                // The escape: e back and e up at 45° (Fanuc figure of G71).
                go(self, out, &mut at, qb - e, level + e, MoveKind::Rapid);
                cuts += 1;
            }
            if from_start && stretches.len() == 1 {
                let p0 = at.1;
                go(self, out, &mut at, q_a, p0, MoveKind::Rapid);
            } else if (at.0 - q_a).abs() > EPS {
                let q0 = at.0;
                go(self, out, &mut at, q0, p_a, MoveKind::Rapid);
                go(self, out, &mut at, q_a, p_a, MoveKind::Rapid);
            }
            prev = level;
        }
        // The finishing-allowance contour, then back to A.
        self.contour_pass(b, out, &c.segs, shape.as_ref(), [du, dw], false)?;
        self.cycle_home(out, a);
        let units = self.units();
        out.notes.push(format!(
            "{} type {}: {} cut{} at {} levels Δd {} apart ({}) from {}{} toward {}{}, escape {} at 45° after each; then the contour N{p}–N{q} (lines {}–{}) shifted by the finishing allowance U{} W{}, and back to the start (behaviour 15.7)",
            self.code_name(cycle),
            if type_two { "II" } else { "I" },
            cuts,
            if cuts == 1 { "" } else { "s" },
            levels as usize,
            show(depth, units),
            if facing { "in Z" } else { "a radius value" },
            depth_name,
            show(a[depth_axis], units),
            depth_name,
            show(pick(frame, p_min, depth_axis), units),
            show(e, units),
            c.p_line,
            c.q_line,
            show(du, units),
            show(dw, units),
        ));
        self.after_contour(b, cycle, &c, (p, q), out);
        Ok(())
    }

    /// The G00 blocks that end the contour going back along the cut axis:
    /// with setting `trailing_rapids` = `exit` (Haas) they are the tool's
    /// exit and leave the shape, with a warning (behaviour 7.25).
    fn trailing_exit(
        &self,
        b: &Block,
        cycle: Repetitive,
        c: &mut Contour,
        cut_axis: usize,
        out: &mut Out,
    ) {
        if self.setup.settings.trailing_rapids() != crate::setup::TrailingRapids::Exit {
            return;
        }
        let rapids = c.segs.iter().rev().take_while(|s| s.rapid).count();
        let keep = c.segs.len() - rapids;
        if rapids == 0 || keep == 0 {
            return;
        }
        let last = c.segs[keep - 1].to;
        let forward = super::sign(last[cut_axis] - c.start[cut_axis]);
        let back = c.segs[keep..]
            .iter()
            .scan(last, |at, s| {
                let d = s.to[cut_axis] - at[cut_axis];
                *at = s.to;
                Some(d)
            })
            .any(|d| d * forward < -1e-9 || (forward == 0.0 && d.abs() > 1e-9));
        if !back {
            return;
        }
        c.segs.truncate(keep);
        out.warnings.push(Diagnostic::warning(
            "mrc-exit",
            b.span,
            format!(
                "{}: the G00 block{} ending the contour go{} back toward the start: taken as the tool's exit, not the shape (setting trailing_rapids; Fanuc would stop with PS0064)",
                self.code_name(cycle),
                if rapids == 1 { "" } else { "s" },
                if rapids == 1 { "es" } else { "" },
            ),
        ));
    }

    /// The contour checks of G71/G72 (behaviour 15.6): monotonic along the
    /// cut axis (types I and II) and the depth axis (type I), and nowhere
    /// beyond the start point.
    fn check_shape(
        &self,
        b: &Block,
        cycle: Repetitive,
        c: &Contour,
        pieces: &[Piece],
        type_two: bool,
        (p, q): (u32, u32),
    ) -> Result<(), Diagnostic> {
        let facing = cycle == Repetitive::FacingStock;
        // The plane's first axis is Z, its second X (G18): Fanuc PS0064 and
        // PS0329.
        let (cut_alarm, depth_alarm) = if facing {
            ("PS0329", "PS0064")
        } else {
            ("PS0064", "PS0329")
        };
        let (cut_name, depth_name) = if facing { ('X', 'Z') } else { ('Z', 'X') };
        let rest = pieces.get(1..).unwrap_or(&[]);
        if rest.iter().any(|pc| pc.b.0 < pc.a.0 - EPS) {
            return Err(self.mrc_error(
                b,
                "mrc-monotonic",
                cut_alarm,
                cycle,
                format!(
                    "the contour N{p}–N{q} (lines {}–{}) turns back along {cut_name}: it must only increase or only decrease",
                    c.p_line, c.q_line
                ),
            ));
        }
        if !type_two {
            let up = rest.iter().any(|pc| pc.b.1 > pc.a.1 + EPS);
            let down = rest.iter().any(|pc| pc.b.1 < pc.a.1 - EPS);
            if up && down {
                return Err(self.mrc_error(
                    b,
                    "mrc-monotonic",
                    depth_alarm,
                    cycle,
                    format!(
                        "type I (the P block names {depth_name} only): the contour N{p}–N{q} (lines {}–{}) turns back along {depth_name}; name {cut_name} in the P block too for type II, which cuts pockets",
                        c.p_line, c.q_line
                    ),
                ));
            }
        }
        let p_a = pieces.first().map_or(0.0, |pc| pc.a.1);
        if pieces
            .iter()
            .any(|pc| pc.a.1 > p_a + 1e-6 || pc.b.1 > p_a + 1e-6)
        {
            return Err(self.mrc_error(
                b,
                "mrc-over-start",
                "PS0322",
                cycle,
                format!(
                    "the contour N{p}–N{q} goes beyond the start point along {depth_name}: start the cycle outside the stock"
                ),
            ));
        }
        Ok(())
    }

    /// After G71–G73: the blocks of a contour that follows are passed over
    /// up to N`q` (behaviour 15.5).
    fn after_contour(
        &mut self,
        b: &Block,
        cycle: Repetitive,
        c: &Contour,
        (p, q): (u32, u32),
        out: &mut Out,
    ) {
        if c.p_start > b.span.start {
            self.mrc.skip = Some(Skip {
                cycle,
                line: b.span.line,
                p,
                q,
            });
            out.notes.push(format!(
                "the run goes on after N{q} (line {}): the blocks up to it are not run again",
                c.q_line
            ));
        } else {
            out.notes.push(format!(
                "the contour N{p}–N{q} (lines {}–{}) is before this block: the run goes on with the next block",
                c.p_line, c.q_line
            ));
        }
    }

    fn passes_error(&self, b: &Block, cycle: Repetitive, n: f64) -> Diagnostic {
        self.error(
            "mrc-passes",
            b.span,
            format!(
                "{}: these values make {n} passes; offsetlab makes at most {MAX_PASSES} in one cycle",
                self.code_name(cycle)
            ),
        )
    }

    /// The contour's moves from the current position, shifted by `shift`
    /// (X diameter, Z); `finishing`: G70, which takes the contour's F and S
    /// and makes its dwells (behaviour 15.11).
    pub(super) fn trace(
        &mut self,
        b: &Block,
        out: &mut Out,
        segs: &[Seg],
        shift: [f64; 2],
        finishing: bool,
    ) -> Result<(), Diagnostic> {
        for s in segs {
            if self.out_of_moves() {
                break;
            }
            if !self.contour_segment(out, s, finishing) {
                continue;
            }
            let to = [s.to[0] + shift[0], s.to[1] + shift[1]];
            let Some(c) = s.arc else {
                let kind = if s.rapid {
                    MoveKind::Rapid
                } else {
                    MoveKind::Feed
                };
                self.cycle_move(out, to[0], to[1], kind);
                continue;
            };
            let p0 = self.state.programmed;
            let target = [to[0], 0.0, to[1]];
            let v = self.state.lathe.vector;
            let req = ArcRequest {
                target,
                actual_end: [target[0] + v[0], 0.0, target[2] + v[2]],
                ccw: c.sweep > 0.0,
                center: [
                    c.center[1] + shift[0] / 2.0 - p0[0] / 2.0,
                    0.0,
                    c.center[0] + shift[1] - p0[2],
                ],
                ..ArcRequest::default()
            };
            let info = self.arc_geometry(b, &req)?;
            let start = self.mark();
            self.state.programmed = target;
            let kind = if info.sweep > 0.0 {
                MoveKind::ArcCcw
            } else {
                MoveKind::ArcCw
            };
            self.emit(out, start, kind, true, Some(info));
        }
        Ok(())
    }

    /// G70: the contour as programmed, with its F and S, from the start
    /// and back to it at rapid (behaviour 15.11).
    pub(super) fn finishing(
        &mut self,
        b: &Block,
        p: u32,
        q: u32,
        out: &mut Out,
        program: &mut dyn super::ProgramText,
    ) -> Result<(), Diagnostic> {
        let c = self.read_contour(b, Repetitive::Finishing, (p, q), program, out)?;
        let shape = self.nose_shape(b, Repetitive::Finishing, &c, out)?;
        self.nose_take_off(out);
        self.take_offset();
        self.contour_pass(b, out, &c.segs, shape.as_ref(), [0.0; 2], true)?;
        self.cycle_home(out, c.start);
        let units = self.units();
        out.notes.push(format!(
            "{}: the contour N{p}–N{q} (lines {}–{}) once as programmed, with its own F and S, then back to the start X{} Z{} at rapid; the run goes on after this block (behaviour 15.11)",
            self.code_name(Repetitive::Finishing),
            c.p_line,
            c.q_line,
            show(c.start[0], units),
            show(c.start[1], units)
        ));
        Ok(())
    }

    /// `G73 U(Δi) W(Δk) R(d);` (behaviour 15.4).
    pub(super) fn pattern_first_block(
        &mut self,
        b: &Block,
        out: &mut Out,
    ) -> Result<(), Diagnostic> {
        let (di, dk, d) = self.mrc.pattern.unwrap_or((0.0, 0.0, 0));
        let di = self.length(b, Address::U).unwrap_or(di);
        let dk = self.length(b, Address::W).unwrap_or(dk);
        let d = b.get(Address::R).map_or(d, |w| w.int());
        self.mrc.pattern = Some((di, dk, d));
        let units = self.units();
        out.notes.push(format!(
            "{}: escape Δi {} (X, a radius value) and Δk {} (Z) over {d} divisions, kept for the pattern repeating cycles that follow (behaviour 15.4)",
            self.code_name(Repetitive::PatternRepeat),
            show(di, units),
            show(dk, units)
        ));
        Ok(())
    }

    /// G73 P… Q…: the contour `d` times, shifted from Δi+Δu/2, Δk+Δw down
    /// to the finishing allowance (behaviour 15.9).
    pub(super) fn pattern_repeat(
        &mut self,
        b: &Block,
        p: u32,
        q: u32,
        out: &mut Out,
        program: &mut dyn super::ProgramText,
    ) -> Result<(), Diagnostic> {
        let cycle = Repetitive::PatternRepeat;
        let (mut di, mut dk, mut d) = self.mrc.pattern.unwrap_or((0.0, 0.0, 0));
        if let Some(i) = self.length(b, Address::I) {
            di = i;
        }
        if let Some(k) = self.length(b, Address::K) {
            dk = k;
        }
        if let Some(w) = b.get(Address::D) {
            d = w.int();
        }
        if d == 0 {
            return Err(self.mrc_error(
                b,
                "mrc-value",
                "PS0062",
                cycle,
                "the number of divisions is 0: give it as R in a first block (G73 U… W… R…) or as D".into(),
            ));
        }
        if d as usize > MAX_PASSES {
            return Err(self.passes_error(b, cycle, f64::from(d)));
        }
        let du = self.length(b, Address::U).unwrap_or(0.0);
        let dw = self.length(b, Address::W).unwrap_or(0.0);
        let c = self.read_contour(b, cycle, (p, q), program, out)?;
        let shape = self.nose_shape(b, cycle, &c, out)?;
        self.nose_take_off(out);
        self.take_offset();
        for k in 1..=d {
            if self.out_of_moves() {
                break;
            }
            let f = if d == 1 {
                0.0
            } else {
                f64::from(d - k) / f64::from(d - 1)
            };
            let shift = [du + 2.0 * di * f, dw + dk * f];
            self.contour_pass(b, out, &c.segs, shape.as_ref(), shift, false)?;
            self.cycle_home(out, c.start);
        }
        let units = self.units();
        out.notes.push(format!(
            "{}: the contour N{p}–N{q} (lines {}–{}) {d} times, shifted first by X {} Z {} and last by the finishing allowance U{} W{}, back to the start after each (behaviour 15.9)",
            self.code_name(cycle),
            c.p_line,
            c.q_line,
            show(du + 2.0 * di, units),
            show(dw + dk, units),
            show(du, units),
            show(dw, units)
        ));
        self.after_contour(b, cycle, &c, (p, q), out);
        Ok(())
    }
}

/// The depths of the contour's pockets' bottoms: where it stops going down
/// and goes up again (flat stretches between count as the bottom).
fn pocket_bottoms(pieces: &[Piece]) -> Vec<f64> {
    let mut out = Vec::new();
    let mut going_down = false;
    for pc in pieces.iter().skip(1) {
        let dp = pc.b.1 - pc.a.1;
        if dp < -EPS {
            going_down = true;
        } else if dp > EPS {
            if going_down {
                out.push(pc.a.1);
            }
            going_down = false;
        }
    }
    out
}

/// The depth axis value (X diameter or Z) of the deepest level.
fn pick(frame: Frame, p: f64, depth_axis: usize) -> f64 {
    let (x, z) = frame.back(0.0, p);
    if depth_axis == 0 { x } else { z }
}
