//! The register specs of `--offset` and of plain links' `offset=` key
//! (behaviour 7.13, 7.14, 17.4): one register a spec, in the forms the
//! README lists.

use super::registers::{MAX_TIP, MillPart, parse_register_number};
use super::{LatheRegister, MachineKind, MillRegister, Setup};

/// Which table of a mill number a spec sets.
#[derive(Clone, Copy, PartialEq, Eq)]
enum MillTable {
    /// `NN=…`: the number's one value (memory A), geometry and wear (B),
    /// or H and D alike (C).
    Both,
    /// `HNN=…`: memory C's H table.
    H,
    /// `DNN=…`: memory C's D table.
    D,
}

/// A spec part's number (`kind` names the spec in the message: `offset`
/// or `tool`).
pub(super) fn spec_number(kind: &str, spec: &str, t: &str) -> Result<f64, String> {
    let t = t.trim();
    t.parse::<f64>()
        .ok()
        .filter(|v| v.is_finite() && !t.is_empty())
        .ok_or_else(|| format!("{kind} `{spec}`: `{t}` is not a number"))
}

/// A spec's tip direction `T`: a whole number 0 to 9 (behaviour 18.2).
pub(super) fn spec_tip(kind: &str, spec: &str, v: &str) -> Result<u8, String> {
    v.trim()
        .parse::<u8>()
        .ok()
        .filter(|t| *t <= MAX_TIP)
        .ok_or_else(|| {
            format!("{kind} `{spec}`: the tip direction T is a whole number 0 to {MAX_TIP}")
        })
}

impl Setup {
    /// Sets one register from a command-line style spec. Mill: `NN=VALUE`
    /// (`01=5.0`, `1=-2.5`), with wear `NN=VALUE,W<wear>`; in offset memory
    /// C the H or the D table alone, `H01=120.` / `D01=5.,W-0.02`. Lathe:
    /// `NN=X<v>,Z<v>` (`08=X0.4,Z-0.2`), with `XW<v>`/`ZW<v>` wear, the nose
    /// radius `R<v>` and its wear `RW<v>`, and the tip direction `T<0–9>`
    /// (`05=R0.8,T3`); parts left out of a lathe spec are 0.
    pub fn set_register(&mut self, spec: &str) -> Result<(), String> {
        let (num, value) = spec
            .split_once('=')
            .ok_or_else(|| format!("offset `{spec}`: expected NN=VALUE"))?;
        let num = num.trim();
        let (table, digits) = match num.as_bytes().first() {
            Some(b'H' | b'h') => (MillTable::H, &num[1..]),
            Some(b'D' | b'd') => (MillTable::D, &num[1..]),
            _ => (MillTable::Both, num),
        };
        if table != MillTable::Both && self.machine == MachineKind::Lathe {
            return Err(format!(
                "offset `{spec}`: the lathe's registers are numbered NN (the offset part of T), not H or D"
            ));
        }
        let n = parse_register_number(digits).map_err(|e| format!("offset `{spec}`: {e}"))?;
        let number = |t: &str| spec_number("offset", spec, t);
        match self.machine {
            MachineKind::Mill => {
                let mut part = MillPart::default();
                for (i, p) in value.split(',').enumerate() {
                    let upper = p.trim().to_ascii_uppercase();
                    if let Some(w) = upper.strip_prefix('W') {
                        part.wear = number(w)?;
                    } else if i == 0 {
                        part.geometry = number(upper.strip_prefix('G').unwrap_or(&upper))?;
                    } else {
                        return Err(format!(
                            "offset `{spec}`: mill registers are NN=VALUE or NN=VALUE,W<wear> (H or D before NN in offset memory C)"
                        ));
                    }
                }
                let reg = self.offsets.entry(n).or_default();
                match table {
                    MillTable::Both => *reg = MillRegister::new(part.geometry, part.wear),
                    MillTable::H => reg.set_h(part),
                    // Each keeps what the other table reads: a number
                    // written before as one value for both keeps it there.
                    MillTable::D => reg.set_d(part),
                }
            }
            MachineKind::Lathe => {
                let mut reg = LatheRegister::default();
                for part in value.split(',') {
                    let p = part.trim().to_ascii_uppercase();
                    if let Some(v) = p.strip_prefix("XW") {
                        reg.x_wear = number(v)?;
                    } else if let Some(v) = p.strip_prefix("ZW") {
                        reg.z_wear = number(v)?;
                    } else if let Some(v) = p.strip_prefix("RW") {
                        reg.r_wear = number(v)?;
                    } else if let Some(v) = p.strip_prefix('X') {
                        reg.x = number(v)?;
                    } else if let Some(v) = p.strip_prefix('Z') {
                        reg.z = number(v)?;
                    } else if let Some(v) = p.strip_prefix('R') {
                        reg.r = number(v)?;
                    } else if let Some(v) = p.strip_prefix('T') {
                        reg.t = spec_tip("offset", spec, v)?;
                    } else {
                        return Err(format!(
                            "offset `{spec}`: lathe registers are NN=X<v>,Z<v> (wear XW<v>, ZW<v>; nose radius R<v>, RW<v>; tip T<0–9>)"
                        ));
                    }
                }
                self.lathe_offsets.insert(n, reg);
            }
        }
        Ok(())
    }
}
