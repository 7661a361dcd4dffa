//! LinuxCNC's tool table at run time (behaviour 22.9): T must name a tool
//! of the table, M61 Q sets the tool in the spindle, G43 (H or the tool in
//! the spindle), G43.1 and G43.2 read the tool's offsets, G41/G42 D half its
//! diameter, G41.1/G42.1 D the diameter written, and G10 L1/L10/L11 change
//! an entry. Without a table the linuxcnc profile reads the registers, as
//! the other profiles do (LinuxCNC 2.9 documentation, "Tool Table Format",
//! "G43", "G43.1", "G43.2", "G41, G42", "G41.1, G42.1", "G10 L1", "G10 L10",
//! "G10 L11", "M61"; `rs274 -g` on `tests/linuxcnc/t*.ngc`).

use std::sync::Arc;

use super::{Machine, Out};
use crate::diag::{Diagnostic, Span};
use crate::offsets::cutter::Phase;
use crate::offsets::length::LengthState;
use crate::setup::{Control, MachineKind, OFFSET_AXES, TableTool};
use crate::syntax::codes::{CutterCompensation, Group, LengthOffset, MCode};
use crate::syntax::{Address, Block, Word};

impl Machine {
    /// True under the linuxcnc profile with a tool table.
    pub(super) fn has_tool_table(&self) -> bool {
        self.setup.settings.control == Control::Linuxcnc && self.setup.tool_table.is_some()
    }

    /// Millimetres in one unit of the table (its own units, a LinuxCNC
    /// machine's, whatever the program's G20/G21).
    fn table_mm(&self) -> f64 {
        self.setup.tool_table_units().mm()
    }

    /// Tool `n` of the table: None for tool 0 (no tool: every offset 0), an
    /// error at `span` for a tool the table does not hold (rs274:
    /// "Requested tool N not found in the tool table").
    fn table_tool(&self, n: u32, span: Span, word: &str) -> Result<Option<&TableTool>, Diagnostic> {
        if n == 0 {
            return Ok(None);
        }
        let table = self.setup.tool_table.as_ref();
        match table.and_then(|t| t.tools.get(&n)) {
            Some(t) => Ok(Some(t)),
            None => Err(self.error(
                "tool-not-in-table",
                span,
                format!(
                    "{word}: tool {n} is not in the tool table (LinuxCNC: \"Requested tool {n} not found in the tool table\"); add it to the table or use one of its tools"
                ),
            )),
        }
    }

    /// The number a T, H, D or Q word gives a tool: whole and not negative
    /// (rs274: "Negative tool id", "Non integer value for integer").
    fn tool_number(&self, w: &Word, what: &str) -> Result<u32, Diagnostic> {
        let v = w.value;
        if v < 0.0 || v.fract() != 0.0 || v > f64::from(crate::setup::MAX_TABLE_TOOL) {
            return Err(self.error(
                "tool-number",
                w.span,
                format!(
                    "{}{}: {what} is a tool number, a whole number 0 to {}",
                    w.address.letter(),
                    v,
                    crate::setup::MAX_TABLE_TOOL
                ),
            ));
        }
        Ok(v as u32)
    }

    /// A block's T under a tool table: the tool must be in it.
    pub(super) fn table_t_word(&self, w: &Word) -> Result<u32, Diagnostic> {
        let n = self.tool_number(w, "T")?;
        self.table_tool(n, w.span, &format!("T{n}"))?;
        Ok(n)
    }

    /// `M61 Q…` (LinuxCNC): the tool in the spindle becomes Q without a
    /// change; with a table, Q must be one of its tools.
    pub(super) fn m61(&mut self, b: &Block, span: Span, out: &mut Out) -> Result<(), Diagnostic> {
        let Some(q) = b.get(Address::Q) else {
            return Err(self.error(
                "m61-words",
                span,
                "M61 needs Q, the number of the tool now in the spindle (LinuxCNC: \"Need non-negative Q-word to specify tool number with M61\")",
            ));
        };
        let n = self.tool_number(q, "M61's Q")?;
        if self.setup.tool_table.is_some() {
            self.table_tool(n, q.span, &format!("M61 Q{n}"))?;
        }
        self.state.tool = n;
        out.notes.push(format!(
            "M61 Q{n}: the spindle holds tool {n} from here, with no tool change (LinuxCNC)"
        ));
        Ok(())
    }

    /// M6 and M61 under linuxcnc (behaviour 22.9): M6 is refused while
    /// G41/G42 is on; after a G40 that has not yet moved the tool off the
    /// offset path, both take the position from where the tool is (rs274
    /// re-reads the machine's position after a tool change), so the vector
    /// ends there without a move and the next block starts from the offset
    /// path's end.
    pub(super) fn linuxcnc_tool_change_position(
        &mut self,
        b: &Block,
        out: &mut Out,
    ) -> Result<(), Diagnostic> {
        let Some(m6) = b.mcodes(MachineKind::Mill).find_map(|m| match m {
            MCode::ToolChange => Some(true),
            MCode::Other(61) => Some(false),
            _ => None,
        }) else {
            return Ok(());
        };
        let c = &mut self.state.cutter;
        if c.mode != CutterCompensation::Cancel {
            if m6 {
                return Err(self.error(
                    "tool-change-in-compensation",
                    b.span,
                    "M6 with G41/G42 on: LinuxCNC changes tools only with compensation off (rs274: \"Cannot change tools with cutter radius compensation on\"); give G40 and a move first",
                ));
            }
            return Ok(());
        }
        if c.vector == [0.0; 3] {
            return Ok(());
        }
        let v = std::mem::take(&mut c.vector);
        c.phase = Phase::Cancel;
        for (p, d) in self.state.programmed.iter_mut().zip(v) {
            *p += d;
        }
        let m = if m6 { "M6" } else { "M61" };
        out.notes.push(format!(
            "{m} after G40: LinuxCNC reads the position again from where the tool is, on the offset path's end, so the compensation's vector ends here without a move and the next block starts from this point"
        ));
        Ok(())
    }

    /// The length (mm) G43 or G43.2 takes from tool `n`: its Z offset. A
    /// tool with an offset along another axis is refused, as offsetlab's
    /// mill offsets the length along Z only.
    fn tool_length(&self, n: u32, span: Span, word: &str) -> Result<f64, Diagnostic> {
        if !self.has_tool_table() {
            return Ok(self.mm(self.setup.h_value(u16::try_from(n).unwrap_or(u16::MAX))));
        }
        let Some(t) = self.table_tool(n, span, word)? else {
            return Ok(0.0);
        };
        if let Some((axis, v)) = OFFSET_AXES
            .iter()
            .zip(t.offsets)
            .find(|(a, v)| **a != 'Z' && *v != 0.0)
        {
            return Err(self.error(
                "tool-offset-axis",
                span,
                format!(
                    "{word}: tool {n}'s {axis} offset {} is not modelled: offsetlab's mill applies a tool's length along Z only",
                    v
                ),
            ));
        }
        Ok(t.z() * self.table_mm())
    }

    /// G43/G43.1/G43.2/G49 and H under linuxcnc: G43 without H is the tool
    /// in the spindle; G43.1 Z is the offset itself and G43.2 adds a tool's
    /// (H) or the Z written; H alone is refused ("H word with no G43 or
    /// G43.2 to use it"). Returns the state before the block.
    pub(super) fn linuxcnc_length(&mut self, b: &Block) -> Result<LengthState, Diagnostic> {
        let code = b.codes().length();
        let h = b.get(Address::H);
        let old = self.state.length;
        if code.is_none() && h.is_none() {
            return Ok(old);
        }
        let span = b.code_span(Group::Length);
        let Some(code) = code else {
            let h = h.map_or(span, |w| w.span);
            return Err(self.error(
                "h-without-g43",
                h,
                "H with no G43 or G43.2 to use it: under LinuxCNC H goes with G43 or G43.2 (\"H word with no G43 or G76 to use it\")",
            ));
        };
        let tool = match h {
            Some(w) => self.tool_number(w, "H")?,
            None => self.state.tool,
        };
        let word = match h {
            Some(_) => format!("{} H{tool}", code.gcode()),
            None => format!("{} (tool {tool} in the spindle)", code.gcode()),
        };
        let z = b.value(Address::Z).map(|v| self.mm(v));
        let (sign, h_number, value) = match code {
            LengthOffset::Add => (1, tool, self.tool_length(tool, span, &word)?),
            // The axes G43.1 leaves out keep their offset (rs274 -g).
            LengthOffset::Dynamic => {
                self.refuse_g43_axes(b)?;
                (1, 0, z.unwrap_or(self.state.length.target))
            }
            LengthOffset::AddTool => {
                self.refuse_g43_axes(b)?;
                let base = self.state.length.target;
                // The documentation lets G43.2 add the axis words written;
                // rs274 refuses G43.2 without H ("Requested tool -1 not
                // found"), and its output is followed (behaviour 22.9).
                let Some(_) = h else {
                    return Err(self.error(
                        "g43-2-words",
                        span,
                        "G43.2 needs H, the tool whose offset is added (rs274 refuses G43.2 without H: \"Requested tool -1 not found in the tool table\")",
                    ));
                };
                let add = self.tool_length(tool, span, &word)?;
                (1, u32::from(self.state.length.h), base + add)
            }
            LengthOffset::Cancel | LengthOffset::Subtract => (0, 0, 0.0),
        };
        // LinuxCNC moves nothing for the change: the machine stays, and the
        // position now reads from the new tool tip (rs274 -g: the next
        // canonical Z is the old one + old offset − new offset), so a G91
        // move goes on from there and a G90 Z lands offset.
        let actual_z = self.state.programmed[2] + self.state.length.vector;
        let l = &mut self.state.length;
        l.take_at_once(sign, u16::try_from(h_number).unwrap_or(u16::MAX), value);
        self.state.programmed[2] = actual_z - l.target;
        self.state.modal.length = code;
        Ok(old)
    }

    /// The sentence of a length offset change under linuxcnc: what the
    /// offset is now and where the position reads, the machine unmoved.
    #[inline(never)]
    pub(super) fn linuxcnc_length_note(&self, old: &LengthState, out: &mut Out) {
        let new = self.state.length;
        let units = self.units();
        let f = |mm: f64| crate::geometry::show(mm, units);
        let what = match (new.sign, self.state.modal.length) {
            (0, _) => "G49: no tool length offset".to_string(),
            (_, LengthOffset::Dynamic) => {
                format!("G43.1: the tool length offset is Z {}", f(new.target))
            }
            (_, LengthOffset::AddTool) => format!(
                "G43.2 adds tool {}: the offset is Z {}",
                new.h,
                f(new.target)
            ),
            _ => format!("G43 tool {}: the offset is Z {}", new.h, f(new.target)),
        };
        let shift = new.vector - old.vector;
        out.notes.push(format!(
            "{what}; the machine stays and the position reads from the new tip: Z {} → {} (LinuxCNC moves nothing for it)",
            f(self.state.programmed[2] + shift),
            f(self.state.programmed[2])
        ));
    }

    /// G43.1/G43.2 read Z as an offset; an axis word of another axis would
    /// offset an axis offsetlab's mill does not offset.
    fn refuse_g43_axes(&self, b: &Block) -> Result<(), Diagnostic> {
        match b
            .words
            .iter()
            .find(|w| matches!(w.address, Address::X | Address::Y | Address::A | Address::B | Address::C))
        {
            Some(w) => Err(self.error(
                "tool-offset-axis",
                w.span,
                format!(
                    "{}: {} offsets Z only on offsetlab's mill: a tool offset along {} is not modelled",
                    w.address.letter(),
                    b.codes().length().map_or("G43.1", LengthOffset::gcode),
                    w.address.letter()
                ),
            )),
            None => Ok(()),
        }
    }

    /// True when the block's axis words are G43.1's or G43.2's offsets, not
    /// a move.
    pub(super) fn axes_are_offsets(&self, b: &Block) -> bool {
        matches!(
            b.codes().length(),
            Some(LengthOffset::Dynamic | LengthOffset::AddTool)
        )
    }

    /// D under linuxcnc: on a G41/G42 block the tool whose half diameter
    /// compensation offsets by (without D, the tool in the spindle); on
    /// G41.1/G42.1 the diameter itself; anywhere else an error ("D word
    /// with no G41, G41.1, G42, G42.1 … to use it").
    pub(super) fn linuxcnc_d(&mut self, b: &Block) -> Result<(), Diagnostic> {
        let cutter = b.codes().cutter();
        let d = b.get(Address::D);
        let on = cutter.is_some_and(|c| c != CutterCompensation::Cancel);
        if !on {
            return match d {
                Some(w) => Err(self.error(
                    "d-without-g41",
                    w.span,
                    "D with no G41, G42, G41.1 or G42.1 to use it: under LinuxCNC D goes with the block that turns compensation on",
                )),
                None => Ok(()),
            };
        }
        let dynamic = b
            .group_word(Group::Cutter)
            .is_some_and(|w| w.gcode().minor == 1);
        if dynamic {
            let Some(w) = d else {
                return Err(self.error(
                    "g41-1-words",
                    b.code_span(Group::Cutter),
                    "G41.1/G42.1 needs D, the tool's diameter (LinuxCNC: \"G41.1 with no D word\")",
                ));
            };
            if w.value < 0.0 {
                return Err(self.error(
                    "g41-1-words",
                    w.span,
                    format!("D{}: the diameter is not negative", w.value),
                ));
            }
            self.state.table_radius = Some(self.mm(w.value) / 2.0);
            return Ok(());
        }
        self.state.table_radius = None;
        if !self.has_tool_table() {
            // The registers stand for the table: G41 without D reads the
            // register of the tool in the spindle.
            if d.is_none() {
                let n = u16::try_from(self.state.tool).unwrap_or(u16::MAX);
                let value = self.mm(self.setup.d_value(n));
                self.state.position.select(n, value);
            }
            return Ok(());
        }
        // D0, like no D, is the tool in the spindle (rs274 -g: the spindle
        // is the table's entry 0).
        let (n, span) = match d {
            Some(w) => (self.tool_number(w, "D")?, w.span),
            None => (0, b.code_span(Group::Cutter)),
        };
        let n = if n == 0 { self.state.tool } else { n };
        let diameter = self
            .table_tool(n, span, &format!("D{n}"))?
            .map_or(0.0, |t| t.diameter);
        self.state.table_radius = Some(diameter * self.table_mm() / 2.0);
        Ok(())
    }

    /// `G10 L1/L10/L11 P… [X Z R I J Q]` under a tool table: sets tool P's
    /// entry (LinuxCNC 2.9, "G10 L1", "G10 L10", "G10 L11"). L1 writes the
    /// values; L10 and L11 write the offset that makes the current point
    /// read the value given, L10 with the work offsets and G92 in force,
    /// L11 without them. R is the radius (the diameter is twice it); words
    /// left out keep the entry's value.
    pub(super) fn g10_table(&mut self, b: &Block, l: u32, out: &mut Out) -> Result<(), Diagnostic> {
        let p = b.get(Address::P).ok_or_else(|| {
            self.error(
                "g10-words",
                b.span,
                format!("G10 L{l} needs P, the tool whose entry it sets"),
            )
        })?;
        let n = self.tool_number(p, "G10's P")?;
        let mut tool = self
            .table_tool(n, p.span, &format!("G10 L{l} P{n}"))?
            .cloned()
            .ok_or_else(|| {
                self.error(
                    "tool-number",
                    p.span,
                    "G10 L1 P0: tool 0 has no entry to set",
                )
            })?;
        let per_table = 1.0 / self.table_mm();
        for w in &b.words {
            let v = self.mm(w.value) * per_table;
            match w.address {
                Address::N | Address::G | Address::L | Address::P => {}
                Address::R => tool.diameter = 2.0 * v,
                Address::I => tool.front_angle = w.value,
                Address::J => tool.back_angle = w.value,
                Address::Q => tool.orientation = self.tool_number(w, "Q")?.min(9) as u8,
                Address::Z => tool.offsets[2] = self.g10_table_z(l, self.mm(w.value)) * per_table,
                Address::X | Address::Y => {
                    return Err(self.error(
                        "tool-offset-axis",
                        w.span,
                        format!(
                            "G10 L{l} {}: a tool offset along {} is not modelled on offsetlab's mill, which offsets Z only",
                            w.address.letter(),
                            w.address.letter()
                        ),
                    ));
                }
                other => {
                    return Err(self.error(
                        "g10-words",
                        w.span,
                        format!(
                            "{}: G10 L{l} reads P, R, I, J, Q and the axis words",
                            other.letter()
                        ),
                    ));
                }
            }
        }
        let text = format!(
            "G10 L{l}: tool {n} now has Z {} and diameter {} (table units)",
            tool.z(),
            tool.diameter
        );
        let setup = Arc::make_mut(&mut self.setup);
        if let Some(t) = setup.tool_table.as_mut() {
            t.tools.insert(n, tool);
        }
        out.notes.push(text);
        Ok(())
    }

    /// The Z offset (mm) G10 L10/L11 give a tool so that the current point
    /// reads `value` with it: the machine Z less `value`, less the work
    /// offset and G92 shift for L10; L1 writes `value` itself.
    fn g10_table_z(&self, l: u32, value: f64) -> f64 {
        if l == 1 {
            return value;
        }
        // The actual point is the programmed one plus the length vector in
        // force; the machine point adds the work offsets to it.
        let work_z = self.state.programmed[2] + self.state.length.vector;
        match l {
            10 => work_z - value,
            _ => work_z + self.state.coords.zero[2] - value,
        }
    }
}
