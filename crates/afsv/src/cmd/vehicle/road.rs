//! `afsv vehicle ride --road FILE`: the D1 ride on a measured two-track road instead of
//! synthesised terrain. The file is a record (docs/records.md): columns `x_m` (uniformly
//! spaced), `left_m` and `right_m`; other length units (`left_mm`, `x_km`) are converted on
//! read, and the conversions are reported.

use afsv::output::OutputGuard;
use afsv_records::Record;
use serde_json::{json, Value};
use std::path::Path;
use terrain_psd::TwoTrackProfile;
use vehicle_3d::scenarios::{measured_ride_tracks, ride_on, RideMeasures, RideSpec};
use vehicle_3d::VehicleParams;

/// Largest measured road read (samples per track): 200 km at 2 cm.
const MAX_ROAD_SAMPLES: usize = 10_000_000;

/// What the ride ran on, for its report.
pub(super) struct Ground {
    /// The ground as JSON (`"terrain"` of the report).
    pub json: Value,
    /// The ground in words (one line of the text report).
    pub text: String,
    /// The measures of each run with what tells the runs apart (`"per_seed"`).
    pub per_run: Value,
}

/// One D1 ride of `p` on the measured road in `file`: its measures and its ground.
pub(super) fn ride(
    p: &VehicleParams,
    spec: &RideSpec,
    file: &Path,
) -> Result<(RideMeasures, Ground), String> {
    OutputGuard::new(false).record_input("--road", file)?;
    let shown = file.display();
    let rec = Record::read(file).map_err(|e| e.to_string())?;
    let column = |name: &str| rec.require(name, file).map_err(|e| e.to_string());
    let (x, left, right) = (column("x_m")?, column("left_m")?, column("right_m")?);
    if x.len() > MAX_ROAD_SAMPLES {
        return Err(format!(
            "{shown}: {} samples, more than the {MAX_ROAD_SAMPLES} a road may have",
            x.len()
        ));
    }
    let profile =
        TwoTrackProfile::from_samples(x, left, right).map_err(|e| format!("{shown}: {e}"))?;
    let (dx, n) = (profile.dx_m, profile.len());
    let tracks = measured_ride_tracks(p, spec, profile).map_err(|e| format!("{shown}: {e}"))?;
    let (_, m) = ride_on(p, spec, tracks).map_err(|e| e.to_string())?;
    let length = dx * (n - 1) as f64;
    let ground = Ground {
        json: json!({
            "kind": "measured two-track road",
            "file": file,
            "length_m": length,
            "dx_m": dx,
            "samples": n,
            "unit_conversions": afsv::output::unit_conversions(&rec),
        }),
        text: format!("measured road {shown} ({length:.0} m at {dx} m)"),
        per_run: json!([{
            "road": file,
            "measures": afsv::output::explain_nulls(json!(m), super::NO_STRUT),
        }]),
    };
    Ok((m, ground))
}
