//! The performance measures `afsv measures` reads from a record (`perf-measures` on its
//! columns): the whole-body vibration of a seat record with its axes, columns and
//! weightings as named ([`wbv`]), the single-DOF free-decay fit of one column
//! ([`decay`]) and the step metrics of an output column to a step in an input column
//! ([`step`]). Each returns the JSON the command prints; errors name the file.

use crate::report::weighting::{wbv_inputs, wbv_report};
use afsv_records::Record;
use perf_measures::decay::decay_window;
use perf_measures::iso2631::{assess_whole_body, Axis, FilterMethod, KFactors, Weighting};
use perf_measures::signal::sample_rate;
use perf_measures::{fit_free_decay, step_amplitude, step_metrics_with, step_time};
use perf_measures::{MeasureError, StepOptions};
use serde_json::{json, Value};
use std::path::Path;

/// Index of axis `x`, `y` or `z` in `option`'s value `spec`.
fn axis_index(option: &str, spec: &str, axis: &str) -> Result<usize, String> {
    match axis.trim().to_ascii_lowercase().as_str() {
        "x" => Ok(0),
        "y" => Ok(1),
        "z" => Ok(2),
        other => Err(format!(
            "{option} `{spec}`: unknown axis `{other}` (x, y or z)"
        )),
    }
}

/// The weighting of each axis: the seat-pan health weightings (x, y W_d, z W_k) with the
/// `AXIS=W` of `specs` replacing theirs.
pub fn axis_weightings(specs: &[String]) -> Result<[Weighting; 3], String> {
    let mut w = [Axis::X, Axis::Y, Axis::Z].map(Axis::health_weighting);
    for s in specs {
        let (axis, name) = s
            .split_once('=')
            .ok_or_else(|| format!("--weighting `{s}`: expected AXIS=W, e.g. z=wk"))?;
        w[axis_index("--weighting", s, axis)?] = name
            .parse()
            .map_err(|e| format!("--weighting `{s}`: {e}"))?;
    }
    Ok(w)
}

/// The column of each axis and whether `specs` (`AXIS=COLUMN`, in m/s², `_m_s2`) named it
/// (then the record must have it): `ax_m_s2`, `ay_m_s2`, `az_m_s2` by default.
pub fn axis_columns(specs: &[String]) -> Result<[(String, bool); 3], String> {
    let mut c = ["ax_m_s2", "ay_m_s2", "az_m_s2"].map(|n| (n.to_string(), false));
    for s in specs {
        let (axis, column) = s.split_once('=').ok_or_else(|| {
            format!("--channel `{s}`: expected AXIS=COLUMN, e.g. y=lateral_accel_front_m_s2")
        })?;
        let column = column.trim();
        if !column.ends_with("_m_s2") {
            return Err(format!(
                "--channel `{s}`: column `{column}` must be in m/s^2 (name ending in _m_s2)"
            ));
        }
        c[axis_index("--channel", s, axis)?] = (column.to_string(), true);
    }
    Ok(c)
}

/// The whole-body vibration of the record `rec` (read from `path`) for `hours` of daily
/// exposure: its axes' columns (`channels`) and weightings (`weightings`) as named, the
/// factors `k` (k_x, k_y, k_z of Eq 1.1), weighted by `method` (`fft` or `iir`).
pub fn wbv(
    (rec, path): (&Record, &Path),
    (weightings, channels): (&[String], &[String]),
    k: &[f64],
    method: &str,
    hours: f64,
) -> Result<Value, String> {
    let t = rec.require("time_s", path).map_err(|e| e.to_string())?;
    let fs = sample_rate(t).map_err(|e| format!("{}: {e}", path.display()))?;
    let w = axis_weightings(weightings)?;
    let [x, y, z] = k[..] else {
        return Err(format!(
            "--k: expected 3 values k_x,k_y,k_z, got {}",
            k.len()
        ));
    };
    let method = if method == "iir" {
        FilterMethod::Iir
    } else {
        FilterMethod::Fft
    };
    let columns = axis_columns(channels)?;
    let (inputs, used) = wbv_inputs(rec, path, &columns, w)?;
    let r = assess_whole_body(&inputs, fs, hours, KFactors { x, y, z }, method)
        .map_err(|e| format!("{}: {e}", path.display()))?;
    wbv_report(&r, used, rec).map_err(|e| e.to_string())
}

/// The free-decay fit of `column` of `rec` (read from `path`) over `[start_s, end_s]`
/// (default: from the largest deviation from the final value to the end), and the fit's
/// problems (`accepted`: printed despite them).
pub fn decay(
    (rec, path): (&Record, &Path),
    column: &str,
    (start_s, end_s): (Option<f64>, Option<f64>),
    accepted: bool,
) -> Result<(Value, Vec<String>), String> {
    let t = rec.require("time_s", path).map_err(|e| e.to_string())?;
    let y = rec.require(column, path).map_err(|e| e.to_string())?;
    if t.is_empty() {
        return Err(format!("{}: the record is empty", path.display()));
    }
    let w = decay_window(t, y, start_s, end_s).map_err(|e| format!("{}: {e}", path.display()))?;
    let (tw, yw) = (&t[w.clone()], &y[w]);
    let fit = fit_free_decay(tw, yw).map_err(|e| format!("{}: {e}", path.display()))?;
    let problems = fit.problems();
    let v = json!({
        "column": column,
        "start_s": tw[0],
        "end_s": tw[tw.len() - 1],
        "samples": tw.len(),
        "note": "amplitude, offset, rmse and noise_rms are in the column's unit",
        "fit": fit,
        "problems": problems,
        "accepted_despite_problems": accepted && !problems.is_empty(),
    });
    Ok((v, problems))
}

/// The step metrics of `output` to a step in `input` of `rec` (read from `path`): the
/// step's time and amplitude as given, else found in the input (its mean over the final
/// `settle_fraction` less its initial value; the first departure by 2 % of it).
pub fn step(
    (rec, path): (&Record, &Path),
    (input, output): (&str, &str),
    (t_step, amplitude): (Option<f64>, Option<f64>),
    settle_fraction: f64,
) -> Result<Value, String> {
    let column = |name: &str| rec.require(name, path).map_err(|e| e.to_string());
    let (t, u, y) = (column("time_s")?, column(input)?, column(output)?);
    let amplitude = match amplitude {
        Some(v) => v,
        None => step_amplitude(u, settle_fraction).map_err(|e| match e {
            MeasureError::NotFound(why) => format!(
                "{}: the input `{input}` {why}; give --amplitude",
                path.display()
            ),
            other => format!("{}: `{input}`: {other}", path.display()),
        })?,
    };
    let t_step = match t_step {
        Some(v) => v,
        None => step_time(t, u, amplitude)
            .map_err(|e| format!("{}: {e}; give --t-step", path.display()))?,
    };
    let opts = StepOptions { settle_fraction };
    let m = step_metrics_with(t, y, t_step, amplitude, &opts)
        .map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(json!({
        "input": input,
        "output": output,
        "t_step_s": t_step,
        "input_amplitude": amplitude,
        "metrics": m,
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn record(columns: &[(&str, Vec<f64>)]) -> Record {
        let mut r = Record::new();
        for (name, v) in columns {
            r.push_column(name, v.clone()).unwrap();
        }
        r
    }

    #[test]
    fn axes_are_named_by_letter() {
        let w = axis_weightings(&["x=wk".into()]).unwrap();
        assert_eq!(w[0], Weighting::Wk);
        assert!(axis_weightings(&["q=wk".into()])
            .unwrap_err()
            .contains("unknown axis"));
        let c = axis_columns(&["Y=lat_m_s2".into()]).unwrap();
        assert_eq!(c[1], ("lat_m_s2".to_string(), true));
        assert!(axis_columns(&["y=lat_g".into()]).is_err());
    }

    #[test]
    fn a_unit_step_to_a_first_order_lag() {
        let t: Vec<f64> = (0..2001).map(|i| i as f64 * 0.01).collect();
        let u: Vec<f64> = t
            .iter()
            .map(|&t| if t >= 1.0 { 2.0 } else { 0.0 })
            .collect();
        let y: Vec<f64> = t
            .iter()
            .map(|&t| {
                if t >= 1.0 {
                    4.0 * (1.0 - (-(t - 1.0) / 0.5).exp())
                } else {
                    0.0
                }
            })
            .collect();
        let rec = record(&[("time_s", t), ("u_deg", u), ("y_deg", y)]);
        let v = step(
            (&rec, Path::new("s.csv")),
            ("u_deg", "y_deg"),
            (None, None),
            0.1,
        )
        .unwrap();
        assert_eq!(v["input_amplitude"], 2.0);
        assert!((v["t_step_s"].as_f64().unwrap() - 1.0).abs() < 0.011);
        assert!(step(
            (&rec, Path::new("s.csv")),
            ("u_deg", "nope"),
            (None, None),
            0.1
        )
        .is_err());
    }

    #[test]
    fn a_damped_oscillation_decays_at_its_frequency() {
        let (wn, zeta): (f64, f64) = (2.0 * std::f64::consts::PI, 0.1);
        let wd = wn * (1.0 - zeta * zeta).sqrt();
        let t: Vec<f64> = (0..1000).map(|i| i as f64 * 0.005).collect();
        let y: Vec<f64> = t
            .iter()
            .map(|&t| (-zeta * wn * t).exp() * (wd * t).cos())
            .collect();
        let rec = record(&[("time_s", t), ("a_deg", y)]);
        let (v, problems) =
            decay((&rec, Path::new("d.csv")), "a_deg", (None, None), false).unwrap();
        assert!(problems.is_empty(), "{problems:?}");
        let found = v["fit"]["damping_ratio"].as_f64().unwrap();
        assert!((found - zeta).abs() < 0.01, "{found}");
    }
}
