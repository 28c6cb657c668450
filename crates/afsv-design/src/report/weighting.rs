//! The report of `afsv measures weighting`: an ISO 2631-1 frequency weighting (Annex A
//! analog transfer function) at given frequencies, with its bilinear IIR realisation at a
//! sampling rate when one is given.

use perf_measures::iso2631::{IirWeighting, Weighting};
use serde_json::{json, Value};

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
