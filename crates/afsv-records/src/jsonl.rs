//! JSON Lines files of the toolkit (the batch and results files of the ask/tell optimisation,
//! docs/optimisation.md): a header line, then one record per line; bounded line length and
//! record count, errors with file, line and column; written whole or not at all.

use serde::de::DeserializeOwned;
use serde::Serialize;
use std::io::{BufRead, Read};
use std::path::Path;

/// Longest line of a JSON Lines file (bytes).
pub const MAX_LINE_BYTES: usize = 1 << 20;

/// A JSON Lines file: the header (line 1), which `check` accepts before any record is read,
/// and at most `max_records` records, each with its line number. Blank lines are skipped; a
/// line longer than [`MAX_LINE_BYTES`], a record beyond `max_records` or a malformed line
/// is an error naming `label`, the file, line and column.
pub fn read_jsonl<H: DeserializeOwned, T: DeserializeOwned>(
    label: &str,
    path: &Path,
    max_records: usize,
    check: &dyn Fn(&H) -> Result<(), String>,
) -> Result<(H, Vec<(usize, T)>), String> {
    let at = |line: usize| format!("{label} {}:{line}", path.display());
    let file = std::fs::File::open(path).map_err(|e| format!("{label} {}: {e}", path.display()))?;
    let mut reader = std::io::BufReader::new(file);
    let mut header: Option<H> = None;
    let mut records = Vec::new();
    let mut buf = String::new();
    for line_no in 1usize.. {
        buf.clear();
        let n = reader
            .by_ref()
            .take(MAX_LINE_BYTES as u64 + 1)
            .read_line(&mut buf)
            .map_err(|e| format!("{}: {e}", at(line_no)))?;
        if n == 0 {
            break;
        }
        if n > MAX_LINE_BYTES {
            return Err(format!(
                "{}: line longer than {MAX_LINE_BYTES} bytes",
                at(line_no)
            ));
        }
        if buf.trim().is_empty() {
            continue;
        }
        let parse_err = |e: serde_json::Error| {
            format!(
                "{}:{}: {}",
                at(line_no),
                e.column(),
                crate::json::message(&e)
            )
        };
        if header.is_none() {
            let h = serde_json::from_str(&buf).map_err(parse_err)?;
            check(&h)?;
            header = Some(h);
            continue;
        }
        if records.len() == max_records {
            return Err(format!("{}: more than {max_records} records", at(line_no)));
        }
        records.push((line_no, serde_json::from_str(&buf).map_err(parse_err)?));
    }
    let header = header.ok_or_else(|| format!("{label} {}: empty file", path.display()))?;
    Ok((header, records))
}

/// Writes `header` and `lines` as JSON Lines to `path` (through a unique temporary file
/// renamed into place, so a reader never sees half a file).
pub fn write_jsonl<H: Serialize, T: Serialize>(
    path: &Path,
    header: &H,
    lines: &[T],
) -> Result<(), String> {
    let mut text = serde_json::to_string(header).map_err(|e| e.to_string())? + "\n";
    for l in lines {
        text += &serde_json::to_string(l).map_err(|e| e.to_string())?;
        text.push('\n');
    }
    crate::atomic::write(path, text).map_err(|e| format!("{}: {e}", path.display()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::PathBuf;

    fn file(name: &str, text: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("afsv-jsonl-unit-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let p = dir.join(name);
        std::fs::write(&p, text).unwrap();
        p
    }

    fn accept(_: &serde_json::Value) -> Result<(), String> {
        Ok(())
    }

    #[test]
    fn json_lines_errors_name_line_and_column_and_bounds_hold() {
        let ok = file("ok.jsonl", "{\"h\":1}\n\n[1]\n[2]\n");
        let (h, recs): (serde_json::Value, Vec<(usize, Vec<u32>)>) =
            read_jsonl("X", &ok, 2, &accept).unwrap();
        assert_eq!(h["h"], 1);
        assert_eq!(recs, vec![(3, vec![1]), (4, vec![2])]);
        let e = read_jsonl::<serde_json::Value, Vec<u32>>("X", &ok, 1, &accept).unwrap_err();
        assert!(e.ends_with("ok.jsonl:4: more than 1 records"), "{e}");
        let bad = file("bad.jsonl", "{}\n[1, x]\n");
        let e = read_jsonl::<serde_json::Value, Vec<u32>>("X", &bad, 9, &accept).unwrap_err();
        assert!(e.contains("bad.jsonl:2:5: expected value"), "{e}");
        let long = file(
            "long.jsonl",
            &format!("{{}}\n[{}]\n", "1,".repeat(MAX_LINE_BYTES)),
        );
        let e = read_jsonl::<serde_json::Value, Vec<u32>>("X", &long, 9, &accept).unwrap_err();
        assert!(e.contains("long.jsonl:2: line longer than"), "{e}");
        let empty = file("empty.jsonl", "\n");
        let e = read_jsonl::<serde_json::Value, Vec<u32>>("X", &empty, 9, &accept).unwrap_err();
        assert!(e.ends_with("empty file"), "{e}");
        let refuse = |_: &serde_json::Value| Err("not this header".to_string());
        let e = read_jsonl::<serde_json::Value, Vec<u32>>("X", &ok, 9, &refuse).unwrap_err();
        assert_eq!(e, "not this header");
    }
}
