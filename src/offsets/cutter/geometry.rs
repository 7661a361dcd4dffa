//! The plane geometry of cutter radius compensation C (behaviour 16): a
//! block's programmed path in the compensation plane, its offset path (a
//! line moved sideways, or a circle about the same centre with the radius
//! grown or shrunk), the intersection of two offset paths, and the points
//! the tool centre passes through at the junction of two blocks — the
//! *corner* — by the Fanuc rules: the intersection at an inside corner and
//! at an outside corner of 90° or more, the extra vectors at an outside
//! corner under 90°, the start-up and cancel types A and B, a change of
//! side. Pure functions of points: no machine, no units.
//!
//! Offsets are signed: `o` > 0 puts the tool centre left of the path (G41
//! with a positive register), `o` < 0 right of it (G42, or G41 with a
//! negative register), seen from the positive side of the plane's normal.

/// A point or a vector in the compensation plane: (first axis, second axis)
/// of G17 (X, Y), G18 (Z, X) or G19 (Y, Z).
pub type P2 = [f64; 2];

/// Turns smaller than this (radians) are no corner: the two paths meet
/// tangentially and the tool centre stands at the offset of the common
/// point (the error of taking it so is below a micrometre for any radius a
/// register holds).
pub const TANGENT: f64 = 1e-6;

/// A turn's cosine within this of 0 is a turn of 90° (α = 90°, an outside
/// corner of 16.6): a right angle written in words and worked out through
/// a unit vector or an arc's centre comes out a hair either side.
const RIGHT_ANGLE: f64 = 1e-12;

/// How far (mm) two offset paths may miss each other and still be taken
/// as touching (a tangent line and circle computed from rounded words).
const TOUCH: f64 = 1e-7;

/// A turn whose sine is under this (about 1.1°) is taken as tangent when
/// the offset paths do not meet: two arcs of an S-curve written with four
/// decimals meet at a tangent the words only round off, and their offset
/// circles may then miss by a hair; the tool goes on at the common point's
/// offset rather than stop at an alarm (our convention).
const NEAR_TANGENT: f64 = 0.02;

fn add(a: P2, b: P2) -> P2 {
    [a[0] + b[0], a[1] + b[1]]
}

fn sub(a: P2, b: P2) -> P2 {
    [a[0] - b[0], a[1] - b[1]]
}

fn mul(a: P2, k: f64) -> P2 {
    [a[0] * k, a[1] * k]
}

fn dot(a: P2, b: P2) -> f64 {
    a[0] * b[0] + a[1] * b[1]
}

fn cross(a: P2, b: P2) -> f64 {
    a[0] * b[1] - a[1] * b[0]
}

fn len(a: P2) -> f64 {
    // Not `hypot`: its care for overflow costs more than the corner at
    // every block, and lengths here are within 10⁹ mm (behaviour 2.23).
    (a[0] * a[0] + a[1] * a[1]).sqrt()
}

/// The distance between two points.
pub fn dist(a: P2, b: P2) -> f64 {
    len(sub(a, b))
}

/// `a` scaled to length 1 (a zero vector stays zero).
pub fn unit(a: P2) -> P2 {
    let l = len(a);
    if l > 0.0 { mul(a, 1.0 / l) } else { [0.0, 0.0] }
}

/// The unit vector 90° counter-clockwise from `t`: left of a path going
/// along `t`.
pub fn left(t: P2) -> P2 {
    [-t[1], t[0]]
}

/// One block's programmed path in the compensation plane.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Path {
    /// A straight move (G00, G01; also the direction of I/J/K in a G41/G42
    /// block without a move, as a line from its point along that
    /// direction).
    Line {
        /// Start point.
        from: P2,
        /// End point.
        to: P2,
    },
    /// A G02/G03 arc.
    Arc {
        /// Start point.
        from: P2,
        /// End point (the start for a full circle).
        to: P2,
        /// Centre.
        center: P2,
        /// Counter-clockwise (G03 seen from the normal's positive side).
        ccw: bool,
    },
}

impl Path {
    /// Where the path starts.
    pub fn start(&self) -> P2 {
        match *self {
            Path::Line { from, .. } | Path::Arc { from, .. } => from,
        }
    }

    /// Where the path ends.
    pub fn end(&self) -> P2 {
        match *self {
            Path::Line { to, .. } | Path::Arc { to, .. } => to,
        }
    }

    /// The unit direction of travel at `p`, a point of the path.
    fn tangent_at(&self, p: P2) -> P2 {
        match *self {
            Path::Line { from, to } => unit(sub(to, from)),
            Path::Arc { center, ccw, .. } => {
                let r = unit(sub(p, center));
                if ccw { left(r) } else { mul(left(r), -1.0) }
            }
        }
    }

    /// The direction of travel where the path starts.
    pub fn start_tangent(&self) -> P2 {
        self.tangent_at(self.start())
    }

    /// The direction of travel where the path ends.
    pub fn end_tangent(&self) -> P2 {
        self.tangent_at(self.end())
    }

    /// True for an arc.
    pub fn is_arc(&self) -> bool {
        matches!(self, Path::Arc { .. })
    }

    /// "line" or "arc", for the sentences.
    pub fn noun(&self) -> &'static str {
        if self.is_arc() { "arc" } else { "line" }
    }

    /// The radius of the offset circle of an arc: the programmed radius
    /// less the offset where the tool is inside the arc (left of a G03),
    /// plus it outside. Zero or less when the tool does not fit inside
    /// (behaviour 16: interference, Fanuc PS0041/PS0038). None for a line.
    pub fn offset_radius(&self, o: f64) -> Option<f64> {
        match *self {
            Path::Line { .. } => None,
            Path::Arc {
                from, center, ccw, ..
            } => {
                let r = dist(from, center);
                Some(if ccw { r - o } else { r + o })
            }
        }
    }

    /// The offset path `o` to the left; `t` is the path's direction where
    /// it is offset (a line's only one).
    fn offset(&self, o: f64, t: P2) -> Offset {
        match *self {
            Path::Line { from, .. } => Offset::Line {
                point: add(from, mul(left(t), o)),
                dir: t,
            },
            Path::Arc { center, .. } => Offset::Circle {
                center,
                radius: self.offset_radius(o).unwrap_or(0.0).abs(),
            },
        }
    }
}

/// An offset path as a whole line or circle (the intersection of two
/// may lie on their extensions).
#[derive(Clone, Copy, Debug)]
enum Offset {
    Line { point: P2, dir: P2 },
    Circle { center: P2, radius: f64 },
}

/// Up to two points (no allocation: a corner is made at every block).
#[derive(Clone, Copy, Debug, Default)]
struct Points {
    p: [P2; 2],
    n: usize,
}

impl Points {
    fn of(points: &[P2]) -> Points {
        let mut out = Points::default();
        for (slot, p) in out.p.iter_mut().zip(points) {
            *slot = *p;
        }
        out.n = points.len().min(2);
        out
    }

    fn iter(&self) -> impl Iterator<Item = P2> + '_ {
        self.p[..self.n].iter().copied()
    }
}

/// The points where two offset paths meet (none, one or two).
#[inline(always)]
fn crossings(a: Offset, b: Offset) -> Points {
    match (a, b) {
        (Offset::Line { point: p, dir: d }, Offset::Line { point: q, dir: e }) => {
            let c = cross(d, e);
            if c.abs() < 1e-12 {
                return Points::default();
            }
            let s = cross(sub(q, p), e) / c;
            Points::of(&[add(p, mul(d, s))])
        }
        (Offset::Line { point, dir }, Offset::Circle { center, radius })
        | (Offset::Circle { center, radius }, Offset::Line { point, dir }) => {
            // The foot of the centre on the line, and half the chord.
            let s = dot(sub(center, point), dir);
            let foot = add(point, mul(dir, s));
            let h = dist(foot, center);
            if h > radius + TOUCH {
                return Points::default();
            }
            let half = (radius * radius - h * h).max(0.0).sqrt();
            if half < TOUCH {
                return Points::of(&[foot]);
            }
            Points::of(&[add(foot, mul(dir, -half)), add(foot, mul(dir, half))])
        }
        (
            Offset::Circle {
                center: c1,
                radius: r1,
            },
            Offset::Circle {
                center: c2,
                radius: r2,
            },
        ) => {
            let d = dist(c1, c2);
            if d < 1e-12 || d > r1 + r2 + TOUCH || d < (r1 - r2).abs() - TOUCH {
                return Points::default();
            }
            let a = (r1 * r1 - r2 * r2 + d * d) / (2.0 * d);
            let h = (r1 * r1 - a * a).max(0.0).sqrt();
            let u = unit(sub(c2, c1));
            let m = add(c1, mul(u, a));
            if h < TOUCH {
                return Points::of(&[m]);
            }
            Points::of(&[add(m, mul(left(u), h)), add(m, mul(left(u), -h))])
        }
    }
}

/// The crossing of two offset paths nearest to `near`.
#[inline]
fn crossing_near(a: Offset, b: Offset, near: P2) -> Option<P2> {
    crossings(a, b)
        .iter()
        .min_by(|p, q| dist(*p, near).total_cmp(&dist(*q, near)))
}

/// Start-up and cancel types (Fanuc parameter SUP, No. 5003#0).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Type {
    /// Type A: the vector at the start-up block's end is perpendicular to
    /// the next block (at a cancel: at the end of the block before the
    /// cancel, perpendicular to it).
    A,
    /// Type B: the corner is compensated on both sides: the intersection,
    /// or at an outside corner under 90° a vector perpendicular to each
    /// block.
    B,
}

/// What the tool does at an outside corner in offset mode.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Outside {
    /// Fanuc: the intersection at 90° or more, the extra vectors under 90°.
    Vectors,
    /// An arc of the compensation radius about the corner (as G39 makes
    /// one; Haas setting 58 = YASNAC).
    Arc,
}

/// Which rule makes the corner between two blocks.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rule {
    /// Both blocks in offset mode.
    Offset(Outside),
    /// The first block starts compensation up.
    StartUp(Type),
    /// The second block cancels compensation.
    Cancel(Type),
    /// The corner is not known (no move in the plane follows within the
    /// blocks the control reads, the program ends, a G39 or a return
    /// follows): the vector is perpendicular to the first block at its end.
    Perpendicular,
}

/// What kind of corner the tool went around, for the sentence.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// The paths meet tangentially (or go straight on).
    Tangent,
    /// An inside corner: the intersection of the offset paths.
    Inside,
    /// An outside corner of 90° or more: the intersection.
    Obtuse,
    /// An outside corner under 90°: the extra vectors (or, with type B at a
    /// start-up or cancel, a vector perpendicular to each block).
    Acute,
    /// An outside corner gone around on an arc about it.
    Rounded,
    /// The vector perpendicular to the first block at its end.
    Perpendicular,
    /// Type A start-up: the vector perpendicular to the next block at its
    /// start.
    NextPerpendicular,
    /// A change of side (G41↔G42): the intersection of the two offsets.
    SideChange,
    /// A change of side whose offsets do not meet: a vector on each side.
    SideChangeApart,
}

/// One piece of the tool centre's way through a corner.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Step {
    /// A straight move to this point.
    Line(P2),
    /// An arc about `center` to `to`.
    Arc {
        /// End point.
        to: P2,
        /// Centre (the corner).
        center: P2,
        /// Counter-clockwise.
        ccw: bool,
    },
}

impl Step {
    /// Where the step ends.
    pub fn end(&self) -> P2 {
        match *self {
            Step::Line(p) | Step::Arc { to: p, .. } => p,
        }
    }
}

/// The tool centre's way through the junction of two blocks: the first
/// step ends the first block's own move (on its offset path), the others
/// are moves the first block adds; the last ends where the second block's
/// move starts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Corner {
    /// The steps (no allocation: a corner is made at every block).
    steps: [Step; 4],
    /// How many of them there are, one to four.
    count: u8,
    /// What kind of corner it is.
    pub kind: Kind,
    /// The sine and cosine of the path's turn and whether it turns toward
    /// the tool: the corner's angle is worked out when a sentence asks.
    turn: (f64, f64, bool),
}

impl Corner {
    /// The steps, one to four.
    pub fn steps(&self) -> &[Step] {
        &self.steps[..usize::from(self.count)]
    }

    /// The angle of the corner on the workpiece side (degrees, as the
    /// manual's α: 180 on a straight or tangent path, under 180 outside,
    /// over 180 inside).
    pub fn alpha(&self) -> f64 {
        let (sin, cos, inside) = self.turn;
        let turn = sin.atan2(cos).abs().to_degrees();
        if inside { 180.0 + turn } else { 180.0 - turn }
    }

    /// True when the path turns by more than 90° (an outside corner's α
    /// under 90°): an acute corner that is not so took the extra vectors
    /// because the offset paths do not meet (behaviour 16.7).
    pub fn under_90(&self) -> bool {
        self.turn.1 < -RIGHT_ANGLE
    }

    /// Where the tool centre stands after the corner.
    pub fn end(&self) -> P2 {
        self.steps().last().map_or([0.0, 0.0], Step::end)
    }

    fn new(kind: Kind, turn: (f64, f64, bool), steps: &[Step]) -> Corner {
        let mut all = [Step::Line([0.0, 0.0]); 4];
        for (slot, s) in all.iter_mut().zip(steps) {
            *slot = *s;
        }
        Corner {
            steps: all,
            count: steps.len().min(4) as u8,
            kind,
            turn,
        }
    }

    #[inline(always)]
    fn points(kind: Kind, alpha: (f64, f64, bool), points: &[P2]) -> Corner {
        // Written in place (a corner is made at every block in offset mode).
        let mut c = Corner {
            steps: [Step::Line([0.0, 0.0]); 4],
            count: points.len().min(4) as u8,
            kind,
            turn: alpha,
        };
        for (slot, p) in c.steps.iter_mut().zip(points) {
            *slot = Step::Line(*p);
        }
        c
    }
}

/// No intersection where the rule needs one (Fanuc PS0033).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NoIntersection;

/// The corner between `prev` and `next` (`next` starting where `prev`
/// ends), `o1` the offset of `prev` and `o2` the offset `next` asks for
/// (different signs: a change of side), by `rule` (behaviour 16.4–16.11).
#[inline]
pub fn corner(
    prev: &Path,
    next: &Path,
    o1: f64,
    o2: f64,
    rule: Rule,
) -> Result<Corner, NoIntersection> {
    // Two straight moves on the same side in offset mode (most corners of
    // a contour): the same arithmetic as the general rule below, written
    // for lines alone (the `check` instruction count with G41,
    // docs/performance.md; `tests/cutter_props.rs` holds the two equal).
    if let (
        Path::Line { from, to },
        Path::Line { from: q, to: end },
        Rule::Offset(Outside::Vectors),
    ) = (*prev, *next, rule)
        && o1 * o2 > 0.0
    {
        return lines_corner(from, to, q, end, o1);
    }
    general_corner(prev, next, o1, o2, rule)
}

/// [`corner`] between two lines in offset mode on the same side, `o` the
/// offset: the first line from `f1` to `p`, the second from `q` to `e2`.
/// Bit for bit what [`general_corner`] gives them.
#[inline(always)]
fn lines_corner(f1: P2, p: P2, q: P2, e2: P2, o: f64) -> Result<Corner, NoIntersection> {
    let t1 = unit(sub(p, f1));
    let t2 = unit(sub(e2, q));
    let n1 = left(t1);
    let n2 = left(t2);
    let (sin, cos) = (cross(t1, t2), dot(t1, t2));
    let inside = o * sin > 0.0;
    let alpha = (sin, cos, inside);
    let end1 = add(p, mul(n1, o));
    if cos > 0.0 && sin.abs() < TANGENT {
        return Ok(Corner::points(Kind::Tangent, alpha, &[end1]));
    }
    let near_tangent = cos > 0.0 && sin.abs() < NEAR_TANGENT;
    // The crossing of the two offset lines, each through its start point
    // moved by the offset.
    let meet = || {
        if sin.abs() < 1e-12 {
            return near_tangent.then_some(end1);
        }
        let a = add(f1, mul(n1, o));
        let b = add(q, mul(n2, o));
        let s = cross(sub(b, a), t2) / sin;
        Some(add(a, mul(t1, s)))
    };
    if inside {
        let x = meet().ok_or(NoIntersection)?;
        return Ok(Corner::points(Kind::Inside, alpha, &[x]));
    }
    if cos >= -RIGHT_ANGLE
        && let Some(x) = meet()
    {
        return Ok(Corner::points(Kind::Obtuse, alpha, &[x]));
    }
    let start2 = add(q, mul(n2, o));
    let r = o.abs();
    let v2 = add(end1, mul(t1, r));
    let v3 = add(start2, mul(t2, -r));
    Ok(Corner::points(Kind::Acute, alpha, &[v2, v3]))
}

/// [`corner`] by the general rule, for any two paths.
#[doc(hidden)]
pub fn general_corner(
    prev: &Path,
    next: &Path,
    o1: f64,
    o2: f64,
    rule: Rule,
) -> Result<Corner, NoIntersection> {
    let p = prev.end();
    let q = next.start();
    let t1 = prev.end_tangent();
    let t2 = next.start_tangent();
    let n1 = left(t1);
    let n2 = left(t2);
    // The path turns by the angle whose sine and cosine these are (no
    // `atan2` at every block: the corner's angle is worked out only for a
    // sentence).
    let (sin, cos) = (cross(t1, t2), dot(t1, t2));
    let o = o1;
    let inside = o * sin > 0.0;
    let alpha = (sin, cos, inside);
    let end1 = add(p, mul(n1, o));
    let start2 = add(q, mul(n2, o));
    let near = mul(add(end1, start2), 0.5);
    let near_tangent = cos > 0.0 && sin.abs() < NEAR_TANGENT;
    let meet = |o2: f64| {
        crossing_near(prev.offset(o, t1), next.offset(o2, t2), near)
            .or_else(|| near_tangent.then_some(end1))
    };
    let tangent = cos > 0.0 && sin.abs() < TANGENT;
    // 90° of turn or less: an obtuse corner (α of 90° or more).
    let obtuse = cos >= -RIGHT_ANGLE;
    match rule {
        Rule::Perpendicular => Ok(Corner::points(Kind::Perpendicular, alpha, &[end1])),
        Rule::StartUp(Type::A) => Ok(Corner::points(Kind::NextPerpendicular, alpha, &[start2])),
        Rule::StartUp(Type::B) | Rule::Cancel(Type::B) => {
            if tangent {
                return Ok(Corner::points(Kind::Tangent, alpha, &[end1]));
            }
            if inside || obtuse {
                let kind = if inside { Kind::Inside } else { Kind::Obtuse };
                let x = meet(o).ok_or(NoIntersection)?;
                return Ok(Corner::points(kind, alpha, &[x]));
            }
            Ok(Corner::points(Kind::Acute, alpha, &[end1, start2]))
        }
        Rule::Cancel(Type::A) => Ok(Corner::points(Kind::Perpendicular, alpha, &[end1])),
        Rule::Offset(outside) => {
            if o1 * o2 < 0.0 {
                // A change of side: no inside or outside, the intersection
                // of the two offsets, or a vector on each side.
                let start2 = add(q, mul(n2, o2));
                let near = mul(add(end1, start2), 0.5);
                return Ok(
                    match crossing_near(prev.offset(o1, t1), next.offset(o2, t2), near) {
                        Some(x) => Corner::points(Kind::SideChange, alpha, &[x]),
                        None => Corner::points(Kind::SideChangeApart, alpha, &[end1, start2]),
                    },
                );
            }
            if tangent {
                return Ok(Corner::points(Kind::Tangent, alpha, &[end1]));
            }
            if inside {
                let x = meet(o).ok_or(NoIntersection)?;
                return Ok(Corner::points(Kind::Inside, alpha, &[x]));
            }
            if outside == Outside::Arc {
                // About the corner, the way the tool side turns: clockwise
                // with the tool on the left.
                let arc = Step::Arc {
                    to: start2,
                    center: p,
                    ccw: o < 0.0,
                };
                let steps = [Step::Line(end1), arc];
                let n = if dist(end1, start2) > TOUCH { 2 } else { 1 };
                return Ok(Corner::new(Kind::Rounded, alpha, &steps[..n]));
            }
            if obtuse && let Some(x) = meet(o) {
                return Ok(Corner::points(Kind::Obtuse, alpha, &[x]));
            }
            // Under 90° (or offset arcs that do not meet): the vector of
            // the first block at its end stretched by the radius along its
            // direction, and the second block's pulled back along its own,
            // so the tool stays the radius off the corner point.
            let r = o.abs();
            let v2 = add(end1, mul(t1, r));
            let v3 = add(start2, mul(t2, -r));
            let first = if prev.is_arc() { 0 } else { 1 };
            let last = if next.is_arc() { 4 } else { 3 };
            // At α = 90° (offset paths that do not meet) the two stretched
            // vectors are one point: one step, not a move of no length.
            if dist(v2, v3) <= TOUCH {
                let all = [end1, v2, start2];
                return Ok(Corner::points(Kind::Acute, alpha, &all[first..last - 1]));
            }
            let all = [end1, v2, v3, start2];
            Ok(Corner::points(Kind::Acute, alpha, &all[first..last]))
        }
    }
}

/// True when a straight block's offset path runs against its programmed
/// direction (Fanuc's interference criterion: directions 90° to 270°
/// apart).
pub fn line_reverses(programmed: (P2, P2), actual: (P2, P2)) -> bool {
    let d = sub(programmed.1, programmed.0);
    let a = sub(actual.1, actual.0);
    len(d) > 0.0 && len(a) > 0.0 && dot(d, a) < 0.0
}

/// The signed sweep (radians, counter-clockwise positive) from `from` to
/// `to` about `center` in the direction `ccw`; a whole turn when they
/// coincide.
pub fn sweep(from: P2, to: P2, center: P2, ccw: bool) -> f64 {
    use std::f64::consts::TAU;
    let a0 = (from[1] - center[1]).atan2(from[0] - center[0]);
    let a1 = (to[1] - center[1]).atan2(to[0] - center[0]);
    if dist(from, to) < 1e-9 {
        return if ccw { TAU } else { -TAU };
    }
    if ccw {
        (a1 - a0).rem_euclid(TAU)
    } else {
        -(a0 - a1).rem_euclid(TAU)
    }
}

/// True when an arc block's offset path interferes (Fanuc's criteria): the
/// tool does not fit inside the arc (the offset radius is zero or less, the
/// tool centre would run the other way round), or the offset arc's sweep
/// differs from the programmed one by more than 180° (its ends crossed
/// over).
pub fn arc_interferes(programmed_sweep: f64, offset_sweep: f64, offset_radius: f64) -> bool {
    offset_radius <= 0.0 || (programmed_sweep - offset_sweep).abs() > std::f64::consts::PI
}

#[cfg(test)]
#[path = "geometry_tests.rs"]
mod tests;
