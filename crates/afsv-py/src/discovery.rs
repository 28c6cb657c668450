//! Records (crate `afsv-records`: CSV + JSON sidecar, sign convention afsv-v1) read into
//! Python, and model-discrepancy discovery (crate `afsv-discovery`, docs/discovery.md) on
//! in-memory records, on the library calls of `afsv discover`: calibrate the paper's model
//! (the hydro-pneumatic strut of Chapter 5, or the yaw-plane vehicle of Chapter 3) on the
//! training records, try the catalogue of missing effects, name the significant ones, and
//! measure the gap on the holdout records.

use crate::{f64s, py_err, record_out, to_json, value_err, Columns};
use afsv_discovery::hps::HpsStrutModel;
use afsv_discovery::yaw::YawPlaneModel;
use afsv_discovery::{discover, DiscoveryModel, DiscoveryOptions, Progress};
use afsv_records::{ReadOptions, Record};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyTuple};
use serde_json::json;

/// A record from Python: `(name, [(channel, float64 bytes)], meta_json)`.
type PyRecord = (String, Vec<(String, Py<PyBytes>)>, String);

/// A record file read as `afsv-records` reads it (conventions honoured, units converted):
/// its columns and its sidecar metadata.
#[pyfunction]
#[pyo3(signature = (path, assume_convention))]
fn read_record<'py>(
    py: Python<'py>,
    path: &str,
    assume_convention: Option<String>,
) -> PyResult<Bound<'py, PyTuple>> {
    let opts = ReadOptions { assume_convention };
    opts.validate().map_err(|e| value_err(e.to_string()))?;
    let rec = Record::read_with(std::path::Path::new(path), &opts).map_err(|e| py_err(py, &e))?;
    let cols: Columns = rec
        .names()
        .iter()
        .map(|n| (n.clone(), rec.column(n).unwrap_or_default().to_vec()))
        .collect();
    record_out(py, &cols, &rec.meta)
}

/// The in-memory `afsv_records::Record` of a Python record, with its name.
fn to_record(py: Python<'_>, r: PyRecord) -> PyResult<(Record, String)> {
    let (name, columns, meta) = r;
    let mut rec = Record::new();
    for (channel, bytes) in columns {
        let values = f64s(&channel, bytes.as_bytes(py))?;
        rec.push_column(&channel, values)
            .map_err(|e| value_err(format!("record `{name}`: {e}")))?;
    }
    rec.meta = serde_json::from_str(&meta)
        .map_err(|e| value_err(format!("record `{name}`: metadata: {e}")))?;
    Ok((rec, name))
}

/// Discovery reports no progress to Python.
struct Quiet;

impl Progress for Quiet {
    fn fit_done(&self, _what: &str) {}
}

/// Run discovery with `model` on the records: the numbers `afsv discover` prints, as JSON.
fn run<M: DiscoveryModel>(
    py: Python<'_>,
    model: &M,
    train: Vec<PyRecord>,
    holdout: Vec<PyRecord>,
    opts: &DiscoveryOptions,
) -> PyResult<String> {
    let split = |v: Vec<PyRecord>| -> PyResult<(Vec<Record>, Vec<String>)> {
        let (mut recs, mut names) = (Vec::new(), Vec::new());
        for r in v {
            let (rec, name) = to_record(py, r)?;
            recs.push(rec);
            names.push(name);
        }
        Ok((recs, names))
    };
    let (train, train_names) = split(train)?;
    let (hold, hold_names) = split(holdout)?;
    let d = py
        .detach(|| {
            discover(
                model,
                &train,
                &hold,
                &train_names,
                &hold_names,
                opts,
                &Quiet,
            )
        })
        .map_err(|e| py_err(py, &e))?;
    Ok(json!({
        "model": d.model,
        "summary": afsv_discovery::report::headline(&d),
        "outcome": to_json(&d.outcome)?,
        "exit_code": d.outcome.exit_code(),
        "excess_over_noise": d.excess_over_noise,
        "named": d.named,
        "effect_params": to_json(&d.final_model.effect_params)?,
        "gap_shrink": d.gap_shrink,
        "best_unnamed": to_json(&d.best_unnamed_shrink)?,
        "holdout_mse": {"calibrated": d.calibrated.holdout_mse, "final": d.final_model.holdout_mse, "noise": d.holdout_noise_mse},
        "channel_errors": d.channel_errors.iter().map(|(tb, ta, hb, ha)| json!({
            "channel": tb.channel, "train_before": tb.nrmse, "train_after": ta.nrmse,
            "holdout_before": hb.nrmse, "holdout_after": ha.nrmse})).collect::<Vec<_>>(),
    })
    .to_string())
}

/// Find which physical effect the paper's model (`hps-strut` or `yaw-plane`, nominal
/// parameters) lacks from measured records: calibrate on `train`, try the catalogue
/// (`effects`: only these), name at most `max_effects`, report the gap shrink on `holdout`.
#[pyfunction]
#[pyo3(signature = (model, train, holdout, effects, max_effects))]
fn discover_effects(
    py: Python<'_>,
    model: &str,
    train: Vec<PyRecord>,
    holdout: Vec<PyRecord>,
    effects: Option<Vec<String>>,
    max_effects: usize,
) -> PyResult<String> {
    let opts = DiscoveryOptions {
        candidates: effects,
        max_effects,
        ..DiscoveryOptions::default()
    };
    match model {
        "hps-strut" => run(py, &HpsStrutModel::nominal(), train, holdout, &opts),
        "yaw-plane" => run(py, &YawPlaneModel::nominal(), train, holdout, &opts),
        other => Err(value_err(format!(
            "model `{other}`: expected hps-strut or yaw-plane"
        ))),
    }
}

/// Register the record and discovery functions.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(read_record, m)?)?;
    m.add_function(wrap_pyfunction!(discover_effects, m)?)?;
    Ok(())
}
