//! LinuxCNC's named parameters (behaviour 22.6): `#<name>` local to the
//! level running, `#<_name>` global, and the predefined read-only ones
//! (`#<_x>`, `#<_metric>`, …), which read the machine's state through the
//! system variables that hold the same fact.
//!
//! Source: LinuxCNC 2.9 documentation, "Overview of the G-code language",
//! sections "Named Parameters" and "Predefined Named Parameters".

use crate::diag::{Diagnostic, Span};
use crate::machine::Machine;

/// A predefined named parameter's value; None for a name that is none.
/// Each reads the Fanuc system variable of the same fact (behaviour 20.10)
/// and writes it in LinuxCNC's terms (G codes ×10: `G17` is 170).
pub(super) fn predefined(
    machine: &Machine,
    name: &str,
    span: Span,
) -> Result<Option<f64>, Diagnostic> {
    let system = |n: u32| machine.read_system(n, span);
    let group = |n: u32| system(4000 + n);
    let is = |n: u32, code: f64| -> Result<Option<f64>, Diagnostic> {
        Ok(group(n)?.map(|g| f64::from(u8::from((g - code).abs() < 1e-9))))
    };
    let tens =
        |n: u32| -> Result<Option<f64>, Diagnostic> { Ok(group(n)?.map(|g| (g * 10.0).round())) };
    Ok(match name {
        "_x" => system(5001)?,
        "_y" => system(5002)?,
        "_z" => system(5003)?,
        "_a" | "_b" | "_c" | "_u" | "_v" | "_w" => Some(0.0),
        "_metric" => is(6, 21.0)?,
        "_imperial" => is(6, 20.0)?,
        "_absolute" => is(3, 90.0)?,
        "_incremental" => is(3, 91.0)?,
        "_inverse_time" => is(5, 93.0)?,
        "_units_per_minute" => is(5, 94.0)?,
        "_units_per_rev" => is(5, 95.0)?,
        "_motion_mode" => tens(1)?,
        "_plane" => tens(2)?,
        "_coord_system" => tens(14)?,
        "_ccomp" => tens(7)?,
        "_retract_r_plane" => is(10, 99.0)?,
        "_retract_old_z" => is(10, 98.0)?,
        "_feed" => system(4109)?,
        "_rpm" => system(4119)?,
        "_current_tool" | "_selected_tool" => system(4120)?,
        "_call_level" => Some(f64::from(machine.macro_level())),
        // The LinuxCNC version the profile follows (2.9).
        "_vmajor" => Some(2.0),
        "_vminor" => Some(9.0),
        _ => None,
    })
}

/// The names [`predefined`] knows, which a program may not set.
pub(super) fn is_predefined(machine: &Machine, name: &str) -> bool {
    name.starts_with('_')
        && predefined(machine, name, Span::new(0, 0, 0))
            .ok()
            .flatten()
            .is_some()
}
