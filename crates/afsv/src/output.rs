//! Output helpers shared by the CLI commands: JSON to stdout.

use serde::Serialize;
use std::io::Write;

/// Print `value` as pretty JSON on stdout.
///
/// A closed pipe (`afsv ... | head`) is not an error: the reader has what it wanted.
pub fn print_json<T: Serialize + ?Sized>(value: &T) -> Result<(), std::io::Error> {
    let text = serde_json::to_string_pretty(value)?;
    let mut out = std::io::stdout().lock();
    match writeln!(out, "{text}").and_then(|()| out.flush()) {
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        other => other,
    }
}
