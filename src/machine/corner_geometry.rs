//! Where a chamfer or a corner round meets the paths it joins when one of
//! them is an arc (behaviour 2.36; Fanuc "chamfering and corner R" between
//! linear and circular interpolation, in either order, and between two
//! arcs). All in the plane, on the part (the lathe's X in radius). Between
//! two straight moves `corner.rs` keeps its own shorter way.

use super::ArcInfo;
use super::arc::P2;
use crate::geometry::Xyz;
use std::f64::consts::TAU;

/// What a `,C` or `,R` word asks for, in the plane's lengths.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Corner {
    /// `,C`: a straight chamfer this far from the corner along each move.
    Chamfer(f64),
    /// `,R`: a tangent arc of this radius.
    Round(f64),
}

/// One of the two paths at the corner, as the plane sees it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Seg {
    /// A straight move: its unit direction and its length.
    Line { dir: P2, len: f64 },
    /// An arc: its centre, radius, turn and the angle it sweeps (> 0).
    Arc {
        center: P2,
        radius: f64,
        ccw: bool,
        sweep: f64,
    },
}

/// The move that cuts the corner, from the point on the path before to
/// the point on the path after.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Cut {
    Chamfer {
        from: P2,
        to: P2,
    },
    Round {
        from: P2,
        to: P2,
        center: P2,
        ccw: bool,
    },
}

/// Why no corner is cut.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum CutError {
    /// The paths meet tangentially (`back`: the second turns right back):
    /// no corner.
    NoCorner { back: bool },
    /// The cut needs more of a path than it has.
    TooLong,
}

fn sub(a: P2, b: P2) -> P2 {
    [a[0] - b[0], a[1] - b[1]]
}

fn add(a: P2, b: P2, k: f64) -> P2 {
    [a[0] + b[0] * k, a[1] + b[1] * k]
}

fn dot(a: P2, b: P2) -> f64 {
    a[0] * b[0] + a[1] * b[1]
}

fn cross(a: P2, b: P2) -> f64 {
    a[0] * b[1] - a[1] * b[0]
}

fn norm(a: P2) -> f64 {
    a[0].hypot(a[1])
}

/// `p` turned about `c` by `angle` (counter-clockwise positive).
fn turn(p: P2, c: P2, angle: f64) -> P2 {
    let (s, k) = angle.sin_cos();
    let d = sub(p, c);
    [c[0] + d[0] * k - d[1] * s, c[1] + d[0] * s + d[1] * k]
}

/// The angle from `a` to `b` about `c` in the arc's direction, in
/// [0, 2π).
fn travelled(c: P2, a: P2, b: P2, ccw: bool) -> f64 {
    let (da, db) = (sub(a, c), sub(b, c));
    let t = db[1].atan2(db[0]) - da[1].atan2(da[0]);
    (if ccw { t } else { -t }).rem_euclid(TAU)
}

impl Seg {
    /// The direction of travel at `p`, a point of the path.
    fn tangent(&self, p: P2) -> P2 {
        match *self {
            Seg::Line { dir, .. } => dir,
            Seg::Arc {
                center,
                radius,
                ccw,
                ..
            } => {
                let r = [(p[0] - center[0]) / radius, (p[1] - center[1]) / radius];
                if ccw { [-r[1], r[0]] } else { [r[1], -r[0]] }
            }
        }
    }

    /// The point `c` (a straight distance) from the corner `k` along the
    /// path, back along it when `back`.
    fn at_distance(&self, k: P2, c: f64, back: bool) -> Result<P2, CutError> {
        match *self {
            Seg::Line { dir, len } => {
                if c > len + 1e-9 {
                    return Err(CutError::TooLong);
                }
                Ok(add(k, dir, if back { -c } else { c }))
            }
            Seg::Arc {
                center,
                radius,
                ccw,
                sweep,
            } => {
                if c > 2.0 * radius {
                    return Err(CutError::TooLong);
                }
                let angle = 2.0 * (c / (2.0 * radius)).asin();
                if angle > sweep + 1e-12 {
                    return Err(CutError::TooLong);
                }
                let forward = if ccw { angle } else { -angle };
                Ok(turn(k, center, if back { -forward } else { forward }))
            }
        }
    }

    /// The path moved `r` to the side `side` (+1 left, −1 right of the
    /// direction of travel): a line (a point and a direction) or a circle.
    fn offset(&self, k: P2, r: f64, side: f64) -> Offset {
        match *self {
            Seg::Line { dir, .. } => Offset::Line(add(k, [-dir[1], dir[0]], side * r), dir),
            Seg::Arc {
                center,
                radius,
                ccw,
                ..
            } => {
                // Left of a counter-clockwise arc is towards its centre.
                let inward = if ccw { side } else { -side };
                Offset::Circle(center, radius - inward * r)
            }
        }
    }

    /// The point of the path nearest `q` (the round's tangent point).
    fn foot(&self, k: P2, q: P2) -> P2 {
        match *self {
            Seg::Line { dir, .. } => add(k, dir, dot(sub(q, k), dir)),
            Seg::Arc { center, radius, .. } => {
                let d = sub(q, center);
                add(center, d, radius / norm(d))
            }
        }
    }

    /// Whether `p` lies on the path within its extent, before the corner
    /// `k` (`back`) or after it.
    fn holds(&self, k: P2, p: P2, back: bool) -> bool {
        match *self {
            Seg::Line { dir, len } => {
                let t = dot(sub(p, k), dir) * if back { -1.0 } else { 1.0 };
                (-1e-9..=len + 1e-9).contains(&t)
            }
            Seg::Arc {
                center, ccw, sweep, ..
            } => {
                let t = if back {
                    travelled(center, p, k, ccw)
                } else {
                    travelled(center, k, p, ccw)
                };
                t <= sweep + 1e-12 || t > TAU - 1e-12
            }
        }
    }
}

/// A path moved sideways: a line through a point along a direction, or
/// a circle.
enum Offset {
    Line(P2, P2),
    Circle(P2, f64),
}

/// The points both offset paths pass through.
fn meet(a: &Offset, b: &Offset) -> Vec<P2> {
    match (a, b) {
        (Offset::Line(p, d), Offset::Line(q, e)) => {
            let den = cross(*d, *e);
            if den.abs() < 1e-12 {
                return Vec::new();
            }
            vec![add(*p, *d, cross(sub(*q, *p), *e) / den)]
        }
        (Offset::Line(p, d), Offset::Circle(c, r)) | (Offset::Circle(c, r), Offset::Line(p, d)) => {
            // |p + t d − c| = r, d a unit vector.
            let w = sub(*p, *c);
            let b = dot(w, *d);
            let disc = b * b - (dot(w, w) - r * r);
            if *r <= 0.0 || disc < 0.0 {
                return Vec::new();
            }
            let s = disc.sqrt();
            vec![add(*p, *d, -b - s), add(*p, *d, -b + s)]
        }
        (Offset::Circle(c1, r1), Offset::Circle(c2, r2)) => {
            let d = sub(*c2, *c1);
            let l = norm(d);
            if *r1 <= 0.0 || *r2 <= 0.0 || l < 1e-12 || l > r1 + r2 || l < (r1 - r2).abs() {
                return Vec::new();
            }
            let a = (r1 * r1 - r2 * r2 + l * l) / (2.0 * l);
            let h = (r1 * r1 - a * a).max(0.0).sqrt();
            let m = add(*c1, d, a / l);
            let n = [-d[1] / l, d[0] / l];
            vec![add(m, n, h), add(m, n, -h)]
        }
    }
}

/// The chamfer (`,C c`: its ends a straight distance `c` from the corner
/// on each path) or the round (`,R r`: the arc of radius r tangent to both
/// paths on the side the path turns to, the one nearest the corner) at the
/// corner `k` between `before`, which ends there, and `after`.
pub(super) fn cut(k: P2, before: Seg, after: Seg, corner: Corner) -> Result<Cut, CutError> {
    let (t1, t2) = (before.tangent(k), after.tangent(k));
    let turning = cross(t1, t2);
    if turning.abs() < 1e-9 {
        return Err(CutError::NoCorner {
            back: dot(t1, t2) < 0.0,
        });
    }
    let round = match corner {
        Corner::Chamfer(c) => {
            return Ok(Cut::Chamfer {
                from: before.at_distance(k, c, true)?,
                to: after.at_distance(k, c, false)?,
            });
        }
        Corner::Round(r) => r,
    };
    let side = turning.signum();
    let centers = meet(
        &before.offset(k, round, side),
        &after.offset(k, round, side),
    );
    let q = centers
        .into_iter()
        .min_by(|a, b| norm(sub(*a, k)).total_cmp(&norm(sub(*b, k))))
        .ok_or(CutError::TooLong)?;
    let (from, to) = (before.foot(k, q), after.foot(k, q));
    if !before.holds(k, from, true) || !after.holds(k, to, false) {
        return Err(CutError::TooLong);
    }
    Ok(Cut::Round {
        from,
        to,
        center: q,
        ccw: side > 0.0,
    })
}

/// The arc of a move as a path at the corner: about `center` with
/// `radius`, turning as `sweep`'s sign says, from `from` to `to` (a full
/// circle when they are one point).
pub(super) fn arc_seg(center: P2, radius: f64, sweep: f64, (from, to): (P2, P2)) -> Seg {
    let ccw = sweep > 0.0;
    let t = travelled(center, from, to, ccw);
    Seg::Arc {
        center,
        radius,
        ccw,
        sweep: if t < 1e-12 { sweep.abs() } else { t },
    }
}

/// The signed sweep from `a` to `b` about `c`, turning as `sweep` does.
fn sweep_between(c: P2, a: P2, b: P2, sweep: f64) -> f64 {
    let t = travelled(c, a, b, sweep > 0.0);
    let t = if t < 1e-12 { sweep.abs() } else { t };
    if sweep > 0.0 { t } else { -t }
}

/// An arc move cut short: it now ends at `to` (programmed) and `actual`,
/// points of its circles; its start and centre stay.
pub(super) fn end_arc_at(info: &mut ArcInfo, (from, to): (Xyz, Xyz), (afrom, ato): (Xyz, Xyz)) {
    let c = info.in_plane(info.programmed_center);
    info.programmed_sweep = sweep_between(
        c,
        info.in_plane(from),
        info.in_plane(to),
        info.programmed_sweep,
    );
    let c = info.in_plane(info.center);
    info.sweep = sweep_between(c, info.in_plane(afrom), info.in_plane(ato), info.sweep);
}

/// An arc move that starts later on its circles, at `from` (programmed)
/// and `afrom` (actual): the block after a cut corner (behaviour 2.36).
pub(super) fn start_arc_at(info: &mut ArcInfo, (from, to): (Xyz, Xyz), (afrom, ato): (Xyz, Xyz)) {
    let c = info.in_plane(info.programmed_center);
    let (a, b) = (info.in_plane(from), info.in_plane(to));
    info.programmed_start_angle = (a[1] - c[1]).atan2(a[0] - c[0]);
    info.programmed_sweep = sweep_between(c, a, b, info.programmed_sweep);
    let c = info.in_plane(info.center);
    let (a, b) = (info.in_plane(afrom), info.in_plane(ato));
    info.start_angle = (a[1] - c[1]).atan2(a[0] - c[0]);
    info.sweep = sweep_between(c, a, b, info.sweep);
}

#[cfg(test)]
mod tests {
    use super::*;

    fn near(a: P2, b: P2) {
        assert!(norm(sub(a, b)) < 1e-9, "{a:?} vs {b:?}");
    }

    #[test]
    fn behaviour2_36_a_round_between_a_line_and_an_arc() {
        // A line along +X ending at (0, 0); then a counter-clockwise arc
        // about (10, 0) of radius 10, which leaves (0, 0) going down (−Y):
        // a right turn of 90°. ,R2.: the round's centre is 2 right of the
        // line (y = −2) and 2 outside the arc's circle (radius 12 about
        // (10, 0)): x = 10 − √(144 − 4) = 10 − √140; the tangent points
        // are (x, 0) on the line and (10, 0) + 10·(q − c)/12 on the arc.
        let before = Seg::Line {
            dir: [1.0, 0.0],
            len: 50.0,
        };
        let after = Seg::Arc {
            center: [10.0, 0.0],
            radius: 10.0,
            ccw: true,
            sweep: 3.0,
        };
        let Ok(Cut::Round {
            from,
            to,
            center,
            ccw,
        }) = cut([0.0, 0.0], before, after, Corner::Round(2.0))
        else {
            panic!()
        };
        let x = 10.0 - 140f64.sqrt();
        near(center, [x, -2.0]);
        near(from, [x, 0.0]);
        near(
            to,
            add([10.0, 0.0], sub([x, -2.0], [10.0, 0.0]), 10.0 / 12.0),
        );
        assert!(!ccw);
    }

    #[test]
    fn behaviour2_36_a_chamfer_on_an_arc_is_a_chord_from_the_corner() {
        // The arc before: counter-clockwise about (0, 0) of radius 10,
        // ending at (10, 0) going up (+Y); then a line along +X: a right
        // turn. ,C2.: on the arc the point 2 from (10, 0) in a straight
        // line, back along it: the angle 2·asin(0.1) clockwise from (10, 0);
        // on the line (12, 0).
        let before = Seg::Arc {
            center: [0.0, 0.0],
            radius: 10.0,
            ccw: true,
            sweep: 1.5,
        };
        let after = Seg::Line {
            dir: [1.0, 0.0],
            len: 20.0,
        };
        let Ok(Cut::Chamfer { from, to }) = cut([10.0, 0.0], before, after, Corner::Chamfer(2.0))
        else {
            panic!()
        };
        let a = 2.0 * 0.1f64.asin();
        near(from, [10.0 * a.cos(), -10.0 * a.sin()]);
        assert!((norm(sub(from, [10.0, 0.0])) - 2.0).abs() < 1e-12);
        near(to, [12.0, 0.0]);
    }

    #[test]
    fn behaviour2_36_tangent_paths_have_no_corner_and_a_cut_must_fit() {
        // A line along +X into (0, 0), then a counter-clockwise arc about
        // (0, 10): it leaves along +X, tangent.
        let line = Seg::Line {
            dir: [1.0, 0.0],
            len: 5.0,
        };
        let arc = Seg::Arc {
            center: [0.0, 10.0],
            radius: 10.0,
            ccw: true,
            sweep: 1.0,
        };
        assert_eq!(
            cut([0.0, 0.0], line, arc, Corner::Chamfer(1.0)),
            Err(CutError::NoCorner { back: false })
        );
        // A chamfer longer than the line before.
        let down = Seg::Arc {
            center: [10.0, 0.0],
            radius: 10.0,
            ccw: true,
            sweep: 3.0,
        };
        assert_eq!(
            cut([0.0, 0.0], line, down, Corner::Chamfer(6.0)),
            Err(CutError::TooLong)
        );
        // More of the arc than it sweeps.
        let short = Seg::Arc {
            center: [10.0, 0.0],
            radius: 10.0,
            ccw: true,
            sweep: 0.05,
        };
        assert_eq!(
            cut([0.0, 0.0], line, short, Corner::Chamfer(2.0)),
            Err(CutError::TooLong)
        );
    }

    /// A path at the corner (0, 0): a line in direction `angle`, or an arc
    /// whose centre lies `radius` from the corner at `angle`.
    fn seg(line: bool, angle: f64, radius: f64, ccw: bool) -> Seg {
        if line {
            let d = [angle.cos(), angle.sin()];
            return Seg::Line { dir: d, len: 100.0 };
        }
        Seg::Arc {
            center: [radius * angle.cos(), radius * angle.sin()],
            radius,
            ccw,
            sweep: 3.0,
        }
    }

    /// The distance of `p` from the path (its line or its circle).
    fn off(s: &Seg, p: P2) -> f64 {
        match *s {
            Seg::Line { dir, .. } => cross(dir, p).abs(),
            Seg::Arc { center, radius, .. } => (norm(sub(p, center)) - radius).abs(),
        }
    }

    #[cfg(not(target_arch = "wasm32"))]
    proptest::proptest! {
        /// Behaviour 2.36: whatever the two paths, a round found touches
        /// both: its ends lie on them, `,R` from its centre, and it leaves
        /// and meets each path along it (the tangents agree); a chamfer's
        /// ends lie on the paths `,C` from the corner.
        #[test]
        fn a_round_is_tangent_to_both_paths_and_a_chamfer_a_chord_of_c(
            (l1, a1, r1, c1) in (proptest::bool::ANY, 0.0f64..TAU, 5.0f64..50.0, proptest::bool::ANY),
            (l2, a2, r2, c2) in (proptest::bool::ANY, 0.0f64..TAU, 5.0f64..50.0, proptest::bool::ANY),
            size in 0.2f64..3.0,
        ) {
            let (before, after) = (seg(l1, a1, r1, c1), seg(l2, a2, r2, c2));
            let k = [0.0, 0.0];
            if let Ok(Cut::Round { from, to, center, ccw }) = cut(k, before, after, Corner::Round(size)) {
                proptest::prop_assert!(off(&before, from) < 1e-9 && off(&after, to) < 1e-9);
                proptest::prop_assert!((norm(sub(from, center)) - size).abs() < 1e-9);
                proptest::prop_assert!((norm(sub(to, center)) - size).abs() < 1e-9);
                let round = Seg::Arc { center, radius: size, ccw, sweep: 1.0 };
                for (path, p) in [(before, from), (after, to)] {
                    let (t, u) = (path.tangent(p), round.tangent(p));
                    proptest::prop_assert!(cross(t, u).abs() < 1e-6 && dot(t, u) > 0.0, "{t:?} {u:?}");
                }
            }
            if let Ok(Cut::Chamfer { from, to }) = cut(k, before, after, Corner::Chamfer(size)) {
                proptest::prop_assert!(off(&before, from) < 1e-9 && off(&after, to) < 1e-9);
                proptest::prop_assert!((norm(from) - size).abs() < 1e-9 && (norm(to) - size).abs() < 1e-9);
            }
        }
    }
}
