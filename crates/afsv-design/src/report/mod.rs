//! The reports of the toolkit's results: the JSON objects and text tables that `afsv`
//! prints and the Python package returns, each a pure function of a library result (no
//! terminal, no files: the CLI decides where a report goes).
//!
//! - [`afs`]: the Chapter 4 optimisation of `afsv optimize afs` ([`crate::AfsOptimum`]);
//! - [`check`]: the self-checks of `afsv check`;
//! - [`params`]: the parameter sets and descriptions of `afsv params`;
//! - [`evaluate`]: the assessment of `afsv evaluate` ([`crate::evaluate::Assessment`]);
//! - [`design_3d`]: the D1-D3 design measures of the 3-D vehicle
//!   ([`crate::design_3d::DesignMeasures`]);
//! - [`layouts`]: the table of `afsv study layouts` ([`crate::layouts::LayoutStudy`]);
//! - [`hps_identify`]: the strut fit of `afsv hps identify`, judged before it is reported;
//! - [`hps_optimum`]: the Chapter 6 optimisation of `afsv optimize hps`
//!   ([`crate::HpsOptimum`]);
//! - [`layout_optimum`]: `afsv optimize layout` ([`crate::LayoutOptimum`]);
//! - [`roll`]: `afsv roll` on the rigid truck of Chapter 2 (crate `roll-truck`);
//! - [`terrain`]: `afsv terrain` (crate `terrain-psd`), the spectral analysis of a profile;
//! - [`tire`]: the rows of `afsv tire sweep` and `afsv tire envelope` (crate `tire-fiala`);
//! - [`vehicle`]: `afsv vehicle ride|roll|yaw` (D1-D3 of the 3-D vehicle over seeds);
//! - [`vehicle_record`]: the records of `afsv vehicle simulate|path-change`, their
//!   sidecars and the summary printed after them;
//! - [`yaw`]: the record of `afsv yaw simulate` (the yaw-plane model), its sidecar and
//!   summary;
//! - [`strut`]: `afsv hps harmonic|characterize|identify`: a harmonic record's sidecar,
//!   the laboratory programme's table, a strut record read for a fit;
//! - [`strut_shift`]: `afsv hps thermal`, the struts over a working shift;
//! - [`weighting`]: an ISO 2631-1 weighting's response (`afsv measures weighting`);
//! - [`table`]: aligned text tables of records and plainly read numbers;
//! - [`speed_sweep`]: the D4 sweep of `afsv study speed-sweep` ([`crate::SpeedSweep`]);
//! - [`hps_sensitivity`]: Table 6.4 of `afsv study hps-sensitivity`
//!   ([`crate::HpsSensitivity`]).

pub mod afs;
pub mod check;
pub mod design_3d;
pub mod evaluate;
pub mod hps_identify;
pub mod hps_optimum;
pub mod hps_sensitivity;
pub mod layout_optimum;
pub mod layouts;
pub mod params;
pub mod roll;
pub mod speed_sweep;
pub mod strut;
pub mod strut_shift;
pub mod table;
pub mod terrain;
pub mod tire;
pub mod vehicle;
pub mod vehicle_record;
pub mod weighting;
pub mod yaw;

/// `v` for a message: plain for ordinary magnitudes, in exponent form for huge or tiny
/// ones (so 1e308 does not print 309 digits).
pub fn show(v: f64) -> String {
    let a = v.abs();
    if a != 0.0 && a.is_finite() && !(1e-4..1e7).contains(&a) {
        format!("{v:e}")
    } else {
        format!("{v}")
    }
}

/// The value of largest magnitude in `v`, with its sign: the signed peak of a channel
/// such as the articulation angle (the first of equal magnitudes; 0 for no value, and NaN
/// values are passed over).
pub fn signed_peak(v: &[f64]) -> f64 {
    v.iter()
        .fold(0.0f64, |m, x| if x.abs() > m.abs() { *x } else { m })
}

/// `v` scaled by `scale` with `digits` decimals, or `n/a` when it cannot be computed.
pub fn num(v: f64, scale: f64, digits: usize) -> String {
    let x = v * scale;
    if x.is_finite() {
        format!("{x:.digits$}")
    } else {
        "n/a".to_string()
    }
}

/// `text` as indented lines of at most about 88 characters.
pub fn wrap_note(text: &str) -> String {
    let mut out = String::new();
    let mut line = String::from("  ");
    for word in text.split_whitespace() {
        if line.len() + word.len() > 88 && !line.trim().is_empty() {
            out += line.trim_end();
            out += "\n";
            line = String::from("    ");
        }
        line += word;
        line += " ";
    }
    out += line.trim_end();
    out + "\n"
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn notes_wrap_to_the_terminal() {
        let long = "word ".repeat(60);
        let text = wrap_note(&long);
        assert!(text.lines().all(|l| l.len() <= 92), "{text}");
        assert_eq!(text.split_whitespace().count(), 60);
        assert!(text.starts_with("  word") && text.lines().nth(1).unwrap().starts_with("    word"));
    }

    #[test]
    fn the_signed_peak_keeps_the_sign_of_the_largest_magnitude() {
        assert_eq!(signed_peak(&[1.0, -3.0, 2.0]), -3.0);
        assert_eq!(
            signed_peak(&[2.0, -2.0]),
            2.0,
            "the first of equal magnitudes"
        );
        assert_eq!(signed_peak(&[f64::NAN, -0.5]), -0.5);
        assert_eq!(signed_peak(&[]), 0.0);
    }

    #[test]
    fn numbers_that_cannot_be_computed_print_as_na() {
        assert_eq!(num(f64::NAN, 1.0, 2), "n/a");
        assert_eq!(num(f64::INFINITY, 1.0, 2), "n/a");
        assert_eq!(num(0.0123, 100.0, 1), "1.2");
    }
}
