//! Tabulated weighting factors of ISO 2631-1:1997.
//!
//! Source: ISO 2631-1:1997, Table 3 (principal weightings Wk, Wd, Wf) and Table 4
//! (additional weightings Wc, We, Wj), columns "factor x 1000", transcribed by hand for the
//! one-third-octave bands 0.1 Hz (band -10) to 100 Hz (band 20); Wf is tabulated by the
//! standard only from 0.02 Hz (band -17) to 4 Hz (band 6), and all of its rows are kept.
//! The factors follow from the Annex A formulas evaluated at the *nominal* band frequencies
//! (0.125, 0.16, ... Hz, as printed): at the nominal frequencies the formulas reproduce the
//! printed values to within their rounding (< 0.35 % except where noted), while at the exact
//! band centres `10^(x/10)` Hz they differ by up to 1.9 % on the steep slopes. The
//! comparison in [`super::check`] therefore uses the nominal frequencies.
//!
//! Erratum: Table 3 prints 212 for Wd at 10 Hz. The Annex A formula gives 201.7, the
//! neighbouring Wd values (253 at 8 Hz, 161 at 12.5 Hz) and the identically shaped We one
//! octave lower (202 at 5 Hz) agree with it, so the printed value is a misprint of 202;
//! [`factors`] returns the corrected 202 and [`ERRATA`] records the printed value.

use super::weighting::Weighting;

/// First band number of [`factors`]' rows for the weightings other than Wf (0.1 Hz).
pub const FIRST_BAND: i32 = -10;
/// First band number of the Wf rows (0.02 Hz).
pub const FIRST_BAND_WF: i32 = -17;

/// Nominal one-third-octave centre frequency (Hz) of band number `x` (IEC 61260 preferred
/// numbers), as printed in the standard's tables.
pub fn nominal_frequency(x: i32) -> f64 {
    const MANTISSA: [f64; 10] = [1.0, 1.25, 1.6, 2.0, 2.5, 3.15, 4.0, 5.0, 6.3, 8.0];
    let decade = x.div_euclid(10);
    let k = x.rem_euclid(10) as usize;
    MANTISSA[k] * 10f64.powi(decade)
}

/// Exact band-centre frequency `10^(x/10)` Hz of band number `x`.
pub fn exact_frequency(x: i32) -> f64 {
    10f64.powf(x as f64 / 10.0)
}

const WK: [f64; 31] = [
    31.2, 48.6, 79.0, 121.0, 182.0, 263.0, 352.0, 418.0, 459.0, 477.0, // 0.1 - 0.8
    482.0, 484.0, 494.0, 531.0, 631.0, 804.0, 967.0, 1039.0, 1054.0, 1036.0, // 1 - 8
    988.0, 902.0, 768.0, 636.0, 513.0, 405.0, 314.0, 246.0, 186.0, 132.0, // 10 - 80
    88.7,  // 100
];
const WD: [f64; 31] = [
    62.4, 97.3, 158.0, 243.0, 365.0, 530.0, 713.0, 853.0, 944.0, 992.0, // 0.1 - 0.8
    1011.0, 1008.0, 968.0, 890.0, 776.0, 642.0, 512.0, 409.0, 323.0, 253.0, // 1 - 8
    202.0, 161.0, 125.0, 100.0, 80.0, 63.2, 49.4, 38.8, 29.5,
    21.1, // 10 - 80 (10 Hz: erratum)
    14.1, // 100
];
const WF: [f64; 24] = [
    24.2, 37.7, 59.7, 97.1, 157.0, 267.0, 461.0, // 0.02 - 0.08
    695.0, 895.0, 1006.0, 992.0, 854.0, 619.0, 384.0, 224.0, 116.0, 53.0, // 0.1 - 0.8
    23.5, 9.98, 3.77, 1.55, 0.64, 0.25, 0.097, // 1 - 4
];
const WC: [f64; 31] = [
    62.4, 97.2, 158.0, 243.0, 364.0, 527.0, 708.0, 843.0, 929.0, 972.0, // 0.1 - 0.8
    991.0, 1000.0, 1007.0, 1012.0, 1017.0, 1022.0, 1024.0, 1013.0, 974.0, 891.0, // 1 - 8
    776.0, 647.0, 512.0, 409.0, 325.0, 256.0, 199.0, 156.0, 118.0, 84.4, // 10 - 80
    56.7, // 100
];
const WE: [f64; 31] = [
    62.5, 97.5, 159.0, 245.0, 368.0, 536.0, 723.0, 862.0, 939.0, 941.0, // 0.1 - 0.8
    880.0, 772.0, 632.0, 512.0, 409.0, 323.0, 253.0, 202.0, 161.0, 125.0, // 1 - 8
    100.0, 80.1, 62.5, 50.0, 39.9, 31.6, 24.7, 19.4, 14.8, 10.5, // 10 - 80
    7.07, // 100
];
const WJ: [f64; 31] = [
    31.0, 48.3, 78.5, 120.0, 181.0, 262.0, 351.0, 417.0, 458.0, 478.0, // 0.1 - 0.8
    484.0, 485.0, 483.0, 482.0, 489.0, 524.0, 628.0, 793.0, 946.0, 1017.0, // 1 - 8
    1030.0, 1026.0, 1018.0, 1012.0, 1007.0, 1001.0, 991.0, 972.0, 931.0, 843.0, // 10 - 80
    708.0, // 100
];

/// A misprinted table entry: weighting, nominal frequency (Hz), printed factor, corrected
/// factor (see the module documentation).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Erratum {
    /// Weighting.
    pub weighting: Weighting,
    /// Nominal band frequency (Hz).
    pub nominal_hz: f64,
    /// Factor as printed in the standard.
    pub printed: f64,
    /// Factor used here.
    pub corrected: f64,
}

/// Known misprints of the standard's tables, corrected in [`factors`].
pub const ERRATA: [Erratum; 1] = [Erratum {
    weighting: Weighting::Wd,
    nominal_hz: 10.0,
    printed: 0.212,
    corrected: 0.202,
}];

/// One tabulated row: band number, nominal and exact frequency, factor (not x 1000).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct TableRow {
    /// Band number `x` (frequency `10^(x/10)` Hz).
    pub band: i32,
    /// Nominal frequency as printed (Hz).
    pub nominal_hz: f64,
    /// Exact band-centre frequency (Hz).
    pub exact_hz: f64,
    /// Tabulated weighting factor.
    pub factor: f64,
}

/// The standard's tabulated factors of weighting `w` (see the module doc for the source).
pub fn factors(w: Weighting) -> Vec<TableRow> {
    let (first, values): (i32, &[f64]) = match w {
        Weighting::Wk => (FIRST_BAND, &WK),
        Weighting::Wd => (FIRST_BAND, &WD),
        Weighting::Wc => (FIRST_BAND, &WC),
        Weighting::We => (FIRST_BAND, &WE),
        Weighting::Wj => (FIRST_BAND, &WJ),
        Weighting::Wf => (FIRST_BAND_WF, &WF),
    };
    values
        .iter()
        .enumerate()
        .map(|(i, v)| {
            let band = first + i as i32;
            TableRow {
                band,
                nominal_hz: nominal_frequency(band),
                exact_hz: exact_frequency(band),
                factor: v / 1000.0,
            }
        })
        .collect()
}
