//! The terrain models `afsv terrain generate` chooses from its options (the displacement
//! PSD of an ISO 8608 class, an off-road terrain of Tables 1.2/2.4 or a power law, Eq 2.8;
//! the two tracks' coherence, Eqs 1.8, 1.9, 2.10), and the table of `afsv terrain psd`.

use afsv_records::Record;
use serde_json::Value;
use std::path::Path;
use terrain_psd::{
    Band, CoherenceModel, Detrend, IsoClass, OffRoadTerrain, PowerLawPsd, WelchConfig, Window,
};

/// The columns of the spectrum table of `afsv terrain psd`.
pub const SPECTRUM_COLUMNS: [&str; 7] = [
    "n_cycles_per_m",
    "psd_left_m3",
    "psd_right_m3",
    "coherence",
    "cross_slope_psd_rad2_per_cycle_per_m",
    "csd_re_m3",
    "csd_im_m3",
];

/// The displacement PSD of one of `class` (A to H), `terrain` (an off-road terrain's name)
/// or the power law `(alpha_r, w)` (both or neither), with a description of it; ISO 8608
/// class E without any (the paper's nominal off-road terrain, section 6.2.3).
pub fn psd_model(
    class: Option<&str>,
    terrain: Option<&str>,
    (alpha, waviness): (Option<f64>, Option<f64>),
) -> Result<(PowerLawPsd, String), String> {
    let chosen = [class.is_some(), terrain.is_some(), alpha.is_some()];
    if chosen.iter().filter(|c| **c).count() > 1 {
        return Err("choose one PSD model: --class, --terrain or --alpha/--waviness".into());
    }
    if alpha.is_some() != waviness.is_some() {
        return Err("--alpha and --waviness go together (G_d = alpha_r n^-w, Eq 2.8)".into());
    }
    if let (Some(alpha), Some(w)) = (alpha, waviness) {
        let m = PowerLawPsd::new(alpha, w).map_err(|e| format!("--alpha/--waviness: {e}"))?;
        return Ok((
            m,
            format!("user power law alpha_r = {alpha:e}, w = {w} (Eq 2.8)"),
        ));
    }
    if let Some(t) = terrain {
        let t: OffRoadTerrain = t.parse().map_err(|e| format!("--terrain: {e}"))?;
        let m = PowerLawPsd::off_road(t);
        return Ok((
            m,
            format!(
                "off-road terrain {t} (Tables 1.2/2.4): alpha_r = {:e}, w = {}",
                m.alpha_r, m.waviness
            ),
        ));
    }
    let class: IsoClass = match class {
        Some(c) => c.parse().map_err(|e| format!("--class: {e}"))?,
        None => IsoClass::E,
    };
    let m = PowerLawPsd::iso(class);
    Ok((
        m,
        format!(
            "ISO 8608 class {class}: G_d(n0) = {:e} m^3, alpha_r = {:e}, w = 2",
            class.gd_n0(),
            m.alpha_r
        ),
    ))
}

/// The spatial band `N_MIN,N_MAX` (cycles/m) of `--band`.
pub fn band(text: &str) -> Result<Band, String> {
    text.parse().map_err(|e| format!("--band: {e}"))
}

/// The coherence model `text` names; a half-track width (m) only with `bogsjo:RHO`, a
/// speed (m/s) only with `zhang`.
pub fn coherence_model(
    text: &str,
    half_track_m: Option<f64>,
    speed_m_s: Option<f64>,
) -> Result<CoherenceModel, String> {
    let c = CoherenceModel::parse(text, half_track_m, speed_m_s)
        .map_err(|e| format!("--coherence: {e}"))?;
    if half_track_m.is_some() && !matches!(c, CoherenceModel::Bogsjo { .. }) {
        return Err("--half-track is only used with --coherence bogsjo:RHO".into());
    }
    if speed_m_s.is_some() && !matches!(c, CoherenceModel::Zhang { .. }) {
        return Err("--speed is only used with --coherence zhang".into());
    }
    Ok(c)
}

/// The Welch estimator of a record of `samples` samples at spacing `dx` (m) read from
/// `file`: segments of `segment_m` (m; default `WelchConfig::auto`), `overlap`, the
/// `window` and `detrend` named, checked against the record.
pub fn welch_config(
    (samples, dx, file): (usize, f64, &Path),
    segment_m: Option<f64>,
    overlap: f64,
    (window, detrend): (&str, &str),
) -> Result<WelchConfig, String> {
    let mut cfg = match segment_m {
        Some(s) => WelchConfig::with_segment_m(s, dx).map_err(|e| format!("--segment-m: {e}"))?,
        None => WelchConfig::auto(samples).map_err(|e| e.to_string())?,
    };
    cfg.overlap = overlap;
    cfg.window = window
        .parse::<Window>()
        .map_err(|e| format!("--window: {e}"))?;
    cfg.detrend = detrend
        .parse::<Detrend>()
        .map_err(|e| format!("--detrend: {e}"))?;
    cfg.validate(samples)
        .map_err(|e| format!("{}: {e}", file.display()))?;
    Ok(cfg)
}

/// The rows of a spectral analysis (`terrain_psd`'s, as `afsv_design::report::terrain`
/// reports it): the `spectrum` columns ([`SPECTRUM_COLUMNS`]) and, when the analysis `out`
/// has the model's `target`, its PSD and coherence.
pub fn psd_table(out: &Value, spectrum: &Value) -> Result<Record, String> {
    use afsv_records::json::from_columns;
    let mut table = from_columns(spectrum, &SPECTRUM_COLUMNS)?;
    if let Some(target) = out.get("target") {
        let t = from_columns(target, &["psd_m3", "coherence"])?;
        for (name, col) in [
            ("target_psd_m3", "psd_m3"),
            ("target_coherence", "coherence"),
        ] {
            if let Some(c) = t.column(col) {
                table
                    .push_column(name, c.to_vec())
                    .map_err(|e| e.to_string())?;
            }
        }
    }
    Ok(table)
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn a_band_is_two_ascending_frequencies() {
        let b = band("0.02,5").unwrap();
        assert_eq!((b.n_min, b.n_max), (0.02, 5.0));
        assert!(band("5,0.02").unwrap_err().starts_with("--band: "));
        assert!(band("1").unwrap_err().starts_with("--band: "));
    }

    #[test]
    fn one_psd_model_is_chosen() {
        let (m, text) = psd_model(None, None, (None, None)).unwrap();
        assert_eq!(m, PowerLawPsd::iso(IsoClass::E));
        assert!(text.starts_with("ISO 8608 class E"));
        assert!(psd_model(Some("C"), Some("forestry"), (None, None)).is_err());
        assert!(psd_model(None, None, (Some(1e-4), None)).is_err());
        let (m, _) = psd_model(None, None, (Some(1e-4), Some(2.5))).unwrap();
        assert_eq!((m.alpha_r, m.waviness), (1e-4, 2.5));
        assert!(coherence_model("piecewise:0.3", Some(1.0), None).is_err());
        assert!(coherence_model("bogsjo:0.5", Some(1.0), None).is_ok());
        let file = Path::new("t.csv");
        let cfg = welch_config((4096, 0.05, file), Some(12.8), 0.25, ("hann", "linear")).unwrap();
        assert_eq!((cfg.overlap, cfg.detrend), (0.25, Detrend::Linear));
        assert!(welch_config((4096, 0.05, file), None, 0.5, ("box", "mean")).is_err());
        assert!(
            welch_config((10, 0.05, file), Some(12.8), 0.5, ("hann", "mean"))
                .unwrap_err()
                .starts_with("t.csv: ")
        );
    }

    #[test]
    fn the_table_takes_the_target_columns() {
        let spectrum: Value = SPECTRUM_COLUMNS
            .iter()
            .map(|c| (c.to_string(), json!([1.0, 2.0])))
            .collect::<serde_json::Map<_, _>>()
            .into();
        let out = json!({ "target": { "psd_m3": [3.0, 4.0], "coherence": [0.5, 0.4] } });
        let t = psd_table(&out, &spectrum).unwrap();
        assert_eq!(t.column("target_coherence"), Some(&[0.5, 0.4][..]));
        assert_eq!(psd_table(&json!({}), &spectrum).unwrap().names().len(), 7);
    }
}
