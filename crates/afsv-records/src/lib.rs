//! Measured or simulated records: CSV with a one-line header of `name_unit` columns and an
//! optional JSON sidecar (`record.json` beside `record.csv`), as fixed in docs/records.md.
//!
//! Reading reports the line and column of any malformed cell. Unknown columns are kept (and
//! ignored by consumers); absent columns are simply not compared. A sidecar's
//! `"sign_convention"` is honoured when it is [`SIGN_CONVENTION`] or a per-channel statement
//! in the vocabulary of [`convention`]; a convention in words is refused rather than
//! guessed at, unless the user assumes it ([`ReadOptions`]).
//!
//! ```
//! use afsv_records::Record;
//! use std::path::Path;
//!
//! let mut rec = Record::new();
//! rec.push_column("time_s", vec![0.0, 0.01, 0.02]).unwrap();
//! rec.push_column("force_n", vec![10.0, 12.5, 11.0]).unwrap();
//! let text = rec.to_csv_string();
//! let back = Record::parse_csv(&text, Path::new("bench.csv")).unwrap();
//! assert_eq!(back.column("force_n"), Some(&[10.0, 12.5, 11.0][..]));
//!
//! // A malformed cell is reported with its line and column.
//! let err = Record::parse_csv("time_s,force_n\n0.0,abc\n", Path::new("bad.csv")).unwrap_err();
//! assert!(err.to_string().starts_with("bad.csv:2:2:"), "{err}");
//! ```
//!
//! Writing goes through [`atomic`] (whole or absent) under the rules of [`guard`] (no output
//! replaces an input or a file the toolkit did not write); [`json`] holds the JSON output
//! rules (no NaN, every `null` explained); [`provenance`] lists the input files read;
//! [`jsonl`] reads and writes JSON Lines files, [`stored`] state files read back (a
//! checkpoint), [`lock`] takes the one-run-at-a-time lock of such a file; [`folders`] lists
//! the records of folders and guards the folders of records the toolkit writes.

pub mod atomic;
pub mod convention;
pub mod folders;
pub mod guard;
pub mod json;
pub mod jsonl;
pub mod lock;
pub mod provenance;
pub mod stored;
pub mod units;

pub use convention::{ReadOptions, SIGN_CONVENTION};
use std::collections::HashSet;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// Most columns a CSV header may have: a wider header is refused before any row is read
/// (a malformed or hostile file fails at once, in time linear in its header). A record of
/// the toolkit has a few dozen channels; 4,096 leaves room for any logger export.
pub const MAX_COLUMNS: usize = 4096;

/// Column names an error message lists before it says how many more there are.
pub const LISTED_COLUMNS: usize = 10;

/// `names` for an error message: the first [`LISTED_COLUMNS`], then "... and N more".
pub fn list_columns(names: &[String]) -> String {
    let shown = names
        .iter()
        .take(LISTED_COLUMNS)
        .map(String::as_str)
        .collect::<Vec<_>>()
        .join(", ");
    match names.len().saturating_sub(LISTED_COLUMNS) {
        0 => shown,
        more => format!("{shown}, ... and {more} more"),
    }
}

/// A column-oriented numeric record.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Record {
    names: Vec<String>,
    columns: Vec<Vec<f64>>,
    /// Sidecar metadata (sample rate, units, manoeuvre, ...), `Null` when there is none.
    pub meta: serde_json::Value,
    /// The file the record was read from (`None` for records built in code).
    pub source: Option<PathBuf>,
    /// Channels [`Record::read_with`] converted from another unit to the toolkit's
    /// ([`units`]), in file order.
    pub unit_conversions: Vec<UnitConversion>,
}

/// One channel read in another unit and converted: `to = factor * from`.
#[derive(Debug, Clone, PartialEq)]
pub struct UnitConversion {
    /// Channel name in the file (e.g. `az_g`).
    pub from: String,
    /// The toolkit's channel name (e.g. `az_m_s2`).
    pub to: String,
    /// Factor from the file's unit to SI.
    pub factor: f64,
}

/// What went wrong reading or writing a record.
#[derive(Debug, thiserror::Error)]
pub enum RecordError {
    /// The file could not be opened, read or written.
    #[error("{path}: {source}")]
    Io {
        /// File involved.
        path: PathBuf,
        /// Underlying error.
        source: std::io::Error,
    },
    /// A cell or the header is malformed.
    #[error("{path}:{line}:{column}: {message}")]
    Parse {
        /// File involved.
        path: PathBuf,
        /// 1-based line number.
        line: u64,
        /// 1-based column number.
        column: usize,
        /// What is wrong.
        message: String,
    },
    /// The sidecar is malformed or states a convention we cannot honour.
    #[error("{path}: {message}")]
    Sidecar {
        /// Sidecar file.
        path: PathBuf,
        /// What is wrong.
        message: String,
    },
    /// A required column is absent.
    #[error("{path}: no column `{name}` (columns: {available})")]
    MissingColumn {
        /// File involved.
        path: PathBuf,
        /// Column asked for.
        name: String,
        /// Columns present.
        available: String,
    },
    /// Columns of unequal length or a duplicate name when building a record in code.
    #[error("invalid record: {0}")]
    Invalid(String),
}

impl Record {
    /// An empty record.
    pub fn new() -> Self {
        Self {
            names: Vec::new(),
            columns: Vec::new(),
            meta: serde_json::Value::Null,
            source: None,
            unit_conversions: Vec::new(),
        }
    }

    /// Add a column; all columns must have the same length and distinct names, and every
    /// value must be finite: a record this crate writes is one its reader accepts.
    pub fn push_column(&mut self, name: &str, values: Vec<f64>) -> Result<(), RecordError> {
        if self.names.iter().any(|n| n == name) {
            return Err(RecordError::Invalid(format!("duplicate column `{name}`")));
        }
        if let Some(row) = values.iter().position(|v| !v.is_finite()) {
            return Err(RecordError::Invalid(format!(
                "column `{name}` holds {} at row {} (counting from 1 below the header); a record holds finite numbers only, so nothing is written",
                values[row],
                row + 1
            )));
        }
        if let Some(first) = self.columns.first() {
            if first.len() != values.len() {
                return Err(RecordError::Invalid(format!(
                    "column `{name}` has {} rows, the record has {}",
                    values.len(),
                    first.len()
                )));
            }
        }
        self.names.push(name.to_string());
        self.columns.push(values);
        Ok(())
    }

    /// A record of the given columns, in order (each checked as [`Record::push_column`]
    /// checks it).
    pub fn from_columns<S: AsRef<str>>(
        columns: impl IntoIterator<Item = (S, Vec<f64>)>,
    ) -> Result<Self, RecordError> {
        let mut out = Self::new();
        for (name, values) in columns {
            out.push_column(name.as_ref(), values)?;
        }
        Ok(out)
    }

    /// A record of the columns of `all` named in `wanted` (all when it is empty), `time_s`
    /// first: an unknown or repeated name is an error listing the known ones (the
    /// `--columns` option of a command that writes a record).
    pub fn from_selected(all: Vec<(String, &[f64])>, wanted: &[String]) -> Result<Self, String> {
        if wanted.is_empty() {
            return Self::from_columns(all.into_iter().map(|(n, v)| (n, v.to_vec())))
                .map_err(|e| e.to_string());
        }
        let mut names: Vec<&str> = vec!["time_s"];
        for w in wanted.iter().map(|w| w.trim()) {
            if w == "time_s" {
                continue;
            }
            if names.contains(&w) {
                return Err(format!("--columns: `{w}` is named twice"));
            }
            if !all.iter().any(|(n, _)| n == w) {
                let known: Vec<&str> = all.iter().map(|(n, _)| n.as_str()).collect();
                return Err(format!(
                    "--columns: no column `{w}` (known: {})",
                    known.join(", ")
                ));
            }
            names.push(w);
        }
        let picked = names
            .iter()
            .filter_map(|n| all.iter().find(|(m, _)| m == n))
            .map(|(n, v)| (n, v.to_vec()));
        Self::from_columns(picked).map_err(|e| e.to_string())
    }

    /// Column names in file order.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// Number of rows.
    pub fn len(&self) -> usize {
        self.columns.first().map_or(0, Vec::len)
    }

    /// True when the record has no rows.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The column called `name`, if present.
    pub fn column(&self, name: &str) -> Option<&[f64]> {
        self.names
            .iter()
            .position(|n| n == name)
            .map(|i| self.columns[i].as_slice())
    }

    /// The column called `name`, or an error naming the columns that are there.
    pub fn require(&self, name: &str, path: &Path) -> Result<&[f64], RecordError> {
        self.column(name).ok_or_else(|| RecordError::MissingColumn {
            path: path.to_path_buf(),
            name: name.to_string(),
            available: list_columns(&self.names),
        })
    }

    /// Read `path` (CSV) and its sidecar `path.with_extension("json")` if it exists, with the
    /// default [`ReadOptions`].
    pub fn read(path: &Path) -> Result<Self, RecordError> {
        Self::read_with(path, &ReadOptions::default())
    }

    /// Read `path` and its sidecar; channels whose sign convention the sidecar states per
    /// channel are converted to [`SIGN_CONVENTION`] (the original statement is kept in the
    /// metadata as `converted_from`).
    pub fn read_with(path: &Path, opts: &ReadOptions) -> Result<Self, RecordError> {
        let text = provenance::read_input(path).map_err(|source| RecordError::Io {
            path: path.to_path_buf(),
            source,
        })?;
        let mut rec = Self::parse_csv(&text, path)?;
        rec.source = Some(path.to_path_buf());
        rec.convert_units(path)?;
        let sidecar = path.with_extension("json");
        if sidecar.is_file() {
            rec.meta = read_sidecar(&sidecar)?;
            rec.apply_convention(&sidecar, opts)?;
        }
        Ok(rec)
    }

    /// Convert channels of known quantities in other units to the toolkit's channels, refuse
    /// those in units that cannot be converted ([`units::classify`]). A converted channel
    /// whose SI channel is also in the file stays as it is, an extra column.
    fn convert_units(&mut self, path: &Path) -> Result<(), RecordError> {
        for i in 0..self.names.len() {
            match units::classify(&self.names[i]) {
                units::ChannelUnit::Keep => {}
                units::ChannelUnit::Convert { to, factor } => {
                    if self.names.contains(&to) {
                        continue;
                    }
                    for v in &mut self.columns[i] {
                        *v *= factor;
                    }
                    let from = std::mem::replace(&mut self.names[i], to.clone());
                    self.unit_conversions
                        .push(UnitConversion { from, to, factor });
                }
                units::ChannelUnit::Refuse { reason } => {
                    return Err(RecordError::Parse {
                        path: path.to_path_buf(),
                        line: 1,
                        column: i + 1,
                        message: reason,
                    });
                }
            }
        }
        Ok(())
    }

    fn apply_convention(&mut self, sidecar: &Path, opts: &ReadOptions) -> Result<(), RecordError> {
        let err = |message: String| RecordError::Sidecar {
            path: sidecar.to_path_buf(),
            message,
        };
        let stated = self.meta.get("sign_convention").cloned();
        let conversions = convention::conversions(stated.as_ref(), opts).map_err(err)?;
        for (channel, conversion) in conversions {
            let Some(j) = self.names.iter().position(|n| *n == channel) else {
                return Err(err(format!(
                    "sign_convention names channel `{channel}`, which the record does not have (columns: {})",
                    list_columns(&self.names)
                )));
            };
            convention::apply(conversion, &mut self.columns[j]);
        }
        if let (Some(stated), Some(obj)) = (stated, self.meta.as_object_mut()) {
            if stated.as_str() != Some(SIGN_CONVENTION) {
                obj.insert("converted_from".into(), stated);
                obj.insert("sign_convention".into(), SIGN_CONVENTION.into());
            }
        }
        Ok(())
    }

    /// Parse CSV text (`path` is only used in error messages).
    pub fn parse_csv(text: &str, path: &Path) -> Result<Self, RecordError> {
        let perr = |line: u64, column: usize, message: String| RecordError::Parse {
            path: path.to_path_buf(),
            line,
            column,
            message,
        };
        // Spreadsheet exports often start with a UTF-8 byte-order mark.
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        let mut reader = csv::ReaderBuilder::new()
            .has_headers(true)
            .trim(csv::Trim::All)
            .comment(Some(b'#'))
            .from_reader(text.as_bytes());
        let headers = reader
            .headers()
            .map_err(|e| perr(1, 1, format!("cannot read header: {e}")))?
            .clone();
        if headers.is_empty() || (headers.len() == 1 && headers[0].is_empty()) {
            return Err(perr(1, 1, "empty file: expected a header line".into()));
        }
        if headers.len() > MAX_COLUMNS {
            return Err(perr(
                1,
                MAX_COLUMNS + 1,
                format!(
                    "the header has {} columns, more than the {MAX_COLUMNS} a record may have",
                    headers.len()
                ),
            ));
        }
        let mut rec = Self::new();
        // One pass with a set: linear in the header's width.
        let mut seen = HashSet::with_capacity(headers.len());
        for (j, h) in headers.iter().enumerate() {
            if h.is_empty() {
                return Err(perr(1, j + 1, "empty column name in header".into()));
            }
            if !seen.insert(h) {
                return Err(perr(1, j + 1, format!("duplicate column `{h}`")));
            }
            rec.names.push(h.to_string());
            rec.columns.push(Vec::new());
        }
        let header_line = headers_line(&reader);
        let mut row_lines = Vec::new();
        for row in reader.records() {
            let row = row.map_err(|e| {
                let line = e.position().map_or(header_line, |p| p.line());
                perr(line, 1, format!("{e}"))
            })?;
            let line = row.position().map_or(0, |p| p.line());
            row_lines.push(line);
            if row.len() != rec.names.len() {
                return Err(perr(
                    line,
                    row.len().min(rec.names.len()) + 1,
                    format!("expected {} fields, found {}", rec.names.len(), row.len()),
                ));
            }
            for (j, cell) in row.iter().enumerate() {
                let v: f64 = cell.parse().map_err(|_| {
                    perr(
                        line,
                        j + 1,
                        format!("`{cell}` in column `{}` is not a number", rec.names[j]),
                    )
                })?;
                if !v.is_finite() {
                    return Err(perr(
                        line,
                        j + 1,
                        format!("`{cell}` in column `{}` is not finite", rec.names[j]),
                    ));
                }
                rec.columns[j].push(v);
            }
        }
        // Every model replays records in time: a clock that stalls or runs back is an error
        // in the file, reported where it happens.
        if let Some(j) = rec.names.iter().position(|n| n == "time_s") {
            let t = &rec.columns[j];
            if let Some(i) = (1..t.len()).find(|&i| t[i] <= t[i - 1]) {
                return Err(perr(
                    row_lines[i],
                    j + 1,
                    format!("time_s does not increase ({} after {})", t[i], t[i - 1]),
                ));
            }
        }
        Ok(rec)
    }

    /// CSV text of the record (full precision, header first).
    pub fn to_csv_string(&self) -> String {
        let mut s = self.names.join(",");
        s.push('\n');
        for i in 0..self.len() {
            for (j, c) in self.columns.iter().enumerate() {
                if j > 0 {
                    s.push(',');
                }
                let _ = write!(s, "{}", c[i]);
            }
            s.push('\n');
        }
        s
    }

    /// Write the CSV to `path`, and the sidecar beside it when `meta` is not `Null`
    /// (the sidecar then carries `"sign_convention": "afsv-v1"`).
    pub fn write(&self, path: &Path) -> Result<(), RecordError> {
        let io = |source| RecordError::Io {
            path: path.to_path_buf(),
            source,
        };
        atomic::write(path, self.to_csv_string()).map_err(io)?;
        if !self.meta.is_null() {
            let mut meta = self.meta.clone();
            if let Some(obj) = meta.as_object_mut() {
                obj.entry("sign_convention")
                    .or_insert_with(|| SIGN_CONVENTION.into());
            }
            let side = path.with_extension("json");
            let text = serde_json::to_string_pretty(&meta).expect("JSON value serialises");
            atomic::write(&side, text + "\n").map_err(|source| RecordError::Io {
                path: side.clone(),
                source,
            })?;
        }
        Ok(())
    }
}

fn headers_line(reader: &csv::Reader<&[u8]>) -> u64 {
    reader.position().line().max(1)
}

fn read_sidecar(path: &Path) -> Result<serde_json::Value, RecordError> {
    let text = provenance::read_input(path).map_err(|source| RecordError::Io {
        path: path.to_path_buf(),
        source,
    })?;
    let meta: serde_json::Value = serde_json::from_str(&text).map_err(|e| RecordError::Parse {
        path: path.to_path_buf(),
        line: e.line() as u64,
        column: e.column(),
        message: format!("invalid JSON sidecar: {e}"),
    })?;
    if !meta.is_object() {
        return Err(RecordError::Sidecar {
            path: path.to_path_buf(),
            message: "sidecar must be a JSON object".into(),
        });
    }
    Ok(meta)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p() -> &'static Path {
        Path::new("rec.csv")
    }

    #[test]
    fn parses_and_keeps_unknown_columns() {
        let r = Record::parse_csv("time_s,force_n,extra_x\n0,1.5,9\n0.1,2.5,9\n", p()).unwrap();
        assert_eq!(r.len(), 2);
        assert_eq!(r.column("force_n").unwrap(), &[1.5, 2.5]);
        assert!(r.column("extra_x").is_some());
        assert!(r.column("p_rod_pa").is_none());
    }

    fn scratch_file(name: &str, text: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("afsv-records-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join(name);
        std::fs::write(&path, text).unwrap();
        path
    }

    #[test]
    fn channels_in_other_units_are_converted_and_listed() {
        let path = scratch_file(
            "units.csv",
            "time_s,az_g,force_kn,p_rod_bar,extra_x\n0,1,2,50,7\n0.01,-0.5,-1,10,7\n",
        );
        let r = Record::read(&path).unwrap();
        assert_eq!(r.column("az_m_s2").unwrap(), &[9.806_65, -4.903_325]);
        assert_eq!(r.column("force_n").unwrap(), &[2000.0, -1000.0]);
        assert_eq!(r.column("p_rod_pa").unwrap(), &[5.0e6, 1.0e6]);
        assert!(r.column("az_g").is_none());
        assert_eq!(r.column("extra_x").unwrap(), &[7.0, 7.0]);
        let from: Vec<&str> = r.unit_conversions.iter().map(|c| c.from.as_str()).collect();
        assert_eq!(from, ["az_g", "force_kn", "p_rod_bar"]);
    }

    #[test]
    fn a_channel_in_an_unconvertible_unit_is_refused_with_its_column() {
        let path = scratch_file("badunit.csv", "time_s,az_ft_s2\n0,1\n0.01,2\n");
        let e = Record::read(&path).unwrap_err().to_string();
        assert!(
            e.contains(":1:2:") && e.contains("az_ft_s2") && e.contains("m_s2"),
            "{e}"
        );
    }

    #[test]
    fn an_si_channel_next_to_its_converted_twin_wins() {
        let path = scratch_file("twin.csv", "time_s,az_m_s2,az_g\n0,1,1\n0.01,2,2\n");
        let r = Record::read(&path).unwrap();
        assert_eq!(r.column("az_m_s2").unwrap(), &[1.0, 2.0]);
        assert_eq!(r.column("az_g").unwrap(), &[1.0, 2.0]);
        assert!(r.unit_conversions.is_empty());
    }

    #[test]
    fn a_record_built_in_code_refuses_non_finite_values() {
        let mut r = Record::new();
        r.push_column("time_s", vec![0.0, 0.1, 0.2]).unwrap();
        let e = r.push_column("ltr", vec![0.1, f64::NAN, 0.3]).unwrap_err();
        assert!(e.to_string().contains("`ltr` holds NaN at row 2"), "{e}");
        let e = r
            .push_column("f_n", vec![f64::INFINITY, 0.0, 0.0])
            .unwrap_err();
        assert!(e.to_string().contains("row 1"), "{e}");
        assert_eq!(r.names(), ["time_s"]);
    }

    #[test]
    fn bad_cell_reports_line_and_column() {
        let e = Record::parse_csv("time_s,force_n\n0,1\n0.1,abc\n", p()).unwrap_err();
        let msg = e.to_string();
        assert!(msg.starts_with("rec.csv:3:2:"), "{msg}");
        let e = Record::parse_csv("time_s,force_n\n0,1\n0.1\n", p()).unwrap_err();
        assert!(e.to_string().starts_with("rec.csv:3:"), "{e}");
        let e = Record::parse_csv("time_s,force_n\n0,nan\n", p()).unwrap_err();
        assert!(e.to_string().starts_with("rec.csv:2:2:"), "{e}");
    }

    #[test]
    fn spreadsheet_exports_with_bom_crlf_and_quotes_parse() {
        let text = "\u{feff}\"time_s\",force_n\r\n0,1.5\r\n0.1,2.5e0\r\n";
        let r = Record::parse_csv(text, p()).unwrap();
        assert_eq!(r.column("time_s").unwrap(), &[0.0, 0.1]);
        assert_eq!(r.column("force_n").unwrap(), &[1.5, 2.5]);
    }

    #[test]
    fn time_that_does_not_increase_is_reported_where_it_happens() {
        let e = Record::parse_csv("force_n,time_s\n1,0\n2,0.1\n3,0.1\n", p()).unwrap_err();
        assert!(e.to_string().starts_with("rec.csv:4:2:"), "{e}");
    }

    #[test]
    fn a_wide_header_is_refused_at_once_and_errors_list_few_columns() {
        let wide: Vec<String> = (0..100_000).map(|j| format!("c{j}_x")).collect();
        let text = format!("{}\n", wide.join(","));
        let t = std::time::Instant::now();
        let e = Record::parse_csv(&text, p()).unwrap_err().to_string();
        assert!(t.elapsed().as_secs_f64() < 1.0, "{:?}", t.elapsed());
        assert!(
            e.starts_with("rec.csv:1:4097:") && e.contains("100000 columns"),
            "{e}"
        );
        assert!(e.len() < 200, "{e}");
        // The widest allowed header parses in one pass, and a missing column's error lists
        // ten names and the count of the others.
        let most = wide[..MAX_COLUMNS].join(",");
        let row = vec!["1"; MAX_COLUMNS].join(",");
        let t = std::time::Instant::now();
        let r = Record::parse_csv(&format!("{most}\n{row}\n"), p()).unwrap();
        assert!(t.elapsed().as_secs_f64() < 1.0, "{:?}", t.elapsed());
        let e = r.require("time_s", p()).unwrap_err().to_string();
        assert!(
            e.ends_with("c8_x, c9_x, ... and 4086 more)") && e.contains("(columns: c0_x, c1_x,"),
            "{e}"
        );
        // A duplicate far along is still found, where it is.
        let mut dup = wide[..MAX_COLUMNS].to_vec();
        dup[MAX_COLUMNS - 1] = "c17_x".into();
        let e = Record::parse_csv(&format!("{}\n", dup.join(",")), p()).unwrap_err();
        assert!(
            e.to_string()
                .starts_with("rec.csv:1:4096: duplicate column `c17_x`"),
            "{e}"
        );
        assert_eq!(list_columns(&wide[..3]), "c0_x, c1_x, c2_x");
    }

    #[test]
    fn empty_and_duplicate_headers_are_errors() {
        assert!(Record::parse_csv("", p()).is_err());
        assert!(Record::parse_csv("a,a\n1,2\n", p()).is_err());
    }

    #[test]
    fn round_trip_through_files_with_sidecar() {
        let dir = std::env::temp_dir().join(format!("afsv-record-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("r.csv");
        let mut r = Record::new();
        r.push_column("time_s", vec![0.0, 0.01]).unwrap();
        r.push_column("force_n", vec![1.0 / 3.0, -2e-9]).unwrap();
        r.meta = serde_json::json!({"sample_rate_hz": 100.0});
        r.write(&path).unwrap();
        let back = Record::read(&path).unwrap();
        assert_eq!(back.column("force_n"), r.column("force_n"));
        assert_eq!(back.meta["sign_convention"], SIGN_CONVENTION);
        std::fs::write(dir.join("r.json"), r#"{"sign_convention": "sae"}"#).unwrap();
        assert!(matches!(
            Record::read(&path),
            Err(RecordError::Sidecar { .. })
        ));
        let assumed = ReadOptions {
            assume_convention: Some(SIGN_CONVENTION.into()),
        };
        assert_eq!(
            Record::read_with(&path, &assumed)
                .unwrap()
                .column("force_n"),
            r.column("force_n")
        );
        std::fs::write(
            dir.join("r.json"),
            r#"{"sign_convention": {"force_n": "tension_positive"}}"#,
        )
        .unwrap();
        let flipped = Record::read(&path).unwrap();
        assert_eq!(flipped.column("force_n").unwrap(), &[-1.0 / 3.0, 2e-9]);
        assert_eq!(flipped.meta["sign_convention"], SIGN_CONVENTION);
        assert_eq!(
            flipped.meta["converted_from"]["force_n"],
            "tension_positive"
        );
        std::fs::write(
            dir.join("r.json"),
            r#"{"sign_convention": {"p_rod_pa": "gauge"}}"#,
        )
        .unwrap();
        let e = Record::read(&path).unwrap_err().to_string();
        assert!(e.contains("p_rod_pa") && e.contains("does not have"), "{e}");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
