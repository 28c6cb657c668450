//! The "ISO 2631 weighting check": every weighting's analog response, its IIR realisation
//! and the frequency-domain method, compared with the standard's tabulated factors
//! ([`super::table`]) at the one-third-octave bands from 0.1 Hz to 100 Hz.

use super::filter::{settling_samples, weight_fft, IirWeighting};
use super::table::{factors, Erratum, TableRow, ERRATA};
use super::weighting::Weighting;
use crate::error::{positive, MeasureError};
use serde::Serialize;
use std::f64::consts::PI;

/// Tolerance of the check, percent of the tabulated factor (the requirement).
pub const CHECK_TOLERANCE_PERCENT: f64 = 2.0;
/// Sampling rate at which [`weighting_check`] evaluates the IIR filters (Hz).
pub const CHECK_IIR_FS_HZ: f64 = 2000.0;
/// Sampling rate of the sine records pushed through the frequency-domain method (Hz).
pub const CHECK_FFT_FS_HZ: f64 = 256.0;
/// Lowest and highest band frequency compared (Hz).
pub const CHECK_BAND_HZ: (f64, f64) = (0.1, 100.0);

/// Check result of one weighting.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WeightingCheckEntry {
    /// The weighting.
    pub weighting: Weighting,
    /// Number of tabulated bands compared.
    pub bands: usize,
    /// Largest `|analog / table - 1|` in percent.
    pub max_analog_error_percent: f64,
    /// Nominal frequency (Hz) of that largest analog error.
    pub worst_analog_hz: f64,
    /// Largest error of the IIR filter at [`WeightingCheck::iir_fs_hz`], percent.
    pub max_iir_error_percent: f64,
    /// Nominal frequency (Hz) of that largest IIR error.
    pub worst_iir_hz: f64,
    /// Largest error of the frequency-domain method, measured as the RMS gain of a unit sine
    /// record at each band frequency, percent.
    pub max_fft_error_percent: f64,
    /// Nominal frequency (Hz) of that largest frequency-domain error.
    pub worst_fft_hz: f64,
    /// All three errors within the tolerance.
    pub pass: bool,
}

/// Outcome of the ISO 2631 weighting check.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WeightingCheck {
    /// Source of the reference values.
    pub reference: &'static str,
    /// Tolerance in percent.
    pub tolerance_percent: f64,
    /// Band range compared (Hz).
    pub band_hz: (f64, f64),
    /// Sampling rate of the IIR filters compared (Hz).
    pub iir_fs_hz: f64,
    /// Sampling rate of the sine records of the frequency-domain method (Hz).
    pub fft_fs_hz: f64,
    /// Misprints of the tables that were corrected before comparing.
    pub errata: Vec<Erratum>,
    /// One entry per weighting.
    pub weightings: Vec<WeightingCheckEntry>,
    /// Largest analog error over all weightings, percent.
    pub max_analog_error_percent: f64,
    /// Largest IIR error over all weightings, percent.
    pub max_iir_error_percent: f64,
    /// Largest frequency-domain error over all weightings, percent.
    pub max_fft_error_percent: f64,
    /// Every weighting passed.
    pub pass: bool,
}

fn rows_in_band(w: Weighting) -> Vec<TableRow> {
    factors(w)
        .into_iter()
        .filter(|r| {
            r.nominal_hz >= CHECK_BAND_HZ.0 * 0.999 && r.nominal_hz <= CHECK_BAND_HZ.1 * 1.001
        })
        .collect()
}

fn worst(errors: impl Iterator<Item = (f64, f64)>) -> (f64, f64) {
    errors.fold((0.0, f64::NAN), |acc, (hz, e)| {
        if e.abs() > acc.0 {
            (e.abs(), hz)
        } else {
            acc
        }
    })
}

/// RMS gain of the frequency-domain method for a unit-amplitude sine at `f_hz`, measured
/// over whole periods after the weighting's settling time.
pub fn fft_sine_gain(w: Weighting, f_hz: f64, fs_hz: f64) -> Result<f64, MeasureError> {
    let settle = settling_samples(&w.params(), fs_hz);
    let period = fs_hz / f_hz;
    let periods = (20.0f64).max((4.0 * f_hz).ceil());
    let measure = (periods * period).round() as usize;
    let n = settle + measure;
    let x: Vec<f64> = (0..n)
        .map(|i| (2.0 * PI * f_hz * i as f64 / fs_hz).sin())
        .collect();
    let y = weight_fft(w, &x, fs_hz)?;
    let ms = y[settle..].iter().map(|v| v * v).sum::<f64>() / measure as f64;
    let x_ms = x[settle..].iter().map(|v| v * v).sum::<f64>() / measure as f64;
    Ok((ms / x_ms).sqrt())
}

/// The weighting check at [`CHECK_IIR_FS_HZ`] (always computable).
pub fn weighting_check() -> WeightingCheck {
    match weighting_check_at(CHECK_IIR_FS_HZ) {
        Ok(c) => c,
        Err(e) => unreachable!("the check's built-in sampling rate is valid: {e}"),
    }
}

/// The weighting check with the IIR filters designed for `iir_fs_hz` (errors above the
/// IIR's accurate range are reported, not hidden).
pub fn weighting_check_at(iir_fs_hz: f64) -> Result<WeightingCheck, MeasureError> {
    positive("iir_fs_hz", iir_fs_hz)?;
    let mut entries = Vec::with_capacity(Weighting::ALL.len());
    for w in Weighting::ALL {
        let rows = rows_in_band(w);
        let iir = IirWeighting::new(w, iir_fs_hz)?;
        let pct = |got: f64, want: f64| 100.0 * (got / want - 1.0);
        let (max_a, worst_a) = worst(
            rows.iter()
                .map(|r| (r.nominal_hz, pct(w.magnitude(r.nominal_hz), r.factor))),
        );
        let (max_i, worst_i) = worst(rows.iter().map(|r| {
            let e = if r.nominal_hz < 0.5 * iir_fs_hz {
                pct(iir.magnitude(r.nominal_hz), r.factor)
            } else {
                f64::INFINITY
            };
            (r.nominal_hz, e)
        }));
        let mut fft_errors = Vec::with_capacity(rows.len());
        for r in &rows {
            fft_errors.push((
                r.nominal_hz,
                pct(fft_sine_gain(w, r.nominal_hz, CHECK_FFT_FS_HZ)?, r.factor),
            ));
        }
        let (max_f, worst_f) = worst(fft_errors.into_iter());
        let tol = CHECK_TOLERANCE_PERCENT;
        entries.push(WeightingCheckEntry {
            weighting: w,
            bands: rows.len(),
            max_analog_error_percent: max_a,
            worst_analog_hz: worst_a,
            max_iir_error_percent: max_i,
            worst_iir_hz: worst_i,
            max_fft_error_percent: max_f,
            worst_fft_hz: worst_f,
            pass: max_a <= tol && max_i <= tol && max_f <= tol,
        });
    }
    let max_of = |f: fn(&WeightingCheckEntry) -> f64| entries.iter().map(f).fold(0.0, f64::max);
    Ok(WeightingCheck {
        reference: "ISO 2631-1:1997 Tables 3 and 4, at the nominal band frequencies (Wd 10 Hz misprint 212 read as 202)",
        tolerance_percent: CHECK_TOLERANCE_PERCENT,
        band_hz: CHECK_BAND_HZ,
        iir_fs_hz,
        fft_fs_hz: CHECK_FFT_FS_HZ,
        max_analog_error_percent: max_of(|e| e.max_analog_error_percent),
        max_iir_error_percent: max_of(|e| e.max_iir_error_percent),
        max_fft_error_percent: max_of(|e| e.max_fft_error_percent),
        pass: entries.iter().all(|e| e.pass),
        errata: ERRATA.to_vec(),
        weightings: entries,
    })
}
