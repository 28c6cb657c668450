//! Tabular results under one output rule: a terminal gets a short aligned table, `--json`
//! (or a pipe) gets the whole result as JSON, and `-o FILE.csv` gets every row as CSV with
//! a sidecar (`FILE.json`: what wrote it, its provenance) beside it, written whole or not
//! at all (`afsv_records::Record::write`).

use crate::output::{OutputGuard, OutputKind};
pub use afsv_design::report::table::{number, text};
pub use afsv_records::json::{from_columns, from_rows};
use afsv_records::Record;
use serde_json::{json, Value};
use std::io::IsTerminal;
use std::path::PathBuf;

/// Rows shown at each end of a table on a terminal.
pub const TERMINAL_ROWS: usize = 8;

/// Where a tabular result goes: the `--json` and `-o` options a command flattens into its
/// own (the command's `--force` reaches the CSV through the [`OutputGuard`] it is declared
/// to).
#[derive(clap::Args, Debug, Clone, Default)]
pub struct TableOutput {
    /// Print the whole result as JSON, also on a terminal (a pipe always gets JSON).
    #[arg(long)]
    pub json: bool,
    /// Write every row as CSV here (a JSON sidecar is written beside it) and print a summary.
    #[arg(short = 'o', long = "output", value_name = "CSV")]
    pub csv: Option<PathBuf>,
}

impl TableOutput {
    /// Declare the CSV output (and its sidecar) to `guard` before anything is computed.
    pub fn declare(&self, guard: &mut OutputGuard) -> Result<(), String> {
        guard.output_if("-o", self.csv.as_deref(), OutputKind::Record)?;
        Ok(())
    }

    /// Emit a result: `table` is its rows as named numeric columns, `full` the whole result
    /// as JSON (the table and whatever else it carries), `summary` the lines a terminal
    /// shows above the table (may be empty), `written_by` the subcommand (e.g.
    /// `"afsv tire sweep"`), `meta` extra sidecar fields.
    pub fn emit(
        &self,
        table: &Record,
        full: &Value,
        summary: &str,
        written_by: &str,
        meta: Value,
    ) -> Result<(), Box<dyn std::error::Error>> {
        let terminal = !self.json && std::io::stdout().is_terminal();
        if let Some(path) = &self.csv {
            let mut rec = table.clone();
            rec.meta = meta;
            if !rec.meta.is_object() {
                rec.meta = json!({});
            }
            rec.meta["written_by"] = json!(written_by);
            crate::provenance::stamp_record(&mut rec);
            rec.write(path)?;
            if terminal {
                println!(
                    "wrote {} rows of {} columns to {} (sidecar {})",
                    rec.len(),
                    rec.names().len(),
                    path.display(),
                    path.with_extension("json").display()
                );
                print!("{summary}{}", text(table, TERMINAL_ROWS));
            } else {
                crate::output::print_json(&json!({
                    "output": path,
                    "sidecar": path.with_extension("json"),
                    "rows": rec.len(),
                    "columns": rec.names(),
                }))?;
            }
        } else if terminal {
            print!("{summary}{}", text(table, TERMINAL_ROWS));
            println!(
                "({} rows; --json for the whole result, -o FILE.csv for every row as CSV)",
                table.len()
            );
        } else {
            crate::output::print_json(full)?;
        }
        Ok(())
    }
}
