//! Writing records in the docs/records.md format ("Data formats"): CSV with a `name_unit` header
//! and a JSON sidecar beside it. Our own writer, with fixed per-column precision so the
//! bytes are reproducible.

use std::fmt::Write as _;
use std::path::Path;

/// One column: header name, values and the number of decimals written.
pub struct Column<'a> {
    /// Header, e.g. `time_s`.
    pub name: &'a str,
    /// Samples.
    pub values: &'a [f64],
    /// Decimals in the CSV.
    pub decimals: usize,
}

/// CSV text of equal-length columns.
pub fn csv_text(cols: &[Column<'_>]) -> String {
    let n = cols.first().map_or(0, |c| c.values.len());
    assert!(cols.iter().all(|c| c.values.len() == n), "ragged columns");
    let mut s = String::with_capacity(n * cols.len() * 12 + 64);
    let header: Vec<&str> = cols.iter().map(|c| c.name).collect();
    s.push_str(&header.join(","));
    s.push('\n');
    for i in 0..n {
        for (k, c) in cols.iter().enumerate() {
            if k > 0 {
                s.push(',');
            }
            let v = c.values[i];
            // avoid "-0.000"
            let v = if v.abs() < 0.5 * 10f64.powi(-(c.decimals as i32)) {
                0.0
            } else {
                v
            };
            write!(s, "{:.*}", c.decimals, v).unwrap();
        }
        s.push('\n');
    }
    s
}

/// Write `dir/name.csv` and `dir/name.json`.
pub fn write_record(dir: &Path, name: &str, cols: &[Column<'_>], sidecar: &serde_json::Value) {
    std::fs::create_dir_all(dir).expect("create record dir");
    std::fs::write(dir.join(format!("{name}.csv")), csv_text(cols)).expect("write csv");
    let mut js = serde_json::to_string_pretty(sidecar).expect("sidecar json");
    js.push('\n');
    std::fs::write(dir.join(format!("{name}.json")), js).expect("write json");
}

/// Write a pretty JSON file.
pub fn write_json(path: &Path, v: &serde_json::Value) {
    if let Some(d) = path.parent() {
        std::fs::create_dir_all(d).expect("create dir");
    }
    let mut js = serde_json::to_string_pretty(v).expect("json");
    js.push('\n');
    std::fs::write(path, js).expect("write json");
}
