//! The G and M codes offsetlab knows, their modal groups, and for codes it
//! recognises but does not model, the reason it says so (spec 2: an
//! unsupported code is an error, never a silent skip).

use crate::setup::MachineKind;

/// A G-code modal group. Two codes of one group in a block is an error
/// (spec 1). Numbers follow the Fanuc/YASNAC M tables where they exist.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Group {
    /// 00: one-shot codes (G04, G28, G45–G48, G92 / lathe G50).
    NonModal,
    /// 01: interpolation (G00–G03; on the lathe also the G90/G92/G94 cycles).
    Motion,
    /// 02: plane selection.
    Plane,
    /// 03: absolute / incremental (mill).
    Distance,
    /// 05: feed per minute / per revolution.
    FeedMode,
    /// 06: inch / metric.
    Units,
    /// 07: cutter compensation (only the cancel G40 is accepted).
    Cutter,
    /// 08: tool length offset.
    Length,
    /// 09: canned cycles (mill).
    Cycle,
    /// 10: canned-cycle return level (mill).
    Return,
    /// 14: work coordinate systems.
    Work,
    /// Lathe 02: constant surface speed on/off.
    SurfaceSpeed,
}

impl Group {
    /// Index for per-group tables.
    pub fn index(self) -> usize {
        self as usize
    }
    /// Number of groups.
    pub const COUNT: usize = 12;
    /// Every group, in index order.
    pub const ALL: [Group; Group::COUNT] = [
        Group::NonModal,
        Group::Motion,
        Group::Plane,
        Group::Distance,
        Group::FeedMode,
        Group::Units,
        Group::Cutter,
        Group::Length,
        Group::Cycle,
        Group::Return,
        Group::Work,
        Group::SurfaceSpeed,
    ];
    /// The group's name in the manuals.
    pub fn label(self) -> &'static str {
        match self {
            Group::NonModal => "00 (one-shot)",
            Group::Motion => "01 (interpolation)",
            Group::Plane => "02 (plane)",
            Group::Distance => "03 (absolute/incremental)",
            Group::FeedMode => "05 (feed mode)",
            Group::Units => "06 (inch/metric)",
            Group::Cutter => "07 (cutter compensation)",
            Group::Length => "08 (tool length offset)",
            Group::Cycle => "09 (canned cycle)",
            Group::Return => "10 (return level)",
            Group::Work => "14 (work coordinates)",
            Group::SurfaceSpeed => "02 (constant surface speed)",
        }
    }
}

/// A G code as written: `G05.1` is major 5, minor 1.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct GCode {
    /// The integer part.
    pub major: u16,
    /// The tenths digit (0 for every code offsetlab models).
    pub minor: u8,
}

impl GCode {
    /// A plain integer code.
    pub const fn new(major: u16) -> GCode {
        GCode { major, minor: 0 }
    }
}

impl std::fmt::Display for GCode {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.minor == 0 {
            write!(f, "G{:02}", self.major)
        } else {
            write!(f, "G{:02}.{}", self.major, self.minor)
        }
    }
}

/// The modal group of a G code this machine models, or why it does not.
pub fn g_group(machine: MachineKind, g: GCode) -> Result<Group, String> {
    if g.minor != 0 {
        return Err(format!("{g} is not supported by offsetlab"));
    }
    group_of(machine, g).ok_or_else(|| unsupported_reason(machine, g))
}

/// The modal group of a G code this machine models (the parser's check of
/// every G word: [`g_group`] says why a code has none).
#[inline(always)]
pub fn group_of(machine: MachineKind, g: GCode) -> Option<Group> {
    if g.minor != 0 {
        return None;
    }
    let n = g.major;
    match machine {
        MachineKind::Mill => match n {
            0..=3 => Some(Group::Motion),
            4 | 28 | 45..=48 | 92 => Some(Group::NonModal),
            17..=19 => Some(Group::Plane),
            20 | 21 => Some(Group::Units),
            40 => Some(Group::Cutter),
            43 | 44 | 49 => Some(Group::Length),
            54..=59 => Some(Group::Work),
            73 | 74 | 76 | 80..=89 => Some(Group::Cycle),
            90 | 91 => Some(Group::Distance),
            94 | 95 => Some(Group::FeedMode),
            98 | 99 => Some(Group::Return),
            _ => None,
        },
        MachineKind::Lathe => match n {
            0..=3 | 90 | 92 | 94 => Some(Group::Motion),
            4 | 28 | 50 => Some(Group::NonModal),
            18 => Some(Group::Plane),
            20 | 21 => Some(Group::Units),
            40 => Some(Group::Cutter),
            54..=59 => Some(Group::Work),
            96 | 97 => Some(Group::SurfaceSpeed),
            98 | 99 => Some(Group::FeedMode),
            _ => None,
        },
    }
}

fn unsupported_reason(machine: MachineKind, g: GCode) -> String {
    let lathe = machine == MachineKind::Lathe;
    let why = match g.major {
        41 | 42 if lathe => "tool nose radius compensation is not modelled",
        41 | 42 => {
            "cutter radius compensation C is not modelled; offsetlab models tool position offset G45–G48 (seed 000)"
        }
        43 | 44 | 49 if lathe => "the lathe uses T-code offsets, not G43/G44/G49 (seed 004)",
        45..=48 if lathe => "the lathe uses T-code offsets, not G45–G48 (seed 004)",
        10 => "programmable data input is not supported; enter offsets in the offset table",
        32..=34 => "thread cutting blocks are not supported",
        50 | 51 if !lathe => "scaling is not supported",
        53 => "machine coordinate positioning is not supported",
        65..=67 => "macro calls are not supported",
        68 | 69 => "coordinate rotation is not supported",
        70..=76 if lathe => "multiple repetitive cycles (G70–G76) are not supported yet",
        15 | 16 => "polar coordinates are not supported",
        17 | 19 if lathe => "the lathe works in the ZX plane (G18) only",
        61..=64 => "cutting modes (exact stop, tapping, continuous) are not modelled",
        91 if lathe => "the lathe (G-code system A) has no G91; U and W are the incremental axes",
        _ => "is not a G code offsetlab knows",
    };
    if why.starts_with("is not") {
        format!("{g} {why} on the {}", machine.as_str())
    } else {
        format!("{g}: {why}")
    }
}

/// The group of an M code: codes of one group exclude each other in a block.
/// Codes without a group are their own group.
pub fn m_group(m: u32) -> u32 {
    match m {
        0 | 1 | 2 | 30 => 1,
        3 | 4 | 5 | 19 => 2,
        7..=9 => 3,
        6 => 4,
        other => 100 + other,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lathe_g90_is_a_cycle_not_absolute_mode() {
        assert_eq!(
            g_group(MachineKind::Lathe, GCode::new(90)),
            Ok(Group::Motion)
        );
        assert_eq!(
            g_group(MachineKind::Mill, GCode::new(90)),
            Ok(Group::Distance)
        );
    }

    #[test]
    fn unsupported_codes_say_why() {
        let e = g_group(MachineKind::Mill, GCode::new(41)).unwrap_err();
        assert!(e.contains("G45–G48"), "{e}");
        let e = g_group(MachineKind::Mill, GCode::new(7)).unwrap_err();
        assert!(e.contains("G07 is not a G code"), "{e}");
        let e = g_group(MachineKind::Mill, GCode { major: 5, minor: 1 }).unwrap_err();
        assert!(e.contains("G05.1"), "{e}");
    }
}
