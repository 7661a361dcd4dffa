//! `--tool-table FILE`: LinuxCNC's tool table file into the setup
//! (behaviour 22.9). Its problems name the file, line and column.

use std::path::Path;

use offsetlab::setup::ToolTable;

use super::{Fatal, read_text};

/// The most a tool table file may hold: far past any machine's carousel.
const MAX_TABLE_BYTES: usize = 4 << 20;

/// The table of the file at `path`; its warnings (a tool given twice) go
/// to standard error, its errors end the command.
pub(super) fn read_tool_table(path: &Path) -> Result<ToolTable, Fatal> {
    let name = format!("tool table {}", path.display());
    let file = std::fs::File::open(path).map_err(|e| Fatal(format!("cannot read {name}: {e}")))?;
    let text = read_text(&name, file, MAX_TABLE_BYTES)?;
    match ToolTable::parse(&text) {
        Ok((table, warnings)) => {
            for w in warnings {
                eprintln!(
                    "{}:{}:{}: warning[tool-table]: {}",
                    path.display(),
                    w.line,
                    w.column,
                    w.message
                );
            }
            Ok(table)
        }
        Err(errors) => Err(Fatal(
            errors
                .iter()
                .map(|p| {
                    format!(
                        "{}:{}:{}: error[tool-table]: {}",
                        path.display(),
                        p.line,
                        p.column,
                        p.message
                    )
                })
                .collect::<Vec<_>>()
                .join("\n"),
        )),
    }
}
