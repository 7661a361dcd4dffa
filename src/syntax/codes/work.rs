//! Group 14, the work coordinate system: the systems a program selects
//! (G54–G59, LinuxCNC's G59.1–G59.3, the Fanuc and Haas additional ones)
//! and the codes that name them, each writing its own code back.

/// Group 14: the work coordinate system.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[allow(missing_docs)]
pub enum WorkSystem {
    G54,
    G55,
    G56,
    G57,
    G58,
    G59,
    /// G59.1–G59.3: LinuxCNC's seventh to ninth systems (LinuxCNC 2.9
    /// documentation, "G54-G59.3"; behaviour 22.14).
    G59_1,
    G59_2,
    G59_3,
    /// `G54.1 Pn` (or `G54 Pn`): Fanuc's additional workpiece coordinate
    /// systems, n from 1 to 48 (behaviour 13.3).
    Additional(u8),
    /// `G154 Pn`: Haas's additional work offsets, n from 1 to 99.
    Haas(u8),
}

/// The most additional work systems of `G54.1 Pn` (Fanuc 0i-MF: 48 sets).
pub const MAX_ADDITIONAL_WORK: u8 = 48;
/// The most additional work offsets of `G154 Pn` (Haas: P1 to P99).
pub const MAX_HAAS_WORK: u8 = 99;

/// `G54.1 P1` … `G54.1 P48` as written back (a modal code is a `&'static str`).
const ADDITIONAL_WORK: [&str; MAX_ADDITIONAL_WORK as usize] = [
    "G54.1 P1",
    "G54.1 P2",
    "G54.1 P3",
    "G54.1 P4",
    "G54.1 P5",
    "G54.1 P6",
    "G54.1 P7",
    "G54.1 P8",
    "G54.1 P9",
    "G54.1 P10",
    "G54.1 P11",
    "G54.1 P12",
    "G54.1 P13",
    "G54.1 P14",
    "G54.1 P15",
    "G54.1 P16",
    "G54.1 P17",
    "G54.1 P18",
    "G54.1 P19",
    "G54.1 P20",
    "G54.1 P21",
    "G54.1 P22",
    "G54.1 P23",
    "G54.1 P24",
    "G54.1 P25",
    "G54.1 P26",
    "G54.1 P27",
    "G54.1 P28",
    "G54.1 P29",
    "G54.1 P30",
    "G54.1 P31",
    "G54.1 P32",
    "G54.1 P33",
    "G54.1 P34",
    "G54.1 P35",
    "G54.1 P36",
    "G54.1 P37",
    "G54.1 P38",
    "G54.1 P39",
    "G54.1 P40",
    "G54.1 P41",
    "G54.1 P42",
    "G54.1 P43",
    "G54.1 P44",
    "G54.1 P45",
    "G54.1 P46",
    "G54.1 P47",
    "G54.1 P48",
];
/// `G154 P1` … `G154 P99`.
const HAAS_WORK: [&str; MAX_HAAS_WORK as usize] = [
    "G154 P1", "G154 P2", "G154 P3", "G154 P4", "G154 P5", "G154 P6", "G154 P7", "G154 P8",
    "G154 P9", "G154 P10", "G154 P11", "G154 P12", "G154 P13", "G154 P14", "G154 P15", "G154 P16",
    "G154 P17", "G154 P18", "G154 P19", "G154 P20", "G154 P21", "G154 P22", "G154 P23", "G154 P24",
    "G154 P25", "G154 P26", "G154 P27", "G154 P28", "G154 P29", "G154 P30", "G154 P31", "G154 P32",
    "G154 P33", "G154 P34", "G154 P35", "G154 P36", "G154 P37", "G154 P38", "G154 P39", "G154 P40",
    "G154 P41", "G154 P42", "G154 P43", "G154 P44", "G154 P45", "G154 P46", "G154 P47", "G154 P48",
    "G154 P49", "G154 P50", "G154 P51", "G154 P52", "G154 P53", "G154 P54", "G154 P55", "G154 P56",
    "G154 P57", "G154 P58", "G154 P59", "G154 P60", "G154 P61", "G154 P62", "G154 P63", "G154 P64",
    "G154 P65", "G154 P66", "G154 P67", "G154 P68", "G154 P69", "G154 P70", "G154 P71", "G154 P72",
    "G154 P73", "G154 P74", "G154 P75", "G154 P76", "G154 P77", "G154 P78", "G154 P79", "G154 P80",
    "G154 P81", "G154 P82", "G154 P83", "G154 P84", "G154 P85", "G154 P86", "G154 P87", "G154 P88",
    "G154 P89", "G154 P90", "G154 P91", "G154 P92", "G154 P93", "G154 P94", "G154 P95", "G154 P96",
    "G154 P97", "G154 P98", "G154 P99",
];

impl WorkSystem {
    /// The G code (with its P number for the additional systems).
    pub fn gcode(self) -> &'static str {
        let numbered = |table: &'static [&'static str], n: u8| {
            table
                .get(usize::from(n).wrapping_sub(1))
                .copied()
                .unwrap_or("G54.1")
        };
        match self {
            WorkSystem::G54 => "G54",
            WorkSystem::G55 => "G55",
            WorkSystem::G56 => "G56",
            WorkSystem::G57 => "G57",
            WorkSystem::G58 => "G58",
            WorkSystem::G59 => "G59",
            WorkSystem::G59_1 => "G59.1",
            WorkSystem::G59_2 => "G59.2",
            WorkSystem::G59_3 => "G59.3",
            WorkSystem::Additional(n) => numbered(&ADDITIONAL_WORK, n),
            WorkSystem::Haas(n) => numbered(&HAAS_WORK, n),
        }
    }

    /// Its row of the G54–G59.3 table (0 for G54 … 5 for G59, 6–8 for
    /// G59.1–G59.3), or None for an additional system (its P number keys
    /// the setup's map).
    pub fn index(self) -> Option<usize> {
        match self {
            WorkSystem::G54 => Some(0),
            WorkSystem::G55 => Some(1),
            WorkSystem::G56 => Some(2),
            WorkSystem::G57 => Some(3),
            WorkSystem::G58 => Some(4),
            WorkSystem::G59 => Some(5),
            WorkSystem::G59_1 => Some(6),
            WorkSystem::G59_2 => Some(7),
            WorkSystem::G59_3 => Some(8),
            WorkSystem::Additional(_) | WorkSystem::Haas(_) => None,
        }
    }
}

/// Group 14 as a block writes it: a work system, or a code whose system is
/// numbered by the block's P word.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum WorkCode {
    /// G54 … G59 (on Fanuc, `G54 Pn` is `G54.1 Pn`).
    Standard(WorkSystem),
    /// G54.1: Fanuc's additional systems, numbered by P.
    Additional,
    /// G154: Haas's additional work offsets, numbered by P.
    Haas,
    /// G110–G129: Haas's names of G154 P1–P20 (the number, 1–20).
    HaasNamed(u8),
}

/// G110 … G129, the Haas names of G154 P1 … P20.
const HAAS_NAMED: [&str; 20] = [
    "G110", "G111", "G112", "G113", "G114", "G115", "G116", "G117", "G118", "G119", "G120", "G121",
    "G122", "G123", "G124", "G125", "G126", "G127", "G128", "G129",
];

impl WorkCode {
    /// The G code as written.
    pub fn gcode(self) -> &'static str {
        match self {
            WorkCode::Standard(w) => w.gcode(),
            WorkCode::Additional => "G54.1",
            WorkCode::Haas => "G154",
            WorkCode::HaasNamed(n) => HAAS_NAMED[usize::from(n.clamp(1, 20) - 1)],
        }
    }
}
