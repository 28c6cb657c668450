//! The rows of `afsv tire` (crate `tire-fiala`): the Fiala forces over a sweep of loads and
//! slips, and a terrain profile enveloped by the tire (Eqs 2.3-2.4 / 6.2-6.3).

use afsv_records::Record;
use std::path::Path;
use tire_fiala::{Envelope, EnvelopeMethod, Fiala, HandlingModel, PolylineProfile};

/// The columns of `afsv tire sweep`'s table, in [`SweepRow`]'s order.
pub const SWEEP_COLUMNS: [&str; 7] = [
    "fz_n",
    "kappa",
    "alpha_deg",
    "fx_n",
    "fy_n",
    "mz_nm",
    "my_nm",
];

/// The columns of `afsv tire envelope`'s table, in [`EnvelopeRow`]'s order.
pub const ENVELOPE_COLUMNS: [&str; 6] = [
    "x_m",
    "z_profile_m",
    "z_eff_m",
    "slope_rad",
    "contact_length_m",
    "wheel_z_m",
];

#[derive(serde::Serialize)]
/// One row of `afsv tire sweep`: the Fiala forces at one load and slip.
pub struct SweepRow {
    /// Normal load (N).
    pub fz_n: f64,
    /// Slip ratio (> 0 in traction).
    pub kappa: f64,
    /// Slip angle (deg, the sign of Eq 3.17).
    pub alpha_deg: f64,
    /// Longitudinal force (N).
    pub fx_n: f64,
    /// Lateral force (N).
    pub fy_n: f64,
    /// Self-aligning moment (N·m, the sign of alpha).
    pub mz_nm: f64,
    /// Rolling-resistance moment (N·m, < 0 opposes forward rolling).
    pub my_nm: f64,
}

/// The Fiala forces of `tire` at every load of `fzs`, slip ratio of `kappas` and slip angle
/// (deg) of `alphas`, in that nesting (alpha fastest).
pub fn sweep_rows(tire: &Fiala, fzs: &[f64], kappas: &[f64], alphas: &[f64]) -> Vec<SweepRow> {
    let mut rows = Vec::with_capacity(fzs.len() * kappas.len() * alphas.len());
    for &fz in fzs {
        for &kappa in kappas {
            for &alpha_deg in alphas {
                let f = tire.forces(fz, kappa, alpha_deg.to_radians());
                rows.push(SweepRow {
                    fz_n: fz,
                    kappa,
                    alpha_deg,
                    fx_n: f.fx,
                    fy_n: f.fy,
                    mz_nm: f.mz,
                    my_nm: f.my,
                });
            }
        }
    }
    rows
}

#[derive(Debug, serde::Serialize)]
/// One row of `afsv tire envelope`: the enveloped profile at one point.
pub struct EnvelopeRow {
    /// Distance along the profile (m).
    pub x_m: f64,
    /// Profile height (m).
    pub z_profile_m: f64,
    /// Effective elevation z_oi (m, Eqs 2.3-2.4 / 6.2-6.3).
    pub z_eff_m: f64,
    /// Effective slope (rad).
    pub slope_rad: f64,
    /// Contact length (m).
    pub contact_length_m: f64,
    /// Wheel-centre height at the given deflection (m).
    pub wheel_z_m: f64,
}

/// The track `column` (`left_m` or `right_m`) of the profile record `rec` read from `path`
/// (points `x_m`), enveloped by a tire of `radius` (m) sampled every `spacing` (m) with
/// `method`, the wheel held at the deflection `deflection_m` (m) at every point; errors of
/// the profile name the file.
pub fn envelope_track(
    (rec, path): (&Record, &Path),
    column: &str,
    (method, radius, spacing): (EnvelopeMethod, f64, f64),
    deflection_m: f64,
) -> Result<Vec<EnvelopeRow>, String> {
    let xs = rec.require("x_m", path).map_err(|e| e.to_string())?;
    let zs = rec.require(column, path).map_err(|e| e.to_string())?;
    let profile = PolylineProfile::new(xs.to_vec(), zs.to_vec())
        .map_err(|e| format!("{}: {e}", path.display()))?;
    let env = Envelope::new(method, radius, spacing).map_err(|e| e.to_string())?;
    let mut rows = Vec::with_capacity(xs.len());
    for (&x, &z) in xs.iter().zip(zs) {
        let p = env
            .at_deflection(&profile, x, deflection_m)
            .map_err(|e| e.to_string())?;
        rows.push(EnvelopeRow {
            x_m: x,
            z_profile_m: z,
            z_eff_m: p.contact.z_eff,
            slope_rad: p.contact.slope,
            contact_length_m: p.contact.contact_length,
            wheel_z_m: p.wheel_z,
        });
    }
    Ok(rows)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The names of the serialised fields, sorted.
    fn fields<T: serde::Serialize>(row: &T) -> Vec<String> {
        let v = serde_json::to_value(row).unwrap();
        v.as_object().unwrap().keys().cloned().collect()
    }

    fn sorted(columns: &[&str]) -> Vec<String> {
        let mut c: Vec<String> = columns.iter().map(|s| s.to_string()).collect();
        c.sort();
        c
    }

    /// Each table names every field of its rows once, so no column is left out or empty.
    #[test]
    fn the_table_columns_are_the_fields_of_the_rows() {
        let tire = Fiala::new(&tire_fiala::TireParams::nominal()).unwrap();
        let rows = sweep_rows(&tire, &[1e5], &[0.0], &[2.0]);
        assert_eq!(fields(&rows[0]), sorted(&SWEEP_COLUMNS));
        let env = EnvelopeRow {
            x_m: 0.0,
            z_profile_m: 0.0,
            z_eff_m: 0.0,
            slope_rad: 0.0,
            contact_length_m: 0.0,
            wheel_z_m: 0.0,
        };
        assert_eq!(fields(&env), sorted(&ENVELOPE_COLUMNS));
    }

    /// Flat ground enveloped is flat ground (statics: the wheel stands at its radius less
    /// the deflection); a missing track names the file.
    #[test]
    fn a_flat_track_envelopes_flat() {
        let xs: Vec<f64> = (0..=40).map(|i| i as f64 * 0.1).collect();
        let flat = vec![0.0; xs.len()];
        let rec = Record::from_columns([("x_m", xs), ("left_m", flat)]).unwrap();
        let file = Path::new("flat.csv");
        let method = (EnvelopeMethod::CircleLine, 1.0, 0.01);
        let rows = envelope_track((&rec, file), "left_m", method, 0.1).unwrap();
        assert_eq!(rows.len(), 41);
        for r in &rows[10..30] {
            assert!(r.z_eff_m.abs() < 1e-9 && r.slope_rad.abs() < 1e-9, "{r:?}");
            assert!((r.wheel_z_m - 0.9).abs() < 1e-6, "{r:?}");
        }
        let e = envelope_track((&rec, file), "right_m", method, 0.1).unwrap_err();
        assert!(e.contains("flat.csv") && e.contains("right_m"), "{e}");
    }
}
