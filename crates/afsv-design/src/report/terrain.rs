//! The reports of `afsv terrain` (crate `terrain-psd`): the record, sidecar and summary
//! of a synthesised profile (`terrain generate`), and the spectral analysis of a two-track profile (`terrain psd`:
//! Welch PSDs, cross-spectrum, coherence, cross-slope PSD, and the errors against the
//! model its sidecar records) with its summary lines.

use afsv_records::{Record, RecordError};
use serde_json::{json, Value};
use std::path::Path;
use terrain_psd::{
    cross_slope_psd, cross_spectrum, welch_psd, Band, TwoTrackProfile, TwoTrackSpec, WelchConfig,
};

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

/// A profile `afsv terrain generate` synthesised, with what made it.
#[derive(Debug, Clone, Copy)]
pub struct Generated<'a> {
    /// The displacement PSD in words (e.g. the ISO 8608 class with its G_d(n0)).
    pub model: &'a str,
    /// The two-track model (PSD, band, coherence).
    pub spec: &'a TwoTrackSpec,
    /// The synthesis seed.
    pub seed: u64,
    /// Sample spacing (m).
    pub dx_m: f64,
    /// The two tracks.
    pub profile: &'a TwoTrackProfile,
}

/// The sidecar of a synthesised profile: the model (in words and whole, so that `terrain
/// psd` can compare an estimate with it), the seed, the length and spacing, and the RMS the
/// model's variance gives.
pub fn generated_sidecar(g: &Generated) -> Value {
    let band = g.spec.band;
    json!({
        "written_by": "afsv terrain generate",
        "generator": "afsv terrain generate",
        "description": format!("{}; band {}-{} cycles/m; coherence {}", g.model, band.n_min, band.n_max, g.spec.coherence),
        "terrain": g.spec,
        "seed": g.seed,
        "length_m": g.profile.length_m(),
        "dx_m": g.dx_m,
        "samples": g.profile.len(),
        "rms_target_m": g.spec.variance().sqrt(),
    })
}

/// The record of a synthesised profile: columns `x_m` ([`x_column`]), `left_m` and
/// `right_m`, with the sidecar `meta`.
pub fn generated_record(g: &Generated, meta: Value) -> Result<Record, RecordError> {
    let p = g.profile;
    let mut rec = Record::new();
    rec.push_column("x_m", x_column(p.len(), g.dx_m))?;
    rec.push_column("left_m", p.left_m.clone())?;
    rec.push_column("right_m", p.right_m.clone())?;
    rec.meta = meta;
    Ok(rec)
}

/// What `terrain generate` prints: the sidecar `meta` with each track's [`rms`], then the
/// files when the profile was written to `output`, else the profile itself.
pub fn generated_summary(g: &Generated, meta: Value, output: Option<&Path>) -> Value {
    let p = g.profile;
    let mut out = meta;
    out["rms_left_m"] = json!(rms(&p.left_m));
    out["rms_right_m"] = json!(rms(&p.right_m));
    match output {
        Some(path) => {
            out["output"] = json!(path.display().to_string());
            out["sidecar"] = json!(path.with_extension("json").display().to_string());
        }
        None => {
            out["x_m"] = json!(x_column(p.len(), g.dx_m));
            out["left_m"] = json!(p.left_m);
            out["right_m"] = json!(p.right_m);
        }
    }
    out
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

#[cfg(test)]
mod tests {
    use super::*;
    use terrain_psd::{synthesize, CoherenceModel, PowerLawPsd};

    /// The record, sidecar and summary of a short synthesised profile agree with it: the
    /// record's columns are the tracks, the sidecar names the seed and spacing, and the
    /// summary carries either the files or the profile.
    #[test]
    fn a_generated_profile_is_recorded_and_summarised_whole() {
        let spec = TwoTrackSpec::new(
            PowerLawPsd::iso(terrain_psd::IsoClass::C),
            Band::default(),
            CoherenceModel::Independent,
        )
        .unwrap();
        let profile = synthesize(&spec, 20.0, 0.1, 3).unwrap();
        let g = Generated {
            model: "class C",
            spec: &spec,
            seed: 3,
            dx_m: 0.1,
            profile: &profile,
        };
        let meta = generated_sidecar(&g);
        assert_eq!(meta["seed"], 3);
        assert_eq!(meta["samples"], profile.len());
        assert!(meta["description"]
            .as_str()
            .unwrap()
            .starts_with("class C; band "));
        let rec = generated_record(&g, meta.clone()).unwrap();
        assert_eq!(rec.names(), ["x_m", "left_m", "right_m"]);
        assert_eq!(rec.column("right_m").unwrap(), &profile.right_m[..]);
        assert_eq!(rec.meta, meta);
        let written = generated_summary(&g, meta.clone(), Some(Path::new("t.csv")));
        assert_eq!(written["sidecar"], "t.json");
        assert!(written.get("left_m").is_none());
        let printed = generated_summary(&g, meta, None);
        assert_eq!(printed["rms_left_m"], rms(&profile.left_m));
        assert_eq!(printed["x_m"][10], 1.0);
        assert!(printed.get("output").is_none());
    }
}
