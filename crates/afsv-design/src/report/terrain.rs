//! The reports of `afsv terrain` (crate `terrain-psd`): the x column and RMS of a
//! synthesised profile, and the spectral analysis of a two-track profile (`terrain psd`:
//! Welch PSDs, cross-spectrum, coherence, cross-slope PSD, and the errors against the
//! model its sidecar records) with its summary lines.

use serde_json::{json, Value};
use terrain_psd::{cross_slope_psd, cross_spectrum, welch_psd, Band, TwoTrackSpec, WelchConfig};

/// `x_i = i dx`, rounded to 1 nm when dx >= 1 um so that the CSV shows 0.15, not
/// 0.15000000000000002.
pub fn x_column(n: usize, dx: f64) -> Vec<f64> {
    (0..n)
        .map(|i| {
            let x = i as f64 * dx;
            if dx >= 1e-6 {
                (x * 1e9).round() / 1e9
            } else {
                x
            }
        })
        .collect()
}

/// The RMS of `v` about its mean (the standard deviation with 1/n).
pub fn rms(v: &[f64]) -> f64 {
    let m = v.iter().sum::<f64>() / v.len() as f64;
    (v.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / v.len() as f64).sqrt()
}

/// The values of `v` at the indices `keep`.
fn select(v: &[f64], keep: &[usize]) -> Vec<f64> {
    keep.iter().map(|&k| v[k]).collect()
}

/// The spectral analysis of `terrain psd` on the profile `input` (its name in the report):
/// the left track (and the right one, when there is one) sampled at `dx` (m), estimated with
/// `cfg`, reported on the bins inside `band` (all without one); with a right track, the
/// cross-slope over `track_width` (m) and, when the sidecar metadata `meta` records the
/// terrain model, the errors against it (`target_report`). Returns the scalar results and
/// the spectrum (one array per column).
pub fn psd_analysis(
    input: &str,
    (left, right): (&[f64], Option<&[f64]>),
    dx: f64,
    cfg: &WelchConfig,
    band: Option<Band>,
    track_width: f64,
    meta: &Value,
) -> Result<(Value, Value), String> {
    let left_spec = welch_psd(left, dx, cfg).map_err(|e| e.to_string())?;
    let keep: Vec<usize> = (0..left_spec.freq.len())
        .filter(|&k| band.is_none_or(|b| b.contains(left_spec.freq[k])))
        .collect();
    let freq = select(&left_spec.freq, &keep);
    let mut out = json!({
        "input": input,
        "samples": left.len(),
        "dx_m": dx,
        "length_m": dx * (left.len() - 1) as f64,
        "welch": {
            "segment_samples": cfg.segment_len,
            "segment_m": cfg.segment_len as f64 * dx,
            "overlap": cfg.overlap,
            "window": cfg.window.to_string(),
            "detrend": cfg.detrend.to_string(),
            "segments": left_spec.segments,
            "resolution_cycles_per_m": left_spec.df,
        },
        "variance_left_m2": rms(left).powi(2),
        "psd_integral_left_m2": left_spec.integral(),
    });
    let mut spectrum = json!({
        "n_cycles_per_m": freq,
        "psd_left_m3": select(&left_spec.psd, &keep),
    });
    if let Some(right) = right {
        let cs = cross_spectrum(left, right, dx, cfg).map_err(|e| e.to_string())?;
        let slope =
            cross_slope_psd(left, right, dx, track_width, cfg).map_err(|e| e.to_string())?;
        out["variance_right_m2"] = json!(rms(right).powi(2));
        out["psd_integral_right_m2"] = json!(cs.pyy.iter().sum::<f64>() * cs.df);
        out["track_width_m"] = json!(track_width);
        out["cross_slope_rms_rad"] = json!(rms(&left
            .iter()
            .zip(right)
            .map(|(l, r)| (l - r) / track_width)
            .collect::<Vec<_>>()));
        spectrum["psd_right_m3"] = json!(select(&cs.pyy, &keep));
        spectrum["csd_re_m3"] = json!(select(&cs.csd_re, &keep));
        spectrum["csd_im_m3"] = json!(select(&cs.csd_im, &keep));
        spectrum["coherence"] = json!(select(&cs.coherence, &keep));
        spectrum["cross_slope_psd_rad2_per_cycle_per_m"] = json!(select(&slope.psd, &keep));
        if let Some(spec) = sidecar_spec(meta) {
            out["target"] = target_report(&spec, &freq, &keep, &cs, track_width);
        }
    }
    Ok((out, spectrum))
}

/// The scalar results of `terrain psd`, as lines for a terminal.
pub fn psd_summary(out: &Value) -> String {
    let num = |k: &str| out[k].as_f64();
    let mut s = format!(
        "{}: {} samples at {} m; Welch {} segments of {} m, resolution {} cycles/m\n",
        out["input"].as_str().unwrap_or_default(),
        out["samples"],
        out["dx_m"],
        out["welch"]["segments"],
        out["welch"]["segment_m"],
        out["welch"]["resolution_cycles_per_m"],
    );
    for (label, v, i) in [
        ("left", "variance_left_m2", "psd_integral_left_m2"),
        ("right", "variance_right_m2", "psd_integral_right_m2"),
    ] {
        if let (Some(v), Some(i)) = (num(v), num(i)) {
            s += &format!("{label} track: variance {v:.4e} m², PSD integral {i:.4e} m²\n");
        }
    }
    if let Some(e) = out["target"]["psd_mean_error_db"].as_f64() {
        s += &format!(
            "against the sidecar's model over its band: PSD {e:+.2} dB, coherence {:+.3} (mean errors)\n",
            out["target"]["coherence_mean_error"].as_f64().unwrap_or(f64::NAN)
        );
    }
    s
}

/// The terrain model recorded in a sidecar by `afsv terrain generate`, if any.
fn sidecar_spec(meta: &Value) -> Option<TwoTrackSpec> {
    let spec: TwoTrackSpec = serde_json::from_value(meta.get("terrain")?.clone()).ok()?;
    spec.validate().ok().map(|_| spec)
}

/// Targets on the reported bins and band-averaged errors of the estimates.
fn target_report(
    spec: &TwoTrackSpec,
    freq: &[f64],
    keep: &[usize],
    cs: &terrain_psd::CrossSpectrum,
    track_width: f64,
) -> Value {
    let mut db = Vec::new();
    let mut coh = Vec::new();
    for (&n, &k) in freq.iter().zip(keep) {
        if spec.band.contains(n) {
            let g = spec.target_psd(n);
            db.push(5.0 * ((cs.pxx[k] / g).log10() + (cs.pyy[k] / g).log10()));
            coh.push(cs.coherence[k] - spec.target_msc(n));
        }
    }
    let mean = |v: &[f64]| {
        if v.is_empty() {
            Value::Null
        } else {
            json!(v.iter().sum::<f64>() / v.len() as f64)
        }
    };
    json!({
        "terrain": spec,
        "variance_m2": spec.variance(),
        "band_bins": db.len(),
        "psd_mean_error_db": mean(&db),
        "coherence_mean_error": mean(&coh),
        "psd_m3": freq.iter().map(|&n| spec.target_psd(n)).collect::<Vec<_>>(),
        "coherence": freq.iter().map(|&n| spec.target_msc(n)).collect::<Vec<_>>(),
        "cross_slope_psd_rad2_per_cycle_per_m": freq
            .iter()
            .map(|&n| spec.target_cross_slope_psd(n, track_width))
            .collect::<Vec<_>>(),
    })
}
