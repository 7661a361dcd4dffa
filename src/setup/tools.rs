//! The tool list of the setup (behaviour 13.16 and 7.53): what each tool
//! is physically — a mill cutter's diameter, a lathe insert's nose radius
//! and tip, and its length — for drawing the tool at its size. It does not
//! feed compensation: G41/G42 and G43 read the D and H registers (and the
//! lathe the offset part of T) as the control does.

use serde::{Deserialize, Serialize};

use super::registers::{MAX_TIP, parse_register_number};
use super::specs::{spec_number, spec_tip};
use super::{MAX_OFFSET_VALUE, Setup, is_zero, setup_error};
use crate::diag::Diagnostic;

/// Highest tool number of the list (a four-digit T word).
pub const MAX_TOOL: u16 = 9999;

/// One tool of the list; every part left out is 0 (not known).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Tool {
    /// The mill cutter's diameter.
    #[serde(skip_serializing_if = "is_zero")]
    pub diameter: f64,
    /// The lathe insert's nose radius.
    #[serde(skip_serializing_if = "is_zero")]
    pub nose_radius: f64,
    /// The lathe insert's imaginary tool nose direction, 0–9 (18.2).
    #[serde(skip_serializing_if = "is_tip_zero")]
    pub tip: u8,
    /// Its length (gauge line to tip, or the holder's overhang).
    #[serde(skip_serializing_if = "is_zero")]
    pub length: f64,
}

fn is_tip_zero(t: &u8) -> bool {
    *t == 0
}

impl Setup {
    /// The tool list's entry for tool `n`, if it has one.
    pub fn tool(&self, n: u32) -> Option<&Tool> {
        u16::try_from(n).ok().and_then(|n| self.tools.get(&n))
    }

    /// Sets one tool from a command-line style spec (behaviour 7.53):
    /// `N=D<diameter>,L<length>` on the mill (`1=D10,L120`),
    /// `N=R<nose radius>,T<tip>,L<length>` on the lathe (`1=R0.8,T3`);
    /// parts left out are 0, and a spec replaces the tool's entry.
    pub fn set_tool(&mut self, spec: &str) -> Result<(), String> {
        let (num, value) = spec
            .split_once('=')
            .ok_or_else(|| format!("tool `{spec}`: expected N=D<diameter>,L<length>"))?;
        let n = parse_register_number(num)
            .ok()
            .filter(|n| (1..=MAX_TOOL).contains(n))
            .ok_or_else(|| format!("tool `{spec}`: the tool number is 1 to {MAX_TOOL}"))?;
        let number = |t: &str| spec_number("tool", spec, t);
        let mut tool = Tool::default();
        for part in value.split(',').filter(|p| !p.trim().is_empty()) {
            let p = part.trim().to_ascii_uppercase();
            if let Some(v) = p.strip_prefix('D') {
                tool.diameter = number(v)?;
            } else if let Some(v) = p.strip_prefix('R') {
                tool.nose_radius = number(v)?;
            } else if let Some(v) = p.strip_prefix('L') {
                tool.length = number(v)?;
            } else if let Some(v) = p.strip_prefix('T') {
                tool.tip = spec_tip("tool", spec, v)?;
            } else {
                return Err(format!(
                    "tool `{spec}`: a tool is N=D<diameter>,L<length> (mill) or N=R<nose radius>,T<0–9>,L<length> (lathe)"
                ));
            }
        }
        self.tools.insert(n, tool);
        Ok(())
    }

    /// The tool list's problems (part of [`Setup::validate`]).
    pub(super) fn validate_tools(&self, out: &mut Vec<Diagnostic>) {
        for (&n, t) in &self.tools {
            if n == 0 || n > MAX_TOOL {
                out.push(setup_error(
                    "setup-range",
                    format!("tool {n:02} is outside 1 to {MAX_TOOL}"),
                ));
            }
            for (what, v) in [
                ("diameter", t.diameter),
                ("nose_radius", t.nose_radius),
                ("length", t.length),
            ] {
                if !v.is_finite() || !(0.0..=MAX_OFFSET_VALUE + 1e-9).contains(&v) {
                    out.push(setup_error(
                        "setup-range",
                        format!("tool {n:02} {what} = {v} is outside 0 to {MAX_OFFSET_VALUE}"),
                    ));
                }
            }
            if t.tip > MAX_TIP {
                out.push(setup_error(
                    "setup-range",
                    format!("tool {n:02} tip = {} is outside 0 to {MAX_TIP}", t.tip),
                ));
            }
        }
    }

    /// The tool list as `--tool` specs, in tool order (plain links, 9.9).
    pub fn tool_specs(&self) -> Vec<String> {
        self.tools
            .iter()
            .map(|(n, t)| {
                let mut parts = Vec::new();
                if t.diameter != 0.0 {
                    parts.push(format!("D{}", t.diameter));
                }
                if t.nose_radius != 0.0 {
                    parts.push(format!("R{}", t.nose_radius));
                }
                if t.tip != 0 {
                    parts.push(format!("T{}", t.tip));
                }
                if t.length != 0.0 {
                    parts.push(format!("L{}", t.length));
                }
                format!("{n:02}:{}", parts.join(","))
            })
            .collect()
    }
}
