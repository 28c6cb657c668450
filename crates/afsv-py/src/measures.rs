//! Performance measures on arrays (crate `perf-measures`), on the library calls of
//! `afsv measures wbv|decay|step`: ISO 2631-1 whole-body vibration (weightings W_k, W_d,
//! ..., Eq 1.1), the lateral load transfer ratio (Eq 2.11) with the smooth-road DRT and the
//! sustained period / SP-DRT (section 2.3), the free-decay fit and step metrics.

use crate::{f64s, py_err, to_bytes, to_json, value_err};
use perf_measures::decay::decay_window;
use perf_measures::iso2631::{
    assess_whole_body, Axis, AxisInput, FilterMethod, KFactors, Weighting,
};
use perf_measures::roll::SustainedPeriodParams;
use perf_measures::signal::sample_rate;
use perf_measures::{
    fit_free_decay, ltr_two_axle, smooth_road_drt, step_amplitude, step_metrics_with, step_time,
    sustained_period, MeasureError, StepOptions,
};
use pyo3::prelude::*;
use pyo3::types::PyByteArray;
use serde_json::json;

/// ISO 2631-1 whole-body vibration of seat accelerations `ax`, `ay`, `az` (any may be
/// absent) sampled at the times `t`: per-axis a_w, crest factor, MTVV, VDV, a_v (Eq 1.1),
/// A(8) and the Annex B caution zone, as JSON.
#[pyfunction]
#[pyo3(signature = (t, ax, ay, az, hours, weightings, k, method))]
#[allow(clippy::too_many_arguments)]
fn wbv(
    py: Python<'_>,
    t: &[u8],
    ax: Option<&[u8]>,
    ay: Option<&[u8]>,
    az: Option<&[u8]>,
    hours: f64,
    weightings: (String, String, String),
    k: (f64, f64, f64),
    method: &str,
) -> PyResult<String> {
    let t = f64s("t", t)?;
    let fs = sample_rate(&t).map_err(|e| value_err(format!("t: {e}")))?;
    let method = match method {
        "fft" => FilterMethod::Fft,
        "iir" => FilterMethod::Iir,
        other => return Err(value_err(format!("method `{other}`: expected fft or iir"))),
    };
    let w = [&weightings.0, &weightings.1, &weightings.2];
    let cols = [ax, ay, az];
    let mut data = Vec::new();
    for (i, (axis, name)) in [(Axis::X, "ax"), (Axis::Y, "ay"), (Axis::Z, "az")]
        .into_iter()
        .enumerate()
    {
        if let Some(bytes) = cols[i] {
            let weighting: Weighting = w[i]
                .parse()
                .map_err(|e| value_err(format!("weighting of {name}: {e}")))?;
            data.push((axis, weighting, f64s(name, bytes)?));
        }
    }
    if data.is_empty() {
        return Err(value_err("no acceleration given (ax, ay or az)"));
    }
    let inputs: Vec<AxisInput<'_>> = data
        .iter()
        .map(|(axis, weighting, accel)| AxisInput {
            axis: *axis,
            weighting: *weighting,
            accel,
        })
        .collect();
    let k = KFactors {
        x: k.0,
        y: k.1,
        z: k.2,
    };
    let r = py
        .detach(|| assess_whole_body(&inputs, fs, hours, k, method))
        .map_err(|e| py_err(py, &e))?;
    Ok(to_json(&r)?.to_string())
}

/// LTR per sample of a two-axle vehicle (Eq 2.11) from the four tire normal forces (N).
#[pyfunction]
fn ltr<'py>(
    py: Python<'py>,
    fz_lf: &[u8],
    fz_rf: &[u8],
    fz_lr: &[u8],
    fz_rr: &[u8],
) -> PyResult<Bound<'py, PyByteArray>> {
    let v = ltr_two_axle(
        &f64s("fz_lf", fz_lf)?,
        &f64s("fz_rf", fz_rf)?,
        &f64s("fz_lr", fz_lr)?,
        &f64s("fz_rr", fz_rr)?,
    )
    .map_err(|e| py_err(py, &e))?;
    to_bytes(py, &v)
}

/// The smooth-road DRT (first LTR >= `threshold`) and the sustained period with its SP-DRT
/// (section 2.3) of an LTR history, as JSON; a measure not found is `null` with a reason.
#[pyfunction]
#[pyo3(signature = (t, ltr, lateral_accel, drt_threshold, sp_threshold, sp_max_dip, sp_min_duration))]
#[allow(clippy::too_many_arguments)]
fn roll_measures(
    py: Python<'_>,
    t: &[u8],
    ltr: &[u8],
    lateral_accel: &[u8],
    drt_threshold: f64,
    sp_threshold: f64,
    sp_max_dip: f64,
    sp_min_duration: f64,
) -> PyResult<String> {
    let (t, l, a) = (
        f64s("t", t)?,
        f64s("ltr", ltr)?,
        f64s("lateral_accel", lateral_accel)?,
    );
    let sp = SustainedPeriodParams {
        threshold: sp_threshold,
        max_dip_s: sp_max_dip,
        min_duration_s: sp_min_duration,
        ..SustainedPeriodParams::default()
    };
    let found = |r: Result<serde_json::Value, MeasureError>| -> PyResult<(serde_json::Value, Option<String>)> {
        match r {
            Ok(v) => Ok((v, None)),
            Err(MeasureError::NotFound(why)) => Ok((serde_json::Value::Null, Some(why))),
            Err(e) => Err(py_err(py, &e)),
        }
    };
    let (drt, drt_reason) = found(
        smooth_road_drt(&t, &l, &a, drt_threshold)
            .map(|p| serde_json::to_value(p).unwrap_or_default()),
    )?;
    let (period, period_reason) = found(
        sustained_period(&t, &l, &a, &sp).map(|p| serde_json::to_value(p).unwrap_or_default()),
    )?;
    Ok(json!({
        "drt": drt, "drt_reason": drt_reason,
        "sustained_period": period, "sustained_period_reason": period_reason,
        "rule": to_json(&sp)?,
    })
    .to_string())
}

/// Free-decay fit y = c + A exp(-zeta wn t) cos(wd t + phi) over the window of
/// `afsv measures decay` (from `start_s`, or the largest deviation from the final value, to
/// `end_s`), as JSON.
#[pyfunction]
#[pyo3(signature = (t, y, start_s, end_s))]
fn decay(
    py: Python<'_>,
    t: &[u8],
    y: &[u8],
    start_s: Option<f64>,
    end_s: Option<f64>,
) -> PyResult<String> {
    let (t, y) = (f64s("t", t)?, f64s("y", y)?);
    if t.is_empty() {
        return Err(value_err("the record is empty"));
    }
    let w = decay_window(&t, &y, start_s, end_s).map_err(|e| py_err(py, &e))?;
    let (tw, yw) = (&t[w.clone()], &y[w]);
    let fit = py
        .detach(|| fit_free_decay(tw, yw))
        .map_err(|e| py_err(py, &e))?;
    Ok(json!({
        "start_s": tw[0],
        "end_s": tw[tw.len() - 1],
        "samples": tw.len(),
        "fit": to_json(&fit)?,
    })
    .to_string())
}

/// Step-response metrics of `y` to a step in `u` (`afsv measures step`): steady gain, 0-100 %
/// rise time, overshoot, peak, as JSON.
#[pyfunction]
#[pyo3(signature = (t, u, y, t_step, amplitude, settle_fraction))]
fn step(
    py: Python<'_>,
    t: &[u8],
    u: &[u8],
    y: &[u8],
    t_step: Option<f64>,
    amplitude: Option<f64>,
    settle_fraction: f64,
) -> PyResult<String> {
    let (t, u, y) = (f64s("t", t)?, f64s("u", u)?, f64s("y", y)?);
    let amplitude = match amplitude {
        Some(v) => v,
        None => step_amplitude(&u, settle_fraction).map_err(|e| match e {
            MeasureError::NotFound(why) => value_err(format!("the input {why}; give amplitude")),
            other => py_err(py, &other),
        })?,
    };
    let t_step = match t_step {
        Some(v) => v,
        None => step_time(&t, &u, amplitude).map_err(|e| value_err(format!("{e}; give t_step")))?,
    };
    let opts = StepOptions { settle_fraction };
    let m = step_metrics_with(&t, &y, t_step, amplitude, &opts).map_err(|e| py_err(py, &e))?;
    Ok(json!({
        "t_step_s": t_step,
        "input_amplitude": amplitude,
        "metrics": to_json(&m)?,
    })
    .to_string())
}

/// Register the measure functions.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(wbv, m)?)?;
    m.add_function(wrap_pyfunction!(ltr, m)?)?;
    m.add_function(wrap_pyfunction!(roll_measures, m)?)?;
    m.add_function(wrap_pyfunction!(decay, m)?)?;
    m.add_function(wrap_pyfunction!(step, m)?)?;
    Ok(())
}
