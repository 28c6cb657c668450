//! Terrain synthesis (Eqs 2.8-2.10, 1.8-1.9) and Welch spectra, on the library calls of
//! `afsv terrain generate` and `afsv terrain psd`.

use crate::{f64s, py_err, record_out, to_bytes, to_json, value_err};
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use serde_json::json;
use terrain_psd::{
    cross_spectrum, synthesize, welch_psd, Band, CoherenceModel, Detrend, IsoClass, OffRoadTerrain,
    PowerLawPsd, TwoTrackSpec, WelchConfig, Window,
};

/// Most samples of one synthesised profile (the CLI's bound, 1e7).
const MAX_SAMPLES: f64 = 1e7;

/// The displacement PSD G_d(n) = alpha_r n^-w (Eq 2.8) named by exactly one of
/// `iso_class`, `terrain` or `alpha` with `waviness` (ISO 8608 class E by default).
fn psd_model(
    iso_class: Option<&str>,
    terrain: Option<&str>,
    alpha: Option<f64>,
    waviness: Option<f64>,
) -> PyResult<PowerLawPsd> {
    let chosen = [iso_class.is_some(), terrain.is_some(), alpha.is_some()];
    if chosen.iter().filter(|c| **c).count() > 1 {
        return Err(value_err(
            "choose one PSD model: iso_class, terrain or alpha/waviness",
        ));
    }
    if alpha.is_some() != waviness.is_some() {
        return Err(value_err(
            "alpha and waviness go together (G_d = alpha_r n^-w, Eq 2.8)",
        ));
    }
    if let (Some(a), Some(w)) = (alpha, waviness) {
        return PowerLawPsd::new(a, w).map_err(|e| value_err(format!("alpha/waviness: {e}")));
    }
    if let Some(t) = terrain {
        let t: OffRoadTerrain = t.parse().map_err(|e| value_err(format!("terrain: {e}")))?;
        return Ok(PowerLawPsd::off_road(t));
    }
    let class: IsoClass = match iso_class {
        Some(c) => c
            .parse()
            .map_err(|e| value_err(format!("iso_class: {e}")))?,
        None => IsoClass::E,
    };
    Ok(PowerLawPsd::iso(class))
}

/// `x_i = i dx`, rounded to 1 nm when dx >= 1 um (as the CLI's `x_m` column).
fn x_column(n: usize, dx: f64) -> Vec<f64> {
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

/// Synthesise a two-track profile (random-phase synthesis, Eqs 2.8-2.10): the columns
/// `x_m`, `left_m`, `right_m` and the sidecar's model description.
#[pyfunction]
#[pyo3(signature = (iso_class, terrain, alpha, waviness, band, coherence, half_track, speed, length, dx, seed))]
#[allow(clippy::too_many_arguments)]
fn synthesize_terrain<'py>(
    py: Python<'py>,
    iso_class: Option<&str>,
    terrain: Option<&str>,
    alpha: Option<f64>,
    waviness: Option<f64>,
    band: (f64, f64),
    coherence: &str,
    half_track: Option<f64>,
    speed: Option<f64>,
    length: f64,
    dx: f64,
    seed: u64,
) -> PyResult<Bound<'py, PyTuple>> {
    for (name, v) in [("length", length), ("dx", dx)] {
        if !(v.is_finite() && v > 0.0) {
            return Err(value_err(format!(
                "{name} {v}: must be a finite number > 0"
            )));
        }
    }
    if length / dx > MAX_SAMPLES {
        return Err(value_err(format!(
            "length/dx = {:.0} samples: at most {MAX_SAMPLES:e}",
            length / dx
        )));
    }
    let psd = psd_model(iso_class, terrain, alpha, waviness)?;
    let band = Band::new(band.0, band.1).map_err(|e| value_err(format!("band: {e}")))?;
    let coh = CoherenceModel::parse(coherence, half_track, speed)
        .map_err(|e| value_err(format!("coherence: {e}")))?;
    if half_track.is_some() && !matches!(coh, CoherenceModel::Bogsjo { .. }) {
        return Err(value_err(
            "half_track is only used with coherence bogsjo:RHO",
        ));
    }
    if speed.is_some() && !matches!(coh, CoherenceModel::Zhang { .. }) {
        return Err(value_err("speed is only used with coherence zhang"));
    }
    let spec = TwoTrackSpec::new(psd, band, coh).map_err(|e| py_err(py, &e))?;
    let prof = py
        .detach(|| synthesize(&spec, length, dx, seed))
        .map_err(|e| py_err(py, &e))?;
    let meta = json!({
        "terrain": to_json(&spec)?,
        "seed": seed,
        "length_m": prof.length_m(),
        "dx_m": dx,
        "samples": prof.len(),
        "rms_target_m": spec.variance().sqrt(),
    });
    let cols = vec![
        ("x_m".to_string(), x_column(prof.len(), dx)),
        ("left_m".to_string(), prof.left_m),
        ("right_m".to_string(), prof.right_m),
    ];
    record_out(py, &cols, &meta)
}

/// The Welch settings: `segment_m` (None: `WelchConfig::auto`), overlap, window, detrend,
/// checked against the signal length.
fn welch_config(
    n: usize,
    dx: f64,
    segment_m: Option<f64>,
    overlap: f64,
    window: &str,
    detrend: &str,
) -> PyResult<WelchConfig> {
    let mut cfg = match segment_m {
        Some(s) => {
            WelchConfig::with_segment_m(s, dx).map_err(|e| value_err(format!("segment_m: {e}")))?
        }
        None => WelchConfig::auto(n).map_err(|e| value_err(e.to_string()))?,
    };
    cfg.overlap = overlap;
    cfg.window = window
        .parse::<Window>()
        .map_err(|e| value_err(format!("window: {e}")))?;
    cfg.detrend = detrend
        .parse::<Detrend>()
        .map_err(|e| value_err(format!("detrend: {e}")))?;
    cfg.validate(n).map_err(|e| value_err(e.to_string()))?;
    Ok(cfg)
}

/// Welch one-sided PSD of `x` sampled every `dx`: `(freq, psd, info_json)`.
#[pyfunction]
#[pyo3(signature = (x, dx, segment_m, overlap, window, detrend))]
fn welch<'py>(
    py: Python<'py>,
    x: &[u8],
    dx: f64,
    segment_m: Option<f64>,
    overlap: f64,
    window: &str,
    detrend: &str,
) -> PyResult<Bound<'py, PyTuple>> {
    let x = f64s("x", x)?;
    let cfg = welch_config(x.len(), dx, segment_m, overlap, window, detrend)?;
    let s = py
        .detach(|| welch_psd(&x, dx, &cfg))
        .map_err(|e| py_err(py, &e))?;
    let info = json!({
        "segment_samples": cfg.segment_len,
        "overlap": cfg.overlap,
        "window": cfg.window.to_string(),
        "detrend": cfg.detrend.to_string(),
        "segments": s.segments,
        "df": s.df,
    });
    PyTuple::new(
        py,
        [
            to_bytes(py, &s.freq)?.into_any(),
            to_bytes(py, &s.psd)?.into_any(),
            crate::json_text(py, &info)?.into_any(),
        ],
    )
}

/// Welch cross-spectrum of `x` and `y`: `(freq, pxx, pyy, csd_re, csd_im, coherence)`.
#[pyfunction]
#[pyo3(signature = (x, y, dx, segment_m, overlap, window, detrend))]
#[allow(clippy::too_many_arguments)]
fn cross<'py>(
    py: Python<'py>,
    x: &[u8],
    y: &[u8],
    dx: f64,
    segment_m: Option<f64>,
    overlap: f64,
    window: &str,
    detrend: &str,
) -> PyResult<Bound<'py, PyTuple>> {
    let x = f64s("x", x)?;
    let y = f64s("y", y)?;
    let cfg = welch_config(x.len(), dx, segment_m, overlap, window, detrend)?;
    let c = py
        .detach(|| cross_spectrum(&x, &y, dx, &cfg))
        .map_err(|e| py_err(py, &e))?;
    let parts = [&c.freq, &c.pxx, &c.pyy, &c.csd_re, &c.csd_im, &c.coherence];
    let mut out = Vec::with_capacity(parts.len());
    for p in parts {
        out.push(to_bytes(py, p)?);
    }
    PyTuple::new(py, out)
}

/// Register the terrain functions.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(synthesize_terrain, m)?)?;
    m.add_function(wrap_pyfunction!(welch, m)?)?;
    m.add_function(wrap_pyfunction!(cross, m)?)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::x_column;

    #[test]
    fn x_column_is_rounded_to_a_nanometre_as_the_cli_writes_it() {
        let x = x_column(4, 0.05);
        assert_eq!(x, vec![0.0, 0.05, 0.1, 0.15]);
        // without the rounding 3 * 0.05 is 0.15000000000000002
        assert_ne!(3.0 * 0.05, 0.15);
        // below 1 um the spacing is kept as computed
        assert_eq!(x_column(2, 1e-7)[1], 1e-7);
    }
}
