//! Validation against the dissertation's reported numbers (`cargo xtask validate`).
//!
//! [`load_fixtures`] reads every `fixtures/reported/*.json` file (the common schema of
//! `fixtures/reported/README.md` and the simpler one of `hps_lab.json`). [`run`] then executes
//! a registry of checks ([`CHECKS`]): each maps a fixture id (and, for multi-valued entries, a
//! key) to a computation with our models and the design layer (`afsv_design`), converts the
//! simulated number to the fixture's printed unit and compares it with the fixture's
//! tolerance; a number that only echoes an input or holds by construction is compared with
//! [`Ctx::echo`] and gets [`Status::Input`] or [`Status::ByConstruction`] instead of
//! [`Status::Reproduced`]. Every `result` and
//! `qualitative` fixture appears in the report, either computed or listed as
//! [`Status::NotReproducible`] with the reason; [`run`] adds a row for any such fixture no
//! check covers, so nothing is hidden.
//!
//! Regression rule: a fixture whose `status` is `"reproduced"` (or, for a partly reproduced
//! multi-valued fixture, `"partially reproduced"` plus the list `reproduced_keys`) guards its
//! rows; [`Report::regressions`] lists guarded rows that no longer agree (within tolerance,
//! whether reproduced or an echo).
//! `docs/validation.md` describes the method and the current results.

mod checks;
mod ctx;
mod fixtures;
mod report;
mod tolerance;

pub use checks::CHECKS;
pub use ctx::Ctx;
pub use fixtures::{load_fixtures, Fixture, Fixtures};
pub use report::{fmt_num, write_outputs, CheckResult, PlotData, Report};
pub use tolerance::{Echo, Status, Tolerance};

use std::path::{Path, PathBuf};
use std::time::Instant;

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

/// The checks that run the chapter-6 design studies on the 3-D vehicle (Table 6.4, the GA of
/// Table 6.5 and the D4 sweep): about two minutes of the validation on two cores.
pub const STUDY_CHECKS: &[&str] = &["table_6_4_hps_sensitivity", "table_6_5_hps_optimum"];

/// Run every check against the fixtures in `fixture_dir`.
pub fn run(fixture_dir: &Path) -> Result<Report, ValidateError> {
    run_skipping(fixture_dir, &[])
}

/// Run every check but those named in `skip` (names of [`CHECKS`]); the fixtures a skipped
/// check covers are listed as not reproduced, with the reason.
pub fn run_skipping(fixture_dir: &Path, skip: &[&str]) -> Result<Report, ValidateError> {
    let t0 = Instant::now();
    let fixtures = load_fixtures(fixture_dir)?;
    let mut ctx = Ctx::new(&fixtures);
    let mut failed = Vec::new();
    for (name, ids, check) in CHECKS {
        if skip.contains(name) {
            for id in *ids {
                // `id[key]` names one keyed row (the others of that id come from other checks).
                let (id, key) = match id.split_once('[') {
                    Some((id, key)) => (id, Some(key.trim_end_matches(']'))),
                    None => (*id, None),
                };
                ctx.not_reproducible(id, key, format!("check `{name}` skipped (--quick)"));
            }
            continue;
        }
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
