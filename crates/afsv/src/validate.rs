//! Validation against the dissertation's reported numbers (`cargo xtask validate`).
//!
//! [`load_fixtures`] reads every `fixtures/reported/*.json` file (the common schema of
//! `fixtures/reported/README.md` and the simpler one of `hps_lab.json`). [`run`] then executes
//! a registry of checks ([`CHECKS`]): each maps a fixture id (and, for multi-valued entries, a
//! key) to a computation with our models, converts the simulated number to the fixture's
//! printed unit and compares it with the fixture's tolerance. Every `result` and
//! `qualitative` fixture appears in the report, either computed or listed as
//! [`Status::NotReproducible`] with the reason; [`run`] adds a row for any such fixture no
//! check covers, so nothing is hidden.
//!
//! Regression rule: a fixture whose `status` is `"reproduced"` (or, for a partly reproduced
//! multi-valued fixture, `"partially reproduced"` plus the list `reproduced_keys`) guards its
//! rows; [`Report::regressions`] lists guarded rows that are no longer within tolerance.
//! `docs/validation.md` describes the method and the current results.

use serde::Serialize;
use serde_json::Value;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::time::Instant;

use afs_hydraulics::params::{
    MU_V_TABLE_UNIT, VALVE_A0_TABLE_UNIT, VALVE_AM_TABLE_UNIT, VALVE_AV_TABLE_UNIT,
};
use afs_hydraulics::{strut_kinematics, AfsParams, AfsSystem};
use afsv_dynamics::analysis::{gain_efficiency_correlation, steady_turn_decay, MeasureChanges};
use afsv_dynamics::{
    measures_for, sensitivity, simulate, table_3_2_speeds_kmh, EquationForm, FieldCourse, Load,
    Manoeuvre, MeasureSpec, SensitivityParam, SensitivityTable, VehicleParams, YawMeasures,
};

/// Why the validation could not run.
#[derive(Debug, thiserror::Error)]
pub enum ValidateError {
    /// A fixture file could not be read.
    #[error("{path}: {source}")]
    Io {
        /// File.
        path: PathBuf,
        /// Cause.
        source: std::io::Error,
    },
    /// A fixture file is not valid JSON or does not follow its schema.
    #[error("{path}: {reason}")]
    Fixture {
        /// File.
        path: PathBuf,
        /// What is wrong.
        reason: String,
    },
    /// Writing the report failed.
    #[error("writing the report: {0}")]
    Output(String),
}

/// Tolerance of one fixture value, in the fixture's printed unit.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Tolerance {
    /// |simulated - reported| <= r |reported|.
    Relative(f64),
    /// |simulated - reported| <= a.
    Absolute(f64),
    /// simulated >= bound (a number printed as "> x").
    LowerBound(f64),
    /// simulated <= bound (a number printed as "< x").
    UpperBound(f64),
}

/// Slack for round-off when a tolerance is exactly zero or a value sits on its limit.
const ROUND_OFF: f64 = 1e-9;

impl Tolerance {
    /// The tolerance of the value at `key` (a `.`-separated path into `values`, or `None`)
    /// from a fixture's `tolerance` field: `{"relative": r}`, `{"absolute": a}`, per-key
    /// objects or arrays of either, `{"lower_bound": x}`, `{"upper_bound": x}`, or an object
    /// keyed by value key whose entries are such tolerances. `None` when there is none.
    pub fn from_fixture(tol: &Value, key: Option<&str>) -> Option<Tolerance> {
        let path: Vec<&str> = key.map(|k| k.split('.').collect()).unwrap_or_default();
        Self::lookup(tol, &path)
    }

    fn lookup(tol: &Value, path: &[&str]) -> Option<Tolerance> {
        let obj = tol.as_object()?;
        for (name, make) in [
            ("relative", Tolerance::Relative as fn(f64) -> Tolerance),
            ("absolute", Tolerance::Absolute),
            ("lower_bound", Tolerance::LowerBound),
            ("upper_bound", Tolerance::UpperBound),
        ] {
            if let Some(v) = obj.get(name) {
                return descend(v, path).and_then(Value::as_f64).map(make);
            }
        }
        let (first, rest) = path.split_first()?;
        Self::lookup(obj.get(*first)?, rest)
    }

    /// Signed error of `simulated` against `reported`: relative `(sim - rep)/|rep|`, absolute
    /// `sim - rep`, and for bounds the margin `sim - bound` (positive = above the bound).
    pub fn error(&self, reported: f64, simulated: f64) -> f64 {
        match *self {
            Tolerance::Relative(_) => (simulated - reported) / reported.abs(),
            Tolerance::Absolute(_) => simulated - reported,
            Tolerance::LowerBound(b) | Tolerance::UpperBound(b) => simulated - b,
        }
    }

    /// Whether `simulated` is within this tolerance of `reported` (non-finite: never).
    pub fn within(&self, reported: f64, simulated: f64) -> bool {
        if !simulated.is_finite() || !reported.is_finite() {
            return false;
        }
        let e = self.error(reported, simulated);
        let slack = ROUND_OFF * reported.abs().max(1e-300);
        match *self {
            Tolerance::Relative(r) => e.abs() <= r + ROUND_OFF,
            Tolerance::Absolute(a) => e.abs() <= a + slack,
            Tolerance::LowerBound(_) => e >= -slack,
            Tolerance::UpperBound(_) => e <= slack,
        }
    }

    /// Short text for tables: `rel 5%`, `abs 0.5`, `>= 0.99`, `<= 4`.
    pub fn describe(&self) -> String {
        match *self {
            Tolerance::Relative(r) => format!("rel {}%", fmt_num(100.0 * r)),
            Tolerance::Absolute(a) => format!("abs {}", fmt_num(a)),
            Tolerance::LowerBound(b) => format!(">= {}", fmt_num(b)),
            Tolerance::UpperBound(b) => format!("<= {}", fmt_num(b)),
        }
    }

    /// Describe a signed error in this tolerance's terms (`+3.1%` or `-0.02`).
    pub fn describe_error(&self, error: f64) -> String {
        match self {
            Tolerance::Relative(_) => format!("{:+.2}%", 100.0 * error),
            _ => format!("{:+}", fmt_num(error)),
        }
    }
}

fn descend<'a>(mut v: &'a Value, path: &[&str]) -> Option<&'a Value> {
    for seg in path {
        if v.is_number() {
            // A scalar applies to every entry below it.
            return Some(v);
        }
        v = match v {
            Value::Object(m) => m.get(*seg)?,
            Value::Array(a) => a.get(seg.parse::<usize>().ok()?)?,
            _ => return None,
        };
    }
    Some(v)
}

/// Outcome of one comparison.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Status {
    /// Computed and within tolerance (a qualitative check passed).
    Reproduced,
    /// Computed, outside tolerance (the reason is in the note).
    Differs,
    /// Needs a model or data we do not have (the reason is in the note).
    NotReproducible,
}

impl Status {
    /// Text as printed.
    pub fn as_str(self) -> &'static str {
        match self {
            Status::Reproduced => "reproduced",
            Status::Differs => "differs",
            Status::NotReproducible => "not-reproducible",
        }
    }
}

/// One reported quantity, from any fixture file.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Fixture {
    /// Fixture file name.
    pub file: String,
    /// Unique id.
    pub id: String,
    /// `parameter`, `result`, `qualitative` or `literature`.
    pub kind: String,
    /// Description.
    pub description: String,
    /// Table / section reference.
    pub reference: String,
    /// `value` or `values` as printed.
    pub value: Value,
    /// Unit as printed (normalized spelling).
    pub unit: String,
    /// The `tolerance` object (common schema; `hps_lab.json` tolerances are converted).
    pub tolerance: Value,
    /// The fixture's `status` field (regression rule).
    pub status: String,
    /// Keys of a partly reproduced multi-valued fixture that are guarded.
    pub reproduced_keys: Vec<String>,
}

impl Fixture {
    /// The number at `key` (`.`-separated path into `values`; `None` = the scalar `value`).
    pub fn number(&self, key: Option<&str>) -> Option<f64> {
        let path: Vec<&str> = key.map(|k| k.split('.').collect()).unwrap_or_default();
        descend(&self.value, &path)?.as_f64()
    }

    /// Whether the fixture marks the row at `key` as reproduced (so it must not regress).
    pub fn guards(&self, key: Option<&str>) -> bool {
        let s = self.status.trim();
        if s == "reproduced" || s.starts_with("reproduced ") || s.starts_with("reproduced(") {
            return true;
        }
        match key {
            Some(k) => self.reproduced_keys.iter().any(|r| r == k),
            None => false,
        }
    }
}

/// All fixtures by id.
#[derive(Debug, Clone, Default)]
pub struct Fixtures {
    /// Fixtures keyed by id.
    pub by_id: BTreeMap<String, Fixture>,
}

impl Fixtures {
    /// Fixture `id`.
    pub fn get(&self, id: &str) -> Option<&Fixture> {
        self.by_id.get(id)
    }

    /// Number of fixture `id` at `key`; an error names the missing entry.
    pub fn num(&self, id: &str, key: Option<&str>) -> Result<f64, String> {
        self.get(id).and_then(|f| f.number(key)).ok_or_else(|| {
            format!(
                "fixture `{id}` has no number at `{}`",
                key.unwrap_or("value")
            )
        })
    }
}

/// Read every `*.json` fixture in `dir`.
pub fn load_fixtures(dir: &Path) -> Result<Fixtures, ValidateError> {
    let io = |path: &Path| {
        let p = path.to_path_buf();
        move |source| ValidateError::Io { path: p, source }
    };
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .map_err(io(dir))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    files.sort();
    let mut out = Fixtures::default();
    for path in files {
        let text = std::fs::read_to_string(&path).map_err(io(&path))?;
        let bad = |reason: String| ValidateError::Fixture {
            path: path.clone(),
            reason,
        };
        let doc: Value = serde_json::from_str(&text).map_err(|e| bad(e.to_string()))?;
        let file = path
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        let qs = doc["quantities"]
            .as_array()
            .ok_or_else(|| bad("no `quantities` array".into()))?;
        for q in qs {
            let f = if q.get("kind").is_some() {
                parse_common(&file, q)
            } else {
                parse_hps_lab(&file, q)
            }
            .map_err(&bad)?;
            if out.by_id.contains_key(&f.id) {
                return Err(bad(format!("duplicate id `{}`", f.id)));
            }
            out.by_id.insert(f.id.clone(), f);
        }
    }
    Ok(out)
}

fn text(q: &Value, field: &str) -> String {
    q.get(field)
        .and_then(Value::as_str)
        .unwrap_or_default()
        .to_string()
}

fn parse_common(file: &str, q: &Value) -> Result<Fixture, String> {
    let id = q["id"].as_str().ok_or("quantity without `id`")?.to_string();
    let value = q
        .get("values")
        .or_else(|| q.get("value"))
        .cloned()
        .unwrap_or(Value::Null);
    let reproduced_keys = q
        .get("reproduced_keys")
        .and_then(Value::as_array)
        .map(|a| {
            a.iter()
                .filter_map(|k| k.as_str().map(String::from))
                .collect()
        })
        .unwrap_or_default();
    Ok(Fixture {
        file: file.to_string(),
        kind: text(q, "kind"),
        description: text(q, "description"),
        reference: text(q, "reference"),
        unit: text(q, "unit"),
        tolerance: q.get("tolerance").cloned().unwrap_or(Value::Null),
        status: text(q, "status"),
        value,
        id,
        reproduced_keys,
    })
}

/// `hps_lab.json`: `{id, description, value, unit, ref, tolerance: number|null,
/// tolerance_kind: "relative" | "absolute <unit>", status?}`; read as it is.
fn parse_hps_lab(file: &str, q: &Value) -> Result<Fixture, String> {
    let id = q["id"].as_str().ok_or("quantity without `id`")?.to_string();
    let tol = q.get("tolerance").and_then(Value::as_f64);
    let kind_text = text(q, "tolerance_kind");
    let tolerance = match tol {
        Some(t) if kind_text.starts_with("absolute") => serde_json::json!({ "absolute": t }),
        Some(t) => serde_json::json!({ "relative": t }),
        None => Value::Null,
    };
    let status = text(q, "status");
    let kind = if tol.is_some() || !status.is_empty() {
        "result"
    } else {
        "parameter"
    };
    Ok(Fixture {
        file: file.to_string(),
        kind: kind.into(),
        description: text(q, "description"),
        reference: text(q, "ref"),
        value: q.get("value").cloned().unwrap_or(Value::Null),
        unit: text(q, "unit"),
        tolerance,
        status,
        reproduced_keys: Vec::new(),
        id,
    })
}

/// One row of the validation table.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CheckResult {
    /// Fixture id.
    pub id: String,
    /// Key into a multi-valued fixture (`.`-separated path), if any.
    pub key: Option<String>,
    /// Model variant or load case when one fixture value is compared several ways.
    pub variant: Option<String>,
    /// Fixture kind.
    pub kind: String,
    /// Fixture description.
    pub description: String,
    /// Unit of `reported` and `simulated` (the fixture's printed unit).
    pub unit: String,
    /// Reported number (None for qualitative or whole multi-valued rows).
    pub reported: Option<f64>,
    /// Reported value as text (numbers, or the JSON of several values).
    pub reported_text: String,
    /// Simulated number, computed at run time.
    pub simulated: Option<f64>,
    /// Signed error in the tolerance's terms (see [`Tolerance::error`]).
    pub error: Option<f64>,
    /// Tolerance applied.
    pub tolerance: Option<Tolerance>,
    /// Outcome.
    pub status: Status,
    /// The fixture marks this row as reproduced (a non-reproduced status is a regression).
    pub guarded: bool,
    /// How it was computed, and why it differs or cannot be computed.
    pub note: String,
}

impl CheckResult {
    /// `id[key] (variant)`.
    pub fn label(&self) -> String {
        let mut s = self.id.clone();
        if let Some(k) = &self.key {
            s.push_str(&format!("[{k}]"));
        }
        if let Some(v) = &self.variant {
            s.push_str(&format!(" ({v})"));
        }
        s
    }

    /// A guarded row that is no longer reproduced.
    pub fn regressed(&self) -> bool {
        self.guarded && self.status != Status::Reproduced
    }
}

/// Data of one SVG plot of the report.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PlotData {
    /// File name under the output directory.
    pub file: String,
    /// Title.
    pub title: String,
    /// Abscissa label.
    pub x_label: String,
    /// Ordinate label.
    pub y_label: String,
    /// `(label, x, y)` curves.
    pub series: Vec<(String, Vec<f64>, Vec<f64>)>,
}

/// The validation outcome.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Report {
    /// Rows in registry order, then uncovered fixtures.
    pub results: Vec<CheckResult>,
    /// Plots.
    pub plots: Vec<PlotData>,
    /// Checks whose computation failed (name, error); their fixtures appear as rows too.
    pub failed_checks: Vec<(String, String)>,
    /// Wall time of [`run`] (s).
    pub elapsed_s: f64,
}

impl Report {
    /// Guarded rows that are no longer reproduced.
    pub fn regressions(&self) -> Vec<&CheckResult> {
        self.results.iter().filter(|r| r.regressed()).collect()
    }

    /// Number of rows with `status`.
    pub fn count(&self, status: Status) -> usize {
        self.results.iter().filter(|r| r.status == status).count()
    }

    /// Plain-text table (quantity, reported, simulated, error, tolerance, status).
    pub fn table_text(&self) -> String {
        let mut rows = vec![[
            "quantity".to_string(),
            "unit".into(),
            "reported".into(),
            "simulated".into(),
            "error".into(),
            "tolerance".into(),
            "status".into(),
        ]];
        for r in &self.results {
            rows.push(row_cells(r));
        }
        let mut w = [0usize; 7];
        for row in &rows {
            for (i, c) in row.iter().enumerate() {
                w[i] = w[i].max(c.chars().count());
            }
        }
        w[0] = w[0].min(64);
        let mut out = String::new();
        for row in &rows {
            let mut line = String::new();
            for (i, c) in row.iter().enumerate() {
                let cap = if i == 0 { 64 } else { 28 };
                let c: String = c.chars().take(cap).collect();
                line.push_str(&format!("{:<width$}  ", c, width = w[i].min(cap)));
            }
            out.push_str(line.trim_end());
            out.push('\n');
        }
        out.push_str(&self.summary_line());
        out.push('\n');
        out
    }

    /// One-line summary.
    pub fn summary_line(&self) -> String {
        format!(
            "{} rows: {} reproduced, {} differ, {} not reproducible; {} regressions; {:.1} s",
            self.results.len(),
            self.count(Status::Reproduced),
            self.count(Status::Differs),
            self.count(Status::NotReproducible),
            self.regressions().len(),
            self.elapsed_s
        )
    }

    /// Markdown report with the table, notes and plot links.
    pub fn markdown(&self) -> String {
        let mut s = String::from("# Validation against the dissertation's reported numbers\n\n");
        s.push_str(&format!("{}\n\n", self.summary_line()));
        s.push_str("Method and regression rule: `docs/validation.md`. Units are the fixture's printed units.\n\n");
        let regs = self.regressions();
        if !regs.is_empty() {
            s.push_str("## Regressions\n\n");
            for r in regs {
                s.push_str(&format!("- `{}`: {}\n", r.label(), r.note));
            }
            s.push('\n');
        }
        if !self.failed_checks.is_empty() {
            s.push_str("## Failed checks\n\n");
            for (n, e) in &self.failed_checks {
                s.push_str(&format!("- `{n}`: {e}\n"));
            }
            s.push('\n');
        }
        s.push_str("## Table\n\n| quantity | unit | reported | simulated | error | tolerance | status | note |\n|---|---|---|---|---|---|---|---|\n");
        for r in &self.results {
            let c = row_cells(r);
            let note = r.note.replace('|', "\\|").replace('\n', " ");
            s.push_str(&format!(
                "| `{}` | {} | {} | {} | {} | {} | {}{} | {} |\n",
                c[0],
                c[1],
                c[2].replace('|', "\\|"),
                c[3],
                c[4],
                c[5],
                c[6],
                if r.guarded { " (guarded)" } else { "" },
                note
            ));
        }
        if !self.plots.is_empty() {
            s.push_str("\n## Plots\n\n");
            for p in &self.plots {
                s.push_str(&format!(
                    "### {}\n\n![{}]({})\n\n",
                    p.title, p.title, p.file
                ));
            }
        }
        s
    }
}

fn row_cells(r: &CheckResult) -> [String; 7] {
    let tol = r.tolerance.map(|t| t.describe()).unwrap_or_default();
    let err = match (r.error, r.tolerance) {
        (Some(e), Some(t)) => t.describe_error(e),
        _ => String::new(),
    };
    [
        r.label(),
        r.unit.clone(),
        r.reported_text.clone(),
        r.simulated.map(fmt_num).unwrap_or_default(),
        err,
        tol,
        r.status.as_str().to_string(),
    ]
}

/// Four significant digits, plain or scientific.
pub fn fmt_num(v: f64) -> String {
    if !v.is_finite() {
        return format!("{v}");
    }
    if v == 0.0 {
        return "0".into();
    }
    let a = v.abs();
    if (1e-3..1e6).contains(&a) {
        let digits = (3 - a.log10().floor() as i32).max(0) as usize;
        let s = format!("{v:.digits$}");
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        }
    } else {
        format!("{v:.3e}")
    }
}

/// State handed to the checks: fixtures in, rows and plots out.
pub struct Ctx<'a> {
    fixtures: &'a Fixtures,
    results: Vec<CheckResult>,
    plots: Vec<PlotData>,
    /// Shared expensive computations (filled lazily by the checks that need them).
    cache: Cache,
}

#[derive(Default)]
struct Cache {
    sens: Option<[SensitivityTable; 2]>,
    ahp_w: Option<Vec<f64>>,
}

impl<'a> Ctx<'a> {
    fn row(&self, id: &str, key: Option<&str>, variant: Option<&str>) -> CheckResult {
        let f = self.fixtures.get(id);
        let reported = f.and_then(|f| f.number(key));
        let reported_text = match (reported, f) {
            (Some(v), _) => fmt_num(v),
            (None, Some(f)) => {
                let path: Vec<&str> = key.map(|k| k.split('.').collect()).unwrap_or_default();
                let v = descend(&f.value, &path).unwrap_or(&Value::Null);
                let t = match v {
                    Value::Null => String::new(),
                    Value::String(s) => s.clone(),
                    other => other.to_string(),
                };
                t.chars().take(60).collect()
            }
            _ => String::new(),
        };
        CheckResult {
            id: id.to_string(),
            key: key.map(String::from),
            variant: variant.map(String::from),
            kind: f.map(|f| f.kind.clone()).unwrap_or_default(),
            description: f.map(|f| f.description.clone()).unwrap_or_default(),
            unit: f.map(|f| f.unit.clone()).unwrap_or_default(),
            reported,
            reported_text,
            simulated: None,
            error: None,
            tolerance: None,
            status: Status::NotReproducible,
            guarded: f.is_some_and(|f| f.guards(key)),
            note: String::new(),
        }
    }

    /// Compare a simulated number (in the fixture's printed unit) with fixture `id` at `key`.
    pub fn compare(
        &mut self,
        id: &str,
        key: Option<&str>,
        variant: Option<&str>,
        simulated: f64,
        note: impl Into<String>,
    ) {
        let mut r = self.row(id, key, variant);
        r.simulated = Some(simulated);
        r.note = note.into();
        let tol = self
            .fixtures
            .get(id)
            .and_then(|f| Tolerance::from_fixture(&f.tolerance, key));
        match (r.reported, tol) {
            (Some(rep), Some(t)) => {
                r.tolerance = Some(t);
                r.error = Some(t.error(rep, simulated));
                r.status = if t.within(rep, simulated) {
                    Status::Reproduced
                } else {
                    Status::Differs
                };
            }
            _ => {
                r.status = Status::NotReproducible;
                r.note = format!("fixture has no number or tolerance here; {}", r.note);
            }
        }
        self.results.push(r);
    }

    /// A qualitative (sign / trend) check.
    pub fn qualitative(
        &mut self,
        id: &str,
        key: Option<&str>,
        passed: bool,
        note: impl Into<String>,
    ) {
        let mut r = self.row(id, key, None);
        r.status = if passed {
            Status::Reproduced
        } else {
            Status::Differs
        };
        r.note = note.into();
        self.results.push(r);
    }

    /// A fixture (or one key of it) we cannot compute, with the reason.
    pub fn not_reproducible(&mut self, id: &str, key: Option<&str>, reason: impl Into<String>) {
        let mut r = self.row(id, key, None);
        r.note = reason.into();
        self.results.push(r);
    }

    fn plot(
        &mut self,
        file: &str,
        title: &str,
        x: &str,
        y: &str,
        series: Vec<(String, Vec<f64>, Vec<f64>)>,
    ) {
        self.plots.push(PlotData {
            file: file.into(),
            title: title.into(),
            x_label: x.into(),
            y_label: y.into(),
            series,
        });
    }

    fn fx(&self) -> &'a Fixtures {
        self.fixtures
    }
}

type CheckFn = fn(&mut Ctx) -> Result<(), String>;

/// The registry: (name, fixture ids it covers, computation). The ids let [`run`] list the
/// fixtures of a failed check as not reproduced with the error as reason.
pub const CHECKS: &[(&str, &[&str], CheckFn)] = &[
    (
        "ahp_weights",
        &["s4_ahp_w_ii_i", "s4_ahp_w_iii_ii", "s4_ahp_w"],
        check_ahp,
    ),
    ("table_3_1_4_1_parameters", &[], check_yaw_parameters),
    ("table_6_2_tire", &[], check_tire),
    ("table_2_4_terrain", &[], check_terrain),
    ("table_6_3_hps_front_axle", &[], check_hps_front),
    (
        "hps_lab",
        &[
            "static_pressure_75mm",
            "static_pressure_100mm",
            "static_pressure_115mm",
            "mid_position_pressure",
            "p_rod_min_compression",
            "s5_min_rod_side_pressure",
            "s5_saturation_pressures",
            "s5_dynamic_qualitative",
        ],
        check_hps_lab,
    ),
    (
        "sensitivity_3_4_3",
        &[
            "s3_sens_a0_arm_length_peak",
            "s3_sens_kl_damping_loaded",
            "s3_sens_muv_damping_loaded",
            "s3_sens_muv_damping_unloaded",
            "s3_sens_kl_minus30_damping",
            "s3_sens_beff_damping",
            "s3_sens_a0_gain",
            "s3_sens_beff_overshoot",
            "s3_sens_beff_minus30_overshoot",
            "s3_sens_kl_muv_overshoot",
            "s3_sens_qualitative_trends",
        ],
        check_sensitivity,
    ),
    (
        "a0_frequency_peak",
        &["s3_sens_a0_frequency_peak"],
        check_a0_peak,
    ),
    (
        "yaw_frequency",
        &["s6_omega_z_unsuspended"],
        check_yaw_frequency,
    ),
    (
        "yaw_plane_qualitative",
        &[
            "s3_leakage_decay_steady_turn",
            "s3_nonzero_final_articulation_after_pulse",
        ],
        check_yaw_qualitative,
    ),
    (
        "gain_efficiency",
        &["s4_gain_efficiency_r2"],
        check_gain_efficiency,
    ),
    ("chapter_4_designs", &[], check_chapter4),
    ("not_reproducible", &[], list_not_reproducible),
];

/// Run every check against the fixtures in `fixture_dir`.
pub fn run(fixture_dir: &Path) -> Result<Report, ValidateError> {
    let t0 = Instant::now();
    let fixtures = load_fixtures(fixture_dir)?;
    let mut ctx = Ctx {
        fixtures: &fixtures,
        results: Vec::new(),
        plots: Vec::new(),
        cache: Cache::default(),
    };
    let mut failed = Vec::new();
    for (name, ids, check) in CHECKS {
        if let Err(e) = check(&mut ctx) {
            for id in *ids {
                if !ctx.results.iter().any(|r| r.id == *id) {
                    ctx.not_reproducible(id, None, format!("check `{name}` failed: {e}"));
                }
            }
            failed.push((name.to_string(), e));
        }
    }
    // Every result / qualitative fixture must appear.
    for f in fixtures.by_id.values() {
        let listed = f.kind == "result" || f.kind == "qualitative";
        if (listed || f.guards(None) || !f.reproduced_keys.is_empty())
            && !ctx.results.iter().any(|r| r.id == f.id)
        {
            ctx.not_reproducible(&f.id, None, "no check registered for this quantity");
        }
    }
    // Guarded keys without a row are regressions too.
    for f in fixtures.by_id.values() {
        for k in &f.reproduced_keys {
            if !ctx
                .results
                .iter()
                .any(|r| r.id == f.id && r.key.as_deref() == Some(k))
            {
                ctx.not_reproducible(&f.id, Some(k), "no check registered for this key");
            }
        }
    }
    Ok(Report {
        results: ctx.results,
        plots: ctx.plots,
        failed_checks: failed,
        elapsed_s: t0.elapsed().as_secs_f64(),
    })
}

/// Write `report.md`, `report.json` and the SVG plots into `out_dir`.
pub fn write_outputs(report: &Report, out_dir: &Path) -> Result<(), ValidateError> {
    let err = |e: String| ValidateError::Output(e);
    std::fs::create_dir_all(out_dir).map_err(|e| err(format!("{}: {e}", out_dir.display())))?;
    for p in &report.plots {
        let series: Vec<afsv_plot::Series<'_>> = p
            .series
            .iter()
            .map(|(label, x, y)| afsv_plot::Series { label, x, y })
            .collect();
        afsv_plot::line_plot(
            &out_dir.join(&p.file),
            &p.title,
            &p.x_label,
            &p.y_label,
            &series,
        )
        .map_err(err)?;
    }
    let md = out_dir.join("report.md");
    std::fs::write(&md, report.markdown()).map_err(|e| err(format!("{}: {e}", md.display())))?;
    let js = out_dir.join("report.json");
    let text = serde_json::to_string_pretty(report).map_err(|e| err(e.to_string()))?;
    std::fs::write(&js, text).map_err(|e| err(format!("{}: {e}", js.display())))?;
    Ok(())
}

// ---------------------------------------------------------------------------------------
// Checks
// ---------------------------------------------------------------------------------------

const DEG: f64 = std::f64::consts::PI / 180.0;
/// Speed of the section 3.3/3.4 and chapter 4 tests (50 km/h) in m/s.
const TEST_SPEED_M_S: f64 = 50.0 / 3.6;

fn matrix(v: &Value) -> Result<Vec<Vec<f64>>, String> {
    v.as_array()
        .ok_or("not a matrix")?
        .iter()
        .map(|r| {
            r.as_array()
                .ok_or_else(|| "matrix row is not an array".to_string())?
                .iter()
                .map(|x| x.as_f64().ok_or_else(|| "non-numeric entry".to_string()))
                .collect()
        })
        .collect()
}

/// Level-II weights (Eq 4.12), level-III columns (Eq 4.15) and composite weights (Eq 4.17).
type AhpLevels = (Vec<f64>, Vec<Vec<f64>>, Vec<f64>);

fn ahp_weights(fx: &Fixtures) -> Result<AhpLevels, String> {
    use optimize::ahp::{compose, embed, weights};
    let rows = |id: &str| -> Result<Vec<Vec<f64>>, String> {
        matrix(&fx.get(id).ok_or(format!("missing fixture {id}"))?.value["rows"])
    };
    let w2 = weights(&rows("s4_ahp_m2")?)
        .map_err(|e| e.to_string())?
        .weights;
    // Level-III measures [L, omega, zeta, Gamma, OS, psi]; the three sub-matrices of Eq 4.14
    // compare (L, omega, zeta), (zeta, Gamma), (Gamma, OS, psi).
    let subsets: [(&str, &[usize]); 3] = [
        ("s4_ahp_m3_a1", &[0, 1, 2]),
        ("s4_ahp_m3_a2", &[2, 3]),
        ("s4_ahp_m3_a3", &[3, 4, 5]),
    ];
    let mut lower = Vec::new();
    for (id, idx) in subsets {
        let w = weights(&rows(id)?).map_err(|e| e.to_string())?.weights;
        lower.push(embed(&w, idx, 6));
    }
    let wa: Vec<f64> = fx
        .get("s4_ahp_wa")
        .and_then(|f| f.value["diagonal"].as_array())
        .ok_or("s4_ahp_wa has no diagonal")?
        .iter()
        .filter_map(Value::as_f64)
        .collect();
    let w = compose(&lower, &wa, &w2).map_err(|e| e.to_string())?;
    Ok((w2, lower, w))
}

/// AHP weights of Eqs 4.12, 4.15 and 4.17 from the printed pairwise matrices.
fn check_ahp(ctx: &mut Ctx) -> Result<(), String> {
    let (w2, lower, w) = ahp_weights(ctx.fx())?;
    let note = "principal eigenvector (optimize::ahp::weights) of the printed matrix";
    for (i, v) in w2.iter().enumerate() {
        ctx.compare("s4_ahp_w_ii_i", Some(&i.to_string()), None, *v, note);
    }
    for (col, c) in lower.iter().enumerate() {
        for (row, v) in c.iter().enumerate() {
            ctx.compare(
                "s4_ahp_w_iii_ii",
                Some(&format!("{row}.{col}")),
                None,
                *v,
                "sub-matrix eigenvectors embedded per Eq 4.14",
            );
        }
    }
    for (i, v) in w.iter().enumerate() {
        ctx.compare(
            "s4_ahp_w",
            Some(&i.to_string()),
            None,
            *v,
            "optimize::ahp::compose(W_III/II, W_a, W_II/I), Eq 4.17",
        );
    }
    ctx.cache.ahp_w = Some(w);
    Ok(())
}

/// Table 3.1 / 4.1 / 4.2 (nominal column) and Table 3.2 against our nominal parameter sets.
fn check_yaw_parameters(ctx: &mut Ctx) -> Result<(), String> {
    let kn_deg = |v: f64| v * DEG / 1e3;
    let note = "VehicleParams::nominal";
    for load in Load::ALL {
        let v = VehicleParams::nominal(load);
        let k = Some(load.name());
        for t in ["t3_1", "t4_1"] {
            for (name, val) in [
                ("m_f", v.m_f_kg),
                ("m_r", v.m_r_kg),
                ("i_f", v.i_f_kg_m2),
                ("i_r", v.i_r_kg_m2),
                ("l_f1", v.l_f1_m),
                ("l_f2", v.l_f2_m),
                ("l_r1", v.l_r1_m),
                ("l_r2", v.l_r2_m),
            ] {
                ctx.compare(&format!("{t}_{name}"), k, None, val, note);
            }
        }
        for (name, val) in [
            ("c_alpha_f", kn_deg(v.c_alpha_f_n_per_rad)),
            ("c_alpha_r", kn_deg(v.c_alpha_r_n_per_rad)),
            ("k_mzf", kn_deg(v.k_mz_f_nm_per_rad)),
            ("k_mzr", kn_deg(v.k_mz_r_nm_per_rad)),
            ("sigma_y", v.relaxation_length_m),
            ("half_track", v.half_track_m),
        ] {
            ctx.compare(&format!("t3_1_{name}"), k, None, val, note);
        }
    }
    let a = AfsParams::nominal();
    let note = "AfsParams::nominal (table units for the unstated ones, docs/afs-hydraulics.md)";
    let common = [
        ("a0", a.a0_rad / DEG),
        ("l1", a.l1_m),
        ("l2", a.l2_m),
        ("a_c", a.piston_area_m2 * 1e4),
        ("a_r", a.annulus_area_m2 * 1e4),
        ("b_eff", a.bulk_modulus_pa / 1e9),
    ];
    for t in ["t3_1", "t4_1"] {
        for (name, val) in common {
            ctx.compare(&format!("{t}_{name}"), None, None, val, note);
        }
    }
    for (name, val) in [
        ("x0", a.dead_band_rad / DEG),
        ("v0", a.dead_volume_m3 * 1e3),
        ("p_s", a.supply_pressure_pa / 1e6),
        ("p0", a.reservoir_pressure_pa / 1e6),
        ("mu_v", a.seal_viscous_n_s_m / MU_V_TABLE_UNIT),
        ("k_l0", a.leak_const),
        ("k_l", a.leak_velocity),
        ("k_theta", a.gerotor_displacement * DEG * 1e6),
        ("k_v", a.return_factor),
        ("eta_g", a.gerotor_efficiency),
    ] {
        ctx.compare(&format!("t3_1_{name}"), None, None, val, note);
    }
    for (name, val) in [
        ("a_0", a.valve_a0_per_pa / VALVE_A0_TABLE_UNIT),
        ("a_m", a.valve_am / VALVE_AM_TABLE_UNIT),
        ("a_v", a.valve_av / VALVE_AV_TABLE_UNIT),
    ] {
        ctx.compare(&format!("t4_1_{name}"), None, None, val, note);
    }
    for (name, val) in [
        ("a0", a.a0_rad / DEG),
        ("l1", a.l1_m),
        ("l2", a.l2_m),
        ("a_v", a.valve_av / VALVE_AV_TABLE_UNIT),
        ("b_eff", a.bulk_modulus_pa / 1e9),
    ] {
        ctx.compare(
            &format!("t4_2_{name}_bounds"),
            Some("nominal"),
            None,
            val,
            note,
        );
        for t in ["t4_3", "t4_4"] {
            ctx.compare(
                &format!("{t}_opt_{name}"),
                Some("current"),
                None,
                val,
                "current design = AfsParams::nominal",
            );
            for k in ["ps", "ps_sqp"] {
                ctx.not_reproducible(
                    &format!("{t}_opt_{name}"),
                    Some(k),
                    "optimum location needs the chapter-4 PS / PS-SQP optimisation, not implemented",
                );
            }
        }
    }
    let note = "afsv_dynamics::table_3_2_speeds_kmh (mean speeds)";
    for (id, course, load, i) in [
        (
            "t3_2_speed_steady_turn_loaded",
            FieldCourse::SteadyTurn,
            Load::Loaded,
            0,
        ),
        (
            "t3_2_speed_steady_turn_unloaded_a",
            FieldCourse::SteadyTurn,
            Load::Unloaded,
            0,
        ),
        (
            "t3_2_speed_steady_turn_unloaded_b",
            FieldCourse::SteadyTurn,
            Load::Unloaded,
            1,
        ),
        (
            "t3_2_speed_path_change_loaded",
            FieldCourse::PathChange,
            Load::Loaded,
            0,
        ),
        (
            "t3_2_speed_path_change_unloaded_a",
            FieldCourse::PathChange,
            Load::Unloaded,
            0,
        ),
        (
            "t3_2_speed_path_change_unloaded_b",
            FieldCourse::PathChange,
            Load::Unloaded,
            1,
        ),
    ] {
        let s = table_3_2_speeds_kmh(course, load)
            .get(i)
            .copied()
            .unwrap_or(f64::NAN);
        ctx.compare(id, Some("mean"), None, s, note);
    }
    Ok(())
}

/// Table 6.2 against `TireParams::nominal`, and its cornering stiffness evaluated at the
/// static tire loads derived from Table 6.1 (pitch-rigid articulation joint).
fn check_tire(ctx: &mut Ctx) -> Result<(), String> {
    let p = tire_fiala::TireParams::nominal();
    let note = "TireParams::nominal";
    ctx.compare("t6_2_free_radius", None, None, p.unloaded_radius_m, note);
    ctx.compare("t6_2_width", None, None, p.width_m, note);
    ctx.compare(
        "t6_2_charge_pressure",
        None,
        None,
        p.charge_pressure_pa / 1e5,
        note,
    );
    let table = p.cornering_table().map_err(|e| e.to_string())?;
    let fx = ctx.fx();
    let n = |id: &str| fx.num(id, None);
    let g = 9.81;
    let x_front_cg = n("t6_1_front_axle_to_joint")? - n("t6_1_front_unit_cg_to_joint")?;
    let x_rear_cg = n("t6_1_front_axle_to_joint")? + n("t6_1_rear_unit_cg_to_joint")?;
    let x_payload = n("t6_1_front_axle_to_joint")? + n("t6_1_payload_cg_to_joint")?;
    let wheelbase = n("t6_1_wheel_base")?;
    for (key, payload) in [("loaded", n("t6_1_payload_mass")?), ("unloaded", 0.0)] {
        let masses = [
            (n("t6_1_front_unit_mass")?, x_front_cg),
            (n("t6_1_rear_unit_mass")?, x_rear_cg),
            (payload, x_payload),
        ];
        let total: f64 = masses.iter().map(|m| m.0).sum();
        let moment: f64 = masses.iter().map(|(m, x)| m * x).sum();
        let rear_tire = moment / wheelbase * g / 2.0;
        let front_tire = total * g / 2.0 - rear_tire;
        for (id, fz) in [
            ("t6_2_front_cornering_stiffness", front_tire),
            ("t6_2_rear_cornering_stiffness", rear_tire),
        ] {
            ctx.compare(
                id,
                Some(key),
                None,
                table.at(fz) * DEG / 1e3,
                format!(
                    "nominal C_alpha(F_z) table at the Table 6.1 static tire load {:.1} kN",
                    fz / 1e3
                ),
            );
        }
    }
    Ok(())
}

/// Table 2.4 roughness parameters against `terrain_psd`.
fn check_terrain(ctx: &mut Ctx) -> Result<(), String> {
    use terrain_psd::{IsoClass, OffRoadTerrain, PowerLawPsd};
    for (id, c) in [
        ("t2_4_iso_class_a", IsoClass::A),
        ("t2_4_iso_class_b", IsoClass::B),
        ("t2_4_iso_class_c", IsoClass::C),
        ("t2_4_iso_class_d", IsoClass::D),
        ("t2_4_iso_class_e", IsoClass::E),
    ] {
        let p = PowerLawPsd::iso(c);
        let note = "PowerLawPsd::iso (ISO 8608 G_d(n0) n0^2)";
        ctx.compare(id, Some("alpha_r"), None, p.alpha_r, note);
        ctx.compare(id, Some("w"), None, p.waviness, note);
    }
    for (id, t) in [
        ("t2_4_offroad_forestry", OffRoadTerrain::Forestry),
        ("t2_4_offroad_pasture", OffRoadTerrain::Pasture),
        ("t2_4_offroad_mvee", OffRoadTerrain::Mvee),
        ("t2_4_offroad_plowed", OffRoadTerrain::Plowed),
    ] {
        let p = PowerLawPsd::off_road(t);
        ctx.compare(
            id,
            Some("alpha_r"),
            None,
            p.alpha_r,
            "PowerLawPsd::off_road",
        );
        ctx.compare(id, Some("w"), None, p.waviness, "PowerLawPsd::off_road");
    }
    Ok(())
}

/// Table 6.3 against `StrutParams::front_axle`, and the nominal column of Table 6.5.
fn check_hps_front(ctx: &mut Ctx) -> Result<(), String> {
    let p = hps_emulsion::StrutParams::front_axle();
    let note = "StrutParams::front_axle";
    let oil = (p.v_c0 + p.v_r0) / (1.0 + p.gamma0);
    for (id, v) in [
        ("t6_3_piston_area", p.a_hc),
        ("t6_3_rod_area", p.a_hr),
        ("t6_3_check_valve_area", p.a_v * 1e6),
        ("t6_3_check_valve_cd", p.c_v),
        ("t6_3_check_valve_number", p.n_v as f64),
        ("t6_3_bleed_orifice_area", p.a_b * 1e6),
        ("t6_3_bleed_orifice_cd", p.c_b),
        ("t6_3_bleed_orifice_number", p.n_b as f64),
        ("t6_3_strut_travel", p.travel * 1e3),
        ("t6_3_total_oil_volume", oil * 1e3),
        ("t6_3_oil_bulk_modulus", p.beta_h / 1e6),
        ("t6_3_oil_density", p.rho_h),
        ("t6_3_initial_gas_volume", p.v_g0 * 1e3),
        ("t6_3_initial_gas_pressure", p.p_h0 / 1e6),
        ("t6_3_initial_gas_fraction", p.gamma0 * 100.0),
        ("t6_3_polytropic_exponent", p.n),
        ("t6_3_leakage_coefficient", p.k_l),
    ] {
        ctx.compare(id, None, None, v, note);
    }
    for (id, v) in [
        ("t6_5_a_hc", p.a_hc),
        ("t6_5_a_v", p.a_v * 1e6),
        ("t6_5_a_b", p.a_b * 1e6),
    ] {
        ctx.compare(
            id,
            Some("nominal"),
            None,
            v,
            "nominal design = StrutParams::front_axle",
        );
        ctx.not_reproducible(
            id,
            Some("optimal"),
            "needs the chapter-6 HPS optimisation on the 3-D vehicle, not implemented",
        );
    }
    Ok(())
}

/// The laboratory strut of chapter 5 identified from `hps_lab.json` (as the hps-emulsion
/// crate does), then simulated.
fn check_hps_lab(ctx: &mut Ctx) -> Result<(), String> {
    use hps_emulsion::{
        identify_lab, run_harmonic, HarmonicTest, HpsExtensions, HpsStrut, LabConfig, LabReported,
    };
    let fx = ctx.fx();
    let n = |id: &str| fx.num(id, None);
    let mm = 1e-3;
    let mpa = 1e6;
    let rep = LabReported {
        oil_volume: n("oil_volume")? * 1e-3,
        charge_pressure: n("charge_pressure")? * mpa,
        static_displacements: [
            n("static_displacement_75mm")? * mm,
            n("static_displacement_100mm")? * mm,
            n("static_displacement_115mm")? * mm,
        ],
        static_pressures: [
            n("static_pressure_75mm")? * mpa,
            n("static_pressure_100mm")? * mpa,
            n("static_pressure_115mm")? * mpa,
        ],
        mid_position_pressure: n("mid_position_pressure")? * mpa,
        saturation_pressure_one: n("saturation_pressure_one_orifice")? * mpa,
        saturation_pressure_two: n("saturation_pressure_two_orifices")? * mpa,
        c_b_one: n("c_b_one_orifice")?,
        c_b_two: n("c_b_two_orifices")?,
        c_v: n("c_v")?,
        k_l: n("k_l")?,
        k_s: n("k_s")?,
        mu_v: n("mu_v")?,
        peak_velocity: n("peak_velocity_max")?,
        p_rod_min_compression: n("p_rod_min_compression")? * mpa,
        n: n("polytropic_exponent")?,
    };
    hps_emulsion::lab::validate_reported(&rep).map_err(|e| e.to_string())?;
    let one = identify_lab(&rep, LabConfig::OneOrifice);
    let two = identify_lab(&rep, LabConfig::TwoOrifices);
    let why = "fresh strut (no emulsion, charged at the bottom) after the one-parameter gas-column fit with n = 1.4 (hps_emulsion::identify_lab), HpsStrut::static_pressure";
    for (i, id) in [
        "static_pressure_75mm",
        "static_pressure_100mm",
        "static_pressure_115mm",
    ]
    .iter()
    .enumerate()
    {
        ctx.compare(id, None, None, one.static_pressures[i] / mpa, why);
    }
    ctx.compare(
        "mid_position_pressure",
        None,
        None,
        one.static_pressures[0] / mpa,
        "fresh strut at mid-stroke (75 mm from the bottom)",
    );
    // Static pressure curve of the fresh strut for the plot (same construction as identify_lab).
    let mut fresh = one.params;
    let (oil_c, oil_r) = (
        fresh.v_c0 / (1.0 + fresh.gamma0),
        fresh.v_r0 / (1.0 + fresh.gamma0),
    );
    fresh.gamma0 = 0.0;
    fresh.v_c0 = oil_c;
    fresh.v_r0 = oil_r;
    fresh.p_h0 =
        rep.charge_pressure * (one.gas_length / (one.gas_length - one.mid_stroke)).powf(rep.n);
    let strut = HpsStrut::new(&fresh, &HpsExtensions::none(), 0.0).map_err(|e| e.to_string())?;
    let (mut xs, mut ps) = (Vec::new(), Vec::new());
    for i in 0..=30 {
        let z = 0.020 + 0.100 * i as f64 / 30.0;
        if let Ok(p) = strut.static_pressure(z - one.mid_stroke) {
            xs.push(z / mm);
            ps.push(p / mpa);
        }
    }
    let rx: Vec<f64> = rep.static_displacements.iter().map(|z| z / mm).collect();
    let ry: Vec<f64> = rep.static_pressures.iter().map(|p| p / mpa).collect();
    ctx.plot(
        "hps_static_pressure.svg",
        "Lab HPS: static pressure vs displacement from the bottom (section 5.4.1)",
        "displacement from bottom (mm)",
        "P_hc (MPa, absolute)",
        vec![
            ("model (fresh strut, n = 1.4)".into(), xs, ps),
            ("reported 1.43 / 2.05 / 2.74 MPa".into(), rx, ry),
        ],
    );
    // Lowest rod-side pressure in compression: one orifice, 2 Hz, the largest peak velocity.
    let test = HarmonicTest::at_peak_velocity(2.0, rep.peak_velocity);
    let opts = hps_emulsion::SimOptions::default();
    let ext = HpsExtensions::none();
    let (_, m1) = run_harmonic(&one.params, &ext, &test, 3.0, &opts).map_err(|e| e.to_string())?;
    let why = "one-orifice lab strut, 2 Hz at 0.2356 m/s, 3 cycles, lowest P_hr of the last (the annulus was identified from this number with the quasi-steady Eq 5.12; this is the dynamic simulation)";
    ctx.compare(
        "p_rod_min_compression",
        None,
        None,
        m1.p_rod_min_pa / mpa,
        why,
    );
    ctx.compare(
        "s5_min_rod_side_pressure",
        None,
        None,
        m1.p_rod_min_pa / mpa,
        why,
    );
    // Saturation pressures: identification inputs (the reference pressure of each strut).
    for (key, id) in [("one_orifice", &one), ("two_orifices", &two)] {
        ctx.compare(
            "s5_saturation_pressures",
            Some(key),
            None,
            id.params.p_h0 / mpa,
            "by construction: the identification uses it as the mid-stroke reference pressure; predicting it needs the hours-long gas dissolution, outside Eqs 5.1-5.12",
        );
    }
    ctx.not_reproducible(
        "pressure_drop_after_emulsion",
        None,
        "gas dissolution into the oil over hours is outside Eqs 5.1-5.12 (not modelled)",
    );
    // Qualitative dynamic behaviour, the parts our baseline model can speak to.
    let t5 = HarmonicTest::at_peak_velocity(5.0, rep.peak_velocity);
    let (_, a) = run_harmonic(&one.params, &ext, &t5, 3.0, &opts).map_err(|e| e.to_string())?;
    let (_, b) = run_harmonic(&two.params, &ext, &t5, 3.0, &opts).map_err(|e| e.to_string())?;
    let both = a.peak_damping_extension_n > a.peak_damping_compression_n
        && b.peak_damping_extension_n > b.peak_damping_compression_n;
    ctx.qualitative(
        "s5_dynamic_qualitative",
        Some("both"),
        both,
        format!(
            "extension vs compression peak damping force at 5 Hz, 0.2356 m/s: one orifice {:.0} / {:.0} N, two {:.0} / {:.0} N (friction/stiction part not checked)",
            a.peak_damping_extension_n, a.peak_damping_compression_n,
            b.peak_damping_extension_n, b.peak_damping_compression_n
        ),
    );
    ctx.qualitative(
        "s5_dynamic_qualitative",
        Some("one_orifice"),
        a.peak_damping_extension_n > 1.5 * b.peak_damping_extension_n,
        format!(
            "one-orifice extension damping {:.0} N vs two orifices {:.0} N (> 1.5x required); P_hc hysteresis / phase error not checked",
            a.peak_damping_extension_n, b.peak_damping_extension_n
        ),
    );
    ctx.not_reproducible(
        "s5_dynamic_qualitative",
        Some("pseudo_static"),
        "pseudo-static loop hysteresis is attributed to gas heat transfer, which the baseline (adiabatic) model leaves out; a switchable HeatTransfer extension exists but has no identified time constant",
    );
    ctx.not_reproducible(
        "s5_dynamic_qualitative",
        Some("two_orifices"),
        "loop shapes are read from Figs 5.9-5.12, absent from the text",
    );
    ctx.not_reproducible(
        "s5_gamma0_trend",
        None,
        "gamma_0 versus peak velocity is identified from measured loops (Fig 5.4b, absent); the model takes gamma_0 as a parameter",
    );
    Ok(())
}

fn sens_tables(ctx: &mut Ctx) -> Result<[SensitivityTable; 2], String> {
    if let Some(t) = &ctx.cache.sens {
        return Ok(t.clone());
    }
    let mut out = Vec::new();
    for form in [EquationForm::EnergyConsistent, EquationForm::PaperEq313] {
        let mut spec = MeasureSpec::default();
        spec.options.form = form;
        out.push(sensitivity(TEST_SPEED_M_S, &spec).map_err(|e| e.to_string())?);
    }
    let t: [SensitivityTable; 2] = [out.remove(0), out.remove(0)];
    ctx.cache.sens = Some(t.clone());
    Ok(t)
}

fn change(
    t: &SensitivityTable,
    load: Load,
    p: SensitivityParam,
    pct: f64,
) -> Result<MeasureChanges, String> {
    t.rows
        .iter()
        .find(|r| r.load == load && r.parameter == p && (r.variation_percent - pct).abs() < 1e-9)
        .map(|r| r.change)
        .ok_or_else(|| {
            format!(
                "no sensitivity row for {} {} {pct}",
                load.name(),
                p.symbol()
            )
        })
}

/// Section 3.4.3 sensitivity percentages, energy-consistent model (printed Eq 3.13 in the note).
fn check_sensitivity(ctx: &mut Ctx) -> Result<(), String> {
    use SensitivityParam::*;
    let [ec, pf] = sens_tables(ctx)?;
    // Kinematics: the A_0 that maximises the initial steering arm h(0) (Eq 3.2).
    let a = AfsParams::nominal();
    let arm = |a0: f64| {
        let l0 = afs_hydraulics::kinematics::strut_length(a.l1_m, a.l2_m, a0);
        strut_kinematics(a.l1_m, a.l2_m, a0, l0, 0.0).arm_left
    };
    let (mut lo, mut hi) = (30.0 * DEG, 150.0 * DEG);
    let phi = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..100 {
        let m1 = hi - phi * (hi - lo);
        let m2 = lo + phi * (hi - lo);
        if arm(m1) < arm(m2) {
            lo = m1;
        } else {
            hi = m2;
        }
    }
    let a0_best = 0.5 * (lo + hi);
    ctx.compare(
        "s3_sens_a0_arm_length_peak",
        None,
        None,
        100.0 * (a0_best / a.a0_rad - 1.0),
        format!(
            "golden-section maximum of strut_kinematics arm h(0) at A_0 = {:.2} deg",
            a0_best / DEG
        ),
    );
    type Pick = fn(&MeasureChanges) -> f64;
    let damping: Pick = |c| c.damping;
    let gain: Pick = |c| c.gain;
    let overshoot: Pick = |c| c.overshoot;
    /// (fixture id, key, load, parameter, variation %, measure, reason it may differ)
    type Case<'a> = (
        &'a str,
        Option<&'a str>,
        Load,
        SensitivityParam,
        f64,
        Pick,
        &'a str,
    );
    let cases: [Case; 9] = [
        ("s3_sens_kl_damping_loaded", None, Load::Loaded, LeakVelocity, 30.0, damping, ""),
        ("s3_sens_muv_damping_loaded", None, Load::Loaded, SealViscous, 30.0, damping, ""),
        (
            "s3_sens_muv_damping_unloaded",
            None,
            Load::Unloaded,
            SealViscous,
            30.0,
            damping,
            "our seal friction acts more on the light unloaded rear unit (faster 7.3 Hz yaw mode); mu_v's unit is not printed (docs/afs-hydraulics.md)",
        ),
        ("s3_sens_kl_minus30_damping", None, Load::Loaded, LeakVelocity, -30.0, damping, "load not stated; loaded used"),
        (
            "s3_sens_beff_damping",
            None,
            Load::Loaded,
            BulkModulus,
            30.0,
            damping,
            "load not stated; loaded used. Our yaw mode is stiffer (5.5 Hz vs the paper's lower frequency), so zeta ~ c/(2 sqrt(kJ)) falls more with B_eff",
        ),
        ("s3_sens_beff_overshoot", Some("loaded"), Load::Loaded, BulkModulus, 30.0, overshoot, ""),
        ("s3_sens_beff_overshoot", Some("unloaded"), Load::Unloaded, BulkModulus, 30.0, overshoot, ""),
        ("s3_sens_beff_minus30_overshoot", None, Load::Loaded, BulkModulus, -30.0, overshoot, "load not stated; loaded used"),
        (
            "s3_sens_kl_muv_overshoot",
            Some("k_l_plus30"),
            Load::Loaded,
            LeakVelocity,
            30.0,
            overshoot,
            "our velocity-dependent leakage (k_l h |dtheta/dt|) acts only while the struts move and our rise is faster, so it trims overshoot less",
        ),
    ];
    for (id, key, load, p, pct, pick, why) in cases {
        let s = pick(&change(&ec, load, p, pct)?);
        let s_pf = pick(&change(&pf, load, p, pct)?);
        let note = format!(
            "{} {} {pct:+}%, energy-consistent Eq 3.13 at 50 km/h; printed Eq 3.13 gives {:+.2}%. {why}",
            load.name(),
            p.symbol(),
            s_pf
        );
        ctx.compare(id, key, None, s, note.trim_end_matches(". ").to_string());
    }
    // Fixtures quoted for both loads: one row per load.
    /// (fixture id, key, parameter, variation %, measure, reason it may differ)
    type BothCase<'a> = (
        &'a str,
        Option<&'a str>,
        SensitivityParam,
        f64,
        Pick,
        &'a str,
    );
    let both: [BothCase; 2] = [
        ("s3_sens_a0_gain", None, A0, 30.0, gain, ""),
        (
            "s3_sens_kl_muv_overshoot",
            Some("mu_v_plus30"),
            SealViscous,
            30.0,
            overshoot,
            "",
        ),
    ];
    for (id, key, p, pct, pick, why) in both {
        for load in Load::ALL {
            let s = pick(&change(&ec, load, p, pct)?);
            let s_pf = pick(&change(&pf, load, p, pct)?);
            ctx.compare(
                id,
                key,
                Some(load.name()),
                s,
                format!(
                    "{} {pct:+}%, energy-consistent; printed Eq 3.13 gives {s_pf:+.2}%{why}",
                    p.symbol()
                ),
            );
        }
    }
    // Qualitative trends (signs), both loads.
    let mut fails = Vec::new();
    let mut n = 0;
    let mut expect = |ok: bool, what: String| {
        n += 1;
        if !ok {
            fails.push(what);
        }
    };
    for load in Load::ALL {
        let l = load.name();
        let c = |p, pct| change(&ec, load, p, pct);
        expect(
            c(BulkModulus, 30.0)?.frequency > 5.0 && c(BulkModulus, -30.0)?.frequency < -5.0,
            format!("{l}: frequency rises strongly with B_eff"),
        );
        for p in [LeakVelocity, SealViscous] {
            for pct in [-30.0, 30.0] {
                expect(
                    c(p, pct)?.frequency.abs() < 1.0,
                    format!("{l}: frequency insensitive to {}", p.symbol()),
                );
                let d = c(p, pct)?.damping;
                expect(
                    d * pct > 0.0,
                    format!("{l}: damping rises with {}", p.symbol()),
                );
                let g = c(p, pct)?.gain;
                expect(
                    g * pct < 0.0,
                    format!("{l}: gain falls with {}", p.symbol()),
                );
            }
        }
        expect(
            c(BulkModulus, 30.0)?.damping < 0.0,
            format!("{l}: damping falls slightly with B_eff"),
        );
        expect(
            c(A0, 30.0)?.gain > 5.0,
            format!("{l}: gain rises strongly with A_0"),
        );
        expect(
            c(BulkModulus, 30.0)?.gain > 0.0,
            format!("{l}: gain rises slightly with B_eff"),
        );
        expect(
            c(BulkModulus, 30.0)?.overshoot < -10.0 && c(BulkModulus, -30.0)?.overshoot > 10.0,
            format!("{l}: overshoot falls strongly with B_eff"),
        );
        for p in [LeakVelocity, SealViscous] {
            expect(
                c(p, 30.0)?.overshoot < 0.0,
                format!("{l}: overshoot falls with {}", p.symbol()),
            );
        }
    }
    let ok = fails.is_empty();
    ctx.qualitative(
        "s3_sens_qualitative_trends",
        None,
        ok,
        if ok {
            format!("all {n} sign checks of section 3.4.3 pass (energy-consistent, both loads)")
        } else {
            format!(
                "{} of {n} sign checks fail: {}",
                fails.len(),
                fails.join("; ")
            )
        },
    );
    // Plots: % change per measure vs variation, loaded, one curve per parameter.
    let picks: [(&str, &str, Pick); 4] = [
        ("frequency", "yaw frequency", |c| c.frequency),
        ("damping", "damping ratio", damping),
        ("gain", "steering gain", gain),
        ("overshoot", "overshoot", overshoot),
    ];
    for (file, name, pick) in picks {
        let mut series = Vec::new();
        for p in SensitivityParam::ALL {
            let xs = vec![-30.0, -15.0, 0.0, 15.0, 30.0];
            let ys: Vec<f64> = xs
                .iter()
                .map(|&v| {
                    if v == 0.0 {
                        Ok(0.0)
                    } else {
                        change(&ec, Load::Loaded, p, v).map(|c| pick(&c))
                    }
                })
                .collect::<Result<_, _>>()?;
            series.push((p.symbol().to_string(), xs, ys));
        }
        ctx.plot(
            &format!("sensitivity_{file}.svg"),
            &format!("Section 3.4.3 sensitivity, loaded, 50 km/h: {name}"),
            "parameter variation (%)",
            &format!("{name} change (%)"),
            series,
        );
    }
    Ok(())
}

/// Location of the yaw-frequency peak over A_0 (section 3.4.3: about -7.5 %).
fn check_a0_peak(ctx: &mut Ctx) -> Result<(), String> {
    let steps: Vec<f64> = (0..=10).map(|i| -17.5 + 2.5 * i as f64).collect();
    let spec = MeasureSpec::default();
    let mut series = Vec::new();
    for load in Load::ALL {
        let v = VehicleParams::nominal(load);
        let mut f = Vec::new();
        for &s in &steps {
            let a = SensitivityParam::A0.scaled(&AfsParams::nominal(), 1.0 + s / 100.0);
            let m = measures_for(&v, &a, Some(load), TEST_SPEED_M_S, &spec)
                .map_err(|e| e.to_string())?;
            f.push(m.natural_frequency_hz);
        }
        let i = (0..f.len())
            .max_by(|&a, &b| f[a].total_cmp(&f[b]))
            .unwrap_or(0);
        // Parabola through the maximum and its neighbours (the curve is flat at the top).
        let peak = if i > 0 && i + 1 < f.len() {
            let (y0, y1, y2) = (f[i - 1], f[i], f[i + 1]);
            let den = y0 - 2.0 * y1 + y2;
            let off = if den.abs() > 0.0 {
                0.5 * (y0 - y2) / den
            } else {
                0.0
            };
            steps[i] + 2.5 * off.clamp(-1.0, 1.0)
        } else {
            steps[i]
        };
        ctx.compare(
            "s3_sens_a0_frequency_peak",
            None,
            Some(load.name()),
            peak,
            format!(
                "A_0 swept -17.5..+7.5 % in 2.5 % steps, parabolic peak; {:.3} Hz at the peak vs {:.3} Hz nominal",
                f[i], f[7]
            ),
        );
        series.push((load.name().to_string(), steps.clone(), f));
    }
    ctx.plot(
        "a0_frequency_sweep.svg",
        "Yaw-mode frequency vs A_0 (energy-consistent, 50 km/h)",
        "A_0 variation (%)",
        "natural frequency (Hz)",
        series,
    );
    Ok(())
}

/// Yaw-mode frequency of the loaded vehicle at 50 km/h, both equation forms, against the
/// 2.81 Hz of the chapter-6 3-D model.
fn check_yaw_frequency(ctx: &mut Ctx) -> Result<(), String> {
    let [ec, pf] = sens_tables(ctx)?;
    let why = "2.81 Hz is the chapter-6 3-D ADAMS model's number (suspension, tire and frame compliance); the chapter-3 yaw-plane model never printed an absolute frequency";
    ctx.compare(
        "s6_omega_z_unsuspended",
        None,
        Some("yaw-plane, energy-consistent"),
        ec.nominal[0].natural_frequency_hz,
        format!("{why}. The printed Eq 3.13 counts m L^2 twice (docs/afs-yaw-plane.md), which lowers the frequency"),
    );
    ctx.compare(
        "s6_omega_z_unsuspended",
        None,
        Some("yaw-plane, printed Eq 3.13"),
        pf.nominal[0].natural_frequency_hz,
        format!("{why}. This form double-counts m L^2 (not energy-consistent) and lands nearer"),
    );
    // Pulse responses of both forms for the report.
    let mut series = Vec::new();
    for load in Load::ALL {
        for (form, name) in [
            (EquationForm::EnergyConsistent, "energy-consistent"),
            (EquationForm::PaperEq313, "printed Eq 3.13"),
        ] {
            let r = pulse_record(load, form)?;
            series.push((
                format!("{} {name}", load.name()),
                r.time_s.clone(),
                r.articulation_deg.clone(),
            ));
        }
    }
    ctx.plot(
        "yaw_pulse_response.svg",
        "Articulation after a 0.2 s, 30 deg half-sine steering pulse at 50 km/h",
        "time (s)",
        "articulation (deg)",
        series,
    );
    Ok(())
}

fn pulse_record(load: Load, form: EquationForm) -> Result<afsv_dynamics::YawRecord, String> {
    let spec = MeasureSpec::default();
    let mut opts = spec.options;
    opts.form = form;
    let sys = AfsSystem::new(AfsParams::nominal()).map_err(|e| e.to_string())?;
    simulate(
        &VehicleParams::nominal(load),
        &sys,
        &Manoeuvre::pulse(TEST_SPEED_M_S, spec.pulse_amplitude_deg),
        &opts,
    )
    .map_err(|e| e.to_string())
}

/// Section 3.4.1 / Fig 3.9 qualitative behaviour of the yaw-plane model.
fn check_yaw_qualitative(ctx: &mut Ctx) -> Result<(), String> {
    let opts = afsv_dynamics::SimOptions::default();
    let mut ok = true;
    let mut parts = Vec::new();
    for load in Load::ALL {
        let u = table_3_2_speeds_kmh(FieldCourse::SteadyTurn, load)[0] / 3.6;
        let d = steady_turn_decay(load, u, 300.0, 10.0, &opts).map_err(|e| e.to_string())?;
        let decays = d.articulation_start_deg.abs() > 1.0
            && (d.articulation_end_deg - d.articulation_start_deg)
                * d.articulation_start_deg.signum()
                < 0.0;
        ok &= decays;
        parts.push(format!(
            "{}: {:.3} -> {:.3} deg over {:.0} s ({:+.2e} deg/s)",
            load.name(),
            d.articulation_start_deg,
            d.articulation_end_deg,
            d.window_s,
            d.drift_deg_s
        ));
    }
    ctx.qualitative(
        "s3_leakage_decay_steady_turn",
        None,
        ok,
        format!(
            "300 deg wheel held at the Table 3.2 speed; |articulation| must fall: {}",
            parts.join("; ")
        ),
    );
    let r = pulse_record(Load::Loaded, EquationForm::EnergyConsistent)?;
    let n = r.articulation_deg.len();
    let tail = &r.articulation_deg[n - n / 10..];
    let final_deg = tail.iter().sum::<f64>() / tail.len() as f64;
    let peak = r
        .articulation_deg
        .iter()
        .fold(0.0f64, |m, v| m.max(v.abs()));
    let spread = tail
        .iter()
        .fold(0.0f64, |m, v| m.max((v - final_deg).abs()));
    ctx.qualitative(
        "s3_nonzero_final_articulation_after_pulse",
        None,
        final_deg.abs() > 0.05 * peak && spread < 0.2 * final_deg.abs(),
        format!(
            "loaded, 50 km/h: articulation settles at {final_deg:.3} deg (peak {peak:.3} deg, last-second spread {spread:.1e} deg): the volume-regulated valve keeps the displaced oil"
        ),
    );
    ctx.not_reproducible(
        "s3_strut_displacement_model_bias",
        None,
        "a model-vs-measurement bias: needs the field records of Fig 3.7 (absent)",
    );
    ctx.not_reproducible(
        "s3_unloaded_articulation_sensor_error",
        None,
        "a measurement artefact (loose potentiometer link); needs the field records. `afsv discover` can name it (backlash effect) on records that show it",
    );
    ctx.not_reproducible(
        "s3_pressure_discrepancy_path_change",
        None,
        "a model-vs-measurement gap; needs the field pressure records of Fig 3.8 (absent)",
    );
    Ok(())
}

/// Fig 4.7 gain-efficiency correlation over the leakage sweep.
fn check_gain_efficiency(ctx: &mut Ctx) -> Result<(), String> {
    let g = gain_efficiency_correlation(Load::Loaded, TEST_SPEED_M_S, &MeasureSpec::default())
        .map_err(|e| e.to_string())?;
    ctx.compare(
        "s4_gain_efficiency_r2",
        None,
        None,
        g.r_squared,
        format!(
            "k_l0, k_l scaled -30..+30 %, loaded, 50 km/h, 30 deg step: gain {:.4}..{:.4}, efficiency {:.4}..{:.4}",
            g.steering_gain[0],
            g.steering_gain[4],
            g.power_efficiency[0],
            g.power_efficiency[4]
        ),
    );
    ctx.plot(
        "gain_efficiency.svg",
        "Steering power efficiency vs steering gain over the leakage sweep (Fig 4.7)",
        "steering gain (deg/deg)",
        "power efficiency (-)",
        vec![(
            "loaded, 50 km/h".into(),
            g.steering_gain,
            g.power_efficiency,
        )],
    );
    Ok(())
}

/// Ratios of one design's measures to the current design's, in Table 4.3's order.
struct Ratios {
    strut_length: f64,
    yaw_frequency: f64,
    damping_ratio: f64,
    steering_gain: f64,
    overshoot: f64,
    response_rate: f64,
}

impl Ratios {
    fn new(m: &YawMeasures, m0: &YawMeasures) -> Self {
        Self {
            strut_length: m.strut_length_m / m0.strut_length_m,
            yaw_frequency: m.natural_frequency_hz / m0.natural_frequency_hz,
            damping_ratio: m.damping_ratio / m0.damping_ratio,
            steering_gain: m.steering_gain / m0.steering_gain,
            overshoot: m.overshoot_percent / m0.overshoot_percent,
            response_rate: m.response_rate_deg_s / m0.response_rate_deg_s,
        }
    }

    /// Objective F = W . V of Eq 4.8 (V uses the inverses of the ratios where larger is better).
    fn objective(&self, w: &[f64]) -> f64 {
        let v = [
            self.strut_length,
            1.0 / self.yaw_frequency,
            1.0 / self.damping_ratio,
            1.0 / self.steering_gain,
            self.overshoot,
            1.0 / self.response_rate,
        ];
        w.iter().zip(v).map(|(a, b)| a * b).sum()
    }
}

/// Measures of the printed optimum designs of Tables 4.3/4.4 with our model (the design
/// values come from the fixtures; the optimisation itself is not reproduced).
fn check_chapter4(ctx: &mut Ctx) -> Result<(), String> {
    let fx = ctx.fx();
    let w = match ctx.cache.ahp_w.clone() {
        Some(w) => w,
        None => ahp_weights(fx)?.2,
    };
    let spec = MeasureSpec::default();
    let v = VehicleParams::nominal(Load::Loaded);
    let design = |table: &str, key: &str| -> Result<AfsParams, String> {
        let mut a = AfsParams::nominal();
        let g = |n: &str| fx.num(&format!("{table}_opt_{n}"), Some(key));
        a.a0_rad = g("a0")? * DEG;
        a.l1_m = g("l1")?;
        a.l2_m = g("l2")?;
        a.valve_av = g("a_v")? * VALVE_AV_TABLE_UNIT;
        a.bulk_modulus_pa = g("b_eff")? * 1e9;
        Ok(a)
    };
    let measure = |a: &AfsParams, form: EquationForm| -> Result<YawMeasures, String> {
        let mut s = spec;
        s.options.form = form;
        measures_for(&v, a, Some(Load::Loaded), TEST_SPEED_M_S, &s).map_err(|e| e.to_string())
    };
    let mut ratios: BTreeMap<(String, String), (Ratios, Ratios, YawMeasures, YawMeasures)> =
        BTreeMap::new();
    let nom_ec = measure(&design("t4_3", "current")?, EquationForm::EnergyConsistent)?;
    let nom_pf = measure(&design("t4_3", "current")?, EquationForm::PaperEq313)?;
    for table in ["t4_3", "t4_4"] {
        for key in ["ps", "ps_sqp"] {
            let a = design(table, key)?;
            let m_ec = measure(&a, EquationForm::EnergyConsistent)?;
            let m_pf = measure(&a, EquationForm::PaperEq313)?;
            ratios.insert(
                (table.into(), key.into()),
                (
                    Ratios::new(&m_ec, &nom_ec),
                    Ratios::new(&m_pf, &nom_pf),
                    m_ec,
                    m_pf,
                ),
            );
        }
    }
    let get = |t: &str, k: &str| &ratios[&(t.to_string(), k.to_string())];
    type Pick = fn(&Ratios) -> f64;
    let picks: [(&str, Pick, &str); 6] = [
        ("strut_length", |r| r.strut_length, "kinematic: l_0 of Eq 3.7 at the printed design / current"),
        ("yaw_frequency", |r| r.yaw_frequency, "our yaw mode is 5.5 Hz (energy-consistent) and reacts differently to A_0, l_1, l_2; the optimiser's model is not available to compare"),
        ("damping_ratio", |r| r.damping_ratio, "damping from the single-DOF fit of our model"),
        ("steering_gain", |r| r.steering_gain, "step-response gain of our model"),
        ("overshoot", |r| r.overshoot, "step-response overshoot of our model"),
        ("response_rate", |r| r.response_rate, "psi = steady articulation / 0-100 % rise time of our model; it rises at every printed optimum (the faster yaw mode shortens the rise more than the gain falls) while the paper's falls, so the paper's psi was probably defined otherwise (not stated)"),
    ];
    let ctx_note = "loaded, 50 km/h, Table 4.3/4.4 design (A_0, l_1, l_2, a_v, B_eff) evaluated with our model, energy-consistent";
    for table in ["t4_3", "t4_4"] {
        for key in ["ps", "ps_sqp"] {
            let (ec, pf, _, _) = get(table, key);
            for (name, pick, why) in picks {
                ctx.compare(
                    &format!("{table}_norm_{name}"),
                    Some(key),
                    None,
                    pick(ec),
                    format!("{ctx_note}; printed Eq 3.13 gives {:.3}; {why}", pick(pf)),
                );
            }
            ctx.compare(
                &format!("{table}_objective_f"),
                Some(key),
                None,
                ec.objective(&w),
                format!(
                    "F = W.V with our AHP weights and our ratios (off mainly through psi, see the response-rate row); printed Eq 3.13 gives {:.3}",
                    pf.objective(&w)
                ),
            );
        }
    }
    // Text scalars that restate Table 4.3/4.4 numbers.
    let pct = |r: f64| 100.0 * (r - 1.0);
    let (t3s, _, _, _) = get("t4_3", "ps_sqp");
    let (t3p, _, _, _) = get("t4_3", "ps");
    let (t4s, _, _, _) = get("t4_4", "ps_sqp");
    let note = "from the Table 4.3 design with our model (energy-consistent)";
    ctx.compare(
        "s4_opt_strut_length_reduction",
        None,
        None,
        pct(t3s.strut_length),
        "kinematic, Table 4.3 PS/SQP design",
    );
    ctx.compare(
        "s4_opt_yaw_frequency_gain",
        Some("ps"),
        None,
        t3p.yaw_frequency,
        note,
    );
    ctx.compare(
        "s4_opt_yaw_frequency_gain",
        Some("ps_sqp"),
        None,
        t3s.yaw_frequency,
        note,
    );
    ctx.compare(
        "s4_opt_damping_gain",
        Some("ps"),
        None,
        pct(t3p.damping_ratio),
        note,
    );
    ctx.compare(
        "s4_opt_damping_gain",
        Some("ps_sqp"),
        None,
        pct(t3s.damping_ratio),
        note,
    );
    ctx.compare(
        "s4_opt_overshoot_rate_reduction",
        Some("overshoot_min"),
        None,
        pct(t3s.overshoot),
        format!("PS/SQP design; {note}; our overshoot falls more at this design than the paper's"),
    );
    ctx.compare(
        "s4_opt_overshoot_rate_reduction",
        Some("overshoot_max"),
        None,
        pct(t3p.overshoot),
        "PS design; ".to_string() + note,
    );
    ctx.compare(
        "s4_opt_overshoot_rate_reduction",
        Some("rate_min"),
        None,
        pct(t3s.response_rate),
        format!("PS/SQP design; {note}; our psi rises at the optimum, see t4_3_norm_response_rate"),
    );
    ctx.compare(
        "s4_opt_overshoot_rate_reduction",
        Some("rate_max"),
        None,
        pct(t3p.response_rate),
        format!("PS design; {note}; our psi rises at the optimum, see t4_3_norm_response_rate"),
    );
    let rel = |a: f64, b: f64| 100.0 * (a / b - 1.0);
    let note = "Table 4.4 vs Table 4.3 PS/SQP design with our model (energy-consistent)";
    for (key, a, b) in [
        ("strut_length", t4s.strut_length, t3s.strut_length),
        ("yaw_frequency", t4s.yaw_frequency, t3s.yaw_frequency),
        ("steering_gain", t4s.steering_gain, t3s.steering_gain),
        ("overshoot", t4s.overshoot, t3s.overshoot),
        ("response_rate", t4s.response_rate, t3s.response_rate),
        ("damping_ratio", t4s.damping_ratio, t3s.damping_ratio),
    ] {
        ctx.compare(
            "s4_relaxed_vs_bounded_changes",
            Some(key),
            None,
            rel(a, b),
            note,
        );
    }
    ctx.compare(
        "s4_optimal_vs_current_strut_length",
        None,
        None,
        pct(t4s.strut_length),
        "kinematic, Table 4.4 PS/SQP design",
    );
    let (_, _, m_opt, _) = get("t4_4", "ps_sqp");
    let checks = [
        (
            "higher frequency",
            m_opt.natural_frequency_hz > nom_ec.natural_frequency_hz,
        ),
        (
            "lower pulse peak",
            m_opt.pulse_peak_articulation_deg < nom_ec.pulse_peak_articulation_deg,
        ),
        (
            "lower overshoot",
            m_opt.overshoot_percent < nom_ec.overshoot_percent,
        ),
        (
            "lower steering gain",
            m_opt.steering_gain < nom_ec.steering_gain,
        ),
        (
            "comparable response rate (within 15 %)",
            (m_opt.response_rate_deg_s / nom_ec.response_rate_deg_s - 1.0).abs() < 0.15,
        ),
        (
            "no efficiency gain",
            m_opt.power_efficiency <= nom_ec.power_efficiency * 1.02,
        ),
    ];
    let failed: Vec<&str> = checks.iter().filter(|c| !c.1).map(|c| c.0).collect();
    ctx.qualitative(
        "s4_optimal_vs_current_step_response",
        None,
        failed.is_empty(),
        format!(
            "Table 4.4 PS/SQP design vs current, our model: frequency {:.2} vs {:.2} Hz, pulse peak {:.3} vs {:.3} deg, overshoot {:.1} vs {:.1} %, gain {:.4} vs {:.4}, rate {:.1} vs {:.1} deg/s, efficiency {:.4} vs {:.4}{}",
            m_opt.natural_frequency_hz, nom_ec.natural_frequency_hz,
            m_opt.pulse_peak_articulation_deg, nom_ec.pulse_peak_articulation_deg,
            m_opt.overshoot_percent, nom_ec.overshoot_percent,
            m_opt.steering_gain, nom_ec.steering_gain,
            m_opt.response_rate_deg_s, nom_ec.response_rate_deg_s,
            m_opt.power_efficiency, nom_ec.power_efficiency,
            if failed.is_empty() { String::new() } else { format!("; not as reported: {}", failed.join(", ")) }
        ),
    );
    Ok(())
}

/// Fixtures that need models we do not have, with the reason.
fn list_not_reproducible(ctx: &mut Ctx) -> Result<(), String> {
    let ch2 = "needs the chapter-2 TruckSim model of the 50 t rigid truck (Tables 2.1-2.3) driven over synthesized terrain; we have the terrain synthesis (terrain-psd) and the DRT/LTR measures (perf-measures) but not that vehicle";
    let ch6 = "needs the chapter-6 3-D multibody AFSV (12 bodies, Table 6.1) with tire enveloping, ride and roll dynamics; not implemented yet";
    let ch6_hps = "needs the chapter-6 3-D vehicle with the front-axle HPS (hps-emulsion has the strut, not the vehicle); not implemented yet";
    let ch6_opt = "needs the chapter-6 HPS optimisation on the 3-D vehicle; not implemented";
    let ch4_opt = "needs the chapter-4 design optimisation; not implemented";
    let fx = ctx.fx();
    // Table 6.5: the nominal column is the nominal HPS vehicle, the optimal one the optimum.
    for id in [
        "t6_5_awz",
        "t6_5_sp_drt",
        "t6_5_omega_z",
        "t6_5_d_s",
        "t6_5_objective_f",
    ] {
        ctx.not_reproducible(id, Some("nominal"), ch6_hps);
        ctx.not_reproducible(id, Some("optimal"), ch6_opt);
    }
    let ids: Vec<(String, &str)> = fx
        .by_id
        .values()
        .filter(|f| f.kind == "result" || f.kind == "qualitative")
        .filter_map(|f| {
            let id = f.id.as_str();
            let reason = if id.starts_with("s2_") {
                ch2
            } else if id.starts_with("s6_hps_opt") || id.starts_with("t6_5_") {
                ch6_opt
            } else if id.starts_with("t6_4_") || id.starts_with("s6_hps_") {
                ch6_hps
            } else if id.starts_with("s6_") {
                ch6
            } else if id.starts_with("s4_") || id.starts_with("t4_") {
                ch4_opt
            } else {
                return None;
            };
            Some((f.id.clone(), reason))
        })
        .collect();
    for (id, reason) in ids {
        // Fixtures (or keys) computed by another check stay as they are.
        if !ctx.results.iter().any(|r| r.id == id) {
            ctx.not_reproducible(&id, None, reason);
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn relative_tolerance_inside_and_outside() {
        let t = Tolerance::from_fixture(&json!({"relative": 0.05}), None).unwrap();
        assert!(t.within(2.81, 2.9));
        assert!(!t.within(2.81, 3.0));
        assert!((t.error(2.0, 2.1) - 0.05).abs() < 1e-12);
        assert!(!t.within(2.81, f64::NAN));
    }

    #[test]
    fn absolute_zero_tolerance_allows_round_off_only() {
        let t = Tolerance::from_fixture(&json!({"absolute": 0}), None).unwrap();
        assert!(t.within(1.0 / 3.0, 0.333_333_333_333_333_3));
        assert!(!t.within(0.3333, 1.0 / 3.0));
    }

    #[test]
    fn bounds() {
        let lo = Tolerance::from_fixture(&json!({"lower_bound": 0.99}), None).unwrap();
        assert!(lo.within(0.99, 0.995));
        assert!(!lo.within(0.99, 0.98));
        let hi = Tolerance::from_fixture(&json!({"upper_bound": 4}), None).unwrap();
        assert!(hi.within(4.0, 3.9));
        assert!(!hi.within(4.0, 4.1));
    }

    #[test]
    fn per_key_and_nested_tolerances() {
        let tol = json!({"absolute": {"loaded": 0.5, "unloaded": 0.005}});
        assert_eq!(
            Tolerance::from_fixture(&tol, Some("unloaded")),
            Some(Tolerance::Absolute(0.005))
        );
        let tol = json!({"drt": {"absolute": 5}, "ratio": {"relative": 0.3}});
        assert_eq!(
            Tolerance::from_fixture(&tol, Some("ratio")),
            Some(Tolerance::Relative(0.3))
        );
        let tol = json!({"absolute": [[0.005, 0.5], [0.005, 0.5]]});
        assert_eq!(
            Tolerance::from_fixture(&tol, Some("1.1")),
            Some(Tolerance::Absolute(0.5))
        );
        // A scalar tolerance applies to every key of a matrix.
        assert_eq!(
            Tolerance::from_fixture(&json!({"absolute": 0.006}), Some("3.1")),
            Some(Tolerance::Absolute(0.006))
        );
        assert_eq!(Tolerance::from_fixture(&Value::Null, None), None);
        assert_eq!(
            Tolerance::from_fixture(&json!({"absolute": {"a": 1}}), Some("b")),
            None
        );
    }

    fn fixture(status: &str, keys: &[&str]) -> Fixture {
        Fixture {
            file: "x.json".into(),
            id: "q".into(),
            kind: "result".into(),
            description: String::new(),
            reference: String::new(),
            value: json!({"a": 1.0, "b": [2.0, 3.0]}),
            unit: "1".into(),
            tolerance: json!({"relative": 0.1}),
            status: status.into(),
            reproduced_keys: keys.iter().map(|k| k.to_string()).collect(),
        }
    }

    #[test]
    fn guard_rule_follows_status_and_keys() {
        assert!(fixture("reproduced", &[]).guards(Some("a")));
        assert!(fixture("reproduced (one orifice, 2 Hz)", &[]).guards(None));
        assert!(!fixture("pending", &[]).guards(None));
        assert!(!fixture("not modelled", &[]).guards(None));
        let p = fixture("partially reproduced", &["a"]);
        assert!(p.guards(Some("a")));
        assert!(!p.guards(Some("b.0")));
        assert_eq!(p.number(Some("b.1")), Some(3.0));
    }

    #[test]
    fn regression_only_for_guarded_rows_out_of_tolerance() {
        let mut fx = Fixtures::default();
        let mut f = fixture("partially reproduced", &["a"]);
        f.value = json!({"a": 1.0, "c": 1.0});
        fx.by_id.insert("q".into(), f);
        let mut ctx = Ctx {
            fixtures: &fx,
            results: Vec::new(),
            plots: Vec::new(),
            cache: Cache::default(),
        };
        ctx.compare("q", Some("a"), None, 1.05, "");
        ctx.compare("q", Some("c"), None, 2.0, "");
        assert_eq!(ctx.results[0].status, Status::Reproduced);
        assert!(!ctx.results[0].regressed());
        assert_eq!(ctx.results[1].status, Status::Differs);
        assert!(!ctx.results[1].regressed(), "unguarded key may differ");
        ctx.compare("q", Some("a"), None, 1.5, "");
        assert!(ctx.results[2].regressed());
    }

    #[test]
    fn hps_lab_schema_is_read_as_is() {
        let q = json!({"id": "p", "description": "d", "value": 0.5, "unit": "MPa", "ref": "5.4.2",
                       "tolerance": 0.1, "tolerance_kind": "absolute MPa", "status": "reproduced (x)"});
        let f = parse_hps_lab("hps_lab.json", &q).unwrap();
        assert_eq!(f.kind, "result");
        assert_eq!(
            Tolerance::from_fixture(&f.tolerance, None),
            Some(Tolerance::Absolute(0.1))
        );
        assert!(f.guards(None));
        let q = json!({"id": "k", "description": "d", "value": 50, "unit": "s/m", "ref": "5.3.2", "tolerance": null});
        assert_eq!(parse_hps_lab("hps_lab.json", &q).unwrap().kind, "parameter");
    }

    #[test]
    fn number_format() {
        assert_eq!(fmt_num(2.81), "2.81");
        assert_eq!(fmt_num(1.8e-10), "1.800e-10");
        assert_eq!(fmt_num(-7.5), "-7.5");
        assert_eq!(fmt_num(21000.0), "21000");
    }
}
