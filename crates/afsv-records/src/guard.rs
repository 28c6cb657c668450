//! The guard that keeps a command's outputs from replacing its inputs or each other, and
//! how a file the toolkit wrote is recognised (records, sidecars, SVG plots, JSON Lines).
//!
//! # Output rules ([`OutputGuard`])
//!
//! Every command that writes files declares its inputs and outputs to one [`OutputGuard`]
//! before it writes anything:
//!
//! 1. **No output is an input.** Paths are compared canonically: the file itself when it
//!    exists (symlinks followed), otherwise the canonical parent directory joined with the
//!    file name, so `x`, `./x`, `dir/../x` and a symlink to `x` are the same file. A record
//!    input (CSV) brings its sidecar (`.json` beside it) along as an input.
//! 2. **No two outputs are the same file**, including the sidecar a record output writes
//!    beside its CSV (so `-o y.json` for a CSV record is refused: its sidecar is `y.json`).
//! 3. **A sidecar never replaces a JSON file afsv did not write**, not even with `--force`.
//!    afsv wrote a JSON file when it is an object with `"sign_convention": "afsv-v1"` and a
//!    `"written_by"` (or, in older files of `terrain generate`, `"generator"`) string that
//!    starts with `afsv` ([`is_afsv_json`]). Any other existing JSON is foreign.
//! 4. **An output onto an existing file afsv did not write needs `--force`.** afsv wrote a
//!    CSV record when its sidecar is afsv-written (rule 3), an SVG when it carries the
//!    [`SVG_MARKER`] comment, a JSON per rule 3, a JSON Lines file when its first line is
//!    such a JSON object. Files afsv wrote may be replaced freely
//!    (re-running a command is normal).

use serde_json::Value;
use std::path::{Path, PathBuf};

/// Value of the `"written_by"` field afsv puts into every sidecar it writes (followed by the
/// subcommand, e.g. `"afsv yaw simulate"`).
pub const WRITTEN_BY: &str = "afsv";

/// The comment afsv puts at the top of every SVG it writes.
pub const SVG_MARKER: &str = "<!-- written_by: afsv -->";

/// The path a file is known by: canonical when it exists (symlinks followed), otherwise
/// the canonical parent directory joined with the file name (a dangling symlink resolves
/// to its target's path).
pub fn canonical_path(path: &Path) -> Result<PathBuf, String> {
    let mut p = path.to_path_buf();
    for _ in 0..40 {
        if let Ok(c) = std::fs::canonicalize(&p) {
            return Ok(c);
        }
        match std::fs::read_link(&p) {
            Ok(target) => {
                p = match p.parent() {
                    Some(parent) if target.is_relative() => parent.join(target),
                    _ => target,
                };
                continue;
            }
            Err(_) => break,
        }
    }
    let name = p
        .file_name()
        .ok_or_else(|| format!("{}: not a file name", path.display()))?;
    let parent = match p.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let dir = std::fs::canonicalize(&parent)
        .map_err(|e| format!("{}: directory {}: {e}", path.display(), parent.display()))?;
    Ok(dir.join(name))
}

/// True when `text` is a JSON object afsv wrote (rule 3 of the module documentation).
pub fn is_afsv_json(text: &str) -> bool {
    let Ok(Value::Object(map)) = serde_json::from_str::<Value>(text) else {
        return false;
    };
    let by = |k: &str| {
        map.get(k)
            .and_then(Value::as_str)
            .is_some_and(|s| s.starts_with(WRITTEN_BY))
    };
    map.get("sign_convention").and_then(Value::as_str) == Some(crate::SIGN_CONVENTION)
        && (by("written_by") || by("generator"))
}

/// What kind of file an output is (decides how "afsv wrote it" is recognised).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OutputKind {
    /// A CSV record; its sidecar is declared with it.
    Record,
    /// A JSON sidecar beside a record.
    Sidecar,
    /// An SVG plot.
    Svg,
    /// A JSON Lines file (the batch and results files of the ask/tell commands): afsv
    /// wrote it when its first line is a JSON object afsv wrote (rule 3).
    JsonLines,
    /// Any other file (e.g. a parameter JSON): afsv never recognises it as its own.
    Other,
}

#[derive(Debug)]
struct Declared {
    label: String,
    shown: PathBuf,
    canonical: PathBuf,
}

/// Checks a command's outputs against its inputs and each other (module documentation).
#[derive(Debug, Default)]
pub struct OutputGuard {
    force: bool,
    inputs: Vec<Declared>,
    outputs: Vec<Declared>,
}

impl OutputGuard {
    /// A guard; `force` allows replacing existing files afsv did not write (rule 4).
    pub fn new(force: bool) -> Self {
        Self {
            force,
            ..Self::default()
        }
    }

    /// Declare an input file (read by the command), e.g. `("--params", path)`.
    pub fn input(&mut self, label: &str, path: &Path) -> Result<&mut Self, String> {
        let canonical = canonical_path(path)?;
        self.inputs.push(Declared {
            label: label.into(),
            shown: path.into(),
            canonical,
        });
        Ok(self)
    }

    /// Declare an input file when an option gave one ([`OutputGuard::input`]).
    pub fn input_if(&mut self, label: &str, path: Option<&Path>) -> Result<&mut Self, String> {
        if let Some(p) = path {
            self.input(label, p)?;
        }
        Ok(self)
    }

    /// Declare a record input: the CSV and its sidecar.
    pub fn record_input(&mut self, label: &str, csv: &Path) -> Result<&mut Self, String> {
        self.input(label, csv)?;
        let side = csv.with_extension("json");
        if side.exists() {
            self.input(&format!("{label} (sidecar)"), &side)?;
        }
        Ok(self)
    }

    /// Declare an output of `kind` when an option gave one ([`OutputGuard::output`]).
    pub fn output_if(
        &mut self,
        label: &str,
        path: Option<&Path>,
        kind: OutputKind,
    ) -> Result<&mut Self, String> {
        if let Some(p) = path {
            self.output(label, p, kind)?;
        }
        Ok(self)
    }

    /// Declare an output of `kind`. A [`OutputKind::Record`] also declares its sidecar.
    pub fn output(
        &mut self,
        label: &str,
        path: &Path,
        kind: OutputKind,
    ) -> Result<&mut Self, String> {
        let canonical = canonical_path(path)?;
        // A sidecar's label already says which file it is.
        let what = if kind == OutputKind::Sidecar {
            label.to_string()
        } else {
            format!("{label} {}", path.display())
        };
        if canonical.is_dir() {
            return Err(format!("{what}: is a directory"));
        }
        for i in &self.inputs {
            if i.canonical == canonical {
                return Err(format!(
                    "{what}: is the same file as the input {} {}; choose another output name",
                    i.label,
                    i.shown.display()
                ));
            }
        }
        for o in &self.outputs {
            if o.canonical == canonical {
                return Err(format!(
                    "{what}: is the same file as the output {} {}{}",
                    o.label,
                    o.shown.display(),
                    if kind == OutputKind::Sidecar || o.label.contains("sidecar") {
                        " (a record's sidecar takes its name with extension .json; give the CSV another extension, e.g. .csv)"
                    } else {
                        ""
                    }
                ));
            }
        }
        if canonical.exists() {
            let ours = match kind {
                OutputKind::Record => std::fs::read_to_string(path.with_extension("json"))
                    .is_ok_and(|t| is_afsv_json(&t)),
                OutputKind::Sidecar => {
                    std::fs::read_to_string(&canonical).is_ok_and(|t| is_afsv_json(&t))
                }
                OutputKind::Svg => {
                    std::fs::read_to_string(&canonical).is_ok_and(|t| t.contains(SVG_MARKER))
                }
                OutputKind::JsonLines => first_line(&canonical).is_some_and(|l| is_afsv_json(&l)),
                OutputKind::Other => false,
            };
            if !ours {
                if kind == OutputKind::Sidecar {
                    return Err(format!(
                        "{what}: exists and was not written by afsv; a sidecar never replaces it, not even with --force (move it away or choose another output name)"
                    ));
                }
                if !self.force {
                    return Err(format!(
                        "{what}: exists and was not written by afsv; give --force to replace it"
                    ));
                }
            }
        }
        self.outputs.push(Declared {
            label: label.into(),
            shown: path.into(),
            canonical,
        });
        if kind == OutputKind::Record {
            let side = path.with_extension("json");
            let side_label = format!(
                "{label} {} (its sidecar {})",
                path.display(),
                side.display()
            );
            self.output(&side_label, &side, OutputKind::Sidecar)?;
        }
        Ok(self)
    }
}

/// The first line of the file at `path` (read up to 1 MiB), if it can be read.
fn first_line(path: &Path) -> Option<String> {
    use std::io::{BufRead, Read};
    let file = std::fs::File::open(path).ok()?;
    let mut line = String::new();
    std::io::BufReader::new(file.take(1 << 20))
        .read_line(&mut line)
        .ok()?;
    Some(line)
}

/// Put [`SVG_MARKER`] at the top of the SVG file at `path` (after an XML declaration).
pub fn mark_svg(path: &Path) -> Result<(), String> {
    let err = |e: std::io::Error| format!("{}: {e}", path.display());
    let text = std::fs::read_to_string(path).map_err(err)?;
    if text.contains(SVG_MARKER) {
        return Ok(());
    }
    let marked = match text.strip_prefix("<?xml") {
        Some(_) => match text.find("?>") {
            Some(i) => format!("{}\n{SVG_MARKER}{}", &text[..i + 2], &text[i + 2..]),
            None => format!("{SVG_MARKER}\n{text}"),
        },
        None => format!("{SVG_MARKER}\n{text}"),
    };
    crate::atomic::write(path, marked).map_err(err)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dir(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("afsv-guard-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    #[test]
    fn same_file_by_any_name_collides() {
        let d = dir("same");
        let x = d.join("x.csv");
        std::fs::write(&x, "a\n1\n").unwrap();
        let dotted = d.join(".").join("x.csv");
        let mut g = OutputGuard::new(true);
        g.input("--input", &x).unwrap();
        assert!(g
            .output("-o", &dotted, OutputKind::Other)
            .unwrap_err()
            .contains("same file"));
        #[cfg(unix)]
        {
            let link = d.join("link.csv");
            std::os::unix::fs::symlink(&x, &link).unwrap();
            assert!(g.output("-o", &link, OutputKind::Other).is_err());
            let dangling = d.join("dangling.csv");
            std::os::unix::fs::symlink(d.join("new.csv"), &dangling).unwrap();
            g.output("-o", &dangling, OutputKind::Other).unwrap();
            assert!(g
                .output("--plot", &d.join("new.csv"), OutputKind::Other)
                .is_err());
        }
    }

    #[test]
    fn record_output_named_json_collides_with_its_sidecar() {
        let d = dir("sidecar");
        let mut g = OutputGuard::new(false);
        let e = g
            .output("-o", &d.join("y.json"), OutputKind::Record)
            .unwrap_err();
        assert!(e.contains(".json"), "{e}");
    }

    #[test]
    fn foreign_files_need_force_and_foreign_sidecars_are_never_replaced() {
        let d = dir("foreign");
        let csv = d.join("r.csv");
        std::fs::write(&csv, "a\n1\n").unwrap();
        assert!(OutputGuard::new(false)
            .output("-o", &csv, OutputKind::Record)
            .unwrap_err()
            .contains("--force"));
        OutputGuard::new(true)
            .output("-o", &csv, OutputKind::Record)
            .unwrap();
        std::fs::write(d.join("r.json"), r#"{"mine": 1}"#).unwrap();
        assert!(OutputGuard::new(true)
            .output("-o", &csv, OutputKind::Record)
            .unwrap_err()
            .contains("never"));
        std::fs::write(
            d.join("r.json"),
            r#"{"sign_convention": "afsv-v1", "written_by": "afsv yaw simulate"}"#,
        )
        .unwrap();
        OutputGuard::new(false)
            .output("-o", &csv, OutputKind::Record)
            .unwrap();
        let svg = d.join("p.svg");
        std::fs::write(&svg, "<svg></svg>").unwrap();
        assert!(OutputGuard::new(false)
            .output("--plot", &svg, OutputKind::Svg)
            .is_err());
        mark_svg(&svg).unwrap();
        OutputGuard::new(false)
            .output("--plot", &svg, OutputKind::Svg)
            .unwrap();
    }

    #[test]
    fn afsv_json_marker() {
        assert!(is_afsv_json(
            r#"{"sign_convention": "afsv-v1", "generator": "afsv terrain generate"}"#
        ));
        assert!(!is_afsv_json(r#"{"sign_convention": "afsv-v1"}"#));
        assert!(!is_afsv_json(r#"{"written_by": "afsv"}"#));
        assert!(!is_afsv_json("[1]"));
    }
}
