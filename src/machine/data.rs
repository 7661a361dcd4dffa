//! G10, programmable data input (behaviour 17.5–17.11): the program writes
//! the offset tables and the work offsets, from the block it runs on. The
//! values go into this machine's copy of the setup (shared until the first
//! write), which every later block reads as it would the user's table: the
//! length offset, the position offset, the lathe's T code and the work
//! systems read their register or zero when they name it, so a block that
//! read a value before the G10 keeps it (behaviour 4.12), and a run made
//! again reads the same.
//!
//! The forms (Fanuc 0i-MF/TF operator's manuals, "Programmable data input
//! (G10)"; Haas mill and lathe operator's manuals, "G10 Set Offsets"):
//! mill `G10 L1/L10–L13 P… R…` by the offset memory type (7.32), lathe `G10
//! P… X/U Z/W R/C Q…` (P ≥ 10000 geometry, else wear) and Haas's `G10 L10/L11
//! P… X Z R Q`, and `G10 L2 P0–P6` / `G10 L20 P…` for the work offsets.

use std::sync::Arc;

use super::modal::{Distance, WorkSystem};
use super::{EventKind, Machine, Out, state::DataSet};
use crate::diag::Diagnostic;
use crate::geometry::round6;
use crate::setup::{
    DecimalInput, ExtendedWork, MAX_OFFSET_VALUE, MAX_TIP, MachineKind, MillPart, MillRegister,
    OffsetMemory, WorkOffsets,
};
use crate::syntax::codes::{Code, MAX_ADDITIONAL_WORK, MAX_HAAS_WORK, NonModal};
use crate::syntax::{Address, Block, Word};

use Address::{C, G, L, N, P, Q, R, U, W, X, Y, Z};

/// Fanuc's alarm for a G10 whose L, P or words are not a data setting
/// (PS0031, "ILLEGAL P COMMAND IN G10").
const PS0031: &str = "Fanuc alarm PS0031";
/// Fanuc's alarm for an offset value past the range (PS0032, "ILLEGAL
/// OFFSET VALUE IN G10").
const PS0032: &str = "Fanuc alarm PS0032";
/// The lathe's geometry offsets are P 10000 + n (Fanuc 0i-TF, G10).
const GEOMETRY_P: u32 = 10_000;

/// Which value of a mill register a G10 L sets (behaviour 17.5).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum MillField {
    /// Memory A: the number's one value.
    Value,
    /// Memory B: the number's geometry.
    Geometry,
    /// Memory B: the number's wear.
    Wear,
    /// Memory C: the H table's geometry.
    HGeometry,
    /// Memory C: the H table's wear.
    HWear,
    /// Memory C: the D table's geometry.
    DGeometry,
    /// Memory C: the D table's wear.
    DWear,
}

impl MillField {
    /// The field as the setup document and the report name it.
    pub(super) fn key(self) -> &'static str {
        match self {
            MillField::Value => "value",
            MillField::Geometry => "geometry",
            MillField::Wear => "wear",
            MillField::HGeometry => "h_geometry",
            MillField::HWear => "h_wear",
            MillField::DGeometry => "d_geometry",
            MillField::DWear => "d_wear",
        }
    }

    /// "register 01", "register 01 wear", "D01 geometry".
    pub(super) fn label(self, n: u16) -> String {
        match self {
            MillField::Value => format!("register {n:02}"),
            MillField::Geometry => format!("register {n:02} geometry"),
            MillField::Wear => format!("register {n:02} wear"),
            MillField::HGeometry => format!("H{n:02} geometry"),
            MillField::HWear => format!("H{n:02} wear"),
            MillField::DGeometry => format!("D{n:02} geometry"),
            MillField::DWear => format!("D{n:02} wear"),
        }
    }

    pub(super) fn get(self, r: &MillRegister) -> f64 {
        match self {
            MillField::Value => r.value(),
            MillField::Geometry | MillField::HGeometry => r.geometry,
            MillField::Wear | MillField::HWear => r.wear,
            MillField::DGeometry => r.d_part().geometry,
            MillField::DWear => r.d_part().wear,
        }
    }

    /// Sets the value; returns the geometry + wear of the part it is in.
    pub(super) fn set(self, r: &mut MillRegister, v: f64) -> f64 {
        let (h, d) = (r.h_part(), r.d_part());
        match self {
            // Memory A keeps one value: a wear part of a document written
            // before memory types is taken into it (behaviour 17.1).
            MillField::Value => *r = MillRegister::new(v, 0.0),
            MillField::Geometry => r.geometry = v,
            MillField::Wear => r.wear = v,
            MillField::HGeometry => r.set_h(MillPart { geometry: v, ..h }),
            MillField::HWear => r.set_h(MillPart { wear: v, ..h }),
            MillField::DGeometry => r.set_d(MillPart { geometry: v, ..d }),
            MillField::DWear => r.set_d(MillPart { wear: v, ..d }),
        }
        match self {
            MillField::DGeometry | MillField::DWear => r.d_part().value(),
            _ => r.value(),
        }
    }

    /// The table the field is read by: H, D or both.
    fn read_by(self) -> (bool, bool) {
        match self {
            MillField::Value | MillField::Geometry | MillField::Wear => (true, true),
            MillField::HGeometry | MillField::HWear => (true, false),
            MillField::DGeometry | MillField::DWear => (false, true),
        }
    }
}

/// An axis of a work offset G10: its absolute word, its incremental one
/// (the lathe's U, W), its index and the document's field.
type WorkAxis = (Address, Option<Address>, usize, &'static str);

/// A value of the program: never -0, which a report could show as such.
pub(super) fn clean(v: f64) -> f64 {
    v + 0.0
}

impl Machine {
    /// A G10 block (behaviour 17.5–17.11): its form by L and the machine.
    pub(super) fn data_setting(&mut self, b: &Block, out: &mut Out) -> Result<(), Diagnostic> {
        self.g10_codes(b)?;
        let lathe = self.setup.machine == MachineKind::Lathe;
        let l = b.get(L);
        match (l.map(Word::int), lathe) {
            // LinuxCNC's nine systems, P0 the one in use (behaviour 22.14).
            (Some(l @ (2 | 20)), false) if self.setup.settings.control == crate::setup::Control::Linuxcnc => self.g10_work_linuxcnc(b, l, out),
            (Some(2), _) => self.g10_work(b, false, out),
            (Some(20), _) => self.g10_work(b, true, out),
            (Some(l @ (1 | 10 | 11)), false) if self.has_tool_table() => self.g10_table(b, l, out),
            (Some(1 | 10..=13), false) => self.g10_mill(b, l.map_or(0, Word::int), out),
            (None, true) => self.g10_lathe(b, None, out),
            (Some(10), true) => self.g10_lathe(b, Some(true), out),
            (Some(1 | 11), true) => self.g10_lathe(b, Some(false), out),
            (None, false) => Err(self.error(
                "g10-words",
                b.code_span(crate::syntax::codes::Group::NonModal),
                format!(
                    "G10 needs L, the kind of data it sets: L2 or L20 work offsets, L1 or L10–L13 tool offsets ({PS0031})"
                ),
            )),
            (Some(n), _) => Err(self.error(
                "g10-words",
                l.map_or(b.span, |w| w.span),
                format!(
                    "G10 L{n} is not a data setting offsetlab models: {} ({PS0031} where the control has no such L)",
                    if lathe {
                        "L2 and L20 set work offsets, L10 and L1/L11 the geometry and wear offsets (Haas), and G10 P… without L the tool offsets (Fanuc)"
                    } else {
                        "L2 and L20 set work offsets, L1 and L10–L13 the tool offsets"
                    }
                ),
            )),
        }
    }

    /// The G codes a G10 block may hold besides G10: G90/G91 (Mitsubishi
    /// M700, "Programmed compensation input": G10 goes with G90, G91 and the
    /// work systems only; our convention for Fanuc, whose G10 moves nothing).
    /// The distance code is set for this block and the next (modal).
    fn g10_codes(&mut self, b: &Block) -> Result<(), Diagnostic> {
        for code in b.codes().each() {
            match code {
                Code::NonModal(NonModal::DataSetting) => {}
                Code::Distance(d) => self.state.modal.distance = d,
                other => {
                    let table = self.state.table();
                    return Err(self.error(
                        "g10-words",
                        b.code_span(other.group()),
                        format!(
                            "{} in a G10 block: G10 sets data and moves nothing; write {} in a block of its own (G10 shares its block with G90/G91 only)",
                            other.gcode(table),
                            other.gcode(table)
                        ),
                    ));
                }
            }
        }
        Ok(())
    }

    /// Refuses every word of a G10 block outside `allowed` (behaviour 2.22,
    /// 17.10): `what` says what the form reads.
    pub(super) fn g10_only(
        &self,
        b: &Block,
        allowed: &[Address],
        what: &str,
    ) -> Result<(), Diagnostic> {
        match b.words.iter().find(|w| !allowed.contains(&w.address)) {
            Some(w) => Err(self.error(
                "g10-words",
                w.span,
                format!(
                    "{}: {what}, and {} is not one of its words ({PS0031}: an address not concerned with data setting)",
                    self.word_text(b, w.address),
                    w.address.letter()
                ),
            )),
            None => Ok(()),
        }
    }

    /// The block's G10 words as written, for its sentence.
    pub(super) fn g10_text(&self, b: &Block) -> String {
        let d = self.units().decimals();
        b.words
            .iter()
            .filter(|w| w.address != N)
            .map(|w| match w.address {
                G | L | P => format!("{}{}", w.address.letter(), w.int()),
                Q if self.setup.machine == MachineKind::Lathe => {
                    format!("Q{}", self.tip_of(w).unwrap_or(0))
                }
                a => format!("{}{:.d$}", a.letter(), w.value),
            })
            .collect::<Vec<_>>()
            .join(" ")
    }

    /// A number of the table as the control shows it.
    fn g10_show(&self, v: f64) -> String {
        let d = self.units().decimals();
        format!("{:.d$}", round6(v))
    }

    /// P of a G10 block: required, within `range`, or the alarm naming
    /// `what` the numbers are.
    fn g10_p(
        &self,
        b: &Block,
        range: std::ops::RangeInclusive<u32>,
        what: &str,
    ) -> Result<u32, Diagnostic> {
        let Some(p) = b.get(P) else {
            return Err(self.error(
                "g10-words",
                b.span,
                format!("G10 needs P, the number of what it sets: {what} ({PS0031})"),
            ));
        };
        let n = p.int();
        if !range.contains(&n) {
            return Err(self.error("g10-number", p.span, format!("G10 P{n}: {what} ({PS0031})")));
        }
        Ok(n)
    }

    /// A value checked against the offset range (seed 001: ±999.999).
    pub(super) fn g10_value(
        &self,
        w: &Word,
        what: &str,
        v: f64,
        max: f64,
    ) -> Result<f64, Diagnostic> {
        if v.is_finite() && v.abs() <= max + 1e-9 {
            // A control keeps whole least increments: G91's sums are exact
            // there, and a millionth is finer than any increment here.
            return Ok(clean(round6(v)));
        }
        Err(self.error(
            "g10-value",
            w.span,
            format!(
                "G10: {what} would be {}, past ±{max} ({PS0032}: illegal offset value in G10)",
                self.g10_show(v)
            ),
        ))
    }

    /// `G10 L1/L10–L13 P… R…` (behaviour 17.5): the mill's tool offsets by
    /// the offset memory type.
    fn g10_mill(&mut self, b: &Block, l: u32, out: &mut Out) -> Result<(), Diagnostic> {
        let memory = self.setup.settings.offset_memory();
        self.g10_only(
            b,
            &[N, G, L, P, R],
            &format!("G10 L{l} sets a tool offset with P (its number) and R (its value)"),
        )?;
        let field = match (memory, l) {
            (OffsetMemory::A, 1 | 11) => MillField::Value,
            (OffsetMemory::B, 10) => MillField::Geometry,
            (OffsetMemory::B, 1 | 11) => MillField::Wear,
            (OffsetMemory::C, 10) => MillField::HGeometry,
            (OffsetMemory::C, 1 | 11) => MillField::HWear,
            (OffsetMemory::C, 12) => MillField::DGeometry,
            (OffsetMemory::C, 13) => MillField::DWear,
            (memory, l) => {
                let forms = match memory {
                    OffsetMemory::A => "one value per number, set with G10 L11 (or L1)",
                    _ => {
                        "a geometry and a wear per number read by H and D alike: G10 L10 geometry, L11 (or L1) wear"
                    }
                };
                return Err(self.error(
                    "g10-words",
                    b.get(L).map_or(b.span, |w| w.span),
                    format!(
                        "G10 L{l}: offset memory {} keeps {forms} (setting offset_memory; L12/L13 set memory C's D table) ({PS0031})",
                        memory.as_str()
                    ),
                ));
            }
        };
        let table = self.setup.table_size;
        let n = self.g10_p(
            b,
            1..=u32::from(table),
            &format!("the tool offsets are 1 to {table} (setting table_size)"),
        )? as u16;
        let Some(r) = b.get(R) else {
            return Err(self.error(
                "g10-words",
                b.span,
                format!("G10 L{l} needs R, the offset value ({PS0031})"),
            ));
        };
        let mut reg = self.setup.offsets.get(&n).copied().unwrap_or_default();
        let was = field.get(&reg);
        let incremental = self.state.modal.distance == Distance::Incremental;
        let label = field.label(n);
        let v = self.g10_value(
            r,
            &label,
            if incremental { was + r.value } else { r.value },
            MAX_OFFSET_VALUE,
        )?;
        let sum = field.set(&mut reg, v);
        self.g10_value(
            r,
            &format!("{label} + the other part"),
            sum,
            MAX_OFFSET_VALUE,
        )?;
        Arc::make_mut(&mut self.setup).offsets.insert(n, reg);
        out.events.push(EventKind::DataSet(DataSet {
            table: "offsets",
            key: format!("{n:02}"),
            field: field.key(),
            value: v,
            was: clean(was),
        }));
        let mut note = format!(
            "{}: {label} = {} (was {}{})",
            self.g10_text(b),
            self.g10_show(v),
            self.g10_show(was),
            if incremental { ", G91 adds R" } else { "" }
        );
        let (h, d) = field.read_by();
        if h && self.state.length.sign != 0 && self.state.length.h == n {
            note.push_str(&format!(
                "; H{n:02} is in force with its old value until an H word names it again"
            ));
        }
        if d && self.state.position.d == n {
            note.push_str(&format!(
                "; D{n:02} is read with its new value by the next G45–G48 block"
            ));
        }
        out.notes.push(note);
        Ok(())
    }

    /// The lathe's tool offsets (behaviour 17.6): Fanuc's `G10 P… X/U Z/W R/C
    /// Q…` (`geometry` None: P ≥ 10000 the geometry of P − 10000, else the
    /// wear of P) or Haas's `G10 L10` geometry / `L1`, `L11` wear.
    fn g10_lathe(
        &mut self,
        b: &Block,
        geometry: Option<bool>,
        out: &mut Out,
    ) -> Result<(), Diagnostic> {
        self.g10_only(
            b,
            &[N, G, L, P, X, U, Z, W, R, C, Q],
            "G10 sets a lathe tool offset with P and X/U, Z/W, R/C (nose radius) and Q (tip direction)",
        )?;
        let table = u32::from(self.setup.table_size);
        let (n, geometry) = match geometry {
            Some(g) => {
                let n = self.g10_p(b, 1..=table, &format!("the tool offsets are 1 to {table}"))?;
                (n, g)
            }
            None => {
                let what = format!(
                    "the wear offsets are P1 to P{table} and the geometry offsets P{} to P{} (10000 + the number)",
                    GEOMETRY_P + 1,
                    GEOMETRY_P + table
                );
                let p = self.g10_p(b, 0..=GEOMETRY_P + table, &what)?;
                if p == 0 {
                    return Err(self.error(
                        "g10-number",
                        b.get(P).map_or(b.span, |w| w.span),
                        "G10 P0 sets the workpiece coordinate system shift (Fanuc), which offsetlab does not model: G10 L2 P0 sets the external work offset",
                    ));
                }
                match p {
                    p if p <= table => (p, false),
                    p if p > GEOMETRY_P => (p - GEOMETRY_P, true),
                    p => {
                        return Err(self.error(
                            "g10-number",
                            b.get(P).map_or(b.span, |w| w.span),
                            format!("G10 P{p}: {what} ({PS0031})"),
                        ));
                    }
                }
            }
        };
        let n = n as u16;
        for (abs, inc) in [(X, U), (Z, W), (R, C)] {
            if let (Some(a), Some(i)) = (b.get(abs), b.get(inc)) {
                let at = if a.span.start > i.span.start { a } else { i };
                return Err(self.error(
                    "g10-words",
                    at.span,
                    format!(
                        "{} and {} both set one value in a G10 block: {} sets it, {} adds to it; write one of them",
                        abs.letter(),
                        inc.letter(),
                        abs.letter(),
                        inc.letter()
                    ),
                ));
            }
        }
        if ![X, U, Z, W, R, C, Q].iter().any(|a| b.has(*a)) {
            return Err(self.error(
                "g10-words",
                b.span,
                format!(
                    "G10 P{}: no value to set (X/U, Z/W, R/C or Q) ({PS0031})",
                    b.get(P).map_or(0, Word::int)
                ),
            ));
        }
        // In G-code system B/C, G91 makes X, Z and R add as U, W and C do
        // (behaviour 7.18; our convention for G10).
        let g91 = self.state.modal.distance == Distance::Incremental;
        let mut reg = self.setup.lathe_register(n);
        let mut changes = Vec::new();
        let part = if geometry { "geometry" } else { "wear" };
        let fields: [(Address, Address, &'static str, &'static str, &'static str); 3] = [
            (X, U, "x", "x_wear", "X"),
            (Z, W, "z", "z_wear", "Z"),
            (R, C, "r", "r_wear", "R"),
        ];
        for (abs, inc, g_key, w_key, name) in fields {
            let (w, add) = match (b.get(abs), b.get(inc)) {
                (Some(w), _) => (w, g91),
                (None, Some(w)) => (w, true),
                (None, None) => continue,
            };
            let key = if geometry { g_key } else { w_key };
            let slot = match key {
                "x" => &mut reg.x,
                "x_wear" => &mut reg.x_wear,
                "z" => &mut reg.z,
                "z_wear" => &mut reg.z_wear,
                "r" => &mut reg.r,
                _ => &mut reg.r_wear,
            };
            let was = *slot;
            let label = format!("offset {n:02} {name} {part}");
            let v = self.g10_value(
                w,
                &label,
                if add { was + w.value } else { w.value },
                MAX_OFFSET_VALUE,
            )?;
            *slot = v;
            changes.push((key, format!("{name} {part}"), v, clean(was)));
        }
        if let Some(q) = b.get(Q) {
            let Some(t) = self.tip_of(q) else {
                return Err(self.error(
                    "g10-words",
                    q.span,
                    format!("G10 Q is the imaginary tool tip direction, a whole number 0 to {MAX_TIP} ({PS0031})"),
                ));
            };
            changes.push(("t", "tip T".to_string(), f64::from(t), f64::from(reg.t)));
            reg.t = t;
        }
        Arc::make_mut(&mut self.setup).lathe_offsets.insert(n, reg);
        let mut said = Vec::new();
        for (key, name, v, was) in changes {
            let show = |x: f64| {
                if key == "t" {
                    format!("{x}")
                } else {
                    self.g10_show(x)
                }
            };
            said.push(format!("{name} = {} (was {})", show(v), show(was)));
            out.events.push(EventKind::DataSet(DataSet {
                table: "lathe_offsets",
                key: format!("{n:02}"),
                field: key,
                value: v,
                was,
            }));
        }
        let mut note = format!("{}: offset {n:02} {}", self.g10_text(b), said.join(", "));
        if self.state.lathe.offset == n {
            note.push_str(&format!(
                "; offset {n:02} is in force with its old values until a T code names it again"
            ));
        }
        out.notes.push(note);
        Ok(())
    }

    /// The imaginary tool tip direction of a lathe G10's Q: a digit 0–9.
    /// Q is read as a dimension word (behaviour 1.15): without a decimal
    /// point in least increments, so `Q3` is taken back to 3, as G05.1's Q
    /// is (behaviour 14.4).
    fn tip_of(&self, q: &Word) -> Option<u8> {
        let increments = self.setup.settings.decimal_input() == DecimalInput::Increment && !q.point;
        let v = if increments {
            q.value * 10f64.powi(self.units().decimals() as i32)
        } else {
            q.value
        };
        let t = v.round();
        ((v - t).abs() < 1e-6 && (0.0..=f64::from(MAX_TIP)).contains(&t)).then_some(t as u8)
    }

    /// `G10 L2 P0–P6` (external, G54–G59) and `G10 L20 P…` (the additional
    /// systems) (behaviour 17.9): the zero points, as machine positions in
    /// the setup's units. A change to the system in force moves its zero
    /// at once: the tool stays, its coordinates change.
    fn g10_work(&mut self, b: &Block, extended: bool, out: &mut Out) -> Result<(), Diagnostic> {
        let lathe = self.setup.machine == MachineKind::Lathe;
        let l = if extended { 20 } else { 2 };
        let (allowed, axes): (&[Address], &[WorkAxis]) = if lathe {
            (
                &[N, G, L, P, X, Z, U, W],
                &[(X, Some(U), 0, "x"), (Z, Some(W), 2, "z")],
            )
        } else {
            (
                &[N, G, L, P, X, Y, Z],
                &[(X, None, 0, "x"), (Y, None, 1, "y"), (Z, None, 2, "z")],
            )
        };
        self.g10_only(
            b,
            allowed,
            &format!(
                "G10 L{l} sets a work offset with P and the zero point's {}",
                if lathe {
                    "X and Z (U and W add)"
                } else {
                    "X, Y and Z"
                }
            ),
        )?;
        let setting = self.setup.settings.extended_work_offsets();
        let (p, key, name) = if extended {
            let (max, code) = match setting {
                ExtendedWork::G54_1 => (MAX_ADDITIONAL_WORK, "G54.1"),
                ExtendedWork::G154 => (MAX_HAAS_WORK, "G154"),
            };
            let p = self.g10_p(
                b,
                1..=u32::from(max),
                &format!(
                    "the additional systems are {code} P1 to P{max} (setting extended_work_offsets)"
                ),
            )?;
            (p as usize, format!("{p:02}"), format!("{code} P{p}"))
        } else {
            let p = self.g10_p(
                b,
                0..=6,
                "P0 is the external work offset, P1 to P6 G54 to G59",
            )? as usize;
            let name = WorkOffsets::name_of_p(p);
            (p, name.to_string(), name.to_string())
        };
        if !axes
            .iter()
            .any(|(a, i, _, _)| b.has(*a) || i.is_some_and(|i| b.has(i)))
        {
            return Err(self.error(
                "g10-words",
                b.span,
                format!("G10 L{l} P{p}: no axis to set ({PS0031})"),
            ));
        }
        let g91 = self.state.modal.distance == Distance::Incremental;
        let unit = self.setup.units;
        let max = unit.max_dimension();
        let mut zero = if extended {
            self.setup
                .extended_work_offsets
                .get(&(p as u16))
                .copied()
                .unwrap_or_default()
        } else {
            self.setup.work_offsets.by_p(p)
        };
        let mut said = Vec::new();
        let mut sets = Vec::new();
        for &(abs, inc, axis, field) in axes {
            let (w, add) = match (b.get(abs), inc.and_then(|i| b.get(i))) {
                (Some(a), Some(i)) => {
                    let at = if a.span.start > i.span.start { a } else { i };
                    return Err(self.error(
                        "g10-words",
                        at.span,
                        format!(
                            "{} and {} both set the {} zero in one block: write one of them",
                            abs.letter(),
                            i.address.letter(),
                            abs.letter()
                        ),
                    ));
                }
                (Some(w), None) => (w, g91),
                (None, Some(w)) => (w, true),
                (None, None) => continue,
            };
            let slot = match axis {
                0 => &mut zero.x,
                1 => &mut zero.y,
                _ => &mut zero.z,
            };
            let was = *slot;
            // The word is in the program's units, the setup in its own.
            let v = self.mm(w.value) / unit.mm();
            let d = unit.decimals();
            let label = format!("{name} {}", abs.letter());
            let new = self.g10_value(w, &label, if add { was + v } else { v }, max)?;
            *slot = new;
            said.push(format!("{} = {new:.d$} (was {was:.d$})", abs.letter()));
            sets.push((field, new, clean(was)));
        }
        let setup = Arc::make_mut(&mut self.setup);
        if extended {
            setup.extended_work_offsets.insert(p as u16, zero);
        } else {
            *setup.work_offsets.by_p_mut(p) = zero;
        }
        let table = if extended {
            "extended_work_offsets"
        } else {
            "work_offsets"
        };
        for (field, value, was) in sets {
            out.events.push(EventKind::DataSet(DataSet {
                table,
                key: key.clone(),
                field,
                value,
                was,
            }));
        }
        let mut note = format!(
            "{}: {name} zero {} (a machine position in {}{})",
            self.g10_text(b),
            said.join(", "),
            unit.as_str(),
            if g91 { "; G91 adds the words" } else { "" }
        );
        let work = self.state.modal.work;
        let in_force = match (extended, work) {
            (false, _) if p == 0 => true,
            (false, w) => w.index() == Some(p - 1),
            (true, WorkSystem::Additional(n) | WorkSystem::Haas(n)) => usize::from(n) == p,
            (true, _) => false,
        };
        if in_force {
            self.select_work(work);
            note.push_str(&format!(
                "; {} is in force: its zero moves now, the tool stays and its position reads {}",
                work.gcode(),
                self.show_point(self.state.programmed)
            ));
        }
        out.notes.push(note);
        Ok(())
    }
}
