//! `run --format table`: one row per block — line, text, programmed and
//! actual position, what the offsets did — then the diagnostics.

use std::io::{self, Write};

use offsetlab::report::BlockReport;
use offsetlab::view::{BlockView, Pos};
use offsetlab::{MachineKind, Run};

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

fn pos_width(machine: MachineKind) -> usize {
    match machine {
        MachineKind::Mill => 32,
        MachineKind::Lathe => 22,
    }
}

pub fn header(out: &mut impl Write, machine: MachineKind) -> io::Result<()> {
    let pos_width = pos_width(machine);
    writeln!(
        out,
        "{:>5}  {:TEXT_WIDTH$}  {:pos_width$}  {:pos_width$}  OFFSETS",
        "LINE", "BLOCK", "PROGRAMMED", "ACTUAL"
    )
}

pub fn row(
    out: &mut impl Write,
    b: &BlockReport,
    v: &BlockView<'_>,
    machine: MachineKind,
) -> io::Result<()> {
    let pos_width = pos_width(machine);
    let d = b.state.modal.units.decimals();
    writeln!(
        out,
        "{:>5}  {}  {:pos_width$}  {:pos_width$}  {}",
        v.line,
        clip(v.text, TEXT_WIDTH),
        position(&v.programmed, d),
        position(&v.actual, d),
        v.explanation
    )
}

pub fn diagnostics(out: &mut impl Write, run: &Run) -> io::Result<()> {
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
