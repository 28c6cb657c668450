//! The validation report: rows, plots, the text / markdown tables and the written outputs.

use super::tolerance::{Status, Tolerance};
use super::ValidateError;
use serde::Serialize;
use std::path::Path;

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
        self.guarded && !self.status.agrees()
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
    /// Wall time of [`super::run`] (s).
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

    /// One-line summary: model-computed rows (reproduced, differ, not reproducible from
    /// the paper's data) apart from the echoes (input, by-construction), so the reproduced
    /// count means model results only.
    pub fn summary_line(&self) -> String {
        let (rep, dif) = (self.count(Status::Reproduced), self.count(Status::Differs));
        let open = self.count(Status::NotReproducibleFromPaperData);
        format!(
            "{} rows: {} model-computed ({} reproduced, {} differ, {} not reproducible from the paper's data), {} echoes ({} input, {} by-construction), {} not reproducible; {} regressions; {:.1} s",
            self.results.len(),
            rep + dif + open,
            rep,
            dif,
            open,
            self.count(Status::Input) + self.count(Status::ByConstruction),
            self.count(Status::Input),
            self.count(Status::ByConstruction),
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
    afsv_records::atomic::write(&md, report.markdown())
        .map_err(|e| err(format!("{}: {e}", md.display())))?;
    let js = out_dir.join("report.json");
    let text = serde_json::to_string_pretty(report).map_err(|e| err(e.to_string()))?;
    afsv_records::atomic::write(&js, text).map_err(|e| err(format!("{}: {e}", js.display())))?;
    Ok(())
}
#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn number_format() {
        assert_eq!(fmt_num(2.81), "2.81");
        assert_eq!(fmt_num(1.8e-10), "1.800e-10");
        assert_eq!(fmt_num(-7.5), "-7.5");
        assert_eq!(fmt_num(21000.0), "21000");
    }
}
