//! The report of `afsv measures weighting`: an ISO 2631-1 frequency weighting (Annex A
//! analog transfer function) at given frequencies, with its bilinear IIR realisation at a
//! sampling rate when one is given; and the axes `afsv measures wbv` reads from a record,
//! with its report.

use afsv_records::Record;
use perf_measures::iso2631::{Axis, AxisInput, IirWeighting, WbvAssessment, Weighting};
use serde_json::{json, Value};
use std::path::Path;

/// Magnitude (factor and dB) and phase of `weighting` at each of `freqs` (Hz, positive),
/// and with `iir` (its sampling rate `fs`, Hz) the IIR magnitude below its Nyquist
/// frequency; the weighting's stage parameters.
pub fn weighting_report(
    weighting: Weighting,
    freqs: &[f64],
    iir: Option<&IirWeighting>,
    fs: Option<f64>,
) -> Value {
    let mut rows = Vec::with_capacity(freqs.len());
    for &f in freqs {
        let h = weighting.response(f);
        let mut row = json!({
            "f_hz": f,
            "magnitude": h.norm(),
            "magnitude_db": afsv_records::json::finite_or_null(20.0 * h.norm().log10()),
            "phase_deg": h.arg().to_degrees(),
        });
        if let Some(iir) = iir {
            if f < 0.5 * iir.fs_hz() {
                row["iir_magnitude"] = afsv_records::json::finite_or_null(iir.magnitude(f));
            } else {
                row["iir_magnitude"] = serde_json::Value::Null;
                row["iir_magnitude_reason"] =
                    json!("at or above the IIR filter's Nyquist frequency --fs/2");
            }
        }
        rows.push(row);
    }
    let params = afsv_records::json::explain_nulls(
        json!(weighting.params()),
        "this weighting has no such stage",
    );
    let mut out = json!({
        "weighting": weighting,
        "params": params,
        "iir_fs_hz": fs,
        "rows": rows,
    });
    if fs.is_none() {
        out["iir_fs_hz_reason"] = json!("no --fs given");
    }
    out
}

/// The axes of a whole-body vibration assessment read from `rec` (`path` names it in
/// errors): axis x, y, z in that order, each from the column `columns[i].0` with the
/// weighting `weightings[i]`; a column the user named (`columns[i].1`) must be there, a
/// default one is used when present. Also the column of each axis used, by axis name (the
/// report's `channels`). No column at all is an error.
pub fn wbv_inputs<'r>(
    rec: &'r Record,
    path: &Path,
    columns: &[(String, bool); 3],
    weightings: [Weighting; 3],
) -> Result<(Vec<AxisInput<'r>>, serde_json::Map<String, Value>), String> {
    let mut inputs = Vec::new();
    let mut used = serde_json::Map::new();
    for (i, axis) in [Axis::X, Axis::Y, Axis::Z].into_iter().enumerate() {
        let (name, chosen) = &columns[i];
        let col = if *chosen {
            Some(rec.require(name, path).map_err(|e| e.to_string())?)
        } else {
            rec.column(name)
        };
        if let Some(col) = col {
            used.insert(["x", "y", "z"][i].into(), json!(name));
            inputs.push(AxisInput {
                axis,
                weighting: weightings[i],
                accel: col,
            });
        }
    }
    if inputs.is_empty() {
        return Err(format!(
            "{}: no acceleration column (expected any of ax_m_s2, ay_m_s2, az_m_s2, or name one with --channel AXIS=COLUMN)",
            path.display()
        ));
    }
    Ok((inputs, used))
}

/// The report of `afsv measures wbv`: the assessment `r`, the column of each axis used
/// (`channels`, from [`wbv_inputs`]) and the unit conversions made reading `rec`, if any.
pub fn wbv_report(
    r: &WbvAssessment,
    channels: serde_json::Map<String, Value>,
    rec: &Record,
) -> Result<Value, serde_json::Error> {
    let mut out = serde_json::to_value(r)?;
    out["channels"] = Value::Object(channels);
    if !rec.unit_conversions.is_empty() {
        out["unit_conversions"] = afsv_records::json::unit_conversions(rec);
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Default columns are taken when present and skipped when not; a named column must be
    /// there; a record without any is refused by name.
    #[test]
    fn the_wbv_axes_come_from_the_named_or_default_columns() {
        let rec = Record::from_columns([("time_s", vec![0.0, 0.1]), ("az_m_s2", vec![1.0, 2.0])])
            .unwrap();
        let path = Path::new("seat.csv");
        let defaults = ["ax_m_s2", "ay_m_s2", "az_m_s2"].map(|n| (n.to_string(), false));
        let w = [Axis::X, Axis::Y, Axis::Z].map(Axis::health_weighting);
        let (inputs, used) = wbv_inputs(&rec, path, &defaults, w).unwrap();
        assert_eq!(inputs.len(), 1);
        assert_eq!(inputs[0].axis, Axis::Z);
        assert_eq!(inputs[0].accel, &[1.0, 2.0]);
        assert_eq!(used["z"], "az_m_s2");
        let mut named = defaults.clone();
        named[0] = ("cab_x_m_s2".to_string(), true);
        assert!(wbv_inputs(&rec, path, &named, w)
            .unwrap_err()
            .contains("cab_x_m_s2"));
        let empty = Record::from_columns([("time_s", vec![0.0, 0.1])]).unwrap();
        let e = wbv_inputs(&empty, path, &defaults, w).unwrap_err();
        assert!(e.starts_with("seat.csv: no acceleration column"), "{e}");
    }
}
