//! `run --format table`: one row per block — line, text, programmed and
//! actual position, what the offsets did — then the diagnostics.

use std::io::{self, Write};

use offsetlab::Run;
use offsetlab::view::{Pos, block_views};

const TEXT_WIDTH: usize = 34;

fn position(p: &Pos, decimals: usize) -> String {
    match p.y {
        Some(y) => format!("X{:.d$} Y{:.d$} Z{:.d$}", p.x, y, p.z, d = decimals),
        None => format!("X{:.d$} Z{:.d$}", p.x, p.z, d = decimals),
    }
}

fn clip(text: &str, width: usize) -> String {
    let n = text.chars().count();
    if n <= width {
        format!("{text:width$}")
    } else {
        let mut s: String = text.chars().take(width - 1).collect();
        s.push('…');
        s
    }
}

pub fn write(out: &mut impl Write, run: &Run, text: &str) -> io::Result<()> {
    let pos_width = if run.machine == offsetlab::MachineKind::Mill {
        32
    } else {
        22
    };
    writeln!(
        out,
        "{:>5}  {:TEXT_WIDTH$}  {:pos_width$}  {:pos_width$}  OFFSETS",
        "LINE", "BLOCK", "PROGRAMMED", "ACTUAL"
    )?;
    for (b, v) in run.blocks.iter().zip(block_views(run, text)) {
        let d = b.state.modal.units.decimals();
        writeln!(
            out,
            "{:>5}  {}  {:pos_width$}  {:pos_width$}  {}",
            v.line,
            clip(v.text, TEXT_WIDTH),
            position(&v.programmed, d),
            position(&v.actual, d),
            v.explanation
        )?;
    }
    if !run.diagnostics.is_empty() {
        writeln!(out)?;
    }
    for d in &run.diagnostics {
        writeln!(
            out,
            "{}:{}: {}[{}]: {}",
            d.line,
            d.column,
            d.severity.as_str(),
            d.code,
            d.message
        )?;
    }
    Ok(())
}
