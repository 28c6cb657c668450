//! Output helpers of the CLI commands: JSON to stdout with the run's provenance, and the
//! exit status of a result printed but not earned. The output guard and the JSON null rules
//! are library code (`afsv_records::guard`, `afsv_records::json`), re-exported here.

use serde::Serialize;
use std::io::{IsTerminal, Write};
use std::path::Path;

pub use afsv_records::guard::*;
pub use afsv_records::json::*;

/// Print `value` as pretty JSON on stdout; an object gets the run's `"provenance"`
/// ([`crate::provenance::stamp`]: tool, version, commit, input files with SHA-256).
///
/// No NaN or infinity is ever printed: serde_json already writes them as `null`, and every
/// `null` field (or array holding a `null`) that has no `"<field>_reason"` sibling gets one
/// ([`annotate_nulls`]). A closed pipe (`afsv ... | head`) is not an error: the reader has
/// what it wanted.
pub fn print_json<T: Serialize + ?Sized>(value: &T) -> Result<(), std::io::Error> {
    let mut v = serde_json::to_value(value)?;
    if let Some(obj) = v.as_object_mut() {
        obj.entry("provenance")
            .or_insert_with(crate::provenance::stamp);
    }
    annotate_nulls(&mut v);
    let text = serde_json::to_string_pretty(&v)?;
    let mut out = std::io::stdout().lock();
    match writeln!(out, "{text}").and_then(|()| out.flush()) {
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        other => other,
    }
}

/// [`print_json`] of `value` with `--json` (`json`) or when stdout is not a terminal, else
/// `text()` printed as it is (the readable form of the same result).
pub fn print_json_or_text<T: Serialize + ?Sized>(
    json: bool,
    value: &T,
    text: impl FnOnce() -> String,
) -> Result<(), std::io::Error> {
    if json || !std::io::stdout().is_terminal() {
        print_json(value)
    } else {
        print!("{}", text());
        Ok(())
    }
}

/// Write `text` to `path`, whole or not at all (`afsv_records::atomic::write`); the error
/// names the file.
pub fn write_file(path: &Path, text: impl AsRef<[u8]>) -> Result<(), String> {
    afsv_records::atomic::write(path, text).map_err(|e| format!("{}: {e}", path.display()))
}

/// Write `value` to `path` as pretty JSON with a final newline (a parameter file, as
/// `afsv params dump` prints one), through [`write_file`].
pub fn write_json_file<T: Serialize + ?Sized>(
    path: &Path,
    value: &T,
) -> Result<(), Box<dyn std::error::Error>> {
    Ok(write_file(
        path,
        serde_json::to_string_pretty(value)? + "\n",
    )?)
}

/// Exit status of a command that printed its result but did not earn it: a fit that ended
/// on a bound, did not converge or ended worse than its start (`afsv` exits with it; 1 is
/// an error with nothing printed, 2 a usage error).
pub const EXIT_NOT_EARNED: u8 = 3;

/// The error of a command whose result is printed but not earned ([`EXIT_NOT_EARNED`]);
/// the message says why, in one line.
#[derive(Debug)]
pub struct NotEarned(pub String);

impl std::fmt::Display for NotEarned {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for NotEarned {}

/// `Ok` when a fit has no `problems` or they are `accepted` (`--accept-poor-fit`), else
/// [`NotEarned`] naming `command` (e.g. `hps identify`) and the problems.
pub fn fit_earned(command: &str, problems: &[String], accepted: bool) -> Result<(), NotEarned> {
    if problems.is_empty() || accepted {
        Ok(())
    } else {
        Err(NotEarned(format!("{command}: {}", problems.join("; "))))
    }
}
